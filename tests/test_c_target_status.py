"""The C target's status is what the evaluation did: the same bits from gcc and clang at
-O2, -O3 and -Ofast, and 0 on ordinary small inputs.

A program built with -Ofast runs with x86-64's FTZ and DAZ set (gcc and clang link
crtfastmath.o into it); the kernels' own sources are built as the CMake target builds them
under such a program, ``-Ofast -fno-fast-math -fno-finite-math-only -fno-associative-math
-ffp-contract=off``. Each build runs one driver over the same inputs, drawn with an
independent exponent per component: rotations by 1e-6 rad and more about axes with
components down to 1e-6, angular rates down to 1e-12 rad/s, a point 1 nm from the origin
(the screw, ``slow``). Asserted: status and outputs the same bits in every build; status 0
on every such input, its outputs within float rounding of an independent reference (the
rotation the input was made from, the wrench's formula in float64); a NaN or infinite input
flagged ``NONFINITE_INPUT``; a wrench whose every product underflows (a torque-free body at
1e-30 rad/s) or overflows flagged, never status 0. Default run: the rotation's log and the
wrench in float, gcc and clang at -O2 and -Ofast, 2,000 inputs each; ``slow``: those and the
screw of a displacement, in float and double, at -O2, -O3 and -Ofast, 20,000 inputs each.
"""

from __future__ import annotations

import platform
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[1]
KERNELS_DIR = REPO / "examples" / "c" / "rigidsym_c"
COMPILERS = [c for c in ("gcc", "clang") if shutil.which(c)]
#: the kernels' flags under an application's optimisation flag (the CMake target's)
KERNEL_FLAGS = {"-O2": ["-O2"], "-O3": ["-O3"],
                "-Ofast": ["-Ofast", "-fno-fast-math", "-fno-finite-math-only",
                           "-fno-associative-math", "-ffp-contract=off"]}
OK, NONFINITE_INPUT, NONFINITE_RESULT, EXTREME_INPUT = 0, 2, 4, 8

#: per kernel: its arguments' sizes (None: a scalar by value) and its outputs' sizes
SIGNATURES = {
    "natural_invariants_from_rotation": ([9], [3, None]),
    "newton_euler_wrench": ([9, None, 3, 3, 3], [6]),
    "screw_of_displacement": ([9, 3, 3], [3, None, 3, None, 6]),
    "rotation_from_natural_invariants": ([3, None], [9]),
    "twist_transfer": ([6, 3, 3], [6]),
}

_DRIVER = r"""#include <stdio.h>
#include <stdlib.h>
#if defined(__x86_64__)
#include <xmmintrin.h>
#endif
#include "rigidsym_c.h"
/* argv[1]: count rows of DRV_NIN values of type DRV_T; writes to argv[2] each row's status (int)
 * and DRV_NOUT outputs; prints 1 when the program runs with FTZ or DAZ set (x86-64) */
int main(int argc, char **argv)
{
    FILE *f = fopen(argv[1], "rb");
    long n, i;
    DRV_T *in, *out;
    int *st;
    if (argc != 3 || !f)
        return 2;
    fseek(f, 0, SEEK_END);
    n = ftell(f) / (long)(sizeof(DRV_T) * DRV_NIN);
    fseek(f, 0, SEEK_SET);
    in = malloc(sizeof(DRV_T) * DRV_NIN * (size_t)n);
    out = malloc(sizeof(DRV_T) * DRV_NOUT * (size_t)n);
    st = malloc(sizeof(int) * (size_t)n);
    if (fread(in, sizeof(DRV_T) * DRV_NIN, (size_t)n, f) != (size_t)n)
        return 2;
    fclose(f);
    for (i = 0; i < n; ++i) {
        const DRV_T *x = in + DRV_NIN * i;
        DRV_T *y = out + DRV_NOUT * i;
        st[i] = DRV_CALL;
    }
    f = fopen(argv[2], "wb");
    fwrite(st, sizeof(int), (size_t)n, f);
    fwrite(out, sizeof(DRV_T) * DRV_NOUT, (size_t)n, f);
    fclose(f);
#if defined(__x86_64__)
    printf("%d\n", (_mm_getcsr() & 0x8040) != 0);
#else
    printf("0\n");
#endif
    return 0;
}
"""


