"""The evaluation of a generated array program on PyTorch or JAX arrays, shared by
both back-ends: no import of either library.

Both back-ends evaluate the same generated programs (``generated/torch``, ``generated/jax``:
:mod:`rigidsym.codegen.backends.arrays.programs`) on array modules with the same names for
what is needed here (``where``, ``stack``, ``isfinite``, ``broadcast_to``, ``einsum``,
``linalg.det``): ``xp`` below is ``torch`` or ``jax.numpy``. This module holds the directory
of programs (:class:`ArraySpace`), their evaluation (one column per scalar input component,
the branch kernels' variant selected with the safe-``where`` idiom, the singular mask from the
denominators, the flat outputs shaped back, the overflow masks), and the checked call both
back-ends share (:class:`Space`: conversion, modes, validation and broadcasting by the input
rules of :mod:`rigidsym.kernels.arrays.inputs`, evaluation, the rescue of
:mod:`rigidsym.kernels.arrays.rescue`, the singular and overflow flags); each back-end
supplies only what differs, as a :class:`Library`. A back-end module's public face is
:mod:`rigidsym.kernels.arrays.namespace`.
"""

from __future__ import annotations

import ast
import json
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from rigidsym.core.config import generated_dir
from rigidsym.core.files import load_module
from rigidsym.kernels.arrays import infinity as _infinity
from rigidsym.kernels.arrays import rescue as _ar
from rigidsym.kernels.arrays.inputs import (
    broadcast_batch,
    convert,
    modes,
    raise_error,
    safe_point,
    validate,
)
from rigidsym.kernels.runtime.errors import raise_flagged
from rigidsym.kernels.runtime.jacobians import contract
from rigidsym.kernels.runtime.jacobians import full_batch as _full

__all__ = ["SUFFIX", "columns", "shape_outputs", "evaluate", "singular_mask", "nonfinite_rows",
           "rounds_to_inf", "propagates_inf", "ArraySpace", "make_all", "cotangents", "Library",
           "Space"]

#: suffix of the generated kernels with Jacobians (rigidsym.codegen.derivatives.jacobians.SUFFIX)
SUFFIX = "_with_jacobians"


# ------------------------------------------------ running a program on arrays
def columns(arrays: list, args: list[dict]) -> list:
    """One array per scalar component (row-major), each of the batch shape."""
    cols = []
    for x, a in zip(arrays, args, strict=True):
        if not a["shape"]:
            cols.append(x)
            continue
        n = int(math.prod(a["shape"]))
        flat = x.reshape(tuple(x.shape[:len(x.shape) - len(a["shape"])]) + (n,))
        # torch's unbind: one dispatch for the n views (and one stack in its backward)
        # instead of n indexings, a fixed cost of a call at small N
        cols.extend(flat.unbind(-1) if hasattr(flat, "unbind") else
                    (flat[..., i] for i in range(n)))
    return cols


def shape_outputs(xp, flat: list, outs: list[dict], like) -> list:
    """The flat outputs of a program as arrays ``batch + output shape``."""
    res, k = [], 0
    batch = tuple(like.shape)
    for o in outs:
        n = int(math.prod(o["shape"]))
        parts = [_full(xp, v, like) for v in flat[k:k + n]]
        k += n
        res.append(parts[0] if not o["shape"] else
                   xp.stack(parts, -1).reshape(batch + tuple(o["shape"])))
    return res


