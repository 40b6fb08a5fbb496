"""The C-only target: ``rigidsym generate --target c --out DIR``.

Writes what a C or C++ project needs and nothing of Python: per kernel a header and a
source with its scalar functions (double and float-only, each with its Jacobian twin when
the kernel has one), the shared declarations (``rigidsym_c.h``: status codes, ``extern
"C"``), the sources' private header (the compiler-flag guards), a ``CMakeLists.txt`` (a
library target usable by ``add_subdirectory`` and, installed, ``find_package``), a
pkg-config file and a README. Every file carries a provenance line (generator version,
declaration hash) and the licence line. docs/c-api.md is the user's guide.

The programs are the ones the package's kernels run (:func:`rigidsym.codegen.generator.
compile_kernel`: the same rewrites and CSE), printed by :mod:`.printer` into the templates of
this folder's ``templates/``; nothing here changes what ``rigidsym generate`` writes into
``generated/``. Its printers extend the extension target's
(:mod:`rigidsym.codegen.backends.extension`: one place for the C printers); its command is
:func:`rigidsym.codegen.usergen.cmd_generate_c`.
"""

from __future__ import annotations

import functools
import hashlib
import json
import math
import textwrap
from pathlib import Path

import jinja2
import sympy as sp

import rigidsym
from rigidsym.codegen.backends import RenderContext, Target
from rigidsym.codegen.backends.c.homogeneous import scaling_plans
from rigidsym.codegen.backends.c.prefix import DEFAULT_PREFIX, check_prefix, rename
from rigidsym.codegen.backends.c.printer import DoublePrinter, FloatOnlyPrinter, WidePrinter
from rigidsym.codegen.backends.extension.program import balanced, finite_check
from rigidsym.codegen.backends.printing import program_lines
from rigidsym.codegen.spec import Kernel
from rigidsym.core.config import generated_dir

__all__ = ["generate_c", "float_bounds", "double_bounds", "notice_lines", "TEMPLATES",
           "LIBRARY", "PREFIX", "STATUS", "FLOAT_BOUNDS", "TARGET", "render", "declaration_hash"]

TEMPLATES = Path(__file__).parent / "templates"
#: the float functions' measured accuracy bounds of the book's kernels
#: (benchmarks/c_float_bounds.py --write), keyed by kernel name, valid for its hash
FLOAT_BOUNDS = Path(__file__).parent / "float_bounds.json"
#: the library's name (CMake target, pkg-config module, file prefix) unless ``--prefix``
#: names another (:mod:`.prefix`)
LIBRARY = DEFAULT_PREFIX
#: the prefix of every exported function
PREFIX = "rigidsym_c_"
#: the status bits of every scalar function: (macro suffix, value, meaning)
STATUS = (
    ("OK", 0, "finite inputs, not on the singular set, evaluated without underflow or "
              "overflow (of ordinary magnitude, rescued, or an evaluation that raised no "
              "exception flag): the outputs are the kernel's values within its stated bound"),
    ("SINGULAR", 1, "the inputs lie on the kernel's singular set (a divisor is exactly "
                    "zero, or a branch condition has no value): every output is NaN"),
    ("NONFINITE_INPUT", 2, "an input component is NaN or infinite: the outputs that depend "
                           "on it are NaN or infinite (IEEE arithmetic), the others as for "
                           "finite input"),
    ("NONFINITE_RESULT", 4, "an output, or a divisor or radicand on the way, is not finite "
                            "(overflow of finite inputs, or a non-finite input)"),
    ("EXTREME_INPUT", 8, "a nonzero input component has magnitude outside [2^-100, 2^101) "
                         "(double; float: [2^-30, 2^31)) that neither a wider type (the "
                         "double functions re-run the sample in long double where that is "
                         "wider, RIGIDSYM_C_WIDE; the float ones in double where double "
                         "has hardware flags, RIGIDSYM_C_WIDE_F) nor power-of-two rescaling "
                         "(of the arguments the kernel is homogeneous in) could take, and "
                         "whose evaluation raised underflow, overflow, invalid or "
                         "divide-by-zero (or ran where those flags cannot be read, "
                         "RIGIDSYM_C_FLAGS_*): intermediates may have underflowed or "
                         "overflowed, so the outputs are not guaranteed to the stated bound; "
                         "or an output of the wider evaluation rounds inexactly into the "
                         "type's subnormal range; or a unit-vector or rotation argument is "
                         "of extreme norm (its largest component so), no unit vector"),
    ("DEFAULT_OUTPUT", 16, "an output that is undetermined at these inputs holds its "
                           "documented default (the axis e = [1, 0, 0] of "
                           "natural_invariants_from_rotation at Q = 1, where phi = 0 "
                           "exactly); every other output is right, as with status 0"),
)


