"""The compiled kernels: CPU dispatch, the cache (one compile for many processes,
checksums), the notice before a compile, staleness, and overflow in the normalising kernels.

The wheel itself (built once per session, no compiler at run time) is tested in
tests/test_wheel.py, which owns the session's wheel fixture.
"""

from __future__ import annotations

import itertools
import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
from _profile import examples
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rigidsym import kernels as K
from rigidsym.kernels.cbuild import driver as _build
from rigidsym.kernels.cbuild import extension as _ext

REPO = Path(__file__).resolve().parents[1]
HAVE_CC = _build.compiler() is not None
needs_cc = pytest.mark.skipif(not HAVE_CC, reason="no C compiler")
# the generated user directory (a `rigidsym generate` process, user_dir) is made once, on one
# worker: each worker that ran one of its tests made it again
pytestmark = pytest.mark.xdist_group("build")

#: a user module of one kernel (and its generated Jacobian kernel)
ONE_KERNEL = '''
from rigidsym.codegen.spec import Arg, Kernel, Out


def rescaled(v, s):
    return v * s


KERNELS = [Kernel(
    name="rescaled", summary="A vector times a scalar.", formula="w = s v",
    ids=("t:rescaled",), sources=(rescaled,),
    args=(Arg("v", (3,), "any", "a vector"), Arg("s", (), "any", "a factor")),
    outputs=(Out("w", (3,), "s v"),), build=lambda v, s: {"w": rescaled(v, s)})]
'''


def _env(cache: Path, **extra: str) -> dict:
    env = {k: v for k, v in os.environ.items() if k != "RIGIDSYM_DISPATCH"}
    env.update(RIGIDSYM_CACHE=str(cache), **extra)
    return env


def _python(code: str, env: dict, cwd: Path) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-c", textwrap.dedent(code)], env=env, cwd=cwd,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


