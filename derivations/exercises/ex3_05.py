"""Exercise 3.5: distance of a line to the origin and its closest point, from Plücker data."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import (
    Param,
    Solution,
    exact_check,
    identity_check,
    is_zero,
    truth_check,
)
from rigidsym.declare import unit_vector, vector

ID = "ex3.5"
TITLE = "Joint-axis calibration from Plücker coordinates"
STATEMENT = ("\"Show that the distance of the axis to the origin ... d = ||n||. Show that the "
             "point P* on the axis, which lies closest to the above-mentioned origin, has a "
             "position vector p* = e x n\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.5"
#: the documented unit of each answer with one (graded answers may be written in any
#: compatible unit); the others are pure numbers or mixed
ANSWER_UNITS = {"d": "m", "p_star": "m"}
FIGURE_NAME = "axis"
#: the Plücker coordinates may be measurements (decimals, or floats): coordinates within
#: tol of a line's (e.n not quite 0) are moved to the nearest line's, the distance printed
MEASURED = True
_h = sp.sqrt(2) / 2
PARAMETERS = (Param("plucker", sp.ImmutableMatrix([-_h, 0, _h, 0, -sp.sqrt(2), 0]), (6,),
                    "estimated Plücker coordinates [e; n] of the joint axis in the gripper "
                    "frame G (e its direction, n its moment about the origin)", "-; m"),)
VARIANTS = (
    ("Plücker coordinates not normalised", {"plucker": [0, 0, 2, 2, 0, 0]}),
    ("not a line, e.n != 0 (ill-posed)", {"plucker": [1, 0, 0, 1, 0, 0]}),
)


def solve(plucker=PARAMETERS[0].default, tol=None) -> Solution:
    """Worked solution of Exercise 3.5 (``plucker``: the 6 Plücker coordinates [e; n];
    ``tol``, in m: measured coordinates, whose e.n need only be 0 within tol)."""
    e = unit_vector("ex35_e")
    p = vector("p")
    data = sp.Matrix(plucker)
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"line": "through a point p, unit direction e; n = p x e (Plücker moment)",
               "[pi_L]_G": data},
        assumptions=["e is a unit vector (normalised Plücker coordinates), as the book's "
                     "data have; other data are normalised first (Plücker coordinates are "
                     "homogeneous)."])
    n, ps = p.cross(e), e.cross(p.cross(e))
    s.step("moment", "n = p x e",
           "The moment of the line about the origin (Sec. 3.3), p any point of the line.")
    s.step("(a) candidate", "p* = e x n = e x (p x e) = (e.e) p - (e.p) e = p - (e.p) e",
           "The double cross product a x (b x c) = (a.c) b - (a.b) c, and e.e = 1.")
    s.step("(a) on the line", "p* x e = (p - (e.p) e) x e = p x e = n",
           "e x e = 0; a point whose moment about O is the line's lies on the line, so p* "
           "is a point of it.")
    s.step("(a) closest", "p*.e = e.p - (e.p)(e.e) = 0",
           "O - p* is normal to the line, so p* is the foot of the perpendicular from O: "
           "||p* + lambda e||^2 = ||p*||^2 + lambda^2 is least at lambda = 0.")
    s.step("(b) distance", "||p*||^2 = ||e x n||^2 = (e.e)(n.n) - (e.n)^2 = ||n||^2",
           "Lagrange's identity, e.e = 1 and e.n = e.(p x e) = 0: d = ||p*|| = ||n||.")
    ec, nc = data[:3, :], data[3:, :]
    if is_zero(ec):
        s.fail("The direction part e of the data is zero, so they are not the Plücker "
               "coordinates of a line.")
    residual = None
    if tol is not None and not is_zero(ec.dot(nc)):
        ec, nc, residual = _measured(s, ec, nc, tol)
    line = sp.Matrix.vstack(ec, nc)          # the data, or the nearest line to them
    if not is_zero(ec.dot(nc)):
        s.fail(f"e.n = {sp.radsimp(ec.dot(nc))} is not zero, so the data are not the Plücker "
               f"coordinates of a line (the moment of a line is normal to it).")
    if not is_zero(ec.dot(ec) - 1):
        k = sp.sqrt(ec.dot(ec))
        ec, nc = (ec / k).applyfunc(sp.radsimp), (nc / k).applyfunc(sp.radsimp)
        s.step("(c) normalised", sp.Matrix.vstack(ec, nc),
               "Divide [e; n] by ||e|| (homogeneous coordinates of the same line).")
    d = s.step("(c) d", sp.sqrt(nc.dot(nc)), "d = ||n||.")
    pstar = s.step("(c) p*", ec.cross(nc), "p* = e x n.")
    s.answers = {"d": d, "p_star": pstar}
    s.check(identity_check("(a)-(b) for every line: p* x e = n, p*.e = 0, ||p*||^2 = ||n||^2",
                           [ps.cross(e) - n, ps.dot(e), ps.dot(ps) - n.dot(n)]))
    # independent check of (c): minimise ||x||^2 over x = p* + lambda e, compare
    lam = sp.Symbol("lambda", real=True)
    s.check(exact_check("(c) data: ||e|| = 1, e.n = 0; p* x e = n (also for the data as "
                        "given, or the nearest line to measured data), p*.e = 0, ||p*|| = d",
                        [ec.dot(ec) - 1, ec.dot(nc), pstar.cross(ec) - nc,
                         pstar.cross(line[:3, :]) - line[3:, :], pstar.dot(ec),
                         pstar.dot(pstar) - d**2]))
    x = pstar + lam * ec
    lam_min = sp.solve(sp.diff(x.dot(x), lam), lam)
    s.check(exact_check("(c) minimising ||p* + lambda e||^2 gives lambda = 0",
                        [lam_min[0]]))
    if residual is not None:
        s.answers["residual"] = residual
        s.check(truth_check(f"the data's distance to the nearest line's coordinates, "
                            f"{float(residual):.3g}, is within tol = {float(tol):.3g}",
                            bool(residual**2 <= tol**2), "exact comparison of rationals"))
    return s


def _measured(s: Solution, ec, nc, tol):
    """Measured coordinates: [e; n] moved to a line by the least step along the gradient
    [n; e] of e.n (first order: lambda = e.n/(e.e + n.n)), then n made exactly normal to
    e (a second-order change); all rational. The misfit, the distance moved (2-norm over
    the 6 coordinates), judged within ``tol`` exactly; else :meth:`Solution.fail` with
    the tolerance that would accept them. Returns the new e, n and the misfit."""
    from ._fit import accepting_tol

    en = ec.dot(nc)
    lam = en / (ec.dot(ec) + nc.dot(nc))
    e2, n1 = ec - lam * nc, nc - lam * ec
    n2 = n1 - e2.dot(n1) / e2.dot(e2) * e2
    moved = sp.Matrix.vstack(e2 - ec, n2 - nc)
    sq = moved.dot(moved)                                 # rational: decided exactly
    gap = sp.sqrt(sq)
    if bool(sq > tol**2):
        s.fail(f"e.n = {float(en):.3g}: the coordinates are not within tol = "
               f"{float(tol):.3g} of a line's (the nearest line is "
               f"{float(sp.N(gap)):.3g} away), so they are not the Plücker coordinates of a "
               f"line{accepting_tol(sp.N(gap, 30))}.")
    s.step("(c) nearest line", sp.Matrix.vstack(e2, n2),
           f"Measured data: e.n = {float(en):.3g} is not 0; [e; n] moved by the least step "
           f"along [n; e] (lambda = e.n/(e.e + n.n)), then n made normal to e: the nearest "
           f"line's coordinates, {float(sp.N(gap)):.3g} from the data, within tol = "
           f"{float(tol):.3g}.")
    return e2, n2, gap


def figure(s: Solution):
    """The joint axis, the gripper origin O and the closest point P* (distance d)."""
    from ._draw import arrow, axes3d, frame, line_in_box, new_figure, point, segment

    pstar, d = s.answers["p_star"], s.answers["d"]
    data = s.given["[pi_L]_G"]
    e = data[:3, :] / sp.sqrt(data[:3, :].dot(data[:3, :]))
    fig, ax = new_figure("Exercise 3.5: the joint axis and its point closest to O")
    size = float(sp.N(d)) + 1
    frame(ax, sp.zeros(3, 1), sp.eye(3) * size / 2, "G", "0.4")
    pts = [sp.zeros(3, 1), pstar + size * e, pstar - size * e, sp.ones(3, 1) * size / 2]
    line_in_box(ax, pstar, e, pts, "tab:blue", "axis L")
    arrow(ax, pstar, e, "tab:blue", "e")
    point(ax, pstar, "tab:red", "P* = e x n", "P*")
    segment(ax, sp.zeros(3, 1), pstar, color="tab:red", linestyle="--",
            label=f"d = ||n|| = {float(sp.N(d)):.4g} m")
    axes3d(ax, pts)
    return fig


def given_figure(s: Solution):
    """The given data only (the students' handout): the direction part e and the moment
    part n of the Plücker coordinates, as arrows at the origin of G; the axis, its point
    closest to O and the distance are the questions."""
    from ._draw import arrow, axes3d, frame, new_figure

    data = sp.Matrix(s.data["plucker"])
    e, n = data[:3, :], data[3:, :]
    size = max(float(sp.N(sp.sqrt(v.dot(v)))) for v in (e, n)) * 0.6
    fig, ax = new_figure("The Plücker coordinates [e; n] of the joint axis, in G")
    frame(ax, sp.zeros(3, 1), sp.eye(3), "G", "0.4", scale=size)
    arrow(ax, sp.zeros(3, 1), e, "tab:blue", "e (direction part)")
    arrow(ax, sp.zeros(3, 1), n, "tab:red", "n (moment part)", dashed=True)
    axes3d(ax, [e, n, sp.ones(3, 1) * size, -sp.ones(3, 1) * size])
    return fig


def random_data(rng) -> dict:
    """A variant with readable exact numbers (an exam's draw): normalised Plücker
    coordinates, the direction e a unit vector of rationals (a Pythagorean quadruple over
    its norm, as (1, 2, 2)/3) and the moment n = p x e of a point p of small integers not
    on the origin's line, so that the handout's p* = e x n and d = ||n|| hold as printed."""
    from ._random import small_vector, unit_vector

    while True:
        e = unit_vector(rng)
        n = small_vector(rng).cross(e)
        if not is_zero(n):
            return {"plucker": [*e, *n]}
