"""What an answer box holds, and the slips that kind of answer admits.

As STACK's potential-response trees name a mistake only where the mathematics names it,
a box is graded with the slips of its kind alone (docs/exams.md, "Slips by kind"):

- ``truth``: true or false (1 or 0, one per statement); ``reason``: a reason's number;
  ``count``: a whole number. No slip: right or wrong.
- ``length``: a unit ``m^k`` (or declared): sign, a unit prefix of length only
  (10^(+-2k), 10^(+-3k): cm, mm for m), factor 2, swap, order, transpose, reference point.
- ``angle``: a unit ``rad`` or ``rad/s``: sign, degrees (either way), factor 2, reference
  point.
- ``rotation``: a 3 x 3 rotation: transpose, sign, swap, factor 2.
- ``quantity``: another unit (``N m``, ``kg m^2``): sign, a prefix (10^(+-3) and the
  powers of its lengths), factor 2, swap, order, transpose, reference point.
- ``vector``: no single unit (a Plücker array, barycentric weights): sign, factor 2, swap,
  order, transpose, reference point.

The slips along the way (the solution replayed with a slip in its data,
:mod:`rigidsym.course.slips`) and rounding apply to every kind but truth, reason and count.
A box's kind is its exercise module's ``ANSWER_KINDS`` entry, else the true-or-false
variants' (``holds``: truth, ``why``: reason), else read from its value and unit.

A slip then matches only where it means something (:func:`slip_counts`): the slipped key
differs from the key and from 0 beyond the tolerance, and the answer is no trivial one
(:func:`trivial`: all zero, all entries equal, a datum echoed).
"""

from __future__ import annotations

import re

import numpy as np
import sympy as sp

__all__ = ["KINDS", "box_kind", "admits", "unit_powers", "trivial", "slip_counts",
           "slip_close", "replays_admitted", "ZERO", "constant"]

KINDS = ("truth", "reason", "count", "length", "angle", "rotation", "quantity", "vector")

_ADMITS = {
    "truth": frozenset(), "reason": frozenset(), "count": frozenset(),
    "length": frozenset({"sign", "unit", "factor 2", "swap", "order", "transpose",
                         "reference point"}),
    "angle": frozenset({"sign", "degrees", "factor 2", "reference point"}),
    "rotation": frozenset({"transpose", "sign", "swap", "factor 2"}),
    "quantity": frozenset({"sign", "unit", "factor 2", "swap", "order", "transpose",
                           "reference point"}),
    "vector": frozenset({"sign", "factor 2", "swap", "order", "transpose",
                         "reference point"}),
}
#: the boxes of the proofs' true-or-false variants
_VARIANT_KINDS = {"holds": "truth", "why": "reason"}
#: an answer whose every entry is within this of 0 is zero (the grader's absolute floor)
ZERO = 1e-12
_LENGTH_UNIT = re.compile(r"^m(\^(\d+))?$")


def box_kind(module, name: str, value, unit: str | None = None) -> str:
    """The kind of box ``name`` (one of :data:`KINDS`).

    Args:
        module: the exercise module (its ``ANSWER_KINDS``: name -> kind, consulted first).
        name: the answer's name.
        value: the key's value (a sympy number, truth or matrix).
        unit: the answer's documented unit (:func:`~.worked.units.answer_unit`), or None.

    Raises:
        ValueError: an ``ANSWER_KINDS`` entry that is not one of :data:`KINDS`.
    """
    own = getattr(module, "ANSWER_KINDS", {}).get(name)
    if own is not None:
        if own not in KINDS:
            raise ValueError(f"ANSWER_KINDS[{name!r}]: expected one of {', '.join(KINDS)}, "
                             f"got {own!r}")
        return own
    if value in (sp.true, sp.false):
        return "truth"
    if name in _VARIANT_KINDS:
        return _VARIANT_KINDS[name]
    if unit:
        if _LENGTH_UNIT.match(unit.strip()):
            return "length"
        return "angle" if "rad" in unit else "quantity"
    if isinstance(value, sp.MatrixBase) and value.shape == (3, 3) and \
            all(x.is_number for x in value):
        try:
            q = np.array(sp.N(value, 17).tolist(), dtype=float)
        except TypeError:
            return "vector"
        if np.allclose(q.T @ q, np.eye(3), atol=1e-12) and np.linalg.det(q) > 0:
            return "rotation"
    return "vector"


