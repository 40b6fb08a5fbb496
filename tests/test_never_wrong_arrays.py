"""Kernels never silently wrong on PyTorch and JAX: finite in,
finite out over the whole floating range, ``check=False`` equal to ``check=True`` on valid
input, and one NaN policy, the same NaN positions as the C and NumPy kernels, on every
public kernel. Skipped where PyTorch or JAX is not installed.

Each test names the defect it guards against.
"""

from __future__ import annotations

import _profile
import numpy as np
import pytest
from test_kernels_props import KERNELS, bad_input_table, valid
from test_never_wrong import EXPONENTS, SCALING, relative_error

from rigidsym import kernels as K

pytestmark = pytest.mark.extra

BACKENDS = ("torch", "jax")
#: the batch size of every call (> 3 x 27 + 1, the labelled rows of the largest kernel)
ROWS = 96
#: the kernels JAX runs in the README's test command (its eager operations compile once per
#: shape: ~1 s a kernel); every kernel in the slow run. PyTorch runs every kernel in both.
QUICK_JAX = ("plucker_from_points", "instant_screw_axis", "screw_of_displacement",
             "natural_invariants_from_rotation", "euler_angle_rates")
#: the kernels JAX runs in every thorough run of the per-kernel families (the cost of the
#: slow run: ~1 s a kernel): QUICK_JAX, wrench_axis (raised NonFiniteResultError with
#: check=True), and a seeded quarter of the others, the same in each family; every kernel
#: in the ``exhaustive`` profile, and the seed rotates per commit. PyTorch runs every kernel.
JAX_SHARED = {*QUICK_JAX, "wrench_axis"}
JAX_SHARED |= set(_profile.share(sorted(n for n in KERNELS if n not in JAX_SHARED), 1 / 4))


def cases(names, quick=QUICK_JAX, shared=None) -> list:
    """``(backend, name)`` parameters: JAX outside ``quick`` marked slow, and run only for
    the kernels of ``shared`` where it is given."""
    return [pytest.param(b, n, marks=[pytest.mark.slow] if b == "jax" and n not in quick
                         else []) for n in sorted(names) for b in BACKENDS
            if b != "jax" or n in quick or shared is None or n in shared]


def backend(b: str):
    """``(module, to_array, to_numpy)`` of back-end ``b``; skip when it is not installed."""
    if b == "torch":
        torch = pytest.importorskip("torch", reason="PyTorch is not installed (the [torch] extra)")
        from rigidsym.kernels import torch as mod
        return mod, lambda a: torch.as_tensor(np.asarray(a)), lambda t: t.detach().numpy()
    jax = pytest.importorskip("jax", reason="JAX is not installed (the [jax] extra)")
    jax.config.update("jax_enable_x64", True)
    import jax.numpy as jnp

    from rigidsym.kernels import jax as mod
    return mod, jnp.asarray, np.asarray


def array_call(mod, name: str):
    """Kernel ``name`` of KERNELS' table in back-end module ``mod`` (keyword inputs)."""
    if name == "euler_rate_matrix":
        return lambda angles, **kw: mod.euler_rate_matrix(angles, "ZYX", "body", **kw)
    if name == "euler_angle_rates":
        return lambda angles, omega, **kw: mod.euler_angle_rates(angles, omega, "XZX", **kw)
    return getattr(mod, name)


def outs(res, to_numpy=np.asarray) -> list[np.ndarray]:
    return [np.asarray(to_numpy(r)) for r in (res if isinstance(res, tuple) else (res,))]


def numpy_and_c(name: str, x: dict, **kw) -> dict:
    """``{backend: outputs}`` of the NumPy and (where built) C kernels."""
    call = KERNELS[name][0]
    res = {}
    for b in ("numpy", "c"):
        if K.use_backend(b) == b:
            try:
                res[b] = outs(call(**x, **kw))
            finally:
                K.use_backend("numpy")
    return res


