"""The checker: compute each declaration's verdict and back it with a numeric check.

Verdicts: ``verified`` (every printed member equals the first, under the first-principles
model, decided by :func:`rigidsym.zero.decide_zero`), ``definition`` (a statement that
introduces a new symbol), ``does-not-hold`` (some member differs: an exact rational
counterexample is given, and the corrected form must verify), ``undecided`` (no method
decided, or the numeric check disagrees: a defect, never counted as verified).

Every verdict is backed by an mpmath evaluation of the *unparametrised* expressions at
``NUMERIC_POINTS`` seeded points that satisfy the constraints exactly, at ``NUMERIC_DIGITS``
digits.
"""

from __future__ import annotations

import random
import time
import zlib
from dataclasses import asdict, dataclass, field
from fractions import Fraction

import mpmath
import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.matrices.expressions.matexpr import MatrixElement

from .records import member_record, model_words
from .registry import REGISTRY, Equation, Rel, Statement
from .zero import Unsupported, decide_zero, evaluate, make_plan

__all__ = ["Result", "check", "explicit", "shape_of", "NUMERIC_DIGITS", "NUMERIC_POINTS"]

NUMERIC_DIGITS = 50
NUMERIC_POINTS = 10
#: relative residual below which the numeric check agrees with "holds".
AGREE_TOL = mpmath.mpf(10) ** -(NUMERIC_DIGITS - 15)
#: relative residual above which the numeric check agrees with "does not hold".
DIFFER_TOL = mpmath.mpf(10) ** -12


@dataclass
class Result:
    """The checker's outcome for one id (the JSON row of ``rigidsym verify --json``)."""

    id: str
    title: str
    kind: str
    verdict: str
    expected: str
    method: str
    printed_latex: str
    printed: str
    derived: str
    corrected: str | None
    counterexample: dict | None
    cause: str | None
    numeric: dict
    seconds: float
    section: str = ""
    evidence: str | None = None
    detail: str = ""
    singular: str | None = None
    failing_member: str | None = None
    #: one record per member (printed, claim, corrected), see
    #: :func:`rigidsym.records.member_record`
    members: list[dict] = field(default_factory=list)
    #: the model's atoms and their constraints, in words ("e: unit vector, ...")
    model: list[str] = field(default_factory=list)

    def as_json(self) -> dict:
        """Every field as a plain dict (the full record; the lean schema-2 row is
        :func:`rigidsym.report.result_record`)."""
        return asdict(self)


# --------------------------------------------------------------------------- helpers
def explicit(x, model: dict | None = None):
    """Substitute the model and return an explicit ``sp.Matrix`` or scalar expression.

    Matrix expressions are evaluated structurally (blocks, sums, products, integer powers,
    transposes, inverses, traces, determinants) on explicit operands: sympy's generic
    ``doit()`` takes symbolic-summation and simplification paths that cost seconds or
    minutes on block products and matrix powers.
    """
    model = model or {}
    key = (id(x), id(model))
    hit = _EXPLICIT_CACHE.get(key)
    if hit is not None and hit[0] is x:
        return hit[1]
    if isinstance(x, sp.MatrixBase | sp.MatrixExpr):
        y = sp.Matrix(_mx(x, model))
    else:
        y = _sc(sp.sympify(x), model)
    _EXPLICIT_CACHE[key] = (x, y)
    return y


#: explicit() results within one check (keyed by object identity; cleared per check)
_EXPLICIT_CACHE: dict = {}


def _sc(s, model):
    """Explicit scalar: model substituted, matrix-valued sub-terms evaluated."""
    y = s.xreplace(model) if model else s
    if not y.has(sp.Trace, sp.Determinant, MatrixElement, sp.MatrixExpr):
        return y

    def ev(z):
        if isinstance(z, sp.Trace):
            return _mx(z.arg, {}).trace()
        if isinstance(z, sp.Determinant):
            return _mx(z.arg, {}).det(method="berkowitz")
        if isinstance(z, MatrixElement):
            return _mx(z.parent, {})[int(z.i), int(z.j)]
        return None

    out = y.replace(lambda z: isinstance(z, sp.Trace | sp.Determinant | MatrixElement), ev)
    return out.doit() if out.has(sp.MatrixExpr) else out


