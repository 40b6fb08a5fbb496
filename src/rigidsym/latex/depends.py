"""What a reader's expression mentions, directly and through the ``--let`` models of the
names it mentions: the dependency a model must have on an argument for ``R(\\theta)``
to be an application (:mod:`rigidsym.latex.guards`, :mod:`rigidsym.latex.transformer.meanings`)."""

from __future__ import annotations

import sympy as sp

__all__: list[str] = []


def names(x) -> set[str]:
    """The names of the symbols and matrix symbols in ``x`` (none for a non-sympy value)."""
    return {s.name for s in x.atoms(sp.Symbol, sp.MatrixSymbol)} \
        if isinstance(x, sp.Basic) else set()


def through(model, models: dict) -> set[str]:
    """The names a model mentions, through the models of the names it mentions (``R_3``
    written with ``c_\\psi``, ``c_\\psi = \\cos\\psi``, depends on ψ)."""
    seen: set[str] = set()
    todo = [model]
    while todo:
        for n in names(todo.pop()) - seen:
            seen.add(n)
            if n in models:
                todo.append(models[n])
    return seen
