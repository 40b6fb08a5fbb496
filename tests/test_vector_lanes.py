"""The float64 lanes across samples (``RIGIDSYM_VEC_F64``, the kernels of ``VEC_F64``): on
x86-64-v3 (and on x86-64-v4 for those of ``VEC_F64_V4``) their lanes function transposes 4
samples' inputs to columns, runs the sample's arithmetic on vector types and feeds the block's
range filter from the columns; elsewhere the row-major scalar loop runs. Both must give every
sample the same bits and the same flag.

Checked by compiling each such kernel's generated C twice for x86-64-v3, as it is (the
vector lanes) and with ``-DRIGIDSYM_NO_VEC_F64`` (the scalar sample function in the row-major
loop, another code path; the same sin/cos code, which differs between build paths), with the
kernels' flags (and, on an AVX-512 CPU, twice for x86-64-v4: the lanes for the kernels of
``VEC_F64_V4``, the row-major loop for the others), and comparing outputs byte for byte and
the flagged counts over batches of many sizes, with extreme, zero, subnormal and non-finite
values at random positions; and the transposes alone against their definition for every row
width 1-9."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from rigidsym.codegen.backends.extension.target import VEC_F64, VEC_F64_V4
from rigidsym.kernels.cbuild.flags import KERNEL_FLAGS

ROOT = Path(__file__).resolve().parents[1]
CDIR = ROOT / "generated" / "c"
GCC = shutil.which("gcc")
_CPU = Path("/proc/cpuinfo").read_text() if Path("/proc/cpuinfo").exists() else ""
AVX2 = " avx2" in _CPU and " fma" in _CPU and " bmi2" in _CPU
AVX512 = AVX2 and all(f" {f}" in _CPU for f in ("avx512f", "avx512bw", "avx512cd",
                                                 "avx512dq", "avx512vl"))
META = {k["name"]: k for k in json.loads((ROOT / "generated" / "kernels.json").read_text())
        ["kernels"]}
pytestmark = pytest.mark.skipif(GCC is None or not AVX2,
                                reason="needs gcc and a CPU with AVX2 (x86-64-v3)")

SIZES = (1, 3, 4, 5, 7, 8, 9, 63, 64, 65, 129, 1000)
EDGES = [0.0, -0.0, 1e-35, 1e-300, 5e-324, 2.0 ** -100, float(np.nextafter(2.0 ** -100, 0)),
         -(2.0 ** -100), 2.0 ** 101, float(np.nextafter(2.0 ** 101, 0)), -(2.0 ** 101), 1e200,
         float("inf"), -float("inf"), float("nan"), 2.2250738585072014e-308]


def _size(shape) -> int:
    return int(np.prod(shape, dtype=np.int64))


def _driver(name: str) -> str:
    """C that includes the kernel's source and runs its batch function on the samples of a
    binary file: per batch size n, the inputs, then it writes the outputs and the count."""
    m = META[name]
    ins, outs = [_size(a["shape"]) for a in m["args"]], [_size(o["shape"]) for o in m["outputs"]]
    decl = "".join(f"    double *i{j} = malloc(8 * {w} * n + 8); fread(i{j}, 8, {w} * n, f);\n"
                   for j, w in enumerate(ins))
    decl += "".join(f"    double *o{j} = malloc(8 * {w} * n + 8);\n" for j, w in enumerate(outs))
    args = ", ".join([f"i{j}" for j in range(len(ins))] + [f"o{j}" for j in range(len(outs))])
    write = "".join(f"    fwrite(o{j}, 8, {w} * n, g);\n" for j, w in enumerate(outs))
    free = "".join(f"    free(i{j});\n" for j in range(len(ins)))
    free += "".join(f"    free(o{j});\n" for j in range(len(outs)))
    return f"""#include <stdio.h>
