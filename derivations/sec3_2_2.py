"""Sec. 3.2.2: The Plücker coordinates of a line, Eqs. (3.19)-(3.33).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.2.2.

First principles: a line is the set of points ``p1 + lambda (p2 - p1)``; here
``p2 = p1 + ell u`` with ``u`` a unit vector and ``ell`` a free length, so that
``||p2 - p1||`` is ``ell`` without a square root (the zero test needs rational
expressions); the moment of a line about a point ``A`` is ``(p - a) x e`` for any point
``p`` of the line. ``e``, ``n`` below are the line's direction and moment (not the rotation
axis of Sec. 3.2).
"""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import (
    Rel,
    Statement,
    as_vector,
    block,
    cpm,
    equation,
    scalar,
    unit_vector,
    vector,
)

from .common import I3, MS, O3, Blocks, Cross, Det, mat, vec

_im = sp.ImmutableMatrix


# book symbols: two points of the line, their CPMs, a point P of it, the arrays
p_1, p_2, p = vec("p_1"), vec("p_2"), vec("p")
P_1, P_2 = mat("P_1"), mat("P_2")
gamma_L = MS("gamma_L", 6, 1)
e, n = vec("e"), vec("n")
kappa = MS("kappa", 6, 1)
#: ||p_2 - p_1||, kept as a symbol (no square root)
norm_p21 = sp.Symbol("norm_p21", real=True)
a, b = vec("a"), vec("b")
A, B = mat("A"), mat("B")
n_A, n_B = vec("n_A"), vec("n_B")
kappa_A, kappa_B = MS("kappa_A", 6, 1), MS("kappa_B", 6, 1)
U = MS("U", 6, 6)
f = vec("f")
kappa_inf = MS("kappa_inf", 6, 1)
_one = sp.ImmutableMatrix([[1]])


# --------------------------------------------------------------------------- formulas
def plucker_from_points(p1, p2, length=None) -> sp.Matrix:
    """Normalised Plücker array of the line through two points: ``[e; n]``.

    ``e = (p2 - p1) / ||p2 - p1||``, ``n = p1 x e`` (moment about the origin).

    Book: Sec. 3.2.2, Eqs. (3.21)-(3.23).

    Args:
        p1: 3 x 1 position of a first point of the line (m).
        p2: 3 x 1 position of a second point (m).
        length: ``||p2 - p1||`` when the caller knows it (avoids a square root in exact
            checks); computed with ``sqrt`` when ``None``.

    Returns:
        6 x 1 ``sympy.Matrix`` ``[e; n]``: unit direction (dimensionless) over moment (m);
        ``e . e = 1``, ``n . e = 0``.

    Notes:
        Singular set: ``p1 = p2`` (no line).
    """
    p1, p2 = as_vector(p1, "p1"), as_vector(p2, "p2")
    d = p2 - p1
    ell = sp.sqrt((d.T * d)[0, 0]) if length is None else length
    e_ = d / ell
    return block([[e_], [p1.cross(e_)]])


def plucker_transfer_matrix(a, b) -> sp.Matrix:
    """Plücker transfer matrix ``U = [[1, O], [A - B, 1]]``, ``A = CPM(a)``, ``B = CPM(b)``.

    Book: Sec. 3.2.2, Eq. (3.29b). ``det U = 1``; ``U^{-1} = [[1, O], [B - A, 1]]``.

    Args:
        a: 3 x 1 position of the point A the moment is measured at (m).
        b: 3 x 1 position of the new point B (m).

    Returns:
        6 x 6 ``sympy.Matrix``; no singular set.
    """
    A_, B_ = cpm(as_vector(a, "a")), cpm(as_vector(b, "b"))
    return block([[sp.eye(3), sp.zeros(3, 3)], [A_ - B_, sp.eye(3)]])


