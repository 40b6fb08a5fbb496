"""The replays of a slip kept in the user cache: the values the grader compares with are
the exact replays' (as floats, to the bit), and a second reader (the grader after the
class's STACK export, in another process) finds them without solving again."""

from __future__ import annotations

import dataclasses
import sys

import numpy as np
import pytest

import rigidsym.course.worked as worked
from rigidsym.course.grading import grade, key_array, replayed_values
from rigidsym.course.slips import replays
from rigidsym.course.worked import solve


def _no_solve(*args, **kwargs):
    raise AssertionError("solved again: the kept replays were not read")


def test_replayed_values_are_the_exact_replays_as_compared():
    s = solve("3.19")
    kept = replayed_values(s)
    fresh = list(replays(s))
    assert len(kept) >= 3                      # 3.19 has unit and sign slips of its data
    assert_compared_as_exact(kept, fresh)


def assert_compared_as_exact(compared: list, exact: list, zero: float = 0.0) -> None:
    """Replays whose answers are as the grader compares them (``compared``) against the
    exact replays (``exact``, of :func:`replays`): the same slips in the same order, each
    value the exact one's float array to the bit; an entry within ``zero`` of 0 may be
    written 0 (a replay on floating data)."""
    assert [(w, d) for w, d, _ in compared] == [(w, d) for w, d, _ in exact]
    for (_, detail, got), (_, _, answers) in zip(compared, exact, strict=True):
        assert set(got) == set(answers), detail
        for name, v in answers.items():
            if isinstance(v, str):
                assert got[name] == v
                continue
            try:
                want = key_array(v)
            except TypeError:
                assert got[name] is None
                continue
            g = got[name]
            assert g.shape == want.shape and g.dtype == np.float64, (detail, name)
            written_zero = (g == 0) & (np.abs(want) <= zero)
            # the same bits: the same STACK literals
            assert np.array_equal(np.where(written_zero, want, g), want), (detail, name, g, want)


def test_kept_replays_are_read_back_by_data_not_by_modules_imported(monkeypatch):
    """The entry is found by another solution object on the same data, after a book module
    that the exercise imports only to draw is imported (a grading process and an exam
    process hold different modules), without a solve."""
    draw = "rigidsym.derivations.exercises._draw"
    monkeypatch.delitem(sys.modules, draw, raising=False)
    s = solve("3.19")
    first = replayed_values(s)
    __import__(draw)
    monkeypatch.setattr(worked, "solve", _no_solve)
    again = replayed_values(dataclasses.replace(s))
    assert [(w, d) for w, d, _ in again] == [(w, d) for w, d, _ in first]
    for (_, _, a), (_, _, b) in zip(again, first, strict=True):
        assert all(np.array_equal(a[n], b[n]) if isinstance(b[n], np.ndarray) else a[n] == b[n]
                   for n in b)


def test_grade_names_a_replayed_slip_from_the_kept_values(monkeypatch):
    """A wrong answer that only a replay explains (a length of 3.19 typed in mm along the
    way) is named by the grader that solves the replays and, the same, by a second grader
    that reads them back (no solve)."""
    s = solve("3.19")
    word, detail, answers = next((w, d, a) for w, d, a in replays(s) if w == "unit")
    name = next(n for n, v in answers.items() if n in s.answers and not isinstance(v, str)
                and not np.allclose(key_array(v), key_array(s.answers[n]))
                and not any(np.allclose(key_array(v), key_array(s.answers[n]) * 10.0 ** k)
                            for k in (-15, -9, -6, -4, -3, -2, 2, 3, 4, 6, 9, 15)))
    given = {name: key_array(answers[name]).tolist()}
    solved = {g.name: g for g in grade(s, given)}[name]
    replayed_values(s)                        # kept (already, or now)
    monkeypatch.setattr(worked, "solve", _no_solve)
    kept = {g.name: g for g in grade(dataclasses.replace(s), given)}[name]
    assert solved.correct is False and solved.note == "unit (along the way)"
    assert (kept.correct, kept.slip, kept.detail, kept.note) == \
        (solved.correct, solved.slip, solved.detail, solved.note)


if __name__ == "__main__":
    sys.exit(pytest.main([__file__, "-q"]))
