"""Defined outputs at the home pose, and validation as peers do it.

- natural_invariants_from_rotation at Q = 1: phi = 0 exactly (it is known exactly there,
  as gtsam's Rot3::Logmap returns an exact zero) and the axis, undetermined, the documented
  default e = [1, 0, 0], on every back-end (one declaration: the kernel's branch
  ``identity``); the C target says so by RIGIDSYM_C_DEFAULT_OUTPUT (16) in the status.
- unit-vector arguments within the tolerance are normalised (pytransform3d, spatialmath):
  the round trip rotation_from_natural_invariants -> natural_invariants_from_rotation is
  accepted at ||e|| - 1 = 1e-8 (float64) and at the float32 tolerance, beyond it refused.
- inertia_at_point (and the dyad) check the body under check=True: m > 0, I_C symmetric,
  positive semi-definite, principal moments obeying the triangle inequality.
"""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidsym import kernels as K
from rigidsym.core import kinds


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("backend", ["numpy", "c"])
def test_identity_gives_phi_zero_and_the_default_axis(dtype, backend):
    """Q = 1 (alone and in a batch with ordinary rotations): no error, phi = 0 exactly,
    e = [1, 0, 0]; the other rows as before (Q(e, phi) gives back Q)."""
    rng = np.random.default_rng(3)
    e0 = rng.standard_normal((4, 3))
    e0 /= np.linalg.norm(e0, axis=1, keepdims=True)
    Qs = K.rotation_from_natural_invariants(e0, rng.uniform(0.1, 3.0, 4))
    Q = np.concatenate([np.eye(3)[None], Qs]).astype(dtype)
    before = K.backend()
    try:
        if K.use_backend(backend) != backend:
            pytest.skip("no C extension")
        e, phi = K.natural_invariants_from_rotation(Q)
    finally:
        K.use_backend(before)
    assert phi[0] == 0.0 and np.array_equal(e[0], [1.0, 0.0, 0.0])
    assert np.all(phi[1:] > 0)
    back = K.rotation_from_natural_invariants(e, phi)        # in the dtype
    tol = 64 * float(np.finfo(dtype).eps)
    assert np.abs(back.astype(np.float64) - Q.astype(np.float64)).max() <= tol


@pytest.mark.parametrize("lib", ["torch", "jax"])
def test_identity_on_the_array_backends(lib):
    """The same declaration on torch and JAX (skipped where the library is missing)."""
    pytest.importorskip(lib)
    import importlib

    # rigidsym.kernels.torch / .jax (rigidsym.kernels.arrays has no such attribute: this
    # line raised AttributeError wherever torch or JAX was installed)
    fn = importlib.import_module(f"rigidsym.kernels.{lib}").natural_invariants_from_rotation
    if lib == "torch":
        import torch
        e, phi = fn(torch.eye(3, dtype=torch.float64))
        e, phi = e.numpy(), phi.numpy()
    else:
        import jax.numpy as jnp
        e, phi = (np.asarray(x) for x in fn(jnp.eye(3)))
    assert phi == 0.0 and np.array_equal(e, [1.0, 0.0, 0.0])


@pytest.mark.skipif(shutil.which("gcc") is None, reason="gcc is not installed")
def test_c_target_flags_only_the_axis_at_the_identity(tmp_path):
    """The C target: status RIGIDSYM_C_DEFAULT_OUTPUT (16) alone, phi = 0, e = [1, 0, 0],
    double and float; an ordinary rotation gives status 0."""
    from rigidsym.codegen.backends.c.target import generate_c
    from rigidsym.codegen.generator import compile_many
    from rigidsym.codegen.usergen import select_kernels

    ks, origin = select_kernels(None, ["natural_invariants_from_rotation"])
    for path, text in generate_c(compile_many(ks, plan32=False), origin).items():
        (tmp_path / path).write_text(text)
    (tmp_path / "main.c").write_text(r"""#include <stdio.h>
#include "rigidsym_c.h"
int main(void)
{
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double R[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};   /* pi/2 about z */
    const float If[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double e[3], phi;
    float ef[3], phif;
    int s;
    s = rigidsym_c_natural_invariants_from_rotation(I, e, &phi);
    printf("%d %.17g %.17g %.17g %.17g\n", s, e[0], e[1], e[2], phi);
    s = rigidsym_c_natural_invariants_from_rotation_f32(If, ef, &phif);
    printf("%d %.9g %.9g %.9g %.9g\n", s, ef[0], ef[1], ef[2], phif);
    s = rigidsym_c_natural_invariants_from_rotation(R, e, &phi);
    printf("%d %.17g %.17g %.17g %.17g\n", s, e[0], e[1], e[2], phi);
    return 0;
}
""")
    exe = tmp_path / "main"
    subprocess.run(["gcc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2",
                    "-I", str(tmp_path), str(tmp_path / "main.c"),
                    str(tmp_path / "rigidsym_c_natural_invariants_from_rotation.c"),
                    "-o", str(exe), "-lm"], check=True)
    lines = subprocess.run([str(exe)], check=True, capture_output=True,
                           text=True).stdout.splitlines()
    for line in lines[:2]:
        assert [float(x) for x in line.split()] == [16, 1, 0, 0, 0], line
    s, *rest = (float(x) for x in lines[2].split())
    assert s == 0 and np.allclose(rest, [0, 0, 1, np.pi / 2], atol=1e-15)


