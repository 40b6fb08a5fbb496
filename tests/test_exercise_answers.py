"""Exercises 3.7 and 3.12 answer on data the solver once refused: parallel
moments fit one line or two mirror lines; a cut through the top face leaves two parts."""

import subprocess
import sys

import numpy as np
import pytest
import sympy as sp

import rigidsym.exercises as ex

V = sp.Matrix


def _line_ok(a, b, nA, nB, e, ps):
    """The oriented line (e, p*) has the moments n_A, n_B about A, B (plain sympy)."""
    a, b, nA, nB = V(a), V(b), V(nA), V(nB)
    return (sp.simplify(e.dot(e) - 1) == 0 and sp.simplify((ps - a).cross(e) - nA) == V([0] * 3)
            and sp.simplify((ps - b).cross(e) - nB) == V([0] * 3))


def test_ex3_7_parallel_moments_axis_normal_to_ab_is_the_z_axis():
    s = ex.solve("ex3.7", a=[1, 0, 0], b=[2, 0, 0], n_A=[0, 1, 0], n_B=[0, 2, 0])
    assert s.status == "solved" and s.checked
    assert s.answers["e"] == V([0, 0, 1]) and s.answers["p_star"] == V([0, 0, 0])
    assert "e_2" not in s.answers                    # the two mirror lines coincide


def test_ex3_7_parallel_moments_give_both_mirror_lines():
    data = dict(a=[1, 0, 0], b=[2, 0, 0], n_A=[0, sp.Rational(4, 5), 0],
                n_B=[0, sp.Rational(8, 5), 0])
    s = ex.solve("ex3.7", **data)
    assert s.status == "solved" and s.checked
    got = {tuple(s.answers["e"]), tuple(s.answers["e_2"])}
    assert got == {(sp.Rational(3, 5), 0, sp.Rational(4, 5)), (-sp.Rational(3, 5), 0,
                                                               sp.Rational(4, 5))}
    for tag in ("", "_2"):
        assert _line_ok(data["a"], data["b"], data["n_A"], data["n_B"], s.answers[f"e{tag}"],
                        s.answers[f"p_star{tag}"])


# default since 3.12's parts are integrated once in a symbolic a and h: about 2 s of CPU
# an exact solve of 3.12 on other data; quick: test_exercises.py::
# test_exercise_solved_and_checked[ex3.12] (its solve and machine checks) and
# test_ex3_12_principal_check_decides_and_can_fail
@pytest.mark.slow
def test_ex3_12_cut_through_the_top_face_gives_both_parts():
    s = ex.solve("ex3.12", a="1/40", h="1/40")
    assert s.status == "solved" and s.checked
    lo, up = (float(s.answers[f"{t}_volume_m3"]) for t in ("wedge", "upper"))
    assert abs(lo - 2.979e-5) < 5e-9 and abs(up - 1.081e-5) < 5e-9
    # the parts fill the prism: V = 3 sqrt(3)/2 a^2 h
    assert abs(lo + up - 3 * 3**0.5 / 2 * (1 / 40) ** 3) < 1e-15
    for t in ("wedge", "upper"):
        R = np.array(s.answers[f"{t}_principal_axes"].evalf(), float)
        assert np.allclose(R.T @ R, np.eye(3), atol=1e-12)           # unit, orthogonal axes
        m = [float(x) for x in s.answers[f"{t}_principal_moments_per_rho_m5"]]
        assert m == sorted(m)


def test_not_solved_has_its_own_status_and_exit_code():
    from rigidsym.cli.exercise import EXIT_ILL_POSED, EXIT_NOT_SOLVED, _exit_code
    from rigidsym.course.worked import IllPosed, Solution
    from rigidsym.course.worked.render import render_text

    s = Solution("ex3.7", "t", "st", "cit")
    try:
        s.not_solved("a case this solver does not handle.")
    except IllPosed:
        pass
    assert s.status == "not solved" and s.reason.startswith("not solved for these data: ")
    assert "Not solved for these data: not solved" in render_text(s)
    assert _exit_code(s) == EXIT_NOT_SOLVED != EXIT_ILL_POSED


