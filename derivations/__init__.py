"""The mathematics of Angeles' chapter 3, one module per book section, in book order.

Importing this package registers every declaration in :data:`rigidsym.registry.REGISTRY`.
"""

from . import sec3_2  # noqa: F401
