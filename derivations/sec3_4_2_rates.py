"""Sec. 3.4.2 (rates): Eqs. (3.76)-(3.77), the Caveat, pose rates and twists (3.78)-(3.83).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.4.2.

Every check runs along the generic motion of :func:`derivations.common.motion_model`
(``e(t)`` unit, ``phi(t)``, ``Q(t)`` from (2.49), ``omega = vect(Qdot Q^T)`` computed): the
rates ``nu_dot``, ``lambda_dot``, ``eta_dot`` are derivatives of the invariants of ``Q(t)``,
and in (3.76a-d) ``N``, ``L``, ``H`` are modelled by the pose Jacobians of
:func:`derivations.sec3_4_2.pose_jacobians` (derived from ``Q`` alone, not from the book);
in (3.77) by the printed forms, once (3.76b-d) have verified them.

(3.77b-d) are definitions (the page: "defined below"); left inverses are not unique
(``nu``, ``lambda``, ``eta`` live on 3-dimensional constraint sets of R^4), so what the page
says of them is checked as claims: ``omega`` is recovered along every motion (3.77a), and
``Ftilde F = 1``. The products ``F Ftilde`` are 4 x 4
projectors onto the tangent space of the constraint set (the range of F), along the kernel
of Ftilde:

- ``N Ntilde = 1_4 - [e; -sin(phi)] [e^T, 0]`` (oblique; tangent space ``e^T e_dot = 0``);
- ``L Ltilde = 1_4 - [u; 1 + u0] lambda^T / (1 + u0)`` (oblique);
- ``H Htilde = 1_4 - eta eta^T`` (orthogonal: the tangent space of the unit 3-sphere).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.declare import (
    Rel,
    Statement,
    block,
    cpm,
    equation,
    rotation_from_quaternion,
    scalar,
    vect,
    vector,
)

from .common import I3, MS
from .sec3_4_2 import (
    CHOICES,
    A_cpm,
    H,
    H_matrix,
    H_tilde,
    Ht,
    L,
    L_matrix,
    L_tilde,
    Lt,
    N,
    N_matrix,
    N_tilde,
    Nt,
    P_cpm,
    S_matrix,
    S_of,
    T_matrix,
    T_of,
    U,
    a,
    e,
    eta,
    eta_dot,
    jacobian_model,
    lam,
    lam_dot,
    nu_dot,
    omega,
    p,
    phi,
    rates_model,
    sdot_of,
    t,
    t_A,
    t_P,
    twist_transfer,
    twist_transfer_matrix,
    v_A,
    v_P,
)

#: the garbled ``\dot{\mathbf{v}}`` of the printed (3.77a): a fresh 4-array
v_dot_garbled = MS("vdot", 4)


def _projectors(m: dict) -> dict:
    """Explicit ``F Ftilde`` projectors (see the module docstring) at the model's pose."""
    ev, ph = sp.Matrix(m[e]), m[phi]
    lv, ev4 = sp.Matrix(m[lam]), sp.Matrix(m[eta])
    kN = block([[ev], [sp.Matrix([[-sp.sin(ph)]])]])
    gN = block([[ev.T, sp.zeros(1, 1)]])
    kL = block([[sp.sin(ph) * ev], [sp.Matrix([[1 + sp.cos(ph)]])]])
    return {"N": sp.eye(4) - kN * gN, "L": sp.eye(4) - kL * lv.T / (1 + sp.cos(ph)),
            "H": sp.eye(4) - ev4 * ev4.T}


@equation("3.76a", "Rates of the invariants are linear in omega", section="3.4.2",
          latex=r"\dot{\boldsymbol{\nu}} = \mathbf{N}\boldsymbol{\omega}, \quad "
                r"\dot{\boldsymbol{\lambda}} = \mathbf{L}\boldsymbol{\omega}, \quad "
                r"\dot{\boldsymbol{\eta}} = \mathbf{H}\boldsymbol{\omega}",
          singular="phi = 0 for N (the axis e is undefined there)")
