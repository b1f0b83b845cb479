"""The same certified results before and after a change of the exact engine.

    python benchmarks/same_results.py write [--max-length 12] [--out FILE]
    python benchmarks/same_results.py check [--max-length 12] [--digests FILE]

``write`` records, for every census word up to ``--max-length`` collisions, the SHA-256
of ``certify pattern WORD --json`` (the whole JSON: certified sets, end points,
conditions, datum, diagnosis, verdict) in ``reports/pattern-json-digests.txt``
(``--out``); ``check`` recomputes them with the engine of this checkout and lists the
words whose JSON differs (exit 1), or says that all agree.  The JSON behind the committed
digests equals, word for word, that of the engine of commit cb9d573 (before the fast
exact core) but for the reworded diagnosis of five words whose first collision fails:
``check`` shows that the faster engine certifies the very same sets.  The census records are compared
the same way by ``tests/patterns/test_census.py`` (against the committed ``reports/census.json``).
"""
from __future__ import annotations

import argparse
import hashlib
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:  # run as a script from a source checkout
    sys.path.insert(0, str(ROOT))

from certify.patterns import analyse, census  # noqa: E402

DIGESTS = ROOT / "reports" / "pattern-json-digests.txt"


def digest(word: str) -> str:
    """SHA-256 of ``certify pattern WORD --json`` over ]0, 1[."""
    return hashlib.sha256(analyse(word, 0, 1).json_text().encode("utf-8")).hexdigest()


def digests(max_length: int, progress=None) -> dict[str, str]:
    out = {}
    words = census.words(max_length)
    for k, word in enumerate(words, 1):
        out[word] = digest(word)
        if progress:
            progress(k, len(words), word)
    return out


def read(path: Path) -> dict[str, str]:
    rows = [line.split() for line in path.read_text(encoding="utf-8").splitlines()
            if line and not line.startswith("#")]
    return {w: d for w, d in rows}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("action", choices=("write", "check"))
    ap.add_argument("--max-length", type=int, default=12)
    ap.add_argument("--digests", "--out", dest="path", type=Path, default=DIGESTS)
    args = ap.parse_args(argv)
    show = (lambda k, n, w: print(f"\r{k}/{n} {w:<24}", end="", file=sys.stderr)) if sys.stderr.isatty() else None
    start = time.perf_counter()
    now = digests(args.max_length, show)
    if show:
        print(file=sys.stderr)
    if args.action == "write":
        text = (f"# SHA-256 of `certify pattern WORD --json` for the {len(now)} census words up to "
                f"{args.max_length} collisions (benchmarks/same_results.py)\n"
                + "".join(f"{w} {d}\n" for w, d in now.items()))
        args.path.write_text(text, encoding="utf-8")
        print(f"wrote {len(now)} digests to {args.path} in {time.perf_counter() - start:.0f} s")
        return 0
    before = read(args.path)
    missing = [w for w in now if w not in before]
    differ = [w for w in now if w in before and before[w] != now[w]]
    print(f"{len(now)} words up to {args.max_length} collisions in {time.perf_counter() - start:.0f} s: "
          f"{len(now) - len(differ) - len(missing)} the same, {len(differ)} different, {len(missing)} without a digest")
    for w in differ + missing:
        print(f"  {w}: {'different' if w in differ else 'no digest'}")
    return 1 if differ or missing else 0


if __name__ == "__main__":
    sys.exit(main())
