"""Sec. 3.2: General rigid-body motion and its associated screw, Eqs. (3.1)-(3.7).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.2.
"""

from __future__ import annotations

from rigidsym.registry import Rel, Statement, equation

from .common import Bk, displacement_model

Q, e, phi, a, a_p, p, p_p, d_A, d_P = (Bk.Q, Bk.e, Bk.phi, Bk.a, Bk.a_prime, Bk.p,
                                       Bk.p_prime, Bk.d_A, Bk.d_P)


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



