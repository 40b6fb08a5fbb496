"""The block range test of the generated C (``rigidsym_any_extreme`` in ``c_common.h.j2``) has
two forms: bit arithmetic on x86-64-v2/v3, max/min reductions under AVX-512. Both
must give the verdict of its definition: an input is extreme when it is not finite,
or nonzero with magnitude outside [2^-100, 2^101). Checked here against that definition,
written in Python with floats, over every exponent field, the range's edges, zeros of both
signs, subnormals, inf and NaN, alone and among ordinary values."""

from __future__ import annotations

import math
import random
import shutil
import struct
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
GCC = shutil.which("gcc")
AVX512 = "avx512f" in Path("/proc/cpuinfo").read_text() if Path("/proc/cpuinfo").exists() else False

DRIVER = r"""
#include "rigidsym_common.h"
#include <stdio.h>
#include <stdlib.h>
int main(void)
{
    long n, len;
    if (scanf("%ld", &n) != 1) return 2;
    for (long t = 0; t < n; ++t) {
        if (scanf("%ld", &len) != 1) return 2;
        double v[8];
        for (long j = 0; j < len; ++j) {
            unsigned long long b;
            if (scanf("%llx", &b) != 1) return 2;
            memcpy(v + j, &b, sizeof b);
        }
        putchar(rigidsym_any_extreme(v, len) ? '1' : '0');
    }
    return 0;
}
"""


def extreme(x: float) -> bool:
    """The definition, in floats: not finite, or nonzero outside [2^-100, 2^101)."""
    return not math.isfinite(x) or (x != 0.0 and not 2.0 ** -100 <= abs(x) < 2.0 ** 101)


def _cases() -> list[list[int]]:
    rng = random.Random(67)
    mants = [0, 1, 1 << 51, (1 << 52) - 1, 12345]
    singles = [(s << 63) | (e << 52) | m for e in range(2048) for m in mants for s in (0, 1)]
    one, zero = struct.unpack("<Q", struct.pack("<d", 1.5))[0], 1 << 63
    cases = [[b] for b in singles] + [[one, zero, b] for b in singles[::3]]
    for _ in range(3000):     # mixtures of ordinary values, zeros and edge exponents
        cases.append([(rng.getrandbits(1) << 63) | (rng.choice([0, 922, 923, 1123, 1124, 1000,
                      2047, rng.randrange(2048)]) << 52) | rng.getrandbits(52)
                      for _ in range(rng.randint(1, 8))])
    return cases


@pytest.mark.skipif(GCC is None, reason="gcc is not installed")
@pytest.mark.parametrize("march", ["x86-64-v3", "x86-64-v4"])
def test_both_forms_of_the_range_test_give_the_definitions_verdict(march, tmp_path):
    if march == "x86-64-v4" and not AVX512:
        pytest.skip("this CPU does not run AVX-512")
    src = tmp_path / "drv.c"
    src.write_text(DRIVER)
    exe = tmp_path / "drv"
    r = subprocess.run([GCC, "-O3", "-std=c99", f"-march={march}", "-I",
                        str(ROOT / "generated" / "c"), str(src), "-o", str(exe), "-lm"],
                       capture_output=True, text=True)
    if r.returncode != 0 and "march" in r.stderr:
        pytest.skip(f"gcc does not know -march={march}")
    assert r.returncode == 0, r.stderr
    cases = _cases()
    stdin = f"{len(cases)}\n" + "\n".join(f"{len(c)} " + " ".join(f"{b:x}" for b in c)
                                          for c in cases)
    out = subprocess.run([str(exe)], input=stdin, capture_output=True, text=True, check=True).stdout
    want = "".join("1" if any(extreme(struct.unpack("<d", struct.pack("<Q", b))[0]) for b in c)
                   else "0" for c in cases)
    assert len(out) == len(want)
    wrong = [i for i, (a, b) in enumerate(zip(out, want, strict=True)) if a != b]
    assert not wrong, [(cases[i], out[i]) for i in wrong[:5]]
    assert 0 < want.count("1") < len(want)      # both verdicts occur


