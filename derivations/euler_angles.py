"""The Euler angles of a rotation: the inverse of Exercise 3.10's ``euler_rotation`` for the
twelve intrinsic sequences, both branches, and the gimbal-lock family.

For the intrinsic sequence ``i-j-k``, ``Q = R_i(a) R_j(b) R_k(c)`` (``euler_rotation`` of
``derivations/exercises/ex3_10.py``, each factor Angeles (2.49) about a coordinate axis).
Nothing here is copied from a table: every entry used, and its sign, is *found* in the
symbolic product ``Q(a, b, c)`` (:func:`derive`), as the pattern

* the middle angle: one entry ``= +-sin b`` (Tait-Bryan) or ``= cos b`` (proper Euler);
* the first angle: two entries ``= rho(b) (+-sin a, +-cos a)`` with ``rho = cos b``
  (Tait-Bryan) or ``sin b`` (proper Euler);
* the third angle: row ``j`` of ``M = R_i(a)^T Q = R_j(b) R_k(c)`` is row ``j`` of ``R_k(c)``
  (``R_j`` fixes axis ``j``), two entries ``(+-sin c, cos c)`` of it.

The formulas (:func:`euler_angles_from_rotation`): ``rho^ = sqrt(A_s^2 + A_c^2)`` from the
first angle's pair, ``a = atan2(A_s, A_c)``, the middle angle by atan2 of its entry against
``rho^`` (never asin or acos: both lose half the digits at the lock, and NaN past +-1), and
the third angle from ``rho^ M`` written with ``rho^ sin a = A_s``, ``rho^ cos a = A_c`` (no
division; it keeps ``Q(a, b, c) = Q`` to the rounding where ``a`` and ``c`` alone are
ill-conditioned, near the lock, the method of Shoemake's *Euler angle conversion*, Graphics
Gems IV, 1994, and of Bernardes & Viollet, PLoS ONE 17(11), 2022). The principal branch has
``rho >= 0``: ``b`` in ``[-pi/2, pi/2]`` (Tait-Bryan) or ``[0, pi]`` (proper Euler); the
other has ``rho <= 0``: ``(a + pi, pi - b, c + pi)`` (Tait-Bryan) or ``(a + pi, -b, c +
pi)``, angles in ``[-pi, pi]``. At the lock (``rho = 0``: ``A_s = A_c = 0``) only ``a + c``
(or ``a - c``) is defined: :func:`euler_angles_at_gimbal_lock` returns the member with
``c = 0`` (SciPy's choice), ``a`` from column ``j`` of ``Q = R_i(a) R_j(b)``.

:func:`checks` proves each atan2's arguments are ``r (sin x, cos x)`` with ``r >= 0`` on the
branch's domain, symbolically (a polynomial identity in the sines and cosines).
"""

from __future__ import annotations

import functools
import importlib

import sympy as sp

__all__ = ["derive", "euler_angles_from_rotation", "euler_angles_at_gimbal_lock", "checks",
           "lock_pair"]

_AX = {"X": 0, "Y": 1, "Z": 2}
_EX10 = "rigidsym.derivations.exercises.ex3_10"


def _ex10():
    return importlib.import_module(_EX10)


def _is_zero(e) -> bool:
    """``e`` (a polynomial in sines and cosines of independent angles) is 0 for every
    angle: its remainder modulo ``sin^2 + cos^2 - 1`` of each angle (a Groebner basis: the
    leading terms are coprime) is the zero polynomial. A proof, never a float."""
    e = sp.expand(e)
    if e == 0:
        return True
    angles = sorted({f.args[0] for f in e.atoms(sp.sin, sp.cos)}, key=str)
    gens, ideal, rep = [], [], {}
    for k, x in enumerate(angles):
        s, c = sp.symbols(f"s{k} c{k}")
        rep.update({sp.sin(x): s, sp.cos(x): c})
        gens += [s, c]
        ideal.append(s**2 + c**2 - 1)
    poly = e.xreplace(rep)
    if poly.free_symbols - set(gens):
        return False
    _, r = sp.reduced(poly, ideal, *gens, order="lex")
    return sp.expand(r) == 0


