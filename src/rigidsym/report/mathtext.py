"""LaTeX to MathML with a text fallback, shared by the HTML report and the repairs view."""

from __future__ import annotations

from markupsafe import Markup

from rigidsym.printing.mathml import mathml_or_text

__all__ = ["math_or_text"]


def math_or_text(latex: str | None, fallback: str | None, display: bool = True) -> Markup:
    """MathML of ``latex``; the text ``fallback`` in ``<code>`` when there is no LaTeX or
    the converter rejects it (a member too long to print, an unusual construct): the
    printing layer's one fallback (:func:`rigidsym.printing.mathml.mathml_or_text`), as
    markup for the templates."""
    return Markup(mathml_or_text(latex, fallback, display))
