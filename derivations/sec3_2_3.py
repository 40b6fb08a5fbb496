"""Sec. 3.2.3: The pose of a rigid body, Eqs. (3.34)-(3.40).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.2.3.

First principles: the rotation invariants of Sec. 2.3 (Euler-Rodrigues parameters, linear
and natural invariants) from a unit ``e`` and an angle ``phi``; an orthonormal right-hand
triad attached at a body point ``A`` as the columns of a generic rotation ``R``; the
displacement ``x -> Q x + c``; and the representation of ``Q`` in the frame of that triad,
``[Q] = R^T Q R`` (change of basis, Sec. 2.2).
"""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import (
    Rel,
    Statement,
    equation,
    euler_rodrigues_parameters,
    linear_invariants,
    rotation,
    vector,
)

from .common import MS, Bk, Blocks, Cross, displacement_model, mat, vec

_im = sp.ImmutableMatrix
e, phi, d_A = Bk.e, Bk.phi, Bk.d_A
#: the pose array (3.34) and its rotation part: ``q``, ``q0`` are any four invariants
pose = MS("pose", 7, 1)
q = vec("q")
q_0 = sp.Symbol("q_0", real=True)
#: Euler-Rodrigues parameters and linear invariants (the two cases of (3.35))
r, u = vec("r"), vec("u")
r_0, u_0 = sp.Symbol("r_0", real=True), sp.Symbol("u_0", real=True)
#: the triad at A (3.37), the points P_i, and the displaced triad e'_i
a = vec("a")
p_i = [vec(f"p_{i}") for i in (1, 2, 3)]
e_i = [vec(f"e_{i}") for i in (1, 2, 3)]
e_i_prime = [vec(f"e_{i}_prime") for i in (1, 2, 3)]
Q_frame = mat("Q_F")
q_ij = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f"q_{i + 1}{j + 1}", real=True))


def invariants_model() -> dict:
    """``q, q0`` as Euler-Rodrigues parameters (the book's first example), ``r, r0`` and
    ``u, u0`` from Sec. 2.3; ``d_A`` of a generic displacement; the pose from (3.34)."""
    model = displacement_model()
    e_ = sp.Matrix(model[e])
    rr, rr0 = euler_rodrigues_parameters(e_, phi)
    uu, uu0 = linear_invariants(e_, phi)
    model.update({q: _im(rr), q_0: rr0, r: _im(rr), r_0: rr0, u: _im(uu), u_0: uu0})
    model[pose] = _im(sp.Matrix.vstack(rr, sp.Matrix([[rr0]]), sp.Matrix(model[d_A])))
    return model


def triad_model() -> dict:
    """An orthonormal right-hand triad ``e_i`` = columns of a generic rotation ``R``, body
    points ``P_i = A + e_i``; the displacement ``x -> Q x + c`` of
    :func:`derivations.common.displacement_model` gives ``e'_i = p'_i - a'``;
    ``[Q] = R^T Q R``."""
    R = rotation("s323_R")
    base = displacement_model()
    Qm, a_ = sp.Matrix(base[Bk.Q]), sp.Matrix(base[a])
    c = vector("c")  # the translation of that displacement
    model = {a: _im(a_), Q_frame: _im(R.T * Qm * R)}
    for i in range(3):
        pi = a_ + R[:, i]
        model[p_i[i]] = _im(pi)
        model[e_i[i]] = _im(pi - a_)
        model[e_i_prime[i]] = _im((Qm * pi + c) - (Qm * a_ + c))
    model.update({q_ij[i, j]: (R.T * Qm * R)[i, j] for i in range(3) for j in range(3)})
    return model


def _dots(left, right) -> sp.Matrix:
    """The 3 x 3 array of ``left_i . right_j`` (book symbols)."""
    return sp.Matrix(3, 3, lambda i, j: (left[i].T * right[j])[0, 0])


@equation("3.34", "Pose array", section="3.2.3", kind="definition",
          latex=r"\mathbf{s} \equiv \begin{bmatrix} \mathbf{q} \\ q_0 \\ \mathbf{d}_A "
                r"\end{bmatrix}")
def pose_array() -> Statement:
    """``s = [q; q0; d_A]`` (7 x 1): four rotation invariants and the displacement of a
    landmark point A (m).

    Book: Sec. 3.2.3, Eq. (3.34) (definition).
    """
    return Statement([Rel(pose, Blocks([[q], [q_0 * sp.Identity(1)], [d_A]]))],
                     invariants_model(), defines=("pose",))


@equation("3.35", "Constraint on Euler-Rodrigues parameters and linear invariants",
          section="3.2.3", latex=r"\|\mathbf{q}\|^2 + q_0^2 = 1")
