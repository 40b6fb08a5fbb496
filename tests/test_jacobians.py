"""Generated Jacobians against the symbolic derivative of the declarations, in mpmath.

Each ``<kernel>_with_jacobians`` is evaluated at float64 inputs by the generated code (NumPy
and C) and by sympy's derivative of the declared formula (``with_jacobians(k).build``,
before the half-angle rewrite, CSE and printing) in mpmath at 50 digits. Per-sample error =
max|got - ref| / max|ref| over all outputs (values and derivatives), as in test_kernels.py;
required <= 1e-13 at 200 random points per kernel (default run).

For constrained inputs (unit ``e``/``eta``, rotation ``Q``) the ambient Jacobian contracted
with a tangent direction is compared with a central difference of the declared value along a
curve on the constraint manifold, in mpmath (h = 1e-20 at 50 digits: truncation 1e-40);
this checks the derivative independently of sympy's ``diff``.

Near the singular sets (the adversarial rows of test_kernels.inputs: phi in {1e-12, 1e-8,
1e-4, pi - 1e-8}, ||omega|| in {1e-12, 1e-6}, Euler angles within 1e-9 of gimbal lock; under
``@pytest.mark.slow``, with 2000 random points), measured on the development machine: at most
1.6e-15 near the singular sets (1.8e-15 if each value / derivative array is normalised by
its own max-norm; the derivatives grow like 1/phi^k there and the half-angle rewrite keeps
them accurate), at most 1.3e-14 at 1000 random points (L_tilde_dot); the limit asserted is
TOL = 1e-13 everywhere.
"""

from __future__ import annotations

import pickle
import shutil
from functools import cache

import _profile
import mpmath
import numpy as np
import pytest
import sympy as sp
from rigidsym.derivations.kernels_spec import KERNELS
from test_kernels import inputs, rel_err

from rigidsym import kernels as K
from rigidsym.codegen.derivatives.jacobians import (
    derivative_name,
    has_jacobian,
    jacobian_name,
    with_jacobians,
)
from rigidsym.codegen.generator import _flatten
from rigidsym.codegen.spec import flat_symbols, input_symbols
from rigidsym.core import kinds as _kinds
from rigidsym.kernels.runtime import state as _state

TOL = 1e-13
N_RANDOM = 200
BASES = {k.name: k for k in KERNELS
         if has_jacobian(k) and jacobian_name(k.name) in _state.meta()}
PUBLIC = sorted(n for n, k in BASES.items() if k.public)
EULER_ALL = sorted(n for n, k in BASES.items() if not k.public)
EULER_DEFAULT = ["euler_rate_matrix_zyx_fixed", "euler_rate_matrix_zxz_body"]
#: differentiated over the program (Kernel.jacobian_from): their declared derivatives, the
#: references here, are trees of 10^5..10^6 nodes (lambdify alone takes ~20 s per branch of
#: the SE(3) log): slow, and not at 2000 points (200 take 216 s)
BIG = [n for n in PUBLIC if BASES[n].jacobian_from == "program"]
SMALL = [n for n in PUBLIC if n not in BIG]
#: the kernels the slow families check in every run: a Lie log (a branched kernel, each
#: branch's own derivative), a Jacobian differentiated over the program (BIG), the worst
#: at random points (L_tilde_dot, 1.3e-14) and the default Euler-angle kernels
ALWAYS = {"rotation_vector_from_rotation", "exponential_coordinates_left_jacobian_inverse",
          "L_tilde_dot", *EULER_DEFAULT}
#: the thorough run's seeded third of the kernels, by name and the same in the three slow
#: families (a kernel's reference, the cost, is built once per process and serves both
#: back-ends and every family), ALWAYS among them; every kernel in the ``exhaustive``
#: profile, and the seed rotates per commit
SHARED = ALWAYS | set(_profile.share(sorted(BASES), 1 / 3))
#: the SE(3) log's reference (lambdify of its declared derivative) takes ~25 s: its tests
#: run on one worker (--dist loadgroup), which builds it once
ONE_WORKER = {"exponential_coordinates_from_transform": "jacobian_se3_log"}


def _group(name: str) -> list:
    return [pytest.mark.xdist_group(ONE_WORKER[name])] if name in ONE_WORKER else []


def _slow(names) -> list:
    """A slow family's parameters: the SHARED kernels, each ONE_WORKER kernel in its group."""
    return [pytest.param(n, marks=_group(n)) for n in names if n in SHARED]


