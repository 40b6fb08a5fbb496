"""The measured accuracy of the package's kernels, read back from the data shipped with them
(``kernels.json``; ``docs/accuracy.md``). Re-exported by :mod:`rigidsym.kernels`.
"""

from __future__ import annotations

from rigidsym.kernels.runtime import names as _names
from rigidsym.kernels.runtime import state as _state
from rigidsym.kernels.runtime.namespace import public

__all__ = ["accuracy"]


@public
def accuracy(name: str) -> dict:
    """The measured accuracy of a package kernel (``docs/accuracy.md``).

    Read from the data shipped with the generated kernels (``kernels.json``, written by
    ``rigidsym generate`` from ``benchmarks/accuracy.py --data``): exact points over the
    kernel's regimes (random; angles to 0 and pi; rotations to 1 and a half turn; norms to
    0; gimbal lock; scales 1e-6..1e6; unit inputs a few ulps off), rounded to the type, against
    the declared formula in ``arb`` ball arithmetic, C and NumPy.

    Args:
        name: a kernel's name: public, ``<name>_with_jacobians`` or an Euler-angle variant
            (``euler_angle_rates_zyz_body``).

    Returns:
        dict: a new one each call, with ``"float64"`` and ``"float32"``, each ``{"bound",
        "regime", "kappa", "err", "ulps", "flagged", "beyond", "spurious", "rule",
        "backends"}``, where the normwise relative error of every output is at most
        ``bound * u * (kappa + 1)`` (``u`` the unit roundoff, ``kappa`` the condition number
        on the inputs' tangent space), attained in ``regime`` (``kappa`` and ``err`` there),
        ``ulps`` the worst componentwise error (against the truth at the input as given),
        ``rule`` the worst ratio to the accuracy rule (:mod:`rigidsym.codegen.accuracy.rule`:
        ``err <= 8 u (kappa + 1)`` and ``err <= max(2 e_ref, 4 u)``, ``e_ref`` the smallest
        error of the textbook formula and of the peers: ``docs/accuracy.md``), ``backends``
        per back-end ``{"err_u", "vs_ref", "vs_ref_where", "rule"}`` (the worst error in u,
        the worst ratio to ``e_ref`` where ``e_ref > 2 u`` and where); ``regimes`` swept;
        ``seeds`` (the seeds of the regimes' random points the bound was measured over);
        ``accurate`` (every regime within the rule); ``singular`` (the set) and
        ``threshold`` (where a sample is flagged, in units of the input).

    Raises:
        TypeError: ``name`` is not a ``str``.
        KeyError: no kernel ``name`` (the message lists the close names), or one without
            measured accuracy.
    """
    meta = _state.meta()
    _names.kernel_name(name, meta)
    row = meta[name].get("accuracy")
    if not row:
        raise KeyError(f"name: kernel {name!r} has no measured accuracy")
    return {k: dict(v) if isinstance(v, dict) else v for k, v in row.items()}