def plucker_transfer(kappa_A, a, b) -> sp.Matrix:
    """Plücker array of a line with its moment moved from point A to point B:
    ``kappa_B = U kappa_A`` (``n_B = n_A + (a - b) x e``).

    Book: Sec. 3.2.2, Eq. (3.29a).

    Args:
        kappa_A: 6 x 1 Plücker array ``[e; n_A]`` (moment about A, m).
        a, b: 3 x 1 positions of A and B (m).

    Returns:
        6 x 1 ``sympy.Matrix`` ``[e; n_B]``.
    """
    kappa_A = sp.Matrix(kappa_A)
    if kappa_A.shape != (6, 1):
        raise ValueError(f"kappa_A: expected a 6 x 1 array, got shape {kappa_A.shape}")
    return plucker_transfer_matrix(a, b) * kappa_A


# --------------------------------------------------------------------------- models
def line_model() -> dict:
    """A line through ``p1`` and ``p2 = p1 + ell u`` (``u`` unit, ``ell`` free), a point
    ``p = p1 + lambda (p2 - p1)`` of it, a free point ``q``; ``P_i = CPM(p_i)``; the
    arrays of Eqs. (3.21)-(3.23) with their definitions."""
    p1 = vector("s322_p1")
    u = unit_vector("s322_u")
    ell = scalar("s322_ell")
    lam = scalar("s322_lambda")
    p2 = p1 + ell * u
    pt = p1 + lam * (p2 - p1)
    e_ = (p2 - p1) / ell
    model = {p_1: _im(p1), p_2: _im(p2), p: _im(pt), P_1: _im(cpm(p1)), P_2: _im(cpm(p2)),
             norm_p21: ell, vec("q"): _im(vector("s322_q")),
             gamma_L: _im(block([[p2 - p1], [p1.cross(p2 - p1)]])),
             e: _im(e_), n: _im(p1.cross(e_)),
             kappa: _im(plucker_from_points(p1, p2, length=ell))}
    return model


def transfer_model() -> dict:
    """A line through a free point ``p`` along a unit ``e``, free points ``a``, ``b``;
    moments about A and B from their definition ``(p - x) x e``; ``U`` from
    :func:`plucker_transfer_matrix`."""
    e_ = unit_vector("s322_e")
    pt, a_, b_ = vector("s322_p"), vector("s322_a"), vector("s322_b")
    nA, nB = (pt - a_).cross(e_), (pt - b_).cross(e_)
    model = {e: _im(e_), p: _im(pt), a: _im(a_), b: _im(b_), A: _im(cpm(a_)),
             B: _im(cpm(b_)), n_A: _im(nA), n_B: _im(nB),
             kappa_A: _im(block([[e_], [nA]])), kappa_B: _im(block([[e_], [nB]])),
             U: _im(plucker_transfer_matrix(a_, b_))}
    return model


# --------------------------------------------------------------------------- declarations
@equation("3.19", "Equation of the line through P1 and P2", section="3.2.2",
          latex=r"(\mathbf{p}_2 - \mathbf{p}_1) \times \mathbf{p} + \mathbf{p}_1 \times "
                r"(\mathbf{p}_2 - \mathbf{p}_1) = \mathbf{0}")
def line_through_two_points() -> Statement:
    """``(p2 - p1) x p + p1 x (p2 - p1) = 0`` for every point P of the line, and it is the
    expansion of the collinearity condition ``(p2 - p1) x (p - p1)`` for every point.

    Book: Sec. 3.2.2, Eq. (3.19). Shapes: 3 x 1, m^2.
    """
    q = vec("q")
    return Statement(
        [Rel(Cross(p_2 - p_1, p) + Cross(p_1, p_2 - p_1), sp.ZeroMatrix(3, 1))], line_model(),
        claims=[Rel(Cross(p_2 - p_1, q) + Cross(p_1, p_2 - p_1), Cross(p_2 - p_1, q - p_1),
                    "expansion of (p2 - p1) x (q - p1) for every q")])


