"""The speed targets of issue 26: the engine against a plain SymPy script, in one sitting.

    python benchmarks/bench_targets.py [--repeat N] [--long] [--all] [--census]
    python -m certify bench --targets [--repeat N] [--long]      (= --all --census: also writes reports/BENCH.md)

The yardstick (:func:`algebra`) is a plain SymPy script doing the core of ``certify
pattern``'s algebra on a word: M_w = K_{c_L} ··· K_{c_1} (expanded after each letter),
cp = det(λI - M_w), disc_λ cp factored over Q and the real roots of its factors in ]0, 1[
(SymPy's isolation), the left eigenvector n* of M_w by Cramer's rule, and Res_λ(numerator
of n*_x, cp) with its real roots in ]0, 1[; nothing of the engine but the word reader.
For each target (``certify orbit`` on the 38-letter word, ``certify pattern
(ab)^6(cb)^6``; with ``--long`` also ``orbit`` on the 122-letter attractor of r = 0.173; with
``--all`` also the whole ``python -m certify all`` against the script on the 38-letter word):
the median seconds of the script and of the engine's analysis (in process, the engine's caches
(:func:`certify.run.runner.reset_caches`) and SymPy's emptied before each run), and their ratio.
Then the whole command ``python -m certify pattern (ab)^6(cb)^6`` (fresh processes: imports,
analysis, printing and exit; benchmarks/bench.py's time_command) against the script on the
38-letter word (issue 26's target: at most 0.6) and on (ab)^6(cb)^6, in the same run.  With
``--census`` also the census's words per second at a few lengths (:func:`census_speed`).  Run the copy
of this file in another checkout to time that checkout's engine (the script imports the
checkout it lives in).
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import sympy as sp

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:  # run as a script from a source checkout
    sys.path.insert(0, str(ROOT))

from certify.patterns.periodic import read  # noqa: E402
from certify.run import files  # noqa: E402

TARGETS = (("orbit", "abacbabcbabcbabcabacbcabcbabcbabcbacbc"), ("pattern", "(ab)^6(cb)^6"))
LONG = ("orbit", "(abacbc)^5a(bcabac)^4bc(ab)^2(cbcaba)^5c(bacbca)^4ba(cb)^2")     # r = 0.173's attractor
r, lam = sp.symbols("r lambda")
H = (1 + r) / 2
K = {"a": sp.Matrix([[-r, 0, 0], [H, 1, 0], [0, 0, 1]]),
     "b": sp.Matrix([[1, H, 0], [0, -r, 0], [0, H, 1]]),
     "c": sp.Matrix([[1, 0, 0], [0, 1, H], [0, 0, -r]])}


def real_roots_01(p) -> list:
    """The real roots of p in ]0, 1[, isolated by SymPy (intervals of its factors)."""
    out = []
    for f, _m in sp.factor_list(sp.Poly(p, r))[1]:
        out += [iv for iv, _k in f.intervals() if iv[1] > 0 and iv[0] < 1]
    return out


def algebra(word: str) -> int:
    normal = read(word)[0]
    M = sp.eye(3)
    for letter in normal:
        M = (K[letter] * M).applyfunc(sp.expand)
    cp = M.charpoly(lam).as_expr()
    disc = sp.discriminant(cp, lam)
    n = len(real_roots_01(disc))
    A = (M.T - lam * sp.eye(3)).applyfunc(sp.expand)
    nx = sp.expand(-A[0, 2] * A[1, 1] + A[0, 1] * A[1, 2])        # numerator of n*_x (rows 0, 1)
    res = sp.resultant(sp.Poly(nx, lam), sp.Poly(cp, lam))
    return n + len(real_roots_01(res.as_expr()))


def engine(kind: str, word: str) -> None:
    """The engine's analysis behind ``certify KIND WORD``, from cold caches."""
    from certify.patterns import analyse as analyse_pattern
    from certify.patterns.reduction_orbits import analyse as analyse_orbit
    from certify.run import runner
    runner.reset_caches()
    (analyse_orbit if kind == "orbit" else analyse_pattern)(word)


def median_seconds(f, repeat: int) -> float:
    """The median of ``repeat`` runs of f, each from SymPy's cache emptied (its memo would
    make every run after the first one several times faster)."""
    times = []
    for _ in range(repeat):
        sp.core.cache.clear_cache()
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


TARGET_RATIOS = {"orbit": 1.2, "pattern": 0.6, "all": 3.0}      # issue 26's ceilings (ratios to the script)
CENSUS_LENGTHS = (8, 10, 12)      # 6, 15 and 39 words: the census's speed at a few lengths (issue 35)


def census_speed(lengths=CENSUS_LENGTHS, repeat: int = 3) -> list[str]:
    """The census's speed (``certify census``'s job, :func:`certify.patterns.census.analyse_word`:
    the self-similar analysis and the reduction's orbits of a word): for each length, every
    word of exactly that length analysed in this process one after the other, the engine's
    caches emptied first; the median seconds of ``repeat`` runs and the words per second.
    Markdown rows | length | words | s | words/s |."""
    from certify.patterns import census
    from certify.run import runner

    def analyse(words) -> None:
        runner.reset_caches()
        for word in words:
            census.analyse_word(word)
    rows = []
    for length in lengths:
        words = census.words_of_length(length)
        seconds = median_seconds(lambda w=words: analyse(w), repeat)
        rows.append(f"| {length} | {len(words)} | {seconds:.2f} | {len(words) / seconds:.2f} |")
        print(f"census, the {len(words)} words of length {length}: {seconds:.2f} s, {len(words) / seconds:.2f} words/s "
              f"(median of {repeat})", flush=True)
    return rows


def main(argv=None) -> int:
    """Time the targets, print one line each; with ``--all`` (``certify bench --targets``) also
    write the section "targets (issue 26)" of reports/BENCH.md."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--long", action="store_true", help="also orbit on the 122-letter word (minutes)")
    ap.add_argument("--all", action="store_true", help="also the whole `python -m certify all` (fresh processes, "
                    "benchmarks/bench.py's time_command) against the script on the 38-letter word; writes BENCH.md")
    ap.add_argument("--census", action="store_true", help="also the census's words per second at lengths "
                    f"{', '.join(map(str, CENSUS_LENGTHS))} (a section of its own in BENCH.md with --all)")
    args = ap.parse_args(argv)
    from benchmarks.bench import BENCH, machine, time_command
    if args.census:
        census_rows = census_speed(CENSUS_LENGTHS, args.repeat)
        if args.all:
            files.write_section(BENCH, "census speed (issue 35)", "\n".join([
                f"Measured by `python -m certify bench --targets --repeat {args.repeat}` on {machine()}: every word "
                "of each length analysed as `certify census` does (self-similar data and the reduction's orbits), "
                "in one process, caches emptied before each length; medians (benchmarks/bench_targets.py, "
                "census_speed).  The whole census's cost by length: docs/census.md.", "",
                "| length | words | s | words/s |", "|---:|---:|---:|---:|", *census_rows]))
    scripts, rows = {}, []

    def row(what: str, eng: float, ref: float, yardstick: str, target: float | None, reading: str = "") -> None:
        met = "" if target is None else ("met" if eng / ref <= target else "**not met**") + f" (≤ {target}×{reading})"
        rows.append(f"| {what} | {eng:.2f} | {yardstick} | {ref:.2f} | {eng / ref:.2f}× | {met} |")
        print(f"{what}: {eng:.2f} s, ratio {eng / ref:.2f} to the script on {yardstick} ({ref:.2f} s; medians of "
              f"{args.repeat})", flush=True)
    for kind, word in TARGETS + ((LONG,) if args.long else ()):
        ref = scripts[word] = median_seconds(lambda w=word: algebra(w), args.repeat)
        eng = median_seconds(lambda k=kind, w=word: engine(k, w), args.repeat)
        if (kind, word) == TARGETS[1]:     # the yardstick is the script on the long word (below)
            row(f"`{kind}` {word}, analysis in process", eng, ref, word, TARGET_RATIOS[kind], ", a stricter reading")
        else:
            row(f"`{kind}` {word}, analysis in process", eng, ref, word,
                TARGET_RATIOS["orbit"] if (kind, word) == TARGETS[0] else None)
    long_word, pattern_word = TARGETS[0][1], TARGETS[1][1]
    eng = statistics.median(time_command(args.repeat, ["pattern", pattern_word]))
    command = f"`certify pattern {pattern_word}`, whole command"
    row(command, eng, scripts[long_word], long_word, TARGET_RATIOS["pattern"])
    row(command, eng, scripts[pattern_word], pattern_word, TARGET_RATIOS["pattern"], ", a stricter reading")
    if args.all:
        eng = statistics.median(time_command(args.repeat))
        row("`certify all`, whole command", eng, scripts[long_word], long_word, TARGET_RATIOS["all"])
        table = ["| target | s | the script on | script s | ratio | issue 26 |", "|---|---:|---|---:|---:|---|"]
        files.write_section(BENCH, "targets (issue 26)", "\n".join([
            f"Measured by `python -m certify bench --targets --repeat {args.repeat}` on {machine()}, in one run: "
            "each target against a plain SymPy script of `pattern`'s algebra (benchmarks/bench_targets.py), "
            "medians; engines from cold caches, whole commands in fresh processes.", "", *table, *rows]))
        print(f"wrote {BENCH} (section 'targets (issue 26)')")
    return 0


if __name__ == "__main__":
    sys.exit(main())
