"""The C++ target's printer: the C target's double printer.

The C++ layer prints no kernel program (its functions call the C target's, which hold the
programs); a :class:`rigidsym.codegen.backends.Target` names a printer all the same, and
this is the one a program in the layer would be printed with (C99 on ``double`` is C++).
"""

from __future__ import annotations

from rigidsym.codegen.backends.c.printer import DoublePrinter

__all__ = ["CppPrinter"]


class CppPrinter(DoublePrinter):
    """C++ printer of kernel programs (the C target's double printer)."""
