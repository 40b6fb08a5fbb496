"""The norm of a free 3-vector under a trigonometric function, in polar form:
``\\sin\\|v\\|/\\|v\\|`` and ``(1 - \\cos\\|v\\|)/\\|v\\|^2``, the
coefficients of Rodrigues' formula for a rotation vector (Murray-Li-Sastry (2.14) for
``\\|\\omega\\| \\ne 1``, Markley-Crassidis, Diebel).

The zero test (:mod:`rigidsym.zero.decide`) takes the trigonometric functions of angles only;
``\\|v\\| = \\sqrt{v_1^2 + v_2^2 + v_3^2}`` is none. Every ``v \\ne 0`` is ``\\theta u`` for one
``\\theta > 0`` and one unit vector ``u``, and then ``\\|v\\| = \\theta`` exactly: each
``\\sqrt{v_1^2 + v_2^2 + v_3^2}`` becomes a fresh angle ``\\theta`` and each entry ``v_i``
becomes ``\\theta u_i``. The result ``F(\\theta, u)`` is rational in ``\\theta``, the sines and
cosines of multiples of ``\\theta`` and ``u`` (the rewrite is refused where any other root
of ``v`` is left), so it is analytic in ``\\theta``: if it vanishes identically (the zero
test, ``\\theta`` and ``\\tan(\\theta/2)`` independent), the original vanishes for every
``v \\ne 0``; if it does not vanish identically, it does not vanish on ``\\theta > 0``
either, so the original does not hold. No floating point decides it.
"""

from __future__ import annotations

import sympy as sp

from rigidsym.algebra.symbols import TIME, angle, constraint_of, unit_vector

__all__ = ["norm_vectors", "polar_norms"]

_TRIG = (sp.cos, sp.sin, sp.tan, sp.cot, sp.sec, sp.csc)


def _squares(base) -> tuple | None:
    """The symbols ``(x_1, x_2, x_3)`` when ``base`` is ``x_1^2 + x_2^2 + x_3^2`` of three
    distinct unconstrained real symbols (a free 3-vector's squared norm), else ``None``."""
    terms = sp.Add.make_args(sp.expand(base))
    xs = []
    for t in terms:
        if not (isinstance(t, sp.Pow) and t.exp == 2 and isinstance(t.base, sp.Symbol)):
            return None
        x = t.base
        if x == TIME or constraint_of(x) is not None or x in xs:
            return None
        xs.append(x)
    return tuple(sorted(xs, key=lambda s: s.name)) if len(xs) == 3 else None


def _multiple(radicand, base, xs, same):
    """``k`` when ``radicand`` is ``k`` times the squared norm ``base`` (``k`` a positive
    rational: ``\\|2\\eta\\|^2 = 4\\|\\eta\\|^2``), as written or identically on the
    constraint set by ``same``; else ``None``."""
    if not radicand.free_symbols & set(xs):
        return None
    k = sp.cancel(radicand / base)
    if k.is_Rational and k > 0:
        return k
    if same is not None and same(radicand, base):
        return sp.S.One
    return None


def norm_vectors(entries: list) -> dict[tuple, sp.Basic]:
    """The free 3-vectors whose norm ``\\sqrt{x_1^2 + x_2^2 + x_3^2}`` is in the argument of a
    trigonometric function somewhere in ``entries``.

    Args:
        entries: scalar sympy expressions.

    Returns:
        ``(x_1, x_2, x_3)`` (three unconstrained real symbols, sorted by name) -> the
        squared norm as written, one item per vector; empty when there is none.
    """
    groups: dict[tuple, sp.Basic] = {}
    for e in entries:
        for f in sp.preorder_traversal(e):
            if not isinstance(f, _TRIG):
                continue
            for p in sp.preorder_traversal(f.args[0]):
                if isinstance(p, sp.Pow) and p.exp == sp.Rational(1, 2):
                    xs = _squares(p.base)
                    if xs is not None:
                        groups.setdefault(xs, p.base)
    return groups


def polar_norms(entries: list, same=None) -> tuple[list, str] | None:
    """``entries`` with each free 3-vector whose norm is under sin/cos written ``\\theta u``.

    Args:
        entries: scalar sympy expressions (the differences the zero test decides).
        same: ``same(a, b)``, True when the radicands ``a`` and ``b`` agree identically on
            the constraint set (decided by the zero test): a root of ``a`` is then the norm
            too (Forster et al.'s ``\\mathrm{Exp}(\\mathbf{R}\\boldsymbol\\phi)``: the
            radicand of ``\\|R\\phi\\|`` is ``\\phi^T R^T R \\phi``, the squared norm of
            ``\\phi`` for a rotation R). ``None``: only the squared norm as written.

    Returns:
        ``(rewritten entries, a note naming each substitution)``, or ``None`` when no norm
        of a free 3-vector is under a trigonometric function, or when a root of such a
        vector other than its norm is left (the rewrite is then not exact).
    """
    groups = norm_vectors(entries)
    if not groups:
        return None
    out, notes = list(entries), []
    for i, (xs, base) in enumerate(sorted(groups.items(), key=lambda g: g[0][0].name)):
        name = "".join(x.name for x in xs)
        theta = angle(f"|{name}|")
        u = unit_vector(f"u[{name}]")
        norm, agree = {}, {}
        for e in out:  # every power of the squared norm with a half-integer exponent
            for p in sp.preorder_traversal(e):
                if not (isinstance(p, sp.Pow) and isinstance(p.exp, sp.Rational)
                        and p.exp.q == 2):
                    continue
                if p.base not in agree:
                    agree[p.base] = _multiple(p.base, base, xs, same)
                if agree[p.base] is not None:
                    norm[p] = agree[p.base] ** p.exp * theta ** (2 * p.exp)
        sub = {x: theta * u[k] for k, x in enumerate(xs)}
        out = [e.xreplace(norm).xreplace(sub) for e in out]
        v = f"({', '.join(x.name for x in xs)})"
        notes.append(f"|{v}| = θ{i or ''} > 0, {v} = θ{i or ''} u{i or ''}, u{i or ''} a "
                     f"unit vector")
        for e in out:
            for p in sp.preorder_traversal(e):
                if isinstance(p, sp.Pow) and not p.exp.is_integer \
                        and p.base.free_symbols & ({theta} | set(u)):
                    return None  # another root of the vector: not exact
    return out, "; ".join(notes)