def assert_agree(got: list, want: list, tol: float, label, atol: float = 0.0) -> None:
    """The same NaN positions; elsewhere within ``tol`` of ``want``, normwise per output
    and sample (relative to the sample's largest finite entry of that output), plus
    ``atol``."""
    for g, w in zip(got, want, strict=True):
        assert g.shape == w.shape, label
        np.testing.assert_array_equal(np.isnan(g), np.isnan(w), err_msg=str(label))
        n = w.shape[0] if w.ndim else 1
        g2, w2 = g.reshape(n, -1), w.reshape(n, -1)
        ok = ~np.isnan(w2)
        np.testing.assert_array_equal(g2[np.isinf(w2)], w2[np.isinf(w2)], err_msg=str(label))
        fin = ok & np.isfinite(w2)
        scale = np.where(fin, np.abs(w2), 0).max(1, keepdims=True)
        with np.errstate(invalid="ignore", over="ignore"):    # inf - inf off the mask
            err = np.where(fin, np.abs(g2 - w2), 0).max(1, keepdims=True)
        assert (err <= tol * scale + atol).all(), (label,
                                                   (err / np.where(scale > 0, scale, 1)).max())


def nan_rows(specs: list, rng) -> tuple[dict, list]:
    """A clean valid sample (row 0), then one row per input component and non-finite value
    (NaN, inf, -inf) holding it: ``(inputs, labels)``."""
    base = {s["name"]: valid(s, (), rng) for s in specs}
    labels = [(s["name"], i, bad) for s in specs
              for i in range(int(np.prod(s["tshape"], dtype=int))) for bad in
              (np.nan, np.inf, -np.inf)]
    # one batch size for every kernel (clean rows after the labelled ones): JAX compiles
    # its eager operations once per shape
    x = {n: np.repeat(np.asarray(v, dtype=float)[None], ROWS, 0) for n, v in base.items()}
    for r, (n, i, bad) in enumerate(labels, 1):
        x[n].reshape(ROWS, -1)[r, i] = bad
    return x, labels


@pytest.mark.parametrize(("b", "name"), cases(KERNELS, shared=JAX_SHARED))
def test_one_nan_policy_arrays(b, name):
    """check=False, a NaN or inf in one input component: NaN in exactly the output
    components where the NumPy and C kernels have it (their rule: those that depend on it),
    the others as there; check=True keeps its ValueError naming the argument. Guards
    against: an inf giving IEEE limits (finite outputs where NumPy and C give NaN, e.g. the Plücker
    array of a point at inf) and the overflow mask turning whole rows NaN."""
    mod, to, back = backend(b)
    call, specs = KERNELS[name]
    x, labels = nan_rows(specs, np.random.default_rng(4))
    kw = {"check": False} if name == "euler_rate_matrix" else {"check": False,
                                                                "on_singular": "nan"}
    ref = numpy_and_c(name, x, **kw)
    got = outs(array_call(mod, name)(**{n: to(v) for n, v in x.items()}, **kw), back)
    for other, want in ref.items():
        assert_agree(got, want, 2.0**-40, (b, other, name))
    for s in specs:                         # check=True: the ValueError stays
        bad = {n: to(v[:1]) for n, v in x.items()}
        row = 1 + next(i for i, lab in enumerate(labels) if lab[0] == s["name"])
        bad[s["name"]] = to(x[s["name"]][row:row + 1])
        with pytest.raises(ValueError, match=f"^{s['name']}: non-finite"):
            array_call(mod, name)(**bad)


def extreme_batch(specs: list, n: int, rng, dtype, k: int) -> dict:
    """``n`` valid samples; in the first 8 the free arguments scaled by 2^k (the first
    argument) and 2^-k (the others): inputs whose squares overflow or underflow."""
    x = {s["name"]: valid(s, (n,), rng) for s in specs}
    for s in specs:   # exponential coordinates w, xi only small (angles of 2^600: no regime)
        if s["kind"] == "any" and s["name"] not in ("angles", "m", "I_C", "T"):
            up = s is specs[0] and s["name"] not in ("w", "xi")
            x[s["name"]][:8] *= np.ldexp(1.0, k if up else -k)
    return {n_: v.astype(dtype) for n_, v in x.items()}


