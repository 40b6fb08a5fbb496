"""Time derivatives of models, entry by entry: the kinematic differential
equations of the attitude books, ``\\dot C = -[\\omega]_\\times C`` with ``C`` a model in
parameters declared functions of time (``--let '\\mathbf{q}(t): vector'``) and their rates
declared (``--let '\\dot{\\mathbf{q}} = \\frac12(I_3 + [\\mathbf{q}]_\\times +
\\mathbf{q}\\mathbf{q}^T)\\boldsymbol\\omega'``) or left free.

The reader's structural product rule (:mod:`rigidsym.latex.transformer.book_notations`)
covers sums, products, transposes, inverses and cross products of the symbols; a model
built with ``[x]_\\times``, a power, a norm, a fraction or a ``--let`` function is
differentiated here instead, exactly: the model made explicit in the entries of the
functions of time (every model it mentions substituted, the functions of time kept as
symbols), then the chain rule ``d/dt X = sum_k dX/dx_k xdot_k`` over each entry ``x_k`` of
each function of time, ``xdot`` its rate (:meth:`velocity`: the declared model, or a free
symbol; a rotation's ``R [w_R]``). That is the derivative along the declared rates; it is
what sympy's ``physics.mechanics`` does with ``dynamicsymbols``, on the book's notation.
The result is :class:`Rate`: the explicit derivative, printed as ``d/dt(X)``.
"""

from __future__ import annotations

import re
from collections.abc import Callable

import sympy as sp

from rigidsym.algebra.rigid_motions import LieOp
from rigidsym.latex.shapes import LatexError, matrix_shape

__all__ = ["Rate", "explicit_rate", "expand_models", "dot_key", "rate_target"]


class Rate(LieOp):
    """``d/dt X`` taken entry by entry: ``args = (D, X)``, ``D`` the explicit derivative (the
    operand the engine evaluates), ``X`` the expression as read (printed only)."""

    label, tex = "d/dt", r"\frac{d}{dt}"

    @classmethod
    def shape_of(cls, shapes):
        return shapes[0]

    def value(self, D):
        return D

    def _sympystr(self, printer):
        return f"d/dt({printer._print(self.args[1])})"

    def _latex(self, printer):
        return rf"\frac{{d}}{{dt}}\left({printer._print(self.args[1])}\right)"


def _frozen(v):
    """A model's value with every mutable matrix made immutable (a mutable one is
    unhashable inside an expression)."""
    if isinstance(v, sp.MatrixBase):
        return sp.ImmutableMatrix(v)
    if isinstance(v, sp.Basic):
        return v.replace(lambda e: isinstance(e, sp.MatrixBase) and not isinstance(
            e, sp.ImmutableMatrix), sp.ImmutableMatrix)
    return v


def expand_models(x: sp.Basic, models: dict) -> sp.Basic:
    """``x`` with every symbol whose name ``models`` holds replaced by its model's value,
    through models built on models (a cycle is the declaration graph's to refuse; at most
    ``len(models) + 1`` rounds).

    Args:
        x: a sympy scalar or matrix expression.
        models: symbol name -> value (the reader's ``model_rhs``).

    Returns:
        ``x`` in the symbols no model defines.
    """
    x = _frozen(x)
    for _ in range(len(models) + 1):
        at = {a: _frozen(models[a.name]) for a in _atoms(x) if a.name in models}
        if not at:
            break
        x = x.xreplace(at)
    return x


def _atoms(x) -> set:
    if not isinstance(x, sp.Basic):
        return set()
    return set(x.atoms(sp.MatrixSymbol)) | {s for s in x.atoms(sp.Symbol)
                                           if type(s) is sp.Symbol}


def explicit_rate(x: sp.Basic, timed: dict, models: dict,
                  velocity: Callable[[str, sp.Basic], sp.Basic]) -> sp.Basic:
    """d/dt of ``x`` along the rates of the functions of time.

    Args:
        x: the expression read (a scalar, or a matrix expression of any operators the
            engine makes explicit).
        timed: the names of the symbols declared functions of time -> their glyph keys.
        models: the models by symbol name (each substituted before differentiating).
        velocity: ``velocity(key, symbol)``: the rate of the function of time ``key`` (the
            reader's :meth:`~rigidsym.latex.transformer.book_notations.BookNotationRules.
            velocity`).

    Returns:
        A scalar, or a :class:`Rate` of ``x``'s shape.

    Raises:
        LatexError: an expression the engine cannot make explicit (named).
    """
    from rigidsym.checking.deciding.explicit import explicit

    y = expand_models(x, models)
    try:
        e = explicit(y)
    except Exception:  # noqa: BLE001 - any operator's own failure, named by its operator
        ops = sorted({type(a).label or type(a).__name__ for a in sp.preorder_traversal(y)
                      if isinstance(a, LieOp)}) or [type(x).__name__]
        raise LatexError(f"d/dt of {'a matrix' if matrix_shape(x) else 'a scalar'} built with "
                         f"{', '.join(ops)}, which cannot be written out entry by entry in the "
                         f"functions of time: write it in closed form (e^{{[x]}} by Rodrigues' "
                         f"formula, say) or declare its rate with a --let", "shapes") from None
    out = sp.zeros(*e.shape) if isinstance(e, sp.MatrixBase) else sp.Integer(0)
    for a in sorted(_atoms(y), key=lambda s: s.name):
        if a.name not in timed:
            continue
        rate = velocity(timed[a.name], a)
        if isinstance(a, sp.MatrixSymbol):
            r = explicit(rate)
            for i in range(a.rows):
                for j in range(a.cols):
                    if r[i, j] != 0:
                        out = out + _diff(e, a[i, j]) * r[i, j]
        else:
            out = out + _diff(e, a) * rate
    if isinstance(out, sp.MatrixBase):
        return Rate(sp.ImmutableMatrix(out), x)
    return out


def _diff(e, var):
    if isinstance(e, sp.MatrixBase):
        return e.applyfunc(lambda z: sp.diff(z, var))
    return sp.diff(e, var)


def _closing(text: str, start: int) -> int:
    """The index of the ``}`` that closes the ``{`` at ``start`` (-1 if none)."""
    depth = 0
    for i in range(start, len(text)):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        if depth == 0:
            return i
    return -1


def rate_target(key: str) -> str:
    """The glyph key ``X`` whose rate the key ``\\dot{X}`` names (``\\dot{\\Omega}_{1}``:
    ``\\Omega_{1}``, the reader's one spelling of both), else ``""``."""
    if not key.startswith("\\dot{"):
        return ""
    j = _closing(key, 4)
    rest = key[j + 1:] if j > 0 else "?"
    if rest and not re.fullmatch(r"(_\{[^{}]*\})+", rest):
        return ""
    return key[5:j] + rest


def dot_key(key: str) -> str:
    """The reader's key of ``\\dot X`` for the glyph key ``X`` (``\\Omega_{1}``:
    ``\\dot{\\Omega}_{1}``, as :func:`rate_target` reads it back)."""
    m = re.fullmatch(r"(\\(?:mathbf|boldsymbol|mathcal|math(?:sf|tt|it))\{[^{}]*\}|\\?[A-Za-z]+)"
                     r"((?:_\{[^{}]*\})+)", key)
    return f"\\dot{{{m.group(1)}}}{m.group(2)}" if m else f"\\dot{{{key}}}"
