"""The vocabulary of rigid motions: twists and wrenches, so(3) and se(3), homogeneous
transforms, the adjoint maps, the exponential and the logarithm, as lazy operators on book
symbols and as the words declarations are written in (``hat``, ``vee``, ``transform``,
``transform_inverse``, ``Ad``, ``ad``, ``ad_dual``, ``expm``, ``logm``, ``diff``).

Sources: Lynch & Park, *Modern Robotics* (MR), ch. 3 (hat and vee (3.30), (3.85); the
transform (3.62) and its inverse (3.64); ``Ad`` (3.83)-(3.85); the exponentials (3.51)
and (3.88) with ``G(theta)``; ``ad`` (8.38)); Murray, Li & Sastry (MLS), ch. 2
((2.14), (2.36), (2.58)); Featherstone, *Rigid Body Dynamics Algorithms*, ch. 2 (the dual
``v x*``). Angeles writes a twist ``[omega; v]`` and a wrench ``[n; f]`` (angular first).

Every word that reads a 6-vector takes ``order``, one of :data:`ORDERS`: the angular part
first (``"angeles"``, the default, ``"modern-robotics"``, ``"featherstone"``) or the linear
part first (``"pinocchio"``, ``"ros"``, as ``kernels.swap_blocks`` knows them); the
order is never implicit in a word's name.

On book symbols (``MatrixSymbol``) the words stay lazy (:class:`LieOp`: they print as the
books write them and become explicit once the checker substitutes the model); on explicit
matrices they return explicit matrices, built on the explicit cross-product matrix and
axial vector of :mod:`rigidsym.algebra.primitives` (``cpm_explicit``, ``vect_explicit``).

The exponential and logarithm of *unconstrained* exponents (a rotation vector ``w`` of
so(3), exponential coordinates ``[w; v]`` of se(3)) take the forms in the norm ``theta =
sqrt(w^T w)`` (:func:`exp_of_vector`, :func:`norm3`): Solà, Deray & Atchuthan, "A micro Lie
theory for state estimation in robotics" (2018), App. B (SO(3)) and D (SE(3)), and Barfoot,
*State Estimation for Robotics* (2017), Sec. 7.1; they equal MR's (3.51), (3.88) with ``w =
theta omega``. As printed they are singular at ``w = 0``, a removable singularity the code
generator replaces by its series (:mod:`rigidsym.codegen.removable.singularities`); the zero
test reads ``theta`` through the polar parametrisation ``w = theta e``
(:mod:`rigidsym.checking.deciding.branches`).
"""

from __future__ import annotations

import sympy as sp
from sympy.printing.precedence import PRECEDENCE

from rigidsym.algebra.operators import Diff, explicit, is_symbolic
from rigidsym.algebra.primitives import cpm, cpm_explicit, vect, vect_explicit

__all__ = ["ORDERS", "LieOp", "Hat", "Vee", "Transform", "TransformInverse", "AdT", "AdV",
           "AdDual", "Expm", "Logm", "exp_explicit", "log_explicit", "log_se3_explicit",
           "exp_of_vector", "norm3", "is_unit", "split_angle",
           "hat", "vee", "transform", "transform_inverse", "Ad", "ad", "ad_dual", "expm",
           "logm", "diff"]

#: the twist and wrench orders by name: 0 the angular part first, 1 the linear part first
ORDERS = {"angeles": 0, "modern-robotics": 0, "featherstone": 0, "pinocchio": 1, "ros": 1}


# --------------------------------------------------------------------- explicit formulas
def _split(V, lin: int) -> tuple[sp.Matrix, sp.Matrix]:
    V = sp.Matrix(V)
    a, b = V[:3, :], V[3:, :]
    return (b, a) if lin else (a, b)


def _join(w, v, lin: int) -> sp.Matrix:
    return sp.Matrix.vstack(*((v, w) if lin else (w, v)))


def _transform_explicit(R, p) -> sp.Matrix:
    return sp.Matrix.vstack(sp.Matrix.hstack(sp.Matrix(R), sp.Matrix(p)),
                            sp.Matrix([[0, 0, 0, 1]]))


