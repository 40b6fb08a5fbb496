# ruff: noqa: E501 - the LaTeX of a book equation is one line, as typed
"""Equations of six books typed from memory, second set: 40 equations.

Books (none named by the LaTeX corpus, any test, docs/check-latex.md or the first trial,
``latex_books_typed_a.py``): Wie, *Space Vehicle Dynamics and Control* (1998); Wittenburg,
*Dynamics of Multibody Systems* (2008); Greenwood, *Advanced Dynamics* (2003); Groves,
*Principles of GNSS, Inertial, and Multisensor Integrated Navigation Systems* (2013);
Hartley & Zisserman, *Multiple View Geometry in Computer Vision* (2003); Shabana,
*Dynamics of Multibody Systems* (2005).

Each case: an id, its book, the LaTeX and the `--let`s as a reader of that book types them
(written before reading the corpus), `slip` (a deliberate one-edit slip of a true
equation), and a truth: a NumPy function of a random generator returning the residual
|lhs - rhs| at one random point of the declarations (for a kinematic equation, the time
derivative by central differences along the declared rates). The truth never imports
rigidsym: it is the independent judge. The verdicts as typed, the checker without the books'
readings, are :data:`BASELINE`; as typed, with them, :data:`AS_TYPED`; after the one attempt a
reader makes after the message (:data:`ATTEMPT`) :data:`AS_ATTEMPTED`.
"""

from __future__ import annotations

import numpy as np

# ---------------------------------------------------------------- NumPy helpers


def _sk(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def _unit(rng, n=3):
    v = rng.normal(size=n)
    return v / np.linalg.norm(v)


def _rot(rng):
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return q * np.sign(np.linalg.det(q))


def _res(a, b):
    return float(np.max(np.abs(np.asarray(a, float) - np.asarray(b, float))))


def _ddt(f, x0, xdot, h=1e-6):
    """d/dt f(x(t)) at t = 0 along x(t) = x0 + t xdot."""
    return (f(x0 + h * xdot) - f(x0 - h * xdot)) / (2 * h)


def _p1(x):
    """Passive elementary rotations (Wie's C_1, C_2, C_3)."""
    c, s = np.cos(x), np.sin(x)
    return np.array([[1, 0, 0], [0, c, s], [0, -s, c]])


def _p2(x):
    c, s = np.cos(x), np.sin(x)
    return np.array([[c, 0, -s], [0, 1, 0], [s, 0, c]])


def _p3(x):
    c, s = np.cos(x), np.sin(x)
    return np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]])


# ---------------------------------------------------------------- Wie


def _wie_c(q):
    q1, q2, q3, q4 = q
    return np.array([
        [1 - 2 * (q2 * q2 + q3 * q3), 2 * (q1 * q2 + q3 * q4), 2 * (q1 * q3 - q2 * q4)],
        [2 * (q2 * q1 - q3 * q4), 1 - 2 * (q1 * q1 + q3 * q3), 2 * (q2 * q3 + q1 * q4)],
        [2 * (q3 * q1 + q2 * q4), 2 * (q3 * q2 - q1 * q4), 1 - 2 * (q1 * q1 + q2 * q2)]])


def t_wie_orth(rng):
    c = _wie_c(_unit(rng, 4))
    return _res(c.T @ c, np.eye(3))


def t_wie_trace(rng, slip=False):
    q = _unit(rng, 4)
    return _res(np.trace(_wie_c(q)), 4 * q[3] ** 2 - (3 if slip else 1))


def t_k_wie_quat(rng, slip=False):
    q, w = _unit(rng, 4), rng.normal(size=3)
    w1, w2, w3 = w
    q1, q2, q3, q4 = q
    qd = 0.5 * np.array([w3 * q2 + (1 if slip else -1) * w2 * q3 + w1 * q4,
                         -w3 * q1 + w1 * q3 + w2 * q4,
                         w2 * q1 - w1 * q2 + w3 * q4,
                         -w1 * q1 - w2 * q2 - w3 * q3])
    return _res(_ddt(_wie_c, q, qd), -_sk(w) @ _wie_c(q))


def _wie_b(t1, t2):
    return np.array([[1, 0, -np.sin(t2)],
                     [0, np.cos(t1), np.sin(t1) * np.cos(t2)],
                     [0, -np.sin(t1), np.cos(t1) * np.cos(t2)]])


def t_wie_321_inverse(rng):
    t1, t2 = rng.uniform(-1.3, 1.3, size=2)
    s1, c1, s2, c2 = np.sin(t1), np.cos(t1), np.sin(t2), np.cos(t2)
    inv = np.array([[c2, s1 * s2, c1 * s2], [0, c1 * c2, -s1 * c2], [0, s1, c1]]) / c2
    return _res(inv @ _wie_b(t1, t2), np.eye(3))


def _wie_321(x):
    return _p1(x[0]) @ _p2(x[1]) @ _p3(x[2])


def t_k_wie_321(rng):
    x, xd = rng.uniform(-1.2, 1.2, size=3), rng.normal(size=3)
    w = _wie_b(x[0], x[1]) @ xd
    return _res(_ddt(_wie_321, x, xd), -_sk(w) @ _wie_321(x))


# ---------------------------------------------------------------- Wittenburg


def t_wit_tilde_comm(rng, slip=False):
    a, b = rng.normal(size=3), rng.normal(size=3)
    rhs = _sk(np.cross(b, a) if slip else np.cross(a, b))
    return _res(_sk(a) @ _sk(b) - _sk(b) @ _sk(a), rhs)


