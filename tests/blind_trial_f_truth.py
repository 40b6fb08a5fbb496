"""NumPy truths of the sixth blind trial (``tests/data/blind_trial_f.json``): for each
statement, a function of a random generator returning the residual |lhs - rhs| at one random
point satisfying the declarations, the statement as its source prints it (each book's own
convention: Schaub & Junkins', Hughes' and Wertz's attitude matrices are passive, Nikravesh's
and Haug's transformation matrix active; a rate by central differences along the declared
rates, a unit vector's rate tangent to its sphere). Written from the sources' definitions
before rigidsym read any statement; never imports rigidsym: it is the independent judge."""

from __future__ import annotations

import numpy as np
from _numpy_truth import angle, ax, ay, az, ddt, expm, holds_in, px, py, pz, res, rot, sk, unit

# ------------------------------------------------------------------ helpers


def tangent(rng, q):
    """A random rate of the unit vector q, tangent to its sphere."""
    v = rng.normal(size=len(q))
    return v - (v @ q) * q


def axis_angle_passive(e, phi):
    """cos(phi) 1 + (1 - cos(phi)) e e^T - sin(phi) [e]_x: the frame rotated by phi about e."""
    return np.cos(phi) * np.eye(3) + (1 - np.cos(phi)) * np.outer(e, e) - np.sin(phi) * sk(e)


# ------------------------------------------------------------------ Schaub & Junkins
def sj_c_beta(b):
    """[C] in the Euler parameters beta_0 (scalar) .. beta_3, as Schaub & Junkins print it."""
    b0, b1, b2, b3 = b
    return np.array([
        [b0 * b0 + b1 * b1 - b2 * b2 - b3 * b3, 2 * (b1 * b2 + b0 * b3), 2 * (b1 * b3 - b0 * b2)],
        [2 * (b1 * b2 - b0 * b3), b0 * b0 - b1 * b1 + b2 * b2 - b3 * b3, 2 * (b2 * b3 + b0 * b1)],
        [2 * (b1 * b3 + b0 * b2), 2 * (b2 * b3 - b0 * b1), b0 * b0 - b1 * b1 - b2 * b2 + b3 * b3]])


def _sj_ep_dcm(rng, sign):
    e, phi = unit(rng), angle(rng)
    beta = np.concatenate([[np.cos(phi / 2)], e * np.sin(phi / 2)])
    rhs = np.cos(phi) * np.eye(3) + (1 - np.cos(phi)) * np.outer(e, e) + sign * np.sin(phi) * sk(e)
    return res(sj_c_beta(beta), rhs)


def sj_ep_dcm(rng):
    return _sj_ep_dcm(rng, -1.0)


def sj_ep_dcm_slip(rng):
    return _sj_ep_dcm(rng, 1.0)


def _sj_ep_kde(rng, slip):
    b, w = unit(rng, 4), rng.normal(size=3)
    b0, b1, b2, b3 = b
    m = np.array([[-b1, -b2, -b3], [b0, -b3, b2], [b3, b0, -b1], [-b2, b1, b0]])
    if slip:  # row 2 typed beta_0 & beta_3 & beta_2
        m[1, 1] = b3
    d = 0.5 * m @ w
    return res(ddt(sj_c_beta, b, d), -sk(w) @ sj_c_beta(b))


def sj_ep_kde(rng):
    return _sj_ep_kde(rng, False)


def sj_ep_kde_slip(rng):
    return _sj_ep_kde(rng, True)


def sj_c_crp(q):
    return ((1 - q @ q) * np.eye(3) + 2 * np.outer(q, q) - 2 * sk(q)) / (1 + q @ q)


def _sj_crp_compose(rng, sign):
    q1, q2 = rng.normal(size=3), rng.normal(size=3)  # q' of [BN], q'' of [FB]
    qc = (q2 + q1 + sign * np.cross(q2, q1)) / (1 - q2 @ q1)
    return res(sj_c_crp(qc), sj_c_crp(q2) @ sj_c_crp(q1))


