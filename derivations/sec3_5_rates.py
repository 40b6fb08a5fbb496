"""Sec. 3.5: time derivatives of N, L, H and of their left inverses, Eqs. (3.96a)-(3.97e):
the formula functions, book symbols and motion model (the declarations are in
:mod:`rigidsym.derivations.sec3_5_rate_equations`).

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.5.

Method: every rate is obtained by differentiating the matrix along a generic smooth motion
(``e(t)`` unit, ``phi(t)``; :func:`derivations.common.motion_model`), never assumed; the
printed forms are then compared with it. The formula functions below give the same rates
in closed form in the variables ``(e, phi, omega)`` only, using ``nu_dot = N omega``
(3.76a) for ``e_dot``, ``phi_dot`` (and ``lambda_dot = L omega``, ``eta_dot = H omega``).

The auxiliary matrices ``B`` (3.96e) and ``V`` (3.97d) are *introduced* by their use in
(3.96a) and (3.97b): ``B = 4 (1 - cos phi)`` times the upper block of ``N_dot``, and
``V = D`` times the upper block of the rate of ``L_tilde`` (3.77c); (3.96e) and (3.97d)
state closed forms for them, which are checked against that characterisation.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.declare import (
    TIME,
    angle,
    block,
    cpm,
    rotation_from_natural_invariants,
    unit_vector,
    vector,
)

from .common import I3, MS, Mt, mat, motion_model, vec
from .sec3_4_2 import H_matrix, H_tilde, L_matrix, L_tilde, N_matrix, N_tilde

__all__ = ["B_matrix", "N_matrix_dot", "L_matrix_dot", "H_matrix_dot", "N_tilde_dot", "V_u",
           "L_tilde_dot", "H_tilde_dot"]


# --------------------------------------------------------------------------- (3.76), (3.77)
# N, L, H and their left inverses exist once, in Sec. 3.4.2 (checked there).
_N, _L, _H = N_matrix, L_matrix, H_matrix
_N_tilde, _L_tilde, _H_tilde = N_tilde, L_tilde, H_tilde


def _col(v) -> sp.Matrix:
    return sp.Matrix(v).reshape(3, 1)


RATE_MATRICES = {"N": _N, "L": _L, "H": _H}
LEFT_INVERSES = {"N": _N_tilde, "L": _L_tilde, "H": _H_tilde}


# --------------------------------------------------------------------------- book symbols
class Rt:
    """Book symbols of the rates (Sec. 3.5); ``Mt`` (common.py) holds e, phi, Q, omega, ..."""

    N_dot, L_dot, H_dot = MS("Ndot", 4, 3), MS("Ldot", 4, 3), MS("Hdot", 4, 3)
    Nt_dot, Lt_dot, Ht_dot = (MS("Ntildedot", 3, 4), MS("Ltildedot", 3, 4),
                              MS("Htildedot", 3, 4))
    Lt_alt_dot = MS("Ltilde_alt_dot", 3, 4)
    B, V, V_alt = mat("B"), mat("V"), mat("V_alt")
    U, U_dot, R, R_dot, E_dot = mat("U"), mat("Udot"), mat("R"), mat("Rdot"), mat("Edot")
    u, u_dot, r, r_dot = vec("u"), vec("udot"), vec("r"), vec("rdot")
    u0, u0_dot, r0, r0_dot = sp.symbols("u0 u0dot r0 r0dot", real=True)
    D = sp.Symbol("D", real=True)


# --------------------------------------------------------------------------- formula functions
# Each formula is written once, generically: called with explicit sympy matrices it returns
# the explicit rate in (e, phi, omega) (rates of the invariants from nu_dot = N omega etc.);
# called with the book's symbols (Mt.e, Mt.phi, Mt.omega) it returns the same formula as a
# compact matrix expression in the book's vocabulary (e_dot, phi_dot, u, U, r_dot, ...).
def _symbolic(e) -> bool:
    return isinstance(e, sp.MatrixSymbol)


def _dot(a, b):
    """``a . b``; for book symbols ``Trace(a^T b)``, which prints compactly."""
    return sp.Trace(a.T * b) if _symbolic(a) else (a.T * b)[0, 0]


def _cp(v):
    """``cpm(v)``, or the book's name for it (E, Omega, U, R, E_dot, ...) for a book symbol."""
    if _symbolic(v):
        return {Mt.e: Mt.E, Mt.omega: Mt.Omega, Mt.e_dot: Rt.E_dot, Rt.u: Rt.U,
                Rt.u_dot: Rt.U_dot, Rt.r: Rt.R, Rt.r_dot: Rt.R_dot}[v]
    return cpm(v)


