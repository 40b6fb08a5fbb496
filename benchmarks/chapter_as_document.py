"""The chapter as a document: ``rigidsym check`` on the chapter's page with its reading,
held against ``rigidsym verify``'s recorded verdicts.

Two paths decide the chapter: ``rigidsym verify`` (each id declared in ``derivations/*.py``,
its verdict in ``generated/report/chapter3.json``) and ``rigidsym check FILE --reading``
(each displayed relation of the page read from its LaTeX, its symbols from the reading file
``derivations/angeles-chapter3.reading.toml``). A relation carries the page's printed label
(``(3.13)``), which is the id ``verify`` gives it. Measured:

- the page's relations: how many are decided (verified, does not hold, a definition) and
  why each other one is not (its reason, grouped);
- per id that both paths decide: whether the verdicts agree. An id *agrees* when every
  relation of the page under its label is decided and none contradicts ``verify``'s verdict
  (``verified``: none does not hold; ``does-not-hold``: one does not hold; ``definition``:
  each a definition or verified); it *disagrees* when a decided relation contradicts it
  (listed with both verdicts) or, for a ``verify`` slip, every relation is decided and holds;
  it is *partly decided* when some relations are decided, none contradicting, others not.
- the reading's lines the document path does not give a relation, each with why.

The page is never shipped (``../shared/book/angeles-chapter3.md`` beside the checkout); the
verdict store (``RIGIDSYM_CACHE``) makes a re-run re-check only what changed. The machine is
recorded with the figures (cpu, cores, load average, commit).

Usage (from the repository root)::

    python benchmarks/chapter_as_document.py [--book PATH] [--timeout S]
        [--out benchmarks/results/chapter_as_document.json]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import time
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT.parent / "shared" / "book" / "angeles-chapter3.md"
READING = ROOT / "derivations" / "angeles-chapter3.reading.toml"
REPORT = ROOT / "generated" / "report" / "chapter3.json"
OUT = ROOT / "benchmarks" / "results" / "chapter_as_document.json"
DECIDED = ("verified", "does-not-hold", "definition")
#: a reason not decided -> its group (the first that matches)
_GROUPS = (
    (r"^undeclared: ", "a symbol the reading does not declare for the label"),
    (r"which the document defines only later", "uses a symbol the reading does not declare "
                                               "for the label, which the page defines later"),
    (r"whose line of the reading for .* is not given", "uses a symbol whose reading line is "
                                                       "not given (listed with why)"),
    (r"are read as one glyph", "two reading lines read as one glyph"),
    (r"^--latex: the numeric cross-check does not evaluate", "the numeric cross-check does not "
                                                             "evaluate a construct"),
    (r"^--(let|latex)\b", "a declaration check_latex refuses"),
    (r"^a construct not read", "LaTeX the reader does not read"),
    (r"^an elision", "an elision"),
    (r"^a side is empty", "a side is empty (a display split by prose)"),
    (r"approximation|inequ|membership|signature|a map", "not a relation with a verdict"),
)


def machine() -> dict:
    """The machine the figures were measured on (test_command.py's host), its load and the
    commit."""
    from test_command import host

    commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True,
                            text=True).stdout.strip()
    return {**host(), "load": [round(x, 2) for x in os.getloadavg()], "commit": commit}


def group(rec: dict) -> str:
    """The group of a relation not decided (its verdict when undecided or by convention)."""
    if rec["verdict"] in ("undecided", "convention-dependent"):
        return rec["verdict"]
    reason = rec.get("reason") or rec.get("method") or ""
    for pat, name in _GROUPS:
        if re.search(pat, reason):
            return name
    return reason.split(":")[0][:80] or "not decided"


def compare(records: list[dict], verify: dict[str, str]) -> dict:
    """Each id of ``verify`` held against the page's relations under its label."""
    by_label: dict[str, list[dict]] = {}
    for rec in records:
        if rec["label"]:
            by_label.setdefault(rec["label"], []).append(rec)
    agree, disagree, partly, undecided = [], [], [], []
    for eq_id, v in verify.items():
        recs = by_label.get(eq_id, [])
        got = [r["verdict"] for r in recs]
        decided = [g for g in got if g in DECIDED]
        if not decided:
            undecided.append(eq_id)
            continue
        all_decided = len(decided) == len(got)
        if v == "does-not-hold":
            bad = all_decided and "does-not-hold" not in decided
            ok = "does-not-hold" in decided
        elif v == "verified":
            bad = "does-not-hold" in decided
            ok = all_decided and not bad
        else:  # a definition: the page's relations define or hold
            bad = "does-not-hold" in decided
            ok = all_decided and not bad
        row = {"id": eq_id, "verify": v, "document": got,
               "lines": [r["line"] for r in recs]}
        if bad:
            row["relations"] = [{"line": r["line"], "verdict": r["verdict"],
                                 "counterexample": r.get("counterexample"),
                                 "reason": r.get("reason")} for r in recs]
            row["latex"] = [r["latex"] for r in recs]  # printed, never recorded (the page's)
            disagree.append(row)
        elif ok:
            agree.append(eq_id)
        else:
            partly.append(row)
    page_only = sorted(set(by_label) - set(verify))
    return {"agree": agree, "disagree": disagree, "partly": partly,
            "undecided": undecided, "labels_not_ids": page_only}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--book", type=Path, default=BOOK)
    ap.add_argument("--reading", type=Path, default=READING)
    ap.add_argument("--timeout", type=float, default=None,
                    help="CPU seconds per relation (default: check_latex's)")
    ap.add_argument("--out", type=Path, default=OUT)
    args = ap.parse_args(argv)
    if not args.book.is_file():
        print(f"the chapter is not at {args.book} (never shipped)", file=sys.stderr)
        return 2
    sys.path.insert(0, str(ROOT / "src"))
    from rigidsym.documents import check_document

    host = machine()
    t0, c0 = time.perf_counter(), time.process_time()
    res = check_document(args.book, reading=args.reading,
                         timeout="default" if args.timeout is None else args.timeout,
                         progress=lambda line: print(line, file=sys.stderr, flush=True))
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    verify = {e["id"]: e["verdict"] for e in json.loads(REPORT.read_text())["equations"]}
    cmp = compare(res.records, verify)
    counts = res.counts()
    decided = sum(counts[v] for v in DECIDED)
    not_decided = Counter(group(r) for r in res.records if r["verdict"] not in DECIDED)
    out = {
        "what": "rigidsym check on the chapter's page with its reading, against verify",
        "machine": host | {"load_after": [round(x, 2) for x in os.getloadavg()]},
        "wall s": round(wall, 1), "cpu s": round(cpu, 1), "from store": res.stored,
        "relations": len(res.records), "displays": len(res.document.displays),
        "counts": counts, "decided": decided,
        "not decided": dict(not_decided.most_common()),
        "ids": len(verify),
        "ids decided": len(verify) - len(cmp["undecided"]),
        "agreeing": len(cmp["agree"]), "disagreeing": len(cmp["disagree"]),
        "partly decided": len(cmp["partly"]), "ids not decided": len(cmp["undecided"]),
        "disagreements": [{k: v for k, v in row.items() if k != "latex"}
                          for row in cmp["disagree"]],
        "agree": cmp["agree"], "partly": cmp["partly"],
        "undecided ids": cmp["undecided"], "labels not ids": cmp["labels_not_ids"],
        "reading lines not given": len(res.omitted),
        "omitted": res.omitted,
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(out, indent=1, ensure_ascii=False) + "\n")
    print(f"{out['relations']} relations in {out['displays']} displays: {decided} decided "
          f"({', '.join(f'{counts[v]} {v}' for v in DECIDED)})")
    for name, n in not_decided.most_common():
        print(f"  not decided, {name}: {n}")
    print(f"ids: {out['ids decided']} of {len(verify)} decided by the page: "
          f"{out['agreeing']} agree, {out['disagreeing']} disagree, "
          f"{out['partly decided']} partly decided")
    for row in cmp["disagree"]:
        print(f"  DISAGREE ({row['id']}): verify {row['verify']}, document {row['document']}")
        for rel, latex in zip(row["relations"], row["latex"], strict=True):
            print(f"    line {rel['line']}: {latex}  {rel['verdict']}")
    print(f"reading lines not given to a relation: {len(res.omitted)}")
    print(f"{wall:.0f} s wall, {cpu:.0f} s CPU, {res.stored} from the store; "
          f"{host['cpu']}, {host['cores']} cores, load {host['load']}; wrote {args.out}")
    return 1 if cmp["disagree"] else 0


if __name__ == "__main__":
    raise SystemExit(main())
