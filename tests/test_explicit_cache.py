"""explicit()'s cache within one check never returns a value made under another model: a
model dict freed and its id taken by the next one (CPython's free list) must not hit."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.deciding.explicit import EXPLICIT_CACHE, explicit


def test_a_freed_model_s_id_taken_by_another_model_is_no_hit():
    C = sp.MatrixSymbol("C", 2, 2)
    x = C[0, 1] + 1                          # an entry of a model's matrix
    EXPLICIT_CACHE.clear()
    try:
        for k in range(50):
            explicit(x, {C: sp.ImmutableMatrix([[0, k], [0, 0]])})   # this model is freed
            model = {C: sp.ImmutableMatrix([[0, k + 1000], [0, 0]])}  # often the same id
            assert explicit(x, model) == k + 1001
            assert explicit(x, {}) == x                # no model: the entry as written
    finally:
        EXPLICIT_CACHE.clear()
