"""certcheck holds each certificate to the chapter's reading (``derivations/
angeles-chapter3.reading.toml``, ``--reading``): the symbol table and the class of every id
are the reading's, a certificate supplies evidence only. The referees' forgeries that a
certificate's own table or class let through (a unit vector or a rotation declared free, a
model line with a dot dropped or a sign changed, (2.49) replaced, a relation-level table of
its own, a look-alike glyph, a sub-case written as a model, words or a citation changed, a
definition relabelled, an id twice in one run, a file past the size limit) are each
rejected naming the id, and every line of the reading, perturbed, fails the ids it serves.
The chapter's certificates are the run's shared ones (``tests/_shared_run.py``)."""

from __future__ import annotations

import copy
import json
import random
import re
import subprocess
import sys
from pathlib import Path

import pytest
from _book import READING

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "certcheck" / "src"))

from certcheck.reading import ReadingError, bind, load_reading  # noqa: E402

READ = load_reading(READING.read_bytes(), str(READING))


def _rejected(cert: dict, reading: dict = READ) -> str:
    with pytest.raises(ReadingError) as exc:
        bind(cert, reading)
    return str(exc.value)


def _line(cert: dict, pred) -> dict:
    return next(e for e in cert["symbols"] if pred(e))


@pytest.fixture(scope="module")
def few():
    """Three ids' certificates of their recorded verdicts: 3.13 (e unit, phi, Q as (2.49)
    prints it), 3.22 (a definition with models), 3.50 (a rotation, its rates, dotted
    models)."""
    from rigidsym.checking.certifying.certificates import certificate
    from rigidsym.registry.declarations import REGISTRY, load_all

    load_all()
    return {i: json.loads(json.dumps(certificate(i, REGISTRY[i].expected)))
            for i in ("3.13", "3.22", "3.50")}


@pytest.mark.slow  # every id: the thorough run; test_forgeries_... holds three in the quick
def test_every_chapter_certificate_is_the_reading_s(chapter_certificates):
    """181 ids: each certificate's tables and class are exactly the reading's, and the
    reading lists every id once (no id the reading leaves to the certificate)."""
    assert set(READ["classes"]) == set(chapter_certificates)
    for i, c in chapter_certificates.items():
        assert bind(c, READ)[0].startswith("reading: "), i


