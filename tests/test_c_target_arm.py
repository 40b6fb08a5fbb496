"""The C target on Arm, run under emulation (qemu-user): the NEON range test and
the rescue where ``long double`` is ``double``, which the x86-64 tests only compile or
imitate (``-DRIGIDSYM_C_NO_SSE2``, ``-DRIGIDSYM_C_NO_WIDE``).

Two targets, each a Debian cross compiler with static linking and its qemu-user:
- armhf (ARMv7-A, NEON, hard float): ``long double`` is ``double`` there, so the double
  functions rescue extreme inputs by power-of-two rescaling, as on Cortex-M and Windows;
- aarch64: NEON in 64-bit lanes, ``long double`` is IEEE quad (the wide rescue).

On each: the example control loop matches the NumPy kernels to 1e-12; the vector range
test calls a component odd exactly when the definition does (2e6 bit patterns per type);
the scalar and batch functions of three kernels at inputs scaled to the ends of the range
meet check_rescued's bound against mpmath. All ``slow``; each skips with its reason where
the cross compiler or qemu is missing (``.ci/run`` installs them: Debian's qemu-user,
gcc-arm-linux-gnueabihf, gcc-aarch64-linux-gnu).
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from test_c_target import (
    _VECTOR_CHECK,
    DOUBLE_SCALES,
    EXAMPLE,
    FLAGGED,
    FLOAT_SCALES,
    KERNEL_OF,
    KERNELS_DIR,
    OUT_SIZE,
    RESCUED,
    STRICT,
    assert_matches,
    expected,
    flagged_inputs,
    judge_flagged,
    judge_rescued,
    rescued_inputs,
    run_example,
    sources,
)

from rigidsym.codegen.backends.c import M4F_SHIM

pytestmark = pytest.mark.slow

#: target: (compiler, its flags, qemu-user binary, long double is double there)
TARGETS = {
    "armhf": ("arm-linux-gnueabihf-gcc",
              ["-march=armv7-a", "-mfpu=neon", "-mfloat-abi=hard"], "qemu-arm", True),
    "aarch64": ("aarch64-linux-gnu-gcc", [], "qemu-aarch64", False),
}


@pytest.fixture(params=sorted(TARGETS))
def target(request):
    cc, flags, qemu, narrow = TARGETS[request.param]
    missing = [t for t in (cc, qemu) if shutil.which(t) is None]
    if missing:
        pytest.skip(f"{' and '.join(missing)} not installed (Debian: qemu-user, "
                    "gcc-arm-linux-gnueabihf, gcc-aarch64-linux-gnu)")
    return request.param, [cc, *STRICT, "-O2", "-static", *flags], qemu, narrow


def _build(cmd: list[str], srcs: list[Path], exe: Path) -> Path:
    subprocess.run([*cmd, "-I", str(KERNELS_DIR), *map(str, srcs), "-o", str(exe), "-lm"],
                   check=True, capture_output=True, text=True)
    return exe


def test_example_matches_numpy_on_arm(tmp_path, target):
    name, cmd, qemu, _ = target
    exe = _build(cmd, [EXAMPLE / "main.c", *sources()], tmp_path / f"loop_{name}")
    wrapper = tmp_path / "run.sh"      # run_example runs one path: qemu in front of it
    wrapper.write_text(f"#!/bin/sh\nexec {qemu} {exe}\n")
    wrapper.chmod(0o755)
    assert_matches(run_example(wrapper), expected())


def test_neon_range_test_is_the_definition(tmp_path, target):
    """On Arm the generic vector range test is the one the kernels take (no macro needed):
    it must be compiled in (not "skip") and agree with the definition everywhere."""
    name, cmd, qemu, _ = target
    src = tmp_path / "check.c"
    src.write_text(_VECTOR_CHECK)
    exe = _build(cmd, [src], tmp_path / f"check_{name}")
    out = subprocess.run([qemu, str(exe)], check=True, capture_output=True,
                         text=True).stdout.strip()
    assert out == "0", out


_DRIVER = r"""
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rigidsym_c.h"
/* stdin: lines "KERNEL TYPE MODE n x1 ... xn" (TYPE d or f, MODE s for the scalar
 * function or b for the batch one at count 1; x in decimal, 17 digits: strtod rounds it
 * back exactly); stdout: "status o1 ... om", each output's double bits in hex. The
 * arguments are the kernel's, flattened in order. */
