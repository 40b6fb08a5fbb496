"""Sec. 3.4.2: The twist of a rigid body: the rate matrices of (3.76)-(3.77) and the book
symbols of the section (the declarations of (3.71)-(3.75) are in :mod:`.sec3_4_2_twists`,
those of (3.76)-(3.83) and the Caveat after (3.77d) in :mod:`.sec3_4_2_rates`).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.4.2.

The rate matrices ``N``, ``L``, ``H`` (3.76) and their left inverses ``Ntilde``,
``Ltilde``, ``Htilde`` (3.77) are exposed as formula functions. Each accepts either explicit
sympy inputs (``e`` a 3 x 1 ``Matrix``, ``phi`` a scalar), returning an explicit ``Matrix``,
or the book symbols (``e`` a ``MatrixSymbol``), returning the book's block expression in
``e``, ``E = CPM(e)`` and ``1``: the declarations transcribe the printed forms by calling
them on book symbols, so the mathematics exists once.

First principles used here: the motion of :func:`derivations.common.motion_model`
(``e(t)`` unit, ``phi(t)``, ``Q(t)`` from (2.49), ``Omega = Qdot Q^T``, ``omega = vect(Omega)``
computed). Independently of the printed N, L, H, their *pose Jacobians* are derived from the
extraction of the invariants from ``Q``: ``u = vect(Q)``, ``u0 = (tr Q - 1)/2`` differentiated
along ``Qdot = Omega Q`` (one column per basis vector of ``omega``), then the inverse-function
derivatives ``lambda -> nu -> eta`` (:func:`pose_jacobians`).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.declare import block, cpm, eye3, trace, vect

from .common import I3, MS, O3, Mt, motion_model

__all__ = ["N_matrix", "L_matrix", "H_matrix", "N_tilde", "L_tilde", "H_tilde",
           "twist_transfer_matrix", "twist_transfer", "pose_jacobians"]


# --------------------------------------------------------------------------- helpers
def _symbolic(v) -> bool:
    return isinstance(v, sp.MatrixSymbol)


def _ops(v):
    """``(CPM(v), 1)``: the book symbols ``E``/``A``/``P``, ``1`` for a book symbol ``v``;
    explicit matrices otherwise (the book names the CPM of a vector by its capital)."""
    if _symbolic(v):
        return sp.MatrixSymbol(v.name.upper(), 3, 3), I3
    return cpm(v), eye3()


def _stack(rows, symbolic: bool):
    return sp.BlockMatrix(rows) if symbolic else block(rows)


def _vec(v):
    return v if _symbolic(v) else sp.Matrix(v).reshape(3, 1)


# --------------------------------------------------------------------------- formulas
def N_matrix(e, phi):
    """Rate matrix of the natural invariants: ``nu_dot = N omega``, ``nu = [e; phi]``.

    ``N = [ sin(phi)/(2 (1 - cos phi)) (1 - e e^T) - E/2 ;  e^T ]``, ``E = CPM(e)``.

    Book: Sec. 3.4.2, Eq. (3.76b).

    Args:
        e: unit axis, 3 x 1 (explicit ``Matrix``, or the book's ``MatrixSymbol`` e).
        phi: rotation angle (rad).

    Returns:
        4 x 3 matrix (1/s per rad/s; the angle row is dimensionless).

    Notes:
        Singular at ``phi = 0`` (mod 2 pi): there the axis of the rotation is undefined.
    """
    e = _vec(e)
    E, one = _ops(e)
    top = sp.sin(phi) / (2 * (1 - sp.cos(phi))) * (one - e * e.T) - E / 2
    return _stack([[top], [e.T]], _symbolic(e))


def L_matrix(e, phi):
    """Rate matrix of the linear invariants: ``lambda_dot = L omega``, ``lambda = [u; u0]``.

    ``L = [ (1/2) (tr(Q) 1 - Q) ;  -sin(phi) e^T ]`` with ``Q`` from (2.49).

    Book: Sec. 3.4.2, Eq. (3.76c). Returns 4 x 3. No singularity.
    """
    e = _vec(e)
    E, one = _ops(e)
    if _symbolic(e):
        Q = Mt.Q
        top = sp.Rational(1, 2) * (sp.Trace(Q) * one - Q)
    else:
        Q = e * e.T + sp.cos(phi) * (one - e * e.T) + sp.sin(phi) * E
        top = sp.Rational(1, 2) * (trace(Q) * one - Q)
    return _stack([[top], [-sp.sin(phi) * e.T]], _symbolic(e))


def H_matrix(e, phi):
    """Rate matrix of the Euler-Rodrigues parameters: ``eta_dot = H omega``.

    ``H = (1/2) [ cos(phi/2) 1 - sin(phi/2) E ;  -sin(phi/2) e^T ]``.

    Book: Sec. 3.4.2, Eq. (3.76d). Returns 4 x 3. No singularity.
    """
    e = _vec(e)
    E, one = _ops(e)
    c, s = sp.cos(phi / 2), sp.sin(phi / 2)
    m = _stack([[c * one - s * E], [-s * e.T]], _symbolic(e))
    return sp.Rational(1, 2) * m


def N_tilde(e, phi):
    """Left inverse of N: ``omega = Ntilde nu_dot``, ``Ntilde N = 1``.

    ``Ntilde = [ sin(phi) 1 + (1 - cos phi) E  |  e ]`` (3 x 3 block, then a column).

    Book: Sec. 3.4.2, Eq. (3.77b). Returns 3 x 4. Defined everywhere; it inverts N (which
    is singular at ``phi = 0``) off ``phi = 0``.
    """
    e = _vec(e)
    E, one = _ops(e)
    return _stack([[sp.sin(phi) * one + (1 - sp.cos(phi)) * E, e]], _symbolic(e))


def L_tilde(e, phi):
    """Left inverse of L: ``omega = Ltilde lambda_dot``, ``Ltilde L = 1``.

    ``Ltilde = [ 1 + tan(phi/2) E  |  -tan(phi/2) e ]``, ``tan(phi/2) = sin phi/(1 + cos phi)``.

    Book: Sec. 3.4.2, Eq. (3.77c). Returns 3 x 4. Singular at ``phi = pi``.
    """
    e = _vec(e)
    E, one = _ops(e)
    k = sp.sin(phi) / (1 + sp.cos(phi))
    return _stack([[one + k * E, -k * e]], _symbolic(e))


def H_tilde(e, phi):
    """Left inverse of H: ``omega = Htilde eta_dot``, ``Htilde H = 1``.

    ``Htilde = 2 [ cos(phi/2) 1 + sin(phi/2) E  |  -sin(phi/2) e ]``.

    Book: Sec. 3.4.2, Eq. (3.77d). Returns 3 x 4. No singularity.
    """
    e = _vec(e)
    E, one = _ops(e)
    c, s = sp.cos(phi / 2), sp.sin(phi / 2)
    return 2 * _stack([[c * one + s * E, -s * e]], _symbolic(e))


def twist_transfer_matrix(a, p):
    """Twist-transfer matrix: ``t_P = U t_A`` for twists ``[omega; v]`` (ray coordinates).

    ``U = [[1, O], [A - P, 1]]``, ``A = CPM(a)``, ``P = CPM(p)``.

    Book: Sec. 3.4.2, Eq. (3.83b) (same matrix as (3.29b)).

    Args:
        a, p: positions of points A and P, 3 x 1 (m).

    Returns:
        6 x 6 matrix. No singularity.
    """
    a, p = _vec(a), _vec(p)
    A, one = _ops(a)
    P, _ = _ops(p)
    Z = O3 if _symbolic(a) else sp.zeros(3)
    return _stack([[one, Z], [A - P, one]], _symbolic(a))


def twist_transfer(t_A, a, p):
    """Twist at P from the twist at A of the same body: ``t_P = U(a, p) t_A``.

    Book: Sec. 3.4.2, Eq. (3.83a).

    Args:
        t_A: twist ``[omega; v_A]`` at A, 6 x 1 (rad/s; m/s).
        a, p: positions of A and P, 3 x 1 (m).

    Returns:
        ``t_P = [omega; v_A + (a - p) x omega]``, 6 x 1.
    """
    return twist_transfer_matrix(a, p) * t_A


def T_matrix(F):
    """Pose-rate matrix: ``s_dot = T t`` for the pose ``s = [q; q0; d_A]`` and ``t = [omega; v_A]``.

    ``T = [[F, O_43], [O, 1]]`` with ``F`` one of N, L, H (4 x 3).

    Book: Sec. 3.4.2, Eq. (3.79). Returns 7 x 6; singular where F is (N: ``phi = 0``).
    """
    if _symbolic(F):
        return sp.BlockMatrix([[F, sp.ZeroMatrix(4, 3)], [O3, I3]])
    return block([[F, sp.zeros(4, 3)], [sp.zeros(3), eye3()]])


def S_matrix(F_tilde):
    """Twist from pose rate: ``t = S s_dot``; ``S = [[Ftilde, O], [O_34, 1]]``.

    Book: Sec. 3.4.2, Eq. (3.80b). ``F_tilde`` one of Ntilde, Ltilde, Htilde (3 x 4).
    Returns 6 x 7; singular where Ftilde is (Ltilde: ``phi = pi``).
    """
    if _symbolic(F_tilde):
        return sp.BlockMatrix([[F_tilde, O3], [sp.ZeroMatrix(3, 4), I3]])
    return block([[F_tilde, sp.zeros(3)], [sp.zeros(3, 4), eye3()]])


def pose_jacobians(e, phi) -> tuple[sp.Matrix, sp.Matrix, sp.Matrix]:
    """First-principles rate matrices ``(N, L, H)`` of the invariants, from the pose alone.

    ``lambda = [vect(Q); (tr Q - 1)/2]`` is differentiated along ``Qdot = Omega Q`` for
    ``Omega = CPM(omega)``, one column per basis vector of ``omega`` (this gives L); then the
    inverse-function derivatives of ``phi = atan2(||u||, u0)``, ``e = u/||u||`` (N) and of
    ``r = sin(phi/2) e``, ``r0 = cos(phi/2)`` (H). The printed (3.76b-d) are not used.

    Args:
        e: explicit unit axis, 3 x 1; phi: angle (rad), ``0 < phi < pi`` for the branch
            ``||u|| = sin(phi)``.

    Returns:
        three explicit 4 x 3 matrices.
    """
    e = sp.Matrix(e).reshape(3, 1)
    one = eye3()
    Q = e * e.T + sp.cos(phi) * (one - e * e.T) + sp.sin(phi) * cpm(e)
    cols = []
    for k in range(3):
        Qd = cpm(one[:, k]) * Q
        cols.append(block([[vect(Qd)], [trace(Qd) / 2]]))
    L_fp = sp.Matrix.hstack(*cols)
    s, c = sp.sin(phi), sp.cos(phi)
    dnu_dlam = block([[(one - e * e.T) / s, sp.zeros(3, 1)], [c * e.T, sp.Matrix([[-s]])]])
    N_fp = dnu_dlam * L_fp
    s2, c2 = sp.sin(phi / 2), sp.cos(phi / 2)
    deta_dnu = block([[s2 * one, c2 / 2 * e], [sp.zeros(1, 3), sp.Matrix([[-s2 / 2]])]])
    return N_fp, L_fp, deta_dnu * N_fp


# --------------------------------------------------------------------------- book symbols
e, E, phi, Q, omega = Mt.e, Mt.E, Mt.phi, Mt.Q, Mt.omega
a, p = Mt.a, Mt.p
nu, lam, eta = MS("nu", 4), MS("lambda", 4), MS("eta", 4)
nu_dot, lam_dot, eta_dot = MS("nudot", 4), MS("lambdadot", 4), MS("etadot", 4)
N, L, H = MS("N", 4, 3), MS("L", 4, 3), MS("H", 4, 3)
Nt, Lt, Ht = MS("Ntilde", 3, 4), MS("Ltilde", 3, 4), MS("Htilde", 3, 4)
t, v, v_A, v_P = MS("t", 6), MS("v"), MS("v_A"), MS("v_P")
t_A, t_P, U = MS("t_A", 6), MS("t_P", 6), MS("U", 6, 6)
A_cpm, P_cpm = MS("A", 3, 3), MS("P", 3, 3)  # book: A = CPM(a), P = CPM(p)
#: the three choices of invariants F = N, L, H: (name, F, Ftilde, invariant rate symbol)
CHOICES = (("N", N, Nt, nu_dot), ("L", L, Lt, lam_dot), ("H", H, Ht, eta_dot))
T_of = {n: MS(f"T_{n}", 7, 6) for n, *_ in CHOICES}
S_of = {n: MS(f"S_{n}", 6, 7) for n, *_ in CHOICES}
sdot_of = {n: MS(f"sdot_{n}", 7) for n, *_ in CHOICES}

_im = sp.ImmutableMatrix


@cache
def rates_model() -> dict:
    """Motion model plus the invariants, their rates, the pose Jacobians and the formulas.

    ``nu``, ``lambda``, ``eta`` and their rates from ``e(t)``, ``phi(t)`` (differentiated);
    ``N``, ``L``, ``H`` and ``Ntilde``... -> the formula functions (checked in (3.76b-d) against
    the first-principles :func:`pose_jacobians`, in :func:`jacobian_model`, and in
    (3.77b-d)); pose ``s_F = [q_F; d_A]`` with
    ``d_A = a(t) - a(0)``, so ``s_F dot = [q_F dot; a_dot]``; twist at A ``t = [omega; a_dot]``.
    """
    m = dict(motion_model(invariants=True))
    ev, ph = sp.Matrix(m[Mt.e]), m[Mt.phi]
    tt = ph.free_symbols.pop() if ph.free_symbols else None
    q = {"N": block([[ev], [ph]]),
         "L": block([[sp.sin(ph) * ev], [sp.cos(ph)]]),
         "H": block([[sp.sin(ph / 2) * ev], [sp.cos(ph / 2)]])}
    qd = {k: x.diff(tt) for k, x in q.items()}
    Ft = {"N": N_tilde(ev, ph), "L": L_tilde(ev, ph), "H": H_tilde(ev, ph)}
    Ff = {"N": N_matrix(ev, ph), "L": L_matrix(ev, ph), "H": H_matrix(ev, ph)}
    adot = sp.Matrix(m[Mt.a_dot])
    tw = block([[sp.Matrix(m[Mt.omega])], [adot]])
    m.update({nu: _im(q["N"]), lam: _im(q["L"]), eta: _im(q["H"]), nu_dot: _im(qd["N"]),
              lam_dot: _im(qd["L"]), eta_dot: _im(qd["H"]), N: _im(N_matrix(ev, ph)),
              L: _im(L_matrix(ev, ph)), H: _im(H_matrix(ev, ph)), Nt: _im(Ft["N"]),
              Lt: _im(Ft["L"]), Ht: _im(Ft["H"]), t: _im(tw),
              t_A: _im(tw), v: _im(adot), v_A: _im(adot),
              v_P: m[Mt.p_dot], t_P: _im(block([[sp.Matrix(m[Mt.omega])], [m[Mt.p_dot]]])),
              A_cpm: _im(cpm(m[Mt.a])), P_cpm: _im(cpm(m[Mt.p])),
              U: _im(twist_transfer_matrix(m[Mt.a], m[Mt.p]))})
    for n, *_ in CHOICES:
        m[T_of[n]] = _im(T_matrix(Ff[n]))
        m[S_of[n]] = _im(S_matrix(Ft[n]))
        m[sdot_of[n]] = _im(block([[qd[n]], [adot]]))
    return m


@cache
def jacobian_model() -> dict:
    """:func:`rates_model` with ``N``, ``L``, ``H`` -> the first-principles pose Jacobians."""
    m = dict(rates_model())
    Nf, Lf, Hf = pose_jacobians(sp.Matrix(m[Mt.e]), m[Mt.phi])
    m.update({N: _im(Nf), L: _im(Lf), H: _im(Hf)})
    return m
