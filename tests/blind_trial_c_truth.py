"""NumPy truths of the third blind trial (``tests/data/blind_trial_c.json``): for each
statement, a function of a random generator returning the residual |lhs - rhs| at one random
point satisfying the declarations, the statement as its book means it (a rate by central
differences along the declared rates). Written from the books' definitions before rigidsym
read any statement; never imports rigidsym: it is the independent judge."""

from __future__ import annotations

import numpy as np
from _numpy_truth import (
    angle,
    ax,
    ay,
    az,
    ddt,
    expm,
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
)

# ------------------------------------------------------------------ helpers


def conj(q):
    return np.concatenate([[q[0]], -q[1:]])


def r_scalar_first(q):
    """Active rotation of a unit quaternion [s; x; y; z] (Farrell, LaValle)."""
    s, x, y, z = q
    return np.array([
        [s * s + x * x - y * y - z * z, 2 * (x * y - s * z), 2 * (x * z + s * y)],
        [2 * (x * y + s * z), s * s - x * x + y * y - z * z, 2 * (y * z - s * x)],
        [2 * (x * z - s * y), 2 * (y * z + s * x), s * s - x * x - y * y + z * z]])


def r_szeliski(q, slip=False):
    """Szeliski (2.41): q = (x, y, z, w), scalar last."""
    x, y, z, w = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y + z * w) if slip else 2 * (x * y - z * w),
         2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def szeliski_product(a, b):
    """Szeliski (2.42): q0 q1 = (v0 x v1 + w0 v1 + w1 v0, w0 w1 - v0 . v1)."""
    v0, w0, v1, w1 = a[:3], a[3], b[:3], b[3]
    return np.concatenate([np.cross(v0, v1) + w0 * v1 + w1 * v0, [w0 * w1 - v0 @ v1]])


# ------------------------------------------------------------------ Jazar
def jazar_rodrigues(rng):
    u, ph = unit(rng), angle(rng)
    rhs = np.eye(3) * np.cos(ph) + np.outer(u, u) * (1 - np.cos(ph)) + sk(u) * np.sin(ph)
    return res(expm(sk(u) * ph), rhs)


def jazar_tilde_sq(rng):
    u = unit(rng)
    return res(sk(u) @ sk(u), np.outer(u, u) - np.eye(3))


def jazar_tilde_cube_slip(rng):
    u = unit(rng)
    return res(sk(u) @ sk(u) @ sk(u), sk(u))


def jazar_qz_inverse(rng):
    a = angle(rng)
    return res(az(-a) @ az(a), np.eye(3))


def jazar_qz_compose(rng):
    a, b = angle(rng), angle(rng)
    return res(az(a) @ az(b), az(a + b))


def jazar_qx_qy_commute_slip(rng):
    g, b = angle(rng), angle(rng)
    return res(ax(g) @ ay(b), ay(b) @ ax(g))


def jazar_omega_global(rng):
    r, w = rot(rng), rng.normal(size=3)
    rdot = sk(w) @ r  # omega is the (global) angular velocity of R
    return res(rdot @ r.T, sk(w))


def jazar_omega_body(rng):
    r, w = rot(rng), rng.normal(size=3)
    rdot = sk(w) @ r
    return res(r.T @ rdot, sk(r.T @ w))


# ------------------------------------------------------------------ Khalil & Dombre
def _khalil_rot(u, th):
    return np.outer(u, u) * (1 - np.cos(th)) + np.eye(3) * np.cos(th) + sk(u) * np.sin(th)


def khalil_axis_fixed(rng):
    u, th = unit(rng), angle(rng)
    return res(_khalil_rot(u, th) @ u, u)


def khalil_trace(rng):
    u, th = unit(rng), angle(rng)
    return abs(np.trace(_khalil_rot(u, th)) - (1 + 2 * np.cos(th)))


