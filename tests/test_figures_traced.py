"""Every measured figure the pages quote comes from a committed record.

A figure in README.md or docs/*.md is followed by an invisible marker naming its source,
``251.5 s<!-- fig: test_command-merged.json wall_s -->``: a JSON record under
benchmarks/results/ that names its machine, and a path into it (docs/testing.md, "Where a
figure comes from"). The figure must read as the record's value does, and a time figure, a
ratio ("1.07x", "0.73-0.84x the hand-written code", "4.5e4 x the bound") or a percentage
with no marker fails unless it is listed below as no measurement (a setting, a target, a
test's tolerance, algebra). A measured figure no record holds is not quoted: the page names
the command that measures it.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results"
#: generated API reference, not prose
NOT_PAGES = {"api.md", "_api_source.md"}

MARKER = re.compile(r"<!--\s*fig:(?P<body>.*?)-->", re.S)
#: FILE PATH [OP]...: PATH is dotted keys, [N] indices, ["quoted key"] and [*] (every item);
#: OP is min, max or a format spec (no "|": a marker may sit in a table cell)
STEP = re.compile(r'\.?(?:\[(\d+|\*|"[^"]*")\]|([^.\[\]"\s]+))')
BODY = re.compile(r'\s*(?P<file>[\w.-]+\.json)\s+(?P<path>(?:\.?(?:\[(?:\d+|\*|"[^"]*")\]'
                  r'|[^.\[\]"\s]+))+)(?P<ops>(?:\s+\S+)*)\s*$')
#: the figure right before a marker: a number, in exponent form too ("3.6e4 x"), optionally
#: its unit
FIGURE = re.compile(r"(-?\d+(?:\.\d+)?(?:e[+-]?\d+)?)(?:\s?(?:s|ms|us|µs|ns|min|%|x|×))?$")
#: an exponent as Python's format writes it ("e+04", "e-03"), for the page's "e4", "e-3"
EXPONENT = re.compile(r"e([+-]?)0*(\d)")

#: a time figure: a number (or range of two) and a unit of time
TIME = re.compile(r"(?<![\w.^/-])\d+(?:\.\d+)?(?:\s?(?:–|-|to)\s?\d+(?:\.\d+)?)?"
                  r"\s?(?:s|ms|us|µs|ns|min|minutes?|seconds?|hours?)\b(?!\.f\.|\^)")

#: a ratio: a number (or range of two, or a power of ten) then "x" or "×" meaning "times" (not a
#: shape, "3 x 3", "6×6"; not a name's digit, "p1 x p2")
RATIO = re.compile(r"(?<![\w.^/%-])\d+(?:\.\d+)?(?:e[+-]?\d+)?"
                   r"(?:\s?(?:–|-|to)\s?\d+(?:\.\d+)?(?:e[+-]?\d+)?)?\s?(?:x|×)(?!\w|\s?\d)")
#: a percentage (not Moodle's "%50%" weight syntax)
PERCENT = re.compile(r"(?<![\w.^/%~-])\d+(?:\.\d+)?(?:\s?(?:–|-|to)\s?\d+(?:\.\d+)?)?\s?%")

#: time figures, ratios and percentages that measure nothing: page, the text around the
#: figure, and why
NOT_MEASURED = [
    ("docs/certificates.md", "| 60 s of CPU time |", "certcheck's CPU limit on one "
     "certificate, a setting (certcheck.limits.MAX_SECONDS)"),
    ("docs/commands.md", "default 60 s of CPU time", "check --latex's time limit, a setting "
     "(rigidsym.latex.limit)"),
    ("README.md", "least one every 2.5 s", "the build's progress interval, a setting "
     "(rigidsym.kernels.cbuild.driver.SILENCE)"),
    ("docs/setup.md", "at least one every 2.5 s", "the build's progress interval, a setting"),
    ("docs/commands.md", "then one every 2.5 s saying", "the start's longest quiet, a "
     "setting (progress.SILENCE)"),
    ("docs/commands.md", "with no line for 2.5 s says", "a piped phase's longest quiet, a "
     "setting (progress.SILENCE)"),
    ("docs/accuracy.md", "= 2 s (c E", "algebra: s is sin(phi/2)"),
    ("docs/accuracy.md", "(s cos s + 2 s - 3 sin s)", "algebra: s is |w|"),
    ("docs/adding-a-kernel.md", "(SIGINT after 150 s)", "the interrupt's time-out, a setting"),
    ("docs/certificates.md", "Within 5 s of CPU, 20 000 terms",
     "the cofactor search's CPU budget per relation, a setting (cofactors.SECONDS)"),
    ("docs/certificates.md", "`coqc` with 60 s per id", "coq_share.py's --timeout, a setting"),
    ("docs/check-latex.md", "the time limit (2 s) passed", "an example's --timeout, a setting"),
    ("docs/check-latex.md", "(default 10 s)", "--repair-seconds' default, a setting"),
    ("docs/check-latex.md", "after 10 s, K candidates tried", "the message at that default"),
    ("docs/kernels-speed.md", "`check=False` <= 1.5 us holds", "the N = 1 target, a goal"),
    ("docs/lie-groups.md", "g(s) = (2s − asin s", "algebra: 2s is 2 times s"),
    ("docs/testing.md", "alive 5 s after it ends", "the process guard's grace, a setting"),
    ("docs/verify.md", "of 5 s stays as a safety net", "the CPU-time alarm, a setting"),
    # ratios
    ("docs/accuracy.md", "abs(phi) < 1e-300 x norm(input)",
     "algebra: a threshold times the input's norm (the declared singular set)"),
    ("docs/audit.md", "(`log_arccos_window`, 10 to 150 x the bound)",
     "the planted defect's error by its construction, u / (8 u phi) on its window"),
    ("docs/audit.md", "width of\n2x or more", "the planted window's width, a test's setting"),
    ("docs/c-api.md", "The target of 1.1x in instructions", "a target"),
    ("docs/c-api.md", "per component is 1.4x",
     "arithmetic: (30 + 12) / 30, the instructions by hand and the components beside it"),
    ("docs/differentiable-kernels.md", "at most 5x the forward program's",
     "the bound tests/test_codegen_vjp.py asserts"),
    ("docs/repairs.md", "its 1.5× time budget", "a target"),
    ("docs/soundness.md", "the gradient `2x ≠ 0`", "algebra: 2 times x"),
    ("docs/where-it-stands.md", "target ≥ 1.7× on K2, K5", "a target"),
    ("docs/where-it-stands.md", "target ≥ 1.6× on K1, K4, K6", "a target"),
    ("docs/where-it-stands.md", "the target of 1.6×", "a target"),
    ("docs/where-it-stands.md", "target 1.10× its time", "a target"),
    # percentages
    ("docs/audit.md", "to within 1 %", "the bisection's tolerance on a window's end, a setting"),
    ("docs/audit.md", "at 2.3e-3 within 1 %", "tests/test_audit_windows.py's tolerance"),
    ("docs/audit.md", "its ends within 5 % of the", "tests/test_audit_windows.py's tolerance"),
    ("docs/check-latex.md", "at least 97 % of the decided", "the metamorphic test's floor"),
    ("docs/check-latex.md", "at most 3 % of the variants", "the same floor, its complement"),
    ("docs/check-latex.md", "(under a floor of 5 %)", "the test's floor"),
    ("docs/exams.md", "the 0.1 % tolerance", "the grading tolerance, a setting"),
    ("docs/exams.md", "within 0.1 % of", "the grading tolerance, a setting"),
    ("docs/exams.md", "(`=value:tol` 100 %", "Moodle's full credit, a definition"),
] + [("docs/kernels.md", around, "measured against the page by "
       "tests/test_one_answer_measured.py (to 2 points; float64 exactly)")
      for around in ("`twist_transfer` 81.2 %", "`kinetic_energy` 16.9 %",
                     "`rotation_from_euler_rodrigues` 99.7 %", "float64: 0 %")]


def pages() -> list[Path]:
    return [ROOT / "README.md"] + sorted(p for p in (ROOT / "docs").glob("*.md")
                                         if p.name not in NOT_PAGES)


def _name(page: Path) -> str:
    return page.relative_to(ROOT).as_posix()


def _line(text: str, pos: int) -> int:
    return text.count("\n", 0, pos) + 1


def _follow(value, path: str):
    pos = 0
    steps = []
    while pos < len(path):
        m = STEP.match(path, pos)
        if not m or m.end() == pos:
            raise ValueError(f"bad path {path!r} at {path[pos:]!r}")
        steps.append(m.group(1) if m.group(1) is not None else m.group(2))
        pos = m.end()
    values = [value]
    for step in steps:
        if step == "*":
            values = [v for value in values for v in
                      (value.values() if isinstance(value, dict) else value)]
        elif step.isdigit() and isinstance(values[0], list):
            values = [value[int(step)] for value in values]
        else:
            key = step[1:-1] if step.startswith('"') else step
            values = [value[key] for value in values]
    return values if "*" in steps else values[0]


def _as_printed(formatted: str) -> str:
    """``formatted`` as the pages print a power of ten: "3.6e+04" as "3.6e4", "2.5e-03" as
    "2.5e-3" (the mantissa's digits, the page's precision, as the format spec gives them)."""
    return EXPONENT.sub(lambda m: "e" + m.group(1).replace("+", "") + m.group(2), formatted)


def _apply(value, ops: str) -> str:
    for op in ops.split():
        if op in ("min", "max"):
            value = (min if op == "min" else max)(value)
        else:
            return _as_printed(format(value, op))
    if isinstance(value, list):
        raise ValueError("a [*] path needs min or max")
    return _as_printed(str(value))


def _names_its_machine(record) -> bool:
    host = record.get("host") or record.get("machine") or {}
    return bool(host.get("cpu") or host.get("cpu model")) and bool(host.get("cores"))


def markers():
    for page in pages():
        text = page.read_text(encoding="utf-8")
        for m in MARKER.finditer(text):
            yield page, text, m


def _check(page: Path, text: str, m: re.Match) -> str | None:
    where = f"{_name(page)}:{_line(text, m.start())}"
    body = BODY.match(m.group("body"))
    if not body:
        return f"{where}: unparsable marker {m.group(0)!r}"
    source = RESULTS / body["file"]
    if not source.is_file():
        return f"{where}: no record benchmarks/results/{body['file']}"
    record = json.loads(source.read_text(encoding="utf-8"))
    if not _names_its_machine(record):
        return f"{where}: {body['file']} names no machine (host or machine: cpu, cores)"
    try:
        want = _apply(_follow(record, body["path"]), body["ops"])
    except (KeyError, IndexError, TypeError, ValueError) as e:
        return f"{where}: {body['file']} {body['path']}{body['ops']}: {e!r}"
    got = FIGURE.search(text[max(0, m.start() - 40):m.start()])
    if not got or got.group(1) != want:
        return (f"{where}: the page says {got.group(0) if got else 'no figure'!r} before the "
                f"marker, {body['file']} {body['path']}{body['ops']} gives {want!r}")
    return None


def test_every_marked_figure_is_its_records_value():
    wrong = [e for e in (_check(*found) for found in markers()) if e]
    assert not wrong, "\n".join(wrong)


def test_the_pages_trace_their_figures():
    # so that deleting every marker cannot pass: at least those of the pages below
    names = {_name(page) for page, _, _ in markers()}
    assert len(list(markers())) >= 47
    assert {"docs/adding-a-kernel.md", "docs/verify.md", "docs/testing.md",
            "docs/where-it-stands.md"} <= names, names


def _untraced(figure: re.Pattern) -> list[str]:
    """Each figure matching ``figure`` on the pages with no marker right after it and no
    allowance in NOT_MEASURED: 'page:line: figure in line'."""
    untraced = []
    for page in pages():
        text = page.read_text(encoding="utf-8")
        allowed = [(around, why) for p, around, why in NOT_MEASURED if p == _name(page)]
        found = []
        for m in figure.finditer(text):
            if text.startswith("<!--", m.end()) or MARKER.match(text, m.end()):
                continue
            if any(around in text[m.start() - 40:m.end() + 40] and m.group(0) in around
                   for around, _ in allowed):
                continue
            line = text.splitlines()[_line(text, m.start()) - 1].strip()
            found.append(f"{_name(page)}:{_line(text, m.start())}: {m.group(0)!r} in "
                         f"{line[:100]!r}")
        untraced += found
    return untraced


def test_no_time_figure_is_untraced():
    untraced = _untraced(TIME)
    assert not untraced, ("time figures with no record (a <!-- fig: --> marker), or list "
                          "them in NOT_MEASURED with why:\n" + "\n".join(untraced))


def test_no_ratio_or_percentage_is_untraced():
    untraced = _untraced(RATIO) + _untraced(PERCENT)
    assert not untraced, ("ratios and percentages with no record (a <!-- fig: --> marker): "
                          "name the command that measures them instead, or list them in "
                          "NOT_MEASURED with why:\n" + "\n".join(untraced))


@pytest.mark.parametrize(("text", "figures"), [
    ("the rotation 1.17x, the wrench 1.03-1.15x and 4.5e4 x the bound", 3),
    ("within 1.2× in both; 0.73–0.84× SymForce's", 2),
    ("a 3 x 3 matrix, 6×6 blocks, `p1 x p2`, `e1 x e2`, log10 x", 0),
])
def test_a_ratio_is_a_number_times_not_a_shape_or_a_product(text, figures):
    assert len(RATIO.findall(text)) == figures, RATIO.findall(text)


@pytest.mark.parametrize(("text", "figures"), [
    ("81.2 %, 16.9%, 5-6 %", 3),
    ("`~%50%-1.414:0.00141`, `%100%`", 0),
])
def test_a_percentage_is_a_number_then_percent(text, figures):
    assert len(PERCENT.findall(text)) == figures, PERCENT.findall(text)


def test_every_allowance_still_applies():
    stale = [(p, around) for p, around, _ in NOT_MEASURED
             if around not in (ROOT / p).read_text(encoding="utf-8")]
    assert not stale, stale


@pytest.mark.parametrize(("text", "error"), [
    ("1 s<!-- fig: nowhere.json wall_s -->", "no record"),
    ("1 s<!-- fig: test_command-merged.json wall_ss -->", "KeyError"),
    ("1 s<!-- fig: test_command-merged.json -->", "unparsable"),
    ("1 s<!-- fig: test_command-merged.json wall_s -->", "gives '251.5'"),
])
def test_a_wrong_marker_fails_naming_page_and_line(text, error):
    page = ROOT / "docs" / "x.md"
    m = MARKER.search("\n" + text)
    found = _check(page, "\n" + text, m)
    assert found and found.startswith("docs/x.md:2: ") and error in found, found


def test_a_right_marker_passes():
    text = "all 251.5 s<!-- fig: test_command-merged.json wall_s --> and 92.6<!-- fig: " \
           "test_command-merged.json parts[0].wall_s .1f -->"
    assert [_check(ROOT / "README.md", text, m) for m in MARKER.finditer(text)] == [None, None]
    assert not [m for m in TIME.finditer(text) if not MARKER.match(text, m.end())]


@pytest.mark.parametrize(("before", "figure"), [
    ("the bound is 3.6e4 x", "3.6e4"),
    ("below 1.8e-8 (5.6e14 x", "5.6e14"),
    ("| 2.5e-3", "2.5e-3"),
    ("(1.15 x", "1.15"),
    ("took 251.5 s", "251.5"),
])
def test_the_figure_before_a_marker_may_be_a_power_of_ten(before, figure):
    assert FIGURE.search(before).group(1) == figure


@pytest.mark.parametrize(("formatted", "printed"), [
    ("3.6e+04", "3.6e4"), ("1.4e+15", "1.4e15"), ("2.5e-03", "2.5e-3"), ("5e+00", "5e0"),
    ("1e-05", "1e-5"), ("297", "297"), ("1.15", "1.15"),
])
def test_an_exponent_is_compared_as_the_pages_print_it(formatted, printed):
    assert _as_printed(formatted) == printed


def test_a_ratio_in_exponent_form_is_checked_at_its_printed_precision():
    # the record holds 36161.52...: "3.6e4" at .1e, "3.62e4" at .2e; "3.7e4" is not it
    right = "3.6e4 x<!-- fig: audit_peers.json rows[0].worst[0].ratio .1e --> and 3.62e4 x" \
            "<!-- fig: audit_peers.json rows[0].worst[0].ratio .2e -->"
    assert [_check(ROOT / "README.md", right, m) for m in MARKER.finditer(right)] == [None] * 2
    assert not [m for m in RATIO.finditer(right) if not MARKER.match(right, m.end())]
    wrong = "\n3.7e4 x<!-- fig: audit_peers.json rows[0].worst[0].ratio .1e -->"
    found = _check(ROOT / "docs" / "x.md", wrong, MARKER.search(wrong))
    assert found and found.startswith("docs/x.md:2: ") and "gives '3.6e4'" in found, found


# ------------------------------------------------------------------ what the tool prints
#: a quoted output of the tool: ``…`<!-- quote: FILE PATH -->``, the code span before it
#: equal to the record's string (or ending in `` = `` and it: ``e = [...]``)
QUOTE = re.compile(r"`(?P<span>[^`]*)`<!--\s*quote:(?P<body>.*?)-->", re.S)
#: a recorded command -> the pages that show it, word for word (benchmarks/
#: check_latex_examples.py records what the tool prints for it)
SHOWN = {"rodrigues_slip": ("README.md", "docs/check-latex.md")}
EXAMPLES = RESULTS / "check_latex_examples.json"


def _commands(text: str) -> list[list[str]]:
    """Every ``rigidsym ...`` shell command of a page's code, its continued lines joined,
    as an argument list."""
    import shlex

    out = []
    for line in text.replace("\\\n", " ").splitlines():
        line = line.strip()
        if line.startswith("rigidsym "):
            try:
                out.append(shlex.split(line, comments=True))
            except ValueError:      # not a shell line (prose starting with the name)
                pass
    return out


def test_every_quoted_output_is_what_the_tool_printed():
    """A counterexample or a repair quoted from the tool equals the record of the command's
    run (benchmarks/check_latex_examples.py), not a hand copy."""
    wrong, n = [], 0
    for page in pages():
        text = page.read_text(encoding="utf-8")
        for m in QUOTE.finditer(text):
            n += 1
            where = f"{_name(page)}:{_line(text, m.start())}"
            body = BODY.match(" ".join(m.group("body").split()))
            if not body:
                wrong.append(f"{where}: unparsable marker {m.group(0)!r}")
                continue
            record = json.loads((RESULTS / body["file"]).read_text(encoding="utf-8"))
            assert _names_its_machine(record), body["file"]
            want = str(_follow(record, body["path"]))
            span = m.group("span")
            if span != want and not span.endswith(" = " + want):
                wrong.append(f"{where}: the page quotes {span!r}, {body['file']} "
                             f"{body['path']} is {want!r}")
    assert not wrong, "\n".join(wrong)
    assert n >= 5, "the Rodrigues slip's quotes in docs/check-latex.md are gone"


def test_the_pages_show_the_recorded_command_word_for_word():
    """The command whose output a page quotes is the one the record ran: a reader who runs
    the README's (or check-latex.md's) command sees the quoted counterexample."""
    record = json.loads(EXAMPLES.read_text(encoding="utf-8"))
    for name, shown in SHOWN.items():
        argv = record["examples"][name]["argv"]
        for page in shown:
            assert argv in _commands((ROOT / page).read_text(encoding="utf-8")), (page, argv)


def test_the_readme_commands_time_is_its_newest_record():
    """One figure for the README's command: each page that states its time states first
    that of the newest record (``test_command-*.json`` by its commit's date; a record with
    no commit predates those with one), and never another as the current one."""
    import subprocess

    dated = {}
    for f in RESULTS.glob("test_command-*.json"):
        commit = json.loads(f.read_text(encoding="utf-8")).get("commit")
        if not commit:
            continue
        r = subprocess.run(["git", "show", "-s", "--format=%ct", commit], cwd=ROOT,
                           capture_output=True, text=True)
        if r.returncode != 0:
            pytest.skip(f"no git history of {commit} here (an sdist, a shallow clone)")
        dated[f.name] = int(r.stdout.strip())
    newest = max(dated.values())
    for page in ("docs/where-it-stands.md", "docs/testing.md"):
        text = (ROOT / page).read_text(encoding="utf-8")
        cited = [b["file"] for b in (BODY.match(m.group("body")) for m in MARKER.finditer(text))
                 if b and b["file"].startswith("test_command-") and b["path"] == "wall_s"]
        assert cited and dated.get(cited[0]) == newest, (page, cited[:1], newest)


def test_the_build_counts_on_the_pages_are_the_trees():
    """The kernels and objects the pages count are those of the generated tree, as the
    driver plans them (x86-64-v2 and -v3 every kernel and the table, -v4 the kernels that
    call sin or cos and the table, and the module), not a figure of an older tree."""
    from rigidsym.kernels.cbuild import driver, paths

    sources = driver.kernel_sources(ROOT / "generated" / "c")
    plan, _ = paths.partial_plan(paths.X86_PATHS, sources, driver.TABLE_SOURCE)
    n = {k: len(v) for k, v in plan.items()}
    want = [("README.md", r"the (\d+) kernels and their table", len(sources) - 1),
            ("README.md", r"the (\d+) that call\s+`sin`/`cos`", n["v4"] - 1),
            ("docs/setup.md", r"\((\d+) objects\s+instead", len(sources) + 1),
            ("docs/setup.md", r"instead of the (\d+) of x86-64-v4 and -v3", n["v4"] + n["v3"] + 1),
            ("benchmarks/RESULTS.md", r"The tree now builds (\d+) objects", sum(n.values()) + 1),
            ("benchmarks/RESULTS.md", r"\((\d+) for x86-64-v2", n["v2"]),
            ("benchmarks/RESULTS.md", r"(\d+) for x86-64-v4, and the module", n["v4"])]
    wrong = []
    for page, pattern, value in want:
        m = re.search(pattern, (ROOT / page).read_text(encoding="utf-8"))
        if not m or int(m.group(1)) != value:
            wrong.append(f"{page}: {pattern!r} reads {m.group(1) if m else None}, the tree "
                         f"has {value}")
    assert not wrong, "\n".join(wrong)
