"""Speed and growth of exact arithmetic in Section 4: the particle system and the
reduction map, and where certified balls take over.

    python benchmarks/bench_reduction.py [--repeat N] [--long]

Printed, each a median of N runs in one process:

* the exact particle simulator (fmpq) from a collapsing datum: seconds for 10^3
  (and, with --long, 10^4) collisions, and the bit size of p, q, t along the run;
* the exact projective map (integer normals): seconds for 10^3, 10^4 (and, with
  --long, 10^5) steps and the bit size of the normal;
* the projective and the trigonometric maps iterated in balls (no exact restart):
  the working precision needed to certify the first k collisions, against the
  bits of the exact normal.
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

from certify.dynamics import reduction as R  # noqa: E402
from certify.dynamics import simulate as sim  # noqa: E402
from certify.algebra.balls import precision  # noqa: E402
from certify.algebra import Q  # noqa: E402

R_PHYS = Q(1, 20)
P0, Q0 = (Q(0), Q(3), Q(5)), (Q(2), Q(-7), Q(-9))        # collapses at r = 1/20
R_MAP, PLANE = Q(37, 100), ("a", (3, 5, -4))


def bits(z) -> int:
    z = Q(z)
    return max(int(z.p).bit_length(), int(z.q).bit_length())


def median_time(f, repeat: int):
    times, out = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - start)
    return statistics.median(times), out


def physical(n: int, repeat: int) -> None:
    seconds, run = median_time(lambda: sim.follow(P0, Q0, R_PHYS, n), repeat)
    marks = [k for k in (10, 100, 1000, 10_000) if k < len(run.states)]
    growth = ", ".join(f"{k}: {max(bits(z) for z in run.states[k].p + run.states[k].q)}/{bits(run.states[k].t)}"
                       for k in marks)
    print(f"particles, exact, r = {R_PHYS}: {len(run.events)} collisions in {seconds:.3f} s "
          f"({1e6 * seconds / max(1, len(run.events)):.0f} µs each); bits of p,q / t at k = {growth}")


def projective(n: int, repeat: int) -> None:
    P = R.canonical(*PLANE)
    seconds, (word, end) = median_time(lambda: R.word_of(P, R_MAP, n), repeat)
    print(f"projective map, exact, r = {R_MAP}: {len(word)} steps in {seconds:.3f} s "
          f"({1e6 * seconds / len(word):.1f} µs each); normal: {end.bits} bits "
          f"({end.bits / len(word):.2f} bits per collision)")


def least_precision(k: int, word_at) -> int:
    """The least precision (steps of 16 bits) at which ``word_at(prec)`` certifies
    the first k collisions of the exact orbit."""
    exact_word = R.word(R.orbit(R.canonical(*PLANE), R_MAP, k))
    prec = 16
    while word_at(prec) != exact_word and prec <= 1 << 16:
        prec += 16
    return prec


def trig_word(k: int, prec: int) -> str:
    """The trigonometric map iterated in balls from the exact plane."""
    letters = []
    with precision(prec):
        T = R.angles(R.canonical(*PLANE))
        try:
            for _ in range(k):
                T = R.trig_step(T, R_MAP)
                letters.append(T.letter)
        except (sim.Undecided, R.Corner):
            pass
    return "".join(letters)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--long", action="store_true", help="also 10^4 physical collisions and 10^5 steps of the map")
    args = ap.parse_args(argv)
    for n in (1000, 10_000) if args.long else (1000,):
        physical(n, args.repeat)
    for n in (1000, 10_000, 100_000) if args.long else (1000, 10_000):
        projective(n, args.repeat)
    P = R.canonical(*PLANE)
    for k in (100, 200, 400, 1000):
        exact_bits = R.orbit(P, R_MAP, k)[-1].bits
        proj = least_precision(k, lambda prec: R.ball_word(P, R_MAP, k, prec))
        trig = least_precision(k, lambda prec: trig_word(k, prec)) if k <= 400 else None
        print(f"{k} collisions certified in balls: projective map at {proj} bits"
              + (f", trigonometric map at {trig} bits" if trig else "")
              + f"; the exact normal has {exact_bits} bits")
    return 0


if __name__ == "__main__":
    sys.exit(main())
