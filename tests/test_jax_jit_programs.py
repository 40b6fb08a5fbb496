"""The compiled ``jax.jit`` value + gradient programs of the JAX kernels:
what XLA computes once, and the gradients' accuracy on cancelling inputs against 50-digit
references and the textbook formula."""

from __future__ import annotations

import re
from fractions import Fraction

import numpy as np
import pytest

#: skipped without its extra in the README's test command; .ci/run installs it
pytestmark = pytest.mark.extra

jax = pytest.importorskip("jax", reason="JAX is not installed (the [jax] extra)")
import jax.numpy as jnp  # noqa: E402

from rigidsym.kernels import jax as rj  # noqa: E402
from tests.test_jax_kernels import _x64  # noqa: E402, F401 - the x64 fixture (autouse)


def _step(fn, nargs: int):
    """One training step: the value and the gradient of the sum of every output."""
    def loss(*xs):
        out = fn(*xs)
        return sum(o.sum() for o in (out if isinstance(out, tuple) else (out,)))
    return jax.jit(jax.value_and_grad(loss, argnums=tuple(range(nargs))))


def _computations(fn, xs) -> list[str]:
    """The computations (fusions and the entry) of the compiled value + gradient step."""
    text = _step(fn, len(xs)).lower(*xs).compile().as_text()
    return re.split(r"\n(?=%\S+ \(|ENTRY)", text)


def _cpu():
    if jax.default_backend() != "cpu":
        pytest.skip("the fusion layout measured is XLA's on the CPU")


@pytest.mark.parametrize("dtype, splitter", [(np.float32, "4097"),
                                             (np.float64, "134217729")])
def test_compensated_pitch_computed_once_under_jit(dtype, splitter):
    """The compensated pitch of ``instant_screw_axis`` (Dot2, ~65 operations, its Veltkamp
    splitter a constant) in one fusion of the compiled value + gradient. Guards against: 6 (XLA
    fused it into each reader: the outputs, the gradients; 2-2.6x a hand-written formula
    at N = 1e3 on one core)."""
    _cpu()
    rng = np.random.default_rng(0)
    xs = [jnp.asarray(rng.standard_normal((64, 3)), dtype) for _ in range(3)]
    found = [c for c in _computations(rj.instant_screw_axis, xs)
             if re.search(rf"constant\({splitter}\)", c)]
    assert len(found) == 1, f"the compensated pitch computed in {len(found)} computations"


def test_values_and_jvp_share_the_forward_under_jit():
    """The JVP rule evaluates the program on the values' own columns (inf as NaN), so that
    XLA computes the forward once for both: one sine in the compiled value + gradient of
    ``rotation_from_natural_invariants``. Guards against: 2 (the JVP's columns lacked the values'
    inf-to-NaN step; ``instant_screw_axis``'s forward, its compensated pitch included, was
    computed twice too)."""
    _cpu()
    rng = np.random.default_rng(0)
    e = rng.standard_normal((64, 3))
    e /= np.linalg.norm(e, axis=1, keepdims=True)
    xs = [jnp.asarray(e, jnp.float32), jnp.asarray(rng.uniform(0.3, 2.8, 64), jnp.float32)]
    sines = sum(len(re.findall(r" sine\(", c))
                for c in _computations(rj.rotation_from_natural_invariants, xs))
    assert sines == 1


def _cancelling(n: int, dtype, seed: int = 1) -> list[np.ndarray]:
    """omega, a, a_dot with a_dot nearly orthogonal to omega: the pitch a_dot.omega cancels
    (by 1e-1 to 1e-9 of its terms)."""
    rng = np.random.default_rng(seed)
    om, a, d = (rng.standard_normal((n, 3)) for _ in range(3))
    d -= (np.sum(d * om, 1) / np.sum(om * om, 1))[:, None] * om
    d += (10.0 ** rng.uniform(-9, -1, n))[:, None] * om
    return [x.astype(dtype) for x in (om, a, d)]


def _reference_gradients(xs) -> np.ndarray:
    """The gradient of the sum of the outputs of the instant screw axis (3.53)-(3.55),
    (3.70) with respect to (omega, a, a_dot), at 50 digits, at the rounded inputs."""
    import mpmath as mp
    import sympy as sp

    w, a, d = (sp.Matrix(sp.symbols(f"{c}0:3")) for c in "wad")
    w2 = w.dot(w)
    p0 = w.cross(d - w.cross(a)) / w2
    e = w / sp.sqrt(w2)
    loss = sum(p0) + d.dot(w) / w2 + sum(e) + sum(p0.cross(e))
    syms = [*w, *a, *d]
    grad = sp.lambdify(syms, [sp.diff(loss, s) for s in syms], "mpmath")
    cols = np.concatenate([x.astype(np.float64) for x in xs], 1)
    with mp.workdps(50):
        return np.array([[float(g) for g in grad(*(mp.mpf(float(v)) for v in row))]
                         for row in cols])


@pytest.mark.slow
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_jit_gradient_on_cancelling_inputs(dtype):
    """The jitted value + gradient of ``instant_screw_axis`` where its pitch cancels (by
    1e-1 to 1e-9), against 50 digits: per sample, the error over the largest gradient entry
    at most 32 u, and the pitch within 16 u where the textbook formula's is off by up to
    1e9 u. The fusion layout moves roundings (XLA contracts a * b + c into an FMA inside a
    fusion), so this is the property, not bits. Measured, 300 samples: 27.8 u / 16.8 u
    (float32 / float64), the same worst as before the compensated pitch was computed once;
    the textbook formula's gradient 12.5 u / 10.8 u, its pitch 1.1e9 u / 4.4e8 u."""
    xs = _cancelling(300, dtype)
    ref = _reference_gradients(xs)
    u = float(np.finfo(dtype).eps) / 2
    js = [jnp.asarray(x) for x in xs]
    (_, g), (_, pitch, _) = _step(rj.instant_screw_axis, 3)(*js), \
        jax.jit(rj.instant_screw_axis)(*js)
    g = np.concatenate([np.asarray(v, np.float64) for v in g], 1)
    assert np.isfinite(g).all()
    err = np.abs(g - ref) / np.abs(ref).max(1, keepdims=True) / u
    assert err.max() <= 32, f"gradient {err.max():.1f} u"
    om, d = (x.astype(np.float64) for x in (xs[0], xs[2]))
    exact = np.array([float(sum(Fraction(p) * Fraction(q) for p, q in zip(a, b, strict=True))
                            / sum(Fraction(p) ** 2 for p in a))
                      for a, b in zip(om, d, strict=True)])
    perr = np.abs(np.asarray(pitch, np.float64) - exact) / np.abs(exact) / u
    assert perr.max() <= 16, f"pitch {perr.max():.1f} u"
