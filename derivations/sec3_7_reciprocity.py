"""Sec. 3.7 (second part): screws of wrenches and twists, reciprocity, wrench transfer,
Eqs. (3.112)-(3.122).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.7. The first
principles of the models are those of :mod:`rigidsym.derivations.sec3_7` (systems of forces,
power on a rigidly moving body, screws as in (3.71)); the book symbols are shared with it.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import TIME, Rel, Statement, block, cpm, equation, scalar, unit_vector, vector

from .common import I3, MS, O3, Mt, motion_model
from .sec3_4_2 import twist_transfer_matrix
from .sec3_7 import (
    A_cpm,
    Gamma,
    P_cpm,
    Pi,
    T_amp,
    U,
    V,
    W_amp,
    _axis_point_by_solving,
    _force_system,
    _gamma,
    a,
    f,
    im,
    n_A,
    n_P,
    n_vec,
    p,
    s_t,
    s_w,
    t,
    t_A,
    t_P,
    w,
    w_A,
    w_P,
    wrench_transfer,
    wrench_transfer_matrix,
)


# --------------------------------------------------------------------------- 3.112-3.117
def _screw(e, r, h) -> sp.Matrix:
    """The screw (3.71) ``[e; r x e + h e]`` of axis (r, e) and pitch h (definition)."""
    return block([[e], [r.cross(e) + h * e]])


@equation("3.112", "The 6x6 matrix Gamma", section="3.7", kind="definition",
          latex=r"\mathbf{\Gamma} \equiv \begin{bmatrix} \mathbf{O} & \mathbf{1} \\ "
                r"\mathbf{1} & \mathbf{O} \end{bmatrix}")
def gamma_matrix() -> Statement:
    """``Gamma = [[O, 1], [1, O]]``; claims ``Gamma^T = Gamma`` (used for (3.117)) and
    ``Gamma^2 = 1``. Book: Sec. 3.7, Eq. (3.112). 6x6, dimensionless.
    """
    return Statement([Rel(Gamma, sp.BlockMatrix([[O3, I3], [I3, O3]]))], {Gamma: im(_gamma())},
                     defines=("Gamma",),
                     claims=[Rel(Gamma.T, Gamma, "symmetric"),
                             Rel(Gamma * Gamma, sp.Identity(6), "involution")])


@equation("3.113", "Wrench array in axis coordinates", section="3.7", kind="definition",
          latex=r"\mathbf{w} \equiv \begin{bmatrix} \mathbf{n} \\ \mathbf{f} \end{bmatrix}")
def wrench_array() -> Statement:
    """``w = [n; f]``. Claim: the unnumbered display before it,
    ``A Gamma s = [p x (A e) + p (A e); A e]`` for the screw (3.71) of a force of magnitude A
    along the line (p, e) plus a parallel moment of magnitude (pitch) A.

    Book: Sec. 3.7, Eq. (3.113). 6x1: N m (top), N (bottom).
    """
    e, r, h, amp = unit_vector("s37_e"), vector("s37_rw"), scalar("s37_h"), scalar("s37_A")
    A_amp, s = sp.Symbol("A_amp", real=True), MS("s", 6, 1)
    fv = amp * e
    nv = r.cross(fv) + h * fv
    model = {Gamma: im(_gamma()), s: im(_screw(e, r, h)), A_amp: amp, n_vec: im(nv),
             f: im(fv), w: im(block([[nv], [fv]]))}
    return Statement([Rel(w, sp.BlockMatrix([[n_vec], [f]]))], model, defines=("w",),
                     claims=[Rel(A_amp * Gamma * s, w, "w = A Gamma s")])


def _moving_body_model():
    """A body in generic rigid motion (motion_model, Q(t) exactly orthogonal) loaded by two
    forces at body points ``x_i(t) = a(t) + Q(t) s_i`` and a couple c. Returns the model of
    t_A, t_P, w_A, w_P (twists at the body points A, P of the motion model) and the power
    ``sum f_i . x_i_dot + c . omega``."""
    mm = motion_model(invariants=False)
    Qv, av, pv, om = mm[Mt.Q], mm[Mt.a], mm[Mt.p], mm[Mt.omega]
    c = vector("s37_c")
    pts = [av + Qv * vector("s37_s1"), av + Qv * vector("s37_s2")]
    forces = [vector("s37_f1"), vector("s37_f2")]
    fv = forces[0] + forces[1]

    def moment(x):
        return sum(((xi - x).cross(fi) for xi, fi in zip(pts, forces, strict=True)),
                   sp.zeros(3, 1)) + c

    power = sum(fi.dot(xi.diff(TIME)) for xi, fi in zip(pts, forces,
                                                                          strict=True))
    power += c.dot(om)
    model = {t_A: im(block([[om], [mm[Mt.a_dot]]])), t_P: im(block([[om], [mm[Mt.p_dot]]])),
             w_A: im(block([[moment(av)], [fv]])), w_P: im(block([[moment(pv)], [fv]])),
             a: im(av), p: im(pv), Pi: power}
    return model


@equation("3.114", "Power of a wrench on a moving body", section="3.7",
          latex=r"\Pi = \mathbf{t}^T \mathbf{w}")
def wrench_power() -> Statement:
    """``Pi = t^T w`` with ``t = [omega; p_dot]``, ``w = [n_P; f]`` both at P; Pi is the power
    ``sum f_i . v_i + c . omega`` of the forces and couple on the rigidly moving body.

    Book: Sec. 3.7, Eq. (3.114). Scalar, W.
    """
    mb = _moving_body_model()
    model = {Pi: mb[Pi], t: mb[t_P], w: mb[w_P]}
    return Statement([Rel(Pi, t.T * w)], model)


def _screw_pair_model(reciprocal: bool):
    """Wrench and twist at the origin O with their screws (3.71).

    Wrench: force ``W e_w`` on the line through ``r_w`` plus a couple ``h_w W e_w``; twist:
    rotation at rate T about the axis (r_t, e_t) plus sliding ``h_t T e_t`` (velocity field
    ``v(x) = T e_t x (x - r_t) + h_t T e_t``). With ``reciprocal``, h_t is solved from
    ``Pi = f . v(r_w) + h_w W e_w . omega = 0`` (first-principles power).
    """
    ew, et = unit_vector("s37_e"), unit_vector("s37_et")
    Wv, Tv, hw = scalar("s37_W"), scalar("s37_T"), scalar("s37_hw")
    rw, rt = vector("s37_rw"), vector("s37_rt")
    ht = scalar("s37_ht")
    if reciprocal:
        x = sp.Dummy("h", real=True)
        vel = Tv * et.cross(rw - rt) + x * Tv * et
        power = (Wv * ew).dot(vel) + (hw * Wv * ew).dot(Tv * et)
        ht = sp.solve(power, x)[0]
    fv, om = Wv * ew, Tv * et
    model = {w: im(block([[rw.cross(fv) + hw * fv], [fv]])),
             t: im(block([[om], [Tv * et.cross(-rt) + ht * Tv * et]])),
             s_w: im(_screw(ew, rw, hw)), s_t: im(_screw(et, rt, ht)), Gamma: im(_gamma()),
             W_amp: Wv, T_amp: Tv}
    return model


@equation("3.115", "Wrench and twist from their screws and amplitudes", section="3.7",
          latex=r"\mathbf{w} = W\mathbf{\Gamma}\mathbf{s}_w, \quad \mathbf{t} = T\mathbf{s}_t,")
def wrench_and_twist_screws() -> Statement:
    """``w = W Gamma s_w``, ``t = T s_t`` for a *general* wrench and twist at the origin.

    Model: ``f = W e_w``, ``n_O`` free; ``omega = T e_t``, ``v_O`` free. The screws are
    derived: axis point by solving "moment (velocity) parallel to f (omega)", pitch as the
    axial moment (sliding velocity) on the axis over W (T), then (3.71). The twist's
    velocity field ``v(x) = v_O + omega x x`` is (3.50), verified in Sec. 3.4.

    Book: Sec. 3.7, Eq. (3.115). 6x1 arrays; W in N, T in rad/s.
    """
    ew, et = unit_vector("s37_e"), unit_vector("s37_et")
    Wv, Tv = scalar("s37_W"), scalar("s37_T")
    nO, vO = vector("s37_c"), vector("s37_v")
    fv, om = Wv * ew, Tv * et

    def mom(x):
        return nO + fv.cross(x)

    def vel(x):
        return vO + om.cross(x)

    rw, rt = _axis_point_by_solving(mom, fv), _axis_point_by_solving(vel, om)
    hw, ht = mom(rw).dot(ew) / Wv, vel(rt).dot(et) / Tv
    model = {w: im(block([[nO], [fv]])), t: im(block([[om], [vO]])),
             s_w: im(_screw(ew, rw, hw)), s_t: im(_screw(et, rt, ht)), Gamma: im(_gamma()),
             W_amp: Wv, T_amp: Tv}
    return Statement([Rel(w, W_amp * Gamma * s_w), Rel(t, T_amp * s_t)], model)


@equation("3.116", "Reciprocity of two screws", section="3.7",
          latex=r"(\mathbf{\Gamma}\mathbf{s}_w)^T \mathbf{s}_t \equiv \mathbf{s}_w^T "
                r"\mathbf{\Gamma}^T \mathbf{s}_t = 0")
def reciprocity_condition() -> Statement:
    """``(Gamma s_w)^T s_t = s_w^T Gamma^T s_t = 0`` for a reciprocal pair.

    Model: a wrench and a twist given by their screws, made reciprocal by solving the
    twist pitch from *zero power* (first principles). Claim: ``Pi = W T (Gamma s_w)^T s_t``
    for a general pair, so reciprocity (Pi = 0, W T != 0) is exactly the printed condition.

    Book: Sec. 3.7, Eq. (3.116). Scalars (units of length).
    """
    model = _screw_pair_model(reciprocal=True)
    gen = _screw_pair_model(reciprocal=False)
    lhs = (Gamma * s_w).T * s_t
    gen[Pi] = (gen[t].T * gen[w])[0]  # power of the wrench at O on the twist at O
    ew, et = unit_vector("s37_e"), unit_vector("s37_et")
    Wv, Tv, hw, ht = (scalar(n) for n in ("s37_W", "s37_T", "s37_hw", "s37_ht"))
    rw, rt = vector("s37_rw"), vector("s37_rt")
    power = (Wv * ew).dot(Tv * et.cross(rw - rt) + ht * Tv * et) + (hw * Wv * ew).dot(Tv * et)
    return Statement([Rel(lhs, s_w.T * Gamma.T * s_t), Rel(lhs, sp.ZeroMatrix(1, 1))], model,
                     claims=[Rel(power, W_amp * T_amp * sp.Matrix(
                         (gen[Gamma] * gen[s_w]).T * gen[s_t]), "power = W T x reciprocal "
                                                                "product")])


@equation("3.117", "Reciprocal product, symmetric forms", section="3.7",
          latex=r"\mathbf{s}_w^T \Gamma \mathbf{s}_t = 0 \quad \text{or} \quad "
                r"\mathbf{s}_t^T \Gamma \mathbf{s}_w = 0")
def reciprocal_product() -> Statement:
    """``s_w^T Gamma s_t = 0`` or ``s_t^T Gamma s_w = 0`` for a reciprocal pair (model as in
    (3.116)). Book: Sec. 3.7, Eq. (3.117).
    """
    model = _screw_pair_model(reciprocal=True)
    return Statement([Rel(s_w.T * Gamma * s_t, sp.ZeroMatrix(1, 1)),
                      Rel(s_t.T * Gamma * s_w, sp.ZeroMatrix(1, 1))], model)


# --------------------------------------------------------------------------- 3.118-3.122
@equation("3.118", "Wrenches at A and at P", section="3.7", kind="definition",
          latex=r"\mathbf{w}_A \equiv \begin{bmatrix} \mathbf{n}_A \\ \mathbf{f} "
                r"\end{bmatrix}, \quad \mathbf{w}_P \equiv \begin{bmatrix} \mathbf{n}_P \\ "
                r"\mathbf{f} \end{bmatrix}")
def wrenches_at_points() -> Statement:
    """``w_A = [n_A; f]``, ``w_P = [n_P; f]``. Book: Sec. 3.7, Eq. (3.118). 6x1."""
    return Statement([Rel(w_A, sp.BlockMatrix([[n_A], [f]])),
                      Rel(w_P, sp.BlockMatrix([[n_P], [f]]))], _transfer_model(),
                     defines=("w_A", "w_P"))


def _transfer_model() -> dict:
    fv, moment, _, _ = _force_system(unit=False)
    av, pv = vector("s37_a"), vector("s37_p")
    return {a: im(av), p: im(pv), A_cpm: im(cpm(av)), P_cpm: im(cpm(pv)), f: im(fv),
            n_A: im(moment(av)), n_P: im(moment(pv)),
            w_A: im(block([[moment(av)], [fv]])), w_P: im(block([[moment(pv)], [fv]])),
            V: im(wrench_transfer_matrix(av, pv)), U: im(twist_transfer_matrix(av, pv))}


@equation("3.119a", "Wrench-transfer formula", section="3.7",
          latex=r"\mathbf{w}_P = \mathbf{V} \mathbf{w}_A")
def wrench_transfer_formula() -> Statement:
    """``w_P = V w_A`` (moments about A and P of the same force system); claim: the kernel
    :func:`wrench_transfer`. Book: Sec. 3.7, Eq. (3.119a). 6x1.
    """
    model = _transfer_model()
    kernel = wrench_transfer(model[w_A], model[a], model[p])
    return Statement([Rel(w_P, V * w_A)], model, claims=[Rel(w_P, kernel, "kernel")])


@equation("3.119b", "Wrench-transfer matrix V", section="3.7", kind="definition",
          latex=r"\mathbf{V} \equiv \begin{bmatrix} \mathbf{1} & \mathbf{A} - \mathbf{P} \\ "
                r"\mathbf{0} & \mathbf{1} \end{bmatrix}")
def wrench_transfer_matrix_definition() -> Statement:
    """``V = [[1, A - P], [O, 1]]``; claim ``V = Gamma U Gamma`` (U of (3.83b)): the wrench
    transfer is the twist transfer with the blocks swapped. Book: Sec. 3.7, Eq. (3.119b).
    """
    model = _transfer_model()
    model[Gamma] = im(_gamma())
    return Statement([Rel(V, sp.BlockMatrix([[I3, A_cpm - P_cpm], [O3, I3]]))], model,
                     defines=("V",), claims=[Rel(V, Gamma * U * Gamma, "V = Gamma U Gamma")])


@equation("3.120", "Power at P from the twist and wrench at A", section="3.7",
          latex=r"\mathbf{t}_P^T \mathbf{w}_P = \mathbf{t}_A^T \mathbf{U}^T \mathbf{V} "
                r"\mathbf{w}_A")
def power_transfer() -> Statement:
    """``t_P^T w_P = t_A^T U^T V w_A`` for a rigidly moving body (Q(t) exactly orthogonal)
    and a force system on it; claim ``t_P^T w_P = t_A^T w_A`` (the power does not depend on
    the point). Book: Sec. 3.7, Eq. (3.120). Scalar, W.
    """
    model = _moving_body_model()
    av, pv = model[a], model[p]
    model.update({U: im(twist_transfer_matrix(av, pv)), V: im(wrench_transfer_matrix(av, pv))})
    return Statement([Rel(t_P.T * w_P, t_A.T * U.T * V * w_A)], model,
                     claims=[Rel(t_P.T * w_P, t_A.T * w_A, "power invariance")])


@equation("3.121", "U^T V is the identity", section="3.7",
          latex=r"\mathbf{U}^T \mathbf{V} = \begin{bmatrix} \mathbf{1} & -\mathbf{A} + "
                r"\mathbf{P} \\ \mathbf{0} & \mathbf{1} \end{bmatrix} \begin{bmatrix} "
                r"\mathbf{1} & \mathbf{A} - \mathbf{P} \\ \mathbf{0} & \mathbf{1} "
                r"\end{bmatrix} = \mathbf{1}_{6 \times 6}")
def transfer_matrices_product() -> Statement:
    """``U^T V = [[1, -A + P], [0, 1]] [[1, A - P], [0, 1]] = 1_6``.

    Book: Sec. 3.7, Eq. (3.121). 6x6.
    """
    model = _transfer_model()
    # the two printed factors, kept as an unevaluated product of explicit 6x6 arrays of
    # book-symbol entries (sympy's block_collapse of a BlockMatrix product takes seconds)
    f1 = sp.ImmutableMatrix(sp.BlockMatrix([[I3, -A_cpm + P_cpm], [O3, I3]]).as_explicit())
    f2 = sp.ImmutableMatrix(sp.BlockMatrix([[I3, A_cpm - P_cpm], [O3, I3]]).as_explicit())
    prod = sp.MatMul(f1, f2, evaluate=False)
    return Statement([Rel(U.T * V, prod), Rel(U.T * V, sp.Identity(6))], model)


@equation("3.122", "Inverse of the wrench-transfer matrix", section="3.7",
          latex=r"\mathbf{V}^{-1} = \mathbf{U}^T")
def wrench_transfer_inverse() -> Statement:
    """``V^-1 = U^T``. Book: Sec. 3.7, Eq. (3.122). 6x6."""
    return Statement([Rel(V.I, U.T)], _transfer_model())