class CTargetError(ValueError):
    """A kernel the C-only target cannot print (a name that would collide in C)."""


def stated(measured: float) -> float:
    """The bound a header states for a measured worst ``measured`` (a ratio, >= 0): twice it,
    rounded up to 1, 1.5, 2, 3 or 5 times a power of ten, at least 1."""
    want = max(1.0, 2.0 * measured)
    e = math.floor(math.log10(want))
    for m in (1.0, 1.5, 2.0, 3.0, 5.0, 10.0):
        if m * 10.0**e >= want * (1 - 1e-12):
            return m * 10.0**e
    raise AssertionError(want)


def _env() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(TEMPLATES)), keep_trailing_newline=True,
        trim_blocks=True, lstrip_blocks=True, undefined=jinja2.StrictUndefined,
        autoescape=False)
    env.filters["wrap"] = lambda text, width: textwrap.wrap(text, width) or [""]
    env.filters["paren"] = lambda eq: f"({eq})"
    return env


def _layout(shape) -> str:
    """The storage of a per-sample shape, for the header."""
    shape = tuple(shape)
    if shape == ():
        return "scalar"
    if len(shape) == 1:
        return f"vector of {shape[0]}"
    dims = " x ".join(map(str, shape))
    strides, s = [], 1
    for d in reversed(shape[1:]):
        s *= d
        strides.insert(0, s)
    idx = " + ".join([f"{st}*{v}" for st, v in zip(strides, "ijklm", strict=False)] +
                     ["ijklm"[len(shape) - 1]])
    sub = "][".join("ijklm"[:len(shape)])
    return f"{dims}, row-major: [{sub}] at [{idx}]"


def _program(kc, printer, ctype: str) -> dict:
    """The printed variants of ``kc``'s program (branches in order, main last)."""
    zero = "0.0f" if ctype == "float" else "0.0"
    out = []
    branches = kc.kernel.branches
    for i, v in enumerate(kc.variants):
        lines = program_lines(v.program, printer)
        out.append({"cond": None if v.cond is None else printer.doprint(v.cond),
                    "default": branches[i].default if i < len(branches) else "",
                    "finite": finite_check(v.program, kc.kernel, printer), "zero": zero,
                    **lines})
    return out


#: log2 of the largest ordinary input (the top of the range the status calls ordinary) and
#: of the largest finite value, per type, less a margin for the rounding of the sums
_ORDINARY = {"double": (101, 1020), "float": (31, 124)}


class _Unbounded(Exception):
    pass


def _log2_bound(e, env: dict, top: float) -> float:
    """An upper bound of log2 |e| when every input is below 2^top in magnitude and each
    temporary of ``env`` below 2^env[t]; raises _Unbounded for a division, a root or a
    function it does not know."""
    if e.is_Symbol:
        return env.get(e, top)
    if e.is_Number:
        return math.log2(abs(float(e))) if e != 0 else -math.inf
    if isinstance(e, sp.sin | sp.cos):
        return 0.0
    if isinstance(e, sp.atan2):
        return 2.0
    if e.is_Add:
        return max(_log2_bound(a, env, top) for a in e.args) + math.log2(len(e.args))
    if e.is_Mul:
        return sum(_log2_bound(a, env, top) for a in e.args)
    if e.is_Pow and e.exp.is_Integer and e.exp > 0:
        return _log2_bound(e.base, env, top) * int(e.exp)
    if isinstance(e, sp.Piecewise):
        return max(_log2_bound(x, env, top) for x, _ in e.args)
    name = type(e).__name__
    if name in ("DiffProd", "SumProd"):   # compensated a b - c d, sum of products
        pairs = [e.args[i:i + 2] for i in range(0, len(e.args), 2)]
        return max(_log2_bound(a, env, top) + _log2_bound(b, env, top) for a, b in pairs) \
            + math.log2(len(pairs))
    raise _Unbounded(name)


