"""docs/adding-a-kernel.md followed as written: its steps, on a scratch kernel, in a fresh
clone, end with the suite's checks of a kernel green.

The slow test clones this checkout's HEAD into a temporary folder, makes a virtual
environment there that sees this one's packages (no network: the README's install then
resolves every requirement from them), and runs the page's commands word for word (each
is asserted to stand on the page first, :data:`STEPS`): a kernel ``scratch_twist_transfer``
declared on the formula of ``twist_transfer`` (step 1's formula exists and is checked),
joined to the public list of ``tests/test_public_api.py`` (step 2), ``rigidsym generate``
(step 3: in a fresh cache it derives every kernel, minutes), the accuracy tables (step 4),
the README's editable install (step 5) and step 7's checks. Step 6 (the C target's float
bound, the vector lanes) is optional and measured by benchmarks: left out.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PAGE = ROOT / "docs" / "adding-a-kernel.md"

#: the page's commands, in its order: (step, the command as the page writes it)
STEPS = [
    (3, "rigidsym generate"),
    (4, "python benchmarks/accuracy.py --docs derivations/kernels_accuracy.json"),
    (5, 'pip install -v -e ".[test]" --no-compile'),
    (7, "rigidsym generate --check"),
    (7, "python -m pytest -n 0 tests/test_generated_fresh.py tests/test_public_api.py "
        "tests/test_accuracy_docs.py tests/test_lie_groups.py"),
]

#: step 2: the scratch kernel, appended to derivations/kernels_spec.py
SCRATCH = '''

# a scratch kernel (tests/test_adding_a_kernel.py)
KERNELS.append(Kernel(
    name="scratch_twist_transfer", summary="Twist at P from the twist at A (a scratch copy).",
    formula="t_P = U(a, p) t_A", ids=("3.83",), sources=(_S42 + "twist_transfer",),
    args=(Arg("t_A", (6,), "any", "twist [omega; v_A] [rad/s; m/s]"),
          _v("a", "point A [m]"), _v("p", "point P [m]")),
    outputs=(Out("t_P", (6,), "[omega; v_P]"),), build=_one("t_P", _S42 + "twist_transfer")))
'''


def _page_text() -> str:
    """The page's prose with its line breaks and list indentation folded into spaces."""
    return re.sub(r"\s*\n\s*", " ", PAGE.read_text(encoding="utf-8"))


def test_the_scratch_steps_are_the_pages():
    """Each command the slow test runs is written on the page, in the step it runs in, so
    that the test follows the page and a change of the page changes the test."""
    text = _page_text()
    steps = re.split(r" (\d)\. \*\*", text)
    at = {int(n): body for n, body in zip(steps[1::2], steps[2::2], strict=True)}
    for step, command in STEPS:
        assert f"`{command}`" in at.get(step, ""), (step, command)
    assert "tests/test_public_api.py" in at[2] and "`KERNELS`" in at[2]


def _run(cmd: str, cwd: Path, env: dict, timeout: float) -> None:
    p = subprocess.run(["bash", "-c", cmd], cwd=cwd, env=env, capture_output=True, text=True,
                       timeout=timeout)
    assert p.returncode == 0, f"{cmd}: exit {p.returncode}\n{(p.stdout + p.stderr)[-4000:]}"


@pytest.mark.slow  # a clone, every kernel derived in a fresh store, a build: 10-20 min
def test_a_kernel_added_by_the_page_alone_leaves_the_suite_green(tmp_path):
    import _profile

    if _profile.PROFILE != "exhaustive":   # CI's budget: test_the_scratch_steps_are_the_pages
        pytest.skip("the exhaustive profile only (RIGIDSYM_TEST_PROFILE=exhaustive): 10-20 "
                    "min; the quick test holds the steps to the page")
    if shutil.which("git") is None or shutil.which(os.environ.get("CC", "cc")) is None:
        pytest.skip("needs git and a C compiler")
    clone = tmp_path / "clone"
    subprocess.run(["git", "clone", "--quiet", str(ROOT), str(clone)], check=True)
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    # this environment's packages visible to the new one (no network): a .pth file
    site = next((venv / "lib").glob("python*/site-packages"))
    (site / "outer.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "RIGIDSYM_"))}
    env.update(PATH=f"{venv / 'bin'}{os.pathsep}{env.get('PATH', '')}",
               VIRTUAL_ENV=str(venv), RIGIDSYM_CACHE=str(tmp_path / "cache"),
               RIGIDSYM_OBJECT_CACHE=os.environ.get("RIGIDSYM_TESTS_OBJECTS", "0"),
               PIP_NO_INDEX="1", PIP_NO_BUILD_ISOLATION="0")
    _run('pip install -v -e ".[test]" --no-compile', clone, env, 1800)   # the set-up
    # step 2: the kernel, and its name in the pinned public list
    spec = clone / "derivations" / "kernels_spec.py"
    spec.write_text(spec.read_text(encoding="utf-8") + SCRATCH, encoding="utf-8")
    api = clone / "tests" / "test_public_api.py"
    text = api.read_text(encoding="utf-8")
    assert '"wrench_transfer", "wrench_transfer_matrix",' in text
    api.write_text(text.replace('"wrench_transfer", "wrench_transfer_matrix",',
                                '"wrench_transfer", "wrench_transfer_matrix", '
                                '"scratch_twist_transfer",', 1), encoding="utf-8")
    for _, command in STEPS:
        _run(command, clone, env, 3600)
    kernels = (clone / "generated" / "kernels.json").read_text(encoding="utf-8")
    assert '"scratch_twist_transfer"' in kernels
