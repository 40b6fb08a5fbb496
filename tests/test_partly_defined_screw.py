"""Partly defined outputs of ``screw_of_displacement``.

At Q = 1 the displacement is a pure translation by t = a' - a, or none. A pure translation
is a screw of infinite pitch (Angeles, Sec. 3.2; pytransform3d's screw parameters, Modern
Robotics' translation screw): e = t/||t||, phi = 0 exactly, p0 = 0 (the axis through the
origin: every line parallel to e is an axis), pitch = +inf, plucker = [0; e], on NumPy and
the C extension (the runtime answers the rows of the generated ``identity`` branch; the
PyTorch and JAX kernels alike: tests/test_singular_pose_inverse.py). No motion (a' = a) has
no screw: SingularConfigurationError naming a_prime, or NaN in every output but phi = 0
under on_singular="nan". The C target keeps the generated branch's finite placeholders,
e = [1, 0, 0], p0 = 0, pitch = 0, plucker = [e; p0 x e], and says so in its status
(RIGIDSYM_C_DEFAULT_OUTPUT, 16).

Rotations by angles whose ||vect(Q)||^2 underflows (phi below about 1e-154 in float64, 1e-19
in float32) are answered through the wide rescue: phi to a few u and the axis of the given Q.
"""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest

from rigidsym import kernels as K

#: the generated identity branch's placeholders (the C target)
DEFAULTS = ([1.0, 0.0, 0.0], 0.0, [0.0, 0.0, 0.0], 0.0, [1.0, 0, 0, 0, 0, 0])


def _batch(dtype):
    """Q = 1 twice (a pure translation, then no displacement) and three screw motions."""
    rng = np.random.default_rng(70)
    e = rng.standard_normal((3, 3))
    e /= np.linalg.norm(e, axis=1, keepdims=True)
    phi = np.array([0.3, 1.7, 3.0])
    Qs = K.rotation_from_natural_invariants(e, phi)
    Q = np.concatenate([np.eye(3)[None], np.eye(3)[None], Qs])
    a = rng.standard_normal((5, 3))
    # a screw motion: rotation about the axis through p0, then a slide d along it
    p0, d = rng.standard_normal((3, 3)), np.array([0.5, -1.0, 0.0])
    ap = np.empty((5, 3))
    ap[0] = a[0] + np.array([0.2, -0.4, 1.0])
    ap[1] = a[1]
    ap[2:] = p0 + np.einsum("nij,nj->ni", Qs, a[2:] - p0) + d[:, None] * e
    return Q.astype(dtype), a.astype(dtype), ap.astype(dtype)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("backend", ["numpy", "c"])
def test_identity_gives_the_screw_at_infinity(dtype, backend):
    """Row 0 (a pure translation): e = t/||t||, phi = 0, p0 = 0, pitch = +inf, plucker =
    [0; e]; row 1 (no motion): an error naming a_prime at batch index (1,), NaN but phi = 0
    under on_singular="nan"; the other rows reproduce their displacement (Chasles: a' = p0
    + Q (a - p0) + pitch phi e)."""
    Q, a, ap = _batch(dtype)
    before = K.backend()
    try:
        if K.use_backend(backend) != backend:
            pytest.skip("no C extension")
        with pytest.raises(K.SingularConfigurationError, match="'a_prime'") as info:
            K.screw_of_displacement(Q, a, ap)
        outs = K.screw_of_displacement(Q, a, ap, on_singular="nan")
    finally:
        K.use_backend(before)
    assert info.value.indices == [(1,)]
    e, phi, p0, pitch, kappa = (np.asarray(x, dtype=np.float64) for x in outs)
    t = np.array([0.2, -0.4, 1.0])
    assert phi[0] == 0 and pitch[0] == np.inf and np.array_equal(p0[0], [0, 0, 0])
    assert np.abs(e[0] - t / np.linalg.norm(t)).max() <= 4 * float(np.finfo(dtype).eps)
    assert np.array_equal(kappa[0], np.r_[0, 0, 0, e[0]])
    assert phi[1] == 0 and all(np.isnan(x[1]).all() for x in (e, p0, pitch, kappa))
    assert np.all(phi[2:] > 0)
    Q64, a64, ap64 = (x.astype(np.float64) for x in (Q, a, ap))
    back = p0[2:] + np.einsum("nij,nj->ni", Q64[2:], a64[2:] - p0[2:]) \
        + (pitch[2:] * phi[2:])[:, None] * e[2:]
    tol = 256 * float(np.finfo(dtype).eps) * (1 + np.abs(ap64[2:]).max())
    assert np.abs(back - ap64[2:]).max() <= tol