def _mx(x, model) -> sp.ImmutableMatrix:
    """Explicit value of a matrix expression (see :func:`explicit`)."""
    im = sp.ImmutableMatrix
    if isinstance(x, sp.MatrixBase):
        return im(x.xreplace(model)) if model else im(x)
    if isinstance(x, sp.MatrixSymbol):
        v = model.get(x)
        return im(v) if v is not None else im(x.as_explicit())
    if isinstance(x, sp.Identity):
        return im(sp.eye(int(x.rows)))
    if isinstance(x, sp.ZeroMatrix):
        return im(sp.zeros(*(int(n) for n in x.shape)))
    if isinstance(x, sp.MatAdd):
        args = [_mx(a, model) for a in x.args]
        acc = args[0]
        for a in args[1:]:
            acc = acc + a
        return im(acc)
    if isinstance(x, sp.MatMul):
        coeff, mats = sp.S.One, []
        for a in x.args:
            if isinstance(a, sp.MatrixBase | sp.MatrixExpr):
                mats.append(_mx(a, model))
            else:
                coeff = coeff * _sc(a, model)
        acc = mats[0]
        for m in mats[1:]:
            acc = acc * m
        return im(coeff * acc) if coeff != 1 else im(acc)
    if isinstance(x, sp.MatPow) and x.exp.is_Integer:
        base, n = _mx(x.base, model), int(x.exp)
        if n < 0:
            base, n = im(base.inv()), -n
        acc = im(sp.eye(base.rows))
        for _ in range(n):
            acc = acc * base
        return im(acc)
    if isinstance(x, sp.Transpose):
        return im(_mx(x.arg, model).T)
    if isinstance(x, sp.Inverse):
        return im(_mx(x.arg, model).inv())
    if isinstance(x, sp.BlockMatrix):
        blocks = x.blocks
        rows = [[_mx(blocks[i, j], model) for j in range(blocks.cols)]
                for i in range(blocks.rows)]
        return im(sp.BlockMatrix(rows).as_explicit())
    # anything else (a custom operator of a derivations module): sympy's generic path
    y = x.xreplace(model) if model else x
    y = y.doit()
    return im(y.as_explicit() if isinstance(y, sp.MatrixExpr) else y)


def shape_of(x) -> tuple[int, int]:
    """Shape of a matrix, matrix expression or scalar (a scalar is 1 x 1)."""
    if isinstance(x, sp.MatrixBase | sp.MatrixExpr):
        return tuple(int(n) for n in x.shape)
    return (1, 1)


def _entries(x) -> list:
    return list(x) if isinstance(x, sp.MatrixBase) else [x]


def _fmt(x) -> str:
    return sp.sstr(x)


def _rel_str(rels: list[Rel] | None) -> str | None:
    if not rels:
        return None
    return "; ".join(f"{_fmt(r.lhs)} = {_fmt(r.rhs)}" for r in rels)


def _seed(eq_id: str) -> int:
    return zlib.crc32(eq_id.encode())


# --------------------------------------------------------------------------- numeric
def _dummify(exprs) -> tuple[list, list, list]:
    """Replace derivatives, then applied functions, then symbols by dummies (outside-in,
    so ``e_1(t)`` inside ``Derivative(e_1(t), t)`` is not mistaken for a lone atom)."""
    exprs = [sp.sympify(e) for e in exprs]
    atoms, dummies = [], []
    for kind in (sp.Derivative, AppliedUndef, sp.Symbol):
        found = set().union(*(e.atoms(kind) for e in exprs)) if exprs else set()
        found = sorted((a for a in found if not isinstance(a, sp.Dummy)),
                       key=sp.default_sort_key)
        sub = {a: sp.Dummy() for a in found}
        exprs = [e.xreplace(sub) for e in exprs]
        atoms += found
        dummies += [sub[a] for a in found]
    return atoms, dummies, exprs


