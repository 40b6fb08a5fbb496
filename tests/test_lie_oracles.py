"""The Lie-group kernels against jaxlie (a test-only oracle, the [oracles] extra) at random
points, orders mapped: jaxlie's SE3 tangent is [v; w] (translation first) and its quaternion
wxyz (scalar first); rigidsym's are [w; v] and [r; r0]."""

from __future__ import annotations

import numpy as np
import pytest

pytestmark = pytest.mark.extra
jaxlie = pytest.importorskip("jaxlie", reason="needs the [oracles] extra (jaxlie)")


@pytest.fixture(scope="module", autouse=True)
def _x64():
    import jax

    jax.config.update("jax_enable_x64", True)


def _points(n=20, seed=5):
    rng = np.random.default_rng(seed)
    w = rng.normal(size=(n, 3))
    w *= (rng.uniform(0, 3.0, size=n) / np.linalg.norm(w, axis=1))[:, None]
    return w, rng.normal(size=(n, 3))


def test_exp_log_so3_match_jaxlie():
    from rigidsym import kernels

    w, _ = _points()
    for wi in w:
        ref = np.asarray(jaxlie.SO3.exp(wi).as_matrix())
        Q = kernels.rotation_from_rotation_vector(wi)
        np.testing.assert_allclose(Q, ref, atol=1e-14)
        np.testing.assert_allclose(kernels.rotation_vector_from_rotation(Q),
                                   np.asarray(jaxlie.SO3.from_matrix(ref).log()), atol=1e-12)


def test_exp_log_se3_match_jaxlie():
    from rigidsym import kernels

    w, v = _points()
    for wi, vi in zip(w, v, strict=True):
        ref = np.asarray(jaxlie.SE3.exp(np.r_[vi, wi]).as_matrix())
        T = kernels.transform_from_exponential_coordinates(np.r_[wi, vi])
        np.testing.assert_allclose(T, ref, atol=1e-13)
        lg = np.asarray(jaxlie.SE3.from_matrix(ref).log())
        np.testing.assert_allclose(kernels.exponential_coordinates_from_transform(T),
                                   np.r_[lg[3:], lg[:3]], atol=1e-11)


def test_quaternion_maps_match_jaxlie():
    from rigidsym import kernels

    w, _ = _points()
    for a, b in zip(w, w[::-1], strict=True):
        qa, qb = jaxlie.SO3.exp(a), jaxlie.SO3.exp(b)
        ea = kernels.euler_rodrigues_from_rotation(np.asarray(qa.as_matrix()))
        wxyz = np.asarray(qa.wxyz) * np.sign(qa.wxyz[0])
        np.testing.assert_allclose(ea, np.r_[wxyz[1:], wxyz[0]], atol=1e-14)
        eb = kernels.euler_rodrigues_from_rotation(np.asarray(qb.as_matrix()))
        prod = np.asarray((qa @ qb).wxyz)
        got = kernels.euler_rodrigues_product(ea, eb)
        ref = np.r_[prod[1:], prod[0]]
        assert min(np.abs(got - ref).max(), np.abs(got + ref).max()) < 1e-14
