"""Exercise 3.1: rotation, minimum-displacement line and its plane intersections for a cube."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Param, Solution, exact_check, is_zero

from ._fit import fitted_rotation
from ._screw import rotation_defect, screw_of_displacement

ID = "ex3.1"
TITLE = "Screw motion of a cube"
STATEMENT = ("\"Determine the matrix representing the rotation Q undergone by the cube ... "
             "Find the Plücker coordinates of line L of the cube undergoing displacements of "
             "minimum magnitude. Find the intersections of L with the coordinate planes.\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.1"
#: the documented unit of each answer with one (graded answers may be written in any
#: compatible unit); the others are pure numbers or mixed
ANSWER_UNITS = {"phi": "rad"}
#: the axis's points on the coordinate planes are points of the data's frame: lengths, with a
#: length's unit slips (mm, cm for m), though written with no unit
ANSWER_KINDS = {"intersection_x=0": "length", "intersection_y=0": "length",
                "intersection_z=0": "length"}
#: what the answers are (the grader judges a student's answer by its class): the axis and
#: angle of Q with the Plücker array of its axis, one sign for all three ((e, phi, [e; n])
#: is (-e, -phi, -[e; n])) and phi + 2 pi k
ANSWER_CLASSES = ({"kind": "axis-angle", "axis": "e", "angle": "phi", "linked": ("plucker",)},)
FIGURE_NAME = "cube"
#: the vertices may be measurements (decimals, or floats): the rotation is then the
#: nearest one to the edges' (orthogonal Procrustes), its misfit printed and within tol
MEASURED = True
_V = sp.ImmutableMatrix
# Assumed geometry (Fig. 3.9 is not in the text): unit cube, A at O, B on X, D on Y, E on Z,
# turned 120 deg about [1, 1, 1] and shifted.
PARAMETERS = (
    Param("A", _V([0, 0, 0]), (3,), "vertex A before the displacement", "m"),
    Param("B", _V([1, 0, 0]), (3,), "vertex B (edge AB)", "m"),
    Param("D", _V([0, 1, 0]), (3,), "vertex D (edge AD)", "m"),
    Param("E", _V([0, 0, 1]), (3,), "vertex E (edge AE)", "m"),
    Param("A_prime", _V([0, 2, 0]), (3,), "vertex A after the displacement", "m"),
    Param("B_prime", _V([0, 3, 0]), (3,), "vertex B after", "m"),
    Param("D_prime", _V([0, 2, 1]), (3,), "vertex D after", "m"),
    Param("E_prime", _V([1, 2, 0]), (3,), "vertex E after", "m"),
)
VARIANTS = (
    ("a half turn about the z axis", {"A_prime": [0, 0, 0], "B_prime": [-1, 0, 0],
                                      "D_prime": [0, -1, 0], "E_prime": [0, 0, 1]}),
    ("a pure translation (ill-posed)", {"A_prime": [1, 0, 0], "B_prime": [2, 0, 0],
                                        "D_prime": [1, 1, 0], "E_prime": [1, 0, 1]}),
)
_PLANES = {"X": "x=0", "Y": "y=0", "Z": "z=0"}


def cube_vertices(A, B, D, E) -> dict:
    """The eight vertices of the parallelepiped on the edges AB, AD, AE (a cube for the
    book's data): ``C = B + D - A``, ``F = B + E - A``, ``G = B + D + E - 2A``, ``H``."""
    return {"A": A, "B": B, "C": B + D - A, "D": D, "E": E, "F": B + E - A,
            "G": B + D + E - 2 * A, "H": D + E - A}


def solve(A=PARAMETERS[0].default, B=PARAMETERS[1].default, D=PARAMETERS[2].default,
          E=PARAMETERS[3].default, A_prime=PARAMETERS[4].default,
          B_prime=PARAMETERS[5].default, D_prime=PARAMETERS[6].default,
          E_prime=PARAMETERS[7].default, tol=None) -> Solution:
    """Worked solution of Exercise 3.1 (vertices before and after, in metres; ``tol``:
    measured vertices, the rotation the least-squares one within ``tol`` metres)."""
    P = {k: sp.Matrix(v) for k, v in zip("ABDE", (A, B, D, E), strict=True)}
    Pp = {k: sp.Matrix(v) for k, v in zip("ABDE", (A_prime, B_prime, D_prime, E_prime),
                                           strict=True)}
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"A, B, D, E": sp.Matrix.hstack(*P.values()),
               "A', B', D', E'": sp.Matrix.hstack(*Pp.values())},
        assumptions=["The data of Fig. 3.9 of the book, as read here: unit cube with A = O and "
                     "edges AB, AD, AE along X, Y, Z; displaced vertices A' = (0, 2, 0), "
                     "B' = (0, 3, 0), D' = (0, 2, 1), E' = (1, 2, 0) (a 120 deg turn about "
                     "[1, 1, 1] and a shift). The method holds for any data: Q = [B'-A', "
                     "D'-A', E'-A'][B-A, D-A, E-A]^-1."])
    edges0 = sp.Matrix.hstack(P["B"] - P["A"], P["D"] - P["A"], P["E"] - P["A"])
    if is_zero(edges0.det()):
        s.fail("The edges AB, AD and AE are linearly dependent (det = 0), so they do not "
               "fix the rotation.")
    edges1 = sp.Matrix.hstack(Pp["B"] - Pp["A"], Pp["D"] - Pp["A"], Pp["E"] - Pp["A"])
    Q = s.step("rotation", (edges1 * edges0.inv()).applyfunc(sp.radsimp),
               "Edge vectors rotate: [b'-a', d'-a', e'-a'] = Q [b-a, d-a, e-a].")
    defect = rotation_defect(Q)
    residual = None
    if defect and tol is not None:
        Q, residual = fitted_rotation(s, edges0, edges1, tol, "edge")
    elif defect:
        s.fail(f"The displaced vertices are not a rigid motion of the given ones ({defect}), "
               f"so there is no rotation Q (measured vertices: give --tol, or decimals).")
    screw = screw_of_displacement(Q, P["A"], Pp["A"])
    if screw is None:
        s.fail("The displacement is a pure translation (Q = 1): every point moves by the "
               "same vector, so no line of minimum displacement is singled out.")
    return _finish(s, Q, P, Pp, *screw, residual=residual)


