"""Worked-solution framework for the chapter's exercises: steps, answers, machine checks.

A solution is data (:class:`Solution`): the statement with its citation, the given data,
named steps (a sympy expression and one sentence of why), the answers (exact, floats
beside them when rendered) and machine checks that do not reuse the solution path
(:mod:`.checks`). The given data are declared parameters (:mod:`.params`, read
by :mod:`.data`, numbers read exactly by :mod:`.numbers`, units by :mod:`.units`), so a
solution re-runs on a student's data; :mod:`.render` renders solutions (text, Markdown,
HTML, LaTeX) and :mod:`.solution_store` keeps solved ones on disk. Deciding truth is never
done here by ``simplify()``: identities go to :func:`rigidsym.zero.decide.decide_zero`;
closed algebraic numbers to their minimal polynomial.
"""

from __future__ import annotations

import importlib
import importlib.util
import os
import pkgutil
import re
from collections import OrderedDict
from collections.abc import Callable
from contextlib import contextmanager
from dataclasses import dataclass, field

from rigidsym.course.worked import solution_store
from rigidsym.course.worked.checks import (  # noqa: F401
    DIGITS,
    Check,
    Undecided,
    algebraic_zero,
    exact_check,
    for_values,
    identity_check,
    is_zero,
    nonidentity_check,
    settled,
    truth_check,
    values_only,
)
from rigidsym.course.worked.data import IllPosed, Param, Parameters, read_data, read_value  # noqa: F401
from rigidsym.course.worked.render import (
    render_html,
    render_latex,
    render_markdown,
    render_text,
    solution_record,
    to_json_value,
)

__all__ = [
    "Step",
    "Check",
    "Solution",
    "Param",
    "Parameters",
    "IllPosed",
    "TooLong",
    "EXERCISE_IDS",
    "measured_in_words",
    "normalise_id",
    "exercise_module",
    "parameters",
    "solve",
    "solve_values",
    "values_only",
    "settled",
    "Undecided",
    "read_value",
    "read_data",
    "is_zero",
    "identity_check",
    "nonidentity_check",
    "algebraic_zero",
    "truth_check",
    "exact_check",
    "to_json_value",
    "solution_record",
    "render_text",
    "render_markdown",
    "render_html",
    "render_latex",
]

#: the book's exercises (``ex3.1`` ... for the chapter): one per module ``exN_MM`` of its
#: exercises package (:data:`rigidsym.core.config.EXERCISES`), in book order
EXERCISE_IDS: list[str]
_EXERCISE_MODULE = re.compile(r"ex(\d+)_(\d+)")


def _exercise_ids() -> list[str]:
    """The ids of the modules ``exN_MM`` of the book's exercises package, found without
    importing it (it imports this module) or the book's package above it (which imports
    every declaration: a command's first words come before that work)."""
    parent, _, leaf = _exercises_package().rpartition(".")
    spec = importlib.util.find_spec(parent)  # the package found, not run
    where = [os.path.join(p, leaf) for p in (spec.submodule_search_locations or [])] \
        if spec else []
    found = [(int(m[1]), int(m[2])) for x in pkgutil.iter_modules(where)
             if (m := _EXERCISE_MODULE.fullmatch(x.name))]
    return [f"ex{c}.{k}" for c, k in sorted(found)]


def __getattr__(name: str):
    if name == "EXERCISE_IDS":  # read once, when first asked (the book is loaded by name)
        ids = _exercise_ids()
        globals()["EXERCISE_IDS"] = ids
        return ids
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


@dataclass
class Step:
    """One named step: an expression and why it is taken."""

    name: str
    expr: object
    why: str


