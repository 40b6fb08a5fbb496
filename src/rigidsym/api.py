"""The public Python API: check one id, verify many, read and display the results.

    >>> import rigidsym
    >>> rigidsym.check("3.96e").verdict                       # doctest: +SKIP
    'does-not-hold'
    >>> rigidsym.verify(sections=["3.2"]).summary()           # doctest: +SKIP
    {'verified': ..., 'definition': ..., 'does-not-hold': ..., 'undecided': 0}

In Jupyter a :class:`Results` displays as a table and one :class:`Result` as mathematics
(MathML in HTML, LaTeX otherwise); ``repr`` stays one line. Both live in
:mod:`rigidsym.report.results` (their display is the report layer's), re-exported here.
"""

from __future__ import annotations

import os
import time
from collections.abc import Iterable, Sequence
from time import process_time
from types import ModuleType

from rigidsym.latex.statement import said_choices
from rigidsym.registry.declarations import BadInput, select
from rigidsym.report.results import Result, Results

__all__ = ["check", "check_latex", "verify", "Result", "Results"]

ModuleSpec = str | os.PathLike | ModuleType


def _load(modules) -> list[str]:
    """Load user modules (paths, dotted names or module objects); their import names."""
    from rigidsym.registry import usermodules

    if isinstance(modules, str | os.PathLike | ModuleType):
        modules = [modules]
    names = []
    for m in modules or ():
        um = usermodules.adopt(m) if isinstance(m, ModuleType) else usermodules.load(m)
        names.append(um.name)
    return names


def _repair_args(repairs, repair_budget) -> None:
    from rigidsym.registry.declarations import check_budget

    if not isinstance(repairs, bool):
        raise ValueError(f"repairs: expected True or False, got {repairs!r}")
    check_budget(repair_budget, "repair_budget", none_ok=True)


def check(eq_id: str, *, modules: Iterable[ModuleSpec] = (), repairs: bool = True,
          repair_budget: int | None = None, cache: bool = True) -> Result:
    """Decide one equation and back the verdict numerically.

    Args:
        eq_id: a book id (``"3.16"``, ``"3.96e"``, ``"thm3.2.1"``) or a user id
            (``"notes:rodrigues"``) of a loaded module or of ``modules``.
        modules: user modules to load first (paths, dotted names or module objects).
        repairs: for a member that does not hold, search the smallest edits that make it
            hold (``Result.repairs``; README, "Repairs").
        repair_budget: candidates tried per failing member (``None``: the declaration's
            ``repair_budget``, else 5000).
        cache: read the result from the verdict cache that :func:`verify` and the
            commands fill (``Result.cached`` then true) and store it there; ``False``
            checks it again and stores nothing.

    Returns:
        The :class:`Result`; its ``verdict`` is computed, never read from the declaration.
        An exception inside the declaration gives ``undecided`` with the error named.

    Raises:
        BadInput: for a malformed or unknown id, an id with several lettered parts
            (``"3.96"``: use :func:`verify`), or a user module that cannot be loaded.
        ValueError: if ``repairs`` or ``cache`` is not a bool or ``repair_budget`` not a
            non-negative integer.
    """
    from rigidsym.checking.runner import check_cached

    _repair_args(repairs, repair_budget)
    if not isinstance(cache, bool):
        raise ValueError(f"cache: expected True or False, got {cache!r}")
    _load(modules)
    ids = select([eq_id], None)
    if len(ids) != 1:
        raise BadInput(f"eq_id: {eq_id} has {len(ids)} parts ({', '.join(ids)}): check one, "
                       f"or verify([{eq_id!r}])")
    return Result.of(check_cached(ids[0], repairs=repairs, repair_budget=repair_budget,
                                  cache=cache))


#: the default time limit of check_latex's repair search, seconds
REPAIR_SECONDS = 10.0
#: the default time limit of one check_latex: 60 s, or the environment variable
#: RIGIDSYM_LATEX_TIMEOUT (rigidsym.latex.limit.default_seconds)
TIMEOUT = "default"


