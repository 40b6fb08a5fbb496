"""Contested constructs (:mod:`rigidsym.latex.contested`): a construct two books read two
ways is decided under each reading; where the verdicts differ the reader asks, naming the
construct, the readings and each verdict, and where they agree the verdict stands and
``read as:`` says so. Never a verdict from a default reading.

Per construct: a true statement and its slip, under each reading (the respelling or the
declaration that fixes it) and with the reading left open.
"""

from __future__ import annotations

import pytest

import rigidsym
from rigidsym.core.errors import BadInput
from rigidsym.latex.contested import CONTESTED
from rigidsym.registry import declarations as registry

C = [r"\mathbf{C}: rotation", r"\boldsymbol\omega: vector"]
#: Groves (2013) (2.50): the cross-product matrix of a rotated vector, true read as the
#: bracket's content; and the slip that is true only where x\wedge binds to C
GROVES = r"\mathbf{C}[\boldsymbol\omega\wedge]\mathbf{C}^T = [\mathbf{C}\boldsymbol\omega\wedge]"
GROVES_SLIP = r"[\mathbf{C}\boldsymbol\omega\wedge] = \mathbf{C}[\boldsymbol\omega\wedge]"


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def _check(latex, lets):
    return rigidsym.check_latex(latex, let=lets, repairs=False)


def test_every_construct_has_two_readings_or_says_why_not_and_its_books():
    for c in CONTESTED.values():
        assert c.readings and all(r.books and r.means for r in c.readings), c.key
        assert c.settles, c.key


SLOW = (pytest.mark.slow,)


@pytest.mark.parametrize("op, latex, content, bind", [
    (r"\wedge", GROVES, "verified", "does-not-hold"),
    pytest.param(r"\wedge", GROVES_SLIP, "does-not-hold", "verified", marks=SLOW),
    pytest.param(r"\times", GROVES, "verified", "does-not-hold", marks=SLOW),
    pytest.param(r"\times", GROVES_SLIP, "does-not-hold", "verified", marks=SLOW),
])
def test_the_bracket_cross_is_asked_naming_each_reading_and_its_verdict(op, latex, content,
                                                                        bind):
    with pytest.raises(BadInput) as e:
        _check(latex.replace(r"\wedge", op), C)
    msg = str(e.value)
    assert f"the cross-product matrix of its content: {content}" in msg, msg
    assert f"binds to the factor before it): {bind}" in msg, msg
    assert "Groves" in msg and "Featherstone" in msg and r"]_\times" in msg, msg


@pytest.mark.slow
@pytest.mark.parametrize("latex, verdict", [
    # the content's reading, respelt: Groves' identity holds, its slip does not
    (r"\mathbf{C}[\boldsymbol\omega]_\times\mathbf{C}^T = [\mathbf{C}\boldsymbol\omega]_\times",
     "verified"),
    (r"[\mathbf{C}\boldsymbol\omega]_\times = \mathbf{C}[\boldsymbol\omega]_\times",
     "does-not-hold"),
    # the binding's reading, respelt: C (ω×) C^T is no C (ω×)
    (r"\mathbf{C}[\boldsymbol\omega]_\times\mathbf{C}^T = \mathbf{C}[\boldsymbol\omega]_\times",
     "does-not-hold"),
    (r"\mathbf{C}[\boldsymbol\omega]_\times\mathbf{C}^T\mathbf{C} = "
     r"\mathbf{C}[\boldsymbol\omega]_\times", "verified"),
])
def test_the_bracket_cross_respelt_is_decided_under_the_reading_written(latex, verdict):
    assert _check(latex, C).verdict == verdict


@pytest.mark.slow
def test_a_bracket_cross_whose_readings_agree_is_decided_and_said():
    r = _check(r"[c\boldsymbol\omega\wedge] = c[\boldsymbol\omega\wedge]",
               [r"c: scalar", r"\boldsymbol\omega: vector"])
    assert r.verdict == "verified"
    assert any("readings type-check" in m and "all verified" in m for m in r.model), r.model