def _bounded(kc, ctype: str) -> int | None:
    """log2 of a bound of every output of ``kc`` for ordinary inputs (below 2^101, float
    2^31), when the program has no division or root and that bound is finite in ``ctype``
    (so that only an extreme or non-finite input can give a non-finite output); else None."""
    top, limit = _ORDINARY[ctype]
    worst = -math.inf
    for v in kc.variants:
        p = v.program
        if p.dens:
            return None
        env: dict = {}
        try:
            for t, e in p.temps:
                env[t] = _log2_bound(sp.sympify(e), env, top)
            for e in p.outputs:
                worst = max(worst, _log2_bound(sp.sympify(e), env, top))
        except _Unbounded:
            return None
    return math.ceil(worst) if worst <= limit else None


def _scan_groups(k: Kernel, ctype: str) -> list[dict]:
    """The input components of the range test in groups of one SIMD register (2 doubles or 4
    floats, 16 bytes: SSE2, NEON): ``{"load": ptr}`` where the group is contiguous in one
    argument (one unaligned load), else ``{"elems": [ptr, ...]}`` (components gathered, the
    last group padded with zeros, which are ordinary). Straight-line groups from the
    arguments themselves: the former copy into a local array and its loop cost more than the
    test (measured 95 of 154 instructions on twist_transfer, benchmarks/c_scalar.py)."""
    lanes = 4 if ctype == "float" else 2
    comps = [(a.name, j, bool(a.shape)) for a in k.args for j in range(a.size)]
    groups = []
    for i in range(0, len(comps), lanes):
        g = comps[i:i + lanes]
        if len(g) == lanes and g[0][2] and all(n == g[0][0] and j == g[0][1] + d
                                               for d, (n, j, _) in enumerate(g)):
            groups.append({"load": f"in_{g[0][0]} + {g[0][1]}" if g[0][1] else
                           f"in_{g[0][0]}"})
        else:
            groups.append({"elems": [f"&in_{n}[{j}]" if sh else f"&in_{n}" for n, j, sh in g],
                           "pad": lanes - len(g)})
    return groups


def spelling(k: Kernel, inputs) -> dict[str, str]:
    """The C identifiers of ``k``'s names, in a namespace of their own: ``{name: C name}``
    for each argument (``in_<name>``), output (``out_<name>``) and component symbol of an
    array argument (``c<j>_<name>``, j its row-major index), keyed by the name (of the
    symbol, for a component). Every other identifier of the generated C (the fixed locals,
    the CSE temporaries ``x<N>``, ``trig_<N>``, the helpers, the macros, the C library)
    starts with none of ``in_``, ``out_``, ``c<digits>_``, ``w_``, ``sc_`` (the long double
    rescue's parameters ``w_<name>`` and the scaled copies ``sc_<name>``), so no argument
    name, a C keyword or a local's name included, can meet one. ``inputs``: the kernel's
    [(argument, its symbols)]."""
    out = {a.name: f"in_{a.name}" for a in k.args}
    out.update({o.name: f"out_{o.name}" for o in k.outputs})
    for a, syms in inputs:
        if len(syms) > 1 or str(syms[0]) != a:
            out.update({str(c): f"c{j}_{a}" for j, c in enumerate(syms)})
    return out


def symbol_spelling(k: Kernel, names: dict[str, str]) -> dict[str, str]:
    """The spellings of :func:`spelling` that the printer applies to the program's symbols:
    the arguments' and components', not the outputs' (the template writes an output's slots
    by its spelling; the program never holds a symbol of an output's name, so a CSE
    temporary ``x0`` beside an output named ``x0`` stays the temporary)."""
    outs = {o.name for o in k.outputs}
    return {n: c for n, c in names.items() if n not in outs}


