"""The constraint kinds, one table: everything the layers need to know about a kind of atom.

A kind (unit 3-vector, unit 4-vector, rotation, angle, homogeneous transform) is one
:class:`Kind` entry in :data:`KINDS`. The entry gives

- the atoms of a group and their names (:meth:`Kind.components`), and the group's
  rational parametrisation for the zero test (:attr:`Kind.params`,
  :attr:`Kind.parametrise`; an angle instead has its sine and cosine parametrised by the
  tangent of a fraction of it, :attr:`Kind.half_angle`);
- its words for reports (:attr:`Kind.words`, :attr:`Kind.arg_words`);
- its run-time validation (:attr:`Kind.check`) and tolerance per dtype
  (:meth:`Kind.tolerance`; the compiled kernels' C validation is bound to the same numbers,
  :mod:`rigidsym.kernels.runtime.entries`);
- its tangent space for Jacobians and their checks (:attr:`Kind.project`,
  :attr:`Kind.curve`, :attr:`Kind.tangent`);
- its spec name (:attr:`Kind.spec`), the ``kind`` of a kernel argument
  (:class:`rigidsym.codegen.spec.Arg`, ``kernels.json``).

Adding a kind is one :func:`register` call (``tests/test_kinds.py`` registers a toy kind
from the test module). The module imports NumPy only, never sympy and no other layer of
rigidsym, so the kernels runtime reads the same table as the zero test: the symbolic
parametrisations are plain arithmetic, and work on the sympy symbols the zero test passes
in as well as on floats.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cache
from typing import Any

import numpy as np

__all__ = ["Kind", "KINDS", "register", "unregister", "get", "for_spec", "spec_names"]


@dataclass(frozen=True)
class Kind:
    """One constraint kind: a row of the table.

    Attributes:
        name: the key, carried by the atoms (``Constraint.kind``): ``"unit"``,
            ``"unit4"``, ``"rotation"``, ``"angle"``.
        shape: the shape of one group of atoms (one argument sample): ``(3,)``, ``(3, 3)``,
            ``()`` for a scalar.
        spec: its name in kernel specs (``Arg.kind``) and ``kernels.json``; several kinds
            may share it when their shapes differ (``"unit"`` for 3- and 4-vectors).
        words: the model in words for reports (``"unit vector, stereographic"``).
        arg_words: appended to an argument's shape in kernel docstrings (``", unit"``).
        params: suffixes of the free parameters of the rational parametrisation; the
            parameters of group ``e`` are named ``e__<suffix>``.
        parametrise: the group's components (row-major) as rational functions of its
            parameters, in the order of :attr:`params`; plain arithmetic, so it takes sympy
            symbols (the zero test) as well as floats. ``None`` for a kind without one.
        half_angle: an angle: the zero test parametrises its sine and cosine by the tangent
            of a fraction of it and keeps the bare angle free; generated code rewrites
            its trigonometric functions by half angles.
        check: run-time validation of a float array of shape ``(..., *shape)`` (finite
            values): ``check(a, name, tol)`` returns the error message naming ``name``,
            or ``None`` when every sample satisfies the constraint within ``tol``.
        tol: the validation tolerance in float64.
        tol_eps: for narrower dtypes the tolerance is ``max(tol, tol_eps * eps)``.
        c_check: the validation routine of the compiled entry points (``c_fast.h.j2``):
            0 none (finiteness only), 1 unit norm (``RIGIDSYM_UNIT``), 2 proper orthogonal
            (``RIGIDSYM_ROTATION``); a kind with a new check adds its C routine there. A
            kind with a :attr:`check` and no C routine (0) is never left unchecked: its
            checked calls take the Python path (``RIGIDSYM_PYTHON``).
        project: ``project(x, d)``: the admissible (tangent) direction nearest to an
            ambient direction ``d`` at a point ``x`` of the constraint set; flat sequences
            in row-major order, plain arithmetic (floats or mpmath numbers).
        curve: ``curve(x, v)``: a function ``t -> c(t)`` on the constraint set with
            ``c(0) = x`` and ``c'(0) = v`` for a tangent ``v`` (flat sequences, plain
            arithmetic and ``** 0.5``), for the checks of Jacobians along the set.
        tangent: the note on derivatives in the docstrings of Jacobian kernels
            (``{a}`` stands for the argument's name).
    """

    name: str
    shape: tuple[int, ...]
    spec: str
    words: str
    arg_words: str = ""
    params: tuple[str, ...] = ()
    parametrise: Callable[[Sequence], list] | None = None
    half_angle: bool = False
    check: Callable[[np.ndarray, str, float], str | None] | None = None
    tol: float = 0.0
    tol_eps: float = 100.0
    c_check: int = 0
    project: Callable[[Sequence, Sequence], list] | None = None
    curve: Callable[[Sequence, Sequence], Callable[[Any], list]] | None = None
    tangent: str = ""

    def components(self, name: str) -> tuple[str, ...]:
        """The atom names of a group ``name``: ``name`` for a scalar, ``name_1 ... name_n``
        for a vector, ``name_ij`` (row-major, from 1) for a matrix."""
        if self.shape == ():
            return (name,)
        if len(self.shape) == 1:
            return tuple(f"{name}_{i}" for i in range(1, self.shape[0] + 1))
        rows, cols = self.shape
        return tuple(f"{name}_{i}{j}" for i in range(1, rows + 1) for j in range(1, cols + 1))

    def tolerance(self, dtype) -> float:
        """The validation tolerance in ``dtype``: :attr:`tol` for float64, at least
        ``tol_eps`` machine epsilons for a narrower float (float32: 100 eps, 1.19e-5)."""
        return _tolerance(self.tol, self.tol_eps, np.dtype(dtype))


@cache  # np.finfo costs microseconds, and a checked call asks on every constrained argument
def _tolerance(tol: float, tol_eps: float, dtype: np.dtype) -> float:
    return max(tol, tol_eps * float(np.finfo(dtype).eps)) if dtype.kind == "f" else tol


# ------------------------------------------------------------------------- parametrisations
def _stereographic(P: Sequence) -> list:
    """The unit sphere in R^(n+1) from n free parameters: ``x_i = 2 p_i / (1 + |p|^2)``,
    ``x_last = (1 - |p|^2) / (1 + |p|^2)``; ``x . x = 1`` identically."""
    s = sum(p**2 for p in P)
    den = 1 + s
    return [2 * p / den for p in P] + [(1 - s) / den]


def _quaternion_rotation(P: Sequence) -> list:
    """``Q = ((q0^2 - v.v) 1 + 2 v v^T + 2 q0 cpm(v)) / (v.v + q0^2)``, ``P = [q1, q2, q3,
    q0]`` unnormalised (:func:`rigidsym.algebra.primitives.rotation_from_quaternion`):
    exactly orthogonal with determinant 1 for every ``P != 0``. Row-major entries."""
    v, q0 = list(P[:3]), P[3]
    vv = sum(x**2 for x in v)
    n2 = vv + q0**2
    cross = [[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]]
    return [((q0**2 - vv) * int(i == j) + 2 * v[i] * v[j] + 2 * q0 * cross[i][j]) / n2
            for i in range(3) for j in range(3)]


# ------------------------------------------------------------------------- run-time checks
def _check_unit(a: np.ndarray, name: str, tol: float) -> str | None:
    err = np.abs(np.sqrt(np.einsum("...i,...i->...", a, a)) - 1.0)
    if (err > tol).any():
        return f"{name}: not a unit vector (| ||{name}|| - 1 | = {err.max():.3g} > {tol:.3g})"
    return None


def _check_rotation(a: np.ndarray, name: str, tol: float) -> str | None:
    g = np.einsum("...ki,...kj->...ij", a, a) - np.eye(3)
    err = np.abs(g).max() if g.size else 0.0
    if not err <= tol:
        return f"{name}: not orthogonal (max |{name}^T {name} - 1| = {err:.3g} > {tol:.3g})"
    if (np.linalg.det(a) <= 0).any():
        return f"{name}: not a proper rotation (det <= 0)"
    return None


# ------------------------------------------------------------------------- tangent spaces
def _dot(x: Sequence, y: Sequence):
    return sum(a * b for a, b in zip(x, y, strict=True))


def _project_sphere(x: Sequence, d: Sequence) -> list:
    s = _dot(x, d) / _dot(x, x)
    return [b - a * s for a, b in zip(x, d, strict=True)]


def _curve_sphere(x: Sequence, v: Sequence) -> Callable[[Any], list]:
    nx = _dot(x, x) ** 0.5

    def c(t):
        y = [a + t * b for a, b in zip(x, v, strict=True)]
        scale = nx / _dot(y, y) ** 0.5
        return [b * scale for b in y]
    return c


def _mat(x: Sequence) -> list[list]:
    return [list(x[3 * i:3 * i + 3]) for i in range(3)]


def _mul(A: list[list], B: list[list]) -> list[list]:
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def _skew_times(D: Sequence, Q: Sequence) -> list[list]:
    """``W = (D Q^T - Q D^T) / 2``: the skew part of ``D Q^T``."""
    A = _mul(_mat(D), [list(r) for r in zip(*_mat(Q), strict=True)])
    return [[(A[i][j] - A[j][i]) / 2 for j in range(3)] for i in range(3)]


def _project_rotation(Q: Sequence, D: Sequence) -> list:
    """``skew(D Q^T) Q``: the tangent space of SO(3) at ``Q`` is ``{W Q : W skew}``."""
    return [x for row in _mul(_skew_times(D, Q), _mat(Q)) for x in row]


def _inverse3(A: list[list]) -> list[list]:
    cof = [[A[(i + 1) % 3][(j + 1) % 3] * A[(i + 2) % 3][(j + 2) % 3]
            - A[(i + 1) % 3][(j + 2) % 3] * A[(i + 2) % 3][(j + 1) % 3] for j in range(3)]
           for i in range(3)]
    det = sum(A[0][j] * cof[0][j] for j in range(3))
    return [[cof[j][i] / det for j in range(3)] for i in range(3)]


def _curve_rotation(Q: Sequence, V: Sequence) -> Callable[[Any], list]:
    """The Cayley curve ``c(t) = (1 - t W / 2)^-1 (1 + t W / 2) Q`` with ``W = V Q^T``:
    rational in ``t``, orthogonal for every ``t``, ``c'(0) = W Q = V``."""
    W = _skew_times(V, Q)

    def c(t):
        eye = [[1 if i == j else 0 for j in range(3)] for i in range(3)]
        P = [[eye[i][j] + t * W[i][j] / 2 for j in range(3)] for i in range(3)]
        M = [[eye[i][j] - t * W[i][j] / 2 for j in range(3)] for i in range(3)]
        return [x for row in _mul(_mul(_inverse3(M), P), _mat(Q)) for x in row]
    return c


# ------------------------------------------------------------------------- homogeneous transforms
# T = [[R, p], [0, 1]] (4 x 4, row-major): R a rotation (the rotation kind's parametrisation,
# check, tangent and curve), p free, the last row exactly (0, 0, 0, 1). Kernels taking a
# transform (the log of SE(3)) are defined on SE(3) only: a random 4 x 4 is not an input.
_R_IDX = (0, 1, 2, 4, 5, 6, 8, 9, 10)
_P_IDX = (3, 7, 11)


def _transform(R: Sequence, p: Sequence) -> list:
    return [*R[0:3], p[0], *R[3:6], p[1], *R[6:9], p[2], 0, 0, 0, 1]


def _quaternion_transform(P: Sequence) -> list:
    """``[[Q(q), p], [0, 1]]``, ``P = [q1, q2, q3, q0, p1, p2, p3]``."""
    return _transform(_quaternion_rotation(P[:4]), P[4:7])


def _check_transform(a: np.ndarray, name: str, tol: float) -> str | None:
    last = np.abs(a[..., 3, :] - np.array([0.0, 0.0, 0.0, 1.0]))
    err = last.max() if last.size else 0.0
    if not err <= tol:
        return (f"{name}: not a homogeneous transform (last row not [0, 0, 0, 1]: max "
                f"deviation {err:.3g} > {tol:.3g})")
    msg = _check_rotation(a[..., :3, :3], f"{name}[:3, :3]", tol)
    return msg and f"{name}: not a homogeneous transform: {msg}"


def _project_transform(x: Sequence, d: Sequence) -> list:
    R = _project_rotation([x[i] for i in _R_IDX], [d[i] for i in _R_IDX])
    return _transform(R, [d[i] for i in _P_IDX])[:12] + [0, 0, 0, 0]


def _curve_transform(x: Sequence, v: Sequence) -> Callable[[Any], list]:
    rot = _curve_rotation([x[i] for i in _R_IDX], [v[i] for i in _R_IDX])
    return lambda t: _transform(rot(t), [x[i] + t * v[i] for i in _P_IDX])


# ------------------------------------------------------------------------- the table
_UNIT_TANGENT = (
    "{a} is a unit vector: d/d{a} is the ambient derivative (all components independent); "
    "along the sphere only directions d{a} with {a}.d{a} = 0 are admissible (restrict "
    "jac[.][{a!r}] to them). The rates of the rotation invariants in terms of omega are the "
    "book's N, L, H, with the left inverses N~, L~, H~ (kernels N_matrix, L_matrix, "
    "H_matrix, ...).")

#: the kinds by name (:func:`register` adds one)
KINDS: dict[str, Kind] = {}
_BY_SPEC: dict[tuple[str, tuple[int, ...]], Kind] = {}


def register(kind: Kind) -> Kind:
    """Add ``kind`` to the table; returns it.

    Args:
        kind: a new kind; its :attr:`Kind.name` and its ``(spec, shape)`` must be new.

    Returns:
        ``kind``.

    Raises:
        ValueError: the name, or the spec name with that shape, is taken already.
    """
    if kind.name in KINDS:
        raise ValueError(f"kind: {kind.name!r} is registered already")
    if (kind.spec, kind.shape) in _BY_SPEC or kind.spec == "any":
        raise ValueError(f"kind: spec name {kind.spec!r} with shape {kind.shape} is taken")
    KINDS[kind.name] = kind
    _BY_SPEC[(kind.spec, kind.shape)] = kind
    return kind


def unregister(name: str) -> None:
    """Remove the kind ``name`` (a test's toy kind).

    Raises:
        KeyError: no kind of that name.
    """
    kind = KINDS.pop(name)
    _BY_SPEC.pop((kind.spec, kind.shape), None)


def get(name: str) -> Kind:
    """The kind ``name`` (a ``Constraint.kind``).

    Raises:
        ValueError: no such kind (the message lists the known ones).
    """
    try:
        return KINDS[name]
    except KeyError:
        raise ValueError(f"kind: expected one of {', '.join(KINDS)}, got {name!r}") from None


def for_spec(spec: str, shape: Sequence[int]) -> Kind | None:
    """The kind of a kernel argument: ``None`` for ``"any"`` (unconstrained).

    Args:
        spec: the argument's ``kind`` (``Arg.kind``, or ``kernels.json``).
        shape: its per-sample shape.

    Returns:
        The :class:`Kind`, or ``None`` for ``"any"``.

    Raises:
        ValueError: an unknown spec name, or one that does not fit the shape.
    """
    if spec == "any":
        return None
    kind = _BY_SPEC.get((spec, tuple(shape)))
    if kind is None:
        fits = [f"{k.spec!r} {k.shape}" for k in KINDS.values()]
        raise ValueError(f"kind: expected 'any' or one of {', '.join(fits)} (spec name and "
                         f"shape), got {spec!r} with shape {tuple(shape)}")
    return kind


def spec_names() -> tuple[str, ...]:
    """The spec names a kernel argument may carry, ``"any"`` first."""
    return ("any", *dict.fromkeys(k.spec for k in KINDS.values()))


register(Kind(
    "unit", (3,), "unit", "unit vector, stereographic", ", unit", ("u", "v"),
    _stereographic, check=_check_unit, tol=1e-8, c_check=1, project=_project_sphere,
    curve=_curve_sphere, tangent=_UNIT_TANGENT))
register(Kind(
    "unit4", (4,), "unit", "unit 4-vector, stereographic", ", unit", ("u", "v", "w"),
    _stereographic, check=_check_unit, tol=1e-8, c_check=1, project=_project_sphere,
    curve=_curve_sphere, tangent=_UNIT_TANGENT))
register(Kind(
    "rotation", (3, 3), "rotation", "rotation, rational quaternion", ", proper orthogonal",
    ("q1", "q2", "q3", "q0"), _quaternion_rotation, check=_check_rotation, tol=1e-8, c_check=2,
    project=_project_rotation, curve=_curve_rotation,
    tangent="{a} is a rotation: d/d{a} is the ambient derivative over its 9 entries; "
            "admissible directions are d{a} = CPM(theta) {a} (tangent space of SO(3)); their "
            "relation to the rates of the invariants is the book's N, L, H (kernels N_matrix, "
            "L_matrix, H_matrix)."))
register(Kind("angle", (), "angle", "angle, half-angle tangent", half_angle=True))


def _check_half_turn(a: np.ndarray, name: str, tol: float) -> str | None:
    bad = (a < -tol) | (a > np.pi + tol)
    if bad.any():
        return f"{name}: outside [0, pi] (an angle of the range [0, pi]; got {a[bad].flat[0]:.6g})"
    return None


# an angle on [0, pi] (MR's theta = acos((tr R - 1) / 2)): acos(cos theta) = theta holds
register(Kind("angle_pi", (), "angle_0_pi", "angle in [0, pi], half-angle tangent",
              ", angle in [0, pi]", half_angle=True, check=_check_half_turn, tol=1e-12))
# twists and wrenches: free 6-vectors, angular part first unless a word says otherwise
# (rigidsym.algebra.rigid_motions.ORDERS); rows for the kernels' specs and docstrings
register(Kind("twist", (6,), "twist", "twist [omega; v] (6-vector), free", ", twist"))
register(Kind("wrench", (6,), "wrench", "wrench [n; f] (6-vector), free", ", wrench"))
# the homogeneous transforms of SE(3) (the log of SE(3)'s argument is a transform)
register(Kind(
    "transform", (4, 4), "transform", "homogeneous transform, rational quaternion and free p",
    ", homogeneous transform [[R, p], [0, 1]]", ("q1", "q2", "q3", "q0", "p1", "p2", "p3"),
    _quaternion_transform, check=_check_transform, tol=1e-8, project=_project_transform,
    curve=_curve_transform,
    tangent="{a} is a homogeneous transform: d/d{a} is the ambient derivative over its 16 "
            "entries; admissible directions are d{a} = [[CPM(theta) R, dp], [0, 0]] (tangent "
            "space of SE(3))."))
