"""The namespace of an array back-end module, its public face: the kernels'
functions with their real signatures and docstrings, the namespace of a generated directory
(``load``), and the module-level functions of ``rigidsym.kernels.torch`` and ``.jax``
(:func:`module_api`). No import of either library.
"""

from __future__ import annotations

import types
from collections.abc import Callable
from pathlib import Path

from rigidsym.kernels.arrays.evaluation import SUFFIX, ArraySpace
from rigidsym.kernels.arrays.inputs import shape_text
from rigidsym.kernels.runtime import names as _names
from rigidsym.kernels.runtime import screw_at_infinity as _infinity
from rigidsym.kernels.runtime import state as _state

__all__ = ["docstring", "make_kernel", "namespace", "module_api"]


def docstring(meta: dict, backend: str, derivative: str) -> str:
    """The docstring of a back-end kernel, from its ``kernels.json`` entry."""
    lib = {"torch": "torch.Tensor", "jax": "jax.Array"}[backend]
    lines = [meta["summary"], "", f"    {meta['formula']}", "",
             f"Book: Eq. {', '.join('(' + i + ')' for i in meta['ids'])}.", "", "Args:"]
    for a in meta["args"]:
        lines.append(f"    {a['name']}: {lib} or array-like {shape_text(a['shape'])}; {a['doc']}")
    lines += [f"    check, on_singular: see :mod:`rigidsym.kernels.{backend}`.", "",
              "Returns:"]
    lines += [f"    {lib} {shape_text(o['shape'])}: {o['name']}" for o in meta["outputs"]]
    lines += ["", "Raises:", "    TypeError, ValueError: bad argument (naming it), or check=True"
              " / on_singular='raise' while traced."]
    infinity = _infinity.note(meta["name"])
    if infinity is not None:   # the singular set is no motion (load) alone
        arg, what = _infinity.NO_MOTION[meta["name"]]
        lines.append(f"    SingularConfigurationError: {what} (naming {arg!r}), eager and "
                     f"on_singular='raise'.")
    elif meta["singular"]:
        lines.append(f"    SingularConfigurationError: on the singular set "
                     f"({meta['singular']}), eager and on_singular='raise'.")
    lines += ["", "Notes:"] + ([f"    {infinity}"] if infinity is not None else []) + [
              f"    Derivative: {derivative}",
              f"    Generated; {meta['ops']} operations; math hash {meta['hash']}."]
    return "\n".join(lines)


def make_kernel(progs: ArraySpace, call: Callable, name: str, module: str) -> Callable:
    """The public function of kernel ``name``: the kernel's arguments (positional or
    keyword), then ``check`` and ``on_singular`` (keyword-only); ``call(name, values,
    check, on_singular)`` evaluates it."""
    meta = progs.meta[name]
    names = [a["name"] for a in meta["args"]]
    params = ", ".join(names)
    # a def of its own per kernel (not one closure for all): its real signature, and a code
    # object of its own, so torch.compile's per-code-object recompile limit (8) is not
    # shared by every kernel a program compiles
    scope: dict = {"_call": call}
    exec(f"def {name}({params}, *, check=None, on_singular=None):\n"  # noqa: S102
         f"    return _call({name!r}, ({params},), check, on_singular)\n", scope)
    fn = scope[name]
    fn.__name__ = fn.__qualname__ = name
    fn.__module__ = module
    lib = {"torch": "torch.autograd.Function", "jax": "jax.custom_jvp"}[progs.backend]
    deriv = (f"the generated vector-Jacobian and Jacobian-vector products, equal to the "
             f"generated Jacobian kernel {name}{SUFFIX} contracted ({lib})"
             if progs.has_jacobian(name) else
             "autograd through the generated expression (safe where at branches)")
    fn.__doc__ = docstring(meta, progs.backend, deriv)
    return fn


def namespace(progs: ArraySpace, call: Callable, title: str) -> types.ModuleType:
    """A namespace (module object) with the public kernels of ``progs`` and
    ``KERNEL_NAMES``."""
    ns = types.ModuleType(title)
    names = progs.kernel_names()
    for n in names:
        setattr(ns, n, make_kernel(progs, call, n, title))
    ns.KERNEL_NAMES = tuple(names)  # type: ignore[attr-defined]
    ns.__all__ = [*names, "KERNEL_NAMES"]  # type: ignore[attr-defined]
    return ns


# --------------------------------------------------------------- a back-end module's API
_LOAD_DOC = """The {lib} kernels of a generated directory (``rigidsym generate --out DIR``).

    Args:
        directory: a folder with ``kernels.json`` and ``{backend}/``; default the package's.

    Returns:
        A namespace with one function per public kernel and ``KERNEL_NAMES``.

    Raises:
        TypeError: ``directory`` is not a str, a path-like or None.
        FileNotFoundError: no ``kernels.json`` or ``{backend}/`` there.
    """
_RATE_MATRIX_DOC = """Euler-angle rate matrix ``W`` with ``omega = W eta_dot`` (Exercise 3.10).

    Args:
        angles: {noun} (..., 3), the intrinsic Euler angles [rad] of ``sequence``.
        sequence: one of the twelve intrinsic sequences ("ZXZ", "ZYX", ...).
        frame: "fixed" (omega in the fixed frame) or "body".
        check, on_singular: see the module.

    Returns:
        {noun} (..., 3, 3); derivative: the generated Jacobian kernel.

    Raises:
        TypeError, ValueError: bad input, naming the argument.
    """
