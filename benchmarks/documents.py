"""Benchmark ``rigidsym check FILE`` on a generated 100-relation Markdown document: cold
(an empty ``RIGIDSYM_CACHE``) and warm after one display is edited.

The document is ten sections of lecture notes on rotations about an axis, each with its own
symbols (``\\mathbf{e}_k``, ``\\phi_k``, ``\\mathbf{a}_k``) declared once in a reading file,
and ten relations: three definitions (``\\mathbf{E}_k \\triangleq \\mathrm{CPM}(\\mathbf{e}_k)``,
Rodrigues' ``\\mathbf{Q}_k``, ``\\mathbf{p}_k = \\mathbf{Q}_k \\mathbf{a}_k``), six identities
and one approximation (``\\approx``, not checked): 30 definitions, 60 identities of which
six are false (a flipped sign, a missing factor, a transposed factor, an index slip), and
10 not checkable, the mix the issue measured on real documents.

Measured, each run in a fresh process (imports count, as for a reader), with the modules'
bytecode compiled beforehand, as ``pip install`` leaves it (a first run on a scratch cache
compiles it where the environment forbids writing it beside the sources,
``PYTHONDONTWRITEBYTECODE``: else every process compiles sympy again, seconds the reader
never pays):

- ``cold``: ``rigidsym check doc.md --json`` on an empty cache: wall and CPU seconds of the
  process tree (``/usr/bin/time``), the check's own seconds, the counts, the slowest
  relations;
- ``warm``: the same after one display's relation is edited (the first slip corrected):
  only that relation is re-checked, the rest come from the verdict store.

The machine is shared: the load average is recorded before each run.

Usage (from the repository root)::

    python benchmarks/documents.py [--sections 10] [--out benchmarks/results/documents.json]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from test_command import host

ROOT = Path(__file__).resolve().parents[1]

#: each section's false identity (the true one it slips from, as an index into IDENTITIES)
SLIPS = {
    0: (5, r"\mathbf{Q}_{K} = \mathbf{1} - \sin\phi_{K}\,\mathbf{E}_{K} "
           r"+ (1 - \cos\phi_{K})\,\mathbf{E}_{K}^2"),  # a flipped sign
    2: (2, r"\mathrm{tr}(\mathbf{Q}_{K}) = 1 + \cos\phi_{K}"),  # a missing factor
    4: (3, r"\mathbf{E}_{K}^3 = \mathbf{E}_{K}"),  # a sign
    6: (4, r"\mathbf{Q}_{K}^T \mathbf{e}_{K} = \mathbf{E}_{K}\mathbf{e}_{K}"),  # a copy slip
    8: (1, r"\mathbf{p}_{K}^T \mathbf{p}_{K} = \mathbf{a}_{K}^T \mathbf{Q}_{K} \mathbf{a}_{K}"),
    9: (0, r"\mathbf{Q}_{K} \mathbf{e}_{K} = \mathbf{a}_{K}"),  # an index slip
}
#: each section's identities (true), K its number
IDENTITIES = [
    r"\mathbf{Q}_{K} \mathbf{e}_{K} = \mathbf{e}_{K}",
    r"\mathbf{p}_{K}^T \mathbf{p}_{K} = \mathbf{a}_{K}^T \mathbf{a}_{K}",
    r"\mathrm{tr}(\mathbf{Q}_{K}) = 1 + 2\cos\phi_{K}",
    r"\mathbf{E}_{K}^3 = -\mathbf{E}_{K}",
    r"\mathbf{Q}_{K}^T \mathbf{e}_{K} = \mathbf{e}_{K}",
    r"\mathbf{Q}_{K} = \mathbf{1} + \sin\phi_{K}\,\mathbf{E}_{K} "
    r"+ (1 - \cos\phi_{K})\,\mathbf{E}_{K}^2",
]


def document(sections: int = 10) -> tuple[str, str]:
    """The Markdown document and its reading file (TOML), ``10 * sections`` relations."""
    md = ["# Rotations about an axis: a generated set of notes", ""]
    toml = ["# The reading of doc.md (benchmarks/documents.py)", "[reading]", "format = 1",
            'page = "doc.md"', ""]
    for k in range(1, sections + 1):
        ids = list(IDENTITIES)
        if k - 1 in SLIPS:
            i, slip = SLIPS[k - 1]
            ids[i] = slip
        ids = [x.replace("{K}", f"{{{k}}}") for x in ids]
        e, phi, a = (rf"\mathbf{{e}}_{{{k}}}", rf"\phi_{{{k}}}", rf"\mathbf{{a}}_{{{k}}}")
        E, Q, p = (rf"\mathbf{{E}}_{{{k}}}", rf"\mathbf{{Q}}_{{{k}}}", rf"\mathbf{{p}}_{{{k}}}")
        for let in (f"{e}: unit vector", f"{phi}: angle", f"{a}: vector"):
            toml += ["[[let]]", f"let = '{let}'", f'where = "section {k}"', ""]
        md += [f"## Section {k}", "",
               f"A rotation through ${phi}$ about the unit vector ${e}$; its cross-product "
               "matrix is", "", "$$", rf"{E} \triangleq \mathrm{{CPM}}({e})", "$$", "",
               "and the rotation matrix, by Rodrigues' formula, is", "", "$$",
               rf"{Q} = {e}{e}^T + \cos{phi}\,(\mathbf{{1}} - {e}{e}^T) + \sin{phi}\,{E}",
               "$$", "", f"It leaves the axis fixed and rotates ${a}$ into", "", "$$",
               rf"{p} = {Q} {a} .", "$$", "", "so that", "", "$$",
               f"{ids[0]}, \\qquad {ids[1]} .", "$$", "",
               "Its trace and the powers of its cross-product matrix:", "",
               "\\begin{align}", f"{ids[2]} \\\\", f"{ids[3]}", "\\end{align}", "",
               "The transpose fixes the axis too, and in the matrix alone", "", "$$",
               f"{ids[4]}, \\quad {ids[5]} .", "$$", "",
               "For a small angle,", "", "$$", rf"{Q} \approx \mathbf{{1}} + {phi}\,{E}",
               "$$", ""]
    return "\n".join(md), "\n".join(toml)


def load() -> list[float]:
    """The 1, 5 and 15 minute load averages now."""
    return [round(x, 2) for x in os.getloadavg()]


def uptime() -> str:
    """``uptime``'s line (the load, as the machine's users see it)."""
    try:
        return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    except OSError:
        return ""


def timed(argv: list[str], env: dict) -> tuple[dict, dict]:
    """Wall and CPU seconds of ``argv`` (``/usr/bin/time``: the process and its children),
    the load before it, and its JSON output."""
    before, up = load(), uptime()
    with tempfile.NamedTemporaryFile("r", suffix=".time") as tf:
        p = subprocess.run(["/usr/bin/time", "-o", tf.name, "-f", "%e %U %S", *argv],
                           env=env, cwd=ROOT, capture_output=True, text=True)
        wall, user, sys_ = (float(x) for x in Path(tf.name).read_text().split()[-3:])
    if p.returncode not in (0, 1, 3):
        raise RuntimeError(f"{argv} exited {p.returncode}:\n{p.stderr[-3000:]}")
    return ({"load before": before, "uptime": up, "wall s": wall,
             "cpu s": round(user + sys_, 2), "exit": p.returncode},
            json.loads(p.stdout))


def summary(doc: dict) -> dict:
    """The check's own figures of a ``--json`` document."""
    rels = doc["relations"]
    slow = sorted(rels, key=lambda r: -(r.get("seconds") or 0))[:5]
    return {"check s": doc["seconds"], "relations": len(rels), "counts": doc["counts"],
            "stored": doc["stored"],
            "false found": [r["latex"] for r in rels if r["verdict"] == "does-not-hold"],
            "corrected": sum(bool(r["corrected"]) for r in rels
                             if r["verdict"] == "does-not-hold"),
            "slowest": [{"latex": r["latex"], "seconds": r.get("seconds"),
                         "verdict": r["verdict"]} for r in slow]}


