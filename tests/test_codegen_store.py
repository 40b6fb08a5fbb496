"""The store of derived kernels (rigidsym.codegen.inputs): a kernel's key moves with its own
declaration, the machinery and the settings, and with nothing else; an entry is whole or
absent. The slow tests generate for real: a second generation derives nothing, an
interrupted one keeps every group it finished and the run after it derives none of them
again (counted by rigidsym.core.work), and the files are those of a generation without the
store, byte for byte.
"""

from __future__ import annotations

import dataclasses
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
import sympy as sp
from test_interrupts import terminal_caller

from rigidsym.codegen import inputs as store
from rigidsym.codegen.derivatives.jacobians import jacobian_kernels
from rigidsym.codegen.spec import Arg, Kernel, Out
from rigidsym.core import cache, interrupts

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "rotation_identities.py"


def _cross(a, b):
    return {"c": sp.Matrix(a).cross(sp.Matrix(b))}


def _kernel(build=_cross, **kw) -> Kernel:
    fields = {"name": "cross_of", "summary": "a x b.", "formula": "c = a x b", "ids": (),
              "sources": ("tests.cross",), "args": (Arg("a", (3,)), Arg("b", (3,))),
              "outputs": (Out("c", (3,)),), "build": build}
    return Kernel(**{**fields, **kw})


@pytest.fixture(autouse=True)
def _machinery(request, monkeypatch):
    """The machinery's digest fixed (its own test reads the files): a key test in
    milliseconds."""
    if "machinery" not in request.node.name:
        monkeypatch.setattr(store, "machinery_hash", lambda: "m" * 64)


def test_the_key_moves_with_the_declaration_and_only_with_it():
    k = _kernel()
    base = store.kernel_key([k], "tests")
    assert store.kernel_key([_kernel()], "tests") == base                 # built again: the same
    assert store.kernel_key([dataclasses.replace(k, summary="b x a.")], "tests") != base
    assert store.kernel_key([dataclasses.replace(k, args=(Arg("a", (3,)), Arg("b", (3,), "unit")))],
                     "tests") != base
    # another formula function: the mathematics it builds, not the function's name
    other = _kernel(build=lambda a, b: {"c": sp.Matrix(b).cross(sp.Matrix(a))})
    assert store.kernel_key([other], "tests") != base
    same = _kernel(build=lambda a, b: {"c": sp.Matrix(a).cross(sp.Matrix(b))})
    assert store.kernel_key([same], "tests") == base
    assert store.kernel_key([k], "another origin") != base


def test_a_twin_is_keyed_with_its_kernel_without_building_its_derivatives(monkeypatch):
    k = _kernel()
    twin = jacobian_kernels([k])[0]
    built = []
    real = store.declared_hash
    monkeypatch.setattr(store, "declared_hash", lambda kern: built.append(kern.name) or
                        real(kern))
    store.kernel_key([k, twin], "tests")
    assert built == [k.name]
    assert store.kernel_key([k, twin], "tests") != store.kernel_key([k], "tests")


def test_the_machinery_is_every_input_but_the_book_and_the_settings(monkeypatch):
    rec = {"inputs": {"rigidsym/codegen/optimise.py": "1" * 64,
                      "rigidsym/derivations/kernels_spec.py": "2" * 64}}
    monkeypatch.setattr(store, "manifest", lambda outputs=None: rec)
    store.machinery_hash.cache_clear()
    try:
        base = store.machinery_hash()
        rec["inputs"]["rigidsym/derivations/kernels_spec.py"] = "3" * 64   # a kernel added
        store.machinery_hash.cache_clear()
        assert store.machinery_hash() == base
        rec["inputs"]["rigidsym/codegen/optimise.py"] = "4" * 64          # a pass changed
        store.machinery_hash.cache_clear()
        assert store.machinery_hash() != base
        monkeypatch.setattr(store, "settings", lambda: {"sympy": "0.0"})
        rec["inputs"]["rigidsym/codegen/optimise.py"] = "1" * 64
        store.machinery_hash.cache_clear()
        assert store.machinery_hash() != base
    finally:
        store.machinery_hash.cache_clear()


