"""Variants of all 21 exercises, each graded by the grader through the
class key's round trip (the record an exam writes, rebuilt by ``solution_of``): the right
answers typed as ``--set`` types data are right, a changed answer is wrong, a blank is
missing. The proofs' true-or-false statements are decided by the sound zero test; an
edit of the identity is never decided true, and the reasons follow the truths."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
import sympy as sp

from rigidsym.course import exam as _exam
from rigidsym.course.gradebook import solution_of
from rigidsym.course.grading import grade
from rigidsym.course.slips import slip_list
from rigidsym.course.worked import EXERCISE_IDS, solution_record, to_json_value

#: slow to solve on a draw (3.10 solves twelve sequences, 3.12 two parts with radicals)
SLOW = {"ex3.10", "ex3.12"}
NEW = {"ex3.3", "ex3.6", "ex3.8", "ex3.9", "ex3.13", "ex3.15", "ex3.16", "ex3.17",
       "ex3.18", "ex3.20", "ex3.21"}
DEFAULT = (NEW - {"ex3.6"}) | {"ex3.19"}     # 3.6: 12 s (ten replays of 0.7 s)


def test_every_exercise_draws_variants_and_the_docs_list_its_slips():
    assert _exam.drawable() == EXERCISE_IDS
    page = (Path(__file__).resolve().parents[1] / "docs" / "exams.md").read_text()
    for ex_id in EXERCISE_IDS:
        assert f"| {ex_id[2:]} | {slip_list(ex_id)} |" in page, ex_id
    assert "| 3.19 | transpose: Q used for Q^T; unit (mm, cm for m): d;" in page


def _entry(x) -> str:
    """One entry as a student types it: exact, or, past the answer reader's 200 characters
    (3.12's unit principal axes are nested radicals), its decimal value to 20 digits."""
    x = str(x)
    return x if len(x) <= 200 else str(sp.N(sp.sympify(x), 20))


def _typed(v) -> str:
    if isinstance(v, list) and v and isinstance(v[0], list):
        return ";".join(",".join(_entry(x) for x in r) for r in v)
    return ",".join(_entry(x) for x in v) if isinstance(v, list) else _entry(v)


def _changed(v):
    """Another answer: each entry plus 7/3 (a truth flipped)."""
    if isinstance(v, list):
        return [_changed(x) for x in v]
    e = sp.sympify(v)
    if e in (sp.true, sp.false):
        return str(not bool(e))
    return str(e + sp.Rational(7, 3))


@pytest.mark.sample      # a seeded share in the quick run, the rest in the thorough one
@pytest.mark.parametrize("ex_id", sorted(DEFAULT))
def test_a_variant_of_the_proofs_and_of_3_19_is_graded(ex_id):
    _graded(ex_id)


@pytest.mark.slow
@pytest.mark.parametrize("ex_id", sorted(set(EXERCISE_IDS) - DEFAULT))
def test_a_variant_of_each_other_exercise_is_graded(ex_id):
    _graded(ex_id)


def _graded(ex_id):
    spec = {"problem": [{"exercise": ex_id, "variants": 1}]}
    taken: dict = {}
    (s, _), = _exam.drawn_exercises(spec, 5, taken)
    (t, _), = _exam.drawn_exercises(spec, 6, taken)
    assert s.status == "solved" and s.checked
    assert _exam.variant_key(s) != _exam.variant_key(t)            # two students, two variants
    asked = _exam.asked(s)
    assert asked
    rec = dict(solution_record(s), asked=asked)
    back = solution_of(rec)
    answers = {a: to_json_value(s.answers[a]) for a in asked}
    right = grade(back, {a: _typed(v) for a, v in answers.items()})
    assert [g.name for g in right] == asked
    assert all(g.correct is True for g in right), [g.as_dict() for g in right]
    wrong = grade(back, {a: _typed(_changed(v)) for a, v in answers.items()})
    assert all(g.correct is False and not g.missing for g in wrong), \
        [g.as_dict() for g in wrong]
    blank = grade(back, {asked[0]: " "})
    assert all(g.missing for g in blank)


@pytest.mark.sample      # a seeded share in the quick run, the rest in the thorough one
@pytest.mark.parametrize("ex_id", sorted(NEW - {"ex3.6"}))
def test_true_or_false_statements_are_decided_and_reasons_follow(ex_id):
    _decided(ex_id)


def _decided(ex_id):
    V = _exam.variants_module()
    stmts = V.statements(ex_id)
    assert len(stmts) >= 5                                # 60 ordered triples at least
    for k, (text, _, why) in enumerate(stmts):
        holds, check = V.decided(ex_id, k)
        assert holds is not None, text                    # proved or refuted, exactly
        assert holds == (why == 1), (text, check.detail)  # an edit is never true
    seen = set()
    for seed in range(12):
        s = V.draw(ex_id, random.Random(seed))
        holds, why = list(s.answers["holds"]), list(s.answers["why"])
        order = [int(r) for r in s.data["reasons"]]          # reason of label n + 1
        assert sorted(order) == [1, 2, 3, 4]
        assert all((h == 1) == (order[w - 1] == 1) for h, w in zip(holds, why, strict=True))
        for n, r in enumerate(order, 1):                     # the handout says which is which
            assert f"{n} {V.WHY[r]}" in s.statement
        assert s.checked and len(s.steps) == 3
        seen.add(tuple(s.data["statements"]))
        words = ",".join("true" if h else "false" for h in holds)
        (g,) = [g for g in grade(s, {"holds": words}) if g.name == "holds"]
        assert g.correct is True
    assert len(seen) >= 6                                 # the draws vary
