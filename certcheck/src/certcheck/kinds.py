"""The kinds a statement may declare, with the checker's own parametrisations and the
hypotheses (constraint polynomials) each kind gives. Nothing here is read from a
certificate: a certificate names a kind, and its meaning is this table's.

A group's atoms are listed row-major (``Q_11, Q_12, ..., Q_33``).
"""

from __future__ import annotations

__all__ = ["KINDS", "SIZES", "PARAMS", "parametrise", "constraints", "words"]

#: number of atoms of a group of each kind ("free" and "angle" groups have one atom)
SIZES = {"free": 1, "angle": 1, "angle_pi": 1, "unit": 3, "unit4": 4, "rotation": 9,
         "transform": 16}
#: the free parameters of the parametrisation of each constrained kind
PARAMS = {"unit": ("u", "v"), "unit4": ("u", "v", "w"), "rotation": ("q1", "q2", "q3", "q0"),
          "transform": ("q1", "q2", "q3", "q0", "p1", "p2", "p3")}
KINDS = tuple(SIZES)

_WORDS = {
    "free": "{g}: a real number (no hypothesis)",
    "angle": "{g}: an angle; cos and sin of its rational multiples are those of a real "
             "angle (cos^2 + sin^2 = 1 and the addition formulas)",
    "angle_pi": "{g}: an angle in [0, pi]",
    "unit": "{g}: a unit vector of R^3, {g}_1^2 + {g}_2^2 + {g}_3^2 = 1",
    "unit4": "{g}: a unit vector of R^4, the sum of the squares of its 4 entries = 1",
    "rotation": "{g}: a rotation matrix, {g}^T {g} = 1 and det {g} = 1",
    "transform": "{g}: a homogeneous transform [[R, p], [0, 1]], R^T R = 1, det R = 1, "
                 "last row (0, 0, 0, 1)",
}


def words(kind: str, group: str, timed: bool, order: int) -> str:
    """The hypothesis of a group in words."""
    s = _WORDS[kind].format(g=group)
    if timed:
        s += (f"; a smooth function of time, its derivatives up to order {order} "
              f"satisfying the time derivatives of these equations") if order else \
             "; a function of time"
    return s


def _stereographic(F, P):
    """``x_i = 2 p_i / (1 + |p|^2)``, ``x_last = (1 - |p|^2) / (1 + |p|^2)``."""
    s = F.one
    for p in P:
        s = F.add(s, F.mul(p, p))
    inv = F.inv(s)
    two = F.const(2)
    out = [F.mul(F.mul(two, p), inv) for p in P]
    return out + [F.mul(F.sub(F.const(2), s), inv)]


def _quaternion(F, P):
    """``Q = ((q0^2 - v.v) 1 + 2 v v^T + 2 q0 [v]x) / (q0^2 + v.v)``, ``P = (q1, q2, q3,
    q0)``: orthogonal with determinant 1 for every non-zero ``P``."""
    v, q0 = P[:3], P[3]
    vv = F.add(F.add(F.mul(v[0], v[0]), F.mul(v[1], v[1])), F.mul(v[2], v[2]))
    inv = F.inv(F.add(vv, F.mul(q0, q0)))
    diag = F.sub(F.mul(q0, q0), vv)
    z = F.zero
    cross = [[z, F.neg(v[2]), v[1]], [v[2], z, F.neg(v[0])], [F.neg(v[1]), v[0], z]]
    two = F.const(2)
    out = []
    for i in range(3):
        for j in range(3):
            x = F.mul(two, F.add(F.mul(v[i], v[j]), F.mul(q0, cross[i][j])))
            if i == j:
                x = F.add(x, diag)
            out.append(F.mul(x, inv))
    return out


def parametrise(kind: str, F, P) -> list:
    """The atoms of a group (row-major) as elements of the field ``F`` from the parameter
    elements ``P``."""
    if kind in ("unit", "unit4"):
        return _stereographic(F, P)
    if kind == "rotation":
        return _quaternion(F, P)
    if kind == "transform":
        R = _quaternion(F, P[:4])
        p = P[4:7]
        z, one = F.zero, F.one
        return [*R[0:3], p[0], *R[3:6], p[1], *R[6:9], p[2], z, z, z, one]
    raise ValueError(f"kind {kind!r} has no parametrisation")


def _det3(F, M):
    def m(i, j):
        return M[3 * i + j]
    out = F.zero
    for j in range(3):
        minor = F.sub(F.mul(m(1, (j + 1) % 3), m(2, (j + 2) % 3)),
                      F.mul(m(1, (j + 2) % 3), m(2, (j + 1) % 3)))
        out = F.add(out, F.mul(m(0, j), minor))
    return out


def _orthogonal(F, M):
    out = []
    for i in range(3):
        for j in range(i, 3):
            s = F.zero
            for k in range(3):
                s = F.add(s, F.mul(M[3 * k + i], M[3 * k + j]))
            out.append(F.sub(s, F.one) if i == j else s)
    out.append(F.sub(_det3(F, M), F.one))
    return out


def constraints(kind: str, F, X) -> list:
    """The constraint expressions of a group (each must vanish), from its atoms ``X``."""
    if kind in ("unit", "unit4"):
        s = F.zero
        for x in X:
            s = F.add(s, F.mul(x, x))
        return [F.sub(s, F.one)]
    if kind == "rotation":
        return _orthogonal(F, X)
    if kind == "transform":
        R = [X[i] for i in (0, 1, 2, 4, 5, 6, 8, 9, 10)]
        return _orthogonal(F, R) + [X[12], X[13], X[14], F.sub(X[15], F.one)]
    return []
