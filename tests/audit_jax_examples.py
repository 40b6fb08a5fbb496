"""JAX functions for tests/test_audit_gradients.py: the exponential of SO(3) with a right
value and a wrong gradient (the two ways the trackers show: a NaN from the unselected branch
of a ``where`` at w = 0, and a ``stop_gradient`` on the axis), and the correct one (the
double ``where``). Imported only where JAX is installed."""

import jax
import jax.numpy as jnp

jax.config.update("jax_enable_x64", True)


def _cpm(v):
    return jnp.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def exp_correct(w):
    """Q = 1 + sin(t)/t W + (1 - cos t)/t^2 W^2, the small-angle series where t < 1e-4,
    the norm guarded by a second where (its gradient finite at w = 0)."""
    w = jnp.asarray(w)
    t2 = jnp.sum(w * w)
    small = t2 < 1e-8
    t = jnp.sqrt(jnp.where(small, 1.0, t2))
    a = jnp.where(small, 1.0 - t2 / 6, jnp.sin(t) / t)
    b = jnp.where(small, 0.5 - t2 / 24, (1.0 - jnp.cos(t)) / t**2)
    W = _cpm(w)
    return jnp.eye(3) + a * W + b * W @ W


def exp_nan_gradient_at_zero(w):
    """The series where t < 1e-4, but the norm unguarded: at w = 0 the value is 1, the
    gradient NaN (0 x the inf of the norm's derivative)."""
    w = jnp.asarray(w)
    t = jnp.linalg.norm(w)
    small = t < 1e-4
    ts = jnp.where(small, 1.0, t)
    a = jnp.where(small, 1.0 - t**2 / 6, jnp.sin(ts) / ts)
    b = jnp.where(small, 0.5 - t**2 / 24, (1.0 - jnp.cos(ts)) / ts**2)
    W = _cpm(w)
    return jnp.eye(3) + a * W + b * W @ W


def exp_stop_gradient_axis(w):
    """Rodrigues' formula with the axis e = w / |w| held constant under differentiation:
    the value right, the derivative along every direction but the axis wrong."""
    w = jnp.asarray(w)
    t = jnp.linalg.norm(w)
    E = _cpm(jax.lax.stop_gradient(w / t))
    return jnp.eye(3) + jnp.sin(t) * E + (1.0 - jnp.cos(t)) * E @ E