SLOW_BIG = [pytest.param(n, marks=[pytest.mark.slow, *_group(n)]) for n in BIG if n in SHARED]
REQUIRED = ["rotation_from_natural_invariants", "rotation_from_euler_rodrigues",
            "screw_axis_point", "plucker_from_points", "plucker_transfer", "twist_transfer",
            "wrench_transfer", "point_acceleration", "inertia_at_point", "newton_euler_wrench",
            "kinetic_energy"]


def test_the_required_kernels_have_jacobians():
    for name in REQUIRED:
        assert name in PUBLIC and callable(K.jacobian(name)), name
    assert callable(K.jacobian("euler_rate_matrix"))
    for k in KERNELS:
        # per-sample branches: no single ambient derivative, unless each branch is
        # differentiated with its value (branch_jacobian: the Lie logs)
        if k.branches:
            assert (jacobian_name(k.name) in _state.meta()) == k.branch_jacobian, k.name
    assert not any(n.endswith("_with_jacobians") for n in K.KERNEL_NAMES)


@cache
def _jac_kernel(name: str):
    return with_jacobians(BASES[name])


@cache
def reference(name: str):
    """``[(condition or None, mpmath function)]`` of the values and sympy derivatives of the
    declaration, per variant (branches first, as the kernel tries them; a branched kernel's
    Jacobian is each branch's own derivative: ``branch_jacobian``)."""
    jk = _jac_kernel(name)
    syms = input_symbols(jk)
    flat = [s for _, ss in flat_symbols(jk) for s in ss]
    out = [(sp.lambdify(flat, br.when(**syms), modules="math"),
            sp.lambdify(flat, _flatten(jk, br.build(**syms)), modules="mpmath", cse=True))
           for br in jk.branches]
    return out + [(None, sp.lambdify(flat, _flatten(jk, jk.build(**syms)), modules="mpmath",
                                     cse=True))]


def _variant(fs, row):
    return next(f for cond, f in fs if cond is None or bool(cond(*map(float, row))))


@cache
def value_function(name: str):
    """``[(condition or None, mpmath function)]`` of the declared values only (for the
    central differences), per variant as :func:`reference`."""
    k = BASES[name]
    syms = input_symbols(k)
    flat = [s for _, ss in flat_symbols(k) for s in ss]
    return [(sp.lambdify(flat, br.when(**syms), modules="math"),
             sp.lambdify(flat, _flatten(k, br.build(**syms)), modules="mpmath", cse=True))
            for br in k.branches] + \
        [(None, sp.lambdify(flat, _flatten(k, k.build(**syms)), modules="mpmath", cse=True))]


def ref_eval(name: str, arrays) -> np.ndarray:
    fs = reference(name)
    n = arrays[0].shape[0]
    cols = np.concatenate([a.reshape(n, -1) for a in arrays], axis=1)
    with mpmath.workdps(50):
        res = [[float(v) for v in _variant(fs, row)(*[mpmath.mpf(float(x)) for x in row])]
               for row in cols]
    return np.array(res, dtype=float).reshape(n, -1)


def run(name: str, arrays, backend: str):
    jk = _jac_kernel(name)
    n = arrays[0].shape[0]
    outs = [np.empty((n,) + o.shape) for o in jk.outputs]
    with np.errstate(all="ignore"):
        K.batch_function(jk.name, backend)(*arrays, *outs)
    return np.concatenate([o.reshape(n, -1) for o in outs], axis=1)


@cache
def case(name: str, n: int, seed: int, adversarial: bool):
    arrays = inputs(BASES[name], n, seed)
    keep = slice(n, None) if adversarial else slice(0, n)
    arrays = [np.ascontiguousarray(a[keep]) for a in arrays]
    return arrays, ref_eval(name, arrays)


def _need_c():
    if K.use_backend("c") != "c":
        if shutil.which("gcc") or shutil.which("cc"):
            pytest.fail("a C compiler is present but the C backend did not build")
        pytest.skip("no C compiler")


@pytest.fixture(scope="module", params=["numpy", "c"])
def backend(request):
    if request.param == "c":
        _need_c()
    return request.param


def _check(name, backend, n, seed, adversarial=False, tol=TOL):
    arrays, ref = case(name, n, seed, adversarial)
    got = run(name, arrays, backend)
    ok = np.isfinite(ref).all(axis=1)
    assert ok.all(), f"{name}: reference not finite at rows {np.flatnonzero(~ok)}"
    err = rel_err(got, ref)
    worst = int(np.argmax(err))
    assert err.max() <= tol, f"{name} [{backend}]: max rel. error {err.max():.3g} at row " \
                             f"{worst} ({[a[worst].tolist() for a in arrays]})"
    return err.max()