def check_latex(latex: str, let: Sequence[str] | dict[str, str] | str | None = None, *,
                book: str | None = None, modules: Iterable[ModuleSpec] = (),
                repairs: bool = True, repair_budget: int | None = None,
                notation: str | None = None,
                repair_seconds: float | None = REPAIR_SECONDS,
                timeout: float | str | None = TIMEOUT) -> Result:
    """Decide a relation written in LaTeX (the Python side of ``rigidsym check --latex``).

    The LaTeX is read by the chapter's reader (:func:`rigidsym.latex.parse_latex`); each
    relation it states is a printed member, the declarations ``let`` give the model, and
    the checker decides it as it decides a declaration (exactly, backed numerically; the
    constraints of the kinds imposed exactly, never by floating point).

    Args:
        latex: one or more relations (``=`` or ``\\equiv`` chains), e.g.
            ``r"\\mathbf{Q}^T\\mathbf{Q} = \\mathbf{1}"``.
        let: what the symbols are: a list of ``"NAME: KIND"`` (KIND one of
            :data:`rigidsym.latex.lets.KIND_WORDS`: ``unit vector``, ``rotation``,
            ``angle``, ``6-vector``, ``4x4 matrix``, ``twist`` ...) or ``"NAME = LATEX"`` (a
            first-principles model in the same notation); one string may hold several,
            separated by ``"; "``; or a dict ``{NAME: KIND or LATEX}``. A symbol nothing
            declares is free, its shape by the book's convention (bold lower-case a
            3-vector, bold capital 3 x 3, else a scalar), and ``Result.model`` says so.
        book: a section of the chapter (``"3.2"``, ``"3.4.2"``): the glyph table's rows of
            that section give the glyphs their meaning (names, shapes, angles, notational
            atoms such as ``E = CPM(e)``).
        modules: user modules that lend their symbols and models (module-level dicts of
            book symbols, ``MODEL`` first), matched by name.
        repairs: search the smallest edits that make a failing relation hold.
        repair_budget: candidates tried per failing relation (``None``: 5000).
        repair_seconds: a time limit of the repair search in seconds (default
            :data:`REPAIR_SECONDS`, 10; ``None``: none): past it the verdict is given with
            "search stopped after N s, K candidates tried".
        timeout: a limit of the whole check in seconds of CPU time (``None``: none; the default,
            ``"default"``: 60 s, or the environment variable ``RIGIDSYM_LATEX_TIMEOUT``,
            seconds or ``none``): past it the verdict is ``undecided``, its ``cause`` naming
            the step it was in (reading, the symbolic zero test, the other readings, the
            numeric cross-check) and a hint; ``method`` is ``time-limit``
            (``rigidsym.latex.limit``).
        notation: a book's symbol table (``"lynch-park"``, ``"murray-li-sastry"``,
            ``"siciliano"``, ``"spong"``, ``"craig"``, ``"featherstone"``, ``"barfoot"``,
            ``"sola"``, ``"corke"``, ``"jpl"``: ``rigidsym.latex.notations.NOTATIONS``): what its
            symbols are (``\\hat\\omega`` a unit vector in Lynch-Park, the skew matrix of
            ``\\omega`` in Murray-Li-Sastry; ``c_{12}`` a cosine in Siciliano), below
            ``let``.

    Returns:
        The :class:`Result` of the id ``latex:`` plus a short hash of the input; its
        ``expected`` repeats the verdict (a question has no expectation); ``model`` lists
        the declarations and the free symbols in words.

    Raises:
        rigidsym.latex.LatexError: LaTeX that cannot be read (the position with a caret and
            the constructs expected; an unknown macro named; a juxtaposition whose meaning
            depends on an undeclared shape asks for a ``let``). A ``ValueError``.
        BadInput: a declaration that is neither form, an unknown KIND (the kinds listed), a
            ``let`` naming a symbol that occurs nowhere while an undeclared glyph is spelt
            near it (an unused ``let`` otherwise is said back and ignored), an ambiguous
            glyph of ``book``, a module that cannot be loaded.
        ValueError: if ``repairs`` is not a bool, ``repair_budget`` not a non-negative
            integer, ``repair_seconds`` or ``timeout`` not a positive number.

    Example:
        >>> r = check_latex(r"\\mathbf{Q}^T\\mathbf{Q} = \\mathbf{1}",
        ...                 let=[r"\\mathbf{Q}: rotation"])      # doctest: +SKIP
        >>> r.verdict                                              # doctest: +SKIP
        'verified'
    """
    return check_latex_run(latex, let, book, modules, repairs, repair_budget, notation,
                           repair_seconds, timeout)[0]



