"""``rigidsym.audit``: judge any function that claims to compute an operation of the chapter.

The function is called under every member of its target's convention product
(:mod:`.conventions`), then, in the convention found, swept over the kernel's singular sets
and the worst-input search (:mod:`.worst`) against the declared formula's truth; what it
gets wrong is collected as findings (:class:`Finding`) in an :class:`AuditReport`, which
:mod:`.report` writes as text, JSON, Markdown or a regression test.
"""

from __future__ import annotations

import functools
import time
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np

from rigidsym.auditing import conventions as C
from rigidsym.auditing import worst as W
from rigidsym.auditing.callables import as_numpy_callable, parameter_names
from rigidsym.auditing.targets import Target, target
from rigidsym.auditing.worst import extreme
from rigidsym.codegen.accuracy.harness import judge as J
from rigidsym.codegen.accuracy.harness import reference as R
from rigidsym.core.errors import BadInput

__all__ = ["audit", "AuditReport", "Finding", "WorstInput"]



@dataclass
class Finding:
    """One thing the function gets wrong: ``severity`` "error" (a silent wrong, an
    inaccuracy past the rule, a broken invariant, no convention) or "note"."""

    severity: str
    kind: str
    text: str


@dataclass
class WorstInput:
    """The worst input found in one float type, in the user's convention."""

    dtype: str
    regime: str
    ratio: float               # err / (8 u (kappa + 1))
    err_u: float               # normwise relative error, in units of u
    kappa: float
    kernel_err_u: float        # rigidsym's kernel at the same input
    flag: str
    args: list                 # the user's arguments (float arrays, as rounded)
    truth: list | None         # the truth, flat, in the user's layout
    got: list | None           # the user's output, flat, in the user's layout
    peers: dict = field(default_factory=dict)   # peer label -> err in u (float64)


@dataclass
class AuditReport:
    """What :func:`audit` found. ``ok``: no finding of severity "error"."""

    function: str
    target: str
    book: str
    tried: int
    convention: str | None
    generators: list
    residual: float
    nearest: str | None
    invariants_broken: list
    behaviour: dict            # dtype -> [per-regime dict]
    worst: list                # [WorstInput]
    batch: str
    findings: list             # [Finding]
    seconds: float
    spec: str = ""             # module:function, for a regression test
    form: str = ""
    versions: dict = field(default_factory=dict)   # the function's library and NumPy
    equivalent: str = ""       # the output's class of outputs of the same rotation, or ""
    windows: dict = field(default_factory=dict)    # dtype -> [window over the bound]
    keywords: dict = field(default_factory=dict)   # the flags it is called with (twist=True)
    wrong: dict = field(default_factory=dict)      # dtype -> [class of wrong output met]
    framework: str = ""        # the array framework it takes ("torch"), or "" (NumPy)
    gradients: dict = field(default_factory=dict)  # the derivative's audit, where it has one

    @property
    def ok(self) -> bool:
        """No finding of severity "error"."""
        return not any(f.severity == "error" for f in self.findings)


def versions(func: Callable, spec: str = "") -> dict:
    """``{distribution: version}`` of the library ``func`` comes from (its top-level
    package, where it says) and of NumPy."""
    from importlib import metadata

    out = {}
    mod = spec.partition(":")[0] or getattr(getattr(func, "__wrapped__", func),
                                            "__module__", "") or ""
    top = mod.split(".")[0]
    if top and top not in ("__main__", "builtins"):
        try:
            out[top] = metadata.version(top)
        except metadata.PackageNotFoundError:
            import sys

            v = getattr(sys.modules.get(top), "__version__", None)
            if isinstance(v, str):
                out[top] = v
    out["numpy"] = np.__version__
    return out


def _truth(tgt: Target, points: list[dict]) -> dict:
    k = R.kernel_of(tgt.kernel)
    arrays = [np.stack([p[a.name] for p in points]) for a in k.args]
    names = {tgt.kernel, tgt.dual, *tgt.family} - {""}
    with np.errstate(all="ignore"):
        return {name: list(J.run_kernel(name, arrays, np.float64, "numpy")) for name in names}


