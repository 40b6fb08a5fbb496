"""Where the machinery finds the book: module names, imported by name, never statically.

The machinery (``check``, ``codegen``, ``cli``, ``exercises``) knows no particular equation;
it reaches the chapter's declarations, kernel declarations and worked exercises through
these dotted names (``importlib.import_module``), so that the layers below the book never
import it and another book could be configured in its place.
"""

from __future__ import annotations

#: the package whose import registers every numbered equation of the chapter
BOOK = "rigidsym.derivations"
#: the module whose ``KERNELS`` list declares the package's kernels
KERNEL_SPEC = "rigidsym.derivations.kernels_spec"
#: the package of worked exercises (modules ``ex3_NN``)
EXERCISES = "rigidsym.derivations.exercises"
