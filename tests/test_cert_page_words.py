"""The theorems the page states in words, read through certcheck's table of them
(``certcheck.words``): Theorems 3.2.1, 3.3.1, 3.4.1, 3.4.2, 3.7.1, 3.7.2 and Corollary
3.4.1, each entry the page's statement and the relation it states in the page's glyphs,
used only where the page's statement is the entry's. Each is read on every side (the command exits 0
on its folder); a sign, a coefficient, a transpose of the certificate's relation or of the
table's, the sides shifted, another id's text, the other verdict and a relation dropped are
each rejected naming the id or left NOT READ, never passed; the page's statement edited, or
the table's entry another id's, leaves the id NOT READ. One id in the default run, the rest
slow."""

from __future__ import annotations

import copy
import json
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "certcheck" / "src"))

from _book import BOOK, READING  # noqa: E402
from certcheck.book import BookError, check_page, locate, sha256  # noqa: E402
from certcheck.braces import displays_after  # noqa: E402
from certcheck.by_definition import unread_vacuous  # noqa: E402
from certcheck.compare import compare  # noqa: E402
from certcheck.reading import load_reading  # noqa: E402
from test_cert_page import another_printed_text, relabelled  # noqa: E402
from test_cert_page_momenta import certificates  # noqa: E402

from certcheck import CheckError, check_certificate, words  # noqa: E402

words.use(load_reading(READING.read_bytes()))   # the theorems in words: the reading's
_V = words.WORDS["thm3.4.2"][1]
#: id -> (a sign, a coefficient, a transpose where it matters: the table's relation changed)
TABLE_TAMPERINGS = {
    "thm3.3.1": [r"\boldsymbol{\Omega} - \boldsymbol{\Omega}^T = \mathbf{O}",
                 r"\boldsymbol{\Omega} + 2\boldsymbol{\Omega}^T = \mathbf{O}",
                 r"\boldsymbol{\Omega} + \boldsymbol{\Omega} = \mathbf{O}"],
    "thm3.4.1": [r"(\dot{\mathbf{p}} + \dot{\mathbf{a}}) \cdot (\mathbf{p} - \mathbf{a}) = 0",
                 r"(\dot{\mathbf{p}} - 2\dot{\mathbf{a}}) \cdot (\mathbf{p} - \mathbf{a}) = 0",
                 r"(\dot{\mathbf{p}} - \dot{\mathbf{a}}) \cdot \mathbf{p} = 0"],
    "cor3.4.1": [r"\boldsymbol{\omega} \cdot \dot{\mathbf{p}} = -\boldsymbol{\omega} \cdot "
                 r"\dot{\mathbf{a}}",
                 r"\boldsymbol{\omega} \cdot \dot{\mathbf{p}} = 2\boldsymbol{\omega} \cdot "
                 r"\dot{\mathbf{a}}",
                 r"\boldsymbol{\omega} \cdot \mathbf{p} = \boldsymbol{\omega} \cdot "
                 r"\mathbf{a}"],
    "thm3.2.1": [r"\mathbf{e}^T (\mathbf{p}' - \mathbf{p}) = \mathbf{e}^T (\mathbf{a}' + "
                 r"\mathbf{a})",
                 r"\mathbf{e}^T (\mathbf{p}' - \mathbf{p}) = 2\mathbf{e}^T (\mathbf{a}' - "
                 r"\mathbf{a})",
                 r"\mathbf{e}^T \mathbf{p}' = \mathbf{e}^T \mathbf{a}'"],
    "thm3.4.2": [_V.replace(r"= \mathbf{v}_0, ", r"= -\mathbf{v}_0, "),
                 _V.replace(r"- \|\mathbf{v}_0\|^2", r"- 2\|\mathbf{v}_0\|^2"),
                 _V.replace(r"\times \mathbf{v}_0", r"\times \dot{\mathbf{a}}")],
    "thm3.7.1": [r"\|\mathbf{n}_A\|^2 = \|\mathbf{n}_0\|^2 - \|\mathbf{f} \times (\mathbf{a}"
                 r" - \mathbf{p})\|^2, \quad \mathbf{f} \times \mathbf{n}_0 = \mathbf{0}",
                 r"\|\mathbf{n}_A\|^2 = 2\|\mathbf{n}_0\|^2 + \|\mathbf{f} \times (\mathbf{a}"
                 r" - \mathbf{p})\|^2, \quad \mathbf{f} \times \mathbf{n}_0 = \mathbf{0}",
                 r"\|\mathbf{n}_A\|^2 = \|\mathbf{n}_0\|^2 + \|\mathbf{f} \times (\mathbf{a}"
                 r" - \mathbf{p})\|^2, \quad \mathbf{f} \times \mathbf{n}_A = \mathbf{0}"],
    "thm3.7.2": [r"\mathbf{e}'' \cdot \mathbf{n}_P = -\mathbf{e}'' \cdot \mathbf{n}_A",
                 r"\mathbf{e}'' \cdot \mathbf{n}_P = 2\mathbf{e}'' \cdot \mathbf{n}_A",
                 r"\mathbf{e} \times \mathbf{n}_P = \mathbf{e} \times \mathbf{n}_A"],
}
IDS = list(TABLE_TAMPERINGS)