@dataclass
class Solution:
    """A worked solution of one exercise.

    Attributes:
        id: ``"ex3.10"``.
        title: a short title.
        statement: a short quotation of the exercise.
        citation: where the statement is (book, section, exercise).
        given: the data, by name (exact sympy values or short strings).
        steps: the solution, in order.
        answers: the final answers by name (exact sympy values; matrices allowed).
        checks: machine checks of the answers (independent of the solution path).
        assumptions: data not in the project's source (chapter 3 converted to text,
            without its figures; chapter 2 is not in it), and caveats.
        status: ``"solved"``, ``"partial"``, ``"ill-posed"`` (the data admit no
            answer, or more than one; the steps end at the one that fails) or ``"not
            solved"`` (a case the solver does not handle: its limit, not the data's).
        extra: free-form rendered text (tables) appended after the answers.
        reason: for an ill-posed or not solved solution, why, in one sentence.
        floats: the data given as floats (measurements); rendering then shows long
            exact numbers to 10 digits.
        data: the data solved on, by parameter name (exact sympy values; the book's
            values where none was given), as :func:`solve` read them.
        tol: the tolerance of measured data, or None (exact data).
        values_only: the answers are 50-digit floats of a slip's replay for its values
            only (``rigidsym.course.worked.solve_values``): its checks were not run.
    """

    id: str
    title: str
    statement: str
    citation: str
    given: dict = field(default_factory=dict)
    steps: list = field(default_factory=list)
    answers: dict = field(default_factory=dict)
    checks: list = field(default_factory=list)
    assumptions: list = field(default_factory=list)
    status: str = "solved"
    extra: str = ""
    reason: str = ""
    floats: tuple = ()
    data: dict = field(default_factory=dict)
    tol: object = None
    values_only: bool = False

    @property
    def checked(self) -> bool:
        """True when there is at least one check and every check passed."""
        return bool(self.checks) and all(c.passed for c in self.checks)

    def step(self, name: str, expr, why: str):
        """Append a step and return its expression (so derivations read top-down)."""
        self.steps.append(Step(name, expr, why))
        return expr

    def check(self, c: Check) -> Check:
        """Append a check and return it."""
        self.checks.append(c)
        return c

    def fail(self, reason: str):
        """End the solution here: the data make the exercise ill-posed.

        Raises:
            IllPosed: always, carrying this solution and ``reason`` (one sentence);
                :func:`solve` returns the solution.
        """
        self.status = "ill-posed"
        self.reason = reason
        raise IllPosed(self, reason)

    def not_solved(self, reason: str):
        """End the solution here: the data may well have an answer, but this solver does
        not handle their case (a limit of the solver, never blamed on the data).

        Raises:
            IllPosed: always (the exception that ends a solution), with ``status ==
                "not solved"`` and ``reason`` starting "not solved for these data: ".
        """
        self.status = "not solved"
        self.reason = f"not solved for these data: {reason}"
        raise IllPosed(self, self.reason)

    def __repr__(self) -> str:
        verdict = (f"checked={self.checked}" if self.status not in ("ill-posed", "not solved")
                   else self.reason)
        return f"<Solution {self.id} {self.title!r}: {self.status}, {verdict}>"

    def _repr_html_(self) -> str:
        return render_html(self)

    def _repr_latex_(self) -> str:
        return render_latex(self)


# --------------------------------------------------------------------------- registry
def normalise_id(text: str) -> str:
    """``"3.10"``, ``"ex3.10"``, ``"3.01"`` -> ``"ex3.10"``: one of :data:`EXERCISE_IDS`.

    Raises:
        ValueError: if ``text`` names no exercise of the book (naming its first and last).
    """
    ids = globals().get("EXERCISE_IDS") or __getattr__("EXERCISE_IDS")
    t = text.strip().lower()
    if t.startswith("ex"):
        t = t[2:]
    try:
        chap, num = (int(x) for x in t.split("."))
    except ValueError:
        raise ValueError(f"expected an exercise id like {ids[0][2:]} or {ids[0]}, got "
                         f"{text!r}") from None
    if f"ex{chap}.{num}" not in ids:
        raise ValueError(f"expected an exercise {ids[0][2:]} ... {ids[-1][2:]}, got {text!r}")
    return f"ex{chap}.{num}"


def _exercises_package() -> str:
    """The configured package of the worked exercises (the machinery reaches the book by
    name, never by a static import)."""
    from rigidsym.core import config as _config

    return _config.EXERCISES


def exercise_module(ex_id: str):
    """The module of exercise ``ex_id`` (``PARAMETERS``, ``solve``, optional ``figure``).

    Raises:
        ValueError: if ``ex_id`` names no exercise of the chapter.
    """
    chap, k = (int(x) for x in normalise_id(ex_id)[2:].split("."))
    return importlib.import_module(f"{_exercises_package()}.ex{chap}_{k:02d}")