def evaluate(xp, variants: tuple, cols: list, stop_gradient: Callable, safe=None,
             singular=None) -> tuple[list, Any]:
    """Run a kernel's variants on ``cols``: ``(flat outputs, singular mask)``.

    A kernel with branches takes, per sample, the first branch whose condition holds, else
    main (the NumPy kernel's rule). Safe ``where``: each variant sees the real inputs only
    in its own samples and ``stop_gradient`` of them elsewhere, so a NaN or inf derivative
    of a branch not taken never reaches the gradient.

    ``safe`` (one float per column, a regular point: :func:`safe_point`) is substituted for
    the inputs of the singular samples before the differentiable evaluation, so that their
    derivatives are finite and a zero cotangent gives exactly zero, never NaN (0 * inf),
    in a parameter the batch shares; their outputs are then the safe point's,
    which the caller replaces by NaN or an error. ``singular``: the mask when known (the
    forward's), else found by a first evaluation on ``stop_gradient`` of the inputs.
    """
    if safe is None:
        return _evaluate(xp, variants, cols, stop_gradient)
    if singular is None:
        _, singular = _evaluate(xp, variants, [stop_gradient(c) for c in cols], stop_gradient)
    cols = [xp.where(singular, v, c) for v, c in zip(safe, cols, strict=True)]
    return _evaluate(xp, variants, cols, stop_gradient)[0], singular


def _evaluate(xp, variants: tuple, cols: list, stop_gradient: Callable) -> tuple[list, Any]:
    like = cols[0]
    if len(variants) == 1:
        outs, dens = variants[0][1](*cols)
        sing = singular_mask(xp, dens, like)
        return list(outs), sing
    taken, rest = [], None
    for _, _, when in variants[:-1]:
        hit = when(*cols)
        hit = hit if rest is None else xp.logical_and(rest, hit)
        rest = xp.logical_not(hit) if rest is None else xp.logical_and(rest, xp.logical_not(hit))
        taken.append(hit)
    taken.append(rest)
    result = sing = None
    for (_, prog, _), hit in zip(reversed(variants), reversed(taken), strict=True):
        safe = [xp.where(hit, c, stop_gradient(c)) for c in cols]
        outs, dens = prog(*safe)
        s = singular_mask(xp, dens, like)
        outs = [_full(xp, v, like) for v in outs]
        if result is None:
            result, sing = outs, s
        else:
            result = [xp.where(hit, v, r) for v, r in zip(outs, result, strict=True)]
            sing = xp.where(hit, s, sing)
    return result, sing


def singular_mask(xp, dens, like):
    """The batch mask of the samples where a denominator is 0 or inf (``like``: a column)."""
    # a denominator that overflowed to inf flags its sample too: x / inf = 0 is
    # a finite wrong value; eager calls re-run such samples in long double (arrays.rescue)
    sing = None
    for d in dens:
        z = (d == 0) | xp.isinf(d)
        sing = z if sing is None else xp.logical_or(sing, z)
    if getattr(sing, "shape", None) != like.shape:  # no denominator, or a constant one
        zero = xp.zeros_like(like, dtype=bool)
        sing = zero if sing is None else xp.logical_or(zero, sing)
    return sing


def nonfinite_rows(xp, arrays: list, batch: tuple):
    """The batch mask of the samples with an inf or NaN entry in one of ``arrays`` (each
    ``batch + shape``): one NaN-propagating sum (``0 * inf`` is NaN) per array, summed,
    where ``isfinite`` then ``all`` was 5 operations an array (``isfinite`` is 4 in
    PyTorch): fewer nodes for inductor to compile; no concatenation, which
    would copy every output once more."""
    total = None
    for a in arrays:
        s = (a.reshape(batch + (-1,)) * 0.0).sum(-1)
        total = s if total is None else total + s
    return xp.isnan(total)


def rounds_to_inf(xp, arrays: list, batch: tuple, finfo):
    """The batch mask of the samples with an entry of ``arrays`` (float32, each ``batch +
    shape``) that rounds to inf in the narrower type of ``finfo`` (float16, bfloat16):
    ``|x| >= max + ulp(max) / 2`` (round to nearest even), decided on the float32 values,
    before the rounding: inductor computes a float16 rounding and a check after it in
    float32 without rounding in between, so ``isinf`` of the rounded value is no test there
   ."""
    big = float(finfo.max) + 2.0 ** math.floor(math.log2(float(finfo.max))) * float(
        finfo.eps) / 2
    rows = None
    for a in arrays:
        r = (xp.abs(a) >= big).reshape(batch + (-1,)).any(-1)
        rows = r if rows is None else rows | r
    return rows


