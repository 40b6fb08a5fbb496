"""rigidsym: checked computer algebra and generated kernels for rigid-body mechanics.

Chapter 3 of J. Angeles, *Fundamentals of Robotic Mechanical Systems*: every numbered
equation declared once (``rigidsym.derivations``), decided by a sound constraint-aware checker,
reported, and compiled to kernels; the same engine checks and compiles a reader's own
equations (user modules).

The public API (README, "Python API"): :func:`check`, :func:`check_latex`, :func:`verify`,
:class:`Result`, :class:`Results`, :func:`load_module`, :func:`audit` (any implementation
judged against the book, ``rigidsym.auditing``) and the declaration vocabulary of
:mod:`rigidsym.declare` (``equation``, ``Statement``, ``Rel``, constrained atoms, operators).
Public modules: ``rigidsym``, ``rigidsym.declare``, ``rigidsym.kernels`` (with
``rigidsym.kernels.torch`` and ``rigidsym.kernels.jax``), ``rigidsym.exercises``,
``rigidsym.codegen.spec`` (kernel declarations), ``rigidsym.cli``, and of the LaTeX reader
``rigidsym.latex``, ``rigidsym.latex.transcription`` and ``rigidsym.latex.lets``
(``tests/test_public_api.py`` lists their names); everything else is private. Names load
lazily, so ``import rigidsym`` stays cheap.
"""

from __future__ import annotations

import importlib

__version__ = "0.2.0"

_API = ("check", "check_latex", "verify", "Result", "Results")
_DECLARE = (
    "equation", "Statement", "Rel",
    "TIME", "unit_vector", "unit_vector4", "rotation", "angle", "rigid_motion", "RigidMotion",
    "vector", "scalar", "matrix", "symmetric_matrix",
    "vec", "mat", "MS", "I3", "O3",
    "cpm", "vect", "trace", "Cross", "Det", "Blocks",
    "rotation_from_natural_invariants", "rotation_from_euler_rodrigues",
    "rotation_from_quaternion", "linear_invariants", "euler_rodrigues_parameters",
    "as_vector", "block", "eye3", "cancel_matrix",
    "twist", "wrench", "hat", "vee", "transform", "transform_inverse", "Ad", "ad", "ad_dual",
    "expm", "logm", "diff", "acos", "atan2", "ORDERS", "norm3",
)
_WHERE = {**{n: "rigidsym.api" for n in _API}, **{n: "rigidsym.declare" for n in _DECLARE},
          "load_module": "rigidsym.registry.usermodules", "audit": "rigidsym.auditing.audit",
          "BadInput": "rigidsym.registry.declarations"}
_RENAMED = {"load_module": "load"}

__all__ = [*_API, "load_module", "audit", "BadInput", *_DECLARE]


def __getattr__(name: str):
    where = _WHERE.get(name)
    if where is None:
        raise AttributeError(f"module 'rigidsym' has no attribute {name!r}")
    value = getattr(importlib.import_module(where), _RENAMED.get(name, name))
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
