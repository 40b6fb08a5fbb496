"""Exercises 3.1, 3.2, 3.4, 3.5 and 3.19 in plain NumPy, by other methods than the
solver's: the screw axis from Q's eigenvector of eigenvalue 1 and a pseudo-inverse (3.1),
the central axis as a least-squares problem (3.2, 3.5), the rotation between two sensor
frames by Kabsch's SVD (3.4), the wrench moved by n_P = n_S + (s - p) x f (3.19). Never
imports rigidsym."""

from __future__ import annotations

import numpy as np

TOL = 1e-9


def _vect(Q):
    return 0.5 * np.array([Q[2, 1] - Q[1, 2], Q[0, 2] - Q[2, 0], Q[1, 0] - Q[0, 1]])


def cube_screw(A, B, D, E, Ap, Bp, Dp, Ep):
    """3.1: ``("ill-posed", why)`` or ``("solved", (Q, phi, e, p0, half_turn))``."""
    A, B, D, E, Ap, Bp, Dp, Ep = (np.asarray(v, float) for v in (A, B, D, E, Ap, Bp, Dp, Ep))
    M0 = np.column_stack([B - A, D - A, E - A])
    M1 = np.column_stack([Bp - Ap, Dp - Ap, Ep - Ap])
    if abs(np.linalg.det(M0)) < TOL:
        return "ill-posed", "dependent"
    Q = M1 @ np.linalg.inv(M0)
    if not np.allclose(Q.T @ Q, np.eye(3), atol=TOL) or np.linalg.det(Q) < 0:
        return "ill-posed", "not rigid"
    if np.allclose(Q, np.eye(3), atol=TOL):
        return "ill-posed", "translation"
    w, V = np.linalg.eig(Q)
    e = np.real(V[:, np.argmin(abs(w - 1))])
    e /= np.linalg.norm(e)
    s = e @ _vect(Q)                            # sin(phi) along e
    c = (np.trace(Q) - 1) / 2
    if s < 0:
        e, s = -e, -s
    phi = np.arctan2(s, c)
    c_vec = Ap - Q @ A                          # x -> Q x + c
    rhs = c_vec - (e @ c_vec) * e
    p0 = np.linalg.pinv(np.eye(3) - Q) @ rhs    # the minimum-norm point: the one nearest O
    return "solved", (Q, phi, e, p0, abs(s) < 1e-7)


def tetra_wrench(P1, P2, P3, P4):
    """3.2: ``("ill-posed", why)`` or ``("solved", (P, n_P, f))``: unit forces along P2->P3
    and P4->P1, their resultant f, and the point P of the central axis nearest P4."""
    P1, P2, P3, P4 = (np.asarray(v, float) for v in (P1, P2, P3, P4))
    if np.linalg.norm(P3 - P2) < TOL or np.linalg.norm(P1 - P4) < TOL:
        return "ill-posed", "coincide"
    f1 = (P3 - P2) / np.linalg.norm(P3 - P2)
    f2 = (P1 - P4) / np.linalg.norm(P1 - P4)
    f = f1 + f2
    if np.linalg.norm(f) < TOL:
        return "ill-posed", "couple"
    nO = np.cross(P2, f1) + np.cross(P4, f2)
    # the central axis: (n_O - P x f) x f = 0, linear in P; P = P4 + delta, delta least
    cols = []
    for k in range(3):
        u = np.eye(3)[k]
        cols.append(-np.cross(np.cross(u, f), f))
    L = np.column_stack(cols)
    r = -np.cross(nO - np.cross(P4, f), f)
    delta, *_ = np.linalg.lstsq(L, r, rcond=None)
    P = P4 + delta
    return "solved", (P, nO - np.cross(P, f), f)


def line_closest_point(pl):
    """3.5: ``("ill-posed", why)`` or ``("solved", (d, p_star))`` of Plücker data [e; n]."""
    pl = np.asarray(pl, float)
    e, n = pl[:3], pl[3:]
    if np.linalg.norm(e) < TOL:
        return "ill-posed", "zero"
    if abs(e @ n) > TOL * max(1.0, np.linalg.norm(n)):
        return "ill-posed", "not a line"
    # the points p of the line: p x e = n; the minimum-norm one is the nearest O
    L = np.column_stack([np.cross(np.eye(3)[k], e) for k in range(3)])
    p, *_ = np.linalg.lstsq(L, n, rcond=None)
    return "solved", (np.linalg.norm(p), p)


