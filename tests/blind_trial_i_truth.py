"""NumPy truths of the ninth blind trial (``tests/data/blind_trial_i.json``): for each
statement, a function of a random generator returning the residual |lhs - rhs| at one random
point satisfying the declarations, the statement as typed (each source's own convention:
Titterton & Weston's C_b^n body to navigation, its quaternion a + bi + cj + dk scalar first
with Hamilton's product and its Euler matrices C_1, C_2, C_3 passive; Jekeli's R_1, R_2, R_3
passive and his navigation frame north-east-down; Wen & Kreutz-Delgado's unit quaternion
scalar first, R = I + 2 q_0 q^x + 2 (q^x)^2; Hibbeler's and Beer & Johnston's inertia matrices
with the products of inertia negated off the diagonal; Hand & Finch's 3-1-3 angles, A the
passive space-to-body matrix and omega the body components; Waldron & Kinzel's 4x4 transforms
[R p; 0 1]). A rate is taken along the declared rates, in closed form or by central
differences. Written from the sources' definitions before rigidsym read any statement; never
imports rigidsym: it is the independent judge."""

from __future__ import annotations

import numpy as np
from _numpy_truth import angle, expm, ham, holds_in, res, rot, sk, unit, vee

# ---------------------------------------------------------------- helpers of this trial


def conj(q):
    """The conjugate of a scalar-first quaternion."""
    return np.concatenate([[q[0]], -np.asarray(q[1:])])


def pr1(x):
    """Passive rotation about axis 1 (Jekeli's R_1, Titterton & Weston's C_3)."""
    c, s = np.cos(x), np.sin(x)
    return np.array([[1.0, 0, 0], [0, c, s], [0, -s, c]])


def pr2(x):
    c, s = np.cos(x), np.sin(x)
    return np.array([[c, 0, -s], [0, 1.0, 0], [s, 0, c]])


def pr3(x):
    c, s = np.cos(x), np.sin(x)
    return np.array([[c, s, 0], [-s, c, 0], [0, 0, 1.0]])


def d1(f, t=0.0, h=1e-3):
    """df/dt at t by a fourth-order central difference."""
    return (-f(t + 2 * h) + 8 * f(t + h) - 8 * f(t - h) + f(t - 2 * h)) / (12 * h)


def d2(f, t=0.0, h=1e-3):
    """d^2f/dt^2 at t by a fourth-order central difference."""
    return (-f(t + 2 * h) + 16 * f(t + h) - 30 * f(t) + 16 * f(t - h) - f(t - 2 * h)) / (12 * h * h)


def hom(R, p):
    t = np.eye(4)
    t[:3, :3], t[:3, 3] = R, p
    return t


def sym(rng):
    a = rng.normal(size=(3, 3))
    return a + a.T


# ---------------------------------------------------------------- Titterton & Weston


def tw_dcm_rate(rng):
    C, w = rot(rng), rng.normal(size=3)  # omega_nb^b the body angular velocity of C_b^n
    Cdot = d1(lambda t: C @ expm(sk(w) * t))
    return res(Cdot, C @ sk(w))