#define CALLS(T, S) \
static int call_##T(const char *k, int batch, const T *x, T *o) { \
    int st = 0; \
    if (!strcmp(k, "twist_transfer")) \
        return batch ? rigidsym_c_twist_transfer##S##_batch(1, x, x + 6, x + 9, o, &st) \
                     : rigidsym_c_twist_transfer##S(x, x + 6, x + 9, o); \
    if (!strcmp(k, "body_energy")) \
        return batch ? rigidsym_c_body_energy##S##_batch(1, x, x + 1, x + 4, x + 13, o, &st) \
                     : rigidsym_c_body_energy##S(x[0], x + 1, x + 4, x + 13, o); \
    if (!strcmp(k, "planar_arm_tip")) \
        return batch ? rigidsym_c_planar_arm_tip##S##_batch(1, x, x + 1, x + 2, x + 3, o, &st) \
                     : rigidsym_c_planar_arm_tip##S(x[0], x[1], x[2], x[3], o); \
    if (!strcmp(k, "newton_euler_wrench")) \
        return batch ? rigidsym_c_newton_euler_wrench##S##_batch(1, x, x + 9, x + 10, x + 13, \
                                                                 x + 16, o, &st) \
                     : rigidsym_c_newton_euler_wrench##S(x, x[9], x + 10, x + 13, x + 16, o); \
    return -1; \
}
CALLS(double, )
CALLS(float, _f32)
int main(void)
{
    char k[64], t[4], m[4];
    int n, i;
    while (scanf("%63s %3s %3s %d", k, t, m, &n) == 4) {
        double xd[32], od[8];
        float xf[32], of[8];
        char buf[64];
        int st;
        for (i = 0; i < n; ++i) {
            if (scanf("%63s", buf) != 1)
                return 2;
            xd[i] = strtod(buf, NULL);
            xf[i] = (float)xd[i];
        }
        st = t[0] == 'd' ? call_double(k, m[0] == 'b', xd, od)
                         : call_float(k, m[0] == 'b', xf, of);
        printf("%d", st);
        for (i = 0; i < 8; ++i) {   /* the bits, as two 32-bit halves: newlib has no %a */
            const double v = t[0] == 'd' ? od[i] : (double)of[i];
            uint64_t b;
            memcpy(&b, &v, 8);
            printf(" %08lx%08lx", (unsigned long)(b >> 32), (unsigned long)(b & 0xffffffffU));
        }
        printf("\n");
    }
    return 0;
}
"""


def test_extreme_inputs_are_right_on_arm(tmp_path, target):
    """check_rescued (test_c_target.py) on the target, for the scalar and the batch
    function: where long double is double (armhf) the double functions rescale, as the
    x86-64 build imitates with -DRIGIDSYM_C_NO_WIDE; on aarch64 they re-run in quad."""
    name, cmd, qemu, narrow = target
    src = tmp_path / "driver.c"
    src.write_text(_DRIVER)
    exe = _build(cmd, [src, *sources()], tmp_path / f"driver_{name}")
    if narrow:       # the premise of this target: no wider type than double
        probe = tmp_path / "ld.c"
        probe.write_text('#include <float.h>\n#include <stdio.h>\n'
                         'int main(void) { printf("%d\\n", LDBL_MANT_DIG); return 0; }\n')
        ld = _build(cmd, [probe], tmp_path / "ld")
        assert subprocess.run([qemu, str(ld)], check=True, capture_output=True,
                              text=True).stdout.strip() == "53"
    cases, lines = [], []
    for dtype, scales in ((np.float64, DOUBLE_SCALES), (np.float32, FLOAT_SCALES)):
        for kernel in sorted(RESCUED):
            for scale in scales:
                for seed in range(6):
                    xs = rescued_inputs(kernel, dtype, scale, seed)
                    flat = np.concatenate([np.ravel(x) for x in xs]).astype(np.float64)
                    for mode in "sb":
                        cases.append((kernel, dtype, xs))
                        lines.append(f"{kernel} {'d' if dtype == np.float64 else 'f'} {mode} "
                                     f"{flat.size} " + " ".join(repr(float(v)) for v in flat))
    out = subprocess.run([qemu, str(exe)], input="\n".join(lines) + "\n", check=True,
                         capture_output=True, text=True).stdout.splitlines()
    assert len(out) == len(cases)
    for (kernel, dtype, xs), line in zip(cases, out, strict=True):
        status, *vals = line.split()
        got = _from_bits(vals[:OUT_SIZE[kernel]], dtype)
        judge_rescued(kernel, dtype, xs, int(status), got)


def _from_bits(words: list[str], dtype) -> np.ndarray:
    """_DRIVER's outputs (each a double's bits in hex) as an array of the type."""
    return np.array([int(w, 16) for w in words], dtype=np.uint64).view(np.float64).astype(dtype)


def _run_driver(qemu: str, exe: Path, cases: list) -> list[tuple[int, np.ndarray]]:
    """(status, outputs) of _DRIVER's calls, one per (kernel, dtype, xs, mode) case."""
    lines = []
    for kernel, dtype, xs, mode in cases:
        flat = np.concatenate([np.ravel(x) for x in xs]).astype(np.float64)
        lines.append(f"{kernel} {'d' if dtype == np.float64 else 'f'} {mode} {flat.size} "
                     + " ".join(repr(float(v)) for v in flat))
    out = subprocess.run([qemu, str(exe)], input="\n".join(lines) + "\n", check=True,
                         capture_output=True, text=True).stdout.splitlines()
    assert len(out) == len(cases)
    got = []
    for (kernel, dtype, _, _), line in zip(cases, out, strict=True):
        status, *vals = line.split()
        got.append((int(status), _from_bits(vals[:OUT_SIZE[kernel]], dtype)))
    return got


