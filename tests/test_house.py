"""The house by meaning: the rules of the tree that docs/layout.md states, checked on the tree.

- no private name crosses a module: no ``_``-name (function, class, constant) of one module
  of ``src/`` is imported, or read as ``module._name``, by another; no ``_``-module is
  imported from outside its package's ``__init__`` (ruff's PLC2701 does not see imports
  within the package);
- each product has its package: the course and the certificates are not inside the
  verifier, nor the course inside the reports; ``kernels/__init__.py`` only re-exports;
  ``codegen/`` has at most 12 entries at its top;
- docs/layout.md describes the tree that exists: each package it names exists, and each
  package of ``src/rigidsym`` is named.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src"
PKG = SRC / "rigidsym"
LAYOUT = ROOT / "docs" / "layout.md"


def _private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def _modules() -> dict[str, Path]:
    out = {}
    for p in PKG.rglob("*.py"):
        parts = list(p.relative_to(SRC).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = p
    return out


def _crossings(name: str, tree: ast.Module, is_init: bool, mods: dict) -> list[str]:
    """The private names module ``name`` takes from other modules, as ``line: what``."""
    package = name if is_init else name.rpartition(".")[0]
    aliases: dict[str, str] = {}   # local name -> the rigidsym module it is bound to
    out = []

    def own_init_submodule(full: str) -> bool:
        return is_init and full in mods and full.rpartition(".")[0] == name

    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[:len(package.split(".")) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if not target.startswith("rigidsym"):
                continue
            for a in node.names:
                full = f"{target}.{a.name}"
                if full in mods:
                    aliases[a.asname or a.name] = full
                if own_init_submodule(full):
                    continue
                private_path = any(_private(c) for c in target.split("."))
                if _private(a.name) or (private_path and target.rpartition(".")[0] != name):
                    out.append(f"{node.lineno}: from {target} import {a.name}")
        elif isinstance(node, ast.Import):
            for a in node.names:
                if not a.name.startswith("rigidsym"):
                    continue
                if a.asname:
                    aliases[a.asname] = a.name
                if any(_private(c) for c in a.name.split(".")):
                    out.append(f"{node.lineno}: import {a.name}")
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) \
                and node.value.id in aliases and _private(node.attr):
            full = f"{aliases[node.value.id]}.{node.attr}"
            if not own_init_submodule(full):
                out.append(f"{node.lineno}: {full}")
    return out


def test_no_private_name_crosses_a_module():
    mods = _modules()
    bad = []
    for name, path in sorted(mods.items()):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        bad += [f"{path.relative_to(ROOT)}:{c}"
                for c in _crossings(name, tree, path.name == "__init__.py", mods)]
    assert not bad, ("private names used across modules (make the name public in its "
                     "module, with a docstring):\n" + "\n".join(bad))


def test_the_rule_sees_each_way_of_crossing():
    """The check itself: each spelling of a crossing is found, and the allowed ones are not."""
    mods = {"rigidsym.a": None, "rigidsym.a.b": None, "rigidsym.a._c": None, "rigidsym.d": None}
    cases = {
        "from rigidsym.d import _x": True,
        "from rigidsym.a._c import y": True,
        "import rigidsym.a._c": True,
        "from rigidsym import d\nd._x": True,
        "import rigidsym.d as D\nD._x": True,
        "from rigidsym.d import x\nfrom rigidsym.a import b": False,
        "from rigidsym.d import __version__": False,
    }
    for code, crosses in cases.items():
        found = _crossings("rigidsym.e", ast.parse(code), False, mods)
        assert bool(found) is crosses, (code, found)
    # a package's own _-module, imported by its __init__: allowed
    assert not _crossings("rigidsym.a", ast.parse("from rigidsym.a import _c"), True, mods)
    assert _crossings("rigidsym.d", ast.parse("from rigidsym.a import _c"), True, mods)


def _entries(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir()
                  if p.name != "__pycache__" and (p.suffix == ".py" or
                                                  (p.is_dir() and (p / "__init__.py").exists())))


def test_each_product_has_its_package():
    # the modules of checking/ itself (its sub-package certifying/ is where certificates live)
    checking = [n for n in _entries(PKG / "checking") if n.endswith(".py")]
    assert not [n for n in checking
                if re.match(r"(worked|exam|grad|course|cert|cof|coq)\w*\.py$", n)], checking
    report = _entries(PKG / "report")
    assert not [n for n in report
                if re.match(r"(exam|grad|course|roster|answers|notebook|exercise)\w*\.py$", n)], \
        report
    assert len(_entries(PKG / "codegen")) <= 12, _entries(PKG / "codegen")
    assert (PKG / "course" / "worked" / "__init__.py").exists()
    assert (PKG / "checking" / "certifying" / "__init__.py").exists()


def test_kernels_init_only_reexports():
    """``kernels/__init__.py`` holds its docstring, imports and ``__all__``, nothing else."""
    tree = ast.parse((PKG / "kernels" / "__init__.py").read_text(encoding="utf-8"))
    other = []
    for node in tree.body:
        if isinstance(node, ast.Import | ast.ImportFrom):
            continue
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant):
            continue  # the docstring
        targets = [t.id for t in getattr(node, "targets", [getattr(node, "target", None)])
                   if isinstance(t, ast.Name)]
        if isinstance(node, ast.Assign | ast.AugAssign) and targets == ["__all__"]:
            continue
        other.append(f"{node.lineno}: {type(node).__name__}")
    assert not other, other


def test_the_course_front_door_lists_what_it_serves():
    import rigidsym.course as course

    assert sorted(course.__all__) == sorted(course.FRONT_DOOR)
    for name in course.__all__:
        assert getattr(course, name) is not None, name
    import rigidsym.exercises as ex

    served = {where.partition(":")[2] or name: name for name, where in course.FRONT_DOOR.items()
              if where.startswith("exercises")}
    assert all(getattr(ex, n) is getattr(course, served[n]) for n in ex.__all__)
    # a front-door name never shadows a submodule of the package
    assert not [n for n in course.__all__ if (Path(course.__file__).parent / f"{n}.py").exists()
                or (Path(course.__file__).parent / n).is_dir()]


def _packages() -> list[str]:
    return sorted(".".join(p.parent.relative_to(SRC).parts) for p in PKG.rglob("__init__.py"))


def _named_in_layout() -> set[str]:
    """The packages docs/layout.md names: ``rigidsym/a/b/`` or ``a/b/`` in code spans."""
    text = LAYOUT.read_text(encoding="utf-8")
    names = set()
    for span in re.findall(r"`([^`]+)`", text):
        m = re.fullmatch(r"(?:src/)?(?:rigidsym/)?([a-z_]+(?:/[a-z_]+)*)/", span.strip())
        if m and m.group(1) not in ("src", "rigidsym", "src/rigidsym"):
            names.add("rigidsym." + m.group(1).replace("/", "."))
    return names


def test_layout_names_every_package_and_only_packages_that_exist():
    named = _named_in_layout()
    outside = {"rigidsym.derivations", "rigidsym.generated", "rigidsym.docs",
               "rigidsym.benchmarks", "rigidsym.certcheck", "rigidsym.templates"}
    missing = [p for p in _packages() if p != "rigidsym" and p not in named]
    assert not missing, f"packages docs/layout.md does not name: {missing}"
    stale = sorted(n for n in named - outside
                   if not n.startswith(tuple(o + "." for o in outside))
                   and not (SRC / n.replace(".", "/")).is_dir()
                   and not any(n.endswith("." + t) for t in ("templates", "notations")))
    assert not stale, f"docs/layout.md names packages that do not exist: {stale}"
