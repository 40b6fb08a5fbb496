"""rigidsym audit's issue bodies run as pasted (docs/audit.md, "Reproducers that run
alone"): a bound method or a chain is audited as written (``'mod:Rot(matrix=...).log'`` or
``'mod:lambda Q: Rot(matrix=Q).log'``) and its reproducer calls it so, with no wrapper
module; a function that takes tensors gets tensors in its reproducer and its framework's
version in the body (a stand-in ``torch`` package here: PyTorch is not a dependency); each
generated body runs alone in a fresh ``python -c`` (no rigidsym on the path)."""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path

import pytest

pytest.importorskip("flint")
sys.path.insert(0, str(Path(__file__).resolve().parent))
import test_audit_issue_bodies as B  # noqa: E402

from rigidsym.auditing import callables  # noqa: E402
from rigidsym.core.errors import BadInput  # noqa: E402

#: the logarithm through arccos (NaN at Q = 1, digits lost near 0 and pi), as a method
LOG = """
    def _log(M):
        M = np.asarray(M, dtype=np.float64)
        th = np.arccos(np.clip((np.trace(M) - 1) / 2, -1, 1))
        v = np.array([M[2, 1] - M[1, 2], M[0, 2] - M[2, 0], M[1, 0] - M[0, 1]]) / 2
        return th / np.sin(th) * v
"""

CHAIN = "import numpy as np\n" + textwrap.dedent(LOG) + textwrap.dedent("""
    __version__ = "1.4.2"


    class Rot:
        def __init__(self, matrix=None):
            self.m = np.asarray(matrix, dtype=np.float64)

        @property
        def log(self):
            return _log(self.m)
""")

FAKE_TORCH = textwrap.dedent('''
    """A stand-in for PyTorch: a tensor a NumPy function cannot take."""
    import numpy as np

    __version__ = "9.1.0"


    class Tensor:
        def __init__(self, a):
            self._a = np.array(a, dtype=np.float64)

        def detach(self):
            return self

        def cpu(self):
            return self

        def numpy(self):
            return self._a.copy()

        def __array__(self, dtype=None, copy=None):
            return self._a if dtype is None else self._a.astype(dtype)


    def as_tensor(a):
        return Tensor(np.asarray(a))
''')

TORCH_LIB = "import numpy as np\nimport torch\n" + textwrap.dedent(LOG) + textwrap.dedent("""
    __version__ = "0.3.0"


    def log(Q):
        if not isinstance(Q, torch.Tensor):
            raise TypeError(f"log(): expected a Tensor, got {type(Q).__name__}")
        return torch.as_tensor(_log(np.asarray(Q)))
""")


def test_an_expression_spec_is_a_lambda_over_the_modules_names():
    ex = callables.expression("pyquaternion:Quaternion(matrix=...).axis")
    assert ex.source == "lambda matrix: Quaternion(matrix=matrix).axis"
    assert ex.names == ("Quaternion",)
    ex = callables.expression("m:lambda Q, t: SE3(Q, t).inverse().log()")
    assert ex.source.startswith("lambda Q, t:") and ex.names == ("SE3",)
    two = callables.expression("m:compose(..., ...)")
    assert two.source == "lambda arg0, arg1: compose(arg0, arg1)"
    assert callables.expression("m:f") is None and callables.expression("m:A.f") is None
    with pytest.raises(BadInput, match="arguments as ..."):
        callables.expression("m:Rot(1).log")
    with pytest.raises(BadInput, match="does not parse"):
        callables.expression("m:Rot(matrix=...).")


def _body(spec, tmp_path, monkeypatch, capsys) -> tuple[str, dict]:
    from rigidsym.cli import main

    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.chdir(tmp_path)
    assert main(["audit", spec, "--as", "rotation_vector_from_rotation", "--markdown",
                 "--no-search"]) == 1
    md = capsys.readouterr().out
    return md, B.parse_issue(md)


def _run_each(issue, tmp_path) -> None:
    assert issue["scripts"]
    for script in issue["scripts"]:
        assert "rigidsym" not in script.replace("# audited with", "")
        ran = _alone(script, tmp_path)
        assert not ran["error"] <= ran["bound"], ran["out"]


def _alone(script: str, where: Path) -> dict:
    """The script in a fresh ``python -c`` with only ``where`` on the path."""
    import re
    import subprocess

    res = subprocess.run([sys.executable, "-c", script], cwd=where, capture_output=True,
                         text=True, timeout=120,
                         env={"PYTHONPATH": str(where), "PATH": "/usr/bin:/bin"})
    assert res.returncode == 0, res.stderr[-2000:]
    err = re.search(r"relative error (\S+)", res.stdout)
    bound = re.search(r"the bound 8 u \(kappa \+ 1\) (\S+)", res.stdout)
    assert err and bound, res.stdout
    return {"error": float(err.group(1)), "bound": float(bound.group(1)), "out": res.stdout}


@pytest.mark.parametrize("spec", ["chainlib:Rot(matrix=...).log", pytest.param(
    "chainlib:lambda Q: Rot(matrix=Q).log", marks=pytest.mark.slow)])
def test_a_method_chain_is_audited_as_written_and_its_body_runs_alone(
        spec, tmp_path, monkeypatch, capsys):
    (tmp_path / "chainlib.py").write_text(CHAIN)
    md, issue = _body(spec, tmp_path, monkeypatch, capsys)
    assert issue["versions"]["chainlib"] == "1.4.2"
    assert "from chainlib import Rot" in md and "Rot(matrix=" in md
    _run_each(issue, tmp_path)


def test_a_tensor_function_gets_tensors_and_its_frameworks_version(
        tmp_path, monkeypatch, capsys):
    (tmp_path / "torch").mkdir()
    (tmp_path / "torch" / "__init__.py").write_text(FAKE_TORCH)
    (tmp_path / "tlib.py").write_text(TORCH_LIB)
    had = "torch" in sys.modules
    try:
        md, issue = _body("tlib:log", tmp_path, monkeypatch, capsys)
    finally:
        if not had:
            for m in ("torch", "tlib"):
                sys.modules.pop(m, None)
    assert issue["versions"]["torch"] == "9.1.0" and issue["versions"]["tlib"] == "0.3.0"
    assert "import torch" in md and "torch.as_tensor(np.array([" in md
    _run_each(issue, tmp_path)


def test_the_framework_is_recorded_on_the_callable(monkeypatch, tmp_path):
    """NumPy first; a framework's tensors where NumPy's arrays raise a TypeError."""
    import numpy as np

    f = callables.as_numpy_callable(lambda a: np.asarray(a) * 2)
    assert f.framework == "" and f(np.ones(2)).tolist() == [2.0, 2.0]
    assert f.framework == ""
    (tmp_path / "torch").mkdir()
    (tmp_path / "torch" / "__init__.py").write_text(FAKE_TORCH)
    monkeypatch.syspath_prepend(str(tmp_path))
    had = "torch" in sys.modules
    try:
        import torch

        def only_tensors(a):
            if not isinstance(a, torch.Tensor):
                raise TypeError("a Tensor")
            return np.asarray(a) * 3

        g = callables.as_numpy_callable(only_tensors)
        assert g(np.ones(2)).tolist() == [3.0, 3.0] and g.framework == "torch"
        assert g(np.ones(1)).tolist() == [3.0]      # from then on, tensors at once
    finally:
        if not had:
            sys.modules.pop("torch", None)
