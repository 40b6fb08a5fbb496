# ruff: noqa: E501 - the LaTeX of a book equation is one line, as typed
"""The estimation and Lie-theory books typed as their readers would: 42 statements from five
sources.

Sources (none typed in the LaTeX corpus): Barfoot, *State Estimation for Robotics* (2017),
ch. 7 (SO(3), SE(3); ξ = [ρ; φ], translation first); Forster, Carlone, Dellaert & Scaramuzza,
*On-Manifold Preintegration for Real-Time Visual-Inertial Odometry* (2017), §III (Exp, J_r);
Kok, Hol & Schön, *Using Inertial Sensors for Position and Orientation Estimation* (2017),
§3 (q = [q_0; q_v], Hamilton's ⊙, the left/right matrices q^L, p^R); Chirikjian, *Stochastic
Models, Information Theory, and Lie Groups* vol. 2 (2011), ch. 10 (SO(3), its Jacobians);
and manif's documentation (Deray & Solà; SO(3) and SE(3), τ = [ρ; θ]).

Each case: an id, its book, the LaTeX and the ``--let``s as a reader of that book types them
after docs/check-latex.md (typed before any change the trial brought), ``slip`` (a one-edit
slip of a true statement), and a truth: a NumPy function of a random generator returning the
residual |lhs - rhs| at one random point of the declarations, the statement as its book
means it (the book's tangent order, Hamilton's product; a rate by central differences). The
truth never imports rigidsym: it is the independent judge. :data:`BASELINE` holds the
answers of ``rigidsym.check_latex`` as typed, judged by the truth (right / WRONG / refused /
undecided), of the checker without the rules these books need: a floor the checker keeps.
"""

from __future__ import annotations

import numpy as np

TRUTH_TOLERANCE = 1e-6

# ---------------------------------------------------------------- NumPy helpers


