"""The public Python API: check one id, verify many, read and display the results.

    >>> import rigidsym
    >>> rigidsym.check("3.96e").verdict                       # doctest: +SKIP
    'does-not-hold'
    >>> rigidsym.verify(sections=["3.2"]).summary()           # doctest: +SKIP
    {'verified': ..., 'definition': ..., 'does-not-hold': ..., 'undecided': 0}

In Jupyter a :class:`Results` displays as a table and one :class:`Result` as mathematics
(MathML in HTML, LaTeX otherwise); ``repr`` stays one line.
"""

from __future__ import annotations

import html
import os
import time
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, fields
from types import ModuleType
from typing import overload

from rigidsym.checking.checker import Outcome
from rigidsym.checking.deciding.registry import VERDICTS, BadInput, select

__all__ = ["check", "check_latex", "verify", "Result", "Results"]

ModuleSpec = str | os.PathLike | ModuleType


@dataclass(repr=False)
class Result(Outcome):
    """The checker's outcome for one id, with notebook display.

    The fields are those of the ``rigidsym verify --json`` rows; :meth:`to_json` gives the
    schema-2 record (documented on the "JSON schema 2" page of the documentation).

    Attributes:
        id: the equation id (``"3.96e"``, ``"notes:rodrigues"``).
        title: its title.
        kind: ``identity``, ``definition`` or ``claim``.
        verdict: ``verified``, ``definition``, ``does-not-hold`` or ``undecided``, computed.
        expected: the verdict the declaration expects.
        method: how it was decided (``exact-cancel``, ``random-exact``,
            ``counterexample``, ...).
        printed, derived, corrected: the expanded sympy strings (``corrected`` is None
            unless the printed form does not hold).
        counterexample: for a does-not-hold, the exact point and both sides there.
        numeric: the numeric backing (``points``, ``digits``, ``max_residual``, ``seed``).
        seconds: the time the check took.
        members: one record per member (printed, claim, corrected) in book notation.
    """

    @classmethod
    def of(cls, r: Outcome) -> Result:
        """The same result with display methods (no copy of its values)."""
        if isinstance(r, cls):
            return r
        return cls(**{f.name: getattr(r, f.name) for f in fields(Outcome)})

    def __repr__(self) -> str:
        flag = "" if self.verdict == self.expected else f", expected {self.expected}"
        return (f"<Result {self.id}: {self.verdict}{flag} ({self.method}, "
                f"{self.seconds:.2f} s)>")

    def to_json(self) -> dict:
        """The schema-2 record of this result (a row of ``Results.to_json()``)."""
        from rigidsym.report.record import result_record

        return result_record(self)

    def forms_latex(self) -> list[tuple[str, str]]:
        """``(role, LaTeX)`` of each member in book notation (printed, claim, corrected),
        from the schema-2 member records; the book's printed LaTeX stands in for printed
        members too long to show."""
        out = []
        for m in self.members:
            label = m["role"] + (f" ({m['label']})" if m.get("label") else "")
            if m.get("latex"):
                out.append((label, m["latex"]))
        if not any(role.startswith("printed") for role, _ in out) and self.printed_latex:
            out.insert(0, ("printed", self.printed_latex.strip()))
        return out

    def _repr_latex_(self) -> str:
        forms = [tex for role, tex in self.forms_latex() if role.startswith("printed")]
        body = r" \\ ".join(forms) if forms else r"\text{(no printed form)}"
        if len(forms) > 1:
            body = r"\begin{aligned}" + body + r"\end{aligned}"
        return f"$\\displaystyle {body}$"

    def _repr_html_(self) -> str:
        from rigidsym.printing.mathml import mathml_or_text

        e = html.escape
        rows = [f"<p><b>({e(self.id)}) {e(self.title)}</b>: <b>{e(self.verdict)}</b> "
                f"(expected {e(self.expected)}; method {e(self.method)}; "
                f"{self.seconds:.2f} s)</p>"]
        for label, latex in self.forms_latex():
            shown = mathml_or_text(latex, latex, display=True, tag="pre")
            rows.append(f"<div><i>{label}</i>{shown}</div>")
        if self.counterexample:
            # in the book's symbols when described (rigidsym.checking.deciding.bookpoint)
            syms = self.counterexample.get("symbols") or []
            pt = "; ".join(f"{x['symbol']} = {x['text']}" for x in syms) or \
                ", ".join(f"{k} = {v}" for k, v in self.counterexample["point"].items())
            rows.append(f"<p>counterexample (exact): <code>{e(pt[:800])}</code></p>")
        rows += self._repairs_html()
        if self.detail:
            rows.append(f"<p><small>{e(self.detail)}</small></p>")
        return "<div class=\"rigidsym-result\">" + "".join(rows) + "</div>"


    def _repairs_html(self) -> list[str]:
        """The verified repairs (issue 23), the edited subterm highlighted."""
        from rigidsym.report.repairs import EDIT_CLASS, marked_mathml

        e = html.escape
        out = []
        for x in self.repairs:
            tag = "; the declared correction" if x["equals_declared"] else ""
            out.append(f"<div><i>repair: {e('; then '.join(x['edits']))} ({e(x['method'])}"
                       f"{tag})</i>{marked_mathml(x['latex'], x['text'])}</div>")
        if out:
            out.insert(0, f"<style>.{EDIT_CLASS} {{ background: #ffe98a; }}</style>")
        return out


