"""What the PyTorch and JAX back-ends (:mod:`rigidsym.kernels.torch`, :mod:`rigidsym.kernels.jax`)
share, and what only PyTorch needs. Nothing is imported here.

- ``evaluation``: the generated programs of a directory, their evaluation on arrays, and the
  checked call both back-ends share (:class:`Space`, :class:`Library`).
- ``inputs``: the input rules: keyword modes, conversion, validation, broadcast, safe point.
- ``namespace``: a back-end module's public face: the kernels' functions, ``load``, the
  Euler-angle kernels.
- ``rescue``: finite in, finite out: the eager rescue of flagged samples, the traced NaN rule.
- ``torch_compiled``: the PyTorch kernels' functions under ``torch.compile``.
- ``torch_host``: the eager CPU route of the PyTorch kernels' value and gradient.
"""
