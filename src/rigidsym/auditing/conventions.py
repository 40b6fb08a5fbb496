"""The convention finder: which member of the product of convention generators makes a bare
callable compute the book's operation.

It receives the callable and the target only (never a peer's name nor the project's peer
table). A *member* is one argument layout (:class:`.targets.Form`) and a set of generators;
each generator changes the kernel's arguments into the user's convention (``args``) and the
user's outputs back into the book's (``out``). The finder calls the function at random
ordinary inputs (well inside every regime: the truth there is the verified kernel's, to a
few ulps) under every member, and reports the member whose outputs match the book's to
``TOL`` with the fewest generators, how many it tried, or that none matches with the nearest
and its residual. Invariants a convention must keep are then checked and named when
broken: the power ``<t, w>`` of a twist and a wrench under a frame change (a wrench map
paired with the book's twist map of the same transform, and back), ``Q^T Q = 1`` and
``det Q = 1`` of a rotation output.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from rigidsym.auditing.targets import Form, Target

__all__ = ["Generator", "GENERATORS", "Member", "Found", "find", "call_member", "flat",
           "ordinary_points", "differ", "describe", "TOL", "OutputKind", "output_kind"]

#: the relative residual under which a member matches at ordinary inputs
TOL = 1e-8


def _swap6(v: np.ndarray) -> np.ndarray:
    v = np.asarray(v)
    return np.concatenate([v[3:6], v[0:3]])


def _swap66(v) -> np.ndarray:
    M = np.asarray(v, dtype=np.float64).reshape(6, 6)
    P = np.roll(np.eye(6), 3, axis=0)
    return (P @ M @ P).ravel()


def _rev(v) -> np.ndarray:
    """Euler-angle rates reversed (3,), or a rate matrix's columns reversed (3 x 3)."""
    v = np.asarray(v, dtype=np.float64)
    return v[::-1].copy() if v.size == 3 else v.reshape(3, 3)[:, ::-1].ravel()


def _last(v, scale: float) -> np.ndarray:
    v = np.array(v, dtype=np.float64)
    v[-1] *= scale
    return v


def _inv_T(T: np.ndarray) -> np.ndarray:
    T = np.asarray(T, dtype=np.float64).reshape(4, 4)
    R, d = T[:3, :3], T[:3, 3]
    out = np.eye(4)
    out[:3, :3], out[:3, 3] = R.T, -R.T @ d
    return out


def _with(x: dict, **kw) -> dict:
    return {**x, **kw}


@dataclass(frozen=True)
class Generator:
    """One convention change.

    Attributes:
        name: its key.
        says: what it means, as the report prints it.
        args: the kernel's arguments (by name) in the user's convention, or None.
        out: the user's flat output in the book's layout, or None.
        out_inv: the book's flat output in the user's layout (the regression test's
            expected value); None: ``out`` is its own inverse.
        dual: the truth is the target's dual kernel (a twist map on wrenches, and back).
    """

    name: str
    says: str
    args: Callable[[dict], dict] | None = None
    out: Callable[[np.ndarray], np.ndarray] | None = None
    out_inv: Callable[[np.ndarray], np.ndarray] | None = None
    dual: bool = False


def _six(x: dict) -> str:
    return "t_A" if "t_A" in x else ("w_A" if "w_A" in x else "xi")


