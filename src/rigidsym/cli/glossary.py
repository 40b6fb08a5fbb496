"""``rigidsym glossary [WORD]``: the words of the verdicts and reports, explained."""

from __future__ import annotations

import re
import sys
import textwrap

__all__ = ["add_arguments", "run", "HELP", "EXAMPLES"]

HELP = "explain the words used (verdict, member, model, ...)"
EXAMPLES = """\
  rigidsym glossary                   every word
  rigidsym glossary parametrisation   one word (stereographic finds it too)"""


def add_arguments(p) -> None:
    """Arguments of ``rigidsym glossary``."""
    p.add_argument("word", nargs="?",
                   help="a word such as verdict, member, counterexample or random-exact "
                        "(default: all of them)")


def _plain(markdown: str) -> str:
    """Markdown links, emphasis and code marks dropped: terminal text."""
    s = re.sub(r"\[([^\]]+)\]\([^)]*\)", r"\1", markdown)
    return s.replace("**", "").replace("`", "")


def run(args) -> int:
    """Print the glossary, or the entries for one word."""
    from rigidsym.report.glossary import entries, lookup
    from rigidsym.report.show import output_width

    found = lookup(args.word) if args.word else list(entries().items())
    if not found:
        print(f"rigidsym: error: word: {args.word!r} is not in the glossary (known: "
              + ", ".join(entries()) + "; rigidsym glossary prints them all)", file=sys.stderr)
        return 2
    width = min(output_width(), 100)
    for k, (word, body) in enumerate(found):
        if k:
            print()
        print(word.upper())
        for para in _plain(body).split("\n\n"):
            print(textwrap.fill(" ".join(para.split()), width=width, initial_indent="  ",
                                subsequent_indent="  "))
    return 0