def _seconds(x) -> float | None:
    if x is None:
        return None
    if isinstance(x, bool) or not isinstance(x, int | float) or not x > 0 or x != x:
        raise ValueError(f"repair_seconds: expected a positive number of seconds or None, "
                         f"got {x!r}")
    return float(x)


def check_latex_run(latex, let, book, modules, repairs=True, repair_budget=None, notation=None,
                 repair_seconds=REPAIR_SECONDS, timeout=TIMEOUT):
    """:func:`check_latex` and the :class:`rigidsym.latex.statement.Reading` (for the CLI;
    ``None`` where the time limit passed before the LaTeX was read)."""
    from rigidsym.latex import contested, limit, quaternions, tangent
    from rigidsym.latex.blackboard import declared_identity, open_blackboard
    from rigidsym.latex.principal import open_principal
    from rigidsym.numeval.conventions import declared_readings
    from rigidsym.numeval.values import quaternion_convention, quaternion_storage, tangent_order

    seconds = limit.default_seconds() if timeout == "default" else \
        limit.seconds_argument(timeout)
    _repair_args(repairs, repair_budget)
    _seconds(repair_seconds)
    let, order, said = tangent.split_setting(let, notation)
    let, product, product_said = quaternions.split_setting(let, notation)
    let, settled, settled_said = contested.split_settings(let)  # 'bracket cross: content'
    let, identity_said = declared_identity(let)  # '\mathbb{I}: identity' (Chirikjian's)
    if identity_said is not None:  # it joins the check's id
        settled_said = [*settled_said, identity_said]
    board_open = identity_said is None and open_blackboard(latex, let)
    principal = open_principal(latex, let)  # I_1, I_2, I_3: identities or moments
    product_fixed = product_said is not None or notation in quaternions.NOTATION_PRODUCTS
    # the user's own lets may fix the storage order (scalar last); the rule of the units
    # stays the declaration's, else both rules are read in that order
    stored = None if product_fixed else quaternions.storage_order(let, latex)
    if stored is not None:
        order_q, product = ("last" if stored[0] == quaternions.JPL else "first"), stored[0]
    else:  # a declaration's own layout ('\otimes: Hamilton, scalar last'), else the rule's
        order_q = quaternions.place_of((product_said or "").partition(":")[2])
    # the scalar first is Hamilton's in every book of the corpora; the scalar last is read
    # with either rule (JPL's: Trawny & Roumeliotis; Hamilton's: Szeliski, Eigen, ROS)
    rule_open = not product_fixed and order_q != "first"
    fixed = said is not None or notation in tangent.NOTATION_ORDERS
    t0, seen = process_time(), {}
    try:
        with limit.limited(seconds), quaternions.using(product, product_said), \
                quaternion_convention(product == quaternions.JPL), \
                quaternions.stored(order_q, stored[1] if stored else
                                   f"--let '{product_said}'" if product_said else ""), \
                quaternion_storage(None if order_q is None else order_q == "last"), \
                contested.using(settled, settled_said), declared_readings(settled):

            def read(let, repairs, seen):
                """The statement read under every quaternion and tangent reading left
                open, ``let`` its declarations."""
                with tangent.using(order, said), tangent_order(order == tangent.TRANSLATION):
                    r, reading = _check_latex_steps(latex, let, book, modules, repairs,
                                                    repair_budget, notation, repair_seconds,
                                                    seen)
                if rule_open and r.verdict != "undecided" and any(
                        "quaternion product:" in n for n in reading.notes):
                    # the product is used and nothing declares its rule: read under the
                    # other rule, and the other scalar's place where nothing fixes it
                    verdicts = {(product, order_q or ("last" if product == quaternions.JPL
                                                      else "first")): r.verdict}
                    verdicts.update(_other_quaternion_readings(
                        product, order_q, (latex, let, book, modules, repair_budget,
                                           notation, repair_seconds), (order, said)))
                    quaternions.both_conventions(verdicts, reading.notes,
                                                 stored[1] if stored else None)
                    r.model = list(r.model) + reading.notes[-1:]
                if fixed or r.verdict == "undecided" or not any(
                        n.startswith("tangent order:") for n in reading.notes):
                    return r, reading
                # the order matters and nothing declares it: read in the other order too
                with tangent.using(tangent.TRANSLATION, tangent.OTHER), tangent_order(True):
                    other, _ = _check_latex_steps(latex, let, book, modules, False,
                                                  repair_budget, notation, repair_seconds, {})
                tangent.both_orders(r.verdict, other.verdict, reading.notes)
                r.model = list(r.model) + reading.notes[-1:]
                return r, reading

            if principal:
                r, reading = _principal_readings(read, let, repairs, seen, principal)
            else:
                r, reading = read(let, repairs, seen)
            if identity_said is not None:
                reading.notes.append(f"\\mathbb{{I}}: the identity (declared by --let "
                                     f"'{identity_said}')")
                r.model = list(r.model) + reading.notes[-1:]
            if board_open and r.verdict != "undecided":
                _blackboard_readings(r, reading, read, let)
            return r, reading
    except limit.TimeUp as exc:
        return _time_up(exc, latex, let, book, modules, notation, seen.get("reading"),
                        process_time() - t0)