@equation("3.20", "Line equation in homogeneous coordinates", section="3.2.2",
          latex=r"\begin{bmatrix} \mathbf{P}_2 - \mathbf{P}_1 & \mathbf{p}_1 \times "
                r"(\mathbf{p}_2 - \mathbf{p}_1) \end{bmatrix} \begin{bmatrix} \mathbf{p} \\ 1 "
                r"\end{bmatrix} = \mathbf{0}")
def line_homogeneous() -> Statement:
    """``[P2 - P1, p1 x (p2 - p1)] [p; 1] = 0`` (3 x 4 times 4 x 1), ``P_i = CPM(p_i)``.

    Book: Sec. 3.2.2, Eq. (3.20).
    """
    lhs = Blocks([[P_2 - P_1, Cross(p_1, p_2 - p_1)]]) * Blocks([[p], [_one]])
    return Statement([Rel(lhs, sp.ZeroMatrix(3, 1))], line_model())


@equation("3.21", "Plücker coordinates gamma_L of a line", section="3.2.2", kind="definition",
          latex=r"\boldsymbol{\gamma}_{\mathcal{L}} \equiv \begin{bmatrix} \mathbf{p}_2 - "
                r"\mathbf{p}_1 \\ \mathbf{p}_1 \times (\mathbf{p}_2 - \mathbf{p}_1) "
                r"\end{bmatrix}")
def plucker_coordinates() -> Statement:
    """``gamma_L = [p2 - p1; p1 x (p2 - p1)]`` (6 x 1: m over m^2).

    Book: Sec. 3.2.2, Eq. (3.21) (definition).
    """
    return Statement([Rel(gamma_L, Blocks([[p_2 - p_1], [Cross(p_1, p_2 - p_1)]]))],
                     line_model(), defines=("gamma_L",))


@equation("3.22", "Unit direction and moment of a line", section="3.2.2", kind="definition",
          latex=r"\mathbf{e} \equiv \frac{\mathbf{p}_2 - \mathbf{p}_1}{\|\mathbf{p}_2 - "
                r"\mathbf{p}_1\|}, \quad \mathbf{n} \equiv \mathbf{p}_1 \times \mathbf{e}",
          singular="p_1 = p_2")
def line_direction_and_moment() -> Statement:
    """``e = (p2 - p1) / ||p2 - p1||``, ``n = p1 x e``; ``||p2 - p1||`` is the symbol
    ``norm_p21``, and the claims check ``norm_p21^2 = ||p2 - p1||^2`` and ``e . e = 1``.

    Book: Sec. 3.2.2, Eq. (3.22) (definition). Shapes: 3 x 1; e dimensionless, n in m.
    """
    d = p_2 - p_1
    return Statement([Rel(e, d / norm_p21), Rel(n, Cross(p_1, e))], line_model(),
                     defines=("e", "n"),
                     claims=[Rel((d.T * d)[0, 0], norm_p21**2, "norm_p21 is ||p2 - p1||"),
                             Rel((e.T * e)[0, 0], 1, "e is a unit vector")])


@equation("3.23", "Plücker array of a line", section="3.2.2", kind="definition",
          latex=r"\boldsymbol{\kappa} = \begin{bmatrix} \mathbf{e} \\ \mathbf{n} "
                r"\end{bmatrix}", singular="p_1 = p_2")
def plucker_array() -> Statement:
    """``kappa = [e; n]``, the normalised Plücker array; the unnumbered
    ``gamma_L = ||p2 - p1|| [e; n]`` before it is checked, and :func:`plucker_from_points`
    against ``[e; n]`` of Eq. (3.22).

    Book: Sec. 3.2.2, Eq. (3.23) (definition). Shape: 6 x 1.
    """
    return Statement([Rel(kappa, Blocks([[e], [n]]))], line_model(),
                     defines=("kappa",),
                     claims=[Rel(gamma_L, norm_p21 * Blocks([[e], [n]]),
                                 "gamma_L = ||p2 - p1|| [e; n]"),
                             Rel(kappa, Blocks([[e], [n]]), "plucker_from_points")])


