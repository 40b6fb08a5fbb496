"""The checker: compute each declaration's verdict and back it with a numeric check.

Verdicts: ``verified`` (every printed member equals the first, under the first-principles
model, decided by :func:`rigidsym.zero.decide.decide_zero`), ``definition`` (a statement that
introduces a new symbol), ``does-not-hold`` (some member differs: an exact rational
counterexample is given, and a declared corrected form must verify), ``undecided`` (no method
decided, or the numeric check disagrees: a defect, never counted as verified).

The verdict follows the counterexample: a member with an exact counterexample makes the id
``does-not-hold`` whether or not a correction is known; a declared correction that does not
verify makes it ``undecided`` (:mod:`rigidsym.checking.repairing.correction`, which also runs the
repair search of :mod:`rigidsym.checking.repairing.repair`).

Every verdict is backed by a ball-arithmetic evaluation (python-flint ``arb``) of the
*unparametrised* expressions at ``ENGINE.numeric_points`` seeded points that satisfy the
constraints exactly, from ``ENGINE.numeric_digits`` digits up
(:mod:`rigidsym.checking.deciding.balls`). The balls back a verdict and never make one: a
disagreement turns it ``undecided``.
"""

from __future__ import annotations

import random
import time
from dataclasses import dataclass
from fractions import Fraction

from rigidsym.checking.deciding.balls import round_up
from rigidsym.checking.deciding.branches import cases
from rigidsym.checking.deciding.counterexample import describe_point
from rigidsym.checking.deciding.evidence import (
    counterexample_ball,
    exact_counterexample,
    numeric_backing,
    rational_norm_witness,
)
from rigidsym.checking.deciding.explicit import (
    EXPLICIT_CACHE,
    UnknownShape,
    entries_of,
    expanded_text,
    explicit,
    identical_by_definition,
    rel_str,
    seed_of,
    shape_of,
)
from rigidsym.checking.deciding.records import member_record, model_words, printed_latex
from rigidsym.checking.outcome import Outcome
from rigidsym.checking.repairing.correction import RepairSettings, correct
from rigidsym.core import work as _work
from rigidsym.core.settings import ENGINE
from rigidsym.printing.names import book_text
from rigidsym.registry.declarations import REGISTRY, Equation, Rel, Statement, is_user_id
from rigidsym.zero.decide import Unsupported, ZeroResult, decide_zero, make_plan

__all__ = ["Outcome", "check", "explicit", "shape_of"]



# --------------------------------------------------------------------------- decide
@dataclass
class _RelOutcome:
    zero: bool | None
    method: str
    detail: str
    counterexample: dict | None = None
    label: str = ""
    #: the residual's ball at the counterexample: (excludes 0, ball text, digits)
    ball: tuple | None = None
    #: the relation the balls re-check when it is not the printed one (a branch case)
    evidence: Rel | None = None


def decide_rel(rel: Rel, model: dict, seed: int, st: Statement | None = None) -> _RelOutcome:
    """Decide one relation exactly (shape check first, then the zero test); a
    counterexample is described in the book symbols of ``st`` when it is given."""
    try:
        ls, rs = shape_of(rel.lhs), shape_of(rel.rhs)
    except UnknownShape as exc:  # a guessed shape is never evidence
        return _RelOutcome(None, "undecided", str(exc), None, rel.label)
    lhs, rhs = explicit(rel.lhs, model), explicit(rel.rhs, model)
    if ls != rs and shape_of(lhs) == shape_of(rhs):
        # the printed shapes differ but the values' agree: a shape rule misread a node
        return _RelOutcome(None, "undecided", f"shape rules disagree with the values: "
                           f"{ls[0]}x{ls[1]} vs {rs[0]}x{rs[1]} as printed", None, rel.label)
    describe = None
    if st is not None:
        rels = st.printed + st.claims + (st.corrected or [])

        def describe(plan, pt, split=None):
            return describe_point(rel, model, rels, plan, pt, st.parametrisation, split)
    if ls != rs:
        plan = make_plan(entries_of(lhs) + entries_of(rhs))
        rng = random.Random(seed)
        ce = None
        for _ in range(100):
            pt = {p: Fraction(rng.randint(-3, 3), rng.randint(1, 3)) for p in plan.params}
            try:
                ce, cplan, cpt = exact_counterexample(lhs, rhs, pt, seed)
                if describe is not None:
                    ce.update(describe(cplan, cpt))
                break
            except ZeroDivisionError:
                continue
        return _RelOutcome(False, "counterexample",
                           f"shape mismatch: {ls[0]}x{ls[1]} vs {rs[0]}x{rs[1]}", ce, rel.label)
    alts = cases(lhs, rhs)  # acos/atan2 on their principal branches (branches.py)
    if alts == [(lhs, rhs, lhs, rhs, {})]:
        return _decide_case(rel, lhs, rhs, lhs, rhs, seed, describe)
    # a split case is described in the reader's angle (a = s b), never in b
    outs = [_decide_case(rel, *alt[:4], seed, None if describe is None else
                         (lambda plan, pt, sub=alt[4]: describe(plan, pt, sub)))
            for alt in alts]
    for o, alt in zip(outs, alts, strict=True):
        if o.zero is False:  # the case's relation is the evidence the balls re-check
            o.evidence = Rel(alt[0], alt[1], rel.label)
            return o
    undecided = [o for o in outs if o.zero is None]
    if undecided:
        return undecided[0]
    o = outs[0]
    o.detail = f"{o.detail} (acos/atan2 on their principal branches, {len(outs)} case(s))"
    return o


