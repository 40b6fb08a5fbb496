"""Jacobians of the generated kernels: ``rigidsym.kernels.jacobian(name)``.

For a kernel ``f`` with a generated ``f_with_jacobians`` (see
:mod:`rigidsym.codegen.derivatives.jacobians`), ``jacobian("f")`` is the module-level function
``rigidsym.kernels.runtime.jacobians.f_jacobian``: same arguments as ``f`` (positional or keyword,
plus ``check``, ``on_singular`` and ``threads``; no ``out``), returning ``(values, jac)`` where
``values`` is what ``f`` returns and ``jac[output][input]`` has shape ``batch + output_shape +
input_shape``, entry ``[..., i, j]`` = ``d output[i] / d input[j]`` (JAX convention), one
Jacobian per sample of the broadcast batch (never summed over a broadcast input).

The functions are created on first access (module ``__getattr__``) and cached here, so they
pickle by reference like any module-level function.
"""

from __future__ import annotations

import inspect
import math
import textwrap
from collections.abc import Callable

from rigidsym.core import kinds as _kinds
from rigidsym.kernels.runtime import state as _state

__all__ = ["jacobian", "euler_rate_matrix_jacobian"]

#: suffix of the generated kernels with Jacobians (rigidsym.codegen.derivatives.jacobians.SUFFIX)
_SUFFIX = "_with_jacobians"
_FN = "_jacobian"
_EULER = ("euler_rate_matrix",)



def _tangent_note(a: dict) -> str:
    """The kind table's note on the derivatives along a constrained argument ("" if none)."""
    k = _kinds.for_spec(a["kind"], a["shape"])
    return k.tangent.format(a=a["name"]) if k is not None else ""


def _names() -> list[str]:
    meta = _state.meta()
    found = [n for n, m in meta.items() if m["public"] and n + _SUFFIX in meta]
    found += [e for e in _EULER if any(n.startswith(e + "_") and n.endswith(_SUFFIX)
                                       for n in meta)]
    return sorted(found)


def jacobian(name: str) -> Callable:
    """The values-and-Jacobians function of kernel ``name``.

    Args:
        name: a public kernel of :mod:`rigidsym.kernels` whose outputs are one smooth
            formula (every kernel without per-sample branches), a branched Lie map whose
            branches are differentiated each with its value (``rotation_vector_from_rotation``,
            ``euler_rodrigues_from_rotation``, ``exponential_coordinates_from_transform``:
            the derivative of the branch the sample takes, the declared map's along SO(3) or
            SE(3); docs/lie-groups.md), or ``"euler_rate_matrix"``.

    Returns:
        A module-level (picklable) function with the kernel's arguments (positional or
        keyword) and ``check``, ``on_singular``, ``threads``, returning ``(values, jac)``:
        ``values`` as the kernel returns them, ``jac[output][input]`` of shape
        ``batch + output_shape + input_shape`` (``d output[i] / d input[j]`` at
        ``[..., i, j]``), per sample.

    Raises:
        TypeError: ``name`` is not a ``str``.
        ValueError: ``name`` has no generated Jacobian (the message lists those that do).

    Example:
        >>> from rigidsym import kernels
        >>> f = kernels.jacobian("kinetic_energy")
        >>> T, jac = f(I_C=[[1.0, 0, 0], [0, 2.0, 0], [0, 0, 3.0]], m=2.0,
        ...            omega=[1.0, 0.0, 0.0], c_dot=[0.0, 1.0, 0.0])
        >>> float(T), jac["T"]["c_dot"].tolist()
        (1.5, [0.0, 2.0, 0.0])
    """
    if not isinstance(name, str):
        raise TypeError(f"name: expected a kernel name (str), got {type(name).__name__} "
                        f"{name!r:.60}")
    if name not in _names():
        raise ValueError(f"name: expected a kernel with a generated Jacobian, one of "
                         f"{', '.join(_names())}; got {name!r}")
    return globals()[name + _FN] if name in _EULER else __getattr__(name + _FN)


def _split(res: tuple, args: list[dict], outs: list[dict]):
    n_out = len(outs)
    values = res[0] if n_out == 1 else tuple(res[:n_out])
    rest = iter(res[n_out:])
    jac = {o["name"]: {a["name"]: next(rest) for a in args} for o in outs}
    return values, jac


