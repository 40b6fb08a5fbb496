"""NumPy truths of the eighth blind trial (``tests/data/blind_trial_h.json``): for each
statement, a function of a random generator returning the residual |lhs - rhs| at one random
point satisfying the declarations, the statement as typed (each source's own convention: Rao's
rotation tensor and Mason's Rot active, Rao's angular velocity dR/dt R^T = skw(omega) and his
corotational one R^T dR/dt = skw(Omega); Meriam & Kraige's inertia matrix with the products of
inertia negated off the diagonal; Kasdin & Paley's and Zipfel's transformation matrices
passive; Uicker-Pennock-Shigley's Denavit-Hartenberg matrix Rot(z) Trans(z) Trans(x) Rot(x);
Mason's and Dai's twists and screws angular part first, Dai's reciprocal product
S1^T Delta S2 with Delta = [0 I; I 0]; Shoemake's and Horn's quaternions scalar first with
Hamilton's product). A rate is taken along the declared rates, in closed form or (the 3-1-3
angles) by central differences. Written from the sources' definitions before rigidsym read any
statement; never imports rigidsym: it is the independent judge."""

from __future__ import annotations

import numpy as np
from _numpy_truth import (
    angle,
    ax,
    az,
    ddt,
    ham,
    holds_in,
    px,
    py,
    pz,
    res,
    rodrigues,
    rot,
    sk,
    unit,
    vee,
)

# ---------------------------------------------------------------- helpers of this trial


def conj(q):
    """The conjugate of a scalar-first quaternion."""
    return np.concatenate([[q[0]], -np.asarray(q[1:])])


def qinv(q):
    return conj(q) / (q @ q)


def pure(v):
    return np.concatenate([[0.0], v])


def expm_skew(w, th):
    """e^{[w]_x th} of a unit w, Rodrigues' closed form (checked against the series below)."""
    return rodrigues(w, th)


def hom_rz(x):
    t = np.eye(4)
    t[:3, :3] = az(x)
    return t


def hom_rx(x):
    t = np.eye(4)
    t[:3, :3] = ax(x)
    return t


def hom_d(axis, x):
    t = np.eye(4)
    t[axis, 3] = x
    return t


# ---------------------------------------------------------------- Rao


def _rao(rng, plus=False):
    r, th = unit(rng), angle(rng)
    lhs = expm_skew(r, th)
    rhs = np.cos(th) * np.eye(3) + (1 + np.cos(th) if plus else 1 - np.cos(th)) * np.outer(r, r) \
        + np.sin(th) * sk(r)
    return res(lhs, rhs)


def rao_rodrigues(rng):
    return _rao(rng)


def rao_rodrigues_slip(rng):
    return _rao(rng, plus=True)


def rao_axis(rng):
    r, th = unit(rng), angle(rng)
    return res(expm_skew(r, th) @ r, r)


def _rao_trace(rng, slip=False):
    r, th = unit(rng), angle(rng)
    return abs(np.trace(expm_skew(r, th)) - ((2 + np.cos(th)) if slip else (1 + 2 * np.cos(th))))


def rao_trace(rng):
    return _rao_trace(rng)


def rao_trace_slip(rng):
    return _rao_trace(rng, slip=True)


def _motion(rng):
    """A rotation R and its rate R [W]_x for a random body rate W."""
    R, W = rot(rng), rng.normal(size=3)
    return R, R @ sk(W), W


def rao_angvel(rng):
    R, Rdot, W = _motion(rng)
    omega = vee(Rdot @ R.T)  # the declared space angular velocity
    return res(Rdot @ R.T, sk(omega)) + res(omega, R @ W)


def rao_body(rng):
    R, Rdot, W = _motion(rng)
    Omega = vee(R.T @ Rdot)  # the declared body angular velocity
    return res(R.T @ Rdot, sk(Omega)) + res(Omega, W)


def rao_body_slip(rng):
    R, Rdot, W = _motion(rng)
    return res(Rdot @ R.T, sk(W))


# ---------------------------------------------------------------- Meriam & Kraige


def _mk_inertia(rng):
    ixx, iyy, izz, ixy, ixz, iyz = rng.normal(size=6)
    I = np.array([[ixx, -ixy, -ixz], [-ixy, iyy, -iyz], [-ixz, -iyz, izz]])
    return I, (ixx, iyy, izz, ixy, ixz, iyz)


def mk_angmom(rng):
    I, (ixx, iyy, izz, ixy, ixz, iyz) = _mk_inertia(rng)
    wx, wy, wz = w = rng.normal(size=3)
    printed = [ixx * wx - ixy * wy - ixz * wz, -ixy * wx + iyy * wy - iyz * wz,
               -ixz * wx - iyz * wy + izz * wz]
    return res(I @ w, printed)


