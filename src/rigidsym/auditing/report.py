"""An audit's report: plain text, JSON, Markdown ready to paste into an issue (the inputs as
exact hex floats, the truth, the error, the convention), and a pytest regression file for
the user's repository. Nothing is written unless asked (:func:`write_pytest`)."""

from __future__ import annotations

import json
import re
from dataclasses import asdict
from pathlib import Path

import numpy as np

from rigidsym.auditing.audit import AuditReport, WorstInput
from rigidsym.core.errors import BadInput

__all__ = ["text", "to_json", "markdown", "pytest_source", "write_pytest", "hexes"]


def hexes(values) -> list[str]:
    """Each float of ``values`` (any nesting) as ``float.hex``: exact."""
    return [float(v).hex() for v in np.ravel(np.asarray(values, dtype=np.float64))]


def _array(a) -> str:
    vals = ", ".join(f"float.fromhex({h!r})" for h in hexes(a))
    shape = np.shape(a)
    return f"np.array([{vals}])" + (f".reshape({shape!r})" if len(shape) > 1 else "")


def _callee(rep: AuditReport) -> tuple[list[str], str]:
    """``(import lines, the callee as the code calls it)`` of the audited function: the
    module's name imported (``from mod import f``) and ``f``, or for an expression (a bound
    method, a chain: :func:`.callables.expression`) the module's names it uses and the
    lambda in parentheses; the array framework's import where the function takes its
    tensors."""
    from rigidsym.auditing.callables import expression

    mod, _, name = rep.spec.partition(":")
    lines = ["import numpy as np"]
    if rep.framework:
        lines.append(f"import {rep.framework}")
    ex = expression(rep.spec) if mod and name else None
    if ex is not None:
        import builtins

        top = mod.split(".")[0]
        if top in ex.names:
            lines.append(f"import {top}")
        names = [n for n in ex.names if not hasattr(builtins, n) and n != top]
        if names:
            lines.append(f"from {mod} import {', '.join(names)}")
        return lines, f"({ex.source})"
    if mod and name and "<" not in name:
        lines.append(f"from {mod} import {name.split('.')[0]}")
    return lines, name or rep.function


def _arg(rep: AuditReport, a, dtype: str = "float64") -> str:
    """An argument as the function takes it: a NumPy array, or the framework's tensor of it
    (``torch.as_tensor(np.array(...))``)."""
    from rigidsym.auditing.callables import FRAMEWORKS

    arr = _array(a) if dtype == "float64" else f"{_array(a)}.astype(np.{dtype})"
    return f"{rep.framework}.{FRAMEWORKS[rep.framework]}({arr})" if rep.framework else arr


#: a line that reads the user's output as float64 NumPy values, tensors included
_READ = ("got = np.concatenate([np.ravel(np.asarray(o.detach().cpu() if hasattr(o, "
         "'detach') else o, dtype=np.float64)) for o in outs])")


def _keywords(rep: AuditReport) -> str:
    """The flags the function is audited with, as a call's trailing arguments."""
    return "".join(f", {k}={v!r}" for k, v in rep.keywords.items())


def _call(rep: AuditReport, w: WorstInput) -> str:
    name = _callee(rep)[1]
    return f"{name}({', '.join(_arg(rep, a, w.dtype) for a in w.args)}{_keywords(rep)})"


def _off(c: dict) -> str:
    """How far off a class of wrong output is, in words."""
    if not np.isfinite(c["off"]):
        return "-"
    if c["class"] in ("wrong rotation", "conjugate", "transposed", "inverse rotation"):
        return f"{c['off']:.3g} rad"
    return f"{c['off']:.3g} (relative)"


def _class_call(rep: AuditReport, c: dict) -> str:
    name = _callee(rep)[1]
    return f"{name}({', '.join(_arg(rep, a) for a in c['args'])}{_keywords(rep)})"


def _wrong_lines(rep: AuditReport) -> list[str]:
    out = []
    for d, classes in rep.wrong.items():
        if classes:
            out.append(f"  wrong outputs met, {d} (class: inputs, off by; worst input):")
        for c in classes:
            out.append(f"    {c['class']}: {c['count']}, {_off(c)}; {c['regime']}: "
                       f"{_class_call(rep, c)}")
    return out


def _worst_lines(rep: AuditReport) -> list[str]:
    out = []
    for w in rep.worst:
        out.append(f"  worst input, {w.dtype} ({w.regime}): error {w.err_u:.3g} u, kappa "
                   f"{w.kappa:.3g}, {w.ratio:.3g} x the bound 8 u (kappa + 1); rigidsym's "
                   f"kernel there: {w.kernel_err_u:.3g} u" + (f"; {w.flag}" if w.flag else ""))
        for label, e in sorted(w.peers.items()):
            out.append(f"    {label}: {e:.3g} u")
        out.append(f"    reproducer: {_call(rep, w)}")
    return out


