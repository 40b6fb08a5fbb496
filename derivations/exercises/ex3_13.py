"""Exercise 3.13: m [tr(P P^T) 1 - P P^T] is the inertia matrix of point masses."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Solution, identity_check
from rigidsym.declare import cpm, scalar, trace, vector

ID = "ex3.13"
TITLE = "Mechanical meaning of m[tr(P P^T) 1 - P P^T]"
STATEMENT = ("\"assume that a mass m is located at every point P_i of position vector p_i. Give a "
             "mechanical interpretation of the matrix m[tr(P P^T) 1 - P P^T]\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.13"


def solve() -> Solution:
    """Worked solution of Exercise 3.13."""
    m = scalar("m")
    n = 4
    pts = [vector(f"p{i}") for i in range(1, n + 1)]
    P = sp.Matrix.hstack(*pts)
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"P": "3 x n matrix [p_1 ... p_n]", "m": m},
        assumptions=["P is the matrix of Exercise 2.23 of the book (chapter 2), taken as the 3 x n "
                     "matrix whose columns are the position vectors p_i of the n points.",
                     "The identity is decided for n = 4 symbolic points; it holds for every n "
                     "because both sides are sums over the columns (P P^T = sum p_i p_i^T)."])
    s.step("outer product", "P P^T = sum_i p_i p_i^T, tr(P P^T) = sum_i ||p_i||^2",
           "Column expansion of the product.")
    Ii = s.step("one point mass", m * ((pts[0].T * pts[0])[0] * sp.eye(3) - pts[0] * pts[0].T),
                "Inertia of a point mass about O: m(||p||^2 1 - p p^T) = -m CPM(p)^2 "
                "(Eq. 3.133a with I_C = O).")
    total = m * (trace(P * P.T) * sp.eye(3) - P * P.T)
    s.step("the matrix", total, "Sum of the point-mass inertias: the system's inertia at O.")
    s.answers = {"interpretation": "the moment-of-inertia matrix, about the origin, of the "
                                   "system of n equal point masses m at the p_i (centroidal "
                                   "when the origin is their centroid)",
                 "is_inertia_about_origin": sp.true}
    s.check(identity_check("m[tr(PP^T)1 - PP^T] = -m sum CPM(p_i)^2 (n = 4)",
                           [total + m * sum((cpm(p) ** 2 for p in pts), sp.zeros(3))]))
    s.check(identity_check("one point: m(||p||^2 1 - p p^T) = m CPM(p) CPM(p)^T",
                           [Ii - m * cpm(pts[0]) * cpm(pts[0]).T]))
    return s
