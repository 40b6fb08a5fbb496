"""``rigidsym check FILE``: documents read into relations, declared once, decided as
``check --latex`` decides each (docs/check-documents.md)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rigidsym
from rigidsym.cli import main
from rigidsym.core.errors import BadInput
from rigidsym.documents import check_document, conventions, exit_code, read_document
from rigidsym.documents.checking import VERDICTS, DocumentResult
from rigidsym.documents.declarations import plan
from rigidsym.documents.displays import Display, Source
from rigidsym.documents.html import as_html
from rigidsym.documents.relations import split_display
from rigidsym.documents.report import FIELDS
from rigidsym.registry import declarations as registry

DATA = Path(__file__).parent / "data" / "documents"


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def relations_of(body: str, macros: dict | None = None):
    d = Display(Source("t.tex", body), 1, body, 0, 1, "equation", None, macros or {})
    return split_display(d)


def pairs(rels):
    return [(r.lhs, r.op, r.rhs) for r in rels]


# ----------------------------------------------------------------------- reading
def test_latex_document_every_construct():
    rels = read_document(DATA / "constructs.tex").relations
    got = {(r.display, r.lhs, r.op, r.rhs) for r in rels}
    assert (1, "a", "=", "b") in got and (1, "b", "=", "c") in got  # a chain
    assert (2, "d", "=", "e") in got and (2, "e", "=", "f") in got  # &= relates to e
    assert (2, "k", ":=", "m") in got  # \quad separates
    assert (3, "q", "=", "r") in got  # eqnarray's &=&
    assert (4, "s", "=", "t + u + w") in got  # multline continues the right side
    assert (5, "z", "\\approx", "\\mathbf{R}_{1}^T \\mathbf{v}") in got  # \newcommand, \def
    m = [r for r in rels if r.display == 6]  # split; a matrix's \\ kept
    assert m[0].rhs.startswith("\\begin{bmatrix}") and m[1].lhs == m[0].rhs
    assert [r.rhs for r in rels if r.display == 7][0].endswith("\\end{cases}")
    assert (8, "\\alpha", "=", "\\left(\\beta, \\gamma\\right)") in got  # no split in ()
    inp = [r for r in rels if r.label == "eq:input"][0]  # \input followed
    assert inp.file.endswith("parts/more.tex") and inp.line == 2
    assert inp.latex == "\\mathbf{R}_{2} = \\mathbf{v}"
    by = {r.latex: r for r in rels}
    assert by["a = b"].label == by["b = c"].label == "eq:chain"
    assert by["d = e"].label == "eq:first" and by["e = f"].label == "T2"
    assert (by["d = e"].line, by["d = e"].column) == (11, 1)
    assert (by["e = f"].line, by["e = f"].column) == (12, 4)  # the '=' of '&= f'


def test_markdown_document_every_flavour():
    rels = read_document(DATA / "constructs.md").relations
    got = [(r.display, r.latex) for r in rels]
    assert got == [(1, "a = b"), (1, "b = c"), (2, "d = e"), (3, "f = g"), (3, "h = k"),
                   (4, "m = n"), (5, "p = q"), (5, "q = r"), (6, "\\mathbf{R}^T = s")]
    text = (DATA / "constructs.md").read_text().splitlines()
    for r in rels:  # every place points at the relation's first glyph
        assert text[r.line - 1][r.column - 1:].startswith(r.lhs[:1] if r.index == 1 or
                                                          r.display in (3,) else "=")


def test_a_document_of_another_kind_or_missing_is_bad_input(tmp_path):
    (tmp_path / "x.txt").write_text("a = b")
    with pytest.raises(BadInput, match="Markdown"):
        read_document(tmp_path / "x.txt")
    with pytest.raises(BadInput, match="cannot read"):
        read_document(tmp_path / "missing.md")


_SYM = st.sampled_from(["a", "b", "c", "x_1", "\\alpha", "\\mathbf{v}", "f(y)"])


@settings(max_examples=25, deadline=None)
@given(st.lists(_SYM, min_size=2, max_size=5))
def test_a_chain_is_its_consecutive_pairs(terms):
    chain = " = ".join(terms)
    want = [(a, "=", b) for a, b in zip(terms[:-1], terms[1:], strict=True)]
    assert pairs(relations_of(chain)) == want
    lines = terms[0] + " &= " + " \\\\\n &= ".join(terms[1:])  # the same as align lines
    assert pairs(relations_of(f"\\begin{{align}}{lines}\\end{{align}}")) == \
        pairs(relations_of(chain))


@settings(max_examples=25, deadline=None)
@given(st.permutations([("a", "b"), ("c", "d + e"), ("\\mathbf{v}", "f(x, y)")]),
       st.sampled_from([", ", ", \\quad ", " \\qquad ", "; "]))
def test_relations_separated_or_reordered_are_the_same_relations(rels, sep):
    body = sep.join(f"{a} = {b}" for a, b in rels)
    assert pairs(relations_of(body)) == [(a, "=", b) for a, b in rels]


@pytest.mark.parametrize("number", ["3.8", "3.9a", "12", "2.4.1"])
@pytest.mark.parametrize("sep", [" \\quad ", " \\qquad ", "\\quad"])
def test_a_printed_number_closing_a_line_is_its_label(number, sep):
    """A converted book's ``x = y \\quad (3.9a)`` is ``x = y`` labelled 3.9a, as
    ``\\tag{3.9a}``; a parenthesised expression or a relation after ``\\quad`` is not."""
    rels = relations_of(f"a = b + c{sep}({number})")
    assert pairs(rels) == [("a", "=", "b + c")] and rels[0].label == number
    tagged = relations_of(f"a = b + c \\tag{{{number}}}")
    assert pairs(tagged) == pairs(rels) and tagged[0].label == rels[0].label
    for body in (f"a = b{sep}(x + y)", f"a = b{sep}(3.8) = c", f"(3.8){sep}a = b"):
        assert all(r.label is None for r in relations_of(body)), body


@settings(max_examples=15, deadline=None)
@given(st.sampled_from(["\\mathbf{R}", "R_{z}", "\\theta"]), st.integers(0, 1))
def test_a_macro_reads_as_its_expansion(body, nargs):
    defn = f"\\newcommand{{\\mac}}[{nargs}]{{{body}{'_{#1}' if nargs else ''}}}"
    use = "\\mac{2}" if nargs else "\\mac"
    want = body + ("_{2}" if nargs else "")
    assert pairs(relations_of(f"{defn}\n{use} = a")) == [(want, "=", "a")]


def test_definitions_in_document_order_and_one_used_before_refused():
    rels = read_document(DATA / "later.md").relations
    plans = plan(list(rels), None, [r"\mathbf{e}: unit vector"])
    assert plans[0].action == "skip"
    assert "\\mathbf{E}" in plans[0].reason and "later" in plans[0].reason
    assert "later.md:6" in plans[0].reason
    assert plans[1].action == "definition" and plans[1].defines == "\\mathbf{E}"
    # the same two displays the other way round: the definition is a model after it
    back = list(reversed(rels))
    again = plan(back, None, [r"\mathbf{e}: unit vector"])
    assert again[1].action == "decide"
    assert r"\mathbf{E} = \mathrm{CPM}(\mathbf{e})" in again[1].lets


def test_each_relation_gets_only_the_declarations_it_uses():
    rels = read_document(DATA / "verdicts.md").relations
    from rigidsym.reading import load_reading

    plans = plan(list(rels), load_reading(DATA / "verdicts.reading.toml"))
    assert [p.action for p in plans] == ["definition", "decide", "decide", "decide"]
    assert plans[1].lets == [r"\mathbf{Q}: rotation"]
    assert set(plans[2].lets) == {r"\mathbf{e}: unit vector",
                                  r"\mathbf{E} = \mathrm{CPM}(\mathbf{e})"}


# ----------------------------------------------------------------------- deciding
def test_verdicts_equal_check_latex_alone_and_undeclared_never_guessed(capsys):
    res = check_document(DATA / "verdicts.md", repairs=False)
    recs = {r["latex"]: r for r in res.records}
    qq = recs[r"\mathbf{Q}^T\mathbf{Q} = \mathbf{1}"]
    alone = rigidsym.check_latex(qq["latex"], let=qq["lets"], repairs=False)
    assert qq["verdict"] == alone.verdict == "verified"
    free = recs[r"\mathbf{Q}\mathbf{a} = \mathbf{a}"]  # a: declared by nothing
    assert free["verdict"] == "not-checked" and free["free"] == ["\\mathbf{a}"]
    assert "line" in free and free["line"] == 12
    assert recs[r"\mathbf{E} := \mathrm{CPM}(\mathbf{e})"]["verdict"] == "definition"
    assert res.stored == 0
    warm = check_document(DATA / "verdicts.md", repairs=False)
    assert warm.stored == 3 and [r["verdict"] for r in warm.records] == \
        [r["verdict"] for r in res.records]
    code = main(["check", str(DATA / "verdicts.md"), "--no-repairs", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == 3 and out["counts"]["not-checked"] == 1  # one not decided: exit 3
    assert {k for k in out["relations"][0]} >= {"file", "line", "verdict", "reason"}


def test_cli_bad_input_and_one_of_file_or_latex(tmp_path, capsys):
    assert main(["check"]) == 2
    assert main(["check", str(tmp_path / "none.md")]) == 2
    (tmp_path / "n.md").write_text("$$a = b$$\n")
    (tmp_path / "n.reading.toml").write_text("[reading]\nformat = 2\n")
    assert main(["check", str(tmp_path / "n.md")]) == 2
    capsys.readouterr()


# ----------------------------------------------------------------------- the HTML page
@given(st.lists(st.sampled_from(VERDICTS), min_size=4, max_size=4))
@settings(max_examples=10)
def test_the_html_page_shows_each_display_in_order_with_its_verdicts(verdicts):
    doc = read_document(DATA / "verdicts.md")
    recs = []
    for r, v in zip(doc.relations, verdicts, strict=True):
        bad = v == "does-not-hold"
        recs.append({k: None for k in FIELDS} | {
            "file": r.file, "line": r.line, "display": r.display, "index": r.index,
            "latex": r.latex, "label": r.label, "verdict": v,
            "reason": None if v in ("verified", "does-not-hold") else f"why {r.index}",
            "point": [{"latex": "\\mathbf{e}", "value": "[0; 1; 0]"}] if bad else None,
            "corrected": "Q = 1" if bad else None,
            "corrected_latex": "\\mathbf{Q} = \\boxed{\\mathbf{1}}" if bad else None,
            "cause": "drop a term" if bad else None})
    page = as_html(DocumentResult(doc, None, recs))
    assert "<script" not in page and "src=" not in page  # offline: nothing fetched
    at = [page.index(f'id="display-{d.number}"') for d in doc.displays]
    assert at == sorted(at)  # the displays in the document's order
    for rec in recs:  # each relation typeset, its verdict beside it, in its display
        i = page.index(f'id="r-{rec["display"]}-{rec["index"]}"')
        j = page.index("</div>", i)
        assert "<math" in page[i:j] and f'badge {rec["verdict"]}"' in page[i:j]
        assert page.index(f'id="display-{rec["display"]}"') < i
    n_bad = verdicts.count("does-not-hold")
    assert page.count("Counterexample (exact)") == n_bad
    assert page.count("Corrected (drop a term)") == n_bad
    assert page.count('<menclose notation="box">') == n_bad  # the edit boxed, in MathML


@pytest.mark.slow
def test_the_example_notes_find_their_slip(capsys, tmp_path):
    code = main(["check", str(Path(__file__).parents[1] / "examples" / "notes.md"),
                 "--html", str(tmp_path / "errata.html")])
    out = capsys.readouterr().out
    page = (tmp_path / "errata.html").read_text(encoding="utf-8")
    assert "Counterexample (exact)" in page and page.count('id="display-') == 5
    assert code == 1
    assert "DOES NOT HOLD" in out and "flip the sign" in out
    assert "an approximation" in out


# ----------------------------------------------------------------------- conventions
VERDICT = st.sampled_from(["verified", "does-not-hold", "undecided"])


@given(st.data(), st.sampled_from(list(conventions.CHOICES)))
def test_a_relation_under_each_open_convention_never_from_a_default(data, key):
    combos = [c for c, _ in conventions.choices([key])]
    verdicts = data.draw(st.lists(VERDICT, min_size=len(combos), max_size=len(combos)))
    outs = [(c, {"verdict": v, "counterexample": f"x = {i}"})
            for i, (c, v) in enumerate(zip(combos, verdicts, strict=True))]
    got = conventions.combine([key], outs)
    assert list(got["under"].values()) == verdicts  # each convention's verdict said
    if len(set(verdicts)) == 1:
        assert got["verdict"] == verdicts[0]
    elif set(verdicts) == {"verified", "does-not-hold"}:
        good = [i for i, v in enumerate(verdicts) if v == "verified"]
        bad = [i for i, v in enumerate(verdicts) if v == "does-not-hold"]
        assert got["verdict"] == "convention-dependent" and got["corrected"] is None
        name = [conventions.NAMES[c[0]] for c in combos]
        assert got["reason"].startswith(f"holds under {', '.join(name[i] for i in good)}, "
                                        f"not under {', '.join(name[i] for i in bad)}")
        assert f"x = {bad[0]}" in got["reason"] and key in got["reason"]
    else:
        assert got["verdict"] == "undecided"


def test_a_convention_fixed_by_a_let_or_notation_is_not_open():
    notes = ["quaternion product: Hamilton's ...", "tangent order: not declared; ..."]
    assert conventions.open_in(notes, None, [], None) == ["quaternion_product",
                                                          "tangent_order"]
    assert conventions.open_in(notes, None, ["\\odot: JPL"], "barfoot") == []
    assert conventions.open_in([], "the two orders disagree (--let 'tangent order: a')",
                               [], None) == ["tangent_order"]
    assert conventions.open_in(["numeric cross-check"], None, [], None) == []


@pytest.mark.slow  # 7 s (priced: .ci/run's thorough part)
def test_open_conventions_decided_under_each_and_fixed_ones_said_back_once():
    res = check_document(DATA / "conventions.md", repairs=False)
    v = [r["verdict"] for r in res.records]
    assert v == ["convention-dependent", "verified", "definition", "convention-dependent"]
    qq, ad = res.records[0], res.records[3]
    assert qq["reason"].startswith("holds under Hamilton's quaternion product (scalar first") \
        and "not under JPL's" in qq["reason"] and "stored scalar last (ij = k" in qq["reason"]
    assert len(qq["under"]) == 3    # Hamilton scalar first, JPL, Hamilton scalar last
    assert ad["reason"].startswith("holds under the tangent order [v; ω]")
    assert exit_code(res) == 3
    fixed = check_document(DATA / "conventions.md", repairs=False,
                           reading=DATA / "conventions-fixed.reading.toml")
    assert [r["verdict"] for r in fixed.records] == ["verified", "verified", "definition",
                                                     "verified"]
    assert not any(r["under"] for r in fixed.records)
    said = fixed.conventions
    assert len(said) == 2 and sum("quaternion_product = hamilton" in c for c in said) == 1
    assert exit_code(fixed) == 0


def test_a_rotations_body_velocity_the_reader_introduces_is_no_undeclared_symbol(tmp_path):
    # \dot{Q} of a rotation Q(t) is Q [Q_w], Q_w any angular velocity: the relations are
    # decided for every one (a slip still found), never refused as using an undeclared Q_w
    (tmp_path / "omega.md").write_text(
        "$$\n\\boldsymbol{\\Omega} := \\dot{\\mathbf{Q}}\\mathbf{Q}^T, \\quad\n"
        "\\boldsymbol{\\omega} := \\text{vect}(\\boldsymbol{\\Omega})\n$$\n\n"
        "$$\n\\boldsymbol{\\Omega}\\mathbf{a} = \\boldsymbol{\\omega} \\times \\mathbf{a}\n$$\n\n"
        "$$\n\\boldsymbol{\\Omega}\\mathbf{a} = \\mathbf{a} \\times \\boldsymbol{\\omega}\n$$\n")
    res = check_document(tmp_path / "omega.md", repairs=False,
                         lets=[r"\mathbf{Q}(t): rotation", r"\dot{\mathbf{Q}}: rate of \mathbf{Q}",
                               r"\mathbf{a}: 3-vector"])
    assert [r["verdict"] for r in res.records] == ["definition", "definition", "verified",
                                                   "does-not-hold"]
    assert not any(r.get("free") for r in res.records)


@pytest.mark.slow  # 2 s CPU (priced: .ci/run's thorough part)
def test_the_documents_own_q_w_beside_a_rotation_is_never_its_body_velocity(tmp_path):
    # the reader names a rotation's body velocity \mathbf{Q}_{w}; the document's own symbol
    # of that name never becomes it: undeclared, it is named (no verdict); declared a
    # 3-vector, it is the document's own free vector, for which the relation (true of the
    # body velocity) does not hold
    (tmp_path / "own.md").write_text(
        "$$\n\\dot{\\mathbf{Q}}\\mathbf{Q}^T\\mathbf{a} = "
        "(\\mathbf{Q}\\mathbf{Q}_{w}) \\times \\mathbf{a}\n$$\n")
    lets = [r"\mathbf{Q}(t): rotation", r"\dot{\mathbf{Q}}: rate of \mathbf{Q}",
            r"\mathbf{a}: 3-vector"]
    for more, verdict in (([], "not-checked"),
                          ([r"\mathbf{Q}_{w}: 3-vector"], "does-not-hold")):
        own = check_document(tmp_path / "own.md", repairs=False, lets=lets + more).records
        assert own[0]["verdict"] == verdict, own[0]


def test_a_rate_the_reader_takes_as_a_glyph_of_its_own_is_undeclared(tmp_path):
    # '\ddot{Q}: second rate of Q' of a rotation Q(t): the reader reads no second rate of a
    # rotation whose angular velocity's rate nothing declares: refused, never a
    # counterexample resting on a \ddot{Q} no motion of Q has (tr of \dot\Omega is 0)
    (tmp_path / "rate.md").write_text(
        "$$\n\\dot{\\boldsymbol{\\Omega}} := \\ddot{\\mathbf{Q}}\\mathbf{Q}^T + "
        "\\dot{\\mathbf{Q}}\\dot{\\mathbf{Q}}^T\n$$\n\n$$\n\\text{tr}(\\dot{\\boldsymbol{\\Omega}})"
        " = 0\n$$\n")
    res = check_document(tmp_path / "rate.md", repairs=False,
                         lets=[r"\mathbf{Q}(t): rotation", r"\dot{\mathbf{Q}}: rate of \mathbf{Q}",
                               r"\ddot{\mathbf{Q}}: second rate of \mathbf{Q}"])
    assert [r["verdict"] for r in res.records] == ["definition", "not-checked"]
    assert res.records[1]["counterexample"] is None
    # the second rate of a rotation needs the rate of its angular velocity, which nothing
    # declares: refused saying what to declare
    assert "second time derivative" in res.records[1]["reason"], res.records[1]
