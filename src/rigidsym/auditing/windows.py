"""The approaches to each singular set searched continuously, so that no window between two
decades is missed, and the cause of a window read from the function's own errors.

An *approach* is a one-parameter family of inputs ``x -> point`` (the angle ``phi`` of a
rotation toward the identity, ``pi - phi`` toward a half turn, ``|w|`` toward 0, the
distance to a derived zero of a norm), everything else (the axis, the other arguments)
drawn anew for each sample; a scalar angle's approach to 0 and to pi, a unit quaternion's
angle to 0 and to pi. A window is written in the variable the function takes: in the
distance to the singular point near it (radians: ``pi - |w|``), in ``|w|`` itself away
from it (:meth:`Approach.shown`). It is sampled on a lattice in ``log10 x``, :data:`PER_DECADE`
points a decade from 1e-16 to 1 shifted by a random offset (seeded), so that every
interval of ``x`` wider than a factor ``10 ** (1 / PER_DECADE)`` (1.075 at 32 a decade)
holds a sample. The whole lattice is first screened at once against rigidsym's kernel (the
user's function called once per input, the kernel once for all); an input is judged
against the truth where the two differ by more than ``4 u`` (or either flags), and at
every :data:`COARSE`-th sample.
Every run of samples over the bound (samples within it between two over it joined when at
most :data:`GAP`) is a window: a golden-section search on ``log x`` around its worst
sample refines its worst input, and its two ends are located by bisection to within a
factor :data:`END_FACTOR` of ``x``. Every window is reported, its ends and its worst.

A cause is stated only from what was measured: an error that jumps by :data:`JUMP` or more
across an end located to within 1 % (three points on each side agreeing) is "a threshold
branch" at that ``x``; the slope of ``log err`` against ``log x`` inside the window is
reported as measured; a flag at exactly 0 where the approach to 0 is finite is "no guard
for exactly 0". Anything else: "cause not determined".
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from flint import fmpq

from rigidsym.codegen.accuracy import regimes as P

__all__ = ["Approach", "Window", "approaches", "scan", "scan_all", "PER_DECADE", "DECADES",
           "END_FACTOR", "JUMP", "GAP", "SCREEN", "COARSE", "MAX_WINDOWS", "GOLDEN",
           "SCATTER", "FAR"]

#: an approach's parameter from which on a window is written in the function's own variable
FAR = 0.1
#: samples per decade of the approach's parameter
PER_DECADE = 32
#: the decades sampled: x from 10**-DECADES to 1
DECADES = 16
#: the window's ends are located to within this factor of x
END_FACTOR = 1.01
#: an error that changes by this factor across an end located to within 1 % is a jump
JUMP = 10.0
#: samples within the bound that may lie between two over it in one window (noise: an
#: error of the rounding's luck can be small at one input of a window)
GAP = 2
#: a sample whose screen (the distance to rigidsym's kernel over 8 u) exceeds this is judged
SCREEN = 0.5
#: every COARSE-th sample is judged whatever its screen (4 a decade at 32 a decade)
COARSE = 8
#: the windows refined on one approach (the worst first); the others as their samples give
MAX_WINDOWS = 8
#: golden-section steps around each window's worst sample
GOLDEN = 8
#: a slope is measured where the rms of ``log err`` off its fitted line is below this (the
#: error within a factor 1.28 of a power law of ``x``)
SCATTER = 0.25


@dataclass(frozen=True)
class Approach:
    """A one-parameter family of inputs: ``point(x, draw)`` (exact, per argument), ``x`` in
    (0, 1], everything else (the axis, the other arguments) drawn by the integer ``draw``
    (the same draw, the same inputs); ``regime`` the regime it refines (its name in the
    report), ``var`` what ``x`` is, in the book's words (``phi``, ``pi - phi``, ``|w|``)."""

    regime: str
    var: str
    point: Callable[[float, int], list]
    #: ``var = scale x`` (pi - |w| = pi x on the approach of |w| to pi)
    scale: float = 1.0
    #: the variable the function takes (``|w|``), where ``var`` is a distance to a point
    #: other than 0 (pi, 2 pi), and ``x -> its value``: away from that point (x >= FAR) a
    #: window is written in it (``|w| = 0.0157``, not ``pi - |w| = 3.12``)
    far_var: str = ""
    far: Callable[[float], float] | None = None

    def shown(self, xs: list[float], near: bool | None = None) -> tuple[str, list[float]]:
        """``(variable, values)`` of the approach's parameters ``xs`` as the report writes
        them: the distance ``var`` near its singular point, the function's own variable
        (``far_var``) where the largest of ``xs`` is FAR or more from it (or ``near`` is
        False)."""
        if near is None:
            near = max(xs) < FAR
        if self.far is None or near:
            return self.var, [self.scale * x for x in xs]
        return self.far_var, [self.far(x) for x in xs]