def invariant_rates() -> Statement:
    """``nu_dot = N omega``, ``lambda_dot = L omega``, ``eta_dot = H omega`` (4 x 3 maps).

    Book: Sec. 3.4.2, Eq. (3.76a). ``N``, ``L``, ``H`` are the first-principles pose
    Jacobians (independent of the printed (3.76b-d)); the rates are differentiated along the
    motion and ``omega`` is computed from ``Q(t)``.
    """
    return Statement([Rel(nu_dot, N * omega, "nu"), Rel(lam_dot, L * omega, "lambda"),
                      Rel(eta_dot, H * omega, "eta")], jacobian_model())


def _rate_matrix(F, F_printed, q_dot, name: str) -> Statement:
    return Statement([Rel(F, F_printed, name)], jacobian_model(),
                     claims=[Rel(q_dot, F_printed * omega, f"rate = {name} omega")])


@equation("3.76b", "Rate matrix N of the natural invariants", section="3.4.2",
          latex=r"\mathbf{N} \equiv \begin{bmatrix} [\sin \phi / (2(1 - \cos \phi))] "
                r"(\mathbf{1} - \mathbf{e}\mathbf{e}^T) - (1/2)\mathbf{E} \\ \mathbf{e}^T "
                r"\end{bmatrix},",
          singular="phi = 0 (mod 2 pi)")
def natural_invariant_rate_matrix() -> Statement:
    """``N = [sin(phi)/(2(1 - cos phi)) (1 - e e^T) - E/2; e^T]`` (4 x 3).

    Book: Sec. 3.4.2, Eq. (3.76b). Checked against the pose Jacobian and, along the motion,
    ``nu_dot = N omega`` with ``nu_dot`` differentiated and ``omega`` computed.
    """
    return _rate_matrix(N, N_matrix(e, phi), nu_dot, "N")


@equation("3.76c", "Rate matrix L of the linear invariants", section="3.4.2",
          expected="definition",
          latex=r"\mathbf{L} \equiv \begin{bmatrix} (1/2)[\text{tr}(\mathbf{Q})\mathbf{1} - "
                r"\mathbf{Q}] \\ -(\sin \phi)\mathbf{e}^T \end{bmatrix},",
          singular="none")
def linear_invariant_rate_matrix() -> Statement:
    """``L = [(1/2)(tr(Q) 1 - Q); -sin(phi) e^T]`` (4 x 3).

    Book: Sec. 3.4.2, Eq. (3.76c). Checked as (3.76b), with ``lambda_dot``.
    """
    return _rate_matrix(L, L_matrix(e, phi), lam_dot, "L")


@equation("3.76d", "Rate matrix H of the Euler-Rodrigues parameters", section="3.4.2",
          latex=r"\mathbf{H} \equiv \frac{1}{2} \begin{bmatrix} \cos(\phi/2)\mathbf{1} - "
                r"\sin(\phi/2)\mathbf{E} \\ -\sin(\phi/2)\mathbf{e}^T \end{bmatrix}",
          singular="none")
def euler_rodrigues_rate_matrix() -> Statement:
    """``H = (1/2) [cos(phi/2) 1 - sin(phi/2) E; -sin(phi/2) e^T]`` (4 x 3).

    Book: Sec. 3.4.2, Eq. (3.76d). Checked as (3.76b), with ``eta_dot``.
    """
    return _rate_matrix(H, H_matrix(e, phi), eta_dot, "H")