def _evaluate(jname: str, args: tuple, check: bool, on_singular: str, threads: int | None):
    """Call the generated kernel ``jname`` through the kernels' checked path (validation,
    broadcasting, singular and non-finite rows); split its outputs into values and jac."""
    meta = _state.meta()[jname]
    n_out = len(meta["outputs"]) // (1 + len(meta["args"]))
    res = _state.call(jname, tuple(args), check=check, on_singular=on_singular, threads=threads)
    return _split(res, meta["args"], meta["outputs"][:n_out])


def _doc(name: str, meta: dict) -> str:
    def shp(s):
        return "(...)" if not s else f"(..., {', '.join(map(str, s))})"
    n_out = len(meta["outputs"]) // (1 + len(meta["args"]))
    outs = meta["outputs"][:n_out]
    lines = [f"Values and Jacobians of :func:`rigidsym.kernels.{name}`.", "",
             f"    {meta['formula']}", "",
             f"Book: Eq. {', '.join('(' + i + ')' for i in meta['ids'])}; derivatives by "
             "sympy of the declared formula, before the half-angle rewrite.", "", "Args:"]
    for a in meta["args"]:
        lines.append(f"    {a['name']}: array-like {shp(a['shape'])}; {a['doc']}")
    lines += ["    check, on_singular, threads: see :mod:`rigidsym.kernels` (no ``out``).", "",
              "Returns:", "    (values, jac): values as the kernel returns them ("
              + ", ".join(f"{o['name']} {shp(o['shape'])}" for o in outs) + "); "
              "jac[output][input] of shape batch + output_shape + input_shape:"]
    for o in outs:
        for a in meta["args"]:
            lines.append(f"        jac[{o['name']!r}][{a['name']!r}]: "
                         f"{shp(tuple(o['shape']) + tuple(a['shape']))}")
    lines += ["", "Raises:", "    TypeError / ValueError: as the kernel (bad argument)."]
    if meta["singular"]:
        lines.append(f"    SingularConfigurationError: on the singular set ({meta['singular']})"
                     ", which the derivatives share, unless on_singular='nan'.")
    notes = [t for t in map(_tangent_note, meta["args"]) if t]
    lines += ["", "Notes:", "    Derivatives are in the ambient coordinates of each input."]
    for t in notes:
        lines += textwrap.wrap(t, 88, initial_indent="    ", subsequent_indent="    ")
    lines += [f"    Generated kernel {name}{_SUFFIX}: {meta['ops']} operations, math hash "
              f"{meta['hash']}."]
    return "\n".join(lines)


def _make(name: str) -> Callable:
    jname = name + _SUFFIX
    meta = _state.meta()[jname]
    P = inspect.Parameter
    sig = inspect.Signature(
        [P(a["name"], P.POSITIONAL_OR_KEYWORD) for a in meta["args"]]
        + [P("check", P.KEYWORD_ONLY, default=True),
           P("on_singular", P.KEYWORD_ONLY, default="raise"),
           P("threads", P.KEYWORD_ONLY, default=None)])

    def fn(*args, **kwargs):
        ba = sig.bind(*args, **kwargs)
        ba.apply_defaults()
        kw = dict(ba.arguments)
        check, on_singular, threads = kw.pop("check"), kw.pop("on_singular"), kw.pop("threads")
        return _evaluate(jname, tuple(kw.values()), check, on_singular, threads)

    fn.__name__ = fn.__qualname__ = name + _FN
    fn.__module__ = __name__
    fn.__doc__ = _doc(name, meta)
    fn.__signature__ = sig
    return fn


def __getattr__(attr: str):
    # module-level functions made on first access, then cached: pickle finds them by name
    if attr.endswith(_FN) and attr[:-len(_FN)] in _names() \
            and attr[:-len(_FN)] not in _EULER:
        fn = _make(attr[:-len(_FN)])
        globals()[attr] = fn
        return fn
    raise AttributeError(f"module {__name__!r} has no attribute {attr!r}")