BLOCK_DRIVER = r"""
#include "rigidsym_common.h"
#include <stdio.h>
#include <stdlib.h>
int main(void)
{
    long n, len, split;
    if (scanf("%ld", &n) != 1) return 2;
    for (long t = 0; t < n; ++t) {
        if (scanf("%ld %ld", &len, &split) != 2) return 2;
        double v[64];
        for (long j = 0; j < len; ++j) {
            unsigned long long b;
            if (scanf("%llx", &b) != 1) return 2;
            memcpy(v + j, &b, sizeof b);
        }
        rigidsym_extreme_acc s;
        rigidsym_extreme_init(&s);
        rigidsym_extreme_add(&s, v, split);              /* two arrays, as a block adds them */
        rigidsym_extreme_add(&s, v + split, len - split);
        putchar(rigidsym_extreme_any(&s) ? '1' : '0');
    }
    return 0;
}
"""


def _block_cases() -> list[list[int]]:
    """Arrays of 1..40 values (the vector loops, their remainders and the scalar tail), an
    edge value at every position among ordinary values and zeros of both signs."""
    rng = random.Random(670)
    bits = [struct.unpack("<Q", struct.pack("<d", x))[0] for x in
            (0.0, -0.0, 1.5, -3.25, 2.0 ** -100, -(2.0 ** -100), 2.0 ** 101, 5e-324, 1e-35, 1e-300,
             2.2250738585072014e-308, 1e200, math.inf, -math.inf, math.nan)]
    near = [struct.unpack("<Q", struct.pack("<d", x))[0] for x in
            (math.nextafter(2.0 ** -100, 0), math.nextafter(2.0 ** -100, 1),
             math.nextafter(2.0 ** 101, 0), -math.nextafter(2.0 ** 101, 0))]
    edges = bits[4:] + near + [(e << 52) | rng.getrandbits(52) for e in (0, 922, 923, 1123, 1124,
                                                                            2047)]
    ordinary = [struct.unpack("<Q", struct.pack("<d", x))[0] for x in (1.5, -3.25, 0.0, -0.0,
                                                                       7e-20, -4e25)]
    cases = []
    for length in range(1, 41):
        cases.append([rng.choice(ordinary) for _ in range(length)])
        for e in edges:
            for pos in {0, length - 1, rng.randrange(length)}:
                c = [rng.choice(ordinary) for _ in range(length)]
                c[pos] = e | (rng.getrandbits(1) << 63)
                cases.append(c)
    return cases


@pytest.mark.skipif(GCC is None, reason="gcc is not installed")
@pytest.mark.parametrize("march", ["x86-64-v2", "x86-64-v3"])
def test_the_blocks_range_test_flags_every_extreme_value(march, tmp_path):
    """The block's test over several arrays (rigidsym_extreme_add, one reduction) answers
    nonzero whenever a value is extreme (the block then re-tests each sample exactly), and
    zero when none is and none has magnitude exactly 2^-100, the one value its AVX2 form also
    admits."""
    src = tmp_path / "drv.c"
    src.write_text(BLOCK_DRIVER)
    exe = tmp_path / "drv"
    r = subprocess.run([GCC, "-O3", "-std=c99", f"-march={march}", "-I",
                        str(ROOT / "generated" / "c"), str(src), "-o", str(exe), "-lm"],
                       capture_output=True, text=True)
    if r.returncode != 0 and "march" in r.stderr:
        pytest.skip(f"gcc does not know -march={march}")
    assert r.returncode == 0, r.stderr
    rng = random.Random(671)
    cases = _block_cases()
    splits = [rng.randrange(len(c) + 1) for c in cases]
    stdin = f"{len(cases)}\n" + "\n".join(f"{len(c)} {s} " + " ".join(f"{b:x}" for b in c)
                                          for c, s in zip(cases, splits, strict=True))
    out = subprocess.run([str(exe)], input=stdin, capture_output=True, text=True, check=True).stdout
    assert len(out) == len(cases)
    for c, got in zip(cases, out, strict=True):
        xs = [struct.unpack("<d", struct.pack("<Q", b))[0] for b in c]
        if any(extreme(x) for x in xs):
            assert got == "1", c
        elif all(abs(x) != 2.0 ** -100 for x in xs):
            assert got == "0", c
