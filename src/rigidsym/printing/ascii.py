"""Plain ASCII for terminals without Unicode (``rigidsym ... --ascii``).

The terminal output is in the book's Unicode notation (``ȧ∥ = (ȧ·ω)/‖ω‖²``). For a
terminal or a log that cannot show it, :func:`to_ascii` writes the same text in the ASCII
names the declarations use (``adot_par = (adot.omega)/||omega||^2``), and
:class:`AsciiStream` applies it to everything a stream is given (rich's progress and
tables included: the stream reports an ASCII encoding, so rich draws ASCII boxes).
"""

from __future__ import annotations

import re
import unicodedata

from rigidsym.printing.names import GREEK

__all__ = ["to_ascii", "AsciiStream", "needs_ascii"]

_NAMES = {ch: name for name, ch in GREEK.items() if name != "lam"}
_ACCENT = {"\u0307": "dot", "\u0308": "ddot", "\u0303": "~", "\u0302": "^", "\u0304": "bar",
          "\u030a": "ring", "\u0306": "breve", "\u030c": "check"}
_SUB = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")
_SUP = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")
_SYMBOLS = {
    "‖": "||", "·": ".", "×": "x", "∥": "_par", "⊥": "_perp", "√": "sqrt", "≈": "~",
    "≤": "<=", "≥": ">=", "≠": "!=", "−": "-", "–": "-", "—": "--", "…": "...",
    "→": "->", "←": "<-", "∈": " in ", "∉": " not in ", "𝟏": "1", "ᵀ": "^T", "’": "'",
    "‘": "'", "“": '"', "”": '"', "•": "*", "✗": "x", "✓": "ok", "∞": "inf", "±": "+-",
    "°": " deg", "½": "1/2", "⁻¹": "^-1", "∑": "sum", "∫": "int", "∂": "d",
}


def to_ascii(text: str) -> str:
    """``text`` in plain ASCII: Greek letters by name, accents as ``dot``/``ddot``/``~``
    suffixes, subscripts as ``_1``, superscripts as ``^2``, ``‖ω‖`` as ``||omega||``; any
    other non-ASCII character by its closest ASCII letter, else ``?``."""
    if text.isascii():
        return text
    s = re.sub(r"√(\w+)", r"sqrt(\1)", text).replace("√", "sqrt")
    s = unicodedata.normalize("NFD", s)
    s = re.sub("[₀-₉]+", lambda m: "_" + m.group(0).translate(_SUB), s)
    s = re.sub("[⁰-⁹⁻¹²³]+", lambda m: "^" + m.group(0).translate(_SUP), s)
    out = []
    for ch in s:
        if ch.isascii():
            out.append(ch)
        elif ch in _ACCENT:
            out.append(_ACCENT[ch])
        elif ch in _NAMES:
            out.append(_NAMES[ch])
        elif ch in _SYMBOLS:
            out.append(_SYMBOLS[ch])
        else:
            base = unicodedata.normalize("NFKD", ch).encode("ascii", "ignore").decode()
            out.append(base or _box(ch))
    return "".join(out)


def _box(ch: str) -> str:
    """Box drawing and block characters (rich's tables and bars) as ASCII lines."""
    name = unicodedata.name(ch, "")
    if "HORIZONTAL" in name or name.startswith("BOX DRAWINGS LIGHT") and "VERTICAL" not in name:
        return "-"
    if "VERTICAL" in name:
        return "|"
    if name.startswith(("BOX DRAWINGS", "FULL BLOCK", "LEFT", "RIGHT")):
        return "+"
    return "?"


def needs_ascii(stream) -> bool:
    """Whether ``stream`` cannot encode the book's notation (an ASCII or Latin-1 locale)."""
    enc = getattr(stream, "encoding", None) or "ascii"
    try:
        "ȧ∥ω‖²ᵀ𝟏".encode(enc)
    except (UnicodeEncodeError, LookupError):
        return True
    return False


class AsciiStream:
    """A text stream that writes :func:`to_ascii` of everything to ``stream``."""

    encoding = "ascii"

    def __init__(self, stream):
        self._stream = stream

    def write(self, text: str) -> int:
        self._stream.write(to_ascii(text))
        return len(text)

    def __getattr__(self, name):  # flush, isatty, fileno, ... of the wrapped stream
        return getattr(self._stream, name)