@pytest.fixture(scope="module")
def user_dir(tmp_path_factory) -> Path:
    """A generated one-kernel user directory (C not compiled: --no-build)."""
    work = tmp_path_factory.mktemp("user")
    (work / "one_kernel.py").write_text(ONE_KERNEL)
    out = work / "kernels"
    p = subprocess.run([sys.executable, "-m", "rigidsym", "generate", "--module",
                        "one_kernel.py", "--out", str(out), "--no-build"], cwd=work,
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stdout + p.stderr
    assert "compiling" not in p.stderr
    return out


_LOAD = """
    import json, sys
    import numpy as np
    from rigidsym import kernels
    k = kernels.load({d!r})
    v = np.arange(30.0).reshape(10, 3) / 7
    w = k.rescaled(v, np.linspace(-2, 2, 10))
    info = kernels.build_info({d!r})
    np.save({out!r}, w)
    print(json.dumps({{"backend": k._SPACE.backend(), "origin": info["origin"],
                      "file": info["file"]}}))
"""


# four cold builds; quick:
# test_a_second_build_reuses_every_object_and_a_corrupt_one_is_compiled_again
@pytest.mark.slow
@needs_cc
def test_four_processes_on_an_empty_cache_compile_once(user_dir, tmp_path):
    cache = tmp_path / "cache"
    procs = [_python(_LOAD.format(d=str(user_dir), out=str(tmp_path / f"w{i}.npy")),
                     _env(cache), tmp_path) for i in range(4)]
    outs = [p.communicate(timeout=600) for p in procs]
    for p, (_, err) in zip(procs, outs, strict=True):
        assert p.returncode == 0, err
    notices = [err.count("rigidsym: compiling") for _, err in outs]
    assert sum(notices) == 1, [err for _, err in outs]
    for (_, err), n in zip(outs, notices, strict=True):    # the others waited, or loaded
        assert n or "waiting for it" in err or not err.strip(), err
    infos = [json.loads(out.splitlines()[-1]) for out, _ in outs]
    assert {i["backend"] for i in infos} == {"c"}
    assert {i["origin"] for i in infos} == {"cache"}
    assert len({i["file"] for i in infos}) == 1
    ws = [np.load(tmp_path / f"w{i}.npy") for i in range(4)]
    for w in ws[1:]:
        assert np.array_equal(w, ws[0])
    v = np.arange(30.0).reshape(10, 3) / 7
    np.testing.assert_allclose(ws[0], v * np.linspace(-2, 2, 10)[:, None], rtol=1e-15)


@pytest.mark.slow  # a build; quick:
# test_a_second_build_reuses_every_object_and_a_corrupt_one_is_compiled_again
@needs_cc
def test_corrupt_cached_module_is_rebuilt_with_a_warning_never_loaded(user_dir, tmp_path):
    cache = tmp_path / "cache"
    env = _env(cache)
    p = _python(_LOAD.format(d=str(user_dir), out=str(tmp_path / "a.npy")), env, tmp_path)
    out, err = p.communicate(timeout=600)
    assert p.returncode == 0, err
    so = Path(json.loads(out.splitlines()[-1])["file"])
    good = so.read_bytes()
    so.write_bytes(b"\x7fELF garbage" * 100)          # overwritten by something else
    code = "import warnings; warnings.simplefilter('always')\n" + textwrap.dedent(
        _LOAD.format(d=str(user_dir), out=str(tmp_path / "b.npy")))
    p = _python(code, env, tmp_path)
    out, err = p.communicate(timeout=600)
    assert p.returncode == 0, err
    assert "fail their checksum" in err and "rigidsym: compiling" in err
    assert json.loads(out.splitlines()[-1])["backend"] == "c"
    assert np.array_equal(np.load(tmp_path / "a.npy"), np.load(tmp_path / "b.npy"))
    assert _ext._valid(so, _build.embedded_hash(good)) is True
    so.write_bytes(good[: len(good) // 2])           # truncated
    assert _ext._valid(so, _build.embedded_hash(good)) is False


@pytest.mark.slow  # a build; quick:
# test_a_second_build_reuses_every_object_and_a_corrupt_one_is_compiled_again
@needs_cc
def test_stale_module_is_never_loaded_and_rebuilt_with_a_notice(user_dir, tmp_path,
                                                                monkeypatch, capfd):
    """A module whose built-in sources hash differs from the folder's (an editable install
    after `rigidsym generate`) is not loaded: the folder is compiled into the cache."""
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path / "cache"))
    built = _ext.package_module()
    if built is None:
        pytest.skip("the package was installed without its compiled module")
    assert _build.embedded_hash(built) != _build.sources_hash(user_dir / "c")
    monkeypatch.setattr(_ext, "_MODULES", {})
    loaded = _ext.load(user_dir, package=True)      # as if user_dir were generated/
    err = capfd.readouterr().err
    assert "stale" in err and "rigidsym: compiling" in err
    assert loaded.origin == "cache" and loaded.file != built
    assert loaded.module.sources == _build.sources_hash(user_dir / "c")


def test_embedded_hash_is_read_without_loading(tmp_path):
    f = tmp_path / "m.so"
    f.write_bytes(b"\0junk rigidsym-sources:" + b"a" * 64 + b"\0more")
    assert _build.embedded_hash(f) == "a" * 64
    f.write_bytes(b"no tag here")
    assert _build.embedded_hash(f) is None


def test_cache_key_names_cpu_features_not_the_host(monkeypatch, tmp_path):
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path))
    gdir = _ext.generated_dir()
    a = (_ext.entry(gdir), _ext.entry(gdir, native=True))
    monkeypatch.setattr("platform.node", lambda: "another-host")
    assert (_ext.entry(gdir), _ext.entry(gdir, native=True)) == a
    monkeypatch.setattr(_build, "cpu_features", lambda: "a different CPU")
    assert _ext.entry(gdir) == a[0] and _ext.entry(gdir, native=True) != a[1]


def test_default_build_never_uses_march_native(monkeypatch):
    monkeypatch.delenv("RIGIDSYM_PATHS", raising=False)
    flags = [f for p in _build.default_paths() for f in p.flags]
    assert "-march=native" not in flags
    if _build._x86():
        assert [p.name for p in _build.default_paths()] == ["x86-64-v4", "x86-64-v3",
                                                             "x86-64-v2"]


