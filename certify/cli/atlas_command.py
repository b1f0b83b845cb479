"""``certify atlas``: the attractors of the reduction over ]0, 1[ (certify/run/atlas.py):
every orbit of a grid of r and initial data classified by identify, each certified word's
exact attracting windows by orbit, stitched into cells; ATLAS.md, atlas.json, atlas.png."""
from __future__ import annotations

import shlex
import sys
from pathlib import Path

from certify.errors import UsageError
from certify.run import progress
from certify.run.files import ensure_writable, keep_larger, load_findings

from .options import DEFAULT_OUT, add_command, count, kill_interrupts, positive_int, r_range


@kill_interrupts                  # `kill` stops it like Ctrl-C: workers too
def cmd_atlas(args) -> int:
    from certify.run import atlas, executors
    if args.sample is not None and not args.check:
        raise UsageError("--sample: only with --check")
    if args.check:
        return check(args)
    lo, hi = r_range(*args.r_range) if args.r_range else (atlas.LO, atlas.HI)
    rs = atlas.r_values(lo, hi, args.resolution)
    data = atlas.data_grid(args.data)
    out = ensure_writable(args.out)
    params = {"r_range": [str(atlas.Fraction(lo)), str(atlas.Fraction(hi))], "resolution": args.resolution,
              "data": args.data, "collisions": args.collisions, "word_max": args.word_max,
              "word_seconds": args.word_seconds, "seeds": args.seeds, "refine": args.refine,
              "command": command_line(args)}
    keep_larger(out / "atlas.json", "atlas", committed_size(out), size(params), args.force)
    state = out / atlas.STATE
    seeds = atlas.seeds() if args.seeds == "known" else {}
    with executors.executor(args.jobs, args.scheduler) as ex:
        rrec, wrec = atlas.run_atlas(rs, data, args.collisions, ex, state, args.resume, progress=progress.Bar("job"),
                                     word_seconds=args.word_seconds, word_max=args.word_max, seeds=seeds,
                                     refine=args.refine, r_range=(atlas.Fraction(lo), atlas.Fraction(hi)))
    doc = atlas.document(rrec, wrec, params)
    atlas.write_outputs(doc, out)
    if args.json:
        print(atlas.to_json(doc), end="")
    else:
        s = doc["summary"]
        c = s["classes"]
        print(f"{s['r_values']} r ({args.resolution} and {s['r_values'] - len(rs)} by refinement) × {len(data)} "
              f"initial data: {s['orbits']} orbits: island {c['island']}, "
              f"attracting periodic {c['attracting periodic']}, unresolved {c['unresolved']}; {s['words']} words "
              f"certified, {s['attractors_with_windows']} attractors with exact windows, "
              f"{s['attractors_without_windows']} without; {len(doc['cells'])} cells; {len(doc['families'])} families")
        print(f"wrote {out / 'ATLAS.md'}, atlas.json, {atlas.FIGURE}; state {state}")
    return 0


def check(args) -> int:
    """``certify atlas --check [--sample K]``: DIR/atlas.json derived again (atlas.check_committed), every
    K-th r row and analysed word; one line per problem and exit 1, or one line and exit 0.  Nothing is
    written."""
    import time

    from certify.run import atlas, executors
    doc = load_findings("atlas.json", args.out)
    if doc is None:
        raise UsageError(f"--check: no readable atlas.json in {args.out}")
    sample, word_max = args.sample or 1, doc["parameters"]["word_max"]
    start = time.perf_counter()
    with executors.executor(args.jobs, args.scheduler) as ex:
        problems = atlas.check_committed(doc, ex, sample, word_max, progress.Bar("job"))
    rows, words = atlas.checked(doc, sample, word_max)
    what = f"{len(rows)} r rows and {len(words)} analysed words" + (f" (every {sample}th)" if sample > 1 else "")
    for p in problems:
        print(p)
    print(f"{args.out / 'atlas.json'}: {len(problems)} problem(s) in {what}, derived again in "
          f"{time.perf_counter() - start:.0f} s" if problems else
          f"{args.out / 'atlas.json'} checks: {what} derived again, and its seeds, cells, families, summaries "
          f"and ends ({time.perf_counter() - start:.0f} s)")
    return 1 if problems else 0


def size(params: dict) -> dict:
    """The measures of an atlas's size, from its parameters (as atlas.json holds them): its
    r-range and grid, the orbits' length, the words' limits (keep_larger compares them with the
    atlas already written)."""
    from fractions import Fraction
    return {"r-range": tuple(Fraction(x) for x in params["r_range"]), "r values": int(params["resolution"]),
            "rounds of refinement": int(params.get("refine", 0)), "initial data per r": int(params["data"]),
            "collisions": int(params["collisions"]), "longest word": int(params["word_max"]),
            "seconds per word": int(params["word_seconds"])}


