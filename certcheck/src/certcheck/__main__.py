"""``python -m certcheck [--no-flint] [--quiet] PATH...``: check certificates (files, or
every ``*.json`` of a folder); print the hypotheses and a verdict per id; exit 1 when any
certificate fails, 2 on bad arguments."""

from __future__ import annotations

import argparse
import os
import sys
import time

from certcheck.check import CheckError, check_certificate, load


def _files(paths: list[str]) -> list[str]:
    out = []
    for p in paths:
        if os.path.isdir(p):
            out += sorted(os.path.join(p, f) for f in os.listdir(p) if f.endswith(".json"))
        else:
            out.append(p)
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="certcheck", description=__doc__.split("\n\n")[0])
    ap.add_argument("paths", nargs="+", help="certificate files or folders of them")
    ap.add_argument("--no-flint", action="store_true",
                    help="standard-library arithmetic only, even when python-flint is there")
    ap.add_argument("--quiet", action="store_true", help="one line per certificate")
    args = ap.parse_args(argv)
    files = _files(args.paths)
    if not files:
        print("certcheck: no certificate found", file=sys.stderr)
        return 2
    failed = 0
    t0 = time.perf_counter()
    for path in files:
        t = time.perf_counter()
        try:
            cert = load(path)
            verdict, lines = check_certificate(cert, fast=not args.no_flint)
        except (CheckError, OSError, ValueError) as exc:
            failed += 1
            print(f"FAILED {os.path.basename(path)}: {exc}")
            continue
        except Exception as exc:  # a malformed certificate is a failure, never a pass
            failed += 1
            print(f"FAILED {os.path.basename(path)}: {type(exc).__name__}: {exc}")
            continue
        print(f"CHECKED ({cert.get('id')}) {verdict}  [{time.perf_counter() - t:.2f} s]")
        if not args.quiet:
            for line in lines:
                print(f"    {line}")
    print(f"certcheck: {len(files) - failed} of {len(files)} certificates checked, "
          f"{failed} failed, {time.perf_counter() - t0:.1f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
