"""The grader names a student's slip: each slip is planted in the right
answer of a variant of its exercise (the expected slip is built here from the exercise's
physics, not read from the grader), the right answers pass, random ones are "not a known
slip"; the CLI grades one student (text, JSON) and a class (folder, CSV)."""

from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest
import sympy as sp
from _profile import examples
from hypothesis import given, settings
from hypothesis import strategies as st

import rigidsym.exercises as ex
from rigidsym.cli import main
from rigidsym.course.worked import to_json_value


def _floats(m) -> list:
    return np.array(sp.N(m, 17).tolist(), dtype=float).tolist()


def _slip(solution, name, value):
    return _named(ex.grade(solution, {name: value}), name)


def _named(graded, name):
    (g,) = [g for g in graded if g.name == name]
    return g


# a variant of each exercise: 3.4 with a Cayley rotation, 3.19 turned 90 deg, a flat plate
@pytest.fixture(scope="module")
def ex34():
    # F_2 turned by the Cayley rotation of (1, 2, 2)/3 ... readings rotated exactly
    c = sp.Matrix([1, 2, 2]) / 3
    C = sp.Matrix([[0, -c[2], c[1]], [c[2], 0, -c[0]], [-c[1], c[0], 0]])
    Q = (sp.eye(3) - C).inv() * (sp.eye(3) + C)       # [x]_1 = Q [x]_2
    n1, f1 = sp.Matrix([1, 0, 5]), sp.Matrix([0, 2, 1])
    s = ex.solve("3.4", n_1=list(n1), f_1=list(f1), n_2=list(Q.T * n1), f_2=list(Q.T * f1))
    assert s.status == "solved" and s.answers["Q_1_2"] == Q
    return s


@pytest.fixture(scope="module")
def ex319():
    return ex.solve("3.19", d=["0.1", 0, 0], Q=[[0, -1, 0], [1, 0, 0], [0, 0, 1]],
                    n_S=[1, 2, 3], f_S=[0, 1, 4])


@pytest.fixture(scope="module")
def ex311():
    return ex.solve("3.11", a="0.05", h="0.01")


def test_transpose(ex34):
    Q = ex34.answers["Q_1_2"]
    g = _slip(ex34, "Q_1_2", _floats(Q.T))
    assert g.correct is False and g.slip == "transpose"


def test_sign_of_the_moment_transfer_and_reference_point(ex319):
    d, f, n, Q = (sp.Matrix(ex319.data[k]) for k in ("d", "f_S", "n_S", "Q"))
    right = Q.T * (n - d.cross(f))               # n_P = n_S - d x f (Sec. 3.7), into F_2
    assert ex319.answers["n_2"] == right
    assert _slip(ex319, "n_2", _floats(Q.T * (n + d.cross(f)))).slip == "sign"
    assert _slip(ex319, "n_2", _floats(Q.T * n)).slip == "reference point"   # about S
    f2 = _floats(Q.T * f)
    assert _slip(ex319, "f_2", [f2[0], f2[2], f2[1]]).slip == "swap"
    # entries 0 and 1 exchanged give f_S itself: a datum echoed names no slip
    assert _floats(f) == [f2[1], f2[0], f2[2]]
    assert _slip(ex319, "f_2", [f2[1], f2[0], f2[2]]).slip is None


def test_degrees_for_radians():
    s = ex.solve("3.1", A_prime=[0, 0, 0], B_prime=[-1, 0, 0], D_prime=[0, -1, 0],
                 E_prime=[0, 0, 1])                    # a half turn about z
    assert s.answers["phi"] == sp.pi
    g = _slip(s, "phi", 180)
    assert g.correct is False and g.slip == "degrees"
    assert _slip(s, "phi", "pi").correct is True


def test_unit_and_the_axis_through_the_base(ex311):
    a, h = sp.Rational(1, 20), sp.Rational(1, 100)
    I_kg = sp.diag(5 * a**2 / 24 + h**2 / 12, 5 * a**2 / 24 + h**2 / 12, 5 * a**2 / 12)
    assert ex311.answers["I_C_per_kg_m2"] == I_kg           # the closed forms, m^2
    mm2 = _floats(I_kg * 10**6)
    assert _slip(ex311, "I_C_per_kg_m2", mm2).slip == "unit"
    # the axes through the base's centre: Steiner with the centroid at h/2 above it
    base = I_kg + sp.diag((h / 2)**2, (h / 2)**2, 0)
    assert _slip(ex311, "I_C_per_kg_m2", _floats(base)).slip == "reference point"