def _find(func, tgt, names, seed) -> C.Found:
    rng = np.random.default_rng(seed)
    pts = C.ordinary_points(R.kernel_of(tgt.kernel), 8, rng)
    found = C.find(func, tgt, pts, _truth(tgt, pts), names)
    if found.nearest is None:      # every member raised: a wrong signature, or a bad function
        why = "; ".join(f"as {k}: {v}" for k, v in found.errors.items())
        raise BadInput(f"function raises on ordinary inputs under every form of "
                       f"{tgt.name} ({why})")
    return found


def _worst_input(tgt, member, j: W.Judged, dtype) -> WorstInput:
    name = member.kernel(tgt)
    truth, rounded = W.truth_at(name, j.point, dtype)
    x = {a.name: np.asarray(v, dtype=np.float64) for a, v in
         zip(R.kernel_of(tgt.kernel).args, rounded, strict=True)}
    args = [np.asarray(a, dtype=dtype) for a in member.user_args(x)]
    u = float(np.finfo(dtype).eps) / 2
    sl = tgt.user_slice(R.kernel_of(name))
    w = WorstInput(np.dtype(dtype).name, j.regime, j.ratio, j.err / u, j.kappa,
                   j.kernel_err / u, j.flag, [a.tolist() for a in args],
                   None if truth is None else member.user_out(truth[sl]).tolist(), None)
    return w


def _peers(tgt, member, w: WorstInput, x_arrays, truth) -> dict:
    from rigidsym.codegen.accuracy.harness import yardsticks as O

    if truth is None:
        return {}
    name = member.kernel(tgt)
    out = {}
    for label, row in O.evaluate(name, x_arrays, len(truth)).items():
        v = row[0]
        if np.isfinite(v).all():
            out[label] = float(np.linalg.norm(v - truth) / max(np.linalg.norm(truth),
                                                               1e-300) / 2.0**-53)
    return out


def _flag_cause(regime: str, rows: dict, wins: list) -> str:
    """A flag's cause where the sweep measured it: a flag at exactly 0 whose approach to 0
    (down to 1e-75) is finite is the lack of a guard for exactly 0; a flag one ulp past
    +-1 alone, an inverse sine or cosine with no clamp; on an approach, the window where it
    happens (:func:`_window_cause`); else not determined."""
    if regime == "gimbal lock, +-1 rounded past":
        lock = rows.get("gimbal lock")
        if lock is not None and lock.n and not lock.nan and not lock.raised:
            return (" - a flag only where an entry of Q is rounded one ulp past +-1 (none at "
                    "the lock itself): the entry taken by an inverse sine or cosine with no "
                    "clamp")
        return " - cause not determined"
    if regime == "Q=1":
        approach = "Q: phi->0"
    elif regime.endswith(" = 0"):
        approach = f"|{regime[:-4]}| -> 0"
    else:
        return _window_cause(regime, wins)
    near = rows.get(approach)
    if near is not None and near.n and not near.nan and not near.raised:
        return (" - finite on the approach to it (down to 1e-75), a flag at exactly 0 "
                "alone: no guard for exactly 0")
    return " - cause not determined"


def _window_cause(regime: str, wins: list) -> str:
    """Every window over the bound on ``regime``'s approaches, the worst first: where it is
    (its ends and its worst), and the worst's cause as measured
    (:meth:`.windows.Window.cause`)."""
    over = sorted((w for w in wins if w.approach.regime == regime and
                   w.worst_ratio >= W.FIND),
                  key=lambda w: -w.worst_ratio)
    if not over:
        return " - cause not determined"
    w = over[0]
    also = "".join(f"; also {v.where()} ({v.worst_ratio:.3g} x the bound)" for v in over[1:4])
    if len(over) > 4:
        also += f"; and {len(over) - 4} more windows (the JSON report lists them)"
    return f" - {w.where()}; {w.cause()}{also}"


