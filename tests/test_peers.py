"""The peers' table (:mod:`rigidsym.codegen.accuracy.peers`): every adapter
computes its kernel's outputs, and the conventions the adapters rest on (right or left Jacobians,
``[v; w]`` or ``[w; v]``, the logarithm's domain) hold numerically, not by belief.

Before it the peers were a list in the harness (harness/yardsticks.py) with no
Pinocchio Jacobian, no PyPose and no jaxlie, and docs/accuracy.md's column was written by
hand. The adapter tests need the ``[oracles]`` extra (``extra``); the table's own shape does
not.
"""

from __future__ import annotations

import inspect
import json
import sys
from pathlib import Path

import numpy as np
import pytest

from rigidsym.codegen.accuracy import peer_adapters as PA
from rigidsym.codegen.accuracy import peers as T

ROOT = Path(__file__).resolve().parents[1]
KERNELS = {k["name"]: k for k in json.loads((ROOT / "generated" / "kernels.json")
                                             .read_text("utf-8"))["kernels"]}


def _spec(name):
    sys.path.insert(0, str(ROOT / "benchmarks"))
    from rigidsym.codegen.accuracy.harness import reference as R

    return R.kernel_of(name)


def test_every_entry_names_a_kernel_its_outputs_and_its_arguments():
    """A peer of a kernel that does not exist, of an output it does not have, or with the
    wrong number of arguments would be a yardstick of nothing (the harness NaNs it)."""
    assert T.PEERS
    for p in T.PEERS:
        assert p.kernel in KERNELS, p.label
        assert p.library in T.LIBRARIES, p.label
        k = _spec(p.kernel)
        assert set(p.outputs) <= {o.name for o in k.outputs}, p.label
        params = list(inspect.signature(p.adapt).parameters.values())
        positional = [q for q in params if q.default is inspect.Parameter.empty]
        assert len(positional) == 1 + len(k.args), p.label
    # each row of the docs' table is a kernel of the table, once
    rows = [r.split("|")[1].strip(" `") for r in T.markdown().splitlines()[2:]]
    assert sorted(rows) == sorted({p.kernel for p in T.PEERS})


def test_a_missing_library_is_left_out_with_its_reason(monkeypatch):
    """Whatever is installed here (the default run has no [oracles] extra): every other
    library stands in as loaded, PyPose as missing."""
    import types

    for lib in T.LIBRARIES:
        monkeypatch.setitem(T._LOADED, lib, types.ModuleType(lib))
    monkeypatch.setitem(T._LOADED, "PyPose", ImportError("No module named 'pypose'"))
    ok, missing = T.available("rotation_vector_right_jacobian")
    assert [p.library for p, _ in missing] == ["PyPose"]
    assert "[oracles]" in missing[0][1] and "pypose" in missing[0][1]
    assert ok and all(p.library != "PyPose" for p, _ in ok)


def _points(name, n=8):
    sys.path.insert(0, str(ROOT / "benchmarks"))
    from rigidsym.codegen.accuracy.harness import judge as A

    k = A.R.kernel_of(name)
    pts = A.P.regimes(k, np.float64, n_random=n, extremes=False)["random"]
    arrays = A.round_points(pts, np.float64, k)
    return arrays, A.run_kernel(name, arrays, np.float64, "numpy")


def _kernels_of(library):
    names = sorted({p.kernel for p in T.PEERS if p.library == library})
    withj = sorted(n + "_with_jacobians" for n in names if n + "_with_jacobians" in KERNELS)
    return names + [n for n in withj if n not in names]


