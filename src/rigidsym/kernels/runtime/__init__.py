"""The NumPy/C runtime of the kernels: the checked evaluation behind :mod:`rigidsym.kernels`.
No symbolic layer, no sympy; nothing is imported here (the package's ``__init__`` re-exports).

- ``namespace``: :func:`~rigidsym.kernels.load`, the binding of a generated ``api`` module and
  the publishing of the package's kernels as :mod:`rigidsym.kernels`'.
- ``backends``: the C or NumPy back-end in use, the build of the C, a kernel's batch function.
- ``accuracy``: the measured accuracy of a kernel, read from ``kernels.json``.
- ``euler``: the Euler-angle rate matrix and rates of any sequence (Exercise 3.10).
- ``block_order``: twists and wrenches between ``[omega; v]`` and ``[v; omega]`` order.
- ``space``: the checked evaluation of one generated directory (:class:`KernelSpace`).
- ``entries``: the per-call entry points the generated ``api.py`` functions call.
- ``inputs``: the checks of a call's inputs (keywords, shapes, constraints, broadcasting).
- ``names``: the checks of the helpers' non-array arguments (kernel name, directory, flag).
- ``errors``: the kernels' exceptions, and the report of flagged samples.
- ``rescue``: the samples a kernel cannot compute in its type, re-run in a wider one.
- ``scale``: thread count, the dtype of a call, float32 over the NumPy kernels.
- ``state``: the global state (back-end choice, the package's kernel space, the lock).
- ``jacobians``: ``kernels.jacobian(name)``, from the generated Jacobian kernels.
- ``dask_arrays``: Dask arrays in, lazy Dask arrays out.
"""
