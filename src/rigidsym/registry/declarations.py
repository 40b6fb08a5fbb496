"""The equation registry: one declaration per numbered equation of the book (or user id).

A declaration is a function in ``derivations/`` (or a user module: :mod:`.usermodules`)
decorated with :func:`equation`. It returns a :class:`Statement`: the printed equation
transcribed member by member in the book's symbols (garbles included), the *model*
(first-principles values of those symbols, derived independently of the printed form), and,
when the printed form does not hold, the corrected form. The verdict is never typed in: the
checker computes it; the *expected* verdict sits beside it as data: a regression flips loudly.
"""

from __future__ import annotations

import re
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from rigidsym.core import work as _work
from rigidsym.core.config import BOOK as BOOK_PACKAGE
from rigidsym.core.errors import BadInput, did_you_mean  # BadInput re-exported: their homes
from rigidsym.registry.relations import Rel

__all__ = [
    "Rel",
    "Statement",
    "Equation",
    "equation",
    "REGISTRY",
    "KINDS",
    "VERDICTS",
    "CAUSES",
    "book_sections",
    "parse_id",
    "section_of",
    "load_all",
    "select",
    "BadInput",
    "is_user_id",
    "book_ids",
    "book_reading",
    "forget_module",
    "forget_built",
    "DeclarationTypeError",
    "USER_CAUSE_DEFAULT",
    "check_budget",
]

KINDS = ("identity", "definition", "claim")
VERDICTS = ("verified", "definition", "does-not-hold", "undecided")
CAUSES = ("conversion", "erratum", "unknown")
#: A book id: an equation's number (chapter.number, a letter for a part), or a claim's
#: (``thm``, ``cor``, ``caveat`` and its section's number); which ids a book has is its
#: declarations', never this module's.
_ID = re.compile(r"^(\d+\.\d+[a-e]?|(thm|cor|caveat)\d+\.\d+(\.\d+)?|ex\d+\.\d+)$")
_ID_PARTS = re.compile(r"^(?:thm|cor|caveat|ex)?(\d+)\.(\d+)(?:\.(\d+))?([a-e]?)$")
#: A user id: ``namespace:name`` (``notes:rodrigues``, ``paper:eq7``).
_USER_ID = re.compile(r"^[a-z][a-z0-9_-]*:[A-Za-z0-9_.-]+$")
#: The cause of a user's does-not-hold when the declaration names none.
USER_CAUSE_DEFAULT = "not determined"


def _in_book(module: str) -> bool:
    return module == BOOK_PACKAGE or module.startswith(BOOK_PACKAGE + ".")


def is_user_id(eq_id: str) -> bool:
    """Whether ``eq_id`` is a user id (``namespace:name``) rather than a book id."""
    return bool(_USER_ID.match(eq_id))


@dataclass
class Statement:
    """What a declaration returns.

    Attributes:
        printed: the book's statement as printed, one :class:`Rel` per member, in book
            symbols (``MatrixSymbol``/``Symbol``). A chain ``x = y = z`` gives ``(x, y)`` and
            ``(x, z)``; a garbled symbol is a fresh symbol, never silently repaired.
            Empty in a user declaration with ``latex=`` (or the function returns the
            model dict alone): read from the LaTeX by :mod:`rigidsym.latex`, its glyphs
            named as the model's symbols.
        model: first-principles values of the book symbols (``symbol -> explicit value``),
            derived without the printed form; substituted before deciding.
        derived: the first-principles value of the quantity (for display and codegen).
        corrected: the corrected form (same conventions as ``printed``), required when the
            printed form does not hold; it must itself verify.
        defines: names of the symbols a definition introduces.
        claims: extra relations a definition or claim asserts that must hold (e.g. the unit
            norm of a direction just defined).
        parametrisation: one sentence on how the model writes its own free variables
            (those that are not book symbols), shown with a counterexample under "how the
            point was chosen", e.g. ``"Q(t) is the rotation of the quaternion q + t u, so
            that QᵀQ = 1 holds exactly"``. Constrained atoms (unit vectors, rotations,
            angles) are described without it.
    """

    printed: list[Rel]
    model: dict = field(default_factory=dict)
    derived: Any = None
    corrected: list[Rel] | None = None
    defines: tuple[str, ...] = ()
    claims: list[Rel] = field(default_factory=list)
    parametrisation: str = ""
    #: a does-not-hold whose printed relation holds a glyph the page never gives (3.148's
    #: P): ``(the printed relation with that glyph a fresh array of free atoms, the array, a
    #: witness x)``; certified failing for every real value of the array (x^T (lhs - rhs) x)
    for_every: tuple | None = None
    #: set when ``printed`` was read from the declaration's LaTeX (not written by hand)
    from_latex: bool = False


