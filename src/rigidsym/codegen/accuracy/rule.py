"""The accuracy rule of the kernels: one function, for the harness
(``benchmarks/accuracy.py``), the code generator's choice of forms (:mod:`.rewrites`) and the
float32 precision plan (:mod:`.float32`).

An output's error ``err`` is normwise relative (``||computed - truth|| / ||truth||``, one
output array at a time; absolute where the truth is exactly 0). It passes where

    err <= 8 u (kappa + 1)   and   err <= max(2 e_ref, 4 u)

``u`` the unit roundoff of the type, ``kappa`` the condition number of the problem at the
point (:mod:`.harness.reference`), ``e_ref`` the smallest error, at the same point and
in the same type, among the textbook formula of the declaration evaluated naively and each
peer library that has the operation (float64 only). The first half says the kernel is as
good as the problem allows; the second that it is never worse than what a user would
write instead, which the first alone does not say where kappa counts perturbations of
several arguments separately (``plucker_from_points`` 8e12 u off where the
textbook is 18 u off, inside ``8 u kappa`` with kappa = 5.8e13).
"""

from __future__ import annotations

import math

__all__ = ["KAPPA_FACTOR", "REF_FACTOR", "FLOOR", "allowed", "ratio"]

#: err <= KAPPA_FACTOR u (kappa + 1): the condition half
KAPPA_FACTOR = 8.0
#: err <= max(REF_FACTOR e_ref, FLOOR u): never worse than the textbook formula or a peer
REF_FACTOR = 2.0
FLOOR = 4.0


def allowed(u: float, kappa: float | None = None, e_ref: float | None = None) -> float:
    """The largest normwise relative error the rule allows at one point and output.

    Args:
        u: unit roundoff of the float type (2**-53 for float64, 2**-24 for float32).
        kappa: condition number of the problem there; None where it is not known (the
            code generator), which drops the condition half.
        e_ref: the smallest error of the textbook formula and the peers there (inf where
            each of them fails: non-finite); None drops the reference half.

    Returns:
        float: ``min(8 u (kappa + 1), max(2 e_ref, 4 u))`` with the halves given.
    """
    out = math.inf
    if kappa is not None:
        out = KAPPA_FACTOR * u * (kappa + 1)
    if e_ref is not None:
        out = min(out, max(REF_FACTOR * e_ref, FLOOR * u))
    return out


def ratio(err: float, u: float, kappa: float | None = None,
          e_ref: float | None = None) -> float:
    """``err / allowed(u, kappa, e_ref)``: the point passes the rule where it is <= 1.

    A non-finite error is inf, unless the rule allows inf too (every reference failed
    there and kappa is unknown): then 1, no worse than the yardstick."""
    a = allowed(u, kappa, e_ref)
    if not math.isfinite(err):
        return 1.0 if a == math.inf else math.inf
    if a == 0:
        return 0.0 if err == 0 else math.inf
    return err / a


# --------------------------------------------------------------------------- the textbook
_TEXTBOOK: dict = {}


def _textbook_variants(kernel):
    """``[(cond or None, f)]`` per variant (branches first): the declaration's builds as
    declared, lambdified plainly for NumPy (no rewrite of the generator; CSE only shares
    subexpressions, it changes no rounding; no docstring printing the expressions), with
    :mod:`rigidsym.codegen.accuracy.elementary`'s correctly rounded functions."""
    import numpy as np
    import sympy as sp

    from rigidsym.codegen.accuracy import elementary
    from rigidsym.codegen.spec import flat_symbols, input_symbols
    from rigidsym.codegen.spec import flatten_outputs as _flatten

    key = (kernel.name, id(kernel))
    if key not in _TEXTBOOK:
        syms = input_symbols(kernel)
        flat = [s for _, ss in flat_symbols(kernel) for s in ss]
        dt = {"now": np.float64}

        def select(conds, choices, default=np.nan):
            # lambdify's Piecewise: integer choices (a sign) in the type under test (int64
            # with float32 is float64: the float32 textbook would be computed in float64)
            return np.select(conds, [np.asarray(c, dtype=dt["now"])
                                     if np.asarray(c).dtype.kind in "iub" else c
                                     for c in choices], default)
        # sin, cos, atan2, asin, acos and pow correctly rounded: NumPy's loops differ per
        # CPU, and a yardstick that moves with the machine moved the generated plans
        mods = [{"select": select, "numpy": elementary.NUMPY}, "numpy"]
        pr = elementary.TEXTBOOK_PRINTER
        out = [(sp.lambdify(flat, br.when(**syms), modules="math"),
                sp.lambdify(flat, _flatten(kernel, br.build(**syms)), modules=mods, cse=True,
                            docstring_limit=0, printer=pr))
               for br in kernel.branches]
        out.append((None, sp.lambdify(flat, _flatten(kernel, kernel.build(**syms)),
                                      modules=mods, cse=True, docstring_limit=0, printer=pr)))
        _TEXTBOOK[key] = (out, dt)
    return _TEXTBOOK[key]


def textbook(kernel, cols: list, dtype):
    """The textbook formula of ``kernel`` (its declaration, evaluated naively) in ``dtype``
    arithmetic: ``cols`` the flat inputs (one array per input symbol, in the order of
    :func:`rigidsym.codegen.spec.flat_symbols`); returns ``(n, outputs)`` float64, each row
    by the variant the kernel takes there (the branches' conditions in float64). Its sin,
    cos, atan2, asin, acos and pow are correctly rounded
    (:mod:`rigidsym.codegen.accuracy.elementary`): "the formula in float32 arithmetic" is
    the same yardstick on every machine, for the generator's plans, the tests and the
    harness (NumPy's own loops differ per CPU by an ulp, which at the margin of the rule
    moved plans and verdicts)."""
    import numpy as np

    variants, dt = _textbook_variants(kernel)
    cols = [np.asarray(c, dtype=dtype) for c in cols]
    n = len(cols[0])
    wide = [c.astype(np.float64) for c in cols]
    res = None
    done = np.zeros(n, dtype=bool)
    for cond, f in variants:
        if cond is None:
            take = ~done
        else:
            # NumPy scalars, not floats: a Python float's ** raises OverflowError where
            # the condition (tr Q - 1)^2 > 2 of a log near 1e160 is simply true
            with np.errstate(all="ignore"):
                take = ~done & np.array([bool(cond(*[c[s] for c in wide]))
                                         for s in range(n)], dtype=bool)
        if not take.any():
            continue
        dt["now"] = dtype
        with np.errstate(all="ignore"):
            v = np.stack([np.broadcast_to(np.asarray(x), (n,)).astype(np.float64)
                          for x in f(*cols)], axis=1)
        if res is None:
            res = np.full(v.shape, np.nan)
        res[take] = v[take]
        done |= take
    return res
