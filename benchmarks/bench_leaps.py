"""The ball engine with and without its leaps along repelling blocks (certify.numerics.leaps).

    python benchmarks/bench_leaps.py [--repeats 3]

For each case (r, datum, collisions) the CPU seconds (``time.process_time``, median of the
repeats) of ``engines.ball_states`` to the last state, with leaps (``leap={}``, what identify and
the atlas use) and without (no attempt), their ratio, and whether the two last states are one
plane (their unit directions overlap).  The cases: two orbits winding out of abcb near r = 1
(where the leaps pay), an orbit of the island and one attracted by (ab)^2(cb)^2 (where every
attempt fails: the cost of trying).
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

CASES = (("93271/100000", (0.6872233929727672, 2.55981623625835), 150_000, "winds out of abcb (ρ − 1 = 5.6e-5)"),
         ("19211/20000", (0.5235987755982988, 0.6283185307179586), 500_000, "winds out of abcb (ρ − 1 = 1.1e-5)"),
         ("50109/100000", (0.5235987755982988, 1.2566370614359172), 100_000, "in the island"),
         ("7187/50000", (0.5235987755982988, 0.6283185307179586), 100_000, "attracted by (ab)^2(cb)^2"))


def last_state(r, datum, collisions, leap):
    from certify.numerics import engines
    *_, last = engines.ball_states(r, *datum, collisions, every=False, leap=leap)
    return last


def timed(r, datum, collisions, leaps: bool):
    from certify.numerics import engines
    every = engines.LEAP_EVERY
    if not leaps:
        engines.LEAP_EVERY = 10 ** 15
    try:
        start = time.process_time()
        holder: dict = {}
        out = last_state(r, datum, collisions, holder)
        return out, time.process_time() - start, holder.get("leaps", [])
    finally:
        engines.LEAP_EVERY = every


def one_plane(n, m) -> bool:
    def unit(v):
        s = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
        return [z / s for z in v]
    return all(a.overlaps(b) for a, b in zip(unit(n), unit(m)))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args(argv)
    import flint
    print("| r | orbit | collisions | with leaps (s) | without (s) | ratio | leaps | same plane |")
    print("|---|---|---:|---:|---:|---:|---|---|")
    for text, datum, collisions, what in CASES:
        r = flint.fmpq(*map(int, text.split("/")))
        runs = {True: [], False: []}
        for _ in range(args.repeats):
            for leaps in (True, False):
                out, seconds, taken = timed(r, datum, collisions, leaps)
                runs[leaps].append((seconds, out, taken))
        with_, without = (statistics.median(s for s, _, _ in runs[x]) for x in (True, False))
        (_, a, taken), (_, b, _) = runs[True][0], runs[False][0]
        same = a[0] == b[0] and one_plane(a[2], b[2])
        shown = ", ".join(f"{p} periods of {L} at {k}" for k, p, L, _ in taken) or "none"
        print(f"| {text} | {what} | {collisions} | {with_:.3f} | {without:.3f} | {with_ / without:.3f} | {shown} | "
              f"{'yes' if same else 'NO'} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
