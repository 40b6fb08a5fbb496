"""The kernel list of the code generator: which declared formula functions compose each kernel.

This module binds mathematics (it says which formula functions a kernel composes and how
their arguments are wired), so it lives in ``derivations/``; it declares no equation and is
not auto-imported as a section. It never restates a formula: every output is the return
value of a formula function from :mod:`rigidsym.algebra.primitives` or a ``derivations.sec3_*``
module.

Conventions (NOTATION.md): vectors (3,), matrices (3, 3) row-major, twists ``[omega; v]``,
wrenches ``[n; f]``, Plücker arrays ``[e; n]``, SI units.
"""

from __future__ import annotations

from functools import partial

import sympy as sp

from rigidsym.codegen.spec import Arg, Branch, Kernel, Out
from rigidsym.declare import rotation_from_natural_invariants

from .kernel_wiring import (
    _PR,
    _S5,
    _S5R,
    _S6,
    _S7,
    _S8,
    _S21,
    _S22,
    _S41,
    _S42,
    OMEGA,
    PHI,
    Q_ARG,
    E,
    _ni_common,
    _ni_near_pi,
    _ni_when,
    _one,
    _v,
    formula,
)
from .kernels_spec_internal import EULER_SEQUENCES, INTERNAL_KERNELS
from .kernels_spec_lie import LIE_KERNELS

__all__ = ["KERNELS", "formula", "EULER_SEQUENCES"]


# ----------------------------------------------------------------------------------------
# Sec. 2.3 / 3.2: rotations


def _rot_ni(e, phi):
    return {"Q": rotation_from_natural_invariants(e, phi)}


def _rot_er(eta):
    # normalised, as jaxlie and pytransform3d: (2.3) divided by eta . eta, a
    # rotation for every eta != 0; the book's form returned |eta|^2 Q, which the next
    # kernel's rotation check rejected at |eta| - 1 = 4e-9 (inside the unit tolerance)
    return {"Q": formula(_PR + "rotation_from_quaternion")(eta)}


def _ni_main(Q):
    v, s, c = _ni_common(Q)
    return {"e": v / s, "phi": sp.atan2(s, c)}


def _ni_identity_when(Q):
    # vect(Q) = 0 exactly (each pair of off-diagonal entries equal, compared without a
    # product, so nothing underflows) with cos phi > 0: phi = 0, Q = 1
    pairs = ((2, 1), (0, 2), (1, 0))
    return sp.And(Q.trace() > 1, *(sp.And(Q[i, j] <= Q[j, i], Q[i, j] >= Q[j, i])
                                   for i, j in pairs))


def _ni_identity(Q):
    # phi = 0 is known exactly; every unit axis is an axis of the identity (Q(e, 0) = 1 for
    # every e), so the axis is a documented default, e_x, and phi = 0 exactly says so
    return {"e": sp.Matrix([1, 0, 0]), "phi": sp.Integer(0)}


_NI_BRANCHES = tuple(
    Branch(f"near_pi_{k}", partial(_ni_when, k=k), partial(_ni_near_pi, k=k),
           doc=f"cos(phi) < -1/2 and Q[{k},{k}] is the largest diagonal entry: e from "
               f"column {k} of the symmetric part Q + Q^T - 2 cos(phi) 1 = 2 (1 - cos phi) "
               "e e^T, signed so that e . vect(Q) >= 0")
    for k in range(3)) + (
    Branch("identity", _ni_identity_when, _ni_identity,
           doc="vect(Q) = 0 and cos(phi) > 0 (Q = 1): phi = 0 exactly, the axis undetermined:"
               " the default e = [1, 0, 0]", default="e"),)

