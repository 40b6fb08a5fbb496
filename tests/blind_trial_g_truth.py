"""NumPy truths of the seventh blind trial (``tests/data/blind_trial_g.json``): for each
statement, a function of a random generator returning the residual |lhs - rhs| at one random
point satisfying the declarations, the statement as its source prints it (each book's own
convention: Paul's Rot and Trans active 4x4 homogeneous transforms; Altmann's, Vince's and
Bottema & Roth's rotations active, their quaternions scalar first with Hamilton's product;
Curtis' and Sidi's matrices passive, Sidi's quaternion scalar last; Arnold's B carrying the
body to space, omega = B Omega). A rate is taken by central differences along the declared
rates. Written from the sources' definitions before rigidsym read any statement; never
imports rigidsym: it is the independent judge."""

from __future__ import annotations

import numpy as np
from _numpy_truth import angle, ax, ay, az, ddt, ham, holds_in, pz, res, rodrigues, rot, sk, unit

# ------------------------------------------------------------------ helpers


def homog(r, p):
    """The 4x4 homogeneous transform [r p; 0 1]."""
    t = np.eye(4)
    t[:3, :3], t[:3, 3] = r, p
    return t


def h3(r):
    """A 3x3 rotation as a 4x4 homogeneous transform with no translation."""
    return homog(r, np.zeros(3))


def conj(q):
    """The conjugate of a scalar-first quaternion."""
    return np.concatenate([[q[0]], -q[1:]])


def quat_rot(a, av):
    """(a^2 - A.A) 1 + 2 A A^T + 2 a [A]x: the (scaled) rotation of the quaternion [a, A]."""
    return (a * a - av @ av) * np.eye(3) + 2 * np.outer(av, av) + 2 * a * sk(av)


def gibbs_rot(t):
    """1 + 2 ([t]x + [t]x^2) / (1 + t.t): the rotation of the Rodrigues (Gibbs) vector t."""
    return np.eye(3) + 2 * (sk(t) + sk(t) @ sk(t)) / (1 + t @ t)


# ------------------------------------------------------------------ Paul, Robot Manipulators
def _paul_frame(rng):
    r, p = rot(rng), rng.normal(size=3)
    return r, p, homog(r, p)


def _pl_tinv(rng, sign):
    r, p, t = _paul_frame(rng)
    n, o, a = r[:, 0], r[:, 1], r[:, 2]
    rhs = np.zeros((4, 4))
    rhs[0, :3], rhs[1, :3], rhs[2, :3] = n, o, a
    rhs[:3, 3] = sign * np.array([p @ n, p @ o, p @ a])
    rhs[3, 3] = 1.0
    return res(np.linalg.inv(t), rhs)


def pl_tinv(rng):
    return _pl_tinv(rng, -1.0)


def pl_tinv_slip(rng):
    return _pl_tinv(rng, 1.0)


def _pl_euler(rng, slip):
    f, t, s = angle(rng), angle(rng), angle(rng)
    cf, sf, ct, st, cs, ss = np.cos(f), np.sin(f), np.cos(t), np.sin(t), np.cos(s), np.sin(s)
    m = np.array([
        [cf * ct * cs - sf * ss, -cf * ct * ss - sf * cs, cf * st],
        [sf * ct * cs + cf * ss, -sf * ct * ss + cf * cs, sf * st],
        [-st * cs, (-1.0 if slip else 1.0) * st * ss, ct]])
    return res(h3(az(f) @ ay(t) @ az(s)), h3(m))


def pl_euler(rng):
    return _pl_euler(rng, False)


def pl_euler_slip(rng):
    return _pl_euler(rng, True)


def pl_rpy(rng):
    f, t, s = angle(rng), angle(rng), angle(rng)
    cf, sf, ct, st, cs, ss = np.cos(f), np.sin(f), np.cos(t), np.sin(t), np.cos(s), np.sin(s)
    m = np.array([
        [cf * ct, cf * st * ss - sf * cs, cf * st * cs + sf * ss],
        [sf * ct, sf * st * ss + cf * cs, sf * st * cs - cf * ss],
        [-st, ct * ss, ct * cs]])
    return res(h3(az(f) @ ay(t) @ ax(s)), h3(m))


