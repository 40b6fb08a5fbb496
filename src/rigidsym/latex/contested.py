"""The contested constructs of the reader's LaTeX: constructs that two books read two ways,
each with its readings and the books behind them (:data:`CONTESTED`). docs/check-latex.md
("Contested constructs") prints this table.

A statement that uses one is decided under each reading the user has not settled: where
the verdicts agree, the verdict stands and ``read as:`` says so; where they differ the answer
is bad input naming the construct, each reading with its verdict, and the ``--let`` (or
``--notation``, or respelling) that settles it. A reading is never picked by a rule alone.
The second semantics (:mod:`rigidsym.numeval`) has its own table of the same constructs
(:mod:`rigidsym.numeval.conventions`), written separately.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Reading", "Construct", "CONTESTED", "construct", "readings_of"]


@dataclass(frozen=True)
class Reading:
    """One reading of a contested construct: its name (a choice's value), what it means,
    and the books that read it so."""

    name: str
    means: str
    books: str


@dataclass(frozen=True)
class Construct:
    """A construct two books read differently: its key (:data:`CONTESTED`), how it is
    written, its readings (the first is the one ``read as:`` shows first) and what settles
    it."""

    key: str
    written: str
    readings: tuple[Reading, ...]
    settles: str


#: every contested construct, by key
CONTESTED: dict[str, Construct] = {c.key: c for c in (
    Construct(
        "bracket cross", r"[A\mathbf{x}\wedge], [A\mathbf{x}\times]",
        (Reading("content", "the cross-product matrix of the bracket's content, [(A x)]_×",
                 "Groves (2013) (2.50), Titterton & Weston (2004)"),
         Reading("bind", "x× binds to the factor before it: A [x]_×",
                 "Featherstone (2008) (2.31)-(2.33): E r× is E (r×)")),
        r"write [A\mathbf{x}]_\times (the content) or A[\mathbf{x}]_\times (A times)"),
    Construct(
        "quaternion product", r"\mathbf{p}\otimes\mathbf{q}, \mathbf{p}\odot\mathbf{q}",
        (Reading("Hamilton", "scalar first q = [w; x; y; z], ij = k",
                 "Solà (2017) (12), Kok–Hol–Schön (2017)"),
         Reading("JPL", "scalar last q = [x; y; z; w], ij = -k",
                 "Trawny & Roumeliotis (2005) (8), Breckenridge (1999)")),
        r"--let '\otimes: Hamilton' or --let '\otimes: JPL' (--notation jpl); a --let that "
        r"names a 4-vector's entries (q_4 = \bar q_{4:4}, \mathbf{q} = \bar q_{1:3}: scalar "
        r"last) fixes the storage order and with it the convention"),
    Construct(
        "tangent order", r"a 6-vector's hat, vee, \mathrm{Ad}, \mathrm{ad}",
        (Reading("angular first", "a twist [ω; v]",
                 "Lynch & Park (2017), Murray–Li–Sastry (1994), Featherstone (2008)"),
         Reading("translation first", "a twist [v; ω] (ξ = [ρ; φ])",
                 "Barfoot (2017), Solà et al. (2018), Sophus, manif")),
        r"--let 'tangent order: angular first' or --let 'tangent order: translation first' "
        r"(or --notation barfoot, sola, lynch-park ...)"),
    Construct(
        "hat", r"\hat{y} of a glyph, \hat{\omega}",
        (Reading("unit", "a unit vector of its own", "Lynch & Park (2017), Corke (2017)"),
         Reading("skew", "the skew matrix [y]_×", "Murray–Li–Sastry (1994), Barfoot (2017)")),
        r"--let '\hat{y}: unit vector' or --notation murray-li-sastry (or --let '\hat{y} = "
        r"[y]_\times')"),
    Construct(
        "hat of a product", r"\hat{xy}, \widehat{\mathrm{Ad}_g\xi}",
        (Reading("skew", "the hat of the product, (xy)^∧", "Murray–Li–Sastry (1994), Bullo & "
                 "Lewis (2004)"),),
        r"write (xy)^\wedge or [xy]_\times for the hat of the product"),
    Construct(
        "exponential", r"e^{X}",
        (Reading("scalar", "the scalar exponential, where the exponent is a scalar "
                 "(e^{\\operatorname{tr} X}, e^{i\\theta})", "Hall (2015) Thm 2.12 (Jacobi)"),
         Reading("matrix", "the matrix exponential, where the exponent is a square matrix",
                 "Lynch & Park (2017) (3.51), Murray–Li–Sastry (1994)")),
        "decided by the exponent's shape: no choice remains"),
)}


def construct(key: str) -> Construct:
    """The contested construct ``key`` (a key of :data:`CONTESTED`).

    Raises:
        KeyError: no such construct.
    """
    return CONTESTED[key]


def readings_of(key: str) -> tuple[str, ...]:
    """The names of the readings of the construct ``key``, the first shown first."""
    return tuple(r.name for r in CONTESTED[key].readings)