def _call(kernel: str, dtype) -> tuple[str, int, int]:
    """The driver's call expression, and the row sizes of its inputs and outputs."""
    args, outs = SIGNATURES[kernel]
    parts, k = [], 0
    for size in args:
        parts.append(f"x[{k}]" if size is None else f"x + {k}")
        k += size or 1
    j = 0
    for size in outs:
        parts.append(f"y + {j}")
        j += size or 1
    fn = f"rigidsym_c_{kernel}" + ("_f32" if dtype == np.float32 else "")
    return f"{fn}({', '.join(parts)})", k, j


def run_builds(tmp: Path, kdir: Path, kernel: str, dtype, rows: np.ndarray, builds,
               defines: tuple[str, ...] = ()) -> dict:
    """{(cc, flag): (status, outputs, flushing)} of ``kernel`` (its source in ``kdir``,
    compiled with ``defines`` as well) over ``rows`` in each build."""
    src = kdir / f"rigidsym_c_{kernel}.c"
    (tmp / "driver.c").write_text(_DRIVER)
    T = "float" if dtype == np.float32 else "double"
    call, nin, nout = _call(kernel, dtype)
    data = tmp / f"in_{kernel}_{T}.bin"
    np.ascontiguousarray(rows, dtype).tofile(data)
    got = {}
    for cc, flag in builds:
        tag = f"{kernel}_{T}_{cc}{flag}" + "".join(defines)
        obj = tmp / f"{cc}{flag}{''.join(defines)}_{kernel}.o"
        if not obj.exists():
            subprocess.run([cc, "-std=c99", *KERNEL_FLAGS[flag], *defines, "-c", str(src),
                            "-o", str(obj)],
                           check=True, capture_output=True)   # clang: -ffp-contract's warning
        exe = tmp / f"d_{tag}"
        subprocess.run([cc, "-std=c99", flag, f"-DDRV_T={T}", f"-DDRV_NIN={nin}",
                        f"-DDRV_NOUT={nout}", f"-DDRV_CALL={call}", "-I", str(kdir),
                        str(tmp / "driver.c"), str(obj), "-o", str(exe), "-lm"], check=True)
        res = tmp / f"out_{tag}.bin"
        flushing = subprocess.run([str(exe), str(data), str(res)], check=True,
                                  capture_output=True, text=True).stdout.strip() == "1"
        raw = res.read_bytes()
        n = len(rows)
        status = np.frombuffer(raw[:4 * n], np.int32)
        outs = np.frombuffer(raw[4 * n:], dtype).reshape(n, nout)
        got[cc, flag] = (status, outs, flushing)
    return got


