"""3.14's rotation box graded by membership in the class its wording defines.

The box asks for "a rotation [Q]_B taking A's frame to B's, [I]_B = Q [I]_A Q^T". The
class of right answers is derived here from that condition alone, in NumPy: with the
eigenvectors V_A of [I]_A and V_B of [I]_B (the same distinct principal moments, in one
order), R [I]_A R^T = [I]_B holds exactly for R = V_B S V_A^T, S a diagonal of signs with
det R = +1 (each principal axis has two senses): four rotations. Every one of them is
graded right; a slip of one (its sign or one entry's, its transpose, doubled or halved,
rounded to one or two significant figures) that leaves the class is graded wrong, and the
slip the grader names is one the test itself finds relating the value to a member. The
test never calls the grader's own class code (:mod:`rigidsym.course.answer_classes`).
"""

from __future__ import annotations

import itertools
import random

import numpy as np
from _profile import examples
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rigidsym import exercises as ex
from rigidsym.course.grading import grade
from rigidsym.course.worked import exercise_module

RTOL = 1e-3          # the documented tolerance: 0.1 % of the key's largest entry (1 here)


def _members(ia: np.ndarray, ib: np.ndarray) -> list[np.ndarray]:
    """Every rotation R with R ia R^T = ib, for two symmetric matrices of the same
    distinct eigenvalues: V_B S V_A^T over the sign matrices S giving det R = +1."""
    la, va = np.linalg.eigh(ia)
    lb, vb = np.linalg.eigh(ib)
    assert np.allclose(la, lb) and np.min(np.diff(la)) > 1e-6 * max(abs(la))
    out = []
    for signs in itertools.product((1.0, -1.0), repeat=3):
        r = vb @ np.diag(signs) @ va.T
        if np.linalg.det(r) > 0:
            out.append(r)
    return out


def _rounded(m: np.ndarray, figures: int) -> np.ndarray:
    return np.array([float(f"{x:.{figures - 1}e}") for x in m.reshape(-1)]).reshape(m.shape)


def _edits(r: np.ndarray) -> list[tuple[str, np.ndarray]]:
    """The slips of one member, each with its word, written out here."""
    out = [("sign", -r), ("transpose", r.T), ("factor 2", 2 * r), ("factor 2", r / 2),
           ("rounded", _rounded(r, 1)), ("rounded", _rounded(r, 2))]
    for i in range(9):
        f = r.reshape(-1).copy()
        if f[i] != 0:
            f[i] = -f[i]
            out.append(("sign", f.reshape(3, 3)))
    return out


def _near(a: np.ndarray, b: np.ndarray) -> bool:
    return bool(np.all(np.abs(a - b) <= RTOL + 1e-12))


def _box(s, value: np.ndarray):
    return next(g for g in grade(s, {"Q_B_A": value.tolist()}, replay=False)
                if g.name == "Q_B_A")


@given(seed=st.one_of(st.none(), st.integers(0, 10_000)), which=st.integers(0, 3),
       slip=st.integers(0, 14))
@settings(max_examples=examples(6), deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))
def test_the_rotation_class_right_and_its_slips_named(seed, which, slip):
    """On the book's data or an exam's draw: the drawn member of the class, written to 5
    decimals, is right; the drawn slip of it is right only when it lands in the class, and
    else wrong with a slip word that relates it to some member."""
    data = {} if seed is None else exercise_module("ex3.14").random_data(random.Random(seed))
    s = ex.solve("ex3.14", **data)
    ia = np.array(s.data["I_A"].tolist(), dtype=float)
    ib = np.array(s.data["I_B"].tolist(), dtype=float)
    members = _members(ia, ib)
    assert len(members) == 4
    r = members[which]
    assert np.allclose(r @ ia @ r.T, ib) and np.allclose(r.T @ r, np.eye(3))
    g = _box(s, np.round(r, 5))
    assert g.correct is True, g.detail
    edits = _edits(r)
    word, value = edits[slip % len(edits)]
    g = _box(s, value)
    if any(_near(value, m) for m in members):
        assert g.correct is True, (word, g.detail)
        return
    named = {w for m in members for w, v in _edits(m) if _near(value, v)}
    assert word in named
    assert g.correct is False and g.slip in named, (word, g.slip, g.detail)
