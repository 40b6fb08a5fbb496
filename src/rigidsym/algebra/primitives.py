"""Symbolic primitives of rigid-body mechanics: the book's operators and chapter-2 facts.

Everything here builds explicit ``sympy.Matrix`` objects; nothing decides truth (that is
:mod:`rigidsym.zero.decide`). Shapes follow ``NOTATION.md``: vectors are 3 x 1 columns.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.algebra.operators import Cpm, Vect, is_symbolic

__all__ = [
    "as_vector",
    "cpm",
    "cpm_explicit",
    "vect",
    "vect_explicit",
    "trace",
    "eye3",
    "zeros3",
    "rotation_from_natural_invariants",
    "linear_invariants",
    "euler_rodrigues_parameters",
    "rotation_from_euler_rodrigues",
    "rotation_from_quaternion",
    "block",
]


def as_vector(v, name: str = "v") -> sp.Matrix:
    """Return ``v`` as an explicit 3 x 1 sympy column.

    Args:
        v: a sequence of 3 sympy expressions or a 3 x 1 / 1 x 3 matrix.
        name: the argument's name, used in the error message.

    Returns:
        3 x 1 ``sympy.Matrix``.

    Raises:
        ValueError: if ``v`` does not hold exactly three entries.
    """
    m = sp.Matrix(v)
    if m.shape not in ((3, 1), (1, 3)):
        raise ValueError(f"{name}: expected a 3-vector, got shape {m.shape}")
    return m.reshape(3, 1)


def cpm(v) -> sp.Matrix | Cpm:
    """Cross-product matrix of a 3-vector: ``cpm(v) @ x == v x x`` for every x.

    Book: Sec. 2.3, Eq. (2.38). Skew-symmetric, rank 2 for v != 0.

    Args:
        v: 3-vector (any sympy entries).

    Returns:
        3 x 3 skew-symmetric ``sympy.Matrix``; for a book symbol (a matrix expression of
        ``MatrixSymbol``), the lazy :class:`~rigidsym.algebra.operators.Cpm`, which prints
        ``CPM(v)`` and becomes that matrix once the symbol has its value.

    Example:
        >>> import sympy as sp
        >>> v, x = sp.Matrix([1, 2, 3]), sp.Matrix([4, 5, 6])
        >>> cpm(v) * x == v.cross(x)
        True
    """
    if is_symbolic(v):
        if tuple(v.shape) != (3, 1):
            raise ValueError(f"v: expected a 3-vector, got shape {tuple(v.shape)}")
        return Cpm(v)
    return cpm_explicit(as_vector(v))


def cpm_explicit(v) -> sp.Matrix:
    """The cross-product matrix of an explicit 3-vector, always a plain ``sympy.Matrix``
    (never the lazy ``Cpm``): ``[[0, -v3, v2], [v3, 0, -v1], [-v2, v1, 0]]``.

    Book: Sec. 2.3, Eq. (2.38). :func:`cpm` is the book's operator (lazy on a book
    symbol) and returns this for explicit entries; the explicit formulas of rigid motions
    (:mod:`rigidsym.algebra.rigid_motions`) call this one, their operands being explicit.

    Args:
        v: 3 entries, indexable ``v[0]``, ``v[1]``, ``v[2]`` (a 3 x 1 ``sympy.Matrix``).

    Returns:
        3 x 3 skew-symmetric ``sympy.Matrix``.
    """
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def vect(A) -> sp.Matrix | Vect:
    """Axial vector of a 3 x 3 matrix: ``vect(A) = 1/2 [a32 - a23, a13 - a31, a21 - a12]``.

    Book: Sec. 2.3.3. ``vect(cpm(v)) == v``.

    Args:
        A: a 3 x 3 matrix (any sympy entries), or a book matrix symbol.

    Returns:
        3 x 1 ``sympy.Matrix``; for a book symbol, the lazy
        :class:`~rigidsym.algebra.operators.Vect` (prints ``vect(A)``).

    Raises:
        ValueError: if ``A`` is not 3 x 3.
    """
    if is_symbolic(A):
        if tuple(A.shape) != (3, 3):
            raise ValueError(f"A: expected a 3 x 3 matrix, got shape {tuple(A.shape)}")
        return Vect(A)
    A = sp.Matrix(A)
    if A.shape != (3, 3):
        raise ValueError(f"A: expected a 3 x 3 matrix, got shape {A.shape}")
    return vect_explicit(A)


def vect_explicit(A) -> sp.Matrix:
    """The axial vector of an explicit 3 x 3 matrix, always a plain ``sympy.Matrix``
    (never the lazy ``Vect``): ``1/2 [a32 - a23, a13 - a31, a21 - a12]``.

    Book: Sec. 2.3.3. :func:`vect` is the book's operator (lazy on a book symbol, its
    shape checked) and returns this for explicit entries; the explicit formulas of rigid
    motions (:mod:`rigidsym.algebra.rigid_motions`) call this one.

    Args:
        A: an explicit 3 x 3 matrix (indexable ``A[i, j]``).

    Returns:
        3 x 1 ``sympy.Matrix``.
    """
    half = sp.Rational(1, 2)
    return sp.Matrix([half * (A[2, 1] - A[1, 2]), half * (A[0, 2] - A[2, 0]),
                      half * (A[1, 0] - A[0, 1])])


def trace(A) -> sp.Expr:
    """Trace of a square matrix. Book: Sec. 2.3 (tr).

    Args:
        A: a square matrix (explicit, or anything ``sympy.Matrix`` accepts), or a book
            matrix symbol.

    Returns:
        The sum of the diagonal; for a book symbol, the lazy ``sympy.Trace`` (prints
        ``tr(A)``, explicit once the symbol has its value).

    Raises:
        ValueError: if ``A`` is not square.
    """
    if is_symbolic(A):
        if A.shape[0] != A.shape[1]:
            raise ValueError(f"A: expected a square matrix, got shape {tuple(A.shape)}")
        return sp.Trace(A)
    A = sp.Matrix(A)
    if A.rows != A.cols:
        raise ValueError(f"A: expected a square matrix, got shape {A.shape}")
    return A.trace()


def eye3() -> sp.Matrix:
    """The 3 x 3 identity, the book's ``1``.

    Returns:
        ``sympy.eye(3)``, a new mutable matrix.
    """
    return sp.eye(3)


def zeros3() -> sp.Matrix:
    """The 3 x 3 zero matrix, the book's ``O``."""
    return sp.zeros(3, 3)


