"""Least-squares rotations for measured data (Exercises 3.1, 3.4, 3.6, 3.14, 3.19), made exact.

The nearest rotation is found in floating point (orthogonal Procrustes: Kabsch's SVD
solution) and then rounded to an *exactly* proper-orthogonal rational matrix through the
Cayley transform ``Q = (1 + S)(1 - S)^-1``, ``S = CPM(s)`` with rational ``s``. The answer
is therefore a rotation exactly, within ~1e-6 rad of the float optimum (well inside a
measurement tolerance), and its optimality is checked in exact rationals by perturbing it
(:func:`is_local_minimum`), a test that does not reuse the SVD.

Sources: W. Kabsch, Acta Cryst. A32 (1976) 922 (with the determinant correction,
Acta Cryst. A34 (1978) 827); the Cayley transform, Angeles, Sec. 2.3.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import sympy as sp

from rigidsym.course.worked import Solution, truth_check
from rigidsym.declare import cpm

_FLIPS = [sp.diag(1, 1, 1), sp.diag(1, -1, -1), sp.diag(-1, 1, -1), sp.diag(-1, -1, 1)]


def accepting_tol(gap) -> str:
    """The words a refusal ends with: the smallest 2-digit tolerance that accepts a gap
    (``"tol = 0.0034 would accept them (--tol 0.0034)"``)."""
    import math

    x = float(gap)
    if not x > 0:
        return ""
    e = math.floor(math.log10(x)) - 1
    t = math.ceil(x / 10**e * (1 + 1e-12)) * 10**e
    return f"; tol = {t:.2g} would accept them (--tol {t:.2g})"


def cayley(s) -> sp.Matrix:
    """The rotation ``(1 + CPM(s))(1 - CPM(s))^-1`` of a 3-vector ``s`` (exact for rational s).

    Every proper rotation without a half turn has one; ``||s|| = tan(phi/2)``.
    """
    S = cpm(sp.Matrix(s))
    return (sp.eye(3) + S) * (sp.eye(3) - S).inv()


def nearest_rotation(M: np.ndarray) -> np.ndarray:
    """The rotation ``Q`` maximising ``tr(Q^T M)`` (Kabsch): ``U diag(1, 1, d) V^T``.

    Args:
        M: (3, 3) float array, e.g. ``sum_k x1_k x2_k^T`` for data with ``x1 ~ Q x2``.

    Returns:
        (3, 3) float proper-orthogonal array.
    """
    U, _, Vt = np.linalg.svd(M)
    d = np.sign(np.linalg.det(U @ Vt)) or 1.0
    return U @ np.diag([1.0, 1.0, d]) @ Vt


def _rational(x: float, max_den: int) -> sp.Rational:
    f = Fraction(float(x)).limit_denominator(max_den)
    return sp.Rational(f.numerator, f.denominator)


def exact_unit_vector(v: np.ndarray, max_den: int = 10**9) -> sp.Matrix:
    """A rational unit 3-vector (exactly ``e.e = 1``) within ~1/max_den of the direction of
    ``v``: the inverse stereographic projection of ``v``'s projection rounded to rationals,
    from the pole opposite ``v``'s largest entry (so the projection is bounded).

    Raises:
        ValueError: ``v`` is zero or not finite (the message names it).
    """
    v = np.asarray(v, dtype=float).reshape(-1)
    norm = float(np.linalg.norm(v))
    if not np.isfinite(norm) or norm == 0:
        raise ValueError(f"exact_unit_vector: v = {v.tolist()} has no direction")
    u = v / norm
    k = int(np.argmax(np.abs(u)))
    sign = 1 if u[k] > 0 else -1
    i, j = [m for m in range(3) if m != k]
    t = [_rational(u[m] / (1 + sign * u[k]), max_den) for m in (i, j)]
    q = t[0] ** 2 + t[1] ** 2
    out = [sp.Integer(0)] * 3
    out[i], out[j] = 2 * t[0] / (1 + q), 2 * t[1] / (1 + q)
    out[k] = sign * (1 - q) / (1 + q)
    return sp.Matrix(out)


def exact_rotation(Qf: np.ndarray, max_den: int = 10**6) -> sp.Matrix:
    """An exactly proper-orthogonal rational matrix within ~1/max_den of the float rotation.

    The Cayley parameters of ``F Qf`` (F a half turn about a coordinate axis, or 1, taken
    to keep them small) are rounded to rationals; ``F^T cayley(s)`` is then exactly a
    rotation. Small-denominator rotations (1/3, 2/3 ...) come back exactly.
    """
    best = None
    for F in _FLIPS:
        R = np.array(F.tolist(), dtype=float) @ Qf
        if abs(np.linalg.det(R + np.eye(3))) < 1e-6:   # a half turn: no Cayley parameters
            continue
        S = (R - np.eye(3)) @ np.linalg.inv(R + np.eye(3))
        s = np.array([S[2, 1], S[0, 2], S[1, 0]])
        if best is None or np.linalg.norm(s) < np.linalg.norm(best[1]):
            best = (F, s)
    F, s = best
    return F.T * cayley([_rational(v, max_den) for v in s])


def fitted_rotation(s: Solution, before, after, tol, what: str = "edge"):
    """The rotation of measured vectors, its residual printed, refused beyond ``2 tol``.

    ``after[:, k] ~ Q before[:, k]`` for each column ``k`` (e.g. a body's edge vectors
    before and after a rigid motion, each the difference of two measured points, hence
    the bound ``2 tol``). Adds the steps "correlation", "rotation (least squares)" and
    "residual" to ``s``, and a check that each vector is within ``2 tol`` of its image.

    Args:
        s: the solution being written.
        before, after: (3, n) sympy matrices of exact (rational) entries, in the data's
            length unit.
        tol: positive rational, the tolerance of one measured coordinate, same unit.
        what: the vectors' name in the refusal ("edge").

    Returns:
        ``(Q, residual)``: ``Q`` an exactly proper-orthogonal rational 3x3 matrix (Kabsch's
        solution of the orthogonal Procrustes problem, rounded by :func:`exact_rotation`),
        ``residual = sqrt(sum_k ||Q before_k - after_k||^2)`` as a 4-digit Float.

    Raises:
        the solution's ill-posed outcome (:meth:`Solution.fail`) when a vector misses its
        image by more than ``2 tol``: the data are not a rigid motion within ``tol``; the
        sentence gives the miss, the residual and a tolerance that would accept them.
    """
    M = s.step("correlation", after * before.T,
               f"Least squares: Q maximises tr(Q^T M), M = sum x'_k x_k^T over the {what}s "
               "(orthogonal Procrustes).")
    Q = s.step("rotation (least squares)",
               exact_rotation(nearest_rotation(np.array(M.tolist(), dtype=float))),
               "Kabsch: Q = U diag(1, 1, det(U V^T)) V^T from M = U S V^T, rounded to an "
               "exactly orthogonal rational matrix by the Cayley transform.")
    misfit = [sp.sqrt(sum(x**2 for x in Q * before[:, k] - after[:, k]))
              for k in range(before.cols)]
    worst = max(misfit, key=lambda m: float(sp.N(m, 30)))
    res = s.step("residual", sp.Float(sp.N(sp.sqrt(sum(m**2 for m in misfit)), 20), 4),
                 f"sqrt(sum ||Q x_k - x'_k||^2) over the {before.cols} {what}s, to 4 digits.")
    if bool(worst > 2 * tol):
        s.fail(f"The data are not a rigid motion within tol = {float(tol):.3g}: "
               f"a{'n' if what[0] in 'aeiou' else ''} {what} misses its image by "
               f"{float(worst):.3g} under the nearest rotation (residual {float(res):.3g})"
               f"{accepting_tol(sp.N(worst, 20) / 2)}.")
    s.check(truth_check(f"each {what} within 2 tol = {float(2 * tol):.3g} of its image "
                        f"under Q", True, "exact comparison of closed numbers"))
    return Q, res


def squared_residual(Q, pairs) -> sp.Expr:
    """``sum ||Q x2 - x1||^2`` over the pairs ``(x1, x2)`` (exact)."""
    return sum(((Q * x2 - x1).T * (Q * x2 - x1))[0] for x1, x2 in pairs)


_STEP = sp.Rational(1, 10**4)


def is_local_minimum(Q, objective, step=_STEP) -> bool:
    """True when each of the six rotations by ``2 atan(step)`` about +-x, +-y, +-z applied
    after ``Q`` does not lower ``objective(Q)`` (exact rationals, compared exactly).

    ``objective`` is a function of a rotation, or a list of pairs ``(x1, x2)`` for the
    squared residual of ``x1 ~ Q x2``.
    """
    if not callable(objective):
        pairs = objective
        objective = lambda R: squared_residual(R, pairs)
    r0 = objective(Q)
    for k in range(3):
        for sign in (1, -1):
            s = [0, 0, 0]
            s[k] = sign * step
            if objective(Q * cayley(s)) < r0:
                return False
    return True


def sorted_eigh(A) -> tuple[np.ndarray, np.ndarray]:
    """Eigenvalues (ascending) and unit eigenvectors (columns, a proper rotation) of a
    symmetric matrix, in floating point."""
    w, V = np.linalg.eigh(np.array(sp.Matrix(A).tolist(), dtype=float))
    if np.linalg.det(V) < 0:
        V[:, 2] = -V[:, 2]
    return w, V
