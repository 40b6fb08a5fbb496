"""examples/modern_robotics.py verifies as declared, its slips are repaired by the search,
and its kernels compute what scipy computes."""

from __future__ import annotations

import importlib.util
import json
import re
from pathlib import Path

import numpy as np
import pytest

from rigidsym.cli import main
from rigidsym.registry import declarations as registry
from rigidsym.registry import usermodules
from rigidsym.registry.declarations import REGISTRY

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "modern_robotics.py"


@pytest.fixture(autouse=True)
def _forget_user_ids():
    yield
    for k in [k for k in REGISTRY if registry.is_user_id(k)]:
        del REGISTRY[k]
    usermodules.LOADED.clear()


def test_verify_module_gives_the_declared_verdicts_and_repairs_every_slip(tmp_path, capsys):
    """Every verdict as declared, each slip repaired by the search; and the summary line
    counts causes only for the book's ids: a reader's slips are neither errata of the book
    nor slips of its conversion (one verify for both: each was a verify of its own)."""
    out = tmp_path / "mr.json"
    code = main(["verify", "--module", str(EXAMPLE), "--no-cache", "--jobs", "1",
                 "--json", str(out)])
    said = capsys.readouterr()
    assert code == 0  # every verdict as declared
    rows = {r["id"]: r for r in json.loads(out.read_text())["equations"]}
    assert sum(r["verdict"] == "verified" for r in rows.values()) >= 20
    slips = [r for r in rows.values() if r["verdict"] == "does-not-hold"]
    assert len(slips) == 3
    for r in slips:  # no corrected= in the module: the repair search supplies one
        assert r["correction"] == "found by search" and r["repairs"], r["id"]
    text = said.out + said.err
    assert "does-not-hold 3" in text and "errata of the book" not in text, text[-600:]


def test_the_report_shows_every_form_in_book_notation(tmp_path, capsys):
    # no "not shown", no internal name, no ASCII member label
    assert main(["report", "--module", str(EXAMPLE), "--out", str(tmp_path), "--jobs", "1",
                 "--no-cache"]) == 0
    capsys.readouterr()
    page = (tmp_path / "modern_robotics.html").read_text(encoding="utf-8")
    text = re.sub(r"<[^>]+>", " ", page)
    assert "not shown" not in text
    for internal in ("_neg", "[:3", "3:]", "_alt", "Pluecker", "dtheta", "omega"):
        assert internal not in text, internal
    labels = re.findall(r'<span class="label">([^<]*)</span>', page)
    assert all(label.isalpha() for label in labels), labels  # words, never ASCII formulas
    # every equation's printed form is shown as MathML (a user id declares no latex=)
    assert page.count('<p class="meta">As printed:</p>\n<math') == 26


@pytest.mark.slow  # generates both kernels (about 5 s on one core) and imports the NumPy
def test_the_kernels_compute_what_scipy_computes(tmp_path, capsys):
    scipy_linalg = pytest.importorskip("scipy.linalg", reason="scipy is in the [test] extra")
    out = tmp_path / "gen"
    assert main(["generate", "--module", str(EXAMPLE), "--out", str(out), "--no-build"]) == 0
    capsys.readouterr()

    def kernel(name):
        spec = importlib.util.spec_from_file_location(name, out / "numpy" / f"{name}.py")
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        return getattr(mod, name)

    rng = np.random.default_rng(6)
    n = 5
    w = rng.standard_normal((n, 3))
    w /= np.linalg.norm(w, axis=1, keepdims=True)
    v, th = rng.standard_normal((n, 3)), rng.uniform(-3, 3, n)
    T = np.zeros((n, 4, 4))
    assert not kernel("twist_exponential")(w, v, th, T).any()
    p = rng.standard_normal((n, 3))
    Ad = np.zeros((n, 6, 6))
    R = T[:, :3, :3].copy()
    assert not kernel("adjoint_matrix")(R, p, Ad).any()
    for k in range(n):
        S = np.zeros((4, 4))
        S[:3, :3] = [[0, -w[k, 2], w[k, 1]], [w[k, 2], 0, -w[k, 0]], [-w[k, 1], w[k, 0], 0]]
        S[:3, 3] = v[k]
        np.testing.assert_allclose(T[k], scipy_linalg.expm(th[k] * S), atol=1e-12)
        P = np.array([[0, -p[k, 2], p[k, 1]], [p[k, 2], 0, -p[k, 0]], [-p[k, 1], p[k, 0], 0]])
        want = np.block([[R[k], np.zeros((3, 3))], [P @ R[k], R[k]]])  # MR (3.83)
        np.testing.assert_allclose(Ad[k], want, atol=1e-12)


def _mutants_of_the_example():
    """One mutant of each kind of every member of the example's verified identities (the
    mutation test, over the rigid-motion words)."""
    import random

    from rigidsym.checking.deciding.explicit import seed_of, shape_of
    from rigidsym.checking.repairing import mutate
    from rigidsym.registry.declarations import Rel

    usermodules.load(EXAMPLE)
    out = []
    for eq_id in sorted(k for k in REGISTRY if k.startswith("mr:")):
        if REGISTRY[eq_id].expected != "verified":
            continue
        st = REGISTRY[eq_id].build()
        rels = st.printed + st.claims
        pl = mutate.pools(rels, st.model)
        for k, rel in enumerate(rels):
            rng = random.Random(f"2026:{eq_id}:{k}")
            for kind in mutate.MUTATION_KINDS:
                edits = mutate.single_edits(rel, pl, (kind,))
                rng.shuffle(edits)
                for e in edits:
                    try:
                        lhs, rhs = mutate.apply_edits(rel, (e,), "canonical", pl.keep)
                    except ValueError:
                        continue
                    if shape_of(lhs) == shape_of(rhs):
                        out.append((f"{eq_id}: {mutate.describe(e)}",
                                    Rel(lhs, rhs, rel.label), st.model, seed_of(eq_id) + k))
                        break
    return out


@pytest.mark.slow  # every mutant of the example's identities (about 5 s)
def test_mutants_of_the_example_never_hold_where_a_ball_excludes_zero():
    from rigidsym.checking.checker import decide_rel
    from rigidsym.checking.deciding.evidence import numeric_backing
    from rigidsym.zero.decide import Unsupported

    decided = 0
    for words, mutant, model, seed in _mutants_of_the_example():
        try:
            balls = numeric_backing([mutant], model, seed, points=2)
        except (Unsupported, ValueError, ArithmeticError):
            continue
        if balls.excluded is None:
            continue
        out = decide_rel(mutant, model, seed)
        assert out.zero is not True, f"{words}: holds, yet the ball {balls.excluded} excludes 0"
        decided += out.zero is False
    assert decided >= 20