def numeric_point(plan, rng: random.Random) -> dict:
    """Values (mpf) of every atom of ``plan`` at a random point satisfying the constraints.

    Constrained groups get exact rational points of their parametrisation (so ``e.e = 1``
    and ``Q^T Q = 1`` hold exactly); angles and free atoms get random reals.
    """
    pt = {p: Fraction(rng.randint(-40, 40), rng.randint(1, 12)) for p in plan.params}
    out = {}
    # sorted: the draws must not follow set/dict order, which varies with PYTHONHASHSEED
    for atom, rule in sorted(plan.rules.items(), key=lambda kv: sp.default_sort_key(kv[0])):
        if atom == sp.pi:
            continue
        if isinstance(rule, sp.Symbol):  # a free atom, a jet, or a bare angle
            out[atom] = mpmath.mpf(rng.randint(-10**8, 10**8)) / 10**8 * 3
        else:  # a constrained group: an exact rational point of its parametrisation
            f = evaluate(rule, plan, pt)
            out[atom] = mpmath.mpf(f.numerator) / f.denominator
    for a in sorted(plan.angles, key=sp.default_sort_key):  # one value per angle
        if a not in out:
            out[a] = mpmath.mpf(rng.randint(1, 10**8)) / 10**8 * 3
    return out


def numeric_residual(rels: list[Rel], model: dict, seed: int, points: int = NUMERIC_POINTS):
    """Max relative residual of ``lhs - rhs`` over seeded constraint-satisfying points."""
    lhs = [explicit(r.lhs, model) for r in rels]
    rhs = [explicit(r.rhs, model) for r in rels]
    flat_l = [e for x in lhs for e in _entries(x)]
    flat_r = [e for x in rhs for e in _entries(x)]
    plan = make_plan(flat_l + flat_r)
    atoms, dummies, flat = _dummify(flat_l + flat_r)
    fl = sp.lambdify(dummies, flat[:len(flat_l)], modules="mpmath", cse=True)
    fr = sp.lambdify(dummies, flat[len(flat_l):], modules="mpmath", cse=True)
    rng = random.Random(seed)
    worst = mpmath.mpf(0)
    residuals = []
    done = tries = 0
    with mpmath.workdps(NUMERIC_DIGITS):
        while done < points and tries < 20 * points:
            tries += 1
            pt = numeric_point(plan, rng)
            args = [pt.get(a, mpmath.mpf(rng.random())) for a in atoms]
            try:
                lv, rv = fl(*args), fr(*args)
            except (ZeroDivisionError, ValueError):
                continue
            scale = max([mpmath.mpf(1)] + [abs(mpmath.mpf(x)) for x in list(lv) + list(rv)])
            res = max((abs(mpmath.mpf(a) - mpmath.mpf(b)) for a, b in zip(lv, rv,
                                                                          strict=True)),
                      default=mpmath.mpf(0)) / scale
            if not mpmath.isfinite(res):
                continue
            residuals.append(res)
            worst = max(worst, res)
            done += 1
    return worst, done, residuals


# --------------------------------------------------------------------------- counterexample
def _small_witness(entries, plan, seed):
    """Look for a counterexample point with small rationals (readable), exactly checked."""
    rng = random.Random(seed)
    small = [Fraction(n, d) for n in range(-3, 4) for d in (1, 2, 3)]
    deadline = time.perf_counter() + 3.0  # readability is worth a few seconds, no more
    for _ in range(300):
        if time.perf_counter() > deadline:
            break
        pt = {p: rng.choice(small) for p in plan.params}
        try:
            if any(evaluate(e, plan, pt) != 0 for e in entries):
                return pt
        except (ZeroDivisionError, Unsupported):
            continue
    return None


def _exact_value(x, plan, pt):
    """Exact value at a witness point; bare angles take their consistent value 2M atan(tau)."""
    bare = {a: 2 * plan.angles[a][1] * sp.atan(sp.Rational(pt[plan.angles[a][0]]))
            for a in plan.bare if a in plan.angles}
    bare.update({a: sp.Rational(pt[s]) for a, s in plan.bare.items() if a not in bare})
    spt = {k: sp.Rational(v.numerator, v.denominator) for k, v in pt.items()}

    def one(e):
        return evaluate(e, plan, spt, lift=lambda v: v, bare_value=bare)

    if isinstance(x, sp.MatrixBase):
        return sp.Matrix(x.rows, x.cols, [one(e) for e in x])
    return one(x)


