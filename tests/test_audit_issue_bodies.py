"""``rigidsym audit --markdown`` as an issue body a maintainer files as it is: for each of
eight peer libraries, the function the audit of docs/audit.md found wrong, re-created
formula for formula in NumPy (tests/peer_bugs/, the library's version as the module's
``__version__``), is audited through the CLI, and the body is read back by a parser that
knows only the body's format: a title naming the function and what it gets wrong, the
versions (the library's and NumPy's), the worst input as exact hex floats, and a reproducer
that runs alone in a fresh ``python -c`` (no rigidsym; only the re-created module on the
path) and prints an error past the bound it prints beside it.

The default run audits one library without the continuous search; the eight run under
``slow`` with the search, as the CLI runs by default."""

from __future__ import annotations

import importlib
import re
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("flint")

ROOT = Path(__file__).resolve().parent.parent
BUGS = ROOT / "tests" / "peer_bugs"

#: (module:function, operation, the library, a finding's kind and regime the body must name)
PEER_BUGS = [
    ("scipy_recreated:as_euler_xyz", "euler_angles_from_rotation", "SciPy",
     "silent wrong", "gimbal lock"),
    ("pinocchio_recreated:log3", "rotation_vector_from_rotation", "Pinocchio",
     "inaccurate", "Q: phi->pi"),
    ("jaxlie_recreated:so3_log", "rotation_vector_from_rotation", "jaxlie",
     "inaccurate", "Q: phi->pi"),
    ("pytransform3d_recreated:compact_axis_angle_from_matrix",
     "rotation_vector_from_rotation", "pytransform3d", "inaccurate", "Q: phi->pi"),
    ("spatialmath_recreated:trlog", "rotation_vector_from_rotation", "spatialmath",
     "silent wrong", "Q: phi->0"),
    ("quaternion_recreated:rotation_vector", "rotation_vector_from_rotation",
     "numpy-quaternion", "convention", "differ by 2 pi w/|w|"),
    ("kornia_recreated:axis_angle_to_rotation_matrix", "rotation_from_rotation_vector",
     "kornia", "invariant", "Q^T Q = 1 broken"),
    ("transforms3d_recreated:mat2axangle", "natural_invariants_from_rotation",
     "transforms3d", "silent wrong", "Q: phi->0"),
]
#: the quick run's one library: found without the continuous search
QUICK = "jaxlie_recreated:so3_log"

TITLE = re.compile(r"^### `(?P<function>[^`]+)` (?P<what>.+)$")
VERSIONS = re.compile(r"Versions: (?P<list>[^\n]*?)\.\n")
FINDING = re.compile(r"^- \*\*(?P<severity>error|note)\*\* \((?P<kind>[\w ]+)\): (?P<text>.+)$",
                     re.M)
ARGUMENT = re.compile(r"^\| argument (?P<i>\d+) \| `(?P<hex>[^`]+)` \|$", re.M)
HEX = re.compile(r"^-?0x(?:[01]\.[0-9a-f]{13}p[+-]\d+|0\.0p\+0)$")   # 0: 0x0.0p+0
SCRIPT = re.compile(r"```python\n(?P<code>.*?)```", re.S)


def parse_issue(md: str) -> dict:
    """An issue body read back: ``title`` (the function, what it gets wrong), ``versions``
    (``{distribution: version}``), ``findings`` (``[(severity, kind, text)]``), ``inputs``
    (per worst input, its arguments as lists of hex strings) and ``scripts`` (the
    reproducers' code). Raises AssertionError naming what is missing."""
    lines = md.splitlines()
    title = TITLE.match(lines[0]) if lines else None
    assert title, f"no '### `function` what' title: {lines[:1]}"
    versions = VERSIONS.search(md)
    assert versions, "no 'Versions: ...' line"
    named = {}
    for item in versions.group("list").split(", "):
        name, _, ver = item.rpartition(" ")
        assert name and re.match(r"^\d+(\.\d+)+", ver), f"a version without a number: {item}"
        named[name] = ver
    findings = [(m["severity"], m["kind"], m["text"]) for m in FINDING.finditer(md)]
    assert findings, "no findings"
    blocks = md.split("**Worst input**")[1:]
    inputs = []
    for b in blocks:
        args = [(int(m["i"]), m["hex"].split()) for m in ARGUMENT.finditer(b)]
        assert args and [i for i, _ in args] == list(range(1, len(args) + 1)), b[:300]
        for _, hexes in args:
            assert all(HEX.match(h) for h in hexes), hexes
        inputs.append([h for _, h in args])
    scripts = [m["code"] for m in SCRIPT.finditer(md)]
    assert len(scripts) == len(inputs), "a worst input without its reproducer"
    return {"title": (title["function"], title["what"]), "versions": named,
            "findings": findings, "inputs": inputs, "scripts": scripts}


def run_alone(script: str, cwd: Path) -> dict:
    """Run a reproducer in a fresh interpreter with only the re-created modules on the path
    (no rigidsym): its printed relative error and bound."""
    res = subprocess.run([sys.executable, "-c", script], cwd=cwd, capture_output=True,
                         text=True, timeout=120,
                         env={"PYTHONPATH": str(BUGS), "PATH": "/usr/bin:/bin"})
    assert res.returncode == 0, res.stderr
    err = re.search(r"^relative error (\S+)$", res.stdout, re.M)
    bound = re.search(r"^the bound 8 u \(kappa \+ 1\) (\S+)$", res.stdout, re.M)
    assert err and bound, res.stdout
    return {"error": float(err.group(1)), "bound": float(bound.group(1)), "out": res.stdout}