def main(argv: list[str] | None = None) -> int:
    """Write the document, run cold then warm, print and write the JSON (``--out``)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sections", type=int, default=10, help="10 relations each")
    ap.add_argument("--out", type=Path,
                    default=ROOT / "benchmarks" / "results" / "documents.json")
    args = ap.parse_args(argv)
    work = Path(tempfile.mkdtemp(prefix="documents-bench-"))
    md, toml = document(args.sections)
    (work / "doc.md").write_text(md, encoding="utf-8")
    (work / "doc.reading.toml").write_text(toml, encoding="utf-8")
    env = {k: v for k, v in os.environ.items()
           if k not in ("RIGIDSYM_WORK_FILE", "PYTHONDONTWRITEBYTECODE")}
    env.setdefault("PYTHONPYCACHEPREFIX", str(work / "pycache"))
    argv0 = [sys.executable, "-m", "rigidsym", "check", str(work / "doc.md"), "--json"]
    # the bytecode, on a scratch verdict store: not measured
    subprocess.run(argv0, env=env | {"RIGIDSYM_CACHE": str(work / "scratch")}, cwd=ROOT,
                   capture_output=True, check=False)
    env["RIGIDSYM_CACHE"] = str(work / "cache")
    import sympy

    res: dict = {"machine": {"cpu model": host()["cpu"] or platform.processor(),
                             "cores": os.cpu_count(), "python": platform.python_version(),
                             "sympy": sympy.__version__, "platform": platform.platform(),
                             "shared": "yes: other processes ran beside it (see the load)",
                             "bytecode": "compiled before the runs, as pip install leaves it"},
                 "started": time.strftime("%Y-%m-%d %H:%M:%S"), "argv": argv0[2:],
                 "targets": {"cold s": 120, "warm s": 5}}
    run, doc = timed(argv0, env)
    res["cold"] = run | summary(doc)
    print("cold:", json.dumps(res["cold"], indent=1), flush=True)
    first = SLIPS[0][1].replace("{K}", "{1}")
    fixed = IDENTITIES[SLIPS[0][0]].replace("{K}", "{1}")
    (work / "doc.md").write_text(md.replace(first, fixed, 1), encoding="utf-8")
    run, doc = timed(argv0, env)
    res["warm"] = run | summary(doc) | {"edited": f"{first}  ->  {fixed}"}
    print("warm:", json.dumps(res["warm"], indent=1), flush=True)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(res, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