KERNELS: list[Kernel] = [
    Kernel(
        name="rotation_from_natural_invariants",
        summary="Rotation matrix from its natural invariants (e, phi).",
        formula="Q = e e^T + cos(phi) (1 - e e^T) + sin(phi) CPM(e)",
        ids=("2.49",), sources=(_PR + "rotation_from_natural_invariants",),
        args=(E, PHI), outputs=(Out("Q", (3, 3), "rotation matrix"),), build=_rot_ni,
    ),
    Kernel(
        name="rotation_from_euler_rodrigues",
        summary="Rotation matrix from the Euler-Rodrigues parameters eta = [r; r0].",
        formula="Q = ((r0^2 - r.r) 1 + 2 r r^T + 2 r0 CPM(r)) / (r.r + r0^2)",
        ids=("2.3",), sources=(_PR + "rotation_from_quaternion",),
        singular="eta = 0 (no rotation)",
        args=(Arg("eta", (4,), "unit", "Euler-Rodrigues parameters [r1, r2, r3, r0]"),),
        outputs=(Out("Q", (3, 3), "rotation matrix"),), build=_rot_er,
    ),
    Kernel(
        name="natural_invariants_from_rotation",
        summary="Natural invariants (e, phi) of a rotation matrix, phi in [0, pi].",
        formula="phi = atan2(||vect(Q)||, (tr Q - 1)/2), e = vect(Q)/||vect(Q)||; for "
                "cos phi < -1/2, e from the symmetric part of Q (never acos)",
        ids=("2.49", "3.95"), sources=(_PR + "vect", _PR + "trace"),
        args=(Q_ARG,), outputs=(Out("e", (3,), "unit axis"), Out("phi", (), "angle [rad]")),
        build=_ni_main, branches=_NI_BRANCHES,
        singular="vect(Q) != 0 with ||vect(Q)||^2 below the type's range (phi under about "
                 "1e-154 in float64, 1e-19 in float32): the axis's direction is lost",
        singular_arg="Q",
        notes="At Q = 1 (vect(Q) = 0 exactly, cos phi > 0) phi = 0 exactly and the axis, "
              "which every unit vector is there, is the default e = [1, 0, 0]: phi == 0 "
              "exactly says the axis is the default (the C target's status has "
              "RIGIDSYM_C_DEFAULT_OUTPUT). For an exactly symmetric Q (phi = pi) the sign of "
              "e is fixed by the rule: the "
              "component of e of largest magnitude is positive (e is taken from the column "
              "of the largest diagonal entry of Q); near pi, the skew part of Q fixes the "
              "sign, as in Pinocchio's log3.",
    ),
]


def _screw_axis_point(e, phi, a, a_prime):
    Q = rotation_from_natural_invariants(e, phi)
    return {"p0": formula(_S21 + "screw_axis_point")(Q, a, a_prime, phi)}


def _isa(omega, a, a_dot):
    return {"p0": formula(_S41 + "instant_screw_axis_point")(omega, a, a_dot),
            "pitch": formula(_S41 + "instant_screw_pitch")(omega, a_dot),
            "plucker": formula(_S41 + "instant_screw_plucker")(omega, a, a_dot)}


def _wrench_axis(w_A, a):
    n_A, f = w_A[:3, :], w_A[3:, :]
    p0 = formula(_S7 + "wrench_axis_point")(n_A, f, a)
    return {"p0": p0, "pitch": formula(_S7 + "wrench_pitch")(n_A, f),
            "plucker": formula(_S22 + "plucker_from_points")(p0, p0 + f)}


_RATE_ARGS = (E, PHI)
_RATE_DOT_ARGS = (E, PHI, OMEGA)
_NL = {"N": "phi = 0 (mod 2 pi): the axis is undefined",
       "L": "", "H": "",
       "N_tilde": "", "L_tilde": "1 + cos(phi) = 0 (phi = pi)", "H_tilde": ""}

#: the rates add e_dot, undefined where the axis is: N_tilde_dot divides by sin(phi/2)
_NL_DOT = dict(_NL, N_tilde="phi = 0 (mod 2 pi): the axis, and so its rate, is undefined")