GENERATORS: dict[str, Generator] = {g.name: g for g in (
    Generator("blocks", "linear block first: [v; w] for the book's [w; v] (a wrench [f; n] "
              "for [n; f])", args=lambda x: _with(x, **{_six(x): _swap6(x[_six(x)])}),
              out=_swap6),
    Generator("blocks_in", "linear block first in xi: [v; w] for the book's [w; v]",
              args=lambda x: _with(x, xi=_swap6(x["xi"]))),
    Generator("blocks_out", "linear block first in xi: [v; w] for the book's [w; v]",
              out=_swap6),
    Generator("inverse", "the inverse transform: points a and p exchanged (T^-1 for T)",
              args=lambda x: _with(x, a=x["p"], p=x["a"])),
    Generator("inverse_in", "the inverse transform: T^-1 for T", args=lambda x: _with(
        x, T=_inv_T(x["T"]))),
    Generator("inverse_out", "the inverse transform returned: T^-1 for T",
              out=lambda v: _inv_T(v).ravel()),
    Generator("dual", "the other transfer: Ad for Ad^-T on wrenches, or Ad^-T for Ad on "
              "twists", dual=True),
    Generator("transpose_out", "the transposed rotation returned: Q^T for Q (passive for "
              "active, or column-major)", out=lambda v: np.asarray(v).reshape(3, 3).T.ravel()),
    Generator("transpose_in", "the transposed rotation taken: Q^T for Q (passive for active)",
              args=lambda x: _with(x, Q=np.asarray(x["Q"]).T)),
    Generator("degrees", "the angle in degrees", args=lambda x: _with(
        x, phi=np.asarray(x["phi"]) * (180.0 / np.pi))),
    Generator("scalar_first", "the quaternion scalar first: [r0; r] (wxyz) for the book's "
              "[r; r0] (xyzw)", args=lambda x: _with(x, eta=np.roll(x["eta"], 1))),
    Generator("other_side", "the other-sided Jacobian: J(-w) (right for left, left for "
              "right)", args=lambda x: _with(x, w=-np.asarray(x["w"]))),
    Generator("blocks_matrix_out", "linear block first: the 6 x 6 matrix on [v; w] for the "
              "book's on [w; v]", out=lambda v: _swap66(v)),
    Generator("scalar_first_out", "the quaternion returned scalar first: [r0; r] (wxyz) for "
              "the book's [r; r0]", out=lambda v: np.roll(v, -1),
              out_inv=lambda v: np.roll(v, 1)),
    Generator("negated_out", "the quaternion of the other sign: -q for q (r0 <= 0)",
              out=lambda v: -np.asarray(v)),
    Generator("degrees_out", "the angle returned in degrees", out=lambda v: _last(
        v, np.pi / 180.0), out_inv=lambda v: _last(v, 180.0 / np.pi)),
    Generator("extrinsic", "the extrinsic sequence: angles (and their rates) in the "
              "reverse order, i.e. the intrinsic sequence read backwards",
              args=lambda x: _with(x, angles=np.asarray(x["angles"])[::-1])
              if "angles" in x else x,
              out=lambda v: _rev(v)),
    Generator("degrees_all_out", "the angles returned in degrees",
              out=lambda v: np.asarray(v) * (np.pi / 180.0),
              out_inv=lambda v: np.asarray(v) * (180.0 / np.pi)),
    Generator("angle_first_out", "the angle returned first: (phi, e) for (e, phi)",
              out=lambda v: np.roll(v, -1), out_inv=lambda v: np.roll(v, 1)),
)}


@dataclass(frozen=True)
class Member:
    """One member of the product: a form and a set of generators (in order)."""

    form: Form
    generators: tuple[str, ...]
    #: the member of the target's family of kernels (an Euler sequence and frame), or ""
    variant: str = ""

    def says(self, tgt: Target) -> str:
        """The member in words."""
        gens = "; ".join(GENERATORS[g].says for g in self.generators
                         if not (self.variant and g == "extrinsic")) or "the book's own"
        if self.variant:
            seq, frame = self.variant.split("_")[-2:]
            if frame not in ("fixed", "body"):      # the Euler angles of a rotation
                seq, frame = frame, ""
            seq = (f"the extrinsic {seq[::-1].upper()} sequence (the intrinsic "
                   f"{seq.upper()} with the angles in reverse order)"
                   if "extrinsic" in self.generators else
                   f"the intrinsic {seq.upper()} sequence")
            gens = seq + (f", angular velocity in the {frame} frame" if frame else "") + (
                "" if gens == "the book's own" else f"; {gens}")
        return f"{self.form.label}, convention: {gens}"

    def kernel(self, tgt: Target) -> str:
        """The kernel whose declaration is this member's truth."""
        if self.variant:
            return self.variant
        return tgt.dual if "dual" in self.generators else tgt.kernel

    def user_args(self, x: dict) -> list:
        """The user's positional arguments at the kernel's arguments ``x``."""
        for g in self.generators:
            if GENERATORS[g].args is not None:
                x = GENERATORS[g].args(x)
        return self.form.build(x)

    def book_out(self, v: np.ndarray) -> np.ndarray:
        """The user's flat output ``v`` in the book's layout."""
        for g in reversed(self.generators):
            if GENERATORS[g].out is not None:
                v = GENERATORS[g].out(v)
        return np.asarray(v, dtype=np.float64)

    def user_out(self, v: np.ndarray) -> np.ndarray:
        """The book's flat output ``v`` in the user's layout (the inverse of :meth:`book_out`)."""
        for g in self.generators:
            gen = GENERATORS[g]
            if gen.out is not None:
                v = (gen.out_inv or gen.out)(v)
        return np.asarray(v, dtype=np.float64)


