"""What an answer *is*: the class of answers equal in meaning to the key's.

An exercise module declares, beside its ``ANSWER_UNITS``, what its answers are
(``ANSWER_CLASSES``, a tuple of dicts); an answer it does not list is a vector, a matrix or
a scalar with a unit, right only near the key's one value. The kinds:

``{"kind": "axis-angle", "axis": "e", "angle": "phi", "linked": ("plucker",)}``
    a rotation's axis and angle: (e, phi) is the rotation (-e, -phi), and phi + 2 pi k
    (Angeles, Sec. 2.3: the axis and angle of a rotation are defined up to these); the
    ``linked`` arrays (a Plücker array [e; n] of the same axis) change sign with e. The
    pieces are graded jointly: one sign s = +-1 for the whole group, the one under which
    most of the student's pieces are right.
``{"kind": "sign", "names": ("q",)}``
    defined up to one common sign (a unit quaternion: q and -q are one rotation).
``{"kind": "point of line", "point": "p_0", "direction": "e"}``
    any point of the line through the key's point along the key's direction.
``{"kind": "columns up to sign", "name": "axes"}``
    a matrix whose columns are lines (principal axes): each column up to its sign.
``{"kind": "angle", "name": "alpha", "period": "pi"}``
    an angle defined modulo ``pi`` (the angle of a line) or ``2 pi``.
``{"kind": "up to scale", "name": "L", "sign": "any" | "positive"}``
    an array defined up to a non-zero (or a positive) factor (a line's Plücker array
    when the problem fixes no normalisation).
``{"kind": "rotation onto", "name": "Q", "from": "I_A", "to": "I_B"}``
    any rotation Q with Q [from] Q^T = [to], two symmetric matrices of the exercise's data
    (two observers' inertia matrices): with eigenvectors V_A of [from], the rotations
    Q_key V_A D V_A^T for the four sign matrices D of determinant +1 (a principal axis has
    no sense); where two eigenvalues of [from] are equal the set is a continuum, and Q is
    a member when it is orthogonal, of determinant +1, and maps [from] onto [to].

:func:`judge` decides, for one declaration, which of the student's pieces are members of
the key's class (within the grader's tolerance) and which member each should be compared
with when a slip is looked for. It is the grader's; the tests generate the members
themselves, by the group action, and never call it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Verdict", "KINDS", "declared", "judge", "names_of", "data_names", "rotations_onto",
           "column_signs"]

KINDS = ("axis-angle", "sign", "point of line", "columns up to sign", "angle", "up to scale",
         "rotation onto")


@dataclass
class Verdict:
    """One piece of a declared answer, judged.

    Attributes:
        right: the student's value is a member of the key's class.
        note: the answer note of a right value (``"right"`` or ``"equivalent ..."``).
        target: the member to compare a wrong value with when looking for its slip (the
            key under the group's chosen sign), a float array of the key's shape.
        period: an angle's period (radians), compared modulo it; None otherwise.
        along: a line's unit direction, for a point of it; None otherwise.
        members: the class's other members, float arrays of the key's shape.
    """

    right: bool
    note: str
    target: np.ndarray
    period: float | None = None
    along: np.ndarray | None = None
    #: other members of the class a wrong value's slip is looked for against (after
    #: ``target``): a rotation class's other sign choices
    members: tuple = ()

    def matches(self, given: np.ndarray, value: np.ndarray, scale: float, rtol: float) -> bool:
        """``given`` is ``value`` within the tolerance, modulo the class's freedom that a
        slip keeps: an angle's period; for a point of a line, a shift along the line (a
        slip that scales the point scales the line through the key's point with it)."""
        t = self.target.reshape(-1)
        i = int(np.argmax(np.abs(t)))
        f = abs(float(value.reshape(-1)[i] / t[i])) if t.size and t[i] else 1.0
        if self.period is not None and f >= 0.5:
            # modulo the period scaled as the slip scaled the angle (degrees: 360; halved:
            # the halves of phi + 2 pi k are phi/2 + pi k); a slip that shrinks the angle
            # further (a power of ten down) is compared as it is
            w = _wrap(given - value, f * self.period)
            return _near(w, np.zeros_like(w), scale, rtol)
        if self.along is not None:
            off = (given - value).reshape(-1)
            return off.size == 3 and _near(np.cross(off, self.along), np.zeros(3), scale, rtol)
        return _near(given, value, scale, rtol)


def declared(module) -> list[dict]:
    """An exercise module's ``ANSWER_CLASSES`` (empty when it declares none).

    Raises:
        ValueError: a declaration of no known kind (the message lists :data:`KINDS`).
    """
    decls = list(getattr(module, "ANSWER_CLASSES", ()))
    for d in decls:
        if d.get("kind") not in KINDS:
            raise ValueError(f"ANSWER_CLASSES of {module.__name__}: kind {d.get('kind')!r} "
                             f"is not one of {', '.join(KINDS)}")
    return decls


def data_names(decl: dict) -> list[str]:
    """The exercise's data one declaration reads (its ``from`` and ``to`` matrices)."""
    return [decl["from"], decl["to"]] if decl["kind"] == "rotation onto" else []


def names_of(decl: dict) -> list[str]:
    """The answer names one declaration covers."""
    k = decl["kind"]
    if k == "axis-angle":
        return [decl["axis"], *([decl["angle"]] if decl.get("angle") else []),
                *decl.get("linked", ())]
    if k == "sign":
        return list(decl["names"])
    if k == "point of line":
        return [decl["point"]]
    return [decl["name"]]


def _scale(a: np.ndarray) -> float:
    return max(float(np.max(np.abs(a))) if a.size else 0.0, 1e-300)


def _near(a: np.ndarray, b: np.ndarray, scale: float, rtol: float) -> bool:
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= rtol * scale + 1e-12))


