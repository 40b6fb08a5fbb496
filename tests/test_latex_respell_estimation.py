"""The respellings the estimation books' notations need (``rigidsym.latex.respell``): each
rewrites exactly the construct it names and leaves the neighbouring notations alone."""

from __future__ import annotations

import pytest

from rigidsym.latex.lexing import named_map_key
from rigidsym.latex.respell import (
    conjugate_c,
    cross_subscripts,
    declared_deltas,
    hat_expressions,
)


@pytest.mark.parametrize("latex, want", [
    (r"\mathbf{R}\boldsymbol\omega_\times\mathbf{R}^T",
     r"\mathbf{R}[\boldsymbol\omega]_\times\mathbf{R}^T"),
    (r"(\mathbf{R}\boldsymbol\omega)_\times", r"[\mathbf{R}\boldsymbol\omega]_\times"),
    (r"\left(\mathbf{a} + \mathbf{b}\right)_\times", r"[\mathbf{a} + \mathbf{b}]_\times"),
    (r"\mathbf{t}_\times\mathbf{R} + \omega_\times^2",
     r"[\mathbf{t}]_\times\mathbf{R} + [\omega]_\times^2"),
])
def test_a_cross_subscript_is_the_cross_product_matrix(latex, want):
    new, _, note = cross_subscripts(latex, None)
    assert new == want and "cross-product matrix" in note


@pytest.mark.parametrize("latex", [r"\mathbf{0}_{3\times 3}", r"[\mathbf{a}]_\times",
                                   r"\mathbf{a}\times\mathbf{b}", r"I_{3 \times 3}"])
def test_a_sized_block_or_a_bracket_is_no_cross_subscript(latex):
    assert cross_subscripts(latex, None) == (latex, None, "")


@pytest.mark.slow
def test_a_wide_hat_over_a_6_vector_product_is_its_se3_hat():
    import rigidsym

    lets = [r"\mathbf{T}: transform", r"\boldsymbol\xi: twist"]
    for right, verdict in ((r"\mathbf{T}\boldsymbol\xi^\wedge\mathbf{T}^{-1}", "verified"),
                           (r"\mathbf{T}^{-1}\boldsymbol\xi^\wedge\mathbf{T}", "does-not-hold")):
        r = rigidsym.check_latex(r"\widehat{\mathrm{Ad}_{\mathbf{T}}\boldsymbol\xi} = " + right,
                                 let=lets, repairs=False)
        assert r.verdict == verdict
        assert any(r"read as (\mathrm{Ad}_{\mathbf{T}}\boldsymbol\xi)^\wedge" in m
                   for m in r.model), r.model


def test_a_wide_hat_over_an_expression_is_its_hat_and_over_one_glyph_a_name():
    new, _, note = hat_expressions(r"R\hat{\boldsymbol\omega}R^T = \widehat{R\boldsymbol\omega}",
                                   None)
    assert new == r"R\hat{\boldsymbol\omega}R^T = (R\boldsymbol\omega)^\wedge" and note
    for one in (r"\widehat{T}R", r"\widehat{\boldsymbol\xi}", r"\widehat{\mathbf{x}_1}"):
        assert hat_expressions(one, None) == (one, None, "")


def test_a_delta_name_is_one_glyph_only_where_a_let_declares_it():
    lets = [r"\Delta\mathbf{R}_{ij} = \mathbf{R}_i^T\mathbf{R}_j", r"\mathbf{R}_i: rotation"]
    new, out, note = declared_deltas(r"\Delta\mathbf{R}_{ij}\Delta t", lets)
    assert new == r"{\mathbf{R}_{\Delta ij}}\Delta t"  # \Delta t: no --let, Δ times t
    assert out[0].startswith(r"{\mathbf{R}_{\Delta ij}} =") and out[1] == lets[1]
    assert r"\Delta \mathbf{R}_{ij}" in note
    assert declared_deltas(r"\Delta\mathbf{R}_{ij}", [r"\mathbf{R}: rotation"])[2] == ""


def test_the_c_conjugate_is_read_only_beside_the_quaternion_product():
    new, _, note = conjugate_c(r"(\mathbf{p}\odot\mathbf{q})^c = \mathbf{q}^{c}\odot\mathbf{p}^c",
                               None)
    assert new == r"(\mathbf{p}\odot\mathbf{q})^{*} = \mathbf{q}^{*}\odot\mathbf{p}^{*}"
    assert "conjugate" in note
    assert conjugate_c(r"a^c = b", None) == (r"a^c = b", None, "")  # no product: untouched
    assert conjugate_c(r"\mathbf{p}\odot\mathbf{q}^{cd}", None)[2] == ""


@pytest.mark.parametrize("token, key", [
    (r"\mathrm{Exp}", r"\mathrm{Exp}"), (r"\operatorname{ Log }", r"\mathrm{Log}"),
    (r"\exp_q", r"\exp_{q}"), (r"\exp_{ q }", r"\exp_{q}"),
])
def test_a_named_map_has_one_spelling(token, key):
    assert named_map_key(token) == key