def _finish(s: Solution, Q, P, Pp, phi, e, p0, pl, residual=None) -> Solution:
    s.step("angle", phi, "cos(phi) = (tr Q - 1)/2.")
    s.step("axis", e, "e = vect(Q)/sin(phi) (a column of Q + 1 for a half turn).")
    s.step("point of L closest to O", p0,
           "Eq. (3.18): p0 = (Q - 1)^T (Q a - a') / (2(1 - cos phi)).")
    s.step("Plücker coordinates", pl, "[e; p0 x e].")
    hits = []
    for i, name in enumerate("XYZ"):
        if not is_zero(e[i]):
            lam = -p0[i] / e[i]
            hits.append((name, (p0 + lam * e).applyfunc(sp.radsimp)))
    if hits:
        s.step("plane intersections", sp.Matrix.hstack(*[h for _, h in hits]),
               "p0 + lambda e with the i-th coordinate zero (planes x = 0, y = 0, z = 0; L "
               "parallel to a plane misses it).")
    s.answers = {"Q": Q, "phi": phi, "e": e, "plucker": pl}
    for name, h in hits:
        s.answers[f"intersection_{_PLANES[name]}"] = h
    c = Pp["A"] - Q * P["A"]
    if residual is not None:
        s.answers["residual"] = residual
        s.check(exact_check("Q proper orthogonal (exact rationals)",
                            [Q.T * Q - sp.eye(3), Q.det() - 1]))
    else:
        s.check(exact_check("Q proper orthogonal, maps every given edge of the cube",
                            [Q.T * Q - sp.eye(3), Q.det() - 1]
                            + [Q * (P[k] - P["A"]) - (Pp[k] - Pp["A"]) for k in P]))
    s.check(exact_check("Plücker constraints e.e = 1, e.n = 0; points of L move along e with "
                        "the minimum magnitude |e.c|",
                        [pl[:3, :].dot(pl[:3, :]) - 1, pl[:3, :].dot(pl[3:, :])]
                        + [((Q - sp.eye(3)) * x + c).cross(e) for x in (p0, p0 + e)]
                        + [((Q - sp.eye(3)) * p0 + c).dot((Q - sp.eye(3)) * p0 + c)
                           - e.dot(c)**2]))
    if hits:
        s.check(exact_check("intersections lie on L (x x e = n) and on their planes",
                            [h.cross(e) - pl[3:, :] for _, h in hits]
                            + [h["XYZ".index(n)] for n, h in hits]))
    return s


