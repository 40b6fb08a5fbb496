"""Rewrites of the parse tree between the grammar and the transformer: where the LALR(1)
grammar cannot tell a reading by itself, these passes give the tree the shape TeX means
(a multiple angle's argument, a superscript written before a subscript) or mark what the
transformer must read by the shapes (a chain of products without parentheses:
:mod:`rigidsym.latex.transformer.products`). Each works in place and returns the tree;
:func:`rigidsym.latex.lexing.tree` runs them in order."""

from __future__ import annotations

import re

import lark

__all__ = ["multiple_angles", "mixed_products", "subscripts_first", "argument_extents"]

_TRIG = {"\\sin", "\\cos", "\\tan", "\\cot", "\\sec", "\\csc"}
_SYMBOL_RULES = {"glyph", "accented", "accented_bare", "arrow"}


def _number_arg(t) -> bool:
    r"""``t`` is ``\sin 2`` (or ``\sin^2 2``): a trigonometric function of a bare number."""
    return isinstance(t, lark.Tree) and t.data in ("func", "func_power") \
        and str(t.children[0]).replace(" ", "") in _TRIG \
        and isinstance(t.children[-1], lark.Tree) and t.children[-1].data == "number"


def multiple_angles(t):
    r"""``\sin 2\theta`` is sin(2θ), as every book means it, not sin(2) θ (the grammar's
    operator argument is one primary; read as the grammar has it, it would print ``θ sin 2``
    and decide that): a product whose left factor ends in a trigonometric
    function of a bare number and whose right factor is a symbol becomes the function of
    their product (``a \sin 2\theta \cos\phi`` is a sin(2θ) cos φ). In place; returns
    ``t``."""
    for sub in list(t.iter_subtrees()):  # bottom-up: inner products first
        if sub.data != "mul" or len(sub.children) != 2:
            continue
        left, right = sub.children
        if not (isinstance(right, lark.Tree) and right.data in _SYMBOL_RULES):
            continue
        if _number_arg(left):
            f, rest = left, None
        elif isinstance(left, lark.Tree) and left.data == "mul" and _number_arg(left.children[1]):
            f, rest = left.children[1], left.children[0]
        else:
            continue
        f.children[-1] = lark.Tree("mul", [f.children[-1], right])
        if rest is None:
            sub.data, sub.children = f.data, f.children
        else:
            sub.children = [rest, f]
    return t


_PRODUCTS = {"dot": "·", "cross": "×"}   # the product rules, and their signs in messages


def mixed_products(t):
    """A ``\\cdot`` and a ``\\times`` in one term with no parentheses between them
    (Goldstein's and Kane's ``a \\cdot b \\times c``, the triple product): the grammar
    groups them from the left, as ``(a \\cdot b) \\times c``, which TeX does not say. Such
    a chain of two becomes ``dot_cross`` (``cross_dot`` for ``a \\times b \\cdot c``) with
    its three operands, which the transformer reads by the shapes
    (:meth:`rigidsym.latex.transformer.book_notations.BookNotationRules.dot_cross`); a longer
    chain mixing them is refused (its groupings are not enumerated). Then the marks of the
    parentheses (``paren``) are dropped: the tree is the grammar's as before. In place;
    returns ``t``."""
    from rigidsym.latex.shapes import LatexError

    seen: set[int] = set()
    for sub in list(t.iter_subtrees_topdown()):
        if sub.data not in _PRODUCTS or id(sub) in seen:
            continue
        spine, node = [], sub
        while isinstance(node, lark.Tree) and node.data in _PRODUCTS:
            seen.add(id(node))
            spine.append(node)
            node = node.children[0]
        ops = [n.data for n in reversed(spine)]
        if ops == ["dot"] * len(ops) and len(ops) > 1:   # a \cdot b \cdot c: by the shapes
            sub.data = "dot_chain"                      # (BookNotationRules.dot_chain)
            sub.children = [node, *(n.children[1] for n in reversed(spine))]
            continue
        if len(set(ops)) < 2:
            continue
        if len(ops) > 2:
            raise LatexError(
                f"a chain of {len(ops)} products mixing · and × with no parentheses "
                f"({' '.join(_PRODUCTS[o] for o in ops)}): its groupings are not enumerated, and "
                f"a verdict on one would be a guess; write parentheses, e.g. a · (b × c)",
                "grouping")
        inner = spine[1]
        sub.data = f"{inner.data}_{sub.data}"  # dot_cross: a \\cdot b \\times c
        sub.children = [*inner.children, sub.children[1]]
    for sub in list(t.iter_subtrees()):
        sub.children = [_unparen(c) for c in sub.children]
    return _unparen(t)


