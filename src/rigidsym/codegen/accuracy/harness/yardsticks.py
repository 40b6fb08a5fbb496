"""The peers of the accuracy harness: what a user would
call instead, from the package's table (:mod:`rigidsym.codegen.accuracy.peers`: pytransform3d,
Pinocchio, PyPose, jaxlie, spatialmath-python, Modern Robotics' library, each wrapped to the
kernel's conventions), evaluated at the harness's points. Test-only oracles: the
``[oracles]`` extra; a peer whose library is missing is left out (the harness then compares
with the textbook formula and the peers it has, and :func:`missing` says why). Peers are
float64 only. A peer that computes some of a kernel's outputs (a ``_with_jacobians``
kernel's values) is NaN in the others, which the rule then judges by the textbook formula.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable

import numpy as np

from rigidsym.codegen.accuracy import peers as table


def peers(name: str) -> list[tuple[str, Callable]]:
    """``[(label, f(*args) -> tuple of output arrays)]`` for kernel ``name``, the peers of
    the package's table whose library is installed (none: an empty list)."""
    return [(p.label, f) for p, f in table.available(name)[0]]


def missing(name: str) -> list[tuple[str, str]]:
    """``[(label, why)]``: the peers of kernel ``name`` left out here (library missing)."""
    return [(p.label, why) for p, why in table.available(name)[1]]


def _slices(name: str) -> dict[str, slice]:
    """Each output's columns in the kernel's flat outputs."""
    from rigidsym.codegen.accuracy.harness import reference as R

    out, at = {}, 0
    for o in R.kernel_of(name).outputs:
        n = int(np.prod(o.shape, dtype=int))
        out[o.name], at = slice(at, at + n), at + n
    return out


def evaluate(name: str, arrays: list[np.ndarray], n_out: int) -> dict[str, np.ndarray]:
    """``{label: (n, n_out)}`` float64 outputs of each peer at the rows of ``arrays``, NaN
    in the outputs it does not compute; a row where the peer raises or returns the wrong
    shape is NaN (it failed there; its warnings are silenced)."""
    sl = _slices(name)
    out = {}
    for p, f in table.available(name)[0]:
        rows = np.full((arrays[0].shape[0], n_out), np.nan)
        cols = [sl[o] for o in p.outputs]
        for s in range(arrays[0].shape[0]):
            args = [np.asarray(a[s], dtype=np.float64) for a in arrays]
            try:
                with warnings.catch_warnings(), np.errstate(all="ignore"):
                    warnings.simplefilter("ignore")
                    got = [np.asarray(v, dtype=np.float64).ravel() for v in f(*args)]
            except Exception:      # noqa: BLE001  (a peer's own error: it failed here)
                continue
            if len(got) == len(cols) and all(v.size == c.stop - c.start
                                             for v, c in zip(got, cols, strict=True)):
                for v, c in zip(got, cols, strict=True):
                    rows[s, c] = v
        out[p.label] = rows
    return out


def textbook(name: str, arrays: list[np.ndarray], dtype) -> np.ndarray:
    """The textbook formula (the declaration, naively;
    :func:`rigidsym.codegen.accuracy.rule.textbook`)
    at the rows of ``arrays`` in ``dtype`` arithmetic: ``(n, outputs)`` float64."""
    from rigidsym.codegen.accuracy import rule
    from rigidsym.codegen.accuracy.harness import reference as R

    n = arrays[0].shape[0]
    return rule.textbook(R.kernel_of(name), [c for a in arrays for c in a.reshape(n, -1).T],
                         dtype)
