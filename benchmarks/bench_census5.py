"""The cost of a five-particle word (certify census --particles 5) by length, in CPU seconds.

    python benchmarks/bench_census5.py [--max-length L] [--from-state FILE] [--words W ...] [--part reduction]

Analyses every word class up to L (default 6), or the words given by ``--words``, with
``five.analyse_five`` in this process, one at a time, and prints per length: the classes, the CPU
seconds (``time.process_time``: the machine is shared, so wall time is not the measure), mean and max,
and the growth of the classes from one length to the next.  ``--from-state FILE`` reads the seconds a
census state file carries (the CPU seconds of ``five.census_record``) instead.  The script times the
checkout it sits in: a copy of it in another checkout's benchmarks/ (``git archive`` of a commit) times
that code on the same words (the before/after of docs/census.md).  ``--part reduction`` times the
second way instead, the periodic orbits of the reduction (``five_orbits.census_part``; in a state file
its ``reduction_seconds``).  In a state file the last line of a word wins (a completed record is
appended after the record it completes).
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:  # run as a script from a source checkout
    sys.path.insert(0, str(ROOT))


def timed(max_length: int, words: list[str] | None = None, part: str = "pattern") -> dict[int, list[float]]:
    """CPU seconds of each class's analysis (or of each of ``words``), by length: ``part`` "pattern" (the
    κ route) or "reduction" (the periodic orbits of the reduction)."""
    from certify.patterns import five, five_orbits
    analyse = five.analyse_five if part == "pattern" else five_orbits.census_part
    by: dict[int, list[float]] = defaultdict(list)
    for w in words or five.word_classes(max_length):
        start = time.process_time()
        analyse(w)
        by[len(w)].append(time.process_time() - start)
    return by


def from_state(path: Path, part: str = "pattern") -> dict[int, list[float]]:
    """The seconds the state's records carry, by length (the last line of a word wins)."""
    key = "seconds" if part == "pattern" else "reduction_seconds"
    last = {}
    for line in path.read_text(encoding="utf-8").splitlines():
        rec = json.loads(line)
        last[rec["word"]] = rec
    by: dict[int, list[float]] = defaultdict(list)
    for rec in last.values():
        if key in rec:
            by[rec["length"]].append(rec[key])
    return by


def table(by: dict[int, list[float]]) -> str:
    rows = ["| length | classes | growth | seconds | mean | max |", "|---:|---:|---:|---:|---:|---:|"]
    previous = None
    for n in sorted(by):
        v = by[n]
        growth = f"{len(v) / previous:.2f}" if previous else ""
        rows.append(f"| {n} | {len(v)} | {growth} | {sum(v):.1f} | {sum(v) / len(v):.2f} | {max(v):.2f} |")
        previous = len(v)
    return "\n".join(rows)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--max-length", type=int, default=6)
    ap.add_argument("--from-state", type=Path, default=None)
    ap.add_argument("--words", nargs="+", default=None, help="these words (normal forms) only")
    ap.add_argument("--part", choices=("pattern", "reduction"), default="pattern",
                    help="the κ route (default) or the periodic orbits of the reduction")
    args = ap.parse_args(argv)
    print(table(from_state(args.from_state, args.part) if args.from_state
                else timed(args.max_length, args.words, args.part)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