def outcome(cert: dict, book: str) -> str:
    """What the command makes of ``cert`` against ``book`` (page, mathematics, reader, the
    table's words): ``"rejected: <why>"``, ``"not read"`` (exit 3) or ``"read"`` (exit 0)."""
    i, counts = cert["id"], []
    try:
        check_page(cert, book)
        check_certificate(cert, fast=True)
        text = locate(book, i)
        compare(cert, words.stated(i, text), fast=True, defs={}, counts=counts,
                later=displays_after(book, i))
        (k, n, firm), = counts
        vacuous, _ = unread_vacuous(cert, firm)
    except (CheckError, BookError) as exc:
        return f"rejected: {exc}"
    return "read" if k - 2 * vacuous == n else "not read"


def _printed(c: dict) -> list:
    return [r for r in c["relations"] if r["role"] == "printed" or r.get("page")]


def _side(c: dict, side: str, change) -> dict:
    t = copy.deepcopy(c)
    for r in _printed(t):
        r[side] = [[change(x) for x in row] for row in r[side]]
    return t


def certificate_tamperings(c: dict, book: str) -> list[tuple[str, dict]]:
    """The certificate's relation changed (each proved, or not), its text, verdict, relation.
    Where the printed sides are identically zero under the hypotheses (Omega + Omega^T = O,
    (p-dot - a-dot) . (p - a) = 0), a sign of a side changes no function: the sign and the
    transpose are the table's tamperings there (:data:`TABLE_TAMPERINGS`)."""
    other = "cor3.4.1" if c["id"] != "cor3.4.1" else "thm3.4.1"
    dropped = copy.deepcopy(c)
    dropped["relations"] = [r for r in c["relations"] if r not in _printed(c)]
    unplaced = copy.deepcopy(c)  # the page's place of a claim dropped: nothing is read
    for r in unplaced["relations"]:
        r.pop("page", None)
    zero = all(x == "0" for r in _printed(c) for row in r["rhs"] for x in row)
    return [("a sign", _side(c, "rhs", lambda x: f"-({x})"))] * (not zero) + [  # -0 is 0
            ("a coefficient", _side(c, "lhs", lambda x: f"2*({x}) + 1")),
            ("sides shifted", _side(_side(c, "lhs", lambda x: f"({x}) + 1"), "rhs",
                                    lambda x: f"({x}) + 1")),
            ("another id's text", another_printed_text(c, book, other)),
            ("does-not-hold", relabelled(c, "does-not-hold")),
            ("definition", relabelled(c, "definition")),
            ("relation dropped", dropped)] + \
        [("claim's place dropped", unplaced)] * any(r.get("page") for r in c["relations"])


