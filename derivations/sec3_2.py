"""Sec. 3.2: General rigid-body motion and its associated screw, Eqs. (3.1)-(3.7).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.2.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import Rel, Statement, equation, scalar

from .common import I3, Bk, Det, displacement_model, vec
from .sec3_2_1 import pitch_of_displacement, screw_axis_point

Q, e, phi, a, a_p, p, p_p, d_A, d_P = (Bk.Q, Bk.e, Bk.phi, Bk.a, Bk.a_prime, Bk.p,
                                       Bk.p_prime, Bk.d_A, Bk.d_P)
#: the axial displacement d_0 (scalar, 3.5), the parts of d_P along and normal to e (3.6),
#: bold d_0 = d_0 e (3.6b), the pitch in m/rad and in m/turn (3.7)
d_0 = sp.Symbol("d_0", real=True)
d_par, d_perp, d0_vec = vec("d_par"), vec("d_perp"), vec("d0_vec")
pitch = sp.Symbol("pitch", real=True)
pitch_turn = sp.Symbol("pitch_turn", real=True)
_im = sp.ImmutableMatrix


def split_model() -> dict:
    """The displacement model plus ``d_0 = e^T d_A`` (3.5) and the split of ``d_P`` along
    and normal to ``e`` (Eq. (2.6a/b)): ``d_par = e e^T d_P``, ``d_perp = (1 - e e^T) d_P``.
    """
    model = displacement_model()
    e_, dA, dP = (sp.Matrix(model[s]) for s in (e, d_A, d_P))
    model.update({d_0: (e_.T * dA)[0, 0], d_par: _im(e_ * e_.T * dP),
                  d_perp: _im((sp.eye(3) - e_ * e_.T) * dP),
                  d0_vec: _im((e_.T * dA)[0, 0] * e_)})
    return model


@equation("3.1", "Relative position is rotated by Q", section="3.2",
          latex=r"\mathbf{p}' - \mathbf{a}' = \mathbf{Q}(\mathbf{p} - \mathbf{a})")
def relative_position_rotated() -> Statement:
    """``p' - a' = Q (p - a)``: the vector between two body points turns with the body.

    Book: Sec. 3.2, Eq. (3.1). Shapes: 3-vectors, metres.
    """
    return Statement([Rel(p_p - a_p, Q * (p - a))], displacement_model())


@equation("3.2", "Displaced position of a body point", section="3.2",
          latex=r"\mathbf{p}' = \mathbf{a}' + \mathbf{Q}(\mathbf{p} - \mathbf{a})")
def displaced_point() -> Statement:
    """``p' = a' + Q (p - a)``. Book: Sec. 3.2, Eq. (3.2)."""
    return Statement([Rel(p_p, a_p + Q * (p - a))], displacement_model())


@equation("3.3", "Displacements of A and P", section="3.2", kind="definition",
          latex=r"\mathbf{d}_A \equiv \mathbf{a}' - \mathbf{a}, \quad \mathbf{d}_P \equiv "
                r"\mathbf{p}' - \mathbf{p}")
def displacements() -> Statement:
    """``d_A = a' - a``, ``d_P = p' - p``. Book: Sec. 3.2, Eq. (3.3) (definition)."""
    return Statement([Rel(d_A, a_p - a), Rel(d_P, p_p - p)], displacement_model(),
                     defines=("d_A", "d_P"))


@equation("thm3.2.1", "All points share the displacement component along e", section="3.2",
          kind="claim",
          latex=r"the displacements of all the points of  $\mathcal{B}$  have the same "
                r"component along  $\mathbf{e}$")
def same_axial_displacement() -> Statement:
    """Theorem 3.2.1: ``e^T d_P = e^T d_A`` for every pair of body points (generic A, P).

    Book: Sec. 3.2, Theorem 3.2.1.
    """
    return Statement([Rel(e.T * d_P, e.T * d_A)], displacement_model())


@equation("3.4", "Displacement of P from that of A", section="3.2",
          latex=r"\begin{aligned} \mathbf{d}_P &= \mathbf{a}' - \mathbf{p} + "
                r"\mathbf{Q}(\mathbf{p} - \mathbf{a}) \\ &= \mathbf{a}' - \mathbf{a} - "
                r"\mathbf{p} + \mathbf{Q}(\mathbf{p} - \mathbf{a}) + \mathbf{a} \\ &= "
                r"\mathbf{d}_A + \underbrace{(\mathbf{Q} - \mathbf{1})(\mathbf{p} - "
                r"\mathbf{a})}_{\mathbf{d}_{P/A}} \end{aligned}")
def displacement_from_reference_point() -> Statement:
    """``d_P = a' - p + Q (p - a) = a' - a - p + Q (p - a) + a = d_A + (Q - 1)(p - a)``;
    the last term is the relative displacement ``d_{P/A}``, caused by the rotation alone.

    Book: Sec. 3.2, Eq. (3.4). Shapes: 3-vectors, metres. Checked member by member.
    """
    return Statement([Rel(d_P, a_p - p + Q * (p - a), "first member"),
                      Rel(d_P, a_p - a - p + Q * (p - a) + a, "second member"),
                      Rel(d_P, d_A + (Q - I3) * (p - a), "third member")],
                     displacement_model())


@equation("3.5", "Common axial displacement d_0", section="3.2", kind="definition",
          latex=r"\mathbf{e}^T \mathbf{d}_P = \mathbf{e}^T \mathbf{d}_A \equiv d_0")
def axial_displacement() -> Statement:
    """``e^T d_P = e^T d_A = d_0``: defines ``d_0`` (m), and the equality of the first two
    members (Theorem 3.2.1) is checked for a generic pair of points.

    Book: Sec. 3.2, Eq. (3.5).
    """
    return Statement([Rel(d_0, (e.T * d_A)[0, 0])], split_model(), defines=("d_0",),
                     claims=[Rel(e.T * d_P, e.T * d_A, "e^T d_P = e^T d_A", page=1)])


@equation("3.6a", "Split of d_P along and normal to e", section="3.2",
          latex=r"\mathbf{d}_P = \mathbf{d}_{\parallel} + \mathbf{d}_{\perp}")
def displacement_split() -> Statement:
    """``d_P = d_par + d_perp`` with the parts of Eq. (3.6b). Book: Sec. 3.2, Eq. (3.6a)."""
    return Statement([Rel(d_P, d_par + d_perp)], split_model())


@equation("3.6b", "Parallel and normal parts of d_P", section="3.2", kind="definition",
          latex=r"\mathbf{d}_{\parallel} = \mathbf{e}\mathbf{e}^T \mathbf{d}_P = d_0 "
                r"\mathbf{e} \equiv \mathbf{d}_0, \quad \mathbf{d}_{\perp} = (\mathbf{1} - "
                r"\mathbf{e}\mathbf{e}^T) \mathbf{d}_P")
def displacement_parts() -> Statement:
    """``d_par = e e^T d_P = d_0 e = bold d_0``, ``d_perp = (1 - e e^T) d_P``.

    Defines ``d_par``, ``d_perp`` and bold ``d_0``; the middle member ``e e^T d_P = d_0 e``
    (``d_par`` is the same for every point) and the orthogonality ``d_par . d_perp = 0``
    stated after the equation are checked.

    Book: Sec. 3.2, Eq. (3.6b). Shapes: 3 x 1, metres.
    """
    return Statement(
        [Rel(d_par, e * e.T * d_P), Rel(d0_vec, d_0 * e), Rel(d_perp, (I3 - e * e.T) * d_P)],
        split_model(), defines=("d_par", "d_perp", "d0_vec"),
        claims=[Rel(e * e.T * d_P, d_0 * e, "e e^T d_P = d_0 e", page=2),
                Rel(d_par.T * d_perp, sp.ZeroMatrix(1, 1), "d_par . d_perp = 0")])


@equation("3.7", "Pitch of the screw of a displacement", section="3.2", kind="definition",
          latex=r"p \equiv \frac{d_0}{\phi} = \frac{\mathbf{d}_P^T \mathbf{e}}{\phi} "
                r"\quad \text{or} \quad p \equiv \frac{2\pi d_0}{\phi}",
          singular="phi = 0")
def displacement_pitch() -> Statement:
    """``p = d_0 / phi = d_P^T e / phi`` (m/rad) or ``p = 2 pi d_0 / phi`` (m/turn).

    Defines the pitch in m/rad and, as a second quantity, the pitch in m/turn; the second
    member ``d_P^T e / phi`` must equal the first (checked for a generic point P), and
    :func:`pitch_of_displacement` must give the m/rad pitch.

    Book: Sec. 3.2, Eq. (3.7). Singular set: ``phi = 0`` (pure translation).
    """
    model = split_model()
    model[pitch] = model[d_0] / phi
    model[pitch_turn] = 2 * sp.pi * model[d_0] / phi
    kernel = pitch_of_displacement(model[e], model[d_A], phi)
    return Statement([Rel(pitch, d_0 / phi, "p in m/rad"),
                      Rel(pitch_turn, 2 * sp.pi * d_0 / phi, "p in m/turn")], model,
                     defines=("pitch", "pitch_turn"),
                     claims=[Rel(pitch, (d_P.T * e)[0, 0] / phi, "second member", page=2),
                             Rel(pitch, kernel, "pitch_of_displacement")])


@equation("thm3.2.2", "Mozzi-Chasles: minimum displacements lie on a line parallel to e",
          section="3.2", kind="claim",
          latex=r"a set of its points, located on a line  $\mathcal{L}$ , undergo identical "
                r"displacements of minimum magnitude", singular="phi = 0")
def mozzi_chasles() -> Statement:
    """Theorem 3.2.2 (Mozzi-Chasles), for a generic displacement ``x -> Q x + c``, ``phi != 0``:

    1. ``||d_P||^2 = d_0^2 + ||d_perp||^2`` for every P: the minimum magnitude is ``|d_0|``,
       reached exactly where ``d_perp = 0``;
    2. ``P*`` of Eq. (3.18) reaches it: ``(1 - e e^T) d_{P*} = 0``;
    3. every point ``p* + lambda e`` of the line L through ``P*`` parallel to ``e`` has the
       same displacement ``d_0 e`` (identical, parallel to the axis);
    4. ``d_perp(P) = (Q - 1)(p - p*)`` for every P, and ``Q - 1 + e e^T`` has determinant
       ``2 (1 - cos phi) != 0``, so the null space of ``Q - 1`` is spanned by ``e`` and the
       minimisers are exactly the points of L.

    Book: Sec. 3.2, Theorem 3.2.2, stated in words only: the four points above are claims
    (the relations of the proof that decide the words), none a printed relation.
    """
    model = split_model()
    p_star = vec("p_star")
    model[p_star] = _im(screw_axis_point(*(model[s] for s in (Q, a, a_p)), phi))
    lam = scalar("lambda_mc")

    def disp(x):
        """Displacement of the body point at ``x``: ``a' + Q (x - a) - x`` (3.2), (3.3)."""
        return a_p + Q * (x - a) - x

    return Statement([], model, derived=model[p_star], claims=[  # the page prints none
        Rel(d_P.T * d_P, d_0**2 * sp.Identity(1) + d_perp.T * d_perp,
            "||d_P||^2 = d_0^2 + ||d_perp||^2"),
        Rel((I3 - e * e.T) * disp(p_star), sp.ZeroMatrix(3, 1), "P* has minimum displacement"),
        Rel(disp(p_star + lam * e), d_0 * e, "points of L: identical, parallel to e"),
        Rel(d_perp, (Q - I3) * (p - p_star), "d_perp = (Q - 1)(p - p*)"),
        Rel(Det(Q - I3 + e * e.T), 2 * (1 - sp.cos(phi)), "null space of Q - 1 is span(e)")])
