"""The given data of a worked exercise: declared parameters, read exactly or as measurements.

An exercise declares its numeric data as :class:`Param` rows (name, the book's value,
shape, one-line meaning, unit; :mod:`.params`, re-exported here). A student's value
is read by :func:`read_value`:

- exact: an ``int``, a :class:`fractions.Fraction`, a :class:`decimal.Decimal`, a decimal
  string (``"0.1"`` is 1/10), a string that sympifies to a closed real number
  (``"sqrt(3)/2"``) or a closed real sympy number;
- a measurement: a ``float`` (or a NumPy float, or a sympy ``Float``), converted exactly
  to the binary fraction it stores (0.1 is 3602879701896397/36028797018963968), and
  flagged, so the solution can say so and judge compatibility within a tolerance.

Bad input raises an error that names the parameter (and the entry) and what was expected:
``TypeError`` for a wrong type or an unknown name, ``ValueError`` for a wrong shape or a
value that is not a finite real number.
"""

from __future__ import annotations

import decimal
import numbers
import re
from dataclasses import dataclass, field
from fractions import Fraction

import sympy as sp

from rigidsym.course.worked.numbers import close, read_text, split_text
from rigidsym.course.worked.params import SHAPE_WORDS, IllPosed, Param, Parameters

__all__ = ["Param", "Parameters", "Data", "read_value", "read_data", "IllPosed"]

#: default tolerance of measured data, relative to the largest magnitude among the data
DEFAULT_RELATIVE_TOL = sp.Rational(1, 1000)


@dataclass
class Data:
    """The values a solver receives: exact sympy data, which were floats, and ``tol``."""

    values: dict
    floats: tuple = ()
    tol: sp.Rational | None = None
    tol_default: bool = False
    notes: list = field(default_factory=list)

    def key(self) -> tuple:
        """A hashable key of the data (for the solution cache)."""
        return (tuple((k, sp.srepr(v) if isinstance(v, sp.Basic) else repr(v))
                      for k, v in sorted(self.values.items())),
                self.floats, None if self.tol is None else str(self.tol))


# --------------------------------------------------------------------------- reading
def _scalar(v, where: str, measured: bool = True, notes: list | None = None
            ) -> tuple[sp.Expr, bool]:
    """One real number: ``(exact value, is it a measurement)``; see :mod:`.numbers`
    for text, transcendental values and the bounds. ``measured``: whether the exercise's
    data are measurements (a float is then its binary fraction, else its shortest
    decimal)."""
    notes = [] if notes is None else notes
    if isinstance(v, bool):
        raise TypeError(f"{where}: expected a real number, got a bool ({v})")
    if isinstance(v, sp.Float):
        v = float(v)
    elif isinstance(v, sp.Basic):    # before numbers.Real: sympy registers its numbers there
        return _kept(close(v, where, repr(v)), notes)
    if isinstance(v, numbers.Integral):
        return _kept(close(sp.Integer(int(v)), where, repr(int(v))), notes)
    if isinstance(v, Fraction):
        return _kept(close(sp.Rational(v.numerator, v.denominator), where, str(v)), notes)
    if isinstance(v, decimal.Decimal):
        if not v.is_finite():
            raise ValueError(f"{where}: expected a finite real number, got {v}")
        return _kept(close(sp.Rational(str(v)), where, str(v)), notes)
    if isinstance(v, numbers.Real):
        x = float(v)
        if x != x or x in (float("inf"), float("-inf")):
            raise ValueError(f"{where}: expected a finite real number, got {x}")
        # the magnitude bounds of every datum; a float's digits are few (17 at most)
        close(sp.Rational(repr(x)), where, repr(x))
        return (sp.Rational(x), True) if measured else (sp.Rational(repr(x)), False)
    if isinstance(v, str):
        return _kept(read_text(v, where), notes)
    raise TypeError(f"{where}: expected a real number (int, Fraction, decimal string such "
                    f"as '0.1', 'sqrt(3)/2', a sympy number or a float), got "
                    f"{type(v).__name__}")


def _kept(read: tuple, notes: list) -> tuple[sp.Expr, bool]:
    value, kind, more = read
    notes.extend(more)
    return value, kind == "rounded"


