"""The form of a bare ``cos phi`` in the half-angle rewrite, chosen per kernel by measured
error.

The half-angle rewrite (:mod:`.optimise`) folds ``1 - cos phi`` into ``2 sin^2(phi/2)`` and
``1 + cos phi`` into ``2 cos^2(phi/2)``, then writes a ``cos phi`` left alone from the two
half-angle values. No one form of that is best everywhere: ``1 - 2 s^2`` is off by about
3 u absolute near pi (the textbook's ``cos phi``, by libm, by u/2), the piecewise one is
best alone but can lose where the kernel combines ``cos phi`` with ``s`` and ``c``
elsewhere (``L_tilde_dot``: 1.39 -> 1.61 times the rule at the harness's points), and
``(c - s)(c + s)`` has no branch. So each build of a kernel (each branch and the main one) is
measured in each of :data:`rigidsym.codegen.optimise.COS_FORMS` as :mod:`.rewrites`
measures its rewrites (:class:`rigidsym.codegen.accuracy.error.Meter`): float64, at exact
points over the regimes of :mod:`.regimes` (seeds :data:`SEEDS`, none of the harness's),
against the declared formula in mpmath; the worst ratio to the rule's reference half
(:func:`rigidsym.codegen.accuracy.error.worst`: ``max(2 e_ref, 4 u)``, ``e_ref`` the
textbook formula evaluated plainly) decides, the default form kept unless another is
:data:`MARGIN` better. Each form is an identity (the zero test decides ``form - cos phi`` on
the angle's constraint), so only the rounding changes.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.codegen.accuracy.error import Meter, worst
from rigidsym.codegen.accuracy.rewrites import Chosen
from rigidsym.codegen.optimise import COS_FORMS, DEFAULT_COS, rewrite

__all__ = ["SEEDS", "MARGIN", "choose"]

#: the seeds of the measurement points: the harness judges at 0-3 (and
#: tests/test_bounds_fresh.py at another), so the choice is not fitted to its points
SEEDS = (40, 41, 42, 43)
#: another form is kept only where its worst ratio is this much smaller than the default's
MARGIN = 0.9


def _decided(form: str) -> str:
    from rigidsym.algebra.symbols import constrained_group
    from rigidsym.zero.decide import decide_zero

    phi = constrained_group("angle", "zt_phi")
    v = COS_FORMS[form](sp.sin(phi / 2), sp.cos(phi / 2))
    parts = [a for a, _ in v.args] if isinstance(v, sp.Piecewise) else [v]
    res = decide_zero([p - sp.cos(phi) for p in parts])
    if res.zero is not True:
        raise AssertionError(f"cos form {form!r} is not cos(phi): {res.method} {res.detail}")
    return res.method


def choose(kernel, variant: str, declared, flat, angles, syms_flat, conds, cond=None):
    """``(form, [Chosen])``: the :data:`~rigidsym.codegen.optimise.COS_FORMS` key for this
    build of ``kernel`` (``declared``: its outputs as declared, the reference and the
    textbook; ``flat``: as the accuracy rewrites and the removable singularities left them),
    and the header line where it is not the default."""
    if not angles or not any(e.has(sp.cos(a)) for e in flat for a in angles):
        return DEFAULT_COS, []
    meter = Meter(kernel, declared, syms_flat, conds, cond, n_random=8, seeds=SEEDS,
                  small=None)
    if not meter.ok.any():
        return DEFAULT_COS, []
    textbook = meter.errors(declared)
    ratio = {f: worst(meter.errors([rewrite(sp.sympify(e), angles, f) for e in flat]),
                      textbook) for f in COS_FORMS}
    best = min(ratio, key=lambda f: (ratio[f], f != DEFAULT_COS))
    if best == DEFAULT_COS or ratio[best] > MARGIN * ratio[DEFAULT_COS]:
        return DEFAULT_COS, []
    return best, [Chosen(
        variant, f"cos phi as {best}",
        f"the bare cos phi left by the half-angle rewrite, as {best} (s, c: sin, cos of "
        f"phi/2) rather than {DEFAULT_COS}: the form of the measured least error among "
        f"{', '.join(COS_FORMS)} (rigidsym.codegen.accuracy.cos_form)",
        ratio[DEFAULT_COS], ratio[best], int(meter.ok.sum()), _decided(best))]