def sj_crp_compose(rng):
    return _sj_crp_compose(rng, -1.0)


def sj_crp_compose_slip(rng):
    return _sj_crp_compose(rng, 1.0)


def sj_c_mrp(s):
    return np.eye(3) + (8 * sk(s) @ sk(s) - 4 * (1 - s @ s) * sk(s)) / (1 + s @ s) ** 2


def _sj_mrp_shadow(rng, sign):
    s = rng.normal(size=3)
    return res(sj_c_mrp(sign * s / (s @ s)), sj_c_mrp(s))


def sj_mrp_shadow(rng):
    return _sj_mrp_shadow(rng, -1.0)


def sj_mrp_shadow_slip(rng):
    return _sj_mrp_shadow(rng, 1.0)


# ------------------------------------------------------------------ Hughes
def hughes_c(eps, eta):
    return (eta * eta - eps @ eps) * np.eye(3) + 2 * np.outer(eps, eps) - 2 * eta * sk(eps)


def _hu_ep_dcm(rng, sign):
    a, phi = unit(rng), angle(rng)
    eps, eta = a * np.sin(phi / 2), np.cos(phi / 2)
    rhs = (eta * eta - eps @ eps) * np.eye(3) + 2 * np.outer(eps, eps) + sign * 2 * eta * sk(eps)
    return res(axis_angle_passive(a, phi), rhs)


def hu_ep_dcm(rng):
    return _hu_ep_dcm(rng, -1.0)


def hu_ep_dcm_slip(rng):
    return _hu_ep_dcm(rng, 1.0)


def _hu_cross_rotate(rng, slip):
    c, a = rot(rng), rng.normal(size=3)
    rhs = c.T @ sk(a) @ c if slip else c @ sk(a) @ c.T
    return res(sk(c @ a), rhs)


def hu_cross_rotate(rng):
    return _hu_cross_rotate(rng, False)


def hu_cross_rotate_slip(rng):
    return _hu_cross_rotate(rng, True)


def hu_cross_product(rng):
    a, b = rng.normal(size=3), rng.normal(size=3)
    return res(sk(sk(a) @ b), np.outer(b, a) - np.outer(a, b))


def _hu_ep_kde(rng, sign):
    eps, eta, w = rng.normal(size=3), rng.normal(), rng.normal(size=3)
    deps = 0.5 * (sign * sk(eps) + eta * np.eye(3)) @ w
    deta = -0.5 * eps @ w
    x, dx = np.concatenate([[eta], eps]), np.concatenate([[deta], deps])
    cdot = ddt(lambda y: hughes_c(y[1:], y[0]), x, dx)
    return res(cdot, -sk(w) @ hughes_c(eps, eta))


def hu_ep_kde(rng):
    return _hu_ep_kde(rng, 1.0)


def hu_ep_kde_slip(rng):
    return _hu_ep_kde(rng, -1.0)


def hu_axis(rng):
    a, phi = unit(rng), angle(rng)
    return res(axis_angle_passive(a, phi) @ a, a)


# ------------------------------------------------------------------ Fossen
def fossen_zyx_written(phi, th, psi):
    """R_b^n(Theta) written out as Fossen prints it (zyx convention, active)."""
    cf, sf, ct, st = np.cos(phi), np.sin(phi), np.cos(th), np.sin(th)
    cp, sp = np.cos(psi), np.sin(psi)
    return np.array([
        [cp * ct, -sp * cf + cp * st * sf, sp * sf + cp * cf * st],
        [sp * ct, cp * cf + sf * st * sp, -cp * sf + st * sp * cf],
        [-st, ct * sf, ct * cf]])


def fossen_zyx(x):
    phi, th, psi = x
    return az(psi) @ ay(th) @ ax(phi)


def fo_zyx(rng):
    phi, th, psi = angle(rng), angle(rng), angle(rng)
    return res(fossen_zyx_written(phi, th, psi), fossen_zyx([phi, th, psi]))


