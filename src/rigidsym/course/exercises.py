"""The chapter-3 exercises, to run, see and vary: solve on your own data, draw, check, grade,
set an exam. The public face is :mod:`rigidsym.exercises` (these functions, re-exported);
the command line reaches them through the front door :mod:`rigidsym.course`.

A thin front to the worked-exercise framework: the exercises themselves are reached by
their configured module name, as the machinery reaches the book.

Example:
    >>> import rigidsym.exercises as ex
    >>> ex.parameters("ex3.4").names
    ['n_1', 'f_1', 'n_2', 'f_2']
    >>> s = ex.solve("ex3.4", f_2=[1, 1, 1])      # readings that are not compatible
    >>> s.status
    'ill-posed'
"""

from __future__ import annotations

from pathlib import Path

from rigidsym.course import worked as _worked
from rigidsym.course.grading import Graded
from rigidsym.course.worked import (
    IllPosed,
    Param,
    Parameters,
    Solution,
    exercise_module,
    normalise_id,
)

__all__ = ["solve", "parameters", "figure", "write_notebook", "grade", "exam",
           "EXERCISE_IDS", "Solution", "Parameters", "Param", "IllPosed", "Graded"]

#: The ids of the chapter's exercises in order, ``"ex3.1"`` to ``"ex3.21"``.
EXERCISE_IDS = _worked.EXERCISE_IDS


def solve(exercise: str, /, *, tol=None, **data) -> Solution:
    """Solve exercise ``exercise`` of chapter 3 on the book's data or on ``data``.

    Every step, answer and machine check is recomputed on the data; the checks stay
    independent of the solution path.

    Args:
        exercise: ``"ex3.4"``, ``"3.4"``.
        tol: tolerance for measured (float) data, in the data's units (Exercises 3.1, 3.4,
            3.5, 3.6, 3.7, 3.14, 3.19); default: set from the data and stated in the
            solution. Given for exact data, it also selects the measured (least-squares)
            path.
        **data: the exercise's parameters by name (see :func:`parameters`): a scalar is an
            int, a ``Fraction``, a decimal string (``"0.1"`` is 1/10), a string such as
            ``"sqrt(3)/2"``, a sympy number, or a float (a measurement, converted exactly);
            a vector is 3 (or 6) of them (list, tuple, NumPy array, sympy Matrix); a matrix
            3 rows of 3. Units as :func:`parameters` lists them (SI: m, N, N m, kg m^2).

    Returns:
        The :class:`Solution`: ``steps``, ``answers`` (exact sympy; vectors as 3 x 1
        matrices), ``checks``, ``status`` (``"solved"``, or ``"ill-posed"`` with
        ``reason``, one sentence, when the data admit no answer). It displays itself as
        HTML with MathML in a notebook. Cached on the exercise and the data.

    Raises:
        ValueError: ``exercise`` names no exercise 3.1-3.21; a value has the wrong shape,
            is not a finite real number, or ``tol <= 0``.
        TypeError: an unknown parameter name, a value of the wrong type, or ``tol`` for
            an exercise whose data are not measurements. Messages name the parameter.
    """
    # looked up at the call (not bound at import): the one solver, whoever replaced it
    return _worked.solve(exercise, tol=tol, **data)


def parameters(exercise: str) -> Parameters:
    """The given data of ``exercise``: name, the book's value, shape, unit and meaning.

    Args:
        exercise: ``"ex3.4"``, ``"3.4"``.

    Returns:
        A :class:`Parameters` table (iterable of :class:`Param`; ``.names``,
        ``.defaults()``; shown as a table in a notebook). The ten exercises with no
        numeric data (3.3, 3.8, 3.9, 3.13, 3.15-3.18, 3.20, 3.21) give an empty table and
        a sentence (``.note``).

    Raises:
        ValueError: ``exercise`` names no exercise 3.1-3.21.
    """
    return _worked.parameters(exercise)


def figure(solution: Solution):
    """The figure of a solved exercise, drawn from its own data and answers.

    Args:
        solution: a :class:`Solution` from :func:`solve`.

    Returns:
        A :class:`matplotlib.figure.Figure` (3-D axes for the geometric exercises; not
        registered with pyplot), or ``None`` when the exercise has no figure or the
        solution is ill-posed.

    Raises:
        TypeError: if ``solution`` is not a :class:`Solution`.
    """
    if not isinstance(solution, Solution):
        raise TypeError(f"solution: expected a Solution from rigidsym.exercises.solve, got "
                        f"{type(solution).__name__}")
    draw = getattr(exercise_module(solution.id), "figure", None)
    if draw is None or solution.status != "solved":
        return None
    return draw(solution)


