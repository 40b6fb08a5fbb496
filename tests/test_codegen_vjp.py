"""The generated vector-Jacobian and Jacobian-vector products, without
the array extras: the reverse- and forward-mode programs of ``rigidsym.codegen.derivatives.vjp``,
evaluated with NumPy, against the contraction of the generated Jacobian kernel
(``rigidsym.kernels.jacobian``, sympy's derivative of the declared formula), and their cost
against the forward program's (reverse mode over the program, not a Jacobian per entry)."""

from __future__ import annotations

import importlib

import _profile
import numpy as np
import pytest
import sympy as sp

from rigidsym import kernels as K
from rigidsym.codegen import generator as G
from rigidsym.codegen.derivatives.vjp import (
    cotangent_names,
    jvp_program,
    tangent_names,
    vjp_program,
)
from tests._arrays_cases import sample

#: a rational kernel with a singular set, a trig one with an angle (half-angle rewrite), and
#: one whose forward-mode program once read a temp before defining it (a local derivative,
#: cos(x2), named by a temp defined later: UnboundLocalError under jax.jacfwd)
NAMES = ["instant_screw_axis", "rotation_from_natural_invariants", "N_matrix_dot"]


def _program(name):
    kernel = {k.name: k for k in importlib.import_module(G.BOOK_ORIGIN).KERNELS}[name]
    kc = G.compile_kernel(kernel)
    return kc.variants[0].program, [s for _, syms in kc.inputs for s in syms]


def _run(prog, args, values):
    """Evaluate a straight-line program with NumPy on one sample."""
    env = {a: sp.Float(float(v), 17) for a, v in zip(args, values, strict=True)}
    for s, e in prog.temps:
        v = sp.sympify(e).xreplace(env)
        # a temp can be a condition (a Piecewise's, shared by CSE: the cos phi form of
        # codegen.cos_form near pi), which the printers write as a bool array
        env[s] = v if v.is_Boolean else sp.Float(float(v), 17)
    return np.array([float(sp.sympify(o).xreplace(env)) for o in prog.outputs])


@pytest.mark.sample(fraction=0.33)
@pytest.mark.parametrize("name", NAMES)
def test_vjp_and_jvp_are_the_generated_jacobian_contracted(name):
    prog, ins = _program(name)
    xs = sample(name, 1, seed=21)
    _, jac = K.jacobian(name)(*xs)
    meta = K._state.meta()[name]
    J = np.concatenate([np.concatenate([jac[o["name"]][a["name"]].reshape(
        int(np.prod(o["shape"])), -1) for a in meta["args"]], axis=1)
        for o in meta["outputs"]], axis=0)
    u = np.concatenate([x.reshape(-1) for x in xs])
    rng = np.random.default_rng(5)
    g, t = rng.standard_normal(J.shape[0]), rng.standard_normal(J.shape[1])
    back = vjp_program(prog, ins)
    got = _run(back, ins + [sp.Symbol(n) for n in cotangent_names(J.shape[0])],
               list(u) + list(g))
    np.testing.assert_allclose(got, g @ J, rtol=1e-12, atol=1e-12 * np.abs(J).max())
    fwd = jvp_program(prog, ins)
    got = _run(fwd, ins + [sp.Symbol(n) for n in tangent_names(J.shape[1])],
               list(u) + list(t))
    np.testing.assert_allclose(got, J @ t, rtol=1e-12, atol=1e-12 * np.abs(J).max())
    # reverse mode costs a small multiple of the forward program, however many entries J has
    assert back.ops <= 5 * prog.ops and fwd.ops <= 5 * prog.ops, (back.ops, fwd.ops, prog.ops)


@pytest.mark.slow
def test_every_product_program_defines_a_temp_before_reading_it():
    """The thorough run: N_matrix_dot (whose forward-mode program once read a temp before
    defining it) and a seeded third of the other kernels with a Jacobian (each commit another
    third; all in the exhaustive profile). A temp read before its definition raises where the
    program runs: every kernel's reverse-mode program in every run as the PyTorch backward
    (test_gradients_are_the_generated_jacobians), its forward-mode program under jax.jacfwd
    (test_jacfwd_and_jacrev_are_the_generated_jacobians, another seeded share)."""
    from rigidsym.codegen.derivatives.jacobians import has_jacobian
    kernels = [k for k in importlib.import_module(G.BOOK_ORIGIN).KERNELS if has_jacobian(k)]
    drawn = set(_profile.share([k.name for k in kernels if k.name != "N_matrix_dot"], 0.33))
    for kernel in kernels:
        if kernel.name != "N_matrix_dot" and kernel.name not in drawn:
            continue
        kc = G.compile_kernel(kernel)
        prog = kc.variants[0].program
        ins = [s for _, syms in kc.inputs for s in syms]
        for p, extra in ((vjp_program(prog, ins), cotangent_names(len(prog.outputs))),
                         (jvp_program(prog, ins), tangent_names(len(ins)))):
            seen = set(ins) | {sp.Symbol(n) for n in extra}
            for x, e in p.temps:
                assert sp.sympify(e).free_symbols <= seen, (kernel.name, x)
                seen.add(x)
            for o in p.outputs:
                assert sp.sympify(o).free_symbols <= seen, kernel.name