def _blk(rows, symbolic: bool):
    return sp.BlockMatrix(rows) if symbolic else block(rows)


def _one(symbolic: bool):
    return I3 if symbolic else sp.eye(3)


def _rates(e, phi, omega) -> dict:
    """Invariants and their rates: book symbols, or explicit from N, L, H times omega."""
    if _symbolic(e):
        return {"e": e, "w": omega, "e_dot": Mt.e_dot, "phi_dot": Mt.phi_dot, "u": Rt.u,
                "u_dot": Rt.u_dot, "u0_dot": Rt.u0_dot, "r_dot": Rt.r_dot,
                "r0_dot": Rt.r0_dot, "Q": Mt.Q, "trQ": sp.Trace(Mt.Q), "D": Rt.D}
    e, omega = _col(e), _col(omega)
    nu, lam, eta = _N(e, phi) * omega, _L(e, phi) * omega, _H(e, phi) * omega
    Q = rotation_from_natural_invariants(e, phi)
    return {"e": e, "w": omega, "e_dot": nu[:3, :], "phi_dot": nu[3],
            "u": sp.sin(phi) * e, "u_dot": lam[:3, :], "u0_dot": lam[3],
            "r_dot": eta[:3, :], "r0_dot": eta[3], "Q": Q, "trQ": Q.trace(),
            "D": 1 + sp.cos(phi)}


def B_matrix(e, phi, omega):
    """Auxiliary matrix of ``N_dot``: ``B = 4 (1 - cos phi)`` times the upper block of ``N_dot``.

    ``B = -2 (e.w) 1 + 2 (2 + cos phi)(e.w) e e^T - 2 cos(phi) w e^T - 2 e w^T
    - sin(phi) [Omega - (e.w) E] + sin(phi) [(E w) e^T + e (E w)^T]``, ``w = omega``.

    Book: Sec. 3.5, Eq. (3.96e), corrected (the printed form does not hold).

    Args:
        e: unit axis, 3 x 1. phi: angle (rad). omega: angular velocity, 3 x 1 (rad/s).

    Returns:
        3 x 3 ``sympy.Matrix`` (rad/s); a matrix expression for book symbols.

    Notes:
        Regular everywhere; ``N_dot = [B / (4 (1 - cos phi)); e_dot^T]`` is singular at
        ``phi = 0`` (mod 2 pi), like ``N``.
    """
    k = _rates(e, phi, omega)
    e, w = k["e"], k["w"]
    c, s, ew = sp.cos(phi), sp.sin(phi), _dot(e, w)
    E = _cp(e)
    Ew = E * w
    return (-2 * ew * _one(_symbolic(e)) + 2 * (2 + c) * ew * e * e.T - 2 * c * w * e.T
            - 2 * e * w.T - s * (_cp(w) - ew * E) + s * (Ew * e.T + e * Ew.T))


def N_matrix_dot(e, phi, omega):
    """Rate of N (3.76b): ``N_dot = [B / (4 (1 - cos phi)); e_dot^T]``, ``e_dot`` from N omega.

    Book: Sec. 3.5, Eq. (3.96a) corrected (the factor multiplies B only; the last row is
    ``e_dot^T``), with ``B`` from :func:`B_matrix`.

    Args:
        e: unit axis, 3 x 1. phi: angle (rad). omega: angular velocity, 3 x 1 (rad/s).

    Returns:
        4 x 3 ``sympy.Matrix`` (1/s). Singular set: ``phi = 0`` (mod 2 pi).
    """
    e_dot = _rates(e, phi, omega)["e_dot"]
    return _blk([[B_matrix(e, phi, omega) / (4 * (1 - sp.cos(phi)))], [e_dot.T]],
                _symbolic(e))


def L_matrix_dot(e, phi, omega):
    """Rate of L (3.76c): ``L_dot = [-(w.u) 1 - Omega Q / 2; -w^T (tr(Q) 1 - Q^T) / 2]``.

    Book: Sec. 3.5, Eq. (3.96b), second member (``u = sin(phi) e``, ``Q`` from (2.49)).

    Args:
        e: unit axis, 3 x 1. phi: angle (rad). omega: angular velocity, 3 x 1 (rad/s).

    Returns:
        4 x 3 ``sympy.Matrix`` (1/s). Regular everywhere.
    """
    k = _rates(e, phi, omega)
    w, Q, one = k["w"], k["Q"], _one(_symbolic(e))
    return _blk([[-_dot(w, k["u"]) * one - _cp(w) * Q / 2],
                 [-w.T * (k["trQ"] * one - Q.T) / 2]], _symbolic(e))


