"""The points a form is measured on, over the regimes of
:mod:`rigidsym.codegen.accuracy.regimes` (the harness's): one builder of them
(:func:`regime_points`), and the two ways they are taken.

- The code generator's choice of forms (:mod:`rigidsym.codegen.accuracy.rewrites`,
  :mod:`rigidsym.codegen.accuracy.cos_form`, measured by
  :class:`rigidsym.codegen.accuracy.error.Meter`): :func:`exact_points`, in mpmath, the
  regimes in float64 on fewer steps (:data:`GENERATOR_STEPS`).
- The float32 precision plan (:mod:`rigidsym.codegen.accuracy.float32`): random and
  adversarial points by argument kind (:func:`sample_inputs`), then the regimes in float32
  (:func:`regime_inputs`), as float32 inputs and as the inputs the harness takes the truth
  at (:func:`plan_inputs`).
"""

from __future__ import annotations

import mpmath
import numpy as np

from rigidsym.codegen.accuracy.regimes import regimes
from rigidsym.core.draws import rotations, units

__all__ = ["GENERATOR_STEPS", "regime_points", "exact_points", "N_RANDOM", "REGIME_SEEDS",
           "RANGE32", "sample_inputs", "regime_inputs", "plan_inputs"]

#: the approach steps of the generator's regimes (a subsample of the harness's, for time)
# decimal literals, correctly rounded everywhere (10.0**-k is the C library's pow)
GENERATOR_STEPS = [float(f"1e-{k}") for k in (1, 3, 5, 7, 9, 11, 13, 15, 20, 100)]


def regime_points(kernel, dtype, seeds, n_random: int = 8, small=None) -> list:
    """The points of :func:`rigidsym.codegen.accuracy.regimes.regimes` for ``kernel`` in
    ``dtype``, drawn with each of ``seeds`` in turn (``n_random`` random ones each, the
    approach steps ``small``, the type's own where None), regime after regime: exact, one
    ``list[fmpq]`` per argument. Not the ends of the floating range: an intermediate that
    overflows there is the runtime's rescue (``rigidsym.kernels.runtime.rescue``, by
    scaling), not a form's to avoid."""
    return [p for seed in seeds
            for ps in regimes(kernel, dtype, n_random=n_random, seed=seed, small=small,
                              extremes=False).values()
            for p in ps]


def exact_points(kernel, seeds=(30,), n_random: int = 6, small=GENERATOR_STEPS) -> list:
    """The generator's points (:func:`regime_points` in float64), per argument a list of
    mpmath numbers (40 digits). The unconstrained arguments are taken as float64 holds them
    (the reference then judges the formula, not the rounding of the input, which every form
    suffers alike); constrained ones stay exact (on their manifold, where the rewrites are
    equal to the declaration). The last kernel's are kept: its every build (branch, main) and
    choice (the accuracy rewrites, the cos form) measures on them."""
    if _EXACT[0] is not kernel:
        _EXACT[:] = [kernel, {}]
    key = (tuple(seeds), n_random, None if small is None else tuple(small))
    if key not in _EXACT[1]:
        _EXACT[1][key] = _exact_points(kernel, seeds, n_random, small)
    return list(_EXACT[1][key])


#: ``[kernel, {(seeds, n_random, small): points}]``: :func:`exact_points` of one kernel
_EXACT: list = [None, {}]


def _exact_points(kernel, seeds, n_random: int, small) -> list:
    with mpmath.workdps(40):
        return [[[mpmath.mpf(float(x)) if arg.kind == "any" else
                  mpmath.mpf(int(x.p)) / int(x.q) for x in a]
                 for arg, a in zip(kernel.args, p, strict=True)]
                for p in regime_points(kernel, np.float64, seeds, n_random, small)]


# --------------------------------------------------------------------------- float32 plan
#: random points per kernel of the float32 plan (then the adversarial ones)
N_RANDOM = 1000
#: the seeds of the harness's regimes the plan is measured on: not the harness's own (0-3)
#: nor tests/test_bounds_fresh.py's (37), so that the harness judges each plan on points it
#: was not chosen on (before, the plan saw none of the regimes, and 12 float32 C rows failed
#: the rule there: Euler-angle rates at gimbal lock, where a random omega and angles make
#: the numerator cancel). Forty: a cancellation of the few that break a float plan turns
#: up in a few seeds of forty, at 4 (20-23) in none for euler_angle_rates_yzy_body.
REGIME_SEEDS = tuple(range(100, 140))
#: the float32 input magnitudes the C kernels compute in float32 (c_common.h,
#: rigidsym_any_extreme_f32; rigidsym.kernels.runtime.rescue.RANGE32): a sample with a nonzero input
#: outside it is re-run in a wider type
RANGE32 = (2.0**-30, 2.0**31)
_ADV_PHI = [1e-12, 1e-8, 1e-4, 1e-2, np.pi - 1e-4, np.pi - 1e-2, -1e-6, 3.0]
_F32, _F64 = np.float32, np.float64


def _unit(rng, n: int, k: int = 3) -> np.ndarray:
    return units(rng, (n, k))


