"""Dask arrays in, lazy Dask arrays out: same bits as the in-memory call, errors at compute
time with global batch indices, nothing computed on call; and one run on a
``distributed.LocalCluster`` (2 worker processes, 1 thread each)."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

from rigidsym import kernels as K

#: skipped without its extra in the README's test command; .ci/run installs it
pytestmark = pytest.mark.extra

da = pytest.importorskip("dask.array", reason="Dask is not installed (the [dask] extra)")
dask = pytest.importorskip("dask", reason="Dask is not installed (the [dask] extra)")




def _unit(rng, shape):
    e = rng.standard_normal(shape + (3,))
    return e / np.linalg.norm(e, axis=-1, keepdims=True)


def _refuse(*args, **kwargs):
    raise AssertionError("something was computed")


def test_calling_on_dask_inputs_computes_nothing(backend):
    calls = []

    def make():
        calls.append(1)
        return np.tile([0.0, 0.6, 0.8], (10, 1))

    e = da.from_delayed(dask.delayed(make)(), shape=(10, 3), dtype=float)
    with dask.config.set(scheduler=_refuse):
        Q = K.rotation_from_natural_invariants(e, np.linspace(0.1, 1, 10))
        e2, phi = K.natural_invariants_from_rotation(Q)
        U = K.twist_transfer_matrix(e, [1.0, 2.0, 3.0])
    assert calls == []
    assert isinstance(Q, da.Array) and Q.shape == (10, 3, 3) and U.shape == (10, 6, 6)
    assert isinstance(phi, da.Array) and phi.shape == (10,)
    np.testing.assert_allclose(phi.compute(), np.linspace(0.1, 1, 10), rtol=1e-14)
    assert calls == [1]


def test_bit_identical_to_in_memory_on_uneven_chunks_and_broadcasting(backend):
    rng = np.random.default_rng(1)
    e, phi = _unit(rng, (7, 50)), rng.uniform(-3, 3, (7, 50))
    a, ap = rng.standard_normal((50, 3)), rng.standard_normal(3)
    de = da.from_array(e, chunks=((3, 1, 3), (20, 11, 19), (2, 1)))     # core split: rechunked
    dphi = da.from_array(phi, chunks=((2, 5), 25))
    got = K.screw_axis_point(de, dphi, a, ap)                            # NumPy args mixed in
    assert got.chunks[:2] == ((3, 1, 3), (20, 11, 19)) and got.chunks[2] == (3,)
    np.testing.assert_array_equal(got.compute(), K.screw_axis_point(e, phi, a, ap))
    Q = K.rotation_from_natural_invariants(e, phi)
    outs = K.screw_of_displacement(da.from_array(Q, chunks=(2, 13, 3, 3)), a, ap)
    ref = K.screw_of_displacement(Q, a, ap)
    assert len(outs) == len(ref) == 5
    for o, r in zip(dask.compute(*outs), ref, strict=True):
        assert o.shape == r.shape
        np.testing.assert_array_equal(o, r)
    # a Dask argument with fewer batch axes than the other (broadcast, one block of size 1)
    w = K.twist_transfer(da.from_array(rng.standard_normal(6)), a, da.from_array(
        rng.standard_normal((4, 50, 3)), chunks=(3, 10, 3)))
    assert w.shape == (4, 50, 6) and w.numblocks == (2, 5, 1)


def test_singular_rows_nan_by_default_raise_names_global_index(backend):
    rng = np.random.default_rng(2)
    e, phi = _unit(rng, (6, 40)), rng.uniform(0.5, 3, (6, 40))
    phi[4, 33] = 0.0
    de = da.from_array(e, chunks=(2, 15, 3))
    dphi = da.from_array(phi, chunks=(2, 15))
    N = K.N_matrix(de, dphi).compute()
    bad = np.zeros(phi.shape, bool)
    bad[4, 33] = True
    assert np.isnan(N[bad]).all() and np.isfinite(N[~bad]).all()
    lazy = K.N_matrix(de, dphi, on_singular="raise")       # building the graph is fine
    with pytest.raises(K.SingularConfigurationError, match=r"\(4, 33\)") as info:
        lazy.compute()
    assert info.value.indices == [(4, 33)] and info.value.argument == "phi"


def test_validation_at_compute_time_names_the_argument(backend):
    e = np.tile([0.0, 0.6, 0.8], (20, 1))
    e[13] = [1.0, 1.0, 0.0]
    lazy = K.rotation_from_natural_invariants(da.from_array(e, chunks=5), 0.3)
    with pytest.raises(ValueError, match="e: not a unit vector"):
        lazy.compute()
    assert np.isfinite(K.rotation_from_natural_invariants(
        da.from_array(e, chunks=5), 0.3, check=False).compute()).all()


def test_rejected_before_building_the_graph():
    e = da.zeros((10, 3), chunks=5)
    with pytest.raises(ValueError, match=r"e: expected shape \(\.\.\., 3\)"):
        K.rotation_from_natural_invariants(da.zeros((10, 4), chunks=5), 0.3)
    with pytest.raises(ValueError, match="broadcast"):
        K.rotation_from_natural_invariants(e, da.zeros(7))
    with pytest.raises(TypeError, match="out"):
        K.rotation_from_natural_invariants(e, 0.3, out=np.empty((10, 3, 3)))
    with pytest.raises(TypeError, match="phi"):
        K.rotation_from_natural_invariants(e, np.array(["a"] * 10))
    with pytest.raises(ValueError, match="on_singular"):
        K.N_matrix(e, 0.3, on_singular="ignore")


def test_euler_rate_functions_take_dask():
    ang = np.random.default_rng(3).uniform(0.2, 1.2, (30, 3))
    W = K.euler_rate_matrix(da.from_array(ang, chunks=7), "ZYX", "body")
    np.testing.assert_array_equal(W.compute(), K.euler_rate_matrix(ang, "ZYX", "body"))


def _error_classes(cls):
    out = [cls]
    for sub in cls.__subclasses__():
        out += _error_classes(sub)
    return out


@pytest.mark.parametrize("cls", _error_classes(K.SingularConfigurationError),
                         ids=lambda c: c.__name__)
def test_singular_errors_survive_pickling(cls):
    exc = cls("k: singular at batch indices [(1, 2)]", "phi", [(1, 2)])
    back = pickle.loads(pickle.dumps(exc))
    assert type(back) is cls and str(back) == str(exc)
    assert back.argument == "phi" and back.indices == [(1, 2)]


def test_distributed_local_cluster_bit_identical_and_singular_row():
    distributed = pytest.importorskip("distributed",
                                      reason="distributed is not installed (the [dask] extra)")
    if K.use_backend("c") != "c":          # build before the workers start: they load it
        pytest.skip("no C compiler")
    n, k = 1_000_000, 612_345
    sizes = [90_000, 140_000, 60_000, 200_000, 110_000, 130_000, 70_000, 120_000, 80_000]
    assert sum(sizes) == n and len(sizes) >= 8
    rs = da.random.RandomState(7)
    e = rs.standard_normal((n, 3), chunks=(tuple(sizes), 3))
    e = e / da.linalg.norm(e, axis=-1, keepdims=True)
    phi = rs.uniform(-3.0, 3.0, n, chunks=(tuple(sizes),))
    phi = da.where(da.arange(n, chunks=(tuple(sizes),)) == k, 0.0, phi)
    a = rs.standard_normal((n, 3), chunks=(tuple(sizes), 3))
    ap = rs.standard_normal((n, 3), chunks=(tuple(sizes), 3))
    e_m, phi_m, a_m, ap_m = dask.compute(e, phi, a, ap, scheduler="sync")
    Q = K.rotation_from_natural_invariants(e, phi)
    p0 = K.screw_axis_point(e, phi, a, ap)
    w = K.twist_transfer(da.concatenate([a, ap], axis=-1), e, ap)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster, \
            distributed.Client(cluster) as client:
        got = client.compute([Q, p0, w], sync=True)
        with pytest.raises(K.SingularConfigurationError, match=f"\\({k},\\)") as info:
            client.compute(K.screw_axis_point(e, phi, a, ap, on_singular="raise"), sync=True)
    assert info.value.indices == [(k,)]
    K.use_backend("c")
    np.testing.assert_array_equal(got[0], K.rotation_from_natural_invariants(e_m, phi_m))
    ref = K.screw_axis_point(e_m, phi_m, a_m, ap_m, on_singular="nan")
    assert np.isnan(got[1][k]).all() and np.isnan(ref[k]).all()
    np.testing.assert_array_equal(got[1], ref)
    np.testing.assert_array_equal(got[2], K.twist_transfer(np.concatenate([a_m, ap_m], -1),
                                                           e_m, ap_m))
