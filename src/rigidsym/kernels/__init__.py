"""Batched NumPy/C kernels generated from the verified chapter-3 declarations.

Every kernel accepts array-likes with leading batch axes that broadcast (vectors
``(..., 3)``, matrices ``(..., 3, 3)`` row-major, twists ``[omega; v]``, wrenches ``[n; f]``,
float64; ints are converted), positionally or by keyword, validates them, calls the
generated code and returns new arrays (or fills ``out=``). The kernels are real functions
generated into ``generated/api.py`` (``rigidsym generate``), with type hints; the C is
compiled when the package is built, into an extension module with one path per CPU level
(x86-64-v2, x86-64-v3) chosen at import (:func:`build_info`). A user's kernels and a stale
editable build are compiled into the user cache, with a notice (``rigidsym build-c``).

Common keyword arguments of every kernel
(``rigidsym.codegen.backends.numpy.api_spec.COMMON_KEYWORDS``):

* ``out``: preallocated output array (a tuple for several outputs), shape batch + output.
* ``check``: validate finiteness, unit vectors and rotations (default True); ``False``
  skips only that: on valid input the same result (an overflow of the result is still
  reported), a NaN or inf input gives NaN in the outputs that depend on it (issue 37).
* ``on_singular``: ``"raise"`` (default) raises :class:`SingularConfigurationError` naming
  the argument and the batch indices (:class:`NonFiniteResultError` for an overflow);
  ``"nan"`` returns NaN in exactly those rows.
* ``threads``: worker threads of the C batch loop (a positive int, or None).

Bad input raises ``TypeError`` (str, objects, complex or bool values) or ``ValueError``
(shape, broadcasting, ragged lists, non-finite values, constraints), naming the argument.

:func:`load` builds the same namespace from any generated directory
(``rigidsym generate --out DIR``); this module's kernels are ``load()`` of the package's.

Example:
    >>> import numpy as np
    >>> from rigidsym import kernels
    >>> Q = kernels.rotation_from_natural_invariants(e=[0.0, 0.0, 1.0], phi=np.pi / 2)
    >>> Q.shape
    (3, 3)
    >>> bool(np.allclose(Q, [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=1e-15))
    True
"""

from __future__ import annotations

import types
from collections.abc import Callable
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from rigidsym.core.config import generated_dir
from rigidsym.core.files import load_module
from rigidsym.generated.api import *  # noqa: F403 - the generated kernels (true signatures)
from rigidsym.generated.api import __all__ as _KERNELS
from rigidsym.kernels.runtime import names as _names
from rigidsym.kernels.runtime import state as _state
from rigidsym.kernels.runtime.errors import NonFiniteResultError, SingularConfigurationError
from rigidsym.kernels.runtime.inputs import ORTHO_TOL as ORTHO_TOL  # the tolerances of check=True
from rigidsym.kernels.runtime.inputs import UNIT_TOL as UNIT_TOL
from rigidsym.kernels.runtime.jacobians import jacobian
from rigidsym.kernels.runtime.scale import check_threads
from rigidsym.kernels.runtime.scale import get_num_threads as get_num_threads
from rigidsym.kernels.runtime.scale import set_num_threads as set_num_threads
from rigidsym.kernels.runtime.space import KernelSpace

__all__ = ["SingularConfigurationError", "NonFiniteResultError", "use_backend", "backend",
           "swap_blocks", "load", "batch_function", "euler_rate_matrix", "euler_angle_rates",
           "jacobian", "set_num_threads", "get_num_threads", "build_info", "accuracy"]
__all__ += _KERNELS

#: names of the public generated kernels
KERNEL_NAMES = tuple(sorted(_KERNELS))
for _name in _KERNELS:  # pickled by reference through this module, which binds them on import
    globals()[_name].__module__ = __name__


def _bind_module(mod: types.ModuleType) -> KernelSpace:
    """Bind a generated ``api`` module to the kernel space of its directory."""
    here = Path(mod.__file__).resolve().parent
    if mod.__name__ == _state.PACKAGE_API:
        if _state.STATE["builtin"] is None:
            # the NumPy module names of the package's kernels are stable (tests look them up)
            _state.register_builtin(KernelSpace.from_directory(
                generated_dir(), prefix="rigidsym._generated_numpy"))
        space = _state.builtin()
    else:
        space = KernelSpace.from_directory(here)
    space.bind_api(mod)
    return space


_LOADED: dict[Path, types.ModuleType] = {}
#: names a loaded namespace exposes besides its kernels
_NAMESPACE_HELPERS = ("KERNEL_NAMES", "batch_function")


