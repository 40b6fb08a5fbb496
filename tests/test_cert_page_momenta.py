"""Section 3.8's twists and momenta read from the page: the symbol table's lines
of ``rigidsym.checking.certifying.twist_symbols`` (the twist ``t`` at the centre of mass,
``W`` of (3.140), ``mu = M t`` of (3.142), the momenta of (3.135), the rates, the wrench
``w = [n_C; f]`` the motion requires) let certcheck's second reader read the Newton-Euler
ids firmly; a changed line, a changed side and another id's text are rejected naming the
id. Two ids here, every id read through the lines in slow."""

from __future__ import annotations

import copy
import json
import sys
from pathlib import Path

import _profile
import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "certcheck" / "src"))

from certcheck.book import BookError, check_page, definitions_before, locate  # noqa: E402
from test_cert_page import (  # noqa: E402
    another_printed_text,
    doubled_rhs,
    mass_changed,
    relabelled,
    shifted_sides,
)

from certcheck import CheckError, check_certificate  # noqa: E402

#: the Newton-Euler ids whose every printed side is read through the lines (measured)
NEWTON_EULER = ["3.134b", "3.135", "3.136", "3.137", "3.139", "3.140", "3.142", "3.143",
                "3.145", "3.146"]


def certificates(ids: list[str]) -> dict:
    """The recorded verdicts' certificates (certcheck, not this test, says they hold)."""
    from rigidsym.checking.certifying.certificates import certificate
    from rigidsym.registry.declarations import REGISTRY, load_all

    load_all()
    return {i: json.loads(json.dumps(certificate(i, REGISTRY[i].expected))) for i in ids}


def read_lines(cert: dict, book: str, fast: bool = True) -> list[str]:
    """certcheck's reader's lines for the certificate (python-flint's arithmetic where it
    is installed, unless ``fast`` is false: the standard library's)."""
    from certcheck.compare import compare

    i = cert["id"]
    return compare(cert, locate(book, i), fast=fast, defs=definitions_before(book, i))


def rejection(cert: dict, book: str) -> str:
    """certcheck's message rejecting ``cert`` (page, mathematics or reader)."""
    try:
        check_page(cert, book)
        check_certificate(cert, fast=True)
        read_lines(cert, book)
    except (CheckError, BookError) as exc:
        return str(exc)
    raise AssertionError(f"({cert['id']}) accepted")


def line_changed(cert: dict, glyph: str, old: str, new: str) -> dict | None:
    """The table's line of ``glyph`` with ``old`` replaced by ``new`` in its LaTeX."""
    c = copy.deepcopy(cert)
    entry = next((e for e in c["symbols"] if e.get("glyph") == glyph), None)
    if entry is None or old not in entry.get("latex", ""):
        return None
    entry["latex"] = entry["latex"].replace(old, new)
    return c


def line_doubled(cert: dict, glyph: str) -> dict | None:
    """The table's line of ``glyph`` multiplied by 2 (another quantity of that name)."""
    entry = next((e for e in cert["symbols"] if e.get("glyph") == glyph), None)
    return None if entry is None or "latex" not in entry else \
        line_changed(cert, glyph, entry["latex"], f"2({entry['latex']})")



def test_twist_and_angular_velocity_dyad_read_firmly_and_tamperings_rejected(book):
    """3.140 (W as printed, its own definition read on both sides) and 3.145 (T = t^T M t / 2:
    T through (3.130)'s integral, M through (3.138), t the twist at the centre of mass)
    read firmly on every side; the twist's c-dot doubled, W's Omega transposed, both sides
    shifted and (3.140) the right side doubled, another id's text, the verdict changed:
    rejected naming the id."""
    certs = certificates(["3.140", "3.145"])
    changed = {"3.140": ("\\mathbf{W}", "\\boldsymbol{\\Omega}", "\\boldsymbol{\\Omega}^T"),
               "3.145": ("\\mathbf{t}", "\\dot{\\mathbf{c}}", "2\\dot{\\mathbf{c}}")}
    for i, c in certs.items():
        lines = read_lines(c, book, fast=False)
        assert lines and all(x.startswith("read from the page") for x in lines), lines
        glyph = changed[i][0]
        assert any(f"{glyph} as the model's" in x for x in lines), lines
        other = "3.145" if i == "3.140" else "3.140"
        cases = [line_changed(c, *changed[i]), shifted_sides(c)]
        assert cases[0] is not None
        if i == "3.140":  # the cheaper id (3.145's rest: slow)
            cases += [doubled_rhs(c), another_printed_text(c, book, other),
                      relabelled(c, "verified")]
        for t in cases:
            assert f"({i})" in rejection(t, book), i


