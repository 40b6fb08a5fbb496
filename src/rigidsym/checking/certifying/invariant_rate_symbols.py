"""Symbol-table lines of the rates of the rotation invariants: how certcheck's
second reader binds the glyphs of (3.76a)-(3.97e) (the end of section 3.4.2 and section
3.5) to a certificate's atoms, each line in the book's glyphs for a referee to hold against
the page.

The project's models (``derivations/sec3_4_2.py``, ``rates_model``;
``derivations/sec3_5.py``, ``_pose``; ``derivations/sec3_5_rates.py``) move ``e(t)``
(unit) and ``phi(t)``, ``Q`` of (2.49), and a landmark point A (``a(t)``). Their glyphs:

- ``nu``, ``lambda``, ``eta`` as printed in (3.75) and their first and second rates, the
  time derivatives of (3.75) term by term (``nu-dot`` of (3.76a), the pose's rates);
- ``N``, ``L``, ``H`` as printed in (3.76b-d) (the page: "with N, L, and H defined as"),
  ``N-tilde``, ``L-tilde``, ``H-tilde`` as printed in (3.77b-d) with their two blocks side
  by side (the page prints ``[X e]``: the 3 x 3 block X and the fourth column; the sign
  printed before the column is the column's), and the time derivatives of all six, term by
  term (the model's rates, ``derivations/sec3_5_rates.py``: ``d/dt`` of those matrices);
- ``O_43``, ``O_34`` the zero matrices the page names in words after (3.79) and (3.80b);
  ``T``, ``S`` as printed in (3.79), (3.80b); ``T-dot`` as printed in (3.92); ``S-dot``
  the time derivative of (3.80b) (the model's; (3.94) prints ``F-dot`` for the tilde's);
- the pose ``s = [q; q_0; d_A]`` of (3.34) with ``d_A = a - a_0`` (the model's landmark
  displacement), so ``s-dot = [nu-dot; a-dot]`` with the natural invariants, and so on;
- ``U`` as printed in (3.83b), ``P`` the cross-product matrix of ``p`` (the page under
  (3.83b)); ``W`` as printed in (3.86); ``u``, ``u_0``, ``r``, ``r_0`` as printed in
  (3.95b), ``r-dot``, ``r_0-dot`` their rates and ``R-dot`` the cross-product matrix of
  ``r-dot`` ("R denotes the cross-product matrix of r", under (3.96d)); ``D`` as printed
  in (3.97e); section 3.5's twist at A (the model's ``[omega; a-dot]``): ``v = a-dot``,
  ``v-dot = a-ddot``, ``t`` as printed in (3.72), ``t-dot`` as printed in (3.90),
  ``omega-dot = vect(Q-ddot Q^T + Q-dot Q-dot^T)`` (the rate of (3.44)-(3.45)) and
  ``Q-ddot`` the second time derivative of (2.49) term by term;
- where the model moves ``e`` and ``phi`` with an angular velocity ``omega`` (an atom,
  ``omega_model`` of 3.96a): ``e-dot`` and ``phi-dot`` from ``nu-dot = N omega`` (3.76a);
- ``\\mathbf{1tr}``, the converted text's run-together of ``\\mathbf{1}`` and ``\\text{tr}``
  in (3.96b): read as those two glyphs (the project's conjecture about the printed page).

The page's ``F`` is "correspondingly, N, L, or H, depending upon the invariant
representation chosen" (after (3.79)), ``F-tilde`` one of ``N-tilde``, ... (after (3.80b)):
:func:`member_symbols` gives those lines per certificate relation (labelled ``F = N``,
``F~ = N~``, ...), so each member is read under its own representation; and (3.35)'s two
cases ("In the first two cases", the Euler-Rodrigues parameters and the linear invariants),
each relation under the page's display of its ``q``, ``q_0`` above (3.35), verbatim.

``B`` and ``V``, only on the page that defines them by an erratum ((3.96e), (3.97d)), as
(3.96a) and (3.97b) use them: ``B`` is 4(1 - cos phi) times the upper block of ``N-dot``,
``V`` is ``D`` times the 3 x 3 block of the rate of ``L-tilde`` (the page's ``L-dot`` of
(3.97b) for the tilde's); ``u-dot``, ``u_0-dot`` the rates of (3.95b), and in section 3.5
``U``, ``U-dot`` the cross-product matrices of ``u``, ``u-dot`` ("with U denoting, now, the
cross-product matrix of u", under (3.97e)). Where (3.96a) prints ``B`` before the page
defines it ("B is defined as"), ``B`` as (3.96e) prints it, cited (``printed_as``), and
``Omega`` the cross-product matrix of ``omega``. Not given: ``V`` in (3.97b), which prints
``[V/D u-dot]``, a product that reads 3 x 1 where the conversion lost a column separator.
"""