@equation("3.77a", "Angular velocity from the rates of the invariants", section="3.4.2",
          latex=r"\boldsymbol{\omega} = \tilde{\mathbf{N}}\dot{\mathbf{v}} = "
                r"\tilde{\mathbf{L}}\dot{\boldsymbol{\lambda}} = "
                r"\tilde{\mathbf{H}}\dot{\boldsymbol{\eta}}",
          expected="does-not-hold", cause="conversion",
          evidence=r"\dot{\mathbf{v}} (v is the velocity) printed where \dot{\boldsymbol{\nu}} "
                   r"is meant: Ntilde acts on the 4-array nu_dot; with nu_dot the chain holds. "
                   r"With a printed copy, look at the first product: nu-dot or v-dot",
          singular="phi = pi for Ltilde")
def angular_velocity_from_invariant_rates() -> Statement:
    """``omega = Ntilde nu_dot = Ltilde lambda_dot = Htilde eta_dot`` (3-vectors, rad/s).

    Book: Sec. 3.4.2, Eq. (3.77a). As printed, the first member has ``v_dot`` (a fresh
    4-array here, the only shape for which the product exists), a conversion garble of
    ``nu_dot``. ``Ntilde`` ... are modelled by the formulas of (3.77b-d), checked there.
    """
    m = dict(rates_model())
    m[v_dot_garbled] = sp.ImmutableMatrix(vector("sec342_vdot", n=4))
    printed = [Rel(omega, Nt * v_dot_garbled, "Ntilde vdot"),
               Rel(omega, Lt * lam_dot, "Ltilde lambda_dot"),
               Rel(omega, Ht * eta_dot, "Htilde eta_dot")]
    corrected = [Rel(omega, Nt * nu_dot, "Ntilde nu_dot")] + printed[1:]
    return Statement(printed, m, corrected=corrected)


def _left_inverse(F, Ft, Ft_printed, q_dot, name: str, extra=()) -> Statement:
    """The definition ``Ftilde = (printed form)`` and the properties the page gives it (the
    words before (3.77b): it recovers ``omega`` as (3.77a) writes, and it is a left inverse
    of ``F``), with the projector ``F Ftilde`` of the module docstring, as claims."""
    m = rates_model()
    return Statement(
        [Rel(Ft, Ft_printed, f"{name}tilde")], m, defines=(f"{name}tilde",),
        claims=[Rel(omega, Ft * q_dot, f"omega = {name}tilde rate"),
                Rel(Ft * F, I3, f"{name}tilde {name} = 1"),
                Rel(F * Ft, _projectors(m)[name], f"{name} {name}tilde"), *extra])


@equation("3.77b", "Left inverse Ntilde of N", section="3.4.2", kind="definition",
          latex=r"\tilde{\mathbf{N}} \equiv [(\sin \phi)\mathbf{1} + (1 - \cos \phi)\mathbf{E} "
                r"\mathbf{e}],",
          singular="none for Ntilde; it inverts N off phi = 0 (mod 2 pi)")
def natural_invariant_left_inverse() -> Statement:
    """``Ntilde = [sin(phi) 1 + (1 - cos phi) E | e]`` (3 x 4; a 3 x 3 block, then ``e``).

    Book: Sec. 3.4.2, Eq. (3.77b), a definition (the page: "defined below"). Claims, the
    properties the page gives it: ``omega = Ntilde nu_dot`` along the motion (3.77a),
    ``Ntilde N = 1`` (a left inverse), and ``N Ntilde = 1_4 - [e; -sin phi][e^T, 0]``, the
    projector onto the tangent space ``{e^T e_dot = 0}`` along ``[e; -sin phi]`` (the kernel
    of Ntilde).
    """
    return _left_inverse(N, Nt, N_tilde(e, phi), nu_dot, "N")


@equation("3.77c", "Left inverse Ltilde of L", section="3.4.2", kind="definition",
          latex=r"\tilde{\mathbf{L}} \equiv [\mathbf{1} + [(\sin \phi)/(1 + \cos \phi)]"
                r"\mathbf{E} - [(\sin \phi)/(1 + \cos \phi)]\mathbf{e}],",
          singular="phi = pi (mod 2 pi)")