def to_numpy(v) -> np.ndarray:
    """An array of the user's (NumPy, PyTorch, JAX, a sequence) as a float64 NumPy array."""
    if hasattr(v, "detach"):
        v = v.detach().cpu().numpy()
    return np.asarray(v, dtype=np.float64)


def flat(v) -> np.ndarray:
    """The user's output flattened: a tuple or list of arrays concatenated, else raveled."""
    if isinstance(v, (tuple, list)) and len(v) > 0:
        return np.concatenate([np.ravel(to_numpy(o)) for o in v])
    return np.ravel(to_numpy(v))


def describe(v) -> str:
    """What a user's function returned, in words (``a 3 x 3 array``, ``a tuple of 2``)."""
    if isinstance(v, (tuple, list)):
        return f"a {type(v).__name__} of {len(v)} ({', '.join(describe(o) for o in v)})"
    shape = np.shape(to_numpy(v)) if not np.isscalar(v) else ()
    return "a scalar" if shape == () else f"a {' x '.join(map(str, shape))} array"


@dataclass
class OutputKind:
    """A function whose output is not the book's kind under any argument layout.

    Attributes:
        says: what it returns against the book's output, with the fix to try, in words.
        keywords: keyword arguments with which it returns the book's kind (a flag of its
            own signature flipped: ``{"twist": True}``), or {} where none does.
    """

    says: str
    keywords: dict


def _flags(func: Callable) -> dict:
    """The keyword parameters of ``func`` with a bool default: ``{name: default}``."""
    import inspect

    try:
        ps = inspect.signature(func).parameters.values()
    except (TypeError, ValueError):
        return {}
    return {p.name: p.default for p in ps if isinstance(p.default, bool)}


def _structure(v, want: int) -> str:
    """What a 3 x 3 or 4 x 4 output is, where that tells the wrapper to write."""
    M = to_numpy(v)
    if M.shape == (3, 3) and want == 3 and np.allclose(M, -M.T, atol=1e-12):
        return ("; it is skew-symmetric, a cross-product matrix: its axial vector [M[2, 1], "
                "M[0, 2], M[1, 0]] is the 3-vector to audit")
    if M.shape == (4, 4) and want == 6 and np.allclose(M[3], 0, atol=1e-12) and np.allclose(
            M[:3, :3], -M[:3, :3].T, atol=1e-12):
        return ("; it is the 4 x 4 matrix [[W, v], [0, 0]] of a twist: [axial vector of W; v] "
                "is the 6-vector to audit")
    return ""


def output_kind(func: Callable, tgt: Target, point: dict) -> OutputKind | None:
    """The function's output checked against the book's kind before any convention is
    sought: where every argument layout that does not raise at ``point`` (the kernel's
    arguments) returns another number of values than the book's output, what it returns
    and the fix to try: a bool flag of its own signature that makes it return the book's
    kind (tried here), else the wrapper its structure calls for (a cross-product matrix's
    axial vector). None where some layout returns the book's kind, or every one raises.
    """
    from rigidsym.codegen.accuracy.harness.reference import kernel_of

    kernel = kernel_of(tgt.kernel)
    sl = tgt.user_slice(kernel)
    want = sl.stop - sl.start
    seen = None
    for form in tgt.forms:
        args = form.build(point)
        try:
            with np.errstate(all="ignore"):
                out = func(*args)
            size = flat(out).size
        except Exception:  # noqa: BLE001  (raises under this layout: the finder says so)
            continue
        if size == want:
            return None
        seen = seen or (form, args, out, size)
    if seen is None:
        return None
    form, args, out, size = seen
    names = ", ".join(f"{o.name}[{o.size}]" for o in kernel.outputs
                      if not tgt.outputs or o.name in tgt.outputs)
    what = describe(out)
    if np.ndim(to_numpy(out)) == 2 and not isinstance(out, (tuple, list)):
        what = what.replace(" array", " matrix")
    says = (f"returns {what} ({size} values) as {form.label}, where the book's "
            f"output is {want} values ({names})")
    raw = getattr(func, "__wrapped__", func)      # the user's own, which takes keywords
    for name, default in _flags(raw).items():
        try:
            with np.errstate(all="ignore"):
                alt = raw(*args, **{name: not default})
            ok = flat(alt).size == want
        except Exception:  # noqa: BLE001  (the flag does not give the book's kind)
            ok = False
        if ok:
            return OutputKind(f"{says}; with {name}={not default} it returns {want} values: "
                              f"audited so", {name: not default})
    return OutputKind(says + (_structure(out, want) or "; a wrapper that returns the book's "
                              "output is the function to audit"), {})