def sample_inputs(args, n: int = N_RANDOM, seed: int = 20, exact: bool = False):
    """float32 values per flat input symbol (``e_0``, ``phi``, ``Q_01``): ``n`` random rows
    then adversarial ones, by argument kind and name (as tests/test_kernels.py).
    ``exact``: also the inputs of the truth (:func:`_columns`)."""
    rng = np.random.default_rng(seed)
    adv = len(_ADV_PHI)
    names = [a.name for a in args]
    vals = []
    for a in args:
        m = n + adv
        if a.kind == "unit":
            v = _unit(rng, m, a.size)
        elif a.kind == "angle":
            v = np.concatenate([rng.uniform(-np.pi, np.pi, n), _ADV_PHI])
        elif a.kind == "rotation":
            v = rotations(_unit(rng, m), np.concatenate([rng.uniform(0, np.pi, n),
                                                          _ADV_PHI]))
        elif a.kind == "transform":
            v = np.zeros((m, 4, 4))
            v[:, :3, :3] = rotations(_unit(rng, m), np.concatenate([
                rng.uniform(0, np.pi, n), _ADV_PHI]))
            v[:, :3, 3], v[:, 3, 3] = rng.standard_normal((m, 3)), 1.0
        elif a.name == "m":
            v = rng.uniform(0.5, 2.0, m)
        elif a.name == "I_C":
            g = rng.standard_normal((m, 3, 3))
            v = np.einsum("nij,nkj->nik", g, g) + 0.1 * np.eye(3)
        else:
            v = rng.standard_normal((m,) + tuple(a.shape))
            if a.name == "omega" and "omega_dot" not in names and "phi" not in names:
                # down to 1e-18: a Jacobian's ||omega||^-3 overflows float32
                # below 7e-13 (the C range test re-runs such rows now: plan_inputs drops them)
                v[n:n + 5] *= np.array([1e-12, 1e-6, 1e-3, 1e-15, 1e-18])[:, None] / \
                    np.linalg.norm(v[n:n + 5], axis=1, keepdims=True)
            if a.name == "angles":   # gimbal lock of either family, as close as float32 gets
                v[n:n + 8, 1] = [1e-9, np.pi / 2 - 1e-9, -1e-9, np.pi / 2 + 1e-9, 1e-6,
                                 np.pi / 2 - 1e-3, 1e-2, 1.5]
        vals.append(np.asarray(v, dtype=_F64).reshape(m, -1))
    return _columns(args, vals, exact)


def _columns(args, vals: list, exact: bool = False):
    """Per flat input symbol, the float32 values of ``vals`` (one ``(m, size)`` float64 array
    per argument); ``exact``: also the inputs the harness takes the truth at
    (``benchmarks/accuracy.py``: the unconstrained arguments as rounded, the constrained ones
    (unit vectors, angles, rotations, transforms) exact, on their manifold): the float32
    values widened for the kind ``"any"``, the float64 ones of ``vals`` for the others."""
    cols: dict[str, np.ndarray] = {}
    wide: dict[str, np.ndarray] = {}
    for a, v in zip(args, vals, strict=True):
        flat = v.astype(_F32)
        x = flat.astype(_F64) if a.kind == "any" else v
        if a.shape == ():
            keys = [a.name]
        elif len(a.shape) == 1:
            keys = [f"{a.name}_{i}" for i in range(a.shape[0])]
        else:
            keys = [f"{a.name}_{i}{j}" for i in range(a.shape[0]) for j in range(a.shape[1])]
        cols.update({key: flat[:, j] for j, key in enumerate(keys)})
        wide.update({key: x[:, j] for j, key in enumerate(keys)})
    return (cols, wide) if exact else cols


def regime_inputs(kernel, seeds=REGIME_SEEDS) -> tuple[dict, dict]:
    """The points of the harness's regimes (:func:`rigidsym.codegen.accuracy.regimes.regimes`,
    float32, without the ends of the range: the rescue's) drawn with each of ``seeds``: per
    flat input symbol the float32 values a caller hands the kernel, and the inputs of the
    truth (:func:`_columns`)."""
    # the regimes depend on the kernel itself (its derived singular sets, an Euler
    # sequence's lock): only a kernel and its _with_jacobians share them (exact rationals:
    # half the planner's time). Keyed by arguments alone, two kernels of one argument list
    # shared the points of whichever the worker planned first: generation was not repeatable
    key = (tuple((a.name, a.kind, a.shape) for a in kernel.args), tuple(seeds),
           kernel.name.removesuffix("_with_jacobians"))
    if key not in _REGIME_VALUES:
        pts = regime_points(kernel, _F32, seeds)
        _REGIME_VALUES[key] = [
            np.array([[float(x) for x in p[i]] for p in pts], dtype=_F64).reshape(len(pts), -1)
            for i in range(len(kernel.args))]
    return _columns(kernel.args, _REGIME_VALUES[key], True)


_REGIME_VALUES: dict = {}


def plan_inputs(kernel) -> tuple[dict, dict]:
    """The points a plan is measured on, ``(float32 inputs, inputs of the truth)``:
    :func:`sample_inputs`, then :func:`regime_inputs`; only the rows whose every input the
    C float32 kernels compute (zero, or of magnitude in :data:`RANGE32`)."""
    own = sample_inputs(kernel.args, n=N_RANDOM, exact=True)
    reg = regime_inputs(kernel, REGIME_SEEDS)
    cols, wide = ({k: np.concatenate([v, r[k]]) for k, v in o.items()}
                  for o, r in zip(own, reg, strict=True))
    keep = np.ones(len(next(iter(cols.values()))), dtype=bool)
    for v in cols.values():
        m = np.abs(v)
        keep &= (m == 0) | ((m >= RANGE32[0]) & (m < RANGE32[1]))
    return {k: v[keep] for k, v in cols.items()}, {k: v[keep] for k, v in wide.items()}
