"""The certificates kept in the verdict store (``rigidsym verify --certificates``): a folder
written from the store holds the bytes a fresh export makes; a corrupt or foreign entry is
ignored with a warning and made again; ``--no-cache`` neither reads nor writes; the key
follows the verdict and the members' statuses the certificate reads."""

from __future__ import annotations

import pytest

from rigidsym.checking import export, verdict_cache
from rigidsym.checking.certifying import certificates
from rigidsym.checking.verdict_cache import VerdictCacheWarning
from rigidsym.cli import main

#: a verified id (cofactor evidence) and a does-not-hold (a counterexample)
IDS = ["3.13", "3.96e"]


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path / "cache"))
    return tmp_path / "cache"


def _export(folder, *extra) -> dict:
    assert main(["verify", *IDS, "--quiet", "--jobs", "1", "--certificates", str(folder),
                 *extra]) == 0
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def _entries(cache) -> list:
    return sorted(cache.rglob("*.certificate.json"))


def test_a_folder_from_the_store_is_the_folder_made_anew(cache, tmp_path, monkeypatch):
    anew = _export(tmp_path / "anew", "--no-cache")
    assert _entries(cache) == []                 # --no-cache stores nothing
    made = _export(tmp_path / "made")
    assert len(_entries(cache)) == len(IDS)
    stamps = [p.stat().st_mtime_ns for p in _entries(cache)]

    def made_again(*args):
        raise AssertionError(f"made again: {args[0]}")
    monkeypatch.setattr(export, "certificate_or_reason", made_again)
    monkeypatch.setattr(certificates, "certificate_or_reason", made_again)
    stored = _export(tmp_path / "stored")
    assert [p.stat().st_mtime_ns for p in _entries(cache)] == stamps   # read, not rewritten
    assert stored == made == anew
    assert set(made) == {"3.13.json", "3.96e.json", "MANIFEST.json", "SKIPPED.txt"}


def test_a_corrupt_entry_is_made_again_with_a_warning(cache, tmp_path):
    made = _export(tmp_path / "made")
    for e in _entries(cache):
        e.write_bytes(e.read_bytes()[:-20] + b"garbage")
    with pytest.warns(VerdictCacheWarning, match="certificate"):
        again = _export(tmp_path / "again")
    assert again == made


def test_a_foreign_entry_is_not_trusted(cache):
    key = "ab" * 32
    verdict_cache.store_certificate("3.96e", key, {"id": "3.96e"})
    with pytest.warns(VerdictCacheWarning, match="another key"):
        assert verdict_cache.read_certificate("3.13", key) is None
    assert verdict_cache.read_certificate("3.96e", key) == {"id": "3.96e"}
    assert verdict_cache.read_certificate("3.13", "cd" * 32) is None   # nothing stored


def test_the_key_follows_the_verdict_and_the_statuses(cache):
    main(["verify", "3.13", "--quiet"])          # registers the book
    k = verdict_cache.certificate_key
    base = k("3.13", "verified", [{"status": "holds"}])
    assert base == k("3.13", "verified", [{"status": "holds", "printed": "x"}])
    assert len({base, k("3.13", "does-not-hold", [{"status": "holds"}]),
                k("3.13", "verified", [{"status": "fails"}]),
                k("3.13", "verified", []), k("3.14", "verified", [{"status": "holds"}])}) == 5


def test_certcheck_over_processes_says_what_it_says_in_one(cache, tmp_path):
    """``certcheck --jobs 2`` (the export's) prints the same lines in the same order and
    exits as one process does, a failing certificate included."""
    import re
    import subprocess
    import sys
    from pathlib import Path

    folder = tmp_path / "certs"
    _export(folder)
    (folder / "3.13.json").write_text("{")      # a malformed certificate: FAILED
    src = Path(__file__).resolve().parents[1] / "certcheck" / "src"

    def run(jobs: int):
        p = subprocess.run([sys.executable, "-m", "certcheck", "--jobs", str(jobs), str(folder)],
                           capture_output=True, text=True, env={"PYTHONPATH": str(src)})
        return p.returncode, re.sub(r"\[[\d.]+ s\]|, [\d.]+ s", "", p.stdout)
    one, two = run(1), run(2)
    assert one == two and one[0] == 1 and "FAILED 3.13.json" in one[1], one
