"""Reading one number of a student's data: exact, or a certified rounding, never a hang.

The rule (documented in ``docs/exercise-data.md``):

- a closed **algebraic** number (rationals, ``+ - * /``, powers with rational exponents,
  ``sqrt``, and ``sin``/``cos``/``tan``/... of a rational multiple of ``pi``) is exact;
  the exercises decide their identities in that field (minimal polynomials);
- any other closed real number (``pi``, ``E``, ``cos(30)``, ``log(2)``) is not algebraic,
  and an algebraic one too large to work with (more than :data:`MAX_RADICALS` radicals or
  trig values, or a rational of more than :data:`MAX_DIGITS` digits) is **rounded**: it is
  replaced by its certified 30-significant-digit value (sympy's ``evalf(strict=True)``,
  which raises rather than return a digit it cannot vouch for) and flagged, so the exercise
  treats it as a measurement and says so;
- magnitudes outside ``[10^-15, 10^15]`` (zero aside) are refused with a reason, since no
  data of the chapter's bodies and sensors come near them and exact arithmetic on them
  takes minutes; so is a text with a function outside the list, an exponent above
  :data:`MAX_EXPONENT` or a part whose value exceeds ``10^100`` (each checked before it is
  computed);
- a trig call on a number above ``2 pi`` gets a hint: ``cos(30)`` is 30 radians, and
  ``cos(pi/6)`` (or ``cos(30°)``: ``°`` reads as ``*pi/180``) is 30 degrees.
"""

from __future__ import annotations

import re

import sympy as sp

__all__ = ["read_text", "classify", "split_text", "MAX_DIGITS", "MAX_RADICALS", "LIMITS"]

#: rationals with more digits (numerator or denominator) are rounded to 30 digits
MAX_DIGITS = 40
#: algebraic numbers with more radicals or trig values than this are rounded
MAX_RADICALS = 4
#: the largest exponent a text may raise to (``2**1000`` is refused before it is built)
MAX_EXPONENT = 100
#: non-zero magnitudes accepted, in the parameter's SI unit
LIMITS = (sp.Rational(1, 10**15), sp.Integer(10**15))
_DIGITS = 30
_TRIG = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)
_FUNCS = {"sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "cot": sp.cot, "sec": sp.sec,
          "csc": sp.csc, "asin": sp.asin, "acos": sp.acos, "atan": sp.atan, "exp": sp.exp,
          "log": sp.log, "sqrt": sp.sqrt, "Abs": sp.Abs, "abs": sp.Abs, "pi": sp.pi,
          "E": sp.E, "Rational": sp.Rational, "Integer": sp.Integer}
_NAME = re.compile(r"[A-Za-z_]\w*")


def split_text(shape: tuple, text: str):
    """A data string as the value of a parameter of ``shape``: the text itself for a
    scalar, a list of entry strings for a vector (``0,0,5`` or ``[0, 0, 5]``), a list of
    rows for a matrix (``1,0,0;0,2,0;0,0,3`` or ``[[1,0,0],[0,2,0],[0,0,3]]``). The one
    reader of the command line's ``--set`` and of a string given to ``solve``."""
    t = text.strip()
    if not shape:
        return t
    if len(shape) == 1:
        return [x.strip() for x in t.strip("[]").split(",")]
    rows = re.sub(r"\]\s*,\s*\[", ";", t).strip("[] ")
    return [[x.strip() for x in r.strip("[] ").split(",")] for r in rows.split(";")]


def _refuse(where: str, shown: str, why: str):
    raise ValueError(f"{where}: {shown} {why}")


def parse_number(text: str, where: str) -> sp.Expr:
    """Parse without evaluating, with only the listed names (nothing runs but sympy's
    number constructors)."""
    t = text.replace("°", "*pi/180").replace("^", "**")
    if not t:
        _refuse(where, "''", "is empty (expected a number such as 2, -5/3 or 0.1)")
    if len(t) > 200:
        _refuse(where, repr(text[:20] + "..."), "is longer than 200 characters")
    for name in _NAME.findall(t):
        if name in ("inf", "nan", "oo", "zoo", "infinity", "Infinity", "NaN"):
            _refuse(where, repr(text), "is not a finite real number")
        if name not in _FUNCS and not re.fullmatch(r"[eE]\d*", name):
            _refuse(where, repr(text), f"is not a number: {name!r} is not a name the reader "
                    f"knows ({', '.join(sorted(set(_FUNCS) - {'abs'}))}); expected e.g. "
                    f"2, -5/3, 0.1, sqrt(3)/2, cos(pi/6) or cos(30°)")
    try:
        e = sp.sympify(t, locals=dict(_FUNCS), rational=True, evaluate=False)
    except (sp.SympifyError, SyntaxError, TypeError, ValueError, AttributeError,
            TokenError):
        _refuse(where, repr(text), "is not a number (expected e.g. 2, -5/3, 0.1 or "
                "sqrt(3)/2)")
    if not isinstance(e, sp.Expr) or e.free_symbols:
        _refuse(where, repr(text), "is not a closed number (no symbols allowed)")
    return e


