"""The regimes of the accuracy harness: :mod:`rigidsym.codegen.accuracy.regimes` (issue 37 item 2:
the code generator chooses its forms over the same regimes)."""

from rigidsym.codegen.accuracy.regimes import (  # noqa: F401
    STEPS,
    STEPS32,
    q,
    regimes,
    rotation,
    unit,
)
