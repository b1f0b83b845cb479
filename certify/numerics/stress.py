"""Stress tests of the numerical engines (``python -m certify stress``): near-singular
data, long orbits and 1000 random orbits, every engine against the certified ball
engine.

The rule checked: what an engine *certifies* is true.  Each floating engine reports
its certified horizon (the collisions its accumulated error bound proves,
:func:`.rules.carry_bound`); past it an orbit may go on (a shadowing orbit) and may
leave the certified ball word: a *departure*, reported with where it happened, but no
error.  A word that departs from the ball word at a collision the engine certified is
a *silent wrong collision*; :func:`report` counts them (the command exits 1 when there
is one).
"""
from __future__ import annotations

import math
import random
import time
from dataclasses import dataclass

import numpy as np

from . import engines

R_CRIT3 = 7 - 4 * math.sqrt(3)                 # the three-particle threshold, ≈ 0.0718
THETA, PHI = math.pi / 6, math.pi / 5          # the first datum of the tool's grid of 8 initial data
COMPARED = (("float64", None), ("mp", 30), ("mp", 16))
RANDOM_COMPARED = (("float64", None), ("mp", 30))
RANDOM = dict(count=1000, collisions=2000, seed=20241110)
RANDOM_QUICK = dict(count=40, collisions=300, seed=20241110)
REGIMES = ((0.0, R_CRIT3, "r < 7−4√3"), (R_CRIT3, 0.13, "7−4√3 < r < 0.13 (between the windows)"),
           (0.13, 0.17, "0.13 < r < 0.17 (windows)"), (0.17, 0.9, "0.17 < r < 0.9 (apparent chaos)"),
           (0.9, 1.0, "0.9 < r < 1"))


@dataclass
class Case:
    group: str
    r: float
    theta0: float
    phi0: float
    collisions: int


def cases(quick: bool = False) -> list[Case]:
    """The near-singular data (and a few random ones), ``collisions`` 2000 (300 quick)."""
    n = 300 if quick else 2000
    out = []
    for d in (1e-17, 1e-15, 5e-15, 8e-15, 1e-14, 1e-13, 1e-12):
        for s in (1, -1):
            out.append(Case("|cos φ0| near 1e-15", 0.5, math.pi / 5, math.pi / 2 + s * d, n))
    for t in (0.0, 1e-300, 1e-16, 1e-14, 1e-12, 1e-8):
        out.append(Case("θ0 near 0", 0.5, t, 1.0, n))
    for t in (1e-16, 1e-15, 1e-13, 1e-10):
        out.append(Case("θ0 near π/2", 0.5, math.pi / 2 - t, 1.0, n))
    for r in (1e-300, 1e-12, 1e-6, 1e-3, 0.01):
        out.append(Case("r near 0", r, THETA, PHI, n))
    for d in (-1e-6, -1e-12, 0.0, 1e-12, 1e-6):
        out.append(Case("r near 7−4√3", R_CRIT3 + d, THETA, PHI, n))
    for d in (1e-3, 1e-6, 1e-12, 2 ** -53):
        out.append(Case("r near 1", 1 - d, THETA, PHI, n))
    rng = random.Random(20241110)
    for _ in range(8 if quick else 40):
        out.append(Case("random", rng.uniform(0.01, 0.999), rng.uniform(0, math.pi / 2), rng.uniform(0, math.pi), n))
    unique: dict = {}                      # once each: π/2 ± 1e-17 is π/2 in float64 (one row, not two)
    for c in out:
        unique.setdefault((c.r, c.theta0, c.phi0, c.collisions), c)
    return list(unique.values())


def random_data(count: int, seed: int) -> list[tuple[float, float, float]]:
    """``count`` seeded (r, θ0, φ0): r uniform in [0.001, 0.999], θ0 in [0, π/2], φ0 in [0, π]."""
    rng = random.Random(seed)
    return [(rng.uniform(0.001, 0.999), rng.uniform(0, math.pi / 2), rng.uniform(0, math.pi)) for _ in range(count)]


def departure(word: str, certified: str) -> int:
    """The first collision (1-based) where ``word`` departs from ``certified``, 0 if none."""
    for k, (x, y) in enumerate(zip(word, certified)):
        if x != y:
            return k + 1
    return 0


def cell(text: str) -> str:
    """A Markdown table cell: a '|' inside it escaped (it would end the cell)."""
    return str(text).replace("|", "\\|")