try:
    from tokenize import TokenError
except ImportError:  # pragma: no cover
    TokenError = SyntaxError  # type: ignore[assignment,misc]


def bounded_number(e: sp.Expr, where: str, shown: str) -> sp.Expr:
    """Build ``e`` bottom-up, refusing an exponent above MAX_EXPONENT or a part above
    10^100 before anything larger is computed."""
    if not e.args:
        return e
    args = [bounded_number(a, where, shown) for a in e.args]
    if isinstance(e, sp.Pow):
        ex = sp.N(args[1], 15)
        if not ex.is_real or abs(ex) > MAX_EXPONENT:
            _refuse(where, shown, f"raises to a power above {MAX_EXPONENT}")
    approx = _approx(e.func(*args, evaluate=False), where, shown)
    if approx is not None and abs(approx) > sp.Float(10) ** 100:
        _refuse(where, shown, "has a part larger than 10^100")
    return e.func(*args)


def _approx(e, where: str, shown: str):
    try:
        v = sp.N(e, 15)
    except (ValueError, TypeError, ZeroDivisionError, OverflowError, RecursionError):
        _refuse(where, shown, "cannot be evaluated to a real number")
    if v.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
        _refuse(where, shown, "is not a finite real number")
    re_, im = v.as_real_imag()
    return re_ if re_.is_Number else None


def classify(e: sp.Expr) -> str:
    """``"exact"`` for a closed algebraic number small enough to work with exactly,
    ``"rounded"`` for one to round to 30 digits (transcendental, or too large)."""
    radicals = _radicals(e)
    return "exact" if radicals is not None and radicals <= MAX_RADICALS else "rounded"


def _radicals(node) -> int | None:
    """How many radicals and trig values ``node`` is built from; None if it is not
    visibly algebraic (pi or E outside a trig argument, exp, log, asin, ...)."""
    if isinstance(node, sp.Rational):
        return None if max(len(str(abs(node.p))), len(str(node.q))) > MAX_DIGITS else 0
    if isinstance(node, _TRIG):
        return 1 if (node.args[0] / sp.pi).is_Rational else None
    if isinstance(node, sp.Pow) and not node.exp.is_Rational:
        return None
    if not isinstance(node, sp.Add | sp.Mul | sp.Pow | sp.Abs):
        return None
    parts = [_radicals(a) for a in node.args]
    if any(p is None for p in parts):
        return None
    return sum(parts) + (isinstance(node, sp.Pow) and not node.exp.is_Integer)


def trig_hints(e: sp.Expr) -> list[str]:
    """Hints for trig calls on a number above 2 pi (radians where degrees were meant)."""
    out = []
    for node in sp.preorder_traversal(e):
        if isinstance(node, _TRIG):
            arg = node.args[0]
            if arg.is_number and bool(abs(arg) > 2 * sp.pi):
                deg = node.func.__name__ + "(" + str(sp.pi * arg / 180) + ")"
                out.append(f"Hint: {node}: {arg} rad; for {arg}° write {deg}")
    return out


def read_text(text: str, where: str) -> tuple[sp.Expr, str, list[str]]:
    """One number from text: ``(value, "exact" or "rounded", notes)``.

    Raises:
        ValueError: not a closed finite real number, a name outside the list, a
            magnitude outside :data:`LIMITS`, an exponent or a part too large (the
            message names ``where``).
    """
    shown = repr(text.strip())
    e = bounded_number(parse_number(text.strip(), where), where, shown)
    return close(e, where, shown)


def close(e: sp.Expr, where: str, shown: str) -> tuple[sp.Expr, str, list[str]]:
    """Check a closed number and decide how it is kept (see :func:`read_text`)."""
    if not isinstance(e, sp.Expr) or e.free_symbols or not e.is_number:
        _refuse(where, shown, "is not a closed number (no symbols allowed)")
    if e.has(sp.Float):
        e = sp.nsimplify(e, rational=True)
    if e.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or e.is_finite is False:
        _refuse(where, shown, "is not a finite real number")
    approx = _approx(e, where, shown)
    if approx is None or e.is_extended_real is False:
        _refuse(where, shown, "is not a finite real number")
    notes = trig_hints(e)
    if approx != 0 or not _is_zero_exactly(e):
        lo, hi = LIMITS
        if abs(approx) > hi or abs(approx) < lo:
            _refuse(where, shown, "is outside the magnitudes the exercises solve (0, or "
                    "1e-15 to 1e15 in the parameter's SI unit); rescale the unit")
    kind = classify(e)
    if kind == "exact":
        return e, kind, notes
    try:
        v = sp.N(e, _DIGITS, strict=True)
    except (sp.core.evalf.PrecisionExhausted, ValueError, TypeError):
        _refuse(where, shown, "cannot be evaluated to 30 certified digits")
    notes.append(f"{where} = {shown} is not kept exactly (not algebraic, or too large to "
                 f"work with exactly): it is read as its certified 30-digit value {v}")
    return sp.Rational(str(v)), kind, notes


def _is_zero_exactly(e) -> bool:
    return e == 0 or (e.is_zero is True)
