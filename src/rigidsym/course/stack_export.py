"""Moodle STACK export of a class: the LMS grades each box as the
gradebook does, the linked boxes of one answer jointly.

A Cloze question scores each number on its own, so it cannot see that (-e, -phi) with
the Plücker array negated is the key's screw, nor give a transposed Q the slip's credit.
STACK's potential response trees (PRTs) can: a PRT reads any of the question's inputs
in its feedback variables (Maxima) and walks a tree of answer tests, each node setting
the score and an answer note. ``stack_xml(title, key)`` writes one STACK question per
student and problem (Moodle XML, ``<question type="stack">``, in a category per
student), with:

* an input per numeric box (``matrix`` for a vector or a matrix, ``algebraic`` for a
  number, ``boolean`` for a truth), ``allowempty`` (a blank box is ``EMPTYANSWER``, so
  the PRTs that read it still run and a linked box is graded without it, as in the
  gradebook);
* a PRT per box, value 1 (the gradebook's mean of boxes), whose feedback variables decide
  in Maxima what the grader decides in Python: membership of the key's class within
  0.1 % of the key's largest entry (for a declared sign group, (e, phi) = (-e, -phi),
  phi + 2 pi k, the group's one sign chosen by the most pieces right, as
  :func:`rigidsym.course.answer_classes.judge`; an angle modulo its period; a point of
  a line modulo a shift along it), then any of the grader's slip values
  (:func:`rigidsym.course.grading.slip_values`; the replays of the solution with a slip
  along the way where the key's ``slips_along_the_way`` is true, as the gradebook then
  tries them; a slip's value compared within 0.1 % of its own largest entry, and no slip
  named on a trivial answer: all zero, all entries equal, a datum echoed), then the key
  rounded to 1, 2 or 3 significant figures;
* STACK's question tests: the key, every box blank, each box negated alone, each PRT's
  expected score and note the gradebook's;
* four nodes per PRT, each ``AlgEquiv(<truth>, true)`` on the feedback variables
  ``isblank``, ``isright``, ``isslip``, ``isrounded``: blank (0), right (1), a named
  slip (the spec's ``slip_credit``), rounded (``rounding_credit``), else wrong (0); the
  answer notes are ``<box>: blank | right | slip | rounded | wrong``.

Only builtins of Maxima are used: ``matrix``, ``args``, ``flatten``, ``abs``, ``lmax``,
``lmin``, ``max``, ``floor``, ``is``, ``if then else``, ``and``/``or``, ``.`` (a matrix
product) and ``%pi``.
A ``rotation onto`` box (3.14's [Q]_B) is right near any of its four rotations, and a
``columns up to sign`` box (3.12's principal axes) near any choice of its columns' signs;
a slip or a rounding of any member is named, as the grader judges it. Boxes that are
expressions in symbols (3.10's W), a ``rotation onto`` whose source has two equal
eigenvalues (a continuum of rotations) and declared classes of other kinds are not
exported: the question says so, and the gradebook (``gradebook.csv``) is then the grade
to import.
"""

from __future__ import annotations

import html
import math

import numpy as np

from rigidsym.course.answer_classes import column_signs, declared, names_of, rotations_onto
from rigidsym.course.box_kinds import ZERO, constant
from rigidsym.course.exam_text import lms_statement
from rigidsym.course.grading import RTOL, key_array, replayed_values, slip_values
from rigidsym.course.worked import exercise_module

__all__ = ["stack_xml", "STACK_KINDS"]

#: the declared kinds whose membership test the export writes in Maxima
STACK_KINDS = ("axis-angle", "sign", "angle", "point of line", "rotation onto",
               "columns up to sign")
_TWO_PI = 2 * math.pi


