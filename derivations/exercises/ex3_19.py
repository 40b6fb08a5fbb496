"""Exercise 3.19: a wrench read by a six-axis force sensor, transferred to the gripper point."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.worked import Solution, exact_check, identity_check
from rigidsym.declare import block, rotation, vector

from ..sec3_4_2 import twist_transfer_matrix

ID = "ex3.19"


def wrench_at(n_S, f, d) -> sp.Matrix:
    """``[n_P; f]`` with ``n_P = n_S - d x f``, ``d = p - s`` (moment transfer, Sec. 3.7)."""
    return sp.Matrix.vstack(n_S - d.cross(f), f)


def solve() -> Solution:
    """Worked solution of Exercise 3.19."""
    nS, fS = sp.Matrix([1, 0, 1]), sp.Matrix([0, 1, 0])
    d_val = sp.Matrix([0, 0, sp.Rational(1, 10)])
    s = Solution(
        ID, "Six-axis force sensor",
        "\"If points P and S lie a distance of 100 mm apart, find the wrench in F_2, when the "
        "readouts of the sensor are [n]_S = [1, 0, 1]^T Nm, [f]_S = [0, 1, 0]^T N\"",
        "Angeles, Sec. 3.9, Exercise 3.19",
        given={"[n]_S": nS, "[f]_S": fS, "||p - s||": sp.Rational(1, 10)},
        assumptions=["Fig. 2.10 is not in the text we have. Solved parametrically for any "
                     "offset d = p - s and any orientation [x]_S = Q [x]_2; specialised to "
                     "P on the sensor's Z axis, d = [0, 0, 0.1] m, and F_2 at P parallel "
                     "to F_S (Q = 1).",
                     "The readouts are the wrench about S (the sensor's origin)."])
    d, Q = vector("d"), rotation("ex319_Q")
    n, f = vector("n"), vector("f")
    gen = s.step("parametric", block([[Q.T, sp.zeros(3)], [sp.zeros(3), Q.T]])
                 * wrench_at(n, f, d),
                 "n_P = n_S + (s - p) x f, then both parts rotate into F_2 by Q^T.")
    w = s.step("specialised", wrench_at(nS, fS, d_val), "d = [0, 0, 0.1] m, Q = 1.")
    s.answers = {"w_2": w, "n_2": w[:3, :], "f_2": w[3:, :]}
    om, vS = vector("omega"), vector("v")
    tS = sp.Matrix.vstack(om, vS)
    tP = twist_transfer_matrix(sp.zeros(3, 1), d) * tS
    wS = sp.Matrix.vstack(n, f)
    s.check(identity_check("power invariant: w_P^T t_P = w_S^T t_S for every twist (ray/axis "
                           "coordinates)", [(wrench_at(n, f, d).T * tP)[0] - (wS.T * tS)[0]]))
    s.check(identity_check("rotating to F_2 keeps the power: (R w)^T (R t) with R = diag(Q^T)",
                           [(gen.T * block([[Q.T, sp.zeros(3)], [sp.zeros(3), Q.T]]) * tP)[0]
                            - (wS.T * tS)[0]]))
    s.check(exact_check("specialised: n_S = n_P + d x f reproduces the readout",
                        [w[:3, :] + d_val.cross(fS) - nS]))
    return s
