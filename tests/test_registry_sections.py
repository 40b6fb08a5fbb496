"""The registry knows no chapter: the book's sections are those its declarations name, the
words on a section without ids are the book package's, and a book id is any book's form."""

from __future__ import annotations

import importlib

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rigidsym.core import config
from rigidsym.core.errors import BadInput
from rigidsym.registry.declarations import (
    REGISTRY,
    book_ids,
    book_sections,
    is_user_id,
    parse_id,
    parse_section,
    section_of,
    select,
)


def test_the_book_s_sections_are_those_its_declarations_name():
    assert book_ids()  # loads the book
    declared = {".".join(eq.section.split(".")[:2]) for k, eq in REGISTRY.items()
                if not is_user_id(k)}
    assert set(book_sections()) == declared and len(book_sections()) == len(declared)
    for s in book_sections():
        assert select(sections=[s]) and all(section_of(i) == s for i in select(sections=[s]))


def test_why_a_section_holds_no_id_is_the_book_s_data(monkeypatch):
    book = importlib.import_module(config.BOOK)
    outside = "0.1"
    assert outside not in book_sections()
    with pytest.raises(BadInput, match=r"got '0\.1'$"):
        parse_section(outside)
    monkeypatch.setattr(book, "SECTIONS_WITHOUT_IDS", {outside: "a preface"}, raising=False)
    with pytest.raises(BadInput, match=r"got '0\.1' \(a preface\)"):
        parse_section(outside)


@given(st.integers(1, 40), st.integers(1, 400), st.sampled_from(["", "a", "e"]),
       st.sampled_from(["{}", "({})", "eq{}", " {} "]))
def test_a_book_id_is_any_book_s_number(chapter, number, part, spelling):
    eq_id = f"{chapter}.{number}{part}"
    assert parse_id(spelling.format(eq_id)) == eq_id
    assert parse_id(f"thm{chapter}.{number}.2") == f"thm{chapter}.{number}.2"


@pytest.mark.parametrize("text", ["3", "x.1", "3.1f", "3.1.2", "thm3", "notes:"])
def test_what_is_no_id_is_refused_naming_the_forms(text):
    with pytest.raises(BadInput, match="N.M or N.Ma"):
        parse_id(text)
