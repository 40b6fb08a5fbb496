"""Slips made along the way: the solution replayed with one common slip
injected into its data, as STACK's potential-response trees name a student's mistake.

A slip in a step is a slip in what that step reads: ``Q`` used for ``Q^T`` is the solution
on ``Q^T``; an offset typed in mm is the solution on the offset times 1000; a frame
swapped is the solution on the two frames' readings exchanged. Each candidate is derived
from the exercise's declared parameters (:class:`~.worked.params.Param`: shape and unit),
so every exercise with data gets them; an exercise module may add its own steps' slips
with ``step_slips(solution) -> [(word, detail, data), ...]``. The replay is the exact
solution on the slipped data (:func:`rigidsym.course.worked.solve`, cached), or, for the
values the grader and the STACK export compare, the solution for its values only
(:func:`rigidsym.course.worked.solve_values`: the exercise's solver on 50-digit floating
data where it allows it, the exact solution where a decision is too close to call); only
data on which it is solved count: a slip that makes the exercise ill-posed reproduces no
answer.

The grader tries the slips of the final answer first (a transposed answer, degrees, a
power of ten), then these, in the order of :func:`data_slips`, and names the first whose
answer matches.
"""

from __future__ import annotations

import re

import sympy as sp

__all__ = ["data_slips", "replays", "slip_list"]

_LENGTH = ("m",)
_FRAME = re.compile(r"^(.*)_(1|2|A|B|S)$")


def _is_rotation(v, every: bool) -> bool:
    """A rotation whose transpose differs from it (``every``: any 3 x 3 datum, to list)."""
    if not isinstance(v, sp.MatrixBase) or v.shape != (3, 3):
        return False
    return every or ((v.T * v - sp.eye(3)).is_zero_matrix is True and v != v.T)


def data_slips(ex_id: str, data: dict, every: bool = False) -> list[tuple[str, str, dict]]:
    """The slips injected into the data of ``ex_id``: ``[(word, detail, slipped data)]``.

    In order: each rotation used for its transpose (``"transpose"``: ``Q`` for ``Q^T``);
    each length typed in mm or cm (``"unit"``: the datum times 1000 or 100); each
    vector's sign (``"sign"``: the reading or offset negated, as a cross product taken in
    the other order); the readings of two frames exchanged (``"frame"``: ``n_1, f_1`` for
    ``n_2, f_2``). ``every``: each 3 x 3 datum with a unit-free meaning is listed as a
    rotation, whatever its value (the docs' list, on the book's data).
    """
    from rigidsym.course.worked import parameters

    params = [p for p in parameters(ex_id) if p.name in data]
    out = []
    for p in params:
        if not p.unit and _is_rotation(data[p.name], every):
            out.append(("transpose", f"{p.name} used for {p.name}^T along the way (the "
                        f"rotation inverted)", {**data, p.name: data[p.name].T}))
    for p in params:
        if p.unit in _LENGTH:
            for k, unit in ((1000, "mm"), (100, "cm")):
                out.append(("unit", f"{p.name} typed in {unit} for m along the way",
                            {**data, p.name: data[p.name] * k}))
    for p in params:
        v = data[p.name]
        if isinstance(v, sp.MatrixBase) and v.cols == 1 and not v.is_zero_matrix:
            out.append(("sign", f"the sign of {p.name} along the way (-{p.name}: a cross "
                        f"product in the other order)", {**data, p.name: -v}))
    frames: dict[str, dict[str, str]] = {}
    for p in params:
        m = _FRAME.match(p.name)
        if m and ("frame" in p.meaning or "observer" in p.meaning):
            frames.setdefault(m.group(2), {})[m.group(1)] = p.name
    tags = sorted(frames)
    for i, a in enumerate(tags):
        for b in tags[i + 1:]:
            common = sorted(set(frames[a]) & set(frames[b]))
            if common:
                swapped = dict(data)
                for stem in common:
                    swapped[frames[a][stem]] = data[frames[b][stem]]
                    swapped[frames[b][stem]] = data[frames[a][stem]]
                out.append(("frame", f"frames {a} and {b} swapped along the way ("
                            + ", ".join(f"{frames[a][c]} for {frames[b][c]}" for c in common)
                            + ")", swapped))
    return out


def replays(solution, values: bool = False, compare=None):
    """The answers of ``solution``'s exercise replayed with each slip: yields
    ``(word, detail, answers)`` for each slip of :func:`data_slips` and the exercise's
    ``step_slips`` on which the exercise is solved (lazily: a replay is a solve).

    ``values``: each replay for its answers' values only
    (:func:`rigidsym.course.worked.solve_values`: floating where the exercise allows it,
    exact otherwise); else the exact solve (:func:`rigidsym.course.worked.solve`, cached).
    ``compare``: a function of a replay's solution, yielded in place of its answers
    (:func:`rigidsym.course.grading.compared_answers`: each answer as the grader compares
    it)."""
    from rigidsym.course.worked import TooLong, exercise_module, solve, solve_values

    if not solution.data:
        return
    own = getattr(exercise_module(solution.id), "step_slips", None)
    slips = data_slips(solution.id, solution.data) + (list(own(solution)) if own else [])
    tol = {"tol": solution.tol} if solution.tol is not None else {}
    for word, detail, data in slips:
        try:
            s = (solve_values if values else solve)(solution.id, **tol, **data)
        except (ValueError, TypeError, TooLong):
            continue                      # data a slip put out of reach: no replay
        if s.status == "solved":
            yield word, detail, (compare(s) if compare is not None else s.answers)


def slip_list(ex_id: str) -> str:
    """The slips the grader tries for ``ex_id`` beyond the final answer's edits, in one
    line (the docs' table): the data slips of :func:`data_slips` on the book's data, grouped
    by word, then the exercise's own (its module's ``slips``), or "-"."""
    from rigidsym.course.worked import exercise_module, parameters, solve

    data = {k: sp.Matrix(v) if isinstance(v, sp.MatrixBase) else v
            for k, v in parameters(ex_id).defaults().items()}
    groups: dict[str, list[str]] = {}
    for word, detail, _ in data_slips(ex_id, data, every=True):
        cut = {"transpose": (" along", 0), "unit": (" typed", 0),
               "sign": (" along", 0), "frame": (" swapped", 0)}[word][0]
        what = detail.split(cut)[0].removeprefix("the sign of ")
        if what not in groups.setdefault(word, []):
            groups[word].append(what)
    words = {"transpose": "transpose", "unit": "unit (mm, cm for m)", "sign": "sign",
             "frame": "frame"}
    parts = [f"{words[w]}: {', '.join(v)}" for w, v in groups.items()]
    own = getattr(exercise_module(ex_id), "slips", None)
    if own:
        found = []
        for items in own(solve(ex_id)).values():
            for w, d, _ in items:
                if f"{w}: {d}" not in found:
                    found.append(f"{w}: {d}")
        parts.append("its own: " + "; ".join(found))
    return "; ".join(parts) or "-"
