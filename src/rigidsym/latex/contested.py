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

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass

from rigidsym.core.errors import BadInput
from rigidsym.latex.let_text import split_lets

__all__ = ["Reading", "Construct", "CONTESTED", "construct", "readings_of", "DECLARABLE",
           "declared", "declared_texts", "using", "split_settings"]


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
        r"--let 'bracket cross: content' or --let 'bracket cross: bind' (or write "
        r"[A\mathbf{x}]_\times for the content, A[\mathbf{x}]_\times for A times)"),
    Construct(
        "quaternion product", r"\mathbf{p}\otimes\mathbf{q}, \mathbf{p}\odot\mathbf{q}, p\star q",
        (Reading("Hamilton", "scalar first q = [w; x; y; z], ij = k",
                 "Solà (2017) (12), Kok–Hol–Schön (2017)"),
         Reading("JPL", "scalar last q = [x; y; z; w], ij = -k",
                 "Trawny & Roumeliotis (2005) (8), Breckenridge (1999)"),
         Reading("Hamilton, scalar last", "scalar last q = [x; y; z; w], ij = k",
                 "Szeliski (2022) (2.41)-(2.42), Eigen, ROS")),
        r"--let '\otimes: Hamilton', --let '\otimes: JPL' (--notation jpl) or --let "
        r"'\otimes: Hamilton, scalar last'; a --let that names a 4-vector's entries "
        r"(q_0 = \bar q_{1:1}: the scalar first) fixes Hamilton's; one that puts the scalar "
        r"last (\mathbf{q} = \bar q_{1:3}) leaves the rule of the units to declare"),
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
        "blackboard I", r"\mathbb{I}",
        (Reading("identity", "the identity matrix, sized by its neighbours",
                 "Chirikjian (2011) vol. 2 ch. 10"),
         Reading("inertia", "a name: the inertia tensor, a symmetric 3×3 matrix",
                 "Marsden & Ratiu (1999) ch. 15: Π = 𝕀Ω")),
        r"--let '\mathbb{I}: identity' (or write \mathbb{I}_3), or a --let naming it "
        r"(--let '\mathbb{I}: symmetric matrix', --let '\mathbb{I} = "
        r"\operatorname{diag}(I_1, I_2, I_3)')"),
    Construct(
        "principal moments", r"I_1, I_2, I_3 side by side in \operatorname{diag}(...) or a "
        r"matrix",
        (Reading("identity", "the identities of those sizes (rule 6: I_3 is the 3×3 "
                 "identity)", "Lynch & Park (2017), Murray–Li–Sastry (1994): I_3, I_6"),
         Reading("scalar", "scalars of their own, the principal moments of inertia",
                 "Kasdin & Paley (2011) ch. 11, Meriam & Kraige (2012) art. 7/10: "
                 r"\operatorname{diag}(I_1, I_2, I_3)")),
        r"--let 'I_{1}: scalar; I_{2}: scalar; I_{3}: scalar' for the principal moments "
        r"(or write I_{3\times 3}, \mathbf{1}_3 for an identity)"),
    Construct(
        "star", r"X^{*} of a 6x6 matrix, \phi^*(\mathbf{l})",
        (Reading("transpose", "the transpose X^T (the adjoint of a real operator)",
                 "Jain (2011) ch. 1, Rodriguez–Jain–Kreutz-Delgado (1991): the rigid-body "
                 "transformation operator's φ^*"),
         Reading("dual", "the dual of a motion transform, the inverse transpose (X^{-1})^T of "
                 "any invertible 6x6 matrix; of a spatial transform [E 0; B E] it is "
                 "[E, -E Bᵀ E; 0, E] by the blocks",
                 "Featherstone (2008) (2.25)")),
        r"--let 'star: transpose' or --let 'star: dual' (or write X^T for the transpose, "
        r"X^{-T} for the dual; --let 'X: spatial transform' makes X Featherstone's, whose "
        r"X^* is the dual)"),
    Construct(
        "braces", r"\{ ... \}",
        (Reading("group", "parentheses around an expression that is no single glyph",
                 r"Lee–Leok–McClamroch (2010) sec. II: (\{tr[A] I - A\}x)^∧"),
         Reading("column", r"the column matrix of a glyph's components, \{\omega\}",
                 "Ginsberg (2008) Engineering Dynamics")),
        "decided by the content: around an expression the braces group (the column of its "
        "components is the same value), around one glyph they are a column only where a "
        r"--let names it (--let '\{\omega\}: vector'); braces holding a list, a bar or a "
        "condition (a set's) are not read"),
    Construct(
        "exponential", r"e^{X}",
        (Reading("scalar", "the scalar exponential, where the exponent is a scalar "
                 "(e^{\\operatorname{tr} X}, e^{i\\theta})", "Hall (2015) Thm 2.12 (Jacobi)"),
         Reading("matrix", "the matrix exponential, where the exponent is a square matrix",
                 "Lynch & Park (2017) (3.51), Murray–Li–Sastry (1994)")),
        "decided by the exponent's shape: no choice remains"),
    Construct(
        "argument extent", r"\cos\theta\phi, \sin\omega t, \cos\omega_0 t: a function "
        r"whose argument has no parentheses, followed directly by further scalar factors",
        (Reading("factor", r"the function takes the next factor only: cos(θ) φ; a thin space "
                 r"\, after it says so (\sin\theta\,\hat{\omega})",
                 "Angeles (2014) ch. 3, Murray–Li–Sastry (1994) (2.14): "
                 r"\sin\theta\,\hat\omega"),
         Reading("product", "the function takes the whole run of juxtaposed scalar factors: "
                 "sin(ω t)",
                 "Thomson & Dahleh (1998) Theory of Vibration, Meirovitch (1986) Elements of "
                 r"Vibration Analysis, Taylor (2005) Classical Mechanics: \sin\omega t")),
        r"--let 'argument extent: factor' or --let 'argument extent: product', or write the "
        r"parentheses: \cos(\theta)\phi or \cos(\theta\phi); a thin space, an operator "
        r"(\cdot), a function or a vector after the argument ends it with no choice"),
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