def _namespace(mod: types.ModuleType, space: KernelSpace, gdir: Path) -> types.ModuleType:
    """The namespace :func:`load` returns: the kernels of ``mod`` and the public helpers,
    nothing of the generated module's own imports (``np``, ``Any``, ...)."""
    ns = types.ModuleType(f"rigidsym.kernels.load({str(gdir)!r})",
                          f"The checked kernels generated into {gdir}.")
    for name in mod.__all__:
        setattr(ns, name, getattr(mod, name))
    ns.KERNEL_NAMES = tuple(mod.__all__)
    ns.batch_function = space.batch_function
    ns.__all__ = [*mod.__all__, *_NAMESPACE_HELPERS]
    ns._SPACE = space  # private: build_info(DIR) and tests reach the directory's space
    return ns


def load(directory: str | Path | None = None) -> types.ModuleType:
    """The checked kernel namespace of a generated directory.

    Args:
        directory: a folder as ``rigidsym generate --out DIR`` writes it (``kernels.json``,
            ``api.py``, ``numpy/``, ``c/``); default the package's own kernels.

    Returns:
        A namespace (a module object) holding only the directory's kernels, with the same
        validation, ``on_singular`` handling and C (compiled into the user cache once, with
        a notice on stderr, when no build matches; NumPy fallback without a compiler) as
        :mod:`rigidsym.kernels`, and the helpers ``KERNEL_NAMES`` (their names) and
        ``batch_function(name, backend)``. Loading the same directory twice returns the
        same namespace.

    Raises:
        TypeError: ``directory`` is not a str, a path-like or None.
        FileNotFoundError: ``directory`` has no ``kernels.json`` or ``api.py``.

    Example:
        >>> load().twist_transfer is twist_transfer
        True
    """
    directory = _names.directory(directory)
    gdir = generated_dir() if directory is None else directory.resolve()
    for f in ("kernels.json", "api.py"):
        if not (gdir / f).is_file():
            raise FileNotFoundError(f"directory: no {f} in {gdir} (run `rigidsym generate "
                                    f"--out {gdir}`)")
    if gdir in _LOADED:
        return _LOADED[gdir]
    if gdir == generated_dir().resolve():
        import rigidsym.generated.api as mod
    else:
        space = KernelSpace.from_directory(gdir)
        mod = load_module(f"{space.prefix}.api", gdir / "api.py")
    _LOADED[gdir] = ns = _namespace(mod, _bind_module(mod), gdir)
    return ns


def use_backend(name: str) -> str:
    """Select the backend of every kernel call: ``"c"`` (the compiled extension) or
    ``"numpy"``.

    ``"c"`` falls back to ``"numpy"`` with a one-time warning when no compiled module
    matches the kernels and none can be built (no compiler): the warning says how to get one.

    Args:
        name: ``"c"`` or ``"numpy"``.

    Returns:
        The backend in use after the call (``"numpy"`` when ``"c"`` fell back).

    Raises:
        TypeError: ``name`` is not a ``str``.
        ValueError: ``name`` is neither.
    """
    return _state.select(name)


def build_info(directory: str | Path | None = None) -> dict:
    """How the C kernels in use were built and which CPU path runs, in the spirit of
    ``numpy.show_runtime()``.

    Args:
        directory: a generated directory (``rigidsym generate --out DIR``); default the
            package's kernels.

    Returns:
        dict with ``path`` (the path in use, e.g. ``"x86-64-v3"``), ``paths`` (compiled, best
        first), ``forced`` (``RIGIDSYM_DISPATCH``, or None), ``openmp``, ``libmvec`` (the
        vector sin/cos variant the path calls, or None), ``file`` (the extension),
        ``origin`` (``"wheel"``, ``"editable build"``, ``"cache"`` or ``"cache (native)"``),
        ``sources`` (SHA-256 of the C it was built from), ``compiler``, ``flags``, ``cpu``
        (this machine's model) and ``build``: what the build did, or None where it left no
        record (``objects``, ``compiled``, ``reused`` from the object cache, ``seconds`` of
        wall time, ``cpu_seconds`` of the compilers, ``paths``, ``built`` (UTC),
        ``object_cache`` (its folder, or None)).

    Raises:
        TypeError: ``directory`` is not a str, a path-like or None.
        rigidsym.kernels.cbuild.extension.NoCompiledKernels: nothing compiled matches and no
        compiler
            can build it (the NumPy backend runs then).

    Example:
        >>> build_info()["path"] in build_info()["paths"]
        True
    """
    from rigidsym.kernels.cbuild import extension as _ext

    space = _state.builtin() if _names.directory(directory) is None else \
        load(directory)._SPACE
    return _ext.info(space.c_lib())


