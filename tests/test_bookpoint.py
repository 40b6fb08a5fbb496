"""Counterexamples in the statement's own symbols.

The values shown for the book's symbols are checked against what they must satisfy: the
constraints (``e·e = 1``, ``cos² + sin² = 1``, ``φ = 2 atan(t)``), the model's own
relations (``E = CPM(e)``, ``‖ω‖² = ω·ω``) and, above all, the failing member: put into
its right side, the shown values must give the right side the record states there.
"""

from __future__ import annotations

import unicodedata
from pathlib import Path

import mpmath
import pytest
import sympy as sp

from rigidsym.algebra.primitives import cpm
from rigidsym.checking.checker import check
from rigidsym.checking.deciding.explicit import explicit
from rigidsym.printing import notation
from rigidsym.registry.declarations import REGISTRY, load_all
from rigidsym.registry.usermodules import load as load_module
from rigidsym.report.record import counterexample_record, result_record

pytestmark = pytest.mark.xdist_group("bookpoint")  # its module fixtures built on one worker

ROOT = Path(__file__).resolve().parents[1]
load_all()


def _nfc(text: str) -> str:
    return unicodedata.normalize("NFC", text)


def _values(ce: dict) -> dict[str, sp.Basic]:
    """Shown value by book name (NFC: ``ȧ`` is ``a`` and a combining dot in the output)."""
    return {_nfc(s["symbol"]): sp.sympify(s["exact"]) for s in ce["symbols"]}


def _close(a, b, digits=40) -> bool:
    a, b = sp.Matrix(a) if hasattr(a, "shape") else sp.Matrix([a]), \
        sp.Matrix(b) if hasattr(b, "shape") else sp.Matrix([b])
    return a.shape == b.shape and all(abs(sp.N(x - y, digits + 10)) < 10**-digits
                                      for x, y in zip(a, b, strict=True))


def _side_from_symbols(rel_side, ce: dict):
    """The side evaluated from the shown values of its book symbols (by their book names)."""
    vals = _values(ce)
    syms = rel_side.free_symbols
    model = {s: (sp.ImmutableMatrix(vals[_nfc(notation.text(s))])
                 if isinstance(s, sp.MatrixSymbol) else vals[_nfc(notation.text(s))])
             for s in syms}
    return explicit(rel_side, model)


@pytest.fixture(scope="module")
def r396e():
    return check("3.96e")


def test_396e_symbols_and_their_constraints(r396e):
    ce = counterexample_record(r396e.counterexample)
    names = [s["symbol"] for s in ce["symbols"]]
    assert {"e", "φ", "ω", "E", "Ω"} <= set(names)
    v = _values(ce)
    e, w = sp.Matrix(v["e"]), sp.Matrix(v["ω"])
    assert (e.T * e)[0] == 1                      # exactly a unit vector
    assert sp.Matrix(v["E"]) == cpm(e)            # the model's E = CPM(e), exactly
    assert sp.Matrix(v["Ω"]) == cpm(w)
    phi = next(s for s in ce["symbols"] if s["symbol"] == "φ")
    c, s_ = sp.Rational(phi["cos"]), sp.Rational(phi["sin"])
    assert c**2 + s_**2 == 1
    t = next(p for p in ce["chosen"]["params"] if p["name"].startswith("t = tan(φ/"))
    assert _close(sp.cos(sp.sympify(phi["exact"])), c) and \
        _close(sp.sympify(phi["exact"]), 2 * sp.atan(sp.Rational(t["exact"])))
    # the failing member's right side, from the shown values, is the right side stated
    rel = REGISTRY["3.96e"].build().printed[0]
    rhs = _side_from_symbols(rel.rhs, ce)
    assert _close(rhs, sp.sympify(ce["rhs"]))
    # exact first, then decimals that agree with it
    for s in ce["symbols"]:
        if s["decimal"] and not s["exact"].startswith("Matrix"):
            assert float(s["decimal"]) == pytest.approx(float(sp.sympify(s["exact"])),
                                                        rel=1e-7)


