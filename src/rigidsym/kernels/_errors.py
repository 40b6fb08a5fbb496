"""The kernels' own exceptions (bad input raises the built-in ``TypeError``/``ValueError``)."""

from __future__ import annotations

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
