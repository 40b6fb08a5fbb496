"""Exercises on a student's data: constructed data with answers known before
solving, measured (float) data, ill-posed data answered with one sentence, bad input.

Each constructed case builds the data *from* the answer (a Cayley rotation, a chosen line,
a chosen wrench), so the expected values are the construction's, never the solver's.
"""

from __future__ import annotations

import decimal
import html
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

import rigidsym.exercises as ex
from rigidsym.course.worked import render_text
from rigidsym.course.worked.data import read_value

R = sp.Rational


def cayley(s) -> sp.Matrix:
    """A rational rotation: (1 + S)(1 - S)^-1, S = CPM(s); angle 2 atan||s|| about s."""
    S = sp.Matrix([[0, -s[2], s[1]], [s[2], 0, -s[0]], [-s[1], s[0], 0]])
    return (sp.eye(3) + S) * (sp.eye(3) - S).inv()


def _col(v) -> sp.Matrix:
    return sp.Matrix(v)


def _solved(s) -> None:
    assert s.status == "solved", s.reason
    failed = [f"{c.name}: {c.detail}" for c in s.checks if not c.passed]
    assert s.checks and not failed


# --------------------------------------------------------------------------- constructed
def test_ex3_4_constructed_rotation_is_the_answer():
    Qc = cayley([R(1, 2), R(-1, 3), R(1, 5)])
    assert Qc.T * Qc == sp.eye(3) and Qc.det() == 1
    n1, f1 = _col([0, 0, 5]), _col([0, 2, 0])
    s = ex.solve("ex3.4", n_1=n1, f_1=f1, n_2=Qc.T * n1, f_2=Qc.T * f1)
    _solved(s)
    assert s.answers["Q_1_2"] == Qc


def test_ex3_4_general_wrench_and_strings():
    Qc = cayley([2, 1, R(-1, 2)])
    n1, f1 = _col([1, -2, 3]), _col([R(1, 2), 4, -1])      # n.f != 0: the triad still works
    n2, f2 = Qc.T * n1, Qc.T * f1
    s = ex.solve("3.4", n_1=[str(x) for x in n1], f_1=tuple(f1), n_2=list(n2), f_2=f2)
    _solved(s)
    assert s.answers["Q_1_2"] == Qc


def test_ex3_1_constructed_screw():
    e = _col([1, 2, 2]) / 3                                 # unit axis
    Qc = cayley(list(e))                                    # ||s|| = 1: a quarter turn
    p0 = _col([2, -1, 0])                                   # on the axis, normal to e
    assert p0.dot(e) == 0
    c = (sp.eye(3) - Qc) * p0 + R(1, 2) * e                 # a screw along that axis
    A, B, D, E = _col([1, 1, 1]), _col([2, 1, 1]), _col([1, 2, 1]), _col([1, 1, 2])
    moved = {k + "_prime": Qc * v + c for k, v in zip("ABDE", (A, B, D, E), strict=True)}
    s = ex.solve("ex3.1", A=A, B=B, D=D, E=E, **moved)
    _solved(s)
    assert s.answers["Q"] == Qc
    assert s.answers["phi"] == sp.pi / 2
    assert s.answers["e"] == e
    assert s.answers["plucker"] == sp.Matrix.vstack(e, p0.cross(e))


def test_ex3_2_constructed_central_axis():
    # f_1 along x at z = -1, f_2 along y at z = +1: a half turn about (1, 1, 0) swaps them,
    # so the central axis is that line through O; the foot from P_4 = (0, -1, 1) is
    # (-1/2, -1/2, 0)
    P = {"P_1": [0, 1, 1], "P_2": [-1, 0, -1], "P_3": [1, 0, -1], "P_4": [0, -1, 1]}
    s = ex.solve("ex3.2", **P)
    _solved(s)
    assert s.answers["P"] == _col([R(-1, 2), R(-1, 2), 0])
    assert s.answers["f"] == _col([1, 1, 0])


def test_ex3_5_constructed_line_unnormalised():
    q, e = _col([3, 4, 7]), _col([0, 0, 2])                 # through q, along z (not unit)
    s = ex.solve("ex3.5", plucker=list(e) + list(q.cross(e)))
    _solved(s)
    assert s.answers["p_star"] == _col([3, 4, 0])
    assert s.answers["d"] == 5


