"""The cost of a five-particle word (certify census --particles 5) by length, in CPU seconds.

    python benchmarks/bench_census5.py [--max-length L] [--from-state FILE] [--words W ...] [--sample N [--seed S]]
                                       [--part pattern|reduction|record]

Analyses every word class up to L (default 6), or the words given by ``--words``, with
``five.analyse_five`` in this process, one at a time, and prints per length: the classes, the CPU
seconds (``time.process_time``: the machine is shared, so wall time is not the measure), mean and max,
and the growth of the classes from one length to the next.  ``--from-state FILE`` reads the seconds a
census state file carries (the CPU seconds of ``five.census_record``) instead.  The script times the
checkout it sits in: a copy of it in another checkout's benchmarks/ (``git archive`` of a commit) times
that code on the same words (the before/after of docs/census.md).  ``--part reduction`` times the
second way instead, the periodic orbits of the reduction (``five_orbits.census_part``; in a state file
its ``reduction_seconds``); ``--part record`` the census's whole record, both parts sharing the word's
candidates (``census5.record``, what a census job costs).  ``--sample N`` analyses N classes of length L
drawn at random (``--seed``, default 1: the same words in every checkout) instead of every class up to L:
the estimate of a length too long to run whole.  In a state file the last line of a word wins (a
completed record is appended after the record it completes).
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
    from certify.run import census5
    analyse = {"pattern": five.analyse_five, "reduction": five_orbits.census_part, "record": census5.record}[part]
    by: dict[int, list[float]] = defaultdict(list)
    for w in words or five.word_classes(max_length):
        start = time.process_time()
        analyse(w)
        by[len(w)].append(time.process_time() - start)
    return by


def sample(length: int, n: int, seed: int = 1) -> list[str]:
    """n word classes of ``length`` letters drawn at random (``random.Random(seed)``), in census order."""
    import random

    from certify.patterns import five
    words = [w for w in five.word_classes(length) if len(w) == length]
    return sorted(random.Random(seed).sample(words, min(n, len(words))))


def from_state(path: Path, part: str = "pattern") -> dict[int, list[float]]:
    """The seconds the state's records carry, by length (the last line of a word wins)."""
    keys = {"pattern": ["seconds"], "reduction": ["reduction_seconds"],
            "record": ["seconds", "reduction_seconds"]}[part]
    last = {}
    for line in path.read_text(encoding="utf-8").splitlines():
        rec = json.loads(line)
        last[rec["word"]] = rec
    by: dict[int, list[float]] = defaultdict(list)
    for rec in last.values():
        if all(key in rec for key in keys):
            by[rec["length"]].append(sum(rec[key] for key in keys))
    return by


def table(by: dict[int, list[float]]) -> str:
    import statistics
    rows = ["| length | classes | growth | seconds | mean | median | max |", "|---:|---:|---:|---:|---:|---:|---:|"]
    previous = None
    for n in sorted(by):
        v = by[n]
        growth = f"{len(v) / previous:.2f}" if previous else ""
        rows.append(f"| {n} | {len(v)} | {growth} | {sum(v):.1f} | {sum(v) / len(v):.2f} | "
                    f"{statistics.median(v):.2f} | {max(v):.2f} |")
        previous = len(v)
    return "\n".join(rows)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--max-length", type=int, default=6)
    ap.add_argument("--from-state", type=Path, default=None)
    ap.add_argument("--words", nargs="+", default=None, help="these words (normal forms) only")
    ap.add_argument("--sample", type=int, default=None, help="N random classes of length --max-length")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--part", choices=("pattern", "reduction", "record"), default="pattern",
                    help="the κ route (default), the periodic orbits of the reduction, or a census job (both)")
    args = ap.parse_args(argv)
    words = sample(args.max_length, args.sample, args.seed) if args.sample else args.words
    print(table(from_state(args.from_state, args.part) if args.from_state
                else timed(args.max_length, words, args.part)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