#: the functions of a program that are non-finite wherever their argument is (sin and cos
#: of inf are NaN, sqrt(inf) = inf, sqrt(-inf) = NaN); JAX's programs call _sin, _cos
_NONFINITE_IN_OUT = {"sin", "cos", "sqrt", "_sin", "_cos"}
_NODES = (ast.Module, ast.FunctionDef, ast.arguments, ast.arg, ast.Assign, ast.Return,
          ast.Tuple, ast.Name, ast.Load, ast.Store, ast.Constant, ast.Add, ast.Sub, ast.Mult,
          ast.Pow, ast.USub, ast.UAdd, ast.UnaryOp, ast.Attribute)


def propagates_inf(source: str) -> bool:
    """Whether the program ``def _main`` in ``source`` (a generated module's text) is
    non-finite in every output that reads an inf input, decided from the program:
    it uses only ``+``, ``-``, ``*``, powers with a positive integer exponent and
    :data:`_NONFINITE_IN_OUT` (each non-finite wherever an argument is: ``inf * 0`` and
    ``inf - inf`` are NaN), so by induction every value that reads an inf is inf or NaN;
    nothing maps an inf to a finite value (``1 / inf``, ``atan``, a branch condition). Then
    mapping the non-finite outputs to NaN is the kernels' rule (an inf input taken as NaN)
    without touching the inputs."""
    start = source.find("\ndef _main(")
    if start < 0:
        return False
    end = source.find("\n\n\n", start + 1)
    tree = ast.parse(source[start:end if end > 0 else None])
    for node in ast.walk(tree):
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Pow):
            e = node.right
            if not (isinstance(e, ast.Constant) and type(e.value) is int and e.value >= 1):
                return False
        elif isinstance(node, ast.BinOp):
            if not isinstance(node.op, ast.Add | ast.Sub | ast.Mult):
                return False
        elif isinstance(node, ast.Call):
            f = node.func
            name = f.attr if isinstance(f, ast.Attribute) else getattr(f, "id", None)
            if name not in _NONFINITE_IN_OUT or len(node.args) != 1 or node.keywords:
                return False
        elif not isinstance(node, _NODES):
            return False
    return True


# ------------------------------------------------ the programs of a directory
@dataclass
class ArraySpace:
    """The generated programs of one directory for one back-end (``"torch"``, ``"jax"``)."""

    directory: Path
    backend: str
    meta: dict
    _programs: dict = field(default_factory=dict)

    @classmethod
    def from_directory(cls, directory: str | Path | None, backend: str) -> ArraySpace:
        """Read ``directory/kernels.json`` (default the package's ``generated/``).

        Raises:
            FileNotFoundError: no ``kernels.json``, or no ``<backend>/`` folder (a directory
                generated before the back-end existed: regenerate it).
        """
        d = (generated_dir() if directory is None else Path(directory)).resolve()
        if not (d / "kernels.json").is_file() or not (d / backend).is_dir():
            raise FileNotFoundError(f"directory: no kernels.json or {backend}/ in {d} (run "
                                    f"`rigidsym generate --out {d}`)")
        data = json.loads((d / "kernels.json").read_text(encoding="utf-8"))
        meta = {k["name"]: k for k in data["kernels"]}
        return cls(d, backend, meta)

    def kernel_names(self) -> list[str]:
        """The public kernels, sorted."""
        return sorted(n for n, m in self.meta.items() if m["public"])

    def has_jacobian(self, name: str) -> bool:
        return name + SUFFIX in self.meta

    def variants(self, name: str) -> tuple:
        """``((name, program, condition or None), ...)`` of kernel ``name``'s module."""
        v = self._programs.get(name)
        if v is None:
            key = abs(hash((str(self.directory), self.backend))) % 10**12
            mod = load_module(f"rigidsym._{self.backend}_{key}.{name}",
                              self.directory / self.backend / f"{name}.py")
            v = self._programs[name] = mod.VARIANTS
            # the generated vector-Jacobian product; None in a folder generated before it
            self._programs["vjp", name] = getattr(mod, "VJP", None)
            self._programs["jvp", name] = getattr(mod, "JVP", None)
            # the forward returning the temps its VJP reads, and that VJP (PyTorch)
            self._programs["saved", name] = getattr(mod, "SAVED", None)
            # whether its program divides (a folder generated before the flag: assume so)
            self._programs["divides", name] = getattr(mod, "DIVIDES", True)
            # an inf input can reach a finite output only through a division, a branch or
            # a function like atan: without them and without a denominator, a traced call
            # maps its non-finite outputs to NaN instead of its inputs
            path = self.directory / self.backend / f"{name}.py"
            self._programs["inf", name] = len(v) == 1 and not getattr(
                mod, "DIVIDES", True) and propagates_inf(path.read_text(encoding="utf-8"))
        return v

    def propagates_inf(self, name: str) -> bool:
        """Kernel ``name``'s program is non-finite in every output that reads an inf input
        (:func:`propagates_inf`)."""
        self.variants(name)
        return self._programs["inf", name]

    def divides(self, name: str) -> bool:
        """Kernel ``name``'s program divides (else no sample is ever singular)."""
        return self.variants(name) is not None and self._programs["divides", name]

    def vjp(self, name: str, mode: str = "vjp"):
        """The generated reverse-mode (``"vjp"``: ``f(*columns, *output cotangents) -> input
        cotangents``) or forward-mode (``"jvp"``: ``f(*columns, *input tangents) -> output
        tangents``) program of kernel ``name`` (``rigidsym.codegen.derivatives.vjp``), or None;
        ``"saved"``: ``(forward, vjp)`` where the forward also returns the temps the VJP
        reads and the VJP takes them after the columns, or None."""
        self.variants(name)
        return self._programs[mode, name]

    def safe(self, name: str) -> list[float]:
        """The :func:`safe_point` of kernel ``name``'s arguments (cached)."""
        key = ("safe", name)
        if key not in self._programs:
            self._programs[key] = safe_point(self.meta[name]["args"])
        return self._programs[key]


