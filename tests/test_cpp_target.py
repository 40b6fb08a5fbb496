"""The C++ layer over the C target: ``rigidsym generate --target cpp`` writes
``rigidsym_c.hpp`` beside the C, a header-only namespace of functions on Eigen matrices of
static shape (either storage order) and on nested ``std::array``.

The slow tests build a C++ application with CMake (g++ and clang++, strict warning
flags under ``-Werror``, the C compiled under a project's ``-Ofast -Werror``) that calls
every kernel of a generated folder with column-major and row-major Eigen matrices and with
``std::array``, in double and float, and check that the three give the same bits and that
the answers are the NumPy kernels' (:mod:`rigidsym.kernels`; a user module's by its sympy
declaration). The default-run tests read the generated header's text.
"""

from __future__ import annotations

import math
import re
import shutil
import subprocess
from pathlib import Path

import _profile
import numpy as np
import pytest
import sympy as sp
from _cmake import configure_and_build

ROOT = Path(__file__).resolve().parents[1]
USER_MODULE = ROOT / "examples" / "c" / "my_kernels.py"
#: book kernels of every shape the layer maps: vector and scalar in, 3 x 3 out (and a
#: Jacobian of rank 3); 3 x 3 in, vector and scalar out; 3 x 4 and 6 x 6 out
BOOK = ("rotation_from_natural_invariants", "natural_invariants_from_rotation",
        "newton_euler_wrench", "N_tilde", "inertia_dyad_at_point")
WARNINGS = ["-Wall", "-Wextra", "-Wpedantic", "-Werror", "-Wconversion",
            "-Wdouble-promotion", "-Wshadow"]
SAMPLES = 3


def _eigen_dir() -> Path | None:
    for d in (Path("/usr/include/eigen3"), Path("/usr/local/include/eigen3")):
        if (d / "Eigen" / "Core").is_file():
            return d
    return None


@pytest.fixture(scope="module")
def generated(tmp_path_factory):
    """The C and C++ of the book's kernels above and the example's user module, generated
    into a folder: (folder, compiled kernels)."""
    from rigidsym.codegen.backends.c.target import generate_c
    from rigidsym.codegen.backends.cpp.target import generate_cpp
    from rigidsym.codegen.generator import compile_many
    from rigidsym.codegen.usergen import select_kernels

    kernels, where = select_kernels([str(USER_MODULE)], list(BOOK))
    codes = compile_many(kernels, plan32=False)
    out = tmp_path_factory.mktemp("cpp") / "kernels"
    out.mkdir()
    files = generate_c(codes, where)
    files.update(generate_cpp(codes, "test_cpp_target"))
    for name, text in files.items():
        (out / name).write_text(text, encoding="utf-8")
    return out, codes


# --- the inputs and the reference answers ------------------------------------------------

def _input(arg, rng) -> np.ndarray:
    """A random valid value of ``arg`` (its constraint met)."""
    from rigidsym import kernels as K

    shape = tuple(arg.shape)
    if arg.kind == "unit":
        v = rng.normal(size=shape)
        return v / np.linalg.norm(v)
    if arg.kind == "rotation":
        e = rng.normal(size=3)
        return K.rotation_from_natural_invariants(e / np.linalg.norm(e), rng.uniform(0.2, 2.8))
    if arg.name in ("I_C", "inertia"):   # a physical inertia (the kernels check it)
        q = K.rotation_from_natural_invariants(np.array([0.0, 0.6, 0.8]), rng.uniform(0, 3))
        return q @ np.diag(rng.uniform(1.0, 2.0, size=3)) @ q.T
    if arg.name == "m":
        return np.array(rng.uniform(0.5, 2.0))
    if arg.kind == "angle":
        return rng.uniform(0.2, 2.8, size=shape)
    return rng.normal(size=shape)


def _user_reference(kernel, values: list[np.ndarray]) -> dict[str, np.ndarray]:
    """A user kernel's outputs (and its twin's Jacobians) from its sympy declaration."""
    syms, flat = [], []
    for a in kernel.args:
        if a.shape:
            m = sp.Matrix(*(a.shape if len(a.shape) == 2 else (a.shape[0], 1)),
                          lambda i, j, a=a: sp.Symbol(f"{a.name}_{i}_{j}"))
            syms.append(m)
            flat.append(list(m))
        else:
            s = sp.Symbol(a.name)
            syms.append(s)
            flat.append([s])
    exprs = kernel.build(*syms)
    subs = {s: float(v) for f, v in zip(flat, values, strict=True)
            for s, v in zip(f, np.ravel(v), strict=True)}
    out = {}
    for name, e in exprs.items():
        comps = list(e) if isinstance(e, sp.MatrixBase) else [e]
        out[name] = np.array([float(c.evalf(30, subs=subs)) for c in comps])
        for a, f in zip(kernel.args, flat, strict=True):
            out[f"{name}_D_{a.name}"] = np.array(
                [float(sp.diff(c, s).evalf(30, subs=subs)) for c in comps for s in f])
    return out


