"""Symbol-table lines of section 3.2's displacement, line and pose: how certcheck's
second reader binds the glyphs sections 3.2-3.2.3 define in words, by a later display or by
the id's own definition, each line in the book's glyphs for a referee to hold against the
page (read firmly: a side that differs is a rejection).

The project's models (``derivations/sec3_2*.py``):

- section 3.2 (``split_model``): the displacement ``x' = Q x + c``; ``d_A``, ``d_P`` as
  printed in (3.3) (3.3's own left sides); ``d_par``, ``d_perp``, the parts of ``d_P`` along
  and normal to the axis ``e`` as printed in (3.6b) (read in (3.6a), printed before them,
  and in (3.6b) itself), and (3.6b)'s bold ``d_0 = d_0 e``;
- section 3.2.1 (``screw_displacement_model``): bold ``d_0``, the displacement of ``P_0``
  ("the displacement d_0 of P_0", the words before (3.9a)): ``Q p_0 + c - p_0``; ``A``,
  ``b`` as printed in (3.11) (read in (3.10), printed before them, and as (3.11)'s own left
  sides); (3.15)'s ``alpha``, ``beta`` as the model derives them from ``A^T A`` (the
  coefficients of (3.14): with ``A^T A = m 1 + k e e^T``, ``alpha = 1 / m``, ``alpha + beta
  = 1 / (m + k)``, ``m`` and ``m + k`` taken from the trace and ``e^T A^T A e``);
- section 3.2.2 (``line_model``, ``transfer_model``): ``||p_2 - p_1||`` the model's length
  ``ell`` (``p_2 = p_1 + ell u``, ``u`` unit: no square root), and the arrays and moments
  as printed where an id defines them (``gamma_L``, ``e``, ``n``, ``kappa``, ``n_A``,
  ``n_B``, ``kappa_A``, ``kappa_B``, ``kappa_inf``); ``U`` as printed in (3.29b) (read in
  (3.29a), printed before it) with ``B`` the cross-product matrix of ``b``;
- section 3.2.3 (``invariants_model``, ``triad_model``): ``q``, ``q_0`` the
  Euler-Rodrigues parameters (the invariants the model takes: the page's first example
  below (3.34)), the pose ``s`` as printed in (3.34) ((3.35)'s two relations, the
  Euler-Rodrigues parameters and the linear invariants, carry their own ``q``, ``q_0``,
  each as its case's display prints it: ``invariant_rate_symbols.member_symbols``); the
  vector from ``A`` to the body point ``P_k = A + (column k of R)`` (the triad of (3.37),
  orthonormal and right-handed) and the displaced triad ``e'_k = p'_k - a' = Q (p_k -
  a)``; (3.39)'s ``q_ij``, the entries of ``Q`` in the triad's frame, ``R^T Q R`` (change
  of basis), with the range ``i, j = 1, 2, 3`` the page states in words (the line of
  ``q_11`` carries ``"family": "ij"``: certcheck reads the relation for each i, j), and
  (3.40)'s ``[Q]``, that matrix ``R^T Q R`` (the frame the words before (3.39) name).

Each line is given only where the id prints the glyph (and the table has the glyphs its
LaTeX names), so the other ids keep reading through the page's own definitions.
"""

from __future__ import annotations

import re

__all__ = ["DISPLACEMENT_GLYPHS", "displacement_symbols"]

_ONE_E = r"(\mathbf{1} - \mathbf{e}\mathbf{e}^T)"
_ATA = r"\mathbf{e}^T\mathbf{A}^T\mathbf{A}\mathbf{e}"
_A = r"\begin{bmatrix} \mathbf{Q} - \mathbf{1} \\ \mathbf{e}^T \end{bmatrix}"
_B = (r"\begin{bmatrix} (\mathbf{Q} - \mathbf{1})\mathbf{a} - " + _ONE_E + r"\mathbf{d}_A "
      r"\\ 0 \end{bmatrix}")
_D21 = r"\mathbf{p}_2 - \mathbf{p}_1"
_NORM = r"\|\mathbf{p}_2 - \mathbf{p}_1\|"
_UNIT = {k: [str(int(j == k)) for j in (1, 2, 3)] for k in (1, 2, 3)}
_COL = {k: r"\mathbf{R}\begin{bmatrix} " + r" \\ ".join(_UNIT[k]) + r" \end{bmatrix}"
        for k in (1, 2, 3)}