@pytest.mark.extra
@pytest.mark.parametrize("library", sorted(T.LIBRARIES))
def test_each_adapter_computes_its_kernels_outputs(library):
    """At random points each peer of ``library`` agrees with rigidsym's kernel (NumPy) to
    1e-12 relative in every output it computes (normwise per output), and computes at least
    one output; a ``_with_jacobians`` kernel's values included."""
    pytest.importorskip("flint")
    try:
        T._load(library)
    except ImportError as e:
        pytest.skip(str(e))
    sys.path.insert(0, str(ROOT / "benchmarks"))
    from rigidsym.codegen.accuracy.harness import yardsticks as O

    checked = 0
    for name in _kernels_of(library):
        arrays, want = _points(name)
        sl = O._slices(name)
        for label, v in O.evaluate(name, arrays, want.shape[1]).items():
            if not label.startswith(library + " "):
                continue
            p = next(p for p in T.for_kernel(name) if p.label == label)
            assert not np.isnan(v[:, [c for o in p.outputs
                                      for c in range(sl[o].start, sl[o].stop)]]).all(), label
            for o in p.outputs:
                for s in range(v.shape[0]):
                    got, ref = v[s, sl[o]], want[s, sl[o]]
                    if np.isnan(got).all():          # outside the peer's domain
                        continue
                    err = np.linalg.norm(got - ref) / max(np.linalg.norm(ref), 1e-300)
                    assert err < 1e-12, f"{name} {label} {o} at row {s}: {err:.3g}"
            checked += 1
    assert checked


def _rot(w):
    from scipy.spatial.transform import Rotation

    return Rotation.from_rotvec(w).as_matrix()


def _log(Q):
    from scipy.spatial.transform import Rotation

    return Rotation.from_matrix(Q).as_rotvec()