def _flagged_cases(dtypes) -> list:
    """(kernel, dtype, xs, mode, must_pass) over FLAGGED at the scales of the x86-64 tests."""
    scales = {np.float32: [1e-12, 1e-20, 1e-30, 1e-41], np.float64: [1e-120, 1e-160, 1e-310]}
    return [(KERNEL_OF.get(name, name), dtype, flagged_inputs(name, dtype, scale, seed), mode,
             scale in (1e-12, 1e-120))
            for dtype in dtypes for name in sorted(FLAGGED) for scale in scales[dtype]
            for seed in range(4) for mode in "sb"]


def test_extreme_inputs_no_rescue_takes_on_arm(tmp_path, target):
    """judge_flagged (test_c_target.py) on the target, scalar and batch: the exception
    flags step reads the FPSCR (armhf) or FPSR (aarch64), so an angular rate of 1e-12 rad/s
    in float passes with status 0 there too, and an underflow keeps EXTREME_INPUT. On
    aarch64 the double functions re-run in quad first; on armhf they reach the flags."""
    name, cmd, qemu, _ = target
    src = tmp_path / "driver.c"
    src.write_text(_DRIVER)
    exe = _build(cmd, [src, *sources()], tmp_path / f"driver_{name}")
    cases = _flagged_cases((np.float32, np.float64))
    for (kernel, dtype, xs, _, must), (status, got) in zip(
            cases, _run_driver(qemu, exe, [c[:4] for c in cases]), strict=True):
        judge_flagged(kernel, dtype, xs, status, got, must_pass=must)


def test_extreme_float_inputs_no_rescue_takes_on_cortex_m4f(tmp_path):
    """The same on the Cortex-M4F build (its float functions read the FPSCR around the
    evaluation; its double functions are soft-float, whose helpers raise no flag, so they
    keep EXTREME_INPUT: only the soundness half of judge_flagged is asked of them)."""
    cc, qemu = "arm-none-eabi-gcc", "qemu-arm"
    missing = [t for t in (cc, qemu) if shutil.which(t) is None]
    if missing:
        pytest.skip(f"{' and '.join(missing)} not installed (Debian: gcc-arm-none-eabi, "
                    "qemu-user)")
    src = tmp_path / "driver.c"
    src.write_text(_DRIVER)
    shim = M4F_SHIM
    exe = _build([cc, *STRICT, "-O2", *M4F_FLAGS, "-nostartfiles", "--specs=nosys.specs"],
                 [src, *sources(), shim], tmp_path / "driver_m4f")
    cases = _flagged_cases((np.float32, np.float64))
    for (kernel, dtype, xs, _, must), (status, got) in zip(
            cases, _run_driver(qemu, exe, [c[:4] for c in cases]), strict=True):
        judge_flagged(kernel, dtype, xs, status, got, must_pass=must and dtype == np.float32)
        # soft double reads no flag, but the per-argument rescue scales a tiny argument by
        # its own exponent: a status 0 there is judged right by judge_flagged above


