"""The C-only target: ``rigidsym generate --target c`` writes C99 that a C or
C++ project builds without Python, with a documented scalar API and status codes, guarded
against the compiler flags that would make it silently wrong.

Default run: the example control loop builds (gcc, -std=c99 -Wall -Wextra -Werror
-pedantic) and matches the NumPy kernels to 1e-12; the status codes, by property; the
fast-math guard; the generator's one-line errors. ``slow``: the committed example folder is
what the generator writes; the flag matrix with gcc and clang (plain and CMake builds), C++,
the installed library (find_package, pkg-config), the Cortex-M4F float-only check.
"""

from __future__ import annotations

import ctypes
import platform
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st

REPO = Path(__file__).resolve().parents[1]
EXAMPLE = REPO / "examples" / "c"
KERNELS_DIR = EXAMPLE / "rigidsym_c"
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]
GCC = shutil.which("gcc")
needs_gcc = pytest.mark.skipif(GCC is None, reason="gcc is not installed")
# one worker compiles the example libraries (module fixtures) for every test of this module
# (each worker that ran one of them compiled them again)
pytestmark = pytest.mark.xdist_group("c_target")

#: the status bits (rigidsym_c_common.h)
OK, SINGULAR, NONFINITE_INPUT, NONFINITE_RESULT, EXTREME_INPUT = 0, 1, 2, 4, 8


def sources(d: Path = KERNELS_DIR) -> list[Path]:
    return sorted(d.glob("rigidsym_c_*.c"))


def build_example(cc: str, out: Path, flags: list[str], lang: str = "c") -> Path:
    """The example control loop built by one plain compiler line."""
    exe = out / f"control_loop_{Path(cc).name}_{len(flags)}"
    args = [cc, *flags, "-I", str(KERNELS_DIR)]
    if lang == "c++":
        # the application in C++ through the same headers; the kernels stay C
        objs = []
        for s in sources():
            o = out / (s.stem + ".o")
            subprocess.run(["gcc", *STRICT, "-O2", "-c", str(s), "-o", str(o)], check=True)
            objs.append(str(o))
        cmd = [*args, "-x", "c++", str(EXAMPLE / "main.c"), "-x", "none", *objs,
               "-o", str(exe), "-lm"]
    else:
        cmd = [*args, str(EXAMPLE / "main.c"), *map(str, sources()), "-o", str(exe), "-lm"]
    subprocess.run(cmd, check=True, capture_output=True, text=True)
    return exe


def run_example(exe: Path) -> dict[tuple[str, int], np.ndarray]:
    res = subprocess.run([str(exe)], check=True, capture_output=True, text=True)
    out = {}
    for line in res.stdout.splitlines():
        name, tick, *vals = line.split()
        out[name, int(tick)] = np.array([float(v) for v in vals])
    return out


def expected() -> dict[tuple[str, int], np.ndarray]:
    """The example's outputs from the package's kernels (book) and NumPy (user module)."""
    from rigidsym import kernels as K

    out = {}
    for tick in range(8):
        t = 0.01 * tick
        e, phi = np.array([0.0, 0.6, 0.8]), 0.3 + t
        out["Q", tick] = K.rotation_from_natural_invariants(e, phi).ravel()
        t_A = np.array([0.1, -0.2 + t, 0.3, 1.0, 0.5, -0.25])
        out["t_P", tick] = K.twist_transfer(t_A, np.zeros(3), np.array([0.2, 0.1 - t, 0.4]))
        I_C = np.array([[0.02, 0.001, 0.0], [0.001, 0.03, 0.002], [0.0, 0.002, 0.025]])
        omega = np.array([0.1, -0.2 + t, 0.3])
        out["w", tick] = K.newton_euler_wrench(I_C, 1.5, omega, np.array([0.0, 0.5, -t]),
                                               np.array([0.0, 0.0, -9.81 + t]))
        s = np.sin(0.5 * phi)
        w_, x, y, z = np.cos(0.5 * phi), 0.0, 0.6 * s, 0.8 * s
        out["Qq", tick] = np.array([
            1 - 2 * (y * y + z * z), 2 * (x * y - w_ * z), 2 * (x * z + w_ * y),
            2 * (x * y + w_ * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w_ * x),
            2 * (x * z - w_ * y), 2 * (y * z + w_ * x), 1 - 2 * (x * x + y * y)])
        q1, q2, l1, l2 = 0.4 + t, -0.7 + 2 * t, 0.35, 0.25
        out["tip", tick] = np.array([l1 * np.cos(q1) + l2 * np.cos(q1 + q2),
                                     l1 * np.sin(q1) + l2 * np.sin(q1 + q2)])
        out["tip_D_q1", tick] = np.array([-l1 * np.sin(q1) - l2 * np.sin(q1 + q2),
                                          l1 * np.cos(q1) + l2 * np.cos(q1 + q2)])
        out["tip_D_q2", tick] = np.array([-l2 * np.sin(q1 + q2), l2 * np.cos(q1 + q2)])
        v = np.array([0.3, 0.0, -0.1 + t])
        out["T", tick] = np.array([0.5 * 1.5 * v @ v + 0.5 * omega @ I_C @ omega])
    return out


def assert_matches(got: dict, want: dict, tol: float = 1e-12) -> None:
    assert set(got) == set(want)
    for key, w in want.items():
        scale = max(1.0, float(np.max(np.abs(w))))
        assert np.max(np.abs(got[key] - w)) <= tol * scale, (key, got[key], w)


@pytest.mark.slow  # generates seven kernels: 3-10 s on a loaded 2-core machine
def test_example_folder_is_what_the_generator_writes(tmp_path):
    """examples/c/rigidsym_c is the output of the command in examples/c/README.md, byte for
    byte (the --check of the C++ target: the C and, for examples/cpp, the C++ layer)."""
    from rigidsym.cli import main

    code = main(["generate", "--target", "cpp", *EXAMPLE_ARGS, "--out", str(KERNELS_DIR),
                 "--check"])
    assert code == 0


#: the example's generate command (examples/c/README.md)
EXAMPLE_ARGS = ["--module", str(EXAMPLE / "my_kernels.py"),
                "--kernel", "rotation_from_natural_invariants", "--kernel",
                "natural_invariants_from_rotation", "--kernel", "twist_transfer",
                "--kernel", "newton_euler_wrench", "--kernel", "wrench_transfer"]


def test_every_file_has_provenance_and_licence():
    for p in KERNELS_DIR.iterdir():
        text = p.read_text(encoding="utf-8")
        head = "\n".join(text.splitlines()[:8])
        assert "rigidsym 0" in head and "sha256:" in head, p.name
        assert "MIT" in head, p.name
    for h in KERNELS_DIR.glob("*.h"):
        text = h.read_text(encoding="utf-8")
        assert "Python.h" not in text and "numpy" not in text.lower()
        if h.name != "rigidsym_c_impl.h":
            assert "__FAST_MATH__" not in text, "guards belong in the sources, not headers"


@needs_gcc
def test_example_builds_strict_and_matches_numpy(tmp_path):
    exe = build_example(GCC, tmp_path, [*STRICT, "-O2"])
    assert_matches(run_example(exe), expected())


@needs_gcc
@pytest.mark.parametrize("flag", ["-ffast-math", "-Ofast", "-ffinite-math-only"])
def test_fast_math_stops_the_build_naming_the_flag(tmp_path, flag):
    res = subprocess.run([GCC, *STRICT, flag, "-c", str(sources()[0]), "-o",
                          str(tmp_path / "x.o")], capture_output=True, text=True)
    assert res.returncode != 0
    named = "-ffinite-math-only" if flag == "-ffinite-math-only" else "-ffast-math"
    assert "#error" in res.stderr and named in res.stderr and "-fno-" in res.stderr


@needs_gcc
def test_an_application_with_fast_math_still_includes_the_headers(tmp_path):
    src = tmp_path / "app.c"
    src.write_text('#include "rigidsym_c.h"\nint main(void) { return RIGIDSYM_C_OK; }\n')
    subprocess.run([GCC, *STRICT, "-Ofast", "-I", str(KERNELS_DIR), "-c", str(src), "-o",
                    str(tmp_path / "app.o")], check=True)


# -- the status codes, through ctypes on a shared build of the folder --

@pytest.fixture(scope="module")
def objects(tmp_path_factory) -> list[str]:
    """The example's kernels compiled once (strict, -O2, position-independent) for the tests
    of this module that link them: the shared library below and the programs of the flags
    tests. test_example_builds_strict_and_matches_numpy keeps the one-line build."""
    if GCC is None:
        pytest.skip("gcc is not installed")
    out = tmp_path_factory.mktemp("objects")
    objs = []
    for s in sources():
        o = out / (s.stem + ".o")
        subprocess.run([GCC, *STRICT, "-O2", "-fPIC", "-c", str(s), "-o", str(o)], check=True)
        objs.append(str(o))
    return objs


@pytest.fixture(scope="module")
def lib(tmp_path_factory, objects):
    so = tmp_path_factory.mktemp("lib") / "librigidsym_c.so"
    subprocess.run([GCC, "-shared", *objects, "-o", str(so), "-lm"], check=True)
    return ctypes.CDLL(str(so))


def call(lib, name: str, *args, dtype=np.float64):
    """Call a scalar function: arrays by pointer, Python floats by value; returns
    (status, outputs)."""
    ct = ctypes.c_double if dtype == np.float64 else ctypes.c_float
    fn = getattr(lib, name)
    cargs, outs = [], []
    for a in args:
        if isinstance(a, int | float):
            cargs.append(ct(a))
        elif isinstance(a, tuple):            # ("out", size)
            o = np.zeros(a[1], dtype)
            outs.append(o)
            cargs.append(o.ctypes.data_as(ctypes.POINTER(ct)))
        else:
            a = np.ascontiguousarray(a, dtype)
            outs.append(None)
            cargs.append(a.ctypes.data_as(ctypes.POINTER(ct)))
            cargs[-1]._keep = a  # type: ignore[attr-defined]
    fn.restype = ctypes.c_int
    status = fn(*cargs)
    return status, [o for o in outs if o is not None]


finite = st.floats(-1e3, 1e3, allow_nan=False, allow_infinity=False)


@settings(max_examples=examples(40), deadline=None)
@given(st.lists(finite, min_size=3, max_size=3), finite)
def test_status_ok_and_values_for_ordinary_inputs(lib, e, phi):
    from rigidsym import kernels as K

    e = np.array(e)
    status, (Q,) = call(lib, "rigidsym_c_rotation_from_natural_invariants", e, phi,
                        ("out", 9))
    small = any(0 < abs(x) < 2.0**-100 for x in [*e, phi])
    # an axis of extreme norm (its largest component below 2^-100) is no unit vector
    tiny_axis = 0 < np.max(np.abs(e)) < 2.0**-100
    assert status == (EXTREME_INPUT if (small and not WIDE) or tiny_axis else OK)
    if small:   # both re-run it in long double (the package NumPy's, this C's own)
        return
    want = K.rotation_from_natural_invariants(e, phi, check=False).ravel()
    scale = max(1.0, float(np.max(np.abs(want))))
    assert np.max(np.abs(Q - want)) <= 1e-12 * scale


@settings(max_examples=examples(40), deadline=None)
@given(st.lists(finite, min_size=3, max_size=3), st.sampled_from([np.nan, np.inf, -np.inf]),
       st.integers(0, 3))
def test_every_kernel_flags_a_nonfinite_input(lib, e, bad, where):
    """A kernel without a division too (rotation_from_natural_invariants) flags it."""
    e, phi = np.array(e), 0.5
    if where < 3:
        e[where] = bad
    else:
        phi = bad
    status, _ = call(lib, "rigidsym_c_rotation_from_natural_invariants", e, phi, ("out", 9))
    assert status & NONFINITE_INPUT
    status, _ = call(lib, "rigidsym_c_body_energy", 1.0, e, np.eye(3), [0.0, 0.0, phi],
                     ("out", 1))
    assert status & NONFINITE_INPUT