def _check_names(k: Kernel, temps: set[str], inputs) -> None:
    """Refuse what would make two of ``k``'s quantities one symbol of its program: an
    argument or output named as another argument's component (``v_0`` beside an array ``v``,
    whose components are the symbols ``v_0``, ``v_1``, ...), an argument named as a CSE
    temporary, or two that share a name. Any other name is allowed: the C spells each in a
    namespace of its own (:func:`spelling`). ``inputs``: the kernel's [(argument, its symbols)]."""
    names = [a.name for a in k.args] + [o.name for o in k.outputs]
    components = {str(c): a for a, syms in inputs for c in syms if str(c) != a}
    for n in names:
        if n in components:
            raise CTargetError(f"kernel {k.name}: argument or output {n!r} is the name of "
                               f"a component of argument {components[n]!r} in the "
                               f"kernel's program; rename it in the declaration")
        if n in temps and n in {a.name for a in k.args}:
            raise CTargetError(f"kernel {k.name}: argument {n!r} is the name of a "
                               f"temporary of the kernel's program; rename it in the "
                               f"declaration")
    if len(set(names)) != len(names):
        raise CTargetError(f"kernel {k.name}: two arguments or outputs share a name")


def _function(kc, ctype: str, rescale: list) -> dict:
    """One scalar function of ``kc`` in ``ctype`` ("double" or "float"); ``rescale``: its
    power-of-two rescaling plans (:func:`.homogeneous.scaling_plans`), with the C
    expressions of their exponents (:func:`_plan_code`)."""
    k = kc.kernel
    used: set[str] = set()
    temps: set[str] = set()
    for v in kc.variants:
        temps |= {str(s) for s, _ in v.program.temps}
        for e in [*(x for _, x in v.program.temps), *v.program.outputs, *v.program.dens,
                  *([v.cond] if v.cond is not None else [])]:
            used |= {str(s) for s in sp.sympify(e).free_symbols}
    _check_names(k, temps, kc.inputs)
    names = spelling(k, kc.inputs)
    printer = DoublePrinter() if ctype == "double" else FloatOnlyPrinter()
    printer.names = symbol_spelling(k, names)
    variants = _program(kc, printer, ctype)
    suffix = "_f32" if ctype == "float" else ""
    slots = [f"out_{o.name}[{j}]" for o in k.outputs for j in range(o.size)]
    # the components read into locals (the used ones): (local, source); the long double
    # rescue's from its parameters w_<argument>, a scalar argument into a local in_<name>
    loads, wide_loads = [], []
    for a, syms in kc.inputs:
        for j, c in enumerate(syms):
            if str(c) in used and str(c) != a:
                loads.append((names[str(c)], f"in_{a}[{j}]"))
                wide_loads.append((names[str(c)], f"w_{a}[{j}]"))
            elif str(c) in used:
                wide_loads.append((names[a], f"w_{a}"))
    return {"name": f"{PREFIX}{k.name}{suffix}", "ctype": ctype, "variants": variants,
            "loads": loads, "wide_loads": wide_loads,
            "args": [{"name": a.name, "c": names[a.name], "w": f"w_{a.name}",
                      "s": f"sc_{a.name}", "size": a.size, "shape": list(a.shape),
                      "doc": a.doc, "kind": a.kind, "layout": _layout(a.shape)}
                     for a in k.args],
            "outs": [{"name": o.name, "c": names[o.name], "w": f"w_{o.name}", "size": o.size,
                      "shape": list(o.shape), "doc": o.doc, "layout": _layout(o.shape)}
                     for o in k.outputs],
            "groups": _scan_groups(k, ctype),
            "slots": slots, "stores": _stores(k, ctype),
            "out_check": balanced([f"({s} - {s})" for s in slots]),
            "out_sum": balanced(slots),
            "st_sum": balanced([f"st{j}_" for j in range(len(slots))]),
            "bounded": None if any(v["finite"] for v in variants) else _bounded(kc, ctype),
            "wide": _wide(kc, symbol_spelling(k, names)) if ctype == "double" else None,
            # the float function's rescue in double: the double function of the kernel
            "wider": f"{PREFIX}{k.name}" if ctype == "float" else None,
            "rescale": [_plan_code(p, slots) for p in rescale],
            "rescaled": {n for p in rescale for n in p["scale"]},
            "detect": _detectable(kc, used) and (ctype == "double" or
                                                 sum(a.size for a in k.args) > DETECT_F32_ABOVE)}


