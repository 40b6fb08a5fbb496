"""A ``--let`` the statement does not use (one set of declarations shared by a book's
statements): said back as ``not used: ...`` and ignored, the verdict that of the statement
without it; refused, naming both spellings, where the statement holds an undeclared glyph
spelt near the ``--let``'s NAME (the same letter under another font, accent, subscript,
left index or prime), the likely misspelling."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_check_latex import forget_latex_ids  # noqa: F401  (autouse fixture)

import rigidsym
from rigidsym.core.errors import BadInput
from rigidsym.latex.unused import base_letter

_LETTERS = ["a", "q", "r", "\\phi", "\\omega"]


@st.composite
def _spelling(draw, letter):
    """One spelling of ``letter``: a font, a bar, a subscript, a prime (each or not)."""
    s = letter
    if draw(st.booleans()):
        s = f"\\boldsymbol{{{s}}}" if letter.startswith("\\") else f"\\mathbf{{{s}}}"
    if draw(st.booleans()):
        s = f"\\bar{{{s}}}"
    s += draw(st.sampled_from(["", "_1", "_{2}"]))
    return s + draw(st.sampled_from(["", "'"]))


@st.composite
def _near_pair(draw):
    letter = draw(st.sampled_from(_LETTERS))
    used, declared = draw(_spelling(letter)), draw(_spelling(letter))
    return used, declared


def test_the_letter_under_fonts_accents_indices_and_primes():
    assert base_letter(r"\tilde{\boldsymbol{\omega}}'") == r"\omega"
    assert base_letter(r"{}^{G}\bar r_{C}") == "r"
    assert base_letter(r"\mathbf{L}") == "L" != base_letter(r"\mathbf{l}")
    assert base_letter(r"R_{v2}^{b}") == "R"


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_near_pair(), st.sampled_from(["scalar", "vector", "angle"]))
def test_an_unused_let_spelt_near_an_undeclared_glyph_is_refused(pair, kind):
    used, declared = pair
    try:
        r = rigidsym.check_latex(f"{used} + {used} = 2{used}", let=[f"{declared}: {kind}"],
                                 repairs=False)
    except BadInput as exc:
        msg = str(exc)
        assert "does not occur" in msg and "spelt near" in msg, msg
        return
    # not refused: only where the --let is used (the same glyph, or \phi_{2} an entry of
    # the declared vector \phi), never an unused --let beside its near spelling
    assert not any(m.startswith("not used") for m in r.model), (used, declared, r.model)


_STATEMENTS = [  # fully declared, or free in letters no extra --let names
    (r"\mathbf{Q}^T\mathbf{Q} = \mathbf{1}", [r"\mathbf{Q}: rotation"], "verified"),
    (r"\mathbf{Q}^T = \mathbf{Q}", [r"\mathbf{Q}: rotation"], "does-not-hold"),
    (r"x y = y x", [], "verified"),
    (r"\sin^2\theta + \cos^2\theta = 2", [r"\theta: angle"], "does-not-hold"),
]


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(_STATEMENTS), _spelling("b") | _spelling("\\psi"),
       st.sampled_from(["scalar", "vector", "angle", "rotation", "= 2"]))
def test_an_unrelated_extra_let_is_noted_and_changes_no_verdict(case, extra, kind):
    latex, lets, verdict = case
    extra_let = f"{extra} = 2" if kind == "= 2" else f"{extra}: {kind}"
    alone = rigidsym.check_latex(latex, let=lets, repairs=False)
    more = rigidsym.check_latex(latex, let=[*lets, extra_let], repairs=False)
    assert alone.verdict == more.verdict == verdict
    said = [m for m in more.model if m.startswith("not used: ")]
    assert len(said) == 1 and extra_let in said[0], more.model
    assert not any(m.startswith("not used: ") for m in alone.model)


@pytest.mark.parametrize("latex, lets, verdict", [
    # Nikravesh: G's and L's models shared by omega = 2 G p-dot and its body twin
    (r"\dot{\mathbf{A}} = \tilde{\boldsymbol\omega}\mathbf{A}",
     [r"\mathbf{p}(t): unit 4-vector", r"e_0 = \mathbf{p}_{1:1}",
      r"\mathbf{e} = \mathbf{p}_{2:4}",
      r"\mathbf{G} = \begin{bmatrix} -\mathbf{e} & \tilde{\mathbf{e}} + e_0\mathbf{I} "
      r"\end{bmatrix}",
      r"\mathbf{L} = \begin{bmatrix} -\mathbf{e} & -\tilde{\mathbf{e}} + e_0\mathbf{I} "
      r"\end{bmatrix}",
      r"\mathbf{A} = (2e_0^2 - 1)\mathbf{I} + 2(\mathbf{e}\mathbf{e}^T + "
      r"e_0\tilde{\mathbf{e}})",
      r"\boldsymbol\omega = 2\mathbf{L}\dot{\mathbf{p}}"], "does-not-hold"),
])
def test_a_books_shared_lets_decide_a_statement_that_uses_some(latex, lets, verdict):
    """The unused model (G) is said back; the verdict is the statement's."""
    r = rigidsym.check_latex(latex, let=lets, repairs=False)
    assert r.verdict == verdict
    assert any(m.startswith("not used: ") and r"\mathbf{G} =" in m for m in r.model)


