"""The zero test: parametrisation plan, exact evaluation and the sound decision.

:func:`decide_zero` is the entry point; see :mod:`rigidsym.zero.decide`.
"""

from rigidsym.zero.decide import Unsupported, decide_zero, evaluate, make_plan

__all__ = ["Unsupported", "decide_zero", "evaluate", "make_plan"]