def stack_xml(title: str, key: dict) -> str:
    """The class's STACK questions as Moodle XML (``<quiz>``): a category per student, a
    STACK question per problem (``idnumber`` ``<id>-P<k>``), a PRT per numeric box.

    Args:
        title: the exam's title (the categories' parent).
        key: the class key (``key.json`` of :func:`rigidsym.course.roster.class_exam`:
            ``slip_credit``, ``rounding_credit``, ``slips_along_the_way`` (absent: true,
            as keys written before the policy existed were graded), ``students`` with
            their problems). Where ``slips_along_the_way`` is true, each question's
            solution is replayed with each slip along the way (a solve each, for its
            values: :func:`rigidsym.course.worked.solve_values`); where false, no replay
            is solved and neither this export nor the gradebook names such a slip.

    Returns:
        The XML text (UTF-8, deterministic: the same key writes the same bytes).
    """
    from rigidsym.course.gradebook import solution_of

    credit = (float(key.get("slip_credit", 0)),
              float(key.get("rounding_credit", key.get("slip_credit", 0))))
    along = bool(key.get("slips_along_the_way", True))
    from rigidsym.course.forked import forked_map

    def student(i: int) -> list[str]:
        st = key["students"][i]
        who = f"{st['student']} ({st['id']})" if st.get("id") else st["student"]
        out = [f"<question type=\"category\"><category><text>$course$/{_x(title)}/"
               f"STACK/{_x(who)}</text></category></question>"]
        for p in st["problems"]:
            ident = f"{st.get('id') or st['student']}-P{p['problem']}"
            name = f"{st['student']}: problem {p['problem']} (Exercise {p['id'][2:]})"
            out.append(_question(name, ident, p, solution_of(p), credit, along))
        return out

    # each student's questions in a forked worker (the replays are solves); the first
    # student's here, so that the workers inherit what its replays warmed (3.12's integrals
    # in a symbolic side and height for the cuts its slips make) instead of each warming it
    n = len(key["students"])
    chunks = ([student(0)] if n else []) + forked_map(lambda i: student(i + 1), max(n - 1, 0))
    lines = ['<?xml version="1.0" encoding="UTF-8"?>', "<quiz>"]
    lines += [x for c in chunks for x in c] + ["</quiz>"]
    return "\n".join(lines) + "\n"


def _boxes(p: dict, sol) -> dict[str, np.ndarray]:
    """The numeric boxes of a problem (answer name -> the key as floats), in order."""
    import sympy as sp

    out = {}
    for a in p["asked"]:
        v = sol.answers.get(a)
        if v is None or isinstance(v, str):
            continue
        free = getattr(v, "free_symbols", set()) if v not in (sp.true, sp.false) else set()
        if free:
            continue
        try:
            out[a] = key_array(v)
        except (TypeError, ValueError):
            continue
    return out


def _question(name: str, ident: str, p: dict, sol, credit: tuple[float, float],
              along: bool = True) -> str:
    mod = exercise_module(p["id"])
    boxes = _boxes(p, sol)
    inputs = {a: f"ans{i}" for i, a in enumerate(boxes, 1)}
    decls = [d for d in declared(mod) if all(n in sol.answers for n in names_of(d))]
    skipped = [n for d in decls if d["kind"] not in STACK_KINDS or
               d["kind"] == "rotation onto" and _members(d, sol) is None
               for n in names_of(d)]
    group = {n: d for d in decls if d["kind"] in STACK_KINDS for n in names_of(d)
             if n in boxes}
    # "[[" opens a STACK tag (an input, a feedback): a block matrix's brackets as entities
    text = [lms_statement(p).replace("[", "&#91;")]
    text += [f"<p>{html.escape(p['labels'].get(a, a))}: [[input:{inputs[a]}]] "
            f"[[validation:{inputs[a]}]] [[feedback:prt_{inputs[a]}]]</p>"
            for a in boxes if a not in skipped]
    text += [f"<p>{html.escape(p['labels'].get(a, a))}: graded by rigidsym grade (import "
             f"gradebook.csv)</p>" for a in p["asked"] if a not in boxes or a in skipped]
    qvars = "".join(f"ta_{inputs[a]}: {_truth_lit(sol.answers[a]) or _lit(k)};\n"
                    for a, k in boxes.items())
    parts = [f"<question type=\"stack\"><name><text>{_x(name)}</text></name>",
             f"<questiontext format=\"html\"><text><![CDATA[{''.join(text)}]]></text>"
             f"</questiontext>",
             f"<questionvariables><text>{_x(qvars)}</text></questionvariables>",
             f"<defaultgrade>{p['weight']:g}</defaultgrade>",
             f"<idnumber>{_x(ident)}</idnumber>"]
    truths = {a for a in boxes if _is_truth(sol.answers[a])}
    for a, k in boxes.items():
        if a in skipped:
            continue
        kind = "boolean" if a in truths else "matrix" if k.ndim else "algebraic"
        parts.append(f"<input><name>{inputs[a]}</name><type>{kind}</type>"
                     f"<tans>ta_{inputs[a]}</tans><forbidfloat>0</forbidfloat>"
                     f"<options>allowempty</options></input>")
    # once per question, kept: the grader reads them too; none unless the key asks
    replayed = replayed_values(sol) if along else []
    for a in boxes:
        if a not in skipped:
            feedback = _truth_feedback(inputs[a], sol.answers[a]) if a in truths else \
                _feedback(a, boxes, inputs, group.get(a), sol, replayed)
            parts.append(_prt(inputs[a], a, feedback, credit))
    parts += _qtests(sol, boxes, inputs, [a for a in boxes if a not in skipped], credit,
                     along)
    parts.append("</question>")
    return "".join(parts)