@pytest.mark.slow
def test_newton_euler_read_through_the_lines_and_each_line_doubled_rejected(
        book, chapter_certificates):
    """Every Newton-Euler id read through the lines: every printed side read firmly, and
    each twist or momentum line it uses doubled, both sides shifted, the right side doubled
    (where not 0), a particle's mass changed, another id's text: rejected naming the id (a
    particle's velocity without o-dot is not: 3.134b reads no velocity, and in 3.139 c-dot
    meets only W's zero block)."""
    from _reading_groups import TWIST_GLYPHS

    # the run's shared certificates (~25 s to build these again), each a copy
    certs = {i: json.loads(json.dumps(chapter_certificates[i])) for i in NEWTON_EULER}
    cases = []
    for k, (i, c) in enumerate(certs.items()):
        lines = read_lines(c, book)
        assert lines and all(x.startswith("read from the page") for x in lines), (i, lines)
        used = [g for g in TWIST_GLYPHS if any(f"{g} as the model's" in x for x in lines)]
        assert used, i
        cases += [(i, f"{g} doubled", line_doubled(c, g)) for g in used]
        cases += [(i, "shifted", shifted_sides(c)), (i, "rhs doubled", doubled_rhs(c)),
                  (i, "mass", mass_changed(c)),
                  (i, "other text", another_printed_text(c, book, NEWTON_EULER[k - 1]))]
    # every id read on every side; a seeded third of the (id, tampering) pairs proved
    # rejected (all in the exhaustive profile); the quick test rejects a changed line, both
    # sides shifted, the right side doubled and another id's text on 3.140 and 3.145
    for i, _, t in _profile.share(cases, 1 / 3, key=lambda x: f"{x[0]} {x[1]}"):
        if t is not None:
            assert f"({i})" in rejection(t, book), i


@pytest.mark.slow
def test_twist_rate_at_a_body_point_read_firmly_and_tamperings_rejected(book):
    """3.90 (section 3.5: t-dot = [omega-dot; v-dot], v-dot the acceleration of the twist's
    body point P) read firmly on both sides; its t-dot or v-dot line doubled, both sides
    shifted, another id's text, the verdict changed: rejected naming the id."""
    c = certificates(["3.90"])["3.90"]
    lines = read_lines(c, book, fast=False)
    assert lines and all(x.startswith("read from the page") for x in lines), lines
    cases = [line_doubled(c, "\\dot{\\mathbf{t}}"), line_doubled(c, "\\dot{\\mathbf{v}}"),
             shifted_sides(c), another_printed_text(c, book, "3.89"), relabelled(c, "verified")]
    assert None not in cases
    for t in cases:
        assert "(3.90)" in rejection(t, book)


@pytest.mark.slow
def test_moving_body_twist_read_where_the_relation_cancels_its_velocity(book):
    """3.141 (W t = 0): the relation cancels t's c-dot (W's lower blocks are O), yet the
    certificate keeps the body's o as atoms, so t = [omega; c-dot] and W as printed in
    (3.140) read the left side and the page's bare 0 takes its size: read on every side.
    t's line with c-dot for omega, W's with 1 for its lower-right O and both sides shifted
    (each a change that makes W t non-zero; doubling omega or Omega would not): rejected
    (~3 s: the moving body's rotation)."""
    c = certificates(["3.141"])["3.141"]
    lines = read_lines(c, book)
    assert len(lines) == 1 and lines[0].startswith("read from the page: relation 1's lhs")
    assert " and rhs" in lines[0] and "\\mathbf{t} as the model's" in lines[0], lines
    cases = [line_changed(c, "\\mathbf{t}", "\\boldsymbol{\\omega} \\\\",
                          "\\dot{\\mathbf{c}} \\\\"),
             line_changed(c, "\\mathbf{W}", "\\mathbf{O} \\end", "\\mathbf{1} \\end"),
             shifted_sides(c)]
    assert None not in cases
    for t in cases:
        assert "(3.141)" in rejection(t, book)
