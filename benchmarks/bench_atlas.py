"""The cost of the committed atlas from an empty state, estimated from a systematic sample of its jobs.

    python benchmarks/bench_atlas.py [--atlas reports/atlas.json] [--every-r K] [--every-word K]

``certify atlas`` runs three kinds of job: an r job (the orbits of every datum at r, classified
by identify, and the island), a horseshoe job at each r, and a word job (the word's window over
]0, 1[ by ``certify orbit``, stopped at ``word_seconds`` of CPU).  This script runs, in this
process and one at a time, every K-th r of the committed atlas (sorted: the refined regions are
sampled as densely as they are gridded) from scratch, its horseshoe job on the unresolved orbits
that r job left, and every K-th of its words (words too long for a window cost nothing), and
prints the CPU seconds (``time.process_time``: the machine is shared, so wall time is not the
measure) of each kind, the sample's total times K (the estimate of the whole atlas's CPU), and
the wall time that total needs on two cores, at best (half of it, or the longest job if that is
longer).  The whole run from an empty state is this estimate plus the rendering (about 30 s).
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:  # run as a script from a source checkout
    sys.path.insert(0, str(ROOT))


def _cpu(fn, *args):
    start = time.process_time()
    out = fn(*args)
    return out, time.process_time() - start


def sample(doc: dict, every_r: int, every_word: int, log=print) -> dict[str, list[tuple[str, float]]]:
    """(key, CPU seconds) of the sampled jobs, by kind: "r", "horseshoe", "word"."""
    from fractions import Fraction

    from certify.run import atlas
    p = doc["parameters"]
    data, collisions = atlas.data_grid(p["data"]), p["collisions"]
    rs = sorted((row["r"] for row in doc["r"]), key=Fraction)[every_r // 2::every_r]
    words = [w["word"] for w in doc["words"]][every_word // 2::every_word]
    out: dict[str, list[tuple[str, float]]] = {"r": [], "horseshoe": [], "word": []}
    for r in rs:
        rec, s = _cpu(atlas.r_job, r, data, collisions)
        out["r"].append((r, s))
        _, h = _cpu(atlas.chaos_job, r, atlas.unresolved_of(rec), collisions)
        out["horseshoe"].append((r, h))
        log(f"r = {r}: {s:.1f} s, horseshoe {h:.1f} s")
    for w in words:
        rec, s = _cpu(atlas.word_job, w, p["word_seconds"], p["word_max"])
        out["word"].append((w, s))
        log(f"{len(w)}-letter word: {rec['outcome']}, {s:.1f} s")
    return out


def table(out: dict, every: dict[str, int]) -> str:
    rows = ["| job | sampled | CPU s | mean | max | estimate for the atlas (× K) |", "|---|---:|---:|---:|---:|---:|"]
    total, longest = 0.0, 0.0
    for kind, v in out.items():
        secs = [s for _, s in v]
        est = sum(secs) * every[kind]
        total, longest = total + est, max([longest, *secs])
        rows.append(f"| {kind} | {len(v)} | {sum(secs):.1f} | {sum(secs) / max(len(v), 1):.2f} | "
                    f"{max(secs, default=0):.1f} | {est:.0f} |")
    rows.append(f"\nestimated CPU of the atlas: {total:.0f} s; on two cores at best "
                f"{max(total / 2, longest) / 60:.1f} min of wall time")
    return "\n".join(rows)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--atlas", type=Path, default=ROOT / "reports" / "atlas.json")
    ap.add_argument("--every-r", type=int, default=10, metavar="K")
    ap.add_argument("--every-word", type=int, default=6, metavar="K")
    args = ap.parse_args(argv)
    doc = json.loads(args.atlas.read_text(encoding="utf-8"))
    out = sample(doc, args.every_r, args.every_word, log=lambda s: print(s, file=sys.stderr, flush=True))
    print(table(out, {"r": args.every_r, "horseshoe": args.every_r, "word": args.every_word}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
