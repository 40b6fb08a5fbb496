"""The documentation: built with warnings as errors, its internal links resolve, and every
public callable has a docstring with its sections (or is a documented constant).

The build runs Sphinx (``docs/conf.py``: autodoc, napoleon, MyST) with ``-W`` and
``nitpicky``: a reference to a missing page, heading or public name fails it. The built
HTML is then read back: every relative link names a file that exists and an anchor that the
file holds.
"""

from __future__ import annotations

import ast
import html.parser
import importlib
import inspect
import subprocess
import sys
from pathlib import Path
from urllib.parse import unquote, urldefrag, urlparse

import pytest
from test_public_api import PUBLIC

#: skipped without its extra in the README's test command; .ci/run installs it
pytestmark = pytest.mark.extra

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"


class _Links(html.parser.HTMLParser):
    """The ids and the link targets (``href``, ``src``) of one HTML page."""

    def __init__(self):
        super().__init__()
        self.ids: set[str] = set()
        self.links: list[str] = []

    def handle_starttag(self, tag, attrs):
        for k, v in attrs:
            if k in ("id", "name") and v:
                self.ids.add(v)
            elif k in ("href", "src") and v:
                self.links.append(v)


def _parse(path: Path) -> _Links:
    p = _Links()
    p.feed(path.read_text(encoding="utf-8"))
    return p


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> Path:
    pytest.importorskip("sphinx", reason="the docs tools are in the [docs] extra")
    pytest.importorskip("myst_parser", reason="the docs tools are in the [docs] extra")
    out = tmp_path_factory.mktemp("html")
    res = subprocess.run([sys.executable, "-m", "sphinx", "-b", "html", "-W", "-n",
                          "--keep-going", "-E", "-q", str(DOCS), str(out)],
                         capture_output=True, text=True, timeout=900, cwd=ROOT)
    assert res.returncode == 0, res.stdout[-4000:] + res.stderr[-6000:]
    return out


def test_docs_build_without_warnings(built):
    for page in ("index", "api", "where-it-stands", "schema", "soundness",
                 "beyond-one-machine"):
        assert (built / f"{page}.html").is_file(), page


def test_every_markdown_page_is_in_the_contents(built):
    """The contents are a glob: a page another issue adds to docs/ needs no index edit."""
    index = _parse(built / "index.html")
    linked = {urldefrag(h)[0] for h in index.links}
    for md in DOCS.glob("*.md"):
        if md.stem != "index" and not md.name.startswith("_"):     # _*: sources, not pages
            assert f"{md.stem}.html" in linked, md.name


def test_internal_links_resolve(built):
    bad = []
    pages = {p: _parse(p) for p in built.rglob("*.html")}
    for page, parsed in pages.items():
        for link in parsed.links:
            if urlparse(link).scheme or link.startswith(("mailto:", "//")):
                continue
            parts = urlparse(link)
            target, frag = parts.path, parts.fragment  # "?v=..." of static files aside
            dest = (page.parent / unquote(target)).resolve() if target else page
            if not dest.exists():
                bad.append(f"{page.name}: {link} (no such file)")
            elif frag and dest.suffix == ".html":
                ids = pages[dest].ids if dest in pages else _parse(dest).ids
                if unquote(frag) not in ids:
                    bad.append(f"{page.name}: {link} (no anchor {frag!r})")
    assert not bad, "\n".join(bad[:40])


def test_the_readme_links_into_the_docs(built):
    """The README's links to docs/ pages name built pages and headings that exist."""
    import re

    bad = []
    for target in re.findall(r"\]\((docs/[^)\s]+)\)", (ROOT / "README.md").read_text()):
        path, _, frag = target.partition("#")
        page = built / Path(path).relative_to("docs").with_suffix(".html")
        if not (ROOT / path).is_file() or not page.is_file():
            bad.append(f"{target}: no such page")
        elif frag and frag not in _parse(page).ids:
            bad.append(f"{target}: no heading {frag!r}")
    assert not bad, bad


