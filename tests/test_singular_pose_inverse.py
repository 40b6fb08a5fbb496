"""Every kernel with partly defined outputs, through its inverse: the input back, or the
output flagged undetermined (NaN, an error).

The kernels whose outputs change form at a pose (Q = 1: the axis of no rotation is any unit
vector, a pure translation is a screw of infinite pitch; omega = 0: a translational twist):

- ``natural_invariants_from_rotation`` -> ``rotation_from_natural_invariants`` gives Q back
  (at Q = 1 with phi = 0 exactly and the default axis, which every unit vector is there);
- ``screw_of_displacement`` -> Chasles' displacement ``a' = p0 + Q(e, phi)(a - p0) + d e``
  with the slide ``d = pitch phi``: a' back for a screw of finite pitch; for a pure
  translation (pitch = +inf) ``e`` is the direction of a' - a, ``plucker = [0; e]`` and the
  slide is flagged undetermined (``inf * 0`` is NaN: it is not among the outputs); for no
  motion (Q = 1, a' = a) an error naming ``a_prime``, NaN but phi = 0 under
  ``on_singular="nan"``;
- ``instant_screw_axis`` -> the twist of the screw ``(p0, pitch, plucker)`` at amplitude
  ``w`` (the kernel's outputs are the unit screw; ``w = ||omega||``, or ``||a_dot||`` for a
  translation, Modern Robotics' theta): ``omega = w e'``, the origin's velocity
  ``w (n' + pitch e')``, or ``w [0; v/||v||]``'s ``v`` at infinite pitch; a_dot back;
- ``wrench_axis`` -> the wrench of the screw at magnitude ||f|| (||n_A|| for a pure couple,
  the dual of a translation).

NumPy, C, PyTorch and JAX back-ends, float64 and float32; the quick profile draws a few
batches.
"""

from __future__ import annotations

import shutil
import subprocess

import _installed
import numpy as np
import pytest
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidsym import kernels as K

#: NumPy, the C extension, and the PyTorch and JAX kernels (their extras: .ci/run's part)
BACKENDS = ("numpy", "c", pytest.param("torch", marks=pytest.mark.extra),
            pytest.param("jax", marks=pytest.mark.extra))
DTYPES = (np.float64, np.float32)
#: rows of each batch: drawn screw motions, rotations near 0 and pi, pure translations, none
N = 12


def _array_library(backend: str):
    """The PyTorch or JAX kernels, an array of the library from a NumPy array (lists are
    passed as they are) and a NumPy array back."""
    if backend == "torch":
        torch = pytest.importorskip("torch")
        from rigidsym.kernels import torch as lib
        return lib, torch.from_numpy, lambda x: x.numpy()
    jax = pytest.importorskip("jax")
    jax.config.update("jax_enable_x64", True)
    from rigidsym.kernels import jax as lib
    return lib, jax.numpy.asarray, np.asarray


def _run(backend: str, f, *args, **kw):
    """``f`` (a NumPy kernel of ``rigidsym.kernels``) on ``backend``, NumPy arrays out."""
    if backend in ("torch", "jax"):
        lib, to, back = _array_library(backend)
        res = getattr(lib, f.__name__)(*(to(x) if isinstance(x, np.ndarray) else x
                                         for x in args), **kw)
        return tuple(back(r) for r in res) if isinstance(res, tuple) else back(res)
    before = K.backend()
    try:
        if K.use_backend(backend) != backend:
            pytest.skip("no C extension")
        return f(*args, **kw)
    finally:
        K.use_backend(before)


def _axes(rng, n):
    e = rng.standard_normal((n, 3))
    return e / np.linalg.norm(e, axis=1, keepdims=True)