def write_notebook(exercise: str, path: str | Path, **data) -> Path:
    """Write the notebook of ``exercise`` to ``path``; with ``data``, its data cell holds
    them instead of the book's values (checked as :func:`solve` checks them).

    Args:
        exercise: ``"ex3.4"``, ``"3.4"``.
        path: the ``.ipynb`` file to write.
        **data: the exercise's parameters by name, as for :func:`solve`.

    Returns:
        The path written (atomically).

    Raises:
        ModuleNotFoundError: nbformat is missing (``pip install "rigidsym[notebooks]"``).
        ValueError, TypeError: as :func:`solve`, for the exercise id and the data.
        OSError: the file cannot be written.
    """
    from rigidsym.core.files import write_atomic
    from rigidsym.course.notebooks import notebook_text

    ex_id = normalise_id(exercise)
    return write_atomic(Path(path), notebook_text(ex_id, data or None))


def grade(solution: Solution, answers: dict) -> list[Graded]:
    """Grade a student's ``answers`` against ``solution``, naming the slip of a wrong one.

    Each answer is right or wrong within 0.1 % of its largest entry; a wrong one is
    compared with small edits of the right one (as the repair search edits a printed
    equation) and the first that matches names the slip: ``"transpose"``, ``"sign"``
    (whole, one component, or one term of the exercise), ``"degrees"``, ``"unit"`` (a
    power of ten: mm, cm, g, mm^2), ``"factor 2"`` (doubled or halved), ``"swap"`` (two
    entries, rows or columns) or
    ``"reference point"`` (the same quantity about another point of the body, where the
    exercise declares it: 3.11, 3.19); then the solution replayed with a slip along the
    way (``Q`` for ``Q^T``, a length in mm, a sign, frames swapped: ``"transpose"``,
    ``"unit"``, ``"sign"``, ``"frame"``); else the detail says "not a known slip". An
    answer left out or blank is missing (and wrong).

    Args:
        solution: a solved :class:`Solution` from :func:`solve` (the student's data).
        answers: answer name (as ``rigidsym exercise ID --json`` prints them) -> a number,
            an exact string such as ``"sqrt(3)/2"``, or nested lists of them.

    Returns:
        A list of :class:`Graded` (``name``, ``correct``, ``missing``, ``slip``,
        ``expected``, ``detail``; ``.as_dict()``), one per answer the solution asks, in
        its order.

    Raises:
        TypeError: ``solution`` is not a :class:`Solution`, or ``answers`` not a dict.
        ValueError: the solution is ill-posed, or an answer name it does not have.
    """
    from rigidsym.course.grading import grade as _grade

    if not isinstance(solution, Solution):
        raise TypeError(f"solution: expected a Solution from rigidsym.exercises.solve, got "
                        f"{type(solution).__name__}")
    if not isinstance(answers, dict):
        raise TypeError(f"answers: expected a dict {{name: value}}, got "
                        f"{type(answers).__name__}")
    return _grade(solution, answers)


def exam(spec, out_dir: str | Path, seed: int | None = None) -> dict[str, Path]:
    """Write an exam set from ``spec``: a student handout and an answer key.

    The spec (a TOML file, or the same as a dict) lists ``[[problem]]`` tables: an
    ``exercise`` with its ``data``, or ``variants = n`` random well-posed variants drawn
    from the seed, for every exercise: readable exact numbers (Cayley rotations of small
    rationals, Pythagorean unit vectors, small integers, short decimals), or, for the
    proofs, true-or-false statements decided by the zero test. A class from a roster:
    ``rigidsym exam SPEC --students ROSTER`` (:mod:`rigidsym.course.roster`). See
    ``docs/exams.md``.

    Args:
        spec: a ``.toml`` path or a dict (``title``, ``seed``, ``problem``).
        out_dir: the folder to write (made if missing).
        seed: the seed of the draws (default: the spec's ``seed``, else 0).

    Returns:
        ``{"handout": path, "key_html": path, "key_json": path}``: ``handout.html``
        (statement, data, a figure of the given data only, space for each answer; a
        print stylesheet; no answer), ``key.html`` (worked, checked solutions and their
        figures), ``key.json`` (schema 2: each problem's data, answers and checks).
        The same spec and seed write the same bytes.

    Raises:
        ValueError: a bad spec (the message names the problem), bad data, or a problem
            ill-posed on its data.
        TypeError: bad data (as :func:`solve`).
        OSError: the folder cannot be written.
    """
    from rigidsym.course.exam import exam as _exam

    return _exam(spec, out_dir, seed)
