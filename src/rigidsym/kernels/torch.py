"""PyTorch kernels generated from the verified chapter-3 declarations.

``pip install "rigidsym[torch]"``. The same kernels, names and positional arguments as
:mod:`rigidsym.kernels`, on tensors: leading batch axes broadcast, float32 and float64
(the promoted dtype of the tensor and NumPy inputs; Python numbers and lists alone take
``torch.get_default_dtype()``), every result on the device of the inputs (no host copy).
The programs are those the NumPy and C kernels print (``generated/torch``).

Keywords (no ``out=``, no ``threads=``: meaningless or harmful under autograd and
``torch.compile``):

* ``check``: validate finiteness, unit vectors and rotations (a result that does not
  fit the dtype is reported either way; eager calls re-run the samples whose
  intermediates overflow or underflow in long double, as C and NumPy: docs/kernels.md);
  default ``True`` in eager mode; refused (``ValueError``) under ``torch.compile`` and
  ``torch.func`` transforms, where the default is ``False`` (no host synchronisation).
* ``on_singular``: ``"nan"`` (NaN in exactly the singular samples) everywhere; ``"raise"``
  (:class:`~rigidsym.kernels.SingularConfigurationError` with the batch indices) in eager
  mode only, its default there; ``"nan"`` is the default while traced.

Derivatives: a kernel with a generated Jacobian kernel (``<name>_with_jacobians``) is a
``torch.autograd.Function`` (``setup_context``, a generated vmap rule, ``backward`` and
``jvp``, taken by calls on forward-mode dual tensors and under torch.func; no ``jvp`` under
``torch.compile``, whose Dynamo cannot trace one) whose
backward and jvp are the generated vector-Jacobian and Jacobian-vector products (reverse and
forward mode over the program, equal to that verified Jacobian contracted), plain tensor
arithmetic that autograd
differentiates again (``create_graph=True``). The others (the branch kernels, the
Euler-angle rates) are differentiated by autograd through the generated expression, with the
safe-``where`` idiom at their branches. A sample masked by ``on_singular="nan"`` has a zero
gradient: its inputs are replaced by a regular point before a differentiated evaluation.
Eager calls on CPU tensors (batch <= 32768, outside torch.func) run the same programs on
NumPy views of the tensors, PyTorch's own functions routed, bit for bit the same results at
~1/3 the fixed cost per operation (:mod:`rigidsym.kernels.arrays.torch_host`).

Example:
    >>> import torch
    >>> from rigidsym.kernels import torch as rk
    >>> f64 = torch.float64
    >>> omega = torch.tensor([[0.0, 0.0, 2.0]], dtype=f64, requires_grad=True)
    >>> a, a_dot = torch.zeros(1, 3, dtype=f64), torch.tensor([[1.0, 0.0, 1.0]], dtype=f64)
    >>> p0, pitch, plucker = rk.instant_screw_axis(omega, a, a_dot)
    >>> pitch.sum().backward()
    >>> omega.grad.tolist()
    [[0.25, 0.0, -0.25]]
"""

from __future__ import annotations

try:
    import torch
except ImportError as _exc:  # pragma: no cover - exercised where PyTorch is absent
    raise ImportError("rigidsym.kernels.torch needs PyTorch: pip install "
                      "'rigidsym[torch]'") from _exc
import numpy as np

from rigidsym.kernels.arrays import evaluation as _evaluation
from rigidsym.kernels.arrays import namespace as _arrays_namespace
from rigidsym.kernels.arrays import torch_host as _torch_host
from rigidsym.kernels.arrays.torch_compiled import compiled_saving as _compiled_saving
from rigidsym.kernels.arrays.torch_compiled import fixed_arity as _fixed_arity
from rigidsym.kernels.arrays.torch_compiled import in_graph as _in_graph
from rigidsym.kernels.runtime.errors import NonFiniteResultError, SingularConfigurationError

__all__ = ["load", "euler_rate_matrix", "euler_angle_rates", "euler_angles_from_rotation",
           "SingularConfigurationError",
           "NonFiniteResultError"]


def _traced(xs) -> bool:
    return torch.compiler.is_compiling() or any(
        torch._C._functorch.is_functorch_wrapped_tensor(x) for x in xs)


_EAGER_ONLY = ("rigidsym.kernels.torch: check=True and on_singular='raise' need eager mode; "
               "under torch.compile leave them unset (check=False, on_singular='nan')")