def t_wit_tilde_ab(rng):
    a, b = rng.normal(size=3), rng.normal(size=3)
    return _res(_sk(a) @ _sk(b), np.outer(b, a) - (a @ b) * np.eye(3))


def _wit_a(n, phi):
    q0, q = np.cos(phi / 2), np.sin(phi / 2) * n
    return (2 * q0 * q0 - 1) * np.eye(3) + 2 * (np.outer(q, q) + q0 * _sk(q))


def t_wit_ep_axis(rng):
    n, phi = _unit(rng), rng.uniform(-3, 3)
    return _res(_wit_a(n, phi) @ (np.sin(phi / 2) * n), np.sin(phi / 2) * n)


def t_wit_ep_orth(rng):
    a = _wit_a(_unit(rng), rng.uniform(-3, 3))
    return _res(a.T @ a, np.eye(3))


def t_wit_rodrigues(rng):
    n, phi = _unit(rng), rng.uniform(-3, 3)
    rod = np.eye(3) * np.cos(phi) + np.outer(n, n) * (1 - np.cos(phi)) + _sk(n) * np.sin(phi)
    return _res(_wit_a(n, phi), rod)


def _a1(x):
    """Active elementary rotations (Wittenburg's Bryan angles)."""
    return _p1(x).T


def _wit_bryan(x):
    return _a1(x[0]) @ _p2(x[1]).T @ _p3(x[2]).T


def t_k_wit_bryan(rng):
    x, xd = rng.uniform(-1.2, 1.2, size=3), rng.normal(size=3)
    (_, p2, p3), (d1, d2, d3) = x, xd
    w = np.array([d1 * np.cos(p2) * np.cos(p3) + d2 * np.sin(p3),
                  -d1 * np.cos(p2) * np.sin(p3) + d2 * np.cos(p3),
                  d1 * np.sin(p2) + d3])
    return _res(_wit_bryan(x).T @ _ddt(_wit_bryan, x, xd), _sk(w))


# ---------------------------------------------------------------- Greenwood


def t_gr_ep_norm(rng, slip=False):
    psi, th, phi = rng.uniform(-3, 3, size=3)
    e0 = np.cos(th / 2) * np.cos((phi + psi) / 2)
    e1 = np.sin(th / 2) * np.cos((phi - psi) / 2)
    e2 = np.sin(th / 2) * np.sin(((phi + psi) if slip else (phi - psi)) / 2)
    e3 = np.cos(th / 2) * np.sin((phi + psi) / 2)
    return _res(e0 ** 2 + e1 ** 2 + e2 ** 2 + e3 ** 2, 1.0)


def _gr_w(x, xd):
    psi, th, phi = x
    pd, td, fd = xd
    return np.array([pd * np.sin(th) * np.sin(phi) + td * np.cos(phi),
                     pd * np.sin(th) * np.cos(phi) - td * np.sin(phi),
                     pd * np.cos(th) + fd])


def t_gr_omega_sq(rng, slip=False):
    x, xd = rng.uniform(-3, 3, size=3), rng.normal(size=3)
    w = _gr_w(x, xd)
    pd, td, fd = xd
    return _res(w @ w, pd * pd + td * td + fd * fd + (-2 if slip else 2) * pd * fd * np.cos(x[1]))


def _gr_313(x):
    psi, th, phi = x
    return _p3(phi) @ _p1(th) @ _p3(psi)


def t_gr_313_orth(rng):
    c = _gr_313(rng.uniform(-3, 3, size=3))
    return _res(c.T @ c, np.eye(3))


def t_k_gr_313(rng, slip=False):
    x, xd = rng.uniform(-3, 3, size=3), rng.normal(size=3)
    w = _gr_w(x, xd)
    if slip:
        w[2] = xd[0] * np.cos(x[1]) - xd[2]
    return _res(_ddt(_gr_313, x, xd), -_sk(w) @ _gr_313(x))


# ---------------------------------------------------------------- Groves


def t_grv_omega_rot(rng, slip=False):
    cib, wi = _rot(rng), rng.normal(size=3)
    wb = cib @ wi
    rhs = cib.T @ _sk(wi) @ cib if slip else cib @ _sk(wi) @ cib.T
    return _res(_sk(wb), rhs)


def t_grv_cross(rng):
    w, l_ = rng.normal(size=3), rng.normal(size=3)
    return _res(_sk(w) @ l_, np.cross(w, l_))


def _grv_cnb(x):
    """Groves' C_n^b of the roll, pitch, yaw (phi, theta, psi)."""
    return _p1(x[0]) @ _p2(x[1]) @ _p3(x[2])


def t_k_grv_euler(rng, slip=False):
    x, xd = rng.uniform(-1.2, 1.2, size=3), rng.normal(size=3)
    b = _wie_b(x[0], x[1])
    if slip:
        b[1, 2] = -b[1, 2]
    w = b @ xd
    return _res(_ddt(lambda y: _grv_cnb(y).T, x, xd), _grv_cnb(x).T @ _sk(w))


# ---------------------------------------------------------------- Hartley & Zisserman


def t_hz_cross_m(rng, slip=False):
    m, a = rng.normal(size=(3, 3)), rng.normal(size=3)
    mi = np.linalg.inv(m)
    rhs = np.linalg.det(m) * (mi @ _sk(a) @ mi.T if slip else mi.T @ _sk(a) @ mi)
    return _res(_sk(m @ a), rhs)