def _entries(p: Param, v) -> list:
    """``v`` as a flat row-major list of entries with the shape of ``p`` checked."""
    want = p.shape
    try:
        import numpy as np
        if isinstance(v, np.ndarray):
            v = v.tolist()
    except ImportError:  # pragma: no cover - numpy is a dependency
        pass
    if isinstance(v, sp.MatrixBase):
        got = (v.rows, v.cols)
        if len(want) == 1 and v.shape in ((want[0], 1), (1, want[0])):
            return list(v)
        if got == want:
            return list(v)
        raise ValueError(f"{p.name}: expected {SHAPE_WORDS[want]}, shape {want}, got a "
                         f"sympy Matrix of shape {got}")
    if isinstance(v, str | bytes) or not isinstance(v, list | tuple):
        raise TypeError(f"{p.name}: expected {SHAPE_WORDS[want]}, shape {want}, as a "
                        f"list, tuple, NumPy array or sympy Matrix; got {type(v).__name__}")
    if len(want) == 1:
        if len(v) != want[0] or any(isinstance(x, list | tuple) for x in v):
            raise ValueError(f"{p.name}: expected {SHAPE_WORDS[want]}, shape {want}, got "
                             f"{_shape_of(v)}")
        return list(v)
    if len(v) != want[0] or any(not isinstance(r, list | tuple) or len(r) != want[1]
                                for r in v):
        raise ValueError(f"{p.name}: expected {SHAPE_WORDS[want]}, shape {want}, got "
                         f"{_shape_of(v)}")
    return [x for r in v for x in r]


def _shape_of(v) -> str:
    if isinstance(v, list | tuple):
        inner = {len(r) if isinstance(r, list | tuple) else None for r in v}
        if inner == {None} or not v:
            return f"{len(v)} entries"
        return f"{len(v)} rows of " + "/".join(str(i) for i in sorted(inner, key=str)) \
            + " entries"
    return type(v).__name__


def read_value(p: Param, v, measured: bool = True, notes: list | None = None
               ) -> tuple[object, bool]:
    """Read a student's value of parameter ``p``: ``(exact sympy value, is a measurement)``.

    Args:
        p: the declared parameter.
        v: a number (see the module docstring) for a scalar; for a vector or matrix a
            list/tuple (nested for a matrix), a NumPy array, a sympy Matrix of numbers or
            a string (``"0,0,5"``, ``"1,0,0;0,1,0;0,0,1"``: the command line's reader);
            for a choice one of ``p.choices`` (case-insensitive).
        measured: whether the exercise's data are measurements: a float is then the
            binary fraction it stores (a measurement), else its shortest decimal (exact).
        notes: a list that receives the sentences on values read (rounded values, hints).

    Returns:
        A sympy number, a ``sympy.ImmutableMatrix`` (vectors as columns) or a str; and
        whether the value is a measurement (a float of a measured exercise, or a value
        rounded to 30 certified digits: see :mod:`.numbers`).

    Raises:
        TypeError: wrong type (the message names the parameter).
        ValueError: wrong shape, a string that is not a number, NaN/inf, complex, a
            magnitude outside 1e-15 to 1e15.
    """
    if v is None and p.default is None:
        return None, False           # an optional datum (3.10's angles), left out
    if p.shape is None:
        if not isinstance(v, str) or v.strip().upper() not in p.choices:
            raise ValueError(f"{p.name}: expected one of {', '.join(p.choices)}, got {v!r}")
        return v.strip().upper(), False
    if isinstance(v, str):
        v = _unit_read(p, v)
    if p.shape == () and p.unit == "rad" and isinstance(v, str):
        turns = _pi_multiple(v, p.name)
        if turns is not None:      # pi/4, 30 deg: exact, as their sines and cosines are
            return turns, False
    if p.shape == ():
        return _scalar(v, p.name, measured, notes)
    if isinstance(v, str):
        v = split_text(p.shape, v)
    flat = _entries(p, v)
    read = [_scalar(x, f"{p.name}[{i}]", measured, notes) for i, x in enumerate(flat)]
    rows, cols = (p.shape[0], 1) if len(p.shape) == 1 else p.shape
    return sp.ImmutableMatrix(rows, cols, [x for x, _ in read]), any(f for _, f in read)


