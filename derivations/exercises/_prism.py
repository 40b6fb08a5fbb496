"""Exact integration over the regular hexagonal prism and its parts (Exercises 3.11-3.12).

The hexagon (side ``a``) is centred at the origin of the x-y plane with two edges at
``y = +-s``, ``s = a sqrt(3)/2``; the prism spans ``0 <= z <= h``. A part is the set
``zlo(y) <= z <= zhi(y)`` over the hexagon; every integral is an exact iterated sympy
integral of a polynomial (density 1).
"""

from __future__ import annotations

import functools

import sympy as sp

x, y, z = sp.symbols("x y z", real=True)
A_SIDE = sp.Rational(1, 40)   # 25 mm in m
HEIGHT = sp.Rational(3, 20)   # 150 mm in m
S = A_SIDE * sp.sqrt(3) / 2   # apothem


def _definite(f, v, lo, hi):
    """``int_lo^hi f dv`` of a polynomial in ``v``, exactly: the antiderivative of its
    :class:`~sympy.Poly` at the bounds (the integrands here are polynomials; sympy's
    general ``integrate`` took 7 s a prism, an exam's class of 30 waited minutes)."""
    F = sp.Poly(sp.expand(f), v).integrate().as_expr()
    return sp.expand(F.subs(v, hi) - F.subs(v, lo))


def integrate_part(f, zlo, zhi, a=A_SIDE):
    """``int f dV`` over ``{(x, y) in hexagon, zlo(y) <= z <= zhi(y)}``, exactly."""
    s = a * sp.sqrt(3) / 2
    return integrate_pieces(f, [(-s, s, zlo, zhi)], a)


def integrate_pieces(f, pieces, a=A_SIDE):
    """``int f dV`` over the union of ``{(x, y) in hexagon, ylo <= y <= yhi, zlo(y) <= z <=
    zhi(y)}`` for ``(ylo, yhi, zlo, zhi)`` in ``pieces`` (``-s <= ylo <= yhi <= s``),
    exactly; a piece is split at ``y = 0``, where the hexagon's x-bound changes."""
    total = 0
    for ylo, yhi, zlo, zhi in pieces:
        g = _definite(f, z, zlo, zhi)
        for lo, hi, xmax in ((ylo, sp.Min(yhi, 0), a + y / sp.sqrt(3)),
                             (sp.Max(ylo, 0), yhi, a - y / sp.sqrt(3))):
            if sp.radsimp(hi - lo) > 0:
                total += _definite(_definite(g, x, -xmax, xmax), y, lo, hi)
    return sp.radsimp(sp.expand(total))


_SIDE, _HEIGHT = sp.symbols("a_side h_height", positive=True)


@functools.cache
def _whole_prism():
    """The whole prism's mass properties once, in a symbolic side and height."""
    return _mass_properties(0, _HEIGHT, _SIDE, None)


def mass_properties(zlo, zhi, a=A_SIDE, pieces=None):
    """Volume V, centroid c, centroidal inertia per unit density I_C / rho (exact), and the
    inertia about O; of the part ``zlo(y) <= z <= zhi(y)``, or of ``pieces`` (see
    :func:`integrate_pieces`) when given. The whole prism (``zlo = 0``, ``zhi = h``, no
    pieces) is integrated once in a symbolic side and height and evaluated at the numbers
    (the same exact values; a class of 30 prisms integrates once)."""
    if pieces is None and zlo == 0 and all(sp.sympify(v).is_Number for v in (zhi, a)):
        at = {_SIDE: a, _HEIGHT: zhi}
        return tuple(sp.sympify(v).subs(at).applyfunc(lambda e: sp.radsimp(sp.expand(e)))
                     if isinstance(v, sp.MatrixBase) else sp.radsimp(sp.expand(v.subs(at)))
                     for v in _whole_prism())
    return _mass_properties(zlo, zhi, a, pieces)