#: Trawny & Roumeliotis (2005) (62), the attitude matrix of a JPL quaternion, scalar last,
#: named through the user's own lets (q_4 the scalar, \mathbf{q} entries 1 to 3)
TRAWNY = [r"\bar q: unit 4-vector", r"\bar p: unit 4-vector", r"q_4 = \bar q_{4:4}",
          r"\mathbf{q} = \bar q_{1:3}",
          r"\mathbf{C}(\bar q) = (2q_4^2 - 1)I_3 - 2q_4[\mathbf{q}]_\times + "
          r"2\mathbf{q}\mathbf{q}^T"]
#: the same matrix as Hamilton's active rotation, scalar first (Solà (2017) (115))
HAMILTON = [r"\bar q: unit 4-vector", r"\bar p: unit 4-vector", r"q_0 = \bar q_{1:1}",
            r"\mathbf{q} = \bar q_{2:4}",
            r"\mathbf{C}(\bar q) = (q_0^2 - \mathbf{q}^T\mathbf{q})I_3 + 2q_0[\mathbf{q}]_\times"
            r" + 2\mathbf{q}\mathbf{q}^T"]
PRODUCT = r"\mathbf{C}(\bar q\otimes\bar p) = \mathbf{C}(\bar q)\mathbf{C}(\bar p)"
PRODUCT_SLIP = r"\mathbf{C}(\bar q\otimes\bar p) = \mathbf{C}(\bar p)\mathbf{C}(\bar q)"


@pytest.mark.parametrize("lets, own", [(TRAWNY, "JPL"),
                                       pytest.param(HAMILTON, "Hamilton", marks=SLOW)])
def test_the_storage_order_of_the_users_lets_fixes_the_product_and_is_said(lets, own):
    """The scalar first (Solà's q_0 = \\bar q_{1:1}) is Hamilton's in every book: decided and
    said. The scalar last (Trawny's \\mathbf{q} = \\bar q_{1:3}) is read with either rule
    (JPL's; Hamilton's in Szeliski, Eigen, ROS): the product and its slip are asked, naming
    the let that fixed the layout, until the rule is declared."""
    if own == "JPL":
        for latex in (PRODUCT, PRODUCT_SLIP):
            with pytest.raises(BadInput, match=r"puts the scalar last, which does not fix the "
                               r"rule of the units.*Trawny.*Szeliski"):
                _check(latex, lets)
        lets = lets + [r"\otimes: JPL"]
    r = _check(PRODUCT, lets)
    assert r.verdict == "verified", r.model
    said = [m for m in r.model if m.startswith("quaternion product:")]
    assert said and f"{own}'s" in said[0], said
    assert own == "JPL" or "the storage order fixed by --let" in said[0], said
    assert _check(PRODUCT_SLIP, lets).verdict == "does-not-hold"


@pytest.mark.slow
@pytest.mark.parametrize("lets, own, other", [(TRAWNY, "JPL", "Hamilton"),
                                              (HAMILTON, "Hamilton", "JPL")])
def test_a_declared_product_is_used_and_the_other_convention_fails(lets, own, other):
    assert _check(PRODUCT, lets + [rf"\otimes: {own}"]).verdict == "verified"
    assert _check(PRODUCT, lets + [rf"\otimes: {other}"]).verdict == "does-not-hold"


def test_the_docs_table_lists_every_construct_with_its_books():
    from pathlib import Path

    doc = (Path(__file__).resolve().parents[1] / "docs" / "check-latex.md").read_text()
    table = doc.split("## Contested constructs", 1)[1].split("\n## ", 1)[0]
    for c in CONTESTED.values():
        row = next((line for line in table.splitlines() if f"({c.key})" in line), None)
        assert row is not None, c.key
        for r in c.readings:
            assert f"**{r.name}**" in row and r.books.split(" (")[0].split(",")[0] in row, \
                (c.key, r.name)


