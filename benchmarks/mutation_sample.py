"""How much the test suite catches where a silent wrong would hurt most: the killed fraction
of a seeded sample of mutants of six module groups (the zero test; the deciding of a verdict;
the kernels' input checks and rescue; grading by meaning; the LaTeX reader's ``--let``s and
their scope; certcheck's comparison), each mutant judged by a fixed selection of the test
files that exercise its group (:data:`GROUPS`).

    pip install -e ".[test,mutation]"
    nice -n 15 python benchmarks/mutation_sample.py [--limit N] [--group G] [--resume] [--all-marks]
        [--tests-from DIR] [--seed 2026] [--per-group 50] [--out FILE]
    nice -n 15 python benchmarks/mutation_sample.py --tests-from ../repriced --out AFTER.json

``--list`` prints the draw (each mutant's changed lines) and ``--baselines`` times each
group's unmutated selection; neither judges a mutant.

The mutants are cosmic-ray's (its core operators, those that take no arguments: arithmetic,
comparison, boolean and unary operators swapped, numbers moved by one, ``break`` and
``continue`` swapped, an ``except`` clause made to catch nothing, a decorator removed, a
``for`` loop run zero times). Every possible mutant of a group's files is listed, those inside
messages (f-strings, a raised exception's arguments, an ``assert``'s message, calls of
``logging``, ``warnings.warn`` and ``print``) and inside annotations (never evaluated here:
``from __future__ import annotations``) are left out, and ``--per-group`` of them are drawn
with ``random.Random(f"{seed}:{group}")``. The run takes the groups in turn, so ``--limit N``
judges a prefix spread over every group.

Each mutant is judged as ``python -m pytest -q -x -p no:cacheprovider -n 0 <files>`` in the
default marker selection (the quick run; ``--all-marks`` adds ``-m ''``: quick and slow). It
is *killed* when pytest exits non-zero, a *timeout* (killed, but counted apart) past 10 times
the unmutated selection's time, measured first in the same invocation, else it *survived*.

The checkout is never written to: the judge's files (``git ls-files`` of ``--tests-from``,
this checkout by default) are copied to a scratch folder under the system's temporary folder,
this checkout's ``src/`` (with the built C extension) and ``certcheck/`` laid over them, and a
mutant is written into that copy only; pytest runs there with ``PYTHONPATH`` on the copy's
``src/``, so the tests import the mutant (``rigidsym.generated`` and ``rigidsym.derivations``
still come from the editable install, unmutated). The scratch folder is removed at the end.
``--tests-from DIR`` judges the same draw (a draw of this checkout's source) by another
checkout's ``tests/`` and pytest configuration, such as a re-priced suite on another branch.

The results go to ``benchmarks/results/mutation_sample.json`` (``--out``), rewritten after
every mutant: the machine, the commits, the seed, each mutant (group, file, line, operator,
the changed lines, outcome, seconds, the first failing test) and the killed fraction; the
surviving mutants are listed beside it (``.survivors.txt``). ``--resume`` keeps the mutants
already in that file (same draw, same judge) and judges the rest.
"""

from __future__ import annotations

import argparse
import ast
import difflib
import hashlib
import importlib.util
import json
import os
import platform
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from test_command import host

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results" / "mutation_sample.json"
SEED = 2026
PER_GROUP = 50
TIMEOUT_FACTOR = 10
PYTEST = ["-m", "pytest", "-q", "-x", "-p", "no:cacheprovider", "-n", "0"]


@dataclass(frozen=True)
class Group:
    """A module group: its source files (``path`` or ``(path, first line, last line)``) and
    the test files that judge its mutants."""

    sources: tuple
    tests: tuple[str, ...]