def t_hz_ess_cubic(rng, slip=False):
    e = _sk(rng.normal(size=3)) @ _rot(rng)
    return _res((1 if slip else 2) * e @ e.T @ e - np.trace(e @ e.T) * e, np.zeros((3, 3)))


def _hz_k(rng):
    ax, ay, s, x0, y0 = rng.uniform(0.5, 2, size=5)
    return np.array([[ax, s, x0], [0, ay, y0], [0, 0, 1.0]])


def _hz_kp(rng):
    f, px, py = rng.uniform(0.5, 2, size=3)
    return np.array([[f, 0, px], [0, f, py], [0, 0, 1.0]])


def _hz_f(rng):
    k, kp, r, t = _hz_k(rng), _hz_kp(rng), _rot(rng), rng.normal(size=3)
    return k, kp, r, t, np.linalg.inv(kp).T @ _sk(t) @ r @ np.linalg.inv(k)


def t_hz_fund(rng):
    k, kp, r, t, f = _hz_f(rng)
    xw = rng.normal(size=3)
    return _res((kp @ (r @ xw + t)) @ f @ (k @ xw), 0.0)


def t_hz_epipole(rng):
    k, kp, r, t, f = _hz_f(rng)
    return _res(f @ (k @ r.T @ t), np.zeros(3))


def t_hz_epipole_prime(rng):
    k, kp, r, t, f = _hz_f(rng)
    return _res((kp @ t) @ f, np.zeros(3))


# ---------------------------------------------------------------- Shabana


def _sha_a(v, th):
    return np.eye(3) + _sk(v) * np.sin(th) + 2 * _sk(v) @ _sk(v) * np.sin(th / 2) ** 2


def t_sha_rod_orth(rng):
    a = _sha_a(_unit(rng), rng.uniform(-3, 3))
    return _res(a.T @ a, np.eye(3))


def t_sha_rod_axis(rng):
    v = _unit(rng)
    return _res(_sha_a(v, rng.uniform(-3, 3)) @ v, v)


def t_sha_rod_ep(rng, slip=False):
    v, th = _unit(rng), rng.uniform(-3, 3)
    t0, tv = np.cos(th / 2), np.sin(th / 2) * v
    rhs = np.eye(3) + 2 * t0 * _sk(tv) + (1 if slip else 2) * _sk(tv) @ _sk(tv)
    return _res(_sha_a(v, th), rhs)


def _sha_g(p):
    t0, t1, t2, t3 = p
    return np.array([[-t1, t0, -t3, t2], [-t2, t3, t0, -t1], [-t3, -t2, t1, t0]])


def _sha_gbar(p):
    t0, t1, t2, t3 = p
    return np.array([[-t1, t0, t3, -t2], [-t2, -t3, t0, t1], [-t3, t2, -t1, t0]])


def t_sha_gbar_gbart(rng):
    p = rng.normal(size=4)
    return _res(_sha_gbar(p) @ _sha_gbar(p).T, (p @ p) * np.eye(3))


def _sha_gg(p):
    return _sha_g(p) @ _sha_gbar(p).T


def _tangent(rng, p):
    d = rng.normal(size=4)
    return d - (d @ p) * p


def t_k_sha_body(rng):
    p = _unit(rng, 4)
    pd = _tangent(rng, p)
    wbar = 2 * _sha_gbar(p) @ pd
    return _res(_sha_gg(p).T @ _ddt(_sha_gg, p, pd), _sk(wbar))


def t_k_sha_space(rng):
    p = _unit(rng, 4)
    pd = _tangent(rng, p)
    w = 2 * _sha_g(p) @ pd
    return _res(_ddt(_sha_gg, p, pd) @ _sha_gg(p).T, _sk(w))


# ---------------------------------------------------------------- the cases

WIE_C = (r"C = \begin{bmatrix} 1 - 2(q_2^2 + q_3^2) & 2(q_1q_2 + q_3q_4) & 2(q_1q_3 - q_2q_4) \\"
         r" 2(q_2q_1 - q_3q_4) & 1 - 2(q_1^2 + q_3^2) & 2(q_2q_3 + q_1q_4) \\"
         r" 2(q_3q_1 + q_2q_4) & 2(q_3q_2 - q_1q_4) & 1 - 2(q_1^2 + q_2^2) \end{bmatrix}")
WIE_OMEGA = (r"\Omega = \begin{bmatrix} 0 & -\omega_3 & \omega_2 \\ \omega_3 & 0 & -\omega_1 \\"
             r" -\omega_2 & \omega_1 & 0 \end{bmatrix}")
WIE_QDOT = [r"\dot q_1 = \frac{1}{2}(\omega_3q_2 - \omega_2q_3 + \omega_1q_4)",
            r"\dot q_2 = \frac{1}{2}(-\omega_3q_1 + \omega_1q_3 + \omega_2q_4)",
            r"\dot q_3 = \frac{1}{2}(\omega_2q_1 - \omega_1q_2 + \omega_3q_4)",
            r"\dot q_4 = \frac{1}{2}(-\omega_1q_1 - \omega_2q_2 - \omega_3q_3)"]
