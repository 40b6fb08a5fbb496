"""Benchmark the generated Jacobian kernels: ns/sample at N = 1e3, 1e5, 1e6, one thread.

Per kernel and N, with caller-provided outputs (the kernel alone): the generated C value
kernel, the generated C ``<name>_with_jacobians`` (values and all derivatives), a plain
``sympy.cse`` + ``ccode`` C loop of the same values and derivative expressions (built by
``run.py``'s helper, through cffi, same flags), and the memory floor of the Jacobian kernel's
input and output bytes (``run.py``'s helper). Targets: value + Jacobian <= 3x the
value alone on kernels calling sin/cos; <= 1.5x the memory floor on the others; faster than
the plain sympy C loop wherever sin/cos appear.

Writes its own section of ``benchmarks/RESULTS.md`` between ``<!-- jacobians -->`` and
``<!-- /jacobians -->`` (``run.py`` keeps it when it rewrites the file).

Usage (from the repository root)::

    python benchmarks/jacobians.py [--quick] [--kernels a,b]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

import numpy as np
import sympy as sp

sys.path.insert(0, str(Path(__file__).resolve().parent))

import run as R  # noqa: E402  (the benchmark helpers of benchmarks/run.py)

from rigidsym import kernels as K  # noqa: E402
from rigidsym.codegen.derivatives.jacobians import jacobian_name, with_jacobians  # noqa: E402
from rigidsym.kernels.runtime import state as _state

#: the Jacobian kernels measured (euler_rate_matrix: one of the 24 sequence/frame kernels)
KERNELS = ["rotation_from_natural_invariants", "rotation_from_euler_rodrigues",
           "screw_axis_point", "plucker_from_points", "plucker_transfer", "twist_transfer",
           "wrench_transfer", "point_acceleration", "inertia_at_point", "newton_euler_wrench",
           "kinetic_energy", "euler_rate_matrix_zyx_fixed", "N_matrix"]
MARK, END = "<!-- jacobians -->", "<!-- /jacobians -->"
COLS = ["value C", "value+Jacobian C", "sympy-cse C (same derivatives)", "memory floor"]


def _trig(name: str) -> bool:
    """Whether the declared values of ``name`` call sin or cos."""
    _k, _flat, exprs = R._declared(name)
    return any(sp.sympify(e).has(sp.sin, sp.cos) for e in exprs)


def measure(names: list[str], Ns: list[int], rounds: int) -> list[dict]:
    rows = []
    rng = np.random.default_rng(3)
    with tempfile.TemporaryDirectory() as tmp:
        build = Path(tmp)
        for name in names:
            jname = jacobian_name(name)
            R.SPECS[jname] = with_jacobians(R.SPECS[name])    # run.py's helpers look it up
            funcs = {"value C": (name, R.col_generated(name, "c")),
                     "value+Jacobian C": (jname, R.col_generated(jname, "c")),
                     "sympy-cse C (same derivatives)": (jname, R.col_sympy_c(jname, build)),
                     "memory floor": (jname, R.col_floor(jname, build))}
            trig = _trig(name)
            for N in Ns:
                xs = R.inputs(name, N, rng)
                cells = {}
                ref = R._flat_out(funcs["value+Jacobian C"][1](*xs), N)
                for col, (kname, f) in funcs.items():
                    if col == "sympy-cse C (same derivatives)":
                        got = f(*xs)
                        err = (np.abs(got - ref).max(axis=1)
                               / np.maximum(np.abs(ref).max(axis=1), 1e-300)).max()
                        if err > 1e-10:
                            cells[col] = f"mismatch {err:.1e}"
                            continue
                    outs = R._outputs(kname, "sympy-cse C" if col.startswith("sympy") else
                                      col, N)
                    cells[col] = R.timeit(lambda *a, _f=f, _o=outs: _f(*a, out=_o), xs, N,
                                          rounds)
                row = {"name": name, "N": N, "trig": trig, "cells": cells,
                       "ops": (_state.meta()[name]["ops"], _state.meta()[jname]["ops"],
                               funcs["sympy-cse C (same derivatives)"][1].ops),
                       "bytes": _bytes(jname)}
                rows.append(row)
                print(name, N, {c: (f"{v:.1f}" if isinstance(v, float) else v)
                                for c, v in cells.items()}, file=sys.stderr)
    return rows


def _bytes(name: str) -> int:
    k = R.SPECS[name]
    return 8 * (sum(a.size for a in k.args) + sum(o.size for o in k.outputs))


def _ratio(a, b) -> str:
    return f"{a / b:.2f}" if isinstance(a, float) and isinstance(b, float) else "n/a"


def _targets(trig: bool, jac, val, floor, plain) -> str:
    """Each speed target that applies, met or missed."""
    if not isinstance(jac, float):
        return "n/a"
    if not trig:
        return f"<= 1.5x floor: {'met' if jac <= 1.5 * floor else 'missed'}"
    res = [f"<= 3x value: {'met' if jac <= 3 * val else 'missed'}"]
    if isinstance(plain, float):
        res.append(f"< sympy C: {'met' if jac < plain else 'missed'}")
    return "; ".join(res)


def table(rows: list[dict], Ns: list[int]) -> list[str]:
    text = []
    for N in Ns:
        text += [f"### N = {N:.0e}: ns/sample, caller-provided outputs", "",
                 "| kernel | trig | ops value / +Jac / sympy | bytes/sample | "
                 + " | ".join(COLS) + " | Jac / value | Jac / floor | Jac / sympy C | targets |",
                 "|---|---|---|---:|" + "---:|" * (len(COLS) + 3) + "---|"]
        for r in rows:
            if r["N"] != N:
                continue
            c = r["cells"]
            jac, val = c["value+Jacobian C"], c["value C"]
            floor, plain = c["memory floor"], c["sympy-cse C (same derivatives)"]
            target = _targets(r["trig"], jac, val, floor, plain)
            cells = [f"{v:.3g}" if isinstance(v, float) else v for v in (c[k] for k in COLS)]
            text.append(f"| `{r['name']}` | {'yes' if r['trig'] else 'no'} | "
                        f"{r['ops'][0]} / {r['ops'][1]} / {r['ops'][2]} | {r['bytes']} | "
                        + " | ".join(cells)
                        + f" | {_ratio(jac, val)} | {_ratio(jac, floor)} | "
                        f"{_ratio(jac, plain)} | {target} |")
        text.append("")
    return text


def write_section(path: Path, lines: list[str]) -> None:
    """Replace (or append) the text between the markers of ``path``, atomically."""
    from _results import write_section as write

    write(path, "\n".join([MARK, *lines, END]), MARK, END)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="N = 1e3, 1e5 and 3 rounds")
    p.add_argument("--kernels", default=",".join(KERNELS))
    p.add_argument("--out", default=str(R.ROOT / "benchmarks" / "RESULTS.md"))
    p.add_argument("--note", default="", help="a line about the machine's load")
    args = p.parse_args(argv)
    if K.use_backend("c") != "c":
        raise SystemExit("the C backend did not build")
    big = np.ones(4_000_000)        # glibc malloc in its steady regime, as run.py
    del big
    Ns = [1000, 100000] if args.quick else [1000, 100000, 1000000]
    rows = measure(args.kernels.split(","), Ns, 3 if args.quick else 7)
    lines = ["## Jacobian kernels (`benchmarks/jacobians.py`)", "",
             "- `<name>_with_jacobians` (values and every d output / d input, one CSE'd "
             "program) beside the value kernel, a plain sympy.cse + ccode C loop of the same "
             "values and derivatives (no half-angle rewrite, no blocked sin/cos loop), and "
             "the memory floor of the Jacobian kernel's input + output bytes; one thread, "
             "thread CPU time, median of rounds, outputs provided by the caller",
             "- targets: value + Jacobian <= 3x the value alone where sin/cos appear (trig), "
             "else <= 1.5x the memory floor; faster than the sympy C loop where trig appears",
             "- `euler_rate_matrix_zyx_fixed` stands for the 24 Euler-angle kernels",
             "- a Jacobian kernel writes 2-20x the bytes of its value kernel (bytes/sample "
             "column: inputs + values + derivatives): where that ratio exceeds 3 and N is "
             "large enough to leave the cache, `Jac / floor` is the meaningful figure, and "
             "`<= 3x value` cannot be met by any code",
             "- `value+Jacobian C` includes the per-block scan of every output for non-finite "
             "values (overflow is reported); the plain sympy C loop checks "
             "nothing",
             f"- {args.note}" if args.note else "", ""]
    write_section(Path(args.out), lines + table(rows, Ns))
    print(f"wrote the jacobians section of {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