def _stores(k: Kernel, ctype: str) -> list[dict]:
    """The stores of the outputs' values ``st<j>_`` (j the value's index over every output's
    components, row-major), in order: ``{"values": [j, ...], "put": C statement}``, one 16-byte
    store per 4 floats or 2 doubles of one output array where the build has vector extensions
    (``RIGIDSYM_C_PUT4F``, ``RIGIDSYM_C_PUT2D``; 2 floats ``RIGIDSYM_C_PUT2F``, 8 bytes:
    rigidsym_c_impl.h), a remaining component and a scalar output one by one. A caller that reads
    the outputs in 16-byte registers (Eigen's fixed-size vectors, any vectorised loop) forwards
    each load from one store; from one store per component it stalls on store forwarding
    (benchmarks/RESULTS.md, "The outputs' 16-byte stores")."""
    lanes = 4 if ctype == "float" else 2
    out, j = [], 0
    for o in k.outputs:
        i = 0
        while i < o.size:
            n = min(lanes, o.size - i) if o.shape else 1
            if n == 3:
                n = 2
            vals = list(range(j, j + n))
            at = f"out_{o.name} + {i}" if i else f"out_{o.name}"
            args = ", ".join(f"st{v}_" for v in vals)
            if n == 1:
                put = f"out_{o.name}[{i}] = st{j}_"
            elif ctype == "float":
                put = f"RIGIDSYM_C_PUT{n}F({at}, {args})"
            else:
                put = f"RIGIDSYM_C_PUT2D({at}, {args})"
            out.append({"values": vals, "put": put})
            i += n
            j += n
    return out


#: the float functions that detect (kernel.c.j2's detecting block) are those of more input
#: components than this; a smaller one keeps the range test first. One read of MXCSR costs
#: about as much as the whole of a small kernel (it waits for the evaluation's operations),
#: while the float range test costs a few operations per 4 components: with the C++ layer
#: against hand-written Eigen (benchmarks/cpp_eigen.py, the same run), the float twist
#: transfer (12 components) 3.27 detecting against 2.12-2.19 with the range test first, the
#: float Newton-Euler wrench (19) 1.67-1.70 against 1.81; every double function detects (its
#: range test reads two components a register, one load each: twist 0.89 against 0.97-1.00)
DETECT_F32_ABOVE = 12


#: the operations through which a NaN input reaches the result and an infinite one reaches
#: it or raises invalid (no comparison, min/max, sign or select, which can drop either)
_PROPAGATING = (sp.Symbol, sp.Number, sp.Add, sp.Mul, sp.sin, sp.cos)


def _detectable(kc, used: set[str]) -> bool:
    """Whether ``kc``'s scalar function may take the detecting fast path (kernel.c.j2):
    one variant (no branch a NaN comparison could steer), every input component used, only
    sums, products, integer powers, sin and cos (a NaN or infinite input reaches an output
    or raises invalid), no division or root (nothing singular), and no unit vector or
    rotation argument (whose extreme norm is flagged by itself). Then a call whose
    evaluation raised none of underflow, overflow, invalid and divide-by-zero and whose
    outputs are finite has every input finite and every operation rounded as in the normal
    range: the status and bits of the range test's path."""
    k = kc.kernel
    if len(kc.variants) != 1 or any(a.kind in ("unit", "rotation") for a in k.args):
        return False
    v = kc.variants[0]
    if v.cond is not None or v.program.dens:
        return False
    if any(str(c) not in used for _, syms in kc.inputs for c in syms):
        return False
    for e in [*(x for _, x in v.program.temps), *v.program.outputs]:
        for node in sp.preorder_traversal(sp.sympify(e)):
            if isinstance(node, sp.Pow):
                if not (node.exp.is_Integer and node.exp > 0):
                    return False
            elif not isinstance(node, _PROPAGATING):
                return False
    return True


