"""Matrix algebra and the chapter's operators on mpmath values (the second semantics):
a value is an mpmath number (a scalar), an :class:`mpmath.matrix` (a vector is n x 1),
or an identity or zero whose size its neighbours give (:class:`Eye`, :class:`Zero`).
Shapes are types: a sum or product whose shapes do not fit raises :class:`NotCovered`."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar

import mpmath as mp

__all__ = ["NotCovered", "Eye", "Zero", "shape", "add", "neg", "mul", "cross", "dot",
           "transpose", "inverse", "power", "hat", "vee", "trace", "det", "vect", "norm",
           "expm", "rodrigues", "logm", "adjoint", "small_adjoint", "spatial_cross", "sized",
           "scalar", "assemble", "TRANSLATION_FIRST", "tangent_order", "JPL_PRODUCT",
           "quaternion_convention", "quaternion_product", "quaternion_conjugate",
           "quaternion_inverse", "SCALAR_LAST", "quaternion_storage"]

#: the quaternion product of the check running now: ``False`` Hamilton's (scalar first,
#: ij = k; the default), ``True`` JPL's (scalar last, ij = -k)
JPL_PRODUCT: ContextVar[bool] = ContextVar("jpl_product", default=False)


@contextmanager
def quaternion_convention(jpl: bool) -> Iterator[None]:
    """Within the block ``p \\otimes q`` and ``q^*`` of 4-vectors are JPL's (``jpl``) or
    Hamilton's."""
    token = JPL_PRODUCT.set(bool(jpl))
    try:
        yield
    finally:
        JPL_PRODUCT.reset(token)


#: the scalar's place where the reader's writing fixes it: ``True`` last, ``False`` first,
#: ``None`` the convention's own (JPL's last, Hamilton's first): the storage order of a
#: 4-vector and the rule of its units are two choices (Szeliski (2022) stores (x, y, z, w)
#: and multiplies by Hamilton's rule)
SCALAR_LAST: ContextVar[bool | None] = ContextVar("scalar_last", default=None)


@contextmanager
def quaternion_storage(last: bool | None) -> Iterator[None]:
    """Within the block a 4-vector's scalar is its last entry (``last``), its first
    (``False``), or where the convention puts it (``None``)."""
    token = SCALAR_LAST.set(last)
    try:
        yield
    finally:
        SCALAR_LAST.reset(token)


def _last() -> bool:
    last = SCALAR_LAST.get()
    return JPL_PRODUCT.get() if last is None else last


def _quaternion(q, what: str):
    """``(w, x, y, z)`` of a 4-vector in the convention now (scalar first or last)."""
    q = scalar(q)
    if not is_matrix(q) or (q.rows, q.cols) != (4, 1):
        raise NotCovered(f"{what} of a value that is no 4-vector")
    return (q[3], q[0], q[1], q[2]) if _last() else (q[0], q[1], q[2], q[3])


def _as_quaternion(w, x, y, z):
    return mp.matrix([x, y, z, w]) if _last() else mp.matrix([w, x, y, z])


def quaternion_product(p, q):
    """``p ⊗ q`` from the units' table: Hamilton's ``ij = k, jk = i, ki = j`` (Hamilton 1843;
    Solà (2017) (8)), JPL's the reverse, ``ij = -k`` (Trawny & Roumeliotis (2005) (2))."""
    a1, b1, c1, d1 = _quaternion(p, "a quaternion product")
    a2, b2, c2, d2 = _quaternion(q, "a quaternion product")
    s = -1 if JPL_PRODUCT.get() else 1  # the sign of every product of two distinct units
    w = a1 * a2 - b1 * b2 - c1 * c2 - d1 * d2
    x = a1 * b2 + b1 * a2 + s * (c1 * d2 - d1 * c2)
    y = a1 * c2 + c1 * a2 + s * (d1 * b2 - b1 * d2)
    z = a1 * d2 + d1 * a2 + s * (b1 * c2 - c1 * b2)
    return _as_quaternion(w, x, y, z)


def quaternion_conjugate(q):
    """``q^*``: the quaternion with its imaginary units negated."""
    w, x, y, z = _quaternion(q, "a quaternion conjugate")
    return _as_quaternion(w, -x, -y, -z)

