"""The ``-march=native`` build of rigidsym's kernels: the second column next to
``peers_adapter.py`` (the default, portable build), in the same peers-bench run.

    python run_all.py --extra .../peers_adapter.py --extra .../peers_adapter_native.py
"""

from __future__ import annotations

import peers_adapter as _base  # the harness puts this folder on sys.path

NAME = "rigidsym-c-native"
PER_SAMPLE_LOOP = False
OPS = _base.OPS
KERNELS: dict = {}


def setup(ctx=None) -> None:
    """Build the native module (cached) and bind K1..K6."""
    mod = _base._build(_base.Path((ctx or {}).get("build_dir") or
                                  (_base.ROOT / "benchmarks" / ".build")), True)
    for kid, name in _base.BENCH.items():
        if name in _base._META:
            KERNELS[kid] = _base._wrap(mod, name)