def khalil_skew_part_slip(rng):
    u, th = unit(rng), angle(rng)
    a = _khalil_rot(u, th)
    return res(a - a.T, 2 * sk(u) * np.cos(th))


def khalil_adot(rng):
    a, w = rot(rng), rng.normal(size=3)
    adot = sk(w) @ a
    return res(adot, sk(w) @ a)


def khalil_hat_anticommute(rng):
    u, v = rng.normal(size=3), rng.normal(size=3)
    return res(sk(u) @ v, -sk(v) @ u)


def khalil_hat_conjugate(rng):
    a, v = rot(rng), rng.normal(size=3)
    return res(a @ sk(v) @ a.T, sk(a @ v))


def _khalil_t(a, p):
    t = np.eye(4)
    t[:3, :3], t[:3, 3] = a, p
    return t


def khalil_t_inverse(rng):
    a, p = rot(rng), rng.normal(size=3)
    return res(np.linalg.inv(_khalil_t(a, p)), _khalil_t(a.T, -a.T @ p))


def khalil_t_inverse_slip(rng):
    a, p = rot(rng), rng.normal(size=3)
    return res(np.linalg.inv(_khalil_t(a, p)), _khalil_t(a.T, -a @ p))


# ------------------------------------------------------------------ LaValle
def _lavalle_r(h):
    a, b, c, d = h
    return np.array([
        [2 * (a * a + b * b) - 1, 2 * (b * c - a * d), 2 * (b * d + a * c)],
        [2 * (b * c + a * d), 2 * (a * a + c * c) - 1, 2 * (c * d - a * b)],
        [2 * (b * d - a * c), 2 * (c * d + a * b), 2 * (a * a + d * d) - 1]])


def lavalle_orthogonal(rng):
    r = _lavalle_r(unit(rng, 4))
    return res(r.T @ r, np.eye(3))


def lavalle_trace(rng):
    h = unit(rng, 4)
    return abs(np.trace(_lavalle_r(h)) - (4 * h[0] ** 2 - 1))


def lavalle_skew_part(rng):
    h = unit(rng, 4)
    r = _lavalle_r(h)
    return res(r - r.T, 4 * h[0] * sk(h[1:]))


def lavalle_skew_part_slip(rng):
    h = unit(rng, 4)
    r = _lavalle_r(h)
    return res(r - r.T, 2 * h[0] * sk(h[1:]))


def _ypr(al, be, ga, slip=False):
    ca, sa, cb, sb, cg, sg = (np.cos(al), np.sin(al), np.cos(be), np.sin(be), np.cos(ga),
                              np.sin(ga))
    return np.array([
        [ca * cb, ca * sb * sg + sa * cg if slip else ca * sb * sg - sa * cg,
         ca * sb * cg + sa * sg],
        [sa * cb, sa * sb * sg + ca * cg, sa * sb * cg - ca * sg],
        [-sb, cb * sg, cb * cg]])


def lavalle_yaw_pitch_roll(rng):
    al, be, ga = angle(rng), angle(rng), angle(rng)
    return res(az(al) @ ay(be) @ ax(ga), _ypr(al, be, ga))


def lavalle_yaw_pitch_roll_slip(rng):
    al, be, ga = angle(rng), angle(rng), angle(rng)
    return res(az(al) @ ay(be) @ ax(ga), _ypr(al, be, ga, slip=True))


# ------------------------------------------------------------------ Szeliski
def szeliski_decomposition(rng):
    n, th, v = unit(rng), angle(rng), rng.normal(size=3)
    par = n * (n @ v)
    perp = v - par
    cross = np.cross(n, v)
    return res(rodrigues(n, th) @ v, par + np.cos(th) * perp + np.sin(th) * cross)


def szeliski_exp(rng):
    n, th = unit(rng), angle(rng)
    return res(expm(sk(th * n)), rodrigues(n, th))


def _szeliski_q(n, th):
    return np.concatenate([np.sin(th / 2) * n, [np.cos(th / 2)]])


