"""An undeclared blackboard glyph: Chirikjian's identity and zero (``\\mathbb{I}``,
``\\mathbb{O}``, also ``1`` and ``0``) or a name of the reader's own (Marsden & Ratiu's
inertia tensor ``\\mathbb{I}``).

The grammar reads ``\\mathbb{I}`` as the identity. Where nothing declares it, a statement
is decided under both readings (the identity, and :data:`NAME_READING`, a symmetric 3x3
matrix) and asked where they differ (:func:`both_blackboard`); ``--let '\\mathbb{I}:
identity'`` settles it (:func:`declared_identity`), and a ``--let`` naming a blackboard
glyph makes it a name (:func:`declared_blackboard`).
"""

from __future__ import annotations

import re

from rigidsym.latex.respell import each_declaration

__all__ = ["NAME_READING", "both_blackboard", "declared_blackboard", "declared_identity",
           "open_blackboard", "with_name_reading"]


#: Chirikjian's identity and zero, \mathbb{I} and \mathbb{O} (also 1, 0), as the grammar reads them
_BLACKBOARD = re.compile(r"\\mathbb\s*\{\s*([IO01])\s*\}")


#: \mathbb{I} as the grammar reads it (the identity), without a size subscript
#: (\mathbb{I}_3 is the identity of that size: no book's inertia tensor is written so)
_OPEN_I = re.compile(r"\\mathbb\{I\}(?!\s*_\s*\{?\s*\d)")
#: the declaration that settles \mathbb{I} as the identity
_IDENTITY = re.compile(r"\\mathbb\s*\{\s*I\s*\}\s*:\s*(?:the\s+)?identity(?:\s+matrix)?\s*",
                       re.IGNORECASE)
#: the kind the name reading of an undeclared \mathbb{I} gives it: Marsden & Ratiu's
#: inertia tensor, a symmetric 3x3 matrix
NAME_READING = r"\mathbb{I}: symmetric matrix"


def _blackboard_named(decls: list[str] | None) -> set[str]:
    """The blackboard glyphs (``I``, ``O``, ``0``, ``1``) a declaration of ``decls`` names."""
    return {m.group(1) for d in decls or []
            if (m := _BLACKBOARD.fullmatch(re.split(r"[:=(]", d, maxsplit=1)[0].strip()))}


def _texts(let: object) -> list[str] | None:
    """The declarations of ``let`` one by one, a dict's written ``NAME: KIND`` or
    ``NAME = LATEX``; ``None`` for a value :func:`rigidsym.latex.lets.read_lets` refuses."""
    from rigidsym.latex.lets import let_items

    if isinstance(let, dict):
        try:
            return let_items(let)
        except (TypeError, ValueError, AttributeError):
            return None
    return each_declaration(let)


def declared_identity(let: object) -> tuple[object, str | None]:
    """``let`` without its ``--let '\\mathbb{I}: identity'`` (Chirikjian's identity, the
    reading that declaration settles: :data:`rigidsym.latex.contested.CONTESTED`, "blackboard
    I"), and that declaration's text (``None`` where there is none; ``let`` unchanged).

    Args:
        let: the declarations, as :func:`declared_e`'s.

    Raises:
        BadInput: ``\\mathbb{I}`` declared the identity and named as well.
    """
    from rigidsym.core.errors import BadInput

    decls = _texts(let)
    said = [d for d in decls or [] if _IDENTITY.fullmatch(d)]
    if not said:
        return let, None
    kept = [d for d in decls if not _IDENTITY.fullmatch(d)]
    if len(said) > 1 or "I" in _blackboard_named(kept):
        other = next((d for d in kept if "I" in _blackboard_named([d])), said[-1])
        raise BadInput(f"--let: \\mathbb{{I}} is declared twice ('{said[0]}' and '{other}')")
    return kept, said[0]