@pytest.mark.parametrize(("b", "name"), cases(KERNELS, shared=JAX_SHARED))
def test_check_false_is_check_true_arrays(b, name):
    """On valid input with rows of extreme magnitude (float64 2^±600, float32 2^±70: their
    squares overflow and underflow): check=False returns what check=True returns, bit for
    bit (on_singular="nan", as test_never_wrong's), and the NumPy kernels' values (their
    long-double rescue, rounded once) to 2^-40 (float64) and 2^-14 (float32: torch and JAX
    compute float32 in float32). Guards against: torch and JAX raised NonFiniteResultError with
    check=True (plucker_from_points, wrench_axis) and returned NaN or finite wrong values
    (e = [0, -0, 0]) with check=False."""
    mod, to, back = backend(b)
    call, specs = KERNELS[name]
    f = array_call(mod, name)
    for dtype, k, tol in ((np.float64, 600, 2.0**-40), (np.float32, 70, 2.0**-14)):
        x = extreme_batch(specs, ROWS, np.random.default_rng(11), dtype, k)
        t = {n: to(v) for n, v in x.items()}
        # on_singular="nan": a free argument that is a transform (T) holds no transform here
        nan = {} if name == "euler_rate_matrix" else {"on_singular": "nan"}
        want = outs(f(**t, **nan), back)
        for g, w in zip(outs(f(**t, check=False, **nan), back), want, strict=True):
            np.testing.assert_array_equal(g, w, err_msg=f"{b} {dtype}")
        assert_agree(want, numpy_and_c(name, x, **nan)["numpy"], tol, (b, name, dtype))


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize(("b", "name"), cases(SCALING, ("plucker_from_points",)))
def test_finite_in_finite_out_arrays(b, name, dtype):
    """The exact scaling laws of test_never_wrong over 1e-300..1e300 (float64; 1e-35..1e35
    float32), every scale in one batch: the scaled result, never an error nor a finite
    wrong value, with check=True and False. Guards against: NonFiniteResultError at |p| = 1e155
    (torch and JAX); with check=False e = [0, -0, 0]."""
    mod, to, back = backend(b)
    make, scale_in, scale_out = SCALING[name]
    f = getattr(mod, name)
    u = np.finfo(dtype).eps / 2
    rng = np.random.default_rng(7)
    x = tuple(np.asarray(a, dtype=dtype) for a in make(rng))
    y = outs(f(*(to(a) for a in x)), back)
    y = np.concatenate([v.ravel() for v in y])
    ks = EXPONENTS[dtype]
    xs = [np.stack([np.asarray(scale_in(x, np.ldexp(dtype(1.0), k))[j], dtype=dtype)
                    for k in ks]) for j in range(len(x))]
    for check in (True, False):
        got = outs(f(*(to(a) for a in xs), check=check), back)
        got = np.concatenate([v.reshape(len(ks), -1) for v in got], axis=1)
        for r, k in enumerate(ks):
            want = scale_out(y, np.ldexp(dtype(1.0), k))
            assert np.isfinite(got[r]).all(), (b, k, check, got[r])
            assert relative_error(got[r], want) <= 16 * u, (b, k, check, got[r], want)


@pytest.mark.parametrize("b", BACKENDS)
def test_plucker_from_points_at_1e155_arrays(b):
    """plucker_from_points at |p| = 1e155, as a user types it."""
    mod, to, back = backend(b)
    p1 = np.array([0.3, -0.7, 1.1]) * 1e155
    want = K.plucker_from_points(p1, 2 * p1 + 1e154)
    for check in (True, False):
        got = back(mod.plucker_from_points(to(p1), to(2 * p1 + 1e154), check=check))
        np.testing.assert_allclose(got, want, rtol=1e-15)


def traced_nan_policy(b: str, name: str, trace) -> None:
    """Kernel ``name`` of back-end ``b`` under ``trace`` (``trace(f) -> traced f``, the
    inputs positional) on :func:`nan_rows`: the NaN positions of the NumPy and C kernels."""
    mod, to, back = backend(b)
    call, specs = KERNELS[name]
    names = [s["name"] for s in specs]
    x, _ = nan_rows(specs, np.random.default_rng(4))
    kw = {"check": False} if name == "euler_rate_matrix" else {"check": False,
                                                                "on_singular": "nan"}
    f = array_call(mod, name)
    traced = trace(lambda *a: f(**dict(zip(names, a, strict=True))))
    got = outs(traced(*[to(x[n]) for n in names]), back)
    for other, want in numpy_and_c(name, x, **kw).items():
        assert_agree(got, want, 2.0**-40, (b, other, name))


@pytest.mark.parametrize("name", [pytest.param(n, marks=[] if n in QUICK_JAX else
                                               [pytest.mark.slow]) for n in sorted(KERNELS)])
