"""The vocabulary of rigid motions: twists and wrenches, so(3) and se(3), homogeneous
transforms, the adjoint maps and the exponential (issue 28).

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
matrices they return explicit matrices.
"""

from __future__ import annotations

import sympy as sp
from sympy.printing.precedence import PRECEDENCE

from rigidsym.algebra.lie_vectors import (
    exp_of_vector,
    explicit_axial,
    explicit_cpm,
    explicit_transform,
    log_explicit,
    log_se3_explicit,
)
from rigidsym.algebra.operators import explicit

__all__ = ["ORDERS", "LieOp", "Hat", "Vee", "Transform", "TransformInverse", "AdT", "AdV",
           "AdDual", "Expm", "Logm", "exp_explicit", "log_explicit", "is_unit", "split_angle"]

#: the twist and wrench orders by name: 0 the angular part first, 1 the linear part first
ORDERS = {"angeles": 0, "modern-robotics": 0, "featherstone": 0, "pinocchio": 1, "ros": 1}


# --------------------------------------------------------------------- explicit formulas
def _split(V, lin: int) -> tuple[sp.Matrix, sp.Matrix]:
    V = sp.Matrix(V)
    a, b = V[:3, :], V[3:, :]
    return (b, a) if lin else (a, b)


def _join(w, v, lin: int) -> sp.Matrix:
    return sp.Matrix.vstack(*((v, w) if lin else (w, v)))


def _hat(x, lin: int) -> sp.Matrix:
    x = sp.Matrix(x)
    if x.shape == (3, 1):
        return explicit_cpm(x)
    w, v = _split(x, lin)
    return sp.Matrix.vstack(sp.Matrix.hstack(explicit_cpm(w), v), sp.zeros(1, 4))


def _vee(X, lin: int) -> sp.Matrix:
    X = sp.Matrix(X)
    if X.shape == (3, 3):
        return explicit_axial(X)
    return _join(explicit_axial(X[:3, :3]), X[:3, 3], lin)


def _transform_inverse(T) -> sp.Matrix:
    T = sp.Matrix(T)
    R, p = T[:3, :3], T[:3, 3]
    return explicit_transform(R.T, -R.T * p)


def _blocks(a, b, c, d, lin: int) -> sp.Matrix:
    """``[[a, b], [c, d]]`` in the angular-first order, rewritten for ``lin``."""
    if lin:
        a, b, c, d = d, c, b, a
    return sp.Matrix.vstack(sp.Matrix.hstack(a, b), sp.Matrix.hstack(c, d))


def _Ad(T, lin: int) -> sp.Matrix:
    T = sp.Matrix(T)
    R, p = T[:3, :3], T[:3, 3]
    return _blocks(R, sp.zeros(3), explicit_cpm(p) * R, R, lin)


def _ad(V, lin: int) -> sp.Matrix:
    w, v = _split(V, lin)
    return _blocks(explicit_cpm(w), sp.zeros(3), explicit_cpm(v), explicit_cpm(w), lin)


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
        return explicit_transform(R, p)


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
    :func:`rigidsym.algebra.lie_vectors.log_se3_explicit`."""
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
    (:func:`rigidsym.algebra.lie_vectors.exp_of_vector`, issue 38), singular as printed at
    ``w = 0`` only: a removable singularity (:mod:`rigidsym.codegen.removable.singularities`).
    """
    if theta is None:
        theta, K = split_angle(X)
    else:
        K = sp.Matrix(X)
    w = explicit_axial(K[:3, :3])
    if not (unit or is_unit(w)):
        if K.shape == (4, 4) and all(e == 0 for e in w) and is_unit(K[:3, 3]):
            return explicit_transform(sp.eye(3), K[:3, 3] * theta)
        return exp_of_vector(K * theta)
    W = explicit_cpm(w)
    R = sp.eye(3) + sp.sin(theta) * W + (1 - sp.cos(theta)) * W * W
    if K.shape == (3, 3):
        return R
    G = sp.eye(3) * theta + (1 - sp.cos(theta)) * W + (theta - sp.sin(theta)) * W * W
    return explicit_transform(R, G * K[:3, 3])

