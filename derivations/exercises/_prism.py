"""Exact integration over the regular hexagonal prism and its parts (Exercises 3.11-3.12).

The hexagon (side ``a``) is centred at the origin of the x-y plane with two edges at
``y = +-s``, ``s = a sqrt(3)/2``; the prism spans ``0 <= z <= h``. A part is the set
``zlo(y) <= z <= zhi(y)`` over the hexagon; every integral is an exact iterated sympy
integral of a polynomial (density 1).
"""

from __future__ import annotations

import functools

import sympy as sp

from rigidsym.course.worked import Check, Undecided, is_zero, settled, values_only

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


def integrate_pieces(f, pieces, a=A_SIDE, split=None):
    """``int f dV`` over the union of ``{(x, y) in hexagon, ylo <= y <= yhi, zlo(y) <= z <=
    zhi(y)}`` for ``(ylo, yhi, zlo, zhi)`` in ``pieces`` (``-s <= ylo <= yhi <= s``),
    exactly; a piece is split at ``y = 0``, where the hexagon's x-bound changes, as
    ``split`` says (one :func:`halves` per piece; decided on the pieces when not given)."""
    split = split or [halves(p[0], p[1]) for p in pieces]
    total = 0
    for (ylo, yhi, zlo, zhi), (below, above, neg, pos) in zip(pieces, split, strict=True):
        g = _definite(f, z, zlo, zhi)
        if neg:
            xmax = a + y / sp.sqrt(3)
            total += _definite(_definite(g, x, -xmax, xmax), y, ylo, yhi if below else 0)
        if pos:
            xmax = a - y / sp.sqrt(3)
            total += _definite(_definite(g, x, -xmax, xmax), y, ylo if above else 0, yhi)
    return sp.radsimp(sp.expand(total))


def halves(ylo, yhi) -> tuple:
    """How the piece ``ylo <= y <= yhi`` splits at ``y = 0``, decided exactly on closed
    bounds: ``(yhi <= 0, ylo >= 0, the half y <= 0 is not empty, the half y >= 0 is not
    empty)``. Pieces with the same split have the same polynomial integrals in their bounds.
    In a replay for its values only, each sign is taken on a value clear of 0
    (:func:`rigidsym.course.worked.settled`)."""
    below, above = bool(settled(sp.radsimp(yhi)) <= 0), bool(settled(sp.radsimp(ylo)) >= 0)
    return (below, above, bool(settled(sp.radsimp((yhi if below else 0) - ylo)) > 0),
            bool(settled(sp.radsimp(yhi - (ylo if above else 0))) > 0))


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
    if pieces is None and zlo == 0 and _closed(zhi, a):
        return _evaluated(_whole_prism(), a, zhi)
    return _mass_properties(zlo, zhi, a, pieces)


def part_properties(pieces_of, a, h, *args):
    """:func:`mass_properties` of the part ``pieces_of(a, h, *args)`` (a module-level
    function giving :func:`integrate_pieces`'s pieces), integrated once in a symbolic side
    and height for each way its pieces split at ``y = 0`` (decided exactly on ``a``, ``h``:
    the integrals are polynomials in the bounds there) and evaluated at ``a``, ``h``."""
    if not _closed(a, h):
        return _mass_properties(None, None, a, pieces_of(a, h, *args))
    split = tuple(halves(p[0], p[1]) for p in pieces_of(a, h, *args))
    return _evaluated(_part_symbolic(pieces_of, args, split), a, h)


@functools.cache
def _part_symbolic(pieces_of, args, split):
    return _mass_properties(None, None, _SIDE, pieces_of(_SIDE, _HEIGHT, *args), split)


def _closed(*values) -> bool:
    return not any(sp.sympify(v).free_symbols for v in values)