@equation("3.24", "Plücker constraints", section="3.2.2",
          latex=r"\mathbf{e} \cdot \mathbf{e} = 1, \quad \mathbf{n} \cdot \mathbf{e} = 0")
def plucker_constraints() -> Statement:
    """``e . e = 1``, ``n . e = 0`` for the array of :func:`plucker_from_points`.

    Book: Sec. 3.2.2, Eq. (3.24).
    """
    model = line_model()
    k = sp.Matrix(model[kappa])
    model.update({e: _im(k[:3, :]), n: _im(k[3:, :])})
    return Statement([Rel((e.T * e)[0, 0], 1, "e . e = 1"),
                      Rel((n.T * e)[0, 0], 0, "n . e = 0")], model)


@equation("3.25", "Moments of a line about A and B", section="3.2.2", kind="definition",
          latex=r"\mathbf{n}_A \equiv (\mathbf{p} - \mathbf{a}) \times \mathbf{e}, \quad "
                r"\mathbf{n}_B \equiv (\mathbf{p} - \mathbf{b}) \times \mathbf{e}")
def line_moments() -> Statement:
    """``n_A = (p - a) x e``, ``n_B = (p - b) x e`` (3 x 1, m).

    Book: Sec. 3.2.2, Eq. (3.25) (definition).
    """
    return Statement([Rel(n_A, Cross(p - a, e)), Rel(n_B, Cross(p - b, e))],
                     transfer_model(), defines=("n_A", "n_B"))


@equation("3.26", "Plücker arrays at A and B", section="3.2.2", kind="definition",
          latex=r"\kappa_A \equiv \begin{bmatrix} \mathbf{e} \\ \mathbf{n}_A \end{bmatrix}, "
                r"\quad \kappa_B \equiv \begin{bmatrix} \mathbf{e} \\ \mathbf{n}_B "
                r"\end{bmatrix}")
def plucker_arrays_at_points() -> Statement:
    """``kappa_A = [e; n_A]``, ``kappa_B = [e; n_B]`` (6 x 1).

    Book: Sec. 3.2.2, Eq. (3.26) (definition).
    """
    return Statement([Rel(kappa_A, Blocks([[e], [n_A]])),
                      Rel(kappa_B, Blocks([[e], [n_B]]))],
                     transfer_model(), defines=("kappa_A", "kappa_B"))


@equation("3.27", "Change of moment between two points", section="3.2.2",
          latex=r"\mathbf{n}_B - \mathbf{n}_A = (\mathbf{a} - \mathbf{b}) \times \mathbf{e}")
def moment_change() -> Statement:
    """``n_B - n_A = (a - b) x e``. Book: Sec. 3.2.2, Eq. (3.27). Shape 3 x 1, m."""
    return Statement([Rel(n_B - n_A, Cross(a - b, e))], transfer_model())


@equation("3.28", "Plücker array at B from the moment at A", section="3.2.2",
          latex=r"\kappa_B = \begin{bmatrix} \mathbf{e} \\ \mathbf{n}_A + (\mathbf{a} - "
                r"\mathbf{b}) \times \mathbf{e} \end{bmatrix}")
def plucker_array_moved() -> Statement:
    """``kappa_B = [e; n_A + (a - b) x e]``. Book: Sec. 3.2.2, Eq. (3.28). Shape 6 x 1."""
    return Statement([Rel(kappa_B, Blocks([[e], [n_A + Cross(a - b, e)]]))],
                     transfer_model())


@equation("3.29a", "Plücker transfer", section="3.2.2",
          latex=r"\kappa_B = \mathbf{U} \kappa_A")
def plucker_transfer_formula() -> Statement:
    """``kappa_B = U kappa_A``; also :func:`plucker_transfer` against ``kappa_B``.

    Book: Sec. 3.2.2, Eq. (3.29a). Shapes: 6 x 6 times 6 x 1.
    """
    model = transfer_model()
    kernel = plucker_transfer(model[kappa_A], model[a], model[b])
    return Statement([Rel(kappa_B, U * kappa_A)], model,
                     claims=[Rel(kappa_B, kernel, "plucker_transfer")])