class Results(Sequence[Result]):
    """The results of :func:`verify`: a sequence of :class:`Result` in id order.

    Indexing by position or slice gives a ``Result`` or ``Results``; by id
    (``results["3.16"]``) the result of that id.

    Args:
        results: the results, in id order (checker outcomes are wrapped as ``Result``).
        seconds: the wall time the run took, if known.
    """

    def __init__(self, results: Iterable[Result], seconds: float | None = None):
        self._rows = tuple(Result.of(r) for r in results)
        self.seconds = seconds

    @overload
    def __getitem__(self, key: int | str) -> Result: ...

    @overload
    def __getitem__(self, key: slice) -> Results: ...

    def __getitem__(self, key):
        if isinstance(key, slice):
            return Results(self._rows[key])
        if isinstance(key, str):
            for r in self._rows:
                if r.id == key:
                    return r
            raise KeyError(key)
        return self._rows[key]

    def __len__(self) -> int:
        return len(self._rows)

    def summary(self) -> dict[str, int]:
        """Counts per verdict, every verdict listed (zeros included)."""
        from rigidsym.report.record import summary

        return summary(list(self._rows))

    def to_json(self) -> dict:
        """The schema-2 document of ``rigidsym verify --json`` as a dict:
        ``{"schema": 2, "python_flint": version, "equations": [record, ...], "summary":
        {verdict: count}}``."""
        from rigidsym.report.record import document_header, result_record

        return {**document_header(), "equations": [result_record(r) for r in self._rows],
                "summary": self.summary()}

    def where(self, verdict: str | None = None, *, kind: str | None = None,
              section: str | None = None, mismatched: bool | None = None) -> Results:
        """The results that match every given criterion.

        Args:
            verdict: ``verified``, ``definition``, ``does-not-hold`` or ``undecided``.
            kind: ``identity``, ``definition`` or ``claim``.
            section: a section (``"3.2"`` takes its subsections too) or a user section.
            mismatched: True for the results whose verdict differs from the expected one.

        Raises:
            ValueError: for an unknown verdict.
        """
        if verdict is not None and verdict not in VERDICTS:
            raise ValueError(f"verdict: expected one of {VERDICTS}, got {verdict!r}")

        def keep(r: Result) -> bool:
            return ((verdict is None or r.verdict == verdict)
                    and (kind is None or r.kind == kind)
                    and (section is None or r.section == section
                         or r.section.startswith(section + "."))
                    and (mismatched is None or (r.verdict != r.expected) == mismatched))

        return Results([r for r in self._rows if keep(r)])

    def __repr__(self) -> str:
        counts = ", ".join(f"{k} {v}" for k, v in self.summary().items())
        return f"<Results: {len(self)} ids: {counts}>"

    def _repr_html_(self) -> str:
        e = html.escape
        head = "".join(f"<th>{c}</th>" for c in ("id", "title", "verdict", "expected",
                                                 "method", "seconds"))
        body = []
        for r in self._rows:
            style = "" if r.verdict == r.expected else " style=\"color:#b00\""
            body.append(f"<tr{style}><td>{e(r.id)}</td><td>{e(r.title)}</td>"
                        f"<td>{e(r.verdict)}</td><td>{e(r.expected)}</td>"
                        f"<td>{e(r.method)}</td><td>{r.seconds:.2f}</td></tr>")
        counts = ", ".join(f"{k} {v}" for k, v in self.summary().items())
        return (f"<table class=\"rigidsym-results\"><caption>{len(self)} ids: {e(counts)}"
                f"</caption><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody>"
                f"</table>")