def _hat(x, lin: int) -> sp.Matrix:
    x = sp.Matrix(x)
    if x.shape == (3, 1):
        return cpm_explicit(x)
    w, v = _split(x, lin)
    return sp.Matrix.vstack(sp.Matrix.hstack(cpm_explicit(w), v), sp.zeros(1, 4))


def _vee(X, lin: int) -> sp.Matrix:
    X = sp.Matrix(X)
    if X.shape == (3, 3):
        return vect_explicit(X)
    return _join(vect_explicit(X[:3, :3]), X[:3, 3], lin)


def _transform_inverse(T) -> sp.Matrix:
    T = sp.Matrix(T)
    R, p = T[:3, :3], T[:3, 3]
    return _transform_explicit(R.T, -R.T * p)


def _blocks(a, b, c, d, lin: int) -> sp.Matrix:
    """``[[a, b], [c, d]]`` in the angular-first order, rewritten for ``lin``."""
    if lin:
        a, b, c, d = d, c, b, a
    return sp.Matrix.vstack(sp.Matrix.hstack(a, b), sp.Matrix.hstack(c, d))


def _Ad(T, lin: int) -> sp.Matrix:
    T = sp.Matrix(T)
    R, p = T[:3, :3], T[:3, 3]
    return _blocks(R, sp.zeros(3), cpm_explicit(p) * R, R, lin)


def _ad(V, lin: int) -> sp.Matrix:
    w, v = _split(V, lin)
    return _blocks(cpm_explicit(w), sp.zeros(3), cpm_explicit(v), cpm_explicit(w), lin)


def _ad_dual(V, lin: int) -> sp.Matrix:
    return -_ad(V, lin).T


# --------------------------------------------------------------------- lazy operators
class LieOp(sp.MatrixExpr):
    """A lazy operator of this vocabulary: ``args`` are its matrix operands, then the order
    flag (0 angular first, 1 linear first) where the operator reads a 6-vector."""

    label = ""  #: the name as printed (text)
    tex = ""  #: the name as printed (LaTeX)
    ordered = False  #: whether the last argument is the order flag
    operands = 1  #: how many matrix operands

    def __new__(cls, *args):  # sympified: a mutable Matrix argument is unhashable
        return sp.Basic.__new__(cls, *map(sp.sympify, args))

    @property
    def lin(self) -> int:
        return int(self.args[-1]) if self.ordered else 0

    @property
    def shape(self):
        return tuple(sp.Integer(n) for n in self.shape_of(
            [tuple(int(n) for n in a.shape) for a in self.args[:self.operands]]))

    @classmethod
    def shape_of(cls, shapes: list) -> tuple[int, int]:
        """The result's shape from the operands' (``ValueError`` when they do not fit)."""
        raise NotImplementedError

    def value(self, *mats) -> sp.Matrix:
        """The explicit value from explicit operands."""
        raise NotImplementedError

    def _entry(self, i, j, **kwargs):
        mats = [a.as_explicit() if isinstance(a, sp.MatrixExpr) else a
                for a in self.args[:self.operands]]
        return self.value(*mats)[i, j]

    def doit(self, **hints):
        ops = [explicit(a, **hints) for a in self.args[:self.operands]]
        if all(isinstance(a, sp.MatrixBase) for a in ops):
            return sp.ImmutableMatrix(self.value(*ops))
        return type(self)(*ops, *self.args[self.operands:])

    def _sympystr(self, printer):
        inner = ", ".join(printer._print(a) for a in self.args[:self.operands])
        return f"{self.label}({inner})"

    def _latex(self, printer):
        inner = ", ".join(printer._print(a) for a in self.args[:self.operands])
        return rf"{self.tex}\left({inner}\right)"


def _need(shapes, allowed, what):
    if tuple(shapes) not in allowed:
        raise ValueError(f"{what}: operands of shapes {shapes} do not fit")


