"""The cost of ``certify pattern (ab)^n(cb)^n`` against n.

    python benchmarks/bench_patterns.py [--repeat N] [--n 2 3 ... 12] [--budget SECONDS]
    python benchmarks/bench_patterns.py --orbit [--repeat N] [--n 2 ... 6]
    python benchmarks/bench_patterns.py --family [--n 12 20 40] [--budget SECONDS]
    python -m certify bench --patterns [--repeat N]
    python -m certify bench --family

For each n, :func:`certify.patterns.analyse` on (ab)^n(cb)^n over ]0, 1[, ``--repeat``
times, each cold (the engine's caches emptied first, :func:`certify.run.runner.reset_caches`);
printed: the median and minimum seconds, the length of the word and the verdict.  An n
whose first run takes longer than ``--budget`` seconds (default 600) stops the series:
the larger n are reported as not measured.  The table goes to stdout and to the section
"certify pattern" of reports/BENCH.md (:func:`certify.run.files.write_section`).  With
``--orbit``: :func:`certify.patterns.reduction_orbits.analyse` instead (``certify orbit``), on
(ab)^n(cb)^n and the complex-pair attractor abacbabcbcabcb, into the section "certify orbit"
(the figures docs/orbit.md quotes).  With ``--family`` (:func:`bench_family`): the whole command
``python -m certify pattern (ab)^n(cb)^n --json`` for n = 8, 12 (the engine's family route) and 31,
40, 60 (the theorem's window; docs/family.md), once each in a fresh process, stopped after ``--budget`` seconds,
into the section "certify pattern, the family".

:func:`bench_pattern_words` is the function other benchmark scripts (the census's) call.
"""
from __future__ import annotations

import argparse
import math
import platform
import statistics
import sys
import time
from datetime import date
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:  # run as a script from a source checkout
    sys.path.insert(0, str(ROOT))

from certify.patterns import analyse  # noqa: E402
from certify.patterns.family_windows import EXACT_N0  # noqa: E402
from certify.run import files, runner  # noqa: E402

BENCH = ROOT / "reports" / "BENCH.md"
NS = tuple(range(2, 13))


def bench_pattern_words(ns=NS, repeat: int = 3, budget: float = 600.0, words=None, analyse=analyse) -> list[dict]:
    """Time ``analyse(word)`` cold, ``repeat`` times per word ((ab)^n(cb)^n for n in ``ns``,
    or the given ``words``); one dict per word: word, length, median, min, verdict (or
    ``skipped``: the reason)."""
    words = list(words) if words is not None else [f"(ab)^{n}(cb)^{n}" for n in ns]
    rows, over = [], None
    for word in words:
        if over is not None:
            rows.append({"word": word, "skipped": f"not measured: a shorter word took {over:.0f} s > {budget:.0f} s"})
            continue
        times, verdict = [], ""
        for k in range(repeat):
            runner.reset_caches()
            start = time.perf_counter()
            try:
                res = analyse(word)
            except ArithmeticError as exc:          # an analysis that stops is a result to report
                rows.append({"word": word, "skipped": f"stopped after {time.perf_counter() - start:.0f} s: {exc}"})
                break
            times.append(time.perf_counter() - start)
            verdict = res.verdict
            if k == 0 and times[0] > budget:
                over = times[0]
                break
        if not times:
            continue
        rows.append({"word": word, "length": len(res.normal), "median": statistics.median(times),
                     "min": min(times), "runs": len(times), "verdict": verdict})
    return rows


FAMILY_NS = (8, 12, 31, 40, 60)        # n ≤ 30: the engine's family route; n > 30: the theorem's window


def bench_family(ns=FAMILY_NS, budget: float = 600.0) -> list[dict]:
    """Wall seconds of ``python -m certify pattern (ab)^n(cb)^n --json`` (a fresh process: imports,
    analysis, printing), once per n; a run past ``budget`` seconds is stopped and reported, and the
    larger n of the engine's route (n ≤ 30) are not measured; n > 30 (the theorem's route) always are.
    One dict per n: word, seconds (or ``skipped``), the route and the verdict's tail."""
    import json
    import os
    import subprocess
    rows, over = [], None
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    for n in ns:
        word = f"(ab)^{n}(cb)^{n}"
        if over is not None and n <= EXACT_N0:
            rows.append({"word": word, "skipped": f"not measured: a shorter word ran past {over:.0f} s"})
            continue
        start = time.perf_counter()
        try:
            out = subprocess.run([sys.executable, "-m", "certify", "pattern", word, "--json"], cwd=ROOT, env=env,
                                 check=True, capture_output=True, text=True, timeout=budget).stdout
        except subprocess.TimeoutExpired:
            over = budget
            rows.append({"word": word, "skipped": f"stopped after {budget:.0f} s"})
            continue
        data = json.loads(out)
        rows.append({"word": word, "length": 4 * n, "median": time.perf_counter() - start, "min": None, "runs": 1,
                     "verdict": f"{data.get('route', 'engine')} route; {len(data['undecided'])} undecided point(s); "
                                "stable: "
                                + "; ".join(f"{s['branch']} {s['fixed_point']}: {s['set']}" for s in data["stable"])})
    return rows