@pytest.mark.slow  # generation and a gcc build: 15 s on 2 shared cores
@pytest.mark.skipif(shutil.which("gcc") is None, reason="gcc is not installed")
def test_c_target_flags_the_defaults_at_the_identity(tmp_path):
    """The C target: status RIGIDSYM_C_DEFAULT_OUTPUT (16) alone at Q = 1 with the defaults,
    double and float; a screw motion gives status 0."""
    from rigidsym.codegen.backends.c.target import generate_c
    from rigidsym.codegen.generator import compile_many
    from rigidsym.codegen.usergen import select_kernels

    ks, origin = select_kernels(None, ["screw_of_displacement"])
    for path, text in generate_c(compile_many(ks, plan32=False), origin).items():
        (tmp_path / path).write_text(text)
    (tmp_path / "main.c").write_text(r"""#include <stdio.h>
#include "rigidsym_c.h"
#define SHOW(fmt, s) printf("%d", s); for (i = 0; i < 14; i++) printf(" " fmt, o[i]); \
    printf("\n")
int main(void)
{
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double R[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};   /* pi/2 about z */
    const double a[3] = {1, 2, 3}, ap[3] = {1.5, 2, 3.25};
    const float If[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const float af[3] = {1, 2, 3}, apf[3] = {1.5, 2, 3.25};
    double o[14];
    float f[14];
    int s, i;
    s = rigidsym_c_screw_of_displacement(I, a, ap, o, o + 3, o + 4, o + 7, o + 8);
    SHOW("%.17g", s);
    s = rigidsym_c_screw_of_displacement_f32(If, af, apf, f, f + 3, f + 4, f + 7, f + 8);
    for (i = 0; i < 14; i++) o[i] = f[i];
    SHOW("%.9g", s);
    s = rigidsym_c_screw_of_displacement(R, a, ap, o, o + 3, o + 4, o + 7, o + 8);
    SHOW("%.17g", s);
    return 0;
}
""")
    exe = tmp_path / "main"
    subprocess.run(["gcc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2",
                    "-I", str(tmp_path), str(tmp_path / "main.c"),
                    str(tmp_path / "rigidsym_c_screw_of_displacement.c"),
                    "-o", str(exe), "-lm"], check=True)
    lines = subprocess.run([str(exe)], check=True, capture_output=True,
                           text=True).stdout.splitlines()
    flat = [v for d in DEFAULTS for v in np.ravel(d)]           # e, phi, p0, pitch, plucker
    for line in lines[:2]:
        assert [float(x) for x in line.split()] == [16] + flat, line
    s, *rest = (float(x) for x in lines[2].split())
    want = K.screw_of_displacement(np.array(
        [[0, -1, 0], [1, 0, 0], [0, 0, 1.0]]), [1, 2, 3.0], [1.5, 2, 3.25])
    assert s == 0 and np.allclose(rest, np.concatenate([np.ravel(w) for w in want]),
                                  rtol=1e-15, atol=1e-15)


def _tiny(phi: float, dtype) -> np.ndarray:
    e = np.array([0.0, 0.6, 0.8])
    skew = np.array([[0, -e[2], e[1]], [e[2], 0, -e[0]], [-e[1], e[0], 0]])
    return (np.eye(3) + phi * skew).astype(dtype)


@pytest.mark.parametrize("dtype,phis", [
    (np.float64, [1e-100, 1e-160, 1e-250, 1e-300]),
    (np.float32, [1e-15, 1e-20, 1e-30, 1e-37])])
@pytest.mark.parametrize("backend", ["numpy", "c"])
def test_angles_below_the_types_range_are_answered(backend, dtype, phis):
    """phi whose ||vect(Q)||^2 underflows (below 1e-154 / 1e-19) or not: phi within 2 u and
    the axis [0, 0.6, 0.8] within 4 u (natural invariants and screw), never flagged: the
    axis is determined by the normal numbers vect(Q)."""
    u = float(np.finfo(dtype).eps) / 2
    before = K.backend()
    try:
        if K.use_backend(backend) != backend:
            pytest.skip("no C extension")
        for phi in phis:
            Q = _tiny(phi, dtype)
            e, got = K.natural_invariants_from_rotation(Q)
            se, sphi, *_ = K.screw_of_displacement(Q, np.ones(3, dtype), np.ones(3, dtype))
            for ee, pp in ((e, got), (se, sphi)):
                assert abs(float(pp) / phi - 1) <= 2 * u, (phi, pp)
                assert np.abs(ee.astype(np.float64) - [0, 0.6, 0.8]).max() <= 4 * u, phi
    finally:
        K.use_backend(before)