class Hat(LieOp):
    """``[x]``: so(3) of a 3-vector (= CPM), se(3) (4 x 4) of a twist (MR (3.30), (3.85))."""
    label, tex, ordered = "hat", r"\mathrm{hat}", True

    @classmethod
    def shape_of(cls, shapes):
        _need(shapes, [((3, 1),), ((6, 1),)], "hat")
        return (3, 3) if shapes[0] == (3, 1) else (4, 4)

    def value(self, x):
        return _hat(x, self.lin)

    def _sympystr(self, printer):
        return f"[{printer._print(self.args[0])}]"

    def _latex(self, printer):
        return rf"\left[{printer._print(self.args[0])}\right]"


class Vee(LieOp):
    """``X^vee``: the 3-vector of so(3), the twist of se(3) (MR (3.30), (3.85))."""
    label, tex, ordered = "vee", r"\mathrm{vee}", True

    @classmethod
    def shape_of(cls, shapes):
        _need(shapes, [((3, 3),), ((4, 4),)], "vee")
        return (3, 1) if shapes[0] == (3, 3) else (6, 1)

    def value(self, X):
        return _vee(X, self.lin)


class Transform(LieOp):
    """``T = [[R, p], [0, 1]]`` (MR (3.62), Angeles (2.80))."""
    label, tex, operands = "T", r"\mathrm{T}", 2

    @classmethod
    def shape_of(cls, shapes):
        _need(shapes, [((3, 3), (3, 1))], "transform")
        return (4, 4)

    def value(self, R, p):
        return _transform_explicit(R, p)


class TransformInverse(LieOp):
    """``T^-1 = [[R^T, -R^T p], [0, 1]]`` (MR (3.64))."""
    label, tex = "Tinv", r"\mathrm{T}^{-1}"

    @classmethod
    def shape_of(cls, shapes):
        _need(shapes, [((4, 4),)], "transform_inverse")
        return (4, 4)

    def value(self, T):
        return _transform_inverse(T)

    def _sympystr(self, printer):
        return f"{printer.parenthesize(self.args[0], PRECEDENCE['Pow'], strict=True)}⁻¹"

    def _latex(self, printer):
        return f"{printer.parenthesize(self.args[0], PRECEDENCE['Pow'], strict=True)}^{{-1}}"


class AdT(LieOp):
    """``[Ad_T] = [[R, 0], [[p] R, R]]`` on twists ``[omega; v]`` (MR (3.83))."""
    label, tex, ordered = "Ad", r"\mathrm{Ad}", True

    @classmethod
    def shape_of(cls, shapes):
        _need(shapes, [((4, 4),)], "Ad")
        return (6, 6)

    def value(self, T):
        return _Ad(T, self.lin)


class AdV(LieOp):
    """``[ad_V] = [[[omega], 0], [[v], [omega]]]`` (MR (8.38)): ``[ad_V1] V2`` is the Lie
    bracket ``vee([V1] [V2] - [V2] [V1])``."""
    label, tex, ordered = "ad", r"\mathrm{ad}", True

    @classmethod
    def shape_of(cls, shapes):
        _need(shapes, [((6, 1),)], "ad")
        return (6, 6)

    def value(self, V):
        return _ad(V, self.lin)


class AdDual(LieOp):
    """``ad*_V = -[ad_V]^T`` (Featherstone's ``v x*``, acting on wrenches)."""
    label, tex, ordered = "ad*", r"\mathrm{ad}^{*}", True

    @classmethod
    def shape_of(cls, shapes):
        _need(shapes, [((6, 1),)], "ad_dual")
        return (6, 6)

    def value(self, V):
        return _ad_dual(V, self.lin)


class Expm(LieOp):
    """``exp(X)`` of ``X = theta [omega]`` in so(3) (Rodrigues, MR (3.51), Angeles (2.49))
    or ``X = theta [S]`` in se(3) (MR (3.88)); see :func:`exp_explicit`."""
    label, tex, ordered = "exp", r"\exp", True

    @classmethod
    def shape_of(cls, shapes):
        _need(shapes, [((3, 3),), ((4, 4),)], "expm")
        return shapes[0]

    def value(self, X):
        return exp_explicit(X, self.lin)

    def _entry(self, i, j, **kwargs):
        raise NotImplementedError("expm: its entries exist once the model is substituted")

    def _latex(self, printer):
        return rf"e^{{{printer._print(self.args[0])}}}"