def _needs_eager_mode(exc_type: type, message: str):
    """Raise a refusal outside Dynamo's trace: raised while traced, it made Dynamo mark the
    kernel's code objects to skip, so that a later fullgraph compile of the same kernel ran
    them eagerly and failed on a nested frame (torch 2.13)."""
    raise exc_type(message)


try:
    _refuse = torch.compiler.disable(_needs_eager_mode, reason=_EAGER_ONLY)
except TypeError:  # torch < 2.7: no reason; Dynamo's message names the function
    _refuse = torch.compiler.disable(_needs_eager_mode)


_FLOATS = (torch.float16, torch.bfloat16, torch.float32, torch.float64)
_NUMPY = {np.dtype(np.float16): torch.float16, np.dtype(np.float32): torch.float32,
          np.dtype(np.float64): torch.float64}


def _float_dtype(v):
    """The torch dtype of a floating tensor or NumPy array (a NumPy float torch lacks: its
    NumPy dtype, refused by the caller), else None."""
    if isinstance(v, torch.Tensor):
        return v.dtype if v.dtype.is_floating_point else None
    return _NUMPY.get(v.dtype, v.dtype) if v.dtype.kind == "f" else None


def _dtype(values, arrays) -> torch.dtype:
    """torch's promotion of the floating tensors and NumPy arrays among the raw ``values``:
    the dimensioned ones decide, else the zero-dimensional ones (``torch.ones(3,
    dtype=float32) * torch.tensor(2.0, dtype=float64)`` is float32); Python numbers and
    lists are weak, as in torch; none at all: the default dtype."""
    dt = _same_float(values)
    if dt is not None:
        return dt
    found = [(v.ndim > 0, _float_dtype(v)) for v, x in zip(values, arrays, strict=True)
             if isinstance(v, torch.Tensor | np.ndarray) and _float_dtype(x) is not None]
    found = [d for dim, d in found if dim] or [d for _, d in found]
    if not found:
        return torch.get_default_dtype()
    dt = found[0]
    for d in found[1:]:
        dt = torch.promote_types(dt, d)
    return dt


def _same_float(values):
    """The dtype of ``values`` when all are dimensioned floating tensors of one dtype (the
    common case), else None: a loop Dynamo traces quickly (the general rule of
    :func:`_dtype` cost 0.6 s of Dynamo's tracing of a call under torch.compile, a third of
    it)."""
    dt = None
    for v in values:
        if not (isinstance(v, torch.Tensor) and v.ndim > 0 and v.dtype.is_floating_point) \
                or (dt is not None and v.dtype != dt):
            return None
        dt = v.dtype
    return dt


def _as_tensor(v, dtype, device, name: str) -> torch.Tensor:
    if isinstance(v, torch.Tensor):
        if v.device != device:
            raise ValueError(f"{name}: on {v.device}, the other inputs on {device}")
        return v if v.dtype == dtype else v.to(dtype)
    return torch.as_tensor(v, dtype=dtype, device=device)


def _differentiable(xs) -> bool:
    """Autograd may run through ``xs``: grad mode with an input requiring grad, or a
    torch.func transform (its wrapped tensors)."""
    return (torch.is_grad_enabled() and any(x.requires_grad for x in xs)) or any(
        torch._C._functorch.is_functorch_wrapped_tensor(x) for x in xs)


def _function(space: _evaluation.Space, name: str, forward_mode: bool):
    """The ``torch.autograd.Function`` of kernel ``name``: backward (and, ``forward_mode``,
    jvp) through the generated Jacobian kernel. Dynamo cannot trace a custom ``jvp``
    ("Unsupported custom jvp"), so compiled code gets the class without it (no forward
    mode under torch.compile)."""
    args = space.progs.meta[name]["args"]

    def setup_context(ctx, inputs, output):
        # the singular mask too: the Jacobian takes safe inputs there (_evaluation.evaluate)
        ctx.save_for_backward(*inputs, output[-1])
        if forward_mode:
            ctx.save_for_forward(*inputs, output[-1])
        ctx.mark_non_differentiable(output[-1])

    def backward(ctx, *grads):
        # plain tensor arithmetic on the saved inputs: differentiable again
        # (create_graph=True, gradgradcheck)
        *xs, sing = ctx.saved_tensors
        return tuple(space.vjp(name, xs, list(grads[:-1]), sing))

    def jvp(ctx, *tangents):
        *xs, sing = ctx.saved_tensors
        t = [torch.zeros_like(x) if d is None else d for x, d in zip(xs, tangents, strict=True)]
        return (*space.jvp(name, xs, t, sing), None)

    # the compiled class runs only while traced: an inf input taken as NaN inside
    body = {"generate_vmap_rule": True,
            "forward": staticmethod(_fixed_arity(
                lambda xs: space.values(name, xs, finite=not forward_mode), len(args))),
            "setup_context": staticmethod(setup_context), "backward": staticmethod(backward)}
    if forward_mode:
        body["jvp"] = staticmethod(jvp)
    title = f"{name}_function" if forward_mode else f"{name}_compiled_function"
    return type(title, (torch.autograd.Function,), body)