def _qtests(sol, boxes: dict, inputs: dict, exported: list,
            credit: tuple[float, float], along: bool = True) -> list[str]:
    """STACK's question tests (each question carries its own): every box right (the
    key), every box blank, and each box negated alone with the others right, the
    expected score and note of each PRT being the gradebook's
    (:func:`rigidsym.course.grading.grade` of the same answers)."""
    from rigidsym.course.grading import grade

    cases = [("the key", {a: f"ta_{inputs[a]}" for a in exported}),
             ("every box blank", {a: "EMPTYANSWER" for a in exported})]
    cases += [(f"{a} negated", {b: f"-ta_{inputs[b]}" if b == a else f"ta_{inputs[b]}"
                                for b in exported})
              for a in exported if np.any(boxes[a]) and not _is_truth(sol.answers[a])]
    out = []
    for n, (what, given) in enumerate(cases, 1):
        values = {a: "" if v == "EMPTYANSWER" else
                  (-boxes[a] if v.startswith("-") else boxes[a]).tolist() for a, v in
                  given.items()}
        graded = {g.name: g for g in grade(sol, values, replay=along)}
        parts = [f"<qtest><testcase>{n}</testcase><description>{_x(what)}</description>"]
        parts += [f"<testinput><name>{inputs[a]}</name><value>{v}</value></testinput>"
                  for a, v in given.items()]
        for a in exported:
            g = graded[a]
            word, score = ("right", 1.0) if g.correct else ("blank", 0.0) if g.missing \
                else ("rounded", credit[1]) if g.slip == "rounded" else \
                ("slip", credit[0]) if g.slip else ("wrong", 0.0)
            parts.append(f"<expected><name>prt_{inputs[a]}</name><expectedscore>{score:g}"
                         f"</expectedscore><expectedpenalty>0</expectedpenalty>"
                         f"<expectedanswernote>{_x(a)}: {word}</expectedanswernote>"
                         f"</expected>")
        out.append("".join(parts) + "</qtest>")
    return out


def _is_truth(v) -> bool:
    import sympy as sp

    return v in (sp.true, sp.false)


def _truth_lit(v) -> str:
    """A truth as Maxima writes it (``true``, ``false``), or ``""`` for another value."""
    return ("true" if bool(v) else "false") if _is_truth(v) else ""


def _truth_feedback(inp: str, v) -> str:
    """A truth box (STACK's ``boolean`` input): right when it is the key's truth; no slip
    of a truth is named (the gradebook names none: its edits of 1 or 0 never give the
    other)."""
    return (f"isblank: is({inp} = EMPTYANSWER);\nisright: is({inp} = {_truth_lit(v)});\n"
            f"isslip: false;\nisrounded: false;\n")


