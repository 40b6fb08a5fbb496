"""LaTeX in, verdict out: ``rigidsym check --latex`` with ``--let``,
``rigidsym.check_latex``, and ``equation(latex=...)`` without a printed form."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
import sympy as sp

import rigidsym
from rigidsym.cli import main
from rigidsym.latex.lets import split_lets
from rigidsym.registry import declarations as registry

Q_ROT = r"\mathbf{Q}: rotation"
RODRIGUES_LETS = [r"\mathbf{e}: unit vector; \phi: angle; \mathbf{E} = \mathrm{CPM}(\mathbf{e})",
                  r"\mathbf{Q} = \mathbf{e}\mathbf{e}^T + \cos\phi(\mathbf{1} - "
                  r"\mathbf{e}\mathbf{e}^T) + \sin\phi\,\mathbf{E}"]
RODRIGUES = r"\mathbf{Q} = \mathbf{1} + \sin\phi\,\mathbf{E} + (1 - \cos\phi)\mathbf{E}^2"


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


def run_cli(capsys, *args) -> tuple[int, str, str]:
    code = main(["check", *args])
    out = capsys.readouterr()
    return code, out.out, out.err


# ------------------------------------------------------------------ the acceptance pair
def test_rotation_identity_prints_verified_from_the_command_line():
    proc = subprocess.run([sys.executable, "-m", "rigidsym", "check", "--latex",
                           r"\mathbf{Q}^T\mathbf{Q} = \mathbf{1}", "--let", Q_ROT],
                          capture_output=True, text=True, timeout=60,
                          env={"RIGIDSYM_ASCII": "0", "PYTHONIOENCODING": "utf-8",
                               **{k: v for k, v in __import__("os").environ.items()
                                  if k != "RIGIDSYM_ASCII"}})
    assert proc.returncode == 0, proc.stderr
    assert "read as: Qᵀ Q = 𝟏" in proc.stdout
    assert "Verdict: verified" in proc.stdout
    assert "Traceback" not in proc.stderr


def test_rodrigues_holds_with_first_principles_models(capsys):
    code, out, _ = run_cli(capsys, "--latex", RODRIGUES, *sum((["--let", x]
                                                            for x in RODRIGUES_LETS), []))
    assert code == 0 and "Verdict: verified" in out


@pytest.mark.parametrize("slip, repair", [
    (RODRIGUES.replace(r"+ \sin", r"- \sin"), "flip the sign"),   # a wrong sign on sin
    (RODRIGUES.replace(r"(1 - \cos\phi)", r"(1 + \cos\phi)"), "flip the sign"),
    (RODRIGUES.replace(r"(1 - \cos\phi)", r"(1 - \sin\phi)"), "sin φ → cos φ"),
    # cos where 1 - cos belongs: one edit of the vocabulary's one-minus
    (RODRIGUES.replace(r"(1 - \cos\phi)", r"\cos\phi"), "cos φ → 1 - cos φ"),
])
def test_a_one_edit_slip_of_rodrigues_does_not_hold_with_exact_point_and_repair(
        capsys, slip, repair):
    # the repairs found are the search's, not the clock's: no time limit in the API, a
    # day's (a hang guard) on the command line
    code, out, _ = run_cli(capsys, "--latex", slip, "--let", RODRIGUES_LETS[0],
                        "--let", RODRIGUES_LETS[1], "--repair-seconds", "86400")
    assert code == 1
    assert "Verdict: does-not-hold" in out and "Counterexample" in out
    r = rigidsym.check_latex(slip, RODRIGUES_LETS, repair_seconds=None)
    assert r.verdict == "does-not-hold"
    point = r.counterexample["point"]  # exact numbers (rationals, 2 atan(t)), no float
    assert point and all(sp.sympify(v).is_number and not sp.sympify(v).atoms(sp.Float)
                         for v in point.values())
    if repair is not None:
        assert any(repair in "; ".join(x["edits"]) for x in r.repairs), r.repairs
        assert "Repairs" in out


# ------------------------------------------------------------------ every --let kind
@pytest.mark.parametrize("latex, let, verdict", [
    (r"\mathbf{e}^T\mathbf{e} = 1", r"\mathbf{e}: unit vector", "verified"),
    (r"\mathbf{e}^T\mathbf{e} = 1", r"\mathbf{e}: vector", "does-not-hold"),
    (r"\mathbf{q}^T\mathbf{q} = 1", r"\mathbf{q}: unit 4-vector", "verified"),
    (r"\mathbf{Q}\mathbf{Q}^T = \mathbf{1}", Q_ROT, "verified"),
    (r"\det(\mathbf{Q}) = 1", r"\mathbf{Q}: matrix", "does-not-hold"),
    (r"(\cos\phi)^2 + (\sin\phi)^2 = 1", r"\phi: angle", "verified"),
    (r"(\cos\theta)^2 + (\sin\theta)^2 = 1", r"\theta: angle in [0, \pi]", "verified"),
    (r"\mathbf{k}\mathbf{a} = \mathbf{a}\mathbf{k}", r"\mathbf{k}: scalar", "verified"),
    (r"(\mathbf{U}\mathbf{s})^T = \mathbf{s}^T\mathbf{U}^T",
     r"\mathbf{U}: 6x6 matrix; \mathbf{s}: 6-vector", "verified"),
    (r"(\mathbf{M}\mathbf{a})^T = \mathbf{a}^T\mathbf{M}^T", r"\mathbf{M}: 2×3 matrix",
     "verified"),
    (r"\mathbf{S}^T = \mathbf{S}", r"\mathbf{S}: symmetric matrix", "verified"),
    (r"\mathbf{S}^T = \mathbf{S}", r"\mathbf{S}: matrix", "does-not-hold"),
    (r"\mathbf{t}^T\mathbf{w} = \mathbf{w}^T\mathbf{t}", r"\mathbf{t}: twist; \mathbf{w}: wrench",
     "verified"),
    (r"\det(\mathbf{T}) = 1", r"\mathbf{T}: transform", "verified"),
])
def test_each_kind_is_imposed_exactly(latex, let, verdict):
    r = rigidsym.check_latex(latex, [let])
    assert r.verdict == verdict, r.detail
    assert r.id.startswith("latex:") and len(r.id) == len("latex:") + 10


def test_a_constrained_kind_names_its_constraint_in_the_model():
    assert "Q: rotation, rational quaternion" in rigidsym.check_latex(
        r"\mathbf{Q}^T\mathbf{Q} = \mathbf{1}", [Q_ROT]).model
    r = rigidsym.check_latex(r"(\cos\theta)^2 + (\sin\theta)^2 = 1", [r"\theta: angle in [0, pi]"])
    assert any("[0, pi]" in m for m in r.model)


def test_names_compare_after_parsing_and_undeclared_symbols_are_free():
    r = rigidsym.check_latex(r"\mathbf Q^T \mathbf{Q}\mathbf{a} = \mathbf{a}",
                             [r"\mathbf Q: rotation"])
    assert r.verdict == "verified"
    assert any(m.startswith("free") and r"\mathbf{a} (3-vector)" in m for m in r.model)


def test_split_at_semicolon_space_outside_braces():
    assert split_lets([r"\mathbf{x} = {a; b}; y: scalar", "z: angle"]) == \
        [r"\mathbf{x} = {a; b}", "y: scalar", "z: angle"]


def test_let_as_list_and_as_dict_agree():
    a = rigidsym.check_latex(RODRIGUES, RODRIGUES_LETS)
    b = rigidsym.check_latex(RODRIGUES, {
        r"\mathbf{e}": "unit vector", r"\phi": "angle",
        r"\mathbf{E}": r"\mathrm{CPM}(\mathbf{e})",
        r"\mathbf{Q}": "= " + RODRIGUES_LETS[1].split("=", 1)[1]})
    assert a.verdict == b.verdict == "verified" and isinstance(a, rigidsym.Result)


def test_a_definition_and_an_undecided_exit_codes(capsys):
    code, out, _ = run_cli(capsys, "--latex", r"\mathbf{V} \equiv \mathbf{a}\mathbf{a}^T")
    assert code == 0 and "Verdict: definition" in out
    # x also occurs bare, so it is no angle (a half angle alone would be: periodic.py)
    code, out, _ = run_cli(capsys, "--latex", r"x\sin x = 2x\sin(x/2)\cos(x/2)")
    assert code == 3 and "undecided" in out  # x is no angle: its trig is never guessed


# ------------------------------------------------------------------ --book and --module
def test_book_section_names_glyphs_and_an_ambiguous_glyph_asks_for_let(capsys):
    code, out, _ = run_cli(capsys, "--latex", r"\mathbf{E}^T = -\mathbf{E}", "--book", "3.2")
    assert code == 0 and "cross-product matrix of e" in out   # E = CPM(e), the table's row
    code, out, _ = run_cli(capsys, "--latex", r"\mathbf{W}^T = -\mathbf{W}", "--book", "3.5")
    assert code == 1 and "angular-acceleration matrix" in " ".join(out.split())  # not skew
    code, _, err = run_cli(capsys, "--latex", r"\mathbf{W}^T = -\mathbf{W}", "--book", "3")
    assert code == 2 and "ambiguous" in err and "--let" in err and "3.5" in err


def test_without_book_no_glyph_of_the_chapter_reaches_a_readers_latex(capsys):
    """The chapter's glyph table names glyphs only where a reader says --book: E e = 0
    holds for the chapter's E = CPM(e) and not for a 3 x 3 matrix of one's own."""
    code, out, _ = run_cli(capsys, "--latex", r"\mathbf{E}\mathbf{e} = \mathbf{0}",
                           "--book", "3.2")
    assert code == 0 and "cross-product matrix of e" in out
    code, out, _ = run_cli(capsys, "--latex", r"\mathbf{E}\mathbf{e} = \mathbf{0}",
                           "--no-repairs")
    assert code == 1 and "cross-product matrix" not in out


MODULE = '''
import sympy as sp
from rigidsym import Statement, angle, cpm, equation, expm, mat, unit_vector, vec

R, Om, om = mat("R"), mat("Omega"), vec("omega")
w, theta = unit_vector("omega"), angle("theta")
ROT = {R: expm(theta * cpm(w)), Om: cpm(w), om: w}


@equation("mine:rodrigues", "Rodrigues, printed form read from the LaTeX",
          latex=r"\\mathbf{R} = \\mathbf{1} + \\sin\\theta\\,\\boldsymbol{\\Omega}"
                r" + (1 - \\cos\\theta)\\boldsymbol{\\Omega}^2")
def rodrigues():
    return ROT  # the model alone


@equation("mine:axis-sign", "The axis, sign slipped", expected="does-not-hold",
          latex=r"\\mathbf{R}\\boldsymbol{\\omega} = -\\boldsymbol{\\omega}")
def axis_sign():
    return Statement([], ROT)
'''


@pytest.fixture
def module(tmp_path):
    path = tmp_path / "mine_latex.py"
    path.write_text(MODULE)
    yield str(path)
    from rigidsym.registry import usermodules

    for name in [n for n, um in usermodules.LOADED.items() if um.path == path]:
        registry.forget_module(name)
        usermodules.LOADED.pop(name)
        sys.modules.pop(name, None)


def test_module_lends_its_symbols_and_models(capsys, module):
    latex = r"\mathbf{R}\boldsymbol{\omega} = \boldsymbol{\omega}"
    code, out, _ = run_cli(capsys, "--latex", latex, "--module", module)
    assert code == 0 and "Verdict: verified" in out
    assert "lent by --module: " in " ".join(out.split())  # wrapped to the width
    code, out, _ = run_cli(capsys, "--latex", latex.replace("= ", "= 2"), "--module", module)
    assert code == 1


def test_equation_with_latex_and_no_printed_form_reads_it(module):
    rs = rigidsym.verify(modules=[module], cache=False, repairs=False)
    assert {r.id: r.verdict for r in rs} == {"mine:rodrigues": "verified",
                                             "mine:axis-sign": "does-not-hold"}
    assert rs["mine:rodrigues"].to_json()["transcription"]["status"] == "machine-checked"


# ------------------------------------------------------------------ bad input, exit 2
@pytest.mark.parametrize("args, words", [
    ([r"\mathbf{Q}^T\mathbf{Q} = "], ["position", "^", "expected"]),
    ([r"\mathbf{Q} = \foo{Q}"], ["unknown macro \\foo"]),
    ([r"\mathbf{a}\mathbf{b} = \mathbf{0}"], ["\\mathbf{a}", "--let", "depends on the shape"]),
    # an unused --let spelt near an undeclared glyph: the likely misspelling, both named
    ([r"\mathbf{a} = \mathbf{a}", "--let", r"a: vector"],
     ["does not occur", "\\mathbf{a}", "spelt near"]),
    ([r"\mathbf{a} = \mathbf{a}", "--let", r"\mathbf{a}: banana"],
     ["unknown kind", "unit vector", "rotation", "m×n matrix", "twist"]),
    ([r"\mathbf{a} = \mathbf{a}", "--let", r"\mathbf{a} rotation"], ["NAME: KIND"]),
    ([r"\mathbf{a} = \mathbf{a}", "--let", r"\mathbf{a}: vector; \mathbf a: vector"],
     ["declared twice"]),
    ([r"\mathbf{Q}\mathbf{e} = \mathbf{e}", "--let", r"\mathbf{Q} = \mathbf{Q}^T"],
     ["refers to"]),
    ([r"\mathbf{a} = \mathbf{a}", "--book", "4.1"], ["--book"]),
])
def test_bad_input_is_named_with_exit_2_and_no_traceback(capsys, args, words):
    code, out, err = run_cli(capsys, "--latex", *args)
    assert code == 2 and not out
    for w in words:
        assert w in err, (w, err)
    assert "Traceback" not in err


def test_bad_input_from_python_raises_value_errors():
    with pytest.raises(ValueError, match="does not occur"):
        rigidsym.check_latex(r"\mathbf{a} = \mathbf{a}", [r"\mathbf{a}_1: vector"])
    with pytest.raises(ValueError, match="position"):
        rigidsym.check_latex(r"\mathbf{a} = (", None)
    with pytest.raises(ValueError, match="let"):
        rigidsym.check_latex(r"\mathbf{a} = \mathbf{a}", 3)
    # a misspelt kind in a dict is an error, never read as a product of letters (a model)
    with pytest.raises(ValueError, match=r"unknown kind 'rotaton'.*'= rotaton'"):
        rigidsym.check_latex(r"\mathbf{Q}^T\mathbf{Q} = \mathbf{1}", {r"\mathbf{Q}": "rotaton"})
    assert rigidsym.check_latex("x = y z", {"x": "= y z"}).verdict == "verified"


# ------------------------------------------------------------------ --json
def test_json_is_the_schema_2_record_with_the_reading(capsys):
    code, out, _ = run_cli(capsys, "--latex", r"\mathbf{Q}^T\mathbf{Q} = \mathbf{1}",
                        "--let", Q_ROT, "--json")
    rec = json.loads(out)
    assert code == 0 and rec["id"].startswith("latex:") and rec["verdict"] == "verified"
    assert rec["read_as"] == "Qᵀ Q = 𝟏" and isinstance(rec["readings"], list)
    r = rigidsym.check_latex(r"\mathbf{Q}^T\mathbf{Q} = \mathbf{1}", [Q_ROT])
    assert set(r.to_json()) <= set(rec)      # the record of rigidsym.check, and more
    assert rec["id"] == r.id                 # the id hashes the input: the same twice


def test_a_scalar_glyph_is_never_an_entry_of_a_free_matrix():
    # Q_{11} beside a free matrix Q: two independent quantities (the entries are renamed
    # Q__11, ...), so the relation does not hold; were they one atom it would "verify"
    r = rigidsym.check_latex(r"Q_{11} = \mathbf{e}_1^T\mathbf{Q}\mathbf{e}_1",
                             [r"\mathbf{Q}: matrix",
                              r"\mathbf{e}_1 = \begin{bmatrix}1 \\ 0 \\ 0\end{bmatrix}"])
    assert r.verdict == "does-not-hold"
    assert {"Q_11", "Q__11"} <= set(r.counterexample["point"])


def test_a_readers_matrix_of_scalars_prints_as_one_matrix(capsys):
    """Craig's rotation written entry by entry: read (and printed) as one 2 x 2 matrix, not
    four 1 x 1 blocks (``[[c_θ], [-s_θ]; ...]`` before), with the Greek subscripts in their
    letters."""
    code, out, _ = run_cli(capsys, "--latex", r"\mathbf{A} = \begin{bmatrix} c_\theta & -s_\theta"
                        r" \\ s_\theta & c_\theta \end{bmatrix}", "--let",
                        r"c_\theta = \cos\theta", "--let", r"s_\theta = \sin\theta",
                        "--let", r"\theta: angle", "--let", r"\mathbf{A}: 2×2 matrix",
                        "--no-repairs")
    assert "Verdict: does-not-hold" in out   # A is free
    assert "A = [c_θ, -s_θ; s_θ, c_θ]" in out and "[[" not in out and "block" not in out
