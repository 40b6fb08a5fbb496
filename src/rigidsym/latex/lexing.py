"""The lark side of the LaTeX reader: the LALR(1) parser of ``grammar.lark`` with its
post-lexer (layout inside ``aligned``), and what a parse returns (:class:`Parsed`)."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cache
from importlib import resources

import lark

__all__ = ["Relation", "Parsed", "parser"]


@dataclass(frozen=True)
class Relation:
    """One relation the LaTeX states: ``lhs op rhs`` (``op`` is ``=`` or ``≡``).

    Attributes:
        lhs, rhs: sympy scalars or matrix expressions of the same shape.
        op: ``"="`` or ``"equiv"``.
        chain: index of the ``=`` chain it belongs to; ``link`` its position in the chain.
        text: how it reads, in book notation (sympy's string form).
    """

    lhs: object
    rhs: object
    op: str
    chain: int
    link: int


@dataclass
class Parsed:
    """A parsed LaTeX statement.

    Attributes:
        chains: per ``=`` chain, the list of its expressions (``x = y = z`` gives three).
        ops: per chain, the relation symbols between them.
        relations: one :class:`Relation` per link of every chain, in order.
        readings: notes on how the text was read (a dropped time argument, a block row whose
            column separator was lost, an ignored condition).
        glyphs: the glyph-table rows used, by LaTeX key.
        applied: the non-scalar symbols read as applied to a parenthesised scalar
            (``R(\\theta)``), by LaTeX key: the arguments (``rigidsym.latex.meaning``).
    """

    chains: list = field(default_factory=list)
    ops: list = field(default_factory=list)
    relations: list = field(default_factory=list)
    readings: list = field(default_factory=list)
    glyphs: dict = field(default_factory=dict)
    applied: dict = field(default_factory=dict)  # R(\theta): key -> arguments (latex.meaning)

    def pairs(self):
        """Every pair ``(chain, i, j, E_i, E_j)`` with ``i < j`` of a chain: each is a
        relation the text states (``x = y = z`` states ``x = y``, ``x = z``, ``y = z``)."""
        for c, exprs in enumerate(self.chains):
            for i in range(len(exprs)):
                for j in range(i + 1, len(exprs)):
                    yield c, i, j, exprs[i], exprs[j]


class _AlignedLayout:
    """Post-lexer: inside ``aligned`` (outside a matrix) ``&``, ``\\\\`` and a ``\\quad``
    right after ``&`` are layout; drop them (and the environment's delimiters)."""

    always_accept = ("AMP", "ROWSEP", "BEGIN_ALIGNED", "END_ALIGNED")

    def process(self, stream):
        aligned = matrix = 0
        after_amp = False
        for tok in stream:
            t = tok.type
            if t == "BEGIN_ALIGNED":
                aligned += 1
                continue
            if t == "END_ALIGNED":
                aligned -= 1
                continue
            if t == "BEGIN_MATRIX":
                matrix += 1
            elif t == "END_MATRIX":
                matrix -= 1
            if aligned and not matrix:
                if t in ("AMP", "ROWSEP"):
                    after_amp = t == "AMP"
                    continue
                if after_amp and tok.value.startswith(("\\quad", "\\qquad")):
                    after_amp = False
                    continue
            after_amp = False
            yield tok


@cache
def parser() -> lark.Lark:
    """The lark LALR(1) parser of ``grammar.lark`` (built once per process)."""
    text = resources.files("rigidsym.latex").joinpath("grammar.lark").read_text("utf-8")
    return lark.Lark(text, parser="lalr", lexer="contextual", postlex=_AlignedLayout(),
                     propagate_positions=False, maybe_placeholders=False)
