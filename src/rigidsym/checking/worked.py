"""Worked-solution framework for the chapter's exercises: steps, answers, machine checks.

A solution is data (:class:`Solution`): the statement with its citation, the given data,
named steps (a sympy expression and one sentence of why), the answers (exact, floats
beside them when rendered) and machine checks that do not reuse the solution path. This
module also renders solutions (terminal text, Markdown) and serialises them to JSON.
Deciding truth is never done here by ``simplify()``: identities go to
:func:`rigidsym.zero.decide.decide_zero`; closed algebraic numbers to their minimal polynomial.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass, field

import sympy as sp

from rigidsym.zero.decide import decide_zero

__all__ = [
    "Step",
    "Check",
    "Solution",
    "EXERCISE_IDS",
    "normalise_id",
    "solve",
    "identity_check",
    "nonidentity_check",
    "algebraic_zero",
    "truth_check",
    "exact_check",
    "to_json_value",
    "render_text",
    "render_markdown",
]

#: ``ex3.1`` ... ``ex3.21``.
EXERCISE_IDS = [f"ex3.{k}" for k in range(1, 22)]
_X = sp.Symbol("x_minpoly")


@dataclass
class Step:
    """One named step: an expression and why it is taken."""

    name: str
    expr: object
    why: str


@dataclass
class Check:
    """A machine check: its name, whether it passed, and how it was decided."""

    name: str
    passed: bool
    detail: str = ""


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
        assumptions: data not in the text we have (figures, chapter 2), and caveats.
        status: ``"solved"`` or ``"partial"``.
        extra: free-form rendered text (tables) appended after the answers.
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


# --------------------------------------------------------------------------- checks
def identity_check(name: str, exprs, seed: int = 0) -> Check:
    """Decide soundly that every expression in ``exprs`` vanishes identically.

    Matrices are flattened. Constrained atoms (unit vectors, angles, rotations from
    :mod:`rigidsym.algebra.symbols`) are parametrised exactly by the zero test.
    """
    flat = []
    for e in exprs if isinstance(exprs, list | tuple) else [exprs]:
        if isinstance(e, sp.MatrixBase):
            flat.extend(list(e))
        else:
            flat.append(e)
    r = decide_zero(flat, seed=seed)
    detail = f"{r.method}: {r.detail}"
    if r.zero is False and r.witness is not None:
        detail += f" (entry {r.entry} non-zero at an exact point)"
    return Check(name, r.zero is True, detail)


def nonidentity_check(name: str, exprs, seed: int = 0) -> Check:
    """Passes when the zero test *refutes* the identity with an exact counterexample."""
    c = identity_check(name, exprs, seed)
    refuted = not c.passed and c.detail.startswith("counterexample")
    return Check(name, refuted, ("refuted by an exact rational counterexample: " if refuted
                                 else "not refuted: ") + c.detail)


def algebraic_zero(e) -> bool:
    """Exactly decide that a closed expression (an algebraic number) is zero.

    Uses the minimal polynomial over Q: ``e == 0`` iff that polynomial is ``x``.
    """
    e = sp.nsimplify(e) if isinstance(e, sp.Float) else sp.sympify(e)
    if e.free_symbols:
        raise ValueError(f"not a closed number: {e}")
    e = sp.expand(e)
    if e == 0:
        return True
    if e.is_Rational:
        return False
    return sp.minimal_polynomial(e, _X) == _X


def exact_check(name: str, exprs) -> Check:
    """Check that closed algebraic expressions (entries of matrices too) are all zero."""
    flat = []
    for e in exprs if isinstance(exprs, list | tuple) else [exprs]:
        flat.extend(list(e) if isinstance(e, sp.MatrixBase) else [e])
    bad = [i for i, e in enumerate(flat) if not algebraic_zero(e)]
    if bad:
        return Check(name, False, f"entries {bad} are not zero (minimal polynomial)")
    return Check(name, True, f"{len(flat)} closed algebraic entries are 0 (minimal polynomial)")


def truth_check(name: str, ok: bool, detail: str) -> Check:
    """A check decided by exact comparison done by the caller (rationals, signs)."""
    return Check(name, bool(ok), detail)


# --------------------------------------------------------------------------- registry
def normalise_id(text: str) -> str:
    """``"3.10"``, ``"ex3.10"``, ``"3.01"`` -> ``"ex3.10"``.

    Raises:
        ValueError: if ``text`` names no exercise of the chapter.
    """
    t = text.strip().lower()
    if t.startswith("ex"):
        t = t[2:]
    try:
        chap, num = t.split(".")
        k = int(num)
    except ValueError:
        raise ValueError(f"expected an exercise id like 3.10 or ex3.10, got {text!r}") from None
    if chap != "3" or not 1 <= k <= 21:
        raise ValueError(f"expected an exercise 3.1 ... 3.21, got {text!r}")
    return f"ex3.{k}"


def _module(ex_id: str):
    k = int(ex_id.split(".")[1])
    from rigidsym import _config

    return importlib.import_module(f"{_config.EXERCISES}.ex3_{k:02d}")


_CACHE: dict[str, Solution] = {}


def solve(ex_id: str) -> Solution:
    """Build (once per process) the worked solution of exercise ``ex_id``."""
    ex_id = normalise_id(ex_id)
    if ex_id not in _CACHE:
        solver: Callable[[], Solution] = _module(ex_id).solve
        _CACHE[ex_id] = solver()
    return _CACHE[ex_id]


# --------------------------------------------------------------------------- output
def to_json_value(v):
    """A sympy value as JSON: ``str()`` that ``sympify`` reads back; matrices nested."""
    if isinstance(v, sp.MatrixBase):
        return [[str(x) for x in v.row(i)] for i in range(v.rows)]
    if isinstance(v, list | tuple):
        return [to_json_value(x) for x in v]
    if isinstance(v, str):
        return v
    return str(sp.sympify(v))


def _float_of(v) -> str:
    if isinstance(v, str):
        return ""
    try:
        if isinstance(v, sp.MatrixBase):
            if v.free_symbols:
                return ""
            return str(sp.N(v, 6).tolist())
        v = sp.sympify(v)
        if not isinstance(v, sp.Expr) or v.free_symbols or v.is_number is not True:
            return ""
        f = sp.N(v, 6)
        return "" if f == v else str(f)
    except (TypeError, ValueError, sp.SympifyError):
        return ""


def _pretty(v) -> str:
    if isinstance(v, str):
        return v
    return sp.pretty(v, use_unicode=True, wrap_line=False)


def render_text(s: Solution) -> str:
    """Terminal rendering: statement, given, numbered steps, answers, checks."""
    out = [f"Exercise {s.id[2:]}: {s.title}", f"  {s.citation}", "", s.statement, ""]
    if s.assumptions:
        out.append("Assumptions:")
        out += [f"  - {a}" for a in s.assumptions]
        out.append("")
    if s.given:
        out.append("Given:")
        for k, v in s.given.items():
            out.append(f"  {k} =")
            out += ["    " + ln for ln in _pretty(v).splitlines()]
        out.append("")
    out.append("Solution:")
    for i, st in enumerate(s.steps, 1):
        out.append(f"  Step {i}. {st.name}: {st.why}")
        out += ["      " + ln for ln in _pretty(st.expr).splitlines()]
    out.append("")
    out.append("Answers:")
    for k, v in s.answers.items():
        f = _float_of(v)
        out.append(f"  {k} =" + (f"   (~ {f})" if f else ""))
        out += ["    " + ln for ln in _pretty(v).splitlines()]
    if s.extra:
        out += ["", s.extra]
    out.append("")
    out.append("Machine checks:")
    for c in s.checks:
        out.append(f"  [{'ok' if c.passed else 'FAIL'}] {c.name}: {c.detail}")
    out.append(f"\nstatus: {s.status}; checked: {str(s.checked).lower()}")
    return "\n".join(out)


def _latex(v) -> str:
    if isinstance(v, str):
        return v
    return f"$${sp.latex(v)}$$"


def render_markdown(s: Solution) -> str:
    """Markdown rendering (LaTeX maths) for the report."""
    out = [f'## Exercise {s.id[2:]}: {s.title} <a id="ex-{s.id[2:]}"></a>', "",
           f"*{s.citation}*", "",
           f"> {s.statement}", "",
           f"**Status:** {s.status}; **checked:** {str(s.checked).lower()}", ""]
    if s.assumptions:
        out.append("**Assumptions**")
        out += [f"- {a}" for a in s.assumptions] + [""]
    if s.given:
        out.append("**Given**")
        out += [f"- `{k}` = {_latex(v)}" for k, v in s.given.items()] + [""]
    out.append("**Solution**")
    out.append("")
    for i, st in enumerate(s.steps, 1):
        out += [f"{i}. *{st.name}*: {st.why}", "", f"   {_latex(st.expr)}", ""]
    out.append("**Answers**")
    out.append("")
    for k, v in s.answers.items():
        f = _float_of(v)
        out += [f"- `{k}` = {_latex(v)}" + (f" ≈ `{f}`" if f else ""), ""]
    if s.extra:
        out += [s.extra, ""]
    out.append("**Machine checks**")
    out.append("")
    out += [f"- [{'x' if c.passed else ' '}] {c.name}: {c.detail}" for c in s.checks]
    out.append("")
    return "\n".join(out)
