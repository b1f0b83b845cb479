"""Write a census's files again from its census.json, without analysing a word.

    python tools/census_render.py reports/census.json OUT

reads the records of a census.json (the full records of an older census, or the brief ones of
today's) and writes OUT/CENSUS.md, OUT/census.json, OUT/census-words.csv.gz and
OUT/census-windows.png through :func:`certify.run.census_report.write_outputs`, the function
`certify census` writes them with: the same bytes as a fresh `certify census --max-length L`
of the same engine (the census to 20 took an hour; this, seconds).  The summary is computed
again from the records and must equal the one the file holds (exit 1 otherwise: a record was
lost or changed); OUT may be the directory of the census read.
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from certify.errors import UsageError  # noqa: E402
from certify.run.census_report import write_outputs  # noqa: E402
from certify.run.files import ensure_writable  # noqa: E402


def render(census: Path, out: Path) -> tuple[dict, dict]:
    """(the document read, the document written) of the census in ``census``, written to ``out``."""
    old = json.loads(census.read_text(encoding="utf-8"))
    new = write_outputs(old["words"], old["census"]["max_length"], out)
    return old, new


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("census", type=Path, help="a census.json")
    ap.add_argument("out", type=Path, help="the directory to write the census's files to")
    args = ap.parse_args(argv)
    try:
        ensure_writable(args.out)
        old, new = render(args.census, args.out)
    except (OSError, ValueError, KeyError, TypeError, UsageError) as exc:
        print(f"census_render: cannot render {args.census}: {exc}", file=sys.stderr)
        return 2
    if new["census"] != old["census"]:
        print(f"census_render: the summary computed from the records of {args.census} differs from the one "
              "it holds", file=sys.stderr)
        return 1
    print(f"{new['census']['words']} words up to length {new['census']['max_length']}: wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
