"""The corpus's own numerical oracle: NumPy values of the books' symbols
at random points, drawn by the kinds of each book's symbol table, and the books' operators
written out from their definitions. Independent of rigidsym's reader: nothing here imports
rigidsym; each entry's ``num`` evaluates both members of its equation by hand."""

from __future__ import annotations

import re

import numpy as np

I3, I4, I6 = np.eye(3), np.eye(4), np.eye(6)
Z3 = np.zeros((3, 3))


def hat(v):
    """so(3) of a 3-vector, se(3) (4x4) of a twist [w; v] (MR (3.30), (3.85))."""
    v = np.asarray(v, float).reshape(-1)
    if v.size == 3:
        return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    m = np.zeros((4, 4))
    m[:3, :3], m[:3, 3] = hat(v[:3]), v[3:]
    return m


def vee(m):
    m = np.asarray(m, float)
    if m.shape == (3, 3):
        return np.array([m[2, 1], m[0, 2], m[1, 0]]).reshape(3, 1)
    return np.vstack([vee(m[:3, :3]), m[:3, 3:4]])


def expm(a):
    """Matrix exponential by scaling and squaring of a Taylor series (no scipy)."""
    a = np.asarray(a, float)
    s = max(0, int(np.ceil(np.log2(max(np.abs(a).sum(axis=1).max(), 1e-300)))) + 1)
    b = a / 2.0 ** s
    term, out = np.eye(len(a)), np.eye(len(a))
    for k in range(1, 30):
        term = term @ b / k
        out = out + term
    for _ in range(s):
        out = out @ out
    return out


def rot(axis, angle):
    """Rodrigues' rotation, written out (MR (3.51))."""
    k = hat(np.asarray(axis, float) / np.linalg.norm(axis))
    return I3 + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def rotz(t):
    return np.array([[np.cos(t), -np.sin(t), 0], [np.sin(t), np.cos(t), 0], [0, 0, 1.0]])


def roty(t):
    return np.array([[np.cos(t), 0, np.sin(t)], [0, 1.0, 0], [-np.sin(t), 0, np.cos(t)]])


def rotx(t):
    return np.array([[1.0, 0, 0], [0, np.cos(t), -np.sin(t)], [0, np.sin(t), np.cos(t)]])


def Ad(T):
    """MR's adjoint of a 4x4 transform, acting on twists [w; v] (MR (3.83))."""
    R, p = T[:3, :3], T[:3, 3]
    out = np.zeros((6, 6))
    out[:3, :3], out[3:, 3:], out[3:, :3] = R, R, hat(p) @ R
    return out


def ad(V):
    """MR's [ad_V] of a twist [w; v] (MR (8.38)); Featherstone's crm for [w; v_O]."""
    V = np.asarray(V, float).reshape(-1)
    out = np.zeros((6, 6))
    out[:3, :3], out[3:, 3:], out[3:, :3] = hat(V[:3]), hat(V[:3]), hat(V[3:])
    return out


crm = ad


def crf(v):
    """Featherstone's v x* (RBDA (2.?)): -crm(v)^T."""
    return -crm(v).T


def plucker(E, r):
    """Featherstone's Plücker motion transform [E 0; -E r x, E] (RBDA (2.24))."""
    out = np.zeros((6, 6))
    out[:3, :3], out[3:, 3:], out[3:, :3] = E, E, -E @ hat(r)
    return out


def transform(R, p):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, np.asarray(p).reshape(-1)
    return T


def cross(a, b):
    """a x b of two 3 x 1 columns, a 3 x 1 column."""
    return np.cross(np.ravel(a), np.ravel(b)).reshape(3, 1)


def col(*xs):
    return np.array(xs, float).reshape(-1, 1)


# ---------------------------------------------------------------- sampling by the kinds
def alias(name: str) -> str:
    """A Python name for a table NAME: ``\\hat\\omega`` -> ``hat_omega``, ``{}^A_B R`` ->
    ``A_B_R``, ``R_{z,\\theta}`` -> ``R_z_theta``, ``R_{Z'Y'X'}`` -> ``R_ZpYpXp``."""
    s = name.replace("(t)", "")
    s = re.sub(r"\\(hat|dot|tilde|bar)\b\s*", r"\1_", s)
    s = re.sub(r"\\(mathbf|boldsymbol|bm|mathcal|mathsf|underline|vec|mathrm)\b", "", s)
    s = s.replace("'", "p").replace("\\", "")
    s = re.sub(r"[^A-Za-z0-9]+", "_", s).strip("_")
    return s


def _rotation(rng):
    return rot(rng.normal(size=3), rng.uniform(-np.pi, np.pi))


