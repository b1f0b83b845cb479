"""Redo only some words of a committed census: a state file of its other records.

    python tools/census_redo.py reports/census.json STATE [--undecided] [--word W ...]
    python -m certify census --max-length L --state STATE --resume --out DIR

writes STATE (JSON lines, :func:`certify.run.census_report.dumps`) with every record of the census
except those to redo: the words with undecided self-similar points (``--undecided``) and the words
named.  ``certify census --resume`` then analyses only the words missing from the state and writes
the census from all the records: the kept ones byte for byte, the redone ones as a fresh run makes
them (a record does not depend on the others, nor on the bound L).  The state has no seconds for the
kept records (the census keeps none).  The kept records are those of census.json, in brief
(:func:`certify.run.census_report.brief`): census.json, CENSUS.md and the table written from them are
the bytes written from the full records; to rewrite the files without redoing any word,
``tools/census_render.py``.
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from certify.run.census_report import dumps  # noqa: E402
from certify.run.saving import write_atomic  # noqa: E402


def kept_records(census: dict, undecided: bool, words: set[str]) -> tuple[list[dict], list[str]]:
    """(the records kept, the words to redo)."""
    kept, redo = [], []
    for rec in census["words"]:
        if rec["word"] in words or (undecided and rec.get("undecided")):
            redo.append(rec["word"])
        else:
            kept.append(rec)
    return kept, redo


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("census", type=Path)
    ap.add_argument("state", type=Path)
    ap.add_argument("--undecided", action="store_true", help="redo the words with undecided points")
    ap.add_argument("--word", action="append", default=[], help="a word (normal form) to redo")
    args = ap.parse_args(argv)
    try:
        census = json.loads(args.census.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        print(f"census_redo: cannot read {args.census}: {exc}", file=sys.stderr)
        return 2
    kept, redo = kept_records(census, args.undecided, set(args.word))
    write_atomic(args.state, "".join(dumps(rec) + "\n" for rec in kept))
    print(f"{len(kept)} records kept in {args.state}, {len(redo)} to redo")
    return 0


if __name__ == "__main__":
    sys.exit(main())
