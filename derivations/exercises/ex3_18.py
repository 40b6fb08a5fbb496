"""Exercise 3.18: M_dot - 2 W M is skew-symmetric."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Solution, identity_check
from rigidsym.declare import TIME

from .ex3_17 import motion

ID = "ex3.18"
TITLE = "Skew-symmetry of M_dot - 2 W M"
STATEMENT = ("\"show that the difference M_dot - 2 W M is skew-symmetric, with M and W introduced "
             "in Sect. 3.8\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.18"


def solve() -> Solution:
    """Worked solution of Exercise 3.18."""
    Q, J, m, omega, M, W, t = motion()
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"M": "diag(Q J Q^T, m 1)", "W": "diag(Omega, O)"},
        assumptions=["Same setting as Exercise 3.17 (inertial-frame components)."])
    s.step("use Exercise 3.17", "M_dot - 2 W M = W M - M W - 2 W M = -(W M + M W)",
           "Substitute M_dot = W M - M W.")
    s.step("transpose", "(W M)^T = M^T W^T = -M W",
           "M is symmetric and W skew-symmetric.")
    s.step("conclusion", "-(W M + M W) = -(W M - (W M)^T)",
           "A matrix minus its transpose is skew-symmetric.")
    D = M.diff(TIME) - 2 * W * M
    s.answers = {"M_dot_minus_2WM_skew_symmetric": sp.true}
    s.check(identity_check("(M_dot - 2 W M) + (M_dot - 2 W M)^T = 0 (generic Q(t), J)",
                           [D + D.T]))
    s.check(identity_check("M_dot - 2 W M = -(W M + M W)", [D + W * M + M * W]))
    return s
