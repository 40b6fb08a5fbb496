"""Book symbols and first-principles models shared by the section modules.

Book symbols are ``sympy.MatrixSymbol`` / ``Symbol`` objects named as in ``NOTATION.md``
so that a printed equation transcribes readably (``(Q - 1)^T (Q a - a')``). A *model* maps
each book symbol to its first-principles value, built from constrained atoms
(:mod:`rigidsym.symbols`): the checker substitutes it before deciding.

First principles used here: a rigid-body displacement is the map ``x -> Q x + c`` with
``Q`` proper orthogonal (here given by its natural invariants, Eq. (2.49)) and ``c`` a
free translation; nothing else about screws, Plücker lines or pitches is assumed.

Book operators shared by the sections (lazy: they print as the book writes them and become
explicit on ``doit()`` once the checker has substituted the model): ``Cross(u, v)``,
``Det(M)`` and the block matrix ``Blocks``.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.primitives import cpm, rotation_from_natural_invariants, vect
from rigidsym.symbols import TIME, angle, rotation, unit_vector, vector

__all__ = ["MS", "I3", "O3", "vec", "mat", "Cross", "Det", "Blocks", "displacement_model", "Bk",
           "Mt", "motion_model"]

I3 = sp.Identity(3)
O3 = sp.ZeroMatrix(3, 3)


def MS(name: str, rows: int = 3, cols: int = 1) -> sp.MatrixSymbol:
    """A book matrix symbol (vector by default)."""
    return sp.MatrixSymbol(name, rows, cols)


def vec(name: str) -> sp.MatrixSymbol:
    """A book 3-vector symbol."""
    return sp.MatrixSymbol(name, 3, 1)


def mat(name: str) -> sp.MatrixSymbol:
    """A book 3 x 3 matrix symbol."""
    return sp.MatrixSymbol(name, 3, 3)


# --------------------------------------------------------------------------- book operators
class Cross(sp.MatrixExpr):
    """The book's ``u x v`` of two 3-vectors as a matrix expression.

    Prints as ``Cross(u, v)``; ``doit()`` gives the explicit cross product once both
    factors are explicit (after the checker substitutes the model).
    """

    def __new__(cls, u, v):
        return sp.Basic.__new__(cls, u, v)

    @property
    def shape(self):
        return (sp.Integer(3), sp.Integer(1))

    def _entry(self, i, j, **kwargs):
        u, v = self.args
        k, m = (i + 1) % 3, (i + 2) % 3
        return u[k, 0] * v[m, 0] - u[m, 0] * v[k, 0]

    def doit(self, **hints):
        u, v = (a.doit(**hints) if isinstance(a, sp.Basic) else a for a in self.args)
        u, v = (x.as_explicit() if isinstance(x, sp.MatrixExpr) and
                not x.atoms(sp.MatrixSymbol) else x for x in (u, v))
        if isinstance(u, sp.MatrixBase) and isinstance(v, sp.MatrixBase):
            return sp.ImmutableMatrix(sp.Matrix(u).cross(sp.Matrix(v)))
        return Cross(u, v)


class Blocks(sp.BlockMatrix):
    """A book block matrix (``[[1, O], [A - B, 1]]``) that becomes explicit on ``doit()``
    once its blocks are (sympy's ``BlockMatrix`` stays symbolic inside a product, and the
    product's ``as_explicit`` then goes through symbolic sums: slow)."""

    def doit(self, **hints):
        r = super().doit(**hints)
        if isinstance(r, sp.BlockMatrix) and not r.atoms(sp.MatrixSymbol):
            return sp.ImmutableMatrix(r.as_explicit())
        return r


class Det(sp.Function):
    """The book's ``det(M)`` of a square matrix expression.

    Prints as ``Det(M)``; ``doit()`` substitutes the entries of an explicit ``M`` into the
    cofactor expansion of a generic 3 x 3 (no expansion, no cancellation: shared subtrees
    stay shared), where sympy's ``Determinant`` expands (slow) or stays unevaluated.
    """

    @classmethod
    def eval(cls, M):
        return None

    def doit(self, **hints):
        M = self.args[0]
        M = M.doit(**hints) if isinstance(M, sp.Basic) else M
        if isinstance(M, sp.MatrixExpr) and not M.atoms(sp.MatrixSymbol):
            M = M.as_explicit()
        if not isinstance(M, sp.MatrixBase):
            return Det(M)
        n = M.rows
        if n > 3:  # larger ones here are sparse (block triangular): sympy's det is fast
            return M.det()
        g = sp.Matrix(n, n, [sp.Dummy() for _ in range(n * n)])
        return g.det(method="berkowitz").xreplace(dict(zip(g, M, strict=True)))

    def _sympystr(self, printer):
        return f"Det({printer.doprint(self.args[0])})"


class Bk:
    """The book's symbols for a rigid-body displacement (Sec. 3.2)."""

    Q = mat("Q")
    E = mat("E")
    e = vec("e")
    phi = angle("phi")
    a = vec("a")
    a_prime = vec("a_prime")
    p = vec("p")
    p_prime = vec("p_prime")
    d_A = vec("d_A")
    d_P = vec("d_P")


def displacement_model() -> dict:
    """First-principles values of the displacement symbols (a fresh copy of a cached dict)."""
    return dict(_displacement_model())


@cache
def _displacement_model() -> dict:
    """First-principles values of the displacement symbols.

    ``Q`` from its natural invariants (2.49) with a constrained unit ``e`` and angle ``phi``;
    body points ``a``, ``p`` free; the displaced points from ``x' = Q x + c`` (``c`` free).
    ``d_A``, ``d_P`` are the displacements ``x' - x`` (definition (3.3)).
    """
    e = unit_vector("e")
    phi = Bk.phi
    Q = rotation_from_natural_invariants(e, phi)
    a, p, c = vector("a"), vector("p"), vector("c")
    a1, p1 = Q * a + c, Q * p + c
    im = sp.ImmutableMatrix
    return {Bk.Q: im(Q), Bk.E: im(cpm(e)), Bk.e: im(e), Bk.a: im(a), Bk.p: im(p),
            Bk.a_prime: im(a1), Bk.p_prime: im(p1), Bk.d_A: im(a1 - a), Bk.d_P: im(p1 - p)}


class Mt:
    """The book's symbols for a motion in time (Secs. 3.3-3.5): ``Q(t)``, its rates, points."""

    Q = mat("Q")
    Q_dot = mat("Qdot")
    Q_ddot = mat("Qddot")
    E = mat("E")
    e = vec("e")
    e_dot = vec("edot")
    phi = sp.Symbol("phi", real=True)
    phi_dot = sp.Symbol("phidot", real=True)
    Omega = mat("Omega")
    Omega_dot = mat("Omegadot")
    omega = vec("omega")
    omega_dot = vec("omegadot")
    a = vec("a")
    a_dot = vec("adot")
    a_ddot = vec("addot")
    p = vec("p")
    p_dot = vec("pdot")
    p_ddot = vec("pddot")


def motion_model(invariants: bool = True) -> dict:
    """First-principles values for a generic smooth rigid motion (see :func:`_motion_model`).

    Returns a fresh copy of a cached dict: the differentiation is done once per process.
    """
    return dict(_motion_model(invariants))


@cache
def _motion_model(invariants: bool) -> dict:
    """First-principles values for a generic smooth rigid motion.

    With ``invariants=False``, ``Q(t)`` is a generic rotation (rational quaternion jets):
    much smaller expressions, for statements that do not mention ``e`` or ``phi``; the
    ``e``, ``E``, ``phi`` entries are then absent from the model.

    ``e(t)`` a unit vector and ``phi(t)`` an angle (their jets are free, the constraint
    ``e.e = 1`` holds along the motion), ``Q(t)`` from (2.49), a reference point ``a(t)``
    free, and a body point moving rigidly: ``p(t) = a(t) + Q(t) (p0 - a0)`` with ``p0, a0``
    free constants, i.e. ``p(t) = a(t) + Q(t) r`` for a constant body vector ``r``.
    ``Omega = Q_dot Q^T`` and ``omega = vect(Omega)`` are *computed* from the motion.
    """
    t = TIME
    if invariants:
        e = unit_vector("e", t)
        phi = angle("phi", t)
        Q = rotation_from_natural_invariants(e, phi)
    else:
        Q = rotation("Q", t)
    Qd = Q.diff(t)
    Qdd = Qd.diff(t)
    Om = Qd * Q.T
    om = vect(Om)
    a = vector("a", t)
    r = vector("r")  # constant body-fixed vector p0 - a0, seen in the reference pose
    p = a + Q * r
    im = sp.ImmutableMatrix
    model = {Mt.Q: im(Q), Mt.Q_dot: im(Qd), Mt.Q_ddot: im(Qdd),
            Mt.Omega: im(Om), Mt.Omega_dot: im(Om.diff(t)), Mt.omega: im(om),
            Mt.omega_dot: im(om.diff(t)), Mt.a: im(a), Mt.a_dot: im(a.diff(t)),
            Mt.a_ddot: im(a.diff(t, 2)), Mt.p: im(p), Mt.p_dot: im(p.diff(t)),
            Mt.p_ddot: im(p.diff(t, 2))}
    if invariants:
        model.update({Mt.E: im(cpm(e)), Mt.e: im(e), Mt.e_dot: im(e.diff(t)), Mt.phi: phi,
                      Mt.phi_dot: phi.diff(t)})
    return model
