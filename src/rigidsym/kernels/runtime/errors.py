"""The kernels' own exceptions (bad input raises the built-in ``TypeError``/``ValueError``)."""

from __future__ import annotations

import numpy as np

__all__ = ["SingularConfigurationError", "NonFiniteResultError"]


class SingularConfigurationError(ValueError):
    """The kernel is evaluated on its singular set (division by an exact zero).

    Attributes:
        argument: the argument that makes the configuration singular.
        indices: the batch indices (tuples over the batch shape) of the singular samples.
    """

    def __init__(self, message: str, argument: str, indices: list):
        super().__init__(message)
        self.argument = argument
        self.indices = indices

    def __reduce__(self):
        # pickled with its fields (distributed re-raises a worker's error on the client)
        return (type(self), (str(self), self.argument, self.indices))


class NonFiniteResultError(SingularConfigurationError):
    """Finite inputs gave a non-finite output (overflow): reported with ``check=True``.

    Attributes:
        argument: the input of largest magnitude in the offending samples.
        indices: the batch indices (tuples over the batch shape) of those samples.
    """


def raise_flagged(name: str, meta: dict, sing, nonfinite, arrays: list) -> None:
    """Eager ``on_singular="raise"``: the kernels' errors, with the batch indices.

    ``sing`` and ``nonfinite`` are boolean NumPy arrays of the batch shape; the caller
    copies them to the host only once a reduction on the device found a flagged sample
    (the error path), as it does ``arrays`` (the inputs, for the largest magnitude).
    """
    s = np.asarray(sing)
    if s.any():
        w = [tuple(int(i) for i in t) for t in np.argwhere(s)[:20]]
        arg = meta["singular_arg"] or meta["args"][0]["name"]
        raise SingularConfigurationError(
            f"{name}: singular configuration ({meta['singular'] or 'division by zero'}) "
            f"in argument {arg!r} at batch indices {w}{' ...' if s.sum() > 20 else ''}",
            arg, w)
    f = np.asarray(nonfinite)
    if f.any():
        w = [tuple(int(i) for i in t) for t in np.argwhere(f)[:20]]
        mags = [float(np.abs(np.asarray(x)).max()) if x.size else 0.0 for x in arrays]
        k = int(np.argmax(mags))
        arg = meta["args"][k]["name"]
        raise NonFiniteResultError(
            f"{name}: non-finite output (overflow) from finite inputs at batch indices {w}"
            f"{' ...' if f.sum() > 20 else ''}; largest input there: {arg!r} "
            f"(max |{arg}| = {mags[k]:.3g})", arg, w)
