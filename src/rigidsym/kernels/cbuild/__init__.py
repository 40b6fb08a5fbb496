"""The C build of the kernels: a generated directory's ``c/`` into the extension module
``rigidsym.kernels._ckernels``. Nothing is imported here: ``setup.py`` loads the driver by
path before rigidsym is importable, and the driver loads its siblings by path then.

- ``driver``: the compiler driver, used by ``setup.py`` and at run time, with the same flags.
- ``flags``: the compiler flags, and the refusal of flags that would make the kernels wrong.
- ``paths``: the build paths (CPU levels) and which kernels each compiles.
- ``objects``: the compiled-object cache a second build reuses.
- ``extension``: find, check and load the compiled module; build it into the user cache.
"""