def _decide_case(rel, blhs, brhs, lhs, rhs, seed, describe) -> _RelOutcome:
    """Decide ``lhs = rhs`` (branches resolved); the ball at a counterexample evaluates
    ``blhs - brhs`` (the same relation, ``acos``/``atan2`` as such)."""
    diff = [a - b for a, b in zip(entries_of(lhs), entries_of(rhs), strict=True)]
    zr = decide_zero(diff, seed=seed, polar=True)
    extra = [] if blhs is lhs and brhs is rhs else entries_of(blhs) + entries_of(brhs)
    witness = zr.witness
    if zr.polar_differs:  # a norm under sin/cos: a point of rational norm, proven by balls
        witness = rational_norm_witness(blhs, brhs, seed, entries_of(lhs) + entries_of(rhs))
        if witness is not None:
            zr = ZeroResult(False, "counterexample",
                            f"non-zero at a point of rational norm, proven by ball arithmetic "
                            f"(the sides differ identically with {zr.polar_differs})")
    if zr.zero is False:
        ce, plan, pt = exact_counterexample(lhs, rhs, witness, seed, extra)
        if describe is not None:
            ce.update(describe(plan, pt))
        try:
            ball = counterexample_ball(blhs, brhs, plan, pt)
        except Unsupported as exc:
            ball = (False, f"no ball: {exc}", ENGINE.numeric_digits)
        return _RelOutcome(False, "counterexample", zr.detail, ce, rel.label, ball)
    return _RelOutcome(zr.zero, zr.method, zr.detail, None, rel.label)


def _condition_on(rel: Rel, defines: tuple[str, ...]) -> bool:
    """Whether a definition's printed relation is a condition imposed on the symbols it
    introduces (its lhs not a bare symbol, and every symbol of it one of ``defines``):
    (3.38)'s ``e_i . e_j = delta_ij`` on the triad it introduces."""
    import sympy as sp

    names = {getattr(s, "name", None) for s in sp.sympify(rel.lhs).free_symbols}
    return bool(defines) and bool(names) and names <= set(defines)


def _combine(outs: list[_RelOutcome]) -> tuple[bool | None, str, str]:
    if any(o.zero is False for o in outs):
        o = next(o for o in outs if o.zero is False)
        return False, "counterexample", o.detail
    if any(o.zero is None for o in outs):
        o = next(o for o in outs if o.zero is None)
        return None, "undecided", o.detail
    method = "random-exact" if any(o.method == "random-exact" for o in outs) else "exact-cancel"
    details = "; ".join(sorted({o.detail for o in outs if o.method == method}))
    return True, method, details


def _derived_str(st: Statement) -> str:
    if st.derived is not None:
        return expanded_text(st.derived)
    return "; ".join(expanded_text(explicit(r.lhs, st.model)) for r in st.printed)


