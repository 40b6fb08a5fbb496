"""Exercise 3.9: for a small rotation the angular velocity is a time-derivative."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Solution, identity_check, nonidentity_check
from rigidsym.declare import TIME, rotation_from_natural_invariants, scalar, unit_vector, vect

ID = "ex3.9"
TITLE = "Small rotations"
STATEMENT = ("\"Prove that the angular-velocity vector, in the special case of 'small' rotations, "
             "turns out to be a time-derivative. What is the vector whose time-derivative yields "
             "the angular-velocity vector?\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.9"


def solve() -> Solution:
    """Worked solution of Exercise 3.9."""
    e = unit_vector("ex39_e", t=TIME)
    phi = scalar("phi", t=TIME)
    eps = sp.Symbol("epsilon", real=True)
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"Q(t)": "rotation about e(t) through phi(t) (Eq. 2.49)"},
        assumptions=["'Small' means first order in phi: phi is replaced by epsilon*phi and "
                     "omega is expanded to first order in epsilon (phi_dot is of the same "
                     "order as phi). The statement holds to first order only; the "
                     "second-order term is shown to be non-zero."])
    Q = rotation_from_natural_invariants(e, eps * phi)
    omega = vect(Q.diff(TIME) * Q.T)
    s.step("Q to first order", sp.eye(3) + eps * phi * sp.Matrix([[0, -e[2], e[1]],
                                                                 [e[2], 0, -e[0]],
                                                                 [-e[1], e[0], 0]]),
           "cos(eps phi) = 1 + O(eps^2), sin(eps phi) = eps phi + O(eps^3) in Eq. (2.49).")
    s.step("omega", "omega = vect(Q_dot Q^T) = d/dt(phi E) + O(eps^2) = phi_dot e + phi e_dot",
           "Q_dot = eps d(phi E)/dt + O(eps^2) and Q^T = 1 + O(eps).")
    w0 = omega.subs(eps, 0)
    w1 = omega.diff(eps).subs(eps, 0)
    w2 = omega.diff(eps, 2).subs(eps, 0)
    target = (phi * e).diff(TIME)
    s.answers = {"omega_first_order": sp.Symbol("d(phi*e)/dt"),
                 "vector": sp.Symbol("phi*e"),
                 "holds_exactly": sp.false}
    s.step("answer", target,
           "omega = d(phi e)/dt: the time-derivative of the 'rotation vector' phi e (to first "
           "order equal to the linear invariant sin(phi) e and to 2 r, r the Euler-Rodrigues "
           "vector).")
    s.check(identity_check("order 0: omega = 0 at epsilon = 0", [w0]))
    s.check(identity_check("order 1: d omega/d epsilon at 0 equals d(phi e)/dt exactly",
                           [w1 - target]))
    s.check(nonidentity_check("order 2 does not vanish (the result is first-order only)",
                              [w2]))
    return s
