"""The C program pieces of the extension module's kernels (and, for :func:`finite_check`
and :func:`balanced`, of the C target's): the finiteness checks of divisions and roots, the
blocked batch loop of a trig-calling kernel (its SIMD sin/cos loop, split off by
:func:`rigidsym.codegen.optimise.trig_split`, and its per-sample loop), and the float32
sample programs under their precision plans (:mod:`rigidsym.codegen.accuracy.float32`).
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from rigidsym.codegen.backends.extension.printer import KernelCFloatPrinter, KernelCPrinter
from rigidsym.codegen.backends.printing import divisors_and_radicands, program_lines
from rigidsym.codegen.optimise import Program, divides_or_roots, trig_split
from rigidsym.codegen.spec import Kernel

__all__ = ["TRIG_BLOCK", "finite_check", "balanced", "trig_plan", "f32_code"]


def finite_check(p: Program, k: Kernel, printer=None) -> str:
    """C expression that is NaN iff a division/root temporary or output, or a divisor or
    radicand, is non-finite (divisors and radicands printed by ``printer``)."""
    names = [str(s) for s, v in p.temps if divides_or_roots(v)]
    slots = [f"out_{o.name}[{j}]" for o in k.outputs for j in range(o.size)]
    names += [slot for slot, v in zip(slots, p.outputs, strict=True) if divides_or_roots(v)]
    names += [b for b in divisors_and_radicands(p, printer or KernelCPrinter()) if b not in names]
    return balanced([f"({n} - {n})" for n in names]) if names else ""


def balanced(terms: list[str]) -> str:
    """``a + b + ...`` as a balanced tree of additions (C does not reassociate doubles)."""
    if len(terms) == 1:
        return terms[0]
    h = len(terms) // 2
    return f"({balanced(terms[:h])} + {balanced(terms[h:])})"


#: samples per block of the blocked batch loop (trig values precomputed on the stack)
TRIG_BLOCK = 64


def trig_plan(kc: Any, printer) -> dict | None:
    """The printed trig split of :func:`trig_split` (``None``: the kernel is not blocked)."""
    split = trig_split(kc)
    if split is None:
        return None
    prog, pre, calls = split["program"], split["pre"], split["calls"]
    used_pre = set().union(*(v.free_symbols for _, v in pre),
                           *(c.args[0].free_symbols for c in calls.values()))
    used = set().union(*(v.free_symbols for _, v in prog.temps),
                       *(sp.sympify(v).free_symbols for v in list(prog.outputs) + prog.dens))
    return {
        "block": TRIG_BLOCK,
        "names": list(calls),
        "pre_temps": [(str(s), printer.doprint(v)) for s, v in pre],
        # the SIMD loop's calls (RIGIDSYM_VSIN/VCOS, c_common.h.j2), and per call its
        # argument and libm function, for the scalar rerun of the lanes RIGIDSYM_TRIG_FAR flags
        "pre_calls": [(t, f"RIGIDSYM_V{type(c).__name__.upper()}({printer.doprint(c.args[0])})")
                      for t, c in calls.items()],
        "far": [(t, type(c).__name__, printer.doprint(c.args[0])) for t, c in calls.items()],
        "far_args": list(dict.fromkeys(printer.doprint(c.args[0]) for c in calls.values())),
        "pre_used": {str(s) for s in used_pre},
        "used": {str(s) for s in used},
        "variant": {"name": "main", "cond": None, "finite": finite_check(prog, kc.kernel),
                    **program_lines(prog, printer)},
    }


def _f32_variant(p: Program, plan: dict, k: Kernel, cond=None) -> dict:
    """One float32 sample program printed under its precision plan (float or double per
    temporary and output; conditions, denominators in double)."""
    fp = KernelCFloatPrinter(plan)
    ctype = {"f": "float", "d": "double"}
    return {"cond": None if cond is None else fp.print_in(cond, "d"),
            "temps": [(ctype[plan[str(s)]], str(s), fp.print_in(v, plan[str(s)]))
                      for s, v in p.temps],
            "outputs": [fp.print_in(v, plan[f"out:{j}"]) for j, v in enumerate(p.outputs)],
            "dens": [fp.print_in(d, "d") for d in p.dens],
            "finite": finite_check(p, k, fp)}


def f32_code(kc: Any) -> dict:
    """The float32 sample function(s) of ``kc`` and the nodes its plan keeps in double."""
    k, plans = kc.kernel, kc.plan32
    slots = [f"{o.name}[{j}]" for o in k.outputs for j in range(o.size)]

    def widened(plan: dict) -> list[str]:
        return [slots[int(n[4:])] if n.startswith("out:") else n
                for n, t in plan.items() if t == "d"]
    if plans["trig"] is not None:
        split = trig_split(kc)
        plan = plans["trig"]["plan"]
        v = _f32_variant(split["program"], plan, k)
        return {"trig_variant": v, "variants": None, "errors": [plans["trig"]["error"]],
                "trig_types": {t: {"f": "float", "d": "double"}[plan[t]] for t in split["calls"]},
                "widened": [widened(plan)]}
    vs = [_f32_variant(v.program, pl["plan"], k, v.cond)
          for v, pl in zip(kc.variants, plans["variants"], strict=True)]
    return {"trig_variant": None, "variants": vs,
            "errors": [pl["error"] for pl in plans["variants"]],
            "widened": [widened(pl["plan"]) for pl in plans["variants"]]}
