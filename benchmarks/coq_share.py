"""How many of the chapter's verified identities Coq proves: each verified id's
certificate exported (:func:`rigidsym.checking.certifying.certificates.certificate`), written as a
Coq file (:func:`rigidsym.checking.certifying.coq.coq_file`) and checked by ``coqc`` with a time
limit
per
id. One JSON line per id (``id``, ``outcome`` = proved / failed / timeout / no-file,
``seconds`` of coqc wall time, ``why``) is appended to ``--out`` as it is measured, so a run
cut short keeps what it measured; a summary is printed at the end.

Usage (from the repository root; needs Debian's ``coq``)::

    python benchmarks/coq_share.py [--timeout 60] [--out coq_share.jsonl] [ID ...]

With no ids, every verified id of the chapter, in book order; ids already in ``--out`` are
skipped (``--again`` measures them again). On the shared 2-core machine the times depend
on the load; the load average is recorded with each line.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import time
from pathlib import Path


def _measure(eq_id: str, timeout: float) -> dict:
    from rigidsym.checking.certifying.certificates import certificate
    from rigidsym.checking.certifying.coq import NoProof, prove
    from rigidsym.registry.declarations import REGISTRY

    cert = certificate(eq_id, REGISTRY[eq_id].expected)
    kinds = [r["evidence"]["type"] for r in cert["relations"]]
    t0 = time.perf_counter()
    try:
        ok, msg = prove(cert, timeout=timeout)
    except NoProof as e:
        return {"outcome": "no-file", "why": str(e), "evidence": kinds}
    except subprocess.TimeoutExpired:
        return {"outcome": "timeout", "seconds": round(time.perf_counter() - t0, 1),
                "evidence": kinds}
    out = {"outcome": "proved" if ok else "failed",
           "seconds": round(time.perf_counter() - t0, 1), "evidence": kinds}
    if not ok:
        out["why"] = msg[-300:]
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("ids", nargs="*")
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--out", default="coq_share.jsonl")
    ap.add_argument("--again", action="store_true")
    args = ap.parse_args()
    from rigidsym.registry.declarations import REGISTRY, book_ids, load_all

    load_all()
    ids = args.ids or [i for i in book_ids() if REGISTRY[i].expected == "verified"]
    path = Path(args.out)
    done = set()
    if path.exists() and not args.again:
        done = {json.loads(line)["id"] for line in path.read_text().splitlines() if line}
    for i in ids:
        if i in done:
            continue
        row = {"id": i, **_measure(i, args.timeout), "load": os.getloadavg()[0]}
        with path.open("a") as f:
            f.write(json.dumps(row) + "\n")
        print(json.dumps(row), flush=True)
    rows = [json.loads(line) for line in path.read_text().splitlines() if line]
    counts: dict = {}
    for r in rows:
        counts[r["outcome"]] = counts.get(r["outcome"], 0) + 1
    print(f"{len(rows)} ids measured: {counts}")


if __name__ == "__main__":
    main()
