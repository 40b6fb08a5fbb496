"""Exercise 3.20: the inertia dyad at a point A (Eq. 3.147), positive definiteness, and R."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Solution, identity_check, nonidentity_check
from rigidsym.declare import block, cpm, scalar, symmetric_matrix, vector

from ..sec3_4_2 import twist_transfer_matrix
from ._inertia import inertia_at_point, inertia_dyad

ID = "ex3.20"
TITLE = "Steiner's theorem in 6 x 6 form"
STATEMENT = ("\"Derive Eq. (3.147). Moreover, show that M_A ... is positive-definite ... Can this "
             "matrix [R, with P = m R R^T] be found? If yes, give an expression for R; if not, "
             "explain why.\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.20; Eqs. (3.133a), (3.147), (3.148)"


def solve() -> Solution:
    """Worked solution of Exercise 3.20."""
    J, m = symmetric_matrix("J"), scalar("m")
    a, c, u = vector("a"), vector("c"), vector("u")
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"I_C": J, "m": m, "a": a, "c": c},
        assumptions=["M_A is defined by the kinetic energy T = t_A^T M_A t_A / 2 with "
                     "t_A = [omega; a_dot] (the twist at A).",
                     "The hint M_A = M_C + P P^T (and the erratum's M_C + m P P^T) asks for a "
                     "positive-semidefinite difference; it is shown indefinite unless a = c, "
                     "so no real P (or R) exists; M_A = U^T M_C U is the correct 6 x 6 form."])
    U = twist_transfer_matrix(a, c)
    s.step("twist transfer", "t_C = U t_A,  U = [[1, O], [A - C, 1]]",
           "Eq. (3.83b): c_dot = a_dot + omega x (c - a) = a_dot + (A - C) omega, with "
           "A = CPM(a), C = CPM(c); omega is the same at every point.")
    M = inertia_dyad(J, m)
    MA = U.T * M * U
    s.step("dyad at A", "M_A = U^T M_C U,  M_C = [[I_C, O], [O, m 1]]",
           "T = t_C^T M_C t_C / 2 = t_A^T (U^T M_C U) t_A / 2 for every t_A.")
    C, A = cpm(c), cpm(a)
    I_A = inertia_at_point(J, m, a, c)
    printed = block([[I_A, m * (C - A)], [m * (C - A).T, m * sp.eye(3)]])
    s.step("(3.147) block by block",
           "U^T M_C U = [[1, (A - C)^T], [O, 1]] [[I_C, O], [m (A - C), m 1]]\n"
           "          = [[I_C + m (A - C)^T (A - C), m (A - C)^T], [m (A - C), m 1]]\n"
           "          = [[I_A, m (C - A)], [m (C - A)^T, m 1]]",
           "A - C is skew: (A - C)^T = C - A, so the first block is I_C - m (C - A)^2 = I_A "
           "(Eq. 3.133b), which is Eq. (3.147).")
    s.step("positive definite", "x^T M_A x = (U x)^T M_C (U x) > 0 for x != 0",
           "M_C is positive definite (I_C > 0, m > 0) and U is invertible (det U = 1).")
    D = MA - M
    B = C - A
    x = sp.Matrix.vstack(u, -B.T * u)
    qf = (x.T * D * x)[0]
    s.step("the hint's difference",
           "M_A - M_C = [[m B B^T, m B], [m B^T, O]],  B = C - A\n"
           "x = [u; -B^T u]:  x^T (M_A - M_C) x = m ||B^T u||^2 - 2 m ||B^T u||^2 "
           "= -m ||B^T u||^2",
           "Negative for a u with B^T u != 0 (B != O when a != c), while [u; 0] gives "
           "m ||B^T u||^2 > 0: M_A - M_C is indefinite.")
    s.answers = {"M_A": "U^T M_C U = [[I_A, m(C - A)], [m(C - A)^T, m 1]] (3.147 holds)",
                 "positive_definite": sp.true,
                 "P_with_M_A_eq_M_C_plus_PPT_exists": sp.false,
                 "R_exists": sp.false,
                 "why": "M_A - M_C = [[m B B^T, m B], [m B^T, O]] (B = C - A) has a zero "
                        "diagonal block beside a non-zero off-diagonal block, so it is "
                        "indefinite; P P^T and m R R^T are positive semidefinite."}
    s.check(identity_check("U^T M_C U equals the printed (3.147)", [MA - printed]))
    s.check(identity_check("x^T (M_A - M_C) x + m ||(C - A)^T u||^2 = 0",
                           [qf + m * (B.T * u).dot(B.T * u)]))
    s.check(identity_check("Schur complement of m 1 in M_A is I_C (so M_A > 0 iff I_C > 0, "
                           "m > 0)", [I_A - m * B * B.T - J]))
    s.check(identity_check("M_A - M_C = [[m B B^T, m B], [m B^T, O]] with B = C - A",
                           [D - block([[m * B * B.T, m * B], [m * B.T, sp.zeros(3)]])]))
    s.check(nonidentity_check("M_A - M_C is not zero (a != c)", [D]))
    return s
