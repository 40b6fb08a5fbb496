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
#: one xdist worker builds the wheel and runs every test of it (``--dist loadgroup``).
#: ``slow``: building the wheel compiles the 444 objects of every path wherever the object
#: cache misses (the editable install of the README's command compiles only this CPU's best
#: path, so the others compile here); .ci/run's slow part builds it.
pytestmark = [pytest.mark.xdist_group("wheel"), pytest.mark.slow]
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
    and wheel come from the test extra). The objects of this CPU's best path come from the
    reader's object cache, which the README's ``pip install -e`` filled (conftest.py); the
    other paths compile here."""
    root = tmp_path_factory.mktemp("wheel")
    src = _copy_sources(root / "src")
    out = root / "dist"
    env = dict(os.environ, RIGIDSYM_OBJECT_CACHE=os.environ["RIGIDSYM_TESTS_OBJECTS"])
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation",
                    "--quiet", "-w", str(out), str(src)], check=True, capture_output=True,
                   env=env)
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
    assert dist_info == {"-".join(wheel.name.split("-")[:2]) + ".dist-info"}


def test_wheel_ships_every_template(wheel):
    """the generator's templates moved to codegen/backends/<target>/templates/;
    the wheel carries every one of the checkout's (``generate`` and ``--target c`` from an
    installed package need them), the report's too."""
    with zipfile.ZipFile(wheel) as z:
        names = set(z.namelist())
    src = REPO / "src"
    templates = {p.relative_to(src).as_posix() for p in (src / "rigidsym").rglob("*.j2")}
    assert any("/backends/numpy/templates/" in t for t in templates)
    assert any("/backends/extension/templates/c_" in t for t in templates)
    assert templates <= names, sorted(templates - names)


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

    from rigidsym.registry.declarations import REGISTRY

    # the example's formulas, in this process: its ids may be registered already by another
    # test's load of the same file, so they are set aside while it executes again here
    saved = {k: REGISTRY.pop(k) for k in [k for k in REGISTRY if k.startswith("rot:")]}
    try:
        spec = importlib.util.spec_from_file_location("_example_source", module)
        src = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(src)
    finally:
        for k in [k for k in REGISTRY if k.startswith("rot:")]:
            del REGISTRY[k]
        REGISTRY.update(saved)
    for i in range(0, n, 8):
        ev = sp.Matrix(e[i].tolist())
        want = np.array(src.rodrigues(ev, sp.Float(phi[i], 30)).evalf(30), dtype=float)
        np.testing.assert_allclose(got["Q"][i], want, rtol=0, atol=1e-14)
        a, b = (sp.Matrix(x[i].tolist()) for x in eta)
        want = np.array(src.er_product(a, b).evalf(30), dtype=float).ravel()
        np.testing.assert_allclose(got["eta"][i], want, rtol=0, atol=1e-14)


# -- the wheel carries the compiled kernels; nothing is compiled at run time -----

_FIRST_CALL = """
from rigidsym import kernels
N = kernels.N_matrix(e=[0.0, 0.6, 0.8], phi=0.3)
import json, shutil
info = kernels.build_info()
print(json.dumps({"backend": kernels.backend(), "origin": info["origin"],
                  "path": info["path"], "cc": shutil.which("gcc") or shutil.which("cc"),
                  "N": N.tolist()}))
"""


def _without_compiler(installed, tmp_path) -> tuple[dict, Path]:
    """The wheel's environment with an empty cache and a PATH holding only Python."""
    bindir = tmp_path / "bin"
    bindir.mkdir()
    (bindir / "python").symlink_to(sys.executable)
    # a bare symlink is not inside the test's virtual environment: its dependencies (numpy,
    # sympy, python-flint, ...) come after the wheel on the path; rigidsym from the wheel
    deps = [p for p in sys.path if p.endswith("site-packages")]
    cache = tmp_path / "empty-cache"
    env = dict(installed["env"], PATH=str(bindir), RIGIDSYM_CACHE=str(cache),
               PYTHONPATH=os.pathsep.join([installed["env"]["PYTHONPATH"], *deps]))
    env.pop("CC", None)
    return env, cache


