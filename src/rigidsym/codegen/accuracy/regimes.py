"""The regimes a user meets, per kernel: exact points (rationals) where formulas cancel,
overflow or lose digits (in the package so that the code generator
(:mod:`rigidsym.codegen.accuracy.rewrites`) chooses its forms over the regimes the accuracy harness,
``benchmarks/accuracy.py``, judges them on).

Regimes: random points; angles to 0 and pi from both sides (exactly 0 and fl(pi) too);
rotations to 1 and to a half turn; norms (omega, f) to 0; the gimbal lock of each Euler
sequence; vectors scaled 1e-6 .. 1e6; nearly coincident points (``|p2 - p1| / |p|`` from 1e-1
down, near the origin and at an offset of 1e6: large offsets, small differences); unit
vectors a few ulps off their constraint; and the ends of the floating range (every
unconstrained argument scaled together, then one at a time, to 1e-300 .. 1e300 in float64 and
1e-35 .. 1e35 in float32, past the square root of the largest and smallest numbers, where a
square overflows or underflows, and to subnormal values).

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

from rigidsym.codegen.accuracy import elementary

#: log-spaced approaches: 1e-1 ... 1e-15, then toward the smallest useful step: the size
#: whose fourth power (the highest power of a norm in the Jacobian kernels) is still a
#: normal number, 1e-75 in float64; float32 goes to 1e-18 (its square). Below it a power of
#: a norm underflows: the float format itself, not a formula, gives up.
STEPS = [float(f"1e-{k}") for k in range(1, 16)] + [1e-20, 1e-40, 1e-75]
STEPS32 = [float(f"1e-{k}") for k in range(1, 16)] + [1e-18]


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


def transform(R: list[fmpq], p: list[fmpq]) -> list[fmpq]:
    """``[[R, p], [0, 1]]`` row-major (a homogeneous transform, exact)."""
    return [*R[0:3], p[0], *R[3:6], p[1], *R[6:9], p[2], *map(fmpq, (0, 0, 0, 1))]


#: the translation entries of a transform (row-major 4 x 4)
_T_P = (3, 7, 11)


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


def random_arg(arg, rng, name: str) -> list[fmpq]:
    """A random exact value of kernel argument ``arg`` (of kernel ``name``) on its manifold
    (unit vectors, rotations, angles) or, unconstrained, standard normal: the regimes'
    ordinary points and the search's constrained starts."""
    n = arg.size
    if arg.kind == "unit":
        return unit(rng, n)
    if arg.kind == "angle":
        return [q(rng.uniform(-math.pi, math.pi))]
    if arg.kind == "rotation":
        return rotation(unit(rng), q(rng.uniform(0.05, 3)), fmpq(1))
    if arg.kind == "transform":
        return transform(rotation(unit(rng), q(rng.uniform(0.05, 3)), fmpq(1)),
                         [q(v) for v in rng.standard_normal(3)])
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


def _axis_rotation(axis: int, t) -> list[list[fmpq]]:
    """The rotation about coordinate axis ``axis`` through ``2 atan(t)`` (``t = None``: a
    half turn), exact: cos and sin rational by the half-angle tangent."""
    c, s = (fmpq(-1), fmpq(0)) if t is None else ((1 - t * t) / (1 + t * t), 2 * t / (1 + t * t))
    i, j = (axis + 1) % 3, (axis + 2) % 3
    R = [[fmpq(int(r == k)) for k in range(3)] for r in range(3)]
    R[i][i], R[i][j], R[j][i], R[j][j] = c, -s, s, c
    return R


def euler_rotation_exact(seq: str, angles: list) -> list[fmpq]:
    """``Q = R_i(a) R_j(b) R_k(c)`` of the intrinsic ``seq`` (``"zyx"``), row-major, exact:
    each angle a float (its half-angle tangent rounded to a rational), an ``fmpq`` (the
    half-angle tangent itself, exact) or ``None`` (a half turn); the gimbal-lock points of
    the Euler angles of a rotation."""
    Q = [[fmpq(int(r == k)) for k in range(3)] for r in range(3)]
    for ax, ang in zip(seq.lower(), angles, strict=True):
        t = ang if ang is None or isinstance(ang, fmpq) else q(float(elementary.tan(ang / 2)))
        R = _axis_rotation("xyz".index(ax), t)
        Q = [[sum((Q[r][m] * R[m][k] for m in range(3)), fmpq(0)) for k in range(3)]
             for r in range(3)]
    return [v for row in Q for v in row]


def _euler_lock(kernel, rng, small, i: int, out: dict, dtype) -> None:
    """The Euler angles of a rotation: Q at the lock (exactly) and toward it from both
    sides, the other two angles random; and at the lock with the entry +-sin b (or +-cos
    b) one ulp past 1, as a rotation computed in floating point holds it (the input of
    an unclamped asin's NaN, SymForce #226)."""
    seq = kernel.name.rsplit("_", 1)[-1]
    k_mid = "xyz".index(seq[0]) * 3 + "xyz".index(seq[2])    # Q[i, k] = +-1 at the lock
    past = 1 + q(float(np.finfo(dtype).eps))
    # the lock's half-angle tangent exactly (tan(pi/4) rounds below 1), None a half turn
    locks = [(0.0, fmpq(0)), (math.pi, None)] if seq[0] == seq[2] else \
        [(math.pi / 2, fmpq(1)), (-math.pi / 2, fmpq(-1))]
    for centre, lock in locks:
        for s in [0.0, *small[:15]]:
            for sign in ((1,) if s == 0 else (1, -1)):
                a, c = rng.uniform(-math.pi, math.pi, 2)
                mid = lock if s == 0 else centre + sign * s
                p = [random_arg(x, rng, kernel.name) for x in kernel.args]
                p[i] = euler_rotation_exact(seq, [a, mid, c])
                out.setdefault("gimbal lock", []).append(p)
                if s == 0:
                    p = [list(v) for v in p]
                    p[i][k_mid] = p[i][k_mid] * past
                    out.setdefault("gimbal lock, +-1 rounded past", []).append(p)


