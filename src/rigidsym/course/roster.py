"""A class from a roster: one exam per student, one key, a Moodle export.

``class_exam(spec, roster, out_dir)`` draws, for every student of the roster, the spec's
problems from the student's own seed (``student_seed``: the spec's seed and the name),
every drawn problem different from every other student's (a repeat is drawn again), and
writes::

    DIR/handouts/<id>.html        name, seed and version printed on every page; named by
                                  the student id (by the name, in any script, without one)
    DIR/keys/<id>.html            that student's worked, checked solutions
    DIR/key.json                  schema 2: per student, the seed, version and each
                                  problem's data, answers and checks
    DIR/key.html                  the worked, checked solutions, student by student
    DIR/answers.csv               the answers template: a row per student, a column
                                  ``P<k>.<answer>`` per box (fill it, grade it)
    DIR/moodle.xml                Moodle XML: a Cloze question per student and problem,
                                  the answers as NUMERICAL parts within 0.1 %
    DIR/stack.xml                 Moodle XML: a STACK question per student and problem,
                                  a PRT per box grading as the gradebook does
                                  (:mod:`rigidsym.course.stack_export`)

The same spec, roster and seed write the same bytes.
"""

from __future__ import annotations

import csv
import hashlib
import html
import io
import json
import math
import pickle
import re
from pathlib import Path

import sympy as sp

from rigidsym.core import cache as _cache
from rigidsym.core import interrupts
from rigidsym.core.files import write_atomic
from rigidsym.course import exam as _exam
from rigidsym.course.box_kinds import box_kind
from rigidsym.course.exam_text import box_label, lms_statement, task
from rigidsym.course.gradebook import checked_weights, key_value
from rigidsym.course.stack_export import stack_xml
from rigidsym.course.worked import exercise_module, render_html, solution_record
from rigidsym.course.worked.units import answer_unit

__all__ = ["class_exam", "read_roster", "student_seed", "version_of"]


def read_roster(path: str | Path) -> list[dict]:
    """The students of a roster CSV: a ``name`` (or ``student``) column, or Moodle's
    participant export (``First name``, ``Surname`` or ``Last name``); optional ``id``
    (``ID number``) and ``email`` (``Email address``) columns, kept for the gradebook an
    LMS imports. UTF-8 with or without a BOM, ``,``, ``;`` or tab separated (as
    :func:`rigidsym.course.answers.read_table` reads it). Two students of one name are
    fine when their ids differ (their answers are then matched by id only).

    Returns:
        ``[{"name", "id", "email"}, ...]`` in the roster's order.

    Raises:
        ValueError: the file is unreadable, has no name columns, a row without a name, a
            name twice without distinct ids, or an id twice (the message names the roster
            and the row).
    """
    from rigidsym.course.answers import read_table

    p = Path(path)
    rows = read_table(p, "--students")
    cols = {c.strip().lower(): c for c in (rows[0].keys() if rows else []) if c}
    name_col = cols.get("name") or cols.get("student") or cols.get("full name")
    first = cols.get("first name")
    last = cols.get("surname") or cols.get("last name")
    if not rows or (name_col is None and not (first and last)):
        raise ValueError(f"--students: {p} needs a header row with a 'name' (or 'student') "
                         f"column, or Moodle's 'First name' and 'Surname', and a row per "
                         f"student")
    id_col = cols.get("id") or cols.get("id number") or cols.get("student id")
    email_col = cols.get("email") or cols.get("email address")
    out, seen, ids = [], {}, set()
    for i, r in enumerate(rows, 2):
        name = (r.get(name_col) or "").strip() if name_col else \
            f"{(r.get(first) or '').strip()} {(r.get(last) or '').strip()}".strip()
        ident = (r.get(id_col, "") or "").strip() if id_col else ""
        if not name:
            raise ValueError(f"--students: {p} row {i} has no name")
        if name in seen and (not ident or not seen[name] or ident in ids):
            raise ValueError(f"--students: {p} row {i}: {name!r} is in the roster twice "
                             f"(two students of one name need distinct ids)")
        if ident and ident in ids:
            raise ValueError(f"--students: {p} row {i}: the id {ident!r} is in the roster "
                             f"twice")
        seen[name] = ident
        if ident:
            ids.add(ident)
        out.append({"name": name, "id": ident,
                    "email": (r.get(email_col, "") or "").strip() if email_col else ""})
    return out


