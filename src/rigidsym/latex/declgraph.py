"""The ``--let`` declarations as a graph: which glyphs each model (or
function) mentions, read from lark's parse tree without deciding any shape, and the order
in which the models are read: each after the models it mentions, ties by name, so any
order of the ``--let``s gives the same reading. A cycle is an error naming it.

Reading in the order given would make a symbol met in a model before its own declaration a
free scalar (``--let '\\mathbf{w} = F\\mathbf{x}' --let 'F = -I_3'`` would make ``F`` a
scalar and the check not hold, while the other order verifies).
"""

from __future__ import annotations

import heapq

import lark

from rigidsym.core.errors import BadInput

__all__: list[str] = []

_GLYPH_RULES = {"glyph", "accented", "accented_bare", "arrow"}


def glyph_keys(latex: str) -> set[str]:
    """The glyph keys a LaTeX expression mentions (``\\mathbf{w} = F\\mathbf{x}``:
    ``{\\mathbf{w}, F, \\mathbf{x}}``), each as the parser keys it, with no shape decided;
    the identity's and zero's glyphs (``\\mathbf{I}``, ``I``, ``\\mathbf{0}``) too, which a
    ``--let`` may name.

    Raises:
        LatexError: LaTeX that does not parse.
    """
    from rigidsym.latex.lexing import tree
    from rigidsym.latex.transformer.chapter import LatexTransformer

    keys: set[str] = set()
    todo = [tree(f"0 = {latex}")]  # the grammar reads relations
    while todo:
        t = todo.pop()
        if not isinstance(t, lark.Tree):
            continue
        if t.data in _GLYPH_RULES:
            build = LatexTransformer(None, {}, False, True)
            try:
                read = build.transform(t)
            except lark.exceptions.VisitError:
                read = None  # a glyph no default rule reads: the parse proper says why
            keys |= set(build.glyphs)
            # a glyph the rules read as a value (\mathbf{I}, I: the identity where nothing
            # declares it) is still a name a --let may declare: mentioned
            if isinstance(getattr(read, "key", None), str):
                keys.add(read.key)
            continue
        todo.extend(t.children)
    return keys


def model_order(lets: list, mentions: dict[str, set[str]]) -> list:
    """The model (and function) ``--let``s, each after those whose NAME it mentions.

    Args:
        lets: the declarations (:class:`~rigidsym.latex.lets.Let`); only those with a
            model (``latex``) are ordered.
        mentions: per model's key, the glyph keys its LaTeX mentions (:func:`glyph_keys`).

    Returns:
        The model ``Let``s in a topological order, ties by key (independent of the order
        given).

    Raises:
        BadInput: models that mention each other in a cycle, the cycle named
            (``A -> B -> A``). A model that mentions only itself is left to the reader (its
            own message).
    """
    models = {x.key: x for x in lets if x.latex}
    deps = {k: (mentions.get(k, set()) & set(models)) - {k} for k in models}
    users: dict[str, set[str]] = {k: set() for k in models}
    for k, ds in deps.items():
        for d in ds:
            users[d].add(k)
    left = {k: len(ds) for k, ds in deps.items()}
    ready = [k for k, n in left.items() if n == 0]
    heapq.heapify(ready)
    out = []
    while ready:
        k = heapq.heappop(ready)
        out.append(models[k])
        for u in users[k]:
            left[u] -= 1
            if left[u] == 0:
                heapq.heappush(ready, u)
    if len(out) < len(models):
        raise BadInput(f"--let: the models refer to each other in a cycle: "
                       f"{' -> '.join(_cycle({k: deps[k] for k in left if left[k]}))}")
    return out


def _cycle(deps: dict[str, set[str]]) -> list[str]:
    """One cycle of a graph where every node left has a dependency left."""
    k = min(deps)
    path: list[str] = []
    while k not in path:
        path.append(k)
        k = min(d for d in deps[k] if d in deps)
    return path[path.index(k):] + [k]
