"""JAX kernels generated from the verified chapter-3 declarations (issue 31).

``pip install "rigidsym[jax]"``. The same kernels, names and positional arguments as
:mod:`rigidsym.kernels`, on JAX arrays: leading batch axes broadcast, float32 and float64,
results on the device of the inputs. The programs are those the NumPy and C kernels print
(``generated/jax``).

float64 needs JAX's ``jax_enable_x64`` flag (``jax.config.update("jax_enable_x64",
True)``); with it off, a float64 input is computed in float32, as JAX itself does, and the
first such call warns, naming the flag.

Keywords (no ``out=``, no ``threads=``: meaningless under ``jit``):

* ``check``: validate finiteness, unit vectors and rotations, and report an overflow;
  default ``True`` on concrete arrays; refused (``ValueError``) under ``jax.jit``,
  ``jax.vmap``, ``jax.grad`` and other tracing, where the default is ``False``.
* ``on_singular``: ``"nan"`` (NaN in exactly the singular samples) everywhere; ``"raise"``
  (:class:`~rigidsym.kernels.SingularConfigurationError`) on concrete arrays only, its
  default there; ``"nan"`` is the default while traced.

Derivatives: a kernel with a generated Jacobian kernel (``<name>_with_jacobians``) is a
``jax.custom_jvp`` whose JVP *is* that verified Jacobian (so ``jax.grad``, ``jax.jacfwd``
and ``jax.jacrev`` all use it); the others (the branch kernels, the Euler-angle rates) are
differentiated by JAX through the generated expression, with the safe-``where`` idiom at
their branches.

Example:
    >>> import jax.numpy as jnp
    >>> from rigidsym.kernels import jax as rj
    >>> g = jax.grad(lambda w: rj.instant_screw_axis(w, jnp.zeros(3),
    ...                                              jnp.array([1.0, 0.0, 1.0]))[1])
    >>> [round(float(x), 6) for x in g(jnp.array([0.0, 0.0, 2.0]))]
    [0.25, 0.0, -0.25]
"""

from __future__ import annotations

import math
import warnings

try:
    import jax
    import jax.numpy as jnp
except ImportError as _exc:  # pragma: no cover - exercised where JAX is absent
    raise ImportError("rigidsym.kernels.jax needs JAX: pip install 'rigidsym[jax]'") from _exc
import numpy as np

from rigidsym.kernels import _arrays
from rigidsym.kernels._errors import NonFiniteResultError, SingularConfigurationError

__all__ = ["load", "euler_rate_matrix", "euler_angle_rates", "SingularConfigurationError",
           "NonFiniteResultError"]

_TRACER = "jax.jit / jax.vmap / jax.grad"
_BAD_KINDS = "bcOUSMmV"
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
                      UserWarning, stacklevel=4)


def _convert(values: tuple, args: list[dict]) -> list:
    """Arrays of one floating dtype; errors name the argument."""
    _x64_note(values)
    res = []
    for v, a in zip(values, args, strict=True):
        if not isinstance(v, jax.Array):
            try:
                v = np.asarray(v)
            except ValueError as exc:
                raise ValueError(f"{a['name']}: not a rectangular array ({exc})") from None
        kind = np.dtype(v.dtype).kind
        if kind in _BAD_KINDS:
            raise TypeError(f"{a['name']}: expected real numbers, got {v.dtype}")
        res.append(v)
    dtype = jnp.result_type(*[x.dtype for x in res if np.dtype(x.dtype).kind == "f"]) \
        if any(np.dtype(x.dtype).kind == "f" for x in res) else jnp.result_type(float)
    out = []
    for v, a in zip(res, args, strict=True):
        t = jnp.asarray(v, dtype=dtype)
        shape = tuple(a["shape"])
        if t.ndim < len(shape) or tuple(t.shape[t.ndim - len(shape):]) != shape:
            raise ValueError(f"{a['name']}: expected shape {_arrays._shp(shape)}, got "
                             f"{tuple(t.shape)}")
        out.append(t)
    return out


class _Space:
    """The JAX kernels of one generated directory."""

    def __init__(self, directory):
        self.progs = _arrays.ArraySpace.from_directory(directory, "jax")
        self._fns = _arrays.make_all(self.progs, self._make)

    def function(self, name: str):
        """``f(*broadcast inputs) -> (*outputs, singular)``: a ``jax.custom_jvp`` whose JVP
        is the generated Jacobian kernel, or the plain expression (no Jacobian kernel)."""
        return self._fns[name]

    def _make(self, name: str):
        meta, progs = self.progs.meta[name], self.progs
        args, outs = meta["args"], meta["outputs"]
        nval = sum(math.prod(o["shape"]) for o in outs)

        def values(*xs):
            cols = _arrays.columns(xs, args)
            flat, sing = _arrays.evaluate(jnp, progs.variants(name), cols,
                                          jax.lax.stop_gradient)
            return (*_arrays.shape_outputs(jnp, flat, outs, cols[0]), sing)

        if not progs.has_jacobian(name):
            return values
        f = jax.custom_jvp(values)

        @f.defjvp
        def _jvp(primals, tangents):
            res = values(*primals)
            cols = _arrays.columns(primals, args)
            flat, _ = _arrays.evaluate(jnp, progs.variants(name + _arrays.SUFFIX), cols,
                                       jax.lax.stop_gradient)
            touts = _arrays.contract(jnp, list(tangents), flat[nval:], outs, args,
                                     forward=True, singular=res[-1])
            zero = np.zeros(res[-1].shape, dtype=jax.dtypes.float0)
            return res, (*touts, zero)

        return f

    def call(self, name: str, values: tuple, check, on_singular):
        meta = self.progs.meta[name]
        args = meta["args"]
        xs = _convert(values, args)
        check, on_singular = _arrays.modes(check, on_singular, _traced(xs), _TRACER)
        batch = _arrays.broadcast_batch(jnp.broadcast_shapes, xs, args)
        if check:
            _arrays.validate(jnp, xs, args)
        full = [jnp.broadcast_to(x, batch + tuple(a["shape"])) for x, a in zip(xs, args,
                                                                               strict=True)]
        *res, sing = self.function(name)(*full)
        bad = sing
        if check:
            over = jnp.zeros_like(sing)
            for r in res:
                over = over | ~jnp.isfinite(r.reshape(batch + (-1,))).all(-1)
            bad = sing | (over & ~sing)
        if on_singular == "raise":
            if bool(bad.any()):  # the error path reads the masks on the host
                _arrays.raise_flagged(name, meta, np.asarray(sing), np.asarray(bad & ~sing),
                                      [np.asarray(x) for x in xs])
        else:
            res = [jnp.where(bad.reshape(batch + (1,) * (r.ndim - len(batch))), jnp.nan, r)
                   for r in res]
        return res[0] if len(res) == 1 else tuple(res)


# load, the Euler-angle kernels, the lazy kernels: the same for both back-ends (_arrays)
load, euler_rate_matrix, euler_angle_rates, __getattr__, __dir__, _space = \
    _arrays.module_api(globals(), _Space, "JAX", "array", "JAX")
__all__ += _space().progs.kernel_names()