def test_dispatch_env_names_an_unknown_path(tmp_path):
    if not HAVE_CC and _ext.package_module() is None:
        pytest.skip("no compiled module")
    env = _env(tmp_path / "cache", RIGIDSYM_DISPATCH="pentium-pro")
    p = _python("import warnings; warnings.simplefilter('error')\n"
                "from rigidsym import kernels\nkernels.build_info()", env, tmp_path)
    _, err = p.communicate(timeout=600)
    assert p.returncode != 0 and "RIGIDSYM_DISPATCH" in err and "pentium-pro" in err


def test_build_info_reports_the_path_in_use(backend):
    if backend != "c":
        pytest.skip("C only")
    info = K.build_info()
    assert info["path"] in info["paths"] and Path(info["file"]).is_file()
    assert info["origin"] in ("wheel", "editable build", "cache", "cache (native)")
    assert info["sources"] == _build.sources_hash(_ext.generated_dir() / "c")
    variant = {"x86-64-v3": "_ZGVdN4v_sin", "x86-64-v4": "_ZGVeN8v_sin"}
    if info["libmvec"] and info["path"] in variant:
        assert variant[info["path"]] in info["libmvec"]


# -- item 6: normalising kernels near the overflow threshold (sqrt(DBL_MAX) = 1.34e154) --

_NORMALISING = {   # kernel -> (args given a direction d and a scale s, unit output slice)
    "plucker_from_points": (lambda d, s: (np.zeros(3), s * d), lambda r: r[:3]),
    "instant_screw_axis": (lambda d, s: (s * d, np.zeros(3), np.zeros(3)),
                           lambda r: r[2][:3]),
    "wrench_axis": (lambda d, s: (np.concatenate([np.zeros(3), s * d]), np.zeros(3)),
                    lambda r: r[2][:3]),
}


@settings(max_examples=examples(40), deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture,
                                 HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(_NORMALISING)),
       exponent=st.floats(150.0, 160.0),
       d=st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3))
def test_normalised_vectors_near_overflow_are_right_or_raise(backend, name, exponent, d):
    d = np.array(d)
    if np.abs(d).max() < 1e-3:
        return
    s = 10.0 ** exponent
    args, unit = _NORMALISING[name]
    try:
        res = getattr(K, name)(*args(d, s))
    except K.NonFiniteResultError as exc:
        assert np.abs(s * d).max() * np.sqrt(3) > 1e153, exc    # only near the threshold
        return
    want = d / np.linalg.norm(d)
    np.testing.assert_allclose(unit(res), want, rtol=0, atol=1e-14)


def test_plucker_from_points_of_the_probe_is_its_representable_line(backend):
    # the probe's squares overflow, its line does not: e = (1, 2, 2)/3, moment 0 (
    # a representable result is returned, never NonFiniteResultError, never zeros)
    res = np.asarray(K.plucker_from_points(p1=[0, 0, 0], p2=[1e155, 2e155, 2e155]))
    np.testing.assert_allclose(res, [1 / 3, 2 / 3, 2 / 3, 0, 0, 0], rtol=4e-16, atol=0)


def test_n_tilde_dot_names_phi_at_its_singular_set(backend):
    with pytest.raises(K.SingularConfigurationError, match="phi = 0") as err:
        K.N_tilde_dot(e=[0.0, 0.6, 0.8], phi=0.0, omega=[0.1, 0.2, 0.3])
    assert err.value.argument == "phi"


# a native build; quick: test_loading_a_user_directory_never_loads_the_package_kernels
@pytest.mark.slow
@needs_cc
def test_native_build_is_used_when_present(user_dir, tmp_path):
    cache = tmp_path / "cache"
    p = subprocess.run([sys.executable, "-m", "rigidsym", "build-c", "--native",
                        str(user_dir)], env=_env(cache), capture_output=True, text=True,
                       timeout=600)
    assert p.returncode == 0, p.stderr
    assert "rigidsym: compiling" in p.stderr and "native" in p.stderr
    p = _python(_LOAD.format(d=str(user_dir), out=str(tmp_path / "w.npy")), _env(cache),
                tmp_path)
    out, err = p.communicate(timeout=600)
    assert p.returncode == 0, err
    assert "compiling" not in err
    assert json.loads(out.splitlines()[-1])["origin"] == "cache (native)"
    p = subprocess.run([sys.executable, "-m", "rigidsym", "build-c", "--info",
                        str(user_dir)], env=_env(cache), capture_output=True, text=True,
                       timeout=600)
    assert p.returncode == 0, p.stderr
    info = json.loads(p.stdout)
    assert info["paths"] == ["native"] and "-march=native" in info["flags"]


