"""The extension target (:mod:`.target`): the C of the Python package's extension module."""

from rigidsym.codegen.backends import register
from rigidsym.codegen.backends.extension.target import TARGET

register(TARGET)
