"""``rigidsym cache info | clear``: where the user cache is, what it holds, and emptying it.

The cache (:mod:`rigidsym.core.cache`) holds compiled kernels (``kernels/``), checked results
(``verdicts/``, :mod:`rigidsym.checking.verdict_cache`), the LaTeX grammar's analysis
(``latex/``) and the book's built statements (``statements/``,
:mod:`rigidsym.registry.statement_cache`). Clearing never changes a verdict:
what is gone is computed again on the next run. ``info`` lists the C driver's object cache
too (:mod:`rigidsym.kernels.cbuild.objects`: ``~/.cache/rigidsym/objects``, or
``RIGIDSYM_OBJECT_CACHE``; ``RIGIDSYM_CACHE`` does not move it),
which ``pip install`` fills and reads; ``rm -r`` of its folder empties it.
"""

from __future__ import annotations

from rigidsym.core import cache as _cache

__all__ = ["add_arguments", "run", "HELP"]

HELP = "where the user cache is, what it holds (info); empty it (clear)"


def add_arguments(c) -> None:
    """Arguments of ``rigidsym cache``."""
    sub = c.add_subparsers(dest="action", required=True)
    sub.add_parser("info", help="where the cache is, how big, how many entries")
    clear = sub.add_parser("clear", help="remove cached verdicts, compiled kernels and "
                                         "built statements")
    which = clear.add_mutually_exclusive_group()
    which.add_argument("--verdicts", action="store_true", help="only the checked results")
    which.add_argument("--kernels", action="store_true", help="only the compiled kernels")


def _size(n: int) -> str:
    for unit in ("B", "KiB", "MiB", "GiB"):
        if n < 1024 or unit == "GiB":
            return f"{n} {unit}" if unit == "B" else f"{n:.1f} {unit}"
        n /= 1024
    return f"{n} B"  # pragma: no cover


def _objects_line() -> str:
    """The object cache's line of ``cache info``: compiled objects, bytes, folder."""
    from rigidsym.kernels.cbuild import objects

    where = objects.root()
    if where is None:
        return ("  objects: off (RIGIDSYM_OBJECT_CACHE=0, or filelock missing): every C "
                "build compiles every object")
    files = [p for p in where.rglob("*") if p.is_file()] if where.is_dir() else []
    n = sum(p.suffix == ".o" for p in files)
    return (f"  objects: {n} compiled objects, {_size(sum(p.stat().st_size for p in files))} "
            f"in {where} (the C build's, filled by pip install; remove the folder to empty "
            f"it)")


def run(args) -> int:
    """``rigidsym cache info`` prints the cache folder (``RIGIDSYM_CACHE``, else the user
    cache folder) and per kind its path, entries and size; ``rigidsym cache clear`` removes
    every kind (``--verdicts`` or ``--kernels``: only those)."""
    if args.action == "info":
        info = _cache.info()
        print(f"cache: {info['root']} (set RIGIDSYM_CACHE to move it)")
        for kind in _cache.KINDS:
            k = info[kind]
            print(f"  {kind}: {k['entries']} entries, {_size(k['bytes'])} in {k['path']}")
        print(_objects_line())
        return 0
    kinds = ("verdicts",) if args.verdicts else ("kernels",) if args.kernels else _cache.KINDS
    gone = _cache.clear(kinds)
    print(f"cleared {' and '.join(kinds)}: "
          + (", ".join(str(p) for p in gone) if gone else "nothing to remove"))
    return 0
