"""The worst input of a user's function, in its convention, against the book's truth.

The project's own search (:mod:`rigidsym.codegen.accuracy.harness`): the regimes of the
kernel (its derived singular sets, approaches log-spaced from 1e-1 to 1e-75 of each, the
ends of the floating range), each vector argument's approach to 0 and to exactly 0 (a
rotation vector's to pi), each approach searched continuously (:mod:`.windows`), then hill
climbing on ``err / (8 u (kappa + 1))`` from exponent-uniform starts. The user's output is
first moved to the member of its class of outputs of the same rotation nearest rigidsym's
kernel there (:mod:`.equivalence`). Each input is judged by the harness's judge against the declared
formula in ball arithmetic at the exact input (``reference``: narrower than 1e-3 ulp), the
condition half of the accuracy rule (``err <= 8 u (kappa + 1)``, the bound rigidsym's kernels
meet), with rigidsym's kernel judged at the same input beside it. A flag (NaN, inf or an
exception) is expected where the truth is undefined or the rounding of the input can reach
the singular set (``kappa u >= 1/8``), else it is a finding.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from rigidsym.auditing.conventions import Member, call_member, ordinary_points, to_numpy
from rigidsym.auditing.equivalence import nearest
from rigidsym.auditing.targets import Target
from rigidsym.codegen.accuracy import regimes as P
from rigidsym.codegen.accuracy.harness import judge as J
from rigidsym.codegen.accuracy.harness import reference as R
from rigidsym.codegen.accuracy.harness import search as S

__all__ = ["FIND", "extreme", "Runner", "Judged", "Behaviour", "audit_regimes", "judge_point",
           "condition_number", "rejudge", "WrongClass", "classify", "rotation_of", "WRONG",
           "sweep", "batch_dependence", "screen_points"]


#: an error is a finding at or past this many times the bound 8 u (kappa + 1), at inputs a
#: re-run confirms: below it (an error of 1.0x to 2x the bound) it is the rounding's luck
#: beside a bound that is itself a rule of thumb, not a defect a maintainer can act on
FIND = 2.0


#: a relative error (or a rotation off by this angle, radians) from which on an output is
#: wrong, not inaccurate
WRONG = 1e-3
#: the angle (radians) within which two rotations are one (a transposed output)
SAME = 1e-6
#: the angle (radians) within which an output is the truth's rotation to the rounding (an
#: output of another branch, w + 2 pi w/|w|, denotes it to a few ulps)
SAME_BRANCH = 1e-12


def extreme(regime: str) -> bool:
    """A regime at the ends of the floating range (``range 1e-300..1e300``, float32's
    ``range 1e-35..1e35``): what goes wrong there is a note of the report, not an error,
    and ranks after every other regime."""
    return regime.startswith("range ")


class Runner:
    """The harness's ``runner``: back-end ``"user"`` the user's function under ``member``
    row by row (an exception is a NaN row, recorded in :attr:`raised`), ``"kernel"``
    rigidsym's NumPy kernel."""

    def __init__(self, func: Callable, member: Member, tgt_kernel, tgt: Target | None = None):
        self.func, self.member, self.args = func, member, tgt_kernel.args
        self.raised: list[str] = []
        #: a function that returns some of the kernel's outputs (the Euler angles alone):
        #: the others are the kernel's, at the same input (judged beside the user's)
        self.tgt = tgt if tgt is not None and tgt.outputs else None
        self.equivalent = tgt.equivalent if tgt is not None else ""

    def __call__(self, name, arrays, dtype, backend) -> np.ndarray:
        if backend == "kernel":
            return J.run_kernel(name, arrays, dtype, "numpy")
        n = arrays[0].shape[0]
        rows = []
        for s in range(n):
            x = {a.name: np.asarray(arrays[j][s], dtype=np.float64)
                 for j, a in enumerate(self.args)}
            try:
                with np.errstate(all="ignore"):
                    rows.append(call_member(self.func, self.member, x, dtype))
            except Exception as e:  # noqa: BLE001  (the user's function raised: a flag)
                self.raised.append(f"{type(e).__name__}: {e}")
                rows.append(None)
        if self.equivalent:
            # an output of the same rotation is the same answer: moved to the member of its
            # class nearest rigidsym's kernel there (a few ulps from the truth)
            anchor = J.run_kernel(name, arrays, np.float64, "numpy")
            u = float(np.finfo(dtype).eps) / 2
            rows = [r if r is None else nearest(self.equivalent, r, anchor[s], u)
                    for s, r in enumerate(rows)]
        if self.tgt is not None:
            full = J.run_kernel(name, arrays, dtype, "numpy")
            sl = self.tgt.user_slice(R.kernel_of(name))
            for s, r in enumerate(rows):
                ok = r is not None and r.size == sl.stop - sl.start
                full[s, sl] = r if ok else np.nan
            return full
        size = max((r.size for r in rows if r is not None), default=1)
        return np.stack([r if r is not None and r.size == size else np.full(size, np.nan)
                         for r in rows])


