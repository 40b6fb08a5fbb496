"""The stated accuracy bounds hold on points the harness did not use.

Every kernel's docstring says ``error <= B u (kappa + 1)`` per float type, ``B`` the
``bound`` of ``derivations/kernels_accuracy.json`` (measured by ``benchmarks/accuracy.py``
with seed 0 and approach steps ``10**-k``). Here the same judge (the ``arb`` ball reference
of the declared formula, the same condition number) measures again at fresh points: another
seed and approach steps ``3 * 10**-k``, which the harness never sampled. A kernel fails
where its error exceeds ``1.5 B u (kappa + 1)``: a bound that only held on the points that
produced it. The margin is fixed; a bound is corrected only by re-running the harness
(``python benchmarks/accuracy.py --data``), never by widening the margin here.

The quick share (a few kernels, both types, C and NumPy, a handful of points) runs in the
README's command; the ``slow`` share sweeps every kernel of the JSON (the thorough run: a
seeded third, ALWAYS among them).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest

from rigidsym import kernels as K

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))
pytest.importorskip("flint")
import _accuracy_seeds as SEEDS  # noqa: E402
from test_accuracy import available_backends  # noqa: E402  (C and NumPy, or NumPy without a compiler)

from rigidsym.codegen.accuracy import regimes as P  # noqa: E402
from rigidsym.codegen.accuracy.harness import judge as A  # noqa: E402

DATA = json.loads((ROOT / "derivations" / "kernels_accuracy.json").read_text("utf-8"))
MARGIN = 1.5
#: not the harness's seed (0) nor its steps (10**-k): points it never judged
SEED = 37
FRESH64 = [3e-2, 3e-6, 3e-11, 3e-15, 3e-40]
FRESH32 = [3e-2, 3e-5, 3e-8, 3e-17]
#: the quick share: a rotation near pi, a screw near 0 and pi, joint points near each
#: other, a Jacobian kernel and an Euler-angle variant
QUICK = ["screw_of_displacement", "rotation_from_natural_invariants",
         "plucker_from_points", "instant_screw_axis_with_jacobians",
         "euler_angle_rates_zyz_body"]


def _stated(name: str, dtype) -> float:
    """``B`` of the docstring (``accuracy_line``: at least 1) for ``name`` in ``dtype``."""
    return max(DATA[name][np.dtype(dtype).name].get("bound", 0), 1)


def _remeasure(name: str, dtype, n_random: int, small) -> list:
    k = A.R.kernel_of(name)
    rows = []
    for regime, pts in P.regimes(k, dtype, n_random=n_random, seed=SEED,
                                 small=small).items():
        rows += A.judge(name, regime, pts, dtype, available_backends())
    return rows


def _over(name: str, dtype, rows) -> list[str]:
    """Rows whose error, in ``u (kappa + 1)`` (``8 worst_ratio``), exceeds the margin times
    the stated bound, or that flag a sample whose result is finite."""
    b = _stated(name, dtype)
    return [f"{r.kernel} {r.dtype} {r.backend} {r.regime}: {8 * r.worst_ratio:.3g} u "
            f"(kappa + 1) > {MARGIN} x {b:.3g} (err {r.err:.2g}, kappa {r.kappa:.2g}) at "
            f"{r.worst_point}; spurious {r.spurious[:1]}"
            for r in rows if 8 * r.worst_ratio > MARGIN * b or r.spurious]


@pytest.mark.sample
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("name", QUICK)
def test_stated_bound_holds_on_fresh_points(name, dtype):
    rows = _remeasure(name, dtype, n_random=3,
                      small=FRESH32 if dtype == np.float32 else FRESH64)
    assert sum(r.samples for r in rows) >= 5
    assert not _over(name, dtype, rows), "\n".join(_over(name, dtype, rows))


def test_docstrings_state_the_json_bounds():
    """The docstring states the JSON row's bounds (``api_spec.accuracy_line``), and
    ``kernels.accuracy`` returns that row: the three stay in step (``rigidsym generate``
    after a new ``--data`` run; tests/test_generated_fresh.py checks generated/)."""
    for name in K.KERNEL_NAMES:
        assert K.accuracy(name) == DATA[name], name
        doc = " ".join(getattr(K, name).__doc__.split())
        for dt in ("float64", "float32"):
            assert f"<= {_stated(name, dt):.3g} u (kappa + 1) in {dt}" in doc, name


#: open rows: none. The log of SE(3)'s NaN "at inputs 1e-160" was the harness
#: feeding it 4 x 4 matrices that are no transform (now the "transform" argument kind)
_OPEN: dict[str, str] = {}
#: the kernels the every-kernel sweep runs each time: those whose bound once held only on
#: the points that produced it (test_a_plain_rerun_measures_each_kernel_over_its_own_seeds)
#: and the open rows; the thorough run takes a seeded third of the others (all of them in
#: the ``exhaustive`` profile; the seed rotates per commit)
ALWAYS = ("H_matrix", "H_tilde", "L_tilde_dot", *_OPEN)


def _every_kernel(n: str):
    if n in _OPEN:
        return pytest.param(n, marks=pytest.mark.xfail(strict=True, reason=_OPEN[n]))
    return n if n in ALWAYS else pytest.param(n, marks=pytest.mark.thorough(1 / 3))


@pytest.mark.slow
@pytest.mark.parametrize("name", [_every_kernel(n) for n in sorted(DATA)])
def test_stated_bound_holds_on_fresh_points_every_kernel(name):
    bad = []
    for dt, small in ((np.float64, FRESH64), (np.float32, FRESH32)):
        bad += _over(name, dt, _remeasure(name, dt, n_random=4, small=small))
    assert not bad, "\n".join(bad)


def test_a_plain_rerun_measures_each_kernel_over_its_own_seeds():
    """A plain ``benchmarks/accuracy.py --data`` run (``--seeds auto``) measures each kernel
    over the seeds its shipped bound came from, and a ``--kernels`` run keeps the other
    rows: a re-run never lowers a bound to what one seed shows (guards against: the default was
    seed 0 alone, the JSON recorded no seeds, and a ``--kernels H_matrix --data`` run
    overwrote the file with that one row; H_matrix, H_tilde and L_tilde_dot came back at
    1, 1, 1.52 where fresh points need 1.62, 1.62, 2.39)."""
    assert all("seeds" in row and 0 in row["seeds"] for row in DATA.values())
    assert not any(SEED in row["seeds"] for row in DATA.values())     # fresh stays fresh
    for name in ("H_matrix", "H_tilde", "L_tilde_dot"):
        assert set(DATA[name]["seeds"]) >= {0, 1, 2, 3}, name
        assert set(SEEDS.seeds_for(name, DATA)) >= {0, 1, 2, 3}, name
    # a row that records only the default seeds is measured over those; one without a row
    # (a new kernel) too
    assert SEEDS.seeds_for("x", {"x": {"seeds": list(SEEDS.DEFAULT_SEEDS)}}) == SEEDS.DEFAULT_SEEDS
    assert SEEDS.seeds_for("new_kernel", DATA) == SEEDS.DEFAULT_SEEDS
    assert SEEDS.seeds_for("H_matrix", DATA, "5,6") == (5, 6)
    new = {"H_matrix": {**DATA["H_matrix"], "seeds": [0]}}
    both = SEEDS.merged(DATA, new)
    assert both.keys() == DATA.keys() and both["H_tilde"] == DATA["H_tilde"]
    rows = [A.Row("H_matrix", "float64", "numpy", "random", 3, seed=s) for s in (2, 0, 2)]
    assert A.summary(rows)["H_matrix"]["seeds"] == [0, 2]
