"""``rigidsym generate --target c|cpp --prefix NAME``: every name a
generated folder exports carries the prefix, so that two folders (the book's kernels with
the default prefix, a user module with ``--prefix mybot``) link into one program.

The default-run tests generate a one-kernel toy folder in memory: its files, macros, C
functions, CMake target, pkg-config module and C++ namespace carry the prefix, nothing is
left of the default one but the template names, the objects' global symbols (``nm``)
all start with the prefix, and a program calling the same kernel from a folder of each
prefix links and gives the same bits; bad prefixes are refused, naming ``--prefix``. The
slow tests build, with CMake (gcc and clang), a C and a C++ program on the book's folder
and a user module's ``--prefix mybot`` folder that share a kernel, under ``-Werror``, and
check the answers against NumPy; install both into one prefix and find them by
``find_package`` and ``pkg-config``; and regenerate a folder under a new prefix.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from _cmake import configure_and_build

pytestmark = pytest.mark.xdist_group("c_prefix")  # its module fixtures built on one worker

ROOT = Path(__file__).resolve().parents[1]
USER_MODULE = ROOT / "examples" / "c" / "my_kernels.py"
#: the warning flags of a strict C++ application
WARNINGS = ["-Wall", "-Wextra", "-Wpedantic", "-Werror", "-Wconversion",
            "-Wdouble-promotion", "-Wshadow"]
C_STRICT = ["-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]
#: the generated files whose names carry no prefix
UNPREFIXED = {"CMakeLists.txt", "README.md", "LICENSE"}
GCC = shutil.which("gcc")


@pytest.fixture(scope="module")
def codes():
    """A one-kernel module compiled as the generator compiles it: the moment r x f."""
    from rigidsym.codegen.generator import compile_many
    from rigidsym.codegen.spec import Arg, Kernel, Out

    def moment(r, f):
        return r.cross(f)

    k = Kernel(name="lever", summary="The moment of a force about a point.",
               formula="n = r x f", ids=("t:lever",), sources=(moment,),
               args=(Arg("r", (3,), "any", "arm [m]"), Arg("f", (3,), "any", "force [N]")),
               outputs=(Out("n", (3,), "moment [N m]"),),
               build=lambda r, f: {"n": moment(r, f)})
    return compile_many([k], plan32=False)


@pytest.fixture(scope="module")
def folders(codes):
    """The toy's files under the default prefix and under ``acme`` (C, single header,
    C++ layer): ``(default files, acme files)``."""
    from rigidsym.codegen.backends.c.target import generate_c
    from rigidsym.codegen.backends.cpp.target import generate_cpp

    out = []
    for prefix in ("rigidsym_c", "acme"):
        files = generate_c(codes, "toy", single_header=True, prefix=prefix)
        files.update(generate_cpp(codes, "toy", prefix=prefix))
        out.append(files)
    return tuple(out)


def test_every_file_and_name_carries_the_prefix(folders):
    """File names, the macros defined (include guards too), declared functions, the CMake
    target (alias, export, package) and the pkg-config module carry ``acme``; of the
    default prefix only the template names of the provenance lines are left."""
    default, acme = folders
    assert len(acme) == len(default)
    assert {p for p in acme if not p.startswith("acme")} == UNPREFIXED
    assert {"acme.h", "acme_common.h", "acme_lever.c", "acme.hpp", "acme_single.h",
            "acme.pc.in", "acmeConfig.cmake.in"} <= set(acme)
    for path, text in acme.items():
        left = re.findall(r"[\w.]*(?:rigidsym_c|RIGIDSYM_C)[\w.]*", text)
        assert all(x.rstrip(".").endswith(".j2") for x in left), (path, sorted(set(left)))
        for macro in re.findall(r"#\s*define\s+(\w+)", text):
            assert macro.startswith("ACME_"), (path, macro)
        for fn in re.findall(r"ACME_API\s+\w+\s+(\w+)\(", text):
            assert fn.startswith("acme_lever"), (path, fn)
        if path.endswith((".h", ".c", ".hpp")):
            assert "`rigidsym generate --target c" in text and "--prefix acme`" in text
    assert len(re.findall(r"ACME_API\s+\w+\s+(\w+)\(", acme["acme_lever.h"])) >= 4
    cmake = acme["CMakeLists.txt"]
    for line in ("project(acme ", "add_library(acme\n", "add_library(acme::acme ALIAS acme)",
                 "EXPORT acmeTargets NAMESPACE acme::", "${CMAKE_INSTALL_INCLUDEDIR}/acme)"):
        assert line in cmake, line
    pc = acme["acme.pc.in"]
    assert "Name: acme\n" in pc and "-lacme " in pc and "@CMAKE_INSTALL_INCLUDEDIR@/acme\n" in pc
    hpp = acme["acme.hpp"]
    assert "namespace acme {" in hpp and '#include "acme.h"' in hpp and "::acme_lever(" in hpp


def test_the_namespace_defaults_to_the_prefix(codes):
    """``--prefix acme`` puts the C++ layer in ``namespace acme``; ``--namespace`` still
    names another; the default prefix keeps ``rigidsym``."""
    from rigidsym.codegen.backends.cpp.target import generate_cpp

    assert "namespace acme {" in generate_cpp(codes, "toy", prefix="acme")["acme.hpp"]
    text = generate_cpp(codes, "toy", namespace="kin::arm", prefix="acme")["acme.hpp"]
    assert "namespace kin::arm {" in text and "namespace acme" not in text
    assert "namespace rigidsym {" in generate_cpp(codes, "toy")["rigidsym_c.hpp"]


def _write(files: dict[str, str], d: Path) -> Path:
    d.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (d / name).write_text(text, encoding="utf-8")
    return d


@pytest.mark.skipif(GCC is None, reason="gcc is not installed")
def test_two_prefixes_link_into_one_program_and_export_only_prefixed_symbols(folders,
                                                                             tmp_path):
    """Both folders' objects in one program (both ``lever`` functions, the same shared
    helpers in each): it links, each object's global symbols start with its prefix, and
    the two functions give the same bits, the cross product."""
    default, acme = folders
    dirs = {"rigidsym_c": _write(default, tmp_path / "d"), "acme": _write(acme, tmp_path / "a")}
    objs = []
    for prefix, d in dirs.items():
        o = tmp_path / f"{prefix}.o"
        subprocess.run([GCC, *C_STRICT, "-O2", "-c", str(d / f"{prefix}_lever.c"), "-o", str(o)],
                       check=True)
        nm = subprocess.run(["nm", "-g", "--defined-only", str(o)], check=True,
                            capture_output=True, text=True).stdout.split()[2::3]
        assert nm and all(s.startswith(f"{prefix}_") for s in nm), (prefix, nm)
        objs.append(str(o))
    (tmp_path / "main.c").write_text(
        '#include <stdio.h>\n#include "rigidsym_c.h"\n#include "acme.h"\n'
        "int main(void) {\n    const double r[3] = {0.5, -1.25, 2.0}, f[3] = {3.0, 0.75, -1.5};\n"
        "    double n1[3], n2[3];\n    int s1 = rigidsym_c_lever(r, f, n1), "
        "s2 = acme_lever(r, f, n2);\n"
        '    printf("%d %d", s1 == RIGIDSYM_C_OK, s2 == ACME_OK);\n'
        '    for (int i = 0; i < 3; ++i) printf(" %.17g %.17g", n1[i], n2[i]);\n'
        "    return 0;\n}\n", encoding="utf-8")
    exe = tmp_path / "app"
    subprocess.run([GCC, *C_STRICT, "-I", str(dirs["rigidsym_c"]), "-I", str(dirs["acme"]),
                    str(tmp_path / "main.c"), *objs, "-o", str(exe), "-lm"], check=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout.split()
    assert out[:2] == ["1", "1"]
    n1, n2 = out[2::2], out[3::2]
    assert n1 == n2
    want = np.cross([0.5, -1.25, 2.0], [3.0, 0.75, -1.5])
    assert np.array_equal([float(x) for x in n1], want)   # exact in binary here


@pytest.mark.parametrize("bad", ["Acme", "1acme", "ac-me", "a__b", "acme_", "_acme", "",
                                 "class", "namespace", "std", "int", "rigidsym",
                                 "rigidsym_c_extra", "a_b", "my_bot"])
def test_bad_prefixes_are_refused_by_name(bad):
    from rigidsym.codegen.backends.c.prefix import PrefixError, check_prefix

    with pytest.raises(PrefixError, match="--prefix"):
        check_prefix(bad)


def test_a_prefix_with_an_underscore_is_refused_naming_the_clash():
    """``--prefix a_b`` is refused: its ``a_b_<kernel>`` would be the names of ``--prefix
    a``'s kernels ``b_<kernel>`` (two folders that cannot see each other), and the error
    says so and proposes a name without ``_``; ``a`` and ``ab`` are accepted."""
    from rigidsym.codegen.backends.c.prefix import PrefixError, check_prefix

    with pytest.raises(PrefixError) as err:
        check_prefix("a_b")
    msg = str(err.value)
    assert "--prefix" in msg and "'a'" in msg and "b_<kernel>" in msg and "'ab'" in msg
    assert check_prefix("a") == "a" and check_prefix("ab") == "ab"


def _names(files: dict[str, str]) -> set[str]:
    """What a generated folder defines: its file names, macros, exported functions and
    types, and the CMake target."""
    out = set(files) - UNPREFIXED
    for text in files.values():
        out |= set(re.findall(r"#\s*define\s+(\w+)", text))
        out |= set(re.findall(r"_API\s+\w+\s+(\w+)\(", text))
        out |= set(re.findall(r"typedef\s[^;]*?\b(\w+)\s*;", text))
        out |= set(re.findall(r"add_library\((\w+)", text))
    return out


def test_prefixes_that_begin_one_another_share_no_name(codes):
    """Folders of the prefixes ``a``, ``ab`` and the default (one beginning another's
    names, as far as ``_`` allows) define no name in common: each name starts with its own
    prefix followed by no lower-case letter or digit."""
    from rigidsym.codegen.backends.c.target import generate_c
    from rigidsym.codegen.backends.cpp.target import generate_cpp

    names = {}
    for prefix in ("a", "ab", "rigidsym_c"):
        files = generate_c(codes, "toy", single_header=True, prefix=prefix)
        files.update(generate_cpp(codes, "toy", prefix=prefix))
        names[prefix] = _names(files)
        assert len(names[prefix]) > 20
        for n in names[prefix]:
            assert re.match(f"(?:{prefix}|{prefix.upper()})(?![a-z0-9])", n), (prefix, n)
    assert not names["a"] & names["ab"]
    assert not names["a"] & names["rigidsym_c"] and not names["ab"] & names["rigidsym_c"]


def test_generate_refuses_a_bad_prefix_and_accepts_the_default(codes):
    from rigidsym.codegen.backends.c.prefix import DEFAULT_PREFIX, check_prefix
    from rigidsym.codegen.backends.c.target import generate_c
    from rigidsym.codegen.backends.cpp.target import generate_cpp

    with pytest.raises(ValueError, match="--prefix"):
        generate_c(codes, "toy", prefix="My-Bot")
    with pytest.raises(ValueError, match="--prefix"):
        generate_cpp(codes, "toy", prefix="rigidsym_c_two")
    assert check_prefix(DEFAULT_PREFIX) == DEFAULT_PREFIX


def test_cli_refuses_a_bad_prefix_before_compiling(tmp_path, capsys):
    """``--prefix`` is checked before any kernel is compiled, and only with --target c or
    cpp."""
    from rigidsym.cli import main

    out = tmp_path / "k"
    code = main(["generate", "--target", "c", "--kernel", "twist_transfer", "--prefix",
                 "My-Bot", "--out", str(out)])
    assert code == 2 and "--prefix" in capsys.readouterr().err
    assert not out.exists()
    code = main(["generate", "--prefix", "acme", "--out", str(out)])
    assert code == 2 and "only with --target c or cpp" in capsys.readouterr().err


def test_a_folder_of_any_prefix_is_recognised_as_generated(folders, tmp_path):
    """The marker of a generated folder is ``<prefix>_common.h``: a folder of another
    prefix is still generated (a regeneration under a new prefix may replace it), a
    folder of someone's own ``*_common.h`` is not."""
    from rigidsym.codegen.backends.c.prefix import generated_marker

    default, acme = folders
    d = _write(default, tmp_path / "d")
    a = _write(acme, tmp_path / "a")
    assert generated_marker(d) == d / "rigidsym_c_common.h"
    assert generated_marker(d, "acme") == d / "rigidsym_c_common.h"
    assert generated_marker(a, "acme") == a / "acme_common.h"
    assert generated_marker(a) == a / "acme_common.h"
    own = tmp_path / "own"
    own.mkdir()
    (own / "motor_common.h").write_text("/* my own header */\n", encoding="utf-8")
    assert generated_marker(own, "acme") is None
    assert generated_marker(tmp_path / "none") is None


