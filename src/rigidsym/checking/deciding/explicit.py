"""Explicit values of book symbols under a declaration's model, and small helpers of the
checker (:mod:`rigidsym.checking.checker`): shapes, entries, the per-id seed.
"""

from __future__ import annotations

import zlib

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.matrices.exceptions import NonInvertibleMatrixError
from sympy.matrices.expressions.matexpr import MatrixElement
from sympy.matrices.kind import MatrixKind
from sympy.polys.matrices import DomainMatrix
from sympy.polys.matrices.exceptions import DMNonInvertibleMatrixError

from rigidsym.algebra.operators import Det, Diff, DiffEntry
from rigidsym.algebra.rigid_motions import LieOp
from rigidsym.registry.declarations import Rel


# --------------------------------------------------------------------------- helpers
def explicit(x, model: dict | None = None):
    """Substitute the model and return an explicit ``sp.Matrix`` or scalar expression.

    Matrix expressions are evaluated structurally (blocks, sums, products, integer powers,
    transposes, inverses, traces, determinants) on explicit operands: sympy's generic
    ``doit()`` takes symbolic-summation and simplification paths that cost seconds or
    minutes on block products and matrix powers.
    """
    model = model or {}
    key = (id(x), id(model))
    hit = EXPLICIT_CACHE.get(key)
    # the entry holds x and the model themselves, so neither id is reused by another object
    # while it is cached (a model built per witness point and freed gave its id to the next)
    if hit is not None and hit[0] is x and hit[2] is model:
        return hit[1]
    if isinstance(x, sp.MatrixBase | sp.MatrixExpr):
        y = sp.Matrix(_mx(x, model))
    else:
        y = explicit_scalar(sp.sympify(x), model)
    EXPLICIT_CACHE[key] = (x, y, model)
    return y


#: explicit() results within one check (keyed by the identity of the expression and the
#: model, both held by the entry; cleared per check)
EXPLICIT_CACHE: dict = {}


_MATRIX_TERMS = (sp.Trace, sp.Determinant, MatrixElement, DiffEntry)


def explicit_scalar(s, model):
    """Explicit scalar: matrix-valued sub-terms evaluated, model substituted."""
    if model and s.has(*_MATRIX_TERMS):
        # evaluated on the model before substituting it: a model's value is often a mutable
        # sp.Matrix, and xreplace would put it inside an operator's arguments (CPM, Ad, ad,
        # hat ...), where hashing it raises TypeError (aᵀ CPM(b) a = 0)
        s = s.replace(lambda z: isinstance(z, _MATRIX_TERMS), lambda z: _ev(z, model))
    y = s.xreplace(model) if model else s
    if not y.has(*_MATRIX_TERMS, sp.MatrixExpr, sp.Derivative):
        return y
    out = y.replace(lambda z: isinstance(z, _MATRIX_TERMS), lambda z: _ev(z, {}))
    out = out.doit() if out.has(sp.MatrixExpr) else out
    if out.has(sp.Derivative):  # a derivative of a model's expression: taken now
        out = out.replace(lambda z: isinstance(z, sp.Derivative)
                          and not isinstance(z.expr, AppliedUndef), lambda z: z.doit())
    return out


def _ev(z, model):
    """The explicit scalar value of a trace, determinant or entry of a matrix expression."""
    if isinstance(z, sp.Trace):
        return _mx(z.arg, model).trace()
    if isinstance(z, sp.Determinant):
        return _mx(z.arg, model).det(method="berkowitz")
    if isinstance(z, MatrixElement):
        return _mx(z.parent, model)[int(z.i), int(z.j)]
    # an entry of a lazy derivative
    var = z.args[1].xreplace(model) if model else z.args[1]
    return sp.diff(_mx(z.args[0], model)[int(z.args[2]), int(z.args[3])], var)


