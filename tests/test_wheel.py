"""The wheel: one top-level package, and a reader's own module checked and compiled from a
non-editable install (the README's "Your own equations" walkthrough)."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

REPO = Path(__file__).resolve().parents[1]
EXAMPLE = REPO / "examples" / "rotation_identities.py"


def _copy_sources(dest: Path) -> Path:
    """The checkout without VCS, build or cache folders (the build writes into its tree)."""
    skip = shutil.ignore_patterns(".git", "build", "dist", "*.egg-info", "__pycache__",
                                  ".venv", ".pytest_cache", ".ruff_cache", ".mypy_cache")
    shutil.copytree(REPO, dest, ignore=skip)
    return dest


@pytest.fixture(scope="session")
def wheel(tmp_path_factory) -> Path:
    """The wheel, built once per session from a copy of the checkout (no network: setuptools
    and wheel come from the test extra)."""
    root = tmp_path_factory.mktemp("wheel")
    src = _copy_sources(root / "src")
    out = root / "dist"
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation",
                    "--quiet", "-w", str(out), str(src)], check=True, capture_output=True)
    (whl,) = out.glob("rigidsym-*.whl")
    return whl


@pytest.fixture(scope="session")
def installed(wheel, tmp_path_factory) -> dict:
    """The wheel installed with ``--no-deps --target``; the environment to run it from."""
    site = tmp_path_factory.mktemp("site")
    subprocess.run([sys.executable, "-m", "pip", "install", "--no-deps", "--quiet",
                    "--target", str(site), str(wheel)], check=True, capture_output=True)
    env = dict(os.environ, PYTHONPATH=str(site),
               RIGIDSYM_CACHE=str(tmp_path_factory.mktemp("cache")))
    return {"site": site, "env": env}


def test_the_wheel_has_one_top_level_package(wheel):
    with zipfile.ZipFile(wheel) as z:
        top = {n.split("/")[0] for n in z.namelist()}
    dist_info = {t for t in top if t.endswith(".dist-info")}
    assert top - dist_info == {"rigidsym"}
    assert dist_info == {wheel.name.split("-py")[0] + ".dist-info"}


def _run(installed, cwd, *args) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, *args], cwd=cwd, env=installed["env"],
                          capture_output=True, text=True, timeout=900)


def test_installed_package_is_the_one_imported(installed, tmp_path):
    p = _run(installed, tmp_path, "-c",
             "import rigidsym; print(rigidsym.__file__); print(rigidsym.check('3.96e').verdict)")
    where, verdict = p.stdout.split()
    assert Path(where).is_relative_to(installed["site"]), p.stderr
    assert verdict == "does-not-hold"


def test_own_module_verified_generated_and_loaded_from_the_wheel(installed, tmp_path):
    work = tmp_path / "reader"
    work.mkdir()
    module = shutil.copy(EXAMPLE, work / EXAMPLE.name)
    p = _run(installed, work, "-m", "rigidsym", "verify", "--module", EXAMPLE.name,
             "--quiet", "--jobs", "2", "--json", "verdicts.json")
    assert p.returncode == 0, p.stdout + p.stderr
    rows = json.loads((work / "verdicts.json").read_text())["equations"]
    verdicts = {r["id"]: r["verdict"] for r in rows}
    assert len(verdicts) >= 8 and "undecided" not in verdicts.values()
    false = [r for r in rows if r["verdict"] == "does-not-hold"]
    assert len(false) >= 2
    for r in false:  # an exact counterexample at which the printed sides differ
        ce = r["counterexample"]
        assert ce["point"] and ce["lhs"] != ce["rhs"]
    out = tmp_path / "kernels"
    p = _run(installed, work, "-m", "rigidsym", "generate", "--module", EXAMPLE.name,
             "--out", str(out))
    assert p.returncode == 0, p.stdout + p.stderr
    header = (out / "c" / "rodrigues_rotation.c").read_text()
    assert "rotation_identities.rodrigues" in header and "kernels_spec" not in header
    _compare_kernels_with_source(installed, tmp_path, out, Path(module))


def _compare_kernels_with_source(installed, cwd, out: Path, module: Path) -> None:
    """Evaluate the loaded kernels (installed package) and the example's formula functions
    (sympy, 30 digits) at the same random points; they must agree to float64 precision."""
    rng = np.random.default_rng(7)
    n = 64
    e = rng.normal(size=(n, 3))
    e /= np.linalg.norm(e, axis=1, keepdims=True)
    phi = rng.uniform(-np.pi, np.pi, n)
    eta = rng.normal(size=(2, n, 4))
    eta /= np.linalg.norm(eta, axis=2, keepdims=True)
    np.savez(cwd / "inputs.npz", e=e, phi=phi, eta=eta)
    script = f"""
import numpy as np
from rigidsym import kernels
k = kernels.load({str(out)!r})
d = np.load("inputs.npz")
np.savez("outputs.npz", Q=k.rodrigues_rotation(d["e"], d["phi"]),
         eta=k.compose_euler_rodrigues(d["eta"][0], d["eta"][1]))
"""
    p = _run(installed, cwd, "-c", script)
    assert p.returncode == 0, p.stderr
    got = np.load(cwd / "outputs.npz")
    import importlib.util

    spec = importlib.util.spec_from_file_location("_example_source", module)
    src = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(src)
    for i in range(0, n, 8):
        ev = sp.Matrix(e[i].tolist())
        want = np.array(src.rodrigues(ev, sp.Float(phi[i], 30)).evalf(30), dtype=float)
        np.testing.assert_allclose(got["Q"][i], want, rtol=0, atol=1e-14)
        a, b = (sp.Matrix(x[i].tolist()) for x in eta)
        want = np.array(src.er_product(a, b).evalf(30), dtype=float).ravel()
        np.testing.assert_allclose(got["eta"][i], want, rtol=0, atol=1e-14)


def test_wheel_ships_the_exercise_notebooks(wheel, installed, tmp_path):
    """Issue 22: the 21 notebooks are package data, and an installed wheel writes one."""
    with zipfile.ZipFile(wheel) as z:
        names = set(z.namelist())
    for k in range(1, 22):
        assert f"rigidsym/generated/notebooks/ex3_{k:02d}.ipynb" in names, k
    assert "rigidsym/generated/notebooks/README.md" in names
    p = _run(installed, tmp_path, "-m", "rigidsym", "exercise", "3.4", "--notebook", "ex.ipynb")
    assert p.returncode == 0, p.stderr
    assert json.loads((tmp_path / "ex.ipynb").read_text())["cells"][0]["cell_type"] == "markdown"