def _principal_readings(read, let, repairs, seen, names: list[str]):
    """``(r, reading)`` of a statement whose undeclared ``names`` (``I_1, I_2, I_3`` side by
    side: :func:`rigidsym.latex.principal.open_principal`) are read as identities and again
    as scalars (``read`` reads under the declarations it is given): the reading that
    type-checks, or where both do and agree the first, each with a note
    (:func:`rigidsym.latex.principal.both_principal`).

    Raises:
        BadInput: the readings disagree.
        LatexError: neither reading type-checks (the identities' error, which names the
            --let that makes them scalars).
    """
    from rigidsym.latex.principal import both_principal, with_scalar_reading
    from rigidsym.latex.shapes import LatexError

    def attempt(lets, state):
        try:
            return read(lets, repairs, state), ""
        except LatexError as exc:
            if exc.construct != "shapes":
                raise
            return exc, f"{exc.construct}: " + str(exc).splitlines()[0].split(" in '", 1)[0]

    first, why_first = attempt(let, seen)
    other, why_other = attempt(with_scalar_reading(let, names), {} if why_first == "" else seen)
    if why_first and why_other:
        raise first
    ok_first, ok_other = not why_first, not why_other
    verdict_first = first[0].verdict if ok_first else None
    verdict_other = other[0].verdict if ok_other else None
    if verdict_first == "undecided":  # no verdict to weigh: undecided, as read
        return first
    if verdict_other == "undecided":
        return other
    r, reading = first if ok_first else other
    both_principal(verdict_first, verdict_other, names, reading.notes, why_first, why_other)
    r.model = list(r.model) + reading.notes[-1:]
    return r, reading


def _blackboard_readings(r: Result, reading, read, let) -> None:
    """An undeclared ``\\mathbb{I}`` read as the identity gave ``r``: the statement read
    again with it a name (Marsden & Ratiu's inertia tensor, a symmetric 3×3 matrix; ``read``
    reads under ``let``); where the verdicts agree a note joins ``r`` and ``reading``
    (:func:`rigidsym.latex.blackboard.both_blackboard`).

    Raises:
        BadInput: the readings disagree, or the name reading is refused."""
    from rigidsym.latex.blackboard import both_blackboard, with_name_reading
    from rigidsym.latex.shapes import LatexError

    other, why = None, ""
    try:
        other = read(with_name_reading(let), False, {})[0].verdict
    except LatexError as exc:
        first = str(exc).splitlines()[0].split(" in '", 1)[0]
        why = f"{exc.construct}: {first}"
    except BadInput as exc:
        why = str(exc).splitlines()[0]
    both_blackboard(r.verdict, other, reading.notes, why)
    r.model = list(r.model) + reading.notes[-1:]


def _other_quaternion_readings(product: str, order_q: str | None, args: tuple,
                               tangent_setting: tuple) -> dict[tuple[str, str], str]:
    """The verdicts of a statement under each other pair of a quaternion rule of the units
    and a scalar's place (:data:`rigidsym.latex.quaternions.READINGS`; ``order_q``: the place
    the lets fix, else any), the first reading ``product`` in its own layout excepted."""
    from rigidsym.latex import quaternions, tangent
    from rigidsym.numeval.values import quaternion_convention, quaternion_storage, tangent_order

    latex, let, book, modules, repair_budget, notation, repair_seconds = args
    order, said = tangent_setting
    first = (product, order_q or ("last" if product == quaternions.JPL else "first"))
    out = {}
    for rule, place in quaternions.READINGS:
        if (rule, place) == first or (order_q and place != order_q):
            continue
        with quaternions.using(rule, quaternions.other_reading(rule, place)), \
                quaternion_convention(rule == quaternions.JPL), \
                quaternions.stored(place, ""), quaternion_storage(place == "last"), \
                tangent.using(order, said), tangent_order(order == tangent.TRANSLATION):
            other, _ = _check_latex_steps(latex, let, book, modules, False,
                                          repair_budget, notation, repair_seconds, {})
        out[(rule, place)] = other.verdict
    return out


