"""JAX kernels generated from the verified chapter-3 declarations.

``pip install "rigidsym[jax]"``. The same kernels, names and positional arguments as
:mod:`rigidsym.kernels`, on JAX arrays: leading batch axes broadcast, float32 and float64,
results on the device of the inputs. The programs are those the NumPy and C kernels print
(``generated/jax``).

float64 needs JAX's ``jax_enable_x64`` flag (``jax.config.update("jax_enable_x64",
True)``); with it off, a float64 input is computed in float32, as JAX itself does, and the
first such call warns, naming the flag.

Keywords (no ``out=``, no ``threads=``: meaningless under ``jit``):

* ``check``: validate finiteness, unit vectors and rotations (a result that does not
  fit the dtype is reported either way; eager calls re-run the samples whose
  intermediates overflow or underflow in long double, as C and NumPy: docs/kernels.md);
  default ``True`` on concrete arrays; refused (``ValueError``) under ``jax.jit``,
  ``jax.vmap``, ``jax.grad`` and other tracing, where the default is ``False``.
* ``on_singular``: ``"nan"`` (NaN in exactly the singular samples) everywhere; ``"raise"``
  (:class:`~rigidsym.kernels.SingularConfigurationError`) on concrete arrays only, its
  default there; ``"nan"`` is the default while traced.

Derivatives: a kernel with a generated Jacobian kernel (``<name>_with_jacobians``) is a
``jax.custom_jvp`` whose rule is the generated forward-mode program, linear in the tangents
and equal to that verified Jacobian contracted (JAX transposes it for ``jax.grad`` and
``jax.jacrev``); the others (the branch kernels, the Euler-angle rates) are
differentiated by JAX through the generated expression, with the safe-``where`` idiom at
their branches. The JVP rule is plain differentiable arithmetic (``jax.hessian`` works). A
sample masked by ``on_singular="nan"`` has a zero gradient: its inputs are replaced by a
regular point before a traced evaluation.

Example:
    >>> import jax.numpy as jnp
    >>> from rigidsym.kernels import jax as rj
    >>> g = jax.grad(lambda w: rj.instant_screw_axis(w, jnp.zeros(3),
    ...                                              jnp.array([1.0, 0.0, 1.0]))[1])
    >>> [round(float(x), 6) for x in g(jnp.array([0.0, 0.0, 2.0]))]
    [0.25, 0.0, -0.25]
"""

from __future__ import annotations

import warnings

try:
    import jax
    import jax.numpy as jnp
except ImportError as _exc:  # pragma: no cover - exercised where JAX is absent
    raise ImportError("rigidsym.kernels.jax needs JAX: pip install 'rigidsym[jax]'") from _exc
import numpy as np

from rigidsym.kernels.arrays import evaluation as _evaluation
from rigidsym.kernels.arrays import namespace as _arrays_namespace
from rigidsym.kernels.runtime.errors import NonFiniteResultError, SingularConfigurationError

__all__ = ["load", "euler_rate_matrix", "euler_angle_rates", "euler_angles_from_rotation",
           "SingularConfigurationError",
           "NonFiniteResultError"]

_WARNED: list = []


def _traced(xs) -> bool:
    return any(isinstance(x, jax.core.Tracer) for x in xs)


def _x64_note(values) -> None:
    """Warn once that a float64 request runs in float32 (jax_enable_x64 off)."""
    if _WARNED or jax.config.jax_enable_x64:
        return
    if any(getattr(v, "dtype", None) == np.float64 for v in values):
        _WARNED.append(True)
        warnings.warn("rigidsym.kernels.jax: float64 input computed in float32 because JAX's "
                      "jax_enable_x64 flag is off (jax.config.update('jax_enable_x64', True))",
                      UserWarning, stacklevel=5)


def _float_dtype(v):
    """The dtype of a floating array (bfloat16's NumPy kind is "V": asked of JAX), else None."""
    return np.dtype(v.dtype) if jnp.issubdtype(v.dtype, jnp.floating) else None


def _dtype(values, arrays):
    """The floating dtypes of the arrays promoted as JAX does, else JAX's default float."""
    found = [x.dtype for x in arrays if _float_dtype(x) is not None]
    return jnp.result_type(*found) if found else jnp.result_type(float)


def _make(space: _evaluation.Space, name: str):
    """``f(*xs) -> (*outputs, singular)``: a ``jax.custom_jvp`` whose JVP is the generated
    Jacobian kernel, or the plain expression (no Jacobian kernel)."""
    if not space.progs.has_jacobian(name):
        # traced (maybe differentiated): safe inputs in the singular samples, inf as NaN
        return lambda *xs: space.values(name, xs, _traced(xs), _traced(xs))

    def values(*xs):
        return space.values(name, xs, finite=_traced(xs))

    f = jax.custom_jvp(values)

    divides = space.progs.divides(name)

    @f.defjvp
    def _jvp(primals, tangents):
        # a kernel that divides: the values on the safe point's inputs in the singular
        # samples too (NaN there after Space.call's mask), so that the forward temps the JVP
        # program reads are the values' own, computed once (XLA merges the two), not again
        # on other inputs (the backward reuses the forward's subexpressions)
        res = space.values(name, primals, divides, _traced(primals))
        # the generated forward-mode program, linear in the tangents (JAX transposes it)
        touts = space.jvp(name, primals, list(tangents), res[-1], _traced(primals))
        zero = np.zeros(res[-1].shape, dtype=jax.dtypes.float0)
        return res, (*touts, zero)

    return f


_LIBRARY = _evaluation.Library(
    backend="jax", xp=jnp, tracer="jax.jit / jax.vmap / jax.grad", traced=_traced,
    stop_gradient=jax.lax.stop_gradient, detach=lambda x: x,
    is_array=lambda v: isinstance(v, jax.Array),
    real=lambda v: _float_dtype(v) is not None or np.dtype(v.dtype).kind in "iu",
    dtype=_dtype, as_array=lambda v, dtype, device, name: jnp.asarray(v, dtype=dtype),
    device=lambda xs: None, host=np.asarray, make=_make, note=_x64_note,
    floats=tuple(np.dtype(t) for t in (jnp.float16, jnp.bfloat16, jnp.float32, jnp.float64)),
    float32=np.dtype(jnp.float32), finfo=jnp.finfo, cast=lambda x, dtype: x.astype(dtype),
    float_dtype=_float_dtype, finite_inside=lambda: True)

# load, the Euler-angle kernels, the lazy kernels: the same for both back-ends (arrays.namespace)
load, euler_rate_matrix, euler_angle_rates, euler_angles_from_rotation, __getattr__, __dir__, \
    _space = \
    _arrays_namespace.module_api(globals(), lambda d: _evaluation.Space(_LIBRARY, d),
                                 "JAX", "array", "JAX")
__all__ += _space().progs.kernel_names()