def test_ex3_7_constructed_axis():
    e, ps = _col([2, 3, 6]) / 7, _col([3, 0, -1])           # unit e, p* normal to e
    assert ps.dot(e) == 0
    a, b = _col([1, 1, 1]), _col([-2, 0, 5])
    s = ex.solve("ex3.7", a=a, b=b, n_A=(ps - a).cross(e), n_B=(ps - b).cross(e))
    _solved(s)
    assert s.answers["e"] == e
    assert s.answers["p_star"] == ps


def test_ex3_11_prism_of_other_size():
    a, h = R(1, 10), R(1, 5)
    s = ex.solve("ex3.11", a=a, h="1/5")
    _solved(s)
    V = 3 * sp.sqrt(3) / 2 * a**2 * h                       # hexagon area times height
    assert sp.simplify(s.answers["volume_m3"] - V) == 0
    assert s.answers["centroid_m"] == _col([0, 0, h / 2])
    # textbook: I_zz/m = 5 a^2/12 (regular hexagon), I_xx/m = 5 a^2/24 + h^2/12
    mom = s.answers["principal_moments_per_kg_m2"]
    assert list(mom) == [5 * a**2 / 24 + h**2 / 12, 5 * a**2 / 24 + h**2 / 12, 5 * a**2 / 12]


def test_ex3_14_constructed_observers():
    IA = sp.diag(2, 3, 4)
    Qc = cayley([1, R(1, 2), R(1, 3)])
    s = ex.solve("ex3.14", I_A=IA, I_B=Qc * IA * Qc.T)
    _solved(s)
    assert list(s.answers["principal_moments"]) == [2, 3, 4]
    Q = s.answers["Q_B_A"]
    # eigenvectors are fixed up to sign: Q = Qc D with D = diag(+-1) and det D = 1
    D = Qc.T * Q
    assert D.is_diagonal() and all(abs(x) == 1 for x in D.diagonal()) and D.det() == 1


def test_ex3_19_constructed_wrench_in_F2():
    n2, f2 = _col([1, -1, 2]), _col([3, 0, -2])             # the answer, chosen first
    Qc, d = cayley([0, 0, 1]), _col([0, R(1, 10), R(1, 20)])  # F_2 turned 90 deg about z
    f_S = Qc * f2
    n_S = Qc * n2 + d.cross(f_S)                            # what the sensor reads at S
    s = ex.solve("ex3.19", n_S=n_S, f_S=f_S, d=d, Q=Qc)
    _solved(s)
    assert s.answers["n_2"] == n2 and s.answers["f_2"] == f2


# --------------------------------------------------------------------------- measured
def test_ex3_4_noisy_floats_give_a_least_squares_rotation():
    Qc = cayley([R(1, 2), R(-1, 3), R(1, 5)])
    n1, f1 = np.array([0.0, 0.0, 5.0]), np.array([0.0, 2.0, 0.0])
    Qf = np.array(Qc.tolist(), dtype=float)
    rng = np.random.default_rng(22)
    n2 = Qf.T @ n1 + rng.normal(0, 1e-4, 3)
    f2 = Qf.T @ f1 + rng.normal(0, 1e-4, 3)
    s = ex.solve("ex3.4", n_1=n1, f_1=f1, n_2=n2, f_2=f2)
    _solved(s)
    Q = s.answers["Q_1_2"]
    assert Q.T * Q == sp.eye(3) and Q.det() == 1            # exactly a rotation
    assert float((Q - Qc).norm()) < 1e-3
    assert 0 < float(s.answers["residual"]) < 1e-3
    assert any("Floats are measurements" in a for a in s.assumptions)
    assert any("tol =" in a and "default" in a for a in s.assumptions)


def test_ex3_4_floats_beyond_tol_are_not_compatible():
    s = ex.solve("ex3.4", n_2=[-5 / 3, -10 / 3, 10 / 3 + 0.1], f_2=[-4 / 3, 4 / 3, 2 / 3])
    assert s.status == "ill-posed" and "not compatible within tol" in s.reason
    # a wider tolerance accepts the same readings
    assert ex.solve("ex3.4", n_2=[-5 / 3, -10 / 3, 10 / 3 + 0.1], f_2=[-4 / 3, 4 / 3, 2 / 3],
                    tol=0.2).status == "solved"