@pytest.mark.parametrize("dtype, lo, hi", [(np.float64, 2.0**-100, 2.0**101),
                                           (np.float32, 2.0**-30, 2.0**31)])
def test_inputs_at_the_ends_of_the_range_are_ordinary(lib, dtype, lo, hi):
    """The x86-64 range test (byte lanes, rigidsym_c_impl.h) flags components within 5
    octaves (float: 1) inside the ends of [lo, hi); the cold path tests them again exactly,
    so they keep status 0 and the ordinary values (twist_transfer: linear, exact here)."""
    sfx = "_f32" if dtype == np.float32 else ""
    for x in [lo, lo * (1 + 2.0**-4), lo * (1 + 2.0**-3) * (1 - 2.0**-20), hi * (1 - 2.0**-6),
              hi * (1 - 2.0**-20), -lo, 0.0, lo * 2.0**5, -lo * 1.5, hi * 2.0**-4]:
        t_A = np.array([x, 0.5, -x, 0.25, x, 1.0])
        a, p = np.array([0.0, 0.0, 0.0]), np.array([0.0, 0.0, 0.0])
        status, (out,) = call(lib, f"rigidsym_c_twist_transfer{sfx}", t_A, a, p, ("out", 6),
                              dtype=dtype)
        assert status == OK, (x, status)
        assert np.array_equal(out, t_A.astype(dtype)), (x, out)
    status, _ = call(lib, f"rigidsym_c_twist_transfer{sfx}", [lo / 2, 0, 0, 0, 0, 0],
                     np.zeros(3), np.zeros(3), ("out", 6), dtype=dtype)
    assert status in (OK, EXTREME_INPUT)     # rescued (0) or flagged, never silent


#: the two bit-pattern checks' common start: the header, a xorshift generator, and the
#: exponents at the ends of the range (double: 2^-100 = 923 - 1023, 2^101 = 1124 - 1023)
_CHECK_PRELUDE = r"""#include "rigidsym_c_impl.h"
#include <stdio.h>
static uint64_t s_ = 88172645463325252ULL;
static uint64_t rnd(void) { s_ ^= s_ << 13; s_ ^= s_ >> 7; s_ ^= s_ << 17; return s_; }
#define RIGIDSYM_CHECK_ENDS \
    static const uint64_t ed[] = {0, 1, 922, 923, 924, 1123, 1124, 1125, 2046, 2047}; \
    static const uint32_t ef[] = {0, 1, 96, 97, 98, 157, 158, 159, 254, 255};
"""


_SSE2_CHECK = _CHECK_PRELUDE + r"""
int main(void)
{
#if RIGIDSYM_C_SSE2
    RIGIDSYM_CHECK_ENDS
    long i, fn = 0, fp = 0;
    for (i = 0; i < 2000000; ++i) {
        uint64_t b = rnd(), acc = 0;
        uint32_t c = (uint32_t)rnd(), accf = 0;
        double x, one = 1.0;
        float xf, onef = 1.0f;
        const __m128i ord = rigidsym_c_q_d(_mm_castpd_si128(_mm_setr_pd(one, -one)));
        const __m128i ordf = rigidsym_c_q_f(_mm_castps_si128(_mm_setr_ps(onef, -onef, 0.0f, 0.5f)));
        __m128i q, qf;
        if (i % 3 == 1) {   /* the exponents at the ends, few significand bits or many */
            b = (b & 0x800fffffffffffffULL) | (ed[rnd() % 10] << 52);
            c = (c & 0x807fffffU) | (ef[rnd() % 10] << 23);
            if (rnd() % 4 == 0) {
                b &= 0xfff0000000000000ULL | (rnd() % 3);
                c &= 0xff800000U | (uint32_t)(rnd() % 3);
            }
        } else if (i % 3 == 2) {
            b = (rnd() % 2) ? 0 : 0x8000000000000000ULL;
            c = (rnd() % 2) ? 0 : 0x80000000U;
        }
        memcpy(&x, &b, 8);
        memcpy(&xf, &c, 4);
        RIGIDSYM_C_ODD_D(acc, x);
        /* as the kernels take it: the byte max with an ordinary register's value */
        q = _mm_max_epu8(ord, rigidsym_c_q_d(_mm_castpd_si128(_mm_setr_pd(one, x))));
        fn += (acc >> 63) && !RIGIDSYM_C_Q_ODD_D(q);
        /* and none is flagged in (2^-95, 2^97) (float: (2^-29, 2^31)), nor a zero */
        fp += RIGIDSYM_C_Q_ODD_D(q) && (x == 0 || (fabs(x) > 0x1p-95 && fabs(x) < 0x1p97));
        RIGIDSYM_C_ODD_F(accf, xf);
        qf = _mm_max_epu8(ordf,
                          rigidsym_c_q_f(_mm_castps_si128(_mm_setr_ps(onef, xf, 0.0f, onef))));
        fn += (accf >> 31) && !RIGIDSYM_C_Q_ODD_F(qf);
        fp += RIGIDSYM_C_Q_ODD_F(qf) && (xf == 0 || (fabsf(xf) > 0x1p-29f && fabsf(xf) < 0x1p31f));
    }
    printf("%ld %ld\n", fn, fp);
#else
    printf("skip\n");
#endif
    return 0;
}
"""


