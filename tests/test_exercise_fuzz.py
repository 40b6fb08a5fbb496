"""Data never crash: every data string for every exercise with data is
solved (exit 0), answered as ill-posed (exit 1) or refused as bad input naming the
parameter (exit 2); never a traceback, never exit 3 (a defect).

The strings drawn are what a class types: exact, decimal, transcendental (``pi``,
``cos(30)``), degrees (``cos(30°)``), huge, tiny, nan, inf and garbage. The default run
draws a few per exercise (derandomised, seconds); ``-m slow`` draws many.
"""

from __future__ import annotations

import contextlib
import io

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rigidsym.exercises as ex
from rigidsym.cli import main

WITH_DATA = [i for i in ex.EXERCISE_IDS if len(ex.parameters(i))]

EXACT = st.one_of(st.integers(-20, 20).map(str),
                  st.tuples(st.integers(-9, 9), st.integers(1, 9)).map(lambda t: f"{t[0]}/{t[1]}"),
                  st.sampled_from(["sqrt(2)", "sqrt(3)/2", "-1/sqrt(2)", "cos(pi/5)", "3/5",
                                   "4/5", "0"]))
DECIMAL = st.one_of(st.decimals(-100, 100, places=3, allow_nan=False).map(str),
                    st.sampled_from(["0.1", "-3.5e-2", "1.5E1", ".5"]))
TRANSCENDENTAL = st.sampled_from(["pi", "E", "cos(30)", "sin(1)", "log(2)", "exp(1)",
                                  "pi/4", "atan(2)", "sqrt(pi)", "cos(1)**2"])
DEGREES = st.sampled_from(["cos(30°)", "30°", "sin(45°)", "cos(45°)", "tan(60°)", "90°"])
HUGE = st.sampled_from(["1e400", "10**20", "2**1000", "1e15", "123456789012345678901234567890",
                        "10**10**10", "exp(exp(exp(10)))", "9" * 60])
TINY = st.sampled_from(["1e-300", "1e-16", "1e-15", "2**-60", "1/10**40"])
NONFINITE = st.sampled_from(["nan", "inf", "-inf", "oo", "NaN", "1/0", "zoo"])
GARBAGE = st.sampled_from(["x", "", "1,2", "sqrt(-1)", "I", "[1", "__import__('os')",
                           "acos(2)", "1e", "Matrix([1])", "(-8)**(1/3)", "  ", "°"])
SCALAR = st.one_of(EXACT, EXACT, DECIMAL, TRANSCENDENTAL, DEGREES, HUGE, TINY, NONFINITE,
                   GARBAGE)


def _text(draw, p) -> str:
    """A ``--set`` value for parameter ``p`` (sometimes of the wrong shape)."""
    if p.shape is None:
        return draw(st.one_of(st.sampled_from(p.choices), st.sampled_from(["zzz", "", "XY"])))
    n = 1
    for k in p.shape:
        n *= k
    if draw(st.integers(0, 9)) == 0:
        n += draw(st.sampled_from([-1, 1]))            # a wrong number of entries
    entries = [draw(SCALAR) for _ in range(max(n, 1))]
    if len(p.shape) == 2 and n == 9:
        return ";".join(",".join(entries[3 * r:3 * r + 3]) for r in range(3))
    return ",".join(entries)


@st.composite
def exercise_data(draw, ex_id: str):
    params = list(ex.parameters(ex_id))
    chosen = draw(st.lists(st.sampled_from(params), min_size=1, max_size=2,
                           unique_by=lambda p: p.name))
    return [f"{p.name}={_text(draw, p)}" for p in chosen]


def _run(ex_id: str, sets: list[str]) -> tuple[int, str, str]:
    argv = ["exercise", ex_id[2:]]
    for s in sets:
        argv += ["--set", s]
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(argv)
    return rc, out.getvalue(), err.getvalue()


def _check(ex_id: str, sets: list[str]) -> None:
    rc, out, err = _run(ex_id, sets)
    assert "Traceback" not in out + err
    assert rc != 3, f"internal error on {sets}: {err}"
    assert rc in (0, 1, 2, 4), (rc, sets, err)          # 4: not solved for these data
    if rc == 2:
        lines = [ln for ln in err.splitlines() if ln.startswith("rigidsym: error:")]
        assert len(lines) == 1, err
        names = [s.partition("=")[0] for s in sets]
        # names the parameter, or refuses data whose exact solve ran past the budget or
        # past the integers sympy's exact arithmetic takes (a float's range)
        assert (any(n in lines[0] for n in names) or "did not finish in" in lines[0]
                or "too large for sympy's exact arithmetic" in lines[0]), lines[0]
    else:
        assert f"Exercise {ex_id[2:]}" in out
        assert ("Ill-posed:" in out) == (rc == 1)
        assert ("Not solved for these data:" in out) == (rc == 4)


def _property(max_examples: int):
    def decorate(fn):
        return settings(max_examples=max_examples, deadline=None, derandomize=True,
                        database=None,
                        suppress_health_check=[HealthCheck.too_slow,
                                               HealthCheck.data_too_large])(fn)
    return decorate