def table(rows) -> str:
    out = ["| word | length | median (s) | min (s) | runs | verdict |", "|---|---|---|---|---|---|"]
    for r in rows:
        if "skipped" in r:
            out.append(f"| {r['word']} | | | | | {r['skipped']} |")
        else:
            low = "" if r["min"] is None else f"{r['min']:.1f}"
            out.append(f"| {r['word']} | {r['length']} | {r['median']:.1f} | {low} | {r['runs']} | "
                       f"{r['verdict']} |")
    return "\n".join(out)


def growth_law(rows) -> str:
    """The power law t ≈ C·L^k fitted by least squares to log(median) against log(length)
    over the measured words, with the ratio of consecutive medians: the growth this run
    measures (a fit, not a bound)."""
    pts = [(math.log(r["length"]), math.log(r["median"])) for r in rows if "skipped" not in r and r["median"] > 0]
    if len(pts) < 2:
        return "growth: fewer than two words measured"
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    k = sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)
    c = math.exp(my - k * mx)
    measured = [r for r in rows if "skipped" not in r]
    ratios = ", ".join(f"{b['median'] / a['median']:.2f}" for a, b in zip(measured, measured[1:]))
    return (f"growth: median ≈ {c:.3g}·L^{k:.2f} seconds for a word of L collisions (least squares on "
            f"log-log over L = {measured[0]['length']}..{measured[-1]['length']}); ratios of consecutive "
            f"medians: {ratios}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--n", type=int, nargs="+", default=list(NS))
    ap.add_argument("--budget", type=float, default=600.0)
    ap.add_argument("--orbit", action="store_true", help="time `certify orbit` instead (section 'certify orbit')")
    ap.add_argument("--family", action="store_true", help="time the whole `certify pattern (ab)^n(cb)^n` for "
                    "n = 8, 12, 31, 40, 60 instead (section 'certify pattern, the family')")
    args = ap.parse_args(argv)
    if args.orbit:
        return bench_orbit(args)
    if args.family:
        ns = args.n if args.n != list(NS) else list(FAMILY_NS)
        body = (f"`python -m certify pattern (ab)^n(cb)^n --json`, the whole command in a fresh process, once each, "
                f"stopped after {args.budget:.0f} s ({date.today()}, {platform.processor() or platform.machine()}, "
                f"Python {platform.python_version()}; benchmarks/bench_patterns.py --family):\n\n"
                + table(bench_family(ns, args.budget)))
        print(body)
        files.write_section(BENCH, "certify pattern, the family", body)
        return 0
    rows = bench_pattern_words(args.n, args.repeat, args.budget)
    body = (f"`certify pattern (ab)^n(cb)^n` over ]0, 1[, cold (caches emptied), median of {args.repeat} "
            f"({date.today()}, {platform.processor() or platform.machine()}, Python {platform.python_version()}; "
            f"benchmarks/bench_patterns.py):\n\n" + table(rows) + "\n\n" + growth_law(rows))
    print(body)
    files.write_section(BENCH, "certify pattern", body)
    return 0


def bench_orbit(args) -> int:
    """``--orbit``: ``certify orbit`` on (ab)^n(cb)^n (n of ``--n``, at most 6 by default) and
    abacbabcbcabcb, cold; the section "certify orbit" of reports/BENCH.md."""
    from certify.patterns.reduction_orbits import analyse as analyse_orbit
    ns = args.n if args.n != list(NS) else [2, 3, 4, 5, 6]
    words = ["abacbabcbcabcb"] + [f"(ab)^{n}(cb)^{n}" for n in ns]
    rows = bench_pattern_words(repeat=args.repeat, budget=args.budget, words=words, analyse=analyse_orbit)
    body = (f"`certify orbit WORD` over ]0, 1[ (with the `pattern` analysis of its physics line), cold (caches "
            f"emptied), median of {args.repeat} ({date.today()}, {platform.processor() or platform.machine()}, "
            f"Python {platform.python_version()}; benchmarks/bench_patterns.py --orbit):\n\n" + table(rows))
    print(body)
    files.write_section(BENCH, "certify orbit", body)
    return 0


if __name__ == "__main__":
    sys.exit(main())
