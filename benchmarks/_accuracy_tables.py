"""The tables of the accuracy harness (``benchmarks/accuracy.py``): per kernel
(docs/accuracy.md), per kernel, type and back-end under issue 37's rule (docs/accuracy.md,
benchmarks/RESULTS.md), and every row."""

from __future__ import annotations

from rigidsym import kernels as K


def kernel_table(data: dict, public_only: bool = False) -> str:
    """The per-kernel table of ``docs/accuracy.md`` from :func:`summary`'s data."""
    lines = ["| kernel | float64: bound, ulps | worst regime, kappa there | float32: bound, "
             "ulps | worst regime, kappa there | singular set (flagged where) |",
             "|---|---|---|---|---|---|"]
    meta = K._state.meta()
    for name, r in data.items():
        if public_only and not meta[name]["public"]:
            continue
        a, b = r.get("float64", {}), r.get("float32", {})
        sing = r["singular"] or "none"
        if r.get("threshold"):
            sing += f" ({r['threshold']})"
        sing = sing.replace("|", "\\|")
        ok = "" if r["accurate"] else " **LOSES**"
        a, b = ({**x, "regime": x.get("regime", "").replace("|", "\\|")} for x in (a, b))
        lines.append(f"| `{name}`{ok} | {a.get('bound', 0):.2g}, {a.get('ulps', 0):.3g} | "
                     f"{a.get('regime', '')}, {a.get('kappa', 0):.2g} | "
                     f"{b.get('bound', 0):.2g}, {b.get('ulps', 0):.3g} | "
                     f"{b.get('regime', '')}, {b.get('kappa', 0):.2g} | {sing} |")
    return "\n".join(lines) + "\n"


def rule_table(data: dict, public_only: bool = False) -> str:
    """The table of issue 37 (docs/accuracy.md, benchmarks/RESULTS.md): per kernel,
    precision and back-end, the worst normwise error in u over every regime, the worst
    ratio to e_ref (where e_ref > 2 u) and the yardstick there, and the rule's verdict."""
    lines = ["| kernel | type | back-end | worst error (u) | worst err / e_ref | where, "
             "against | rule (<= 1) |", "|---|---|---|---|---|---|---|"]
    meta = K._state.meta()
    for name, r in data.items():
        if public_only and not meta[name]["public"]:
            continue
        for dt in ("float64", "float32"):
            d = r.get(dt)
            if not d:
                continue
            for b, x in sorted(d.get("backends", {}).items()):
                where = x["vs_ref_where"].replace("|", "\\|") or "e_ref <= 2 u everywhere"
                lines.append(f"| `{name}` | {dt} | {b} | {x['err_u']:.3g} | "
                             f"{x['vs_ref']:.3g} | {where} | {x['rule']:.2g} |")
    return "\n".join(lines) + "\n"


def markdown(rows: list) -> str:
    lines = ["| kernel | dtype | backend | regime | worst err/(8u kappa+8u) | err | kappa | "
             "ulps | flagged (expected) | spurious singular |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r.kernel} | {r.dtype} | {r.backend} | {r.regime} | "
                     f"{r.worst_ratio:.3g} | {r.err:.2g} | {r.kappa:.2g} | {r.ulps:.3g} | "
                     f"{r.flagged_expected} | {len(r.spurious)} |")
    return "\n".join(lines) + "\n"