def _load(modules) -> list[str]:
    """Load user modules (paths, dotted names or module objects); their import names."""
    from rigidsym.checking.deciding import usermodules

    if isinstance(modules, str | os.PathLike | ModuleType):
        modules = [modules]
    names = []
    for m in modules or ():
        um = usermodules.adopt(m) if isinstance(m, ModuleType) else usermodules.load(m)
        names.append(um.name)
    return names


def _repair_args(repairs, repair_budget) -> None:
    from rigidsym.checking.deciding.registry import check_budget

    if not isinstance(repairs, bool):
        raise ValueError(f"repairs: expected True or False, got {repairs!r}")
    check_budget(repair_budget, "repair_budget", none_ok=True)


def check(eq_id: str, *, modules: Iterable[ModuleSpec] = (), repairs: bool = True,
          repair_budget: int | None = None) -> Result:
    """Decide one equation and back the verdict numerically.

    Args:
        eq_id: a book id (``"3.16"``, ``"3.96e"``, ``"thm3.2.1"``) or a user id
            (``"notes:rodrigues"``) of a loaded module or of ``modules``.
        modules: user modules to load first (paths, dotted names or module objects).
        repairs: for a member that does not hold, search the smallest edits that make it
            hold (``Result.repairs``; README, "Repairs").
        repair_budget: candidates tried per failing member (``None``: the declaration's
            ``repair_budget``, else 5000).

    Returns:
        The :class:`Result`; its ``verdict`` is computed, never read from the declaration.
        An exception inside the declaration gives ``undecided`` with the error named.

    Raises:
        BadInput: for a malformed or unknown id, an id with several lettered parts
            (``"3.96"``: use :func:`verify`), or a user module that cannot be loaded.
        ValueError: if ``repairs`` is not a bool or ``repair_budget`` not a non-negative
            integer.
    """
    from rigidsym.checking.checker import check as _check

    _repair_args(repairs, repair_budget)
    _load(modules)
    ids = select([eq_id], None)
    if len(ids) != 1:
        raise BadInput(f"eq_id: {eq_id} has {len(ids)} parts ({', '.join(ids)}): check one, "
                       f"or verify([{eq_id!r}])")
    return Result.of(_check(ids[0], repairs=repairs, repair_budget=repair_budget))


#: the default time limit of check_latex's repair search, seconds (issue 52, item 6)
REPAIR_SECONDS = 10.0