M4F_FLAGS = ["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard", "-mfpu=fpv4-sp-d16"]


def test_float_example_matches_numpy_on_cortex_m4f(tmp_path):
    """The float-only control loop built for a Cortex-M4F (Thumb-2, single-precision FPU,
    newlib: the objects the firmware links) and run under qemu-arm's user mode, whose
    Cortex-A core executes the same Thumb-2 and VFP instructions: every output within 8 u
    (float32) of the NumPy kernels' float64 value, as on the host. The x86-64 tests only
    check that these objects reference no double helper; this runs them."""
    cc, qemu = "arm-none-eabi-gcc", "qemu-arm"
    missing = [t for t in (cc, qemu) if shutil.which(t) is None]
    if missing:
        pytest.skip(f"{' and '.join(missing)} not installed (Debian: gcc-arm-none-eabi, "
                    "qemu-user)")
    shim = M4F_SHIM
    exe = _build([cc, *STRICT, "-O2", *M4F_FLAGS, "-nostartfiles", "--specs=nosys.specs",
                  "-DRIGIDSYM_EXAMPLE_PRINT"],
                 [EXAMPLE / "main_f32.c", *sources(), shim], tmp_path / "loop_m4f")
    wrapper = tmp_path / "run.sh"
    wrapper.write_text(f"#!/bin/sh\nexec {qemu} {exe}\n")
    wrapper.chmod(0o755)
    assert_matches(run_example(wrapper), expected(), tol=8 * 2.0**-24)


_FLUSH_ARM = r"""#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "rigidsym_c.h"
/* subnormal float twists, with Arm's flush-to-zero mode (FZ) off and on: the cold path
 * turns it off for its own run, so the rescue is exact (status 0) in both, and the mode is
 * the caller's again after the call */
static unsigned fz(int set)
{
#if defined(__aarch64__)
    uint64_t r;
    __asm__ volatile("mrs %0, fpcr" : "=r"(r));
    if (set) {
        r |= 1U << 24;
        __asm__ volatile("msr fpcr, %0" : : "r"(r));
    }
#else
    unsigned r;
    __asm__ volatile("vmrs %0, fpscr" : "=r"(r));
    if (set) {
        r |= 1U << 24;
        __asm__ volatile("vmsr fpscr, %0" : : "r"(r));
    }
#endif
    return (unsigned)(r >> 24) & 1U;
}
int main(void)
{
    const float t[6] = {1e-40f, 2e-40f, -3e-40f, 4e-40f, 5e-40f, -6e-40f}, z[3] = {0, 0, 0};
    float o[6];
    int s, k;
    for (k = 0; k < 2; ++k) {
        (void)fz(k);
        s = rigidsym_c_twist_transfer_f32(t, z, z, o);
        printf("%d %d %u\n", s, memcmp(o, t, sizeof o) == 0, fz(0));
    }
    return 0;
}
"""


def test_a_flush_to_zero_caller_on_arm_gets_the_values_of_an_ieee_caller(tmp_path, target):
    """Arm's FZ (aarch64's FPCR, 32-bit Arm's FPSCR) set by the caller: the cold path turns
    it off for its own run, so the subnormal twist is rescued exactly, status 0, as without
    it, and the caller's FZ is set again after the call."""
    name, cmd, qemu, _ = target
    src = tmp_path / "flush.c"
    src.write_text(_FLUSH_ARM)
    exe = _build(cmd, [src, *sources()], tmp_path / f"flush_{name}")
    out = subprocess.run([qemu, str(exe)], check=True, capture_output=True, text=True).stdout
    assert out.split("\n")[:2] == ["0 1 0", "0 1 1"], out
