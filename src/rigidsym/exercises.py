"""The chapter-3 exercises, to run, see and vary: solve on your own data, draw, check.

A thin front to the worked-exercise framework: the exercises themselves are reached by
their configured module name, as the machinery reaches the book. The functions live in
:mod:`rigidsym.course.exercises`, the course's package; this module is their public name.

Example:
    >>> import rigidsym.exercises as ex
    >>> ex.parameters("ex3.4").names
    ['n_1', 'f_1', 'n_2', 'f_2']
    >>> s = ex.solve("ex3.4", f_2=[1, 1, 1])      # readings that are not compatible
    >>> s.status
    'ill-posed'
"""

from rigidsym.course.exercises import EXERCISE_IDS as _EXERCISE_IDS
from rigidsym.course.exercises import (
    Graded,
    IllPosed,
    Param,
    Parameters,
    Solution,
    exam,
    figure,
    grade,
    parameters,
    solve,
    write_notebook,
)

#: The ids of the chapter's exercises in order, ``"ex3.1"`` to ``"ex3.21"``.
EXERCISE_IDS = _EXERCISE_IDS

__all__ = ["solve", "parameters", "figure", "write_notebook", "grade", "exam",
           "EXERCISE_IDS", "Solution", "Parameters", "Param", "IllPosed", "Graded"]