@pytest.fixture
def short_budget(monkeypatch):
    """An exact solve is refused after 3 CPU s (the default is 20), so that the many drawn
    data are each answered or refused in a few seconds (a refusal is an accepted answer)."""
    import rigidsym.course.worked as worked
    monkeypatch.setattr(worked, "SOLVE_BUDGET", 3.0)


@pytest.mark.sample
@pytest.mark.parametrize("ex_id", WITH_DATA)
def test_data_strings_never_crash(ex_id, short_budget):
    # the slow exact exercises (3.10, 3.12 solve in seconds) get fewer draws
    n = 1 if ex_id in ("ex3.2", "ex3.6", "ex3.10", "ex3.11", "ex3.12") else 10

    @_property(n)
    @given(exercise_data(ex_id))
    def prop(sets):
        _check(ex_id, sets)
    prop()


@pytest.mark.slow
@pytest.mark.parametrize("ex_id", [
    # in every run: 3.6, where this property found sympy factoring integers past a float's
    # range (test_integers_past_sympys_reach_are_refused_not_a_defect)
    pytest.param(i, marks=[] if i == "ex3.6" else [pytest.mark.thorough(0.33)])
    for i in WITH_DATA])
def test_data_strings_never_crash_exhaustive(ex_id, short_budget):
    # the thorough run: a seeded third of the other exercises (each commit another third; all
    # in the exhaustive profile); every exercise gets its draws of test_data_strings_never_crash
    # in every run (its sample in the quick run, its slow rest in the thorough one);
    # the short budget here too; derandomized, as the default run: CI draws the same 30
    # data sets every time (a new seed is a new search, for a person, not a coin CI flips);
    # 30: three times the quick run's 10, the thorough profile's factor (tests/_profile.py)
    @_property(30)
    @given(exercise_data(ex_id))
    def prop(sets):
        _check(ex_id, sets)
    prop()


@pytest.mark.parametrize(("ex_id", "sets", "rc", "words"), [
    ("3.19", ["Q=cos(30),-sin(30),0;sin(30),cos(30),0;0,0,1"], 0,
     "write cos(pi/6)"),
    ("3.19", ["Q=cos(30°),-sin(30°),0;sin(30°),cos(30°),0;0,0,1"], 0, "status: solved"),
    ("3.4", ["n_1=pi,0,5"], 1, "certified 30-digit value 3.14159265358979323846264338328"),
    ("3.11", ["a=1e400"], 2, "a: '1e400' is outside the magnitudes"),
    ("3.11", ["a=1e-300"], 2, "a: '1e-300' is outside the magnitudes"),
    ("3.11", ["a=10**10**10"], 2, "raises to a power above 100"),
    ("3.4", ["n_1=nan,0,0"], 2, "n_1[0]: 'nan' is not a finite real number"),
])
def test_hostile_exercise_data_is_answered_or_refused_by_name(ex_id, sets, rc, words):
    got, out, err = _run("ex" + ex_id, sets)
    assert got == rc and words in out + err
    assert ("cos(30): 30 rad" in out) == ("cos(30)" in sets[0])      # the radians hint
    assert ("certified" in out) == ("cos(30)" in sets[0] or "pi," in sets[0])


def test_integers_past_sympys_reach_are_refused_not_a_defect(monkeypatch):
    """Found by the exhaustive property: transcendental entries of 3.6's face normal made
    sympy factor integers past a float's range (OverflowError): refused (2), not exit 3.
    3.6's directions are now measurements (rounded to 30 certified digits, the grasp frame
    fitted in floating point): solved; the overflow is planted to keep the refusal tested."""
    got, out, err = _run("ex3.6", ["face_normal=pi,pi,cos(30°)"])
    assert got == 0 and "certified" in out and "residual" in out, err
    from rigidsym.course.worked import exercise_module

    def overflowing(**kw):
        raise OverflowError("int too large to convert to float")
    monkeypatch.setattr(exercise_module("ex3.7"), "solve", overflowing)
    got, out, err = _run("ex3.7", ["a=7,0,0", "b=0,7,7"])    # not cached
    assert got == 2 and "integers too large" in err, (got, err)


def test_a_defect_exits_3_not_an_answer_code(monkeypatch):
    import rigidsym.course.worked as worked

    def broken(*a, **k):
        raise ZeroDivisionError("a planted defect")
    monkeypatch.setattr(worked, "solve", broken)
    rc, out, err = _run("ex3.7", [])
    assert rc == 3 and "internal error, please report" in err and "ZeroDivisionError" in err


def test_string_data_read_the_same_through_solve_and_the_cli():
    text = "cos(pi/6),-sin(pi/6),0;sin(pi/6),cos(pi/6),0;0,0,1"
    s = ex.solve("3.19", Q=text)
    assert s.status == "solved" and s.checked and s.tol is None      # exact: algebraic
    rc, out, _ = _run("ex3.19", [f"Q={text}"])
    assert rc == 0 and str(s.answers["f_2"][0]) in out