def _find(Q: sp.Matrix, target, where) -> tuple[tuple[int, int], int]:
    """The entry of ``Q`` among ``where`` equal to ``+-target`` and its sign."""
    for rc in where:
        for s in (1, -1):
            if _is_zero(Q[rc] - s * target):
                return rc, s
    raise ValueError(f"no entry of Q equals +-{target}")


@functools.cache
def derive(seq: str) -> dict:
    """The entries of ``Q`` (and of row ``j`` of ``R_k(c)``) that give each angle of the
    intrinsic sequence ``seq`` (``"ZYX"``), with their signs, found in ``Q(a, b, c)``.

    Returns:
        ``{"proper": bool, "mid": ((r, c), s), "a_sin": ((r, c), s), "a_cos": ((r, c), s),
        "c_sin": (col, s), "c_cos": (col, s), "lock_sin": ((r, c), s), "lock_cos": ((r,
        c), s)}``: ``Q[r, c] = s sin b`` (or ``cos b``), ``Q[a_sin] = s rho sin a``, ...;
        ``M[j, col] = s sin c``; at the lock, ``Q[lock_sin] = s sin a`` with ``c = 0``.

    Raises:
        ValueError: ``seq`` is not one of the twelve sequences.
    """
    ex = _ex10()
    if seq not in ex.SEQUENCES:
        raise ValueError(f"sequence {seq!r}: expected one of {', '.join(ex.SEQUENCES)}")
    a, b, c = ex.ETA
    Q = ex.euler_rotation(seq)
    proper = seq[0] == seq[2]
    every = [(r, k) for r in range(3) for k in range(3)]
    rho = sp.sin(b) if proper else sp.cos(b)
    out = {"proper": proper,
           "mid": _find(Q, sp.cos(b) if proper else sp.sin(b), every),
           "a_sin": _find(Q, rho * sp.sin(a), every),
           "a_cos": _find(Q, rho * sp.cos(a), every)}
    j = _AX[seq[1]]
    Rk = ex.axis_rotation(seq[2], c)
    row = [(j, k) for k in range(3)]
    (_, cs), ss = _find(Rk, sp.sin(c), row)
    (_, cc), sc = _find(Rk, sp.cos(c), row)
    out["c_sin"], out["c_cos"] = (cs, ss), (cc, sc)
    Q0 = Q.xreplace({c: 0})
    col = [(r, j) for r in range(3)]
    out["lock_sin"] = _find(Q0, sp.sin(a), col)
    out["lock_cos"] = _find(Q0, sp.cos(a), col)
    return out


def _first_pair(Q, d) -> tuple:
    (rs, s1), (rc, s2) = d["a_sin"], d["a_cos"]
    return s1 * Q[rs], s2 * Q[rc]


def lock_pair(seq: str, Q: sp.Matrix) -> tuple:
    """``(A_s, A_c) = rho(b) (sin a, cos a)``: the first angle's pair of entries of ``Q``,
    both exactly 0 at the gimbal lock (the kernel's branch condition)."""
    return _first_pair(Q, derive(seq))


def _third(seq: str, Q, As, Ac, d):
    """``rho^ (M[j, sin col], M[j, cos col])`` with ``M = R_i(a)^T Q``: ``R_i(a)^T``'s row
    ``j`` is linear in (sin a, cos a), so ``rho^ M`` is ``Q`` times the row with ``A_s,
    A_c`` for ``rho^ sin a, rho^ cos a``: no division."""
    ex = _ex10()
    a = ex.ETA[0]
    j = _AX[seq[1]]
    rowT = ex.axis_rotation(seq[0], a).T[j, :]
    rowT = rowT.xreplace({sp.sin(a): As, sp.cos(a): Ac})
    m = rowT * Q
    (cs, ss), (cc, sc) = d["c_sin"], d["c_cos"]
    return ss * m[0, cs], sc * m[0, cc]


