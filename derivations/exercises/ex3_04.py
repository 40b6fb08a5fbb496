"""Exercise 3.4: compatibility of two wrench measurements and the relative rotation.

Exact data: the invariants ``||f||^2, ||n||^2, n.f`` must agree exactly, and the rotation
is ``B_1 B_2^-1`` for the triads ``[f, n, f x n]``. Float data are measurements: the
invariants are compared within ``tol`` and the rotation is the least-squares one
(orthogonal Procrustes), rounded to an exact rotation (:mod:`._fit`).
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from rigidsym.course.worked import Param, Solution, exact_check, is_zero, truth_check

from ._fit import (
    accepting_tol,
    exact_rotation,
    is_local_minimum,
    nearest_rotation,
    squared_residual,
)
from ._random import cayley

ID = "ex3.4"
R = sp.Rational
TITLE = "Two redundant wrench sensors"
STATEMENT = ("\"Show that the measurements are compatible, based on invariance arguments. "
             "Determine the relative orientation of the two frames\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.4"
FIGURE_NAME = "frames"
MEASURED = True
PARAMETERS = (
    Param("n_1", sp.ImmutableMatrix([0, 0, 5]), (3,), "moment read by sensor 1, in its frame "
          "F_1", "N m"),
    Param("f_1", sp.ImmutableMatrix([0, 2, 0]), (3,), "force read by sensor 1, in F_1", "N"),
    Param("n_2", sp.ImmutableMatrix([-R(5, 3), -R(10, 3), R(10, 3)]), (3,),
          "moment read by sensor 2, in its frame F_2", "N m"),
    Param("f_2", sp.ImmutableMatrix([-R(4, 3), R(4, 3), R(2, 3)]), (3,),
          "force read by sensor 2, in F_2", "N"),
)
VARIANTS = (
    ("noisy float readings (least squares, tol)", {"n_2": [-1.667, -3.333, 3.334],
                                                   "f_2": [-1.333, 1.334, 0.667]}),
    ("readings that are not compatible (ill-posed)", {"f_2": [1, 1, 1]}),
)
_INVARIANTS = ("||f||^2", "||n||^2", "n.f")


def _invariants(n, f) -> sp.Matrix:
    return sp.Matrix([f.dot(f), n.dot(n), n.dot(f)])


def solve(n_1=PARAMETERS[0].default, f_1=PARAMETERS[1].default, n_2=PARAMETERS[2].default,
          f_2=PARAMETERS[3].default, tol=None) -> Solution:
    """Worked solution of Exercise 3.4 (exact data; ``tol``: the measured-data path)."""
    n1, f1, n2, f2 = (sp.Matrix(v) for v in (n_1, f_1, n_2, f_2))
    s = Solution(ID, TITLE, STATEMENT, CITATION,
                 given={"n_1": n1, "f_1": f1, "n_2": n2, "f_2": f2},
                 assumptions=["Both sensors report the wrench at the same point P, so n and f "
                              "change between frames by the same rotation Q (no moment "
                              "transfer)."])
    inv1 = s.step("invariants in F1", _invariants(n1, f1),
                  "A rotation preserves ||f||^2, ||n||^2 and n.f.")
    inv2 = s.step("invariants in F2", _invariants(n2, f2),
                  "A rotation must leave them equal to those in F1 (exactly, or within the "
                  "tolerance for measured data).")
    for n, f, frame in ((n1, f1, "F_1"), (n2, f2, "F_2")):
        if is_zero(f.cross(n)):
            s.fail(f"In {frame} the force and the moment are parallel (or one is zero), so "
                   f"the readings fix the rotation only up to a turn about their line.")
    if tol is None:
        return _exact(s, n1, f1, n2, f2, inv1, inv2)
    return _measured(s, n1, f1, n2, f2, tol)


def _exact(s: Solution, n1, f1, n2, f2, inv1, inv2) -> Solution:
    for k, name in enumerate(_INVARIANTS):
        if not is_zero(inv1[k] - inv2[k]):
            gap = max(_gaps(n1, f1, n2, f2), key=float)
            s.fail(f"The measurements are not compatible: {name} is {inv1[k]} in F_1 but "
                   f"{inv2[k]} in F_2, and a rotation preserves it{accepting_tol(gap)}.")
    B1 = s.step("triad in F1", sp.Matrix.hstack(f1, n1, f1.cross(n1)),
                "f, n and f x n are independent (f, n not parallel) and rotate together.")
    B2 = s.step("triad in F2", sp.Matrix.hstack(f2, n2, f2.cross(n2)), "The same triad in F2.")
    Q = s.step("rotation F2 -> F1", (B1 * B2.inv()).applyfunc(sp.radsimp),
               "[x]_1 = Q [x]_2 for the three columns.")
    s.answers = {"invariants": inv1, "compatible": sp.true, "Q_1_2": Q}
    s.check(truth_check("invariants equal (exact)", inv1 == inv2, f"{list(inv1)}"))
    s.check(exact_check("Q^T Q = 1, det Q = 1", [Q.T * Q - sp.eye(3), Q.det() - 1]))
    s.check(exact_check("Q maps the F2 measurements onto the F1 ones", [Q * n2 - n1, Q * f2 - f1]))
    return s


def _gaps(n1, f1, n2, f2) -> list[sp.Expr]:
    """Differences of the invariants in the data's own units: ||f||, ||n||, n.f/||f||."""
    a = [sp.sqrt(f1.dot(f1)), sp.sqrt(n1.dot(n1)), n1.dot(f1) / sp.sqrt(f1.dot(f1))]
    b = [sp.sqrt(f2.dot(f2)), sp.sqrt(n2.dot(n2)), n2.dot(f2) / sp.sqrt(f2.dot(f2))]
    return [sp.Abs(x - y) for x, y in zip(a, b, strict=True)]


