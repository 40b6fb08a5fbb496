"""Exercise 3.6: grasping a truncated cube; rotation of the gripper and its screw axis."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Param, Solution, exact_check, is_zero, values_only

from ._fit import exact_rotation
from ._screw import screw_of_displacement

ID = "ex3.6"
TITLE = "Gripper grasping a truncated cube"
STATEMENT = ("\"Compute the angle of rotation of the motion undergone by G ... and find the "
             "unit vector parallel to the axis of rotation ... Determine the set of points of "
             "G undergoing a displacement of minimum magnitude\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.6"
#: the documented unit of each answer with one (graded answers may be written in any
#: compatible unit); the others are pure numbers or mixed
ANSWER_UNITS = {"phi": "rad", "axis_point_p0": "m"}
#: what the answers are: the axis and angle of Q with the axis's Plücker array, one sign
#: for all three, phi + 2 pi k; "a point p_0 of the axis": any point of it
ANSWER_CLASSES = (
    {"kind": "axis-angle", "axis": "e", "angle": "phi", "linked": ("axis_plucker",)},
    {"kind": "point of line", "point": "axis_point_p0", "direction": "e"},
)
FIGURE_NAME = "grasp"
#: the solver runs on floating data for a slip's replay (rigidsym.course.worked.solve_values):
#: its decisions are is_zero's (a sign tested after is_zero says it is not 0)
VALUES_REPLAY = True
#: the two directions may be measurements (decimals, or floats): the grasp frame is then
#: built in floating point, rounded to an exact rotation (its residual printed), and a
#: degeneracy (a sign, a parallel pair) is judged within tol; C' and p stay exact
MEASURED = True
READINGS = ("face_normal", "CC_prime")
_V = sp.ImmutableMatrix
PARAMETERS = (
    Param("face_normal", _V([1, 1, 1]), (3,), "normal of the triangular faces DEF, D'E'F' "
          "(the finger planes), in F", ""),
    Param("CC_prime", _V([-1, 1, 1]), (3,), "the diagonal from C to C' of the workpiece", "m"),
    Param("C_prime", _V([0, 1, 1]), (3,), "vertex C', where P is carried", "m"),
    Param("p", _V([2, -1, sp.Rational(1, 4)]), (3,), "point P of the gripper in the "
          "reference pose, in F", "m"),
)
VARIANTS = (
    ("P at the origin of F", {"p": [0, 0, 0]}),
    ("a diagonal normal to the faces (ill-posed)", {"CC_prime": [1, 1, 1]}),
)


def solve(face_normal=PARAMETERS[0].default, CC_prime=PARAMETERS[1].default,
          C_prime=PARAMETERS[2].default, p=PARAMETERS[3].default, tol=None) -> Solution:
    """Worked solution of Exercise 3.6 (vectors in F, lengths in metres; ``tol``: the face
    normal and CC' are measured directions, the grasp frame rounded to an exact rotation)."""
    d_faces, CCp, Cp, p = (sp.Matrix(v) for v in (face_normal, CC_prime, C_prime, p))
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"face normal": d_faces, "diagonal CC'": CCp, "C'": Cp, "[p]_F": p},
        assumptions=["The data of Fig. 3.11 of the book, as read here: unit cube [0, 1]^3 in F; "
                     "the removed vertices are O and (1, 1, 1), so the faces DEF, D'E'F' are "
                     "normal to [1, 1, 1]; C = (1, 0, 0), C' = (0, 1, 1).",
                     "Grasp: X'' normal to the finger planes (= faces), i'' with positive "
                     "components; j'' normal to i'' and to CC' with positive Z component; "
                     "k'' = i'' x j''. The method applies to any other reading of the figure."])
    if tol is None:
        Q, checks, res = *_grasp_frame(s, d_faces, CCp), None
    else:
        Q, checks, res = _measured_frame(s, d_faces, CCp, tol)
    screw = screw_of_displacement(Q, p, Cp)
    if screw is None:
        s.fail("The gripper does not turn (Q = 1): the motion is a translation and no screw "
               "axis is singled out.")
    phi, e, p0, pl = screw
    s.step("(a) angle", phi, "cos(phi) = (tr Q - 1)/2.")
    s.step("(a) axis", e, "e = vect(Q)/sin(phi).")
    s.step("(b) point of the screw axis", p0,
           "P goes to C': a = p, a' = C' in Eq. (3.18); the minimum-displacement points are "
           "the screw axis {p0 + lambda e}.")
    s.answers = {"Q": Q, "phi": phi, "e": e, "axis_point_p0": p0, "axis_plucker": pl}
    if res is not None:
        s.answers["residual"] = res
    if values_only():
        return s                # a replay for its values: no check (its exact solve checks)
    c = Cp - Q * p
    s.check(checks)
    s.check(exact_check("Q e = e, e.e = 1; cos(phi) matches tr Q",
                        [Q * e - e, e.dot(e) - 1, 1 + 2 * sp.cos(phi) - Q.trace()]))
    s.check(exact_check("axis points move along e by the minimum |e.c|",
                        [((Q - sp.eye(3)) * x + c).cross(e) for x in (p0, p0 + e)]))
    return s


