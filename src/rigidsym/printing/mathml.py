"""LaTeX to MathML Core through ``latex2mathml``, with that library's silent gaps closed.

``latex2mathml`` converts the book's LaTeX well but, left alone, it

- rejects or garbles ``\\begin{aligned}`` (its ``&`` comes out as the text ``<mi>&</mi>``):
  rewritten to ``align*``, which it supports (a table with right/left columns);
- reads a ``[`` right after ``\\\\`` or ``\\begin{bmatrix}`` as an optional argument
  (``InvalidAlignmentError`` on the book's ``\\\\ [\\sin(\\phi/2)]\\mathbf{e}``): an empty
  group ``{}`` is put before such a bracket;
- passes an unknown command through as ``<mi>\\foo</mi>``: the known ones are rewritten
  before conversion; any left over is shown as text (``<mtext>``), never as an identifier;
- writes bold and script as ``mathvariant="bold"`` / ``"bold-italic"`` / ``"script"``,
  which MathML Core ignores (Chromium renders a plain letter): the characters are mapped
  to the Unicode mathematical alphanumeric symbols instead, so that after conversion no
  ``mathvariant`` other than ``normal`` remains.
"""

from __future__ import annotations

import html
import re

from latex2mathml.converter import convert

__all__ = ["latex_to_mathml", "mathml_or_text", "bold_char", "LEFTOVER_COMMAND"]

#: commands latex2mathml does not know, rewritten before conversion (sympy's printer and the
#: book both use some of them).
_REWRITES = [
    (re.compile(r"\\begin\{aligned\}"), r"\\begin{align*}"),
    (re.compile(r"\\end\{aligned\}"), r"\\end{align*}"),
    (re.compile(r"\\operatorname\{([^{}]*)\}"), r"\\mathrm{\1}"),
    (re.compile(r"\\displaystyle\b"), ""),
    (re.compile(r"\\limits\b"), ""),
    (re.compile(r"\\middle\b"), ""),
    (re.compile(r"\\tfrac\b"), r"\\frac"),
    (re.compile(r"\\dfrac\b"), r"\\frac"),
    (re.compile(r"\\lVert|\\rVert"), r"\\|"),
    (re.compile(r"\\lvert|\\rvert"), "|"),
    (re.compile(r"\\mathit\{([^{}]*)\}"), r"\1"),
    # a bracket opening a row or a matrix would be read as an optional argument
    (re.compile(r"(\\\\|\\begin\{[a-zA-Z*]+\})(\s*)\["), r"\1\2{}["),
]

#: a command the converter passed through (``<mi>\foo</mi>``, also in <mo>/<mn>).
LEFTOVER_COMMAND = re.compile(r"<(mi|mo|mn)([^>]*)>(\\[a-zA-Z]+)</\1>")

_TOKEN = re.compile(r'<(mi|mn|mo|mtext)([^>]*?) mathvariant="([a-z-]+)"([^>]*)>(.*?)</\1>',
                    re.S)

# first code points of the Unicode mathematical alphanumeric blocks (Latin A, a, Greek
# Alpha, alpha, digit 0); None where the style has no such block.
_BLOCKS = {
    "bold": (0x1D400, 0x1D41A, 0x1D6A8, 0x1D6C2, 0x1D7CE),
    "italic": (0x1D434, 0x1D44E, 0x1D6E2, 0x1D6FC, None),
    "bold-italic": (0x1D468, 0x1D482, 0x1D71C, 0x1D736, 0x1D7CE),
    "script": (0x1D49C, 0x1D4B6, None, None, None),
    "bold-script": (0x1D4D0, 0x1D4EA, None, None, None),
    "double-struck": (0x1D538, 0x1D552, None, None, 0x1D7D8),
    "fraktur": (0x1D504, 0x1D51E, None, None, None),
    "sans-serif": (0x1D5A0, 0x1D5BA, None, None, 0x1D7E2),
    "monospace": (0x1D670, 0x1D68A, None, None, 0x1D7F6),
}
# letters whose slot in a block is a hole: they live in the Letterlike Symbols block
_HOLES = {
    "italic": {"h": "\u210e"},
    "script": {"B": "\u212c", "E": "\u2130", "F": "\u2131", "H": "\u210b", "I": "\u2110",
               "L": "\u2112", "M": "\u2133", "R": "\u211b", "e": "\u212f", "g": "\u210a",
               "o": "\u2134"},
    "double-struck": {"C": "\u2102", "H": "\u210d", "N": "\u2115", "P": "\u2119",
                      "Q": "\u211a", "R": "\u211d", "Z": "\u2124"},
    "fraktur": {"C": "\u212d", "H": "\u210c", "I": "\u2111", "R": "\u211c", "Z": "\u2128"},
}
# Greek variants follow omega in each Greek block (Unicode order: nabla after Omega,
# partial, epsilon, theta, kappa, phi, rho, pi symbols after omega)
_GREEK_UPPER = "ΑΒΓΔΕΖΗΘΙΚΛΜΝΞΟΠΡϴΣΤΥΦΧΨΩ∇"
_GREEK_LOWER = "αβγδεζηθικλμνξοπρςστυφχψω∂ϵϑϰϕϱϖ"


