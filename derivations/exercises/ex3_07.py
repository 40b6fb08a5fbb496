"""Exercise 3.7: Plücker coordinates of an axis from its moments about two points."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.worked import Solution, exact_check, truth_check

ID = "ex3.7"


def solve() -> Solution:
    """Worked solution of Exercise 3.7."""
    a, b = sp.Matrix([1, 0, 0]), sp.Matrix([0, 1, 1])
    nA, nB = sp.Matrix([0, 2, 0]), sp.Matrix([0, 1, 1])
    s = Solution(
        ID, "Calibrating an axis from two moment measurements",
        "\"the moment of this axis is measured with respect to two points, A and B ... "
        "Determine the unit vector e ... the point P* ... the Plücker coordinates of the "
        "axis about the origin\"",
        "Angeles, Sec. 3.9, Exercise 3.7",
        given={"a": a, "b": b, "n_A": nA, "n_B": nB},
        assumptions=["The moment of the line about a point X is n_X = (p - x) x e for any p "
                     "on the line (Sec. 3.3); the sign of e is fixed by n_A - n_B = (b - a) x e."])
    u = s.step("direction", nA.cross(nB),
               "Both moments are normal to e (n_X.e = 0), so e is parallel to n_A x n_B.")
    e0 = u / u.norm()
    rel = s.step("transfer", (b - a).cross(e0) - (nA - nB),
                 "n_A - n_B = (b - a) x e fixes the sense of e (zero here, so e = +u/||u||).")
    e = e0 if rel == sp.zeros(3, 1) else -e0
    n0 = s.step("moment about O", nA + a.cross(e), "n_O = n_A + a x e (moment transfer).")
    ps = s.step("closest point", e.cross(n0), "p* = e x n_O (Exercise 3.5).")
    pl = s.step("Plücker coordinates about O", sp.Matrix.vstack(e, n0), "[e; n_O].")
    s.answers = {"e": e, "p_star": ps, "plucker_O": pl}
    s.check(exact_check("(p* - a) x e = n_A and (p* - b) x e = n_B (the data are reproduced)",
                        [(ps - a).cross(e) - nA, (ps - b).cross(e) - nB]))
    s.check(exact_check("Plücker constraints: e.e = 1, e.n_O = 0; p*.e = 0",
                        [e.dot(e) - 1, e.dot(n0), ps.dot(e)]))
    s.check(truth_check("both measured moments are normal to e",
                        nA.dot(e) == 0 and nB.dot(e) == 0, "exact"))
    return s
