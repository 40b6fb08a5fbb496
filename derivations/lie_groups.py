"""The Lie-group maps of SO(3) and SE(3), verified by the chapter's checker.

Not the book's equations: their ids say their source, ``sola:`` (Solà, Deray & Atchuthan,
"A micro Lie theory for state estimation in robotics", arXiv:1812.01537, 2018, App. B for
SO(3) and D for SE(3)) and ``barfoot:`` (Barfoot, *State Estimation for Robotics*, 2017,
Sec. 7.1). The formulas are those of :mod:`derivations.lie_maps`; each declaration checks
one defining property or identity of them on a first-principles model:

- a rotation vector is ``w = theta e`` (the polar parametrisation: ``theta`` an angle on
  ``[0, pi]``, ``e`` a unit vector): every rotation vector of norm at most ``pi``, and the
  trigonometric functions of the norm ``sqrt(w^T w)`` become those of ``theta``
  (:mod:`rigidsym.checking.deciding.branches`); the identities below are analytic in
  ``w``, so holding there they hold for every ``w`` where both sides are defined;
- the Jacobians by their definitions, ``d/dt Exp(w) Exp(w)^T = [J_l w_dot]`` along a
  motion ``w(t) = theta(t) e(t)``;
- a rotation from the chapter's natural invariants (Angeles (2.49)), so that ``w = phi e``
  links the maps to ``(e, phi)``.

``rigidsym verify --module rigidsym.derivations.lie_groups`` checks them (or ``--module
derivations/lie_groups.py`` in a checkout).
"""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import (
    TIME,
    Rel,
    Statement,
    angle,
    cpm,
    equation,
    rotation_from_euler_rodrigues,
    rotation_from_natural_invariants,
    unit_vector,
    unit_vector4,
    vector,
)

try:  # a package (rigidsym.derivations) or a file loaded by --module
    from . import lie_maps as L
    from .common import MS, mat, vec
except ImportError:  # pragma: no cover - loaded as a file
    import lie_maps as L  # type: ignore[no-redef]
    from common import MS, mat, vec  # type: ignore[no-redef]

theta = angle("theta", range="[0, pi]")
phi = angle("phi")                      # the chapter's angle, on (-pi, pi)
e = unit_vector("e")
w_ = theta * e                          # the polar parametrisation of a rotation vector
v_ = vector("v")

R, Jl, Jr, Jm = mat("R"), mat("J_l"), mat("J_r"), mat("J_r(-w)")
Jli, Jri, Q = mat("J_l^-1"), mat("J_r^-1"), mat("Q")
w, v, wd = vec("w"), vec("v"), vec("w_dot")
T, X = MS("T", 4, 4), MS("J_l(xi)", 6, 6)
xi = MS("xi", 6, 1)
I3, I6 = sp.Identity(3), sp.Identity(6)
_im = sp.ImmutableMatrix


def _so3(wv) -> dict:
    return {w: _im(wv), R: _im(L.rotation_from_rotation_vector(wv)),
            Jl: _im(L.rotation_vector_left_jacobian(wv)),
            Jr: _im(L.rotation_vector_right_jacobian(wv)),
            Jm: _im(L.rotation_vector_right_jacobian(-wv)),
            Jli: _im(L.rotation_vector_left_jacobian_inverse(wv)),
            Jri: _im(L.rotation_vector_right_jacobian_inverse(wv))}


SO3 = _so3(w_)


# ------------------------------------------------------------------ SO(3)
@equation("sola:exp-so3", "Exp(w) = Exp of the natural invariants, w = φ e "
          "(Solà App. B; Angeles (2.49))", section="so3")
def exp_so3() -> Statement:
    wv = phi * e  # the chapter's (e, phi), phi of either sign
    return Statement([Rel(R, Q)], {R: _im(L.rotation_from_rotation_vector(wv)),
                                   Q: _im(rotation_from_natural_invariants(e, phi))})


@equation("sola:log-exp-so3", "Log(Exp(w)) = w for |w| < π (Solà App. B)", section="so3",
          singular="|w| = 0 (removable) or π (the axis up to sign)")
def log_exp_so3() -> Statement:
    Lg = vec("Log(R)")
    return Statement([Rel(Lg, w)], {**SO3, Lg: _im(L.rotation_vector_from_rotation(SO3[R]))})


@equation("sola:exp-log-so3", "Exp(Log(Q)) = Q (Solà App. B)", section="so3",
          singular="the angle of Q is 0 (removable) or π")
def exp_log_so3() -> Statement:
    Qv = rotation_from_natural_invariants(e, theta)  # every rotation, its angle in [0, pi]
    # the formulas applied to the model's value (on the symbol Q, the substitution would
    # rebuild sin(acos(c)) as sqrt(1 - c^2))
    return Statement([Rel(R, Q)], {Q: _im(Qv), R: _im(L.rotation_from_rotation_vector(
        L.rotation_vector_from_rotation(Qv)))})