def _mx(x, model) -> sp.ImmutableMatrix:
    """Explicit value of a matrix expression (see :func:`explicit`)."""
    im = sp.ImmutableMatrix
    if isinstance(x, sp.MatrixBase):
        if x.has(*_MATRIX_TERMS):  # an entry's trace or determinant (a norm x^T x) evaluated
            return im(x.applyfunc(lambda e: explicit_scalar(e, model)))
        return im(x.xreplace(model)) if model else im(x)
    if isinstance(x, sp.MatrixSymbol):
        v = model.get(x)
        return im(v) if v is not None else im(x.as_explicit())
    if isinstance(x, sp.Identity):
        return im(sp.eye(int(x.rows)))
    if isinstance(x, sp.ZeroMatrix):
        return im(sp.zeros(*(int(n) for n in x.shape)))
    if isinstance(x, sp.MatAdd):
        args = [_mx(a, model) for a in x.args]
        acc = args[0]
        for a in args[1:]:
            acc = acc + a
        return im(acc)
    if isinstance(x, sp.MatMul):
        coeff, mats = sp.S.One, []
        for a in x.args:
            if isinstance(a, sp.MatrixBase | sp.MatrixExpr):
                mats.append(_mx(a, model))
            else:
                coeff = coeff * explicit_scalar(a, model)
        acc = mats[0]
        for m in mats[1:]:
            acc = matmul(acc, m)
        return im(coeff * acc) if coeff != 1 else im(acc)
    if isinstance(x, sp.MatPow) and x.exp.is_Integer:
        base, n = _mx(x.base, model), int(x.exp)
        if n < 0:
            base, n = _inverse(base), -n
        acc = im(sp.eye(base.rows))
        for _ in range(n):
            acc = matmul(acc, base)
        return im(acc)
    if isinstance(x, sp.Transpose):
        return im(_mx(x.arg, model).T)
    if isinstance(x, sp.Inverse):
        return _inverse(_mx(x.arg, model))
    if isinstance(x, Diff):
        return im(sp.Matrix(_mx(x.args[0], model)).diff(explicit_scalar(x.args[1], model)))
    if isinstance(x, LieOp):  # hat, vee, transform, Ad, ad, expm (rigidsym.algebra.rigid_motions)
        return im(x.value(*[_mx(a, model) for a in x.args[:x.operands]]))
    if isinstance(x, sp.BlockMatrix):
        blocks = x.blocks
        rows = [[_mx(blocks[i, j], model) for j in range(blocks.cols)]
                for i in range(blocks.rows)]
        return im(sp.BlockMatrix(rows).as_explicit())
    # anything else (a custom operator of a derivations module): sympy's generic path
    y = x.xreplace(model) if model else x
    y = y.doit()
    return im(y.as_explicit() if isinstance(y, sp.MatrixExpr) else y)


def _inverse(m: sp.ImmutableMatrix) -> sp.ImmutableMatrix:
    """The exact inverse of ``m``. A block-triangular matrix (a transform ``[R p; 0 1]``,
    Featherstone's ``[E 0; -E[r] E]``) by the inverses of its diagonal blocks; a 4x4 or
    smaller whose entries are rational functions of its symbols (and of entries of matrix
    symbols, ``b[0, 0]``) fraction-free over their ring (sympy's ``DomainMatrix``), each
    entry one cancelled fraction; any other by ``inv()``. Sympy's ``inv()`` simplifies each
    Gauss-Jordan pivot: it took 6-39 s on the Cayley map's ``(I_3 - [b]x)^{-1}(I_3 + [b]x)``
    (McCarthy) and 29 s on a generic 4x4, the ring 0.01-0.15 s.

    Raises:
        ValueError: ``m`` is not square, or singular (as ``inv()``:
            ``NonSquareMatrixError``, ``NonInvertibleMatrixError``).
    """
    n = m.rows
    if m.cols != n or not m.free_symbols:
        return sp.ImmutableMatrix(m.inv())
    for k in range(1, n):
        if all(x == 0 for x in m[:k, k:]):  # [A 0; C D]: [A^-1 0; -D^-1 C A^-1 D^-1]
            ai, di = _inverse(m[:k, :k]), _inverse(m[k:, k:])
            low = -matmul(matmul(di, m[k:, :k]), ai)
            return sp.ImmutableMatrix(sp.BlockMatrix(
                [[ai, sp.zeros(k, n - k)], [low, di]]).as_explicit())
        if all(x == 0 for x in m[k:, :k]):  # [A B; 0 D]: [A^-1 -A^-1 B D^-1; 0 D^-1]
            ai, di = _inverse(m[:k, :k]), _inverse(m[k:, k:])
            up = -matmul(matmul(ai, m[:k, k:]), di)
            return sp.ImmutableMatrix(sp.BlockMatrix(
                [[ai, up], [sp.zeros(n - k, k), di]]).as_explicit())
    if n > 4:
        return sp.ImmutableMatrix(m.inv())
    sub = {a: sp.Dummy() for a in m.atoms(MatrixElement)}
    dm = DomainMatrix.from_Matrix(sp.Matrix(m.xreplace(sub)))
    ring = dm.domain
    if ring.is_EX or ring.is_EXRAW:
        return sp.ImmutableMatrix(m.inv())
    try:
        num, den = dm.inv_den()  # fraction-free: the adjugate and determinant, or multiples
    except DMNonInvertibleMatrixError:
        raise NonInvertibleMatrixError("Matrix det == 0; not invertible.") from None
    field = ring.get_field()  # each entry num/den, cancelled there
    inv = num.convert_to(field) * field.quo(field.one, field.convert_from(den, ring))
    return sp.ImmutableMatrix(inv.to_Matrix().xreplace({v: k for k, v in sub.items()}))


