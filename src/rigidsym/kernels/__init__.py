"""Batched NumPy/C kernels generated from the verified chapter-3 declarations.

Every kernel accepts array-likes with leading batch axes that broadcast (vectors
``(..., 3)``, matrices ``(..., 3, 3)`` row-major, twists ``[omega; v]``, wrenches ``[n; f]``,
float64; ints are converted), positionally or by keyword, validates them, calls the
generated code and returns new arrays (or fills ``out=``). The kernels are real functions
generated into ``generated/api.py`` (``rigidsym generate``), with type hints; the C is
compiled when the package is built, into an extension module with one path per CPU level
(x86-64-v2, x86-64-v3) chosen at import (:func:`build_info`). A user's kernels and a stale
editable build are compiled into the user cache, with a notice (``rigidsym build-c``).

Common keyword arguments of every kernel
(``rigidsym.codegen.backends.numpy.api_spec.COMMON_KEYWORDS``):

* ``out``: preallocated output array (a tuple for several outputs), shape batch + output.
* ``check``: validate finiteness, unit vectors and rotations (default True); ``False``
  skips only that: on valid input the same result (an overflow of the result is still
  reported), a NaN or inf input gives NaN in the outputs that depend on it.
* ``on_singular``: ``"raise"`` (default) raises :class:`SingularConfigurationError` naming
  the argument and the batch indices (:class:`NonFiniteResultError` for an overflow);
  ``"nan"`` returns NaN in exactly those rows.
* ``threads``: worker threads of the C batch loop (a positive int, or None).

Bad input raises ``TypeError`` (str, objects, complex or bool values) or ``ValueError``
(shape, broadcasting, ragged lists, non-finite values, constraints), naming the argument.

:func:`load` builds the same namespace from any generated directory
(``rigidsym generate --out DIR``); this module's kernels are ``load()`` of the package's.

Example:
    >>> import numpy as np
    >>> from rigidsym import kernels
    >>> Q = kernels.rotation_from_natural_invariants(e=[0.0, 0.0, 1.0], phi=np.pi / 2)
    >>> Q.shape
    (3, 3)
    >>> bool(np.allclose(Q, [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=1e-15))
    True
"""

from __future__ import annotations

from rigidsym.generated.api import *  # noqa: F403 - the generated kernels (true signatures)
from rigidsym.generated.api import __all__ as _KERNELS
from rigidsym.kernels.runtime import state as _state  # noqa: F401 - kernels._state: the state
from rigidsym.kernels.runtime.accuracy import accuracy
from rigidsym.kernels.runtime.backends import backend, batch_function, build_info, use_backend
from rigidsym.kernels.runtime.block_order import swap_blocks
from rigidsym.kernels.runtime.errors import (
    BroadcastWarning,
    NonFiniteResultError,
    SingularConfigurationError,
)
from rigidsym.kernels.runtime.euler import (
    euler_angle_rates,
    euler_angles_from_rotation,
    euler_rate_matrix,
)
from rigidsym.kernels.runtime.inputs import ORTHO_TOL as ORTHO_TOL  # the tolerances of check=True
from rigidsym.kernels.runtime.inputs import UNIT_TOL as UNIT_TOL
from rigidsym.kernels.runtime.jacobians import jacobian
from rigidsym.kernels.runtime.namespace import KERNEL_NAMES as KERNEL_NAMES  # their names
from rigidsym.kernels.runtime.namespace import load
from rigidsym.kernels.runtime.outpool import release_output_pool, set_output_pool
from rigidsym.kernels.runtime.scale import get_num_threads as get_num_threads
from rigidsym.kernels.runtime.scale import set_num_threads as set_num_threads

__all__ = ["SingularConfigurationError", "NonFiniteResultError", "BroadcastWarning", "use_backend",
           "backend",
           "swap_blocks", "load", "batch_function", "euler_rate_matrix", "euler_angle_rates",
           "euler_angles_from_rotation",
           "jacobian", "set_num_threads", "get_num_threads", "build_info", "accuracy",
           "set_output_pool", "release_output_pool"]
__all__ += _KERNELS