def _make(space: _evaluation.Space, name: str):
    """The kernel's function: a ``torch.autograd.Function`` whose derivative is the
    generated Jacobian kernel, or autograd through the expression (no Jacobian kernel;
    safe inputs in the singular samples when differentiated)."""
    if not space.progs.has_jacobian(name):
        return lambda *xs: space.values(name, xs, _differentiable(xs),
                                        torch.compiler.is_compiling())
    eager, compiled = _function(space, name, True), _function(space, name, False)
    fast = _plain_apply(_saving(space, name) if space.progs.vjp(name, "saved") else eager)
    eager_apply = _plain_apply(eager) or eager.apply
    nout = len(space.progs.meta[name]["outputs"])
    if space.progs.vjp(name, "saved"):
        compiled = _compiled_saving(space, name)
    traced = _in_graph(compiled, nout)

    def apply(*xs):
        if torch.compiler.is_compiling():
            return traced(*xs)
        if fast is None or torch._C._are_functorch_transforms_active():
            return eager.apply(*xs)
        if not _recorded(xs):  # nothing to differentiate: the program alone
            host = _torch_host.forward(space.progs, name, xs)
            return space.values(name, xs) if host is None else (*host[0], host[1])
        if _dual(xs):  # forward-mode AD: the saving class has no jvp
            return eager_apply(*xs)
        return fast(*xs)

    # compiled, the mask returned holds the samples whose result overflowed (Space.call)
    apply.flags_overflow = getattr(compiled, "flags_overflow", False)
    return apply


def _saving(space: _evaluation.Space, name: str):
    """The ``torch.autograd.Function`` of eager autograd outside torch.func (the
    backward reuses the forward's common subexpressions): its forward saves the temps the
    generated VJP would compute again, and its backward takes them, unless a sample is
    singular (its VJP then runs on the safe point there) or the backward is differentiated
    (``create_graph=True``: the saved temps carry no graph), when it recomputes as
    :func:`_function`'s. An old-style ``forward(ctx, ...)``: the temps are saved from
    inside it; never traced (``apply`` takes it only in eager mode)."""
    nargs = len(space.progs.meta[name]["args"])

    def forward(ctx, *xs):
        host = _torch_host.forward(space.progs, name, xs)
        if host is not None:  # CPU tensors: the same programs on NumPy views, bit for bit
            outs, sing, ctx.host, ctx.regular = host
            ctx.save_for_backward(*xs, sing)
        else:
            outs, sing, temps = space.values_saved(name, xs)
            ctx.save_for_backward(*xs, sing, *temps)
            ctx.host = None
        ctx.mark_non_differentiable(sing)
        return (*outs, sing)

    def backward(ctx, *grads):
        saved = ctx.saved_tensors
        xs, sing, temps = saved[:nargs], saved[nargs], saved[nargs + 1:]
        if torch.is_grad_enabled() or not (
                ctx.regular if ctx.host is not None else space.regular(name, sing)):
            return tuple(space.vjp(name, xs, list(grads[:-1]), sing))
        if ctx.host is not None:
            got = _torch_host.vjp(space.progs, name, xs, ctx.host, grads[:-1])
            if got is not None:
                return tuple(got)
            temps = [torch.from_numpy(t) for t in ctx.host]
        return tuple(space.vjp_saved(name, xs, temps, list(grads[:-1])))

    return type(f"{name}_saving_function", (torch.autograd.Function,),
                {"forward": staticmethod(forward), "backward": staticmethod(backward)})


def _plain_apply(cls):
    """``cls.apply`` less what eager autograd outside torch.func does not need (
    a fixed cost of a call at small N): ``Function.apply`` binds the arguments to
    ``forward``'s signature through ``inspect`` at every call (for default values, which
    these ``forward``s have none of), then calls the C ``apply`` on the arguments with
    dead torch.func wrappers unwrapped; this calls the latter directly. None where a torch
    version lacks the internals (then ``cls.apply``)."""
    try:
        from torch._functorch.utils import unwrap_dead_wrappers
        c_apply = super(torch.autograd.Function, cls).apply
        torch._C._are_functorch_transforms_active  # noqa: B018 - present, or None below
    except (ImportError, AttributeError):  # pragma: no cover - other torch versions
        return None
    return lambda *xs: c_apply(*unwrap_dead_wrappers(xs))