@dataclass
class Window:
    """What :func:`scan` found on one approach.

    Attributes:
        approach: the approach.
        worst_x, worst_ratio: the worst input's parameter and its error over the bound.
        worst: the worst input's judgement (a :class:`.worst.Judged`).
        lo, hi: the ends of the window over the bound around the worst (``x``), or None
            where the worst is within the bound.
        lo_open, hi_open: the window reaches the smallest (largest) ``x`` sampled.
        jump: ``(x, ratio inside, ratio outside)`` at an end where the error jumps, or None.
        slope: the slope of ``log err`` against ``log x`` over the window's samples (None:
            fewer than 4 in it, a flag, or samples off a line by more than :data:`SCATTER`).
        evaluations: how many inputs were judged.
        judged: every judgement made, ``(x, judgement)``.
    """

    approach: Approach
    worst_x: float
    worst_ratio: float
    worst: object
    lo: float | None = None
    hi: float | None = None
    jump: tuple | None = None
    slope: float | None = None
    evaluations: int = 0
    lo_open: bool = False
    hi_open: bool = False
    judged: list = field(default_factory=list)

    def cause(self) -> str:
        """The cause as measured, or "cause not determined"."""
        v = self.approach.var
        if self.jump is not None and not math.isfinite(self.jump[1]):
            jv, (jx,) = self.approach.shown([self.jump[0]], self._near())
            return (f"the output is NaN, inf or an exception on the window, from {jv} = "
                    f"{jx:.3g} (located to within 1 %); cause not determined")
        if self.jump is not None:
            x, inside, outside = self.jump
            near_hi = self.hi is not None and (self.lo is None or abs(math.log(
                x / self.hi)) < abs(math.log(x / self.lo)))
            jv, (jx,) = self.approach.shown([x], self._near())
            if jv != v and self.approach.far is not None and \
                    self.approach.far(1.0) < self.approach.far(0.5):
                near_hi = not near_hi        # |w| = pi (1 - x) runs the other way
            side = "below" if near_hi else "above"
            text = (f"the error jumps {inside / max(outside, 1e-300):.3g}-fold at {jv} = "
                    f"{jx:.3g} (located to within 1 %; the error {side} it is the window's): "
                    f"a threshold branch")
            if self.slope is not None and abs(self.slope) >= 0.5:
                text += f"; inside the window the error goes as ({v})^{self.slope:.2g}"
            return text
        if self.slope is not None and abs(self.slope) >= 0.5:
            return (f"the error goes as ({v})^{self.slope:.2g} over the window (measured); "
                    f"cause not determined")
        return "cause not determined"

    def _near(self) -> bool:
        """Whether the window is written in the distance ``var`` (else in ``far_var``)."""
        return max(x for x in (self.worst_x, self.lo, self.hi) if x is not None) < FAR

    def where(self) -> str:
        """The window in words: its ends and its worst, in the variable the function takes
        (``|w|``) away from the singular point, in the distance to it near it."""
        near = self._near()
        v, (wx,) = self.approach.shown([self.worst_x], near)
        if self.lo is None or self.hi is None:
            return f"worst at {v} = {wx:.3g}"
        _, (lo, hi) = self.approach.shown([self.lo, self.hi], near)
        ends = sorted([(lo, self.lo_open, "the smallest sampled"),
                       (hi, self.hi_open, "the largest sampled")])
        a, b = (f"{x:.3g}" + (f" ({why})" if o else "") for x, o, why in ends)
        return f"over the bound for {a} < {v} < {b}, worst at {v} = {wx:.3g}"


