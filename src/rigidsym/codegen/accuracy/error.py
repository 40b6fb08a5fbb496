"""The error of a form and its worst ratio to the rule: the one measure the code
generator's choice of forms (:mod:`rigidsym.codegen.accuracy.rewrites`,
:mod:`rigidsym.codegen.accuracy.cos_form`) and the float32 precision plan
(:mod:`rigidsym.codegen.accuracy.float32`) judge by.

- :func:`normwise`: per point and output array, ``||computed - truth|| / ||truth||``
  (absolute where the truth is exactly 0), as :mod:`rigidsym.codegen.accuracy.rule` reads it.
- :func:`worst`: the worst ratio of such errors to the rule's reference half
  ``max(2 e_ref, 4 u)`` (:func:`budget`; the generator has no condition number).
- :class:`Meter`: the declared outputs in mpmath at the generator's points
  (:func:`rigidsym.codegen.accuracy.points.exact_points`) and a form's :func:`normwise`
  error there, in float64.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import sympy as sp
from sympy.core.function import FunctionClass

from rigidsym.codegen.accuracy import elementary, rule
from rigidsym.codegen.accuracy.compensated import diffprod, sumprod
from rigidsym.codegen.accuracy.points import GENERATOR_STEPS, exact_points

__all__ = ["U64", "normwise", "budget", "worst", "round_up", "Meter", "implementations",
           "lambdified"]

#: the unit roundoff of float64
U64 = 2.0**-53


def normwise(got: np.ndarray, ref: np.ndarray, groups, no_answer_from: float = math.inf
             ) -> np.ndarray:
    """The normwise relative error of each output array at each point.

    Args:
        got: ``(points, flat outputs)`` the computed values (float64).
        ref: ``(points, flat outputs)`` the truth there.
        groups: one slice of the flat outputs per output array.
        no_answer_from: an error this large or larger is no answer (a zero, a wrong sign)
            and reads as inf, a flag (the generator: 1); inf keeps every finite error.

    Returns:
        ``(points, len(groups))``: relative where the truth's norm is nonzero, absolute where
        it is exactly 0; inf where not finite.
    """
    out = np.zeros((len(ref), len(groups)))
    for j, sl in enumerate(groups):
        norm = np.linalg.norm(ref[:, sl], axis=1)
        with np.errstate(all="ignore"):
            d = np.linalg.norm(got[:, sl] - ref[:, sl], axis=1)
            e = np.where(norm > 0, d / np.where(norm > 0, norm, 1.0), d)
        out[:, j] = np.where(np.isfinite(e) & (e < no_answer_from), e, np.inf)
    return out


def budget(e_ref, u: float) -> np.ndarray:
    """The rule's reference half per point and output
    (:func:`rigidsym.codegen.accuracy.rule.allowed` without a condition number):
    ``max(2 e_ref, 4 u)``, elementwise; ``e_ref`` the textbook formula's error there, ``u``
    the unit roundoff of the type."""
    return np.maximum(rule.REF_FACTOR * np.asarray(e_ref), rule.FLOOR * u)


def round_up(x: float) -> float:
    """``x`` rounded up to 1e-3 (so that float64 noise never flips a decision between
    machines); inf where not finite."""
    return math.ceil(x * 1000) / 1000 if math.isfinite(x) else math.inf


def worst(err: np.ndarray, e_ref: np.ndarray, u: float = U64, *, every_point: bool = False,
          rounded: bool = False) -> float:
    """The worst ratio of ``err`` to :func:`budget` ``(e_ref, u)``: per point and output
    :func:`rigidsym.codegen.accuracy.rule.ratio` with no condition number (0 where ``err``
    is 0, inf where it is not finite); 0 where there is no point.

    Args:
        err: the form's errors (:func:`normwise`), any shape.
        e_ref: the textbook formula's errors, the same shape.
        u: the unit roundoff of the type.
        every_point: False: over the points where ``e_ref`` is finite only (the generator:
            where every form fails no form is judged); True: over every point, a form that
            fails where the textbook fails too counting as inf (the float32 plan).
        rounded: rounded up to 1e-3 (:func:`round_up`).
    """
    err, e_ref = np.asarray(err), np.asarray(e_ref)
    if not every_point:
        some = np.isfinite(e_ref)
        err, e_ref = err[some], e_ref[some]
    if not err.size:
        return 0.0
    with np.errstate(all="ignore"):
        r = np.where(err == 0, 0.0, err / budget(e_ref, u))
    w = float(np.max(np.where(np.isfinite(r), r, np.inf)))
    return round_up(w) if rounded else w


def implementations(exprs) -> dict:
    """``{name: implementation}`` of the implemented functions (a class with ``_imp_``: the
    removable quotients of :mod:`rigidsym.codegen.removable`) in the sympy expressions
    ``exprs``, as ``sympy.lambdify`` finds them (its ``_imp_namespace``), but visiting each
    shared sub-expression once: lambdify's walk visits the tree, exponential in the depth of
    a differentiated output's sharing (a fifth of the generation's time)."""
    out: dict = {}
    seen: set = set()
    stack = list(exprs)
    while stack:
        e = stack.pop()
        if id(e) in seen:
            continue
        seen.add(id(e))
        f = getattr(e, "func", None)
        if isinstance(f, FunctionClass) and getattr(f, "_imp_", None) is not None:
            out[f.__name__] = f._imp_
        stack.extend(getattr(e, "args", ()))
    return out


def lambdified(args, exprs: list, modules, **kw):
    """``sympy.lambdify(args, exprs, modules, **kw)``, the same function, with the
    implemented functions found by :func:`implementations` (``exprs`` a list of sympy
    expressions; ``modules`` a module name or a list of them and dicts), and no expression
    in its docstring unless ``docstring_limit`` is given."""
    mods = [modules] if isinstance(modules, str | dict) else list(modules)
    # docstring_limit=0: no docstring printing each expression (str() of every candidate
    # form, 2 % of a cold generation); the function is the same
    return sp.lambdify(args, exprs, modules=[implementations(exprs), *mods], use_imps=False,
                       **{"docstring_limit": 0, **kw})


class Meter:
    """The declared outputs at the measurement points (mpmath) and a form's error there:
    per point and output, normwise relative (absolute where the output is exactly 0), in
    float64, as :mod:`rigidsym.codegen.accuracy.rule` reads it.

    ``flat``: the declared outputs (the reference); ``syms_flat``: the flat input symbols;
    ``conds``: the float predicates of the branches tried before this build (a point they
    take is not this build's), ``cond`` this build's own (None for the main build); the
    points: :func:`rigidsym.codegen.accuracy.points.exact_points` with each of ``seeds``,
    ``n_random`` and ``small``."""

    def __init__(self, kernel, flat, syms_flat, conds, cond, n_random: int = 6,
                 seeds=(30,), small=GENERATOR_STEPS):
        pts = exact_points(kernel, seeds, n_random, small)
        self.syms = syms_flat
        offs = np.cumsum([0] + [o.size for o in kernel.outputs])
        self.groups = [slice(a, b) for a, b in zip(offs[:-1], offs[1:], strict=True)]
        keep = []
        for p in pts:
            row = [float(x) for a in p for x in a]
            ok = cond is None or bool(cond(*row))
            ok = ok and not any(bool(c(*row)) for c in conds)
            if ok:
                keep.append(p)
        self.exact = keep
        self.rounded = np.array([[float(x) for a in p for x in a] for p in keep], dtype=float)
        f = lambdified(syms_flat, list(flat), "mpmath", cse=True)
        refs = []
        with mpmath.workdps(40):
            for p in keep:
                try:   # TypeError: float() of a complex value, a root of a negative
                    refs.append([float(v) for v in f(*[x for a in p for x in a])])
                except (ZeroDivisionError, ValueError, OverflowError, TypeError):  # radicand
                    refs.append([math.nan] * len(flat))
        self.ref = np.array(refs, dtype=float).reshape(len(keep), len(flat))
        self.ok = np.isfinite(self.ref).all(axis=1)
        self._seen: dict = {}   # (textbook, ids of the outputs) -> (the outputs, errors)

    def errors(self, flat, textbook: bool = False) -> np.ndarray:
        """``(points, outputs)``: the error of ``flat`` at the points with a finite
        reference (inf where it is not finite or not below 1: :func:`normwise`). A form is
        evaluated as the kernels print it
        (:class:`~rigidsym.codegen.backends.numpy.printer.KernelNumPyPrinter`: a rational
        power as roots and a quotient); ``textbook``: as the harness evaluates the declaration
        (sympy's NumPy printer: ``pow``). The same outputs (the same objects) again give
        the errors measured before: a choice re-reads the current form's at each candidate."""
        key = (textbook, *map(id, flat))
        hit = self._seen.get(key)
        if hit is not None and all(a is b for a, b in zip(hit[0], flat, strict=True)):
            return hit[1].copy()
        got = self._errors(flat, textbook)
        self._seen[key] = (tuple(flat), got)   # the outputs kept: their ids stay theirs
        return got.copy()

    def _errors(self, flat, textbook: bool) -> np.ndarray:
        n = int(self.ok.sum())
        if not n:
            return np.zeros((0, len(self.groups)))
        # the elementary functions with values the same on every machine: the ratios
        # measured here are written into generated/
        mods = [{"DiffProd": diffprod, "SumProd": sumprod, "_diffprod": diffprod,
                 "_sumprod": sumprod, "numpy": elementary.NUMPY}, "numpy"]
        f = lambdified(self.syms, list(flat), mods, cse=True,
                       printer=elementary.TEXTBOOK_PRINTER if textbook
                       else elementary.KERNEL_PRINTER)
        with np.errstate(all="ignore"):
            got = np.array([np.broadcast_to(np.asarray(v, dtype=float), (len(self.exact),))
                            for v in f(*self.rounded.T)]).T[self.ok]
        # a relative error of 1 or more is no answer (a zero, a wrong sign): as a flag
        return normwise(got, self.ref[self.ok], self.groups, no_answer_from=1.0)
