"""Threads: the lazy C build and ``use_backend`` from several threads at once; the OpenMP
build and its one-thread fallback."""

from __future__ import annotations

import shutil
import threading
import time
import warnings
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import rigidsym.kernels as K
from rigidsym.kernels.cbuild import driver as _build
from rigidsym.kernels.cbuild import extension as _ext
from rigidsym.kernels.runtime import scale as _scale
from rigidsym.kernels.runtime import state as _state

HAVE_CC = bool(shutil.which("gcc") or shutil.which("cc"))


def test_lazy_build_runs_once_under_a_thread_pool(monkeypatch):
    real = _ext.load
    calls = []

    def slow_load(gdir, package=False):
        calls.append(threading.get_ident())
        time.sleep(0.2)            # wide window: without the lock every thread would load
        return real(gdir, package)

    space = _state.builtin()
    # the kernels' entry points bind at the first call too: unbind them (the
    # functions' direct calls of C as well)
    import rigidsym.generated.api as api

    from rigidsym.kernels.runtime import entries as _entries

    _entries.unbind(space, api)
    monkeypatch.setattr(space, "_clib", None)
    monkeypatch.setitem(_state.STATE, "backend", None)
    monkeypatch.setattr(_ext, "load", slow_load)
    phi = np.linspace(0.1, 3.0, 1000)
    with ThreadPoolExecutor(8) as pool:
        res = list(pool.map(lambda _: K.rotation_from_natural_invariants([0, 0.6, 0.8], phi),
                            range(16)))
    assert len(calls) == 1
    for r in res[1:]:
        np.testing.assert_array_equal(r, res[0])
    assert K.backend() in ("c", "numpy")
    K.use_backend("numpy")


def test_use_backend_from_many_threads_is_consistent():
    phi = np.linspace(0.1, 3.0, 257)

    def work(i):
        b = K.use_backend("c" if i % 2 else "numpy")
        assert b in ("c", "numpy")
        return K.rotation_from_natural_invariants([0, 0.6, 0.8], phi)

    with ThreadPoolExecutor(6) as pool:
        res = list(pool.map(work, range(24)))
    for r in res:
        np.testing.assert_allclose(r, res[0], rtol=0, atol=2e-15)   # NumPy vs C
    K.use_backend("numpy")


def test_extension_load_from_many_threads_returns_one_module():
    if not HAVE_CC and _ext.package_module() is None:
        pytest.skip("no C compiler and no compiled module")
    gdir = _ext.generated_dir()
    with ThreadPoolExecutor(4) as pool:
        mods = list(pool.map(lambda _: _ext.load(gdir, package=True).module, range(8)))
    assert all(m is mods[0] for m in mods)


def test_openmp_build_when_the_compiler_has_it():
    if not HAVE_CC:
        pytest.skip("no C compiler")
    assert _build.configure().openmp, "gcc is present but cannot build OpenMP code"
    if K.use_backend("c") == "c":
        assert K.build_info()["openmp"], "the kernels in use were built without OpenMP"
    K.use_backend("numpy")


# a build without OpenMP; quick: test_thread_counts_and_positions_give_the_same_bits
@pytest.mark.slow
def test_no_openmp_falls_back_to_one_thread_with_one_warning(monkeypatch, tmp_path):
    """A compiler without OpenMP builds the one-thread kernels; loading them warns once."""
    if not HAVE_CC:
        pytest.skip("no C compiler")
    real = _build._probe
    monkeypatch.setattr(_build, "_probe",
                        lambda cc, flags, libs, simd: "-fopenmp" not in flags
                        and real(cc, flags, libs, simd))
    assert _build.configure().openmp is False
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path / "cache"))
    monkeypatch.setattr(_ext, "_MODULES", {})
    monkeypatch.setitem(_ext._WARNED, "omp", False)
    out = tmp_path / "k"
    from rigidsym.codegen.generator import write
    from rigidsym.codegen.usergen import generate_user
    write(generate_user([str(Path(__file__).parents[1] / "examples" /
                             "rotation_identities.py")]), out)
    with pytest.warns(RuntimeWarning, match="without OpenMP.*one thread"):
        loaded = _ext.load(out)
    assert not loaded.module.openmp
    monkeypatch.setattr(_ext, "_MODULES", {})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _ext.load(out)


# --- threads in the C batch loops: same bits for every thread count and position ---------

from test_kernels import AVAILABLE, inputs  # noqa: E402  (the kernels' input sampler)

#: above MIN_PARALLEL, so that 2 and 3 threads really run in parallel
N_THREADED = 2 * 16384 + 37
assert N_THREADED > 2 * _scale.MIN_PARALLEL
#: block edges of both batch-loop block sizes (64, 256), the parallel split, the tail
EDGES = [0, 63, 64, 65, 255, 256, 257, 16383, 16384, 16385, N_THREADED - 2, N_THREADED - 1]


def _hard_inputs(name: str) -> list[np.ndarray]:
    """Random valid inputs with degenerate rows (phi = 0, zero vectors, Q = 1: singular
    sets) and huge rows (free arguments times 1e300: overflow) at the block edges."""
    kernel = AVAILABLE[name]
    arrays = inputs(kernel, N_THREADED - 4, seed=5)
    zero, huge = EDGES[0::2], EDGES[1::2]
    for a, v in zip(kernel.args, arrays, strict=True):
        if a.kind == "angle":
            v[zero] = 0.0
        elif a.kind == "rotation":
            v[zero] = np.eye(3)
        elif a.kind != "unit":
            v[zero] = 0.0 if a.name != "m" else v[zero]
            v[huge] *= 1e300
    return arrays