@pytest.mark.parametrize("latex, verdict", [
    (r"[F_1, F_2] = F_1F_2 - F_2F_1", "verified"),  # Hall (2015) Def. 2.21
    (r"[F_1, F_2] = F_2F_1 - F_1F_2", "does-not-hold"),
])
def test_the_commutator_of_two_matrices_is_read(latex, verdict):
    assert _check(latex, [r"F_1: matrix", r"F_2: matrix"]).verdict == verdict


@pytest.mark.parametrize("latex, verdict", [
    # Arnold's [a, b] of 3-vectors: the bracket of so(3), the vee of [a^, b^]
    (r"[\mathbf{a}, \mathbf{b}] = \mathbf{a}\times\mathbf{b}", "verified"),
    (r"[\mathbf{a}, \mathbf{b}] = \mathbf{b}\times\mathbf{a}", "does-not-hold"),
])
def test_a_bracket_of_two_3_vectors_is_their_cross_product(latex, verdict):
    assert _check(latex, [r"\mathbf{a}: vector", r"\mathbf{b}: vector"]).verdict == verdict


def test_a_bracket_of_two_6_vectors_is_refused_saying_what_to_write():
    with pytest.raises(ValueError, match=r"\[x\^\\wedge, y\^\\wedge\]"):
        _check(r"[\mathbf{a}, \mathbf{b}] = \mathbf{0}",
               [r"\mathbf{a}: 6-vector", r"\mathbf{b}: 6-vector"])


ROT = r"\mathbf{Q}(t): rotation"
SPACE = r"\dot{\mathbf{Q}} = [\boldsymbol\omega]_\times\mathbf{Q}"
BODY = r"\dot{\mathbf{Q}} = \mathbf{Q}[\boldsymbol\omega]_\times"


@pytest.mark.parametrize("declared, latex, verdict", [
    (r"\boldsymbol\omega: angular velocity of \mathbf{Q}", SPACE, "verified"),
    pytest.param(r"\boldsymbol\omega: angular velocity of \mathbf{Q}", BODY, "does-not-hold",
                 marks=SLOW),
    pytest.param(r"\boldsymbol\omega: angular velocity of \mathbf{Q} in the body frame", BODY,
                 "verified", marks=SLOW),
    pytest.param(r"\boldsymbol\omega: body angular velocity of \mathbf{Q}", SPACE,
                 "does-not-hold", marks=SLOW),
])
def test_the_angular_velocity_of_a_rotation_is_declarable_in_words(declared, latex, verdict):
    r = _check(latex, [ROT, declared])
    assert r.verdict == verdict
    assert any("angular velocity of \\mathbf{Q}, read as" in m for m in r.model), r.model


def test_the_readers_own_body_velocity_is_said_as_what_it_is_everywhere():
    r = _check(SPACE, [ROT, r"\boldsymbol\omega: vector"])
    assert r.verdict == "does-not-hold"  # ω free: the relation does not hold for every ω
    assert not any(m.startswith("free") and "Q_w" in m for m in r.model), r.model
    assert any("Q_w: the body angular velocity of Q, introduced by the reader" in m
               and "angular velocity of \\mathbf{Q}' declares" in m for m in r.model), r.model
    names = [s["symbol"] for s in r.counterexample["symbols"]]
    assert "Q_w, the body angular velocity of Q, introduced by the reader" in names, names


@pytest.mark.parametrize("reading, verdict", [("content", "verified"),
                                              pytest.param("bind", "does-not-hold",
                                                           marks=SLOW)])
def test_a_declared_bracket_cross_is_used_by_both_semantics_and_said(reading, verdict):
    r = _check(GROVES, C + [f"bracket cross: {reading}"])
    assert r.verdict == verdict
    assert any("declared by --let 'bracket cross" in m for m in r.model), r.model
    assert any(m.startswith("numeric cross-check") for m in r.model), r.model