def test_396e_chosen_names_the_parametrisation(r396e):
    ce = counterexample_record(r396e.counterexample)
    text = ce["chosen"]["text"]
    assert "stereographic" in text and "e·e = 1" in text and "tan(φ/2)" in text
    names = [p["name"] for p in ce["chosen"]["params"]]
    assert names[:2] == ["u of e", "v of e"]
    # the parametrisation variables are not shown as book symbols
    assert not any(s["symbol"].startswith(("u", "v", "t")) for s in ce["symbols"])


def test_schema_2_is_additive(r396e):
    rec = result_record(r396e, timings=False)
    ce = rec["counterexample"]
    for key in ("member", "point", "lhs", "rhs", "residual", "residual_max_abs"):
        assert key in ce                          # the keys of before are all still there
    assert set(ce["symbols"][0]) >= {"symbol", "latex", "exact", "text", "decimal"}
    assert set(ce["chosen"]) == {"text", "params"}


def test_user_module_counterexample_in_its_own_symbols():
    um = load_module(str(ROOT / "examples" / "rotation_identities.py"))
    r = check(next(i for i in um.ids if i.endswith("rodrigues-sign")))
    ce = counterexample_record(r.counterexample)
    v = _values(ce)
    assert {"E", "φ", "e"} <= set(v) and "Q" not in v  # Q is the left side, shown as such
    e = sp.Matrix(v["e"])
    assert (e.T * e)[0] == 1 and sp.Matrix(v["E"]) == cpm(e)
    Q = sp.Matrix(sp.sympify(ce["lhs"]))  # a rotation: orthogonal, determinant 1, exactly
    assert Q.T * Q == sp.eye(3) and Q.det() == 1


def test_an_atom_that_cancels_gets_a_stated_value():
    """(3.59): ``a`` drops out of ``Ω(p - a)``; it is still shown, and the text says why
    its value is arbitrary."""
    r = check("3.59")
    ce = counterexample_record(r.counterexample)
    v = _values(ce)
    assert {"a", "p", _nfc("ȧ"), "Ω", "‖ω‖"} <= set(v)
    w = sp.Matrix(v["ω"])
    assert v["‖ω‖"] ** 2 == (w.T * w)[0]          # the norm, exact (a square root)
    assert "cancel" in ce["chosen"]["text"] and "q, u" in ce["chosen"]["text"]
    rel = next(x for x in REGISTRY["3.59"].build().printed if x.label == "pdot_perp brace")
    assert _close(_side_from_symbols(rel.rhs, ce), sp.sympify(ce["rhs"]))


@pytest.mark.slow
def test_357_shows_omega_and_adot():
    """The issue's example: (3.57) at the counterexample in ω and ȧ, exactly."""
    r = check("3.57")
    ce = counterexample_record(r.counterexample)
    v = _values(ce)
    assert {"ω", _nfc("ȧ"), "‖ω‖"} <= set(v)
    w, ad = sp.Matrix(v["ω"]), sp.Matrix(v[_nfc("ȧ")])
    assert v["‖ω‖"] ** 2 == (w.T * w)[0]
    assert sp.Matrix(sp.sympify(ce["rhs"])) == sp.Matrix([(ad.T * w)[0] / (w.T * w)[0]])
    assert [p["name"] for p in ce["chosen"]["params"]] == ["q", "u"]
    assert "quaternion" in ce["chosen"]["text"]


@pytest.mark.slow
def test_every_does_not_hold_has_its_symbols():
    """Every does-not-hold id of the chapter shows book symbols, numerically consistent
    with its stated right side wherever that side is made of them."""
    for i, eq in REGISTRY.items():
        if eq.expected != "does-not-hold" or ":" in i:
            continue
        ce = counterexample_record(check(i).counterexample)
        assert ce["symbols"], i
        assert ce["chosen"]["text"], i
        for s in ce["symbols"]:
            mpmath.mpf(1)  # decimals parse
            assert s["text"] and s["exact"], (i, s)