def _time_up(exc, latex, let, book, modules, notation, reading, seconds):
    """The ``undecided`` of a check whose time limit passed: the step and a hint."""
    import hashlib
    import json

    from rigidsym.latex import limit

    why = limit.reason(exc)
    if reading is not None and reading.eq is not None:
        eq_id = reading.eq.id
    else:
        key = json.dumps([latex, let if isinstance(let, str | None) else
                          sorted(let.items()) if isinstance(let, dict) else list(let),
                          book, [str(m) for m in modules or ()], notation], default=str)
        eq_id = "latex:" + hashlib.sha256(key.encode()).hexdigest()[:10]
    r = Result(id=eq_id, title="LaTeX check", kind="identity", verdict="undecided",
               expected="undecided", method="time-limit", printed_latex=latex, printed=None,
               derived=None, corrected=None, counterexample=None, cause=why, numeric={},
               seconds=seconds, detail=why)
    if reading is not None:
        r.model = list(reading.notes)
    return r, reading


def _check_latex_steps(latex, let, book, modules, repairs, repair_budget, notation,
                       repair_seconds, seen):
    """:func:`check_latex_run`'s steps, each marked for the time limit
    (:func:`rigidsym.latex.limit.step`); the reading, once made, left in ``seen``. A name
    the reader respells (a labelled ``R_{v2}^b``) is named as typed in the notes and in a
    refusal's message."""
    from rigidsym.latex.respell import labels_as_typed
    from rigidsym.latex.shapes import LatexError

    as_typed = labels_as_typed(let)
    try:
        r, reading = _latex_steps(latex, let, book, modules, repairs, repair_budget, notation,
                                  repair_seconds, seen)
    except (LatexError, BadInput) as exc:
        if exc.args and isinstance(exc.args[0], str):
            text = exc.args[0]
            for respelt, typed in seen.get("typed lets", {}).items():  # the --let as typed
                text = text.replace(f"--let '{respelt}'", f"--let '{typed}'")
            exc.args = (as_typed(text), *exc.args[1:])
        raise
    r.model = [as_typed(m) if isinstance(m, str) else m for m in r.model]
    reading.notes[:] = [as_typed(n) for n in reading.notes]
    return r, reading


