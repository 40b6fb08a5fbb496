"""The constraint-kind table (rigidsym.core.kinds): every row is consistent, and adding a kind is
one entry.

The toy kind below (a point of the unit circle, spec name ``"unit"`` with shape ``(2,)``) is
registered from this test module and nowhere else; the zero test, the reports' words, the
kernel specs and docstrings, the generated C header, the run-time validation, a generated
and loaded kernel and the Jacobians' tangent note then all know it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from rigidsym.algebra.symbols import TIME, constrained_group, unit_vector
from rigidsym.core import kinds as _kinds
from rigidsym.zero.decide import decide_zero


def _circle(P):
    (u,) = P
    return [2 * u / (1 + u**2), (1 - u**2) / (1 + u**2)]


def _check_circle(a, name, tol):
    err = np.abs(np.hypot(a[..., 0], a[..., 1]) - 1.0)
    return f"{name}: not on the unit circle ({err.max():.3g} > {tol:.3g})" \
        if (err > tol).any() else None


def _project(x, d):
    s = (x[0] * d[0] + x[1] * d[1]) / (x[0] ** 2 + x[1] ** 2)
    return [d[0] - s * x[0], d[1] - s * x[1]]


def _curve(x, v):
    def c(t):
        y = [x[0] + t * v[0], x[1] + t * v[1]]
        n = (y[0] ** 2 + y[1] ** 2) ** 0.5
        return [y[0] / n, y[1] / n]
    return c


TOY = _kinds.Kind("circle", (2,), "unit", "unit circle point, stereographic", ", on the circle",
                  ("s",), _circle, check=_check_circle, tol=1e-9, project=_project,
                  curve=_curve, tangent="{a} lies on the unit circle: admissible d{a} are "
                                        "orthogonal to {a}.")


@pytest.fixture
def toy():
    _kinds.register(TOY)
    yield TOY
    _kinds.unregister(TOY.name)


# ---------------------------------------------------------------------------- every row
def _point(kind, rng):
    """A float point of the constraint set: the kind's own parametrisation at random
    parameters."""
    return np.array([float(v) for v in kind.parametrise(list(rng.uniform(-2, 2,
                                                                         len(kind.params))))])


def _rows():
    return [k for k in _kinds.KINDS.values() if k.parametrise is not None]


@pytest.mark.parametrize("kind", _rows(), ids=lambda k: k.name)
def test_parametrised_points_pass_the_runtime_check_and_off_points_fail(kind):
    rng = np.random.default_rng(1)
    for _ in range(20):
        x = _point(kind, rng).reshape(kind.shape)
        assert kind.check(x, "x", kind.tolerance(np.float64)) is None
        assert kind.check(x.astype(np.float32), "x", kind.tolerance(np.float32)) is None
        bad = x * 1.001
        msg = kind.check(bad, "x", kind.tolerance(np.float64))
        assert msg is not None and msg.startswith("x: ")


@pytest.mark.parametrize("kind", _rows(), ids=lambda k: k.name)
def test_the_tangent_space_is_the_derivative_of_curves_on_the_set(kind):
    """project() gives a direction v with c'(0) = v for the kind's curve, and the curve stays
    on the constraint set (the runtime check passes along it)."""
    rng = np.random.default_rng(2)
    for _ in range(10):
        x = list(_point(kind, rng))
        v = kind.project(x, list(rng.standard_normal(len(x))))
        assert np.allclose(kind.project(x, v), v, atol=1e-12)  # a projection
        c = kind.curve(x, v)
        assert np.allclose(c(0.0), x, atol=1e-15)
        h = 1e-6
        fd = (np.array(c(h)) - np.array(c(-h))) / (2 * h)
        assert np.allclose(fd, v, atol=1e-8)
        for t in (0.3, -1.1):
            y = np.array(c(t)).reshape(kind.shape)
            assert kind.check(y, "y", 1e-12) is None


def test_tolerances_per_dtype():
    unit = _kinds.get("unit")
    assert unit.tolerance(np.float64) == 1e-8
    assert unit.tolerance(np.float32) == pytest.approx(100 * np.finfo(np.float32).eps)
    assert _kinds.get("angle").check is None  # nothing to validate for an angle


def test_unknown_kinds_are_refused_with_the_known_ones_listed():
    from rigidsym.codegen.spec import Arg

    with pytest.raises(ValueError, match="'unit' \\(3,\\)"):
        _kinds.for_spec("positive", ())
    with pytest.raises(ValueError, match="^Arg 'x': kind"):
        Arg("x", (5,), "unit")
    with pytest.raises(ValueError, match="kind: expected one of"):
        constrained_group("positive", "x")
    with pytest.raises(ValueError, match="registered already"):
        _kinds.register(_kinds.get("unit"))


def test_the_book_kinds_keep_their_parametrisation():
    """The zero test still imposes e.e = 1 through the table's stereographic rows."""
    e = unit_vector("ke")
    assert decide_zero([(e.T * e)[0] - 1]).zero is True
    assert decide_zero([(e.T * e)[0] - 2]).zero is False