class Logm(LieOp):
    """``log(R)`` of a rotation on the principal branch (MR (3.53)-(3.54)):
    ``theta / (2 sin theta) (R - R^T)`` with ``theta = acos((tr R - 1) / 2)`` in
    ``[0, pi]``; singular at ``theta = 0`` (``0/0``: the log is ``O``) and at ``theta = pi``
    (the axis is not unique). See :func:`log_explicit`; of a transform (4 x 4),
    :func:`log_se3_explicit`."""
    label, tex = "log", r"\log"

    @classmethod
    def shape_of(cls, shapes):
        _need(shapes, [((3, 3),), ((4, 4),)], "logm")
        return shapes[0]

    def value(self, R):
        return log_explicit(R) if sp.Matrix(R).shape == (3, 3) else log_se3_explicit(R)

    def _entry(self, i, j, **kwargs):
        raise NotImplementedError("logm: its entries exist once the model is substituted")


# --------------------------------------------------------------------- the exponential
def _angle_atoms(X) -> list:
    from rigidsym.algebra.symbols import constraint_of
    from rigidsym.core import kinds as _kinds

    atoms = [a for a in sp.Matrix(X).free_symbols | set(sp.Matrix(X).atoms(sp.Function))
             if (c := constraint_of(a)) is not None and _kinds.get(c.kind).half_angle]
    return sorted(atoms, key=sp.default_sort_key)


def split_angle(X) -> tuple:
    """``(theta, K)`` with ``X = theta K``, ``theta`` an angle atom and ``K`` free of it,
    or ``(1, X)`` when no angle factors out."""
    X = sp.Matrix(X)
    plain = sorted(X.free_symbols - set(_angle_atoms(X)), key=sp.default_sort_key)
    for a in _angle_atoms(X) + plain:  # an angle atom first; a kernel's plain symbol next
        K = (X / a).applyfunc(sp.cancel)
        if not K.has(a):
            return a, K
    return sp.Integer(1), X


def is_unit(w) -> bool:
    """Whether the 3-vector ``w`` is a unit vector *by construction*, exactly: the atoms of
    one :func:`~rigidsym.algebra.symbols.unit_vector` in order, up to a sign, or rational
    constants with ``w . w = 1``. No floating point, no simplification."""
    from rigidsym.algebra.symbols import constraint_of

    w = list(sp.Matrix(w))
    if all(e.is_Rational for e in w):
        return sum(e**2 for e in w) == 1
    for sign in (1, -1):
        atoms = [sign * e for e in w]
        cs = {constraint_of(a) for a in atoms}
        if len(cs) == 1 and (c := cs.pop()) is not None and c.kind == "unit" and \
                tuple(getattr(a, "name", None) or a.func.__name__ for a in atoms) == c.names:
            return True
    return False


