"""Shapes and errors of the LaTeX reader: the shape rules of juxtaposition and sums, block
sizing, default glyphs and :class:`LatexError` (used by
:mod:`rigidsym.latex.transformer.chapter`)."""

from __future__ import annotations

import re

import sympy as sp

from rigidsym.latex.table import Glyph

__all__ = ["LatexError"]


class LatexError(ValueError):
    """LaTeX that cannot be read: a syntax error (with the position, a caret under the
    offending token and the constructs expected), an unknown macro (named), or a
    juxtaposition or sum whose shapes do not fit (a ``ValueError``).

    Attributes:
        construct: a short name of what could not be read (``"syntax"``, ``"unknown macro
            \\int"``, ``"shapes"``).
        glyphs: for an error past the syntax, the glyph-table rows of the glyphs read
            before it, by LaTeX key (to name those a ``--let`` should declare).
    """

    def __init__(self, message: str, construct: str = "syntax"):
        super().__init__(message)
        self.construct = construct
        self.glyphs: dict = {}


class SizedIdentity(sp.Identity):
    """An identity whose size the LaTeX wrote (``I_3``): never resized by its neighbours."""


class SizedZero(sp.ZeroMatrix):
    """A zero whose size the LaTeX wrote (``0_{3\\times 3}``): never resized."""


def loose(x) -> bool:
    """An identity or zero the LaTeX left unsized (``I``, ``\\mathbf{1}``, ``\\mathbf{0}``):
    its neighbours size it."""
    return type(x) in (sp.Identity, sp.ZeroMatrix)


def matrix_shape(x) -> tuple[int, int] | None:
    """``(rows, cols)`` of a matrix expression, ``None`` for a scalar."""
    if isinstance(x, sp.MatrixBase | sp.MatrixExpr):
        return int(x.shape[0]), int(x.shape[1])
    return None


def as_scalar(x):
    """A 1 x 1 matrix as its entry (the book's ``e^T d`` is a scalar)."""
    s = matrix_shape(x)
    if s == (1, 1):  # lazily: indexing a symbolic product builds a sum (slow)
        return x[0, 0] if isinstance(x, sp.MatrixBase) else sp.Trace(x)
    return x


def shape_words(x) -> str:
    """The shape of ``x`` in words for a message: ``a scalar`` or ``a 3x3 matrix``."""
    s = matrix_shape(x)
    return "a scalar" if s is None else f"a {s[0]}x{s[1]} matrix"


#: the meaning of a glyph the user wrote and nothing declares (:func:`default_glyph`); a
#: free glyph with another meaning is one the reader introduced (a rate, a body velocity)
UNDECLARED = "(not in the glyph table)"


def default_glyph(key: str, base) -> Glyph:
    """A glyph the table does not list: bold lower-case a 3-vector, bold capital a 3x3
    matrix, anything else a scalar; named after its LaTeX."""
    shape: tuple = ()
    if base and base[0] == "bold":
        letter = base[1].lstrip("\\")
        shape = (3, 3) if letter[0].isupper() else (3, 1)
    return Glyph(key, "*", name_from_key(key), shape, "free", UNDECLARED, "")


def name_from_key(key: str) -> str:
    """The plain name of a glyph key (``\\mathbf{Q}`` -> ``Q``, ``\\dot{a}`` -> ``adot``,
    ``{}^{A}_{B}R`` -> ``^A_B R``): fonts and braces dropped, an accent written after the letter."""
    m = re.match(r"\{\}((?:[\^_]\{[^{}]*\})+)(.+)$", key)  # {}^{A}_{B}R: ^A_B R
    if m:
        return re.sub(r"[{}]", "", m.group(1)) + " " + name_from_key(m.group(2))
    s = re.sub(r"\\(mathbf|boldsymbol|mathcal)\{([^}]*)\}", r"\2", key)
    s = re.sub(r"\\math(sf|tt|it|frak)\{([^}]*)\}", r"\2_\1", s)  # \mathsf{R}: R_sf
    s = re.sub(r"\\(dot|ddot|tilde|hat|bar|mathring|breve|check|vec|underline)\{([^}]*)\}",
               lambda m: m.group(2) + m.group(1), s)  # \vec{a}: avec, printed a⃗
    s = s.replace("\\", "").replace("{", "").replace("}", "")
    return s


