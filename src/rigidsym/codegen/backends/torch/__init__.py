"""The PyTorch target (:mod:`.target`): the kernels' programs for PyTorch."""

from rigidsym.codegen.backends import register
from rigidsym.codegen.backends.torch.target import TARGET

register(TARGET)
