"""The peers of the accuracy harness (issue 37 item 1): what a user would call instead.

Per kernel, the functions of pytransform3d 3.17, Modern Robotics' library 1.1.1,
spatialmath-python 1.1.18 and Pinocchio 4.1 (``pin``) that compute the same outputs, each
wrapped to take the kernel's arguments at one point (float64 arrays of the declared shapes)
and return its outputs flat, in the kernel's order and conventions (the adapters are
checked against the kernels at random points by ``tests/test_accuracy_rule.py``). Test-only
oracles: the ``[oracles]`` extra; a peer whose library is missing is left out (the harness
then compares with the textbook formula alone, and says so). Peers are float64 only.

The name of each peer is what docs/accuracy.md's table lists.
"""

from __future__ import annotations

import importlib
import warnings
from collections.abc import Callable

import numpy as np


def _lib(name: str):
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return importlib.import_module(name)
    except ImportError:
        return None


def _hat_free_screw(S: np.ndarray, pt) -> list[float]:
    """p0, pitch, Plücker array of a unit screw axis S = [s; v] (pytransform3d)."""
    q, s, h = pt.screw_parameters_from_screw_axis(S)
    return [*q, h, *s, *np.cross(q, s)]


def _peers() -> dict[str, list[tuple[str, Callable]]]:
    pr = _lib("pytransform3d.rotations")
    pt = _lib("pytransform3d.transformations")
    mr = _lib("modern_robotics")
    sb = _lib("spatialmath.base")
    pin = _lib("pinocchio")
    P: dict[str, list[tuple[str, Callable]]] = {}

    def add(kernel, label, lib, fn):
        if lib is not None:
            P.setdefault(kernel, []).append((label, fn))

    def unit(v):
        return v / np.linalg.norm(v)

    # rotations
    k = "rotation_from_natural_invariants"
    add(k, "pytransform3d matrix_from_axis_angle", pr,
        lambda e, phi: pr.matrix_from_axis_angle(np.r_[e, phi]).ravel())
    add(k, "modern_robotics MatrixExp3", mr,
        lambda e, phi: mr.MatrixExp3(mr.VecToso3(e * phi)).ravel())
    add(k, "spatialmath angvec2r", sb, lambda e, phi: sb.angvec2r(float(phi), e).ravel())
    add(k, "pinocchio exp3", pin, lambda e, phi: pin.exp3(e * phi).ravel())
    k = "natural_invariants_from_rotation"
    add(k, "pytransform3d axis_angle_from_matrix", pr,
        lambda Q: pr.axis_angle_from_matrix(Q, check=False))
    add(k, "modern_robotics AxisAng3(MatrixLog3)", mr,
        lambda Q: (lambda w, t: [*w, t])(*mr.AxisAng3(mr.so3ToVec(mr.MatrixLog3(Q)))))
    add(k, "spatialmath tr2angvec", sb,
        lambda Q: (lambda t, v: [*v, t])(*sb.tr2angvec(Q, check=False)))
    add(k, "pinocchio log3", pin,
        lambda Q: (lambda v: [*unit(v), np.linalg.norm(v)])(pin.log3(Q)))
    k = "rotation_from_euler_rodrigues"
    add(k, "pytransform3d matrix_from_quaternion", pr,
        lambda eta: pr.matrix_from_quaternion(np.r_[eta[3], eta[:3]]).ravel())
    add(k, "spatialmath q2r", sb, lambda eta: sb.q2r(np.r_[eta[3], eta[:3]]).ravel())
    add(k, "pinocchio Quaternion.toRotationMatrix", pin,
        lambda eta: pin.Quaternion(eta[3], *eta[:3]).toRotationMatrix().ravel())
    # lines and screws
    k = "plucker_from_points"
    add(k, "pytransform3d screw_axis_from_screw_parameters", pt,
        lambda p1, p2: pt.screw_axis_from_screw_parameters(p1, unit(p2 - p1), 0.0))
    add(k, "modern_robotics ScrewToAxis", mr,
        lambda p1, p2: mr.ScrewToAxis(p1, unit(p2 - p1), 0.0))
    k = "instant_screw_axis"
    add(k, "pytransform3d screw_parameters_from_screw_axis", pt,
        lambda w, a, ad: _hat_free_screw(np.r_[w, ad - np.cross(w, a)] /
                                         np.linalg.norm(w), pt))
    k = "wrench_axis"
    add(k, "pytransform3d screw_parameters_from_screw_axis", pt,
        lambda w, a: _hat_free_screw(np.r_[w[3:], w[:3] + np.cross(a, w[3:])] /
                                     np.linalg.norm(w[3:]), pt))

    def displacement(Q, a, ap):
        T = np.eye(4)
        T[:3, :3], T[:3, 3] = Q, ap - Q @ a
        S = pt.exponential_coordinates_from_transform(T, check=False)
        th = np.linalg.norm(S[:3])
        q, s, h, _ = [*pt.screw_parameters_from_screw_axis(S / th), th]
        return [*s, th, *q, h, *s, *np.cross(q, s)]
    add("screw_of_displacement", "pytransform3d exponential_coordinates_from_transform", pt,
        displacement)
    # transfers (the translation a - p between the points; Adjoint of [1, d; 0, 1])
    k = "twist_transfer"

    def shift(d):
        return mr.RpToTrans(np.eye(3), d)
    add(k, "modern_robotics Adjoint", mr, lambda t, a, p: mr.Adjoint(shift(a - p)) @ t)
    add(k, "pinocchio SE3.act(Motion)", pin,
        lambda t, a, p: (lambda m: [*m.angular, *m.linear])(
            pin.SE3(np.eye(3), a - p).act(pin.Motion(t[3:], t[:3]))))
    add("twist_transfer_matrix", "modern_robotics Adjoint", mr,
        lambda a, p: mr.Adjoint(shift(a - p)).ravel())
    add("twist_transfer_matrix", "pytransform3d adjoint_from_transform", pt,
        lambda a, p: pt.adjoint_from_transform(shift(a - p), check=False).ravel())
    k = "wrench_transfer"
    add(k, "modern_robotics Adjoint^T", mr, lambda w, a, p: mr.Adjoint(shift(p - a)).T @ w)
    add(k, "pinocchio SE3.act(Force)", pin,
        lambda w, a, p: (lambda f: [*f.angular, *f.linear])(
            pin.SE3(np.eye(3), a - p).act(pin.Force(w[3:], w[:3]))))
    add("wrench_transfer_matrix", "modern_robotics Adjoint^T", mr,
        lambda a, p: mr.Adjoint(shift(p - a)).T.ravel())
    # mass properties and dynamics (Pinocchio's spatial inertia: linear part first)
    add("inertia_at_point", "pinocchio Inertia.matrix", pin,
        lambda I, m, c, a: pin.Inertia(float(m), c - a, I).matrix()[3:, 3:].ravel())

    def dyad(I, m, c, a):
        M = pin.Inertia(float(m), c - a, I).matrix()
        return np.block([[M[3:, 3:], M[3:, :3]], [M[:3, 3:], M[:3, :3]]]).ravel()
    add("inertia_dyad_at_point", "pinocchio Inertia.matrix", pin, dyad)
    add("kinetic_energy", "pinocchio Inertia.vtiv", pin,
        lambda I, m, w, cd: [pin.Inertia(float(m), np.zeros(3), I).vtiv(
            pin.Motion(cd, w)) / 2])

    def newton_euler(I, m, w, wd, cdd):
        In = pin.Inertia(float(m), np.zeros(3), I)
        f = In * pin.Motion(cdd, wd) + In.vxiv(pin.Motion(np.zeros(3), w))
        return [*f.angular, *f.linear]
    add("newton_euler_wrench", "pinocchio Inertia (I a + v x* I v)", pin, newton_euler)
    _lie_peers(add, pr, pt)
    return P