def _prt(inp: str, box: str, feedback: str, credit: tuple[float, float]) -> str:
    """A PRT of four nodes over the feedback variables ``isblank``, ``isright``,
    ``isslip`` and ``isrounded``: the first true one sets the score and the note."""
    nodes = [("blank", 0.0), ("right", 1.0), ("slip", credit[0]), ("rounded", credit[1])]
    # the variables are is<word>: no Maxima or STACK name is shadowed
    out = [f"<prt><name>prt_{inp}</name><value>1</value><autosimplify>1</autosimplify>"
           f"<feedbackvariables><text>{_x(feedback)}</text></feedbackvariables>"]
    for i, (var, score) in enumerate(nodes):
        last = i == len(nodes) - 1
        out.append(
            f"<node><name>{i}</name><answertest>AlgEquiv</answertest><sans>is{var}</sans>"
            f"<tans>true</tans><testoptions></testoptions><quiet>0</quiet>"
            f"<truescoremode>=</truescoremode><truescore>{score:g}</truescore>"
            f"<truenextnode>-1</truenextnode><trueanswernote>{_x(box)}: {var}"
            f"</trueanswernote><falsescoremode>=</falsescoremode><falsescore>0"
            f"</falsescore><falsenextnode>{-1 if last else i + 1}</falsenextnode>"
            f"<falseanswernote>{_x(box)}: {'wrong' if last else 'not ' + var}"
            f"</falseanswernote></node>")
    out.append("</prt>")
    return "".join(out)


def _feedback(box: str, boxes: dict, inputs: dict, decl: dict | None, sol,
              replayed: list) -> str:
    """The Maxima of one box's PRT: ``isblank``, ``isright``, ``isslip``, ``isrounded``."""
    k, inp = boxes[box], inputs[box]
    lines = [f"isblank: is({inp} = EMPTYANSWER)"]
    kind = decl["kind"] if decl else None
    if kind in ("axis-angle", "sign"):
        pieces = [n for n in names_of(decl) if n in boxes]
        angle = decl.get("angle")
        for n in pieces:
            for tag, s in (("p", 1.0), ("m", -1.0)):
                test = _wrapped(inputs[n], s * boxes[n], _TWO_PI, _scale(boxes[n])) \
                    if n == angle else _near(inputs[n], s * boxes[n], _scale(boxes[n]))
                lines.append(f"r{tag}_{inputs[n]}: if is({inputs[n]} = EMPTYANSWER) then "
                             f"false else {test}")
        count = {t: " + ".join(f"(if r{t}_{inputs[n]} then 1 else 0)" for n in pieces)
                 for t in "pm"}
        lines += [f"np: {count['p']}", f"nm: {count['m']}",
                  "sg: if is(nm > np) then -1 else 1",
                  f"isright: if is(sg = 1) then rp_{inp} else rm_{inp}"]
        period = _TWO_PI if box == angle else None
        for tag, s in (("p", 1.0), ("m", -1.0)):
            lines.append(f"sl{tag}: {_slips(inp, sol, box, s * k, period, None, replayed)}")
            lines.append(f"rd{tag}: {_rounded(inp, s * k)}")
        lines += ["isslip: if is(sg = 1) then slp else slm",
                  "isrounded: if is(sg = 1) then rdp else rdm"]
    elif kind in ("rotation onto", "columns up to sign"):
        members = _members(decl, sol)
        # the grader's scale: 1 for a rotation, the key's largest entry for columns
        sc = 1.0 if kind == "rotation onto" else _scale(k)
        near = " or ".join(_near(inp, m, sc) for m in members)
        lines.append(f"isright: if isblank then false else ({near})")
        slips = " or ".join(dict.fromkeys(
            t for m in members for t in _slip_tests(inp, sol, box, m, None, None, replayed)))
        lines.append(f"isslip: if isblank then false else if {_trivial(inp, sol, k)} then "
                     f"false else ({slips or 'false'})")
        rounded = " or ".join(_rounded_tests(inp, m) for m in members)
        lines.append(f"isrounded: if isblank then false else ({rounded})")
    else:
        period = along = None
        if kind == "angle":
            period = math.pi if decl.get("period") == "pi" else _TWO_PI
            test = _wrapped(inp, k, period, _scale(k))
            lines.append(f"isright: if isblank then false else {test}")
        elif kind == "point of line":
            d = boxes.get(decl["direction"])
            d = key_array(sol.answers[decl["direction"]]) if d is None else d
            along = d.reshape(-1) / np.linalg.norm(d)
            sc = _scale(k) if _scale(k) > 1e-12 else 1.0
            lines.append(f"isright: if isblank then false else {_along(inp, k, along, sc)}")
        else:
            lines.append(f"isright: if isblank then false else {_near(inp, k, _scale(k))}")
        lines.append(f"isslip: {_slips(inp, sol, box, k, period, along, replayed)}")
        lines.append(f"isrounded: {_rounded(inp, k)}")
    return ";\n".join(lines) + ";\n"