_ANGLE_RATES_DOC = """Euler-angle rates ``eta_dot = W^-1 omega`` (Exercise 3.10).

    Args:
        angles: {noun} (..., 3) [rad].
        omega: {noun} (..., 3) [rad/s], in the frame given by ``frame``.
        sequence: one of the twelve intrinsic sequences.
        frame: "fixed" or "body".
        check, on_singular: see the module.

    Returns:
        {noun} (..., 3); derivative: {autodiff} through the generated expression.

    Raises:
        TypeError, ValueError: bad input, naming the argument.
        SingularConfigurationError: at gimbal lock, eager with on_singular="raise".
    """
_EULER_ANGLES_DOC = """The intrinsic Euler angles of a rotation and the gimbal-lock flag (the
    inverse of Exercise 3.10's ``Q = R_i(a) R_j(b) R_k(c)``; derivations/euler_angles.py).

    Args:
        Q: {noun} (..., 3, 3), rotation matrices.
        sequence: one of the twelve intrinsic sequences ("ZYX", "ZXZ", ...).
        branch: "principal" (b in [-pi/2, pi/2] Tait-Bryan, [0, pi] proper Euler) or
            "other" ((a + pi, pi - b, c + pi) or (a + pi, -b, c + pi)); the same at the lock.
        check: see the module.

    Returns:
        ``(angles, gimbal_lock)``: {noun} (..., 3) [rad] and a boolean {noun} (...): at the
        lock (the first angle's two entries of Q exactly 0) the member c = 0, never NaN.

    Raises:
        TypeError, ValueError: bad input, naming the argument (also a bad ``sequence`` or
            ``branch``).
    """


def module_api(scope: dict, make_space: Callable, lib: str, noun: str,
               autodiff: str) -> tuple:
    """The module-level functions of a back-end module (``rigidsym.kernels.torch``, ``.jax``).

    Args:
        scope: the back-end module's ``globals()`` (its name; where ``__getattr__`` caches a
            kernel made on first access).
        make_space: ``make_space(directory)``, the back-end's space: ``.progs`` (an
            :class:`ArraySpace`) and ``.call(name, values, check, on_singular)``.
        lib, noun, autodiff: the words of its docstrings ("PyTorch", "tensor", "autograd").

    Returns:
        ``(load, euler_rate_matrix, euler_angle_rates, euler_angles_from_rotation,
        __getattr__, __dir__, space)``: the first six made as the module's own
        (``__module__``, ``__qualname__``, ``__doc__``: Sphinx documents them there);
        ``space(directory=None)`` caches one space a folder.
    """
    module, spaces = scope["__name__"], {}

    def space(directory=None):
        key = None if directory is None else Path(directory).resolve()
        if key not in spaces:
            spaces[key] = make_space(directory)
        return spaces[key]

    def load(directory: str | Path | None = None) -> types.ModuleType:
        s = space(_names.directory(directory))  # a wrong type: TypeError naming it
        return namespace(s.progs, s.call, f"{module}.load({str(directory)!r})")

    def euler_rate_matrix(angles, sequence: str, frame: str = "fixed", *, check=None,
                          on_singular=None):
        name = _state.euler_name("euler_rate_matrix", sequence, frame)
        return space().call(name, (angles,), check, on_singular)

    def euler_angle_rates(angles, omega, sequence: str, frame: str = "fixed", *, check=None,
                          on_singular=None):
        name = _state.euler_name("euler_angle_rates", sequence, frame)
        return space().call(name, (angles, omega), check, on_singular)

    def euler_angles_from_rotation(Q, sequence: str, *, branch: str = "principal",
                                   check=None):
        if branch not in ("principal", "other"):
            raise ValueError(f"branch: expected 'principal' or 'other', got {branch!r}")
        seq = _state.euler_name("euler_rate_matrix", sequence, "fixed").split("_")[-2]
        angles, other, lock = space().call(f"euler_angles_from_rotation_{seq}", (Q,), check,
                                           None)
        return (angles if branch == "principal" else other), lock != 0

    def __getattr__(attr: str):
        # the package's kernels, made on first access (importing the module stays cheap)
        s = space()
        if attr in s.progs.kernel_names():
            fn = scope[attr] = make_kernel(s.progs, s.call, attr, module)
            return fn
        raise AttributeError(f"module {module!r} has no attribute {attr!r}")

    def __dir__():
        return sorted([*scope, *space().progs.kernel_names()])

    words = {"lib": lib, "noun": noun, "autodiff": autodiff, "backend": space().progs.backend}
    docs = {load: _LOAD_DOC, euler_rate_matrix: _RATE_MATRIX_DOC,
            euler_angle_rates: _ANGLE_RATES_DOC,
            euler_angles_from_rotation: _EULER_ANGLES_DOC, __getattr__: None, __dir__: None}
    for fn, doc in docs.items():
        fn.__module__, fn.__qualname__ = module, fn.__name__
        fn.__doc__ = None if doc is None else doc.format(**words)
    return (load, euler_rate_matrix, euler_angle_rates, euler_angles_from_rotation,
            __getattr__, __dir__, space)
