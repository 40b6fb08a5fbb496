"""The book's built statements kept on disk (:mod:`rigidsym.registry.statement_cache`): a
statement read back is the statement a build gives, node by node; a damaged entry is built
again and replaced, never trusted; a change of what the key covers misses; an unwritable
cache is no error; processes filling one cache at once leave it whole.

Each process here is fresh (as a command or a test worker starts) and counts its work
(:mod:`rigidsym.core.work`): ``build`` for a declaration run, ``load`` for a statement read
from the cache. The comparison of every statement and the four processes at once are
``slow``; the rest runs in the quick profile.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import _profile
import pytest

from rigidsym.core import cache, sources, work
from rigidsym.registry import declarations, statement_cache
from rigidsym.registry.declarations import REGISTRY, book_ids

#: small modules of the book (7 and 16 declarations, a tenth of a second to build each)
SMALL = "rigidsym.derivations.sec3_3"
OTHER = "rigidsym.derivations.sec3_2_2"

#: run in a fresh process: build (or load) the book's statements, or one module's, and
#: count; with ``compare``, build each one again from its function and say where it differs
SCRIPT = r'''
import dataclasses, json, sys
from collections import Counter

import sympy as sp
from sympy.matrices.utilities import dotprodsimp

from rigidsym.core import work
from rigidsym.registry.declarations import REGISTRY, Statement, book_ids

mode, module = sys.argv[1], sys.argv[2]
ids = [i for i in book_ids() if module in ("all", REGISTRY[i].module)]
compared = sys.argv[3].split(",") if len(sys.argv) > 3 else ids  # compare: these, or all
got = {i: REGISTRY[i].build() for i in ids}
out = {k: dict(work.since(Counter(), k)) for k in ("build", "load")}


def shape(x):
    """The tree of a value, down to sympy's srepr of each expression (its classes too)."""
    if dataclasses.is_dataclass(x):
        return [type(x).__name__] + [shape(getattr(x, f.name)) for f in dataclasses.fields(x)]
    if isinstance(x, dict):
        return sorted(json.dumps([shape(k), shape(v)]) for k, v in x.items())
    if isinstance(x, (list, tuple)):
        return [type(x).__name__] + [shape(v) for v in x]
    return sp.srepr(x) if isinstance(x, (sp.Basic, sp.MatrixBase)) else repr(x)


if mode == "compare":
    diffs = []
    for i in compared:
        with dotprodsimp(False):  # as Equation.build runs a declaration
            fresh = REGISTRY[i].build_fn()
        for f in dataclasses.fields(Statement):
            a, b = getattr(got[i], f.name), getattr(fresh, f.name)
            if a != b or shape(a) != shape(b):
                diffs.append([i, f.name])
    out["diffs"] = diffs
