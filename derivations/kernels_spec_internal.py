"""Kernels of the list that are not public functions of :mod:`rigidsym.kernels`: the
Euler-angle rate kernels of Exercise 3.10, one per (sequence, frame), dispatched by name by
``euler_rate_matrix`` / ``euler_angle_rates``, and the benchmark kernels K4 and K6.
"""

from __future__ import annotations

import importlib

import sympy as sp

from rigidsym.codegen.spec import Arg, Branch, Kernel, Out

from .kernel_wiring import _EX10, _S8, _S41, OMEGA, _v, formula

__all__ = ["EULER_SEQUENCES", "INTERNAL_KERNELS"]

INTERNAL_KERNELS: list[Kernel] = []

# ----------------------------------------------------------------------------------------
# Exercise 3.10: Euler-angle rates, one kernel per (sequence, frame); dispatched by name.
# The twelve intrinsic sequences are the exercise's (one list, in ex3_10.py).
EULER_SEQUENCES = tuple(importlib.import_module(_EX10[:-1]).SEQUENCES)


def _euler_W(angles, seq, frame):
    ex = importlib.import_module(_EX10[:-1])
    W = ex.euler_rate_matrix(seq, frame)
    return W.xreplace(dict(zip(list(ex.ETA), list(angles), strict=True)))


def _euler_rates(angles, omega, seq, frame):
    W = _euler_W(angles, seq, frame)
    det = sp.trigsimp(W.det())
    adj = W.adjugate().applyfunc(sp.trigsimp)
    return {"eta_dot": adj * omega / det}


def _angles_arg(seq: str) -> Arg:
    """The angles, said as the C headers need it (an outside trial found "ZYX" alone
    ambiguous): intrinsic, Q the product of the three elementary rotations in order."""
    q = " ".join(f"R{axis.lower()}(angles[{i}])" for i, axis in enumerate(seq))
    return Arg("angles", (3,), "any", f"intrinsic {seq} Euler angles [rad]: Q = {q}")


def _omega_arg(frame: str) -> Arg:
    return Arg("omega", (3,), "any", f"angular velocity [rad/s] in {frame}-frame coordinates")


for _seq in EULER_SEQUENCES:
    for _frame in ("fixed", "body"):
        _tag = f"{_seq.lower()}_{_frame}"
        INTERNAL_KERNELS.append(Kernel(
            name=f"euler_rate_matrix_{_tag}", public=False,
            summary=f"Euler-angle rate matrix W ({_seq}, omega in the {_frame} frame).",
            formula="omega = W eta_dot", ids=("ex3.10",),
            sources=(_EX10 + "euler_rate_matrix",),
            args=(_angles_arg(_seq),),
            outputs=(Out("W", (3, 3), ""),),
            build=lambda angles, _s=_seq, _f=_frame: {"W": _euler_W(angles, _s, _f)}))
        INTERNAL_KERNELS.append(Kernel(
            name=f"euler_angle_rates_{_tag}", public=False,
            summary=f"Euler-angle rates from omega ({_seq}, {_frame} frame).",
            formula="eta_dot = W^-1 omega = adj(W) omega / det(W)", ids=("ex3.10",),
            sources=(_EX10 + "euler_rate_matrix",),
            args=(_angles_arg(_seq), _omega_arg(_frame)),
            outputs=(Out("eta_dot", (3,), "[rad/s]"),),
            build=lambda angles, omega, _s=_seq, _f=_frame: _euler_rates(angles, omega, _s, _f),
            singular="det W = 0 (gimbal lock)", singular_arg="angles",
            # no generated Jacobian: its build (trigsimp of adj W and det W) dominates the
            # generation time; d eta_dot = W^-1 (d omega - dW eta_dot) from W's Jacobian
            jacobian=False))


# ----------------------------------------------------------------------------------------
# The Euler angles of a rotation (the inverse of Exercise 3.10's Q(angles)), one kernel per
# sequence, both branches and the gimbal-lock flag; dispatched by euler_angles_from_rotation.
_EA = "rigidsym.derivations.euler_angles."


def _euler_angles(Q, seq):
    f = formula(_EA + "euler_angles_from_rotation")
    return {"angles": f(seq, Q, 1), "angles_other": f(seq, Q, -1), "gimbal_lock": sp.S.Zero}


def _euler_angles_lock(Q, seq):
    a = formula(_EA + "euler_angles_at_gimbal_lock")(seq, Q)
    return {"angles": a, "angles_other": a, "gimbal_lock": sp.S.One}