def quaternion_inverse(q):
    """``q^{-1}``: the quaternion whose product with ``q`` is 1, ``(w, -x, -y, -z) / (w^2 +
    x^2 + y^2 + z^2)`` (the conjugate over the norm squared)."""
    w, x, y, z = _quaternion(q, "a quaternion inverse")
    n2 = w * w + x * x + y * y + z * z
    return _as_quaternion(w / n2, -x / n2, -y / n2, -z / n2)

#: the twist order of the check running now: ``False`` ``[ω; v]`` (angular first, the
#: default), ``True`` ``[v; ω]`` (translation first: Barfoot, Solà, manif)
TRANSLATION_FIRST: ContextVar[bool] = ContextVar("translation_first", default=False)


@contextmanager
def tangent_order(translation_first: bool) -> Iterator[None]:
    """Within the block the hat of a 6-vector, its vee, Ad and ad take the twist order
    ``[v; ω]`` (``translation_first``) or ``[ω; v]``."""
    token = TRANSLATION_FIRST.set(bool(translation_first))
    try:
        yield
    finally:
        TRANSLATION_FIRST.reset(token)


def _swap6(v):
    """A 6-vector with its halves swapped ([ω; v] <-> [v; ω])."""
    return mp.matrix([v[3], v[4], v[5], v[0], v[1], v[2]])


def _swap_blocks(m):
    """P M P of a 6 x 6, P the swap of the 3-blocks."""
    out = mp.zeros(6, 6)
    for i in range(6):
        for j in range(6):
            out[(i + 3) % 6, (j + 3) % 6] = m[i, j]
    return out


class NotCovered(ValueError):
    """A construct the second semantics does not evaluate (named), or shapes that do not
    fit: the check is refused, never decided by the symbolic path alone."""


class Eye:
    """``c`` times an identity whose size the other operand gives (``\\mathbf{1}``, a plain
    ``I``, ``I\\theta``)."""

    def __init__(self, n: int | None = None, c=1):
        self.n, self.c = n, c


class Zero:
    """A zero whose shape the other operand gives (``\\mathbf{0}``); ``row``: a transposed
    one, ``\\mathbf{0}^T``, a row, so a block row of it alone is one row high."""

    def __init__(self, row: bool = False):
        self.row = row


def is_matrix(v) -> bool:
    return isinstance(v, mp.matrix)


def shape(v):
    """``(rows, cols)`` of a matrix, ``()`` of a scalar, ``None`` of an unsized one."""
    if is_matrix(v):
        return (v.rows, v.cols)
    if isinstance(v, Eye):
        return (v.n, v.n) if v.n else None
    if isinstance(v, Zero):
        return None
    return ()


def sized(v, like):
    """``v`` made an explicit matrix of the shape of ``like`` (an unsized identity or zero),
    a 1 x 1 matrix made a scalar."""
    if isinstance(v, Eye):
        n = v.n or (like.rows if is_matrix(like) else None)
        if n is None:
            return v if isinstance(like, Eye | Zero) or not v.n else v.c * mp.eye(v.n)
        return v.c * mp.eye(n)
    if isinstance(v, Zero):
        return mp.zeros(like.rows, like.cols) if is_matrix(like) else mp.mpf(0)
    return scalar(v)


def scalar(v):
    """A 1 x 1 matrix as its entry; anything else as it is."""
    if is_matrix(v) and v.rows == 1 and v.cols == 1:
        return v[0, 0]
    return v


def _pair(a, b):
    a, b = sized(a, b), sized(b, a)
    return sized(a, b), sized(b, a)


def add(a, b):
    """``a + b``; a scalar 0 is the zero of the other side's shape."""
    if isinstance(a, Zero):
        return b
    if isinstance(b, Zero):
        return a
    if isinstance(a, Eye) and isinstance(b, Eye) and not a.n and not b.n:
        return Eye(None, a.c + b.c)
    a, b = _pair(a, b)
    if isinstance(a, Eye) or isinstance(b, Eye):
        raise NotCovered("a sum of an identity and a scalar")
    if is_matrix(a) != is_matrix(b):
        s, m = (a, b) if is_matrix(b) else (b, a)
        if s == 0:
            return m
        raise NotCovered(f"a sum of a scalar and a {m.rows}x{m.cols} matrix")
    if is_matrix(a) and (a.rows, a.cols) != (b.rows, b.cols):
        raise NotCovered(f"a sum of a {a.rows}x{a.cols} and a {b.rows}x{b.cols} matrix")
    return a + b


