"""Time ``certify all``: in-process with one process and on every core, and as the whole
command a user types; write the medians to ``reports/BENCH.md``, which README quotes.

    python benchmarks/bench.py [--repeat N] [--jobs N]
    python -m certify bench [--repeat N] [--jobs N]

For each repetition the engine's caches are emptied first
(:func:`certify.run.runner.reset_caches`), so every run is cold.  The proofs modules
(and SymPy, python-flint) are imported once before the clock starts.

Measured, each a median of N runs in one sitting:

* ``run_selected(jobs=1)``: every certificate one after another, in this process;
* ``run_selected(jobs=J)``: the same on J worker processes (default: every core);
* ``python -m certify all --out TMP``: the whole command (imports, certificates on
  every core, figures, report), wall time.

``--jobs J`` times only the in-process run on J processes.  Printed: the medians and
minima, the ratio serial/parallel, the heaviest certificates and the shared
quantities (from the serial runs).  With no ``--jobs``, the figures also go to
``reports/BENCH.md`` (section "certify all"), with the date, the machine and the
library versions.
"""
from __future__ import annotations

import argparse
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from datetime import date
from importlib.metadata import version
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:  # run as a script from a source checkout
    sys.path.insert(0, str(ROOT))

from certify.run import files, runner  # noqa: E402

HEAVIEST = 6
BENCH = ROOT / "reports" / "BENCH.md"


def time_runs(repeat: int, jobs: int) -> list[dict]:
    """Run every certificate ``repeat`` times on ``jobs`` processes; per run: total
    seconds, timings, FAIL ids."""
    runner.load_all()
    runs = []
    for _ in range(repeat):
        runner.reset_caches()
        start = time.perf_counter()
        results, timings = runner.run_selected(jobs=jobs)
        total = time.perf_counter() - start
        fails = [c.id for c, o in results if o.status == runner.FAIL]
        runs.append({"total": total, "timings": timings, "fails": fails})
    return runs


def time_command(repeat: int, args: list[str] | None = None) -> list[float]:
    """Wall seconds of ``python -m certify all --out TMP`` (or of ``python -m certify ARGS``),
    a fresh process each time."""
    seconds = []
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    for _ in range(repeat):
        with tempfile.TemporaryDirectory() as out:
            start = time.perf_counter()
            subprocess.run([sys.executable, "-m", "certify", *(args or ["all", "--out", out])], cwd=ROOT, env=env,
                           check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            seconds.append(time.perf_counter() - start)
    return seconds


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


def format_summary(s: dict, title: str) -> str:
    """One run kind as a small text table."""
    runs = f"{s['runs']} run{'s' if s['runs'] != 1 else ''}"
    fails = f" ({len(s['fails'])} FAIL: {', '.join(s['fails'])})" if s["fails"] else ""
    return (f"{title}: {runs} of {s['certificates']} certificates{fails}\n"
            f"  median {s['median']:.2f} s   min {s['min']:.2f} s   first (cold) {s['first']:.2f} s")


def format_detail(s: dict) -> str:
    """The heaviest certificates and the shared quantities of the serial runs."""
    lines = ["heaviest certificates (serial)   median s   of which shared"]
    lines += [f"  {cid:<30} {sec:>8.2f}   {shared:>15.2f}" for cid, (sec, shared) in s["heaviest"]]
    lines += ["", "shared quantities                median s"]
    lines += [f"  {name:<30} {sec:>8.2f}" for name, sec in s["shared"]] or ["  (none)"]
    return "\n".join(lines)


def machine() -> str:
    """The machine and the libraries, in one line."""
    libs = ", ".join(f"{name} {version(name)}" for name in ("sympy", "python-flint", "matplotlib"))
    return (f"{date.today().isoformat()}, {runner.default_jobs()} cores, {platform.machine()}, "
            f"Python {platform.python_version()}, {libs}")


def markdown(serial: dict, parallel: dict, jobs: int, command: list[float]) -> str:
    """The section of reports/BENCH.md for ``certify all``."""
    rows = [("`runner.run_selected(jobs=1)`, in-process", serial["median"], serial["min"]),
            (f"`runner.run_selected(jobs={jobs})`, in-process", parallel["median"], parallel["min"]),
            (f"`python -m certify all` (whole command, {jobs} processes)", statistics.median(command), min(command))]
    table = ["| run | median s | min s |", "|---|---:|---:|"]
    table += [f"| {name} | {med:.2f} | {low:.2f} |" for name, med, low in rows]
    heavy = ", ".join(f"{cid} {sec:.2f} s" for cid, (sec, _) in serial["heaviest"])
    shared = ", ".join(f"`{name}` {sec:.2f} s" for name, sec in serial["shared"])
    return "\n".join([
        f"Measured by `python -m certify bench --repeat {serial['runs']}` on {machine()}; "
        f"{serial['certificates']} certificates, caches emptied before each run.", "", *table, "",
        f"Ratio serial / parallel (medians): {serial['median'] / parallel['median']:.2f}.", "",
        f"Heaviest certificates (serial medians): {heavy}.", "",
        f"Shared quantities (serial medians): {shared}."])


def main(argv=None) -> int:
    """``bench.py [--repeat N] [--jobs N]``: time the runs, print, write BENCH.md."""
    parser = argparse.ArgumentParser(prog="bench", description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=3, metavar="N", help="number of runs of each kind (default: 3)")
    parser.add_argument("--jobs", type=int, default=None, metavar="N",
                        help="time only the in-process run on N processes (nothing written)")
    args = parser.parse_args(argv)
    if args.repeat < 1:
        parser.error("--repeat must be at least 1")
    if args.jobs is not None:
        s = summarise(time_runs(args.repeat, args.jobs))
        print(format_summary(s, f"run(jobs={args.jobs})"))
        print(format_detail(s))
        return 0
    jobs = runner.default_jobs()
    serial = summarise(time_runs(args.repeat, 1))
    parallel = summarise(time_runs(args.repeat, jobs))
    command = time_command(args.repeat)
    print(format_summary(serial, "run(jobs=1)"))
    print(format_summary(parallel, f"run(jobs={jobs})"))
    print(f"python -m certify all: median {statistics.median(command):.2f} s   min {min(command):.2f} s")
    print(f"ratio serial/parallel: {serial['median'] / parallel['median']:.2f}")
    print()
    print(format_detail(serial))
    files.write_section(BENCH, "certify all", markdown(serial, parallel, jobs, command))
    print(f"\nwrote {BENCH.relative_to(ROOT)} (section 'certify all')")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
