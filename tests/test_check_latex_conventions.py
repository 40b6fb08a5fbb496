"""The second semantics owns its conventions: for every contested construct and every pair
of readings (the symbolic reader's, the second semantics' own, :mod:`rigidsym.numeval.
conventions`) the two semantics disagree on a witness statement exactly where the readings
differ, so that no reading shared by both can decide a statement silently."""

from __future__ import annotations

import pytest

import rigidsym
from rigidsym.latex.contested import CONTESTED
from rigidsym.latex.crosscheck import FAILS, VANISHES, decls_of
from rigidsym.latex.lets import read_lets
from rigidsym.latex.lexing import tree
from rigidsym.numeval import conventions, residuals
from rigidsym.numeval import values as V
from rigidsym.registry import declarations as registry

C = [r"\mathbf{C}: rotation", r"\boldsymbol\omega: vector"]
GROVES = r"\mathbf{C}[\boldsymbol\omega\wedge]\mathbf{C}^T = [\mathbf{C}\boldsymbol\omega\wedge]"
#: the reader's reading of [C ω\wedge], written out so that no choice remains
RESPELT = {"content": r"\mathbf{C}[\boldsymbol\omega]_\times\mathbf{C}^T = "
                     r"[\mathbf{C}\boldsymbol\omega]_\times",
           "bind": r"\mathbf{C}[\boldsymbol\omega]_\times\mathbf{C}^T = "
                   r"\mathbf{C}[\boldsymbol\omega]_\times"}
Q = [r"\mathbf{q}: unit 4-vector"]
#: q ⊗ q^* is the identity quaternion: [1; 0; 0; 0] scalar first, [0; 0; 0; 1] scalar last
UNIT_FIRST = r"\mathbf{q}\otimes\mathbf{q}^* = \begin{bmatrix} 1 \\ 0 \\ 0 \\ 0 \end{bmatrix}"
UNIT_LAST = r"\mathbf{q}\otimes\mathbf{q}^* = \begin{bmatrix} 0 \\ 0 \\ 0 \\ 1 \end{bmatrix}"
#: i ⊗ j = k with the scalar last: Hamilton's units (Szeliski's layout), not JPL's (ij = -k)
IJ_LAST = (r"\begin{bmatrix} 1 \\ 0 \\ 0 \\ 0 \end{bmatrix}\otimes\begin{bmatrix} 0 \\ 1 "
           r"\\ 0 \\ 0 \end{bmatrix} = \begin{bmatrix} 0 \\ 0 \\ 1 \\ 0 \end{bmatrix}")


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def test_both_tables_name_the_same_constructs_and_readings_each_written_separately():
    for name, readings in conventions.READINGS.items():
        assert set(readings) == {r.name for r in CONTESTED[name].readings}, name


def _second(latex, lets, choices=None, jpl=False, translation=False, last=None) -> bool:
    """Whether the second semantics, in the reading given, finds the sides equal."""
    with V.quaternion_convention(jpl), V.quaternion_storage(last), \
            V.tangent_order(translation):
        found = residuals(tree(latex), decls_of(read_lets(lets)), 4, choices=choices)
    worst = max(r.relative for r in found)
    assert worst < VANISHES or worst > FAILS, worst
    return worst < VANISHES


def _disagree(verdict: str, equal: bool) -> bool:
    return (verdict == "verified") != equal


@pytest.mark.parametrize("mine", conventions.BRACKET_CROSS)
@pytest.mark.parametrize("theirs", [r.name for r in CONTESTED["bracket cross"].readings])
def test_the_bracket_cross_disagrees_exactly_where_the_readings_differ(mine, theirs):
    verdict = rigidsym.check_latex(RESPELT[theirs], let=C, repairs=False).verdict
    key = conventions.choice_key("bracket cross", r"\mathbf C \boldsymbol \omega \wedge")
    equal = _second(GROVES, C, {key: mine})
    assert _disagree(verdict, equal) == (mine != theirs), (mine, theirs, verdict, equal)


