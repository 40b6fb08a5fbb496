"""The verdict cache: what re-runs after an edit, bad entries, controls, reports unchanged."""

from __future__ import annotations

import json
import sys
import warnings
from pathlib import Path

import pytest

import rigidsym
from rigidsym.checking import verdict_cache
from rigidsym.cli import main
from rigidsym.core.settings import ENGINE
from rigidsym.registry.declarations import REGISTRY

HELPER = '''
"""A helper module of a user module: its scale factor enters one model."""
import sympy as sp

SCALE = sp.Integer({scale})
'''
USES_HELPER = '''
"""Declarations that import a local helper module."""
import sympy as sp
from rigidsym import Rel, Statement, angle, equation
import {helper} as h

phi = angle("phi")

@equation("cachea:pyth", "cos^2 + sin^2 = 1", section="cache tests")
def pyth() -> Statement:
    return Statement([Rel(sp.cos(phi) ** 2 + sp.sin(phi) ** 2, 1)], {{}})

@equation("cachea:scaled", "scaled double angle", section="cache tests")
def scaled() -> Statement:
    return Statement([Rel(h.SCALE * sp.sin(2 * phi), h.SCALE * 2 * sp.sin(phi) * sp.cos(phi))],
                     {{}})
'''
STANDALONE = '''
"""Declarations without local imports (one of them fails, as declared)."""
import sympy as sp
from rigidsym import Rel, Statement, angle, equation

psi = angle("psi")

@equation("cacheb:double", "cos 2 psi", section="cache tests")
def double() -> Statement:
    return Statement([Rel(sp.cos(2 * psi), 2 * sp.cos(psi) ** 2 - 1)], {})

@equation("cacheb:wrong", "cos 2 psi misremembered", section="cache tests",
          expected="does-not-hold")
def wrong() -> Statement:
    return Statement([Rel(sp.cos(2 * psi), 1 - 2 * sp.cos(psi) ** 2)], {},
                     corrected=[Rel(sp.cos(2 * psi), 1 - 2 * sp.sin(psi) ** 2)])
'''


@pytest.fixture
def project(tmp_path, monkeypatch):
    """Two user modules (one importing a local helper), an unrelated module, a private
    cache folder; each test's names are unique so that ``sys.modules`` stays clean."""
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path / "cache"))
    tag = tmp_path.name.replace("-", "_")
    helper = f"helper_{tag}"
    src = tmp_path / "src"
    src.mkdir()
    (src / f"{helper}.py").write_text(HELPER.format(scale=3))
    (src / "uses_helper.py").write_text(USES_HELPER.format(helper=helper))
    (src / "standalone.py").write_text(STANDALONE)
    (src / "unrelated.py").write_text("X = 1\n")
    yield src, helper
    sys.modules.pop(helper, None)
    for k in [k for k in REGISTRY if k.startswith(("cachea:", "cacheb:"))]:
        del REGISTRY[k]


def _run(src: Path, helper: str, fresh_process: bool = True) -> dict[str, bool]:
    """Verify both modules; ``{id: cached}``. A fresh process is emulated by forgetting
    the helper module, as a new ``rigidsym verify`` would not have it imported."""
    if fresh_process:
        sys.modules.pop(helper, None)
    res = rigidsym.verify(modules=[src / "uses_helper.py", src / "standalone.py"])
    assert [r.verdict for r in res] == [r.expected for r in res]
    return {r.id: r.cached for r in res}


def test_a_rerun_reads_everything_from_the_cache(project):
    src, helper = project
    assert not any(_run(src, helper).values())
    assert all(_run(src, helper).values())


def test_editing_a_helper_rechecks_exactly_the_ids_of_the_module_importing_it(project):
    src, helper = project
    _run(src, helper)
    (src / f"{helper}.py").write_text(HELPER.format(scale=5))
    cached = _run(src, helper)
    assert {k for k, c in cached.items() if not c} == {"cachea:pyth", "cachea:scaled"}


def test_editing_a_user_module_rechecks_its_ids_only(project):
    src, helper = project
    _run(src, helper)
    path = src / "standalone.py"
    path.write_text(path.read_text() + "\n# an edit\n")
    cached = _run(src, helper)
    assert {k for k, c in cached.items() if not c} == {"cacheb:double", "cacheb:wrong"}


def test_editing_an_unrelated_module_rechecks_nothing(project):
    src, helper = project
    _run(src, helper)
    (src / "unrelated.py").write_text("X = 2\n")
    assert all(_run(src, helper).values())


@pytest.mark.parametrize("garbage", [b"not json at all", b'{"format": 1}', b""])
def test_a_corrupt_entry_is_ignored_with_a_warning_and_recomputed(project, garbage):
    src, helper = project
    _run(src, helper)
    key = verdict_cache.key_of("cacheb:wrong")
    path = verdict_cache._path(key)
    path.write_bytes(garbage)  # the checksum no longer matches
    with pytest.warns(verdict_cache.VerdictCacheWarning, match="cacheb:wrong"):
        cached = _run(src, helper)
    assert {k for k, c in cached.items() if not c} == {"cacheb:wrong"}
    assert all(_run(src, helper).values())  # and written again, whole