def test_a_bracket_cross_reading_no_book_has_is_refused_naming_both():
    with pytest.raises(BadInput, match=r"'bracket cross: content', 'bracket cross: bind'"):
        _check(GROVES, C + ["bracket cross: inside"])


A = [r"\mathbf{a}: vector"]
#: Marsden & Ratiu's inertia tensor, principal axes (1999) ch. 15
MR = [r"I_1: scalar", r"I_2: scalar", r"I_3: scalar",
      r"\mathbb{I} = \operatorname{diag}(I_1, I_2, I_3)"]
PRINCIPAL = (r"\mathbb{I}\mathbf{a} = \begin{bmatrix} I_1 a_1 \\ I_2 a_2 \\ I_3 a_3 "
             r"\end{bmatrix}")


def test_an_undeclared_blackboard_i_is_asked_where_the_readings_disagree():
    """\\mathbb{I} a = a: true of Chirikjian's identity, false of Marsden & Ratiu's inertia
    tensor (a symmetric 3x3 matrix): bad input naming both, each verdict and the --let."""
    with pytest.raises(BadInput) as e:
        _check(r"\mathbb{I}\mathbf{a} = \mathbf{a}", A)
    msg = str(e.value)
    assert "the identity: verified; a symmetric 3×3 matrix: does-not-hold" in msg, msg
    assert "Chirikjian" in msg and "Marsden & Ratiu" in msg, msg
    assert r"--let '\mathbb{I}: identity'" in msg and r"--let '\mathbb{I}: symmetric " \
        r"matrix'" in msg, msg


@pytest.mark.parametrize("latex, lets, verdict", [
    (r"\mathbb{I}\mathbf{a} = \mathbf{a}", A + [r"\mathbb{I}: identity"], "verified"),
    (r"\mathbb{I}\mathbf{a} = \mathbf{a}", A + [r"\mathbb{I}: symmetric matrix"],
     "does-not-hold"),
    # true of the inertia tensor on its principal axes, false of the identity
    (PRINCIPAL, A + MR, "verified"),
    (PRINCIPAL, A + MR[:3] + [r"\mathbb{I}: identity"], "does-not-hold"),
])
def test_each_declaration_of_blackboard_i_decides(latex, lets, verdict):
    r = _check(latex, lets)
    assert r.verdict == verdict, r.model
    if r"\mathbb{I}: identity" in lets:
        assert any(r"declared by --let '\mathbb{I}: identity'" in m for m in r.model), r.model


@pytest.mark.parametrize("latex, lets, said", [
    (r"\mathbb{I}^T = \mathbb{I}", [], "both verified"),  # symmetric either way
    (r"\mathbb{I}\mathbf{a} = 2\mathbf{a}", A, "both does-not-hold"),
    # a 4x4 identity: the 3x3 inertia tensor does not fit
    (r"\begin{bmatrix} R & \mathbf{t} \\ \mathbf{0}^T & 1 \end{bmatrix}\begin{bmatrix} R^T & "
     r"-R^T\mathbf{t} \\ \mathbf{0}^T & 1 \end{bmatrix} = \mathbb{I}",
     [r"R: rotation", r"\mathbf{t}: vector"], "does not type-check"),
])
def test_an_undeclared_blackboard_i_is_decided_where_one_verdict_remains(latex, lets, said):
    r = _check(latex, lets)
    assert r.verdict in ("verified", "does-not-hold")
    assert any(m.startswith(r"\mathbb{I}: not declared") and said in m for m in r.model), \
        r.model


def test_a_sized_blackboard_i_is_the_identity_and_a_twice_declared_one_refused():
    assert _check(r"\mathbb{I}_3\mathbf{a} = \mathbf{a}", A).verdict == "verified"
    with pytest.raises(BadInput, match="declared twice"):
        _check(r"\mathbb{I}\mathbf{a} = \mathbf{a}",
               A + [r"\mathbb{I}: identity", r"\mathbb{I}: matrix"])