from __future__ import annotations

import re

from rigidsym.checking.certifying.unit_alternatives import unit_symbols

__all__ = ["INVARIANT_RATE_GLYPHS", "invariant_rate_symbols", "member_symbols"]

_TAN = r"[(\sin \phi)/(1 + \cos \phi)]"
_TAN_DOT = (r"[(\dot{\phi}\cos\phi)(1 + \cos\phi) + (\sin\phi)(\dot{\phi}\sin\phi)]"
            r"/(1 + \cos\phi)^2")
_COT_DOT = (r"[(\dot{\phi}\cos\phi)(2(1 - \cos\phi)) - (\sin\phi)(2\dot{\phi}\sin\phi)]"
            r"/(2(1 - \cos\phi))^2")


def _col(top: str, bottom: str) -> str:
    return rf"\begin{{bmatrix}} {top} \\ {bottom} \end{{bmatrix}}"


def _zeros(rows: int, cols: int) -> str:
    row = " & ".join("0" for _ in range(cols))
    return r"\begin{bmatrix} " + r" \\ ".join(row for _ in range(rows)) + r" \end{bmatrix}"


#: (glyph, LaTeX in the table's glyphs, the model's words), both sections
_COMMON = (
    (r"\dot{\boldsymbol{\nu}}", _col(r"\dot{\mathbf{e}}", r"\dot{\phi}"),
     "rate of nu = [e; phi] (3.75), term by term"),
    (r"\dot{\boldsymbol{\lambda}}", _col(r"\dot{\phi}(\cos\phi)\mathbf{e} + (\sin\phi)"
                                         r"\dot{\mathbf{e}}", r"-\dot{\phi}\sin\phi"),
     "rate of lambda = [(sin phi) e; cos phi] (3.75), term by term"),
    (r"\dot{\boldsymbol{\eta}}", _col(r"(1/2)\dot{\phi}\cos(\phi/2)\mathbf{e} + \sin(\phi/2)"
                                      r"\dot{\mathbf{e}}", r"-(1/2)\dot{\phi}\sin(\phi/2)"),
     "rate of eta = [sin(phi/2) e; cos(phi/2)] (3.75), term by term"),
    (r"\mathbf{N}", _col(r"[\sin \phi / (2(1 - \cos \phi))] (\mathbf{1} - \mathbf{e}"
                         r"\mathbf{e}^T) - (1/2)\mathbf{E}", r"\mathbf{e}^T"),
     "N as printed in (3.76b) (the page: with N, L, and H defined as)"),
    (r"\mathbf{L}", _col(r"(1/2)[\text{tr}(\mathbf{Q})\mathbf{1} - \mathbf{Q}]",
                         r"-(\sin \phi)\mathbf{e}^T"), "L as printed in (3.76c)"),
    (r"\mathbf{H}", r"\frac{1}{2}" + _col(r"\cos(\phi/2)\mathbf{1} - \sin(\phi/2)\mathbf{E}",
                                          r"-\sin(\phi/2)\mathbf{e}^T"),
     "H as printed in (3.76d)"),
    (r"\tilde{\mathbf{N}}", r"\begin{bmatrix} (\sin \phi)\mathbf{1} + (1 - \cos \phi)"
     r"\mathbf{E} & \mathbf{e} \end{bmatrix}",
     "N-tilde as printed in (3.77b), its 3 x 3 block and its column e side by side"),
    (r"\tilde{\mathbf{L}}", rf"\begin{{bmatrix}} \mathbf{{1}} + {_TAN}\mathbf{{E}} & -{_TAN}"
     r"\mathbf{e} \end{bmatrix}", "L-tilde as printed in (3.77c), its 3 x 3 block and its "
     "column -[(sin phi)/(1 + cos phi)] e side by side"),
    (r"\tilde{\mathbf{H}}", r"2\begin{bmatrix} [\cos(\phi/2)]\mathbf{1} + [\sin(\phi/2)]"
     r"\mathbf{E} & -[\sin(\phi/2)]\mathbf{e} \end{bmatrix}", "H-tilde as printed in "
     "(3.77d), its 3 x 3 block and its column -[sin(phi/2)] e side by side"),
    (r"\mathbf{O}_{43}", _zeros(4, 3), "the 4 x 3 zero matrix (the page under (3.79))"),
    (r"\mathbf{O}_{34}", _zeros(3, 4), "the 3 x 4 zero matrix (the page under (3.80b))"),
)
#: the end of section 3.4.2 (glyphs printed after their first use there)
_SEC342 = (
    (r"\mathbf{T}", r"\begin{bmatrix} \mathbf{F} & \mathbf{O}_{43} \\ \mathbf{O} & "
     r"\mathbf{1} \end{bmatrix}", "T as printed in (3.79)"),
    (r"\mathbf{S}", r"\begin{bmatrix} \tilde{\mathbf{F}} & \mathbf{O} \\ \mathbf{O}_{34} & "
     r"\mathbf{1} \end{bmatrix}", "S as printed in (3.80b)"),
    (r"\mathbf{U}", r"\begin{bmatrix} \mathbf{1} & \mathbf{O} \\ \mathbf{A} - \mathbf{P} & "
     r"\mathbf{1} \end{bmatrix}", "U as printed in (3.83b)"),
)
#: section 3.5
_SEC35 = (
    (r"\mathbf{W}", r"\dot{\boldsymbol{\Omega}} + \boldsymbol{\Omega}^2",
     "angular-acceleration matrix as printed in (3.86)"),
    (r"\ddot{\boldsymbol{\nu}}", _col(r"\ddot{\mathbf{e}}", r"\ddot{\phi}"),
     "second rate of nu = [e; phi] (3.75), term by term"),
    (r"\ddot{\boldsymbol{\lambda}}", _col(
        r"\ddot{\phi}(\cos\phi)\mathbf{e} - \dot{\phi}^2(\sin\phi)\mathbf{e} + 2\dot{\phi}"
        r"(\cos\phi)\dot{\mathbf{e}} + (\sin\phi)\ddot{\mathbf{e}}",
        r"-\ddot{\phi}\sin\phi - \dot{\phi}^2\cos\phi"),
     "second rate of lambda (3.75), term by term"),
    (r"\ddot{\boldsymbol{\eta}}", _col(
        r"(1/2)\ddot{\phi}\cos(\phi/2)\mathbf{e} - (1/4)\dot{\phi}^2\sin(\phi/2)\mathbf{e} + "
        r"\dot{\phi}\cos(\phi/2)\dot{\mathbf{e}} + \sin(\phi/2)\ddot{\mathbf{e}}",
        r"-(1/2)\ddot{\phi}\sin(\phi/2) - (1/4)\dot{\phi}^2\cos(\phi/2)"),
     "second rate of eta (3.75), term by term"),
    (r"\dot{\mathbf{N}}", _col(
        _COT_DOT + r" (\mathbf{1} - \mathbf{e}\mathbf{e}^T) - [\sin\phi/(2(1 - \cos\phi))]"
        r"(\dot{\mathbf{e}}\mathbf{e}^T + \mathbf{e}\dot{\mathbf{e}}^T) - (1/2)\dot{\mathbf{E}}",
        r"\dot{\mathbf{e}}^T"), "rate of N (3.76b), term by term"),
    (r"\dot{\mathbf{L}}", _col(r"(1/2)[\text{tr}(\dot{\mathbf{Q}})\mathbf{1} - \dot{\mathbf{Q}}]",
                               r"-(\dot{\phi}\cos\phi)\mathbf{e}^T - (\sin\phi)"
                               r"\dot{\mathbf{e}}^T"), "rate of L (3.76c), term by term"),
    (r"\dot{\mathbf{H}}", r"\frac{1}{2}" + _col(
        r"-(1/2)\dot{\phi}\sin(\phi/2)\mathbf{1} - (1/2)\dot{\phi}\cos(\phi/2)\mathbf{E} - "
        r"\sin(\phi/2)\dot{\mathbf{E}}",
        r"-(1/2)\dot{\phi}\cos(\phi/2)\mathbf{e}^T - \sin(\phi/2)\dot{\mathbf{e}}^T"),
     "rate of H (3.76d), term by term"),
    (r"\dot{\tilde{\mathbf{N}}}", r"\begin{bmatrix} (\dot{\phi}\cos\phi)\mathbf{1} + "
     r"(\dot{\phi}\sin\phi)\mathbf{E} + (1 - \cos\phi)\dot{\mathbf{E}} & \dot{\mathbf{e}} "
     r"\end{bmatrix}", "rate of N-tilde (3.77b), term by term"),
    (r"\dot{\tilde{\mathbf{L}}}", rf"\begin{{bmatrix}} {_TAN_DOT} \mathbf{{E}} + {_TAN}"
     rf"\dot{{\mathbf{{E}}}} & -{_TAN_DOT} \mathbf{{e}} - {_TAN}\dot{{\mathbf{{e}}}} "
     r"\end{bmatrix}", "rate of L-tilde (3.77c), term by term"),
    (r"\dot{\tilde{\mathbf{H}}}", r"2\begin{bmatrix} -(1/2)\dot{\phi}\sin(\phi/2)\mathbf{1} + "
     r"(1/2)\dot{\phi}\cos(\phi/2)\mathbf{E} + \sin(\phi/2)\dot{\mathbf{E}} & -(1/2)"
     r"\dot{\phi}\cos(\phi/2)\mathbf{e} - \sin(\phi/2)\dot{\mathbf{e}} \end{bmatrix}",
     "rate of H-tilde (3.77d), term by term"),
    (r"\dot{\mathbf{T}}", r"\begin{bmatrix} \dot{\mathbf{F}} & \mathbf{O}_{43} \\ \mathbf{O} & "
     r"\mathbf{O} \end{bmatrix}", "T-dot as printed in (3.92)"),
    (r"\dot{\mathbf{S}}", r"\begin{bmatrix} \dot{\tilde{\mathbf{F}}} & \mathbf{O} \\ "
     r"\mathbf{O}_{34} & \mathbf{O} \end{bmatrix}", "rate of S (3.80b), term by term (the "
     "model's: the rate of F-tilde in its 3 x 4 block)"),
    (r"\boldsymbol{\lambda}", _col(r"(\sin \phi)\mathbf{e}", r"\cos \phi"),
     "lambda as printed in (3.75)"),
    (r"\boldsymbol{\eta}", _col(r"[\sin(\phi/2)]\mathbf{e}", r"\cos(\phi/2)"),
     "eta as printed in (3.75)"),
    (r"\mathbf{u}", r"\sin \phi \mathbf{e}", "u as printed in (3.95b)"),
    (r"u_0", r"\cos \phi", "u_0 as printed in (3.95b)"),
    (r"\mathbf{r}", r"\sin \left( \frac{\phi}{2} \right) \mathbf{e}", "r as printed in (3.95b)"),
    (r"r_0", r"\cos \left( \frac{\phi}{2} \right)", "r_0 as printed in (3.95b)"),
    (r"\dot{\mathbf{r}}", r"(1/2)\dot{\phi}\cos(\phi/2)\mathbf{e} + \sin(\phi/2)"
     r"\dot{\mathbf{e}}", "rate of r (3.95b)"),
    (r"\dot{r}_0", r"-(1/2)\dot{\phi}\sin(\phi/2)", "rate of r_0 (3.95b)"),
    (r"D", r"1 + u_0", "D as printed in (3.97e)"),
    (r"\dot{\mathbf{u}}", r"\dot{\phi}\cos\phi\mathbf{e} + \sin\phi\dot{\mathbf{e}}",
     "rate of u (3.95b)"),
    (r"\dot{u}_0", r"-\dot{\phi}\sin\phi", "rate of u_0 (3.95b)"),
    (r"\mathbf{v}", r"\dot{\mathbf{a}}", "the velocity of the twist's point A, the landmark "
     "of the pose (3.34)"),
    (r"\dot{\mathbf{v}}", r"\ddot{\mathbf{a}}", "the acceleration of that point A"),
    (r"\mathbf{t}", _col(r"\boldsymbol{\omega}", r"\mathbf{v}"),
     "the twist at A as printed in (3.72)"),
    (r"\dot{\mathbf{t}}", _col(r"\dot{\boldsymbol{\omega}}", r"\dot{\mathbf{v}}"),
     "the twist's rate at A as printed in (3.90)"),
    (r"\dot{\boldsymbol{\omega}}", r"\text{vect}(\ddot{\mathbf{Q}}\mathbf{Q}^T + "
     r"\dot{\mathbf{Q}}\dot{\mathbf{Q}}^T)", "rate of omega = vect(Q-dot Q^T) (3.44), "
     "(3.45), term by term"),
    (r"\ddot{\mathbf{Q}}", r"\ddot{\mathbf{e}}\mathbf{e}^T + 2\dot{\mathbf{e}}"
     r"\dot{\mathbf{e}}^T + \mathbf{e}\ddot{\mathbf{e}}^T - (\ddot{\phi}\sin\phi + "
     r"\dot{\phi}^2\cos\phi)(\mathbf{1} - \mathbf{e}\mathbf{e}^T) + 2\dot{\phi}\sin\phi"
     r"(\dot{\mathbf{e}}\mathbf{e}^T + \mathbf{e}\dot{\mathbf{e}}^T) - \cos\phi(\ddot{"
     r"\mathbf{e}}\mathbf{e}^T + 2\dot{\mathbf{e}}\dot{\mathbf{e}}^T + \mathbf{e}\ddot{"
     r"\mathbf{e}}^T) + (\ddot{\phi}\cos\phi - \dot{\phi}^2\sin\phi)\mathbf{E} + 2"
     r"\dot{\phi}\cos\phi\dot{\mathbf{E}} + \sin\phi\ddot{\mathbf{E}}",
     "the second time derivative of (2.49), term by term"),
)
#: B and V, only on the page that defines them (3.96e, 3.97d): what (3.96a), (3.97b) make them
_DEFINED = (
    (r"\mathbf{B}", r"4(1 - \cos\phi)(" + _COT_DOT + r" (\mathbf{1} - \mathbf{e}\mathbf{e}^T) - "
     r"[\sin\phi/(2(1 - \cos\phi))](\dot{\mathbf{e}}\mathbf{e}^T + \mathbf{e}\dot{\mathbf{e}}^T)"
     r" - (1/2)\dot{\mathbf{E}})", "B as (3.96a) makes it: 4(1 - cos phi) times the upper "
     "3 x 3 block of N-dot, the rate of N (3.76b) term by term"),
    (r"\mathbf{V}", rf"D({_TAN_DOT} \mathbf{{E}} + {_TAN}\dot{{\mathbf{{E}}}})", "V as (3.97b) "
     "makes it: D times the 3 x 3 block of the rate of L-tilde (3.77c) term by term (the page's "
     "L-dot of (3.97b) for the tilde's)"),
)
#: B and V where the page prints them before defining them: as (3.96e), (3.97d) print them,
#: verbatim (alignment marks too; "B is defined as" under (3.96c), "V and D are defined
#: below" under (3.97c)), cited and held to those displays
_PRINTED_BELOW = (
    (r"\mathbf{B}", r"-2(\mathbf{e} \cdot \boldsymbol{\omega})\mathbf{1} + 2(3 - \cos \phi)"
     r"(\mathbf{e} \cdot \boldsymbol{\omega})\mathbf{e}\mathbf{e}^T - 2(1 + \sin \phi)"
     r"\boldsymbol{\omega}\mathbf{e}^T \\ &\quad - (2 \cos \phi + \sin \phi)\mathbf{e}"
     r"\boldsymbol{\omega}^T - (\sin \phi)[\boldsymbol{\Omega} - (\mathbf{e} \cdot "
     r"\boldsymbol{\omega})\mathbf{E}]", "(3.96e)"),
    (r"\mathbf{V}", r"\dot{\mathbf{U}} - (\dot{\mathbf{u}}\mathbf{u}^T + \mathbf{u}\dot{"
     r"\mathbf{u}}^T) - \frac{\dot{u}_0}{D}(\mathbf{U} - \mathbf{u}\mathbf{u}^T)", "(3.97d)"),
)
#: the jets of a motion given by its angular velocity (``omega_model``: e, phi, omega atoms)
_JETS = (
    (r"\dot{\mathbf{e}}", r"[\sin \phi / (2(1 - \cos \phi))] (\mathbf{1} - \mathbf{e}"
     r"\mathbf{e}^T)\boldsymbol{\omega} - (1/2)\mathbf{E}\boldsymbol{\omega}", "e-dot of the "
     "motion of angular velocity omega: the upper block of nu-dot = N omega (3.76a), N as "
     "printed in (3.76b)"),
    (r"\dot{\phi}", r"\mathbf{e}^T\boldsymbol{\omega}", "phi-dot of that motion: the last "
     "row of nu-dot = N omega (3.76a)"),
)
#: section 3.5's twist at A, only where the table has a-dot and no body point P
_AT_A = (r"\mathbf{v}", r"\dot{\mathbf{v}}", r"\mathbf{t}", r"\dot{\mathbf{t}}",
         r"\dot{\boldsymbol{\omega}}", r"\ddot{\mathbf{Q}}")