def exp_explicit(X, lin: int = 0, theta=None, unit: bool = False) -> sp.Matrix:
    """The exponential of ``theta K`` with a unit axis, exactly.

    so(3): ``exp(theta [w]) = 1 + sin(theta) [w] + (1 - cos(theta)) [w]^2`` for
    ``|w| = 1`` (MR (3.51), Angeles (2.49)). se(3): ``exp(theta [S]) = [[exp(theta [w]),
    G(theta) v], [0, 1]]`` with ``G(theta) = 1 theta + (1 - cos theta) [w] + (theta -
    sin theta) [w]^2`` for ``|w| = 1``, and ``[[1, v theta], [0, 1]]`` for ``w = 0``
    (MR (3.88)-(3.89)).

    Args:
        X: 3 x 3 skew or 4 x 4 se(3) matrix, ``theta K`` (``theta`` an angle atom
            factored out when ``theta`` is ``None``).
        lin: the order flag (unused: se(3) matrices have one layout).
        theta: the angle, when ``X`` is the unit generator ``K`` itself.
        unit: the caller asserts ``|w| = 1`` (a kernel whose argument is validated unit
            at run time, ``Arg(..., "unit")``); never in a declaration's model.

    An axis not known to be unit (a free rotation vector ``w``, a kernel's unconstrained
    input) takes the closed forms in the norm ``theta = sqrt(w^T w)``
    (:func:`exp_of_vector`), singular as printed at
    ``w = 0`` only: a removable singularity (:mod:`rigidsym.codegen.removable.singularities`).
    """
    if theta is None:
        theta, K = split_angle(X)
    else:
        K = sp.Matrix(X)
    w = vect_explicit(K[:3, :3])
    if not (unit or is_unit(w)):
        if K.shape == (4, 4) and all(e == 0 for e in w) and is_unit(K[:3, 3]):
            return _transform_explicit(sp.eye(3), K[:3, 3] * theta)
        return exp_of_vector(K * theta)
    W = cpm_explicit(w)
    R = sp.eye(3) + sp.sin(theta) * W + (1 - sp.cos(theta)) * W * W
    if K.shape == (3, 3):
        return R
    G = sp.eye(3) * theta + (1 - sp.cos(theta)) * W + (theta - sp.sin(theta)) * W * W
    return _transform_explicit(R, G * K[:3, 3])


# --------------------------------------------------------------------- unconstrained exponents
def log_explicit(R) -> sp.Matrix:
    """``theta / (2 sin theta) (R - R^T)``, ``theta = acos((tr R - 1) / 2)`` (MR (3.53)-(3.54)).

    ``sin theta`` is kept unevaluated (sympy would write ``sqrt(1 - c^2)`` for
    ``sin(acos(c))``), so that the zero test's principal branch
    (:mod:`rigidsym.checking.deciding.branches`) makes it ``sin b`` for an angle ``b`` on
    ``[0, pi]`` with ``cos b = (tr R - 1) / 2``.
    """
    R = sp.Matrix(R)
    theta = sp.acos((R.trace() - 1) / 2)
    s = sp.sin(theta, evaluate=False)
    return (R - R.T).applyfunc(lambda e: sp.Mul(theta, e, sp.Pow(2 * s, -1, evaluate=False),
                                                 evaluate=False))


def norm3(w) -> sp.Expr:
    """``theta = sqrt(w^T w)``, the angle of the rotation vector ``w`` (3 x 1).

    The zero test reads it through the polar parametrisation ``w = theta e`` (``theta`` an
    angle on ``[0, pi]``, ``e`` a unit vector: :mod:`rigidsym.checking.deciding.branches`);
    Solà, Deray & Atchuthan (2018), App. B, ``theta = ||theta u||``.

    Args:
        w: the rotation vector, 3 entries (a sympy Matrix or a sequence) [rad].

    Returns:
        The scalar ``sqrt(w1**2 + w2**2 + w3**2)`` [rad], a sympy expression.
    """
    w = sp.Matrix(w)
    return sp.sqrt(sum(x**2 for x in w))


def exp_of_vector(X) -> sp.Matrix:
    """``exp([w])`` (3 x 3) or ``exp([w, v]^)`` (4 x 4) of an unconstrained exponent.

    With ``theta = sqrt(w^T w)`` and ``W = [w]``: ``exp(W) = 1 + (sin theta / theta) W +
    ((1 - cos theta) / theta^2) W^2`` (Solà et al. 2018, "A micro Lie theory", App. B;
    Barfoot, *State Estimation for Robotics*, Sec. 7.1.3) and ``exp([[W, v], [0, 0]]) =
    [[exp(W), J_l(w) v], [0, 1]]`` with the left Jacobian ``J_l(w) = 1 + ((1 - cos
    theta) / theta^2) W + ((theta - sin theta) / theta^3) W^2`` (MR (3.88) with ``[w] =
    theta [omega]``; Solà App. D; Barfoot Sec. 7.1.4). Removable singularity at ``w = 0``.
    """
    X = sp.Matrix(X)
    w = vect_explicit(X[:3, :3])
    W, th = cpm_explicit(w), norm3(w)
    R = sp.eye(3) + sp.sin(th) / th * W + (1 - sp.cos(th)) / th**2 * W * W
    if X.shape == (3, 3):
        return R
    J = sp.eye(3) + (1 - sp.cos(th)) / th**2 * W + (th - sp.sin(th)) / th**3 * W * W
    return _transform_explicit(R, J * X[:3, 3])


