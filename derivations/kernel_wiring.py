"""Wiring shared by the kernel list (:mod:`rigidsym.derivations.kernels_spec`): the lazy
lookup of formula functions by dotted name, the common arguments, the section prefixes.
"""

from __future__ import annotations

import importlib

from rigidsym.codegen.spec import Arg

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
