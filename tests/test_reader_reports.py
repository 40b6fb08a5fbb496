"""What `show` says of a record: one bound per record, and nothing of a corrected form
that does not exist."""

from __future__ import annotations

import pytest
import sympy as sp

from rigidsym import Rel, Statement, acos, angle, equation, mat, trace, unit_vector
from rigidsym import rotation_from_natural_invariants as rodrigues
from rigidsym.checking.checker import check
from rigidsym.registry.declarations import REGISTRY, load_all
from rigidsym.report.record import RESIDUAL_FLOOR, result_record
from rigidsym.report.show import explain


@pytest.fixture(autouse=True)
def _forget():
    yield
    for k in [k for k in REGISTRY if k.startswith("rr:")]:
        del REGISTRY[k]


def _show(r) -> str:
    st = REGISTRY[r.id].build()
    return explain(r, {"printed": st.printed, "claim": st.claims,
                       "corrected": st.corrected or []}, "test", 100, full=True)


def test_show_prints_the_records_bound_the_report_prints():
    # (3.59): show printed r ≤ 3.7e-51 where the HTML printed the record's floor 1e-40
    load_all()
    r = check("3.59", repairs=False)
    assert r.numeric["enclosure"] < RESIDUAL_FLOOR
    assert result_record(r, timings=False)["numeric"]["enclosure"] == RESIDUAL_FLOOR
    text = " ".join(_show(r).split())
    assert "r ≤ 1e-40" in text and "e-51" not in text


def test_show_says_nothing_of_a_corrected_form_that_does_not_exist():
    w, th, R = unit_vector("rr_w"), angle("rr_th"), mat("R")
    equation("rr:acos", "θ = acos((tr R − 1)/2) on (−π, π)", expected="does-not-hold")(
        lambda: Statement([Rel(th, acos((trace(R) - 1) / 2))], {R: rodrigues(w, th)}))
    r = check("rr:acos", repair_budget=5)
    assert r.verdict == "does-not-hold" and not r.repairs
    text = " ".join(_show(r).split())
    assert "corrected form's residual" not in text
    assert "0 ∉" in text and "certified" in text and "not certified" not in text
    assert sp.sympify(r.counterexample["residual"]) != 0


def test_how_the_point_was_chosen_names_the_readers_symbol():
    # the issue: a reader's R (= rigid_motion().Q) was explained as "Q is written through a
    # rational quaternion ... q0̇ of Q", the group's internal name, not the reader's
    from rigidsym import rigid_motion
    R, Rd, W = mat("R"), mat("R_dot"), mat("Omega")

    def slip():
        m = rigid_motion()
        return Statement([Rel(Rd, R * W)], {R: m.Q, Rd: m.Q_dot, W: m.Omega})

    equation("rr:rate", "Ṙ = R Ω (a slip)", expected="does-not-hold")(slip)
    r = check("rr:rate", repairs=False)
    assert r.verdict == "does-not-hold"
    chosen = r.counterexample["chosen"]
    assert chosen["text"].startswith("R is written through a rational quaternion")
    names = [p["name"] for p in chosen["params"]]
    assert names and all(n.endswith(" of R") for n in names), names
    assert "q̇₀ of R" in names  # the accent on the letter, the index a subscript
    text = _show(r)
    assert "in the equation's own symbols" in text
    assert " of Q" not in text and "Q is written" not in text


def test_a_split_angle_is_shown_as_the_readers_angle_with_its_own_value():
    # the issue: acos splits θ into θ = ±b; the counterexample showed "θ_neg = 2*atan(2/3)"
    # and "left side θ = 2/3" (the zero test's independent variable, not θ)
    w, th, R = unit_vector("omega"), angle("theta"), mat("R")
    equation("rr:acos2", "θ = acos((tr R − 1)/2) on (−π, π)", expected="does-not-hold")(
        lambda: Statement([Rel(th, acos((trace(R) - 1) / 2))], {R: rodrigues(w, th)}))
    r = check("rr:acos2", repairs=False)
    ce = r.counterexample
    (theta,) = [s for s in ce["symbols"] if s["symbol"] == "θ"]
    value = sp.sympify(theta["exact"])
    t = sp.Rational(next(p["exact"] for p in ce["chosen"]["params"]
                         if p["name"].startswith("t = tan(")))
    sign = -1 if "tan(−" in ce["chosen"]["text"] else 1
    assert sp.simplify(value - sign * 2 * sp.atan(t)) == 0
    assert sp.nsimplify(sp.cos(value)) == sp.Rational(theta["cos"])
    # the sides are θ's own value and acos of the trace there: the residual is theirs
    lhs, rhs = sp.sympify(ce["lhs"]), sp.sympify(ce["rhs"])
    assert sp.simplify(lhs - value) == 0
    assert abs(float(rhs) - abs(float(value))) < 1e-12  # acos(cos θ) = |θ|
    assert abs(float(sp.sympify(ce["residual"])) - (float(value) - abs(float(value)))) < 1e-12
    text = _show(r)
    assert "neg" not in text and "θ = " + theta["text"] in text


def test_show_prints_a_path_a_reader_can_use(tmp_path):
    import os

    import rigidsym
    from rigidsym.cli.show import reader_path
    here = tmp_path / "notes" / "rot.py"
    assert reader_path(str(here), str(tmp_path)) == os.path.join("notes", "rot.py")
    outside = tmp_path.parent / "elsewhere.py"
    assert reader_path(str(outside), str(tmp_path)) == str(outside)  # never ../
    pkg_file = os.path.join(os.path.dirname(rigidsym.__file__), "api.py")
    assert reader_path(pkg_file, str(tmp_path)) == os.path.join("rigidsym", "api.py")
