"""The generator's shortcuts for time (all book kernels <= 60 s cold) compute what
sympy computes: the math hash as ``srepr`` prints it, lambdify's implemented functions as
its own walk finds them, and the pool's jobs hold every kernel once, a twin with its kernel;
a worker renders a kernel's files as the targets do, and the printers order an Add's terms
as sympy does.
"""

from __future__ import annotations

import hashlib

import sympy as sp
from sympy.utilities.lambdify import _imp_namespace, implemented_function

from rigidsym.codegen.accuracy.error import implementations, lambdified
from rigidsym.codegen.optimise import math_hash


def _deep(n: int):
    """An expression whose sub-expressions are shared at every level (a tree of 2^n
    leaves, n + 1 distinct nodes): what differentiation builds."""
    x, y = sp.symbols("x y")
    e = sp.sin(x) * y + sp.Rational(1, 3)
    for _ in range(n):
        e = sp.cos(e) * e + e**2
    return e


def test_math_hash_is_srepr_of_shared_subexpressions():
    parts = [_deep(6), sp.Symbol("x") > 0, sp.Piecewise((_deep(3), sp.Symbol("y") > 1),
                                                          (sp.Float("0.5"), True))]
    h = hashlib.sha256()
    for p in parts:
        h.update(sp.srepr(p).encode())
        h.update(b"\0")
    assert math_hash(parts) == h.hexdigest()[:16]
    assert math_hash(parts[:1]) != math_hash(parts[1:2])


def test_implementations_are_lambdifys_own():
    x = sp.Symbol("x")
    f = implemented_function("f_one", lambda v: v + 1)
    g = implemented_function("g_ten", lambda v: 10 * v)
    exprs = [f(g(x)) * _deep(4).subs(sp.Symbol("y"), 2), g(x) + 1, sp.Integer(2)]
    assert implementations(exprs) == _imp_namespace(exprs)
    assert set(implementations(exprs)) == {"f_one", "g_ten"}
    num = lambdified([x], exprs, "math")
    ref = sp.lambdify([x], exprs, modules="math")
    assert num(0.25) == ref(0.25)
    assert num(0.25)[1] == 3.5


def test_pool_jobs_hold_every_kernel_once_with_its_twin():
    import importlib

    from rigidsym.codegen import generator as g
    from rigidsym.core.config import KERNEL_SPEC

    todo = g._with_jacobian_kernels(sorted(importlib.import_module(KERNEL_SPEC).KERNELS,
                                           key=lambda k: k.name))
    groups = g._groups(todo)
    flat = [i for gr in groups for i in gr]
    assert sorted(flat) == list(range(len(todo)))
    for gr in groups:
        names = [todo[i].name for i in gr]
        base = names[0]
        assert all(n == base + "_with_jacobians" for n in names[1:]), names
    twins = [n for n in (k.name for k in todo) if n.endswith("_with_jacobians")]
    assert sum(len(gr) == 2 for gr in groups) == len(twins)


def test_a_workers_rendered_files_are_the_targets_own():
    """A pool job compiles a kernel and renders its package files; the parent gets the
    files and the programs packed: the files are what each target's ``render_kernel``
    prints from the unpacked kernel, and the unpacked programs are the compiled ones."""
    import importlib

    from rigidsym.codegen import generator as g
    from rigidsym.codegen.backends import targets
    from rigidsym.core.config import KERNEL_SPEC

    book = {k.name: k for k in importlib.import_module(KERNEL_SPEC).KERNELS}
    todo = g._with_jacobian_kernels([book["kinetic_energy"]])
    assert [k.name for k in todo] == ["kinetic_energy", "kinetic_energy_with_jacobians"]
    g._TODO[:], g._RENDER[0] = todo, KERNEL_SPEC
    try:
        got = g._compile_group((0, 1))
    finally:
        g._TODO.clear()
        g._RENDER[0] = None
    rendering = [t for t in targets(package=True) if t.render_kernel is not None]
    assert {t.name for t in rendering} >= {"numpy", "extension", "torch", "jax"}
    for (i, part, files), k in zip(got, todo, strict=True):
        assert todo[i] is k
        kc = g.PackedKernelCode(k, *part)
        fresh = g.compile_kernel(k)
        assert kc.hash == fresh.hash and kc.ops == fresh.ops
        assert [v.program.outputs for v in kc.variants] == \
            [v.program.outputs for v in fresh.variants]
        assert kc.plan32 == fresh.plan32
        ctx = g._context([kc], [g._meta(kc)], KERNEL_SPEC)
        assert set(files) == {(t.name, k.name) for t in rendering}
        for t in rendering:
            assert files[(t.name, k.name)] == t.render_kernel(ctx, fresh), (t.name, k.name)


def test_the_printers_order_of_terms_is_sympys():
    from rigidsym.codegen.backends.extension.printer import KernelCPrinter
    from rigidsym.codegen.backends.numpy.printer import KernelNumPyPrinter

    x, y, z = sp.symbols("x y z")
    sums = [x - 2 * y + sp.sin(z), 1 - x * y, sp.Rational(1, 3) + z**2 - x, _deep(2) + y]
    for pr in (KernelCPrinter(), KernelNumPyPrinter()):
        for e in sums:
            first = pr._as_ordered_terms(e)
            assert first == e.as_ordered_terms()
            first.reverse()    # the caller's list is its own: the remembered order stays
            assert pr._as_ordered_terms(e) == e.as_ordered_terms()
