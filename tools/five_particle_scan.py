"""Five-particle words guided by the dynamics (issue 39): random starts of the five-particle
reduction at many r, the periodic tails they settle on, and each tail's windows certified by
``certify pattern``.

    python tools/five_particle_scan.py                                   # 60 r in ]0.2, 0.3[, 20 below, 16 starts
    python tools/five_particle_scan.py --certify --timeout 900 --json scan.json

What is observed and what is certified.  The runs are the float64 engine of
``certify simulate --particles 5`` (certify/numerics/five_reduction.py): only their first 40-60 collisions
are certified, so the tail each orbit settles on (its last letters repeating with a period of at
most ``--longest`` letters, four times) is *observed*.  With ``--certify`` each distinct tail of at
most ``--max-length`` letters is given to ``certify pattern WORD --json`` (one at a time, at most
``--timeout`` seconds each, over ``--window LO HI``): its stable and feasible windows, with exact
ends, are *certified*; a clean run is listed as "analysed" (whether or not it found a stable window),
a word that ran out of time as such, and the points the analysis left undecided are counted.
"""
from __future__ import annotations

import argparse
import collections
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from certify.numerics import five_reduction as five  # noqa: E402
from certify.patterns.five import half_of  # noqa: E402


def grid(lo: float, hi: float, count: int) -> list[float]:
    """``count`` r strictly inside ]lo, hi[, equally spaced (the ends excluded)."""
    return list(np.linspace(lo, hi, count + 2)[1:-1])


def scan(rs, orbits: int, collisions: int, seed: int, longest: int):
    """{r: Counter of the orbits' observed periodic tails (None: none)} and the seconds."""
    start = time.perf_counter()
    p0, q0 = five.random_data(orbits, seed)
    run = five.iterate(rs, p0, q0, collisions=collisions, words=True)
    tails = {float(r): collections.Counter(five.periodic_tail(str(w), longest, 4) for w in run.word[a])
             for a, r in enumerate(rs)}
    return tails, time.perf_counter() - start


def certify_word(word: str, lo: str, hi: str, timeout: float) -> dict:
    """``certify pattern WORD --json --r-range LO HI`` in a child process (with ``--half`` for a word
    X·m(X): the same stable set, faster): its stable and feasible windows (exact ends, with floats) and
    undecided count, or why it gave none."""
    start = time.perf_counter()
    half = ["--half"] if half_of(word) is not None else []
    try:
        done = subprocess.run([sys.executable, "-m", "certify", "pattern", word, "--json", "--r-range", lo, hi,
                               *half], capture_output=True, text=True, timeout=timeout, cwd=ROOT)
    except subprocess.TimeoutExpired:
        return {"word": word, "status": f"not finished in {timeout:.0f} s"}
    seconds = round(time.perf_counter() - start, 1)
    if done.returncode != 0:
        return {"word": word, "status": f"exit {done.returncode}: {done.stderr.strip()[-300:]}", "seconds": seconds}
    data = json.loads(done.stdout)
    return {"word": word, "status": "analysed", "seconds": seconds, "stable": data.get("stable", []),
            "feasible": data.get("feasible", []), "undecided": len(data.get("undecided", []))}


def windows_text(sets: list) -> str:
    """The windows of a pattern JSON's sets as decimals (the exact ends are in the JSON)."""
    out = []
    for s in sets:
        for piece in s.get("pieces", []):
            if piece.get("kind") == "interval":
                out.append(f"]{piece['lo']['digits']}, {piece['hi']['digits']}[ ({s['branch']}, {s['fixed_point']})")
            else:
                out.append(f"{piece}")
    return "; ".join(out) or "none"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--r-range", nargs=3, default=("0.2", "0.3", "60"), metavar=("LO", "HI", "COUNT"))
    ap.add_argument("--below", nargs=3, default=("0.1", "0.2", "20"), metavar=("LO", "HI", "COUNT"),
                    help="more r below (default 20 in ]0.1, 0.2[)")
    ap.add_argument("--orbits", type=int, default=16)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--collisions", type=int, default=20_000)
    ap.add_argument("--longest", type=int, default=400, help="the longest period looked for")
    ap.add_argument("--certify", action="store_true", help="run certify pattern on every tail")
    ap.add_argument("--max-length", type=int, default=40, help="certify tails of at most this many letters")
    ap.add_argument("--timeout", type=float, default=900.0)
    ap.add_argument("--window", nargs=2, default=("1/10", "3/10"), metavar=("LO", "HI"),
                    help="the range of r given to certify pattern (default ]1/10, 3/10[)")
    ap.add_argument("--json", type=Path, default=None, help="write everything found to this file")
    args = ap.parse_args(argv)
    rs = sorted(grid(float(args.below[0]), float(args.below[1]), int(args.below[2]))
                + grid(float(args.r_range[0]), float(args.r_range[1]), int(args.r_range[2])))
    tails, seconds = scan(rs, args.orbits, args.collisions, args.seed, args.longest)
    print(f"{len(rs)} r × {args.orbits} orbits × {args.collisions} collisions: {seconds:.1f} s (float64; the tails "
          "observed)")
    seen: dict = {}
    for r, count in tails.items():
        print(f"r = {r:.5f}: " + ", ".join(f"{w or 'no periodic tail'} ×{n}" for w, n in count.most_common()))
        for w in count:
            if w is not None:
                seen.setdefault(w, []).append(r)
    print(f"\n{len(seen)} distinct tails (observed):")
    for w, at in sorted(seen.items(), key=lambda x: (len(x[0]), x[0])):
        print(f"  {len(w):>3} {w}: at {len(at)} r in [{min(at):.5f}, {max(at):.5f}]"
              + ("" if "d" in w else "  (no d: four particles collapse, the fifth leaves)"))
    results = []
    if args.certify:
        print(f"\ncertify pattern over ]{args.window[0]}, {args.window[1]}[ (timeout {args.timeout:.0f} s each):")
        for w in sorted(seen, key=len):
            if len(w) > args.max_length or "d" not in w:
                continue
            res = certify_word(w, *args.window, args.timeout)
            results.append(res)
            if res["status"] == "analysed":
                print(f"  {w}: stable on {windows_text(res['stable'])}; feasible on {windows_text(res['feasible'])}; "
                      f"{res['undecided']} undecided point(s); {res['seconds']} s", flush=True)
            else:
                print(f"  {w}: {res['status']}", flush=True)
    if args.json is not None:
        args.json.write_text(json.dumps({"r": rs, "orbits": args.orbits, "collisions": args.collisions,
                                         "seed": args.seed, "seconds": round(seconds, 1),
                                         "tails": {f"{r:.6f}": {str(k): n for k, n in c.items()}
                                                   for r, c in tails.items()},
                                         "certified": results}, indent=1, ensure_ascii=False) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