def _unparen(c):
    while isinstance(c, lark.Tree) and c.data == "paren":
        c = c.children[0]
    return c


_GLYPH_TREES = {"glyph", "accented", "accented_bare"}


def subscripts_first(t):
    """TeX's ``X^a_b`` is ``X_b^a``: a subscript written after a superscript belongs to the
    symbol (Spong's ``R^T_{k,\\theta}`` is ``R_{k,\\theta}^T``; a syntax error before the
    outside trial of 16 books). The grammar reads it as ``power_sub`` (``apply_pre_sub``
    before an argument); here its subscript moves into the glyph, giving the tree of the
    subscript-first spelling. Of no glyph (``(a + b)^2_1``, ``\\overrightarrow{AB}^T_1``)
    or of a glyph with a subscript already (``x_1^2_3``, TeX's double subscript) it is
    refused, never read as a guess. In place; returns ``t``."""
    from rigidsym.latex.shapes import LatexError

    for sub in list(t.iter_subtrees()):
        if sub.data not in ("power_sub", "apply_pre_sub"):
            continue
        x, sup, script, *rest = sub.children
        if not (isinstance(x, lark.Tree) and x.data in _GLYPH_TREES) or any(
                isinstance(c, lark.Tree) and c.data == "subscript" for c in x.children):
            raise LatexError("X^a_b with X no symbol of its own (a group, a power, a symbol "
                             "with a subscript already): TeX puts the subscript on X; write "
                             "the subscript first, X_b^a, or braces: {X^a}_b is not read",
                             "syntax")
        at = 1 if x.data == "glyph" and not isinstance(x.children[0], lark.Tree) else 0
        at += 1 if x.data == "glyph" else 2  # after the base (the accent's glyph or letter)
        if at < len(x.children) and isinstance(x.children[at], lark.Token) \
                and x.children[at].type == "PRIMES":
            at += 1  # R'^T_z: after the primes, as R'_z^T
        x.children.insert(at, script)
        sub.data = "power" if sub.data == "power_sub" else "apply_pre"
        sub.children = [x, sup, *rest]
    return t


#: the functions whose argument a book may write without parentheses (``\sin\omega t``)
_EXTENT_FUNCS = {"func", "func_power", "matfunc"}
#: the factors that may continue such an argument: a glyph, a number, a power of either
_EXTENT_ATOMS = {"glyph", "accented", "accented_bare", "number", "label_first"}
#: TeX's explicit spaces: one after a function's argument ends it (``\sin\phi\,\mathbf{E}``)
_SPACES = re.compile(r"\\[,;: ]|\\q?quad(?![A-Za-z])|~")
_GROUPED = ("(", "{", "[", "\\left", "\\big", "\\Big")


def _span(node) -> tuple[int, int] | None:
    """The source span of a token or subtree (a rewritten one: its children's)."""
    if isinstance(node, lark.Token):
        return (node.start_pos, node.end_pos) if node.start_pos is not None else None
    if not node.meta.empty:
        return node.meta.start_pos, node.meta.end_pos
    spans = [s for s in (_span(c) for c in node.children) if s is not None]
    return (min(s[0] for s in spans), max(s[1] for s in spans)) if spans else None


def _atom(node) -> bool:
    if not isinstance(node, lark.Tree):
        return False
    if node.data == "power":
        return _atom(node.children[0])
    return node.data in _EXTENT_ATOMS