_INFINITE = (sp.S.Infinity, sp.S.NegativeInfinity, sp.S.ComplexInfinity, sp.S.NaN)


def _finite_atoms(mats) -> bool:
    """Whether no entry of ``mats`` holds an infinity or ``nan`` (or an atom declared
    infinite): each distinct node visited once (a shared subexpression is not walked again,
    as ``Basic.has`` would)."""
    seen: set[int] = set()
    stack = [e for m in mats for e in m]
    while stack:
        x = stack.pop()
        if id(x) in seen:
            continue
        seen.add(id(x))
        if x in _INFINITE or (x.is_Symbol and x.is_finite is False):
            return False
        stack.extend(x.args)
    return True


def matmul(a: sp.MatrixBase, b: sp.MatrixBase) -> sp.ImmutableMatrix:
    """``a * b`` of explicit matrices, entry by entry: ``Add`` of the products of the
    nonzero pairs, the same expressions as sympy's product.

    sympy's product (``DomainMatrix`` over ``EXRAW``) first asks, for every nonzero entry
    of either side, whether ``0 * entry`` is ``0`` (``Mul`` asks whether the entry is
    finite, a walk of the assumptions system over the whole expression): a fifth of a
    cold ``rigidsym verify``. Here that question is asked of the atoms only, once: with no
    infinity anywhere, ``0 * entry`` is ``0`` for every entry and the products of the
    nonzero pairs are all that sympy adds; otherwise sympy's own product is used.

    Raises:
        ShapeError: the shapes do not fit (sympy's error).
    """
    if a.cols != b.rows or not _finite_atoms((a, b)):
        return sp.ImmutableMatrix(a * b)
    rows, cols = a.tolist(), b.T.tolist()
    return sp.ImmutableMatrix([[sp.Add(*[x * y for x, y in zip(r, c, strict=True) if x and y])
                                for c in cols] for r in rows])


class UnknownShape(ValueError):
    """A node whose shape the rules do not know (matrix-valued to sympy, yet not a matrix
    expression): its shape is never evidence of a mismatch."""


def _flat(e) -> str:
    """``e`` as written up to the grouping and order of its sums and products (the
    certificate's printer writes ``a + (b + c)`` as ``a + b + c``)."""
    if isinstance(e, sp.Add | sp.Mul):
        args, stack = [], list(e.args)
        while stack:
            x = stack.pop()
            if type(x) is type(e):
                stack.extend(x.args)
            else:
                args.append(_flat(x))
        return f"{type(e).__name__}({', '.join(sorted(args))})"
    if isinstance(e, sp.Basic) and e.args:
        return f"{type(e).__name__}({', '.join(_flat(x) for x in e.args)})"
    return str(e)


def same_text(a, b) -> bool:
    """Whether two sides are the same entries as written, up to the grouping and order of
    sums and products (:func:`_flat`)."""
    return [_flat(sp.sympify(x)) for x in entries_of(a)] == \
        [_flat(sp.sympify(x)) for x in entries_of(b)]


