"""The ball engine's precision and speed: bits lost per collision and µs per collision
at a fixed precision, and the certified horizon it reaches in 10 s.

    python benchmarks/bench_ball.py                      # the engine of this checkout
    PYTHONPATH=OTHER python benchmarks/bench_ball.py     # the engine of another checkout

Measures whatever ``certify`` imports first (so that an older checkout, e.g.
``git archive cb9d573``, can be measured by the same code); used by
bench_numerics.py for the current engine.

* bits lost after k collisions: prec + log2(max radius / max |midpoint|) of the
  normal's balls at the checkpoint k, for the paper's first orbit (θ0, φ0) =
  (π/6, π/5), precision fixed at ``prec`` (the engine's start and, up to the rounding
  of digits to bits, its cap);
* the horizon in 10 s: the largest N = 1000·2^m whose certified orbit (default
  engine: precision doubled from 64 bits) completes within ``seconds``.
"""
from __future__ import annotations

import math
import sys
import time
from pathlib import Path

try:
    import certify  # noqa: F401
except ImportError:  # run as a script from a source checkout
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import flint  # noqa: E402

from certify.numerics import engines  # noqa: E402

THETA, PHI = math.pi / 6, math.pi / 5
REGIMES = {"between the windows": 0.1, "stable window": 0.15, "chaotic": 0.5}


def log2(x) -> float:
    return float(flint.arb(x).log().mid()) / math.log(2)


def bits_lost(r, prec=2048, marks=(500, 1500)):
    """(µs per collision, {k: bits lost after k collisions, or None past the horizon},
    collisions done) at a fixed precision."""
    dps = prec // 3 + 1                              # a cap of about prec bits
    start = time.perf_counter()
    res = engines.ball_orbit(r, THETA, PHI, marks[-1], dps=dps, start_bits=prec, checkpoints=marks)
    seconds = time.perf_counter() - start
    lost = {}
    for k in marks:
        if k not in res.checkpoints:
            lost[k] = None
            continue
        n = res.checkpoints[k][1]
        rad, top = max(z.rad() for z in n), max(abs(z.mid()) for z in n)
        lost[k] = res.bits + log2(rad) - log2(top) if rad > 0 else 0.0
    return seconds / max(res.collisions, 1) * 1e6, lost, res.collisions


def horizon_in(r, seconds=10.0, first=1000):
    """(N, seconds, bits): the largest N = first·2^m certified within ``seconds``."""
    n, best = first, (0, 0.0, 0)
    while True:
        start = time.perf_counter()
        res = engines.ball_orbit(r, THETA, PHI, n)
        dt = time.perf_counter() - start
        if dt > seconds or res.collisions < n:
            return best
        best = (n, dt, res.bits)
        n *= 2


def table(prec=2048, marks=(500, 1500), seconds=10.0) -> list[str]:
    lines = [f"| regime | r | µs/coll. at {prec} bits | "
             + " | ".join(f"bits lost after {k} (per coll.)" for k in marks)
             + f" | certified in {seconds:g} s (bits) |", "|---|---|---|" + "---|" * len(marks) + "---|"]
    for name, r in REGIMES.items():
        us, lost, done = bits_lost(r, prec, marks)
        n, dt, bits = horizon_in(r, seconds)
        cells = [f"{lost[k]:.0f} ({lost[k] / k:.3f})" if lost[k] is not None else f"past the horizon ({done})"
                 for k in marks]
        lines.append(f"| {name} | {r} | {us:.0f} | " + " | ".join(cells) + f" | ≥ {n} in {dt:.1f} s ({bits}) |")
    return lines


if __name__ == "__main__":
    print("\n".join(table()))
