"""The per-call entry points in C: the same bits, errors and NumPy conventions as
the Python path, which they hand every case they do not take.

The Python path (``KernelSpace.call``) is the reference: it runs the same compiled batch
functions, so the two agree bitwise. A sample's bits do not depend on its batch either (a
short batch runs the same block function as a full block, padded).
"""

from __future__ import annotations

import pickle

import numpy as np
import pytest
from test_kernels import AVAILABLE, PUBLIC, inputs

from rigidsym import kernels as K
from rigidsym.kernels.runtime import scale as _scale
from rigidsym.kernels.runtime import state as _state

pytestmark = pytest.mark.skipif(K.use_backend("c") != "c", reason="no C backend")


@pytest.fixture(autouse=True)
def c_backend():
    K.use_backend("c")
    yield
    K.use_backend("c")


def _space():
    return _state.builtin()


def _python(name, *args, **kw):
    """The Python path itself (what the entries fall back to)."""
    return _space().call(name, args, **kw)


def _rows(name: str, n: int, dtype=np.float64):
    return [a.astype(dtype) for a in inputs(AVAILABLE[name], n, seed=3)]


def _flat(res) -> np.ndarray:
    res = res if isinstance(res, tuple) else (res,)
    return np.concatenate([np.asarray(r).reshape(-1) for r in res])


@pytest.mark.sample
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("name", PUBLIC)
def test_one_sample_has_the_bits_of_its_row_in_a_batch(name, dtype):
    """K(row) through the C entry == row i of K(batch), bitwise, for every row of a batch
    of two full blocks and a tail (arrays of one sample; lists and floats too)."""
    arrays = _rows(name, 150, dtype)
    n = arrays[0].shape[0]
    with np.errstate(all="ignore"):
        whole = getattr(K, name)(*arrays, on_singular="nan")
    whole = whole if isinstance(whole, tuple) else (whole,)
    for i in range(n):
        row = [a[i] for a in arrays]
        got = getattr(K, name)(*row, on_singular="nan")
        want = np.concatenate([np.asarray(w[i]).reshape(-1) for w in whole])
        np.testing.assert_array_equal(_flat(got), want, err_msg=f"row {i}")
        if dtype == np.float64 and i % 7 == 0:   # Python numbers and lists: the same bits
            got = getattr(K, name)(*[r.tolist() for r in row], on_singular="nan")
            np.testing.assert_array_equal(_flat(got), want, err_msg=f"row {i} (lists)")


@pytest.mark.parametrize("name", ["rotation_from_natural_invariants", "screw_axis_point",
                                  "N_matrix", "newton_euler_wrench"])
def test_jacobian_kernels_one_sample_same_bits(name):
    f = K.jacobian(name)
    arrays = _rows(name, 70)
    vals, jac = f(*arrays)
    v1, j1 = f(*[a[66] for a in arrays])
    vals = vals if isinstance(vals, tuple) else (vals,)
    want = np.concatenate([np.asarray(v)[66].reshape(-1) for v in vals])
    np.testing.assert_array_equal(_flat(v1), want)
    for o in jac:
        for a in jac[o]:
            np.testing.assert_array_equal(j1[o][a], jac[o][a][66])


def test_common_cases_never_reach_python(monkeypatch):
    """Lists, floats, ints, NumPy scalars, float32 and float64 arrays of any strides: all in
    C (the Python path is replaced by one that fails)."""
    K.rotation_from_natural_invariants([0, 0, 1], 0.1)      # binds the entries

    def boom(*a, **k):
        raise AssertionError("the Python path was taken")
    monkeypatch.setattr(type(_space()), "call", boom)
    e = np.array([[0.0, 0.6, 0.8], [0.0, 0.0, 1.0]])
    K.rotation_from_natural_invariants([0.0, 0.6, 0.8], 0.3)
    K.rotation_from_natural_invariants((0, 0, 1), 1)
    K.rotation_from_natural_invariants(e, np.float64(0.3), check=False)
    K.rotation_from_natural_invariants(e[::-1], np.array([0.1, 0.2]), threads=1)
    K.rotation_from_natural_invariants(e.astype(np.float32), 0.3, on_singular="nan")
    K.rotation_from_natural_invariants(np.asfortranarray(e), np.float32(0.3))
    K.twist_transfer([1, 2, 3, 4, 5, 6], [1, 2, 3], [0.5, 0, 0])
    K.newton_euler_wrench([[1, 0, 0], [0, 2, 0], [0, 0, 3]], 2.0, [1, 2, 3], [0, 0, 1], [0, 0, 0])
    K.natural_invariants_from_rotation(np.eye(3)[None], on_singular="nan")


def test_types_and_dtypes_follow_nep50():
    e32 = np.float32([0.0, 0.6, 0.8])
    f = K.rotation_from_natural_invariants
    assert f(e32, 0.3).dtype == np.float32
    assert f(e32, np.float32(0.3)).dtype == np.float32
    assert f(e32, np.float64(0.3)).dtype == np.float64
    assert f(e32, [0.3]).dtype == np.float64
    assert f([0, 0.6, 0.8], 0.3).dtype == np.float64
    assert f([0, 0.6, 0.8], 0.3).shape == (3, 3)
    assert K.kinetic_energy(np.eye(3), 1.0, [1, 0, 0], [0, 1, 0]).shape == ()