def _slips(inp: str, sol, box: str, target: np.ndarray, period, along,
           replayed: list) -> str:
    """``is`` the answer one of the grader's slip values of ``target``, compared as
    :meth:`rigidsym.course.answer_classes.Verdict.matches` compares (``period``: an angle
    modulo the period scaled as the slip scaled it; ``along``: modulo a shift along;
    ``replayed``: the solution's replays, computed once per question)."""
    body = " or ".join(dict.fromkeys(_slip_tests(inp, sol, box, target, period, along,
                                                 replayed))) or "false"
    if body == "false":
        return f"if is({inp} = EMPTYANSWER) then false else false"
    return (f"if is({inp} = EMPTYANSWER) then false else if {_trivial(inp, sol, target)} "
            f"then false else ({body})")


def _trivial(inp: str, sol, target: np.ndarray) -> str:
    """``is`` the answer trivial, as :func:`rigidsym.course.box_kinds.trivial` decides: all
    zero (within the tolerance of the key's largest entry), all entries equal, or a datum
    of the exercise echoed: such an answer earns no slip credit."""
    from rigidsym.course.grading import data_arrays

    matrix = target.ndim > 0
    flat = f"flatten(args({inp}))" if matrix else inp
    top = f"lmax(abs({flat}))" if matrix else f"abs({inp})"
    tests = [f"is({top} <= {ZERO!r})"]
    if target.size > 1 and not constant(target, RTOL):
        tests.append(f"is(lmax({flat}) - lmin({flat}) <= {RTOL!r}*{top})")
    for d in data_arrays(sol):
        d = d.reshape(-1)
        if d.size != target.size:
            continue
        lit = ("[" + ",".join(repr(float(x)) for x in d) + "]") if matrix else \
            repr(float(d[0]))
        dist = f"lmax(abs({flat} - {lit}))" if matrix else f"abs({inp} - {lit})"
        tests.append(f"is({dist} <= {RTOL!r}*max({float(np.max(np.abs(d)))!r}, {top}))")
    return "(" + " or ".join(tests) + ")"


def _slip_tests(inp: str, sol, box: str, target: np.ndarray, period, along,
                replayed: list) -> list[str]:
    """The Maxima tests of :func:`_slips`, one per slip value."""
    sc = _scale(target)
    tests = []
    for _, value in slip_values(sol, box, target, replayed=replayed):
        if value.shape != target.shape:
            continue
        s = float(np.max(np.abs(value))) if value.size else sc    # the slipped key's
        t = target.reshape(-1)
        i = int(np.argmax(np.abs(t)))
        f = abs(float(value.reshape(-1)[i] / t[i])) if t.size and t[i] else 1.0
        if period is not None and f >= 0.5:     # as Verdict.matches: halved included
            tests.append(_wrapped(inp, value, f * period, s))
        elif along is not None:
            tests.append(_along(inp, value, along, s))
        else:
            tests.append(_near(inp, value, s, floor=False))
    return tests


