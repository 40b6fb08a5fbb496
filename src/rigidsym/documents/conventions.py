"""The conventions a document may leave open, and a relation decided under each.

A relation that uses the quaternion product (``\\otimes``, ``\\odot``, a conjugate of a
4-vector: Hamilton's scalar first, JPL's, or Hamilton's stored scalar last) or the tangent
order of SE(3) (a twist ``[ω; v]`` or ``[v; ω]``) where neither the reading file, a
``--let`` nor the ``--notation`` fixes it is never given a verdict from a default: it is
decided under each admissible convention. Where
the verdicts agree, that is the verdict (``under`` says each); where they differ, the
relation ``holds under X, not under Y`` (verdict ``convention-dependent``), with the
counterexample under the convention where it fails, and the reading file's line that fixes
it.
"""

from __future__ import annotations

from itertools import product

__all__ = ["CHOICES", "NAMES", "choices", "combine", "fixed", "open_in"]

#: each convention's admissible choices: the reading file's value -> the ``--let`` saying it
CHOICES = {
    "quaternion_product": {"hamilton": "\\otimes: Hamilton", "jpl": "\\otimes: JPL",
                           "hamilton-scalar-last": "\\otimes: Hamilton, scalar last"},
    "tangent_order": {"angular-first": "tangent order: angular first",
                      "linear-first": "tangent order: linear first"},
}
#: each choice in words
NAMES = {
    ("quaternion_product", "hamilton"): "Hamilton's quaternion product (scalar first, ij = k)",
    ("quaternion_product", "jpl"): "JPL's quaternion product (scalar last, ij = -k)",
    ("quaternion_product", "hamilton-scalar-last"): "Hamilton's quaternion product stored "
    "scalar last (ij = k, [x; y; z; w])",
    ("tangent_order", "angular-first"): "the tangent order [ω; v] (angular first)",
    ("tangent_order", "linear-first"): "the tangent order [v; ω] (linear first)",
}
#: the words of the engine's notes (or of its question) that say the relation uses the
#: convention
_USES = {"quaternion_product": ("quaternion product:", "quaternion product \\otimes"),
         "tangent_order": ("tangent order:",)}


def fixed(lets: list[str], notation: str | None) -> set[str]:
    """The conventions ``lets`` (in ``--let``'s words) or ``notation`` fix."""
    from rigidsym.latex import quaternions, tangent

    out = set()
    for t in lets:
        name = t.split(":", 1)[0].strip()
        if ":" in t and name in quaternions.NAMES:
            out.add("quaternion_product")
        if ":" in t and name == tangent.NAME:
            out.add("tangent_order")
    if (notation or "").strip().lower() in quaternions.NOTATION_PRODUCTS:
        out.add("quaternion_product")
    if notation in tangent.NOTATION_ORDERS:
        out.add("tangent_order")
    return out


def open_in(notes: list[str], refusal: str | None, lets: list[str],
            notation: str | None) -> list[str]:
    """The conventions a relation uses that nothing fixes, in :data:`CHOICES`' order.

    Args:
        notes: the engine's notes of its reading (under the defaults).
        refusal: the engine's refusal, if it refused the relation (the tangent order's two
            readings disagreeing is one).
        lets: the declarations it is checked with.
        notation: the ``--notation`` name, or ``None``.
    """
    done = fixed(lets, notation)
    uses = set()
    for key, words in _USES.items():
        if any(w in n for w in words for n in notes) or \
                (refusal and any(w in refusal for w in words)):
            uses.add(key)
    return [k for k in CHOICES if k in uses and k not in done]


def choices(keys: list[str]) -> list[tuple[tuple[tuple[str, str], ...], list[str]]]:
    """Each combination of the choices of ``keys``: its ``((key, value), ...)`` and lets."""
    out = []
    for combo in product(*[list(CHOICES[k].items()) for k in keys]):
        out.append((tuple((k, v) for k, (v, _) in zip(keys, combo, strict=True)),
                    [let for _, let in combo]))
    return out


def _words(combo: tuple[tuple[str, str], ...]) -> str:
    return " and ".join(NAMES[c] for c in combo)


def combine(keys: list[str], outs: list[tuple[tuple[tuple[str, str], ...], dict]]) -> dict:
    """One record's verdict fields from its verdicts under each combination of choices.

    Args:
        keys: the open conventions.
        outs: ``(combination, verdict fields)`` per combination (:func:`choices`' order).

    Returns:
        The verdict fields: the common verdict where all agree; ``convention-dependent``
        where it holds under some and not others; ``undecided`` where one is not decided.
        ``under`` maps each combination, in words, to its verdict.
    """
    under = {_words(c): o["verdict"] for c, o in outs}
    verdicts = {o["verdict"] for _, o in outs}
    fix = "; fix it in the reading file's [conventions]: " + "; ".join(
        " or ".join(f'{k} = "{v}"' for v in CHOICES[k]) for k in keys)
    first = outs[0][1]
    if len(verdicts) == 1:
        word = {"verified": "holds", "does-not-hold": "does not hold"}.get(
            first["verdict"], first["verdict"])
        note = (f"{word} under each convention the document leaves open: "
                + "; ".join(under))
        reason = first.get("reason")
        return first | {"under": under,
                        "reason": f"{reason} ({note})" if reason else note}
    holds = [c for c, o in outs if o["verdict"] == "verified"]
    fails = [(c, o) for c, o in outs if o["verdict"] == "does-not-hold"]
    if verdicts == {"verified", "does-not-hold"}:
        c, o = fails[0]
        return {"verdict": "convention-dependent", "method": o.get("method"),
                "read_as": first.get("read_as"),
                "counterexample": o.get("counterexample"), "point": o.get("point"),
                "corrected": None, "corrected_latex": None, "cause": None,
                "under": under,
                "reason": (f"holds under {', '.join(_words(h) for h in holds)}, not under "
                           f"{', '.join(_words(f) for f, _ in fails)} (counterexample under "
                           f"{_words(c)}: {o.get('counterexample') or 'not printed'})" + fix)}
    return {"verdict": "undecided", "method": "conventions", "read_as": first.get("read_as"),
            "under": under, "reason": "under the conventions the document leaves open: "
            + "; ".join(f"{w}: {v}" for w, v in under.items()) + fix}