#: Jain (2011) ch. 1: the rigid-body transformation operator φ(l) = [I l~; 0 I]
PHI = [r"\mathbf{l}: vector",
       r"\phi(\mathbf{l}) = \begin{bmatrix} \mathbf{I} & \tilde{\mathbf{l}} \\ \mathbf{0} & "
       r"\mathbf{I} \end{bmatrix}"]
#: Jain's φ^*, the transpose: [I 0; -l~ I] (l~ is skew); true of the transpose only
STAR_TRANSPOSE = (r"\phi^*(\mathbf{l}) = \begin{bmatrix} \mathbf{I} & \mathbf{0} \\ "
                  r"-\tilde{\mathbf{l}} & \mathbf{I} \end{bmatrix}")
#: Featherstone's X^* = X^{-T}: φ(l)^{-1} = φ(-l), so φ^{-T} = [I 0; l~ I]; true of the dual only
STAR_DUAL = (r"\phi^*(\mathbf{l}) = \begin{bmatrix} \mathbf{I} & \mathbf{0} \\ "
             r"\tilde{\mathbf{l}} & \mathbf{I} \end{bmatrix}")


@pytest.mark.parametrize("reading, latex, verdict", [
    ("transpose", STAR_TRANSPOSE, "verified"),
    ("transpose", STAR_DUAL, "does-not-hold"),
    ("dual", STAR_DUAL, "verified"),
    pytest.param("dual", STAR_TRANSPOSE, "does-not-hold", marks=SLOW),
])
def test_a_declared_star_is_used_by_both_semantics_and_said(reading, latex, verdict):
    r = _check(latex, PHI + [f"star: {reading}"])
    assert r.verdict == verdict, r.model
    assert any(m.startswith(f"X^*: read as the {reading}") and "declared by --let 'star" in m
               for m in r.model), r.model
    assert any(m.startswith("numeric cross-check") for m in r.model), r.model


@pytest.mark.parametrize("latex, transpose, dual", [
    (STAR_TRANSPOSE, "verified", "does-not-hold"),
    pytest.param(STAR_DUAL, "does-not-hold", "verified", marks=SLOW),
])
def test_an_undeclared_star_is_asked_naming_each_reading_and_its_verdict(latex, transpose,
                                                                         dual):
    with pytest.raises(BadInput) as e:
        _check(latex, PHI)
    msg = str(e.value)
    assert f"the transpose X^T (Jain); each \\tilde{{x}} of a 3-vector its cross-product " \
           f"matrix [x]_\\times: {transpose}" in msg, msg
    assert f"the dual (X^{{-1}})^T (Featherstone); each \\tilde{{x}} of a 3-vector its " \
           f"cross-product matrix [x]_\\times: {dual}" in msg, msg
    assert "--let 'star: transpose'" in msg and "--let 'star: dual'" in msg, msg
    assert "Jain (2011)" in msg and "Featherstone (2008)" in msg, msg
    assert "\\mathbf{l})" not in msg, msg  # the operand's parameter is not the matrix


@pytest.mark.parametrize("latex, verdict", [
    (r"\operatorname{tr}(\phi^*(\mathbf{l})) = 6", "verified"),
    pytest.param(r"\operatorname{tr}(\phi^*(\mathbf{l})) = 5", "does-not-hold", marks=SLOW),
])
def test_a_star_whose_readings_agree_is_decided_and_said(latex, verdict):
    r = _check(latex, PHI)
    assert r.verdict == verdict
    assert any("readings type-check" in m and f"all {verdict}" in m and "X^*" in m
               for m in r.model), r.model


def test_a_star_of_a_6_vector_is_its_transpose_and_of_a_3_vector_refused_saying_why():
    v = [r"\mathcal{V}: 6-vector", r"\mathfrak{f}: 6-vector"]
    assert _check(r"\mathcal{V}^*\mathfrak{f} = \mathfrak{f}^T\mathcal{V}", v).verdict == \
        "verified"
    with pytest.raises(ValueError, match=r"\^\{\*\} of a 3-vector: expected a 4-vector.*6x6"):
        _check(r"\mathbf{a}^*\mathbf{a} = 1", A)