def euler_rate_matrix_jacobian(angles, sequence: str, frame: str = "fixed", *,
                               check: bool = True, on_singular: str = "raise",
                               threads: int | None = None):
    """Euler-angle rate matrix ``W`` (``omega = W eta_dot``, Exercise 3.10) and dW/d angles.

    Args:
        angles: array-like (..., 3), the Euler angles [rad] of ``sequence``.
        sequence: one of the twelve intrinsic sequences ("ZXZ", "ZYX", ...).
        frame: "fixed" (omega in the fixed frame) or "body".
        check, on_singular, threads: see :mod:`rigidsym.kernels`.

    Returns:
        (W, jac): W (..., 3, 3); jac["W"]["angles"] (..., 3, 3, 3), entry [..., i, j, k] =
        d W[i, j] / d angles[k].

    Raises:
        ValueError: bad sequence, frame or angles.

    Example:
        >>> W, jac = euler_rate_matrix_jacobian([0.1, 0.2, 0.3], "ZYX")
        >>> jac["W"]["angles"].shape
        (3, 3, 3)
    """
    base = _state.euler_name("euler_rate_matrix", sequence, frame)
    return _evaluate(base + _SUFFIX, (angles,), check, on_singular, threads)


def full_batch(xp, v, like):
    """An output entry as an array of the batch shape (a constant entry prints as a float)."""
    return v if hasattr(v, "shape") and tuple(v.shape) == tuple(like.shape) else \
        xp.zeros_like(like) + v


def contract(xp, grads: list, jac: list, outs: list[dict], args: list[dict],
             forward: bool, singular=None) -> list:
    """Chain rule through the generated Jacobian entries ``jac`` (flat, output-major then
    input, each entry row-major ``output shape + input shape``).

    ``forward=False``: ``grads`` are the cotangents of the outputs; returns those of the
    inputs, ``sum_i g_i J_ij``. ``forward=True``: ``grads`` are the tangents of the inputs;
    returns those of the outputs, ``sum_j J_ij t_j``. A zero cotangent contributes zero
    even where ``J`` is not finite (a masked singular sample), a non-zero one NaN.
    Forward mode cannot test the tangent (its transpose must stay linear): there the
    ``singular`` samples (a boolean mask of the batch shape) get a zero derivative, their
    values being NaN or an error already.
    """
    sizes_o = [int(math.prod(o["shape"])) for o in outs]
    sizes_a = [int(math.prod(a["shape"])) for a in args]
    k = 0
    blocks = {}
    for io, no in enumerate(sizes_o):
        for ia, na in enumerate(sizes_a):
            blocks[io, ia] = jac[k:k + no * na]
            k += no * na
    if forward:
        res = []
        for io, no in enumerate(sizes_o):
            acc = 0
            for ia, na in enumerate(sizes_a):
                t = grads[ia].reshape(tuple(grads[ia].shape[:grads[ia].ndim - len(
                    args[ia]["shape"])]) + (na, 1))
                J = xp.stack([full_batch(xp, v, t[..., 0, 0]) for v in blocks[io, ia]], -1)
                J = J.reshape(tuple(t.shape[:-2]) + (no, na))
                if singular is not None:
                    J = xp.where(singular[..., None, None], 0.0, J)
                acc = acc + (J @ t)[..., 0]
            res.append(acc.reshape(tuple(acc.shape[:-1]) + tuple(outs[io]["shape"])))
        return res
    res = []
    for ia, na in enumerate(sizes_a):
        acc = 0
        for io, no in enumerate(sizes_o):
            g = grads[io]
            if g is None:
                continue
            batch = tuple(g.shape[:g.ndim - len(outs[io]["shape"])])
            g = g.reshape(batch + (no, 1))
            J = xp.stack([full_batch(xp, v, g[..., 0, 0]) for v in blocks[io, ia]], -1)
            J = J.reshape(batch + (no, na))
            acc = acc + xp.where(g == 0, 0.0, g * J).sum(-2)
        res.append(acc if not isinstance(acc, int) else None)
    return [None if r is None else r.reshape(tuple(r.shape[:-1]) + tuple(a["shape"]))
            for r, a in zip(res, args, strict=True)]
