"""Writing one benchmark's section of ``RESULTS.md`` (shared by the benchmark scripts).

Each script owns the text between its markers (``<!-- name -->`` ... ``<!-- /name -->``);
``benchmarks/run.py`` carries such sections over when it rewrites the whole file.
"""

from __future__ import annotations

from pathlib import Path

from rigidsym.core.files import write_atomic


def write_section(path: Path, block: str, begin: str, end: str) -> None:
    """Replace the section of ``path`` from ``begin`` to ``end`` (the markers included) by
    ``block``, which holds both markers, or append it when ``path`` has none; atomically
    (a reader never sees half a file).

    Args:
        path: the results file (created if missing).
        block: the new section, from ``begin`` to ``end``, without a final newline.
        begin: its opening marker.
        end: its closing marker.
    """
    old = path.read_text(encoding="utf-8") if path.exists() else ""
    if begin in old and end in old:
        head, rest = old.split(begin, 1)
        new = head + block + rest.split(end, 1)[1]
    else:
        new = old.rstrip("\n") + "\n\n" + block + "\n"
    write_atomic(path, new)
