"""The public kernels API: broadcasting, validation, singular handling, out=, backends."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from _profile import fast_or_slow

from rigidsym import kernels as K
from rigidsym.kernels.runtime import state as _state

E = np.array([0.0, 0.6, 0.8])


pytestmark = pytest.mark.usefixtures("backend")  # conftest: NumPy, then C


def test_lists_and_floats_and_broadcasting():
    Q = K.rotation_from_natural_invariants([0, 0, 1], 0.5)
    assert Q.shape == (3, 3)
    phis = np.linspace(0.1, 3.0, 10).reshape(2, 5)
    Qs = K.rotation_from_natural_invariants(E, phis)
    assert Qs.shape == (2, 5, 3, 3)
    np.testing.assert_allclose(Qs[1, 2], K.rotation_from_natural_invariants(E, phis[1, 2]))
    e2 = np.stack([E, [1.0, 0, 0]])[:, None, :]            # (2, 1, 3) x (4,) -> (2, 4)
    with pytest.warns(K.BroadcastWarning, match="new batch shape"):   # said
        assert K.rotation_from_natural_invariants(e2, np.ones(4)).shape == (2, 4, 3, 3)


def test_multiple_outputs_and_round_trip():
    phi = np.array([1e-8, 0.3, 2.0, np.pi - 1e-8, np.pi])
    Q = K.rotation_from_natural_invariants(E, phi)
    e, ph = K.natural_invariants_from_rotation(Q)
    np.testing.assert_allclose(ph, phi, rtol=0, atol=1e-15 * 4)
    np.testing.assert_allclose(e[:-1], np.broadcast_to(E, (4, 3)), atol=1e-7)
    # at phi = pi the sign rule: largest-magnitude component positive
    assert e[-1][np.argmax(np.abs(e[-1]))] > 0


def test_out_argument():
    out = np.empty((4, 3, 3))
    res = K.rotation_from_natural_invariants(E, np.ones(4), out=out)
    assert res is out
    outs = (np.empty((2, 3)), np.empty(2))
    Q = K.rotation_from_natural_invariants(E, [0.2, 0.4])
    r = K.natural_invariants_from_rotation(Q, out=outs)
    assert r[0] is outs[0] and r[1] is outs[1]
    nc = np.empty((3, 3, 4)).transpose(2, 0, 1)              # non-contiguous out
    res = K.rotation_from_natural_invariants(E, np.ones(4), out=nc)
    assert res is nc and np.isfinite(nc).all()
    with pytest.raises(ValueError, match="out"):
        K.rotation_from_natural_invariants(E, np.ones(4), out=np.empty((3, 3)))


def test_singular_raises_and_nan():
    with pytest.raises(K.SingularConfigurationError, match="'phi'.*\\(1,\\)") as info:
        K.N_matrix(E, [0.5, 0.0, 1.0])
    assert isinstance(info.value, ValueError) and info.value.indices == [(1,)]
    N = K.N_matrix(E, [0.5, 0.0, 1.0], on_singular="nan")
    assert np.isnan(N[1]).all() and np.isfinite(N[[0, 2]]).all()
    # near (not at) the singularity: finite, ~1/phi
    N = K.N_matrix(E, 1e-12)
    assert np.isfinite(N).all() and 1e11 < np.abs(N).max() < 1e13
    with pytest.raises(K.SingularConfigurationError, match="'a_dot'"):   # no motion
        K.instant_screw_axis([0, 0, 0], [1, 2, 3], [0, 0, 0])
    with pytest.raises(K.SingularConfigurationError):
        K.screw_axis_point(E, 0.0, [1, 0, 0], [1, 0, 1])
    with pytest.raises(K.SingularConfigurationError, match="angles"):
        K.euler_angle_rates([0.1, 0.0, 0.2], [1, 2, 3], "ZXZ")


def test_validation():
    with pytest.raises(ValueError, match="e: not a unit vector"):
        K.rotation_from_natural_invariants([1, 1, 0], 0.3)
    with pytest.raises(ValueError, match="phi: non-finite"):
        K.rotation_from_natural_invariants(E, np.nan)
    with pytest.raises(ValueError, match=r"e: expected shape \(\.\.\., 3\)"):
        K.rotation_from_natural_invariants([1, 0], 0.3)
    with pytest.raises(ValueError, match="Q: not orthogonal"):
        K.natural_invariants_from_rotation(2 * np.eye(3))
    with pytest.raises(ValueError, match="proper"):
        K.natural_invariants_from_rotation(-np.eye(3))
    # check=False skips it
    assert K.rotation_from_natural_invariants([1, 1, 0], 0.3, check=False).shape == (3, 3)
    with pytest.raises(ValueError, match="sequence"):
        K.euler_rate_matrix([0, 0, 0], "ZZZ")


def test_euler_rates_invert_W():
    rng = np.random.default_rng(0)
    ang = rng.uniform(0.2, 1.2, (5, 3))
    w = rng.standard_normal((5, 3))
    for seq in ("ZXZ", "ZYX", "XYZ"):
        for frame in ("fixed", "body"):
            W = K.euler_rate_matrix(ang, seq, frame)
            rates = K.euler_angle_rates(ang, w, seq, frame)
            np.testing.assert_allclose(np.einsum("nij,nj->ni", W, rates), w, atol=1e-12)


def test_swap_blocks():
    t = np.arange(12.0).reshape(2, 6)
    assert np.array_equal(K.swap_blocks(K.swap_blocks(t)), t)
    U = K.twist_transfer_matrix([1, 2, 3], [0, 1, 0])
    Us = K.swap_blocks(U, matrix=True)
    np.testing.assert_allclose(Us @ K.swap_blocks(t[0]), K.swap_blocks(U @ t[0]))


def test_fallback_warns_once(monkeypatch):
    def boom(*a, **k):
        raise OSError("no compiler")
    monkeypatch.setitem(_state.STATE, "backend", None)
    monkeypatch.setitem(_state.STATE, "warned", False)
    monkeypatch.setattr(_state.builtin(), "_clib", None)
    monkeypatch.setattr("rigidsym.kernels.cbuild.extension.load", boom)
    with pytest.warns(RuntimeWarning, match="C backend unavailable"):
        assert K.use_backend("c") == "numpy"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert K.use_backend("c") == "numpy"


# (name, argument scaled, scale): finite inputs whose output overflows, one per batch-loop
# shape of the C template: plain loop (no singular set), counting loop, blocked sin/cos loop
# (plucker_from_points at p1 = 1e308 [1, 0, 0] was here, but its moment is
# |p1| sin(angle) / ... = 1 there: the overflow was spurious, and the rescue now returns it;
# a Plücker array never overflows. instant_screw_axis's pitch and p0 do: 2.5e309)
OVERFLOW = [("kinetic_energy", "omega", 1e200), ("instant_screw_axis", "a_dot", 1e308),
            ("N_matrix_dot", "omega", 1e307)]
_ARGS = {"kinetic_energy": dict(I_C=np.diag([1.0, 2.0, 3.0]), m=2.0, omega=[1.0, 2.0, 3.0],
                                c_dot=[0.5, 0.0, 1.0]),
         "instant_screw_axis": dict(omega=[0.01, 0.02, 0.03], a=[1.0, 0.0, 0.0],
                                    a_dot=[0.5, 0.0, 1.0]),
         "N_matrix_dot": dict(e=E, phi=0.3, omega=[1.0, 2.0, -1.0])}



@pytest.mark.parametrize("name,arg,scale", OVERFLOW)
def test_overflow_is_reported(name, arg, scale):
    """Finite inputs whose output overflows: NonFiniteResultError naming the largest input and
    the batch indices, or NaN in exactly those rows; never a silent inf/NaN."""
    kw = {k: np.asarray(v, dtype=float) for k, v in _ARGS[name].items()}
    big = np.stack([kw[arg], kw[arg] * scale, kw[arg], kw[arg] * scale])      # batch (4,)
    kw_big = dict(kw, **{arg: big})
    assert all(np.isfinite(v).all() for v in kw_big.values())
    with pytest.raises(K.NonFiniteResultError, match="non-finite output \\(overflow\\)") as info:
        getattr(K, name)(**kw_big)
    assert isinstance(info.value, K.SingularConfigurationError)
    assert info.value.indices == [(1,), (3,)] and info.value.argument == arg
    assert f"'{arg}'" in str(info.value)
    res = _rows(getattr(K, name)(**kw_big, on_singular="nan"), 4)
    # NaN in the rows whose result overflows, every output of them
    assert np.isnan(res[[1, 3]]).all() and np.isfinite(res[[0, 2]]).all()
    one = _rows(getattr(K, name)(**kw), 1)
    np.testing.assert_array_equal(res[0], one[0])


def _rows(res, n):
    """The outputs of a call, one row per sample."""
    return np.concatenate([np.asarray(r).reshape(n, -1)
                           for r in (res if isinstance(res, tuple) else (res,))], axis=1)


@pytest.mark.parametrize("name,arg,scale", OVERFLOW)
def test_c_batch_counts_overflow_rows_across_blocks(name, arg, scale, backend):
    """The C batch function flags overflowing rows as it flags singular ones: NaN in exactly
    those rows, their number returned; rows in several blocks and in a partial last block."""
    if backend != "c":
        pytest.skip("C batch loop")
    meta = _state.meta()[name]
    n = 1000
    bad = [0, 63, 64, 255, 256, 700, 999]
    flat = []
    for a in meta["args"]:
        v = np.broadcast_to(np.asarray(_ARGS[name][a["name"]], dtype=float),
                            (n,) + tuple(a["shape"])).copy()
        if a["name"] == arg:
            v[bad] *= scale
        flat.append(v)
    outs = [np.empty((n,) + tuple(o["shape"])) for o in meta["outputs"]]
    with np.errstate(all="ignore"):
        count = K.batch_function(name, "c")(*flat, *outs)
    flagged = np.flatnonzero(np.isnan(np.concatenate([o.reshape(n, -1) for o in outs], 1))
                             .any(axis=1))
    assert count == len(bad) and flagged.tolist() == bad


# quick: NumPy; C (its own extension compiled, about 13 s) thorough: a user directory's C
# build has its quick test in test_build.py (never loads the package's kernels)
@pytest.mark.parametrize("backend", fast_or_slow(["numpy", "c"], {"numpy"}), indirect=True)
def test_load_other_generated_directory(tmp_path, backend):
    """load(DIR) builds the same checked namespace from any generated directory (here two
    kernels written by the generator into a temporary folder)."""
    from rigidsym.derivations.kernels_spec import KERNELS

    from rigidsym.codegen.generator import generate, write

    picked = [k for k in KERNELS if k.name in ("plucker_from_points", "N_matrix")]
    write(generate(picked), tmp_path)
    ns = K.load(tmp_path)
    assert K.load(tmp_path) is ns and ns is not K.load()
    assert ns.KERNEL_NAMES == ("N_matrix", "plucker_from_points")
    # only the kernels and the public helpers: nothing the generated module imports
    public = sorted(n for n in vars(ns) if not n.startswith("_"))
    assert public == ["KERNEL_NAMES", "N_matrix", "batch_function", "plucker_from_points"]
    assert sorted(n for n in vars(K.load()) if not n.startswith("_")) == \
        sorted([*K.KERNEL_NAMES, "KERNEL_NAMES", "batch_function"])
    p1, p2 = [[1.0, 2.0, 3.0], [0.0, 0.0, 0.0]], [-1.0, 0.5, 2.0]
    np.testing.assert_array_equal(ns.plucker_from_points(p2=p2, p1=p1),
                                  K.plucker_from_points(p1, p2))
    with pytest.raises(K.SingularConfigurationError, match="'phi'"):
        ns.N_matrix(e=E, phi=[0.3, 0.0])
    assert np.isnan(ns.N_matrix(e=E, phi=[0.3, 0.0], on_singular="nan")[1]).all()
    with pytest.raises(TypeError, match="^p1:"):
        ns.plucker_from_points(p1="abc", p2=p2)
    if backend == "c":
        assert ns._SPACE._clib is not None      # its own C, compiled into the cache
    with pytest.raises(FileNotFoundError, match="directory"):
        K.load(tmp_path / "nowhere")


@pytest.mark.parametrize("name,arg,scale", OVERFLOW[:1])
def test_an_unbatched_error_names_no_batch_index(name, arg, scale):
    """an unbatched call has no batch index to name (not "[()]")."""
    kw = dict({k: np.asarray(v, dtype=float) for k, v in _ARGS[name].items()})
    kw[arg] = kw[arg] * scale
    with pytest.raises(K.NonFiniteResultError) as info:
        getattr(K, name)(**kw)
    assert info.value.indices == [()] and "batch indices" not in str(info.value)
    assert "[()]" not in str(info.value) and f"'{arg}'" in str(info.value)


def test_two_batch_shapes_making_a_new_axis_warn_naming_both(backend):
    """e (5, 3) and phi (5, 1) broadcast to batch (5, 5), as NumPy does, with
    a BroadcastWarning naming both arguments and their shapes; the values are those of the
    explicit broadcast, which does not warn."""
    e = np.array([[0.0, 0.6, 0.8], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0],
                  [0.6, 0.8, 0.0]])
    phi = np.linspace(0.1, 2.0, 5).reshape(5, 1)
    with pytest.warns(K.BroadcastWarning) as rec:
        Q = K.rotation_from_natural_invariants(e, phi)
    msg = str(rec[0].message)
    assert rec[0].filename == __file__          # at the caller's line
    assert "e of shape (5, 3)" in msg and "phi of shape (5, 1)" in msg and "(5, 5)" in msg
    assert Q.shape == (5, 5, 3, 3)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        full = K.rotation_from_natural_invariants(np.broadcast_to(e, (5, 5, 3)),
                                                  np.broadcast_to(phi, (5, 5)))
        np.testing.assert_array_equal(Q, full)
        # Q[i, j] is the rotation about e[j] by phi[i]: NumPy's rule, row by row
        np.testing.assert_array_equal(Q[2, 4], K.rotation_from_natural_invariants(e[4],
                                                                                  phi[2, 0]))


@pytest.mark.parametrize("e_shape, phi_shape", [((5, 3), (5,)), ((3,), (5,)), ((5, 3), ()),
                                                ((1, 5, 3), (5,)), ((2, 1, 3), (2, 1)),
                                                ((0, 3), (0, 1))])
def test_broadcasts_adding_no_sample_do_not_warn(e_shape, phi_shape, backend):
    """Stretching size-1 axes or a missing leading axis gives no argument more samples than
    the largest one has: no warning (an empty batch neither)."""
    e = np.broadcast_to(E, e_shape).copy()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        K.rotation_from_natural_invariants(e, np.full(phi_shape, 0.5))