def _measured(s: Solution, n1, f1, n2, f2, tol) -> Solution:
    gaps = s.step("invariant gaps", sp.Matrix(_gaps(n1, f1, n2, f2)),
                  "| ||f||_1 - ||f||_2 |, | ||n||_1 - ||n||_2 |, and the gap of the moment "
                  "component along f, n.f/||f||, all in the data's units.")
    names = ("||f||", "||n||", "n.f/||f||")
    for g, name in zip(gaps, names, strict=True):
        if bool(g > tol):
            s.fail(f"The measurements are not compatible within tol = {float(tol):.3g}: "
                   f"{name} differs by {float(g):.3g} between F_1 and F_2, and a rotation "
                   f"preserves it{accepting_tol(max(gaps, key=float))}.")
    pairs = [(f1, f2), (n1, n2)]
    M = s.step("correlation", f1 * f2.T + n1 * n2.T,
               "Least squares: Q maximises tr(Q^T M), M = f_1 f_2^T + n_1 n_2^T (orthogonal "
               "Procrustes).")
    Qf = nearest_rotation(np.array(M.tolist(), dtype=float))
    Q = s.step("rotation F2 -> F1 (least squares)", exact_rotation(Qf),
               "Kabsch: Q = U diag(1, 1, det(U V^T)) V^T from M = U S V^T, rounded to an "
               "exactly orthogonal rational matrix by the Cayley transform.")
    r2 = squared_residual(Q, pairs)
    res = s.step("residual", sp.Float(sp.sqrt(r2).evalf(20), 4),
                 "sqrt(||Q f_2 - f_1||^2 + ||Q n_2 - n_1||^2), to 4 digits (a statistic of "
                 "the measurements).")
    s.answers = {"invariants": _invariants(n1, f1), "compatible": sp.true, "Q_1_2": Q,
                 "residual": res}
    s.check(exact_check("Q^T Q = 1, det Q = 1 (exact rationals)", [Q.T * Q - sp.eye(3),
                                                                   Q.det() - 1]))
    s.check(truth_check(f"invariants agree within tol = {float(tol):.3g}",
                        all(bool(g <= tol) for g in gaps), "exact comparison of closed "
                        "numbers"))
    s.check(truth_check("Q is a least-squares minimum: turning it by 2e-4 rad about any of "
                        "+-x, +-y, +-z does not lower the residual", is_local_minimum(Q, pairs),
                        "six exact rational rotations, residuals compared in Q"))
    return s