def test_a_star_reading_no_book_has_is_refused_naming_both():
    with pytest.raises(BadInput, match=r"'star: transpose', 'star: dual'"):
        _check(STAR_TRANSPOSE, PHI + ["star: adjugate"])


#: Lee–Leok–McClamroch (2010) sec. II: the hat map's symmetric identity, braces as grouping
LEE = (r"\hat{x}A + A^T\hat{x} = (\{\operatorname{tr}[A]I_{3\times 3} - A\}x)^\wedge")
LEE_LETS = [r"A: matrix", r"x: vector"]


@pytest.mark.parametrize("latex, verdict", [
    (LEE, "verified"),
    pytest.param(LEE.replace("- A\\}", "+ A\\}"), "does-not-hold", marks=SLOW),  # the sign
])
def test_braces_around_an_expression_group_and_are_said(latex, verdict):
    r = rigidsym.check_latex(latex, let=LEE_LETS, notation="murray-li-sastry", repairs=False)
    assert r.verdict == verdict, r.model
    assert any("braces around an expression, read as parentheses" in m for m in r.model), \
        r.model


def test_braces_of_one_glyph_or_of_a_set_are_not_read_as_a_group():
    from rigidsym.latex.respell import grouping_braces

    for latex in (r"\{\boldsymbol\omega\} = \mathbf{a}", r"\{x, y\} = \{y, x\}",
                  r"\{x \mid x^2 = 1\} = \{1\}"):
        assert grouping_braces(latex, [])[0] == latex, latex
    out, _, note = grouping_braces(r"(\{a + \{b c\}\}x)", [])
    assert out == r"((a + (b c))x)" and note
    with pytest.raises(ValueError, match=r"\\\{"):  # an undeclared glyph's braces: unread
        _check(r"\{\boldsymbol\omega\} = \boldsymbol\omega", [r"\boldsymbol\omega: vector"])


ANGLES = [r"\theta: angle", r"\phi: angle"]
#: true read as cos(θ) φ only, and true read as cos(θ φ) only
EXTENT_FACTOR = r"\cos\theta\phi = \phi\cos\theta"
EXTENT_PRODUCT = r"\cos\theta\phi = \cos(\theta\phi)"


@pytest.mark.parametrize("reading, latex, verdict", [
    ("factor", EXTENT_FACTOR, "verified"),
    ("product", EXTENT_PRODUCT, "verified"),
    # the engine decides no identity of cos(theta phi) but a syntactic one: the factor
    # reading's truth, read as the product, is never verified (undecided, or refuted)
    pytest.param("product", r"\cos\theta\phi = \phi\cos\theta", "not verified", marks=SLOW),
])
def test_a_declared_argument_extent_is_used_by_both_semantics_and_said(reading, latex, verdict):
    r = _check(latex, ANGLES + [f"argument extent: {reading}"])
    if verdict == "not verified":
        assert r.verdict in ("does-not-hold", "undecided"), r.model
    else:
        assert r.verdict == verdict, r.model
    spelt = r"\cos(\theta)\phi" if reading == "factor" else r"\cos(\theta\phi)"
    assert any(m.startswith(rf"\cos\theta\phi: read as {spelt}") and
               "declared by --let 'argument extent" in m for m in r.model), r.model
    if verdict == "verified":
        assert any(m.startswith("numeric cross-check") for m in r.model), r.model


@pytest.mark.parametrize("latex", [EXTENT_FACTOR, EXTENT_PRODUCT])
def test_an_undeclared_argument_extent_is_asked_naming_each_reading(latex):
    with pytest.raises(BadInput) as e:
        _check(latex, ANGLES)
    msg = str(e.value)
    own = "factor" if latex == EXTENT_FACTOR else "product"
    verified = r"\cos(\theta)\phi" if own == "factor" else r"\cos(\theta\phi)"
    assert rf"\cos\theta\phi read as {verified}: verified" in msg, msg
    assert "--let 'argument extent: factor'" in msg and "--let 'argument extent: product'" \
        in msg, msg
    assert r"write \cos(\theta)\phi or \cos(\theta\phi)" in msg, msg
    assert "Thomson" in msg and "Murray" in msg, msg


