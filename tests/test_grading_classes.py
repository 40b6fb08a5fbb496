"""Each exercise's question tests: every member of the key's class is right, every one-edit
slip is wrong and named, a blank is a blank.

The members are generated here by the group action each answer's meaning allows, written
in this file (an axis and angle (e, phi) ~ (-e, -phi) and phi + 2 pi k with the Plücker
array's sign following e; any point of an axis; principal axes each up to sign; a line's
angle modulo pi; every rotation R with R [I]_A R^T = [I]_B, built from the eigenvectors of
both matrices), never by the grader's :mod:`rigidsym.course.answer_classes`. The key's
numbers come from the exact solution through sympy's ``N``; the edits and the membership
test below are plain NumPy. The default run draws a few members per exercise; the
exhaustive run (``-m slow``) many.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
import sympy as sp
from _profile import examples
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rigidsym import exercises as ex
from rigidsym.course.grading import grade

IDS = [f"ex3.{k}" for k in range(1, 22)]
RTOL = 1e-3          # the course's documented tolerance: 0.1 % of the largest entry

#: the group actions of each exercise's answers, as the problem states them
SIGN_GROUPS = {"ex3.1": ("e", "phi", ("plucker",)), "ex3.6": ("e", "phi", ("axis_plucker",))}
POINTS_ON_AXIS = {"ex3.6": ("axis_point_p0", "e")}
COLUMN_SIGNS = {"ex3.12": ("wedge_principal_axes", "upper_principal_axes")}
ANGLES_MOD_PI = {"ex3.12": ("wedge_axis_angle_from_y_rad", "upper_axis_angle_from_y_rad")}
#: a rotation box stated by its property R [from] R^T = [to] (the exercise's data)
ROTATIONS_ONTO = {"ex3.14": ("Q_B_A", "I_A", "I_B")}


def rotations_between(source, image):
    """Every rotation R with R source R^T = image, for two symmetric matrices with the same
    distinct eigenvalues: R = V_image S V_source^T, S = diag(+-1, +-1, +-1) of determinant
    +1 (each eigenvector of either matrix has two senses)."""
    _, va = np.linalg.eigh(np.asarray(source, dtype=float))
    _, vb = np.linalg.eigh(np.asarray(image, dtype=float))
    out = []
    for signs in ((1, 1, 1), (1, 1, -1), (1, -1, 1), (1, -1, -1), (-1, 1, 1), (-1, 1, -1),
                  (-1, -1, 1), (-1, -1, -1)):
        r = vb @ np.diag(signs) @ va.T
        if np.linalg.det(r) > 0:
            out.append(r)
    return out


def rotation_class(ex_id):
    """The members of the rotation box of ``ex_id`` on the book's data (four)."""
    s, _ = key_of(ex_id)
    _, src, dst = ROTATIONS_ONTO[ex_id]
    return rotations_between(np.array(s.data[src].tolist(), dtype=float),
                             np.array(s.data[dst].tolist(), dtype=float))


def _key(ex_id):
    """The numeric boxes of an exercise on the book's data: name -> (float array, truth?)."""
    s = ex.solve(ex_id)
    out = {}
    for k, v in s.answers.items():
        if isinstance(v, str) or getattr(v, "free_symbols", None):
            continue
        if v in (sp.true, sp.false):
            out[k] = (np.array(float(bool(v))), True)
        elif isinstance(v, sp.MatrixBase):
            out[k] = (np.array(sp.N(v, 17).tolist(), dtype=float), False)
        elif isinstance(v, sp.Expr):
            out[k] = (np.array(float(sp.N(v, 17))), False)
    return s, out


_CACHE: dict = {}


def key_of(ex_id):
    if ex_id not in _CACHE:
        _CACHE[ex_id] = _key(ex_id)
    return _CACHE[ex_id]


