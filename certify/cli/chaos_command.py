"""The command ``chaos``: a horseshoe of the b-to-b map at a rational r, proved by covering
relations in exact arithmetic (:mod:`certify.numerics.horseshoe`).

    chaos --r R [--json]

Exit 0 when a horseshoe is proved, 1 when none was found (nothing is claimed), 2 for bad input.
"""
from __future__ import annotations

import json
import time

from .options import add_command, restitution


def cmd_chaos(args) -> int:
    """Search and prove a horseshoe at r; print it (text or JSON)."""
    from certify.numerics import horseshoe
    start = time.perf_counter()
    found = horseshoe.find(args.r)
    doc = horseshoe.as_json(found, time.perf_counter() - start)
    print(json.dumps(doc, indent=2, ensure_ascii=False) if args.json else "\n".join(horseshoe.text_lines(doc)))
    return 0 if doc["certified"] else 1


def register(commands) -> None:
    """The parser of ``chaos``."""
    p = add_command(commands, "chaos", cmd_chaos,
                    help="a horseshoe of the b-to-b map at r: chaos proved by covering relations",
                    description="Search (floats) a saddle periodic orbit of the b-to-b map and a homoclinic "
                    "point, build quadrilaterals along it, and prove exactly (rationals) that each lies in one "
                    "branch of the map and the covering relations between them: an invariant set with "
                    "positive topological entropy (a lower bound printed) and periodic orbits of infinitely "
                    "many periods.  Exit 1 when no horseshoe is found.  Numbers: 11/100 or 0.11 (exact).")
    p.add_argument("--r", type=restitution, required=True, metavar="R",
                   help="a rational restitution coefficient in ]0,1[")
    p.add_argument("--json", action="store_true", help="print JSON (certify/schemas/chaos.schema.json)")