@needs_gcc
def test_sse2_range_test_misses_no_odd_component(tmp_path):
    """The x86-64 range test (an unsigned byte max over s = |x|'s bits shifted left and -s,
    rigidsym_c_impl.h) flags every component that the exact bit test (RIGIDSYM_C_ODD_*)
    calls odd, and none of magnitude in (2^-95, 2^97) (float (2^-29, 2^31)) nor a zero: 2e6
    random bit patterns of each type, each in a register's byte max with an ordinary
    register's, a third with their exponent at an end of the range (subnormals, 2^-100,
    2^101, infinities and NaNs with every payload), a third signed zeros."""
    src = tmp_path / "check.c"
    src.write_text(_SSE2_CHECK)
    exe = tmp_path / "check"
    subprocess.run([GCC, *STRICT, "-O2", "-I", str(KERNELS_DIR), str(src), "-o", str(exe),
                    "-lm"], check=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    if out.strip() == "skip":
        pytest.skip("no SSE2 range test on this machine")
    assert out.split() == ["0", "0"]


_VECTOR_CHECK = _CHECK_PRELUDE + r"""
#include <math.h>
/* the definition: odd = not zero and |x| outside [lo, hi), or not finite */
static int odd_d(double x) { double a = fabs(x); return x != 0 && !(a >= 0x1p-100 && a < 0x1p101); }
static int odd_f(float x) { float a = fabsf(x); return x != 0 && !(a >= 0x1p-30f && a < 0x1p31f); }
int main(void)
{
#if RIGIDSYM_C_VECTOR
    RIGIDSYM_CHECK_ENDS
    long i, bad = 0;
    for (i = 0; i < 2000000; ++i) {
        uint64_t b = rnd(), acc = 0, accz = 0;
        uint32_t c = (uint32_t)rnd(), accf = 0, acczf = 0;
        double x;
        float xf;
        rigidsym_c_vd vd = {0, 0};
        rigidsym_c_vf vf = {0, 0, 0, 0};
        if (i % 2) {
            b = (b & 0x800fffffffffffffULL) | (ed[rnd() % 10] << 52);
            c = (c & 0x807fffffU) | (ef[rnd() % 10] << 23);
        }
        memcpy(&x, &b, 8);
        memcpy(&xf, &c, 4);
        RIGIDSYM_C_ODD_D(acc, x);
        RIGIDSYM_C_ODD_F(accf, xf);
        RIGIDSYM_C_ODDNZ_D(accz, x);
        RIGIDSYM_C_ODDNZ_F(acczf, xf);
        vd[1] = b;
        vf[2] = c;
        vd = rigidsym_c_odd_vd(vd);
        vf = rigidsym_c_odd_vf(vf);
        bad += (int)(acc >> 63) != odd_d(x) || (int)(vd[1] >> 63) != odd_d(x) || vd[0] >> 63;
        bad += (int)(accf >> 31) != odd_f(xf) || (int)(vf[2] >> 31) != odd_f(xf) || vf[0] >> 31;
        bad += (accz != 0) != odd_d(x) || (acczf != 0) != odd_f(xf);
    }
    printf("%ld\n", bad);
#else
    printf("skip\n");
#endif
    return 0;
}
"""


@needs_gcc
def test_the_vector_and_scalar_range_tests_are_the_definition(tmp_path):
    """The generic vector range test (Arm with NEON) and the scalar ones (Cortex-M, other
    compilers: RIGIDSYM_C_ODD_* and the fast path's RIGIDSYM_C_ODDNZ_*), built here with
    -DRIGIDSYM_C_NO_SSE2, call a component odd exactly when it
    is not zero and its magnitude lies outside [2^-100, 2^101) (float: [2^-30, 2^31)) or
    it is not finite: 2e6 random bit patterns per type, half with exponents at the ends."""
    src = tmp_path / "check.c"
    src.write_text(_VECTOR_CHECK)
    exe = tmp_path / "check"
    subprocess.run([GCC, *STRICT, "-O2", "-DRIGIDSYM_C_NO_SSE2", "-I", str(KERNELS_DIR),
                    str(src), "-o", str(exe), "-lm"], check=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    if out.strip() == "skip":
        pytest.skip("no generic vector range test with this compiler")
    assert out.strip() == "0"


_HELPERS_CHECK = _CHECK_PRELUDE + r"""
/* the branch-free sign and the outputs' store macros against their plain C definitions */
int main(void)
{
    static const double sd[] = {0.0, -0.0, 1.0, -1.0, 5e-324, -5e-324, 1e308, -1e308};
    long i, bad = 0;
    for (i = 0; i < 400000; ++i) {
        uint64_t b = rnd();
        uint32_t c = (uint32_t)rnd();
        double x, o[2] = {7.0, 7.0};
        float xf, of[4] = {7.0f, 7.0f, 7.0f, 7.0f}, of2[3] = {7.0f, 7.0f, 7.0f};
        memcpy(&x, &b, 8);
        memcpy(&xf, &c, 4);
        if (i < 8) x = sd[i], xf = (float)sd[i];
        if (i == 8) x = NAN, xf = NAN;
        if (i == 9) x = -NAN, xf = -NAN;
        if (i == 10) x = -INFINITY, xf = -INFINITY;
        /* the same bits as the ternary (1.0 for -0 and NaN) */
        { const double r = rigidsym_c_negative_d(x), t = (x < 0.0) ? -1.0 : 1.0;
          bad += memcmp(&r, &t, 8) != 0; }
        { const float r = rigidsym_c_negative_f(xf), t = (xf < 0.0f) ? -1.0f : 1.0f;
          bad += memcmp(&r, &t, 4) != 0; }
        RIGIDSYM_C_PUT2D(o, x, -x);
        bad += memcmp(&o[0], &x, 8) != 0;
        { const double m = -x; bad += memcmp(&o[1], &m, 8) != 0; }
        RIGIDSYM_C_PUT4F(of, xf, -xf, 2.0f, xf);
        bad += memcmp(&of[0], &xf, 4) != 0 || memcmp(&of[3], &xf, 4) != 0 || of[2] != 2.0f;
        RIGIDSYM_C_PUT2F(of2, -xf, xf);
        bad += memcmp(&of2[1], &xf, 4) != 0 || of2[2] != 7.0f;   /* 8 bytes, no more */
    }
    printf("%ld\n", bad);
    return 0;
}
"""


@needs_gcc
@pytest.mark.parametrize("flags", [[], ["-DRIGIDSYM_C_NO_VECTOR"]], ids=["vector", "scalar"])
def test_the_sign_and_store_helpers_are_their_plain_definitions(tmp_path, flags):
    """``rigidsym_c_negative_d``/``_f`` (the printed sign choice ``x < 0 ? -1 : 1``, by a
    mask) give the ternary's bits for -0, NaN of either sign, infinities, subnormals and 4e5
    random bit patterns; the outputs' 16-byte stores (``RIGIDSYM_C_PUT*``) write exactly their
    components, bit for bit, and nothing past them; both in the vector build and in the
    scalar one of Cortex-M and other compilers."""
    src = tmp_path / "helpers.c"
    src.write_text(_HELPERS_CHECK)
    exe = tmp_path / "helpers"
    subprocess.run([GCC, *STRICT, "-O2", *flags, "-I", str(KERNELS_DIR), str(src), "-o",
                    str(exe), "-lm"], check=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    assert out.strip() == "0"


def test_only_the_sign_choice_prints_branch_free():
    """``Piecewise((-1, x < 0), (1, True))`` prints as the helper of its type; a form whose
    value differs from the helper's anywhere (``x <= 0``: -1 at x = -0; swapped values;
    another threshold) prints as the ternary, and so does the long double rescue."""
    import sympy as sp

    from rigidsym.codegen.backends.c.printer import DoublePrinter, FloatOnlyPrinter, WidePrinter

    x, y = sp.symbols("x y")
    sign = sp.Piecewise((-1, x + y < 0), (1, True))
    assert DoublePrinter().doprint(sign) == "rigidsym_c_negative_d(x + y)"
    assert FloatOnlyPrinter().doprint(sign) == "rigidsym_c_negative_f(x + y)"
    assert "?" in WidePrinter().doprint(sign)
    for other in (sp.Piecewise((-1, x <= 0), (1, True)), sp.Piecewise((1, x < 0), (-1, True)),
                  sp.Piecewise((-1, x < 1), (1, True)), sp.Piecewise((-2, x < 0), (1, True)),
                  sp.Piecewise((-1, x < 0), (0, y < 0), (1, True))):
        assert "?" in DoublePrinter().doprint(other), other


#: the three input range tests: x86-64's SSE2 one (the default here), the generic vector
#: one that Arm with NEON takes, and the scalar loop of Cortex-M and other compilers
RANGE_TESTS = {"sse2": [], "vector": ["-DRIGIDSYM_C_NO_SSE2"], "scalar": ["-DRIGIDSYM_C_NO_VECTOR"]}


# three builds of every source; quick: test_the_vector_and_scalar_range_tests_are_the_definition
@pytest.mark.slow
@needs_gcc
def test_the_three_range_tests_give_the_same_status_and_values(tmp_path):
    """Each input range test (the SSE2 one run here, and the two that Arm and Cortex-M
    take, built here by their macros) gives every call the same status and the same bits:
    the generic vector and scalar tests would otherwise run nowhere in the tests. Random
    components with exponents spread over the whole floating line (zeros, subnormals, the
    ends of the range, infinities and NaNs), double and float."""
    libs = {}
    for name, flags in RANGE_TESTS.items():
        so = tmp_path / f"lib_{name}.so"
        subprocess.run([GCC, *STRICT, "-O2", *flags, "-shared", "-fPIC",
                        *map(str, sources()), "-o", str(so), "-lm"], check=True)
        libs[name] = ctypes.CDLL(str(so))
    rng = np.random.default_rng(53)
    special = [0.0, -0.0, np.inf, -np.inf, np.nan, 5e-324, 2.0**-100, 2.0**101, 1e-30, 3e9]
    for dtype, suffix, emax in ((np.float64, "", 1023), (np.float32, "_f32", 127)):
        for _ in range(400):
            x = rng.standard_normal(18) * 2.0 ** rng.integers(-emax - 20, emax + 1, 18)
            pick = rng.random(18) < 0.15
            x[pick] = rng.choice(special, pick.sum())
            with np.errstate(over="ignore"):
                x = x.astype(dtype)
            t, a, p, v, w = x[:6], x[6:9], x[9:12], x[12:15], x[15:18]
            got = {}
            for name, lib in libs.items():
                s1, (o1,) = call(lib, f"rigidsym_c_twist_transfer{suffix}", t, a, p,
                                 ("out", 6), dtype=dtype)
                s2, (o2,) = call(lib, f"rigidsym_c_body_energy{suffix}", 1.5, v,
                                 np.eye(3, dtype=dtype), w, ("out", 1), dtype=dtype)
                got[name] = (s1, o1.tobytes(), s2, o2.tobytes())
            assert got["vector"] == got["sse2"] == got["scalar"], (dtype, x)


WIDE = np.finfo(np.longdouble).maxexp > np.finfo(np.float64).maxexp


@pytest.mark.skipif(not WIDE, reason="long double is double here: no wider type to rescue in")
@settings(max_examples=examples(25), deadline=None)
@given(st.sampled_from([1e-300, 1e-200, 1e-40, 1e-12, 1e30]), st.integers(0, 2**32 - 1))
def test_extreme_inputs_are_rescued_in_long_double(lib, scale, seed):
    """Inputs scaled to 1e-300 ... 1e30 (every intermediate representable in long double):
    status 0 and the package kernels' values (both re-run in long double, rounded once);
    an axis (a unit-vector argument) of extreme norm is flagged, its values the same."""
    from rigidsym import kernels as K

    rng = np.random.default_rng(seed)
    t, a, p = (rng.normal(size=n) * scale for n in (6, 3, 3))
    status, (got,) = call(lib, "rigidsym_c_twist_transfer", t, a, p, ("out", 6))
    want = K.twist_transfer(t, a, p, check=False)
    assert status == OK
    assert np.max(np.abs(got - want)) <= 1e-15 * np.max(np.abs(want))
    e = rng.normal(size=3) * scale
    status, (Q,) = call(lib, "rigidsym_c_rotation_from_natural_invariants", e, 0.3, ("out", 9))
    # an axis of extreme norm (its largest component outside [2^-100, 2^101)) is flagged:
    # no unit vector is that short or long
    big = float(np.max(np.abs(e)))
    assert status == (OK if 2.0**-100 <= big < 2.0**101 else EXTREME_INPUT)
    want = K.rotation_from_natural_invariants(e, 0.3, check=False).ravel()
    assert np.max(np.abs(Q - want)) <= 1e-15 * np.max(np.abs(want))


@settings(max_examples=examples(30), deadline=None)
@given(st.floats(2.0**101, 1e300))
def test_overflow_is_flagged_never_silent(lib, big):
    """v |v|^2 overflows: the status says so (the package's batch path re-runs the row)."""
    status, (T,) = call(lib, "rigidsym_c_body_energy", 1.0, [big, 0, 0], np.eye(3),
                        [0.0, 0.0, 0.0], ("out", 1))
    if WIDE:    # rescued in long double: right where it fits, flagged where it does not
        assert status in (OK, NONFINITE_RESULT)
        assert (status == OK) == (big * big / 2 < np.finfo(np.float64).max)
    else:
        assert status & EXTREME_INPUT
    assert np.isfinite(T[0]) or status & NONFINITE_RESULT


@settings(max_examples=examples(15), deadline=None)
@given(st.integers(0, 9), st.data())
def test_batch_function_is_the_scalar_function_per_row(lib, n, data):
    """rigidsym_c_<k>_batch over n rows gives each row what the scalar function gives it,
    the statuses per row and their OR (a NaN row among ordinary ones)."""
    rows = np.array(data.draw(st.lists(st.lists(finite, min_size=12, max_size=12),
                                       min_size=n, max_size=n))).reshape(n, 12)
    if n:
        rows[data.draw(st.integers(0, n - 1)), 0] = np.nan
    t_A, a, p = (np.ascontiguousarray(rows[:, s]) for s in (slice(0, 6), slice(6, 9),
                                                            slice(9, 12)))
    out = np.zeros((n, 6))
    status = np.zeros(n, np.int32)
    ptr = ctypes.POINTER(ctypes.c_double)
    fn = lib.rigidsym_c_twist_transfer_batch
    fn.restype = ctypes.c_int
    total = fn(ctypes.c_size_t(n), t_A.ctypes.data_as(ptr), a.ctypes.data_as(ptr),
               p.ctypes.data_as(ptr), out.ctypes.data_as(ptr),
               status.ctypes.data_as(ctypes.POINTER(ctypes.c_int)))
    want_all = 0
    for i in range(n):
        s, (row,) = call(lib, "rigidsym_c_twist_transfer", t_A[i], a[i], p[i], ("out", 6))
        assert s == status[i]
        np.testing.assert_array_equal(row, out[i])
        want_all |= s
    assert total == want_all


def test_float_functions_agree_with_double(lib):
    rng = np.random.default_rng(5)
    worst = 0.0
    for _ in range(200):
        e = rng.normal(size=3)
        e /= np.linalg.norm(e)
        phi = float(rng.uniform(-3, 3))
        _, (Qd,) = call(lib, "rigidsym_c_rotation_from_natural_invariants", e, phi,
                        ("out", 9))
        s, (Qf,) = call(lib, "rigidsym_c_rotation_from_natural_invariants_f32",
                        e.astype(np.float32), float(np.float32(phi)), ("out", 9),
                        dtype=np.float32)
        assert s == OK
        worst = max(worst, float(np.max(np.abs(Qf - Qd))))
    assert worst < 8 * 2.0**-24


def test_header_documents_arguments_units_and_layout():
    h = (KERNELS_DIR / "rigidsym_c_newton_euler_wrench.h").read_text(encoding="utf-8")
    for needed in ["3.134", "I_C: inertia at the mass centre [kg m^2]; 3 x 3, row-major: "
                   "[i][j] at [3*i + j]", "w: [n_C; f] [N m; N]; vector of 6",
                   "RIGIDSYM_C_NONFINITE_INPUT", "rigidsym_c_newton_euler_wrench_f32(",
                   "rigidsym_c_newton_euler_wrench_with_jacobians(",
                   "w_D_I_C: d w / d I_C, shape (6,) + (3, 3); 6 x 3 x 3, row-major: "
                   "[i][j][k] at [9*i + 3*j + k]"]:
        assert needed in h, needed
    assert re.search(r"RIGIDSYM_C_BEGIN_DECLS", h)


# -- slow: every source under every flag of the matrix, gcc and clang, plain and CMake --

#: flags -> the flag the #error must name, or None where the sources must build and be right
MATRIX = {
    "": None,
    "-O3": None,
    "-ffast-math": "-ffast-math",
    "-Ofast": "-Ofast",
    "-fassociative-math -fno-signed-zeros -fno-trapping-math": "-fassociative-math",
    "-ffinite-math-only": "-ffinite-math-only",
    "-ffp-contract=fast": None,
    "-O3 -march=native -ffp-contract=fast": None,
    "-DRIGIDSYM_C_TRUSTED_INPUTS": None,      # no input range test: still right
    "-DRIGIDSYM_C_NO_WIDE": None,             # no long double rescue: still right
    # found by an outside trial: gcc's single-precision constants (no macro shows them; an
    # array of negative size named for the fix stops the build), clang's NaNs and
    # infinities not honoured (no macro either; the sources' precise pragma keeps them)
    "-fsingle-precision-constant": "-fsingle-precision-constant",
    "-fno-honor-nans": None,
    "-fno-honor-nans -fno-honor-infinities -U__FINITE_MATH_ONLY__": None,
    "-Wdouble-promotion": None,   # clang warned in the long double rescue and at NAN (trial)
}
#: flags one compiler does not have: (compiler, flag) -> why the cell is skipped
NOT_A_FLAG = {("gcc", "-fno-honor-nans"): "gcc has no -fno-honor-nans (its -ffinite-math-only "
                                          "defines __FINITE_MATH_ONLY__)",
              ("clang", "-fsingle-precision-constant"): "clang does not support it (a warning, "
                                                        "an error under -Werror)"}
COMPILERS = [c for c in ("gcc", "clang") if shutil.which(c)]
#: the cells of the matrix every run builds: each one that must stop at an #error (a
#: compile of each source, cheap) and those an outside trial found (clang's
#: -fassociative-math, which no macro shows; clang's NaNs and infinities not honoured;
#: clang's -Wdouble-promotion warnings; gcc's -fsingle-precision-constant). The thorough
#: run builds a seeded quarter of the other cells, the plain builds that must be right
#: under ordinary flags (every cell in the ``exhaustive`` profile; the seed rotates per
#: commit)
MATRIX_ALWAYS = {(cc, f) for cc in ("gcc", "clang") for f, err in MATRIX.items()
                 if err is not None and not (cc == "clang" and err == "-fassociative-math")} | {
    ("clang", "-fassociative-math -fno-signed-zeros -fno-trapping-math"),
    ("clang", "-fno-honor-nans"),
    ("clang", "-fno-honor-nans -fno-honor-infinities -U__FINITE_MATH_ONLY__"),
    ("clang", "-Wdouble-promotion"), ("gcc", "-fsingle-precision-constant")}


def _cells(flag_list, always) -> list:
    """(cc, flags) for gcc then clang: the cells of ``always`` and those a compiler skips
    (NOT_A_FLAG) as they are, the others in the thorough run's seeded quarter
    (``thorough``)."""
    def kept(cc: str, f: str) -> bool:
        return (cc, f) in always or any((cc, flag) in NOT_A_FLAG for flag in f.split())

    return [(cc, f) if kept(cc, f) else pytest.param(cc, f, marks=pytest.mark.thorough(1 / 4))
            for cc in ("gcc", "clang") for f in flag_list]


def _fails_naming(res: subprocess.CompletedProcess, flag: str) -> bool:
    return res.returncode != 0 and "#error" in res.stderr or \
        (res.returncode != 0 and "error:" in res.stderr and flag in res.stderr)


@pytest.mark.slow
@pytest.mark.skipif(not COMPILERS, reason="neither gcc nor clang is installed")
@pytest.mark.parametrize("cc,flags", _cells(MATRIX, MATRIX_ALWAYS))
def test_flag_matrix_plain_build_right_or_error(tmp_path, cc, flags):
    """Each source file alone stops at an #error naming the flag, or the example with every
    source builds under the flags and matches the NumPy kernels to 1e-12 (clang's
    -fassociative-math, which no macro shows, is turned off by the sources' pragma, so it
    must build and be right)."""
    if shutil.which(cc) is None:
        pytest.skip(f"{cc} is not installed")
    for (c, flag), why in NOT_A_FLAG.items():
        if c == cc and flag in flags.split():
            pytest.skip(why)
    want_error = MATRIX[flags]
    if cc == "clang" and want_error == "-fassociative-math":
        want_error = None            # clang: no macro; the pragma keeps the code right
    for src in sources() if want_error is not None else ():  # else: the example builds them
        res = subprocess.run([cc, *STRICT, "-O2", *flags.split(), "-c", str(src), "-o",
                              str(tmp_path / (src.stem + ".o"))], capture_output=True,
                             text=True)
        if want_error == "-fsingle-precision-constant":   # the array's name says it
            assert res.returncode != 0, res.stderr
            assert "error_fsingle_precision_constant_add_fno_single_precision_constant" in \
                res.stderr, res.stderr
        else:
            named = "-ffast-math" if want_error == "-Ofast" else want_error
            assert res.returncode != 0 and "#error" in res.stderr or "error:" in res.stderr
            assert named in res.stderr and "-fno-" in res.stderr, res.stderr
    if want_error is None:
        exe = build_example(cc, tmp_path, [*STRICT, "-O2", *flags.split()])
        assert_matches(run_example(exe), expected())


def _cmake(tmp_path: Path, cc: str, flags: str) -> Path:
    build = tmp_path / f"build_{cc}"
    subprocess.run(["cmake", "-S", str(EXAMPLE), "-B", str(build), f"-DCMAKE_C_COMPILER={cc}",
                    f"-DCMAKE_C_FLAGS={' '.join([*STRICT, flags])}",
                    "-DCMAKE_BUILD_TYPE=Release"], check=True, capture_output=True)
    subprocess.run(["cmake", "--build", str(build)], check=True, capture_output=True)
    return build / "control_loop"


#: the application flags of the CMake build
CMAKE_FLAGS = ["", "-Ofast", "-fassociative-math -fno-signed-zeros -fno-trapping-math",
               "-ffinite-math-only", "-fsingle-precision-constant"]
#: the CMake builds every run makes (the docstring's two cases); the thorough run makes a
#: seeded quarter of the others
CMAKE_ALWAYS = {("gcc", "-Ofast"), ("gcc", "-fsingle-precision-constant")}


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("cmake") is None, reason="cmake is not installed")
@pytest.mark.parametrize("cc,flags", _cells(CMAKE_FLAGS, CMAKE_ALWAYS))
def test_cmake_build_is_right_under_the_application_flags(tmp_path, cc, flags):
    """The CMake target compiles the kernels with its own flags after the project's: an
    application built with -Ofast links right kernels (and its own main.c stays fast);
    one built with gcc's -fsingle-precision-constant too (the target undoes it)."""
    if shutil.which(cc) is None:
        pytest.skip(f"{cc} is not installed")
    for (c, flag), why in NOT_A_FLAG.items():
        if c == cc and flag in flags.split():
            pytest.skip(why)
    exe = _cmake(tmp_path, cc, flags)
    if "-fsingle-precision-constant" in flags:
        return   # built: the sources' guard proves their constants double; the example's
        #          own main.c then holds float inputs, so NumPy's values are not its answer
    assert_matches(run_example(exe), expected())


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("cmake") is None or shutil.which("pkg-config") is None,
                    reason="cmake or pkg-config is not installed")
def test_installed_library_by_find_package_and_pkg_config(tmp_path):
    """cmake --install, then a project using find_package(rigidsym_c), and a plain line
    using pkg-config --cflags --libs rigidsym_c."""
    build, prefix = tmp_path / "lib", tmp_path / "prefix"
    subprocess.run(["cmake", "-S", str(KERNELS_DIR), "-B", str(build),
                    f"-DCMAKE_INSTALL_PREFIX={prefix}"], check=True, capture_output=True)
    subprocess.run(["cmake", "--build", str(build)], check=True, capture_output=True)
    subprocess.run(["cmake", "--install", str(build)], check=True, capture_output=True)
    app = tmp_path / "app"
    app.mkdir()
    shutil.copy(EXAMPLE / "main.c", app / "main.c")
    (app / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.13)\nproject(app LANGUAGES C)\n"
        "find_package(rigidsym_c REQUIRED)\nadd_executable(app main.c)\n"
        "target_link_libraries(app PRIVATE rigidsym_c::rigidsym_c m)\n")
    subprocess.run(["cmake", "-S", str(app), "-B", str(app / "b"),
                    f"-DCMAKE_PREFIX_PATH={prefix}"], check=True, capture_output=True)
    subprocess.run(["cmake", "--build", str(app / "b")], check=True, capture_output=True)
    assert_matches(run_example(app / "b" / "app"), expected())
    pcdir = next(prefix.rglob("rigidsym_c.pc")).parent
    env = {"PKG_CONFIG_PATH": str(pcdir), "PATH": "/usr/bin:/bin"}
    for static in ([], ["--static"]):   # the README's line has no --static (an outside
        flags = subprocess.run(["pkg-config", "--cflags", "--libs", *static, "rigidsym_c"],
                               env=env, check=True, capture_output=True,
                               text=True).stdout.split()    # trial: -lm was private)
        exe = tmp_path / f"pc_app{len(static)}"
        subprocess.run([GCC or "cc", *STRICT, str(EXAMPLE / "main.c"), *flags, "-o",
                        str(exe)], check=True)
        assert_matches(run_example(exe), expected())


