"""The time limit of ``rigidsym check --latex`` (``--timeout``, ``check_latex(timeout=)``):
past it the answer is ``undecided`` (exit 3) naming the step it was in and a hint.

The limit is injected through the deterministic hook ``RIGIDSYM_LATEX_LIMIT_AT=STEP``
(:mod:`rigidsym.latex.limit`): the limit counts as passed when STEP begins, so that no test
here depends on the machine's speed.
"""

from __future__ import annotations

import signal

import pytest

import rigidsym
from rigidsym.cli import main
from rigidsym.latex import limit
from rigidsym.registry import declarations as registry

#: micro Lie's closed form of J_r^{-1} beside J_r, in the rotation vector and its norm
JR_INV = (r"\mathbf{J}_r\mathbf{K} = \mathbf{I}",
          [r"\boldsymbol\theta: vector", r"\theta = \|\boldsymbol\theta\|",
           r"\mathbf{J}_r = \mathbf{I} - \frac{1 - \cos\theta}{\theta^2}[\boldsymbol\theta]_\times"
           r" + \frac{\theta - \sin\theta}{\theta^3}[\boldsymbol\theta]_\times^2",
           r"\mathbf{K} = \mathbf{I} + \frac{1}{2}[\boldsymbol\theta]_\times + \left(\frac{1}"
           r"{\theta^2} - \frac{1 + \cos\theta}{2\theta\sin\theta}\right)"
           r"[\boldsymbol\theta]_\times^2"])
ROT = (r"\mathbf{C}^T\mathbf{C} = \mathbf{1}", [r"\mathbf{C}: rotation"])
SLIP = (r"\mathbf{C}^T\mathbf{C} = 2\mathbf{1}", [r"\mathbf{C}: rotation"])


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


@pytest.mark.parametrize("step", ["reading", "deciding", "cross-check"])
def test_past_the_limit_the_check_is_undecided_naming_its_step_and_a_hint(monkeypatch, step):
    monkeypatch.setenv(limit.HOOK, step)
    r = rigidsym.check_latex(*JR_INV, repairs=False, timeout=2)
    assert r.verdict == "undecided" and r.method == "time-limit"
    words, hint = limit.STEPS[step]
    assert f"step '{step}'" in r.cause and words in r.cause and hint in r.cause, r.cause
    assert "(2 s)" in r.cause and "--timeout" in r.cause
    assert signal.getsignal(signal.SIGALRM) is signal.SIG_DFL  # the alarm is given back


def test_without_the_hook_the_same_check_decides(monkeypatch):
    monkeypatch.delenv(limit.HOOK, raising=False)
    r = rigidsym.check_latex(*ROT, repairs=False, timeout=60)
    assert r.verdict == "verified"


def test_the_command_line_says_undecided_with_the_step_and_exits_3(monkeypatch, capsys):
    monkeypatch.setenv(limit.HOOK, "deciding")
    code = main(["check", "--latex", ROT[0], "--let", ROT[1][0], "--timeout", "2"])
    cap = capsys.readouterr()
    out = cap.out
    assert code == 3, cap.err
    assert "read as: " in out and "undecided: the time limit (2 s)" in out, out
    assert "step 'deciding'" in out and "hint:" in out, out


def test_a_limit_that_passes_in_the_repair_search_keeps_the_alarm_nested(monkeypatch):
    # the repair search's own alarm nests inside the check's: a does-not-hold with its
    # repairs, and the check's alarm handed back at the end
    monkeypatch.delenv(limit.HOOK, raising=False)
    r = rigidsym.check_latex(*SLIP, timeout=600, repair_seconds=5)
    assert r.verdict == "does-not-hold"
    assert signal.getsignal(signal.SIGALRM) is signal.SIG_DFL
    assert signal.getsignal(signal.SIGPROF) is signal.SIG_DFL


@pytest.mark.parametrize("bad", [0, -1, "60", True, float("nan")])
def test_a_timeout_that_is_no_positive_number_is_refused_naming_it(bad):
    with pytest.raises(ValueError, match="timeout"):
        rigidsym.check_latex(*ROT, timeout=bad)


def test_the_hook_names_only_steps():
    with pytest.raises(ValueError, match="step"):
        limit.step("thinking")


@pytest.mark.parametrize("text, seconds", [("", limit.DEFAULT_SECONDS), ("none", None),
                                           ("NONE", None), ("2.5", 2.5)])