# --- slow: two folders in one CMake program ------------------------------------------------

@pytest.fixture(scope="module")
def book_and_mybot(tmp_path_factory):
    """The book's twist transfer with the default prefix, and the example's user module
    with the same book kernel under ``--prefix mybot``, both with the C++ layer, written by
    the command line: ``(book folder, mybot folder)``."""
    from rigidsym.cli import main

    base = tmp_path_factory.mktemp("prefix")
    book, mybot = base / "book", base / "mybot"
    assert main(["generate", "--target", "cpp", "--kernel", "twist_transfer",
                 "--out", str(book)]) == 0
    assert main(["generate", "--target", "cpp", "--module", str(USER_MODULE), "--kernel",
                 "twist_transfer", "--prefix", "mybot", "--out", str(mybot)]) == 0
    return book, mybot


T_A = [0.1, -0.2, 0.3, 1.0, 0.5, -0.25]
A_PT = [0.3, -0.1, 0.2]
P_PT = [0.2, 0.1, 0.4]
ARM = [0.4, 0.9, 1.5, 0.75]       # q1, q2, l1, l2

MAIN_C = """#include <stdio.h>
#include "rigidsym_c.h"
#include "mybot.h"
static void show(const char *tag, int status, const double *x, int n) {
    printf("%s %d", tag, status);
    for (int i = 0; i < n; ++i) printf(" %.17g", x[i]);
    printf("\\n");
}
int main(void) {
    const double t_A[6] = {T_A}, a[3] = {A_PT}, p[3] = {P_PT};
    double t1[6], t2[6], tip[2];
    show("book_twist", rigidsym_c_twist_transfer(t_A, a, p, t1) == RIGIDSYM_C_OK, t1, 6);
    show("mybot_twist", mybot_twist_transfer(t_A, a, p, t2) == MYBOT_OK, t2, 6);
    show("mybot_tip", mybot_planar_arm_tip(ARM, tip) == MYBOT_OK, tip, 2);
    return 0;
}
"""

