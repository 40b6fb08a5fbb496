"""Sphinx configuration of the rigidsym documentation (the API reference and the measured
pages).

Built by ``tests/test_docs.py`` with warnings as errors (``-W``) and every cross-reference
checked (``nitpicky``): a reference to a public name, a page or a heading that does not
exist fails the build. No intersphinx: CI reaches no outside site, so references to NumPy,
sympy or the standard library stay plain text (``nitpick_ignore_regex`` below).
"""

from __future__ import annotations

project = "rigidsym"
author = "the rigidsym maintainers"
copyright = "the rigidsym maintainers, MIT license"

extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon", "myst_parser"]
try:    # the Markdown builder of docs/api.md (docs/make_api_md.py); the [docs] extra has it
    import sphinx_markdown_builder  # noqa: F401

    extensions.append("sphinx_markdown_builder")
except ImportError:
    pass
source_suffix = {".md": "markdown"}
root_doc = "index"
# _api_source.md: the directives of the API reference, read in place of api.md (below)
exclude_patterns = ["_build", "README.md", "_*.md"]
html_theme = "alabaster"
html_static_path: list[str] = []
# the pages are built by a test, often in parallel with other work: no search index to keep
html_copy_source = False

# Markdown pages: headings get anchors (for [text](page.md#heading) links), $...$ maths
myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath"]

# API reference: Google-style docstrings (Args, Returns, Raises, Example)
napoleon_google_docstring = True
napoleon_numpy_docstring = False
# attributes as a field list: a dataclass's fields are documented once, in its docstring
napoleon_use_ivar = True
autodoc_member_order = "bysource"
autodoc_typehints = "signature"
# signatures show the aliases, not NumPy's expansion of ArrayLike into a page of unions
autodoc_type_aliases = {n: n for n in ("ArrayLike", "NDArray", "OnSingular", "OutArrays")}
autodoc_default_options = {"members": True, "undoc-members": False}

# every reference is checked, except those to other projects (no intersphinx) and to the
# private layers, which the reference does not document (README, "Public modules")
nitpicky = True
_PUBLIC = r"rigidsym(\.(declare|kernels|cli|codegen\.spec|api))?"
nitpick_ignore_regex = [
    (r"py:.*", r"(?!rigidsym\b)[\w.]+"),                    # numpy, sympy, the stdlib, ...
    (r"py:.*", r"rigidsym\.(algebra|checking|zero|printing|report|generated|derivations"
               r"|core|registry|course|_\w+|codegen\.(?!spec\b)\w+"
               r"|kernels\.(_\w+|cbuild|runtime|arrays))(\.\w+)*"),
    (r"py:.*", r"(ArrayLike|NDArray|OnSingular|OutArrays|Outcome|ModuleSpec|Path)"),
]


def _sympy_inherited(what: str, name: str, obj) -> bool:
    """A member a sympy subclass (``Cross``, ``Det``, ``Blocks``) has from sympy, not from
    rigidsym: the assumption flags sympy's metaclass writes on every class (``is_*``,
    ``default_assumptions``), or a method whose only docstring is sympy's."""
    if what != "class":
        return False
    if name == "default_assumptions" or (name.startswith("is_") and
                                         isinstance(obj, (bool, type(None)))):
        return True
    func = obj.fget if isinstance(obj, property) else getattr(obj, "__func__", obj)
    if callable(func) and not isinstance(func, type):
        import sympy

        module = getattr(func, "__module__", "") or ""
        from_sympy = any(hasattr(c, name) for c in (sympy.Basic, sympy.MatrixExpr))
        return module.startswith("sympy") or (from_sympy and not func.__doc__)
    return False


def _skip(app, what, name, obj, skip, options):
    """The declaration vocabulary is documented once, under ``rigidsym.declare``; the
    package re-exports it. Members inherited from sympy are sympy's to document."""
    import rigidsym.declare

    module = getattr(app.env, "temp_data", {}).get("autodoc:module")
    if module == "rigidsym" and name in rigidsym.declare.__all__:
        return True
    if _sympy_inherited(what, name, obj):
        return True
    return skip


def _index_toctree(app, docname, source):
    """The landing page's contents for Sphinx: a hidden glob of every page, appended here
    so that docs/index.md shows no directive on the repository page (it links every page
    itself)."""
    if docname == "index":
        source[0] += ("\n```{toctree}\n:hidden:\n:maxdepth: 2\n:glob:\n\napi\n*\n```\n")


#: the API reference's source: autodoc directives; docs/api.md is what the Markdown builder
#: made of it (committed, readable unbuilt: docs/make_api_md.py writes it, tests/test_docs.py
#: checks it fresh)
API_SOURCE = "_api_source.md"


def _api_source(app, docname, source):
    """Every build reads the directives for the page ``api``, not the Markdown on disk."""
    if docname == "api":
        from pathlib import Path

        source[0] = (Path(app.srcdir) / API_SOURCE).read_text(encoding="utf-8")


def _abbreviation(self, node):
    """A signature's keyword-only marker ``*`` (an abbreviation node), as text."""
    from docutils import nodes

    self.add(node.astext())
    raise nodes.SkipNode


def _glossary_role(name, rawtext, text, lineno, inliner, options=None, content=None):
    """``:glossary:`term``` or ``:glossary:`text <term>```: a link to the heading ``term`` of
    glossary.md (docstrings are reStructuredText; this is MyST's ``[text](glossary.md#term)``,
    resolved and checked the same way)."""
    from docutils import nodes
    from sphinx.addnodes import pending_xref
    from sphinx.util.nodes import split_explicit_title

    explicit, label, term = split_explicit_title(text)
    env = inliner.document.settings.env
    node = pending_xref(rawtext, refdomain="doc", reftarget="glossary", reftype="myst",
                        reftargetid=term.strip().lower().replace(" ", "-"),
                        refdoc=env.docname, refexplicit=True)
    node += nodes.literal(label, label)
    return [node], []


def setup(app):
    app.add_role("glossary", _glossary_role)
    app.connect("autodoc-skip-member", _skip)
    app.connect("source-read", _api_source)
    app.connect("source-read", _index_toctree)
    if "sphinx_markdown_builder" in extensions:
        from docutils import nodes

        app.add_node(nodes.abbreviation, override=True, markdown=(_abbreviation, None))