#: the constructs a ``--let 'CONSTRUCT: READING'`` settles here (the quaternion product and
#: the tangent order have declarations of their own: rigidsym.latex.quaternions, .tangent)
DECLARABLE = ("bracket cross", "star", "argument extent")
_DECLARED: ContextVar[tuple[dict, tuple] | None] = ContextVar("contested_declared",
                                                             default=None)


def declared(key: str) -> str | None:
    """The reading of the construct ``key`` a ``--let`` declared for the check running now,
    or ``None``."""
    return (_DECLARED.get() or ({}, ()))[0].get(key)


def declared_texts() -> tuple[str, ...]:
    """The ``--let`` texts that declared readings now (they join the check's id)."""
    return (_DECLARED.get() or ({}, ()))[1]


@contextmanager
def using(readings: dict, texts=()) -> Iterator[None]:
    """Within the block the constructs of ``readings`` (key -> reading) are read so, as the
    ``--let`` s ``texts`` declare."""
    token = _DECLARED.set((dict(readings), tuple(texts)))
    try:
        yield
    finally:
        _DECLARED.reset(token)


def split_settings(let) -> tuple[object, dict, list[str]]:
    """``let`` without its ``CONSTRUCT: READING`` declarations (:data:`DECLARABLE`), the
    readings they declare, and their texts (which join the check's id).

    Raises:
        BadInput: a reading the construct does not have, or a construct declared twice.
    """
    if let is None or isinstance(let, dict):
        return let, {}, []
    try:
        strings = split_lets([let] if isinstance(let, str) else list(let))
    except (TypeError, AttributeError):
        return let, {}, []
    kept, found, texts = [], {}, []
    for s in strings:
        name, _, value = s.partition(":")
        key = " ".join(name.split()).lower()
        if key not in DECLARABLE or not value.strip():
            kept.append(s)
            continue
        names = readings_of(key)
        if value.strip().lower() not in names:
            raise BadInput(f"--let '{s}': expected one of "
                           + ", ".join(f"'{key}: {n}'" for n in names))
        if key in found:
            raise BadInput(f"--let: {key} is declared twice")
        found[key] = value.strip().lower()
        texts.append(s)
    return (let if not found else kept), found, texts
