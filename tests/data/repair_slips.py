"""Slips the repair search must undo: three per kind of edit in its vocabulary.

Each slip is a true identity of rotations or of a rigid motion with one edit made to it;
``corrected=`` is the identity, and ``KIND[id]`` the kind of edit that undoes the slip. The
identities lean on the model (``Qᵀ Q = 1``, ``E = cpm(e)``, ``Q̇ = Ω Q``): an identity true
of every matrix would be the same expression on both sides with the book symbols left
unsubstituted, which the search rejects as saying nothing. ``slip:three-edits`` needs three
edits and searches exhaustively (its own ``repair_budget``).
"""

from __future__ import annotations

import sympy as sp

from rigidsym import (
    I3,
    O3,
    Cross,
    Rel,
    Statement,
    angle,
    cpm,
    equation,
    mat,
    matrix,
    rigid_motion,
    rotation_from_natural_invariants,
    trace,
    unit_vector,
    vec,
    vect,
    vector,
)

e, phi, theta = unit_vector("e"), angle("phi"), angle("theta")
Q, E, A = mat("Q"), mat("E"), mat("A")
e_, a_ = vec("e"), vec("a")
s, c = sp.sin(phi), sp.cos(phi)
ROT = {Q: rotation_from_natural_invariants(e, phi), E: cpm(e), e_: e}
ROT_A = {**ROT, a_: vector("a")}
ROT_M = {**ROT, A: matrix("A")}
_m = rigid_motion()
Qm, Qd, W = mat("R"), mat("R_dot"), mat("Omega")
MOTION = {Qm: _m.Q, Qd: _m.Q_dot, W: _m.Omega}
Z = sp.ZeroMatrix(3, 1)

#: the kind of edit that undoes each slip
KIND: dict[str, str] = {}


def _slip(name: str, kind: str, printed: list, corrected: list, model: dict,
          budget: int | None = None) -> None:
    eq_id = f"slip:{name}"
    KIND[eq_id] = kind

    @equation(eq_id, f"a {kind} slip", section=kind, expected="does-not-hold",
              repair_budget=budget)
    def declaration() -> Statement:
        return Statement([Rel(*r) for r in printed], model,
                         corrected=[Rel(*r) for r in corrected])


ROD = I3 + s * E + (1 - c) * E**2  # Rodrigues' formula
# flip-sign
_slip("flip-1", "flip-sign", [(Q, I3 - s * E + (1 - c) * E**2)], [(Q, ROD)], ROT)
_slip("flip-2", "flip-sign", [(E.T, E)], [(E.T, -E)], ROT)
_slip("flip-3", "flip-sign", [(Q - Q.T, -2 * s * E)], [(Q - Q.T, 2 * s * E)], ROT)
# drop-term: an extra term
_slip("drop-1", "drop-term", [(Q * e_, e_ + s * e_)], [(Q * e_, e_)], ROT)
_slip("drop-2", "drop-term", [(trace(Q), 1 + 2 * c + s)], [(trace(Q), 1 + 2 * c)], ROT)
_slip("drop-3", "drop-term", [(E.T, -E + I3)], [(E.T, -E)], ROT)
# insert-term: a term lost, which occurs in another member
_slip("insert-1", "insert-term", [(Q - I3 - s * E, (1 - c) * E**2, "rest"), (Q, I3 + s * E, "Q")],
      [(Q - I3 - s * E, (1 - c) * E**2, "rest"), (Q, ROD, "Q")], ROT)
_slip("insert-2", "insert-term", [(trace(Q), 1 + 2 * c, "trace"), (trace(Q), 1, "one")],
      [(trace(Q), 1 + 2 * c, "trace"), (trace(Q), 1 + 2 * c, "one")], ROT)
_slip("insert-3", "insert-term",
      [(Q + Q.T, 2 * c * I3 + (2 - 2 * c) * e_ * e_.T, "sym"), (Q + Q.T, 2 * c * I3, "iso")],
      [(Q + Q.T, 2 * c * I3 + (2 - 2 * c) * e_ * e_.T, "sym"),
       (Q + Q.T, 2 * c * I3 + (2 - 2 * c) * e_ * e_.T, "iso")], ROT)
# scale-term: a term off by a factor 2
_slip("scale-1", "scale-term", [(E - E.T, E)], [(E - E.T, 2 * E)], ROT)
_slip("scale-2", "scale-term", [(vect(Q), s * e_ / 2)], [(vect(Q), s * e_)], ROT)
_slip("scale-3", "scale-term", [(Q - Q.T, s * E)], [(Q - Q.T, 2 * s * E)], ROT)
# coefficient
_slip("coef-1", "coefficient", [(trace(Q), 1 + 3 * c)], [(trace(Q), 1 + 2 * c)], ROT)
_slip("coef-2", "coefficient", [(E**2, e_ * e_.T - 2 * I3)], [(E**2, e_ * e_.T - I3)], ROT)
_slip("coef-3", "coefficient", [(vect(Q), 2 * s * e_)], [(vect(Q), s * e_)], ROT)
# transpose: a transpose lost
_slip("transpose-1", "transpose", [(Q * E * Q, E)], [(Q * E * Q.T, E)], ROT)
_slip("transpose-2", "transpose", [(E, -E)], [(E.T, -E)], ROT)
_slip("transpose-3", "transpose", [(Qd * Qm, W)], [(Qd * Qm.T, W)], MOTION)
# drop-transpose: a transpose too many
_slip("untranspose-1", "drop-transpose", [(E.T, -E.T)], [(E.T, -E)], ROT)
_slip("untranspose-2", "drop-transpose", [(Q.T * E, E * Q)], [(Q * E, E * Q)], ROT)
_slip("untranspose-3", "drop-transpose", [(Qd, W.T * Qm)], [(Qd, W * Qm)], MOTION)
# transpose-every: one symbol transposed wherever it occurs
_slip("every-1", "transpose-every", [(Q.T, ROD)],
      [(Q.T, I3 + s * E.T + (1 - c) * E.T**2)], ROT)
