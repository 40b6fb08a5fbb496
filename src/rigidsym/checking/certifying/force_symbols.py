"""Symbol-table lines of section 3.7's systems of forces: how certcheck's second
reader binds the book's resultant force ``f``, its magnitude ``||f||`` and the moments
``n_A``, ``n_P`` (which the page defines in words: "a system of forces acting on a rigid
body") to a certificate's atoms, each line in the book's glyphs for a referee to hold
against the page.

The project's models (``derivations/sec3_7.py``, ``_force_system``) are

- two forces ``f_1``, ``f_2`` applied at ``r_1``, ``r_2`` plus a couple ``c`` (reaching
  every pair of resultant and moment): ``f = f_1 + f_2`` and the moment about X
  ``n_X = (r_1 - x) x f_1 + (r_2 - x) x f_2 + c``;
- one force ``W e`` at ``r_1`` plus a couple ``c``, ``e`` a unit vector, where the page
  prints ``||f||``: ``f = W e``, ``||f|| = W`` (``W > 0``; a rational identity in ``W`` that
  holds for ``W > 0`` holds for every ``W``), ``n_X = W (r_1 - x) x e + c``.

A wrench and a twist of screws ``s_w``, ``s_t`` (3.71) (``derivations/sec3_7_reciprocity.py``):
axes through ``rw`` and ``rt`` along the unit vectors ``e`` and ``et``, pitch ``hw``, and the
twist's pitch solved from zero power (a reciprocal pair, 3.116-3.117). The wrench axis of
the one-force model (``p_0''``, ``e''``, ``n''``, the minimum moment ``n_0``: 3.108-3.111)
and the wrench and twist arrays ``w = [n; f]``, ``t = [omega; v]`` of the models of 3.113-3.115
and of the moving body (3.114, 3.120), as the models have them (:func:`_wrench_axis`,
:func:`_wrench_twist`).

(``A`` and ``P``, the cross-product matrices of ``a`` and ``p``, are given only where the id
prints them, or on the moving body (3.120's ``U``, ``V`` through (3.83b), (3.119b)): 3.122's
certificate proves the restatement ``V U^T = 1``, against which the printed ``U^T`` read
through (3.83b) would differ.)
"""

from __future__ import annotations

__all__ = ["force_symbols"]

_TWO = "two forces f_1 at r_1 and f_2 at r_2 and a couple c (the page's system of forces)"
_ONE = ("one force W e at r_1 (e unit, W = ||f|| > 0) and a couple c (the page's system of "
        "forces)")


def force_symbols(have: set, section: str, table: list[dict] | None = None) -> list[dict]:
    """The lines of section 3.7's system of forces for a table whose glyphs are ``have``.

    Args:
        have: the glyphs the table already gives (atoms' glyphs and model lines).
        section: the id's section; only ``3.7`` has the system of forces.
        table: the table's entries so far (the wrench's pitch ``hw``, named ``h_w``).

    Returns:
        Entries ``{"glyph", "latex", "model"}`` for ``f``, ``||f||`` (one-force model), and
        ``n_A``, ``n_P`` (where ``a``, ``p`` are points of the table), the wrench axis,
        the wrench and twist arrays; only glyphs the table lacks; ``[]`` where the table
        has none of the models.
    """
    if section != "3.7":
        return []
    out: list[dict] = []

    def line(glyph: str, latex: str, words: str) -> None:
        if glyph not in have:
            out.append({"glyph": glyph, "latex": latex, "model": words})

    two = {"\\mathbf{f}_1", "\\mathbf{f}_2", "\\mathbf{r}_1", "\\mathbf{r}_2",
           "\\mathbf{c}"} <= have
    one = {"\\mathbf{e}", "W", "\\mathbf{r}_1", "\\mathbf{c}"} <= have and not two
    if two:
        line("\\mathbf{f}", "\\mathbf{f}_1 + \\mathbf{f}_2", "resultant of " + _TWO)
        for x in ("a", "p"):
            if f"\\mathbf{{{x}}}" in have:
                line(f"\\mathbf{{n}}_{x.upper()}", f"(\\mathbf{{r}}_1 - \\mathbf{{{x}}}) \\times"
                     f" \\mathbf{{f}}_1 + (\\mathbf{{r}}_2 - \\mathbf{{{x}}}) \\times "
                     f"\\mathbf{{f}}_2 + \\mathbf{{c}}", f"moment about {x.upper()} of " + _TWO)
    elif one:
        line("\\mathbf{f}", "W\\mathbf{e}", "resultant of " + _ONE)
        line("\\|\\mathbf{f}\\|", "W", "magnitude of the resultant of " + _ONE)
        for x in ("a", "p"):
            if f"\\mathbf{{{x}}}" in have:
                line(f"\\mathbf{{n}}_{x.upper()}", f"W(\\mathbf{{r}}_1 - \\mathbf{{{x}}}) "
                     f"\\times \\mathbf{{e}} + \\mathbf{{c}}", f"moment about {x.upper()} of "
                     + _ONE)
        out += _wrench_axis(have, table or [])
    if {"\\mathbf{e}", "\\mathbf{et}", "\\mathbf{rw}", "\\mathbf{rt}", "hw"} <= have:
        out += _screw_pair(have, table or [])
    out += _wrench_twist(have)
    return [e for e in out if e["glyph"] not in have]


