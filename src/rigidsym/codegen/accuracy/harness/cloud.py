"""The reference half of the rule judged over a cloud of neighbouring floating-point inputs
: the judge (:func:`.judge.judge`) asks it where the kernel's error at a point is past
``max(2 e_ref, 4 u)`` of the best yardstick there.

Why. A program's error at one input is a pseudo-random function of that input's low bits
(how each operation happened to round). Where the conditioning of the problem dominates it,
every program's error is a spread of about ``u kappa`` around 0: the rounding of
``theta = |w|`` feeds ``sin theta`` an absolute error near ``theta u`` whatever the algorithm,
so at ``|w|`` 50 .. 300 ``rotation_from_rotation_vector``'s error is 60 u (median of 40
points) and pytransform3d's ``matrix_from_compact_axis_angle`` 78 u, each from near 0 to
300 u from one input to the next. At one input the peer can be 1.1 u while the kernel is
137 u (kappa 202: within ``8 u (kappa + 1)``), and the search, which climbs on the ratio,
finds exactly such inputs: the per-point comparison then measures luck, not the programs.

So the per-point comparison is a screen. Where it fails, the kernel and every yardstick
are evaluated at the point and at :data:`N` neighbours, each against the truth at its own
input, and the reference half is decided by the **medians**:
``median(err) <= max(2 min_y median(err_y), 4 u)``. A neighbour moves each nonzero
unconstrained component by a random relative amount up to
``rho = min(sqrt(eps), MOVE / (kappa + 1))`` (``MOVE = 2^-13``; at least :data:`ULPS`
units in the last place; reproducibly, from the point's bits; constrained arguments and
exact zeros kept). The output then moves by at most about ``2^-13`` of itself, so the
neighbours lie in the point's regime (near a singular set ``kappa`` is about one over the
distance to it, which changes by ``2^-13`` of itself), while every rounding on the way,
``theta = |w|`` included, lands afresh. Smaller moves do not do that: moves of a few ulps
at ``w = (-3.6, 0.28, 248.2)`` shift ``|w|`` by whole ulps of ``|w|`` and its rounding
error not at all (the peer stayed 1 u at all nine such inputs); moves of
``sqrt(eps) / (kappa + 1)`` at ``w = (-0.006, 0.005, 32.3)`` shift it by about 0.2 ulp (the peer
2.4 u median there, the kernel 9.8 u; 13 u and 15 u over the wider cloud).

A program systematically worse than a yardstick over the regime (the
SE(3) inverse Jacobian at ``|w| = 4.5``, median 7.0 u where pytransform3d's is 2.2 u) fails
the medians as it failed the points; a yardstick lucky at one input no longer makes a kernel
fail. The condition half is still judged at the point itself (no median there).
"""

from __future__ import annotations

import hashlib

import numpy as np

from rigidsym.codegen.accuracy import regimes as P
from rigidsym.codegen.accuracy import rule
from rigidsym.codegen.accuracy.harness import compare as J
from rigidsym.codegen.accuracy.harness import reference as R
from rigidsym.codegen.accuracy.harness import yardsticks as O

#: neighbours of the point in the cloud (the point itself is the first of N + 1)
N = 32
MOVE = 2.0**-13
#: a neighbour's component moves by up to min(sqrt(eps), MOVE / (kappa + 1)) of itself,
#: and at least ULPS units in the last place of the type
ULPS = 8


def neighbours(k, arrays, s, dtype, kappa) -> list[np.ndarray]:
    """The cloud's inputs: row 0 the point ``s`` of ``arrays``, rows 1 .. N its neighbours
    (see the module; ``kappa`` the condition number at the point), one array per argument,
    as the kernel takes them."""
    seed = int.from_bytes(hashlib.sha256(b"".join(a[s].tobytes() for a in arrays))
                          .digest()[:8], "little")
    rng = np.random.default_rng(seed)
    eps = float(np.finfo(dtype).eps)
    rho = max(min(np.sqrt(eps), MOVE / (kappa + 1)) if np.isfinite(kappa) else 0.0,
              ULPS * eps)
    out = []
    for a, arg in zip(arrays, k.args, strict=True):
        x = np.repeat(a[s][None].astype(np.float64), N + 1, axis=0)
        if arg.kind == "any":
            z = rng.uniform(-1.0, 1.0, x.shape)
            z[0] = 0.0
            with np.errstate(all="ignore"):
                moved = (x * (1 + rho * z)).astype(dtype).astype(np.float64)
            x = np.where(np.isfinite(moved), moved, x)
        out.append(np.ascontiguousarray(x.astype(dtype)))
    return out


class Cloud:
    """The kernel's and the yardsticks' outputs and the truth over the cloud of point ``s``,
    computed on first use (a point whose screen passes costs nothing)."""

    def __init__(self, name, k, p, arrays, s, dtype, run, kappa):
        self.name, self.k, self.p, self.dtype, self.run = name, k, p, dtype, run
        self.kappa = kappa
        self.arrays, self.s, self.got, self.data = arrays, s, {}, None

    def _load(self):
        k, c = self.k, neighbours(self.k, self.arrays, self.s, self.dtype, self.kappa)
        refs, fs = [], []
        for i in range(N + 1):
            flat = [float(x) for a in c for x in a[i].ravel()]
            exact = [x for j, a in enumerate(k.args)
                     for x in ([P.q(float(v)) for v in c[j][i].ravel()] if a.kind == "any"
                               else self.p[j])]
            f = R.pick(self.name, flat)
            refs.append(R.reference(f, exact)[0])
            fs.append(f)
        n_out = sum(o.size for o in k.outputs)
        yard = {"textbook": O.textbook(self.name, c, self.dtype)}
        if np.dtype(self.dtype) == np.float64:
            yard.update(O.evaluate(self.name, c, n_out))
        self.data = c, refs, fs, yard

    def _errors(self, out, sl, bound) -> np.ndarray:
        c, refs, fs, _ = self.data
        e = []
        for i, ref in enumerate(refs):
            if ref is None:
                continue
            at = J.AtInput(fs[i], c, i) if self.k.branches else None
            e.append(J.diff(out[i, sl], ref[sl], at, sl, bound)
                     / (float(np.linalg.norm(ref[sl])) or 1.0))
        return np.array(e)

    def ratio(self, backend, sl, bound, u) -> tuple[float, float, float, str]:
        """``(reference-half ratio, median err, median e_ref, yardstick)`` for one output
        (slice ``sl`` of the flat outputs; ``bound`` the point's ``8 u (scale + norm)``,
        which ``_diff`` reads to forgive the sign of e near pi) on ``backend``."""
        if self.data is None:
            self._load()
        if backend not in self.got:
            self.got[backend] = self.run(self.name, self.data[0], self.dtype, backend)
        e_k = self._errors(self.got[backend], sl, bound)
        if e_k.size == 0:
            return 0.0, 0.0, 0.0, ""
        meds = {lab: float(np.median(self._errors(v, sl, bound)))
                for lab, v in self.data[3].items()}
        src = min(meds, key=meds.get)
        med = float(np.median(e_k))
        return rule.ratio(med, u, None, meds[src]), med, meds[src], src