def audit_regimes(kernel, dtype, seed: int) -> dict[str, list]:
    """The kernel's regimes (derived singular sets included) and, per unconstrained vector
    argument, its approach to 0 (log-spaced), exactly 0, and for a rotation vector (or the
    angular block of ``xi``) its approach to pi: ``{regime: [exact point]}``."""
    out = P.regimes(kernel, dtype, n_random=4, seed=seed, derived=True)
    rng = np.random.default_rng(seed + 1)
    small = P.STEPS32 if dtype == np.float32 else P.STEPS
    for i, a in enumerate(kernel.args):
        if a.kind != "any" or a.shape not in ((3,), (6,)):
            continue
        blk = slice(0, 3)

        def base():
            return [P.random_arg(b, rng, kernel.name) for b in kernel.args]

        for s in [*small, 0.0]:
            p = base()
            v = list(p[i])
            v[blk] = [x * P.q(s) for x in v[blk]]
            p[i] = v
            out.setdefault(f"|{a.name}[0:3]| -> 0" if s else f"{a.name}[0:3] = 0", []).append(p)
        if a.name in ("w", "xi"):
            for s in small[:12]:
                for sign in (-1, 1):
                    p = base()
                    e = P.unit(rng)
                    p[i] = [*(x * P.q(math.pi * (1 + sign * s)) for x in e), *p[i][3:]]
                    out.setdefault(f"|{a.name}[0:3]| -> pi", []).append(p)
    return out


@dataclass
class Judged:
    """One input judged: the user's function and rigidsym's kernel there."""

    regime: str
    point: list              # exact (fmpq) per argument
    ratio: float             # err / (8 u (kappa + 1)) of the user's function
    err: float               # its normwise relative error
    kappa: float
    kernel_ratio: float
    kernel_err: float
    flag: str = ""           # "", "expected", "NaN", "raises: ..."


@dataclass
class Behaviour:
    """Per regime: how the user's function behaved."""

    regime: str
    n: int = 0
    worst_ratio: float = 0.0
    worst_err: float = 0.0   # the largest normwise relative error met (finite outputs)
    kernel_worst_ratio: float = 0.0
    nan: int = 0             # non-finite where the truth is finite (a silent wrong)
    raised: int = 0          # exceptions where the truth is finite
    expected: int = 0        # flags (NaN or exceptions) where the truth is undefined
    over: int = 0            # inputs at or past FIND x the bound
    examples: list = field(default_factory=list)