MAIN_CPP = """#include <cstdio>
#include "rigidsym_c.hpp"
#include "mybot.hpp"
template <class A> static void show(const char *tag, bool ok, const A &x) {
    std::printf("%s %d", tag, static_cast<int>(ok));
    for (double v : x) std::printf(" %.17g", v);
    std::printf("\\n");
}
int main() {
    const std::array<double, 6> t_A = {{T_A}};
    const std::array<double, 3> a = {{A_PT}}, p = {{P_PT}};
    const auto r1 = rigidsym::arrays::twist_transfer(t_A, a, p);
    const auto r2 = mybot::arrays::twist_transfer(t_A, a, p);
    const auto r3 = mybot::arrays::planar_arm_tip(ARM);
    show("book_twist", rigidsym::ok(r1.status), r1.t_P);
    show("mybot_twist", mybot::ok(r2.status), r2.t_P);
    show("mybot_tip", r3.status == mybot::Status::ok, r3.p);
#if RIGIDSYM_C_EIGEN && MYBOT_EIGEN
    const Eigen::Matrix<double, 6, 1> e_t(t_A.data());
    const Eigen::Vector3d e_a(a.data()), e_p(p.data());
    const auto r4 = mybot::eigen::twist_transfer(e_t, e_a, e_p);
    std::printf("eigen_twist %d", static_cast<int>(mybot::ok(r4.status)));
    for (int i = 0; i < 6; ++i) std::printf(" %.17g", r4.t_P(i));
    std::printf("\\n");
#endif
    return 0;
}
"""

