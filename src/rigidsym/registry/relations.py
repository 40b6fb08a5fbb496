"""A relation :class:`Rel` and what its sides may be written in: the nodes the engine knows,
checked when a ``Rel`` is made (it raises :class:`BadInput`, the error of bad user input, of
:mod:`rigidsym.core.errors`; both are re-exported by
:mod:`rigidsym.registry.declarations`).

A node the engine does not know would be decided through a guess (sympy calls a
``Derivative`` of a 3 x 3 symbol a scalar; an undefined ``f(theta)`` and ``f(phi)`` would
be one variable): such a node is refused at declaration time with ``BadInput`` naming it
and the vocabulary word to use. A ``Derivative`` of a matrix at the top of a side becomes the lazy
:class:`~rigidsym.algebra.operators.Diff`, which the engine knows.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from rigidsym.core.errors import BadInput

# sympy and the algebra layer are imported where a side is checked, not here: the registry
# (and with it the command line's --help) imports this module and stays free of sympy

__all__ = ["BadInput", "Rel", "check_side", "UnknownNode", "WORDS"]

#: sympy functions a printed form may not hold, and the word of ``rigidsym`` to use (``asin``
#: is decided on its principal branch since ``asin(sin(b/2)) = b/2`` for ``b`` on
#: ``[0, pi]``, :mod:`rigidsym.checking.deciding.branches`; elsewhere undecided)
WORDS = {
    "exp": "rigidsym.expm (the exponential of so(3) or se(3))",
    "log": "rigidsym.logm (the principal logarithm of a rotation or a transform)",
    "atan": "rigidsym.atan2 (principal branch the zero test honours)",
    "acot": "rigidsym.atan2", "asec": "rigidsym.acos", "acsc": "rigidsym.acos",
}


def _is_matrix_valued(x) -> bool:
    import sympy as sp
    from sympy.matrices.kind import MatrixKind

    return isinstance(x, sp.MatrixBase | sp.MatrixExpr) or \
        isinstance(getattr(x, "kind", None), MatrixKind)


class UnknownNode(ValueError):
    """A node the engine does not know (``Rel`` raises it as ``BadInput``)."""


def _refuse(what: str, node, word: str):
    import sympy as sp

    text = sp.sstr(node)
    text = text if len(text) <= 80 else text[:77] + "..."
    raise UnknownNode(f"{what}: the node {type(node).__name__} `{text}` is not in the "
                   f"vocabulary the engine decides; use {word}")


def check_side(x, what: str):
    """The side ``x`` of a relation, checked (and a top-level matrix ``Derivative`` made a
    :class:`Diff`).

    Args:
        x: a sympy expression, matrix or matrix expression.
        what: the side's name in messages (``"lhs"``, ``"rhs"``).

    Returns:
        ``x``, or ``Diff(X, v)`` for ``x = Derivative(X, v)`` with ``X`` a matrix.

    Raises:
        UnknownNode: a node the engine does not know (a matrix ``Derivative`` inside an
            expression, a function of a matrix, an undefined function of anything but
            time, an inverse trigonometric function other than ``acos``/``asin``/``atan2``); the
            message names the node and the word to use.
    """
    import sympy as sp

    from rigidsym.algebra.operators import Diff

    if isinstance(x, sp.Derivative) and _is_matrix_valued(x.expr):
        out = x.expr
        for v, n in x.variable_count:
            for _ in range(int(n)):
                out = Diff(out, v)
        x = out
    _walk(x, what)
    return x


def _walk(x, what: str) -> None:
    import sympy as sp
    from sympy.core.function import AppliedUndef

    from rigidsym.algebra.operators import Det, DiffEntry
    from rigidsym.algebra.symbols import TIME, constraint_of

    seen: set = set()
    stack = [x]
    while stack:
        y = stack.pop()
        if isinstance(y, sp.MatrixBase):
            stack.extend(y)
            continue
        if not isinstance(y, sp.Basic) or y in seen:
            continue
        seen.add(y)
        if y.is_Atom:
            continue
        if isinstance(y, sp.Derivative):
            if _is_matrix_valued(y.expr):
                _refuse(what, y, "rigidsym.diff(X, v) (a matrix derivative, lazily)")
        elif isinstance(y, AppliedUndef):
            if y.args != (TIME,) and constraint_of(y) is None:
                _refuse(what, y, "rigidsym.scalar(name, t=TIME) for a function of time, or "
                                 "a book symbol with a model")
            continue
        elif isinstance(y, sp.Function) and not isinstance(y, sp.MatrixExpr):
            name = type(y).__name__
            if name in WORDS:
                _refuse(what, y, WORDS[name])
            if not isinstance(y, Det | DiffEntry) and any(_is_matrix_valued(a) for a in y.args):
                _refuse(what, y, "an operator of rigidsym.declare (trace, Det, expm, ...)")
        stack.extend(y.args)


@dataclass(frozen=True)
class Rel:
    """One equality ``lhs = rhs`` to decide (sympy expressions, matrices or matrix expressions).

    Attributes:
        lhs: the left-hand side.
        rhs: the right-hand side, of the same shape.
        label: names the member in reports (``"d_P"``, ``"second member"``); optional.
        page: for a claim that the page prints as a member of the id's chain (``p'' \\equiv
            n_0 / ||f|| = n_P . f / ||f||^2``: the last member, derived, not defined), its
            place k (1, 2, ...) among the printed relations as the page reads them (each
            chain ``a = b = c`` as ``a = b``, ``a = c``); 0: not printed. The certificate
            marks it (``"page": k``) so that certcheck reads that member against the proof.

    Raises:
        BadInput: a side holds a node the engine does not know (the message names it and
            the word of :mod:`rigidsym.declare` to use).
    """

    lhs: Any
    rhs: Any
    label: str = ""
    page: int = 0

    def __post_init__(self):
        try:
            object.__setattr__(self, "lhs", check_side(self.lhs, "lhs"))
            object.__setattr__(self, "rhs", check_side(self.rhs, "rhs"))
        except UnknownNode as exc:
            raise BadInput(str(exc)) from None
