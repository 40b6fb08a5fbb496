"""Identities of Lynch & Park, *Modern Robotics* (MR), ch. 3, and Murray, Li & Sastry (MLS),
ch. 2, written in rigidsym's vocabulary of rigid motions.

Run ``rigidsym verify --module examples/modern_robotics.py``; ``rigidsym show ID --module
examples/modern_robotics.py`` explains one; ``rigidsym generate --module
examples/modern_robotics.py --out DIR`` compiles its two kernels.

Each declaration gives the printed form in book symbols (``R``, ``Omega`` = ``[omega]``,
``T``, ``V``, ``F``) and a model: first-principles values of those symbols, here the words
themselves (``expm``, ``transform``, ``Ad``, ...) on constrained atoms (a unit axis
``omega``, an angle ``theta``, generic rotations ``Q1``, ``Q2``). Twists are ``[omega; v]``
and wrenches ``[m; f]`` (MR's order, the words' default). Three slips, each a likely
misremembering, carry no corrected form: the repair search finds it.
"""

from __future__ import annotations

import sympy as sp

from rigidsym import (
    I3,
    MS,
    Ad,
    Blocks,
    Cross,
    Det,
    Rel,
    Statement,
    acos,
    ad,
    ad_dual,
    angle,
    cpm,
    diff,
    equation,
    expm,
    hat,
    logm,
    mat,
    rotation,
    trace,
    transform,
    transform_inverse,
    twist,
    unit_vector,
    vec,
    vector,
    vee,
    wrench,
)
from rigidsym.codegen.spec import Arg, Kernel, Out

# constrained atoms: |w| = 1, cos^2 + sin^2 = 1, Q^T Q = 1 (imposed exactly by the checker)
w, theta = unit_vector("omega"), angle("theta")
theta_p = angle("theta", range="[0, pi]")  # MR's theta of the logarithm, in [0, pi]
Q1, Q2 = rotation("Q1"), rotation("Q2")
p1, p2, q, v = vector("p1"), vector("p2"), vector("q"), vector("v")
h = sp.Symbol("h", real=True)  # the pitch of a screw
V1, V2, F1 = twist("V1"), twist("V2"), wrench("F1")

# book symbols, so that a printed form reads like the book
R, Om, Qs = mat("R"), mat("Omega"), mat("Q")
om, a, pv, qv = vec("omega"), vec("a"), vec("p"), vec("q")
T, T1, T2 = MS("T", 4, 4), MS("T1", 4, 4), MS("T2", 4, 4)
V, W, F = MS("V", 6, 1), MS("W", 6, 1), MS("F", 6, 1)
I4, I6 = sp.Identity(4), sp.Identity(6)

ROT = {R: expm(theta * cpm(w)), Om: cpm(w), om: w}
ROT_P = {R: expm(theta_p * cpm(w)), Om: cpm(w), om: w}
MOTION = {T: transform(Q1, p1), T1: transform(Q1, p1), T2: transform(Q2, p2), Qs: Q1,
          pv: p1, V: V1, W: V2, F: F1}


def screw(omega, q, h) -> sp.Matrix:
    """The screw axis of a joint along the unit ``omega`` through ``q`` with pitch ``h``:
    ``S = [omega; -omega x q + h omega]`` (MR (3.71))."""
    return sp.Matrix.vstack(omega, -omega.cross(q) + h * omega)


def exp_twist(omega, v, theta) -> sp.Matrix:
    """``exp([S] theta)`` of the screw axis ``S = [omega; v]``, ``|omega| = 1`` (MR (3.88));
    the kernel's ``omega`` is validated unit at run time."""
    return expm(theta * hat(sp.Matrix.vstack(omega, v)), unit_axis=True)


def adjoint(Rm, p) -> sp.Matrix:
    """``[Ad_T]`` of ``T = (R, p)`` (MR (3.83))."""
    return Ad(transform(Rm, p))


# ------------------------------------------------------------------ rotations (MR 3.2)
@equation("mr:rodrigues", "Rodrigues' formula: exp([ω] θ) (MR (3.51))", section="so3")
def rodrigues() -> Statement:
    return Statement([Rel(R, I3 + sp.sin(theta) * Om + (1 - sp.cos(theta)) * Om**2)], ROT)


@equation("mr:rodrigues-sign", "Rodrigues' formula, sin term with the wrong sign",
          section="so3", expected="does-not-hold")
def rodrigues_sign() -> Statement:
    return Statement([Rel(R, I3 - sp.sin(theta) * Om + (1 - sp.cos(theta)) * Om**2)], ROT)