def admits(kind: str, word: str) -> bool:
    """Whether a box of ``kind`` admits the final answer's slip ``word``."""
    return word in _ADMITS[kind]


def replays_admitted(kind: str) -> bool:
    """Whether a box of ``kind`` is compared with the slips along the way and rounding
    (every kind but a truth, a reason and a count)."""
    return kind not in ("truth", "reason", "count")


def unit_powers(kind: str, unit: str | None) -> tuple[int, ...]:
    """The powers of ten a unit slip of a box of ``kind`` in ``unit`` multiplies by.

    A length ``m^k`` (``m`` when no unit is written): +-2k, +-3k (cm, mm, either way); a
    quantity: +-3 (a kilo or milli prefix) and the powers of the lengths in it (``N m``:
    +-2, +-3; ``kg m^2``: +-3, +-4, +-6); any other kind: none.
    """
    if kind not in ("length", "quantity"):
        return ()
    k = 1
    m = _LENGTH_UNIT.match((unit or "m").strip())
    if kind == "length" and m:
        k = int(m.group(2) or 1)
        base = {2 * k, 3 * k}
    else:
        base = {3}
        for part in (unit or "").split():
            pm = _LENGTH_UNIT.match(part)
            if pm:
                k = int(pm.group(2) or 1)
                base |= {2 * k, 3 * k}
    return tuple(sorted({s * p for p in base for s in (1, -1)}))


def trivial(given: np.ndarray, key: np.ndarray, data: list[np.ndarray], rtol: float) -> bool:
    """An answer that earns no slip credit whatever it matches: all zero (every entry
    within :data:`ZERO` of 0, the grader's absolute floor), all entries equal (an array
    of two or more, within ``rtol`` of its largest entry; unless the ``key`` is so too:
    then its slips are), or a datum of the exercise echoed (equal within ``rtol`` to one
    of ``data`` of the same size)."""
    g = np.asarray(given, dtype=float).reshape(-1)
    if not g.size or not np.all(np.isfinite(g)):
        return True
    top = float(np.max(np.abs(g)))
    if top <= ZERO:
        return True
    if g.size > 1 and float(np.max(g) - np.min(g)) <= rtol * top and not constant(key, rtol):
        return True
    for d in data:
        d = np.asarray(d, dtype=float).reshape(-1)
        if d.size == g.size and float(np.max(np.abs(g - d))) <= \
                rtol * max(float(np.max(np.abs(d))), top):
            return True
    return False


def constant(a: np.ndarray, rtol: float) -> bool:
    """An array of two or more entries, all equal within ``rtol`` of its largest."""
    a = np.asarray(a, dtype=float).reshape(-1)
    return a.size > 1 and float(np.max(a) - np.min(a)) <= rtol * float(np.max(np.abs(a)))


def slip_counts(value: np.ndarray, key: np.ndarray, rtol: float) -> bool:
    """Whether a slipped key ``value`` can name a slip at all: it is finite, of the key's
    shape, not near zero (its largest entry above ``rtol`` times the key's) and differs
    from the key beyond the tolerance (else the slip is no mistake)."""
    v = np.asarray(value, dtype=float)
    k = np.asarray(key, dtype=float)
    if v.shape != k.shape or not v.size or not np.all(np.isfinite(v)):
        return False
    top_v, top_k = float(np.max(np.abs(v))), float(np.max(np.abs(k)))
    if top_k == 0.0 or top_v == 0.0:
        return False
    return float(np.max(np.abs(v - k))) > rtol * max(top_v, top_k)


def slip_close(given: np.ndarray, value: np.ndarray, rtol: float) -> bool:
    """``given`` within the tolerance of the slipped key ``value``, relative to the slipped
    key's largest entry (not the key's), with no absolute floor: 0 matches no slip."""
    g = np.asarray(given, dtype=float)
    v = np.asarray(value, dtype=float)
    if g.shape != v.shape or not v.size:
        return False
    return bool(np.all(np.abs(g - v) <= rtol * float(np.max(np.abs(v)))))