@pytest.mark.sample
@pytest.mark.parametrize("name", [
    n if n in ALWAYS else pytest.param(n, marks=pytest.mark.thorough(1 / 3))
    for n in SMALL + EULER_DEFAULT] + SLOW_BIG)
def test_jacobian_matches_symbolic_derivative(name, backend):
    """The quick run's sample; the thorough run: ALWAYS, a seeded third of the rest of the
    sample's family, and the SHARED BIG kernels."""
    _check(name, backend, N_RANDOM, 10)


@pytest.mark.slow
@pytest.mark.parametrize("name", _slow(SMALL + EULER_ALL))
def test_jacobian_matches_symbolic_derivative_many(name, backend):
    _check(name, backend, 2000, 11)


@pytest.mark.slow
@pytest.mark.parametrize("name", _slow(PUBLIC + EULER_ALL))
def test_jacobian_near_singular_sets(name, backend):
    _check(name, backend, 0, 12, adversarial=True)


@pytest.mark.parametrize("name", PUBLIC + EULER_DEFAULT)
def test_c_and_numpy_agree(name):
    _need_c()
    arrays = inputs(BASES[name], 300, seed=13)
    assert rel_err(run(name, arrays, "numpy"), run(name, arrays, "c")).max() <= 1e-14


# ------------------------------------------------------------------------------------------
# tangent directions of constrained inputs: central differences along the manifold


def _mp(x):
    return mpmath.matrix([[mpmath.mpf(float(v)) for v in row] for row in np.atleast_2d(x)])


def _curve(kind: str, x: np.ndarray, rng):
    """A curve c(t) on the constraint set through c(0) = x (exact), and c'(0), in mpmath:
    the tangent space and curve of the kind's row in the kind table (rigidsym.core.kinds)."""
    k = _kinds.for_spec(kind, x.shape)
    X = [mpmath.mpf(float(v)) for v in x.reshape(-1)]
    D = k.project(X, [mpmath.mpf(float(v)) for v in rng.standard_normal(x.size)])
    c = k.curve(X, D)
    return (lambda t: mpmath.matrix(c(t))), D  # a column of the entries, row-major


CONSTRAINED = sorted((n, a.name, a.kind) for n, k in BASES.items() if n in PUBLIC
                     for a in k.args
                     if (kd := _kinds.for_spec(a.kind, a.shape)) and kd.curve is not None)
CONSTRAINED = [c if c[0] not in BIG else pytest.param(*c, marks=pytest.mark.slow)
               for c in CONSTRAINED]


@pytest.mark.sample
@pytest.mark.parametrize(("name", "arg", "kind"), CONSTRAINED)
def test_tangent_derivative_against_manifold_difference(name, arg, kind):
    k = BASES[name]
    fs = value_function(name)
    rng = np.random.default_rng(14)
    n = 12
    arrays = [a[:n] for a in inputs(k, n, seed=15)]
    names = [a.name for a in k.args]
    i = names.index(arg)
    values, jac = K.jacobian(name)(*arrays, check=False)
    worst = 0.0
    h = mpmath.mpf(10) ** -20
    with mpmath.workdps(50):
        for s in range(n):
            c, dc = _curve(kind, arrays[i][s], rng)
            base = [_mp(a[s]) if a.ndim > 1 else mpmath.mpf(float(a[s])) for a in arrays]
            # the variant the kernel takes at the sample (a branched kernel's Jacobian is
            # its branch's derivative; off the manifold by rounding the branches differ)
            f = _variant(fs, np.concatenate([np.ravel(a[s]) for a in arrays]))

            def flat_args(t, base=base, c=c):
                args = list(base)
                args[i] = c(t)
                out = []
                for a in args:
                    out += list(a) if isinstance(a, mpmath.matrix) else [a]
                return out
            fd = [(p - m) / (2 * h) for p, m in zip(f(*flat_args(h)), f(*flat_args(-h)),
                                                     strict=True)]
            fd = np.array([float(v) for v in fd])
            direction = np.array([float(v) for v in dc]).reshape(k.args[i].shape)
            got = []
            for o in k.outputs:
                J = np.asarray(jac[o.name][arg])[s]
                ax = tuple(range(J.ndim - direction.ndim, J.ndim))
                got.append(np.tensordot(J, direction, axes=(ax, tuple(range(direction.ndim))))
                           .reshape(-1))
            got = np.concatenate(got)
            scale = max(np.abs(fd).max(), 1e-300)
            worst = max(worst, np.abs(got - fd).max() / scale)
    assert worst <= TOL, f"{name}.{arg}: tangent derivative error {worst:.3g}"


# ------------------------------------------------------------------------------------------
# the API