@st.composite
def members(draw, ex_id):
    """A member of the key's class: the key under the group actions of ``ex_id``."""
    _, key = key_of(ex_id)
    out = {k: v.copy() for k, (v, _) in key.items()}
    if ex_id in SIGN_GROUPS:
        axis, angle, linked = SIGN_GROUPS[ex_id]
        s = draw(st.sampled_from((1.0, -1.0)))
        turns = draw(st.integers(-2, 2))
        for n in (axis, *linked):
            out[n] = s * out[n]
        out[angle] = s * out[angle] + 2 * math.pi * turns
    if ex_id in POINTS_ON_AXIS:
        point, direction = POINTS_ON_AXIS[ex_id]
        t = draw(st.floats(-3, 3))
        d = key[direction][0].reshape(-1)
        out[point] = out[point] + t * (d / np.linalg.norm(d)).reshape(out[point].shape)
    for name in COLUMN_SIGNS.get(ex_id, ()):
        signs = np.array(draw(st.lists(st.sampled_from((1.0, -1.0)), min_size=3, max_size=3)))
        out[name] = out[name] * signs
    for name in ANGLES_MOD_PI.get(ex_id, ()):
        out[name] = out[name] + math.pi * draw(st.integers(-2, 2))
    if ex_id in ROTATIONS_ONTO:
        out[ROTATIONS_ONTO[ex_id][0]] = draw(st.sampled_from(rotation_class(ex_id)))
    noise = draw(st.floats(-0.2, 0.2))          # a student's last decimals: in tolerance
    for k, (v, truth) in key.items():
        if not truth:
            out[k] = out[k] + noise * RTOL * max(float(np.max(np.abs(v))), 1e-300) * \
                np.sign(np.arange(v.size).reshape(v.shape) % 2 - 0.5)
    return out


def in_class(ex_id, name, value, member) -> bool:
    """Whether ``value`` for box ``name`` (the other boxes as in ``member``) is a member of
    the key's class: the test's own judgement, from the group actions above."""
    _, key = key_of(ex_id)
    k = key[name][0]
    scale = max(float(np.max(np.abs(k))), 1e-300)

    def near(a, b, sc=scale):
        return a.shape == b.shape and bool(np.all(np.abs(a - b) <= RTOL * sc + 1e-12))

    if ex_id in SIGN_GROUPS and name in (SIGN_GROUPS[ex_id][0], SIGN_GROUPS[ex_id][1],
                                         *SIGN_GROUPS[ex_id][2]):
        axis, angle, _ = SIGN_GROUPS[ex_id]
        # the sign the member's axis chose decides the others' (checked on the axis)
        s = 1.0 if near(member[axis], key[axis][0], 1.0) else -1.0
        if name == angle:
            w = (value - s * k + math.pi) % (2 * math.pi) - math.pi
            return near(w, np.zeros_like(w))
        return near(value, s * k)
    if ex_id in POINTS_ON_AXIS and name == POINTS_ON_AXIS[ex_id][0]:
        d = key[POINTS_ON_AXIS[ex_id][1]][0].reshape(-1)
        return near(np.cross((value - k).reshape(-1), d / np.linalg.norm(d)), np.zeros(3))
    if name in COLUMN_SIGNS.get(ex_id, ()):
        return all(near(value[:, j], k[:, j]) or near(value[:, j], -k[:, j])
                   for j in range(k.shape[1]))
    if name in ANGLES_MOD_PI.get(ex_id, ()):
        w = (value - k + math.pi / 2) % math.pi - math.pi / 2
        return near(w, np.zeros_like(w))
    if name == ROTATIONS_ONTO.get(ex_id, ("",))[0]:
        return any(near(value, r) for r in rotation_class(ex_id))
    return near(value, k)


def unit_factor(name, ex_id=None):
    """The factor of a unit slip of box ``name`` as the docs give it (docs/exams.md, the
    slips by kind): a length m^k (its documented unit, or declared a length) typed in mm^k,
    10^(3k); another quantity with a unit, 10^3; a box with no unit (or an angle), none."""
    from rigidsym.course.worked import exercise_module
    from rigidsym.course.worked.units import answer_unit

    if ex_id is None:
        return None
    mod = exercise_module(ex_id)
    if getattr(mod, "ANSWER_KINDS", {}).get(name) == "length":
        return 1000.0
    unit = answer_unit(mod, name)
    if not unit or "rad" in unit:
        return None
    m = re.fullmatch(r"m(?:\^(\d+))?", unit.strip())
    return 10.0 ** (3 * int(m.group(1) or 1)) if m else 1000.0


