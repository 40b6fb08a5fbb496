"""The C blocks' floating-point exception flags: a non-finite output of
finite inputs of ordinary magnitude is caught by the flags its arithmetic raised, which stand
for the finiteness pass over a block's outputs. A reader's kernel whose powers overflow from
inputs inside the range test's [2^-100, 2^101) is the case no package kernel has (their
products of inputs stay finite there): were the flags not read, or read before the lanes
function's arithmetic, the inf would come back silently. (A separate pass would catch it,
so this test guards the flags; it does not fail there.)"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from rigidsym.kernels.cbuild import driver as _build

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(_build.compiler() is None, reason="no C compiler")]

POWERS = '''
from rigidsym.codegen.spec import Arg, Kernel, Out


def twelfth(v, s):
    return v * s**12


KERNELS = [Kernel(
    name="twelfth", summary="A vector times the twelfth power of a scalar.",
    formula="w = s^12 v", ids=("t:twelfth",), sources=(twelfth,),
    args=(Arg("v", (3,), "any", "a vector"), Arg("s", (), "any", "a factor")),
    outputs=(Out("w", (3,), "s^12 v"),), build=lambda v, s: {"w": twelfth(v, s)})]
'''

CALL = """
    import json
    import numpy as np
    from rigidsym import kernels
    k = kernels.load({d!r})
    assert k._SPACE.backend() == "c", k._SPACE.backend()
    res = {{}}
    for dtype, big in ((np.float64, 2.0**100), (np.float32, 2.0**20)):
        n = 200                                  # several blocks, the bad rows inside them
        v = np.linspace(0.5, 1.5, 3 * n).reshape(n, 3).astype(dtype)
        s = np.linspace(0.9, 1.1, n).astype(dtype)
        bad = [3, 64, 130]
        s[bad] = big                             # in range; s**12 overflows the type
        try:
            k.twelfth(v, s)
            raised = None
        except kernels.NonFiniteResultError as exc:
            raised = str(exc)
        w = k.twelfth(v, s, on_singular="nan")
        alone = np.array([k.twelfth(v[i], s[i], on_singular="nan") for i in range(n)])
        res[np.dtype(dtype).name] = {{
            "raised": raised, "nan_rows": np.flatnonzero(np.isnan(w).any(1)).tolist(),
            "same_alone": bool(np.array_equal(w, alone, equal_nan=True)),
            "ok_rows_exact": bool(np.allclose(   # s**12 by the kernel's own products
                np.delete(w, bad, 0), np.delete(v * s[:, None]**12, bad, 0), rtol=1e-5
                if dtype == np.float32 else 1e-14, atol=0))}}
    print(json.dumps(res))
"""


def test_an_overflow_from_inputs_of_ordinary_magnitude_is_flagged(tmp_path: Path):
    (tmp_path / "powers.py").write_text(POWERS)
    out = tmp_path / "kernels"
    env = {**os.environ, "RIGIDSYM_CACHE": str(tmp_path / "cache")}
    p = subprocess.run([sys.executable, "-m", "rigidsym", "generate", "--module", "powers.py",
                        "--out", str(out), "--no-build"], cwd=tmp_path, env=env,
                       capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stdout + p.stderr
    p = subprocess.run([sys.executable, "-c", textwrap.dedent(CALL.format(d=str(out)))],
                       cwd=tmp_path, env=env, capture_output=True, text=True, timeout=900)
    assert p.returncode == 0, p.stdout + p.stderr
    res = json.loads(p.stdout.strip().splitlines()[-1])
    for dtype, r in res.items():
        assert r["raised"] is not None and "(3,)" in r["raised"], (dtype, r)
        assert r["nan_rows"] == [3, 64, 130], (dtype, r)
        assert r["same_alone"] and r["ok_rows_exact"], (dtype, r)