def check_issue_body(spec: str, op: str, kind: str, where: str, tmp_path, monkeypatch,
                     capsys, search: bool) -> None:
    from rigidsym.cli import main

    monkeypatch.syspath_prepend(str(BUGS))
    monkeypatch.chdir(tmp_path)
    assert main(["audit", spec, "--as", op, "--markdown",
                 *([] if search else ["--no-search"])]) == 1
    md = capsys.readouterr().out
    issue = parse_issue(md)
    mod_name, _, func = spec.partition(":")
    mod = importlib.import_module(mod_name)
    assert issue["title"][0] == func and issue["title"][1] != "passes the audit", issue["title"]
    assert issue["versions"][mod_name] == mod.__version__, issue["versions"]
    assert issue["versions"]["numpy"] == importlib.import_module("numpy").__version__
    assert any(s == "error" and k == kind and where in t for s, k, t in issue["findings"]), \
        issue["findings"]
    assert issue["inputs"], "no worst input"
    for hexes, script in zip(issue["inputs"], issue["scripts"], strict=True):
        assert "rigidsym" not in script
        assert all(f"float.fromhex({h!r})" in script for arg in hexes for h in arg)
        ran = run_alone(script, tmp_path)
        # the wrong value: past the bound, or NaN (a comparison with NaN is False)
        assert not ran["error"] <= ran["bound"], ran["out"]


def test_one_peer_bug_becomes_an_issue_body_the_parser_reads(tmp_path, monkeypatch, capsys):
    spec, op, _, kind, where = next(b for b in PEER_BUGS if b[0] == QUICK)
    check_issue_body(spec, op, kind, where, tmp_path, monkeypatch, capsys, search=False)


@pytest.mark.slow
@pytest.mark.thorough(1 / 4)     # two of the eight each commit (all: exhaustive)
@pytest.mark.parametrize("spec, op, library, kind, where", PEER_BUGS,
                         ids=[b[2] for b in PEER_BUGS])
def test_each_libraries_bug_becomes_an_issue_body(spec, op, library, kind, where, tmp_path,
                                                   monkeypatch, capsys):
    check_issue_body(spec, op, kind, where, tmp_path, monkeypatch, capsys, search=True)


def test_the_parser_rejects_a_body_without_versions_or_hex():
    good = ("### `f` loses accuracy (float64, Q: phi->0)\n\nFound by `rigidsym audit` (2 "
            "conventions tried). Versions: lib 1.2, numpy 2.4.6.\n\n**Findings**\n\n"
            "- **error** (inaccurate): float64, Q: phi->0: error 3 x the bound\n\n"
            "**Worst input** (float64, Q: phi->0): error 5 u\n\n| | exact value |\n|---|---|\n"
            "| argument 1 | `0x1.0000000000000p+0 -0x1.8000000000000p-3` |\n\n"
            "```python\nprint(1)\n```\n")
    assert parse_issue(good)["versions"] == {"lib": "1.2", "numpy": "2.4.6"}
    with pytest.raises(AssertionError, match="Versions"):
        parse_issue(good.replace("Versions: lib 1.2, numpy 2.4.6.", ""))
    with pytest.raises(AssertionError):
        parse_issue(good.replace("-0x1.8000000000000p-3", "-0.1875"))
    with pytest.raises(AssertionError, match="reproducer"):
        parse_issue(good.replace("```python\nprint(1)\n```\n", ""))


def test_the_reproducer_judges_an_output_of_the_same_rotation_as_right(tmp_path):
    """A signed angle returns (-e, -phi) where the book's is (e, phi): the reproducer
    measures the error to the nearer of the truth and its negation (the same rotation by
    (2.49)), so that a correct function's issue body does not show a wrong value."""
    import numpy as np

    sys.path.insert(0, str(ROOT / "tests"))
    import audit_examples as X

    from rigidsym.auditing.audit import AuditReport, WorstInput
    from rigidsym.auditing.report import markdown

    e = np.array([-0.48, 0.6, 0.64])
    phi = 0.7
    E = X.cpm(e)
    Q = np.eye(3) + np.sin(phi) * E + (1 - np.cos(phi)) * E @ E
    got = np.concatenate([np.ravel(v) for v in X.axangle_signed(Q)])
    truth = np.concatenate([e, [phi]])
    assert np.linalg.norm(got - truth) > 1          # the negated member, not the truth
    w = WorstInput("float64", "random", 0.0, 0.0, 1.0, 0.0, "", [Q.tolist()],
                   truth.tolist(), got.tolist())
    rep = AuditReport("axangle_signed", "natural_invariants_from_rotation", "(2.49)", 8,
                      "f(Q), convention: the book's own", [], 0.0, None, [], {}, [w], "",
                      [], 0.0, "audit_examples:axangle_signed", "f(Q)", {"numpy": "2.4"},
                      "axis_angle")
    script = parse_issue(markdown(rep).replace("**Findings**\n\n", "**Findings**\n\n"
                                               "- **note** (none): nothing\n"))["scripts"][0]
    res = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True,
                         text=True, timeout=120,
                         env={"PYTHONPATH": str(ROOT / "tests"), "PATH": "/usr/bin:/bin"})
    assert res.returncode == 0, res.stderr
    err = float(re.search(r"^relative error (\S+)$", res.stdout, re.M).group(1))
    # a few u of the float rotation's rounding, where the naive difference is about 2
    assert err < 1e-14, res.stdout