def test_the_api_reference_covers_the_public_names(built):
    text = (built / "api.html").read_text(encoding="utf-8")
    missing = []
    for mod, names in PUBLIC.items():
        # the vocabulary re-exported by rigidsym is documented once, under rigidsym.declare
        where = "rigidsym.declare" if mod == "rigidsym" else mod
        for n in names:
            m = where if n in PUBLIC["rigidsym.declare"] else mod
            if f'id="{m}.{n}"' not in text:
                missing.append(f"{m}.{n}")
    assert not missing, missing


# ----------------------------------------------------------------------------- docstrings
def _doc_comment(modname: str, name: str) -> bool:
    """Whether ``name`` has a ``#:`` doc comment in ``modname`` or in the module it is
    imported from there (``from X import name``)."""
    pytest.importorskip("sphinx", reason="the docs tools are in the [docs] extra")
    from sphinx.pycode import ModuleAnalyzer

    if ("", name) in ModuleAnalyzer.for_module(modname).find_attr_docs():
        return True
    src = inspect.getsource(importlib.import_module(modname))
    for node in ast.walk(ast.parse(src)):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0 \
                and any(a.name == name and a.asname in (None, name) for a in node.names):
            return _doc_comment(node.module, name)
    return False


def _problems(modname: str, name: str) -> list[str]:
    obj = getattr(importlib.import_module(modname), name)
    if not (inspect.isclass(obj) or inspect.isroutine(obj)):
        home = getattr(importlib.import_module(modname), "_WHERE", {}).get(name, modname)
        return [] if _doc_comment(home, name) else ["a constant without a #: doc comment"]
    doc = inspect.getdoc(obj) or ""
    if not doc.strip():
        return ["no docstring"]
    if inspect.isclass(obj):
        return [] if ("Args:" in doc or "Attributes:" in doc) else ["no Args/Attributes"]
    out = []
    sig = inspect.signature(obj)
    if sig.parameters and "Args:" not in doc:
        out.append("no Args")
    if sig.return_annotation not in (None, "None") and "Returns:" not in doc:
        out.append("no Returns")
    return out


@pytest.mark.parametrize("modname", sorted(PUBLIC))
def test_every_public_callable_has_args_and_returns(modname):
    bad = [f"{modname}.{n}: {', '.join(p)}" for n in PUBLIC[modname]
           if (p := _problems(modname, n))]
    assert not bad, "\n".join(bad)


#: the modules whose docstrings hold examples (``>>>``): the reference shows them, so they run
DOCTEST_MODULES = ("rigidsym.api", "rigidsym.declare", "rigidsym.exercises", "rigidsym.kernels",
                   "rigidsym.kernels.runtime.jacobians", "rigidsym.algebra.primitives")


@pytest.mark.parametrize("modname", DOCTEST_MODULES)
def test_docstring_examples_run(modname):
    import doctest

    res = doctest.testmod(importlib.import_module(modname),
                          optionflags=doctest.NORMALIZE_WHITESPACE)
    assert res.attempted >= 1 and res.failed == 0, f"{modname}: {res}"


def test_the_markdown_api_reference_is_fresh():
    """docs/api.md, readable unbuilt, is what docs/make_api_md.py makes of the docstrings
    now; a stale one names the command that rewrites it."""
    pytest.importorskip("sphinx_markdown_builder",
                        reason="sphinx-markdown-builder is not installed (the [docs] extra)")
    sys.path.insert(0, str(DOCS))
    try:
        import make_api_md
    finally:
        sys.path.remove(str(DOCS))
    text = make_api_md.render()
    assert (DOCS / "api.md").read_text(encoding="utf-8") == text, \
        "docs/api.md is stale: python docs/make_api_md.py"
    assert "automodule" not in text and "rigidsym.kernels.rotation_from_natural_invariants" \
        in text