def compare(r, theta0, phi0, collisions, setups=COMPARED) -> dict:
    """One datum on the ball engine and on every (engine, dps) of ``setups``: plain data
    (picklable, for a worker).  ``ball``: (code, collisions, bits); per setup: (code,
    collisions, certified, departure from the ball word (0: none within both))."""
    ball = engines.run_orbit("ball", r, theta0, phi0, collisions, word=True)
    out = {"ball": (ball.code, ball.collisions, ball.bits)}
    for engine, dps in setups:
        res = engines.run_orbit(engine, r, theta0, phi0, collisions, dps=dps, word=True)
        out[(engine, dps)] = (res.code, res.collisions, res.certified, departure(res.word, ball.word))
    return out


def silent(entry, ball) -> bool:
    """A departure at a certified collision that the ball engine also proves."""
    code, done, certified, k = entry
    return 0 < k <= certified


def verdict(entry, ball) -> str:
    """The cell of one engine's run against the certified one."""
    code, done, certified, k = entry
    if silent(entry, ball):
        return f"**WRONG at {k}** (certified {certified})"
    text = f"= {done}" if code == 0 else f"break {code} at {done}"
    text += f", certified {certified}"
    if k:
        text += f", departs at {k}"
    if done > ball[1] and not k:
        text += f" ({done - ball[1]} beyond the ball's)"
    return text


def _head(ball) -> str:
    code, done, bits = ball
    return (f"break {code} at {done}" if code else f"= {done}") + f" ({bits} bits)"


def long_orbits(quick: bool):
    """float64 for 10^6 collisions (10^4 quick), against mp 30 digits for the first
    10^5 (10^3) and the certified ball word for the first 10^4 (10^3)."""
    n_float, n_mp, n_ball = (10**4, 10**3, 10**3) if quick else (10**6, 10**5, 10**4)
    rows, wrong = [], 0
    for r in (0.15, 0.5, 0.9):
        start = time.perf_counter()
        f = engines.run_orbit("float64", r, THETA, PHI, n_float, word=True)
        t_f = time.perf_counter() - start
        m = engines.run_orbit("mp", r, THETA, PHI, n_mp, dps=30, word=True)
        start = time.perf_counter()
        b = engines.run_orbit("ball", r, THETA, PHI, n_ball, word=True)
        t_b = time.perf_counter() - start
        k_m, k_b, k_mb = departure(f.word, m.word), departure(f.word, b.word), departure(m.word, b.word)
        wrong += (0 < k_b <= f.certified) + (0 < k_mb <= m.certified)
        rows.append(f"| {r} | {f.collisions} (break {f.code}), certified {f.certified}, {t_f:.2f} s | "
                    f"{'departs at ' + str(k_m) if k_m else 'same'} ({m.collisions}, mp certified {m.certified}) | "
                    f"{'departs at ' + str(k_b) if k_b else 'same'}; mp {'departs at ' + str(k_mb) if k_mb else 'same'}"
                    f" ({b.collisions}, {b.bits} bits, {t_b:.1f} s) |")
    return rows, wrong, (n_float, n_mp, n_ball)


def quantiles(values) -> str:
    """min / 10 % / median / 90 % / max of integers, or '-'."""
    if len(values) == 0:
        return "-"
    q = np.percentile(np.asarray(values, dtype=float), [0, 10, 50, 90, 100], method="lower")
    return " / ".join(str(int(x)) for x in q)


def random_section(results, data, collisions) -> tuple[list[str], int]:
    """The tables of the random orbits: per regime of r and engine, the certified
    horizons, the departures, the silent wrong collisions."""
    lines = ["| regime | orbits | ball: completed, bits (median / max) | engine | certified horizon "
             "(min / 10 % / median / 90 % / max) | departed | departure (min / 10 % / median / 90 % / max) | "
             "beyond the horizon before departing (min / median) | silent wrong |",
             "|---|---|---|---|---|---|---|---|---|"]
    wrong = 0
    for lo, hi, name in REGIMES:
        idx = [k for k, (r, _, _) in enumerate(data) if lo < r <= hi]
        if not idx:
            continue
        balls = [results[k]["ball"] for k in idx]
        completed = sum(1 for b in balls if b[0] == 0 and b[1] == collisions)
        bits = sorted(b[2] for b in balls)
        head = f"{completed}/{len(idx)}, {bits[len(bits) // 2]} / {bits[-1]}"
        for engine, dps in RANDOM_COMPARED:
            entries = [results[k][(engine, dps)] for k in idx]
            cert = [e[2] for e in entries]
            deps = [e[3] for e in entries if e[3]]
            gaps = sorted(e[3] - e[2] for e in entries if e[3])
            bad = sum(silent(e, results[k]["ball"]) for e, k in zip(entries, idx))
            wrong += bad
            label = engine if dps is None else f"{engine} {dps} digits"
            lines.append(f"| {cell(name)} | {len(idx)} | {head} | {label} | {quantiles(cert)} | {len(deps)} | "
                         f"{quantiles(deps)} | {(str(gaps[0]) + ' / ' + str(gaps[len(gaps) // 2])) if gaps else '-'} | "
                         f"{bad} |")
    return lines, wrong


