"""A handout's box labels name the order the key uses: a box whose label says "ascending"
holds ascending values in the key (3.14; 3.12, whose exact solve takes a second, under
``slow``), and 3.15's two moments normal to d come in the order
its label names (the one from I_2, then the one from I_3)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from rigidsym import exercises as ex
from rigidsym.course.exam import asked
from rigidsym.course.exam_text import box_label


@pytest.mark.parametrize("ex_id", [pytest.param("ex3.12", marks=pytest.mark.slow),
                                   "ex3.14"])
def test_a_box_labelled_ascending_holds_ascending_values(ex_id):
    s = ex.solve(ex_id)
    labelled = [a for a in asked(s) if "ascending" in box_label(ex_id, a)]
    assert labelled, ex_id
    for a in labelled:
        v = np.array([float(sp.N(x, 17)) for x in sp.Matrix(s.answers[a])])
        assert v.size > 1 and np.all(np.diff(v) >= 0), (a, v)


def test_315_moments_normal_to_d_in_the_labelled_order():
    s = ex.solve("ex3.15")
    label = box_label("ex3.15", "moments_normal_to_d")
    assert label.index("I_2") < label.index("I_3")
    first, second = sp.Matrix(s.answers["moments_normal_to_d"])
    names = {str(x) for x in first.free_symbols}, {str(x) for x in second.free_symbols}
    assert "I_2" in names[0] and "I_3" not in names[0]
    assert "I_3" in names[1] and "I_2" not in names[1]
