"""Exercise 3.14: two centroidal inertia measurements compared by their invariants.

Exact data: the characteristic polynomials (trace, second invariant, determinant) must
agree exactly; the rotation between the observers' frames maps the eigenvectors of
``[I]_A`` onto those of ``[I]_B`` (exact when the principal moments are rational). Float
data are measurements: the principal moments are compared within ``tol`` and the rotation
is the least-squares one, ``min ||Q [I]_A Q^T - [I]_B||``, made exact (:mod:`._fit`).
"""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Param, Solution, exact_check, is_zero, truth_check

from ._fit import accepting_tol, exact_rotation, is_local_minimum, sorted_eigh

ID = "ex3.14"
TITLE = "Two observers of one inertia matrix"
STATEMENT = ("\"The centroidal inertia matrix of a rigid body is measured by two observers ... "
             "Show that the two measurements are acceptable.\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.14"
#: the documented unit of each answer with one (graded answers may be written in any
#: compatible unit); the others are pure numbers or mixed
ANSWER_UNITS = {"principal_moments": "kg m^2"}
#: what the rotation box is: any rotation Q with Q [I]_A Q^T = [I]_B (four when the
#: principal moments are distinct: a principal axis has no sense)
ANSWER_CLASSES = ({"kind": "rotation onto", "name": "Q_B_A", "from": "I_A", "to": "I_B"},)
MEASURED = True
PARAMETERS = (
    Param("I_A", sp.ImmutableMatrix(sp.diag(1, 2, 3)), (3, 3),
          "centroidal inertia matrix reported by observer A, in A's frame", "kg m^2"),
    Param("I_B", sp.ImmutableMatrix([[6, 2, 2], [2, 5, 0], [2, 0, 7]]) / 3, (3, 3),
          "the same body's centroidal inertia matrix reported by observer B", "kg m^2"),
)
VARIANTS = (
    ("noisy float measurements (tol)", {"I_B": [[2.0, 0.667, 0.666], [0.667, 1.667, 0.0],
                                                [0.666, 0.0, 2.333]]}),
    ("different bodies (ill-posed)", {"I_B": [[1, 0, 0], [0, 2, 0], [0, 0, 4]]}),
)
_LAM = sp.Symbol("lambda")
_INV = ("tr I", "the second invariant", "det I")


def _invariants(I) -> sp.Matrix:
    return sp.Matrix([I.trace(), (I.trace()**2 - (I * I).trace()) / 2, I.det()])


def principal_moments(I) -> list:
    """The three principal moments, ascending, exact (rationals, radicals or CRootOf)."""
    return sp.Poly(I.charpoly(_LAM).as_expr(), _LAM).real_roots()


def _admissible(s: Solution, name: str, lam, slack=0) -> None:
    if not all(bool(x > 0) for x in lam):
        s.fail(f"{name} is not an inertia matrix: its principal moments {_show(lam)} are not "
               f"all positive.")
    if bool(lam[0] + lam[1] < lam[2] - slack):
        s.fail(f"{name} is not an inertia matrix: its principal moments {_show(lam)} violate "
               f"the triangle inequality I_1 + I_2 >= I_3.")


def _show(lam) -> str:
    return ", ".join(str(x) if x.is_Rational else f"{float(x):.4g}" for x in lam)


def solve(I_A=PARAMETERS[0].default, I_B=PARAMETERS[1].default, tol=None) -> Solution:
    """Worked solution of Exercise 3.14 (3 x 3 inertia matrices in kg m^2)."""
    IA, IB = sp.Matrix(I_A), sp.Matrix(I_B)
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"[I]_A": IA, "[I]_B": IB},
        assumptions=["'Acceptable' = same tensor in two frames (equal invariants: trace, "
                     "second invariant, determinant) and physically admissible (symmetric, "
                     "positive definite, triangle inequalities I_i + I_j >= I_k)."])
    for name, I in (("[I]_A", IA), ("[I]_B", IB)):
        asym = I - I.T
        if tol is None and not is_zero(asym) or tol is not None and any(
                bool(abs(x) > tol) for x in asym):
            s.fail(f"{name} is not symmetric, so it is not an inertia matrix.")
    if tol is not None:
        IA, IB = (IA + IA.T) / 2, (IB + IB.T) / 2
    inv = s.step("invariants of I_A", _invariants(IA),
                 "Coefficients of the characteristic polynomial are frame-invariant.")
    invB = s.step("invariants of I_B", _invariants(IB), "The same three numbers."
                  if tol is None else "Compared through the principal moments, within tol.")
    if tol is None:
        for k, name in enumerate(_INV):
            if not is_zero(inv[k] - invB[k]):
                gap = max(abs(float(a) - float(b)) for a, b in
                          zip(principal_moments(IA), principal_moments(IB), strict=True))
                s.fail(f"The measurements are not acceptable: {name} is {inv[k]} for A but "
                       f"{invB[k]} for B, and a change of frame preserves it"
                       f"{accepting_tol(gap)}.")
        return _exact(s, IA, IB, inv)
    return _measured(s, IA, IB, inv, tol)