#: module group -> (its files, the test files that exercise them), chosen by reading tests/
#: and by line coverage of the group's files: each a file that calls the group's code directly
#: or through one short path. Narrowed so that the whole draw takes about an hour on two
#: shared cores (10 to 35 s an unmutated selection): left out, test_kinds (zero),
#: test_mutation, test_bookpoint and test_labels (deciding), test_c_rescue_exponents (kernel
#: inputs: it covers a quarter of their lines, the C target's own rescue being its subject),
#: test_grading_classes (grading: no line of answers.py or matching.py) and test_certcheck
#: (certcheck: no line of compare.py; test_cert_page covers 86% of check.py and 84% of
#: compare.py)
GROUPS: dict[str, Group] = {
    "zero": Group(
        ("src/rigidsym/zero/cancel.py", "src/rigidsym/zero/decide.py",
         "src/rigidsym/zero/exact.py", "src/rigidsym/zero/plan.py",
         "src/rigidsym/zero/polar.py", "src/rigidsym/zero/program.py",
         "src/rigidsym/zero/roots.py", "src/rigidsym/zero/signs.py"),
        ("tests/test_zero.py", "tests/test_zero_polar.py", "tests/test_cancel.py",
         "tests/test_program.py", "tests/test_mutation.py")),
    "deciding": Group(
        ("src/rigidsym/checking/checker.py", "src/rigidsym/checking/deciding/balls.py",
         "src/rigidsym/checking/deciding/branches.py",
         "src/rigidsym/checking/deciding/counterexample.py",
         "src/rigidsym/checking/deciding/evidence.py",
         "src/rigidsym/checking/deciding/explicit.py",
         "src/rigidsym/checking/deciding/point_values.py",
         "src/rigidsym/checking/deciding/records.py"),
        ("tests/test_balls.py", "tests/test_never_contradicts.py", "tests/test_cold_verify.py")),
    "kernel-inputs": Group(
        ("src/rigidsym/kernels/runtime/inputs.py", "src/rigidsym/kernels/runtime/rescue.py",
         "src/rigidsym/kernels/runtime/errors.py",
         # KernelSpace.batch_function, .call and the checks of outputs and flags
         ("src/rigidsym/kernels/runtime/space.py", 147, 333)),
        ("tests/test_home_pose_and_validation.py", "tests/test_kernels_api.py")),
    "grading": Group(
        ("src/rigidsym/course/grading.py", "src/rigidsym/course/answers.py",
         "src/rigidsym/course/matching.py"),
        ("tests/test_grading_a_class.py", "tests/test_exercise_grade.py")),
    "latex-lets": Group(
        ("src/rigidsym/latex/lets.py", "src/rigidsym/latex/declgraph.py",
         "src/rigidsym/latex/reader_glyphs.py"),
        ("tests/test_check_latex_scope.py", "tests/test_check_latex_functions.py",
         "tests/test_check_latex_names.py")),
    "certcheck": Group(
        ("certcheck/src/certcheck/compare.py", "certcheck/src/certcheck/check.py"),
        ("tests/test_cert_page.py",)),
}

#: calls whose arguments are messages, not behaviour
MESSAGE_CALLS = {"debug", "info", "warning", "error", "exception", "critical", "warn", "print"}


class Stop(Exception):
    """A signal asked the run to stop (the results so far are kept)."""


# ---------------------------------------------------------------------------------------
# the draw


def _char_col(lines: list[str], line: int, byte_col: int) -> int:
    """ast's UTF-8 byte column as parso's character column."""
    text = lines[line - 1] if 0 < line <= len(lines) else ""
    return len(text.encode("utf-8")[:byte_col].decode("utf-8", errors="ignore"))


def skipped_spans(source: str) -> list[tuple[tuple[int, int], tuple[int, int]]]:
    """``((line, col), (end line, end col))`` of the messages and annotations of ``source``
    (character columns, as parso's): a mutant starting inside one is not drawn."""
    lines = source.splitlines()
    nodes: list[ast.AST] = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.JoinedStr):
            nodes.append(node)
        elif isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call):
            nodes += node.exc.args + [k.value for k in node.exc.keywords]
        elif isinstance(node, ast.Assert) and node.msg is not None:
            nodes.append(node.msg)
        elif isinstance(node, ast.Call):
            f = node.func
            name = f.attr if isinstance(f, ast.Attribute) else getattr(f, "id", "")
            if name in MESSAGE_CALLS:
                nodes.append(node)
        elif isinstance(node, ast.arg) and node.annotation is not None:
            nodes.append(node.annotation)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.returns:
            nodes.append(node.returns)
        elif isinstance(node, ast.AnnAssign):
            nodes.append(node.annotation)
    return [((n.lineno, _char_col(lines, n.lineno, n.col_offset)),
             (n.end_lineno, _char_col(lines, n.end_lineno, n.end_col_offset)))
            for n in nodes]