def judge_point(name: str, regime: str, point, dtype, runner: Runner,
                antipodal: str = "") -> Judged:
    """The user's function and the kernel judged at one exact ``point`` (``antipodal``: the
    target's :attr:`~.targets.Target.antipodal`)."""
    before = len(runner.raised)
    user, kern = J.judge(name, regime, [point], dtype, ["user", "kernel"], runner=runner,
                         reference_half=False)
    raised = runner.raised[before:]
    flag, ratio = "", user.worst_ratio
    if user.spurious:
        flag, ratio = (f"raises {raised[0]}" if raised else "NaN"), math.inf
    elif user.flagged_expected:
        flag, ratio = _at_undefined(name, point, dtype, runner, before)
    err, kappa = user.err, user.kappa
    if not flag and user.beyond:
        # kappa u >= 1/8: the harness does not judge; the condition number is still the
        # problem's (never 0), and an error past 8 u (kappa + 1) is still wrong
        kappa = condition_number(name, point, dtype)
        if antipodal != "euler":
            ratio, err = _beyond(name, point, dtype, runner, antipodal, kappa)
    if antipodal == "euler":
        if not flag and (ratio > 1 or user.beyond):
            ratio, err = _euler_family(name, point, dtype, runner, ratio, err,
                                       bool(user.beyond))
    elif not flag and ratio > 1 and antipodal and not user.beyond:
        other = _antipodal(name, point, dtype, runner, kappa, antipodal)
        if other < ratio:       # the other sign's truth: its error is the one reported
            u = float(np.finfo(dtype).eps) / 2
            ratio, err = other, other * 8 * u * (kappa + 1)
    return Judged(regime, point, ratio, err, kappa, kern.worst_ratio, kern.err, flag)


def condition_number(name: str, point, dtype) -> float:
    """The condition number ``kappa`` of the declared formula at the exact ``point`` (the
    harness's: derivatives along each argument's tangent space, ball arithmetic), at least
    ``1 / (8 u)`` where the harness leaves the input unjudged (``kappa u >= 1/8``); inf where
    the formula is undefined there."""
    k = R.kernel_of(name)
    arrays = J.round_points([point], dtype, k)
    f = R.pick(name, [float(x) for a in arrays for x in a[0].ravel()])
    exact = [x for a in point for x in a]
    ref, prec = R.reference(f, exact)
    if ref is None:
        return math.inf
    from rigidsym.codegen.accuracy.harness.compare import kappa_of

    scale, norms = R.condition(name, f, point, [o.size for o in k.outputs], ref, prec)
    return kappa_of(scale, norms)


def _near_half_turn(truth: np.ndarray, kind: str) -> bool:
    """Whether the truth lies nearer a half turn than the identity, where its sign (of w,
    of the axis, of q) is what the input's rounding decides."""
    if kind == "rotation_vector":
        return float(np.linalg.norm(truth)) > math.pi / 2
    if kind == "axis":
        return abs(float(truth[3])) > math.pi / 2
    if kind == "quaternion":
        return abs(float(truth[3])) < math.sqrt(0.5)
    return False


def _beyond(name, point, dtype, runner, antipodal: str, kappa: float) -> tuple[float, float]:
    """``(ratio, err)`` at an input the harness leaves unjudged (``kappa u >= 1/8``): near a
    half turn the distance to the nearer of the truth and its other sign over 16 u (the sign
    is the rounding's, the magnitude and axis are not, :func:`_at_half_turn`); elsewhere the
    error over the bound ``8 u (kappa + 1)`` with the problem's own ``kappa`` (near the
    identity ``kappa ~ 1 / phi``: a flat error of 2e-14 at phi = 1e-16 is within it)."""
    truth, _ = truth_at(name, point, dtype)
    if truth is None or not np.linalg.norm(truth):
        return 0.0, 0.0
    if antipodal and _near_half_turn(truth, antipodal):
        return _at_half_turn(name, point, dtype, runner, antipodal)
    if not math.isfinite(kappa):
        return 0.0, 0.0
    arrays = J.round_points([point], dtype, R.kernel_of(name))
    mine = runner(name, arrays, dtype, "user")[0]
    if not np.isfinite(mine).all():
        return 0.0, 0.0
    u = float(np.finfo(dtype).eps) / 2
    err = float(np.linalg.norm(mine - truth)) / float(np.linalg.norm(truth))
    return err / (8 * u * (kappa + 1)), err


