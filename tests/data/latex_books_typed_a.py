# ruff: noqa: E501 - the LaTeX of a book equation is one line, as typed
"""Equations of six books typed from memory, first set: 40 equations.

Books: Shuster, "A Survey of Attitude Representations" (J. Astronaut. Sci. 41, 1993);
Markley & Crassidis, *Fundamentals of Spacecraft Attitude Determination and Control* (2014);
Kuipers, *Quaternions and Rotation Sequences* (1999); Murray, Li & Sastry, *A Mathematical
Introduction to Robotic Manipulation* (1994); Ma, Soatto, Košecká & Sastry, *An Invitation
to 3-D Vision* (2004); Diebel, "Representing Attitude: Euler Angles, Unit Quaternions, and
Rotation Vectors" (2006).

Each case: an id, its book, the LaTeX and the `--let`s as a reader of that book types them,
`slip` (a deliberate one-edit slip of a true equation), the verdict as typed (`before`, run
without the books' readings) and with them (`after`), and a truth: a NumPy function of a
random generator returning the residual |lhs - rhs| at one random point of the declarations
(for a kinematic equation, the time derivative by central differences along the declared
rates). The truth never imports rigidsym: it is the independent judge.
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


def _axang(e, th):
    """Shuster / Markley-Crassidis attitude matrix (passive)."""
    return np.cos(th) * np.eye(3) - np.sin(th) * _sk(e) + (1 - np.cos(th)) * np.outer(e, e)


def _gibbs(g):
    return ((1 - g @ g) * np.eye(3) + 2 * np.outer(g, g) - 2 * _sk(g)) / (1 + g @ g)


def _xi(q):
    return np.vstack([q[3] * np.eye(3) + _sk(q[:3]), -q[:3][None, :]])


def _psi(q):
    return np.vstack([q[3] * np.eye(3) - _sk(q[:3]), -q[:3][None, :]])


def _aq(q):
    v, s = q[:3], q[3]
    return (s * s - v @ v) * np.eye(3) + 2 * np.outer(v, v) - 2 * s * _sk(v)


def _mrp(p):
    s = _sk(p)
    return np.eye(3) + (8 * s @ s - 4 * (1 - p @ p) * s) / (1 + p @ p) ** 2


def _kuipers(u, th, slip=False):
    q0, q = np.cos(th / 2), np.sin(th / 2) * u
    return (2 * q0 * q0 - 1) * np.eye(3) + 2 * np.outer(q, q) + 2 * q0 * _sk(q), q0


def _r1(x):
    c, s = np.cos(x), np.sin(x)
    return np.array([[1, 0, 0], [0, c, s], [0, -s, c]])


def _r2(x):
    c, s = np.cos(x), np.sin(x)
    return np.array([[c, 0, -s], [0, 1, 0], [s, 0, c]])


def _r3(x):
    c, s = np.cos(x), np.sin(x)
    return np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]])


def _expso3(v):
    n = np.linalg.norm(v)
    k = _sk(v)
    return np.eye(3) + np.sin(n) / n * k + (1 - np.cos(n)) / n**2 * k @ k


def _ddt(f, x0, xdot, h=1e-6):
    """d/dt f(x(t)) at t = 0 along x(t) = x0 + t xdot (first order suffices)."""
    return (f(x0 + h * xdot) - f(x0 - h * xdot)) / (2 * h)


def _diebel_r(q):
    q0, q1, q2, q3 = q
    return np.array([
        [q0*q0 + q1*q1 - q2*q2 - q3*q3, 2*q1*q2 + 2*q0*q3, 2*q1*q3 - 2*q0*q2],
        [2*q1*q2 - 2*q0*q3, q0*q0 - q1*q1 + q2*q2 - q3*q3, 2*q2*q3 + 2*q0*q1],
        [2*q1*q3 + 2*q0*q2, 2*q2*q3 - 2*q0*q1, q0*q0 - q1*q1 - q2*q2 + q3*q3]])


def _res(a, b):
    return float(np.max(np.abs(np.asarray(a, float) - np.asarray(b, float))))


# ---------------------------------------------------------------- truths


def t_sh_axis(rng):
    n, th = _unit(rng), rng.uniform(-3, 3)
    return _res(_axang(n, th) @ n, n)


def t_sh_trace(rng, slip=False):
    n, th = _unit(rng), rng.uniform(-3, 3)
    rhs = 1 + np.cos(th) if slip else 1 + 2 * np.cos(th)
    return _res(np.trace(_axang(n, th)), rhs)


def t_sh_gibbs_compose(rng):
    g, gp = rng.normal(size=3), rng.normal(size=3)
    gpp = (gp + g - np.cross(gp, g)) / (1 - gp @ g)
    return _res(_gibbs(gpp), _gibbs(gp) @ _gibbs(g))


def t_sh_skew_square(rng):
    u = rng.normal(size=3)
    return _res(_sk(u) @ _sk(u), np.outer(u, u) - (u @ u) * np.eye(3))


def t_sh_gibbs_from_a(rng):
    g = rng.normal(size=3)
    a = _gibbs(g)
    rhs = np.array([a[1, 2] - a[2, 1], a[2, 0] - a[0, 2], a[0, 1] - a[1, 0]]) / (1 + np.trace(a))
    return _res(g, rhs)


def t_mc_psi_orth(rng):
    q = _unit(rng, 4)
    return _res(_psi(q).T @ _psi(q), np.eye(3))


def t_mc_xi_proj(rng, slip=False):
    q = _unit(rng, 4)
    rhs = np.eye(4) if slip else np.eye(4) - np.outer(q, q)
    return _res(_xi(q) @ _xi(q).T, rhs)


def t_mc_at_psi_xi(rng):
    q = _unit(rng, 4)
    return _res(_aq(q).T, _psi(q).T @ _xi(q))


def t_mc_psi_q(rng):
    q = _unit(rng, 4)
    return _res(_psi(q).T @ q, np.zeros(3))


def t_mc_axang_transpose(rng):
    e, th = _unit(rng), rng.uniform(-3, 3)
    return _res(_axang(e, th).T, _axang(e, -th))


def t_mc_mrp_shadow(rng):
    p = rng.normal(size=3)
    return _res(_mrp(-p / (p @ p)), _mrp(p))


def t_ku_axis(rng):
    u, th = _unit(rng), rng.uniform(-3, 3)
    m, _ = _kuipers(u, th)
    return _res(m @ u, u)


def t_ku_orth(rng):
    u, th = _unit(rng), rng.uniform(-3, 3)
    m, _ = _kuipers(u, th)
    return _res(m.T @ m, np.eye(3))


def t_ku_trace(rng, slip=False):
    u, th = _unit(rng), rng.uniform(-3, 3)
    m, q0 = _kuipers(u, th)
    return _res(np.trace(m), 4 * q0 * q0 + (1 if slip else -1))


def t_mls_hat_square(rng):
    w = _unit(rng)
    k = _sk(w)
    return _res(k @ k, np.outer(w, w) - np.eye(3))


def t_mls_2link_reach(rng, slip=False):
    l1, l2, t1, t2 = rng.uniform(0.5, 2, size=4)
    p = np.array([l1 * np.cos(t1) + l2 * np.cos(t1 + t2), l1 * np.sin(t1) + l2 * np.sin(t1 + t2)])
    return _res(p @ p, l1**2 + l2**2 + (-2 if slip else 2) * l1 * l2 * np.cos(t2))


def _epi(rng):
    r, t, x1 = _rot(rng), rng.normal(size=3), rng.normal(size=3)
    l1, l2 = rng.uniform(0.5, 2, size=2)
    x2 = (l1 * r @ x1 + t) / l2
    return r, t, x1, x2


def t_msks_epipolar(rng):
    r, t, x1, x2 = _epi(rng)
    return _res(x2 @ _sk(t) @ r @ x1, 0.0)


def t_msks_et(rng, slip=False):
    r, t = _rot(rng), rng.normal(size=3)
    e = _sk(t) @ r
    return _res(e @ t if slip else e.T @ t, np.zeros(3))


def t_msks_tr_eet(rng):
    r, t = _rot(rng), rng.normal(size=3)
    e = _sk(t) @ r
    return _res(np.trace(e @ e.T), 2 * (t @ t))


def t_msks_homography(rng):
    r, t, n, y = _rot(rng), rng.normal(size=3), _unit(rng), rng.normal(size=3)
    d = rng.uniform(0.5, 2)
    x = d * n + np.cross(n, y)
    h = r + np.outer(t, n) / d
    return _res(h @ x, r @ x + t)


def t_msks_hat_anti(rng):
    u, v = rng.normal(size=3), rng.normal(size=3)
    return _res(_sk(u) @ v, -_sk(v) @ u)


def t_di_quat_orth(rng):
    q = rng.normal(size=4)
    r = _diebel_r(q)
    return _res(r.T @ r, (q @ q) ** 2 * np.eye(3))


def t_di_r1_compose(rng):
    a, b = rng.uniform(-3, 3, size=2)
    return _res(_r1(a) @ _r1(b), _r1(a + b))


def t_mls_exp_fixed(rng):
    v = rng.normal(size=3)
    return _res(_expso3(v) @ v, v)


def t_mls_exp_orth(rng, slip=False):
    v = rng.normal(size=3)
    n, k = np.linalg.norm(v), _sk(v)
    r = np.eye(3) + np.sin(n) / n * k + (1 - np.cos(n)) / (n if slip else n**2) * k @ k
    return _res(r.T @ r, np.eye(3))


def t_k_sh_quat(rng):
    q, w = _unit(rng, 4), rng.normal(size=3)
    om = np.zeros((4, 4))
    om[:3, :3], om[:3, 3], om[3, :3] = -_sk(w), w, -w
    qd = 0.5 * om @ q
    return _res(_ddt(_aq, q, qd), -_sk(w) @ _aq(q))


def t_k_mc_gibbs(rng, slip=False):
    g, w = rng.normal(size=3), rng.normal(size=3)
    cr = np.cross(w, g) if slip else np.cross(g, w)
    gd = 0.5 * (w + cr + (g @ w) * g)
    return _res(_sk(w), -_ddt(_gibbs, g, gd) @ _gibbs(g).T)


def _c123(x):
    return _r3(x[2]) @ _r2(x[1]) @ _r1(x[0])


def t_k_123(rng, slip=False):
    x, xd = rng.uniform(-1.2, 1.2, size=3), rng.normal(size=3)
    ph, th, ps = x
    pd, td, sd = xd
    w3 = pd * (np.cos(th) if slip else np.sin(th)) + sd
    w = np.array([pd * np.cos(th) * np.cos(ps) + td * np.sin(ps),
                  -pd * np.cos(th) * np.sin(ps) + td * np.cos(ps), w3])
    return _res(_ddt(_c123, x, xd), -_sk(w) @ _c123(x))


def _rz(th):
    c, s = np.cos(th), np.sin(th)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def t_k_mls_rz(rng):
    th, thd = rng.uniform(-3, 3), rng.normal()
    lhs = _rz(th).T @ _ddt(_rz, th, thd)
    return _res(lhs, thd * np.array([[0, -1, 0], [1, 0, 0], [0, 0, 0]]))


def t_k_di_quat(rng):
    q, w = rng.normal(size=4), rng.normal(size=3)
    q0, q1, q2, q3 = q
    wm = np.array([[-q1, q0, q3, -q2], [-q2, -q3, q0, q1], [-q3, q2, -q1, q0]])
    qd = 0.5 * wm.T @ w
    return _res(_ddt(_diebel_r, q, qd), -_sk(w) @ _diebel_r(q))


def t_k_mls_skew(rng):
    r0, w = _rot(rng), rng.normal(size=3)
    rdot = r0 @ _sk(w)
    a = rdot @ r0.T
    return _res(a.T, -a)


def t_k_axang(rng):
    e, th, w = _unit(rng), rng.uniform(0.3, 3), rng.normal(size=3)
    thd = e @ w
    ed = 0.5 * (np.cross(e, w) - np.cross(e, np.cross(e, w)) / np.tan(th / 2))
    x = np.concatenate([e, [th]])
    xd = np.concatenate([ed, [thd]])
    return _res(_ddt(lambda y: _axang(y[:3], y[3]), x, xd), -_sk(w) @ _axang(e, th))


# ---------------------------------------------------------------- the cases

AXANG = r"A = \cos\theta I_3 - \sin\theta[\hat{\mathbf{n}}\times] + (1 - \cos\theta)\hat{\mathbf{n}}\hat{\mathbf{n}}^T"
GIBBS_A = r"A(\mathbf{g}) = \frac{(1 - \mathbf{g}^T\mathbf{g})I_3 + 2\mathbf{g}\mathbf{g}^T - 2[\mathbf{g}\times]}{1 + \mathbf{g}^T\mathbf{g}}"
XI = r"\Xi(\mathbf{q}) = \begin{bmatrix} q_4 I_3 + [\mathbf{q}_{1:3}\times] \\ -\mathbf{q}_{1:3}^T \end{bmatrix}"
PSI = r"\Psi(\mathbf{q}) = \begin{bmatrix} q_4 I_3 - [\mathbf{q}_{1:3}\times] \\ -\mathbf{q}_{1:3}^T \end{bmatrix}"
AQ = r"A(\mathbf{q}) = (q_4^2 - \|\mathbf{q}_{1:3}\|^2)I_3 + 2\mathbf{q}_{1:3}\mathbf{q}_{1:3}^T - 2q_4[\mathbf{q}_{1:3}\times]"
MRP = r"A(\mathbf{p}) = I_3 + \frac{8[\mathbf{p}\times]^2 - 4(1 - \|\mathbf{p}\|^2)[\mathbf{p}\times]}{(1 + \|\mathbf{p}\|^2)^2}"
KU = [r"q_0 = \cos\frac{\theta}{2}", r"\mathbf{q} = \sin\frac{\theta}{2}\mathbf{u}",
      r"M = (2q_0^2 - 1)I + 2\mathbf{q}\mathbf{q}^T + 2q_0[\mathbf{q}]_\times",
      r"\mathbf{u}: unit vector", r"\theta: angle"]
P2 = (r"\mathbf{p} = \begin{bmatrix} l_1\cos\theta_1 + l_2\cos(\theta_1 + \theta_2) \\"
      r" l_1\sin\theta_1 + l_2\sin(\theta_1 + \theta_2) \end{bmatrix}")
DIEBEL = (r"R(\mathbf{q}) = \begin{bmatrix} q_0^2 + q_1^2 - q_2^2 - q_3^2 & 2q_1q_2 + 2q_0q_3 & 2q_1q_3 - 2q_0q_2 \\"
          r" 2q_1q_2 - 2q_0q_3 & q_0^2 - q_1^2 + q_2^2 - q_3^2 & 2q_2q_3 + 2q_0q_1 \\"
          r" 2q_1q_3 + 2q_0q_2 & 2q_2q_3 - 2q_0q_1 & q_0^2 - q_1^2 - q_2^2 + q_3^2 \end{bmatrix}")
R1 = r"R_1(\phi) = \begin{bmatrix} 1 & 0 & 0 \\ 0 & \cos\phi & \sin\phi \\ 0 & -\sin\phi & \cos\phi \end{bmatrix}"
R2 = r"R_2(\theta) = \begin{bmatrix} \cos\theta & 0 & -\sin\theta \\ 0 & 1 & 0 \\ \sin\theta & 0 & \cos\theta \end{bmatrix}"
R3 = r"R_3(\psi) = \begin{bmatrix} \cos\psi & \sin\psi & 0 \\ -\sin\psi & \cos\psi & 0 \\ 0 & 0 & 1 \end{bmatrix}"
EXPV = r"R = I_3 + \frac{\sin\|\mathbf{v}\|}{\|\mathbf{v}\|}\hat{\mathbf{v}} + \frac{1 - \cos\|\mathbf{v}\|}{\|\mathbf{v}\|^2}\hat{\mathbf{v}}^2"
W123 = (r"\boldsymbol\omega = \begin{bmatrix} \dot\phi\cos\theta\cos\psi + \dot\theta\sin\psi \\"
        r" -\dot\phi\cos\theta\sin\psi + \dot\theta\cos\psi \\ \dot\phi\sin\theta + \dot\psi \end{bmatrix}")


def _c(cid, book, latex, let, truth, slip=False, before="", after="", slow=False):
    return {"id": cid, "book": book, "latex": latex, "let": let, "truth": truth,
            "slip": slip, "before": before, "after": after, "slow": slow}


SH, MC, KU_B, MLS, MSKS, DI = ("Shuster 1993", "Markley-Crassidis 2014", "Kuipers 1999",
                                "Murray-Li-Sastry 1994", "Ma-Soatto-Kosecka-Sastry 2004",
                                "Diebel 2006")

CASES = [
    _c("sh-axis-fixed", SH, r"A\hat{\mathbf{n}} = \hat{\mathbf{n}}",
       [AXANG, r"\hat{\mathbf{n}}: unit vector", r"\theta: angle"], t_sh_axis),
    _c("sh-trace", SH, r"\operatorname{tr}A = 1 + 2\cos\theta",
       [AXANG, r"\hat{\mathbf{n}}: unit vector", r"\theta: angle"], t_sh_trace),
    _c("sh-trace-slip", SH, r"\operatorname{tr}A = 1 + \cos\theta",
       [AXANG, r"\hat{\mathbf{n}}: unit vector", r"\theta: angle"],
       lambda rng: t_sh_trace(rng, True), slip=True),
    _c("sh-gibbs-compose", SH, r"A(\mathbf{g}'') = A(\mathbf{g}')A(\mathbf{g})",
       [GIBBS_A, r"\mathbf{g}'' = \frac{\mathbf{g}' + \mathbf{g} - \mathbf{g}'\times\mathbf{g}}{1 - \mathbf{g}'\cdot\mathbf{g}}"],
       t_sh_gibbs_compose),
    _c("sh-skew-square", SH, r"[[\mathbf{u}]]^2 = \mathbf{u}\mathbf{u}^T - |\mathbf{u}|^2 I_3",
       [], t_sh_skew_square),
    _c("sh-gibbs-from-a", SH,
       r"\mathbf{g} = \frac{1}{1 + \operatorname{tr}A}\begin{bmatrix} A_{23} - A_{32} \\ A_{31} - A_{13} \\ A_{12} - A_{21} \end{bmatrix}",
       [r"A = \frac{(1 - \mathbf{g}^T\mathbf{g})I_3 + 2\mathbf{g}\mathbf{g}^T - 2[\mathbf{g}\times]}{1 + \mathbf{g}^T\mathbf{g}}"],
       t_sh_gibbs_from_a),
    _c("mc-psi-orth", MC, r"\Psi(\mathbf{q})^T\Psi(\mathbf{q}) = I_3",
       [PSI, r"\mathbf{q}: unit 4-vector"], t_mc_psi_orth),
    _c("mc-xi-proj", MC, r"\Xi(\mathbf{q})\Xi^T(\mathbf{q}) = I_4 - \mathbf{q}\mathbf{q}^T",
       [XI, r"\mathbf{q}: unit 4-vector"], t_mc_xi_proj),
    _c("mc-xi-proj-slip", MC, r"\Xi(\mathbf{q})\Xi^T(\mathbf{q}) = I_4",
       [XI, r"\mathbf{q}: unit 4-vector"], lambda rng: t_mc_xi_proj(rng, True), slip=True),
    _c("mc-at-psi-xi", MC, r"A^T(\mathbf{q}) = \Psi^T(\mathbf{q})\Xi(\mathbf{q})",
       [AQ, XI, PSI, r"\mathbf{q}: unit 4-vector"], t_mc_at_psi_xi),
    _c("mc-psi-q", MC, r"\Psi^T(\mathbf{q})\mathbf{q} = \mathbf{0}_3",
       [PSI, r"\mathbf{q}: unit 4-vector"], t_mc_psi_q),
    _c("mc-axang-transpose", MC, r"A^T(\mathbf{e}, \vartheta) = A(\mathbf{e}, -\vartheta)",
       [r"A(\mathbf{e}, \vartheta) = \cos\vartheta I_3 - \sin\vartheta[\mathbf{e}\times] + (1 - \cos\vartheta)\mathbf{e}\mathbf{e}^T",
        r"\mathbf{e}: unit vector", r"\vartheta: angle"], t_mc_axang_transpose),
    _c("mc-mrp-shadow", MC, r"A(\mathbf{p}^S) = A(\mathbf{p})",
       [MRP, r"\mathbf{p}^S = -\frac{\mathbf{p}}{\|\mathbf{p}\|^2}"], t_mc_mrp_shadow),
    _c("ku-axis", KU_B, r"M\mathbf{u} = \mathbf{u}", KU, t_ku_axis),
    _c("ku-orth", KU_B, r"M^TM = I", KU, t_ku_orth),
    _c("ku-trace", KU_B, r"\operatorname{tr}M = 4q_0^2 - 1", KU, t_ku_trace),
    _c("ku-trace-slip", KU_B, r"\operatorname{tr}M = 4q_0^2 + 1", KU,
       lambda rng: t_ku_trace(rng, True), slip=True),
    _c("mls-hat-square", MLS, r"\hat\omega^2 = \omega\omega^T - I", [r"\omega: unit vector"],
       t_mls_hat_square),
    _c("mls-2link-reach", MLS, r"\|\mathbf{p}\|^2 = l_1^2 + l_2^2 + 2l_1l_2\cos\theta_2", [P2],
       t_mls_2link_reach),
    _c("mls-2link-reach-slip", MLS, r"\|\mathbf{p}\|^2 = l_1^2 + l_2^2 - 2l_1l_2\cos\theta_2", [P2],
       lambda rng: t_mls_2link_reach(rng, True), slip=True),
    _c("msks-epipolar", MSKS, r"\mathbf{x}_2^T\widehat{T}R\mathbf{x}_1 = 0",
       [r"R: rotation", r"T: vector",
        r"\mathbf{x}_2 = \frac{\lambda_1 R\mathbf{x}_1 + T}{\lambda_2}"], t_msks_epipolar),
    _c("msks-et", MSKS, r"E^T T = 0", [r"E = \widehat{T}R", r"R: rotation", r"T: vector"], t_msks_et),
    _c("msks-et-slip", MSKS, r"E T = 0", [r"E = \widehat{T}R", r"R: rotation", r"T: vector"],
       lambda rng: t_msks_et(rng, True), slip=True),
    _c("msks-tr-eet", MSKS, r"\operatorname{trace}(EE^T) = 2\|T\|^2",
       [r"E = \widehat{T}R", r"R: rotation", r"T: vector"], t_msks_tr_eet),
    _c("msks-homography", MSKS, r"H\mathbf{X} = R\mathbf{X} + T",
       [r"H = R + \frac{1}{d}TN^T", r"\mathbf{X} = dN + N\times\mathbf{Y}", r"R: rotation",
        r"T: vector", r"N: unit vector"], t_msks_homography),
    _c("msks-hat-anti", MSKS, r"\widehat{u}v = -\widehat{v}u", [r"u: vector", r"v: vector"],
       t_msks_hat_anti),
    _c("di-quat-orth", DI, r"R(\mathbf{q})^TR(\mathbf{q}) = (q_0^2 + q_1^2 + q_2^2 + q_3^2)^2 I_3",
       [DIEBEL], t_di_quat_orth),
    _c("di-r1-compose", DI, r"R_1(\phi)R_1(\psi) = R_1(\phi + \psi)", [R1], t_di_r1_compose),
    _c("mls-exp-fixed", MLS, r"R\mathbf{v} = \mathbf{v}", [EXPV], t_mls_exp_fixed),
    _c("mls-exp-orth", MLS, r"R^TR = I_3", [EXPV], t_mls_exp_orth),
    _c("mls-exp-orth-slip", MLS, r"R^TR = I_3",
       [EXPV.replace(r"{\|\mathbf{v}\|^2}", r"{\|\mathbf{v}\|}")],
       lambda rng: t_mls_exp_orth(rng, True), slip=True),
    # ------------------------------------------------ kinematic differential equations
    _c("k-sh-quat-omega", SH, r"\dot{A} = -[\boldsymbol\omega\times]A",
       [AQ.replace(r"A(\mathbf{q})", "A"),
        r"\dot{\mathbf{q}} = \frac{1}{2}\Omega(\boldsymbol\omega)\mathbf{q}",
        r"\Omega(\boldsymbol\omega) = \begin{bmatrix} -[\boldsymbol\omega\times] & \boldsymbol\omega \\ -\boldsymbol\omega^T & 0 \end{bmatrix}",
        r"\mathbf{q}(t): unit 4-vector", r"\boldsymbol\omega: vector"], t_k_sh_quat),
    _c("k-mc-gibbs", MC, r"[\boldsymbol\omega\times] = -\dot{A}A^T",
       [GIBBS_A.replace(r"A(\mathbf{g})", "A"),
        r"\dot{\mathbf{g}} = \frac{1}{2}\left(\boldsymbol\omega + \mathbf{g}\times\boldsymbol\omega + (\mathbf{g}\cdot\boldsymbol\omega)\mathbf{g}\right)",
        r"\boldsymbol\omega: vector"], t_k_mc_gibbs),
    _c("k-mc-gibbs-slip", MC, r"[\boldsymbol\omega\times] = -\dot{A}A^T",
       [GIBBS_A.replace(r"A(\mathbf{g})", "A"),
        r"\dot{\mathbf{g}} = \frac{1}{2}\left(\boldsymbol\omega + \boldsymbol\omega\times\mathbf{g} + (\mathbf{g}\cdot\boldsymbol\omega)\mathbf{g}\right)",
        r"\boldsymbol\omega: vector"], lambda rng: t_k_mc_gibbs(rng, True), slip=True),
    _c("k-di-123", DI, r"\dot{C} = -[\boldsymbol\omega]_\times C",
       [r"C = R_3(\psi)R_2(\theta)R_1(\phi)", R1, R2, R3, W123,
        r"\phi(t): angle", r"\theta(t): angle", r"\psi(t): angle"], t_k_123),
    _c("k-di-123-slip", DI, r"\dot{C} = -[\boldsymbol\omega]_\times C",
       [r"C = R_3(\psi)R_2(\theta)R_1(\phi)", R1, R2, R3,
        W123.replace(r"\dot\phi\sin\theta + \dot\psi", r"\dot\phi\cos\theta + \dot\psi"),
        r"\phi(t): angle", r"\theta(t): angle", r"\psi(t): angle"],
       lambda rng: t_k_123(rng, True), slip=True),
    _c("k-mls-rz", MLS, r"R^T\dot{R} = \dot\theta\begin{bmatrix} 0 & -1 & 0 \\ 1 & 0 & 0 \\ 0 & 0 & 0 \end{bmatrix}",
       [r"R = \begin{bmatrix} \cos\theta & -\sin\theta & 0 \\ \sin\theta & \cos\theta & 0 \\ 0 & 0 & 1 \end{bmatrix}",
        r"\theta(t): angle"], t_k_mls_rz),
    _c("k-di-quat", DI, r"\dot{R} = -[\boldsymbol\omega]_\times R",
       [DIEBEL.replace(r"R(\mathbf{q})", "R"),
        r"\dot q_0 = \frac{1}{2}(-q_1\omega_1 - q_2\omega_2 - q_3\omega_3)",
        r"\dot q_1 = \frac{1}{2}(q_0\omega_1 - q_3\omega_2 + q_2\omega_3)",
        r"\dot q_2 = \frac{1}{2}(q_3\omega_1 + q_0\omega_2 - q_1\omega_3)",
        r"\dot q_3 = \frac{1}{2}(-q_2\omega_1 + q_1\omega_2 + q_0\omega_3)",
        r"\boldsymbol\omega = \begin{bmatrix} \omega_1 \\ \omega_2 \\ \omega_3 \end{bmatrix}"],
       t_k_di_quat),
    _c("k-mls-skew", MLS, r"(\dot{R}R^T)^T = -\dot{R}R^T", [r"R(t): rotation"], t_k_mls_skew),
    _c("k-mc-axis-angle", MC, r"\dot{A} = -[\boldsymbol\omega\times]A",
       [AXANG.replace(r"\hat{\mathbf{n}}", r"\mathbf{e}"), r"\dot\theta = \mathbf{e}^T\boldsymbol\omega",
        r"\dot{\mathbf{e}} = \frac{1}{2}\left(\mathbf{e}\times\boldsymbol\omega - \cot\frac{\theta}{2}\mathbf{e}\times(\mathbf{e}\times\boldsymbol\omega)\right)",
        r"\mathbf{e}(t): unit vector", r"\theta(t): angle", r"\boldsymbol\omega: vector"],
       t_k_axang, slow=True),
]

TRUTH_TOLERANCE = 1e-6

#: the baseline: the verdicts as typed, without the books' readings (right / refused /
#: undecided / wrong)
BASELINE = {'sh-axis-fixed': 'right',
          'sh-trace': 'right',
          'sh-trace-slip': 'right',
          'sh-gibbs-compose': 'refused',
          'sh-skew-square': 'refused',
          'sh-gibbs-from-a': 'undecided',
          'mc-psi-orth': 'refused',
          'mc-xi-proj': 'refused',
          'mc-xi-proj-slip': 'right',
          'mc-at-psi-xi': 'right',
          'mc-psi-q': 'refused',
          'mc-axang-transpose': 'refused',
          'mc-mrp-shadow': 'right',
          'ku-axis': 'right',
          'ku-orth': 'right',
          'ku-trace': 'right',
          'ku-trace-slip': 'right',
          'mls-hat-square': 'refused',
          'mls-2link-reach': 'right',
          'mls-2link-reach-slip': 'right',
          'msks-epipolar': 'refused',
          'msks-et': 'refused',
          'msks-et-slip': 'refused',
          'msks-tr-eet': 'refused',
          'msks-homography': 'refused',
          'msks-hat-anti': 'refused',
          'di-quat-orth': 'refused',
          'di-r1-compose': 'right',
          'mls-exp-fixed': 'refused',
          'mls-exp-orth': 'refused',
          'mls-exp-orth-slip': 'refused',
          'k-sh-quat-omega': 'refused',
          'k-mc-gibbs': 'right',
          'k-mc-gibbs-slip': 'right',
          'k-di-123': 'right',
          'k-di-123-slip': 'right',
          'k-mls-rz': 'right',
          'k-di-quat': 'right',
          'k-mls-skew': 'right',
          'k-mc-axis-angle': 'right'}

#: the one attempt a reader makes after a refusal, where its message names it: the
#: notation it names, the entry it names (\mathbf{q}_{4:4} for q_4), or the --let it asks for
_NOTATION_MLS = {"notation": "murray-li-sastry"}
_ENTRY_Q4 = {"replace": ("q_4", r"\mathbf{q}_{4:4}")}
ATTEMPT = {
    "mc-psi-orth": _ENTRY_Q4, "mc-xi-proj": _ENTRY_Q4, "mc-psi-q": _ENTRY_Q4,
    "k-sh-quat-omega": _ENTRY_Q4,
    "msks-epipolar": _NOTATION_MLS, "msks-et": _NOTATION_MLS, "msks-et-slip": _NOTATION_MLS,
    "msks-tr-eet": _NOTATION_MLS, "msks-hat-anti": _NOTATION_MLS,
    "mls-hat-square": _NOTATION_MLS, "mls-exp-fixed": _NOTATION_MLS,
    "mls-exp-orth": _NOTATION_MLS, "mls-exp-orth-slip": _NOTATION_MLS,
    "msks-homography": {"add": [r"\mathbf{Y}: vector"]},
    "di-quat-orth": {"add": ["q_1: scalar", "q_2: scalar", "q_3: scalar"]},
}


def attempted(case: dict) -> tuple[str, list, dict]:
    """``(latex, lets, options)`` of ``case`` after the reader's one attempt (as typed where
    :data:`ATTEMPT` has none)."""
    a = ATTEMPT.get(case["id"], {})
    latex, lets = case["latex"], list(case["let"])
    if "replace" in a:
        old, new = a["replace"]
        latex, lets = latex.replace(old, new), [x.replace(old, new) for x in lets]
    lets += a.get("add", [])
    return latex, lets, {"notation": a["notation"]} if "notation" in a else {}

#: the verdicts as typed with the first of the books' readings (none of those
#: :data:`AS_TYPED` lists)
AS_TYPED_FIRST_READINGS = {'sh-axis-fixed': 'right',
         'sh-trace': 'right',
         'sh-trace-slip': 'right',
         'sh-gibbs-compose': 'right',
         'sh-skew-square': 'refused',
         'sh-gibbs-from-a': 'refused',
         'mc-psi-orth': 'refused',
         'mc-xi-proj': 'refused',
         'mc-xi-proj-slip': 'right',
         'mc-at-psi-xi': 'right',
         'mc-psi-q': 'refused',
         'mc-axang-transpose': 'right',
         'mc-mrp-shadow': 'right',
         'ku-axis': 'right',
         'ku-orth': 'right',
         'ku-trace': 'right',
         'ku-trace-slip': 'right',
         'mls-hat-square': 'refused',
         'mls-2link-reach': 'right',
         'mls-2link-reach-slip': 'right',
         'msks-epipolar': 'refused',
         'msks-et': 'refused',
         'msks-et-slip': 'refused',
         'msks-tr-eet': 'refused',
         'msks-homography': 'refused',
         'msks-hat-anti': 'refused',
         'di-quat-orth': 'refused',
         'di-r1-compose': 'right',
         'mls-exp-fixed': 'refused',
         'mls-exp-orth': 'refused',
         'mls-exp-orth-slip': 'refused',
         'k-sh-quat-omega': 'refused',
         'k-mc-gibbs': 'right',
         'k-mc-gibbs-slip': 'right',
         'k-di-123': 'right',
         'k-di-123-slip': 'right',
         'k-mls-rz': 'right',
         'k-di-quat': 'right',
         'k-mls-skew': 'right',
         'k-mc-axis-angle': 'right'}

#: the verdicts after the reader's one attempt (:data:`ATTEMPT`; the test holds a case to
#: it where the case has an attempt), with the books' readings
AS_ATTEMPTED = {'sh-axis-fixed': 'right',
         'sh-trace': 'right',
         'sh-trace-slip': 'right',
         'sh-gibbs-compose': 'right',
         'sh-skew-square': 'refused',
         'sh-gibbs-from-a': 'refused',
         'mc-psi-orth': 'right',
         'mc-xi-proj': 'right',
         'mc-xi-proj-slip': 'right',
         'mc-at-psi-xi': 'right',
         'mc-psi-q': 'right',
         'mc-axang-transpose': 'right',
         'mc-mrp-shadow': 'right',
         'ku-axis': 'right',
         'ku-orth': 'right',
         'ku-trace': 'right',
         'ku-trace-slip': 'right',
         'mls-hat-square': 'right',
         'mls-2link-reach': 'right',
         'mls-2link-reach-slip': 'right',
         'msks-epipolar': 'right',
         'msks-et': 'right',
         'msks-et-slip': 'right',
         'msks-tr-eet': 'right',
         'msks-homography': 'right',
         'msks-hat-anti': 'right',
         'di-quat-orth': 'right',
         'di-r1-compose': 'right',
         'mls-exp-fixed': 'right',
         'mls-exp-orth': 'right',
         'mls-exp-orth-slip': 'right',
         'k-sh-quat-omega': 'right',
         'k-mc-gibbs': 'right',
         'k-mc-gibbs-slip': 'right',
         'k-di-123': 'right',
         'k-di-123-slip': 'right',
         'k-mls-rz': 'right',
         'k-di-quat': 'right',
         'k-mls-skew': 'right',
         'k-mc-axis-angle': 'right'}


#: the verdicts as typed with the books' readings: a free hat read both ways, q_k
#: beside a --let's vector its entry (a 4-vector counted from 1 or 0), Shuster's [[u]] with
#: either sign, one notation per letter in and outside a function's body, a free bold
#: capital a 3-vector where its conventional 3x3 does not fit; each decided where its
#: readings agree, refused naming the choice where they differ
AS_TYPED = {'sh-axis-fixed': 'right',
             'sh-trace': 'right',
             'sh-trace-slip': 'right',
             'sh-gibbs-compose': 'right',
             'sh-skew-square': 'right',
             'sh-gibbs-from-a': 'refused',
             'mc-psi-orth': 'right',
             'mc-xi-proj': 'right',
             'mc-xi-proj-slip': 'right',
             'mc-at-psi-xi': 'right',
             'mc-psi-q': 'right',
             'mc-axang-transpose': 'right',
             'mc-mrp-shadow': 'right',
             'ku-axis': 'right',
             'ku-orth': 'right',
             'ku-trace': 'right',
             'ku-trace-slip': 'right',
             'mls-hat-square': 'right',
             'mls-2link-reach': 'right',
             'mls-2link-reach-slip': 'right',
             'msks-epipolar': 'refused',
             'msks-et': 'right',
             'msks-et-slip': 'right',
             'msks-tr-eet': 'right',
             'msks-homography': 'right',
             'msks-hat-anti': 'right',
             'di-quat-orth': 'right',
             'di-r1-compose': 'right',
             'mls-exp-fixed': 'right',
             'mls-exp-orth': 'right',
             'mls-exp-orth-slip': 'right',
             'k-sh-quat-omega': 'right',
             'k-mc-gibbs': 'right',
             'k-mc-gibbs-slip': 'right',
             'k-di-123': 'right',
             'k-di-123-slip': 'right',
             'k-mls-rz': 'right',
             'k-di-quat': 'right',
             'k-mls-skew': 'right',
             'k-mc-axis-angle': 'right'}