#: reads a statement's printed form from its declaration's LaTeX (``printed=None``); set by
#: :mod:`rigidsym.declare`, since the reader is a layer above the registry
PRINTED_FROM_LATEX: Callable[[Any, Statement], list[Rel]] | None = None


@dataclass(frozen=True)
class Equation:
    """A registered declaration (metadata plus the builder of its :class:`Statement`)."""

    id: str
    title: str
    section: str
    kind: str
    latex: str
    expected: str
    build_fn: Callable[[], Statement]
    cause: str | None = None
    evidence: str | None = None
    singular: str | None = None
    module: str = ""
    function: str = ""
    where: str = ""
    #: candidates per failing member for the repair search (``None``: the default)
    repair_budget: int | None = None

    def build(self) -> Statement:
        """The statement, built once per process (derivations can be expensive); a book
        declaration's is read from the user cache when a process stored it before
        (:mod:`rigidsym.registry.statement_cache`).

        Raises:
            DeclarationTypeError: the declaration returned something other than a
                :class:`Statement` of :class:`Rel`.
        """
        return _build(self.id)


REGISTRY: dict[str, Equation] = {}
#: Built statements, by id (cleared for an id when its declaration is replaced).
_BUILT: dict[str, Statement] = {}
#: The function each statement of :data:`_BUILT` came from (a test or a notebook may have
#: replaced a declaration's function since: such a statement is never stored on disk).
_BUILT_BY: dict[str, Callable] = {}
#: Per book module, what this process read of its entry in the user cache
#: (:mod:`rigidsym.registry.statement_cache`): ``{id: statement}`` not yet taken, or ``None``
#: for a miss (the module's statements are stored once this process has built them all).
_STORED: dict[str, dict[str, Statement] | None] = {}


class DeclarationTypeError(TypeError):
    """A declaration returned something other than a :class:`Statement` of :class:`Rel`."""


def _as_written(eq: Equation) -> bool:
    """Whether ``eq`` is a book declaration whose function is the one its module defines
    (not replaced in memory by a test or a notebook): its statement may be kept on disk."""
    if not _in_book(eq.module) or "<locals>" in eq.function:
        return False
    obj = sys.modules.get(eq.module)
    for part in eq.function.split("."):
        obj = getattr(obj, part, None)
    return obj is eq.build_fn


def _module_ids(module: str) -> list[str]:
    return [k for k, e in REGISTRY.items() if e.module == module]


def _from_disk(eq: Equation) -> Statement | None:
    """The statement of ``eq`` read from the user cache, or ``None`` (a user declaration, a
    replaced one, a miss). The module's entry is read once per process."""
    if not _as_written(eq):
        return None
    if eq.module not in _STORED:
        from rigidsym.registry import statement_cache

        key = statement_cache.key_of(eq.module)
        got = statement_cache.load(eq.module, key) if key else None
        ids = _module_ids(eq.module)
        if got is not None and (set(got) != set(ids) or not all(
                isinstance(st, Statement) for st in got.values())):
            got = None  # not this module's declarations as they are now: built again
        _STORED[eq.module] = got
    got = _STORED[eq.module]
    return None if got is None else got.pop(eq.id, None)


def _to_disk(eq: Equation) -> None:
    """Store the statements of ``eq``'s module once this process holds every one of them,
    each built from the function its module defines (best effort: see
    :func:`rigidsym.registry.statement_cache.store`)."""
    if _STORED.get(eq.module, {}) is not None:
        return  # read from the cache (or not looked up): nothing to write
    ids = _module_ids(eq.module)
    if not all(i in _BUILT and _BUILT_BY.get(i) is REGISTRY[i].build_fn
               and _as_written(REGISTRY[i]) for i in ids):
        return
    from rigidsym.registry import statement_cache

    key = statement_cache.key_of(eq.module)
    if key is not None:
        statement_cache.store(eq.module, key, {i: _BUILT[i] for i in ids})
    _STORED[eq.module] = {}  # written (or not writable): once per process


