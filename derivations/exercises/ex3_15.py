"""Exercise 3.15: when I_P and I_C share principal axes, and how the moments relate."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Solution, identity_check
from rigidsym.declare import rotation, scalar, symmetric_matrix, vector

from ._inertia import inertia_at_point

ID = "ex3.15"
TITLE = "Common principal axes at a point and at the centre of mass"
STATEMENT = ("\"State the conditions under which the two matrices have common eigenvectors. "
             "Moreover, under these conditions, what are the relationships between the two sets of "
             "principal moments of inertia?\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.15"


def solve() -> Solution:
    """Worked solution of Exercise 3.15."""
    R = rotation("ex315_R")
    l1, l2, l3, m, delta = (scalar(n) for n in ("I_1", "I_2", "I_3", "m", "delta"))
    I_C = R * sp.diag(l1, l2, l3) * R.T
    c = sp.zeros(3, 1)
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"I_C": "R diag(I_1, I_2, I_3) R^T (principal axes R e_k)", "d": "p - c"},
        assumptions=["Origin at C; 'common eigenvectors' = a full common orthonormal "
                     "eigenbasis (the two symmetric matrices commute)."])
    s.step("Steiner", "I_P = I_C + m (||d||^2 1 - d d^T), d = p - c",
           "Eq. (3.133a).")
    s.step("commutation", "I_P I_C - I_C I_P = -m (I_C d d^T - d d^T I_C)",
           "||d||^2 1 commutes with everything; symmetric matrices share an eigenbasis iff "
           "they commute.")
    Ig, dg = symmetric_matrix("J"), vector("d")
    comm = Ig * dg * dg.T - dg * dg.T * Ig
    lhs = s.step("necessity", comm * dg,
                 "Applying the commutator to d gives ||d||^2 I_C d - (d^T I_C d) d: zero iff "
                 "I_C d is parallel to d, i.e. d is a principal axis of I_C.")
    s.step("sufficiency", "d = delta R e_1 => I_P R e_1 = I_1 R e_1, I_P R e_k = "
           "(I_k + m delta^2) R e_k (k = 2, 3)",
           "d d^T R e_k = 0 for k != 1 and (||d||^2 1 - d d^T) d = 0.")
    d = delta * R[:, 0]
    I_P = inertia_at_point(I_C, m, d, c)
    s.answers = {"condition": "P = C, or P lies on a principal axis of inertia through C "
                              "(d = p - c an eigenvector of I_C)",
                 "moment_along_d": l1,
                 "moments_normal_to_d": sp.Matrix([l2 + m * delta**2, l3 + m * delta**2])}
    s.check(identity_check("commutator applied to d = ||d||^2 I_C d - (d^T I_C d) d",
                           [lhs - ((dg.T * dg)[0] * Ig * dg - (dg.T * Ig * dg)[0] * dg)]))
    s.check(identity_check("I_P R e_1 = I_1 R e_1; I_P R e_k = (I_k + m delta^2) R e_k",
                           [I_P * R[:, 0] - l1 * R[:, 0],
                            I_P * R[:, 1] - (l2 + m * delta**2) * R[:, 1],
                            I_P * R[:, 2] - (l3 + m * delta**2) * R[:, 2]]))
    s.check(identity_check("I_P and I_C commute when d = delta R e_1",
                           [I_P * I_C - I_C * I_P]))
    return s