def student_seed(seed: int, name: str) -> int:
    """The seed of one student's exam: 8 hex digits of SHA-256 of the class seed and the
    name (``rigidsym exam SPEC --seed`` with it draws the same problems, repeats aside)."""
    return int(hashlib.sha256(f"{seed}:{name}".encode()).hexdigest()[:8], 16)


def version_of(sols: list) -> str:
    """A short version of an exam: 6 letters (no digit, so no number on the sheet reads
    as an answer) of a hash of its problems' exercises and data, so a returned sheet is
    matched to its key."""
    text = "|".join(f"{s.id}:{sorted((k, str(v)) for k, v in s.data.items())!r}"
                    for s in sols)
    h = int(hashlib.sha256(text.encode()).hexdigest(), 16)
    return "".join("ABCDEFGHJKLMNPQRSTUVWXYZ"[(h >> (5 * i)) % 24] for i in range(6))


def _slug(st: dict) -> str:
    """A student's file name: the student id when the roster gives one, else the name
    with its letters kept in any script (``山田_太郎``, ``José_Núñez``, NFC)."""
    import unicodedata

    text = st["id"] or unicodedata.normalize("NFC", st["name"])
    return re.sub(r"[^\w]+", "_", text).strip("_") or "student"


def _head(title: str, st: dict, seed: int, version: str) -> str:
    who = html.escape(st["name"]) + (f" ({html.escape(st['id'])})" if st["id"] else "")
    return (f"<p class=\"student\"><b>Student:</b> {who} &nbsp; <b>Seed:</b> {seed} &nbsp; "
            f"<b>Version:</b> {version}</p>\n")


def _draw_student(ctx: dict, i: int, taken: dict | None = None) -> dict:
    """Student i's exam of :func:`class_exam` (``ctx``: its spec, roster, seeds, file
    names, title, folder and weights): drawn (against ``taken``: the draws of the students
    before i), its handout written; its key record and section, and its drawn data keys."""
    spec, students, seeds, slugs = ctx["spec"], ctx["students"], ctx["seeds"], ctx["slugs"]
    title, out, given, slots = ctx["title"], ctx["out"], ctx["given"], ctx["slots"]
    spec_weights = ctx["spec_weights"]
    st, own = students[i], seeds[i]
    drawn = _exam.drawn_exercises(spec, own, taken)
    sols = [s for s, _ in drawn]
    version = version_of(sols)
    head = _head(title, st, own, version)
    files = {f"handouts/{slugs[i]}.html": _exam.handout_text(f"{title}: {st['name']}",
                                                             sols, head, columns=True)}
    section = _key_section(head, sols)
    files[f"keys/{slugs[i]}.html"] = _exam.handout_page(
        f"{title}: answer key of {st['name']}", section)
    for rel, text in files.items():
        write_atomic(out / rel, text)
    problems = [dict(solution_record(s), problem=n, spec_problem=k,
                     weight=given[n - 1] if given is not None else spec_weights[k - 1],
                     asked=_exam.asked(s),
                     labels={a: box_label(s.id, a) for a in _exam.asked(s)},
                     task=task(s.id, s.statement))
                for n, (s, k) in enumerate(drawn, 1)]
    return {"record": {"student": st["name"], "id": st["id"], "email": st["email"],
                       "seed": own, "version": version,
                       "handout": f"handouts/{slugs[i]}.html", "problems": problems},
            "section": section, "files": files,
            "drawn": [(slot, _exam.variant_key(s)) for slot, s in zip(slots, sols, strict=True)
                      if slot is not None]}