def _pl_rot_trans(rng, slip):
    th, (a, b, c) = angle(rng), rng.normal(size=3)
    ct, st = np.cos(th), np.sin(th)
    trans = homog(np.eye(3), np.array([a, b, c]))
    lhs = trans @ h3(az(th)) if slip else h3(az(th)) @ trans
    rhs = homog(az(th), np.array([a * ct - b * st, a * st + b * ct, c]))
    return res(lhs, rhs)


def pl_rot_trans(rng):
    return _pl_rot_trans(rng, False)


def pl_rot_trans_slip(rng):
    return _pl_rot_trans(rng, True)


def _pl_diff(rng, slip):
    r, p, t = _paul_frame(rng)
    n, o, a = r[:, 0], r[:, 1], r[:, 2]
    dl, d = rng.normal(size=3), rng.normal(size=3)
    big = np.zeros((4, 4))
    big[:3, :3], big[:3, 3] = sk(dl), d
    w = (np.cross(p, dl) if slip else np.cross(dl, p)) + d
    rhs = np.array([
        [0.0, -dl @ a, dl @ o, n @ w],
        [dl @ a, 0.0, -dl @ n, o @ w],
        [-dl @ o, dl @ n, 0.0, a @ w],
        [0.0, 0.0, 0.0, 0.0]])
    return res(np.linalg.inv(t) @ big @ t, rhs)


def pl_diff(rng):
    return _pl_diff(rng, False)


def pl_diff_slip(rng):
    return _pl_diff(rng, True)


# ------------------------------------------------------------------ Altmann, Rotations, Quaternions
def _al_rodrigues(rng, sign):
    n, phi, r = unit(rng), angle(rng), rng.normal(size=3)
    big = quat_rot(np.cos(phi / 2), np.sin(phi / 2) * n)
    rhs = r * np.cos(phi) + (1 - np.cos(phi)) * (n @ r) * n + sign * np.sin(phi) * np.cross(n, r)
    return res(big @ r, rhs)


def al_rodrigues(rng):
    return _al_rodrigues(rng, 1.0)


def al_rodrigues_slip(rng):
    return _al_rodrigues(rng, -1.0)


def _al_compose(rng, sign):
    a1, a2 = rng.normal(size=2)
    v1, v2 = rng.normal(size=3), rng.normal(size=3)
    a3 = a1 * a2 - v1 @ v2
    v3 = a1 * v2 + a2 * v1 + sign * np.cross(v1, v2)
    return res(quat_rot(a1, v1) @ quat_rot(a2, v2), quat_rot(a3, v3))


def al_compose(rng):
    return _al_compose(rng, 1.0)


def al_compose_slip(rng):
    return _al_compose(rng, -1.0)


def al_trace(rng):
    n, phi = unit(rng), angle(rng)
    a = np.cos(phi / 2)
    return abs(np.trace(quat_rot(a, np.sin(phi / 2) * n)) - (4 * a * a - 1))


def al_inverse(rng):
    n, phi = unit(rng), angle(rng)
    a, av = np.cos(phi / 2), np.sin(phi / 2) * n
    return res(quat_rot(a, av).T, quat_rot(a, -av))


def al_gibbs(rng):
    t1, t2 = rng.normal(size=3), rng.normal(size=3)
    t3 = (t1 + t2 + np.cross(t1, t2)) / (1 - t1 @ t2)
    return res(gibbs_rot(t1) @ gibbs_rot(t2), gibbs_rot(t3))


# ------------------------------------------------------------------ Arnold, Mathematical Methods
def _arnold_motion(rng):
    """B(t) = B0 e^{[w] t} at t = 0 and its rate: B, its rate, omega (space), Omega (body)."""
    b, big_omega = rot(rng), rng.normal(size=3)
    bdot = b @ sk(big_omega)
    return b, bdot, b @ big_omega, big_omega