def reference(name: str, user: dict, values: list[np.ndarray]) -> dict[str, np.ndarray]:
    """Kernel ``name``'s outputs, flattened row-major: the NumPy kernels' (a Jacobian twin's
    by :func:`rigidsym.kernels.jacobian`), a user kernel's by its declaration."""
    from rigidsym import kernels as K
    from rigidsym.codegen.derivatives.jacobians import SUFFIX

    base = name[:-len(SUFFIX)] if name.endswith(SUFFIX) else name
    if base in user:
        return _user_reference(user[base], values)
    decl = {k.name: k for k in __import__("rigidsym.derivations.kernels_spec",
                                          fromlist=["KERNELS"]).KERNELS}[base]
    outs = [o.name for o in decl.outputs]
    if name == base:
        got = getattr(K, base)(*values)
        got = got if isinstance(got, tuple) else (got,)
        return {o: np.ravel(v) for o, v in zip(outs, got, strict=True)}
    vals, jac = K.jacobian(base)(*values)
    vals = vals if isinstance(vals, tuple) else (vals,)
    res = {o: np.ravel(v) for o, v in zip(outs, vals, strict=True)}
    for o in outs:
        for a in decl.args:
            res[f"{o}_D_{a.name}"] = np.ravel(jac[o][a.name])
    return res


# --- the application ----------------------------------------------------------------------

def _literal(v: float, ctype: str) -> str:
    return f"{np.float32(v)!r}".replace("np.float32(", "").rstrip(")") + "f" \
        if ctype == "float" else repr(float(v))


def _eigen_type(shape: tuple, ctype: str, row_major: bool) -> str:
    if len(shape) == 1:
        return f"Eigen::Matrix<{ctype}, 1, {shape[0]}>" if row_major else \
            f"Eigen::Matrix<{ctype}, {shape[0]}, 1>"
    order = ", Eigen::RowMajor" if row_major else ""
    return f"Eigen::Matrix<{ctype}, {shape[0]}, {shape[1]}{order}>"


def _nested(shape: tuple, ctype: str) -> str:
    t = ctype
    for d in reversed(shape):
        t = f"std::array<{t}, {d}>"
    return t


def _call(kc, ctype: str, values, flavour: str, tag: str) -> list[str]:
    """C++ lines that call ``kc`` with ``values`` in ``flavour`` and print ``tag flavour
    status output values...`` per output. Flavours: ``arrays`` (nested std::array), ``col``
    (column-major Eigen matrices, column vectors), ``row`` (row-major, row vectors: read in
    place), ``expr`` (a strided row of a bigger matrix, a matrix expression: copied)."""
    k = kc.kernel
    lines, names = ["{"], []
    for i, (a, v) in enumerate(zip(k.args, values, strict=True)):
        shape = tuple(a.shape)
        lits = ", ".join(_literal(x, ctype) for x in np.ravel(v))
        n = f"in{i}"
        if not shape:
            lines.append(f"    const {ctype} {n} = {lits};")
        elif flavour == "arrays":
            lines.append(f"    {_nested(shape, ctype)} {n};")
            lines.append(f"    {{ const {ctype} f[] = {{{lits}}}; std::size_t c = 0; "
                         f"fill(f, c, {n}); }}")
        elif flavour == "expr" and len(shape) == 1:   # a strided view: copied element-wise
            lines.append(f"    Eigen::Matrix<{ctype}, 2, {shape[0]}> {n}_big;")
            lines.append(f"    {n}_big.row(0) << {lits};")
            lines.append(f"    {n}_big.row(1).setZero();")
            n = f"{n}_big.row(0)"
        else:
            lines.append(f"    {_eigen_type(shape, ctype, flavour == 'row')} {n};")
            lines.append(f"    {n} << {lits};")     # the comma initializer: row by row
            if flavour == "expr":    # an expression without storage: evaluated, copied
                n = f"({n} * {ctype}(1))"
        names.append(n)
    ns = "arrays" if flavour == "arrays" else "eigen"
    lines.append(f"    const auto r = rigidsym::{ns}::{k.name}({', '.join(names)});")
    for o in k.outputs:
        lines.append(f'    std::printf("{tag} {flavour} %d {o.name}", '
                     f"static_cast<int>(r.status));")
        lines.append(f"    show(r.{o.name});")
        lines.append('    std::printf("\\n");')
    lines.append("}")
    return lines