def _wrench_axis(have: set, table: list[dict]) -> list[dict]:
    """The wrench axis L'' of the one-force model as ``derivations/sec3_7.py`` has it (the
    page defines it in words, Theorem 3.7.1): ``p_0''`` the point where the moment is
    parallel to ``f`` and ``f . x = 0`` (solved there: ``r_1 - (e^T r_1) e + e x c / W``),
    a point ``p_0'' + lambda f`` of it, the moment there (``n_0``, the minimum moment),
    ``e''`` the unit ``e`` of ``f = W e``, ``n''`` the axis' moment about the origin, the
    Plücker array's six atoms, and ``n_0`` as (3.108) prints it."""
    words = "wrench axis L'' of " + _ONE
    p0 = ("\\mathbf{r}_1 - (\\mathbf{e}^T\\mathbf{r}_1)\\mathbf{e} + \\frac{1}{W}\\mathbf{e}"
          " \\times \\mathbf{c}")
    out = [{"glyph": "\\mathbf{p}_0''", "latex": p0, "model": "point closest to the origin "
            "(moment parallel to f, f . x = 0, solved) of the " + words},
           {"glyph": "\\mathbf{e}''", "latex": "\\mathbf{e}", "model": "unit vector of the "
            + words}]
    lam = [{**e, "glyph": "\\lambda"} for e in table if e.get("glyph") == "lam"]
    point = "(\\mathbf{p}_0'' + \\lambda\\mathbf{f})"
    if lam:
        out += [*lam, {"glyph": "\\mathbf{n}_0", "latex": f"W(\\mathbf{{r}}_1 - {point}) "
                       "\\times \\mathbf{e} + \\mathbf{c}", "model": "minimum-magnitude "
                       "moment: the moment about the point p_0'' + lambda f of the " + words},
                {"glyph": "\\mathbf{n}''", "latex": f"{point} \\times \\mathbf{{e}}''",
                 "model": "moment about the origin of the point p_0'' + lambda f of the "
                 + words}]
        if "\\mathbf{p}" not in have:
            out.append({"glyph": "\\mathbf{p}", "latex": point[1:-1], "model": "any point "
                        "P of the " + words})
    if "\\mathbf{p}" in have:  # n_P is given
        out.append({"glyph": "n_0", "latex": "\\frac{\\mathbf{n}_P \\cdot \\mathbf{f}}"
                    "{\\|\\mathbf{f}\\|}", "model": "magnitude of the minimum moment, as "
                    "printed in (3.108)"})
    pl = [a for e in table if e.get("glyph", "").startswith("p_L2_") for a in e["atoms"]]
    if len(pl) == 6:
        out.append({"glyph": "\\mathbf{p}_{\\mathcal{L}''}", "kind": "free", "atoms": pl})
    return out