def test_wheel_is_a_platform_wheel_with_the_compiled_kernels(wheel):
    assert not wheel.name.endswith("-none-any.whl")
    with zipfile.ZipFile(wheel) as z:
        names = z.namelist()
    assert any(n.startswith("rigidsym/kernels/_ckernels.") and n.endswith((".so", ".pyd"))
               for n in names), names


def test_first_call_from_the_wheel_runs_prebuilt_c_without_a_compiler(installed, tmp_path):
    """Import plus the first N_matrix call in a fresh process: C from the wheel, no
    compiler on PATH, nothing compiled or written to the (empty) cache."""
    env, cache = _without_compiler(installed, tmp_path)
    p = subprocess.run([str(tmp_path / "bin" / "python"), "-c", _FIRST_CALL], env=env,
                       cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert "warn" not in p.stderr.lower(), p.stderr
    r = json.loads(p.stdout.splitlines()[-1])
    assert r["cc"] is None and r["backend"] == "c" and r["origin"] == "wheel", r
    assert not cache.exists() or not any(cache.rglob("*")), list(cache.rglob("*"))
    N, e = np.array(r["N"]), np.array([0.0, 0.6, 0.8])
    # [e_dot; phi_dot] = N omega (3.76): phi_dot = e . omega, and e_dot is normal to e
    assert N.shape == (4, 3) and np.allclose(N[3], e, rtol=0, atol=1e-15)
    assert np.allclose(e @ N[:3], 0.0, rtol=0, atol=1e-15) and np.abs(N[:3]).max() > 0.1


def test_user_kernels_without_a_compiler_run_on_numpy_with_one_warning(installed, tmp_path):
    env, cache = _without_compiler(installed, tmp_path)
    work = tmp_path / "reader"
    work.mkdir()
    shutil.copy(EXAMPLE, work / EXAMPLE.name)
    out = tmp_path / "kernels"
    py = str(tmp_path / "bin" / "python")
    p = subprocess.run([py, "-m", "rigidsym", "generate", "--module", EXAMPLE.name, "--out",
                        str(out)], env=env, cwd=work, capture_output=True, text=True,
                       timeout=600)
    assert p.returncode == 0, p.stderr
    assert "not compiled" in p.stderr and "C compiler" in p.stderr
    script = f"""
import warnings
warnings.simplefilter("always")
import numpy as np
from rigidsym import kernels
k = kernels.load({str(out)!r})
Q = k.rodrigues_rotation([0.0, 0.0, 1.0], np.linspace(0, 1, 5))
Q = k.rodrigues_rotation([0.0, 0.0, 1.0], 0.5)
print(k._SPACE.backend(), float(Q[0, 1]))
"""
    p = subprocess.run([py, "-c", script], env=env, cwd=work, capture_output=True, text=True,
                       timeout=120)
    assert p.returncode == 0, p.stderr
    backend, q01 = p.stdout.split()
    assert backend == "numpy" and abs(float(q01) + np.sin(0.5)) < 1e-15
    assert p.stderr.count("RuntimeWarning") == 1, p.stderr
    assert "C compiler" in p.stderr and "rigidsym build-c" in p.stderr, p.stderr
    assert not cache.exists() or not any(cache.rglob("*.so"))


def test_wheel_ships_the_exercise_notebooks(wheel, installed, tmp_path):
    """the 21 notebooks are package data, and an installed wheel writes one."""
    with zipfile.ZipFile(wheel) as z:
        names = set(z.namelist())
    for k in range(1, 22):
        assert f"rigidsym/generated/notebooks/ex3_{k:02d}.ipynb" in names, k
    assert "rigidsym/generated/notebooks/README.md" in names
    p = _run(installed, tmp_path, "-m", "rigidsym", "exercise", "3.4", "--notebook", "ex.ipynb")
    assert p.returncode == 0, p.stderr
    assert json.loads((tmp_path / "ex.ipynb").read_text())["cells"][0]["cell_type"] == "markdown"


def test_wheel_ships_the_torch_and_jax_programs(wheel):
    """generated/torch and generated/jax are package data, one program per kernel
    (and per Jacobian kernel), as generated/numpy."""
    with zipfile.ZipFile(wheel) as z:
        names = set(z.namelist())
    numpy_files = {n.split("/")[-1] for n in names if n.startswith("rigidsym/generated/numpy/")
                   and n != "rigidsym/generated/numpy/__init__.py"}
    for backend in ("torch", "jax"):
        got = {n.split("/")[-1] for n in names if n.startswith(f"rigidsym/generated/{backend}/")}
        assert got == numpy_files, backend
    assert "rigidsym/kernels/torch.py" in names and "rigidsym/kernels/jax.py" in names


def test_wheel_ships_the_latex_reader(wheel):
    """the grammar and every book's notation table (``--notation NAME``) are package data,
    and so are the chapter's data: its reading with its glyph table, the transcription's
    per-id notes, the handouts' words of the exercises."""
    from rigidsym.latex.notations import NOTATIONS

    with zipfile.ZipFile(wheel) as z:
        names = set(z.namelist())
    for f in ("grammar.lark", "transformer/chapter.py",
              "transcription.py", *(f"notations/{n}.txt" for n in NOTATIONS)):
        assert f"rigidsym/latex/{f}" in names, f
    # the chapter's data, beside its declarations in the book's package
    for f in ("angeles-chapter3.reading.toml", "angeles-chapter3.glyphs.csv",
              "angeles-chapter3.transcription-notes.json", "exercises/handout.toml",
              "exercises/notebooks-README.md"):
        assert f"rigidsym/derivations/{f}" in names, f


_DISPATCH = """
import json, sys
sys.path.insert(0, {tests!r})
import numpy as np
import test_kernels as T
from rigidsym import kernels
kernels.use_backend("c")
xs = np.load({inputs!r})
got = {{}}
for name in T.PUBLIC + T.EULER:
    arrays = [xs[f"{{name}}/{{i}}"] for i in range(len(T.AVAILABLE[name].args))]
    got[name] = T.run(name, arrays, "c")[0]
np.savez({out!r}, **got)
print(json.dumps([kernels.build_info()["path"], kernels.build_info()["paths"]]))
"""


def test_forced_baseline_agrees_with_the_dispatched_path(installed, tmp_path):
    """The wheel holds every path (an editable install only this CPU's best):
    RIGIDSYM_DISPATCH=baseline runs its x86-64-v2 objects, and every kernel agrees with the
    dispatched path (normwise, as C and NumPy must) and with the 50-digit reference."""
    sys.path.insert(0, str(REPO / "tests"))
    import test_kernels as T

    # the same inputs in both processes (the rotations among them come from a kernel, whose
    # last bits depend on the path; near phi = pi that would move the outputs by 1e-4)
    cases = {name: T.inputs(T.AVAILABLE[name], 64, seed=5) for name in T.PUBLIC + T.EULER}
    np.savez(tmp_path / "in.npz", **{f"{n}/{i}": a for n, arrays in cases.items()
                                     for i, a in enumerate(arrays)})
    ran = {}
    for forced in ("baseline", None):
        env = {k: v for k, v in installed["env"].items() if k != "RIGIDSYM_DISPATCH"}
        if forced:
            env["RIGIDSYM_DISPATCH"] = forced
        code = _DISPATCH.format(tests=str(REPO / "tests"), inputs=str(tmp_path / "in.npz"),
                                out=str(tmp_path / f"{forced}.npz"))
        p = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env,
                           capture_output=True, text=True, timeout=900)
        assert p.returncode == 0, p.stderr
        ran[forced] = json.loads(p.stdout.splitlines()[-1])
    (base_path, paths), (disp_path, _) = ran["baseline"], ran[None]
    if len(paths) < 2:
        pytest.skip(f"one path compiled ({paths})")
    # each ran where asked: the baseline forced, else the best path this CPU runs (a wheel
    # holds x86-64-v4 too, which a CPU without AVX-512 never dispatches to)
    from rigidsym.kernels.cbuild.paths import X86_PATHS, host_paths

    best = host_paths(tuple(p for p in X86_PATHS if p.name in paths))[0].name
    assert base_path == paths[-1] and disp_path == best, ran
    base, disp = np.load(tmp_path / "baseline.npz"), np.load(tmp_path / "None.npz")
    for name, arrays in cases.items():
        assert T.rel_err(base[name], disp[name]).max() <= 1e-14, name
        if name in ("N_matrix", "rotation_from_natural_invariants", "screw_axis_point"):
            ref = T.ref_eval(name, arrays)
            assert T.rel_err(base[name], ref).max() <= T.TOL, name
