"""The declared data of a worked exercise: its parameters (:class:`Param`, one datum each;
:class:`Parameters`, the exercise's table) and :class:`IllPosed`, the exception that ends a
solution whose data admit no answer. Reading a student's values against them is
:mod:`.data`'s.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

__all__ = ["Param", "Parameters", "IllPosed"]


SHAPE_WORDS = {(): "a real number", (3,): "a 3-vector (3 numbers)",
                (6,): "a 6-array (6 numbers)", (3, 3): "a 3 x 3 matrix (3 rows of 3 numbers)"}


class IllPosed(Exception):
    """The data make the exercise ill-posed.

    Args:
        solution: the solution so far, ending at the failing step.
        reason: why, in one sentence.

    Attributes:
        solution: as given.
        reason: as given (also the exception's message).
    """

    def __init__(self, solution, reason: str):
        super().__init__(reason)
        self.solution = solution
        self.reason = reason


@dataclass(frozen=True)
class Param:
    """One given datum of an exercise.

    Attributes:
        name: a valid identifier, as the book writes it with subscripts after ``_`` and
            primes spelled out (``n_1``, ``I_A``, ``C_prime``).
        default: the book's value (exact sympy: a number or a Matrix; a str for a choice;
            None for an optional datum the book leaves symbolic, such as 3.10's angles).
        shape: ``()`` a number, ``(3,)`` a vector, ``(6,)``, ``(3, 3)`` a matrix; ``None``
            for a choice among ``choices``.
        meaning: one line.
        unit: SI unit of the entries ("" when dimensionless).
        choices: the allowed strings of a choice parameter.
    """

    name: str
    default: object
    shape: tuple | None
    meaning: str
    unit: str = ""
    choices: tuple = ()

    @property
    def shape_text(self) -> str:
        """The shape in words, as a reader says it (``(3,)``, ``(3, 3)``, ``scalar``,
        ``one of ...``)."""
        if self.shape is None:
            return "one of " + ", ".join(self.choices)
        return "scalar" if self.shape == () else str(self.shape)


@dataclass(frozen=True)
class Parameters:
    """The given data of one exercise: a table of :class:`Param` and a sentence.

    Iterating gives the rows; ``params["n_1"]`` one row; ``defaults()`` the book's values.
    Displayed as a table in a notebook (``_repr_html_``) and as text by ``str()``.

    Attributes:
        exercise: the exercise id (``"ex3.4"``).
        rows: the :class:`Param` rows, in the exercise's order.
        note: a sentence on the data (why there are none, how tolerances are chosen).
        measured: whether the data are measurements (floats, judged within a tolerance).
        default_tol: ``values -> (tol, how it was chosen)``, or None for 10^-3 times the
            largest datum.
        readings: the parameters whose decimal texts (``"1.667"``) are readings, judged
            within a tolerance derived from their digits; ``()``: all of them.
    """

    exercise: str
    rows: tuple = ()
    note: str = ""
    measured: bool = False
    #: ``values -> (tol, how it was chosen)``; None: 10^-3 x the largest absolute datum
    default_tol: object = None
    #: the parameters whose decimal texts are readings (measured exercises); () all of them
    readings: tuple = ()

    def __iter__(self):
        return iter(self.rows)

    def __len__(self) -> int:
        return len(self.rows)

    def __getitem__(self, name: str) -> Param:
        for p in self.rows:
            if p.name == name:
                return p
        raise KeyError(f"{self.exercise} has no parameter {name!r}")

    @property
    def names(self) -> list[str]:
        """The parameter names, in the order of the table."""
        return [p.name for p in self.rows]

    def defaults(self) -> dict:
        """``{name: the book's value}``."""
        return {p.name: p.default for p in self.rows}

    def __str__(self) -> str:
        if not self.rows:
            return f"{self.exercise}: {self.note}"
        out = [f"{self.exercise}: {self.note}" if self.note else f"{self.exercise}:"]
        for p in self.rows:
            unit = f" [{p.unit}]" if p.unit else ""
            out.append(f"  {p.name:10s} {p.shape_text:8s} = {_flat_text(p.default)}{unit}")
            out.append(f"  {'':10s} {p.meaning}")
        if self.measured:
            out.append("  tol        scalar   (keyword) tolerance of float (measured) data; by "
                       "default set from the data, and stated in the solution")
        return "\n".join(out)

    def _repr_html_(self) -> str:
        import html
        head = f"<p><b>{html.escape(self.exercise)}</b>: {html.escape(self.note)}</p>"
        if not self.rows:
            return head
        # inline left alignment: Jupyter's table style right-aligns every cell
        td = '<td style="text-align: left">'
        rows = "".join(
            f"<tr>{td}<code>{html.escape(p.name)}</code></td>{td}{html.escape(p.shape_text)}"
            f"</td>{td}<code>{html.escape(_flat_text(p.default))}</code></td>"
            f"{td}{html.escape(p.unit)}</td>{td}{html.escape(p.meaning)}</td></tr>"
            for p in self.rows)
        th = "".join(f'<th style="text-align: left">{h}</th>'
                     for h in ("name", "shape", "book's value", "unit", "meaning"))
        return (head + f"<table><thead><tr>{th}</tr></thead><tbody>{rows}</tbody></table>")


def _flat_text(v) -> str:
    if v is None:
        return "(not given)"
    if isinstance(v, sp.MatrixBase):
        if v.cols == 1:
            return "[" + ", ".join(str(x) for x in v) + "]"
        return "[" + "; ".join(", ".join(str(x) for x in v.row(i)) for i in range(v.rows)) + "]"
    return str(v)
