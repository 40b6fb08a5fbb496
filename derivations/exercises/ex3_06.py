"""Exercise 3.6: grasping a truncated cube; rotation of the gripper and its screw axis."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.worked import Solution, exact_check

from ._screw import screw_of_displacement

ID = "ex3.6"


def solve() -> Solution:
    """Worked solution of Exercise 3.6."""
    d_faces = sp.Matrix([1, 1, 1])          # normal of the triangular faces DEF, D'E'F'
    CCp = sp.Matrix([-1, 1, 1])             # diagonal C -> C'
    Cp = sp.Matrix([0, 1, 1])
    p = sp.Matrix([2, -1, sp.Rational(1, 4)])
    s = Solution(
        ID, "Gripper grasping a truncated cube",
        "\"Compute the angle of rotation of the motion undergone by G ... and find the unit "
        "vector parallel to the axis of rotation ... Determine the set of points of G "
        "undergoing a displacement of minimum magnitude\"",
        "Angeles, Sec. 3.9, Exercise 3.6",
        given={"face normal": d_faces, "diagonal CC'": CCp, "C'": Cp, "[p]_F": p},
        assumptions=["Fig. 3.11 is not in the text we have. Assumed: unit cube [0, 1]^3 in F; "
                     "the removed vertices are O and (1, 1, 1), so the faces DEF, D'E'F' are "
                     "normal to [1, 1, 1]; C = (1, 0, 0), C' = (0, 1, 1).",
                     "Grasp: X'' normal to the finger planes (= faces), i'' with positive "
                     "components; j'' normal to i'' and to CC' with positive Z component; "
                     "k'' = i'' x j''. The method applies to any other reading of the figure."])
    i2 = s.step("i''", d_faces / d_faces.norm(), "Normal to the faces, all components positive.")
    j = i2.cross(CCp)
    j2 = j / j.norm()
    if j2[2] < 0:
        j2 = -j2
    j2 = s.step("j''", j2, "Normal to i'' and to CC', Z component positive.")
    k2 = s.step("k''", i2.cross(j2).applyfunc(sp.radsimp), "Right-handed frame.")
    Q = s.step("rotation", sp.Matrix.hstack(i2, j2, k2),
               "F' starts parallel to F, so Q's columns are i'', j'', k'' in F.")
    phi, e, p0, pl = screw_of_displacement(Q, p, Cp)
    s.step("(a) angle", phi, "cos(phi) = (tr Q - 1)/2.")
    s.step("(a) axis", e, "e = vect(Q)/sin(phi).")
    s.step("(b) point of the screw axis", p0,
           "P goes to C': a = p, a' = C' in Eq. (3.18); the minimum-displacement points are "
           "the screw axis {p0 + lambda e}.")
    s.answers = {"Q": Q, "phi": phi, "e": e, "axis_point_p0": p0, "axis_plucker": pl}
    c = Cp - Q * p
    s.check(exact_check("Q proper orthogonal; j'' normal to CC' and to i''",
                        [Q.T * Q - sp.eye(3), Q.det() - 1, j2.dot(CCp), i2.dot(j2)]))
    s.check(exact_check("Q e = e, e.e = 1; cos(phi) matches tr Q",
                        [Q * e - e, e.dot(e) - 1, 1 + 2 * sp.cos(phi) - Q.trace()]))
    s.check(exact_check("axis points move along e by the minimum |e.c|",
                        [((Q - sp.eye(3)) * x + c).cross(e) for x in (p0, p0 + e)]))
    return s