def _window(w) -> dict:
    """A window over the bound as plain data (JSON)."""
    return {"regime": w.approach.regime, "var": w.approach.var, "lo": w.lo, "hi": w.hi,
            "worst_x": w.worst_x, "worst_ratio": w.worst_ratio, "where": w.where(),
            "cause": w.cause(), "evaluations": w.evaluations}


def _judged_anyway(found: C.Found) -> bool:
    """No member matches at every input, but the nearest returns the book's kind of output
    (a finite residual): its accuracy is searched and judged all the same, reported beside
    the convention (what it gets wrong may be the reason)."""
    return found.member is None and found.nearest is not None and bool(
        np.isfinite(found.residual))


def _no_member(found: C.Found, tgt) -> str:
    """Where no member matches at every input: how many match under the nearest, how many
    under each other member, and how the rest differ."""
    n = found.nearest.says(tgt)
    if not found.agree and not found.also:
        return f"no input matches under any; the nearest, {n}, differs {found.differ}"
    parts = [f"{found.agree} of {found.n} inputs match the book's under the nearest, {n}"]
    parts += [f"{c} more under {m.says(tgt)}" for m, c in found.also]
    left = found.n - found.agree - sum(c for _, c in found.also)
    if left:
        parts.append(f"the other {left} differ {found.differ}")
    return "; ".join(parts)


def _float32_values(call, found: C.Found, point: dict) -> bool:
    """Whether the nearest member's outputs at ``point`` (an ordinary input, float64) are
    each a float32 value: the function computes in float32 (a JAX function without x64),
    measured, not guessed from the size of the residual."""
    try:
        out = C.call_member(call, found.nearest, point)
    except Exception:  # noqa: BLE001  (raised at the point: nothing measured)
        return False
    out = np.asarray(out, dtype=np.float64)
    return bool(out.size and np.isfinite(out).all()
                and (out.astype(np.float32).astype(np.float64) == out).all()
                and (out != np.round(out)).any())


def _findings(found: C.Found, tgt, beh: dict, wins: dict, batch: str,
              single: bool = False, confirm: dict | None = None) -> list[Finding]:
    out = []
    if found.member is None:
        agree = _no_member(found, tgt)
        out.append(Finding("error", "convention", f"no member of {found.tried} matches the "
                           f"book's {tgt.name} at every input: {agree} (residual "
                           f"{found.residual:.3g}, relative)" + (
                               "; its outputs are float32 values (each rounds to itself in "
                               "float32): it computes in float32 (JAX without x64?)"
                               if single else "")
                           + ("; the accuracy below is judged under the nearest"
                              if _judged_anyway(found) else "")))
    for b in found.broken:
        out.append(Finding("error", "invariant", b))
    m = found.member
    if m is not None and "inverse" in m.generators and found.broken and tgt.kind == "wrench":
        out.append(Finding("error", "convention", "maps wrenches by Ad_T^T where the book's "
                           "Ad_T^-T is due (the transfer of T^-1): with twists mapped by Ad_T "
                           "the power is not invariant"))
    if found.member is not None and "dual" in found.member.generators:
        out.append(Finding("error", "convention", f"computes {tgt.dual}, not {tgt.name}"))
    for dt, rows in beh.items():
        for b in rows.values():
            sev = "note" if extreme(b.regime) else "error"
            ex = b.examples[0].flag if b.examples else ""
            if b.nan or b.raised:
                out.append(Finding(sev, "flag", f"{dt}, {b.regime}: {b.nan} NaN/inf and "
                                   f"{b.raised} exceptions of {b.n} inputs where the truth is "
                                   f"finite ({ex})" + _flag_cause(b.regime, rows, wins.get(
                                       dt, []))))
            again = (confirm or {}).get((dt, b.regime))
            if np.isfinite(b.worst_ratio) and b.worst_ratio >= W.FIND and again is not None \
                    and not again >= W.FIND:
                out.append(Finding("note", "unconfirmed", f"{dt}, {b.regime}: one input at "
                                   f"{b.worst_ratio:.3g} x the bound; a re-run with another "
                                   f"seed met {again:.3g} x at most there: not confirmed, "
                                   f"not a finding"))
            elif np.isfinite(b.worst_ratio) and b.worst_ratio >= W.FIND:
                # wrong past 0.1 % of its size: a wrong value, whatever kappa allows
                kind = "silent wrong" if b.worst_err > 1e-3 else "inaccurate"
                out.append(Finding(sev, kind, f"{dt}, {b.regime}: error {b.worst_ratio:.3g} "
                                   f"x the bound 8 u (kappa + 1) (rigidsym's kernel: "
                                   f"{b.kernel_worst_ratio:.2g} x)" +
                                   _window_cause(b.regime, wins.get(dt, []))))
    if "disagrees" in batch:
        out.append(Finding("error", "batch", batch))
    elif "differs" in batch:
        out.append(Finding("note", "batch", batch))
    return out