def open_blackboard(latex: str, let: object) -> bool:
    """Whether ``latex`` or a declaration of ``let`` uses ``\\mathbb{I}`` (without a size
    subscript) and no ``--let`` names it: the identity in Chirikjian (2011), Marsden &
    Ratiu's inertia tensor (1999), a contested construct read both ways
    (:data:`rigidsym.latex.contested.CONTESTED`, "blackboard I"). A ``--let
    '\\mathbb{I}: identity'`` is taken out first (:func:`declared_identity`).

    Args:
        latex: the LaTeX.
        let: the declarations, as :func:`declared_e`'s.
    """
    decls = _texts(let)
    if decls is None or "I" in _blackboard_named(decls):
        return False
    return any(_OPEN_I.search(x) for x in [latex, *decls])


def with_name_reading(let: object) -> list[str]:
    """``let`` (one ``\\mathbb{I}`` uses, undeclared: :func:`open_blackboard`) with
    :data:`NAME_READING`: the statement read with ``\\mathbb{I}`` a name, Marsden &
    Ratiu's inertia tensor.

    Args:
        let: the declarations, as :func:`declared_e`'s (:func:`open_blackboard` true).
    """
    return [*(_texts(let) or []), NAME_READING]


def both_blackboard(first: str, other: str | None, notes: list[str],
                    why: str = "") -> None:
    """A statement that uses ``\\mathbb{I}`` undeclared, read both ways: ``first`` the
    verdict with ``\\mathbb{I}`` the identity, ``other`` with it a name (a symmetric 3×3
    matrix, :data:`NAME_READING`), ``None`` where that reading does not type-check (``why``:
    the reader's words). Where one verdict remains a note is appended to ``notes`` (the
    reading's).

    Raises:
        BadInput: they differ, or the name reading is refused (``why``): the reading is the
            reader's to declare, never assumed.
    """
    from rigidsym.core.errors import BadInput
    from rigidsym.latex.contested import construct

    c = construct("blackboard I")
    identity, name = c.readings
    if other == first:
        notes.append(f"\\mathbb{{I}}: not declared; read as {identity.means} "
                     f"({identity.books}) and as {name.means} ({name.books}): both {first}")
        return
    if other is None and why.startswith("shapes:"):
        notes.append(f"\\mathbb{{I}}: not declared; read as {identity.means} "
                     f"({identity.books}): {first}; as {name.means} ({name.books}), the "
                     f"statement does not type-check ({why[7:].strip()})")
        return
    said = other if other is not None else f"refused ({why})"
    raise BadInput(f"--latex: \\mathbb{{I}} is read two ways by the books, as "
                   f"{identity.means} ({identity.books}) or as {name.means} ({name.books}); "
                   f"nothing declares it, and the readings disagree (the identity: {first}; "
                   f"a symmetric 3×3 matrix: {said}): say which, {c.settles}")


def declared_blackboard(latex: str, let: object) -> tuple[str, object, str]:
    """``(latex, let, note)``: where a ``--let`` names ``\\mathbb{I}`` (Marsden & Ratiu's
    inertia tensor, ``--let '\\mathbb{I} = \\operatorname{diag}(I_1, I_2, I_3)'``; also
    ``\\mathbb{O}``), that glyph is the declared name, not Chirikjian's identity (zero): each
    occurrence in the LaTeX and the declarations is respelt ``\\mathbb{ I }``, the grammar's
    name in the blackboard font (``note`` says so); else all unchanged and ``note`` is ``""``.

    Args:
        latex: the LaTeX.
        let: the declarations, as :func:`declared_e`'s.
    """
    decls = each_declaration(let)
    named = _blackboard_named(decls)
    if not named:
        return latex, let, ""

    def name(m):
        return f"\\mathbb{{ {m.group(1)} }}" if m.group(1) in named else m.group(0)

    glyphs = ", ".join(f"\\mathbb{{{g}}}" for g in sorted(named))
    return (_BLACKBOARD.sub(name, latex), [_BLACKBOARD.sub(name, d) for d in decls],
            f"{glyphs}: the declared name, not the identity (zero) matrix")
