"""The kernels' own exceptions (bad input raises the built-in ``TypeError``/``ValueError``)."""

from __future__ import annotations

import numpy as np

__all__ = ["SingularConfigurationError", "NonFiniteResultError", "BroadcastWarning",
           "at_batch_indices"]


class BroadcastWarning(UserWarning):
    """Two arguments' different batch shapes broadcast into a new batch axis (``e`` of shape
    (5, 3) and ``phi`` of shape (5, 1) give (5, 5, 3, 3): 25 samples from 5 and 5), which
    NumPy does silently and which is most often a mistake (``phi`` meant as (5,)). The
    result is NumPy's broadcast, unchanged; broadcast the arguments explicitly
    (``np.broadcast_to``) to say it is meant, or make it an error with
    ``warnings.simplefilter("error", BroadcastWarning)``.

    Args:
        message: the arguments, their shapes and the batch shape they broadcast to.
    """


def at_batch_indices(w: list, more: bool) -> str:
    """`` at batch indices [(0,), (3,)]`` for an error message, ``""`` for an unbatched call
    (its only index is ``()``: nothing to locate).

    Args:
        w: the batch indices (tuples) of the flagged samples, the first 20.
        more: whether there are more than those.

    Returns:
        str: the clause, with a leading space, or an empty string.
    """
    if not w or w == [()]:
        return ""
    return f" at batch indices {w}{' ...' if more else ''}"


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
            f"in argument {arg!r}{at_batch_indices(w, s.sum() > 20)}",
            arg, w)
    f = np.asarray(nonfinite)
    if f.any():
        w = [tuple(int(i) for i in t) for t in np.argwhere(f)[:20]]
        mags = [float(np.abs(np.asarray(x)).max()) if x.size else 0.0 for x in arrays]
        k = int(np.argmax(mags))
        arg = meta["args"][k]["name"]
        raise NonFiniteResultError(
            f"{name}: non-finite output (overflow) from finite inputs"
            f"{at_batch_indices(w, f.sum() > 20)}; largest input there: {arg!r} "
            f"(max |{arg}| = {mags[k]:.3g})", arg, w)


# the public module re-exports them: a traceback names them as a user imports them
# (``rigidsym.kernels.SingularConfigurationError``), and pickles find them there
for _cls in (BroadcastWarning, SingularConfigurationError, NonFiniteResultError):
    _cls.__module__ = "rigidsym.kernels"
del _cls
