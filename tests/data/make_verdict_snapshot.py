"""Record verdict, method and Schwartz-Zippel failure bound per id and member (the chapter
and examples/rotation_identities.py) as tests/data/verdict_snapshot.json.

Run from the repository root: ``python tests/data/make_verdict_snapshot.py OUT.json``.
The committed snapshot was taken on the engine before python-flint; the test
``tests/test_verdict_snapshot.py`` holds the current engine to it (same verdicts, bounds
no higher).
"""

from __future__ import annotations

import json
import re
import sys

#: the failure bound as the zero test words it ("P(false zero) <= 1.2e-80")
_P = re.compile(r"P\(false zero\) <= ([0-9.eE+-]+)")
EXAMPLE = "examples/rotation_identities.py"


def bound(detail: str | None) -> float | None:
    """The largest failure bound named in ``detail`` (None for an exact method)."""
    found = _P.findall(detail or "")
    return max(float(x) for x in found) if found else None


def record(r) -> dict:
    """Verdict, method and bound of a result and of each of its members."""
    return {"verdict": r.verdict, "method": r.method, "bound": bound(r.detail),
            "members": [{"role": m["role"], "label": m["label"], "status": m["status"],
                         "method": m["method"], "bound": bound(m["detail"])}
                        for m in r.members]}


def snapshot(jobs: int = 2) -> dict:
    """Run the chapter and the example module; their records by id."""
    import rigidsym

    chapter = rigidsym.verify(jobs=jobs)
    example = rigidsym.verify(modules=[EXAMPLE], jobs=jobs)
    return {"chapter": {r.id: record(r) for r in chapter},
            EXAMPLE: {r.id: record(r) for r in example}}


if __name__ == "__main__":
    with open(sys.argv[1], "w", encoding="utf-8") as f:
        json.dump(snapshot(), f, indent=1, sort_keys=True)