#: the small-angle branches of the logs read a rotation of at most a quarter turn from
#: ``s = |vect(Q)| = sin theta``: its angle ``theta = beta/2``, ``beta`` on ``[0, pi]``, so that
#: ``asin(s) = theta`` and ``sqrt(1 - s^2) = cos theta`` exactly (the checker's principal
#: branches, :mod:`rigidsym.checking.deciding.branches`); the kernels take them below pi/4
beta = angle("beta", range="[0, pi]")


@equation("sola:log-so3-small", "Log(Q) = (asin s / s) vect(Q), s = |vect(Q)|, for an angle "
          "≤ π/2 (Solà App. B; Barfoot Sec. 7.1.3)", section="so3",
          singular="the angle of Q is 0 (removable)")
def log_so3_small() -> Statement:
    Lg = vec("Log(R)")
    Rv = rotation_from_natural_invariants(e, beta / 2)
    return Statement([Rel(Lg, w)], {w: _im(beta / 2 * e),
                                    Lg: _im(L.rotation_vector_from_rotation_small(Rv))})


@equation("sola:log-se3-small", "Log(T) = [a u; p − (a/2) u × p + g u × (u × p)], u = vect(R), "
          "s = |u|, a = asin(s)/s, g = (2s − asin(s)(1 + √(1 − s²)))/(2s³), for an angle ≤ π/2 "
          "(Solà App. D; Barfoot Sec. 7.1.5)", section="se3",
          singular="the angle of R is 0 (removable)")
def log_se3_small() -> Statement:
    wv = beta / 2 * e
    Tv = sp.Matrix.vstack(sp.Matrix.hstack(rotation_from_natural_invariants(e, beta / 2), v_),
                          sp.Matrix([[0, 0, 0, 1]]))
    Lg = MS("Log(T)", 6, 1)
    xv = sp.Matrix.vstack(wv, L.rotation_vector_left_jacobian_inverse(wv) * v_)
    return Statement([Rel(Lg, xi)], {xi: _im(xv),
                                     Lg: _im(L.exponential_coordinates_from_transform_small(Tv))})


@equation("sola:jl-definition", "d/dt Exp(w) Exp(w)ᵀ = [J_l(w) ẇ] (Solà App. B)",
          section="so3")
def jl_definition() -> Statement:
    th, ee = angle("theta", TIME, range="[0, pi]"), unit_vector("e", TIME)
    wt = th * ee
    Rt = L.rotation_from_rotation_vector(wt)
    return Statement([Rel(R * Q.T, cpm(Jl * wd))],
                     {R: _im(Rt.diff(TIME)), Q: _im(Rt), wd: _im(wt.diff(TIME)),
                      Jl: _im(L.rotation_vector_left_jacobian(wt))})


@equation("sola:jr-definition", "Exp(w)ᵀ d/dt Exp(w) = [J_r(w) ẇ] (Solà App. B)",
          section="so3")
def jr_definition() -> Statement:
    th, ee = angle("theta", TIME, range="[0, pi]"), unit_vector("e", TIME)
    wt = th * ee
    Rt = L.rotation_from_rotation_vector(wt)
    return Statement([Rel(Q.T * R, cpm(Jr * wd))],
                     {R: _im(Rt.diff(TIME)), Q: _im(Rt), wd: _im(wt.diff(TIME)),
                      Jr: _im(L.rotation_vector_right_jacobian(wt))})


@equation("sola:jl-jr", "J_l(w) = J_r(−w) (Solà App. B; Barfoot Sec. 7.1.5)",
          section="so3")
def jl_jr() -> Statement:
    return Statement([Rel(Jl, Jm)], SO3)


@equation("sola:jl-R-jr", "J_l(w) = Exp(w) J_r(w) (Solà App. B)", section="so3")
def jl_r_jr() -> Statement:
    return Statement([Rel(Jl, R * Jr)], SO3)


@equation("sola:jl-w", "J_l(w) w = w = J_r(w) w (Barfoot Sec. 7.1.5)", section="so3")
def jl_w() -> Statement:
    return Statement([Rel(Jl * w, w), Rel(Jr * w, w, "right")], SO3)


@equation("sola:jl-inverse", "J_l(w) J_l(w)⁻¹ = 1 = J_r(w) J_r(w)⁻¹ (Solà App. B)",
          section="so3", singular="|w| = 2πk, k ≠ 0")
def jl_inverse() -> Statement:
    return Statement([Rel(Jl * Jli, I3), Rel(Jr * Jri, I3, "right")], SO3)


@equation("sola:jl-times", "J_l(w) v = (sin θ/θ) v + ((1 − cos θ)/θ²) w × v + ((θ − sin θ)/θ³) "
          "(w·v) w (Solà App. B; Barfoot Sec. 7.1.3)", section="so3")
def jl_times() -> Statement:
    # the kernels' form of J_l v (no cancellation at large theta)
    p = vec("J_l v")
    return Statement([Rel(p, Jl * v)],
                     {**SO3, v: _im(v_),
                      p: _im(L.rotation_vector_left_jacobian_times(w_, v_))})