def fit(a, b, op):
    """The operands of a sum or difference (``op``: ``"add"`` or another word), scalars read
    as such, with an exact scalar 0 made the zero matrix of the other side's shape.

    Raises:
        LatexError: the shapes do not fit (construct ``shapes``)."""
    a, b = as_scalar(a), as_scalar(b)
    if matrix_shape(a) != matrix_shape(b):
        if matrix_shape(a) is None and a == 0:
            return sp.ZeroMatrix(*matrix_shape(b)), b
        if matrix_shape(b) is None and b == 0:
            return a, sp.ZeroMatrix(*matrix_shape(a))
        word = "sum" if op == "add" else "difference"
        raise LatexError(f"a {word} of {shape_words(a)} and {shape_words(b)}: shapes do not fit",
                         "shapes")
    return a, b


def shaped_product(a, b):
    """The product of a juxtaposition ``a b`` read by the shapes: the matrix product where it
    fits, a 1x1 matrix taken as a scalar otherwise.

    Raises:
        LatexError: no product fits (construct ``shapes``)."""
    sa, sb = matrix_shape(a), matrix_shape(b)
    if sa is None or sb is None:
        return a * b
    if sa[1] == sb[0]:
        r = a * b
        if type(r) in (sp.Identity, sp.ZeroMatrix) and not (loose(a) or loose(b)):
            # M M^{-1} of a sized M is the identity of M's size: never resized by the other
            # side (M M^{-1} = I_4 of a 3x3 M is a shape mismatch, not 4x4 = 4x4)
            return SizedIdentity(r.rows) if type(r) is sp.Identity else SizedZero(*r.shape)
        return r
    if sa == (1, 1):
        return as_scalar(a) * b
    if sb == (1, 1):
        return a * as_scalar(b)
    raise LatexError(f"juxtaposition of {shape_words(a)} and {shape_words(b)}: no product fits "
                     f"(declare the shapes, e.g. with the glyph table)", "shapes")


def as_block(c):
    """``c`` as a matrix: a scalar as a 1x1 matrix, a matrix as it is."""
    if matrix_shape(c) is None:
        return sp.ImmutableMatrix([[c]])
    return c


def fit_blocks(cells: list[list], unit_rows: frozenset[int] = frozenset()) -> list[list]:
    """Size the zero and identity blocks (``\\mathbf{O}``, ``\\mathbf{0}``, ``\\mathbf{1}``)
    from the other blocks of their row and column: the book writes them unsized.
    ``unit_rows``: the rows one high where no block of theirs sizes them (a reader's row of
    scalar zeros, Gallier's ``[B & U; 0 & 0]``)."""

    def first(sizes):  # a sized block, else an identity's (square) size
        sizes = list(sizes)
        return next((n for n, c in sizes if not loose(c)),
                    next((n for n, c in sizes if isinstance(c, sp.Identity)), None))

    heights = [first((matrix_shape(c)[0], c) for c in row) or (1 if i in unit_rows else None)
               for i, row in enumerate(cells)]
    ncol = max(len(r) for r in cells)
    widths = [first((matrix_shape(r[j])[1], r[j]) for r in cells if j < len(r))
              for j in range(ncol)]
    out = []
    for i, row in enumerate(cells):
        new = []
        for j, c in enumerate(row):
            if loose(c) and heights[i] and widths[j] and matrix_shape(c) != (heights[i], widths[j]):
                if isinstance(c, sp.Identity) and heights[i] != widths[j]:
                    raise LatexError("an identity block that is not square", "shapes")
                c = (sp.ZeroMatrix(heights[i], widths[j]) if isinstance(c, sp.ZeroMatrix)
                     else sp.Identity(heights[i]))
            new.append(c)
        out.append(new)
    return out


def _caret(text: str, pos: int) -> str:
    return f"  {text}\n  {' ' * pos}^"


def size_identity(a, b, product: int):
    """A reader's unsized identity (``I``, ``\\mathbf{1}``) sized by its neighbour: in a
    sum as the other term, in a product as the other factor's inner dimension."""
    sa, sb = matrix_shape(a), matrix_shape(b)
    if sa is None or sb is None or sa == sb or product and (1, 1) in (sa, sb):
        return a, b  # a 1x1 factor is a scalar (a^T b I, Wittenburg): it sizes nothing
    if type(a) is sp.Identity and (product or sb[0] == sb[1]):  # not an I_3 (transformer.meanings)
        a = sp.Identity(sb[0])
    elif type(b) is sp.Identity and (product or sa[0] == sa[1]):
        b = sp.Identity(sa[1])
    return a, b