# a process of its own; quick: test_exercises.py::test_cli_student_data (the command on a
# student's --set data, exit 0)
@pytest.mark.slow
def test_cli_3_7_on_a_users_data_exits_0():
    r = subprocess.run([sys.executable, "-m", "rigidsym", "exercise", "3.7", "--set", "a=1,0,0",
                        "--set", "b=2,0,0", "--set", "n_A=0,1,0", "--set", "n_B=0,2,0"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr


def test_ex3_10_evaluation_step_at_given_angles():
    """The evaluation step alone (the full solve decides the twelve sequences' symbolic
    checks first, 3-4 s of CPU: under -m slow below and in the property test)."""
    from rigidsym.course.worked import IllPosed, Solution, exercise_module

    m = exercise_module("ex3.10")
    W = m.euler_rate_matrix("ZXZ")
    d = sp.trigsimp(W.det())
    s = Solution("ex3.10", "t", "st", "cit")
    m._evaluated(s, W, d, {"theta": sp.pi / 6, "phi": sp.pi / 4, "psi": 0}, V([0, 0, 1]))
    assert s.answers["det_W_at"] == -sp.sqrt(2) / 2 and s.answers["eta_dot"] == V([1, 0, 0])
    assert s.checked
    lock = Solution("ex3.10", "t", "st", "cit")
    with pytest.raises(IllPosed, match="infinitely many"):
        m._evaluated(lock, W, d, {"theta": 0, "phi": 0, "psi": 0}, V([0, 0, 1]))
    none = Solution("ex3.10", "t", "st", "cit")
    with pytest.raises(IllPosed, match="no eta_dot"):      # W = [e_z, e_x, e_z] there
        m._evaluated(none, W, d, {"theta": 0, "phi": 0, "psi": 0}, V([0, 1, 0]))


@pytest.mark.slow      # the full solve: 3-4 s of CPU for the symbolic part, once
def test_ex3_10_evaluated_at_given_angles():
    s = ex.solve("ex3.10", theta="30 deg", phi="pi/4", psi="0", omega=[0, 0, 1])
    assert s.status == "solved" and s.checked
    assert s.data["theta"] == sp.pi / 6                      # 30 deg, exact
    W = s.answers["W_at"]
    assert sp.simplify(W.det() - s.answers["det_W_at"]) == 0
    assert s.answers["det_W_at"] == -sp.sqrt(2) / 2         # -sin(phi) for Z-X-Z
    assert s.answers["eta_dot"] == V([1, 0, 0])             # omega along Z: theta_dot alone
    gimbal = ex.solve("ex3.10", theta="0", phi="0", psi="0", omega=[1, 0, 0])
    assert gimbal.status == "ill-posed" and "singular" in gimbal.reason


def test_ex3_12_principal_check_decides_and_can_fail(monkeypatch):
    """3.12 checks its principal pairs' formula once, in symbols (a draw costs no
    minimal polynomial): the formula holds, and a formula with a slip does not pass."""
    import importlib

    from rigidsym.course.worked import exercise_module

    prism = importlib.import_module(exercise_module("ex3.12").__package__ + "._prism")
    assert prism._formula_holds()
    right = prism._yz_pairs
    monkeypatch.setattr(prism, "_yz_pairs", lambda p, q, r, s: [
        (lam, v + sp.Matrix([0, 0, r])) for lam, v in right(p, q, r, s)])   # a slip
    prism._formula_holds.cache_clear()
    try:
        assert not prism._formula_holds()
    finally:
        prism._formula_holds.cache_clear()
    I = sp.Matrix([[2, 1, 0], [1, 3, 1], [0, 1, 4]])                       # x not principal
    assert not prism.principal_check("x", I, []).passed
