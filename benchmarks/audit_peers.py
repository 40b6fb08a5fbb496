"""docs/audit.md's table of real peers: one or more functions of each installed peer library
audited by ``rigidsym.audit`` (the convention it finds from the bare callable, the worst
input of the search, the error there against the ball-arithmetic truth and rigidsym's
kernel's, every window over the bound, the findings), the time each audit takes, and the
versions of the libraries; written to ``benchmarks/results/audit_peers.json``.

Usage (from the repository root, the peers installed: the [oracles] extra, SciPy,
transforms3d, numpy-quaternion, kornia)::

    python benchmarks/audit_peers.py [--seed 0] [--only LIBRARY] [--out FILE]

A peer that does not import is left out and listed under ``missing``.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from importlib import metadata
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "results" / "audit_peers.json"
#: the distributions whose versions the record names
DISTRIBUTIONS = ("numpy", "scipy", "pin", "jaxlie", "jax", "pytransform3d",
                 "spatialmath-python", "numpy-quaternion", "kornia", "torch", "transforms3d",
                 "modern-robotics")


def _pytransform3d():
    from pytransform3d import rotations as pr

    return [("pytransform3d", "rotations.compact_axis_angle_from_matrix",
             "rotation_vector_from_rotation", pr.compact_axis_angle_from_matrix,
             "pytransform3d.rotations:compact_axis_angle_from_matrix")]


def _spatialmath():
    from spatialmath import base as sb

    return [("spatialmath", "base.exp2jac", "rotation_vector_left_jacobian", sb.exp2jac,
             "spatialmath.base:exp2jac"),
            ("spatialmath", "base.trlog (twist=True found by the audit)",
             "rotation_vector_from_rotation", sb.trlog, "spatialmath.base:trlog")]


def _pinocchio():
    import pinocchio as pin

    def log3(Q):
        return pin.log3(np.asarray(Q, dtype=np.float64))

    def jexp3(w):
        return pin.Jexp3(np.asarray(w, dtype=np.float64))

    def jlog3_of_exp3(w):
        return pin.Jlog3(pin.exp3(np.asarray(w, dtype=np.float64)))

    return [("Pinocchio", "SE3(T).act(Force(f)).vector", "wrench_transfer",
             lambda T, f: pin.SE3(T).act(pin.Force(f)).vector, ""),
            ("Pinocchio", "log3(Q)", "rotation_vector_from_rotation", log3, "pinocchio:log3"),
            ("Pinocchio", "Jexp3(w)", "rotation_vector_right_jacobian", jexp3,
             "pinocchio:Jexp3"),
            ("Pinocchio", "Jlog3(exp3(w))", "rotation_vector_right_jacobian_inverse",
             jlog3_of_exp3, "")]


def _jaxlie():
    import jaxlie

    from rigidsym.codegen.accuracy.peers import x64

    def so3_log(Q):
        with x64():
            return np.asarray(jaxlie.SO3.from_matrix(Q).log())

    return [("jaxlie", "SO3.from_matrix(Q).log() (x64)", "rotation_vector_from_rotation",
             so3_log, "")]


def _modern_robotics():
    import modern_robotics as mr

    return [("Modern Robotics", "MatrixExp3(VecToso3(w))", "rotation_from_rotation_vector",
             lambda w: mr.MatrixExp3(mr.VecToso3(w)), "")]


def _scipy():
    from scipy.spatial.transform import Rotation

    return [("SciPy", 'Rotation.from_matrix(R).as_euler("xyz")', "euler_angles_from_rotation",
             lambda R: Rotation.from_matrix(R).as_euler("xyz"), ""),
            ("SciPy", 'Rotation.from_matrix(R).as_euler("ZXZ")', "euler_angles_from_rotation",
             lambda R: Rotation.from_matrix(R).as_euler("ZXZ"), ""),
            ("SciPy", "Rotation.from_matrix(Q).as_rotvec()", "rotation_vector_from_rotation",
             lambda Q: Rotation.from_matrix(Q).as_rotvec(), "")]


def _transforms3d():
    from transforms3d import axangles

    return [("transforms3d", "axangles.mat2axangle", "natural_invariants_from_rotation",
             axangles.mat2axangle, "transforms3d.axangles:mat2axangle")]


def _quaternion():
    import quaternion

    return [("numpy-quaternion", "as_rotation_vector(from_rotation_matrix(Q))",
             "rotation_vector_from_rotation",
             lambda Q: quaternion.as_rotation_vector(quaternion.from_rotation_matrix(Q)), "")]


def _kornia():
    import torch
    from kornia.geometry import conversions as kc

    def exp(w):
        t = torch.as_tensor(np.asarray(w, dtype=np.float64))[None]
        return kc.axis_angle_to_rotation_matrix(t)[0].numpy()

    def log(Q):
        t = torch.as_tensor(np.asarray(Q, dtype=np.float64))[None]
        return kc.rotation_matrix_to_axis_angle(t)[0].numpy()

    return [("kornia", "axis_angle_to_rotation_matrix (float64)",
             "rotation_from_rotation_vector", exp, ""),
            ("kornia", "rotation_matrix_to_axis_angle (float64)",
             "rotation_vector_from_rotation", log, "")]


LIBRARIES = {"pytransform3d": _pytransform3d, "spatialmath": _spatialmath,
             "Pinocchio": _pinocchio, "jaxlie": _jaxlie, "Modern Robotics": _modern_robotics,
             "SciPy": _scipy, "transforms3d": _transforms3d, "numpy-quaternion": _quaternion,
             "kornia": _kornia}


def host() -> dict:
    """The host as benchmarks/test_command.py names it."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from test_command import host as machine

    return machine()