def backend() -> str:
    """The backend in use.

    Returns:
        ``"c"`` or ``"numpy"``; the first call selects ``"c"``, with the NumPy fallback.
    """
    return _state.backend()


def batch_function(name: str, backend_name: str | None = None,
                   threads: int | None = None, dtype=np.float64) -> Callable:
    """Low-level ``f(*inputs, *outputs) -> flags`` of a package kernel (for benchmarks).

    The call takes every input *and then every output*, in the kernel's order (its
    signature, ``help(kernels.NAME)``), all preallocated by the caller: C-contiguous
    ``(n, ...)`` arrays of ``dtype`` with the same leading ``n``, no validation, no
    broadcasting, no allocation. ``kernels.load(DIR).batch_function`` is the same for a
    generated directory. Passing the inputs only fails (``expected 5 arguments, got 4``
    for ``N_matrix``: ``n``, the thread count, ``e``, ``phi`` and the missing output).

    Args:
        name: a kernel's name (``"N_matrix"``).
        backend_name: ``"c"`` or ``"numpy"`` (default: the current backend).
        threads: worker threads of the C loop (default: :func:`get_num_threads`).
        dtype: ``np.float64`` or ``np.float32`` (arrays in and out of that type).

    Returns:
        ``f(*inputs, *outputs)``: for the C backend the number of flagged samples
        (singular or non-finite, written as NaN); for NumPy the ``(n,)`` uint8 flags (1
        singular, 2 non-finite output).

    Raises:
        TypeError: ``name`` not a ``str``, ``dtype`` not a dtype, ``threads`` not an int.
        KeyError: no kernel ``name`` (the message lists the close names).
        ValueError: ``backend_name`` neither ``"c"`` nor ``"numpy"``, ``dtype`` neither
            float64 nor float32, ``threads`` < 1.

    Example:
        >>> import numpy as np
        >>> f = batch_function("N_matrix", "numpy")
        >>> e, phi = np.tile([0.0, 0.6, 0.8], (4, 1)), np.linspace(0.5, 2.0, 4)
        >>> N = np.empty((4, 4, 3))           # the output, (n, 4, 3), preallocated
        >>> int(np.sum(f(e, phi, N)))         # no flagged sample
        0
        >>> bool(np.allclose(N, N_matrix(e, phi)))
        True
    """
    space = _state.builtin()
    _names.kernel_name(name, space.meta)
    if backend_name is not None and backend_name not in ("c", "numpy"):
        raise ValueError(f"backend_name: expected 'c', 'numpy' or None, got {backend_name!r}")
    if threads is not None:
        check_threads(threads, "threads")
    return space.batch_function(name, backend_name, threads, _names.dtype(dtype))


def accuracy(name: str) -> dict:
    """The measured accuracy of a package kernel (issue 30; ``docs/accuracy.md``).

    Read from the data shipped with the generated kernels (``kernels.json``, written by
    ``rigidsym generate`` from ``benchmarks/accuracy.py --data``): exact points over the
    kernel's regimes (random; angles to 0 and pi; rotations to 1 and a half turn; norms to
    0; gimbal lock; scales 1e-6..1e6; unit inputs a few ulps off), rounded to the type, against
    the declared formula in ``arb`` ball arithmetic, C and NumPy.

    Args:
        name: a kernel's name: public, ``<name>_with_jacobians`` or an Euler-angle variant
            (``euler_angle_rates_zyz_body``).

    Returns:
        dict: a new one each call, with ``"float64"`` and ``"float32"``, each ``{"bound",
        "regime", "kappa", "err", "ulps", "flagged", "beyond", "spurious", "rule",
        "backends"}``, where the normwise relative error of every output is at most
        ``bound * u * (kappa + 1)`` (``u`` the unit roundoff, ``kappa`` the condition number
        on the inputs' tangent space), attained in ``regime`` (``kappa`` and ``err`` there),
        ``ulps`` the worst componentwise error (against the truth at the input as given),
        ``rule`` the worst ratio to issue 37's rule
        (``err <= 8 u (kappa + 1)`` and ``err <= max(2 e_ref, 4 u)``, ``e_ref`` the smallest
        error of the textbook formula and of the peers: ``docs/accuracy.md``), ``backends``
        per back-end ``{"err_u", "vs_ref", "vs_ref_where", "rule"}`` (the worst error in u,
        the worst ratio to ``e_ref`` where ``e_ref > 2 u`` and where); ``regimes`` swept;
        ``seeds`` (the seeds of the regimes' random points the bound was measured over);
        ``accurate`` (every regime within the rule); ``singular`` (the set) and
        ``threshold`` (where a sample is flagged, in units of the input).

    Raises:
        TypeError: ``name`` is not a ``str``.
        KeyError: no kernel ``name`` (the message lists the close names), or one without
            measured accuracy.
    """
    meta = _state.meta()
    _names.kernel_name(name, meta)
    row = meta[name].get("accuracy")
    if not row:
        raise KeyError(f"name: kernel {name!r} has no measured accuracy")
    return {k: dict(v) if isinstance(v, dict) else v for k, v in row.items()}


