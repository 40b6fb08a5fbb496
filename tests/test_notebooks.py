"""The exercise notebooks: generated deterministically, shipped, and runnable.

nbclient executes each notebook in a fresh ipykernel: no cell may fail, the solve cell
must display the solution's HTML (MathML) and the figure cell an SVG figure. Five
notebooks run by default; all 21 under ``-m slow``.
"""

from __future__ import annotations

from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")

from rigidsym.cli import main  # noqa: E402
from rigidsym.course.notebooks import (  # noqa: E402
    check_files,
    file_name,
    notebook_files,
    notebook_text,
)
from rigidsym.course.worked import EXERCISE_IDS, exercise_module, parameters  # noqa: E402

FOLDER = Path(__file__).resolve().parents[1] / "generated" / "notebooks"
#: a fixed sample that runs in the default suite (fast to solve, each with a figure)
SAMPLE = ["ex3.1", "ex3.4", "ex3.5", "ex3.7", "ex3.19"]


def test_generated_notebooks_are_fresh():
    stale = check_files(notebook_files(), FOLDER)
    assert stale == [], f"generated/notebooks is stale, run `rigidsym generate`: {stale}"


@pytest.mark.parametrize("ex_id", EXERCISE_IDS)
def test_notebook_structure(ex_id):
    text = notebook_text(ex_id)
    assert text == notebook_text(ex_id)                     # deterministic
    nb = nbformat.reads(text, as_version=4)
    nbformat.validate(nb)
    assert "language_info" not in nb.metadata and nb.metadata.kernelspec.name == "python3"
    tag = f"ex{ex_id[2:].replace('.', '-')}"
    assert all(c.id.startswith(tag) for c in nb.cells)
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert all(c.outputs == [] and c.execution_count is None for c in code)
    ids = {c.id for c in nb.cells}
    mod = exercise_module(ex_id)
    assert (f"{tag}-data" in ids) == (len(parameters(ex_id)) > 0)
    assert (f"{tag}-figure" in ids) == hasattr(mod, "figure")
    assert mod.CITATION in nb.cells[0].source and mod.TITLE in nb.cells[0].source


def test_notebook_with_student_data(tmp_path):
    import rigidsym.exercises as ex

    path = ex.write_notebook("3.4", tmp_path / "mine.ipynb", f_2=[1, 1, 1], tol=0.01)
    nb = nbformat.read(path, as_version=4)
    data = next(c for c in nb.cells if c.id.endswith("-data")).source
    assert "f_2=[1, 1, 1]" in data and 'n_2=["-5/3", "-10/3", "10/3"]' in data
    assert "tol=0.01" in next(c for c in nb.cells if c.id.endswith("-solve")).source
    with pytest.raises(TypeError, match="no parameter 'g'"):
        ex.write_notebook("3.4", tmp_path / "bad.ipynb", g=1)
    assert not (tmp_path / "bad.ipynb").exists()


def test_cli_writes_a_notebook(tmp_path, capsys):
    out = tmp_path / "ex3_07.ipynb"
    assert main(["exercise", "3.7", "--set", "a=0,0,0", "--set", "n_A=0,2,0",
                 "--notebook", str(out)]) == 0
    nb = nbformat.read(out, as_version=4)
    assert "a=[0, 0, 0]" in next(c for c in nb.cells if c.id.endswith("-data")).source
    assert main(["exercise", "3.7", "--notebook", str(tmp_path / "book.ipynb")]) == 0
    assert (tmp_path / "book.ipynb").read_text() == (FOLDER / file_name("ex3.7")).read_text()


def _run(ex_id: str):
    pytest.importorskip("nbclient", reason="nbclient is not installed (the [notebooks] extra)")
    pytest.importorskip("ipykernel", reason="ipykernel is not installed (the [notebooks] extra)")
    from nbclient import NotebookClient

    nb = nbformat.read(FOLDER / file_name(ex_id), as_version=4)
    NotebookClient(nb, timeout=900, kernel_name="python3").execute()
    return {c.id.split("-", 2)[-1]: c for c in nb.cells}


def _assert_ran(ex_id: str) -> None:
    cells = _run(ex_id)
    for c in cells.values():
        if c.cell_type == "code":
            assert not [o for o in c.outputs if o.output_type == "error"], c.id
    shown = cells["solve"].outputs[0]["data"]
    assert "<math" in shown["text/html"] and "Exercise" in shown["text/latex"]
    printed = "".join(o.get("text", "") for o in cells["checks"].outputs)
    assert "every check passed: True" in printed and "FAILED" not in printed
    if "figure" in cells:
        assert "image/svg+xml" in cells["figure"].outputs[0]["data"]
    if "parameters" in cells:
        assert "text/html" in cells["parameters"].outputs[0]["data"]


@pytest.mark.extra
@pytest.mark.parametrize("ex_id", SAMPLE)
def test_sample_notebooks_execute(ex_id):
    _assert_ran(ex_id)


@pytest.mark.slow
@pytest.mark.thorough(0.25)  # the thorough run: a seeded quarter of the others a commit
@pytest.mark.parametrize("ex_id", [i for i in EXERCISE_IDS if i not in SAMPLE])
def test_every_notebook_executes(ex_id):
    _assert_ran(ex_id)


def test_a_variants_try_other_data_cell_is_a_second_valid_variant():
    # the book's changes merged into a variant's readings were incompatible
    import json
    import re

    import rigidsym.exercises as ex
    from rigidsym.course.notebooks import notebook_text

    for ex_id in ("ex3.4", "ex3.19"):
        variant = {"n_1": ["0", "0", "5"]} if ex_id == "ex3.4" else {"d": ["0.1", "0", "0"]}
        nb = json.loads(notebook_text(ex_id, variant))
        cell = "".join(nb["cells"][-1]["source"])
        calls = re.findall(r"`(ex\.solve\(.*?\))`", cell)
        assert "second variant" in cell and "**dict(data" not in cell
        second = eval(calls[0], {"ex": ex})          # the cell's own call, as a reader runs it
        assert second.status == "solved" and second.checked
        assert second.data != ex.solve(ex_id, **variant).data
