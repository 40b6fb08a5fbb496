"""Generated kernels against their symbolic declarations, evaluated in mpmath at 50 digits.

Each kernel is evaluated at the same float64 inputs by the generated code (NumPy and C) and
by the declared sympy expressions (the formula functions composed in
``derivations/kernels_spec.py``, before any rewrite) in mpmath with 50 digits. Per-sample
error = max|got - ref| / max|ref|; required <= 1e-13. Points: 1000 random ones per public
kernel plus adversarial ones (phi in {1e-12, 1e-8, 1e-4, pi - 1e-8}, ||omega|| in
{1e-12, 1e-6}, near gimbal lock, rotations near 0 and pi).
"""

from __future__ import annotations

import shutil
from functools import cache

import mpmath
import numpy as np
import pytest
import sympy as sp
from rigidsym.derivations.kernels_spec import KERNELS

from rigidsym import kernels as K
from rigidsym.codegen.generator import _flatten
from rigidsym.codegen.spec import flat_symbols, input_symbols
from rigidsym.kernels.runtime import state as _state

TOL = 1e-13
# the kernels generated/ holds (test_generated_fresh.py checks it matches the spec)
AVAILABLE = {k.name: k for k in KERNELS
             if k.name in _state.meta()}
PUBLIC = sorted(n for n, k in AVAILABLE.items() if k.public)
EULER = sorted(n for n, k in AVAILABLE.items() if not k.public)
ADV_PHI = [1e-12, 1e-8, 1e-4, np.pi - 1e-8]
#: kernels whose generated formula rests on an identity that holds on SO(3) only (
#: rigidsym.codegen.accuracy.rewrites: 1 - cos phi from the skew part of Q), name -> column of phi
# in : the flat output. The reference here is the declared formula at the *rounded* Q, off SO(3):
#: that differs from the problem's answer by the rounding of Q over sin^2(phi) (the loss the
#: rewrite removed), so its rows get that bound here; tests/test_accuracy.py judges the kernel
#: at the exact rotation against its condition number (about 1/sin(phi)).
ON_SO3 = {"screw_of_displacement": 3}


def row_tol(name: str, ref: np.ndarray, u: float, tol: float):
    """``tol``, or per row ``tol + 8 u (1 + 1/sin^2 phi)`` for the kernels of ON_SO3."""
    if name not in ON_SO3:
        return tol
    s2 = np.sin(ref[:, ON_SO3[name]]) ** 2
    return tol + 8 * u * (1 + 1 / np.maximum(s2, 1e-300))


def _unit(rng, n, k=3):
    x = rng.standard_normal((n, k))
    return x / np.linalg.norm(x, axis=1, keepdims=True)


def _rotations(e, phi):
    return K.rotation_from_natural_invariants(e, phi, check=False)


def inputs(kernel, n: int, seed: int = 0) -> list[np.ndarray]:
    """Random inputs followed by adversarial rows for ``kernel``'s argument kinds."""
    rng = np.random.default_rng(seed)
    names = [a.name for a in kernel.args]
    out = []
    adv = len(ADV_PHI)
    for a in kernel.args:
        if a.kind == "unit":
            v = _unit(rng, n + adv, a.size)
        elif a.kind == "angle":
            v = np.concatenate([rng.uniform(0.0, np.pi, n), ADV_PHI])
        elif a.kind in ("rotation", "transform"):
            ph = np.concatenate([rng.uniform(0.0, np.pi, n), [1e-6, np.pi - 1e-8, np.pi,
                                                               np.pi - 1e-4]])
            v = _rotations(_unit(rng, n + adv), ph)
            if a.kind == "transform":   # [[R, p], [0, 1]] (the log of SE(3) reads one)
                R, v = v, np.zeros((n + adv, 4, 4))
                v[:, :3, :3], v[:, :3, 3], v[:, 3, 3] = R, rng.standard_normal((n + adv, 3)), 1
        elif a.name == "m":
            v = rng.uniform(0.5, 2.0, n + adv)
        elif a.name == "I_C":    # an inertia matrix: tr(S) 1 - S of a second moment S
            g = rng.standard_normal((n + adv, 3, 3))        # (so a body's: the triangle
            S = np.einsum("nij,nkj->nik", g, g) + 0.1 * np.eye(3)   # inequality holds)
            v = np.trace(S, axis1=1, axis2=2)[:, None, None] * np.eye(3) - S
        else:
            v = rng.standard_normal((n + adv,) + a.shape)
            if a.name == "omega" and "omega_dot" not in names and "phi" not in names:
                v[n:n + 2] *= np.array([1e-12, 1e-6])[:, None] / np.linalg.norm(
                    v[n:n + 2], axis=1, keepdims=True)
            if a.name == "angles":   # near gimbal lock of either family
                v[n:, 1] = [1e-9, np.pi / 2 - 1e-9, -1e-9, np.pi / 2 + 1e-9]
        out.append(np.ascontiguousarray(v, dtype=np.float64))
    return out


