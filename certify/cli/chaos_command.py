"""The command ``chaos``: a horseshoe of the b-to-b map at a rational r, proved by covering
relations in exact arithmetic (:mod:`certify.numerics.horseshoe`).

    chaos (--r R | --r-range LO HI COUNT) [--json]

Exit 0 when a horseshoe is proved, 1 when none was found (nothing is claimed), 2 for bad input.
"""
from __future__ import annotations

import json
import time

from certify.errors import UsageError
from certify.run import progress

from .options import add_command, count, integer, r_grid, r_value, restitution

MAX_COUNT = 200              # --r-range COUNT: a few seconds each


def cmd_chaos(args) -> int:
    """Search and prove a horseshoe at r (text or JSON; exit 1 without a proof); with --r-range,
    at each r of the sweep, one line each (exit 0 when one is proved somewhere)."""
    from certify.numerics import horseshoe
    if args.r_range is not None:
        return sweep(args, horseshoe)
    if args.figure is not None:
        from pathlib import Path

        from certify.run.files import ensure_writable
        if Path(args.figure).is_dir():
            raise UsageError(f"--figure {args.figure!r} is a directory, not a file")
        ensure_writable(Path(args.figure).parent if str(Path(args.figure).parent) else Path("."))
    start = time.perf_counter()
    found = horseshoe.find(args.r)
    doc = horseshoe.as_json(found, time.perf_counter() - start)
    if args.visits and doc["certified"]:
        doc["visits"] = horseshoe.visits(args.r, found.proof.boxes, orbits=args.visits)
    if args.figure is not None and doc["certified"]:
        from certify.run import horseshoe_figure
        horseshoe_figure.horseshoe_figure(args.figure, found)
    print(json.dumps(doc, indent=2, ensure_ascii=False) if args.json else "\n".join(horseshoe.text_lines(doc)))
    return 0 if doc["certified"] else 1


def sweep(args, horseshoe) -> int:
    """``--r-range LO HI COUNT``: COUNT exact r, ends included; at which a horseshoe is proved."""
    lo, hi, count = args.r_range
    if integer(count, "--r-range COUNT") > MAX_COUNT:
        raise UsageError(f"--r-range COUNT must lie in 1..{MAX_COUNT}, not {count}")
    rs = r_grid(lo, hi, count)
    for r in rs:
        r_value(str(r), "--r-range r")              # every r of the sweep in ]0, 1[
    bar = progress.Bar("r")
    records = []
    for k, r in enumerate(rs):
        start = time.perf_counter()
        records.append(horseshoe.as_json(horseshoe.find(r), time.perf_counter() - start))
        bar(k + 1, len(rs), str(r))
    progress.clear()
    if args.json:
        print(json.dumps({"schema": "certify-chaos", "version": 1, "sweep": records}, indent=2, ensure_ascii=False))
    else:
        for rec in records:
            what = (f"horseshoe proved, entropy ≥ {rec['entropy_lower']} (saddle {rec['saddle']['word']})"
                    if rec["certified"] else "no horseshoe found (nothing claimed)")
            print(f"r = {rec['r']}: {what}  [{rec['seconds']:.1f} s]")
        print(f"{sum(rec['certified'] for rec in records)} of {len(records)} r: a horseshoe proved")
    return 0 if any(rec["certified"] for rec in records) else 1


def register(commands) -> None:
    """The parser of ``chaos``."""
    p = add_command(commands, "chaos", cmd_chaos,
                    help="a horseshoe of the b-to-b map at r: chaos proved by covering relations",
                    description="Search (floats) a saddle periodic orbit of the b-to-b map and a homoclinic "
                    "point, build quadrilaterals along it, and prove exactly (rationals) that each lies in one "
                    "branch of the map and the covering relations between them: an invariant set with "
                    "positive topological entropy (a lower bound printed) and periodic orbits of infinitely "
                    "many periods.  Exit 1 when no horseshoe is found.  Numbers: 11/100 or 0.11 (exact).")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--r", type=restitution, default=None, metavar="R",
                   help="a rational restitution coefficient in ]0,1[")
    g.add_argument("--r-range", nargs=3, default=None, metavar=("LO", "HI", "COUNT"),
                   help=f"COUNT rationals from LO to HI, ends included (COUNT at most {MAX_COUNT})")
    p.add_argument("--json", action="store_true", help="print JSON (certify/schemas/chaos.schema.json)")
    p.add_argument("--figure", default=None, metavar="PATH",
                   help="also draw the boxes on the b-section and each covering relation into PATH (PNG)")
    p.add_argument("--visits", type=count, default=0, metavar="N",
                   help="also simulate N random float64 orbits and say how many enter the boxes "
                   "(observed, not a proof; default 0: none)")
