"""Run every corpus entry through ``rigidsym.check_latex`` with its book's table and write
what it answered to ``baseline.json`` (today's results, recorded before
the reader is changed). Run: ``python tests/data/latex_corpus/record.py [IDS...]``."""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import corpus  # noqa: E402

EXIT = {"verified": 0, "definition": 0, "does-not-hold": 1, "undecided": 3, "bad-input": 2}


def run(entry: dict) -> dict:
    """What ``rigidsym check --latex`` answers for one entry: verdict, exit code, message.

    The entry is read with its book's table (``--let`` lines) and, where the package ships
    one, the book's ``--notation`` (what no ``NAME: KIND`` line can say: Murray-Li-Sastry's
    ``\\hat\\omega`` a skew matrix, Siciliano's and Spong's ``c_\\vartheta``, ``s_{12}``);
    the table's lines win over the notation's, as a ``--let`` does."""
    import rigidsym
    from rigidsym.latex.notations import NOTATIONS
    from rigidsym.registry import declarations as registry

    lets = corpus.lets_of(entry)
    book = entry["book"]["key"]
    t0 = time.perf_counter()
    try:
        r = rigidsym.check_latex(entry["latex"], let=lets, repairs=False,
                                 notation=book if book in NOTATIONS else None)
        out = {"verdict": r.verdict, "message": (r.detail or r.cause or "")[:300],
               "counterexample": bool(r.counterexample)}
    except ValueError as exc:  # LatexError and BadInput
        out = {"verdict": "bad-input", "message": str(exc).splitlines()[0][:300],
               "counterexample": False, "construct": getattr(exc, "construct", "declaration")}
    except Exception as exc:  # a crash is recorded as what it is
        out = {"verdict": "crash", "message": f"{type(exc).__name__}: {exc}"[:300],
               "counterexample": False}
    finally:
        registry.forget_module("rigidsym.latex.statement")
    out["exit"] = EXIT.get(out["verdict"], 4)
    out["seconds"] = round(time.perf_counter() - t0, 2)
    return out


def main(ids: list[str]) -> None:
    path = HERE / "baseline.json"
    old = json.loads(path.read_text()) if path.exists() else {}
    for e in corpus.entries():
        if ids and e["id"] not in ids:
            continue
        old[e["id"]] = run(e)
        print(e["id"], old[e["id"]]["verdict"], old[e["id"]]["message"][:100], flush=True)
    path.write_text(json.dumps(dict(sorted(old.items())), indent=1, ensure_ascii=False) + "\n")


if __name__ == "__main__":
    main(sys.argv[1:])