def _evaluated(props, a, h):
    if values_only():
        return _floated(props, a, h)
    at = {_SIDE: sp.sympify(a), _HEIGHT: sp.sympify(h)}
    return tuple(v.xreplace(at).applyfunc(lambda e: sp.radsimp(sp.expand(e)))
                 if isinstance(v, sp.MatrixBase) else sp.radsimp(sp.expand(v.xreplace(at)))
                 for v in props)


#: the mpmath functions of (side, height) of each entry of a symbolic ``props``, by its id
_NUMERIC: dict[int, tuple] = {}


def _floated(props, a, h):
    """``props`` (symbolic in the side and the height) at floating ``a``, ``h``, in a
    replay for its values only: each entry an mpmath function of the two (sympy's
    ``lambdify``, made once for the cached ``props``) at 50 digits, as sympy Floats."""
    import mpmath

    from rigidsym.course.worked import DIGITS

    hit = _NUMERIC.get(id(props))
    if hit is None or hit[0] is not props:
        hit = (props, [sp.lambdify((_SIDE, _HEIGHT), list(v) if isinstance(v, sp.MatrixBase)
                                   else v, "mpmath") for v in props])
        _NUMERIC[id(props)] = hit
    out = []
    with mpmath.workdps(DIGITS):
        A, H = (mpmath.mpf(sp.Float(x, DIGITS)._mpf_) for x in (a, h))
        for v, f in zip(props, hit[1], strict=True):
            got = f(A, H)
            out.append(sp.Matrix(v.rows, v.cols, [sp.Float(x, DIGITS) for x in got])
                       if isinstance(v, sp.MatrixBase) else sp.Float(got, DIGITS))
    return tuple(out)


def _mass_properties(zlo, zhi, a, pieces, split=None):
    if pieces is None:
        s = a * sp.sqrt(3) / 2
        pieces = [(-s, s, zlo, zhi)]
    r = sp.Matrix([x, y, z])
    V = integrate_pieces(sp.Integer(1), pieces, a, split)
    c = sp.Matrix([integrate_pieces(ri, pieces, a, split) for ri in r]) / V
    c = c.applyfunc(lambda e: sp.radsimp(sp.expand(e)))
    I_O = sp.Matrix(3, 3, lambda i, j: integrate_pieces(
        (r.dot(r) if i == j else 0) - r[i] * r[j], pieces, a, split))
    I_C = I_O - V * (c.dot(c) * sp.eye(3) - c * c.T)
    return V, c, I_C.applyfunc(lambda e: sp.radsimp(sp.expand(e))), I_O


def principal_yz(I):
    """Principal moments and unit axes of a matrix with the x axis principal (I_xy = I_xz = 0).

    The y-z block gives ``lambda = (I_yy + I_zz)/2 -+ sqrt(((I_yy - I_zz)/2)^2 + I_yz^2)`` and
    unit axes ``[0, cos(alpha), sin(alpha)]``, ``tan(2 alpha) = 2 I_yz / (I_yy - I_zz)``.
    Returns ``[(I_xx, e_x), (lambda_1, v_1), (lambda_2, v_2)]`` sorted by moment (smallest
    first), with exact unit ``v`` (``v_k = [0, I_yz, lambda_k - I_yy] / |.|``; ``e_y``,
    ``e_z`` when ``I_yz = 0``), and the angle ``alpha`` of the y-z block's first axis.
    :func:`principal_check` checks the formula. In a replay for its values only, an
    ``I_yz`` within 1e-10 of the block's size is left to the exact solve.

    Raises:
        rigidsym.course.worked.Undecided: in such a replay, ``I_yz`` so near 0.
    """
    Iyy, Izz, Iyz = I[1, 1], I[2, 2], I[1, 2]
    out = [(I[0, 0], sp.Matrix([1, 0, 0]))]
    if values_only() and abs(Iyz) <= 1e-10 * (abs(Iyy) + abs(Izz)):
        # lambda - I_yy, of order I_yz^2 / (I_yy - I_zz), is then too small for floating data
        raise Undecided(f"I_yz = {Iyz} is too near 0 for the axes in floating point")
    if not values_only() and sp.radsimp(Iyz) == 0:
        yz = [(Iyy, sp.Matrix([0, 1, 0])), (Izz, sp.Matrix([0, 0, 1]))]
    else:
        rad = sp.sqrt(_discriminant(Iyy, Izz, Iyz))
        yz = []
        for lam, v in _yz_pairs(Iyy, Izz, Iyz, rad):
            n = sp.sqrt(sp.radsimp(sp.expand(v.dot(v))))
            yz.append((sp.radsimp(lam), v.applyfunc(lambda e, n=n: sp.expand(e) / n)))
    alpha = sp.atan2(yz[0][1][2], yz[0][1][1])
    out += yz
    out.sort(key=lambda p: float(sp.N(p[0], 30)))
    return out, alpha