def H_matrix_dot(e, phi, omega):
    """Rate of H (3.76d): ``H_dot = 1/2 [r0_dot 1 - R_dot; -r_dot^T]``, ``[r_dot; r0_dot] = H w``.

    Book: Sec. 3.5, Eq. (3.96c).

    Args:
        e: unit axis, 3 x 1. phi: angle (rad). omega: angular velocity, 3 x 1 (rad/s).

    Returns:
        4 x 3 ``sympy.Matrix`` (1/s). Regular everywhere.
    """
    k = _rates(e, phi, omega)
    r_dot, r0_dot = k["r_dot"], k["r0_dot"]
    return _blk([[r0_dot * _one(_symbolic(e)) - _cp(r_dot)], [-r_dot.T]], _symbolic(e)) / 2


def N_tilde_dot(e, phi, omega):
    """Rate of N~ (3.77b): ``[phi_dot (cos phi 1 + sin phi E) + (1 - cos phi) E_dot, e_dot]``.

    ``E_dot = cpm(e_dot)``; ``e_dot``, ``phi_dot`` from ``nu_dot = N omega``.
    Book: Sec. 3.5, Eq. (3.97a), corrected.

    Args:
        e: unit axis, 3 x 1. phi: angle (rad). omega: angular velocity, 3 x 1 (rad/s).

    Returns:
        3 x 4 ``sympy.Matrix`` (1/s). Singular set: ``phi = 0`` (through ``N``).
    """
    k = _rates(e, phi, omega)
    e, e_dot, phi_dot = k["e"], k["e_dot"], k["phi_dot"]
    c, s = sp.cos(phi), sp.sin(phi)
    terms = ((1 - c) * _cp(e_dot), phi_dot * (c * _one(_symbolic(e)) + s * _cp(e)))
    # unevaluated MatAdd in this order: sympy's pretty printer drops the "+" before a
    # (1 - cos phi) coefficient when it comes second
    upper = sp.MatAdd(*terms) if _symbolic(e) else terms[0] + terms[1]
    return _blk([[upper, e_dot]], _symbolic(e))


def V_u(e, phi, omega):
    """Auxiliary matrix of the L~ rate: ``V = U_dot - (u0_dot / D) U`` (D = 1 + u0).

    ``D`` times the rate of the upper block ``1 + U / D`` of L~ (3.77c).
    Book: Sec. 3.5, Eq. (3.97d), corrected.

    Args:
        e: unit axis, 3 x 1. phi: angle (rad). omega: angular velocity, 3 x 1 (rad/s).

    Returns:
        3 x 3 ``sympy.Matrix`` (1/s). Singular set: ``phi = pi`` (``D = 0``).
    """
    k = _rates(e, phi, omega)
    return _cp(k["u_dot"]) - k["u0_dot"] / k["D"] * _cp(k["u"])


def L_tilde_dot(e, phi, omega):
    """Rate of L~ (3.77c): ``[V / D, ((u0_dot / D) u - u_dot) / D]``, V from :func:`V_u`.

    ``u = sin(phi) e``, ``u0 = cos phi``, ``D = 1 + u0``, ``[u_dot; u0_dot] = L omega``.
    Book: Sec. 3.5, Eq. (3.97b), corrected.

    Args:
        e: unit axis, 3 x 1. phi: angle (rad). omega: angular velocity, 3 x 1 (rad/s).

    Returns:
        3 x 4 ``sympy.Matrix`` (1/s). Singular set: ``phi = pi`` (``D = 0``).
    """
    k = _rates(e, phi, omega)
    u, u_dot, u0_dot, D = k["u"], k["u_dot"], k["u0_dot"], k["D"]
    return _blk([[V_u(e, phi, omega) / D, (u0_dot / D * u - u_dot) / D]], _symbolic(e))


def H_tilde_dot(e, phi, omega):
    """Rate of H~ (3.77d): ``2 [r0_dot 1 + R_dot, -r_dot]``, ``[r_dot; r0_dot] = H omega``.

    Book: Sec. 3.5, Eq. (3.97c), corrected (the factor 2 of (3.77d) restored).

    Args:
        e: unit axis, 3 x 1. phi: angle (rad). omega: angular velocity, 3 x 1 (rad/s).

    Returns:
        3 x 4 ``sympy.Matrix`` (1/s). Regular everywhere.
    """
    k = _rates(e, phi, omega)
    r_dot, r0_dot = k["r_dot"], k["r0_dot"]
    return _blk([[2 * (r0_dot * _one(_symbolic(e)) + _cp(r_dot)), -2 * r_dot]], _symbolic(e))


