"""CLI contract: exit codes, JSON schema, mutations flip the verdict loudly."""

from __future__ import annotations

import dataclasses
import json

import pytest
import sympy as sp

from rigidsym.cli import main
from rigidsym.registry import declarations as registry
from rigidsym.registry.declarations import REGISTRY, Rel, load_all

load_all()


def test_verify_exits_0_and_writes_schema_2(tmp_path, capsys):
    out = tmp_path / "v.json"
    assert main(["verify", "3.1", "thm3.2.1", "--json", str(out), "--quiet", "--jobs", "1"]) == 0
    doc = json.loads(out.read_text())
    assert doc["schema"] == 2
    row = doc["equations"][0]
    for key in ("id", "title", "kind", "verdict", "expected", "method", "printed_latex",
                "members", "model", "failing_member", "counterexample", "cause",
                "cause_class", "numeric", "seconds"):
        assert key in row
    assert set(row["numeric"]) >= {"points", "digits", "max_residual", "seed"}
    assert sum(doc["summary"].values()) == 2


@pytest.mark.parametrize("argv", [["verify", "3.999"], ["verify", "x.1"],
                                  ["verify", "--section", "3.1"], ["verify", "--section", "3.9"],
                                  ["verify", "--section", "4.2"], ["show", "3.0"],
                                  ["frobnicate"]])
def test_bad_input_exits_2_with_one_line(argv, capsys):
    with pytest.raises(SystemExit) as exc:
        raise SystemExit(main(argv))
    assert exc.value.code == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("rigidsym: error:") and "\n" not in err


def _mutate(monkeypatch, eq_id, change):
    eq = REGISTRY[eq_id]
    orig = eq.build_fn

    def build():
        return change(orig())

    monkeypatch.setitem(REGISTRY, eq_id, dataclasses.replace(eq, build_fn=build))
    registry._build.cache_clear()


def _flip_sign(st):
    """Negate the printed right side; where it is zero (a characterising condition such as
    e^T p0 = 0), shift the printed left side instead, so the mutation always changes it."""
    r = st.printed[0]
    if sp.sympify(r.rhs).is_zero if not hasattr(r.rhs, "shape") else \
            isinstance(r.rhs, sp.ZeroMatrix) or r.rhs == sp.zeros(*r.rhs.shape):
        shift = sp.ones(*r.lhs.shape) if hasattr(r.lhs, "shape") else 1
        return dataclasses.replace(st, printed=[Rel(r.lhs + shift, r.rhs, r.label)]
                                   + st.printed[1:])
    return dataclasses.replace(st, printed=[Rel(r.lhs, -r.rhs, r.label)] + st.printed[1:])


MUTABLE = [i for i in ("3.1", "3.2", "3.13", "3.16", "3.18", "3.29a", "thm3.2.1")
           if i in REGISTRY]


@pytest.mark.sample(fraction=0.3)
@pytest.mark.parametrize("eq_id", MUTABLE)
def test_a_sign_change_in_a_printed_form_exits_1(eq_id, monkeypatch, capsys):
    _mutate(monkeypatch, eq_id, _flip_sign)
    try:
        assert main(["verify", eq_id, "--quiet", "--jobs", "1"]) == 1
        assert f"MISMATCH ({eq_id})" in capsys.readouterr().out
    finally:
        registry._build.cache_clear()


@pytest.mark.sample(fraction=0.3)
@pytest.mark.parametrize("eq_id", MUTABLE)
def test_a_changed_derivation_exits_1(eq_id, monkeypatch, capsys):
    def perturb(st):
        # double the first-principles value of one model symbol the printed form uses
        used = set().union(*(sp.sympify(r.rhs).free_symbols | sp.sympify(r.lhs).free_symbols
                             for r in st.printed))
        key = next(k for k in sorted(st.model, key=str) if k in used and k.shape != (3, 3))
        model = dict(st.model)
        model[key] = 2 * model[key] + sp.ones(*model[key].shape)
        return dataclasses.replace(st, model=model)

    _mutate(monkeypatch, eq_id, perturb)
    try:
        assert main(["verify", eq_id, "--quiet", "--jobs", "1"]) == 1
    finally:
        registry._build.cache_clear()


def test_an_exception_in_a_declaration_is_undecided_not_a_crash(monkeypatch, capsys):
    def boom(st):
        raise RecursionError("maximum recursion depth exceeded")

    _mutate(monkeypatch, "3.1", boom)
    try:
        assert main(["verify", "3.1", "3.2", "--quiet", "--jobs", "1"]) == 1
        out = capsys.readouterr().out
        assert "MISMATCH (3.1): computed undecided" in out and "RecursionError" in out
        assert "MISMATCH (3.2)" not in out
    finally:
        registry._build.cache_clear()