def class_exam(spec, roster: str | Path, out_dir: str | Path,
               seed: int | None = None, weights: list[float] | None = None
               ) -> dict[str, Path]:
    """One exam per student of ``roster``, one key, an answers template and a Moodle XML
    export, in ``out_dir`` (see the module docstring).

    Args:
        spec: a TOML file path or a dict, as :func:`rigidsym.course.exam.exam` takes.
        roster: a CSV with a ``name`` (or ``student``) column; ``id``, ``email`` optional.
        out_dir: the folder to write (made if missing).
        seed: the class seed (default: the spec's ``seed``, else 0).
        weights: each problem's weight (its points in the gradebook and the exports), one
            per problem of the exam in the handout's order (problem 1 first: a spec
            problem of ``variants = 2`` is two), in place of the spec problems' ``weight``
            (default: theirs, else 1). Kept in ``key.json``.

    Returns:
        ``{"handouts": folder, "keys": folder, "key_json", "key_html", "answers",
        "moodle", "stack"}``.

    Raises:
        ValueError: a bad spec or roster, ``weights`` not one finite number >= 0 per
            problem with a positive sum (the message names ``weights``, before anything
            is drawn), or no new well-posed variant in 50 draws.
    """
    import matplotlib
    matplotlib.use("Agg", force=False)
    from rigidsym.report.record import document_header

    spec = _exam.read_spec(spec)
    seed = int(spec.get("seed", 0) if seed is None else seed)
    title = str(spec.get("title", "Rigid-body mechanics: exercises"))
    slots = _slots(spec)
    # problem n's weight: given, one per problem of the exam; else its spec problem's
    given = None if weights is None else checked_weights(weights, len(slots))
    spec_weights = [float(p.get("weight", 1)) for p in spec["problem"]]
    students = read_roster(roster)
    out = Path(out_dir)
    slugs = _unique_slugs(students)
    seeds = [student_seed(seed, st["name"]) for st in students]

    ctx = {"spec": spec, "students": students, "seeds": seeds, "slugs": slugs, "title": title,
           "out": out, "given": given, "spec_weights": spec_weights, "slots": slots}
    kept_at = [_kept_at(spec, seed, title, given, st, slug, own)
               for st, slug, own in zip(students, slugs, seeds, strict=True)]
    interrupts.note_kept(lambda: sum(_cache.get(p) is not None for p in kept_at),
                         len(students), "students")

    def make(i: int, taken: dict | None = None) -> dict:
        """Student i's exam: kept from an earlier run of the same class (its files
        written again only where they differ), else drawn and kept."""
        if taken is None:
            blob = _cache.get(kept_at[i])
            if blob is not None:
                done = pickle.loads(blob)
                for rel, text in done.pop("files").items():
                    _write_if_changed(out / rel, text)
                interrupts.checkpoint("advance")
                return done
        done = _draw_student(ctx, i, taken)
        if taken is None:
            _cache.put(kept_at[i], pickle.dumps(done))
        interrupts.checkpoint("advance")
        done.pop("files")
        return done

    made = _draw_all(make, len(students))
    records = [m["record"] for m in made]
    keys_html = [m["section"] for m in made]
    columns = {f"P{p['problem']}.{a}": None for r in records for p in r["problems"]
               for a in p["asked"]}
    key = {**document_header(), "title": title, "seed": seed,
           "slip_credit": float(spec.get("slip_credit", 0)),
           "rounding_credit": float(spec.get("rounding_credit", spec.get("slip_credit", 0))),
           "slips_along_the_way": spec.get("slips_along_the_way", True),
           "students": records}
    return {
        "handouts": out / "handouts", "keys": out / "keys",
        "key_json": write_atomic(out / "key.json", json.dumps(key, indent=2,
                                                              ensure_ascii=False) + "\n"),
        "key_html": write_atomic(out / "key.html", _exam.handout_page(f"{title}: answer key",
                                                               "\n".join(keys_html))),
        "answers": write_atomic(out / "answers.csv", _template(students, list(columns))),
        "moodle": write_atomic(out / "moodle.xml", moodle_xml(title, key)),
        "stack": write_atomic(out / "stack.xml", stack_xml(title, key)),
    }