def _antipodal(name, point, dtype, runner, kappa, kind: str) -> float:
    """The ratio of the other sign's truth to the user's output where the truth is within
    16 u of a half turn: there the rounding of Q decides the sign (of w, of the axis e;
    vect(Q) is rounding noise), and both are the truth of a rotation within the input's
    rounding; a quaternion's sign anywhere (q and -q are the same rotation). ``kind``:
    :attr:`~.targets.Target.antipodal`."""
    truth, _ = truth_at(name, point, dtype)
    u = float(np.finfo(dtype).eps) / 2
    if truth is None:
        return math.inf
    other = -truth
    if kind == "rotation_vector":
        near = np.linalg.norm(truth) >= math.pi * (1 - 16 * u)
    elif kind == "quaternion":      # q and -q are the same rotation everywhere
        near = True
    else:                       # the axis and angle: [-e; phi]
        near = truth[3] >= math.pi * (1 - 16 * u)
        other = np.concatenate([-truth[:3], truth[3:]])
    if not near:
        return math.inf
    arrays = J.round_points([point], dtype, R.kernel_of(name))
    mine = runner(name, arrays, dtype, "user")[0]
    d = float(np.linalg.norm(mine - other)) / float(np.linalg.norm(truth))
    return d / (8 * u * (kappa + 1))


def euler_rotation(seq: str, angles) -> np.ndarray:
    """``Q = R_i(a) R_j(b) R_k(c)`` of the intrinsic ``seq`` (``"zyx"``) in float64: the
    rotation of a user's Euler angles (written here, apart from the kernels it judges)."""
    Q = np.eye(3)
    for ax, t in zip(seq.lower(), angles, strict=True):
        i = "xyz".index(ax)
        j, k = (i + 1) % 3, (i + 2) % 3
        R = np.eye(3)
        R[j, j], R[j, k], R[k, j], R[k, k] = math.cos(t), -math.sin(t), math.sin(t), math.cos(t)
        Q = Q @ R
    return Q


def _euler_family(name, point, dtype, runner, ratio, err, beyond) -> tuple[float, float]:
    """``(ratio, err)`` of Euler angles the rule calls wrong (or does not judge: ``beyond``,
    the input's rounding reaches the gimbal lock, ``kappa u >= 1/8``): the other branch's
    truth is as true; at the lock (the kernel's flag) or beyond, every member of the family
    is, and the rotation of the user's angles is judged against the truth's, over 16 u."""
    truth, _ = truth_at(name, point, dtype)
    if truth is None:
        return ratio, err
    arrays = J.round_points([point], dtype, R.kernel_of(name))
    mine = runner(name, arrays, dtype, "user")[0]
    if not np.isfinite(mine[:3]).all():
        return math.inf, math.inf
    u = float(np.finfo(dtype).eps) / 2
    cands = []
    if not beyond:
        cands.append((ratio, err))
        d = float(np.linalg.norm(mine[:3] - truth[3:6])) / max(
            float(np.linalg.norm(truth[3:6])), 1e-300)
        if err > 0:                  # the other branch (the same bound)
            cands.append((ratio * d / err, d))
    if truth[6] == 1 or beyond:
        seq = name.rsplit("_", 1)[-1]
        dq = float(np.linalg.norm(euler_rotation(seq, mine[:3]) - euler_rotation(
            seq, truth[:3]))) / math.sqrt(3)
        cands.append((dq / (16 * u), dq))
    return min(cands)


def _at_half_turn(name, point, dtype, runner, kind: str) -> tuple[float, float]:
    """``(ratio, err)`` of the user's output at a point the rule does not judge (the input's
    rounding reaches the sign's discontinuity): the distance to the nearer of the truth and
    its other sign, over 16 u."""
    truth, _ = truth_at(name, point, dtype)
    if truth is None or not np.linalg.norm(truth):
        return 0.0, 0.0
    other = (np.concatenate([-truth[:3], truth[3:]]) if kind == "axis" else -truth)
    arrays = J.round_points([point], dtype, R.kernel_of(name))
    mine = runner(name, arrays, dtype, "user")[0]
    if not np.isfinite(mine).all():
        return 0.0, 0.0
    u = float(np.finfo(dtype).eps) / 2
    d = min(float(np.linalg.norm(mine - truth)), float(np.linalg.norm(mine - other)))
    d /= float(np.linalg.norm(truth))
    return d / (16 * u), d