def figure(s: Solution):
    """The two sensor frames: F_1 and F_2 (its axes are the columns of Q_1_2), with the
    measured force and moment drawn in F_1; F_2's readings mapped by Q as dashed arrows."""
    from ._draw import arrow, axes3d, frame, new_figure

    Q, g = s.answers["Q_1_2"], s.given
    size = max(float(sp.N(sp.sqrt(v.dot(v)))) for v in (g["f_1"], g["n_1"])) * 0.6
    fig, ax = new_figure("Exercise 3.4: the two sensor frames")
    frame(ax, sp.zeros(3, 1), sp.eye(3), "1", "0.2", scale=size)
    frame(ax, sp.zeros(3, 1), Q, "2", "tab:purple", scale=size)
    arrow(ax, sp.zeros(3, 1), g["f_1"], "tab:red", "f (F_1)")
    arrow(ax, sp.zeros(3, 1), g["n_1"], "tab:blue", "n (F_1)")
    # the checks land on the readings they check (that is the point), so they are drawn
    # apart: a dashed arrow of another colour and a hollow ring at its tip
    for vec, colour, label in ((Q * g["f_2"], "tab:orange", "Q f_2 (check: tip on f's)"),
                               (Q * g["n_2"], "tab:cyan", "Q n_2 (check: tip on n's)")):
        arrow(ax, sp.zeros(3, 1), vec, colour, None, dashed=True)
        tip = [float(x) for x in vec]
        ax.scatter(*tip, s=160, facecolors="none", edgecolors=colour, linewidths=2.0,
                   label=label, depthshade=False)
    axes3d(ax, [g["f_1"], g["n_1"], sp.ones(3, 1) * size, -sp.ones(3, 1) * size])
    return fig


def given_figure(s: Solution):
    """The given data only (the students' handout): each sensor's readings in its own
    frame, side by side; the relative orientation is the question."""
    from ._draw import arrow, axes3d, frame, new_figure

    g = s.data
    size = max(float(sp.N(sp.sqrt(v.dot(v)))) for v in g.values()) * 0.6
    fig, ax = new_figure("The readings of sensor 1 (in F_1) and sensor 2 (in F_2)")
    shift = sp.Matrix([0, 2.5 * size, 0])
    frame(ax, sp.zeros(3, 1), sp.eye(3), "1", "0.2", scale=size)
    frame(ax, shift, sp.eye(3), "2", "tab:purple", scale=size)
    arrow(ax, sp.zeros(3, 1), g["f_1"], "tab:red", "f_1 (in F_1)")
    arrow(ax, sp.zeros(3, 1), g["n_1"], "tab:blue", "n_1 (in F_1)")
    arrow(ax, shift, g["f_2"], "tab:red", "f_2 (in F_2)", dashed=True)
    arrow(ax, shift, g["n_2"], "tab:blue", "n_2 (in F_2)", dashed=True)
    axes3d(ax, [g["f_1"], g["n_1"], shift + g["f_2"], shift + g["n_2"],
                sp.ones(3, 1) * size, -sp.ones(3, 1) * size])
    return fig


def random_data(rng) -> dict:
    """A well-posed variant with readable exact numbers (an exam's draw): readings in F_1
    of small integers, F_2 turned by a Cayley rotation of small rationals."""
    Q = cayley(rng)
    n1 = sp.Matrix([rng.randint(-4, 4) for _ in range(3)])
    f1 = sp.Matrix([rng.randint(-3, 3) for _ in range(3)])
    return {"n_1": list(n1), "f_1": list(f1), "n_2": list(Q.T * n1), "f_2": list(Q.T * f1)}