def report(quick: bool = False, progress=None, executor=None) -> tuple[str, int]:
    """The Markdown of reports/STRESS.md and the number of silent wrong collisions.
    ``executor``: where the random orbits run (None: in this process)."""
    all_cases = cases(quick)
    spec = RANDOM_QUICK if quick else RANDOM
    data = random_data(spec["count"], spec["seed"])
    total = len(all_cases) + len(data) + 1
    lines = ["# Stress tests of the numerical engines", "",
             "Written by `python -m certify stress`" + (" --quick" if quick else "") + " (certify/numerics/stress.py). "
             "Each datum (r, θ0, φ0 at contact b, as floats read exactly) is run on the certified ball engine "
             f"(exact products of the cofactor matrices evaluated in balls, precision doubled from "
             f"{engines.BALL_START} bits up to {engines.BALL_CAP_DPS} digits) and on the floating engines.  Each "
             "floating engine reports its *certified horizon*: the collisions its accumulated rigorous error bound "
             "proves (certify/numerics/rules.py, `carry_bound`).  Past it an orbit goes on (a shadowing orbit, as in "
             "the paper's figures) and may leave the ball word: a *departure*, not an error.  A departure at a "
             "certified collision is a **silent wrong collision** (a bug).", "",
             "## Near-singular data", "",
             "A cell: `= N` the ball word for N collisions, `break k at N` a named break after N collisions (1 "
             "undecided contact, 2 time step below precision, 3 corner, 4 non-finite), `certified C` the "
             "certified horizon, `departs at k` the first collision where the word leaves the ball word.", "",
             "| group | r | θ0 | φ0 | ball (certified) | float64 | mp 30 | mp 16 |",
             "|---|---|---|---|---|---|---|---|"]
    n = spec["collisions"]
    start = time.perf_counter()
    # the random orbits go to the executor first; the near-singular cases run here meanwhile
    futures = [executor.submit(compare, r, t, p, n, RANDOM_COMPARED) for r, t, p in data] if executor else None
    wrong = 0
    done = 0
    for c in all_cases:
        res = compare(c.r, c.theta0, c.phi0, c.collisions)
        ball = res["ball"]
        wrong += sum(silent(res[s], ball) for s in COMPARED)
        lines.append("| " + " | ".join(cell(x) for x in (c.group, f"{c.r:.17g}", f"{c.theta0:.17g}", f"{c.phi0:.17g}",
                                                          _head(ball), *(verdict(res[s], ball) for s in COMPARED)))
                     + " |")
        done += 1
        if progress is not None:
            progress(done, total, c.group)
    results = []
    for k, (r, t, p) in enumerate(data):
        results.append(futures[k].result() if futures else compare(r, t, p, n, RANDOM_COMPARED))
        done += 1
        if progress is not None:
            progress(done, total, "random")
    seconds = time.perf_counter() - start
    table, bad = random_section(results, data, n)
    wrong += bad
    rows, bad, (n_f, n_m, n_b) = long_orbits(quick)
    wrong += bad
    if progress is not None:
        progress(total, total, "long orbits")
    lines += ["", f"## {len(data)} random orbits, {n} collisions each", "",
              f"Seeded (`random.Random({spec['seed']})`): r uniform in [0.001, 0.999], θ0 in [0, π/2], φ0 in [0, π]; "
              f"each on the ball engine, float64 and mp 30 digits ({seconds:.0f} s wall for these and the "
              "near-singular "
              "data, on the executor of the command).  "
              "Per regime of r: how many ball orbits completed and the bits they needed; per engine, the "
              "distribution of the certified horizons, how many orbits departed from the ball word and where, how "
              "far past the certified horizon the departure came, and the silent wrong collisions.", "",
              *table, "",
              f"## Long orbits: float64 for {n_f} collisions from (θ0, φ0) = (π/6, π/5)", "",
              f"| r | float64 | against mp 30 digits (first {n_m}) | against ball (first {n_b}) |",
              "|---|---|---|---|", *rows, "",
              f"**Silent wrong collisions: {wrong}.**", ""]
    return "\n".join(lines), wrong
