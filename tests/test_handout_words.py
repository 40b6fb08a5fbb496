"""A handout's words are the book's data (``handout.toml`` beside its exercises), every key
checked when read: an exercise the file names is one the book has, and a file the course
cannot trust is an error naming it, never a handout with a missing label."""

from __future__ import annotations

import sys

import pytest

from rigidsym.core import config
from rigidsym.core.errors import BadInput
from rigidsym.course import exam_text
from rigidsym.course.worked import EXERCISE_IDS


def test_every_exercise_the_words_name_is_the_book_s():
    words = exam_text.handout_words()
    assert words and set(words) <= set(EXERCISE_IDS)
    assert all(w["boxes_of"] in words for w in words.values() if "boxes_of" in w)
    assert all(exam_text.task(i, "") == w["task"] for i, w in words.items() if "task" in w)


@pytest.fixture
def handout(tmp_path, monkeypatch):
    """A book whose exercises' package is a folder of the test's, its handout written."""
    pkg = tmp_path / "someones_exercises"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setattr(config, "EXERCISES", "someones_exercises")
    exam_text.handout_words.cache_clear()
    yield pkg / exam_text.HANDOUT
    exam_text.handout_words.cache_clear()
    sys.modules.pop("someones_exercises", None)  # the next test's folder is another


def test_another_book_s_words_label_its_boxes(handout):
    handout.write_text('[exercise."ex1.2"]\ntask = "Find x."\nasked = ["x"]\n'
                       '[exercise."ex1.2".boxes]\nx = "the root x (m)"\n'
                       '[[exercise."ex1.2".box_stems]]\nstem = "y_"\nwords = "y for "\n')
    assert exam_text.task("ex1.2", "its statement") == "Find x."
    assert exam_text.task("ex1.3", "its statement") == "its statement"
    assert exam_text.box_label("ex1.2", "x") == "the root x (m)"
    assert exam_text.box_label("ex1.2", "y_left") == "y for left"
    assert exam_text.answers_asked("ex1.2") == ("x",) and exam_text.answers_asked("ex1.3") is None


@pytest.mark.parametrize(("text", "says"), [
    ('[exercise."ex1.2"]\nhint = "x"\n', "unknown key 'hint'"),
    ('[exercise."ex1.2"]\nasked = "x"\n', "asked: expected a list"),
    ('[exercise."ex1.2".boxes]\nx = 1\n', "non-empty string"),
    ('[exercise."ex1.2"]\nbox_stems = [{stem = "y_"}]\n', "stem and its words"),
    ('[handout]\nx = 1\n', "tables only"),
    ('[exercise\n', "cannot read it"),
])
def test_words_the_course_cannot_trust_are_an_error_naming_the_file(handout, text, says):
    handout.write_text(text)
    with pytest.raises(BadInput, match=f"someones_exercises/handout.toml.*{says}"):
        exam_text.handout_words()