def _fo_quat_r(rng, k):
    lam, beta = unit(rng), angle(rng)
    eta, eps = np.cos(beta / 2), lam * np.sin(beta / 2)
    lhs = np.eye(3) + 2 * eta * sk(eps) + k * sk(eps) @ sk(eps)
    rhs = np.eye(3) + np.sin(beta) * sk(lam) + (1 - np.cos(beta)) * sk(lam) @ sk(lam)
    return res(lhs, rhs)


def fo_quat_r(rng):
    return _fo_quat_r(rng, 2.0)


def fo_quat_r_slip(rng):
    return _fo_quat_r(rng, 1.0)


def _fo_rdot(rng, slip):
    r0, w = rot(rng), rng.normal(size=3)
    rdot = ddt(lambda t: r0 @ expm(sk(w) * t[0]), [0.0], [1.0])  # the body rate w
    return res(rdot, sk(w) @ r0 if slip else r0 @ sk(w))


def fo_rdot(rng):
    return _fo_rdot(rng, False)


def fo_rdot_slip(rng):
    return _fo_rdot(rng, True)


def _fo_euler_rate(rng, sign):
    phi, th, psi = angle(rng), angle(rng), angle(rng)
    p, q, r = rng.normal(size=3)
    dphi = p + q * np.sin(phi) * np.tan(th) + r * np.cos(phi) * np.tan(th)
    dth = q * np.cos(phi) + sign * r * np.sin(phi)
    dpsi = q * np.sin(phi) / np.cos(th) + r * np.cos(phi) / np.cos(th)
    x, dx = [phi, th, psi], [dphi, dth, dpsi]
    return res(ddt(fossen_zyx, x, dx), fossen_zyx(x) @ sk([p, q, r]))


def fo_euler_rate(rng):
    return _fo_euler_rate(rng, -1.0)


def fo_euler_rate_slip(rng):
    return _fo_euler_rate(rng, 1.0)


# ------------------------------------------------------------------ Beard & McLain
def beard_rvb(phi, th, psi):
    """R_v^b = R_{v2}^b(phi) R_{v1}^{v2}(theta) R_v^{v1}(psi), each a passive rotation."""
    return px(phi) @ py(th) @ pz(psi)


def bm_rvb(rng):
    phi, th, psi = angle(rng), angle(rng), angle(rng)
    cf, sf, ct, st = np.cos(phi), np.sin(phi), np.cos(th), np.sin(th)
    cp, sp = np.cos(psi), np.sin(psi)
    written = np.array([
        [ct * cp, ct * sp, -st],
        [sf * st * cp - cf * sp, sf * st * sp + cf * cp, sf * ct],
        [cf * st * cp + sf * sp, cf * st * sp - sf * cp, cf * ct]])
    return res(written, beard_rvb(phi, th, psi))


def _bm_inverse(rng, sign):
    phi, th = angle(rng), angle(rng)
    cf, sf, ct, st = np.cos(phi), np.sin(phi), np.cos(th), np.sin(th)
    m1 = np.array([[1, sf * np.tan(th), cf * np.tan(th)], [0, cf, -sf], [0, sf / ct, cf / ct]])
    m2 = np.array([[1, 0, -st], [0, cf, sf * ct], [0, sign * sf, cf * ct]])
    return res(m1 @ m2, np.eye(3))


def bm_inverse(rng):
    return _bm_inverse(rng, -1.0)


def bm_inverse_slip(rng):
    return _bm_inverse(rng, 1.0)


def beard_rvb_quat(e):
    e0, e1, e2, e3 = e
    return np.array([
        [e1 * e1 + e0 * e0 - e2 * e2 - e3 * e3, 2 * (e1 * e2 + e3 * e0), 2 * (e1 * e3 - e2 * e0)],
        [2 * (e1 * e2 - e3 * e0), e2 * e2 + e0 * e0 - e1 * e1 - e3 * e3, 2 * (e2 * e3 + e1 * e0)],
        [2 * (e1 * e3 + e2 * e0), 2 * (e2 * e3 - e1 * e0), e3 * e3 + e0 * e0 - e1 * e1 - e2 * e2]])


