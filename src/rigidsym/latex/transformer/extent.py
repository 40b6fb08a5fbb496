r"""The extent of a function's argument written without parentheses (a mixin of the LaTeX
transformer :class:`rigidsym.latex.transformer.chapter.LatexTransformer`): ``\cos\theta\phi``,
``\sin\omega t``, a contested construct (:mod:`rigidsym.latex.contested`, "argument extent").

The tree marks it (``arg_extent``, :func:`rigidsym.latex.rewrites.argument_extents`): a
function (``\sin``, ``\cos``, ``\tan``, ``\exp``, ``\log``, ``\operatorname{tr}`` ...) whose
argument has no parentheses, followed directly (no ``\,``, no operator) by more factors.
The factors that continue the argument are the leading run of scalars among them; a vector or
matrix ends it (``\sin\phi\mathbf{E}`` is sin(φ) E, the only reading that types). Where that
run is empty the function takes its one factor as before and nothing is said; else the run
is a choice point (one per construct, all read alike, :func:`is_extent_point`): ``factor``,
the function of the next factor only (Angeles, Murray-Li-Sastry), or ``product``, the
function of the whole run (Thomson, Meirovitch, Taylor: ``\sin\omega t``), unless a
``--let 'argument extent: ...'`` settles it.
"""

from __future__ import annotations

import lark
import sympy as sp

from rigidsym.latex.shapes import as_scalar, matrix_shape

__all__ = ["ArgumentExtentRules", "EXTENT_SUFFIX", "is_extent_point", "extent_parts"]

#: the suffix of an argument extent's choice point: ``\cos\theta\phi argument``
EXTENT_SUFFIX = " argument"


def is_extent_point(key: str) -> bool:
    r"""``key`` is the choice point of an argument extent (``\cos\theta\phi argument``)."""
    return key.endswith(EXTENT_SUFFIX)


def extent_parts(key: str) -> tuple[str, str, str]:
    r"""The head, argument and run of the choice point ``key``, as written: ``("\cos",
    "\theta", "\phi")``."""
    head, arg, run = key[:-len(EXTENT_SUFFIX)].split("\x1f")
    return head, arg, run


class ArgumentExtentRules:
    """The transformer rule of ``arg_extent`` (a mixin of ``LatexTransformer``, which
    provides ``mul``, ``func``, ``func_power``, ``matfunc``, ``reader``, ``choices``,
    ``choice_points``, ``_note``)."""

    def arg_extent(self, items):
        head, arg_text, inner = str(items[0]), str(items[1]), items[2]
        texts, factors = [str(x) for x in items[3::2]], list(items[4::2])
        rule = getattr(self, inner.data[len("extent_"):])
        kids = list(inner.children)
        run = 0
        arg = kids[-1]
        if self.reader and self._scalar(arg):
            while run < len(factors) and self._scalar(factors[run]):
                run += 1
        if run == 0:
            return self._times(rule(kids), factors)
        written = _joined(texts[:run])
        key = "\x1f".join((head, arg_text, written)) + EXTENT_SUFFIX
        choice, how = self.contested_reading("argument extent", key, ("factor", "product"))
        spelt = f"{head}{_sep(head, arg_text)}{arg_text}{_sep(arg_text, written)}{written}"
        if choice == "product":
            self._note(f"{spelt}: read as {head}({arg_text}{_sep(arg_text, written)}"
                       f"{written}), the function of the whole product ({how}: or "
                       f"{head}({arg_text}){written})")
            whole = self._times(arg, factors[:run])
            return self._times(rule([*kids[:-1], whole]), factors[run:])
        self._note(f"{spelt}: read as {head}({arg_text}){written}, the function of the next "
                   f"factor only ({how}: or {head}({arg_text}{_sep(arg_text, written)}"
                   f"{written}))")
        return self._times(rule(kids), factors)

    def _times(self, v, factors):
        for f in factors:
            v = self.mul([v, f])
        return v

    def _scalar(self, v) -> bool:
        """``v`` (a transformed child) is a scalar: it may continue the argument."""
        if isinstance(v, lark.Tree | lark.Token):
            return False
        x = self._val(v)
        return isinstance(x, sp.Expr) and not isinstance(x, sp.MatrixExpr) \
            and matrix_shape(as_scalar(x)) is None


def _sep(before: str, after: str) -> str:
    """A space where TeX needs one between two pieces (``\\omega t``)."""
    return " " if before[-1:].isalpha() and after[:1].isalpha() else ""


def _joined(texts) -> str:
    out = ""
    for t in texts:
        out += _sep(out, t) + t
    return out