def euler_rate_matrix(angles: ArrayLike, sequence: str, frame: str = "fixed", *,
                      out: NDArray[np.float64] | None = None, check: bool = True,
                      threads: int | None = None) -> NDArray[np.floating]:
    """Euler-angle rate matrix ``W`` with ``omega = W eta_dot`` (Exercise 3.10).

    Args:
        angles: array-like (..., 3), the intrinsic Euler angles [rad] of ``sequence``.
        sequence: one of the twelve intrinsic sequences ("ZXZ", "ZYX", ...).
        frame: "fixed" (omega in the fixed frame) or "body".
        out, check, threads: see :mod:`rigidsym.kernels`.

    Returns:
        ndarray (..., 3, 3) [1].

    Raises:
        TypeError, ValueError: bad input, naming the argument (also a bad ``sequence`` or
            ``frame``).

    Example:
        >>> euler_rate_matrix([0.1, 0.2, 0.3], "ZYX").shape
        (3, 3)
    """
    return _state.call(_state.euler_name("euler_rate_matrix", sequence, frame), (angles,),
                       out=out, check=check, threads=threads)


def euler_angle_rates(angles: ArrayLike, omega: ArrayLike, sequence: str,
                      frame: str = "fixed", *, out: NDArray[np.float64] | None = None,
                      check: bool = True, on_singular: str | None = None,
                      threads: int | None = None) -> NDArray[np.floating]:
    """Euler-angle rates ``eta_dot = W^-1 omega`` (Exercise 3.10).

    Args:
        angles: array-like (..., 3) [rad].
        omega: array-like (..., 3) [rad/s], in the frame given by ``frame``.
        sequence: one of the twelve intrinsic sequences.
        frame: "fixed" or "body".
        out, check, on_singular, threads: see :mod:`rigidsym.kernels`.

    Returns:
        ndarray (..., 3) [rad/s].

    Raises:
        TypeError, ValueError: bad input, naming the argument.
        SingularConfigurationError: at gimbal lock (det W = 0), unless on_singular="nan".

    Example:
        >>> euler_angle_rates([0.1, 0.2, 0.3], [0.0, 0.0, 1.0], "ZYX").shape
        (3,)
    """
    return _state.call(_state.euler_name("euler_angle_rates", sequence, frame), (angles, omega),
                       out=out, check=check, on_singular=on_singular, threads=threads)


def swap_blocks(x: ArrayLike, matrix: bool = False) -> NDArray[np.floating]:
    """Swap the 3-blocks of 6-arrays: ``[omega; v] <-> [v; omega]``, ``[n; f] <-> [f; n]``.

    Converts to and from the order of Pinocchio and ROS. With ``matrix=True`` a
    ``(..., 6, 6)`` operator is converted (rows and columns).

    Args:
        x: array-like (..., 6), or (..., 6, 6) with ``matrix=True``.
        matrix: convert an operator instead of a vector.

    Returns:
        ndarray of the shape of ``x``.

    Raises:
        TypeError, ValueError: ``x`` not real numbers, or of the wrong trailing shape;
            ``matrix`` not a bool.

    Example:
        >>> swap_blocks([1, 2, 3, 4, 5, 6]).tolist()
        [4.0, 5.0, 6.0, 1.0, 2.0, 3.0]
    """
    from rigidsym.kernels.runtime.inputs import as_array

    shape = (6, 6) if _names.flag(matrix, "matrix") else (6,)
    a = as_array(x, {"name": "x", "tshape": shape})
    perm = [3, 4, 5, 0, 1, 2]
    return a[..., perm, :][..., perm] if matrix else a[..., perm]


# the package's kernels are load() of its generated directory (binds generated.api here)
load()