def _mass_properties(zlo, zhi, a, pieces):
    if pieces is None:
        s = a * sp.sqrt(3) / 2
        pieces = [(-s, s, zlo, zhi)]
    r = sp.Matrix([x, y, z])
    V = integrate_pieces(sp.Integer(1), pieces, a)
    c = sp.Matrix([integrate_pieces(ri, pieces, a) for ri in r]) / V
    c = c.applyfunc(lambda e: sp.radsimp(sp.expand(e)))
    I_O = sp.Matrix(3, 3, lambda i, j: integrate_pieces(
        (r.dot(r) if i == j else 0) - r[i] * r[j], pieces, a))
    I_C = I_O - V * (c.dot(c) * sp.eye(3) - c * c.T)
    return V, c, I_C.applyfunc(lambda e: sp.radsimp(sp.expand(e))), I_O


def principal_yz(I):
    """Principal moments and unit axes of a matrix with the x axis principal (I_xy = I_xz = 0).

    The y-z block gives ``lambda = (I_yy + I_zz)/2 -+ sqrt(((I_yy - I_zz)/2)^2 + I_yz^2)`` and
    unit axes ``[0, cos(alpha), sin(alpha)]``, ``tan(2 alpha) = 2 I_yz / (I_yy - I_zz)``.
    Returns ``[(I_xx, e_x), (lambda_1, v_1), (lambda_2, v_2)]`` sorted by moment (smallest
    first), with exact unit ``v`` (``v_k = [0, I_yz, lambda_k - I_yy]`` normalised; ``e_y``,
    ``e_z`` when ``I_yz = 0``), and the angle ``alpha`` of the y-z block's first axis.
    """
    Iyy, Izz, Iyz = I[1, 1], I[2, 2], I[1, 2]
    out = [(I[0, 0], sp.Matrix([1, 0, 0]))]
    if sp.radsimp(Iyz) == 0:
        yz = [(Iyy, sp.Matrix([0, 1, 0])), (Izz, sp.Matrix([0, 0, 1]))]
    else:
        mid = (Iyy + Izz) / 2
        rad = sp.sqrt(sp.radsimp(sp.expand(((Iyy - Izz) / 2) ** 2 + Iyz**2)))
        yz = []
        for lam in (mid - rad, mid + rad):
            v = sp.Matrix([0, Iyz, lam - Iyy])
            n = sp.sqrt(sp.radsimp(sp.expand(v.dot(v))))
            yz.append((sp.radsimp(lam), v.applyfunc(lambda e, n=n: sp.radsimp(e / n))))
    alpha = sp.atan2(yz[0][1][2], yz[0][1][1])
    out += yz
    out.sort(key=lambda p: float(sp.N(p[0], 30)))
    return out, alpha


def hexagon(a) -> list:
    """The six vertices ``(x, y)`` of the base hexagon (side ``a``, edges at ``y = +-s``)."""
    s = a * sp.sqrt(3) / 2
    return [(a, 0), (a / 2, s), (-a / 2, s), (-a, 0), (-a / 2, -s), (a / 2, -s)]


def draw_prism(ax, a, h, color: str = "0.55", label: str | None = "prism") -> list:
    """The prism's edges on 3-D axes; returns its corner points (for the axes limits)."""
    from ._draw import segment

    hx = hexagon(a)
    pts = []
    for k, (px, py) in enumerate(hx):
        qx, qy = hx[(k + 1) % 6]
        for zz in (0, h):
            segment(ax, (px, py, zz), (qx, qy, zz), color=color,
                    label=label if (k, zz) == (0, 0) else None)
        segment(ax, (px, py, 0), (px, py, h), color=color)
        pts += [sp.Matrix([px, py, 0]), sp.Matrix([px, py, h])]
    return pts


def positive_sizes(s, a, h) -> None:
    """End ``s`` (ill-posed) unless the side and the height are positive."""
    if not (a > 0 and h > 0):
        s.fail(f"The side a = {a} and the height h = {h} must both be positive for a "
               f"prism.")
