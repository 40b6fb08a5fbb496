"""The user's function as a Python callable: ``package.module:function`` imported, a bound
method or a chain written as an expression over the module's names
(``pyquaternion:Quaternion(matrix=...).axis``, each ``...`` an argument, or the lambda
form ``pyquaternion:lambda Q: Quaternion(matrix=Q).axis``), or a C symbol of a shared
library called through ctypes (``libfoo.so:fn`` with a signature
``t_A[6],a[3],p[3]->t_P[6]``: pointers to doubles, inputs then outputs, returning void).
PyTorch functions are called with NumPy arrays first and, where that raises, with tensors
of the same values (their outputs are read back as NumPy arrays); the framework used is
recorded on the callable (``framework``), for the reproducer to build the same tensors.
"""

from __future__ import annotations

import ast
import ctypes
import importlib
import inspect
import re
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from rigidsym.core.errors import BadInput

__all__ = ["load", "c_function", "parameter_names", "as_numpy_callable", "Expression",
           "expression", "FRAMEWORKS", "framework_version"]

#: the array frameworks a function may need its arguments in: ``{module: the function
#: that makes its array of a NumPy array}`` (JAX takes NumPy arrays itself)
FRAMEWORKS = {"torch": "as_tensor"}


@dataclass(frozen=True)
class Expression:
    """A spec whose attribute part is an expression (a bound method, a chain).

    Attributes:
        module: the module whose names it uses.
        source: the lambda's source (``lambda matrix: Quaternion(matrix=matrix).axis``).
        names: the module's names it uses (imported by a reproducer).
    """

    module: str
    source: str
    names: tuple[str, ...]


def expression(spec: str) -> Expression | None:
    """The :class:`Expression` of ``spec`` (``mod:lambda x: f(x).g`` or ``mod:EXPR`` with each
    ``...`` an argument, named after its keyword where it is one: ``Quaternion(matrix=...)
    .axis`` takes ``matrix``), or None for a plain ``module:attribute[.attribute]``. The
    expression sees the module's names and its top-level package by its own name
    (``rowan:lambda Q: rowan.to_euler(rowan.from_matrix(Q), 'zyx', 'intrinsic')``).

    Raises:
        BadInput: an expression that does not parse, or has no argument."""
    mod_name, sep, attr = spec.partition(":")
    if not sep or re.fullmatch(r"[A-Za-z_]\w*(\.[A-Za-z_]\w*)*", attr.strip()):
        return None
    text = attr.strip()
    if not text.startswith("lambda"):
        names, out, k = [], [], 0
        for m in re.finditer(r"(?:(\b[A-Za-z_]\w*)\s*=\s*)?\.\.\.", text):
            kw = m.group(1)
            name = kw if kw and kw not in names else f"arg{len(names)}"
            names.append(name)
            out.append(text[k:m.start()] + (f"{kw}={name}" if kw else name))
            k = m.end()
        if not names:
            raise BadInput(f"function {spec!r}: an expression needs its arguments as ... "
                           f"(Quaternion(matrix=...).axis) or the lambda form "
                           f"(lambda Q: Quaternion(matrix=Q).axis)")
        text = f"lambda {', '.join(names)}: " + "".join(out) + text[k:]
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as e:
        raise BadInput(f"function {spec!r}: the expression does not parse ({e.msg})") from e
    if not isinstance(tree.body, ast.Lambda):
        raise BadInput(f"function {spec!r}: expected a lambda or an expression with ...")
    params = {a.arg for a in tree.body.args.args}
    used = sorted({n.id for n in ast.walk(tree) if isinstance(n, ast.Name)
                   and isinstance(n.ctx, ast.Load)} - params)
    return Expression(mod_name, text, tuple(used))


def framework_version(name: str) -> str | None:
    """The installed version of the framework ``name`` (its distribution's, else its
    ``__version__``), None where it does not import."""
    from importlib import metadata

    try:
        return metadata.version(name)
    except metadata.PackageNotFoundError:
        import sys

        v = getattr(sys.modules.get(name), "__version__", None)
        return v if isinstance(v, str) else None


def load(spec: str) -> Callable:
    """The callable named by ``spec``, ``package.module:attribute[.attribute]``.

    Raises:
        BadInput: a spec without ``:``, a module that does not import, a missing name or
            one that is not callable, each named."""
    mod_name, sep, attr = spec.partition(":")
    if not sep or not mod_name or not attr:
        raise BadInput(f"function {spec!r}: expected MODULE:FUNCTION (mypkg.mymod:adjoint)")
    try:
        obj = importlib.import_module(mod_name)
    except ImportError as e:
        raise BadInput(f"function {spec!r}: module {mod_name!r} does not import ({e})") from e
    ex = expression(spec)
    if ex is not None:
        import builtins

        top = mod_name.split(".")[0]
        missing = [n for n in ex.names if not hasattr(obj, n) and not hasattr(builtins, n)
                   and n != top]
        if missing:
            raise BadInput(f"function {spec!r}: {mod_name} has no {', '.join(missing)}")
        # the module's names, and the package by its own name (rowan.to_euler(...))
        scope = {**vars(obj), top: importlib.import_module(top)}
        fn = eval(ex.source, scope)  # noqa: S307  (the user's own expression)
        fn.__name__ = fn.__qualname__ = attr.strip()
        return fn
    for part in attr.split("."):
        if not hasattr(obj, part):
            raise BadInput(f"function {spec!r}: {mod_name} has no {attr!r}")
        obj = getattr(obj, part)
    if not callable(obj):
        raise BadInput(f"function {spec!r}: {attr!r} is a {type(obj).__name__}, not callable")
    return obj


