"""Threads: the lazy C build and ``use_backend`` from several threads at once; the OpenMP
build and its one-thread fallback."""

from __future__ import annotations

import shutil
import threading
import time
import warnings
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import rigidsym.kernels as K
from rigidsym.codegen import cbuild

HAVE_CC = bool(shutil.which("gcc") or shutil.which("cc"))


def test_lazy_build_runs_once_under_a_thread_pool(monkeypatch):
    real = cbuild.load
    calls = []

    def slow_load(force=False):
        calls.append(threading.get_ident())
        time.sleep(0.2)            # wide window: without the lock every thread would build
        return real(force)

    monkeypatch.setattr(K, "_STATE", {"backend": None, "warned": False, "lib": None})
    monkeypatch.setattr(cbuild, "load", slow_load)
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


def test_cbuild_load_from_many_threads_returns_one_library():
    if not HAVE_CC:
        pytest.skip("no C compiler")
    with ThreadPoolExecutor(4) as pool:
        libs = list(pool.map(lambda _: cbuild.load()[1], range(8)))
    assert all(lib is libs[0] for lib in libs)


def test_openmp_build_when_the_compiler_has_it():
    if not HAVE_CC:
        pytest.skip("no C compiler")
    assert cbuild.openmp(), "gcc is present but the OpenMP build of the kernels failed"


def test_no_openmp_falls_back_to_one_thread_with_one_warning(monkeypatch, tmp_path):
    built = []

    def fake_build(gdir, meta, flags, libs, force):
        if "-fopenmp" in flags:
            raise OSError("omp.h: no such file")
        built.append(flags)
        return tmp_path / "fake.so"

    monkeypatch.setattr(cbuild, "_build", fake_build)
    monkeypatch.setattr(cbuild, "_WARNED", {"omp": False})
    with pytest.warns(RuntimeWarning, match="without OpenMP.*one thread"):
        assert cbuild.build() == tmp_path / "fake.so"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        cbuild.build()
    assert all("-fopenmp" not in f for f in built)
