"""Exercise 3.5: distance of a line to the origin and its closest point, from Plücker data."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.worked import Solution, exact_check, identity_check
from rigidsym.declare import unit_vector, vector

ID = "ex3.5"


def solve() -> Solution:
    """Worked solution of Exercise 3.5."""
    e = unit_vector("ex35_e")
    p = vector("p")
    s = Solution(
        ID, "Joint-axis calibration from Plücker coordinates",
        "\"Show that the distance of the axis to the origin ... d = ||n||. Show that the point "
        "P* on the axis, which lies closest to the above-mentioned origin, has a position "
        "vector p* = e x n\"",
        "Angeles, Sec. 3.9, Exercise 3.5",
        given={"line": "through a point p, unit direction e; n = p x e (Plücker moment)",
               "[pi_L]_G": "[-sqrt(2)/2, 0, sqrt(2)/2, 0, -sqrt(2), 0]^T"},
        assumptions=["e is a unit vector (normalised Plücker coordinates), as the data have."])
    n = s.step("moment", p.cross(e), "Moment of the line about the origin, Sec. 3.3.")
    ps = s.step("candidate", e.cross(n), "p* = e x n = e x (p x e) = p - (e.p) e.")
    s.step("on the line", ps.cross(e) - n,
           "p* x e = n means p* lies on the line (its moment about O is the line's).")
    s.step("closest", ps.dot(e),
           "p*.e = 0: O - p* is normal to the line, so p* is the foot of the perpendicular.")
    s.step("distance", ps.dot(ps) - n.dot(n), "||p*|| = ||e x n|| = ||n|| since e is normal to n.")
    ec = sp.Matrix([-sp.sqrt(2) / 2, 0, sp.sqrt(2) / 2])
    nc = sp.Matrix([0, -sp.sqrt(2), 0])
    d = s.step("(c) d", sp.sqrt(nc.dot(nc)), "d = ||n||.")
    pstar = s.step("(c) p*", ec.cross(nc), "p* = e x n.")
    s.answers = {"d": d, "p_star": pstar}
    s.check(identity_check("(a)-(b) for every line: p* x e = n, p*.e = 0, ||p*||^2 = ||n||^2",
                           [ps.cross(e) - n, ps.dot(e), ps.dot(ps) - n.dot(n)]))
    # independent check of (c): minimise ||x||^2 over x = p* + lambda e, compare
    lam = sp.Symbol("lambda", real=True)
    s.check(exact_check("(c) data: ||e|| = 1, e.n = 0; p* x e = n, p*.e = 0, ||p*|| = d",
                        [ec.dot(ec) - 1, ec.dot(nc), pstar.cross(ec) - nc, pstar.dot(ec),
                         pstar.dot(pstar) - d**2]))
    x = pstar + lam * ec
    lam_min = sp.solve(sp.diff(x.dot(x), lam), lam)
    s.check(exact_check("(c) minimising ||p* + lambda e||^2 gives lambda = 0",
                        [lam_min[0]]))
    return s