def call_member(func: Callable, member: Member, x: dict, dtype=None) -> np.ndarray:
    """The user's function under ``member`` at the kernel's arguments ``x`` (its arguments
    cast to ``dtype`` where given): its flat output in the book's layout. Raises what the
    function raises."""
    args = member.user_args(x)
    if dtype is not None:
        args = [np.asarray(a, dtype=dtype) for a in args]
    return member.book_out(flat(func(*args)))


def ordinary_points(kernel, n: int, rng) -> list[dict]:
    """``n`` random ordinary inputs of ``kernel``: ``{argument name: float64 array}``."""
    from rigidsym.codegen.accuracy.regimes import random_arg

    out = []
    for _ in range(n):
        out.append({a.name: np.array([float(v) for v in random_arg(a, rng, kernel.name)])
                    .reshape(a.shape) for a in kernel.args})
    return out


@dataclass
class Found:
    """What the finder found.

    Attributes:
        member: the matching member with the fewest generators (None: none matched).
        tried: how many members it tried.
        residual: the member's relative residual (the nearest's where none matched).
        nearest: the member with the smallest residual.
        errors: per form label, the first exception the function raised under it.
        broken: the invariants broken, each as a sentence.
        matches: every matching member.
        n: the inputs tried.
        agree: at how many of them the member (the nearest where none matched) matches.
        differ: how the nearest's outputs differ at the inputs no member matches
            (:func:`differ`), or "".
        also: where no member matches at every input, the other members that match at
            some of the inputs the nearest does not: ``[(member, how many)]``, the most
            first, each input counted once.
    """

    member: Member | None
    tried: int
    residual: float
    nearest: Member | None
    errors: dict = field(default_factory=dict)
    broken: list = field(default_factory=list)
    matches: list = field(default_factory=list)
    n: int = 0
    agree: int = 0
    differ: str = ""
    also: list = field(default_factory=list)


def _members(tgt: Target, names: tuple[str, ...] | None) -> list[Member]:
    forms = list(tgt.forms)
    if names is not None:      # forms whose parameter names fit go first
        def fits(f: Form) -> bool:
            return len(f.names) == len(names) and all(
                n.lower() in ok for n, ok in zip(names, f.names, strict=True))
        forms.sort(key=lambda f: not fits(f))
    gens = tgt.generators
    return [Member(f, c, v) for f in forms for v in (tgt.family or ("",))
            for r in range(len(gens) + 1) for c in itertools.combinations(gens, r)]


def _gaps(func, member, points, truth, tgt: Target) -> list[float]:
    """The relative gap of the user's output under ``member`` to the book's truth, per
    point (inf where the shapes differ)."""
    from rigidsym.auditing.equivalence import nearest
    from rigidsym.codegen.accuracy.harness.reference import kernel_of

    kernel = kernel_of(member.kernel(tgt))
    out = []
    for x, full in zip(points, truth, strict=True):
        got = call_member(func, member, x)
        # the user's columns; an output of the same rotation is the same answer
        # (:mod:`.equivalence`); either branch of the Euler angles
        cands = tgt.candidates(kernel, np.asarray(full))
        t = cands[0]
        if got.shape != t.shape:
            return [np.inf] * len(points)
        got = nearest(tgt.equivalent, got, t)
        gap = min(float(np.linalg.norm(got - c)) for c in cands)
        d = gap / max(float(np.linalg.norm(t)), 1e-300)
        out.append(d if np.isfinite(d) else np.inf)
    return out


def _residual(func, member, points, truth, tgt: Target) -> float:
    return max(_gaps(func, member, points, truth, tgt))


