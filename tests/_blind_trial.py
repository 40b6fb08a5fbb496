"""The blind trials' one rule, shared by their tests (``tests/test_check_latex_blind_*.py``):
no verdict of ``check_latex`` on a statement as typed may be wrong; a refusal or an undecided
answer is not decided, never wrong."""

from __future__ import annotations

import pytest

import rigidsym


def params(cases: list[dict], known_wrong: set[str]) -> list:
    """One pytest param a case, named by its id; the ids of ``known_wrong`` a strict xfail."""
    return [pytest.param(c, id=c["id"], marks=pytest.mark.xfail(strict=True,
                                                              reason="wrong as typed"))
            if c["id"] in known_wrong else pytest.param(c, id=c["id"]) for c in cases]


def assert_not_wrong(case: dict) -> None:
    """The case's verdict as typed is its NumPy truth, or no verdict at all."""
    try:
        r = rigidsym.check_latex(case["latex"], let=case["lets"], notation=case["notation"],
                                 repairs=False, timeout=None)
    except ValueError:
        return  # refused: not decided, never wrong
    if r.verdict == "undecided":
        return
    said = r.verdict in ("verified", "definition")
    assert said is case["truth"], (r.verdict, r.model)