print(json.dumps(out))
'''


def fresh(cache: Path, mode: str = "fill", module: str = "all", compared: list | None = None,
          **env: str) -> dict:
    """Run :data:`SCRIPT` in a fresh process on ``cache``; its counts (and differences: of
    the ids ``compared``, or of every id it builds)."""
    p = subprocess.run([sys.executable, "-c", SCRIPT, mode, module,
                        *([",".join(compared)] if compared is not None else [])],
                       env=dict(os.environ, RIGIDSYM_CACHE=str(cache), **env),
                       capture_output=True, text=True, timeout=900)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    return json.loads(p.stdout.splitlines()[-1])


def ids_of(module: str) -> set[str]:
    return {i for i in book_ids() if REGISTRY[i].module == module}


def entry(module: str) -> Path:
    return statement_cache.path_of(statement_cache.key_of(module))


# every statement built twice in fresh processes; quick:
# test_a_damaged_entry_is_built_again_and_replaced
@pytest.mark.slow
def test_every_statement_read_back_equals_the_one_its_declaration_builds(tmp_path):
    every = set(book_ids())
    first = fresh(tmp_path)  # the first process builds each and stores them, per module
    assert set(first["build"]) == every and set(first["build"].values()) == {1}
    assert first["load"] == {}
    stored = list((tmp_path / "statements").rglob("*.pickle"))
    assert len(stored) == len({REGISTRY[i].module for i in every})
    # the next reads them: no build, one load each; each statement built again from its
    # declaration and compared costs ~0.5 s: a seeded third of them (all in the exhaustive
    # profile); the quick test_a_damaged_entry_is_built_again_and_replaced compares a module
    second = fresh(tmp_path, "compare", compared=_profile.share(sorted(every), 1 / 3))
    assert second["build"] == {} and set(second["load"]) == every
    assert set(second["load"].values()) == {1}
    assert second["diffs"] == []  # printed, model, corrected, claims, derived, ... equal


@pytest.mark.sample(fraction=0.33)
@pytest.mark.parametrize("damage", ["truncated", "checksummed garbage", "another key"])
def test_a_damaged_entry_is_built_again_and_replaced(tmp_path, monkeypatch, damage):
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path))
    small = ids_of(SMALL)
    assert fresh(tmp_path, module=SMALL)["build"] == dict.fromkeys(small, 1)
    path = entry(SMALL)
    good = path.read_bytes()
    if damage == "truncated":  # its checksum no longer matches
        path.write_bytes(good[: len(good) // 2])
    elif damage == "checksummed garbage":  # a checksum that matches is not enough either
        cache.put(path, b"\x80\x05not a pickle")
    else:  # a sound entry of another module, checksummed, where this one lies
        fresh(tmp_path, module=OTHER)
        cache.put(path, entry(OTHER).read_bytes())
    again = fresh(tmp_path, module=SMALL)
    assert again["build"] == dict.fromkeys(small, 1) and again["load"] == {}
    assert cache.get(path) not in (None, good[: len(good) // 2])  # replaced, whole
    last = fresh(tmp_path, "compare", SMALL)
    assert last["build"] == {} and last["load"] == dict.fromkeys(small, 1)
    assert last["diffs"] == []


@pytest.fixture
def digests():
    """The package's digest computed afresh in the test and again after it."""
    sources.package_digest.cache_clear()
    yield
    sources.package_digest.cache_clear()


@pytest.mark.parametrize("what", ["sec3_3.py", "sec3_8.py", "kernels_accuracy.json",
                                  "zero/decide.py", "sympy's version"])
def test_a_change_of_what_the_key_covers_misses(tmp_path, monkeypatch, digests, what):
    """A changed byte of the module, of another book module, of a data file of the book, of
    the machinery, or another sympy: the entry is not read (a file's digest is changed as
    its bytes would change it, through the package's own digest)."""
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path))
    fresh(tmp_path, module=SMALL)
    key = statement_cache.key_of(SMALL)
    assert statement_cache.load(SMALL, key) is not None
    if what.endswith(("py", "json")):
        real = sources.file_digest
        hit = []

        def edited(path):
            if path.as_posix().endswith("/" + what):
                hit.append(path)
                return "0" * 64
            return real(path)

        monkeypatch.setattr(sources, "file_digest", edited)
        sources.package_digest.cache_clear()
        changed = statement_cache.key_of(SMALL)
        assert len(hit) == 1, hit  # the file is one the digest reads
    else:
        env = sources.environment()
        monkeypatch.setattr(sources, "environment",
                            lambda: env.replace('"sympy": "', '"sympy": "0.'))
        changed = statement_cache.key_of(SMALL)
    assert changed is not None and changed != key
    assert statement_cache.load(SMALL, changed) is None


def test_a_cache_that_cannot_be_written_is_no_error(tmp_path):
    (tmp_path / "statements").write_text("a file where the folder would be")
    small = ids_of(SMALL)
    for _ in range(2):  # built each time, nothing stored, no error
        got = fresh(tmp_path, module=SMALL)
        assert got["build"] == dict.fromkeys(small, 1) and got["load"] == {}


@pytest.mark.slow  # four processes; quick: test_a_cache_that_cannot_be_written_is_no_error
def test_four_processes_filling_one_cache_at_once_leave_it_whole(tmp_path):
    modules = [SMALL, OTHER]
    env = dict(os.environ, RIGIDSYM_CACHE=str(tmp_path))
    procs = [subprocess.Popen([sys.executable, "-c", SCRIPT, "fill", m], env=env,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for m in modules * 2]
    for p in procs:
        out, err = p.communicate(timeout=900)
        assert p.returncode == 0, err[-3000:]
    leftovers = [p for p in (tmp_path / "statements").rglob("*")
                 if p.is_file() and not p.name.endswith((".pickle", ".sha256", ".lock"))]
    assert leftovers == []  # no temporary file left behind
    for m in modules:
        got = fresh(tmp_path, "compare", m)
        assert got["build"] == {} and got["load"] == dict.fromkeys(ids_of(m), 1)
        assert got["diffs"] == []


def test_a_replaced_declaration_is_built_never_read_nor_stored(tmp_path, monkeypatch):
    """A test or a notebook that replaces a book declaration's function gets its own
    statement, never the stored one, and never stores it."""
    import dataclasses

    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path))
    small = ids_of(SMALL)
    eq_id = sorted(small)[0]
    marker = declarations.Statement([], {}, parametrisation="replaced")
    monkeypatch.setitem(REGISTRY, eq_id,
                        dataclasses.replace(REGISTRY[eq_id], build_fn=lambda: marker))
    try:
        declarations.forget_built()
        before = work.snapshot()
        assert REGISTRY[eq_id].build() is marker  # the module built whole, one replaced:
        for other in sorted(small - {eq_id}):
            REGISTRY[other].build()
        assert work.since(before, "build") == dict.fromkeys(small, 1)
        assert not (tmp_path / "statements").exists()  # nothing stored
        fresh(tmp_path, module=SMALL)  # stored by a process that runs the declarations
        declarations.forget_built()
        before = work.snapshot()
        assert REGISTRY[eq_id].build() is marker
        for other in sorted(small - {eq_id}):
            REGISTRY[other].build()
        assert work.since(before, "build") == {eq_id: 1}
        assert work.since(before, "load") == dict.fromkeys(small - {eq_id}, 1)
    finally:
        declarations.forget_built()
