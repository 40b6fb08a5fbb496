"""Exam sets: a handout and a key from a spec of three problems, the same
bytes for the same seed, and no answer of the key in the handout."""

from __future__ import annotations

import html
import json
import re

import pytest
import sympy as sp

import rigidsym.exercises as ex
from rigidsym.cli import main
from rigidsym.course.worked import to_json_value

pytestmark = pytest.mark.xdist_group("exam")  # its module fixtures built on one worker

SPEC = {"title": "Quiz", "seed": 7, "problem": [
    {"exercise": "3.19", "data": {"d": ["0.1", 0, 0], "Q": [[0, -1, 0], [1, 0, 0], [0, 0, 1]]}},
    {"exercise": "3.4", "variants": 1},
    {"exercise": "3.11", "variants": 1}]}
_NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e-?\d+)?(?:/\d+)?")


def _visible_numbers(page: str) -> set[str]:
    """The numbers a reader sees: the text of the page and of its figures' <text>."""
    page = re.sub(r"<style>.*?</style>", " ", page, flags=re.S)    # CSS is not seen
    # every tag goes, attributes too (an SVG <text style="font-size: 11px"> is not seen);
    # the text between the tags, the figures' labels included, stays
    text = html.unescape(re.sub(r"<[^>]*>", " ", page))
    return set(_NUMBER.findall(text))


def _flat(v) -> list:
    if not isinstance(v, list):
        return [v]
    return [x for r in v for x in _flat(r)]


def _leaks(key: dict, page: str) -> list:
    """Answers of problem k seen in problem k's section (other problems' data may hold
    the same number by chance) or in the page's head."""
    head, *sections = page.split('<section class="problem">')
    found = []
    for e, section in zip(key["exercises"], sections, strict=True):
        numbers = _visible_numbers(head + section)
        data = {sp.sympify(x) for v in e["data"].values() for x in _flat(v)}
        for name, v in e["answers"].items():
            for x in map(sp.sympify, _flat(v)):
                if not isinstance(x, sp.Expr) or x in data or not x.is_number:  # sets, truths
                    continue
                if x.is_Integer and abs(x) <= 10:       # problem numbers, headings
                    continue
                shown = {str(x)} | {f"{float(x):.{k}g}" for k in (3, 4, 6)}
                if shown & numbers:
                    found.append((e["problem"], name, str(x)))
    return found


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    out = tmp_path_factory.mktemp("exam")
    return ex.exam(SPEC, out)


def test_three_problems_and_schema_2(written):
    paths = written
    key = json.loads(paths["key_json"].read_text())
    assert key["schema"] == 2 and [e["problem"] for e in key["exercises"]] == [1, 2, 3]
    for e in key["exercises"]:
        assert e["status"] == "solved" and e["checked"] and e["data"] and e["checks"]
        again = ex.solve(e["id"], **e["data"])          # the key's data give its answers
        assert {k: to_json_value(again.answers[k]) for k in e["answers"]} == e["answers"]
    handout = paths["handout"].read_text()
    assert "@media print" in handout and handout.count('class="answer"') >= 3
    assert handout.count("<svg") == 3                 # a figure of the data of each


def test_no_answer_of_the_key_in_the_handout(written):
    paths = written
    key = json.loads(paths["key_json"].read_text())
    assert not _leaks(key, paths["handout"].read_text())
    # the search finds them where they are: the key's own page
    assert _leaks(key, paths["key_html"].read_text())


def test_deterministic_for_a_spec_and_seed(written, tmp_path):
    paths = written
    again = ex.exam(SPEC, tmp_path / "a")
    for k in paths:
        assert again[k].read_bytes() == paths[k].read_bytes()
    from rigidsym.course.exam import _problems, read_spec
    drawn = [[s.data for s in _problems(read_spec(SPEC), seed)] for seed in (7, 8)]
    assert drawn[0][0] == drawn[1][0] and drawn[0][1:] != drawn[1][1:]   # given; drawn


def test_cli_and_bad_specs(tmp_path, capsys):
    spec = tmp_path / "quiz.toml"
    spec.write_text('seed = 3\n[[problem]]\nexercise = "3.7"\n')
    assert main(["exam", str(spec), "--out", str(tmp_path / "q")]) == 0
    assert (tmp_path / "q" / "handout.html").exists()
    spec.write_text('[[problem]]\nexercise = "3.6"\nvariants = 1\ndata = { p = [0, 0, 0] }\n')
    assert main(["exam", str(spec), "--out", str(tmp_path / "r")]) == 2
    assert "both data and variants" in capsys.readouterr().err
    with pytest.raises(ValueError, match="at least one"):
        ex.exam({"problem": []}, tmp_path / "s")