def audit(func: Callable, as_: str, *, names: Sequence[str] | None = None, seed: int = 0,
          dtypes: Sequence[str] = ("float64",), search: bool = True, n_start: int = 12,
          steps: int = 40, spec: str = "", gradients: bool = True) -> AuditReport:
    """Audit ``func`` as the operation ``as_`` of the chapter.

    Finds the convention ``func`` implements (its argument layout and the member of the
    target's convention product, or none with the nearest and at how many inputs it
    matches), the invariants it breaks, its behaviour on each singular set of the book's
    formula (NaN, inf, exceptions), its worst input (the kernel's regimes, each approach
    searched continuously and a hill-climbing search on ``err / (8 u (kappa + 1))``)
    against the declared formula's truth in ball arithmetic, an output of the same
    rotation judged as the same answer, rigidsym's kernel and each installed peer at that
    input, the cause of each window of error where it is measured, and whether a row
    depends on its batch.

    Args:
        func: the function (NumPy; PyTorch or JAX: called with tensors where NumPy
            arrays raise; a C function: ``rigidsym.auditing.callables.c_function``).
        as_: the operation (``twist_transfer``, ``wrench_transfer``,
            ``rotation_vector_from_rotation``, ...: ``rigidsym.auditing.targets.TARGETS``).
        names: the function's positional parameter names (default: read from ``func``),
            which put the argument layouts that fit them first.
        seed: the seed of the random inputs, the regimes and the search.
        dtypes: the float types swept (``"float64"``, ``"float32"``).
        search: run the continuous search of each approach and the hill-climbing search
            besides the regimes.
        n_start, steps: the search's random starts and climbing steps.
        spec: ``module:function`` (written into a regression test).
        gradients: audit the derivative too where the function is differentiable in
            PyTorch or JAX (:mod:`.gradients`): a wrong gradient behind a right value.

    Returns:
        An :class:`AuditReport` (``ok`` False where there is a finding of severity error).

    Raises:
        BadInput: an operation that does not exist; a function that raises on ordinary
            inputs under every argument layout (a wrong signature); a float type other
            than float64 and float32.
    """
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        # the user's function and the reference at the ends of the floating range overflow
        # by design there: the report says what came of it, the warnings would not
        warnings.simplefilter("ignore", RuntimeWarning)
        return _audit(func, as_, names, seed, dtypes, search, n_start, steps, spec,
                      gradients)


def _gradients(func, tgt, m, framework: str, seed: int, point: dict) -> dict:
    """The derivative audited (:mod:`.gradients`) where the function is differentiable in a
    framework it already uses (PyTorch where it takes tensors; JAX where JAX is imported):
    ``{framework, checked, wrong: [{regime, err, tol, args}]}``, or {} where it is not."""
    import sys

    from rigidsym.auditing import gradients as D

    tried = framework or ("jax" if "jax" in sys.modules else "")
    if not tried:
        return {}
    lib = D.differentiable(func, m.user_args(point), tried)
    if not lib:
        return {}
    checks = D.check_gradients(func, tgt, m, lib, D.gradient_points(tgt, m, seed))
    wrong = [vars(c) for c in checks if not c.err <= c.tol]
    return {"framework": lib, "checked": len(checks), "wrong": wrong}


