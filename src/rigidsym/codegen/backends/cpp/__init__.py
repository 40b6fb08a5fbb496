"""The C++ layer over the C-only target (``rigidsym generate --target cpp``): see
:mod:`.target`."""

from rigidsym.codegen.backends import register
from rigidsym.codegen.backends.cpp.target import TARGET, generate_cpp

register(TARGET)

__all__ = ["generate_cpp"]
