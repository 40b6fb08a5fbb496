"""A controls engineer's C++ application re-built from docs/c-api.md alone, on gcc and clang.

What a user does, and nothing the tests know: ``rigidsym generate --target cpp`` of six book
kernels (the rotation from its natural invariants, the screw of a displacement, the twist
transfer, the Newton-Euler wrench, the rotation vector and the natural invariants of a
rotation) into ``kernels/``; the docs' CMake program (``find_package(Eigen3)``,
``add_subdirectory(kernels)``, ``target_link_libraries(app PRIVATE rigidsym_c::rigidsym_c
Eigen3::Eigen)``) around ``benchmarks/engineer_app.cpp``, which calls ``rigidsym::eigen``
with column-major Eigen arguments; configured with no build type, built by gcc and by clang
with ``CMAKE_C_FLAGS``/``CMAKE_CXX_FLAGS`` each of ``-O2``, ``-O3`` and ``-Ofast`` (the
latter links crtfastmath.o: FTZ and DAZ at start-up), float and double.

Inputs: the regimes of the trial that found the status depending on the build, drawn with an
independent exponent per component: rotations by 1e-6 rad to 3 rad about axes with
components down to 1e-6 of the largest; points from 1 nm to 10 m from the origin; angular
rates from 1e-12 rad/s; the Newton-Euler wrench of a body of mass 1e-3 to 100 kg with a
principal inertia of 1e-3 to 10 kg m^2. Each value is drawn in float64 and the float run
gets it rounded to float32 (the same inputs in every build).

Judged: the status and the outputs' bits the same in all six builds, per precision; status
0 on every input (an ordinary input is never flagged); and each output against an
independent NumPy formula in long double (Rodrigues's formula, the rotation vector the
rotation was made from, the twist transfer ``[w; v + w x (p - a)]``, the wrench
``[I w' + w x I w; m c'']``, the screw's defining relation ``a' = Q (a - p0) + p0 + pitch
phi e`` with ``e . p0 = 0``), each within a tolerance of 64 units of the precision scaled by
the formula's magnitudes and conditioning (the constants in :func:`judge`). Writes per
kernel and precision the status counts per build, whether bits and statuses agree, and the
worst error over its tolerance.

    python benchmarks/engineer_app.py [--n 20000] [--json benchmarks/results/engineer_app.json]

x86-64 or aarch64 Linux with gcc, g++, clang, clang++, cmake and Eigen 3 (Debian's
libeigen3-dev); exits 1 when a judgement fails.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from test_command import host

ROOT = Path(__file__).resolve().parents[1]
APP = Path(__file__).with_name("engineer_app.cpp")
KERNELS = ("rotation_from_natural_invariants", "rotation_vector_from_rotation",
           "natural_invariants_from_rotation", "screw_of_displacement", "twist_transfer",
           "newton_euler_wrench")
#: outputs per sample, in the application's order
WIDTH = {"rotation_from_natural_invariants": 9, "rotation_vector_from_rotation": 3,
         "natural_invariants_from_rotation": 4, "screw_of_displacement": 14,
         "twist_transfer": 6, "newton_euler_wrench": 6}
COMPILERS = {"gcc": ("gcc", "g++"), "clang": ("clang", "clang++")}
FLAGS = ("-O2", "-O3", "-Ofast")
CMAKE = """cmake_minimum_required(VERSION 3.13)
project(engineer_app LANGUAGES C CXX)
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
add_subdirectory(kernels)
add_executable(app main.cpp)
target_link_libraries(app PRIVATE rigidsym_c::rigidsym_c Eigen3::Eigen)
"""


def _directions(rng, n: int, spread: float) -> np.ndarray:
    """Unit vectors whose components have independent magnitudes down to ``spread`` of the
    largest, independent signs."""
    v = rng.choice([-1.0, 1.0], (n, 3)) * 10.0 ** rng.uniform(np.log10(spread), 0, (n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def _magnitudes(rng, n: int, lo: float, hi: float) -> np.ndarray:
    return 10.0 ** rng.uniform(np.log10(lo), np.log10(hi), (n, 1))


def _rodrigues(e: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """(n, 3, 3) rotations in long double: Q = cos phi 1 + (1 - cos phi) e e^T + sin phi [e]x
    (Angeles, eq. 2.48)."""
    e = e.astype(np.longdouble)
    phi = phi.astype(np.longdouble).reshape(-1, 1, 1)
    cpm = np.zeros(e.shape[:1] + (3, 3), np.longdouble)
    cpm[:, 0, 1], cpm[:, 0, 2], cpm[:, 1, 2] = -e[:, 2], e[:, 1], -e[:, 0]
    cpm -= cpm.transpose(0, 2, 1)
    return (np.cos(phi) * np.eye(3) + (1 - np.cos(phi)) * e[:, :, None] * e[:, None, :]
            + np.sin(phi) * cpm)


def inputs(n: int, seed: int = 2026) -> dict:
    """Per kernel: (inputs as an (n, k) float64 array, what the reference needs)."""
    rng = np.random.default_rng(seed)
    e = _directions(rng, n, 1e-6)
    phi = _magnitudes(rng, n, 1e-6, 3.0)[:, 0]
    Q = _rodrigues(e, phi).astype(np.float64)
    a = _directions(rng, n, 1e-3) * _magnitudes(rng, n, 1e-9, 10.0)
    d = _directions(rng, n, 1e-3) * _magnitudes(rng, n, 1e-9, 10.0)
    a_prime = (Q.astype(np.longdouble) @ a.astype(np.longdouble)[:, :, None])[:, :, 0] + d
    a_prime = a_prime.astype(np.float64)
    w = _directions(rng, n, 1e-3) * _magnitudes(rng, n, 1e-12, 10.0)
    v = _directions(rng, n, 1e-3) * _magnitudes(rng, n, 1e-9, 10.0)
    p = _directions(rng, n, 1e-3) * _magnitudes(rng, n, 1e-9, 10.0)
    R = _rodrigues(_directions(rng, n, 1e-2), rng.uniform(0, np.pi, n)).astype(np.float64)
    lam = _magnitudes(rng, n, 1e-3, 10.0) * rng.uniform(0.2, 1.0, (n, 3))
    inertia = R @ (lam[:, :, None] * R.transpose(0, 2, 1))
    inertia = (inertia + inertia.transpose(0, 2, 1)) / 2
    m = _magnitudes(rng, n, 1e-3, 100.0)
    w_dot = _directions(rng, n, 1e-3) * _magnitudes(rng, n, 1e-9, 100.0)
    c_ddot = _directions(rng, n, 1e-3) * _magnitudes(rng, n, 1e-9, 100.0)
    flat = Q.reshape(n, 9)
    return {
        "rotation_from_natural_invariants": np.hstack([e, phi[:, None]]),
        "rotation_vector_from_rotation": flat,
        "natural_invariants_from_rotation": flat,
        "screw_of_displacement": np.hstack([flat, a, a_prime]),
        "twist_transfer": np.hstack([w, v, a, p]),
        "newton_euler_wrench": np.hstack([inertia.reshape(n, 9), m, w, w_dot, c_ddot]),
    }, {"w": e * phi[:, None], "phi": phi}


def build(work: Path, kernels_dir: Path, cc: str, cxx: str, flag: str) -> Path:
    """The docs' CMake program, configured with no build type; returns the executable."""
    src = work / "app"
    if not src.exists():
        src.mkdir()
        (src / "CMakeLists.txt").write_text(CMAKE)
        shutil.copy(APP, src / "main.cpp")
        shutil.copytree(kernels_dir, src / "kernels")
    b = work / f"build-{cc}{flag}"
    subprocess.run(["cmake", "-S", str(src), "-B", str(b), f"-DCMAKE_C_COMPILER={cc}",
                    f"-DCMAKE_CXX_COMPILER={cxx}", f"-DCMAKE_C_FLAGS={flag}",
                    f"-DCMAKE_CXX_FLAGS={flag}"], check=True, capture_output=True, text=True)
    subprocess.run(["cmake", "--build", str(b), "-j", "2"], check=True, capture_output=True,
                   text=True)
    return b / "app"