def _gradient_finding(g: dict) -> Finding:
    """The wrong derivatives as one finding: how many inputs, how far off, where."""
    wrong = g["wrong"]
    nan = sum(1 for c in wrong if not np.isfinite(c["err"]))
    fin = [c["err"] for c in wrong if np.isfinite(c["err"])]
    worst = max(wrong, key=lambda c: c["err"])
    regimes = ", ".join(dict.fromkeys(c["regime"] for c in wrong))
    return Finding("error", "gradient", f"its {g['framework']} derivative is wrong at "
                   f"{len(wrong)} of {g['checked']} inputs where the value is right "
                   f"(against the book's, along each tangent direction: "
                   + (f"NaN/inf at {nan}" if nan else "")
                   + ("; " if nan and fin else "")
                   + (f"relative error up to {max(fin):.3g}, past sqrt(u) = "
                      f"{worst['tol']:.2g}" if fin else "")
                   + f"); at: {regimes}")


def _audit(func, as_, names, seed, dtypes, search, n_start, steps, spec,
           gradients=True) -> AuditReport:
    t0 = time.perf_counter()
    tgt = target(as_)
    for d in dtypes:
        if d not in ("float64", "float32"):
            raise BadInput(f"dtypes: {d!r}: expected float64 or float32")
    fname = getattr(func, "__qualname__", getattr(func, "__name__", repr(func)))
    # the output's kind first: a 3 x 3 where the book's is 3 values is said as such, with
    # the flag of its own that gives the book's kind (then audited with it) or the wrapper
    point = C.ordinary_points(R.kernel_of(tgt.kernel), 1, np.random.default_rng(seed + 5))
    kind = C.output_kind(as_numpy_callable(func), tgt, point[0])
    keywords = kind.keywords if kind is not None else {}
    if kind is not None and not keywords:
        return AuditReport(fname, tgt.name, tgt.book, 0, None, [], np.inf, None, [], {}, [],
                           "", [Finding("error", "output", kind.says)],
                           time.perf_counter() - t0, spec, "", versions(func, spec),
                           tgt.equivalent)
    call = as_numpy_callable(functools.partial(func, **keywords) if keywords else func)
    found = _find(call, tgt, tuple(names) if names else parameter_names(func), seed)
    beh, worst, batch, wins, confirm, undefined, sign = {}, [], "", {}, {}, None, ""
    wrong: dict = {}
    m = found.member
    if m is None and _judged_anyway(found):
        m = found.nearest
    if m is not None:
        for d in dtypes:
            dt = np.dtype(d).type
            b, j, bad, win = W.sweep(tgt, m, call, dt, seed, n_start, steps, search)
            beh[d] = b
            wrong[d] = [_wrong(tgt, m, c, dt) for c in sorted(
                bad.values(), key=lambda c: (-c.count, c.name))]
            wins[d] = win
            if j is not None:
                w = _worst_input(tgt, m, j, dt)
                if dt == np.float64:
                    truth, rounded = W.truth_at(m.kernel(tgt), j.point, dt)
                    w.peers = {} if tgt.outputs else _peers(tgt, m, w, [r[None] for r in
                                                                       rounded], truth)
                    try:
                        w.got = m.user_out(W.call_member(call, m, {
                            a.name: r for a, r in zip(R.kernel_of(tgt.kernel).args, rounded,
                                                      strict=True)})).tolist()
                    except Exception:  # noqa: BLE001  (it raised there: the flag says so)
                        w.got = None
                worst.append(w)
        batch = W.batch_dependence(call, m, R.kernel_of(tgt.kernel),
                                   np.random.default_rng(seed + 2), tgt)
        confirm = _confirmations(call, tgt, m, beh, seed, n_start, steps, search)
        undefined = _undefined_axis(call, tgt, m)
        sign = _sign_convention(call, tgt, m, seed)
    single = found.member is None and found.nearest is not None and _float32_values(
        call, found, point[0])
    rep = AuditReport(fname, tgt.name, tgt.book, found.tried,
                      m.says(tgt) + (f"; {sign}" if sign else "") if found.member else None,
                      list(m.generators) if m else [],
                      found.residual, found.nearest.says(tgt) if found.nearest else None,
                      found.broken, {d: [vars(b) | {"examples": [e.flag for e in b.examples]}
                                         for b in rows.values()] for d, rows in beh.items()},
                      worst, batch, _findings(found, tgt, beh, wins, batch, single, confirm),
                      time.perf_counter() - t0, spec, m.form.label if m else "",
                      versions(func, spec), tgt.equivalent,
                      {d: [_window(w) for w in ws if w.worst_ratio >= W.FIND]
                       for d, ws in wins.items()}, keywords)
    if kind is not None:
        rep.findings.insert(0, Finding("note", "output", kind.says))
    rep.wrong = wrong
    rep.framework = getattr(call, "framework", "")
    return _told_all(rep, functools.partial(func, **keywords) if keywords else func, tgt, m,
                     (seed, point[0]) if gradients else None, undefined, sign)


