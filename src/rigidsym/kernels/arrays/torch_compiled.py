"""The PyTorch kernels' functions under ``torch.compile`` (the first compile;
split from :mod:`rigidsym.kernels.torch`): the ``torch.autograd.Function`` of a traced call
of a kernel with ``SAVED`` programs, made one call in Dynamo's graph."""

from __future__ import annotations

import torch

from rigidsym.kernels.arrays.evaluation import (
    Space,
    columns,
    cotangents,
    shape_outputs,
    singular_mask,
)
from rigidsym.kernels.arrays.rescue import finite_columns
from rigidsym.kernels.runtime.jacobians import full_batch

__all__ = ["compiled_saving", "in_graph", "fixed_arity", "nonfinite"]


def fixed_arity(values, n: int):
    """``forward(x0, ..., x{n-1})``: Dynamo reads a ``forward(*xs)`` as taking ``ctx``
    first, so the arity is spelled out (the kernels' argument counts differ)."""
    params = ", ".join(f"x{i}" for i in range(n))
    scope: dict = {"values": values}
    exec(f"def forward({params}):\n    return values(({params},))\n", scope)  # noqa: S102
    return scope["forward"]


def compiled_saving(space: Space, name: str):
    """The ``torch.autograd.Function`` of a traced call (torch.compile) of a kernel with
    ``SAVED`` programs (the first compile: fewer operations for Dynamo to trace
    and inductor to compile): the forward returns, as non-differentiable outputs after the
    mask, the temps the VJP reads; the backward takes them, no forward temp computed again,
    and sets the input cotangents of the flagged samples (singular, or a result that
    overflowed; their output cotangents are zero) to zero after the VJP, whose arithmetic
    may be NaN there. A backward differentiated again recomputes, as
    :func:`rigidsym.kernels.torch._function`'s
    (the safe point's inputs in the flagged samples, so that no NaN reaches the second
    derivative)."""
    meta, xp = space.progs.meta[name], torch
    nargs, nout = len(meta["args"]), len(meta["outputs"])
    forward, vjp = space.progs.vjp(name, "saved")
    inf = space.progs.propagates_inf(name)

    def values(xs):
        # an inf input taken as NaN inside, as Space.values(finite=True)
        cols = raw = columns(xs, meta["args"])
        if not inf:
            cols = finite_columns(cols)
        outs, dens, temps = forward(*cols)
        # the samples whose result does not fit the dtype, from finite inputs (Space.call's
        # rule), found here on the columns: pointwise, fused into the program's kernel
        # (on the stacked outputs it was a reduction per output and per input, a buffer
        # each for inductor)
        sing = singular_mask(xp, dens, cols[0]) | (
            nonfinite(outs, cols[0]) & ~nonfinite(raw, cols[0]))
        # NaN in the flagged samples here, column by column (Space.call's where on the
        # stacked outputs read each stack once more: a buffer each for inductor); a program
        # that keeps inf inputs: its non-finite outputs NaN too, as Space.call's
        outs = [torch.where(sing | torch.isinf(v) if inf else sing, torch.nan, v)
                for v in (full_batch(xp, v, cols[0]) for v in outs)]
        return (*shape_outputs(xp, outs, meta["outputs"], cols[0]), sing, *temps)

    def setup_context(ctx, inputs, output):
        ctx.save_for_backward(*inputs, *output[nout:])
        ctx.mark_non_differentiable(*output[nout:])

    def backward(ctx, *grads):
        saved = ctx.saved_tensors
        xs, sing, temps = saved[:nargs], saved[nargs], saved[nargs + 1:]
        if torch.is_grad_enabled():  # the safe point's inputs in the flagged samples
            return tuple(torch.where(sing.reshape(sing.shape + (1,) * (g.ndim - sing.ndim)),
                                     0.0, g)
                         for g in space.vjp(name, xs, list(grads[:nout]), sing))
        # the flagged samples' outputs are NaN whatever the inputs: their inputs'
        # cotangents zero, set after the VJP, which may be NaN there (0 * inf)
        cols = columns(xs, meta["args"])
        flat = vjp(*cols, *temps, *cotangents(list(grads[:nout]), meta["outputs"]))
        flat = [torch.where(sing, 0.0, full_batch(xp, v, cols[0])) for v in flat]
        return tuple(shape_outputs(xp, flat, meta["args"], cols[0]))

    fn = type(f"{name}_compiled_saving_function", (torch.autograd.Function,), {
        "generate_vmap_rule": True, "setup_context": staticmethod(setup_context),
        "backward": staticmethod(backward), "forward": staticmethod(fixed_arity(
            values, nargs))})
    # Space.call: its mask holds the overflowed samples, its outputs are NaN where flagged
    fn.flags_overflow = True
    return fn


def nonfinite(cols, like):
    """The batch mask of the samples with an inf or NaN among ``cols`` (scalar columns or
    constants): one NaN-propagating sum of ``0.0 * c`` (a float zero: inductor folds an
    integer ``x * 0`` to zeros, which hid every overflow under torch.compile)."""
    total = torch.zeros_like(like)
    for c in cols:
        total = total + c * 0.0
    return torch.isnan(total)


def in_graph(cls, nout: int):
    """``cls.apply`` (its outputs and mask) as one call in Dynamo's graph
    (``torch.compiler.allow_in_graph``): Dynamo does not trace its Python bytecode by
    bytecode, AOTAutograd traces the forward and the backward at tensor-operation level
    (the first compile: Dynamo's trace of the Function's forward, backward and
    outputs took ~0.8 s of ``instant_screw_axis``'s, the hand-written formula's whole trace
    ~0.2 s). Sound here: the function reads no Python state a guard would have to
    watch (the kernel's programs are fixed; the inputs' dtypes and devices Dynamo guards on
    the tensors) and mutates none."""
    def call(*xs):
        return cls.apply(*xs)[:nout + 1]

    return torch.compiler.allow_in_graph(call)
