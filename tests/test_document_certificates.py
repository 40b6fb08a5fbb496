"""A document's verdicts certified (docs/check-documents.md, "Certificates"): ``rigidsym
check examples/notes.md --certificates DIR`` writes a certificate per decided relation,
bound to the document as its page and to its reading file, and certcheck, run as a user runs
it (``python -m certcheck --book examples/notes.md --reading examples/notes.reading.toml
DIR``), CHECKS each one; a certificate whose kind is changed fails naming its id; the
relation not decided is listed as not certified with its reason; the ids are the page's
labels, else its lines, which certcheck's locator finds."""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from rigidsym.cli import main

pytestmark = pytest.mark.xdist_group("document_certificates")  # module fixtures once

ROOT_ = Path(__file__).resolve().parents[1]
if str(ROOT_ / "certcheck" / "src") not in sys.path:  # the locator tests import certcheck
    sys.path.insert(0, str(ROOT_ / "certcheck" / "src"))  # (a distribution of its own)

ROOT = Path(__file__).resolve().parents[1]
NOTES = ROOT / "examples" / "notes.md"
READING = ROOT / "examples" / "notes.reading.toml"
#: the ids of the decided relations of examples/notes.md, with their verdicts
IDS = {"line:7": "definition", "line:13": "definition", "line:19.1": "verified",
       "line:19.2": "verified", "eq:rodrigues-E": "does-not-hold"}


def _certcheck(*args) -> subprocess.CompletedProcess:
    """``python -m certcheck ARGS`` in its own process from the repository root (the
    checkout's certcheck/src on the path, nothing of rigidsym's)."""
    env = dict(os.environ, PYTHONPATH=str(ROOT / "certcheck" / "src"))
    return subprocess.run([sys.executable, "-m", "certcheck", *map(str, args)], cwd=ROOT,
                          env=env, capture_output=True, text=True, check=False, timeout=120)


def _rewrite(folder: Path, path: Path, cert: dict) -> None:
    """Write ``cert`` to ``path`` and its SHA-256 into the folder's manifest (a forger's
    whole folder, consistent with itself)."""
    path.write_text(json.dumps(cert, indent=1) + "\n")
    manifest = json.loads((folder / "MANIFEST.json").read_text())
    manifest["certificates"][path.name] = hashlib.sha256(path.read_bytes()).hexdigest()
    (folder / "MANIFEST.json").write_text(json.dumps(manifest, indent=1) + "\n")


@pytest.fixture(scope="module")
def run(tmp_path_factory) -> tuple[Path, int, str]:
    """``rigidsym check examples/notes.md --certificates DIR`` in this process (from the
    repository root): the folder, the exit code and stderr."""
    folder = tmp_path_factory.mktemp("notes-certs")
    cwd = os.getcwd()
    os.chdir(ROOT)
    try:
        import contextlib
        import io

        err = io.StringIO()
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            rc = main(["check", "examples/notes.md", "--certificates", str(folder)])
    finally:
        os.chdir(cwd)
    return folder, rc, err.getvalue()


def test_every_decided_relation_certified_and_checked(run):
    """Exit 1 (the document's slip), one certificate per decided relation, and the line
    saying certcheck CHECKED 5 of 5 against the document and its reading."""
    folder, rc, err = run
    assert rc == 1, err
    assert sorted(p.name for p in folder.glob("*.json") if p.name != "MANIFEST.json") == \
        sorted(re.sub(r"[^A-Za-z0-9._-]", "_", i) + ".json" for i in IDS)
    assert "certcheck CHECKED 5 of 5 against examples/notes.md and " \
           "examples/notes.reading.toml" in err, err
    assert "not certified: examples/notes.md:31" in err and "approximation" in err
    skipped = (folder / "SKIPPED.txt").read_text()
    assert skipped.count("\n") == 1 and "examples/notes.md:31" in skipped


