"""A Jupyter notebook per exercise: statement, editable data, solution, checks, figure.

Built with nbformat from the exercise modules' declarations (title, statement, citation,
parameters, figure, variants) without solving anything, so ``rigidsym generate`` is fast.
The notebooks are deterministic: fixed cell ids (nbformat >= 5.1 would draw them at random),
no outputs, no machine-specific metadata (``language_info``), sorted JSON. They are written
to ``generated/notebooks/`` and shipped in the wheel (``rigidsym.generated``).
"""

from __future__ import annotations

import os
from pathlib import Path

import sympy as sp

__all__ = ["notebook_text", "notebook_files", "write_files", "check_files", "NOTEBOOK_DIR",
           "file_name"]

#: relative to ``generated/``
NOTEBOOK_DIR = "notebooks"
_KERNEL = {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"}


def _worked():
    from rigidsym.course import worked
    return worked


def file_name(ex_id: str) -> str:
    """``"ex3.4"`` -> ``"ex3_04.ipynb"``."""
    k = int(_worked().normalise_id(ex_id).split(".")[1])
    return f"ex3_{k:02d}.ipynb"


def _literal(v) -> str:
    """A parameter value as Python source a student edits: ints bare, floats as floats,
    others as strings the exact reader takes ("-5/3", "sqrt(3)/2"); vectors and matrices
    as lists."""
    if v is None:                                     # an optional datum, not given
        return "None"
    if type(v).__module__.split(".")[0] == "numpy":   # NumPy arrays and scalars
        v = v.tolist()
    if isinstance(v, str):
        t = v.strip()
        return t if t.lstrip("+-").isdigit() else f'"{t}"'
    if isinstance(v, sp.MatrixBase):
        if v.cols == 1:
            return "[" + ", ".join(_literal(x) for x in v) + "]"
        return "[" + ", ".join("[" + ", ".join(_literal(x) for x in v.row(i)) + "]"
                               for i in range(v.rows)) + "]"
    if isinstance(v, list | tuple):
        return "[" + ", ".join(_literal(x) for x in v) + "]"
    if isinstance(v, float):
        return repr(float(v))
    v = sp.sympify(v)
    return str(v) if v.is_Integer else f'"{v}"'


def _data_cell(params, data: dict) -> str:
    lines = ["# The given data: " + ("yours, the others the book's" if data else "the book's "
             "values") + ". Change any of them, then run the cells",
             "# below again (exact: 2, \"5/3\", \"0.1\", \"sqrt(3)/2\"; a float such as 0.1 is",
             "# read as a measurement)."]
    if params.measured:
        lines.append("# Float data are compared within a tolerance: add tol=... to the "
                     "solve call.")
    lines.append("data = dict(")
    for p in params:
        unit = f" [{p.unit}]" if p.unit else ""
        value = data[p.name] if p.name in data else p.default
        lines.append(f"    {p.name}={_literal(value)},  # {p.meaning}{unit}")
    lines.append(")")
    return "\n".join(lines)


def _intro(mod, params) -> str:
    k = mod.ID[2:]
    about = ("This notebook solves the exercise with computer algebra (rigidsym) and checks "
             "every answer by machine, independently of the solution path.")
    if len(params):
        about += (" Edit the data below and run all cells to solve your own variant: the "
                  "steps, the answers, the checks and the figure follow the data.")
    else:
        about += f" The exercise has no numeric data: {params.note}."
    return "\n".join([f"# Exercise {k}: {mod.TITLE}", "", f"*{mod.CITATION}*", "",
                      f"> {mod.STATEMENT}", "", about])


def _variants(mod, given: dict | None = None) -> str | None:
    """The "Try other data" cell. The book's notebook varies its own data cell; a
    variant's notebook (``given``) offers whole data sets instead, since the book's
    changes merged into other readings are incompatible with them: a second drawn
    variant, checked well-posed (exercises with ``random_data``), then the book's
    variants on the book's data."""
    rows = getattr(mod, "VARIANTS", ())
    if not rows:
        return None
    out = ["## Try other data", ""]
    if given:
        second = _second_variant(mod, given)
        if second:
            args = ", ".join(f"{k}={_literal(v)}" for k, v in second.items())
            out.append(f"- a second variant of the same kind: `ex.solve(\"{mod.ID}\", "
                       f"{args})`")
        for desc, data in rows:
            args = ", ".join(f"{k}={_literal(v)}" for k, v in data.items())
            out.append(f"- {desc}, on the book's data: `ex.solve(\"{mod.ID}\", {args})`")
        return "\n".join(out)
    for desc, data in rows:
        args = ", ".join(f"{k}={_literal(v)}" for k, v in data.items())
        out.append(f"- {desc}: `ex.solve(\"{mod.ID}\", **dict(data, {args}))`")
    return "\n".join(out)


def _second_variant(mod, given: dict) -> dict | None:
    """A well-posed variant drawn from a seed made of the given data (deterministic)."""
    import random

    draw = getattr(mod, "random_data", None)
    if draw is None:
        return None
    rng = random.Random(repr(sorted((k, str(v)) for k, v in given.items())))
    w = _worked()
    for _ in range(50):
        data = draw(rng)
        s = w.solve(mod.ID, **data)
        if s.status == "solved" and s.checked:
            return {k: _plain(v) for k, v in data.items()}
    return None


def _plain(v):
    """Drawn data as literals the reader can edit: exact numbers as strings."""
    if isinstance(v, list | tuple):
        return [_plain(x) for x in v]
    return v if isinstance(v, int | str) else str(v)


def notebook_text(ex_id: str, data: dict | None = None) -> str:
    """The notebook of exercise ``ex_id`` as .ipynb JSON text (deterministic).

    ``data`` (name -> value, as :func:`rigidsym.exercises.solve` takes them) replace the
    book's values in the data cell; they are checked first.

    Raises:
        ModuleNotFoundError: if nbformat is not installed (``pip install
            "rigidsym[notebooks]"``).
        ValueError, TypeError: a bad exercise id or bad data (the message names them).
    """
    import nbformat
    from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

    w = _worked()
    ex_id = w.normalise_id(ex_id)
    mod, params = w.exercise_module(ex_id), w.parameters(ex_id)
    data = dict(data or {})
    tol = data.pop("tol", None)
    w.read_data(params, data, tol)  # bad names, shapes or types raise here, not in Jupyter
    tag = f"ex{ex_id[2:].replace('.', '-')}"
    cells = [new_markdown_cell(_intro(mod, params), id=f"{tag}-statement"),
             new_code_cell("%matplotlib inline\n%config InlineBackend.figure_formats = "
                           "[\"svg\"]\nimport rigidsym.exercises as ex", id=f"{tag}-setup"),
             new_code_cell(f"ex.parameters(\"{ex_id}\")", id=f"{tag}-parameters")]
    call = f"ex.solve(\"{ex_id}\")"
    if len(params):
        cells.append(new_code_cell(_data_cell(params, data), id=f"{tag}-data"))
        call = f"ex.solve(\"{ex_id}\", **data"
        call += f", tol={_literal(tol)})" if tol is not None else ")"
    cells += [new_markdown_cell("## The worked solution", id=f"{tag}-solution-title"),
              new_code_cell(f"solution = {call}\nsolution", id=f"{tag}-solve"),
              new_markdown_cell("## Machine checks\n\nEach check is decided exactly (the sound "
                                "zero test or exact arithmetic), without reusing the solution "
                                "path.", id=f"{tag}-checks-title"),
              new_code_cell("if solution.status == \"ill-posed\":\n"
                            "    print(\"no checks: the data admit no answer.\", "
                            "solution.reason)\n"
                            "else:\n"
                            "    for check in solution.checks:\n"
                            "        print(\"passed\" if check.passed else \"FAILED\", "
                            "\"|\", check.name)\n"
                            "    print(\"every check passed:\", solution.checked)",
                            id=f"{tag}-checks")]
    if hasattr(mod, "figure"):
        cells += [new_markdown_cell("## Figure\n\nDrawn from the computed answers: new data "
                                    "redraw it.", id=f"{tag}-figure-title"),
                  new_code_cell("ex.figure(solution)", id=f"{tag}-figure")]
    more = _variants(mod, data)
    if more:
        cells.append(new_markdown_cell(more, id=f"{tag}-variants"))
    nb = new_notebook(cells=cells, metadata={"kernelspec": dict(_KERNEL)})
    nbformat.validate(nb)
    text = nbformat.writes(nb)
    return text if text.endswith("\n") else text + "\n"


#: the notebooks' README, the book's words beside its exercises (their package,
#: :data:`rigidsym.core.config.EXERCISES`)
README = "notebooks-README.md"


def _readme() -> str:
    from importlib import resources

    from rigidsym.core import config

    return resources.files(config.EXERCISES).joinpath(README).read_text("utf-8")


def notebook_files() -> dict[str, str]:
    """``{file name: text}`` of all 21 notebooks and their README (relative to the folder)."""
    w = _worked()
    files = {file_name(i): notebook_text(i) for i in w.EXERCISE_IDS}
    files["README.md"] = _readme()
    return dict(sorted(files.items()))


def _on_disk(folder: Path) -> dict[str, Path]:
    if not folder.is_dir():
        return {}
    return {p.name: p for p in sorted(folder.iterdir())
            if p.is_file() and not p.name.startswith(".")}


def check_files(files: dict[str, str], folder: Path) -> list[str]:
    """Names that differ between ``files`` and ``folder`` (missing, changed or orphan)."""
    disk = _on_disk(Path(folder))
    out = [n for n, t in files.items() if n not in disk or
           disk[n].read_text(encoding="utf-8") != t]
    return out + [f"{n} (orphan)" for n in disk if n not in files]


def write_files(files: dict[str, str], folder: Path) -> list[str]:
    """Write changed files atomically and remove orphans; returns the names touched."""
    from rigidsym.core.files import write_atomic

    folder = Path(folder)
    touched = []
    for name in check_files(files, folder):
        if name.endswith(" (orphan)"):
            os.unlink(folder / name[:-len(" (orphan)")])
        else:
            write_atomic(folder / name, files[name])
        touched.append(name)
    return touched