def _build(eq_id: str) -> Statement:
    hit = _BUILT.get(eq_id)
    if hit is not None:
        return hit
    eq = REGISTRY[eq_id]
    st = _from_disk(eq)
    if st is not None:
        _work.count("load", eq_id)  # read, not built: a test counting builds sees none
        _BUILT[eq_id], _BUILT_BY[eq_id] = st, eq.build_fn
        return st
    from sympy.matrices.utilities import dotprodsimp

    _work.count("build", eq_id)  # a real build (counted, so a test sees a rebuild)
    # no simplification of intermediate matrix products (sympy applies `cancel` to each
    # entry of a Matrix power, for instance): a model is decided exactly, not read, and
    # this took a third of the time of building the chapter's declarations
    with dotprodsimp(False):
        st = eq.build_fn()
    if isinstance(st, dict) and eq.latex:  # the model alone: the printed form is the LaTeX
        st = Statement([], st)
    if not isinstance(st, Statement):
        raise DeclarationTypeError(f"declaration {eq_id} returned {type(st).__name__}, "
                                   f"not Statement")
    if not st.printed and eq.latex and PRINTED_FROM_LATEX is not None and is_user_id(eq_id):
        st.printed, st.from_latex = list(PRINTED_FROM_LATEX(eq, st)), True
    bad = [type(r).__name__ for r in list(st.printed) + list(st.corrected or []) + st.claims
           if not isinstance(r, Rel)]
    if bad:
        raise DeclarationTypeError(f"declaration {eq_id}: printed/corrected/claims hold "
                                   f"{bad[0]}, not Rel")
    _BUILT[eq_id], _BUILT_BY[eq_id] = st, eq.build_fn
    if _as_written(eq):
        _to_disk(eq)
    return st


def forget_built() -> None:
    """Forget every built statement of this process and what it read of the user cache: the
    next :meth:`Equation.build` of an id reads the cache again (a book declaration as
    written) or runs its declaration."""
    _BUILT.clear()
    _BUILT_BY.clear()
    _STORED.clear()


_build.cache_clear = forget_built  # the functools.cache spelling, kept for callers


def _where(fn) -> str:
    """``file:line`` of a declaration, for messages that must name both places."""
    code = getattr(fn, "__code__", None)
    if code is None:
        return f"{fn.__module__}.{fn.__qualname__}"
    return f"{code.co_filename}:{code.co_firstlineno}"


def section_of(eq_id: str) -> str:
    """The book section (``"3.2"`` … ``"3.8"``) an id belongs to, from the registry."""
    return ".".join(REGISTRY[eq_id].section.split(".")[:2])


def _numbers(text: str) -> tuple[int, ...]:
    return tuple(int(x) for x in text.split(".") if x.isdigit())


def book_sections() -> tuple[str, ...]:
    """The book's sections that hold numbered equations or claims: those its loaded
    declarations name (each declares its section), in book order.

    Returns:
        The sections (``"3.2"`` ...), each once.
    """
    load_all()
    return tuple(sorted({section_of(k) for k in REGISTRY if not is_user_id(k)}, key=_numbers))


def _sections_without_ids() -> dict[str, str]:
    """The book's sections that hold no id, each with why (``SECTIONS_WITHOUT_IDS`` of the
    book package, :data:`rigidsym.core.config.BOOK`; ``{}`` where it names none)."""
    import importlib

    from rigidsym.core import config as _config

    return dict(getattr(importlib.import_module(_config.BOOK), "SECTIONS_WITHOUT_IDS", {}))