@pytest.mark.slow
@pytest.mark.parametrize("cc", ["clang", "g++"])
def test_example_builds_with_clang_and_as_cpp(tmp_path, cc):
    if shutil.which(cc) is None or GCC is None:
        pytest.skip(f"{cc} is not installed")
    if cc == "g++":
        exe = build_example(cc, tmp_path, ["-std=c++11", "-Wall", "-Wextra", "-Werror",
                                           "-pedantic", "-O2"], lang="c++")
    else:
        exe = build_example(cc, tmp_path, [*STRICT, "-O2"])
    assert_matches(run_example(exe), expected())


ARM = shutil.which("arm-none-eabi-gcc")
M4F = ["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard", "-mfpu=fpv4-sp-d16"]
#: what a double operation or double libm call leaves in a Cortex-M4F object
DOUBLE_SYMBOLS = re.compile(r"^(__aeabi_d\w+|__aeabi_[fil]2d|__aeabi_d2\w+|sin|cos|tan|sqrt|"
                            r"atan2|fma|pow|exp|log|fabs|__ieee754_\w+[^f])$")


@pytest.mark.slow
@pytest.mark.skipif(ARM is None, reason="arm-none-eabi-gcc is not installed (Debian: "
                                        "gcc-arm-none-eabi)")
def test_float_functions_have_no_double_operation_on_cortex_m4f(tmp_path):
    """Every _f32 function's section of every Cortex-M4F object references no __aeabi_d*
    helper and no double libm function; the float example, linked with newlib, neither;
    -Wdouble-promotion clean."""
    relocs: dict[str, set[str]] = {}
    for src in sources():
        obj = tmp_path / (src.stem + ".o")
        subprocess.run([ARM, *M4F, *STRICT, "-Wdouble-promotion", "-O2", "-ffunction-sections",
                        "-I", str(KERNELS_DIR), "-c", str(src), "-o", str(obj)], check=True)
        dump = subprocess.run(["arm-none-eabi-objdump", "-r", str(obj)], check=True,
                              capture_output=True, text=True).stdout
        section = ""
        for line in dump.splitlines():
            if line.startswith("RELOCATION RECORDS FOR"):
                section = line.split("[")[1].rstrip("]:")
            elif "R_ARM" in line:
                relocs.setdefault(section, set()).add(line.split()[-1])
    floats = [sec for sec in relocs if sec.endswith("_f32")]
    doubles = [sec for sec in relocs if sec.startswith(".text.rigidsym_c_")
               and not sec.endswith("_f32")]
    assert floats and doubles
    for sec in floats:
        assert not {s for s in relocs[sec] if DOUBLE_SYMBOLS.match(s)}, (sec, relocs[sec])
    # the check can fail: the double functions do call double helpers or libm
    assert any(DOUBLE_SYMBOLS.match(s) for sec in doubles for s in relocs[sec])
    elf = tmp_path / "fw.elf"
    subprocess.run([ARM, *M4F, *STRICT, "-Wdouble-promotion", "-O2", "-ffunction-sections",
                    "-fdata-sections", "-I", str(KERNELS_DIR), str(EXAMPLE / "main_f32.c"),
                    *map(str, sources()), "-Wl,--gc-sections", "--specs=nosys.specs",
                    "-o", str(elf), "-lm"], check=True)
    syms = subprocess.run(["arm-none-eabi-nm", str(elf)], check=True, capture_output=True,
                          text=True).stdout.split()
    assert "sinf" in syms and "cosf" in syms
    assert not [s for s in syms if DOUBLE_SYMBOLS.match(s)]
    # a per-sample loop for MCUs with <= 2 KB of stack: every function's frame, batch
    # loops included (-fstack-usage), well under it
    for src in sources():
        subprocess.run([ARM, *M4F, "-std=c99", "-O2", "-fstack-usage", "-I", str(KERNELS_DIR),
                        "-c", str(src), "-o", str(tmp_path / "su.o")], check=True,
                       cwd=tmp_path)
        frames = [int(line.split("\t")[1])
                  for line in (tmp_path / "su.su").read_text().splitlines()]
        assert frames and max(frames) <= 2048, (src.name, frames)


