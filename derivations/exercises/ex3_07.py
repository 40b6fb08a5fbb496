"""Exercise 3.7: Plücker coordinates of an axis from its moments about two points."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Param, Solution, exact_check, is_zero, truth_check

ID = "ex3.7"
TITLE = "Calibrating an axis from two moment measurements"
STATEMENT = ("\"the moment of this axis is measured with respect to two points, A and B ... "
             "Determine the unit vector e ... the point P* ... the Plücker coordinates of the "
             "axis about the origin\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.7"
#: the documented unit of each answer with one (graded answers may be written in any
#: compatible unit); the others are pure numbers or mixed
ANSWER_UNITS = {"p_star": "m", "p_star_2": "m"}
FIGURE_NAME = "axis"
#: the moments may be measurements (decimals, or floats): the line is then the nearest
#: one to them (least squares), and the misfit of the moments about A and B (in m)
#: printed and judged within tol
MEASURED = True
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
          n_B=PARAMETERS[3].default, tol=None) -> Solution:
    """Worked solution of Exercise 3.7 (positions and moments in metres; ``tol``, in m:
    measured data, whose moments need fit one line only within tol)."""
    a, b, nA, nB = (sp.Matrix(v) for v in (a, b, n_A, n_B))
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"a": a, "b": b, "n_A": nA, "n_B": nB},
        assumptions=["The moment of the line about a point X is n_X = (p - x) x e for any p "
                     "on the line (Sec. 3.3); the sign of e is fixed by n_A - n_B = (b - a) x e."])
    u = s.step("direction", nA.cross(nB),
               "Both moments are normal to e (n_X.e = 0), so e is parallel to n_A x n_B.")
    if tol is not None and not is_zero(u):
        return _measured(s, a, b, nA, nB, u, tol)
    if is_zero(u):
        lines = _parallel_moments(s, a, b, nA, nB)
    else:
        e0 = (u / u.norm()).applyfunc(sp.radsimp)
        rel = s.step("transfer", ((b - a).cross(e0) - (nA - nB)).applyfunc(sp.radsimp),
                     "n_A - n_B = (b - a) x e fixes the sense of e (zero for e = +u/||u||).")
        if is_zero(rel):
            e = e0
        elif is_zero((b - a).cross(-e0) - (nA - nB)):
            e = -e0
        else:
            s.fail("The moments are not those of one line: n_A - n_B must equal (b - a) x e "
                   "for a unit e normal to both, and it does not for either sense of e.")
        lines = [e]
    answers = {}
    for k, e in enumerate(lines):
        tag = "" if k == 0 else "_2"
        which = "" if len(lines) == 1 else f" (line {k + 1})"
        n0 = s.step(f"moment about O{which}", nA + a.cross(e),
                    "n_O = n_A + a x e (moment transfer).")
        ps = s.step(f"closest point{which}", e.cross(n0), "p* = e x n_O (Exercise 3.5).")
        pl = s.step(f"Plücker coordinates about O{which}", sp.Matrix.vstack(e, n0), "[e; n_O].")
        answers.update({f"e{tag}": e, f"p_star{tag}": ps, f"plucker_O{tag}": pl})
        _checks(s, a, b, nA, nB, e, n0, ps, which)
    s.answers = answers
    return s


def _measured(s: Solution, a, b, nA, nB, u, tol) -> Solution:
    """Measured moments: the line nearest them in the least-squares sense (e on the unit
    sphere and n_O normal to it minimising ||n_O - a x e - n_A||^2 + ||n_O - b x e -
    n_B||^2, from e along n_A x n_B, by Gauss-Newton in floating point); e then made a
    rational unit vector (within 1e-9) and n_O the exact minimiser for that e, so all
    that follows is exact; the misfit, the 2-norm of the 6 moment residuals (m), judged
    within ``tol`` exactly and printed as ``residual``."""
    import numpy as np

    from ._fit import accepting_tol, exact_unit_vector

    m = nA - nB
    e0 = exact_unit_vector(np.array([float(x) for x in u]))
    e0 = e0 if bool(((b - a).cross(e0)).dot(m) >= 0) else -e0
    e = exact_unit_vector(_fitted_direction(*(np.array([float(x) for x in v]).ravel()
                                              for v in (a, b, nA, nB, e0))))
    s.step("measured: e", e,
           "The direction of the line nearest the measured moments (least squares, from "
           "the direction of n_A x n_B in the sense for which (b - a) x e points along "
           "n_A - n_B), as a rational unit vector (within 1e-9, exactly of norm 1).")
    c = (nA + a.cross(e) + nB + b.cross(e)) / 2
    n0 = s.step("moment about O", (c - c.dot(e) * e).applyfunc(sp.radsimp),
                "n_O = the mean of n_A + a x e and n_B + b x e (moment transfer), its part "
                "along e removed: the least-squares moment for this e.")
    ps = s.step("closest point", e.cross(n0), "p* = e x n_O (Exercise 3.5).")
    pl = s.step("Plücker coordinates about O", sp.Matrix.vstack(e, n0), "[e; n_O].")
    misfits = [((ps - x).cross(e) - nx) for x, nx in ((a, nA), (b, nB))]
    sq = sp.radsimp(sum(v.dot(v) for v in misfits))         # rational: decided exactly
    if bool(sq > tol**2):
        s.fail(f"The moments are not those of one line within tol = {float(tol):.3g} m: "
               f"the nearest line's moments miss the measured ones by "
               f"{float(sp.N(sp.sqrt(sq))):.3g} m{accepting_tol(sp.N(sp.sqrt(sq), 30))}.")
    s.answers = {"e": e, "p_star": ps, "plucker_O": pl, "residual": sp.sqrt(sq)}
    s.check(exact_check("Plücker constraints: e.e = 1, e.n_O = 0; p*.e = 0",
                        [e.dot(e) - 1, e.dot(n0), ps.dot(e)]))
    s.check(truth_check(f"the moments about A and B are reproduced within tol = "
                        f"{float(tol):.3g} m (misfit {float(sp.N(sp.sqrt(sq))):.3g} m)",
                        bool(sq <= tol**2), "exact comparison of squares of rationals"))
    return s


def _fitted_direction(a, b, nA, nB, e0, steps: int = 12):
    """The unit e minimising the moments' squared misfit (n_O the least-squares moment
    for each e), by Gauss-Newton on the sphere from ``e0`` (floats; a numerical
    Jacobian): the start, the measurements' noise away, converges in a few steps."""
    import numpy as np

    def residual(e):
        e = e / np.linalg.norm(e)
        c = (nA + np.cross(a, e) + nB + np.cross(b, e)) / 2
        n0 = c - (c @ e) * e
        return np.concatenate([n0 - np.cross(a, e) - nA, n0 - np.cross(b, e) - nB])

    e = e0 / np.linalg.norm(e0)
    for _ in range(steps):
        t1 = np.cross(e, [1.0, 0, 0] if abs(e[0]) < 0.9 else [0, 1.0, 0])
        t1 /= np.linalg.norm(t1)
        t2 = np.cross(e, t1)
        r, h = residual(e), 1e-7
        J = np.column_stack([(residual(e + h * t) - residual(e - h * t)) / (2 * h)
                             for t in (t1, t2)])
        step = np.linalg.lstsq(J, -r, rcond=None)[0]
        e = e + step[0] * t1 + step[1] * t2
        e /= np.linalg.norm(e)
        if np.linalg.norm(step) < 1e-13:
            break
    return e


