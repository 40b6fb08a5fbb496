"""A second semantics of a reader's LaTeX: the lark parse tree and the ``--let``
declarations, given as plain data, evaluated numerically with mpmath at random points of
the declared kinds. It shares no code with the symbolic reader (``rigidsym.latex``) past the
parse tree: its own scope and function application, matrix algebra, operators, derivatives,
shapes and sampler. An import-linter contract (``pyproject.toml``) lets it import lark,
mpmath and the standard library only.

Modules: :mod:`~rigidsym.numeval.sampler` (points of each kind), :mod:`~rigidsym.numeval.
values` (matrix algebra and the operators on mpmath values), :mod:`~rigidsym.numeval.
evaluator` (the tree walk, scope, and the residual of each relation).
"""

from rigidsym.numeval.evaluator import Decl, NotCovered, Residual
from rigidsym.numeval.random_points import residuals

__all__ = ["Decl", "NotCovered", "Residual", "residuals"]