# ---------------------------------------------------------------------------- the toy kind
def test_a_toy_kind_is_one_entry_for_the_zero_test_and_the_reports(toy):
    from rigidsym.checking.deciding.records import model_words

    x = constrained_group("circle", "kx")
    assert x.shape == (2, 1)
    assert decide_zero([x[0] ** 2 + x[1] ** 2 - 1]).zero is True
    r = decide_zero([(x[0] + x[1]) ** 2 - 1])
    assert r.zero is False and r.method == "counterexample"
    # along a motion: d/dt (x.x) = 0 through the jets of the parameter
    xt = constrained_group("circle", "kxt", TIME)
    assert decide_zero([sp.diff(xt[0] ** 2 + xt[1] ** 2, TIME)]).zero is True
    assert decide_zero([sp.diff(xt[0], TIME)]).zero is False
    assert "kx: unit circle point, stereographic" in model_words([x[0] * x[1]])


def test_a_toy_kind_is_one_entry_for_kernels(toy, tmp_path):
    from rigidsym import kernels as K
    from rigidsym.codegen.backends.numpy.api_spec import docstring
    from rigidsym.codegen.generator import generate, write
    from rigidsym.codegen.spec import Arg, Kernel, Out
    from rigidsym.kernels.runtime import jacobians as _jacobian
    from rigidsym.kernels.runtime import space as _core

    arg = Arg("x", (2,), "unit", "a point of the circle")
    kernel = Kernel("circle_slope", "Slope of the ray to a circle point.", "x2 / x1",
                    ("toy:slope",), ("toy.slope",), (arg,), (Out("m", ()),),
                    lambda x: {"m": x[1] / x[0]}, jacobian=False)
    res = generate([kernel], origin="tests.test_kinds")
    # the row names no C routine: the compiled entry points leave its checks to Python
    assert "{1, {2}, 2, 3}" in res.files["c/rigidsym_fast.h"]
    write(res, tmp_path)
    ns = K.load(tmp_path)
    before = K._state.STATE["backend"]
    K.use_backend("numpy")  # the toy kernel's C is not compiled: its checks are the same
    try:
        assert ns.circle_slope([0.6, 0.8]) == pytest.approx(4 / 3)
        with pytest.raises(ValueError, match="^x: not on the unit circle"):
            ns.circle_slope([0.6, 0.81])
        assert math.isfinite(ns.circle_slope([0.6, 0.81], check=False))
    finally:
        K._state.STATE["backend"] = before
    spec = {"name": "x", "kind": "unit", "tshape": (2,)}
    _core.validate(np.float32([0.6, 0.8000001]), spec)
    meta = {"summary": "s", "formula": "f", "ids": ["toy:slope"], "sources": ["toy.slope"],
            "args": [{"name": "x", "shape": [2], "kind": "unit", "doc": ""}],
            "outputs": [{"name": "m", "shape": [], "doc": ""}], "singular": "", "notes": "",
            "ops": 1, "hash": "0"}
    assert "x: array-like (..., 2), on the circle" in docstring(meta)
    assert _jacobian._tangent_note(meta["args"][0]) == \
        "x lies on the unit circle: admissible dx are orthogonal to x."


@pytest.mark.slow
def test_a_toy_kind_compiled_is_still_checked(toy, tmp_path):
    """The compiled entry points have no C routine for the toy kind (``c_check`` 0): a
    checked call takes the Python path, so a point off the circle is refused on C too."""
    from rigidsym import kernels as K
    from rigidsym.codegen.generator import generate, write
    from rigidsym.codegen.spec import Arg, Kernel, Out

    kernel = Kernel("circle_slope_c", "Slope of the ray to a circle point.", "x2 / x1",
                    ("toy:slope",), ("toy.slope",), (Arg("x", (2,), "unit"),),
                    (Out("m", ()),), lambda x: {"m": x[1] / x[0]}, jacobian=False)
    write(generate([kernel], origin="tests.test_kinds"), tmp_path)
    before = K._state.STATE["backend"]
    try:
        if K.use_backend("c") != "c":
            pytest.skip("no compiled kernels here (no compiler)")
        ns = K.load(tmp_path)
        ns._SPACE.c_lib()  # compiled now (a notice on stderr), not skipped
        assert ns.circle_slope_c([0.6, 0.8]) == pytest.approx(4 / 3)
        with pytest.raises(ValueError, match="^x: not on the unit circle"):
            ns.circle_slope_c([0.6, 0.81])
        with pytest.raises(ValueError, match="^x: not on the unit circle"):
            ns.circle_slope_c(np.array([[0.6, 0.8], [0.6, 0.81]]))
        assert ns.circle_slope_c([0.6, 0.81], check=False) == pytest.approx(0.81 / 0.6)
    finally:
        K._state.STATE["backend"] = before