def _members(decl: dict, sol) -> list[np.ndarray] | None:
    """The members of a finite class: the four rotations of a ``rotation onto`` box (None
    where the source matrix has two equal eigenvalues: a continuum, not exported), or
    every choice of the columns' signs of a ``columns up to sign`` box."""
    import sympy as sp

    if decl["kind"] == "columns up to sign":
        return column_signs(key_array(sol.answers[decl["name"]]))
    data = getattr(sol, "data", None) or {}
    if decl["from"] not in data:
        return None
    source = np.array(sp.N(sp.Matrix(data[decl["from"]]), 17).tolist(), dtype=float)
    lam = np.linalg.eigvalsh((source + source.T) / 2)
    if float(np.min(np.diff(lam))) <= RTOL * max(float(np.max(np.abs(lam))), 1e-300):
        return None
    return rotations_onto(key_array(sol.answers[decl["name"]]), source)


def _rounded(inp: str, target: np.ndarray) -> str:
    """``is`` every entry the target rounded to 1, 2 or 3 significant figures (within
    1e-9 relative and 1e-12 absolute, as :func:`rigidsym.course.grading.rounded_figures`)."""
    return f"if is({inp} = EMPTYANSWER) then false else ({_rounded_tests(inp, target)})"


def _rounded_tests(inp: str, target: np.ndarray) -> str:
    """The tests of :func:`_rounded`, joined by ``or``."""
    tests = []
    for n in range(1, 4):
        r = np.vectorize(lambda x, n=n: float(f"{x:.{n - 1}e}"))(target)
        diff = _dist(f"{inp} - {_lit(r)}", r.ndim > 0, f"1e-9*{_abs(_lit(r), r.ndim > 0)}")
        tests.append(f"is({diff} <= 1e-12)")
    return " or ".join(tests)


def _abs(expr: str, matrix: bool) -> str:
    return f"abs(flatten(args({expr})))" if matrix else f"abs({expr})"


def _dist(expr: str, matrix: bool, minus: str = "") -> str:
    """The largest entry of ``|expr|`` (less ``minus`` entry by entry)."""
    a = _abs(expr, matrix) + (f" - {minus}" if minus else "")
    return f"lmax({a})" if matrix else a


def _tol(scale: float, floor: bool = True) -> str:
    return repr(RTOL * scale + (1e-12 if floor else 0.0))


def _near(inp: str, value: np.ndarray, scale: float, floor: bool = True) -> str:
    """``is`` the answer within the tolerance of ``value`` (``floor``: plus 1e-12, as the
    grader compares with the key; a slip's value is compared relative to itself alone,
    as :func:`rigidsym.course.box_kinds.slip_close`)."""
    return f"is({_dist(f'{inp} - {_lit(value)}', value.ndim > 0)} <= {_tol(scale, floor)})"


def _wrapped(inp: str, value: np.ndarray, period: float, scale: float) -> str:
    """An angle within tolerance of ``value`` modulo ``period`` (reduced to
    [-period/2, period/2) by ``floor``, as the grader reduces it)."""
    x = f"({inp} - {_lit(value)})"
    P = repr(float(period))
    return f"is(abs({x} - {P}*floor(({x} + {P}/2)/{P})) <= {_tol(scale)})"


def _along(inp: str, value: np.ndarray, d: np.ndarray, scale: float) -> str:
    """A point within tolerance of the line through ``value`` along the unit ``d``: the
    cross product of the offset with d (a matrix product with d's skew matrix) near 0."""
    D = np.array([[0, -d[2], d[1]], [d[2], 0, -d[0]], [-d[1], d[0], 0]], dtype=float)
    col = value.reshape(-1, 1) if value.ndim == 1 else value
    return (f"is(lmax(abs(flatten(args({_lit(D)} . ({inp} - {_lit(col)}))))) <= "
            f"{_tol(scale)})")


def _scale(a: np.ndarray) -> float:
    return max(float(np.max(np.abs(a))) if a.size else 0.0, 1e-300)


def _lit(a: np.ndarray) -> str:
    """A float array as Maxima: ``matrix([..],[..])`` (a vector as a column), or a
    number (17 significant digits, ``repr``)."""
    a = np.asarray(a, dtype=float)
    if a.ndim == 0:
        return repr(float(a))
    m = a.reshape(-1, 1) if a.ndim == 1 else a
    return "matrix(" + ",".join("[" + ",".join(repr(float(x)) for x in r) + "]"
                                for r in m) + ")"


def _x(text: str) -> str:
    return html.escape(str(text), quote=False)