def _euler_lock_when(Q, seq):
    As, Ac = formula(_EA + "lock_pair")(seq, Q)
    # exactly 0 both: every atan2 of the main build would be atan2(0, 0); |x| <= 0 is x == 0
    return sp.And(sp.Abs(As) <= 0, sp.Abs(Ac) <= 0)


for _seq in EULER_SEQUENCES:
    _q = " ".join(f"R{axis.lower()}(angles[{i}])" for i, axis in enumerate(_seq))
    INTERNAL_KERNELS.append(Kernel(
        name=f"euler_angles_from_rotation_{_seq.lower()}", public=False,
        summary=f"Intrinsic {_seq} Euler angles of a rotation, both branches, and the "
                "gimbal-lock flag.",
        formula=f"Q = {_q}; a = atan2(A_s, A_c), b by atan2 against rho = |(A_s, A_c)|, c "
                "= atan2 of rho R_i(a)^T Q's row j; at the lock (A_s = A_c = 0) c = 0",
        ids=("ex3.10",),
        sources=(_EA + "euler_angles_from_rotation", _EA + "euler_angles_at_gimbal_lock"),
        args=(Arg("Q", (3, 3), "rotation", "rotation matrix (proper orthogonal)"),),
        outputs=(Out("angles", (3,), f"[a, b, c] [rad], Q = {_q}, the principal branch "
                     "(cos b >= 0 Tait-Bryan, sin b >= 0 proper Euler)"),
                 Out("angles_other", (3,), "[rad], the other branch (a + pi, pi - b or "
                     "-b, c + pi), the same as angles at the lock"),
                 Out("gimbal_lock", (), "1 at the gimbal lock (angles: the member c = 0 of "
                     "the family), else 0")),
        build=lambda Q, _s=_seq: _euler_angles(Q, _s),
        branches=(Branch("gimbal_lock", lambda Q, _s=_seq: _euler_lock_when(Q, _s),
                         lambda Q, _s=_seq: _euler_angles_lock(Q, _s),
                         doc="the first angle's pair of entries is exactly 0: only a + c "
                             "(or a - c) is defined; the member c = 0 and the flag"),),
        notes="Near the lock a and c alone are ill-conditioned (kappa ~ 1/rho); Q(angles) "
              "keeps Q to the rounding there: c is computed from a.",
        jacobian=False))


def _isa_point_pitch(omega, a, a_dot):
    return {"p0": formula(_S41 + "instant_screw_axis_point")(omega, a, a_dot),
            "pitch": formula(_S41 + "instant_screw_pitch")(omega, a_dot)}


INTERNAL_KERNELS.append(Kernel(
    name="instant_screw_point_pitch", public=False,
    summary="Instant screw axis point and pitch (no Plücker array; benchmark kernel K4).",
    formula="p0' = omega x (a_dot - omega x a)/||omega||^2, pitch' = a_dot.omega/||omega||^2",
    ids=("3.53", "3.70"),
    sources=(_S41 + "instant_screw_axis_point", _S41 + "instant_screw_pitch"),
    args=(OMEGA, _v("a", "body point A [m]"), _v("a_dot", "velocity of A [m/s]")),
    outputs=(Out("p0", (3,), "ISA point closest to the origin [m]"),
             Out("pitch", (), "pitch [m/rad]")),
    build=_isa_point_pitch, singular="omega = 0 (pure translation)", singular_arg="omega",
    jacobian=False))


def _newton_euler_residual(I_C, m, omega, omega_dot, c_ddot, n, f):
    w = formula(_S8 + "newton_euler_wrench")(I_C, m, omega, omega_dot, c_ddot)
    return {"r": sp.Matrix(w) - sp.Matrix.vstack(n, f)}


INTERNAL_KERNELS.append(Kernel(
    name="newton_euler_residual", public=False,
    summary="Residual of the Newton-Euler equations, w - [n; f] (benchmark kernel K6).",
    formula="r = [I_C omega_dot + omega x I_C omega - n; m c_ddot - f]",
    ids=("3.134", "3.139"), sources=(_S8 + "newton_euler_wrench",),
    args=(Arg("I_C", (3, 3), "any", "inertia at the mass centre [kg m^2]"),
          Arg("m", (), "any", "mass [kg]"), OMEGA,
          _v("omega_dot", "angular acceleration [rad/s^2]"),
          _v("c_ddot", "acceleration of the mass centre [m/s^2]"),
          _v("n", "applied moment about C [N m]"), _v("f", "applied force [N]")),
    outputs=(Out("r", (6,), "[N m; N]"),), build=_newton_euler_residual, jacobian=False))