def _mk_kinetic(rng, slip=False):
    I, (ixx, iyy, izz, ixy, ixz, iyz) = _mk_inertia(rng)
    wx, wy, wz = w = rng.normal(size=3)
    printed = 0.5 * (ixx * wx**2 + iyy * wy**2 + izz * wz**2) \
        + (1 if slip else -1) * ixy * wx * wy - ixz * wx * wz - iyz * wy * wz
    return abs(0.5 * w @ (I @ w) - printed)


def mk_kinetic(rng):
    return _mk_kinetic(rng)


def mk_kinetic_slip(rng):
    return _mk_kinetic(rng, slip=True)


def _mk_euler(rng, slip=False):
    ixx, iyy, izz = rng.uniform(0.5, 3, size=3)
    I = np.diag([ixx, iyy, izz])
    wx, wy, wz = w = rng.normal(size=3)
    a1, a2, a3 = a = rng.normal(size=3)
    M = I @ a + np.cross(w, I @ w)
    third = (iyy - ixx) if slip else (ixx - iyy)
    printed = [ixx * a1 - (iyy - izz) * wy * wz, iyy * a2 - (izz - ixx) * wz * wx,
               izz * a3 - third * wx * wy]
    return res(M, printed)


def mk_euler(rng):
    return _mk_euler(rng)


def mk_euler_slip(rng):
    return _mk_euler(rng, slip=True)


# ---------------------------------------------------------------- Kasdin & Paley


def _kp313(rng, slip=False):
    psi, th, phi = angle(rng), angle(rng), angle(rng)
    rates = rng.normal(size=3)  # psi dot, theta dot, phi dot

    def C(x):
        return pz(x[0]) @ px(x[1]) @ pz(x[2])

    x = np.array([psi, th, phi])
    Cdot = ddt(C, x, rates)
    pd, td, fd = rates
    s2 = 1 if slip else -1
    w = np.array([fd * np.sin(th) * np.sin(psi) + td * np.cos(psi),
                  fd * np.sin(th) * np.cos(psi) + s2 * td * np.sin(psi),
                  fd * np.cos(th) + pd])
    return res(Cdot, -sk(w) @ C(x))


def kp_313(rng):
    return _kp313(rng)


def kp_313_slip(rng):
    return _kp313(rng, slip=True)


def _kp_frame(rng):
    C = rot(rng)
    a = rng.normal(size=(3, 3))
    IA = a + a.T
    wA = rng.normal(size=3)
    return C, IA, wA, C @ wA


def kp_inertia_frame(rng):
    C, IA, wA, wB = _kp_frame(rng)
    IB = C @ IA @ C.T
    return abs(0.5 * wB @ IB @ wB - 0.5 * wA @ IA @ wA)


def kp_inertia_frame_slip(rng):
    C, IA, wA, wB = _kp_frame(rng)
    IB = C.T @ IA @ C
    return abs(0.5 * wB @ IB @ wB - 0.5 * wA @ IA @ wA)


def kp_momentum_frame(rng):
    C, IA, wA, wB = _kp_frame(rng)
    IB = C @ IA @ C.T
    return res(IB @ wB, C @ IA @ wA)


def _kp_free(rng):
    I = np.diag(rng.uniform(0.5, 3, size=3))
    w = rng.normal(size=3)
    wdot = -np.linalg.solve(I, np.cross(w, I @ w))
    return I, w, wdot


def kp_energy_conserved(rng):
    I, w, wdot = _kp_free(rng)
    return abs(w @ I @ wdot)  # d/dt (w^T I w / 2), I symmetric


def kp_momentum_conserved(rng):
    I, w, wdot = _kp_free(rng)
    return abs(2 * (I @ w) @ (I @ wdot))


def kp_momentum_conserved_slip(rng):
    I, w, wdot = _kp_free(rng)
    return abs(2 * w @ wdot)


# ---------------------------------------------------------------- Uicker, Pennock & Shigley


def _ups_dh(rng, slip=False):
    th, al = angle(rng), angle(rng)
    s, a = rng.normal(size=2)
    T = hom_rz(th) @ hom_d(2, s) @ hom_d(0, a) @ hom_rx(al)
    c, sn, ca, sa = np.cos(th), np.sin(th), np.cos(al), np.sin(al)
    printed = np.array([[c, -sn * ca, (-1 if slip else 1) * sn * sa, a * c],
                        [sn, c * ca, -c * sa, a * sn],
                        [0, sa, ca, s], [0, 0, 0, 1]])
    return res(T, printed)


def ups_dh(rng):
    return _ups_dh(rng)


def ups_dh_slip(rng):
    return _ups_dh(rng, slip=True)


