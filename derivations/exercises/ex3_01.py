"""Exercise 3.1: rotation, minimum-displacement line and its plane intersections for a cube."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.worked import Solution, exact_check

from ._screw import screw_of_displacement

ID = "ex3.1"
# Assumed geometry (Fig. 3.9 is not in the text): unit cube, A at O, B on X, D on Y, E on Z.
CUBE = {"A": (0, 0, 0), "B": (1, 0, 0), "C": (1, 1, 0), "D": (0, 1, 0),
        "E": (0, 0, 1), "F": (1, 0, 1), "G": (1, 1, 1), "H": (0, 1, 1)}
Q_ASSUMED = sp.Matrix([[0, 0, 1], [1, 0, 0], [0, 1, 0]])
C_ASSUMED = sp.Matrix([0, 2, 0])


def solve() -> Solution:
    """Worked solution of Exercise 3.1."""
    P = {k: sp.Matrix(v) for k, v in CUBE.items()}
    Pp = {k: Q_ASSUMED * v + C_ASSUMED for k, v in P.items()}
    s = Solution(
        ID, "Screw motion of a cube",
        "\"Determine the matrix representing the rotation Q undergone by the cube ... Find the "
        "Plücker coordinates of line L of the cube undergoing displacements of minimum "
        "magnitude. Find the intersections of L with the coordinate planes.\"",
        "Angeles, Sec. 3.9, Exercise 3.1",
        given={"A, B, D, E": sp.Matrix.hstack(P["A"], P["B"], P["D"], P["E"]),
               "A', B', D', E'": sp.Matrix.hstack(Pp["A"], Pp["B"], Pp["D"], Pp["E"])},
        assumptions=["Fig. 3.9 is not in the text we have. Assumed: unit cube with A = O and "
                     "edges AB, AD, AE along X, Y, Z; displaced vertices A' = (0, 2, 0), "
                     "B' = (0, 3, 0), D' = (0, 2, 1), E' = (1, 2, 0) (a 120 deg turn about "
                     "[1, 1, 1] and a shift). The method holds for any data: Q = [B'-A', "
                     "D'-A', E'-A'][B-A, D-A, E-A]^-1."])
    Q = s.step("rotation", sp.Matrix.hstack(Pp["B"] - Pp["A"], Pp["D"] - Pp["A"],
                                            Pp["E"] - Pp["A"])
               * sp.Matrix.hstack(P["B"] - P["A"], P["D"] - P["A"], P["E"] - P["A"]).inv(),
               "Edge vectors rotate: [b'-a', d'-a', e'-a'] = Q [b-a, d-a, e-a].")
    phi, e, p0, pl = screw_of_displacement(Q, P["A"], Pp["A"])
    s.step("angle", phi, "cos(phi) = (tr Q - 1)/2.")
    s.step("axis", e, "e = vect(Q)/sin(phi).")
    s.step("point of L closest to O", p0,
           "Eq. (3.18): p0 = (Q - 1)^T (Q a - a') / (2(1 - cos phi)).")
    s.step("Plücker coordinates", pl, "[e; p0 x e].")
    hits = []
    for i, name in enumerate("XYZ"):
        if e[i] != 0:
            lam = -p0[i] / e[i]
            hits.append((name, (p0 + lam * e).applyfunc(sp.radsimp)))
    s.step("plane intersections", sp.Matrix.hstack(*[h for _, h in hits]),
           "p0 + lambda e with the i-th coordinate zero (planes x = 0, y = 0, z = 0).")
    s.answers = {"Q": Q, "phi": phi, "e": e, "plucker": pl}
    planes = {"X": "x=0", "Y": "y=0", "Z": "z=0"}
    for name, h in hits:
        s.answers[f"intersection_{planes[name]}"] = h
    c = Pp["A"] - Q * P["A"]
    s.check(exact_check("Q proper orthogonal, maps every edge of the cube",
                        [Q.T * Q - sp.eye(3), Q.det() - 1]
                        + [Q * (P[k] - P["A"]) - (Pp[k] - Pp["A"]) for k in P]))
    s.check(exact_check("Plücker constraints e.e = 1, e.n = 0; points of L move along e with "
                        "the minimum magnitude |e.c|",
                        [pl[:3, :].dot(pl[:3, :]) - 1, pl[:3, :].dot(pl[3:, :])]
                        + [((Q - sp.eye(3)) * x + c).cross(e) for x in (p0, p0 + e)]
                        + [((Q - sp.eye(3)) * p0 + c).dot((Q - sp.eye(3)) * p0 + c)
                           - e.dot(c)**2]))
    s.check(exact_check("intersections lie on L (x x e = n) and on their planes",
                        [h.cross(e) - pl[3:, :] for _, h in hits]
                        + [h["XYZ".index(n)] for n, h in hits]))
    return s