def _folder(tmp: Path, cert: dict, book_path: Path) -> Path:
    """A folder of one certificate and its manifest (the run's, as rigidsym writes it)."""
    name = f"{cert['id']}.json"
    (tmp / name).write_text(json.dumps(cert), encoding="utf-8")
    man = {"rigidsym": "test", "certificates": {name: sha256((tmp / name).read_bytes())},
           "book_sha256": sha256(book_path.read_bytes()),
           "reading_sha256": sha256(READING.read_bytes())}
    (tmp / "MANIFEST.json").write_text(json.dumps(man), encoding="utf-8")
    return tmp


def check_words(i: str, book: str, monkeypatch) -> None:
    c = certificates([i])[i]
    assert outcome(c, book) == "read"
    for what, t in certificate_tamperings(c, book):
        got = outcome(t, book)
        assert got == "not read" or got.startswith(f"rejected: ({i})"), (what, got)
        assert got != "read", what
    for latex in TABLE_TAMPERINGS[i]:  # the table's relation changed: held to the proof
        assert latex != words.WORDS[i][1]
        monkeypatch.setitem(words.WORDS, i, (words.WORDS[i][0], latex, "tampered"))
        got = outcome(c, book)
        assert got.startswith(f"rejected: ({i})"), (latex, got)
    monkeypatch.undo()
    line = next(x for x in book.splitlines() if " ".join(x.split()) == locate(book, i))
    for new in (line[:-1] + " Moreover, it vanishes.*",  # a sentence added: not read
                line[:-32] + " the contrary.*"):  # its end changed (the certificate's too)
        edited = book.replace(line, new)
        assert words.stated(i, locate(edited, i)) == locate(edited, i)
        got = outcome(c, edited)
        assert got == "not read" or got.startswith(f"rejected: ({i})"), got
    assert outcome(c, book.replace(line, line[:-1] + " Moreover, it vanishes.*")) == "not read"
    other = next(j for j in IDS if j != i)  # another id's statement in the entry: not used
    monkeypatch.setitem(words.WORDS, i, (words.WORDS[other][0], *words.WORDS[i][1:]))
    assert outcome(c, book) == "not read"
    monkeypatch.undo()


def test_default_theorem_in_words_read_and_tamperings_rejected(book, monkeypatch):
    check_words("thm3.3.1", book, monkeypatch)


@pytest.mark.slow
@pytest.mark.parametrize("i", IDS[1:])
def test_theorems_in_words_read_and_tamperings_rejected(book, monkeypatch, i):
    check_words(i, book, monkeypatch)


def test_command_reads_the_words_and_fails_closed(book, tmp_path):
    """The command itself: exit 0 on a theorem read through the table, 1 on a changed
    relation, 3 on a certificate whose claim the page's words do not place."""
    from certcheck.__main__ import main

    c = certificates(["thm3.7.2"])["thm3.7.2"]
    codes = []
    for k, t in enumerate([c, _side(c, "rhs", lambda x: f"-({x})"),
                           certificate_tamperings(c, book)[-1][1]]):
        (tmp_path / str(k)).mkdir()
        folder = _folder(tmp_path / str(k), t, BOOK)
        codes.append(main([str(folder), "--book", str(BOOK), "--reading", str(READING), "--quiet"]))
    assert codes == [0, 1, 3]


def test_table_entries_are_the_pages_statements(book):
    """Every entry's statement is its id's on the page, and the words of the other
    theorems (no entry) are read as nothing."""
    for i, (sentence, latex, why) in words.WORDS.items():
        assert words.stated(i, locate(book, i)) == latex, i
        assert why and sentence in locate(book, i)
    for i in ("thm3.2.2", "caveat3.4"):
        assert words.stated(i, locate(book, i)) == locate(book, i)