def parameters(ex_id: str) -> Parameters:
    """The given data of exercise ``ex_id``: names, the book's values, shapes, meanings.

    An exercise with no numeric data (a proof for every body, line or motion) gives an
    empty table and a sentence saying so.

    Raises:
        ValueError: if ``ex_id`` names no exercise of the chapter.
    """
    ex_id = normalise_id(ex_id)
    mod = exercise_module(ex_id)
    rows = tuple(getattr(mod, "PARAMETERS", ()))
    note = getattr(mod, "DATA_NOTE", "") or (
        "the book's data; change any of them" if rows else
        "no numeric data: the exercise is stated for every body, line or motion, so "
        "there is nothing to vary")
    return Parameters(ex_id, rows, note, bool(getattr(mod, "MEASURED", False)),
                      getattr(mod, "default_tol", None), tuple(getattr(mod, "READINGS", ())))


def measured_in_words() -> str:
    """The exercises whose data are measurements (their module's ``MEASURED``), in words:
    ``"3.1, 3.4 and 3.19"``."""
    ids = [i[2:] for i in globals().get("EXERCISE_IDS") or __getattr__("EXERCISE_IDS")
           if getattr(exercise_module(i), "MEASURED", False)]
    return ", ".join(ids[:-1]) + (" and " if len(ids) > 1 else "") + (ids[-1] if ids else "none")


#: CPU seconds one exact solve may take before its data are refused (a student's exact data
#: can multiply radicals past any useful size; the book's data take 4 s at most)
SOLVE_BUDGET = 20.0


class TooLong(ValueError):
    """The exact solution on the data did not finish within :data:`SOLVE_BUDGET`."""


@contextmanager
def _time_budget(seconds: float, ex_id: str):
    """Interrupt the solve after ``seconds`` of CPU time (a SIGPROF timer, so a loaded
    machine does not refuse good data: the main thread on POSIX; elsewhere no budget).
    sympy is pure Python, so the interrupt lands between steps."""
    import signal
    import threading

    if (seconds <= 0 or not hasattr(signal, "setitimer")
            or threading.current_thread() is not threading.main_thread()):
        yield
        return

    def stop(signum, frame):
        raise _Stop
    old = signal.signal(signal.SIGPROF, stop)
    # repeated each second: a BaseException is not swallowed by sympy's `except
    # Exception`, and should one be caught anyway the next tick stops the solve
    signal.setitimer(signal.ITIMER_PROF, seconds, 1.0)
    try:
        yield
    except _Stop:
        raise TooLong(f"{ex_id}: the exact solution on these data did not finish in "
                      f"{seconds:g} s (their radicals and digits multiply); give shorter "
                      f"numbers or fewer distinct square roots, or floats where the "
                      f"exercise takes measurements (Exercises {measured_in_words()})") from None
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, old)


class _Stop(BaseException):
    """The budget's interrupt (a BaseException, so no `except Exception` swallows it)."""


#: solutions by exercise and data, most recent last (bounded: a student varies the data)
_CACHE: OrderedDict[tuple, Solution] = OrderedDict()
_CACHE_SIZE = 64


def solve(ex_id: str, tol=None, **data) -> Solution:
    """The worked solution of exercise ``ex_id`` on the book's data or on ``data``.

    Args:
        ex_id: ``"ex3.4"``, ``"3.4"``.
        tol: compatibility tolerance of measured data (Exercises 3.1, 3.4, 3.5, 3.6, 3.7,
            3.14, 3.19 only);
            by default ``10^-3`` times the largest magnitude among the data when any
            datum is a float, and exact compatibility otherwise.
        **data: values of the exercise's parameters (:func:`parameters`); the others
            keep the book's values. See :func:`read_value` for what a value may be.

    Returns:
        The :class:`Solution` (cached on the exercise and the data). Data that make the
        exercise ill-posed give a solution with ``status == "ill-posed"`` that ends at
        the failing step, ``reason`` saying why in one sentence.

    Raises:
        ValueError: an unknown exercise, a bad shape or value; :class:`TooLong` when the
            exact solve exceeds :data:`SOLVE_BUDGET` seconds.
        TypeError: an unknown parameter name or a bad type (the message names it).
    """
    ex_id = normalise_id(ex_id)
    params = parameters(ex_id)
    d = read_data(params, data, tol)
    key = (ex_id, d.key())
    if key in _CACHE:
        _CACHE.move_to_end(key)
        return _CACHE[key]
    book = not data and tol is None  # the book's data: kept on disk too (the report's)
    where = solution_store.path(ex_id, exercise_module(ex_id).__name__, d) if book else None
    s = solution_store.stored(where, ex_id, Solution) if where else None
    if s is None:
        s = _solved(ex_id, params, d)
        if where:
            solution_store.store(where, s)
    _CACHE[key] = s
    while len(_CACHE) > _CACHE_SIZE:
        _CACHE.popitem(last=False)
    return s