def _told_all(rep: AuditReport, func, tgt, m, gradients, undefined, sign) -> AuditReport:
    """The rest of an audit's report: the gradients checked (``gradients``: ``(seed,
    point)``, or ``None``), the framework's version, each wrong output told, an undefined
    axis and the library's sign convention as findings."""
    if m is not None and gradients is not None:
        rep.gradients = _gradients(func, tgt, m, rep.framework, *gradients)
        if rep.gradients.get("wrong"):
            rep.findings.append(_gradient_finding(rep.gradients))
    if rep.framework:
        from rigidsym.auditing.callables import framework_version

        rep.versions[rep.framework] = framework_version(rep.framework) or "not known"
    told = _told(rep.wrong)
    if told is not None:
        rep.findings.append(told)
    if undefined is not None:
        rep.findings.append(undefined)
    if sign:
        rep.findings.append(Finding("note", "sign convention", sign))
    return rep


def _sign_convention(call, tgt, m, seed: int) -> str:
    """The sign the function gives an output whose negation is the same rotation, in words,
    where it is not the book's (``r0 >= 0`` of a quaternion, ``phi >= 0`` of the natural
    invariants), measured at 16 ordinary inputs before any output is moved onto its class:
    "" where it is the book's at each."""
    if tgt.equivalent not in ("quaternion", "axis_angle") or "negated_out" in m.generators:
        return ""
    rng = np.random.default_rng(seed + 17)
    pts = C.ordinary_points(R.kernel_of(tgt.kernel), 16, rng)
    truth = _truth(tgt, pts)[m.kernel(tgt)]
    other = 0
    for x, t in zip(pts, truth, strict=True):
        try:
            got = C.call_member(call, m, x)
        except Exception:  # noqa: BLE001  (it raises there: the flags say so)
            return ""
        if got.shape != t.shape or not np.isfinite(got).all():
            return ""
        if tgt.equivalent == "quaternion":
            other += bool(np.linalg.norm(got + t) < np.linalg.norm(got - t))
        else:
            other += bool(got[3] * t[3] < 0)
    what = ("the quaternion of the other sign, -q (r0 <= 0), for the book's q (r0 >= 0): "
            "the same rotation (q and -q, (2.3))" if tgt.equivalent == "quaternion" else
            "the angle negated with the axis, (-e, -phi) for the book's (e, phi), phi >= 0: "
            "the same rotation (2.49)")
    if other == len(pts):
        return f"sign: {what}, at each of {len(pts)} ordinary inputs; its convention"
    if other:
        return (f"sign: {what} at {other} of {len(pts)} ordinary inputs, the book's sign at "
                f"the others (a sign of its own choosing); its convention")
    return ""