def _at_undefined(name, point, dtype, runner, before) -> tuple[str, float]:
    """Where the declared formula is undefined (a removable singularity, ``w = 0``) or the
    input's rounding reaches the singular set: a flag of the user's is expected, unless
    rigidsym's kernel gives the finite limit there; a finite value of the user's far from
    that limit is a finding too."""
    arrays = J.round_points([point], dtype, R.kernel_of(name))
    kern = runner(name, arrays, dtype, "kernel")[0]
    if not np.isfinite(kern).all():
        return "expected", 0.0
    mine = runner(name, arrays, dtype, "user")[0]
    if not np.isfinite(mine).all():
        raised = runner.raised[before:]
        why = f"raises {raised[-1]}" if raised else "NaN"
        return f"{why} where the limit is finite (rigidsym's kernel: finite)", math.inf
    u = float(np.finfo(dtype).eps) / 2
    d = float(np.linalg.norm(mine - kern)) / max(float(np.linalg.norm(kern)), 1e-300)
    return "", d / (8 * u)


def screen_points(name: str, points, dtype, runner: Runner) -> np.ndarray:
    """The user's distance to rigidsym's kernel at exact ``points`` (rounded to ``dtype``),
    over ``8 u`` of ``dtype``: the user's function called once per point through
    ``runner`` (its convention), the kernel once for all, in float64. Shape ``(n,)``; inf
    where the user's output is not finite and the kernel's is, NaN where the kernel's is
    not finite. A screen for :func:`.windows.scan_all`: where it is at most 1/2 the user's
    error is within ``4 u`` of the kernel's, which meets the bound ``8 u (kappa + 1)``."""
    k = R.kernel_of(name)
    arrays = J.round_points(points, dtype, k)
    before = len(runner.raised)
    mine = runner(name, arrays, dtype, "user")
    del runner.raised[before:]          # a flag here is judged (and recorded) at the input
    kern = J.run_kernel(name, [a.astype(np.float64) for a in arrays], np.float64, "numpy")
    u = float(np.finfo(dtype).eps) / 2
    out = np.full(len(points), np.nan)
    fin_k, fin_m = np.isfinite(kern).all(axis=1), np.isfinite(mine).all(axis=1)
    with np.errstate(all="ignore"):
        d = np.linalg.norm(mine - kern, axis=1) / np.maximum(
            np.linalg.norm(kern, axis=1), 1e-300) / (8 * u)
    out[fin_k & fin_m] = d[fin_k & fin_m]
    out[fin_k & ~fin_m] = np.inf
    return out


def sweep(tgt: Target, member: Member, func: Callable, dtype, seed: int = 0,
          n_start: int = 12, steps: int = 40, search: bool = True):
    """``(behaviours by regime, worst Judged, wrong outputs, windows)`` over the regimes,
    the approaches searched continuously (:mod:`.windows`: each a :class:`.windows.Window`)
    and the hill-climbing search, in ``dtype``; the wrong outputs ``{class:
    WrongClass}`` (:func:`classify`) of every input judged outside the ends of the
    floating range."""
    from rigidsym.auditing import windows as V

    name = member.kernel(tgt)
    k = R.kernel_of(name)
    runner = Runner(func, member, R.kernel_of(tgt.kernel), tgt)
    beh: dict[str, Behaviour] = {}
    worst: Judged | None = None
    regs = audit_regimes(k, dtype, seed)
    if search:
        ratio, pt = S.search(name, dtype, ("user",), seed=seed, n_start=n_start, steps=steps,
                             runner=runner, condition=True)
        if pt is not None:
            regs["search (hill climbing)"] = [pt]

    def judge(pt, regime):
        return judge_point(name, regime, pt, dtype, runner, tgt.antipodal)

    judged = [(regime, judge(pt, regime)) for regime, pts in regs.items() for pt in pts]
    def screen(pts, regime):
        return screen_points(name, pts, dtype, runner)

    windows = []
    if search:
        for ap in V.approaches(k, seed):
            ws = V.scan_all(ap, judge, seed, screen)
            windows += ws
            judged += [(ap.regime, j) for _, j in ws[0].judged]
    wrong: dict[str, WrongClass] = {}
    for regime, j in judged:
        if j.flag != "expected" and (j.flag or j.ratio >= FIND) and not extreme(regime):
            cls, off = classify(tgt, name, j, dtype, runner)
            c = wrong.setdefault(cls, WrongClass(cls))
            c.count += 1
            if c.worst is None or (off, j.ratio) > (c.off, c.worst.ratio):
                c.off, c.worst = off, j
        b = beh.setdefault(regime, Behaviour(regime))
        b.n += 1
        b.kernel_worst_ratio = max(b.kernel_worst_ratio, j.kernel_ratio)
        if j.flag == "expected":
            b.expected += 1
            continue
        if j.flag:
            b.raised += j.flag.startswith("raises")
            b.nan += j.flag.startswith("NaN")
            if len(b.examples) < 2:
                b.examples.append(j)
        b.worst_ratio = max(b.worst_ratio, j.ratio)
        if not j.flag and math.isfinite(j.err):
            b.worst_err = max(b.worst_err, j.err)
        b.over += int(j.ratio >= FIND)
        # the ends of the floating range rank after every other regime
        key = (not extreme(regime), j.ratio)
        if worst is None or key > (not extreme(worst.regime), worst.ratio):
            worst = j
    return beh, worst, wrong, windows