def test_loading_a_user_directory_never_loads_the_package_kernels(user_dir, tmp_path,
                                                                    monkeypatch):
    from rigidsym.kernels.runtime import state as _state

    calls = []
    real = _ext.load

    def spy(gdir, package=False):
        calls.append(package)
        return real(gdir, package)
    monkeypatch.setenv("RIGIDSYM_CACHE", str(tmp_path / "cache"))
    monkeypatch.setattr(_ext, "load", spy)
    monkeypatch.setitem(_state.STATE, "backend", None)
    monkeypatch.setattr(_state.builtin(), "_clib", None)
    k = K.load(user_dir)
    monkeypatch.setattr(k._SPACE, "_clib", None)
    w = k.rescaled([1.0, 2.0, 3.0], 2.0)
    np.testing.assert_array_equal(w, [2.0, 4.0, 6.0])
    assert True not in calls
    assert calls == [False]


# ------------------------------------------------------------------ the object cache
def _build_with_objects(user_dir: Path, tmp: Path, objects: Path) -> tuple[dict, bytes]:
    cfg = _build.configure()
    stats: dict = {}
    out = tmp / f"m{len(list(tmp.glob('m*')))}.so"
    work = tmp / f"objs{len(list(tmp.glob('objs*')))}"
    old = os.environ.get("RIGIDSYM_OBJECT_CACHE")
    os.environ["RIGIDSYM_OBJECT_CACHE"] = str(objects)
    try:
        _build.build(user_dir, out, cfg, work, stats=stats)
    finally:
        if old is None:
            os.environ.pop("RIGIDSYM_OBJECT_CACHE")
        else:
            os.environ["RIGIDSYM_OBJECT_CACHE"] = old
    return stats, out.read_bytes()


@needs_cc
def test_a_second_build_reuses_every_object_and_a_corrupt_one_is_compiled_again(user_dir,
                                                                              tmp_path):
    """A second build reuses every object and links the same module; an object whose
    checksum no longer matches is compiled again, never linked (one cache, three builds:
    two tests built the first cold one apiece)."""
    objects = tmp_path / "objects"
    first, so1 = _build_with_objects(user_dir, tmp_path, objects)
    n = _build.object_count(user_dir / "c", _build.configure())
    assert first["objects"] == first["compiled"] == n and first["reused"] == 0
    second, so2 = _build_with_objects(user_dir, tmp_path, objects)
    assert second["compiled"] == 0 and second["reused"] == n
    assert so1 == so2
    assert not list(objects.rglob("*.tmp")) and not list(objects.rglob(".*.tmp"))
    victim = sorted(objects.rglob("*.o"))[0]
    victim.write_bytes(b"\x7fELF not an object")          # its checksum no longer matches
    stats, so3 = _build_with_objects(user_dir, tmp_path, objects)
    assert stats["compiled"] == 1 and so3 == so1
    assert victim.read_bytes() != b"\x7fELF not an object"   # replaced by the fresh compile


# two cold builds; quick: test_kernels' values of the package's C kernels, which pip built
# with the precompiled header
@pytest.mark.slow
@needs_cc
def test_the_precompiled_header_changes_no_byte_of_the_module(user_dir, tmp_path, monkeypatch):
    """GCC's precompiled ``rigidsym_common.h`` is a faster reading of the same header: the
    module linked from objects compiled with it is the module compiled without it, byte for
    byte, and the build made one per path of ``PCH_MIN_OBJECTS`` objects or more (a partial
    path of fewer reads the header as text)."""
    cfg = _build.configure()
    if not _build._precompiles(cfg):
        pytest.skip("the compiler is not GCC: no precompiled header")
    monkeypatch.setattr(_build, "PCH_MIN_OBJECTS", 3)     # the user directory's paths
    made: list[str] = []
    real = _build._precompile
    monkeypatch.setattr(_build, "_precompile",
                        lambda argv, cdir: made.append(argv[argv.index("-include") + 1])
                        or real(argv, cdir))
    stats, with_pch = _build_with_objects(user_dir, tmp_path, tmp_path / "objects-pch")
    assert stats["compiled"] == stats["objects"]
    plan, _ = _build._paths.partial_plan(cfg.paths, _build.kernel_sources(user_dir / "c"),
                                         "rigidsym_table.c")
    big = sorted(k for k, v in plan.items() if len(v) >= _build.PCH_MIN_OBJECTS)
    assert big and sorted(Path(m).parent.name for m in made) == big
    for m in made:      # GCC wrote it (the build's work folder is kept)
        assert Path(m + ".gch").stat().st_size > 100_000
    monkeypatch.setenv("RIGIDSYM_PCH", "0")
    _, without = _build_with_objects(user_dir, tmp_path, tmp_path / "objects-text")
    assert with_pch == without
    assert len(made) == len(big)


