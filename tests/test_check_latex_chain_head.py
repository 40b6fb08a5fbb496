"""A chain headed by a name nothing declares (Bottema & Roth's ``A = \\frac{1}{\\Delta}[...] =
(I - B)^{-1}(I + B)``): the first link defines the head and the rest is claimed
(rigidsym.latex.chain_head); a declared head keeps its link a claim."""

from __future__ import annotations

import pytest

import rigidsym

AB = [r"\mathbf{a}: vector", r"\mathbf{b}: vector"]


def test_an_undeclared_head_is_defined_by_its_first_link_and_the_rest_decided():
    r = rigidsym.check_latex(r"\mathbf{c} = \mathbf{a}\times\mathbf{b} = -\mathbf{b}\times"
                             r"\mathbf{a}", let=AB, repairs=False)
    assert r.verdict == "verified", r.detail
    assert any("heads the chain" in m and r"\mathbf{c} = \mathbf{a}\times\mathbf{b}" in m
               for m in r.model), r.model
    slip = rigidsym.check_latex(r"\mathbf{c} = \mathbf{a}\times\mathbf{b} = \mathbf{b}\times"
                                r"\mathbf{a}", let=AB, repairs=False)
    assert slip.verdict == "does-not-hold", slip.detail


@pytest.mark.parametrize("latex, let", [
    # declared: its first link is a claim (c free: it does not hold)
    (r"\mathbf{c} = \mathbf{a}\times\mathbf{b} = -\mathbf{b}\times\mathbf{a}",
     [*AB, r"\mathbf{c}: vector"]),
    # the head occurs again in the chain: no definition of it
    (r"\mathbf{c} = \mathbf{a}\times\mathbf{b} = \mathbf{c}", AB),
])
def test_a_declared_or_recurring_head_keeps_its_link_a_claim(latex, let):
    r = rigidsym.check_latex(latex, let=let, repairs=False)
    assert r.verdict == "does-not-hold", r.detail
    assert not any("heads the chain" in m for m in r.model), r.model
