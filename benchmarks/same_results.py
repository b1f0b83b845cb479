"""The same certified results before and after a change of the exact engine.

    python benchmarks/same_results.py write [--max-length 12] [--out FILE] [--orbit]
    python benchmarks/same_results.py check [--max-length 12] [--digests FILE] [--orbit]
    python benchmarks/same_results.py check --orbit --sample

``write`` records, for every census word up to ``--max-length`` collisions, the SHA-256
of ``certify pattern WORD --json`` (the whole JSON: certified sets, end points,
conditions, datum, diagnosis, verdict) in ``reports/pattern-json-digests.txt``
(``--out``); ``check`` recomputes them with the engine of this checkout and lists the
words whose JSON differs (exit 1), or says that all agree.  The JSON behind the committed
digests equals, word for word, that of the engine of commit cb9d573 (before the fast
exact core) but for the reworded diagnosis of five words whose first collision fails:
``check`` shows that the faster engine certifies the very same sets.  The census records are compared
the same way by ``tests/patterns/test_census.py`` (against the committed ``reports/census.json``).

``--orbit`` does the same for ``certify orbit WORD --json`` (the census words of the
four-particle system; ``reports/orbit-json-digests.txt``).  Its committed digests were written
by the engine of the long-words branch; the engine before it (398b50a) gives the same JSON
but for two texts that changed on purpose: the physics line (which now says what a branch
names) and the self-similar verdict quoted from ``pattern`` (now without its diagnosis).

``--sample`` (with ``--orbit``) takes instead a sample of longer words: every
:data:`SAMPLE_STEP`-th census word of 13 to 17 collisions and the 38-letter word of
``bench_targets.py`` (``reports/orbit-json-sample-digests.txt``, a few minutes).  Its
committed digests were written by the engine before the speedorbit branch (320b3b0).
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
ORBIT_DIGESTS = ROOT / "reports" / "orbit-json-digests.txt"
SAMPLE_DIGESTS = ROOT / "reports" / "orbit-json-sample-digests.txt"
SAMPLE_STEP = 60
LONGEST_CENSUS = 17


def sample_words() -> list[str]:
    """Every SAMPLE_STEP-th four-particle census word of 13 to 17 collisions, and the
    38-letter word of the speed targets."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from bench_targets import TARGETS

    from certify.patterns.periodic import read as read_word
    words = [w for w in census.words(LONGEST_CENSUS) if read_word(w)[1] == "four" and len(read_word(w)[0]) > 12]
    return words[::SAMPLE_STEP] + [w for kind, w in TARGETS if kind == "orbit"]


def digest(word: str, orbit: bool = False) -> str:
    """SHA-256 of ``certify pattern WORD --json`` (``orbit``: of ``certify orbit WORD --json``) over ]0, 1[."""
    from certify.patterns.reduction_orbits import analyse as analyse_orbit
    res = analyse_orbit(word, 0, 1) if orbit else analyse(word, 0, 1)
    return hashlib.sha256(res.json_text().encode("utf-8")).hexdigest()


def digests(max_length: int, progress=None, orbit: bool = False, sample: bool = False) -> dict[str, str]:
    from certify.patterns.periodic import read as read_word
    out = {}
    words = sample_words() if sample else \
        [w for w in census.words(max_length) if not orbit or read_word(w)[1] == "four"]
    for k, word in enumerate(words, 1):
        out[word] = digest(word, orbit)
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
    ap.add_argument("--digests", "--out", dest="path", type=Path, default=None)
    ap.add_argument("--orbit", action="store_true", help="certify orbit WORD --json instead of pattern")
    ap.add_argument("--sample", action="store_true",
                    help="with --orbit: a sample of census words of 13-17 collisions and the 38-letter word")
    args = ap.parse_args(argv)
    if args.sample and not args.orbit:
        ap.error("--sample goes with --orbit")
    args.path = args.path or (SAMPLE_DIGESTS if args.sample else ORBIT_DIGESTS if args.orbit else DIGESTS)
    command = "orbit" if args.orbit else "pattern"
    show = (lambda k, n, w: print(f"\r{k}/{n} {w:<24}", end="", file=sys.stderr)) if sys.stderr.isatty() else None
    start = time.perf_counter()
    now = digests(args.max_length, show, args.orbit, args.sample)
    if show:
        print(file=sys.stderr)
    if args.action == "write":
        what = (f"a sample of {len(now)} words (census words of 13-{LONGEST_CENSUS} collisions, every "
                f"{SAMPLE_STEP}th, and the 38-letter word of bench_targets.py)" if args.sample else
                f"the {len(now)} census words up to {args.max_length} collisions")
        text = (f"# SHA-256 of `certify {command} WORD --json` for {what} (benchmarks/same_results.py)\n"
                + "".join(f"{w} {d}\n" for w, d in now.items()))
        args.path.write_text(text, encoding="utf-8")
        print(f"wrote {len(now)} digests to {args.path} in {time.perf_counter() - start:.0f} s")
        return 0
    before = read(args.path)
    missing = [w for w in now if w not in before]
    differ = [w for w in now if w in before and before[w] != now[w]]
    which = "of the sample" if args.sample else f"up to {args.max_length} collisions"
    print(f"{len(now)} words {which} in {time.perf_counter() - start:.0f} s: "
          f"{len(now) - len(differ) - len(missing)} the same, {len(differ)} different, {len(missing)} without a digest")
    for w in differ + missing:
        print(f"  {w}: {'different' if w in differ else 'no digest'}")
    return 1 if differ or missing else 0


if __name__ == "__main__":
    sys.exit(main())