def test_right_answers_pass_and_random_ones_are_not_a_known_slip(ex34, ex319, ex311):
    rng = np.random.default_rng(32)
    for s in (ex34, ex319, ex311):
        numeric = {k: v for k, v in s.answers.items() if isinstance(v, sp.MatrixBase)}
        right = {k: to_json_value(v) for k, v in s.answers.items() if not isinstance(v, str)}
        assert all(g.correct and g.slip is None for g in ex.grade(s, right))
        for k, v in numeric.items():
            g = _slip(s, k, (rng.uniform(-7, 7, size=v.shape) + 0.123).tolist())
            assert g.correct is False and g.slip is None and "not a known slip" in g.detail


def test_bad_answers():
    s = ex.solve("3.7")
    with pytest.raises(ValueError, match="has no answer 'x'"):
        ex.grade(s, {"x": 1})
    with pytest.raises(TypeError, match="answers: expected a dict"):
        ex.grade(s, [1])
    g = _named(ex.grade(s, {"e": ["a", 0, 0]}), "e")
    assert g.correct is False and g.detail.startswith("not read")


def test_cli_one_student_and_a_class(tmp_path, capsys):
    s = ex.solve("3.19")
    right = {k: [[str(x) for x in r] for r in v.tolist()] for k, v in s.answers.items()}
    wrong = dict(right, n_2=_floats(-s.answers["n_2"]))
    (tmp_path / "amy.json").write_text(json.dumps(right))
    (tmp_path / "bob.json").write_text(json.dumps(wrong))
    assert main(["exercise", "3.19", "--grade", str(tmp_path / "amy.json")]) == 0
    capsys.readouterr()
    assert main(["exercise", "3.19", "--grade", str(tmp_path / "bob.json"), "--json"]) == 1
    doc = json.loads(capsys.readouterr().out)
    by = {a["name"]: a for a in doc["answers"]}
    assert set(by["n_2"]) == {"name", "correct", "missing", "slip", "expected", "detail",
                             "note"}
    assert by["n_2"]["slip"] == "sign" and by["f_2"]["correct"] is True
    assert main(["exercise", "3.19", "--grade", str(tmp_path)]) == 1
    out = capsys.readouterr().out
    assert "2 students" in out and "n_2: sign" in out
    table = tmp_path / "class.csv"
    with table.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["student", "n_2"])
        w.writerow(["cy", json.dumps(_floats(s.answers["n_2"] * 1000))])
    assert main(["exercise", "3.19", "--grade", str(table), "--json"]) == 1
    doc = json.loads(capsys.readouterr().out)
    by = {a["name"]: a for a in doc["students"][0]["answers"]}
    assert by["n_2"]["slip"] == "unit" and by["f_2"]["missing"] is True
    assert main(["exercise", "3.19", "--grade", str(tmp_path / "none.json")]) == 2


def test_a_blank_is_missing_and_one_of_three_is_one_of_three(tmp_path, capsys):
    s = ex.solve("3.19")
    asked = [k for k, v in s.answers.items() if isinstance(v, sp.MatrixBase)]
    assert len(asked) == 3
    n2 = [[str(x) for x in r] for r in s.answers["n_2"].tolist()]
    graded = ex.grade(s, {"n_2": n2, "w_2": "  ", "f_2": []})
    assert [g.name for g in graded] == asked                 # every answer asked, graded
    assert [(g.correct, g.missing) for g in graded if g.name != "n_2"] == [(False, True)] * 2
    table = tmp_path / "class.csv"
    with table.open("w", newline="") as fh:
        csv.writer(fh).writerows([["student", "w_2", "n_2", "f_2"],
                                  ["dee", "", json.dumps(n2), ""]])
    assert main(["exercise", "3.19", "--grade", str(table)]) == 1
    out = capsys.readouterr().out
    assert " 1/3 " in out and "w_2: missing" in out and "f_2: missing" in out


def test_answers_are_read_as_set_reads_data(ex34):
    """A matrix answer typed as ``--set`` takes it (rows split by ';'), or as JSON rows."""
    Q = ex34.answers["Q_1_2"]
    typed = ";".join(",".join(str(x) for x in Q.row(i)) for i in range(3))
    assert _slip(ex34, "Q_1_2", typed).correct is True
    assert _slip(ex34, "Q_1_2", "[" + typed.replace(";", "],[") + "]").correct is True
    t_typed = ";".join(",".join(str(x) for x in Q.col(i)) for i in range(3))
    assert _slip(ex34, "Q_1_2", t_typed).slip == "transpose"
    s = ex.solve("3.19")
    f = s.answers["f_2"]
    assert _slip(s, "f_2", ",".join(str(x) for x in f)).correct is True