def _rate_kernels() -> list[Kernel]:
    ks = []
    for base in ("N", "L", "H"):
        for tilde in (False, True):
            key = base + ("_tilde" if tilde else "")
            fn = f"{base}_tilde" if tilde else f"{base}_matrix"
            shape = (3, 4) if tilde else (4, 3)
            what = {"N": "natural invariants [e; phi]", "L": "linear invariants [u; u0]",
                    "H": "Euler-Rodrigues parameters [r; r0]"}[base]
            summ = (f"Left inverse of the rate matrix of the {what}: omega = {fn} rate."
                    if tilde else f"Rate matrix of the {what}: rate = {fn} omega.")
            ks.append(Kernel(
                name=fn, summary=summ, formula=f"{fn}(e, phi), {shape[0]}x{shape[1]}",
                ids=("3.77",) if tilde else ("3.76",), sources=(_S42 + fn,),
                args=_RATE_ARGS, outputs=(Out(fn, shape, ""),), build=_one(fn, _S42 + fn),
                singular=_NL[key], singular_arg="phi" if _NL[key] else ""))
            ks.append(Kernel(
                name=fn + "_dot", summary=f"Time derivative of {fn} along omega.",
                formula=f"d/dt {fn}(e(t), phi(t)) with e_dot, phi_dot from omega "
                        "(the corrected form where the printed one does not hold)",
                ids=("3.97",) if tilde else ("3.96",), sources=(_S5R + fn + "_dot",),
                args=_RATE_DOT_ARGS, outputs=(Out(fn + "_dot", shape, "[1/s]"),),
                build=_one(fn + "_dot", _S5R + fn + "_dot"),
                singular=_NL_DOT[key], singular_arg="phi" if _NL_DOT[key] else ""))
    return ks