def test_traced_jax_nan_policy_and_overflow(name):
    """Under jax.jit (no host reads, so no rescue): the same NaN positions as C and NumPy for
    a NaN/inf input, and a sample whose denominator overflows is NaN, never a finite wrong
    value. Guards against: plucker_from_points at |p| = 1e155 gave e = [0, -0, 0] under jit, and
    an inf input its IEEE limits."""
    mod, to, back = backend("jax")
    import jax

    traced_nan_policy("jax", name, jax.jit)
    if name == "plucker_from_points":
        p1 = np.array([0.3, -0.7, 1.1]) * 1e155
        kappa = back(jax.jit(mod.plucker_from_points)(to(p1), to(2 * p1 + 1e154)))
        assert np.isnan(kappa).all(), kappa


#: the thorough run: a seeded third of the kernels (each commit another third; all in the
#: exhaustive profile), and in every run the two that
#: test_propagates_inf_is_decided_from_the_program names: euler_rodrigues_product (it
#: propagates inf) and instant_screw_axis (it does not: its unit axis at an omega of inf was
#: [0, 0]); the same policy under jax.jit: test_traced_jax_nan_policy_and_overflow
@pytest.mark.slow  # a compile a kernel: 9 s for the first, 3-4 s each after
@pytest.mark.parametrize("name", [
    pytest.param(n, marks=[] if n in ("euler_rodrigues_product", "instant_screw_axis")
                 else [pytest.mark.thorough(0.33)]) for n in sorted(KERNELS)])
def test_compiled_torch_nan_policy(name):
    """Under torch.compile (no host reads, so no rescue; an inf input taken as NaN inside
    the compiled kernel's function, not by a ``where`` on every input): the
    same NaN positions as C and NumPy for a NaN/inf input. Guards that move: a compiled
    call that skipped both mappings gave IEEE limits (the unit axis [0, 0] of an omega at
    inf)."""
    backend("torch")
    import torch

    def compile_with_grad(f):
        torch._dynamo.reset()  # one code object for every kernel: its recompile limit
        g = torch.compile(f, backend="aot_eager", fullgraph=True)
        return lambda *a: g(*[t.requires_grad_(True) for t in a])

    traced_nan_policy("torch", name, compile_with_grad)


def test_torch_rescued_row_derivative():
    """A sample written by the long-double rescue (points at 1e155) has no derivative to
    autograd: NaN in its inputs' gradient where its cotangent is nonzero, zero where it is
    zero (no NaN leaks into a loss that ignores it), and the ordinary sample beside it keeps
    the generated gradient (that of the same sample alone)."""
    torch = pytest.importorskip("torch", reason="PyTorch is not installed (the [torch] extra)")
    from rigidsym.kernels import torch as rt

    f64 = torch.float64
    p1 = torch.tensor([[0.3, -0.7, 1.1], [0.3, -0.7, 1.1]], dtype=f64)
    p1 = (p1 * torch.tensor([[1e155], [1.0]], dtype=f64)).requires_grad_(True)
    p2 = torch.tensor([[1.0, 2.0, 3.0], [1.0, 2.0, 3.5]], dtype=f64, requires_grad=True)
    q1, q2 = p1[1:].detach().clone().requires_grad_(True), p2[1:].detach().clone()
    rt.plucker_from_points(q1, q2.requires_grad_(True)).sum().backward()
    rt.plucker_from_points(p1, p2)[1].sum().backward()
    assert (p1.grad[0] == 0).all() and (p2.grad[0] == 0).all()
    torch.testing.assert_close(p1.grad[1], q1.grad[0], rtol=0, atol=1e-15)
    torch.testing.assert_close(p2.grad[1], q2.grad[0], rtol=0, atol=1e-15)
    p1.grad = p2.grad = None
    rt.plucker_from_points(p1, p2).sum().backward()
    assert p1.grad[0].isnan().all() and p2.grad[0].isnan().all()
    assert p1.grad[1].isfinite().all()


@pytest.mark.parametrize(("b", "name"), cases(KERNELS, shared=JAX_SHARED))
def test_bad_input_table_arrays(b, name):
    """The bad-input table on PyTorch and JAX: test_kernels_props' >= 200 generated corruptions
    per kernel give a finite result or a TypeError/ValueError naming the corrupted argument
    (or a SingularConfigurationError naming one): a batch mismatch names the arguments first,
    never only "batch shapes do not broadcast"."""
    mod, to, back = backend(b)
    res = bad_input_table(name, 200, seed=12, call=array_call(mod, name))
    assert res["escapes"] == [], res["escapes"][:10]