def test_ex3_14_and_ex3_19_measured():
    IB = np.array(sp.Matrix([[6, 2, 2], [2, 5, 0], [2, 0, 7]]).tolist(), dtype=float) / 3
    _solved(ex.solve("ex3.14", I_B=IB))
    Qn = np.array(cayley([0, 0, 1]).tolist(), dtype=float) + 1e-5
    s = ex.solve("ex3.19", Q=Qn)
    _solved(s)
    assert "nearest rotation" in [st.name for st in s.steps]
    assert ex.solve("ex3.19", Q=Qn + 0.1).status == "ill-posed"


# --------------------------------------------------------------------------- ill-posed
ILL_POSED = [
    ("ex3.1", dict(A_prime=[1, 0, 0], B_prime=[2, 0, 0], D_prime=[1, 1, 0],
                   E_prime=[1, 0, 1]), "pure translation"),
    ("ex3.1", dict(B_prime=[0, 4, 0]), "not a rigid motion"),
    ("ex3.1", dict(D=[2, 0, 0]), "linearly dependent"),
    ("ex3.2", dict(P_1=[0, 0, 0], P_2=[1, 0, 0], P_3=[1, 1, 0], P_4=[0, 1, 0]), "couple"),
    ("ex3.4", dict(f_2=[1, 1, 1]), "not compatible"),
    ("ex3.4", dict(n_1=[0, 4, 0], n_2=[0, 0, 2], f_2=[0, 0, 1]), "parallel"),
    ("ex3.5", dict(plucker=[1, 0, 0, 1, 0, 0]), "not the Plücker coordinates"),
    ("ex3.5", dict(plucker=[0, 0, 0, 1, 0, 0]), "zero"),
    ("ex3.6", dict(CC_prime=[1, 1, 1]), "normal to the faces"),
    ("ex3.7", dict(n_B=[0, 1, 2]), "not those of one line"),
    ("ex3.7", dict(n_B=[0, 4, 0]), "normal to b - a"),
    ("ex3.7", dict(a=[1, 0, 0], b=[2, 0, 0], n_A=[0, 1, 0], n_B=[0, 3, 0]),
     "|n_A - n_B| > |b - a|"),
    ("ex3.7", dict(a=[1, 0, 0], b=[1, 0, 0], n_A=[0, 1, 0], n_B=[0, 1, 0]),
     "infinitely many"),
    ("ex3.11", dict(h=0), "positive"),
    ("ex3.14", dict(I_B=[[1, 0, 0], [0, 2, 0], [0, 0, 4]]), "not acceptable"),
    ("ex3.14", dict(I_A=[[1, 1, 0], [0, 2, 0], [0, 0, 3]]), "not symmetric"),
    ("ex3.14", dict(I_A=sp.diag(1, 1, 3), I_B=sp.diag(1, 1, 3)), "triangle inequality"),
    ("ex3.19", dict(Q=[[1, 1, 0], [0, 1, 0], [0, 0, 1]]), "not a rotation"),
    ("ex3.19", dict(Q=[[-1, 0, 0], [0, 1, 0], [0, 0, 1]]), "reflection"),
]


@pytest.mark.parametrize(("ex_id", "data", "words"), ILL_POSED)
def test_ill_posed_data_give_one_sentence(ex_id, data, words):
    s = ex.solve(ex_id, **data)
    assert s.status == "ill-posed" and not s.checked and not s.answers
    assert words in s.reason
    assert s.reason.endswith(".") and "\n" not in s.reason and s.reason.count(". ") == 0
    assert s.given and s.statement                          # the solution up to the failure
    assert ex.figure(s) is None
    assert html.escape(s.reason, quote=False) in s._repr_html_()
    assert f"Ill-posed: {s.reason}" in " ".join(render_text(s).split())   # wrapped at 100


