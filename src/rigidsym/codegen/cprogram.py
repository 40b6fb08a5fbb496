"""The C program pieces of a kernel (split from :mod:`rigidsym.codegen.generator`):
printed straight-line programs, the finiteness checks of divisions and roots, the split of
a trig-calling kernel into a SIMD sin/cos loop and a per-sample loop, and the float32 sample
programs under their precision plans (:mod:`rigidsym.codegen.accuracy.float32`).
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from rigidsym.codegen.optimise import Program
from rigidsym.codegen.printers import KernelCFloatPrinter, KernelCPrinter
from rigidsym.codegen.spec import Kernel

# used by the generator only (``kc``: its KernelCode)
__all__ = ["TRIG_BLOCK", "program_lines", "_risky", "risky_names", "finite_check",
           "trig_split", "trig_plan", "f32_code"]

def program_lines(p: Program, printer) -> dict:
    return {
        "temps": [(str(s), printer.doprint(v)) for s, v in p.temps],
        "outputs": [printer.doprint(v) for v in p.outputs],
        "dens": [printer.doprint(v) for v in p.dens],
    }


def _risky(e) -> bool:
    """Whether ``e`` itself divides or takes a root (may be non-finite for finite inputs)."""
    return any(isinstance(p, sp.Pow) and not (p.exp.is_Integer and p.exp > 0)
               for p in sp.preorder_traversal(e))


def _risky_bases(p: Program, printer) -> list[str]:
    """The divisors and radicands of ``p``, printed: a finite quotient of an overflowed
    divisor (``x / inf == 0``: the unit vector of ``1/sqrt(|p|^2)`` with ``|p|^2 = inf``) is
    finite but wrong, so they are checked for finiteness too (issue 19, item 6)."""
    out: list[str] = []
    for e in [v for _, v in p.temps] + list(p.outputs):
        for node in sp.preorder_traversal(sp.sympify(e)):
            if isinstance(node, sp.Pow) and not (node.exp.is_Integer and node.exp > 0) \
                    and not node.base.is_number:
                s = printer.doprint(node.base)
                s = s if s.isidentifier() else f"({s})"
                if s not in out:
                    out.append(s)
    return out


def risky_names(p: Program, printer) -> list[str]:
    """Temporaries / outputs that divide or take a root, and their divisors and radicands,
    printed (NumPy finiteness check)."""
    names = [str(s) for s, v in p.temps if _risky(v)]
    names += [printer.doprint(v) for v in p.outputs if _risky(v)]
    return names + [b for b in _risky_bases(p, printer) if b not in names]


def finite_check(p: Program, k: Kernel, printer=None) -> str:
    """C expression that is NaN iff a division/root temporary or output, or a divisor or
    radicand, is non-finite (divisors and radicands printed by ``printer``)."""
    names = [str(s) for s, v in p.temps if _risky(v)]
    slots = [f"out_{o.name}[{j}]" for o in k.outputs for j in range(o.size)]
    names += [slot for slot, v in zip(slots, p.outputs, strict=True) if _risky(v)]
    names += [b for b in _risky_bases(p, printer or KernelCPrinter()) if b not in names]
    return balanced([f"({n} - {n})" for n in names]) if names else ""


def balanced(terms: list[str]) -> str:
    """``a + b + ...`` as a balanced tree of additions (C does not reassociate doubles)."""
    if len(terms) == 1:
        return terms[0]
    h = len(terms) // 2
    return f"({balanced(terms[:h])} + {balanced(terms[h:])})"


#: samples per block of the blocked batch loop (trig values precomputed on the stack)
TRIG_BLOCK = 64
_TRIG = (sp.sin, sp.cos)


def trig_split(kc: Any) -> dict | None:
    """Split a trig-calling kernel into a SIMD trig loop and a per-sample loop.

    For a kernel without branches whose ``sin``/``cos`` arguments do not themselves depend
    on a trig call, returns the prelude (the temporaries the arguments need, in order, and
    the ``sin``/``cos`` calls by parameter name ``trig_<k>``) and the per-sample program with
    each call replaced by its parameter; ``None`` when the kernel is not blocked.
    """
    if len(kc.variants) != 1:
        return None
    p = kc.variants[0].program
    exprs = [v for _, v in p.temps] + list(p.outputs) + list(p.dens)
    calls: list = []
    for e in exprs:
        for node in sp.preorder_traversal(sp.sympify(e)):
            if isinstance(node, _TRIG) and node not in calls:
                calls.append(node)
    if not calls:
        return None
    defs = dict(p.temps)
    need: set = set()
    todo = [s for c in calls for s in c.args[0].free_symbols]
    while todo:
        s = todo.pop()
        if s in defs and s not in need:
            need.add(s)
            todo.extend(defs[s].free_symbols)
    pre = [(s, v) for s, v in p.temps if s in need]
    if any(v.has(*_TRIG) for _, v in pre):
        return None
    names = {c: sp.Symbol(f"trig_{k}") for k, c in enumerate(calls)}
    temps = [(s, v.xreplace(names)) for s, v in p.temps]
    outputs = [sp.sympify(v).xreplace(names) for v in p.outputs]
    dens = [sp.sympify(v).xreplace(names) for v in p.dens]
    # drop the temporaries that only fed the trig arguments (keep divisions and roots: the
    # finiteness check stays the same)
    live = set().union(*(sp.sympify(v).free_symbols for v in outputs + dens))
    kept = []
    for s, v in reversed(temps):
        if s in live or _risky(v):
            kept.append((s, v))
            live |= v.free_symbols
    kept.reverse()
    return {"calls": {str(names[c]): c for c in calls}, "pre": pre,
            "program": Program(kept, outputs, dens, p.ops)}


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
