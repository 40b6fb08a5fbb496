"""The C++ target: ``rigidsym generate --target cpp --out DIR [--namespace NAME]``.

Writes the C-only target's folder (:mod:`rigidsym.codegen.backends.c`) and beside it one
header-only C++ layer over its scalar functions, ``rigidsym_c.hpp``: in ``namespace NAME``
(default ``rigidsym``) the status as an ``enum class``, and per kernel (and Jacobian twin)

* ``NAME::eigen::<kernel>(...)``: arguments of any Eigen type of the argument's static
  shape (``Eigen::MatrixBase``: plain matrices of either storage order, maps, blocks,
  expressions), copied element by element ``(i, j)`` into the C function's row-major
  buffer, so that a column-major ``Matrix3d`` is read as the matrix it is, never as its
  transpose; a wrong shape or scalar type is a compile-time error;
* ``NAME::arrays::<kernel>(...)``: arguments as ``std::array`` nested as the kernel's
  per-sample shape (a 3 x 3 matrix is ``std::array<std::array<S, 3>, 3>``, row i first);

each returning a ``<kernel>_result<S>`` by value: the ``status`` and the outputs by their
names (Eigen matrices of static shape, a Jacobian of an output of rank >= 1 by an argument
of rank >= 1 of total rank > 2 folded to the matrix ``d vec(X) / d vec(a)`` of row-major
``vec``; or nested ``std::array``), for ``float`` (the C ``_f32`` functions) and ``double``
alike, chosen by the arguments' scalar type. The Eigen part is compiled where
``<Eigen/Core>`` is found (``__has_include``), or as the macro ``RIGIDSYM_C_EIGEN`` says;
the ``std::array`` part needs no Eigen. The layer holds no kernel program: it calls the C
functions, so the C++ and C answers are the same bits. docs/c-api.md, "C++", is the
user's guide.
"""

from __future__ import annotations

import keyword
import math
import re
import textwrap
from pathlib import Path

import jinja2
import sympy as sp

import rigidsym
from rigidsym.codegen.backends import RenderContext, Target
from rigidsym.codegen.backends.c import target as c_target
from rigidsym.codegen.backends.c.prefix import check_prefix, rename
from rigidsym.codegen.backends.c.target import LIBRARY, PREFIX, STATUS, notice_lines
from rigidsym.codegen.backends.cpp.printer import CppPrinter

__all__ = ["generate_cpp", "CppTargetError", "HEADER", "TEMPLATES", "TARGET", "render",
           "check_namespace", "DEFAULT_NAMESPACE"]

TEMPLATES = Path(__file__).parent / "templates"
#: the layer's file name in the generated folder
HEADER = f"{LIBRARY}.hpp"
#: the namespace of the layer unless ``--namespace`` names another (or ``--prefix``: then
#: the prefix)
DEFAULT_NAMESPACE = "rigidsym"
#: C++ keywords and alternative tokens a name of the layer must not be (C's are the C
#: target's to refuse)
_CPP_KEYWORDS = set("""alignas alignof and and_eq asm bitand bitor bool catch char16_t
char32_t char8_t class co_await co_return co_yield compl concept const_cast consteval
constexpr constinit decltype delete dynamic_cast explicit export false friend mutable
namespace new noexcept not not_eq nullptr operator or or_eq private protected public
reinterpret_cast requires static_assert static_cast template this thread_local throw true
try typeid typename using virtual wchar_t xor xor_eq auto break case char const continue
default do double else enum extern float for goto if inline int long register return short
signed sizeof static struct switch typedef union unsigned void volatile while""".split())
#: names the layer defines in the namespace (a kernel must not take one)
_RESERVED = {"Status", "detail", "eigen", "arrays", "has", "ok"}


class CppTargetError(ValueError):
    """A kernel or namespace name the C++ layer cannot use."""


