"""Exercise 3.16: the smallest principal moment is least at the centre of mass."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Solution, identity_check
from rigidsym.declare import rotation, scalar, symmetric_matrix, vector

from ._inertia import inertia_at_point

ID = "ex3.16"
TITLE = "Minimum of the smallest principal moment"
STATEMENT = ("\"Show that the smallest principal moment of inertia of a rigid body attains its "
             "minimum value at the center of mass.\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.16"


def solve() -> Solution:
    """Worked solution of Exercise 3.16."""
    J, m, d, x = symmetric_matrix("J"), scalar("m"), vector("d"), vector("x")
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"I_C": J, "d": "a - c", "m": "mass, m > 0"},
        assumptions=["The minimum is attained at C but not only there: also at every point "
                     "of the principal axis of the smallest moment through C (shown below)."])
    I_A = inertia_at_point(J, m, d, sp.zeros(3, 1))
    q = s.step("quadratic form of the difference", (x.T * (I_A - J) * x)[0],
               "x^T (I_A - I_C) x = m (||d||^2 ||x||^2 - (d.x)^2) = m ||d x x||^2 >= 0.")
    s.step("Rayleigh quotient",
           "lambda_min(I_A) = min_{||x||=1} x^T I_A x >= min_{||x||=1} x^T I_C x "
           "= lambda_min(I_C)",
           "The difference is positive semidefinite (Courant-Fischer).")
    s.step("attained", "d = 0 gives I_A = I_C",
           "So the lower bound lambda_min(I_C) is the minimum, attained at C.")
    R = rotation("ex316_R")
    l1, l2, l3, dl = (scalar(n) for n in ("I_1", "I_2", "I_3", "delta"))
    I_C = R * sp.diag(l1, l2, l3) * R.T
    I_on = inertia_at_point(I_C, m, dl * R[:, 0], sp.zeros(3, 1))
    s.answers = {"min_value": sp.Symbol("lambda_min(I_C)"),
                 "attained_at": "C, and every point of the principal axis of the smallest "
                                "moment through C",
                 "difference_quadratic_form": m * x.cross(d).dot(x.cross(d))}
    s.check(identity_check("x^T (I_A - I_C) x = m ||d x x||^2 for every x, d, I_C",
                           [q - m * x.cross(d).dot(x.cross(d))]))
    s.check(identity_check("on the axis of I_1 (d = delta R e_1): I_A R e_1 = I_1 R e_1",
                           [I_on * R[:, 0] - l1 * R[:, 0]]))
    return s