# -- validation as peers do it --

def _tol(dtype) -> float:
    return kinds.get("unit").tolerance(dtype)


@settings(max_examples=examples(25), deadline=None)
@given(st.sampled_from([np.float64, np.float32]), st.floats(-0.95, 0.95),
       st.integers(0, 2**32 - 1))
def test_near_unit_axis_is_normalised_and_the_round_trip_accepted(dtype, frac, seed):
    """||e|| - 1 anywhere within the tolerance (1e-8 in float64, 100 eps in float32): Q is
    the rotation about e / ||e|| (orthogonal to a few u, e / ||e|| its fixed axis), and
    natural_invariants_from_rotation accepts it and gives back the axis and the angle."""
    rng = np.random.default_rng(seed)
    u = rng.standard_normal(3)
    u /= np.linalg.norm(u)
    e = (u * (1 + frac * _tol(dtype))).astype(dtype)
    phi = dtype(rng.uniform(0.2, 3.0))
    Q = K.rotation_from_natural_invariants(e, phi)
    eps = float(np.finfo(dtype).eps)
    Q64 = Q.astype(np.float64)
    assert np.abs(Q64.T @ Q64 - np.eye(3)).max() <= 32 * eps
    un = e.astype(np.float64) / np.linalg.norm(e.astype(np.float64))
    assert np.abs(Q64 @ un - un).max() <= 32 * eps
    e2, phi2 = K.natural_invariants_from_rotation(Q)          # accepted: no ValueError
    assert abs(float(phi2) - float(phi)) <= 64 * eps
    assert np.abs(e2.astype(np.float64) - un).max() <= 64 * eps / min(1.0, float(phi))


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_an_axis_beyond_the_tolerance_is_refused(dtype):
    e = np.array([0.0, 0.6, 0.8]) * (1 + 3 * _tol(dtype))
    with pytest.raises(ValueError, match="e: not a unit vector"):
        K.rotation_from_natural_invariants(e.astype(dtype), dtype(0.3))


def test_the_callers_axis_is_not_changed():
    e = np.array([0.0, 0.6, 0.8]) * (1 + 5e-9)
    before = e.copy()
    K.rotation_from_natural_invariants(e, 0.3)
    assert np.array_equal(e, before)


BODY = (np.diag([0.2, 0.3, 0.4]), 2.0, np.array([0.1, 0.0, 0.2]), np.array([0.0, 0.3, 0.1]))


@pytest.mark.parametrize("kernel", ["inertia_at_point", "inertia_dyad_at_point"])
@pytest.mark.parametrize("bad,match", [
    ({1: -2.0}, "m: expected a positive mass"),
    ({1: 0.0}, "m: expected a positive mass"),
    ({0: np.array([[0.2, 0.1, 0], [0, 0.3, 0], [0, 0, 0.4]])}, "I_C: not symmetric"),
    ({0: np.diag([0.2, -0.3, 0.4])}, "I_C: not positive semi-definite"),
    ({0: np.diag([0.1, 0.1, 0.4])}, "I_C: principal moments violate the triangle"),
])
def test_a_body_that_cannot_exist_is_refused(kernel, bad, match):
    args = [bad.get(i, a) for i, a in enumerate(BODY)]
    with pytest.raises(ValueError, match=match):
        getattr(K, kernel)(*args)
    getattr(K, kernel)(*args, check=False)        # check=False: the caller's promise


@settings(max_examples=examples(20), deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_every_rigid_body_is_accepted(seed):
    """A body of point masses (any layout, so moments that meet the triangle inequality
    with equality for a flat body) is always accepted."""
    rng = np.random.default_rng(seed)
    pts = rng.standard_normal((int(rng.integers(1, 6)), 3))
    if rng.random() < 0.3:
        pts[:, 2] = 0.0      # a flat body: I_zz = I_xx + I_yy
    ms = rng.uniform(0.1, 2.0, len(pts))
    c = (ms[:, None] * pts).sum(0) / ms.sum()
    r = pts - c
    I_C = sum(mi * (ri @ ri * np.eye(3) - np.outer(ri, ri)) for mi, ri in zip(ms, r,
                                                                                strict=True))
    K.inertia_at_point(I_C, ms.sum(), c, np.zeros(3))
