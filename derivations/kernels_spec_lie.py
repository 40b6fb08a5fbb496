"""The kernels of the Lie-group maps: each composes the formula functions of
:mod:`rigidsym.derivations.lie_maps` (verified by ``derivations/lie_groups.py``); their
removable singularities at ``w = 0`` become certified series branches in the generator
(:mod:`rigidsym.codegen.removable.singularities`). The logarithms reuse the natural invariants'
branches near ``phi = pi`` (the axis from the symmetric part of ``Q``).

They join the book's ``KERNELS`` (``derivations/kernels_spec.py``); their names are pinned in
``tests/test_public_api.py``.
"""

from __future__ import annotations

from functools import partial

import sympy as sp

from rigidsym.codegen.spec import Arg, Branch, Grouped, Kernel, Out

from .kernel_wiring import Q_ARG, _ni_common, _ni_near_pi, _ni_when, formula

__all__ = ["LIE_KERNELS"]

_LM = "rigidsym.derivations.lie_maps."
_IDS = {"so3": ("sola:exp-so3", "sola:log-exp-so3", "sola:exp-log-so3"),
        "jac": ("sola:jl-definition", "sola:jr-definition", "sola:jl-jr", "sola:jl-R-jr",
                "sola:jl-w", "sola:jl-inverse"),
        "se3": ("sola:exp-se3", "sola:log-exp-se3"),
        "se3jac": ("barfoot:se3-jl-definition", "barfoot:se3-jl-xi",
                   "barfoot:se3-jl-inverse", "barfoot:se3-q-block"),
        "quat": ("sola:quat-of-rotation", "sola:quat-product")}
W = Arg("w", (3,), "any", "rotation vector w = phi e [rad]")
XI = Arg("xi", (6,), "any", "exponential coordinates [w; v] ([rad]; [m])")
T_ARG = Arg("T", (4, 4), "transform", "homogeneous transform [[R, p], [0, 1]] (R a rotation)")


def _call(out, fn):
    def build(**kw):
        return {out: formula(_LM + fn)(*kw.values())}
    return build


def _mark(e):
    # a sub-expression the removable pass keeps together (codegen.spec.Grouped)
    return e if e.is_Atom or (-e).is_Atom else Grouped(e)


_grouped = partial(sp.Matrix.applyfunc, f=_mark)


def _se3_exp(xi):
    # J_l(w) v as lie_maps.rotation_vector_left_jacobian_times writes it, its w x v and w . v
    # Grouped: distributed into monomials, the removable pass reads w0^2 as theta^2 - w1^2 -
    # w2^2 and folds sin(theta)/theta v back into v - (1 - sin(theta)/theta) v, which loses
    # theta relative at large |w| (float32 4.65 u median at |w| = 24.5)
    return {"T": formula(_LM + "transform_from_exponential_coordinates")(xi, group=_mark)}


def _se3_jl(xi):
    # the declared [[J_l, 0], [Q, J_l]] with lie_maps.se3_q_block's products of w and v
    # Grouped (w . v, v w^T + w v^T, w w^T): distributed, the removable pass folds
    # its coefficients back into Barfoot's, whose terms of size |v| cancel to |v|/theta
    w, v = xi[:3, :], xi[3:, :]
    J = formula(_LM + "rotation_vector_left_jacobian")(w)
    Q = formula(_LM + "se3_q_block")(w, v, group=_mark)
    return {"J": sp.Matrix.vstack(sp.Matrix.hstack(J, sp.zeros(3)), sp.Matrix.hstack(Q, J))}


