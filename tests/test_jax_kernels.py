"""The JAX kernels: the NumPy kernels' values, the generated Jacobians as their
JVPs (jacfwd, jacrev, grad), check_grads at random points, no NaN gradient within 1e-6 of
the singular sets, jit / vmap keyword rules, and float64 only under jax_enable_x64."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from rigidsym import kernels as K
from tests._arrays_cases import EULER, euler_probe, sample, singular_probes

#: skipped without its extra in the README's test command; .ci/run installs it
pytestmark = pytest.mark.extra

jax = pytest.importorskip("jax", reason="JAX is not installed (the [jax] extra)")
import jax.numpy as jnp  # noqa: E402
from jax.test_util import check_grads  # noqa: E402

from rigidsym.kernels import jax as rj  # noqa: E402

ALL = list(K.KERNEL_NAMES)
#: the default suite runs a few kernels (one per family); every kernel runs as `slow`
#: (JAX dispatches each operation of an eager call on its own: seconds per kernel on 2 cores)
FEW = {"instant_screw_axis", "natural_invariants_from_rotation"}
NAMES = [n if n in FEW else pytest.param(n, marks=pytest.mark.slow) for n in ALL]
JAC = [n for n in NAMES if (n if isinstance(n, str) else n.values[0]) + "_with_jacobians"
       in K._state.meta()]
PROBED = [n for n in NAMES if singular_probes(n if isinstance(n, str) else n.values[0])
          is not None]


@pytest.fixture(autouse=True)
def _x64():
    old = jax.config.jax_enable_x64
    jax.config.update("jax_enable_x64", True)
    yield
    jax.config.update("jax_enable_x64", old)


def _tuple(v):
    return v if isinstance(v, tuple) else (v,)


def _close(got, ref, rtol):
    ref = np.asarray(ref)
    scale = max(1.0, float(np.abs(ref).max())) if ref.size else 1.0
    np.testing.assert_allclose(np.asarray(got), ref, rtol=rtol, atol=rtol * scale)


@pytest.mark.parametrize("name", NAMES)
def test_values_match_the_numpy_kernel(name):
    xs = sample(name, 16)
    ref = _tuple(getattr(K, name)(*xs))
    got = _tuple(getattr(rj, name)(*[jnp.asarray(x) for x in xs]))
    for g, r in zip(got, ref, strict=True):
        assert g.dtype == jnp.float64 and g.shape == r.shape
        _close(g, r, 1e-13)


@pytest.mark.parametrize("seq,frame", EULER)
def test_euler_kernels_match_numpy(seq, frame):
    rng = np.random.default_rng(1)
    ang, w = rng.uniform(-1, 1, (8, 3)), rng.standard_normal((8, 3))
    _close(rj.euler_rate_matrix(ang, seq, frame), K.euler_rate_matrix(ang, seq, frame), 1e-13)
    _close(rj.euler_angle_rates(ang, w, seq, frame), K.euler_angle_rates(ang, w, seq, frame),
           1e-13)


#: the thorough run: a seeded third of the slow kernels (each commit another third; all in the
#: exhaustive profile), each an XLA compile of its jacfwd and its jacrev; FEW's kernel runs in
#: every run, and every kernel's values (test_values_match_the_numpy_kernel) and its generated
#: Jacobian as the PyTorch gradient (tests/test_torch_kernels.py) are checked in every run
@pytest.mark.thorough(0.33)
@pytest.mark.parametrize("name", JAC)
def test_jacfwd_and_jacrev_are_the_generated_jacobians(name):
    xs = sample(name, 3, seed=2)
    _, ref = K.jacobian(name)(*xs)
    meta = K._state.meta()[name]
    fn = getattr(rj, name)
    nargs = tuple(range(len(xs)))
    for transform in (jax.jacfwd, jax.jacrev):
        # jit: one XLA compilation instead of thousands of eager dispatches
        per_sample = jax.jit(jax.vmap(transform(lambda *a: _tuple(fn(*a)), argnums=nargs)))
        jac = per_sample(*[jnp.asarray(x) for x in xs])
        for k, o in enumerate(meta["outputs"]):
            for j, a in enumerate(meta["args"]):
                _close(jac[k][j], ref[o["name"]][a["name"]], 1e-12)


#: the kernels whose JAX derivatives only finite differences judge: those without a generated
#: Jacobian kernel (the others' jacfwd and jacrev equal it to 1e-12,
#: ``test_jacfwd_and_jacrev_are_the_generated_jacobians``, and it equals sympy's derivative,
#: tests/test_jacobians.py), and FEW, where finite differences judge the two side by side
FINITE_DIFFERENCES = [n for n in NAMES if (n if isinstance(n, str) else n.values[0]) in FEW
                      or n not in JAC]


@pytest.mark.parametrize("name", FINITE_DIFFERENCES)
def test_check_grads_at_random_points(name):
    xs = [jnp.asarray(x) for x in sample(name, 2, seed=5)]
    fn = getattr(rj, name)
    check_grads(jax.jit(lambda *a: _tuple(fn(*a, check=False))), xs, order=1,
                modes=("fwd", "rev"))


@pytest.mark.parametrize("name", PROBED)
def test_no_nan_gradient_near_the_singular_sets(name):
    xs = [jnp.asarray(x) for x in singular_probes(name)]
    fn = getattr(rj, name)
    grads = jax.jit(jax.grad(lambda *a: sum(o.sum() for o in _tuple(fn(*a))),
                             argnums=tuple(range(len(xs)))))(*xs)
    for g in grads:
        assert bool(jnp.isfinite(g).all()), name


@pytest.mark.parametrize("seq", ["ZYX", "ZXZ"])
def test_euler_rates_gradient_finite_near_gimbal_lock(seq):
    w = jnp.array([[0.1, 0.2, 0.3]] * 2)
    g = jax.grad(lambda a: rj.euler_angle_rates(a, w, seq).sum())(jnp.asarray(euler_probe(seq)))
    assert bool(jnp.isfinite(g).all())


def test_jit_vmap_scan_and_keyword_rules():
    xs = [jnp.asarray(x) for x in sample("twist_transfer", 4)]
    _close(jax.jit(rj.twist_transfer)(*xs), K.twist_transfer(*map(np.asarray, xs)), 1e-13)
    with pytest.raises(ValueError, match="check=True needs eager mode"):
        jax.jit(lambda *a: rj.twist_transfer(*a, check=True))(*xs)
    with pytest.raises(ValueError, match="on_singular='raise' needs eager mode"):
        jax.vmap(lambda t: rj.twist_transfer(t, xs[1][0], xs[2][0], on_singular="raise"))(xs[0])

    def step(t, _):  # a kernel inside a lax.scan step
        return rj.twist_transfer(t, xs[1][0], xs[2][0]), None
    t, _ = jax.lax.scan(step, xs[0][0], None, length=3)
    assert t.shape == (6,)
    for kw in ("out", "threads"):
        with pytest.raises(TypeError):
            rj.twist_transfer(*xs, **{kw: None})


def test_singular_raise_in_eager_nan_on_request():
    a = jnp.zeros((2, 3))
    omega = jnp.array([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0]])
    with pytest.raises(K.SingularConfigurationError, match=r"\(1,\)"):
        rj.instant_screw_axis(omega, a, a)
    g = jax.grad(lambda w: rj.instant_screw_axis(w, a, a, on_singular="nan")[1][0])(omega)
    assert bool(jnp.isfinite(g).all())


def test_float64_without_x64_warns_naming_the_flag_and_computes_float32():
    jax.config.update("jax_enable_x64", False)
    rj._WARNED.clear()
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        out = rj.twist_transfer(np.ones(6), np.zeros(3), np.ones(3))
        rj.twist_transfer(np.ones(6), np.zeros(3), np.ones(3))
    ours = [w for w in seen if "jax_enable_x64" in str(w.message) and "rigidsym" in
            str(w.message)]
    assert len(ours) == 1 and out.dtype == jnp.float32
