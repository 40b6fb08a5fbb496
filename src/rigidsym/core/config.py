"""Where the machinery finds the book and the generated kernels, by name, never statically.

The machinery (``check``, ``codegen``, ``cli``, ``exercises``) knows no particular equation;
it reaches the chapter's declarations, kernel declarations and worked exercises through
these dotted names (``importlib.import_module``), so that the layers below the book never
import it and another book could be configured in its place. The generated kernels are
found the same way (:func:`generated_dir`), by the code generator and the kernels alike.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

#: the package whose import registers every numbered equation of the chapter
BOOK = "rigidsym.derivations"
#: the module whose ``KERNELS`` list declares the package's kernels
KERNEL_SPEC = "rigidsym.derivations.kernels_spec"
#: the package of worked exercises (modules ``ex3_NN``)
EXERCISES = "rigidsym.derivations.exercises"
#: the package of generated kernels (the folder ``generated/`` of a checkout)
GENERATED = "rigidsym.generated"


def generated_dir() -> Path:
    """The folder of the package's generated kernels: ``generated/`` of a checkout (an
    editable install), or ``rigidsym/generated`` inside an installed package.

    Raises:
        FileNotFoundError: it holds no ``kernels.json`` (run ``rigidsym generate``).
    """
    spec = importlib.util.find_spec(GENERATED)
    where = Path(spec.origin).resolve().parent if spec is not None and spec.origin else None
    if where is None or not (where / "kernels.json").is_file():
        raise FileNotFoundError("generated kernels not found; run `rigidsym generate`")
    return where
