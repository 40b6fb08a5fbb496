"""generated/ is what `rigidsym generate` would write: byte for byte, no missing or orphan file.

The default run compares generated/inputs.json (the digests of every input file of the
generator and of every file it wrote) with the tree: seconds instead of a generation of 70 to
360 s of CPU. The `slow` test derives again in a fresh process under a fixed PYTHONHASHSEED
(a seeded sixth of the kernels; the whole tree by `rigidsym generate --check` in the
exhaustive profile): the same bytes (the output does not depend on set iteration order), and
the modules it imported all among the recorded inputs (the digest rule misses nothing the
generator reads).
"""

from __future__ import annotations

import importlib
import json
import os
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import _profile
import pytest

import rigidsym
from rigidsym.codegen import inputs
from rigidsym.codegen.generator import TEMPLATES, check, default_out_dir, write

ROOT = Path(__file__).resolve().parents[1]

# the module on one worker (--dist loadgroup): the group whose mark the first test checks
pytestmark = pytest.mark.xdist_group("generated_fresh")


def test_loadgroup_keeps_this_module_on_one_worker(request):
    """--dist loadgroup marks a grouped test's node id with its group; when it does not
    (pytest 9.2 with pytest-xdist 3.8, pytest-xdist#1386) every worker that runs a test of
    this module pays for its own generation."""
    if not getattr(request.config.option, "loadgroup", False):
        pytest.skip("not under pytest-xdist's --dist loadgroup")
    assert request.node.nodeid.endswith("@generated_fresh"), request.node.nodeid


def test_generated_matches_its_recorded_inputs():
    """No input of the generator changed since generated/ was written, and no generated file
    was edited, removed or added by hand (the cheap half of `rigidsym generate --check`)."""
    lines = inputs.compare(ROOT / "generated")
    assert lines == [], ("generated/ is stale or edited; run `rigidsym generate`:\n"
                         + "\n".join(lines[:60]))


def test_compare_sees_an_edit_an_orphan_a_missing_file_and_a_changed_input(tmp_path):
    out = tmp_path / "generated"
    shutil.copytree(ROOT / "generated", out, ignore=shutil.ignore_patterns("__pycache__"))
    assert inputs.compare(out) == []
    (out / "kernels.json").write_text("{}\n")
    (out / "numpy" / "orphan.py").write_text("x = 1\n")
    (out / "api.py").unlink()
    lines = inputs.compare(out)
    assert "changed by hand: generated/kernels.json" in lines
    assert "orphan file: generated/numpy/orphan.py" in lines
    assert "missing file: generated/api.py" in lines
    # an input edited after the generation: its digest differs from the recorded one
    rec = json.loads((out / inputs.MANIFEST).read_text())
    some = "rigidsym/codegen/backends/extension/templates/c_fast.h.j2"
    assert some in rec["inputs"]
    rec["inputs"][some] = "0" * 64
    (out / inputs.MANIFEST).write_text(json.dumps(rec))
    assert f"input changed: {some}" in inputs.compare(out)


def test_the_inputs_hold_the_declarations_templates_and_lazy_imports():
    labels = set(inputs.manifest()["inputs"])
    for must in ("rigidsym/codegen/generator.py",
                 "rigidsym/codegen/backends/extension/templates/c_fast.h.j2",
                 "rigidsym/derivations/kernels_spec.py", "rigidsym/derivations/sec3_2.py",
                 "rigidsym/derivations/kernels_accuracy.json",
                 # imported inside generate(), not at the top of the module
                 "rigidsym/codegen/derivatives/jacobians.py"):
        assert must in labels, must
    assert not any(lab.startswith("rigidsym/generated") for lab in labels)
    # every template the generator's loader can render is an input (they live in
    # codegen/backends/<language>/templates/), and none hides another of the same name
    found = [p for folder in TEMPLATES for p in sorted(folder.glob("*.j2"))]
    assert {p.name for p in found} >= {"c_fast.h.j2", "numpy_kernel.py.j2", "api.py.j2"}
    assert len({p.name for p in found}) == len(found), sorted(p.name for p in found)
    site = Path(rigidsym.__file__).resolve().parents[1]      # src/ or an installed tree
    missing = [p for p in found if p.resolve().relative_to(site).as_posix() not in labels]
    assert not missing, missing
    # the build record an install writes beside the extension differs on every machine
    assert not any("_ckernels" in lab for lab in labels), sorted(labels)