def rejudge(tgt: Target, member: Member, func: Callable, dtype, regime: str, seed: int,
            n_start: int = 12, steps: int = 40) -> float:
    """The worst ratio on ``regime`` judged anew with ``seed``: its points drawn again (new
    axes, new other arguments), the approach scanned again, or the hill-climbing search
    run again; 0 where ``seed`` gives the regime no input. What confirms (or not) an
    error met at one input alone."""
    from rigidsym.auditing import windows as V

    name = member.kernel(tgt)
    k = R.kernel_of(name)
    runner = Runner(func, member, R.kernel_of(tgt.kernel), tgt)

    def judge(pt, reg):
        return judge_point(name, reg, pt, dtype, runner, tgt.antipodal)

    if regime == "search (hill climbing)":
        _, pt = S.search(name, dtype, ("user",), seed=seed, n_start=n_start, steps=steps,
                         runner=runner, condition=True)
        pts = [] if pt is None else [pt]
    else:
        pts = audit_regimes(k, dtype, seed).get(regime, [])
    ratios = [j.ratio for j in map(lambda p: judge(p, regime), pts) if j.flag != "expected"]
    for ap in V.approaches(k, seed):
        if ap.regime == regime:
            def screen(ps, reg):
                return screen_points(name, ps, dtype, runner)
            ws = V.scan_all(ap, judge, seed, screen)
            ratios += [w.worst_ratio for w in ws]
    return max(ratios, default=0.0)


@dataclass
class WrongClass:
    """One class of wrong output the audit met (:func:`classify`): how many inputs, the
    largest ``off`` (the angle between the rotation returned and the truth's, radians,
    where the output denotes a rotation; else the relative error), and the worst input."""

    name: str
    count: int = 0
    off: float = 0.0
    worst: Judged | None = None


def _quat_rotation(q) -> np.ndarray:
    r, r0 = np.asarray(q[:3], dtype=np.float64), float(q[3])
    n = float(r @ r) + r0 * r0
    if n == 0:
        return np.full((3, 3), np.nan)
    R = np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])
    return np.eye(3) + (2 * r0 * R + 2 * R @ R) / n


def rotation_of(tgt: Target, name: str, v) -> np.ndarray | None:
    """The rotation (3 x 3) an output of ``tgt`` denotes, ``v`` flat in the book's layout (a
    row of :class:`Runner`'s, or the truth): a rotation matrix, a quaternion ``[r; r0]``,
    the natural invariants ``[e; phi]``, a rotation vector, Euler angles (their sequence
    from the kernel ``name``); None where the output is no rotation."""
    from rigidsym.auditing.equivalence import axis_angle_rotation

    v = np.asarray(v, dtype=np.float64)
    if not np.isfinite(v).all():
        return None
    if tgt.antipodal == "euler":
        sl = tgt.user_slice(R.kernel_of(name))
        return euler_rotation(name.rsplit("_", 1)[-1], v[sl][:3])
    if tgt.kind == "rotation" and v.size == 9:
        return v.reshape(3, 3)
    if tgt.equivalent == "quaternion" and v.size == 4:
        return _quat_rotation(v)
    if tgt.equivalent == "axis_angle" and v.size == 4:
        n = float(np.linalg.norm(v[:3]))
        return np.eye(3) if v[3] == 0 else (axis_angle_rotation(v[:3] / n, float(v[3]))
                                             if n else None)
    if tgt.antipodal == "rotation_vector" and v.size == 3:
        n = float(np.linalg.norm(v))
        return np.eye(3) if n == 0 else axis_angle_rotation(v / n, n)
    return None


