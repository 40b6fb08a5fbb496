"""Exercise 3.17: M_dot = W M - M W and mu_dot = M t_dot + W M t."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Solution, identity_check
from rigidsym.declare import TIME, rotation, scalar, symmetric_matrix, vect, vector

from ._inertia import angular_velocity_dyad, inertia_dyad

ID = "ex3.17"
TITLE = "Time-rate of the inertia dyad and of the momentum screw"
STATEMENT = ("\"Show that the time-rate of change of the inertia dyad M of a rigid body is given "
             "by M_dot = W M - M W ... show that mu_dot = M t_dot + W M t\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.17; Eqs. (3.138)-(3.143)"


def motion():
    """A generic rigid motion: Q(t), body-frame inertia J, mass m, c_dot(t)."""
    Q = rotation("ex317_Q", t=TIME)
    J = symmetric_matrix("J")
    m = scalar("m")
    cd = vector("cdot", t=TIME)
    omega = vect(Q.diff(TIME) * Q.T)
    I_C = Q * J * Q.T
    M = inertia_dyad(I_C, m)
    W = angular_velocity_dyad(omega)
    t = sp.Matrix.vstack(omega, cd)
    return Q, J, m, omega, M, W, t


def solve() -> Solution:
    """Worked solution of Exercise 3.17."""
    Q, J, m, omega, M, W, t = motion()
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"Q(t)": "generic rotation", "J": J, "m": m,
               "I_C": "Q J Q^T (body-fixed J: the centroidal inertia moves with the body)",
               "t": "[omega; c_dot]"},
        assumptions=["M is expressed in the inertial frame, I_C = Q J Q^T with constant "
                     "body-frame J; in body-frame components M is constant and the identity "
                     "does not apply."])
    s.step("rate of I_C", "Q_dot J Q^T + Q J Q_dot^T = Omega I_C - I_C Omega",
           "Q_dot = Omega Q and Omega^T = -Omega.")
    s.step("rate of M", "M_dot = diag(Omega I_C - I_C Omega, O) = W M - M W",
           "Block-multiply W = diag(Omega, O) with M = diag(I_C, m 1); m is constant.")
    s.step("momentum screw", "mu_dot = M_dot t + M t_dot = W M t - M W t + M t_dot",
           "Product rule on mu = M t.")
    s.step("null space", "W t = [Omega omega; 0] = 0",
           "Eq. (3.141): omega x omega = 0, hence mu_dot = M t_dot + W M t.")
    Md = M.diff(TIME)
    mu_d = (M * t).diff(TIME)
    s.answers = {"M_dot_equals_WM_minus_MW": sp.true, "mu_dot_equals_Mtdot_plus_WMt": sp.true}
    s.check(identity_check("M_dot - (W M - M W) = 0 (generic Q(t), J)", [Md - (W * M - M * W)]))
    s.check(identity_check("d(M t)/dt - (M t_dot + W M t) = 0",
                           [mu_d - (M * t.diff(TIME) + W * M * t)]))
    s.check(identity_check("W t = 0", [W * t]))
    return s