@pytest.mark.parametrize("latex, let, near", [
    # an undeclared hat, read by default under either of its books' readings
    (r"\hat{\mathbf{n}}^T\hat{\mathbf{n}} = 1", [r"n: unit vector"], r"\hat{\mathbf{n}}"),
    # a bold capital read by default as the identity
    (r"\mathbf{I}\mathbf{x} = \mathbf{x}", [r"I: scalar", r"\mathbf{x}: vector"],
     r"\mathbf{I}"),
])
def test_a_glyph_read_by_a_default_is_a_near_miss_too(latex, let, near):
    with pytest.raises(BadInput) as exc:
        rigidsym.check_latex(latex, let=let, repairs=False)
    assert "does not occur" in str(exc.value) and near in str(exc.value), str(exc.value)


def test_an_unused_let_of_a_letter_the_statement_writes_is_refused():
    """An unused p_0 beside the statement's p(t) is refused naming both, never ignored: a
    --let of a letter the statement or its models write may hold what they need (Wie's
    unit q(t) beside its entries q_1 ... q_4: ignored, the unit norm was lost and a true
    relation came out does-not-hold)."""
    with pytest.raises(BadInput) as exc:
        rigidsym.check_latex(r"\dot{\mathbf{p}} = \mathbf{p}",
                             let=[r"\mathbf{p}(t): vector", r"\mathbf{p}_0: vector"],
                             repairs=False)
    assert r"\mathbf{p}_0" in str(exc.value) and r"\mathbf{p}" in str(exc.value), exc.value


def test_an_unused_let_beside_a_declared_glyph_of_its_letter_is_noted_not_refused():
    r"""Wen & Kreutz-Delgado's shared lines ``q_0 = \bar{q}_{1:1}``, ``\mathbf{q} =
    \bar{q}_{2:4}`` unused by ``\bar{q}\otimes\bar{q}^* = [1; 0; 0; 0]``, whose ``\bar{q}`` a
    --let declares: noted and ignored (the refusal said "\bar{q}, which no --let declares")."""
    r = rigidsym.check_latex(
        r"\bar{q}\otimes\bar{q}^* = \begin{bmatrix} 1 \\ 0 \\ 0 \\ 0 \end{bmatrix}",
        repairs=False, let=[r"\bar{q}: unit 4-vector", r"q_0 = \bar{q}_{1:1}",
                            r"\mathbf{q} = \bar{q}_{2:4}", r"\otimes: Hamilton"])
    assert r.verdict == "verified", r.detail
    assert any(m.startswith("not used: ") for m in r.model), r.model
