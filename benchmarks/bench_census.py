"""The cost of the census (certify census) against the bound L.

    python benchmarks/bench_census.py [--lengths 8 10 12 14 16] [--jobs N] [--state FILE]
                                      [--from-state FILE]

For each L in turn, the census up to L is run on ``--jobs`` local processes with
``--resume`` on one state file, so the step to L analyses only the words longer than
the previous bound: printed are the wall time of each step and its cumulative sum
(the time of ``census --max-length L`` from scratch), and, from the seconds each
record carries in the state file, the analysis time per word length (sum, mean, max,
the slowest word) — where the time goes.  ``--from-state FILE`` only reads an
existing state file (e.g. reports/census-state.jsonl) and prints that table.

The table goes to stdout and to the section "census" of reports/BENCH.md.
(``bench_census()`` is the function ``certify bench --patterns`` is meant to call.)
"""
from __future__ import annotations

import argparse
import json
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


def per_length(state) -> list[str]:
    """The analysis seconds by word length, from the records of a state file."""
    by = defaultdict(list)
    for line in Path(state).read_text(encoding="utf-8").splitlines():
        try:
            rec = json.loads(line)
        except ValueError:
            continue
        if census.SECONDS in rec:
            by[rec["length"]].append((rec[census.SECONDS], rec["word"], rec["outcome"], bool(rec["feasible"])))
    rows = ["| length | words | analysis s (sum) | mean | max (word) | feasible: mean s | infeasible: mean s |",
            "|---:|---:|---:|---:|---|---:|---:|"]
    for n in sorted(by):
        xs = by[n]
        tot = sum(s for s, *_ in xs)
        worst = max(xs)
        feas = [s for s, _, _, f in xs if f]
        infe = [s for s, _, _, f in xs if not f]
        mean = lambda v: f"{sum(v) / len(v):.1f}" if v else "—"          # noqa: E731
        rows.append(f"| {n} | {len(xs)} | {tot:.1f} | {tot / len(xs):.1f} | {worst[0]:.1f} ({worst[1]}) | "
                    f"{mean(feas)} | {mean(infe)} |")
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
    args = p.parse_args(argv)
    if args.from_state:
        rows = ["Analysis time per word length (seconds in one worker, from "
                f"{args.from_state.name}):", ""] + per_length(args.from_state)
    else:
        rows = bench_census(args.lengths, args.jobs, args.state)
    print("\n".join(rows))
    if not args.no_write:
        write_section(ROOT / "reports" / "BENCH.md", "census", "\n".join(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