def one_edit_slips(name, v, ex_id=None):
    """The one-edit slips of a value: (word, edited value); the unit slip only where the
    box has a unit (``ex_id`` given: :func:`unit_factor`)."""
    out = []
    f = unit_factor(name, ex_id)
    if np.any(v != 0):
        out.append(("sign", -v))
        if f is not None:
            out.append(("unit", v * f))
    if v.ndim == 2 and v.shape[0] == v.shape[1] > 1 and not np.allclose(v, v.T, atol=1e-6):
        out.append(("transpose", v.T))
    if v.ndim == 0 and ("phi" in name or "rad" in name or "angle" in name) and v != 0:
        out.append(("degrees", v * 180 / math.pi))
    flat = v.reshape(-1)
    if flat.size == 6 and not np.allclose(flat[:3], flat[3:], atol=1e-6):
        out.append(("order", np.concatenate([flat[3:], flat[:3]]).reshape(v.shape)))
    if flat.size > 1 and (v.ndim == 1 or (v.ndim == 2 and 1 in v.shape)):
        i = int(np.argmax(np.abs(flat)))
        j = int(np.argmax(np.abs(flat - flat[i])))
        if abs(flat[i] - flat[j]) > 0.01 * abs(flat[i]):
            f = flat.copy()
            f[[i, j]] = f[[j, i]]
            out.append(("swap", f.reshape(v.shape)))
    return out


def _answers(member, key):
    return {k: (bool(v > 0.5) if key[k][1] else v.tolist()) for k, v in member.items()}


def _check(ex_id, member, blank):
    s, key = key_of(ex_id)
    answers = _answers(member, key)
    graded = {g.name: g for g in grade(s, answers, replay=False)}
    for k in key:
        assert graded[k].correct is True, (ex_id, k, answers[k], graded[k].detail)
    for k, (v, truth) in key.items():
        if truth:
            flipped = grade(s, {k: not bool(v > 0.5)}, replay=False)
            assert next(g for g in flipped if g.name == k).correct is False
            continue
        edits = one_edit_slips(k, member[k], ex_id)
        if k in POINTS_ON_AXIS.get(ex_id, ())[:1]:
            # a slip that scales a point scales the axis with it (named for any point);
            # an exchange of entries is named on the key's own point
            edits = [(w, x) for w, x in edits if w in ("sign", "unit")] + \
                [(w, x) for w, x in one_edit_slips(k, key[k][0], ex_id)
                 if w not in ("sign", "unit")]
        for word, value in edits:
            if in_class(ex_id, k, value, member):
                continue                # an edit that lands in the class: right, not a slip
            # the box with the rest of its sign group (judged jointly), the others left out
            group = SIGN_GROUPS.get(ex_id, ("", "", ()))
            ctx = {n: answers[n] for n in (group[0], group[1], *group[2]) if n in answers}
            g = next(g for g in grade(s, {**ctx, k: value.tolist()}, replay=False)
                     if g.name == k)
            assert g.correct is False, (ex_id, k, word, g.detail)
            if g.slip is None and "a trivial answer" in g.detail:
                continue   # the slipped key is itself trivial (a datum, zero): no slip credit
            assert g.slip is not None and g.note not in ("wrong", "right"), \
                (ex_id, k, word, g.detail)
    if blank in key:
        g = next(g for g in grade(s, {blank: ""}, replay=False) if g.name == blank)
        assert g.correct is False and g.missing and g.note == "blank"


def _property(ex_id, n):
    _, key = key_of(ex_id)
    names = sorted(key) or ["-"]

    @given(member=members(ex_id), blank=st.sampled_from(names))
    @settings(max_examples=n, deadline=None, derandomize=True, database=None,
              suppress_health_check=list(HealthCheck))
    def run(member, blank):
        _check(ex_id, member, blank)

    run()


#: exercises whose exact solve takes seconds on a cold cache (their boxes: truths and
#: expressions in symbols): their question tests run under ``slow`` only
SLOW_SOLVES = {"ex3.3", "ex3.10"}