def test_api_shapes_broadcasting_and_pickling():
    f = K.jacobian("point_acceleration")
    rng = np.random.default_rng(16)
    a_ddot, omega, omega_dot = rng.standard_normal((3, 4, 1, 3))
    p, a = rng.standard_normal((5, 3)), np.zeros(3)
    with pytest.warns(K.BroadcastWarning, match="new batch shape"):  # (4, 1) x (5,): meant
        p_ddot, jac = f(a_ddot, omega, omega_dot, p=p, a=a)
    assert p_ddot.shape == (4, 5, 3)
    # the same values up to rounding (one CSE'd program with the derivatives, not the value
    # kernel's: FMA contraction and operation order may differ in the last bits)
    with pytest.warns(K.BroadcastWarning):
        ref = K.point_acceleration(a_ddot, omega, omega_dot, p, a)
    assert np.abs(p_ddot - ref).max() <= 4e-16 * np.abs(ref).max()
    assert set(jac) == {"p_ddot"}
    assert set(jac["p_ddot"]) == {"a_ddot", "omega", "omega_dot", "p", "a"}
    for v in jac["p_ddot"].values():
        assert v.shape == (4, 5, 3, 3)       # per sample, never summed over the broadcast
    # d p_ddot / d a_ddot is the identity, d p_ddot / d p = W = CPM(omega_dot) + CPM(omega)^2
    assert np.array_equal(jac["p_ddot"]["a_ddot"], np.broadcast_to(np.eye(3), (4, 5, 3, 3)))
    w = omega[0, 0]
    cpm = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    wd = omega_dot[0, 0]
    cpm_d = np.array([[0, -wd[2], wd[1]], [wd[2], 0, -wd[0]], [-wd[1], wd[0], 0]])
    assert np.allclose(jac["p_ddot"]["p"][0, 3], cpm_d + cpm @ cpm, rtol=0, atol=1e-14)
    g = pickle.loads(pickle.dumps(f))
    assert g is f
    with pytest.raises(TypeError):
        f(a_ddot, omega, omega_dot, p, a, out=None)
    with pytest.raises(ValueError, match="name"):
        K.jacobian("natural_invariants_from_rotation")   # per-sample branches


def test_multi_output_and_singular_handling():
    f = K.jacobian("instant_screw_axis")
    omega = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0]])
    a = np.array([1.0, 0.0, 0.0])
    a_dot = np.array([0.0, 1.0, 0.5])
    with pytest.raises(K.SingularConfigurationError) as exc:
        f(omega, a, a_dot)
    assert exc.value.argument == "omega" and exc.value.indices == [(1,)]
    (p0, pitch, plucker), jac = f(omega, a, a_dot, on_singular="nan")
    assert np.isnan(p0[1]).all() and np.isnan(jac["pitch"]["omega"][1]).all()
    assert np.isfinite(jac["plucker"]["a_dot"][0]).all()
    assert jac["plucker"]["omega"].shape == (2, 6, 3)
    # pitch = a_dot . omega / ||omega||^2: d pitch / d a_dot = omega / ||omega||^2
    assert np.array_equal(jac["pitch"]["a_dot"][0], omega[0])


def test_euler_rate_matrix_jacobian():
    angles = np.array([0.1, 0.2, 0.3])
    W, jac = K.jacobian("euler_rate_matrix")(angles, "ZYX", frame="body")
    assert np.array_equal(W, K.euler_rate_matrix(angles, "ZYX", "body"))
    assert jac["W"]["angles"].shape == (3, 3, 3)
    eps = 1e-6
    for j in range(3):
        d = np.zeros(3)
        d[j] = eps
        fd = (K.euler_rate_matrix(angles + d, "ZYX", "body")
              - K.euler_rate_matrix(angles - d, "ZYX", "body")) / (2 * eps)
        assert np.allclose(jac["W"]["angles"][..., j], fd, rtol=0, atol=1e-9)
    with pytest.raises(ValueError, match="sequence"):
        K.jacobian("euler_rate_matrix")(angles, "ZZZ")


def test_derivative_names_follow_symforce():
    assert derivative_name("Q", "e") == "Q_D_e"
    meta = _state.meta()[jacobian_name("kinetic_energy")]
    assert [o["name"] for o in meta["outputs"]] == ["T", "T_D_I_C", "T_D_m", "T_D_omega",
                                                   "T_D_c_dot"]
    assert meta["public"] is False


def test_docstring_examples_run():
    import doctest

    import rigidsym.kernels.runtime.jacobians as mod

    res = doctest.testmod(mod, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert res.attempted >= 2 and res.failed == 0
