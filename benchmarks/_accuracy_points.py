"""The regimes of the accuracy harness: exact points (rationals), per kernel.

Constrained inputs are exactly on their manifold through rational parametrisations (the
zero test's, ``rigidsym.zero``): a unit vector by inverse stereographic projection of a
rational point, a rotation by its (unnormalised) Euler-Rodrigues parameters ``(t e, 1)`` or
``(e, tau)`` with ``e`` a rational unit vector, so ``tan(phi/2) = t`` or ``1/tau`` is exact and
``phi`` reaches 0 and pi exactly. Unconstrained inputs are the exact binary values of floats.
The harness rounds each point to the float type under test (what a caller hands a kernel).

A regime is a name and a list of points; a point is one ``list[fmpq]`` per argument.
"""

from __future__ import annotations

import math

import numpy as np
from flint import fmpq

#: log-spaced approaches: 1e-1 ... 1e-15, then toward the smallest useful step: the size
#: whose fourth power (the highest power of a norm in the Jacobian kernels) is still a
#: normal number, 1e-75 in float64; float32 goes to 1e-18 (its square). Below it a power of
#: a norm underflows: the float format itself, not a formula, gives up.
STEPS = [10.0**-k for k in range(1, 16)] + [1e-20, 1e-40, 1e-75]
STEPS32 = [10.0**-k for k in range(1, 16)] + [1e-18]


def q(x: float) -> fmpq:
    return fmpq(*float(x).as_integer_ratio())


def unit(rng, n: int = 3) -> list[fmpq]:
    """A rational unit vector (inverse stereographic projection of a rational point)."""
    u = [q(v) for v in rng.standard_normal(n - 1)]
    s = sum(v * v for v in u)
    vec = [2 * v / (1 + s) for v in u] + [(1 - s) / (1 + s)]
    perm = rng.permutation(n)
    return [vec[i] for i in perm]


def rotation(e: list[fmpq], r: fmpq, r0: fmpq) -> list[fmpq]:
    """Q of the Euler-Rodrigues parameters (r e, r0) (not normalised), row-major, exact."""
    x, y, z = (r * v for v in e)
    n = x * x + y * y + z * z + r0 * r0
    Q = [[r0 * r0 + x * x - y * y - z * z, 2 * (x * y - r0 * z), 2 * (x * z + r0 * y)],
         [2 * (x * y + r0 * z), r0 * r0 - x * x + y * y - z * z, 2 * (y * z - r0 * x)],
         [2 * (x * z - r0 * y), 2 * (y * z + r0 * x), r0 * r0 - x * x - y * y + z * z]]
    return [v / n for row in Q for v in row]


def _near_angles(small: list[float]) -> list[tuple[str, float]]:
    """Angles toward 0 and pi, both sides, 0 and fl(pi) included."""
    out = [("phi=0", 0.0), ("phi=pi", math.pi)]
    for s in small:
        out += [("phi->0+", s), ("phi->0-", -s), ("phi->pi-", math.pi - s * math.pi),
                ("phi->pi+", math.pi + s * math.pi)]
    return out


def _rotations_near(rng, small) -> list[tuple[str, list[fmpq]]]:
    out = [("Q=1", rotation(unit(rng), fmpq(0), fmpq(1))),
           ("Q at phi=pi", rotation(unit(rng), fmpq(1), fmpq(0)))]
    for s in small:
        out += [("Q: phi->0", rotation(unit(rng), q(s / 2), fmpq(1))),
                ("Q: phi->pi-", rotation(unit(rng), fmpq(1), q(s))),
                ("Q: phi->pi+", rotation(unit(rng), fmpq(1), q(-s)))]
    return out


def _random_arg(arg, rng, name: str) -> list[fmpq]:
    n = arg.size
    if arg.kind == "unit":
        return unit(rng, n)
    if arg.kind == "angle":
        return [q(rng.uniform(-math.pi, math.pi))]
    if arg.kind == "rotation":
        return rotation(unit(rng), q(rng.uniform(0.05, 3)), fmpq(1))
    if arg.name == "m":
        return [q(rng.uniform(0.5, 2.0))]
    if arg.name == "I_C":
        g = rng.standard_normal((3, 3))
        return [q(v) for v in (g @ g.T + 0.1 * np.eye(3)).ravel()]
    if arg.name == "angles":
        return [q(v) for v in rng.uniform(-math.pi, math.pi, 3)]
    return [q(v) for v in rng.standard_normal(n)]


def _gimbal(seq_tag: str) -> list[float]:
    """The middle angle's gimbal-lock values: symmetric sequences (xyx) at 0 and pi,
    asymmetric (xyz) at +-pi/2."""
    s = seq_tag.split("_")[-2]
    return [0.0, math.pi] if s[0] == s[2] else [math.pi / 2, -math.pi / 2]


def regimes(kernel, dtype, n_random: int = 8, seed: int = 0, small=None):
    """``{regime: [point]}`` for ``kernel`` (its ``Arg`` kinds and names decide the sweeps)."""
    rng = np.random.default_rng(seed)
    small = small if small is not None else (STEPS32 if dtype == np.float32 else STEPS)
    args = kernel.args
    names = [a.name for a in args]

    def base():
        return [_random_arg(a, rng, kernel.name) for a in args]

    out: dict[str, list] = {"random": [base() for _ in range(n_random)]}

    def add(regime: str, i: int, value: list[fmpq]):
        p = base()
        p[i] = value
        out.setdefault(regime, []).append(p)

    for i, a in enumerate(args):
        if a.kind == "angle":
            for reg, phi in _near_angles(small):
                add(reg, i, [q(phi)])
        elif a.kind == "rotation":
            for reg, Q in _rotations_near(rng, small):
                add(reg, i, Q)
        elif a.kind == "unit":
            for k in (1, 3):         # a few ulps off the constraint (beyond rounding)
                v = unit(rng, a.size)
                eps = float(np.finfo(dtype).eps)
                add("unit off by ulps", i, [x * (1 + q(k * eps * rng.choice([-1, 1])))
                                            for x in v])
        elif a.name == "angles":
            for lock in _gimbal(kernel.name):
                for s in small[:15]:
                    for sign in (1, -1):
                        p = base()
                        p[i] = [p[i][0], q(lock + sign * s), p[i][2]]
                        out.setdefault("gimbal lock", []).append(p)
        elif a.name in ("omega", "w_A", "t_A") and a.size in (3, 6):
            part = slice(3, 6) if a.name == "w_A" else slice(0, 3)
            reg = "||f||->0" if a.name == "w_A" else "||omega||->0"
            for s in small:
                p = base()
                v = list(p[i])
                v[part] = [x * q(s) for x in v[part]]
                p[i] = v
                out.setdefault(reg, []).append(p)
        elif a.shape == (3,) and a.name not in ("omega_dot",):
            for s in (1e-6, 1e-3, 1e3, 1e6):
                p = base()
                p[i] = [x * q(s) for x in p[i]]
                out.setdefault("scale 1e-6..1e6", []).append(p)
    if names[:2] == ["p1", "p2"]:          # nearly coincident points
        for s in small:
            p = base()
            d = [q(v) for v in rng.standard_normal(3)]
            p[1] = [x + q(s) * y for x, y in zip(p[0], d, strict=True)]
            out.setdefault("p2->p1", []).append(p)
    return out
