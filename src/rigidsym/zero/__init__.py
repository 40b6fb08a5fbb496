"""The zero test: parametrisation plan (plan), straight-line programs (program), exact
evaluation (exact), the sound decision (decide), roots and signs (roots, signs), and
``sympy.cancel`` through FLINT for the derivations (cancel).

:func:`decide_zero` is the entry point; see :mod:`rigidsym.zero.decide`.
"""

from rigidsym.zero.decide import Unsupported, decide_zero, evaluate, make_plan

__all__ = ["Unsupported", "decide_zero", "evaluate", "make_plan"]