def _run_c(name, arrays, threads):
    meta = _state.meta()[name]
    n = arrays[0].shape[0]
    outs = [np.full((n,) + tuple(o["shape"]), -7.0) for o in meta["outputs"]]
    with np.errstate(all="ignore"):
        count = K.batch_function(name, "c", threads=threads)(*arrays, *outs)
    return count, np.concatenate([o.reshape(n, -1) for o in outs], axis=1)


@pytest.fixture(scope="module")
def c_backend():
    if not HAVE_CC:
        pytest.skip("no C compiler")
    assert K.use_backend("c") == "c"
    yield
    K.use_backend("numpy")


@pytest.mark.sample
@pytest.mark.parametrize("name", sorted(AVAILABLE))
def test_thread_counts_and_positions_give_the_same_bits(name, c_backend):
    arrays = _hard_inputs(name)
    count, ref = _run_c(name, arrays, 1)
    flagged = np.isnan(ref).any(axis=1)
    assert count == flagged.sum()
    assert np.isnan(ref[flagged]).all()          # a flagged row is NaN throughout
    for t in (2, 3):
        c, got = _run_c(name, arrays, t)
        assert c == count
        np.testing.assert_array_equal(got, ref)
    # position: the same samples at another offset, and in uneven pieces
    shift = 37
    c, got = _run_c(name, [np.ascontiguousarray(a[shift:]) for a in arrays], 2)
    np.testing.assert_array_equal(got, ref[shift:])
    cuts = [0, 1, 70, 333, 4200, N_THREADED]
    pieces = [_run_c(name, [np.ascontiguousarray(a[lo:hi]) for a in arrays], 1)[1]
              for lo, hi in zip(cuts[:-1], cuts[1:], strict=True)]
    np.testing.assert_array_equal(np.concatenate(pieces), ref)


def test_some_rows_at_block_edges_are_flagged(c_backend):
    """The degenerate rows above do reach the flagged paths (singular and overflow)."""
    kinds = {}
    for name in ("N_matrix", "instant_screw_axis", "kinetic_energy",
                 "rotation_from_euler_rodrigues"):
        _, ref = _run_c(name, _hard_inputs(name), 3)
        kinds[name] = np.flatnonzero(np.isnan(ref).any(axis=1)).tolist()
    assert kinds["N_matrix"] == EDGES[0::2]                  # phi = 0
    # omega = 0 only: the rows times 1e300 have a representable axis (e, pitch, a point),
    # rescued (not flagged as overflow)
    assert kinds["instant_screw_axis"] == EDGES[0::2]
    assert kinds["kinetic_energy"] == EDGES[1::2]            # overflow only
    assert kinds["rotation_from_euler_rodrigues"] == []


def test_public_api_threads_keyword(c_backend):
    e = np.tile([0.0, 0.6, 0.8], (N_THREADED, 1))
    phi = np.linspace(0.1, 3, N_THREADED)
    phi[[64, 16384]] = 0.0
    one = K.N_matrix(e, phi, threads=1, on_singular="nan")
    np.testing.assert_array_equal(K.N_matrix(e, phi, threads=3, on_singular="nan"), one)
    with pytest.raises(K.SingularConfigurationError, match=r"\[\(64,\), \(16384,\)\]"):
        K.N_matrix(e, phi, threads=2)
    with pytest.raises(ValueError, match="threads"):
        K.N_matrix(e, phi, threads=0)


def test_thread_count_setting_order(monkeypatch):
    monkeypatch.delenv("RIGIDSYM_NUM_THREADS", raising=False)
    K.set_num_threads(None)
    assert K.get_num_threads() == 1                      # never oversubscribes unasked
    monkeypatch.setenv("RIGIDSYM_NUM_THREADS", "2")
    assert K.get_num_threads() == 2
    K.set_num_threads(3)
    try:
        assert K.get_num_threads() == 3                  # the process-wide setting wins
    finally:
        K.set_num_threads(None)
    monkeypatch.setenv("RIGIDSYM_NUM_THREADS", "lots")
    with pytest.raises(ValueError, match="RIGIDSYM_NUM_THREADS"):
        K.get_num_threads()
    # one validation for the keyword and the setting: a float is a TypeError in both
    with pytest.raises(TypeError, match="^n: expected a positive int"):
        K.set_num_threads(1.5)
    with pytest.raises(ValueError, match="^n: expected a positive int"):
        K.set_num_threads(0)


def test_numpy_backend_warns_once_and_runs_one_thread(monkeypatch):
    monkeypatch.setitem(_scale._STATE, "warned", False)
    K.use_backend("numpy")
    with pytest.warns(RuntimeWarning, match="one thread"):
        a = K.rotation_from_natural_invariants([0, 0, 1], [0.1, 0.2], threads=2)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        b = K.rotation_from_natural_invariants([0, 0, 1], [0.1, 0.2], threads=2)
    np.testing.assert_array_equal(a, b)
