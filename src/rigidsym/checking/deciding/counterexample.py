"""A counterexample in the statement's own symbols (what ``show`` and the reports print).

The zero test finds its counterexample in the *parametrisation* variables (a quaternion
``q`` for a rotation, stereographic ``u, v`` for a unit vector, ``t = tan(φ/2)`` for an
angle, a model's private atoms). A reader wrote the equation in the book's symbols
(``ω``, ``ȧ``, ``M_A``), so at the exact counterexample every book symbol of the failing
member is evaluated here, exactly, through the model; the parametrisation variables go to
a separate "how the point was chosen" part with one sentence on the parametrisation.

Exact values are sympy numbers (rationals, or closed forms such as ``√21/4`` for a norm or
``2 atan(3/2)`` for an angle); decimals are for reading only. Nothing here decides
anything: a failure to describe a symbol drops that symbol, never the verdict.
"""

from __future__ import annotations

import sympy as sp
from sympy.core.function import AppliedUndef

from rigidsym.algebra.symbols import TIME, constrained_atom, constraint_of
from rigidsym.checking.deciding.explicit import entries_of, explicit, shape_of
from rigidsym.checking.deciding.point_values import (
    PointValues,
    atom_base,
    decimal,
    decimal_text,
    group_base,
    plain_name,
    point_atoms,
)
from rigidsym.printing import notation
from rigidsym.zero.decide import Unsupported

__all__ = ["describe_point", "MAX_ENTRIES"]

#: a symbol whose value has more entries than this is left out (the sides still show it)
MAX_ENTRIES = 49

_KIND_SENTENCE = {
    "unit": "{n} is a unit vector written by stereographic projection of two rationals "
            "(u, v), so that {n}·{n} = 1 holds exactly",
    "unit4": "{n} is a unit 4-array written by stereographic projection of three rationals "
             "(u, v, w), so that ‖{n}‖ = 1 holds exactly",
    "rotation": "{n} is written through a rational quaternion (q₁, q₂, q₃, q₀), so that "
                "{n}ᵀ{n} = 𝟏 and det {n} = 1 hold exactly",
    "angle": "{n} is chosen through its half-angle tangent t = tan({n}/{d}), so that "
             "cos {n} and sin {n} are exact rationals and {n} = {m}·atan(t)",
    "angle_pi": "{n} is an angle on [0, π], chosen through its half-angle tangent "
                "t = tan({n}/{d}) ≥ 0, so that cos {n} and sin {n} are exact rationals and "
                "{n} = {m}·atan(t)",
    # an angle of the default range split by acos(cos θ) = |θ| (branches.py)
    "split+": "{n} is taken in [0, π] (the case acos(cos {n}) = {n}), chosen through its "
              "half-angle tangent t = tan({n}/{d}) ≥ 0, so that cos {n} and sin {n} are "
              "exact rationals and {n} = {m}·atan(t)",
    "split-": "{n} is taken in [−π, 0] (the case acos(cos {n}) = −{n}), chosen through "
              "t = tan(−{n}/{d}) ≥ 0, so that cos {n} and sin {n} are exact rationals and "
              "{n} = −{m}·atan(t)",
}


def describe_point(rel, model: dict, rels: list, plan, pt: dict, sentence: str = "",
                   split: dict | None = None) -> dict:
    """The book symbols of ``rel`` at the counterexample, and how the point was chosen.

    Args:
        rel: the failing relation (:class:`rigidsym.registry.declarations.Rel`), book symbols.
        model: the statement's model (book symbol -> first-principles value).
        rels: every relation of the statement (printed, claims, corrected): the other
            scalar and vector symbols it uses are shown too when the point fixes them.
        plan: the zero test's plan of ``rel`` (:func:`rigidsym.zero.decide.make_plan`).
        pt: the exact counterexample, plan parameter -> ``Fraction``.
        sentence: the statement's own words on its model's parameters
            (:attr:`rigidsym.registry.declarations.Statement.parametrisation`), or "".
        split: the case's substitution of a split angle (``θ -> ±b``,
            :func:`rigidsym.checking.deciding.branches.cases`): the point is described in
            ``θ``, the reader's angle, never in ``b``.

    Returns:
        ``{"symbols": [...], "chosen": {"text": ..., "params": [...]}}`` (see
        :func:`_symbol_entry` and :func:`_chosen`), or ``{}`` when the point cannot be
        described (describing never changes a verdict).
    """
    try:
        return _describe(rel, model, rels, plan, pt, sentence, split or {})
    except Exception:  # noqa: BLE001  a description must never change a verdict
        return {}