CMAKE = """cmake_minimum_required(VERSION 3.13)
project(two_prefixes LANGUAGES C CXX)
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
add_subdirectory(book)
add_subdirectory(mybot)
add_executable(app_c main.c)
set_target_properties(app_c PROPERTIES C_STANDARD 99)
target_compile_options(app_c PRIVATE -Wall -Wextra -Wpedantic -Werror)
target_link_libraries(app_c PRIVATE rigidsym_c::rigidsym_c mybot::mybot)
add_executable(app_cpp main.cpp)
target_compile_options(app_cpp PRIVATE {warnings})
target_link_libraries(app_cpp PRIVATE rigidsym_c::rigidsym_c mybot::mybot)
{eigen}
"""


def _fill(template: str) -> str:
    for name, values in (("T_A", T_A), ("A_PT", A_PT), ("P_PT", P_PT), ("ARM", ARM)):
        template = template.replace(name, ", ".join(repr(v) for v in values))
    return template


@pytest.mark.slow  # generates 4 kernels, builds two folders and two programs: 20-90 s
@pytest.mark.parametrize("cc,cxx", [("gcc", "g++"), ("clang", "clang++")])
def test_book_and_user_folders_in_one_cmake_program(book_and_mybot, tmp_path, cc, cxx):
    """add_subdirectory of the book's folder and of a ``--prefix mybot`` user folder (both
    holding twist_transfer) into one CMake project: its C program (C99) and its C++ program
    (both layers in one translation unit, WARNINGS) build under -Werror, the C
    under a project's ``-Ofast -Werror``; both folders' twist transfer give the same bits
    and the NumPy kernel's value, the user kernel its formula's."""
    from rigidsym import kernels as K

    if shutil.which("cmake") is None or shutil.which(cc) is None or \
            shutil.which(cxx) is None:
        pytest.skip(f"cmake, {cc} or {cxx} is not installed")
    book, mybot = book_and_mybot
    shutil.copytree(book, tmp_path / "book")
    shutil.copytree(mybot, tmp_path / "mybot")
    (tmp_path / "main.c").write_text(_fill(MAIN_C), encoding="utf-8")
    (tmp_path / "main.cpp").write_text(_fill(MAIN_CPP), encoding="utf-8")
    eigen = any((Path(d) / "Eigen" / "Core").is_file()
                for d in ("/usr/include/eigen3", "/usr/local/include/eigen3"))
    (tmp_path / "CMakeLists.txt").write_text(CMAKE.format(
        warnings=" ".join(WARNINGS),
        eigen="find_package(Eigen3 3.3 REQUIRED NO_MODULE)\n"
              "target_link_libraries(app_cpp PRIVATE Eigen3::Eigen)" if eigen else ""),
        encoding="utf-8")
    build = configure_and_build(tmp_path, tmp_path / "build", cc, cxx)
    want_twist = K.twist_transfer(np.array(T_A), np.array(A_PT), np.array(P_PT))
    q1, q2, l1, l2 = ARM
    want_tip = [l1 * np.cos(q1) + l2 * np.cos(q1 + q2), l1 * np.sin(q1) + l2 * np.sin(q1 + q2)]
    for app in ("app_c", "app_cpp"):
        out = subprocess.run([str(build / app)], check=True, capture_output=True,
                             text=True).stdout.splitlines()
        got = {line.split()[0]: line.split()[1:] for line in out}
        assert all(v[0] == "1" for v in got.values()), (app, got)
        assert got["book_twist"] == got["mybot_twist"], app
        assert np.allclose([float(x) for x in got["mybot_twist"][1:]], want_twist,
                           rtol=0, atol=1e-15)
        assert np.allclose([float(x) for x in got["mybot_tip"][1:]], want_tip, rtol=0,
                           atol=1e-14)
        if app == "app_cpp" and eigen:
            assert got["eigen_twist"] == got["mybot_twist"]