def _counterexample(lhs, rhs, witness, seed) -> dict:
    plan = make_plan(_entries(lhs) + _entries(rhs))
    diff = [a - b for a, b in zip(_entries(lhs), _entries(rhs), strict=True)] \
        if shape_of(lhs) == shape_of(rhs) else []
    pt = _small_witness(diff, plan, seed) if diff else None
    if pt is None:  # keep the proven witness; parameters it does not mention get 1/2
        pt = {p: witness.get(p, Fraction(1, 2)) for p in plan.params}
    point = {}
    for atom, rule in sorted(plan.rules.items(), key=lambda kv: sp.default_sort_key(kv[0])):
        if atom in plan.bare:
            continue
        v = evaluate(rule, plan, pt) if rule != atom else pt[atom]
        point[sp.sstr(atom)] = str(v)
    for a, (tau, M) in plan.angles.items():
        point[sp.sstr(a)] = f"{2 * M}*atan({pt[tau]})"
    lv, rv = _exact_value(lhs, plan, pt), _exact_value(rhs, plan, pt)
    ce = {"point": point, "lhs": sp.sstr(lv), "rhs": sp.sstr(rv)}
    if shape_of(lhs) == shape_of(rhs):
        ce["residual"] = sp.sstr(lv - rv)
    return ce


# --------------------------------------------------------------------------- decide
@dataclass
class _RelOutcome:
    zero: bool | None
    method: str
    detail: str
    counterexample: dict | None = None
    label: str = ""


def decide_rel(rel: Rel, model: dict, seed: int) -> _RelOutcome:
    """Decide one relation exactly (shape check first, then the zero test)."""
    ls, rs = shape_of(rel.lhs), shape_of(rel.rhs)
    lhs, rhs = explicit(rel.lhs, model), explicit(rel.rhs, model)
    if ls != rs:
        plan = make_plan(_entries(lhs) + _entries(rhs))
        rng = random.Random(seed)
        ce = None
        for _ in range(100):
            pt = {p: Fraction(rng.randint(-3, 3), rng.randint(1, 3)) for p in plan.params}
            try:
                ce = _counterexample(lhs, rhs, pt, seed)
                break
            except ZeroDivisionError:
                continue
        return _RelOutcome(False, "counterexample",
                           f"shape mismatch: {ls[0]}x{ls[1]} vs {rs[0]}x{rs[1]}", ce, rel.label)
    diff = [a - b for a, b in zip(_entries(lhs), _entries(rhs), strict=True)]
    zr = decide_zero(diff, seed=seed)
    if zr.zero is False:
        ce = _counterexample(lhs, rhs, zr.witness, seed)
        return _RelOutcome(False, "counterexample", zr.detail, ce, rel.label)
    return _RelOutcome(zr.zero, zr.method, zr.detail, None, rel.label)


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
        return _fmt(st.derived)
    return "; ".join(_fmt(explicit(r.lhs, st.model)) for r in st.printed)


def check(eq: Equation | str) -> Result:
    """Compute the verdict of one declaration, with its numeric backing.

    Args:
        eq: an :class:`Equation` or its id.

    Returns:
        A :class:`Result`; ``verdict`` is computed here, never read from the declaration.
        An exception inside the declaration or the checker (a recursion limit in a huge
        expression, say) gives ``undecided`` with the error named, never a crashed run.
    """
    if isinstance(eq, str):
        eq = REGISTRY[eq]
    t0 = time.perf_counter()
    try:
        return _check(eq, t0)
    except Exception as exc:  # a defect to report as undecided, not to hide
        return Result(
            id=eq.id, title=eq.title, kind=eq.kind, verdict="undecided", expected=eq.expected,
            method="undecided", printed_latex=eq.latex, printed="", derived="",
            corrected=None, counterexample=None, cause=None,
            numeric={"points": 0, "digits": NUMERIC_DIGITS, "max_residual": None,
                     "seed": _seed(eq.id)},
            seconds=round(time.perf_counter() - t0, 3), section=eq.section,
            detail=f"{type(exc).__name__} while checking: {str(exc)[:200]}",
            singular=eq.singular)