def _se3_jl_inverse(xi):
    # the declared block inverse (lie_maps), its -J^-1 Q J^-1 kept as products of 3 x 3
    # matrices: each entry of J^-1 and Q and of Q J^-1 Grouped, so the
    # removable pass rewrites each alone and never distributes the product into monomials
    # of degree 9 in w (median 4-10 u at |w| in {3, pi, 4.5}, 24 of 60 samples outside the
    # rule's max(2 e_peer, 4 u) of pytransform3d's left_jacobian_SE3_inv, which multiplies);
    # Q as lie_maps.se3_q_block writes it, without Barfoot's cancellation at large |w|
    w, v = xi[:3, :], xi[3:, :]
    Ji = _grouped(formula(_LM + "rotation_vector_left_jacobian_inverse")(w))
    Qb = _grouped(formula(_LM + "se3_q_block")(w, v, group=_mark))
    lower = -Ji * _grouped(Qb * Ji)
    return {"J": sp.Matrix.vstack(sp.Matrix.hstack(Ji, sp.zeros(3)),
                                  sp.Matrix.hstack(lower, Ji))}


def _log_small(Q):
    # theta < pi/4 (tr Q > 1 + sqrt 2): theta = asin(|vect Q|), no acos; the quotient
    # asin(s)/s is removable at s = 0 (codegen.removable); verified: sola:log-so3-small
    return {"w": formula(_LM + "rotation_vector_from_rotation_small")(Q)}


def _log_main(Q):
    return {"w": formula(_LM + "rotation_vector_from_rotation")(Q)}


def _log_near_pi(Q, k):
    # the natural invariants' axis e (column k of the symmetric part, signed by vect Q), and
    # phi = atan2(e . vect Q, cos phi): e . vect Q = sin phi = |vect Q| on SO(3), but its
    # derivative reads the direction of vect Q from e (well conditioned), where |vect Q|'s
    # reads it from vect Q / |vect Q|, a vector of size sin phi rounded to u: the Jacobian
    # kernel was 6.5e10 u off at phi = pi - 3e-15 (the value is the same either way)
    v, _, c = _ni_common(Q)
    e = _ni_near_pi(Q, k)["e"]
    return {"w": sp.atan2((e.T * v)[0], c) * e}


def _log_when(Q, k):
    return _ni_when(Q, k)


def _log_small_when(Q):
    # phi < pi/4 (tr Q > 1 + sqrt 2): asin's condition 1/cos(phi) stays under sqrt 2; at the
    # pi/2 of before it grew without bound (3e-13 relative at phi = pi/2 - 1e-3)
    # (written without a root: the array printers' sqrt takes tensors only)
    t = Q.trace() - 1
    return sp.And(t > 0, t**2 > 2)


def _log_branches(wrap):
    near = tuple(Branch(f"near_pi_{k}", partial(_log_when, k=k),
                        lambda k=k, **kw: wrap(_log_near_pi(kw["Q"], k), kw),
                        doc=f"cos(phi) < -1/2, Q[{k},{k}] the largest diagonal entry: the axis "
                            f"from column {k} of the symmetric part (never acos)")
                 for k in range(3))
    small = Branch("small", lambda Q: _log_small_when(Q),
                   lambda **kw: wrap(_log_small(kw["Q"]), kw),
                   doc="phi < pi/4: w = (asin s / s) vect(Q), s = |vect(Q)|, no acos")
    return (*near, small)


def _se3_near_pi(T, k):
    w = _log_near_pi(T[:3, :3], k)["w"]
    Ji = formula(_LM + "rotation_vector_left_jacobian_inverse")(w)
    return {"xi": sp.Matrix.vstack(w, Ji * T[:3, 3])}


def _se3_small(T):
    # theta < pi/4: w and v in s = |vect(R)| = sin theta alone (asin, sqrt(1 - s^2), no
    # acos), removable at s = 0 (codegen.removable); verified: sola:log-se3-small
    return {"xi": formula(_LM + "exponential_coordinates_from_transform_small")(T)}


