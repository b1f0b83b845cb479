"""python3 -m certify_kernel [reports/certificates.json] [--statements DIR] [--only ID ...] [--jobs N] [--verbose]

Decides every statement of the statement files (statements/*.txt) with the kernel's own
definitions and the witnesses of reports/certificates.json; prints one line per certificate
(its status and how many of its statements are verified, and why any is not), then the count;
exit 0 when nothing fails, 1 when a statement's decision contradicts its verdict or the run's
file disagrees with the statement files, 2 on bad input.
"""
from __future__ import annotations

import argparse
import os
import sys
import time

from . import counts, line, load, read, verify_all
from .statements import DEFAULT as STATEMENTS
from .statements import FileError

DEFAULT = os.path.join("reports", "certificates.json")


class Parser(argparse.ArgumentParser):
    """An option error in one line on stderr, exit 2 (bad input), as every other error."""

    def error(self, message):
        print(f"error: {message}", file=sys.stderr)
        raise SystemExit(2)


def jobs(text: str) -> int:
    """--jobs: a positive integer."""
    if not text.isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {text[:40]!r}")
    return int(text)


def _is_terminal(stream) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):      # no isatty, or a closed stream
        return False


def progress(k: int, n: int, label: str = "") -> None:
    """k of n certificates decided, on one line of stderr rewritten in place (erased at the end);
    :func:`main` passes it only when stderr is a terminal, so a file or a pipe gets nothing."""
    text = f"\r{k}/{n} certificates decided" + (f" (last: {label})" if label else "") if k < n else "\r"
    sys.stderr.write(text + "\x1b[K")
    sys.stderr.flush()


def main(argv=None) -> int:
    """Parse the options, verify, print; the exit code."""
    parser = Parser(prog="python3 -m certify_kernel",
                    description="Decides the paper's statements (statements/*.txt) with the "
                                "kernel's own definitions and the witnesses of a certificates file.")
    parser.add_argument("path", nargs="?", default=DEFAULT, help=f"the certificates file (default: {DEFAULT})")
    parser.add_argument("--statements", default=str(STATEMENTS), metavar="DIR",
                        help="the statement files (default: statements/ of the checkout)")
    parser.add_argument("--only", nargs="+", metavar="ID", default=None, help="check only these certificates")
    parser.add_argument("--jobs", type=jobs, default=min(2, os.cpu_count() or 1), metavar="N",
                        help="processes (default: 2)")
    parser.add_argument("--verbose", action="store_true", help="list every statement and its result")
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:               # --help: 0; an option error: 2, said in one line
        return exc.code if isinstance(exc.code, int) else 0
    try:
        data = load(args.path)
        paper = read(args.statements)
    except (OSError, ValueError, FileError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    ids = None
    if args.only:
        ids = {i.upper() for i in args.only}
        unknown = ids - {c.id for c in paper.certificates}
        if unknown:
            print(f"error: no certificate {', '.join(sorted(unknown))} in the statement files", file=sys.stderr)
            return 2
    stray = sorted({c["id"] for c in data["certificates"]} - {c.id for c in paper.certificates})
    start = time.perf_counter()
    results = verify_all(data, paper, args.jobs, ids, tick=progress if _is_terminal(sys.stderr) else None)
    for r in results:
        print(line(r))
        if args.verbose:
            for sid, ok, why in r["statements"]:
                print(f"    {sid}: {'verified' if ok else 'not verified: ' + why}")
    for i in stray:
        print(f"{i}: FAILED: certificates.json has it, the statement files do not")
    failed = [r["id"] for r in results if not r["ok"]] + stray
    k, n = counts(results)
    print(f"{len(results)} certificates, {len(failed)} failed ({time.perf_counter() - start:.1f} s); "
          f"{k}/{n} statements verified")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