def _open_argument(f, text: str) -> bool:
    r"""``f`` is a function whose argument is written without parentheses or braces
    (``\sin\omega``, ``\sin^2\omega``, ``\sin 2\theta``), all spans known."""
    if not (isinstance(f, lark.Tree) and f.data in _EXTENT_FUNCS):
        return False
    before, arg = _span(f.children[-2]), _span(f.children[-1])
    if before is None or arg is None:
        return False
    return not text[before[1]:arg[1]].lstrip().startswith(_GROUPED)


#: a parenthesised group directly after a factor (``\cos\omega(t - t_0)``): its opening
#: and closing, TeX's sizing commands allowed
_OPENS = re.compile(r"\s*(?:\\left\s*)?\(\s*$")
_CLOSES = re.compile(r"\s*(?:\\right\s*)?\)")


def _group_after(prev, node, text: str) -> bool:
    r"""``node`` is written as a group in parentheses directly after ``prev`` (no space
    command between): Thomson's ``\cos\omega(t - t_0)``, an argument's continuation in the
    vibration books."""
    a, b = _span(prev), _span(node)
    return bool(_OPENS.fullmatch(text[a[1]:b[0]]) and _CLOSES.match(text, b[1]))


def _written(prev, node, text: str) -> str:
    """``node``'s text as written after ``prev``: with its parentheses where it is a group."""
    a, b = _span(prev), _span(node)
    if _group_after(prev, node, text):
        return text[a[1]:_CLOSES.match(text, b[1]).end()].strip()
    return text[b[0]:b[1]].strip()


def argument_extents(t, text: str):
    r"""A function whose argument is written without parentheses and then directly (no
    ``\,``, ``\;``, ``\quad``, ``~``, no operator) by further factors (``\cos\theta\phi``,
    ``\sin\omega t``) is a contested construct (:mod:`rigidsym.latex.contested`, "argument
    extent"): the grammar's operator argument is one primary, the vibration books' the whole
    run of scalar factors. Such a product becomes ``arg_extent``: the texts of the
    function's head and argument, the function (``extent_func``, ``extent_func_power``,
    ``extent_matfunc``: the rule's own children) and each factor after its text; each
    semantics reads it under the reading chosen, the shapes ending the run at the first
    factor that is no scalar. ``text`` is the parsed text the spans index. In place;
    returns ``t``."""
    done: set[int] = set()
    for sub in list(t.iter_subtrees_topdown()):
        if sub.data != "mul" or id(sub) in done:
            continue
        spine, node = [], sub
        while isinstance(node, lark.Tree) and node.data == "mul" and len(node.children) == 2:
            done.add(id(node))
            spine.append(node)
            node = node.children[0]
        factors = [node, *(n.children[1] for n in reversed(spine))]
        out, i, changed = [], 0, False
        while i < len(factors):
            f, j = factors[i], i + 1
            if _open_argument(f, text):
                while j < len(factors) and _span(factors[j - 1]) and _span(factors[j]) and (
                        _atom(factors[j]) and not _SPACES.search(
                            text[_span(factors[j - 1])[1]:_span(factors[j])[0]])
                        or _group_after(factors[j - 1], factors[j], text)):
                    j += 1
            if j == i + 1:
                out.append(f)
                i += 1
                continue
            (start, _), arg = _span(f), _span(f.children[-1])
            kids = [lark.Token("EXTENT", text[start:arg[0]].strip()),
                    lark.Token("EXTENT", text[arg[0]:arg[1]].strip()),
                    lark.Tree("extent_" + f.data, list(f.children))]
            for k in range(i + 1, j):
                kids += [lark.Token("EXTENT", _written(factors[k - 1], factors[k], text)),
                         factors[k]]
            out.append(lark.Tree("arg_extent", kids))
            changed, i = True, j
        if not changed:
            continue
        v = out[0]
        for g in out[1:]:
            v = lark.Tree("mul", [v, g])
        sub.data, sub.children = v.data, v.children
    return t