def szeliski_quaternion_matrix(rng):
    n, th = unit(rng), angle(rng)
    return res(r_szeliski(_szeliski_q(n, th)), rodrigues(n, th))


def szeliski_quaternion_matrix_slip(rng):
    n, th = unit(rng), angle(rng)
    return res(r_szeliski(_szeliski_q(n, th), slip=True), rodrigues(n, th))


def szeliski_product_written_out(rng):
    a, b = unit(rng, 4), unit(rng, 4)
    return res(r_szeliski(szeliski_product(a, b)), r_szeliski(a) @ r_szeliski(b))


def szeliski_product_otimes(rng):
    # the same statement, the book's product q0 q1 written \otimes: Szeliski's meaning
    return szeliski_product_written_out(rng)


# ------------------------------------------------------------------ Farrell
def _farrell_rate(b, w):
    return 0.5 * np.concatenate([[-b[1:] @ w], b[0] * w + sk(b[1:]) @ w])


def farrell_quaternion_rate(rng):
    b, w = unit(rng, 4), rng.normal(size=3)
    rdot = ddt(r_scalar_first, b, _farrell_rate(b, w))
    return res(rdot, r_scalar_first(b) @ sk(w))


def farrell_quaternion_rate_slip(rng):
    b, w = unit(rng, 4), rng.normal(size=3)
    rdot = ddt(r_scalar_first, b, _farrell_rate(b, w))
    return res(rdot, sk(w) @ r_scalar_first(b))


def farrell_omega_cube(rng):
    w = rng.normal(size=3)
    o = sk(w)
    return res(o @ o @ o, -(w @ w) * o)


# ------------------------------------------------------------------ Stevens, Lewis & Johnson
def _euler_rates(phi, th, p, q, r, slip=False):
    phidot = p + (q * np.sin(phi) + r * np.cos(phi)) * np.tan(th)
    thdot = q * np.cos(phi) + r * np.sin(phi) if slip else q * np.cos(phi) - r * np.sin(phi)
    psidot = (q * np.sin(phi) + r * np.cos(phi)) / np.cos(th)
    return np.array([phidot, thdot, psidot])


def _c_bn(x):
    phi, th, psi = x
    return px(phi) @ py(th) @ pz(psi)


def _stevens_euler(rng, slip):
    x = np.array([angle(rng), rng.uniform(-1.4, 1.4), angle(rng)])
    w = rng.normal(size=3)
    cdot = ddt(_c_bn, x, _euler_rates(x[0], x[1], *w, slip=slip))
    return res(cdot, -sk(w) @ _c_bn(x))


def stevens_euler_rates(rng):
    return _stevens_euler(rng, False)


def stevens_euler_rates_slip(rng):
    return _stevens_euler(rng, True)


def stevens_quaternion_rate(rng):
    q, (p_, q_, r_) = unit(rng, 4), rng.normal(size=3)
    om = np.array([[0, -p_, -q_, -r_], [p_, 0, r_, -q_], [q_, -r_, 0, p_], [r_, q_, -p_, 0]])
    qdot = 0.5 * om @ q

    def c(x):
        return r_scalar_first(x).T

    return res(ddt(c, q, qdot), -sk(np.array([p_, q_, r_])) @ c(q))


def stevens_gravity(rng):
    phi, th, psi, g = angle(rng), angle(rng), angle(rng), rng.normal()
    lhs = _c_bn((phi, th, psi)) @ np.array([0, 0, g])
    return res(lhs, g * np.array([-np.sin(th), np.sin(phi) * np.cos(th),
                                  np.cos(phi) * np.cos(th)]))


def stevens_gravity_slip(rng):
    phi, th, psi, g = angle(rng), angle(rng), angle(rng), rng.normal()
    lhs = _c_bn((phi, th, psi)) @ np.array([0, 0, g])
    return res(lhs, g * np.array([np.sin(th), np.sin(phi) * np.cos(th),
                                  np.cos(phi) * np.cos(th)]))