def derived_sides(r, model: dict, lhs, rhs) -> tuple:
    """The sides of ``r`` computed from the model without sympy's automatic evaluation
    (products, sums and determinants of the explicit matrices left as written; ``X^-1 = Y``
    as ``X Y = 1``, which for square matrices says the same), so that the checker, not
    sympy, does the arithmetic; ``(lhs, rhs)`` unchanged where that fails
    or the sides are still the same expression (a definition of the model: the checker
    rejects it as a verification)."""
    def side(x):
        if isinstance(x, Det | sp.Determinant):   # every entry in place, a zero one too
            return laplace_determinant(explicit(x.args[0], model))
        if isinstance(x, sp.Inverse) and x is r.lhs:  # X^-1 = Y: shown as X Y = 1
            with sp.evaluate(False):
                return explicit(x.arg, model) * explicit(r.rhs, model)
        if isinstance(x, sp.MatMul):  # each factor explicit, their product unevaluated
            mats = [explicit(a, model) for a in x.args]
            with sp.evaluate(False):
                out = mats[0]
                for m in mats[1:]:
                    out = out * m
            return out
        with sp.evaluate(False):
            return explicit(x, model)
    EXPLICIT_CACHE.clear()
    try:
        new = side(r.lhs), (sp.eye(shape_of(r.lhs)[0]) if isinstance(r.lhs, sp.Inverse)
                            else side(r.rhs))
    except (IndexError, TypeError, ValueError, AttributeError):
        new = None
    EXPLICIT_CACHE.clear()
    if new is None or same_text(*new) or shape_of(new[0]) != shape_of(lhs):
        return lhs, rhs
    if any(not p.exp.is_Integer for x in new for e in entries_of(x)
           for p in sp.sympify(e).atoms(sp.Pow)):  # x**(1*1): outside the grammar
        return lhs, rhs
    if isinstance(new[0], sp.MatrixBase) != isinstance(lhs, sp.MatrixBase):
        return lhs, rhs
    return new


def laplace_determinant(m: sp.MatrixBase):
    """The determinant of the explicit square matrix ``m`` by Laplace's expansion along the
    first row, left unevaluated: every entry appears, a zero one too, so that a checker,
    not sympy's triangular shortcut (a product of the diagonal), does the arithmetic
    (``det(U) = 1`` of Eq. (3.30) is then a polynomial identity in the entries of
    ``A - B``). ``m`` is at most 6 x 6 (720 products).

    Raises:
        ValueError: ``m`` is not square or larger than 6 x 6.
    """
    n = m.rows
    if m.cols != n or not 1 <= n <= 6:
        raise ValueError(f"m: expected a square matrix of at most 6 x 6, got {m.shape}")
    if n == 1:
        return m[0, 0]
    with sp.evaluate(False):
        terms = []
        for j in range(n):
            minor = laplace_determinant(m.minor_submatrix(0, j))
            term = sp.Mul(m[0, j], minor)
            terms.append(term if j % 2 == 0 else sp.Mul(sp.Integer(-1), term))
        return sp.Add(*terms)


def identical_by_definition(r: Rel, model: dict) -> bool:
    """Whether ``r``'s two sides are the same expression once the model (the book's
    definitions) is substituted, even computed without sympy's evaluation
    (:func:`derived_sides`): a definition, or an identity by definition, never a
    verification (nothing is derived)."""
    lhs, rhs = explicit(r.lhs, model), explicit(r.rhs, model)
    if shape_of(lhs) != shape_of(rhs) or not same_text(lhs, rhs):
        return False
    return same_text(*derived_sides(r, model, lhs, rhs))


def shape_of(x) -> tuple[int, int]:
    """Shape of a matrix, matrix expression or scalar (a scalar is 1 x 1).

    Raises:
        UnknownShape: ``x`` is matrix-valued to sympy but has no known shape (a sympy
            ``Derivative`` of a matrix symbol, say): never read as 1 x 1.
    """
    if isinstance(x, sp.MatrixBase | sp.MatrixExpr):
        return tuple(int(n) for n in x.shape)
    if isinstance(getattr(x, "kind", None), MatrixKind):
        raise UnknownShape(f"no shape rule for the node {type(x).__name__}: {x}")
    return (1, 1)


def entries_of(x) -> list:
    """The entries of ``x`` in row-major order: a matrix's entries, or ``[x]`` for a scalar."""
    return list(x) if isinstance(x, sp.MatrixBase) else [x]


def expanded_text(x) -> str:
    """``x`` as text, its terms in sympy's own deterministic order (for the full reports)."""
    # the terms in sympy's own (deterministic) order: sorting them for print took more time
    # than deciding; these expanded strings appear in the full reports only
    return sp.sstr(x, order="none")


def rel_str(rels: list[Rel] | None) -> str | None:
    """The relations ``rels`` as ``lhs = rhs`` texts joined by ``; ``; None for none."""
    if not rels:
        return None
    return "; ".join(f"{expanded_text(r.lhs)} = {expanded_text(r.rhs)}" for r in rels)


def seed_of(eq_id: str) -> int:
    """The seed of the random points drawn for equation ``eq_id`` (its CRC-32): the same id
    draws the same points in every run and process."""
    return zlib.crc32(eq_id.encode())