_slip("every-2", "transpose-every", [(Q.T - Q, 2 * s * E)], [(Q - Q.T, 2 * s * E)], ROT)
_slip("every-3", "transpose-every", [(Qm * Qd + Qd.T * Qm.T, O3)],
      [(Qm.T * Qd + Qd.T * Qm, O3)], MOTION)
# swap-factors
_slip("swap-1", "swap-factors", [(Qd, Qm * W)], [(Qd, W * Qm)], MOTION)
_slip("swap-2", "swap-factors", [(W, Qm.T * Qd)], [(W, Qd * Qm.T)], MOTION)
_slip("swap-3", "swap-factors", [(Qm.T * Qd, W)], [(Qd * Qm.T, W)], MOTION)
# reverse-product
_slip("reverse-1", "reverse-product", [(Qm.T * Qd, Qm * W * Qm.T)],
      [(Qm.T * Qd, Qm.T * W * Qm)], MOTION)
_slip("reverse-2", "reverse-product", [(Qm * W * Qm.T, Qm.T * Qd)],
      [(Qm.T * W * Qm, Qm.T * Qd)], MOTION)
_slip("reverse-3", "reverse-product", [(Qd.T * Qm, Qm * W.T * Qm.T)],
      [(Qd.T * Qm, Qm.T * W.T * Qm)], MOTION)
# sin-cos
_slip("sincos-1", "sin-cos", [(trace(Q), 1 + 2 * s)], [(trace(Q), 1 + 2 * c)], ROT)
_slip("sincos-2", "sin-cos", [(vect(Q), c * e_)], [(vect(Q), s * e_)], ROT)
_slip("sincos-3", "sin-cos", [(Q, I3 + c * E + (1 - c) * E**2)], [(Q, ROD)], ROT)
# one-minus: cos where 1 - cos belongs, and back (sympy distributes a number over a sum,
# so the 1 - x stands beside a symbol: (1 - sin φ) e, not 2 (1 - cos φ))
_slip("one-minus-1", "one-minus", [(Q, I3 + s * E + c * E**2)], [(Q, ROD)], ROT)
_slip("one-minus-2", "one-minus", [(vect(Q), (1 - s) * e_)], [(vect(Q), s * e_)], ROT)
_slip("one-minus-3", "one-minus", [((Q + Q.T) / 2, I3 + c * E**2)],
      [((Q + Q.T) / 2, I3 + (1 - c) * E**2)], ROT)
# replace-symbol: one occurrence
_slip("replace-1", "replace-symbol", [(Q * e_, a_)], [(Q * e_, e_)], ROT_A)
_slip("replace-2", "replace-symbol",
      [(vect(Q), s * e_, "axis"), (trace(Q), 1 + 2 * sp.cos(theta), "trace")],
      [(vect(Q), s * e_, "axis"), (trace(Q), 1 + 2 * c, "trace")], ROT)
_slip("replace-3", "replace-symbol", [(E * a_, Z)], [(E * e_, Z)], ROT_A)
# replace-every: every occurrence
_slip("every-symbol-1", "replace-every", [(Q * a_, a_)], [(Q * e_, e_)], ROT_A)
_slip("every-symbol-2", "replace-every", [(A + A.T, O3)], [(E + E.T, O3)], ROT_M)
_slip("every-symbol-3", "replace-every", [(A * A.T, I3)], [(Q * Q.T, I3)], ROT_M)
# multiply-factor: a factor lost, which occurs elsewhere
_slip("factor-1", "multiply-factor", [(E, Cross(e_, a_))], [(E * a_, Cross(e_, a_))], ROT_A)
_slip("factor-2", "multiply-factor", [(Qm.T * Qm, I3, "orthogonal"), (Qd, W, "rate")],
      [(Qm.T * Qm, I3, "orthogonal"), (Qd, W * Qm, "rate")], MOTION)
_slip("factor-3", "multiply-factor", [(E**2, -E)], [(E * E**2, -E)], ROT)

# three edits (coefficient, sin -> cos, theta -> phi): beyond the vocabulary's two
_slip("three-edits", "three edits",
      [(vect(Q), s * e_, "axis"), (trace(Q), 1 + 3 * sp.sin(theta), "trace")],
      [(vect(Q), s * e_, "axis"), (trace(Q), 1 + 2 * c, "trace")], ROT, budget=10**6)