def _recorded(xs) -> bool:
    """Autograd records the call: grad mode with an input requiring grad, or a forward-mode
    AD level open (``torch.autograd.forward_ad``, whose dual tensors need ``jvp``)."""
    return (torch.is_grad_enabled() and any(x.requires_grad for x in xs)) or \
        getattr(torch.autograd.forward_ad, "_current_level", 0) >= 0


def _dual(xs) -> bool:
    """A forward-mode AD level is open and an input is a dual tensor (it carries a tangent
    there): the call needs the class with ``jvp`` (:func:`_function`'s), not the saving one.
    Read only past :func:`_recorded`, so the plain call pays nothing for it."""
    level = getattr(torch.autograd.forward_ad, "_current_level", 0)
    return level >= 0 and any(
        isinstance(x, torch.Tensor) and torch.autograd.forward_ad.unpack_dual(x).tangent
        is not None for x in xs)


def _clear(mask) -> bool:
    """An eager CPU mask with no sample set (read at the cost of a reduction; never on a
    GPU, where it would synchronise, nor on a traced or fake tensor)."""
    return (type(mask) is torch.Tensor and mask.device.type == "cpu"
            and not torch.compiler.is_compiling()
            and not torch._C._functorch.is_functorch_wrapped_tensor(mask)
            and not bool(mask.any()))


class _Rescued(torch.autograd.Function):
    """Outputs whose masked rows came from the long-double rescue: the
    identity on the outputs, and a NaN derivative for the inputs of those rows wherever
    their cotangent is nonzero (autograd cannot follow the host; a zero derivative would be
    silently wrong), zero where it is zero (a loss that ignores them stays finite)."""

    @staticmethod
    def forward(rows, nout, *tensors):
        return tuple(t.clone() for t in tensors[:nout])

    @staticmethod
    def setup_context(ctx, inputs, output):
        rows, nout, *tensors = inputs
        ctx.save_for_backward(rows)
        ctx.inputs = [(t.shape, t.dtype) for t in tensors[nout:]]

    @staticmethod
    def backward(ctx, *grads):
        (rows,) = ctx.saved_tensors
        hit = torch.zeros_like(rows)
        for g in grads:
            hit = hit | (g.reshape(rows.shape + (-1,)) != 0).any(-1)
        hit = hit & rows
        bad = [torch.where(hit.reshape(rows.shape + (1,) * (len(s) - rows.ndim)),
                           torch.tensor(torch.nan, dtype=d, device=rows.device),
                           torch.tensor(0.0, dtype=d, device=rows.device)).expand(s)
               for s, d in ctx.inputs]
        return (None, None, *grads, *bad)


def _rescued(res: list, rows, xs: list) -> list:
    if not (torch.is_grad_enabled() and any(x.requires_grad for x in xs)):
        return res
    return list(_Rescued.apply(rows, len(res), *res, *xs))


_LIBRARY = _evaluation.Library(
    backend="torch", xp=torch, tracer="torch.compile / torch.func", traced=_traced,
    stop_gradient=torch.detach, detach=torch.detach,
    is_array=lambda v: isinstance(v, torch.Tensor),
    real=lambda v: v.dtype != torch.bool and not v.dtype.is_complex,
    dtype=_dtype, as_array=_as_tensor,
    device=lambda xs: next((x.device for x in xs if isinstance(x, torch.Tensor)), None),
    host=lambda x: x.cpu().numpy(), make=_make, refuse=_refuse, floats=_FLOATS,
    float32=torch.float32, finfo=torch.finfo, float_dtype=_float_dtype,
    cast=lambda x, dtype: x.to(dtype), rescued=_rescued, clear=_clear,
    constant=getattr(torch.compiler, "assume_constant_result", lambda fn: fn),
    finite_inside=torch.compiler.is_compiling, views=_torch_host.views)

# load, the Euler-angle kernels, the lazy kernels: the same for both back-ends (arrays.namespace)
load, euler_rate_matrix, euler_angle_rates, euler_angles_from_rotation, __getattr__, __dir__, \
    _space = \
    _arrays_namespace.module_api(globals(), lambda d: _evaluation.Space(_LIBRARY, d),
                                 "PyTorch", "tensor", "autograd")
__all__ += _space().progs.kernel_names()