WIE_C1 = r"C_1(\theta) = \begin{bmatrix} 1 & 0 & 0 \\ 0 & \cos\theta & \sin\theta \\ 0 & -\sin\theta & \cos\theta \end{bmatrix}"
WIE_C2 = r"C_2(\theta) = \begin{bmatrix} \cos\theta & 0 & -\sin\theta \\ 0 & 1 & 0 \\ \sin\theta & 0 & \cos\theta \end{bmatrix}"
WIE_C3 = r"C_3(\theta) = \begin{bmatrix} \cos\theta & \sin\theta & 0 \\ -\sin\theta & \cos\theta & 0 \\ 0 & 0 & 1 \end{bmatrix}"
WIE_B = (r"\begin{bmatrix} 1 & 0 & -\sin\theta_2 \\ 0 & \cos\theta_1 & \sin\theta_1\cos\theta_2 \\"
         r" 0 & -\sin\theta_1 & \cos\theta_1\cos\theta_2 \end{bmatrix}")
WIE_BINV = (r"\frac{1}{\cos\theta_2}\begin{bmatrix} \cos\theta_2 & \sin\theta_1\sin\theta_2 & \cos\theta_1\sin\theta_2 \\"
            r" 0 & \cos\theta_1\cos\theta_2 & -\sin\theta_1\cos\theta_2 \\ 0 & \sin\theta_1 & \cos\theta_1 \end{bmatrix}")
WIE_W = [r"\omega_1 = \dot\theta_1 - \dot\theta_3\sin\theta_2",
         r"\omega_2 = \dot\theta_2\cos\theta_1 + \dot\theta_3\sin\theta_1\cos\theta_2",
         r"\omega_3 = -\dot\theta_2\sin\theta_1 + \dot\theta_3\cos\theta_1\cos\theta_2"]

WIT_EP = [r"\mathbf{A} = (2q_0^2 - 1)\mathbf{I} + 2(\mathbf{q}\mathbf{q}^T + q_0\tilde{\mathbf{q}})",
          r"q_0 = \cos\frac{\varphi}{2}", r"\mathbf{q} = \mathbf{n}\sin\frac{\varphi}{2}",
          r"\mathbf{n}: unit vector", r"\varphi: angle"]
WIT_A = [r"\mathbf{A}_1(\varphi) = \begin{bmatrix} 1 & 0 & 0 \\ 0 & \cos\varphi & -\sin\varphi \\ 0 & \sin\varphi & \cos\varphi \end{bmatrix}",
         r"\mathbf{A}_2(\varphi) = \begin{bmatrix} \cos\varphi & 0 & \sin\varphi \\ 0 & 1 & 0 \\ -\sin\varphi & 0 & \cos\varphi \end{bmatrix}",
         r"\mathbf{A}_3(\varphi) = \begin{bmatrix} \cos\varphi & -\sin\varphi & 0 \\ \sin\varphi & \cos\varphi & 0 \\ 0 & 0 & 1 \end{bmatrix}"]
WIT_BRYAN_W = (r"\boldsymbol\omega = \begin{bmatrix} \dot\varphi_1\cos\varphi_2\cos\varphi_3 + \dot\varphi_2\sin\varphi_3 \\"
               r" -\dot\varphi_1\cos\varphi_2\sin\varphi_3 + \dot\varphi_2\cos\varphi_3 \\ \dot\varphi_1\sin\varphi_2 + \dot\varphi_3 \end{bmatrix}")

GR_E = [r"e_0 = \cos\frac{\theta}{2}\cos\frac{\phi + \psi}{2}",
        r"e_1 = \sin\frac{\theta}{2}\cos\frac{\phi - \psi}{2}",
        r"e_2 = \sin\frac{\theta}{2}\sin\frac{\phi - \psi}{2}",
        r"e_3 = \cos\frac{\theta}{2}\sin\frac{\phi + \psi}{2}",
        r"\psi: angle", r"\theta: angle", r"\phi: angle"]
GR_W = [r"\omega_x = \dot\psi\sin\theta\sin\phi + \dot\theta\cos\phi",
        r"\omega_y = \dot\psi\sin\theta\cos\phi - \dot\theta\sin\phi",
        r"\omega_z = \dot\psi\cos\theta + \dot\phi"]
GR_C = (r"C = \begin{bmatrix} \cos\psi\cos\phi - \sin\psi\cos\theta\sin\phi & \sin\psi\cos\phi + \cos\psi\cos\theta\sin\phi & \sin\theta\sin\phi \\"
        r" -\cos\psi\sin\phi - \sin\psi\cos\theta\cos\phi & -\sin\psi\sin\phi + \cos\psi\cos\theta\cos\phi & \sin\theta\cos\phi \\"
        r" \sin\psi\sin\theta & -\cos\psi\sin\theta & \cos\theta \end{bmatrix}")
GR_OMEGA = r"\boldsymbol\omega = \begin{bmatrix} \omega_x \\ \omega_y \\ \omega_z \end{bmatrix}"

GRV_CNB = (r"C_n^b = \begin{bmatrix} \cos\theta\cos\psi & \cos\theta\sin\psi & -\sin\theta \\"
           r" -\cos\phi\sin\psi + \sin\phi\sin\theta\cos\psi & \cos\phi\cos\psi + \sin\phi\sin\theta\sin\psi & \sin\phi\cos\theta \\"
           r" \sin\phi\sin\psi + \cos\phi\sin\theta\cos\psi & -\sin\phi\cos\psi + \cos\phi\sin\theta\sin\psi & \cos\phi\cos\theta \end{bmatrix}")