KERNELS += [
    Kernel(
        name="screw_axis_point", summary="Point of the screw axis closest to the origin.",
        formula="p0 = (Q - 1)^T (Q a - a') / (2 (1 - cos phi)), Q from (e, phi) by (2.49)",
        ids=("3.18", "2.49"), sources=(_PR + "rotation_from_natural_invariants",
                                      _S21 + "screw_axis_point"),
        args=(E, PHI, _v("a", "body point before the displacement [m]"),
              _v("a_prime", "the same point after the displacement [m]")),
        outputs=(Out("p0", (3,), "point of the axis closest to the origin [m]"),),
        build=_screw_axis_point, singular="phi = 0 (pure translation)", singular_arg="phi"),
    Kernel(
        name="plucker_from_points", summary="Plücker array of the line through two points.",
        formula="kappa = [e; p1 x e], e = (p2 - p1)/||p2 - p1||",
        ids=("3.21", "3.22", "3.23"), sources=(_S22 + "plucker_from_points",),
        args=(_v("p1", "first point [m]"), _v("p2", "second point [m]")),
        outputs=(Out("kappa", (6,), "[e; n] (n in m)"),),
        build=_one("kappa", _S22 + "plucker_from_points"),
        singular="p1 = p2", singular_arg="p2"),
    Kernel(
        name="plucker_transfer", summary="Plücker array of a line referred to point B.",
        formula="kappa_B = U(a, b) kappa_A", ids=("3.29",),
        sources=(_S22 + "plucker_transfer",),
        args=(Arg("kappa_A", (6,), "any", "Plücker array [e; n_A]"),
              _v("a", "point A [m]"), _v("b", "point B [m]")),
        outputs=(Out("kappa_B", (6,), "[e; n_B]"),),
        build=_one("kappa_B", _S22 + "plucker_transfer")),
    Kernel(
        name="instant_screw_axis",
        summary="Instant screw axis of a twist: point, pitch and Plücker array.",
        formula="p0' = omega x (a_dot - omega x a)/||omega||^2, pitch' = a_dot.omega/"
                "||omega||^2, kappa = [e'; p0' x e']",
        ids=("3.53", "3.54", "3.55", "3.70"),
        sources=(_S41 + "instant_screw_axis_point", _S41 + "instant_screw_pitch",
                 _S41 + "instant_screw_plucker"),
        args=(OMEGA, _v("a", "body point A [m]"), _v("a_dot", "velocity of A [m/s]")),
        outputs=(Out("p0", (3,), "ISA point closest to the origin [m]"),
                 Out("pitch", (), "pitch [m/rad]"), Out("plucker", (6,), "[e'; n']")),
        build=_isa, singular="omega = 0 (pure translation)", singular_arg="omega"),
    Kernel(
        name="wrench_axis", summary="Axis of a wrench: point, pitch and Plücker array.",
        formula="p0'' = f x (n_A - f x a) / (f.f) per (3.109)-(3.111), kappa through p0'' along f",
        ids=("3.109", "3.110", "3.111"),
        sources=(_S7 + "wrench_axis_point", _S7 + "wrench_pitch",
                 _S22 + "plucker_from_points"),
        args=(Arg("w_A", (6,), "any", "wrench [n_A; f] at A [N m; N]"),
              _v("a", "point A [m]")),
        outputs=(Out("p0", (3,), "wrench-axis point closest to the origin [m]"),
                 Out("pitch", (), "pitch [m]"), Out("plucker", (6,), "[e''; n'']")),
        build=_wrench_axis, singular="f = 0 (pure moment)", singular_arg="w_A"),
    Kernel(
        name="twist_transfer", summary="Twist at P from the twist at A (same body).",
        formula="t_P = U(a, p) t_A, U = [[1, O], [A - P, 1]]", ids=("3.83",),
        sources=(_S42 + "twist_transfer",),
        args=(Arg("t_A", (6,), "any", "twist [omega; v_A] [rad/s; m/s]"),
              _v("a", "point A [m]"), _v("p", "point P [m]")),
        outputs=(Out("t_P", (6,), "[omega; v_P]"),), build=_one("t_P", _S42 + "twist_transfer")),
    Kernel(
        name="twist_transfer_matrix", summary="Twist-transfer matrix U (6x6).",
        formula="U = [[1, O], [A - P, 1]]", ids=("3.83",),
        sources=(_S42 + "twist_transfer_matrix",),
        args=(_v("a", "point A [m]"), _v("p", "point P [m]")),
        outputs=(Out("U", (6, 6), ""),), build=_one("U", _S42 + "twist_transfer_matrix")),
    Kernel(
        name="wrench_transfer", summary="Wrench at P from the wrench at A.",
        formula="w_P = V(a, p) w_A", ids=("3.119",), sources=(_S7 + "wrench_transfer",),
        args=(Arg("w_A", (6,), "any", "wrench [n_A; f] [N m; N]"),
              _v("a", "point A [m]"), _v("p", "point P [m]")),
        outputs=(Out("w_P", (6,), "[n_P; f]"),), build=_one("w_P", _S7 + "wrench_transfer")),
    Kernel(
        name="wrench_transfer_matrix", summary="Wrench-transfer matrix V (6x6).",
        formula="V = [[1, A - P], [O, 1]]", ids=("3.119",),
        sources=(_S7 + "wrench_transfer_matrix",),
        args=(_v("a", "point A [m]"), _v("p", "point P [m]")),
        outputs=(Out("V", (6, 6), ""),), build=_one("V", _S7 + "wrench_transfer_matrix")),
    *_rate_kernels(),
    Kernel(
        name="point_acceleration", summary="Acceleration of a body point P.",
        formula="p_ddot = a_ddot + (Omega_dot + Omega^2)(p - a)", ids=("3.89",),
        sources=(_S5 + "point_acceleration",),
        args=(_v("a_ddot", "acceleration of A [m/s^2]"), OMEGA,
              _v("omega_dot", "angular acceleration [rad/s^2]"), _v("p", "point P [m]"),
              _v("a", "point A [m]")),
        outputs=(Out("p_ddot", (3,), "[m/s^2]"),),
        build=_one("p_ddot", _S5 + "point_acceleration")),
    Kernel(
        name="moving_frame_acceleration",
        summary="Acceleration of a point in the fixed frame from moving-frame data.",
        formula="[p_ddot]_F = o_ddot + Q(rho_ddot + 2 omega x rho_dot + omega_dot x rho + "
                "omega x (omega x rho)) (Coriolis term included)", ids=("3.105",),
        sources=(_S6 + "moving_frame_acceleration",),
        args=(_v("o_ddot", "acceleration of the moving origin [m/s^2]"), Q_ARG,
              _v("omega", "angular velocity of the moving frame, M-frame components"),
              _v("omega_dot", "angular acceleration, M-frame components"),
              _v("rho_M", "position in M [m]"), _v("rho_dot_M", "velocity in M [m/s]"),
              _v("rho_ddot_M", "acceleration in M [m/s^2]")),
        outputs=(Out("p_ddot", (3,), "[m/s^2], F-frame"),),
        build=_one("p_ddot", _S6 + "moving_frame_acceleration")),
    Kernel(
        name="inertia_at_point", summary="Moment of inertia about a point A.",
        formula="I_A = I_C - m CPM(a - c)^2", ids=("3.133",), sources=(_S8 + "inertia_at_point",),
        args=(Arg("I_C", (3, 3), "any", "inertia at the mass centre [kg m^2]"),
              Arg("m", (), "any", "mass [kg]"), _v("c", "mass centre [m]"),
              _v("a", "point A [m]")),
        outputs=(Out("I_A", (3, 3), "[kg m^2]"),), build=_one("I_A", _S8 + "inertia_at_point")),
    Kernel(
        name="inertia_dyad_at_point", summary="Inertia dyad M_A (6x6) at point A.",
        formula="M_A per (3.147)", ids=("3.147",), sources=(_S8 + "inertia_dyad_at_point",),
        args=(Arg("I_C", (3, 3), "any", "inertia at the mass centre [kg m^2]"),
              Arg("m", (), "any", "mass [kg]"), _v("c", "mass centre [m]"),
              _v("a", "point A [m]")),
        outputs=(Out("M_A", (6, 6), ""),), build=_one("M_A", _S8 + "inertia_dyad_at_point")),
    Kernel(
        name="newton_euler_wrench", summary="Newton-Euler wrench [n_C; f] of a rigid body.",
        formula="n_C = I_C omega_dot + omega x I_C omega, f = m c_ddot",
        ids=("3.134", "3.139"), sources=(_S8 + "newton_euler_wrench",),
        args=(Arg("I_C", (3, 3), "any", "inertia at the mass centre [kg m^2]"),
              Arg("m", (), "any", "mass [kg]"), OMEGA,
              _v("omega_dot", "angular acceleration [rad/s^2]"),
              _v("c_ddot", "acceleration of the mass centre [m/s^2]")),
        outputs=(Out("w", (6,), "[n_C; f] [N m; N]"),),
        build=_one("w", _S8 + "newton_euler_wrench")),
    Kernel(
        name="kinetic_energy", summary="Kinetic energy of a rigid body.",
        formula="T = 1/2 m c_dot.c_dot + 1/2 omega^T I_C omega", ids=("3.145",),
        sources=(_S8 + "kinetic_energy",),
        args=(Arg("I_C", (3, 3), "any", "inertia at the mass centre [kg m^2]"),
              Arg("m", (), "any", "mass [kg]"), OMEGA,
              _v("c_dot", "velocity of the mass centre [m/s]")),
        outputs=(Out("T", (), "[J]"),), build=_one("T", _S8 + "kinetic_energy")),
]


