"""Random points of each kind a ``--let`` declares (the numeric check's own sampler):
unit vectors, rotations (from a uniform unit quaternion), angles, transforms,
twists, ... as mpmath values, drawn from :class:`random.Random` at the working precision."""

from __future__ import annotations

import random
import re

import mpmath as mp

from rigidsym.numeval.values import NotCovered, hat

__all__ = ["sample", "kind_words"]


def kind_words(text: str) -> str:
    """A KIND as written, normalised (``4×4 Matrix`` -> ``4x4 matrix``)."""
    t = text.lower().replace("×", "x").replace("π", "pi").replace("\\pi", "pi")
    t = " ".join(t.split())
    t = re.sub(r"\[\s*0\s*,\s*pi\s*\]", "[0, pi]", t)
    return t.replace("angle on [0, pi]", "angle in [0, pi]")


def _real(rng: random.Random, lo: float | None = None, hi: float | None = None):
    if lo is None:  # an unconstrained real: in (-2, 2), or wider where the rng says so
        spread = getattr(rng, "spread", 1)
        lo, hi = -2.0 * spread, 2.0 * spread
    # 64 random bits past the float: a point of the working precision, not of a double's
    return mp.mpf(lo) + (mp.mpf(hi) - mp.mpf(lo)) * mp.mpf(rng.getrandbits(120)) / mp.mpf(2) ** 120


def _vector(rng, n: int):
    return mp.matrix([_real(rng) for _ in range(n)])


def _unit(rng, n: int):
    while True:
        v = _vector(rng, n)
        r = mp.norm(v)
        if r > mp.mpf("0.1"):
            return v / r


def rotation(rng):
    """A rotation matrix from a random unit quaternion (Shoemake)."""
    q = _unit(rng, 4)
    w, x, y, z = q[0], q[1], q[2], q[3]
    return mp.matrix([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                      [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                      [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def _transform(rng):
    R, p = rotation(rng), _vector(rng, 3)
    T = mp.eye(4)
    for i in range(3):
        for j in range(3):
            T[i, j] = R[i, j]
        T[i, 3] = p[i]
    return T


def _spatial(rng):
    # Featherstone's X = [E 0; -E r×, E]
    E, r = rotation(rng), _vector(rng, 3)
    low = -(E * hat(r))
    X = mp.zeros(6, 6)
    for i in range(3):
        for j in range(3):
            X[i, j] = X[i + 3, j + 3] = E[i, j]
            X[i + 3, j] = low[i, j]
    return X


def sample(kind: str, rng: random.Random):
    """A random value of ``kind`` (a ``--let`` KIND, normalised by :func:`kind_words`).

    Raises:
        NotCovered: a kind this sampler has no points of."""
    t = kind_words(kind)
    fixed = {
        "unit vector": lambda: _unit(rng, 3), "unit 3-vector": lambda: _unit(rng, 3),
        "unit 4-vector": lambda: _unit(rng, 4),
        "rotation": lambda: rotation(rng), "rotation matrix": lambda: rotation(rng),
        "angle": lambda: _real(rng, -3.1, 3.1), "angle in [0, pi]": lambda: _real(rng, 0.05, 3.1),
        "scalar": lambda: _real(rng), "vector": lambda: _vector(rng, 3),
        "matrix": lambda: mp.matrix([[_real(rng) for _ in range(3)] for _ in range(3)]),
        "symmetric matrix": lambda: _symmetric(rng),
        "twist": lambda: _vector(rng, 6), "wrench": lambda: _vector(rng, 6),
        "transform": lambda: _transform(rng), "spatial transform": lambda: _spatial(rng),
        "so(3)": lambda: hat(_vector(rng, 3)), "se(3)": lambda: hat(_vector(rng, 6)),
    }
    if t in fixed:
        return fixed[t]()
    m = re.fullmatch(r"(\d+)-vector", t)
    if m and int(m.group(1)) >= 1:
        return _vector(rng, int(m.group(1)))
    m = re.fullmatch(r"(\d+) ?x ?(\d+) matrix", t)
    if m and int(m.group(1)) >= 1 and int(m.group(2)) >= 1:
        return mp.matrix([[_real(rng) for _ in range(int(m.group(2)))]
                          for _ in range(int(m.group(1)))])
    raise NotCovered(f"the kind {kind!r}")


def _symmetric(rng):
    A = mp.matrix([[_real(rng) for _ in range(3)] for _ in range(3)])
    return (A + A.T) / 2