@pytest.mark.parametrize("b", BACKENDS)
def test_bad_input_module_functions(b):
    """load, euler_rate_matrix, euler_angle_rates and the keywords of torch and JAX: a
    wrong type or value names the argument. Guards against: load(3) was "TypeError: expected str,
    bytes or os.PathLike object, not int"."""
    mod, to, back = backend(b)
    a3 = to([0.1, 0.2, 0.3])
    cases = [
        (lambda: mod.load(3), TypeError, "directory"),
        (lambda: mod.load(True), TypeError, "directory"),
        (lambda: mod.euler_rate_matrix(a3, "ZZZ"), ValueError, "sequence"),
        (lambda: mod.euler_rate_matrix(a3, 5), ValueError, "sequence"),
        (lambda: mod.euler_rate_matrix(a3, "ZYX", frame=3), ValueError, "frame"),
        (lambda: mod.euler_rate_matrix(to([0.1, 0.2]), "ZYX"), ValueError, "angles"),
        (lambda: mod.euler_angle_rates(a3, "abc", "ZYX"), TypeError, "omega"),
        (lambda: mod.euler_angle_rates(a3, a3, "ZYX", frame="world"), ValueError, "frame"),
        (lambda: mod.twist_transfer(to(np.zeros(6)), a3, a3, check="yes"), TypeError,
         "check"),
        (lambda: mod.twist_transfer(to(np.zeros(6)), a3, a3, on_singular="ignore"),
         ValueError, "on_singular"),
    ]
    for call, exc, arg in cases:
        with pytest.raises(exc) as info:
            call()
        assert type(info.value) is exc
        assert str(info.value).split(":")[0] == arg, str(info.value)


@pytest.mark.parametrize("b", BACKENDS)
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_subnormal_inputs_arrays(b, dtype):
    """A subnormal input (omega of N_tilde_dot) whose result is normal: NumPy's value (its
    long-double rescue) to 2^-14. Found by the regimes' property with JAX on every kernel:
    XLA on CPU flushes subnormals to zero in comparisons too, so a float range test missed
    them and JAX returned 0 for a result of 9.2e-38 (float32)."""
    mod, to, back = backend(b)
    e = np.array([0.18881711, -0.19839032, 0.9617637])
    e = (e / np.linalg.norm(e)).astype(dtype)
    omega = np.array([-7.6857185, -1.5236010, 9.2155875]) * (1e-39 if dtype == np.float32
                                                             else 1e-309)
    omega, phi = omega.astype(dtype), dtype(-0.1)
    want = K.N_tilde_dot(e, phi, omega)
    got = back(mod.N_tilde_dot(to(e), to(phi), to(omega)))
    assert np.abs(want).max() > np.finfo(dtype).tiny
    assert np.abs(got - want).max() <= 2.0**-14 * np.abs(want).max(), (got, want)


def test_propagates_inf_is_decided_from_the_program():
    """a traced call leaves inf inputs alone only for a program whose every
    operation is non-finite wherever an argument is (then its non-finite outputs become
    NaN); a division (1/inf = 0), a negative power, atan2 or an unknown call refuses it.
    The generated programs: the quaternion product propagates, the screw axis (which
    divides) does not; both checked end to end by test_traced_jax_nan_policy_and_overflow and
    test_compiled_torch_nan_policy."""
    from rigidsym.core.config import generated_dir
    from rigidsym.kernels.arrays.evaluation import propagates_inf

    def prog(body: str) -> str:
        return f"import torch\n\n\ndef _main(a, b):\n    x0 = {body}\n    return (x0,), ()\n"

    assert propagates_inf(prog("torch.sin(a)*b + (a*a)**2 - torch.sqrt(b)"))
    for bad in ("a/b", "1.0/torch.sqrt(a)", "a**(-2)", "a**0.5", "torch.atan2(a, b)",
                "torch.exp(a)", "torch.where(a > 0, a, b)", "abs(a)"):
        assert not propagates_inf(prog(bad)), bad
    gen = generated_dir()
    for backend in ("torch", "jax"):
        # (Rodrigues' formula propagated until its cos phi became a where of two forms,
        # codegen.cos_form: a where is refused, conservatively; the column map stays)
        text = (gen / backend / "euler_rodrigues_product.py").read_text()
        assert propagates_inf(text)
        assert not propagates_inf((gen / backend / "instant_screw_axis.py").read_text())