# ----------------------------------------------------------------------------------------
# The screw of a finite displacement from (Q, a, a'): natural invariants (with the near-pi
# branches), the axis point (3.18), the pitch (3.7) and the Plücker array of the axis.


def _screw_of_displacement(Q, a, a_prime, ni):
    e, phi = ni["e"], ni["phi"]
    # (3.18) needs cos(phi) only: with phi_c = acos((tr Q - 1)/2), cos(phi_c) is
    # (tr Q - 1)/2 identically, so no trigonometric call and no acos is evaluated.
    # (3.18) needs only cos(phi) = (tr Q - 1)/2, i.e. 1 - cos(phi) = ((1 - Q_00) + (1 - Q_11)
    # + (1 - Q_22))/2: each 1 - Q_ii is exact in floating point near phi = 0 (Sterbenz), so
    # the sum keeps full relative accuracy where 3 - tr Q would cancel. UnevaluatedExpr keeps
    # that grouping through sympy's Add; no trigonometric call is needed.
    ph, half = sp.Symbol("screw_phi", real=True), sp.Symbol("screw_half_omc", real=True)
    p0 = formula(_S21 + "screw_axis_point")(Q, a, a_prime, ph)
    p0 = p0.xreplace({sp.cos(ph): 1 - half})
    if p0.has(ph):
        raise ValueError("screw_axis_point: expected a function of cos(phi) only")
    one_minus = sp.Add(*[sp.UnevaluatedExpr(1 - Q[i, i]) for i in range(3)])
    p0 = p0.xreplace({half: one_minus / 2})
    pitch = formula(_S21 + "pitch_of_displacement")(e, a_prime - a, phi)
    kappa = formula(_S22 + "plucker_from_points")(p0, p0 + e)
    return {"e": e, "phi": phi, "p0": p0, "pitch": pitch, "plucker": kappa}


