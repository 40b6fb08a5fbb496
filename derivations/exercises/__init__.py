"""Worked solutions of Exercises 3.1-3.21 of Angeles' chapter 3, by computer algebra.

One module per exercise (``ex3_01`` ... ``ex3_21``), each exposing ``solve() -> Solution``;
the framework (steps, checks, rendering) is :mod:`rigidsym.course.worked` and the
``rigidsym exercise`` command is :mod:`rigidsym.cli.exercise`.
"""

from rigidsym.course.worked import EXERCISE_IDS, Solution, normalise_id, solve

__all__ = ["EXERCISE_IDS", "Solution", "normalise_id", "solve"]
