"""The theorems the page states in words, with no display: a fixed table (part of the
trusted base, read in minutes), each entry an id, the theorem's statement as
:func:`certcheck.book.locate` gives it (spaces collapsed, the italic text after its bold
head), the relation(s) that statement states, in the page's own glyphs, as LaTeX the
second reader parses (:mod:`certcheck.reader`), and why the relation is what the words
say, no stronger, no weaker. An entry is used only where the page's statement of its id is
the entry's, character for character; otherwise the words are not read (NOT READ: fail
closed). The relation is then read under the certificate's symbol table and held to its
printed relation as a display's is (:func:`certcheck.compare.compare`): a sign, a
coefficient, a transpose, a relation dropped or added is a rejection naming the id.
"""

from __future__ import annotations

import re

__all__ = ["WORDS", "stated", "said"]

#: id -> (the statement, the relation(s) it states, why they are what it says)
WORDS = {
    "thm3.2.1": (
        "Let a rigid body $\\mathcal{B}$ move under a general displacement, of rotation "
        "$\\mathbf{Q}$ with axis parallel to the unit vector $\\mathbf{e}$ . Then, the "
        "displacements of all the points of $\\mathcal{B}$ have the same component along "
        "$\\mathbf{e}$ .",
        r"\mathbf{e}^T (\mathbf{p}' - \mathbf{p}) = \mathbf{e}^T (\mathbf{a}' - \mathbf{a})",
        "the displacement of a point X is x' - x (3.3), its component along the unit e is "
        "e^T (x' - x); 'the same for all points' is the same for any two, P and A"),
    "thm3.3.1": (
        "The angular-velocity matrix is skew-symmetric.",
        r"\boldsymbol{\Omega} + \boldsymbol{\Omega}^T = \mathbf{O}",
        "a matrix A is skew-symmetric exactly when A + A^T = O (its definition)"),
    "thm3.4.1": (
        "The relative velocity of two points of the same rigid body is perpendicular to the "
        "line joining them.",
        r"(\dot{\mathbf{p}} - \dot{\mathbf{a}}) \cdot (\mathbf{p} - \mathbf{a}) = 0",
        "the relative velocity of P and A is p-dot - a-dot, the line joining them has the "
        "direction p - a; perpendicular: their dot product is zero (the page's (3.51))"),
    "cor3.4.1": (
        "The projections of the velocities of all the points of a rigid body onto the "
        "angular-velocity vector are identical.",
        r"\boldsymbol{\omega} \cdot \dot{\mathbf{p}} = \boldsymbol{\omega} \cdot \dot{\mathbf{a}}",
        "the projection of v onto omega is (omega . v)/||omega||: identical for any two "
        "points P and A exactly when omega . p-dot = omega . a-dot (the page's display)"),
    "thm3.4.2": (
        "Given a rigid body under general motion, a set of its points located on a line "
        "$\\mathcal{L}'$ undergoes the identical minimum-magnitude velocity $\\mathbf{v}_0$ "
        "parallel to the angular velocity.",
        r"\dot{\mathbf{p}} = \mathbf{v}_0, \quad \boldsymbol{\omega} \times \mathbf{v}_0 = "
        r"\mathbf{0}, \quad \|\dot{\mathbf{a}}\|^2 - \|\mathbf{v}_0\|^2 = "
        r"\|\boldsymbol{\omega} \times (\mathbf{a} - \mathbf{p}'_0)\|^2",
        "p = p'_0 + alpha omega, any point of the line L' (alpha free): its velocity is v_0 "
        "(identical); v_0 is parallel to omega; the velocity a-dot = v_0 + omega x (a - p'_0) "
        "(3.50) of any point A is of magnitude at least ||v_0|| exactly when the cross term "
        "vanishes for every A, i.e. when ||a-dot||^2 - ||v_0||^2 = ||omega x (a - p'_0)||^2"),
    "thm3.7.1": (
        "For a given system of forces and moments acting on a rigid body, if the resultant "
        "force is applied at any point of a particular line $\\mathcal{L}''$ , then the "
        "resultant moment is of minimum magnitude. Moreover, that minimum-magnitude moment "
        "is parallel to the resultant force.",
        r"\|\mathbf{n}_A\|^2 = \|\mathbf{n}_0\|^2 + \|\mathbf{f} \times (\mathbf{a} - "
        r"\mathbf{p})\|^2, \quad \mathbf{f} \times \mathbf{n}_0 = \mathbf{0}",
        "n_0, the moment about a point P of L'', is n_A - f x (a - p) (3.107) for every A: it "
        "is of minimum magnitude exactly when the cross term 2 n_0 . f x (a - p) vanishes for "
        "every A, i.e. when ||n_A||^2 = ||n_0||^2 + ||f x (a - p)||^2; parallel: f x n_0 = 0"),
    "thm3.7.2": (
        "Consider a system of moments and forces acting on a rigid body, with the resultant "
        "force applied at an arbitrary point of the body. The projection of the resultant "
        "moment onto the wrench axis is identical for all points.",
        r"\mathbf{e}'' \cdot \mathbf{n}_P = \mathbf{e}'' \cdot \mathbf{n}_A",
        "the wrench axis has the unit vector e'' = f/||f|| (3.110); the projection of the "
        "moment n_P about P onto it is e'' . n_P, the same for any two points P and A"),
}


def _statement(page: str) -> str | None:
    """The italic statement after the bold head of a theorem's paragraph (None: none)."""
    m = re.fullmatch(r"\*\*[^*]+\*\* \*(.+)\*", page)
    return m[1] if m else None


def stated(eq_id: str, page: str) -> str:
    """The relation(s) the words of ``eq_id`` state, where ``page`` (its text, from
    :func:`certcheck.book.locate`) states exactly the table's statement; else ``page`` (a
    paragraph in words, read as nothing)."""
    entry = WORDS.get(eq_id)
    return entry[1] if entry and _statement(page) == entry[0] else page


def said(eq_id: str, page: str) -> list[str]:
    """The referee's line for the table's entry used (none where none is)."""
    if stated(eq_id, page) == page:
        return []
    return [f"the page's words state: {WORDS[eq_id][1]} (certcheck.words: {WORDS[eq_id][2]})"]
