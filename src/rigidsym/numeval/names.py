"""Spellings of one glyph that the second semantics takes as one: an accent over a
bare letter followed by a subscript, ``\\dot{\\Omega}_1`` or ``\\dot\\Omega_1``, is the
accent over the subscripted letter, ``\\dot{\\Omega_1}`` (TeX sets the same glyph, and the
reader keys them alike); a superscript label (``\\boldsymbol\\sigma^S``, ``x^{(k)}``) is
part of the name, one spelling for ``^S`` and ``^{S}``, and the shape of a free labelled
glyph is that of its letter. Imports lark and the standard library only."""

from __future__ import annotations

import re

import lark

__all__ = ["canonical", "decorated_name", "glyph_key", "unlabelled"]


def canonical(t: object) -> object:
    """``t`` with an accent's trailing subscript moved under the accent, a superscript
    label written before a subscript moved after it; any other tree as it is.

    Args:
        t: a parse subtree (``accented``, ``accented_bare``, or anything).
    """
    if isinstance(t, lark.Tree) and t.data == "label_first":  # a^S_1 is a_1^S
        labels = [c for c in t.children if isinstance(c, lark.Token) and c.type == "SUPLABEL"]
        t = lark.Tree("glyph", [c for c in t.children if c not in labels] + labels)
    if isinstance(t, lark.Tree) and t.data == "glyph" and t.children \
            and isinstance(t.children[-1], lark.Token) and t.children[-1].type == "SUPLABEL":
        label = "^{" + "".join(_plain_frame(str(t.children[-1])).lstrip("^").split()).strip(
            "{}") + "}"
        return lark.Tree("glyph", [*t.children[:-1], lark.Token("SUPLABEL", label)])
    if isinstance(t, lark.Tree) and t.data == "indexed_accent":  # {}^{G}\tilde{r}_C
        index, accent, letter, *rest = t.children
        plain = re.sub(r"\{([^{}]+)\}", r"\1", "".join(_plain_frame(str(index)).split()))  # {}^G
        spelt = lark.Token("LEFT_INDEX", plain)
        base = lark.Tree("base", list(letter.children)) if letter.data == "bare" else letter
        return lark.Tree("indexed_accent", [spelt, accent, base, *rest])
    if not isinstance(t, lark.Tree) or t.data not in ("accented", "accented_bare"):
        return t
    label = [c for c in t.children[2:] if isinstance(c, lark.Token) and c.type == "SUPLABEL"]
    if label:  # Savage's \dot{C}_B^N: the accent over C_B^N, its label part of the name
        accent, inner, *rest = [c for c in t.children if c not in label]
        return canonical(lark.Tree("accented", [accent, canonical(lark.Tree(
            "glyph", [_base_of(t.data, inner), *rest, *label]))]))
    if len(t.children) != 3:
        return t
    accent, inner, sub = t.children
    if not isinstance(sub, lark.Tree) or sub.data != "subscript":
        return t
    if t.data == "accented_bare":
        base = lark.Tree("base", list(inner.children))
    elif inner.data == "glyph" and len(inner.children) == 1 \
            and isinstance(inner.children[0], lark.Tree):
        base = inner.children[0]
    else:
        return t
    return lark.Tree("accented", [accent, lark.Tree("glyph", [base, sub])])


def _plain_frame(text: str) -> str:
    """A left index's or a label's text with a calligraphic frame as its plain letter
    (Kasdin & Paley's ``{}^{\\mathcal{A}}`` is ``{}^{A}``, ``^{\\mathcal{B}}`` is ``^{B}``)."""
    return re.sub(r"\\mathcal\s*\{\s*([A-Za-z])\s*\}", r"\1", text)


def _base_of(rule: str, inner):
    """The base of an accent's letter: a bare letter's, or a plain glyph's one child."""
    if rule == "accented_bare":
        return lark.Tree("base", list(inner.children))
    if inner.data == "glyph" and len(inner.children) == 1:
        return inner.children[0]
    return inner


def unlabelled(t: object) -> object:
    """A glyph tree as the letter that gives a free glyph's shape: without its superscript
    label, and a font that only names (``\\mathsf{R}``) as the plain letter."""
    if isinstance(t, lark.Tree) and t.data == "glyph" and len(t.children) > 1 \
            and isinstance(t.children[-1], lark.Token) and t.children[-1].type == "SUPLABEL":
        t = lark.Tree("glyph", t.children[:-1])
    if isinstance(t, lark.Tree) and t.data == "glyph" and t.children \
            and isinstance(t.children[0], lark.Tree) and t.children[0].data == "fontbase":
        t = lark.Tree("glyph", [lark.Tree("base", t.children[0].children[-1:]),
                                *t.children[1:]])
    return t


def decorated_name(tree: object) -> bool:
    """A glyph whose subscript or primes are part of its name, so that a free one has its
    letter's shape: ``x_1``, ``\\theta_{2}`` (a subscript of atoms), ``\\mathbf{g}'``,
    ``\\mathbf{g}''``, ``x_1'`` (primes: Shuster's composed Gibbs vectors).

    Args:
        tree: a parse subtree (a ``glyph``, or anything: then false).
    """
    if not isinstance(tree, lark.Tree) or tree.data != "glyph" or len(tree.children) < 2:
        return False
    rest = tree.children[1:]
    primes = [c for c in rest if isinstance(c, lark.Token) and c.type == "PRIMES"]
    subs = [c for c in rest if isinstance(c, lark.Tree) and c.data == "subscript"]
    if len(primes) + len(subs) != len(rest) or len(subs) > 1:
        return False
    return all(isinstance(c, lark.Token) and c.type == "SUBATOM"
               for s in subs for c in s.children)


def glyph_key(t) -> str:
    """A glyph's identity: its subtree's rules and tokens (``\\mathbf Q`` and ``\\mathbf{Q}``
    parse alike)."""
    t = canonical(t)  # \dot{\Omega}_1 is \dot{\Omega_1}
    if isinstance(t, lark.Token) and t.type == "BRACKET_NAME":  # [\mathbf q]_L: one spelling
        s = re.sub(r"[\s{}]", "", str(t))
        return re.sub(r"\\(boldsymbol|bm)(?![A-Za-z])", r"\\mathbf", s)
    if isinstance(t, lark.Token) and t.type == "LEFT_INDEX":  # {}^{G} and {}^G: one index
        return re.sub(r"\{([^{}]+)\}", r"\1", "".join(_plain_frame(str(t)).split()))
    if isinstance(t, lark.Token):
        # bold by any macro is one glyph, as the books and the reader take it
        return {"\\widehat": "\\hat", "\\widetilde": "\\tilde", "\\boldsymbol": "\\mathbf",
                "\\bm": "\\mathbf"}.get(str(t).strip(), str(t).strip())
    if t.data == "accented" and len(t.children) == 2 and isinstance(t.children[1], lark.Tree) \
            and len(t.children[1].children) == 1 and t.children[1].children[0].data == "base" \
            and len(t.children[1].children[0].children) == 1:  # \hat{\omega} is \hat\omega
        return glyph_key(lark.Tree("accented_bare", [
            t.children[0], lark.Tree("bare", t.children[1].children[0].children)]))
    return f"{t.data}(" + ",".join(glyph_key(c) for c in t.children) + ")"