#: a module with an import in every place a statement can stand, and names in strings
_NESTED = '''
import rigidsym.a
from . import b
from ..c import d as e


def f():
    from rigidsym.g import h
    class K:
        def m(self):
            try:
                import rigidsym.i
            except ImportError:
                import rigidsym.j
            else:
                from rigidsym import k
            finally:
                import rigidsym.l
    match h:
        case 1:
            import rigidsym.m
    with open(h) as fh, fh:
        while True:
            if fh:
                import rigidsym.n
            else:
                import rigidsym.o
            for _ in fh:
                import rigidsym.p
            break
    return lambda: __import__("x")
'''


def _walked_imports(text: str, package: str) -> set[str]:
    """Every node of the module walked (the oracle the statement scan must agree with)."""
    import ast

    found = set()
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = package.split(".")
            mod = (".".join(base[:len(base) - node.level + 1] + [node.module or ""])
                   if node.level else node.module)
            mod = mod.rstrip(".")
            found |= {mod} | {f"{mod}.{a.name}" for a in node.names}
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) \
                and node.value.startswith("rigidsym.") and " " not in node.value:
            found.add(node.value)
    return found


@pytest.mark.parametrize("strings", [
    "", 'NAME = "rigidsym.q"\n', "x = f'rigidsym.r.{1}'\n",
    "y = g(('rigidsym.s'), 'rigidsym. not a module')\n"])
def test_the_import_scan_finds_what_a_walk_of_every_node_finds(tmp_path, strings):
    """Imports nested anywhere, relative ones, and module names in strings (f-strings
    included): the scan of statements (and of strings only where the text quotes
    ``rigidsym.``) finds what walking every node of the tree finds."""
    src = tmp_path / "mod.py"
    src.write_text(_NESTED + strings)
    found = inputs._imports(src, "rigidsym.pkg.mod")
    assert found == _walked_imports(_NESTED + strings, "rigidsym.pkg")
    assert {"rigidsym.g.h", "rigidsym.pkg.b", "rigidsym.c.d", "rigidsym.m",
            "rigidsym.p"} <= found
    assert ("rigidsym.q" in found) is ("rigidsym.q" in strings)


@dataclass
class _Files:
    files: dict[str, str]


def test_check_reports_missing_orphan_and_changed(tmp_path):
    res = _Files({"c/k.c": "int k;\n", "kernels.json": "{}\n",
                  "numpy/k.py": "def k():\n    pass\n"})
    write(res, tmp_path)
    assert check(res, tmp_path) == ""
    first = next(iter(res.files))
    (tmp_path / first).write_text("changed\n")
    (tmp_path / "numpy" / "orphan.py").write_text("x = 1\n")
    (tmp_path / "kernels.json").unlink()
    diff = check(res, tmp_path)
    assert f"a/generated/{first}" in diff
    assert "orphan file: generated/numpy/orphan.py" in diff
    assert "missing file: generated/kernels.json" in diff
    write(res, tmp_path)
    assert check(res, tmp_path) == ""
    assert not (tmp_path / "numpy" / "orphan.py").exists()


def test_no_timestamps_or_absolute_paths():
    # the files on disk: test_generated_matches_its_recorded_inputs holds them to a generation
    for p in sorted((ROOT / "generated").rglob("*")):
        if not p.is_file() or "__pycache__" in p.parts or p.suffix not in (".py", ".c", ".h",
                                                                            ".json"):
            continue
        rel, text = p.relative_to(ROOT).as_posix(), p.read_text(encoding="utf-8")
        assert str(ROOT) not in text, rel
        assert "/home/" not in text and "/root/" not in text, rel