def _plan_code(plan: dict, slots: list[str]) -> dict:
    """``plan`` (:func:`.homogeneous.scaling_plans`) with the C integer expressions of each
    scaled argument's exponent (``scaled``: [(name, expr)]) and of each output slot's
    exponent to undo (``back``: [(slot, expr)], the nonzero ones), in the ``rs_k<i>_`` (no
    argument is spelled so in the C: :func:`spelling`)."""
    def expr(coefs):
        terms = [f"{c} * rs_k{i}_" if c != 1 else f"rs_k{i}_"
                 for i, c in enumerate(coefs) if c]
        return " + ".join(terms).replace("+ -", "- ") if terms else ""

    return {**plan, "scaled": [(n, expr(c)) for n, c in plan["scale"].items()],
            "back": [(s, expr(c)) for s, c in zip(slots, plan["out"], strict=True) if any(c)]}


def _wide(kc, names: dict[str, str]) -> list[dict]:
    """The variants of ``kc`` printed in long double (the rescue of extreme inputs), its
    symbols spelled by ``names`` (:func:`spelling`)."""
    printer = WidePrinter()
    printer.names = names
    variants = _program(kc, printer, "long double")
    for v in variants:
        v["zero"] = "0.0L"
    return variants


def float_bounds(modules=()) -> dict:
    """The measured bounds of the float functions: the book's (:data:`FLOAT_BOUNDS`) and,
    for each user module given as a path ``M.py``, those of ``M.float_bounds.json`` beside
    it (both written by ``benchmarks/c_float_bounds.py --write``)."""
    out: dict = {}
    for path in [FLOAT_BOUNDS, *(Path(m).with_suffix(".float_bounds.json")
                                 for m in modules or () if str(m).endswith(".py"))]:
        if path.is_file():
            out.update(json.loads(path.read_text(encoding="utf-8")))
    return out


@functools.lru_cache(maxsize=1)
def double_bounds() -> dict:
    """The float64 bounds of the package's kernels, ``{name: {"hash", "measured", "bound",
    "regime"}}``: from the package's ``kernels.json`` (the accuracy harness over each
    kernel's regimes against arb, docs/accuracy.md: every output within ``measured u (kappa
    + 1)``, ``u = 2^-53``), the bound stated as the float functions' is (:func:`.stated`:
    twice the measured, rounded up); empty where the package's generated kernels are not found. A
    double function of the C target is the package kernel's program without FMA, the same
    bits (``tests/test_c_target.py``), so a bound holds for it where the hash is the same."""
    try:
        path = generated_dir() / "kernels.json"
    except FileNotFoundError:
        return {}
    out = {}
    for k in json.loads(path.read_text(encoding="utf-8"))["kernels"]:
        acc = (k.get("accuracy") or {}).get("float64") or {}
        if acc.get("bound") is not None:
            out[k["name"]] = {"hash": k["hash"], "measured": acc["bound"],
                              "bound": stated(acc["bound"]), "regime": acc.get("regime", "")}
    return out


def _kernel_entry(kc, bounds: dict) -> dict:
    k = kc.kernel
    d = double_bounds().get(k.name)
    b = bounds.get(k.name)
    steps = scaling_plans(k, kc.variants[0].program) if len(kc.variants) == 1 else []
    return {"name": k.name, "summary": k.summary, "formula": k.formula, "ids": list(k.ids),
            "sources": list(k.sources), "singular": k.singular, "hash": kc.hash,
            "ops": kc.ops, "notes": k.notes,
            "float_bound": b if b is not None and b.get("hash") == kc.hash else None,
            "double_bound": d if d is not None and d["hash"] == kc.hash else None,
            "homogeneity": _homogeneity(k, steps),
            "functions": [_function(kc, "double", steps), _function(kc, "float", steps)]}


def _homogeneity(k: Kernel, plans: list) -> dict | None:
    """What the header states of the rescaling: the scaled arguments, the constraints on
    their exponents and each output's degree (its slots' degrees, " / " where they differ)."""
    if not plans:
        return None
    p = plans[0]
    degrees, j = [], 0
    for o in k.outputs:
        degrees.append((o.name, " / ".join(dict.fromkeys(p["degrees"][j:j + o.size]))))
        j += o.size
    scaled = sorted({n for q in plans for n in q["scale"]},
                    key=[a.name for a in k.args].index)
    return {"scaled": scaled, "constraints": p["constraints"], "degrees": degrees}