def _latex_steps(latex, let, book, modules, repairs, repair_budget, notation,
                 repair_seconds, seen):
    """:func:`_check_latex_steps` before the names are written back as typed."""
    from rigidsym.checking.checker import check as _check
    from rigidsym.latex.blackboard import declared_blackboard
    from rigidsym.latex.chain_head import defined_head
    from rigidsym.latex.limit import step
    from rigidsym.latex.respell import (
        accent_primes,
        angular_velocities,
        conjugate_c,
        cross_subscripts,
        declared_columns,
        declared_deltas,
        declared_e,
        declared_labels,
        each_declaration,
        floor_cross,
        grouping_braces,
        hat_expressions,
        rate_entries,
        tilde_expressions,
    )
    from rigidsym.latex.statement import declare_latex

    step("reading")
    given_let = let
    seen.pop("typed lets", None)
    latex, let, board = declared_blackboard(latex, let)  # M&R's inertia \mathbb{I}: a name
    latex, let, column = declared_columns(latex, let)  # Ginsberg's \{\omega\}: omega
    latex, let, braces = grouping_braces(latex, let)  # Lee's \{tr[A] I - A\}x: ( )
    latex, let, spin = angular_velocities(latex, let)  # ω: angular velocity of Q
    latex, let, deltas = declared_deltas(latex, let)  # Forster's \Delta R_{ij}: one name
    latex, let, labels = declared_labels(latex, let)  # Groves' C_b^n: C_{b}^{(n)}
    latex, let, respelt = declared_e(latex, let)  # a declared e before ^: a power
    latex, let, prime = accent_primes(latex, let)  # \tilde{\omega}' of a declared \omega'
    latex, let, tilde = tilde_expressions(latex, let)  # \widetilde{a \times b}: [a x b]_x
    latex, let, floor = floor_cross(latex, let)  # Trawny's \lfloor a\times\rfloor: [a]_x
    latex, let, rates = rate_entries(latex, let)  # Greenwood's \dot\epsilon_k: entries
    latex, let, subx = cross_subscripts(latex, let)  # Eade's \omega_\times: [\omega]_x
    latex, let, hat = hat_expressions(latex, let)  # \widehat{R\omega}: [R\omega]_x
    latex, let, conj = conjugate_c(latex, let)  # Kok's q^c beside \odot: q^*
    latex, let, head = defined_head(latex, let, book=book, notation=notation)  # A = X = Y
    as_given, as_read = each_declaration(given_let), each_declaration(let)
    if as_given and as_read and len(as_given) == len(as_read):  # each respelt one by one
        seen["typed lets"] = {r: t for r, t in zip(as_read, as_given, strict=True)
                              if r != t}
    eq, reading = declare_latex(latex, let, book=book, modules=modules, notation=notation)
    given = let  # the second semantics reads every declaration, the unused ones too
    if reading.unused:  # a --let it does not use is ignored: read again without it
        from rigidsym.latex.lets import without_lets

        said = [n for n in reading.notes if n.startswith("not used: ")]
        let = without_lets(let, reading.unused)
        eq, reading = declare_latex(latex, let, book=book, modules=modules, notation=notation)
        reading.notes += said
    for note in (labels, prime, tilde, floor, rates, subx, hat, deltas, conj, respelt, board,
                 column, braces, spin, head):
        if note:
            reading.notes.insert(0, note)
    seen["reading"] = reading
    step("deciding")
    r = Result.of(_check(eq, repairs=repairs, repair_budget=repair_budget,
                         repair_seconds=_seconds(repair_seconds)))
    from rigidsym.latex.printed_point import own_symbols_said, project_rates

    project_rates(r.counterexample, reading.rows)  # a unit vector's rate: the one used
    own_symbols_said(r.counterexample, reading.rows)  # never the reader's internal name
    if reading.others:  # several readings type-check: a verdict only when all agree
        step("readings")
        _readings_agree(reading, r, [_check(o.eq, repairs=False) for o in reading.others])
    from rigidsym.latex.crosscheck import cross_check, given_point

    step("cross-check")

    # a verdict needs the second, independent semantics to agree (a does-not-hold
    # at the symbolic path's own counterexample, handed over as plain data)
    at = given_point(r.counterexample, reading.eq.build(), reading.symbols, reading.rows) \
        if r.verdict == "does-not-hold" else None
    second = cross_check(latex, given, r.verdict, notation=notation, book=book, modules=modules,
                         at=at, symbols=reading.symbols, statement=reading.eq.build(),
                         rows=reading.rows)
    if second:
        reading.notes.append(second)
    r.expected = r.verdict
    r.model = _without_own(list(r.model), reading.rows) + reading.notes
    return r, reading


def _without_own(model: list[str], rows: dict) -> list[str]:
    """The model's lines without the reader's own symbols (a rotation's body velocity,
    said in words where the reader makes it) in its ``free:`` line: a message names only
    what the user wrote."""
    from rigidsym.printing import notation

    own = {notation.book_group(g.name) for g in rows.values()
           if getattr(g, "meaning", "") == "body velocity"}
    if not own:
        return model
    out = []
    for line in model:
        if line.startswith("free: "):
            kept = [x for x in line[6:].split(", ") if x not in own]
            if not kept:
                continue
            line = "free: " + ", ".join(kept)
        out.append(line)
    return out


def _readings_agree(reading, first, others) -> None:
    """the verdict of every reading that type-checks, or bad input naming
    the choice, each reading's verdict and the ``--let`` that settles it."""
    from rigidsym.core.errors import BadInput

    verdicts = [first.verdict] + [o.verdict for o in others]
    readings = [reading, *reading.others]
    if len(set(verdicts)) == 1:
        reading.notes.append(f"{len(readings)} readings type-check "
                             f"({' | '.join(said_choices(x.choices) for x in readings)}): all "
                             f"{verdicts[0]}")
        return
    keys = sorted({k for x in readings for k, c in x.choices.items()
                   if c != reading.choices.get(k)})
    said = "; ".join(f"{said_choices(x.choices)}: {v}" for x, v in zip(readings, verdicts,
    strict=True))
    raise BadInput(f"--latex: {' and '.join(_choice_words(k) for k in keys)}, and the readings "
                   f"disagree ({said}): say which, {'; '.join(_settles(k) for k in keys)}")


