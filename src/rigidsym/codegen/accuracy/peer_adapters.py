"""The peers' adapters: each library's call for each kernel, in the
kernel's conventions, registered into :mod:`.peers`' table by subject (rotations, lines and
screws, transfers, mass properties and dynamics, SO(3), SE(3), quaternions). Each function
here calls ``add(kernel, library, call, outputs, adapt)`` once per peer; the conventions they
rest on are stated in :mod:`.peers` and checked numerically by ``tests/test_peers.py``.
"""

from __future__ import annotations

import math

import numpy as np


def _unit(v):
    return v / np.linalg.norm(v)


def _hat(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def _swap(J):
    """A 6 x 6 matrix on ``[v; w]`` as one on ``[w; v]`` (and back)."""
    return np.block([[J[3:, 3:], J[3:, :3]], [J[:3, 3:], J[:3, :3]]])


def _vw(xi):
    """``[w; v]`` -> ``[v; w]`` (and back)."""
    return np.r_[xi[3:], xi[:3]]


def _in_log_domain(w):
    """``Log(Exp(w)) = w`` only for ``|w| < pi``: a peer of a Jacobian at ``w`` through the
    logarithm computes the kernel's function there alone."""
    if not np.linalg.norm(w) < math.pi:
        raise ValueError("|w| >= pi: Log(Exp(w)) is not w")


def _positive(q):
    """A quaternion with a non-negative scalar part (``q[3]`` in rigidsym's order): the
    kernel's sign."""
    q = np.asarray(q, dtype=np.float64)
    return q if q[3] >= 0 else -q


def _screw(S, pt):
    """p0, pitch, Plücker array of a unit screw axis ``S = [s; v]`` (pytransform3d)."""
    q, s, h = pt.screw_parameters_from_screw_axis(S)
    return q, h, np.r_[s, np.cross(q, s)]


def _displacement(pt, Q, a, ap):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = Q, ap - Q @ a
    S = pt.exponential_coordinates_from_transform(T, check=False)
    th = np.linalg.norm(S[:3])
    q, s, h = pt.screw_parameters_from_screw_axis(S / th)
    return s, th, q, h, np.r_[s, np.cross(q, s)]


def _shift(mr, d):
    return mr.RpToTrans(np.eye(3), d)


def _dexp3(Q, Jr):
    """``dQ/dw`` (3, 3, 3) from ``Q = Exp(w)`` and the right Jacobian: ``Q hat(J_r e_k)``."""
    return np.stack([Q @ _hat(Jr[:, k]) for k in range(3)], axis=-1)


def _dexp6(T, Jr):
    """``dT/dxi`` (4, 4, 6) from ``T = Exp(xi)`` and the right Jacobian on ``[w; v]``."""
    out = []
    for k in range(6):
        d = Jr[:, k]
        H = np.zeros((4, 4))
        H[:3, :3], H[:3, 3] = _hat(d[:3]), d[3:]
        out.append(T @ H)
    return np.stack(out, axis=-1)


def _torch(x):
    import torch

    return torch.as_tensor(np.asarray(x, dtype=np.float64))


def _np(t):
    return np.asarray(t.detach().numpy() if hasattr(t, "detach") else t, dtype=np.float64)


def _pin_inertia(pin, I, m, c, a):
    return pin.Inertia(float(m), c - a, I).matrix()


def _newton_euler(pin, I, m, w, wd, cdd):
    In = pin.Inertia(float(m), np.zeros(3), I)
    f = In * pin.Motion(cdd, wd) + In.vxiv(pin.Motion(np.zeros(3), w))
    return (np.r_[f.angular, f.linear],)


_JIT: dict = {}


def _jit(key, make):
    """jaxlie's calls compiled once each (one point per call: eager JAX dispatch was the
    harness's bottleneck)."""
    if key not in _JIT:
        import jax

        _JIT[key] = jax.jit(make())
    return _JIT[key]


def x64():
    """A context in which JAX computes in float64 (the peers are float64; jaxlie follows
    JAX's default type), leaving the process's setting as it was."""
    import jax

    ctx = getattr(jax, "enable_x64", None)
    if ctx is not None:
        return ctx(True)
    from jax.experimental import enable_x64  # JAX < 0.5

    return enable_x64()


def _jl(jaxlie, key, make, *args):
    with x64():
        return _np(_jit(key, make)(*(np.asarray(a, dtype=np.float64) for a in args)))


def _er_sm(sb, Q):
    q = sb.r2q(Q, check=False)
    return (_positive(np.r_[q[1:], q[0]]),)


def rotations(add) -> None:
    """The peers of the rotations."""
    k = "rotation_from_natural_invariants"
    add(k, "pytransform3d", "`rotations.matrix_from_axis_angle`", "Q",
        lambda pt, e, phi: (pt.rotations.matrix_from_axis_angle(np.r_[e, phi]),))
    add(k, "Modern Robotics", "`MatrixExp3(VecToso3(e phi))`", "Q",
        lambda mr, e, phi: (mr.MatrixExp3(mr.VecToso3(e * phi)),))
    add(k, "spatialmath", "`base.angvec2r`", "Q",
        lambda sb, e, phi: (sb.angvec2r(float(phi), e),))
    add(k, "Pinocchio", "`exp3(e phi)`", "Q", lambda pin, e, phi: (pin.exp3(e * phi),))
    add(k, "PyPose", "`so3(e phi).matrix()`", "Q",
        lambda pp, e, phi: (_np(pp.so3(_torch(e * phi)).matrix()),))
    add(k, "jaxlie", "`SO3.exp(e phi).as_matrix()`", "Q",
        lambda jl, e, phi: (_jl(jl, "exp3", lambda: lambda w: jl.SO3.exp(w).as_matrix(),
                                e * phi),))
    k = "natural_invariants_from_rotation"
    add(k, "pytransform3d", "`rotations.axis_angle_from_matrix`", "e phi",
        lambda pt, Q: (lambda a: (a[:3], a[3]))(
            pt.rotations.axis_angle_from_matrix(Q, check=False)))
    add(k, "Modern Robotics", "`AxisAng3(so3ToVec(MatrixLog3(Q)))`", "e phi",
        lambda mr, Q: mr.AxisAng3(mr.so3ToVec(mr.MatrixLog3(Q))))
    add(k, "spatialmath", "`base.tr2angvec`", "e phi",
        lambda sb, Q: (lambda t, v: (v, t))(*sb.tr2angvec(Q, check=False)))
    add(k, "Pinocchio", "`log3` (then its norm and direction)", "e phi",
        lambda pin, Q: (lambda v: (_unit(v), np.linalg.norm(v)))(pin.log3(Q)))
    k = "rotation_from_euler_rodrigues"
    add(k, "pytransform3d", "`rotations.matrix_from_quaternion` (w first)", "Q",
        lambda pt, eta: (pt.rotations.matrix_from_quaternion(np.r_[eta[3], eta[:3]]),))
    add(k, "spatialmath", "`base.q2r` (w first)", "Q",
        lambda sb, eta: (sb.q2r(np.r_[eta[3], eta[:3]]),))
    add(k, "Pinocchio", "`Quaternion(w, x, y, z).toRotationMatrix()`", "Q",
        lambda pin, eta: (pin.Quaternion(eta[3], *eta[:3]).toRotationMatrix(),))
    add(k, "PyPose", "`SO3(eta).matrix()` (xyzw)", "Q",
        lambda pp, eta: (_np(pp.SO3(_torch(eta)).matrix()),))
    add(k, "jaxlie", "`SO3.from_quaternion_xyzw(eta).as_matrix()`", "Q",
        lambda jl, eta: (_jl(jl, "q2r", lambda: lambda q: jl.SO3.from_quaternion_xyzw(q)
                             .as_matrix(), eta),))


def screws(add) -> None:
    """The peers of the lines and screws."""
    k = "plucker_from_points"
    add(k, "pytransform3d",
        "`transformations.screw_axis_from_screw_parameters(p1, (p2 - p1)/\\|p2 - p1\\|, 0)`",
        "kappa", lambda pt, p1, p2: (pt.transformations.screw_axis_from_screw_parameters(
            p1, _unit(p2 - p1), 0.0),))
    add(k, "Modern Robotics", "`ScrewToAxis(p1, (p2 - p1)/\\|p2 - p1\\|, 0)`", "kappa",
        lambda mr, p1, p2: (mr.ScrewToAxis(p1, _unit(p2 - p1), 0.0),))
    add("instant_screw_axis", "pytransform3d",
        "`transformations.screw_parameters_from_screw_axis` of the twist at the origin over "
        "`\\|omega\\|`", "p0 pitch plucker",
        lambda pt, w, a, ad: _screw(np.r_[w, ad - np.cross(w, a)] / np.linalg.norm(w),
                                    pt.transformations))
    add("instant_screw_point_pitch", "pytransform3d",
        "`transformations.screw_parameters_from_screw_axis` of the twist at the origin over "
        "`\\|omega\\|`", "p0 pitch",
        lambda pt, w, a, ad: _screw(np.r_[w, ad - np.cross(w, a)] / np.linalg.norm(w),
                                    pt.transformations)[:2])
    add("wrench_axis", "pytransform3d",
        "`transformations.screw_parameters_from_screw_axis` of `[f; n_O] / \\|f\\|`",
        "p0 pitch plucker",
        lambda pt, w, a: _screw(np.r_[w[3:], w[:3] + np.cross(a, w[3:])] /
                                np.linalg.norm(w[3:]), pt.transformations))
    add("screw_of_displacement", "pytransform3d",
        "`transformations.exponential_coordinates_from_transform`, then "
        "`screw_parameters_from_screw_axis`", "e phi p0 pitch plucker",
        lambda pt, Q, a, ap: _displacement(pt.transformations, Q, a, ap))
    add("screw_axis_point", "pytransform3d",
        "`rotations.matrix_from_axis_angle`, then as `screw_of_displacement`", "p0",
        lambda pt, e, phi, a, ap: _displacement(pt.transformations, pt.rotations
                                                .matrix_from_axis_angle(np.r_[e, phi]),
                                                a, ap)[2:3])


def transfers(add) -> None:
    """The peers of the transfers (the translation a - p; Adjoint of [1, d; 0, 1])."""
    k = "twist_transfer"
    add(k, "Modern Robotics", "`Adjoint(RpToTrans(1, a - p)) t`", "t_P",
        lambda mr, t, a, p: (mr.Adjoint(_shift(mr, a - p)) @ t,))
    add(k, "Pinocchio", "`SE3(1, a - p).act(Motion)`", "t_P",
        lambda pin, t, a, p: (lambda m: (np.r_[m.angular, m.linear],))(
            pin.SE3(np.eye(3), a - p).act(pin.Motion(t[3:], t[:3]))))
    k = "twist_transfer_matrix"
    add(k, "Modern Robotics", "`Adjoint(RpToTrans(1, a - p))`", "U",
        lambda mr, a, p: (mr.Adjoint(_shift(mr, a - p)),))
    add(k, "pytransform3d", "`transformations.adjoint_from_transform`", "U",
        lambda pt, a, p: (pt.transformations.adjoint_from_transform(
            pt.transformations.transform_from(np.eye(3), a - p), check=False),))
    k = "wrench_transfer"
    add(k, "Modern Robotics", "`Adjoint(RpToTrans(1, p - a))^T w`", "w_P",
        lambda mr, w, a, p: (mr.Adjoint(_shift(mr, p - a)).T @ w,))
    add(k, "Pinocchio", "`SE3(1, a - p).act(Force)`", "w_P",
        lambda pin, w, a, p: (lambda f: (np.r_[f.angular, f.linear],))(
            pin.SE3(np.eye(3), a - p).act(pin.Force(w[3:], w[:3]))))
    add("plucker_transfer", "Modern Robotics", "`Adjoint(RpToTrans(1, a - b)) kappa`",
        "kappa_B", lambda mr, kap, a, b: (mr.Adjoint(_shift(mr, a - b)) @ kap,))
    add("plucker_transfer", "Pinocchio", "`SE3(1, a - b).act(Motion)`", "kappa_B",
        lambda pin, kap, a, b: (lambda m: (np.r_[m.angular, m.linear],))(
            pin.SE3(np.eye(3), a - b).act(pin.Motion(kap[3:], kap[:3]))))
    add("wrench_transfer_matrix", "Modern Robotics", "`Adjoint(RpToTrans(1, p - a))^T`", "V",
        lambda mr, a, p: (mr.Adjoint(_shift(mr, p - a)).T,))


def dynamics(add) -> None:
    """The peers of the mass properties and dynamics (Pinocchio's spatial inertia: linear first)."""
    add("inertia_at_point", "Pinocchio", "`Inertia(m, c - a, I_C).matrix()` (angular block)",
        "I_A", lambda pin, I, m, c, a: (_pin_inertia(pin, I, m, c, a)[3:, 3:],))
    add("inertia_dyad_at_point", "Pinocchio",
        "`Inertia(m, c - a, I_C).matrix()` (blocks reordered, angular first)", "M_A",
        lambda pin, I, m, c, a: (_swap(_pin_inertia(pin, I, m, c, a)),))
    add("kinetic_energy", "Pinocchio", "`Inertia(m, 0, I_C).vtiv(Motion(c_dot, omega)) / 2`",
        "T", lambda pin, I, m, w, cd: (pin.Inertia(float(m), np.zeros(3), I).vtiv(
            pin.Motion(cd, w)) / 2,))
    add("newton_euler_wrench", "Pinocchio",
        "`Inertia(m, 0, I_C) * Motion(c_ddot, omega_dot) + vxiv(Motion(0, omega))`", "w",
        _newton_euler)
    add("newton_euler_residual", "Pinocchio", "the `newton_euler_wrench` peer `- [n; f]`", "r",
        lambda pin, I, m, w, wd, cdd, n, f: (_newton_euler(pin, I, m, w, wd, cdd)[0]
                                             - np.r_[n, f],))


def so3(add) -> None:
    """The exponential and logarithm of SO(3) and their Jacobians."""
    k = "rotation_from_rotation_vector"
    add(k, "pytransform3d", "`rotations.matrix_from_compact_axis_angle`", "Q",
        lambda pt, w: (pt.rotations.matrix_from_compact_axis_angle(w),))
    add(k, "Pinocchio", "`exp3`", "Q", lambda pin, w: (pin.exp3(w),))
    add(k, "PyPose", "`so3(w).matrix()`", "Q", lambda pp, w: (_np(pp.so3(_torch(w)).matrix()),))
    add(k, "jaxlie", "`SO3.exp(w).as_matrix()`", "Q",
        lambda jl, w: (_jl(jl, "exp3", lambda: lambda w: jl.SO3.exp(w).as_matrix(), w),))
    add(k, "spatialmath", "`base.trexp`", "Q", lambda sb, w: (sb.trexp(w),))
    add(k, "Modern Robotics", "`MatrixExp3(VecToso3(w))`", "Q",
        lambda mr, w: (mr.MatrixExp3(mr.VecToso3(w)),))
    k = "rotation_from_rotation_vector_with_jacobians"
    add(k, "Pinocchio", "`exp3`, `Jexp3` (right): `Q hat(J_r e_k)`", "Q Q_D_w",
        lambda pin, w: (lambda Q: (Q, _dexp3(Q, pin.Jexp3(w))))(pin.exp3(w)))
    add(k, "PyPose", "`so3(w).matrix()`, `so3(w).Jr()`: `Q hat(J_r e_k)`", "Q Q_D_w",
        lambda pp, w: (lambda x: (lambda Q: (Q, _dexp3(Q, _np(x.Jr()))))(_np(x.matrix())))(
            pp.so3(_torch(w))))
    k = "rotation_vector_from_rotation"
    add(k, "pytransform3d", "`rotations.compact_axis_angle_from_matrix`", "w",
        lambda pt, Q: (pt.rotations.compact_axis_angle_from_matrix(Q, check=False),))
    add(k, "Pinocchio", "`log3`", "w", lambda pin, Q: (pin.log3(Q),))
    add(k, "PyPose", "`mat2SO3(Q).Log()`", "w",
        lambda pp, Q: (_np(pp.mat2SO3(_torch(Q), check=False).Log()),))
    add(k, "jaxlie", "`SO3.from_matrix(Q).log()`", "w",
        lambda jl, Q: (_jl(jl, "log3", lambda: lambda Q: jl.SO3.from_matrix(Q).log(), Q),))
    add(k, "spatialmath", "`base.trlog(Q, twist=True)`", "w",
        lambda sb, Q: (sb.trlog(Q, check=False, twist=True),))
    add(k, "Modern Robotics", "`so3ToVec(MatrixLog3(Q))`", "w",
        lambda mr, Q: (mr.so3ToVec(mr.MatrixLog3(Q)),))
    for side, s in (("left", -1.0), ("right", 1.0)):
        arg = "(w)" if s > 0 else "(-w)"
        k = f"rotation_vector_{side}_jacobian"
        add(k, "pytransform3d", f"`rotations.left_jacobian_SO3{'(-w)' if s > 0 else '(w)'}`",
            "J", lambda pt, w, s=s: (pt.rotations.left_jacobian_SO3(-s * w),))
        add(k, "Pinocchio", f"`Jexp3{arg}` (right)", "J",
            lambda pin, w, s=s: (pin.Jexp3(s * w),))
        add(k, "PyPose", f"`so3{arg}.Jr()`", "J",
            lambda pp, w, s=s: (_np(pp.so3(_torch(s * w)).Jr()),))
        add(k, "spatialmath", f"`base.exp2jac{'(-w)' if s > 0 else '(w)'}`", "J",
            lambda sb, w, s=s: (sb.exp2jac(-s * w),))
        k = f"rotation_vector_{side}_jacobian_inverse"
        add(k, "pytransform3d",
            f"`rotations.left_jacobian_SO3_inv{'(-w)' if s > 0 else '(w)'}`", "J",
            lambda pt, w, s=s: (pt.rotations.left_jacobian_SO3_inv(-s * w),))
        add(k, "Pinocchio", f"`Jlog3(exp3{arg})` (\\|w\\| < pi)", "J",
            lambda pin, w, s=s: (_in_log_domain(w), pin.Jlog3(pin.exp3(s * w)))[1:])
        add(k, "jaxlie", f"`SO3.exp{arg}.jlog()` (\\|w\\| < pi)", "J",
            lambda jl, w, s=s: (_in_log_domain(w), _jl(
                jl, "jlog3", lambda: lambda w: jl.SO3.exp(w).jlog(), s * w))[1:])


def se3(add) -> None:
    """The exponential and logarithm of SE(3) and the left Jacobian."""
    k = "transform_from_exponential_coordinates"
    add(k, "pytransform3d", "`transformations.transform_from_exponential_coordinates`", "T",
        lambda pt, xi: (pt.transformations.transform_from_exponential_coordinates(xi),))
    add(k, "Pinocchio", "`exp6(Motion(v, w)).homogeneous`", "T",
        lambda pin, xi: (pin.exp6(pin.Motion(xi[3:], xi[:3])).homogeneous,))
    add(k, "PyPose", "`se3([v; w]).matrix()`", "T",
        lambda pp, xi: (_np(pp.se3(_torch(_vw(xi))).matrix()),))
    add(k, "jaxlie", "`SE3.exp([v; w]).as_matrix()`", "T",
        lambda jl, xi: (_jl(jl, "exp6", lambda: lambda x: jl.SE3.exp(x).as_matrix(),
                            _vw(xi)),))
    add(k, "spatialmath", "`base.trexp([v; w])`", "T", lambda sb, xi: (sb.trexp(_vw(xi)),))
    add(k, "Modern Robotics", "`MatrixExp6(VecTose3(xi))`", "T",
        lambda mr, xi: (mr.MatrixExp6(mr.VecTose3(xi)),))
    add("transform_from_exponential_coordinates_with_jacobians", "Pinocchio",
        "`exp6`, `Jexp6` (right, `[v; w]` reordered): `T hat(J_r e_k)`", "T T_D_xi",
        lambda pin, xi: (lambda m: (lambda T: (T, _dexp6(T, _swap(pin.Jexp6(m)))))(
            pin.exp6(m).homogeneous))(pin.Motion(xi[3:], xi[:3])))
    k = "exponential_coordinates_from_transform"
    add(k, "pytransform3d", "`transformations.exponential_coordinates_from_transform`", "xi",
        lambda pt, T: (pt.transformations.exponential_coordinates_from_transform(
            T, check=False),))
    add(k, "Pinocchio", "`log6(SE3(T))` (`[v; w]` reordered)", "xi",
        lambda pin, T: (lambda m: (np.r_[m.angular, m.linear],))(pin.log6(pin.SE3(T))))
    add(k, "PyPose", "`mat2SE3(T).Log()` (`[v; w]` reordered)", "xi",
        lambda pp, T: (_vw(_np(pp.mat2SE3(_torch(T), check=False).Log())),))
    add(k, "jaxlie", "`SE3.from_matrix(T).log()` (`[v; w]` reordered)", "xi",
        lambda jl, T: (_vw(_jl(jl, "log6", lambda: lambda T: jl.SE3.from_matrix(T).log(),
                               T)),))
    add(k, "spatialmath", "`base.trlog(T, twist=True)` (`[v; w]` reordered)", "xi",
        lambda sb, T: (_vw(sb.trlog(T, check=False, twist=True)),))
    add(k, "Modern Robotics", "`se3ToVec(MatrixLog6(T))`", "xi",
        lambda mr, T: (mr.se3ToVec(mr.MatrixLog6(T)),))
    k = "exponential_coordinates_left_jacobian"
    add(k, "pytransform3d", "`transformations.left_jacobian_SE3`", "J",
        lambda pt, xi: (pt.transformations.left_jacobian_SE3(xi),))
    add(k, "Pinocchio", "`Jexp6(Motion(-v, -w))` (right, `[v; w]` reordered)", "J",
        lambda pin, xi: (_swap(pin.Jexp6(pin.Motion(-xi[3:], -xi[:3]))),))
    k = "exponential_coordinates_left_jacobian_inverse"
    add(k, "pytransform3d", "`transformations.left_jacobian_SE3_inv`", "J",
        lambda pt, xi: (pt.transformations.left_jacobian_SE3_inv(xi),))
    add(k, "Pinocchio", "`Jlog6(exp6(Motion(-v, -w)))` (`[v; w]` reordered; \\|w\\| < pi)",
        "J", lambda pin, xi: (_in_log_domain(xi[:3]), _swap(pin.Jlog6(pin.exp6(
            pin.Motion(-xi[3:], -xi[:3])))))[1:])
    add(k, "jaxlie", "`SE3.exp(-[v; w]).jlog()` (`[v; w]` reordered; \\|w\\| < pi)", "J",
        lambda jl, xi: (_in_log_domain(xi[:3]), _swap(_jl(
            jl, "jlog6", lambda: lambda x: jl.SE3.exp(x).jlog(), -_vw(xi))))[1:])


def quaternions(add) -> None:
    """Euler-Rodrigues parameters (unit quaternions, scalar last in rigidsym)."""
    k = "euler_rodrigues_from_rotation"
    add(k, "pytransform3d", "`rotations.quaternion_from_matrix` (w first)", "eta",
        lambda pt, Q: (lambda q: (_positive(np.r_[q[1:], q[0]]),))(
            pt.rotations.quaternion_from_matrix(Q, strict_check=False)))
    add(k, "Pinocchio", "`Quaternion(Q).coeffs()` (xyzw)", "eta",
        lambda pin, Q: (_positive(pin.Quaternion(Q).coeffs()),))
    add(k, "PyPose", "`mat2SO3(Q)` (xyzw)", "eta",
        lambda pp, Q: (_positive(_np(pp.mat2SO3(_torch(Q), check=False))),))
    add(k, "jaxlie", "`SO3.from_matrix(Q).as_quaternion_xyzw()`", "eta",
        lambda jl, Q: (_positive(_jl(jl, "r2q", lambda: lambda Q: jl.SO3.from_matrix(Q)
                                     .as_quaternion_xyzw(), Q)),))
    add(k, "spatialmath", "`base.r2q` (w first)", "eta", _er_sm)
    k = "euler_rodrigues_product"
    add(k, "pytransform3d", "`rotations.concatenate_quaternions` (w first)", "eta",
        lambda pt, a, b: (lambda q: (np.r_[q[1:], q[0]],))(
            pt.rotations.concatenate_quaternions(np.r_[a[3], a[:3]], np.r_[b[3], b[:3]])))
    add(k, "Pinocchio", "`Quaternion(w, x, y, z) * Quaternion(...)`", "eta",
        lambda pin, a, b: ((pin.Quaternion(a[3], *a[:3]) * pin.Quaternion(b[3], *b[:3]))
                           .coeffs(),))
    add(k, "spatialmath", "`base.qqmul` (w first)", "eta",
        lambda sb, a, b: (lambda q: (np.r_[q[1:], q[0]],))(
            sb.qqmul(np.r_[a[3], a[:3]], np.r_[b[3], b[:3]])))
    add(k, "PyPose", "`SO3(eta1) @ SO3(eta2)` (xyzw)", "eta",
        lambda pp, a, b: (_np(pp.SO3(_torch(a)) @ pp.SO3(_torch(b))),))
    add(k, "jaxlie", "`SO3.from_quaternion_xyzw(eta1) @ ...(eta2)`", "eta",
        lambda jl, a, b: (_jl(jl, "qq", lambda: lambda a, b: (
            jl.SO3.from_quaternion_xyzw(a) @ jl.SO3.from_quaternion_xyzw(b))
            .as_quaternion_xyzw(), a, b),))
