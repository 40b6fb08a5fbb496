"""The user's words only: what show, verify and check --latex print, and the errors a user
meets, name no internal module, no private name and no word the glossary lacks ("second
semantics")."""

from __future__ import annotations

import contextlib
import io
import re
import traceback

import pytest

import rigidsym
from rigidsym.cli import main

#: internal words: the numeric reading's old name, private names, dotted module paths of the
#: package (``rigidsym.kernels.runtime.errors``, ``rigidsym.derivations.sec3_4_1``)
INTERNAL = re.compile(r"second semantics|\b_internal|\b_rigidsym|\brigidsym(?:\.[a-z_]+){2,}")


def _run(*argv: str) -> str:
    """``rigidsym ARGV`` in this process: stdout and stderr together."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
        main(list(argv))
    return out.getvalue()


@pytest.mark.parametrize("argv", [
    ("show", "3.59"), ("show", "3.148", "--full"), ("show", "3.13"),
    ("verify", "3.59", "3.148", "3.13", "--jobs", "1"),
    ("check", "--latex", r"\mathbf{e}^T\mathbf{e} = 2", "--let", r"\mathbf{e}: unit vector"),
    ("check", "--latex", r"\det(\mathbf{1} + [\mathbf{a}]_\times) = 1 + \|\mathbf{a}\|^2"),
], ids=lambda a: " ".join(a[:2]))
def test_outputs_name_no_internal_word(argv):
    text = _run(*argv)
    assert text.strip()
    assert not INTERNAL.findall(text), INTERNAL.findall(text)


def test_verify_summary_counts_by_origin():
    """The summary line splits the does-not-hold by origin: (3.148) is an erratum of the
    book, (3.59) attributed to neither (the ids test_show decides too); never "not
    determined"."""
    line = _run("verify", "3.148", "3.59", "--jobs", "1", "--quiet").strip().splitlines()[-1]
    assert "2 do not hold as printed" in line
    assert "1 erratum of the book" in line
    assert "1 not attributed to the book or the conversion" in line
    assert "not determined" not in line


def test_the_count_by_origin_names_each_class():
    """Errata of the book and slips of the text's conversion are counted apart, in words
    (the declared cause of a checked result set to each class in turn)."""
    import dataclasses

    from rigidsym.checking.checker import check
    from rigidsym.report.record import cause_counts, cause_line

    r = check("3.148")
    rows = [dataclasses.replace(r, cause=c) for c in ("erratum", "conversion", "conversion")]
    assert cause_counts(rows) == {"erratum": 1, "conversion": 2, "unattributed": 0}
    assert cause_line(rows) == "1 erratum of the book, 2 slips of the text's conversion"


def test_errors_a_user_meets_are_named_as_imported():
    """A traceback names the public class (``rigidsym.BadInput``,
    ``rigidsym.kernels.SingularConfigurationError``), not the module that defines it."""
    with pytest.raises(rigidsym.BadInput) as exc:
        rigidsym.check("3.0")
    last = traceback.format_exception_only(exc.type, exc.value)[-1]
    assert last.startswith("rigidsym.BadInput: "), last
    from rigidsym import kernels
    for cls in (kernels.SingularConfigurationError, kernels.NonFiniteResultError,
                kernels.BroadcastWarning):
        assert cls.__module__ == "rigidsym.kernels"
        assert getattr(kernels, cls.__name__) is cls


def test_an_exercise_on_the_users_data_names_those_data():
    """Exercise 3.2 on a tetrahedron of the user's that is not regular: the title and the
    assumptions say what the data are (not the book's regular one), and every answer is
    expanded (no product of a sum with a radical left, as sp.expand would leave it)."""
    import sympy as sp
    from rigidsym.derivations.exercises import ex3_02

    s = ex3_02.solve(P_3=[1, 2, 0], P_4=[sp.Rational(1, 2), sp.Rational(1, 3), 2])
    words = " ".join([s.title, *s.assumptions])
    assert "regular tetrahedron" not in words and "Fig. 3.10" not in words
    assert "not regular" in words
    for name in ("P", "n_min", "f", "P_barycentric"):
        for e in sp.Matrix(s.answers[name]):
            assert sp.expand(e) == e, (name, e)
    book = ex3_02.solve()
    assert "regular tetrahedron" in " ".join([book.title, *book.assumptions])
