"""The code-generation targets as units (``rigidsym.codegen.backends``): one interface for all,
a generator that names none of them, and a target added by the README's steps alone."""

from __future__ import annotations

import ast
import dataclasses
import inspect
from pathlib import Path

import pytest
import sympy as sp

import rigidsym.codegen.generator as G
from rigidsym.codegen import backends
from rigidsym.codegen.backends import RenderContext, Target, register, targets, unregister
from rigidsym.codegen.backends.numpy.printer import KernelNumPyPrinter
from rigidsym.codegen.spec import Arg, Kernel, Out

BACKENDS = Path(backends.__file__).parent
BUILT_IN = ("numpy", "extension", "torch", "jax", "c", "cpp")


def test_every_registered_target_has_the_same_interface():
    got = targets()
    assert tuple(t.name for t in got[:len(BUILT_IN)]) == BUILT_IN
    assert [t.name for t in targets(package=False)] == ["c", "cpp"]
    for t in got:
        assert isinstance(t, Target) and dataclasses.is_dataclass(t)
        assert t.template_dir.is_dir() and list(t.template_dir.glob("*.j2")), t.name
        assert callable(t.render) and list(inspect.signature(t.render).parameters) == ["ctx"]
        pr = t.printer()
        assert pr.doprint(sp.Symbol("x") ** 2) == "(x*x)", t.name
        # each target is a folder of its own with its printer and its target module
        assert (BACKENDS / t.name / "printer.py").is_file(), t.name
        assert (BACKENDS / t.name / "target.py").is_file(), t.name
    with pytest.raises(ValueError, match="registered already"):
        register(got[0])


#: what generator.py may not contain: it loops over the registered targets
FORBIDDEN = {"numpy", "torch", "jax", "c_kernel", "KernelCPrinter", "KernelNumPyPrinter"}


def test_the_generator_names_no_target():
    tree = ast.parse(Path(G.__file__).read_text(encoding="utf-8"))
    docstring = tree.body[0].value
    templates = {p.name for t in targets() for p in t.template_dir.glob("*.j2")}
    bad = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str) \
                and node is not docstring:
            words = node.value.replace("/", " ").replace(".", " ").split()
            bad += [w for w in FORBIDDEN if w in words]
            bad += [t for t in templates if t in node.value]
        elif isinstance(node, ast.Name):
            bad += [node.id] if node.id in FORBIDDEN else []
        elif isinstance(node, ast.Attribute):
            bad += [node.attr] if node.attr in FORBIDDEN else []
        elif isinstance(node, ast.alias):
            bad += [node.name] if node.name in FORBIDDEN else []
        elif isinstance(node, ast.ImportFrom | ast.Import):
            mods = [node.module or ""] if isinstance(node, ast.ImportFrom) else \
                [a.name for a in node.names]
            bad += [m for m in mods if m.startswith("rigidsym.codegen.backends.")]
    assert not bad, bad


@pytest.fixture
def toy_target(tmp_path):
    """A target made by the README's steps alone: a folder with a template, a printer, a
    render function, a Target, registered; unregistered after."""
    folder = tmp_path / "toy" / "templates"
    folder.mkdir(parents=True)
    (folder / "toy.txt.j2").write_text("{{ name }}: {{ outputs }} output(s)\n")

    def render(ctx: RenderContext) -> dict[str, str]:
        env = backends.environment(folder)
        return {f"toy/{kc.kernel.name}.txt": env.get_template("toy.txt.j2").render(
            name=kc.kernel.name, outputs=len(kc.kernel.outputs)) for kc in ctx.kernels}

    target = register(Target("toy", folder, KernelNumPyPrinter, render))
    try:
        yield target
    finally:
        unregister("toy")
    assert "toy" not in [t.name for t in targets()]


def test_a_target_added_by_the_readme_steps_generates_its_files(toy_target):
    assert targets()[-1] is toy_target
    k = Kernel(name="toy_cross", summary="s", formula="f", ids=("0.0",),
               sources=("rigidsym.algebra.primitives.cpm",), args=(Arg("v", (3,)),),
               outputs=(Out("w", (3,)), Out("n", ())),
               build=lambda v: {"w": v.cross(v + sp.ones(3, 1)), "n": v.dot(v)})
    res = G.generate([k])
    assert res.files["toy/toy_cross.txt"] == "toy_cross: 2 output(s)\n"
    # and every built-in package target's files beside it
    assert {"numpy/toy_cross.py", "c/toy_cross.c", "torch/toy_cross.py",
            "jax/toy_cross.py", "api.py", "kernels.json"} <= set(res.files)


def test_two_targets_writing_one_path_is_an_error(tmp_path):
    def render(ctx):
        return {"kernels.json": "", "api.py": ""}
    register(Target("clash", tmp_path, KernelNumPyPrinter, render))
    try:
        k = Kernel(name="toy_sum", summary="s", formula="f", ids=("0.0",),
                   sources=("rigidsym.algebra.primitives.cpm",), args=(Arg("a", ()),),
                   outputs=(Out("b", ()),), build=lambda a: {"b": a + 1})
        with pytest.raises(ValueError, match="target clash writes api.py"):
            G.generate([k])
    finally:
        unregister("clash")
