"""User modules: ids namespace:name, constraints scoped to atoms, reloading, bad input."""

from __future__ import annotations

import json
import textwrap

import pytest

from rigidsym.cli import main
from rigidsym.registry import declarations as registry
from rigidsym.registry import usermodules
from rigidsym.registry.declarations import REGISTRY, BadInput, load_all

load_all()  # the book first: its unit vector e and angle phi exist in this process


def _module(tmp_path, name: str, body: str):
    path = tmp_path / f"{name}.py"
    path.write_text("import sympy as sp\nfrom rigidsym import *\n\n" + textwrap.dedent(body))
    return path


def _run(argv, capsys):
    code = main(argv)
    cap = capsys.readouterr()
    return code, cap.out, cap.err


@pytest.fixture(autouse=True)
def _forget_user_ids():
    """Each test starts with the book only (user modules are process-wide state)."""
    yield
    for k in [k for k in REGISTRY if registry.is_user_id(k)]:
        del REGISTRY[k]
    usermodules.LOADED.clear()


def test_a_free_e_is_not_the_books_unit_vector(tmp_path, capsys):
    # the book declares unit_vector("e") (atoms e_1, e_2, e_3) and angle("phi"); a user's free
    # vector e and a user's angle named e_1 must not pick up those constraints by name
    assert any(c.kind == "unit" for c in _book_constraints("e_1"))
    path = _module(tmp_path, "freee", '''
        e = vector("e")            # free: e . e = 1 does not hold
        u = unit_vector("e")       # the same name, constrained: it does
        a = angle("e_1")           # an angle named like a component of the book's e

        @equation("free:norm", "e.e = 1 for a free e", expected="does-not-hold")
        def free_norm():
            n = (e.T * e)[0]
            return Statement([Rel(n, 1)], corrected=[Rel(n, e[0]**2 + e[1]**2 + e[2]**2)])

        @equation("free:unit-norm", "e.e = 1 for a unit e")
        def unit_norm():
            return Statement([Rel((u.T * u)[0], 1)])

        @equation("free:angle", "cos^2 + sin^2 = 1 for an angle named e_1")
        def angle_named_e1():
            return Statement([Rel(sp.cos(a)**2 + sp.sin(a)**2, 1)])
    ''')
    code, out, _ = _run(["verify", "--module", str(path), "--quiet", "--jobs", "1"], capsys)
    assert code == 0, out
    assert "does-not-hold 1" in out and "verified 2" in out and "undecided 0" in out


def _book_constraints(name):
    from rigidsym.algebra.symbols import constraint_of
    from rigidsym.zero.decide import make_plan

    found = []
    for eq_id in ("3.1", "3.16"):
        st = REGISTRY[eq_id].build()
        for v in st.model.values():
            atoms = getattr(v, "free_symbols", set())
            found += [constraint_of(a) for a in atoms if getattr(a, "name", "") == name]
    make_plan([])  # the zero test imports cleanly with the book loaded
    return [c for c in found if c is not None]


def test_counterexample_is_exact_for_a_user_does_not_hold(tmp_path):
    import rigidsym

    path = _module(tmp_path, "slip", '''
        e, phi = unit_vector("e"), angle("phi")
        E = cpm(e)

        @equation("slip:rodrigues", "sign slip", expected="does-not-hold")
        def slip():
            good = sp.eye(3) + sp.sin(phi) * E + (1 - sp.cos(phi)) * E * E
            bad = sp.eye(3) - sp.sin(phi) * E + (1 - sp.cos(phi)) * E * E
            return Statement([Rel(rotation_from_natural_invariants(e, phi), bad)],
                             corrected=[Rel(rotation_from_natural_invariants(e, phi), good)])
    ''')
    r = rigidsym.verify(modules=[path])[0]
    assert r.verdict == "does-not-hold" and r.cause == registry.USER_CAUSE_DEFAULT
    ce = r.counterexample
    assert ce["lhs"] != ce["rhs"] and "phi" in ce["point"]