def bold_char(ch: str, style: str = "bold") -> str:
    """The Unicode mathematical alphanumeric character for ``ch`` in ``style``.

    Args:
        ch: one character (Latin letter, digit, Greek letter); others come back unchanged.
        style: a MathML ``mathvariant`` value (``bold``, ``bold-italic``, ``script``, ...).

    Returns:
        One character, e.g. ``bold_char("e") == "𝐞"``, ``bold_char("ω", "bold-italic")
        == "𝝎"``.
    """
    blocks = _BLOCKS.get(style)
    if blocks is None or len(ch) != 1:
        return ch
    hole = _HOLES.get(style, {}).get(ch)
    if hole:
        return hole
    up, low, gup, glow, dig = blocks
    if "A" <= ch <= "Z":
        return chr(up + ord(ch) - ord("A"))
    if "a" <= ch <= "z":
        return chr(low + ord(ch) - ord("a"))
    if "0" <= ch <= "9" and dig is not None:
        return chr(dig + ord(ch) - ord("0"))
    if gup is not None and ch in _GREEK_UPPER:
        return chr(gup + _GREEK_UPPER.index(ch))
    if glow is not None and ch in _GREEK_LOWER:
        return chr(glow + _GREEK_LOWER.index(ch))
    return ch


def _restyle(m: re.Match) -> str:
    tag, pre, style, post, body = m.groups()
    if style == "normal":
        return m.group(0)
    text = html.unescape(body)
    if "<" in text:  # not a plain token: leave the content, drop the ignored attribute
        return f"<{tag}{pre}{post}>{body}</{tag}>"
    mapped = "".join(bold_char(c, style) for c in text)
    # a multi-letter <mi> is upright by default; a single mapped letter keeps its own style
    return f"<{tag}{pre}{post}>{html.escape(mapped, quote=False)}</{tag}>"


def latex_to_mathml(latex: str, display: bool = True) -> str:
    """Convert LaTeX to one ``<math>`` element of MathML Core.

    Args:
        latex: a formula, without ``$`` delimiters (the book's LaTeX or sympy's).
        display: ``display="block"`` (an equation) when true, inline otherwise.

    Returns:
        The ``<math>`` element as a string: no ``mathvariant`` other than ``normal``, no
        ``<mi>`` holding a backslash command (an unknown command is shown as text), no
        ``&`` as text.

    Raises:
        ValueError: if ``latex`` is not a string or the converter rejects it (the message
            names the formula).
    """
    if not isinstance(latex, str):
        raise ValueError(f"latex: expected a string, got {type(latex).__name__}")
    src = latex.strip()
    for pat, rep in _REWRITES:
        src = pat.sub(rep, src)
    try:
        out = convert(src, display="block" if display else "inline")
    except Exception as exc:  # the library raises its own classes, often without a message
        raise ValueError(f"latex: latex2mathml cannot convert {latex[:120]!r} "
                         f"({type(exc).__name__}: {exc})") from exc
    out = _TOKEN.sub(_restyle, out)
    out = LEFTOVER_COMMAND.sub(lambda m: f"<mtext>{m.group(3)}</mtext>", out)
    return out


def mathml_or_text(latex: str | None, fallback: str | None, display: bool = True,
                   tag: str = "code") -> str:
    """MathML of ``latex``, or the text ``fallback`` escaped in ``<tag>`` when there is no
    LaTeX or the converter rejects it: the one fallback of every HTML view (reports,
    notebooks), so a converter gap never hides a result.

    Args:
        latex: a formula, or ``None``.
        fallback: the text shown instead (``"(not shown: too long)"`` when ``None``).
        display: as for :func:`latex_to_mathml`.
        tag: the HTML element around the fallback text.

    Returns:
        HTML text: a ``<math>`` element or ``<tag>fallback</tag>``.
    """
    if latex:
        try:
            return latex_to_mathml(latex, display=display)
        except ValueError:
            pass
    return f"<{tag}>{html.escape(fallback or '(not shown: too long)')}</{tag}>"