def _sod_main(Q, a, a_prime):
    return _screw_of_displacement(Q, a, a_prime, _ni_main(Q))


def _sod_near_pi(Q, a, a_prime, k):
    return _screw_of_displacement(Q, a, a_prime, _ni_near_pi(Q, k))


def _sod_when(Q, a, a_prime, k):
    return _ni_when(Q, k)


def _sod_identity_when(Q, a, a_prime):
    return _ni_identity_when(Q)


def _sod_identity(Q, a, a_prime):
    # Q = 1: phi = 0 is known exactly (as natural_invariants_from_rotation); the displacement
    # is a pure translation by a' - a (or none), which has no axis, no axis point and an
    # infinite (or 0/0) pitch: those hold documented finite defaults, e = [1, 0, 0],
    # p0 = 0, pitch = 0 and kappa = [e; p0 x e], and phi == 0 exactly says so
    return {"e": sp.Matrix([1, 0, 0]), "phi": sp.Integer(0), "p0": sp.zeros(3, 1),
            "pitch": sp.Integer(0), "plucker": sp.Matrix([1, 0, 0, 0, 0, 0])}


KERNELS.append(Kernel(
    name="screw_of_displacement",
    summary="Screw of a finite displacement: axis, angle, axis point, pitch, Plücker array.",
    formula="(e, phi) from Q as natural_invariants_from_rotation; p0 = (Q - 1)^T (Q a - a')"
            " / ((1 - Q_00) + (1 - Q_11) + (1 - Q_22));"
            " pitch = e^T (a' - a) / phi; kappa = [e; p0 x e]",
    ids=("3.7", "3.18", "3.23"),
    sources=(_PR + "vect", _PR + "trace", _S21 + "screw_axis_point",
             _S21 + "pitch_of_displacement", _S22 + "plucker_from_points"),
    args=(Q_ARG, _v("a", "body point before the displacement [m]"),
          _v("a_prime", "the same point after the displacement [m]")),
    outputs=(Out("e", (3,), "unit axis"), Out("phi", (), "angle [rad], in [0, pi]"),
             Out("p0", (3,), "axis point closest to the origin [m]"),
             Out("pitch", (), "pitch [m/rad]"), Out("plucker", (6,), "[e; p0 x e]")),
    build=_sod_main,
    branches=tuple(Branch(f"near_pi_{k}", partial(_sod_when, k=k),
                          partial(_sod_near_pi, k=k), doc=_NI_BRANCHES[k].doc)
                   for k in range(3)) + (
        Branch("identity", _sod_identity_when, _sod_identity,
               doc="vect(Q) = 0 and cos(phi) > 0 (Q = 1): phi = 0 exactly; a pure translation"
                   " has no axis, axis point or finite pitch: the defaults e = [1, 0, 0], "
                   "p0 = 0, pitch = 0, plucker = [1, 0, 0, 0, 0, 0]",
               default="e, p0, pitch, plucker"),),
    singular="Q != 1 with ||Q - Q^T||^2 below the type's range (phi under about 1e-154 in "
             "float64, 1e-19 in float32) or exactly symmetric with tr Q > -1: the axis is "
             "lost in the type",
    singular_arg="Q",
    notes="At Q = 1 (vect(Q) = 0 exactly, cos phi > 0: a pure translation by a' - a, or "
          "none) phi = 0 exactly and the outputs it leaves undetermined hold documented "
          "defaults: e = [1, 0, 0], p0 = 0, pitch = 0 (the pitch of a pure translation is "
          "infinite), plucker = [1, 0, 0, 0, 0, 0]; phi == 0 exactly says they are the "
          "defaults (the C target's status has RIGIDSYM_C_DEFAULT_OUTPUT). "
          "For an exactly symmetric Q (phi = pi) the sign of e follows "
          "natural_invariants_from_rotation's rule (largest-magnitude component positive)."))

KERNELS += INTERNAL_KERNELS
# the Lie-group maps (derivations/kernels_spec_lie.py)
KERNELS += LIE_KERNELS