def test_reloading_replaces_declarations_and_their_statements(tmp_path):
    body = '''
        x = scalar("x")

        @equation("re:one", "TITLE")
        def one():
            return Statement([Rel(x + 0, x * VALUE)])
    '''
    path = _module(tmp_path, "re", body.replace("TITLE", "first").replace("VALUE", "1"))
    um = usermodules.load(path)
    assert REGISTRY["re:one"].title == "first"
    first = REGISTRY["re:one"].build()
    path.write_text(path.read_text().replace("first", "second").replace("x * 1", "x * 2"))
    um2 = usermodules.load(path)  # no "declared twice": the module's ids are replaced
    assert um2.name == um.name and um2.ids == ("re:one",)
    assert REGISTRY["re:one"].title == "second"
    second = REGISTRY["re:one"].build()
    assert second is not first and str(second.printed[0].rhs) == "2*x"


def test_the_same_id_in_two_modules_names_both_places(tmp_path):
    decl = '''
        @equation("dup:eq", "twice")
        def f():
            return Statement([Rel(scalar("y"), scalar("y"))])
    '''
    a = _module(tmp_path, "dupa", decl)
    (tmp_path / "other").mkdir()
    b = _module(tmp_path / "other", "dupb", decl)
    usermodules.load(a)
    with pytest.raises(BadInput) as exc:
        usermodules.load(b)
    msg = str(exc.value)
    assert "dup:eq" in msg and str(a) in msg and str(b) in msg and "\n" not in msg


@pytest.mark.parametrize("body, words", [
    ("raise RuntimeError('boom on import')", "boom on import"),
    ("@equation('3.16', 'mine')\ndef f():\n    return None", "reserved"),
    ("@equation('Notes:x', 'bad')\ndef f():\n    return None", "namespace:name"),
    ("@equation('notes', 'bad')\ndef f():\n    return None", "namespace:name"),
    ("@equation('w:wrong', 'wrong type')\ndef f():\n    return 42", "not Statement"),
    ("@equation('w:rel', 'not a Rel')\ndef f():\n    return Statement([(1, 1)])", "not Rel"),
])
def test_bad_user_modules_exit_2_with_one_line(tmp_path, capsys, body, words):
    path = _module(tmp_path, "bad", body + "\n")
    code, _, err = _run(["verify", "--module", str(path), "--quiet"], capsys)
    err = err.strip()
    assert code == 2 and "\n" not in err
    assert err.startswith("rigidsym: error: module ") and str(path) in err and words in err