def _angle(A: np.ndarray, B: np.ndarray) -> float:
    """The angle (radians) between two rotations, from ``|A - B|_F = 2 sqrt(2) sin(t/2)``."""
    return 2 * math.asin(min(1.0, float(np.linalg.norm(A - B)) / (2 * math.sqrt(2))))


def classify(tgt: Target, name: str, j: Judged, dtype, runner: Runner) -> tuple[str, float]:
    """``(class, off)`` of a wrong output at the judged input ``j`` (a flag, or an error at
    or past :data:`FIND` x the bound): "exception", "NaN/inf"; where the output denotes a
    rotation, "conjugate" (a quaternion's), "transposed" (a matrix's) or "inverse rotation"
    (another's) where it is the truth's inverse, "wrong branch" where it is the truth's
    rotation but not the book's output (``w + 2 pi w/|w|``), "wrong rotation" off by
    :data:`WRONG` rad or more; else "wrong value" (relative error WRONG or more) or
    "inaccurate". ``off``: the angle between the rotations (radians), else the relative
    error."""
    if j.flag.startswith("raises"):
        return "exception", math.inf
    if j.flag:
        return "NaN/inf", math.inf
    arrays = J.round_points([j.point], dtype, R.kernel_of(name))
    mine = runner(name, arrays, dtype, "user")[0]
    if not np.isfinite(mine).all():
        return "NaN/inf", math.inf
    truth, _ = truth_at(name, j.point, dtype)
    Rm = rotation_of(tgt, name, mine)
    Rt = None if truth is None else rotation_of(tgt, name, truth)
    if Rm is None or Rt is None:
        return ("wrong value" if j.err >= WRONG else "inaccurate"), j.err
    off, inv = _angle(Rm, Rt), _angle(Rm, Rt.T)
    if off <= SAME_BRANCH and _angle(Rt, np.eye(3)) >= SAME:
        # the truth's rotation to the rounding, another output: w + 2 pi w/|w| (near the
        # identity an axis is nearly free and a wrong one is no branch: a wrong value)
        return ("wrong branch" if j.err >= WRONG else "inaccurate"), j.err
    if inv <= SAME and _angle(Rt, Rt.T) >= WRONG:     # the inverse told from the rotation
        return ("conjugate" if tgt.equivalent == "quaternion" else "transposed"
                if tgt.kind == "rotation" else "inverse rotation"), off
    if off >= WRONG:
        return "wrong rotation", off
    # a rotation near the truth's, an output far from the book's (an axis near the identity)
    return ("wrong value" if j.err >= WRONG else "inaccurate"), j.err


def truth_at(name: str, point, dtype) -> tuple[np.ndarray | None, list[np.ndarray]]:
    """``(truth at the input as rounded to dtype, the rounded arguments)`` at an exact
    point; where the declared formula is undefined there (a removable singularity, ``w =
    0``) the limit, as rigidsym's kernel gives it (None where that is not finite either)."""
    k = R.kernel_of(name)
    arrays = J.round_points([point], dtype, k)
    flat_in = [float(x) for a in arrays for x in a[0].ravel()]
    f = R.pick(name, flat_in)
    ref = R.reference(f, [P.q(x) for x in flat_in])[0]
    if ref is None:
        lim = J.run_kernel(name, [a.astype(np.float64) for a in arrays], np.float64,
                           "numpy")[0]
        ref = lim if np.isfinite(lim).all() else None
    return ref, [a[0] for a in arrays]


