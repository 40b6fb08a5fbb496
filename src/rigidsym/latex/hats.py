r"""An undeclared hat, ``\hat{X}`` or ``\widehat{X}``: the books give it
two meanings, a unit vector of its own (Lynch & Park, Corke: ``\hat\omega`` the unit axis)
or the skew (cross-product) matrix of ``X`` (Murray, Li & Sastry (2.9); Ma, Soatto, Košecká &
Sastry: ``\widehat{T}R``). Neither is guessed: the hat is a choice point whose two readings
the reader reads in turn (:func:`rigidsym.latex.statement.read_statement`), the checker
keeping each that type-checks. Where the shapes allow one (``\hat\omega^2``, ``\widehat{T}R``,
``I_3 + \hat{\mathbf{v}}``: the skew matrix; ``[\hat\omega]``, ``\hat\omega\theta + \mathbf{v}``:
the unit vector) that is the reading; where both type-check and their verdicts differ the
statement is refused naming the ``--let`` and the ``--notation`` that settle it.

A free bold capital whose conventional 3 x 3 does not fit is a choice of the same kind
(:func:`capital_point`): a 3 x 3 matrix or a 3-vector.

A ``--let`` for ``\hat{X}`` (a kind or a model), a ``--notation`` line or a book's glyph row
wins over this: the choice is met only by a hat nothing declares.
"""

from __future__ import annotations

import re

__all__ = ["hat_reading", "HAT_READINGS", "hat_point", "no_hat_reading", "CAPITAL_READINGS",
           "capital_point", "is_capital"]

#: the readings of an undeclared hat, the default first
HAT_READINGS = ("unit", "skew")

_HAT = re.compile(r"\\hat\{(.+)\}")


def hat_point(key: str) -> str:
    r"""The choice point of the glyph ``key`` (``\hat{T}`` -> ``"\hat{T} hat"``)."""
    return f"{key} hat"


def hat_reading(key: str, choices: dict, points: dict) -> tuple[str, str] | None:
    r"""The declaration that reads the undeclared glyph ``key`` at its choice point, and the
    note that says so; ``None`` where ``key`` is no hat.

    Args:
        key: a glyph key as the parser normalises it (``\hat{T}``, ``\hat{\mathbf{v}}``;
            ``\widehat`` is read as ``\hat``).
        choices: the reading of each choice point (``{"\hat{T} hat": "skew"}``); a point
            not in it takes its first reading, ``"unit"``.
        points: the choice points met, updated with this one (its readings).

    Returns:
        ``(let, note)``, ``let`` the text of a ``--let`` (read by the caller:
        :mod:`rigidsym.latex.lets` imports the parser, which imports this): ``\hat{T}: unit
        vector`` (a unit 3-vector of its own) or
        ``\hat{T} = [T]_\times`` (the skew matrix of a 3-vector ``T``; of anything
        else the model is refused when read, and the reading dropped).
    """
    m = _HAT.fullmatch(key)
    if m is None:
        return None
    point = hat_point(key)
    points[point] = HAT_READINGS
    inner = m.group(1)
    if choices.get(point, HAT_READINGS[0]) == "skew":
        return f"{key} = [{inner}]_\\times", (
            f"{key}: read as the skew matrix [{inner}]_× (Murray-Li-Sastry's hat; a "
            f"choice: or a unit vector of its own)")
    return f"{key}: unit vector", (
        f"{key}: read as a unit vector of its own (Lynch-Park's hat; a choice: or the "
        f"skew matrix [{inner}]_×)")


def no_hat_reading(points, dropped: list) -> str | None:
    r"""The refusal where no reading of a statement type-checks and one of its choice points
    is an undeclared hat (``\hat\omega^3`` of a free scalar ``\omega``: no skew matrix of a
    scalar, no cube of a vector): the hat's two meanings, why each reading failed, and the
    declarations that settle it; ``None`` where no hat is among ``points``.

    Args:
        points: the choice points' keys.
        dropped: ``(choices, why)`` of each reading that did not type-check.
    """
    hats = sorted(k for k in points if k.endswith(" hat"))
    if not hats:
        return None
    hat = hats[0][:-4]
    inner = hat[5:-1]
    whys = "; ".join(dict.fromkeys(_short(why) for _, why in dropped))
    return (f"--latex: {hat} is a unit vector in Lynch-Park and Corke, the skew matrix of "
            f"{inner} in Murray-Li-Sastry, and neither reading fits here ({whys}): say which, "
            f"with --let '{hat}: unit vector' (or another KIND), --notation lynch-park or "
            f"--notation murray-li-sastry, and what {inner} is (--let '{inner}: vector')")


def _short(why: str) -> str:
    """A dropped reading's reason without the statement it quotes nor its hints."""
    why = why.split("; its meaning depends")[0].split("; say it another way")[0]
    return why.split("': ", 1)[1] if why.startswith(("cannot read '", "the reading '")) \
        and "': " in why else why


# ---- a free bold capital whose conventional 3 x 3 does not fit (the same kind of choice)

#: the readings of a free bold capital, the convention first
CAPITAL_READINGS = ("matrix", "vector")

_CAPITAL = re.compile(r"\\(?:mathbf|boldsymbol)\{[A-Z]\}")


def is_capital(key: str) -> bool:
    r"""``key`` is a bold capital with nothing else (``\mathbf{Y}``)."""
    return _CAPITAL.fullmatch(key) is not None


def capital_point(key: str) -> str:
    r"""The choice point of the free bold capital ``key``: 3 x 3 by the books' convention,
    or a 3-vector (Ma-Soatto-Košecká-Sastry's point ``\mathbf{X}``, ``N\times\mathbf{Y}``).
    Met only where the convention's shape does not fit (a reading failed on shapes), so a
    statement the convention reads is read as before; where both type-check and disagree,
    refused naming ``--let '\mathbf{Y}: vector'``."""
    return f"{key} shape"
