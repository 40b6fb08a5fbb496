"""What a user's function can be audited as: the operations of the chapter with a verified
kernel, each with the argument layouts a user's function may take (its *forms*) and the
convention generators that apply to it.

A target's truth is its kernel's declaration (the book's formula,
:mod:`rigidsym.codegen.accuracy.harness.reference`); a form says how the kernel's
arguments become the user's positional arguments (``f(T, t)`` with ``T = [[1, a - p], [0,
1]]`` for a twist transfer), a generator (:mod:`.conventions`) how a convention changes the
arguments or the outputs (``[v; w]`` for ``[w; v]``, ``Q^T`` for ``Q``, degrees, the
quaternion's scalar first, the inverse transform, Ad for Ad^-T).

Conventions of the book (docs/NOTATION.md): a twist is ``[omega; v]``, a wrench ``[n;
f]`` (angular first), a quaternion ``eta = [r; r0]`` (scalar last), angles in radians, a
rotation maps body coordinates to the fixed frame (``Q``, active).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

__all__ = ["Form", "Target", "TARGETS", "target", "homogeneous"]


def homogeneous(R: np.ndarray, d: np.ndarray) -> np.ndarray:
    """``[[R, d], [0, 1]]``: the 4 x 4 homogeneous transform of rotation ``R`` (3 x 3) and
    translation ``d`` (3,)."""
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, d
    return T


@dataclass(frozen=True)
class Form:
    """One layout of the user's positional arguments.

    Attributes:
        label: the call as a report prints it (``f(T, t_A)``).
        names: the user's parameter names it fits (for inference by name), one tuple of
            accepted lower-case names per positional argument.
        build: ``build(args) -> list of arrays``: ``args`` the kernel's arguments by name
            (float64 arrays of the declared shapes), in the member's convention.
    """

    label: str
    names: tuple[tuple[str, ...], ...]
    build: Callable[[dict], list]


@dataclass(frozen=True)
class Target:
    """An operation the audit judges a function as.

    Attributes:
        name: the name ``--as`` takes (the kernel's).
        kernel: the verified kernel whose declaration is the truth.
        book: the book's equation and what it computes, for the report.
        forms: the argument layouts tried.
        generators: the names of the convention generators that apply (:mod:`.conventions`).
        dual: the kernel a twist map is confused with on wrenches (and back), or "".
        kind: ``"twist"``, ``"wrench"``, ``"rotation"`` (a rotation output: QᵀQ = 1 and det
            = 1 checked) or ``""``.
        antipodal: an output whose sign at a half turn the input's rounding decides:
            ``"rotation_vector"`` (``-w`` accepted where ``pi - |w|`` is within 16 u pi),
            ``"quaternion"`` (``-eta`` anywhere: the same rotation), ``"axis"``
            (``[-e; phi]`` where ``pi - phi`` is within 16 u pi), ``"euler"`` (the other
            branch anywhere; at and near the gimbal lock any member of the family: the
            rotation of the angles judged), or "".
        family: kernels of the same arguments each member may be (the 12 Euler sequences
            in the fixed and the body frame), or () for :attr:`kernel` alone.
        outputs: the kernel's outputs the user's function returns (the Euler angles, not
            the other branch nor the flag), or () for all of them.
        equivalent: the output's class of outputs of the same rotation
            (:data:`.equivalence.KINDS`: ``"axis_angle"``, ``"quaternion"``), judged as one
            answer, or "".
    """

    name: str
    kernel: str
    book: str
    forms: tuple[Form, ...]
    generators: tuple[str, ...]
    dual: str = ""
    kind: str = ""
    antipodal: str = ""
    family: tuple[str, ...] = ()
    outputs: tuple[str, ...] = ()
    equivalent: str = ""

    def user_slice(self, kernel) -> slice:
        """The columns of ``kernel``'s flat output (a :class:`~rigidsym.codegen.spec.Kernel`)
        that the user's function returns (:attr:`outputs`; all where empty)."""
        offs, start, stop = 0, None, 0
        for o in kernel.outputs:
            if not self.outputs or o.name in self.outputs:
                start = offs if start is None else start
                stop = offs + o.size
            offs += o.size
        return slice(start or 0, stop)

    def candidates(self, kernel, t: np.ndarray) -> list[np.ndarray]:
        """The truths a user's output may equal, from ``kernel``'s flat truth ``t``: the
        user's columns; ``-q`` too for a quaternion (the same rotation); the other branch
        too for Euler angles (``"euler"``)."""
        sl = self.user_slice(kernel)
        out = [t[sl]]
        if self.antipodal == "quaternion":
            out.append(-t[sl])
        if self.antipodal == "euler":
            out.append(t[sl.stop:sl.stop + (sl.stop - sl.start)])
        return out


_T = ("t", "twist", "t_a", "xi", "v", "vel", "velocity", "motion", "screw")
_W = ("w", "wrench", "w_a", "f", "force")
_TR = ("t", "tf", "transform", "pose", "m", "g", "h", "x", "se3", "a_t_b", "t_ab")
_ROT = ("r", "q", "rot", "rotation", "matrix", "mat", "c", "dcm", "so3")
_PTS = (("a", "p_a", "from_point", "src"), ("p", "p_p", "b", "to_point", "dst"))


def _transfer_forms(first: str, names: tuple[str, ...]) -> tuple[Form, ...]:
    def T(x):
        return homogeneous(np.eye(3), x["a"] - x["p"])

    return (
        Form(f"f({first}, a, p)", (names, *_PTS), lambda x: [x[first], x["a"], x["p"]]),
        Form(f"f(T, {first}), T = [[1, a - p], [0, 1]]", (_TR, names),
             lambda x: [T(x), x[first]]),
        Form(f"f({first}, T), T = [[1, a - p], [0, 1]]", (names, _TR),
             lambda x: [x[first], T(x)]),
        Form(f"f(R, d, {first}), R = 1, d = a - p", (_ROT, ("d", "p", "t", "trans"), names),
             lambda x: [np.eye(3), x["a"] - x["p"], x[first]]),
    )


def _one(name: str, names: tuple[str, ...]) -> tuple[Form, ...]:
    return (Form(f"f({name})", (names,), lambda x: [x[name]]),)


_ROTVEC = ("w", "omega", "rotvec", "r", "v", "phi", "theta", "axis_angle", "aa", "log", "x")
_QUAT = ("q", "quat", "quaternion", "eta", "x")

_ANG = ("angles", "euler", "rpy", "ypr", "eul", "a", "x", "q")


_SEQS = ("xyx", "xyz", "xzx", "xzy", "yxy", "yxz", "yzx", "yzy", "zxy", "zxz", "zyx", "zyz")


def _EULER(prefix: str, frames=("fixed", "body")) -> tuple[str, ...]:   # noqa: N802
    # a family's constructor: one kernel per sequence (and frame, where there is one)
    if not frames:
        return tuple(f"{prefix}_{s}" for s in _SEQS)
    return tuple(f"{prefix}_{s}_{f}" for s in _SEQS for f in frames)


TARGETS: dict[str, Target] = {t.name: t for t in (
    Target("twist_transfer", "twist_transfer",
           "(3.83): t_P = [omega; v_A + (a - p) x omega], the twist at P of the body's twist "
           "at A (Ad of T = [[1, a - p], [0, 1]])",
           _transfer_forms("t_A", _T), ("blocks", "inverse", "dual"),
           dual="wrench_transfer", kind="twist"),
    Target("wrench_transfer", "wrench_transfer",
           "(3.119): w_P = [n_A + (a - p) x f; f], the wrench at P of the wrench at A "
           "(Ad^-T of T = [[1, a - p], [0, 1]])",
           _transfer_forms("w_A", _W), ("blocks", "inverse", "dual"),
           dual="twist_transfer", kind="wrench"),
    Target("rotation_from_rotation_vector", "rotation_from_rotation_vector",
           "Q = exp(CPM(w)), the rotation of rotation vector w = phi e (Rodrigues' formula, (2.49) "
           "with the angle phi = |w|; the exponential of SO(3), Sola et al. 2018)",
           _one("w", _ROTVEC), ("transpose_out",), kind="rotation"),
    Target("rotation_vector_left_jacobian", "rotation_vector_left_jacobian",
           "J_l(w) = 1 + (1 - cos phi)/phi^2 W + (phi - sin phi)/phi^3 W^2, the "
           "left Jacobian of SO(3) (Sola et al. 2018)",
           _one("w", _ROTVEC), ("other_side",)),
    *(Target(n, n, f"{what} of SO(3) at w (Sola et al. 2018)", _one("w", _ROTVEC),
             ("other_side",)) for n, what in (
        ("rotation_vector_right_jacobian", "J_r(w) = J_l(-w), the right Jacobian"),
        ("rotation_vector_left_jacobian_inverse", "J_l(w)^-1, the left Jacobian's inverse"),
        ("rotation_vector_right_jacobian_inverse", "J_r(w)^-1, the right Jacobian's "
         "inverse"))),
    Target("euler_angle_rates", "euler_angle_rates_zyx_body",
           "(Exercise 3.10): eta_dot = W(angles)^-1 omega, the Euler-angle rates of the "
           "angular velocity, for each of the 12 sequences and either frame",
           (Form("f(angles, omega)", (_ANG, ("omega", "w", "pqr", "rates", "v")),
                 lambda x: [x["angles"], x["omega"]]),
            Form("f(omega, angles)", (("omega", "w", "pqr", "rates", "v"), _ANG),
                 lambda x: [x["omega"], x["angles"]])),
           ("extrinsic",), family=_EULER("euler_angle_rates")),
    Target("euler_rate_matrix", "euler_rate_matrix_zyx_body",
           "(Exercise 3.10): W(angles), omega = W eta_dot, for each of the 12 sequences and "
           "either frame", (Form("f(angles)", (_ANG,), lambda x: [x["angles"]]),),
           ("extrinsic",), family=_EULER("euler_rate_matrix")),
    Target("euler_angles_from_rotation", "euler_angles_from_rotation_zyx",
           "(Exercise 3.10, inverted; derivations/euler_angles.py): the intrinsic Euler angles "
           "[a; b; c] of Q = R_i(a) R_j(b) R_k(c), either branch, for each of the 12 "
           "sequences; at the gimbal lock any member of the family (Q(angles) = Q)",
           _one("Q", _ROT), ("extrinsic", "transpose_in", "degrees_all_out"),
           antipodal="euler", family=_EULER("euler_angles_from_rotation", ()),
           outputs=("angles",)),
    Target("euler_rodrigues_from_rotation", "euler_rodrigues_from_rotation",
           "(2.3), inverted: the Euler-Rodrigues parameters eta = [r; r0] of Q (a unit "
           "quaternion, scalar last, r0 >= 0)",
           _one("Q", _ROT), ("transpose_in", "scalar_first_out", "negated_out"),
           antipodal="quaternion", equivalent="quaternion"),
    Target("natural_invariants_from_rotation", "natural_invariants_from_rotation",
           "(2.49), (3.95): the natural invariants (e, phi) of Q, phi in [0, pi]",
           _one("Q", _ROT), ("transpose_in", "degrees_out", "angle_first_out"),
           antipodal="axis", equivalent="axis_angle"),
    *(Target(n, n, f"({eq}): the {what} of T = [[1, a - p], [0, 1]]",
             (Form("f(a, p)", _PTS, lambda x: [x["a"], x["p"]]),
              Form("f(T), T = [[1, a - p], [0, 1]]", (_TR,),
                   lambda x: [homogeneous(np.eye(3), x["a"] - x["p"])]),
              Form("f(R, d), R = 1, d = a - p", (_ROT, ("d", "p", "t", "trans")),
                   lambda x: [np.eye(3), x["a"] - x["p"]])),
             ("blocks_matrix_out", "inverse", "dual"), dual=d, kind=kind)
      for n, eq, what, d, kind in (
          ("twist_transfer_matrix", "3.83", "twist-transfer matrix U = Ad_T",
           "wrench_transfer_matrix", "twist_matrix"),
          ("wrench_transfer_matrix", "3.119", "wrench-transfer matrix V = Ad_T^-T",
           "twist_transfer_matrix", "wrench_matrix"))),
    Target("rotation_vector_from_rotation", "rotation_vector_from_rotation",
           "the logarithm of SO(3), w = phi e with (e, phi) the natural invariants of Q, "
           "phi in [0, pi] ((2.49), inverted; Sola et al. 2018)",
           _one("Q", _ROT), ("transpose_in",), antipodal="rotation_vector"),
    Target("rotation_from_natural_invariants", "rotation_from_natural_invariants",
           "(2.49): Q = e e^T + cos(phi) (1 - e e^T) + sin(phi) E, from axis e and angle phi",
           (Form("f(e, phi)", (("e", "axis", "n", "u", "k"), ("phi", "theta", "angle", "a")),
                 lambda x: [x["e"], x["phi"]]),
            Form("f(phi, e)", (("phi", "theta", "angle", "a"), ("e", "axis", "n", "u", "k")),
                 lambda x: [x["phi"], x["e"]]),
            Form("f([e; phi])", (("a", "axis_angle", "aa", "x", "v"),),
                 lambda x: [np.concatenate([x["e"], np.ravel(x["phi"])])]),
            Form("f([phi; e])", (("a", "axis_angle", "aa", "x", "v"),),
                 lambda x: [np.concatenate([np.ravel(x["phi"]), x["e"]])])),
           ("transpose_out", "degrees"), kind="rotation"),
    Target("rotation_from_euler_rodrigues", "rotation_from_euler_rodrigues",
           "(2.3): Q of the Euler-Rodrigues parameters eta = [r; r0] (a unit quaternion, "
           "scalar last)",
           _one("eta", _QUAT), ("transpose_out", "scalar_first"), kind="rotation"),
    Target("exponential_coordinates_from_transform", "exponential_coordinates_from_transform",
           "the logarithm of SE(3), xi = [w; v] with |w| <= pi, from T (Sola et al. 2018)",
           _one("T", _TR), ("blocks_out", "inverse_in")),
    Target("transform_from_exponential_coordinates", "transform_from_exponential_coordinates",
           "the exponential of SE(3), T = exp([W, v; 0, 0]) of xi = [w; v] (Sola et al. "
           "2018)",
           _one("xi", _T), ("blocks_in", "inverse_out")),
)}


def target(name: str) -> Target:
    """The target ``name``.

    Raises:
        BadInput: a name that is no target, naming those there are."""
    from rigidsym.core.errors import BadInput

    if name not in TARGETS:
        raise BadInput(f"--as {name!r}: no such operation to audit; expected one of "
                       f"{', '.join(sorted(TARGETS))}")
    return TARGETS[name]