#: lengths by their definitions (not pint's table): an answer in any of them grades right
_METRES_PER = {"m": 1, "cm": sp.Rational(1, 100), "mm": sp.Rational(1, 1000),
               "um": sp.Rational(1, 10**6), "km": 1000, "in": sp.Rational(254, 10**4),
               "ft": sp.Rational(3048, 10**4)}


@given(unit=st.sampled_from(sorted(_METRES_PER)), per_entry=st.booleans())
@settings(max_examples=examples(12), deadline=None, derandomize=True, database=None)
def test_an_answer_in_any_compatible_unit_grades_right(ex311, unit, per_entry):
    a, h = sp.Rational(1, 20), sp.Rational(1, 100)
    centroid = [0, 0, h / 2]                     # metres: the prism's middle, on its axis
    volume = 3 * sp.sqrt(3) / 2 * a**2 * h       # the hexagon's area times h, m^3
    shown = [f"{float(x / _METRES_PER[unit]):.12g}" for x in centroid]
    given = [f"{x} {unit}" for x in shown] if per_entry else ",".join(shown) + f" {unit}"
    g = _slip(ex311, "centroid_m", given)
    assert g.correct is True and g.slip is None, g.detail
    v = _slip(ex311, "volume_m3", f"{float(volume / _METRES_PER[unit] ** 3):.12g} {unit}^3")
    assert v.correct is True, v.detail
    if unit != "m":
        assert f"read in {unit}" in g.detail


def test_a_bare_number_in_another_unit_is_named_a_unit_slip(ex311):
    h = sp.Rational(1, 100)
    g = _slip(ex311, "centroid_m", [0, 0, float(h / 2 * 1000)])     # mm typed as m
    assert g.correct is False and g.slip == "unit"
    assert "a unit slip: the number is in mm, the answer in m" in g.detail
    v = _slip(ex311, "volume_m3", float(3 * sp.sqrt(3) / 2 * (sp.Rational(1, 20))**2 * h
                                        * 10**6))                  # cm^3 typed as m^3
    assert v.slip == "unit" and "in cm^3" in v.detail
    s = ex.solve("3.1", A_prime=[0, 0, 0], B_prime=[-1, 0, 0], D_prime=[0, -1, 0],
                 E_prime=[0, 0, 1])                    # a half turn about z: phi = pi rad
    assert _slip(s, "phi", "180 deg").correct is True
    d = _slip(s, "phi", 180)
    assert d.slip == "degrees" and "a unit slip: deg given where rad is expected" in d.detail


def test_a_unit_that_does_not_fit_is_refused_by_name(ex311, ex34):
    g = _slip(ex311, "volume_m3", "0.0001 kg")
    assert g.correct is False and "'kg' is not a unit of m^3" in g.detail
    q = _slip(ex34, "Q_1_2", "1,0,0;0,1,0;0,0,1 mm")
    assert q.correct is False and "no single unit" in q.detail


# ---------------------------------------------------------------- what a grader must not miss
def test_rows_of_a_matrix_exchanged_are_a_swap(ex34):
    """Two rows of the rotation exchanged (a student's misplaced row) is named a swap of
    rows, not a wrong answer: no single-entry edit gives it."""
    Q = ex34.answers["Q_1_2"]
    P = Q.copy()
    P.row_swap(0, 2)
    g = _slip(ex34, "Q_1_2", _floats(P))
    assert g.correct is False and g.slip == "swap" and "rows 0 and 2" in g.detail


@pytest.mark.parametrize("factor", [10**-6, 10**-4, 10**-3, 10**-2, 10**2, 10**3, 10**4,
                                    10**6], ids=lambda f: f"{f:g}")
def test_a_prefix_either_way_is_a_unit_slip(ex311, factor):
    """The inertia per kg in m^2 written with mm^2 (10^6), cm^2 (10^4), and the conversion
    done the wrong way round (10^-6, 10^-4): each a unit slip; a length's factor (10^3,
    10^2, inverted) is no prefix of an area, and names no slip."""
    I_kg = ex311.answers["I_C_per_kg_m2"]
    got = _slip(ex311, "I_C_per_kg_m2", _floats(I_kg * sp.Rational(factor))).slip
    assert got == ("unit" if abs(math.log10(factor)) in (4, 6) else None)