APP_HEAD = r"""// generated by tests/test_cpp_target.py
#include <array>
#include <cstddef>
#include <cstdio>
#include "rigidsym_c.hpp"

template <class S> static void fill(const S *f, std::size_t &c, S &x) { x = f[c++]; }
template <class S, class T, std::size_t N>
static void fill(const S *f, std::size_t &c, std::array<T, N> &x) {
    for (T &y : x) fill(f, c, y);
}
static void show(double x) { std::printf(" %.17g", x); }
static void show(float x) { std::printf(" %.9g", static_cast<double>(x)); }
template <class T, std::size_t N> static void show(const std::array<T, N> &x) {
    for (const T &y : x) show(y);
}
#if RIGIDSYM_C_EIGEN
template <class D> static void show(const Eigen::MatrixBase<D> &x) {
    for (Eigen::Index i = 0; i < x.rows(); ++i)
        for (Eigen::Index j = 0; j < x.cols(); ++j) show(x(i, j));
}
#endif

int main() {
"""


def write_app(folder: Path, codes, flavours: tuple[str, ...]) -> tuple[str, dict]:
    """The application's source, and per tag its inputs: ``{tag: (kernel name, ctype,
    [values])}``."""
    rng = np.random.default_rng(66)
    body, cases = [], {}
    for kc in codes:
        # the thorough run calls each kernel at a seeded one of its SAMPLES (every kernel,
        # type and flavour each run; all samples in the exhaustive profile): the calls are
        # what the C++ compiler spends its time on. Every sample is drawn, so each keeps
        # its values in either profile
        samples = [(s, [_input(a, rng) for a in kc.kernel.args]) for s in range(SAMPLES)]
        for s, values in _profile.share(samples, 1 / SAMPLES,
                                        key=lambda sv, n=kc.kernel.name: f"{n}/{sv[0]}"):
            for ctype in ("double", "float"):
                tag = f"{kc.kernel.name}/{ctype}/{s}"
                cases[tag] = (kc.kernel.name, ctype, values)
                for fl in flavours:
                    body += _call(kc, ctype, values, fl, tag)
    return APP_HEAD + "\n".join("    " + x for x in body) + "\n    return 0;\n}\n", cases


def parse(stdout: str) -> dict:
    """``{(tag, flavour, output): (status, [values as printed])}``."""
    out = {}
    for line in stdout.splitlines():
        tag, flavour, status, name, *vals = line.split()
        out[tag, flavour, name] = (int(status), vals)
    return out


CMAKE = """cmake_minimum_required(VERSION 3.13)
project(rigidsym_cpp_test LANGUAGES C CXX)
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
add_subdirectory(kernels)
add_executable(app app.cpp)
# -O2: the warnings that need the optimiser's analysis (-Wmaybe-uninitialized) too
target_compile_options(app PRIVATE -O2 {warnings})
target_link_libraries(app PRIVATE rigidsym_c::rigidsym_c Eigen3::Eigen)
add_executable(app_no_eigen app_no_eigen.cpp)
target_compile_options(app_no_eigen PRIVATE {warnings})
target_link_libraries(app_no_eigen PRIVATE rigidsym_c::rigidsym_c)
"""