def _draw(kind: str, rng):
    k = kind.strip().lower().replace("×", "x")
    if k in ("rotation", "rotation matrix"):
        return _rotation(rng)
    if k == "unit vector":
        v = rng.normal(size=3)
        return (v / np.linalg.norm(v)).reshape(3, 1)
    if k == "unit 4-vector":
        v = rng.normal(size=4)
        return (v / np.linalg.norm(v)).reshape(4, 1)
    if k == "angle":
        return rng.uniform(-np.pi, np.pi)
    if k == "angle in [0, pi]":
        return rng.uniform(0, np.pi)
    if k == "scalar":
        return rng.normal()
    if k == "vector":
        return rng.normal(size=(3, 1))
    if k in ("twist", "wrench"):
        return rng.normal(size=(6, 1))
    if k == "matrix":
        return rng.normal(size=(3, 3))
    if k == "symmetric matrix":
        a = rng.normal(size=(3, 3))
        return a + a.T
    if k == "transform":
        return transform(_rotation(rng), rng.normal(size=3))
    if k == "spatial transform":
        return plucker(_rotation(rng), rng.normal(size=3))
    if k == "so(3)":
        return hat(rng.normal(size=3))
    if k == "se(3)":
        return hat(rng.normal(size=6))
    m = re.fullmatch(r"(\d+)-vector", k)
    if m:
        return rng.normal(size=(int(m.group(1)), 1))
    m = re.fullmatch(r"(\d+) ?x ?(\d+) matrix", k)
    if m:
        return rng.normal(size=(int(m.group(1)), int(m.group(2))))
    raise ValueError(f"no sampler for the kind {kind!r}")


def parse_table(text: str) -> list[tuple[str, str]]:
    """``NAME: KIND`` lines (blank lines and ``#`` comments skipped)."""
    rows = []
    for line in text.strip().splitlines():
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        name, kind = line.rsplit(":", 1)
        rows.append((name.strip(), kind.strip()))
    return rows


class Point:
    """Values of a table's symbols at one random point. A NAME declared ``X(t)`` depends on
    time: a smooth path through a random value, evaluated by :meth:`at`; ``dot_X`` is its
    time derivative at t = 0 (exact for the paths used)."""

    def __init__(self, table: str, rng):
        self._paths = {}
        for name, kind in parse_table(table):
            a = alias(name)
            v0 = _draw(kind, rng)
            if name.endswith("(t)"):
                k = kind.lower()
                if k == "rotation":
                    w = rng.normal(size=3)
                    self._paths[a] = lambda t, v0=v0, w=w: v0 @ expm(hat(w) * t)
                    self.__dict__["dot_" + a] = v0 @ hat(w)
                else:
                    d = rng.normal(size=np.shape(v0)) if np.ndim(v0) else rng.normal()
                    dd = rng.normal(size=np.shape(v0)) if np.ndim(v0) else rng.normal()
                    self._paths[a] = lambda t, v0=v0, d=d, dd=dd: v0 + d * t + dd * t * t
                    self.__dict__["dot_" + a] = d
            self.__dict__[a] = v0

    def at(self, t: float) -> Point:
        """The point with every time-dependent symbol moved to time t."""
        p = object.__new__(Point)
        p.__dict__.update(self.__dict__)
        for a, f in self._paths.items():
            p.__dict__[a] = f(t)
        return p


def ddt(v: Point, f, h: float = 1e-5):
    """d/dt at t = 0 of f(point) by a central difference."""
    return (np.asarray(f(v.at(h)), float) - np.asarray(f(v.at(-h)), float)) / (2 * h)


def residual(pair) -> float:
    """The relative difference of the two members (shapes must agree)."""
    a, b = (np.atleast_2d(np.asarray(x, float)) for x in pair)
    if a.shape != b.shape:
        raise ValueError(f"members of shapes {a.shape} and {b.shape}")
    return float(np.abs(a - b).max() / max(1.0, np.abs(a).max(), np.abs(b).max()))


def E(section: str, number: str, latex: str, holds: bool, num, note: str = "",
      lets: tuple = ()) -> dict:
    """One corpus entry: where it is in the book, its LaTeX as the book prints it, whether
    it holds (False: a slip, a realistic mistyping of a true equation) and ``num``, a
    function of a :class:`Point` returning the two members as NumPy values. ``lets``: the
    ``--let`` models and functions a reader of the book writes, beside the
    table's kinds."""
    return {"section": section, "number": number, "latex": latex, "holds": holds,
            "num": num, "note": note, "lets": list(lets)}