def committed_size(out: Path) -> dict | None:
    """The size of the atlas already in OUT/atlas.json (:func:`size` of its parameters), or None."""
    doc = load_findings("atlas.json", out)
    try:
        return size(doc["parameters"])
    except (KeyError, TypeError, ValueError, ZeroDivisionError):
        return None


def command_line(args) -> str:
    """The command as typed, without --jobs, --scheduler, --resume, --json (they do not change the atlas)."""
    argv, skip, out = sys.argv[1:], {"--jobs": 1, "--scheduler": 1, "--resume": 0, "--json": 0}, []
    if not argv or argv[0] != "atlas":
        argv = ["atlas"]
    i = 0
    while i < len(argv):
        if argv[i] in skip:
            i += 1 + skip[argv[i]]
            continue
        out.append(argv[i])
        i += 1
    return "python -m certify " + shlex.join(out)


def register(commands) -> None:
    from certify.run import atlas
    p = add_command(commands, "atlas", cmd_atlas,
                    help="map the attractors of the reduction over ]0, 1[: classes, certified windows, families",
                    description="Starting from the known attractors (the families' members, the census's and "
                    "identify --section5's attracting words) and over a grid of r refined where it matters and of "
                    "initial data on the b-section, every orbit classified by identify (island / attracting periodic, "
                    "certified / unresolved, with what it shows); each certified word's exact attracting windows over "
                    "]0, 1[ by orbit (words too long or too slow: only at the r seen); the windows stitched into cells "
                    "of ]0, 1[ with the attractors that coexist there (certified) and the shares of initial data "
                    "reaching each (observed); the families as rules, their next members predicted and certified. "
                    "Writes DIR/ATLAS.md, "
                    "DIR/atlas.json, DIR/atlas.png and the state DIR/atlas-state.jsonl (--resume).")
    p.add_argument("--r-range", nargs=2, default=None, metavar=("LO", "HI"),
                   help=f"r in ]LO, HI[ (rationals, 0 <= LO < HI <= 1; default {atlas.LO} 1)")
    p.add_argument("--resolution", type=positive_int, default=atlas.RESOLUTION, metavar="N",
                   help=f"number of r values (midpoints of N equal cells; default {atlas.RESOLUTION})")
    p.add_argument("--data", type=count, default=atlas.DATA, metavar="M",
                   help=f"initial data per r besides the tool's 8 (Halton points; default {atlas.DATA})")
    p.add_argument("--collisions", type=positive_int, default=atlas.COLLISIONS, metavar="N",
                   help=f"collisions per float64 run and rigorous scan (default {atlas.COLLISIONS})")
    p.add_argument("--word-max", type=positive_int, default=atlas.WORD_MAX, metavar="L",
                   help=f"longest word whose window over ]0, 1[ is computed (default {atlas.WORD_MAX})")
    p.add_argument("--word-seconds", type=positive_int, default=atlas.WORD_SECONDS, metavar="S",
                   help=f"time limit of one word's window, in seconds of CPU (default {atlas.WORD_SECONDS})")
    p.add_argument("--refine", type=count, default=atlas.REFINE, metavar="K",
                   help=f"rounds of refinement after the grid: an r in every unsampled cell, near each window end, "
                   f"around words without a window (default {atlas.REFINE})")
    p.add_argument("--seeds", choices=("known", "none"), default="known",
                   help="start from the known attractors (the families' members, the census's and identify "
                   "--section5's attracting words; default) or only from what the orbits meet")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, metavar="DIR", help="output directory (default: reports)")
    p.add_argument("--resume", action="store_true", help="reuse the records of DIR/atlas-state.jsonl")
    p.add_argument("--force", action="store_true",
                   help="replace an atlas of a larger range, grid or limits already in DIR (refused without it)")
    p.add_argument("--json", action="store_true", help="also print atlas.json on stdout")
    p.add_argument("--check", action="store_true",
                   help="derive DIR/atlas.json again (every orbit, horseshoe and word window, the cells, families "
                        "and summaries: about the time of the atlas itself) and print each difference; exit 1 on one. "
                        "Nothing is written")
    p.add_argument("--sample", type=positive_int, default=None, metavar="K",
                   help="with --check: every K-th r row and analysed word only (the rest in full)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run on the Dask cluster at ADDRESS (needs certify[distributed]) instead of local processes")
    p.add_argument("--jobs", type=positive_int, default=None, metavar="N",
                   help="worker processes (default: all cores)")