def neg(a):
    if isinstance(a, Zero):
        return a
    if isinstance(a, Eye):
        return Eye(a.n, -a.c)
    return -a


def mul(a, b):
    """The product of a juxtaposition: the matrix product where it fits, a scalar (or a
    1 x 1 matrix) times anything; an identity or zero takes the other's size."""
    if isinstance(a, Zero) or isinstance(b, Zero):
        return Zero()
    if isinstance(a, Eye) and isinstance(b, Eye) and not a.n and not b.n:
        return Eye(None, a.c * b.c)
    if isinstance(a, Eye) and not a.n:
        return Eye(None, a.c * b) if not is_matrix(b) and not isinstance(b, Eye) else \
            mul(a.c, b)
    if isinstance(b, Eye) and not b.n:
        return Eye(None, b.c * a) if not is_matrix(a) and not isinstance(a, Eye) else \
            mul(a, b.c)
    a, b = sized(a, b), sized(b, a)
    if not is_matrix(a) or not is_matrix(b):
        return a * b
    if a.cols == b.rows:
        return scalar(a * b)
    raise NotCovered(f"a product of a {a.rows}x{a.cols} and a {b.rows}x{b.cols} matrix")


def _vec3(v, what: str):
    v = scalar(v)
    if not is_matrix(v) or v.cols != 1 or v.rows != 3:
        raise NotCovered(f"{what} of a value that is no 3-vector")
    return v


def cross(a, b):
    a, b = _vec3(a, "a cross product"), _vec3(b, "a cross product")
    return mp.matrix([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                      a[0] * b[1] - a[1] * b[0]])


def dot(a, b):
    """``a \\cdot b``: the scalar product of two vectors, a product otherwise."""
    if is_matrix(a) and is_matrix(b) and a.cols == b.cols == 1:
        if a.rows != b.rows:
            raise NotCovered(f"a scalar product of a {a.rows}- and a {b.rows}-vector")
        return mp.fsum(a[i] * b[i] for i in range(a.rows))
    if is_matrix(a) and is_matrix(b):
        raise NotCovered("a dot between matrices")
    return mul(a, b)


def transpose(a):
    if isinstance(a, Zero):
        return Zero(not a.row)
    if is_matrix(a):
        return scalar(a.T) if a.rows == a.cols == 1 else a.T
    return a


def inverse(a):
    if isinstance(a, Eye):
        if a.c == 0:
            raise NotCovered("the inverse of 0")
        return Eye(a.n, 1 / a.c)
    if is_matrix(a):
        if a.rows != a.cols:
            raise NotCovered(f"the inverse of a {a.rows}x{a.cols} matrix")
        return mp.inverse(a)
    if a == 0:
        raise NotCovered("the inverse of 0")
    return 1 / a


def power(a, n: int):
    if not is_matrix(a):
        if isinstance(a, Zero):
            return a
        if isinstance(a, Eye):
            return Eye(a.n, a.c ** n)
        return a ** n
    if a.rows != a.cols:
        raise NotCovered(f"a power of a {a.rows}x{a.cols} matrix")
    if n < 0:
        return power(inverse(a), -n)
    out = mp.eye(a.rows)
    for _ in range(n):
        out = out * a
    return out


def hat(v):
    """The cross-product matrix of a 3-vector; the 4 x 4 se(3) matrix of a 6-vector
    ``[ω; v]`` (``[v; ω]`` under :func:`tangent_order`)."""
    v = scalar(v)
    if is_matrix(v) and v.cols == 1 and v.rows == 3:
        return mp.matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    if is_matrix(v) and v.cols == 1 and v.rows == 6:
        if TRANSLATION_FIRST.get():
            v = _swap6(v)
        W = hat(mp.matrix([v[0], v[1], v[2]]))
        out = mp.zeros(4, 4)
        for i in range(3):
            for j in range(3):
                out[i, j] = W[i, j]
            out[i, 3] = v[i + 3]
        return out
    raise NotCovered("a hat (cross-product matrix) of a value that is no 3- or 6-vector")