# ------------------------------------------------------------------ Thornton & Marion
def _point_inertia(m, r):
    return m * ((r @ r) * np.eye(3) - np.outer(r, r))


def thornton_angular_momentum(rng):
    m, r, w = rng.normal(), rng.normal(size=3), rng.normal(size=3)
    return res(m * np.cross(r, np.cross(w, r)), _point_inertia(m, r) @ w)


def thornton_kinetic_energy(rng):
    m, r, w = rng.normal(), rng.normal(size=3), rng.normal(size=3)
    v = np.cross(w, r)
    return abs(0.5 * w @ _point_inertia(m, r) @ w - 0.5 * m * (v @ v))


def thornton_kinetic_energy_slip(rng):
    m, r, w = rng.normal(), rng.normal(size=3), rng.normal(size=3)
    return abs(0.5 * w @ _point_inertia(m, r) @ w - 0.5 * m * (w @ w) * (r @ r))


def thornton_rotated_inertia(rng):
    m, r, lam = rng.normal(), rng.normal(size=3), rot(rng)
    return res(lam @ _point_inertia(m, r) @ lam.T, _point_inertia(m, lam @ r))


def _two_particles(m, r, a):
    return _point_inertia(m, r - a) + _point_inertia(m, r + a)


def thornton_parallel_axis(rng):
    m, r, a = rng.normal(), rng.normal(size=3), rng.normal(size=3)
    big_m = 2 * m
    rhs = 2 * _point_inertia(m, r) + big_m * ((a @ a) * np.eye(3) - np.outer(a, a))
    return res(_two_particles(m, r, a), rhs)


def thornton_parallel_axis_slip(rng):
    m, r, a = rng.normal(), rng.normal(size=3), rng.normal(size=3)
    big_m = 2 * m
    rhs = 2 * _point_inertia(m, r) + big_m * ((a @ a) * np.eye(3) + np.outer(a, a))
    return res(_two_particles(m, r, a), rhs)


def thornton_trace_invariant(rng):
    lam, j = rot(rng), rng.normal(size=(3, 3))
    j = j + j.T
    return abs(np.trace(lam @ j @ lam.T) - np.trace(j))


# ------------------------------------------------------------------ Stillwell
def stillwell_jacobi(rng):
    a = rng.normal(size=(2, 2))
    return abs(np.linalg.det(expm(a)) - np.exp(np.trace(a)))


def stillwell_norm_multiplicative(rng):
    p, q = rng.normal(size=4), rng.normal(size=4)
    return abs(np.linalg.norm(ham(p, q)) - np.linalg.norm(p) * np.linalg.norm(q))


def stillwell_q_qbar(rng):
    q = rng.normal(size=4)
    return res(ham(q, conj(q)), (q @ q) * np.array([1.0, 0, 0, 0]))


def stillwell_conjugate_slip(rng):
    p, q = rng.normal(size=4), rng.normal(size=4)
    return res(conj(ham(p, q)), ham(conj(p), conj(q)))


def stillwell_conjugate(rng):
    p, q = rng.normal(size=4), rng.normal(size=4)
    return res(conj(ham(p, q)), ham(conj(q), conj(p)))


def stillwell_bracket(rng):
    x, y = rng.normal(size=3), rng.normal(size=3)
    X, Y = sk(x), sk(y)  # noqa: N806
    return res(X @ Y - Y @ X, sk(np.cross(x, y)))


def stillwell_bracket_slip(rng):
    x, y = rng.normal(size=3), rng.normal(size=3)
    X, Y = sk(x), sk(y)  # noqa: N806
    return res(X @ Y - Y @ X, sk(np.cross(y, x)))


def holds(name: str, points: int = 6, seed: int = 2024) -> bool:
    """Whether the named truth holds at ``points`` random points (:func:`_numpy_truth.holds_in`)."""
    return holds_in(globals(), name, points, seed)
