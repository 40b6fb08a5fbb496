"""docs/audit.md's figures: one function of each installed peer library audited by
``rigidsym.audit`` (the convention it finds from the bare callable, the worst input of the
search, the error there against the ball-arithmetic truth and rigidsym's kernel's, the
findings), and the time each audit takes.

Usage (from the repository root, the [oracles] extra installed)::

    python benchmarks/audit_peers.py [--seed 0] [--md]
"""

from __future__ import annotations

import argparse
import time


def cases() -> list[tuple[str, str, str, object]]:
    """``(library, call, operation, bare callable)`` for each installed peer."""
    out = []
    try:
        from pytransform3d import rotations as pr

        out.append(("pytransform3d", "rotations.compact_axis_angle_from_matrix",
                    "rotation_vector_from_rotation", pr.compact_axis_angle_from_matrix))
    except ImportError:
        pass
    try:
        from spatialmath import base as sb

        out.append(("spatialmath", "base.exp2jac", "rotation_vector_left_jacobian",
                    sb.exp2jac))
    except ImportError:
        pass
    try:
        import pinocchio as pin

        out.append(("Pinocchio", "SE3(T).act(Force(f)).vector", "wrench_transfer",
                    lambda T, f: pin.SE3(T).act(pin.Force(f)).vector))
    except ImportError:
        pass
    try:
        import jaxlie

        from rigidsym.codegen.accuracy.peers import x64

        def so3_log(Q):
            with x64():
                return jaxlie.SO3.from_matrix(Q).log()

        out.append(("jaxlie", "SO3.from_matrix(Q).log() (x64)",
                    "rotation_vector_from_rotation", so3_log))
    except ImportError:
        pass
    try:
        import modern_robotics as mr

        out.append(("Modern Robotics", "MatrixExp3(VecToso3(w))",
                    "rotation_from_rotation_vector", lambda w: mr.MatrixExp3(mr.VecToso3(w))))
    except ImportError:
        pass
    return out


def main(argv=None) -> int:
    from rigidsym import audit

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=0)
    a = ap.parse_args(argv)
    print("| library | function | audited as | convention found (members tried) | worst "
          "input: regime, error (u), kappa | rigidsym's kernel there (u) | findings "
          "(errors; notes) | seconds |")
    print("|---|---|---|---|---|---|---|---|")
    for lib, call, op, f in cases():
        t0 = time.perf_counter()
        rep = audit(f, op, seed=a.seed)
        dt = time.perf_counter() - t0
        w = rep.worst[0] if rep.worst else None
        conv = ", ".join(rep.generators) or ("the book's" if rep.convention else "none")
        where = (f"{w.regime}, {w.err_u:.3g}, {w.kappa:.3g}" + (f" ({w.flag})" if w.flag
                                                                else "")) if w else ""
        errs = [f"{x.kind}: {x.text}" for x in rep.findings if x.severity == "error"]
        notes = [f"{x.kind}: {x.text}" for x in rep.findings if x.severity == "note"]
        finding = "; ".join(errs) or "none"
        if notes:
            finding += f"; notes: {'; '.join(notes)}"
        where, finding = where.replace("|", "\\|"), finding.replace("|", "\\|")
        print(f"| {lib} | `{call}` | `{op}` | {conv} ({rep.tried}) | {where} | "
              f"{w.kernel_err_u if w else 0:.3g} | {finding} | {dt:.1f} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