@pytest.mark.slow  # compiles 8 kernels, builds two C++ programs (one at -O2): 40-120 s
@pytest.mark.parametrize("cc,cxx", [("gcc", "g++"), ("clang", "clang++")])
def test_every_kernel_same_in_every_layout_and_right(generated, tmp_path, cc, cxx):
    """Column-major and row-major Eigen matrices, strided views and expressions, and
    std::array give the same bits, and
    the answers are the NumPy kernels' (1e-12 double, 1e-5 float, relative to the output's
    largest magnitude); built warning-free under strict warning flags, the C under a project's
    ``-Ofast -Werror`` with no build type (clang's -Woverriding-t-option)."""
    if shutil.which("cmake") is None:
        pytest.skip("cmake is not installed")
    if shutil.which(cc) is None or shutil.which(cxx) is None:
        pytest.skip(f"{cc} or {cxx} is not installed")
    if _eigen_dir() is None:
        pytest.skip("Eigen is not installed (Debian: libeigen3-dev)")
    folder, codes = generated
    shutil.copytree(folder, tmp_path / "kernels")
    src, cases = write_app(folder, codes, ("arrays", "col", "row", "expr"))
    (tmp_path / "app.cpp").write_text(src, encoding="utf-8")
    plain, _ = write_app(folder, codes, ("arrays",))
    (tmp_path / "app_no_eigen.cpp").write_text(plain, encoding="utf-8")
    (tmp_path / "CMakeLists.txt").write_text(CMAKE.format(warnings=" ".join(WARNINGS)),
                                             encoding="utf-8")
    build = configure_and_build(tmp_path, tmp_path / "build", cc, cxx)
    got = parse(subprocess.run([str(build / "app")], check=True, capture_output=True,
                               text=True).stdout)
    plain_got = parse(subprocess.run([str(build / "app_no_eigen")], check=True,
                                     capture_output=True, text=True).stdout)
    user = {k.name: k for k in __import__("importlib").import_module(
        "rigidsym.codegen.usergen").load_user_kernels([str(USER_MODULE)])[0]}
    kernels_called = set()
    for tag, (name, ctype, values) in cases.items():
        kernels_called.add(name)
        want = reference(name, user, values)
        kc = next(c for c in codes if c.kernel.name == name)
        for o in kc.kernel.outputs:
            status, arr = got[tag, "arrays", o.name]
            assert got[tag, "col", o.name] == (status, arr), (tag, o.name)
            assert got[tag, "row", o.name] == (status, arr), (tag, o.name)
            assert got[tag, "expr", o.name] == (status, arr), (tag, o.name)
            assert plain_got[tag, "arrays", o.name] == (status, arr), (tag, o.name)
            assert status in (0, 16), (tag, status)
            v = np.array([float(x) for x in arr])
            w = want[o.name]
            assert v.shape == (math.prod(o.shape),) == w.shape, (tag, o.name)
            tol = 1e-12 if ctype == "double" else 1e-5
            scale = max(1.0, float(np.max(np.abs(w))))
            assert np.max(np.abs(v - w)) <= tol * scale * 10, (tag, o.name, v, w)
    assert kernels_called == {kc.kernel.name for kc in codes}


@pytest.mark.slow
def test_a_wrong_shape_or_scalar_type_does_not_compile(generated, tmp_path):
    """The layer's shapes are static: a 3 x 3 matrix where a vector is due, or a float
    matrix with double arguments, is a compile-time error naming the argument."""
    if shutil.which("g++") is None or _eigen_dir() is None:
        pytest.skip("g++ or Eigen is not installed")
    folder, _ = generated
    cases = {
        "Eigen::Matrix3d e = Eigen::Matrix3d::Identity();\n"
        "    (void)rigidsym::eigen::rotation_from_natural_invariants(e, 0.5);":
            "e must be an Eigen vector of size 3",
        "Eigen::Matrix<double, 3, 4> Q = Eigen::Matrix<double, 3, 4>::Zero();\n"
        "    (void)rigidsym::eigen::natural_invariants_from_rotation(Q);":
            "Q must be a 3 x 3 Eigen matrix",
        "Eigen::Matrix3f I = Eigen::Matrix3f::Identity(); Eigen::Vector3d w(1, 2, 3);\n"
        "    (void)rigidsym::eigen::newton_euler_wrench(I, 1.0f, w, w, w);":
            "omega must have the scalar type",
    }
    for body, message in cases.items():
        src = tmp_path / "bad.cpp"
        src.write_text(f'#include "rigidsym_c.hpp"\nint main() {{\n    {body}\n}}\n',
                       encoding="utf-8")
        res = subprocess.run(["g++", "-std=c++17", "-fsyntax-only", f"-I{folder}",
                              f"-I{_eigen_dir()}", str(src)], capture_output=True, text=True)
        assert res.returncode != 0
        assert message in res.stderr, res.stderr[-2000:]


# --- the header's text (default run) ------------------------------------------------------

def _toy_codes():
    from rigidsym.codegen.generator import compile_many
    from rigidsym.codegen.spec import Arg, Kernel, Out

    def f(a, s):
        return a * s

    k = Kernel(name="scaled", summary="A matrix times a scalar.", formula="B = s A",
               ids=("t:1",), sources=(f,),
               args=(Arg("A", (2, 3), "any", "a matrix"), Arg("s", (), "any", "a scalar")),
               outputs=(Out("B", (2, 3), "the product"),),
               build=lambda A, s: {"B": A * s})
    return compile_many([k], plan32=False)


