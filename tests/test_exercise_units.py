"""Units on a student's data: a unit after the value converts every
entry exactly (pint); a bare number keeps the documented unit, and an implausible one is
read as given and warned of, naming the unit assumed."""

import pytest
import sympy as sp

import rigidsym.exercises as ex
from rigidsym.cli import main
from rigidsym.course.worked.units import factor, split_unit


@pytest.mark.parametrize(("text", "unit"), [
    ("0,0,100 mm", "mm"), ("30 deg", "deg"), ("1,0,1 N m", "N m"), ("5 kg m^2", "kg m^2"),
    ("sqrt(3)/2", None), ("2 pi", None), ("cos(30°)", None), ("150", None), ("1e-3", None),
    # as students type them: a unit right after the digits, never a number's own letters
    ("30deg", "deg"), ("0,0,100mm", "mm"), ("2pi", None), ("2e3", None), ("1E5", None)])
def test_split_unit(text, unit):
    assert split_unit(text)[1] == unit


@pytest.mark.parametrize(("unit", "documented", "exact"), [
    ("mm", "m", sp.Rational(1, 1000)), ("deg", "rad", sp.pi / 180), ("in", "m",
     sp.Rational(127, 5000)), ("N*m", "N m", 1), ("mN m", "N m", sp.Rational(1, 1000)),
    ("g cm^2", "kg m^2", sp.Rational(1, 10**7))])
def test_factors_are_exact(unit, documented, exact):
    assert factor(unit, documented, "x") == exact


def test_mm_and_metres_give_the_same_3_19_answer():
    a, b = ex.solve("ex3.19", d="0,0,100 mm"), ex.solve("ex3.19", d=[0, 0, "0.1"])
    assert a.answers == b.answers and a.status == "solved" and a.checked
    assert a.data["d"] == sp.Matrix([0, 0, sp.Rational(1, 10)])


def test_a_unit_of_another_quantity_names_both(capsys):
    with pytest.raises(ValueError, match=r"d: 'N' is not a unit of m"):
        ex.solve("ex3.19", d="0,0,100 N")
    assert main(["exercise", "3.19", "--set", "n_S=1,0,1 N m"]) == 0
    assert main(["exercise", "3.19", "--set", "n_S=1,0,1 N"]) == 2
    assert "n_S: 'N' is not a unit of N m" in capsys.readouterr().err


def test_bare_millimetres_warn_naming_the_unit(capsys):
    s = ex.solve("ex3.11", a=25, h=150)
    warned = [n for n in s.assumptions if n.startswith("Warning:")]
    assert len(warned) == 2 and "h was read in m" in warned[1] and "150 m" in warned[1]
    assert ex.solve("ex3.11", a="25 mm", h="150 mm").answers == ex.solve("ex3.11").answers
    assert main(["exercise", "3.11", "--set", "a=25", "--set", "h=150"]) == 0
    err = capsys.readouterr().err
    assert "rigidsym: warning: a was read in m" in err
    assert max(map(len, err.splitlines())) <= 100        # wrapped, as the solution's text
    assert not [n for n in ex.solve("ex3.11").assumptions if n.startswith("Warning:")]


def test_a_unit_right_after_the_digits_converts_as_with_a_space(capsys):
    """``100mm`` as students type it is ``100 mm`` (before: "'mm' is not a name the
    reader knows"); letters that are not a unit are still refused as bad data."""
    assert main(["exercise", "3.19", "--set", "d=0,0,100mm"]) == 0
    with_space = capsys.readouterr().out
    assert main(["exercise", "3.19", "--set", "d=0,0,100 mm"]) == 0
    assert capsys.readouterr().out == with_space and "1/10" in with_space
    assert main(["exercise", "3.19", "--set", "d=0,0,100zz"]) == 2
    assert "'zz' is not a name" in capsys.readouterr().err
