"""Static tools see the kernels: mypy accepts keyword calls and rejects a wrong keyword.

mypy reads the package as a wheel lays it out (``rigidsym/generated/api.py`` inside the
package, ``py.typed`` at its top): an editable install maps ``rigidsym.generated`` through
an import hook that static tools cannot follow, so the test builds that layout from
symbolic links to the checkout.
"""

from __future__ import annotations

import inspect
import os
import pickle
import subprocess
import sys
from pathlib import Path

import pytest

from rigidsym import kernels as K
from rigidsym.kernels.runtime import state as _state

#: skipped without its extra in the README's test command; .ci/run installs it
pytestmark = pytest.mark.extra

ROOT = Path(__file__).resolve().parents[1]

GOOD = """\
import numpy as np
from numpy.typing import NDArray
from rigidsym import kernels

Q: NDArray[np.floating] = kernels.rotation_from_natural_invariants(e=[0.0, 0.0, 1.0], phi=0.5)
t = kernels.twist_transfer(t_A=np.zeros(6), a=[0, 0, 0], p=[1.0, 2.0, 3.0], threads=2,
                           on_singular="nan")
e, phi = kernels.natural_invariants_from_rotation(Q=Q, check=False)
reveal_type(t)
"""

BAD = """\
from rigidsym import kernels

kernels.twist_transfer(t_a=[0.0] * 6, a=[0, 0, 0], p=[1.0, 2.0, 3.0])
kernels.rotation_from_natural_invariants([0.0, 0.0, 1.0], 0.5, on_singular="ignore")
"""


def _wheel_layout(dest: Path) -> Path:
    pkg = dest / "rigidsym"
    pkg.mkdir(parents=True)
    for p in (ROOT / "src" / "rigidsym").iterdir():
        if p.name != "__pycache__":
            (pkg / p.name).symlink_to(p)
    (pkg / "generated").symlink_to(ROOT / "generated")
    (pkg / "derivations").symlink_to(ROOT / "derivations")
    return dest


def test_mypy_sees_true_signatures(tmp_path):
    pytest.importorskip("mypy", reason="mypy is not installed (the [typing] extra)")
    assert (ROOT / "src" / "rigidsym" / "py.typed").is_file()
    site = _wheel_layout(tmp_path / "site")
    (tmp_path / "good.py").write_text(GOOD)
    (tmp_path / "bad.py").write_text(BAD)
    env = dict(os.environ, MYPYPATH=str(site))
    res = subprocess.run(
        [sys.executable, "-m", "mypy", "--follow-imports=silent", "--no-error-summary",
         "--cache-dir", str(tmp_path / "cache"), "good.py", "bad.py"],
        cwd=tmp_path, env=env, capture_output=True, text=True)
    lines = res.stdout.splitlines()
    good = [x for x in lines if x.startswith("good.py")]
    bad = [x for x in lines if x.startswith("bad.py")]
    assert len(good) == 1 and "Revealed type" in good[0] and "floating" in good[0], res.stdout
    assert any('Unexpected keyword argument "t_a"' in x for x in bad), res.stdout
    assert any("on_singular" in x and "error" in x for x in bad), res.stdout


def test_signatures_are_real():
    """Positional and keyword calls agree; the signature lists the arguments, then the
    common keywords (defined once, in rigidsym.codegen.backends.numpy.api_spec)."""
    from rigidsym.codegen.backends.numpy.api_spec import COMMON_KEYWORDS

    common = [k.name for k in COMMON_KEYWORDS]
    for name in K.KERNEL_NAMES:
        sig = inspect.signature(getattr(K, name))
        args = [a["name"] for a in _state.meta()[name]["args"]]
        assert list(sig.parameters) == args + common, name
        kinds = [p.kind for p in sig.parameters.values()]
        assert kinds == [inspect.Parameter.POSITIONAL_OR_KEYWORD] * len(args) \
            + [inspect.Parameter.KEYWORD_ONLY] * len(common), name
        # pickled by reference through the facade, whose import binds the kernels
        assert getattr(K, name).__module__ == "rigidsym.kernels"
        assert pickle.loads(pickle.dumps(getattr(K, name))) is getattr(K, name)
    assert set(K.KERNEL_NAMES) <= set(K.__all__)
    for helper in ("KERNEL_NAMES", "UNIT_TOL", "ORTHO_TOL"):
        assert helper not in K.__all__
