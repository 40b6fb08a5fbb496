"""Neighbours' answer keys differ: in a class of 24 on the quiz 3.5, 3.9, 3.16, 3.20 (the
students drawn one after another from their own seeds, as ``rigidsym exam --students``
draws them), at most 20 % of the students share a problem's exact answer (every box of it)
with another student. The proofs' true-or-false variants list their reasons in a drawn
order, and a class draws a student's variant again while its answers repeat another's.
"""

from __future__ import annotations

import collections

from rigidsym.course.exam import drawn_exercises, read_spec
from rigidsym.course.roster import student_seed

_SPEC = {"seed": 11, "problem": [{"exercise": e, "variants": 1}
                                  for e in ("3.5", "3.9", "3.16", "3.20")]}


def _shared(n: int) -> dict[str, int]:
    spec = read_spec(_SPEC)
    taken: dict = {}
    keys = collections.defaultdict(list)
    for i in range(n):
        for s, _ in drawn_exercises(spec, student_seed(11, f"Student {i}"), taken):
            keys[s.id].append(repr(sorted((a, str(v)) for a, v in s.answers.items())))
    return {ex: sum(c[x] > 1 for x in xs) for ex, xs in keys.items()
            for c in [collections.Counter(xs)]}


def test_at_most_a_fifth_of_a_class_of_24_share_an_answer():
    shared = _shared(24)
    print("students sharing a problem's exact answer with another, of 24:", shared)
    assert all(v <= 0.2 * 24 for v in shared.values()), shared
