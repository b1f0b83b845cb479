"""The five-particle stable windows beside the four-particle ones (issue 39): reports/five-windows.png.

    python tools/five_particle_figure.py                     # the committed results, reports/five-patterns/
    python tools/five_particle_figure.py abadcbcabc [WORD ...] [--pattern-json FILE ...] [--out PNG]
    python tools/five_particle_figure.py --check             # analyse the committed words again

reports/five-patterns/WORD.json is what ``certify pattern WORD --json [--r-range LO HI]`` wrote, byte for
byte (the longer words' analyses take 1-6 min of CPU each: done once, committed; docs/particles.md).
With no word and no --pattern-json the figure is drawn from those files; ``--check`` runs ``certify
pattern`` again on each committed word over its committed r-range and compares the bytes (exit 1 on a
difference, nothing is drawn; a result of the half route, ``--half``, again with ``--half``).  Each
five-particle WORD given is analysed here; ``--pattern-json FILE`` reads a result file instead; --out
defaults to reports/five-windows.png.  The four-particle windows are
those of the committed census (reports/census.json).  Only certified windows are drawn
(certify/run/five_figure.py).
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from certify.patterns.five import HALF_MARK, analyse_five  # noqa: E402
from certify.run import five_figure  # noqa: E402
from certify.run.files import REPORTS  # noqa: E402

COMMITTED = REPORTS / "five-patterns"


def pattern_json(word: str, r_range: list[str], *flags: str) -> bytes:
    """What ``certify pattern WORD --json --r-range LO HI [FLAGS]`` prints now (this checkout's code)."""
    cmd = [sys.executable, "-m", "certify", "pattern", word, "--json", "--r-range", *r_range, *flags]
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, check=True).stdout


def flags_of(data: dict) -> tuple[str, ...]:
    """The options besides --r-range that wrote a result: ``--half`` for the half route's (its explanation
    says so: certify.patterns.five.HALF_ROUTE)."""
    return ("--half",) if HALF_MARK in data["explanation"] else ()


def differences(paths: list[Path], fresh=pattern_json) -> list[str]:
    """One line per committed result file whose word, analysed again over its own r-range (and route),
    prints other bytes (``fresh(word, r_range, *flags)`` gives the new output)."""
    out = []
    for path in paths:
        data = json.loads(path.read_text(encoding="utf-8"))
        flags = flags_of(data)
        if fresh(data["input"], data["r_range"], *flags) != path.read_bytes():
            out.append(f"{path.name}: certify pattern {data['input']} --r-range {' '.join(data['r_range'])}"
                       f"{''.join(' ' + f for f in flags)} prints something else now")
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("words", nargs="*", metavar="WORD")
    ap.add_argument("--pattern-json", nargs="+", type=Path, default=[], metavar="FILE",
                    help="five-particle results written by certify pattern WORD --json")
    ap.add_argument("--out", type=Path, default=REPORTS / five_figure.NAME)
    ap.add_argument("--check", action="store_true", help="analyse the committed words again and compare")
    args = ap.parse_args(argv)
    committed = sorted(COMMITTED.glob("*.json"))
    if args.check:
        bad = differences(committed)
        print("\n".join(bad) or f"{len(committed)} committed five-particle results reproduced")
        return 1 if bad else 0
    if not args.words and not args.pattern_json:
        args.pattern_json = committed
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