_QF = r"\mathbf{R}^T\mathbf{Q}\mathbf{R}"  # Q in the triad's frame (change of basis)
_TRIAD = "orthonormal and right-handed"

#: (section, glyph, LaTeX in the table's glyphs, the model's words, the glyphs the table
#: must give, the texts (spaces removed) of which one must begin a printed relation of the
#: id)
_LINES = (
    ("3.2", r"\mathbf{d}_A", r"\mathbf{a}' - \mathbf{a}", "displacement of A as printed in "
     "(3.3), x' = Q x + c", (r"\mathbf{a}'",), r"\mathbf{d}_A\equiv"),
    ("3.2", r"\mathbf{d}_P", r"\mathbf{p}' - \mathbf{p}", "displacement of P as printed in "
     "(3.3), x' = Q x + c", (r"\mathbf{p}'",), r"\mathbf{d}_P\equiv"),
    ("3.2", r"\mathbf{d}_{\parallel}", r"\mathbf{e}\mathbf{e}^T\mathbf{d}_P", "part of d_P "
     "parallel to the axis e (the words before (3.6a)), as printed in (3.6b)",
     (r"\mathbf{p}'",), (r"\mathbf{d}_P=\mathbf{d}_{\parallel}", r"\mathbf{d}_{\parallel}=")),
    ("3.2", r"\mathbf{d}_{\perp}", _ONE_E + r"\mathbf{d}_P", "part of d_P normal to the axis "
     "e (the words before (3.6a)), as printed in (3.6b)", (r"\mathbf{p}'",),
     (r"\mathbf{d}_P=\mathbf{d}_{\parallel}", r"\mathbf{d}_{\perp}=")),
    ("3.2", r"\mathbf{d}_0", r"d_0\mathbf{e}", "displacement along the axis as printed in "
     "(3.6b)", ("d_0",), r"\mathbf{d}_{\parallel}="),
    ("3.2.1", r"\mathbf{d}_0", r"\mathbf{Q}\mathbf{p}_0 + \mathbf{c} - \mathbf{p}_0",
     "displacement of P_0 (the words before (3.9a)), p_0' - p_0 with x' = Q x + c",
     (r"\mathbf{p}_0", r"\mathbf{c}"), r"\mathbf{d}_0="),
    ("3.2.1", r"\mathbf{A}", _A, "4 x 3 matrix A as printed in (3.11)", (r"\mathbf{Q}",),
     (r"\mathbf{A}\mathbf{p}_0=\mathbf{b}", r"\mathbf{A}\equiv", r"\alpha=\frac")),
    ("3.2.1", r"\mathbf{b}", _B, "4-vector b as printed in (3.11)", (r"\mathbf{a}'",),
     (r"\mathbf{A}\mathbf{p}_0=\mathbf{b}", r"\mathbf{b}\equiv")),
    ("3.2.1", r"\alpha", r"\frac{2}{\mathrm{tr}(\mathbf{A}^T\mathbf{A}) - " + _ATA + "}",
     "coefficient of 1 in (A^T A)^{-1} = alpha 1 + beta e e^T (3.14), derived from A^T A = "
     "m 1 + k e e^T: alpha = 1/m, m = (tr(A^T A) - e^T A^T A e)/2", (r"\mathbf{Q}",),
     r"\alpha=\frac"),
    ("3.2.1", r"\beta", r"\frac{1}{" + _ATA + r"} - \alpha", "coefficient of e e^T in (A^T "
     "A)^{-1} = alpha 1 + beta e e^T (3.14), derived from A^T A = m 1 + k e e^T: alpha + "
     "beta = 1/(m + k) = 1/(e^T A^T A e)", (r"\mathbf{Q}",), r"\beta=\frac"),
    ("3.2.2", _NORM, r"\ell", "distance ell from P_1 to P_2 (p_2 = p_1 + ell u, u unit), "
     "||p_2 - p_1|| without a square root", (r"\mathbf{p}_2", r"\ell"),
     (r"\mathbf{e}\equiv", r"\boldsymbol{\kappa}=\begin")),
    ("3.2.2", r"\boldsymbol{\gamma}_{\mathcal{L}}", r"\begin{bmatrix} " + _D21 + r" \\ "
     r"\mathbf{p}_1 \times (" + _D21 + r") \end{bmatrix}", "Plücker coordinates of the line "
     "through P_1 and P_2 as printed in (3.21)", (r"\mathbf{p}_2",),
     r"\boldsymbol{\gamma}_{\mathcal{L}}\equiv"),
    ("3.2.2", r"\mathbf{e}", r"\frac{" + _D21 + "}{" + _NORM + "}", "the line's unit "
     "direction as printed in (3.22)", (r"\mathbf{p}_2", r"\ell"), r"\mathbf{e}\equiv"),
    ("3.2.2", r"\mathbf{n}", r"\mathbf{p}_1 \times \mathbf{e}", "the line's moment as "
     "printed in (3.22)", (r"\mathbf{p}_2", r"\ell"), r"\mathbf{n}\equiv"),
    ("3.2.2", r"\boldsymbol{\kappa}", r"\begin{bmatrix} \mathbf{e} \\ \mathbf{n} "
     r"\end{bmatrix}", "Plücker array as printed in (3.23)", (r"\mathbf{p}_2", r"\ell"),
     r"\boldsymbol{\kappa}=\begin"),
    ("3.2.2", r"\mathbf{n}_A", r"(\mathbf{p} - \mathbf{a}) \times \mathbf{e}", "moment of "
     "the line about A as printed in (3.25)", (r"\mathbf{p}", r"\mathbf{a}", r"\mathbf{e}"),
     r"\mathbf{n}_A\equiv"),
    ("3.2.2", r"\mathbf{n}_B", r"(\mathbf{p} - \mathbf{b}) \times \mathbf{e}", "moment of "
     "the line about B as printed in (3.25)", (r"\mathbf{p}", r"\mathbf{b}", r"\mathbf{e}"),
     r"\mathbf{n}_B\equiv"),
    ("3.2.2", r"\kappa_A", r"\begin{bmatrix} \mathbf{e} \\ \mathbf{n}_A \end{bmatrix}",
     "Plücker array at A as printed in (3.26)", (r"\mathbf{e}",), r"\kappa_A\equiv"),
    ("3.2.2", r"\kappa_B", r"\begin{bmatrix} \mathbf{e} \\ \mathbf{n}_B \end{bmatrix}",
     "Plücker array at B as printed in (3.26)", (r"\mathbf{e}",), r"\kappa_B\equiv"),
    ("3.2.2", r"\mathbf{U}", r"\begin{bmatrix} \mathbf{1} & \mathbf{O} \\ \mathbf{A} - "
     r"\mathbf{B} & \mathbf{1} \end{bmatrix}", "Plücker transfer matrix as printed in "
     "(3.29b)", (r"\mathbf{a}", r"\mathbf{b}"), (r"\kappa_B=\mathbf{U}", r"\mathbf{U}\equiv")),
    ("3.2.2", r"\boldsymbol{\kappa}_\infty", r"\begin{bmatrix} \mathbf{0} \\ \mathbf{f} "
     r"\end{bmatrix}", "Plücker array of a line at infinity as printed in (3.33)",
     (r"\mathbf{f}",), r"\boldsymbol{\kappa}_\infty="),
    ("3.2.3", r"\mathbf{q}", r"\sin(\frac{\phi}{2})\mathbf{e}", "Euler-Rodrigues "
     "parameters' vector, the invariants the model takes (the page's first example below "
     "(3.34))", (r"\mathbf{e}", r"\phi"), r"\mathbf{s}\equiv"),
    ("3.2.3", "q_0", r"\cos(\frac{\phi}{2})", "Euler-Rodrigues parameters' scalar, the "
     "invariants the model takes (the page's first example below (3.34))",
     (r"\mathbf{e}", r"\phi"), r"\mathbf{s}\equiv"),
    ("3.2.3", r"\mathbf{s}", r"\begin{bmatrix} \mathbf{q} \\ q_0 \\ \mathbf{d}_A "
     r"\end{bmatrix}", "pose array as printed in (3.34)", (r"\mathbf{a}'",),
     r"\mathbf{s}\equiv"),
    *(("3.2.3", rf"\overrightarrow{{AP_{k}}}", _COL[k], f"vector from A to the body point "
       f"P_{k} = A + (column {k} of the rotation R: the triad {_TRIAD})", (r"\mathbf{R}",),
       (r"\mathbf{e}_1\equiv\overrightarrow", r"[\mathbf{Q}]=")) for k in (1, 2, 3)),
    *(("3.2.3", rf"\mathbf{{e}}_{k}", _COL[k], f"column {k} of the rotation R (the triad "
       f"e_1, e_2, e_3 {_TRIAD})", (r"\mathbf{R}",), r"\mathbf{e}_1\equiv\overrightarrow")
      for k in (1, 2, 3)),
    *(("3.2.3", rf"\mathbf{{e}}'_{k}", rf"\mathbf{{Q}}\mathbf{{e}}_{k}", f"triad in the "
       f"displaced configuration, e'_{k} = p'_{k} - a' = Q (p_{k} - a) with x' = Q x + c",
       (r"\mathbf{Q}", r"\mathbf{R}"), (r"[\mathbf{Q}]=", "q_{ij}=")) for k in (1, 2, 3)),
    *(("3.2.3", f"q_{{{k}{m}}}", r"\begin{bmatrix} " + " & ".join(_UNIT[k]) + r" \end{bmatrix}"
       + _QF + r"\begin{bmatrix} " + r" \\ ".join(_UNIT[m]) + r" \end{bmatrix}", f"entry {k}, "
       f"{m} of [Q] = R^T Q R, the matrix of Q in the frame X, Y, Z of axes parallel to e_1, "
       "e_2, e_3 (the columns of R; change of basis), its entries q_ij, i, j = 1, 2, 3 (the "
       "words before (3.39))", (r"\mathbf{Q}", r"\mathbf{R}"), "q_{ij}=")
      for k in (1, 2, 3) for m in (1, 2, 3)),
    ("3.2.3", r"[\mathbf{Q}]", r"\mathbf{R}^T\mathbf{Q}\mathbf{R}", "the matrix of Q in the "
     "frame X, Y, Z of axes parallel to e_1, e_2, e_3 (the columns of R; change of basis), "
     "its entries (3.39)'s q_ij (the words before (3.39))", (r"\mathbf{Q}", r"\mathbf{R}"),
     r"[\mathbf{Q}]="),
)
#: the glyphs of the lines, in order (a glyph may have a line in more than one section)
DISPLACEMENT_GLYPHS = tuple(dict.fromkeys(g for _, g, _, _, _, _ in _LINES))