def _q(x: float) -> fmpq:
    return P.q(x)


def approaches(kernel, seed: int) -> list[Approach]:
    """The approaches of ``kernel``'s arguments: a rotation's (or a transform's) toward the
    identity and toward a half turn from both sides, an unconstrained 3- or 6-vector's
    (its first block) toward 0, a rotation vector's toward pi from both sides, and the
    distance to each derived zero of a norm. Each draw takes a new axis and new other
    arguments (seeded by ``seed`` and the draw)."""

    cache: dict = {}

    def drawn(i: int, draw: int, n: int = 3):
        """(the other arguments, a unit n-vector, a random 3-vector) of ``draw``."""
        key = (i, draw, n)
        if key not in cache:
            rng = np.random.default_rng([seed + 11, i, draw])
            base = [P.random_arg(a, rng, kernel.name) for a in kernel.args]
            cache[key] = (base, P.unit(rng, n), [_q(v) for v in rng.standard_normal(3)])
        return cache[key]

    def put(i, value_of):
        def point(x, draw, i=i, value_of=value_of):
            base, e, d = drawn(i, draw)
            p = list(base)
            p[i] = value_of(x, e, d, base[i])
            return p
        return point

    out: list[Approach] = []
    for i, a in enumerate(kernel.args):
        if a.kind in ("rotation", "transform"):
            def wrap(Q, d, a=a):
                return P.transform(Q, d) if a.kind == "transform" else Q

            name = "Q" if a.kind == "rotation" else a.name
            out += [
                Approach(f"{name}: phi->0", "phi", put(i, lambda x, e, d, _, w=wrap: w(
                    P.rotation(e, _q(math.tan(x / 2)), fmpq(1)), d))),
                Approach(f"{name}: phi->pi-", "pi - phi", put(i, lambda x, e, d, _, w=wrap: w(
                    P.rotation(e, fmpq(1), _q(math.tan(x / 2))), d))),
                Approach(f"{name}: phi->pi+", "phi - pi", put(i, lambda x, e, d, _, w=wrap: w(
                    P.rotation(e, fmpq(1), _q(-math.tan(x / 2))), d)))]
        elif a.kind == "any" and a.shape in ((3,), (6,)) and a.name != "m":
            def vec(r, e, own):
                return [*(v * r for v in e), *own[3:]]

            out.append(Approach(f"|{a.name}[0:3]| -> 0", f"|{a.name}|",
                                put(i, lambda x, e, d, own, f=vec: f(_q(x), e, own))))
            if a.name in ("w", "xi"):
                n = f"|{a.name}|"
                out += [Approach(f"|{a.name}[0:3]| -> pi", f"pi - {n}",
                                 put(i, lambda x, e, d, own, f=vec: f(
                                     _q(math.pi * (1 - x)), e, own)), math.pi, n,
                                 lambda x: math.pi * (1 - x)),
                        Approach(f"|{a.name}[0:3]| -> pi", f"{n} - pi",
                                 put(i, lambda x, e, d, own, f=vec: f(
                                     _q(math.pi * (1 + x)), e, own)), math.pi, n,
                                 lambda x: math.pi * (1 + x))]
        elif a.kind == "angle":
            def ang(r):
                return [r]

            out += [Approach(f"|{a.name}| -> 0", f"|{a.name}|",
                             put(i, lambda x, e, d, _, f=ang: f(_q(x)))),
                    Approach(f"|{a.name}| -> pi", f"pi - |{a.name}|",
                             put(i, lambda x, e, d, _, f=ang: f(_q(math.pi * (1 - x)))),
                             math.pi, f"|{a.name}|", lambda x: math.pi * (1 - x))]
        elif a.kind == "unit" and a.shape == (4,):
            # a unit quaternion [r; r0] of the angle x toward the identity, pi - x toward a
            # half turn: exact (t = tan(x / 4), the axis a rational unit vector)
            def quat(x, e, half):
                t = _q(math.tan(x / 4))
                s, c = 2 * t / (1 + t * t), (1 - t * t) / (1 + t * t)
                if half:
                    s, c = c, s
                return [*(v * s for v in e), c]

            out += [Approach("eta: phi->0", "phi", put(i, lambda x, e, d, _, f=quat: f(
                        x, e, False))),
                    Approach("eta: phi->pi", "pi - phi", put(i, lambda x, e, d, _, f=quat: f(
                        x, e, True)))]
    return out + _derived(kernel, drawn)