def pose_invariants_constraint() -> Statement:
    """``||q||^2 + q0^2 = 1`` for the Euler-Rodrigues parameters and for the linear
    invariants (the book's "first two cases"), checked for each.

    Book: Sec. 3.2.3, Eq. (3.35).
    """
    printed = (q.T * q)[0, 0] + q_0**2
    return Statement([Rel(printed.xreplace({q: r, q_0: r_0}), 1, "Euler-Rodrigues"),
                      Rel(printed.xreplace({q: u, q_0: u_0}), 1, "linear invariants")],
                     invariants_model())


@equation("3.36", "Constraint on the natural invariants", section="3.2.3",
          latex=r"\|\mathbf{e}\|^2 = 1")
def pose_natural_constraint() -> Statement:
    """``||e||^2 = 1``. Book: Sec. 3.2.3, Eq. (3.36)."""
    return Statement([Rel((e.T * e)[0, 0], 1)], invariants_model())


@equation("3.37", "Triad attached at A", section="3.2.3", kind="definition",
          latex=r"\mathbf{e}_1 \equiv \overrightarrow{AP_1}, \quad \mathbf{e}_2 \equiv "
                r"\overrightarrow{AP_2}, \quad \mathbf{e}_3 \equiv \overrightarrow{AP_3}")
def pose_triad() -> Statement:
    """``e_i = p_i - a`` (the vector from A to P_i), i = 1, 2, 3 (3 x 1, m).

    Book: Sec. 3.2.3, Eq. (3.37) (definition).
    """
    return Statement([Rel(e_i[i], p_i[i] - a) for i in range(3)], triad_model(),
                     defines=("e_1", "e_2", "e_3"))


@equation("3.38", "The triad is orthonormal and right-handed", section="3.2.3",
          kind="definition",
          latex=r"\mathbf{e}_i \cdot \mathbf{e}_j = \delta_{ij}, \quad i, j = 1, 2, 3, \quad "
                r"\mathbf{e}_3 = \mathbf{e}_1 \times \mathbf{e}_2")
def pose_triad_orthonormal() -> Statement:
    """``e_i . e_j = delta_ij`` (all nine, entry by entry) and ``e_3 = e_1 x e_2``: the
    conditions the book imposes on the triad ("define three points ... in such a way that
    the three vectors ... are orthonormal and form a right-hand system"), so a definition,
    not an identity: the model's triad is the columns of a rotation, whose hypotheses are
    the first relation itself. The second is also derived, as a claim: e_3 = e_1 x e_2 from
    orthonormal columns and det = 1 (the certificate's cofactors use e_1 . e_3, e_2 . e_3,
    |e_3|^2 - 1 and det - 1, never e_3 - e_1 x e_2).

    Book: Sec. 3.2.3, Eq. (3.38) (definition: a condition of the construction).
    """
    return Statement([Rel(_dots(e_i, e_i), sp.eye(3), "e_i . e_j = delta_ij"),
                      Rel(e_i[2], Cross(e_i[0], e_i[1]), "e_3 = e_1 x e_2")], triad_model(),
                     defines=("e_1", "e_2", "e_3"),
                     claims=[Rel(e_i[2], Cross(e_i[0], e_i[1]),
                                 "e_3 = e_1 x e_2, from orthonormal columns and det = 1")])


@equation("3.39", "Entries of Q in the frame of the triad", section="3.2.3",
          latex=r"q_{ij} = \mathbf{e}_i \cdot \mathbf{e}'_j")
def rotation_entries_from_triads() -> Statement:
    """``q_ij = e_i . e'_j`` for the nine entries of ``[Q]`` in the triad's frame.

    Book: Sec. 3.2.3, Eq. (3.39).
    """
    return Statement([Rel(q_ij, _dots(e_i, e_i_prime))], triad_model())


@equation("3.40", "Matrix of Q from two triads", section="3.2.3",
          latex=r"[\mathbf{Q}] = \begin{bmatrix} \mathbf{e}_1 \cdot \mathbf{e}'_1 & "
                r"\mathbf{e}_1 \cdot \mathbf{e}'_2 & \mathbf{e}_1 \cdot \mathbf{e}'_3 \\ "
                r"\mathbf{e}_2 \cdot \mathbf{e}'_1 & \mathbf{e}_2 \cdot \mathbf{e}'_2 & "
                r"\mathbf{e}_2 \cdot \mathbf{e}'_3 \\ \mathbf{e}_3 \cdot \mathbf{e}'_1 & "
                r"\mathbf{e}_3 \cdot \mathbf{e}'_2 & \mathbf{e}_3 \cdot \mathbf{e}'_3 "
                r"\end{bmatrix}")
def rotation_matrix_from_triads() -> Statement:
    """``[Q] = [e_i . e'_j]`` (3 x 3, entry by entry), all vectors in one frame.

    Book: Sec. 3.2.3, Eq. (3.40).
    """
    return Statement([Rel(Q_frame, _dots(e_i, e_i_prime))], triad_model())