def _operators():
    """cosmic-ray's core operators that take no arguments: ``[(name, instance)]``."""
    from cosmic_ray import plugins

    out = []
    for name in plugins.operator_names():
        cls = plugins.get_operator(name)
        if not cls.arguments():
            out.append((name, cls()))
    return out


def _changed_lines(before: str, after: str) -> list[str]:
    return [d.rstrip("\n") for d in difflib.unified_diff(
        before.splitlines(), after.splitlines(), lineterm="", n=0)
        if d[:1] in "-+" and not d.startswith(("---", "+++"))]


def candidates(group: str, root: Path = ROOT) -> list[dict]:
    """Every mutant of ``group``'s files that is not in a message or an annotation, in a
    fixed order: ``{"id", "group", "file", "line", "col", "operator", "occurrence"}``."""
    from cosmic_ray.ast import ast_nodes, get_ast

    ops = _operators()
    out = []
    for src in GROUPS[group].sources:
        path, first, last = (src, 1, 10**9) if isinstance(src, str) else src
        source = (root / path).read_text(encoding="utf-8")
        spans = skipped_spans(source)
        nodes = list(ast_nodes(get_ast(source)))  # the operators only read the tree
        for name, op in ops:
            positions = ((s, e) for node in nodes for s, e in op.mutation_positions(node))
            for occurrence, (start, _end) in enumerate(positions):
                if not first <= start[0] <= last:
                    continue
                if any(a <= start < b for a, b in spans):
                    continue
                short = name.split("/", 1)[1]
                out.append({"id": f"{path}@{short}#{occurrence}", "group": group,
                            "file": path, "line": start[0], "col": start[1],
                            "operator": short, "occurrence": occurrence})
    out.sort(key=lambda m: (m["file"], m["line"], m["col"], m["operator"], m["occurrence"]))
    return out


def draw(seed: int, per_group: int, root: Path = ROOT) -> tuple[list[dict], dict[str, int]]:
    """The seeded draw, the groups taken in turn (so that a prefix is spread over them), and
    each group's number of candidates."""
    samples, sizes = {}, {}
    for group in GROUPS:
        pool = candidates(group, root)
        sizes[group] = len(pool)
        samples[group] = random.Random(f"{seed}:{group}").sample(pool, min(per_group,
                                                                             len(pool)))
    order = []
    for i in range(max(len(s) for s in samples.values())):
        order += [s[i] for s in samples.values() if i < len(s)]
    return order, sizes


def mutate(source: str, mutant: dict) -> str:
    """``source`` with ``mutant`` applied (cosmic-ray's ``mutate_code``)."""
    from cosmic_ray import plugins
    from cosmic_ray.mutating import mutate_code

    op = plugins.get_operator("core/" + mutant["operator"])()
    code = mutate_code(source, op, mutant["occurrence"])
    if code is None:
        raise RuntimeError(f"{mutant['id']}: cosmic-ray finds no such mutation")
    return code


# ---------------------------------------------------------------------------------------
# the scratch copy and the judge


def _git(cwd: Path, *args: str) -> str:
    try:
        return subprocess.run(["git", *args], cwd=cwd, capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def _copy(src: Path, dst: Path) -> None:
    dst.parent.mkdir(parents=True, exist_ok=True)
    shutil.copy2(src, dst)


def build_scratch(base: Path, judge: Path) -> Path:
    """The judge's tracked files under ``base/tree``, this checkout's ``src/`` (built
    extension included) and ``certcheck/`` laid over them; ``base/shared`` the judge's
    sibling ``shared/`` (the tests look for the book there)."""
    tree = base / "tree"
    listed = _git(judge, "ls-files", "-z")
    files = [f for f in listed.split("\0") if f] if listed else [
        str(p.relative_to(judge)) for p in judge.rglob("*")
        if p.is_file() and not {".git", ".venv", "__pycache__"} & set(p.parts)]
    for rel in files:
        if (judge / rel).is_file() and not rel.startswith(("src/", "certcheck/")):
            _copy(judge / rel, tree / rel)
    ignore = shutil.ignore_patterns("__pycache__", "*.egg-info", "build", "dist")
    for part in ("src", "certcheck"):
        shutil.copytree(ROOT / part, tree / part, ignore=ignore, symlinks=True)
    if (judge.parent / "shared").is_dir():
        (base / "shared").symlink_to(judge.parent / "shared")
    return tree


def _env(tree: Path) -> dict:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(tree / "src")] + [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p])
    return env


