"""A reader's own module certified against their own text and reading
(docs/own-equations.md, "Certified against your own text"): ``rigidsym verify --module
examples/rotation_notes.py --certificates DIR --book examples/rotation_notes.md --reading
examples/rotation_notes.reading.toml`` writes certificates whose symbol tables are the
reader's reading's lines (none of the chapter's), and certcheck, run as a user runs it,
CHECKS each one against the text and the reading; a kind changed in a certificate is a
failure naming its id; the run exits 1 when certcheck is missing or does not check them."""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from rigidsym.cli import main

pytestmark = pytest.mark.xdist_group("user_certificates")  # its module fixtures built on one worker

ROOT = Path(__file__).resolve().parents[1]
MODULE = ROOT / "examples" / "rotation_notes.py"
TEXT = ROOT / "examples" / "rotation_notes.md"
READING = ROOT / "examples" / "rotation_notes.reading.toml"
CHAPTER_READING = ROOT / "derivations" / "angeles-chapter3.reading.toml"
IDS = tomllib.loads(READING.read_text(encoding="utf-8"))["classes"]["relation"]


def _verify(folder: Path, *extra: str) -> int:
    """``rigidsym verify --module examples/rotation_notes.py --certificates FOLDER EXTRA``
    in this process (no repair search: a certificate does not read it)."""
    return main(["verify", "--module", str(MODULE), "--quiet", "--jobs", "1", "--no-repairs",
                 "--certificates", str(folder), *extra])


def _certcheck(*args) -> subprocess.CompletedProcess:
    """``python -m certcheck ARGS`` in its own process, as a user runs it from the repo root
    (the checkout's certcheck/src on the path, nothing of rigidsym's)."""
    env = dict(os.environ, PYTHONPATH=str(ROOT / "certcheck" / "src"))
    return subprocess.run([sys.executable, "-m", "certcheck", *map(str, args)], cwd=ROOT,
                          env=env, capture_output=True, text=True, check=False, timeout=120)


@pytest.fixture(scope="module")
def certs(tmp_path_factory) -> Path:
    """The example's certificates, written and re-checked by verify bound to the text and
    the reading (the run must pass: every certificate CHECKED)."""
    folder = tmp_path_factory.mktemp("rotation_notes")
    rc = _verify(folder, "--book", str(TEXT), "--reading", str(READING))
    assert rc == 0
    return folder


def _lines(path: Path) -> set[tuple]:
    """The ``[[let]]`` lines of a reading file, as the certificate writes them: ``("kind",
    glyph, kind)``, ``("cpm", glyph, of)`` or ``("model", glyph, latex, where, cites)``
    (spaces removed from LaTeX), with the ids each serves."""
    kinds = {"unit vector": "unit", "angle": "angle", "rotation": "rotation",
             "scalar": "free", "3-vector": "free"}
    out = set()
    for entry in tomllib.loads(path.read_text(encoding="utf-8")).get("let", []):
        text = entry["let"]
        name, colon, kind = text.partition(":")
        if colon and "=" not in name:
            out.add(("kind", name.strip().removesuffix("(t)"), kinds.get(kind.strip(), kind)))
            continue
        name, _, latex = text.partition("=")
        latex = "".join(latex.split())
        if latex.startswith("\\mathrm{CPM}("):
            out.add(("cpm", name.strip(), latex[len("\\mathrm{CPM}("):-1]))
        else:
            out.add(("model", name.strip(), latex, entry.get("where", ""),
                     entry.get("cites", "")))
    return out


def _cert_lines(cert: dict) -> set[tuple]:
    out = set()
    for s in cert.get("symbols", []) + [s for r in cert["relations"]
                                        for s in r.get("symbols", [])]:
        if "kind" in s:
            out.add(("kind", s["glyph"], s["kind"]))
        elif "cpm_of" in s:
            out.add(("cpm", s["glyph"], "".join(s["cpm_of"].split())))
        else:
            out.add(("model", s["glyph"], "".join(s["latex"].split()), s.get("model", ""),
                     s.get("printed_as", "")))
    return out


def test_every_certificate_checked_by_certcheck_as_a_user_runs_it(certs):
    """python -m certcheck --book TEXT --reading READING DIR: exit 0, a CHECKED line per id
    of the reading, the manifest bound to the text's and the reading's SHA-256."""
    proc = _certcheck("--book", TEXT.relative_to(ROOT), "--reading",
                      READING.relative_to(ROOT), certs, "--quiet")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    checked = re.findall(r"^CHECKED \((\S+)\) (\S+)", proc.stdout, re.M)
    assert sorted(i for i, _ in checked) == sorted(IDS)
    assert dict(checked)["axis:rodrigues-sign"] == "does-not-hold"
    assert "NOT READ" not in proc.stdout and "FAILED" not in proc.stdout
    manifest = json.loads((certs / "MANIFEST.json").read_text())
    assert manifest["book_sha256"] == hashlib.sha256(TEXT.read_bytes()).hexdigest()
    assert manifest["reading_sha256"] == hashlib.sha256(READING.read_bytes()).hexdigest()
    cert = json.loads((certs / "axis_rodrigues-sign.json").read_text())
    assert [r["evidence"]["type"] for r in cert["relations"]][0] == "counterexample"