def check_namespace(name: str) -> str:
    """``name`` if it is a C++ namespace name (identifiers joined by ``::``, none a keyword,
    none reserved: no ``__``, no leading ``_``); raises :class:`CppTargetError` otherwise."""
    parts = name.split("::")
    for p in parts:
        if not re.fullmatch(r"[A-Za-z]\w*", p) or "__" in p or p in _CPP_KEYWORDS:
            raise CppTargetError(f"--namespace: {name!r} is not a C++ namespace name "
                                 f"(identifiers joined by '::', no keyword, no '__')")
    return name


def _rows_cols(shape: tuple, fold: tuple | None) -> tuple[int, int]:
    """The Eigen shape of a per-sample shape: (n, 1) for a vector, (m, n) for a matrix,
    and for a higher rank ``fold`` (the rows' part, a Jacobian's output shape) or the
    first axis against the rest."""
    if len(shape) == 1:
        return shape[0], 1
    if len(shape) == 2 and fold is None:
        return shape
    head = fold if fold is not None else shape[:1]
    return math.prod(head), math.prod(shape[len(head):])


def _nested(shape: tuple, scalar: str) -> str:
    t = scalar
    for d in reversed(shape):
        t = f"std::array<{t}, {d}>"
    return t


def _value(name: str, shape: tuple, doc: str, fold: tuple | None) -> dict:
    """What the template needs of one argument or output."""
    shape = tuple(int(d) for d in shape)
    kind = "scalar" if not shape else "vector" if len(shape) == 1 else "matrix"
    entry = {"name": name, "p": f"in_{name}", "b": f"buf_{name}", "t": f"cp_{name}",
             "shape": list(shape), "size": math.prod(shape), "doc": doc,
             "kind": kind, "array": _nested(shape, "rs_S"),
             "shape_text": " x ".join(map(str, shape)) or "scalar"}
    if shape:
        rows, cols = _rows_cols(shape, fold)
        # row-major where both sides exceed 1 (Eigen's rule for a vector): the C function
        # writes an output in place, and reads such an argument in place
        order = ", Eigen::RowMajor" if rows > 1 and cols > 1 else ""
        entry.update(rows=rows, cols=cols, folded=len(shape) > 2,
                     eigen=f"Eigen::Matrix<rs_S, {rows}, {cols}{order}>")
    else:
        entry.update(eigen="rs_S", folded=False)
    return entry


def _check_names(k) -> None:
    """Refuse a name the layer cannot spell: an output (a member of the result struct) or the
    kernel named as a C++ keyword or ``status``, a name reserved in C++ (``__`` in it, a
    leading ``_``), a kernel named as what the layer defines. An argument may take any
    other name: the layer spells it and its locals ``in_<name>``, ``buf_<name>``,
    ``cp_<name>`` (:func:`_value`), which none of its own identifiers (``rs_...``,
    ``detail``, Eigen's, the standard library's) starts with."""
    for n in [*(a.name for a in k.args), *(o.name for o in k.outputs), k.name]:
        if "__" in n or n.startswith("_"):
            raise CppTargetError(f"kernel {k.name}: the name {n!r} is reserved in C++ "
                                 f"(a leading _ or a __); rename it in the declaration")
    for n in [*(o.name for o in k.outputs), k.name]:
        if n in _CPP_KEYWORDS or keyword.iskeyword(n) or n == "status":
            raise CppTargetError(f"kernel {k.name}: the name {n!r} is a C++ keyword or "
                                 f"the result's status member; rename it in the "
                                 f"declaration")
    if k.name in _RESERVED or k.name.endswith("_result"):
        raise CppTargetError(f"kernel {k.name}: its name is one the C++ layer defines "
                             f"({', '.join(sorted(_RESERVED))}, *_result); rename it")