@pytest.mark.sample(fraction=0.33)   # a seeded third in the quick run, the rest thorough
@pytest.mark.parametrize("ex_id", [i for i in IDS if i not in SLOW_SOLVES])
def test_question_tests(ex_id):
    """A member or two of each exercise's class, its slips and a blank (default run)."""
    _property(ex_id, 1 if ex_id not in SIGN_GROUPS | COLUMN_SIGNS | ROTATIONS_ONTO else 3)


@pytest.mark.slow
@pytest.mark.parametrize("ex_id", IDS)
def test_question_tests_exhaustive(ex_id):
    _property(ex_id, 40)


def test_31_equivalent_pairs_are_right():
    """3.1: (-e, -phi) with the Plücker array negated to match, and (-e, 2 pi - phi)."""
    s, key = key_of("ex3.1")
    e, phi, pl = key["e"][0], float(key["phi"][0]), key["plucker"][0]
    base = _answers({k: v for k, (v, _) in key.items()}, key)
    for form in ({"e": -e, "phi": -phi, "plucker": -pl},
                 {"e": -e, "phi": 2 * math.pi - phi, "plucker": -pl}):
        graded = grade(s, dict(base, **{k: np.asarray(v).tolist() for k, v in
                                           form.items()}))
        assert all(g.correct for g in graded if g.name in form)
        assert any("equivalent (-e, -phi)" in g.note for g in graded)
    half = grade(s, dict(base, e=(-e).tolist()))           # -e alone: the inverse turn
    assert next(g for g in half if g.name == "e").slip == "sign"


def test_numbers_as_people_write_them():
    """A decimal comma is read, ``1,234`` is left to the instructor, thousands separators
    are refused, and a rounded answer is named with its figures."""
    s, key = key_of("ex3.1")
    phi = float(key["phi"][0])
    by = {g.name: g for g in grade(s, {"phi": f"{phi:.6f}".replace(".", ",")},
                                   replay=False)}
    assert by["phi"].correct is True
    for text in ("1,234", "-2,094"):
        g = next(g for g in grade(s, {"phi": text}, replay=False) if g.name == "phi")
        assert g.correct is None and g.note == "ambiguous" and "instructor" in g.detail
    for text in ("1,234,567", "12 345.6"):
        g = next(g for g in grade(s, {"phi": text}, replay=False) if g.name == "phi")
        assert g.correct is False and "thousands separators" in g.detail
    for figures in (1, 2):
        shown = float(f"{phi:.{figures - 1}e}")
        g = next(g for g in grade(s, {"phi": shown}, replay=False) if g.name == "phi")
        assert g.correct is False and g.note == f"rounded {figures} s.f."


@given(key=st.lists(st.floats(-5, 5), min_size=4, max_size=4).filter(
           lambda v: max(map(abs, v)) > 0.5),
       factor=st.floats(0.1, 10), sign=st.sampled_from((1.0, -1.0)))
@settings(max_examples=examples(15), deadline=None, derandomize=True, database=None)
def test_the_sign_and_scale_classes(key, factor, sign):
    """A unit quaternion's class (+-q) and a Plücker array up to scale: members built
    here by the group action are right, the key's other edits are not."""
    from rigidsym.course.answer_classes import judge

    k = np.array(key)
    q = {"q": k}
    assert judge({"kind": "sign", "names": ("q",)}, {"q": sign * k}, q, RTOL)["q"].right
    assert not judge({"kind": "sign", "names": ("q",)}, {"q": 2 * k}, q, RTOL)["q"].right
    any_scale = {"kind": "up to scale", "name": "q", "sign": "any"}
    positive = {"kind": "up to scale", "name": "q", "sign": "positive"}
    assert judge(any_scale, {"q": sign * factor * k}, q, RTOL)["q"].right
    assert judge(positive, {"q": sign * factor * k}, q, RTOL)["q"].right == (sign > 0)
    swapped = k[[1, 0, 2, 3]]
    if not np.allclose(np.cross(swapped[:3], k[:3]), 0, atol=1e-3) or \
            abs(k[0] - k[1]) > 1e-2 * max(map(abs, key)):
        assert not judge(any_scale, {"q": swapped}, q, RTOL)["q"].right


