"""The C and C++ targets spell a kernel's names in a namespace of their own: a kernel whose
argument names are the generated code's own identifiers (its locals, the CSE temporaries,
the C library's functions and macros, the C++ layer's locals) or C and C++ keywords
generates C and C++ that compile, and the C computes what the declaration says."""

from __future__ import annotations

import ctypes
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from _profile import examples
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

GCC = shutil.which("gcc")
GXX = shutil.which("g++")
needs_gcc = pytest.mark.skipif(GCC is None, reason="gcc is not installed")
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]

#: names the generated C or C++ uses for itself (locals of the templates, CSE temporaries,
#: the C library, macros, the C++ layer's locals and template parameters, the spellings of
#: other names) and C / C++ keywords that Python allows as a name
INTERNAL = ("status singular finite odd count j args sizes t1 t2 rs_t1 rs_k0_ k_ q_ s_ v_ "
            "env_ i_ all_ done_ still_ x0 trig_0 in_x w_x sc_x c0_x out_x result S D0 "
            "buf_x cp_x sqrt sqrtf sinf fabs NAN INFINITY errno size_t uint64_t Eigen "
            "detail").split()
KEYWORDS = ("int double float char long short auto register static const volatile restrict "
            "inline switch case default goto sizeof struct union enum typedef extern signed "
            "unsigned void do new delete this template typename namespace operator private "
            "public virtual bool using explicit friend mutable throw catch").split()
#: an output is a member of the C++ layer's result: a keyword or ``status`` cannot be one;
#: nor can a name ending in _ (its Jacobian ``<output>_D_<argument>`` would hold a __,
#: reserved in C++)
OUTPUT_NAMES = [n for n in INTERNAL if n != "status" and not n.endswith("_")]


def _module(s1: str, u: str, v: str, s2: str, y: str, z: str) -> str:
    """A user module of one kernel: y = s1 (u x v) + s2 u / (1 + |v|), z = s1 s2 (the
    division and root give it a rescue and a finite test; the names as given)."""
    return f'''import sympy as sp
from rigidsym.codegen.spec import Arg, Kernel, Out


def mixed(s1, u, v, s2):
    return s1 * u.cross(v) + s2 * u / (1 + sp.sqrt(v.dot(v)))


def product(s1, s2):
    return s1 * s2


KERNELS = [Kernel(
    name="mixed", summary="s", formula="y = s1 u x v + s2 u / (1 + |v|)", ids=("t:m",),
    sources=(mixed, product),
    args=(Arg({s1!r}, (), "any", "a"), Arg({u!r}, (3,), "any", "b"),
          Arg({v!r}, (3,), "any", "c"), Arg({s2!r}, (), "any", "d")),
    outputs=(Out({y!r}, (3,), "y"), Out({z!r}, (), "z")),
    build=lambda **kw: {{{y!r}: mixed(kw[{s1!r}], kw[{u!r}], kw[{v!r}], kw[{s2!r}]),
                         {z!r}: product(kw[{s1!r}], kw[{s2!r}])}})]
'''


def _generate(tmp: Path, names: tuple, target: str) -> Path:
    from rigidsym.cli import main

    mod = tmp / "named.py"
    mod.write_text(_module(*names))
    out = tmp / target
    assert main(["generate", "--target", target, "--module", str(mod), "--out", str(out),
                 "--no-measure"]) == 0
    return out


def _values(so: Path, names: tuple) -> None:
    """The C function's outputs against NumPy at an ordinary point (double) and the float
    function's at a rescued one (u at 1e-30: power-of-two scaling), both status 0."""
    lib = ctypes.CDLL(str(so))
    s1, s2 = 1.5, -0.25
    u, v = np.array([1.0, 2.0, -0.5]), np.array([0.25, -1.0, 3.0])
    for fn, dt, scale, rtol in (("rigidsym_c_mixed", np.float64, 1.0, 1e-14),
                                ("rigidsym_c_mixed_f32", np.float32, 1e-30, 2e-6)):
        ct = ctypes.c_double if dt == np.float64 else ctypes.c_float
        uu, vv = (u * scale).astype(dt), v.astype(dt)
        y, z = np.zeros(3, dt), np.zeros(1, dt)
        f = getattr(lib, fn)
        f.restype = ctypes.c_int
        ptr = ctypes.POINTER(ct)
        status = f(ct(s1), uu.ctypes.data_as(ptr), vv.ctypes.data_as(ptr), ct(s2),
                   y.ctypes.data_as(ptr), z.ctypes.data_as(ptr))
        u64, v64 = uu.astype(float), vv.astype(float)
        want = s1 * np.cross(u64, v64) + s2 * u64 / (1 + np.linalg.norm(v64))
        assert status == 0, (fn, names, status)
        assert np.allclose(y, want, rtol=rtol, atol=0), (fn, names, y, want)
        assert z[0] == dt(s1 * s2), (fn, names, z)


def _compile_c(out: Path, tmp: Path, names: tuple) -> Path:
    so = tmp / "libnamed.so"
    subprocess.run([GCC, *STRICT, "-O1", "-shared", "-fPIC",
                    *map(str, sorted(out.glob("*.c"))), "-o", str(so), "-lm"], check=True)
    return so


@needs_gcc
def test_keywords_and_the_generated_codes_own_names_as_arguments_compile(tmp_path):
    """One kernel whose arguments are `int`, `status`, `t1` (beside `rs_t1`'s former
    spelling) and `sqrt`, and whose outputs are `x0` (the first CSE temporary's name) and
    `count`: the C compiles under -Werror and gives the declared values (ordinary double,
    rescued float)."""
    names = ("int", "status", "t1", "sqrt", "x0", "count")
    out = _generate(tmp_path, names, "c")
    _values(_compile_c(out, tmp_path, names), names)


@pytest.mark.slow
@pytest.mark.skipif(GCC is None or GXX is None, reason="gcc or g++ is not installed")
@settings(max_examples=examples(4), deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(st.sampled_from(INTERNAL + KEYWORDS), min_size=4, max_size=4, unique=True),
       st.lists(st.sampled_from(OUTPUT_NAMES), min_size=2, max_size=2, unique=True))
def test_any_drawn_names_compile_in_c_and_cpp(tmp_path_factory, args, outs):
    """Arguments drawn from the generated code's own names and the C / C++ keywords, outputs
    from its names: the C target compiles under -Werror as C and its functions give the
    declared values; the C++ layer (with Eigen where found) compiles under -Werror."""
    names = (*args, *(o for o in outs if o not in args))
    if len(names) != 6:     # an output drawn as one of the arguments: draw again
        return
    tmp = tmp_path_factory.mktemp("names")
    out = _generate(tmp, names, "cpp")
    _values(_compile_c(out, tmp, names), names)
    app = tmp / "app.cpp"
    app.write_text('#include "rigidsym_c.hpp"\n#include <array>\n'
                   "int main() {\n    std::array<double, 3> u{{1, 2, -0.5}}, v{{0.25, -1, 3}};\n"
                   "    return static_cast<int>(rigidsym::arrays::mixed(1.5, u, v, -0.25)"
                   ".status);\n}\n")
    eigen = [f"-I{p}" for p in ("/usr/include/eigen3",) if Path(p).is_dir()]
    subprocess.run([GXX, "-std=c++14", "-Wall", "-Wextra", "-Werror", *eigen, "-I", str(out),
                    "-fsyntax-only", str(app)], check=True)
