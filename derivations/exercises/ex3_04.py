"""Exercise 3.4: compatibility of two wrench measurements and the relative rotation."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.worked import Solution, exact_check, truth_check

ID = "ex3.4"
R = sp.Rational


def solve() -> Solution:
    """Worked solution of Exercise 3.4."""
    n1, f1 = sp.Matrix([0, 0, 5]), sp.Matrix([0, 2, 0])
    n2, f2 = sp.Matrix([-R(5, 3), -R(10, 3), R(10, 3)]), sp.Matrix([-R(4, 3), R(4, 3), R(2, 3)])
    s = Solution(
        ID, "Two redundant wrench sensors",
        "\"Show that the measurements are compatible, based on invariance arguments. Determine "
        "the relative orientation of the two frames\"",
        "Angeles, Sec. 3.9, Exercise 3.4",
        given={"[n]_1": n1, "[f]_1": f1, "[n]_2": n2, "[f]_2": f2},
        assumptions=["Both sensors report the wrench at the same point P, so n and f change "
                     "between frames by the same rotation Q (no moment transfer)."])
    inv1 = s.step("invariants in F1", sp.Matrix([f1.dot(f1), n1.dot(n1), n1.dot(f1)]),
                  "A rotation preserves ||f||^2, ||n||^2 and n.f.")
    inv2 = s.step("invariants in F2", sp.Matrix([f2.dot(f2), n2.dot(n2), n2.dot(f2)]),
                  "Equal to those in F1: the measurements are compatible.")
    B1 = s.step("triad in F1", sp.Matrix.hstack(f1, n1, f1.cross(n1)),
                "f, n and f x n are independent (n.f = 0, both non-zero) and rotate together.")
    B2 = s.step("triad in F2", sp.Matrix.hstack(f2, n2, f2.cross(n2)), "The same triad in F2.")
    Q = s.step("rotation F2 -> F1", B1 * B2.inv(), "[x]_1 = Q [x]_2 for the three columns.")
    s.answers = {"invariants": inv1, "compatible": sp.true, "Q_1_2": Q}
    s.check(truth_check("invariants equal (exact rationals)", inv1 == inv2, f"{list(inv1)}"))
    s.check(exact_check("Q^T Q = 1, det Q = 1", [Q.T * Q - sp.eye(3), Q.det() - 1]))
    s.check(exact_check("Q maps the F2 measurements onto the F1 ones", [Q * n2 - n1, Q * f2 - f1]))
    return s