def _lie_peers(add, pr, pt) -> None:
    """The Lie-group maps and their Jacobians in pytransform3d (issue 48: "none has the
    operation" was wrong; angular first as rigidsym, quaternions w first there)."""
    add("rotation_from_rotation_vector", "pytransform3d matrix_from_compact_axis_angle", pr,
        lambda w: pr.matrix_from_compact_axis_angle(w).ravel())
    add("rotation_vector_from_rotation", "pytransform3d compact_axis_angle_from_matrix", pr,
        lambda Q: pr.compact_axis_angle_from_matrix(Q))
    for side, sign in (("left", 1), ("right", -1)):
        add(f"rotation_vector_{side}_jacobian", "pytransform3d left_jacobian_SO3" +
            ("(-w)" if sign < 0 else ""), pr,
            lambda w, sign=sign: pr.left_jacobian_SO3(sign * w).ravel())
        add(f"rotation_vector_{side}_jacobian_inverse", "pytransform3d left_jacobian_SO3_inv" +
            ("(-w)" if sign < 0 else ""), pr,
            lambda w, sign=sign: pr.left_jacobian_SO3_inv(sign * w).ravel())
    add("transform_from_exponential_coordinates",
        "pytransform3d transform_from_exponential_coordinates", pt,
        lambda xi: pt.transform_from_exponential_coordinates(xi).ravel())
    add("exponential_coordinates_from_transform",
        "pytransform3d exponential_coordinates_from_transform", pt,
        lambda T: pt.exponential_coordinates_from_transform(T))
    add("exponential_coordinates_left_jacobian", "pytransform3d left_jacobian_SE3", pt,
        lambda xi: pt.left_jacobian_SE3(xi).ravel())
    add("exponential_coordinates_left_jacobian_inverse", "pytransform3d left_jacobian_SE3_inv",
        pt, lambda xi: pt.left_jacobian_SE3_inv(xi).ravel())

    def er(Q):
        q = pr.quaternion_from_matrix(Q)
        return np.r_[q[1:], q[0]] * (1.0 if q[0] >= 0 else -1.0)
    add("euler_rodrigues_from_rotation", "pytransform3d quaternion_from_matrix", pr, er)

    def product(a, b):
        q = pr.concatenate_quaternions(np.r_[a[3], a[:3]], np.r_[b[3], b[:3]])
        return np.r_[q[1:], q[0]]
    add("euler_rodrigues_product", "pytransform3d concatenate_quaternions", pr, product)


