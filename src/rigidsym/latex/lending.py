"""What a reader's modules lend to LaTeX read by ``rigidsym check --latex --module M`` and
to a module's own ``equation(..., latex=...)`` (issue 29, item 4): their symbols, by name,
and the first-principles models of those symbols."""

from __future__ import annotations

import sympy as sp

__all__ = ["lent", "module_symbols"]


def lent(modules) -> dict:
    """The symbols and models user modules lend, by name.

    A module's models are its module-level dicts whose keys are all book symbols (``MODEL``
    first, then in module order; the first value of a name wins); its symbols are those
    keys and its module-level symbols (a constrained atom such as ``angle("theta")`` lends
    itself as its model).

    Args:
        modules: paths, dotted names or module objects
            (:func:`rigidsym.registry.usermodules.load`).

    Returns:
        ``{name: (symbol, model value or None)}``.

    Raises:
        BadInput: a module that cannot be loaded.
    """
    import sys
    from types import ModuleType

    from rigidsym.registry import usermodules

    out: dict = {}
    for m in modules or ():
        um = usermodules.adopt(m) if isinstance(m, ModuleType) else usermodules.load(m)
        for name, v in module_symbols(vars(sys.modules[um.name])).items():
            out.setdefault(name, v)
    return out


def module_symbols(names: dict) -> dict:
    """What one module's namespace lends (see :func:`lent`): ``{name: (symbol, value)}``."""
    from rigidsym.algebra.symbols import constraint_of

    out: dict = {}
    dicts = [v for v in names.values() if isinstance(v, dict) and v and all(
        isinstance(k, sp.Symbol | sp.MatrixSymbol) for k in v)]
    if isinstance(names.get("MODEL"), dict) and names["MODEL"] in dicts:
        dicts.remove(names["MODEL"])
        dicts.insert(0, names["MODEL"])
    for d in dicts:
        for sym, value in d.items():
            out.setdefault(sym.name, (sym, value))
    for v in names.values():
        if isinstance(v, sp.MatrixSymbol) or (isinstance(v, sp.Symbol)
                                              and not isinstance(v, sp.Dummy)):
            out.setdefault(v.name, (v, v if constraint_of(v) is not None else None))
    return out