GRV_W = (r"\boldsymbol\omega_{nb}^b = \begin{bmatrix} 1 & 0 & -\sin\theta \\ 0 & \cos\phi & \sin\phi\cos\theta \\"
         r" 0 & -\sin\phi & \cos\phi\cos\theta \end{bmatrix}\begin{bmatrix} \dot\phi \\ \dot\theta \\ \dot\psi \end{bmatrix}")
GRV_OMEGA = [r"\Omega_{ib}^b = [\boldsymbol\omega_{ib}^b\wedge]", r"\Omega_{ib}^i = [\boldsymbol\omega_{ib}^i\wedge]",
             r"\boldsymbol\omega_{ib}^b = C_i^b\boldsymbol\omega_{ib}^i", r"C_i^b: rotation",
             r"C_b^i = (C_i^b)^T", r"\boldsymbol\omega_{ib}^i: vector"]
GRV_K = [r"C_b^n = (C_n^b)^T", GRV_CNB, r"\Omega_{nb}^b = [\boldsymbol\omega_{nb}^b\wedge]", GRV_W,
         r"\phi(t): angle", r"\theta(t): angle", r"\psi(t): angle"]

HZ_F = [r"F = K'^{-T}[\mathbf{t}]_\times RK^{-1}",
        r"K = \begin{bmatrix} \alpha_x & s & x_0 \\ 0 & \alpha_y & y_0 \\ 0 & 0 & 1 \end{bmatrix}",
        r"K' = \begin{bmatrix} f' & 0 & p'_x \\ 0 & f' & p'_y \\ 0 & 0 & 1 \end{bmatrix}",
        r"R: rotation", r"\mathbf{t}: vector"]
HZ_E = [r"E = [\mathbf{t}]_\times R", r"R: rotation", r"\mathbf{t}: vector"]

SHA_A = [r"\mathbf{A} = \mathbf{I} + \tilde{\mathbf{v}}\sin\theta + 2(\tilde{\mathbf{v}})^2\sin^2\frac{\theta}{2}",
         r"\mathbf{v}: unit vector", r"\theta: angle"]
SHA_G = r"\mathbf{G} = \begin{bmatrix} -\theta_1 & \theta_0 & -\theta_3 & \theta_2 \\ -\theta_2 & \theta_3 & \theta_0 & -\theta_1 \\ -\theta_3 & -\theta_2 & \theta_1 & \theta_0 \end{bmatrix}"
SHA_GBAR = r"\bar{\mathbf{G}} = \begin{bmatrix} -\theta_1 & \theta_0 & \theta_3 & -\theta_2 \\ -\theta_2 & -\theta_3 & \theta_0 & \theta_1 \\ -\theta_3 & \theta_2 & -\theta_1 & \theta_0 \end{bmatrix}"
SHA_K = [r"\mathbf{A} = \mathbf{G}\bar{\mathbf{G}}^T", SHA_G, SHA_GBAR,
         r"\boldsymbol\theta(t): unit 4-vector"]


def _c(cid, book, latex, let, truth, slip=False):
    return {"id": cid, "book": book, "latex": latex, "let": let, "truth": truth, "slip": slip}


WIE, WIT, GR, GRV, HZ, SHA = ("Wie 1998", "Wittenburg 2008", "Greenwood 2003", "Groves 2013",
                              "Hartley-Zisserman 2003", "Shabana 2005")