_ARG = re.compile(r"^\s*([A-Za-z_]\w*)\s*\[\s*([\d\s,x]*)\s*\]\s*$")


def _shapes(part: str, what: str, sig: str) -> list[tuple[str, tuple[int, ...]]]:
    out = []
    for a in filter(None, (x.strip() for x in re.split(r",(?![^\[]*\])", part))):
        m = _ARG.match(a)
        if not m:
            raise BadInput(f"--signature {sig!r}: {what} {a!r}: expected NAME[N] or "
                           f"NAME[N,M] (doubles)")
        dims = tuple(int(d) for d in re.split(r"[,x\s]+", m.group(2).strip()) if d) or (1,)
        out.append((m.group(1), dims))
    return out


def c_function(spec: str, signature: str) -> tuple[Callable, tuple[str, ...]]:
    """``(callable, parameter names)`` of the C function ``spec`` (``path/libfoo.so:fn``)
    with ``signature`` (``in1[3],in2[3,3]->out[6]``: ``void fn(const double *in1, ...,
    double *out, ...)``, arrays row-major).

    Raises:
        BadInput: a library that does not load, a missing symbol, a malformed signature."""
    lib_path, sep, sym = spec.rpartition(":")
    if not sep or not lib_path or not sym:
        raise BadInput(f"--c {spec!r}: expected LIBRARY:SYMBOL (./libfoo.so:adjoint)")
    ins, arrow, outs = signature.partition("->")
    if not arrow:
        raise BadInput(f"--signature {signature!r}: expected INPUTS->OUTPUTS "
                       f"(t_A[6],a[3],p[3]->t_P[6])")
    ins_s, outs_s = _shapes(ins, "input", signature), _shapes(outs, "output", signature)
    if not ins_s or not outs_s:
        raise BadInput(f"--signature {signature!r}: at least one input and one output")
    try:
        lib = ctypes.CDLL(lib_path)
        fn = getattr(lib, sym)
    except OSError as e:
        raise BadInput(f"--c {spec!r}: library {lib_path!r} does not load ({e})") from e
    except AttributeError as e:
        raise BadInput(f"--c {spec!r}: no symbol {sym!r} in {lib_path}") from e
    ptr = ctypes.POINTER(ctypes.c_double)
    fn.argtypes = [ptr] * (len(ins_s) + len(outs_s))
    fn.restype = None

    def call(*args):
        if len(args) != len(ins_s):
            raise TypeError(f"{sym}() takes {len(ins_s)} arguments but {len(args)} were given")
        keep = []
        for (name, shape), a in zip(ins_s, args, strict=True):
            a = np.ascontiguousarray(a, dtype=np.float64)
            if a.size != int(np.prod(shape)):
                raise ValueError(f"{sym}: {name} has {a.size} values, expected {shape}")
            keep.append(a)
        res = [np.zeros(shape) for _, shape in outs_s]
        fn(*[a.ctypes.data_as(ptr) for a in keep], *[r.ctypes.data_as(ptr) for r in res])
        return res[0] if len(res) == 1 else tuple(res)

    call.__name__ = sym
    return call, tuple(n for n, _ in ins_s)


def parameter_names(func: Callable) -> tuple[str, ...] | None:
    """The names of ``func``'s positional parameters (None where Python cannot say)."""
    try:
        ps = inspect.signature(func).parameters.values()
    except (TypeError, ValueError):
        return None
    names = [p.name for p in ps if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)
             and p.default is p.empty]
    return tuple(names) or None


def as_numpy_callable(func: Callable) -> Callable:
    """``func`` called with NumPy arrays, and where that raises a TypeError or an
    AttributeError (a PyTorch function), with float64 tensors of the same values (each
    framework of :data:`FRAMEWORKS` that imports, in turn); the framework that worked is
    the callable's ``framework`` attribute from then on ("" for NumPy)."""
    def convert(name: str, args) -> list:
        mod = importlib.import_module(name)
        make = getattr(mod, FRAMEWORKS[name])
        return [make(np.asarray(a)) for a in args]

    def call(*args):
        if call.framework:
            return func(*convert(call.framework, args))
        try:
            return func(*args)
        except (TypeError, AttributeError) as first:
            for name in FRAMEWORKS:
                try:
                    importlib.import_module(name)
                except ImportError:
                    continue
                try:
                    out = func(*convert(name, args))
                except Exception:  # noqa: BLE001, S112  (not this framework's function)
                    continue
                call.framework = name
                return out
            raise first from None

    call.framework = ""
    call.__name__ = getattr(func, "__name__", "function")
    call.__wrapped__ = func
    return call
