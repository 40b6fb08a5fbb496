"""Grading a student's answers against a worked solution, naming the slip of a wrong one.

In the spirit of the repair search (:mod:`rigidsym.checking.repairing`): a wrong answer
is compared with small edits of the right one, and the first edit that explains it names
the slip: ``"transpose"`` (a matrix transposed), ``"sign"`` (the sign of the whole answer,
of one component, or of one term where the exercise lists its terms), ``"degrees"`` (an
angle in degrees for radians), ``"unit"`` (a factor that is a power of ten: mm, cm, g,
mm^2 for m, m, kg, m^2), ``"factor 2"`` (the answer doubled or halved: a diameter for a
radius, a half-angle formula's 2 dropped), ``"swap"`` (two components, rows or columns
exchanged) and ``"reference point"`` (the same quantity about another point of the body,
where the exercise declares one: its module's ``slips(solution)``). Else ``"not a known
slip"``. Only the slips the box's kind admits are tried (:mod:`.box_kinds`: a truth or a
reason number none, a length only its unit prefixes, an angle degrees), and a slip is
named only for an answer that is not trivial (zero, all entries equal, a datum echoed)
within the tolerance of the slipped key itself.

Numbers are compared in floating point within a stated tolerance: a grade is a judgement
on a student's decimals, not a proof; the expected values themselves are exact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import sympy as sp

from rigidsym.course.box_kinds import (
    admits,
    box_kind,
    replays_admitted,
    slip_close,
    slip_counts,
    trivial,
    unit_powers,
)
from rigidsym.course.grading_units import unit_off, unit_slip
from rigidsym.course.worked.numbers import read_text, split_text
from rigidsym.course.worked.units import answer_unit

__all__ = ["grade", "Graded", "RTOL", "SLIPS", "is_blank", "answer_shape", "gradeable",
           "rounded_figures", "read_decimal_comma", "AmbiguousNumber", "key_array",
           "compared_answers", "replayed_values", "slip_values"]

#: relative tolerance: an answer is right within 0.1 % of its largest entry
RTOL = 1e-3
#: the slip words, in the order they are tried
SLIPS = ("transpose", "sign", "degrees", "unit", "factor 2", "swap", "order", "frame",
         "reference point", "rounded")
_TRUTH = {"true": 1.0, "t": 1.0, "yes": 1.0, "y": 1.0, "holds": 1.0,
          "false": 0.0, "f": 0.0, "no": 0.0, "n": 0.0, "fails": 0.0}


@dataclass
class Graded:
    """One graded answer.

    Attributes:
        name: the answer's name, as ``rigidsym exercise ID --json`` prints it.
        correct: within the tolerance (None when it could not be graded).
        slip: the slip word (one of :data:`SLIPS`), or None (right, or not a known slip).
        expected: the right answer, as the JSON key writes it.
        detail: one sentence (the tolerance, the slip's edit, or why not graded).
        missing: no answer given (absent or blank); then ``correct`` is False.
        note: the answer note (STACK's word): ``right``, ``equivalent (-e, -phi)``,
            ``sign``, ``transpose``, ``units mm→m``, ``rounded 2 s.f.``, ``order [f; n]``,
            ``blank``, ``not read``, ``ambiguous``, ``wrong``; the gradebook writes it
            as ``<exercise>/<answer>: <note>`` and counts each per exercise.
    """

    name: str
    correct: bool | None
    slip: str | None
    expected: object
    detail: str
    missing: bool = False
    note: str = ""

    def __post_init__(self):
        if not self.note:
            self.note = ("blank" if self.missing else "right" if self.correct else
                         "not graded" if self.correct is None else
                         "not read" if self.detail.startswith("not read") else
                         self.slip or "wrong")

    def as_dict(self) -> dict:
        """``{"name", "correct", "missing", "slip", "expected", "detail", "note"}``."""
        return {"name": self.name, "correct": self.correct, "missing": self.missing,
                "slip": self.slip, "expected": self.expected, "detail": self.detail,
                "note": self.note}


def is_blank(v) -> bool:
    """A blank answer: absent, ``None``, an empty or all-space string, an empty list."""
    return v is None or (isinstance(v, str) and not v.strip()) or \
        (isinstance(v, list | tuple) and not v)


def answer_shape(right) -> tuple:
    """The shape an answer is typed in, for :func:`~.worked.numbers.split_text` (the
    reader of ``--set``): ``()`` a number, ``(n,)`` a column, ``(r, c)`` a matrix."""
    if isinstance(right, sp.MatrixBase):
        return (right.rows,) if right.cols == 1 else (right.rows, right.cols)
    return ()


def _as_array(v, where: str, shape: tuple = ()) -> np.ndarray:
    """A student's value (number, exact string, nested lists) as a float array; a string
    for a vector or matrix answer is split as ``--set`` splits it (``0,0,1;1,0,0;0,1,0``)."""
    if isinstance(v, str) and shape and ("," in v or ";" in v):
        rows = ";" in v and len(shape) == 1           # a column typed as rows: 1;2;3
        return _as_array(split_text((shape[0], 1) if rows else shape, v), where)
    if isinstance(v, str) and v.strip().lower() in _TRUTH:
        return np.array(_TRUTH[v.strip().lower()])
    if isinstance(v, bool):
        return np.array(float(v))
    if isinstance(v, str):
        try:
            return np.array(float(v))      # a decimal: no bounds on a student's slip
        except ValueError:
            return np.array(float(read_text(v, where)[0]))
    if isinstance(v, int | float):
        return np.array(float(v))
    if isinstance(v, list | tuple):
        return np.array([_as_array(x, where) for x in v], dtype=float)
    raise TypeError(f"{where}: expected a number, an exact string such as 'sqrt(3)/2' or "
                    f"nested lists of them, got {type(v).__name__}")


#: the key's values as floats, by the identity of the sympy value (an exact key's nested
#: radicals take long to evaluate, and a class is graded box by box, student by student)
_FLOATS: dict[int, tuple] = {}


def _expected(v) -> np.ndarray:
    if isinstance(v, np.ndarray):         # a replay's value, already as compared
        return v.astype(float)
    hit = _FLOATS.get(id(v))
    if hit is not None and hit[0] is v:
        return hit[1].copy()
    out = _expected_now(v)
    if len(_FLOATS) > 4096:
        _FLOATS.clear()
    _FLOATS[id(v)] = (v, out)
    return out.copy()


def _expected_now(v) -> np.ndarray:
    if isinstance(v, sp.MatrixBase):
        return np.array(sp.N(v, 17).tolist(), dtype=float)
    if v in (sp.true, sp.false):
        return np.array(float(bool(v)))
    return np.array(float(sp.N(v, 17)))


def key_array(v) -> np.ndarray:
    """A key's value (a sympy number, truth or matrix) as the float array the grader
    compares with (17 digits; a matrix keeps its shape, an n x 1 column included)."""
    return _expected(v)


def slip_values(solution, name: str, target: np.ndarray, replay: bool = True,
                replayed: list | None = None) -> list[tuple[str, np.ndarray]]:
    """The values a wrong answer of box ``name`` is compared with, in the grader's order
    (:func:`grade` names the first that matches): the edits of ``target`` (the key, or
    the member of its class the grader compares with), the exercise's own slips (its
    module's ``slips(solution)``), then the solution replayed with a slip along the way
    (``replay``; ``replayed``: :func:`replayed_values` of the solution, when the caller asks
    for many boxes). Rounding (:func:`rounded_figures`) is tried after all of them.

    Returns:
        ``[(slip word, value as a float array), ...]``; a replay whose answer has another
        shape than ``target`` is left out (it could not match).
    """
    from rigidsym.course.worked import exercise_module

    module = exercise_module(solution.id)
    kind, unit = kind_of(module, name, solution.answers.get(name))
    own = getattr(module, "slips", None)
    extra = [(w, d, _expected(v)) for w, d, v in (own(solution) if own else {}).get(name, [])]
    out = [(w, v) for w, _, v in _candidates(target, name, extra, kind, unit)]
    if not replays_admitted(kind):
        return out
    for word, _, answers in (() if not replay else replayed if replayed is not None
                             else _Replays(solution)):
        value = answers.get(name)
        if value is None or isinstance(value, str):
            continue
        try:
            v = _expected(value)
        except TypeError:
            continue
        if v.shape == target.shape and slip_counts(v, target, RTOL):
            out.append((word, v))
    return out


def kind_of(module, name: str, right) -> tuple[str, str | None]:
    """``(kind, unit)`` of box ``name`` of an exercise ``module`` whose key is ``right``
    (:func:`rigidsym.course.box_kinds.box_kind`; the unit documented, or None)."""
    unit = answer_unit(module, name)
    return box_kind(module, name, right, unit), unit


def data_arrays(solution) -> list[np.ndarray]:
    """The solution's numeric data as float arrays (an answer that echoes one of them is
    trivial: :func:`rigidsym.course.box_kinds.trivial`)."""
    out = []
    for v in (getattr(solution, "data", None) or {}).values():
        if isinstance(v, list):
            try:
                v = sp.Matrix(v)
            except (TypeError, ValueError, sp.SympifyError):
                continue
        if not isinstance(v, sp.MatrixBase | sp.Expr) or isinstance(v, sp.Symbol):
            continue
        try:
            out.append(np.array(sp.N(v, 17).tolist() if isinstance(v, sp.MatrixBase)
                                else sp.N(v, 17), dtype=float))
        except (TypeError, ValueError, AttributeError):
            continue
    return out


def _close(a: np.ndarray, b: np.ndarray, scale: float) -> bool:
    return _close_plain(a, b, scale)


def _close_plain(a: np.ndarray, b: np.ndarray, scale: float) -> bool:
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= RTOL * scale + 1e-12))


def _candidates(e: np.ndarray, name: str, extra: list, kind: str = "vector",
                unit: str | None = None):
    """(slip, what the edit is, edited answer), in the order of :data:`SLIPS`: those a box
    of ``kind`` admits (:func:`rigidsym.course.box_kinds.admits`) whose edited answer can
    name a slip (:func:`rigidsym.course.box_kinds.slip_counts`: not near 0, not the key)."""
    for word, detail, value in _all_candidates(e, name, extra, kind, unit):
        if admits(kind, word) and slip_counts(value, e, RTOL):
            yield word, detail, value


def _all_candidates(e: np.ndarray, name: str, extra: list, kind: str, unit: str | None):
    if e.ndim == 2 and e.shape[0] == e.shape[1] > 1 and not np.allclose(e, e.T):
        yield "transpose", f"{name} transposed", e.T
    yield "sign", f"-{name}", -e
    flat = e.reshape(-1)
    for i in range(flat.size):
        if abs(flat[i]) > RTOL * float(np.max(np.abs(flat))) and flat.size > 1:
            f = flat.copy()
            f[i] = -f[i]
            yield "sign", f"the sign of entry {i} of {name}", f.reshape(e.shape)
    for word, detail, value in extra:
        if word == "sign":
            yield word, detail, value
    yield "degrees", f"{name} in degrees for radians", e * 180 / math.pi
    yield "degrees", f"{name} in radians for degrees", e * math.pi / 180
    for k in unit_powers(kind, unit):
        yield "unit", f"{name} x 10^{k} (a unit prefix: mm, cm, g, mm^2 for m, m, kg, m^2)", \
            e * 10.0**k
    yield "factor 2", f"{name} doubled", 2 * e
    yield "factor 2", f"{name} halved", e / 2
    if e.ndim == 2 and min(e.shape) > 1:
        for i in range(e.shape[0]):
            for j in range(i + 1, e.shape[0]):
                f = e.copy()
                f[[i, j]] = f[[j, i]]
                yield "swap", f"rows {i} and {j} of {name} exchanged", f
                g = e.copy()
                g[:, [i, j]] = g[:, [j, i]]
                yield "swap", f"columns {i} and {j} of {name} exchanged", g
    for i in range(flat.size):
        for j in range(i + 1, flat.size):
            if flat[i] != flat[j]:
                f = flat.copy()
                f[[i, j]] = f[[j, i]]
                yield "swap", f"entries {i} and {j} of {name} exchanged", f.reshape(e.shape)
    if e.shape in ((6, 1), (6,)):
        halves = "[f; n] for [n; f]" if name.startswith("w") else "[n; e] for [e; n]"
        yield "order", f"the halves of {name} exchanged (order {halves})", \
            np.concatenate([e[3:], e[:3]])
    for word, detail, value in extra:
        if word != "sign":
            yield word, detail, value


def _shown(v):
    """The key's value as the JSON key writes it (kept, as :func:`_expected`'s floats)."""
    from rigidsym.course.worked.render import to_json_value

    hit = _SHOWN.get(id(v))
    if hit is not None and hit[0] is v:
        return hit[1]
    if len(_SHOWN) > 4096:
        _SHOWN.clear()
    _SHOWN[id(v)] = (v, to_json_value(v))
    return _SHOWN[id(v)][1]


_SHOWN: dict[int, tuple] = {}


def grade(solution, answers: dict, slips: dict | None = None,
          replay: bool = True) -> list[Graded]:
    """Grade ``answers`` (name -> value) against ``solution``'s answers.

    Args:
        solution: a solved :class:`~rigidsym.course.worked.Solution`.
        answers: answer name -> a number, an exact string (``"sqrt(3)/2"``) or nested
            lists of them (a vector as 3 numbers or as a column).
        slips: answer name -> ``[(slip word, detail, sympy value), ...]``: the
            exercise's own slips (a term's sign, another reference point); default: its
            module's ``slips(solution)``.
        replay: also replay the solution with a slip injected along the way
            (:mod:`.slips`: ``Q`` for ``Q^T``, mm for m, a sign, frames swapped) when no
            slip of the final answer explains a wrong one.

    Returns:
        One :class:`Graded` per answer the solution asks for (its numeric answers, in the
        solution's order; an answer in words only when given): an answer absent or blank
        (:func:`is_blank`) is ``missing``, and wrong.

    Raises:
        ValueError: the solution is not solved (an ill-posed exercise has no answers), or
            an answer name the solution does not have (the message lists them).
    """
    if solution.status != "solved":
        raise ValueError(f"{solution.id} on these data is {solution.status}: there are no "
                         f"answers to grade against ({solution.reason})")
    known = [k for k, v in solution.answers.items() if not isinstance(v, str)]
    unknown = [k for k in answers if k not in solution.answers]
    if unknown:
        raise ValueError(f"answers: {solution.id} has no answer {unknown[0]!r}; its answers "
                         f"are: {', '.join(known)}")
    from rigidsym.course.worked import exercise_module

    module = exercise_module(solution.id)
    if slips is None:
        own = getattr(module, "slips", None)
        slips = own(solution) if own else {}
    replayed = _Replays(solution) if replay else None
    units = {name: answer_unit(module, name) for name in solution.answers}
    read = _read_all(solution, answers, units)
    data = data_arrays(solution)
    verdicts = _classes(module, solution, read)
    out = []
    for name, right in solution.answers.items():
        given = answers.get(name)
        if isinstance(right, str) or not gradeable(right):
            if name in answers:
                out.append(Graded(name, None, None, _shown(right),
                                  "an answer in words or a set: not graded by machine"))
            continue
        if is_blank(given):
            out.append(Graded(name, False, None, _shown(right),
                              "missing: no answer given", missing=True))
            continue
        if _symbols(right):
            out.append(_grade_expression(name, given, right))
            continue
        shown = _shown(right)
        got = read[name]
        if isinstance(got, Graded):
            out.append(got)
            continue
        v = verdicts.get(name)
        if v is not None and v.right:
            out.append(Graded(name, True, None, shown, got[2], note=v.note))
            continue
        kind = box_kind(module, name, right, units[name])
        if not replays_admitted(kind):     # a truth, a reason, a count: no slips
            out.append(_grade_exact(name, got, right, shown, kind))
            continue
        out.append(_grade_one(name, got, right, shown, (slips or {}).get(name, []),
                              replayed, units[name], v, kind, data))
    return out


def _read_all(solution, answers: dict, units: dict) -> dict:
    """Each numeric box's answer read: ``name -> (array of the key's shape, key array,
    tolerance text, unit written)``, or a :class:`Graded` (not read, ambiguous)."""

    out: dict = {}
    for name, right in solution.answers.items():
        given = answers.get(name)
        if isinstance(right, str) or not gradeable(right) or is_blank(given) or \
                _symbols(right):
            continue
        shown = _shown(right)
        e = _expected(right)
        try:
            given = read_decimal_comma(given, answer_shape(right), name)
            given, f, written = unit_off(given, units[name], name)
            g = _as_array(given, name, answer_shape(right)) * f
        except AmbiguousNumber as exc:
            out[name] = Graded(name, None, None, shown, f"ambiguous: {exc}",
                               note="ambiguous")
            continue
        except (ValueError, TypeError) as exc:
            out[name] = Graded(name, False, None, shown, f"not read: {exc}")
            continue
        if g.size == e.size and g.shape != e.shape:
            g = g.reshape(e.shape)        # a vector as 3 numbers, or as a column
        scale = max(float(np.max(np.abs(e))) if e.size else 0.0, 1e-300)
        tol = f"within {RTOL:g} x {scale:.3g} (0.1 % of the largest entry)"
        if written and written != units[name]:
            tol = f"read in {written}, converted to {units[name]}: {tol}"
        out[name] = (g, e, tol, written)
    return out


def _classes(module, solution, read: dict) -> dict:
    """The declared answers' verdicts (:mod:`.answer_classes`): ``name -> Verdict`` for
    each answered piece of a declared class; the pieces of one class judged jointly."""
    from rigidsym.course.answer_classes import data_names, declared, judge, names_of

    out = {}
    for decl in declared(module):
        names = names_of(decl)
        if not all(n in solution.answers for n in names):
            continue
        key = {n: _expected(solution.answers[n]) for n in names}
        if decl["kind"] == "point of line":
            key[decl["direction"]] = _expected(solution.answers[decl["direction"]])
        data = getattr(solution, "data", None) or {}
        if not all(d in data for d in data_names(decl)):
            continue
        key.update({d: np.array(sp.N(sp.Matrix(data[d]), 17).tolist(), dtype=float)
                    for d in data_names(decl)})
        given = {n: read[n][0] for n in names
                 if isinstance(read.get(n), tuple) and read[n][0].shape == key[n].shape}
        out.update(judge(decl, given, key, RTOL))
    return out


def gradeable(right) -> bool:
    """A number, a truth, an expression or a matrix of them (not a set, not words)."""
    if isinstance(right, sp.MatrixBase):
        return all(isinstance(x, sp.Expr) for x in right)
    return right in (sp.true, sp.false) or isinstance(right, sp.Expr)


def _symbols(right) -> list:
    """The free symbols of an answer that is an expression (3.10's W in the angles)."""
    if right in (sp.true, sp.false):
        return []
    return sorted(right.free_symbols, key=str)


#: the points at which an expression answer is compared (angles in radians, generic)
_POINTS = ((0.3, -0.7, 1.1, 0.45), (1.3, 0.4, -0.9, -1.2), (-0.8, 1.7, 0.25, 0.6))
_FUNCTIONS = {"sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "sqrt": sp.sqrt, "pi": sp.pi,
              "sec": sp.sec, "csc": sp.csc, "cot": sp.cot}


def _parse_expression(text: str, names: dict, where: str) -> sp.Expr:
    """A student's expression in the answer's own symbols and a few functions: checked
    character by character and name by name before sympy reads it (nothing else runs)."""
    import re

    t = text.strip().replace("^", "**")
    if len(t) > 400 or not re.fullmatch(r"[\w\s+\-*/().]*", t):
        raise ValueError(f"{where}: {text!r} is not an expression (allowed: numbers, "
                         f"{', '.join(sorted(names))}, {', '.join(sorted(_FUNCTIONS))}, "
                         f"+ - * / ^ and brackets)")
    for n in re.findall(r"[A-Za-z_]\w*", t):
        if n not in names and n not in _FUNCTIONS:
            raise ValueError(f"{where}: {n!r} is neither a symbol of the answer "
                             f"({', '.join(sorted(names))}) nor a known function")
    if "__" in t:
        raise ValueError(f"{where}: {text!r} is not an expression")
    return sp.sympify(t, locals={**_FUNCTIONS, **names})


def _grade_expression(name, given, right) -> Graded:
    """An answer that is an expression (or a matrix of them) in symbols: the student's
    expression equals it at three generic points within the tolerance; the slips of the
    final answer are tried as for numbers, at every point alike."""
    syms = _symbols(right)
    names = {str(s): s for s in syms}
    shown = to_json_value_light(right)
    shape = answer_shape(right)
    try:
        g = _expressions(given, shape, names, name)
        G = np.array([_at(g, syms, pt) for pt in _POINTS])
    except (ValueError, TypeError, ZeroDivisionError, sp.SympifyError) as exc:
        return Graded(name, False, None, shown, f"not read: {exc}")
    E = np.array([_at(right, syms, pt) for pt in _POINTS])
    if G.size == E.size and G.shape != E.shape:
        G = G.reshape(E.shape)
    scale = max(float(np.max(np.abs(E))), 1e-300)
    tol = (f"equal at {len(_POINTS)} generic values of {', '.join(names)}, within "
           f"{RTOL:g} x {scale:.3g}")
    if _close(G, E, scale):
        return Graded(name, True, None, shown, tol)
    per_point = [list(_candidates(E[k], name, [])) for k in range(len(_POINTS))]
    for i, (word, detail, _) in enumerate(per_point[0]):
        if all(i < len(c) and c[i][:2] == (word, detail)
               and _close(G[k], c[i][2], max(scale, float(np.max(np.abs(c[i][2])))))
               for k, c in enumerate(per_point)):
            return Graded(name, False, word, shown, f"matches {detail}")
    return Graded(name, False, None, shown, f"not {tol}, and not a known slip")


def _expressions(v, shape, names, where):
    if isinstance(v, str) and shape and ("," in v or ";" in v):
        rows = ";" in v and len(shape) == 1
        v = split_text((shape[0], 1) if rows else shape, v)
    if isinstance(v, list | tuple):
        return sp.Matrix([_expressions(x, (), names, where) if not isinstance(x, list | tuple)
                          else [_expressions(y, (), names, where) for y in x] for x in v])
    if isinstance(v, bool):
        raise TypeError(f"{where}: expected an expression, got a truth")
    if isinstance(v, int | float):
        return sp.Float(v) if isinstance(v, float) else sp.Integer(v)
    if isinstance(v, str):
        return _parse_expression(v, names, where)
    raise TypeError(f"{where}: expected an expression or nested lists of them, got "
                    f"{type(v).__name__}")


def _at(expr, syms, point) -> np.ndarray:
    vals = {s: point[k % len(point)] for k, s in enumerate(syms)}
    e = expr.subs(vals) if syms else expr
    out = np.array(sp.N(e, 17).tolist() if isinstance(e, sp.MatrixBase) else sp.N(e, 17),
                   dtype=float)
    return out


def to_json_value_light(v):
    """The expected answer as the key writes it (``str`` of sympy values)."""
    from rigidsym.course.worked.render import to_json_value
    return to_json_value(v)


class _Replays:
    """The replays of a solution with a slip along the way, computed once, when first
    needed (each a solve for its values, :func:`replayed_values`)."""

    def __init__(self, solution):
        self.solution, self.done = solution, None

    def __iter__(self):
        if self.done is None:
            self.done = replayed_values(self.solution)
        return iter(self.done)


def _grade_exact(name, got, right, shown, kind) -> Graded:
    """A truth, a reason number or a count: right when it is the key, else wrong; no slip
    is named (a wrong truth is no sign or unit slip of the right one)."""
    g, e = got[0], got[1]
    ok = g.shape == e.shape and bool(np.all(np.abs(g - e) <= 1e-9))
    what = {"truth": "truth", "reason": "reason", "count": "count"}.get(kind, "value")
    if ok:
        return Graded(name, True, None, shown, f"the key's {what}")
    return Graded(name, False, None, shown, f"not the key's {what} ({_shown_short(right)}); "
                  f"a {what} has no slips")


def _shown_short(right) -> str:
    if right in (sp.true, sp.false):
        return str(bool(right)).lower()
    if isinstance(right, sp.MatrixBase):
        return "[" + ", ".join(str(x) for x in right) + "]"
    return str(right)


def _grade_one(name, got, right, shown, extra, replayed=None, unit=None,
               verdict=None, kind="vector", data=()) -> Graded:
    """A read answer (``got``: :func:`_read_all`'s tuple) against the key (or, for a
    declared class, ``verdict``'s member, compared modulo the class's freedom): right, a
    named slip of the box's ``kind``, rounded, or wrong. A slip is named only when the
    answer is not trivial (:func:`rigidsym.course.box_kinds.trivial`: all zero, all equal,
    a datum echoed) and matches the slipped key within the tolerance relative to the
    slipped key."""
    g, e, tol, written = got
    if verdict is not None:
        e = verdict.target

    def _close(a, b, sc):
        return verdict.matches(a, b, sc, RTOL) if verdict is not None else \
            _close_plain(a, b, sc)

    def _slipped(a, b):
        return verdict.matches(a, b, float(np.max(np.abs(b))), RTOL) \
            if verdict is not None else slip_close(a, b, RTOL)

    scale = max(float(np.max(np.abs(e))) if e.size else 0.0, 1e-300)
    if _close(g, e, scale):
        return Graded(name, True, None, shown, tol,
                      note=f"units {written}→{unit}" if written and written != unit
                      else "right")
    plain = trivial(g, e, list(data), RTOL)      # zero, constant, a datum: no slip
    extra_f = [(w, d, _expected(v)) for w, d, v in extra]
    for member in () if plain else (e, *(verdict.members if verdict is not None else ())):
        for word, detail, value in _candidates(member, name, extra_f, kind, unit):
            if _slipped(g, value):
                more = unit_slip(word, value, member, unit, written)
                return Graded(name, False, word, shown, f"matches {detail}" + more,
                              note=_slip_note(word, detail, value, member, unit, written))
    for word, detail, answers in () if plain else replayed or ():
        value = answers.get(name)
        if value is None or isinstance(value, str):
            continue
        try:
            v = _expected(value)
        except TypeError:
            continue
        if v.shape == g.shape and slip_counts(v, e, RTOL) and _slipped(g, v):
            return Graded(name, False, word, shown, f"matches the solution with {detail}",
                          note=f"{word} (along the way)")
    figures = next((f for m in (e, *(verdict.members if verdict is not None else ()))
                    if (f := rounded_figures(g, m))), 0)
    if figures:
        return Graded(name, False, "rounded", shown,
                      f"rounded to {figures} significant figures (the tolerance: {tol})",
                      note=f"rounded {figures} s.f.")
    if plain:
        return Graded(name, False, None, shown, f"not within the tolerance ({tol}); a "
                      f"trivial answer (zero, all entries equal, or a datum echoed) names "
                      f"no slip")
    return Graded(name, False, None, shown, f"not within the tolerance ({tol}), and not a "
                  f"known slip")


def _slip_note(word, detail, value, e, unit, written) -> str:
    """The answer note of a slip: the word, with the units or the order named."""
    if word == "unit" and not written:
        from rigidsym.course.worked.units import slipped_unit

        k = int(np.argmax(np.abs(e)))
        u = slipped_unit(float(value.reshape(-1)[k] / e.reshape(-1)[k]), unit)
        return f"units {u}→{unit}" if u else "unit"
    if word == "order":
        return "order " + detail.split("(order ")[-1].split(" for ")[0]
    return word


def rounded_figures(given: np.ndarray, right: np.ndarray, most: int = 3) -> int:
    """The number of significant figures N (1 to ``most``) to which every entry of
    ``given`` is ``right`` rounded (and at least one entry differs by more than the
    tolerance), or 0: an answer rounded to fewer figures than the grader's tolerance
    asks is named so, not "wrong"."""
    if given.shape != right.shape or not given.size:
        return 0
    for n in range(1, most + 1):
        r = np.array([float(f"{x:.{n - 1}e}") for x in right.reshape(-1)])
        if np.allclose(given.reshape(-1), r, rtol=1e-9, atol=1e-12):
            return n
    return 0


class AmbiguousNumber(ValueError):
    """A number that reads two ways (``1,234``: one and 234 thousandths, or 1234)."""


_COMMA_DECIMAL = __import__("re").compile(r"^\s*[-+]?\d+,\d+\s*$")
_THOUSANDS = __import__("re").compile(r"^\s*[-+]?\d{1,3}([, ]\d{3})+(\.\d+)?\s*$")


def read_decimal_comma(given, shape: tuple, where: str):
    """A scalar answer written with a decimal comma (``1,23096``) read as a decimal point;
    vectors keep the comma as the separator of entries. ``1,234`` (three digits after one
    comma) reads two ways and is left ungraded (:class:`AmbiguousNumber`); thousands
    separators (``1,234,567``, ``12 345.6``) are refused.

    Raises:
        AmbiguousNumber: ``1,234``.
        ValueError: a number with thousands separators.
    """
    if shape or not isinstance(given, str):
        return given
    t = given.strip()
    if _THOUSANDS.match(t) and (t.count(",") + t.count(" ") > 1 or "." in t or " " in t):
        raise ValueError(f"{where}: {given!r} has thousands separators; write the number "
                         f"without them (1234567.5)")
    if _COMMA_DECIMAL.match(t):
        if len(t.split(",")[1].strip()) == 3:
            raise AmbiguousNumber(f"{where}: {given!r} is one and a fraction with a decimal "
                                  f"comma, or a whole number with a thousands separator: "
                                  f"left to the instructor")
        return t.replace(",", ".")
    return given


def compared_answers(s) -> dict:
    """The answers of solution ``s`` as the grader compares them: each value a float array
    (:func:`key_array`), ``None`` for a value that is no number (an expression in symbols,
    a set), text kept as text; where ``s`` was solved on floating data
    (``s.values_only``: :func:`rigidsym.course.worked.solve_values`), an entry within
    :data:`rigidsym.course.worked.checks.ZERO` (1e-20) of 0 written 0."""
    from rigidsym.course.worked.checks import ZERO

    out: dict = {}
    for name, v in s.answers.items():
        if isinstance(v, str):
            out[name] = v
            continue
        try:
            a = key_array(v)
        except TypeError:
            out[name] = None
            continue
        if s.values_only:
            a = np.where(np.abs(a) <= ZERO, 0.0, a)
        out[name] = a
    return out


def replayed_values(solution) -> list[tuple[str, str, dict]]:
    """:func:`rigidsym.course.slips.replays` of ``solution`` for their values
    (``values=True``) with each answer as the grader compares it: the value as a float array
    (:func:`key_array`: 17 digits, the key's shape; a replay on 50-digit floating data where
    the exercise allows it, its entries within 1e-20 of 0 written 0), ``None`` for a value
    that is no number (an expression in symbols, a set), text kept as text.

    The list is kept in the user cache (``verdicts/``, beside the solutions on the book's
    data; keyed by the exercise, the solution's exact data and tolerance, every source
    file of the package and the book, and the libraries' versions), so that the class's
    STACK export and its grading, each of which compares every student's boxes with the
    replays, solve each slipped datum once between them.

    Returns:
        ``[(word, detail, {answer name: float array | str | None}), ...]``, in the order
        of :func:`rigidsym.course.slips.replays`.
    """
    import pickle

    from rigidsym.core import cache as _cache

    where = _kept_at(solution)
    blob = _cache.get(where) if where is not None else None
    if blob is not None:
        try:
            kept = pickle.loads(blob)
        except Exception:  # noqa: BLE001 -- an entry of another version: replayed again
            kept = None
        if isinstance(kept, list):
            return kept
    from rigidsym.course.slips import replays

    out = list(replays(solution, values=True, compare=compared_answers))
    if where is not None:
        _cache.put(where, pickle.dumps(out))
    return out


def _kept_at(solution):
    """Where :func:`replayed_values` of ``solution`` is kept, or None (no data, or data
    that do not read). The key holds the digest of every source file of the package and
    the book (:func:`rigidsym.core.sources.package_digest`), not the modules imported so
    far: a class's exam and its grading, in other processes, find the same entry."""
    import hashlib

    from rigidsym.core import cache as _cache
    from rigidsym.core import sources as _sources
    from rigidsym.course.worked import parameters, read_data

    if not solution.data:
        return None
    try:
        d = read_data(parameters(solution.id), solution.data, solution.tol)
    except (ValueError, TypeError):
        return None
    h = hashlib.sha256()
    for part in ("replays 2", _sources.package_digest(), _sources.environment(),
                 solution.id, repr(d.key())):
        h.update(part.encode() + b"\0")
    key = h.hexdigest()
    return _cache.folder("verdicts") / key[:2] / f"replays-{key}.pickle"