@pytest.mark.slow
@needs_gcc
def test_float_example_matches_numpy_to_float_rounding(tmp_path):
    """The float-only loop on the host: every output within 8 u (float32) of the NumPy
    kernels' float64 value, normwise (the inputs themselves rounded to float)."""
    exe = tmp_path / "f32"
    subprocess.run([GCC, *STRICT, "-Wdouble-promotion", "-O2", "-DRIGIDSYM_EXAMPLE_PRINT",
                    "-I", str(KERNELS_DIR), str(EXAMPLE / "main_f32.c"), *map(str, sources()),
                    "-o", str(exe), "-lm"], check=True)
    assert_matches(run_example(exe), expected(), tol=8 * 2.0**-24)


def _unused():  # keep sys imported
    return sys.executable


# -- the package's own build refuses the same flags (RIGIDSYM_CFLAGS) --

SAFE = ["-O2", "-O3", "-std=c99", "-ffp-contract=off", "-ffp-contract=fast", "-march=native",
        "-fno-math-errno", "-g"]


@settings(max_examples=examples(60), deadline=None)
@given(st.lists(st.sampled_from(SAFE), max_size=4), st.sampled_from(sorted(
    __import__("rigidsym.kernels.cbuild.driver", fromlist=["UNSAFE_FLAGS"]).UNSAFE_FLAGS)),
    st.lists(st.sampled_from(SAFE), max_size=3), st.booleans())
def test_package_build_refuses_unsafe_flags(before, bad, after, undo):
    """An unsafe flag is refused, naming it, unless a later flag undoes it."""
    import os

    from rigidsym.kernels.cbuild import driver as _build

    fix = [_build.UNSAFE_FLAGS[bad]] if undo else []
    old = os.environ.get("RIGIDSYM_CFLAGS")
    os.environ["RIGIDSYM_CFLAGS"] = " ".join([*before, bad, *after, *fix])
    try:
        if undo:
            assert _build.kernel_flags()[-1] == fix[0]
        else:
            with pytest.raises(ValueError, match=re.escape(bad)):
                _build.kernel_flags()
    finally:
        if old is None:
            del os.environ["RIGIDSYM_CFLAGS"]
        else:
            os.environ["RIGIDSYM_CFLAGS"] = old


# -- generator errors a user can act on (item 7) --

_HEAD = '''import sympy as sp
from rigidsym.codegen.spec import Arg, Kernel, Out
'''
BAD_MODULES = {
    # a symbol that is not an argument
    "unknown_symbol": (_HEAD + '''
def pend(theta, l):
    return sp.Symbol("g") * sp.sin(theta) / l
KERNELS = [Kernel(name="pendulum", summary="s", formula="a = g sin(theta) / l", ids=("x",),
    sources=(pend,), args=(Arg("theta", (), "any", "angle"), Arg("l", (), "any", "length")),
    outputs=(Out("a", (), "acc"),), build=lambda theta, l: {"a": pend(theta, l)})]
''', "pendulum", "symbol g is not an argument"),
    # a Python NameError in a formula
    "name_error": (_HEAD + '''
def f(x):
    return x * gravity
KERNELS = [Kernel(name="scaled", summary="s", formula="y", ids=("x",), sources=(f,),
    args=(Arg("x", (), "any", "x"),), outputs=(Out("y", (), "y"),),
    build=lambda x: {"y": f(x)})]
''', "scaled", "'gravity', which is not defined"),
    # an output of another shape than declared
    "shape_mismatch": (_HEAD + '''
def f(x):
    return sp.Matrix([x, x])
KERNELS = [Kernel(name="pair", summary="s", formula="y", ids=("x",), sources=(f,),
    args=(Arg("x", (), "any", "x"),), outputs=(Out("y", (3,), "y"),),
    build=lambda x: {"y": f(x)})]
''', "pair", "y: expected (3,), got (2, 1)"),
}


