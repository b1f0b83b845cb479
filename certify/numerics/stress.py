"""Stress tests of the numerical engines (``python -m certify stress``): near-singular
data, long orbits and random data, every engine against the certified ball engine.

The rule checked: an engine either gives the certified collision word (as far as the
ball engine proves it) or stops with a named break (:data:`rules.BREAKS`).  A word
that departs from the certified one while the engine goes on is a *silent wrong
collision*; :func:`report` counts them (the command exits 1 when there is one).
"""
from __future__ import annotations

import math
import random
import time
from dataclasses import dataclass

from . import engines, rules

R_CRIT3 = 7 - 4 * math.sqrt(3)                 # the three-particle threshold, ≈ 0.0718
THETA, PHI = math.pi / 6, math.pi / 5          # the first datum of the paper's grid
COMPARED = (("float64", None), ("mp", 30), ("mp", 16))


@dataclass
class Case:
    group: str
    r: float
    theta0: float
    phi0: float
    collisions: int


def cases(quick: bool = False) -> list[Case]:
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
    return out


def departure(word: str, certified: str) -> int:
    """The first collision (1-based) where ``word`` departs from ``certified``, 0 if none."""
    for k, (x, y) in enumerate(zip(word, certified)):
        if x != y:
            return k + 1
    return 0


def verdict(res, ball) -> tuple[str, bool]:
    """(cell text, silent wrong?) of one engine's run against the certified one."""
    k = departure(res.word, ball.word)
    if k:
        return f"**WRONG at {k}** (break {res.code} at {res.collisions})", True
    text = f"= {res.collisions}" if res.code == 0 else f"break {res.code} at {res.collisions}"
    if res.collisions > ball.collisions:
        text += f" ({res.collisions - ball.collisions} beyond the certified)"
    return text, False


def run_case(c: Case):
    ball = engines.run_orbit("ball", c.r, c.theta0, c.phi0, c.collisions, word=True)
    cells, silent = [], 0
    for engine, dps in COMPARED:
        res = engines.run_orbit(engine, c.r, c.theta0, c.phi0, c.collisions, dps=dps, word=True)
        text, wrong = verdict(res, ball)
        cells.append(text)
        silent += wrong
    head = f"break {ball.code} at {ball.collisions}" if ball.code else f"= {ball.collisions}"
    return ball, head, cells, silent


def long_orbits(quick: bool):
    """float64 for 10^6 collisions (10^4 quick), against mp 30 digits for the first
    10^5 (10^3) and the certified ball word for the first 10^4 (10^3)."""
    n_float, n_mp, n_ball = (10**4, 10**3, 10**3) if quick else (10**6, 10**5, 10**4)
    rows, silent = [], 0
    for r in (0.15, 0.5, 0.9):
        start = time.perf_counter()
        f = engines.run_orbit("float64", r, THETA, PHI, n_float, word=True)
        t_f = time.perf_counter() - start
        m = engines.run_orbit("mp", r, THETA, PHI, n_mp, dps=30, word=True)
        b = engines.run_orbit("ball", r, THETA, PHI, n_ball, word=True)
        k_m, k_b = departure(f.word, m.word), departure(f.word, b.word)
        silent += bool(k_b)
        rows.append(f"| {r} | {f.collisions} (break {f.code}), {t_f:.2f} s | "
                    f"{'departs at ' + str(k_m) if k_m else 'same'} ({m.collisions}) | "
                    f"{'**WRONG at ' + str(k_b) + '**' if k_b else 'same'} ({b.collisions}, {b.bits} bits) |")
    return rows, silent, (n_float, n_mp, n_ball)


def report(quick: bool = False, progress=None) -> tuple[str, int]:
    """The Markdown of reports/STRESS.md and the number of silent wrong collisions."""
    all_cases = cases(quick)
    lines = ["# Stress tests of the numerical engines", "",
             "Written by `python -m certify stress`" + (" --quick" if quick else "") + " (certify/numerics/stress.py). "
             "Each datum (r, θ0, φ0 at contact b, as floats read exactly) is run on the certified ball engine "
             f"(precision doubled from {engines.BALL_START} bits up to {engines.BALL_CAP_DPS} digits) and on "
             "float64, mp 30 digits and mp 16 digits.  A cell: `= N` the certified word for N collisions; "
             "`break k at N` a named break after N collisions (1 undecided contact, 2 time step below "
             "precision, 3 corner, 4 non-finite), with the certified word before it; **WRONG at k**: the word "
             "departs from the certified one at collision k while the engine went on (a silent wrong collision: a bug).",
             "", "| group | r | θ0 | φ0 | ball (certified) | float64 | mp 30 | mp 16 |", "|---|---|---|---|---|---|---|---|"]
    silent = 0
    for k, c in enumerate(all_cases, 1):
        ball, head, cells, wrong = run_case(c)
        silent += wrong
        lines.append(f"| {c.group} | {c.r:.17g} | {c.theta0:.17g} | {c.phi0:.17g} | {head} ({ball.bits} bits) | "
                     + " | ".join(cells) + " |")
        if progress is not None:
            progress(k, len(all_cases) + 1, c.group)
    rows, wrong, (n_f, n_m, n_b) = long_orbits(quick)
    silent += wrong
    if progress is not None:
        progress(len(all_cases) + 1, len(all_cases) + 1, "long orbits")
    lines += ["", f"## Long orbits: float64 for {n_f} collisions from (θ0, φ0) = (π/6, π/5)", "",
              f"| r | float64 | against mp 30 digits (first {n_m}) | against ball (first {n_b}) |",
              "|---|---|---|---|", *rows, "",
              f"**Silent wrong collisions: {silent}.**", ""]
    return "\n".join(lines), silent