def _derived(kernel, drawn) -> list[Approach]:
    """The approaches of :func:`approaches` to each derived zero of a norm (both sides),
    ``drawn`` its draws of the other arguments and directions."""
    from rigidsym.codegen.accuracy.singular_sets import norm_zeros

    out: list[Approach] = []
    seen = set()
    for z in norm_zeros(kernel):
        t0 = float(z.theta0)
        if (z.arg, z.comps, t0) in seen:
            continue
        seen.add((z.arg, z.comps, t0))
        arg = kernel.args[z.arg].name
        name = f"derived: |{arg}|->{P.sp_str(z.theta0)}"

        def at(x, draw, z=z, t0=t0, sign=1):
            base, _, _ = drawn(100 + z.arg, draw)
            _, d, _ = drawn(200 + z.arg, draw, len(z.comps))
            p = list(base)
            v = list(p[z.arg])
            r = _q(t0 + sign * x * max(t0, 1.0))
            for j, c in enumerate(z.comps):
                v[c] = r * d[j]
            p[z.arg] = v
            return p

        s0 = P.sp_str(z.theta0)
        sc = max(t0, 1.0)
        out += [Approach(name, f"{s0} - |{arg}|", lambda x, draw, f=at: f(x, draw, sign=-1),
                         sc, f"|{arg}|", lambda x, t0=t0, sc=sc: t0 - x * sc),
                Approach(name, f"|{arg}| - {s0}", lambda x, draw, f=at: f(x, draw, sign=1),
                         sc, f"|{arg}|", lambda x, t0=t0, sc=sc: t0 + x * sc)]
    return out


def _samples(rng) -> list[float]:
    """``x`` on a lattice of :data:`PER_DECADE` points a decade in ``log10 x`` from
    ``10**-DECADES`` to 1, shifted by a random offset: consecutive samples are a factor
    ``10 ** (1 / PER_DECADE)`` apart, so every interval wider than that holds one."""
    off = rng.uniform(0, 1 / PER_DECADE)
    return [10.0 ** (-DECADES + off + k / PER_DECADE) for k in range(DECADES * PER_DECADE)]


def _runs(over: list[bool]) -> list[tuple[int, int]]:
    """The runs ``(first, last)`` of lattice samples over the bound, two runs joined where
    at most :data:`GAP` samples within it lie between them."""
    out: list[list[int]] = []
    for k, o in enumerate(over):
        if not o:
            continue
        if out and k - out[-1][1] <= GAP + 1:
            out[-1][1] = k
        else:
            out.append([k, k])
    return [(a, b) for a, b in out]


def scan(ap: Approach, judge: Callable[[list, str], object], seed: int,
         screen: Callable[[list, str], np.ndarray] | None = None) -> Window:
    """The worst window of :func:`scan_all` (its first): the one over the bound with the
    largest error, else the worst input of an approach within the bound."""
    return scan_all(ap, judge, seed, screen)[0]