def test_a_slip_along_the_way_is_named_only_by_the_replay(ex319):
    """n_2 computed with Q where the solution reads Q^T (a slip in a step, not an edit of
    the final answer): named, as made along the way, when the grader replays the solution;
    not a known slip without the replay; and among the values STACK's tree compares with."""
    d, f, n, Q = (sp.Matrix(ex319.data[k]) for k in ("d", "f_S", "n_S", "Q"))
    along = _floats(Q * (n - d.cross(f)))
    g = _named(ex.grade(ex319, {"n_2": along}), "n_2")
    assert g.correct is False and g.slip is not None and "along the way" in g.note
    from rigidsym.course.grading import grade, slip_values

    assert _named(grade(ex319, {"n_2": along}, replay=False), "n_2").slip is None

    key = np.array(_floats(ex319.answers["n_2"]), dtype=float)
    values = slip_values(ex319, "n_2", key.reshape(-1, 1) if key.ndim == 1 else key)
    assert any(np.allclose(np.ravel(v), np.ravel(along), rtol=1e-12) for _, v in values)


def test_significant_figures_of_a_rounded_answer():
    """An answer rounded to N significant figures (N = 1, 2, 3) reads as rounded to N, the
    fewest that reproduce it; the key itself or another value reads 0."""
    from rigidsym.course.grading import rounded_figures

    right = np.array([1.234567, -27.18281, 0.0031416])
    for n in (1, 2, 3):
        given = np.array([float(f"{x:.{n - 1}e}") for x in right])
        assert rounded_figures(given, right) == n, (n, given)
    assert rounded_figures(right * 1.01, right) == 0


@pytest.mark.parametrize(("text", "read"), [("1,5", "1.5"), ("-0,25", "-0.25"),
                                            ("1.234", "1.234"), ("1234567.5", "1234567.5")])
def test_a_decimal_comma_reads_as_a_point(text, read):
    from rigidsym.course.grading import read_decimal_comma

    assert read_decimal_comma(text, (), "phi") == read


@pytest.mark.parametrize("text", ["1,234", "-12,500"])
def test_one_comma_and_three_digits_is_left_to_the_instructor(text):
    """1,234 reads two ways (a decimal comma or a thousands separator): ambiguous, not
    refused as thousands separators and not read as either number."""
    from rigidsym.course.grading import AmbiguousNumber, read_decimal_comma

    with pytest.raises(AmbiguousNumber, match="left to the instructor"):
        read_decimal_comma(text, (), "phi")


@pytest.mark.parametrize("text", ["1,234,567", "12 345.6", "1,234.5"])
def test_thousands_separators_are_refused_by_name(text):
    from rigidsym.course.grading import AmbiguousNumber, read_decimal_comma

    with pytest.raises(ValueError, match="thousands separators") as info:
        read_decimal_comma(text, (), "phi")
    assert not isinstance(info.value, AmbiguousNumber)


@pytest.fixture(scope="module")
def ex310():
    """3.10's key as its solve gives it (the angles symbolic: W and det W are expressions),
    from the exercise's own rate matrix: the full solve decides the twelve sequences'
    symbolic checks first (seconds of CPU, the slow tests of test_exercise_answers.py and
    test_exercises.py), which grading does not read."""
    from rigidsym.course.worked import Solution, exercise_module

    W = exercise_module("ex3.10").euler_rate_matrix("ZXZ")     # the default sequence
    s = Solution("ex3.10", "t", "st", "cit")
    s.answers.update(W=W, det_W=sp.trigsimp(W.det()))
    assert s.answers["det_W"].free_symbols
    return s


def test_an_expression_answer_is_graded_at_generic_values(ex310):
    """The key's expressions, written as text by the student (a matrix as nested lists, or
    as 9 entries in a row): right; a truth or an answer of another size: wrong and said
    why, never an exception."""
    W, det = ex310.answers["W"], ex310.answers["det_W"]
    rows = [[str(x) for x in W.row(i)] for i in range(W.rows)]
    assert _named(ex.grade(ex310, {"det_W": str(det)}), "det_W").correct is True
    assert _named(ex.grade(ex310, {"W": rows}), "W").correct is True
    assert _named(ex.grade(ex310, {"W": [x for r in rows for x in r]}), "W").correct is True
    truth = _named(ex.grade(ex310, {"det_W": True}), "det_W")
    assert truth.correct is False and "truth" in truth.detail
    short = _named(ex.grade(ex310, {"W": rows[0]}), "W")
    assert short.correct is False
    columns = [list(c) for c in zip(*rows, strict=True)]
    assert _named(ex.grade(ex310, {"W": columns}), "W").slip == "transpose"


@pytest.mark.slow  # the full solve; quick: test_an_expression_answer_is_graded_at_generic_values
def test_the_solves_key_of_3_10_is_the_key_graded_above(ex310):
    """The key the quick test grades is the one 3.10's solve gives (W, det W)."""
    s = ex.solve("3.10")
    assert s.status == "solved"
    assert s.answers["W"] == ex310.answers["W"]
    assert sp.simplify(s.answers["det_W"] - ex310.answers["det_W"]) == 0
