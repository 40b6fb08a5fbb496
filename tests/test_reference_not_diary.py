"""The code, the tests and the docs say what is, in the present tense: no reference to the
project's tracker ("issue N") and no round of work ("wave N") in src/, tests/, docs/,
derivations/, examples/ or benchmarks/. The history of the project is CHANGELOG.md's, and the
dated runs of the benchmarks are benchmarks/RESULTS.md's and benchmarks/results/' records.

Citations of other projects' trackers stay, each spelled as a citation of that project and
listed in :data:`CITATIONS`. docs/api.md is generated from the docstrings of src/, which this
test reads at their source.
"""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TREES = ("src", "tests", "docs", "derivations", "examples", "benchmarks")

#: files that keep history by design, or are generated from what this test reads
EXCLUDED = {ROOT / "docs" / "CHANGELOG.md", ROOT / "CHANGELOG.md", ROOT / "docs" / "api.md",
            ROOT / "benchmarks" / "RESULTS.md", Path(__file__).resolve()}
#: folders of dated records
EXCLUDED_DIRS = {ROOT / "benchmarks" / "results"}

#: citations of another project's tracker, exactly as written where they are cited
CITATIONS = ("box2d's GitHub issue 1086",)

#: a reference to this project's tracker, or a round of work, also broken over two lines
#: (of a comment or docstring: "issue" at the end of one, the number at the start of the next)
_BREAK = r"(?: |-|\n[ \t]*(?:#:?|\*|//)?[ \t]*)"
DIARY = re.compile(rf"\bissues?{_BREAK}#?\d+|\bwave{_BREAK}\d+\b|\b(?:first|second|third|"
                   rf"fourth|fifth|sixth|previous|last){_BREAK}session\b", re.IGNORECASE)


def _text_files():
    for tree in TREES:
        for path in sorted((ROOT / tree).rglob("*")):
            if (not path.is_file() or "__pycache__" in path.parts or path in EXCLUDED
                    or any(d in path.parents for d in EXCLUDED_DIRS)
                    or path.suffix in (".pyc", ".so", ".o", ".png", ".gz", ".pdf")):
                continue
            data = path.read_bytes()
            if b"\0" in data:
                continue
            try:
                yield path, data.decode("utf-8")
            except UnicodeDecodeError:
                continue


def diary_lines(text: str) -> list[tuple[int, str]]:
    """``(line number, line)`` of each line of ``text`` where a reference to this project's
    tracker or a round of work starts, the :data:`CITATIONS` of other projects left out."""
    for c in CITATIONS:
        text = text.replace(c, " " * len(c))
    lines = text.split("\n")
    out = []
    for m in DIARY.finditer(text):
        n = text.count("\n", 0, m.start()) + 1
        if not out or out[-1][0] != n:
            out.append((n, lines[n - 1].strip()))
    return out


def test_the_pattern_finds_tracker_references_and_waves_and_spares_citations():
    found = [n for n, _ in diary_lines("a (issue 37)\nIssue 52's rule\nissues #3 and 4\n"
                                       "before wave 11\nthe wave-6 merge\n"
                                       "box2d's GitHub issue 1086\na wave of 3 rows\n"
                                       "tissue 5\nbefore issue\n  # 21 in a comment\n"
                                       "issue 3 and issue 4\n(third session)\n"
                                       "the session's wheel fixture\n")]
    assert found == [1, 2, 3, 4, 5, 9, 11, 12]


def test_no_tracker_reference_or_round_of_work_in_src_tests_or_docs():
    hits = [f"{path.relative_to(ROOT)}:{n}: {line[:120]}"
            for path, text in _text_files() for n, line in diary_lines(text)]
    assert not hits, ("say what is, in the present tense (history goes in CHANGELOG.md):\n"
                      + "\n".join(hits))