def _members(codes) -> list[tuple[str, list]]:
    """``(name, [kernel, its Jacobian twin if any])`` per file pair, sorted by name."""
    from rigidsym.codegen.derivatives.jacobians import SUFFIX

    by = {kc.kernel.name: kc for kc in codes}
    return sorted(((name, [kc] + ([by[name + SUFFIX]] if name + SUFFIX in by else []))
                   for name, kc in by.items()
                   if not (name.endswith(SUFFIX) and name[:-len(SUFFIX)] in by)),
                  key=lambda g: g[0])


def _groups(codes, origin, bounds: dict) -> list[dict]:
    """Kernels with their Jacobian twins (``<name>_with_jacobians``) in one file pair."""
    return [{"name": name, "kernels": [_kernel_entry(m, bounds) for m in members],
             "origin": origin.get(name, "") if isinstance(origin, dict) else origin,
             "hash": _combined([m.hash for m in members])}
            for name, members in _members(codes)]


def declaration_hash(codes) -> str:
    """The folder's declaration hash of ``codes`` (the ``sha256:`` of its provenance lines,
    16 hex digits): of the kernels' hashes, per file pair and then over the pairs."""
    return _combined([_combined([m.hash for m in members]) for _, members in _members(codes)])


def _combined(hashes) -> str:
    return hashlib.sha256(" ".join(hashes).encode()).hexdigest()[:16]


def notice_lines(notice: str | None) -> tuple[list[str], str]:
    """The licence lines of a file's header and the one-line form (``notice`` None: the
    project's MIT line; "": none; else the user's lines).

    Raises:
        CTargetError: a notice that would end a comment of a generated file (``*/``,
            ``-->``).
    """
    if notice is not None and ("*/" in notice or "-->" in notice):
        raise CTargetError("--notice: the text must not hold '*/' or '-->' (it would end "
                           "the comment of a generated file)")
    if notice is None:
        return ["SPDX-License-Identifier: MIT (see LICENSE beside this file)"], \
            "SPDX-License-Identifier: MIT"
    lines = [line.rstrip() for line in notice.splitlines()]
    return lines, " ".join(line.strip() for line in lines if line.strip())


def _single_header(files: dict[str, str], groups: list[dict], allhash: str, ver: dict,
                   origin: str, notice: str | None = None) -> str:
    """One self-contained header (stb style): the declarations, and under
    ``RIGIDSYM_C_IMPLEMENTATION`` the guards and the definitions."""
    def body(text: str) -> str:
        return "".join(line for line in text.splitlines(keepends=True)
                       if not line.startswith(f'#include "{LIBRARY}'))
    heads = [f"{LIBRARY}_common.h"] + [f"{LIBRARY}_{g['name']}.h" for g in groups]
    srcs = [f"{LIBRARY}_impl.h"] + [f"{LIBRARY}_{g['name']}.c" for g in groups]
    top = (f"/*\n * {LIBRARY}: every kernel in one header. In exactly one C file of your "
           f"project:\n *     #define RIGIDSYM_C_IMPLEMENTATION\n *     #include "
           f"\"{LIBRARY}_single.h\"\n * (that file gets the definitions and the compiler-flag "
           f"guards, which also\n * apply to the rest of it); elsewhere include it without "
           f"the define.\n * Generated by rigidsym {ver['rigidsym']} (sympy {ver['sympy']}) "
           f"from {origin};\n * declaration hash sha256:{allhash}. Do not edit: regenerate "
           f"with\n * `rigidsym generate --target c --single-header`.\n"
           + "".join(f" * {line}\n" for line in notice_lines(notice)[0]) + " */\n")
    return (top + "".join(body(files[h]) for h in heads) +
            # the definitions once per file, however often it includes the header (an
            # outside trial included it twice: redefinitions)
            "\n#if defined(RIGIDSYM_C_IMPLEMENTATION) && !defined(RIGIDSYM_C_IMPLEMENTED)\n"
            "#define RIGIDSYM_C_IMPLEMENTED\n" +
            "".join(body(files[c]) for c in srcs) +
            "\n#endif /* RIGIDSYM_C_IMPLEMENTATION */\n")


