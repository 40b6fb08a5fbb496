"""Symbol-table lines of section 3.8's body of point masses: how certcheck's
second reader binds the book's integral sign, mass, centroid and inertia dyad to a
certificate's atoms, each line in the book's glyphs for a referee to hold against the page.

The project's model of a rigid body in section 3.8 (``derivations/sec3_8.py``) is four point
masses ``m_i`` at ``p_i = o + Q rho_i`` with body coordinates ``rho_i = m_4 s_i`` (``i <
4``) and ``rho_4 = -(m_1 s_1 + m_2 s_2 + m_3 s_3)``; the book's integral ``\\int_B rho f
dB`` over it is the sum of ``m_i f(p_i)``. The line of the integral sign lists the
particles, each a small table of its own glyphs (its mass as ``\\rho``, its position as
``\\mathbf{p}`` and, for a moving body (the table gives ``\\dot{\\mathbf{Q}}`` or
``\\dot{\\mathbf{o}}``), their rates); certcheck reads an integrand once per particle under
it. A moving body's integrals cost certcheck under 2 s of CPU per id without python-flint
since its field cancels a denominator's factors as soon as they divide (they took
20-40 s before, and a moving body had no line).
Where the certificate's relation is free of ``o`` but has ``Q`` and the body's shape (the
inertia dyad (3.138), unchanged by a translation), each particle binds ``\\mathbf{r}``, its
position from the centre of mass, ``r_i = p_i - c = Q rho_i`` (the model's C is at ``o``).
Every other line cites the page: ``m`` as printed in (3.123), ``I_C`` as printed under the
brace of (3.130), ``c``'s rates from (3.124)-(3.125) with ``m`` constant; ``r``, ``q_O``,
``c``, ``T``, ``I_A`` the reader takes from their printed definitions (``\\equiv``).
"""

from __future__ import annotations

__all__ = ["point_body_symbols"]

#: the model's words on the integral sign, printed by certcheck beside the page
BODY_WORDS = ("body of four point masses m_i at p_i = o + Q rho_i (Q = 1 at rest; moving, "
              "their rates o' + Q' rho_i and o'' + Q'' rho_i), rho_i = m_4 s_i (i < 4), "
              "rho_4 = -(m_1 s_1 + m_2 s_2 + m_3 s_3): the integral of rho f over B is the "
              "sum of m_i f(p_i)")

_IC = (r"\int_{\mathcal{B}} \rho (\|\mathbf{r}\|^2 \mathbf{1} - \mathbf{r}\mathbf{r}^T) "
       r"d\mathcal{B}")


def _masses(have: set) -> list[str] | None:
    """The four masses in the table's glyphs (``m_i``, or ``1 + mu_i^2`` where the model
    writes them positive), or ``None`` when the table has no point-mass body."""
    out = []
    for i in range(1, 5):
        if f"m_{i}" in have:
            out.append(f"m_{i}")
        elif f"\\mu_{i}" in have:
            out.append(f"(1 + \\mu_{i}^2)")
        else:
            return None
    return out


