"""Configure and build a CMake project for the tests of generated C and C++ (the C++
layer's, the --prefix folders'): one place for the commands and their failure report."""

from __future__ import annotations

import subprocess
from pathlib import Path


def configure_and_build(src: Path, build: Path, cc: str, cxx: str,
                        c_flags: str = "-Ofast -Werror", extra: tuple[str, ...] = ()) -> Path:
    """``cmake -S src -B build`` with the compilers ``cc``/``cxx`` and ``CMAKE_C_FLAGS``
    ``c_flags`` (default: a project's ``-Ofast -Werror``, which the kernels' own flags must
    survive) and the ``extra`` options, then ``cmake --build`` on two cores; returns
    ``build``. A failing step fails
    the test with CMake's and the compiler's output."""
    res = subprocess.run(["cmake", "-S", str(src), "-B", str(build), f"-DCMAKE_C_COMPILER={cc}",
                          f"-DCMAKE_CXX_COMPILER={cxx}", f"-DCMAKE_C_FLAGS={c_flags}", *extra],
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stdout + res.stderr
    res = subprocess.run(["cmake", "--build", str(build), "-j", "2"], capture_output=True,
                         text=True)
    assert res.returncode == 0, res.stdout + res.stderr
    return build