# --------------------------------------------------------------------------- bad input
@pytest.mark.parametrize(("ex_id", "data", "error", "words"), [
    ("ex3.4", dict(n_3=[1, 2, 3]), TypeError, "no parameter 'n_3'"),
    ("ex3.4", dict(n_1=[1, 2]), ValueError, "n_1: expected a 3-vector"),
    ("ex3.4", dict(n_1="1,2"), ValueError, "n_1: expected a 3-vector"),  # the CLI reader
    ("ex3.4", dict(n_1=[1, 2, "y"]), ValueError, "n_1[2]"),
    ("ex3.4", dict(n_1=[1, 2, float("nan")]), ValueError, "n_1[2]: expected a finite"),
    ("ex3.4", dict(n_1=[1, 2, True]), TypeError, "n_1[2]: expected a real number, got a bool"),
    ("ex3.4", dict(n_1=[1, 2, "I"]), ValueError, "n_1[2]"),
    ("ex3.4", dict(n_1=[1, 2, {}]), TypeError, "n_1[2]"),
    ("ex3.4", dict(tol=0), ValueError, "tol: expected a positive"),
    ("ex3.1", dict(A=[[1, 2, 3]]), ValueError, "A: expected a 3-vector"),
    ("ex3.2", dict(tol=0.1), TypeError, "tol: the data of ex3.2 are not measurements"),
    ("ex3.2", dict(P_1=sp.Matrix([1, 2])), ValueError, "P_1"),
    ("ex3.5", dict(plucker=[1, 0, 0]), ValueError, "plucker: expected a 6-array"),
    ("ex3.7", dict(a=None), TypeError, "a: expected a 3-vector"),
    ("ex3.8", dict(omega=[1, 2, 3]), TypeError, "none (no numeric data)"),
    ("ex3.10", dict(sequence="ZZZ"), ValueError, "sequence: expected one of ZXZ"),
    ("ex3.11", dict(a=[1]), TypeError, "a: expected a real number"),
    ("ex3.11", dict(a="oo"), ValueError, "a: 'oo' is not a finite real number"),
    ("ex3.14", dict(I_A=[[1, 0], [0, 1]]), ValueError, "I_A: expected a 3 x 3 matrix"),
    ("ex3.19", dict(Q=np.eye(2)), ValueError, "Q: expected a 3 x 3 matrix"),
    ("ex3.99", {}, ValueError, "3.1 ... 3.21"),
])
def test_bad_input_names_the_parameter(ex_id, data, error, words):
    with pytest.raises(error) as info:
        ex.solve(ex_id, **data)
    assert words in str(info.value)


def test_exact_readers():
    p = ex.parameters("ex3.11")["a"]
    assert read_value(p, "0.1") == (R(1, 10), False)
    assert read_value(p, "1e-3") == (R(1, 1000), False)
    assert read_value(p, Fraction(1, 3)) == (R(1, 3), False)
    assert read_value(p, decimal.Decimal("0.25")) == (R(1, 4), False)
    assert read_value(p, "sqrt(3)/2") == (sp.sqrt(3) / 2, False)
    assert read_value(p, np.int64(7)) == (7, False)
    value, was_float = read_value(p, 0.1)
    assert was_float and value == R(3602879701896397, 36028797018963968) == sp.Rational(0.1)
    assert read_value(ex.parameters("ex3.4")["n_1"], np.array([0.5, 1, 2])) == (
        sp.ImmutableMatrix([R(1, 2), 1, 2]), True)


def test_cache_is_keyed_on_the_data():
    book = ex.solve("ex3.7")
    assert ex.solve("3.7") is book
    assert ex.solve("ex3.7", a=[1, 0, 0]) is book           # the book's value, given again
    other = ex.solve("ex3.7", a=[0, 0, 0], n_A=[0, 2, 0])
    assert other is not book and other.given["a"] == sp.zeros(3, 1)


NO_DATA = ("ex3.3", "ex3.8", "ex3.9", "ex3.13", "ex3.15", "ex3.16", "ex3.17", "ex3.18",
           "ex3.20", "ex3.21")


@pytest.mark.parametrize("ex_id", ex.EXERCISE_IDS)
def test_parameters_table(ex_id):
    params = ex.parameters(ex_id)
    assert params.note
    if ex_id in NO_DATA:
        assert len(params) == 0 and "no numeric data" in params.note and not params.names
        return
    assert len(params) > 0
    for p in params:
        assert p.name.isidentifier() and p.meaning
        if p.shape is not None:      # the book's value reads back as itself
            assert read_value(p, p.default)[0] == p.default
    assert params.measured == (ex_id in ("ex3.1", "ex3.4", "ex3.5", "ex3.6", "ex3.7", "ex3.14",
                                         "ex3.19"))
    assert "<table>" in params._repr_html_() and params.names[0] in str(params)
