"""Exercise 3.7: Plücker coordinates of an axis from its moments about two points."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.worked import Param, Solution, exact_check, is_zero, truth_check

ID = "ex3.7"
TITLE = "Calibrating an axis from two moment measurements"
STATEMENT = ("\"the moment of this axis is measured with respect to two points, A and B ... "
             "Determine the unit vector e ... the point P* ... the Plücker coordinates of the "
             "axis about the origin\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.7"
FIGURE_NAME = "axis"
_V = sp.ImmutableMatrix
PARAMETERS = (
    Param("a", _V([1, 0, 0]), (3,), "position of point A", "m"),
    Param("b", _V([0, 1, 1]), (3,), "position of point B", "m"),
    Param("n_A", _V([0, 2, 0]), (3,), "measured moment of the axis about A", "m"),
    Param("n_B", _V([0, 1, 1]), (3,), "measured moment of the axis about B", "m"),
)
VARIANTS = (
    ("the moment about the origin instead of A", {"a": [0, 0, 0], "n_A": [0, 2, 0]}),
    ("moments of no single line (ill-posed)", {"n_B": [0, 1, 2]}),
)


def solve(a=PARAMETERS[0].default, b=PARAMETERS[1].default, n_A=PARAMETERS[2].default,
          n_B=PARAMETERS[3].default) -> Solution:
    """Worked solution of Exercise 3.7 (positions and moments in metres)."""
    a, b, nA, nB = (sp.Matrix(v) for v in (a, b, n_A, n_B))
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"a": a, "b": b, "n_A": nA, "n_B": nB},
        assumptions=["The moment of the line about a point X is n_X = (p - x) x e for any p "
                     "on the line (Sec. 3.3); the sign of e is fixed by n_A - n_B = (b - a) x e."])
    u = s.step("direction", nA.cross(nB),
               "Both moments are normal to e (n_X.e = 0), so e is parallel to n_A x n_B.")
    if is_zero(u):
        s.fail("The two moments are parallel (or one is zero), so they do not fix the "
               "direction of the axis.")
    e0 = (u / u.norm()).applyfunc(sp.radsimp)
    rel = s.step("transfer", ((b - a).cross(e0) - (nA - nB)).applyfunc(sp.radsimp),
                 "n_A - n_B = (b - a) x e fixes the sense of e (zero for e = +u/||u||).")
    if is_zero(rel):
        e = e0
    elif is_zero((b - a).cross(-e0) - (nA - nB)):
        e = -e0
    else:
        s.fail("The moments are not those of one line: n_A - n_B must equal (b - a) x e for "
               "a unit e normal to both, and it does not for either sense of e.")
    n0 = s.step("moment about O", nA + a.cross(e), "n_O = n_A + a x e (moment transfer).")
    ps = s.step("closest point", e.cross(n0), "p* = e x n_O (Exercise 3.5).")
    pl = s.step("Plücker coordinates about O", sp.Matrix.vstack(e, n0), "[e; n_O].")
    s.answers = {"e": e, "p_star": ps, "plucker_O": pl}
    s.check(exact_check("(p* - a) x e = n_A and (p* - b) x e = n_B (the data are reproduced)",
                        [(ps - a).cross(e) - nA, (ps - b).cross(e) - nB]))
    s.check(exact_check("Plücker constraints: e.e = 1, e.n_O = 0; p*.e = 0",
                        [e.dot(e) - 1, e.dot(n0), ps.dot(e)]))
    s.check(truth_check("both measured moments are normal to e",
                        is_zero(nA.dot(e)) and is_zero(nB.dot(e)), "exact (minimal polynomial)"))
    return s


def figure(s: Solution):
    """The axis with its unit vector e, the points A and B with the measured moments, and
    the point P* closest to the origin."""
    from ._draw import arrow, axes3d, line_in_box, new_figure, point

    g, e, ps = s.given, s.answers["e"], s.answers["p_star"]
    fig, ax = new_figure("Exercise 3.7: the axis from two moment measurements")
    point(ax, sp.zeros(3, 1), "0.3", text="O")
    point(ax, g["a"], "tab:green", text="A")
    point(ax, g["b"], "tab:purple", text="B")
    arrow(ax, g["a"], g["n_A"], "tab:green", "n_A at A")
    arrow(ax, g["b"], g["n_B"], "tab:purple", "n_B at B")
    pts = [sp.zeros(3, 1), g["a"], g["b"], g["a"] + g["n_A"], g["b"] + g["n_B"], ps]
    line_in_box(ax, ps, e, pts, "tab:blue", "axis")
    arrow(ax, ps, e, "tab:blue", "e")
    point(ax, ps, "tab:red", "P* (closest to O)", "P*")
    axes3d(ax, pts)
    return fig


def given_figure(s: Solution):
    """The given data only (the students' handout): the points A and B with the moments
    measured there; the axis is the question."""
    from ._draw import arrow, axes3d, new_figure, point

    g = s.data
    a, b, nA, nB = (sp.Matrix(g[k]) for k in ("a", "b", "n_A", "n_B"))
    fig, ax = new_figure("The moments of the axis measured at A and at B")
    point(ax, sp.zeros(3, 1), "0.3", text="O")
    point(ax, a, "tab:green", text="A")
    point(ax, b, "tab:purple", text="B")
    arrow(ax, a, nA, "tab:green", "n_A at A")
    arrow(ax, b, nB, "tab:purple", "n_B at B")
    axes3d(ax, [sp.zeros(3, 1), a, b, a + nA, b + nB])
    return fig


def random_data(rng) -> dict:
    """A well-posed variant with readable exact numbers (an exam's draw): A, B and a point
    of the axis of small integers, the axis's direction a Pythagorean quadruple, and the
    moments n_X = (p - x) x e it has about A and B (redrawn until they are not parallel)."""
    from ._random import small_vector, unit_vector

    while True:
        a, b, p = small_vector(rng, -2, 2), small_vector(rng, -2, 2), small_vector(rng)
        e = unit_vector(rng)
        nA, nB = (p - a).cross(e), (p - b).cross(e)
        if not is_zero(nA.cross(nB)):
            return {"a": list(a), "b": list(b), "n_A": list(nA), "n_B": list(nB)}
