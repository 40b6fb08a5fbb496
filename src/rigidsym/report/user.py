"""User reports: ``rigidsym report --module M --out DIR`` writes ``DIR/<M>.{md,json,html}``."""

from __future__ import annotations

from pathlib import Path

from rigidsym._io import write_atomic
from rigidsym._progress import Reporter
from rigidsym.checking.deciding.registry import select
from rigidsym.checking.deciding.usermodules import load_many
from rigidsym.checking.runner import run_checks
from rigidsym.report.html import to_html
from rigidsym.report.markdown import to_markdown
from rigidsym.report.record import to_json, transcription_extra

__all__ = ["write_user_report"]


def write_user_report(modules, out: Path, jobs: int = 1, cache: bool = False) -> int:
    """``rigidsym report --module M --out DIR``: ``DIR/<M>.{md,json,html}``.

    The same Markdown, JSON and HTML as the chapter's, titled by the module and named after
    it (several modules: one set of files each).

    ``cache`` reads and stores results in the verdict cache (the files are the same).

    Returns:
        The exit code: 1 when a computed verdict differs from the declared expectation.
    """
    code = 0
    for um in load_many(modules):
        with Reporter(f"rigidsym report --module {um.title}") as rep:
            results = run_checks(select(None, None, [um.name]), jobs=jobs, progress=True,
                                 cache=cache, reporter=rep, extra=transcription_extra())
        title, source = f"{um.title} checked: verdicts", f"the user module {um.title}"
        files = {f"{um.title}.md": to_markdown(results, title=title, source=source),
                 f"{um.title}.json": to_json(results, timings=False),
                 f"{um.title}.html": to_html(results, title=title, source=source)}
        for name, text in files.items():
            write_atomic(out / name, text)
        print(f"wrote {', '.join(str(out / n) for n in files)}")
        code |= any(r.verdict != r.expected for r in results)
    return int(code)
