"""``rigidsym generate --target c --module M.py`` measures the module's float bounds itself
(:mod:`rigidsym.codegen.accuracy.float_measure`): its headers state a
measured bound, not "not measured", with no script of the repository; ``--no-measure``
leaves them unmeasured."""

from __future__ import annotations

import math
import re
import shutil

import pytest

from rigidsym.codegen.accuracy.float_measure import stated

needs_cc = pytest.mark.skipif(shutil.which("gcc") is None and shutil.which("cc") is None,
                              reason="no C compiler")

MODULE = '''import sympy as sp
from rigidsym.codegen.spec import Arg, Kernel, Out


def moment(r, f):
    return r.cross(f)


KERNELS = [Kernel(name="lever_moment", summary="s", formula="m = r x f", ids=("x",),
    sources=(moment,), args=(Arg("r", (3,), "any", "lever arm"), Arg("f", (3,), "any",
    "force")), outputs=(Out("m", (3,), "moment"),), build=lambda r, f: {"m": moment(r, f)})]
'''
BOUND = re.compile(r"Accuracy: each output within ([0-9.e+]+) u \(kappa \+ 1\)")


def _generate(tmp_path, *extra):
    from rigidsym.cli import main

    mod = tmp_path / "moment_mod.py"
    mod.write_text(MODULE)
    out = tmp_path / "c"
    assert main(["generate", "--target", "c", "--module", str(mod), "--out", str(out),
                 *extra]) == 0
    return (out / "rigidsym_c_lever_moment.h").read_text()


@needs_cc
def test_a_user_module_gets_measured_float_bounds(tmp_path, capsys):
    """No ``moment_mod.float_bounds.json`` beside the module: the header states a bound the
    generation measured for the kernel and its Jacobian twin (the float32 rule of
    docs/accuracy.md allows 8; a cross product rounds twice), and the run says what it measured."""
    head = _generate(tmp_path)
    assert "not measured" not in head
    bounds = [float(b) for b in BOUND.findall(head)]
    assert len(bounds) == 2 and all(1 <= b <= 8 for b in bounds), bounds
    assert "measured the float bounds of 2 functions" in capsys.readouterr().err


@needs_cc
def test_no_measure_leaves_the_bounds_unmeasured(tmp_path):
    head = _generate(tmp_path, "--no-measure")
    assert "Accuracy: not measured" in head and not BOUND.search(head)


def test_no_measure_is_refused_without_the_c_target(tmp_path, capsys):
    from rigidsym.cli import main

    assert main(["generate", "--no-measure", "--out", str(tmp_path)]) == 2
    assert "--no-measure: only with --target c or cpp" in capsys.readouterr().err


@pytest.mark.parametrize("measured", [0.0, 0.3, 0.5, 0.51, 0.74, 0.76, 1.06, 2.4, 4.63, 6.2e6])
def test_the_stated_bound_is_twice_the_measured_rounded_up_to_a_round_number(measured):
    """At least twice the measured worst and 1; a 1, 1.5, 2, 3 or 5 times a power of ten;
    and the smallest such (the next smaller round number is below twice the worst)."""
    b = stated(measured)
    want = max(1.0, 2 * measured)
    assert b >= want * (1 - 1e-12)
    e = math.floor(math.log10(b) + 1e-12)
    mant = b / 10.0**e
    assert any(math.isclose(mant, m) for m in (1.0, 1.5, 2.0, 3.0, 5.0)), b
    rounds = sorted(m * 10.0**k for k in range(e - 1, e + 1) for m in (1, 1.5, 2, 3, 5))
    below = [r for r in rounds if r < b * (1 - 1e-12)]
    assert not below or below[-1] < want * (1 - 1e-12), (b, below[-1])
