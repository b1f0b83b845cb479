"""Time a whole ``certify all`` run, in-process, without writing any report.

    python benchmarks/bench.py [--repeat N]
    python -m certify bench [--repeat N]

Each repetition calls :func:`certify.run.runner.run` over every certificate with a
fresh context, so the shared quantities (M, cp(M), the branches, ...) are
computed again each time.  No figure and no report is written.  The proofs
modules (and SymPy, python-flint) are imported once before the clock starts.
The engine's caches are emptied before each repetition
(:func:`certify.run.runner.reset_caches`), so every repetition is a cold run.

Printed: the median and minimum total, the five heaviest certificates (median
seconds, and the part spent computing shared quantities they were the first
to need) and the median time of every shared quantity.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:  # run as a script from a source checkout
    sys.path.insert(0, str(ROOT))

from certify.run import runner  # noqa: E402

HEAVIEST = 5


def time_runs(repeat: int) -> list[dict]:
    """Run every certificate ``repeat`` times; per run: total seconds, timings, FAIL ids."""
    runner.load_all()
    runs = []
    for _ in range(repeat):
        runner.reset_caches()
        start = time.perf_counter()
        results, timings = runner.run()
        total = time.perf_counter() - start
        fails = [c.id for c, o in results if o.status == runner.FAIL]
        runs.append({"total": total, "timings": timings, "fails": fails})
    return runs


def median_of(runs: list[dict], section: str, name: str, key: str | None = None) -> float:
    """The median over the runs of one timing (a certificate's or a quantity's)."""
    values = []
    for run in runs:
        entry = run["timings"][section].get(name)
        if entry is not None:
            values.append(entry[key] if key else entry)
    return statistics.median(values) if values else 0.0


def summarise(runs: list[dict]) -> dict:
    """Medians and minima of the runs, as plain data."""
    totals = [run["total"] for run in runs]
    certs = runs[0]["timings"]["certificates"]
    per_cert = {c: (median_of(runs, "certificates", c, "seconds"),
                    median_of(runs, "certificates", c, "of_which_shared")) for c in certs}
    heaviest = sorted(per_cert.items(), key=lambda kv: -kv[1][0])[:HEAVIEST]
    shared = {q: median_of(runs, "shared", q) for q in runs[0]["timings"]["shared"]}
    return {"runs": len(runs), "certificates": len(certs), "fails": runs[-1]["fails"],
            "median": statistics.median(totals), "min": min(totals), "first": totals[0],
            "heaviest": heaviest, "shared": sorted(shared.items(), key=lambda kv: -kv[1])}


def format_summary(s: dict) -> str:
    """The summary as a small text table."""
    runs = f"{s['runs']} run{'s' if s['runs'] != 1 else ''}"
    fails = f" ({len(s['fails'])} FAIL: {', '.join(s['fails'])})" if s["fails"] else ""
    lines = [f"certify bench: {runs} of {s['certificates']} certificates{fails}",
             f"total  median {s['median']:.3f} s   min {s['min']:.3f} s   "
             f"first (cold) {s['first']:.3f} s", "",
             "heaviest certificates      median s   of which shared"]
    lines += [f"  {cid:<22} {sec:>9.3f}   {shared:>15.3f}" for cid, (sec, shared) in s["heaviest"]]
    lines += ["", "shared quantities          median s"]
    lines += [f"  {name:<22} {sec:>9.3f}" for name, sec in s["shared"]] or ["  (none)"]
    return "\n".join(lines)


def main(argv=None) -> int:
    """``bench.py [--repeat N]``: time the runs and print the table."""
    parser = argparse.ArgumentParser(prog="bench", description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=5, metavar="N",
                        help="number of runs (default: 5)")
    args = parser.parse_args(argv)
    if args.repeat < 1:
        parser.error("--repeat must be at least 1")
    runs = time_runs(args.repeat)
    if not runs[0]["timings"]["certificates"]:
        print("certify bench: no certificate to time")
        return 0
    print(format_summary(summarise(runs)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