def _discriminant(Iyy, Izz, Iyz):
    return sp.radsimp(sp.expand(((Iyy - Izz) / 2) ** 2 + Iyz**2))


def _yz_pairs(Iyy, Izz, Iyz, rad) -> list:
    """The y-z block's eigenpairs ``(lambda, [0, I_yz, lambda - I_yy])``, ``rad`` standing
    for the square root of :func:`_discriminant`."""
    mid = (Iyy + Izz) / 2
    return [(lam, sp.Matrix([0, Iyz, lam - Iyy])) for lam in (mid - rad, mid + rad)]


@functools.cache
def _formula_holds() -> bool:
    """:func:`_yz_pairs` as identities in symbols ``I_yy, I_zz, I_yz`` and ``s`` with
    ``s^2`` = the discriminant: ``(I - lambda_k) v_k = 0`` and ``v_1 . v_2 = 0``, each
    reduced modulo ``s^2 - discriminant`` to the zero polynomial (exact, decided once)."""
    p, q, r, s = sp.symbols("I_yy I_zz I_yz s", real=True)
    block = sp.Matrix([[0, 0, 0], [0, p, r], [0, r, q]])
    (l1, v1), (l2, v2) = _yz_pairs(p, q, r, s)
    exprs = list((block - l1 * sp.eye(3)) * v1) + list((block - l2 * sp.eye(3)) * v2)
    exprs.append(v1.dot(v2))
    rel = sp.Poly(s**2 - _discriminant(p, q, r), s)
    return all(sp.Poly(sp.expand(e), s).rem(rel).is_zero for e in exprs)


def principal_check(name: str, I, pairs) -> Check:
    """Check :func:`principal_yz`'s ``pairs`` of ``I``: ``I_xy = I_xz = 0`` exactly, and, when
    ``I_yz != 0``, the formula's identities (:func:`_formula_holds`, decided once in
    symbols, so a draw costs no minimal polynomial of its nested radicals); the axes are
    ``v / sqrt(v . v)``, unit by construction, ``e_x`` orthogonal to them; when ``I_yz = 0``
    the moments are ``I``'s diagonal about the coordinate axes, exactly. Not run in a replay
    for its values only (a failed check saying so)."""
    if values_only():
        return Check(name, False, "not run: a replay for its values only")
    if not is_zero(sp.Matrix([I[0, 1], I[0, 2]])):
        return Check(name, False, "I_xy or I_xz is not 0: x is not principal")
    if is_zero(I[1, 2]):
        ok = all(is_zero(I * v - lam * v) for lam, v in pairs)
        return Check(name, ok, "I_yz = 0: the coordinate axes, exactly (minimal polynomial)")
    return Check(name, _formula_holds(),
                 "I_xy = I_xz = 0, I_yz != 0 exactly; (I - lambda) v = 0 and v_1 . v_2 = 0 "
                 "as identities in I_yy, I_zz, I_yz modulo s^2 = ((I_yy - I_zz)/2)^2 + "
                 "I_yz^2 (polynomial remainder); axes v / sqrt(v . v)")


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
