"""A class made and graded: the CPU and wall time of ``rigidsym exam`` and ``rigidsym grade``.

The class: a quiz of exercises 3.2, 3.4, 3.6, 3.12 (weight 2) and 3.14, one drawn variant
each, for a roster of N students (``Student 01``, id ``00001``, ...). Then an answers CSV
made from the key, box by box in turn: the key's value, the key negated (a named slip),
the key times 1.37 (wrong and no slip of the final answer), a blank. Four commands, each
in a subprocess:

* ``exam`` in an empty user cache (``RIGIDSYM_CACHE`` a new folder) of the spec with
  ``slips_along_the_way = false`` (no replay solved);
* ``grade`` after it, in the cache ``exam`` left;
* ``grade`` again in another empty cache;
* ``exam`` of the spec with ``slips_along_the_way = true`` in a third empty cache (each
  student's solutions replayed with each slip along the way, an exact solve each, for
  the STACK export's slip tests);
* ``grade`` of that class (its answers made from its key as above) in the cache that
  ``exam`` left (the replays read back, none solved again).

CPU is the commands' user + system time with their worker processes
(``getrusage(RUSAGE_CHILDREN)`` before and after each). Prints the figures; ``--json F``
writes them with the host (CPU model, cores this process may use, load average before and
after).

    python benchmarks/class_cost.py [--students 30] [--json benchmarks/results/class_cost.json]
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

SPEC = """title = "Class"
seed = 4
slip_credit = 0.5
slips_along_the_way = false
[[problem]]
exercise = "3.2"
variants = 1
[[problem]]
exercise = "3.4"
variants = 1
[[problem]]
exercise = "3.6"
variants = 1
[[problem]]
exercise = "3.12"
variants = 1
weight = 2
[[problem]]
exercise = "3.14"
variants = 1
"""


def host() -> dict:
    """The host as benchmarks/test_command.py names it, and the cores this process may use."""
    from test_command import host as machine

    try:
        usable = len(os.sched_getaffinity(0))
    except AttributeError:
        usable = os.cpu_count()
    return {**machine(), "cores_usable": usable}


def timed(cmd: list[str], cache: Path, cwd: Path) -> dict:
    """Run ``cmd`` in ``cwd`` with ``RIGIDSYM_CACHE=cache``: its wall time, its CPU (user +
    system, its workers included) and its exit status.

    Raises:
        SystemExit: the command failed for another reason than wrong answers (status 1
            is ``grade``'s "not every box right").
    """
    env = dict(os.environ, RIGIDSYM_CACHE=str(cache))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    run = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if run.returncode not in (0, 1):
        raise SystemExit(f"{' '.join(cmd)} failed ({run.returncode}):\n{run.stderr[-3000:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"command": " ".join(cmd[2:] if cmd[:2] == [sys.executable, "-m"] else cmd),
            "cpu_s": round(cpu, 2), "user_s": round(after.ru_utime - before.ru_utime, 2),
            "wall_s": round(wall, 2), "exit": run.returncode}


def answers_csv(out: Path, path: Path) -> int:
    """Write the class's answers from ``out/key.json`` (see the module docstring); the
    number of boxes."""
    from rigidsym.course.gradebook import solution_of
    from rigidsym.course.grading import key_array

    key = json.loads((out / "key.json").read_text(encoding="utf-8"))
    rows, columns, n = [], [], 0
    for st in key["students"]:
        row = {"student": st["student"], "id": st["id"]}
        for p in st["problems"]:
            sol = solution_of(p)
            for a in p["asked"]:
                col = f"P{p['problem']}.{a}"
                if col not in columns:
                    columns.append(col)
                v = sol.answers[a]
                try:
                    k = key_array(v)
                except TypeError:           # an expression in symbols: left blank
                    continue
                truth = str(v) in ("True", "False")
                turn = n % 4
                n += 1
                if truth:
                    row[col] = ("true" if bool(v) else "false") if turn != 3 else ""
                elif turn == 0:
                    row[col] = json.dumps(k.tolist())
                elif turn == 1:
                    row[col] = json.dumps((-k).tolist())
                elif turn == 2:
                    row[col] = json.dumps((1.37 * k + 0.01).tolist())
                else:
                    row[col] = ""
        rows.append(row)
    with path.open("w", encoding="utf-8", newline="") as f:
        w = csv.DictWriter(f, ["student", "id", *columns], quoting=csv.QUOTE_ALL)
        w.writeheader()
        w.writerows(rows)
    return n


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--students", type=int, default=30)
    ap.add_argument("--json", type=Path, default=None)
    args = ap.parse_args()
    record = {"host": host(), "load_before": os.getloadavg(), "students": args.students,
              "spec": SPEC}
    cli = [sys.executable, "-m", "rigidsym"]
    along = SPEC.replace("slips_along_the_way = false\n", "slips_along_the_way = true\n")
    assert along != SPEC
    with tempfile.TemporaryDirectory(prefix="rigidsym-class-") as tmp:
        d = Path(tmp)
        (d / "quiz.toml").write_text(SPEC, encoding="utf-8")
        with (d / "roster.csv").open("w", encoding="utf-8", newline="") as f:
            w = csv.writer(f, quoting=csv.QUOTE_ALL)
            w.writerow(["name", "id"])
            w.writerows([f"Student {k:02d}", f"{k:05d}"] for k in range(1, args.students + 1))
        warm, cold = d / "cache", d / "cache-cold"
        record["exam"] = timed([*cli, "exam", "quiz.toml", "--students", "roster.csv",
                                "--out", "out"], warm, d)
        record["exam"]["files"] = sorted(p.name for p in (d / "out").iterdir())
        record["boxes"] = answers_csv(d / "out", d / "answers.csv")
        record["grade"] = timed([*cli, "grade", "out", "answers.csv"], warm, d)
        record["grade_cold_cache"] = timed([*cli, "grade", "out", "answers.csv"], cold, d)
        (d / "quiz-along.toml").write_text(along, encoding="utf-8")
        record["exam_slips_along_the_way"] = timed(
            [*cli, "exam", "quiz-along.toml", "--students", "roster.csv", "--out", "out-along"],
            d / "cache-along", d)
        answers_csv(d / "out-along", d / "answers-along.csv")
        record["grade_slips_along_the_way"] = timed(
            [*cli, "grade", "out-along", "answers-along.csv"], d / "cache-along", d)
    record["load_after"] = os.getloadavg()
    for k in ("exam", "grade", "grade_cold_cache", "exam_slips_along_the_way",
              "grade_slips_along_the_way"):
        r = record[k]
        print(f"{k:24s} cpu {r['cpu_s']:7.1f} s  wall {r['wall_s']:7.1f} s  ({r['command']})")
    print(f"host: {record['host']}; load {record['load_before']} -> {record['load_after']}")
    if args.json:
        args.json.write_text(json.dumps(record, indent=2) + "\n", encoding="utf-8")
        print(f"wrote {args.json}")


if __name__ == "__main__":
    main()
