"""Measured data: decimals in a measured exercise are readings, judged
within a tolerance derived from the digits given (stated); a refusal names the tolerance
that would accept the data, and that tolerance does accept them."""

import re

import pytest
import sympy as sp

import rigidsym.exercises as ex

READ_3 = dict(n_2="-1.667,-3.333,3.333", f_2="-1.333,1.333,0.667")


def test_readings_to_three_decimals_are_compatible_within_their_digits():
    s = ex.solve("ex3.4", **READ_3)
    assert s.status == "solved" and s.checked
    assert s.tol == sp.Rational(3, 1000)
    assert any("3 units in the last decimal place given (1/1000" in a for a in s.assumptions)
    Q = s.answers["Q_1_2"]
    assert Q.T * Q == sp.eye(3)


def test_fractions_stay_exact():
    s = ex.solve("ex3.4", n_2="-5/3,-10/3,10/3", f_2="-4/3,4/3,2/3")
    assert s.tol is None and s.status == "solved"


def test_decimals_of_an_exact_length_stay_exact():
    assert ex.solve("ex3.19", d=["0.1", 0, 0]).tol is None        # d is not a reading
    assert ex.solve("ex3.19", Q="1,0.001,0;0,1,0;0,0,1").tol == sp.Rational(3, 1000)


@pytest.mark.parametrize(("ex_id", "data"), [
    ("ex3.4", dict(f_2=[1, 1, 1])),                                # exact, incompatible
    ("ex3.4", dict(READ_3, f_2="-1.333,1.333,0.767")),             # beyond its digits
    ("ex3.14", dict(I_B="1,0,0;0,2,0;0,0,4")),
    ("ex3.19", dict(Q="1,0.1,0;0,1,0;0,0,1", tol="0.01")),
    ("ex3.1", dict(B_prime="0,3.9,0")),                           # an edge 0.9 m long
])
def test_a_refusal_names_a_tolerance_that_accepts(ex_id, data):
    s = ex.solve(ex_id, **data)
    assert s.status == "ill-posed"
    m = re.search(r"tol = ([0-9.e-]+) would accept them \(--tol \1\)", s.reason)
    assert m, s.reason
    more = dict(data, tol=m.group(1))
    assert ex.solve(ex_id, **more).status == "solved"