#: the glyphs of every line above (cross-product matrices and the slip apart)
INVARIANT_RATE_GLYPHS = tuple(g for g, _, _ in _COMMON + _SEC342 + _SEC35 + _JETS + _DEFINED)

#: per representation: (F, F-tilde, the invariants' array, the page's words)
_REPS = {"N": (r"\boldsymbol{\nu}", "natural invariants"),
         "L": (r"\boldsymbol{\lambda}", "linear invariants"),
         "H": (r"\boldsymbol{\eta}", "Euler-Rodrigues parameters")}
_FAMILY = re.compile(r"\\mathbf\{[FTS]\}|\\mathbf\{s\}")


def _members(rep: str) -> tuple:
    """The lines of one representation ``rep`` (N, L or H): ``F``, ``F-tilde``, their rates
    and the pose's rates, each ``(glyph, latex, words)``."""
    q, words = _REPS[rep]
    f, ft = rf"\mathbf{{{rep}}}", rf"\tilde{{\mathbf{{{rep}}}}}"
    return (
        (r"\mathbf{F}", f, f"F is {rep} for the {words} (the page under (3.79))"),
        (r"\dot{\mathbf{F}}", rf"\dot{{{f}}}", f"F-dot is {rep}-dot (the page under (3.94))"),
        (r"\tilde{\mathbf{F}}", ft, f"F-tilde is {rep}-tilde (the page under (3.80b))"),
        (r"\dot{\tilde{\mathbf{F}}}", rf"\dot{{{ft}}}", f"the rate of F-tilde, {rep}-tilde's"),
        (r"\dot{\mathbf{s}}", _col(rf"\dot{{{q}}}", r"\dot{\mathbf{a}}"), "rate of the pose s "
         f"= [q; q_0; d_A] (3.34) with the {words}, d_A = a - a_0 (the landmark A's "
         "displacement)"),
        (r"\ddot{\mathbf{s}}", _col(rf"\ddot{{{q}}}", r"\ddot{\mathbf{a}}"),
         f"second rate of that pose (the {words})"),
    )


