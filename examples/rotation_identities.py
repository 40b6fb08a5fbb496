"""Rotation identities a robotics reader checks, from outside chapter 3 of Angeles' book.

Run ``rigidsym verify --module examples/rotation_identities.py``; generate its kernels with
``rigidsym generate --module examples/rotation_identities.py --out DIR``.

Each declaration returns the two sides of an identity: ``printed`` is the formula as it is
usually written (book symbols ``Q``, ``E``, ``e``, ``phi``, ...), ``model`` gives those
symbols their first-principles values (the rotation of Eq. (2.49):
``Q = e e^T + cos(phi) (1 - e e^T) + sin(phi) E``, ``E = cpm(e)``, ``|e| = 1``). Two forms
are misremembered on purpose (``expected="does-not-hold"``) and carry their corrected form.
"""

from __future__ import annotations

import sympy as sp

from rigidsym import (
    I3,
    Rel,
    Statement,
    angle,
    cpm,
    equation,
    mat,
    rigid_motion,
    rotation_from_euler_rodrigues,
    rotation_from_natural_invariants,
    trace,
    unit_vector,
    unit_vector4,
    vec,
    vect,
)
from rigidsym.codegen.spec import Arg, Kernel, Out

# constrained atoms: e . e = 1, cos^2 + sin^2 = 1, |eta| = 1 (imposed exactly by the checker)
e, phi = unit_vector("e"), angle("phi")
eta_a, eta_b = unit_vector4("eta_a"), unit_vector4("eta_b")
# book symbols, so that a printed form reads like the formula
Q, E, e_, r, r0 = mat("Q"), mat("E"), vec("e"), vec("r"), sp.Symbol("r_0", real=True)
MODEL = {Q: rotation_from_natural_invariants(e, phi), E: cpm(e), e_: e}


def rodrigues(e, phi) -> sp.Matrix:
    """Rodrigues' formula ``Q = 1 + sin(phi) E + (1 - cos(phi)) E^2``, ``E = cpm(e)``."""
    E = cpm(e)
    return sp.eye(3) + sp.sin(phi) * E + (1 - sp.cos(phi)) * E * E


def er_product(a, b) -> sp.Matrix:
    """Product of Euler-Rodrigues parameters ``[r; r0]`` (quaternion product, ``b`` first):
    ``[a0 b + b0 a + a x b; a0 b0 - a . b]``."""
    av, a0, bv, b0 = a[:3, :], a[3], b[:3, :], b[3]
    return sp.Matrix.vstack(a0 * bv + b0 * av + av.cross(bv),
                            sp.Matrix([a0 * b0 - av.dot(bv)]))


@equation("rot:rodrigues", "Rodrigues' rotation formula", section="rotations")
def rodrigues_formula() -> Statement:
    return Statement([Rel(Q, I3 + sp.sin(phi) * E + (1 - sp.cos(phi)) * E**2)], MODEL)


@equation("rot:rodrigues-sign", "Rodrigues' formula, sin term with the wrong sign",
          section="rotations", expected="does-not-hold",
          cause="misremembered: 1 - sin(phi) E + ... is Q^T, the rotation by -phi")
def rodrigues_sign_slip() -> Statement:
    return Statement([Rel(Q, I3 - sp.sin(phi) * E + (1 - sp.cos(phi)) * E**2)], MODEL,
                     corrected=[Rel(Q, I3 + sp.sin(phi) * E + (1 - sp.cos(phi)) * E**2)])


@equation("rot:proper-orthogonal", "Rodrigues' Q is proper orthogonal", section="rotations")
def proper_orthogonal() -> Statement:
    R = rodrigues(e, phi)
    return Statement([Rel(R.T * R, sp.eye(3), "Q^T Q"), Rel(R.det(), 1, "det Q")])


@equation("rot:trace", "Trace of a rotation", section="rotations")
def trace_of_rotation() -> Statement:
    return Statement([Rel(trace(Q), 1 + 2 * sp.cos(phi))], MODEL)