# three builds; quick: test_a_second_build_reuses_every_object_and_a_corrupt_one_is_compiled_again
@pytest.mark.slow
@needs_cc
def test_other_flags_or_sources_miss_the_object_cache(user_dir, tmp_path, monkeypatch):
    objects = tmp_path / "objects"
    _build_with_objects(user_dir, tmp_path, objects)
    monkeypatch.setenv("RIGIDSYM_CFLAGS", "-O2 -std=c99 -ffp-contract=fast")
    stats, _ = _build_with_objects(user_dir, tmp_path, objects)
    assert stats["reused"] == 0
    monkeypatch.delenv("RIGIDSYM_CFLAGS")
    copy = tmp_path / "edited"
    import shutil

    shutil.copytree(user_dir, copy)
    src = _build.kernel_sources(copy / "c")[0]
    src.write_text(src.read_text() + "\n/* an edit */\n")
    stats, _ = _build_with_objects(copy, tmp_path, objects)
    # that source once per path that compiles it, and the module's C (it embeds the hash)
    plan, _ = _build._paths.partial_plan(_build.configure().paths,
                                         _build.kernel_sources(copy / "c"), "rigidsym_table.c")
    assert stats["compiled"] == sum(src in v for v in plan.values()) + 1


def test_object_cache_off_and_its_folder():
    from rigidsym.kernels.cbuild import objects as _objects

    old = dict(os.environ)
    try:
        os.environ["RIGIDSYM_OBJECT_CACHE"] = "0"
        assert _objects.root() is None
        os.environ["RIGIDSYM_OBJECT_CACHE"] = "/elsewhere/objs"
        assert _objects.root() == Path("/elsewhere/objs")
        os.environ.pop("RIGIDSYM_OBJECT_CACHE")
        os.environ["XDG_CACHE_HOME"] = "/home/x/.cache"
        assert _objects.root() == Path("/home/x/.cache/rigidsym/objects")
    finally:
        os.environ.clear()
        os.environ.update(old)


@settings(max_examples=examples(20))
@given(st.one_of(st.none(), st.text(st.characters(blacklist_categories=("Cs",),
                                                  blacklist_characters="\x00"), min_size=1)))
def test_rigidsym_cache_moves_verdicts_never_the_objects(cache):
    """``RIGIDSYM_CACHE`` (one run's verdicts kept apart) leaves the object cache where it is,
    so the next build reuses every object; only ``RIGIDSYM_OBJECT_CACHE`` moves it."""
    pytest.importorskip("filelock")
    from rigidsym.core import cache as _cache
    from rigidsym.kernels.cbuild import objects as _objects

    old = dict(os.environ)
    try:
        os.environ.pop("RIGIDSYM_OBJECT_CACHE", None)
        os.environ.pop("RIGIDSYM_CACHE", None)
        before = _objects.root()
        if cache is not None:
            os.environ["RIGIDSYM_CACHE"] = cache
        assert _objects.root() == before
        assert cache is None or _cache.root() == Path(cache).expanduser()
    finally:
        os.environ.clear()
        os.environ.update(old)


