"""A printed relation that holds by definition: beside the other relations of a verified id,
one whose two sides the certificate writes as one expression, or as constants only
(:func:`certcheck.check.is_vacuous`: 3.116's ``(Γ s_w)^T s_t ≡ s_w^T Γ^T s_t``, 3.121's
``U^T V`` and the product of its blocks, 3.129's ``∫ρ dB = m``, 3.130's ``I_C`` under the
brace, 3.136's ``ṁ = m c̈``). It derives nothing, so it is never evidence of the id
(:mod:`certcheck.check` requires another relation that is not vacuous); but where the
second reader read both its printed sides firmly (:func:`certcheck.compare.compare`: each
side, read from the page under the symbol table, is the certificate's side as a rational
function, neither through an equation of the page nor under one of several models), the
page's two sides are one rational function as read, so the printed relation is read on
every side and classified an identity by definition. Where a side is not read firmly, its
two sides count as not read: the relation is the certificate's word.
"""

from __future__ import annotations

from certcheck.check import CheckError, Statement, is_vacuous

__all__ = ["page_class", "unread_vacuous"]


def unread_vacuous(cert: dict, firm: list[dict]) -> tuple[int, list[str]]:
    """The vacuous printed relations of a verified ``cert`` not read firmly on both sides,
    and a line for each one that is (an identity by definition, not evidence).

    Args:
        cert: the certificate (its ``relations`` the dicts ``firm`` holds).
        firm: the relations :func:`certcheck.compare.compare` read firmly on both sides
            (the third member of its ``counts``), compared by identity.

    Returns:
        ``(n, lines)``: ``n`` such relations, each two printed sides not read.

    Raises:
        certcheck.check.CheckError: the certificate is outside the grammar.
    """
    if cert.get("verdict") != "verified":
        return 0, []
    st = Statement(cert)
    vacuous = [r for r in st.rels if r[0].get("role") == "printed" and is_vacuous(r, st)]
    read = [r for r in vacuous if any(f is r[0] for f in firm)]
    return len(vacuous) - len(read), [
        f"{' '.join(filter(None, ('printed', r[0].get('label'))))}: an identity by "
        "definition, both sides read from the page (one rational function as read); not "
        "evidence of the id"
        for r in read]


def page_class(cert: dict, verdict: str, read_sides: list) -> list[str]:
    """Whether the page's relations, as read, derive something: a verified id whose printed
    relations, each read firmly from the page, are constants only there (3.30's determinant
    of a unit triangular matrix) is a restatement, and a restatement must be one on the page.
    (Two sides the reader expands to one text are not taken for a restatement: it reads
    through the page's definitions, 3.76b's both sides among them.) The certificate's sides
    may be written otherwise (``(1) + (a - a)``); the page's decide.

    Args:
        cert: the certificate.
        verdict: what :func:`certcheck.check.check_certificate` proved of it.
        read_sides: :func:`certcheck.compare.compare`'s ``read_sides``.

    Returns:
        A line for the referee where the page decided (none where a printed relation is not
        read firmly: that relation is then NOT READ, the certificate's word).

    Raises:
        certcheck.check.CheckError: the certificate's class is not the page's.
    """
    printed = [r for r in cert.get("relations", []) if r.get("role") == "printed"]
    if verdict not in ("verified", "restatement") or not printed or \
            len(read_sides) != len(printed):
        return []
    probe = {**cert, "verdict": "verified", "let": [
        *cert.get("let", []), *{n: t for _, _, _, lets in read_sides for n, t in lets}.items()],
        "relations": [{"label": r.get("label", ""), "role": "printed", "lhs": lhs, "rhs": rhs,
                       "evidence": {"type": "identity"}} for r, lhs, rhs, _ in read_sides]}
    st = Statement(probe)  # constants only: the reader may expand both sides to one text
    restated = all(is_vacuous(rel, st, same=False) for rel in st.rels)
    if restated != (verdict == "restatement"):
        raise CheckError(f"({cert.get('id')}) the certificate says {verdict}, but the page's "
                         "relations as read " + ("are constants only: a restatement"
                                                 if restated else
                                                 "derive something: not a restatement"))
    return [f"class decided from the page: {'a restatement' if restated else 'derives something'}"
            " (the printed relations as read)"]
