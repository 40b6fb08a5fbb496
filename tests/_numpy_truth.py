"""NumPy helpers of the blind trials' truths (``tests/blind_trial_*_truth.py``): the
cross-product matrix, random unit vectors, rotations and angles, the matrix exponential, the
elementary rotations, Hamilton's product, a residual and the rule that turns residuals into a
truth. Standard NumPy only; never imports rigidsym (the truths are the independent judge)."""

from __future__ import annotations

import numpy as np

#: a statement holds where its residual stays under this at every random point
TOLERANCE = 1e-6


def sk(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def vee(m):
    return np.array([m[2, 1], m[0, 2], m[1, 0]])


def unit(rng, n=3):
    v = rng.normal(size=n)
    return v / np.linalg.norm(v)


def rot(rng):
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return q * np.sign(np.linalg.det(q))


def angle(rng):
    return rng.uniform(-np.pi, np.pi)


def expm(a, terms=60):
    """The matrix exponential by scaling and squaring a Taylor series."""
    a = np.asarray(a, dtype=float)
    s = max(0, int(np.ceil(np.log2(max(np.linalg.norm(a), 1e-300)))) + 1)
    b = a / 2**s
    out, term = np.eye(len(a)), np.eye(len(a))
    for k in range(1, terms):
        term = term @ b / k
        out = out + term
    for _ in range(s):
        out = out @ out
    return out


def res(a, b):
    return float(np.max(np.abs(np.asarray(a, dtype=float) - np.asarray(b, dtype=float))))


def rodrigues(n, th):
    return np.eye(3) + np.sin(th) * sk(n) + (1 - np.cos(th)) * sk(n) @ sk(n)


def ddt(f, x, xdot, h=1e-6):
    """d/dt f(x(t)) by central differences along xdot."""
    x, xdot = np.asarray(x, dtype=float), np.asarray(xdot, dtype=float)
    return (f(x + h * xdot) - f(x - h * xdot)) / (2 * h)


# active elementary rotations
def ax(x):
    c, s = np.cos(x), np.sin(x)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def ay(x):
    c, s = np.cos(x), np.sin(x)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def az(x):
    c, s = np.cos(x), np.sin(x)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


# passive: the transposes
def px(x):
    return ax(x).T


def py(x):
    return ay(x).T


def pz(x):
    return az(x).T


def ham(p, q):
    """Hamilton's product, scalar first."""
    p0, pv, q0, qv = p[0], p[1:], q[0], q[1:]
    return np.concatenate([[p0 * q0 - pv @ qv], p0 * qv + q0 * pv + np.cross(pv, qv)])


def holds_in(truths: dict, name: str, points: int = 6, seed: int = 2024) -> bool:
    """Whether the truth ``truths[name]`` (a function of a random generator returning a
    residual) stays under :data:`TOLERANCE` at ``points`` random points (a slip misses it at
    every generic point)."""
    rng = np.random.default_rng(seed)
    f = truths[name]
    return max(f(rng) for _ in range(points)) < TOLERANCE
