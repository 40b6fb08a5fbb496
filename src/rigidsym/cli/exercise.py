"""``rigidsym exercise``: solve, vary and check the chapter's exercises; write notebooks.

``rigidsym exercise 3.4`` prints the worked solution on the book's data;
``--set n_1=0,0,5`` and ``--data FILE.json`` give other data (checked as
:func:`rigidsym.exercises.solve` checks them), ``--parameters`` lists them,
``--notebook PATH`` writes the exercise's notebook. The report hook (``exercises.md``,
``exercises.html`` and the figures) is :mod:`rigidsym.course.exercise_report`.
"""

from __future__ import annotations

import json
import sys
import textwrap
from pathlib import Path

from rigidsym.core.files import write_atomic

__all__ = ["add_arguments", "run", "to_json", "parse_value"]  # and, lazily, write_report, svg_text



def __getattr__(name: str):
    # the report hook, re-exported; imported when asked for (`rigidsym --help` stays light)
    if name in ("svg_text", "write_report"):
        from rigidsym.course import exercise_report as exercises
        return getattr(exercises, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


HELP = "solve a chapter-3 exercise, machine-checked (no id: list them)"
EXAMPLES = """\
  rigidsym exercise                   the 21 exercises with their titles
  rigidsym exercise 3.10              a worked solution on the book's data
  rigidsym exercise 3.4 --set f_2=1,1,1   on your own data (--parameters lists them)
  rigidsym exercise --all --format json   every exercise's answers as JSON on stdout"""


def add_arguments(p) -> None:
    """Arguments of ``rigidsym exercise``."""
    p.add_argument("id", nargs="?",
                   help="exercise id: 3.10 or ex3.10 (default: none, list the exercises)")
    p.add_argument("--all", action="store_true", help="solve all 21 exercises (default: off)")
    p.add_argument("--json", metavar="PATH", nargs="?", const="-",
                   help="also write the results (schema 2: data, answers, checks) as JSON "
                        "to PATH (no PATH: to stdout; default: none)")
    p.add_argument("--format", choices=("plain", "json"),
                   help="what goes to stdout: the solution (one line per exercise with "
                        "--all), or the JSON document (default: plain)")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="a datum of the exercise (repeatable): n_1=0,0,5 (a vector), "
                        "I_A='1,0,0;0,2,0;0,0,3' (a matrix, rows split by ;), a=0.05; "
                        "values are exact: 5/3, 0.1 (= 1/10), sqrt(3)/2; a unit after a "
                        "space applies to every entry: 'd=0,0,100 mm', '30 deg', 'N m' "
                        "(a bare number is in the unit --parameters lists)")
    p.add_argument("--data", metavar="FILE.json",
                   help="the data as a JSON object {name: value}; JSON numbers with a "
                        "decimal point are floats, read as measurements; strings are exact")
    p.add_argument("--tol", help="tolerance of measured data (the exercises whose data are "
                                 "measurements, as --parameters says); given, it selects the "
                                 "least-squares path")
    p.add_argument("--grade", metavar="ANSWERS",
                   help="grade a student's answers (a JSON file {name: value}, or a folder "
                        "or CSV of them for a class) against the solution on the data; "
                        "names the slip of a wrong answer (with --json: JSON)")
    p.add_argument("--parameters", action="store_true",
                   help="list the exercise's data (names, the book's values, shapes, units)")
    p.add_argument("--notebook", metavar="PATH",
                   help="write the exercise's Jupyter notebook (with the data given) to PATH")


def to_json(ids, data: dict | None = None) -> str:
    """The schema-2 JSON key for the exercises ``ids`` (``data`` for a single id):
    ``{"schema": 2, "python_flint": ..., "exercises": [record, ...]}``, a record per
    :func:`rigidsym.course.worked.solution_record` (the data solved on, the answers,
    the statements in words, the checks; ``reason`` when ill-posed)."""
    from rigidsym.course import solution_record
    from rigidsym.course import solve_exercise as solve
    from rigidsym.report.record import document_header

    items = [solution_record(solve(i, **(data or {}))) for i in ids]
    return json.dumps({**document_header(), "exercises": items}, indent=2,
                      ensure_ascii=False) + "\n"