def log_se3_explicit(T) -> sp.Matrix:
    """The principal logarithm of a transform ``T = [[R, p], [0, 1]]``: ``[[Omega, J_l^-1
    p], [0, 0]]`` with ``Omega = log R`` (:func:`log_explicit`, ``[w] = Omega``, ``theta =
    acos((tr R - 1) / 2)``) and ``J_l^-1 = 1 - Omega / 2 + (1 / theta^2 - sin theta / (2
    theta (1 - cos theta))) Omega^2`` (MR (3.91)-(3.92); Solà App. D; Barfoot Sec. 7.1.4).
    Singular as printed at ``theta = 0`` and ``theta = pi`` (those of ``log R``).
    """
    T = sp.Matrix(T)
    Om = log_explicit(T[:3, :3])
    theta = sp.acos((T[:3, :3].trace() - 1) / 2)
    s = sp.sin(theta, evaluate=False)
    k = 1 / theta**2 - s / (2 * theta * (1 - sp.cos(theta)))
    Jinv = sp.eye(3) - Om / 2 + k * Om * Om
    return sp.Matrix.vstack(sp.Matrix.hstack(Om, Jinv * T[:3, 3]), sp.zeros(1, 4))


# --------------------------------------------------------------------- the words
def _order(order: str) -> int:
    if order not in ORDERS:
        raise ValueError(f"order: expected one of {', '.join(map(repr, ORDERS))}, "
                         f"got {order!r}")
    return ORDERS[order]


def _shape(x, name: str) -> tuple[int, int]:
    if not isinstance(x, sp.MatrixBase | sp.MatrixExpr):
        raise ValueError(f"{name}: expected a matrix or vector, got {type(x).__name__}")
    return tuple(int(n) for n in x.shape)


def _lazy_or(cls, args, flag=None):
    mats = list(args)
    extra = [sp.Integer(flag)] if flag is not None else []
    if any(is_symbolic(a) for a in mats):
        return cls(*mats, *extra)
    op = cls(*[sp.ImmutableMatrix(a) if isinstance(a, sp.MatrixBase) else a for a in mats],
             *extra)
    return sp.Matrix(op.value(*[sp.Matrix(a) for a in mats]))


def hat(x, order: str = "angeles"):
    """``[x]``: the so(3) matrix of a 3-vector (the cross-product matrix, Angeles (2.38),
    MR (3.30)) or the se(3) matrix ``[[[w], v], [0, 0]]`` of a twist (MR (3.85), MLS
    (2.36)).

    Args:
        x: a 3 x 1 vector or a 6 x 1 twist (explicit, or a book symbol).
        order: the twist's order (:data:`ORDERS`).

    Returns:
        3 x 3 or 4 x 4; explicit for explicit ``x``, the lazy :class:`Hat` for a symbol.

    Raises:
        ValueError: ``x`` is neither 3 x 1 nor 6 x 1, or an unknown ``order``.
    """
    lin = _order(order)
    if Hat.shape_of([_shape(x, "x")]) == (3, 3):
        return cpm(x)  # so(3): the book's cross-product matrix, one word for one thing
    return _lazy_or(Hat, [x], lin)


