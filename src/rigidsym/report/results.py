"""The results of the public API (:mod:`rigidsym.api`): :class:`Result`, one id's checker
outcome, and :class:`Results`, a run's, with their displays.

In Jupyter a :class:`Results` displays as a table and one :class:`Result` as mathematics
(MathML in HTML, LaTeX otherwise); ``repr`` stays one line; ``to_json`` gives the schema-2
records. Public as ``rigidsym.Result`` and ``rigidsym.Results``.
"""

from __future__ import annotations

import html
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, fields
from typing import overload

from rigidsym.checking.outcome import Outcome
from rigidsym.registry.declarations import VERDICTS

__all__ = ["Result", "Results"]


@dataclass(repr=False)
class Result(Outcome):
    """The checker's outcome for one id, with notebook display.

    The fields are those of the ``rigidsym verify --json`` rows; :meth:`to_json` gives the
    schema-2 record (documented on the "JSON schema 2" page of the documentation).

    Attributes:
        id: the equation id (``"3.96e"``, ``"notes:rodrigues"``).
        title: its title.
        kind: ``identity``, ``definition`` or ``claim``.
        verdict: :glossary:`verified <verdict>`, :glossary:`definition <verdict>`,
            :glossary:`does-not-hold <verdict>` or :glossary:`undecided <verdict>`, computed
            (each defined in the glossary).
        expected: the verdict the declaration expects.
        method: how it was decided (:glossary:`exact-cancel`, :glossary:`random-exact`,
            :glossary:`counterexample`, ...; see :glossary:`method`).
        printed: the printed form, as an expanded sympy string.
        derived: the derived form, likewise.
        corrected: the :glossary:`corrected form <corrected form>`, likewise; None unless
            the printed form does not hold.
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
            # in the book's symbols when described (rigidsym.checking.deciding.counterexample)
            syms = self.counterexample.get("symbols") or []
            pt = "; ".join(f"{x['symbol']} = {x['text']}" for x in syms) or \
                ", ".join(f"{k} = {v}" for k, v in self.counterexample["point"].items())
            rows.append(f"<p>counterexample (exact): <code>{e(pt[:800])}</code></p>")
        rows += self._repairs_html()
        if self.detail:
            rows.append(f"<p><small>{e(self.detail)}</small></p>")
        return "<div class=\"rigidsym-result\">" + "".join(rows) + "</div>"


    def _repairs_html(self) -> list[str]:
        """The verified repairs, the edited subterm highlighted."""
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
            verdict: :glossary:`verified <verdict>`, :glossary:`definition <verdict>`,
                :glossary:`does-not-hold <verdict>` or :glossary:`undecided <verdict>`.
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