def check(eq: Equation | str, *, repairs: bool = True,
          repair_budget: int | None = None, expanded: bool = True,
          repair_seconds: float | None = None) -> Outcome:
    """Compute the verdict of one declaration, with its numeric backing.

    Args:
        eq: an :class:`Equation` or its id.
        repairs: search the repairs of a member that does not hold
            (:mod:`rigidsym.checking.repairing.repair`).
        repair_budget: candidates per failing member; ``None``: the declaration's
            ``repair_budget``, else ``ENGINE.repair_budget``.
        expanded: print the expanded strings (``printed``, ``derived``, ``corrected``:
            the full reports and the API); ``False`` leaves them ``None`` (a tenth of a
            chapter's checking time, for ``rigidsym verify``, which never shows them).
        repair_seconds: a time limit of the repair search, seconds (``None``: none); past
            it the result says "search stopped after N s, K candidates tried".

    Returns:
        A :class:`Outcome`; ``verdict`` is computed here, never read from the declaration.
        An exception inside the declaration or the checker (a recursion limit in a huge
        expression, say) gives ``undecided`` with the error named, never a crashed run.
    """
    if isinstance(eq, str):
        eq = REGISTRY[eq]
    _work.count("decide", eq.id)
    t0 = time.perf_counter()
    try:
        return _check(eq, t0, RepairSettings(repairs, repair_budget, repair_seconds), expanded)
    except Exception as exc:  # a defect to report as undecided, not to hide
        return Outcome(
            id=eq.id, title=eq.title, kind=eq.kind, verdict="undecided", expected=eq.expected,
            method="undecided", printed_latex=eq.latex, printed="", derived="",
            corrected=None, counterexample=None, cause=None,
            numeric={"points": 0, "digits": ENGINE.numeric_digits, "max_residual": None,
                     "seed": seed_of(eq.id), "enclosure": None, "certified": False},
            seconds=round(time.perf_counter() - t0, 3), section=eq.section,
            detail=f"{type(exc).__name__} while checking: {str(exc)[:200]}",
            singular=eq.singular)


def _check(eq: Equation, t0: float, settings: RepairSettings,
           expanded: bool = True) -> Outcome:
    """The verdict of one declaration (:func:`check` without its safety net).

    Long: the verdict, method and detail are refined step by step (a definition or an
    identity; the failing member and the corrected form; then the numeric backing, which may
    demote any verdict to undecided), each step reading what the previous ones decided; the
    steps stay in that one reading order.
    """
    seed = seed_of(eq.id)
    st = eq.build()
    EXPLICIT_CACHE.clear()
    verdict, method, detail = "undecided", "undecided", ""
    members: list[dict] = []
    ce = None
    failing = None
    backing: list[Rel] = []
    bad = bad_rel = None
    correction, repairs, searches = None, [], []
    fixed_str = None
    if eq.kind == "definition":
        ok = True
        for r in st.printed:
            name = getattr(r.lhs, "name", None)
            if shape_of(r.lhs) != shape_of(r.rhs):
                ok = False
                detail = f"shape mismatch in definition of {name}"
            elif name not in st.defines and not _condition_on(r, st.defines):
                ok = False
                detail = f"lhs {expanded_text(r.lhs)} is not a symbol this definition introduces"
        outs = [decide_rel(r, st.model, seed) for r in st.claims]
        members = [member_record(r, "printed", None) for r in st.printed]
        members += [member_record(r, "claim", o) for r, o in zip(st.claims, outs, strict=True)]
        if ok and all(o.zero for o in outs):
            verdict, method = "definition", "definition"
            detail = "introduces " + ", ".join(book_text(d) for d in st.defines)
            backing = list(st.claims)
        elif ok:
            verdict, method, detail = ("undecided", "undecided",
                                       "a claim attached to the definition was not verified")
    else:
        outs = [decide_rel(r, st.model, seed + i, st)
                for i, r in enumerate(st.printed + st.claims)]
        members = [member_record(r, "printed" if i < len(st.printed) else "claim", o)
                   for i, (r, o) in enumerate(zip(st.printed + st.claims, outs, strict=True))]
        zero, method, detail = _combine(outs)
        if zero:
            verdict = "verified"
            backing = st.printed + st.claims
            if st.printed and not is_user_id(eq.id) and \
                    all(identical_by_definition(r, st.model) for r in st.printed):
                # the sides are one expression once the definitions are substituted (the
                # chapter's ids; a reader's own keep their verdict, their tests rely on it)
                verdict, method = "definition", "identity by definition"
                detail = ("identity by definition: each printed relation's two sides are the "
                          "same expression once the model (the book's definitions) is "
                          "substituted; nothing is derived")
        elif zero is False:
            verdict = "does-not-hold"
            bad = next(o for o in outs if o.zero is False)
            ce, failing = bad.counterexample, bad.label or None
            if ce is not None:
                ce["member"] = bad.label
            fix = correct(eq, st, outs, seed, settings, decide_rel, _combine, rel_str)
            members += fix.members
            backing = fix.backing
            correction, repairs, searches = fix.kind, fix.repairs, fix.searches
            fixed_str = fix.corrected
            detail = f"{bad.detail}; {fix.detail}" if fix.holds else fix.detail
            if not fix.holds:
                verdict = "undecided"
            bad_rel = bad.evidence or (st.printed + st.claims)[outs.index(bad)]
    rels = backing or [r for r in st.printed if shape_of(r.lhs) == shape_of(r.rhs)]
    verdict, detail, numeric = _numeric(verdict, detail, rels, bool(backing), st.model, seed,
                                        bad_rel if verdict == "does-not-hold" else None,
                                        bad)
    return Outcome(
        id=eq.id, title=eq.title, kind=eq.kind, verdict=verdict, expected=eq.expected,
        method=method if verdict != "undecided" else "undecided",
        printed_latex=eq.latex or printed_latex(members),
        printed=(rel_str(st.printed) or "") if expanded else None,
        derived=_derived_str(st) if expanded else None,
        corrected=(rel_str(st.corrected) or fixed_str) if expanded else None,
        counterexample=ce,
        cause=eq.cause if verdict == "does-not-hold" else None, numeric=numeric,
        seconds=round(time.perf_counter() - t0, 3), section=eq.section,
        evidence=eq.evidence if verdict == "does-not-hold" else None, detail=detail,
        singular=eq.singular, failing_member=failing, members=members,
        model=model_words([explicit(r.lhs, st.model) for r in st.printed or st.claims]
                          + [explicit(r.rhs, st.model) for r in st.printed or st.claims]),
        repairs=repairs, repair_search=searches, correction=correction)


