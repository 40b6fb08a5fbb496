"""A function whose argument has no parentheses, then factors, in the second semantics
(``\\sin\\omega t``, ``\\cos\\theta\\phi``): the leading scalar factors may continue the
argument, a choice point (:data:`rigidsym.numeval.conventions.ARGUMENT_EXTENT`) where there
is one; a vector or matrix ends the run. Written here apart from the first semantics'
reading (:mod:`rigidsym.latex.transformer.extent`)."""

from __future__ import annotations

import lark

from rigidsym.numeval import conventions
from rigidsym.numeval import values as V

__all__ = ["extent_value"]


def scalar_value(v) -> bool:
    """``v`` is a scalar value (a 1x1 matrix counts): it may continue a function's argument."""
    v = V.scalar(v)
    return not (V.is_matrix(v) or isinstance(v, V.Eye | V.Zero))


def extent_value(ev, t):
    """The value of the ``arg_extent`` subtree ``t`` (:func:`rigidsym.latex.rewrites.
    argument_extents`) under the reading of its choice point.

    Args:
        ev: the :class:`~rigidsym.numeval.evaluator.Evaluator` (its ``value``, ``choose``
            and ``function_of``).
        t: the subtree: the function's tokens, its argument, then the factors after it.

    Raises:
        NotCovered: a construct of the argument or the factors it does not evaluate.
    """
    texts = [str(c) for c in t.children[3::2]]
    inner, factors = t.children[2], [ev.value(c) for c in t.children[4::2]]
    kids = list(inner.children)
    arg = ev.value(kids[-1])
    run = 0
    if scalar_value(arg):
        while run < len(factors) and scalar_value(factors[run]):
            run += 1
    how = "factor"
    if run:
        key = conventions.choice_key(
            "argument extent", " ".join([str(t.children[0]), str(t.children[1]),
                                         *texts[:run]]))
        how = conventions.settled("argument extent") or ev.choose(
            key, conventions.ARGUMENT_EXTENT)
    if how == "product":
        for f in factors[:run]:
            arg = V.mul(arg, f)
        factors = factors[run:]
    v = ev.function_of(lark.Tree(inner.data[len("extent_"):], kids), arg)
    for f in factors:
        v = V.mul(v, f)
    return v
