"""Exercises 3.11 and 3.12 by polyhedra: the hexagonal prism (and its parts cut by the
plane z = y + a sqrt(3)/2) as convex polyhedra, their volume, centroid and inertia summed
over tetrahedra of a triangulated hull. Never imports rigidsym."""

from __future__ import annotations

import numpy as np
from scipy.spatial import ConvexHull


def hexagon(a):
    s = a * np.sqrt(3) / 2
    return np.array([(a, 0), (a / 2, s), (-a / 2, s), (-a, 0), (-a / 2, -s), (a / 2, -s)])


def prism_points(a, h):
    hx = hexagon(a)
    return np.array([(x, y, z) for z in (0.0, h) for x, y in hx])


def clip(points, n, c):
    """The vertices of the convex hull of ``points`` cut to ``n.x <= c``."""
    hull = ConvexHull(points)
    pts = [p for p in points if n @ p <= c]
    for simplex in hull.simplices:                     # every hull edge crossing the plane
        for i in range(3):
            p, q = points[simplex[i]], points[simplex[(i + 1) % 3]]
            fp, fq = n @ p - c, n @ q - c
            if fp * fq < 0:
                pts.append(p + (q - p) * fp / (fp - fq))
    return np.unique(np.round(np.array(pts), 15), axis=0)


def mass_properties(points):
    """Volume, centroid and centroidal inertia per unit density of the convex hull."""
    hull = ConvexHull(points)
    o = points.mean(axis=0)
    V, first, C = 0.0, np.zeros(3), np.zeros((3, 3))
    for simplex in hull.simplices:
        v = [points[k] - o for k in simplex]
        vol = abs(np.linalg.det(np.array(v))) / 6
        V += vol
        first += vol * (sum(v) / 4)
        s = sum(v)
        C += vol / 20 * (sum(np.outer(w, w) for w in v) + np.outer(s, s))
    c_rel = first / V
    C_c = C - V * np.outer(c_rel, c_rel)                # second moments about the centroid
    I_C = np.trace(C_c) * np.eye(3) - C_c
    return V, o + c_rel, I_C


def prism(a, h):
    return mass_properties(prism_points(a, h))


def cut_parts(a, h):
    """(lower, upper): the mass properties of the parts below and above z = y + s."""
    s = a * np.sqrt(3) / 2
    P = prism_points(a, h)
    n = np.array([0.0, -1.0, 1.0])
    lower = mass_properties(clip(P, n, s))
    upper_pts = clip(P, -n, -s)
    upper = mass_properties(upper_pts) if len(upper_pts) >= 4 else None
    return lower, upper
