"""The repository as a reader meets it: no merge leftovers, a README of at
most 10 KB that says nothing twice, set-up first, and docs pages that are plain Markdown."""

from __future__ import annotations

import re
import subprocess
from collections import Counter
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"


def _tracked() -> list[str]:
    try:
        out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                             check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        pytest.skip("not a git checkout")
    return out.splitlines()


def test_no_merge_leftovers_in_the_repository():
    left = [f for f in _tracked() if f.endswith((".orig", ".rej", ".BACKUP", ".BASE"))
            or re.search(r"\.(LOCAL|REMOTE)\.\d+", f)]
    assert not left, left
    marks = [f for f in _tracked() if f.endswith((".md", ".py", ".toml"))
             and re.search(r"^(<<<<<<<|>>>>>>>) ", (ROOT / f).read_text(errors="replace"),
                           re.M)]
    assert not marks, f"conflict markers in {marks}"


def test_readme_at_most_8_kb_with_set_up_first():
    assert README.stat().st_size <= 8 * 1024, README.stat().st_size   # one screen or two
    heads = re.findall(r"^## (.+)$", README.read_text(), re.M)
    assert heads[0].startswith("Set-up"), heads


def _sentences(text: str) -> list[str]:
    text = re.sub(r"^    .*$", "", text, flags=re.M)          # commands, not prose
    text = " ".join(text.split())
    parts = re.split(r"(?<=[.!?])\s+(?=[A-Z`(\[])", text)
    return [p.strip() for p in parts if len(p.split()) >= 6]


def test_no_sentence_is_said_twice_in_the_readme():
    seen = Counter(_sentences(README.read_text()))
    twice = [s for s, n in seen.items() if n > 1]
    assert not twice, twice


def test_the_sentence_check_finds_a_repeated_sentence():
    text = ("Results are kept in the verdict cache for the next run. A table follows the "
            "progress bar on a terminal. Results are kept in the verdict cache for the next "
            "run.")
    seen = Counter(_sentences(text))
    assert [s for s, n in seen.items() if n > 1] == [
        "Results are kept in the verdict cache for the next run."]


def test_readme_links_resolve():
    for target in re.findall(r"\]\(([^)#]+)(?:#[^)]*)?\)", README.read_text()):
        if "://" not in target:
            assert (ROOT / target).exists(), target