def differ(func, member: Member, points, truth, tgt: Target) -> str:
    """How the user's outputs under ``member`` differ from the book's at the inputs where
    they do not match, each way with the number of inputs: ``"by sign at 2"``, ``"by 2 pi
    w/|w| (a whole turn) at 4"`` (a rotation vector or an angle off by a whole turn), ``"by
    a transpose"`` (a 3 x 3), ``"by a factor c"``, else by how much (relative)."""
    from rigidsym.auditing.equivalence import nearest
    from rigidsym.codegen.accuracy.harness.reference import kernel_of

    kernel = kernel_of(member.kernel(tgt))
    kinds, worst = [], 0.0
    for x, full in zip(points, truth, strict=True):
        try:
            with np.errstate(all="ignore"):
                got = call_member(func, member, x)
        except Exception as e:  # noqa: BLE001  (the user's function raised there)
            kinds.append(f"raises {type(e).__name__}")
            continue
        t = tgt.candidates(kernel, np.asarray(full))[0]
        if got.shape != t.shape:
            raw = func(*member.user_args(x))
            return (f"in kind: it returns {describe(raw)} ({got.size} values) where the book's "
                    f"output is {t.size} values ("
                    f"{', '.join(f'{o.name}[{o.size}]' for o in kernel.outputs)}); "
                    f"a wrapper that returns the book's output is audited instead")
        got = nearest(tgt.equivalent, got, t)
        nt = max(float(np.linalg.norm(t)), 1e-300)
        d = float(np.linalg.norm(got - t)) / nt
        if d <= TOL:
            continue
        worst = max(worst, d)

        def close(a, b, nt=nt):
            return float(np.linalg.norm(a - b)) <= 1e-6 * nt

        kind = f"by {d:.3g} (relative)"
        if close(got, -t):
            kind = "by sign"
        elif t.size == 3 and np.linalg.norm(t) > 0 and any(
                close(got, t + k * 2 * np.pi * t / np.linalg.norm(t)) for k in (-1, 1)):
            kind = "by 2 pi w/|w| (a whole turn)"
        elif t.size == 4 and any(close(got, np.concatenate([t[:3], [t[3] + k * 2 * np.pi]]))
                                 for k in (-1, 1)):
            kind = "by 2 pi in the angle (a whole turn)"
        elif t.size == 9 and close(got, t.reshape(3, 3).T.ravel()):
            kind = "by a transpose"
        else:
            c = float(got @ t) / (nt * nt)
            if abs(c) > 1e-12 and close(got, c * t):
                kind = f"by a factor {c:.6g}"
        kinds.append(kind)
    if not kinds:
        return ""
    uniq = sorted(set(kinds), key=kinds.index)
    return ", ".join(f"{k} at {kinds.count(k)}" for k in uniq)


def find(func: Callable, tgt: Target, points: list[dict], truth: dict,
         names: tuple[str, ...] | None = None) -> Found:
    """Try every member of ``tgt``'s product on ``func`` at ``points`` (ordinary inputs).

    Args:
        func: the user's callable.
        tgt: the target.
        points: the kernel's arguments per point (:func:`ordinary_points`).
        truth: ``{kernel name: [flat output per point]}`` for the target's kernel and dual.
        names: the user's parameter names, if known (forms that fit them are tried first).

    Returns:
        :class:`Found` (``member`` None where no member matches to :data:`TOL`).
    """
    members = _members(tgt, names)
    best, best_key, errors, matches, gaps_of = None, None, {}, [], {}
    best_r, best_agree = np.inf, 0
    for m in members:
        try:
            with np.errstate(all="ignore"):
                gaps = _gaps(func, m, points, truth[m.kernel(tgt)], tgt)
        except Exception as e:      # noqa: BLE001  (the user's function failed: say so)
            errors.setdefault(m.form.label, f"{type(e).__name__}: {e}")
            continue
        gaps_of[m] = gaps
        r = max(gaps)
        agree = sum(g <= TOL for g in gaps)
        # the nearest: the most inputs matched, then the smallest residual on the others
        key = (-agree, r if agree == len(gaps) else max(g for g in gaps if g > TOL))
        if best_key is None or key < best_key:
            best, best_key, best_r, best_agree = m, key, r, agree
        if r <= TOL:
            matches.append(m)
    match = min(matches, key=lambda m: len(m.generators)) if matches else None
    found = Found(match, len(members), best_r if match is None else _residual(
        func, match, points, truth[match.kernel(tgt)], tgt),
        match or best, errors, [], matches, len(points),
        len(points) if match is not None else (best_agree if best is not None else 0))
    if match is None and best is not None:
        rest = [i for i, g in enumerate(gaps_of[best]) if g > TOL]
        while rest:     # the other members that match some of the rest, the most first
            m2, hit = max(((m, [i for i in rest if g[i] <= TOL]) for m, g in gaps_of.items()
                           if m != best), key=lambda t: len(t[1]), default=(None, []))
            if not hit:
                break
            found.also.append((m2, len(hit)))
            rest = [i for i in rest if i not in hit]
        t = truth[best.kernel(tgt)]
        found.differ = differ(func, best, [points[i] for i in rest], [t[i] for i in rest],
                              tgt)
    if match is not None or best is not None:
        found.broken = invariants(func, tgt, match or best, points)
    return found