def linear_invariant_left_inverse() -> Statement:
    """``Ltilde = [1 + tan(phi/2) E | -tan(phi/2) e]`` (3 x 4), ``tan(phi/2) = sin/(1 + cos)``.

    Book: Sec. 3.4.2, Eq. (3.77c), a definition. The printed minus is the sign of the fourth
    column. Claims: ``omega = Ltilde lambda_dot``, ``Ltilde L = 1``, and
    ``L Ltilde = 1_4 - [u; 1 + u0] lambda^T / (1 + u0)``, the projector onto the tangent
    space ``lambda^T lambda_dot = 0`` along ``[u; 1 + u0]``.
    """
    return _left_inverse(L, Lt, L_tilde(e, phi), lam_dot, "L")


@equation("3.77d", "Left inverse Htilde of H", section="3.4.2", kind="definition",
          latex=r"\tilde{\mathbf{H}} \equiv 2 [ [\cos(\phi/2)]\mathbf{1} + [\sin(\phi/2)]"
                r"\mathbf{E} - [\sin(\phi/2)]\mathbf{e} ]",
          singular="none")
def euler_rodrigues_left_inverse() -> Statement:
    """``Htilde = 2 [cos(phi/2) 1 + sin(phi/2) E | -sin(phi/2) e]`` (3 x 4).

    Book: Sec. 3.4.2, Eq. (3.77d), a definition. Claims: ``omega = Htilde eta_dot``,
    ``Htilde H = 1``, ``H Htilde = 1_4 - eta eta^T``, the orthogonal projector onto the
    tangent space of the unit 3-sphere at ``eta``, and ``Htilde = 4 H^T``.
    """
    return _left_inverse(H, Ht, H_tilde(e, phi), eta_dot, "H",
                         extra=[Rel(Ht, 4 * H.T, "Htilde = 4 H^T")])


# --------------------------------------------------------------------------- the caveat
omega_x, omega_y = MS("omega_x"), MS("omega_y")
d_x_omega_y, d_y_omega_x = MS("d_x(omega_y)"), MS("d_y(omega_x)")
Omega_x = MS("Omega_x", 3, 3)  # CPM(omega_x)


@cache
def _surface_model() -> tuple[dict, sp.Matrix]:
    """A generic two-parameter family of poses ``Q(x, y)`` and the angular velocities of the
    motions along its coordinate lines, ``omega_x = vect(Q_x Q^T)``, ``omega_y = vect(Q_y Q^T)``.

    ``Q(x, y)`` is the rotation of the (unnormalised) quaternion ``[x, y, c3, c0]`` with free
    constants ``c3``, ``c0``: a surface through an arbitrary rotation. Returns the model and
    the curl ``d_x omega_y - d_y omega_x`` at ``(x, y, c3, c0) = (0, 0, 0, 1)``.
    """
    x, y = scalar("sec342_x"), scalar("sec342_y")
    c3, c0 = scalar("sec342_c3"), scalar("sec342_c0")
    Qs = rotation_from_quaternion([x, y, c3, c0])
    wx, wy = vect(Qs.diff(x) * Qs.T), vect(Qs.diff(y) * Qs.T)
    dxwy, dywx = wy.diff(x), wx.diff(y)
    im = sp.ImmutableMatrix
    model = {omega_x: im(wx), omega_y: im(wy), d_x_omega_y: im(dxwy), d_y_omega_x: im(dywx),
             Omega_x: im(cpm(wx))}
    at = {x: 0, y: 0, c3: 0, c0: 1}
    return model, sp.Matrix(dxwy - dywx).xreplace(at)


@equation("caveat3.4", "The angular velocity is not a time derivative", section="3.4.2",
          kind="claim",
          latex=r"The angular velocity vector is **not** a time-derivative")
