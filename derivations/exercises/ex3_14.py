"""Exercise 3.14: two centroidal inertia measurements compared by their invariants."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.worked import Solution, exact_check, truth_check

ID = "ex3.14"


def solve() -> Solution:
    """Worked solution of Exercise 3.14."""
    IA = sp.diag(1, 2, 3)
    IB = sp.Matrix([[6, 2, 2], [2, 5, 0], [2, 0, 7]]) / 3
    lam = sp.Symbol("lambda")
    s = Solution(
        ID, "Two observers of one inertia matrix",
        "\"The centroidal inertia matrix of a rigid body is measured by two observers ... "
        "Show that the two measurements are acceptable.\"",
        "Angeles, Sec. 3.9, Exercise 3.14",
        given={"[I]_A": IA, "[I]_B": IB},
        assumptions=["'Acceptable' = same tensor in two frames (equal invariants: trace, "
                     "second invariant, determinant) and physically admissible (symmetric, "
                     "positive definite, triangle inequalities I_i + I_j >= I_k)."])
    inv = s.step("invariants of I_A", sp.Matrix([IA.trace(), (IA.trace()**2 - (IA * IA).trace())
                                                 / 2, IA.det()]),
                 "Coefficients of the characteristic polynomial are frame-invariant.")
    invB = s.step("invariants of I_B", sp.Matrix([IB.trace(), (IB.trace()**2 - (IB * IB).trace())
                                                  / 2, IB.det()]), "The same three numbers.")
    ev = s.step("principal moments", sp.Matrix(sorted(sp.roots(IB.charpoly(lam).as_expr(),
                                                               lam))),
                "Roots of the common characteristic polynomial: 1, 2, 3.")
    vecs = []
    for val in (1, 2, 3):
        v = (IB - val * sp.eye(3)).nullspace()[0]
        vecs.append(v / v.norm())
    Q = sp.Matrix.hstack(*vecs)
    if Q.det() < 0:
        Q[:, 2] = -Q[:, 2]
    Q = s.step("rotation B <- A", Q, "Unit eigenvectors of I_B as columns: [I]_B = Q [I]_A Q^T.")
    s.answers = {"invariants": inv, "principal_moments": ev, "Q_B_A": Q, "acceptable": sp.true}
    s.check(truth_check("invariants equal", inv == invB, f"{list(inv)}"))
    s.check(exact_check("Q proper orthogonal and Q [I]_A Q^T = [I]_B",
                        [Q.T * Q - sp.eye(3), Q.det() - 1, Q * IA * Q.T - IB]))
    s.check(truth_check("admissible: positive definite, I1 + I2 >= I3 (= : a planar lamina)",
                        all(x > 0 for x in ev) and ev[0] + ev[1] >= ev[2],
                        "1 + 2 = 3: the limiting case, a body with all mass in one plane"))
    return s