def _turn(axis, angle):
    """The rotation by ``angle`` about the unit ``axis`` (Rodrigues), NumPy."""
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * kx + (1 - math.cos(angle)) * kx @ kx


def _rotation_box(seed):
    """3.14 on the book's data (seed None) or on an exam's draw: (solution, members)."""
    import random

    from rigidsym.course.worked import exercise_module

    if seed is None:
        s = key_of("ex3.14")[0]
    else:
        s = ex.solve("ex3.14", **exercise_module("ex3.14").random_data(random.Random(seed)))
    members = rotations_between(np.array(s.data["I_A"].tolist(), dtype=float),
                                np.array(s.data["I_B"].tolist(), dtype=float))
    return s, members


@pytest.mark.parametrize("seed", [None, 3])
def test_every_rotation_of_the_box_is_right(seed):
    """3.14's rotation box states a property, [I]_B = Q [I]_A Q^T: each of the four
    rotations that have it (built here from both matrices' eigenvectors), written to 4
    decimals, is right; each turned by 0.3 degrees more is wrong; each transposed or
    negated is wrong with its slip named."""
    s, members = _rotation_box(seed)
    ia = np.array(s.data["I_A"].tolist(), dtype=float)
    ib = np.array(s.data["I_B"].tolist(), dtype=float)
    rng = np.random.default_rng(0 if seed is None else seed)
    assert len(members) == 4
    for r in members:
        assert np.allclose(r @ ia @ r.T, ib) and np.isclose(np.linalg.det(r), 1)
        g = grade(s, {"Q_B_A": np.round(r, 4).tolist()}, replay=False)
        assert next(x for x in g if x.name == "Q_B_A").correct is True
        off = _turn(rng.normal(size=3), math.radians(0.3)) @ r
        g = next(x for x in grade(s, {"Q_B_A": off.tolist()}, replay=False)
                 if x.name == "Q_B_A")
        assert g.correct is False
        for word, wrong in (("transpose", r.T), ("sign", -r)):
            if any(np.allclose(wrong, m, atol=1e-3) for m in members):
                continue
            g = next(x for x in grade(s, {"Q_B_A": wrong.tolist()}, replay=False)
                     if x.name == "Q_B_A")
            assert g.correct is False and g.slip == word, (word, g.detail)


@pytest.mark.slow
@given(seed=st.integers(0, 10_000), which=st.integers(0, 3),
       axis=st.lists(st.floats(-1, 1), min_size=3, max_size=3).filter(
           lambda v: np.linalg.norm(v) > 0.1),
       angle=st.floats(0.1, 20))
@settings(max_examples=examples(30), deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))
def test_rotation_box_on_exam_draws(seed, which, axis, angle):
    """On exams' draws: a member of the class is right; the member turned by more than
    the tolerance allows (0.1 to 20 degrees about any axis) is wrong."""
    s, members = _rotation_box(seed)
    r = members[which]
    assert next(x for x in grade(s, {"Q_B_A": np.round(r, 5).tolist()}, replay=False)
                if x.name == "Q_B_A").correct is True
    off = _turn(axis, math.radians(angle)) @ r
    if any(np.all(np.abs(off - m) <= RTOL + 1e-12) for m in members):
        return                              # a turn so small it stays within tolerance
    assert next(x for x in grade(s, {"Q_B_A": off.tolist()}, replay=False)
                if x.name == "Q_B_A").correct is False


@pytest.mark.parametrize("text", ["0 m, 0 m, {z} m", "0 mm, 0 mm, {mm} mm",
                                  "0 cm; 0 cm; {cm} cm", "0, 0, {z} m"])
def test_a_zero_coordinate_with_its_unit(text):
    """A vector typed with a unit on every entry, zeros included, is read entry by
    entry: 3.11's centroid [0, 0, h/2] in m, mm or cm."""
    s, key = key_of("ex3.11")
    c = key["centroid_m"][0].reshape(-1)
    assert c[0] == 0 and c[1] == 0
    z = float(c[2])
    answer = text.format(z=repr(z), mm=repr(z * 1000), cm=repr(z * 100))
    g = next(x for x in grade(s, {"centroid_m": answer}, replay=False)
             if x.name == "centroid_m")
    assert g.correct is True, g.detail