def text(rep: AuditReport) -> str:
    """The report as plain text."""
    lines = [f"audit of {rep.function} as {rep.target}: {'PASS' if rep.ok else 'FINDINGS'}"
             f" ({rep.seconds:.1f} s)", f"  the book: {rep.book}"]
    if rep.convention:
        lines.append(f"  convention: {rep.convention} (found among {rep.tried} members)")
    elif not rep.tried:
        lines.append("  convention: not sought (the output is not the book's kind)")
    else:
        lines.append(f"  convention: none of {rep.tried} members matches; nearest: "
                     f"{rep.nearest} (residual {rep.residual:.3g})")
    lines += _worst_lines(rep)
    lines += _wrong_lines(rep)
    for dt, rows in rep.behaviour.items():
        lines.append(f"  per regime, {dt} (inputs: worst err / bound, yours | rigidsym's; "
                     f"flags where the truth is finite; flags where it is not):")
        for b in rows:
            lines.append(f"    {b['regime']}: {b['n']}: {b['worst_ratio']:.3g} | "
                         f"{b['kernel_worst_ratio']:.3g}; {b['nan']} NaN/inf, {b['raised']} "
                         f"raised; {b['expected']} expected")
    if rep.batch:
        lines.append(f"  batch: {rep.batch}")
    for f in rep.findings:
        lines.append(f"  {f.severity.upper()} [{f.kind}] {f.text}")
    return "\n".join(lines) + "\n"


def to_json(rep: AuditReport) -> str:
    """The report as JSON (every field; floats of the worst inputs also as hex)."""
    d = asdict(rep)
    d["ok"] = rep.ok
    for w in d["worst"]:
        w["args_hex"] = [hexes(a) for a in w["args"]]
        w["truth_hex"] = None if w["truth"] is None else hexes(w["truth"])

    def clean(x):
        if isinstance(x, float) and not np.isfinite(x):
            return str(x)
        if isinstance(x, dict):
            return {k: clean(v) for k, v in x.items()}
        if isinstance(x, list):
            return [clean(v) for v in x]
        return x
    return json.dumps(clean(d), indent=1) + "\n"


def _title(rep: AuditReport) -> str:
    errors = [f for f in rep.findings if f.severity == "error"]
    if not errors:
        return f"`{rep.function}` passes the audit as `{rep.target}`"
    f = errors[0]
    m = re.match(r"(float\d+, .*?): (error|\d+ NaN)", f.text)
    where = m.group(1) if m else ""
    what = {"silent wrong": "returns a wrong value", "inaccurate": "loses accuracy",
            "flag": "returns NaN or raises where the result is finite",
            "convention": "does not compute the book's operation at every input",
            "invariant": "breaks an invariant"}.get(f.kind, f.kind)
    return f"`{rep.function}` {what}" + (f" ({where})" if where else "")


def _bound(w: WorstInput) -> float:
    """The accuracy rule's bound at the worst input, relative: ``8 u (kappa + 1)``."""
    u = 2.0**-53 if w.dtype == "float64" else 2.0**-24
    return 8 * u * (w.kappa + 1)


def _reproducer(rep: AuditReport, w: WorstInput) -> list[str]:
    """A script that runs without rigidsym: the call at the worst input, exact, and the
    truth (ball arithmetic, rounded to float64) beside what it returns."""
    lines, name = _callee(rep)
    vers = ", ".join(f"{k} {v}" for k, v in rep.versions.items())
    lines = [f"# audited with {vers}" if vers else "# versions not known", *lines, ""]
    for i, a in enumerate(w.args):
        lines.append(f"arg{i} = {_arg(rep, a, w.dtype)}")
    call = (f"{name}({', '.join(f'arg{i}' for i in range(len(w.args)))}"
            f"{_keywords(rep)})")
    lines += [f"out = {call}",
              "outs = out if isinstance(out, (tuple, list)) else [out]", _READ]
    if w.truth is not None:
        truth = ", ".join(f"float.fromhex({h!r})" for h in hexes(w.truth))
        lines += [f"truth = np.array([{truth}])",
                  "print('got  ', got)", "print('truth', truth)"]
        if rep.equivalent:
            # the output negated is the same rotation, in any layout, degrees or radians
            lines += ["# an output of the same rotation is as right: (-e, -phi) for (e, phi) "
                      "by (2.49), -q for q by (2.3);",
                      "# the error is to the nearer of truth and -truth (phi + 2 pi k is "
                      "right too)",
                      "err = min(np.linalg.norm(got - truth), np.linalg.norm(got + truth))"]
        else:
            lines.append("err = np.linalg.norm(got - truth)")
        lines += ["print('relative error', err / (np.linalg.norm(truth) or 1.0))",
                  f"print('the bound 8 u (kappa + 1)', {_bound(w)!r})"]
    return lines