def test_header_text_names_every_kernel_in_both_flavours_and_namespace():
    """The header has, for the kernel and its Jacobian twin, a std::array and an Eigen
    function calling the double and float C functions, its Eigen part guarded, a static
    shape assertion per matrix argument, and the namespace given."""
    from rigidsym.codegen.backends.cpp.target import HEADER, generate_cpp

    text = generate_cpp(_toy_codes(), "toy", namespace="acme::kin")[HEADER]
    assert "namespace acme::kin {" in text
    assert "#if __has_include(<Eigen/Core>)" in text and "#if RIGIDSYM_C_EIGEN" in text
    for name in ("scaled", "scaled_with_jacobians"):
        assert f"::rigidsym_c_{name}(" in text and f"::rigidsym_c_{name}_f32(" in text
        assert text.count(f"struct {name}_result {{") == 2      # arrays and eigen
        assert f"acme::kin::eigen::{name}: A must be a 2 x 3 Eigen matrix" in text
    # the Jacobian of a 2 x 3 output by a 2 x 3 argument: rank 4, folded to 6 x 6
    assert "Eigen::Matrix<rs_S, 6, 6, Eigen::RowMajor> B_D_A;" in text
    assert "std::array<std::array<std::array<std::array<rs_S, 3>, 2>, 3>, 2> B_D_A;" in text
    # the Eigen part is inside the guard: nothing of Eigen before it
    assert text.index("#if RIGIDSYM_C_EIGEN\n#include <Eigen/Core>") < text.index("Eigen::")


@pytest.mark.parametrize("bad", ["1abc", "a::", "class", "a__b", "std::vector<int>"])
def test_namespace_must_be_a_cpp_name(bad):
    from rigidsym.codegen.backends.cpp.target import CppTargetError, check_namespace

    with pytest.raises(CppTargetError, match="--namespace"):
        check_namespace(bad)


def test_kernel_names_the_layer_defines_are_refused():
    """A kernel named as a namespace of the layer would not compile: refused, named."""
    import dataclasses

    from rigidsym.codegen.backends.cpp.target import CppTargetError, generate_cpp

    kc = _toy_codes()[0]
    renamed = dataclasses.replace(kc, kernel=dataclasses.replace(kc.kernel, name="detail"))
    with pytest.raises(CppTargetError, match="detail"):
        generate_cpp([renamed], "toy")


# --- the example (examples/cpp) ----------------------------------------------------------

EXAMPLE = ROOT / "examples" / "cpp"
#: the generated folder the example builds on: the C example's, written with --target cpp
#: (its freshness: tests/test_c_target.py::test_example_folder_is_what_the_generator_writes)
EXAMPLE_KERNELS = ROOT / "examples" / "c" / "rigidsym_c"


@pytest.mark.slow
def test_example_builds_strict_and_matches_numpy(tmp_path):
    """The example builds warning-free under strict warning flags and prints the NumPy
    kernels' values; the transpose of Q gives the axis -e (the layer reads (i, j))."""
    from rigidsym import kernels as K

    if shutil.which("cmake") is None or shutil.which("g++") is None or _eigen_dir() is None:
        pytest.skip("cmake, g++ or Eigen is not installed")
    build = tmp_path / "build"
    subprocess.run(["cmake", "-S", str(EXAMPLE), "-B", str(build), "-DCMAKE_CXX_COMPILER=g++",
                    f"-DCMAKE_CXX_FLAGS={' '.join(WARNINGS)}"], check=True,
                   capture_output=True)
    res = subprocess.run(["cmake", "--build", str(build)], capture_output=True, text=True)
    assert res.returncode == 0, res.stdout + res.stderr
    out = subprocess.run([str(build / "kinematics")], check=True, capture_output=True,
                         text=True).stdout.splitlines()
    e = np.array([0.0, 0.6, 0.8])
    Q = K.rotation_from_natural_invariants(e, 0.3)
    lines = {" ".join(x.split()[:1 if not x.startswith(("row", "trans")) else 2]): x
             for x in out}

    def numbers(line: str) -> np.ndarray:
        return np.array([float(t) for t in line.split()
                         if re.fullmatch(r"[-+]?[\d.]+(e[-+]?\d+)?", t)])

    e_back, phi_back = K.natural_invariants_from_rotation(Q)
    want = np.array([*e_back, phi_back])
    assert np.allclose(numbers(lines["e"]), want, atol=1e-14)
    assert np.allclose(numbers(lines["row-major e"]), want, atol=1e-14)
    e_t, phi_t = K.natural_invariants_from_rotation(Q.T)
    assert np.allclose(numbers(lines["transpose e"]), [*e_t, phi_t], atol=1e-14)
    assert np.allclose(e_t, -e, atol=1e-14)      # what a silent transpose would give
    t_P = K.twist_transfer(np.array([0.1, -0.2, 0.3, 1.0, 0.5, -0.25]), np.zeros(3),
                           np.array([0.2, 0.1, 0.4]))
    assert np.allclose(numbers(lines["t_P"]), t_P, atol=1e-14)
    assert numbers(lines["status"])[0] == 0
    assert abs(numbers(lines["status"])[1] - Q[0, 1]) <= 1e-6


