"""The cost of the census (certify census) against the bound L.

    python benchmarks/bench_census.py [--lengths 8 10 12 14 16] [--jobs N] [--state FILE]
                                      [--from-state FILE [--extrapolate L] [--fit-lengths N ...]
                                       [--scale F] [--anchor L0 SECONDS]]

For each L in turn, the census up to L is run on ``--jobs`` local processes with
``--resume`` on one state file, so the step to L analyses only the words longer than
the previous bound: printed are the wall time of each step and its cumulative sum
(the time of ``census --max-length L`` from scratch), and, from the seconds each
record carries in the state file, the analysis time per word length (sum, mean, max,
the slowest word) — where the time goes.  ``--from-state FILE`` only reads an
existing state file (e.g. reports/census-state.jsonl) and prints that table; with
``--extrapolate L`` also the time of the census up to L on 2, 16 and 64 cores, from the
growth of the words (counted exactly) and of the mean seconds per word (fitted): an
extrapolation, and the table says so.

The table goes to stdout and to the section "census" of reports/BENCH.md.
(``bench_census()`` is the function ``certify bench --patterns`` is meant to call.)
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:  # run as a script from a source checkout
    sys.path.insert(0, str(ROOT))

from certify.patterns import census  # noqa: E402
from certify.run import census_report as run_census  # noqa: E402
from certify.run.executors import default_jobs, executor  # noqa: E402
from certify.run.files import write_section  # noqa: E402

LENGTHS = (8, 10, 12, 14, 16)


def seconds_by_length(state) -> dict[int, list[tuple[float, str, bool]]]:
    """From the records of a state file: per word length, (seconds of both analyses, the
    self-similar one and the reduction's, word, feasible) of each word (its last line)."""
    last = {}
    for line in Path(state).read_text(encoding="utf-8").splitlines():
        try:
            rec = json.loads(line)
        except ValueError:
            continue
        if census.SECONDS in rec:
            last[rec["word"]] = rec
    by = defaultdict(list)
    for rec in last.values():
        total = rec[census.SECONDS] + rec.get(census.REDUCTION_SECONDS, 0.0)
        by[rec["length"]].append((total, rec["word"], bool(rec["feasible"])))
    return by


def per_length(state) -> list[str]:
    """The analysis seconds (both parts) by word length, from the records of a state file."""
    by = seconds_by_length(state)
    rows = ["| length | words | analysis s (sum) | mean | max (word) | feasible: mean s | infeasible: mean s |",
            "|---:|---:|---:|---:|---|---:|---:|"]
    for n in sorted(by):
        xs = by[n]
        tot = sum(s for s, *_ in xs)
        worst = max(xs)
        feas = [s for s, _, f in xs if f]
        infe = [s for s, _, f in xs if not f]
        mean = lambda v: f"{sum(v) / len(v):.2f}" if v else "—"          # noqa: E731
        rows.append(f"| {n} | {len(xs)} | {tot:.1f} | {tot / len(xs):.2f} | {worst[0]:.1f} ({worst[1]}) | "
                    f"{mean(feas)} | {mean(infe)} |")
    return rows


def extrapolate(means: dict[int, float], upto: int, cores=(2, 16, 64), anchor: tuple[int, float] | None = None,
                rows_from: int | None = None) -> list[str]:
    """An extrapolation, not a measurement: the mean seconds per word of each length fitted
    as exp(a + b·length) (least squares on the logarithms of ``means``), times the exact
    number of words of each length (census.words_of_length); per bound L up to ``upto``
    (from ``rows_from``, default past the fitted lengths): the words, the mean at L, the
    seconds of the whole census to L and the hours on N cores (the words are independent
    jobs; the longest word, about a minute at 20, is small against a core's share).

    Without ``anchor`` the measured means stand for their lengths and the fit beyond (the
    words shorter than the first fitted length are left out: minutes at most).  With
    ``anchor = (L0, seconds)`` (a whole census to L0 that took that many CPU seconds) the
    fitted means of every length are scaled so that the census to L0 costs exactly that:
    the fit gives the growth, the anchor the level."""
    xs = sorted(means)
    n = len(xs)
    mx, my = sum(xs) / n, sum(math.log(means[x]) for x in xs) / n
    b = sum((x - mx) * (math.log(means[x]) - my) for x in xs) / sum((x - mx) ** 2 for x in xs)
    a = my - b * mx
    counts = {length: len(census.words_of_length(length)) for length in range(1, upto + 1)}
    if anchor is None:
        mean = {k: means.get(k, math.exp(a + b * k)) if k >= xs[0] else 0.0 for k in counts}
        level = ""
    else:
        at, seconds = anchor
        scale = seconds / sum(counts[k] * math.exp(a + b * k) for k in range(1, at + 1))
        mean = {k: scale * math.exp(a + b * k) for k in counts}
        level = f"; level: the census to {at} in {seconds:.0f} s, so {mean[at]:.2f} s a word of length {at}"
    rows = [f"Fit: mean s per word = exp({a:.3f} + {b:.4f}·length), {math.exp(b):.3f}× per collision "
            f"(lengths {xs[0]}-{xs[-1]}){level}.", "",
            "| L | words to L | words of length L | mean s per word at L | hours of one worker to L | "
            + " | ".join(f"hours on {c} cores" for c in cores) + " |",
            "|---:|---:|---:|---:|---:|" + "---:|" * len(cores)]
    total_words, total = 0, 0.0
    for length in range(1, upto + 1):
        total_words += counts[length]
        total += counts[length] * mean[length]
        if length >= (xs[-1] + 1 if rows_from is None else rows_from):
            rows.append(f"| {length} | {total_words} | {counts[length]} | {mean[length]:.2f} | {total / 3600:.1f} | "
                        + " | ".join(f"{total / 3600 / c:.2f}" for c in cores) + " |")
    return rows


def bench_census(lengths=LENGTHS, jobs: int | None = None, state=None) -> list[str]:
    """Run the census up to each L of ``lengths`` in turn (resuming one state file);
    return the Markdown lines of the timings."""
    jobs = jobs or default_jobs()
    own = state is None
    tmp = tempfile.TemporaryDirectory() if own else None
    state = Path(tmp.name) / "state.jsonl" if own else Path(state)
    rows = [f"Census on {jobs} local process(es), each bound resuming the previous one "
            f"(state {'temporary' if own else state}).",
            "", "| L | words | new words | step wall s | cumulative wall s |", "|---:|---:|---:|---:|---:|"]
    total, before = 0.0, 0
    try:
        for L in lengths:
            start = time.perf_counter()
            with executor(jobs) as ex:
                records = run_census.run_census(L, ex, state, resume=True)
            step = time.perf_counter() - start
            total += step
            rows.append(f"| {L} | {len(records)} | {len(records) - before} | {step:.1f} | {total:.1f} |")
            before = len(records)
            print(rows[-1], flush=True)
        rows += ["", "Analysis time per word length (seconds in one worker, from the state file):", ""]
        rows += per_length(state)
    finally:
        if tmp is not None:
            tmp.cleanup()
    return rows


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--lengths", type=int, nargs="+", default=list(LENGTHS), metavar="L")
    p.add_argument("--jobs", type=int, default=None, metavar="N")
    p.add_argument("--state", type=Path, default=None, metavar="FILE", help="resume and keep this state file")
    p.add_argument("--from-state", type=Path, default=None, metavar="FILE",
                   help="only read the seconds of an existing state file")
    p.add_argument("--no-write", action="store_true", help="do not write reports/BENCH.md")
    p.add_argument("--extrapolate", type=int, default=None, metavar="L",
                   help="with --from-state: also extrapolate the census's time up to L from the means per length "
                        "of --fit-lengths (an extrapolation, said so)")
    p.add_argument("--fit-lengths", type=int, nargs="+", default=None, metavar="N",
                   help="the lengths whose mean seconds per word the extrapolation fits (default: 12 and above)")
    p.add_argument("--scale", type=float, default=1.0, metavar="F",
                   help="multiply the measured seconds by F before fitting (e.g. the CPU share of a loaded machine: "
                        "the process's CPU seconds over the summed wall seconds of its records)")
    p.add_argument("--anchor", nargs=2, type=float, default=None, metavar=("L0", "SECONDS"),
                   help="with --extrapolate: scale the fit so that the census to L0 costs SECONDS of CPU (a run "
                        "measured whole); the fit then gives only the growth")
    args = p.parse_args(argv)
    if args.from_state:
        rows = ["Analysis time per word length (seconds in one worker, from "
                f"{args.from_state.name}):", ""] + per_length(args.from_state)
        if args.extrapolate:
            by = seconds_by_length(args.from_state)
            fit = args.fit_lengths or [n for n in by if n >= 12]
            means = {n: args.scale * sum(s for s, *_ in by[n]) / len(by[n]) for n in fit}
            rows += ["", f"Extrapolated (not measured) to {args.extrapolate}, seconds scaled by {args.scale}:", ""]
            anchor = (int(args.anchor[0]), args.anchor[1]) if args.anchor else None
            rows += extrapolate(means, args.extrapolate, anchor=anchor,
                                rows_from=anchor[0] if anchor else None)
    else:
        rows = bench_census(args.lengths, args.jobs, args.state)
    print("\n".join(rows))
    if not args.no_write:
        write_section(ROOT / "reports" / "BENCH.md", "census", "\n".join(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
