"""The derivative of a differentiable user's function (JAX, PyTorch) audited against the
book's at the same inputs: a wrong gradient behind a right value is a finding.

The user's Jacobian is the framework's own (``jax.jacfwd``, ``torch.autograd.functional.
jacobian``) at the input as rounded to float64; the book's is the declared formula's
derivative along each orthonormal direction of each argument's tangent space (a rotation's
``Q W_k / sqrt(2)``, a unit vector's projected axes, a free vector's axes), by central
differences of the formula in ``arb`` ball arithmetic (a step of 2^-100, at the reference's
precision plus 300 bits: the harness's condition number's derivatives). The user's
directional derivative is its Jacobian applied to the direction as its convention maps it
(the member's argument and output maps, linear ones only), and moved with the output to
its class of the same rotation (``-q``, ``(-e, -phi)``). At each input the relative error
``|D_user - D_book| / |D_book|`` over every direction is judged against ``sqrt(u)`` of the
function's float type: a NaN or a zero where the book's derivative is finite, or a
derivative of another function (a ``stop_gradient`` on the axis), is far past it; the
rounding of a derivative is far within it.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from flint import arb, ctx

from rigidsym.auditing.conventions import Member, flat
from rigidsym.auditing.targets import Target
from rigidsym.codegen.accuracy.harness import judge as J
from rigidsym.codegen.accuracy.harness import reference as R

__all__ = ["FRAMEWORKS", "differentiable", "jacobian", "book_derivatives", "GradientCheck",
           "check_gradients", "gradient_points", "LINEAR"]

#: the frameworks whose own differentiation is audited
FRAMEWORKS = ("jax", "torch")

#: the convention generators whose maps are linear (a direction maps as a value does)
LINEAR = frozenset({"blocks", "blocks_in", "blocks_out", "transpose_out", "transpose_in",
                    "degrees", "scalar_first", "blocks_matrix_out", "scalar_first_out",
                    "negated_out", "degrees_out", "degrees_all_out", "angle_first_out",
                    "other_side", "extrinsic", "inverse", "dual"})


def _flat_out(out, lib):
    outs = out if isinstance(out, (tuple, list)) else [out]
    if lib == "torch":
        import torch

        if not any(isinstance(o, torch.Tensor) and o.requires_grad for o in outs):
            # the inputs left the graph (pyquaternion's float() and NumPy arrays): autograd
            # would give a zero Jacobian, which is no derivative of the function's
            raise TypeError("the outputs are not tensors of the inputs' graph")
        return torch.cat([torch.as_tensor(o).reshape(-1).to(torch.float64) for o in outs])
    import jax.numpy as jnp

    return jnp.concatenate([jnp.ravel(jnp.asarray(o)) for o in outs])


def jacobian(func: Callable, args: list, framework: str) -> np.ndarray:
    """``d flat(func(*args)) / d flat(args)``, (outputs, inputs) float64, by ``framework``'s
    own differentiation (``"jax"``: ``jax.jacfwd``; ``"torch"``: ``torch.autograd.functional.
    jacobian``). Raises what the framework raises (a NumPy function traced by JAX), and
    TypeError where no output of a PyTorch call is in the inputs' graph (a function that
    converts its tensors to floats or NumPy arrays)."""
    if framework == "torch":
        import torch

        ts = tuple(torch.as_tensor(np.asarray(a, dtype=np.float64)) for a in args)
        Js = torch.autograd.functional.jacobian(lambda *t: _flat_out(func(*t), "torch"), ts)
        Js = Js if isinstance(Js, tuple) else (Js,)
        m = int(Js[0].shape[0])
        return np.concatenate([np.asarray(j.detach().cpu(), dtype=np.float64).reshape(m, -1)
                               for j in Js], axis=1)
    import jax
    import jax.numpy as jnp

    xs = [jnp.asarray(np.asarray(a, dtype=np.float64)) for a in args]
    Js = jax.jacfwd(lambda *a: _flat_out(func(*a), "jax"), argnums=tuple(range(len(xs))))(*xs)
    m = int(np.asarray(Js[0]).shape[0])
    return np.concatenate([np.asarray(j, dtype=np.float64).reshape(m, -1) for j in Js], axis=1)


def differentiable(func: Callable, args: list, framework: str = "") -> str:
    """The framework whose differentiation goes through ``func`` at ``args`` (``framework``
    first, the one it is called with, then JAX's where it imports), or "" where none does
    (a NumPy function)."""
    for lib in dict.fromkeys([framework, *FRAMEWORKS]):
        if not lib:
            continue
        try:
            __import__(lib)
            J_ = jacobian(func, args, lib)
        except Exception:  # noqa: BLE001, S112  (not differentiable in this framework)
            continue
        if J_.size:
            return lib
    return ""


def book_derivatives(name: str, point) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """``[(argument index, direction, derivative of the flat output)]`` of the declared
    formula of kernel ``name`` at the exact ``point``, along an orthonormal basis of each
    argument's tangent space (float64 values of ball-arithmetic central differences,
    across a removable singularity too: w = 0); [] where the formula is undefined beside
    the input."""
    k = R.kernel_of(name)
    arrays = J.round_points([point], np.float64, k)
    f = R.pick(name, [float(x) for a in arrays for x in a[0].ravel()])
    exact = [x for a in point for x in a]
    ref, prec = R.reference(f, exact)
    # where the formula is undefined at the input itself (a removable singularity, w = 0)
    # its derivative is still the difference across it: only x +- h d are evaluated
    p = (prec if ref is not None else 256) + 300
    old = ctx.prec
    ctx.prec = p
    try:
        flat_x = [arb(q) for q in exact]
        out, start = [], 0
        for i, (a, ex) in enumerate(zip(k.args, point, strict=True)):
            n = len(ex)
            size = float(sum(arb(q) ** 2 for q in ex).sqrt().mid())
            h = arb(min(size, 1.0) if size > 0 else 1.0) * arb(2) ** -100
            for d in R.tangent_basis(a.kind, a.shape, ex, p):
                plus, minus = list(flat_x), list(flat_x)
                for j in range(n):
                    plus[start + j] = flat_x[start + j] + h * d[j]
                    minus[start + j] = flat_x[start + j] - h * d[j]
                fp, fm = f(*plus), f(*minus)
                der = np.array([float(((u - v) / (2 * h)).mid()) for u, v in
                                zip(fp, fm, strict=True)])
                out.append((i, np.array([float(v.mid()) for v in d]), der))
            start += n
        return out
    except (ZeroDivisionError, ValueError):
        return []
    finally:
        ctx.prec = old


@dataclass
class GradientCheck:
    """The derivative judged at one input: ``err`` (relative, over every direction), the
    ``tol`` it is judged against, and the regime."""

    regime: str
    err: float
    tol: float
    args: list


def _user_direction(member: Member, kernel, i: int, d: np.ndarray) -> np.ndarray:
    """The direction ``d`` of kernel argument ``i`` in the user's flat arguments (the
    member's argument map is linear: a direction maps as a value does)."""
    x = {a.name: np.zeros(a.shape) for a in kernel.args}
    x[kernel.args[i].name] = d.reshape(kernel.args[i].shape)
    return np.concatenate([np.ravel(np.asarray(a, dtype=np.float64))
                           for a in member.user_args(x)])