#: the thorough run's share of the book's kernels derived again under another hash seed
#: (every kernel, and the whole tree compared, in the exhaustive profile)
FRESH_SHARE = 1 / 6
#: the fresh process: the CLI's start-up imported first (it imports every command's module,
#: and only generate's runs), then either ``generate --check`` of the whole tree or the
#: kernels named in argv[1] derived (none read from the store) and their files written as
#: JSON to argv[2]; its last line lists the rigidsym modules imported beyond the start-up
FRESH = """
import importlib, json, sys
from rigidsym.cli import main
start = set(sys.modules)
names = json.loads(sys.argv[1])
if names is None:
    rc = main(["generate", "--check"])
else:
    from rigidsym.codegen.generator import BOOK_ORIGIN, generate
    book = importlib.import_module(BOOK_ORIGIN).KERNELS
    res = generate(kernels=[k for k in book if k.name in names], origin=BOOK_ORIGIN)
    with open(sys.argv[2], "w", encoding="utf-8") as f:
        json.dump({"kernels": [kc.kernel.name for kc in res.kernels], "files": res.files}, f)
    rc = 0
print(json.dumps(sorted(m.__file__ for n, m in sys.modules.items()
                        if n.startswith("rigidsym") and n not in start
                        and getattr(m, "__file__", None))))
sys.exit(rc)
"""


@pytest.mark.slow  # a generation: a share of the kernels (the whole tree when exhaustive)
def test_check_in_a_fresh_process_under_another_hash_seed(tmp_path):
    """Derived again in a fresh process under a fixed PYTHONHASHSEED, the kernels' files are
    byte for byte those of generated/ (written under another seed): the output does not
    depend on set iteration order; and every module the generation imported (beyond the
    CLI's start-up) is among the inputs whose digests generated/inputs.json records. The
    thorough run derives a seeded share of the book's kernels (another share each commit)
    and compares each derived kernel's own files; the exhaustive profile runs `rigidsym
    generate --check` over the whole tree (its aggregate files too). A stale tree prints its
    diff and exits 1 (`test_check_reports_missing_orphan_and_changed`)."""
    from rigidsym.codegen.generator import BOOK_ORIGIN

    book = sorted(k.name for k in importlib.import_module(BOOK_ORIGIN).KERNELS)
    picked = _profile.share(book, FRESH_SHARE)
    whole = len(picked) == len(book)
    # one process (RIGIDSYM_GENERATE_JOBS=1): the modules its workers import are its own
    env = dict(os.environ, PYTHONHASHSEED="4242", RIGIDSYM_GENERATE_JOBS="1")
    out = tmp_path / "files.json"
    p = subprocess.run([sys.executable, "-c", FRESH, json.dumps(None if whole else picked),
                        str(out)], env=env, cwd=ROOT, capture_output=True, text=True)
    assert p.returncode == 0, (p.returncode, p.stdout[-4000:], p.stderr[-4000:])
    assert default_out_dir() == ROOT / "generated"
    if not whole:
        got = json.loads(out.read_text(encoding="utf-8"))
        derived = set(got["kernels"])
        assert set(picked) <= derived, sorted(set(picked) - derived)
        # a kernel's own files (named by it) are the same whichever kernels a generation
        # holds; the aggregate files (api.py, kernels.json, the module's tables) are not
        own = {path: text for path, text in got["files"].items()
               if Path(path).stem in derived}
        for name in derived:
            assert sum(Path(path).stem == name for path in own) >= 2, (name, sorted(own))
        differ = sorted(path for path, text in own.items()
                        if not (ROOT / "generated" / path).is_file()
                        or (ROOT / "generated" / path).read_text(encoding="utf-8") != text)
        assert differ == [], f"derived under PYTHONHASHSEED=4242, these differ: {differ}"
    recorded = {f.resolve() for f in inputs.input_files()}
    generated = (ROOT / "generated").resolve()
    imported = {Path(f).resolve() for f in json.loads(p.stdout.splitlines()[-1])}
    missed = sorted(str(f) for f in imported
                    if f not in recorded and not f.is_relative_to(generated))
    assert missed == [], f"modules the generator imports but inputs.json does not hash: {missed}"


def test_cli_check_without_generated_folder(tmp_path, capsys):
    """Outside a checkout (no generated/ folder): a one-line error and exit code 2."""
    from rigidsym.cli import main
    assert main(["generate", "--check", "--out", str(tmp_path / "generated")]) == 2
    err = capsys.readouterr().err
    assert "no generated/ folder here" in err and "stale" not in err