def test_the_avx512_path_compiles_only_the_kernels_calling_sin_or_cos(tmp_path):
    """x86-64-v4 buys 8-wide sin/cos and nothing else (benchmarks/RESULTS.md):
    the other kernels' v4 entries alias their x86-64-v3 functions at link time."""
    from rigidsym.kernels.cbuild import paths as _paths

    (tmp_path / "trig.c").write_text("double f(double x) { return sin(x) + 1.0; }\n")
    (tmp_path / "plain.c").write_text("/* sin( in a comment: not a call? it is text */\n"
                                      "double g(double x) { return x * x; }\n")
    (tmp_path / "plain2.c").write_text("double cosh_like(double x) { return x; }\n")
    (tmp_path / "rigidsym_table.c").write_text("/* table */\n")
    # no sin/cos, but measured faster on x86-64-v4: compiled there too
    (tmp_path / "instant_screw_point_pitch.c").write_text("double f(double x) { return x; }\n")
    srcs = sorted(tmp_path.glob("*.c"))
    plan, aliases = _paths.partial_plan(_paths.X86_PATHS, srcs, "rigidsym_table.c")
    names = {k: sorted(p.name for p in v) for k, v in plan.items()}
    assert names["v3"] == names["v2"] == sorted(p.name for p in srcs)
    if sys.platform.startswith("linux"):
        # a text match: a comment naming sin( counts, which only costs a compile
        assert names["v4"] == ["instant_screw_point_pitch.c", "plain.c", "rigidsym_table.c",
                               "trig.c"]
        assert "-Wl,--defsym,rigidsym_plain2_threads_v4=rigidsym_plain2_threads_v3" in aliases
        assert not any("trig" in a or "table" in a for a in aliases)
    # without a path after it, a trig_only path compiles everything
    plan, aliases = _paths.partial_plan((_paths.X86_V4,), srcs, "rigidsym_table.c")
    assert len(plan["v4"]) == len(srcs) and aliases == []


@pytest.mark.parametrize("flags, want", [
    # an AVX-512 machine: x86-64-v4 alone, every kernel compiled there (no alias to -v3)
    ("sse4_2 ssse3 popcnt cx16 avx avx2 fma bmi1 bmi2 f16c movbe abm avx512f avx512bw "
     "avx512cd avx512dq avx512vl", ["v4"]),
    # AVX2 without AVX-512 (many AMD desktops): x86-64-v3 alone
    ("sse4_2 ssse3 popcnt cx16 avx avx2 fma bmi1 bmi2 f16c movbe abm", ["v3"]),
    # AVX-512 flags without FMA cannot run x86-64-v4 either (the levels nest)
    ("sse4_2 ssse3 popcnt cx16 avx avx2 avx512f avx512bw avx512cd avx512dq avx512vl",
     ["v2"]),
    # a CPU below x86-64-v2: every path, and the dispatcher refuses at import, naming it
    ("sse2", ["v4", "v3", "v2"]),
])
def test_an_editable_install_compiles_the_paths_its_cpu_runs(flags, want, monkeypatch):
    """an editable install (setup.py, ``editable_mode``) compiles only the best path
    this CPU runs, every kernel there: the path a full build's dispatcher picks on this CPU
    (its values bit for bit those of a full build: benchmarks/editable_paths.py)."""
    from rigidsym.kernels.cbuild import paths as _paths

    monkeypatch.delenv("RIGIDSYM_PATHS", raising=False)
    info = f"processor\t: 0\nflags\t\t: {flags}\n"
    got = [p.suffix for p in _paths.host_paths(_paths.X86_PATHS, cpuinfo=info)]
    assert got == want
    # the full build's choice on this CPU, alone (or every path where none runs at all)
    runs = [p.suffix for p in _paths.X86_PATHS if _paths._runs(p, set(flags.split()))]
    assert got == runs[:1] if runs else got == [p.suffix for p in _paths.X86_PATHS]
    if runs:       # a trig-only path alone compiles every kernel, aliasing none
        srcs = [Path("plain.c"), Path("rigidsym_table.c")]
        plan, aliases = _paths.partial_plan(_paths.host_paths(_paths.X86_PATHS, cpuinfo=info),
                                            srcs, "rigidsym_table.c")
        assert plan == {runs[0]: srcs} and aliases == []
    monkeypatch.setenv("RIGIDSYM_PATHS", "v3,v2")     # the user's choice wins
    assert _paths.host_paths(_paths.X86_PATHS, cpuinfo=info) == _paths.X86_PATHS
    # no flags line (not Linux's cpuinfo): unchanged
    monkeypatch.delenv("RIGIDSYM_PATHS")
    assert _paths.host_paths(_paths.X86_PATHS, cpuinfo="model name: x\n") == _paths.X86_PATHS


