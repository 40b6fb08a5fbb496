"""The eager CPU route of the PyTorch kernels' value + gradient.

At a small batch the cost of an eager step is a fixed cost per operation, not arithmetic:
the generated program works on one tensor per scalar component, and each of its ~50-180
operations is a PyTorch dispatch of ~1.6-3 us at N = 1e3 (Python binding, dispatcher,
TensorIterator), where NumPy's is ~0.6 us. So for an eager call on CPU tensors outside
``torch.func`` and ``torch.compile`` (:func:`rigidsym.kernels.torch._saving`), the forward
that saves its temps and the VJP that takes them run on NumPy views of the tensors' memory
(no copy in, one ``torch.from_numpy`` per result out). The same generated source runs with
its ``torch`` bound to :data:`_SHIM`: ``+``, ``-``, ``*``, ``/`` are NumPy's, correctly
rounded as PyTorch's, so bit for bit the same; every named function (``sin``, ``cos``,
``sqrt``, ``atan2``, ``where``, comparisons) is PyTorch's own on the same memory, so the
results are the PyTorch program's bit for bit (PyTorch's ``sqrt`` is not NumPy's: it rounds
some values the other way) and dtype promotion is PyTorch's (``torch.where(c, -1.0, 1.0)``
is of the default dtype). tests/test_torch_kernels.py compares the two routes on every
kernel that has them. No gradient is recorded here: this is the inside of a custom
``autograd.Function``; double backward (``create_graph=True``) and singular samples take
the PyTorch programs.
"""

from __future__ import annotations

import math

import numpy as np
import torch

from rigidsym.kernels.arrays.evaluation import columns, shape_outputs, singular_mask

__all__ = ["programs", "forward", "vjp", "views", "GRAIN"]

#: the largest batch this route takes: PyTorch's grain size (``at::internal::GRAIN_SIZE``),
#: below which its elementwise operations run on one thread anyway; a larger batch is
#: arithmetic, not dispatch, and PyTorch may spread it over its threads
GRAIN = 32768


def _routed(fn):
    """PyTorch's ``fn`` on NumPy arrays (zero-copy both ways)."""
    def call(*args):
        return fn(*(torch.from_numpy(a) if type(a) is np.ndarray else a
                    for a in args)).numpy()
    return call


class _Torch:
    """What a generated program reads from ``torch``: its functions, routed (cached)."""

    float32 = np.dtype(np.float32)  # ``a.dtype == torch.float32`` in the compensated sums
    float64 = np.dtype(np.float64)

    def __getattr__(self, name: str):
        fn = _routed(getattr(torch, name))
        setattr(self, name, fn)
        return fn


_SHIM = _Torch()


def programs(progs, name: str):
    """``(forward, vjp)``: the ``SAVED`` programs of kernel ``name``'s generated PyTorch
    module with ``torch`` bound to :data:`_SHIM` (cached on ``progs``), or None without
    them."""
    key = ("host", name)
    got = progs._programs.get(key)
    if got is None:
        if progs.vjp(name, "saved") is not None:
            path = progs.directory / progs.backend / f"{name}.py"
            scope = {"__name__": f"rigidsym._torch_host.{name}", "torch": _SHIM}
            source = path.read_text(encoding="utf-8").replace("\nimport torch\n", "\n", 1)
            exec(compile(source, str(path), "exec"), scope)  # noqa: S102 - our own output
            got = scope["SAVED"]
        progs._programs[key] = got or False
    return got or None


def _host(x):
    """A NumPy view of a CPU float32/float64 tensor of at least one dimension, else None."""
    d = x.detach()
    if type(d) is not torch.Tensor or d.device.type != "cpu" or d.is_neg() or \
            d.dtype not in (torch.float32, torch.float64) or d.ndim == 0:
        return None
    return d.numpy()


def forward(progs, name: str, xs):
    """``(outputs, singular, temps, regular)`` of kernel ``name`` on the broadcast inputs
    ``xs`` (tensors out, NumPy temps for :func:`vjp`, ``regular``: no sample singular), or
    None where this route does not apply (not all CPU float tensors, a batch of no
    dimension or of more than :data:`GRAIN` samples, no ``SAVED`` programs)."""
    prog = programs(progs, name)
    if prog is None:
        return None
    arrays = [_host(x) for x in xs]
    meta = progs.meta[name]
    if any(a is None for a in arrays):
        return None
    batch = arrays[0].shape[:arrays[0].ndim - len(meta["args"][0]["shape"])]
    if not batch or math.prod(batch) > GRAIN:
        return None
    cols = columns(arrays, meta["args"])
    with np.errstate(all="ignore"):  # IEEE results, as PyTorch's (the mask flags them)
        outs, dens, temps = prog[0](*cols)
        res = shape_outputs(np, list(outs), meta["outputs"], cols[0])
        sing = singular_mask(np, dens, cols[0])
    return _tensors(res), torch.from_numpy(sing), temps, not sing.any()


def vjp(progs, name: str, xs, temps, grads):
    """The cotangents of the inputs ``xs`` (tensors) from those of the outputs ``grads``
    (tensors or None), on the forward's NumPy ``temps`` (:func:`forward`), as tensors; None
    where a cotangent is not a CPU tensor of the dtype."""
    meta, dtype = progs.meta[name], xs[0].detach().numpy().dtype
    gcols = []
    for g, o in zip(grads, meta["outputs"], strict=True):
        if g is None:
            gcols += [0.0] * int(math.prod(o["shape"]))
            continue
        a = _host(g)
        if a is None or a.dtype != dtype:
            return None
        gcols += columns([a], [o])  # autograd gives each the shape of its output
    cols = columns([x.detach().numpy() for x in xs], meta["args"])
    with np.errstate(all="ignore"):
        flat = programs(progs, name)[1](*cols, *temps, *gcols)
        res = shape_outputs(np, list(flat), meta["args"], cols[0])
    return _tensors(res)


def _tensors(res: list) -> list:
    """The results as tensors, copied where one may be another's memory (a result may be
    a component of an input or of a cotangent, a view of a tensor's memory): an array an
    operation made owns its memory, one stacked by ``shape_outputs`` is a view of a new
    stack that does."""
    return [torch.from_numpy(r if r.flags.owndata or (isinstance(r.base, np.ndarray) and
                                                      r.base.flags.owndata) else np.array(r))
            for r in res]


def views(tensors: list):
    """NumPy views of eager CPU tensors (the screen of :mod:`.rescue`), or None
    where one is not (a GPU, a tensor subclass, a negative view, a traced tensor)."""
    out = []
    for x in tensors:
        d = x.detach()
        if type(d) is not torch.Tensor or d.device.type != "cpu" or d.is_neg() or \
                torch.compiler.is_compiling():
            return None
        out.append(d.numpy())
    return out