def markdown(rep: AuditReport) -> str:
    """A GitHub issue body to file with the function's project: a title, the versions, the
    convention block, the findings, the worst input in exact hex and a reproducer that runs
    without rigidsym."""
    vers = ", ".join(f"{k} {v}" for k, v in rep.versions.items()) or "not known"
    conv = rep.convention or f"none at every input; nearest {rep.nearest}"
    lines = [f"### {_title(rep)}", "",
             f"Found by `rigidsym audit` ({rep.tried} conventions tried). Versions: {vers}.",
             "", "```text",
             f"Operation:   {rep.target}",
             f"The book:    {rep.book}",
             f"Convention:  {conv}",
             "```", "", "**Findings**", ""]
    for f in rep.findings:
        lines.append(f"- **{f.severity}** ({f.kind}): {f.text}")
    for d, classes in rep.wrong.items():
        if not classes:
            continue
        lines += ["", f"**Wrong outputs met** ({d}; each class, the audit's inputs that gave "
                  f"it, how far off, its worst input):", "",
                  "| class | inputs | off by | worst input |", "|---|---|---|---|"]
        for c in classes:
            args = "; ".join(" ".join(hexes(a)) for a in c["args"])
            lines.append(f"| {c['class']} | {c['count']} | {_off(c)} | {c['regime']}: "
                         f"`{args}` |")
    for w in rep.worst:
        kind = f", as {rep.framework} tensors" if rep.framework else ""
        # a flag has no error to weigh against a condition number: said as what it is
        said = (f"**{w.flag}**, where the truth is finite" if w.flag and not
                np.isfinite(w.ratio) else
                f"error **{w.err_u:.3g} u** (condition number {w.kappa:.3g}; the bound 8 u "
                f"(kappa + 1) x {w.ratio:.3g})")
        lines += ["", f"**Worst input** ({w.dtype}, {w.regime}): {said}; rigidsym's kernel: "
                  f"{w.kernel_err_u:.3g} u.", "",
                  "| | exact value (hex floats) |", "|---|---|"]
        for i, a in enumerate(w.args):
            lines.append(f"| argument {i + 1} | `{' '.join(hexes(a))}` |")
        if w.truth is not None:
            lines.append(f"| truth (60+ digits, rounded) | `{' '.join(hexes(w.truth))}` |")
        if w.got is not None:
            lines.append(f"| got | `{' '.join(hexes(w.got))}` |")
        lines += ["", f"Reproducer (NumPy and the function's library{kind}; no rigidsym):",
                  "", "```python", *_reproducer(rep, w), "```"]
    return "\n".join(lines) + "\n"


def pytest_source(rep: AuditReport) -> str:
    """A pytest file that fails while the worst input's error is past the bound.

    Raises:
        BadInput: no importable ``module:function`` to call, or no worst input with a
            truth."""
    mod, _, name = rep.spec.partition(":")
    if not mod or not name or "<" in name:
        raise BadInput("--pytest: the function must be importable as module:function")
    imports, callee = _callee(rep)
    cases = [w for w in rep.worst if w.truth is not None]
    if not cases:
        raise BadInput("--pytest: no worst input with a defined truth to test")
    body = [f'"""Regression test written by `rigidsym audit {rep.spec} --as {rep.target}`:',
            f"the worst input found, in the function's convention ({rep.form};",
            f"{', '.join(rep.generators) or 'the book'}'s), against the truth of the book's",
            'formula (ball arithmetic, rounded); within 8 u (kappa + 1) passes."""', "",
            *imports, ""]
    for i, w in enumerate(cases):
        bound = _bound(w)
        args = ", ".join(_arg(rep, a, w.dtype) for a in w.args)
        body += ["", f"def test_{rep.target}_worst_input_{w.dtype}_{i}():",
                 f"    # {w.regime}: error {w.err_u:.3g} u at audit time",
                 f"    args = [{args}]",
                 f"    truth = np.array([float.fromhex(h) for h in {hexes(w.truth)!r}])",
                 f"    out = {callee}(*args{_keywords(rep)})",
                 "    outs = out if isinstance(out, (tuple, list)) else [out]",
                 f"    {_READ}",
                 "    assert np.isfinite(got).all()",
                 f"    assert np.linalg.norm(got - truth) <= {bound!r} * ("
                 "np.linalg.norm(truth) or 1.0)"]
    return "\n".join(body) + "\n"


def write_pytest(rep: AuditReport, path: str | Path) -> Path:
    """Write :func:`pytest_source` to ``path`` (atomically; BadInput as it raises)."""
    from rigidsym.core.files import write_atomic

    src = pytest_source(rep)
    p = Path(path)
    write_atomic(p, src)
    return p