def _symbol_entry(name_text: str, name_latex: str, value, angle, vals) -> dict:
    """``{"symbol", "latex", "exact", "text", "decimal"}``; for an angle (``angle`` its
    atom) also ``cos`` and ``sin``, exact."""
    out = {"symbol": name_text, "latex": name_latex, "exact": sp.sstr(value),
           "text": notation.text(value), "decimal": decimal_text(value)}
    if angle is not None:
        out["cos"] = str(vals.scalar(sp.cos(angle)))
        out["sin"] = str(vals.scalar(sp.sin(angle)))
    return out


# --------------------------------------------------------------------------- symbols
def _book_symbols(x) -> list:
    """Book symbols (``Symbol``/``MatrixSymbol``) of one side, in a stable order."""
    syms = [s for s in sp.sympify(x).free_symbols if s != TIME] \
        if not isinstance(x, sp.MatrixBase | sp.MatrixExpr) else \
        [s for s in x.free_symbols if s != TIME]
    return sorted(syms, key=lambda s: notation.text(s))


def _owner_map(model: dict) -> dict:
    """Atom -> the model key whose value is exactly an array of bare atoms (``ȧ`` owns the
    atoms ``s34_adot_1..3``): such atoms are that book symbol, not a parametrisation."""
    owners: dict = {}
    for key, val in model.items():
        entries = entries_of(sp.Matrix(val)) if isinstance(val, sp.MatrixBase) else [val]
        ok = all(isinstance(e, sp.Symbol | AppliedUndef | sp.Derivative) for e in entries)
        if ok and len(set(entries)) == len(entries):
            for e in entries:
                owners.setdefault(e, key)
    return owners


def _group_value(c, k: int):
    """The value of a constrained group (or its k-th rate) as book layout: the rotation's
    3x3, a unit vector's column, an angle's atom."""
    atoms = [constrained_atom(n, c) for n in c.names]
    if k:
        atoms = [sp.Derivative(a, (TIME, k)) for a in atoms]
    if c.kind == "angle":
        return atoms[0]
    if c.kind == "rotation":
        return sp.ImmutableMatrix(3, 3, atoms)
    return sp.ImmutableMatrix(atoms)


def _name(base_name: str, k: int, bold: bool) -> tuple[str, str]:
    acc = {0: "", 1: "_dot", 2: "_ddot"}.get(k, "")
    return notation.book_text(base_name + acc), notation.book_latex(base_name + acc, bold=bold)


def _split_inverse(split: dict) -> dict:
    """``b -> (θ, sign)`` of a split substitution ``θ -> sign·b``."""
    out = {}
    for a, v in split.items():
        (b,) = v.free_symbols
        out[b] = (a, int(v / b))
    return out


def _in_case(x, split: dict):
    """A value in the reader's atoms, in the split case's atoms (``θ -> -b``)."""
    if not split or x is None:
        return x
    return x.xreplace(split) if not isinstance(x, sp.MatrixBase) else \
        x.applyfunc(lambda e: sp.sympify(e).xreplace(split))


def _describe(rel, model, rels, plan, pt, sentence, split) -> dict:
    vals = PointValues(plan, pt)
    inverse = _split_inverse(split)
    known = set(point_atoms(plan)) | {TIME}
    shown: list[dict] = []
    seen: set = set()
    sides = {rel.lhs, rel.rhs}

    def add(key, name_text, name_latex, value, angle=None):
        if key in seen or key in sides:  # a whole side is printed as that side
            return
        seen.add(key)
        if len(entries_of(value)) > MAX_ENTRIES:
            return
        try:
            v = vals.value(_in_case(value, split))
        except (Unsupported, ZeroDivisionError, KeyError, TypeError, ValueError):
            return
        if not entries_of(v) or (angle is None and not _has_atoms(value)):
            return  # a constant (𝟏, O): nothing the point chose
        shown.append(_symbol_entry(name_text, name_latex, v, _in_case(angle, split), vals))

    # 1. the failing member's own symbols (a whole side is printed as that side)
    for s in _book_symbols(rel.lhs) + _book_symbols(rel.rhs):
        if s in sides:
            continue
        if s in model:
            v = explicit(s, model)
            add(s, notation.text(s), notation.latex(s), v, angle=_angle_of(v, plan))
        elif constraint_of(s) is not None:
            _add_group(add, constraint_of(s), 0)
        elif isinstance(s, sp.Symbol) and s in known:
            _add_free(add, s, plan)
    # 2. the book symbols among the point's atoms (given data: ȧ, e, φ, a)
    owners = _owner_map(model)
    in_rels = set().union(*(_atoms_of(r.lhs) | _atoms_of(r.rhs) for r in rels)) if rels else set()
    params: list = []
    for a in point_atoms(plan):
        base, k = atom_base(a)
        if base in inverse:  # the case's b: shown as the reader's angle
            _add_group(add, constraint_of(inverse[base][0]), k)
        elif a in owners:
            key = owners[a]
            add(key, notation.text(key), notation.latex(key), explicit(key, model),
                angle=_angle_of(model[key], plan))
        elif constraint_of(base) is not None:
            _add_group(add, constraint_of(base), k)
        elif a in in_rels:
            _add_free(add, a, plan)
        else:
            params.append(a)
    # 3. other scalars and vectors of the statement that the point fixes (m, c, ȧ⊥)
    _add_fixed(add, in_rels, seen | sides, model, known)
    chosen = _chosen(plan, pt, params, sentence, inverse,
                     _group_alias(model, _atoms_of(rel.lhs) | _atoms_of(rel.rhs), in_rels))
    return {"symbols": shown, "chosen": _filled_words(chosen, vals)}