#include <stdlib.h>
#include "{name}.c"
int main(int argc, char **argv)
{{
    FILE *f = fopen(argv[1], "rb"), *g = fopen(argv[2], "wb");
    long long n;
    printf("%d\\n", RIGIDSYM_VEC_F64);
    while (fread(&n, 8, 1, f) == 1) {{
{decl}    long long count = rigidsym_{name}_threads(n, 1, {args});
{write}    fwrite(&count, 8, 1, g);
{free}    }}
    fclose(f);
    fclose(g);
    return 0;
}}
"""


def _build(src: Path, march: str, tmp: Path, *defines: str) -> Path:
    exe = tmp / f"{src.stem}_{march}{''.join(defines)}"
    r = subprocess.run([GCC, *KERNEL_FLAGS, f"-march={march}", *defines, "-I", str(CDIR),
                        str(src), "-o", str(exe), "-lm"], capture_output=True, text=True)
    if r.returncode != 0 and "march" in r.stderr:
        pytest.skip(f"gcc does not know -march={march}")
    assert r.returncode == 0, r.stderr
    return exe


#: the extreme values alone (an extreme value in one array of a block must trip its filter)
EXTREME = [x for x in EDGES if x != x or (x != 0.0 and not 2.0 ** -100 <= abs(x) < 2.0 ** 101)]


def _kinds(name: str) -> list:
    """The batches' kinds: ordinary values; edge values in every array; rows of zeros in the
    first array (a singular sample where a kernel divides by its norm); one extreme value in
    one array only (each array in turn), the others ordinary."""
    return ["ordinary", "edges", "zero rows", *range(len(META[name]["args"]))]


def _batches(name: str, seed: int) -> bytes:
    rng = np.random.default_rng(seed)
    chunks = []
    for n in SIZES:
        for kind in _kinds(name):
            chunks.append(np.int64(n).tobytes())
            for i, a in enumerate(META[name]["args"]):
                x = rng.standard_normal((n, _size(a["shape"])))
                x *= 10.0 ** rng.integers(-3, 4, x.shape)
                flat = x.reshape(-1)
                if kind == "edges":
                    pos = rng.integers(0, flat.size, max(1, flat.size // 20))
                    flat[pos] = rng.choice(EDGES, pos.size)
                elif kind == "zero rows" and i == 0:
                    x[rng.random(n) < 0.1] = 0.0
                elif kind == i:
                    flat[rng.integers(0, flat.size)] = rng.choice(EXTREME)
                chunks.append(np.ascontiguousarray(x).tobytes())
    return b"".join(chunks)


#: the default run's kernels: every construct of the vector text once at least (the 4 x 4,
#: 3-wide and 1-wide transposes, a lane select, a square root, the compensated products of
#: 3 and 4 pairs and the difference of products, singular masks, sin/cos columns), K2, K4, K6;
#: the others of VEC_F64 in the slow run. The quick run builds a seeded 0.3 of them; the
#: thorough run builds the rest of them and a seeded third of the others (``thorough``, on
#: the others alone), so every construct is built each run and every kernel over a few
#: commits (all of them in the ``exhaustive`` profile)
DEFAULT = ("newton_euler_residual", "instant_screw_point_pitch", "rotation_from_natural_invariants",
           "plucker_from_points", "screw_axis_point", "instant_screw_axis", "N_matrix")


@pytest.mark.sample(fraction=0.3)
@pytest.mark.parametrize("name", [
    n if n in DEFAULT else pytest.param(n, marks=[pytest.mark.slow, pytest.mark.thorough(1 / 3)])
    for n in sorted(VEC_F64)])
def test_vector_lanes_give_the_scalar_samples_bits_and_flags(name, tmp_path):
    src = tmp_path / f"drv_{name}.c"
    src.write_text(_driver(name))
    inp = tmp_path / "in.bin"
    inp.write_bytes(_batches(name, seed=sum(map(ord, name))))
    results = {}
    for defines, vec in (((), "1"), (("-DRIGIDSYM_NO_VEC_F64",), "0")):
        exe = _build(src, "x86-64-v3", tmp_path, *defines)
        out = tmp_path / f"out_{vec}.bin"
        r = subprocess.run([str(exe), str(inp), str(out)], capture_output=True, text=True,
                           check=True)
        assert r.stdout.split() == [vec]         # which lanes ran
        results[vec] = out.read_bytes()
    v3, scalar = results["1"], results["0"]
    assert len(v3) == len(scalar) > 0
    assert v3 == scalar
    if AVX512:      # x86-64-v4: the lanes where VEC_F64_V4 lists the kernel, the same bits
        v4 = {}
        for defines, vec in (((), "1" if name in VEC_F64_V4 else "0"),
                             (("-DRIGIDSYM_NO_VEC_F64",), "0")):
            exe = _build(src, "x86-64-v4", tmp_path, *defines)
            out = tmp_path / f"out_v4{''.join(defines)}.bin"
            r = subprocess.run([str(exe), str(inp), str(out)], capture_output=True,
                               text=True, check=True)
            assert r.stdout.split() == [vec]
            v4[defines] = out.read_bytes()
        assert v4[()] == v4[("-DRIGIDSYM_NO_VEC_F64",)]
    # counts (the 8 bytes after each batch's outputs): none of ordinary values, the one
    # sample of a lone extreme value, some of the edge batches
    per = 8 * sum(_size(o["shape"]) for o in META[name]["outputs"])
    off = 0
    for n in SIZES:
        for kind in _kinds(name):
            off += per * n
            count = int(np.frombuffer(v3[off:off + 8], np.int64)[0])
            off += 8
            assert count == {"ordinary": 0, "edges": count, "zero rows": count}.get(kind, 1), \
                (n, kind)
            if kind == "edges" and n >= 64:
                assert count > 0
            if kind == "zero rows" and n >= 64 and name == "instant_screw_point_pitch":
                assert count > 0          # omega = 0: no instant screw axis


TRANSPOSE_DRIVER = r"""
#include "rigidsym_common.h"
#include <stdio.h>
int main(void)
{
    int bad = 0;
    for (int w = 1; w <= 9; ++w) {
        double p[4 * 9 + 2], q[4 * 9 + 2];
        __m256d c[9];
        for (int i = 0; i < 4 * w + 2; ++i) {
            p[i] = 1.0 + i;
            q[i] = -1.0;
        }
        rigidsym_load_cols(p, w, c);
        for (int col = 0; col < w; ++col) {
            double v[4];
            _mm256_storeu_pd(v, c[col]);
            for (int s = 0; s < 4; ++s)
                bad |= v[s] != p[s * w + col];
        }
        rigidsym_store_cols(q, w, c);
        for (int i = 0; i < 4 * w; ++i)
            bad |= q[i] != p[i];
        bad |= q[4 * w] != -1.0 || q[4 * w + 1] != -1.0;   /* nothing written past the rows */
        printf("%d", bad);
    }
    return 0;
}
"""


def test_the_transposes_match_their_definition_for_every_width(tmp_path):
    """rigidsym_load_cols gives column q of sample s as the row-major value s * w + q, and
    rigidsym_store_cols writes exactly the 4 w values back (widths 1-9: the 4 x 4 tiles, the
    3-wide and 2-wide shuffles, and the remainders of 1, 2 and 3 columns)."""
    src = tmp_path / "tr.c"
    src.write_text(TRANSPOSE_DRIVER)
    exe = _build(src, "x86-64-v3", tmp_path)
    out = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout
    assert out == "0" * 9