def make_all(progs: ArraySpace, make: Callable) -> dict:
    """``{name: make(name)}`` for every kernel of ``progs`` but the Jacobian kernels, every
    program loaded first (0.15 s for the package's 134 kernels): never inside a traced call,
    so torch.compile(fullgraph=True) and jit see only tensor code."""
    for name in progs.meta:
        progs.variants(name)
        progs.safe(name)
    return {name: make(name) for name in progs.meta if not name.endswith(SUFFIX)}


def cotangents(grads: list, outs: list[dict]) -> list:
    """The columns of the outputs' cotangents (None: zeros, as Python floats)."""
    gcols = []
    for g, o in zip(grads, outs, strict=True):
        gcols += ([0.0] * int(math.prod(o["shape"])) if g is None else columns([g], [o]))
    return gcols


# ------------------------------------------------ the call path both back-ends share
@dataclass(frozen=True)
class Library:
    """What differs between the array back-ends; :class:`Space` does the rest.

    Fields: ``backend`` (``"torch"``, ``"jax"``), ``xp`` (``torch``, ``jax.numpy``),
    ``tracer`` (the tracers' names in errors), ``traced(xs)`` (an input is traced: no host
    reads), ``stop_gradient``, ``detach`` (a view for host reads), ``is_array(v)`` (the
    library's own array), ``real(v)`` (a library array holds real numbers), ``dtype(values,
    arrays)`` (the working dtype of the raw ``values``, once ``arrays`` are the library
    arrays and NumPy arrays they became), ``as_array(v, dtype, device, name)`` (convert, or
    raise naming ``name``), ``device(arrays)``, ``host(x)`` (a NumPy copy), ``make(space,
    name)`` (``f(*broadcast inputs) -> (*outputs, singular)``, with the derivative rule),
    ``refuse(exc_type, message)`` (raises the refusals of :func:`modes`), ``note(values)``
    (a warning before conversion, or nothing), ``clear(mask)`` (the mask is known all False
    without a sync or a trace) and ``constant(fn)`` (``fn``'s result a trace-time constant:
    Dynamo restarted once per float read from an object); for the dtypes,
    ``floats`` (those accepted), ``float32``, ``finfo``, ``float_dtype(v)`` (the library
    dtype of a floating library or NumPy array, else None) and ``cast(x, dtype)``.
    """

    backend: str
    xp: Any
    tracer: str
    traced: Callable
    stop_gradient: Callable
    detach: Callable
    is_array: Callable
    real: Callable
    dtype: Callable
    as_array: Callable
    device: Callable
    host: Callable
    make: Callable
    floats: tuple
    float32: Any
    finfo: Callable
    float_dtype: Callable
    cast: Callable
    refuse: Callable = raise_error
    note: Callable = lambda values: None
    clear: Callable = lambda mask: False
    constant: Callable = lambda fn: fn
    #: ``finite_inside()``: the function of a traced call (``make``) takes an inf input as
    #: NaN itself (``Space.values(finite=True)``); else ``Space.call`` maps the inputs
    finite_inside: Callable = lambda: False
    #: ``views(arrays)``: NumPy views of eager host arrays (PyTorch's CPU tensors:
    #: cheaper operations at a small batch), or None
    views: Callable = lambda arrays: None
    #: ``rescued(outputs, rows, inputs)``: the outputs, whose ``rows`` (a batch mask) hold
    #: values of the long-double rescue, with no derivative there (NaN for a nonzero
    #: cotangent, as autograd cannot follow the host); None: nothing differentiates eagerly
    rescued: Callable | None = None