def test_certcheck_checks_each_as_a_referee(run):
    """python -m certcheck --book examples/notes.md --reading examples/notes.reading.toml
    DIR: exit 0, CHECKED with its verdict for every id, the manifest bound to both files."""
    folder, _, _ = run
    proc = _certcheck("--book", "examples/notes.md", "--reading",
                      "examples/notes.reading.toml", folder)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert dict(re.findall(r"^CHECKED \((\S+)\) (\S+)", proc.stdout, re.M)) == IDS
    assert "(the model's defined on the page, line 13)" in proc.stdout  # Q: the page's
    assert "a definition on the page" in proc.stdout
    manifest = json.loads((folder / "MANIFEST.json").read_text())
    assert manifest["book_sha256"] == hashlib.sha256(NOTES.read_bytes()).hexdigest()
    assert manifest["reading_sha256"] == hashlib.sha256(READING.read_bytes()).hexdigest()
    cert = json.loads((folder / "eq_rodrigues-E.json").read_text())
    assert [r["evidence"]["type"] for r in cert["relations"]][0] == "counterexample"
    assert [r["role"] for r in cert["relations"]][1:] == ["corrected"]


def test_a_kind_changed_fails_naming_the_id(run, tmp_path):
    """The unit vector e made a free 3-vector in one certificate (its group and its line,
    the manifest rewritten): certcheck fails it naming its id, the others stay CHECKED."""
    folder = tmp_path / "forged"
    shutil.copytree(run[0], folder)
    path = folder / "line_19.1.json"
    cert = json.loads(path.read_text())
    for group in cert["atoms"]:
        if group["group"] == "e":
            group["kind"] = "free"
    for line in cert["symbols"]:
        if line["glyph"] == "\\mathbf{e}":
            line["kind"] = "free"
    _rewrite(folder, path, cert)
    proc = _certcheck("--book", NOTES, "--reading", READING, folder, "--quiet")
    assert proc.returncode == 1
    failed = [x for x in proc.stdout.splitlines() if x.startswith("FAILED")]
    assert len(failed) == 1 and failed[0].startswith("FAILED line_19.1.json: (line:19.1)")
    assert "\\mathbf{e}" in failed[0], failed
    assert proc.stdout.count("CHECKED (") == len(IDS) - 1


@pytest.mark.parametrize("forge, words", [
    (lambda c: c.update(verdict="verified"),
     "the page prints the relation on line 7 as a definition"),
    (lambda c: c.update(book_latex=c["book_latex"].replace("\\triangleq", "=")),
     "book_latex is not the text printed"),
    (lambda c: c["symbols"].append({"glyph": "\\mathbf{E}", "kind": "rotation",
                                    "atoms": ["e_1", "e_2", "e_3"]}), "(line:7)"),
])
def test_a_class_a_text_or_a_line_of_its_own_fails(run, tmp_path, forge, words):
    """The definition of E said verified, its printed text changed, a line the reading and
    the page do not give: each fails naming the id."""
    folder = tmp_path / "forged"
    shutil.copytree(run[0], folder)
    path = folder / "line_7.json"
    cert = json.loads(path.read_text())
    forge(cert)
    _rewrite(folder, path, cert)
    proc = _certcheck("--book", NOTES, "--reading", READING, folder, "--quiet")
    assert proc.returncode == 1
    failed = [x for x in proc.stdout.splitlines() if x.startswith("FAILED")]
    assert len(failed) == 1 and "(line:7)" in failed[0] and words in failed[0], failed


def test_a_model_other_than_the_page_definition_fails(run, tmp_path):
    """Q read through the false relation of line 25 instead of its definition on line 13
    (the refuted relation made to hold): not a line the page gives Q there."""
    folder = tmp_path / "forged"
    shutil.copytree(run[0], folder)
    path = folder / "eq_rodrigues-E.json"
    cert = json.loads(path.read_text())
    for line in cert["symbols"]:
        if line["glyph"] == "\\mathbf{Q}":
            line["latex"] = ("\\mathbf{1} - \\sin\\phi\\,\\mathbf{E} + (1 - \\cos\\phi)\\,"
                             "\\mathbf{E}^2")
    _rewrite(folder, path, cert)
    proc = _certcheck("--book", NOTES, "--reading", READING, folder, "--quiet")
    assert proc.returncode == 1
    assert "FAILED eq_rodrigues-E.json: (eq:rodrigues-E)" in proc.stdout