def _kept_at(spec: dict, seed: int, title: str, weights, st: dict, slug: str,
             own: int) -> Path:
    """Where one student's finished exam is kept in the user cache (``verdicts/``): keyed
    by the spec, the class seed, the title, the weights, the student's record, file name
    and seed, every source file of the package and the book, and the libraries'
    versions; a class exam interrupted and run again draws only the students not kept."""
    from rigidsym.core import sources as _sources

    h = hashlib.sha256()
    for part in ("class exam 1", _sources.package_digest(), _sources.environment(),
                 json.dumps(spec, sort_keys=True, default=str), str(seed), title,
                 repr(weights), json.dumps(st, sort_keys=True, default=str), slug,
                 str(own)):
        h.update(part.encode() + b"\0")
    key = h.hexdigest()
    return _cache.folder("verdicts") / key[:2] / f"exam-{key}.pickle"


def _write_if_changed(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` (atomically) unless the file already holds it."""
    try:
        if path.read_text(encoding="utf-8") == text:
            return
    except (OSError, UnicodeDecodeError):
        pass
    write_atomic(path, text)


def _unique_slugs(students: list[dict]) -> list[str]:
    """One file name per student, in roster order, each distinct (``"Amy Ames"`` and
    ``"Amy-Ames"``: two files)."""
    slugs: list[str] = []
    for st in students:
        slug = _slug(st)
        while slug in slugs:
            slug += "_"
        slugs.append(slug)
    return slugs


def _draw_all(make, n: int) -> list[dict]:
    """``make(i)`` of every student i < n, drawn at once (forked workers: the solves and
    figures); then, in roster order, a student whose draw repeats an earlier student's is
    drawn again here against the draws before it (``make(i, taken)``): the same exams as
    drawing one student after another."""
    from rigidsym.course.forked import forked_map

    # the first student here: the workers, forked after it, inherit what it warmed (the
    # exercise modules imported, 3.12's integrals in a symbolic side and height, the
    # figures' fonts) instead of each warming them again
    made = [make(0)] if n else []
    made += forked_map(lambda i: make(i + 1), n - 1)
    taken: dict = {}
    for i, m in enumerate(made):
        if any(key in taken.get(slot, ()) for slot, key in m["drawn"]):
            made[i] = make(i, taken)
        else:
            for slot, key in m["drawn"]:
                taken.setdefault(slot, set()).add(key)
    return made


def _slots(spec: dict) -> list:
    """The draw slot ``(spec problem, variant)`` of each problem of an exam, in order;
    ``None`` for a problem on given data (the same for every student)."""
    out = []
    for k, p in enumerate(spec["problem"], 1):
        out += [(k, v) for v in range(int(p["variants"]))] if "variants" in p else [None]
    return out


def _key_section(head: str, sols: list) -> str:
    parts = [f"<section class=\"problem\">{head}"]
    for k, s in enumerate(sols, 1):
        parts.append(f"<h2>Problem {k}</h2>{_exam.data_table(s)}{render_html(s)}")
    return "".join(parts) + "</section>"


def _template(students: list, columns: list) -> str:
    buf = io.StringIO()
    # every cell quoted: an id such as 00042 stays one text field to a CSV reader
    w = csv.writer(buf, lineterminator="\n", quoting=csv.QUOTE_ALL)
    w.writerow(["student", "id", *columns])
    for st in students:
        w.writerow([st["name"], st.get("id") or ""] + [""] * len(columns))
    return "\ufeff" + buf.getvalue()       # a BOM: Excel reads the names' accents right


def moodle_xml(title: str, key: dict) -> str:
    """Moodle XML (``<quiz>``): a category per student (name and id; the questions'
    ``idnumber`` ``<id>-P<k>``), a Cloze (embedded answers)
    question per problem, each entry of each answer a ``NUMERICAL`` part right within
    0.1 % of the answer's largest entry (the grader's tolerance). Moodle marks a Cloze
    question by its parts' integer weights (it ignores ``<defaultgrade>``): each box's
    entries share lcm(the problem's entry counts) marks, so every box weighs the same, as
    in the gradebook; a true-or-false box is a ``MULTICHOICE`` of ``true`` and ``false``,
    as its label asks. Moodle still scores entry by entry (a box graded jointly, an
    equivalent form or a slip's credit is rigidsym's: import ``gradebook.csv``, or use
    ``stack.xml``; which boxes Moodle scores as the gradebook: docs/exams.md)."""
    from rigidsym.course.answer_classes import declared, names_of
    from rigidsym.course.grading import RTOL

    along = bool(key.get("slips_along_the_way", True))
    out = ['<?xml version="1.0" encoding="UTF-8"?>', "<quiz>"]
    for st in key["students"]:
        # by id as well: two students of one name get two categories, unique idnumbers
        who = f"{st['student']} ({st['id']})" if st.get("id") else st["student"]
        out.append(f"<question type=\"category\"><category><text>$course$/{_x(title)}/"
                   f"{_x(who)}</text></category></question>")
        for p in st["problems"]:
            mod = exercise_module(p["id"])
            body = [lms_statement(p)]
            # each box's key read once (a parse and an exact evaluation per entry)
            floats = {a: _floats(p["answers"][a]) for a in p["asked"]}
            counts = {a: len(v) for a, v in floats.items() if v}
            # a box whose class is declared (an angle whose sign goes with its axis) is
            # right or wrong with its other pieces: no per-number credit in Moodle
            classed = {n for d in declared(mod) for n in names_of(d)}
            whole = math.lcm(*counts.values()) if counts else 1
            for a in p["asked"]:
                vals = floats[a]
                if vals is None:            # an expression in symbols: read on paper
                    body.append(f"<p>{html.escape(p['labels'][a])}: (an expression, "
                                f"graded on paper or by rigidsym grade)</p>")
                    continue
                scale = max([abs(v) for v in vals] + [1e-300])
                # each box weighs the same (the gradebook's mean of boxes): its entries
                # share lcm(entry counts) integer marks, as Moodle reads a part's weight
                w = whole // len(vals)
                tol = f"{RTOL * scale:.3g}"
                kind = box_kind(mod, a, key_value(p["answers"][a]) if not
                                isinstance(p["answers"][a], list) else None,
                                answer_unit(mod, a))
                exact = kind in ("truth", "reason", "count")
                extra = "" if a in classed or exact or len(vals) != 1 else \
                    _slip_answers(vals, _one_number_slips(p, a, along),
                                  key.get("slip_credit", 0),
                                  key.get("rounding_credit", key.get("slip_credit", 0)))
                if kind == "truth":   # one choice of the truths in order: all or nothing
                    parts = _truth_choice(vals, whole)
                elif exact:          # the numbers in order, as typed: all or nothing
                    parts = _exact_answer(vals, whole)
                else:
                    parts = " ".join(f"{{{w}:NUMERICAL:={v!r}:{tol}{extra}}}" for v in vals)
                body.append(f"<p>{html.escape(p['labels'][a])}: {parts}</p>")
            name = f"{st['student']}: problem {p['problem']} (Exercise {p['id'][2:]})"
            out.append(f"<question type=\"cloze\"><name><text>{_x(name)}</text></name>"
                       f"<questiontext format=\"html\"><text><![CDATA[{''.join(body)}]]>"
                       f"</text></questiontext><generalfeedback><text></text>"
                       f"</generalfeedback><defaultgrade>{p['weight']:g}</defaultgrade>"
                       f"<idnumber>{_x(st.get('id') or st['student'])}-P{p['problem']}</idnumber>"
                       f"</question>")
    out.append("</quiz>")
    return "\n".join(out) + "\n"


def _truth_choice(vals: list[float], weight: int) -> str:
    """A truth box as one ``MULTICHOICE`` of every combination of its truths in order
    (``true, false, true``): right only with every truth right, as the gradebook scores
    the box."""
    import itertools

    words = ("false", "true")
    right = tuple(int(round(v)) for v in vals)
    choices = [", ".join(words[t] for t in c) for c in itertools.product((1, 0),
                                                                        repeat=len(vals))]
    mark = [("=" if c == ", ".join(words[t] for t in right) else "") + c for c in choices]
    return f"{{{weight}:MULTICHOICE:{'~'.join(mark)}}}"


def _exact_answer(vals: list[float], weight: int) -> str:
    """A reason or count box as one ``SHORTANSWER``: its whole numbers in order, with or
    without spaces after the commas (``1, 4, 1`` or ``1,4,1``); all or nothing."""
    nums = [str(int(round(v))) for v in vals]
    forms = dict.fromkeys((", ".join(nums), ",".join(nums), " ".join(nums)))
    return f"{{{weight}:SHORTANSWER:" + "~".join(f"={f}" for f in forms) + "}"


def _one_number_slips(p: dict, name: str, along: bool) -> list[float]:
    """The grader's slip values of a one-number box, in its order
    (:func:`rigidsym.course.grading.slip_values`: the slips the box's kind admits, and the
    replays along the way where the key's policy asks for them)."""
    from rigidsym.course.gradebook import solution_of
    from rigidsym.course.grading import key_array, replayed_values, slip_values

    sol = solution_of(p)
    target = key_array(sol.answers[name])
    replayed = replayed_values(sol) if along else []
    return [float(v.reshape(-1)[0]) for _, v in slip_values(sol, name, target,
                                                             replayed=replayed)
            if v.size == 1]


def _slip_answers(vals: list[float], slips: list[float], credit: float,
                  rounding: float = 0.0) -> str:
    """Moodle's partial credit (``~%n%value:tol``) of a one-number box: each of the
    grader's ``slips`` values (``slip_credit``), each within 0.1 % of itself as the grader
    compares a slip, then the key rounded to 1, 2 or 3 significant figures
    (``rounding_credit``, as :func:`rigidsym.course.grading.rounded_figures` names it:
    within 1e-9 relative). Where a box is one number, Moodle's part is the box, and scores
    as the gradebook (a slip is never 0: a zero answer earns none, as in the gradebook)."""
    from rigidsym.course.grading import RTOL

    if len(vals) != 1 or not vals[0]:
        return ""
    v, out = vals[0], []
    tol = f"{RTOL * abs(v) + 1e-12:.3g}"
    pct = round(100 * float(credit))
    if pct > 0:
        out += [f"~%{pct}%{x!r}:{RTOL * abs(x)!r}" for x in dict.fromkeys(slips) if x]
    pct = round(100 * float(rounding))
    if pct > 0:
        for n in range(1, 4):
            r = float(f"{v:.{n - 1}e}")
            if abs(r - v) > float(tol):   # a rounding inside the tolerance is right
                out.append(f"~%{pct}%{r!r}:{max(1e-9 * abs(r), 1e-12):.3g}")
    return "".join(out)


def _floats(v) -> list[float] | None:
    """An answer of the key as floats (a truth as 1 or 0), or None for an expression."""
    out = []
    for x in _flat(v):
        e = key_value(x)
        if e in (sp.true, sp.false):
            out.append(float(bool(e)))
        elif getattr(e, "is_number", False):
            out.append(float(sp.N(e, 17)))
        else:
            return None
    return out


def _x(text: str) -> str:
    return html.escape(str(text), quote=True)


def _flat(v) -> list:
    if isinstance(v, list):
        return [x for r in v for x in _flat(r)]
    return [v]
