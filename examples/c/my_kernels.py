"""A firmware team's own kernels for the C example (examples/c/README.md): a unit
quaternion's rotation matrix, a planar two-link arm's tip position (its Jacobian is the
generated twin), and a rigid body's kinetic energy.

Generate the C with ``rigidsym generate --target cpp --module examples/c/my_kernels.py
--kernel ... --out examples/c/rigidsym_c`` (the command of examples/c/README.md).
"""

from __future__ import annotations

import sympy as sp

from rigidsym.codegen.spec import Arg, Kernel, Out


def quaternion_rotation(q):
    """Rotation matrix of the unit quaternion q = (w, x, y, z) (Euler-Rodrigues)."""
    w, x, y, z = q
    return sp.Matrix([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def planar_arm_tip(q1, q2, l1, l2):
    """Tip position of a planar arm of two revolute joints."""
    return sp.Matrix([l1 * sp.cos(q1) + l2 * sp.cos(q1 + q2),
                      l1 * sp.sin(q1) + l2 * sp.sin(q1 + q2)])


def kinetic_energy(m, v, inertia, omega):
    """T = m |v|^2 / 2 + omega^T I omega / 2 (I about the mass centre)."""
    return (m * (v.T * v)[0, 0] + (omega.T * inertia * omega)[0, 0]) / 2


KERNELS = [
    Kernel(name="quaternion_rotation", summary="Rotation matrix of a unit quaternion.",
           formula="Q = (w^2 - x.x) 1 + 2 x x^T + 2 w CPM(x)", ids=("fw:quat",),
           sources=(quaternion_rotation,),
           args=(Arg("q", (4,), "unit", "unit quaternion (w, x, y, z), scalar first"),),
           outputs=(Out("Q", (3, 3), "rotation matrix (body to world)"),),
           build=lambda q: {"Q": quaternion_rotation(q)}),
    Kernel(name="planar_arm_tip", summary="Tip position of a planar two-link arm.",
           formula="p = l1 (cos q1, sin q1) + l2 (cos(q1+q2), sin(q1+q2))",
           ids=("fw:arm",), sources=(planar_arm_tip,),
           args=(Arg("q1", (), "any", "shoulder angle [rad]"),
                 Arg("q2", (), "any", "elbow angle [rad]"),
                 Arg("l1", (), "any", "upper link length [m]"),
                 Arg("l2", (), "any", "lower link length [m]")),
           outputs=(Out("p", (2,), "tip position in the base frame [m]"),),
           build=lambda q1, q2, l1, l2: {"p": planar_arm_tip(q1, q2, l1, l2)}),
    Kernel(name="body_energy", summary="Kinetic energy of a rigid body.",
           formula="T = m v.v / 2 + omega.I omega / 2", ids=("fw:energy",),
           sources=(kinetic_energy,),
           args=(Arg("m", (), "any", "mass [kg]"),
                 Arg("v", (3,), "any", "velocity of the mass centre [m/s]"),
                 Arg("inertia", (3, 3), "any", "inertia matrix about the mass centre [kg m^2]"),
                 Arg("omega", (3,), "any", "angular velocity [rad/s]")),
           outputs=(Out("T", (), "kinetic energy [J]"),),
           build=lambda m, v, inertia, omega: {"T": kinetic_energy(m, v, inertia, omega)}),
]