@equation("mr:exp-inverse", "exp(−[ω] θ) = exp([ω] θ)ᵀ", section="so3")
def exp_inverse() -> Statement:
    return Statement([Rel(expm(-theta * Om), expm(theta * Om).T)], ROT)


@equation("mr:axis-fixed", "The axis is fixed: R ω = ω", section="so3")
def axis_fixed() -> Statement:
    return Statement([Rel(R * om, om)], ROT)


@equation("mr:det", "det exp([ω] θ) = 1 (MLS (2.14))", section="so3")
def det_one() -> Statement:
    return Statement([Rel(Det(R), 1)], ROT)


@equation("mr:log-trace", "The log's angle: θ = acos((tr R − 1)/2) (MR (3.54))",
          section="so3", singular="θ = π (the axis is not unique)")
def log_trace() -> Statement:
    return Statement([Rel(theta_p, acos((trace(R) - 1) / 2))], ROT_P)


@equation("mr:log-axis", "The log's axis: [ω] = (R − Rᵀ)/(2 sin θ) (MR (3.53))",
          section="so3", singular="θ = 0 or π")
def log_axis() -> Statement:
    return Statement([Rel(Om, (R - R.T) / (2 * sp.sin(theta_p)))], ROT_P)


@equation("mr:logm", "The principal log: log R = [ω] θ (MR (3.53)-(3.54))", section="so3",
          singular="θ = 0 (0/0) or π (the axis up to sign)")
def log_principal() -> Statement:
    # on (-π, π) too: R(θ, ω) = R(-θ, -ω), so the log by |θ| about ±ω is [ω] θ
    return Statement([Rel(logm(R), theta * Om)], ROT)


@equation("mr:log-axis-half", "The log's axis with the ½ dropped", section="so3",
          expected="does-not-hold", singular="θ = 0 or π")
def log_axis_half() -> Statement:
    return Statement([Rel(Om, (R - R.T) / sp.sin(theta_p))], ROT_P)


@equation("mr:conjugate", "R [a] Rᵀ = [R a] (MR (3.30) property)", section="so3")
def conjugate() -> Statement:
    return Statement([Rel(Qs * cpm(a) * Qs.T, cpm(Qs * a))], {Qs: Q1, a: v})


@equation("mr:rate", "dR/dθ = [ω] R (MR (3.49))", section="so3")
def rate() -> Statement:
    return Statement([Rel(diff(R, theta), Om * R), Rel(R.T * diff(R, theta), Om, "body")],
                     ROT)


# ------------------------------------------------------------------ transforms (MR 3.3)
@equation("mr:transform-inverse", "T T⁻¹ = 1 (MR (3.64))", section="se3")
def transform_inv() -> Statement:
    return Statement([Rel(T * transform_inverse(T), I4)], MOTION)


@equation("mr:transform-inverse-sign", "T⁻¹ with +Rᵀ p", section="se3",
          expected="does-not-hold")
def transform_inv_sign() -> Statement:
    return Statement([Rel(transform(R.T, R.T * pv), transform_inverse(T))], {**MOTION, R: Q1})


@equation("mr:compose", "T₁ T₂ = (R₁ R₂, R₁ p₂ + p₁) (MR (3.63))", section="se3")
def compose() -> Statement:
    Qa, Qb, pa, pb = mat("R1"), mat("R2"), vec("p1"), vec("p2")
    return Statement([Rel(T1 * T2, transform(Qa * Qb, Qa * pb + pa))],
                     {**MOTION, Qa: Q1, Qb: Q2, pa: p1, pb: p2})


@equation("mr:Ad-conjugation", "[Ad_T V] = T [V] T⁻¹ (MR (3.83))", section="se3")
def ad_conjugation() -> Statement:
    return Statement([Rel(hat(Ad(T) * V), T * hat(V) * transform_inverse(T))], MOTION)


@equation("mr:Ad-product", "Ad of a product: Ad(T1 T2) = Ad(T1) Ad(T2) (MR (3.84))",
          section="se3")
def ad_product() -> Statement:
    return Statement([Rel(Ad(T1 * T2), Ad(T1) * Ad(T2))], MOTION)


@equation("mr:Ad-inverse", "Ad of an inverse: Ad(T⁻¹) Ad(T) = 1 (MR (3.84))",
          section="se3")
def ad_inverse() -> Statement:
    return Statement([Rel(Ad(transform_inverse(T)) * Ad(T), I6)], MOTION)


# ------------------------------------------------------------------ screws (MR 3.3.2)
@equation("mr:screw-pitch", "The pitch of a screw axis: h = ω·v_S (MR (3.71))",
          section="screws")