def generate_c(codes, origin: str | dict[str, str], single_header: bool = False,
               bounds: dict | None = None, notice: str | None = None,
               prefix: str = LIBRARY) -> dict[str, str]:
    """The C-only target's files (``{relative path: text}``) of compiled kernels.

    Args:
        codes: :class:`rigidsym.codegen.generator.KernelCode` of the kernels and their
            Jacobian twins (as :func:`rigidsym.codegen.generator.compile_many` gives them).
        origin: where the kernels are declared (a module's name), for the provenance lines;
            or ``{kernel name: module}`` when they come from several.
        single_header: also write ``rigidsym_c_single.h``, every declaration and (under
            ``RIGIDSYM_C_IMPLEMENTATION``) every definition in one file.
        bounds: the float functions' measured bounds, ``{kernel: {"hash", "bound", ...}}``
            (default: the book's, :func:`float_bounds`); a kernel without one, or whose
            hash differs, is stated as not measured.
        notice: the licence or copyright notice of every file (its lines): None, the
            project's (MIT, with ``LICENSE``); "" none (no ``LICENSE``); else the user's
            (``rigidsym generate --notice``; no ``LICENSE``).
        prefix: the name of every exported symbol, macro, file, the CMake target and the
            pkg-config module (``rigidsym generate --prefix``; :mod:`.prefix`): a folder of
            another prefix links into the same program as one of the default.

    Returns:
        ``{relative path: text}``: ``rigidsym_c.h``, ``rigidsym_c_impl.h``, per kernel
        ``rigidsym_c_<kernel>.h`` and ``.c``, ``CMakeLists.txt``, ``rigidsym_c.pc.in``,
        ``rigidsym_cConfig.cmake.in``, ``README.md``, ``LICENSE`` (with the project's notice);
        ``<prefix>`` in place of ``rigidsym_c`` with another prefix.

    Raises:
        CTargetError: a kernel whose argument or output name would collide in C.
        PrefixError: a prefix :func:`.prefix.check_prefix` refuses (a ``ValueError``).
    """
    check_prefix(prefix)
    env = _env()
    groups = _groups(codes, origin, float_bounds() if bounds is None else bounds)
    if isinstance(origin, dict):
        origin = ", ".join(dict.fromkeys(origin.values()))
    ver = {"rigidsym": rigidsym.__version__, "sympy": sp.__version__}
    allhash = declaration_hash(codes)
    licence, licence_short = notice_lines(notice)
    common = {"lib": LIBRARY, "prefix": PREFIX, "status": STATUS, "ver": ver,
              "origin": origin, "groups": groups, "allhash": allhash, "licence": licence,
              "licence_short": licence_short}
    files: dict[str, str] = {}
    for g in groups:
        for t, ext in (("kernel.h.j2", "h"), ("kernel.c.j2", "c")):
            files[f"{LIBRARY}_{g['name']}.{ext}"] = env.get_template(t).render(
                g=g, template=t, **common)
    for t, path in (("rigidsym_c.h.j2", f"{LIBRARY}.h"),
                    ("rigidsym_c_common.h.j2", f"{LIBRARY}_common.h"),
                    ("rigidsym_c_impl.h.j2", f"{LIBRARY}_impl.h"),
                    ("CMakeLists.txt.j2", "CMakeLists.txt"),
                    ("pc.in.j2", f"{LIBRARY}.pc.in"),
                    ("Config.cmake.in.j2", f"{LIBRARY}Config.cmake.in"),
                    ("README.md.j2", "README.md"),
                    ("LICENSE.j2", "LICENSE")):
        if path != "LICENSE" or notice is None:
            files[path] = env.get_template(t).render(template=t, **common)
    if single_header:
        files[f"{LIBRARY}_single.h"] = _single_header(files, groups, allhash, ver, origin,
                                                      notice)
    return rename(dict(sorted(files.items())), prefix)


def render(ctx: RenderContext) -> dict[str, str]:
    """The C target's files of a generation (:func:`generate_c` of ``ctx.kernels``; the
    options ``single_header``, ``bounds``, ``notice`` and ``prefix`` from ``ctx.options``)."""
    return generate_c(ctx.kernels, ctx.origin, single_header=ctx.options.get("single_header",
                                                                              False),
                      bounds=ctx.options.get("bounds"), notice=ctx.options.get("notice"),
                      prefix=ctx.options.get("prefix", LIBRARY))


TARGET = Target("c", TEMPLATES, DoublePrinter, render, package=False)