# ------------------------------------------------------------------ SE(3)
def _se3(wv, vv) -> dict:
    x = sp.Matrix.vstack(wv, vv)
    return {xi: _im(x), T: _im(L.transform_from_exponential_coordinates(x)),
            X: _im(L.exponential_coordinates_left_jacobian(x))}


@equation("sola:exp-se3", "Exp([w; v]) = [[Exp(w), J_l(w) v], [0, 1]] is MR's "
          "exp([S] θ) (Solà App. D; MR (3.88))", section="se3")
def exp_se3() -> Statement:
    from rigidsym.declare import expm, hat

    S = sp.Matrix.vstack(e, v_)
    return Statement([Rel(T, expm(theta * hat(S)))],
                     {T: _im(L.transform_from_exponential_coordinates(theta * S))})


@equation("sola:log-exp-se3", "Log(Exp(ξ)) = ξ for |w| < π (Solà App. D)", section="se3",
          singular="|w| = 0 (removable) or π")
def log_exp_se3() -> Statement:
    m, Lg = _se3(w_, v_), MS("Log(T)", 6, 1)
    return Statement([Rel(Lg, xi)], {**m, Lg: _im(L.exponential_coordinates_from_transform(m[T]))})


@equation("barfoot:se3-jl-xi", "J_l(ξ) ξ = ξ (Barfoot Sec. 7.1.5)", section="se3")
def se3_jl_xi() -> Statement:
    return Statement([Rel(X * xi, xi)], _se3(w_, v_))


@equation("barfoot:se3-jl-inverse", "J_l(ξ) J_l(ξ)⁻¹ = 1 (Barfoot Sec. 7.1.5)",
          section="se3", singular="|w| = 2πk, k ≠ 0")
def se3_jl_inverse() -> Statement:
    x = sp.Matrix.vstack(w_, v_)
    Xi = MS("J_l(xi)^-1", 6, 6)
    return Statement([Rel(X * Xi, I6)],
                     {**_se3(w_, v_),
                      Xi: _im(L.exponential_coordinates_left_jacobian_inverse(x))})


@equation("barfoot:se3-q-block", "Q(v, w) = A V + B (v wᵀ + w vᵀ) + (w·v)(D W + G w wᵀ − H 1) "
          "is Barfoot's printed Q (Barfoot Sec. 7.1.5; Solà App. D)", section="se3")
def se3_q_block() -> Statement:
    # the kernels' Q, whose terms are each O(|v|/theta), against Barfoot's seven products,
    # each O(|v|) at large theta
    Qk, Qb = mat("Q(v, w)"), mat("Q_Barfoot(v, w)")
    return Statement([Rel(Qk, Qb)], {Qk: _im(L.se3_q_block(w_, v_)),
                                     Qb: _im(L.se3_q_block_barfoot(w_, v_))})


@equation("barfoot:se3-jl-definition", "d/dt Exp(ξ) Exp(ξ)⁻¹ = [J_l(ξ) ξ̇]^ "
          "(Barfoot Sec. 7.1.5)", section="se3")
def se3_jl_definition() -> Statement:
    from rigidsym.declare import hat, transform_inverse

    th, ee, vt = angle("theta", TIME, range="[0, pi]"), unit_vector("e", TIME), \
        vector("v", TIME)
    x = sp.Matrix.vstack(th * ee, vt)
    Tt = L.transform_from_exponential_coordinates(x)
    Td, xd = MS("T_dot", 4, 4), MS("xi_dot", 6, 1)
    return Statement([Rel(Td * transform_inverse(T), hat(X * xd))],
                     {T: _im(Tt), Td: _im(Tt.diff(TIME)), xd: _im(x.diff(TIME)),
                      X: _im(L.exponential_coordinates_left_jacobian(x))})


# ------------------------------------------------------------------ Euler-Rodrigues
@equation("sola:quat-of-rotation", "The parameters of Q(e, φ): [sin(φ/2) e; cos(φ/2)], "
          "r0 ≥ 0 (Angeles Sec. 2.3)", section="quaternion",
          singular="φ = π (r0 = 0)")
def quat_of_rotation() -> Statement:
    eta = MS("eta", 4, 1)
    Qv = rotation_from_natural_invariants(e, theta)
    return Statement([Rel(eta, sp.Matrix.vstack(sp.sin(theta / 2) * e,
                                                 sp.Matrix([sp.cos(theta / 2)])))],
                     {eta: _im(L.euler_rodrigues_from_rotation(Qv))})


@equation("sola:quat-product", "Q(η₁ ⊗ η₂) = Q(η₁) Q(η₂) (Solà App. B)",
          section="quaternion")
def quat_product() -> Statement:
    a, b = unit_vector4("eta1"), unit_vector4("eta2")
    c = L.euler_rodrigues_product(a, b)
    Q1, Q2 = mat("Q_1"), mat("Q_2")
    return Statement([Rel(Q, Q1 * Q2)],
                     {Q: _im(rotation_from_euler_rodrigues(c[:3, :], c[3])),
                      Q1: _im(rotation_from_euler_rodrigues(a[:3, :], a[3])),
                      Q2: _im(rotation_from_euler_rodrigues(b[:3, :], b[3]))})