def check_latex(latex: str, let: Sequence[str] | dict[str, str] | str | None = None, *,
                book: str | None = None, modules: Iterable[ModuleSpec] = (),
                repairs: bool = True, repair_budget: int | None = None,
                notation: str | None = None,
                repair_seconds: float | None = REPAIR_SECONDS) -> Result:
    """Decide a relation written in LaTeX (the Python side of ``rigidsym check --latex``).

    The LaTeX is read by the chapter's reader (:func:`rigidsym.latex.parse_latex`); each
    relation it states is a printed member, the declarations ``let`` give the model, and
    the checker decides it as it decides a declaration (exactly, backed numerically; the
    constraints of the kinds imposed exactly, never by floating point).

    Args:
        latex: one or more relations (``=`` or ``\\equiv`` chains), e.g.
            ``r"\\mathbf{Q}^T\\mathbf{Q} = \\mathbf{1}"``.
        let: what the symbols are: a list of ``"NAME: KIND"`` (KIND one of
            :data:`rigidsym.latex.lets.KIND_WORDS`: ``unit vector``, ``rotation``,
            ``angle``, ``6-vector``, ``4x4 matrix``, ``twist`` ...) or ``"NAME = LATEX"`` (a
            first-principles model in the same notation); one string may hold several,
            separated by ``"; "``; or a dict ``{NAME: KIND or LATEX}``. A symbol nothing
            declares is free, its shape by the book's convention (bold lower-case a
            3-vector, bold capital 3 x 3, else a scalar), and ``Result.model`` says so.
        book: a section of the chapter (``"3.2"``, ``"3.4.2"``): the glyph table's rows of
            that section give the glyphs their meaning (names, shapes, angles, notational
            atoms such as ``E = CPM(e)``).
        modules: user modules that lend their symbols and models (module-level dicts of
            book symbols, ``MODEL`` first), matched by name.
        repairs: search the smallest edits that make a failing relation hold.
        repair_budget: candidates tried per failing relation (``None``: 5000).
        repair_seconds: a time limit of the repair search in seconds (default
            :data:`REPAIR_SECONDS`, 10; ``None``: none): past it the verdict is given with
            "search stopped after N s, K candidates tried" (issue 52).
        notation: a book's symbol table (``"lynch-park"``, ``"murray-li-sastry"``,
            ``"siciliano"``, ``"spong"``, ``"craig"``, ``"featherstone"``, ``"barfoot"``,
            ``"sola"``, ``"corke"``: ``rigidsym.latex.notations.NOTATIONS``): what its
            symbols are (``\\hat\\omega`` a unit vector in Lynch-Park, the skew matrix of
            ``\\omega`` in Murray-Li-Sastry; ``c_{12}`` a cosine in Siciliano), below
            ``let``.

    Returns:
        The :class:`Result` of the id ``latex:`` plus a short hash of the input; its
        ``expected`` repeats the verdict (a question has no expectation); ``model`` lists
        the declarations and the free symbols in words.

    Raises:
        rigidsym.latex.LatexError: LaTeX that cannot be read (the position with a caret and
            the constructs expected; an unknown macro named; a juxtaposition whose meaning
            depends on an undeclared shape asks for a ``let``). A ``ValueError``.
        BadInput: a declaration that is neither form, an unknown KIND (the kinds listed), a
            ``let`` naming a symbol that occurs nowhere, an ambiguous glyph of ``book``, a
            module that cannot be loaded.
        ValueError: if ``repairs`` is not a bool, ``repair_budget`` not a non-negative
            integer or ``repair_seconds`` not a positive number.

    Example:
        >>> r = check_latex(r"\\mathbf{Q}^T\\mathbf{Q} = \\mathbf{1}",
        ...                 let=[r"\\mathbf{Q}: rotation"])      # doctest: +SKIP
        >>> r.verdict                                              # doctest: +SKIP
        'verified'
    """
    return _check_latex(latex, let, book, modules, repairs, repair_budget, notation,
                        repair_seconds)[0]



def _seconds(x) -> float | None:
    if x is None:
        return None
    if isinstance(x, bool) or not isinstance(x, int | float) or not x > 0 or x != x:
        raise ValueError(f"repair_seconds: expected a positive number of seconds or None, "
                         f"got {x!r}")
    return float(x)


