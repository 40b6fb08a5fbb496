"""An unsquared norm read from the page: ``||x||`` is the square root of ``x^T x``, and
certcheck decides a relation holding one square root in K(s), ``s^2 = d`` (an entry zero
when both its parts are, so never a false identity). (3.52)'s ``v_0 = v_0 omega /
||omega||`` (the scalar v_0 the signed magnitude, the page's words), (3.55)'s ``e' =
omega / ||omega||``, ``n' = p x e'`` read on every side; a side doubled or negated, or a
line of the table changed, is rejected naming the id."""

from __future__ import annotations

import copy

from test_cert_page import page_outcome
from test_cert_page_momenta import certificates, line_changed


def _side(c: dict, k: int, new) -> dict:
    t = copy.deepcopy(c)
    rel = [r for r in t["relations"] if r["role"] == "printed"][k]
    rel["rhs"] = [[new(x) for x in row] for row in rel["rhs"]]
    return t


def test_unsquared_norms_read_and_tamperings_rejected(book):
    certs = certificates(["3.52", "3.55"])
    for i, c in certs.items():
        assert page_outcome(c, book) == "read", i
        n = len([r for r in c["relations"] if r["role"] == "printed"])
        cases = [_side(c, k, f) for k in range(n) for f in (lambda x: f"2*({x})",
                                                            lambda x: f"-({x})")]
        cases += [line_changed(c, "v_0", "\\frac{\\mathbf{v}_0", "-\\frac{\\mathbf{v}_0"),
                  line_changed(c, "v_0", "{\\|\\boldsymbol{\\omega}\\|}",
                               "{\\|\\boldsymbol{\\omega}\\|^2}"),
                  line_changed(c, "\\mathbf{e}'", "{\\|", "{2\\|")]
        for t in filter(None, cases):
            assert page_outcome(t, book).startswith(f"rejected: ({i})"), i