@cache
def reference(name: str):
    """mpmath (50 digits) functions of the declared outputs, per variant, and conditions."""
    kernel = AVAILABLE[name]
    syms = input_symbols(kernel)
    flat = [s for _, ss in flat_symbols(kernel) for s in ss]
    variants = []
    for br in kernel.branches:
        cond = sp.lambdify(flat, br.when(**syms), modules="mpmath")
        variants.append((cond, sp.lambdify(flat, _flatten(kernel, br.build(**syms)),
                                           modules="mpmath", cse=True)))
    variants.append((None, sp.lambdify(flat, _flatten(kernel, kernel.build(**syms)),
                                       modules="mpmath", cse=True)))
    return variants


def ref_eval(name: str, arrays: list[np.ndarray]) -> np.ndarray:
    kernel = AVAILABLE[name]
    n = arrays[0].shape[0]
    cols = np.concatenate([a.reshape(n, -1) for a in arrays], axis=1)
    variants = reference(name)
    res = []
    with mpmath.workdps(50):
        for row in cols:
            xs = [mpmath.mpf(float(x)) for x in row]
            for cond, f in variants:
                if cond is None or cond(*[float(x) for x in row]):
                    res.append([float(v) for v in f(*xs)])
                    break
    size = sum(o.size for o in kernel.outputs)
    return np.array(res, dtype=float).reshape(n, size)


def run(name: str, arrays, backend: str) -> tuple[np.ndarray, np.ndarray]:
    kernel = AVAILABLE[name]
    n = arrays[0].shape[0]
    outs = [np.empty((n,) + o.shape) for o in kernel.outputs]
    with np.errstate(all="ignore"):
        K.batch_function(name, backend)(*arrays, *outs)
    got = np.concatenate([o.reshape(n, -1) for o in outs], axis=1)
    return got, ~np.isfinite(got).all(axis=1)


def rel_err(got, ref) -> np.ndarray:
    scale = np.abs(ref).max(axis=1)
    scale = np.where(scale == 0, 1.0, scale)
    return np.abs(got - ref).max(axis=1) / scale


@pytest.fixture(scope="module", params=["numpy", "c"])
def backend(request):
    if request.param == "c" and K.use_backend("c") != "c":
        if shutil.which("gcc") or shutil.which("cc"):
            pytest.fail("a C compiler is present but the C backend did not build")
        pytest.skip("no C compiler")
    return request.param


@cache
def cached_case(name: str, n: int, seed: int):
    """Inputs and their 50-digit reference, shared by the NumPy and C runs."""
    arrays = inputs(AVAILABLE[name], n, seed)
    return arrays, ref_eval(name, arrays)