@pytest.mark.slow
@needs_cc
def test_a_header_compiles_again_only_the_objects_that_include_it(user_dir, tmp_path):
    """A header no source includes (a kernel added beside) compiles only the module's C (it
    embeds the sources' hash); a kernel's header edited, that kernel's objects, the table's
    (it includes every kernel's header) and the module's."""
    import shutil

    objects = tmp_path / "objects"
    _build_with_objects(user_dir, tmp_path, objects)
    copy = tmp_path / "added"
    shutil.copytree(user_dir, copy)
    (copy / "c" / "another_kernel.h").write_text("/* a header no source includes */\n")
    stats, _ = _build_with_objects(copy, tmp_path, objects)
    assert stats["compiled"] == 1, stats
    srcs = _build.kernel_sources(copy / "c")
    kernel = next(s for s in srcs if (copy / "c" / f"{s.stem}.h").is_file())
    header = copy / "c" / f"{kernel.stem}.h"
    header.write_text(header.read_text() + "\n/* an edit */\n")
    stats, _ = _build_with_objects(copy, tmp_path, objects)
    plan, _ = _build._paths.partial_plan(_build.configure().paths, srcs, "rigidsym_table.c")
    readers = {kernel.name, "rigidsym_table.c"}
    assert stats["compiled"] == sum(s.name in readers for v in plan.values() for s in v) + 1


# ------------------------------------------------------------------ the build's progress
@settings(max_examples=examples(60))
@given(steps=st.lists(st.tuples(st.floats(0.0, 1.0), st.booleans()), min_size=1, max_size=80))
def test_the_build_is_never_quiet_longer_than_silence_and_a_tick(steps):
    """Called as :func:`build` calls it (a step finishing, or a tick every TICK s while none
    does), the text progress prints a line at least every SILENCE + TICK seconds of the
    build's clock, and the line after a quiet spell names what runs."""
    from io import StringIO
    from unittest import mock

    clock, out, printed = [0.0], StringIO(), []
    total = sum(f for _, f in steps) + 2
    with mock.patch("time.perf_counter", lambda: clock[0]):
        progress = _build.text_progress(0.0, out)
        done = 0
        for dt, finished in steps:
            # the gap between two calls: a tick at most (wait() returns on a finish sooner)
            clock[0] += dt * _build.TICK
            done += finished
            before = out.tell()
            progress(done, total, (("slow.c (x86-64-v3)", clock[0]),))
            if out.tell() > before:
                printed.append((clock[0], out.getvalue()[before:]))
    times = [0.0] + [t for t, _ in printed]
    assert all(b - a <= _build.SILENCE + _build.TICK for a, b in itertools.pairwise(times))
    assert clock[0] - times[-1] < _build.SILENCE + _build.TICK
    for _, line in printed:
        if "%" in line and "running:" in line:
            assert "slow.c (x86-64-v3)" in line


def test_a_long_compile_is_named_while_it_runs(tmp_path, monkeypatch):
    """The pool itself reports: while one object compiles longer than SILENCE and none
    finishes, a line says which source, for which path, runs."""
    import io
    import time

    cdir = tmp_path / "c"
    cdir.mkdir()
    for name in (_build.MODULE_SOURCE, _build.TABLE_SOURCE, "quick.c", "slow.c"):
        (cdir / name).write_text("/* */\n")
    monkeypatch.setenv("RIGIDSYM_OBJECT_CACHE", "0")
    monkeypatch.setattr(_build, "SILENCE", 0.2)
    monkeypatch.setattr(_build, "TICK", 0.02)
    monkeypatch.setattr(_build, "_run", lambda argv: time.sleep(0.6 if "slow.c" in
                                                                    " ".join(argv) else 0))
    cfg = _build.configure()
    monkeypatch.setattr(_build, "jobs", lambda: 1)     # one at a time: slow.c alone runs
    out = io.StringIO()
    _build.build(tmp_path, tmp_path / "m.so", cfg, tmp_path / "objs",
                 progress=_build.text_progress(time.perf_counter(), out))
    lines = out.getvalue().splitlines()
    assert any("running: slow.c (" in line for line in lines), lines
    assert "and the link" in lines[-1]
