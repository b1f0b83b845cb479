"""The ball engine with and without its leaps along repelling blocks (certify.numerics.leaps), and
identify's scan with and without its float64 sieve.

    python benchmarks/bench_leaps.py [--repeats 3] [--identify]

For each case (r, datum, collisions) the CPU seconds (``time.process_time``, median of the
repeats) of ``engines.ball_states`` to the last state, with leaps (``leap={}``, what identify and
the atlas use: the bound and the turning criterion of a focus), with the bound alone (the
leaps of the first version, ``_periods`` for every block), and without (no attempt), the ratios,
and whether the last states are one plane (their unit directions overlap).  The cases: orbits
winding out of abcb near r = 1 and returning to it (where the leaps pay), an orbit of the island
and one attracted by (ab)^2(cb)^2 (where every attempt fails: the cost of trying).

``--identify``: ``identify.classify`` of orbits near r = 1 that the atlas's rule 5 runs (10.24
million collisions), as the atlas has it (leaps, turning criterion, sieve) and with the leaps of
the bound alone and no sieve (the scan of the last version; its float64 run is this version's):
CPU seconds and whether the answers are the same as the atlas records them.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:  # run as a script from a source checkout
    sys.path.insert(0, str(ROOT))

CASES = (("93271/100000", (0.6872233929727672, 2.55981623625835), 150_000, "winds out of abcb (ρ − 1 = 5.6e-5)"),
         ("19211/20000", (0.5235987755982988, 0.6283185307179586), 500_000, "winds out of abcb (ρ − 1 = 1.1e-5)"),
         ("50109/100000", (0.5235987755982988, 1.2566370614359172), 100_000, "in the island"),
         ("7187/50000", (0.5235987755982988, 0.6283185307179586), 100_000, "attracted by (ab)^2(cb)^2"),
         ("44/45", (0.5235987755982988, 0.6283185307179586), 3_700_000, "winds out of abcb, returns to it"))
MODES = ("turning", "bound", "none")
IDENTIFY = (("44/45", (0.5235987755982988, 0.6283185307179586)),
            ("12239/12500", (0.5235987755982988, 0.6283185307179586)),
            ("12239/12500", (0.9817477042468103, 2.443460952792061)))


def last_state(r, datum, collisions, leap):
    from certify.numerics import engines
    *_, last = engines.ball_states(r, *datum, collisions, every=False, leap=leap)
    return last


@contextmanager
def mode(name: str):
    """"turning" (as committed), "bound" (``_periods`` for every block: no focus's turning read) or
    "none" (no leap attempted)."""
    from certify.numerics import engines, leaps
    every, pair = engines.LEAP_EVERY, leaps._pair
    if name == "none":
        engines.LEAP_EVERY = 10 ** 15
    if name == "bound":
        leaps._pair = lambda E, a: None
    try:
        yield
    finally:
        engines.LEAP_EVERY, leaps._pair = every, pair


def timed(r, datum, collisions, name: str):
    with mode(name):
        start = time.process_time()
        holder: dict = {}
        out = last_state(r, datum, collisions, holder)
        return out, time.process_time() - start, holder.get("leaps", [])


def classified(r: str, datum, committed: bool):
    """identify's answer and its CPU seconds, as committed or with the last version's scan (the bound
    alone, no sieve)."""
    from fractions import Fraction

    from certify.run import identify
    sieve = identify.SIEVE
    identify.SIEVE = committed
    try:
        with mode("turning" if committed else "bound"):
            start = time.process_time()
            x = identify.classify(Fraction(r), *datum, 10_240_000, word_max=identify.MAX_ANALYSED)
            return x, time.process_time() - start
    finally:
        identify.SIEVE = sieve


def answer(x) -> tuple:
    """What the atlas records of an answer (its why names the leaps taken, which differ)."""
    return x.cls, x.certified_from, x.word, x.why if x.cls == "unresolved" else ""


def one_plane(n, m) -> bool:
    def unit(v):
        s = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
        return [z / s for z in v]
    return all(a.overlaps(b) for a, b in zip(unit(n), unit(m)))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--identify", action="store_true", help="identify's orbits near r = 1 instead")
    args = ap.parse_args(argv)
    if args.identify:
        return identify_table(args.repeats)
    import flint
    print("| r | orbit | collisions | leaps (s) | bound alone (s) | none (s) | ratios | leaps taken | same plane |")
    print("|---|---|---:|---:|---:|---:|---|---|---|")
    for text, datum, collisions, what in CASES:
        r = flint.fmpq(*map(int, text.split("/")))
        runs: dict = {name: [] for name in MODES}
        for _ in range(args.repeats):
            for name in MODES:
                runs[name].append(timed(r, datum, collisions, name))
        t = {name: statistics.median(s for _, s, _ in runs[name]) for name in MODES}
        outs = {name: runs[name][0][0] for name in MODES}
        taken = runs["turning"][0][2]
        same = all(outs[x][0] == outs["none"][0] and one_plane(outs[x][2], outs["none"][2]) for x in MODES)
        shown = f"{len(taken)}: " + ", ".join(f"{p}×{L} at {k}" for k, p, L, _ in taken[:3]) + \
            (", …" if len(taken) > 3 else "") if taken else "none"
        print(f"| {text} | {what} | {collisions} | {t['turning']:.3f} | {t['bound']:.3f} | {t['none']:.3f} | "
              f"{t['turning'] / t['none']:.3f}, {t['bound'] / t['none']:.3f} | {shown} | {'yes' if same else 'NO'} |",
              flush=True)
    return 0


def identify_table(repeats: int) -> int:
    print("| r | datum | class | from | committed (s) | bound alone, no sieve (s) | ratio | same answer |")
    print("|---|---|---|---:|---:|---:|---:|---|")
    for r, datum in IDENTIFY:
        runs: dict = {True: [], False: []}
        for _ in range(repeats):
            for committed in (True, False):
                runs[committed].append(classified(r, datum, committed))
        t = {c: statistics.median(s for _, s in runs[c]) for c in runs}
        x, y = runs[True][0][0], runs[False][0][0]
        print(f"| {r} | ({datum[0]:.4f}, {datum[1]:.4f}) | {x.cls} | {x.certified_from or '—'} | {t[True]:.2f} | "
              f"{t[False]:.2f} | {t[True] / t[False]:.3f} | {'yes' if answer(x) == answer(y) else 'NO'} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