@pytest.mark.sample
@pytest.mark.parametrize("name", PUBLIC)
def test_kernel_matches_declaration_mpmath(name, backend):
    arrays, ref = cached_case(name, 1000, 0)
    got, singular = run(name, arrays, backend)
    assert not singular.any(), f"{name}: singular rows {np.flatnonzero(singular)}"
    err = rel_err(got, ref) / row_tol(name, ref, 2.0**-53, TOL) * TOL
    worst = int(np.argmax(err))
    assert err.max() <= TOL, f"{name} [{backend}]: max rel. error {err.max():.3g} at row " \
                             f"{worst} ({[a[worst].tolist() for a in arrays]})"


@pytest.mark.sample
@pytest.mark.parametrize("name", EULER)
def test_euler_kernels_match_declaration(name, backend):
    arrays, ref = cached_case(name, 40, 1)
    got, singular = run(name, arrays, backend)
    assert not singular.any()
    err = rel_err(got, ref)
    assert err.max() <= TOL, f"{name}: {err.max():.3g}"


@pytest.mark.parametrize("name", PUBLIC + EULER)
def test_c_and_numpy_agree(name):
    if K.use_backend("c") != "c":
        if shutil.which("gcc") or shutil.which("cc"):
            pytest.fail("a C compiler is present but the C backend did not build")
        pytest.skip("no C compiler")
    arrays = inputs(AVAILABLE[name], 500, seed=2)
    a, _ = run(name, arrays, "numpy")
    b, _ = run(name, arrays, "c")
    assert rel_err(a, b).max() <= 1e-14


@pytest.mark.parametrize("name", ["N_matrix", "screw_axis_point"])
def test_c_blocked_trig_loop_singular_rows(name):
    """The blocked sin/cos batch loop (blocks of 64): singular rows at block edges and in a
    partial last block are counted and written as NaN, the others equal NumPy's."""
    if K.use_backend("c") != "c":
        if shutil.which("gcc") or shutil.which("cc"):
            pytest.fail("a C compiler is present but the C backend did not build")
        pytest.skip("no C compiler")
    kernel = AVAILABLE[name]
    arrays = inputs(kernel, 131, seed=3)
    bad = [0, 63, 64, 130]
    phi = [a.name for a in kernel.args].index("phi")
    arrays[phi][bad] = 0.0
    a, sa = run(name, arrays, "numpy")
    b, sb = run(name, arrays, "c")
    assert np.flatnonzero(sb).tolist() == bad
    assert np.isnan(b[bad]).all()
    assert np.array_equal(sa, sb)
    good = ~sb
    assert rel_err(a[good], b[good]).max() <= 1e-14


@pytest.mark.parametrize("name", ["natural_invariants_from_rotation", "screw_axis_point",
                                  "newton_euler_wrench"])
def test_numpy_chunked_equals_whole(name, monkeypatch):
    """The generated NumPy kernels evaluate large batches in blocks of CHUNK samples (so
    temporaries stay in cache): a tiny CHUNK, with blocks that split the near-pi branch rows
    and singular rows, gives bit-identical outputs and the same singular mask as one block."""
    import sys

    kernel = AVAILABLE[name]
    _state.builtin().numpy_kernel(name)
    mod = sys.modules[f"rigidsym._generated_numpy.{name}"]
    arrays = inputs(kernel, 40, seed=5)
    names = [a.name for a in kernel.args]
    bad = []
    if "phi" in names:
        bad = [0, 6, 7, 30]
        arrays[names.index("phi")][bad] = 0.0
    f = K.batch_function(name, "numpy")

    def call():
        outs = [np.empty((arrays[0].shape[0],) + o.shape) for o in kernel.outputs]
        mask = f(*arrays, *outs)
        return np.concatenate([o.reshape(len(o), -1) for o in outs], axis=1), mask

    monkeypatch.setattr(mod, "CHUNK", 10**9)
    whole, mask_whole = call()
    monkeypatch.setattr(mod, "CHUNK", 7)
    chunked, mask_chunked = call()
    assert np.flatnonzero(mask_chunked).tolist() == bad
    assert np.array_equal(mask_whole, mask_chunked)
    assert np.array_equal(whole, chunked, equal_nan=True)