def angular_velocity_not_a_derivative() -> Statement:
    """No vector function ``f`` of the pose has ``d/dt f(Q(t)) = omega`` for every motion.

    Book: Sec. 3.4.2, Caveat after Eq. (3.77d).

    Claims checked (the page states the caveat in words only, with no relation): on a
    generic two-parameter family of poses ``Q(x, y)``, the angular velocities of the
    coordinate motions obey the Maurer-Cartan relation
    ``d_x omega_y - d_y omega_x = omega_x x omega_y`` (transcribed ``Omega_x omega_y``), and
    at the identity pose with ``omega_x = 2 i``, ``omega_y = 2 j`` this curl is ``[0, 0, 4]``.
    Why it captures the caveat: if ``omega = d/dt f(Q)`` for all motions, then
    ``omega_x = d_x f(Q(x, y))`` and ``omega_y = d_y f(Q(x, y))``, so the mixed partials
    would force the curl to vanish identically; the 1-form ``vect(dQ Q^T)`` is not closed
    (by Stokes, a small closed loop of rotations has a nonzero integral of ``omega``).
    Rates of the invariants, in contrast, are derivatives: ``N``, ``L``, ``H`` are the
    integration factors of (3.76a).
    """
    model, curl_at_identity = _surface_model()
    return Statement([], model, claims=[  # the page prints no relation: the words alone
        Rel(d_x_omega_y - d_y_omega_x, Omega_x * omega_y, "Maurer-Cartan"),
        Rel(curl_at_identity, sp.Matrix([0, 0, 4]), "curl at the identity pose is non-zero")])


# --------------------------------------------------------------------------- pose rates and twists
def _per_choice(fn):
    return [fn(n, F, Ft, q_dot) for n, F, Ft, q_dot in CHOICES]


@equation("3.78", "Pose rate from the twist", section="3.4.2",
          latex=r"\dot{\mathbf{s}} = \mathbf{T}\mathbf{t}",
          singular="phi = 0 for F = N")
def pose_rate_from_twist() -> Statement:
    """``s_dot = T t`` (7) for each choice F = N, L, H of rotation invariants.

    Book: Sec. 3.4.2, Eq. (3.78). ``s = [q; q0; d_A]`` with ``d_A = a(t) - a(0)``;
    ``t = [omega; a_dot]`` the twist at A; ``T`` from (3.79), F from (3.76b-d).
    """
    return Statement(_per_choice(lambda n, F, Ft, q: Rel(sdot_of[n], T_of[n] * t, f"F = {n}")),
                     rates_model())


@equation("3.79", "Pose-rate matrix T", section="3.4.2", kind="definition",
          latex=r"\mathbf{T} \equiv \begin{bmatrix} \mathbf{F} & \mathbf{O}_{43} \\ "
                r"\mathbf{O} & \mathbf{1} \end{bmatrix}",
          singular="phi = 0 for F = N")
def pose_rate_matrix() -> Statement:
    """``T = [[F, O_43], [O, 1]]`` (7 x 6), one per choice F = N, L, H (``T_N`` ...).

    Book: Sec. 3.4.2, Eq. (3.79).
    """
    return Statement(_per_choice(lambda n, F, Ft, q: Rel(T_of[n], T_matrix(F), f"F = {n}")),
                     rates_model(), defines=tuple(f"T_{n}" for n, *_ in CHOICES))


@equation("3.80a", "Twist from the pose rate", section="3.4.2",
          latex=r"\mathbf{t} = \mathbf{S}\dot{\mathbf{s}}",
          singular="phi = pi for F = L")
def twist_from_pose_rate() -> Statement:
    """``t = S s_dot`` (6) for each choice F = N, L, H, ``S`` from (3.80b).

    Book: Sec. 3.4.2, Eq. (3.80a). Checked along the motion.
    """
    return Statement(_per_choice(lambda n, F, Ft, q: Rel(t, S_of[n] * sdot_of[n], f"F = {n}")),
                     rates_model())


