"""``rigidsym.core.draws``: the one place tests and benchmarks draw valid kernel inputs."""

from __future__ import annotations

import numpy as np
import pytest

from rigidsym.core import kinds as _kinds
from rigidsym.core.draws import draw


@pytest.mark.parametrize("kind, own", [("unit", (3,)), ("rotation", (3, 3)),
                                       ("transform", (4, 4))])
def test_draws_lie_on_the_kinds_manifold(kind, own):
    rng = np.random.default_rng(5)
    x = draw(kind, (2, 7) + own, rng)
    assert x.shape == (2, 7) + own
    # the runtime validation of the kind accepts them (a transform: R proper orthogonal,
    # last row [0, 0, 0, 1]; the benchmarks once drew a free 4 x 4 here)
    assert _kinds.for_spec(kind, own).check(x, "x", 1e-12) is None
    if kind == "transform":
        assert np.linalg.det(x[..., :3, :3]) == pytest.approx(1.0)


def test_angle_ranges_and_free_arguments():
    rng = np.random.default_rng(1)
    a = draw("angle", (1000,), rng, angle=(0.3, 2.8))
    assert a.min() >= 0.3 and a.max() <= 2.8
    assert draw("any", (3, 6), rng, free=lambda s: np.full(s, 2.0)).tolist() == [[2.0] * 6] * 3


def test_a_rotation_needs_its_shape():
    with pytest.raises(ValueError, match="shape: a transform ends in"):
        draw("transform", (5, 3, 3), np.random.default_rng(0))
