"""The state file of ``certify atlas`` rebuilt from a committed atlas.json, so that
``certify atlas --resume`` goes on from the committed atlas's records when its
atlas-state.jsonl (not committed) is gone.

    python tools/atlas_state.py reports/atlas.json > reports/atlas-state.jsonl
    python tools/atlas_state.py --retry-time-limit reports/atlas.json > reports/atlas-state.jsonl

An r record is the document's row (its orbits, the island) with the data and collisions of
its parameters; a word record is the document's word (as analysed: its windows exactly as
`certify orbit` gave them).  A horseshoe record (``chaos``) is written back only where the
row has one.  No timing: the seconds are 0.  An r record is marked ``late`` = LATE_RULE
(reused as it is by ``--resume``: ``atlas.current``) when none of its orbits is one that
``atlas.r_job`` would run again under that rule (``atlas.rerun_due``): its upgrade would give the
same record; a row made under an older rule is left unmarked, and upgraded."""
from __future__ import annotations

import json
import sys

from certify.run import atlas
from certify.run.census_report import dumps

ORBIT_KEYS = atlas.ORBIT_KEYS + atlas.ORBIT_LATE_KEYS


def records(doc: dict, retry_time_limit: bool = False):
    """The state's records of an atlas document (r records, then word records, then chaos).
    ``retry_time_limit``: the words over the time limit get no record, so that the resume analyses
    them again under the same limit (a faster engine may now finish them); ``--resume`` alone reuses
    a "time limit" record measured in CPU time as it is."""
    p = doc["parameters"]
    data = len(atlas.data_grid(p["data"]))
    for row in doc["r"]:
        orbits = [{k: o.get(k) for k in ORBIT_KEYS} for o in row["orbits"]]
        rec = {"kind": "r", "r": row["r"], "data": data, "collisions": p["collisions"], "island": row["island"],
               "orbits": orbits, "seconds": 0.0}
        due = [atlas.rerun_due(o, atlas._fq(row["r"]), p["collisions"]) for o in orbits]
        if not any(due):                                   # what r_job's upgrade would give: the same record
            rec["late"] = atlas.LATE_RULE
        yield rec
    for w in doc["words"]:
        if retry_time_limit and w["outcome"] == "time limit":
            continue
        yield {**{k: v for k, v in w.items() if k != "source"}, "seconds": 0.0}
    for row in doc["r"]:
        if row.get("horseshoe") is not None:
            yield {"kind": "chaos", "r": row["r"], "collisions": p["collisions"], "horseshoe": row["horseshoe"],
                   "orbits": [{"index": i, "visits_horseshoe": o.get("visits_horseshoe"), "curve": o.get("curve")}
                              for i, o in enumerate(row["orbits"]) if o["class"] == "unresolved"],
                   "search_seconds": 0.0, "seconds": 0.0}


def main(argv: list[str]) -> int:
    retry = "--retry-time-limit" in argv
    argv = [a for a in argv if a != "--retry-time-limit"]
    if len(argv) != 1:
        print("usage: python tools/atlas_state.py [--retry-time-limit] ATLAS_JSON > atlas-state.jsonl", file=sys.stderr)
        return 2
    with open(argv[0], encoding="utf-8") as f:
        doc = json.load(f)
    for rec in records(doc, retry):
        sys.stdout.write(dumps(rec) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
