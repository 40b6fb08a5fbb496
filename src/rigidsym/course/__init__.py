"""The course: the chapter's exercises worked and machine-checked, graded, set as exams.

One front door: the command line and :mod:`rigidsym.exercises` take every name they need
from here. A name is imported from its module when first asked for (PEP 562), so that
importing the worked-exercise framework (``rigidsym.course.worked``, which the book's
exercises do) does not load the grader, the exam writer or the notebooks.

The package, by concept:

* ``worked/``: the worked-exercise framework (steps, answers, machine checks; the given
  data, numbers and units a student writes; rendering; the solution store);
* ``exercises``: solve, draw, grade, write a notebook, set an exam (the public functions,
  re-exported by :mod:`rigidsym.exercises`);
* ``grading``, ``grading_units``, ``slips``, ``answer_classes``: one student's answers
  against a worked solution, units converted, each answer judged by its class (what it
  means: an axis and angle, a point of a line, principal axes), the slip of a wrong
  answer named;
* ``exam``, ``exam_text``, ``roster``: exam sets (a handout and a key from a spec; what a
  handout says; a class from a roster, one exam per student);
* ``answers``, ``matching``, ``gradebook``: students' answer files read and matched to the
  roster (by id, then by folded name), a class graded, the LMS export;
* ``stack_export``: the class as Moodle STACK questions whose response trees grade each
  box as the gradebook does (linked boxes jointly);
* ``notebooks``, ``exercise_report``: a notebook per exercise, the exercises in the report;
* ``forked``: a class's work mapped over forked worker processes.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the edges the lazy names stand for, as import-linter and mypy see them
    from rigidsym.course.answers import read_answers
    from rigidsym.course.exercise_report import rendered
    from rigidsym.course.exercises import (
        EXERCISE_IDS,
        Graded,
        IllPosed,
        Param,
        Parameters,
        Solution,
        figure,
        grade,
        parameters,
        solve,
        write_notebook,
    )
    from rigidsym.course.exercises import exam as write_exam
    from rigidsym.course.gradebook import grade_class
    from rigidsym.course.notebooks import (
        NOTEBOOK_DIR,
        check_files,
        file_name,
        notebook_files,
        write_files,
    )
    from rigidsym.course.roster import class_exam
    from rigidsym.course.worked import (
        exercise_module,
        normalise_id,
        render_text,
        solution_record,
    )
    from rigidsym.course.worked import parameters as exercise_parameters
    from rigidsym.course.worked import solve as solve_exercise
    from rigidsym.course.worked.data import read_data
    from rigidsym.course.worked.numbers import split_text
    from rigidsym.course.worked.render import display
    from rigidsym.course.worked.units import split_unit

#: public name -> the module of this package that defines it (``module:name`` where the front
#: door's name differs: the framework's own ``solve`` and ``parameters``, on a normalised id,
#: beside the public ones of :mod:`rigidsym.exercises`)
FRONT_DOOR = {
    **dict.fromkeys(("EXERCISE_IDS", "Graded", "IllPosed", "Param", "Parameters", "Solution",
                     "figure", "grade", "parameters", "solve", "write_notebook"),
                    "exercises"),
    # the submodule course/exam.py keeps the name exam: the function is served as write_exam
    "write_exam": "exercises:exam",
    **dict.fromkeys(("exercise_module", "normalise_id", "render_text", "solution_record"),
                    "worked"),
    "read_data": "worked.data", "split_text": "worked.numbers", "display": "worked.render",
    "split_unit": "worked.units", "read_answers": "answers", "grade_class": "gradebook",
    "class_exam": "roster", "rendered": "exercise_report",
    "solve_exercise": "worked:solve", "exercise_parameters": "worked:parameters",
    **dict.fromkeys(("NOTEBOOK_DIR", "check_files", "file_name", "notebook_files",
                     "write_files"), "notebooks"),
}

__all__ = ["EXERCISE_IDS", "Graded", "IllPosed", "NOTEBOOK_DIR", "Param", "Parameters",
           "Solution", "check_files", "class_exam", "display", "exercise_module",
           "exercise_parameters", "figure", "file_name", "grade", "grade_class", "normalise_id",
           "notebook_files", "parameters", "read_answers", "read_data", "render_text",
           "rendered", "solution_record", "solve", "solve_exercise", "split_text", "split_unit",
           "write_exam", "write_files", "write_notebook"]


def __getattr__(name: str):
    """A front-door name, imported from its module on first use.

    Raises:
        AttributeError: ``name`` is not a front-door name (nor a submodule).
    """
    where = FRONT_DOOR.get(name)
    if where is None:
        raise AttributeError(f"module 'rigidsym.course' has no attribute {name!r}")
    module, _, attr = where.partition(":")
    # looked up at each use, not cached here: a name rebound in its module (a test's
    # monkeypatch, a reload) is what the front door serves, as a direct import would be
    return getattr(importlib.import_module(f"rigidsym.course.{module}"), attr or name)


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(FRONT_DOOR))