def euler_angles_from_rotation(seq: str, Q: sp.Matrix, branch: int = 1) -> sp.Matrix:
    """The intrinsic ``seq`` Euler angles ``[a; b; c]`` of ``Q = R_i(a) R_j(b) R_k(c)``.

    Source: the inverse of ``euler_rotation`` (Exercise 3.10, Angeles (2.49) per factor);
    the third angle through ``R_i(a)^T Q`` as Shoemake (Graphics Gems IV, 1994).

    Args:
        seq: one of the twelve intrinsic sequences (``"ZYX"``, ``"ZXZ"``, ...).
        Q: 3 x 3 rotation matrix.
        branch: ``1`` the principal branch (``cos b >= 0`` Tait-Bryan, ``sin b >= 0``
            proper Euler), ``-1`` the other.

    Returns:
        3 x 1 ``[a; b; c]`` [rad], each in ``[-pi, pi]``; off the gimbal lock only (there
        every atan2 below is ``atan2(0, 0)``: :func:`euler_angles_at_gimbal_lock`).
    """
    d = derive(seq)
    As, Ac = _first_pair(Q, d)
    As, Ac = branch * As, branch * Ac
    rho = branch * sp.sqrt(As**2 + Ac**2)
    (rm, sm) = d["mid"]
    b = sp.atan2(rho, sm * Q[rm]) if d["proper"] else sp.atan2(sm * Q[rm], rho)
    Cs, Cc = _third(seq, Q, As, Ac, d)
    return sp.Matrix([sp.atan2(As, Ac), b, sp.atan2(Cs, Cc)])


def euler_angles_at_gimbal_lock(seq: str, Q: sp.Matrix) -> sp.Matrix:
    """The member ``c = 0`` of the gimbal-lock family of ``Q`` (``rho(b) = 0``: ``Q = R_i(a)
    R_j(b)`` with ``b = +-pi/2`` Tait-Bryan, ``0`` or ``pi`` proper Euler; only ``a + c``
    or ``a - c`` is defined).

    Args:
        seq: one of the twelve intrinsic sequences.
        Q: 3 x 3 rotation matrix at the lock.

    Returns:
        3 x 1 ``[a; b; 0]`` [rad].
    """
    d = derive(seq)
    (rm, sm) = d["mid"]
    b = sp.atan2(0, sm * Q[rm]) if d["proper"] else sp.atan2(sm * Q[rm], 0)
    (rs, s1), (rc, s2) = d["lock_sin"], d["lock_cos"]
    return sp.Matrix([sp.atan2(s1 * Q[rs], s2 * Q[rc]), b, 0])


def checks(seq: str) -> list[tuple[str, bool]]:
    """Symbolic checks of the formulas of ``seq`` at ``Q = Q(a, b, c)``: each atan2's
    arguments equal ``r (sin x, cos x)`` with ``r = rho(b)`` (``>= 0`` on the principal
    branch's domain), ``r = 1`` at the lock; each a polynomial identity.

    Returns:
        ``[(what, holds)]``.
    """
    ex = _ex10()
    a, b, c = ex.ETA
    d = derive(seq)
    Q = ex.euler_rotation(seq)
    rho = sp.sin(b) if d["proper"] else sp.cos(b)
    As, Ac = _first_pair(Q, d)
    Cs, Cc = _third(seq, Q, As, Ac, d)
    rm, sm = d["mid"]
    mid = sm * Q[rm] - (sp.cos(b) if d["proper"] else sp.sin(b))
    Q0 = Q.xreplace({c: 0})
    (rs, s1), (rc, s2) = d["lock_sin"], d["lock_cos"]
    return [
        (f"{seq}: first pair = rho (sin a, cos a)",
         _is_zero(As - rho * sp.sin(a)) and _is_zero(Ac - rho * sp.cos(a))),
        (f"{seq}: middle entry", _is_zero(mid)),
        (f"{seq}: third pair = rho (sin c, cos c)",
         _is_zero(Cs - rho * sp.sin(c)) and _is_zero(Cc - rho * sp.cos(c))),
        (f"{seq}: at c = 0, column j = (sin a, cos a)",
         _is_zero(s1 * Q0[rs] - sp.sin(a)) and _is_zero(s2 * Q0[rc] - sp.cos(a))),
    ]