def check_imports(tree: Path) -> None:
    """The copy's rigidsym is the one a test imports (not the editable install's)."""
    got = subprocess.run([sys.executable, "-c", "import rigidsym; print(rigidsym.__file__)"],
                         cwd=tree, env=_env(tree), capture_output=True, text=True)
    if not got.stdout.strip().startswith(str(tree / "src")):
        raise SystemExit(f"the scratch copy is not what the tests import: {got.stdout}"
                         f"{got.stderr[-500:]}")


_CHILD: list[subprocess.Popen] = []


def run_tests(tree: Path, tests: tuple[str, ...], marks: list[str],
              timeout: float | None) -> tuple[str, float, str]:
    """``(outcome, seconds, first failing test or '')``: outcome ``passed``, ``failed`` or
    ``timeout``."""
    missing = [t for t in tests if not (tree / t).is_file()]
    if missing:
        raise SystemExit(f"the judge has no {missing}")
    cmd = [sys.executable, *PYTEST, *marks, *tests]
    t0 = time.monotonic()
    proc = subprocess.Popen(cmd, cwd=tree, env=_env(tree), stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, errors="replace",
                            start_new_session=True)
    _CHILD.append(proc)
    try:
        out, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return "timeout", time.monotonic() - t0, ""
    finally:
        _CHILD.remove(proc)
    seconds = time.monotonic() - t0
    if proc.returncode == 0:
        return "passed", seconds, ""
    failed = re.search(r"^(?:FAILED|ERROR) (\S+)", out, re.M)
    last = (out.strip().splitlines() or [f"exit status {proc.returncode}"])[-1]
    return "failed", seconds, failed.group(1) if failed else last[-200:]


def _kill_child() -> None:
    for proc in list(_CHILD):
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass


# ---------------------------------------------------------------------------------------
# the results


def machine() -> dict:
    cpu = host()["cpu"]
    return {"cpu": cpu or platform.processor() or platform.machine(),
            "cores": os.cpu_count(), "cores_usable": len(os.sched_getaffinity(0)),
            "python": platform.python_version(), "system": platform.platform()}


def sources_hash(root: Path = ROOT) -> str:
    h = hashlib.sha256()
    for group in GROUPS.values():
        for src in group.sources:
            path = src if isinstance(src, str) else src[0]
            h.update(path.encode() + b"\0" + (root / path).read_bytes())
    return h.hexdigest()[:16]


def summary(mutants: list[dict]) -> dict:
    judged = [m for m in mutants if "outcome" in m]
    n = len(judged)
    count = {k: sum(m["outcome"] == k for m in judged) for k in ("killed", "timeout",
                                                                 "survived")}
    by_group = {}
    for g in GROUPS:
        mine = [m for m in judged if m["group"] == g]
        dead = sum(m["outcome"] != "survived" for m in mine)
        by_group[g] = {"judged": len(mine), "killed_or_timeout": dead,
                       "killed_fraction": round(dead / len(mine), 4) if mine else None}
    return {"judged": n, **count,
            "killed_fraction": round((count["killed"] + count["timeout"]) / n, 4) if n else None,
            "by_group": by_group,
            "seconds_judging": round(sum(m["seconds"] for m in judged), 1)}


