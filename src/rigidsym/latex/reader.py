"""Read a LaTeX statement: :func:`parse_latex` (lark's parse, then the transformer of
:mod:`rigidsym.latex.transformer.chapter`), with errors that say where and what was expected."""

from __future__ import annotations

import lark
import sympy as sp

from rigidsym.core.errors import BadInput
from rigidsym.latex.lexing import Parsed, Relation, tree
from rigidsym.latex.shapes import LatexError, as_scalar, loose, matrix_shape
from rigidsym.latex.transformer.chapter import LatexTransformer, value_of

__all__ = ["parse_latex", "construct_text"]


def parse_latex(latex: str, section: str | None = None, overrides: dict | None = None,
                block_rows: bool = False, reader: bool = False,
                functions: dict | None = None, choices: dict | None = None,
                models: dict | None = None, renamed: frozenset[str] = frozenset()) -> Parsed:
    """Parse a LaTeX statement into relations of book symbols.

    Args:
        latex: the LaTeX (one or more relations separated by ``,``, ``\\quad`` or
            ``\\text{or}``; ``=``/``\\equiv`` chains; ``aligned`` blocks).
        section: the book section whose rows of the book's glyph table (the one its
            reading names, :func:`rigidsym.latex.glyph_table`) name the glyphs (``"3.4.2"``);
            ``"*"``: only the section-free rows; ``None`` (the default: a text of one's own
            is not the book's): no row of any table (every glyph by the default rules, or
            by ``overrides``).
        overrides: glyph rows by LaTeX key that take precedence (a per-id note's).
        block_rows: read a bracket ``[A v]`` whose column separator was lost (the
            conversion's slip in (3.77b-d), (3.97a-c)) as a block row.
        reader: a reader's LaTeX (``rigidsym check --latex``): ``[x]`` of one 3- or
            6-vector symbol or product is its hat, a plain ``I`` no override declares is the
            identity, an identity is sized by its neighbours
            (``rigidsym.latex.transformer.rigid_motions``).
        functions: the ``--let`` functions by LaTeX key: ``expand(args)`` gives
            ``(value, parameter names)``, the body with the arguments substituted.
        choices: how to read each choice point by key (``{"R": "apply"}``): ``X(y)``
            with ``X`` a model and ``y`` no scalar, a product unless told.
        models: the models read so far, their values by symbol name: ``d/dt`` of a model
            of a function of time differentiates its value.
        renamed: the keys of plain glyphs that no row or override names and that stand
            beside a bold glyph of the same letter (``\\theta`` beside
            ``\\boldsymbol\\theta``): named with a trailing ``_`` (printed the same), so that
            the scalar and the vector stay two symbols.

    Returns:
        A :class:`Parsed`.

    Raises:
        LatexError: unparseable LaTeX (position, caret, expected constructs), an unknown
            macro (named) or shapes that do not fit.
    """
    if not isinstance(latex, str) or not latex.strip():
        raise LatexError(f"latex: expected a non-empty LaTeX string, got {latex!r}")
    tree = _tree(latex)
    build = LatexTransformer(section, overrides or {}, block_rows, reader)
    build.braces = []
    build.functions = functions or {}
    build.choices = choices or {}
    build.model_rhs = models or {}
    build.renamed = renamed
    try:
        stmts = build.transform(tree)
    except lark.exceptions.VisitError as exc:
        if isinstance(exc.orig_exc, LatexError):
            exc.orig_exc.glyphs = dict(build.glyphs)  # those read before it: for hints
            exc.orig_exc.choice_points = dict(build.choice_points)
            raise exc.orig_exc from None
        if isinstance(exc.orig_exc, BadInput):
            raise exc.orig_exc from None
        # an internal error (sympy's, say) is named by the construct, never by its text;
        # two glyphs of one name and different shapes (\theta beside \boldsymbol\theta)
        # are named too, the likely cause
        err = LatexError(f"cannot read {latex!r}: an internal error at the construct "
                         f"{construct_text(exc.obj)!r} ({exc.rule}){_same_name(build)}; say "
                         f"it another way or report it", "internal")
        err.glyphs = dict(build.glyphs)  # those read before it: the --lets involved
        raise err from None
    out = Parsed(readings=build.readings, glyphs=build.glyphs,
                 applied=build.applied, choice_points=build.choice_points)
    for st in stmts:
        _, exprs, ops = st
        exprs = [as_scalar(value_of(e)) for e in exprs]
        sized = next((matrix_shape(e) for e in exprs if matrix_shape(e)
                      and type(e) is not sp.ZeroMatrix), None)
        exprs = [sp.ZeroMatrix(*sized) if type(e) is sp.ZeroMatrix and sized else e
                 for e in exprs]  # "= \mathbf{0}": the zero of the other side's shape
        if reader and sized and sized != (1, 1) and any(e is sp.S.Zero for e in exprs):
            # "Q e - e = 0": the books write a plain 0 for the zero vector or matrix, and a
            # scalar equal to a 3-vector means nothing else (said in the reading)
            exprs = [sp.ZeroMatrix(*sized) if e is sp.S.Zero else e for e in exprs]
            out.readings.append(f"0: the {sized[0]}×{sized[1]} zero (the shape of the "
                                f"other side)")
        sized = next((matrix_shape(e) for e in exprs if matrix_shape(e) and not loose(e)),
                     sized) if reader else sized
        if reader and sized and sized[0] == sized[1]:  # "= I": the identity of that size
            exprs = [sp.Identity(sized[0]) if type(e) is sp.Identity else e
                     for e in exprs]  # (not an I_3: rigidsym.latex.transformer.meanings)
        out.chains.append(exprs)
        out.ops.append(ops)
    for label, body in build.braces:  # an underbrace whose label is a symbol: a member
        if isinstance(label, sp.Symbol | sp.MatrixSymbol):
            out.chains.append([label, as_scalar(body)])
            out.ops.append(["="])
            out.readings.append(f"underbrace: {label} is a member of its own")
    for c, exprs in enumerate(out.chains):
        for k in range(len(exprs) - 1):
            out.relations.append(Relation(exprs[k], exprs[k + 1], out.ops[c][k], c, k))
    return out


def construct_text(t) -> str:
    """The LaTeX tokens of a parse subtree joined by spaces (``\\det ( M ) M``): a
    construct named in a message (the parser keeps no positions)."""
    if isinstance(t, lark.Token):
        return str(t)
    if not isinstance(t, lark.Tree):
        return str(t)
    return " ".join(str(v) for v in t.scan_values(lambda v: isinstance(v, lark.Token)))


def _tree(latex: str):
    """lark's parse tree, or a :class:`LatexError` that says where and what was expected
    (:func:`rigidsym.latex.lexing.tree`: pylatexenc's boundaries of the macros)."""
    return tree(latex)


def _same_name(build) -> str:
    """The words naming glyphs that share one name with different shapes (the scalar
    ``\\theta`` and the vector ``\\boldsymbol\\theta`` are both ``theta``), or ``""``."""
    rows = {**getattr(build, "overrides", {}), **getattr(build, "glyphs", {})}
    by_name: dict = {}
    for key, g in rows.items():
        by_name.setdefault(getattr(g, "name", None), {})[key] = getattr(g, "shape", None)
    pairs = [sorted(keys) for name, keys in by_name.items()
             if name and len({str(v) for v in keys.values()}) > 1]
    if not pairs:
        return ""
    keys = pairs[0]
    return (f" (the symbols {' and '.join(keys)} share the name "
            f"{rows[keys[0]].name!r} with different shapes: rename one, in the LaTeX and "
            f"its --let (the scalar \\vartheta for \\theta, say))")