def invariants(func: Callable, tgt: Target, member: Member, points: list[dict]) -> list[str]:
    """The invariants ``func`` breaks under ``member``, as sentences (none: empty)."""
    from rigidsym.codegen.accuracy.harness.judge import run_kernel

    broken = []
    if tgt.kind == "rotation":
        worst_o, worst_d = 0.0, 0.0
        for x in points:
            with np.errstate(all="ignore"):
                Q = call_member(func, member, x)[:9].reshape(3, 3)
            worst_o = max(worst_o, float(np.abs(Q.T @ Q - np.eye(3)).max()))
            worst_d = max(worst_d, abs(float(np.linalg.det(Q)) - 1.0))
        if not worst_o <= 1e-10:
            broken.append(f"Q^T Q = 1 broken: |Q^T Q - 1| = {worst_o:.3g}")
        if not worst_d <= 1e-10:
            broken.append(f"det Q = 1 broken: |det Q - 1| = {worst_d:.3g}")
    if tgt.kind in ("twist_matrix", "wrench_matrix"):
        broken += _power_matrix(func, tgt, member, points)
    if tgt.kind in ("twist", "wrench"):
        # the user's map with the transform as given (no inverse, no dual), paired with the
        # book's map of the other kind of the same transform: <t_P, w_P> = <t_A, w_A>
        same = Member(member.form, tuple(g for g in member.generators
                                         if g not in ("inverse", "dual")))
        other = tgt.dual
        rng = np.random.default_rng(7)
        worst = 0.0
        for x in points:
            y = rng.standard_normal(6)
            mine = call_member(func, same, x)
            arrays = [y[None], x["a"][None], x["p"][None]]
            theirs = run_kernel(other, arrays, np.float64, "numpy")[0]
            a_in = x["t_A" if tgt.kind == "twist" else "w_A"]
            before, after = float(a_in @ y), float(mine @ theirs)
            worst = max(worst, abs(after - before) / (np.linalg.norm(a_in)
                                                      * np.linalg.norm(y) + 1e-300))
        if not worst <= 1e-10:
            kind = "twists" if tgt.kind == "wrench" else "wrenches"
            broken.append(f"power <t, w> not invariant under the frame change: with {kind} "
                          f"mapped by the book's transfer of the same transform, "
                          f"|<t_P, w_P> - <t_A, w_A>| / (|t| |w|) = {worst:.3g}")
    return broken


def _power_matrix(func: Callable, tgt: Target, member: Member, points: list[dict]) -> list:
    """``U^T V = 1`` (the power kept) of the user's matrix under ``member`` without the
    inverse or dual, with the book's matrix of the other kind of the same transform."""
    from rigidsym.codegen.accuracy.harness.judge import run_kernel

    same = Member(member.form, tuple(g for g in member.generators
                                     if g not in ("inverse", "dual")))
    worst = 0.0
    for x in points:
        M = call_member(func, same, x).reshape(6, 6)
        D = run_kernel(tgt.dual, [x["a"][None], x["p"][None]], np.float64,
                       "numpy")[0].reshape(6, 6)
        worst = max(worst, float(np.abs(M.T @ D - np.eye(6)).max()))
    if worst <= 1e-10:
        return []
    kind = "twists" if tgt.kind == "wrench_matrix" else "wrenches"
    return [f"power <t, w> not invariant under the frame change: with {kind} mapped by the "
            f"book's matrix of the same transform, |U^T V - 1| = {worst:.3g}"]