#: (3.35)'s cases: the relation's label -> (its place among the page's cases, ``q``, ``q_0``
#: as the display above (3.35) prints them)
_CASES = {"Euler-Rodrigues": (1, r"\sin\left(\frac{\phi}{2}\right)\mathbf{e}",
                              r"\cos\left(\frac{\phi}{2}\right)"),
          "linear invariants": (2, r"(\sin \phi)\mathbf{e}", r"\cos \phi")}


def member_symbols(label: str, section: str) -> list[dict]:
    """The lines of one certificate relation of the family ``F = N, L, H`` (its label ``F =
    N`` or ``F~ = N~``, ...), ``{"glyph", "latex", "model"}``, or of a case of (3.35) (its
    ``q``, ``q_0`` as the page's k-th display above it prints them, ``printed_as``), or of
    an alternative of a pitch in m/rad or m/turn (``unit_alternatives.unit_symbols``); ``[]``
    for any other label or section. certcheck reads the page's one relation once per member,
    under the table and the member's lines."""
    if own := unit_symbols(label, section):  # a pitch in m/rad or in m/turn
        return own
    if section == "3.2.3" and label in _CASES:
        k, q, q0 = _CASES[label]
        return [{"glyph": g, "latex": x, "printed_as": f"case {k} above (3.35)"}
                for g, x in ((r"\mathbf{q}", q), ("q_0", q0))]
    m = re.fullmatch(r"F~? = ([NLH])~?", label or "")
    if m is None or section not in ("3.4.2", "3.5"):
        return []
    return [{"glyph": g, "latex": x, "model": w} for g, x, w in _members(m.group(1))]