def _tr(xi):
    """``Exp`` of SE(3) at ``xi = [w; v]`` (scipy's matrix exponential: no peer's)."""
    from scipy.linalg import expm

    X = np.zeros((4, 4))
    w, v = xi[:3], xi[3:]
    X[:3, :3] = [[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]
    X[:3, 3] = v
    return expm(X)


def _right_first_order(exp, J, x, h=1e-6, seed=0):
    """``|Exp(x + h d) - Exp(x) Exp(h J d)| / h`` over random ``d`` (O(h): J is the right
    Jacobian) and the same with ``Exp(h J d) Exp(x)`` (O(1) unless J is also the left one)."""
    rng = np.random.default_rng(seed)
    right = left = 0.0
    for _ in range(4):
        d = rng.standard_normal(x.size)
        a = exp(x + h * d)
        right = max(right, np.abs(a - exp(x) @ exp(h * J @ d)).max() / h)
        left = max(left, np.abs(a - exp(h * J @ d) @ exp(x)).max() / h)
    return right, left


W = np.array([0.4, -1.1, 0.7])
XI = np.array([0.4, -1.1, 0.7, 0.3, 2.0, -0.5])


def _pin():
    return pytest.importorskip("pinocchio", reason="the [oracles] extra")


def _pp():
    pytest.importorskip("torch", reason="the [oracles] extra needs torch")
    return pytest.importorskip("pypose", reason="the [oracles] extra")


def _conv_pin_jexp3():
    pin = _pin()
    return _right_first_order(_rot, pin.Jexp3(W), W)


def _conv_pin_jexp6():
    pin = _pin()
    J = PA._swap(pin.Jexp6(pin.Motion(XI[3:], XI[:3])))     # [v; w] -> [w; v]
    return _right_first_order(_tr, J, XI)


def _conv_pypose_jr():
    pp = _pp()
    return _right_first_order(_rot, PA._np(pp.so3(PA._torch(W)).Jr()), W)


def _conv_spatialmath_exp2jac():
    sb = pytest.importorskip("spatialmath.base", reason="the [oracles] extra")
    right, left = _right_first_order(_rot, sb.exp2jac(W), W)
    return left, right                     # the left Jacobian: the roles swap


def _conv_pin_jlog3():
    """``Log(R Exp(h d)) = Log(R) + h Jlog3(R) d + O(h^2)``: J_r^-1 at the logarithm."""
    pin = _pin()
    return _log_first_order(lambda Q: pin.Jlog3(Q))


def _conv_jaxlie_jlog():
    jaxlie = pytest.importorskip("jaxlie", reason="the [oracles] extra")
    with T.x64():
        return _log_first_order(lambda Q: np.asarray(jaxlie.SO3.from_matrix(Q).jlog()))


def _log_first_order(jlog, h=1e-6):
    rng = np.random.default_rng(1)
    Q = _rot(W)
    right = left = 0.0
    for _ in range(4):
        d = rng.standard_normal(3)
        right = max(right, np.abs(_log(Q @ _rot(h * d)) - W - h * jlog(Q) @ d).max() / h)
        left = max(left, np.abs(_log(_rot(h * d) @ Q) - W - h * jlog(Q) @ d).max() / h)
    return right, left


CONVENTIONS = {"Pinocchio Jexp3 is J_r": _conv_pin_jexp3,
               "Pinocchio Jexp6 is J_r on [v; w]": _conv_pin_jexp6,
               "PyPose so3.Jr is J_r": _conv_pypose_jr,
               "spatialmath exp2jac is J_l": _conv_spatialmath_exp2jac,
               "Pinocchio Jlog3 is J_r^-1 at Log": _conv_pin_jlog3,
               "jaxlie SO3.jlog is J_r^-1 at Log": _conv_jaxlie_jlog}


@pytest.mark.extra
@pytest.mark.parametrize("what", sorted(CONVENTIONS))
def test_the_conventions_the_adapters_rest_on(what):
    """Each convention an adapter assumes, as a first-order expansion: the claimed side is
    O(h) off (h = 1e-6), the other side O(1) off (so the check can fail). With it, the
    adapters' ``J_l(w) = J_r(-w)`` is the identity ``Exp(-w) = Exp(w)^T``."""
    claimed, other = CONVENTIONS[what]()
    assert claimed < 1e-4, (what, claimed)
    assert other > 1e-2, (what, other)


@pytest.mark.extra
def test_the_jaxlie_peers_leave_jaxs_default_type_alone():
    """The jaxlie adapters compute in float64 inside a context: a test after them that runs
    JAX in its default float32 (tests/test_jax_kernels.py) still gets float32."""
    jax = pytest.importorskip("jax", reason="the [oracles] extra")
    before = jax.config.jax_enable_x64
    ok = [f for p, f in T.available("rotation_from_rotation_vector")[0]
          if p.library == "jaxlie"]
    if not ok:
        pytest.skip("jaxlie: not installed (the [oracles] extra)")
    Q = ok[0](W)[0]
    assert Q.dtype == np.float64 and np.allclose(Q @ Q.T, np.eye(3), atol=1e-15)
    assert jax.config.jax_enable_x64 == before


@pytest.mark.extra
def test_a_peer_through_the_logarithm_fails_outside_its_domain():
    """``Jlog3(exp3(w))`` is ``J_r^-1`` at ``Log(Exp(w))``, which is not ``w`` for ``|w| >
    pi``: there the adapter raises (the harness counts the peer failed) rather than hand
    the rule the Jacobian of another point."""
    pin = _pin()
    w = 4.0 * W / np.linalg.norm(W)
    assert not np.allclose(pin.Jlog3(pin.exp3(w)), np.linalg.inv(pin.Jexp3(w)))
    for p, f in T.available("rotation_vector_right_jacobian_inverse")[0]:
        if "Jlog" in p.call or "jlog" in p.call:
            with pytest.raises(ValueError, match="pi"):
                f(w)


def test_a_users_file_named_like_a_peer_library_is_never_taken_for_it(tmp_path, monkeypatch):
    """A ``--module`` folder stays on ``sys.path`` (examples/ holds modern_robotics.py): a
    file there named like a peer's library is not the library, whether or not the library is
    installed, and is never executed (it would register its declarations a second time)."""
    (tmp_path / "modern_robotics.py").write_text(
        "raise RuntimeError('a user file executed as the peer library')\n", encoding="utf-8")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setattr(T, "_LOADED", {})
    monkeypatch.delitem(sys.modules, "modern_robotics", raising=False)
    kernel = next(p.kernel for p in T.PEERS if p.library == "Modern Robotics")
    ok, missing = T.available(kernel)
    assert not [p for p, _ in ok if p.library == "Modern Robotics"]
    why = [w for p, w in missing if p.library == "Modern Robotics"]
    assert why and all("not available" in w for w in why), why
    assert "modern_robotics" not in sys.modules