class Space:
    """The kernels of one generated directory in one back-end: ``call`` is the public path."""

    def __init__(self, lib: Library, directory):
        self.lib = lib
        self.progs = ArraySpace.from_directory(directory, lib.backend)
        self._safe = lib.constant(lambda name: self.progs.safe(name))
        self._fns = make_all(self.progs, lambda name: lib.make(self, name))

    def function(self, name: str) -> Callable:
        """``f(*broadcast inputs) -> (*outputs, singular)`` of kernel ``name``, with its
        back-end's derivative rule."""
        return self._fns[name]

    def values(self, name: str, xs, differentiated: bool = False,
               finite: bool = False) -> tuple:
        """``(*outputs, singular)`` of kernel ``name`` on broadcast inputs ``xs``;
        ``differentiated``: autograd will run through it (safe inputs where singular);
        ``finite``: a traced call, an inf input taken as NaN here
        (:func:`rigidsym.kernels.arrays.rescue.finite_columns`)."""
        xp, outs = self.lib.xp, self.progs.meta[name]["outputs"]
        cols = columns(xs, self.progs.meta[name]["args"])
        if finite and not self.progs.propagates_inf(name):  # else Space.call's outputs
            cols = _ar.finite_columns(cols)
        flat, sing = evaluate(xp, self.progs.variants(name), cols, self.lib.stop_gradient,
                              self._safe(name) if differentiated else None)
        return (*shape_outputs(xp, flat, outs, cols[0]), sing)

    def jacobian(self, name: str, xs, singular) -> list:
        """The entries of the generated Jacobian kernel of ``name`` at ``xs``, flat; the
        safe point's in the ``singular`` samples (finite, so that a zero cotangent gives
        zero and a second derivative through them is finite)."""
        meta = self.progs.meta[name]
        nval = sum(math.prod(o["shape"]) for o in meta["outputs"])
        flat, _ = evaluate(self.lib.xp, self.progs.variants(name + SUFFIX),
                           columns(xs, meta["args"]), self.lib.stop_gradient,
                           self._safe(name), singular)
        return flat[nval:]

    def values_saved(self, name: str, xs) -> tuple:
        """``(outputs, singular, temps)``: :meth:`values` of a kernel with a ``"saved"``
        program, and the forward temps its VJP reads, for :meth:`vjp_saved`."""
        xp, meta = self.lib.xp, self.progs.meta[name]
        cols = columns(xs, meta["args"])
        outs, dens, temps = self.progs.vjp(name, "saved")[0](*cols)
        return (shape_outputs(xp, list(outs), meta["outputs"], cols[0]),
                singular_mask(xp, dens, cols[0]), temps)

    def regular(self, name: str, singular) -> bool:
        """No sample is singular, known without a trace or a device sync (no denominator,
        or an eager CPU mask read)."""
        return not self.progs.divides(name) or self.lib.clear(singular)

    def vjp_saved(self, name: str, xs, temps, grads: list, singular=None) -> list:
        """:meth:`vjp` on the forward's ``temps`` (:meth:`values_saved`) where no sample
        is singular (:meth:`regular`), or on the safe point's inputs in the ``singular``
        samples with the temps of :meth:`values_saved_traced`: the same operations less
        those of the forward."""
        meta = self.progs.meta[name]
        cols = columns(xs, meta["args"]) if singular is None else \
            self._safe_columns(name, xs, singular)
        flat = self.progs.vjp(name, "saved")[1](*cols, *temps,
                                                 *cotangents(grads, meta["outputs"]))
        return shape_outputs(self.lib.xp, list(flat), meta["args"], cols[0])

    def vjp(self, name: str, xs, grads: list, singular) -> list:
        """The cotangents of the inputs ``xs`` from those of the outputs, ``grads`` (None:
        zero): the generated reverse-mode program, on the safe point's inputs in the
        ``singular`` samples (their cotangent is zero there), plain arithmetic that autograd
        differentiates again; the Jacobian kernel then a contraction in a folder generated
        without it."""
        meta, xp = self.progs.meta[name], self.lib.xp
        args, outs = meta["args"], meta["outputs"]
        fn = self.progs.vjp(name)
        if fn is None:
            return contract(xp, grads, self.jacobian(name, xs, singular), outs, args,
                            forward=False)
        cols = self._safe_columns(name, xs, singular)
        return shape_outputs(xp, list(fn(*cols, *cotangents(grads, outs))), args, cols[0])

    def jvp(self, name: str, xs, tangents: list, singular, finite: bool = False) -> list:
        """The tangents of the outputs from those of the inputs (arrays, zeros for none):
        the generated forward-mode program, linear in the tangents, zero in the
        ``singular`` samples (whose values are NaN or an error); the Jacobian kernel then
        a contraction in a folder generated without it. ``finite``: as :meth:`values`'
        (the columns its own, so that XLA computes the forward temps once for both)."""
        meta, xp = self.progs.meta[name], self.lib.xp
        args, outs = meta["args"], meta["outputs"]
        fn = self.progs.vjp(name, "jvp")
        if fn is None:
            return contract(xp, tangents, self.jacobian(name, xs, singular), outs, args,
                            forward=True, singular=singular)
        cols = self._safe_columns(name, xs, singular, finite)
        flat = list(fn(*cols, *columns(tangents, args)))
        if self.progs.divides(name):
            flat = [xp.where(singular, 0.0, _full(xp, v, cols[0])) for v in flat]
        return shape_outputs(xp, flat, outs, cols[0])

    def _safe_columns(self, name: str, xs, singular, finite: bool = False) -> list:
        """The columns of ``xs``, the safe point's in the ``singular`` samples (no
        ``where`` without a denominator or with a clear eager mask); ``finite``:
        inf as NaN first, as :meth:`values`."""
        cols, where = columns(xs, self.progs.meta[name]["args"]), self.lib.xp.where
        if finite and not self.progs.propagates_inf(name):
            cols = _ar.finite_columns(cols)
        if self.regular(name, singular):
            return cols
        return [where(singular, v, c) for v, c in zip(self._safe(name), cols, strict=True)]

    def call(self, name: str, values: tuple, check, on_singular):
        """Kernel ``name`` on ``values`` (the public functions' body): convert, validate
        (``check``), broadcast, evaluate, rescue the samples the program cannot compute in
        its type (eager: :mod:`.rescue`), then flag the singular samples
        and those whose result does not fit the dtype: an error (``on_singular="raise"``)
        or NaN there. ``check=False`` only skips validation."""
        lib, xp = self.lib, self.lib.xp
        meta = self.progs.meta[name]
        args = meta["args"]
        xs, dtype, eps = convert(lib, values, args)
        traced = lib.traced(xs)
        check, on_singular = modes(check, on_singular, traced, lib.tracer, lib.refuse)
        batch = broadcast_batch(xp.broadcast_shapes, xs, args, traced)
        if check:
            validate(xp, [lib.detach(x) for x in xs], args, eps)
        full = [x if not traced and tuple(x.shape) == batch + tuple(a["shape"]) else
                xp.broadcast_to(x, batch + tuple(a["shape"])) for x, a in zip(xs, args,
                                                                             strict=True)]
        if traced and not lib.finite_inside():  # else the function maps them, cheaper
            full = _ar.traced_inputs(xp, full)
        *res, bad = self.function(name)(*full)
        clear = False
        if not traced:
            res, bad, clear = self._rescue(name, full, res, bad, batch)
        # screws at infinity (pure translations, couples): the field's answer, pitch +inf
        res, bad, at_inf = _infinity.complete(lib, name, full, res, bad, batch, on_singular,
                                              traced)
        big = None
        if res[0].dtype != dtype:  # float16, bfloat16: computed in float32, rounded once
            big = rounds_to_inf(xp, res, batch, lib.finfo(dtype))
            res = [lib.cast(r, dtype) for r in res]
        elif clear or (lib.finite_inside() and
                       getattr(self.function(name), "flags_overflow", False)):
            # no sample singular, of non-finite output or input: nothing to flag; or a
            # compiled function that flagged the overflowed samples and set NaN there
            return res[0] if len(res) == 1 else tuple(res)
        # a result that does not fit the dtype, from finite inputs (a NaN input's NaN is
        # its IEEE value)
        sing = bad
        over = nonfinite_rows(xp, res, batch)
        over = over if big is None else over | big
        if at_inf is not None:  # pitch = +inf, or no motion's NaN: the answer, not an overflow
            over = over & ~at_inf
        bad = bad | (over & ~nonfinite_rows(xp, full, batch))
        if on_singular == "raise":
            if bool(bad.any()):  # the error path copies the masks to the host
                raise_flagged(name, meta, lib.host(sing), lib.host(bad & ~sing),
                              [lib.host(lib.detach(x)) for x in xs])
        else:
            # inf inputs kept by a program that propagates them: its non-finite outputs NaN
            inf = traced and lib.finite_inside() and self.progs.propagates_inf(name)
            if inf and at_inf is not None:
                keep = at_inf.reshape(batch + (1,))
                res = [xp.where(keep if r.ndim > len(batch) else at_inf, r,
                                xp.where(xp.isinf(r), xp.nan, r)) for r in res]
                inf = False
            res = [xp.where(bad.reshape(batch + (1,) * (r.ndim - len(batch))) |
                            xp.isinf(r) if inf else
                            bad.reshape(batch + (1,) * (r.ndim - len(batch))), xp.nan, r)
                   for r in res]
        return res[0] if len(res) == 1 else tuple(res)

    def _rescue(self, name: str, full: list, res: list, sing, batch: tuple):
        """Eager: the outputs with the flagged samples re-run in long double, the
        singular mask the wide run finds (:mod:`.rescue`), and whether no sample
        was flagged at all."""
        lib, xp = self.lib, self.lib.xp
        bits = int(lib.finfo(full[0].dtype).bits)
        if not _ar.screen(lib, full, res, sing, bits):
            return res, sing, True
        rows = _ar.flag_rows(xp, full, res, sing, batch, bits)
        if not bool(rows.any()):     # flags of ordinary inputs stand
            return res, sing, False
        res, s, put = _ar.rescue(lib, self.progs, name, full, res, rows, batch, bits)
        dev = lib.device(full)
        if lib.rescued is not None and put.any():
            res = lib.rescued(res, lib.as_array(put.reshape(batch), None, dev, "rows"), full)
        s = lib.as_array(s.reshape(batch), None, dev, "singular")
        # the wide run's singular rows, and the own flags of the rows it did not re-run
        return res, s | (sing.reshape(s.shape) & ~rows.reshape(s.shape)), False
