"""The two test profiles: one set of properties, two budgets.

- ``quick`` (the default; the README's test command): each property at its quick budget;
  a family marked ``sample`` runs on a seeded sample of its parameters, the rest of the
  family is marked ``slow``.
- ``thorough`` (``RIGIDSYM_TEST_PROFILE=thorough``; the second part of ``.ci/run``, which
  selects ``-m "slow or extra or budget"``): the rest of every sampled family (through its
  ``slow`` mark), and every Hypothesis property again: a quick one at
  :data:`THOROUGH_FACTOR` times its quick budget (``max_examples=examples(n)``), a ``slow``
  one at the budget it writes as a number. The costliest slow families and loops run a
  seeded share (:func:`share`, the ``thorough`` mark) drawn with
  ``RIGIDSYM_THOROUGH_SEED``, which ``.ci/run`` sets from the commit: each commit runs
  another share, so that every member runs over a few commits, and a failure reproduces
  with the seed the run printed.
- ``exhaustive`` (``RIGIDSYM_TEST_PROFILE=exhaustive``, same selection as ``thorough``):
  every member of every share; a release's check.

Both profiles draw the same Hypothesis examples every run; ``--hypothesis-profile=search``
draws new ones (tests/conftest.py).

The sample is the same in every process (xdist workers must collect the same items): a
parameter is in it when the CRC-32 of its node id and the seed ``RIGIDSYM_TEST_SEED``
(default 0) is among the smallest of its family. Another seed draws another sample.
"""

from __future__ import annotations

import math
import os
import re
import zlib

#: ``quick`` or ``thorough``
PROFILE = os.environ.get("RIGIDSYM_TEST_PROFILE", "quick")
if PROFILE not in ("quick", "thorough", "exhaustive"):
    raise ValueError("RIGIDSYM_TEST_PROFILE: expected 'quick', 'thorough' or 'exhaustive', "
                     f"got {PROFILE!r}")
#: the seed of the sampled families' draw
SEED = int(os.environ.get("RIGIDSYM_TEST_SEED", "0"))
#: the seed of the thorough run's shares (:func:`share`)
THOROUGH_SEED = int(os.environ.get("RIGIDSYM_THOROUGH_SEED", "0"))
#: the thorough run's Hypothesis budget, in quick budgets
THOROUGH_FACTOR = 3
#: the share of a sampled family the quick run keeps, when its mark names none
DEFAULT_FRACTION = 0.25


def examples(n: int) -> int:
    """A Hypothesis property's ``max_examples``: ``n`` in the quick profile,
    :data:`THOROUGH_FACTOR` times ``n`` in the thorough one."""
    return n if PROFILE == "quick" else THOROUGH_FACTOR * n


def plain(nodeid: str) -> str:
    """The node id without the ``@group`` suffix that ``--dist loadgroup`` appends."""
    return re.sub(r"@[^\[\]@]*$", "", nodeid)


def rank(nodeid: str) -> int:
    """The draw's key of one parameter: CRC-32 of the seed and the node id."""
    return zlib.crc32(f"{SEED}:{nodeid}".encode())


def _smallest(keys: list[str], fraction: float, seed: int) -> list[int]:
    """The indices, in order, of the ``ceil(fraction * n)`` keys (at least one) of smallest
    CRC-32 of ``seed`` and the key: the one draw of both profiles' shares."""
    if not 0 < fraction <= 1:
        raise ValueError(f"fraction: expected a number in (0, 1], got {fraction!r}")
    k = max(1, math.ceil(fraction * len(keys)))
    order = sorted(range(len(keys)), key=lambda i: zlib.crc32(f"{seed}:{keys[i]}".encode()))
    return sorted(order[:k])


def kept(nodeids: list[str], fraction: float) -> set[str]:
    """The quick run's share of a family: the ``ceil(fraction * n)`` node ids (at least one)
    of smallest :func:`rank`."""
    return {nodeids[i] for i in _smallest(nodeids, fraction, SEED)}


def fast_or_slow(ids, fast) -> list:
    """A family's parameters: those in ``fast`` in the quick run, the others marked ``slow``
    (a hand-picked quick share, where a seeded sample would miss the one case each book
    needs)."""
    import pytest

    return [pytest.param(i, marks=() if i in fast else pytest.mark.slow) for i in ids]


def share(items, fraction: float, key=str) -> list:
    """The thorough run's share of a costly slow family or loop: every item in the
    ``exhaustive`` profile; else the ``ceil(fraction * n)`` items (at least one) of
    smallest CRC-32 of :data:`THOROUGH_SEED` and ``key(item)``, in their given order.

    Raises:
        ValueError: ``fraction`` outside (0, 1]."""
    items = list(items)
    picked = _smallest([key(x) for x in items], fraction, THOROUGH_SEED)
    return items if PROFILE == "exhaustive" else [items[i] for i in picked]