#: a page of the forms the locator reads: a chain, an align with one label (it names both
#: relations of the display), a matrix's & and \\, a printed number, separators outside
#: \left ... \right and parentheses
PAGE = ("Text.\n\n$$\na = b = c\n$$\n\n\\begin{align}\nx &= y \\label{eq:x} \\\\\n"
        "&= z\n\\end{align}\n\n$$\n\\mathbf{A} = \\begin{bmatrix} 1 & 0 \\\\ 0 & 1 "
        "\\end{bmatrix} \\quad (3.9a)\n$$\n\n$$\n\\mathbf{a} = \\left\\{ x, y \\right\\}, "
        "b = \\left( c, d \\right) \\quad \\text{and} \\quad f = g(x, y)\n$$\n")


def test_locator_reads_labels_lines_and_chains():
    """certcheck.document: a chain is two relations on one line (line:L.1, line:L.2), an
    &= line relates to the right side before it, a display's one \\label names each of its
    relations, a printed (3.9a) its line, a matrix's & and \\\\ stay in it; an id naming
    two relations or none is an error naming it."""
    from certcheck.document import DocumentError, locate, printed

    got = {}
    for eq_id in ("line:4.1", "line:4.2", "line:8", "line:9", "label:3.9a"):
        k, rels = locate(PAGE, eq_id)
        got[eq_id] = printed(rels[k])
    assert got == {"line:4.1": "a = b", "line:4.2": "b = c", "line:8": "x = y",
                   "line:9": "y = z", "label:3.9a": "\\mathbf{A} = \\begin{bmatrix} 1 & 0 "
                   "\\\\ 0 & 1 \\end{bmatrix}"}
    for eq_id in ("line:4", "line:5", "eq:x", "eq:nowhere"):
        with pytest.raises(DocumentError, match=re.escape(f"({eq_id})")):
            locate(PAGE, eq_id)


@pytest.mark.parametrize("page", ["notes", "forms"])
def test_rigidsym_ids_are_certchecks(page, tmp_path):
    """rigidsym's id of each relation of a page is one certcheck's locator resolves to the
    same relation, printed as rigidsym read it (a label the page prints for that relation
    alone, else its line)."""
    from certcheck.document import locate, printed

    from rigidsym.documents import read_document
    from rigidsym.documents.certifying import document_ids

    path = NOTES if page == "notes" else tmp_path / "forms.md"
    if page == "forms":
        path.write_text(PAGE, encoding="utf-8")
    doc = read_document(path)
    text = path.read_text(encoding="utf-8")
    ids = document_ids(list(doc.relations), text, str(path))
    want = [*IDS, "line:31"] if page == "notes" else \
        ["line:4.1", "line:4.2", "line:8", "line:9", "label:3.9a", "line:17.1", "line:17.2",
         "line:17.3"]
    assert sorted(ids.values()) == sorted(want)
    for k, eq_id in ids.items():
        j, rels = locate(text, eq_id)
        assert printed(rels[j]) == doc.relations[k].latex, eq_id


def test_let_refused_with_certificates(tmp_path, capsys):
    """A --let names a symbol the reading file does not: certcheck could not hold the
    table to it, so the run refuses it (exit 2, naming the reading file)."""
    rc = main(["check", str(NOTES), "--certificates", str(tmp_path / "c"), "--let",
               "\\mathbf{a}: 3-vector"])
    assert rc == 2
    assert "declare each symbol in the reading file" in capsys.readouterr().err