def read_out(path: Path, width: int, dtype) -> tuple[np.ndarray, np.ndarray]:
    raw = path.read_bytes()
    n = int(np.frombuffer(raw[:4], np.int32)[0])
    status = np.frombuffer(raw[4:4 + 4 * n], np.int32)
    out = np.frombuffer(raw[4 + 4 * n:], dtype).reshape(n, width)
    return status, out


def _cross(a, b):
    return np.cross(a, b)


def judge(name: str, x: np.ndarray, out: np.ndarray, made: dict, u: float) -> np.ndarray:
    """Per sample, the error over its tolerance (<= 1: right), against an independent
    formula in long double on the inputs ``x`` as the build read them."""
    L = np.longdouble
    x, o = x.astype(L), out.astype(L)
    if name == "rotation_from_natural_invariants":
        ref = _rodrigues(x[:, :3], x[:, 3]).reshape(-1, 9)
        return np.abs(o - ref).max(1) / (64 * u)
    if name in ("rotation_vector_from_rotation", "natural_invariants_from_rotation"):
        w = o[:, :3] * o[:, 3:4] if name.startswith("natural") else o
        phi = made["phi"].astype(L)
        # the log's condition grows as 1/sin(phi) towards pi; relative to |w| near 0
        tol = 64 * u * (phi + 1) / np.minimum(1, np.sin(phi) / phi)
        err = np.abs(w - made["w"].astype(L)).max(1) / tol
        if name.startswith("natural"):
            err = np.maximum(err, np.abs(np.linalg.norm(o[:, :3].astype(np.float64), axis=1)
                                         - 1) / (64 * u))
        return err
    if name == "screw_of_displacement":
        Q, a, ap = x[:, :9].reshape(-1, 3, 3), x[:, 9:12], x[:, 12:15]
        e, phi, p0, pitch = o[:, :3], o[:, 3], o[:, 4:7], o[:, 7]
        moved = (Q @ (a - p0)[:, :, None])[:, :, 0] + p0 + (pitch * phi)[:, None] * e
        scale = (np.abs(a).max(1) + np.abs(ap).max(1) + np.abs(p0).max(1))
        # p0 is d / (2 sin(phi / 2)) in size: its error grows as 1/phi
        tol = 64 * u * scale / np.minimum(1, phi)
        err = np.abs(moved - ap).max(1) / tol
        # p0's error is absolute, on the inputs' scale (p0 may be far smaller)
        err = np.maximum(err, np.abs((e * p0).sum(1)) / tol)
        pl = np.hstack([e, _cross(p0, e)])
        return np.maximum(err, np.abs(o[:, 8:14] - pl).max(1)
                          / (64 * u * (1 + np.abs(p0).max(1) / np.minimum(1, phi))))
    if name == "twist_transfer":
        w, v, a, p = x[:, :3], x[:, 3:6], x[:, 6:9], x[:, 9:12]
        ref = np.hstack([w, v + _cross(w, p - a)])
        scale = np.abs(v).max(1) + np.abs(w).max(1) * (np.abs(p).max(1) + np.abs(a).max(1))
        return np.abs(o - ref).max(1) / (64 * u * scale)
    if name == "newton_euler_wrench":
        inertia, m = x[:, :9].reshape(-1, 3, 3), x[:, 9:10]
        w, wd, cdd = x[:, 10:13], x[:, 13:16], x[:, 16:19]
        Iw = (inertia @ w[:, :, None])[:, :, 0]
        n_ = (inertia @ wd[:, :, None])[:, :, 0] + _cross(w, Iw)
        ref = np.hstack([n_, m * cdd])
        big = np.abs(inertia).max((1, 2))
        scale = np.hstack([np.repeat((big * (np.abs(wd).max(1) + np.abs(w).max(1) ** 2)
                                      )[:, None], 3, 1),
                           np.abs(m * cdd) + 1e-300])
        return (np.abs(o - ref) / (64 * u * scale)).max(1)
    raise ValueError(f"name: expected one of {KERNELS}, got {name!r}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=20000, help="inputs per kernel")
    ap.add_argument("--json", type=Path, help="write the record here")
    ap.add_argument("--work", type=Path, help="keep the builds here (default: a temporary "
                    "folder)")
    args = ap.parse_args(argv)
    missing = [t for t in ("gcc", "g++", "clang", "clang++", "cmake") if not shutil.which(t)]
    if missing:
        print(f"engineer_app: {', '.join(missing)} not installed", file=sys.stderr)
        return 2
    work = args.work or Path(tempfile.mkdtemp(prefix="engineer_app-"))
    work.mkdir(parents=True, exist_ok=True)
    data = work / "data"
    data.mkdir(exist_ok=True)
    kernels_dir = work / "kernels"
    if not kernels_dir.exists():
        cmd = [str(Path(sys.executable).with_name("rigidsym")), "generate", "--target", "cpp",
               *[a for k in KERNELS for a in ("--kernel", k)], "--out", str(kernels_dir)]
        subprocess.run(cmd, check=True, capture_output=True, text=True)
    xs, made = inputs(args.n)
    for name, x in xs.items():
        (data / f"{name}.f64.in").write_bytes(x.astype(np.float64).tobytes())
        (data / f"{name}.f32.in").write_bytes(x.astype(np.float32).tobytes())
    versions, tags = {}, []
    for comp, (cc, cxx) in COMPILERS.items():
        versions[comp] = subprocess.run([cxx, "--version"], capture_output=True,
                                        text=True).stdout.splitlines()[0]
        for flag in FLAGS:
            tag = f"{comp}{flag}"
            exe = build(work, kernels_dir, cc, cxx, flag)
            subprocess.run([str(exe), str(data), tag], check=True)
            tags.append(tag)
    rows, ok = [], True
    for name in KERNELS:
        for suffix, dtype, u in (("f64", np.float64, 2.0 ** -53), ("f32", np.float32,
                                                                   2.0 ** -24)):
            runs = {t: read_out(data / f"{name}.{suffix}.{t}.out", WIDTH[name], dtype)
                    for t in tags}
            s0, o0 = runs[tags[0]]
            same_status = all(np.array_equal(s, s0) for s, _ in runs.values())
            same_bits = all(np.array_equal(o.view(np.uint8), o0.view(np.uint8))
                            for _, o in runs.values())
            x = xs[name].astype(dtype)
            worst = max(float(np.max(judge(name, x, o, made, u))) for _, o in runs.values())
            counts = {t: dict(zip(*[v.tolist() for v in np.unique(s, return_counts=True)],
                                  strict=True)) for t, (s, _) in runs.items()}
            flagged = sum(int((s != 0).sum()) for s, _ in runs.values())
            good = same_status and same_bits and flagged == 0 and worst <= 1
            ok &= good
            rows.append({"kernel": name, "dtype": suffix, "n": len(s0),
                         "same_status_every_build": same_status,
                         "same_bits_every_build": same_bits, "flagged": flagged,
                         "status_counts": counts, "worst_error_over_tolerance": worst,
                         "ok": good})
            print(f"{name:34s} {suffix}: same status {same_status}, same bits {same_bits}, "
                  f"flagged {flagged}, worst error/tolerance {worst:.3g}")
    rec = {"host": host(), "machine": platform.machine(), "compilers": versions,
           "builds": tags, "n": args.n, "kernels": rows, "ok": ok,
           "command": "python benchmarks/engineer_app.py" + (
               f" --n {args.n}" if args.n != 20000 else "")}
    try:
        rec["commit"] = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT,
                                       capture_output=True, text=True).stdout.strip()
    except OSError:
        pass
    rec["load_after"] = list(os.getloadavg())
    if args.json:
        args.json.write_text(json.dumps(rec, indent=1) + "\n")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