def _ar_space(rng, slip):
    b, bdot, w, _ = _arnold_motion(rng)
    q = rng.normal(size=3)
    lhs = np.linalg.inv(b) @ bdot @ q if slip else bdot @ np.linalg.inv(b) @ q
    return res(lhs, np.cross(w, q))


def ar_space(rng):
    return _ar_space(rng, False)


def ar_space_slip(rng):
    return _ar_space(rng, True)


def _ar_body(rng, slip):
    b, _, w, big_omega = _arnold_motion(rng)
    return res(big_omega, b @ w) if slip else res(w, b @ big_omega)


def ar_body(rng):
    return _ar_body(rng, False)


def ar_body_slip(rng):
    return _ar_body(rng, True)


def _ar_euler(rng, slip):
    b, bdot, _, big_omega = _arnold_motion(rng)
    m = rng.normal(size=3)
    mb = np.linalg.inv(b) @ m
    mdot = bdot.T @ m  # B^{-1} = B^T; m constant
    rhs = np.cross(big_omega, mb) if slip else np.cross(mb, big_omega)
    return res(mdot, rhs)


def ar_euler(rng):
    return _ar_euler(rng, False)


def ar_euler_slip(rng):
    return _ar_euler(rng, True)


def ar_energy(rng):
    a = rng.normal(size=(3, 3))
    a = a + a.T
    b, big_omega = rot(rng), rng.normal(size=3)
    return abs(0.5 * (a @ big_omega) @ big_omega - 0.5 * (b @ a @ big_omega) @ (b @ big_omega))


def ar_inertia(rng):
    q, big_omega = rng.normal(size=3), rng.normal(size=3)
    return res(np.cross(q, np.cross(big_omega, q)), -sk(q) @ sk(q) @ big_omega)


# ------------------------------------------------------------------ Curtis, Orbital Mechanics
def curtis_q(psi, theta, phi):
    """[Q]_Xx = [R3(psi)][R1(theta)][R3(phi)], Curtis' passive 3-1-3 sequence."""
    return pz(psi) @ ax(theta).T @ pz(phi)


def _cu_kde(rng, slip):
    ang, rate = np.array([angle(rng) for _ in range(3)]), rng.normal(size=3)
    phi, theta, psi = ang
    dphi, dtheta, dpsi = rate
    w = np.array([
        dphi * np.sin(theta) * np.sin(psi) + dtheta * np.cos(psi),
        dphi * np.sin(theta) * np.cos(psi) + (1.0 if slip else -1.0) * dtheta * np.sin(psi),
        dphi * np.cos(theta) + dpsi])

    def q(x):
        return curtis_q(x[2], x[1], x[0])

    return res(ddt(q, ang, rate), -sk(w) @ q(ang))


def cu_kde(rng):
    return _cu_kde(rng, False)


def cu_kde_slip(rng):
    return _cu_kde(rng, True)


def _cu_euler(rng, slip):
    big_a, big_b, big_c = rng.normal(size=3)
    w = rng.normal(size=3)
    wx, wy, wz = w
    rhs = np.array([(big_b - big_c if slip else big_c - big_b) * wy * wz,
                    (big_a - big_c) * wz * wx, (big_b - big_a) * wx * wy])
    return res(np.cross(w, np.diag([big_a, big_b, big_c]) @ w), rhs)


def cu_euler(rng):
    return _cu_euler(rng, False)


def cu_euler_slip(rng):
    return _cu_euler(rng, True)


def _cu_dcm(rng, sign):
    phi, theta, psi = angle(rng), angle(rng), angle(rng)
    cf, sf, ct, st, cs, ss = (np.cos(phi), np.sin(phi), np.cos(theta), np.sin(theta),
                              np.cos(psi), np.sin(psi))
    m = np.array([
        [-sf * ct * ss + cf * cs, cf * ct * ss + sf * cs, st * ss],
        [-sf * ct * cs - cf * ss, cf * ct * cs - sf * ss, st * cs],
        [sf * st, sign * cf * st, ct]])
    return res(curtis_q(psi, theta, phi), m)