def point_body_symbols(have: set, section: str) -> list[dict]:
    """The lines of section 3.8's point-mass body for a table whose glyphs are ``have``.

    Args:
        have: the glyphs the table already gives (atoms' glyphs and model lines).
        section: the id's section; only ``3.8`` has the body.

    Returns:
        Entries ``{"glyph": "\\int_{\\mathcal{B}}", "model", "particles"}`` (each particle
        ``{glyph: LaTeX}``), and ``{"glyph", "latex", "model"}`` or ``{"glyph",
        "cpm_of"}`` for ``m``, the generic body point ``p`` and its rate, ``c``'s rates,
        ``omega``, ``Omega``, ``R``, ``C``, ``I_C`` where the table lacks them; where the
        table has ``Q`` and the ``s_i`` but no ``o`` (the relation free of the translation),
        the particles' ``r_i = Q rho_i`` (C at o), ``m`` and ``I_C``; ``[]`` where the
        table has no point-mass body.
    """
    ms = _masses(have)
    if not section.startswith("3.8") or ms is None:
        return []
    shape = {"\\mathbf{s}_1", "\\mathbf{s}_2", "\\mathbf{s}_3"} <= have
    rho = [f"{ms[3]}\\mathbf{{s}}_{i}" for i in (1, 2, 3)]
    rho.append("-(" + " + ".join(f"{ms[i]}\\mathbf{{s}}_{i + 1}" for i in range(3)) + ")")
    if shape and "\\mathbf{o}" not in have and "\\mathbf{Q}" in have:  # r_i free of o
        return [e for e in (
            {"glyph": "\\int_{\\mathcal{B}}", "model": BODY_WORDS + "; C is at o, so r_i = "
             "p_i - c = Q rho_i", "particles": [{"\\rho": m, "\\mathbf{r}": f"\\mathbf{{Q}}({x})"}
                                                for m, x in zip(ms, rho, strict=True)]},
            {"glyph": "m", "latex": r"\int_{\mathcal{B}} \rho d\mathcal{B}",
             "model": "mass as printed in (3.123)"},
            {"glyph": r"\mathbf{I}_C", "latex": _IC,
             "model": "I_C as printed under the brace of (3.130)"}) if e["glyph"] not in have]
    if not shape or "\\mathbf{o}" not in have:
        return [{"glyph": "\\int_{\\mathcal{B}}", "model": "body of four point masses m_i: "
                 "the integral of rho over B is the sum of the m_i",
                 "particles": [{"\\rho": m} for m in ms]},
                {"glyph": "m", "latex": r"\int_{\mathcal{B}} \rho d\mathcal{B}",
                 "model": "mass as printed in (3.123)"}][:1 + ("m" not in have)]
    moving = bool({"\\dot{\\mathbf{Q}}", "\\dot{\\mathbf{o}}"} & have)
    parts = []
    for m, x in zip(ms, rho, strict=True):
        if not moving:
            parts.append({"\\rho": m, "\\mathbf{p}": f"\\mathbf{{o}} + ({x})"})
            continue
        part = {"\\rho": m}
        for dots in ("", "dot", "ddot"):
            o, q, p = (f"\\{dots}{{{g}}}" if dots else g
                       for g in ("\\mathbf{o}", "\\mathbf{Q}", "\\mathbf{p}"))
            if o in have:
                part[p] = f"{o} + {q}({x})"
        parts.append(part)
    out: list[dict] = [{"glyph": "\\int_{\\mathcal{B}}", "model": BODY_WORDS,
                        "particles": parts}]

    def line(glyph: str, latex: str, words: str) -> None:
        if glyph not in have:
            out.append({"glyph": glyph, "latex": latex, "model": words})

    line("m", r"\int_{\mathcal{B}} \rho d\mathcal{B}", "mass as printed in (3.123)")
    line(r"\mathbf{I}_C", _IC, "I_C as printed under the brace of (3.130)")
    if "\\mathbf{pP}" in have:
        line(r"\mathbf{p}", r"\mathbf{pP}", "a body point P, anywhere")
    if moving:
        if "\\mathbf{sP}" in have:
            line(r"\mathbf{p}", r"\mathbf{o} + \mathbf{Q}\mathbf{sP}",
                 "a body point P, sP its body coordinates")
            line(r"\dot{\mathbf{p}}", r"\dot{\mathbf{o}} + \dot{\mathbf{Q}}\mathbf{sP}",
                 "the body point P's velocity")
        for dots in ("dot", "ddot"):
            if f"\\{dots}{{\\mathbf{{o}}}}" in have:
                line(f"\\{dots}{{\\mathbf{{c}}}}", f"\\frac{{1}}{{m}}\\int_{{\\mathcal{{B}}}} "
                     f"\\rho \\{dots}{{\\mathbf{{p}}}} d\\mathcal{{B}}",
                     f"{dots} of c = q_O/m (3.124)-(3.125), m constant")
        line(r"\boldsymbol{\Omega}", r"\dot{\mathbf{Q}}\mathbf{Q}^T",
             "angular velocity matrix, Omega = Q-dot Q^T (3.44)")
        line(r"\boldsymbol{\omega}", r"\text{vect}(\dot{\mathbf{Q}}\mathbf{Q}^T)",
             "angular velocity, omega = vect(Omega) (3.45)")
    for cap, vec in ((r"\mathbf{R}", r"\mathbf{r}"), (r"\mathbf{C}", r"\mathbf{c}")):
        if cap not in have:
            out.append({"glyph": cap, "cpm_of": vec})
    return out