def equation(eq_id: str, title: str, *, section: str | None = None,
             latex: str | None = None, kind: str = "identity", expected: str | None = None,
             cause: str | None = None, evidence: str | None = None,
             singular: str | None = None, repair_budget: int | None = None):
    """Register a declaration under its id (a decorator).

    A book id (``"3.6a"``, ``"thm3.2.1"``) is declared only in ``rigidsym.derivations``, with
    its section and printed LaTeX. A user id is ``namespace:name`` (``"notes:rodrigues"``)
    and ``section``, ``latex``, ``cause`` and ``evidence`` are optional.

    Args:
        eq_id: the id (book form, or ``namespace:name`` matching
            ``[a-z][a-z0-9_-]*:[A-Za-z0-9_.-]+``).
        title: a short title.
        section: the book (sub)section, e.g. ``"3.2.1"`` (required for a book id); any label
            for a user id (``rigidsym verify --section`` selects by it).
        latex: the printed LaTeX (for a book id verbatim from the chapter, which a test
            checks; optional for a user id). A user declaration with ``latex=`` whose
            function returns its model alone (a dict) or a :class:`Statement` with no
            printed member takes its printed form from the LaTeX (``rigidsym.latex``).
        kind: ``identity``, ``definition`` or ``claim``.
        expected: the verdict the checker is expected to compute (data, not the verdict);
            defaults to ``definition`` for a definition and ``verified`` otherwise.
        cause: for an expected ``does-not-hold``: ``conversion``, ``erratum`` or ``unknown``
            for a book id; any text for a user id (default ``"not determined"``).
        evidence: one line of evidence for the cause (required for a book id).
        singular: the singular set of the formula, in words (``"phi = 0"``).
        repair_budget: candidates the repair search tries per failing member of this
            declaration (a non-negative integer; ``None``: the default, 5000). A run's own
            budget (``verify(..., repair_budget=N)``) takes precedence.

    Returns:
        A decorator that registers the function (which takes no argument and returns a
        :class:`Statement`) and returns it unchanged.

    Raises:
        ValueError: for a malformed id, a book id declared outside the book, an id declared
            in two places (both named), an unknown kind/verdict/cause, or a repair budget
            that is not a non-negative integer.
    """
    user = is_user_id(eq_id)
    if not user and not _ID.match(eq_id):
        raise ValueError(f"eq_id: expected namespace:name (e.g. notes:rodrigues) or a book id, "
                         f"got {eq_id!r}")
    if kind not in KINDS:
        raise ValueError(f"kind: expected one of {KINDS}, got {kind!r}{did_you_mean(kind, KINDS)}")
    check_budget(repair_budget, "repair_budget", none_ok=True)
    if expected is None:
        expected = "definition" if kind == "definition" else "verified"
    if expected not in VERDICTS:
        raise ValueError(f"expected: expected one of {VERDICTS}, got {expected!r}"
                         f"{did_you_mean(expected, VERDICTS)}")
    if not user and not _in_book(sys._getframe(1).f_globals.get("__name__", "")):
        raise ValueError(f"eq_id: {eq_id!r} is a book id, reserved for the chapter; "
                         f"declare your own as namespace:name (e.g. notes:eq1)")
    if user:
        if expected == "does-not-hold":
            cause = cause or USER_CAUSE_DEFAULT
        section, latex = section or "", latex or ""
    else:
        if section is None or latex is None:
            raise ValueError(f"{eq_id}: a book id needs section= and latex=")
        if expected == "does-not-hold" and (cause not in CAUSES or not evidence):
            raise ValueError(f"{eq_id}: a does-not-hold needs a cause in {CAUSES} and evidence")

    def deco(fn):
        module = fn.__module__
        if not user and not _in_book(module):
            raise ValueError(f"eq_id: {eq_id!r} is a book id, reserved for the chapter; "
                             f"declare your own as namespace:name (e.g. notes:eq1)")
        new = Equation(eq_id, title, section, kind, latex, expected, fn, cause, evidence,
                       singular, module, fn.__qualname__, _where(fn), repair_budget)
        old = REGISTRY.get(eq_id)
        if old is not None and (old.module, old.function) != (new.module, new.function):
            raise ValueError(f"equation {eq_id} is declared twice: by {old.function} at "
                             f"{old.where} and by {new.function} at {new.where}; rename one "
                             f"of the ids")
        # the same function declared again (a notebook cell run twice): the new one replaces it
        REGISTRY[eq_id] = new
        _BUILT.pop(eq_id, None)
        _BUILT_BY.pop(eq_id, None)
        return fn

    return deco


def check_budget(value, name: str, none_ok: bool = False) -> None:
    """Raise a ``ValueError`` naming ``name`` unless ``value`` is a non-negative integer
    (or ``None`` when ``none_ok``)."""
    if value is None and none_ok:
        return
    if not isinstance(value, int) or isinstance(value, bool) or value < 0:
        raise ValueError(f"{name}: expected a non-negative integer (candidates per failing "
                         f"member), got {value!r}")


def forget_module(module: str) -> list[str]:
    """Remove the declarations of ``module`` (before it is loaded again); returns their ids."""
    gone = [k for k, eq in REGISTRY.items() if eq.module == module]
    for k in gone:
        del REGISTRY[k]
        _BUILT.pop(k, None)
        _BUILT_BY.pop(k, None)
    return gone


def load_all() -> dict[str, Equation]:
    """Import the book (:data:`rigidsym.core.config.BOOK`), which registers its declarations."""
    import importlib

    from rigidsym.core import config as _config

    importlib.import_module(_config.BOOK)  # by name: the machinery never imports the book

    return REGISTRY


def book_reading():
    """The reading file of the book the registry declares (``READING`` of the book package,
    :data:`rigidsym.core.config.BOOK`): each glyph's kind or model and each id's class, as a
    person reviewed them (:mod:`rigidsym.reading`); ``None`` where the book names none.

    Returns:
        A :class:`pathlib.Path`, or ``None``.
    """
    import importlib

    from rigidsym.core import config as _config

    return getattr(importlib.import_module(_config.BOOK), "READING", None)