CASES = [
    # ------------------------------------------------ Wie
    _c("wie-c-orth", WIE, r"C^TC = I", [WIE_C, r"\mathbf{q}: unit 4-vector"], t_wie_orth),
    _c("wie-trace", WIE, r"\operatorname{tr}C = 4q_4^2 - 1", [WIE_C, r"\mathbf{q}: unit 4-vector"],
       t_wie_trace),
    _c("wie-trace-slip", WIE, r"\operatorname{tr}C = 4q_4^2 - 3", [WIE_C, r"\mathbf{q}: unit 4-vector"],
       lambda rng: t_wie_trace(rng, True), slip=True),
    _c("wie-321-inverse", WIE, WIE_BINV + WIE_B + " = I",
       [r"\theta_1: angle", r"\theta_2: angle"], t_wie_321_inverse),
    _c("k-wie-quat", WIE, r"\dot{C} = -\Omega C",
       [WIE_C, WIE_OMEGA, *WIE_QDOT, r"\mathbf{q}(t): unit 4-vector"], t_k_wie_quat),
    _c("k-wie-quat-slip", WIE, r"\dot{C} = -\Omega C",
       [WIE_C, WIE_OMEGA, WIE_QDOT[0].replace(r"- \omega_2q_3", r"+ \omega_2q_3"), *WIE_QDOT[1:],
        r"\mathbf{q}(t): unit 4-vector"], lambda rng: t_k_wie_quat(rng, True), slip=True),
    _c("k-wie-321", WIE, r"\dot{C} = -\Omega C",
       [r"C = C_1(\theta_1)C_2(\theta_2)C_3(\theta_3)", WIE_C1, WIE_C2, WIE_C3, WIE_OMEGA, *WIE_W,
        r"\theta_1(t): angle", r"\theta_2(t): angle", r"\theta_3(t): angle"], t_k_wie_321),
    # ------------------------------------------------ Wittenburg
    _c("wit-tilde-comm", WIT,
       r"\tilde{\mathbf{a}}\tilde{\mathbf{b}} - \tilde{\mathbf{b}}\tilde{\mathbf{a}} = \widetilde{\mathbf{a}\times\mathbf{b}}",
       [], t_wit_tilde_comm),
    _c("wit-tilde-comm-slip", WIT,
       r"\tilde{\mathbf{a}}\tilde{\mathbf{b}} - \tilde{\mathbf{b}}\tilde{\mathbf{a}} = \widetilde{\mathbf{b}\times\mathbf{a}}",
       [], lambda rng: t_wit_tilde_comm(rng, True), slip=True),
    _c("wit-tilde-ab", WIT,
       r"\tilde{\mathbf{a}}\tilde{\mathbf{b}} = \mathbf{b}\mathbf{a}^T - \mathbf{a}^T\mathbf{b}\,\mathbf{I}",
       [], t_wit_tilde_ab),
    _c("wit-ep-axis", WIT, r"\mathbf{A}\mathbf{q} = \mathbf{q}", WIT_EP, t_wit_ep_axis),
    _c("wit-ep-orth", WIT, r"\mathbf{A}^T\mathbf{A} = \mathbf{I}", WIT_EP, t_wit_ep_orth),
    _c("wit-rodrigues", WIT,
       r"\mathbf{A} = \mathbf{I}\cos\varphi + \mathbf{n}\mathbf{n}^T(1 - \cos\varphi) + \tilde{\mathbf{n}}\sin\varphi",
       WIT_EP, t_wit_rodrigues),
    _c("k-wit-bryan", WIT, r"\mathbf{A}^T\dot{\mathbf{A}} = \tilde{\boldsymbol\omega}",
       [r"\mathbf{A} = \mathbf{A}_1(\varphi_1)\mathbf{A}_2(\varphi_2)\mathbf{A}_3(\varphi_3)", *WIT_A,
        WIT_BRYAN_W, r"\varphi_1(t): angle", r"\varphi_2(t): angle", r"\varphi_3(t): angle"],
       t_k_wit_bryan),
    # ------------------------------------------------ Greenwood
    _c("gr-ep-norm", GR, r"e_0^2 + e_1^2 + e_2^2 + e_3^2 = 1", GR_E, t_gr_ep_norm),
    _c("gr-ep-norm-slip", GR, r"e_0^2 + e_1^2 + e_2^2 + e_3^2 = 1",
       [GR_E[0], GR_E[1], GR_E[2].replace(r"\phi - \psi", r"\phi + \psi"), *GR_E[3:]],
       lambda rng: t_gr_ep_norm(rng, True), slip=True),
    _c("gr-omega-sq", GR,
       r"\omega_x^2 + \omega_y^2 + \omega_z^2 = \dot\psi^2 + \dot\theta^2 + \dot\phi^2 + 2\dot\psi\dot\phi\cos\theta",
       [*GR_W, r"\psi: angle", r"\theta: angle", r"\phi: angle"], t_gr_omega_sq),
    _c("gr-omega-sq-slip", GR,
       r"\omega_x^2 + \omega_y^2 + \omega_z^2 = \dot\psi^2 + \dot\theta^2 + \dot\phi^2 - 2\dot\psi\dot\phi\cos\theta",
       [*GR_W, r"\psi: angle", r"\theta: angle", r"\phi: angle"],
       lambda rng: t_gr_omega_sq(rng, True), slip=True),
    _c("gr-313-orth", GR, r"C^TC = I", [GR_C, r"\psi: angle", r"\theta: angle", r"\phi: angle"],
       t_gr_313_orth),
    _c("k-gr-313", GR, r"\dot{C} = -\tilde{\omega}C",
       [GR_C, *GR_W, GR_OMEGA.replace(r"\boldsymbol\omega", r"\omega"),
        r"\psi(t): angle", r"\theta(t): angle", r"\phi(t): angle"], t_k_gr_313),
    _c("k-gr-313-slip", GR, r"\dot{C} = -\tilde{\omega}C",
       [GR_C, *GR_W[:2], GR_W[2].replace(r"+ \dot\phi", r"- \dot\phi"),
        GR_OMEGA.replace(r"\boldsymbol\omega", r"\omega"),
        r"\psi(t): angle", r"\theta(t): angle", r"\phi(t): angle"],
       lambda rng: t_k_gr_313(rng, True), slip=True),
    # ------------------------------------------------ Groves
    _c("grv-omega-rot", GRV, r"\Omega_{ib}^b = C_i^b\Omega_{ib}^iC_b^i", GRV_OMEGA, t_grv_omega_rot),
    _c("grv-omega-rot-slip", GRV, r"\Omega_{ib}^b = C_b^i\Omega_{ib}^iC_i^b", GRV_OMEGA,
       lambda rng: t_grv_omega_rot(rng, True), slip=True),
    _c("grv-cross", GRV, r"\Omega_{ib}^b\mathbf{l}_{ba}^b = \boldsymbol\omega_{ib}^b\wedge\mathbf{l}_{ba}^b",
       [r"\Omega_{ib}^b = [\boldsymbol\omega_{ib}^b\wedge]", r"\boldsymbol\omega_{ib}^b: vector",
        r"\mathbf{l}_{ba}^b: vector"], t_grv_cross),
    _c("k-grv-euler", GRV, r"\dot{C}_b^n = C_b^n\Omega_{nb}^b", GRV_K, t_k_grv_euler),
    _c("k-grv-euler-slip", GRV, r"\dot{C}_b^n = C_b^n\Omega_{nb}^b",
       [*GRV_K[:3], GRV_W.replace(r"\sin\phi\cos\theta \\", r"-\sin\phi\cos\theta \\"), *GRV_K[4:]],
       lambda rng: t_k_grv_euler(rng, True), slip=True),
    # ------------------------------------------------ Hartley & Zisserman
    _c("hz-cross-m", HZ, r"[M\mathbf{a}]_\times = \det(M)M^{-T}[\mathbf{a}]_\times M^{-1}",
       [r"M: matrix", r"\mathbf{a}: vector"], t_hz_cross_m),
    _c("hz-cross-m-slip", HZ, r"[M\mathbf{a}]_\times = \det(M)M^{-1}[\mathbf{a}]_\times M^{-T}",
       [r"M: matrix", r"\mathbf{a}: vector"], lambda rng: t_hz_cross_m(rng, True), slip=True),
    _c("hz-ess-cubic", HZ, r"2EE^TE - \operatorname{trace}(EE^T)E = 0", HZ_E, t_hz_ess_cubic),
    _c("hz-ess-cubic-slip", HZ, r"EE^TE - \operatorname{trace}(EE^T)E = 0", HZ_E,
       lambda rng: t_hz_ess_cubic(rng, True), slip=True),
    _c("hz-fund", HZ, r"\mathbf{x}'^TF\mathbf{x} = 0",
       [*HZ_F, r"\mathbf{x} = K\mathbf{X}", r"\mathbf{x}' = K'(R\mathbf{X} + \mathbf{t})",
        r"\mathbf{X}: vector"], t_hz_fund),
    _c("hz-epipole", HZ, r"F\mathbf{e} = \mathbf{0}", [*HZ_F, r"\mathbf{e} = KR^T\mathbf{t}"],
       t_hz_epipole),
    _c("hz-epipole-prime", HZ, r"\mathbf{e}'^TF = \mathbf{0}^T", [*HZ_F, r"\mathbf{e}' = K'\mathbf{t}"],
       t_hz_epipole_prime),
    # ------------------------------------------------ Shabana
    _c("sha-rod-orth", SHA, r"\mathbf{A}^T\mathbf{A} = \mathbf{I}", SHA_A, t_sha_rod_orth),
    _c("sha-rod-axis", SHA, r"\mathbf{A}\mathbf{v} = \mathbf{v}", SHA_A, t_sha_rod_axis),
    _c("sha-rod-ep", SHA, r"\mathbf{A} = \mathbf{I} + 2\theta_0\tilde{\boldsymbol\theta} + 2(\tilde{\boldsymbol\theta})^2",
       [*SHA_A, r"\theta_0 = \cos\frac{\theta}{2}", r"\boldsymbol\theta = \mathbf{v}\sin\frac{\theta}{2}"],
       t_sha_rod_ep),
    _c("sha-rod-ep-slip", SHA, r"\mathbf{A} = \mathbf{I} + 2\theta_0\tilde{\boldsymbol\theta} + (\tilde{\boldsymbol\theta})^2",
       [*SHA_A, r"\theta_0 = \cos\frac{\theta}{2}", r"\boldsymbol\theta = \mathbf{v}\sin\frac{\theta}{2}"],
       lambda rng: t_sha_rod_ep(rng, True), slip=True),
    _c("sha-gbar-gbart", SHA, r"\bar{\mathbf{G}}\bar{\mathbf{G}}^T = (\theta_0^2 + \theta_1^2 + \theta_2^2 + \theta_3^2)\mathbf{I}",
       [SHA_GBAR], t_sha_gbar_gbart),
    _c("k-sha-body", SHA, r"\mathbf{A}^T\dot{\mathbf{A}} = \tilde{\bar{\boldsymbol\omega}}",
       [*SHA_K, r"\bar{\boldsymbol\omega} = 2\bar{\mathbf{G}}\dot{\boldsymbol\theta}"], t_k_sha_body),
    _c("k-sha-space", SHA, r"\dot{\mathbf{A}}\mathbf{A}^T = \tilde{\boldsymbol\omega}",
       [*SHA_K, r"\boldsymbol\omega = 2\mathbf{G}\dot{\boldsymbol\theta}"], t_k_sha_space),
]