def vee(X, order: str = "angeles"):
    """``X^vee``, the inverse of :func:`hat`: the axial vector of the skew part of a 3 x 3
    (= ``vect``, Angeles Sec. 2.3.3), the twist ``[w; v]`` of a 4 x 4 (MR (3.85)).

    Args:
        X: 3 x 3 or 4 x 4 (explicit, or a book symbol).
        order: the twist's order (:data:`rigidsym.algebra.rigid_motions.ORDERS`).

    Returns:
        3 x 1 or 6 x 1; lazy for a book symbol.

    Raises:
        ValueError: ``X`` is neither 3 x 3 nor 4 x 4, or an unknown ``order``.
    """
    lin = _order(order)
    if Vee.shape_of([_shape(X, "X")]) == (3, 1):
        return vect(X)
    return _lazy_or(Vee, [X], lin)


def transform(R, p):
    """The homogeneous transform ``[[R, p], [0, 1]]`` (4 x 4; MR (3.62), Angeles (2.80)).

    Args:
        R: 3 x 3 rotation.
        p: 3 x 1 translation [m].

    Returns:
        4 x 4; lazy for book symbols.

    Raises:
        ValueError: shapes other than 3 x 3 and 3 x 1.
    """
    Transform.shape_of([_shape(R, "R"), _shape(p, "p")])
    return _lazy_or(Transform, [R, p])


def transform_inverse(T):
    """``T^-1 = [[R^T, -R^T p], [0, 1]]`` of a homogeneous transform (MR (3.64)); exact for
    a rotation block only (no general matrix inverse).

    Args:
        T: 4 x 4 homogeneous transform.

    Returns:
        4 x 4; lazy for a book symbol.

    Raises:
        ValueError: ``T`` is not 4 x 4.
    """
    TransformInverse.shape_of([_shape(T, "T")])
    return _lazy_or(TransformInverse, [T])


def Ad(T, order: str = "angeles"):
    """``[Ad_T]`` (6 x 6) of ``T = (R, p)``: ``[[R, 0], [[p] R, R]]`` on angular-first
    twists (MR (3.83), MLS (2.58)); wrenches transform by its transpose (MR (3.98)).

    Args:
        T: 4 x 4 homogeneous transform.
        order: the twists' order (:data:`rigidsym.algebra.rigid_motions.ORDERS`).

    Returns:
        6 x 6; lazy for a book symbol.

    Raises:
        ValueError: ``T`` is not 4 x 4, or an unknown ``order``.
    """
    lin = _order(order)
    AdT.shape_of([_shape(T, "T")])
    return _lazy_or(AdT, [T], lin)


def ad(V, order: str = "angeles"):
    """``[ad_V]`` (6 x 6) of a twist ``V = [w; v]``: ``[[[w], 0], [[v], [w]]]`` (MR (8.38)):
    ``ad(V1) V2`` is the Lie bracket ``vee([V1] [V2] - [V2] [V1])``.

    Args:
        V: 6 x 1 twist.
        order: its order (:data:`rigidsym.algebra.rigid_motions.ORDERS`).

    Returns:
        6 x 6; lazy for a book symbol.

    Raises:
        ValueError: ``V`` is not 6 x 1, or an unknown ``order``.
    """
    lin = _order(order)
    AdV.shape_of([_shape(V, "V")])
    return _lazy_or(AdV, [V], lin)


def ad_dual(V, order: str = "angeles"):
    """``ad*_V = -[ad_V]^T`` (6 x 6), the dual acting on wrenches (Featherstone (2.20),
    ``v x*``); MR's ``[ad_V]^T`` is ``-ad_dual(V)``.

    Args:
        V: 6 x 1 twist.
        order: its order (:data:`rigidsym.algebra.rigid_motions.ORDERS`).

    Returns:
        6 x 6; lazy for a book symbol.

    Raises:
        ValueError: ``V`` is not 6 x 1, or an unknown ``order``.
    """
    lin = _order(order)
    AdDual.shape_of([_shape(V, "V")])
    return _lazy_or(AdDual, [V], lin)