#: a batched row that differs from the row alone by this much (relative) or more
#: disagrees: at ordinary inputs (kappa of a few) it is far past any rounding
DISAGREE = 1e-8


def _same_rotations(tgt: Target, pairs: list) -> bool:
    """Each pair ``(batched row, row alone)`` denotes one rotation (within :data:`SAME`)."""
    for b, r in pairs:
        Rb, Rr = rotation_of(tgt, tgt.kernel, b), rotation_of(tgt, tgt.kernel, r)
        if Rb is None or Rr is None or not _angle(Rb, Rr) <= SAME:
            return False
    return True


def batch_dependence(func: Callable, member: Member, tgt_kernel, rng,
                     tgt: Target | None = None) -> str:
    """Whether the function takes a batch in its form and, if so, whether a row alone and
    the same row in a batch agree bit for bit; where they differ by :data:`DISAGREE` or
    more (relative), "disagrees", with what the batched rows are against the rows alone
    where ``tgt``'s output denotes a rotation (the conjugate, the transpose)."""
    pts = ordinary_points(tgt_kernel, 8, rng)
    rows = [call_member(func, member, x) for x in pts]
    args = [member.user_args(x) for x in pts]
    try:
        with np.errstate(all="ignore"):
            out = func(*[np.stack([np.asarray(a[j], dtype=np.float64) for a in args])
                         for j in range(len(args[0]))])
        # each output batched along its first axis: a row is each output's row, in turn
        # (a tuple (axes, angles) is (n, 3) and (n,), not one array of n rows)
        outs = out if isinstance(out, (tuple, list)) else [out]
        outs = [to_numpy(o) for o in outs]
        if not all(o.ndim and o.shape[0] == len(pts) for o in outs):
            return "not batched (one input at a time)"
        per = [np.concatenate([np.ravel(o[i]) for o in outs]) for i in range(len(pts))]
    except Exception:  # noqa: BLE001  (not batched: one input at a time)
        return "not batched (one input at a time)"
    if any(p.size != rows[0].size for p in per):
        return "not batched (one input at a time)"
    batched = [member.book_out(per[i]) for i in range(len(pts))]
    diffs = [float(np.max(np.abs(b - r))) for b, r in zip(batched, rows, strict=True)]
    worst = max(diffs)
    rel = max(float(np.linalg.norm(b - r)) / max(float(np.linalg.norm(r)), 1e-300)
              for b, r in zip(batched, rows, strict=True))
    if not rel >= DISAGREE:
        return ("batched; each row equal bit for bit to the row alone" if worst == 0 else
                f"batched; a row in the batch differs from the row alone by up to "
                f"{worst:.3g}")
    apart = [(b, r) for b, r in zip(batched, rows, strict=True)
             if not np.linalg.norm(b - r) < DISAGREE * np.linalg.norm(r)]
    off = len(apart)
    if tgt is not None and tgt.equivalent and _same_rotations(tgt, apart):
        return (f"batched; a row in the batch differs from the row alone at {off} of "
                f"{len(pts)} ordinary inputs: another member of its class, the same "
                f"rotation ({tgt.equivalent})")
    what = ""
    if tgt is not None:
        name = tgt.kernel
        kinds = set()
        for b, r in zip(batched, rows, strict=True):
            Rb, Rr = rotation_of(tgt, name, b), rotation_of(tgt, name, r)
            if Rb is None or Rr is None:
                kinds.add("")
            elif _angle(Rb, Rr.T) <= SAME < _angle(Rb, Rr):
                kinds.add("conjugate" if tgt.equivalent == "quaternion" else
                          "transpose" if tgt.kind == "rotation" else "inverse")
            elif _angle(Rb, Rr) > SAME:
                kinds.add("other rotation")
        if len(kinds) == 1 and "" not in kinds:
            what = f": the batched path returns the {kinds.pop()} of the row alone's"
    return (f"batched; the batched path disagrees with the row alone at {off} of "
            f"{len(pts)} ordinary inputs, by up to {rel:.3g} (relative){what}")
