"""The quaternion product of the estimation books, a declaration of the reader's: ``\\otimes``
(Solà, Trawny-Roumeliotis), ``\\odot`` (Kok-Hol-Schön) and ``\\star`` (Hanson) between two
4-vectors, in
**Hamilton's** convention (scalar first, ``q = [w; x; y; z]``, ``ij = k``: Solà, Kok-Hol-Schön,
the default) or **JPL's** (scalar last, ``q = [x; y; z; w]``, ``ij = -k``: Trawny-
Roumeliotis, Breckenridge), said once: ``--let '\\otimes: JPL'`` (or ``Hamilton``; ``\\odot``
likewise). ``q^*`` of a 4-vector is its conjugate (the vector part negated, where the
convention puts it), ``q^{-1}`` its inverse, the conjugate over the squared norm (a unit
quaternion's is its conjugate). ``--notation jpl`` declares JPL's as a table line
``\\otimes: JPL`` (:data:`NOTATION_PRODUCTS`); a ``--let`` wins over it. ``read as:``
names the convention on every statement that uses one.

The products are written out from the conventions' definitions (Solà (2017) (12), Trawny &
Roumeliotis (2005) (8)); the second semantics has its own (:mod:`rigidsym.numeval.values`).
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar

import sympy as sp

from rigidsym.core.errors import BadInput
from rigidsym.latex.let_text import split_lets

__all__ = ["HAMILTON", "JPL", "NAMES", "current", "declared", "using", "split_setting",
           "product", "conjugate", "inverse", "said", "NOTATION_PRODUCTS", "word",
           "storage_order", "both_conventions", "other_reading", "READINGS", "scalar_last",
           "stored", "layout", "place_of"]

HAMILTON, JPL = "Hamilton", "JPL"
#: the glyphs of the product, as a --let NAME
NAMES = ("\\otimes", "\\odot", "\\star")
#: the notations whose table declares the product (``\\otimes: JPL`` in ``jpl.txt``)
NOTATION_PRODUCTS = {"jpl": JPL}
_CONVENTION: ContextVar[tuple[str, str | None]] = ContextVar("quaternion_convention",
                                                             default=(HAMILTON, None))


#: where the reader's own writing fixes the 4-vector's storage order: the scalar "first" or
#: "last", whatever the rule of the units; ``None``: the convention's own (Hamilton's first,
#: JPL's last). Szeliski (2022) (2.41)-(2.42), Eigen and ROS store (x, y, z, w) and multiply
#: by Hamilton's rule: the storage order does not fix the rule
_STORAGE: ContextVar[tuple[str, str] | None] = ContextVar("quaternion_storage", default=None)


def current() -> str:
    """The convention of the check running now (:data:`HAMILTON` unless one is declared)."""
    return _CONVENTION.get()[0]


def declared() -> str | None:
    """The ``--let`` that declared the convention now (it joins the check's id), or ``None``."""
    return _CONVENTION.get()[1]


@contextmanager
def using(convention: str, text: str | None = None) -> Iterator[None]:
    """Within the block ``convention`` (:data:`HAMILTON` or :data:`JPL`) is the product's.

    Raises:
        ValueError: another convention.
    """
    if convention not in (HAMILTON, JPL):
        raise ValueError(f"convention: expected {HAMILTON!r} or {JPL!r}, got {convention!r}")
    token = _CONVENTION.set((convention, text))
    try:
        yield
    finally:
        _CONVENTION.reset(token)


def scalar_last() -> bool:
    """Whether the scalar is a 4-vector's last entry in the check running now."""
    fixed = _STORAGE.get()
    return current() == JPL if fixed is None else fixed[0] == "last"


@contextmanager
def stored(order: str | None, how: str = "") -> Iterator[None]:
    """Within the block the scalar is entry ``order`` ("first", "last"; ``None``: where the
    convention puts it), whatever the rule of the units; ``how``: the writing that fixed it.

    Raises:
        ValueError: another order.
    """
    if order not in (None, "first", "last"):
        raise ValueError(f"order: expected 'first', 'last' or None, got {order!r}")
    token = _STORAGE.set(None if order is None else (order, how))
    try:
        yield
    finally:
        _STORAGE.reset(token)


def word(value: str) -> str | None:
    """The convention a declaration's value names (``"JPL"``, ``" hamilton"``, ``"Hamilton,
    scalar last"``), or ``None``."""
    rule, _, place = value.partition(",")
    if place and place_of(value) is None:
        return None
    return {"hamilton": HAMILTON, "jpl": JPL}.get(rule.strip().lower())


def place_of(value: str | None) -> str | None:
    """The scalar's place a declaration's value names after its rule (``"Hamilton, scalar
    last"``: Szeliski's and Eigen's layout), or ``None`` (the rule's own)."""
    _, _, place = (value or "").partition(",")
    return {"scalar first": "first", "scalar last": "last"}.get(" ".join(place.split()).lower())


def split_setting(let, notation: str | None = None) -> tuple[object, str, str | None]:
    """``let`` without its ``\\otimes: ...`` declaration, the convention, and the text of the
    declaration (``None``: none given, the notation's (:data:`NOTATION_PRODUCTS`) or
    Hamilton's).

    Raises:
        BadInput: a convention other than Hamilton and JPL, or two declarations.
    """

    convention, text = NOTATION_PRODUCTS.get((notation or "").strip().lower(), HAMILTON), None
    if let is None or isinstance(let, dict):
        return let, convention, text
    try:
        strings = split_lets([let] if isinstance(let, str) else list(let))
    except (TypeError, AttributeError):
        return let, convention, text
    kept = []
    for s in strings:
        name, _, value = s.partition(":")
        if name.strip() in NAMES and value.strip():
            if text is not None:
                raise BadInput(f"--let: the quaternion product is declared twice ('{text}' "
                               f"and '{s}')")
            named = word(value)
            if named is None:
                raise BadInput(f"--let '{s}': expected '{name.strip()}: Hamilton' (scalar "
                               f"first, ij = k) or '{name.strip()}: JPL' (scalar last, ij = -k), "
                               f"either followed by ', scalar last' or ', scalar first' where "
                               f"the layout is the other rule's (Szeliski's 'Hamilton, scalar "
                               f"last')")
            convention, text = named, s
        else:
            kept.append(s)
    return (let if text is None else kept), convention, text


def other_reading(rule: str, order: str) -> str:
    """The declaration text of another reading of an undeclared product (it joins that
    reading's id): the rule of the units and the scalar's place."""
    return f"\\otimes: {rule}, the scalar {order} (a reading of the undeclared convention)"


#: the pairs of a rule of the units and a scalar's place that the books use, and the books
#: behind each: an undeclared product is read under each (no book of the corpora pairs the
#: scalar first with ij = -k)
READINGS = {(HAMILTON, "first"): "Solà (2017), Kok-Hol-Schön (2017)",
            (JPL, "last"): "Trawny & Roumeliotis (2005)",
            (HAMILTON, "last"): "Szeliski (2022) (2.42), Eigen, ROS"}


def layout() -> str | None:
    """The scalar's place where the reader's writing fixed it ("first", "last"), or ``None``
    (it joins the check's id)."""
    fixed = _STORAGE.get()
    return None if fixed is None else f"the scalar {fixed[0]}"
#: a --let's slice of three entries of a 4-vector: \bar q_{1:3} (scalar last), q_{2:4}
#: (scalar first), counted from 1
_SLICE = re.compile(r"_\{\s*([1-4])\s*:\s*([1-4])\s*\}")


#: a column of two blocks, ``\\begin{bmatrix} 0 \\\\ \\mathbf{v} \\end{bmatrix}``
_BLOCKS = re.compile(r"\\begin\{[bp]matrix\}((?:(?!\\end\{|&).)*?)\\\\((?:(?!\\end\{|&|"
                     r"\\\\).)*?)\\end\{[bp]matrix\}", re.S)
_BOLD = re.compile(r"\\(?:mathbf|boldsymbol|bm)\b")
#: a norm's content (a scalar whatever it holds): \|\boldsymbol\eta\|
_NORMS = re.compile(r"\\\|.*?\\\|")
#: a plain letter's entry 0, q_0, q_{0}
_ZERO = re.compile(r"(?<![A-Za-z\\])([a-z])_\{?\s*0\s*\}?(?![0-9])")


def storage_order(let, latex: str = "") -> tuple[str, str] | None:
    """The convention the user's own writing fixes by the 4-vector's storage order:
    ``(JPL, how)`` where a ``--let`` names entries 1 to 3 as the vector part (``\\mathbf{q} =
    \\bar q_{1:3}``: the scalar last) or a column of two blocks puts a bold vector above a
    scalar, ``(HAMILTON, how)`` where a ``--let`` names entries 2 to 4 or a column puts the
    scalar first (Kok-Hol-Schön's ``[0; \\mathbf{v}]``); ``None`` where nothing does or the
    signs contradict each other. ``how`` says which writing fixed it."""
    strings: list[str] = []
    if let is not None:
        try:
            strings = split_lets([let] if isinstance(let, str) else
                                 [f"{k} = {v}" for k, v in let.items()]
                                 if isinstance(let, dict) else list(let))
        except (TypeError, AttributeError):
            strings = []
    found: dict[str, str] = {}
    for s in strings:
        for m in _SLICE.finditer(s):
            lo, hi = int(m.group(1)), int(m.group(2))
            if (lo, hi) == (1, 3):
                found.setdefault(JPL, f"--let '{s}'")
            elif (lo, hi) == (2, 4):
                found.setdefault(HAMILTON, f"--let '{s}'")
    for text in [latex, *strings]:
        for m in _BLOCKS.finditer(text or ""):
            top, bottom = (bool(_BOLD.search(_NORMS.sub("", g))) for g in m.groups())
            if top != bottom:
                written = " ".join(m.group(0).split())
                found.setdefault(JPL if top else HAMILTON, f"the column {written}")
    for text in [latex, *strings]:  # q_0 of a bold q: entries counted from 0, scalar first
        for m in _ZERO.finditer(text or ""):
            if re.search(r"\\(?:mathbf|boldsymbol|bm|bar)\s*\{?\s*" + re.escape(m.group(1))
                         + r"(?![A-Za-z])", " ".join([latex, *strings])):
                found.setdefault(HAMILTON, f"the entry {m.group(0)} (counted from 0: the "
                                           f"scalar first)")
    return next(iter(found.items())) if len(found) == 1 else None


def both_conventions(verdicts: dict[tuple[str, str], str], notes: list[str],
                     storage: str | None = None) -> None:
    """A statement that uses the quaternion product with no rule declared, read under each
    pair of a rule of the units and a scalar's place (:data:`READINGS`): ``verdicts`` each
    pair's verdict; ``storage`` what fixed the scalar's place (then both rules read in that
    one layout), or ``None``. Where they agree a note is appended to ``notes``.

    Raises:
        BadInput: they differ: the convention is the reader's to declare, never assumed.
    """
    rule = {HAMILTON: "Hamilton's ij = k", JPL: "JPL's ij = -k"}
    if len(set(verdicts.values())) == 1:
        pairs = ", ".join(f"{rule[r]} with the scalar {o}" for r, o in verdicts)
        what = (f"the scalar {next(iter(verdicts))[1]}, as {storage} fixes it; the rule of "
                f"the units declared by nothing" if storage else "no convention declared")
        notes.append(f"quaternion product: {what}; the statement read in each of the books' "
                     f"readings ({pairs}): each {next(iter(verdicts.values()))}")
        return
    each = "; ".join(f"{rule[r]} with the scalar {o} ({READINGS[(r, o)]}): {v}"
                     for (r, o), v in verdicts.items())
    fixed = (f"{storage} puts the scalar {next(iter(verdicts))[1]}, which does not fix the "
             f"rule of the units, " if storage else "nothing declares it, ")
    raise BadInput(f"--latex: the quaternion product \\otimes (\\odot, \\star) is read two ways "
                   f"by the books: the rule of the units (Hamilton's ij = k or JPL's ij = -k) "
                   f"and the scalar's place are two choices; {fixed}and the readings disagree "
                   f"({each}): say which, --let '\\otimes: Hamilton' (the scalar first), "
                   f"--let '\\otimes: JPL' (the scalar last; or --notation jpl) or --let "
                   f"'\\otimes: Hamilton, scalar last'")


def said() -> str:
    """The reading's note of the convention used."""
    fixed = _STORAGE.get()
    if fixed is not None:
        rule = ("ij = -k (Trawny & Roumeliotis (2005) (8))" if current() == JPL else
                "ij = k (Solà (2017) (12))")
        how = f"the storage order fixed by {fixed[1]}" if fixed[1] else "the storage order"
        return (f"quaternion product: {current()}'s, {how} (the scalar {fixed[0]}), the rule "
                f"of the units {rule}")
    if current() == JPL:
        return ("quaternion product: JPL's, scalar last q = [x; y; z; w], ij = -k "
                "(Trawny & Roumeliotis (2005) (8))")
    return ("quaternion product: Hamilton's, scalar first q = [w; x; y; z], ij = k (Solà "
            "(2017) (12); --let '\\otimes: JPL' for JPL's)")


def _parts(q) -> tuple[sp.Expr, sp.Matrix]:
    """``(scalar, vector part)`` of a 4-vector in the convention now."""
    e = [q[i, 0] for i in range(4)]
    if scalar_last():
        return e[3], sp.Matrix(e[:3])
    return e[0], sp.Matrix(e[1:])


def _join(w, v) -> sp.Matrix:
    if scalar_last():
        return sp.Matrix([v[0], v[1], v[2], w])
    return sp.Matrix([w, v[0], v[1], v[2]])


def product(p, q) -> sp.Matrix:
    """``p ⊗ q`` of two 4-vectors: Hamilton's ``[pw qw - pv·qv; pw qv + qw pv + pv × qv]``,
    JPL's ``[pw qv + qw pv - pv × qv; pw qw - pv·qv]`` (scalar last)."""
    pw, pv = _parts(p)
    qw, qv = _parts(q)
    sign = -1 if current() == JPL else 1
    return _join(pw * qw - pv.dot(qv), pw * qv + qw * pv + sign * pv.cross(qv))


def conjugate(q) -> sp.Matrix:
    """``q^*``: the vector part negated."""
    w, v = _parts(q)
    return _join(w, -v)


def inverse(q) -> sp.Matrix:
    """``q^{-1}``: the conjugate over the squared norm, ``q^* / (q^T q)`` (Solà (2017) (24),
    Trawny & Roumeliotis (2005) (13)); the same in both conventions' layouts."""
    n2 = sum(q[i, 0] ** 2 for i in range(4))
    return conjugate(q) / n2