@equation("rot:axis-fixed", "The axis is fixed by the rotation", section="rotations")
def axis_is_fixed() -> Statement:
    return Statement([Rel(Q * e_, e_)], MODEL)


@equation("rot:cayley", "Cayley's form of a rotation", section="rotations",
          singular="phi = pi")
def cayley() -> Statement:
    t = sp.tan(phi / 2)
    return Statement([Rel(Q, (I3 - t * E) ** -1 * (I3 + t * E))], MODEL)


@equation("rot:axial-vector", "Axial vector of a rotation", section="rotations")
def axial_vector() -> Statement:
    return Statement([Rel(vect(Q), sp.sin(phi) * e_)], MODEL)


@equation("rot:euler-rodrigues", "Rotation from Euler-Rodrigues parameters",
          section="parameters")
def from_euler_rodrigues() -> Statement:
    form = (r0**2 - (r.T * r)[0]) * I3 + 2 * r * r.T + 2 * r0 * cpm(r)
    model = {**MODEL, r: sp.sin(phi / 2) * e, r0: sp.cos(phi / 2)}
    return Statement([Rel(Q, form)], model)


@equation("rot:euler-rodrigues-norm", "Euler-Rodrigues form with r0^2 + r.r",
          section="parameters", expected="does-not-hold",
          cause="misremembered: the isotropic term is r0^2 - r.r (it equals cos(phi))")
def er_norm_slip() -> Statement:
    model = {**MODEL, r: sp.sin(phi / 2) * e, r0: sp.cos(phi / 2)}
    R = 2 * r * r.T + 2 * r0 * cpm(r)
    return Statement([Rel(Q, (r0**2 + (r.T * r)[0]) * I3 + R)], model,
                     corrected=[Rel(Q, (r0**2 - (r.T * r)[0]) * I3 + R)])


@equation("rot:composition", "Composition as the product of Euler-Rodrigues parameters",
          section="parameters")
def composition() -> Statement:
    def rot(eta):
        return rotation_from_euler_rodrigues(eta[:3, :], eta[3])

    return Statement([Rel(rot(eta_a) * rot(eta_b), rot(er_product(eta_a, eta_b)))])


@equation("rot:rate", "Rate of a rotation: Q_dot = Omega Q", section="rates")
def rotation_rate() -> Statement:
    m = rigid_motion()
    return Statement([Rel(m.Q_dot, m.Omega * m.Q), Rel(m.Omega + m.Omega.T, sp.zeros(3),
                                                       "Omega is skew")])


KERNELS = [
    Kernel(
        name="rodrigues_rotation", summary="Rotation matrix by Rodrigues' formula.",
        formula="Q = 1 + sin(phi) E + (1 - cos(phi)) E^2, E = cpm(e)",
        ids=("rot:rodrigues",), sources=(rodrigues,),
        args=(Arg("e", (3,), "unit", "unit vector along the axis"),
              Arg("phi", (), "angle", "rotation angle [rad]")),
        outputs=(Out("Q", (3, 3), "rotation matrix"),),
        build=lambda e, phi: {"Q": rodrigues(e, phi)}),
    Kernel(
        name="compose_euler_rodrigues",
        summary="Euler-Rodrigues parameters of the composed rotation Q(eta_a) Q(eta_b).",
        formula="[a0 b + b0 a + a x b; a0 b0 - a . b]",
        ids=("rot:composition",), sources=(er_product,),
        args=(Arg("eta_a", (4,), "unit", "Euler-Rodrigues parameters [r; r0] of the first"),
              Arg("eta_b", (4,), "unit", "Euler-Rodrigues parameters [r; r0] of the second")),
        outputs=(Out("eta", (4,), "Euler-Rodrigues parameters of the product"),),
        build=lambda eta_a, eta_b: {"eta": er_product(eta_a, eta_b)}),
]