#: the ends of the range: powers of two near 1e-300, 1e-160 (a square underflows), 1e160 (a
#: square overflows), 1e300, and a subnormal (float64); 1e-35, 1e-20, 1e20, 1e35, 1e-40
RANGE = [-997, -531, 531, 997, -1040]
RANGE32 = [-116, -66, 66, 116, -133]


def _range(kernel, dtype, base, out) -> None:
    """The ends of the floating range: the unconstrained vector and scalar arguments scaled
    together by each power of :data:`RANGE`, then each alone."""
    free = [i for i, a in enumerate(kernel.args) if a.kind in ("any", "transform")
            and a.name != "m"]
    if not free:
        return
    for k in RANGE32 if dtype == np.float32 else RANGE:
        s = fmpq(2) ** k
        for group in [free] + ([[i] for i in free] if len(free) > 1 else []):
            p = base()
            for i in group:
                # the scaled value as the type holds it (a subnormal keeps fewer bits): the
                # point is exactly what the kernel gets; a transform's translation only
                scaled = range(len(p[i])) if kernel.args[i].kind == "any" else _T_P
                p[i] = [q(float(np.asarray(float(x * s)).astype(dtype))) if j in scaled
                        else x for j, x in enumerate(p[i])]
            out.setdefault("range 1e-300..1e300" if dtype != np.float32 else
                           "range 1e-35..1e35", []).append(p)


def _coincident(rng, small, base, out: dict) -> None:
    """Nearly coincident points p2 -> p1, at the origin's scale and at an offset of 1e6."""
    for s in small:
        p = base()
        d = [q(v) for v in rng.standard_normal(3)]
        p[1] = [x + q(s) * y for x, y in zip(p[0], d, strict=True)]
        out.setdefault("p2->p1", []).append(p)
    # a large offset, a small difference (|p2 - p1| / |p| from 1e-1 to 1e-12)
    for s in [x for x in small if x >= 1e-12]:
        p = base()
        d = [q(v) for v in rng.standard_normal(3)]
        p[0] = [x * 10**6 for x in p[0]]
        p[1] = [x + q(s) * 10**6 * y for x, y in zip(p[0], d, strict=True)]
        out.setdefault("p2->p1 at 1e6", []).append(p)


def _transforms_near(rng, small, add, name: str) -> None:
    """A transform's rotation toward the identity and a half turn (a random translation),
    then its translation scaled from 1e-6 to 1e6."""
    for reg, Q in _rotations_near(rng, small):
        add(reg.replace("Q:", f"{name}:"), transform(Q, [q(v) for v in rng.standard_normal(3)]))
    for sc in (1e-6, 1e-3, 1e3, 1e6):
        add("scale 1e-6..1e6", transform(rotation(unit(rng), q(rng.uniform(0.05, 3)), fmpq(1)),
                                         [q(v) * q(sc) for v in rng.standard_normal(3)]))


def _derived(kernel, rng, small, base, out: dict) -> None:
    """The zeros of the kernel's own denominator factors and differences in a norm
    (:mod:`rigidsym.codegen.accuracy.singular_sets`), approached from both sides along a
    random rational axis per point: ``|w| = theta0 -+ delta`` for each step ``delta``."""
    from rigidsym.codegen.accuracy.singular_sets import norm_zeros

    seen = set()
    for z in norm_zeros(kernel):
        t0 = float(z.theta0)
        if (z.arg, z.comps, t0) in seen:
            continue
        seen.add((z.arg, z.comps, t0))
        name = f"derived: |{kernel.args[z.arg].name}|->{sp_str(z.theta0)}"
        for s in small:
            for sign in (-1, 1):
                p = base()
                d = unit(rng, len(z.comps))
                r = q(t0 + sign * s)
                v = list(p[z.arg])
                for j, c in enumerate(z.comps):
                    v[c] = r * d[j]
                p[z.arg] = v
                out.setdefault(name, []).append(p)


def sp_str(x) -> str:
    """A zero as the regime names it (``2*pi``)."""
    import sympy as sp

    return sp.sstr(x).replace(" ", "")


def regimes(kernel, dtype, n_random: int = 8, seed: int = 0, small=None,
            extremes: bool = True, derived: bool = False):
    """``{regime: [point]}`` for ``kernel`` (its ``Arg`` kinds and names decide the sweeps);
    ``extremes``: the ends of the floating range too; ``derived``: the zeros of the
    kernel's own denominator factors and differences in a norm (
    :mod:`rigidsym.codegen.accuracy.singular_sets`; the harness's, not yet the generator's choice of
    forms: that would regenerate every kernel with a norm)."""
    rng = np.random.default_rng(seed)
    small = small if small is not None else (STEPS32 if dtype == np.float32 else STEPS)
    args = kernel.args
    names = [a.name for a in args]

    def base():
        return [random_arg(a, rng, kernel.name) for a in args]

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
            if kernel.name.startswith("euler_angles_from_rotation_"):
                _euler_lock(kernel, rng, small, i, out, dtype)
        elif a.kind == "transform":
            _transforms_near(rng, small, lambda reg, T, i=i: add(reg, i, T), a.name)
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
    if names[:2] == ["p1", "p2"]:
        _coincident(rng, small, base, out)
    if extremes:
        _range(kernel, dtype, base, out)
    if derived:
        _derived(kernel, rng, small, base, out)
    return out
