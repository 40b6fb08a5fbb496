"""Kernel specification types: what a generated kernel computes, independent of any backend.

A :class:`Kernel` names its inputs and outputs (per-sample shapes), the book ids and the
formula functions it composes, and a ``build`` callable that returns the explicit sympy
outputs from explicit sympy inputs. Optional :class:`Branch` entries are alternative builds
selected per sample by a declared condition (a template construct, e.g. near phi = pi).
The particular kernels live in ``derivations/kernels_spec.py``; this module knows none.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import sympy as sp

from rigidsym.core import kinds as _kinds

__all__ = ["Arg", "Out", "Branch", "Kernel", "input_symbols", "Grouped"]


@dataclass(frozen=True)
class Arg:
    """One kernel input.

    Attributes:
        name: the argument name (book letters in ASCII, e.g. ``a_dot``).
        shape: per-sample shape, ``()`` for a scalar, ``(3,)``, ``(3, 3)``, ``(4,)``.
        kind: the constraint the kernels validate at run time (``check=True``), a spec
            name of the kind table (:mod:`rigidsym.core.kinds`) that fits ``shape``:
            ``"any"`` (no constraint, the default), ``"unit"`` (a unit vector, shape
            ``(3,)`` or ``(4,)``: ``| ||x|| - 1 | <= 1e-8``), ``"rotation"`` (shape
            ``(3, 3)``, proper orthogonal: ``max |Q^T Q - 1| <= 1e-8``, ``det Q > 0``),
            ``"angle"`` (a scalar in radians: not validated beyond finiteness; the
            generated code rewrites its sines and cosines by half angles). float32
            arguments are checked to 100 float32 epsilons.
        doc: what it is (units, frame), for the docstring.

    Raises:
        ValueError: ``kind`` is not a spec name of the kind table, or does not fit
            ``shape``.
    """

    name: str
    shape: tuple[int, ...]
    kind: str = "any"
    doc: str = ""

    def __post_init__(self) -> None:
        try:
            _kinds.for_spec(self.kind, self.shape)
        except ValueError as exc:
            raise ValueError(f"Arg {self.name!r}: {exc}") from None

    @property
    def size(self) -> int:
        return math.prod(self.shape)


@dataclass(frozen=True)
class Out:
    """One kernel output.

    Attributes:
        name: the output name (book letters in ASCII).
        shape: per-sample shape, ``()`` for a scalar.
        doc: what it is (units, frame), for the docstring.
    """

    name: str
    shape: tuple[int, ...]
    doc: str = ""

    @property
    def size(self) -> int:
        return math.prod(self.shape)


@dataclass(frozen=True)
class Branch:
    """An alternative build used where ``when(inputs)`` (a sympy boolean) holds.

    Branches are tried in order before the kernel's main ``build``; the first whose
    condition holds is used for that sample.

    Attributes:
        name: the branch's name (in the generated code).
        when: ``when(**inputs)``: a sympy boolean of the explicit inputs.
        build: ``build(**inputs) -> {output name: value}``, as :attr:`Kernel.build`.
        doc: why the branch exists (for the generated code's comments).
        default: the outputs this branch sets to a documented default because they are
            undetermined there (the axis at phi = 0), ``""`` when none: the C target's
            status then has ``RIGIDSYM_C_DEFAULT_OUTPUT``; the other outputs are right.
    """

    name: str
    when: Callable[..., sp.Basic]
    build: Callable[..., dict]
    doc: str = ""
    default: str = ""


@dataclass(frozen=True)
class Kernel:
    """A batched kernel composed of declared formula functions.

    Attributes:
        name: public name (``rigidsym.kernels.<name>``).
        summary: one-line docstring summary.
        formula: the formula in plain text.
        ids: book equation ids.
        sources: dotted names of the formula functions composed (``module.function``).
        args, outputs: inputs and outputs, in call order.
        build: ``build(**symbols) -> {output name: sympy Matrix or scalar}``.
        singular: human description of the singular set (``""`` when none).
        singular_arg: the argument named in ``SingularConfigurationError``.
        branches: per-sample alternatives (template construct).
        notes: extra docstring notes.
        public: exported as-is from :mod:`rigidsym.kernels` (False for building blocks
            that a hand-written wrapper dispatches to, e.g. the Euler-angle sequences).
        jacobian: also generate ``<name>_with_jacobians`` (values and derivatives w.r.t.
            every input, :mod:`rigidsym.codegen.derivatives.jacobians`) when the kernel has no
            branches.
        branch_jacobian: with branches too, each differentiated with its value (the same
            selection per sample): for branches that agree on the inputs' manifold, whose
            derivatives then agree along it (the Lie logs).
    """

    name: str
    summary: str
    formula: str
    ids: tuple[str, ...]
    sources: tuple[str, ...]
    args: tuple[Arg, ...]
    outputs: tuple[Out, ...]
    build: Callable[..., dict]
    singular: str = ""
    singular_arg: str = ""
    branches: tuple[Branch, ...] = field(default_factory=tuple)
    notes: str = ""
    public: bool = True
    jacobian: bool = True
    branch_jacobian: bool = False
    jacobian_from: str = "formula"
    jacobian_of: Kernel | None = None


def input_symbols(kernel: Kernel) -> dict:
    """Explicit sympy inputs for ``kernel``: real scalar symbols arranged in its shapes.

    A vector ``e`` of shape (3,) becomes the column ``Matrix([e_0, e_1, e_2])``; a matrix
    ``Q`` of shape (3, 3) becomes ``Matrix([[Q_00, ...]])``; a scalar is a Symbol.

    Args:
        kernel: the kernel declaration.

    Returns:
        ``{argument name: sympy Symbol or Matrix}``, real symbols, in the argument order.
    """
    out = {}
    for a in kernel.args:
        if a.shape == ():
            out[a.name] = sp.Symbol(a.name, real=True)
        elif len(a.shape) == 1:
            out[a.name] = sp.Matrix([sp.Symbol(f"{a.name}_{i}", real=True)
                                     for i in range(a.shape[0])])
        else:
            r, c = a.shape
            out[a.name] = sp.Matrix(r, c, [sp.Symbol(f"{a.name}_{i}{j}", real=True)
                                           for i in range(r) for j in range(c)])
    return out


def flat_symbols(kernel: Kernel) -> list[tuple[str, list[sp.Symbol]]]:
    """Per argument, its scalar symbols in row-major order."""
    syms = input_symbols(kernel)
    res = []
    for a in kernel.args:
        v = syms[a.name]
        res.append((a.name, [v] if a.shape == () else list(v)))
    return res


def flatten_outputs(kernel: Kernel, values: dict) -> list[sp.Expr]:
    """A build's ``{output: value}`` as one flat list, in the order of the outputs, each
    row-major (the order of the generated programs' outputs)."""
    flat: list[sp.Expr] = []
    for o in kernel.outputs:
        if o.name not in values:
            raise ValueError(f"{kernel.name}: build did not return output {o.name!r}")
        v = values[o.name]
        if o.shape == ():
            if isinstance(v, sp.MatrixBase):
                if v.shape != (1, 1):
                    raise ValueError(f"{kernel.name}.{o.name}: expected a scalar, got {v.shape}")
                v = v[0, 0]
            flat.append(sp.sympify(v))
        else:
            m = sp.Matrix(v)
            if len(m) != o.size:
                raise ValueError(f"{kernel.name}.{o.name}: expected {o.shape}, got {m.shape}")
            if len(o.shape) == 2 and m.shape != o.shape:
                raise ValueError(f"{kernel.name}.{o.name}: expected {o.shape}, got {m.shape}")
            flat.extend(list(m))          # row-major
    return flat


class Grouped(sp.UnevaluatedExpr):
    """A sub-expression the removable-singularity pass
    (:mod:`rigidsym.codegen.removable.singularities`)
    rewrites alone and never distributes into the monomials around it (the SE(3)
    inverse Jacobian's 3 x 3 matrix products, which distributed into monomials of degree 9 in
    ``w`` lost up to 470 times the rule at large ``|w|``); that pass removes the marks from
    what it returns, so the program keeps the grouping as its structure and nothing after it
    sees them. Printed (the harness's reference) as its argument in parentheses: an
    ``UnevaluatedExpr`` of a sum printed bare (``-a + b``) was read by the enclosing sum's
    printer as a negative term, its sign pulled out of the first term alone (``- (a + b)``).
    Here, beside the kernel declarations' other names, so that a book or a reader's module
    marks a group without importing the generator's passes.

    Args:
        expr: the sympy expression to keep together (a scalar; a matrix is marked entry by
            entry).
    """

    def _in_parentheses(self, printer, *args, **kw):
        return f"({printer._print(self.args[0])})"

    _sympystr = _lambdacode = _pythoncode = _mpmathcode = _numpycode = _in_parentheses

    def _eval_derivative(self, s):
        # the mark is a grouping, not a function: d(group)/ds is the derivative of what it
        # groups (without it sympy leaves Derivative(group, s), which the Jacobian program
        # cannot substitute into: the SE(3) inverse Jacobian's)
        return self.args[0].diff(s)
