"""Sec. 3.2.1: The screw of a rigid-body motion, Eqs. (3.8)-(3.18).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.2.1.

Two first-principles models are used:

- the generic displacement ``x -> Q x + c`` (:func:`derivations.common.displacement_model`);
- the same displacement written about a line: ``x -> w + Q (x - w) + d0 e`` for a free point
  ``w`` and a free axial slide ``d0`` (:func:`screw_displacement_model`). It is generic (the
  map ``c = (1 - Q) w + d0 e`` reaches every translation when ``phi != 0``), and ``p0``, the
  point of that line closest to the origin, is *derived* by minimising ``||w + lambda e||``;
  nothing of Eqs. (3.8)-(3.18) is assumed.
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
    rotation_from_natural_invariants,
    scalar,
    unit_vector,
    vector,
)

from .common import I3, MS, Bk, Det, displacement_model

Q, E, e, phi, a, a_p, d_A = Bk.Q, Bk.E, Bk.e, Bk.phi, Bk.a, Bk.a_prime, Bk.d_A
#: book symbols of this subsection: the point P0 of the screw axis closest to the origin,
#: its displacement (bold d_0), the 4 x 3 system (3.10)-(3.11) and the coefficients (3.14).
p_0 = MS("p_0")
d0_vec = MS("d0_vec")
A_screw = MS("A_screw", 4, 3)
b_screw = MS("b_screw", 4, 1)
AtA_inv = MS("AtA_inv", 3, 3)
alpha = sp.Symbol("alpha_AtA", real=True)
beta = sp.Symbol("beta_AtA", real=True)
_im = sp.ImmutableMatrix


# --------------------------------------------------------------------------- formulas
def screw_axis_point(Q, a, a_prime, phi) -> sp.Matrix:
    """Point of the screw axis closest to the origin.

    ``p0 = (Q - 1)^T (Q a - a') / (2 (1 - cos phi))``.

    Book: Sec. 3.2.1, Eq. (3.18).

    Args:
        Q: 3 x 3 rotation matrix of the displacement (explicit sympy matrix).
        a: 3 x 1 position of a body point A before the displacement (m).
        a_prime: 3 x 1 position of the same point after the displacement (m).
        phi: rotation angle of ``Q`` (rad).

    Returns:
        3 x 1 ``sympy.Matrix``, the position vector ``p0`` (m), ``e^T p0 = 0``.

    Notes:
        Singular set: ``phi = 0`` (pure translation: every point has minimum displacement).
    """
    Q = sp.Matrix(Q)
    a, a_prime = as_vector(a, "a"), as_vector(a_prime, "a_prime")
    return (Q - sp.eye(3)).T * (Q * a - a_prime) / (2 * (1 - sp.cos(phi)))


def pitch_of_displacement(e, d_A, phi) -> sp.Expr:
    """Pitch of the screw of a finite displacement, in m/rad: ``p = e^T d_A / phi``.

    Book: Sec. 3.2, Eq. (3.7) (``d0 = e^T d_A`` from Eq. (3.5)). The book's m/turn variant
    is ``2 pi`` times this value.

    Args:
        e: 3 x 1 unit vector along the rotation axis.
        d_A: 3 x 1 displacement of any body point (m).
        phi: rotation angle (rad).

    Returns:
        the pitch (scalar sympy expression, m/rad).

    Notes:
        Singular set: ``phi = 0`` (pure translation, infinite pitch).
    """
    e, d_A = as_vector(e, "e"), as_vector(d_A, "d_A")
    return (e.T * d_A)[0, 0] / phi


# --------------------------------------------------------------------------- models
def closest_point_to_origin(w, e) -> sp.Matrix:
    """The point of the line ``{w + lambda e}`` closest to the origin, by minimisation."""
    lam = sp.Symbol("lambda_min", real=True)
    x = w + lam * e
    lam_star = sp.solve(sp.diff((x.T * x)[0, 0], lam), lam)[0]
    return x.subs(lam, lam_star)


def screw_displacement_model() -> dict:
    """First-principles values for a displacement written about its own line.

    The displacement rotates by ``Q`` (natural invariants ``e``, ``phi``) about the line
    through a free point ``w`` along ``e`` and slides by a free ``d0`` along it:
    ``x -> w + Q (x - w) + d0 e``. ``p_0`` is the point of that line closest to the origin
    (derived by minimisation); ``d0_vec`` is its displacement, computed from the map.
    The book's ``A``, ``b`` (3.11) enter with their definitions.
    """
    e_ = unit_vector("e")
    Q_ = rotation_from_natural_invariants(e_, phi)
    w = vector("w_axis")
    d0 = scalar("d0_axial")
    c = w - Q_ * w + d0 * e_
    a_ = vector("a")
    a1 = Q_ * a_ + c
    p0 = closest_point_to_origin(w, e_)
    model = {Q: _im(Q_), E: _im(cpm(e_)), e: _im(e_), a: _im(a_), a_p: _im(a1),
             d_A: _im(a1 - a_), p_0: _im(p0), d0_vec: _im(Q_ * p0 + c - p0)}
    model.update(screw_system_model(model))
    return model


def screw_system_model(model: dict) -> dict:
    """Values of ``A`` and ``b`` from their definition (3.11), given the other symbols."""
    Q_, e_, a_, dA = (sp.Matrix(model[s]) for s in (Q, e, a, d_A))
    one = sp.eye(3)
    A_ = block([[Q_ - one], [e_.T]])
    b_ = block([[(Q_ - one) * a_ - (one - e_ * e_.T) * dA], [sp.zeros(1, 1)]])
    return {A_screw: _im(A_), b_screw: _im(b_)}


def gram_inverse_model(model: dict) -> dict:
    """``(A^T A)^{-1}`` by adjugate over determinant (no structure assumed)."""
    A_ = sp.Matrix(model[A_screw])
    M = A_.T * A_
    # adjugate over determinant of a generic 3 x 3, then the entries of A^T A put in
    # (xreplace keeps shared subtrees shared: no expansion)
    g = sp.Matrix(3, 3, sp.symbols("g_11:14 g_21:24 g_31:34"))
    sub = dict(zip(g, M, strict=True))
    return {AtA_inv: _im((g.adjugate() / g.det(method="berkowitz")).xreplace(sub))}


def gram_inverse_coefficients_model(model: dict) -> dict:
    """``alpha``, ``beta`` of Eq. (3.14) derived from ``A^T A`` itself.

    If ``M = A^T A = m 1 + k e e^T`` (unit ``e``), then ``tr M - e^T M e = 2 m`` and
    ``e^T M e = m + k``; ``M (alpha 1 + beta e e^T) = 1`` gives ``alpha = 1 / m`` and
    ``alpha + beta = 1 / (m + k)`` (solved by sympy below). Whether ``M`` really lies in
    that span, and the product really is ``1``, is what the checks decide.
    """
    A_ = sp.Matrix(model[A_screw])
    e_ = sp.Matrix(model[e])
    M = A_.T * A_
    eMe = (e_.T * M * e_)[0, 0]
    m, k, al, be = sp.symbols("m_AtA k_AtA al be")
    # (m 1 + k e e^T)(al 1 + be e e^T) = m al 1 + (m be + k al + k be) e e^T = 1
    sol = sp.solve([m * al - 1, m * be + k * al + k * be], [al, be], dict=True)[0]
    vals = {m: (M.trace() - eMe) / 2, k: eMe - (M.trace() - eMe) / 2}
    return {alpha: sol[al].xreplace(vals), beta: sol[be].xreplace(vals),
            "derived": sp.Matrix([sol[al], sol[be]])}


def _generic_model() -> dict:
    model = displacement_model()
    model.update(screw_system_model(model))
    return model


# --------------------------------------------------------------------------- declarations
@equation("3.8", "The closest point of the screw axis is normal to e", section="3.2.1",
          latex=r"\mathbf{e}^T \mathbf{p}_0 = 0")
def closest_point_normal_to_axis() -> Statement:
    """``e^T p0 = 0`` for ``p0`` the point of the screw axis closest to the origin.

    Book: Sec. 3.2.1, Eq. (3.8). Shapes: 1 x 1; metres.
    """
    return Statement([Rel(e.T * p_0, sp.ZeroMatrix(1, 1))], screw_displacement_model())


@equation("3.9a", "Displacement of the axis point P0", section="3.2.1",
          latex=r"\mathbf{d}_0 = \mathbf{d}_A + (\mathbf{Q} - \mathbf{1})(\mathbf{p}_0 - "
                r"\mathbf{a})")
def axis_point_displacement() -> Statement:
    """``d_0 = d_A + (Q - 1)(p0 - a)``: Eq. (3.4) at ``P0``; the text's ``(Q - 1) d_0 = 0``
    (the displacement of ``P0`` is parallel to the axis) is checked as a claim.

    Book: Sec. 3.2.1, Eq. (3.9a). Shapes: 3 x 1; metres.
    """
    return Statement([Rel(d0_vec, d_A + (Q - I3) * (p_0 - a))], screw_displacement_model(),
                     claims=[Rel((Q - I3) * d0_vec, sp.ZeroMatrix(3, 1),
                                 "(Q - 1) d_0 = 0: d_0 parallel to e")])


@equation("3.9b", "Singular system for the axis point", section="3.2.1",
          latex=r"(\mathbf{Q} - \mathbf{1})\mathbf{p}_0 = (\mathbf{Q} - \mathbf{1})\mathbf{a} "
                r"- (\mathbf{1} - \mathbf{e}\mathbf{e}^T)\mathbf{d}_A",
          singular="Q - 1 is singular for every phi; rank 2 when phi != 0")
def axis_point_system() -> Statement:
    """``(Q - 1) p0 = (Q - 1) a - (1 - e e^T) d_A``, plus the text's claim that ``Q - 1`` is
    singular with null space spanned by ``e``: ``det(Q - 1) = 0``, ``(Q - 1) e = 0`` and
    ``det(Q - 1 + e e^T) = 2 (1 - cos phi)``, non-zero for ``phi != 0`` (so rank 2).

    Book: Sec. 3.2.1, Eq. (3.9b). Shapes: 3 x 1; metres.
    """
    return Statement(
        [Rel((Q - I3) * p_0, (Q - I3) * a - (I3 - e * e.T) * d_A)],
        screw_displacement_model(),
        claims=[Rel(Det(Q - I3), 0, "Q - 1 singular"),
                Rel((Q - I3) * e, sp.ZeroMatrix(3, 1), "e spans the null space"),
                Rel(Det(Q - I3 + e * e.T), 2 * (1 - sp.cos(phi)),
                    "rank 2 for phi != 0")])


@equation("3.10", "Overdetermined system for the axis point", section="3.2.1",
          latex=r"\mathbf{A}\mathbf{p}_0 = \mathbf{b}")
def axis_point_overdetermined() -> Statement:
    """``A p0 = b`` with ``A`` (4 x 3), ``b`` (4 x 1) of Eq. (3.11).

    Book: Sec. 3.2.1, Eq. (3.10). Units: metres.
    """
    return Statement([Rel(A_screw * p_0, b_screw)], screw_displacement_model())


@equation("3.11", "The 4 x 3 system A, b", section="3.2.1", kind="definition",
          latex=r"\mathbf{A} \equiv \begin{bmatrix} \mathbf{Q} - \mathbf{1} \\ \mathbf{e}^T "
                r"\end{bmatrix}, \quad \mathbf{b} \equiv \begin{bmatrix} (\mathbf{Q} - "
                r"\mathbf{1})\mathbf{a} - (\mathbf{1} - \mathbf{e}\mathbf{e}^T)\mathbf{d}_A "
                r"\\ 0 \end{bmatrix}")
def screw_system() -> Statement:
    """``A = [Q - 1; e^T]`` (4 x 3, dimensionless), ``b = [(Q - 1) a - (1 - e e^T) d_A; 0]``
    (4 x 1, metres).

    Book: Sec. 3.2.1, Eq. (3.11) (definition).
    """
    return Statement(
        [Rel(A_screw, sp.BlockMatrix([[Q - I3], [e.T]])),
         Rel(b_screw, sp.BlockMatrix([[(Q - I3) * a - (I3 - e * e.T) * d_A],
                                      [sp.ZeroMatrix(1, 1)]]))],
        _generic_model(), defines=("A_screw", "b_screw"))


@equation("3.12", "Normal equations for the axis point", section="3.2.1",
          latex=r"\mathbf{A}^T \mathbf{A}\mathbf{p}_0 = \mathbf{A}^T \mathbf{b}",
          singular="phi = 0 (A^T A singular)")
def axis_point_normal_equations() -> Statement:
    """``A^T A p0 = A^T b``; the text's claim that ``A^T A`` is invertible is checked as
    ``det(A^T A) = 4 (1 - cos phi)^2``, non-zero for ``phi != 0``.

    Book: Sec. 3.2.1, Eq. (3.12). Shapes: 3 x 1.
    """
    return Statement([Rel(A_screw.T * A_screw * p_0, A_screw.T * b_screw)],
                     screw_displacement_model(),
                     claims=[Rel(Det(A_screw.T * A_screw), 4 * (1 - sp.cos(phi))**2,
                                 "A^T A invertible for phi != 0")])


@equation("3.13", "A^T A in terms of e and phi", section="3.2.1",
          latex=r"\mathbf{A}^T \mathbf{A} = 2(1 - \cos \phi) \mathbf{1} - (1 - 2 \cos \phi) "
                r"\mathbf{e} \mathbf{e}^T")
def screw_system_gram() -> Statement:
    """``A^T A = 2 (1 - cos phi) 1 - (1 - 2 cos phi) e e^T`` (3 x 3, entry by entry).

    Book: Sec. 3.2.1, Eq. (3.13).
    """
    return Statement([Rel(A_screw.T * A_screw,
                          2 * (1 - sp.cos(phi)) * I3 - (1 - 2 * sp.cos(phi)) * e * e.T)],
                     _generic_model())


@equation("3.14", "(A^T A)^-1 is a combination of 1 and e e^T", section="3.2.1",
          latex=r"(\mathbf{A}^T \mathbf{A})^{-1} = \alpha \mathbf{1} + \beta \mathbf{e} "
                r"\mathbf{e}^T", singular="phi = 0")
def gram_inverse_form() -> Statement:
    """``(A^T A)^{-1} = alpha 1 + beta e e^T``: checked as ``A^T A (alpha 1 + beta e e^T)
    = 1`` entry by entry (for a square matrix this characterises the inverse), with
    ``alpha``, ``beta`` derived from ``A^T A`` (:func:`gram_inverse_coefficients_model`).

    Book: Sec. 3.2.1, Eq. (3.14). Shapes: 3 x 3, dimensionless.
    """
    model = _generic_model()
    model.update(gram_inverse_coefficients_model(model))
    derived = model.pop("derived")
    return Statement([Rel(A_screw.T * A_screw * (alpha * I3 + beta * e * e.T), I3,
                          "A^T A times alpha 1 + beta e e^T = 1")], model, derived=derived)


@equation("3.15", "Coefficients alpha and beta", section="3.2.1",
          latex=r"\alpha = \frac{1}{2(1 - \cos \phi)}, \quad \beta = \frac{1 - 2 \cos \phi}"
                r"{2(1 - \cos \phi)}", singular="phi = 0")
def gram_inverse_coefficients() -> Statement:
    """``alpha = 1 / (2 (1 - cos phi))``, ``beta = (1 - 2 cos phi) / (2 (1 - cos phi))``.

    Book: Sec. 3.2.1, Eq. (3.15).
    """
    model = _generic_model()
    model.update(gram_inverse_coefficients_model(model))
    derived = model.pop("derived")
    c = sp.cos(phi)
    return Statement([Rel(alpha, 1 / (2 * (1 - c)), "alpha"),
                      Rel(beta, (1 - 2 * c) / (2 * (1 - c)), "beta")], model, derived=derived)


@equation("3.16", "Inverse of A^T A", section="3.2.1",
          latex=r"(\mathbf{A}^T \mathbf{A})^{-1} = \frac{1}{2(1 - \cos \phi)} \mathbf{1} + "
                r"\frac{1 - 2 \cos \phi}{2(1 - \cos \phi)} \mathbf{e} \mathbf{e}^T",
          singular="phi = 0")
def gram_inverse() -> Statement:
    """``(A^T A)^{-1} = 1/(2(1 - cos phi)) 1 + (1 - 2 cos phi)/(2(1 - cos phi)) e e^T``.

    Checked twice, entry by entry: against the inverse derived by adjugate/determinant, and
    by ``A^T A`` times the printed inverse being ``1``.

    Book: Sec. 3.2.1, Eq. (3.16). Shapes: 3 x 3.
    """
    model = _generic_model()
    model.update(gram_inverse_model(model))
    c = sp.cos(phi)
    printed = 1 / (2 * (1 - c)) * I3 + (1 - 2 * c) / (2 * (1 - c)) * e * e.T
    return Statement([Rel(AtA_inv, printed, "inverse"),
                      Rel(A_screw.T * A_screw * printed, I3, "A^T A times printed = 1")],
                     model, derived=sp.Inverse(A_screw.T * A_screw))


@equation("3.17", "A^T b", section="3.2.1",
          latex=r"\mathbf{A}^T \mathbf{b} = (\mathbf{Q} - \mathbf{1})^T [(\mathbf{Q} - "
                r"\mathbf{1}) \mathbf{a} - \mathbf{d}_A]")
def screw_system_rhs() -> Statement:
    """``A^T b = (Q - 1)^T [(Q - 1) a - d_A]`` (the ``e e^T d_A`` term drops since
    ``(Q - 1)^T e = 0``). Book: Sec. 3.2.1, Eq. (3.17). Shapes: 3 x 1, metres.
    """
    return Statement([Rel(A_screw.T * b_screw, (Q - I3).T * ((Q - I3) * a - d_A))],
                     _generic_model())


@equation("3.18", "Point of the screw axis closest to the origin", section="3.2.1",
          latex=r"\mathbf{p}_0 = \frac{(\mathbf{Q} - \mathbf{1})^T (\mathbf{Q} \mathbf{a} - "
                r"\mathbf{a}')}{2(1 - \cos \phi)}, \quad \text{for } \phi \neq 0",
          singular="phi = 0")
def screw_axis_point_formula() -> Statement:
    """``p0 = (Q - 1)^T (Q a - a') / (2 (1 - cos phi))``, for ``phi != 0``.

    Checked against the model's ``p0``, the point closest to the origin of the axis of a
    displacement written about its own line (:func:`screw_displacement_model`: a rotation
    ``Q`` about the line through ``w`` along ``e`` and a slide ``d0`` along it, ``p0 = w -
    (e^T w) e`` by minimisation). Claims: the conditions that characterise ``p0`` for a
    generic displacement ``x -> Q x + c``, ``e^T p0 = 0`` (closest to the origin) and the
    displacement of ``p0``, ``a' + Q (p0 - a) - p0`` (Eqs. (3.2), (3.3)), parallel to ``e``
    (``(1 - e e^T)(a' + Q (p0 - a) - p0) = 0``), which for ``phi != 0`` determine ``p0``
    uniquely (the rank of ``Q - 1`` is 2, Eq. (3.9b)); :func:`screw_axis_point` against the
    printed form.

    Book: Sec. 3.2.1, Eq. (3.18). Shapes: 3 x 1; metres.
    """
    model = screw_displacement_model()
    printed = (Q - I3).T * (Q * a - a_p) / (2 * (1 - sp.cos(phi)))
    kernel = screw_axis_point(*(model[s] for s in (Q, a, a_p)), phi)
    return Statement([Rel(p_0, printed, "p0 as printed")], model, derived=kernel,
                     claims=[Rel(e.T * printed, sp.ZeroMatrix(1, 1), "e^T p0 = 0"),
                             Rel((I3 - e * e.T) * (a_p + Q * (printed - a) - printed),
                                 sp.ZeroMatrix(3, 1), "displacement of p0 parallel to e"),
                             Rel(printed, kernel, "screw_axis_point")])
