"""The reading file (``rigidsym.reading``): one TOML format for the chapter and for a
reader's notes, every key checked (fail closed: a key, a convention or a class it does not
know is an error naming the file and the key, never "nothing said"), and the same lines
read by certcheck's own parser (``certcheck/reading.py``)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from _book import READING
from hypothesis import given, settings
from hypothesis import strategies as st

from rigidsym.core.errors import BadInput
from rigidsym.reading import CONVENTIONS, lets_for, load_reading, parse_reading, sidecar

ROOT = Path(__file__).resolve().parents[1]
HEAD = '[reading]\nformat = 1\npage = "notes.md"\n'


def test_the_chapter_s_reading_gives_every_id_one_class_and_both_parsers_agree():
    sys.path.insert(0, str(ROOT / "certcheck" / "src"))
    from certcheck.reading import load_reading as referee_reading

    mine = load_reading(READING)
    theirs = referee_reading(READING.read_bytes())
    assert len(mine.ids) == 181 and set(mine.ids) == set(theirs["classes"])
    assert {i: x.cls for i, x in mine.ids.items()} == theirs["classes"]
    assert sum(len(x.ids) for x in mine.lets) == sum(len(v) for v in theirs["lines"].values())
    assert mine.sha256 == theirs["sha256"]
    assert {i for i, x in mine.ids.items() if x.words} == set(theirs["words"])


@pytest.mark.parametrize(("text", "says"), [
    ("[reading]\nformat = 2\n", "format = 1"),
    (HEAD + "[glyph]\nx = 1\n", "unknown table or key 'glyph'"),
    (HEAD + '[conventions]\nquaternion_product = "hamiltonian"\n', "hamilton, jpl"),
    (HEAD + '[conventions]\nhandedness = "left"\n', "unknown convention 'handedness'"),
    (HEAD + '[[let]]\nlet = ""\n', "let must be a non-empty string"),
    (HEAD + '[[let]]\nlet = "x: scalar"\nkind = "scalar"\n', "unknown key 'kind'"),
    (HEAD + '[classes]\nrelation = ["1"]\ndefinition = ["1"]\n', "'1' is given two classes"),
    (HEAD + '[classes]\nlemma = ["1"]\n', "unknown class 'lemma'"),
    (HEAD + '[id."1"]\nclass = "definition"\n[classes]\nrelation = ["1"]\n',
     "class 'definition' but [classes] gives 'relation'"),
    (HEAD + "[[let]\n", "not TOML"),
])
def test_what_the_format_does_not_know_is_an_error_naming_it(text, says):
    with pytest.raises(BadInput, match="reading <text>: .*" + says.replace("[", r"\[")
                       .replace("]", r"\]").replace("(", r"\(")):
        parse_reading(text)


def test_a_byte_order_mark_and_the_sidecar_s_name(tmp_path):
    page = tmp_path / "notes.md"
    path = sidecar(page)
    assert path.name == "notes.reading.toml"
    path.write_bytes(b"\xef\xbb\xbf" + HEAD.encode() + b'[[let]]\nlet = "\\\\phi: angle"\n')
    r = load_reading(path)
    assert r.page == "notes.md" and [x.let for x in r.lets] == ["\\phi: angle"]
    with pytest.raises(BadInput, match="cannot read the file"):
        load_reading(tmp_path / "absent.reading.toml")


@settings(max_examples=25)
@given(st.lists(st.tuples(st.sampled_from([None, "2", "2.1", "3"]),
                          st.lists(st.sampled_from(["a", "b"]), max_size=2)), max_size=6),
       st.sampled_from([None, "2", "2.1", "2.10", "3.2"]), st.sampled_from([None, "a", "b"]))
def test_a_let_holds_in_its_section_and_its_subsections_for_its_ids(entries, scope, eq_id):
    text = HEAD + "".join(
        f'[[let]]\nlet = "x_{k}: scalar"\n' + (f'scope = "{s}"\n' if s else "")
        + (f"ids = {ids!r}\n".replace("'", '"') if ids else "")
        for k, (s, ids) in enumerate(entries))
    got = lets_for(parse_reading(text), scope=scope, id=eq_id)
    want = [f"x_{k}: scalar" for k, (s, ids) in enumerate(entries)
            if (s is None or (scope is not None and (scope == s or scope.startswith(s + "."))))
            and (not ids or eq_id in ids)]
    assert got == want


def test_every_convention_value_reads():
    for key, values in CONVENTIONS.items():
        for v in values:
            assert parse_reading(HEAD + f'[conventions]\n{key} = "{v}"\n').conventions == {key: v}


def test_the_page_tests_groups_are_lines_of_the_reading():
    """The glyphs the page-reading tests group by section (tests/_reading_groups.py) are each
    given a line by the chapter's reading: a group never names a line the reading dropped."""
    import _reading_groups as groups

    given = {x.let.split("=")[0].split(":")[0].strip().removesuffix("(t)").strip()
             for x in load_reading(READING).lets}
    for name in ("DISPLACEMENT_GLYPHS", "INSTANT_SCREW_GLYPHS", "INVARIANT_RATE_GLYPHS",
                 "TWIST_GLYPHS"):
        missing = set(getattr(groups, name)) - given
        assert not missing, (name, missing)