def _bm_quat_euler(rng, sign):
    phi, th, psi = angle(rng), angle(rng), angle(rng)
    cf, sf = np.cos(phi / 2), np.sin(phi / 2)
    ct, st = np.cos(th / 2), np.sin(th / 2)
    cp, sp = np.cos(psi / 2), np.sin(psi / 2)
    e = [cp * ct * cf + sp * st * sf, cp * ct * sf - sp * st * cf,
         cp * st * cf + sp * ct * sf, sp * ct * cf + sign * cp * st * sf]
    return res(beard_rvb_quat(e), beard_rvb(phi, th, psi))


def bm_quat_euler(rng):
    return _bm_quat_euler(rng, -1.0)


def bm_quat_euler_slip(rng):
    return _bm_quat_euler(rng, 1.0)


def bm_coriolis(rng):
    r0, w = rot(rng), rng.normal(size=3)
    p, pd = rng.normal(size=3), rng.normal(size=3)
    lhs = ddt(lambda t: r0 @ expm(sk(w) * t[0]) @ (p + t[0] * pd), [0.0], [1.0])
    return res(lhs, r0 @ (pd + np.cross(w, p)))


# ------------------------------------------------------------------ Nikravesh
def nik_g(p):
    e0, e = p[0], p[1:]
    return np.hstack([-e[:, None], sk(e) + e0 * np.eye(3)])


def nik_l(p):
    e0, e = p[0], p[1:]
    return np.hstack([-e[:, None], -sk(e) + e0 * np.eye(3)])


def nik_a(p):
    e0, e = p[0], p[1:]
    return (2 * e0 * e0 - 1) * np.eye(3) + 2 * (np.outer(e, e) + e0 * sk(e))


def nk_a_gl(rng):
    p = unit(rng, 4)
    return res(nik_a(p), nik_g(p) @ nik_l(p).T)


def nk_a_gl_slip(rng):
    p = unit(rng, 4)
    return res(nik_a(p), nik_l(p) @ nik_g(p).T)


def _nk_omega(rng, rate):
    p = unit(rng, 4)
    pd = tangent(rng, p)
    w = 2 * rate(p) @ pd
    return res(ddt(nik_a, p, pd), sk(w) @ nik_a(p))


def nk_omega(rng):
    return _nk_omega(rng, nik_g)


def nk_omega_slip(rng):
    return _nk_omega(rng, nik_l)


def nk_body_omega(rng):
    p = unit(rng, 4)
    pd = tangent(rng, p)
    w = 2 * nik_l(p) @ pd
    return res(ddt(nik_a, p, pd), nik_a(p) @ sk(w))


def nk_ggt(rng):
    p = unit(rng, 4)
    return res(nik_g(p) @ nik_g(p).T, np.eye(3))


def nk_gtg(rng):
    p = unit(rng, 4)
    return res(nik_g(p).T @ nik_g(p), np.eye(4) - np.outer(p, p))


# ------------------------------------------------------------------ Haug
def haug_e(p):
    e0, e = p[0], p[1:]
    return np.hstack([-e[:, None], sk(e) + e0 * np.eye(3)])


def haug_g(p):
    e0, e = p[0], p[1:]
    return np.hstack([-e[:, None], -sk(e) + e0 * np.eye(3)])


def haug_a(p):
    e0, e = p[0], p[1:]
    return 2 * ((e0 * e0 - 0.5) * np.eye(3) + np.outer(e, e) + e0 * sk(e))


def _hg_tilde_comm(rng, sign):
    a, b = rng.normal(size=3), rng.normal(size=3)
    return res(sk(sk(a) @ b), sign * (sk(a) @ sk(b) - sk(b) @ sk(a)))


def hg_tilde_comm(rng):
    return _hg_tilde_comm(rng, 1.0)


def hg_tilde_comm_slip(rng):
    return _hg_tilde_comm(rng, -1.0)