def _forgeries(certs: dict) -> list[tuple[str, str, dict]]:
    """(what, id, forged certificate): the referees' tamperings of the table and class."""
    out = []
    c = copy.deepcopy(certs["3.13"])  # e unit, phi an angle, Q of (2.49) as printed
    e = _line(c, lambda x: x["glyph"] == "\\mathbf{e}")
    e["kind"] = "free"
    for g in c["atoms"]:
        if set(g["names"]) & set(e["atoms"]):
            g["kind"] = "free"
    out.append(("e declared three free atoms", "3.13", c))
    c = copy.deepcopy(certs["3.13"])
    q = _line(c, lambda x: x["glyph"] == "\\mathbf{Q}")
    q["latex"] = q["latex"].replace("+ \\sin", "- \\sin", 1)
    out.append(("(2.49) with a sign changed", "3.13", c))
    c = copy.deepcopy(certs["3.13"])
    _line(c, lambda x: x["glyph"] == "\\mathbf{Q}")["printed_as"] = "(2.4)"
    out.append(("a citation by substring", "3.13", c))
    c = copy.deepcopy(certs["3.13"])
    c["symbols"].append({"glyph": "\\mathbf{\u0435}", "kind": "free",
                         "atoms": list(e["atoms"])})
    out.append(("a Cyrillic look-alike of e", "3.13", c))
    c = copy.deepcopy(certs["3.13"])
    c["symbols"].append({"glyph": "\\mathbf{e}", "latex": "\\begin{bmatrix} 0 \\\\ 0 \\\\ 1 "
                         "\\end{bmatrix}", "model": "a sub-case: e = (0, 0, 1)"})
    out.append(("a sub-case e = (0, 0, 1)", "3.13", c))
    c = copy.deepcopy(certs["3.13"])
    c["relations"][0]["symbols"] = [{"glyph": "\\phi", "latex": "\\frac{\\pi}{2}",
                                     "model": "phi = pi/2 for this relation"}]
    out.append(("a relation-level table of its own (phi = pi/2)", "3.13", c))
    c = copy.deepcopy(certs["3.13"])
    c["verdict"] = "definition"
    out.append(("a relation relabelled a definition", "3.13", c))
    c = copy.deepcopy(certs["3.22"])  # a definition the page prints with \equiv
    c["verdict"] = "verified"
    out.append(("a definition relabelled verified", "3.22", c))
    c = copy.deepcopy(certs["3.22"])
    _line(c, lambda x: x["glyph"] == "\\mathbf{p}_2")["model"] = "any point"
    out.append(("a model's words changed", "3.22", c))
    c = copy.deepcopy(certs["3.22"])
    c["symbols"] = [x for x in c["symbols"] if x["glyph"] != "\\mathbf{P}_1"]
    out.append(("a line of the reading dropped", "3.22", c))
    for i, c0 in certs.items():  # a rotation's nine atoms made free
        if any(x.get("kind") == "rotation" for x in c0["symbols"]):
            c = copy.deepcopy(c0)
            r = _line(c, lambda x: x.get("kind") == "rotation")
            r["kind"] = "free"
            for g in c["atoms"]:
                if set(g["names"]) & set(r["atoms"]):
                    g["kind"] = "free"
            out.append(("Q's nine atoms free", i, c))
            break
    for i, c0 in certs.items():  # a model line with one dot dropped
        hit = next((x for x in c0["symbols"] if "\\dot{" in str(x.get("latex", ""))), None)
        if hit:
            c = copy.deepcopy(c0)
            y = _line(c, lambda x, g=hit["glyph"]: x["glyph"] == g and "latex" in x)
            y["latex"] = y["latex"].replace("\\dot{", "{", 1)
            out.append(("a model line with one dot dropped", i, c))
            break
    for i, c0 in certs.items():  # a rate whose atoms are another glyph's
        rates = [x for x in c0["symbols"] if "kind" in x and x["atoms"][0].endswith("'")]
        plain = [x for x in c0["symbols"] if "kind" in x and not x["atoms"][0].endswith("'")
                 and len(x["atoms"]) == len(rates[0]["atoms"])] if rates else []
        others = [x for x in plain if [a + "'" for a in x["atoms"]] != rates[0]["atoms"]]
        if others:
            c = copy.deepcopy(c0)
            y = _line(c, lambda x, g=rates[0]["glyph"]: x["glyph"] == g)
            y["atoms"] = [a + "'" for a in others[0]["atoms"]]
            out.append(("a rate bound to another glyph's atoms", i, c))
            break
    return out


def test_forgeries_of_the_table_and_class_rejected_naming_the_id(few):
    """Each forgery fails with a message naming its id (certcheck prints it on the id's
    FAILED line); the genuine three bind."""
    for i, c in few.items():
        assert bind(c, READ)[0].startswith("reading: "), i
    found = _forgeries(few)
    assert len(found) == 13, [w for w, *_ in found]
    for what, i, c in found:
        assert f"({i})" in _rejected(c), what


def _perturbed(entry: str, rng: random.Random) -> str:
    """One [[let]] line changed as a careless or a hostile reviewer would: a kind, a sign,
    a glyph, a cited argument."""
    name, sep, rest = re.match(r"(.*?)(\s*[:=]\s*)(.*)", entry, re.S).groups()
    swaps = {"unit vector": "3-vector", "rotation": "3x3 matrix", "angle": "scalar",
             "scalar": "angle", "rate of": "second rate of", "second rate of": "rate of"}
    if ":" in sep:
        for a, b in swaps.items():
            if rest.startswith(a):
                return name + sep + b + rest[len(a):]
        m = re.match(r"(\d+)-vector", rest)
        if m:
            return f"{name}{sep}{int(m.group(1)) + 1}-vector"
        return name + "'" + sep + rest
    choices = ["glyph"]
    if re.search(r"(?<!\\)[+-]", rest):
        choices.append("sign")
    way = rng.choice(choices)
    if way == "sign":
        k = [m.start() for m in re.finditer(r"(?<![\\{])[+-]", rest)]
        if k:
            j = rng.choice(k)
            return name + sep + rest[:j] + {"+": "-", "-": "+"}[rest[j]] + rest[j + 1:]
    return name + "'" + sep + rest