@pytest.mark.slow  # generates one kernel three times: 5-20 s
def test_a_folder_regenerated_under_a_new_prefix(tmp_path, capsys):
    """A folder of the default prefix regenerated with ``--prefix mybot`` keeps no file of
    the old names; ``--check`` with the prefix finds it fresh, without it stale."""
    from rigidsym.cli import main

    out = tmp_path / "kernels"
    args = ["generate", "--target", "c", "--kernel", "twist_transfer", "--out", str(out)]
    assert main(args) == 0
    assert (out / "rigidsym_c_twist_transfer.c").is_file()
    assert main([*args, "--prefix", "mybot"]) == 0
    names = sorted(p.name for p in out.iterdir())
    assert "mybot_twist_transfer.c" in names
    assert not [n for n in names if "rigidsym" in n], names
    capsys.readouterr()
    assert main([*args, "--prefix", "mybot", "--check"]) == 0
    assert main([*args, "--check"]) == 1
    assert "--prefix" not in capsys.readouterr().err    # the default's rerun command


def _run_lines(exe: Path) -> dict[str, list[str]]:
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    return {line.split()[0]: line.split()[1:] for line in out.splitlines()}


@pytest.mark.slow  # builds and installs two folders, then two programs: 15-60 s
def test_two_folders_installed_into_one_prefix(book_and_mybot, tmp_path):
    """Both folders ``cmake --install``ed into one prefix keep apart (headers, libraries,
    CMake packages, pkg-config modules of their own names); a program finds both by
    ``find_package`` and, by one plain line, by ``pkg-config --cflags --libs rigidsym_c
    mybot``, and gets the same answers as by add_subdirectory."""
    from rigidsym import kernels as K

    if shutil.which("cmake") is None or GCC is None or shutil.which("pkg-config") is None:
        pytest.skip("cmake, gcc or pkg-config is not installed")
    prefix = tmp_path / "prefix"
    for folder in book_and_mybot:
        build = tmp_path / f"build_{folder.name}"
        for cmd in (["cmake", "-S", str(folder), "-B", str(build), "-DCMAKE_C_COMPILER=gcc",
                     f"-DCMAKE_INSTALL_PREFIX={prefix}"], ["cmake", "--build", str(build)],
                    ["cmake", "--install", str(build)]):
            res = subprocess.run(cmd, capture_output=True, text=True)
            assert res.returncode == 0, res.stdout + res.stderr
    for name in ("rigidsym_c", "mybot"):
        assert (prefix / "include" / name / f"{name}.h").is_file()
        assert (prefix / "include" / name / f"{name}.hpp").is_file()
        assert len(list(prefix.glob(f"lib*/**/cmake/{name}/{name}Config.cmake"))) == 1
        assert len(list(prefix.glob(f"lib*/**/lib{name}.a"))) == 1
    pcdir = next(prefix.glob("lib*/**/pkgconfig/mybot.pc")).parent
    app = tmp_path / "app"
    app.mkdir()
    (app / "main.c").write_text(_fill(MAIN_C), encoding="utf-8")
    (app / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.13)\nproject(app LANGUAGES C)\n"
        "find_package(rigidsym_c REQUIRED)\nfind_package(mybot REQUIRED)\n"
        "add_executable(app main.c)\nset_target_properties(app PROPERTIES C_STANDARD 99)\n"
        f"target_compile_options(app PRIVATE {' '.join(C_STRICT[1:])})\n"
        "target_link_libraries(app PRIVATE rigidsym_c::rigidsym_c mybot::mybot)\n",
        encoding="utf-8")
    configure_and_build(app, app / "b", "gcc", "g++", c_flags="-O2",
                        extra=(f"-DCMAKE_PREFIX_PATH={prefix}",))
    by_package = _run_lines(app / "b" / "app")
    flags = subprocess.run(["pkg-config", "--cflags", "--libs", "rigidsym_c", "mybot"],
                           check=True, capture_output=True, text=True,
                           env={"PKG_CONFIG_PATH": str(pcdir), "PATH": "/usr/bin:/bin"}
                           ).stdout.split()
    subprocess.run([GCC, *C_STRICT, str(app / "main.c"), *flags, "-o", str(app / "plain")],
                   check=True)
    assert _run_lines(app / "plain") == by_package
    assert by_package["book_twist"] == by_package["mybot_twist"]
    assert all(v[0] == "1" for v in by_package.values())
    want = K.twist_transfer(np.array(T_A), np.array(A_PT), np.array(P_PT))
    assert np.allclose([float(x) for x in by_package["book_twist"][1:]], want, rtol=0,
                       atol=1e-15)
