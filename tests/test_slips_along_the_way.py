"""The class's policy on slips along the way (``slips_along_the_way`` in the spec, in
key.json): STACK's questions (stack.xml, read by the independent reader of
tests/_stack_maxima.py) and the gradebook name such a slip under the same policy, so the
LMS's mark is the gradebook's either way; without the policy no replay is solved."""

from __future__ import annotations

import numpy as np
import pytest


def _record(s) -> dict:
    from rigidsym.course.exam import asked
    from rigidsym.course.exam_text import box_label
    from rigidsym.course.worked import solution_record

    return dict(solution_record(s), problem=1, weight=1, asked=asked(s),
                labels={a: box_label(s.id, a) for a in asked(s)})


def _question(s, along: bool):
    from rigidsym.course.stack_export import stack_xml
    from tests._stack_maxima import questions

    key = {"slip_credit": 0.5, "rounding_credit": 0.75, "slips_along_the_way": along,
           "students": [{"student": "Amy", "id": "7", "problems": [_record(s)]}]}
    return questions(stack_xml("q", key))["7-P1"]


def _slipped_box(s):
    """A box and a value that only a replay explains: the answer of the solution replayed
    with a slip along the way, which no edit of the final answer gives."""
    from rigidsym.course.exam import asked
    from rigidsym.course.grading import grade, key_array
    from rigidsym.course.slips import replays

    for _, _, answers in replays(s):
        for box in asked(s):
            v = key_array(answers[box])
            with_replays = {g.name: g for g in grade(s, {box: v.tolist()})}[box]
            without = {g.name: g for g in grade(s, {box: v.tolist()}, replay=False)}[box]
            if with_replays.slip and not with_replays.correct and not without.slip:
                return box, v
    raise AssertionError(f"{s.id}: no box that only a replay explains")


def test_stack_and_the_gradebook_name_a_slip_along_the_way_under_the_same_policy(
        monkeypatch):
    from rigidsym import exercises as ex
    from rigidsym.course.grading import grade, key_array
    from tests._stack_maxima import boxes, mark, question_tests

    s = ex.solve("3.4")
    box, v = _slipped_box(s)
    for along, word, score in ((True, "slip", 0.5), (False, "wrong", 0.0)):
        q = _question(s, along)
        assert all(ok for _, ok in question_tests(q))
        answers = {b: key_array(s.answers[b]) for b in boxes(q)}
        answers[box] = v
        _, notes = mark(q, {inp: float(answers[b]) if answers[b].ndim == 0 else
                            answers[b].reshape(-1, 1) if answers[b].ndim == 1 else answers[b]
                            for b, (inp, kind) in boxes(q).items()})
        assert notes[f"prt_{boxes(q)[box][0]}"] == (score, f"{box}: {word}")
        g = {g.name: g for g in grade(s, {box: v.tolist()}, replay=along)}[box]
        assert (g.slip is not None) == along and not g.correct

    def no_replay(solution):
        raise AssertionError("a replay solved where the policy asks for none")

    from rigidsym.course import grading, stack_export

    monkeypatch.setattr(grading, "replayed_values", no_replay)
    monkeypatch.setattr(stack_export, "replayed_values", no_replay)
    q = _question(s, False)                     # written without a single replay
    assert all(ok for _, ok in question_tests(q))
    with pytest.raises(AssertionError, match="a replay solved"):
        _question(s, True)


@pytest.mark.parametrize("value", ["yes", 1, "false"])
def test_a_policy_that_is_no_truth_is_refused_naming_it(value):
    from rigidsym.course.exam import read_spec

    with pytest.raises(ValueError, match="slips_along_the_way must be true or false"):
        read_spec({"slips_along_the_way": value, "problem": [{"exercise": "3.4"}]})


@pytest.mark.slow      # two class exams with their handouts' figures: about 4 s of CPU
def test_a_class_key_carries_the_policy_and_grades_by_it(tmp_path):
    """A class of two on 3.4 (the book's data): key.json carries the spec's policy
    (default true); the gradebook names the replayed slip only under
    ``slips_along_the_way = true``."""
    import csv
    import json

    from rigidsym.course import class_exam
    from rigidsym.course.gradebook import grade_class, solution_of

    roster = tmp_path / "roster.csv"
    roster.write_text("name,id\nAmy Ames,1\nBo Bell,2\n", encoding="utf-8")
    for along in (False, None):     # None: the spec says nothing, the default (true)
        spec = {"seed": 3, "slip_credit": 0.5,
                "problem": [{"exercise": "3.4", "data": {}}]}
        if along is not None:
            spec["slips_along_the_way"] = along
        out = tmp_path / f"c{along}"
        class_exam(spec, roster, out)
        key = json.loads((out / "key.json").read_text(encoding="utf-8"))
        named = along is None
        assert key["slips_along_the_way"] is named
        p = key["students"][0]["problems"][0]
        box, v = _slipped_box(solution_of(p))
        answers = tmp_path / f"a{along}.json"
        answers.mkdir()
        (answers / "1.json").write_text(json.dumps({"id": "1", f"P1.{box}": v.tolist()}),
                                        encoding="utf-8")
        grade_class(out, answers)
        rows = [r for r in csv.DictReader((out / "grades.csv").open(encoding="utf-8-sig"))
                if r["id"] == "1" and r["answer"] == box]
        assert len(rows) == 1 and rows[0]["status"] == "wrong"
        assert bool(rows[0]["slip"]) is named, rows[0]
        assert float(rows[0]["points"]) == pytest.approx(
            0.5 * float(rows[0]["max_points"]) if named else 0.0, rel=1e-5)
        assert np.isfinite(v).all()
