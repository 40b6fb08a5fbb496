"""Fit a rigid motion to point pairs, from w = 0, through rigidsym's differentiable kernels.

The motion is exponential coordinates ``xi = [w; v]`` (angular first), started at ``xi = 0``
(the identity: the kernels' removable singularity at ``w = 0`` is a certified series, so
the gradient there is exact, never NaN); the loss is the mean squared distance between the
moved points ``Exp(xi) p`` and their observed images ``q``. In PyTorch, Adam with a decaying
step; in JAX, plain ``jax.grad`` steps. From noiseless pairs both reach the known motion to
1e-6 rad and 1e-6 m (``tests/test_training.py``); the geodesic error of the rotation is
``|Log(R_fit^T R_true)|`` (``rotation_vector_from_rotation``).

Run: ``python examples/train_rigid_motion.py`` (needs ``torch`` and/or ``jax``).
"""

from __future__ import annotations

import numpy as np


def problem(n: int = 64, noise: float = 0.0, seed: int = 0):
    """Points ``p`` (n, 3), their images ``q = R p + t (+ noise)``, and the true ``xi``."""
    from rigidsym import kernels

    rng = np.random.default_rng(seed)
    xi = np.r_[rng.normal(size=3) * 0.8, rng.normal(size=3)]
    T = kernels.transform_from_exponential_coordinates(xi)
    p = rng.normal(size=(n, 3))
    q = p @ T[:3, :3].T + T[:3, 3] + noise * rng.normal(size=(n, 3))
    return p, q, xi


def errors(xi_fit, xi_true) -> tuple[float, float]:
    """(geodesic rotation error [rad], translation error [m]) of a fitted motion."""
    from rigidsym import kernels

    Ta = kernels.transform_from_exponential_coordinates(np.asarray(xi_fit, dtype=float))
    Tb = kernels.transform_from_exponential_coordinates(np.asarray(xi_true, dtype=float))
    w = kernels.rotation_vector_from_rotation(Ta[:3, :3].T @ Tb[:3, :3])
    return float(np.linalg.norm(w)), float(np.linalg.norm(Ta[:3, 3] - Tb[:3, 3]))


def fit_torch(p, q, steps: int = 1500, lr: float = 0.1):
    """Adam from xi = 0 (float64), the step decaying to 0 over ``steps``."""
    import torch

    from rigidsym.kernels import torch as rk

    P, Qm = torch.as_tensor(p), torch.as_tensor(q)
    xi = torch.zeros(6, dtype=torch.float64, requires_grad=True)
    opt = torch.optim.Adam([xi], lr=lr)
    sched = torch.optim.lr_scheduler.LambdaLR(opt, lambda k: (1 - k / steps) ** 2)
    for _ in range(steps):
        opt.zero_grad()
        T = rk.transform_from_exponential_coordinates(xi)
        loss = ((P @ T[:3, :3].T + T[:3, 3] - Qm) ** 2).sum(-1).mean()
        loss.backward()
        opt.step()
        sched.step()
    return xi.detach().numpy()


def fit_jax(p, q, steps: int = 300, lr: float = 0.3):
    """``jax.grad`` steps from xi = 0 (float64: ``jax_enable_x64``), jitted."""
    import jax
    import jax.numpy as jnp

    jax.config.update("jax_enable_x64", True)
    from rigidsym.kernels import jax as rk

    P, Qm = jnp.asarray(p), jnp.asarray(q)

    def loss(xi):
        T = rk.transform_from_exponential_coordinates(xi)
        return ((P @ T[:3, :3].T + T[:3, 3] - Qm) ** 2).sum(-1).mean()

    step = jax.jit(lambda xi: xi - lr * jax.grad(loss)(xi))
    xi = jnp.zeros(6)
    for _ in range(steps):
        xi = step(xi)
    return np.asarray(xi)


def fit_quaternion_network(target_Q, steps: int = 800, seed: int = 0):
    """A network's quaternion output, normalised, through ``rotation_from_euler_rodrigues``:
    a linear layer from a fixed feature to 4 numbers, trained so that the rotation matches
    ``target_Q`` (chordal loss). Returns the final rotation (3, 3)."""
    import torch

    from rigidsym.kernels import torch as rk

    torch.manual_seed(seed)
    net = torch.nn.Linear(8, 4, dtype=torch.float64)
    x = torch.ones(8, dtype=torch.float64)
    target = torch.as_tensor(target_Q)
    opt = torch.optim.Adam(net.parameters(), lr=0.05)
    sched = torch.optim.lr_scheduler.LambdaLR(opt, lambda k: (1 - k / steps) ** 2)
    for _ in range(steps):
        opt.zero_grad()
        eta = net(x)
        Q = rk.rotation_from_euler_rodrigues(eta / eta.norm(dim=-1, keepdim=True))
        ((Q - target) ** 2).sum().backward()
        opt.step()
        sched.step()
    with torch.no_grad():
        eta = net(x)
        return rk.rotation_from_euler_rodrigues(eta / eta.norm()).numpy()


if __name__ == "__main__":  # pragma: no cover - a demonstration
    p, q, xi = problem()
    for name, fit in (("torch", fit_torch), ("jax", fit_jax)):
        try:
            got = fit(p, q)
        except ImportError as exc:
            print(f"{name}: skipped ({exc})")
            continue
        print(f"{name}: rotation error %.1e rad, translation error %.1e m" % errors(got, xi))