def _wrap(x: np.ndarray, period: float) -> np.ndarray:
    """``x`` reduced to ``[-period/2, period/2)``."""
    return (x + period / 2) % period - period / 2


def judge(decl: dict, given: dict, key: dict, rtol: float) -> dict[str, Verdict]:
    """The pieces of one declared answer judged: ``{name: Verdict}`` for each name of
    ``decl`` the student answered (``given[name]`` a float array of the key's shape;
    a blank piece is left out of ``given``).

    Args:
        decl: one entry of an exercise's ``ANSWER_CLASSES``.
        given: answer name -> the student's value (float array, reshaped as the key).
        key: answer name -> the key's value (float array); for a ``rotation onto``, the
            data it reads by their names as well (:func:`data_names`).
        rtol: the relative tolerance (of the largest entry of the key's value).
    """
    kind = decl["kind"]
    if kind in ("axis-angle", "sign"):
        return _sign_group(decl, given, key, rtol)
    name = names_of(decl)[0]
    if name not in given:
        return {}
    g, k = given[name], key[name]
    if kind == "rotation onto":
        return {name: _rotation_onto(g, k, key[decl["from"]], key[decl["to"]], rtol)}
    if kind == "point of line":
        d = key[decl["direction"]].reshape(-1)
        d = d / np.linalg.norm(d)
        off = (g - k).reshape(-1)
        ok = _near(np.cross(off, d), np.zeros(3), _scale(k) if _scale(k) > 1e-12 else 1.0,
                   rtol)
        moved = ok and not _near(g, k, _scale(k), rtol)
        return {name: Verdict(ok, "equivalent: another point of the axis" if moved
                              else "right", k, along=d)}
    if kind == "columns up to sign":
        # each column's sign by its projection on the key's: a slip that scales or
        # reorders the matrix is then looked for against the same member
        signs = np.array([-1.0 if float(g[:, j] @ k[:, j]) < 0 else 1.0
                          for j in range(k.shape[1])])
        target = k * signs
        ok = _near(g, target, _scale(k), rtol)
        if not ok:               # the axes written as rows: the slip is looked for there
            rows = np.array([-1.0 if float(g[j, :] @ k[:, j]) < 0 else 1.0
                             for j in range(k.shape[1])])
            if _near(g.T, k * rows, _scale(k), rtol):
                target = k * rows
        flipped = [j for j, s in enumerate(signs) if s < 0]
        note = f"equivalent: columns {flipped} negated" if ok and flipped else "right"
        others = tuple(m for m in column_signs(k) if not np.array_equal(m, target))
        return {name: Verdict(ok, note, target, members=others)}
    if kind == "angle":
        period = math.pi if decl.get("period") == "pi" else 2 * math.pi
        w = _wrap(g - k, period)
        ok = _near(w, np.zeros_like(w), _scale(k), rtol)
        turns = int(round(float((g - k - w).reshape(-1)[0]) / period))
        word = "pi" if period == math.pi else "2 pi"
        note = f"equivalent {name} + {word} k (k = {turns})" if ok and turns else "right"
        return {name: Verdict(ok, note, k + turns * period if ok else k, period=period)}
    # up to scale
    kk = float(np.vdot(k, k))
    lam = float(np.vdot(g, k)) / kk if kk else 0.0
    ok = abs(lam) > 1e-9 and (decl.get("sign") != "positive" or lam > 0) and \
        _near(g, lam * k, abs(lam) * _scale(k), rtol)
    note = f"equivalent: {name} scaled by {lam:.4g}" if ok and abs(lam - 1) > rtol \
        else "right"
    return {name: Verdict(ok, note, k)}