def _check_latex(latex, let, book, modules, repairs=True, repair_budget=None, notation=None,
                 repair_seconds=REPAIR_SECONDS):
    """:func:`check_latex` and the :class:`rigidsym.latex.letting.Reading` (for the CLI)."""
    from rigidsym.checking.checker import check as _check
    from rigidsym.latex.letting import declare_latex

    _repair_args(repairs, repair_budget)
    eq, reading = declare_latex(latex, let, book=book, modules=modules, notation=notation)
    r = Result.of(_check(eq, repairs=repairs, repair_budget=repair_budget,
                         repair_seconds=_seconds(repair_seconds)))
    if reading.others:  # several readings type-check: a verdict only when all agree
        _readings_agree(reading, r, [_check(o.eq, repairs=False) for o in reading.others])
    r.expected = r.verdict
    r.model = list(r.model) + reading.notes
    return r, reading


def _readings_agree(reading, first, others) -> None:
    """Issue 52, item 2: the verdict of every reading that type-checks, or bad input naming
    the choice, each reading's verdict and the ``--let`` that settles it."""
    from rigidsym.checking.deciding.errors import BadInput
    from rigidsym.latex.letting import _said

    verdicts = [first.verdict] + [o.verdict for o in others]
    readings = [reading, *reading.others]
    if len(set(verdicts)) == 1:
        reading.notes.append(f"{len(readings)} readings type-check "
                             f"({' | '.join(_said(x.choices) for x in readings)}): all "
                             f"{verdicts[0]}")
        return
    keys = sorted({k for x in readings for k, c in x.choices.items()
                   if c != reading.choices.get(k)})
    said = "; ".join(f"{_said(x.choices)}: {v}" for x, v in zip(readings, verdicts, strict=True))
    k = keys[0] if keys else "X"
    raise BadInput(f"--latex: {', '.join(f'{x}(...)' for x in keys)} can be read as a product or "
                   f"as {k} applied to its argument, and the readings disagree ({said}): say "
                   f"which, with a --let function (--let '{k}(PARAM) = LATEX': an application) "
                   f"or by writing the product without parentheses")


def verify(ids: Sequence[str] | str | None = None, sections: Sequence[str] | str | None = None,
           *, modules: Iterable[ModuleSpec] = (), jobs: int = 1,
           progress: bool = False, cache: bool = True, repairs: bool = True,
           repair_budget: int | None = None) -> Results:
    """Decide many equations (the Python side of ``rigidsym verify``).

    Args:
        ids: ids to check (``"3.96"`` means all its lettered parts); a single string is one id.
        sections: book sections ``"3.2"`` … ``"3.8"`` or sections of user declarations.
        modules: user modules to load (paths to ``.py`` files, dotted names, or module
            objects); with no ids and no sections, only their ids are checked.
        jobs: worker processes (forked; 1 checks in this process).
        progress: show a progress bar on stderr.
        cache: read unchanged ids from the verdict cache and store the others (``RIGIDSYM_CACHE``,
            ``verdicts/``; ``Result.cached`` says which); ``False`` checks every id again.
        repairs: search repairs of every member that does not hold (``Result.repairs``);
            ``False`` turns the search off.
        repair_budget: candidates tried per failing member (``None``: each declaration's
            ``repair_budget``, else 5000). The budget and the vocabulary's version join the
            verdict cache's key.

    Returns:
        :class:`Results` in id order (book order, then user ids in declaration order). With
        no argument at all: the whole chapter.

    Raises:
        BadInput: for a malformed or unknown id or section, or a user module that cannot be
            loaded (one line naming the module and the problem).
        ValueError: if ``jobs`` is not a positive integer, ``repairs`` not a bool or
            ``repair_budget`` not a non-negative integer.
    """
    from rigidsym.checking.runner import run_checks

    if not isinstance(jobs, int) or isinstance(jobs, bool) or jobs < 1:
        raise ValueError(f"jobs: expected a positive integer, got {jobs!r}")
    _repair_args(repairs, repair_budget)
    ids = [ids] if isinstance(ids, str) else ids
    sections = [sections] if isinstance(sections, str) else sections
    names = _load(modules)
    selected = select(list(ids) if ids else None, list(sections) if sections else None, names)
    t0 = time.perf_counter()
    rows = run_checks(selected, jobs=jobs, progress=progress, cache=cache, repairs=repairs,
                      repair_budget=repair_budget)
    return Results(rows, seconds=time.perf_counter() - t0)