def _rotations(rng, dtype):
    """N rotations: the first two Q = 1 exactly, then angles near 0, near pi and anywhere
    (float64 matrices rounded to ``dtype``)."""
    tiny = 1e-6 if dtype == np.float64 else 1e-3
    phi = np.concatenate([[0.0, 0.0], tiny * rng.uniform(1, 10, 2),
                          np.pi - tiny * rng.uniform(0, 10, 2), rng.uniform(0, np.pi, N - 6)])
    Q = K.rotation_from_natural_invariants(_axes(rng, N), phi)
    Q[:2] = np.eye(3)
    return Q.astype(dtype)


def _tol(dtype) -> float:
    return 512 * float(np.finfo(dtype).eps)


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("backend", BACKENDS)
@settings(max_examples=examples(4), deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_natural_invariants_give_the_rotation_back(backend, dtype, seed):
    Q = _rotations(np.random.default_rng(seed), dtype)
    e, phi = _run(backend, K.natural_invariants_from_rotation, Q)
    assert np.all(phi[:2] == 0) and np.all(e[:2] == [1, 0, 0])    # any axis is right there
    back = K.rotation_from_natural_invariants(e, phi)
    assert np.abs(back.astype(np.float64) - Q).max() <= 8 * _tol(dtype)


def _displacements(rng, dtype):
    """N displacements: Q = 1 with a' - a != 0 (row 0) and a' = a (row 1), then screw
    motions (a rotation about the axis through p0, a slide d along it) with some d = 0."""
    Q = _rotations(rng, dtype)                       # near-0 angles of the type
    e, _ = (x.astype(np.float64) for x in K.natural_invariants_from_rotation(Q))
    Q = Q.astype(np.float64)
    a = rng.uniform(-2, 2, (N, 3))
    p0, d = rng.uniform(-2, 2, (N, 3)), rng.uniform(-1, 1, N)
    d[rng.uniform(size=N) < 0.3] = 0
    ap = p0 + np.einsum("nij,nj->ni", Q, a - p0) + d[:, None] * e
    ap[0] = a[0] + rng.uniform(-2, 2, 3)
    ap[1] = a[1]
    return Q.astype(dtype), a.astype(dtype), ap.astype(dtype)


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("backend", BACKENDS)
@settings(max_examples=examples(4), deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_screw_of_displacement_gives_the_displacement_back(backend, dtype, seed):
    Q, a, ap = _displacements(np.random.default_rng(seed), dtype)
    with pytest.raises(K.SingularConfigurationError, match="'a_prime'") as info:
        _run(backend, K.screw_of_displacement, Q, a, ap)
    assert info.value.indices == [(1,)]                       # no motion: row 1 only
    e, phi, p0, pitch, kappa = _run(backend, K.screw_of_displacement, Q, a, ap,
                                    on_singular="nan")
    R = np.full((N, 3, 3), np.nan)
    R[2:] = K.rotation_from_natural_invariants(e[2:], phi[2:])     # in the call's dtype
    e, phi, p0, pitch, kappa, Q, a, ap = (x.astype(np.float64) for x in
                                          (e, phi, p0, pitch, kappa, Q, a, ap))
    # no motion: every output undetermined but phi = 0
    assert phi[1] == 0 and np.isnan(e[1]).all() and np.isnan(p0[1]).all()
    assert np.isnan(pitch[1]) and np.isnan(kappa[1]).all()
    # a pure translation: the screw at infinity along t = a' - a; its slide is undetermined
    t = ap[0] - a[0]
    with np.errstate(invalid="ignore"):
        assert phi[0] == 0 and pitch[0] == np.inf and np.isnan(pitch[0] * phi[0])
    assert np.abs(e[0] - t / np.linalg.norm(t)).max() <= _tol(dtype)
    assert np.array_equal(kappa[0, :3], [0, 0, 0]) and np.array_equal(kappa[0, 3:], e[0])
    assert np.isfinite(p0[0]).all()
    # the screws of finite pitch: Chasles' displacement gives a' back
    r = slice(2, None)
    assert np.isfinite(pitch[r]).all()
    back = p0[r] + np.einsum("nij,nj->ni", R[r], a[r] - p0[r]) \
        + (pitch[r] * phi[r])[:, None] * e[r]
    scale = 1 + np.abs(a[r]).max() + np.abs(ap[r]).max() + np.abs(p0[r]).max()
    assert np.abs(back - ap[r]).max() <= _tol(dtype) * scale
    # and the Plücker array of a finite axis is [e; p0 x e]
    np.testing.assert_allclose(kappa[r], np.concatenate([e[r], np.cross(p0[r], e[r])], 1),
                               atol=_tol(dtype) * scale)


def _twists(rng, dtype):
    """N twists at points a: omega = 0 with a_dot != 0 (rows 0, 2) and a_dot = 0 (row 1),
    then general ones, some of zero pitch."""
    omega = rng.uniform(-2, 2, (N, 3))
    omega[:3] = 0
    a, a_dot = rng.uniform(-2, 2, (N, 3)), rng.uniform(-2, 2, (N, 3))
    a_dot[1] = 0
    flat = 3 + np.flatnonzero(rng.uniform(size=N - 3) < 0.3)
    a_dot[flat] -= (np.einsum("ni,ni->n", a_dot[flat], omega[flat])
                    / np.einsum("ni,ni->n", omega[flat], omega[flat]))[:, None] * omega[flat]
    return omega.astype(dtype), a.astype(dtype), a_dot.astype(dtype)


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("backend", BACKENDS)
@settings(max_examples=examples(4), deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_instant_screw_gives_the_twist_back(backend, dtype, seed):
    omega, a, a_dot = _twists(np.random.default_rng(seed), dtype)
    with pytest.raises(K.SingularConfigurationError, match="'a_dot'") as info:
        _run(backend, K.instant_screw_axis, omega, a, a_dot)
    assert info.value.indices == [(1,)]
    p0, pitch, kappa = (np.asarray(x, dtype=np.float64) for x in
                        _run(backend, K.instant_screw_axis, omega, a, a_dot,
                             on_singular="nan"))
    omega, a, a_dot = (x.astype(np.float64) for x in (omega, a, a_dot))
    assert np.isnan(p0[1]).all() and np.isnan(pitch[1]) and np.isnan(kappa[1]).all()
    w = np.linalg.norm(np.where((omega == 0).all(1)[:, None], a_dot, omega), axis=1)
    rows = np.r_[0, 2:N]
    inf = np.isinf(pitch[rows])
    assert np.array_equal(inf, (omega[rows] == 0).all(1))
    assert (pitch[rows][inf] > 0).all()
    with np.errstate(invalid="ignore"):
        om = w[rows, None] * kappa[rows, :3]
        v0 = np.where(inf[:, None], w[rows, None] * kappa[rows, 3:],
                      w[rows, None] * (kappa[rows, 3:] + pitch[rows, None] * kappa[rows, :3]))
    back = v0 + np.cross(om, a[rows])
    scale = 1 + np.abs(a_dot).max() + np.abs(omega).max() * (1 + np.abs(a).max())
    assert np.abs(om - omega[rows]).max() <= _tol(dtype) * scale
    assert np.abs(back - a_dot[rows]).max() <= _tol(dtype) * scale * (1 + np.abs(p0[rows]).max())


def _wrenches(rng, dtype):
    """N wrenches [n_A; f] at points a: f = 0 with n_A != 0 (rows 0, 2: pure couples) and
    w_A = 0 (row 1), then general ones."""
    w = rng.uniform(-2, 2, (N, 6))
    w[:3, 3:] = 0
    w[1] = 0
    return w.astype(dtype), rng.uniform(-2, 2, (N, 3)).astype(dtype)


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("backend", BACKENDS)
@settings(max_examples=examples(4), deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_wrench_axis_gives_the_wrench_back(backend, dtype, seed):
    """The wrench of the screw (p0, pitch, plucker) at magnitude ||f|| (||n_A|| for a pure
    couple): f = m e'', the moment about the origin m (n'' + pitch e''), or m [0; n/||n||]'s
    n at infinite pitch; n_A = n_O - a x f."""
    w, a = _wrenches(np.random.default_rng(seed), dtype)
    with pytest.raises(K.SingularConfigurationError, match="'w_A'") as info:
        _run(backend, K.wrench_axis, w, a)
    assert info.value.indices == [(1,)]
    p0, pitch, kappa = (np.asarray(x, dtype=np.float64) for x in
                        _run(backend, K.wrench_axis, w, a, on_singular="nan"))
    w, a = w.astype(np.float64), a.astype(np.float64)
    assert np.isnan(p0[1]).all() and np.isnan(pitch[1]) and np.isnan(kappa[1]).all()
    couple = (w[:, 3:] == 0).all(1)
    m = np.linalg.norm(np.where(couple[:, None], w[:, :3], w[:, 3:]), axis=1)
    rows = np.r_[0, 2:N]
    inf = np.isinf(pitch[rows])
    assert np.array_equal(inf, couple[rows]) and (pitch[rows][inf] > 0).all()
    with np.errstate(invalid="ignore"):
        f = m[rows, None] * kappa[rows, :3]
        n_O = np.where(inf[:, None], m[rows, None] * kappa[rows, 3:],
                       m[rows, None] * (kappa[rows, 3:] + pitch[rows, None] * kappa[rows, :3]))
    scale = 1 + np.abs(w).max() * (1 + np.abs(a).max())
    assert np.abs(f - w[rows, 3:]).max() <= _tol(dtype) * scale
    assert np.abs(n_O - np.cross(a[rows], f) - w[rows, :3]).max() \
        <= _tol(dtype) * scale * (1 + np.abs(p0[rows]).max())


@pytest.mark.extra
@pytest.mark.parametrize("backend", BACKENDS)
def test_pure_translation_as_the_peers(backend):
    """pytransform3d (screw parameters q, s, h of a translation: q = 0, s = t/||t||,
    h = inf) and Modern Robotics (MatrixLog6: S = [0; t/||t||], theta = ||t||) agree with
    screw_of_displacement at Q = 1 and with instant_screw_axis at omega = 0, up to their
    conventions (pytransform3d's q is our p0; their S is our plucker; theta, the slide, is
    not among our outputs)."""
    pt = pytest.importorskip("pytransform3d.transformations")
    mr = _installed.peer("modern_robotics", "modern_robotics")
    rng = np.random.default_rng(11)
    for t in [np.array([0.0, 0.5, 0.2]), *rng.uniform(-3, 3, (5, 3))]:
        a = rng.uniform(-1, 1, 3)
        e, phi, p0, pitch, kappa = _run(backend, K.screw_of_displacement, np.eye(3), a, a + t)
        T = np.eye(4)
        T[:3, 3] = t
        q, s, h = pt.screw_parameters_from_screw_axis(
            pt.screw_axis_from_exponential_coordinates(
                pt.exponential_coordinates_from_transform(T))[0])
        S, theta = mr.AxisAng6(mr.se3ToVec(mr.MatrixLog6(T)))
        assert h == pitch == np.inf and phi == 0
        np.testing.assert_allclose(e, s, rtol=0, atol=1e-15)
        np.testing.assert_allclose(p0, q, rtol=0, atol=0)
        np.testing.assert_allclose(kappa, S, rtol=0, atol=1e-15)
        np.testing.assert_allclose(theta, float(np.dot(e, t)), rtol=1e-15)
        # the instant screw of the twist [0; t] at a: the same screw at infinity
        p0_i, pitch_i, kappa_i = _run(backend, K.instant_screw_axis, np.zeros(3), a, t)
        assert pitch_i == np.inf
        np.testing.assert_allclose(kappa_i, S, rtol=0, atol=1e-15)
        np.testing.assert_array_equal(p0_i, q)


def test_docstrings_list_the_pure_translation():
    """The kernels that answer a pure translation (a pure couple) say so in their
    docstrings, without the generated sentences on the finite placeholders and on a singular
    set that the answer leaves."""
    for f in (K.screw_of_displacement, K.instant_screw_axis, K.wrench_axis):
        doc = f.__doc__
        assert ("Pure translation: at " in doc or "Pure couple: at " in doc) \
            and "pitch = +inf" in doc, f.__name__
        for stale in ("hold documented defaults", "Singular set: f = 0 (pure moment).",
                      "(f = 0 (pure moment))", "Singular set: omega = 0 (pure translation).",
                      "(omega = 0 (pure translation))"):
            assert stale not in doc, (f.__name__, stale)


@pytest.mark.extra
@pytest.mark.parametrize("backend", ["torch", "jax"])
def test_array_docstrings_list_the_pure_translation(backend):
    """The PyTorch and JAX kernels say the same, and name no motion (load) as their only
    singular set."""
    lib = _array_library(backend)[0]
    for f in (lib.screw_of_displacement, lib.instant_screw_axis, lib.wrench_axis):
        doc = f.__doc__
        assert ("Pure translation: at " in doc or "Pure couple: at " in doc) \
            and "pitch = +inf" in doc, f.__name__
        assert "no motion (naming" in doc or "no load (naming" in doc, f.__name__
        assert "(pure moment)" not in doc and "(pure translation))" not in doc, f.__name__


@pytest.mark.parametrize("backend", BACKENDS)
def test_pure_translation_at_the_ends_of_the_range(backend):
    """A translation whose a' - a overflows keeps its direction (finite in, the answer
    out); an unchecked NaN in a' gives NaN in every output that depends on it (phi = 0
    does not)."""
    for dtype, big in ((np.float64, 1e308), (np.float32, np.float32(3e38))):
        I3 = np.eye(3, dtype=dtype)
        a, ap = np.array([-big, 0, 0], dtype), np.array([big, big, 0], dtype)
        e, phi, p0, pitch, kappa = _run(backend, K.screw_of_displacement, I3, a, ap)
        assert e.dtype == dtype and pitch == np.inf and phi == 0
        np.testing.assert_allclose(e, [2 / 5**0.5, 1 / 5**0.5, 0], rtol=4e-7)
        p0, pitch, kappa = _run(backend, K.instant_screw_axis, np.zeros(3, dtype), a, ap)
        assert pitch == np.inf and np.allclose(kappa[3:], [2**-0.5, 2**-0.5, 0])
    e, phi, p0, pitch, kappa = _run(backend, K.screw_of_displacement, np.eye(3),
                                    [0.0, 0, 0], [np.nan, 1, 0], check=False,
                                    on_singular="nan")
    assert phi == 0 and all(np.isnan(x).all() for x in (e, p0, pitch, kappa))


def test_strided_out_arrays_and_the_backends_agree():
    """The answer reaches the caller's strided ``out`` arrays, and NumPy and C give the same
    bits for a batch mixing translations and screws."""
    Q = np.stack([np.eye(3)] * 4)
    Q[2:] = K.rotation_from_natural_invariants([0, 0.6, 0.8], [0.5, 1.0])
    a, ap = np.zeros((4, 3)), np.array([[1, 2, 2], [3, 0, 0], [1, 1, 1], [0, 0, 1.0]])
    ref = _run("numpy", K.screw_of_displacement, Q, a, ap)
    assert np.array_equal(ref[3][:2], [np.inf, np.inf])
    np.testing.assert_array_equal(ref[0][:2], [[1 / 3, 2 / 3, 2 / 3], [1, 0, 0]])
    for backend in ("numpy", "c"):
        big = [np.empty((4, 2 * n)) for n in (3, 1, 3, 1, 6)]
        out = tuple(b[:, ::2] if b.shape[1] > 2 else b[:, 0] for b in big)
        got = _run(backend, K.screw_of_displacement, Q, a, ap, out=out)
        assert all(g is o for g, o in zip(got, out, strict=True))
        for g, w in zip(got, ref, strict=True):
            np.testing.assert_array_equal(g, w)


#: the C target's kernels of partly defined outputs: (name, input sizes, output sizes)
_C_KERNELS = (("natural_invariants_from_rotation", (9,), (3, 1)),
              ("screw_of_displacement", (9, 3, 3), (3, 1, 3, 1, 6)),
              ("instant_screw_axis", (3, 3, 3), (3, 1, 6)),
              ("wrench_axis", (6, 3), (3, 1, 6)))
#: the generated placeholders of the C target's RIGIDSYM_C_DEFAULT_OUTPUT (16), flattened
_C_PLACEHOLDERS = {"natural_invariants_from_rotation": [1, 0, 0, 0],
                   "screw_of_displacement": [1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0]}


def _c_rows(rng, dtype) -> dict:
    """Each kernel's rows in ``dtype``: its poses of partly defined outputs first."""
    Q = _rotations(rng, dtype)
    Qd, a, ap = _displacements(rng, dtype)
    return {"natural_invariants_from_rotation": (Q,), "screw_of_displacement": (Qd, a, ap),
            "instant_screw_axis": _twists(rng, dtype), "wrench_axis": _wrenches(rng, dtype)}


def _c_call(name: str, ins: tuple, outs: tuple, suffix: str, ctype: str, fmt: str,
            row: list) -> str:
    """One C block: the row's inputs, the call, the status and outputs printed."""
    decl = [f"const {ctype} i{j}[{n}] = {{" + ", ".join(repr(float(v)) for v in x.ravel())
            + "};" for j, (n, x) in enumerate(zip(ins, row, strict=True))]
    offs = np.cumsum((0, *outs))[:-1]
    call = (f"s = rigidsym_c_{name}{suffix}(" + ", ".join(
        [f"i{j}" for j in range(len(ins))] + [f"o{suffix} + {o}" for o in offs]) + ");")
    return ("{ " + " ".join(decl) + f' {call} printf("%d", s); for (i = 0; i < {sum(outs)};'
            f' i++) printf(" {fmt}", (double)o{suffix}[i]); printf("\\n"); }}')


@pytest.mark.slow  # four kernels derived for the C target and a gcc build: ~1 min
@pytest.mark.skipif(shutil.which("gcc") is None, reason="gcc is not installed")
def test_c_target_gives_the_input_back_or_says_it_cannot(tmp_path):
    """The C target, double and float: where the status is 0 the outputs are the NumPy
    kernels' of the same type (which give the input back, above) to the type's tolerance;
    the poses the runtime answers as screws at infinity are flagged there,
    RIGIDSYM_C_DEFAULT_OUTPUT (16) with the documented placeholders (and phi = 0, where
    NumPy's phi is 0 exactly) or RIGIDSYM_C_SINGULAR (1, with NONFINITE_RESULT 4) with every
    output NaN: never a status 0 with another screw's values."""
    from rigidsym.codegen.backends.c.target import generate_c
    from rigidsym.codegen.generator import compile_many
    from rigidsym.codegen.usergen import select_kernels

    ks, origin = select_kernels(None, [k[0] for k in _C_KERNELS])
    for path, text in generate_c(compile_many(ks, plan32=False), origin).items():
        (tmp_path / path).write_text(text)
    rows = {dt: _c_rows(np.random.default_rng(5), dt) for dt in DTYPES}
    body = [_c_call(name, ins, outs, suffix, ctype, fmt, [x[r] for x in rows[dt][name]])
            for name, ins, outs in _C_KERNELS
            for dt, suffix, ctype, fmt in ((np.float64, "", "double", "%.17g"),
                                           (np.float32, "_f32", "float", "%.9g"))
            for r in range(N)]
    (tmp_path / "main.c").write_text(
        '#include <stdio.h>\n#include "rigidsym_c.h"\nint main(void)\n{\n'
        "    double o[16]; float o_f32[16]; int s, i;\n    "
        + "\n    ".join(body) + "\n    return 0;\n}\n")
    exe = tmp_path / "main"
    subprocess.run(["gcc", "-std=c99", "-O2", "-I", str(tmp_path), str(tmp_path / "main.c"),
                    *map(str, tmp_path.glob("rigidsym_c_*.c")), "-o", str(exe), "-lm"],
                   check=True)
    lines = iter(subprocess.run([str(exe)], check=True, capture_output=True,
                                text=True).stdout.splitlines())
    seen = set()
    for name, _ins, _outs in _C_KERNELS:
        for dt in DTYPES:
            want = np.concatenate(
                [np.asarray(o, dtype=np.float64).reshape(N, -1) for o in
                 _run("numpy", getattr(K, name), *rows[dt][name], on_singular="nan")], 1)
            for r in range(N):
                s, *got = (float(x) for x in next(lines).split())
                label = (name, np.dtype(dt).name, r, s, got)
                seen.add(int(s) & 17)
                if s == 16:
                    assert got == _C_PLACEHOLDERS[name] and want[r][3] == 0, label
                elif int(s) & 1:                # with NONFINITE_RESULT (4) on the way
                    assert np.isnan(got).all() and not np.isfinite(want[r]).all(), label
                else:
                    assert s == 0 and np.isfinite(want[r]).all(), label
                    scale = 1 + np.abs(want[r]).max()
                    assert np.abs(np.array(got) - want[r]).max() \
                        <= 4096 * scale * float(np.finfo(dt).eps), label
    assert seen == {0, 1, 16}


@pytest.mark.extra
@pytest.mark.parametrize("backend", ["torch", "jax"])
def test_the_screw_at_infinity_traced_and_differentiated(backend):
    """Traced (jax.jit, torch.func.vmap), the pure translation's row is the eager answer and
    no motion's is NaN (on_singular='nan', the traced default); a gradient through a batch
    holding both is finite, that of e along t/||t|| (d e/d a' = (1 - e e^T)/||t||)."""
    lib, to, back = _array_library(backend)
    Q = np.stack([np.eye(3)] * 3)
    Q[2] = K.rotation_from_natural_invariants([0.0, 0.6, 0.8], 0.5)
    a, ap = np.zeros((3, 3)), np.array([[1.0, 2.0, 2.0], [0.0, 0.0, 0.0], [1.0, 1.0, 1.0]])
    eager = lib.screw_of_displacement(to(Q), to(a), to(ap), on_singular="nan")
    t = ap[0] / 3.0
    want = (np.eye(3) - np.outer(t, t)) / 3.0           # d e / d a' of row 0, ||t|| = 3
    if backend == "jax":
        import jax
        import jax.numpy as jnp

        traced = jax.jit(lambda *x: lib.screw_of_displacement(*x))(to(Q), to(a), to(ap))
        grad = jax.jacfwd(lambda p: lib.screw_of_displacement(to(Q), to(a), p)[0])(to(ap))
        grad = np.asarray(grad)[0, :, 0, :]
        assert bool(jnp.all(jnp.isfinite(grad)))
    else:
        import torch

        traced = torch.func.vmap(lambda q, x, y: lib.screw_of_displacement(q, x, y))(
            to(Q), to(a), to(ap))
        grad = torch.autograd.functional.jacobian(
            lambda p: lib.screw_of_displacement(to(Q), to(a), p, on_singular="nan")[0][0],
            to(ap))[:, 0, :].numpy()
    for e, t_ in zip(eager, traced, strict=True):  # the same NaN and inf; values to an ulp
        np.testing.assert_allclose(back(e), back(t_), rtol=1e-15, atol=0)
    got = back(traced[3])
    assert got[0] == np.inf and np.isnan(got[1]) and np.isfinite(got[2])
    np.testing.assert_allclose(grad, want, atol=1e-12)