# --------------------------------------------------------------------------- model
@cache
def rates_model() -> dict:
    """First-principles values along a generic motion ``e(t)``, ``phi(t)`` (cached per run).

    Rates are ``d/dt`` of the (3.76)/(3.77) matrices along the motion; ``B`` and ``V`` are
    the characterisations of (3.96a)/(3.97b) (see the module docstring); ``V_alt`` is the
    same for the other left inverse ``[1 + (U - u u^T)/D, -u]`` of ``L``.
    """
    m = motion_model(invariants=True)
    e, phi, t = m[Mt.e], m[Mt.phi], TIME
    im = sp.ImmutableMatrix
    u, u0 = sp.sin(phi) * e, sp.cos(phi)
    r, r0 = sp.sin(phi / 2) * e, sp.cos(phi / 2)
    D = 1 + u0
    N_dot = _N(e, phi).diff(t)
    Lt_dot = _L_tilde(e, phi).diff(t)
    Lt_alt_dot = block([[sp.eye(3) + (cpm(u) - u * u.T) / D, -u]]).diff(t)
    m.update({
        Rt.N_dot: im(N_dot), Rt.L_dot: im(_L(e, phi).diff(t)), Rt.H_dot: im(_H(e, phi).diff(t)),
        Rt.Nt_dot: im(_N_tilde(e, phi).diff(t)), Rt.Lt_dot: im(Lt_dot),
        Rt.Ht_dot: im(_H_tilde(e, phi).diff(t)), Rt.Lt_alt_dot: im(Lt_alt_dot),
        Rt.B: im(4 * (1 - sp.cos(phi)) * N_dot[:3, :]), Rt.V: im(D * Lt_dot[:, :3]),
        Rt.V_alt: im(D * Lt_alt_dot[:, :3]),
        Rt.u: im(u), Rt.u_dot: im(u.diff(t)), Rt.U: im(cpm(u)), Rt.U_dot: im(cpm(u.diff(t))),
        Rt.r: im(r), Rt.r_dot: im(r.diff(t)), Rt.R: im(cpm(r)), Rt.R_dot: im(cpm(r.diff(t))),
        Rt.E_dot: im(cpm(e.diff(t))), Rt.u0: u0, Rt.u0_dot: u0.diff(t), Rt.r0: r0,
        Rt.r0_dot: r0.diff(t), Rt.D: D,
        I3: im(sp.eye(3))})  # the book's 1, explicit: keeps explicit() off its slow Sum path
    return m


@cache
def omega_model() -> dict:
    """Rates along a motion given by its angular velocity: ``nu_dot = N omega`` (3.76a).

    For the statements whose printed form is a formula in ``omega`` (3.96a, e): ``e``,
    ``phi``, ``omega`` are free (``e`` unit), and the jets ``e_dot``, ``phi_dot`` of
    :func:`rates_model` are replaced by ``N omega`` -- small expressions, where the motion's
    ``omega = vect(Q_dot Q^T)`` of (2.49) would be large. ``N_dot`` and ``B`` are still
    obtained by differentiating ``N`` (3.76b, verified there) along the motion.
    """
    m = rates_model()
    e_t, phi_t = m[Mt.e], m[Mt.phi]
    e_s, phi_s, w = unit_vector("e"), angle("phi"), vector("omega")
    nu_dot = _N(e_s, phi_s) * w
    jets = {sp.Derivative(e_t[i], TIME): nu_dot[i] for i in range(3)}
    jets[sp.Derivative(phi_t, TIME)] = nu_dot[3]
    static = {e_t[i]: e_s[i] for i in range(3)}
    static[phi_t] = phi_s

    def along(x):
        return sp.ImmutableMatrix(x.xreplace(jets).xreplace(static))

    im = sp.ImmutableMatrix
    return {Mt.e: im(e_s), Mt.phi: phi_s, Mt.omega: im(w), Mt.Omega: im(cpm(w)),
            Mt.E: im(cpm(e_s)), Mt.e_dot: im(nu_dot[:3, :]), Mt.phi_dot: nu_dot[3],
            Rt.N_dot: along(m[Rt.N_dot]), Rt.B: along(m[Rt.B]), I3: im(sp.eye(3))}


def along_motion(fn):
    """``fn(e, phi, omega)`` evaluated explicitly on the motion's e(t), phi(t), omega(t)."""
    m = rates_model()
    return fn(m[Mt.e], m[Mt.phi], m[Mt.omega])


def _book(fn):
    """``fn`` as a compact matrix expression in the book's symbols."""
    return fn(Mt.e, Mt.phi, Mt.omega)
