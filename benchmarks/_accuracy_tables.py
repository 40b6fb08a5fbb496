"""The tables of the accuracy harness (``benchmarks/accuracy.py``): per kernel
(docs/accuracy.md), per kernel, type and back-end under the accuracy rule (docs/accuracy.md,
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
    """The rule's table (docs/accuracy.md, benchmarks/RESULTS.md): per kernel,
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


_BACKEND = {"c": "C", "numpy": "NumPy"}


def summary_table(data: dict) -> str:
    """Per float type and back-end: how many kernels meet the rule, and the rows whose worst
    err / e_ref is above 2 where e_ref > 2 u (the rule's acceptance), worst first."""
    lines = ["| type | back-end | kernels | within the rule | worst err / e_ref above 2 (where "
             "e_ref > 2 u) |", "|---|---|---|---|---|"]
    for dt in ("float64", "float32"):
        for b in ("c", "numpy"):
            rows = [(name, r[dt]["backends"][b]) for name, r in data.items()
                    if b in r.get(dt, {}).get("backends", {})]
            if not rows:
                continue
            within = sum(x["rule"] <= 1 for _, x in rows)
            above = sorted(((x["vs_ref"], name) for name, x in rows if x["vs_ref"] > 2),
                           reverse=True)
            worst = ", ".join(f"`{n}` {v:.3g}" for v, n in above[:6])
            more = f", {len(above) - 6} more" if len(above) > 6 else ""
            lines.append(f"| {dt} | {_BACKEND[b]} | {len(rows)} | {within} | {len(above)}"
                         f"{': ' + worst + more if above else ''} |")
    return "\n".join(lines) + "\n"


def peer_table(data: dict) -> str:
    """docs/accuracy.md's peer column: the package's table (:mod:`rigidsym.codegen.accuracy.peers`),
    not the data (``data`` unused: every table here takes it)."""
    from rigidsym.codegen.accuracy import peers

    return peers.markdown()


# The tables the data file makes, by file and marker (<!-- name --> ... <!-- /name -->).
DOC_TABLES = {
    "docs/accuracy.md": {"rule-summary": summary_table, "peers": peer_table,
                         "rule-public": lambda d: rule_table(d, public_only=True),
                         "table": lambda d: kernel_table(d, public_only=True)},
    "benchmarks/RESULTS.md": {"rule-summary-all": summary_table, "rule-all": rule_table},
}


def replace_marked(text: str, marker: str, body: str) -> str:
    """``text`` with what lies between ``<!-- marker -->`` and ``<!-- /marker -->`` (each on
    a line of its own) replaced by ``body``. ValueError if either line is missing."""
    start, end = f"<!-- {marker} -->\n", f"<!-- /{marker} -->\n"
    i, j = text.find(start), text.find(end)
    if i < 0 or j < i:
        raise ValueError(f"no {start.strip()} ... {end.strip()} region")
    return text[:i + len(start)] + body + text[j:]


def synced(root, data: dict) -> dict:
    """Per file of :data:`DOC_TABLES` (relative to ``root``), its text with every table
    made anew from ``data``."""
    from pathlib import Path

    out = {}
    for rel, tables in DOC_TABLES.items():
        text = (Path(root) / rel).read_text(encoding="utf-8")
        for marker, make in tables.items():
            text = replace_marked(text, marker, make(data))
        out[rel] = text
    return out