def _filled_words(chosen: dict, vals) -> dict:
    """``chosen`` with a sentence on the atoms the failing member does not depend on."""
    if vals.filled:
        names = sorted({notation.book_group(plain_name(a)) for a in vals.filled})
        chosen["text"] += (f" {', '.join(names)} cancel from the failing member, so any value "
                           f"does: 1/2 is taken for each entry.")
        chosen["text"] = chosen["text"].strip()
    return chosen


def _add_fixed(add, in_rels: set, skip: set, model, known: set) -> None:
    """Step 3 of :func:`_describe`: the statement's scalars and vectors (up to 6 entries)
    that the point fixes, those not already shown (``skip``)."""
    for s in sorted(in_rels, key=lambda x: notation.text(x)):
        if s in skip or s not in model or not isinstance(s, sp.Symbol | sp.MatrixSymbol):
            continue
        r, c = shape_of(s)
        if c != 1 or r > 6:
            continue
        v = explicit(s, model)
        if _atoms_of(v) <= known:
            add(s, notation.text(s), notation.latex(s), v)


def _group_alias(model: dict, failing: set = frozenset(), used: set = frozenset()) -> dict:
    """Constrained group name -> the reader's symbol whose model value is exactly that
    group (``R: rigid_motion().Q`` -> ``{"Q": "R"}``): "how the point was chosen" names
    the reader's symbol, not the group's internal name. A symbol of the failing
    member is preferred, then one of the statement's relations, then any."""
    out: dict = {}
    keys = sorted(model, key=lambda k: (k not in failing, k not in used))
    for key in keys:
        val = model[key]
        if not isinstance(key, sp.Symbol | sp.MatrixSymbol):
            continue
        ents = entries_of(val) if isinstance(val, sp.MatrixBase) else [val]
        cs = {constraint_of(e) for e in ents}
        if len(cs) != 1 or None in cs:
            continue
        (c,) = cs
        if c.name in out:
            continue
        try:
            same = sp.ImmutableMatrix(val) == sp.ImmutableMatrix(_group_value(c, 0)) \
                if isinstance(val, sp.MatrixBase) else val == _group_value(c, 0)
        except (TypeError, ValueError):
            continue
        if same:
            out[c.name] = notation.text(key)
    return out


def _has_atoms(v) -> bool:
    return any(sp.sympify(e).free_symbols - {TIME} or sp.sympify(e).has(AppliedUndef)
               for e in entries_of(v))


def _atoms_of(x) -> set:
    """Symbols, applied functions and derivatives of an expression or a matrix of them
    (``MatrixSymbol`` included); the function inside a derivative is not an atom of its
    own (``Derivative(e_1(t), t)`` needs no value of ``e_1(t)``)."""
    out: set = set()
    for e in (entries_of(x) if isinstance(x, sp.MatrixBase) else [x]):
        e = sp.sympify(e)
        ds = e.atoms(sp.Derivative)
        rest = e.xreplace({d: sp.Dummy() for d in ds}) if ds else e
        out |= ds | {a for a in rest.free_symbols if not isinstance(a, sp.Dummy)}
        out |= rest.atoms(AppliedUndef)
    return out


def _add_free(add, a, plan) -> None:
    """A free atom with its siblings of the same book name (``a_1..a_3`` -> ``a``)."""
    base, k = atom_base(a)
    g = group_base(plain_name(a))
    mates = sorted((x for x in plan.rules if x != sp.pi and atom_base(x)[1] == k
                    and constraint_of(atom_base(x)[0]) is None
                    and group_base(plain_name(x)) == g), key=sp.default_sort_key)
    lone = len(mates) < 2  # a lone scalar by its own name: a reader's K_1 is K₁, not K
    g = plain_name(a) if lone else g
    add(("free", g, k), *_name(g, k, not lone), a if lone else sp.ImmutableMatrix(mates))


def _angle_of(value, plan):
    """The angle atom when a model key's value is one bare angle (``φ -> φ(t)``)."""
    if isinstance(value, sp.MatrixBase):
        return None
    return value if value in plan.angles else None