def _radsimp(v):
    """``sympy.radsimp(v)``; ``v`` itself in a replay for its values only (floats)."""
    return v if values_only() else sp.radsimp(v)


def _grasp_frame(s: Solution, d_faces, CCp):
    """The grasp frame [i'', j'', k''] from exact directions, and its exact check (None in a
    replay for its values only)."""
    signs = {sp.sign(x) for x in d_faces}
    if signs not in ({1}, {-1}):
        s.fail("The face normal has a zero component or components of both signs, so no "
               "normal i'' has all three components positive, as the grasp requires.")
    i2 = s.step("i''", (d_faces / d_faces.norm() * signs.pop()).applyfunc(_radsimp),
                "Normal to the faces, all components positive.")
    j = i2.cross(CCp)
    if is_zero(j):
        s.fail("The diagonal CC' is normal to the faces (parallel to i''), so j'', normal "
               "to both, is not fixed.")
    j2 = (j / j.norm()).applyfunc(_radsimp)
    if is_zero(j2[2]):
        s.fail("j'' has a zero Z component, so the grasp's rule (Z component positive) does "
               "not fix its sense.")
    if j2[2] < 0:
        j2 = -j2
    j2 = s.step("j''", j2, "Normal to i'' and to CC', Z component positive.")
    k2 = s.step("k''", i2.cross(j2).applyfunc(_radsimp), "Right-handed frame.")
    Q = s.step("rotation", sp.Matrix.hstack(i2, j2, k2),
               "F' starts parallel to F, so Q's columns are i'', j'', k'' in F.")
    if values_only():
        return Q, None
    return Q, exact_check("Q proper orthogonal; j'' normal to CC' and to i''",
                          [Q.T * Q - sp.eye(3), Q.det() - 1, j2.dot(CCp), i2.dot(j2)])


def _measured_frame(s: Solution, d_faces, CCp, tol):
    """The grasp frame from measured directions: built in floating point (30 digits),
    rounded to an exactly proper-orthogonal rational matrix (Cayley transform), its
    distance to the float frame printed as the residual; a sign or a parallel pair that
    the readings decide only within ``tol`` (per coordinate) is refused."""
    import numpy as np

    from rigidsym.course.worked import truth_check

    small = [x for x in d_faces if bool(abs(x) <= tol)]
    signs = {sp.sign(x) for x in d_faces}
    if small or signs not in ({1}, {-1}):
        s.fail(f"The face normal has a component within tol = {float(tol):.3g} of zero or "
               f"components of both signs, so the readings do not give a normal i'' with all "
               f"three components positive, as the grasp requires.")
    d = np.array(sp.N(d_faces, 30).tolist(), dtype=float).ravel() * float(signs.pop())
    c = np.array(sp.N(CCp, 30).tolist(), dtype=float).ravel()
    i2 = d / np.linalg.norm(d)
    j = np.cross(i2, c)
    if np.linalg.norm(j) <= 2 * float(tol):
        s.fail(f"The diagonal CC' is parallel to the face normal within tol = {float(tol):.3g} "
               f"(|i'' x CC'| = {np.linalg.norm(j):.3g}), so the readings do not fix j'', "
               f"normal to both.")
    if abs(j[2]) <= 2 * float(tol):
        s.fail(f"j'' has a Z component within tol = {float(tol):.3g} of zero, so the readings "
               f"do not decide its sense (the grasp's rule: Z component positive).")
    j2 = j / np.linalg.norm(j) * np.sign(j[2])
    F = np.column_stack([i2, j2, np.cross(i2, j2)])
    Q = s.step("rotation (measured directions)", exact_rotation(F),
               "i'' = normal/|normal|, j'' = i'' x CC' normalised (Z component positive), "
               "k'' = i'' x j'' in floating point, rounded to an exactly orthogonal rational "
               "matrix by the Cayley transform.")
    res = float(np.linalg.norm(np.array(sp.N(Q, 30).tolist(), dtype=float) - F))
    shown = s.step("residual", sp.Float(res, 4), "||Q - [i'', j'', k'']||_F, the rounding of "
                   "the measured frame to an exact rotation, to 4 digits.")
    return Q, truth_check(f"Q proper orthogonal (exact rationals), within tol = "
                          f"{float(tol):.3g} of the frame of the readings",
                          Q.T * Q == sp.eye(3) and Q.det() == 1 and res <= float(tol),
                          "exact rationals; residual in floating point"), shown


