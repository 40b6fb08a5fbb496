"""Gradients of the PyTorch kernels within 1e-6 of the singular sets.

Two checks at the probes of ``tests/_arrays_cases.py`` (phi -> 0 or pi, ||omega|| -> 0,
p2 -> p1, f -> 0, Q -> 1 and pi, Euler angles at gimbal lock; float64):

* ``torch.autograd.gradcheck``. Its default step (eps = 1e-6) is the distance to the singular
  set: it steps onto or across it (N_matrix: phi - eps = 0, a SingularConfigurationError),
  and the derivatives there grow like 1/delta^k (max|J| up to 4e18 at delta = 1e-6). So the
  step is EPS = 1e-10 (1e-4 of the distance: central-difference truncation ~ (eps/delta)^2 =
  1e-8 of the derivative's scale, rounding ~ u delta / eps = 1e-12), compared normwise:
  atol = ATOL * max|J| (the entries span 1e-1 to 1e18 at one point), rtol = 1e-5.
  Measured worst normwise error 1e-6 (plucker_from_points, L_tilde_dot); asserted 1e-5.
  rotation_from_natural_invariants at phi = 1e-6 is no singular set (the hand-written
  formulas' sin(phi)/phi is): there gradcheck passes with its default tolerances.
* The kernels with a generated Jacobian: the Jacobian autograd computes (the backward of the
  ``torch.autograd.Function``) against sympy's derivative of the declaration evaluated in
  mpmath at 50 digits (tests/test_jacobians.py), normwise within its TOL = 1e-13, or the
  accuracy harness's 8 u kappa + 8 u where that is larger: p2 -> p1 (plucker_from_points),
  where kappa = max|p| / ||p2 - p1|| ~ 1e6 (the program forms p2 - p1 from O(1) inputs;
  measured 4.4e-11, the same as the NumPy and C Jacobian kernels'); kappa = 1 elsewhere, the
  singular sets there being at an input itself.
"""

from __future__ import annotations

import numpy as np
import pytest
import test_jacobians as TJ
from test_kernels import rel_err

from rigidsym import kernels as K
from rigidsym.kernels.runtime import state as _state
from tests._arrays_cases import euler_probe, sample, singular_probes

#: skipped without its extra in the README's test command; .ci/run installs it
pytestmark = pytest.mark.extra

torch = pytest.importorskip("torch", reason="PyTorch is not installed (the [torch] extra)")
from rigidsym.kernels import torch as rk  # noqa: E402

EPS = 1e-10
ATOL = 1e-5
RTOL = 1e-5
#: near the identity: no singular set, but where sin(phi)/phi is evaluated by hand elsewhere
SMOOTH = "rotation_from_natural_invariants"
PROBED = [n for n in K.KERNEL_NAMES if singular_probes(n) is not None]
EULER = [("ZYX", "fixed"), ("ZXZ", "body")]


def _probes(name: str) -> list[np.ndarray]:
    if name == SMOOTH:
        xs = sample(name, 3, seed=7)
        xs[1] = np.full(3, 1e-6)
        return xs
    return singular_probes(name)


def _gradcheck(fn, xs, **kw) -> bool:
    return torch.autograd.gradcheck(fn, [torch.tensor(x, requires_grad=True) for x in xs],
                                    **kw)


def _normwise(fn, xs) -> dict:
    """gradcheck's step and tolerances at a point delta = 1e-6 from a singular set."""
    J = torch.autograd.functional.jacobian(fn, tuple(torch.tensor(x) for x in xs))
    blocks = [j for row in (J if isinstance(J[0], tuple) else (J,)) for j in row]
    jmax = max(float(j.abs().max()) for j in blocks)
    assert np.isfinite(jmax), "non-finite Jacobian"
    return {"eps": EPS, "atol": ATOL * jmax, "rtol": RTOL}


@pytest.mark.parametrize("name", [*PROBED, SMOOTH])
def test_gradcheck_near_the_singular_sets(name):
    xs = _probes(name)

    def fn(*a):
        return getattr(rk, name)(*a, check=False)
    if name == SMOOTH:
        assert _gradcheck(fn, xs)
    else:
        assert _gradcheck(fn, xs, **_normwise(fn, xs))


@pytest.mark.parametrize("seq", ["ZYX", "ZXZ"])
def test_gradcheck_of_euler_rates_near_gimbal_lock(seq):
    xs = [euler_probe(seq), np.array([[0.1, 0.2, 0.3]] * 2)]

    def fn(ang, w):
        return rk.euler_angle_rates(ang, w, seq, check=False)
    assert _gradcheck(fn, xs, **_normwise(fn, xs))


def _torch_row(fn, xs, outs: list[dict]) -> np.ndarray:
    """One sample's values, then d output / d input for each output and input in order,
    each row-major: the layout of the ``<name>_with_jacobians`` kernel."""
    ts = tuple(torch.tensor(x) for x in xs)
    vals = fn(*ts)
    vals = vals if isinstance(vals, tuple) else (vals,)
    J = torch.autograd.functional.jacobian(fn, ts)
    J = J if isinstance(J[0], tuple) else (J,)
    parts = [v.reshape(-1) for v in vals[:len(outs)]]
    parts += [J[k][j].reshape(-1) for k in range(len(outs)) for j in range(len(ts))]
    return torch.cat(parts).numpy()


def _kappa(base: str, xs) -> float:
    """The condition number the tolerance allows for (see the module)."""
    if _state.meta()[base]["singular_arg"] != "p2":
        return 1.0
    p1, p2 = xs
    big = max(np.abs(p1).max(), np.abs(p2).max())
    return float(big / np.linalg.norm(p2 - p1, axis=-1).min())


def _against_mpmath(base: str, fn, xs):
    outs = _state.meta()[base]["outputs"]
    got = np.stack([_torch_row(fn, [x[i] for x in xs], outs) for i in range(len(xs[0]))])
    ref = TJ.ref_eval(base, xs)
    assert got.shape == ref.shape and np.isfinite(ref).all()
    u = float(np.finfo(np.float64).eps)
    tol = max(TJ.TOL, 8 * u * _kappa(base, xs) + 8 * u)
    err = rel_err(got, ref)
    assert err.max() <= tol, f"{base}: max normwise error {err.max():.3g} > {tol:.3g}"


@pytest.mark.parametrize("name", [n for n in [*PROBED, SMOOTH] if n in TJ.BASES])
def test_jacobian_near_the_singular_sets_is_sympys_to_50_digits(name):
    _against_mpmath(name, lambda *a: getattr(rk, name)(*a, check=False), _probes(name))


@pytest.mark.parametrize("seq,frame", EULER)
def test_euler_rate_matrix_jacobian_at_gimbal_lock_is_sympys(seq, frame):
    _against_mpmath(f"euler_rate_matrix_{seq.lower()}_{frame}",
                    lambda a: rk.euler_rate_matrix(a, seq, frame, check=False),
                    [euler_probe(seq)])