def _pi_multiple(text: str, where: str):
    """An angle's text that is a rational multiple of pi (``pi/4``, ``(30)*(pi/180)``), as
    that exact multiple; else None (read as any number)."""
    from rigidsym.course.worked.numbers import bounded_number, parse_number

    try:
        read_text(text, where)                       # the reader's bounds and refusals
        value = bounded_number(parse_number(text.strip(), where), where, repr(text))
    except ValueError:
        return None
    ratio = sp.simplify(value / sp.pi)
    return ratio * sp.pi if ratio.is_Rational else None


def _unit_read(p: Param, text: str):
    """The text of a value with its unit (``"0,0,100 mm"``) as entry texts in ``p``'s
    documented unit (``[..., "(100)*(1/1000)"]``); a text with no unit as it is."""
    from rigidsym.course.worked.units import split_unit, with_unit

    num, unit = split_unit(text)
    if unit is None:
        return text
    return with_unit(split_text(p.shape, num) if p.shape else num, unit, p.unit, p.name)


def has_unit(v) -> bool:
    """Whether a raw value is a text that ends with a unit (``"25 mm"``)."""
    from rigidsym.course.worked.units import split_unit

    return isinstance(v, str) and split_unit(v)[1] is not None


#: a tolerance derived from the digits given: this many units in the last decimal place
DECIMAL_ULPS = 3
_DECIMAL = re.compile(r"^\s*[-+]?(\d*)\.(\d+)\s*$")


def _decimal_ulp(v):
    """The coarsest last decimal place among the decimal texts in a raw value (``"1.667"``
    -> 1/1000), or None when it holds none (integers and fractions are exact)."""
    if isinstance(v, str):
        from rigidsym.course.worked.units import split_unit

        num, unit = split_unit(v)
        if unit is not None:
            return None
        v = re.split(r"[,;\[\]]", num)
        got = [sp.Rational(1, 10 ** len(m.group(2))) for m in map(_DECIMAL.match, v) if m]
        return max(got) if got else None
    if isinstance(v, list | tuple):
        got = [u for u in (_decimal_ulp(x) for x in v) if u is not None]
        return max(got) if got else None
    return None


def _has_float(v) -> bool:
    """Whether a raw value holds a Python, NumPy or sympy float anywhere."""
    if isinstance(v, str | bytes | bool):
        return False
    if isinstance(v, sp.MatrixBase):
        return any(isinstance(x, sp.Float) for x in v)
    if hasattr(v, "tolist"):
        v = v.tolist()
    if isinstance(v, list | tuple):
        return any(_has_float(x) for x in v)
    return isinstance(v, float | sp.Float)


def _magnitude(values: dict) -> sp.Rational:
    best = sp.Integer(0)
    for v in values.values():
        for x in (list(v) if isinstance(v, sp.MatrixBase) else [v]):
            if isinstance(x, sp.Expr):
                best = max(best, abs(sp.Rational(str(sp.N(abs(x), 30)))))
    return best


def _default_tol(values: dict) -> tuple[sp.Rational, str]:
    mag = _magnitude(values)
    tol = DEFAULT_RELATIVE_TOL * (mag if mag > 0 else 1)
    return sp.Rational(f"{float(tol):.2g}"), "10^-3 x the largest magnitude among the data"


def read_data(params: Parameters, data: dict, tol=None) -> Data:
    """Check and read ``data`` (name -> value) against ``params``; missing names take the
    book's values. ``tol`` applies to measured data only (``params.measured``).

    Raises:
        TypeError: an unknown name (the message lists the exercise's parameters), a bad
            type, or ``tol`` given for an exercise whose data are not measurements.
        ValueError: a bad shape or value, or ``tol <= 0``.
    """
    unknown = [k for k in data if k not in params.names]
    if unknown:
        have = ", ".join(params.names) if params.names else "none (no numeric data)"
        raise TypeError(f"{params.exercise} has no parameter {unknown[0]!r}; its parameters "
                        f"are: {have}")
    values, measures, given_floats, notes, places = _read_given(params, data)
    out = Data(values, tuple(measures))
    _say_how_read(out, params, places, given_floats, notes)
    how = _tolerance(out, params, tol, values, measures, places, given_floats)
    if out.tol is not None:
        how = f"the default, {how}" if out.tol_default else "as given"
        out.notes.append(f"Measured data: compatibility is judged within tol = {out.tol} "
                         f"(~ {float(out.tol):.3g}; {how}); the answer is the least-squares "
                         f"one, with its residual.")
    return out


