"""The C-only target (``rigidsym generate --target c``): see :mod:`.target`."""

from rigidsym.codegen.backends.c.target import generate_c

__all__ = ["generate_c"]