def invariant_rate_symbols(have: set, section: str, latex: str) -> list[dict]:
    """The lines of the rates of the invariants for a table whose glyphs are ``have``.

    Args:
        have: the glyphs the table already gives.
        section: the id's section: ``3.4.2`` or ``3.5`` (``[]`` elsewhere).
        latex: the id's printed text: only the lines of glyphs it prints, or that a given
            line (or a member's line, :func:`member_symbols`) names, are given.

    Returns:
        Entries ``{"glyph", "latex", "model"}`` (``{"glyph", "cpm_of"}`` for ``P``,
        ``R-dot`` and ``Omega``; ``{"glyph", "latex", "printed_as"}`` for (3.96a)'s ``B``,
        (3.96e)'s text verbatim; ``{"glyph", "latex", "model", "reads_as": "text"}`` for
        ``\\mathbf{1tr}``: certcheck reads the glyph as the text ``latex`` in its place),
        only for glyphs the table lacks.
    """
    if section not in ("3.4.2", "3.5"):
        return []
    lines = _COMMON + (_SEC342 if section == "3.4.2" else _SEC35)
    lines += tuple(x for x in _DEFINED if re.search(re.escape(x[0]) + r"\s*&?\\equiv", latex))
    if {r"\boldsymbol{\omega}", r"\mathbf{e}"} <= have and r"\dot{\phi}" not in have:
        lines += _JETS  # e and phi move with the angular velocity omega (an atom)
    text = latex + (" ".join(x for r in "NLH" for _, x, _ in _members(r))
                    if _FAMILY.search(latex) else "")
    out: list[dict] = []
    for g, x, where in _PRINTED_BELOW:  # a glyph the id prints, defined further down
        if section == "3.5" and re.search(re.escape(g) + r"(?![_'])", latex) and \
                g not in have and not re.search(re.escape(g) + r"\s*&?\\equiv", latex):
            out.append({"glyph": g, "latex": x, "printed_as": where})
            text += " " + x
    grown = True
    while grown:  # a line's glyphs are given too, once
        grown = False
        for g, x, w in lines:
            if g not in have and g in text and all(e["glyph"] != g for e in out) and not (
                    g in _AT_A and ("\\ddot{\\mathbf{p}}" in have or
                                    "\\dot{\\mathbf{a}}" not in have)):
                out.append({"glyph": g, "latex": x, "model": w})
                text, grown = text + " " + x, True
    given = have | {e["glyph"] for e in out}
    if r"\boldsymbol{\Omega}" in text and r"\boldsymbol{\Omega}" not in given and \
            r"\boldsymbol{\omega}" in given:  # Omega, the cross-product matrix of omega
        out.append({"glyph": r"\boldsymbol{\Omega}", "cpm_of": r"\boldsymbol{\omega}"})
    if section == "3.4.2" and r"\mathbf{P}" in text and r"\mathbf{P}" not in given and \
            r"\mathbf{p}" in given:  # "A and P denote the cross-product matrices of a and p"
        out.append({"glyph": r"\mathbf{P}", "cpm_of": r"\mathbf{p}"})
    if r"\dot{\mathbf{e}}" in text and r"\dot{\mathbf{E}}" not in given:
        out.append({"glyph": r"\dot{\mathbf{E}}", "cpm_of": r"\dot{\mathbf{e}}"})
    if r"\ddot{\mathbf{Q}}" in text and r"\ddot{\mathbf{E}}" not in given:
        out.append({"glyph": r"\ddot{\mathbf{E}}", "cpm_of": r"\ddot{\mathbf{e}}"})
    for g, v in ((r"\mathbf{U}", r"\mathbf{u}"), (r"\dot{\mathbf{U}}", r"\dot{\mathbf{u}}")):
        if section == "3.5" and g in text and g not in given:  # "U denoting, now, the
            out.append({"glyph": g, "cpm_of": v})  # cross-product matrix of u" (3.97e)
    if r"\dot{\mathbf{R}}" in text and r"\dot{\mathbf{R}}" not in given:
        out.append({"glyph": r"\dot{\mathbf{R}}", "cpm_of": r"\dot{\mathbf{r}}"})
    if r"\mathbf{1tr}" in text:  # the conversion ran 1 and tr together (3.96b)
        out.append({"glyph": r"\mathbf{1tr}", "latex": r"\mathbf{1}\text{tr}", "reads_as":
                    "text", "model": "reading of the converted text's run-together of the "
                    "identity 1 and tr (the project's conjecture: the printed page reads "
                    "1 tr(.))"})
    return out