def _exact(s: Solution, IA, IB, inv) -> Solution:
    lam = principal_moments(IB)
    ev = s.step("principal moments", sp.Matrix(lam),
                "Roots of the common characteristic polynomial.")
    _admissible(s, "[I]_B", lam)
    if all(x.is_Rational for x in lam):
        VA, VB = _eigenbasis(IA, lam), _eigenbasis(IB, lam)
        Q = s.step("rotation B <- A", (VB * VA.T).applyfunc(sp.radsimp),
                   "Unit eigenvectors (columns V_A, V_B, in the order of the moments): "
                   "[I]_B = Q [I]_A Q^T with Q = V_B V_A^T.")
        exact = True
    else:
        Q = _rounded_rotation(s, IA, IB)
        exact = False
    s.answers = {"invariants": inv, "principal_moments": ev, "Q_B_A": Q, "acceptable": sp.true,
                 "Q_B_A_is_one_of": _family(lam)}
    s.check(truth_check("invariants equal (exact)", inv == _invariants(IB), f"{list(inv)}"))
    s.check(exact_check("Q proper orthogonal" + (" and Q [I]_A Q^T = [I]_B" if exact else ""),
                        [Q.T * Q - sp.eye(3), Q.det() - 1] + ([Q * IA * Q.T - IB] if exact
                                                               else [])))
    _admissible_check(s, lam)
    return s


def _family(lam) -> str:
    """Which rotations map [I]_A onto [I]_B besides the one given: a principal axis has no
    sense, and equal moments leave their plane's axes free."""
    ties = sum(is_zero(lam[i] - lam[j]) for i, j in ((0, 1), (1, 2), (0, 2)))
    distinct = 3 if ties == 0 else 1 if ties == 3 else 2
    if distinct == 3:
        return ("four rotations: Q D_A with D_A = V_A D V_A^T, D = diag(1, 1, 1), "
                "diag(1, -1, -1), diag(-1, 1, -1) or diag(-1, -1, 1) (a principal axis has "
                "no sense)")
    if distinct == 2:
        return ("infinitely many: Q times any turn about the principal axis of the simple "
                "moment (the two equal moments leave their plane's axes free), and the half "
                "turns about the axes of that plane")
    return "every rotation: [I]_A = [I]_B = I 1 (all moments equal)"


def _eigenbasis(I, lam) -> sp.Matrix:
    """Orthonormal eigenvectors for the (rational) moments ``lam``, a proper rotation."""
    cols = []
    for x in sorted(set(lam)):
        cols += sp.GramSchmidt((I - x * sp.eye(3)).nullspace(), orthonormal=True)
    V = sp.Matrix.hstack(*cols).applyfunc(sp.radsimp)
    if V.det() < 0:
        V[:, 2] = -V[:, 2]
    return V


def _rounded_rotation(s: Solution, IA, IB) -> sp.Matrix:
    (_, VA), (_, VB) = sorted_eigh(IA), sorted_eigh(IB)
    return s.step("rotation B <- A (least squares)", exact_rotation(VB @ VA.T),
                  "Unit eigenvectors in the order of the moments, V_B V_A^T, computed in "
                  "floating point and rounded to an exact rotation (Cayley transform).")


def _measured(s: Solution, IA, IB, inv, tol) -> Solution:
    lamA, lamB = principal_moments(IA), principal_moments(IB)
    gaps = s.step("principal-moment gaps", sp.Matrix([sp.Abs(a - b) for a, b in
                                                      zip(lamA, lamB, strict=True)]),
                  "The sorted principal moments are the invariants, in kg m^2.")
    for k, g in enumerate(gaps):
        if bool(g > tol):
            s.fail(f"The measurements are not acceptable within tol = {float(tol):.3g}: the "
                   f"principal moment I_{k + 1} differs by {float(g):.3g} between A and B"
                   f"{accepting_tol(max(gaps, key=float))}.")
    _admissible(s, "[I]_B", lamB, slack=tol)
    Q = _rounded_rotation(s, IA, IB)

    def misfit(R):
        D = R * IA * R.T - IB
        return (D.T * D).trace()

    res = s.step("residual", sp.Float(sp.sqrt(misfit(Q)).evalf(20), 4),
                 "||Q [I]_A Q^T - [I]_B||_F, to 4 digits.")
    s.answers = {"invariants": inv, "principal_moments": sp.Matrix(lamB), "Q_B_A": Q,
                 "acceptable": sp.true, "residual": res}
    s.check(exact_check("Q proper orthogonal (exact rationals)", [Q.T * Q - sp.eye(3),
                                                                  Q.det() - 1]))
    s.check(truth_check(f"principal moments agree within tol = {float(tol):.3g}",
                        all(bool(g <= tol) for g in gaps), "exact comparison of closed numbers"))
    s.check(truth_check("Q is a least-squares minimum: turning it by 2e-4 rad about any of "
                        "+-x, +-y, +-z does not lower the misfit", is_local_minimum(Q, misfit),
                        "six exact rational rotations, misfits compared in Q"))
    _admissible_check(s, lamB, tol)
    return s


def _admissible_check(s: Solution, lam, slack=0) -> None:
    s.check(truth_check("admissible: positive definite, I1 + I2 >= I3",
                        all(bool(x > 0) for x in lam) and bool(lam[0] + lam[1] >= lam[2] - slack),
                        "equality (1 + 2 = 3 for the book's data) is the limiting case, a body "
                        "with all its mass in one plane" if bool(lam[0] + lam[1] == lam[2])
                        else "exact comparison of the principal moments"))


def random_data(rng) -> dict:
    """A well-posed variant with readable exact numbers (an exam's draw): distinct integer
    principal moments obeying the strict triangle inequality, seen by A and by B in two
    frames turned by Cayley rotations with entries of denominator 3 (so the matrices have
    entries of denominator 9), the two matrices distinct."""
    from ._random import cayley_small

    while True:
        lam = sorted(rng.sample(range(2, 10), 3))
        if lam[2] < lam[0] + lam[1]:
            break
    D = sp.diag(*lam)
    QA = cayley_small(rng, halves=False)
    while True:              # two observers in two frames: the reports differ
        QB = cayley_small(rng, halves=False)
        if QB * D * QB.T != QA * D * QA.T:
            break
    return {"I_A": (QA * D * QA.T).tolist(), "I_B": (QB * D * QB.T).tolist()}