def _sk(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def _vee(m):
    return np.array([m[2, 1], m[0, 2], m[1, 0]])


def _unit(rng, n=3):
    v = rng.normal(size=n)
    return v / np.linalg.norm(v)


def _angle(rng, lo=-np.pi, hi=np.pi):
    return float(rng.uniform(lo, hi))


def _exp3(phi):
    """Rodrigues' formula, written out (not scipy's): exp of the hat of phi."""
    th = np.linalg.norm(phi)
    if th < 1e-12:
        return np.eye(3) + _sk(phi)
    k = _sk(phi / th)
    return np.eye(3) + np.sin(th) * k + (1 - np.cos(th)) * k @ k


def _expm(a, terms=40):
    """The matrix exponential by its series, scaled and squared (independent of sympy)."""
    s = max(0, int(np.ceil(np.log2(max(np.abs(a).sum(), 1.0)))) + 1)
    b = a / 2 ** s
    out, term = np.eye(len(a)), np.eye(len(a))
    for k in range(1, terms):
        term = term @ b / k
        out = out + term
    for _ in range(s):
        out = out @ out
    return out


def _rot(rng):
    return _exp3(_unit(rng) * _angle(rng))


def _tf(rot, p):
    t = np.eye(4)
    t[:3, :3], t[:3, 3] = rot, p
    return t


def _ad_rho_first(t):
    """Ad of a 4×4 transform for the tangent order [ρ; θ] (translation first)."""
    r, p = t[:3, :3], t[:3, 3]
    out = np.zeros((6, 6))
    out[:3, :3], out[:3, 3:], out[3:, 3:] = r, _sk(p) @ r, r
    return out


def _hat6_rho_first(x):
    """The 4×4 se(3) matrix of x = [ρ; θ]."""
    m = np.zeros((4, 4))
    m[:3, :3], m[:3, 3] = _sk(x[3:]), x[:3]
    return m


def _adj6_rho_first(x):
    """ad of x = [ρ; θ] (Barfoot's ξ^⋏)."""
    out = np.zeros((6, 6))
    out[:3, :3], out[:3, 3:], out[3:, 3:] = _sk(x[3:]), _sk(x[:3]), _sk(x[3:])
    return out


def _res(a, b):
    return float(np.max(np.abs(np.asarray(a, float) - np.asarray(b, float))))


def _qmul(p, q):
    """Hamilton's product of scalar-first quaternions, written from its definition."""
    p0, pv, q0, qv = p[0], np.asarray(p[1:]), q[0], np.asarray(q[1:])
    return np.concatenate([[p0 * q0 - pv @ qv], p0 * qv + q0 * pv + np.cross(pv, qv)])


def _qL(q):
    m = np.zeros((4, 4))
    m[0, 0], m[0, 1:], m[1:, 0] = q[0], -q[1:], q[1:]
    m[1:, 1:] = q[0] * np.eye(3) + _sk(q[1:])
    return m


def _qR(q):
    m = _qL(q)
    m[1:, 1:] = q[0] * np.eye(3) - _sk(q[1:])
    return m


def _qrot(q):
    q0, qv = q[0], q[1:]
    return np.outer(qv, qv) + q0 ** 2 * np.eye(3) + 2 * q0 * _sk(qv) + _sk(qv) @ _sk(qv)


def _jr(phi):
    th = np.linalg.norm(phi)
    k = _sk(phi)
    return np.eye(3) - (1 - np.cos(th)) / th ** 2 * k + (th - np.sin(th)) / th ** 3 * k @ k


def _jl(phi):
    return _jr(-phi)


def _jr_inv(phi):
    th = np.linalg.norm(phi)
    k = _sk(phi)
    return (np.eye(3) + 0.5 * k
            + (1 / th ** 2 - (1 + np.cos(th)) / (2 * th * np.sin(th))) * k @ k)


# ---------------------------------------------------------------- truths, one per case


def _ua(rng):
    return _unit(rng), _angle(rng)


def t_b_orth(rng):
    c = _rot(rng)
    return _res(c.T @ c, np.eye(3))


def t_b_hat_conj(rng, slip=False):
    c, a = _rot(rng), rng.normal(size=3)
    rhs = c.T @ _sk(a) @ c if slip else c @ _sk(a) @ c.T
    return _res(_sk(c @ a), rhs)


def t_b_rodrigues(rng, slip=False):
    a, ph = _ua(rng)
    s = -1 if slip else 1
    rhs = np.cos(ph) * np.eye(3) + (1 - np.cos(ph)) * np.outer(a, a) + s * np.sin(ph) * _sk(a)
    return _res(_expm(ph * _sk(a)), rhs)


def t_b_ad_hom(rng):
    t1, t2 = _tf(_rot(rng), rng.normal(size=3)), _tf(_rot(rng), rng.normal(size=3))
    return _res(_ad_rho_first(t1 @ t2), _ad_rho_first(t1) @ _ad_rho_first(t2))


def t_b_ad_inv(rng):
    t = _tf(_rot(rng), rng.normal(size=3))
    return _res(_ad_rho_first(np.linalg.inv(t)), np.linalg.inv(_ad_rho_first(t)))


def t_b_curly_anti(rng):
    x, z = rng.normal(size=6), rng.normal(size=6)
    return _res(_adj6_rho_first(x) @ z, -_adj6_rho_first(z) @ x)


def t_b_hat_sq(rng, slip=False):
    a = rng.normal(size=3)
    rhs = np.outer(a, a) + (a @ a) * np.eye(3) if slip else np.outer(a, a) - (a @ a) * np.eye(3)
    return _res(_sk(a) @ _sk(a), rhs)


def _barfoot_j(a, ph, slip=False):
    s = -1 if slip else 1
    return (np.sin(ph) / ph * np.eye(3) + (1 - np.sin(ph) / ph) * np.outer(a, a)
            + s * (1 - np.cos(ph)) / ph * _sk(a))


def t_b_jleft(rng, slip=False):
    a, ph = _ua(rng)
    return _res(_expm(ph * _sk(a)), np.eye(3) + ph * _sk(a) @ _barfoot_j(a, ph, slip))


def t_b_tinv(rng, slip=False):
    c, r = _rot(rng), rng.normal(size=3)
    inv = _tf(c.T, (c.T @ r) if slip else -(c.T @ r))
    return _res(np.linalg.inv(_tf(c, r)), inv)


def t_b_ad_explicit(rng, slip=False):
    c, r = _rot(rng), rng.normal(size=3)
    m = np.zeros((6, 6))
    m[:3, :3], m[3:, 3:] = c, c
    if slip:
        m[3:, :3] = _sk(r) @ c
    else:
        m[:3, 3:] = _sk(r) @ c
    return _res(_ad_rho_first(_tf(c, r)), m)


def t_b_ad_hat(rng):
    t, x = _tf(_rot(rng), rng.normal(size=3)), rng.normal(size=6)
    return _res(_hat6_rho_first(_ad_rho_first(t) @ x), t @ _hat6_rho_first(x) @ np.linalg.inv(t))


def t_f_exp_adj(rng, slip=False):
    r, (u, th) = _rot(rng), _ua(rng)
    lhs = r.T @ _exp3(th * u) @ r if slip else r @ _exp3(th * u) @ r.T
    return _res(lhs, _exp3(r @ (th * u)))


def t_f_rate(rng, slip=False):
    u, th, thd = _unit(rng), _angle(rng), rng.normal()
    h = 1e-6
    rdot = (_exp3((th + h * thd) * u) - _exp3((th - h * thd) * u)) / (2 * h)
    r = _exp3(th * u)
    rhs = _sk(thd * u) @ r.T if slip else r @ _sk(thd * u)
    return _res(rdot, rhs)


def t_f_jr_phi(rng):
    u, th = _ua(rng)
    return _res(_jr(th * u) @ (th * u), th * u)


def t_f_r_jr(rng, slip=False):
    u, th = _ua(rng)
    r = _exp3(th * u)
    return _res((r.T if slip else r) @ _jr(th * u), _jr(th * u).T)


def t_f_log(rng):
    u, th = _unit(rng), _angle(rng, 0.1, np.pi - 0.1)
    r = _exp3(th * u)
    c = np.clip((np.trace(r) - 1) / 2, -1, 1)
    ang = np.arccos(c)
    return _res(ang / (2 * np.sin(ang)) * (r - r.T), th * _sk(u))


def _kq(rng):
    q = _unit(rng, 4)
    return q


def t_k_lr_commute(rng):
    q, p = rng.normal(size=4), rng.normal(size=4)
    return _res(_qL(q) @ _qR(p), _qR(p) @ _qL(q))


def t_k_rot_orth(rng, slip=False):
    q = _kq(rng)
    r = _qrot(q)
    if slip:
        q0, qv = q[0], q[1:]
        r = np.outer(qv, qv) + q0 ** 2 * np.eye(3) + 2 * q0 * _sk(qv) + _sk(qv)
    return _res(r.T @ r, np.eye(3))


def t_k_odot(rng, slip=False):
    p, q = rng.normal(size=4), rng.normal(size=4)
    return _res(_qmul(p, q), (_qR(p) if slip else _qL(p)) @ q)


def t_k_odot_right(rng):
    p, q = rng.normal(size=4), rng.normal(size=4)
    return _res(_qmul(p, q), _qR(q) @ p)


def t_k_rotate(rng):
    # Kok (3.23): [0; R v] = q ⊙ [0; v] ⊙ q^c, R = R(q) of (3.25)
    q, v = _kq(rng), rng.normal(size=3)
    qc = np.concatenate([[q[0]], -q[1:]])
    lhs = np.concatenate([[0.0], _qrot(q) @ v])
    return _res(lhs, _qmul(_qmul(q, np.concatenate([[0.0], v])), qc))


def t_k_rot_product(rng):
    p, q = _kq(rng), _kq(rng)
    return _res(_qrot(_qmul(p, q)), _qrot(p) @ _qrot(q))


def t_c_trace(rng, slip=False):
    u, th = _ua(rng)
    return _res(np.trace(_exp3(th * u)), (1 if slip else 1 + np.cos(th)) + (0 if slip else np.cos(th)))


def t_c_vee(rng):
    u, th = _ua(rng)
    r = _exp3(th * u)
    return _res(_vee(r - r.T), 2 * np.sin(th) * u)


def t_c_jl_det(rng):
    u, th = _ua(rng)
    return _res(np.linalg.det(_jl(th * u)), 2 * (1 - np.cos(th)) / th ** 2)


def t_c_cross_hat(rng, slip=False):
    a, b = rng.normal(size=3), rng.normal(size=3)
    s = 1 if slip else -1
    return _res(_sk(np.cross(a, b)), _sk(a) @ _sk(b) + s * _sk(b) @ _sk(a))


def t_m_so3_ad(rng):
    # manif: Ad of SO(3) is R itself (R θ^∧ R^T = (R θ)^∧)
    r, x = _rot(rng), rng.normal(size=3)
    return _res(r @ _sk(x) @ r.T, _sk(r @ x))


def t_m_se3_ad(rng):
    return t_b_ad_explicit(rng)


def t_m_jr_norm(rng):
    u, th = _ua(rng)
    return _res(_jr(th * u) @ (th * u), th * u)


def t_m_jr_inv(rng):
    u, th = _ua(rng)
    return _res(_jr(th * u) @ _jr_inv(th * u), np.eye(3))


def t_m_se3_exp(rng):
    # manif: Exp([ρ; θ]) = [Exp(θ), V(θ) ρ; 0, 1]; here its rotation part and V ρ of a unit axis
    u, th, rho = _unit(rng), _angle(rng), rng.normal(size=3)
    x = np.concatenate([rho, th * u])
    k = _sk(u)
    v = np.eye(3) + (1 - np.cos(th)) / th * k + (th - np.sin(th)) / th * k @ k
    return _res(_expm(_hat6_rho_first(x)), _tf(_exp3(th * u), v @ rho))


# ---------------------------------------------------------------- the cases

C = r"\mathbf{C}: rotation"
T12 = [r"\mathbf{T}_1: transform", r"\mathbf{T}_2: transform"]
AXIS = [r"\mathbf{u}: unit vector", r"\theta: angle"]
BJ = r"\mathbf{J} = \frac{\sin\phi}{\phi}\mathbf{1} + \left(1 - \frac{\sin\phi}{\phi}\right)\mathbf{a}\mathbf{a}^T + \frac{1 - \cos\phi}{\phi}\mathbf{a}^\wedge"
JR = r"\mathbf{J}_r = \mathbf{I} - \frac{1 - \cos\theta}{\theta}\mathbf{u}^\wedge + \frac{\theta - \sin\theta}{\theta}\mathbf{u}^\wedge\mathbf{u}^\wedge"
KQV = r"\mathbf{q}_v = \begin{bmatrix} q_1 \\ q_2 \\ q_3 \end{bmatrix}"
KL = r"\mathbf{q}^L = \begin{bmatrix} q_0 & -\mathbf{q}_v^T \\ \mathbf{q}_v & q_0\mathbf{I}_3 + [\mathbf{q}_v]_\times \end{bmatrix}"
KR_P = r"\mathbf{p}^R = \begin{bmatrix} p_0 & -\mathbf{p}_v^T \\ \mathbf{p}_v & p_0\mathbf{I}_3 - [\mathbf{p}_v]_\times \end{bmatrix}"
KPV = r"\mathbf{p}_v = \begin{bmatrix} p_1 \\ p_2 \\ p_3 \end{bmatrix}"
KRQ = r"\mathbf{R} = \mathbf{q}_v\mathbf{q}_v^T + q_0^2\mathbf{I}_3 + 2q_0[\mathbf{q}_v]_\times + [\mathbf{q}_v]_\times^2"
MSE3 = [r"\mathbf{M} = \begin{bmatrix} \mathbf{R} & \mathbf{t} \\ \mathbf{0}^T & 1 \end{bmatrix}",
         r"\mathbf{R}: rotation", r"\mathbf{t}: vector"]


def _case(cid, book, latex, let, truth, slip=False):
    return {"id": cid, "book": book, "latex": latex, "let": list(let), "slip": slip,
            "truth": truth}


def _slip(f):
    return lambda rng: f(rng, slip=True)


BAR, FOR, KOK, CHI, MAN = ("Barfoot 2017", "Forster et al. 2017", "Kok-Hol-Schon 2017",
                          "Chirikjian 2011", "manif docs")

CASES = [
    _case("b-orth", BAR, r"\mathbf{C}^T\mathbf{C} = \mathbf{1}", [C], t_b_orth),
    _case("b-hat-conj", BAR, r"(\mathbf{C}\mathbf{a})^\wedge = \mathbf{C}\mathbf{a}^\wedge\mathbf{C}^T", [C, r"\mathbf{a}: vector"], t_b_hat_conj),
    _case("b-hat-conj-slip", BAR, r"(\mathbf{C}\mathbf{a})^\wedge = \mathbf{C}^T\mathbf{a}^\wedge\mathbf{C}", [C, r"\mathbf{a}: vector"], _slip(t_b_hat_conj), True),
    _case("b-rodrigues", BAR, r"\exp(\phi\mathbf{a}^\wedge) = \cos\phi\mathbf{1} + (1 - \cos\phi)\mathbf{a}\mathbf{a}^T + \sin\phi\mathbf{a}^\wedge", [r"\mathbf{a}: unit vector", r"\phi: angle"], t_b_rodrigues),
    _case("b-rodrigues-slip", BAR, r"\exp(\phi\mathbf{a}^\wedge) = \cos\phi\mathbf{1} + (1 - \cos\phi)\mathbf{a}\mathbf{a}^T - \sin\phi\mathbf{a}^\wedge", [r"\mathbf{a}: unit vector", r"\phi: angle"], _slip(t_b_rodrigues), True),
    _case("b-ad-hom", BAR, r"\mathrm{Ad}(\mathbf{T}_1\mathbf{T}_2) = \mathrm{Ad}(\mathbf{T}_1)\mathrm{Ad}(\mathbf{T}_2)", T12, t_b_ad_hom),
    _case("b-ad-inv", BAR, r"\mathrm{Ad}(\mathbf{T}^{-1}) = \mathrm{Ad}(\mathbf{T})^{-1}", [r"\mathbf{T}: transform"], t_b_ad_inv),
    _case("b-curly-anti", BAR, r"\boldsymbol\xi^\curlywedge\boldsymbol\zeta = -\boldsymbol\zeta^\curlywedge\boldsymbol\xi", [r"\boldsymbol\xi: 6-vector", r"\boldsymbol\zeta: 6-vector"], t_b_curly_anti),
    _case("b-hat-sq", BAR, r"\mathbf{a}^\wedge\mathbf{a}^\wedge = \mathbf{a}\mathbf{a}^T - \mathbf{a}^T\mathbf{a}\mathbf{1}", [r"\mathbf{a}: vector"], t_b_hat_sq),
    _case("b-hat-sq-slip", BAR, r"\mathbf{a}^\wedge\mathbf{a}^\wedge = \mathbf{a}\mathbf{a}^T + \mathbf{a}^T\mathbf{a}\mathbf{1}", [r"\mathbf{a}: vector"], _slip(t_b_hat_sq), True),
    _case("b-jleft", BAR, r"\exp(\phi\mathbf{a}^\wedge) = \mathbf{1} + \phi\mathbf{a}^\wedge\mathbf{J}", [r"\mathbf{a}: unit vector", r"\phi: angle", BJ], t_b_jleft),
    _case("b-jleft-slip", BAR, r"\exp(\phi\mathbf{a}^\wedge) = \mathbf{1} + \phi\mathbf{a}^\wedge\mathbf{J}", [r"\mathbf{a}: unit vector", r"\phi: angle", BJ.replace(r"\right)\mathbf{a}\mathbf{a}^T + \frac{1 - \cos", r"\right)\mathbf{a}\mathbf{a}^T - \frac{1 - \cos")], _slip(t_b_jleft), True),
    _case("b-tinv", BAR, r"\mathbf{T}^{-1} = \begin{bmatrix} \mathbf{C}^T & -\mathbf{C}^T\mathbf{r} \\ \mathbf{0}^T & 1 \end{bmatrix}", [r"\mathbf{T} = \begin{bmatrix} \mathbf{C} & \mathbf{r} \\ \mathbf{0}^T & 1 \end{bmatrix}", C, r"\mathbf{r}: vector"], t_b_tinv),
    _case("b-ad-explicit", BAR, r"\mathrm{Ad}(\mathbf{T}) = \begin{bmatrix} \mathbf{C} & \mathbf{r}^\wedge\mathbf{C} \\ \mathbf{0} & \mathbf{C} \end{bmatrix}", [r"\mathbf{T} = \begin{bmatrix} \mathbf{C} & \mathbf{r} \\ \mathbf{0}^T & 1 \end{bmatrix}", C, r"\mathbf{r}: vector"], t_b_ad_explicit),
    _case("b-ad-hat", BAR, r"(\mathrm{Ad}(\mathbf{T})\boldsymbol\xi)^\wedge = \mathbf{T}\boldsymbol\xi^\wedge\mathbf{T}^{-1}", [r"\mathbf{T}: transform", r"\boldsymbol\xi: 6-vector"], t_b_ad_hat),
    _case("f-exp-adj", FOR, r"\mathbf{R}\exp(\theta\mathbf{u}^\wedge)\mathbf{R}^T = \exp((\mathbf{R}\theta\mathbf{u})^\wedge)", [r"\mathbf{R}: rotation"] + AXIS, t_f_exp_adj),
    _case("f-exp-adj-slip", FOR, r"\mathbf{R}^T\exp(\theta\mathbf{u}^\wedge)\mathbf{R} = \exp((\mathbf{R}\theta\mathbf{u})^\wedge)", [r"\mathbf{R}: rotation"] + AXIS, _slip(t_f_exp_adj), True),
    _case("f-rate", FOR, r"\dot{\mathbf{R}} = \mathbf{R}(\dot\theta\mathbf{u})^\wedge", [r"\mathbf{R} = \exp(\theta\mathbf{u}^\wedge)", r"\mathbf{u}: unit vector", r"\theta(t): angle"], t_f_rate),
    _case("f-rate-slip", FOR, r"\dot{\mathbf{R}} = (\dot\theta\mathbf{u})^\wedge\mathbf{R}^T", [r"\mathbf{R} = \exp(\theta\mathbf{u}^\wedge)", r"\mathbf{u}: unit vector", r"\theta(t): angle"], _slip(t_f_rate), True),
    _case("f-jr-phi", FOR, r"\mathbf{J}_r\theta\mathbf{u} = \theta\mathbf{u}", AXIS + [JR], t_f_jr_phi),
    _case("f-r-jr", FOR, r"\exp(\theta\mathbf{u}^\wedge)\mathbf{J}_r = \mathbf{J}_r^T", AXIS + [JR], t_f_r_jr),
    _case("f-r-jr-slip", FOR, r"\exp(\theta\mathbf{u}^\wedge)^T\mathbf{J}_r = \mathbf{J}_r^T", AXIS + [JR], _slip(t_f_r_jr), True),
    _case("f-log", FOR, r"\log(\exp(\theta\mathbf{u}^\wedge)) = \theta\mathbf{u}^\wedge", [r"\mathbf{u}: unit vector", r"\theta: angle in [0, pi]"], t_f_log),
    _case("k-lr-commute", KOK, r"\mathbf{q}^L\mathbf{p}^R = \mathbf{p}^R\mathbf{q}^L", [KL, KR_P, KQV, KPV, r"q_0: scalar", r"p_0: scalar"], t_k_lr_commute),
    _case("k-rot-orth", KOK, r"\mathbf{R}^T\mathbf{R} = \mathbf{I}_3", [r"\mathbf{q}: unit 4-vector", KQV, KRQ], t_k_rot_orth),
    _case("k-rot-orth-slip", KOK, r"\mathbf{R}^T\mathbf{R} = \mathbf{I}_3", [r"\mathbf{q}: unit 4-vector", KQV, KRQ.replace(r"[\mathbf{q}_v]_\times^2", r"[\mathbf{q}_v]_\times")], _slip(t_k_rot_orth), True),
    _case("k-odot", KOK, r"\mathbf{p}\odot\mathbf{q} = \mathbf{p}^L\mathbf{q}", [r"\mathbf{p}: 4-vector", r"\mathbf{q}: 4-vector"], t_k_odot),
    _case("k-odot-slip", KOK, r"\mathbf{p}\odot\mathbf{q} = \mathbf{p}^R\mathbf{q}", [r"\mathbf{p}: 4-vector", r"\mathbf{q}: 4-vector"], _slip(t_k_odot), True),
    _case("k-odot-right", KOK, r"\mathbf{p}\odot\mathbf{q} = \mathbf{q}^R\mathbf{p}", [r"\mathbf{p}: 4-vector", r"\mathbf{q}: 4-vector"], t_k_odot_right),
    _case("k-rotate", KOK, r"\begin{bmatrix} 0 \\ \mathbf{R}\mathbf{v} \end{bmatrix} = \mathbf{q}\odot\begin{bmatrix} 0 \\ \mathbf{v} \end{bmatrix}\odot\mathbf{q}^c", [r"\mathbf{q}: unit 4-vector", KQV, KRQ, r"\mathbf{v}: vector"], t_k_rotate),
    _case("k-rot-product", KOK, r"\mathbf{R}(\mathbf{p}\odot\mathbf{q}) = \mathbf{R}(\mathbf{p})\mathbf{R}(\mathbf{q})", [r"\mathbf{p}: unit 4-vector", r"\mathbf{q}: unit 4-vector"], t_k_rot_product),
    _case("c-trace", CHI, r"\operatorname{tr}(R) = 1 + 2\cos\theta", [r"R = \exp(\theta\hat{\mathbf{u}})", r"\hat{\mathbf{u}} = [\mathbf{u}]_\times"] + AXIS, t_c_trace),
    _case("c-trace-slip", CHI, r"\operatorname{tr}(R) = 1 + \cos\theta", [r"R = \exp(\theta\hat{\mathbf{u}})", r"\hat{\mathbf{u}} = [\mathbf{u}]_\times"] + AXIS, _slip(t_c_trace), True),
    _case("c-vee", CHI, r"(R - R^T)^\vee = 2\sin\theta\,\mathbf{u}", [r"R = \exp(\theta\hat{\mathbf{u}})", r"\hat{\mathbf{u}} = [\mathbf{u}]_\times"] + AXIS, t_c_vee),
    _case("c-jl-det", CHI, r"\det J_l = \frac{2(1 - \cos\theta)}{\theta^2}", [r"J_l = \mathbf{I} + \frac{1 - \cos\theta}{\theta}\hat{\mathbf{u}} + \frac{\theta - \sin\theta}{\theta}\hat{\mathbf{u}}^2", r"\hat{\mathbf{u}} = [\mathbf{u}]_\times"] + AXIS, t_c_jl_det),
    _case("c-cross-hat", CHI, r"(\mathbf{a}\times\mathbf{b})^\wedge = \mathbf{a}^\wedge\mathbf{b}^\wedge - \mathbf{b}^\wedge\mathbf{a}^\wedge", [], t_c_cross_hat),
    _case("c-cross-hat-slip", CHI, r"(\mathbf{a}\times\mathbf{b})^\wedge = \mathbf{a}^\wedge\mathbf{b}^\wedge + \mathbf{b}^\wedge\mathbf{a}^\wedge", [], _slip(t_c_cross_hat), True),
    _case("m-so3-ad", MAN, r"\mathbf{Ad}_{\mathbf{R}} = \mathbf{R}", [r"\mathbf{R}: rotation"], t_m_so3_ad),
    _case("m-se3-ad", MAN, r"\mathbf{Ad}_{\mathbf{M}} = \begin{bmatrix} \mathbf{R} & [\mathbf{t}]_\times\mathbf{R} \\ \mathbf{0} & \mathbf{R} \end{bmatrix}", MSE3, t_m_se3_ad),
    _case("m-jr-norm", MAN, r"\mathbf{J}_r\boldsymbol\theta = \boldsymbol\theta", [r"\theta = \|\boldsymbol\theta\|", r"\boldsymbol\theta: vector", r"\mathbf{J}_r = \mathbf{I} - \frac{1 - \cos\theta}{\theta^2}[\boldsymbol\theta]_\times + \frac{\theta - \sin\theta}{\theta^3}[\boldsymbol\theta]_\times^2"], t_m_jr_norm),
    _case("m-jr-inv", MAN, r"\mathbf{J}_r\mathbf{J}_r^{-1} = \mathbf{I}", AXIS + [JR, r"\mathbf{J}_r^{-1} = \mathbf{I} + \frac{1}{2}\theta[\mathbf{u}]_\times + \left(1 - \frac{\theta(1 + \cos\theta)}{2\sin\theta}\right)[\mathbf{u}]_\times^2"], t_m_jr_inv),
    _case("m-se3-exp", MAN, r"\exp(\boldsymbol\tau^\wedge) = \begin{bmatrix} \exp(\theta[\mathbf{u}]_\times) & \mathbf{V}\boldsymbol\rho \\ \mathbf{0}^T & 1 \end{bmatrix}", AXIS + [r"\boldsymbol\tau = \begin{bmatrix} \boldsymbol\rho \\ \theta\mathbf{u} \end{bmatrix}", r"\boldsymbol\rho: vector", r"\mathbf{V} = \mathbf{I} + \frac{1 - \cos\theta}{\theta}[\mathbf{u}]_\times + \frac{\theta - \sin\theta}{\theta}[\mathbf{u}]_\times^2"], t_m_se3_exp),
]


#: the baseline: the answers as typed, judged by the truth, of the checker without the rules
#: these books need (a 60 s limit per case; none reached it): 31 right, 10 refused, 1 undecided, 0 WRONG (the
#: Kok case k-rotate replaced an ill-posed rate, refused at \odot alike)
BASELINE = {
    'b-orth': 'right',
    'b-hat-conj': 'right',
    'b-hat-conj-slip': 'right',
    'b-rodrigues': 'right',
    'b-rodrigues-slip': 'right',
    'b-ad-hom': 'right',
    'b-ad-inv': 'right',
    'b-curly-anti': 'refused',
    'b-hat-sq': 'right',
    'b-hat-sq-slip': 'right',
    'b-jleft': 'right',
    'b-jleft-slip': 'right',
    'b-tinv': 'refused',
    'b-ad-explicit': 'refused',
    'b-ad-hat': 'right',
    'f-exp-adj': 'right',
    'f-exp-adj-slip': 'right',
    'f-rate': 'right',
    'f-rate-slip': 'right',
    'f-jr-phi': 'right',
    'f-r-jr': 'right',
    'f-r-jr-slip': 'right',
    'f-log': 'right',
    'k-lr-commute': 'right',
    'k-rot-orth': 'right',
    'k-rot-orth-slip': 'right',
    'k-odot': 'refused',
    'k-odot-slip': 'refused',
    'k-odot-right': 'refused',
    'k-rotate': 'refused',
    'k-rot-product': 'refused',
    'c-trace': 'right',
    'c-trace-slip': 'right',
    'c-vee': 'right',
    'c-jl-det': 'right',
    'c-cross-hat': 'right',
    'c-cross-hat-slip': 'right',
    'm-so3-ad': 'refused',
    'm-se3-ad': 'refused',
    'm-jr-norm': 'right',
    'm-jr-inv': 'refused',
    'm-se3-exp': 'undecided',
}

#: the one attempt a reader makes after the message of a case refused or undecided as typed:
#: the --lets it adds (the message names them), or a NAME respelt
_TF = "tangent order: translation first"
_PL = r"\mathbf{p}^L = \begin{bmatrix} p_0 & -\mathbf{p}_v^T \\ \mathbf{p}_v & p_0\mathbf{I}_3 + [\mathbf{p}_v]_\times \end{bmatrix}"
_PR = r"\mathbf{p}^R = \begin{bmatrix} p_0 & -\mathbf{p}_v^T \\ \mathbf{p}_v & p_0\mathbf{I}_3 - [\mathbf{p}_v]_\times \end{bmatrix}"
_QR = r"\mathbf{q}^R = \begin{bmatrix} q_0 & -\mathbf{q}_v^T \\ \mathbf{q}_v & q_0\mathbf{I}_3 - [\mathbf{q}_v]_\times \end{bmatrix}"
ATTEMPT = {
    "b-ad-explicit": {"add": [_TF]},
    "m-se3-ad": {"add": [_TF]},
    "m-se3-exp": {"add": [_TF]},
    "m-jr-inv": {"rename": (r"\mathbf{J}_r^{-1}", r"\mathbf{K}")},
    "k-odot": {"add": [_PL, KPV]},
    "k-odot-slip": {"add": [_PR, KPV]},
    "k-odot-right": {"add": [_QR, KQV]},
    "k-rotate": {"add": [r"\mathbf{q}^c = \begin{bmatrix} q_0 \\ -\mathbf{q}_v \end{bmatrix}"]},
}


def attempted(case: dict) -> tuple[str, list]:
    """The LaTeX and ``--let``s of ``case`` after its :data:`ATTEMPT` (as typed if none)."""
    a = ATTEMPT.get(case["id"], {})
    latex, lets = case["latex"], list(case["let"]) + list(a.get("add", []))
    if "rename" in a:
        old, new = a["rename"]
        latex, lets = latex.replace(old, new), [x.replace(old, new) for x in lets]
    return latex, lets

#: the answers as typed, with the rules these books need: 34 right, 8 refused, 0 undecided,
#: 0 WRONG (k-rotate reads Kok-Hol-Schon's q^c as the conjugate beside \odot; m-se3-exp is
#: refused naming the tangent order: read [ω; v] it fails at a point where ρ has a rational
#: norm, read [v; ω] it is verified)
AS_TYPED = {
    'b-orth': 'right',
    'b-hat-conj': 'right',
    'b-hat-conj-slip': 'right',
    'b-rodrigues': 'right',
    'b-rodrigues-slip': 'right',
    'b-ad-hom': 'right',
    'b-ad-inv': 'right',
    'b-curly-anti': 'right',
    'b-hat-sq': 'right',
    'b-hat-sq-slip': 'right',
    'b-jleft': 'right',
    'b-jleft-slip': 'right',
    'b-tinv': 'right',
    'b-ad-explicit': 'refused',
    'b-ad-hat': 'right',
    'f-exp-adj': 'right',
    'f-exp-adj-slip': 'right',
    'f-rate': 'right',
    'f-rate-slip': 'right',
    'f-jr-phi': 'right',
    'f-r-jr': 'right',
    'f-r-jr-slip': 'right',
    'f-log': 'right',
    'k-lr-commute': 'right',
    'k-rot-orth': 'right',
    'k-rot-orth-slip': 'right',
    'k-odot': 'refused',
    'k-odot-slip': 'refused',
    'k-odot-right': 'refused',
    'k-rotate': 'right',
    'k-rot-product': 'refused',
    'c-trace': 'right',
    'c-trace-slip': 'right',
    'c-vee': 'right',
    'c-jl-det': 'right',
    'c-cross-hat': 'right',
    'c-cross-hat-slip': 'right',
    'm-so3-ad': 'right',
    'm-se3-ad': 'refused',
    'm-jr-norm': 'right',
    'm-jr-inv': 'refused',
    'm-se3-exp': 'refused',
}
#: the answers after the one attempt of :data:`ATTEMPT`: all right but k-rot-product (R(q) of
#: a quaternion, a function no --let gives)
AS_ATTEMPTED = {
    'b-ad-explicit': 'right',
    'k-odot': 'right',
    'k-odot-slip': 'right',
    'k-odot-right': 'right',
    'k-rotate': 'right',
    'm-se3-ad': 'right',
    'm-jr-inv': 'right',
    'm-se3-exp': 'right',
}
