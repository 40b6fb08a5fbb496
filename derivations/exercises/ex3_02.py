"""Exercise 3.2: two unit forces on a regular tetrahedron; the point of least moment."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.worked import Solution, exact_check

ID = "ex3.2"


def solve() -> Solution:
    """Worked solution of Exercise 3.2."""
    r3, r6 = sp.sqrt(3), sp.sqrt(6)
    P1, P2 = sp.Matrix([0, 0, 0]), sp.Matrix([1, 0, 0])
    P3, P4 = sp.Matrix([sp.Rational(1, 2), r3 / 2, 0]), sp.Matrix([sp.Rational(1, 2), r3 / 6,
                                                                  r6 / 3])
    s = Solution(
        ID, "Wrench on a regular tetrahedron",
        "\"f_1 is directed from P_2 to P_3, whereas f_2 is directed from P_4 to P_1 ... Find "
        "the location of point P lying closest to P_4 that will make the magnitude of n a "
        "minimum.\"",
        "Angeles, Sec. 3.9, Exercise 3.2",
        given={"P1": P1, "P2": P2, "P3": P3, "P4": P4},
        assumptions=["Fig. 3.10 is not in the text we have: unit-edge regular tetrahedron "
                     "placed with P1 at O, P2 on X, P3 in the X-Y plane, P4 above it. The "
                     "answer is also given in barycentric coordinates, valid for any "
                     "placement."])
    f1, f2 = P3 - P2, P1 - P4
    f = s.step("resultant", f1 + f2, "f = f_1 + f_2 (unit forces along the edges).")
    n0 = s.step("moment about O", P2.cross(f1) + P4.cross(f2),
                "f_1 acts along line P2P3, f_2 along P4P1.")
    p0 = s.step("central axis point", (f.cross(n0) / f.dot(f)).applyfunc(sp.radsimp),
                "The moment is least (parallel to f) on the central axis {f x n_O / ||f||^2 "
                "+ lambda f}.")
    lam = sp.radsimp((P4 - p0).dot(f) / f.dot(f))
    P = s.step("closest to P4", (p0 + lam * f).applyfunc(sp.radsimp),
               "Foot of the perpendicular from P4 on the central axis.")
    B = sp.Matrix([[*P1, *P2, *P3, *P4][i::3] for i in range(3)])  # 3 x 4 vertex coordinates
    Bh = sp.Matrix.vstack(B, sp.ones(1, 4))
    bary = (Bh.inv() * sp.Matrix.vstack(P, sp.Matrix([1]))).applyfunc(sp.radsimp)
    s.step("barycentric coordinates", bary, "P = sum w_i P_i with sum w_i = 1 (placement-free).")
    nP = (n0 - P.cross(f)).applyfunc(sp.radsimp)
    s.answers = {"P": P, "P_barycentric": bary, "n_min": nP, "f": f,
                 "n_min_magnitude": sp.radsimp(sp.sqrt(nP.dot(nP)))}
    s.check(exact_check("unit edges and unit forces", [(P2 - P1).norm() - 1, (P3 - P1).norm() - 1,
                                                       (P4 - P1).norm() - 1, (P3 - P2).norm() - 1,
                                                       (P4 - P2).norm() - 1, (P4 - P3).norm() - 1]))
    s.check(exact_check("moment at P is parallel to f (minimum magnitude) and P - P4 is normal "
                        "to f (closest point)", [nP.cross(f), (P - P4).dot(f)]))
    return s