@pytest.mark.parametrize("mine", conventions.QUATERNION)
@pytest.mark.parametrize("theirs", [r.name for r in CONTESTED["quaternion product"].readings])
def test_the_quaternion_product_disagrees_exactly_where_the_readings_differ(mine, theirs):
    """On the witnesses (the identity in each layout; i ⊗ j = k stored scalar last) the two
    semantics agree on each where the readings are the same, and differ on one at least where
    they are not: the scalar's place and the rule of the units are each caught."""
    differ = []
    for latex, lets in ((UNIT_FIRST, Q), (UNIT_LAST, Q), (IJ_LAST, [])):
        verdict = rigidsym.check_latex(latex, let=lets + [rf"\otimes: {theirs}"],
                                       repairs=False).verdict
        equal = _second(latex, lets, jpl=mine == "JPL", last=mine != "Hamilton")
        differ.append(_disagree(verdict, equal))
    assert any(differ) == (mine != theirs), (mine, theirs, differ)


#: the hat of a twist written as the block matrix of an angular-first twist [ω; v]
XI = [r"\boldsymbol\xi = \begin{bmatrix} \boldsymbol\omega \\ \mathbf{v} \end{bmatrix}",
      r"\boldsymbol\omega: vector", r"\mathbf{v}: vector"]
HAT = (r"\boldsymbol\xi^\wedge = \begin{bmatrix} [\boldsymbol\omega]_\times & \mathbf{v} \\ "
       r"\mathbf{0}^T & 0 \end{bmatrix}")


@pytest.mark.parametrize("mine", conventions.TANGENT)
@pytest.mark.parametrize("theirs", [r.name for r in CONTESTED["tangent order"].readings])
def test_the_tangent_order_disagrees_exactly_where_the_readings_differ(mine, theirs):
    verdict = rigidsym.check_latex(HAT, let=XI + [f"tangent order: {theirs}"], repairs=False
                                   ).verdict
    equal = _second(HAT, XI, translation=mine == "translation first")
    assert _disagree(verdict, equal) == (mine != theirs), (mine, theirs, verdict, equal)


#: Jain (2011) ch. 1: φ(l) = [I l~; 0 I], and its transpose written out, [I 0; -l~ I]: true
#: of Jain's φ^* (the transpose), false of Featherstone's dual φ^{-T} = [I 0; l~ I]
PHI = [r"\mathbf{l}: vector",
       r"\phi(\mathbf{l}) = \begin{bmatrix} \mathbf{I} & \tilde{\mathbf{l}} \\ \mathbf{0} & "
       r"\mathbf{I} \end{bmatrix}"]
STAR = (r"\phi^*(\mathbf{l}) = \begin{bmatrix} \mathbf{I} & \mathbf{0} \\ -\tilde{\mathbf{l}} "
        r"& \mathbf{I} \end{bmatrix}")


@pytest.mark.parametrize("mine", conventions.STAR)
@pytest.mark.parametrize("theirs", [r.name for r in CONTESTED["star"].readings])
def test_the_star_disagrees_exactly_where_the_readings_differ(mine, theirs):
    verdict = rigidsym.check_latex(STAR, let=PHI + [f"star: {theirs}"], repairs=False).verdict
    equal = _second(STAR, PHI, {conventions.choice_key("star", "X^*"): mine})
    assert _disagree(verdict, equal) == (mine != theirs), (mine, theirs, verdict, equal)


#: true of cos(θ φ) only: the argument running over the product
EXTENT = r"\cos\theta\phi = \cos(\theta\phi)"
ANGLES = [r"\theta: angle", r"\phi: angle"]


@pytest.mark.parametrize("mine", conventions.ARGUMENT_EXTENT)
@pytest.mark.parametrize("theirs", [r.name for r in CONTESTED["argument extent"].readings])
def test_the_argument_extent_disagrees_exactly_where_the_readings_differ(mine, theirs):
    verdict = rigidsym.check_latex(EXTENT, let=ANGLES + [f"argument extent: {theirs}"],
                                   repairs=False).verdict
    key = conventions.choice_key("argument extent", r"\cos \theta \phi")
    equal = _second(EXTENT, ANGLES, {key: mine})
    assert _disagree(verdict, equal) == (mine != theirs), (mine, theirs, verdict, equal)
