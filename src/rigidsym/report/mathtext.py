"""LaTeX to MathML with a text fallback, shared by the HTML report and the repairs view."""

from __future__ import annotations

import html

from markupsafe import Markup

from rigidsym.printing.mathml import latex_to_mathml

__all__ = ["math_or_text"]


def math_or_text(latex: str | None, fallback: str | None, display: bool = True) -> Markup:
    """MathML of ``latex``; the text ``fallback`` in ``<code>`` when there is no LaTeX or
    the converter rejects it (a member too long to print, an unusual construct)."""
    if latex:
        try:
            return Markup(latex_to_mathml(latex, display=display))
        except ValueError:
            pass
    return Markup(f"<code>{html.escape(fallback or '(not shown: too long)')}</code>")
