"""A property of the repair search: a verified identity with one random edit,
drawn from kinds whose inverse is in the vocabulary, is repaired when it stops holding, and
every repair reported is decided to hold (again, with another seed)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from _profile import examples
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rigidsym.checking.checker import decide_rel
from rigidsym.checking.repairing import mutate, repair
from rigidsym.registry import usermodules
from rigidsym.registry.declarations import REGISTRY, Rel

ROOT = Path(__file__).resolve().parents[1]
SLIPS = ROOT / "tests" / "data" / "repair_slips.py"
#: kinds whose inverse the vocabulary has (a coefficient only to itself +- 1, a symbol only
#: one the model keeps, a transpose dropped only from a symbol)
INVERTIBLE = ("flip-sign", "transpose", "drop-transpose", "swap-factors", "sin-cos",
              "coefficient", "replace-symbol")


def _invertible(e: mutate.Edit, model: dict) -> bool:
    w = e.what
    if w[0] == "coef":
        return abs(w[2] - w[1]) == 1
    if w[0] == "replace":
        return w[1] in model
    if w[0] == "untranspose":
        return w[1].arg.is_symbol
    return True


@pytest.fixture(scope="module")
def identities():
    """The corrected (true) forms of the rotation slips: ``(rels, model)``."""
    um = usermodules.load(SLIPS)
    kinds = sys.modules[um.name].KIND
    out = []
    for eq_id in sorted(kinds):
        st_ = REGISTRY[eq_id].build()
        if "R" not in {str(k) for k in st_.model}:  # the rigid motions' full tests are slow
            out.append((list(st_.corrected), st_.model))
    yield out
    for k in [k for k in REGISTRY if k.startswith("slip:")]:
        del REGISTRY[k]


@settings(max_examples=examples(12), deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.function_scoped_fixture,
                                 HealthCheck.too_slow])
@given(data=st.data())
def test_a_one_edit_mutant_is_repaired(identities, data):
    rels, model = data.draw(st.sampled_from(identities))
    k = data.draw(st.integers(0, len(rels) - 1))
    rel = rels[k]
    assert decide_rel(rel, model, 1).zero is True
    muts = [(e, m) for e, m in mutate.mutants(rel, rels, model, INVERTIBLE)
            if _invertible(e, model)]
    if not muts:
        return
    edit, (lhs, rhs) = data.draw(st.sampled_from(muts))
    mutant = Rel(lhs, rhs, rel.label)
    if decide_rel(mutant, model, 2).zero is not False:
        return  # the edit did not break it (a sign flipped on a vanishing term)
    others = rels[:k] + [mutant] + rels[k + 1:]
    sh = repair.share([mutant], others, model, decide_rel, 3)
    found = repair.search_member(mutant, sh).found
    assert found, f"no repair of the mutant ({mutate.describe(edit)})"
    for f in found:
        assert decide_rel(f.rel, model, 4).zero is True
