"""Respellings of a reader's LaTeX that its ``--let`` declarations settle (issue 63).

The grammar reads a plain ``e`` directly before ``^`` as the exponential (``e^{[\\omega]
\\theta}``), as the books mean it when nothing names a symbol ``e``. A reader who declares
one (``--let 'e = |\\mathbf{e}|'``, Hughes' and Markley's norm of the Euler-axis vector, or
``--let 'e: scalar'``) means ``e^2`` as its square: with such a declaration every ``e^`` of
the LaTeX and of the models is respelt ``{e}^`` (a braced group, the same glyph), before
either semantics parses it, and the reading says so.
"""

from __future__ import annotations

import re

from rigidsym.latex.lets import read_lets, split_lets

__all__ = ["declared_e"]

_E_POWER = re.compile(r"(?<![\\A-Za-z{])e(?=\^)")


def declared_e(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: with a ``--let`` naming a plain ``e``, each ``e^`` respelt
    ``{e}^`` in the LaTeX and in every declaration (``note`` says so); else all unchanged
    and ``note`` is ``""``.

    Args:
        latex: the LaTeX.
        let: the declarations as :func:`rigidsym.latex.lets.read_lets` takes them (``None``,
            a string, a list of strings or a dict).

    Raises:
        BadInput: as :func:`rigidsym.latex.lets.read_lets`.
    """
    if let is None or not any(x.key == "e" for x in read_lets(let)):
        return latex, let, ""
    new = _E_POWER.sub("{e}", latex)
    if isinstance(let, dict):
        out = {k: _E_POWER.sub("{e}", v) if isinstance(v, str) else v for k, v in let.items()}
    else:
        out = [_E_POWER.sub("{e}", d) for d in split_lets([let] if isinstance(let, str)
                                                             else let)]
    changed = new != latex or out != let
    note = ("e^: a power of the declared symbol e (a --let names e), not the exponential; "
            "write \\exp for it") if changed else ""
    return new, out, note
