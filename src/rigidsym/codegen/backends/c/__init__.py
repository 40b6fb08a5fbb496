"""The C-only target (``rigidsym generate --target c``): see :mod:`.target`."""

from pathlib import Path

from rigidsym.codegen.backends import register
from rigidsym.codegen.backends.c.target import TARGET, generate_c

register(TARGET)

#: the Linux system calls newlib needs, for a Cortex-M4F build run under ``qemu-arm``'s user
#: mode (docs/c-api.md, "float and double": the command); a C file shipped with the package
M4F_SHIM = Path(__file__).parent / "m4f_qemu_shim.c"

__all__ = ["generate_c", "M4F_SHIM"]