def test_no_line_of_the_chapters_reading(certs):
    """Each certificate's table is exactly the reader's reading's lines; none of the lines
    the chapter's reading gives and the reader's does not (the chapter's Q, cited from
    (2.49), or its quaternion form) is in any of them."""
    mine, chapter = _lines(READING), _lines(CHAPTER_READING)
    only_chapter = chapter - mine
    assert any(x[1] == "\\mathbf{Q}" for x in only_chapter)  # a leak would be seen
    for eq_id in IDS:
        cert = json.loads((certs / (eq_id.replace(":", "_") + ".json")).read_text())
        lines = _cert_lines(cert)
        assert lines == mine, (eq_id, lines ^ mine)
        assert not lines & only_chapter, eq_id


def test_a_kind_changed_fails_naming_the_id(certs, tmp_path):
    """The unit vector e made a free 3-vector in one certificate (its atom group and its
    line alike, the manifest rewritten to match): certcheck rejects it, naming the id,
    and the others stay CHECKED."""
    folder = tmp_path / "forged"
    shutil.copytree(certs, folder)
    path = folder / "axis_trace.json"
    cert = json.loads(path.read_text())
    for group in cert["atoms"]:
        if group["group"] == "e":
            group["kind"] = "free"
    for line in cert["symbols"]:
        if line["glyph"] == "\\mathbf{e}":
            line["kind"] = "free"
    path.write_text(json.dumps(cert, indent=1) + "\n")
    manifest = json.loads((folder / "MANIFEST.json").read_text())
    manifest["certificates"][path.name] = hashlib.sha256(path.read_bytes()).hexdigest()
    (folder / "MANIFEST.json").write_text(json.dumps(manifest, indent=1) + "\n")
    proc = _certcheck("--book", TEXT, "--reading", READING, folder, "--quiet")
    assert proc.returncode == 1
    failed = [x for x in proc.stdout.splitlines() if x.startswith("FAILED")]
    assert len(failed) == 1 and failed[0].startswith("FAILED axis_trace.json: (axis:trace)")
    assert "\\mathbf{e}" in failed[0] and "not the reading's" in failed[0], failed
    assert proc.stdout.count("CHECKED (") == len(IDS) - 1


def test_verify_exits_1_when_certcheck_is_missing(tmp_path, monkeypatch, capsys):
    """certcheck nowhere (neither the checkout's certcheck/src nor installed): the
    certificates are written, nothing is re-checked, and the run fails, saying so."""
    from rigidsym.checking.certifying import certificates

    monkeypatch.setattr(certificates, "_checker_path", lambda: None)
    rc = _verify(tmp_path, "--book", str(TEXT), "--reading", str(READING))
    out, err = capsys.readouterr()
    assert rc == 1
    assert "certcheck not found, not re-checked" in err
    assert "certificates NOT CHECKED by certcheck (certcheck not found)" in out
    assert len(list(tmp_path.glob("axis_*.json"))) == len(IDS)


def test_verify_exits_1_when_a_certificate_is_not_checked(tmp_path, capsys):
    """The text without its reading (a copy with no TEXT.reading.toml beside it, no
    --reading): certcheck proves the certificates but binds none to a reading, so none is
    CHECKED, and the bound run fails, naming what certcheck said."""
    text = tmp_path / "notes.md"
    shutil.copy(TEXT, text)
    rc = _verify(tmp_path / "certs", "--book", str(text))
    out, err = capsys.readouterr()
    assert rc == 1
    assert f"NOT CHECKED: certcheck CHECKED 0 of {len(IDS)} (exit" in err, err
    assert "certificates NOT CHECKED by certcheck" in out


@pytest.mark.parametrize("args, words", [
    (["--reading", "no-such.toml"], "--reading: expected a reading file"),
    (["--reading", str(TEXT)], "--reading: reading"),
])
def test_bad_reading_is_named(tmp_path, capsys, args, words):
    rc = _verify(tmp_path, *args)
    assert rc == 2 and words in capsys.readouterr().err


def test_reading_refused_for_the_books_ids(tmp_path, capsys):
    rc = main(["verify", "3.13", "--quiet", "--certificates", str(tmp_path), "--reading",
               str(READING)])
    assert rc == 2 and "the run holds the book's ids too (3.13)" in capsys.readouterr().err


def test_locate_finds_a_readers_id_by_its_tag():
    """certcheck's locator: a reader's id tagged \\tag{ns:name} or (ns:name), the tag cut
    off; an id that is only a prefix of another's tag is not found there."""
    sys.path.insert(0, str(ROOT / "certcheck" / "src"))
    from certcheck.book import BookError, locate

    text = "$$\nx = y \\tag{my:one}\n$$\n\n$$ a = b \\quad (my:two) $$\n"
    assert locate(text, "my:one") == "x = y"
    assert locate(text, "my:two") == "a = b"
    with pytest.raises(BookError, match="printed in 0 places"):
        locate(text, "my:on")
