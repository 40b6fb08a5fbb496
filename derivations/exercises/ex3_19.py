"""Exercise 3.19: a wrench read by a six-axis force sensor, transferred to the gripper point.

Exact data: the orientation ``Q`` (``[x]_S = Q [x]_2``) must be exactly a rotation. Float
data are measurements: ``Q`` must be orthogonal within ``tol`` and is replaced by the
nearest rotation (its orthogonal polar factor), made exact (:mod:`._fit`).
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from rigidsym.course.worked import Param, Solution, exact_check, identity_check, is_zero
from rigidsym.declare import block, rotation, vector

from ..sec3_4_2 import twist_transfer_matrix
from ._fit import accepting_tol, exact_rotation, nearest_rotation
from ._random import cayley
from ._screw import rotation_defect

ID = "ex3.19"
TITLE = "Six-axis force sensor"
STATEMENT = ("\"If points P and S lie a distance of 100 mm apart, find the wrench in F_2, when "
             "the readouts of the sensor are [n]_S = [1, 0, 1]^T Nm, [f]_S = [0, 1, 0]^T N\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.19"
#: the documented unit of each answer with one (graded answers may be written in any
#: compatible unit); the others are pure numbers or mixed
ANSWER_UNITS = {"n_2": "N m", "f_2": "N"}
FIGURE_NAME = "sensor"
MEASURED = True
#: decimals in Q are readings (its orthogonality is judged within a tolerance); decimals in
#: the offset d and the wrench are exact lengths and loads (0.1 m is 1/10 m)
READINGS = ("Q",)
_V = sp.ImmutableMatrix
PARAMETERS = (
    Param("n_S", _V([1, 0, 1]), (3,), "moment read by the sensor (about S), in F_S", "N m"),
    Param("f_S", _V([0, 1, 0]), (3,), "force read by the sensor, in F_S", "N"),
    Param("d", _V([0, 0, sp.Rational(1, 10)]), (3,), "d = p - s, from the sensor origin S to "
          "the gripper point P, in F_S", "m"),
    Param("Q", _V(sp.eye(3)), (3, 3), "orientation of F_2 in F_S: [x]_S = Q [x]_2", ""),
)
VARIANTS = (
    ("P 100 mm along x, F_2 turned 90 deg about z", {"d": ["0.1", 0, 0],
                                                     "Q": [[0, -1, 0], [1, 0, 0], [0, 0, 1]]}),
    ("a Q that is not a rotation (ill-posed)", {"Q": [[1, 1, 0], [0, 1, 0], [0, 0, 1]]}),
)


def default_tol(values: dict) -> tuple[sp.Rational, str]:
    """The tolerance on ``Q^T Q - 1`` (dimensionless): 10^-3."""
    return sp.Rational(1, 1000), "10^-3 on the entries of Q^T Q - 1 (Q is dimensionless)"


def wrench_at(n_S, f, d) -> sp.Matrix:
    """``[n_P; f]`` with ``n_P = n_S - d x f``, ``d = p - s`` (moment transfer, Sec. 3.7)."""
    return sp.Matrix.vstack(n_S - d.cross(f), f)


def _rotation(s: Solution, Q, tol):
    """The rotation to use: ``Q`` itself (exact data) or its nearest rotation (measured)."""
    if tol is None:
        defect = rotation_defect(Q)
        if defect:
            s.fail(f"The given orientation Q is not a rotation ({defect}).")
        return Q
    err = max(abs(x) for x in Q.T * Q - sp.eye(3))
    if bool(err > tol) or bool(Q.det() <= 0):
        s.fail(f"The given orientation Q is not a rotation within tol = {float(tol):.3g} "
               f"(Q^T Q - 1 has an entry of {float(err):.3g}, det Q = {float(Q.det()):.4g})"
               f"{accepting_tol(err) if Q.det() > 0 else ''}.")
    R = exact_rotation(nearest_rotation(np.array(Q.tolist(), dtype=float)))
    s.step("nearest rotation", R,
           "The measured Q is orthogonal within tol; it is replaced by its orthogonal polar "
           "factor (the rotation nearest in the Frobenius norm), made exact.")
    s.step("residual", sp.Float(sp.sqrt(((R - Q).T * (R - Q)).trace()).evalf(20), 4),
           "||R - Q||_F, the distance from the measured Q to the rotation used, to 4 "
           "digits.")
    return R


def solve(n_S=PARAMETERS[0].default, f_S=PARAMETERS[1].default, d=PARAMETERS[2].default,
          Q=PARAMETERS[3].default, tol=None) -> Solution:
    """Worked solution of Exercise 3.19 (N, N m, m; ``tol``: the measured-data path)."""
    nS, fS, d_val, Q_val = (sp.Matrix(v) for v in (n_S, f_S, d, Q))
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"[n]_S": nS, "[f]_S": fS, "d = p - s": d_val, "Q": Q_val,
               "||p - s||": sp.sqrt(d_val.dot(d_val))},
        assumptions=["Fig. 2.10 of the book (chapter 2) places the sensor; solved "
                     "parametrically for any "
                     "offset d = p - s and any orientation [x]_S = Q [x]_2; the book's data "
                     "take P on the sensor's Z axis, d = [0, 0, 0.1] m, and F_2 at P parallel "
                     "to F_S (Q = 1).",
                     "The readouts are the wrench about S (the sensor's origin)."])
    dg, Qg = vector("d"), rotation("ex319_Q")
    n, f = vector("n"), vector("f")
    Rg = block([[Qg.T, sp.zeros(3)], [sp.zeros(3), Qg.T]])
    gen = Rg * wrench_at(n, f, dg)
    # shown in the reader's names (Q_11 ...); the check below keeps the constrained atoms
    s.step("parametric", gen.subs({Qg[i, j]: sp.Symbol(f"Q_{i + 1}{j + 1}", real=True)
                                   for i in range(3) for j in range(3)}),
           "n_P = n_S + (s - p) x f, then both parts rotate into F_2 by Q^T.")
    Qr = _rotation(s, Q_val, tol)
    w_S = wrench_at(nS, fS, d_val)
    turned = not is_zero(Qr - sp.eye(3))
    w = s.step("specialised", block([[Qr.T, sp.zeros(3)], [sp.zeros(3), Qr.T]]) * w_S
               if turned else w_S, "The data in the parametric form (" +
               (_turn_text(Qr) if turned else "Q = 1: F_2 parallel to F_S, no rotation") +
               f"; P at d = {list(d_val)} m from S).")
    s.answers = {"w_2": w, "n_2": w[:3, :], "f_2": w[3:, :]}
    om, vS = vector("omega"), vector("v")
    tS = sp.Matrix.vstack(om, vS)
    tP = twist_transfer_matrix(sp.zeros(3, 1), dg) * tS
    wS = sp.Matrix.vstack(n, f)
    s.check(identity_check("power invariant: w_P^T t_P = w_S^T t_S for every twist (ray/axis "
                           "coordinates)", [(wrench_at(n, f, dg).T * tP)[0] - (wS.T * tS)[0]]))
    s.check(identity_check("rotating to F_2 keeps the power: (R w)^T (R t) with R = diag(Q^T)",
                           [(gen.T * Rg * tP)[0] - (wS.T * tS)[0]]))
    n2, f2 = w[:3, :], w[3:, :]
    s.check(exact_check("specialised: Q f_2 = f_S and Q n_2 + d x (Q f_2) = n_S reproduce the "
                        "readout", [Qr * f2 - fS, Qr * n2 + d_val.cross(Qr * f2) - nS]))
    return s


def _turn_text(Q) -> str:
    """``F_2 turned by 90 deg about [0, 0, 1]`` from a rotation (angle and axis to 4
    digits: words for the reader, computed from the data)."""
    Qf = np.array(sp.N(Q, 17).tolist(), dtype=float)
    angle = float(np.degrees(np.arccos(np.clip((np.trace(Qf) - 1) / 2, -1, 1))))
    axis = np.array([Qf[2, 1] - Qf[1, 2], Qf[0, 2] - Qf[2, 0], Qf[1, 0] - Qf[0, 1]])
    if np.linalg.norm(axis) < 1e-9:          # a half turn: the axis is Q + 1's column
        M = Qf + np.eye(3)
        axis = M[:, int(np.argmax(np.linalg.norm(M, axis=0)))]
    axis = axis / np.linalg.norm(axis)
    shown = ", ".join(f"{x:.4g}" for x in axis + 0.0)
    return f"Q: F_2 turned from F_S by {angle:.4g} deg about [{shown}]"


def slips(s: Solution) -> dict:
    """The exercise's own slips, for the grader: the moment left about S (the sensor's
    origin, not transferred to P) and the moment transfer with the wrong sign."""
    n_S, f_S, d, Q = (s.data[k] for k in ("n_S", "f_S", "d", "Q"))
    Qr = next((st.expr for st in s.steps if st.name == "nearest rotation"), Q)
    about_S = Qr.T * n_S
    wrong_sign = Qr.T * (n_S + d.cross(f_S))
    f2 = Qr.T * f_S
    return {"n_2": [("reference point", "the moment about S (not transferred to P)", about_S),
                    ("sign", "n_S + d x f (the transfer's sign)", wrong_sign)],
            "w_2": [("reference point", "the wrench about S (not transferred to P)",
                     sp.Matrix.vstack(about_S, f2)),
                    ("sign", "n_S + d x f (the transfer's sign)",
                     sp.Matrix.vstack(wrong_sign, f2))]}


def figure(s: Solution):
    """The sensor frame F_S at S, the gripper frame F_2 at P, and the wrench: the force at
    P, the moment read at S and the moment about P (each scaled to the drawing; the legend
    gives the magnitudes)."""
    from ._draw import arrow, axes3d, frame, new_figure, point

    g = s.given
    d, f, nS = g["d = p - s"], g["[f]_S"], g["[n]_S"]
    Q = g["Q"] if "nearest rotation" not in [st.name for st in s.steps] else \
        next(st.expr for st in s.steps if st.name == "nearest rotation")
    nP = nS - d.cross(f)
    L = max(float(sp.N(sp.sqrt(d.dot(d)))), 0.1)
    big = max(float(sp.N(sp.sqrt(v.dot(v)))) for v in (f, nS, nP)) or 1.0
    k = L / big
    fig, ax = new_figure("Exercise 3.19: sensor frame F_S, gripper frame F_2 and the wrench")
    frame(ax, sp.zeros(3, 1), sp.eye(3) * L / 2, "S", "0.35")
    frame(ax, d, Q * L / 2, "2", "tab:purple")
    point(ax, sp.zeros(3, 1), "0.35", text="S")
    point(ax, d, "tab:purple", text="P")
    for vec, at, colour, name in ((f, d, "tab:red", "f"), (nS, sp.zeros(3, 1), "tab:blue",
                                                             "n_S (about S)"),
                                  (nP, d, "tab:cyan", "n_P (about P)")):
        mag = float(sp.N(sp.sqrt(vec.dot(vec))))
        arrow(ax, at, vec, colour, f"{name}: {mag:.3g} {'N' if name == 'f' else 'N m'}",
              scale=k)
    pts = [sp.zeros(3, 1), d, d + f * k, nS * k, d + nP * k, sp.ones(3, 1) * L / 2]
    axes3d(ax, pts)
    return fig


def given_figure(s: Solution):
    """The given data only (the students' handout): the sensor frame F_S at S, the
    gripper point P at d with the frame F_2 of the given Q, and the readouts n_S, f_S at
    S; no moment about P."""
    from ._draw import arrow, axes3d, frame, new_figure, point

    d, f, nS, Q = (s.data[k] for k in ("d", "f_S", "n_S", "Q"))
    L = max(float(sp.N(sp.sqrt(d.dot(d)))), 0.1)
    big = max(float(sp.N(sp.sqrt(v.dot(v)))) for v in (f, nS)) or 1.0
    fig, ax = new_figure("Sensor frame F_S, gripper point P and frame F_2, readouts at S")
    frame(ax, sp.zeros(3, 1), sp.eye(3) * L / 2, "S", "0.35")
    frame(ax, d, sp.Matrix(Q) * L / 2, "2", "tab:purple")
    point(ax, sp.zeros(3, 1), "0.35", text="S")
    point(ax, d, "tab:purple", text="P")
    arrow(ax, sp.zeros(3, 1), f, "tab:red", "f_S (read at S)", scale=L / big)
    arrow(ax, sp.zeros(3, 1), nS, "tab:blue", "n_S (read at S)", scale=L / big)
    axes3d(ax, [sp.zeros(3, 1), d, f * L / big, nS * L / big, sp.ones(3, 1) * L / 2])
    return fig


def random_data(rng) -> dict:
    """A variant with readable exact numbers (an exam's draw): small integer readouts, an
    offset of a few centimetres, F_2 turned by a Cayley rotation of small rationals."""
    d = [rng.choice(["0", "0.05", "0.1", "-0.05", "0.2"]) for _ in range(3)]
    return {"n_S": [rng.randint(-3, 3) for _ in range(3)],
            "f_S": [rng.randint(-5, 5) for _ in range(3)], "d": d,
            "Q": cayley(rng).tolist()}