def _wrong(tgt, m, c: W.WrongClass, dtype) -> dict:
    """A class of wrong output as plain data: its count, how far off, and its worst input
    in the user's convention (the regime, the arguments as the function takes them)."""
    j = c.worst
    _, rounded = W.truth_at(m.kernel(tgt), j.point, dtype)
    x = {a.name: np.asarray(v, dtype=np.float64) for a, v in
         zip(R.kernel_of(tgt.kernel).args, rounded, strict=True)}
    return {"class": c.name, "count": c.count, "off": c.off, "regime": j.regime,
            "ratio": j.ratio, "args": [np.asarray(a, dtype=dtype).tolist()
                                       for a in m.user_args(x)]}


#: the classes of wrong output that are wrong answers (not a loss of digits)
WRONG_ANSWERS = ("NaN/inf", "exception", "wrong rotation", "conjugate", "transposed",
                 "inverse rotation", "wrong branch", "wrong value")


def _told(wrong: dict) -> Finding | None:
    """Every class of wrong output the audit met, with its count and how far off: one
    finding (an error where a class is a wrong answer, else a note), so that 16 wrong
    rotations are told beside the NaN of the same function."""
    parts = []
    for d, classes in wrong.items():
        for c in classes:
            off = c["off"]
            how = ("" if not np.isfinite(off) else
                   f", off by up to {off:.3g} rad" if c["class"] in (
                       "wrong rotation", "conjugate", "transposed", "inverse rotation")
                   else f", relative error up to {off:.3g}")
            parts.append(f"{d}: {c['class']} at {c['count']} input"
                         f"{'s' if c['count'] != 1 else ''}{how} (worst: {c['regime']})")
    if not parts:
        return None
    sev = "error" if any(c["class"] in WRONG_ANSWERS for cs in wrong.values()
                         for c in cs) else "note"
    return Finding(sev, "wrong outputs", "the wrong outputs met, by class: " +
                   "; ".join(parts))


#: the seed offset of the re-run that confirms a finding resting on one input
CONFIRM_SEED = 1009


def _confirmations(call, tgt, m, beh: dict, seed, n_start, steps, search) -> dict:
    """``{(dtype, regime): the re-run's worst ratio there}`` for each regime whose error
    at or past :data:`.worst.FIND` x the bound rests on one input alone: the regime judged
    anew with another seed (new axes, new other arguments, a new search) confirms it there
    or not. A regime with two inputs or more past it needs no re-run."""
    out = {}
    for d, rows in beh.items():
        for r, b in rows.items():
            if np.isfinite(b.worst_ratio) and b.worst_ratio >= W.FIND and b.over < 2:
                out[(d, r)] = W.rejudge(tgt, m, call, np.dtype(d).type, r,
                                        seed + CONFIRM_SEED, n_start, steps)
    return out


def _undefined_axis(call, tgt, m) -> Finding | None:
    """At ``Q = 1`` (the axis undefined: any unit ``e`` with ``phi = 0`` is the truth) the
    zero axis with the angle 0, the answer some libraries document (pyquaternion's): the
    library's convention there, said as such (the judge takes it as the same rotation)."""
    if tgt.equivalent != "axis_angle":
        return None
    try:
        out = C.call_member(call, m, {"Q": np.eye(3)})
    except Exception:  # noqa: BLE001  (it raises at the identity: the flags say so)
        return None
    if out.size == 4 and not np.any(out):
        return Finding("note", "axis convention", "at Q = 1 (phi = 0, where the axis is "
                       "undefined) it returns the zero axis [0, 0, 0] with the angle 0: its "
                       "convention for the undefined axis, the same rotation, not counted as "
                       "wrong (a caller that divides by |e| must test for it)")
    return None