def scan_all(ap: Approach, judge: Callable[[list, str], object], seed: int,
             screen: Callable[[list, str], np.ndarray] | None = None) -> list[Window]:
    """Every window over the bound on ``ap`` (see the module), the worst first; where there
    is none, one :class:`Window` with the approach's worst input and no ends.

    ``judge(point, regime)`` returns a judgement with ``ratio`` (err over the bound; inf for
    a spurious flag) and ``flag``. ``screen(points, regime)``, where given, returns for the
    whole lattice at once (one call of the user's function per input, as its convention
    allows) the user's distance to rigidsym's kernel over ``8 u`` (inf where the user's
    output is not finite and the kernel's is, NaN where the kernel's is not finite): a
    sample is judged where that exceeds :data:`SCREEN` or is NaN, and at every
    :data:`COARSE`-th sample; elsewhere it is within the bound (its error is at most
    ``8 u`` past the kernel's, which meets the bound). Without ``screen`` every sample is
    judged. Each sample is a new draw of the approach (a new axis, new other arguments);
    the search around each window's worst sample keeps that sample's draw, the bisection
    of each end the draw of the sample inside it. The first window carries every
    judgement made (:attr:`Window.judged`); every window the count of them."""
    rng = np.random.default_rng(seed + 101)
    seen: dict[tuple[float, int], object] = {}

    def judged(x: float, draw: int) -> float:
        if (x, draw) not in seen:
            seen[(x, draw)] = judge(ap.point(x, draw), ap.regime)
        j = seen[(x, draw)]
        return j.ratio if j.flag != "expected" else 0.0

    def error(x: float, draw: int) -> float:
        judged(x, draw)
        j = seen[(x, draw)]
        return j.err if j.flag != "expected" else 0.0

    xs = _samples(rng)
    if screen is None:
        rs = [judged(x, k) for k, x in enumerate(xs)]
    else:
        pts = [ap.point(x, k) for k, x in enumerate(xs)]
        d = np.asarray(screen(pts, ap.regime), dtype=np.float64)
        rs = [judged(x, k) if (k % COARSE == 0 or not d[k] <= SCREEN) else 0.0
              for k, x in enumerate(xs)]
    runs = _runs([r > 1 for r in rs])
    runs.sort(key=lambda ab: -max(rs[ab[0]:ab[1] + 1]))
    if not runs:
        i = int(np.argmax(rs))
        wx, wr = _golden(xs, i, lambda x, i=i: judged(x, i))
        out = [Window(ap, wx, wr, seen[(wx, i)])]
    else:
        out = []
        for a, b in runs[:MAX_WINDOWS]:
            i = a + int(np.argmax(rs[a:b + 1]))
            if any(w.lo <= xs[i] <= w.hi for w in out):
                continue            # inside a worse window (as that one's draw gives it)
            wx, wr = _golden(xs, i, lambda x, i=i: judged(x, i))
            w = Window(ap, wx, wr, seen[(wx, i)])
            _ends(w, xs, rs, a, b, i, judged, error)
            out.append(w)
        for a, b in runs[MAX_WINDOWS:]:
            if any(w.lo <= xs[a] and xs[b] <= w.hi for w in out):
                continue
            # past the refined ones: the window as its samples give it, unrefined
            i = a + int(np.argmax(rs[a:b + 1]))
            w = Window(ap, xs[i], rs[i], seen[(xs[i], i)], lo=xs[a], hi=xs[b],
                       lo_open=a == 0, hi_open=b + 1 == len(xs))
            out.append(w)
        out = _merged(sorted(out, key=lambda w: -w.worst_ratio))
    for w in out:
        w.evaluations = len(seen)
    out[0].judged = sorted(((x, j) for (x, _), j in seen.items()), key=lambda t: t[0])
    return out


def _merged(ws: list[Window]) -> list[Window]:
    """Windows that overlap (each as its own worst's draw gives it) joined into one, the
    worst first: its worst the worse, its ends the outer ones, a jump kept only where it
    lies at one of them."""
    out: list[Window] = []
    for w in ws:
        m = next((m for m in out if w.lo <= m.hi and m.lo <= w.hi), None)
        if m is None:
            out.append(w)
            continue
        if w.lo < m.lo:
            m.lo, m.lo_open = w.lo, w.lo_open
        if w.hi > m.hi:
            m.hi, m.hi_open = w.hi, w.hi_open
        at_end = [j for j in (m.jump, w.jump) if j is not None and (
            j[0] <= m.lo * END_FACTOR ** 2 or j[0] >= m.hi / END_FACTOR ** 2)]
        m.jump = max(at_end, key=lambda j: j[1] / max(j[2], 1e-300), default=None)
    return out