@pytest.mark.parametrize("bad, err, match", [
    (([0, 0, 2], 0.3), ValueError, "e: not a unit vector"),
    (([0, 0, 1], float("nan")), ValueError, "phi: non-finite"),
    (([True, False, True], 0.3), TypeError, "e: expected real numbers"),
    (("abc", 0.3), TypeError, "e: expected an array-like"),
    (([0, 1], 0.3), ValueError, r"e: expected shape \(\.\.\., 3\)"),
    ((np.zeros((2, 3)) + [0, 0, 1], np.zeros(3)), ValueError, "batch shapes do not broadcast"),
])
def test_errors_are_the_python_paths(bad, err, match):
    with pytest.raises(err, match=match) as got:
        K.rotation_from_natural_invariants(*bad)
    with pytest.raises(err) as want:
        _python("rotation_from_natural_invariants", *bad)
    assert str(got.value) == str(want.value)


@pytest.mark.parametrize("kw, err", [({"check": 1}, TypeError), ({"on_singular": "x"}, ValueError),
                                     ({"threads": 0}, ValueError), ({"threads": True}, TypeError),
                                     ({"threads": 1.5}, TypeError)])
def test_bad_keywords(kw, err):
    with pytest.raises(err):
        K.rotation_from_natural_invariants([0, 0, 1], 0.3, **kw)


def test_singular_raise_and_nan_rows():
    # omega = 0 and a_dot = 0: no motion, so no instant screw axis (omega = 0 alone is a
    # pure translation, a screw of infinite pitch; natural_invariants_from_rotation at
    # Q = 1 is not singular: phi = 0 and the default axis)
    with pytest.raises(K.SingularConfigurationError, match=r"batch indices \[\(1,\)\]"):
        K.instant_screw_axis(np.array([[0.0, 0, 1], [0, 0, 0]]), np.zeros(3), np.zeros(3))
    p0, pitch, plucker = K.instant_screw_axis(np.zeros(3), np.zeros(3), np.zeros(3),
                                              on_singular="nan")
    assert np.isnan(p0).all() and np.isnan(pitch) and np.isnan(plucker).all()
    with pytest.raises(K.NonFiniteResultError):
        K.kinetic_energy(np.eye(3), 1.0, [1e200, 0, 0], [0, 0, 0])
    assert np.isnan(K.kinetic_energy(np.eye(3), 1.0, [1e200, 0, 0], [0, 0, 0],
                                     on_singular="nan"))


def test_numpy_conventions_strides_broadcasting_out_empty():
    rng = np.random.default_rng(1)
    e = rng.standard_normal((4, 5, 3))
    e /= np.linalg.norm(e, axis=-1, keepdims=True)
    phi = rng.uniform(-3, 3, (5,))
    f = K.rotation_from_natural_invariants
    ref = _python("rotation_from_natural_invariants", np.ascontiguousarray(e), phi)
    np.testing.assert_array_equal(f(e, phi), ref)
    np.testing.assert_array_equal(f(e[::-1, ::-1], phi[::-1]), ref[::-1, ::-1])
    np.testing.assert_array_equal(f(np.transpose(np.transpose(e).copy()), phi), ref)
    # out= of the broadcast batch shape, contiguous or not
    out = np.empty((4, 5, 3, 3))
    assert f(e, phi, out=out) is out
    np.testing.assert_array_equal(out, ref)
    strided = np.empty((4, 5, 3, 6))[..., ::2]
    assert f(e, phi, out=strided) is strided
    np.testing.assert_array_equal(strided, ref)
    # 0-sized batches
    assert f(np.empty((0, 3)), np.empty(0)).shape == (0, 3, 3)
    assert f(np.empty((2, 0, 3)), 0.3).shape == (2, 0, 3, 3)
    # an out that is an input: the Python path, as before
    t = rng.standard_normal((4, 6))
    want = K.twist_transfer(t.copy(), [1, 2, 3], [0, 0, 1])
    assert K.twist_transfer(t, [1, 2, 3], [0, 0, 1], out=t) is t
    np.testing.assert_array_equal(t, want)


def test_out_mismatch_is_the_python_error():
    with pytest.raises(TypeError, match="out"):
        K.rotation_from_natural_invariants([0, 0, 1], 0.3, out=np.empty((3, 3), np.float32))
    with pytest.raises(ValueError, match="out"):
        K.rotation_from_natural_invariants([0, 0, 1], 0.3, out=np.empty((1, 3, 3)))


def test_threads_keep_the_bits():
    rng = np.random.default_rng(2)
    n = _scale.MIN_PARALLEL + 77
    e = rng.standard_normal((n, 3))
    e /= np.linalg.norm(e, axis=1, keepdims=True)
    phi = rng.uniform(-3, 3, n)
    one = K.rotation_from_natural_invariants(e, phi, threads=1)
    np.testing.assert_array_equal(K.rotation_from_natural_invariants(e, phi, threads=2), one)
    np.testing.assert_array_equal(K.rotation_from_natural_invariants(e[7], phi[7]), one[7])


def test_numpy_backend_switch_takes_the_python_path(monkeypatch):
    K.rotation_from_natural_invariants([0, 0, 1], 0.3)
    assert K.use_backend("numpy") == "numpy"
    calls = []
    real = type(_space()).numpy_kernel

    def spy(self, name):
        calls.append(name)
        return real(self, name)
    monkeypatch.setattr(type(_space()), "numpy_kernel", spy)
    K.rotation_from_natural_invariants([0, 0, 1], 0.3)
    assert calls == ["rotation_from_natural_invariants"]


def test_signature_help_and_pickle_unchanged():
    import inspect

    f = K.rotation_from_natural_invariants
    assert list(inspect.signature(f).parameters) == ["e", "phi", "out", "check",
                                                     "on_singular", "threads"]
    assert "Rotation matrix" in f.__doc__
    assert pickle.loads(pickle.dumps(f)) is f
