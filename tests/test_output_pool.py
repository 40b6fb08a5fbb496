"""The kernels' output pool (rigidsym.kernels.set_output_pool): an output block is handed out
again only when nothing refers to it any more, and the values are the same as without it."""

from __future__ import annotations

import ctypes
import multiprocessing
import pickle
import sys
import threading
import weakref

import numpy as np
import pytest

from rigidsym import kernels
from rigidsym.kernels.runtime import outpool

pytestmark = pytest.mark.skipif(not outpool.supported(), reason="needs CPython with the GIL")

N = 600
#: kernels whose arguments are unit vectors, angles or free vectors (random valid inputs)
NAMES = ("rotation_from_natural_invariants", "rotation_from_euler_rodrigues", "N_matrix",
         "screw_axis_point", "instant_screw_axis")


def _inputs(name: str, n: int = N, dtype=np.float64, seed: int = 3) -> list[np.ndarray]:
    rng = np.random.default_rng(seed)
    xs = []
    for a in kernels.load()._SPACE.meta[name]["args"]:
        shape = (n, *a["shape"])
        if a["kind"] == "unit":
            v = rng.standard_normal(shape)
            v /= np.linalg.norm(v, axis=-1, keepdims=True)
        elif a["kind"] == "angle":
            v = rng.uniform(-3.0, 3.0, shape)
        else:
            v = rng.standard_normal(shape)
        xs.append(v.astype(dtype))
    return xs


def _outs(r) -> tuple:
    return r if isinstance(r, tuple) else (r,)


def _span(a: np.ndarray) -> tuple[int, int]:
    lo = a.__array_interface__["data"][0]
    return lo, lo + a.nbytes


def _overlap(a: np.ndarray, b: np.ndarray) -> bool:
    (a0, a1), (b0, b1) = _span(a), _span(b)
    return a0 < b1 and b0 < a1


@pytest.fixture
def pool():
    """The pool on for small outputs too (min_bytes 0), a fresh one, on the C backend (the
    pool serves the C entries; other tests leave NumPy selected); the state restored."""
    backend = kernels.backend()
    if kernels.use_backend("c") != "c":
        pytest.skip("the output pool serves the C backend, which this install lacks")
    before = kernels.set_output_pool()
    kernels.release_output_pool()
    yield kernels.set_output_pool(True, min_bytes=0, max_bytes=64 << 20)
    kernels.set_output_pool(before["enabled"], min_bytes=before["min_bytes"],
                            max_bytes=before["max_bytes"])
    kernels.release_output_pool()
    kernels.use_backend(backend)


def test_same_bits_as_without_the_pool(pool):
    for name in NAMES:
        for dtype in (np.float64, np.float32):
            f = getattr(kernels, name)
            xs = _inputs(name, dtype=dtype)
            kernels.set_output_pool(False)
            ref = [o.copy() for o in _outs(f(*xs, check=False))]
            kernels.set_output_pool(True)
            for _ in range(3):         # the first call takes new blocks, the others reuse
                got = _outs(f(*xs, check=False))
                assert all(g.base is not None for g in got)           # on pooled blocks
                for g, r in zip(got, ref, strict=True):
                    assert g.dtype == r.dtype and g.shape == r.shape and g.flags.c_contiguous
                    assert g.tobytes() == r.tobytes(), (name, dtype)
                del got


def test_a_freed_block_is_reused(pool):
    f = kernels.rotation_from_natural_invariants
    xs = _inputs("rotation_from_natural_invariants")
    spans = {_span(f(*xs, check=False)) for _ in range(5)}
    assert len(spans) == 1              # each result dropped at once: one block serves all


def _holders(y: np.ndarray) -> list:
    """Every kind of object that keeps y's memory alive without being y."""
    mv = memoryview(y)
    return [y[::2], y.reshape(-1)[5:], y.T, y.view(np.uint8), mv, np.frombuffer(mv),
            np.asarray(mv), pickle.PickleBuffer(y),
            y.ctypes.data_as(ctypes.POINTER(ctypes.c_double)), y.base]


