"""The prefix of a generated C folder (``rigidsym generate --target c|cpp --prefix NAME``).

Every name a generated folder exports carries one prefix, so that two folders (the book's
kernels under the default ``rigidsym_c`` and a user module under ``--prefix mybot``) link
into one program: the C functions and types (``mybot_twist_transfer``, ``mybot_status``),
the macros (``MYBOT_OK``, ``MYBOT_COMMON_H``), the file names (``mybot.h``,
``mybot_twist_transfer.c``), the CMake target with its alias and export
(``mybot::mybot``, ``find_package(mybot)``), the pkg-config module (``mybot.pc``) and the
C++ layer's header (``mybot.hpp``, whose namespace defaults to the prefix).

The templates print the default prefix; :func:`rename` applies another one to the
finished files, whole identifier by identifier, as CasADi's ``prefix`` option is applied
to every symbol of its generated C: an identifier that starts with ``rigidsym_c`` (then
``_``, an upper-case letter or its end: ``rigidsym_c_status``, ``rigidsym_cConfig``,
``rigidsym_c``) and one that starts with ``RIGIDSYM_C`` (then ``_`` or its end). The
template names in the provenance comments (``rigidsym_c_common.h.j2``) and words that
merely begin the same way (``rigidsym_cpp``) keep their text.
"""

from __future__ import annotations

import keyword
import re
from pathlib import Path

__all__ = ["DEFAULT_PREFIX", "PrefixError", "check_prefix", "rename", "generated_marker",
           "MARKER_SUFFIX"]

#: the prefix the templates print (the library's name when no ``--prefix`` is given)
DEFAULT_PREFIX = "rigidsym_c"
#: the file (``<prefix>_common.h``) whose presence marks a folder as a generated C target
MARKER_SUFFIX = "_common.h"
#: C and C++ keywords and alternative tokens (a prefix is a whole identifier: ``mybot`` is
#: also the C++ namespace), and namespaces a program already has
_KEYWORDS = set("""alignas alignof and and_eq asm auto bitand bitor bool break case catch
char char16_t char32_t char8_t class co_await co_return co_yield compl concept const
const_cast consteval constexpr constinit continue decltype default delete do double
dynamic_cast else enum explicit export extern false float for friend goto if inline int
long mutable namespace new noexcept not not_eq nullptr operator or or_eq private protected
public register reinterpret_cast requires restrict return short signed sizeof static
static_assert static_cast struct switch template this thread_local throw true try typedef
typeid typename union unsigned using virtual void volatile wchar_t while xor xor_eq std
posix""".split())
#: an identifier's start: no word character before it, or a compiler option's letter
#: (``-DRIGIDSYM_C_NO_WIDE``, ``-lrigidsym_c``)
_START = r"(?:(?<=-[DUlI])|(?<![A-Za-z0-9_]))"
_LOWER = re.compile(_START + r"rigidsym_c(?![a-z0-9])(?![\w.]*\.j2\b)")
_UPPER = re.compile(_START + r"RIGIDSYM_C(?![A-Za-z0-9])")
#: the regenerate hints in the files' comments, which gain the option
_HINT = re.compile(r"`rigidsym generate --target (c|cpp)`")


class PrefixError(ValueError):
    """A ``--prefix`` that cannot name a generated folder's symbols."""


def check_prefix(prefix: str) -> str:
    """``prefix`` if it can name every symbol of a generated folder, else an error.

    A prefix is a lower-case C identifier without ``_`` (``[a-z][a-z0-9]*``: the names are
    ``<prefix>_<kernel>``, so with ``_`` allowed ``--prefix a`` and ``--prefix a_b`` could
    both write ``a_b_twist_transfer``, ``a``'s kernel ``b_twist_transfer`` and ``a_b``'s
    ``twist_transfer``, and no folder can see the other; without it a name's prefix is what
    stands before its first ``_``, so folders of different prefixes share no name), not a
    C or C++ keyword (it is also the C++ namespace), and clashing with no name of the
    default prefix's folder: not ``rigidsym`` (whose ``rigidsym_c_...`` kernels would be
    the default folder's). The default ``rigidsym_c`` itself is accepted (no accepted
    prefix begins its names: they would have to be ``rigidsym``).

    Raises:
        PrefixError: naming ``--prefix`` and the rule it breaks.
    """
    if isinstance(prefix, str) and prefix == DEFAULT_PREFIX:
        return prefix
    if not isinstance(prefix, str) or not re.fullmatch(r"[a-z][a-z0-9_]*", prefix) or \
            "__" in prefix or prefix.endswith("_"):
        raise PrefixError(f"--prefix: {prefix!r} is not a lower-case C identifier "
                          f"([a-z][a-z0-9]*)")
    if "_" in prefix:
        head = prefix.split("_")[0]
        raise PrefixError(f"--prefix: {prefix!r} contains '_': the names of its folder "
                          f"({prefix}_<kernel>) could be those of a folder of prefix "
                          f"{head!r} (whose kernel {prefix[len(head) + 1:]}_<kernel> is "
                          f"also {prefix}_<kernel>), so that the two would not link into "
                          f"one program; choose a name without '_' "
                          f"(e.g. {prefix.replace('_', '')!r})")
    if prefix in _KEYWORDS or keyword.iskeyword(prefix):
        raise PrefixError(f"--prefix: {prefix!r} is a C or C++ keyword or a namespace of "
                          f"the standard library; choose another name")
    if DEFAULT_PREFIX.startswith(prefix + "_"):
        raise PrefixError(f"--prefix: {prefix!r} would clash with the names of a folder of "
                          f"the default prefix {DEFAULT_PREFIX!r} ({DEFAULT_PREFIX}_...); "
                          f"choose a name that neither starts with {DEFAULT_PREFIX}_ nor "
                          f"begins it")
    return prefix


def _rename_text(text: str, prefix: str) -> str:
    text = _LOWER.sub(prefix, text)
    text = _UPPER.sub(prefix.upper(), text)
    return _HINT.sub(lambda m: f"`rigidsym generate --target {m.group(1)} --prefix "
                               f"{prefix}`", text)


def rename(files: dict[str, str], prefix: str) -> dict[str, str]:
    """``files`` (``{relative path: text}`` of a generated folder, printed with the default
    prefix) with every path and text carrying ``prefix`` instead (see the module's
    docstring for what is renamed); unchanged for the default prefix.

    Raises:
        PrefixError: ``prefix`` is not one :func:`check_prefix` accepts.
    """
    check_prefix(prefix)
    if prefix == DEFAULT_PREFIX:
        return dict(files)
    return dict(sorted((_rename_text(path, prefix), _rename_text(text, prefix))
                       for path, text in files.items()))


def generated_marker(out: Path, prefix: str = DEFAULT_PREFIX) -> Path | None:
    """The file that marks ``out`` as a generated C folder: ``<prefix>_common.h``, or that of
    any other prefix (a folder regenerated under a new one) when it carries the generator's
    stamp (its comment says to regenerate with ``rigidsym generate --target c``); None for
    a folder of anyone else's files."""
    mine = out / f"{prefix}{MARKER_SUFFIX}"
    if mine.is_file():
        return mine
    for p in sorted(out.glob(f"*{MARKER_SUFFIX}")) if out.is_dir() else []:
        try:
            head = p.read_text(encoding="utf-8")[:2000]
        except (OSError, UnicodeDecodeError):
            continue
        if "Generated by rigidsym" in head and "rigidsym generate --target c" in head:
            return p
    return None