def _add_group(add, c, k: int) -> None:
    value = _group_value(c, k)
    angle = value if (c.kind == "angle" and k == 0) else None
    add(("group", c.name, k), *_name(c.name, k, c.kind not in ("angle",)), value, angle)


# --------------------------------------------------------------------------- chosen
def _param_label(p, inverse: dict | None = None, alias: dict | None = None) -> str:
    """``e__u(t)`` -> ``u of e``, ``e__u__d1`` -> ``u̇ of e``, ``tan(phi/2)`` -> ``t =
    tan(φ/2)``, a model atom by its book name (``s34_q_1`` -> ``q₁``)."""
    name = p.name
    if name.startswith("tan("):
        inner, _, den = name[4:-1].rpartition("/")
        timed = inner.endswith("(t)")
        inner = inner[:-3] if timed else inner
        hit = next(((a, sg) for b, (a, sg) in (inverse or {}).items() if b.name == inner),
                   None)
        inner = notation.book_text(inner) if hit is None else \
            ("−" if hit[1] < 0 else "") + notation.book_text(hit[0].name)
        return f"t = tan({inner}/{den})"
    if "__" in name:
        group, rest = name.split("__", 1)
        rest = rest.replace("(t)", "")
        k = 0
        if "__d" in rest:
            rest, _, order = rest.partition("__d")
            k = int(order)
        who = (alias or {}).get(group) or notation.book_text(group)
        if k <= 2:  # the accent on the letter: q̇₀, not q₀̇
            return f"{notation.book_text(rest + ('', 'dot', 'ddot')[k])} of {who}"
        return f"{notation.book_text(rest)}^({k}) of {who}"
    return notation.book_text(name)


def _chosen(plan, pt, params: list, sentence: str, inverse: dict | None = None,
            alias: dict | None = None) -> dict:
    """The parametrisation: one sentence, and the values of its variables.

    Returns:
        ``{"text": words, "params": [{"name", "exact", "decimal"}]}``: the model's own
        variables grouped by book name (``q = (2, -2, 1, 0)``), then the stereographic
        and quaternion parameters of constrained atoms and the half-angle tangents.
    """
    words = [sentence.strip().rstrip(".")] if sentence.strip() else []
    groups: dict = {}
    for a in params:
        groups.setdefault(notation.book_group(plain_name(a)), []).append(a)
    rows = []
    vals = PointValues(plan, pt)
    for g, atoms in groups.items():
        v = [vals.atom(a) for a in atoms]
        rows.append(_row(g, v))
    if groups and not words:
        words.append(", ".join(groups) + (" are" if len(groups) > 1 else " is")
                     + " the model's own variables (see the declaration): every value is "
                       "allowed, so the point is a valid configuration")
    seen_kinds = set()
    for a in point_atoms(plan):
        c = constraint_of(atom_base(a)[0])
        if c is None or (c.kind, c.name) in seen_kinds:
            continue
        seen_kinds.add((c.kind, c.name))
        n = (alias or {}).get(c.name) or notation.book_text(c.name)
        if c.kind in ("angle", "angle_pi"):
            base = atom_base(a)[0]
            if base not in plan.angles:
                continue
            M = plan.angles[base][1]
            kind = c.kind
            if base in (inverse or {}):
                reader, sign = inverse[base]
                n, kind = notation.book_text(reader.name), "split+" if sign > 0 else "split-"
            words.append(_KIND_SENTENCE[kind].format(n=n, d=2 * M, m=2 * M))
        else:
            words.append(_KIND_SENTENCE[c.kind].format(n=n) + (
                "; along the motion their rates at the instant are free rationals too"
                if c.timed else ""))
    for p in plan.params:
        group, _, rest = p.name.partition("__")
        mine = group in {n for _, n in seen_kinds} and \
            rest.split("(")[0].split("__")[0] in ("u", "v", "w", "q0", "q1", "q2", "q3")
        if p in pt and (mine or p.name.startswith("tan(")):
            rows.append(_row(_param_label(p, inverse, alias), [sp.Rational(pt[p].numerator,
                                                           pt[p].denominator)]))
    text = ". ".join(words) + "." if words else ""
    return {"text": text, "params": rows}


def _row(name: str, values: list) -> dict:
    """One variable (or a group of them) of the parametrisation: ``(2, -2, 1, 0)``."""
    exact = ", ".join(str(x) for x in values)
    dec = "" if all(x.is_Integer for x in values) else ", ".join(decimal(x) for x in values)
    if len(values) > 1:
        exact, dec = f"({exact})", (f"({dec})" if dec else "")
    return {"name": name, "exact": exact, "decimal": dec}

