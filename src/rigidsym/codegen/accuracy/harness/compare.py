"""How the judge (:mod:`.judge`) compares a kernel's output with its references: the truth
at the input as rounded (``Rounded``), the declared formula at the input the kernel got
(``AtInput``, for the sign rule near pi), the distance the rule reads (``diff``) and the
reference the componentwise figure is taken against (``judged_by``)."""

from __future__ import annotations

import numpy as np

from rigidsym.codegen.accuracy import regimes as P
from rigidsym.codegen.accuracy.harness import reference as R


def kappa_of(scale, norms) -> float:
    """The worst condition number over the outputs (an output that is 0: its absolute
    scale); inf where a derivative or a norm overflowed float64."""
    with np.errstate(all="ignore"):
        k = scale / np.where(norms > 0, norms, np.inf)
    return float(np.where(np.isnan(k), np.inf, k).max())


class Rounded:
    """The declared formula at the point with the unconstrained arguments as rounded to the
    type (constrained ones exact, on their manifold), on first use; the exact point's
    reference where nothing was rounded."""

    def __init__(self, k, f, p, arrays, s, ref):
        self.pt = [[P.q(float(x)) for x in arrays[j][s].ravel()] if a.kind == "any"
                   else list(p[j]) for j, a in enumerate(k.args)]
        self.f, self.ref = f, ref
        self.v = ref if self.pt == [list(x) for x in p] else None

    def get(self):
        if self.v is None:
            self.v = R.reference(self.f, [x for a in self.pt for x in a])[0]
            if self.v is None:          # undefined there: the exact point's
                self.v = self.ref
        return self.v


class AtInput:
    """The declared formula at the input the kernel got (not the exact point), computed on
    first use: the reference of the sign rule near pi."""

    def __init__(self, f, arrays, s):
        self.f, self.arrays, self.s, self.v = f, arrays, s, False

    def get(self):
        if self.v is False:
            exact = [P.q(float(x)) for a in self.arrays for x in a[self.s].ravel()]
            self.v = R.reference(self.f, exact)[0]
        return self.v


def diff(c, ref, at_input, sl, bound) -> float:
    """``||c - ref||``; where that is past ``bound`` in a kernel with branches, at most the
    distance to the declared formula at the input the kernel got. Near pi the rounding of
    Q (or of a transform's R) can flip the sign of its skew part, which fixes e: the exact
    point's output is then -w (the log of SO(3)), or [-w; J_l(-w)^-1 p] (the log of SE(3),
    not the negation of [w; v]), a jump that no derivative (kappa) sees; the kernel is
    judged by its documented sign rule at its own input there (a Jacobian kernel's derivative
    is then that of the other logarithm, ``d phi e - phi de`` for ``d phi e + phi de``).

    Only such a jump (the formula at the input at least 1e-3 of the output's norm away from
    ``ref``) is forgiven: near phi = 0 the declared formula at a rounded Q (off SO(3))
    reads Q's diagonal, 1e8 u from the truth, and forgiving that would make the textbook,
    which does the same, a yardstick of 1 u (screw_of_displacement's `Q: phi -> 0` row)."""
    if not np.isfinite(c).all():
        return np.inf
    return float(np.linalg.norm(c - judged_by(c, ref, at_input, sl, bound)))


def judged_by(c, ref, at_input, sl, bound):
    """The reference ``diff`` judges ``c`` by: ``ref``, or the declared formula at the input
    where that is a jump away from ``ref`` and nearer ``c`` (the sign of e near pi); the
    componentwise figure is taken against it too, so that an axis of the other sign is not
    counted 2 / u ulps."""
    if at_input is None or not np.isfinite(c).all() or np.linalg.norm(c - ref) <= bound:
        return ref
    v = at_input.get()
    if v is None or np.linalg.norm(v[sl] - ref) < 1e-3 * np.linalg.norm(ref):
        return ref
    return v[sl] if np.linalg.norm(c - v[sl]) < np.linalg.norm(c - ref) else ref


def point_text(arrays, s) -> str:
    """Row ``s`` of ``arrays`` as text, 17 digits a component (a reproducer)."""
    return "; ".join(np.array2string(a[s].ravel().astype(np.float64), precision=17,
                                     separator=",") for a in arrays)