def _wrench_twist(have: set) -> list[dict]:
    """The wrench array ``w = [n; f]`` (3.113) and the twist array ``t = [omega; v]`` of the
    models of ``derivations/sec3_7_reciprocity.py``, in the page's words:

    - (3.113): a force ``f = A e`` on the line through ``rw`` along ``e`` and the parallel
      moment ``h f``: ``n = rw x f + h f`` (the display above (3.113), its P at ``rw``);
    - (3.115): a general wrench and twist at the origin, ``f = W e``, ``n = c`` (free),
      ``omega = T et``, ``v`` free; their screws (3.71) as the model solves them (the axis
      point nearest the origin where the moment, the velocity, is parallel to ``f``,
      ``omega``: ``e x c / W``, ``et x v / T``; pitches ``c . e / W``, ``v . et / T``);
    - (3.114): a moving body loaded by forces ``f_1``, ``f_2`` at its points ``a + Q s_i``
      and a couple ``c``: ``n_X`` about its point X (``a``, ``p``), ``omega = vect(Q-dot
      Q^T)``, the twist at X ``[omega; x-dot]`` and the power ``Pi`` of the forces."""
    out, cpms = [], []
    bf, be, bc, bv = "\\mathbf{f}", "\\mathbf{e}", "\\mathbf{c}", "\\mathbf{v}"
    w_words = "wrench array (3.113) of the resultant f and the moment n"
    if {be, "\\mathbf{rw}", "A", "h"} <= have:
        out += [(bf, "A\\mathbf{e}", "force of magnitude A along the line through rw along e"),
                ("\\mathbf{n}", "\\mathbf{rw} \\times \\mathbf{f} + h\\mathbf{f}",
                 "moment about the origin of f on the line through rw plus the parallel "
                 "moment of pitch h (the display above (3.113), its P at rw)")]
    elif {be, "\\mathbf{et}", bc, bv, "W", "T"} <= have and "\\mathbf{rw}" not in have:
        out += [(bf, "W\\mathbf{e}", "resultant of a general wrench at the origin"),
                ("\\mathbf{n}", bc, "moment about the origin of that wrench (free)"),
                ("\\boldsymbol{\\omega}", "T\\mathbf{et}", "angular velocity of a general "
                 "twist at the origin"),
                ("\\mathbf{s}_w", _screw(be, "(\\frac{1}{W}\\mathbf{e} \\times \\mathbf{c})",
                                        "\\frac{\\mathbf{c} \\cdot \\mathbf{e}}{W}"),
                 "wrench's screw (3.71) as solved: axis point e x c / W, pitch c . e / W"),
                ("\\mathbf{s}_t", _screw("\\mathbf{et}", "(\\frac{1}{T}\\mathbf{et} \\times "
                                        "\\mathbf{v})", "\\frac{\\mathbf{v} \\cdot "
                                        "\\mathbf{et}}{T}"),
                 "twist's screw (3.71) as solved: axis point et x v / T, pitch v . et / T"),
                ("\\mathbf{t}", "\\begin{bmatrix} \\boldsymbol{\\omega} \\\\ \\mathbf{v} "
                 "\\end{bmatrix}", "twist array at the origin, the velocity v of the point "
                 "there")]
    elif {"\\mathbf{s}_1", "\\mathbf{s}_2", "\\mathbf{f}_1", "\\mathbf{f}_2",
          "\\dot{\\mathbf{Q}}", "\\dot{\\mathbf{p}}"} <= have:
        body = "forces f_1, f_2 at the moving body's points a + Q s_i and a couple c"
        out += [(bf, "\\mathbf{f}_1 + \\mathbf{f}_2", "resultant of " + body),
                ("\\boldsymbol{\\omega}", "\\text{vect}(\\dot{\\mathbf{Q}}\\mathbf{Q}^T)",
                 "angular velocity, vect(Q-dot Q^T) (3.44)-(3.45)"),
                ("\\Pi", " + ".join(f"\\mathbf{{f}}_{k} \\cdot (\\dot{{\\mathbf{{a}}}} + "
                                     f"\\dot{{\\mathbf{{Q}}}}\\mathbf{{s}}_{k})" for k in (1, 2))
                 + " + \\mathbf{c} \\cdot \\boldsymbol{\\omega}", "power of " + body)]
        for x in ("a", "p"):  # the body's points A and P
            n = " + ".join(f"(\\mathbf{{a}} + \\mathbf{{Q}}\\mathbf{{s}}_{k} - \\mathbf{{{x}}}) "
                           f"\\times \\mathbf{{f}}_{k}" for k in (1, 2)) + " + \\mathbf{c}"
            X = x.upper()
            out += [(f"\\mathbf{{n}}_{X}", n, f"moment about {X} of " + body),
                    (f"\\mathbf{{w}}_{X}", f"\\begin{{bmatrix}} \\mathbf{{n}}_{X} \\\\ "
                     "\\mathbf{f} \\end{bmatrix}", f"wrench array (3.113) at {X} of " + body),
                    (f"\\mathbf{{t}}_{X}", f"\\begin{{bmatrix}} \\boldsymbol{{\\omega}} \\\\ "
                     f"\\dot{{\\mathbf{{{x}}}}} \\end{{bmatrix}}", f"twist array at {X}")]
        out += [("\\mathbf{w}", "\\mathbf{w}_P", "wrench array at P"),
                ("\\mathbf{t}", "\\mathbf{t}_P", "twist array at P")]
        cpms = [{"glyph": f"\\mathbf{{{x.upper()}}}", "cpm_of": f"\\mathbf{{{x}}}"}
                for x in ("a", "p")]  # through (3.83b), (3.119b): U, V of the moving body
    if out and out[1][0] == "\\mathbf{n}":
        out.append(("\\mathbf{w}", "\\begin{bmatrix} \\mathbf{n} \\\\ \\mathbf{f} "
                    "\\end{bmatrix}", w_words))
    return [{"glyph": g, "latex": latex, "model": words} for g, latex, words in out] + cpms