def versions() -> dict:
    """``{distribution: version}`` of each installed distribution the record names."""
    out = {}
    for d in DISTRIBUTIONS:
        try:
            out[d] = metadata.version(d)
        except metadata.PackageNotFoundError:
            pass
    return out


def row(lib: str, call: str, op: str, func, spec: str, seed: int) -> dict:
    """One audit as plain data: what the table quotes and the windows it found."""
    from rigidsym import audit

    t0 = time.perf_counter()
    rep = audit(func, op, seed=seed, spec=spec)
    dt = time.perf_counter() - t0
    worst = [{"regime": w.regime, "err_u": w.err_u, "kappa": w.kappa, "ratio": w.ratio,
              "kernel_err_u": w.kernel_err_u, "flag": w.flag} for w in rep.worst]
    return {"library": lib, "call": call, "as": op, "spec": spec, "ok": rep.ok,
            "convention": rep.convention, "generators": rep.generators, "tried": rep.tried,
            "nearest": rep.nearest, "keywords": rep.keywords, "worst": worst,
            "windows": rep.windows.get("float64", []),
            "findings": [{"severity": f.severity, "kind": f.kind, "text": f.text}
                         for f in rep.findings], "seconds": round(dt, 2)}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--only", action="append", default=[],
                    help="a library of the table (repeatable); default: every one")
    ap.add_argument("--out", type=Path, default=OUT)
    a = ap.parse_args(argv)
    unknown = set(a.only) - set(LIBRARIES)
    if unknown:
        ap.error(f"--only: {sorted(unknown)}: expected one of {sorted(LIBRARIES)}")
    rows, missing = [], []
    for lib, make in LIBRARIES.items():
        if a.only and lib not in a.only:
            continue
        try:
            cases = make()
        except ImportError as e:
            missing.append(f"{lib}: {e}")
            continue
        for case in cases:
            r = row(*case, seed=a.seed)
            rows.append(r)
            print(f"{r['library']} {r['call']} as {r['as']}: "
                  f"{'PASS' if r['ok'] else 'FINDINGS'} ({r['seconds']} s)", flush=True)
            for f in r["findings"]:
                print(f"  {f['severity']} [{f['kind']}] {f['text']}", flush=True)
    record = {"host": host(), "load_before": os.getloadavg(), "seed": a.seed,
              "versions": versions(), "missing": missing, "rows": rows}
    from rigidsym.core.files import write_atomic

    write_atomic(a.out, json.dumps(record, indent=1, default=float) + "\n")
    print(f"wrote {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