def _tw_C(q):
    a, b, c, d = q
    return np.array([[a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
                     [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
                     [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d]])


def _tw_quat_rate(rng, slip=False):
    q, w = unit(rng, 4), rng.normal(size=3)
    p = np.concatenate([[0.0], w])
    qdot = 0.5 * (ham(p, q) if slip else ham(q, p))
    Cdot = d1(lambda t: _tw_C(q + t * qdot))
    return res(Cdot, _tw_C(q) @ sk(w))


def tw_quat_rate(rng):
    return _tw_quat_rate(rng)


def tw_quat_rate_slip(rng):
    return _tw_quat_rate(rng, slip=True)


def _tw_euler(rng, slip=False):
    phi, th, psi = angle(rng), angle(rng), angle(rng)
    C = pr3(psi).T @ pr2(th).T @ pr1(phi).T  # C_1^T C_2^T C_3^T
    cf, sf, ct, st = np.cos(phi), np.sin(phi), np.cos(th), np.sin(th)
    cp, sp = np.cos(psi), np.sin(psi)
    e12 = (1 if slip else -1) * cf * sp + sf * st * cp
    printed = np.array([[ct * cp, e12, sf * sp + cf * st * cp],
                        [ct * sp, cf * cp + sf * st * sp, -sf * cp + cf * st * sp],
                        [-st, sf * ct, cf * ct]])
    return res(C, printed)


def tw_euler(rng):
    return _tw_euler(rng)


def tw_euler_slip(rng):
    return _tw_euler(rng, slip=True)


def _tw_rotvec(rng, slip=False):
    sv = rng.normal(size=3)
    s = np.linalg.norm(sv)
    k2 = (1 - np.cos(s)) / (s if slip else s * s)
    C = np.eye(3) + np.sin(s) / s * sk(sv) + k2 * sk(sv) @ sk(sv)
    return res(C.T @ C, np.eye(3))


def tw_rotvec(rng):
    return _tw_rotvec(rng)


def tw_rotvec_slip(rng):
    return _tw_rotvec(rng, slip=True)


def _tw_bracket(rng, slip=False):
    C, w = rot(rng), rng.normal(size=3)  # [C w x]: the cross-product matrix of C w
    lhs = C.T @ sk(w) @ C if slip else C @ sk(w) @ C.T
    return res(lhs, sk(C @ w))


def tw_bracket(rng):
    return _tw_bracket(rng)


def tw_bracket_slip(rng):
    return _tw_bracket(rng, slip=True)


# ---------------------------------------------------------------- Jekeli


def _jk_Cen(phi, lam):
    return pr2(-phi - np.pi / 2) @ pr3(lam)


def _jk_nav(rng, slip=False):
    phi, lam = angle(rng), angle(rng)
    sf, cf, sl, cl = np.sin(phi), np.cos(phi), np.sin(lam), np.cos(lam)
    printed = np.array([[-sf * cl, -sf * sl, cf], [(1 if slip else -1) * sl, cl, 0],
                        [-cf * cl, -cf * sl, -sf]])
    return res(_jk_Cen(phi, lam), printed)


def jk_nav_frame(rng):
    return _jk_nav(rng)


def jk_nav_frame_slip(rng):
    return _jk_nav(rng, slip=True)


def jk_earth_rate(rng):
    phi, lam, we = angle(rng), angle(rng), rng.normal()
    return res(_jk_Cen(phi, lam) @ [0, 0, we], [we * np.cos(phi), 0, -we * np.sin(phi)])


def _jk_transport(rng, slip=False):
    phi, lam, phid, lamd = angle(rng), angle(rng), rng.normal(), rng.normal()
    Cne = _jk_Cen(phi, lam).T
    Cdot = d1(lambda t: _jk_Cen(phi + phid * t, lam + lamd * t).T)
    w = np.array([lamd * np.cos(phi), (1 if slip else -1) * phid, -lamd * np.sin(phi)])
    return res(Cdot, Cne @ sk(w))


def jk_transport(rng):
    return _jk_transport(rng)


def jk_transport_slip(rng):
    return _jk_transport(rng, slip=True)


def _jk_similarity(rng, slip=False):
    C, w = rot(rng), rng.normal(size=3)
    lhs = C.T @ sk(w) @ C if slip else C @ sk(w) @ C.T
    return res(lhs, sk(C @ w))


def jk_similarity(rng):
    return _jk_similarity(rng)


def jk_similarity_slip(rng):
    return _jk_similarity(rng, slip=True)


# ---------------------------------------------------------------- Wen & Kreutz-Delgado


def _wk_R(qb, half=False):
    q0, q = qb[0], qb[1:]
    return np.eye(3) + 2 * q0 * sk(q) + (1 if half else 2) * sk(q) @ sk(q)


def _wk_orth(rng, slip=False):
    R = _wk_R(unit(rng, 4), half=slip)
    return res(R.T @ R, np.eye(3))


def wk_rot_orth(rng):
    return _wk_orth(rng)


def wk_rot_orth_slip(rng):
    return _wk_orth(rng, slip=True)


def wk_axis(rng):
    qb = unit(rng, 4)
    return res(_wk_R(qb) @ qb[1:], qb[1:])


def _wk_rate(qb, w, slip=False):
    q0, q = qb[0], qb[1:]
    return 0.5 * np.concatenate([[-q @ w], (q0 * np.eye(3) + (-1 if slip else 1) * sk(q)) @ w])


def _wk_kde(rng, slip=False):
    qb, w = unit(rng, 4), rng.normal(size=3)
    qd = _wk_rate(qb, w, slip)
    Rdot = d1(lambda t: _wk_R(qb + t * qd))
    return res(Rdot, _wk_R(qb) @ sk(w))


def wk_kde(rng):
    return _wk_kde(rng)


def wk_kde_slip(rng):
    return _wk_kde(rng, slip=True)


def _wk_lyap(rng, slip=False):
    qb, w = unit(rng, 4), rng.normal(size=3)
    qd = _wk_rate(qb, w)
    sign = 1 if slip else -1

    def V(t):
        x = qb + t * qd
        return x[1:] @ x[1:] + (1 + sign * x[0]) ** 2

    return abs(d1(V) - qb[1:] @ w)


def wk_lyap(rng):
    return _wk_lyap(rng)


def wk_lyap_slip(rng):
    return _wk_lyap(rng, slip=True)


def wk_gibbs(rng):
    n, th = unit(rng), angle(rng)
    g = np.tan(th / 2) * n
    lhs = np.eye(3) + 2 / (1 + g @ g) * (sk(g) + sk(g) @ sk(g))
    return res(lhs, np.eye(3) + np.sin(th) * sk(n) + (1 - np.cos(th)) * sk(n) @ sk(n))


def wk_conj(rng):
    qb = unit(rng, 4)
    return res(ham(qb, conj(qb)), [1, 0, 0, 0])


# ---------------------------------------------------------------- Hibbeler


def _hb_IO(IG, m, r, slip=False):
    return IG + m * ((r @ r) * np.eye(3) + (1 if slip else -1) * np.outer(r, r))


def _hb_ke(rng, slip=False):
    m, w, r, IG = rng.uniform(0.5, 2), rng.normal(size=3), rng.normal(size=3), sym(rng)
    v = np.cross(w, r)
    lhs = 0.5 * m * v @ v + 0.5 * w @ IG @ w
    return abs(lhs - 0.5 * w @ _hb_IO(IG, m, r, slip) @ w)


def hb_ke(rng):
    return _hb_ke(rng)


def hb_ke_slip(rng):
    return _hb_ke(rng, slip=True)


def hb_angmom(rng):
    m, w, r, IG = rng.uniform(0.5, 2), rng.normal(size=3), rng.normal(size=3), sym(rng)
    vG = np.cross(w, r)
    return res(_hb_IO(IG, m, r) @ w, np.cross(r, m * vG) + IG @ w)


def _hb_euler(rng, slip=False):
    Ix, Iy, Iz = rng.uniform(0.5, 3, size=3)
    w, wd = rng.normal(size=3), rng.normal(size=3)
    J = np.diag([Ix, Iy, Iz])
    rhs = J @ wd + np.cross(w, J @ w)
    lhs = np.array([Ix * wd[0] + (1 if slip else -1) * (Iy - Iz) * w[1] * w[2],
                    Iy * wd[1] - (Iz - Ix) * w[2] * w[0],
                    Iz * wd[2] - (Ix - Iy) * w[0] * w[1]])
    return res(lhs, rhs)


def hb_euler(rng):
    return _hb_euler(rng)


def hb_euler_slip(rng):
    return _hb_euler(rng, slip=True)


# ---------------------------------------------------------------- Beer & Johnston


def _bj_inertia(rng):
    Ix, Iy, Iz, Ixy, Iyz, Izx = rng.normal(size=6)
    J = np.array([[Ix, -Ixy, -Izx], [-Ixy, Iy, -Iyz], [-Izx, -Iyz, Iz]])
    return (Ix, Iy, Iz, Ixy, Iyz, Izx), J


def _bj_ke(rng, slip=False):
    (Ix, Iy, Iz, Ixy, Iyz, Izx), J = _bj_inertia(rng)
    wx, wy, wz = w = rng.normal(size=3)
    lhs = 0.5 * (Ix * wx**2 + Iy * wy**2 + Iz * wz**2 + (2 if slip else -2) * Ixy * wx * wy
                 - 2 * Iyz * wy * wz - 2 * Izx * wz * wx)
    return abs(lhs - 0.5 * w @ J @ w)


def bj_ke(rng):
    return _bj_ke(rng)


def bj_ke_slip(rng):
    return _bj_ke(rng, slip=True)


def bj_axis(rng):
    (Ix, Iy, Iz, Ixy, Iyz, Izx), J = _bj_inertia(rng)
    lx, ly, lz = lam = unit(rng)
    printed = (Ix * lx**2 + Iy * ly**2 + Iz * lz**2 - 2 * Ixy * lx * ly - 2 * Iyz * ly * lz
               - 2 * Izx * lz * lx)
    return abs(lam @ J @ lam - printed)


def _bj_rotating(rng, slip=False):
    R, W = rot(rng), rng.normal(size=3)  # R(t) = R e^{[W] t}; Omega its space angular velocity
    Q, Qd = rng.normal(size=3), rng.normal(size=3)
    lhs = d1(lambda t: R @ expm(sk(W) * t) @ (Q + t * Qd))
    Om = R @ W
    return res(lhs, R @ Qd + (-1 if slip else 1) * np.cross(Om, R @ Q))


def bj_rotating(rng):
    return _bj_rotating(rng)


def _bj_power(rng, slip=False):
    F, w, vA, MA, rA, rB = (rng.normal(size=3) for _ in range(6))
    vB = vA + np.cross(w, rB - rA)
    MB = MA + np.cross((rB - rA) if slip else (rA - rB), F)
    return abs(F @ vB + MB @ w - (F @ vA + MA @ w))


def bj_power(rng):
    return _bj_power(rng)


def bj_power_slip(rng):
    return _bj_power(rng, slip=True)


# ---------------------------------------------------------------- Kleppner & Kolenkow


def _kk_L(rng, slip=False):
    m, r, w = rng.uniform(0.5, 2), rng.normal(size=3), rng.normal(size=3)
    rhs = m * ((r @ r) * w + (1 if slip else -1) * (r @ w) * r)
    return res(m * np.cross(r, np.cross(w, r)), rhs)


def kk_L(rng):
    return _kk_L(rng)


def kk_L_slip(rng):
    return _kk_L(rng, slip=True)


def kk_torque(rng):
    m, a, b, c = rng.uniform(0.5, 2), rng.normal(size=3), rng.normal(size=3), rng.normal(size=3)

    def r(t):
        return a + b * t + c * t * t

    lhs = d1(lambda t: np.cross(r(t), m * d1(r, t)))
    return res(lhs, np.cross(r(0), m * d2(r)))


def kk_energy(rng):
    m, r, w = rng.uniform(0.5, 2), rng.normal(size=3), rng.normal(size=3)
    v = np.cross(w, r)
    L = m * np.cross(r, v)
    return abs(0.5 * m * v @ v - 0.5 * w @ L)


# ---------------------------------------------------------------- Hand & Finch


def _hf_A(phi, th, psi):
    return pr3(psi) @ pr1(th) @ pr3(phi)


def _hf_rates(rng, slip=False):
    phi, th, psi = angle(rng), angle(rng), angle(rng)
    fd, td, pd = rng.normal(size=3)
    A = _hf_A(phi, th, psi)
    Adot = d1(lambda t: _hf_A(phi + fd * t, th + td * t, psi + pd * t))
    w = np.array([fd * np.sin(th) * np.sin(psi) + td * np.cos(psi),
                  fd * np.sin(th) * np.cos(psi) + (1 if slip else -1) * td * np.sin(psi),
                  fd * np.cos(th) + pd])
    return res(Adot @ A.T, -sk(w))


def hf_euler_rates(rng):
    return _hf_rates(rng)


def hf_euler_rates_slip(rng):
    return _hf_rates(rng, slip=True)


def _hf_trace(rng, slip=False):
    R, J = rot(rng), sym(rng)
    return abs(np.trace(R @ J @ (R if slip else R.T)) - np.trace(J))


def hf_trace(rng):
    return _hf_trace(rng)


def hf_trace_slip(rng):
    return _hf_trace(rng, slip=True)


def _hf_torque_free(rng, slip=False):
    J, w = sym(rng) + 6 * np.eye(3), rng.normal(size=3)
    g = np.cross(w, J @ w)
    wd = -(J if slip else np.linalg.inv(J)) @ g
    return w, wd, J


def _hf_energy(rng, slip=False):
    w, wd, J = _hf_torque_free(rng, slip)
    return abs(w @ J @ wd)  # d/dt (1/2 w^T J w) with J symmetric


def hf_energy(rng):
    return _hf_energy(rng)


def hf_energy_slip(rng):
    return _hf_energy(rng, slip=True)


def hf_momentum(rng):
    w, wd, J = _hf_torque_free(rng)
    return abs(2 * (J @ w) @ (J @ wd))


# ---------------------------------------------------------------- Jose & Saletan


def _js_bracket(rng, slip=False):
    a, b = rng.normal(size=3), rng.normal(size=3)
    A, B = sk(a), sk(b)
    return res(A @ B - B @ A, sk(np.cross(b, a) if slip else np.cross(a, b)))


def js_bracket(rng):
    return _js_bracket(rng)


def js_bracket_slip(rng):
    return _js_bracket(rng, slip=True)


def _js_conj(rng, slip=False):
    R, a, b = rot(rng), rng.normal(size=3), rng.normal(size=3)
    return res((R.T if slip else R) @ np.cross(a, b), np.cross(R @ a, R @ b))


def js_conj(rng):
    return _js_conj(rng)


def js_conj_slip(rng):
    return _js_conj(rng, slip=True)


def _js_finite(rng, slip=False):
    n, th, x = unit(rng), angle(rng), rng.normal(size=3)
    sign = -1 if slip else 1
    rhs = x * np.cos(th) + n * (n @ x) * (1 - np.cos(th)) + sign * np.cross(n, x) * np.sin(th)
    return res(expm(th * sk(n)) @ x, rhs)


def js_finite(rng):
    return _js_finite(rng)


def js_finite_slip(rng):
    return _js_finite(rng, slip=True)


def _js_space_body(rng, slip=False):
    R, wb = rot(rng), rng.normal(size=3)  # omega_b: the body angular velocity of R
    Rdot = d1(lambda t: R @ expm(sk(wb) * t))
    lhs = R.T @ Rdot if slip else Rdot @ R.T
    return res(lhs, sk(R @ wb))


def js_space_body(rng):
    return _js_space_body(rng)


def js_space_body_slip(rng):
    return _js_space_body(rng, slip=True)


# ---------------------------------------------------------------- Fowles & Cassiday


def _fc_centripetal(rng):
    w, r = rng.normal(size=3), rng.normal(size=3)
    return res(np.cross(w, np.cross(w, r)), (w @ r) * w - (w @ w) * r)


def fc_centripetal(rng):
    return _fc_centripetal(rng)


def _fc_accel(rng, slip=False):
    R0, a, b = rot(rng), rng.normal(size=3), rng.normal(size=3)
    c0, c1, c2 = rng.normal(size=3), rng.normal(size=3), rng.normal(size=3)

    def R(t):
        return expm(sk(a * t + b * t * t)) @ R0

    def rp(t):  # r'(t), the coordinates in the moving frame
        return c0 + c1 * t + c2 * t * t

    def r(t):
        return R(t) @ rp(t)

    def omega(t):  # the declared space angular velocity of R
        return vee(d1(R, t) @ R(t).T)

    lhs = d2(r)
    rhs = (R(0) @ d2(rp) + (1 if slip else 2) * np.cross(omega(0), R(0) @ d1(rp))
           + np.cross(d1(omega), r(0)) + np.cross(omega(0), np.cross(omega(0), r(0))))
    return res(lhs, rhs)


def fc_accel(rng):
    return _fc_accel(rng)


def fc_accel_slip(rng):
    return _fc_accel(rng, slip=True)


# ---------------------------------------------------------------- Waldron & Kinzel


def _wz_inverse(rng, slip=False):
    R, p = rot(rng), rng.normal(size=3)
    printed = hom(R.T, (1 if slip else -1) * R.T @ p)
    return res(np.linalg.inv(hom(R, p)), printed)


def wz_inverse(rng):
    return _wz_inverse(rng)


def wz_inverse_slip(rng):
    return _wz_inverse(rng, slip=True)


def wz_compose(rng):
    R1, R2, p1, p2 = rot(rng), rot(rng), rng.normal(size=3), rng.normal(size=3)
    return res(hom(R1, p1) @ hom(R2, p2), hom(R1 @ R2, R1 @ p2 + p1))


def holds(name: str, points: int = 6, seed: int = 2024) -> bool:
    """Whether the named truth holds at ``points`` random points (:func:`_numpy_truth.holds_in`)."""
    return holds_in(globals(), name, points, seed)
