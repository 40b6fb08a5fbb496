"""Shared inputs of the PyTorch and JAX kernel tests: random valid samples for
every public kernel and for the Euler-angle kernels, and probes within 1e-6 of the singular
sets, all as float64 NumPy arrays; the reference values and Jacobians come from the NumPy
kernels (:mod:`rigidsym.kernels`, :func:`rigidsym.kernels.jacobian`)."""

from __future__ import annotations

import numpy as np

from rigidsym import kernels as K
from rigidsym.core.draws import draw
from rigidsym.kernels.runtime import state as _state


def sample(name: str, n: int, seed: int = 0) -> list[np.ndarray]:
    """``n`` random valid samples of every argument of kernel ``name`` (unit vectors,
    rotations, transforms, angles in (0.3, 2.8), others standard normal)."""
    rng = np.random.default_rng(seed)
    out = []
    for a in _state.meta()[name]["args"]:
        x = draw(a["kind"], (n, *a["shape"]), rng, phi=(0.3, 2.8), angle=(0.3, 2.8))
        if a["name"] == "m":        # a body's mass and inertia (the kernels check them)
            x = np.abs(x) + 0.5
        elif a["name"] == "I_C":    # tr(S) 1 - S of a second moment S
            S = np.einsum("nij,nkj->nik", x, x) + 0.1 * np.eye(3)
            x = np.trace(S, axis1=1, axis2=2)[:, None, None] * np.eye(3) - S
        out.append(x)
    return out


#: Euler kernels sampled in the default suite (all 24 of each kind are generated)
EULER = [("ZYX", "fixed"), ("ZXZ", "body"), ("XYZ", "fixed")]


def singular_probes(name: str, n: int = 3) -> list[np.ndarray] | None:
    """Samples within 1e-6 of kernel ``name``'s singular set, or None (no singular set)."""
    meta = _state.meta()[name]
    arg = meta["singular_arg"]
    if not arg:
        return None
    xs = sample(name, n, seed=7)
    names = [a["name"] for a in meta["args"]]
    k = names.index(arg)
    if arg == "phi":    # phi -> 0, or phi -> pi where the set is 1 + cos(phi) = 0
        xs[k] = np.full(n, np.pi - 1e-6 if "phi = pi" in meta["singular"] else 1e-6)
    elif arg in ("omega", "p2"):
        if arg == "p2":
            xs[k] = xs[names.index("p1")] + 1e-6 * xs[k] / np.linalg.norm(xs[k], axis=-1,
                                                                          keepdims=True)
        else:
            xs[k] = 1e-6 * xs[k] / np.linalg.norm(xs[k], axis=-1, keepdims=True)
    elif arg == "w_A":  # w_A = [n_A; f], singular at f = 0
        xs[k][:, 3:] *= 1e-6 / np.linalg.norm(xs[k][:, 3:], axis=-1, keepdims=True)
    elif arg == "Q":  # rotations by pi - 1e-6 and by 1e-6
        e = np.array([[0.0, 0.6, 0.8], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])[:n]
        xs[k] = K.rotation_from_natural_invariants(e, np.array([np.pi - 1e-6, 1e-6,
                                                                np.pi - 1e-6])[:n])
    else:
        return None
    return xs


def euler_probe(sequence: str, n: int = 2, seed: int = 3) -> np.ndarray:
    """Euler angles within 1e-6 of gimbal lock (middle angle pi/2 for Tait-Bryan
    sequences, 0 for proper Euler sequences)."""
    rng = np.random.default_rng(seed)
    angles = rng.uniform(-1.0, 1.0, (n, 3))
    angles[:, 1] = (1e-6 if sequence[0] == sequence[2] else np.pi / 2 - 1e-6)
    return angles
