"""rigidsym audit counts every wrong output it meets (docs/audit.md, "Every wrong output
counted"): each class (NaN/inf, exception, wrong rotation, conjugate, transposed, inverse
rotation, wrong branch, wrong value) with how many of its inputs gave it, how far off and
the worst input; a batched path that disagrees with the row alone is a finding, with what
it returns (the conjugate quaternion of ahrs' hughes)."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("flint")
sys.path.insert(0, str(Path(__file__).resolve().parent))
import audit_examples as X  # noqa: E402
import audit_noise_examples as N  # noqa: E402

from rigidsym import audit  # noqa: E402
from rigidsym.auditing import audit as A  # noqa: E402
from rigidsym.auditing import conventions as C  # noqa: E402
from rigidsym.auditing import report  # noqa: E402
from rigidsym.auditing import worst as W  # noqa: E402
from rigidsym.auditing.targets import target  # noqa: E402
from rigidsym.codegen.accuracy import regimes as P  # noqa: E402
from rigidsym.codegen.accuracy.harness.reference import kernel_of  # noqa: E402

FLIP = np.array([-1.0, -1.0, -1.0, 1.0])


def _classify(func, op, pt):
    tgt = target(op)
    m = C.Member(tgt.forms[0], ())
    runner = W.Runner(func, m, kernel_of(tgt.kernel), tgt)
    j = W.judge_point(tgt.kernel, "random", pt, np.float64, runner, tgt.antipodal)
    return W.classify(tgt, tgt.kernel, j, np.float64, runner)


def _rotation(seed, tan_half=0.7):
    rng = np.random.default_rng(seed)
    return [P.rotation(P.unit(rng), P.q(tan_half), P.q(1.0))]


@pytest.mark.parametrize("seed", range(3))
def test_each_class_is_told_apart(seed):
    pt = _rotation(seed)
    q = "euler_rodrigues_from_rotation"
    assert _classify(lambda Q: N.quaternion(Q) * FLIP, q, pt)[0] == "conjugate"
    assert _classify(N.quaternion_negated, q, pt)[0] == "inaccurate"    # -q: the same
    assert _classify(lambda Q: N.quaternion(Q)[[1, 2, 0, 3]], q, pt)[0] == "wrong rotation"
    log = "rotation_vector_from_rotation"
    assert _classify(lambda Q: -N.log(Q), log, pt)[0] == "inverse rotation"
    w = N.log(np.array([[float(v) for v in pt[0]]]).reshape(3, 3))
    branch = _classify(lambda Q: N.log(Q) * (1 - 2 * np.pi / np.linalg.norm(w)), log, pt)
    assert branch[0] == "wrong branch"
    assert _classify(lambda Q: N.log(Q) * np.nan, log, pt)[0] == "NaN/inf"

    def raises(Q):
        raise ValueError("no")
    assert _classify(raises, log, pt)[0] == "exception"
    rot = "rotation_from_euler_rodrigues"
    rng = np.random.default_rng(seed)
    eta = [[*P.unit(rng, 4)]]
    off = _classify(lambda e: N.rotation_from_axis_angle(
        *_axis_angle(e)).T, rot, eta)
    assert off[0] == "transposed" and off[1] > 1e-3


def _axis_angle(eta):
    r, r0 = np.asarray(eta[:3]), float(eta[3])
    n = float(np.linalg.norm(r))
    return r / n, 2 * np.arctan2(n, r0)


def test_a_batched_path_that_disagrees_is_a_finding():
    tgt = target("euler_rodrigues_from_rotation")
    m = C.Member(tgt.forms[0], ())
    call = A.as_numpy_callable(N.quaternion_batched_conjugate)
    said = W.batch_dependence(call, m, kernel_of(tgt.kernel), np.random.default_rng(0), tgt)
    assert "disagrees" in said and "8 of 8" in said and "conjugate" in said, said
    found = C.Found(m, 1, 0.0, m)
    fs = A._findings(found, tgt, {}, {}, said)
    assert [(f.severity, f.kind) for f in fs] == [("error", "batch")]
    # a batched path equal to the row alone is no finding
    ok = W.batch_dependence(A.as_numpy_callable(lambda Q: np.stack([N.quaternion(M) for M in Q])
                                                if np.ndim(Q) == 3 else N.quaternion(Q)),
                            m, kernel_of(tgt.kernel), np.random.default_rng(0), tgt)
    assert "bit for bit" in ok, ok


def test_the_wrong_outputs_are_one_finding_with_their_counts():
    wrong = {"float64": [
        {"class": "NaN/inf", "count": 3, "off": np.inf, "regime": "gimbal lock", "ratio": 1.0,
         "args": [[1.0]]},
        {"class": "wrong rotation", "count": 16, "off": 1.17, "regime": "gimbal lock",
         "ratio": 1e15, "args": [[1.0]]}]}
    f = A._told(wrong)
    assert f.severity == "error" and "wrong rotation at 16 inputs, off by up to 1.17 rad" \
        in f.text and "NaN/inf at 3 inputs" in f.text
    only = A._told({"float64": [{"class": "inaccurate", "count": 2, "off": 1e-14,
                                 "regime": "random", "ratio": 3.0, "args": [[1.0]]}]})
    assert only.severity == "note"
    assert A._told({"float64": []}) is None


@pytest.mark.slow
def test_the_gimbal_lock_bug_is_told_whole():
    """NaN past +-1 and wrong rotations at the lock, both counted, each with its worst
    input, in the text and the Markdown."""
    rep = audit(X.ypr_asin_no_clamp, "euler_angles_from_rotation",
                spec="audit_examples:ypr_asin_no_clamp")
    classes = {c["class"]: c for c in rep.wrong["float64"]}
    assert {"NaN/inf", "wrong rotation"} <= set(classes)
    assert classes["wrong rotation"]["off"] > 0.1
    md = report.markdown(rep)
    assert "**Wrong outputs met**" in md and "| wrong rotation |" in md
    assert "wrong outputs met, float64" in report.text(rep)
