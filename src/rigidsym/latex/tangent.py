"""The tangent order of SE(3), a declaration of the reader's: a twist ``[ω; v]`` (angular
first: Modern Robotics, Murray-Li-Sastry, Featherstone, the chapter) or ``[v; ω]``
(translation first: Barfoot's ``ξ = [ρ; φ]``, Solà's ``τ = [ρ; θ]``, manif, Sophus).

It is said once, ``--let 'tangent order: translation first'`` (or ``angular first``; the
books' spellings ``[\\rho;\\theta]``, ``[v;\\omega]``, ``[\\omega;v]`` too), or by a
``--notation`` whose book fixes it (:data:`NOTATION_ORDERS`: ``barfoot``, ``sola``
translation first; ``lynch-park``, ``murray-li-sastry``, ``featherstone``, ``corke``
angular first). A statement that uses an order nothing declares is read in both: one
verdict where they agree, else bad input naming the ``--let`` (the order is never assumed).
It rules the hat of a 6-vector, its vee, ``Ad`` and ``ad`` of both semantics (the symbolic
path through :mod:`rigidsym.algebra.rigid_motions`' ``order``, the second through
:mod:`rigidsym.numeval.values`' own definitions), and ``read as:`` names the order on every
statement that uses one.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar

from rigidsym.core.errors import BadInput
from rigidsym.latex.let_text import split_lets

__all__ = ["ANGULAR", "TRANSLATION", "NAME", "ORDER_OF", "OTHER", "current", "declared",
           "using", "rigid_order", "both_orders",
           "said", "split_setting", "NOTATION_ORDERS"]

ANGULAR, TRANSLATION = "angular first", "translation first"
#: the NAME of the declaration (``--let 'tangent order: ...'``)
NAME = "tangent order"
#: the words of a declaration (spaces and ``\boldsymbol``/``\mathbf`` ignored) -> the order
ORDER_OF = {"angular first": ANGULAR, "rotation first": ANGULAR,
            "translation first": TRANSLATION, "linear first": TRANSLATION,
            "[\\omega;v]": ANGULAR, "[\\theta;\\rho]": ANGULAR, "[\\phi;\\rho]": ANGULAR,
            "[v;\\omega]": TRANSLATION, "[\\rho;\\theta]": TRANSLATION,
            "[\\rho;\\phi]": TRANSLATION}
#: the declaration text of the other order's reading (it joins that reading's id)
OTHER = "tangent order: translation first (the undeclared order's other reading)"
#: the books whose notation fixes the order (their table's ``tangent order:`` line)
NOTATION_ORDERS = {"barfoot": TRANSLATION, "sola": TRANSLATION, "lynch-park": ANGULAR,
                   "murray-li-sastry": ANGULAR, "featherstone": ANGULAR, "corke": ANGULAR}
#: the order of the check running now and the text of its ``--let`` (``None``: none given)
_ORDER: ContextVar[tuple[str, str | None]] = ContextVar("tangent_order",
                                                        default=(ANGULAR, None))


def current() -> str:
    """The order of the check running now (:data:`ANGULAR` unless one is declared)."""
    return _ORDER.get()[0]


def declared() -> str | None:
    """The ``--let`` that declared the order of the check running now (it joins the
    check's id), or ``None``."""
    return _ORDER.get()[1]


@contextmanager
def using(order: str, text: str | None = None) -> Iterator[None]:
    """Within the block, ``order`` (:data:`ANGULAR` or :data:`TRANSLATION`) is the order,
    declared by the ``--let`` ``text`` (``None``: by a notation, or the default).

    Raises:
        ValueError: another order.
    """
    if order not in (ANGULAR, TRANSLATION):
        raise ValueError(f"order: expected {ANGULAR!r} or {TRANSLATION!r}, got {order!r}")
    token = _ORDER.set((order, text))
    try:
        yield
    finally:
        _ORDER.reset(token)


def rigid_order() -> str:
    """The order's name for :mod:`rigidsym.algebra.rigid_motions` (``order=``)."""
    return "ros" if current() == TRANSLATION else "angeles"


def said() -> str:
    """The reading's note of the order used."""
    if current() == TRANSLATION:
        return ("tangent order: translation first, a twist [v; ω] (Barfoot's ξ = [ρ; φ], "
                "Solà's τ = [ρ; θ]): the hat of a 6-vector, its vee, Ad and ad so")
    return ("tangent order: angular first, a twist [ω; v] (Modern Robotics, Murray-Li-Sastry; "
            "--let 'tangent order: translation first' for [v; ω]): the hat of a 6-vector, its "
            "vee, Ad and ad so")


def both_orders(first: str, other: str, notes: list[str]) -> None:
    """A statement that uses an order nothing declares, read in both: ``first`` the verdict
    angular first, ``other`` translation first. Where they agree, a note is appended to
    ``notes`` (the reading's).

    Raises:
        BadInput: they differ: the order is the reader's to declare, never assumed.
    """
    if first == other:
        notes.append(f"tangent order: not declared; the statement read in both orders, [ω; v] "
                     f"and [v; ω]: both {first}")
        return
    raise BadInput(f"--latex: the statement uses the tangent order of SE(3) (a twist [ω; v] or "
                   f"[v; ω]: the hat of a 6-vector, its vee, Ad, ad), nothing declares it, "
                   f"and the two orders disagree ([ω; v]: {first}; [v; ω]: {other}): say "
                   f"which, --let 'tangent order: angular first' or --let 'tangent order: "
                   f"translation first' (or a --notation that fixes it: barfoot, sola)")


def _words(text: str) -> str:
    t = re.sub(r"\\(?:boldsymbol|mathbf|bm)\s*\{?\s*(\\?[A-Za-z]+)\s*\}?", r"\1", text)
    if t.strip().startswith("["):
        return re.sub(r"\s+", "", t).replace(",", ";")
    return " ".join(t.split()).lower()


def split_setting(let, notation: str | None) -> tuple[object, str, str | None]:
    """``let`` without its ``tangent order`` declaration, the order, and the text of the
    declaration (``None`` where none was given; a notation that fixes the order gives it).

    Args:
        let: the ``--let`` argument of a check (``None``, a string, a list, a dict).
        notation: the ``--notation`` name, or ``None``.

    Raises:
        BadInput: an order no word of :data:`ORDER_OF` names, or two declarations.
    """

    order, text = NOTATION_ORDERS.get(notation or "", ANGULAR), None
    if let is None:
        return let, order, text
    if isinstance(let, dict):
        items = [(k, v, f"{k}: {v}") for k, v in let.items()]
    else:
        try:
            strings = split_lets([let] if isinstance(let, str) else list(let))
        except (TypeError, AttributeError):
            return let, order, text  # not strings: read_lets says what is wrong
        items = [(s.partition(":")[0], s.partition(":")[2], s) for s in strings]
    kept = []
    for name, value, whole in items:
        if isinstance(name, str) and " ".join(name.split()).lower() == NAME:
            if text is not None:
                raise BadInput(f"--let: the tangent order is declared twice ('{text}' and "
                               f"'{whole}')")
            words = _words(str(value))
            if words not in ORDER_OF:
                raise BadInput(f"--let '{whole}': expected 'tangent order: translation "
                               f"first' ([v; ω], [ρ; θ]) or 'tangent order: angular first' "
                               f"([ω; v])")
            order, text = ORDER_OF[words], whole
        else:
            kept.append((name, value, whole))
    if text is None:
        return let, order, None
    if isinstance(let, dict):
        return {k: v for k, v, _ in kept}, order, text
    return [w for _, _, w in kept], order, text
