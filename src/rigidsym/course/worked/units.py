"""Units on a student's data: ``'0,0,100 mm'``, ``'30 deg'``, ``'1,0,1 N m'`` (pint).

A value's text may end with a unit, after a space; it applies to every entry, and the
entries are converted to the parameter's documented (SI) unit by an exact factor: pint
gives the conversion as a float, and the factor kept is the rational, or rational multiple
of pi, it rounds (``mm`` -> 1/1000, ``deg`` -> pi/180, ``in`` -> 127/5000), checked to 15
digits. The entries stay text, ``(100)*(1/1000)``, so the one number reader
(:mod:`.numbers`) reads them exactly. A bare number keeps the documented unit; one
implausible for it (a length above :data:`PLAUSIBLE` m: a 150 m prism) is read as given
and warned of, naming the unit assumed.
"""

from __future__ import annotations

import functools
import re

import sympy as sp

__all__ = ["split_unit", "factor", "with_unit", "implausible", "PLAUSIBLE", "answer_unit",
           "answer_factor", "slipped_unit"]

#: the largest magnitude plausible for a bare number in a parameter's unit (the chapter's
#: bodies and sensors are hand-sized to a few metres); above it, a warning names the unit
PLAUSIBLE = {"m": sp.Integer(10)}

# a unit: after a space, starts with a letter (or µ, °), then letters, digits, spaces,
# *, /, ^, ** and . (``N m``, ``kg*m^2``, ``m/s``); the number before it ends with a digit,
# a bracket or a degree sign. Written as students write it, a letter may follow the last
# digit directly (``30deg``, ``100mm``): pint still has to read the tail as a unit
_UNIT = re.compile(r"^(?P<num>.*?[\d)\]°.])(?:\s+|(?<=\d)(?=[A-Za-zµ]))"
                   r"(?P<unit>[A-Za-zµ°][A-Za-z0-9µ°_*/^.· ]*)$", re.S)


@functools.cache
def _registry():
    import pint

    return pint.UnitRegistry()


def split_unit(text: str) -> tuple[str, str | None]:
    """``"0,0,100 mm"`` -> ``("0,0,100", "mm")``; a text with no unit -> ``(text, None)``.
    Only a tail that pint reads as a unit counts (``"2 pi"`` has none: ``pi`` is a number
    to the reader, which refuses the space)."""
    m = _UNIT.match(text.strip())
    if not m:
        return text, None
    unit = m.group("unit").strip()
    if unit in ("pi", "E") or not _is_unit(unit):
        return text, None
    return m.group("num").strip(), unit


def _pint_text(unit: str) -> str:
    """The project's unit spelling as pint reads it: ``N m`` -> ``N*m``, ``m^2`` kept."""
    return re.sub(r"\s+", "*", unit.strip().replace("·", "*"))


def _is_unit(unit: str) -> bool:
    try:
        _registry().parse_units(_pint_text(unit))
    except Exception:  # noqa: BLE001 - pint raises several kinds for text it cannot read
        return False
    return True


def factor(unit: str, documented: str, where: str) -> sp.Expr:
    """The exact factor from ``unit`` to the parameter's ``documented`` unit.

    Raises:
        ValueError: the units are not compatible, or the parameter has no single unit
            (the message names ``where`` and both units).
    """
    if ";" in documented:
        raise ValueError(f"{where}: its entries have different units ({documented}); give "
                         f"bare numbers in those units, not {unit!r}")
    f = _float_factor(unit, documented, where)
    from fractions import Fraction

    for base, den in ((sp.pi, 10**4), (sp.Integer(1), 10**9)):   # deg = pi/180 first
        q = Fraction(f / float(base)).limit_denominator(den)
        guess = sp.Rational(q.numerator, q.denominator) * base
        if abs(float(guess) - f) <= 4e-16 * abs(f):
            return guess
    raise ValueError(f"{where}: the factor from {unit!r} to {documented} ({f!r}) is not an "
                     f"exact rational; give the value in {documented}")


