"""Wiring shared by the kernel list (:mod:`rigidsym.derivations.kernels_spec`): the lazy
lookup of formula functions by dotted name, the common arguments, the section prefixes.
"""

from __future__ import annotations

import importlib

import sympy as sp

from rigidsym.codegen.spec import Arg
from rigidsym.declare import trace, vect

__all__ = ["formula", "E", "PHI", "OMEGA", "Q_ARG"]


def formula(dotted: str):
    """The formula function named ``module.function`` (imported lazily)."""
    mod, _, fn = dotted.rpartition(".")
    return getattr(importlib.import_module(mod), fn)


# ----------------------------------------------------------------------------------------
# common arguments
E = Arg("e", (3,), "unit", "unit vector along the rotation axis")
PHI = Arg("phi", (), "angle", "rotation angle [rad]")
OMEGA = Arg("omega", (3,), "any", "angular velocity [rad/s]")
Q_ARG = Arg("Q", (3, 3), "rotation", "rotation matrix (proper orthogonal)")
_PR = "rigidsym.algebra.primitives."

# ----------------------------------------------------------------------------------------
# Sections 3.2-3.8: kernels composed of the sections' formula functions
_S21, _S22 = "rigidsym.derivations.sec3_2_1.", "rigidsym.derivations.sec3_2_2."
_S41, _S42 = "rigidsym.derivations.sec3_4_1.", "rigidsym.derivations.sec3_4_2."
_S5, _S5R = "rigidsym.derivations.sec3_5.", "rigidsym.derivations.sec3_5_rates."
_S6 = "rigidsym.derivations.sec3_6."
_S7, _S8 = "rigidsym.derivations.sec3_7.", "rigidsym.derivations.sec3_8."
_EX10 = "rigidsym.derivations.exercises.ex3_10."


def _v(name, doc, kind="any"):
    return Arg(name, (3,), kind, doc)


def _one(out, fn, wire=None):
    """A build returning ``{out: fn(*args)}`` with the kernel's arguments in order."""
    def build(**kw):
        args = list(kw.values()) if wire is None else wire(**kw)
        return {out: formula(fn)(*args)}
    return build


# ----------------------------------------------------------------------------------------
# the natural invariants' formulas near phi = pi, shared by the book's kernels and the
# logarithms of derivations/kernels_spec_lie.py
def _ni_common(Q):
    v = vect(Q)
    s = sp.sqrt((v.T * v)[0])
    c = (trace(Q) - 1) / 2
    return v, s, c


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
