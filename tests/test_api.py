"""The public Python API: check, verify, Result/Results, display, the exported names."""

from __future__ import annotations

import pytest

import rigidsym
from rigidsym.registry.declarations import REGISTRY, VERDICTS, BadInput, load_all

pytestmark = pytest.mark.xdist_group("api")  # its module fixtures built on one worker

load_all()


@pytest.fixture(scope="module")
def r316():
    return rigidsym.check("3.16")


@pytest.fixture(scope="module")
def section33():
    return rigidsym.verify(sections=["3.3"], jobs=2)


def test_check_computes_the_recorded_verdicts():
    r = rigidsym.check("3.96e")
    assert isinstance(r, rigidsym.Result)
    assert r.verdict == "does-not-hold" == REGISTRY["3.96e"].expected
    assert r.counterexample and r.corrected


def test_verify_a_section_summary_counts_every_id(section33):
    ids = [k for k, eq in REGISTRY.items() if eq.section.split(".")[:2] == ["3", "3"]]
    assert sorted(r.id for r in section33) == sorted(ids)
    s = section33.summary()
    assert list(s) == list(VERDICTS) and sum(s.values()) == len(ids)
    expected = {v: sum(REGISTRY[i].expected == v for i in ids) for v in VERDICTS}
    assert s == expected


def test_results_where_index_and_json(section33):
    defs = section33.where(verdict="definition")
    assert all(r.verdict == "definition" for r in defs)
    # an identity by definition (3.41, 3.42) is of kind identity with verdict definition
    assert len(section33.where(kind="definition")) + len(section33.where(kind="identity")) + \
        len(section33.where(kind="claim")) == len(section33)
    assert all(r.kind == "definition" or r.method == "identity by definition" for r in defs)
    assert len(section33.where(mismatched=True)) == 0
    first = section33[0]
    assert section33[first.id] is first and isinstance(section33[:2], rigidsym.Results)
    doc = section33.to_json()
    assert doc["schema"] == 2 and [e["id"] for e in doc["equations"]] == \
        [r.id for r in section33]
    assert doc["summary"] == section33.summary()
    assert first.to_json() == doc["equations"][0]
    with pytest.raises(ValueError, match="verdict"):
        section33.where(verdict="true")


def test_repr_is_one_line_and_display_is_a_table(section33, r316):
    for obj in (section33, r316):
        assert "\n" not in repr(obj)
    assert "3.16" in repr(r316) and r316.verdict in repr(r316)
    table = section33._repr_html_()
    assert table.startswith("<table") and table.count("<tr") == len(section33) + 1


def test_one_result_shows_its_forms_as_mathml_and_latex(r316):
    page = r316._repr_html_()
    assert "<math" in page and "3.16" in page
    tex = r316._repr_latex_()
    assert tex.startswith("$\\displaystyle") and tex.endswith("$")


def test_bad_ids_and_arguments():
    with pytest.raises(BadInput, match="parts"):
        rigidsym.check("3.96")
    with pytest.raises(BadInput):
        rigidsym.check("notes:nothing-here")
    with pytest.raises(ValueError, match="jobs"):
        rigidsym.verify(["3.1"], jobs=0)


def test_every_public_name_resolves():
    for name in rigidsym.__all__:
        assert getattr(rigidsym, name) is not None, name
    assert set(rigidsym.__all__) <= set(dir(rigidsym))
    with pytest.raises(AttributeError):
        rigidsym.no_such_name  # noqa: B018
    import rigidsym.declare as declare

    assert set(declare.__all__) <= set(rigidsym.__all__)


def test_a_notebook_declaration_run_twice_replaces_itself():
    x = rigidsym.scalar("x")

    def declare(rhs):
        @rigidsym.equation("nb:cell", "a notebook cell")
        def cell():
            return rigidsym.Statement([rigidsym.Rel(x * 2, rhs)])
        return cell

    try:
        declare(x + x)
        assert rigidsym.check("nb:cell").verdict == "verified"
        declare(x * 3)  # the cell edited and run again: replaced, not "declared twice"
        r = rigidsym.check("nb:cell")
        # an exact counterexample: does-not-hold although no corrected form is declared; with
        # no model every repair (2x = 2x) is the same expression on both sides, said nothing
        assert r.verdict == "does-not-hold" and r.counterexample is not None
        assert r.correction == "none" and r.repairs == []
        assert "no correction declared or found" in r.detail
    finally:
        REGISTRY.pop("nb:cell", None)


def test_rigid_motion_keeps_its_constraints():
    from rigidsym.zero.decide import decide_zero

    m = rigidsym.rigid_motion()
    assert decide_zero(list(m.Omega + m.Omega.T)).zero is True
    assert decide_zero(list(m.Q_dot - m.Omega * m.Q)).zero is True
    eta = rigidsym.unit_vector4("eta")
    assert decide_zero([(eta.T * eta)[0] - 1]).zero is True
    assert decide_zero([eta[0] ** 2 - 1]).zero is False
