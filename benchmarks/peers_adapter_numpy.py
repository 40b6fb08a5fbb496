"""rigidsym's generated NumPy kernels as an extra column of ../shared/peers-bench (``--extra``).

    python run_all.py --extra /path/to/rigidsym/benchmarks/peers_adapter_numpy.py

The generated modules ``generated/numpy/<kernel>.py`` need only NumPy, so they are loaded from
their files (the harness's environment need not have rigidsym installed); each K is one call of
the low-level function (no validation, the equivalent of ``check=False``), outputs allocated
inside the call like every other peer. Kernels as in ``peers_adapter.py``.
"""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import numpy as np

NAME = "rigidsym-numpy"
PER_SAMPLE_LOOP = False
GEN = Path(__file__).resolve().parents[1] / "generated"
BENCH = {"K1": "rotation_from_euler_rodrigues", "K2": "rotation_from_natural_invariants",
         "K3": "screw_axis_point", "K4": "instant_screw_point_pitch", "K5": "N_matrix",
         "K6": "newton_euler_residual"}
_META = {k["name"]: k for k in json.loads((GEN / "kernels.json").read_text())["kernels"]}
OPS = {kid: _META[name]["ops"] for kid, name in BENCH.items() if name in _META}
KERNELS: dict = {}


def _load(name: str):
    spec = importlib.util.spec_from_file_location(f"_rigidsym_np_{name}",
                                                  GEN / "numpy" / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return getattr(mod, name)


def _wrap(name: str):
    fn = _load(name)
    shapes = [tuple(o["shape"]) for o in _META[name]["outputs"]]

    def call(*xs):
        n = xs[0].shape[0]
        outs = [np.empty((n,) + s) for s in shapes]
        fn(*xs, *outs)
        return outs[0] if len(outs) == 1 else tuple(outs)
    call.__name__ = name
    return call


def setup(ctx=None) -> None:
    """Bind K1..K6; ``ctx`` (as passed by the peers-bench harness) is not needed."""
    for kid, name in BENCH.items():
        if name in _META:
            KERNELS[kid] = _wrap(name)
