"""The Lie-group maps of SO(3) and SE(3) from unconstrained vectors: formula
functions, each the closed form of its sources, composed by the kernels of
``derivations/kernels_spec_lie.py`` and verified by the declarations of
``derivations/lie_groups.py``.

Sources (cited per function): Solà, Deray & Atchuthan, "A micro Lie theory for state
estimation in robotics" (arXiv:1812.01537, 2018), App. B (SO(3)), D (SE(3)); Barfoot,
*State Estimation for Robotics* (2017), Sec. 7.1.3-7.1.5; Lynch & Park, *Modern Robotics*
(MR) (3.51)-(3.54), (3.88)-(3.92); Angeles, Sec. 2.3 (the Euler-Rodrigues parameters).

Conventions (NOTATION.md): a rotation vector ``w = theta e`` (3,), ``theta = |w|`` [rad];
exponential coordinates angular first, ``xi = [w; v]`` (6,) as Angeles' twists and MR;
the 6 x 6 Jacobian of SE(3) in the same order (Barfoot's ``[[J, Q], [0, J]]`` for his
``[rho; phi]`` becomes ``[[J, 0], [Q, J]]``); Euler-Rodrigues parameters scalar last,
``eta = [r; r0]``, as ``rotation_from_euler_rodrigues``. Every quotient in ``theta`` below is
a removable singularity at ``w = 0`` (the kernels replace it by its certified series,
:mod:`rigidsym.codegen.removable.singularities`).

Long: one subject, the closed forms of the maps of SO(3) and SE(3), each with its sources and
the derivation of the rewritten forms the kernels use (Q of the SE(3) Jacobian and J_l(w) v
without their cancellation at large |w|) beside the printed form they are proved
equal to; the kernels and the declarations name these functions by this module's path.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.declare import as_vector, cpm, norm3, vect

__all__ = ["rotation_from_rotation_vector", "rotation_vector_from_rotation",
           "transform_from_exponential_coordinates", "exponential_coordinates_from_transform",
           "rotation_vector_left_jacobian", "rotation_vector_right_jacobian",
           "rotation_vector_left_jacobian_inverse", "rotation_vector_right_jacobian_inverse",
           "exponential_coordinates_left_jacobian",
           "exponential_coordinates_left_jacobian_inverse", "euler_rodrigues_from_rotation",
           "euler_rodrigues_product", "se3_q_block", "se3_q_block_barfoot",
           "rotation_vector_left_jacobian_times", "rotation_vector_from_rotation_small",
           "exponential_coordinates_from_transform_small"]


def _w(w):
    w = as_vector(w, "w")
    return w, cpm(w), norm3(w)


def rotation_from_rotation_vector(w) -> sp.Matrix:
    """``Exp(w) = 1 + (sin theta / theta) [w] + ((1 - cos theta) / theta^2) [w]^2``.

    Source: Solà et al. 2018, App. B (Exp of SO(3)); Barfoot Sec. 7.1.3; MR (3.51) with
    ``w = theta omega``; Angeles (2.49) with ``w = phi e``.

    Args:
        w: 3 x 1 rotation vector [rad].

    Returns:
        3 x 3 rotation matrix.
    """
    w, W, th = _w(w)
    return sp.eye(3) + sp.sin(th) / th * W + (1 - sp.cos(th)) / th**2 * W * W


def rotation_vector_from_rotation(Q) -> sp.Matrix:
    """``Log(Q) = (theta / sin theta) vect(Q)``, ``theta = acos((tr Q - 1) / 2)``.

    Source: Solà et al. 2018, App. B (Log of SO(3)); MR (3.53)-(3.54). The principal branch
    ``theta`` in ``[0, pi]``; singular as printed at ``theta = 0`` (removable) and at
    ``theta = pi`` (the kernel's branch there reads the axis from ``(Q + Q^T)/2``).

    Args:
        Q: 3 x 3 rotation matrix.

    Returns:
        3 x 1 rotation vector ``w`` with ``|w|`` in ``[0, pi]`` [rad].
    """
    Q = sp.Matrix(Q)
    th = sp.acos((Q.trace() - 1) / 2)
    return th / sp.sin(th, evaluate=False) * vect(Q)


def rotation_vector_left_jacobian(w) -> sp.Matrix:
    """``J_l(w) = 1 + ((1 - cos theta)/theta^2) [w] + ((theta - sin theta)/theta^3) [w]^2``.

    Source: Solà et al. 2018, App. B (left Jacobian of SO(3)); Barfoot Sec. 7.1.5; MR's
    ``G(theta) / theta`` of (3.88). Defined by ``d/dt Exp(w) Exp(w)^T = [J_l(w) w_dot]``.

    Args:
        w: 3 x 1 rotation vector [rad].

    Returns:
        3 x 3 matrix.
    """
    w, W, th = _w(w)
    return sp.eye(3) + (1 - sp.cos(th)) / th**2 * W + (th - sp.sin(th)) / th**3 * W * W


def _ungrouped(x):
    return x


def rotation_vector_left_jacobian_times(w, v, group=None) -> sp.Matrix:
    """``J_l(w) v = (sin theta / theta) v + ((1 - cos theta)/theta^2) w x v + ((theta - sin
    theta)/theta^3) (w . v) w``: :func:`rotation_vector_left_jacobian` applied to ``v``.

    Exactly ``J_l(w) v`` (``[w]^2 v = (w . v) w - theta^2 v``, and ``1 - theta^2 (theta -
    sin theta)/theta^3 = sin theta / theta``), written so that no two terms cancel at large
    ``theta``: as ``v + a [w] v + b [w]^2 v`` the part of ``v`` across ``w`` is ``v - (1 -
    sin theta/theta) v``, which loses ``theta`` relative when ``J_l v`` is ``|v|/theta``
    (4.7 u median at ``|w| = 24.5`` in float32, the search's 1.16 times the rule).

    Source: Solà et al. 2018, App. B (``J_l``) and App. D (the translation of ``Exp`` of
    SE(3)); Barfoot Sec. 7.1.3 (``J v``); MR (3.88) (``G(theta) v``).

    Args:
        w: 3 x 1 rotation vector [rad].
        v: 3 x 1 vector.
        group: the kernels' marker of a sub-expression kept together (``w x v`` and
            ``w . v``, so that the removable pass does not distribute them back into the
            monomials of ``v + a [w] v + b [w]^2 v``), or None.

    Returns:
        3 x 1 vector.
    """
    g = group or _ungrouped
    w, _, th = _w(w)
    v = as_vector(v, "v")
    wxv = w.cross(v).applyfunc(g)
    wv = g((w.T * v)[0])
    return sp.sin(th) / th * v + (1 - sp.cos(th)) / th**2 * wxv \
        + (th - sp.sin(th)) / th**3 * wv * w


def rotation_vector_right_jacobian(w) -> sp.Matrix:
    """``J_r(w) = 1 - ((1 - cos theta)/theta^2) [w] + ((theta - sin theta)/theta^3) [w]^2``.

    Source: Solà et al. 2018, App. B (right Jacobian of SO(3)); Barfoot Sec. 7.1.5.
    Defined by ``Exp(w)^T d/dt Exp(w) = [J_r(w) w_dot]``.

    Args:
        w: 3 x 1 rotation vector [rad].

    Returns:
        3 x 3 matrix.
    """
    w, W, th = _w(w)
    return sp.eye(3) - (1 - sp.cos(th)) / th**2 * W + (th - sp.sin(th)) / th**3 * W * W


def _inverse_coefficient(th):
    # 1/theta^2 - (1 + cos theta) / (2 theta sin theta), written so that its only
    # denominators are powers of theta and 1 - cos theta (removable at theta = 0)
    return 1 / th**2 - sp.sin(th) / (2 * th * (1 - sp.cos(th)))


def rotation_vector_left_jacobian_inverse(w) -> sp.Matrix:
    """``J_l(w)^-1 = 1 - [w]/2 + (1/theta^2 - sin theta / (2 theta (1 - cos theta))) [w]^2``.

    Source: Solà et al. 2018, App. B; Barfoot Sec. 7.1.5; MR (3.92) with ``w = theta
    omega``. Singular at ``theta = 2 pi k``, ``k != 0`` (removable at ``w = 0``).

    Args:
        w: 3 x 1 rotation vector [rad], ``|w| < 2 pi``.

    Returns:
        3 x 3 matrix.
    """
    w, W, th = _w(w)
    return sp.eye(3) - W / 2 + _inverse_coefficient(th) * W * W


def rotation_vector_right_jacobian_inverse(w) -> sp.Matrix:
    """``J_r(w)^-1 = 1 + [w]/2 + (1/theta^2 - sin theta / (2 theta (1 - cos theta))) [w]^2``.

    Source: Solà et al. 2018, App. B; Barfoot Sec. 7.1.5.

    Args:
        w: 3 x 1 rotation vector [rad], ``|w| < 2 pi``.

    Returns:
        3 x 3 matrix.
    """
    w, W, th = _w(w)
    return sp.eye(3) + W / 2 + _inverse_coefficient(th) * W * W


def _xi(xi):
    xi = sp.Matrix(xi)
    if xi.shape != (6, 1):
        raise ValueError(f"xi: expected a 6 x 1 vector [w; v], got shape {xi.shape}")
    return xi[:3, :], xi[3:, :]


def transform_from_exponential_coordinates(xi, group=None) -> sp.Matrix:
    """``Exp([w; v]) = [[Exp(w), J_l(w) v], [0, 1]]``, ``J_l(w) v`` as
    :func:`rotation_vector_left_jacobian_times` writes it (no cancellation at large
    ``theta``).

    Source: Solà et al. 2018, App. D (Exp of SE(3)); Barfoot Sec. 7.1.3; MR (3.88) with
    ``[w; v] = [omega; v] theta``.

    Args:
        xi: 6 x 1 exponential coordinates ``[w; v]`` ([rad]; [m]).
        group: the kernels' marker of a sub-expression kept together
            (:class:`rigidsym.codegen.spec.Grouped`), or None (the plain formula).

    Returns:
        4 x 4 homogeneous transform.
    """
    w, v = _xi(xi)
    R = rotation_from_rotation_vector(w)
    p = rotation_vector_left_jacobian_times(w, v, group)
    return sp.Matrix.vstack(sp.Matrix.hstack(R, p), sp.Matrix([[0, 0, 0, 1]]))


def exponential_coordinates_from_transform(T) -> sp.Matrix:
    """``Log(T) = [w; J_l(w)^-1 p]`` with ``w = Log(R)`` of ``T = [[R, p], [0, 1]]``.

    Source: Solà et al. 2018, App. D (Log of SE(3)); MR (3.91)-(3.92).

    Args:
        T: 4 x 4 homogeneous transform.

    Returns:
        6 x 1 exponential coordinates ``[w; v]``, ``|w|`` in ``[0, pi]``.
    """
    T = sp.Matrix(T)
    w = rotation_vector_from_rotation(T[:3, :3])
    return sp.Matrix.vstack(w, rotation_vector_left_jacobian_inverse(w) * T[:3, 3])


def rotation_vector_from_rotation_small(Q) -> sp.Matrix:
    """``Log(Q) = (asin s / s) u`` with ``u = vect(Q) = sin theta e``, ``s = |u| = sin
    theta``: the log below a quarter turn, in ``u`` alone (no ``acos``; the kernel's branch
    for ``theta < pi/4``, where ``acos`` of a trace near 1 loses half the digits).

    Source: Solà et al. 2018, App. B (Log of SO(3), ``theta = atan2(|u|, (tr Q - 1)/2)``, here
    ``asin``, exact for ``theta <= pi/2``); Barfoot Sec. 7.1.3 (``phi`` from ``vect`` of the
    skew part). Removable at ``s = 0``.

    Args:
        Q: 3 x 3 rotation matrix, its angle in ``[0, pi/2]``.

    Returns:
        3 x 1 rotation vector ``w`` [rad].
    """
    u = vect(sp.Matrix(Q))
    s = sp.sqrt((u.T * u)[0])
    return sp.asin(s) / s * u


def exponential_coordinates_from_transform_small(T) -> sp.Matrix:
    """``Log(T) = [a u; p - (a/2) u x p + g u x (u x p)]`` with ``u = vect(R)``, ``s = |u|``,
    ``a = asin(s)/s``, ``g = (2 s - asin(s) (1 + sqrt(1 - s^2))) / (2 s^3)``: the SE(3) log
    below a quarter turn in ``s`` alone (the kernel's branch for ``theta < pi/4``).

    With ``theta = asin s`` and ``cos theta = sqrt(1 - s^2)`` (``theta <= pi/2``), ``w = a
    u``, ``[w] = a [u]`` and ``J_l(w)^-1 p = p - [w] p / 2 + c(theta) [w]^2 p`` (Solà et al.
    2018, App. D; Barfoot Sec. 7.1.5), ``c(theta) = 1/theta^2 - (1 + cos theta)/(2 theta sin
    theta)``, so ``c a^2 = g``. Removable at ``s = 0`` (``a -> 1``, ``g -> 1/12``).

    Args:
        T: 4 x 4 homogeneous transform, the angle of its rotation in ``[0, pi/2]``.

    Returns:
        6 x 1 exponential coordinates ``[w; v]``.
    """
    T = sp.Matrix(T)
    u, p = vect(T[:3, :3]), T[:3, 3]
    s = sp.sqrt((u.T * u)[0])
    a = sp.asin(s) / s
    g = (2 * s - sp.asin(s) * (1 + sp.sqrt(1 - s**2))) / (2 * s**3)
    up = u.cross(p)
    return sp.Matrix.vstack(a * u, p - a / 2 * up + g * u.cross(up))


def se3_q_block_barfoot(w, v) -> sp.Matrix:
    """Barfoot's ``Q(v, w)`` block of the left Jacobian of SE(3) as he prints it (Barfoot Sec.
    7.1.5, his ``Q(rho, phi)`` with ``rho = v``, ``phi = w``; Solà et al. 2018, App. D,
    ``Q(rho, theta)``): ``V/2 + a (W V + V W + W V W) + b (W W V + V W W - 3 W V W) + c (W V
    W W + W W V W)`` with ``W = [w]``, ``V = [v]``, ``a = (theta - sin theta)/theta^3``, ``b =
    (theta^2 + 2 cos theta - 2)/(2 theta^4)``, ``c = (2 theta - 3 sin theta + theta cos
    theta)/(2 theta^5)``. The kernels use :func:`se3_q_block`, the same matrix without the
    cancellation (``derivations/lie_groups.py``, ``barfoot:se3-q-block``, proves them equal).
    """
    w, W, th = _w(w)
    V = cpm(as_vector(v, "v"))
    a = (th - sp.sin(th)) / th**3
    b = (th**2 + 2 * sp.cos(th) - 2) / (2 * th**4)
    c = (2 * th - 3 * sp.sin(th) + th * sp.cos(th)) / (2 * th**5)
    return V / 2 + a * (W * V + V * W + W * V * W) + b * (W * W * V + V * W * W - 3 * W * V * W) \
        + c * (W * V * W * W + W * W * V * W)


def se3_q_block(w, v, group=None) -> sp.Matrix:
    """Barfoot's ``Q(v, w)`` block of the left Jacobian of SE(3), written without
    cancellation: ``A V + B (v w^T + w v^T) + (w . v) (D W + G w w^T - H 1)`` with ``W =
    [w]``, ``V = [v]`` and

    - ``A = (1 - cos theta)/theta^2``, ``B = (theta - sin theta)/theta^3`` (those of
      ``J_l``),
    - ``D = (theta sin theta + 2 cos theta - 2)/theta^4``,
    - ``G = (3 sin theta - 2 theta - theta cos theta)/theta^5``,
    - ``H = (sin theta - theta cos theta)/theta^3``.

    Derivation, from Barfoot's printed form (:func:`se3_q_block_barfoot`, Barfoot Sec. 7.1.5;
    Solà et al. 2018, App. D): with ``W = theta E``, ``e`` unit, ``s = e . v`` and ``V = s E
    + U`` (``U = [u]``, ``u = v - s e`` across ``w``), the identities ``E V E = -s E``, ``E^2
    = e e^T - 1``, ``e e^T U + U e e^T = U`` and ``E V + V E = v e^T + e v^T - 2 s 1`` reduce
    its seven products to ``V``, ``E V + V E``, ``s E`` and ``s E^2``; their coefficients are
    ``1/2 - b theta^2 = A``, ``a theta = B theta``, ``1/2 - a theta^2 + b theta^2 - A = sin
    theta/theta - 2 A = D theta^2`` and ``-2 c theta^3 = G theta^3``; ``[w]^2 = w w^T -
    theta^2 1`` then gives ``H = 2 B + G theta^2``.
    Barfoot's terms are each ``O(|v|)`` at large ``theta`` and cancel to a ``Q`` of size
    ``|v|/theta`` (66 .. 280 u in every program at ``|w| ~ 240``, condition 1.8);
    these are each ``O(|v|/theta)``. Exactly Barfoot's matrix for every ``w != 0`` (the
    declaration ``barfoot:se3-q-block`` of ``derivations/lie_groups.py``); every coefficient
    is removable at ``w = 0`` (``A -> 1/2``, ``B -> 1/6``, ``D -> -1/12``, ``G -> -1/60``,
    ``H -> 1/3``).

    Args:
        w: 3 x 1 rotation vector [rad].
        v: 3 x 1 vector ([m]).
        group: the kernels' marker of a sub-expression kept together
            (:class:`rigidsym.codegen.spec.Grouped`: ``w . v`` and the entries of ``v w^T +
            w v^T`` and ``w w^T``, so that the removable pass does not distribute them into
            monomials whose ``w0^2`` it reads as ``theta^2 - w1^2 - w2^2``), or None.

    Returns:
        3 x 3 matrix.
    """
    g = group or _ungrouped
    w, W, th = _w(w)
    v = as_vector(v, "v")
    V = cpm(v)
    A = (1 - sp.cos(th)) / th**2
    B = (th - sp.sin(th)) / th**3
    D = (th * sp.sin(th) + 2 * sp.cos(th) - 2) / th**4
    G = (3 * sp.sin(th) - 2 * th - th * sp.cos(th)) / th**5
    H = (sp.sin(th) - th * sp.cos(th)) / th**3
    wv = g((w.T * v)[0])
    sym = (v * w.T + w * v.T).applyfunc(g)
    ww = (w * w.T).applyfunc(g)
    return A * V + B * sym + wv * (D * W + G * ww - H * sp.eye(3))


def exponential_coordinates_left_jacobian(xi) -> sp.Matrix:
    """The left Jacobian of SE(3), 6 x 6 on ``[w; v]``: ``[[J_l(w), 0], [Q(v, w), J_l(w)]]``.

    Source: Barfoot Sec. 7.1.5 (``[[J, Q], [0, J]]`` on his ``[rho; phi]``, reordered);
    Solà et al. 2018, App. D. Defined by ``d/dt Exp(xi) Exp(xi)^-1 = [J_l(xi) xi_dot]^``.

    Args:
        xi: 6 x 1 exponential coordinates ``[w; v]``.

    Returns:
        6 x 6 matrix.
    """
    w, v = _xi(xi)
    J = rotation_vector_left_jacobian(w)
    return sp.Matrix.vstack(sp.Matrix.hstack(J, sp.zeros(3)),
                            sp.Matrix.hstack(se3_q_block(w, v), J))


def exponential_coordinates_left_jacobian_inverse(xi) -> sp.Matrix:
    """``J_l(xi)^-1 = [[J_l(w)^-1, 0], [-J_l(w)^-1 Q(v, w) J_l(w)^-1, J_l(w)^-1]]``.

    Source: Barfoot Sec. 7.1.5 (the block inverse of ``[[J, Q], [0, J]]``); Solà et al.
    2018, App. D.

    Args:
        xi: 6 x 1 exponential coordinates ``[w; v]``, ``|w| < 2 pi``.

    Returns:
        6 x 6 matrix.
    """
    w, v = _xi(xi)
    Ji = rotation_vector_left_jacobian_inverse(w)
    return sp.Matrix.vstack(sp.Matrix.hstack(Ji, sp.zeros(3)),
                            sp.Matrix.hstack(-Ji * se3_q_block(w, v) * Ji, Ji))


def euler_rodrigues_from_rotation(Q) -> sp.Matrix:
    """``eta = [r; r0]`` with ``r0 = sqrt(1 + tr Q)/2 >= 0``, ``r = vect(Q)/(2 r0)``.

    Source: Angeles Sec. 2.3 (the Euler-Rodrigues parameters ``r = sin(phi/2) e``, ``r0 =
    cos(phi/2)``); Solà et al. 2018, App. B (the quaternion of a rotation). Scalar last, as
    ``rotation_from_euler_rodrigues``; the sign is fixed by ``r0 >= 0``. Singular as
    printed at ``phi = pi`` (``r0 = 0``; the kernel reads ``r`` from the diagonal there).

    Args:
        Q: 3 x 3 rotation matrix.

    Returns:
        4 x 1 unit vector ``[r; r0]``.
    """
    Q = sp.Matrix(Q)
    r0 = sp.sqrt(1 + Q.trace()) / 2
    return sp.Matrix.vstack(vect(Q) / (2 * r0), sp.Matrix([r0]))


def euler_rodrigues_product(eta1, eta2) -> sp.Matrix:
    """The product of Euler-Rodrigues parameters (Hamilton's quaternion product, scalar
    last): ``[r1_0 r2 + r2_0 r1 + r1 x r2; r1_0 r2_0 - r1 . r2]``, the parameters of
    ``Q(eta1) Q(eta2)``.

    Source: Solà et al. 2018, App. B (the quaternion product); Angeles Sec. 2.3.

    Args:
        eta1, eta2: 4 x 1 ``[r; r0]``.

    Returns:
        4 x 1 ``[r; r0]`` (unit when both are).
    """
    a, b = sp.Matrix(eta1), sp.Matrix(eta2)
    for n, x in (("eta1", a), ("eta2", b)):
        if x.shape != (4, 1):
            raise ValueError(f"{n}: expected a 4 x 1 vector [r; r0], got shape {x.shape}")
    r1, s1, r2, s2 = a[:3, :], a[3], b[:3, :], b[3]
    return sp.Matrix.vstack(s1 * r2 + s2 * r1 + r1.cross(r2),
                            sp.Matrix([s1 * s2 - (r1.T * r2)[0]]))
