"""A reading file's lines as a document's relations are given them: names of the model
(``\\mathbf{w_axis}``, ``ell``) read as one glyph each, and each line ``--let`` does not
say (a rate, a member of a family, particles) listed with why, never dropped silently
(docs/check-documents.md, "The reading's lines")."""

from __future__ import annotations

import pytest

import rigidsym
from rigidsym.core.errors import BadInput
from rigidsym.documents.checking import decide
from rigidsym.documents.declarations import omitted_lines, plan, reading_lets
from rigidsym.documents.displays import Display, Source
from rigidsym.documents.relations import split_display
from rigidsym.latex.lets import model_names, model_spelling, read_lets, respell_model_names
from rigidsym.reading import parse_reading
from rigidsym.registry import declarations as registry


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def test_a_name_of_the_model_is_one_upright_glyph():
    texts = [r"\mathbf{w_axis}: 3-vector", "ell: scalar", "d0_axial: scalar",
             "sec342_sigma: scalar", "m_1: scalar", r"\mathbf{e}: unit vector",
             r"\mathbf{p}_0 = \mathbf{w_axis} - \mathbf{e}"]
    names = model_names(texts)
    assert names == {r"\mathbf{w_axis}": r"\mathrm{w\_axis}", "ell": r"\mathrm{ell}",
                     "d0_axial": r"\mathrm{d0\_axial}",
                     "sec342_sigma": r"\mathrm{sec342\_sigma}"}  # m_1 is the glyph m_1
    assert model_spelling("w_axis") == r"\mathrm{w\_axis}"
    # a bare name stands alone: never inside a macro, a word or another name
    assert respell_model_names(r"\ell + ell\,x + 2ell + \mathrm{ell} + cell", names) == \
        r"\ell + \mathrm{ell}\,x + 2\mathrm{ell} + \mathrm{ell} + cell"
    keys = [x.key for x in read_lets(texts)]
    assert keys[:4] == [r"\mathrm{w\_axis}", r"\mathrm{ell}", r"\mathrm{d0\_axial}",
                        r"\mathrm{sec342\_sigma}"]
    assert keys[4] == "m_{1}"


def test_a_model_built_on_a_name_of_the_model_is_decided():
    lets = [r"\mathbf{e}: unit vector", r"\mathbf{w_axis}: 3-vector",
            r"\mathbf{p}_0 = \mathbf{w_axis} - (\mathbf{e}^T\mathbf{w_axis})\mathbf{e}"]
    assert rigidsym.check_latex(r"\mathbf{e}^T\mathbf{p}_0 = 0", let=lets,
                                repairs=False).verdict == "verified"
    assert rigidsym.check_latex(r"\mathbf{e}^T\mathbf{p}_0 = 1", let=lets,
                                repairs=False).verdict == "does-not-hold"


READING = r"""
[reading]
format = 1

[[let]]
let = 'd0_axial: scalar'
ids = ["1"]

[[let]]
let = 'd_0: scalar'
atoms_of = 'd0_axial'
ids = ["1"]

[[let]]
let = '\mathbf{a}(t): 3-vector'
ids = ["1"]

[[let]]
let = '\dot{\mathbf{a}}: rate of \mathbf{a}'
ids = ["1"]

[[let]]
let = 'p = d_0'
relation = 'p in m/rad'
ids = ["1"]

[[let]]
let = 'p = 2\pi d_0'
relation = 'p in m/turn'
ids = ["1"]

[[let]]
let = '\|\mathbf{v}\|: scalar'
ids = ["1"]

[[let]]
let = '\mathbf{Q}: rotation'
ids = ["2"]

[[let]]
let = '[\mathbf{Q}] = \mathbf{Q}^T'
ids = ["2"]

[classes]
relation = ["1", "2", "3"]
"""


def test_each_line_not_given_is_listed_with_why():
    rd = parse_reading(READING)
    given, omitted = reading_lets(rd, "1")
    assert given == ["d0_axial: scalar", "d_0 = d0_axial", r"\mathbf{a}(t): 3-vector",
                     r"\dot{\mathbf{a}}: rate of \mathbf{a}"]
    why = dict(omitted)
    assert "'p in m/rad'" in why["p = d_0"] and "'p in m/turn'" in why[r"p = 2\pi d_0"]
    assert why[r"\|\mathbf{v}\|: scalar"].startswith("--let does not read it")
    listed = omitted_lines(rd, ["1", "1", None, "2"])
    assert len(listed) == 3 and all(x["labels"] == ["1"] for x in listed)


def display(body: str):
    d = Display(Source("t.md", body), 1, body, 0, 1, "displaymath", None, {})
    return split_display(d)


def test_the_reading_s_class_and_its_lines_for_a_label_rule_the_page():
    rd = parse_reading(READING)
    rels = (display(r"\mathbf{Q} = \mathbf{1} \quad (3)")
            + display(r"\mathbf{Q}^T\mathbf{Q} = \mathbf{1} \quad (2)")
            + display(r"[\mathbf{Q}]\mathbf{Q} = \mathbf{1} \quad (2)"))
    plans = plan(rels, rd)
    # printed as a relation: a claim (its symbol undeclared), never the page's definition
    assert plans[0].action == "decide"
    # (2)'s lines read two glyphs as one: what uses it is not decided, and says why
    assert plans[1].action == "skip" and "read as one glyph \\mathbf{Q}" in plans[1].reason
    assert plans[2].action == "skip"


def test_a_line_read_nowhere_is_still_bad_input_from_the_command_line():
    with pytest.raises(BadInput, match="cannot be read"):
        plan(display(r"x = y \quad (1)"), None, [r"\|\mathbf{v}\|: scalar"])


def test_a_line_not_given_withholds_its_glyphs_and_a_rate_reads_from_x_of_t():
    rd = parse_reading(READING)
    rels = (display(r"p = d_0 \quad (1)") + display(r"\mathbf{v} = \mathbf{v} \quad (1)")
            + display(r"\dot{\mathbf{a}}^T\mathbf{a} = \mathbf{a}^T\dot{\mathbf{a}} \quad (1)"))
    plans = plan(rels, rd)
    # the member's p (m/rad or m/turn) is not said: never read as another p
    assert plans[0].action == "skip" and "'p = d_0', is not given" in plans[0].reason
    # a line that constrains v and is not given leaves v undecided, never free
    assert plans[1].action == "skip" and r"\|\mathbf{v}\|: scalar" in plans[1].reason
    # \dot a is the rate of a(t): its declaration comes with it, and the rate is no
    # symbol the check was not told of
    assert plans[2].action == "decide" and set(plans[2].lets) == {
        r"\mathbf{a}(t): 3-vector", r"\dot{\mathbf{a}}: rate of \mathbf{a}"}
    rec = decide(plans[2], {"notation": None, "repairs": False, "repair_seconds": None,
                            "timeout": "default"})
    assert rec["verdict"] == "verified" and rec["free"] == []


def test_ell_is_a_glyph():
    assert rigidsym.check_latex(r"(\ell + 1)^2 = \ell^2 + 2\ell + 1",
                                repairs=False).verdict == "verified"
