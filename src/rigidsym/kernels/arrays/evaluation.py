"""Running a generated array program on arrays (issue 31; split from :mod:`._arrays`):
one column per scalar input component, the branch kernels' safe-``where`` selection, the
singular mask from the denominators, the flat outputs shaped back. No import of PyTorch or
JAX (``xp`` is ``torch`` or ``jax.numpy``)."""

from __future__ import annotations

import ast
import math
from collections.abc import Callable
from typing import Any

from rigidsym.kernels.runtime.jacobians import full_batch as _full

__all__ = ["columns", "shape_outputs", "evaluate", "singular_mask", "nonfinite_rows",
           "rounds_to_inf", "propagates_inf"]


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
        # instead of n indexings, a fixed cost of a call at small N (issue 38)
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
    in a parameter the batch shares (issue 38); their outputs are then the safe point's,
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
    # a denominator that overflowed to inf flags its sample too (issue 37): x / inf = 0 is
    # a finite wrong value; eager calls re-run such samples in long double (_arrays_rescue)
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
    PyTorch): fewer nodes for inductor to compile (issue 38); no concatenation, which
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
    (issue 38)."""
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
    non-finite in every output that reads an inf input, decided from the program (issue 38):
    it uses only ``+``, ``-``, ``*``, powers with a positive integer exponent and
    :data:`_NONFINITE_IN_OUT` (each non-finite wherever an argument is: ``inf * 0`` and
    ``inf - inf`` are NaN), so by induction every value that reads an inf is inf or NaN;
    nothing maps an inf to a finite value (``1 / inf``, ``atan``, a branch condition). Then
    mapping the non-finite outputs to NaN is issue 37's rule (an inf input taken as NaN)
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
