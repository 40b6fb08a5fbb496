"""The C-only target (``rigidsym generate --target c``): see :mod:`.target`."""

from rigidsym.codegen.backends import register
from rigidsym.codegen.backends.c.target import TARGET, generate_c

register(TARGET)

__all__ = ["generate_c"]