def _screw(e: str, r: str, h: str) -> str:
    """The screw (3.71) of the axis through ``r`` along ``e`` of pitch ``h``, in LaTeX."""
    return f"\\begin{{bmatrix}} {e} \\\\ {r} \\times {e} + {h}{e} \\end{{bmatrix}}"


def _screw_pair(have: set, table: list[dict]) -> list[dict]:
    """Section 3.7's wrench and twist of screws ``s_w``, ``s_t`` (``derivations/
    sec3_7_reciprocity.py``): the wrench's axis through ``rw`` along the unit ``e``, pitch
    ``hw``; the twist's through ``rt`` along the unit ``et``, its pitch solved from zero
    power (``W e . v(rw) + hw W e . T et = 0``): the printed relations of these ids (3.116,
    3.117) are of a reciprocal pair (3.116's claim, of a general pair, is not read); the
    page's ``\\Gamma`` is (3.112)'s ``\\mathbf{\\Gamma}``."""
    pitches = [{**e, "glyph": "h_w"} for e in table if e.get("glyph") == "hw"]  # one letter
    ht = ("(-\\frac{\\mathbf{e} \\cdot (\\mathbf{et} \\times (\\mathbf{rw} - \\mathbf{rt})) + "
          "h_w\\mathbf{e} \\cdot \\mathbf{et}}{\\mathbf{e} \\cdot \\mathbf{et}})")
    words = ", its pitch solved from zero power (a reciprocal pair)"
    return [*pitches,
            {"glyph": "\\mathbf{s}_w", "latex": _screw("\\mathbf{e}", "\\mathbf{rw}", "h_w"),
             "model": "wrench's screw (3.71): axis through rw along e, pitch hw"},
            {"glyph": "\\mathbf{s}_t", "latex": _screw("\\mathbf{et}", "\\mathbf{rt}", ht),
             "model": "twist's screw (3.71): axis through rt along et" + words},
            {"glyph": "\\Gamma", "latex": "\\mathbf{\\Gamma}",
             "model": "(3.112)'s Gamma, printed here without bold"}]
