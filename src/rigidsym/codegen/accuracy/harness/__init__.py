"""rigidsym.codegen.accuracy.harness: the one search and the one judge of accuracy, which
``benchmarks/accuracy.py`` (every kernel), the project's accuracy tests and ``rigidsym
audit`` (any user's function) share.

- ``reference``: the declared formula in ball arithmetic (the truth, to 1e-3 ulp of float64)
  and the problem's condition number.
- ``compare``: the distance the rule reads (the sign of e near pi forgiven), the truth at
  the input as rounded.
- ``yardsticks``: the textbook formula and the installed peers at the judged points.
- ``cloud``: the reference half decided over neighbouring inputs.
- ``judge``: rows of the rule per kernel, type, back-end and regime; the sweep.
- ``search``: exponent-uniform starts and hill climbing on the rule's ratio.
"""