def screw_pitch() -> Statement:
    S = MS("S", 6, 1)
    return Statement([Rel((S[:3, :].T * S[3:, :])[0, 0], h)], {S: screw(w, q, h)})


@equation("mr:exp-G", "exp([S] θ) = (exp([ω] θ), G(θ) v) (MR (3.88))",
          section="screws")
def exp_g() -> Statement:
    S, vs = MS("S", 6, 1), vec("v")
    G = I3 * theta + (1 - sp.cos(theta)) * Om + (theta - sp.sin(theta)) * Om**2
    return Statement([Rel(expm(theta * hat(S)), transform(R, G * vs))],
                     {**ROT, S: sp.Matrix.vstack(w, v), vs: v})


@equation("mr:exp-pure-rotation", "A zero-pitch screw through q: exp = (R, (1 - R) q) "
          "(MLS (2.40))", section="screws")
def exp_pure_rotation() -> Statement:
    S = MS("S", 6, 1)
    return Statement([Rel(expm(theta * hat(S)), transform(R, (I3 - R) * qv))],
                     {**ROT, S: screw(w, q, 0), qv: q})


# ------------------------------------------------------------------ wrenches and brackets
@equation("mr:wrench-transfer", "Ad_Tᵀ F = [Rᵀ (m − p × f); Rᵀ f] (MR (3.98))",
          section="wrenches")
def wrench_transfer() -> Statement:
    m, f = vec("m"), vec("f")
    return Statement([Rel(Ad(T).T * Blocks([[m], [f]]),
                          Blocks([[Qs.T * (m - Cross(pv, f))], [Qs.T * f]]))],
                     {**MOTION, m: F1[:3, :], f: F1[3:, :]})


@equation("mr:power", "Power is frame-invariant: Vᵀ F = (Ad_T V)ᵀ (Ad_T⁻¹ᵀ F)",
          section="wrenches")
def power() -> Statement:
    return Statement([Rel(V.T * F, (Ad(T) * V).T * (Ad(transform_inverse(T)).T * F))],
                     MOTION)


@equation("mr:bracket", "The Lie bracket: [ad_V] W = vee([V][W] − [W][V]) (MR (8.38))",
          section="brackets")
def bracket() -> Statement:
    return Statement([Rel(ad(V) * W, vee(hat(V) * hat(W) - hat(W) * hat(V)))], MOTION)


@equation("mr:bracket-antisymmetric", "[ad_V] W = −[ad_W] V", section="brackets")
def bracket_antisymmetric() -> Statement:
    return Statement([Rel(ad(V) * W, -ad(W) * V)], MOTION)


@equation("mr:Ad-ad", "Ad_T [ad_V] Ad_T⁻¹ = [ad_(Ad_T V)]", section="brackets")
def ad_of_ad() -> Statement:
    return Statement([Rel(Ad(T) * ad(V) * Ad(transform_inverse(T)), ad(Ad(T) * V))], MOTION)


@equation("mr:ad-dual", "The dual bracket: (ad_V W)ᵀ F = −Wᵀ (ad*_V F)",
          section="brackets")
def ad_dual_pairing() -> Statement:
    return Statement([Rel((ad(V) * W).T * F, -(W.T * (ad_dual(V) * F)))], MOTION)


KERNELS = [
    Kernel(
        name="twist_exponential", summary="The transform exp([S] theta) of a screw axis.",
        formula="exp([S] theta) = [[exp([w] theta), G(theta) v], [0, 1]], MR (3.88)",
        ids=("mr:exp-G",), sources=(exp_twist,),
        args=(Arg("omega", (3,), "unit", "unit vector along the screw axis"),
              Arg("v", (3,), "any", "linear part of the screw axis [m]"),
              Arg("theta", (), "angle", "rotation about the axis [rad]")),
        outputs=(Out("T", (4, 4), "homogeneous transform"),),
        build=lambda omega, v, theta: {"T": exp_twist(omega, v, theta)}),
    Kernel(
        name="adjoint_matrix", summary="The adjoint [Ad_T] of a transform (R, p).",
        formula="[Ad_T] = [[R, 0], [[p] R, R]], MR (3.83)",
        ids=("mr:Ad-product", "mr:Ad-conjugation"), sources=(adjoint,),
        args=(Arg("R", (3, 3), "rotation", "rotation matrix"),
              Arg("p", (3,), "any", "translation [m]")),
        outputs=(Out("Ad", (6, 6), "adjoint matrix on twists [w; v]"),),
        build=lambda R, p: {"Ad": adjoint(R, p)}),
]