def test_the_default_limit_is_60_s_or_the_environment_variables(monkeypatch, text, seconds):
    monkeypatch.setenv(limit.ENV, text)
    assert limit.default_seconds() == seconds


@pytest.mark.parametrize("text", ["0", "-3", "soon", "nan"])
def test_an_environment_limit_that_is_no_number_is_refused_naming_it(monkeypatch, text):
    monkeypatch.setenv(limit.ENV, text)
    with pytest.raises(ValueError, match=limit.ENV):
        rigidsym.check_latex(*ROT)


def test_the_default_limit_applies_where_none_is_given(monkeypatch):
    monkeypatch.setenv(limit.ENV, "30")
    monkeypatch.setenv(limit.HOOK, "deciding")
    r = rigidsym.check_latex(*ROT, repairs=False)
    assert r.verdict == "undecided" and "(30 s)" in r.cause, r.cause


#: micro Lie's J_r^{-1} in closed form against the inverse of J_r itself: the symbolic inverse
#: of a 3 x 3 in sin and cos of a norm, far past a few seconds on any machine
JR_INVERSE = (r"\mathbf{J}_r^{-1} = \mathbf{I} + \frac{1}{2}[\boldsymbol\theta]_\times + "
              r"\left(\frac{1}{\theta^2} - \frac{1 + \cos\theta}{2\theta\sin\theta}\right)"
              r"[\boldsymbol\theta]_\times^2", JR_INV[1][:3])


# 2 s of CPU by the clock; quick: the same ending at a named step
# (test_past_the_limit_the_check_is_undecided_naming_its_step_and_a_hint) and the limit
# counting CPU time (test_the_limit_counts_cpu_time_so_waiting_never_ends_a_check)
@pytest.mark.slow
def test_a_2_s_limit_on_a_slow_statement_ends_undecided_with_its_reason_by_the_clock(monkeypatch):
    # no hook: the alarm itself ends the check, in whichever step it runs then
    monkeypatch.delenv(limit.HOOK, raising=False)
    r = rigidsym.check_latex(*JR_INVERSE, repairs=False, timeout=2)
    assert r.verdict == "undecided" and r.method == "time-limit", (r.verdict, r.cause)
    step = next(s for s in limit.STEPS if f"step '{s}'" in r.cause)
    assert limit.STEPS[step][1] in r.cause and "(2 s)" in r.cause, r.cause
    assert signal.getsignal(signal.SIGALRM) is signal.SIG_DFL
    assert signal.getsignal(signal.SIGPROF) is signal.SIG_DFL


def test_the_limit_counts_cpu_time_so_waiting_never_ends_a_check():
    # a block that waits (as a check does beside busy processes) spends wall-clock time and
    # next to no CPU time: a limit of 0.2 s has not passed after 0.5 s of waiting
    import time

    with limit.limited(0.2):
        time.sleep(0.5)
        limit.step("deciding")  # no TimeUp: the CPU deadline is not reached


def _spin(seconds: float) -> None:
    import time

    end = time.monotonic() + seconds
    while time.monotonic() < end:
        pass


@pytest.mark.slow
def test_the_same_verdict_on_an_idle_machine_and_beside_cpu_bound_siblings(monkeypatch):
    # a limit a few times the check's own CPU time: on an idle machine and beside CPU-bound
    # sibling processes (more than the cores, so that the wall clock stretches) the verdict
    # is the same, since the limit counts the check's CPU time only
    import multiprocessing as mp
    import os
    import time

    monkeypatch.delenv(limit.HOOK, raising=False)
    t0 = time.process_time()
    idle = rigidsym.check_latex(*SLIP, repairs=False, timeout=600)
    spent = time.process_time() - t0
    ctx = mp.get_context("fork")
    # a load of 8, and more than the cores where a machine has more
    siblings = [ctx.Process(target=_spin, args=(60.0,), daemon=True)
                for _ in range(max(8, (os.cpu_count() or 1) + 2))]
    for p in siblings:
        p.start()
    try:
        registry.forget_module("rigidsym.latex.statement")
        loaded = rigidsym.check_latex(*SLIP, repairs=False, timeout=max(3 * spent, 1.0))
    finally:
        for p in siblings:
            p.terminate()
            p.join()
    assert idle.verdict == loaded.verdict == "does-not-hold", (loaded.verdict, loaded.cause)