def parse_value(ex_id: str, name: str, text: str):
    """The text of ``--set NAME=VALUE`` as the value :func:`solve` takes (the one reader,
    :func:`rigidsym.course.worked.numbers.split_text`, which :func:`solve` also
    applies to a string): a list of entry strings for a vector (``0,0,5``), a list of rows
    for a matrix (``1,0,0;0,2,0;0,0,3`` or ``[[1,0,0],[0,2,0],[0,0,3]]``), the text itself
    for a scalar or a choice (an unknown name is left to :func:`solve`, which lists the
    exercise's parameters)."""
    from rigidsym.course import exercise_parameters as parameters
    from rigidsym.course import split_text, split_unit

    if split_unit(text)[1] is not None:
        return text.strip()   # a unit for every entry: solve() splits and converts
    try:
        shape = parameters(ex_id)[name].shape
    except KeyError:
        return text
    return split_text(shape or (), text)


def _data(args, ex_id: str) -> dict:
    """The data of ``--data`` and ``--set`` (``--set`` wins), ``tol`` included."""
    data: dict = {}
    if args.data:
        try:
            loaded = json.loads(Path(args.data).read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            raise ValueError(f"--data: cannot read {args.data}: {exc}") from None
        if not isinstance(loaded, dict):
            raise ValueError(f"--data: expected a JSON object {{name: value}} in {args.data}")
        data.update(loaded)
    for item in args.set:
        name, sep, text = item.partition("=")
        if not sep or not name.strip():
            raise ValueError(f"--set: expected NAME=VALUE, got {item!r}")
        data[name.strip()] = parse_value(ex_id, name.strip(), text)
    if args.tol is not None:
        data["tol"] = args.tol
    return data


def _notebook(ex_id: str, path: str, data: dict) -> None:
    """Write the notebook: built with the data (nbformat), or copied from the package."""
    try:
        from rigidsym.course import write_notebook
        print(f"wrote {write_notebook(ex_id, path, **data)}")
    except ModuleNotFoundError as exc:
        if exc.name != "nbformat":
            raise
        if data:
            raise ValueError("--notebook with data needs nbformat: pip install "
                             "\"rigidsym[notebooks]\"") from None
        from importlib.resources import files

        from rigidsym.course import file_name
        packaged = files("rigidsym.generated") / "notebooks" / file_name(ex_id)
        print(f"wrote {write_atomic(path, packaged.read_text(encoding='utf-8'))}")


#: exit codes of ``rigidsym exercise`` (docs/exercise-data.md)
EXIT_SOLVED, EXIT_ILL_POSED, EXIT_BAD_INPUT, EXIT_INTERNAL = 0, 1, 2, 3
#: a case the solver does not handle ("not solved for these data: ..."): its limit, not
#: the data's, so never the code of an ill-posed exercise
EXIT_NOT_SOLVED = 4


def run(args) -> int:
    """Solve chapter-3 exercises with computer algebra (worked solutions, machine-checked).

    Exit codes: 0 solved and checked, 1 ill-posed (one sentence says why), 2 bad input
    (one line names the argument), 3 an internal error (a defect: please report it), 4 not
    solved for these data (a case the solver does not handle; one sentence says which)."""
    try:
        return _run(args)
    except Exception as exc:  # noqa: BLE001 - a defect must never read as an answer
        import traceback
        where = traceback.extract_tb(exc.__traceback__)[-1]
        print(f"rigidsym: internal error, please report: {type(exc).__name__}: {exc} (at "
              f"{Path(where.filename).name}:{where.lineno}; rigidsym exercise "
              f"{' '.join(sys.argv[2:]) or ''})".rstrip(), file=sys.stderr)
        return EXIT_INTERNAL


def _run(args) -> int:
    from rigidsym.course import EXERCISE_IDS, normalise_id, render_text
    from rigidsym.course import exercise_parameters as parameters

    if args.all and args.id:
        print("rigidsym: error: give one exercise id or --all, not both", file=sys.stderr)
        return EXIT_BAD_INPUT
    if not args.all and not args.id:
        return _list()
    varied = args.set or args.data or args.tol is not None
    grade = getattr(args, "grade", None)
    try:
        if args.all and (varied or args.notebook or args.parameters or grade):
            raise ValueError("--set, --data, --tol, --parameters, --grade and --notebook "
                             "take one exercise id, not --all")
        ids = EXERCISE_IDS if args.all else [normalise_id(args.id)]
        if args.parameters:
            print(parameters(ids[0]))
            return EXIT_SOLVED
        data = {} if args.all else _data(args, ids[0])
        if args.notebook:
            _notebook(ids[0], args.notebook, data)
            return EXIT_SOLVED
        if args.all:
            fmt = "json" if args.json == "-" else args.format or "plain"
            return _run_all(ids, fmt, None if args.json == "-" else args.json)
        s = _solve_one(ids[0], data)
        if grade:
            from rigidsym.cli.grade import grade_command
            return grade_command(s, grade, args.json)
        to_stdout = args.format == "json" or args.json == "-"
        if args.json or to_stdout:
            doc = to_json(ids, data)
            if args.json and args.json != "-":
                write_atomic(args.json, doc)
    except (ValueError, TypeError) as exc:
        print(f"rigidsym: error: {exc} ({_next_step(args)})", file=sys.stderr)
        return EXIT_BAD_INPUT
    if to_stdout:
        sys.stdout.write(doc)
    else:
        print(render_text(s, ascii_only=_ascii(args)))
    return _exit_code(s)


def _ascii(args) -> bool:
    """Whether the output is plain ASCII (``--ascii`` in either place, RIGIDSYM_ASCII, or
    a terminal that cannot show Unicode: stdout is then an ASCII stream)."""
    from rigidsym.printing.ascii import AsciiStream

    return bool(getattr(args, "ascii", False)) or isinstance(sys.stdout, AsciiStream)


def answers_text(s) -> str:
    """The answers of a solution, one ``name = value`` per answer in sympy's one-line form
    (with a float beside an exact number), lines of at most 100 columns, indented; or the
    reason of an ill-posed or not solved one."""
    import textwrap

    import sympy as sp

    from rigidsym.course import display

    if s.status != "solved":
        return textwrap.fill(s.reason, 100, initial_indent="    ", subsequent_indent="      ")
    out = []
    for k, v in s.answers.items():
        def listed(m):      # a column as one list, a matrix as a list of rows
            return m.T.tolist()[0] if m.cols == 1 else m.tolist()

        shown = display(v)
        text = (v if isinstance(v, str) else sp.sstr(listed(shown))
                if isinstance(v, sp.MatrixBase) else sp.sstr(shown))
        if isinstance(v, sp.Basic | sp.MatrixBase) and not isinstance(v, str):
            try:
                approx = sp.N(v, 6)
                approx = sp.sstr(listed(approx) if isinstance(v, sp.MatrixBase) else approx)
            except Exception:  # noqa: BLE001 - sympy's N refuses booleans and sets variously
                approx = text
            if approx != text and not (isinstance(v, sp.Basic) and v.free_symbols):
                text += f"  (~ {approx})"
        out.append(textwrap.fill(f"{k} = {text}", 100, initial_indent="    ",
                                 subsequent_indent="        ", break_on_hyphens=False))
    return "\n".join(out)


def _exit_code(s) -> int:
    """0 solved and checked, 1 ill-posed, 4 not solved; a solution whose own checks fail
    is a defect."""
    if s.status == "ill-posed":
        return EXIT_ILL_POSED
    if s.status == "not solved":
        return EXIT_NOT_SOLVED
    if s.checked:
        return EXIT_SOLVED
    failed = [c.name for c in s.checks if not c.passed] or ["no check ran"]
    print(f"rigidsym: internal error, please report: exercise {s.id[2:]} was solved but "
          f"its machine check failed ({'; '.join(failed)})", file=sys.stderr)
    return EXIT_INTERNAL


def _next_step(args) -> str:
    """What to run after a bad exercise id or bad data."""
    from rigidsym.course import normalise_id

    try:
        ex = normalise_id(args.id) if args.id else None
    except ValueError:
        return "rigidsym exercise lists the exercises"
    if ex and (args.set or args.data or args.tol is not None):
        return f"rigidsym exercise {ex[2:]} --parameters lists its data"
    return "rigidsym exercise --help shows the options"


def _list() -> int:
    """``rigidsym exercise`` with no id: the exercises and their titles, read from the
    modules' ``TITLE`` constants (nothing is solved)."""
    from rigidsym.course import EXERCISE_IDS, exercise_module

    print(f"The book's {len(EXERCISE_IDS)} exercises (rigidsym exercise {EXERCISE_IDS[0][2:]} "
          f"solves one; --all solves all):")
    for i in EXERCISE_IDS:
        print(f"  {i[2:]:5s} {getattr(exercise_module(i), 'TITLE', '')}")
    return 0


def _solve_one(ex_id: str, data: dict):
    """Solve one exercise with a spinner on stderr (a solution can take seconds)."""
    from rigidsym.core.progress import Reporter
    from rigidsym.course import exercise_parameters as parameters
    from rigidsym.course import read_data
    from rigidsym.course import solve_exercise as solve

    # bad data is one error line, before any progress line
    rest = {k: v for k, v in data.items() if k != "tol"}
    for note in read_data(parameters(ex_id), rest, data.get("tol")).notes:
        if note.startswith("Warning: "):
            print(textwrap.fill(f"rigidsym: warning: {note[len('Warning: '):]}", 100,
                                subsequent_indent="  ", break_long_words=False,
                                break_on_hyphens=False), file=sys.stderr)   # 100 columns
    with Reporter("rigidsym exercise") as rep, \
            rep.phase(f"solving exercise {ex_id[2:]}") as ph:
        s = solve(ex_id, **data)
        ph.finish(f"{s.status}, {'checked' if s.checked else 'NOT checked'}")
    return s


def _run_all(ids, fmt: str, json_path: str | None) -> int:
    """Solve every exercise with progress on stderr; a line per exercise (or the JSON
    document) on stdout."""
    from rigidsym.core.progress import Reporter
    from rigidsym.course import solve_exercise as solve

    n_ok = 0
    with Reporter("rigidsym exercise --all") as rep, \
            rep.phase(f"solving {len(ids)} exercises", total=len(ids)) as ph:
        for i in ids:
            ph.label(f"solving exercise {i[2:]}")
            s = solve(i)
            ok = s.status == "solved" and s.checked
            n_ok += ok
            ph.advance(1, label=f"exercise {i[2:]} {s.status}")
            if fmt == "plain":
                print(f"{s.id:7s} {s.status:8s} checked={str(s.checked).lower():5s} {s.title}")
                print(answers_text(s), flush=True)
        ph.finish(f"{n_ok} / {len(ids)} solved and checked")
    if json_path or fmt == "json":
        doc = to_json(ids)  # from the solutions just cached
        if json_path:
            write_atomic(json_path, doc)
        if fmt == "json":
            sys.stdout.write(doc)
    if fmt == "plain":
        print(f"{n_ok} / {len(ids)} solved and checked")
    return 0 if n_ok == len(ids) else 1