def test_an_entry_is_read_back_whole_and_a_corrupt_one_is_not(tmp_path, monkeypatch):
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path))
    entry = [("cross_of", b"programs", "abc", 7, [], [], {("numpy", "cross_of"): {"x": "y"}})]
    path = store.save_entry("ab" + "0" * 62, entry)
    assert path.is_relative_to(cache.folder(store.STORE))
    assert store.load_entry("ab" + "0" * 62) == entry
    assert store.load_entry("cd" + "0" * 62) is None
    assert store.kept({"ab" + "0" * 62: 2, "cd" + "0" * 62: 2}) == 2
    path.write_bytes(path.read_bytes()[:-1])                 # truncated: never trusted
    assert store.load_entry("ab" + "0" * 62) is None
    assert store.kept({"ab" + "0" * 62: 2}) == 0


# ----------------------------------------------------------------------------------------
# generating for real

def _env(cache_dir: Path, work: Path, more: dict | None = None) -> dict:
    env = {**os.environ, "RIGIDSYM_CACHE": str(cache_dir), "RIGIDSYM_WORK_FILE": str(work),
           "PYTHONPATH": str(ROOT / "src"), **(more or {})}
    env.pop("RIGIDSYM_GENERATE_JOBS", None)
    return env


def _generate(out: Path, cache_dir: Path, work: Path, *extra: str,
              env: dict | None = None) -> subprocess.Popen:
    with terminal_caller():  # a SIGINT the child can receive, however pytest was started
        return subprocess.Popen(
            [sys.executable, "-m", "rigidsym", "generate", "--module", str(EXAMPLE), "--out",
             str(out), "--no-build", *extra], env=_env(cache_dir, work, env), cwd=out.parent,
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _derived(work: Path) -> dict:
    return json.loads(work.read_text())["derive"]


def _files(folder: Path) -> dict[str, bytes]:
    return {p.relative_to(folder).as_posix(): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.mark.slow
def test_an_interrupted_generation_keeps_what_it_finished(tmp_path, monkeypatch):
    """SIGINT as the second group of two kernels begins (the third ``derive`` checkpoint,
    after the first group's entries are stored; rigidsym.core.interrupts): exit 130, a line
    saying what was kept; the run after it derives only what was not stored, and writes the
    files of a generation without the store."""
    ref, out, c = tmp_path / "ref", tmp_path / "out", tmp_path / "cache"
    monkeypatch.setenv("RIGIDSYM_CACHE", str(c))       # where store.load reads
    p = _generate(ref, tmp_path / "refcache", tmp_path / "ref.json", "--no-store")
    first = _generate(out, c, tmp_path / "first.json", env={interrupts.AT: "derive:3"})
    entries = c / store.STORE
    _, err = first.communicate(timeout=600)
    assert p.wait(timeout=600) == 0, p.stderr.read()
    all_kernels = set(_derived(tmp_path / "ref.json"))
    assert len(all_kernels) == 4
    assert first.returncode == 130, err
    assert "rigidsym: interrupted: 2 of 4 kernels kept; run again to continue" in err, err
    kept = {k for k, n in _derived(tmp_path / "first.json").items() if n}
    stored = {e[0] for f in entries.rglob("*.pkl") for e in store.load_entry(f.stem)}
    assert len(stored) == 2 and stored <= kept
    second = _generate(out, c, tmp_path / "second.json")
    assert second.wait(timeout=600) == 0, second.stderr.read()
    again = set(_derived(tmp_path / "second.json"))
    assert not again & stored, "a stored kernel was derived again"
    assert again | stored == all_kernels
    assert _files(out) == _files(ref)
    third = _generate(out, c, tmp_path / "third.json")
    assert third.wait(timeout=600) == 0
    assert _derived(tmp_path / "third.json") == {}
    assert _files(out) == _files(ref)