@pytest.mark.parametrize("latex", [
    r"\cos\theta\,\phi = \phi\cos\theta",       # a thin space ends the argument
    r"\cos\theta\cdot\phi = \phi\cos\theta",    # so does an operator
    r"\sin 2\theta = 2\sin\theta\cos\theta",    # a number, then a glyph: one argument
    r"\sin\theta\cos\theta = \cos\theta\sin\theta",  # a function after it
])
def test_an_argument_ended_without_ambiguity_is_decided_with_no_choice(latex):
    r = _check(latex, ANGLES if r"\phi" in latex else ANGLES[:1])
    assert r.verdict == "verified", r.model
    assert not any("argument" in m and "read as" in m for m in r.model), r.model


def test_a_vector_after_the_argument_ends_it():
    """Rodrigues' ``\\sin\\theta\\mathbf{E}``: the matrix cannot be in a sine's argument."""
    lets = [r"\theta: angle", r"\mathbf{E}: matrix"]
    r = _check(r"\sin\theta\mathbf{E} = \mathbf{E}\sin\theta", lets)
    assert r.verdict == "verified", r.model
    assert not any("argument" in m and "read as" in m for m in r.model), r.model


_EULER = [r"\boldsymbol\omega(t): vector", r"\mathbf{J} = \operatorname{diag}(I_1, I_2, I_3)",
          r"\dot{\boldsymbol\omega} = -\mathbf{J}^{-1}(\boldsymbol\omega\times"
          r"\mathbf{J}\boldsymbol\omega)"]


@pytest.mark.parametrize("latex, lets, verdict, said", [
    # identities: 6x6, no product fits; scalars: Kasdin & Paley's torque-free motion
    (r"\frac{d}{dt}\|\mathbf{J}\boldsymbol\omega\|^2 = 0", _EULER, "verified", "scalars"),
    (r"\frac{d}{dt}\|\boldsymbol\omega\|^2 = 0", _EULER, "does-not-hold", "scalars"),
    # both readings type-check and agree
    (r"\operatorname{diag}(I_1, I_2, I_3)^T = \operatorname{diag}(I_1, I_2, I_3)", [],
     "verified", "both"),
])
def test_undeclared_principal_moments_are_read_both_ways(latex, lets, verdict, said):
    """Kasdin & Paley's ``diag(I_1, I_2, I_3)``: identities of sizes 1, 2, 3 by rule 6, or the
    principal moments; the reading that does not type-check is dropped and said, agreeing
    readings decide (before: 'no product fits', naming neither)."""
    r = _check(latex, lets)
    assert r.verdict == verdict, r.detail
    note = next(m for m in r.model if m.startswith("I_{1}, I_{2}, I_{3}: not declared"))
    assert ("both verified" in note) == (said == "both"), note
    assert said == "both" or "does not type-check" in note, note


def test_undeclared_principal_moments_whose_readings_differ_are_asked():
    """tr diag(I_1, I_2, I_3) = 6 holds of the identities (6x6) and not of the moments: asked,
    naming both readings, each verdict and the --let; each declaration decides."""
    latex = r"\operatorname{tr}\operatorname{diag}(I_1, I_2, I_3) = 6"
    with pytest.raises(BadInput, match=r"identities: verified; scalars: does-not-hold") as exc:
        _check(latex, [])
    assert "--let 'I_{1}: scalar; I_{2}: scalar; I_{3}: scalar'" in str(exc.value)
    assert _check(latex, ["I_1: scalar; I_2: scalar; I_3: scalar"]).verdict == "does-not-hold"