def figure(s: Solution):
    """The truncated unit cube, the grasp frame F'' at C', P before and after, and the
    screw axis (the points of G with a displacement of minimum magnitude)."""
    import itertools

    from ._draw import axes3d, frame, line_in_box, new_figure, point, segment

    t = sp.Rational(1, 3)   # depth of the corner cuts, for drawing only
    corners = [sp.Matrix(c) for c in itertools.product((0, 1), repeat=3)]
    cut = {(0, 0, 0), (1, 1, 1)}
    fig, ax = new_figure("Exercise 3.6: the grasp of the truncated cube and the screw axis")
    for a, b in itertools.combinations(corners, 2):
        if sum(abs(x - y) for x, y in zip(a, b, strict=True)) != 1:
            continue
        a2 = a + t * (b - a) if tuple(a) in cut else a
        b2 = b + t * (a - b) if tuple(b) in cut else b
        segment(ax, a2, b2, color="0.5")
    for c in cut:
        c = sp.Matrix(c)
        tri = [c + t * (sp.Matrix(n) - c) for n in corners
               if sum(abs(x - y) for x, y in zip(c, n, strict=True)) == 1]
        for a, b in itertools.combinations(tri, 2):
            segment(ax, a, b, color="tab:olive")
    Cp, p = s.given["C'"], s.given["[p]_F"]
    frame(ax, Cp, s.answers["Q"] * sp.Rational(1, 2), "G''", "tab:purple")
    point(ax, p, "tab:blue", "P (reference pose)", "P")
    point(ax, Cp, "tab:purple", "P after the grasp (= C')", "C'")
    pts = corners + [p, Cp, s.answers["axis_point_p0"]]
    line_in_box(ax, s.answers["axis_point_p0"], s.answers["e"], pts, "tab:red", "screw axis")
    axes3d(ax, pts)
    return fig


def given_figure(s: Solution):
    """The given data only (the students' handout): the unit cube in F, the finger
    planes' normal at the cube's centre, the diagonal from C to C', and the gripper
    point P; no grasp frame, no rotation, no axis."""
    import itertools

    from ._draw import arrow, axes3d, new_figure, point, segment

    n, d = sp.Matrix(s.data["face_normal"]), sp.Matrix(s.data["CC_prime"])
    Cp, p = sp.Matrix(s.data["C_prime"]), sp.Matrix(s.data["p"])
    C = Cp - d
    fig, ax = new_figure("The workpiece in F: the finger planes' normal, C to C', and P")
    corners = [sp.Matrix(c) for c in itertools.product((0, 1), repeat=3)]
    for a, b in itertools.combinations(corners, 2):
        if sum(abs(x - y) for x, y in zip(a, b, strict=True)) == 1:
            segment(ax, a, b, color="0.6")
    centre = sp.Matrix([sp.Rational(1, 2)] * 3)
    arrow(ax, centre, n / n.norm(), "tab:olive", "normal of the finger planes", scale=0.6)
    arrow(ax, C, d, "tab:purple", "diagonal C to C'", dashed=True)
    point(ax, C, "tab:purple", text="C")
    point(ax, Cp, "tab:purple", text="C'")
    point(ax, p, "tab:blue", "P (reference pose)", "P")
    axes3d(ax, corners + [p, C, Cp])
    return fig