_SE3_BRANCHES = (*(
    Branch(f"near_pi_{k}", lambda T, k=k: _log_when(T[:3, :3], k),
           lambda T, k=k: _se3_near_pi(T, k),
           doc=f"cos(phi) < -1/2, R[{k},{k}] the largest diagonal entry: w from column {k} "
               "of the symmetric part of R")
    for k in range(3)),
    Branch("small", lambda T: _log_small_when(T[:3, :3]), _se3_small,
           doc="phi < pi/4: w = (asin s / s) vect(R), s = |vect(R)|, and v in s alone "
               "(no acos): smooth at T = 1"))


def _er_main(Q):
    return {"eta": formula(_LM + "euler_rodrigues_from_rotation")(Q)}


def _er_branch(Q, k):
    # Shepperd: tr Q <= 0 and Q[k,k] the largest diagonal entry: r_k = sqrt(1 + 2 Q_kk -
    # tr Q) / 2 (at least 1/2), the rest from the off-diagonal sums; signed so r0 >= 0
    i, j = (k + 1) % 3, (k + 2) % 3
    rk = sp.sqrt(1 + 2 * Q[k, k] - Q.trace()) / 2
    r = [0, 0, 0]
    r[k] = rk
    r[i] = (Q[i, k] + Q[k, i]) / (4 * rk)
    r[j] = (Q[j, k] + Q[k, j]) / (4 * rk)
    r0 = (Q[j, i] - Q[i, j]) / (4 * rk)
    sign = sp.Piecewise((-1, r0 < 0), (1, True))
    return {"eta": sign * sp.Matrix([*r, r0])}


def _er_when(Q, k):
    d = [Q[n, n] for n in range(3)]
    return sp.And(Q.trace() <= 0, *[d[k] >= d[n] for n in range(3) if n != k])