def rotation_from_natural_invariants(e, phi) -> sp.Matrix:
    """Rotation matrix from its natural invariants.

    ``Q = e e^T + cos(phi) (1 - e e^T) + sin(phi) E``, ``E = cpm(e)``, ``||e|| = 1``.

    Book: Sec. 2.3, Eq. (2.49).

    Args:
        e: unit 3-vector along the axis (the caller guarantees ``e.e = 1``; the zero
            test of :mod:`rigidsym.zero.decide` imposes it exactly).
        phi: angle in radians (a sympy expression).

    Returns:
        3 x 3 proper orthogonal matrix (when ``e.e = 1``).
    """
    e = as_vector(e, "e")
    eeT = e * e.T
    return eeT + sp.cos(phi) * (sp.eye(3) - eeT) + sp.sin(phi) * cpm(e)


def linear_invariants(e, phi) -> tuple[sp.Matrix, sp.Expr]:
    """Linear invariants ``u = sin(phi) e``, ``u0 = cos(phi)``. Book: Sec. 2.3; Eq. (3.95b).

    Args:
        e: unit 3-vector along the axis.
        phi: angle [rad].

    Returns:
        The pair ``(u, u0)``, a 3 x 1 ``sympy.Matrix`` and a scalar expression.

    Raises:
        ValueError: ``e`` is not a 3-vector.
    """
    e = as_vector(e, "e")
    return sp.sin(phi) * e, sp.cos(phi)


def euler_rodrigues_parameters(e, phi) -> tuple[sp.Matrix, sp.Expr]:
    """Euler-Rodrigues parameters ``r = sin(phi/2) e``, ``r0 = cos(phi/2)``.

    Book: Sec. 2.3; Eq. (3.95b).

    Args:
        e: unit 3-vector along the axis.
        phi: angle [rad].

    Returns:
        The pair ``(r, r0)``, a 3 x 1 ``sympy.Matrix`` and a scalar expression.

    Raises:
        ValueError: ``e`` is not a 3-vector.
    """
    e = as_vector(e, "e")
    return sp.sin(phi / 2) * e, sp.cos(phi / 2)


def rotation_from_euler_rodrigues(r, r0) -> sp.Matrix:
    """``Q = (r0^2 - r.r) 1 + 2 r r^T + 2 r0 cpm(r)``, valid when ``r.r + r0^2 = 1``.

    Book: Sec. 2.3 (Euler-Rodrigues form of the rotation).

    Args:
        r: the vector part, 3 x 1.
        r0: the scalar part.

    Returns:
        3 x 3 ``sympy.Matrix``, proper orthogonal when ``r.r + r0^2 = 1``.

    Raises:
        ValueError: ``r`` is not a 3-vector.
    """
    r = as_vector(r, "r")
    return (r0**2 - (r.T * r)[0]) * sp.eye(3) + 2 * r * r.T + 2 * r0 * cpm(r)


def rotation_from_quaternion(q) -> sp.Matrix:
    """Proper orthogonal matrix from an *unnormalised* quaternion ``q = [q1, q2, q3, q0]``.

    ``Q = ((q0^2 - v.v) 1 + 2 v v^T + 2 q0 cpm(v)) / (v.v + q0^2)`` with ``v = [q1, q2, q3]``.
    Rational in ``q`` and exactly orthogonal for every ``q != 0``: this is the rational
    parametrisation of SO(3) that lets the zero test honour ``Q^T Q = 1`` by cancellation.

    Args:
        q: four entries ``[q1, q2, q3, q0]``, not all zero.

    Returns:
        3 x 3 ``sympy.Matrix``, rational in ``q``.

    Raises:
        ValueError: ``q`` does not hold four entries.
    """
    q = list(sp.Matrix(q))
    if len(q) != 4:
        raise ValueError(f"q: expected 4 entries, got {len(q)}")
    v = sp.Matrix(q[:3])
    q0 = q[3]
    n2 = (v.T * v)[0] + q0**2
    return ((q0**2 - (v.T * v)[0]) * sp.eye(3) + 2 * v * v.T + 2 * q0 * cpm(v)) / n2


def block(rows) -> sp.Matrix:
    """Explicit block matrix from a nested list of matrices/scalars (scalars become 1 x 1).

    Used for the book's stacked arrays (``[e; phi]``, ``[[1, O], [A - B, 1]]``).

    Args:
        rows: a list of rows, each a list of explicit matrices or scalars whose shapes fit.

    Returns:
        The explicit ``sympy.Matrix``.

    Raises:
        ValueError: the blocks' shapes do not fit together (sympy's message).
    """
    def _m(x):
        return x if isinstance(x, sp.MatrixBase) else sp.Matrix([[x]])

    return sp.Matrix(sp.BlockMatrix([[_m(x) for x in row] for row in rows]).as_explicit())