def test_never_hands_out_memory_still_referenced(pool):
    f = kernels.screw_axis_point
    xs = _inputs("screw_axis_point")
    for which in range(10):
        y = f(*xs, check=False)
        lo, hi = _span(y)
        bits = y.tobytes()
        keep = _holders(y)[which]
        del y
        for _ in range(4):
            z = f(*xs, check=False)
            z0, z1 = _span(z)
            assert not (lo < z1 and z0 < hi), which
            z[...] = -1.0                   # the new output written over entirely
            del z
        assert keep is not None and ctypes.string_at(lo, hi - lo) == bits, which
        del keep


def test_views_keep_their_bits(pool):
    f = kernels.N_matrix
    xs = _inputs("N_matrix")
    live = []
    for i in range(6):
        y = f(*xs, check=False)
        v = _holders(y)[i % 4]
        live.append((v, np.array(v, copy=True)))
        del y, v
    for (a, _), (b, _) in ((p, q) for i, p in enumerate(live) for q in live[i + 1:]):
        assert not np.shares_memory(a, b)
    for _ in range(3):
        f(*xs, check=False)[...] = np.nan   # reused blocks written over
    for v, copy in live:
        assert np.array_equal(v, copy)


def test_weak_reference_blocks_are_not_reused(pool):
    f = kernels.N_matrix
    xs = _inputs("N_matrix")
    y = f(*xs, check=False)
    w = weakref.ref(y.base)
    del y
    z = f(*xs, check=False)
    assert w() is None or not np.shares_memory(z, w())


def test_pickled_and_copied_outputs_are_their_own(pool):
    f = kernels.rotation_from_natural_invariants
    xs = _inputs("rotation_from_natural_invariants")
    y = f(*xs, check=False)
    bits = y.tobytes()
    u = pickle.loads(pickle.dumps(y))
    c = y.copy()
    del y
    f(*xs, check=False)[...] = 0.0
    assert u.tobytes() == bits and c.tobytes() == bits


def test_bound(pool):
    kernels.set_output_pool(max_bytes=3 * N * 9 * 8)
    f = kernels.rotation_from_natural_invariants
    xs = _inputs("rotation_from_natural_invariants")
    held = [f(*xs, check=False) for _ in range(5)]
    state = kernels.set_output_pool()
    assert state["bytes"] <= state["max_bytes"] and state["blocks"] == 3
    assert sum(h.base is not None for h in held) == 3          # the others allocated as before
    assert all(not np.shares_memory(a, b) for i, a in enumerate(held) for b in held[i + 1:])
    del held
    assert kernels.release_output_pool() == 3 * N * 9 * 8
    assert kernels.set_output_pool()["blocks"] == 0