def vee(A):
    """The inverse of :func:`hat` (of a 3 x 3 or a 4 x 4 matrix)."""
    if is_matrix(A) and A.rows == A.cols == 3:
        return mp.matrix([A[2, 1], A[0, 2], A[1, 0]])
    if is_matrix(A) and A.rows == A.cols == 4:
        out = mp.matrix([A[2, 1], A[0, 2], A[1, 0], A[0, 3], A[1, 3], A[2, 3]])
        return _swap6(out) if TRANSLATION_FIRST.get() else out
    raise NotCovered("a vee of a value that is no 3x3 or 4x4 matrix")


def _square(A, what: str):
    if not is_matrix(A) or A.rows != A.cols:
        raise NotCovered(f"{what} of a value that is no square matrix")
    return A


def trace(A):
    A = _square(A, "a trace")
    return mp.fsum(A[i, i] for i in range(A.rows))


def det(A):
    return mp.det(_square(A, "a determinant"))


def vect(A):
    """The book's vect(A) (Angeles (2.40)): the axial vector of A's skew part."""
    A = _square(A, "vect")
    if A.rows != 3:
        raise NotCovered("vect of a matrix that is no 3x3")
    return mp.matrix([A[2, 1] - A[1, 2], A[0, 2] - A[2, 0], A[1, 0] - A[0, 1]]) / 2


def norm(a):
    """The Euclidean norm of a vector, the absolute value of a scalar."""
    if is_matrix(a):
        if a.cols != 1:
            raise NotCovered("a norm of a matrix")
        return mp.sqrt(mp.fsum(abs(a[i]) ** 2 for i in range(a.rows)))
    return abs(a)


def expm(a):
    """The exponential; of a 3 x 3 skew matrix by Rodrigues' closed form (mpmath's Padé
    ``expm`` is some 20 times slower, and this is the check's hot spot)."""
    if is_matrix(a):
        _square(a, "an exponential")
        if a.rows == 3 and max(abs(a[i, j] + a[j, i]) for i in range(3) for j in range(3)) \
                == 0:
            return rodrigues(mp.matrix([a[2, 1], a[0, 2], a[1, 0]]))
        return mp.expm(a)
    return mp.exp(a)


def rodrigues(w):
    """``e^{[w]}`` of a 3-vector w: ``1 + sin|w|/|w| [w] + (1 - cos|w|)/|w|^2 [w]^2``."""
    W = hat(w)
    th = norm(w)
    if th == 0:
        return mp.eye(3)
    return mp.eye(3) + (mp.sin(th) / th) * W + ((1 - mp.cos(th)) / th ** 2) * (W * W)


def logm(a):
    if is_matrix(a):
        out = mp.logm(_square(a, "a logarithm"))
        return out.apply(lambda z: z.real if abs(z.imag) < mp.mpf(10) ** (-mp.mp.dps + 5)
                         else z)
    return mp.log(a)


def adjoint(T):
    """Ad of a 4 x 4 homogeneous transform ``[R p; 0 1]`` on twists ``[ω; v]``:
    ``[R 0; [p]R R]`` (Modern Robotics (3.83)); on ``[v; ω]`` (:func:`tangent_order`)
    ``[R [p]R; 0 R]``. Of a 3 x 3 rotation, the rotation itself (SO(3): ``R [x] R^T = [R x]``)."""
    if is_matrix(T) and (T.rows, T.cols) == (3, 3):
        return T
    if not is_matrix(T) or (T.rows, T.cols) != (4, 4):
        raise NotCovered("Ad of a value that is no 4x4 transform")
    out = _adjoint_angular_first(T)
    return _swap_blocks(out) if TRANSLATION_FIRST.get() else out


def _adjoint_angular_first(T):
    R = mp.matrix([[T[i, j] for j in range(3)] for i in range(3)])
    pR = hat(mp.matrix([T[0, 3], T[1, 3], T[2, 3]])) * R
    out = mp.zeros(6, 6)
    for i in range(3):
        for j in range(3):
            out[i, j] = out[i + 3, j + 3] = R[i, j]
            out[i + 3, j] = pR[i, j]
    return out


def small_adjoint(V):
    """ad of a twist ``[ω; v]``: ``[[ω] 0; [v] [ω]]`` (Modern Robotics (8.38)); of ``[v; ω]``
    (:func:`tangent_order`) ``[[ω] [v]; 0 [ω]]``."""
    V = scalar(V)
    if not is_matrix(V) or (V.rows, V.cols) != (6, 1):
        raise NotCovered("ad of a value that is no twist")
    if TRANSLATION_FIRST.get():
        return _swap_blocks(_small_adjoint_angular_first(_swap6(V)))
    return _small_adjoint_angular_first(V)