def _numeric(verdict: str, detail: str, rels: list[Rel], decisive: bool, model: dict,
             seed: int, bad_rel: Rel | None, bad: _RelOutcome | None):
    """The numeric record, and the verdict turned ``undecided`` where the balls disagree.

    ``rels`` are evaluated at the seeded points (the verdict's backing when ``decisive``);
    for a does-not-hold, ``bad_rel`` (the failing printed member) at the same points and
    ``bad.ball`` (its ball at the counterexample) back the failure.
    """
    numeric = {"points": 0, "digits": ENGINE.numeric_digits, "max_residual": None, "seed": seed,
               "enclosure": None, "certified": False}
    try:
        certified = False
        if rels:
            b = numeric_backing(rels, model, seed)
            numeric.update(points=b.points, digits=b.digits, max_residual=b.max_residual,
                           enclosure=None if b.enclosure is None else round_up(b.enclosure))
            certified = b.certified and b.points >= ENGINE.numeric_points
            if verdict in ("verified", "definition", "does-not-hold") and decisive:
                if b.points < ENGINE.numeric_points:
                    verdict, detail = "undecided", f"numeric check reached only {b.points} points"
                elif b.excluded is not None:
                    verdict = "undecided"
                    detail = f"numeric check disagrees: the residual ball {b.excluded} excludes 0"
                elif b.enclosure > ENGINE.agree_tol:
                    verdict = "undecided"
                    detail = (f"numeric check too wide: residual enclosed within "
                              f"{round_up(b.enclosure):.1e} at {b.digits} digits")
        if bad_rel is not None:
            if shape_of(bad_rel.lhs) != shape_of(bad_rel.rhs):  # cannot hold at any point
                numeric["printed_residual"] = "shape mismatch"
            else:
                verdict, detail, ok = _printed_numeric(verdict, detail, numeric, bad_rel, bad,
                                                       model, seed)
                certified = certified and ok
        if verdict == "does-not-hold" and not decisive:
            # no corrected form: the printed form's points say nothing of one;
            # the ball at the counterexample is the certificate
            numeric["enclosure"] = None
            certified = bool(bad and bad.ball and bad.ball[0])
        numeric["certified"] = certified and verdict != "undecided"
    except Unsupported as exc:
        verdict, detail = "undecided", f"numeric check impossible: {exc}"
    return verdict, detail, numeric


def _printed_numeric(verdict, detail, numeric, bad_rel, bad, model, seed):
    """The failing printed member at the seeded points and its ball at the counterexample;
    returns the verdict, the detail and whether the ball excludes 0."""
    try:
        pb = numeric_backing([bad_rel], model, seed)
    except Unsupported as exc:  # pragma: no cover
        return verdict, detail + f"; numeric of printed form failed: {exc}", False
    excludes, ball, digits = bad.ball
    numeric.update(printed_residual=pb.max_residual, printed_enclosure=ball,
                   digits=max(numeric["digits"], pb.digits, digits))
    if verdict == "does-not-hold" and pb.max_residual < ENGINE.differ_tol:
        verdict, detail = "undecided", "numeric check finds the printed form holding"
    elif verdict == "does-not-hold" and not excludes:
        verdict = "undecided"
        detail = f"numeric check: the ball {ball} at the counterexample holds 0"
    return verdict, detail, excludes