def test_missing_file_and_unknown_dotted_name_exit_2(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    for spec in (str(tmp_path / "nowhere.py"), "no_such_module_here"):
        code, _, err = _run(["verify", "--module", spec, "--quiet"], capsys)
        assert code == 2 and spec in err and "\n" not in err.strip()


def test_an_exception_inside_one_declaration_is_that_id_undecided(tmp_path, capsys):
    path = _module(tmp_path, "partial", '''
        @equation("part:ok", "fine")
        def ok():
            x = scalar("x")
            return Statement([Rel(2 * x, x + x)])

        @equation("part:broken", "raises")
        def broken():
            raise ZeroDivisionError("inside the declaration")
    ''')
    code, out, _ = _run(["verify", "--module", str(path), "--quiet", "--jobs", "1",
                         "--json", str(tmp_path / "r.json")], capsys)
    assert code == 1  # undecided differs from the expected verified
    rows = {r["id"]: r for r in json.loads((tmp_path / "r.json").read_text())["equations"]}
    assert rows["part:ok"]["verdict"] == "verified"
    assert rows["part:broken"]["verdict"] == "undecided"
    assert "inside the declaration" in rows["part:broken"]["decision"]


def test_dotted_name_from_the_current_directory_and_id_selection(tmp_path, capsys,
                                                                  monkeypatch):
    pkg = tmp_path / "mynotes"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    _module(pkg, "algebra", '''
        x, y = scalar("x"), scalar("y")

        @equation("alg:square", "square of a sum", section="algebra")
        def square():
            return Statement([Rel((x + y)**2, x**2 + 2*x*y + y**2)])

        @equation("alg:wrong", "a wrong square", section="algebra")
        def wrong():
            return Statement([Rel((x + y)**2, x**2 + y**2)])
    ''')
    monkeypatch.chdir(tmp_path)
    code, out, _ = _run(["verify", "--module", "mynotes.algebra", "alg:square", "--quiet"],
                        capsys)
    assert code == 0 and "1 checked" in out
    # the module's own ids: the wrong square has an exact counterexample, so it does not hold
    # although it declares no corrected form; the run exits 1 (it was declared as verified)
    code, out, _ = _run(["verify", "--module", "mynotes.algebra", "--quiet", "--jobs", "1"],
                        capsys)
    assert code == 1 and "2 checked" in out and "MISMATCH (alg:wrong)" in out
    assert "computed does-not-hold, expected verified" in out
    code, out, _ = _run(["show", "alg:square", "--module", "mynotes.algebra"], capsys)
    assert code == 0 and "mynotes.algebra" in out and "algebra.py" in out


def test_report_and_generate_for_a_user_module(tmp_path, capsys):
    path = _module(tmp_path, "kern", '''
        from rigidsym.codegen.spec import Arg, Kernel, Out

        def doubled(x):
            return 2 * x

        x = scalar("x")

        @equation("kern:double", "double")
        def double():
            return Statement([Rel(doubled(x), x + x)])

        KERNELS = [Kernel("doubled_value", "Twice x.", "2 x", ("kern:double",), (doubled,),
                          (Arg("x", ()),), (Out("y", ()),),
                          lambda x: {"y": doubled(x)})]
    ''')
    out = tmp_path / "report"
    code, _, _ = _run(["report", "--module", str(path), "--out", str(out), "--jobs", "1"],
                      capsys)
    assert code == 0
    md = (out / "kern.md").read_text()
    assert md.startswith("# kern checked: verdicts\n\nSource: the user module kern.")
    assert json.loads((out / "kern.json").read_text())["equations"][0]["id"] == "kern:double"
    page = (out / "kern.html").read_text()
    assert "<title>kern checked: verdicts</title>" in page and "Angeles" not in page
    assert "Source: the user module kern." in page and "exercises.html" not in page
    gen = tmp_path / "gen"
    assert main(["generate", "--module", str(path), "--out", str(gen)]) == 0
    c_text = (gen / "c" / "doubled_value.c").read_text()
    assert "source: kern.doubled (composed in kern)" in c_text
    assert "derivations" not in c_text
    # the PyTorch and JAX programs too, from the same optimised program
    for backend in ("torch", "jax"):
        text = (gen / backend / "doubled_value.py").read_text()
        assert "source: kern.doubled (composed in kern)" in text and "2.0*x" in text
    assert main(["generate", "--module", str(path), "--out", str(gen), "--check"]) == 0
    (gen / "numpy" / "doubled_value.py").write_text("# edited by hand\n")
    assert main(["generate", "--module", str(path), "--out", str(gen), "--check"]) == 1
    foreign = tmp_path / "foreign"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("mine")
    capsys.readouterr()
    code, _, err = _run(["generate", "--module", str(path), "--out", str(foreign)], capsys)
    assert code == 2 and (foreign / "notes.txt").exists() and "not empty" in err


def test_a_user_file_named_like_a_package_does_not_shadow_it(tmp_path, monkeypatch):
    """The user's folder is first on ``sys.path`` only while the module executes (its sibling
    imports work then and later), never ahead of the installed packages afterwards: loading
    examples/modern_robotics.py once made ``import modern_robotics`` in the same process
    return the example (the peers' table then failed on every row)."""
    import importlib
    import sys

    monkeypatch.setattr(sys, "path", list(sys.path))
    (tmp_path / "colorsys.py").write_text("SHADOW = True\n")   # a stdlib module's name
    (tmp_path / "mysibling.py").write_text("VALUE = 7\n")
    (tmp_path / "mylate.py").write_text("VALUE = 8\n")
    path = _module(tmp_path, "shadowing", '''
        import mysibling

        def late():
            import mylate
            return mylate.VALUE

        @equation("shadow:one", "1 = 1 with a sibling import")
        def one():
            return Statement([Rel(sp.Integer(mysibling.VALUE - 6), 1)])
    ''')
    for m in ("colorsys", "mysibling", "mylate"):
        monkeypatch.delitem(sys.modules, m, raising=False)
    um = usermodules.load(str(path))
    assert REGISTRY["shadow:one"].build() is not None
    assert sys.path[-1] == str(tmp_path) and str(tmp_path) not in sys.path[:-1]
    monkeypatch.delitem(sys.modules, "colorsys", raising=False)
    assert not hasattr(importlib.import_module("colorsys"), "SHADOW")
    assert sys.modules[um.name].late() == 8
