"""Exercise 3.2: two unit forces on a regular tetrahedron; the point of least moment."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Param, Solution, exact_check, is_zero, values_only

ID = "ex3.2"
TITLE = "Wrench on a regular tetrahedron"
STATEMENT = ("\"f_1 is directed from P_2 to P_3, whereas f_2 is directed from P_4 to P_1 ... "
             "Find the location of point P lying closest to P_4 that will make the magnitude "
             "of n a minimum.\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.2"
#: the documented unit of each answer with one (graded answers may be written in any
#: compatible unit); the others are pure numbers or mixed
ANSWER_UNITS = {"P": "m"}
FIGURE_NAME = "tetrahedron"
#: the solver runs on floating data for a slip's replay (rigidsym.course.worked.solve_values):
#: its decisions are is_zero's, its closed forms only simplified when exact
VALUES_REPLAY = True
_r3, _r6 = sp.sqrt(3), sp.sqrt(6)
_BOOK = ([0, 0, 0], [1, 0, 0], [sp.Rational(1, 2), _r3 / 2, 0],
         [sp.Rational(1, 2), _r3 / 6, _r6 / 3])
PARAMETERS = tuple(Param(f"P_{k}", sp.ImmutableMatrix(v), (3,), m, "m") for k, v, m in zip(
    (1, 2, 3, 4), _BOOK,
    ("vertex P_1 (f_2 points to it)", "vertex P_2 (f_1 starts there)",
     "vertex P_3 (f_1 points to it)", "vertex P_4 (f_2 starts there)"), strict=True))
VARIANTS = (
    ("a taller tetrahedron", {"P_4": ["1/2", "sqrt(3)/6", 2]}),
    ("a square, where the forces are opposite (ill-posed)",
     {"P_1": [0, 0, 0], "P_2": [1, 0, 0], "P_3": [1, 1, 0], "P_4": [0, 1, 0]}),
)


def unit(v) -> sp.Matrix:
    """``v / ||v||`` with radicals simplified."""
    return (v / sp.sqrt(v.dot(v))).applyfunc(_simplified)


def _simplified(e):
    """An entry in the closed form of its number field: products of radicals expanded and
    denominators rationalised (``a + b sqrt(157)``, not nested products); unchanged in a
    replay for its values only (floating data)."""
    if values_only():
        return e
    return sp.radsimp(sp.expand(sp.radsimp(e)))


def _what_the_data_are(P1, P2, P3, P4) -> tuple[str, str]:
    """The title and the first assumption, named after the data: the book's figure, or the
    tetrahedron (regular or not, or four points in one plane) that the data give."""
    V = (P1, P2, P3, P4)
    if all(sp.Matrix(v) == sp.Matrix(b) for v, b in zip(V, _BOOK, strict=True)):
        return TITLE, ("Fig. 3.10 of the book, as placed here: a unit-edge regular tetrahedron "
                       "placed with P1 at O, P2 on X, P3 in the X-Y plane, P4 above it. The "
                       "answer is also given in barycentric coordinates, valid for any "
                       "placement.")
    bary = " The answer is also given in barycentric coordinates, valid for any placement."
    if is_zero(sp.Matrix.hstack(P2 - P1, P3 - P1, P4 - P1).det()):
        return ("Wrench on four points in one plane",
                "The four points P1, P2, P3, P4 as given lie in one plane (no tetrahedron).")
    edges = [_simplified(sp.sqrt((V[j] - V[i]).dot(V[j] - V[i])))
             for i in range(4) for j in range(i + 1, 4)]
    if all(is_zero(x - edges[0]) for x in edges):
        return TITLE, (f"The tetrahedron P1 P2 P3 P4 as given: a regular one, every edge "
                       f"{sp.sstr(edges[0])} m.{bary}")
    return ("Wrench on a tetrahedron",
            f"The tetrahedron P1 P2 P3 P4 as given (not regular: its edges P1P2, P1P3, P1P4, "
            f"P2P3, P2P4, P3P4 measure {', '.join(sp.sstr(x) for x in edges)} m).{bary}")


def solve(P_1=PARAMETERS[0].default, P_2=PARAMETERS[1].default, P_3=PARAMETERS[2].default,
          P_4=PARAMETERS[3].default) -> Solution:
    """Worked solution of Exercise 3.2 (vertex positions in metres)."""
    P1, P2, P3, P4 = (sp.Matrix(v) for v in (P_1, P_2, P_3, P_4))
    # the title names the data's shape: not needed for a replay's values
    title, placed = (TITLE, "") if values_only() else _what_the_data_are(P1, P2, P3, P4)
    s = Solution(ID, title, STATEMENT, CITATION,
                 given={"P1": P1, "P2": P2, "P3": P3, "P4": P4}, assumptions=[placed])
    for a, b, name in ((P2, P3, "P_2 and P_3"), (P4, P1, "P_4 and P_1")):
        if is_zero(b - a):
            s.fail(f"The vertices {name} coincide, so the force along that edge has no "
                   f"direction.")
    f1, f2 = unit(P3 - P2), unit(P1 - P4)
    f = s.step("resultant", (f1 + f2).applyfunc(_simplified),
               "f = f_1 + f_2 (unit forces along the edges).")
    n0 = s.step("moment about O", (P2.cross(f1) + P4.cross(f2)).applyfunc(_simplified),
                "f_1 acts along line P2P3, f_2 along P4P1.")
    if is_zero(f):
        s.fail("The two forces are opposite (f = 0): they form a couple, whose moment is "
               "the same at every point, so no point is singled out.")
    p0 = s.step("central axis point", (f.cross(n0) / f.dot(f)).applyfunc(_simplified),
                "The moment is least (parallel to f) on the central axis {f x n_O / ||f||^2 "
                "+ lambda f}.")
    lam = _simplified((P4 - p0).dot(f) / f.dot(f))
    P = s.step("closest to P4", (p0 + lam * f).applyfunc(_simplified),
               "Foot of the perpendicular from P4 on the central axis.")
    Bh = sp.Matrix.vstack(sp.Matrix.hstack(P1, P2, P3, P4), sp.ones(1, 4))
    nP = (n0 - P.cross(f)).applyfunc(_simplified)
    s.answers = {"P": P}
    if not is_zero(Bh.det()):
        bary = (Bh.inv() * sp.Matrix.vstack(P, sp.Matrix([1]))).applyfunc(_simplified)
        s.step("barycentric coordinates", bary,
               "P = sum w_i P_i with sum w_i = 1 (placement-free).")
        s.answers["P_barycentric"] = bary
    s.answers.update({"n_min": nP, "f": f, "n_min_magnitude": sp.sqrt(_simplified(nP.dot(nP)))})
    if values_only():
        return s                # a replay for its values: no check (its exact solve checks)
    s.check(exact_check("unit forces along the edges: ||f_i|| = 1, f_1 x (P3 - P2) = 0, "
                        "f_2 x (P1 - P4) = 0",
                        [f1.dot(f1) - 1, f2.dot(f2) - 1, f1.cross(P3 - P2), f2.cross(P1 - P4)]))
    s.check(exact_check("moment at P is parallel to f (minimum magnitude) and P - P4 is normal "
                        "to f (closest point)", [nP.cross(f), (P - P4).dot(f)]))
    s.check(exact_check("same wrench: the moment of f_1 and f_2 about P equals n_min",
                        [(P2 - P).cross(f1) + (P4 - P).cross(f2) - nP]))
    return s


def figure(s: Solution):
    """The tetrahedron, the two forces on their edges, the central axis and the point P
    closest to P_4 with the least moment."""
    from ._draw import arrow, axes3d, edges, line_in_box, new_figure, point, segment

    V = {k: s.given[f"P{k}"] for k in "1234"}
    fig, ax = new_figure("Exercise 3.2: forces on the tetrahedron, the point of least moment")
    edges(ax, V, ["12", "13", "14", "23", "24", "34"], "0.55", "tetrahedron")
    for k, v in V.items():
        point(ax, v, "0.3", text=f"P{k}")
    arrow(ax, V["2"], unit(V["3"] - V["2"]), "tab:red", "f_1")
    arrow(ax, V["4"], unit(V["1"] - V["4"]), "tab:orange", "f_2")
    P, f = s.answers["P"], s.answers["f"]
    line_in_box(ax, P, f, list(V.values()) + [P], "tab:green", "central axis")
    point(ax, P, "tab:green", "P (least moment)", "P")
    segment(ax, V["4"], P, color="tab:green", linestyle=":")
    axes3d(ax, list(V.values()) + [P])
    return fig


def given_figure(s: Solution):
    """The given data only (the students' handout): the tetrahedron and the two unit
    forces on their edges; the central axis and the point P are the questions."""
    from ._draw import arrow, axes3d, edges, new_figure, point

    V = {k: sp.Matrix(s.data[f"P_{k}"]) for k in "1234"}
    fig, ax = new_figure("The tetrahedron and the two unit forces on its edges")
    edges(ax, V, ["12", "13", "14", "23", "24", "34"], "0.55", "tetrahedron")
    for k, v in V.items():
        point(ax, v, "0.3", text=f"P{k}")
    arrow(ax, V["2"], unit(V["3"] - V["2"]), "tab:red", "f_1")
    arrow(ax, V["4"], unit(V["1"] - V["4"]), "tab:orange", "f_2")
    axes3d(ax, list(V.values()))
    return fig


def random_data(rng) -> dict:
    """A variant with readable exact numbers (an exam's draw): the regular tetrahedron on
    alternate corners of a cube of side 2, 4 or 6 (edge 2 sqrt(2) k, k = 1, 2, 3), its vertices
    in a random order, turned by a Cayley rotation with entries of denominator 3 and
    shifted by small integers: rational vertices, a regular tetrahedron exactly."""
    from ._random import cayley_small, small_vector

    corners = [sp.Matrix(v) for v in ((1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1))]
    rng.shuffle(corners)
    side, Q, t = rng.choice((1, 2, 3)), cayley_small(rng, halves=False), small_vector(rng, -2, 2)
    return {f"P_{k}": list(side * Q * v + t) for k, v in enumerate(corners, 1)}