def test_cli_refuses_a_bad_namespace_before_compiling(tmp_path, capsys):
    """``--namespace`` is checked before any kernel is compiled, and only with
    ``--target cpp``."""
    from rigidsym.cli import main

    out = tmp_path / "k"
    code = main(["generate", "--target", "cpp", "--kernel", "twist_transfer",
                 "--namespace", "class", "--out", str(out)])
    assert code != 0 and "--namespace" in capsys.readouterr().err
    assert not out.exists()
    code = main(["generate", "--target", "c", "--namespace", "acme", "--out", str(out)])
    assert code == 2 and "only with --target cpp" in capsys.readouterr().err


@pytest.mark.slow
def test_installed_layer_by_find_package_without_eigen(tmp_path):
    """``cmake --install`` of a --target cpp folder installs the layer with the C headers;
    a program found by find_package uses its std::array part where no Eigen is on the
    include path (RIGIDSYM_C_EIGEN is then 0)."""
    from rigidsym import kernels as K

    if shutil.which("cmake") is None or shutil.which("g++") is None:
        pytest.skip("cmake or g++ is not installed")
    if Path("/usr/include/Eigen/Core").is_file():
        pytest.skip("Eigen is on the default include path here")
    build, prefix, app = tmp_path / "build", tmp_path / "prefix", tmp_path / "app"
    for cmd in (["cmake", "-S", str(EXAMPLE_KERNELS), "-B", str(build),
                 f"-DCMAKE_INSTALL_PREFIX={prefix}"], ["cmake", "--build", str(build)],
                ["cmake", "--install", str(build)]):
        subprocess.run(cmd, check=True, capture_output=True)
    assert (prefix / "include" / "rigidsym_c" / "rigidsym_c.hpp").is_file()
    app.mkdir()
    (app / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.13)\nproject(app LANGUAGES C CXX)\n"
        "find_package(rigidsym_c REQUIRED)\nadd_executable(app app.cpp)\n"
        "target_compile_features(app PRIVATE cxx_std_11)\n"
        f"target_compile_options(app PRIVATE {' '.join(WARNINGS)})\n"
        "target_link_libraries(app PRIVATE rigidsym_c::rigidsym_c)\n", encoding="utf-8")
    (app / "app.cpp").write_text(
        '#include <cstdio>\n#include "rigidsym_c.hpp"\n'
        'static_assert(RIGIDSYM_C_EIGEN == 0, "no Eigen on this include path");\n'
        "int main() {\n    const std::array<double, 3> e = {{0.0, 0.6, 0.8}};\n"
        "    const auto r = rigidsym::arrays::rotation_from_natural_invariants(e, 0.3);\n"
        '    std::printf("%d", static_cast<int>(r.status));\n'
        '    for (const auto &row : r.Q) for (double x : row) std::printf(" %.17g", x);\n'
        "    return 0;\n}\n", encoding="utf-8")
    subprocess.run(["cmake", "-S", str(app), "-B", str(app / "b"), "-DCMAKE_CXX_COMPILER=g++",
                    f"-DCMAKE_PREFIX_PATH={prefix}"], check=True, capture_output=True)
    res = subprocess.run(["cmake", "--build", str(app / "b")], capture_output=True, text=True)
    assert res.returncode == 0, res.stdout + res.stderr
    out = subprocess.run([str(app / "b" / "app")], check=True, capture_output=True,
                         text=True).stdout.split()
    assert out[0] == "0"
    want = K.rotation_from_natural_invariants(np.array([0.0, 0.6, 0.8]), 0.3).ravel()
    assert np.allclose([float(x) for x in out[1:]], want, atol=1e-15)
