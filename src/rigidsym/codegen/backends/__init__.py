"""Output targets of the code generator, one folder per language (as SymForce's
``codegen/backends/<lang>/``): each holds its printer and its templates.

Every template of the generator lives here, in its language's ``templates/`` folder:

* ``c/templates/``: the C target (:mod:`.c`, written by ``rigidsym generate --target c``: C99
  for C and C++ projects, firmware included, with no Python at build or run time) and, named
  ``c_*.j2``, the C of the Python package's extension module (``generated/c/``);
* ``python/templates/``: the Python package's own files (``generated/numpy/``, ``torch/``,
  ``jax/``, ``api.py``, ``__init__.py``).

The Python package's outputs are still rendered by :mod:`rigidsym.codegen.generator`, whose
Jinja2 loader searches both folders (:data:`rigidsym.codegen.generator.TEMPLATES`); the
generated files name their template by its file name alone.
"""