def figure(s: Solution):
    """The cube before (grey) and after (blue) the displacement, with the line L of
    minimum displacement (red) and its intersections with the coordinate planes."""
    from ._draw import axes3d, line_in_box, new_figure, point

    before = [s.given["A, B, D, E"][:, k] for k in range(4)]
    after = [s.given["A', B', D', E'"][:, k] for k in range(4)]
    fig, ax = new_figure("Exercise 3.1: the cube displaced, and the line L")
    pts = _draw_cubes(ax, before, after)
    e, p0 = s.answers["e"], s.answers["plucker"][:3, :].cross(s.answers["plucker"][3:, :])
    for k, v in s.answers.items():
        if k.startswith("intersection_"):
            point(ax, v, "tab:red", text=k.split("_")[1])
            pts.append(v)
    line_in_box(ax, p0, e, pts, "tab:red", "L (minimum displacement)")
    axes3d(ax, pts)
    return fig


def given_figure(s: Solution):
    """The given data only (the students' handout): the cube before (grey) and after
    (blue) the displacement; the rotation and the line L are the questions."""
    from ._draw import axes3d, new_figure

    before = [sp.Matrix(s.data[k]) for k in ("A", "B", "D", "E")]
    after = [sp.Matrix(s.data[k]) for k in ("A_prime", "B_prime", "D_prime", "E_prime")]
    fig, ax = new_figure("The cube before and after the displacement")
    axes3d(ax, _draw_cubes(ax, before, after))
    return fig


def _draw_cubes(ax, before, after) -> list:
    """The cube on the edges A, B, D, E before (grey) and after (blue), its given vertices
    named; returns the vertices drawn."""
    from ._draw import edges, point

    V0, V1 = cube_vertices(*before), cube_vertices(*after)
    pairs = ["AB", "BC", "CD", "DA", "EF", "FG", "GH", "HE", "AE", "BF", "CG", "DH"]
    edges(ax, V0, pairs, "0.55", "before")
    edges(ax, V1, pairs, "tab:blue", "after")
    for k in "ABDE":
        point(ax, V0[k], "0.35", text=k)
        point(ax, V1[k], "tab:blue", text=k + "'")
    return list(V0.values()) + list(V1.values())


def random_data(rng) -> dict:
    """A variant with readable exact numbers (an exam's draw): a cube of side 1 or 2 with
    its edges along the axes and A at small integers, turned by a Cayley rotation of
    entries of denominator 3 or 9 (about no coordinate axis) and shifted by small integers."""
    from ._random import cayley_small, small_vector

    side, A = rng.choice((1, 2)), small_vector(rng, -1, 1)
    P = {"A": A, "B": A + side * sp.Matrix([1, 0, 0]), "D": A + side * sp.Matrix([0, 1, 0]),
         "E": A + side * sp.Matrix([0, 0, 1])}
    Q, t = cayley_small(rng), small_vector(rng, -2, 2)
    out = {k: list(v) for k, v in P.items()}
    out.update({f"{k}_prime": list(Q * v + t) for k, v in P.items()})
    return out
