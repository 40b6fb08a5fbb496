"""Exercise 3.21: the Cartesian decomposition W = Omega_dot + Omega^2 is orthogonal."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Solution, identity_check, nonidentity_check
from rigidsym.declare import TIME, cpm, trace, vector

ID = "ex3.21"
TITLE = "Orthogonality of the two parts of the angular-acceleration matrix"
STATEMENT = ("\"Show that the two components of the foregoing decomposition are mutually "
             "orthogonal, which is a restatement of the orthogonality of the tangential and the "
             "centripetal relative acceleration\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.21; Eq. (3.86)"


def solve() -> Solution:
    """Worked solution of Exercise 3.21."""
    w = vector("omega", t=TIME)
    r = vector("r")
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"omega(t)": w, "W": "Omega_dot + Omega^2 (3.86)", "r": r},
        assumptions=["The 'restatement' for vectors is decided too: it is false in general."])
    Om = cpm(w)
    Od = s.step("skew part", Om.diff(TIME), "Omega_dot = CPM(omega_dot) is skew-symmetric.")
    O2 = s.step("symmetric part", Om**2, "Omega^2 = omega omega^T - ||omega||^2 1 is symmetric.")
    ip = s.step("inner product", trace(Od * O2.T),
                "tr(A B^T) for A skew, B symmetric: tr(A B) = tr((A B)^T) = tr(B^T A^T) "
                "= -tr(B A) = -tr(A B), hence 0.")
    tang, cent = Od * r, O2 * r
    vec = s.step("tangential . centripetal", (tang.T * cent)[0],
                 "For a relative position r: (omega_dot x r).(omega x (omega x r)).")
    formula = (w.dot(r)) * (w.diff(TIME).cross(r)).dot(w)
    s.step("closed form", formula,
           "(omega_dot x r).(omega (omega.r) - r ||omega||^2) = (omega.r) (omega_dot x r).omega: "
           "zero only if r is normal to omega or omega, omega_dot, r are coplanar.")
    s.answers = {"tr(Omega_dot (Omega^2)^T)": sp.Integer(0),
                 "matrix_components_orthogonal": sp.true,
                 "tangential_dot_centripetal": formula,
                 "vector_restatement_holds_in_general": sp.false}
    s.check(identity_check("tr(Omega_dot Omega^2^T) = 0 for every omega(t)", [ip]))
    s.check(identity_check("Omega_dot skew, Omega^2 symmetric", [Od + Od.T, O2 - O2.T]))
    s.check(identity_check("(omega_dot x r).(omega x (omega x r)) = (omega.r)(omega_dot x r).omega",
                           [vec - formula]))
    s.check(nonidentity_check("vector restatement is not an identity", [vec]))
    return s