def _choice_words(key: str) -> str:
    if key == "\\tilde":
        return ("\\tilde{x} of a 3-vector can be read as its cross-product matrix [x]_\\times "
                "(Wittenburg, Shabana) or as a vector of its own")
    from rigidsym.latex.entries import is_base_point

    if is_base_point(key):
        return (f"the subscripts of the 4-vector {key.split(' of ', 1)[1].split(' counted')[0]}"
                f" can count its entries from 1 or from 0")
    if key.endswith(" shape"):
        return (f"{key[:-6]} (a bold capital no --let declares) can be a 3×3 matrix or a "
                f"3-vector")
    from rigidsym.latex.transformer.meanings import STAR_POINT, is_cross_bracket

    if is_cross_bracket(key):
        return _cross_words(key)
    if key == STAR_POINT:
        return _star_words()
    from rigidsym.latex.transformer.extent import extent_parts, is_extent_point

    if is_extent_point(key):
        return _extent_words(extent_parts(key))
    if key.startswith("[["):
        return (f"{key} can be read as the cross-product matrix [{key[2:-2]}]_\\times or as "
                f"its negative (Shuster's (57))")
    if key.endswith(" hat"):
        return (f"{key[:-4]} can be read as a unit vector of its own (Lynch-Park, Corke) or "
                f"as the skew matrix of {key[5:-5]} (Murray-Li-Sastry)")
    if key.startswith("["):
        return f"{key} can be read as the hat of the vector or as a bracket that groups it"
    if " of " in key:
        name, vec = key.split(" of ", 1)
        return f"{name} can be read as a symbol of its own or as an entry of {vec}"
    return f"{key}(...) can be read as a product or as {key} applied to its argument"


def _cross_words(key: str) -> str:
    """``[A x\\wedge]`` in words: its readings and their books
    (:data:`rigidsym.latex.contested.CONTESTED`)."""
    from rigidsym.latex.contested import construct

    c = construct("bracket cross")
    return (f"{key} (a product before x\\wedge inside a bracket) can be read as "
            + " or as ".join(f"{r.means} ({r.books})" for r in c.readings))


def _star_words() -> str:
    """``X^*`` of a 6x6 matrix in words: its readings and their books
    (:data:`rigidsym.latex.contested.CONTESTED`, "star")."""
    from rigidsym.latex.contested import construct

    c = construct("star")
    return ("X^* of a 6x6 matrix (the star) can be read as "
            + " or as ".join(f"{r.means} ({r.books})" for r in c.readings))


def _extent_words(parts: tuple[str, str, str]) -> str:
    """``\\cos\\theta\\phi`` in words: its readings and their books
    (:data:`rigidsym.latex.contested.CONTESTED`, "argument extent")."""
    from rigidsym.latex.contested import construct

    head, arg, run = parts
    gap = " " if arg[-1:].isalpha() and run[:1].isalpha() else ""
    c = construct("argument extent")
    return (f"{head}{arg}{gap}{run} (a function's argument without parentheses, then "
            f"{run}) can be read as " + " or as ".join(
                f"{head}({arg}){run} ({r.books})" if r.name == "factor" else
                f"{head}({arg}{gap}{run}) ({r.books})" for r in c.readings))


