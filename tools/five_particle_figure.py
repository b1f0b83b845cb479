"""The five-particle stable windows beside the four-particle ones (issue 39): reports/five-windows.png.

    python tools/five_particle_figure.py abadcbcabc [WORD ...] [--pattern-json FILE ...] [--out PNG]

Each five-particle WORD is analysed exactly here (``certify pattern``, certify/patterns/five.py);
``--pattern-json FILE`` reads instead what ``certify pattern WORD --json [--r-range LO HI] > FILE``
wrote (a long word's analysis, done once; its range is the one it was given); --out defaults to
reports/five-windows.png.  The four-particle
windows are those of the committed census (reports/census.json).  Only certified windows are
drawn (certify/run/five_figure.py).
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from certify.patterns.five import analyse_five  # noqa: E402
from certify.run import five_figure  # noqa: E402
from certify.run.files import REPORTS  # noqa: E402


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("words", nargs="*", metavar="WORD")
    ap.add_argument("--pattern-json", nargs="+", type=Path, default=[], metavar="FILE",
                    help="five-particle results written by certify pattern WORD --json")
    ap.add_argument("--out", type=Path, default=REPORTS / five_figure.NAME)
    args = ap.parse_args(argv)
    results = {}
    for w in args.words:
        start = time.perf_counter()
        res = analyse_five(w)
        results[res.normal] = res.to_json()
        print(f"{res.normal}: {res.verdict.splitlines()[0]} ({time.perf_counter() - start:.1f} s)", flush=True)
    for path in args.pattern_json:
        data = json.loads(path.read_text(encoding="utf-8"))
        if data.get("system") != "five":
            raise SystemExit(f"{path}: not a five-particle pattern result")
        results[data["normal_form"]] = data
        print(f"{data['normal_form']}: read from {path} (r in {data['r_range']})")
    doc = json.loads((REPORTS / "census.json").read_text(encoding="utf-8"))
    path = five_figure.figure(five_figure.four_particle_windows(doc), five_figure.five_particle_windows(results),
                              args.out, five_figure.marks(), doc["census"]["max_length"])
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