@equation("3.80b", "Twist matrix S", section="3.4.2", kind="definition",
          latex=r"\mathbf{S} \equiv \begin{bmatrix} \tilde{\mathbf{F}} & \mathbf{O} \\ "
                r"\mathbf{O}_{34} & \mathbf{1} \end{bmatrix}",
          singular="phi = pi for F = L")
def twist_matrix() -> Statement:
    """``S = [[Ftilde, O], [O_34, 1]]`` (6 x 7), one per choice; claim ``S T = 1_6``.

    Book: Sec. 3.4.2, Eq. (3.80b). ``T S = diag(F Ftilde, 1)`` is a projector (see
    :mod:`derivations.sec3_4_2_rates`).
    """
    return Statement(
        _per_choice(lambda n, F, Ft, q: Rel(S_of[n], S_matrix(Ft), f"F = {n}")),
        rates_model(), defines=tuple(f"S_{n}" for n, *_ in CHOICES),
        claims=_per_choice(lambda n, F, Ft, q: Rel(S_of[n] * T_of[n], sp.Identity(6),
                                                   f"S T = 1 (F = {n})")))


@equation("3.81", "Twists at two body points", section="3.4.2", kind="definition",
          latex=r"\mathbf{t}_A = \begin{bmatrix} \boldsymbol{\omega} \\ \mathbf{v}_A "
                r"\end{bmatrix}, \quad \mathbf{t}_P = \begin{bmatrix} \boldsymbol{\omega} \\ "
                r"\mathbf{v}_P \end{bmatrix}")
def twists_at_two_points() -> Statement:
    """``t_A = [omega; v_A]``, ``t_P = [omega; v_P]`` (6), ``v_A = a_dot``, ``v_P = p_dot``.

    Book: Sec. 3.4.2, Eq. (3.81).
    """
    return Statement([Rel(t_A, sp.BlockMatrix([[omega], [v_A]]), "t_A"),
                      Rel(t_P, sp.BlockMatrix([[omega], [v_P]]), "t_P")], rates_model(),
                     defines=("t_A", "t_P"))


@equation("3.82", "Velocity of P from that of A", section="3.4.2",
          latex=r"\mathbf{v}_P = \mathbf{v}_A + (\mathbf{a} - \mathbf{p}) \times "
                r"\boldsymbol{\omega}")
def velocity_transfer() -> Statement:
    """``v_P = v_A + (a - p) x omega`` (m/s); ``x`` transcribed by ``A - P = CPM(a - p)``.

    Book: Sec. 3.4.2, Eq. (3.82). ``p(t) = a(t) + Q(t) r`` moves rigidly.
    """
    return Statement([Rel(v_P, v_A + (A_cpm - P_cpm) * omega)], rates_model())


@equation("3.83a", "Twist transfer", section="3.4.2",
          latex=r"\mathbf{t}_P = \mathbf{U}\mathbf{t}_A")
def twist_transfer_law() -> Statement:
    """``t_P = U t_A`` (6) along the motion, ``U`` from (3.83b).

    Book: Sec. 3.4.2, Eq. (3.83a).
    """
    return Statement([Rel(t_P, U * t_A)], rates_model())


@equation("3.83b", "Twist-transfer matrix", section="3.4.2", kind="definition",
          latex=r"\mathbf{U} \equiv \begin{bmatrix} \mathbf{1} & \mathbf{O} \\ \mathbf{A} - "
                r"\mathbf{P} & \mathbf{1} \end{bmatrix}")
def twist_transfer_matrix_definition() -> Statement:
    """``U = [[1, O], [A - P, 1]]`` (6 x 6); claim: ``twist_transfer(t_A, a, p) = t_P``.

    Book: Sec. 3.4.2, Eq. (3.83b) (as (3.29b)).
    """
    m = rates_model()
    return Statement([Rel(U, twist_transfer_matrix(a, p))], m, defines=("U",),
                     claims=[Rel(t_P, twist_transfer(m[t_A], m[a], m[p]), "t_P = U t_A")])