def _settles(key: str) -> str:
    if key == "\\tilde":
        return ("--let '\\tilde{\\mathbf{a}} = [\\mathbf{a}]_\\times' (the matrix) or "
                "--let '\\tilde{\\mathbf{a}}: vector' (its own)")
    from rigidsym.latex.entries import base_settles, is_base_point

    if is_base_point(key):
        return base_settles(key)
    if key.endswith(" shape"):
        return f"--let '{key[:-6]}: vector' or --let '{key[:-6]}: matrix'"
    from rigidsym.latex.transformer.extent import extent_parts, is_extent_point
    from rigidsym.latex.transformer.meanings import STAR_POINT, is_cross_bracket

    if is_extent_point(key):
        head, arg, run = extent_parts(key)
        gap = " " if arg[-1:].isalpha() and run[:1].isalpha() else ""
        return (f"--let 'argument extent: factor' or --let 'argument extent: product', or "
                f"write {head}({arg}){run} or {head}({arg}{gap}{run})")
    if key == STAR_POINT:
        return ("--let 'star: transpose' (Jain's) or --let 'star: dual' (Featherstone's), "
                "or write X^T for the transpose and X^{-T} for the dual (a name of "
                "Featherstone's: --let 'X: spatial transform', whose X^* is the dual)")
    if is_cross_bracket(key):
        left, x = key[1:].rsplit("\\", 1)[0].rsplit(" ", 1)
        return (f"--let 'bracket cross: content' or --let 'bracket cross: bind', or write "
                f"[{left} {x}]_\\times (the content's cross-product matrix) or "
                f"{left}[{x}]_\\times ({left} times)")
    if key.startswith("[["):
        return (f"write [{key[2:-2]}]_\\times or -[{key[2:-2]}]_\\times for {key}, or a "
                f"--let function (--let 'N(\\mathbf{{u}}) = -[\\mathbf{{u}}]_\\times')")
    if key.endswith(" hat"):
        return (f"--let '{key[:-4]}: unit vector' (a vector of its own) or --notation "
                f"murray-li-sastry (or --let '{key[:-4]} = [{key[5:-5]}]_\\times': the skew "
                f"matrix)")
    if key.startswith("["):
        return f"{key[:-1]}]_\\times for the hat or ({key[1:-1]}) to group"
    if " of " in key:
        name, vec = key.split(" of ", 1)
        k = name.rsplit("_{", 1)[-1].rstrip("}")
        return (f"--let '{name}: scalar' (a symbol of its own) or {vec}_{{{k}:{k}}} (the "
                f"entry)")
    return (f"with a --let function (--let '{key}(PARAM) = LATEX': an application) or by "
            f"writing the product without parentheses")


def verify(ids: Sequence[str] | str | None = None, sections: Sequence[str] | str | None = None,
           *, modules: Iterable[ModuleSpec] = (), jobs: int = 1,
           progress: bool = False, cache: bool = True, repairs: bool = True,
           repair_budget: int | None = None) -> Results:
    """Decide many equations (the Python side of ``rigidsym verify``).

    Args:
        ids: ids to check (``"3.96"`` means all its lettered parts); a single string is one id.
        sections: book sections ``"3.2"`` … ``"3.8"`` or sections of user declarations.
        modules: user modules to load (paths to ``.py`` files, dotted names, or module
            objects); with no ids and no sections, only their ids are checked.
        jobs: worker processes (forked; 1 checks in this process).
        progress: show a progress bar on stderr.
        cache: read unchanged ids from the verdict cache and store the others (``RIGIDSYM_CACHE``,
            ``verdicts/``; ``Result.cached`` says which); ``False`` checks every id again.
        repairs: search repairs of every member that does not hold (``Result.repairs``);
            ``False`` turns the search off.
        repair_budget: candidates tried per failing member (``None``: each declaration's
            ``repair_budget``, else 5000). The budget and the vocabulary's version join the
            verdict cache's key.

    Returns:
        :class:`Results` in id order (book order, then user ids in declaration order). With
        no argument at all: the whole chapter.

    Raises:
        BadInput: for a malformed or unknown id or section, or a user module that cannot be
            loaded (one line naming the module and the problem).
        ValueError: if ``jobs`` is not a positive integer, ``repairs`` not a bool or
            ``repair_budget`` not a non-negative integer.
    """
    from rigidsym.checking.runner import run_checks

    if not isinstance(jobs, int) or isinstance(jobs, bool) or jobs < 1:
        raise ValueError(f"jobs: expected a positive integer, got {jobs!r}")
    _repair_args(repairs, repair_budget)
    ids = [ids] if isinstance(ids, str) else ids
    sections = [sections] if isinstance(sections, str) else sections
    names = _load(modules)
    selected = select(list(ids) if ids else None, list(sections) if sections else None, names)
    t0 = time.perf_counter()
    rows = run_checks(selected, jobs=jobs, progress=progress, cache=cache, repairs=repairs,
                      repair_budget=repair_budget)
    return Results(rows, seconds=time.perf_counter() - t0)