def expm(X, order: str = "angeles", *, unit_axis: bool = False):
    """The matrix exponential of ``theta [w]`` (so(3), a rotation) or ``theta [S]`` (se(3),
    a transform), in closed form (:func:`exp_explicit`: MR (3.51), (3.88); Angeles (2.49)).

    An angle times a generator with a unit axis ``|w| = 1`` (or ``w = 0``, ``|v| = 1``),
    proven exactly when the value is formed, takes MR's closed forms; any other exponent (a
    free rotation vector ``w``, exponential coordinates ``[w; v]``) those in the norm
    ``theta = sqrt(w^T w)`` (:func:`rigidsym.algebra.rigid_motions.exp_of_vector`, Solà et
    al. 2018 App. B and D), whose ``w = 0`` is a removable singularity.

    Args:
        X: 3 x 3 or 4 x 4: ``theta * hat(w)`` of book symbols (lazy), or explicit.
        order: unused by the matrix form; accepted for a uniform vocabulary.
        unit_axis: explicit ``X`` only: the caller asserts ``|w| = 1`` (a kernel's
            argument of kind ``"unit"``, validated at run time); a declaration's model
            never needs it (its unit vectors are known by construction).

    Returns:
        3 x 3 rotation or 4 x 4 transform; lazy for book symbols.

    Raises:
        ValueError: not 3 x 3 or 4 x 4, or an unknown ``order``.
    """
    lin = _order(order)
    Expm.shape_of([_shape(X, "X")])
    if unit_axis and not is_symbolic(X):
        return exp_explicit(X, lin, unit=True)
    return _lazy_or(Expm, [X], lin)


def logm(R):
    """The principal logarithm of a rotation (MR (3.53)-(3.54), Algorithm of Sec. 3.2.3.3):
    ``[omega] theta = theta / (2 sin theta) (R - R^T)`` with ``theta = acos((tr R - 1) /
    2)`` in ``[0, pi]``.

    Singular set: ``theta = 0`` (the formula is ``0/0``; the log is ``O``) and ``theta =
    pi`` (``sin theta = 0``, the axis is determined only up to sign: MR's other branch).
    The zero test decides it where ``R``'s model is a rotation by an angle on ``[0, pi]``
    (``angle(..., range="[0, pi]")``); on the default range it is the log of the rotation
    by ``|theta|`` about ``sign(theta) omega``, which the split of ``acos`` handles.

    Of a transform ``T = [[R, p], [0, 1]]`` (4 x 4): ``[[log R, J_l^-1 p], [0, 0]]``
    (MR (3.91)-(3.92); :func:`rigidsym.algebra.rigid_motions.log_se3_explicit`).

    Args:
        R: 3 x 3 rotation or 4 x 4 transform (explicit, or a book symbol: lazy).

    Returns:
        3 x 3 skew matrix ``[omega] theta``, or the 4 x 4 se(3) matrix of a transform.

    Raises:
        ValueError: ``R`` is neither 3 x 3 nor 4 x 4.
    """
    Logm.shape_of([_shape(R, "R")])
    return _lazy_or(Logm, [R])


def diff(X, v):
    """``dX/dv`` of any modelled symbol or expression: matrices (lazily for book symbols,
    :class:`~rigidsym.algebra.operators.Diff`) and scalars; the book's dot accents are
    ``v = t`` (:data:`rigidsym.algebra.symbols.TIME`).

    Args:
        X: a scalar, an explicit matrix or a matrix expression of book symbols.
        v: the variable (a real symbol: an angle, time, a scalar).

    Returns:
        The derivative, of the shape of ``X``: lazy (``Diff`` or an unevaluated
        ``Derivative``) where ``X`` holds book symbols.

    Raises:
        ValueError: ``v`` is not a symbol.
    """
    if not isinstance(v, sp.Symbol):
        raise ValueError(f"v: expected a sympy symbol, got {type(v).__name__}")
    if isinstance(X, sp.MatrixExpr) and not isinstance(X, sp.MatrixBase):
        return Diff(X, v)
    if isinstance(X, sp.MatrixBase):
        return sp.Matrix(X).diff(v)
    return sp.Derivative(X, v) if X.atoms(sp.MatrixSymbol) else sp.diff(X, v)