def test_a_foreign_entry_with_a_valid_checksum_is_not_trusted(project):
    src, helper = project
    _run(src, helper)
    from rigidsym.core import cache as _cache

    # the entry of one id copied under another id's key, checksum and all
    good = verdict_cache._path(verdict_cache.key_of("cacheb:double")).read_bytes()
    _cache.put(verdict_cache._path(verdict_cache.key_of("cacheb:wrong")), good)
    with pytest.warns(verdict_cache.VerdictCacheWarning, match="another key"):
        res = rigidsym.verify(modules=[src / "standalone.py"])
    assert res["cacheb:wrong"].verdict == "does-not-hold" and not res["cacheb:wrong"].cached


def test_a_declaration_replaced_in_memory_is_never_cached(project):
    import dataclasses

    src, helper = project
    _run(src, helper)
    eq = REGISTRY["cacheb:double"]
    def rebuilt():  # the same statement, from a function the module does not define
        return eq.build_fn()

    REGISTRY["cacheb:double"] = dataclasses.replace(eq, build_fn=rebuilt)
    try:
        assert verdict_cache.key_of("cacheb:double") is None
        res = rigidsym.verify(ids=["cacheb:double"])
        assert not res["cacheb:double"].cached
    finally:
        REGISTRY["cacheb:double"] = eq


def test_a_helper_edited_after_its_import_is_checked_and_not_stored(project):
    src, helper = project
    _run(src, helper)
    (src / f"{helper}.py").write_text(HELPER.format(scale=7))  # the old one stays imported
    with pytest.warns(verdict_cache.VerdictCacheWarning, match="changed on disk"):
        cached = _run(src, helper, fresh_process=False)
    assert not cached["cachea:scaled"] and cached["cacheb:double"]


def test_no_cache_neither_reads_nor_writes(project, capsys):
    src, helper = project
    from rigidsym.core import cache as _cache

    assert main(["verify", "--module", str(src / "standalone.py"), "--no-cache",
                 "--quiet"]) == 0
    assert _cache.info()["verdicts"]["entries"] == 0
    assert main(["verify", "--module", str(src / "standalone.py"), "--quiet"]) == 0
    assert "(0 from the cache)" in capsys.readouterr().out
    assert main(["verify", "--module", str(src / "standalone.py"), "--quiet",
                 "--json", str(src / "out.json")]) == 0
    assert "(2 from the cache)" in capsys.readouterr().out
    rows = json.loads((src / "out.json").read_text())["equations"]
    assert [r["cached"] for r in rows] == [True, True]


def test_report_files_are_the_same_with_and_without_the_cache(project, tmp_path):
    src, helper = project
    outs = [tmp_path / "cold", tmp_path / "warm", tmp_path / "none"]
    for out, extra in zip(outs, ([], [], ["--no-cache"]), strict=True):
        assert main(["report", "--module", str(src / "standalone.py"), "--out", str(out),
                     "--jobs", "1", *extra]) == 0
    names = sorted(p.name for p in outs[0].iterdir())
    assert names == ["standalone.html", "standalone.json", "standalone.md"]
    for name in names:
        assert (outs[0] / name).read_bytes() == (outs[1] / name).read_bytes() == \
            (outs[2] / name).read_bytes(), name
    assert '"cached"' not in (outs[1] / "standalone.json").read_text()


def test_cache_info_and_clear(project, capsys):
    src, helper = project
    from rigidsym.core import cache as _cache

    _run(src, helper)
    kernels = _cache.folder("kernels")
    kernels.mkdir(parents=True)
    (kernels / "k.so").write_bytes(b"x")
    assert main(["cache", "info"]) == 0
    out = capsys.readouterr().out
    assert str(_cache.root()) in out and "verdicts: 4 entries" in out
    assert "kernels: 1 entries" in out
    assert main(["cache", "clear", "--verdicts"]) == 0
    assert _cache.info()["verdicts"]["entries"] == 0 and (kernels / "k.so").exists()
    assert not any(_run(src, helper).values())
    assert main(["cache", "clear"]) == 0
    assert not kernels.exists() and _cache.info()["verdicts"]["entries"] == 0


def test_the_key_changes_with_the_engine_settings(project, monkeypatch):
    src, helper = project
    _run(src, helper)

    before = verdict_cache.key_of("cacheb:double")
    monkeypatch.setattr(ENGINE, "numeric_points", 11)
    assert verdict_cache.key_of("cacheb:double") not in (None, before)


def test_no_warning_on_a_clean_rerun(project):
    src, helper = project
    _run(src, helper)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert all(_run(src, helper).values())
