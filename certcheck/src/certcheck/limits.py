"""Bounds on what one certificate may ask of the checker, each a located refusal.

A certificate is data from someone else: a statement of 40 nested squarings (degree 2^40),
an exponent of a million or an integer of a million digits would take the checker's time and
memory without end. Before any arithmetic, every parsed tree is measured:

- its **degree bound** (:func:`degree_bound`): a name counts 1, a sum the larger of its
  terms, a product or a quotient the sum of its factors', a power its base's times the
  exponent, ``cos``/``sin`` twice the size of their argument's coefficients (the tangent of
  the half angle, as the checker evaluates them); at most :data:`MAX_DEGREE`;
- each **exponent** at most :data:`MAX_EXPONENT` in size, each **integer** at most
  :data:`MAX_DIGITS` digits;
- the **nesting** of parentheses is bounded by the parser's recursion (a refusal, not a
  crash: :data:`MAX_NESTING`).

:func:`cpu_limit` bounds one certificate's CPU time (:data:`MAX_SECONDS`) where the platform
has ``setitimer`` (POSIX). The chapter's largest values, for scale: degree bound 74,
exponent 12, 6 digits, parentheses 4 deep (docs/certificates.md, "Limits").
"""

from __future__ import annotations

import contextlib
import signal
import sys
import threading
from fractions import Fraction

__all__ = ["LimitError", "MAX_DEGREE", "MAX_DIGITS", "MAX_EXPONENT", "MAX_NESTING",
           "MAX_SECONDS", "check_tree", "cpu_limit", "degree_bound"]

#: the largest degree bound of a side, a let or an evidence term
MAX_DEGREE = 400
#: the largest exponent (in size) of a power
MAX_EXPONENT = 64
#: the most digits of one integer literal
MAX_DIGITS = 60
#: the deepest nesting of parentheses and unary minus signs the parser follows
MAX_NESTING = 64
#: the most CPU seconds one certificate may take
MAX_SECONDS = 60.0


class LimitError(ValueError):
    """A certificate asks more than the checker's bounds allow (the message names which)."""


def _coefficients(node, memo: dict) -> Fraction:
    """A bound on the sum of the sizes of the coefficients of a cos/sin argument."""
    key = id(node)
    if key in memo:
        return memo[key]
    op = node[0]
    if op == "num":
        out = Fraction(abs(node[1]))
    elif op in ("name", "pi"):
        out = Fraction(1)
    elif op in ("add", "sub"):
        out = _coefficients(node[1], memo) + _coefficients(node[2], memo)
    elif op == "mul":
        out = _coefficients(node[1], memo) * _coefficients(node[2], memo)
    elif op in ("neg", "div"):
        out = _coefficients(node[1], memo)
    else:
        out = Fraction(1)
    memo[key] = out
    return out


def degree_bound(node, memo: dict | None = None) -> int:
    """A bound on the degree of the polynomial arithmetic ``node`` (a parse tree of
    :mod:`certcheck.parse`) asks for; shared subtrees (lets) are measured once.

    Raises:
        LimitError: an exponent or an integer past its bound.
    """
    memo = {} if memo is None else memo
    stack, order = [node], []
    while stack:  # post-order without recursion: a deep tree is measured, not a crash
        n = stack.pop()
        if id(n) in memo:
            continue
        order.append(n)
        if n[0] in ("add", "sub", "mul", "div"):
            stack.extend((n[1], n[2]))
        elif n[0] in ("neg", "pow", "sqrt"):
            stack.append(n[1])
    for n in reversed(order):
        if id(n) in memo:
            continue
        op = n[0]
        if op == "num":
            if len(str(n[1])) > MAX_DIGITS:
                raise LimitError(f"an integer of {len(str(n[1]))} digits (at most "
                                 f"{MAX_DIGITS})")
            d = 0
        elif op in ("name", "pi"):
            d = 1
        elif op in ("add", "sub"):
            d = max(memo[id(n[1])], memo[id(n[2])])
        elif op in ("mul", "div"):
            d = memo[id(n[1])] + memo[id(n[2])]
        elif op in ("neg", "sqrt"):
            d = memo[id(n[1])]
        elif op == "pow":
            if abs(n[2]) > MAX_EXPONENT:
                raise LimitError(f"an exponent {n[2]} (at most {MAX_EXPONENT} in size)")
            d = memo[id(n[1])] * abs(n[2])
        else:  # cos, sin: the tangent of the half angle, to the argument's multiple
            d = int(2 * max(1, _coefficients(n[1], {})))
        memo[id(n)] = min(d, 10 * MAX_DEGREE)  # past the bound: stop growing the number
    return memo[id(node)]


def check_tree(node, where: str, memo: dict | None = None) -> None:
    """Refuse ``node`` (at ``where``) when its degree bound passes :data:`MAX_DEGREE`.

    Raises:
        LimitError: the bound, an exponent or an integer past its limit (names ``where``).
    """
    try:
        d = degree_bound(node, memo)
    except LimitError as exc:
        raise LimitError(f"{where}: {exc}") from None
    if d > MAX_DEGREE:
        raise LimitError(f"{where}: degree bound {d if d < 10 * MAX_DEGREE else 'over'} "
                         f"{'' if d < 10 * MAX_DEGREE else str(10 * MAX_DEGREE) + ' '}"
                         f"(at most {MAX_DEGREE}; docs/certificates.md, Limits)")


@contextlib.contextmanager
def cpu_limit(seconds: float = MAX_SECONDS):
    """Raise :class:`LimitError` in the block once it has used ``seconds`` of CPU time
    (``ITIMER_PROF``); a no-op off the main thread or where ``setitimer`` is missing."""
    usable = hasattr(signal, "setitimer") and threading.current_thread() is \
        threading.main_thread() and sys.platform != "win32"
    if not usable:
        yield
        return

    def _expired(signum, frame):
        raise LimitError(f"more than {seconds:g} s of CPU time (certcheck's limit on one "
                         "certificate)")
    old = signal.signal(signal.SIGPROF, _expired)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, old)