def _read_given(params: Parameters, data: dict) -> tuple:
    """Each parameter's value (read, or the book's): ``(values, measured names, names given
    as floats, notes, decimal places of readings, coarsest first)``."""
    values, measures, given_floats, notes, places = {}, [], [], [], []
    for p in params:
        if p.name in data and data[p.name] is None and p.default is None:
            values[p.name] = None          # an optional datum, left out (a notebook's None)
        elif p.name in data:
            values[p.name], measure = read_value(p, data[p.name], params.measured, notes)
            if not has_unit(data[p.name]):
                from rigidsym.course.worked.units import implausible
                warning = implausible(values[p.name], p.unit, p.name)
                if warning:
                    notes.append(warning)
            ulp = (_decimal_ulp(data[p.name]) if params.measured
                   and p.name in (params.readings or params.names) else None)
            if ulp is not None:
                places.append(ulp)
            if measure or ulp is not None:
                measures.append(p.name)
            if _has_float(data[p.name]):
                given_floats.append(p.name)
        else:
            values[p.name] = p.default
    places.sort(reverse=True)          # the coarsest reading first
    return values, measures, given_floats, notes, places


def _say_how_read(out: Data, params: Parameters, places: list, given_floats: list,
                  notes: list) -> None:
    """Append to ``out.notes`` the sentences on how decimals and floats were read, then
    ``notes`` (each hint once)."""
    if places and params.measured:
        out.notes.append(f"Decimals are readings: data given with a decimal point in a "
                         f"measured exercise are measurements, the coarsest read to "
                         f"{places[0]}; write fractions (5/3) for exact data.")
    if given_floats and params.measured:
        out.notes.append(f"Floats are measurements: {', '.join(given_floats)} were given as "
                         f"floats, each converted exactly to the binary fraction it stores "
                         f"(0.1 is 3602879701896397/36028797018963968); give strings such "
                         f"as '0.1' or '1/3' for exact data.")
    elif given_floats:
        out.notes.append(f"Floats in exact data: {', '.join(given_floats)} given as floats; "
                         f"the data of {params.exercise} are exact, so each float is "
                         f"read as the shortest decimal that prints it (0.1 is 1/10).")
    out.notes.extend(dict.fromkeys(notes))   # a hint once, however many entries share it


def _tolerance(out: Data, params: Parameters, tol, values: dict, measures: list,
               places: list, given_floats: list):
    """Set ``out.tol`` (and ``out.tol_default``): ``tol`` as given, or the default for
    measured data; returns how the default was chosen (``None`` when it was not).

    Raises:
        TypeError: ``tol`` for data that are not measurements.
        ValueError: ``tol <= 0``.
    """
    how = None
    if tol is not None:
        if not params.measured:
            from rigidsym.course.worked import measured_in_words

            raise TypeError(f"tol: the data of {params.exercise} are not measurements; tol "
                            f"applies to Exercises {measured_in_words()}")
        if isinstance(tol, float):
            tol = repr(tol)  # a tolerance is not data: read 1e-3 as the decimal it shows
        out.tol, _ = _scalar(tol, "tol")
        if not out.tol > 0:
            raise ValueError(f"tol: expected a positive number, got {tol!r}")
        if not out.tol.is_Rational:
            out.tol = sp.Rational(str(sp.N(out.tol, 30)))
    elif measures and params.measured:
        out.tol, how = (params.default_tol or _default_tol)(values)
        out.tol_default = True
        if places:
            digit_tol = DECIMAL_ULPS * places[0]
            if digit_tol > out.tol or not given_floats:
                out.tol = digit_tol
                how = (f"{DECIMAL_ULPS} units in the last decimal place given ({places[0]}: "
                       f"each entry is within half a unit, and an invariant of 3 entries in "
                       f"two frames moves by at most {DECIMAL_ULPS} units)")
    return how
