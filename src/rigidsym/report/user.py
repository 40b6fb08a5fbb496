"""User reports: ``rigidsym report --module M --out DIR`` writes ``DIR/<M>.{md,json,html}``."""

from __future__ import annotations

from pathlib import Path

from rigidsym.checking.runner import run_checks
from rigidsym.core.files import write_atomic
from rigidsym.core.progress import Reporter
from rigidsym.registry.declarations import select
from rigidsym.registry.usermodules import load_many
from rigidsym.report.html import to_html
from rigidsym.report.markdown import to_markdown
from rigidsym.report.record import to_json, transcription_extra

__all__ = ["write_user_report"]


def certified(results, directory) -> dict:
    """Write the results' certificates into ``directory``, re-check them with certcheck,
    say so on stderr, and return ``{id: certificate field}`` for the reports
    (``rigidsym report --certificates DIR``)."""
    import sys

    from rigidsym.checking.export import certificate_field, certify_line, export

    done = export(results, directory, progress=False)
    print(certify_line(done, directory), file=sys.stderr)
    return {r.id: certificate_field(done, r.id) for r in results}


def write_user_report(modules, out: Path, jobs: int = 1, cache: bool = False,
                      certificates: Path | None = None) -> int:
    """``rigidsym report --module M --out DIR``: ``DIR/<M>.{md,json,html}``.

    The same Markdown, JSON and HTML as the chapter's, titled by the module and named after
    it (several modules: one set of files each).

    ``cache`` reads and stores results in the verdict cache (the files are the same).
    ``certificates``: a folder for the verdicts' certificates, re-checked by certcheck; the
    Markdown and HTML then say how each verdict is certified.

    Returns:
        The exit code: 1 when a computed verdict differs from the declared expectation.
    """
    code = 0
    for um in load_many(modules):
        with Reporter(f"rigidsym report --module {um.title}") as rep:
            # the files show no expanded strings: verify's stored results serve
            results = run_checks(select(None, None, [um.name]), jobs=jobs, progress=True,
                                 cache=cache, reporter=rep, extra=transcription_extra(),
                                 expanded=False)
        title, source = f"{um.title} checked: verdicts", f"the user module {um.title}"
        cert = certified(results, certificates) if certificates else None
        files = {f"{um.title}.md": to_markdown(results, title=title, source=source,
                                               certified=cert),
                 f"{um.title}.json": to_json(results, timings=False),
                 f"{um.title}.html": to_html(results, title=title, source=source,
                                             certified=cert)}
        for name, text in files.items():
            write_atomic(out / name, text)
        print(f"wrote {', '.join(str(out / n) for n in files)}")
        code |= any(r.verdict != r.expected for r in results)
    return int(code)