TRUTH_TOLERANCE = 1e-6

#: the one attempt a reader makes after a refusal, where its message names it: the entry
#: it names (\boldsymbol\theta_{1:1} for theta_0, counted from 1), or the spelling it names
#: (a \times b for Groves' a \wedge b)
_SHA_ENTRIES = [(rf"\theta_{k}", rf"\boldsymbol\theta_{{{k + 1}:{k + 1}}}") for k in range(4)]
ATTEMPT = {
    "grv-cross": {"replace": [(r"\wedge\mathbf{l}", r"\times\mathbf{l}")]},
    "k-sha-body": {"replace": _SHA_ENTRIES},
    "k-sha-space": {"replace": _SHA_ENTRIES},
}


def attempted(case: dict) -> tuple[str, list, dict]:
    """``(latex, lets, options)`` of ``case`` after the reader's one attempt (as typed where
    :data:`ATTEMPT` has none)."""
    latex, lets = case["latex"], list(case["let"])
    for old, new in ATTEMPT.get(case["id"], {}).get("replace", []):
        latex, lets = latex.replace(old, new), [x.replace(old, new) for x in lets]
    return latex, lets, {}

#: the baseline: the verdicts as typed, the checker without the books' readings (right / refused / undecided / WRONG)
BASELINE = {
    'wie-c-orth': 'right',
    'wie-trace': 'right',
    'wie-trace-slip': 'right',
    'wie-321-inverse': 'right',
    'k-wie-quat': 'refused',
    'k-wie-quat-slip': 'refused',
    'k-wie-321': 'right',
    'wit-tilde-comm': 'refused',
    'wit-tilde-comm-slip': 'refused',
    'wit-tilde-ab': 'refused',
    'wit-ep-axis': 'refused',
    'wit-ep-orth': 'refused',
    'wit-rodrigues': 'refused',
    'k-wit-bryan': 'refused',
    'gr-ep-norm': 'right',
    'gr-ep-norm-slip': 'right',
    'gr-omega-sq': 'refused',
    'gr-omega-sq-slip': 'refused',
    'gr-313-orth': 'right',
    'k-gr-313': 'refused',
    'k-gr-313-slip': 'refused',
    'grv-omega-rot': 'refused',
    'grv-omega-rot-slip': 'refused',
    'grv-cross': 'refused',
    'k-grv-euler': 'refused',
    'k-grv-euler-slip': 'refused',
    'hz-cross-m': 'right',
    'hz-cross-m-slip': 'right',
    'hz-ess-cubic': 'right',
    'hz-ess-cubic-slip': 'right',
    'hz-fund': 'refused',
    'hz-epipole': 'right',
    'hz-epipole-prime': 'right',
    'sha-rod-orth': 'refused',
    'sha-rod-axis': 'refused',
    'sha-rod-ep': 'refused',
    'sha-rod-ep-slip': 'refused',
    'sha-gbar-gbart': 'right',
    'k-sha-body': 'refused',
    'k-sha-space': 'refused',
}