def check_gradients(func: Callable, tgt: Target, member: Member, framework: str,
                    points: list[tuple[str, list]]) -> list[GradientCheck]:
    """The user's derivative against the book's at each ``(regime, exact point)``
    (:func:`book_derivatives`), under ``member`` (its generators linear: :data:`LINEAR`;
    [] otherwise): one :class:`GradientCheck` per point where the book's derivative is
    defined and finite."""
    if not set(member.generators) <= LINEAR or tgt.antipodal == "euler":
        return []           # a branch of Euler angles: its derivative is the branch's
    name = member.kernel(tgt)
    k = R.kernel_of(name)
    sl = tgt.user_slice(k)
    out = []
    for regime, pt in points:
        ders = book_derivatives(name, pt)
        if not ders or not all(np.isfinite(d).all() for _, _, d in ders):
            continue
        arrays = J.round_points([pt], np.float64, k)
        x = {a.name: np.asarray(arrays[j][0], dtype=np.float64)
             for j, a in enumerate(k.args)}
        args = member.user_args(x)
        try:
            with np.errstate(all="ignore"):
                Ju = jacobian(func, args, framework)
                value = member.book_out(flat(func(*args)))
        except Exception:  # noqa: BLE001, S112  (it raises here: the value's audit says so)
            continue
        truth = J.run_kernel(name, arrays, np.float64, "numpy")[0][sl]
        if value.shape != truth.shape or not np.isfinite(value).all():
            continue
        sign = -1.0 if tgt.equivalent and np.linalg.norm(value + truth) < np.linalg.norm(
            value - truth) else 1.0
        if np.linalg.norm(sign * value - truth) > 1e-6 * max(np.linalg.norm(truth), 1.0):
            continue        # another value (the value's audit tells it): no derivative of it
        u_f = 2.0**-53 if np.asarray(flat(func(*args))).dtype != np.float32 else 2.0**-24
        diff = book = 0.0
        for i, d, der in ders:
            du = _user_direction(member, k, i, d)
            mine = sign * member.book_out(Ju @ du)
            want = der[sl]
            diff += float(np.sum((mine - want) ** 2)) if np.isfinite(mine).all() else math.inf
            book += float(np.sum(want ** 2))
        err = math.sqrt(diff) / max(math.sqrt(book), 1e-300)
        out.append(GradientCheck(regime, err, math.sqrt(u_f),
                                 [np.asarray(a).tolist() for a in args]))
    return out


def gradient_points(tgt: Target, member: Member, seed: int) -> list[tuple[str, list]]:
    """The inputs the derivative is judged at: the regimes' first two inputs each (the
    random ones, each approach's decades, exactly 0 of a vector, the identity), at most 40."""
    from rigidsym.auditing.worst import audit_regimes

    k = R.kernel_of(member.kernel(tgt))
    regs = audit_regimes(k, np.float64, seed)
    pts = [(r, p) for r, ps in regs.items() if not r.startswith("range ") for p in ps[:2]]
    return pts[:40]