def _hg_tilde_sq(rng, slip):
    a, b = rng.normal(size=3), rng.normal(size=3)
    outer = np.outer(a, b) if slip else np.outer(b, a)
    return res(sk(a) @ sk(b), outer - (a @ b) * np.eye(3))


def hg_tilde_sq(rng):
    return _hg_tilde_sq(rng, False)


def hg_tilde_sq_slip(rng):
    return _hg_tilde_sq(rng, True)


def hg_a_eg(rng):
    p = unit(rng, 4)
    return res(haug_a(p), haug_e(p) @ haug_g(p).T)


def hg_gdot(rng):
    p = unit(rng, 4)
    pd = tangent(rng, p)
    return res(ddt(haug_g, p, pd) @ pd, np.zeros(3))


def hg_pdot(rng):
    p = unit(rng, 4)
    pd = tangent(rng, p)
    w = 2 * haug_g(p) @ pd
    return res(pd, 0.5 * haug_g(p).T @ w)


# ------------------------------------------------------------------ Wertz
def wertz_a(q):
    """The attitude matrix in the Euler symmetric parameters q_1..q_4 (q_4 the scalar), written
    out as Wertz prints it (12-13a)."""
    q1, q2, q3, q4 = q
    return np.array([
        [q1 * q1 - q2 * q2 - q3 * q3 + q4 * q4, 2 * (q1 * q2 + q3 * q4), 2 * (q1 * q3 - q2 * q4)],
        [2 * (q1 * q2 - q3 * q4), -q1 * q1 + q2 * q2 - q3 * q3 + q4 * q4, 2 * (q2 * q3 + q1 * q4)],
        [2 * (q1 * q3 + q2 * q4), 2 * (q2 * q3 - q1 * q4), -q1 * q1 - q2 * q2 + q3 * q3 + q4 * q4]])


def _wz_ep_a(rng, sign):
    q, q4 = rng.normal(size=3), rng.normal()
    rhs = (q4 * q4 - q @ q) * np.eye(3) + 2 * np.outer(q, q) + sign * 2 * q4 * sk(q)
    return res(wertz_a(np.concatenate([q, [q4]])), rhs)


def wz_ep_a(rng):
    return _wz_ep_a(rng, -1.0)


def wz_ep_a_slip(rng):
    return _wz_ep_a(rng, 1.0)


def _wz_kde(rng, slip):
    q, w = unit(rng, 4), rng.normal(size=3)
    w1, w2, w3 = w
    om = np.array([[0, w3, -w2, w1], [-w3, 0, w1, w2], [w2, -w1, 0, w3], [-w1, -w2, -w3, 0]])
    if slip:  # the first row typed 0 & -omega_3 & ...
        om[0, 1] = -w3
    qd = 0.5 * om @ q
    return res(ddt(wertz_a, q, qd), -sk(w) @ wertz_a(q))


def wz_kde(rng):
    return _wz_kde(rng, False)


def wz_kde_slip(rng):
    return _wz_kde(rng, True)


def _wz_gibbs(rng, sign):
    q = unit(rng, 4)
    g = q[:3] / q[3]
    rhs = ((1 - g @ g) * np.eye(3) + 2 * np.outer(g, g) - 2 * sk(g)) / (1 + sign * g @ g)
    return res(wertz_a(q), rhs)


def wz_gibbs(rng):
    return _wz_gibbs(rng, 1.0)


def wz_gibbs_slip(rng):
    return _wz_gibbs(rng, -1.0)


def wz_axis(rng):
    e, phi = unit(rng), angle(rng)
    q = np.concatenate([e * np.sin(phi / 2), [np.cos(phi / 2)]])
    return res(wertz_a(q), axis_angle_passive(e, phi))


def holds(name: str, points: int = 6, seed: int = 2024) -> bool:
    """Whether the named truth holds at ``points`` random points (:func:`_numpy_truth.holds_in`)."""
    return holds_in(globals(), name, points, seed)