def cu_dcm(rng):
    return _cu_dcm(rng, -1.0)


def cu_dcm_slip(rng):
    return _cu_dcm(rng, 1.0)


def cu_transport(rng):
    r0, w = rot(rng), rng.normal(size=3)  # R(t) = e^{[w]t} R0: space angular velocity w
    x, xdot = rng.normal(size=3), rng.normal(size=3)
    h = 1e-6

    def f(s):
        return rodrigues(w / np.linalg.norm(w), np.linalg.norm(w) * s) @ r0 @ (x + s * xdot)

    lhs = (f(h) - f(-h)) / (2 * h)
    return res(lhs, r0 @ xdot + np.cross(w, r0 @ x))


# ------------------------------------------------------------------ Sidi, Spacecraft Dynamics
def sidi_a(q):
    """Sidi's attitude matrix in q1..q4, q4 the scalar (Wertz's, passive)."""
    q1, q2, q3, q4 = q
    return np.array([
        [q1 * q1 - q2 * q2 - q3 * q3 + q4 * q4, 2 * (q1 * q2 + q3 * q4), 2 * (q1 * q3 - q2 * q4)],
        [2 * (q1 * q2 - q3 * q4), -q1 * q1 + q2 * q2 - q3 * q3 + q4 * q4, 2 * (q2 * q3 + q1 * q4)],
        [2 * (q1 * q3 + q2 * q4), 2 * (q2 * q3 - q1 * q4), -q1 * q1 - q2 * q2 + q3 * q3 + q4 * q4]])


def _si_axis(rng, sign):
    e, big_phi = unit(rng), angle(rng)
    q = np.concatenate([e * np.sin(big_phi / 2), [np.cos(big_phi / 2)]])
    rhs = (np.cos(big_phi) * np.eye(3) + (1 - np.cos(big_phi)) * np.outer(e, e)
           + sign * np.sin(big_phi) * sk(e))
    return res(sidi_a(q), rhs)


def si_axis(rng):
    return _si_axis(rng, -1.0)


def si_axis_slip(rng):
    return _si_axis(rng, 1.0)


def _si_kde(rng, slip):
    q, w = unit(rng, 4), rng.normal(size=3)
    wx, wy, wz = w
    s = -1.0 if slip else 1.0  # the slip: omega_z's two entries of the first 2x2 block swapped
    big_omega = np.array([
        [0.0, s * wz, -wy, wx],
        [-s * wz, 0.0, wx, wy],
        [wy, -wx, 0.0, wz],
        [-wx, -wy, -wz, 0.0]])
    return res(ddt(sidi_a, q, 0.5 * big_omega @ q), -sk(w) @ sidi_a(q))


def si_kde(rng):
    return _si_kde(rng, False)


def si_kde_slip(rng):
    return _si_kde(rng, True)


def si_trace(rng):
    q = unit(rng, 4)
    return abs(4 * q[3] ** 2 - (1 + np.trace(sidi_a(q))))


# ------------------------------------------------------------------ Vince, Quaternions for CG
def vince_r(q):
    s, x, y, z = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - s * z), 2 * (x * z + s * y)],
        [2 * (x * y + s * z), 1 - 2 * (x * x + z * z), 2 * (y * z - s * x)],
        [2 * (x * z - s * y), 2 * (y * z + s * x), 1 - 2 * (x * x + y * y)]])


def _vi_rotate(rng, slip):
    q, p = unit(rng, 4), rng.normal(size=3)
    m = vince_r(q)
    if slip:  # entry (1, 2) typed 2(xy + sz)
        m[0, 1] = 2 * (q[1] * q[2] + q[0] * q[3])
    lhs = ham(ham(q, np.concatenate([[0.0], p])), conj(q) / (q @ q))
    return res(lhs, np.concatenate([[0.0], m @ p]))


def vi_rotate(rng):
    return _vi_rotate(rng, False)


def vi_rotate_slip(rng):
    return _vi_rotate(rng, True)