def _parallel_moments(s: Solution, a, b, nA, nB) -> list:
    """The directions e when n_A x n_B = 0: from (b - a) x e = n_A - n_B, |e| = 1 and
    n_A.e = 0 (n_B.e = 0 follows). ``e = e_perp + t d/|d|`` with ``e_perp = m x d/|d|^2``;
    one or two directions, or :meth:`Solution.fail` when none or infinitely many."""
    d, m = b - a, nA - nB
    if is_zero(d):
        if is_zero(m):
            s.fail("A and B coincide and n_A = n_B, so the data give one moment only: every "
                   "line with a unit e normal to n_A, through p = a + e x n_A, fits "
                   "(infinitely many, a circle of directions).")
        s.fail("A and B coincide but n_A != n_B, so no line has these moments.")
    if not is_zero(m.dot(d)):
        s.fail("The moments are not those of one line: n_A - n_B = (b - a) x e must be "
               "normal to b - a, and it is not.")
    dd = d.dot(d)
    ep = s.step("parallel moments: e normal to b - a",
                (m.cross(d) / dd).applyfunc(sp.radsimp),
                "n_A x n_B = 0 leaves e free in the plane normal to n_A; (b - a) x e = "
                "n_A - n_B fixes its part normal to b - a: e_perp = (n_A - n_B) x (b - a) / "
                "|b - a|^2, and e = e_perp + t (b - a)/|b - a|.")
    rest = sp.radsimp(1 - ep.dot(ep))
    if is_zero(rest):
        rest = sp.Integer(0)
    elif rest < 0:
        s.fail("The moments are not those of one line: |n_A - n_B| > |b - a|, so no unit "
               "e has (b - a) x e = n_A - n_B.")
    dn = d / sp.sqrt(dd)
    c, c0 = sp.radsimp(nA.dot(dn)), sp.radsimp(nA.dot(ep))
    roots = {sp.radsimp(sp.sqrt(rest)), sp.radsimp(-sp.sqrt(rest))}
    ts = sorted((t for t in roots if is_zero(c0 + t * c)), key=lambda t: -t)
    if not ts:
        s.fail("The moments are not those of one line: no unit e with (b - a) x e = n_A - "
               "n_B is normal to n_A.")
    lines = [(ep + t * dn).applyfunc(sp.radsimp) for t in ts]
    s.step("parallel moments: the directions", sp.Matrix.hstack(*lines),
           "t = +-sqrt(1 - |e_perp|^2), kept where n_A.e = 0: "
           + ("one line (e normal to b - a, or t fixed by n_A)." if len(lines) == 1 else
              "the line AB in either sense (zero moments do not fix the sense of e); both "
              "are answers (e_2, p_star_2, plucker_O_2)." if is_zero(nA) else
              "two lines, mirror images of each other in the plane through A and B that "
              "contains n_A; both are answers (e_2, p_star_2, plucker_O_2)."))
    return lines


def _checks(s: Solution, a, b, nA, nB, e, n0, ps, which: str) -> None:
    """The checks of one line: the data reproduced, the Plücker constraints."""
    s.check(exact_check(f"(p* - a) x e = n_A and (p* - b) x e = n_B{which}",
                        [(ps - a).cross(e) - nA, (ps - b).cross(e) - nB]))
    s.check(exact_check(f"Plücker constraints: e.e = 1, e.n_O = 0; p*.e = 0{which}",
                        [e.dot(e) - 1, e.dot(n0), ps.dot(e)]))
    s.check(truth_check(f"both measured moments are normal to e{which}",
                        is_zero(nA.dot(e)) and is_zero(nB.dot(e)), "exact (minimal polynomial)"))

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
