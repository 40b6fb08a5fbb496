"""A user's kernel declarations checked before generation: errors a user
can act on, one line each, naming the module, the kernel and the symbol, and a warning for a
division by an argument that can vanish.

:func:`validate` builds each kernel once on its explicit symbols (as the generator will) and
turns what would otherwise surface deep in the generator as a long traceback (a Python
``NameError`` in a formula, a symbol that is not an argument, an output of the wrong shape)
into :class:`~rigidsym.registry.declarations.BadInput`; the CLI prints it and exits 2
before anything is written. A kernel that declares no singular set but divides by
something that can be zero (``v / r``) gets a warning and the set ``r = 0`` in its
declaration, so that ``kernels.json`` and the C headers record it.
"""

from __future__ import annotations

import dataclasses
import traceback
import warnings

import sympy as sp

from rigidsym.codegen.spec import Kernel, flatten_outputs, input_symbols
from rigidsym.registry.declarations import BadInput

__all__ = ["validate", "validate_all", "DivisionWarning", "one_line_warnings"]


class DivisionWarning(UserWarning):
    """A kernel divides by an expression of its arguments that can be zero and declares no
    singular set (the set is then recorded as that expression ``= 0``)."""


def _where(exc: BaseException) -> str:
    """``file:line`` of the innermost frame of ``exc`` (the user's formula)."""
    tb = traceback.extract_tb(exc.__traceback__)
    if not tb:
        return ""
    f = tb[-1]
    return f" ({f.filename.rsplit('/', 1)[-1]}:{f.lineno})"


def _build(kernel: Kernel, module: str, what: str, fn, syms: dict):
    head = f"module {module}, kernel {kernel.name}"
    try:
        return fn(**syms)
    except NameError as exc:
        name = getattr(exc, "name", None) or str(exc)
        raise BadInput(f"{head}: the {what} uses {name!r}, which is not defined "
                       f"(NameError{_where(exc)}); define it in the module or make it an "
                       f"argument (Arg)") from None
    except TypeError as exc:
        raise BadInput(f"{head}: the {what} failed on the declared arguments "
                       f"({', '.join(a.name for a in kernel.args)}): {exc}"
                       f"{_where(exc)}") from None


def _vanishing_divisors(e, allowed: set) -> list:
    """The factors of ``e``'s divisors that can be zero for real arguments: every base of a
    negative power (``v / r``, ``v / (r**2 - 1)``, ``1 / sqrt(x)``), factored over the
    rationals; a factor of constant sign (``1 + r**2``: sympy proves it positive for real
    ``r``) is none. A symbol factor whose numerator vanishes with it (``sin r / r``: may be
    removable, left to the generator's removable rewrite) is none either; another factor
    is kept (a removable ``(r**2 - 1) / (r - 1)`` is cancelled before this)."""
    e = sp.cancel(sp.together(e))
    bases = [node.base for node in sp.preorder_traversal(e)
             if isinstance(node, sp.Pow) and node.exp.is_negative
             and node.base.free_symbols and node.base.free_symbols <= allowed]
    if not bases:
        return []
    num, _ = sp.fraction(e)
    out: list = []
    for b in bases:
        try:
            factors = [f for f, _ in sp.factor_list(b)[1]]
        except (sp.PolynomialError, NotImplementedError):
            factors = [b]
        for f in factors:
            while isinstance(f, sp.Pow) and f.exp.is_positive:  # sqrt(x) vanishes with x
                f = f.base
            if not f.free_symbols or f in out or f.is_positive or f.is_negative:
                continue
            if isinstance(f, sp.Symbol) and sp.sympify(num).subs(f, 0).is_zero is True:
                continue
            out.append(f)
    return sorted(out, key=str)


def validate(kernel: Kernel, module: str) -> Kernel:
    """``kernel`` checked; returned with its singular set filled in where a division by an
    argument that can vanish was found and none was declared (with a
    :class:`DivisionWarning`).

    Raises:
        BadInput: one line naming ``module``, the kernel and the symbol or output: a
            ``NameError`` in the formula, a free symbol that is not an argument, or an
            output whose shape is not the declared one.
    """
    head = f"module {module}, kernel {kernel.name}"
    syms = input_symbols(kernel)
    allowed = {s for v in syms.values() for s in (v if isinstance(v, sp.MatrixBase) else [v])}
    builds = [("formula", kernel.build)] + [(f"branch {b.name}", b.build)
                                             for b in kernel.branches]
    outs: list = []
    for what, fn in builds:
        values = _build(kernel, module, what, fn, syms)
        if not isinstance(values, dict):
            raise BadInput(f"{head}: the {what} returns a {type(values).__name__}; it must "
                           f"return {{output name: value}}")
        missing = [o.name for o in kernel.outputs if o.name not in values]
        if missing:
            raise BadInput(f"{head}: the {what} gives no output {missing[0]!r} (it gives "
                           f"{', '.join(map(str, values)) or 'none'})")
        try:
            outs += flatten_outputs(kernel, values)
        except ValueError as exc:
            raise BadInput(f"{head}: output shape: {exc} (declared in Out(...))") from None
    for b in kernel.branches:
        outs.append(_build(kernel, module, f"condition of branch {b.name}", b.when, syms))
    for e in outs:
        extra = sorted((s for s in sp.sympify(e).free_symbols if s not in allowed), key=str)
        if extra:
            names = ", ".join(a.name for a in kernel.args)
            raise BadInput(f"{head}: symbol {extra[0]} is not an argument (arguments: "
                           f"{names}); declare it as an Arg or substitute its value")
    if kernel.singular or kernel.branches:
        return kernel
    dens: list = []
    for e in outs:
        for f in _vanishing_divisors(sp.sympify(e), allowed):
            if f not in dens:
                dens.append(f)
    if not dens:
        return kernel
    where = " or ".join(f"{d} = 0" for d in dens)
    owner = next((a.name for a in kernel.args
                  for s in ([syms[a.name]] if a.shape == () else list(syms[a.name]))
                  if s in dens[0].free_symbols), "")
    what = f"the argument {dens[0]}" if isinstance(dens[0], sp.Symbol) else str(dens[0])
    warnings.warn(f"{head}: divides by {what}, which can be 0, and declares "
                  f"no singular "
                  f"set: recorded as {where!r} (declare Kernel(singular=...) to say it in "
                  f"your words)", DivisionWarning, stacklevel=2)
    return dataclasses.replace(kernel, singular=where, singular_arg=owner)


def validate_all(kernels: list[Kernel], module: str) -> list[Kernel]:
    """:func:`validate` of each kernel of ``module``."""
    return [validate(k, module) for k in kernels]


class one_line_warnings:  # noqa: N801 - a context manager used as a statement
    """For the CLI: :class:`DivisionWarning` printed as one ``rigidsym: warning: ...`` line
    on stderr (not Python's two-line warning format)."""

    def __enter__(self):
        self._cm = warnings.catch_warnings(record=True)
        self._caught = self._cm.__enter__()
        warnings.simplefilter("always", DivisionWarning)
        return self

    def __exit__(self, *exc):
        self._cm.__exit__(*exc)
        import sys

        for w in self._caught:
            if issubclass(w.category, DivisionWarning):
                print(f"rigidsym: warning: {w.message}", file=sys.stderr)
            else:
                warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
        return False