def _vi_product(rng, sign):
    sa, sb = rng.normal(size=2)
    a, b = rng.normal(size=3), rng.normal(size=3)
    qa, qb = np.concatenate([[sa], a]), np.concatenate([[sb], b])
    rhs = np.concatenate([[sa * sb - a @ b], sa * b + sb * a + sign * np.cross(a, b)])
    return res(ham(qa, qb), rhs)


def vi_product(rng):
    return _vi_product(rng, 1.0)


def vi_product_slip(rng):
    return _vi_product(rng, -1.0)


def _vi_inverse(rng, slip):
    q = rng.normal(size=4)
    other = conj(q) if slip else conj(q) / (q @ q)
    return res(ham(q, other), np.array([1.0, 0.0, 0.0, 0.0]))


def vi_inverse(rng):
    return _vi_inverse(rng, False)


def vi_inverse_slip(rng):
    return _vi_inverse(rng, True)


def vi_norm(rng):
    qa, qb = rng.normal(size=4), rng.normal(size=4)
    return abs(np.linalg.norm(ham(qa, qb)) - np.linalg.norm(qa) * np.linalg.norm(qb))


# ------------------------------------------------------------------ Bottema & Roth
def cayley(b):
    """(1 - B)^{-1}(1 + B), B = [b]x."""
    big_b = sk(b)
    return np.linalg.inv(np.eye(3) - big_b) @ (np.eye(3) + big_b)


def _br_cayley(rng, sign):
    b = rng.normal(size=3)
    rhs = ((1 - b @ b) * np.eye(3) + 2 * np.outer(b, b) + sign * 2 * sk(b)) / (1 + b @ b)
    return res(cayley(b), rhs)


def br_cayley(rng):
    return _br_cayley(rng, 1.0)


def br_cayley_slip(rng):
    return _br_cayley(rng, -1.0)


def br_commute(rng):
    big_b = sk(rng.normal(size=3))
    one = np.eye(3)
    inv = np.linalg.inv(one - big_b)
    return res(inv @ (one + big_b), (one + big_b) @ inv)


def _br_euler_params(rng, slip):
    c0, c1, c2, c3 = rng.normal(size=4)
    delta = c0 * c0 + c1 * c1 + c2 * c2 + c3 * c3
    m = np.array([
        [c0 * c0 + c1 * c1 - c2 * c2 - c3 * c3, 2 * (c1 * c2 - c0 * c3), 2 * (c1 * c3 + c0 * c2)],
        [2 * (c1 * c2 + c0 * c3), c0 * c0 - c1 * c1 + c2 * c2 - c3 * c3, 2 * (c2 * c3 - c0 * c1)],
        [2 * (c1 * c3 - c0 * c2), 2 * (c2 * c3 + c0 * c1), c0 * c0 - c1 * c1 - c2 * c2 + c3 * c3]])
    if slip:  # entry (1, 3) typed 2(c1 c3 - c0 c2)
        m[0, 2] = 2 * (c1 * c3 - c0 * c2)
    return res(m / delta, cayley(np.array([c1, c2, c3]) / c0))


def br_euler_params(rng):
    return _br_euler_params(rng, False)


def br_euler_params_slip(rng):
    return _br_euler_params(rng, True)


def _br_axis(rng, sign):
    s, phi = unit(rng), angle(rng)
    big_s = sk(s)
    rhs = np.eye(3) + np.sin(phi) * big_s + (1 + sign * np.cos(phi)) * big_s @ big_s
    return res(cayley(np.tan(phi / 2) * s), rhs)


def br_axis(rng):
    return _br_axis(rng, -1.0)


def br_axis_slip(rng):
    return _br_axis(rng, 1.0)


def br_inverse(rng):
    b = rng.normal(size=3)
    a, one = cayley(b), np.eye(3)
    return res(sk(b), (a - one) @ np.linalg.inv(a + one))


def holds(name: str, points: int = 6, seed: int = 2024) -> bool:
    """Whether the named truth holds at ``points`` random points (:func:`_numpy_truth.holds_in`)."""
    return holds_in(globals(), name, points, seed)
