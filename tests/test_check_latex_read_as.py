"""``read as:`` printed with every parenthesis its reading needs: the line a reader checks the
reading against is the expression decided, so an operand that binds looser than its operator
(a sum under a fraction bar, a sum raised to a power, a sum times a matrix) is printed inside
parentheses. The property is checked structurally on the printer's own tree: every sum among
the operands of a product, quotient, power, transpose or inverse appears in its parent's
text only as a parenthesised group."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
import sympy as sp

from rigidsym.latex.lets import read_lets
from rigidsym.latex.notations import NOTATIONS, notation
from rigidsym.latex.statement import read_statement
from rigidsym.printing.notation import BookStrPrinter
from rigidsym.registry import declarations as registry

CORPUS = Path(__file__).resolve().parent / "data" / "latex_corpus"
sys.path.insert(0, str(CORPUS))

import corpus  # noqa: E402

NORM = [r"\theta = \|\boldsymbol\theta\|", r"\boldsymbol\theta(t): vector"]
RATE = r"\dot\theta = \frac{\boldsymbol\theta^T\dot{\boldsymbol\theta}}{\theta}"


@pytest.fixture(autouse=True)
def forget_latex_ids():
    yield
    registry.forget_module("rigidsym.latex.statement")


class _Recording(BookStrPrinter):
    """The book printer, each node's text kept beside the node."""

    def __init__(self):
        super().__init__()
        self.seen: list[tuple[object, str]] = []

    def _print(self, expr, **kwargs):
        out = super()._print(expr, **kwargs)
        self.seen.append((expr, out))
        return out


def _sum_in(x):
    """The sum that ``x`` is (an Add, a MatAdd, or a 1 x 1 trace of a MatAdd, which the
    printers write as the scalar it is), else ``None``."""
    if isinstance(x, sp.Add | sp.MatAdd):
        return x
    if isinstance(x, sp.Trace) and tuple(x.arg.shape) == (1, 1) \
            and isinstance(x.arg, sp.MatAdd):
        return x.arg
    return None


def _operands(node) -> list:
    if isinstance(node, sp.Mul | sp.MatMul):
        return list(node.args) + [a.base for a in node.args
                                  if isinstance(a, sp.Pow) and a.exp.is_negative]
    if isinstance(node, sp.Pow | sp.MatPow | sp.Transpose | sp.Inverse):
        return [node.args[0]]
    return []


def unbracketed_sums(expr, printer=_Recording) -> list[str]:
    """Each ``parent text: sum text`` where a sum operand of a product, quotient, power,
    transpose or inverse is printed in its parent's text outside parentheses."""
    pr = printer()
    pr.doprint(expr)
    texts: dict = {}
    for node, text in pr.seen:
        texts.setdefault(node, text)
    bad = []
    for node, text in pr.seen:
        for op in _operands(node):
            s = _sum_in(op)
            if s is None or s not in texts:
                continue
            st = texts[s]
            if text.count(st) != text.count(f"({st})"):
                bad.append(f"{text}: {st}")
    return bad


def _sides(r) -> list:
    return [x for rel in r.statement.printed for x in (rel.lhs, rel.rhs)]


def test_the_rate_of_the_norm_reads_with_the_sum_over_the_fraction_in_parentheses():
    r = read_statement(RATE, read_lets(NORM))
    # the chain rule's (θ̇·θ + θ·θ̇)/(2 √(θ·θ)): the whole sum over the bar, as decided
    left = r.text.split(" = ")[0]
    assert left.startswith("((") and left.endswith("))/(2 √(θ·θ))"), r.text
    assert not unbracketed_sums(r.statement.printed[0].lhs)


def test_the_property_finds_a_sum_printed_bare_under_a_bar():
    # the check itself: a printer that drops a sum's parentheses is caught
    a, b, c = sp.symbols("a b c")

    class Bare(_Recording):
        def parenthesize(self, item, level, strict=False):
            return self._print(item)

    assert unbracketed_sums((a + b) / c, Bare) == ["a + b/c: a + b"]
    assert unbracketed_sums(sp.Mul(2, a + b, evaluate=False) ** 2, Bare)
    assert unbracketed_sums((a + b) / c) == []  # the book printer keeps them


def _entries(quick: bool) -> list[dict]:
    es = corpus.entries()
    return es[::12] if quick else es


@pytest.mark.parametrize("quick", [pytest.param(True, id="quick"),
                                   pytest.param(False, id="all", marks=pytest.mark.slow)])
def test_every_sum_operand_of_a_corpus_reading_is_printed_in_parentheses(quick):
    # a sample of the corpus (every 12th entry quick, all in the thorough run), each read
    # with its book's table and notation as the corpus test reads it
    read, bad = 0, []
    for e in _entries(quick):
        book = e["book"]["key"]
        table = notation(book) if book in NOTATIONS else None
        try:
            r = read_statement(e["latex"], read_lets(corpus.lets_of(e)), None, {}, table)
        except ValueError:
            continue  # an entry the reader refuses (the corpus test judges those)
        read += 1
        bad += [f"{e['id']}: {b}" for x in _sides(r) for b in unbracketed_sums(x)]
    assert read >= (10 if quick else 150), read
    assert not bad, bad