def sensor_rotation(n1, f1, n2, f2):
    """3.4 (exact readings): ``("ill-posed", why)`` or ``("solved", Q)`` with
    ``[x]_1 = Q [x]_2``, by Kabsch's SVD."""
    n1, f1, n2, f2 = (np.asarray(v, float) for v in (n1, f1, n2, f2))
    for n, f in ((n1, f1), (n2, f2)):
        if np.linalg.norm(np.cross(n, f)) < TOL:
            return "ill-posed", "parallel"
    inv = lambda n, f: np.array([f @ f, n @ n, n @ f])  # noqa: E731
    if not np.allclose(inv(n1, f1), inv(n2, f2), atol=1e-9):
        return "ill-posed", "not compatible"
    M = np.outer(f1, f2) + np.outer(n1, n2) + np.outer(np.cross(f1, n1), np.cross(f2, n2))
    U, _, Vt = np.linalg.svd(M)
    Q = U @ np.diag([1, 1, np.linalg.det(U @ Vt)]) @ Vt
    return "solved", Q


def wrench_in_f2(n_S, f_S, d, Q):
    """3.19: the wrench [n_2; f_2] at P in F_2: n_P = n_S + (s - p) x f, d = p - s, both
    parts turned by Q^T; ``None`` when Q is not a rotation."""
    n_S, f_S, d, Q = (np.asarray(v, float) for v in (n_S, f_S, d, Q))
    if not np.allclose(Q.T @ Q, np.eye(3), atol=TOL) or np.linalg.det(Q) < 0:
        return None
    nP = n_S + np.cross(-d, f_S)
    return np.concatenate([Q.T @ nP, Q.T @ f_S])


_AXES = {"X": 0, "Y": 1, "Z": 2}


def _rot(axis: str, a: float):
    c, s = np.cos(a), np.sin(a)
    i = _AXES[axis]
    j, k = (i + 1) % 3, (i + 2) % 3
    R = np.eye(3)
    R[j, j], R[j, k], R[k, j], R[k, k] = c, -s, s, c
    return R


def euler_rate_matrix(seq: str, eta, h: float = 1e-6):
    """3.10: W with omega = W eta_dot (fixed frame) at the angles ``eta``, by central
    differences of Q(eta) = R_a R_b R_c: column k is vect(dQ/deta_k Q^T)."""
    def Q(e):
        return _rot(seq[0], e[0]) @ _rot(seq[1], e[1]) @ _rot(seq[2], e[2])
    eta = np.asarray(eta, float)
    cols = []
    for k in range(3):
        d = np.zeros(3)
        d[k] = h
        Qd = (Q(eta + d) - Q(eta - d)) / (2 * h)
        cols.append(_vect(Qd @ Q(eta).T))
    return np.column_stack(cols)


def inertia_pair(IA, IB):
    """3.14 (exact data): ``"ill-posed"`` or ``"solved"``: the same inertia matrix in two
    frames iff both are symmetric with equal eigenvalues, positive, obeying I_1 + I_2 >=
    I_3 (sorted)."""
    IA, IB = np.asarray(IA, float), np.asarray(IB, float)
    if not (np.allclose(IA, IA.T, atol=TOL) and np.allclose(IB, IB.T, atol=TOL)):
        return "ill-posed"
    la, lb = np.linalg.eigvalsh(IA), np.linalg.eigvalsh(IB)
    if not np.allclose(la, lb, atol=1e-9):
        return "ill-posed"
    if la[0] <= TOL or la[0] + la[1] < la[2] - 1e-9:
        return "ill-posed"
    return "solved"


def grasp_screw(face_normal, CCp, Cp, p):
    """3.6: ``("ill-posed", why)`` or ``("solved", (Q, phi, e, p0, half_turn))``: the grasp
    frame [i'', j'', k''] (i'' along the face normal with positive components, j'' normal to
    i'' and CC' with a positive Z component) and the screw taking P to C'."""
    d, CCp, Cp, p = (np.asarray(v, float) for v in (face_normal, CCp, Cp, p))
    if not (np.all(d > 0) or np.all(d < 0)):
        return "ill-posed", "signs"
    i2 = np.abs(d) / np.linalg.norm(d)
    j = np.cross(i2, CCp)
    if np.linalg.norm(j) < TOL:
        return "ill-posed", "normal to the faces"
    j2 = j / np.linalg.norm(j)
    if abs(j2[2]) < TOL:
        return "ill-posed", "zero Z"
    j2 = j2 if j2[2] > 0 else -j2
    Q = np.column_stack([i2, j2, np.cross(i2, j2)])
    if np.allclose(Q, np.eye(3), atol=TOL):
        return "ill-posed", "translation"
    w, V = np.linalg.eig(Q)
    e = np.real(V[:, np.argmin(abs(w - 1))])
    e /= np.linalg.norm(e)
    s = e @ _vect(Q)
    if s < 0:
        e, s = -e, -s
    phi = np.arctan2(s, (np.trace(Q) - 1) / 2)
    c = Cp - Q @ p
    p0 = np.linalg.pinv(np.eye(3) - Q) @ (c - (e @ c) * e)
    return "solved", (Q, phi, e, p0, abs(s) < 1e-7)