def book_ids() -> list[str]:
    """The chapter's ids (user declarations left out), in book order."""
    load_all()
    return sorted((k for k in REGISTRY if not is_user_id(k)), key=_sort_key)


def _sort_key(eq_id: str):
    """Book order: by section, a section's equations by number and part, then its claims;
    an id no declaration holds after the book's, user ids last in declaration order."""
    if is_user_id(eq_id):  # after the book, in declaration order
        return ((10**6,), 2, list(REGISTRY).index(eq_id) if eq_id in REGISTRY else 0, "")
    sec = _numbers(section_of(eq_id)) if eq_id in REGISTRY else (10**5,)
    if eq_id.startswith(("thm", "cor", "caveat")):
        return (sec, 1, 0, eq_id)
    m = _ID_PARTS.match(eq_id)
    return (sec, 0, int(m.group(2)), m.group(4))


def _known_book_ids() -> str:
    """The book's ids in words for a message: its first and last numbered equation, a claim,
    how to list a section's."""
    ids = book_ids()
    numbered = [i for i in ids if not i.startswith(("thm", "cor", "caveat"))]
    claims = [i for i in ids if i.startswith("thm")]
    if not numbered:
        return "the book declares no id"
    return (f"{numbered[0]} ... {numbered[-1]}"
            + (f" and claims such as {claims[0]}" if claims else "")
            + f"; the ids of a section: rigidsym verify --section {section_of(numbered[0])}")


def parse_id(text: str) -> str:
    """Normalise a user-given id (``"(3.16)"``, ``"eq3.16"`` -> ``"3.16"``; a user id
    ``namespace:name`` as given).

    Raises:
        BadInput: if the text is neither a book id nor a user id.
    """
    t = text.strip().strip("()")
    if is_user_id(t):
        return t
    if t.lower().startswith("eq"):
        t = t[2:]
    if not _ID.match(t):
        raise BadInput(f"id: expected a book id (an equation's number N.M or N.Ma, a claim's "
                       f"thmN.M.K), or a user id namespace:name, got {text!r}")
    return t


def parse_section(text: str) -> str:
    """Validate a section argument: one of :func:`book_sections`, or a section a loaded user
    declaration names.

    Raises:
        BadInput: any other, naming the book's sections (and why, where the book says why
            a section holds no id: ``SECTIONS_WITHOUT_IDS`` of the book package).
    """
    sections = book_sections()
    if text not in sections and not any(is_user_id(k) and eq.section == text
                                        for k, eq in REGISTRY.items()):
        why = _sections_without_ids().get(text)
        raise BadInput(f"section: expected one of {', '.join(sections)}, got {text!r}"
                       + (f" ({why})" if why else ""))
    return text


def _in_section(eq_id: str, s: str) -> bool:
    if is_user_id(eq_id):
        return REGISTRY[eq_id].section == s
    return section_of(eq_id) == s


def select(ids: list[str] | None = None, sections: list[str] | None = None,
           modules: list[str] | None = None) -> list[str]:
    """Resolve ids (an id without a letter means all its parts) and sections to sorted ids.

    Args:
        ids: book ids (``"3.16"``, ``"3.96"`` for all its parts) or user ids.
        sections: book sections ``"3.2"`` … ``"3.8"`` or sections of loaded user
            declarations.
        modules: names of loaded user modules
            (:func:`rigidsym.registry.usermodules.load`): with no ids and no
            sections, their ids are selected.

    Returns:
        The ids in order: book order first, then user ids in declaration order. With no
        argument at all, the chapter's ids only.

    Raises:
        BadInput: for an unknown id or section, or an id that holds no equation.
    """
    load_all()
    out: set[str] = set()
    for raw in ids or []:
        i = parse_id(raw)
        if i in REGISTRY:
            out.add(i)
            continue
        parts = [k for k in REGISTRY if re.fullmatch(re.escape(i) + "[a-e]", k)]
        if not parts:
            known = ("a loaded user module's ids: give its file with --module" if is_user_id(i)
                     else _known_book_ids())
            raise BadInput(f"id: {i} holds no declared equation{did_you_mean(i, REGISTRY)} "
                           f"(known: {known})")
        out.update(parts)
    for s in sections or []:
        s = parse_section(s)
        out.update(k for k in REGISTRY if _in_section(k, s))
    if not ids and not sections:
        if modules:
            out.update(k for k, eq in REGISTRY.items() if eq.module in modules)
        else:
            out.update(k for k in REGISTRY if not is_user_id(k))
    return sorted(out, key=_sort_key)