def _write_atomic(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


def survivors_path(out: Path) -> Path:
    return out.with_name(out.stem + ".survivors.txt")


def write(out: Path, doc: dict) -> None:
    doc["summary"] = summary(doc["mutants"])
    _write_atomic(out, json.dumps(doc, indent=1, ensure_ascii=False) + "\n")
    lines = [f"# surviving mutants of {out.name}: file:line operator, then the changed lines",
             f"# seed {doc['seed']}, source {doc['source']['commit'][:12]}, judge "
             f"{doc['judge']['commit'][:12]} ({doc['marks']})", ""]
    for m in doc["mutants"]:
        if m.get("outcome") == "survived":
            lines.append(f"{m['file']}:{m['line']}  {m['operator']}  [{m['group']}]")
            lines += [f"    {d}" for d in m["diff"]]
    _write_atomic(survivors_path(out), "\n".join(lines) + "\n")


# ---------------------------------------------------------------------------------------
# the run


def _stop(signum, _frame):
    raise Stop(signal.Signals(signum).name)


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--seed", type=int, default=SEED)
    p.add_argument("--per-group", type=int, default=PER_GROUP,
                   help=f"mutants drawn from each module group (default {PER_GROUP})")
    p.add_argument("--limit", type=int, default=None, help="judge the first N of the draw")
    p.add_argument("--group", choices=sorted(GROUPS), default=None,
                   help="judge only this group's mutants of the draw (the same mutants as in "
                        "a run of every group), e.g. after its tests changed")
    p.add_argument("--resume", action="store_true",
                   help="keep the mutants already judged in --out, judge the rest")
    p.add_argument("--all-marks", action="store_true",
                   help="judge with -m '' (quick and slow tests) instead of the default run")
    p.add_argument("--tests-from", type=Path, default=ROOT,
                   help="the checkout whose tests/ and pytest configuration judge the mutants")
    p.add_argument("--out", type=Path, default=OUT)
    p.add_argument("--list", action="store_true",
                   help="print the draw (id, line, changed lines) and judge nothing")
    p.add_argument("--baselines", action="store_true",
                   help="time each group's unmutated selection and judge nothing")
    args = p.parse_args(argv)

    judge = args.tests_from.resolve()
    marks = ["-m", ""] if args.all_marks else []
    if args.baselines:
        with tempfile.TemporaryDirectory(prefix="rigidsym-mutation-") as base:
            tree = build_scratch(Path(base), judge)
            check_imports(tree)
            for g, grp in GROUPS.items():
                outcome, secs, by = run_tests(tree, grp.tests, marks, None)
                print(f"{g:14} {outcome:7} {secs:6.1f} s  {by}", flush=True)
        return 0
    order, sizes = draw(args.seed, args.per_group)
    if args.group is not None:
        order = [m for m in order if m["group"] == args.group]
    if args.limit is not None:
        order = order[:args.limit]
    if args.list:
        for m in order:
            source = (ROOT / m["file"]).read_text(encoding="utf-8")
            print(f"{m['id']}  line {m['line']}: "
                  + " | ".join(_changed_lines(source, mutate(source, m))))
        return 0

    doc = {
        "what": "killed fraction of a seeded sample of mutants, each judged by its module "
                "group's test files (benchmarks/mutation_sample.py)",
        "tool": "cosmic-ray " + _version("cosmic-ray"),
        "machine": machine(),
        "source": {"commit": _git(ROOT, "rev-parse", "HEAD"),
                   "dirty": bool(_git(ROOT, "status", "--porcelain", "--", "src",
                                      "certcheck")),
                   "sources_sha256": sources_hash()},
        "judge": {"dir": str(judge), "commit": _git(judge, "rev-parse", "HEAD"),
                  "tests_tree": _git(judge, "rev-parse", "HEAD:tests"),
                  "pytest_config": _pytest_config(judge),
                  "dirty": bool(_git(judge, "status", "--porcelain", "--", "tests",
                                     "pyproject.toml"))},
        "seed": args.seed, "per_group": args.per_group, "only_group": args.group,
        "marks": "quick and slow (-m '')" if marks else "default (quick run)",
        "command": " ".join(["python", *PYTEST, *(["-m", "''"] if marks else []),
                             "<the group's tests>"]),
        "timeout": f"{TIMEOUT_FACTOR} x the unmutated selection's seconds",
        "groups": {g: {"sources": [s if isinstance(s, str) else f"{s[0]}:{s[1]}-{s[2]}"
                                   for s in grp.sources],
                       "tests": list(grp.tests), "candidates": sizes[g]}
                   for g, grp in GROUPS.items()},
        "drawn": len(order), "wall_s": 0.0, "baselines": {}, "mutants": [],
    }
    done: dict[str, dict] = {}
    if args.resume and args.out.exists():
        old = json.loads(args.out.read_text(encoding="utf-8"))
        same = ("seed", "per_group", "marks", "only_group")
        if any(old.get(k) != doc[k] for k in same) \
                or old["source"]["sources_sha256"] != doc["source"]["sources_sha256"] \
                or any(old["judge"].get(k) != doc["judge"][k]
                       for k in ("tests_tree", "pytest_config", "dirty")):
            raise SystemExit(f"{args.out}: another draw or judge (seed, per group, marks, "
                             "source, the judge's tests/ or pytest configuration); run "
                             "without --resume")
        done = {m["id"]: m for m in old["mutants"] if "outcome" in m}
        doc["wall_s"] = old.get("wall_s", 0.0)
        doc["baselines"] = old.get("baselines", {})
    doc["mutants"] = [done.get(m["id"], m) for m in order]
    todo = [m for m in doc["mutants"] if "outcome" not in m]
    print(f"{len(order)} mutants drawn ({', '.join(f'{g} {sizes[g]}' for g in GROUPS)} "
          f"candidates); {len(order) - len(todo)} already judged; judge {judge}", flush=True)

    for sig in (signal.SIGTERM, signal.SIGHUP, signal.SIGINT):
        signal.signal(sig, _stop)
    base = Path(tempfile.mkdtemp(prefix="rigidsym-mutation-"))
    t_start = time.monotonic()
    wall0 = doc["wall_s"]
    try:
        tree = build_scratch(base, judge)
        check_imports(tree)
        timeouts: dict[str, float] = {}
        for i, m in enumerate(todo, 1):
            group = GROUPS[m["group"]]
            if m["group"] not in timeouts:
                outcome, secs, by = run_tests(tree, group.tests, marks, None)
                if outcome != "passed":
                    raise SystemExit(f"{m['group']}: the unmutated selection fails ({by})")
                timeouts[m["group"]] = TIMEOUT_FACTOR * secs
                doc["baselines"][m["group"]] = {"seconds": round(secs, 1),
                                                "timeout_s": round(TIMEOUT_FACTOR * secs, 1)}
                print(f"baseline {m['group']}: {secs:.1f} s", flush=True)
            target = tree / m["file"]
            original = target.read_bytes()
            source = original.decode("utf-8")
            mutated = mutate(source, m)
            m["diff"] = _changed_lines(source, mutated)
            pyc = Path(importlib.util.cache_from_source(str(target)))
            try:
                target.write_text(mutated, encoding="utf-8")
                pyc.unlink(missing_ok=True)
                outcome, secs, by = run_tests(tree, group.tests, marks, timeouts[m["group"]])
            finally:
                target.write_bytes(original)
                pyc.unlink(missing_ok=True)
            m.update(outcome={"failed": "killed", "passed": "survived"}.get(outcome, outcome),
                     seconds=round(secs, 1), by=by)
            doc["wall_s"] = round(wall0 + time.monotonic() - t_start, 1)
            write(args.out, doc)
            print(f"[{i}/{len(todo)}] {m['outcome']:8} {secs:6.1f}s {m['id']} "
                  f"line {m['line']}", flush=True)
    except Stop as why:
        _kill_child()
        print(f"stopped by {why}; the results so far are in {args.out} (--resume goes on)",
              flush=True)
        return 130
    finally:
        doc["wall_s"] = round(wall0 + time.monotonic() - t_start, 1)
        if any("outcome" in m for m in doc["mutants"]):
            write(args.out, doc)
        shutil.rmtree(base, ignore_errors=True)
    s = summary(doc["mutants"])
    print(f"killed {s['killed']} + timeout {s['timeout']} of {s['judged']}: "
          f"{s['killed_fraction']}; survived {s['survived']} ({survivors_path(args.out)})")
    return 0


def _pytest_config(judge: Path) -> dict:
    """The judge's ``[tool.pytest.ini_options]`` (its markers and default selection)."""
    import tomllib

    path = judge / "pyproject.toml"
    if not path.is_file():
        return {}
    return tomllib.loads(path.read_text(encoding="utf-8")).get("tool", {}).get(
        "pytest", {}).get("ini_options", {})


def _version(dist: str) -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version(dist)
    except PackageNotFoundError:
        return "?"


if __name__ == "__main__":
    sys.exit(main())