def _sign_group(decl: dict, given: dict, key: dict, rtol: float) -> dict[str, Verdict]:
    """Pieces that change sign together (and an angle with them, modulo 2 pi)."""
    angle = decl.get("angle")
    names = [n for n in names_of(decl) if n in given]
    best: tuple | None = None
    for s in (1.0, -1.0):
        out = {}
        for n in names:
            g, k = given[n], key[n]
            if n == angle:
                w = _wrap(g - s * k, 2 * math.pi)
                turns = int(round(float((g - s * k - w).reshape(-1)[0]) / (2 * math.pi)))
                ok = _near(w, np.zeros_like(w), _scale(k), rtol)
                # a wrong angle's slips are looked for against the key's own value
                out[n] = (ok, turns if ok else 0, s * k + 2 * math.pi * turns if ok else s * k)
            else:
                out[n] = (_near(g, s * k, _scale(k), rtol), 0, s * k)
        count = sum(v[0] for v in out.values())
        if best is None or count > best[0]:
            best = (count, s, out)
    if best is None:
        return {}
    _, s, out = best
    axis = decl.get("axis") or names_of(decl)[0]
    verdicts = {}
    for n, (ok, turns, target) in out.items():
        note = "right"
        if ok and s < 0:
            note = (f"equivalent (-{axis}, -{angle})" if angle else
                    f"equivalent: -{n} (the same {decl.get('what', 'answer')})")
        if ok and turns:
            note = (note + "," if note != "right" else "equivalent") + \
                f" {n} + 2 pi k (k = {turns})"
        verdicts[n] = Verdict(ok, note, target, period=2 * math.pi if n == angle else None)
    return verdicts


def column_signs(k: np.ndarray) -> list[np.ndarray]:
    """The members of a ``columns up to sign`` class: ``k`` with each column's sign
    chosen, every choice (``k`` first)."""
    n = k.shape[1]
    return [k * np.array([-1.0 if c >> j & 1 else 1.0 for j in range(n)])
            for c in range(2 ** n)]


#: the four sign matrices of determinant +1: a principal axis has no sense
_SIGNS = (np.diag([1.0, 1.0, 1.0]), np.diag([1.0, -1.0, -1.0]), np.diag([-1.0, 1.0, -1.0]),
          np.diag([-1.0, -1.0, 1.0]))


def rotations_onto(key_q: np.ndarray, source: np.ndarray) -> list[np.ndarray]:
    """The rotations ``key_q V D V^T`` (V: unit eigenvectors of the symmetric ``source``,
    D: the four sign matrices of determinant +1), each mapping ``source`` as ``key_q``
    does: ``Q source Q^T = key_q source key_q^T``; ``key_q`` first."""
    _, v = np.linalg.eigh((source + source.T) / 2)
    return [key_q @ v @ d @ v.T for d in _SIGNS]


def _rotation_onto(g: np.ndarray, k: np.ndarray, source: np.ndarray, image: np.ndarray,
                   rtol: float) -> Verdict:
    """A rotation judged by the property its box states: ``g source g^T = image``."""
    members = rotations_onto(k, source)
    dist = [float(np.max(np.abs(g - m))) for m in members]
    best = int(np.argmin(dist))
    ok = _near(g, members[best], 1.0, rtol)
    lam = np.linalg.eigvalsh((source + source.T) / 2)
    tied = float(np.min(np.diff(lam))) <= rtol * max(float(np.max(np.abs(lam))), 1e-300)
    if not ok and tied and g.shape == (3, 3):
        # a continuum of rotations: membership by the defining property itself
        ok = _near(g.T @ g, np.eye(3), 1.0, 2 * rtol) and np.linalg.det(g) > 0 and \
            _near(g @ source @ g.T, image, _scale(image), 3 * rtol)
    note = "right" if ok and best == 0 else \
        "equivalent: another rotation with Q [I]_A Q^T = [I]_B" if ok else "right"
    order = [best] + [i for i in range(len(members)) if i != best]
    return Verdict(bool(ok), note, members[best],
                   members=tuple(members[i] for i in order[1:]))