def _check(eq: Equation, t0: float) -> Result:
    seed = _seed(eq.id)
    st = eq.build()
    _EXPLICIT_CACHE.clear()
    verdict, method, detail = "undecided", "undecided", ""
    members: list[dict] = []
    ce = None
    failing = None
    backing: list[Rel] = []
    printed_res = None
    corrected_str = _rel_str(st.corrected)
    if eq.kind == "definition":
        ok = True
        for r in st.printed:
            name = getattr(r.lhs, "name", None)
            if shape_of(r.lhs) != shape_of(r.rhs):
                ok = False
                detail = f"shape mismatch in definition of {name}"
            elif name not in st.defines:
                ok = False
                detail = f"lhs {_fmt(r.lhs)} is not a symbol this definition introduces"
        outs = [decide_rel(r, st.model, seed) for r in st.claims]
        members = [member_record(r, "printed", None) for r in st.printed]
        members += [member_record(r, "claim", o) for r, o in zip(st.claims, outs, strict=True)]
        if ok and all(o.zero for o in outs):
            verdict, method = "definition", "definition"
            detail = "introduces " + ", ".join(st.defines)
            backing = list(st.claims)
        elif ok:
            verdict, method, detail = ("undecided", "undecided",
                                       "a claim attached to the definition was not verified")
    else:
        outs = [decide_rel(r, st.model, seed + i) for i, r in enumerate(st.printed + st.claims)]
        members = [member_record(r, "printed" if i < len(st.printed) else "claim", o)
                   for i, (r, o) in enumerate(zip(st.printed + st.claims, outs, strict=True))]
        zero, method, detail = _combine(outs)
        if zero:
            verdict = "verified"
            backing = st.printed + st.claims
        elif zero is False:
            verdict = "does-not-hold"
            bad = next(o for o in outs if o.zero is False)
            ce, failing = bad.counterexample, bad.label or None
            if ce is not None:
                ce["member"] = bad.label
            if not st.corrected:
                verdict, detail = "undecided", "does not hold, but no corrected form is declared"
            else:
                couts = [decide_rel(r, st.model, seed + 100 + i)
                         for i, r in enumerate(st.corrected)]
                members += [member_record(r, "corrected", o)
                            for r, o in zip(st.corrected, couts, strict=True)]
                cz, cm, cd = _combine(couts)
                if not cz:
                    verdict = "undecided"
                    detail = f"the corrected form did not verify ({cm}: {cd})"
                else:
                    detail = f"{bad.detail}; corrected form verified by {cm}"
                backing = list(st.corrected)
            try:
                bad_rel = (st.printed + st.claims)[outs.index(bad)]
                if shape_of(bad_rel.lhs) == shape_of(bad_rel.rhs):
                    printed_res, _, _ = numeric_residual([bad_rel], st.model, seed)
                else:  # a shape mismatch cannot hold at any point
                    printed_res = mpmath.inf
            except (Unsupported, TypeError) as exc:  # pragma: no cover
                detail += f"; numeric of printed form failed: {exc}"
    numeric = {"points": 0, "digits": NUMERIC_DIGITS, "max_residual": None, "seed": seed}
    try:
        rels = backing or [r for r in st.printed if shape_of(r.lhs) == shape_of(r.rhs)]
        if rels:
            worst, n, _ = numeric_residual(rels, st.model, seed)
            numeric.update(points=n, max_residual=float(worst))
            if verdict in ("verified", "definition", "does-not-hold") and backing:
                if n < NUMERIC_POINTS:
                    verdict, detail = "undecided", f"numeric check reached only {n} points"
                elif worst > AGREE_TOL:
                    verdict = "undecided"
                    detail = f"numeric check disagrees: residual {mpmath.nstr(worst, 5)}"
        if printed_res is not None:
            numeric["printed_residual"] = (float(printed_res) if mpmath.isfinite(printed_res)
                                           else "shape mismatch")
            if verdict == "does-not-hold" and printed_res < DIFFER_TOL:
                verdict, detail = "undecided", "numeric check finds the printed form holding"
    except Unsupported as exc:
        verdict, detail = "undecided", f"numeric check impossible: {exc}"
    return Result(
        id=eq.id, title=eq.title, kind=eq.kind, verdict=verdict, expected=eq.expected,
        method=method if verdict != "undecided" else "undecided",
        printed_latex=eq.latex, printed=_rel_str(st.printed) or "",
        derived=_derived_str(st), corrected=corrected_str, counterexample=ce,
        cause=eq.cause if verdict == "does-not-hold" else None, numeric=numeric,
        seconds=round(time.perf_counter() - t0, 3), section=eq.section,
        evidence=eq.evidence if verdict == "does-not-hold" else None, detail=detail,
        singular=eq.singular, failing_member=failing, members=members,
        model=model_words([explicit(r.lhs, st.model) for r in st.printed]
                          + [explicit(r.rhs, st.model) for r in st.printed]))
