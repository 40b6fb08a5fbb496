"""The PyTorch kernels: the NumPy kernels' values, the generated Jacobians as
their derivatives (backward, forward mode, vmap), gradcheck at random points, no NaN
gradient within 1e-6 of the singular sets, the keyword rules of eager and compiled calls,
dtypes, broadcasting, devices, and a user directory."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from rigidsym import kernels as K
from rigidsym.cli import main
from tests._arrays_cases import EULER, euler_probe, sample, singular_probes

#: skipped without its extra in the README's test command; .ci/run installs it
pytestmark = pytest.mark.extra

torch = pytest.importorskip("torch", reason="PyTorch is not installed (the [torch] extra)")
from rigidsym.kernels import torch as rk  # noqa: E402

ALL = list(K.KERNEL_NAMES)
#: the default suite runs a few kernels (one per family); every kernel runs as `slow`
FEW = {"N_matrix", "instant_screw_axis", "natural_invariants_from_rotation"}
NAMES = [n if n in FEW else pytest.param(n, marks=pytest.mark.slow) for n in ALL]
JAC = [n for n in NAMES if (n if isinstance(n, str) else n.values[0]) + "_with_jacobians"
       in K._state.meta()]
PROBED = [n for n in NAMES if singular_probes(n if isinstance(n, str) else n.values[0])
          is not None]


def _t(xs, grad=False):
    return [torch.tensor(x, dtype=torch.float64, requires_grad=grad) for x in xs]


def _tuple(v):
    return v if isinstance(v, tuple) else (v,)


def _close(got, ref, rtol):
    ref = np.asarray(ref)
    scale = max(1.0, float(np.abs(ref).max())) if ref.size else 1.0
    np.testing.assert_allclose(np.asarray(got), ref, rtol=rtol, atol=rtol * scale)


@pytest.mark.parametrize("name", NAMES)
def test_values_match_the_numpy_kernel(name):
    xs = sample(name, 16)
    ref = _tuple(getattr(K, name)(*xs))
    got = _tuple(getattr(rk, name)(*_t(xs)))
    assert len(got) == len(ref)
    for g, r in zip(got, ref, strict=True):
        assert g.dtype == torch.float64 and tuple(g.shape) == r.shape
        _close(g.detach(), r, 1e-13)


@pytest.mark.parametrize("seq,frame", EULER)
def test_euler_kernels_match_numpy(seq, frame):
    rng = np.random.default_rng(1)
    ang, w = rng.uniform(-1, 1, (8, 3)), rng.standard_normal((8, 3))
    _close(rk.euler_rate_matrix(torch.tensor(ang), seq, frame), K.euler_rate_matrix(
        ang, seq, frame), 1e-13)
    _close(rk.euler_angle_rates(torch.tensor(ang), torch.tensor(w), seq, frame),
           K.euler_angle_rates(ang, w, seq, frame), 1e-13)


def _autograd_jacobian(fn, xs, outs_count):
    """d out[k][s, i...] / d xs[j][s, ...] per sample s, by one backward per output entry."""
    ts = _t(xs, grad=True)
    outs = _tuple(fn(*ts))
    jac = []
    for o in outs[:outs_count]:
        flat = o.reshape(o.shape[0], -1)
        rows = []
        for i in range(flat.shape[1]):
            gs = torch.autograd.grad(flat[:, i].sum(), ts, allow_unused=True, retain_graph=True)
            rows.append([torch.zeros_like(t) if g is None else g for g, t in zip(gs, ts,
                                                                                  strict=True)])
        jac.append(rows)
    return jac


@pytest.mark.parametrize("name", JAC)
def test_gradients_are_the_generated_jacobians(name):
    xs = sample(name, 4, seed=2)
    _, ref = K.jacobian(name)(*xs)
    meta = K._state.meta()[name]
    jac = _autograd_jacobian(getattr(rk, name), xs, len(meta["outputs"]))
    for k, o in enumerate(meta["outputs"]):
        for j, a in enumerate(meta["args"]):
            want = ref[o["name"]][a["name"]].reshape(4, -1, *(a["shape"] or [1]))
            got = np.stack([np.asarray(row[j]).reshape(4, *(a["shape"] or [1]))
                            for row in jac[k]], axis=1)
            _close(got, want, 1e-12)


@pytest.mark.parametrize("name", NAMES)
def test_gradcheck_at_random_points(name):
    xs = _t(sample(name, 2, seed=5), grad=True)
    fn = getattr(rk, name)
    assert torch.autograd.gradcheck(lambda *a: fn(*a, check=False), xs)


@pytest.mark.parametrize("name", ["instant_screw_axis", "N_matrix", "inertia_dyad_at_point"])
def test_forward_mode_and_vmap_use_the_same_jacobian(name):
    xs = sample(name, 1, seed=4)
    fn = getattr(rk, name)
    one = [torch.tensor(x[0]) for x in xs]

    def first(*a):
        return _tuple(fn(*a))[0]
    fwd = torch.func.jacfwd(first)(*one)
    rev = torch.func.jacrev(first)(*one)
    torch.testing.assert_close(fwd, rev, rtol=1e-12, atol=1e-12)
    batched = torch.func.vmap(first)(*[torch.tensor(x) for x in xs])
    torch.testing.assert_close(batched[0], first(*one), rtol=1e-15, atol=0)


@pytest.mark.parametrize("name", ["rotation_vector_left_jacobian_inverse",
                                  "rotation_vector_from_rotation"])
def test_forward_mode_on_dual_tensors_is_reverse_mode(name):
    """forward-mode AD on dual tensors (torch.autograd.forward_ad, outside
    torch.func) through a kernel whose eager autograd class saves the forward's temps for
    its backward (no jvp of its own: the call takes the class with the generated jvp) and
    through one without saved temps: the tangents are the reverse-mode Jacobian (one
    backward per output entry) contracted with the input tangents."""
    xs = sample(name, 2, seed=7)
    fn = getattr(rk, name)
    rng = np.random.default_rng(8)
    ts = [torch.tensor(rng.standard_normal(x.shape)) for x in xs]
    with torch.autograd.forward_ad.dual_level():
        outs = _tuple(fn(*[torch.autograd.forward_ad.make_dual(torch.tensor(x), t)
                           for x, t in zip(xs, ts, strict=True)]))
        fwd = [torch.autograd.forward_ad.unpack_dual(o).tangent for o in outs]
    jac = _autograd_jacobian(fn, xs, len(outs))
    for k, o in enumerate(outs):
        flat = o.reshape(2, -1)
        want = torch.stack([sum((row[j] * ts[j]).reshape(2, -1).sum(1)
                                for j in range(len(xs))) for row in jac[k]], dim=1)
        assert fwd[k] is not None and tuple(fwd[k].shape) == tuple(o.shape), (name, k)
        torch.testing.assert_close(fwd[k].reshape(flat.shape), want, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("name", PROBED)
def test_no_nan_gradient_near_the_singular_sets(name):
    xs = _t(singular_probes(name), grad=True)
    outs = _tuple(getattr(rk, name)(*xs))
    sum(o.sum() for o in outs).backward()
    for x in xs:
        assert torch.isfinite(x.grad).all(), name


@pytest.mark.parametrize("seq", ["ZYX", "ZXZ"])
def test_euler_rates_gradients_finite_near_gimbal_lock(seq):
    ang = torch.tensor(euler_probe(seq), requires_grad=True)
    w = torch.tensor([[0.1, 0.2, 0.3]] * 2, requires_grad=True)
    rk.euler_angle_rates(ang, w, seq).sum().backward()
    assert torch.isfinite(ang.grad).all() and torch.isfinite(w.grad).all()
    ang2 = torch.tensor(np.random.default_rng(0).uniform(-1, 1, (2, 3)), requires_grad=True)
    assert torch.autograd.gradcheck(lambda a: rk.euler_angle_rates(a, w.detach(), seq,
                                                                   check=False), (ang2,))


def test_branch_kernel_masked_branches_leak_no_nan():
    # near pi the main branch divides by |vect Q| ~ 0: its gradient must not leak
    Q = torch.tensor(singular_probes("natural_invariants_from_rotation")[0], requires_grad=True)
    e, phi = rk.natural_invariants_from_rotation(Q)
    (e.sum() + phi.sum()).backward()
    assert torch.isfinite(Q.grad).all()
    _close(e.detach(), K.natural_invariants_from_rotation(Q.detach().numpy())[0], 1e-12)


def test_singular_samples_raise_in_eager_and_are_nan_on_request():
    omega = torch.tensor([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0]], dtype=torch.float64,
                         requires_grad=True)
    a = torch.zeros(2, 3, dtype=torch.float64)
    with pytest.raises(K.SingularConfigurationError, match=r"\(1,\)") as info:
        rk.instant_screw_axis(omega, a, a)
    assert info.value.argument == "a_dot"     # omega = 0 and a_dot = 0: no motion
    p0, pitch, _ = rk.instant_screw_axis(omega, a, a, on_singular="nan")
    assert torch.isnan(pitch[1]) and torch.isfinite(pitch[0])
    pitch[0].backward()   # the NaN row contributes a zero gradient, not NaN
    assert torch.isfinite(omega.grad).all()


def test_keyword_rules_under_compile():
    xs = [torch.tensor(x) for x in sample("twist_transfer", 4)]
    f = torch.compile(lambda *a: rk.twist_transfer(*a), backend="aot_eager", fullgraph=True)
    _close(f(*xs), K.twist_transfer(*[x.numpy() for x in xs]), 1e-13)
    bad = torch.compile(lambda *a: rk.twist_transfer(*a, check=True), backend="aot_eager")
    with pytest.raises(Exception, match="check=True needs eager mode"):
        bad(*xs)
    with pytest.raises(ValueError, match="on_singular='raise' needs eager mode"):
        torch.func.vmap(lambda w: rk.N_matrix(w, xs[0][0, 0], on_singular="raise"))(xs[1])
    for kw in ("out", "threads"):
        with pytest.raises(TypeError):
            rk.twist_transfer(*xs, **{kw: None})


def test_a_refused_compile_leaves_no_trace():
    """A refused compile (check=True; on_singular='raise' under fullgraph), then a fullgraph
    compile of the same kernel, without torch._dynamo.reset(): the refusal used to raise
    inside Dynamo's trace, which marked the kernel's code objects to be skipped, and the
    fullgraph compile then failed ("Attempt to trace generator")."""
    xs = [torch.tensor(x) for x in sample("wrench_transfer", 4, seed=3)]
    loose = torch.compile(lambda *a: rk.wrench_transfer(*a, check=True), backend="aot_eager")
    with pytest.raises(ValueError, match="check=True needs eager mode"):
        loose(*xs)
    strict = torch.compile(lambda *a: rk.wrench_transfer(*a, on_singular="raise"),
                           backend="aot_eager", fullgraph=True)
    with pytest.raises(Exception, match="need.{0,3}eager.mode"):  # the reason, or its name
        strict(*xs)
    f = torch.compile(rk.wrench_transfer, backend="aot_eager", fullgraph=True)
    _close(f(*xs), K.wrench_transfer(*[x.numpy() for x in xs]), 1e-13)


def test_validation_names_the_argument():
    e = torch.tensor([1.0, 1.0, 0.0], dtype=torch.float64)
    with pytest.raises(ValueError, match="e: not a unit vector"):
        rk.N_matrix(e, 0.5)
    with pytest.raises(ValueError, match=r"omega: expected shape \(\.\.\., 3\)"):
        rk.instant_screw_axis(torch.zeros(2), torch.zeros(3), torch.zeros(3))
    with pytest.raises(TypeError, match="a: expected real numbers"):
        rk.twist_transfer(torch.zeros(6), torch.zeros(3, dtype=torch.bool), torch.zeros(3))
    with pytest.raises(ValueError, match="non-finite"):
        rk.twist_transfer(torch.full((6,), float("nan")), torch.zeros(3), torch.zeros(3))
    with pytest.raises(ValueError, match="do not broadcast"):
        rk.twist_transfer(torch.zeros(2, 6), torch.zeros(3, 3), torch.zeros(3))


def test_float32_broadcasting_and_double_backward():
    rng = np.random.default_rng(0)
    t = torch.tensor(rng.standard_normal((2, 1, 6)), dtype=torch.float32)
    a = torch.tensor(rng.standard_normal((5, 3)), dtype=torch.float32)
    p = torch.zeros(3, dtype=torch.float32)
    out = rk.twist_transfer(t, a, p)
    assert out.dtype == torch.float32 and tuple(out.shape) == (2, 5, 6)
    ref = K.twist_transfer(t.double().numpy(), a.double().numpy(), p.double().numpy())
    np.testing.assert_allclose(out.numpy(), ref, rtol=1e-5, atol=1e-5)
    # double backward (never refused: create_graph=True): T = x.x/2 + m x.x/2
    # with I = 1 and m = 2 has the Hessian 3 * 1 at every x
    x = torch.tensor(rng.standard_normal(3), requires_grad=True)
    T = rk.kinetic_energy(torch.eye(3, dtype=torch.float64), 2.0, x, x)
    (g,) = torch.autograd.grad(T, x, create_graph=True)
    H = torch.stack([torch.autograd.grad(g[i], x, retain_graph=True)[0] for i in range(3)])
    torch.testing.assert_close(H, 3 * torch.eye(3, dtype=torch.float64), rtol=0, atol=1e-15)


def test_rigidsym_kernels_does_not_import_torch_and_missing_torch_names_the_extra():
    code = ("import sys, rigidsym.kernels; assert 'torch' not in sys.modules\n"
            "sys.modules['torch'] = None\n"
            "try:\n    import rigidsym.kernels.torch\nexcept ImportError as e:\n"
            "    print(e)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, timeout=60).stdout
    assert "pip install 'rigidsym[torch]'" in out


def test_user_directory(tmp_path):
    mod = tmp_path / "kern.py"
    mod.write_text(
        "from rigidsym.codegen.spec import Arg, Kernel, Out\n"
        "def scaled(x, v):\n    return x * v\n"
        "KERNELS = [Kernel('scaled_vector', 'x v.', 'x v', ('kern:s',), (scaled,),\n"
        "    (Arg('x', ()), Arg('v', (3,))), (Out('y', (3,)),),\n"
        "    lambda x, v: {'y': scaled(x, v)})]\n")
    gen = tmp_path / "gen"
    assert main(["generate", "--module", str(mod), "--out", str(gen)]) == 0
    ns = rk.load(gen)
    assert ns.KERNEL_NAMES == ("scaled_vector",)
    x = torch.tensor(2.0, dtype=torch.float64, requires_grad=True)
    y = ns.scaled_vector(x, torch.tensor([1.0, 2.0, 3.0], dtype=torch.float64))
    y.sum().backward()
    assert y.tolist() == [2.0, 4.0, 6.0] and x.grad.item() == 6.0


def _compiled_matches(name, backend, dynamic=None):
    """Values and gradients of the fullgraph-compiled kernel, inputs requiring grad (old
    main: "Unsupported custom jvp", the jvp of the autograd.Function), against the NumPy
    kernel and eager autograd."""
    # no torch._dynamo.reset(): an earlier refused compile of the same kernel must not spoil
    # this one (test_a_refused_compile_leaves_no_trace)
    xs = [torch.tensor(x, requires_grad=True) for x in sample(name, 4, seed=9)]
    f = torch.compile(getattr(rk, name), backend=backend, fullgraph=True, dynamic=dynamic)
    got = _tuple(f(*xs))
    for g, r in zip(got, _tuple(getattr(K, name)(*[x.detach().numpy() for x in xs])),
                    strict=True):
        _close(g.detach(), r, 1e-12)
    want = torch.autograd.grad(sum(o.sum() for o in _tuple(getattr(rk, name)(*xs))), xs)
    for g, w in zip(torch.autograd.grad(sum(o.sum() for o in got), xs), want, strict=True):
        _close(g, w, 1e-12)


def test_compiled_with_grad():
    """One small kernel in the default suite (4 s); every kernel runs as `slow`."""
    _compiled_matches("twist_transfer", "aot_eager")


@pytest.mark.slow
def test_compiled_dynamic_shapes_with_grad():
    _compiled_matches("instant_screw_axis", "aot_eager", dynamic=True)


#: the thorough run: a seeded third of the kernels (each commit another third; all in the
#: exhaustive profile), each a compile; every run compiles twist_transfer
#: (test_compiled_with_grad), instant_screw_axis with dynamic shapes, the benchmark kernels
#: K1-K6 under inductor (test_inductor_with_grad), and another seeded share of the kernels
#: under torch.compile (test_compiled_torch_nan_policy, tests/test_never_wrong_arrays.py)
@pytest.mark.slow
@pytest.mark.thorough(0.33)
@pytest.mark.parametrize("name", ALL)
def test_every_kernel_under_aot_eager(name):
    _compiled_matches(name, "aot_eager")


#: the benchmark kernels K1-K6 (benchmarks/RESULTS.md); K4 is instant_screw_point_pitch, the
#: internal part of the public instant_screw_axis, compiled here
K1_K6 = ["rotation_from_euler_rodrigues", "rotation_from_natural_invariants", "screw_axis_point",
         "instant_screw_axis", "N_matrix", "newton_euler_wrench"]


@pytest.mark.parametrize("name", K1_K6)
def test_inductor(name):
    """Inductor's forward only in the default suite (its backward compile costs 10-40 s a
    kernel on 2 cores: test_inductor_with_grad, `slow`)."""
    xs = [torch.tensor(x) for x in sample(name, 4, seed=9)]
    f = torch.compile(getattr(rk, name), backend="inductor", fullgraph=True)
    for g, r in zip(_tuple(f(*xs)), _tuple(getattr(K, name)(*[x.numpy() for x in xs])),
                    strict=True):
        _close(g, r, 1e-12)


@pytest.mark.slow
@pytest.mark.parametrize("name", K1_K6)
def test_inductor_with_grad(name):
    _compiled_matches(name, "inductor")


@pytest.mark.slow
@pytest.mark.parametrize("backend", ["aot_eager", "inductor"])
def test_compiled_float16_flags_a_result_that_overflows_float16(backend):
    """float16 is computed in float32 and rounded once: a result beyond float16's range
    (pitch 1e5) is NaN in its row under torch.compile as in eager mode, not inf (the
    compiled Function's own overflow flag is float32's; the rounding's is Space.call's,
    decided before the rounding: main's inductor returned inf, its check after the
    rounding computed in float32)."""
    h = torch.float16
    omega = torch.tensor([[1e-3, 0.0, 0.0], [0.3, -0.2, 1.0]], dtype=h)
    a = torch.zeros(2, 3, dtype=h)
    a_dot = torch.tensor([[100.0, 0.0, 0.0], [0.5, 0.1, -0.4]], dtype=h)
    f = torch.compile(rk.instant_screw_axis, backend=backend, fullgraph=True)
    got, want = f(omega, a, a_dot), rk.instant_screw_axis(omega, a, a_dot, on_singular="nan")
    for g, w in zip(got, want, strict=True):
        assert torch.isnan(g[0]).all() and torch.isnan(w[0]).all()
        assert torch.equal(g[1], w[1])


@pytest.mark.slow
def test_compiled_torch_func_grad():
    """``torch.compile(torch.func.grad(...))`` of a kernel equals the eager transform. Old
    main: Dynamo's trace of the Function under the transform failed ("Cannot access data
    pointer of Tensor that doesn't have storage"); now the Function is one call in its
    graph (``allow_in_graph``)."""
    rng = np.random.default_rng(0)
    xs = _t([rng.standard_normal((5, 3)) for _ in range(3)])
    g = torch.func.grad(lambda o, a, ad: rk.instant_screw_axis(o, a, ad, check=False)[1].sum())
    _close(torch.compile(g, backend="aot_eager", fullgraph=True)(*xs), g(*xs).numpy(), 1e-12)


@pytest.mark.slow
def test_inductor_flags_an_overflowed_result():
    """A result that does not fit the dtype from finite inputs is NaN in its whole row under
    inductor as in eager mode (the kernels' rule). Guards against returning the pitch inf
    there and the row's other outputs as numbers: inductor folds an integer ``x * 0`` to zeros,
    which removed the check (``_arrays_eval.nonfinite_rows``)."""
    omega = torch.tensor([[1e-10, 0.0, 0.0], [0.3, -0.2, 1.0]], dtype=torch.float64)
    a = torch.zeros(2, 3, dtype=torch.float64)
    a_dot = torch.tensor([[1e300, 0.0, 0.0], [0.5, 0.1, -0.4]], dtype=torch.float64)
    f = torch.compile(rk.instant_screw_axis, backend="inductor", fullgraph=True)
    got, want = f(omega, a, a_dot), rk.instant_screw_axis(omega, a, a_dot, on_singular="nan")
    for g, w in zip(got, want, strict=True):
        assert torch.isnan(g[0]).all() and torch.isnan(w[0]).all()
        _close(g[1], w[1], 1e-12)


def test_inside_a_module_with_its_own_parameters():
    class Screw(torch.nn.Module):
        def __init__(self):
            super().__init__()
            self.omega = torch.nn.Parameter(torch.tensor([0.3, -0.2, 1.0],
                                                         dtype=torch.float64))

        def forward(self, a, a_dot):
            return rk.instant_screw_axis(self.omega, a, a_dot)[1]

    m = Screw()
    a = torch.tensor(sample("instant_screw_axis", 5)[1])
    m(a, a).pow(2).sum().backward()
    assert m.omega.grad.shape == (3,) and torch.isfinite(m.omega.grad).all()


def test_backward_reuses_the_forward_temps():
    """the eager backward takes the temps of the forward that the
    generated VJP reads (saved by autograd) instead of computing them again. Guards
    against the backward of Rodrigues' formula computing the sine of phi / 2 again (one
    aten::sin, two aten::cos; the forward names its cosine too). The
    gradient is that of the recomputing path (``create_graph=True``) bit for bit, and a
    singular sample in the batch still takes the recomputing path (zero gradient there)."""
    from torch.profiler import ProfilerActivity, profile

    rng = np.random.default_rng(3)
    e = rng.standard_normal((64, 3))
    e /= np.linalg.norm(e, axis=1, keepdims=True)
    e, phi = _t([e, rng.uniform(0.3, 2.8, 64)], grad=True)
    R = rk.rotation_from_natural_invariants(e, phi, check=False)
    w = torch.tensor(rng.standard_normal((64, 3, 3)))
    with profile(activities=[ProfilerActivity.CPU]) as prof:
        ge, gp = torch.autograd.grad((R * w).sum(), (e, phi))
    ops = {k.key: k.count for k in prof.key_averages()}
    assert ops.get("aten::sin", 0) == 0 and ops.get("aten::cos", 0) == 0, ops
    R = rk.rotation_from_natural_invariants(e, phi, check=False)
    re, rp = torch.autograd.grad((R * w).sum(), (e, phi), create_graph=True)
    assert torch.equal(ge, re.detach()) and torch.equal(gp, rp.detach())
    omega, a, a_dot = _t([rng.standard_normal((4, 3)) for _ in range(3)], grad=True)
    with torch.no_grad():
        omega[2] = 0.0  # singular: the pitch is NaN there
    p0, pitch, kappa = rk.instant_screw_axis(omega, a, a_dot, check=False, on_singular="nan")
    pitch[[0, 1, 3]].sum().backward()
    assert (omega.grad[2] == 0).all() and omega.grad.isfinite().all()


@pytest.mark.parametrize("dtype", [torch.float64, torch.float32])
def test_the_cpu_route_is_the_torch_program_bit_for_bit(dtype):
    """eager value + gradient on CPU tensors runs the generated forward
    and VJP on NumPy views (``kernels._torch_host``, a fixed cost per operation ~2.5x
    lower at N = 1e3). Its values, singular masks, saved temps and input cotangents are
    those of the PyTorch programs bit for bit, on every kernel that has the programs,
    a masked sample in the batch included (its NaN where PyTorch has one)."""
    from rigidsym.kernels.arrays import torch_host as _torch_host

    space = rk._space()
    rng = np.random.default_rng(11)
    names = [n for n in ALL if space.progs.vjp(n, "saved") is not None]
    assert len(names) > 30

    def same(a, b):
        torch.testing.assert_close(a, b, rtol=0, atol=0, equal_nan=True)

    for name in names:
        meta = space.progs.meta[name]
        xs = [torch.tensor(x, dtype=dtype) for x in sample(name, 7)]
        xs = [x.reshape(7, *a["shape"]) for x, a in zip(xs, meta["args"], strict=True)]
        xs[0][3] = 0.0  # singular for many: NaN and inf where the programs divide
        outs, sing, temps, regular = _torch_host.forward(space.progs, name, xs)
        routs, rsing, rtemps = space.values_saved(name, xs)
        same(sing, rsing)
        assert regular == (not bool(rsing.any()))
        for a, b in zip([*outs, *temps], [*routs, *rtemps], strict=True):
            same(a if isinstance(a, torch.Tensor) else torch.from_numpy(a), b)
        grads = [torch.tensor(rng.standard_normal(tuple(o.shape)), dtype=dtype)
                 for o in outs]
        got = _torch_host.vjp(space.progs, name, xs, temps, grads)
        want = space.vjp_saved(name, xs, rtemps, grads)
        for a, b in zip(got, want, strict=True):
            assert a.dtype == dtype and a.shape == b.shape, name
            same(a, b)


def test_backward_takes_the_compensated_sums_from_the_forward():
    """the backward (``_vjp_saved``, eager and compiled) computes no
    compensated sum of products (``_sumprod``, ``_diffprod``: ~65 operations for the pitch
    of instant_screw_axis, which the VJP does not compute again, its first torch.compile
    1.6-2x the hand's); the forward names each one and saves it. Counted by wrapping the
    helpers the generated PyTorch programs call, on every kernel that calls one."""
    space = rk._space()
    names = []
    for name in ALL:
        progs = space.progs.vjp(name, "saved")
        if progs is None or not {"_sumprod", "_diffprod"} & progs[0].__globals__.keys():
            continue
        names.append(name)
        scope, calls = progs[0].__globals__, []
        real = {h: scope[h] for h in ("_sumprod", "_diffprod")}
        meta = space.progs.meta[name]
        xs = [torch.tensor(x).reshape(5, *a["shape"])
              for x, a in zip(sample(name, 5), meta["args"], strict=True)]
        try:
            for h, f in real.items():
                scope[h] = lambda *a, f=f, h=h, calls=calls: calls.append(h) or f(*a)
            outs, _, temps = space.values_saved(name, xs)
            forward, calls[:] = len(calls), []
            grads = [torch.ones_like(o) for o in outs]
            space.vjp_saved(name, xs, temps, grads)
        finally:
            scope.update(real)
        assert forward > 0 and calls == [], (name, forward, calls)
    assert {"instant_screw_axis", "plucker_from_points", "wrench_axis"} <= set(names)


@pytest.mark.slow
def test_compiled_masked_row_has_zero_gradient():
    """under torch.compile the backward takes the temps its forward saved
    (``_torch_compiled.compiled_saving``) and sets the input cotangents of a masked sample
    to zero after the VJP (NaN there, 0 * inf), so its gradient is exactly 0 and a
    parameter the batch shares stays finite, equal to eager autograd's."""
    rng = np.random.default_rng(5)
    base, a, a_dot = _t([rng.standard_normal((4, 3)) for _ in range(3)])
    base[2] = 0.0  # no motion (omega = 0, a_dot = 0): every output NaN there
    a_dot[2] = 0.0  # (omega = 0 alone is a pure translation, a screw at infinity)

    def grads(fn):
        s = torch.tensor(1.5, dtype=torch.float64, requires_grad=True)
        omega = base * s
        omega.retain_grad()
        p0, pitch, kappa = fn(omega, a, a_dot)
        assert torch.isnan(pitch[2]) and torch.isnan(p0[2]).all()
        (pitch[[0, 1, 3]].sum() + p0[[0, 1, 3]].sum() + kappa[[0, 1, 3]].sum()).backward()
        return s.grad, omega.grad

    f = torch.compile(rk.instant_screw_axis, backend="aot_eager", fullgraph=True)
    (gs, go), (ws, wo) = grads(f), grads(lambda *xs: rk.instant_screw_axis(
        *xs, check=False, on_singular="nan"))
    assert torch.isfinite(gs) and (go[2] == 0).all() and go.isfinite().all()
    _close(gs, ws, 1e-12)
    _close(go, wo, 1e-12)
