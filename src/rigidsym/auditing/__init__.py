"""rigidsym.auditing: audit any implementation of an operation of the chapter against the
book (``rigidsym audit``, :func:`rigidsym.audit`).

- ``targets``: the operations a function can be audited as, their argument layouts.
- ``conventions``: the convention generators, the finder over their product, the invariants.
- ``equivalence``: the outputs that denote the same rotation, judged as one answer.
- ``worst``: the singular sets, the worst-input search and the judge on the user's function
  (the accuracy harness of :mod:`rigidsym.codegen.accuracy.harness`).
- ``windows``: each approach to a singular set searched continuously, the window of error
  located, its cause as measured.
- ``gradients``: the derivative of a JAX or PyTorch function against the book's.
- ``callables``: a ``module:function``, a method or chain (``mod:Rot(matrix=...).log``,
  ``mod:lambda Q: ...``) or a C symbol (ctypes) as a callable.
- ``audit``: :func:`audit` and its :class:`AuditReport`.
- ``report``: the report as text, JSON, Markdown and a pytest regression file.
"""
