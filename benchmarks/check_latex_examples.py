"""The worked counterexamples the pages quote, as the tool prints them.

Runs each command of :data:`EXAMPLES` (``rigidsym check ... --json``) and records its
argument list, exit code, verdict, the counterexample's symbols as printed (``text``, and
``cos``/``sin`` of an angle) and its repairs' edits, beside the machine and the commit.
docs/check-latex.md quotes them behind ``<!-- quote: check_latex_examples.json PATH -->``
markers, and the command it shows is the recorded one, word for word;
``tests/test_figures_traced.py`` checks both. A change of the reader, the counterexample
search or the printer that moves a quoted figure is re-recorded by running this again:

    python benchmarks/check_latex_examples.py --json benchmarks/results/check_latex_examples.json
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

from test_command import host

ROOT = Path(__file__).resolve().parents[1]

#: name -> the ``rigidsym check`` arguments (README.md's and docs/check-latex.md's command)
EXAMPLES = {
    "rodrigues_slip": [
        "check", "--latex",
        r"\mathbf{Q} = \mathbf{1} - \sin\phi\,\mathbf{E} + (1-\cos\phi)\mathbf{E}^2",
        "--let", r"\mathbf{e}: unit vector; \phi: angle",
        "--let", r"\mathbf{E} = \mathrm{CPM}(\mathbf{e})",
        "--let", r"\mathbf{Q} = \mathbf{e}\mathbf{e}^T + \cos\phi(\mathbf{1} - "
                  r"\mathbf{e}\mathbf{e}^T) + \sin\phi\,\mathbf{E}"],
}


def one(args: list[str]) -> dict:
    """Run ``rigidsym ARGS --json``; what the pages quote of its record."""
    p = subprocess.run([sys.executable, "-m", "rigidsym", *args, "--json"], cwd=ROOT,
                       capture_output=True, text=True, timeout=600)
    rec = json.loads(p.stdout)
    cx = rec.get("counterexample") or {}
    symbols = {}
    for s in cx.get("symbols", []):
        symbols[s["symbol"]] = {k: s[k] for k in ("text", "cos", "sin") if k in s}
    return {"argv": ["rigidsym", *args], "rc": p.returncode, "verdict": rec["verdict"],
            "counterexample": symbols,
            "repairs": [" and ".join(r["edits"]) for r in rec.get("repairs", [])]}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--json", type=Path, required=True)
    args = ap.parse_args(argv)
    doc = {"host": host(), "commit": subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT,
                                                   capture_output=True, text=True).stdout.strip(),
           "examples": {name: one(a) for name, a in EXAMPLES.items()}}
    args.json.parent.mkdir(parents=True, exist_ok=True)
    part = args.json.with_suffix(".part")
    part.write_text(json.dumps(doc, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    part.replace(args.json)
    print(json.dumps(doc["examples"], indent=1, ensure_ascii=False))
    return 0


if __name__ == "__main__":
    sys.exit(main())