def test_threads(pool):
    f = kernels.instant_screw_axis
    xs = _inputs("instant_screw_axis")
    ref = [o.copy() for o in f(*xs, check=False)]
    kept = []

    def work(seed):
        rng = np.random.default_rng(seed)
        mine = []
        for _ in range(40):
            out = f(*xs, check=False)
            if rng.random() < 0.3:
                mine.append(out[rng.integers(3)][::3])      # a view of one output
            for o in out:
                o[...] = rng.standard_normal(o.shape)       # the caller writes its outputs
            del out
        kept.extend(mine)

    threads = [threading.Thread(target=work, args=(s,)) for s in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    snap = [(v, v.copy()) for v in kept]
    for _ in range(10):
        for o in f(*xs, check=False):
            o[...] = 7.0
    assert all(np.array_equal(v, c) for v, c in snap)
    assert all(not _overlap(a, b) for i, (a, _) in enumerate(snap) for b, _ in snap[i + 1:])
    got = f(*xs, check=False)
    assert all(g.tobytes() == r.tobytes() for g, r in zip(got, ref, strict=True))


def _child(seed: int) -> bytes:
    f = kernels.N_matrix
    xs = _inputs("N_matrix", seed=seed)
    first = f(*xs, check=False)
    keep = first[1:]
    again = f(*xs, check=False)
    assert not np.shares_memory(keep, again) and kernels.set_output_pool()["enabled"]
    return pickle.dumps(again)


@pytest.mark.skipif(sys.platform != "linux", reason="fork start method")
def test_four_processes(pool):
    f = kernels.N_matrix
    with multiprocessing.get_context("fork").Pool(4) as procs:
        got = procs.map(_child, range(4))
    for seed, blob in enumerate(got):
        kernels.set_output_pool(False)
        ref = f(*_inputs("N_matrix", seed=seed), check=False)
        kernels.set_output_pool(True)
        assert pickle.loads(blob).tobytes() == ref.tobytes()


def test_other_calls_unchanged(pool):
    f = kernels.screw_axis_point
    xs = _inputs("screw_axis_point")
    bad = [x.copy() for x in xs]
    bad[0][7] *= 2.0                     # not a unit vector: the same error with or without
    with pytest.raises(ValueError) as on:
        f(*bad)
    kernels.set_output_pool(False)
    with pytest.raises(ValueError) as off:
        f(*bad)
    assert str(on.value) == str(off.value)
    kernels.set_output_pool(True)
    assert f(xs[0][0], xs[1][0], xs[2][0], xs[3][0]).base is None   # one sample: no pool
    out = np.empty((N, 3))
    assert f(*xs, out=out) is out
    # mixed float32 and float64 inputs: float64 outputs, pooled as well (the C entry knows
    # the outputs' dtype and batch shape after it reads the inputs), the same values
    mixed = [x.astype(np.float32) for x in xs[:2]] + xs[2:]
    y = f(*mixed)
    assert y.dtype == np.float64 and y.base is not None
    kernels.set_output_pool(False)
    np.testing.assert_array_equal(y, f(*mixed))


def test_settings():
    with pytest.raises(TypeError):
        kernels.set_output_pool("yes")
    with pytest.raises(TypeError):
        kernels.set_output_pool(max_bytes=1.5)
    with pytest.raises(ValueError):
        kernels.set_output_pool(min_bytes=-1)
    assert outpool.parse_setting(None) is None and outpool.parse_setting("off") is None
    assert outpool.parse_setting("1") == outpool.DEFAULT_MAX_BYTES
    assert outpool.parse_setting("512M") == 512 << 20 and outpool.parse_setting("2g") == 2 << 30
    assert outpool.parse_setting("1000") == 1000
    with pytest.raises(ValueError, match="RIGIDSYM_OUTPUT_POOL"):
        outpool.parse_setting("lots")


def test_on_or_off_the_functions_call_their_c_entries(pool, monkeypatch):
    """The compiled entries ask the pool themselves (no Python frame in a call, pool on or
    off): a call below ``min_bytes`` never reaches Python, a larger one asks once."""
    import rigidsym.generated.api as api
    f = kernels.N_matrix
    xs = _inputs("N_matrix")
    f(*xs)
    space = kernels.load()._SPACE
    assert api._F is space._entries
    asked = []
    take = outpool.take
    monkeypatch.setattr(outpool, "take", lambda *a: asked.append(a) or take(*a))
    kernels.set_output_pool(True, min_bytes=1 << 20)     # rebinds: the C reads both anew
    small = [x[:10] for x in xs]
    assert f(*small, check=False).base is None and not asked
    big = _inputs("N_matrix", n=30000)                   # 30000 x 12 doubles: 2.9 MB
    assert f(*big, check=False).base is not None and len(asked) == 1
    kernels.set_output_pool(False)
    assert api._F is space._entries
    y = f(*xs, check=False)
    assert y.base is None and kernels.set_output_pool()["blocks"] == 0 and len(asked) == 1


def test_empty_batches_are_not_pooled(pool):
    xs = _inputs("N_matrix", n=0)
    y, z = kernels.N_matrix(*xs, check=False), kernels.N_matrix(*xs, check=False)
    assert y.shape == (0, 4, 3) and y.base is None and z.base is None


def test_flagged_rows_the_same(pool):
    # singular rows (phi = 0: no screw axis) and rows of extreme magnitude, which the entry
    # hands to the Python path with the pool's arrays as out=
    f = kernels.screw_axis_point
    xs = _inputs("screw_axis_point")
    xs[1][::7] = 0.0
    xs[2][3::11] *= 1e-300
    xs[3][5::13] *= 1e200
    kernels.set_output_pool(False)
    ref = f(*xs, on_singular="nan")
    kernels.set_output_pool(True)
    got = f(*xs, on_singular="nan")
    assert got.base is not None and np.isnan(ref).any() and got.tobytes() == ref.tobytes()
