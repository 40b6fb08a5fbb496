"""Code generation: kernels from the verified declarations, printed to NumPy and C.

Layers: :mod:`.spec` (kernel types), :mod:`.optimise` (rewrites, CSE, op count),
:mod:`.printers` (sympy printer subclasses), :mod:`.generator` (templates, files, check),
:mod:`.cli` (commands).
"""
