"""The NumPy target (:mod:`.target`): the Python package's NumPy kernels and Python files."""

from rigidsym.codegen.backends import register
from rigidsym.codegen.backends.numpy.target import TARGET

register(TARGET)