def _golden(xs, i, r) -> tuple[float, float]:
    """``(x, ratio)`` of the largest error found by a golden-section search on ``log x``
    between sample ``i``'s neighbours, ``r`` the error on sample ``i``'s draw."""
    a = math.log(xs[i - 1] if i > 0 else xs[i] / 2)
    b = math.log(xs[i + 1] if i + 1 < len(xs) else min(1.0, xs[i] * 2))
    g = (math.sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    tried = [xs[i]]
    for _ in range(GOLDEN):
        tried += [math.exp(c), math.exp(d)]
        if not math.isfinite(r(math.exp(c))) and not math.isfinite(r(math.exp(d))):
            break
        if r(math.exp(c)) >= r(math.exp(d)):
            b, d = d, c
            c = b - g * (b - a)
        else:
            a, c = c, d
            d = a + g * (b - a)
    wx = max(tried, key=lambda x: (r(x), -abs(math.log(x / xs[i]))))
    return wx, r(wx)


def _ends(w: Window, xs, rs, lo_i: int, hi_i: int, i: int, judged, error) -> None:
    """The ends of the window of lattice samples ``lo_i..hi_i`` (over the bound at both),
    on the draw of its worst sample ``i``: the lattice re-judged on that draw out from
    each end, :data:`COARSE` samples a step, while over the bound (a defect of some draws
    only, the axis, is a window on each of them), then bisected to within
    :data:`END_FACTOR`; a jump of the error across an end, and the slope of the error over
    the window's samples. A jump is one of the error itself (``error(x, draw)``), not of
    its ratio to the bound alone: a flat error beside a bound that changes is no branch."""
    def r(x):
        return judged(x, i)

    def e(x):
        return error(x, i)

    def walk(k: int, step: int) -> int:
        """The last lattice index over the bound on draw ``i`` stepping from ``k``."""
        while 0 <= k + step < len(xs) and r(xs[k + step]) > 1:
            k += step
        return k

    lo_i = walk(walk(lo_i, -COARSE), -1)
    hi_i = walk(walk(hi_i, COARSE), 1)

    def bisect(k_in: int, k_out: int) -> tuple[float, float, Callable]:
        inside, outside = xs[k_in], xs[k_out]
        while max(inside, outside) / min(inside, outside) > END_FACTOR:
            m = math.sqrt(inside * outside)
            if r(m) > 1:
                inside = m
            else:
                outside = m
        return inside, outside, r

    w.lo_open, w.hi_open = lo_i == 0, hi_i + 1 == len(xs)
    ends = []
    if w.lo_open:
        w.lo = min(xs[0], w.worst_x)
    else:
        ins, out, r = bisect(lo_i, lo_i - 1)
        w.lo = min(ins, w.worst_x)
        ends.append((ins, out, r))
    if w.hi_open:
        w.hi = max(xs[-1], w.worst_x)
    else:
        ins, out, r = bisect(hi_i, hi_i + 1)
        w.hi = max(ins, w.worst_x)
        ends.append((ins, out, r))
    for ins, out, r in ends:
        if ins == out:
            continue
        step = ins / out                       # toward the inside
        a = [r(ins * step ** k) for k in range(3)]
        b = [r(out / step ** k) for k in range(3)]
        ea = [e(ins * step ** k) for k in range(3)]
        eb = [e(out / step ** k) for k in range(3)]
        if all(map(math.isfinite, b)) and min(a) >= JUMP * max(max(b), 1e-300) \
                and min(a) > 1 and min(ea) >= JUMP * max(eb):
            if w.jump is None or min(a) / max(b) > w.jump[1] / max(w.jump[2], 1e-300):
                w.jump = (math.sqrt(ins * out), min(a), max(b))
    inside = [(x, rr) for x, rr in zip(xs[lo_i:hi_i + 1], rs[lo_i:hi_i + 1], strict=True)
              if math.isfinite(rr) and rr > 1]
    if len(inside) >= 4:
        lx = np.log([x for x, _ in inside])
        ly = np.log([rr for _, rr in inside])
        fit = np.polyfit(lx, ly, 1)
        # a slope only where the samples lie on a line in log-log (within 1.3x rms):
        # an error of the rounding's luck scatters, and its fitted slope says nothing
        if float(np.sqrt(np.mean((np.polyval(fit, lx) - ly) ** 2))) < SCATTER:
            w.slope = float(fit[0])
