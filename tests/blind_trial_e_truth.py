"""NumPy truths of the fifth blind trial (``tests/data/blind_trial_e.json``): for each
statement, a function of a random generator returning the residual |lhs - rhs| at one random
point satisfying the declarations, the statement as its source means it (a rate by central
differences along the declared rates). Written from the sources' definitions before rigidsym
read any statement; never imports rigidsym: it is the independent judge."""

from __future__ import annotations

import numpy as np
from _numpy_truth import angle, ddt, ham, holds_in, res, rot, sk, unit, vee

# ------------------------------------------------------------------ helpers


def r_hamilton(q):
    """The active rotation of a unit quaternion [q0; q1; q2; q3], scalar first."""
    q0, q1, q2, q3 = q
    return np.array([
        [q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3, 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
        [2 * (q1 * q2 + q0 * q3), q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3, 2 * (q2 * q3 - q0 * q1)],
        [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3]])


def tangent(rng, q):
    """A random rate of the unit vector q, tangent to its sphere."""
    v = rng.normal(size=len(q))
    return v - (v @ q) * q


# ------------------------------------------------------------------ Kane & Levinson
def kane_c(eps):
    """Kane's direction cosine matrix C_ij = a_i . b_j in the Euler parameters eps_1..eps_4
    (eps_4 the scalar): the unit-norm form 1 - 2 eps_2^2 - 2 eps_3^2 on the diagonal."""
    e1, e2, e3, e4 = eps
    return np.array([
        [1 - 2 * e2**2 - 2 * e3**2, 2 * (e1 * e2 - e3 * e4), 2 * (e3 * e1 + e2 * e4)],
        [2 * (e1 * e2 + e3 * e4), 1 - 2 * e3**2 - 2 * e1**2, 2 * (e2 * e3 - e1 * e4)],
        [2 * (e3 * e1 - e2 * e4), 2 * (e2 * e3 + e1 * e4), 1 - 2 * e1**2 - 2 * e2**2]])


def _kane_axis(rng, sign):
    lam, th = unit(rng), angle(rng)
    eps = np.concatenate([lam * np.sin(th / 2), [np.cos(th / 2)]])
    rhs = (np.cos(th) * np.eye(3) + (1 - np.cos(th)) * np.outer(lam, lam)
           + sign * np.sin(th) * sk(lam))
    return res(kane_c(eps), rhs)


def kane_axis_angle(rng):
    return _kane_axis(rng, 1.0)


def kane_axis_angle_slip(rng):
    return _kane_axis(rng, -1.0)


def kane_omega_eps(rng):
    eps = unit(rng, 4)
    d = tangent(rng, eps)
    e1, e2, e3, e4 = eps
    d1, d2, d3, d4 = d
    w = 2 * np.array([e4 * d1 - e1 * d4 + e3 * d2 - e2 * d3,
                      e4 * d2 - e2 * d4 + e1 * d3 - e3 * d1,
                      e4 * d3 - e3 * d4 + e2 * d1 - e1 * d2])
    return res(ddt(kane_c, eps, d), kane_c(eps) @ sk(w))


def _kane_eps_rates(rng, slip):
    eps, w = unit(rng, 4), rng.normal(size=3)
    e1, e2, e3, e4 = eps
    if slip:  # the rows of the vector part with -[eps]_x: a rate of the space frame's omega
        top = np.array([[e4, e3, -e2], [-e3, e4, e1], [e2, -e1, e4]])
    else:
        top = np.array([[e4, -e3, e2], [e3, e4, -e1], [-e2, e1, e4]])
    m = np.vstack([top, [-e1, -e2, -e3]])
    d = 0.5 * m @ w
    return res(ddt(kane_c, eps, d), kane_c(eps) @ sk(w))


def kane_eps_rates(rng):
    return _kane_eps_rates(rng, False)


def kane_eps_rates_slip(rng):
    return _kane_eps_rates(rng, True)


def _kane_addition(rng, slip):
    cab, cbc = rot(rng), rot(rng)
    w_ab, w_bc = rng.normal(size=3), rng.normal(size=3)  # each in its own reference frame
    dab, dbc = sk(w_ab) @ cab, sk(w_bc) @ cbc  # space angular velocities
    cac, dac = cab @ cbc, dab @ cbc + cab @ dbc
    w_ac = vee(dac @ cac.T)
    return res(w_ac, w_ab + (w_bc if slip else cab @ w_bc))


def kane_addition(rng):
    return _kane_addition(rng, False)


def kane_addition_slip(rng):
    return _kane_addition(rng, True)


def kane_angular_acceleration(rng):
    c, w, wdot = rot(rng), rng.normal(size=3), rng.normal(size=3)
    cdot = c @ sk(w)  # omega in b-components
    return res(cdot @ w + c @ wdot, c @ wdot)


# ------------------------------------------------------------------ Lee, Leok & McClamroch
def lee_hat_cross(rng):
    x, y = rng.normal(size=3), rng.normal(size=3)
    return max(res(sk(x) @ y, np.cross(x, y)), res(np.cross(x, y), -sk(y) @ x))


def lee_hat_conjugate(rng):
    r, x = rot(rng), rng.normal(size=3)
    return res(r @ sk(x) @ r.T, sk(r @ x))


def _lee_trace(rng, sign):
    a, x = rng.normal(size=(3, 3)), rng.normal(size=3)
    first = np.trace(a @ sk(x))
    second = 0.5 * np.trace(sk(x) @ (a - a.T))
    third = sign * x @ vee(a - a.T)
    return max(abs(first - second), abs(second - third))


def lee_trace(rng):
    return _lee_trace(rng, -1.0)


def lee_trace_slip(rng):
    return _lee_trace(rng, 1.0)


def lee_hat_sym(rng):
    a, x = rng.normal(size=(3, 3)), rng.normal(size=3)
    return res(sk(x) @ a + a.T @ sk(x), sk((np.trace(a) * np.eye(3) - a) @ x))


def _lee_psi(rng, sign):
    r, rd = rot(rng), rot(rng)
    om, omd = rng.normal(size=3), rng.normal(size=3)  # body angular velocities
    rdot, rddot = r @ sk(om), rd @ sk(omd)
    psi_dot = -0.5 * np.trace(rddot.T @ r + rd.T @ rdot)
    e_r = 0.5 * vee(rd.T @ r - r.T @ rd)
    e_om = om + sign * r.T @ rd @ omd
    return abs(psi_dot - e_r @ e_om)


def lee_psi_rate(rng):
    return _lee_psi(rng, -1.0)


def lee_psi_rate_slip(rng):
    return _lee_psi(rng, 1.0)


def _lee_er_rate(rng, slip):
    r, rd = rot(rng), rot(rng)
    om, omd = rng.normal(size=3), rng.normal(size=3)
    rdot, rddot = r @ sk(om), rd @ sk(omd)
    e_dot = 0.5 * vee(rddot.T @ r + rd.T @ rdot - rdot.T @ rd - r.T @ rddot)
    e_om = om - r.T @ rd @ omd
    m = rd.T @ r if slip else r.T @ rd
    return res(e_dot, 0.5 * (np.trace(r.T @ rd) * np.eye(3) - m) @ e_om)


def lee_er_rate(rng):
    return _lee_er_rate(rng, False)


def lee_er_rate_slip(rng):
    return _lee_er_rate(rng, True)


# ------------------------------------------------------------------ Holm
def _holm_double_hat(rng, sign):
    u, v = rng.normal(size=3), rng.normal(size=3)
    return res(sk(u) @ sk(u) @ v, sign * (u * (u @ v) - (u @ u) * v))


def holm_double_hat(rng):
    return _holm_double_hat(rng, 1.0)


def holm_double_hat_slip(rng):
    return _holm_double_hat(rng, -1.0)


def holm_spatial_body(rng):
    o, om = rot(rng), rng.normal(size=3)  # Omega: the body angular velocity of O
    odot = o @ sk(om)
    return res(odot @ o.T, o @ sk(om) @ np.linalg.inv(o))


def _holm_momentum(rng, slip):
    o, om, pi = rot(rng), rng.normal(size=3), rng.normal(size=3)
    odot = o @ sk(om)
    pidot = np.cross(om, pi) if slip else np.cross(pi, om)
    return res(odot @ pi + o @ pidot, np.zeros(3))


def holm_spatial_momentum(rng):
    return _holm_momentum(rng, False)


def holm_spatial_momentum_slip(rng):
    return _holm_momentum(rng, True)


def holm_casimir(rng):
    inertia, pi = np.diag(rng.uniform(0.5, 3.0, size=3)), rng.normal(size=3)
    pidot = np.cross(pi, np.linalg.solve(inertia, pi))
    return abs(ddt(lambda x: x @ x, pi, pidot))


def holm_energy(rng):
    inertia, pi = np.diag(rng.uniform(0.5, 3.0, size=3)), rng.normal(size=3)
    pidot = np.cross(pi, np.linalg.solve(inertia, pi))
    return abs(ddt(lambda x: 0.5 * x @ np.linalg.solve(inertia, x), pi, pidot))


def holm_energy_slip(rng):
    inertia, pi = np.diag(rng.uniform(0.5, 3.0, size=3)), rng.normal(size=3)
    pidot = np.cross(pi, inertia @ pi)  # slip: I Pi for I^{-1} Pi in the rate
    return abs(ddt(lambda x: 0.5 * x @ np.linalg.solve(inertia, x), pi, pidot))


# ------------------------------------------------------------------ Savage
def savage_c(phi, power=2):
    """C_B^I of the rotation vector phi: I + sin(f)/f (phi x) + (1 - cos f)/f^power (phi x)^2."""
    f = np.linalg.norm(phi)
    p = sk(phi)
    return np.eye(3) + np.sin(f) / f * p + (1 - np.cos(f)) / f**power * p @ p


def savage_axis(rng):
    phi = rng.normal(size=3)
    return res(savage_c(phi) @ phi, phi)


def _savage_orth(rng, power):
    c = savage_c(rng.normal(size=3), power)
    return res(c.T @ c, np.eye(3))


def savage_orth(rng):
    return _savage_orth(rng, 2)


def savage_orth_slip(rng):
    return _savage_orth(rng, 1)


def _savage_cbn(rng, sign):
    cbi, cni = rot(rng), rot(rng)
    wb, wn = rng.normal(size=3), rng.normal(size=3)  # body rates of C_B^I and C_N^I
    dbi, dni = cbi @ sk(wb), cni @ sk(wn)
    cbn = cni.T @ cbi
    dbn = dni.T @ cbi + cni.T @ dbi
    return res(dbn, cbn @ sk(wb) + sign * sk(wn) @ cbn)


def savage_cbn_rate(rng):
    return _savage_cbn(rng, -1.0)


def savage_cbn_rate_slip(rng):
    return _savage_cbn(rng, 1.0)


def _savage_bortz(rng, half):
    phi, w = rng.normal(size=3), rng.normal(size=3)
    f = np.linalg.norm(phi)
    pdot = (w + half * np.cross(phi, w)
            + (1 - f * np.sin(f) / (2 * (1 - np.cos(f)))) / f**2 * np.cross(phi, np.cross(phi, w)))
    return res(ddt(savage_c, phi, pdot), savage_c(phi) @ sk(w))


def savage_bortz(rng):
    return _savage_bortz(rng, 0.5)


def savage_bortz_slip(rng):
    return _savage_bortz(rng, -0.5)


# ------------------------------------------------------------------ Jain
def jain_phi(l_vec):
    """phi(x, y) = [I l~; 0 I], l = l(x, y) from x to y."""
    out = np.eye(6)
    out[:3, 3:] = sk(l_vec)
    return out


def jain_compose(rng):
    a, b = rng.normal(size=3), rng.normal(size=3)
    return res(jain_phi(a + b), jain_phi(a) @ jain_phi(b))


def jain_inverse(rng):
    l_vec = rng.normal(size=3)
    return res(np.linalg.inv(jain_phi(l_vec)), jain_phi(-l_vec))


def jain_inverse_slip(rng):
    l_vec = rng.normal(size=3)
    return res(np.linalg.inv(jain_phi(l_vec)), jain_phi(l_vec).T)


def jain_velocity(rng):
    om, v, l_vec = rng.normal(size=3), rng.normal(size=3), rng.normal(size=3)
    return res(np.concatenate([om, v + np.cross(om, l_vec)]),
               jain_phi(l_vec).T @ np.concatenate([om, v]))


def jain_power(rng):
    vx, fy, l_vec = rng.normal(size=6), rng.normal(size=6), rng.normal(size=3)
    vy, fx = jain_phi(l_vec).T @ vx, jain_phi(l_vec) @ fy
    return abs(vy @ fy - vx @ fx)


def _jain_m(jc, m, p):
    out = np.zeros((6, 6))
    out[:3, :3] = jc - m * sk(p) @ sk(p)
    out[:3, 3:] = m * sk(p)
    out[3:, :3] = -m * sk(p)
    out[3:, 3:] = m * np.eye(3)
    return out


def _jain_inertia(rng, slip):
    jc = rng.normal(size=(3, 3))
    jc = jc + jc.T
    m, p, l_vec = rng.uniform(0.5, 3.0), rng.normal(size=3), rng.normal(size=3)
    phi = jain_phi(l_vec)
    rhs = phi.T @ _jain_m(jc, m, p) @ phi if slip else phi @ _jain_m(jc, m, p) @ phi.T
    # M(x): the same body's inertia about x, its mass centre at l(x, z) + p(z) from x
    return res(_jain_m(jc, m, l_vec + p), rhs)


def jain_inertia(rng):
    return _jain_inertia(rng, False)


def jain_inertia_slip(rng):
    return _jain_inertia(rng, True)


def jain_inertia_from_momentum(rng):
    """A cross-check of _jain_m itself from the particles' momenta (not a statement)."""
    masses, pts = rng.uniform(0.5, 2.0, size=4), rng.normal(size=(4, 3))
    om, v = rng.normal(size=3), rng.normal(size=3)  # the velocity of the point at the origin
    m, c = masses.sum(), masses @ pts / masses.sum()
    jc = sum(mi * ((r - c) @ (r - c) * np.eye(3) - np.outer(r - c, r - c))
             for mi, r in zip(masses, pts, strict=True))
    vel = [v + np.cross(om, r) for r in pts]
    moment = sum(mi * np.cross(r, vi) for mi, r, vi in zip(masses, pts, vel, strict=True))
    h = np.concatenate([moment, sum(mi * vi for mi, vi in zip(masses, vel, strict=True))])
    return res(h, _jain_m(jc, m, c) @ np.concatenate([om, v]))


# ------------------------------------------------------------------ Taylor
def _taylor_point(rng):
    m, r, om = rng.uniform(0.5, 3.0), rng.normal(size=3), rng.normal(size=3)
    return m, r, om, m * np.cross(r, np.cross(om, r))


def _taylor_i(m, r, slip=False):
    x, y, z = r
    return m * np.array([[y * y + z * z, (x * y if slip else -x * y), -x * z],
                         [-y * x, z * z + x * x, -y * z],
                         [-z * x, -z * y, x * x + y * y]])


def taylor_l(rng):
    m, r, om, ang = _taylor_point(rng)
    return res(ang, _taylor_i(m, r) @ om)


def taylor_l_slip(rng):
    m, r, om, ang = _taylor_point(rng)
    return res(ang, _taylor_i(m, r, slip=True) @ om)


def taylor_kinetic(rng):
    m, r, om, ang = _taylor_point(rng)
    v = np.cross(om, r)
    return abs(0.5 * m * v @ v - 0.5 * om @ ang)


def taylor_axis(rng):
    m, r, _, _ = _taylor_point(rng)
    u = unit(rng)
    return abs(u @ _taylor_i(m, r) @ u - m * (r @ r - (r @ u) ** 2))


def _taylor_top(rng, sign):
    l1, l3, w0, w3, t = rng.uniform(0.5, 3.0, size=5)
    big_om = (l3 - l1) * w3 / l1
    w1 = lambda s: w0 * np.cos(big_om * s)  # noqa: E731
    w2 = sign * w0 * np.sin(big_om * t)
    w1dot = ddt(lambda s: w1(s[0]), [t], [1.0])
    return abs(l1 * w1dot - (l1 - l3) * w2 * w3)


def taylor_top(rng):
    return _taylor_top(rng, 1.0)


def taylor_top_slip(rng):
    return _taylor_top(rng, -1.0)


# ------------------------------------------------------------------ Hanson
def hanson_rotate(rng):
    q, v = unit(rng, 4), rng.normal(size=3)
    qbar = np.concatenate([[q[0]], -q[1:]])
    lhs = ham(ham(q, np.concatenate([[0.0], v])), qbar)
    return res(lhs, np.concatenate([[0.0], r_hamilton(q) @ v]))


def _hanson_trace(rng, a, b):
    q = unit(rng, 4)
    return abs(np.trace(r_hamilton(q)) - (a * q[0] ** 2 - b))


def hanson_trace(rng):
    return _hanson_trace(rng, 4.0, 1.0)


def _hanson_axis(rng, sign):
    n, th = unit(rng), angle(rng)
    q = np.concatenate([[np.cos(th / 2)], n * np.sin(th / 2)])
    rhs = np.cos(th) * np.eye(3) + (1 - np.cos(th)) * np.outer(n, n) + sign * np.sin(th) * sk(n)
    return res(r_hamilton(q), rhs)


def hanson_axis_angle(rng):
    return _hanson_axis(rng, 1.0)


def hanson_axis_angle_slip(rng):
    return _hanson_axis(rng, -1.0)


def hanson_norm(rng):
    q, p = rng.normal(size=4), rng.normal(size=4)
    return abs(np.linalg.norm(ham(q, p)) - np.linalg.norm(q) * np.linalg.norm(p))


def _hanson_compose(rng, slip):
    q, p = unit(rng, 4), unit(rng, 4)
    rq, rp = r_hamilton(q), r_hamilton(p)
    return res(r_hamilton(ham(q, p)), rp @ rq if slip else rq @ rp)


def hanson_compose(rng):
    return _hanson_compose(rng, False)


def hanson_compose_slip(rng):
    return _hanson_compose(rng, True)


def holds(name: str, points: int = 6, seed: int = 2024) -> bool:
    """Whether the named truth holds at ``points`` random points (:func:`_numpy_truth.holds_in`)."""
    return holds_in(globals(), name, points, seed)