def _float_factor(unit: str, documented: str, where: str) -> float:
    """pint's factor from ``unit`` to ``documented`` (a float), or a ValueError naming both."""
    ureg = _registry()
    target = _pint_text(documented) if documented else "dimensionless"
    if target in ("rad", "dimensionless") and unit in ("rad", "radian", "radians"):
        return 1.0
    try:
        return float(ureg.Quantity(1, _pint_text(unit)).to(target).magnitude)
    except Exception:  # noqa: BLE001 - pint's DimensionalityError and kin
        shown = documented or "a pure number"
        dim = str(ureg.parse_units(_pint_text(unit)).dimensionality)
        raise ValueError(f"{where}: {unit!r} is not a unit of {shown} ({unit} is "
                         f"{dim}); give {where} in {shown}, or a unit of it") from None


def with_unit(entries, unit: str, documented: str, where: str):
    """Each entry text times the exact factor (nested lists kept): ``"100"`` ->
    ``"(100)*(1/1000)"``."""
    f = factor(unit, documented, where)
    if f == 1:
        return entries
    if isinstance(entries, list):
        return [with_unit(e, unit, documented, where) for e in entries]
    return f"({entries})*({f})"


def implausible(value, documented: str, name: str) -> str:
    """A warning (one sentence) when a bare ``value`` is implausible in its documented
    unit, else ``""``."""
    top = PLAUSIBLE.get(documented)
    if top is None:
        return ""
    entries = list(value) if isinstance(value, sp.MatrixBase) else [value]
    big = max((abs(float(x)) for x in entries if isinstance(x, sp.Expr)), default=0.0)
    if big <= top:
        return ""
    return (f"Warning: {name} was read in {documented}, its documented unit: {big:g} "
            f"{documented} is implausible for the chapter's bodies; if you meant another unit, "
            f"write it after the value (e.g. '{name}=... mm').")


#: an answer's unit from its name's tail (``volume_m3``, ``centroid_m``), longest first
_TAILS = (("_per_kg_m2", "m^2"), ("_m5", "m^5"), ("_m3", "m^3"), ("_m2", "m^2"), ("_m", "m"),
          ("_rad", "rad"))


def answer_unit(module, name: str) -> str | None:
    """The documented unit of the answer ``name`` of an exercise ``module``: its
    ``ANSWER_UNITS`` entry, else its name's tail (``volume_m3`` -> ``m^3``); ``None`` when
    the answer documents no single unit (a pure number, a Plücker vector's two units)."""
    own = getattr(module, "ANSWER_UNITS", {})
    if name in own:
        return own[name] or None
    return next((u for tail, u in _TAILS if name.endswith(tail)), None)


def answer_factor(text: str, documented: str | None, where: str) -> tuple[str, float, str]:
    """A student's answer text with its unit taken off, the factor to the answer's
    documented unit, and the unit written (``"25 mm"`` -> ``("25", 0.001, "mm")``; no unit
    -> ``(text, 1.0, "")``).

    Raises:
        ValueError: a unit on an answer that documents none, or an incompatible one (the
            message names ``where`` and both units).
    """
    num, unit = split_unit(text)
    if unit is None:
        return text, 1.0, ""
    if documented is None:
        raise ValueError(f"{where}: this answer has no single unit to convert {unit!r} to; "
                         f"give the bare number")
    return num, _float_factor(unit, documented, where), unit   # a grade is a float judgement


def slipped_unit(ratio: float, documented: str | None) -> str | None:
    """The unit a bare number ``ratio`` times the right one was most likely given in (the
    answer's ``documented`` unit with a prefix: ``m`` and 1000 -> ``mm``, ``m^3`` and 1e9 ->
    ``mm^3``), or ``None``."""
    if not documented or "m" not in documented.split("^")[0].split():
        return None
    ureg = _registry()
    for pre in ("m", "c", "k", "µ", "d"):
        cand = re.sub(r"(?<![A-Za-z])m(?![A-Za-z])", pre + "m", documented)
        f = float(ureg.Quantity(1, _pint_text(cand)).to(_pint_text(documented)).magnitude)
        if abs(f * ratio - 1) < 1e-9:
            return cand
    return None