LIE_KERNELS = [
    Kernel(name="rotation_from_rotation_vector", summary="Exp of so(3): the rotation of w.",
           formula="Q = 1 + (sin t / t) [w] + ((1 - cos t) / t^2) [w]^2, t = norm of w",
           ids=_IDS["so3"], sources=(_LM + "rotation_from_rotation_vector",), args=(W,),
           outputs=(Out("Q", (3, 3), "rotation matrix"),),
           build=_call("Q", "rotation_from_rotation_vector")),
    Kernel(name="rotation_vector_from_rotation", summary="Log of SO(3): the rotation vector "
           "w = phi e of Q, phi in [0, pi].",
           formula="w = (phi / sin phi) vect(Q); asin near 0, the symmetric part near pi",
           ids=(*_IDS["so3"], "sola:log-so3-small"),
           sources=(_LM + "rotation_vector_from_rotation",
                    _LM + "rotation_vector_from_rotation_small"), args=(Q_ARG,),
           outputs=(Out("w", (3,), "rotation vector [rad]"),), build=_log_main,
           branches=_log_branches(lambda r, kw: r),
           notes="At phi = pi exactly, w and -w are both logarithms; the sign follows "
                 "natural_invariants_from_rotation's rule.", branch_jacobian=True),
    *[Kernel(name=f"rotation_vector_{side}_jacobian{inv}",
             summary=f"The {side} Jacobian{' inverse' if inv else ''} of SO(3) at w.",
             formula=f"J_{side[0]}{'^-1' if inv else ''}(w), Solà et al. 2018 App. B",
             ids=_IDS["jac"], sources=(_LM + f"rotation_vector_{side}_jacobian{inv}",),
             args=(W,), outputs=(Out("J", (3, 3), ""),),
             build=_call("J", f"rotation_vector_{side}_jacobian{inv}"),
             singular="theta = 2 pi k, k != 0 (theta = norm of w)" if inv else "")
      for side in ("left", "right") for inv in ("", "_inverse")],
    Kernel(name="transform_from_exponential_coordinates",
           summary="Exp of se(3): the transform of xi = [w; v].",
           formula="T = [[Exp(w), J_l(w) v], [0, 1]]", ids=(*_IDS["se3"], "sola:jl-times"),
           sources=(_LM + "transform_from_exponential_coordinates",), args=(XI,),
           outputs=(Out("T", (4, 4), "homogeneous transform"),), build=_se3_exp),
    *[Kernel(name=f"exponential_coordinates_left_jacobian{inv}",
             summary=f"The left Jacobian{' inverse' if inv else ''} of SE(3) at xi = [w; v] "
                     "(6 x 6, angular first).",
             formula="[[J_l(w), 0], [Q(v, w), J_l(w)]] (Barfoot Sec. 7.1.5, reordered)"
             if not inv else "the block inverse of [[J_l, 0], [Q, J_l]]",
             ids=_IDS["se3jac"], sources=(_LM + f"exponential_coordinates_left_jacobian{inv}",),
             args=(XI,), outputs=(Out("J", (6, 6), ""),),
             build=_se3_jl_inverse if inv else _se3_jl,
             singular="theta = 2 pi k, k != 0 (theta = norm of w)" if inv else "",
             # 216 entries of degree 5: sympy's derivative of the expanded formula took
             # minutes to generate; forward mode over the optimised program takes seconds
             jacobian_from="program")
      for inv in ("", "_inverse")],
    Kernel(name="exponential_coordinates_from_transform",
           summary="Log of SE(3): the exponential coordinates xi = [w; v] of T, norm of w in "
                   "[0, pi].",
           formula="w = Log(R), v = J_l(w)^-1 p; below pi/4 in s = norm of vect(R) alone "
                   "(asin, sqrt(1 - s^2)), near pi the symmetric part of R",
           ids=(*_IDS["se3"], "sola:log-se3-small"),
           sources=(_LM + "exponential_coordinates_from_transform",
                    _LM + "exponential_coordinates_from_transform_small"), args=(T_ARG,),
           outputs=(Out("xi", (6,), "[w; v]"),),
           build=lambda T: {"xi": formula(_LM + "exponential_coordinates_from_transform")(T)},
           branches=_SE3_BRANCHES,
           notes="check=True validates T: its last row [0, 0, 0, 1], its R a rotation.",
           # its Jacobian (6 x 16, five branches) by sympy on the expanded formula compiled
           # in 516 s to 5331 operations; by forward mode over each branch's optimised
           # program (codegen.derivatives.vjp.jacobian_program) in seconds
           branch_jacobian=True, jacobian_from="program"),
    Kernel(name="euler_rodrigues_from_rotation",
           summary="The Euler-Rodrigues parameters eta = [r; r0] of Q, r0 >= 0.",
           formula="r0 = sqrt(1 + tr Q) / 2, r = vect(Q) / (2 r0); Shepperd's branches for "
                   "tr Q <= 0", ids=_IDS["quat"],
           sources=(_LM + "euler_rodrigues_from_rotation",), args=(Q_ARG,),
           outputs=(Out("eta", (4,), "[r; r0], unit, r0 >= 0"),), build=_er_main,
           branches=tuple(Branch(f"shepperd_{k}", partial(_er_when, k=k),
                                 partial(_er_branch, k=k),
                                 doc=f"tr Q <= 0, Q[{k},{k}] the largest diagonal entry")
                          for k in range(3)),
           notes="At phi = pi exactly (r0 = 0) eta and -eta are both parameters of Q.",
           branch_jacobian=True),
    Kernel(name="euler_rodrigues_product",
           summary="The product of Euler-Rodrigues parameters (Hamilton, scalar last).",
           formula="[a0 b + b0 a + a x b; a0 b0 - a . b]", ids=_IDS["quat"],
           sources=(_LM + "euler_rodrigues_product",),
           args=(Arg("eta1", (4,), "any", "[r; r0] of the first rotation"),
                 Arg("eta2", (4,), "any", "[r; r0] of the second rotation")),
           outputs=(Out("eta", (4,), "[r; r0] of Q(eta1) Q(eta2)"),),
           build=_call("eta", "euler_rodrigues_product")),
]