@pytest.mark.slow  # the chapter's certificates: built in the thorough run anyway
def test_each_line_of_the_reading_perturbed_fails_the_ids_it_serves(chapter_certificates,
                                                                     tmp_path):
    """A seeded sample of the reading's [[let]] lines (every line in the thorough run), each
    changed once (a kind, a sign, a glyph): every id the line serves now fails, naming the
    id, and the reading's other ids still bind."""
    import _profile

    text = READING.read_text(encoding="utf-8")
    lines = [m for m in re.finditer(r"^let = (.*)$", text, re.M)]
    rng = random.Random(_profile.SEED)
    n = len(lines) if _profile.PROFILE != "quick" else 12
    for m in rng.sample(lines, n):
        old = m.group(1)
        raw = json.loads(old) if old.startswith('"') else old[1:-1]
        new = _perturbed(raw, rng)
        assert new != raw
        changed = text[:m.start(1)] + json.dumps(new, ensure_ascii=False) + text[m.end(1):]
        try:
            reading = load_reading(changed.encode())
        except ReadingError:   # a kind no reading knows: the whole reading refused
            continue
        ids = re.search(r"^ids = \[(.*)\]$", text[m.end():], re.M).group(1)
        for i in json.loads(f"[{ids}]"):
            assert f"({i})" in _rejected(chapter_certificates[i], reading), (raw, new, i)


def _certcheck(*args) -> subprocess.CompletedProcess:
    code = ("import sys; sys.path.insert(0, sys.argv[1]); from certcheck.__main__ import "
            "main; sys.exit(main(sys.argv[2:]))")
    return subprocess.run([sys.executable, "-I", "-S", "-c", code,
                           str(ROOT / "certcheck" / "src"), *map(str, args)],
                          capture_output=True, text=True, timeout=600)


def test_the_command_binds_to_the_reading_and_fails_closed(few, tmp_path):
    """The command: a genuine pair of certificates passes with --reading (exit 0, their
    table bound); the same folder without --reading exits 3 (the tables are the
    certificate's word); a forged table, an id twice in one run, a reading the manifest
    does not name and a file past the size limit each exit 1 naming what failed."""
    from _book import book_path
    from _certforge import write_run

    book = book_path()   # skips where the chapter is absent: exit 0 needs the page read
    ids = ["3.13", "3.22"]
    run = tmp_path / "run"
    write_run(run, {f"{i}.json": few[i] for i in ids}, book)
    p = _certcheck("--quiet", "--book", book, "--reading", READING, run)
    assert p.returncode == 0, p.stdout + p.stderr
    assert _certcheck("--quiet", "--book", book, run).returncode == 3
    forged = {f"{i}.json": few[i] for i in ids}
    forged["3.13.json"] = _forgeries(few)[0][2]
    write_run(tmp_path / "forged", forged, book)
    p = _certcheck("--quiet", "--book", book, "--reading", READING, tmp_path / "forged")
    assert p.returncode == 1 and "FAILED 3.13.json: (3.13)" in p.stdout, p.stdout
    relabelled = copy.deepcopy(few["3.13"])   # one id, two folders
    write_run(tmp_path / "second", {"3.13.json": relabelled}, book)
    p = _certcheck("--quiet", "--book", book, "--reading", READING, run, tmp_path / "second")
    assert p.returncode == 1 and "two certificates of one id" in p.stdout, p.stdout
    other = tmp_path / "other.reading.toml"
    other.write_text(READING.read_text(encoding="utf-8") + "\n# reviewed again\n")
    p = _certcheck("--quiet", "--book", book, "--reading", other, run)
    assert p.returncode == 1 and "the reading given has SHA-256" in p.stdout, p.stdout
    big = copy.deepcopy(few["3.22"])
    big["padding"] = "x" * 4_100_000
    write_run(tmp_path / "big", {"3.22.json": big}, book)
    p = _certcheck("--quiet", "--book", book, "--reading", READING, tmp_path / "big")
    assert p.returncode == 1 and "larger than" in p.stdout, p.stdout
