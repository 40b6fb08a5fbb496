"""A Herbie-style search for the inputs where a kernel loses accuracy: it
knows nothing of the regimes someone listed or derived.

Per kernel and float type, seeded: ``n_start`` random points on the floating line
(exponent-uniform: every unconstrained component ``+-2^e``, ``e`` uniform in ``[-E, E]``
times a random significand; constrained arguments drawn on their manifold as the harness
does), each judged by the harness's own rule (the judge, :func:`.judge.judge`: the ratio to
``8 u (kappa + 1)`` and to ``max(2 e_ref, 4 u)``, a spurious flag counting as infinite);
then hill climbing from the worst: one unconstrained component at a time multiplied by
``1 +- 2^-j`` (``j`` uniform in 1 .. 52) or its sign flipped, a step kept when the measured
ratio grows. The worst points found are regression cases (``tests/test_whole_domain.py``).
"""

from __future__ import annotations

import math

import numpy as np

from rigidsym.codegen.accuracy import regimes as P
from rigidsym.codegen.accuracy.harness import judge as A
from rigidsym.codegen.accuracy.harness import reference as R
from rigidsym.codegen.accuracy.regimes import random_arg

#: the exponent range of the random start points (float32: a smaller one)
EXP = {np.float64: 8, np.float32: 8}


def _score(name, point, dtype, backends, runner=None, condition: bool = False) -> float:
    rows = A.judge(name, "search", [point], dtype, backends, runner=runner,
                   reference_half=not condition)
    if any(r.spurious for r in rows):
        return math.inf
    return max(r.worst_ratio if condition else r.rule_ratio for r in rows)


def _start(k, rng, dtype) -> list:
    e = EXP[np.dtype(dtype).type]
    p = []
    for a in k.args:
        if a.kind == "any" and a.name != "m":
            v = rng.choice([-1.0, 1.0], a.size) * 2.0 ** rng.uniform(-e, e, a.size)
            p.append([P.q(x) for x in v])
        else:
            p.append(random_arg(a, rng, k.name))
    return p


def search(name: str, dtype=np.float64, backends=("numpy",), seed: int = 0,
           n_start: int = 24, steps: int = 60, runner=None,
           condition: bool = False) -> tuple[float, list]:
    """``(worst rule ratio, its point)`` found for ``name``: exponent-uniform starts, then
    hill climbing on the measured ratio (see the module); ``runner`` as
    :func:`.judge.judge`'s (the PyTorch and JAX kernels, tests/test_search_every_kernel.py;
    a user's function, ``rigidsym audit``); ``condition``: climb on the condition half
    alone, ``err / (8 u (kappa + 1))`` (the audit's measure)."""
    k = R.kernel_of(name)
    rng = np.random.default_rng(seed)
    free = [i for i, a in enumerate(k.args) if a.kind == "any" and a.name != "m"]
    best, best_p = -1.0, None
    for _ in range(n_start):
        p = _start(k, rng, dtype)
        s = _score(name, p, dtype, backends, runner, condition)
        if s > best:
            best, best_p = s, p
    if not free or not math.isfinite(best):
        return best, best_p
    for _ in range(steps):
        i = free[rng.integers(len(free))]
        j = rng.integers(len(best_p[i]))
        p = [list(a) for a in best_p]
        x = float(p[i][j])
        if rng.random() < 0.1:
            x = -x
        else:
            x *= 1 + rng.choice([-1, 1]) * 2.0 ** -rng.integers(1, 53)
        p[i][j] = P.q(x)
        s = _score(name, p, dtype, backends, runner, condition)
        if s > best:
            best, best_p = s, p
            if not math.isfinite(s):
                break
    return best, best_p
