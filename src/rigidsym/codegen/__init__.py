"""Code generation: kernels from the verified declarations, printed to NumPy, C, PyTorch, JAX.

Layers: :mod:`.spec` (kernel types), :mod:`.validate` (a user's declarations checked),
:mod:`.optimise` (rewrites, CSE, op count, the trig split), :mod:`.removable` (removable
singularities as series), :mod:`.accuracy` (accurate forms chosen by measured error,
float32 plans), :mod:`.derivatives` (Jacobian kernels, forward and reverse mode over a
program), :mod:`.backends` (the targets: printers, templates, renderers),
:mod:`.generator` (compile, render every target, check), :mod:`.files` and :mod:`.inputs`
(``generated/`` on disk and what made it), :mod:`.usergen` (the commands that write a
folder of the user's: ``--module``, ``--target c``).
"""