_CACHE: dict = {}


def peers(name: str) -> list[tuple[str, Callable]]:
    """``[(label, f(*args) -> flat outputs)]`` for kernel ``name`` (none: an empty list)."""
    if "all" not in _CACHE:
        _CACHE["all"] = _peers()
    return _CACHE["all"].get(name, [])


def evaluate(name: str, arrays: list[np.ndarray], n_out: int) -> dict[str, np.ndarray]:
    """``{label: (n, n_out)}`` float64 outputs of each peer at the rows of ``arrays``; a
    row where the peer raises or warns is NaN (it failed there)."""
    out = {}
    for label, f in peers(name):
        rows = np.full((arrays[0].shape[0], n_out), np.nan)
        for s in range(arrays[0].shape[0]):
            args = [np.asarray(a[s], dtype=np.float64) for a in arrays]
            try:
                with warnings.catch_warnings(), np.errstate(all="ignore"):
                    warnings.simplefilter("ignore")
                    v = np.asarray(f(*args), dtype=np.float64).ravel()
                if v.size == n_out:
                    rows[s] = v
            except Exception:      # noqa: BLE001  (a peer's own error: it failed here)
                pass
        out[label] = rows
    return out


def textbook(name: str, arrays: list[np.ndarray], dtype) -> np.ndarray:
    """The textbook formula (the declaration, naively; :func:`rigidsym.codegen.rule.textbook`)
    at the rows of ``arrays`` in ``dtype`` arithmetic: ``(n, outputs)`` float64."""
    import _accuracy_ref as R

    from rigidsym.codegen import rule

    n = arrays[0].shape[0]
    return rule.textbook(R.kernel_of(name), [c for a in arrays for c in a.reshape(n, -1).T],
                         dtype)