def _ups_inverse(rng, sign):
    R, d = rot(rng), rng.normal(size=3)
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, d
    printed = np.eye(4)
    printed[:3, :3], printed[:3, 3] = R.T, sign * R.T @ d
    return res(np.linalg.inv(T), printed)


def ups_inverse(rng):
    return _ups_inverse(rng, -1)


def ups_inverse_slip(rng):
    return _ups_inverse(rng, 1)


# ---------------------------------------------------------------- Mason


def ms_line_moment(rng):
    r, q, lam = rng.normal(size=3), rng.normal(size=3), rng.normal()
    return res(np.cross(r, q), np.cross(r + lam * q, q))


def ms_line_moment_slip(rng):
    r, q, lam = rng.normal(size=3), rng.normal(size=3), rng.normal()
    return res(np.cross(r, q), np.cross(q, r + lam * q))


def ms_plucker(rng):
    r, q = rng.normal(size=3), rng.normal(size=3)
    return abs(q @ np.cross(r, q))


def _mason_rot(u, x):
    return np.eye(3) + np.sin(x) * sk(u) + (1 - np.cos(x)) * sk(u) @ sk(u)


def _ms_rodrigues(rng, sign):
    k, th, x = unit(rng), angle(rng), rng.normal(size=3)
    rhs = np.cos(th) * x + sign * np.sin(th) * np.cross(k, x) + (1 - np.cos(th)) * (k @ x) * k
    return res(_mason_rot(k, th) @ x, rhs)


def ms_rodrigues(rng):
    return _ms_rodrigues(rng, 1)


def ms_rodrigues_slip(rng):
    return _ms_rodrigues(rng, -1)


def _ms_reciprocal(rng, sign):
    w, v0, f, n0, p = (rng.normal(size=3) for _ in range(5))
    vp = v0 + np.cross(w, p)
    n_p = n0 + sign * np.cross(p, f)
    return abs(w @ n0 + v0 @ f - (w @ n_p + vp @ f))


def ms_reciprocal(rng):
    return _ms_reciprocal(rng, -1)


def ms_reciprocal_slip(rng):
    return _ms_reciprocal(rng, 1)


def _ms_quat(rng, slip=False):
    k, th, x = unit(rng), angle(rng), rng.normal(size=3)
    q = np.concatenate([[np.cos(th / 2)], np.sin(th / 2) * k])
    lhs = ham(ham(conj(q), pure(x)), q) if slip else ham(ham(q, pure(x)), conj(q))
    return res(lhs, pure(_mason_rot(k, th) @ x))


def ms_quat_rot(rng):
    return _ms_quat(rng)


def ms_quat_rot_slip(rng):
    return _ms_quat(rng, slip=True)


# ---------------------------------------------------------------- Dai

DELTA = np.block([[np.zeros((3, 3)), np.eye(3)], [np.eye(3), np.zeros((3, 3))]])


def _dai_adjoint(rng, slip=False):
    R, p = rot(rng), rng.normal(size=3)
    S1, S2 = rng.normal(size=6), rng.normal(size=6)
    P = sk(p)
    A = np.block([[R, np.zeros((3, 3))], [P if slip else P @ R, R]])
    return abs((A @ S1) @ DELTA @ (A @ S2) - S1 @ DELTA @ S2)


def dai_adjoint(rng):
    return _dai_adjoint(rng)


def dai_adjoint_slip(rng):
    return _dai_adjoint(rng, slip=True)


def _dai_self(rng, factor):
    s, r, h = unit(rng), rng.normal(size=3), rng.normal()
    S = np.concatenate([s, np.cross(r, s) + h * s])
    return abs(S @ DELTA @ S - factor * h)


def dai_self(rng):
    return _dai_self(rng, 2)


def dai_self_slip(rng):
    return _dai_self(rng, 1)


def _dai_ad(rng, sign):
    s1, s01, s2, s02 = (rng.normal(size=3) for _ in range(4))
    ad = np.block([[sk(s1), np.zeros((3, 3))], [sk(s01), sk(s1)]])  # ad of [w; v], angular first
    printed = np.concatenate([np.cross(s1, s2), np.cross(s1, s02) + sign * np.cross(s2, s01)])
    return res(ad @ np.concatenate([s2, s02]), printed)


def dai_ad(rng):
    return _dai_ad(rng, -1)


def dai_ad_slip(rng):
    return _dai_ad(rng, 1)


# ---------------------------------------------------------------- Shoemake


def _sh_product(rng, sign):
    s1, s2 = rng.normal(size=2)
    v1, v2 = rng.normal(size=3), rng.normal(size=3)
    printed = np.concatenate([[s1 * s2 - v1 @ v2], s1 * v2 + s2 * v1 + sign * np.cross(v1, v2)])
    return res(ham(np.concatenate([[s1], v1]), np.concatenate([[s2], v2])), printed)