def _small_adjoint_angular_first(V):
    W, U = hat(mp.matrix([V[0], V[1], V[2]])), hat(mp.matrix([V[3], V[4], V[5]]))
    out = mp.zeros(6, 6)
    for i in range(3):
        for j in range(3):
            out[i, j] = out[i + 3, j + 3] = W[i, j]
            out[i + 3, j] = U[i, j]
    return out


def spatial_cross(v, dual: bool = False):
    """Featherstone's ``v\\times`` of a spatial motion vector ``[ω; v]``: ``[[ω] 0; [v]
    [ω]]`` (RBDA (2.31)); ``v\\times^*`` is ``-(v\\times)^T`` (2.32)."""
    V = scalar(v)
    if not is_matrix(V) or (V.rows, V.cols) != (6, 1):
        raise NotCovered("a spatial cross product of a value that is no 6-vector")
    M = _small_adjoint_angular_first(V)  # Featherstone's order, whatever the declaration
    return -M.T if dual else M


def assemble(rows, where: str):
    """A bmatrix of scalars, or of blocks (a scalar 0 a zero block of its row's height and
    column's width)."""
    if all(not is_matrix(scalar(e)) and not isinstance(e, Eye | Zero)
           for r in rows for e in r):
        if len({len(r) for r in rows}) != 1:
            raise NotCovered(f"rows of different lengths in {where!r}")
        return mp.matrix([[scalar(e) for e in r] for r in rows])
    ncol = len(rows[0])
    if any(len(r) != ncol for r in rows):
        raise NotCovered(f"block rows of different lengths in {where!r}")
    heights = [next((shape(e)[0] for e in r if shape(e)), 1 if any(map(_one, r)) or any(
        isinstance(e, Zero) and e.row for e in r) or _zero_row(r) else None)
               for r in rows]  # [A; 0^T]
    widths = [next((shape(r[j])[1] for r in rows if shape(r[j])),
                   1 if any(_one(r[j]) for r in rows) else None) for j in range(ncol)]
    unsized = 3 if any(isinstance(e, Eye | Zero) for r in rows for e in r) else 1
    heights = [h if h is not None else unsized for h in heights]
    widths = [w if w is not None else unsized for w in widths]
    out = mp.zeros(sum(heights), sum(widths))
    r0 = 0
    for i, r in enumerate(rows):
        c0 = 0
        for j, e in enumerate(r):
            blk = _block(e, heights[i], widths[j], where)
            for a in range(heights[i]):
                for b in range(widths[j]):
                    out[r0 + a, c0 + b] = blk[a, b] if is_matrix(blk) else blk
            c0 += widths[j]
        r0 += heights[i]
    return out


def _zero_row(r) -> bool:
    r"""A row of zeros only, a bold ``\mathbf{0}`` beside a scalar ``0`` (Eade's
    ``[\omega_\times u; \mathbf{0} 0]``): the scalar gives the row its height, 1."""
    return all(isinstance(e, Zero) or (not is_matrix(e) and not isinstance(e, Eye) and e == 0)
               for e in r) and any(isinstance(e, Zero) for e in r) and \
        any(not isinstance(e, Zero) for e in r)


def _one(e) -> bool:
    r"""A nonzero scalar block: 1 x 1, its row's height and its column's width (a zero, an
    identity or a ``\mathbf{0}`` takes its size from the others)."""
    return not is_matrix(e) and not isinstance(e, Eye | Zero) and e != 0


def _block(e, h, w, where: str):
    if isinstance(e, Zero) or (not is_matrix(e) and not isinstance(e, Eye) and e == 0):
        return mp.zeros(h, w)
    if isinstance(e, Eye):
        if h != w:
            raise NotCovered(f"an identity block of {h}x{w} in {where!r}")
        return e.c * mp.eye(h)
    if is_matrix(e) and (e.rows, e.cols) == (h, w):
        return e
    if not is_matrix(e) and h == w == 1:
        return e
    raise NotCovered(f"blocks that do not fit in {where!r}")
