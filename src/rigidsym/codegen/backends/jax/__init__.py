"""The JAX target (:mod:`.target`): the kernels' programs for JAX."""

from rigidsym.codegen.backends import register
from rigidsym.codegen.backends.jax.target import TARGET

register(TARGET)