def sh_product(rng):
    return _sh_product(rng, 1)


def sh_product_slip(rng):
    return _sh_product(rng, -1)


def _sh_matrix(rng, slip=False):
    q, v = unit(rng, 4), rng.normal(size=3)
    w, x, y, z = q
    M = np.array([[1 - 2 * y**2 - 2 * z**2, 2 * x * y + (1 if slip else -1) * 2 * w * z,
                   2 * x * z + 2 * w * y],
                  [2 * x * y + 2 * w * z, 1 - 2 * x**2 - 2 * z**2, 2 * y * z - 2 * w * x],
                  [2 * x * z - 2 * w * y, 2 * y * z + 2 * w * x, 1 - 2 * x**2 - 2 * y**2]])
    return res(pure(M @ v), ham(ham(q, pure(v)), qinv(q)))


def sh_matrix(rng):
    return _sh_matrix(rng)


def sh_matrix_slip(rng):
    return _sh_matrix(rng, slip=True)


def sh_sign(rng):
    q, p = unit(rng, 4), rng.normal(size=4)
    return res(ham(ham(q, p), qinv(q)), ham(ham(-q, p), qinv(-q)))


# ---------------------------------------------------------------- Horn


def hn_dot_mult(rng):
    q, p, r = (rng.normal(size=4) for _ in range(3))
    return abs(ham(q, p) @ ham(q, r) - (q @ q) * (p @ r))


def hn_dot_swap(rng):
    q, p, r = (rng.normal(size=4) for _ in range(3))
    return abs(ham(p, q) @ r - p @ ham(r, conj(q)))


def hn_dot_swap_slip(rng):
    q, p, r = (rng.normal(size=4) for _ in range(3))
    return abs(ham(p, q) @ r - p @ ham(conj(q), r))


def _horn_Q(q):
    q0, qx, qy, qz = q
    return np.array([[q0, -qx, -qy, -qz], [qx, q0, -qz, qy], [qy, qz, q0, -qx], [qz, -qy, qx, q0]])


def _horn_Qbar(q):
    q0, qx, qy, qz = q
    return np.array([[q0, -qx, -qy, -qz], [qx, q0, qz, -qy], [qy, -qz, q0, qx], [qz, qy, -qx, q0]])


def hn_matrix(rng):
    q, r = rng.normal(size=4), rng.normal(size=4)
    return res(ham(q, r), _horn_Q(q) @ r)


def hn_matrix_bar(rng):
    q, r = rng.normal(size=4), rng.normal(size=4)
    return res(ham(r, q), _horn_Qbar(q) @ r)


def hn_matrix_bar_slip(rng):
    q, r = rng.normal(size=4), rng.normal(size=4)
    return res(ham(r, q), _horn_Q(q) @ r)


def hn_orthogonal(rng):
    q = rng.normal(size=4)
    Q = _horn_Q(q)
    return res(Q.T @ Q, (q @ q) * np.eye(4))


# ---------------------------------------------------------------- Zipfel


def _zp_euler(rng, slip=False):
    psi, th, phi = angle(rng), angle(rng), angle(rng)
    T = px(phi) @ py(th) @ pz(psi)
    cs, ss, ct, st = np.cos(psi), np.sin(psi), np.cos(th), np.sin(th)
    cf, sf = np.cos(phi), np.sin(phi)
    e32 = ss * st * cf + (1 if slip else -1) * cs * sf
    printed = np.array([[cs * ct, ss * ct, -st],
                        [cs * st * sf - ss * cf, ss * st * sf + cs * cf, ct * sf],
                        [cs * st * cf + ss * sf, e32, ct * cf]])
    return res(T, printed)


def zp_euler(rng):
    return _zp_euler(rng)


def zp_euler_slip(rng):
    return _zp_euler(rng, slip=True)


def _zp_rate(rng, slip=False):
    R, Rdot, W = _motion(rng)  # [T]^{IB} and its rate; W its body angular velocity
    T, Tdot, Om = R.T, Rdot.T, sk(vee(R.T @ Rdot))
    return res(Tdot, -(T @ Om) if slip else -(Om @ T))


def zp_dcm_rate(rng):
    return _zp_rate(rng)


def zp_dcm_rate_slip(rng):
    return _zp_rate(rng, slip=True)


def holds(name: str, points: int = 6, seed: int = 2024) -> bool:
    """Whether the named truth holds at ``points`` random points (:func:`_numpy_truth.holds_in`)."""
    return holds_in(globals(), name, points, seed)