def _entry(kc) -> dict:
    """One kernel (or Jacobian twin) of the layer."""
    from rigidsym.codegen.derivatives.jacobians import SUFFIX

    k = kc.kernel
    _check_names(k)
    shapes = {o.name: tuple(o.shape) for o in k.outputs}
    args = {a.name: tuple(a.shape) for a in k.args}
    outs = []
    for o in k.outputs:
        fold = None
        for x, xs in shapes.items():       # X_D_a: d X / d a, rows X's components
            a = o.name[len(x) + 3:] if o.name.startswith(f"{x}_D_") else None
            if a in args and xs and args[a] and len(xs) + len(args[a]) > 2:
                fold = xs
        outs.append(_value(o.name, o.shape, o.doc or "", fold))
    group = k.name[:-len(SUFFIX)] if k.name.endswith(SUFFIX) else k.name
    return {"name": k.name, "summary": k.summary, "hash": kc.hash,
            "c_header": f"{LIBRARY}_{group}.h", "c_double": f"{PREFIX}{k.name}",
            "c_float": f"{PREFIX}{k.name}_f32",
            "args": [_value(a.name, a.shape, a.doc or "", None) for a in k.args],
            "outs": outs}


def _env() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(TEMPLATES)), keep_trailing_newline=True,
        trim_blocks=True, lstrip_blocks=True, undefined=jinja2.StrictUndefined,
        autoescape=False)
    env.filters["wrap"] = lambda text, width: textwrap.wrap(text, width) or [""]
    return env


def generate_cpp(codes, origin: str, namespace: str | None = None,
                 notice: str | None = None, prefix: str = LIBRARY) -> dict[str, str]:
    """The C++ layer's files (``{relative path: text}``) over the C target of ``codes``.

    Args:
        codes: :class:`rigidsym.codegen.generator.KernelCode` of the kernels and their
            Jacobian twins (those :func:`rigidsym.codegen.backends.c.generate_c` prints).
        origin: where the kernels are declared (a module's name), for the provenance line.
        namespace: the C++ namespace of the layer (``a`` or ``a::b``); default (None): the
            prefix, or ``rigidsym`` (:data:`DEFAULT_NAMESPACE`) for the default prefix.
        notice: the licence or copyright notice (its lines): None the project's (MIT),
            "" none, else the user's (``rigidsym generate --notice``).
        prefix: the C folder's prefix (:func:`rigidsym.codegen.backends.c.generate_c`'s):
            the header's name, its macros and the C functions it calls carry it.

    Returns:
        ``{"rigidsym_c.hpp": text}``: the header-only layer (it includes ``rigidsym_c.h``
        of the C target, which must be generated into the same folder); ``<prefix>.hpp``
        including ``<prefix>.h`` with another prefix.

    Raises:
        CppTargetError: a namespace or a kernel, argument or output name the layer cannot
            use (a C++ keyword, a name it defines, one with ``__`` or ``rs_``).
        PrefixError: a prefix :func:`rigidsym.codegen.backends.c.prefix.check_prefix`
            refuses (a ``ValueError``).
    """
    check_prefix(prefix)
    if namespace is None:
        namespace = DEFAULT_NAMESPACE if prefix == LIBRARY else prefix
    check_namespace(namespace)
    kernels = [_entry(kc) for kc in sorted(codes, key=lambda kc: kc.kernel.name)]
    ver = {"rigidsym": rigidsym.__version__, "sympy": sp.__version__}
    t = "rigidsym_cpp.hpp.j2"
    text = _env().get_template(t).render(
        template=t, ns=namespace, lib=LIBRARY, guard=f"{LIBRARY.upper()}_HPP",
        eigen_macro=f"{LIBRARY.upper()}_EIGEN", status=STATUS, kernels=kernels, ver=ver,
        origin=origin, licence=notice_lines(notice)[0], allhash=c_target.declaration_hash(codes))
    return rename({HEADER: text}, prefix)


def render(ctx: RenderContext) -> dict[str, str]:
    """The C++ layer's files of a generation (:func:`generate_cpp` of ``ctx.kernels``; the
    options ``namespace``, ``notice`` and ``prefix`` from ``ctx.options``)."""
    return generate_cpp(ctx.kernels, ctx.origin, namespace=ctx.options.get("namespace"),
                        notice=ctx.options.get("notice"),
                        prefix=ctx.options.get("prefix", LIBRARY))


TARGET = Target("cpp", TEMPLATES, CppPrinter, render, package=False)