@pytest.mark.parametrize("target", ["c", "package"])
@pytest.mark.parametrize("case", sorted(BAD_MODULES))
def test_generator_errors_are_one_line_exit_2_nothing_written(tmp_path, capsys, case, target):
    from rigidsym.cli import main

    text, kernel, says = BAD_MODULES[case]
    mod = tmp_path / f"{case}.py"
    mod.write_text(text)
    out = tmp_path / "out"
    extra = ["--target", "c"] if target == "c" else ["--no-build"]
    assert main(["generate", *extra, "--module", str(mod), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    assert f"module {case}, kernel {kernel}" in err and says in err, err
    assert not out.exists()


@needs_gcc
def test_a_root_of_a_sign_changing_radicand_generates_and_flags_where_negative(tmp_path):
    """An outside trial's module, 2 sqrt(r^2 - h^2) of arguments of any sign, crashed the
    generator (a complex mpmath reference at a sampled point). It generates, and the C
    returns the chord where the radicand is positive and NONFINITE_RESULT where not."""
    from rigidsym.cli import main

    mod = tmp_path / "chord_mod.py"
    mod.write_text(_HEAD + '''
def chord(r, h):
    return 2 * sp.sqrt(r**2 - h**2)
KERNELS = [Kernel(name="chord", summary="s", formula="c = 2 sqrt(r^2 - h^2)", ids=("x",),
    sources=(chord,), args=(Arg("r", (), "any", "radius"), Arg("h", (), "any", "distance")),
    outputs=(Out("c", (), "chord"),), build=lambda r, h: {"c": chord(r, h)})]
''')
    out = tmp_path / "c"
    assert main(["generate", "--target", "c", "--module", str(mod), "--out", str(out),
                 "--no-measure"]) == 0      # the bounds: tests/test_c_float_measure.py
    so = tmp_path / "libchord.so"
    subprocess.run([GCC, *STRICT, "-O2", "-shared", "-fPIC", *map(str, sorted(out.glob("*.c"))),
                    "-o", str(so), "-lm"], check=True)
    lib_ = ctypes.CDLL(str(so))
    status, (c,) = call(lib_, "rigidsym_c_chord", 5.0, 3.0, ("out", 1))
    assert status == OK and c[0] == 8.0               # 2 sqrt(25 - 9)
    status, (c,) = call(lib_, "rigidsym_c_chord", 1.0, 2.0, ("out", 1))
    assert status & NONFINITE_RESULT and np.isnan(c[0])


@needs_gcc
def test_argument_names_near_the_templates_locals_compile(tmp_path):
    """A kernel whose arguments are named t1 and t2 (and t0, k1, in_t1: the names of the
    rescue's exponents and of the long double rescue's parameters of before) generates C
    that compiles under -Werror, and the rescue of an extreme input (a float argument at
    1e-30, taken by power-of-two scaling, each argument its own exponent) gives status 0 and
    the product."""
    from rigidsym.cli import main

    mod = tmp_path / "clash_mod.py"
    mod.write_text(_HEAD + '''
def triple(t0, t1, t2, k1, in_t1):
    return t0 * k1 * in_t1 * t1.cross(t2)
KERNELS = [Kernel(name="triple", summary="s", formula="y = t0 k1 in_t1 (t1 x t2)",
    ids=("x",), sources=(triple,), args=(Arg("t0", (), "any", "a"),
    Arg("t1", (3,), "any", "b"), Arg("t2", (3,), "any", "c"), Arg("k1", (), "any", "d"),
    Arg("in_t1", (), "any", "e")), outputs=(Out("y", (3,), "y"),),
    build=lambda t0, t1, t2, k1, in_t1: {"y": triple(t0, t1, t2, k1, in_t1)})]
''')
    out = tmp_path / "c"
    assert main(["generate", "--target", "c", "--module", str(mod), "--out", str(out),
                 "--no-measure"]) == 0
    so = tmp_path / "libtriple.so"
    subprocess.run([GCC, *STRICT, "-O2", "-shared", "-fPIC", *map(str, sorted(out.glob("*.c"))),
                    "-o", str(so), "-lm"], check=True)
    lib_ = ctypes.CDLL(str(so))
    b, c = np.array([1.0, 2.0, -0.5]), np.array([0.25, -1.0, 3.0])
    for t0, scale in ((2.0, 1.0), (0.5, 1e-30)):
        xs = [t0, (b * scale).astype(np.float32), c.astype(np.float32), 4.0, 0.5]
        status, (y,) = call(lib_, "rigidsym_c_triple_f32", *xs, ("out", 3), dtype=np.float32)
        want = t0 * 4.0 * 0.5 * np.cross(xs[1].astype(np.float64), c)
        assert status == OK, (scale, status)
        assert np.allclose(y, want, rtol=4e-7, atol=0), (scale, y, want)
    xs = [0.5, b * 1e-300, c, 4.0, 0.5]          # the double rescue (long double on x86-64)
    status, (y,) = call(lib_, "rigidsym_c_triple", *xs, ("out", 3))
    assert status == OK and np.allclose(y, np.cross(b, c) * 1e-300, rtol=1e-15, atol=0)


@pytest.mark.parametrize("names", [("v", "v_0")])
def test_an_argument_name_a_local_would_meet_is_refused_in_one_line(tmp_path, capsys, names):
    """An argument named as another's component (v_0 beside an array v, whose components are
    the program's symbols v_0, v_1, ...) is refused before anything is written: exit 2, one
    line naming the argument. (A fixed local's name or one ending in _ compiles:
    tests/test_c_names.py.)"""
    from rigidsym.cli import main

    a, b = names
    mod = tmp_path / "bad_names.py"
    mod.write_text(_HEAD + f'''
def f({a}, {b}):
    return {a} * {b}
KERNELS = [Kernel(name="scaled", summary="s", formula="y", ids=("x",), sources=(f,),
    args=(Arg("{a}", (3,), "any", "a"), Arg("{b}", (), "any", "b")),
    outputs=(Out("y", (3,), "y"),), build=lambda {a}, {b}: {{"y": f({a}, {b})}})]
''')
    out = tmp_path / "out"
    assert main(["generate", "--target", "c", "--module", str(mod), "--out", str(out),
                 "--no-measure"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and repr(b) in err, err
    assert not out.exists()


def test_division_by_a_vanishing_argument_warns_and_records_the_set(tmp_path, capsys):
    import json

    from rigidsym.cli import main

    mod = tmp_path / "rates.py"
    mod.write_text(_HEAD + '''
def rate(v, r):
    return v / r
def sinc(r):
    return sp.sin(r) / r
KERNELS = [Kernel(name="angular_rate", summary="s", formula="w = v / r", ids=("x",),
    sources=(rate,), args=(Arg("v", (), "any", "speed"), Arg("r", (), "any", "radius")),
    outputs=(Out("w", (), "rate"),), build=lambda v, r: {"w": rate(v, r)}),
    Kernel(name="sinc", summary="s", formula="sin r / r", ids=("x",), sources=(sinc,),
    args=(Arg("r", (), "any", "r"),), outputs=(Out("y", (), "y"),),
    build=lambda r: {"y": sinc(r)})]
''')
    out = tmp_path / "out"
    assert main(["generate", "--module", str(mod), "--out", str(out), "--no-build"]) == 0
    err = capsys.readouterr().err
    warned = [line for line in err.splitlines() if line.startswith("rigidsym: warning:")]
    assert len(warned) == 1 and "kernel angular_rate" in warned[0] and "r = 0" in warned[0]
    meta = {k["name"]: k for k in json.loads((out / "kernels.json").read_text())["kernels"]}
    assert meta["angular_rate"]["singular"] == "r = 0"
    assert meta["angular_rate"]["singular_arg"] == "r"
    assert meta["sinc"]["singular"] == ""      # removable at 0: no warning, no set
    cdir = tmp_path / "c"
    assert main(["generate", "--target", "c", "--module", str(mod), "--out", str(cdir),
                 "--no-measure"]) == 0
    assert "Singular set: r = 0" in (cdir / "rigidsym_c_angular_rate.h").read_text()


@pytest.mark.slow
@needs_gcc
def test_single_header_builds_in_c_and_cpp_and_guards_only_the_implementation(tmp_path):
    """--single-header: one file; the implementing C file stops under -Ofast, an
    application (C++, -Ofast) includes it freely, and the program matches NumPy."""
    from rigidsym.cli import main

    out = tmp_path / "k"
    assert main(["generate", "--target", "c", *EXAMPLE_ARGS, "--single-header", "--out",
                 str(out)]) == 0
    impl = tmp_path / "impl.c"       # included twice, as an outside trial did: once defines
    impl.write_text('#define RIGIDSYM_C_IMPLEMENTATION\n#include "rigidsym_c_single.h"\n'
                    '#include "rigidsym_c_single.h"\n')
    bad = subprocess.run([GCC, *STRICT, "-Ofast", "-I", str(out), "-c", str(impl), "-o",
                          str(tmp_path / "bad.o")], capture_output=True, text=True)
    assert bad.returncode != 0 and "-ffast-math" in bad.stderr
    subprocess.run([GCC, *STRICT, "-O2", "-I", str(out), "-c", str(impl), "-o",
                    str(tmp_path / "impl.o")], check=True)
    main_cpp = tmp_path / "main.c"
    main_cpp.write_text((EXAMPLE / "main.c").read_text().replace('"rigidsym_c.h"',
                                                                '"rigidsym_c_single.h"'))
    exe = tmp_path / "app"
    cxx = shutil.which("g++")
    if cxx is None:
        pytest.skip("g++ is not installed")
    subprocess.run([cxx, "-std=c++11", "-Wall", "-Wextra", "-Werror", "-pedantic", "-Ofast",
                    "-I", str(out), "-x", "c++", str(main_cpp), "-x", "none",
                    str(tmp_path / "impl.o"), "-o", str(exe), "-lm"], check=True)
    assert_matches(run_example(exe), expected())


#: book kernels with branches, removable quotients, compensated products, atan2 and roots
HARD_KERNELS = ["screw_of_displacement", "rotation_vector_from_rotation",
                "exponential_coordinates_left_jacobian", "euler_rodrigues_from_rotation",
                "instant_screw_axis", "natural_invariants_from_rotation"]


@pytest.mark.slow  # generation: about 40 s of CPU
@needs_gcc
def test_hard_book_kernels_equal_the_package_kernels(tmp_path):
    """The C target of kernels with branches, removable quotients and singular sets: the
    double functions give the package's bits at random valid inputs (the same program,
    without FMA), the float ones agree within 16 u of float32 (inputs rounded too), the
    Jacobian twins build, and a pure translation gives phi = 0 and the defaults (status 16)."""
    import json

    from rigidsym import kernels as K
    from rigidsym.cli import main

    assert K.use_backend("c") == "c"  # the package's bits are the C backend's bits
    out = tmp_path / "k"
    args = [a for n in HARD_KERNELS for a in ("--kernel", n)]
    assert main(["generate", "--target", "c", *args, "--out", str(out)]) == 0
    so = tmp_path / "lib.so"
    subprocess.run([GCC, *STRICT, "-Wdouble-promotion", "-O2", "-shared", "-fPIC",
                    *map(str, sorted(out.glob("*.c"))), "-o", str(so), "-lm"], check=True)
    clib = ctypes.CDLL(str(so))
    meta = {k["name"]: k for k in
            json.loads((REPO / "generated" / "kernels.json").read_text())["kernels"]}
    rng = np.random.default_rng(53)

    def value(a):
        shape = tuple(a["shape"])
        if a["kind"] == "rotation":
            e = rng.normal(size=3)
            return np.asarray(K.rotation_from_natural_invariants(e / np.linalg.norm(e),
                                                                 rng.uniform(-3, 3)))
        if a["kind"] == "unit":
            v = rng.normal(size=shape)
            return v / np.linalg.norm(v)
        return float(rng.uniform(-2, 2)) if shape == () else rng.normal(size=shape)

    for name in HARD_KERNELS:
        m = meta[name]
        outs = [("out", max(1, int(np.prod(o["shape"])))) for o in m["outputs"]]
        for _ in range(30):
            xs = [value(a) for a in m["args"]]
            s, got = call(clib, f"rigidsym_c_{name}", *xs, *outs)
            sf, gotf = call(clib, f"rigidsym_c_{name}_f32",
                            *[x if isinstance(x, float) else np.float32(x) for x in xs],
                            *outs, dtype=np.float32)
            want = getattr(K, name)(*xs, check=False)
            want = list(want) if isinstance(want, tuple) else [want]
            assert s == 0 and sf == 0, (name, s, sf)
            for g, gf, w in zip(got, gotf, want, strict=True):
                w = np.ravel(w)
                np.testing.assert_array_equal(g, w)
                assert np.max(np.abs(gf - w)) <= 16 * 2.0**-24 * max(1, np.max(np.abs(w)))
    m = meta["screw_of_displacement"]
    s, got = call(clib, "rigidsym_c_screw_of_displacement", np.eye(3), [1.0, 0, 0],
                  [2.0, 0.5, 0], *[("out", max(1, int(np.prod(o["shape"]))))
                                   for o in m["outputs"]])
    # a pure translation (Q = 1): phi = 0 exactly, the others their documented defaults,
    # status RIGIDSYM_C_DEFAULT_OUTPUT (16) alone (guards against: singular, all NaN)
    assert s == 16
    want = [[1, 0, 0], [0], [0, 0, 0], [0], [1, 0, 0, 0, 0, 0]]
    assert all(np.array_equal(np.ravel(g), w) for g, w in zip(got, want, strict=True))


# -- the float functions' accuracy bound, stated in each header (item 4) --

BOUND = re.compile(r"/\* (\w+) in float arithmetic only.*?Accuracy: each output within "
                   r"([\d.e+-]+) u \(kappa \+ 1\)", re.S)


def stated_bounds(d: Path = KERNELS_DIR) -> dict[str, float]:
    """``{kernel: the float bound its header states}`` over the headers of ``d``."""
    out = {}
    for h in sorted(d.glob("rigidsym_c_*.h")):
        out.update({k: float(b) for k, b in BOUND.findall(h.read_text(encoding="utf-8"))})
    return out


def test_every_float_function_of_the_example_states_its_bound():
    """Each kernel of the example (the book's and the module's, with their twins) states a
    measured bound, none 'not measured', and each within the float32 rule (8 u (kappa+1))."""
    heads = "".join(h.read_text(encoding="utf-8") for h in KERNELS_DIR.glob("rigidsym_c_*.h"))
    names = set(re.findall(r"^RIGIDSYM_C_API int rigidsym_c_(\w+)_f32\($", heads, re.M))
    bounds = stated_bounds()
    assert names and set(bounds) == names, names ^ set(bounds)
    assert "not measured" not in heads
    assert all(0 < b <= 8 for b in bounds.values()), bounds


def test_every_double_function_of_a_book_kernel_states_its_bound():
    """Each double function of the example that is a book kernel (or its twin) states a
    bound, u = 2^-53, at least the package's measured float64 worst for that kernel and
    within docs/accuracy.md's rule (8 u (kappa + 1)); the module's kernels state none."""
    import json

    meta = {k["name"]: k for k in
            json.loads((REPO / "generated" / "kernels.json").read_text())["kernels"]}
    heads = "".join(h.read_text(encoding="utf-8") for h in KERNELS_DIR.glob("rigidsym_c_*.h"))
    blocks = re.split(r"^/\* (\w+):$", heads, flags=re.M)[1:]   # name, its comment, ...
    stated = {}
    for name, text in zip(blocks[::2], blocks[1::2], strict=True):
        b = re.search(r"Accuracy \(double\): each output within ([\d.e+-]+) u \(kappa", text)
        if b:
            stated[name] = b.group(1)
    names = set(blocks[::2])
    book = {n for n in names if n in meta}
    assert book and set(stated) == book, set(stated) ^ book
    for n, b in stated.items():
        assert meta[n]["accuracy"]["float64"]["bound"] <= float(b) <= 8, (n, b)
    assert heads.count("Accuracy (double): no bound stated") == len(names - book)


@pytest.mark.slow  # the harness on every kernel of the example: ~20-60 s on a loaded machine
def test_stated_float_bounds_hold_on_fresh_points(lib):
    """The accuracy harness (benchmarks/accuracy.py: float32 regimes, arb reference,
    condition number) on the float functions of the committed example, with seeds the
    bound was not measured on: the worst err / (u (kappa + 1)) stays within the bound the
    header states (and is not 0: a header stating 0 would fail)."""
    sys.path.insert(0, str(REPO / "benchmarks"))
    import c_float_bounds as CB

    from rigidsym.codegen.usergen import load_user_kernels

    CB.register(load_user_kernels([str(EXAMPLE / "my_kernels.py")])[0])
    run = CB.runner(lib)
    for name, bound in stated_bounds().items():
        measured, rows = CB.worst(run, name, seeds=(11,), n_random=8)
        assert sum(r.samples for r in rows) >= 8, name
        assert 0 < measured <= bound, (name, measured, bound)


# -- the rescue without a wider type: power-of-two rescaling (item 3) --

@pytest.fixture(scope="module")
def lib_narrow(tmp_path_factory):
    """The example's kernels built as on a target whose long double is double
    (-DRIGIDSYM_C_NO_WIDE): the double functions have no wider type, the float ones never."""
    if GCC is None:
        pytest.skip("gcc is not installed")
    so = tmp_path_factory.mktemp("narrow") / "librigidsym_c_narrow.so"
    subprocess.run([GCC, *STRICT, "-O2", "-DRIGIDSYM_C_NO_WIDE", "-shared", "-fPIC",
                    *map(str, sources()), "-o", str(so), "-lm"], check=True)
    return ctypes.CDLL(str(so))


def _reference(name: str, xs: list) -> tuple[np.ndarray, np.ndarray]:
    """(value, sum of the magnitudes of its terms) of three example kernels at the exact
    inputs, in 60-digit mpmath: the rounding of any evaluation is within a few u of the
    second, whatever the scale."""
    import mpmath as mp

    mp.mp.dps = 60
    f = [[mp.mpf(float(v)) for v in np.ravel(x)] for x in xs]
    if name == "body_energy":
        (m,), v, inertia, w = f
        terms = [m * vi * vi / 2 for vi in v] + \
            [w[i] * inertia[3 * i + j] * w[j] / 2 for i in range(3) for j in range(3)]
        return np.array([float(sum(terms))]), np.array([float(sum(map(abs, terms)))])
    if name == "planar_arm_tip":
        (q1,), (q2,), (l1,), (l2,) = f
        terms = [(l1 * mp.cos(q1), l2 * mp.cos(q1 + q2)), (l1 * mp.sin(q1), l2 * mp.sin(q1 + q2))]
        # the sum q1 + q2 is rounded before its cos and sin: that rounding moves the second
        # term by |d/dq of it| |q1 + q2| u, which the terms' magnitudes alone do not cover
        # (seed 555 at 1e-36: 1.95e-43 off, 1.98e-43 from this term alone)
        moved = [abs(l2 * mp.sin(q1 + q2) * (q1 + q2)), abs(l2 * mp.cos(q1 + q2) * (q1 + q2))]
        return (np.array([float(a + b) for a, b in terms]),
                np.array([float(abs(a) + abs(b) + d)
                          for (a, b), d in zip(terms, moved, strict=True)]))
    if name == "newton_euler_wrench":  # [I wd + w x (I w); m cdd] (Newton-Euler, (3.134))
        inertia, (m,), w, wd, cdd = f
        h = [[inertia[3 * k + j] * w[j] for j in range(3)] for k in range(3)]  # I w, termwise
        terms = []
        for i in range(3):
            j, k = (i + 1) % 3, (i + 2) % 3
            terms.append([inertia[3 * i + c] * wd[c] for c in range(3)]
                         + [w[j] * t for t in h[k]] + [-w[k] * t for t in h[j]])
        terms += [[m * cdd[i]] for i in range(3)]
        return (np.array([float(sum(t)) for t in terms]),
                np.array([float(sum(map(abs, t))) for t in terms]))
    t, a, p = f                       # twist_transfer: [omega; v + (a - p) x omega]
    w, v = t[:3], t[3:]
    r = [a[i] - p[i] for i in range(3)]
    cross = [(r[1] * w[2], -r[2] * w[1]), (r[2] * w[0], -r[0] * w[2]),
             (r[0] * w[1], -r[1] * w[0])]
    val = [*w, *(v[i] + c[0] + c[1] for i, c in enumerate(cross))]
    mag = [*map(abs, w), *(abs(v[i]) + abs(c[0]) + abs(c[1]) for i, c in enumerate(cross))]
    return np.array([float(x) for x in val]), np.array([float(x) for x in mag])


#: per kernel: (arguments scaled, degree of the outputs in them, a point of ordinary scale)
RESCUED = {
    "body_energy": lambda r, s: [np.array(abs(r.normal()) * s), r.normal(size=3) * s,
                                 np.diag(abs(r.normal(size=3)) + 0.1).ravel() * s,
                                 r.normal(size=3) * s],
    "planar_arm_tip": lambda r, s: [float(r.uniform(-3, 3)), float(r.uniform(-3, 3)),
                                    float(r.uniform(2, 3) * s), float(r.uniform(0, 1) * s)],
    "twist_transfer": lambda r, s: [r.normal(size=6) * s, r.normal(size=3),
                                    r.normal(size=3)],
}
OUT_SIZE = {"body_energy": 1, "planar_arm_tip": 2, "twist_transfer": 6}


FLOAT_SCALES = [1e-36, 1e-12, 3e9, 1e37]
DOUBLE_SCALES = [1e-300, 1e-200, 1e-40, 1e300]


@settings(max_examples=examples(30), deadline=None)
@given(st.sampled_from(sorted(RESCUED)), st.sampled_from(FLOAT_SCALES),
       st.integers(0, 2**32 - 1))
def test_extreme_float_inputs_are_rescaled(lib, name, scale, seed):
    """The float functions (no wider type on a float-only FPU) at 1e-36 ... 1e37: right
    by power-of-two rescaling (check_rescued)."""
    check_rescued(lib, name, np.float32, scale, seed)


@pytest.mark.slow   # its own build of the example's sources (-DRIGIDSYM_C_NO_WIDE)
@settings(max_examples=30, deadline=None)
@given(st.sampled_from(sorted(RESCUED)), st.sampled_from(DOUBLE_SCALES),
       st.integers(0, 2**32 - 1))
def test_extreme_double_inputs_are_rescaled_without_long_double(lib_narrow, name, scale,
                                                                seed):
    """The double functions where long double is double (Cortex-M, Windows) at 1e-300 ...
    1e300: right by power-of-two rescaling (check_rescued)."""
    check_rescued(lib_narrow, name, np.float64, scale, seed)


# -- an extreme input that no rescue takes: the exception flags decide (item 3) --

#: per kernel: its arguments with the ones it is not homogeneous in scaled (the wrench's
#: angular velocity, the arm's joint angles), the others of ordinary size
FLAGGED = {
    "newton_euler_wrench": lambda r, s: [
        (np.diag(r.uniform(0.01, 0.1, 3)) + 0.002 * r.normal(size=(3, 3))).ravel(),
        float(r.uniform(0.5, 2)), r.normal(size=3) * s, r.normal(size=3), r.normal(size=3)],
    # torque-free: n = omega x I omega alone, so an underflow there is the whole output and
    # a status 0 that hid one would break the bound (the wrench above hides it in I wd)
    "newton_euler_wrench_free": lambda r, s: [
        (np.diag(r.uniform(0.01, 0.1, 3)) + 0.002 * r.normal(size=(3, 3))).ravel(),
        float(r.uniform(0.5, 2)), r.normal(size=3) * s, np.zeros(3), np.zeros(3)],
    "planar_arm_tip": lambda r, s: [float(r.normal() * s), float(r.normal() * s),
                                    float(r.uniform(0.2, 1)), float(r.uniform(0.2, 1))],
}
OUT_SIZE["newton_euler_wrench"] = 6
KERNEL_OF = {"newton_euler_wrench_free": "newton_euler_wrench"}


def flagged_inputs(name: str, dtype, scale: float, seed: int) -> list:
    """FLAGGED's draw in the type (scalars as Python floats holding a value of the type)."""
    rng = np.random.default_rng(seed)
    xs = [np.asarray(x, dtype) if not isinstance(x, float) else float(dtype(x))
          for x in FLAGGED[name](rng, scale)]
    return [x.item() if isinstance(x, np.ndarray) and x.ndim == 0 else x for x in xs]


def judge_flagged(name: str, dtype, xs: list, status: int, got: np.ndarray,
                  must_pass: bool) -> None:
    """An extreme input that no rescue takes: never NaN; status 0 or EXTREME_INPUT; with
    status 0, within 8 u of the sum of the terms' magnitudes (mpmath) of the exact value,
    the bound of an ordinary sample. ``must_pass``: every product of the formula is a normal
    number of the type here, so nothing can underflow and the status must be 0."""
    ref, mag = _reference(name, xs)
    eps = float(np.finfo(dtype).eps)
    assert not np.isnan(got).any(), (status, got)
    assert status in (OK, EXTREME_INPUT), status
    if must_pass:
        assert status == OK, (xs, status)
    if status == OK:
        assert np.all(np.abs(got - ref) <= 8 * eps / 2 * mag), (got, ref, mag)


@settings(max_examples=examples(40), deadline=None)
@given(st.sampled_from(sorted(FLAGGED)), st.sampled_from([1e-12, 1e-15, 1e-20, 1e-30, 1e-41]),
       st.integers(0, 2**32 - 1))
def test_extreme_float_inputs_no_rescue_takes_are_right_or_flagged(lib, name, scale, seed):
    """The issue's case: an angular rate of 1e-12 rad/s in float, where the wrench is not
    homogeneous in omega, so no rescaling takes it. Where no operation underflows (1e-12:
    omega x I omega ~ 1e-26, far above float's 1.2e-38) status 0 and the ordinary bound;
    smaller (products below float's normal range), EXTREME_INPUT or, if status 0, still
    within the bound: the flags never pass a sample that lost accuracy."""
    kernel = KERNEL_OF.get(name, name)
    xs = flagged_inputs(name, np.float32, scale, seed)
    status, (got,) = call(lib, f"rigidsym_c_{kernel}_f32", *xs, ("out", OUT_SIZE[kernel]),
                          dtype=np.float32)
    judge_flagged(kernel, np.float32, xs, status, got, must_pass=scale == 1e-12)


@pytest.mark.slow   # its own build of the example's sources (-DRIGIDSYM_C_NO_WIDE)
@settings(max_examples=30, deadline=None)
@given(st.sampled_from(sorted(FLAGGED)), st.sampled_from([1e-120, 1e-160, 1e-200, 1e-310]),
       st.integers(0, 2**32 - 1))
def test_extreme_double_inputs_no_rescue_takes_without_long_double(lib_narrow, name, scale,
                                                                   seed):
    """The same for the double functions where long double is double (armhf, Cortex-M,
    Windows): omega at 1e-120 passes (products ~1e-240), 1e-160 and below may underflow."""
    kernel = KERNEL_OF.get(name, name)
    xs = flagged_inputs(name, np.float64, scale, seed)
    status, (got,) = call(lib_narrow, f"rigidsym_c_{kernel}", *xs, ("out", OUT_SIZE[kernel]))
    judge_flagged(kernel, np.float64, xs, status, got, must_pass=scale == 1e-120)


_FLAGS_KEPT = r"""#include <fenv.h>
#include <stdio.h>
#include "rigidsym_c.h"
int main(void)
{
    const float I[9] = {0.02f, 0.001f, 0, 0.001f, 0.03f, 0.002f, 0, 0.002f, 0.025f};
    const float wd[3] = {0.1f, 0.5f, -0.2f}, cdd[3] = {0, 0, -9.81f};
    const float w[3] = {1e-12f, -2e-12f, 3e-12f}, tiny[3] = {1e-30f, -2e-30f, 3e-30f};
    const float none[3] = {0, 0, 0};
    float out[6];
    int s1, s2, s3, kept, raised;
    feclearexcept(FE_ALL_EXCEPT);
    feraiseexcept(FE_DIVBYZERO);   /* the caller's own flag, raised before the call */
    s1 = rigidsym_c_newton_euler_wrench_f32(I, 1.5f, w, wd, cdd, out);
    s3 = rigidsym_c_newton_euler_wrench_f32(I, 1.5f, tiny, wd, cdd, out);
    kept = fetestexcept(FE_DIVBYZERO) != 0 && fetestexcept(FE_UNDERFLOW) == 0;
    s2 = rigidsym_c_newton_euler_wrench_f32(I, 1.5f, tiny, none, cdd, out);
    raised = fetestexcept(FE_UNDERFLOW) != 0 && fetestexcept(FE_DIVBYZERO) != 0;
    printf("%d %d %d %d %d\n", s1, s2, kept, raised, s3);
    return 0;
}
"""


@needs_gcc
@pytest.mark.parametrize("predict", [False, True], ids=["default", "predict"])
def test_the_flags_step_keeps_the_callers_flags(tmp_path, objects, predict):
    """The cold path clears the exception flags for its evaluation and gives the caller
    back its own with those raised since: a divide-by-zero raised before the call stays
    raised, an underflow of the call (a torque-free body at omega = 1e-30 in float, whose
    whole wrench is below float's range) shows after it. The status is 0 at 1e-12, 0 at
    1e-30 with an angular acceleration (omega x I omega, 1e-62, is below float's resolution
    of I omega_dot: the double evaluation rounded to float is right, and raises nothing),
    and EXTREME_INPUT (8) for the torque-free body. Where the kernel detects (the default
    on x86-64: the float evaluation first, its flags read after it), that evaluation's
    underflow at 1e-30 is an operation of the call and stays raised (the third value 0);
    with -DRIGIDSYM_C_PREDICT (the range test first) or off x86-64, it is never made."""
    src = tmp_path / "kept.c"
    src.write_text(_FLAGS_KEPT)
    exe = tmp_path / "kept"
    objs = list(objects)
    if predict:
        wrench = KERNELS_DIR / "rigidsym_c_newton_euler_wrench.c"
        obj = tmp_path / "wrench_predict.o"
        subprocess.run([GCC, *STRICT, "-O2", "-DRIGIDSYM_C_PREDICT", "-c", str(wrench),
                        "-o", str(obj)], check=True)
        objs = [str(obj) if Path(o).stem == wrench.stem else o for o in objs]
    subprocess.run([GCC, *STRICT, "-O2", "-I", str(KERNELS_DIR), str(src), *objs,
                    "-o", str(exe), "-lm"], check=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    detects = not predict and platform.machine() in ("x86_64", "AMD64")
    assert out.split() == ["0", "8", "0" if detects else "1", "1", "0"]


def _rodrigues(e: np.ndarray, phi: float) -> np.ndarray:
    """The rotation by phi about the unit axis e, (2.49) in float64 with 1 - cos phi as
    2 sin^2(phi/2) (exact to a few u of float64 at any angle)."""
    E = np.array([[0, -e[2], e[1]], [e[2], 0, -e[0]], [-e[1], e[0], 0]])
    return np.eye(3) + np.sin(phi) * E + 2 * np.sin(phi / 2) ** 2 * (E @ E)


@pytest.mark.parametrize("phi", [1e-16, 1e-18, 1e-20, 1e-25])
def test_float_log_of_a_tiny_rotation_is_status_0_and_right(lib, phi):
    """The float log (natural invariants) of rotations by 1e-16 ... 1e-25 rad about axes
    with components of every sign: the float evaluation's small-angle series raises a
    harmless underflow ((1/6) s_k^2 under float's range, absorbed by 1 +); the double
    evaluation rounded once raises none, so the status is 0, and the angle and axis are
    within float rounding of the rotation's own."""
    rng = np.random.default_rng(83)
    eps = float(np.finfo(np.float32).eps)
    for _ in range(16):
        e = rng.normal(size=3)
        e /= np.linalg.norm(e)
        Q = _rodrigues(e, phi).astype(np.float32)
        status, (ax, ang) = call(lib, "rigidsym_c_natural_invariants_from_rotation_f32", Q,
                                 ("out", 3), ("out", 1), dtype=np.float32)
        assert status == OK, (phi, e)
        # Q's rounding to float moves the angle by up to 2 u of its entries' magnitude
        assert abs(float(ang[0]) - phi) <= 4 * eps * phi, (phi, ang)
        assert np.linalg.norm(ax.astype(np.float64) - e) <= 8 * eps, (phi, ax, e)


EXTREME_AXES = [
    ("rigidsym_c_rotation_from_natural_invariants", np.float64, 2.0**300, 2.0**-400),
    ("rigidsym_c_rotation_from_natural_invariants_f32", np.float32, 2.0**100, 2.0**-100)]


def check_extreme_axis(one, name: str, dtype, big: float, tiny: float, wide: bool) -> None:
    """The axis (0, 0, big) turning by tiny rad, and (0, 0, 1/big) by 1 rad, flagged; the
    unit axis by tiny rad the identity but for Q_12 = -tiny, Q_21 = tiny, status 0 (float
    without a wider type: the flags step flags it, sin^2(tiny/2) underflowing)."""
    s, (Q,) = call(one, name, np.array([0, 0, big]), tiny, ("out", 9), dtype=dtype)
    assert s & EXTREME_INPUT, (s, Q)
    s, (Q,) = call(one, name, np.array([0, 0, 1 / big]), 1.0, ("out", 9), dtype=dtype)
    assert s & EXTREME_INPUT, (s, Q)          # a tiny axis neither
    s, (Q,) = call(one, name, np.array([0, 0, 1.0]), tiny, ("out", 9), dtype=dtype)
    want = np.eye(3)
    want[0, 1], want[1, 0] = -tiny, tiny
    if dtype == np.float64 or wide:
        assert s == OK, s
        assert np.array_equal(Q.astype(np.float64), want.ravel()), Q


@pytest.mark.parametrize("name, dtype, big, tiny", EXTREME_AXES)
def test_an_axis_of_extreme_norm_is_flagged(lib, name, dtype, big, tiny):
    """The axis (0, 0, 2^300) turning by 2^-400 rad (float: 2^100, 2^-100): no unit vector,
    and the formula's value there is no rotation (its Q_33 cancels to 0), so the status has
    EXTREME_INPUT; the unit axis by the same angle is the identity to within the angle,
    status 0."""
    check_extreme_axis(lib, name, dtype, big, tiny, wide=True)


@pytest.mark.slow   # its own build of the example's sources (-DRIGIDSYM_C_NO_WIDE)
@pytest.mark.parametrize("name, dtype, big, tiny", EXTREME_AXES)
def test_an_axis_of_extreme_norm_is_flagged_without_a_wider_type(lib_narrow, name, dtype,
                                                                 big, tiny):
    """The same where no wider type rescues (-DRIGIDSYM_C_NO_WIDE)."""
    check_extreme_axis(lib_narrow, name, dtype, big, tiny, wide=False)


_FLUSH = r"""#include <stdio.h>
#include <string.h>
#include <xmmintrin.h>
#include "rigidsym_c.h"
/* subnormal float twists: the power-of-two rescue takes them (status 0, the exact values:
 * linear, a = p = 0), also where the caller runs with DAZ/FTZ set (an application linked
 * with -Ofast), whose mode is its own again after the call */
int main(void)
{
    const float t[6] = {1e-40f, 2e-40f, -3e-40f, 4e-40f, 5e-40f, -6e-40f}, z[3] = {0, 0, 0};
    float o[6];
    int s, k;
    for (k = 0; k < 2; ++k) {
        if (k)
            _mm_setcsr(_mm_getcsr() | 0x8040);   /* FTZ | DAZ */
        s = rigidsym_c_twist_transfer_f32(t, z, z, o);
        printf("%d %d %d\n", s, memcmp(o, t, sizeof o) == 0,   /* bits: DAZ reads a */
               (_mm_getcsr() & 0x8040) == 0x8040);             /* subnormal as 0 */
    }
    return 0;
}
"""


@needs_gcc
@pytest.mark.skipif(platform.machine() not in ("x86_64", "AMD64"), reason="MXCSR is x86-64's")
def test_a_flush_to_zero_caller_gets_the_values_of_an_ieee_caller(tmp_path, objects):
    """With DAZ set (gcc links crtfastmath.o into any -Ofast program) the float rescue once
    scaled subnormal inputs to zero and returned zeros with status 0 (an outside trial). The
    cold path turns the flush modes off for its run: the rescue is exact, status 0, in both
    modes, and the caller's mode is its own again after the call."""
    src = tmp_path / "flush.c"
    src.write_text(_FLUSH)
    exe = tmp_path / "flush"
    subprocess.run([GCC, *STRICT, "-O2", "-I", str(KERNELS_DIR), str(src), *objects,
                    "-o", str(exe), "-lm"], check=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    assert out.split("\n")[:2] == ["0 1 0", "0 1 1"]      # rescued, exact; the mode kept


def check_rescued(lib_, name, dtype, scale, seed):
    """Inputs of extreme magnitude in the arguments a kernel is homogeneous in (float, and
    double without long double): never NaN; where the exact result is a normal number of
    the type, status 0 (no EXTREME_INPUT left) and within 8 u of the sum of the terms'
    magnitudes (mpmath) of the exact value; where it overflows, NONFINITE_RESULT."""
    xs = rescued_inputs(name, dtype, scale, seed)
    fn = f"rigidsym_c_{name}" + ("_f32" if dtype == np.float32 else "")
    status, (got,) = call(lib_, fn, *xs, ("out", OUT_SIZE[name]), dtype=dtype)
    judge_rescued(name, dtype, xs, status, got)


def rescued_inputs(name: str, dtype, scale: float, seed: int) -> list:
    """The arguments of check_rescued's call: RESCUED's draw in the type (scalars as
    Python floats holding a value of the type)."""
    rng = np.random.default_rng(seed)
    xs = [np.asarray(x, dtype) if not isinstance(x, float) else float(dtype(x))
          for x in RESCUED[name](rng, scale)]
    return [x.item() if isinstance(x, np.ndarray) and x.ndim == 0 else x for x in xs]


def judge_rescued(name: str, dtype, xs: list, status: int, got: np.ndarray) -> None:
    """check_rescued's verdict on one call's status and outputs."""
    ref, mag = _reference(name, xs)
    fi = np.finfo(dtype)
    assert not np.isnan(got).any(), (status, got)
    if np.max(np.abs(ref)) > float(fi.max):
        assert status & NONFINITE_RESULT
        return
    small = 4 * float(fi.tiny)     # a normal result: rescaled, it is rounded once
    if np.max(mag) < small or np.min(mag[mag > 0], initial=np.inf) < small or \
            np.max(mag) > float(fi.max) / 4:
        return          # (partly) subnormal or at the top: no relative bound there
    assert status == OK, status
    assert np.all(np.abs(got - ref) <= 8 * float(fi.eps) / 2 * mag), (got, ref, mag)


@settings(max_examples=examples(20), deadline=None)
@given(st.lists(st.tuples(st.integers(-3, 3).filter(bool), st.integers(0, 3),
                          st.integers(0, 3), st.integers(0, 2)), min_size=1, max_size=4),
       st.booleans())
def test_homogeneity_degree_is_exact(terms, wrap):
    """homogeneous.degree on sums of monomials c x^a y^b z^e (x, y scaled; z fixed), and
    the same under a square root or a sine of z: a degree is claimed exactly when the terms
    share one, and then f(2x, 2y, z) = 2^d f(x, y, z) holds symbolically."""
    import sympy as sp

    from rigidsym.codegen.backends.c.homogeneous import degree

    x, y, z = sp.symbols("x y z", positive=True)
    poly = sp.expand(sum(c * x**a * y**b * z**e for c, a, b, e in terms))
    degs = {a + b for a, b, _ in sp.Poly(poly, x, y, z).monoms()} if poly != 0 else set()
    f = sp.sqrt(poly**2) * sp.sin(z) if wrap else poly
    try:
        d = degree(f, {x, y})
    except ValueError:
        assert len(degs) > 1
        return
    assert len(degs) <= 1
    if d is not None:
        at = {x: sp.Rational(3, 7), y: sp.Rational(-5, 3), z: sp.Rational(2, 9)}
        scaled = f.subs({x: 2 * x, y: 2 * y}, simultaneous=True).subs(at)
        want = (2**d * f).subs(at)
        assert abs(sp.N(scaled - want, 60)) <= 1e-50 * (1 + abs(sp.N(want, 60)))
    with pytest.raises(ValueError):
        degree(sp.sin(x) + f, {x, y})


@pytest.mark.parametrize("formula, recorded", [
    (lambda v, r: v / (r**2 - 1), "r + 1 = 0 or r - 1 = 0"),
    (lambda v, r: v / (v - r), "r - v = 0"),
    (lambda v, r: v / (r**2 + v**2) ** 0.5, "r**2 + v**2 = 0"),
    (lambda v, r: v / (1 + r**2), ""),                     # positive for real r: no set
    (lambda v, r: (r**2 - 1) / (r - 1), ""),               # cancelled: r + 1
])
def test_a_vanishing_divisor_of_the_arguments_is_recorded(formula, recorded):
    """Not only a bare argument (``v / r``): any divisor that can vanish for real arguments
    is recorded (before, ``v / (r**2 - 1)`` went into kernels.json and the C header with an
    empty singular set); one of constant sign is not."""
    import warnings as W

    from rigidsym.codegen.spec import Arg, Kernel, Out
    from rigidsym.codegen.validate import DivisionWarning, validate

    k = Kernel(name="k", summary="s", formula="f", ids=("x",), sources=(),
               args=(Arg("v", (), "any", "v"), Arg("r", (), "any", "r")),
               outputs=(Out("y", (), "y"),), build=lambda v, r: {"y": formula(v, r)})
    with W.catch_warnings(record=True) as got:
        W.simplefilter("always")
        out = validate(k, "m")
    assert out.singular == recorded
    assert bool([w for w in got if issubclass(w.category, DivisionWarning)]) == bool(recorded)


@pytest.mark.skipif(shutil.which("cmake") is None, reason="cmake is not installed")
def test_cmake_without_a_build_type_configures_release_and_says_so(tmp_path):
    """CMake's default build type is empty (the kernels at -O0): the generated project,
    configured on its own with none named, takes Release and says so in one line; one
    named is kept, without the line. (Configured only: no compile.)"""
    said = "no CMAKE_BUILD_TYPE given, building Release"
    for extra, want in (([], "Release"), (["-DCMAKE_BUILD_TYPE=Debug"], "Debug")):
        build = tmp_path / f"b{want}"
        p = subprocess.run(["cmake", "-S", str(KERNELS_DIR), "-B", str(build), *extra],
                           check=True, capture_output=True, text=True)
        cache = (build / "CMakeCache.txt").read_text()
        assert f"CMAKE_BUILD_TYPE:STRING={want}\n" in cache, (want, p.stdout)
        assert (said in p.stdout) == (not extra), p.stdout
