"""The kernel list of the code generator: which declared formula functions compose each kernel.

This module binds mathematics (it says which formula functions a kernel composes and how
their arguments are wired), so it lives in ``derivations/``; it declares no equation and is
not auto-imported as a section. It never restates a formula: every output is the return
value of a formula function from :mod:`rigidsym.primitives` or a ``derivations.sec3_*``
module. A kernel whose formula function is not importable is skipped by the generator with
a note (see :func:`missing_sources`).

Conventions (NOTATION.md): vectors (3,), matrices (3, 3) row-major, twists ``[omega; v]``,
wrenches ``[n; f]``, Plücker arrays ``[e; n]``, SI units.
"""

from __future__ import annotations

import importlib
from functools import partial

import sympy as sp

from rigidsym.codegen.spec import Arg, Branch, Kernel, Out
from rigidsym.primitives import cpm, rotation_from_natural_invariants, trace, vect

__all__ = ["KERNELS", "formula", "missing_sources", "EULER_SEQUENCES"]


def formula(dotted: str):
    """The formula function named ``module.function`` (imported lazily)."""
    mod, _, fn = dotted.rpartition(".")
    return getattr(importlib.import_module(mod), fn)


def missing_sources(kernel: Kernel) -> list[str]:
    """The formula functions of ``kernel`` that are not importable yet (sorted)."""
    missing = []
    for s in kernel.sources:
        try:
            formula(s)
        except (ImportError, AttributeError):
            missing.append(s)
    return sorted(missing)


def _col(v, n: int | None = None) -> sp.Matrix:
    m = sp.Matrix(v)
    return m.reshape(len(m), 1) if n is None else m.reshape(n, 1)


def _scalar(x) -> sp.Expr:
    if isinstance(x, sp.MatrixBase):
        if x.shape != (1, 1):
            raise ValueError(f"expected a scalar, got shape {x.shape}")
        return x[0, 0]
    return sp.sympify(x)


# ----------------------------------------------------------------------------------------
# common arguments
E = Arg("e", (3,), "unit", "unit vector along the rotation axis")
PHI = Arg("phi", (), "angle", "rotation angle [rad]")
OMEGA = Arg("omega", (3,), "any", "angular velocity [rad/s]")
Q_ARG = Arg("Q", (3, 3), "rotation", "rotation matrix (proper orthogonal)")
_PR = "rigidsym.primitives."

# ----------------------------------------------------------------------------------------
# Sec. 2.3 / 3.2: rotations


def _rot_ni(e, phi):
    return {"Q": rotation_from_natural_invariants(e, phi)}


def _rot_er(eta):
    return {"Q": formula(_PR + "rotation_from_euler_rodrigues")(eta[:3, :], eta[3])}


def _ni_common(Q):
    v = vect(Q)
    s = sp.sqrt((v.T * v)[0])
    c = (trace(Q) - 1) / 2
    return v, s, c


def _ni_main(Q):
    v, s, c = _ni_common(Q)
    return {"e": v / s, "phi": sp.atan2(s, c)}


def _ni_near_pi(Q, k):
    v, s, c = _ni_common(Q)
    sym = (Q + Q.T) / 2 - c * sp.eye(3)      # = (1 - cos phi) e e^T
    col = sym[:, k]
    sign = sp.Piecewise((-1, (col.T * v)[0] < 0), (1, True))
    return {"e": sign * col / sp.sqrt((col.T * col)[0]), "phi": sp.atan2(s, c)}


def _ni_when(Q, k):
    d = [Q[i, i] for i in range(3)]
    near_pi = trace(Q) < 0                   # cos phi < -1/2
    others = [d[k] >= d[j] for j in range(3) if j != k]
    return sp.And(near_pi, *others)


_NI_BRANCHES = tuple(
    Branch(f"near_pi_{k}", partial(_ni_when, k=k), partial(_ni_near_pi, k=k),
           doc=f"cos(phi) < -1/2 and Q[{k},{k}] is the largest diagonal entry: e from "
               f"column {k} of the symmetric part Q + Q^T - 2 cos(phi) 1 = 2 (1 - cos phi) "
               "e e^T, signed so that e . vect(Q) >= 0")
    for k in range(3))

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
        formula="Q = (r0^2 - r.r) 1 + 2 r r^T + 2 r0 CPM(r)",
        ids=("2.3",), sources=(_PR + "rotation_from_euler_rodrigues",),
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
        singular="phi = 0 (Q = 1): the axis e is undefined",
        singular_arg="Q",
        notes="At phi = pi the sign of e is fixed by the rule: the component of e of largest "
              "magnitude is positive (e is taken from the column of the largest diagonal "
              "entry of Q).",
    ),
]