def solve_values(ex_id: str, tol=None, **data) -> Solution:
    """The solution of ``ex_id`` on ``data`` for its answers' values only (a slip's replay,
    of which the grader and the STACK export compare floats): where the exercise's module
    says ``VALUES_REPLAY = True`` and the data are exact (no ``tol``), its solver runs on the
    data as :data:`~.checks.DIGITS`-digit floats inside :func:`~.checks.for_values` (its
    checks not run, its closed forms not simplified, each decision taken only on a value
    clear of 0), and the solution has ``values_only`` set; otherwise, or when a decision is
    too close to call (:class:`~.checks.Undecided`), or the float solve ends otherwise than
    solved (ill-posed, or an error sympy raises on floats), it is :func:`solve`'s exact
    solution.

    Args:
        ex_id, tol, data: as :func:`solve` takes them.

    Returns:
        The :class:`Solution` (source: the exercise module's ``solve``); a values-only one
        is not cached (each replay's data differ), its data are the exact ones read.

    Raises:
        ValueError: as :func:`solve` (:class:`TooLong` when either solve exceeds
            :data:`SOLVE_BUDGET`).
        TypeError: as :func:`solve`.
    """
    ex_id = normalise_id(ex_id)
    params = parameters(ex_id)
    d = read_data(params, data, tol)
    if d.tol is not None or not getattr(exercise_module(ex_id), "VALUES_REPLAY", False):
        return solve(ex_id, tol=tol, **data)
    floats = {k: _floated(v) for k, v in d.values.items()}
    try:
        with for_values():
            s = _solved(ex_id, params, d, floats)
    except TooLong:
        raise                           # the exact solve would take longer still
    except (Undecided, Exception):  # noqa: BLE001 -- any other end of the float solve: exact
        s = None
    if s is None or s.status != "solved":
        return solve(ex_id, tol=tol, **data)
    s.values_only = True
    return s


def _floated(v):
    """A datum as :data:`~.checks.DIGITS`-digit floats (a matrix entry by entry); text kept."""
    import sympy as sp

    if isinstance(v, sp.MatrixBase):
        return v.applyfunc(lambda x: sp.N(x, DIGITS))
    return sp.N(v, DIGITS) if isinstance(v, sp.Basic) and v.is_number else v


def _solved(ex_id: str, params: Parameters, d, values: dict | None = None) -> Solution:
    """Solve ``ex_id`` on the read data ``d`` (see :func:`solve`); ``values``: the data the
    solver is given instead of ``d.values`` (:func:`solve_values`)."""
    from rigidsym.core import work as _work

    _work.count("solve", ex_id)
    solver: Callable[..., Solution] = exercise_module(ex_id).solve
    kwargs = dict(d.values if values is None else values,
                  **({"tol": d.tol} if params.measured else {}))
    try:
        with _time_budget(SOLVE_BUDGET, ex_id):
            s = solver(**kwargs)
    except IllPosed as exc:
        s = exc.solution
    except OverflowError:
        # sympy's exact arithmetic gave up on integers past a float's range (factoring a
        # minimal polynomial's coefficients): too large for the exact path, as a timeout
        raise TooLong(f"{ex_id}: the exact solution on these data needs integers too large "
                      f"for sympy's exact arithmetic; give shorter numbers, or floats where "
                      f"the exercise takes measurements (Exercises "
                      f"{measured_in_words()})") from None
    s.assumptions.extend(d.notes)
    s.floats, s.data, s.tol = d.floats, dict(d.values), d.tol
    return s
