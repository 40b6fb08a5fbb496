"""Output targets of the code generator, one folder per language (as SymForce's
``codegen/backends/<lang>/``): each holds its printer and its templates.

The Python package's own outputs (NumPy, the C of the extension module, PyTorch, JAX) are
still rendered by :mod:`rigidsym.codegen.generator` from ``codegen/templates/``; the
targets here are written by ``rigidsym generate --target <name>``:

* :mod:`.c`: C99 for C and C++ projects (firmware), with no Python at build or run time.
"""