def _rot(e: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """Rotation matrices (n, 3, 3) of unit axes e (n, 3) by angles phi (n,) (Rodrigues)."""
    K = np.zeros((len(e), 3, 3))
    K[:, 0, 1], K[:, 0, 2], K[:, 1, 2] = -e[:, 2], e[:, 1], -e[:, 0]
    K = K - K.transpose(0, 2, 1)
    s, c = np.sin(phi)[:, None, None], np.cos(phi)[:, None, None]
    return np.eye(3) + s * K + (1 - c) * K @ K


def _axes(rng, n: int) -> np.ndarray:
    """Unit axes whose components have independent exponents (down to 1e-6)."""
    e = rng.normal(size=(n, 3)) * 10.0 ** rng.uniform(-6, 0, (n, 3))
    return e / np.linalg.norm(e, axis=1, keepdims=True)


def ordinary(kernel: str, n: int, seed: int, lo: float = -6) -> tuple[np.ndarray, dict]:
    """n ordinary small inputs of ``kernel`` (float64 rows) and what they were made from;
    the log's angles log-uniform from 10^lo rad to 3 rad."""
    rng = np.random.default_rng(seed)
    if kernel == "natural_invariants_from_rotation":
        e, phi = _axes(rng, n), 10.0 ** rng.uniform(lo, np.log10(3.0), n)
        return _rot(e, phi).reshape(n, 9), {"e": e, "phi": phi}
    if kernel == "rotation_from_natural_invariants":
        e, phi = _axes(rng, n), 10.0 ** rng.uniform(-12, np.log10(3.0), n)
        return np.hstack([e, phi[:, None]]), {}
    if kernel == "twist_transfer":
        comps = lambda lo, hi: rng.normal(size=(n, 3)) * 10.0 ** rng.uniform(lo, hi, (n, 3))  # noqa: E731
        return np.hstack([comps(-12, 1), comps(-9, 1), comps(-9, 1), comps(-9, 1)]), {}
    if kernel == "newton_euler_wrench":
        inertia = np.einsum("i,jk->ijk", np.ones(n), np.diag([0.02, 0.03, 0.025])) + \
            0.002 * rng.normal(size=(n, 3, 3))
        m = rng.uniform(0.5, 2.0, (n, 1))
        exps = lambda lo, hi: rng.normal(size=(n, 3)) * 10.0 ** rng.uniform(lo, hi, (n, 3))  # noqa: E731
        return np.hstack([inertia.reshape(n, 9), m, exps(-12, 1), exps(-6, 1),
                          exps(-6, 1)]), {}
    e, phi = _axes(rng, n), 10.0 ** rng.uniform(-6, np.log10(3.0), n)
    Q = _rot(e, phi)
    a = rng.normal(size=(n, 3))
    a *= 1e-9 / np.linalg.norm(a, axis=1, keepdims=True)       # 1 nm from the origin
    d = rng.normal(size=(n, 3)) * 10.0 ** rng.uniform(-9, 0, (n, 3))
    return np.hstack([Q.reshape(n, 9), a, np.einsum("nij,nj->ni", Q, a) + d]), {}


def check_against_reference(kernel: str, rows: np.ndarray, made: dict, outs: np.ndarray,
                            dtype) -> None:
    """Status-0 outputs within float rounding of an independent reference: the rotation's
    own axis and angle, the wrench's formula in float64 on the same (rounded) inputs."""
    eps = float(np.finfo(dtype).eps)
    x = rows.astype(dtype).astype(np.float64)
    if kernel == "natural_invariants_from_rotation":
        e, phi = outs[:, :3].astype(np.float64), outs[:, 3].astype(np.float64)
        assert np.all(np.abs(phi - made["phi"]) <= 64 * eps * made["phi"] + 4 * eps)
        assert np.all(np.linalg.norm(e - made["e"], axis=1) <= 64 * eps + 4 * eps / made["phi"])
    elif kernel == "newton_euler_wrench":
        inertia, m = x[:, :9].reshape(-1, 3, 3), x[:, 9]
        w, wd, cdd = x[:, 10:13], x[:, 13:16], x[:, 16:19]
        Iw = np.einsum("nij,nj->ni", inertia, w)
        n_ = np.einsum("nij,nj->ni", inertia, wd) + np.cross(w, Iw)
        mag = np.einsum("nij,nj->ni", np.abs(inertia), np.abs(wd)) + \
            np.abs(w)[:, [1, 2, 0]] * np.abs(Iw)[:, [2, 0, 1]] + \
            np.abs(w)[:, [2, 0, 1]] * np.abs(Iw)[:, [1, 2, 0]] + \
            np.einsum("nij,nj->ni", np.abs(inertia), np.abs(w)) * np.abs(w).max(1)[:, None]
        ref = np.hstack([n_, m[:, None] * cdd])
        mag = np.hstack([mag, np.abs(ref[:, 3:])])
        assert np.all(np.abs(outs - ref) <= 16 * eps * mag), \
            np.max(np.abs(outs - ref) / np.maximum(mag, 1e-300))
    elif kernel == "rotation_from_natural_invariants":
        # (2.49) on the rounded axis and angle: entries of magnitude at most |e|^2 + 1
        ref = _rot(x[:, :3], x[:, 3]).reshape(-1, 9)
        assert np.all(np.abs(outs - ref) <= 16 * eps), np.max(np.abs(outs - ref))
    elif kernel == "twist_transfer":
        # t_P = [omega; v_A + omega x (p - a)], the rounded inputs, the terms' magnitudes
        w, v, a, p = x[:, :3], x[:, 3:6], x[:, 6:9], x[:, 9:12]
        ref = np.hstack([w, v + np.cross(w, p - a)])
        r = np.abs(p) + np.abs(a)
        mag = np.hstack([np.abs(w), np.abs(v) + np.abs(w)[:, [1, 2, 0]] * r[:, [2, 0, 1]]
                         + np.abs(w)[:, [2, 0, 1]] * r[:, [1, 2, 0]]])
        assert np.all(np.abs(outs - ref) <= 16 * eps * mag), \
            np.max(np.abs(outs - ref) / np.maximum(mag, 1e-300))


def assert_same_everywhere(got: dict) -> None:
    """Every build's status and outputs the same bits as the first's (a NaN's sign and
    payload aside: IEEE 754 gives them no meaning, and gcc and clang differ there)."""
    (k0, (s0, o0, _)), *rest = got.items()
    nan0 = np.isnan(o0)
    for k, (s, o, _) in rest:
        assert np.array_equal(s, s0), (k, k0, np.flatnonzero(s != s0)[:5])
        assert np.array_equal(np.isnan(o), nan0), (k, k0)
        assert o[~nan0].tobytes() == o0[~nan0].tobytes(), (k, k0)


def check_kernel(tmp: Path, kdir: Path, kernel: str, dtype, n: int, flags,
                 seed: int = 1, lo: float = -6) -> None:
    builds = [(cc, f) for cc in COMPILERS for f in flags]
    rows, made = ordinary(kernel, n, seed, lo)
    special = []
    if kernel == "newton_euler_wrench":
        huge = rows[:3].copy()
        huge[:, 10:13] = 1e25 if dtype == np.float32 else 1e200
        special = [("overflow", huge)]
        if dtype == np.float32:     # (double: x86-64's long double rescue takes it, status 0)
            tiny = rows[:3].copy()
            tiny[:, 10:13] = np.array([1e-30, -2e-30, 3e-30])
            tiny[:, 13:] = 0.0      # torque-free: the underflowed n = omega x I omega is all
            special.append(("underflow", tiny))
    bad = rows[:4].copy()
    bad[0, 0], bad[1, 1], bad[2, -1], bad[3, 2] = np.nan, np.inf, -np.inf, np.nan
    special.append(("nonfinite", bad))
    allrows = np.vstack([rows] + [r for _, r in special])
    got = run_builds(tmp, kdir, kernel, dtype, allrows, builds)
    if platform.machine() in ("x86_64", "AMD64"):
        for (cc, flag), (_, _, flushing) in got.items():
            assert flushing == (flag == "-Ofast"), (cc, flag)   # the mode is the one named
    assert_same_everywhere(got)
    status, outs, _ = next(iter(got.values()))
    assert np.all(status[:n] == OK), (np.unique(status[:n], return_counts=True),
                                      rows[status[:n] != OK][:3])
    check_against_reference(kernel, rows, made, outs[:n], dtype)
    at = n
    for what, r in special:
        s = status[at:at + len(r)]
        at += len(r)
        if what == "nonfinite":
            assert np.all(s & NONFINITE_INPUT), s
        else:                       # never status 0: the answer is not to the bound
            assert np.all(s & (EXTREME_INPUT | NONFINITE_RESULT)), (what, s)


needs_two = pytest.mark.skipif(len(COMPILERS) < 2, reason="gcc and clang are both needed "
                               "(clang: apt-get install clang)")


@needs_two
@pytest.mark.sample(fraction=0.5)   # one kernel in the quick run, the other thorough
@pytest.mark.parametrize("kernel", ["natural_invariants_from_rotation", "newton_euler_wrench"])
def test_status_is_the_same_under_every_compiler_and_flag(tmp_path, kernel):
    """Float, gcc and clang at -O2 and -Ofast: 2,000 ordinary small inputs of status 0 with
    the same bits everywhere, and the non-finite, underflowing and overflowing ones
    flagged."""
    check_kernel(tmp_path, KERNELS_DIR, kernel, np.float32, 2000, ["-O2", "-Ofast"])


@pytest.mark.slow   # 5 kernels x 2 types x 2 compilers x 3 flags, 20,000 inputs each
@pytest.mark.thorough(0.5)  # a seeded half of the (kernel, type) pairs each commit
@needs_two
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("kernel", sorted(SIGNATURES))
def test_status_is_the_same_under_every_compiler_and_flag_full(tmp_path, kernel, dtype):
    """The full matrix: the log, the wrench, the rotation from an axis and angle (angles
    down to 1e-12 rad), the twist transfer (angular velocities down to 1e-12 rad/s, points
    1 nm from the origin) and the screw of a displacement (generated here), float and
    double, gcc and clang at -O2, -O3 and -Ofast."""
    kdir = KERNELS_DIR
    if not (kdir / f"rigidsym_c_{kernel}.c").exists():
        from rigidsym.cli import main

        kdir = tmp_path / "gen"
        assert main(["generate", "--target", "c", "--kernel", kernel, "--out", str(kdir),
                     "--no-measure"]) == 0
    check_kernel(tmp_path, kdir, kernel, dtype, 20000, ["-O2", "-O3", "-Ofast"], seed=7)


@pytest.mark.slow   # 2 types x 2 compilers x 3 flags, 20,000 inputs each
@needs_two
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_the_log_of_tiny_rotations_is_status_0_everywhere(tmp_path, dtype):
    """The log (natural invariants) of rotations by angles log-uniform from 1e-30 rad to
    3 rad: below about 1e-15 rad the float evaluation's series raises a harmless underflow;
    what decides the status is the double evaluation rounded once, which raises none. So
    status 0 on every one, the same bits from gcc and clang at -O2, -O3 and -Ofast, within
    float rounding of the rotation's own angle and axis."""
    check_kernel(tmp_path, KERNELS_DIR, "natural_invariants_from_rotation", dtype, 20000,
                 ["-O2", "-O3", "-Ofast"], seed=83, lo=-30)


def check_detect(tmp: Path, kernel: str, dtype, n: int, builds) -> None:
    """The default build on x86-64 (the evaluation first, its flags read after it): the
    status of every row the same as the predicting build's (-DRIGIDSYM_C_PREDICT, the range
    test first; gcc -O2), the outputs the same bits in every detecting build (with and
    without a flush mode), status-0 rows within the reference's bound; rows: ordinary small
    inputs, the same scaled by 2^-600 (double) or 2^-40 (float) where nothing underflows,
    overflowing, underflowing and non-finite ones."""
    rows, made = ordinary(kernel, n, 3)
    scaled = rows[:64] * (2.0 ** (-600 if dtype == np.float64 else -40))
    huge = rows[:3].copy()
    bad = rows[:4].copy()
    bad[0, 0], bad[1, 1], bad[2, -1], bad[3, 2] = np.nan, np.inf, -np.inf, np.nan
    if kernel == "newton_euler_wrench":
        huge[:, 10:13] = 1e25 if dtype == np.float32 else 1e200
    else:
        huge[:, :3] = 1e25 if dtype == np.float32 else 1e200
        huge[:, 6:9] = 1e25 if dtype == np.float32 else 1e200
    allrows = np.vstack([rows, scaled, huge, bad])
    ref = run_builds(tmp, KERNELS_DIR, kernel, dtype, allrows, [("gcc", "-O2")],
                     ("-DRIGIDSYM_C_PREDICT",))
    got = run_builds(tmp, KERNELS_DIR, kernel, dtype, allrows, builds)
    status0 = ref["gcc", "-O2"][0]
    for key, (status, _, _) in got.items():
        assert np.array_equal(status, status0), (key, np.flatnonzero(status != status0)[:5])
    assert_same_everywhere(got)
    status, outs, _ = next(iter(got.values()))
    assert np.all(status[:n] == OK)
    check_against_reference(kernel, rows, made, outs[:n], dtype)
    assert np.all(status[-4:] & NONFINITE_INPUT)


@pytest.mark.skipif(platform.machine() not in ("x86_64", "AMD64"), reason="x86-64's MXCSR")
def test_detect_gives_the_default_status(tmp_path):
    """The wrench in float, gcc at -O2 and -Ofast (FTZ and DAZ: the range test's path)."""
    check_detect(tmp_path, "newton_euler_wrench", np.float32, 500,
                 [("gcc", "-O2"), ("gcc", "-Ofast")])


@pytest.mark.slow   # 2 kernels x 2 types x 2 compilers x 3 flags, 20,000 inputs each
@needs_two
@pytest.mark.skipif(platform.machine() not in ("x86_64", "AMD64"), reason="x86-64's MXCSR")
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("kernel", ["newton_euler_wrench", "twist_transfer"])
def test_detect_gives_the_default_status_full(tmp_path, kernel, dtype):
    """The same for both detecting kernels of the example, float and double, gcc and clang
    at -O2, -O3 and -Ofast."""
    check_detect(tmp_path, kernel, dtype, 20000,
                 [(cc, f) for cc in COMPILERS for f in ("-O2", "-O3", "-Ofast")])