def displacement_symbols(have: set, section: str, latex: str) -> list[dict]:
    """The lines of section 3.2's displacement, lines and pose for one id's table.

    Args:
        have: the glyphs the table already gives (atoms' glyphs and the model lines of
            :func:`rigidsym.checking.certifying.certificates.model_symbols`).
        section: the id's section (``3.2``, ``3.2.1``, ``3.2.2`` or ``3.2.3``; others get
            none).
        latex: the id's printed LaTeX: a line is given only where it prints the glyph (its
            own definition, or a glyph the page defines later or in words).

    Returns:
        Entries ``{"glyph", "latex", "model"}`` (and ``{"glyph": "\\mathbf{B}", "cpm_of":
        "\\mathbf{b}"}`` beside ``U``; ``q_11``'s with ``"family": "ij"``, the range of
        (3.39) the page states in words), only for glyphs the table lacks and whose needed
        glyphs it has; ``[]`` elsewhere.
    """
    starts = re.split(r",\\quad", latex.replace(" ", ""))  # the printed relations
    have = set(have)
    out: list[dict] = []
    for sec, glyph, tex, words, needs, where in _LINES:
        if sec != section or glyph in have or not set(needs) <= have or \
                not any(s.startswith(where) for s in starts):
            continue
        if glyph == "\\mathbf{U}" and "\\mathbf{B}" not in have:
            out.append({"glyph": "\\mathbf{B}", "cpm_of": "\\mathbf{b}"})
        out.append({"glyph": glyph, "latex": tex, "model": words})
        if glyph == "q_{11}":  # the page's family in words: certcheck reads it for each i, j
            out[-1]["family"] = "ij"
        have.add(glyph)
    return out