#: the verdicts as typed, with the books' readings
AS_TYPED = {
    'wie-c-orth': 'right',
    'wie-trace': 'right',
    'wie-trace-slip': 'right',
    'wie-321-inverse': 'right',
    'k-wie-quat': 'refused',
    'k-wie-quat-slip': 'refused',
    'k-wie-321': 'right',
    'wit-tilde-comm': 'right',
    'wit-tilde-comm-slip': 'right',
    'wit-tilde-ab': 'right',
    'wit-ep-axis': 'right',
    'wit-ep-orth': 'right',
    'wit-rodrigues': 'right',
    'k-wit-bryan': 'right',
    'gr-ep-norm': 'right',
    'gr-ep-norm-slip': 'right',
    'gr-omega-sq': 'right',
    'gr-omega-sq-slip': 'right',
    'gr-313-orth': 'right',
    'k-gr-313': 'right',
    'k-gr-313-slip': 'right',
    'grv-omega-rot': 'right',
    'grv-omega-rot-slip': 'right',
    'grv-cross': 'refused',
    'k-grv-euler': 'right',
    'k-grv-euler-slip': 'right',
    'hz-cross-m': 'right',
    'hz-cross-m-slip': 'right',
    'hz-ess-cubic': 'right',
    'hz-ess-cubic-slip': 'right',
    'hz-fund': 'right',
    'hz-epipole': 'right',
    'hz-epipole-prime': 'right',
    'sha-rod-orth': 'right',
    'sha-rod-axis': 'right',
    'sha-rod-ep': 'right',
    'sha-rod-ep-slip': 'right',
    'sha-gbar-gbart': 'right',
    'k-sha-body': 'right',
    'k-sha-space': 'right',
}

#: after the reader's one attempt (:data:`ATTEMPT`), with the books' readings
AS_ATTEMPTED = {
    'wie-c-orth': 'right',
    'wie-trace': 'right',
    'wie-trace-slip': 'right',
    'wie-321-inverse': 'right',
    'k-wie-quat': 'refused',
    'k-wie-quat-slip': 'refused',
    'k-wie-321': 'right',
    'wit-tilde-comm': 'right',
    'wit-tilde-comm-slip': 'right',
    'wit-tilde-ab': 'right',
    'wit-ep-axis': 'right',
    'wit-ep-orth': 'right',
    'wit-rodrigues': 'right',
    'k-wit-bryan': 'right',
    'gr-ep-norm': 'right',
    'gr-ep-norm-slip': 'right',
    'gr-omega-sq': 'right',
    'gr-omega-sq-slip': 'right',
    'gr-313-orth': 'right',
    'k-gr-313': 'right',
    'k-gr-313-slip': 'right',
    'grv-omega-rot': 'right',
    'grv-omega-rot-slip': 'right',
    'grv-cross': 'right',
    'k-grv-euler': 'right',
    'k-grv-euler-slip': 'right',
    'hz-cross-m': 'right',
    'hz-cross-m-slip': 'right',
    'hz-ess-cubic': 'right',
    'hz-ess-cubic-slip': 'right',
    'hz-fund': 'right',
    'hz-epipole': 'right',
    'hz-epipole-prime': 'right',
    'sha-rod-orth': 'right',
    'sha-rod-axis': 'right',
    'sha-rod-ep': 'right',
    'sha-rod-ep-slip': 'right',
    'sha-gbar-gbart': 'right',
    'k-sha-body': 'right',
    'k-sha-space': 'right',
}