@equation("3.29b", "Plücker transfer matrix U", section="3.2.2", kind="definition",
          latex=r"\mathbf{U} \equiv \begin{bmatrix} \mathbf{1} & \mathbf{O} \\ \mathbf{A} - "
                r"\mathbf{B} & \mathbf{1} \end{bmatrix}")
def plucker_transfer_matrix_definition() -> Statement:
    """``U = [[1, O], [A - B, 1]]`` with ``A = CPM(a)``, ``B = CPM(b)`` (6 x 6; lower blocks
    in m); :func:`plucker_transfer_matrix` is checked against it.

    Book: Sec. 3.2.2, Eq. (3.29b) (definition).
    """
    printed = Blocks([[I3, O3], [A - B, I3]])
    return Statement([Rel(U, printed)], transfer_model(), defines=("U",),
                     claims=[Rel(U, printed, "plucker_transfer_matrix")])


@equation("3.30", "U is unimodular", section="3.2.2", latex=r"\det(\mathbf{U}) = 1")
def plucker_transfer_unimodular() -> Statement:
    """``det(U) = 1``. Book: Sec. 3.2.2, Eq. (3.30)."""
    return Statement([Rel(Det(U), 1)], transfer_model())


@equation("3.31", "Inverse of U", section="3.2.2",
          latex=r"\mathbf{U}^{-1} = \begin{bmatrix} \mathbf{1} & \mathbf{O} \\ \mathbf{B} - "
                r"\mathbf{A} & \mathbf{1} \end{bmatrix}")
def plucker_transfer_inverse() -> Statement:
    """``U^{-1} = [[1, O], [B - A, 1]]``: checked as ``U X = 1`` and ``X U = 1`` (6 x 6,
    entry by entry) for the printed ``X``.

    Book: Sec. 3.2.2, Eq. (3.31).
    """
    X = Blocks([[I3, O3], [B - A, I3]])
    return Statement([Rel(U * X, sp.Identity(6), "U U^-1 = 1"),
                      Rel(X * U, sp.Identity(6), "U^-1 U = 1")], transfer_model())


@equation("3.32", "Moments share their component along a - b", section="3.2.2",
          latex=r"(\mathbf{a} - \mathbf{b})^T \mathbf{n}_B = (\mathbf{a} - \mathbf{b})^T "
                r"\mathbf{n}_A")
def moments_common_component() -> Statement:
    """``(a - b)^T n_B = (a - b)^T n_A``. Book: Sec. 3.2.2, Eq. (3.32). Units: m^2."""
    return Statement([Rel((a - b).T * n_B, (a - b).T * n_A)], transfer_model())


@equation("3.33", "Plücker array of a line at infinity", section="3.2.2", kind="definition",
          latex=r"\boldsymbol{\kappa}_\infty = \begin{bmatrix} \mathbf{0} \\ \mathbf{f} "
                r"\end{bmatrix}")
def plucker_array_at_infinity() -> Statement:
    """``kappa_inf = [0; f]`` with ``f`` the unit moment direction (6 x 1); the claim checks
    that it satisfies the Plücker constraint ``n . e = 0`` of Eq. (3.24).

    Book: Sec. 3.2.2, Eq. (3.33) (definition).
    """
    f_ = unit_vector("s322_f")
    model = {f: _im(f_), kappa_inf: _im(block([[sp.zeros(3, 1)], [f_]]))}
    k = kappa_inf
    return Statement([Rel(kappa_inf, Blocks([[sp.ZeroMatrix(3, 1)], [f]]))],
                     model, defines=("kappa_inf",),
                     claims=[Rel((k[3:, :].T * k[:3, :])[0, 0], 0, "n . e = 0"),
                             Rel((f.T * f)[0, 0], 1, "f is a unit vector")])
