"""The commands of the exact engine on words and particles: ``census`` (every periodic
pattern up to a length), ``pattern WORD`` (one word), ``particles`` (four particles,
exactly).
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

from certify.errors import UsageError

from .options import (
    DEFAULT_OUT,
    add_command,
    add_jobs,
    kill_interrupts,
    number,
    positive_int,
    r_range,
    r_value,
    restitution,
    say,
)

MAX_DIGITS = 1000             # particles --digits
# census --max-length: the census to 20 (5618 words) took about an hour of the two cores (7300 s of
# CPU; 83 min wall on a machine shared with other work, 2026-11-24), and the words multiply by
# about 1.7 per collision (9423 at 21, 45178 at 24, 375592 at 28) while each takes longer: 21 would be
# some three hours more (an estimate); beyond 20 a census does not finish in a working day (and at 60 listing the
# words alone exhausts memory).  Measured: benchmarks/bench_census.py, issues 25 and 26.
MAX_CENSUS_LENGTH = 20
CENSUS_COST = "the census to 20 (5618 words) took about an hour on two cores"
# With --scheduler (a Dask cluster) the census goes further: the words stream (census.iter_words), the
# records come back to this process.  32 (about 3 million words) bounds a typing slip, not the cluster.
MAX_CLUSTER_LENGTH = 32
CLUSTER_COST = ("beyond 20 on a Dask cluster (--scheduler): 22 about 8-10 hours of one core (about half an hour on "
                "16), 24 about 28-47 (2-3 hours on 16), an extrapolation (docs/census.md)")


def plural(n: int, word: str) -> str:
    """``1 word``, ``2 words``."""
    return f"{n} {word}{'' if n == 1 else 's'}"


@kill_interrupts                  # `kill` stops it like Ctrl-C: workers too
def cmd_census(args) -> int:
    """The census of periodic patterns (certify/run/census_report.py): records stream to the
    state file, --resume skips the words already there."""
    from certify.run import census_report as census
    from certify.run import executors, progress
    from certify.run.files import ensure_writable, ensure_writable_file, keep_larger
    if args.particles != 4:
        return census_of_five(args)
    if args.check:
        raise UsageError("--check: for --particles 5 (the four-particle census is checked by its tests and "
                         "tools/census_render.py)")
    if args.max_length > MAX_CENSUS_LENGTH and not args.scheduler:
        raise UsageError(f"--max-length {args.max_length}: at most {MAX_CENSUS_LENGTH} on this machine ({CENSUS_COST}; "
                         f"the words multiply by about 1.7 per collision, so a longer census does not finish in a "
                         f"working day); {CLUSTER_COST}")
    if args.max_length > MAX_CLUSTER_LENGTH:
        raise UsageError(f"--max-length {args.max_length}: at most {MAX_CLUSTER_LENGTH}, even on a cluster (about "
                         "3 million words at 32)")
    if args.max_length > 17:
        from certify.patterns.census import iter_words
        n = sum(1 for _ in iter_words(args.max_length))
        if args.max_length > MAX_CENSUS_LENGTH:
            say(f"census up to length {args.max_length}: {n} words on the cluster at {args.scheduler}; "
                f"{CLUSTER_COST}; progress on a terminal, --resume after an interruption")
        else:
            say(f"census up to length {args.max_length}: {n} words; {CENSUS_COST} and the census to 17 (1214 "
                "words) about ten minutes (progress on a terminal)")
    out = ensure_writable(args.out)
    longer = census.written_length(out)
    keep_larger(out / "census.json", "census", None if longer is None else {"longest period": longer},
                {"longest period": args.max_length}, args.force)
    state = args.state if args.state is not None else out / "census-state.jsonl"
    ensure_writable_file(state, "--state")
    with executors.executor(args.jobs, args.scheduler, one_thread=True) as ex:
        records = census.run_census(args.max_length, ex, state, args.resume, progress=progress.Bar("word"))
    doc = census.write_outputs(records, args.max_length, out)
    if args.json:
        print(census.to_json(doc), end="")
    else:
        s = doc["census"]
        print(f"{plural(s['words'], 'word')} up to length {s['max_length']}: {len(s['feasible'])} with feasible "
              f"self-similar data, {len(s['stable'])} with stable self-similar data, {len(s['undecided'])} with "
              f"undecided points, {plural(len(s['errors']), 'error')}; with abcab: {s['abcab']['words']}, "
              f"feasible {len(s['abcab']['feasible'])}; "
              f"with an attracting periodic orbit of the reduction: {len(s['reduction']['attracting'])}")
        figure = f", {census.FIGURE}" if (out / census.FIGURE).is_file() else " (no window to draw: no figure)"
        print(f"wrote {out / 'CENSUS.md'}, census.json, {census.TABLE}{figure}; state {state}")
    return 0


def cmd_pattern(args) -> int:
    """The exact analysis of one periodic word: Markdown on stdout, or JSON with --json
    (schema certify/patterns/pattern.schema.json).  A bad word is a UsageError (exit 2),
    raised before any work; nothing is written to a file."""
    from certify.patterns import analyse, check_range, family_windows, read
    from certify.patterns.family import family_n
    lo, hi = check_range(*r_range(*args.r_range)) if args.r_range else (0, 1)
    if "d" in args.word:                  # five particles (issue 39): the κ route, certify.patterns.five
        from certify.patterns.five import analyse_five, half_of, read_five
        normal, _why = read_five(args.word)                      # validate first: one line, exit 2
        if not args.half and half_of(normal) is not None:
            print(f"certify: {normal} is X·m(X): --half gives the same stable set, faster", file=sys.stderr)
        result = analyse_five(args.word, lo, hi, half=args.half)
        print(result.json_text() if args.json else result.markdown())
        return 0
    if args.half:
        raise UsageError("--half is for five-particle words X·m(X) (over a, b, c, d)")
    normal, system, _why = read(args.word)                       # validate first: one line, exit 2
    n = family_n(normal) if system == "four" else None
    if n is not None and n > family_windows.EXACT_N0 and not args.r_range:
        rec = family_windows.theorem_record(n)   # (ab)^n(cb)^n beyond n = 30: the proof's window
        print(json.dumps(rec, ensure_ascii=False, indent=2) if args.json else family_windows.theorem_markdown(rec))
        return 0 if rec["proof_holds"] else 1
    bar = None
    if sys.stderr.isatty():               # a progress bar on a terminal: certify.run (numpy, tqdm) loaded only then
        from certify.run.progress import Bar
        bar = Bar("step")
    result = analyse(args.word, lo, hi, progress=bar)
    print(result.json_text() if args.json else result.markdown())
    return 0


def cmd_family(args) -> int:
    """The windows of (ab)^n(cb)^n for n = 2..N (certify.patterns.family_windows): DIR/family.json,
    written atomically, and one line per n; exit 1 when a check fails (the first n is named)."""
    from certify.patterns.family_windows import windows
    from certify.run import files, progress
    if args.n_max < 2:
        raise UsageError(f"--n-max: the family starts at n = 2, not {args.n_max}")
    out = files.ensure_writable(args.out)
    files.keep_larger(out / "family.json", "family", committed_family(out), {"largest n": args.n_max}, args.force)
    from certify.run.executors import executor
    with executor(args.jobs) as pool:
        doc, seconds = windows(args.n_max, progress=progress.Bar("n"), pool=None if args.jobs == 1 else pool)
    files.write_atomic(out / "family.json", json.dumps(doc, ensure_ascii=False, indent=2, sort_keys=True) + "\n")
    for rec, sec in zip(doc["windows"], seconds):
        where = f"]{rec['lo']['digits']}, {rec['hi']['digits']}[" if rec.get("one_interval") \
            else "; ".join(rec["stable"])
        print(f"(ab)^{rec['n']}(cb)^{rec['n']}: W = {where} ({sec:.1f} s, {rec['undecided']} undecided)")
    failure = doc["first_failure"]
    print("every window one interval above 7-4√3, hi_n a zero of q_2(0), hi_{n+1} < lo_n" if doc["all_hold"]
          else f"fails at n = {failure['n']}: {failure['reason']}")
    print(f"wrote {out / 'family.json'}")
    return 0 if doc["all_hold"] else 1


def committed_family(out: Path) -> dict | None:
    """The size of the family already in OUT/family.json (its largest n), or None."""
    from certify.run.files import load_findings
    doc = load_findings("family.json", out)
    try:
        return {"largest n": int(doc["n_max"])} if doc is not None else None
    except (KeyError, TypeError, ValueError):
        return None


def cmd_orbit(args) -> int:
    """The periodic orbits of the reduction with one word: Markdown on stdout, or JSON
    with --json (schema certify/patterns/orbit.schema.json).  A bad word is a UsageError
    (exit 2), raised before any work."""
    from certify.patterns import check_range, read
    from certify.patterns.reduction_orbits import analyse as analyse_orbit
    from certify.run import progress
    lo, hi = check_range(*r_range(*args.r_range)) if args.r_range else (0, 1)
    if "d" in args.word:
        return _five_orbit(args, lo, hi)
    normal, system, _why = read(args.word)                       # validate first: one line, exit 2
    if args.trap is not None:
        if args.r_range:
            raise UsageError("--trap R certifies one r: not with --r-range (use one or the other)")
        return _trap(normal, system, args.trap, args.json)
    result = analyse_orbit(args.word, lo, hi, self_similar=True if args.self_similar else None,
                           progress=progress.Bar("step"))
    print(result.json_text() if args.json else result.markdown())
    return 0


def _five_orbit(args, lo, hi) -> int:
    """``orbit WORD`` for a five-particle word: the periodic orbits of the five-particle reduction
    (certify/patterns/five_orbits.py), Markdown or --json; --trap and --self-similar are four-particle
    options (UsageError)."""
    from certify.patterns.five import read_five
    from certify.patterns.five_orbits import analyse
    from certify.run import progress
    read_five(args.word)                                         # validate first: one line, exit 2
    if args.trap is not None or args.self_similar:
        raise UsageError("orbit: --trap and --self-similar are for four-particle words (a, b, c); a five-particle "
                         "word's self-similar data are `certify pattern WORD`'s")
    result = analyse(args.word, lo, hi, progress=progress.Bar("step"))
    print(result.json_text() if args.json else result.markdown())
    return 0


def _trap(normal: str, system: str, r_text: str, as_json: bool = False) -> int:
    """``orbit WORD --trap R``: the certified trapping ellipse of the attracting orbit at the
    rational R (certify/numerics/trapping.py), exit 0; or one line saying why none was
    found, exit 1; with ``as_json`` the same as JSON (certify/schemas/trap.schema.json).
    A bad R or a word without a, b and c: UsageError (exit 2)."""
    from certify.numerics.trapping import attempt
    r = r_value(r_text, "--trap R")
    if system != "four":
        raise UsageError(f"orbit --trap: {normal!r} is a word of the {system} system; the reduction of Section 4 "
                         "is the four-particle one: a word with a, b and c")
    found = attempt(normal, r)
    if as_json:
        print(json.dumps(trap_json(normal, r, found), ensure_ascii=False, indent=2, sort_keys=True))
    elif isinstance(found, str):
        print(f"{normal} at r = {r}: no certified trapping neighbourhood: {found}")
    else:
        print("\n".join(found.lines()))
    return 1 if isinstance(found, str) else 0


def _number(q) -> dict:
    """An exact rational for JSON: the fraction as text, and a float to read."""
    from fractions import Fraction
    return {"exact": str(q), "approx": float(Fraction(int(q.p), int(q.q)))}


def trap_json(word: str, r, found) -> dict:
    """``orbit --trap --json`` (schema certify/schemas/trap.schema.json): the trapping ellipse
    U = {c + T u : |u| ≤ ρ} in exact rationals, or why none was found."""
    doc = {"schema": "certify-trap", "version": 1, "word": word, "r": str(r), "trapped": not isinstance(found, str)}
    if isinstance(found, str):
        return {**doc, "why": found}
    return {**doc, "contact": word[-1], "pair": found.pair, "lines": found.lines(),
            "centre": [str(z) for z in found.centre], "frame": [[str(z) for z in col] for col in found.frame],
            **{name: _number(getattr(found, name))
               for name in ("radius", "contraction", "image", "distance", "inner", "outer")}}


def cmd_particles(args) -> int:
    """Simulate the four particles exactly; one line per collision, then why it stopped."""
    if args.digits > MAX_DIGITS:
        raise UsageError(f"--digits is at most {MAX_DIGITS} (--exact prints the full fractions)")
    from certify.dynamics import particles
    from certify.run import progress
    history = particles.evolve(args.x, args.v, args.r, args.collisions, progress=progress.Bar("collision"))
    for line in particles.report_lines(history, digits=args.digits, full=args.exact):
        print(line)
    return 0


def add_word_options(p, word_help: str, schema: str) -> None:
    """WORD, --json and --r-range: the options of the exact analyses of one word."""
    p.add_argument("word", metavar="WORD", help=word_help)
    p.add_argument("--json", action="store_true", help=f"print JSON (certify/patterns/{schema})")
    p.add_argument("--r-range", nargs=2, default=None, metavar=("LO", "HI"),
                   help="restrict to ]LO, HI[ (rationals, 0 <= LO < HI <= 1)")


MAX_FIVE_LENGTH = 11         # census --particles 5: the classes multiply by about 3 per collision (docs/census.md)
FIVE_COST = ("the classes multiply by about 3 per collision, 4262 to 10, 11942 to 11 (4-6 h of one core); "
             "docs/census.md gives the times")


def census_of_five(args) -> int:
    """``census --particles 5``: the five-particle census (certify.run.census5): DIR/CENSUS5.md and
    census5.json, written atomically, the records streamed to the state file (--resume skips the words
    already there); with --check, the committed DIR/census5.json analysed again up to --max-length and
    compared (exit 1 on a difference, each named)."""
    from certify.run import census5, executors, progress
    from certify.run.files import ensure_writable, ensure_writable_file, keep_larger
    if args.particles != 5:
        raise UsageError(f"--particles {args.particles}: the census takes 4 (the paper's) or 5 particles")
    if args.max_length > MAX_FIVE_LENGTH:
        raise UsageError(f"--max-length {args.max_length}: at most {MAX_FIVE_LENGTH} for five particles on this "
                         f"machine ({FIVE_COST})")
    if args.scheduler:
        raise UsageError("--particles 5: no --scheduler (the five-particle census runs on local processes)")
    if args.check:
        with executors.executor(args.jobs, one_thread=True) as ex:
            problems = census5.check(args.out, ex, args.max_length, progress=progress.Bar("word"))
        for line in problems:
            print(line)
        print(f"{args.out / census5.JSON}: " + ("the records to length "
              f"{args.max_length} and the summary stand" if not problems else f"{len(problems)} difference(s)"))
        return 1 if problems else 0
    out = ensure_writable(args.out)
    longer = census5.written_length(out)
    keep_larger(out / census5.JSON, "five-particle census", None if longer is None else {"longest period": longer},
                {"longest period": args.max_length}, args.force)
    state = args.state if args.state is not None else out / "census5-state.jsonl"
    ensure_writable_file(state, "--state")
    with executors.executor(args.jobs, one_thread=True) as ex:
        records = census5.run(args.max_length, ex, state, args.resume, progress=progress.Bar("word"), notice=say)
    doc = census5.write_outputs(records, args.max_length, out)
    if args.json:
        print(census5.to_json(doc), end="")
        return 0
    print(five_summary(doc["census"]))
    print(f"wrote {out / census5.MARKDOWN}, {census5.JSON}; state {state}")
    return 0


def five_summary(s: dict) -> str:
    """The five-particle census in a few lines: words per length, the largest r of stable and of feasible
    self-similar collapse and of an undecided point (exact), the stable words, the words with a factor
    not analysed."""
    lines = [f"five particles, {plural(s['words'], 'word')} up to length {s['max_length']} (classes: rotations, "
             "mirror a<->d, b<->c)"]
    lines += [f"  length {n}: {e['words']} words, {e['feasible']} feasible, {e['stable']} stable"
              for n, e in s["lengths"].items()]
    for stage in ("stable", "feasible", "undecided"):
        best = s[f"largest_{stage}"]
        lines.append(f"largest r of {stage if stage == 'undecided' else stage + ' self-similar collapse'}: " + (
            "none" if best is None else f"≈{best['r']['digits']} (the root of {best['r']['minimal_polynomial']} in "
            f"]{best['r']['interval'][0]}, {best['r']['interval'][1]}[), {best['word']}"))
    lines += [f"stable: {w['word']} on {'; '.join(w['windows'])}" for w in s["stable_words"]]
    for key, kind in (("attracting_real", "real"), ("attracting_complex", "complex")):
        best = s[f"largest_orbit_{key}"]
        lines.append(f"largest r of an attracting periodic orbit of the reduction, {kind} in-plane pair: " + (
            "none" if best is None else f"≈{best['r']['digits']}, {best['word']}"))
    lines += [f"attracting orbit: {a['word']}: " + "; ".join([f"real pair {t}" for t in a["real"]]
                                                             + [f"complex pair {t}" for t in a["complex"]])
              for a in s["attracting_orbits"]]
    lines.append(f"words with undecided points: {s['undecided_words']} (certify pattern WORD lists them)")
    if s["not_analysed"]:
        scope = ("each a repeated factor, never stable (proved): the largest stable r holds for every word, the "
                 "largest feasible r for the factors analysed" if s["stable_complete"] else
                 "the largest r above hold for the factors analysed only")
        lines.append(f"words with a factor of cp(Λ²M) not analysed ({scope}): "
                     f"{', '.join(n['word'] for n in s['not_analysed'])}")
    return "\n".join(lines)


def register(commands) -> None:
    """The parsers of ``census``, ``pattern``, ``family``, ``orbit`` and ``particles``."""
    p = add_command(commands, "census", cmd_census, help="analyse every periodic pattern of blocks up to a length",
                    description="Every periodic collision word made of the blocks ab, cb, acb, cab (Corollary 4.5) "
                    "of at most L collisions, one per class (rotations, mirror a<->c), analysed two ways: stable "
                    "self-similar data (`pattern`) and attracting periodic orbits of the reduction (`orbit`).  "
                    f"Writes DIR/CENSUS.md, census.json, census-words.csv.gz, census-windows.png; {CENSUS_COST}.")
    p.add_argument("--max-length", type=positive_int, required=True, metavar="L",
                   help=f"longest period, in collisions (at most {MAX_CENSUS_LENGTH}; with --scheduler at most "
                        f"{MAX_CLUSTER_LENGTH})")
    p.add_argument("--json", action="store_true", help="also print the census as JSON on stdout")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, metavar="DIR", help="output directory (default: reports)")
    p.add_argument("--state", type=Path, default=None, metavar="FILE",
                   help="JSON lines, one per word analysed (default: DIR/census-state.jsonl)")
    p.add_argument("--resume", action="store_true", help="do not analyse again the words already in the state file")
    p.add_argument("--force", action="store_true",
                   help="replace a census of longer periods already in DIR (refused without it)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run on the Dask cluster at ADDRESS (needs certify[distributed]) instead of local processes")
    p.add_argument("--particles", type=positive_int, default=4, metavar="N",
                   help=f"4 (the paper's, default) or 5: every five-particle word class up to L ≤ {MAX_FIVE_LENGTH} "
                        "by the κ route of `pattern` and the periodic orbits of the reduction of `orbit`: "
                        "DIR/CENSUS5.md and census5.json (state: DIR/census5-state.jsonl)")
    p.add_argument("--check", action="store_true",
                   help="with --particles 5: analyse the words of DIR/census5.json up to L again and compare "
                        "(exit 1 on a difference); nothing is written")
    add_jobs(p)

    p = add_command(commands, "pattern", cmd_pattern, help="analyse one periodic collision word exactly",
                    description="Where in r the self-similar data of a periodic word exist, are "
                    "feasible and are stable, with algebraic end points.  WORD: ababcb, (ab)^3(cb)^3, "
                    "[ac]b (a and c at once, the symmetric system), ab (three particles); any rotation "
                    "or the mirror a<->c.")
    add_word_options(p, "a period over a, b, c; powers (…)^n; [ac]", "pattern.schema.json")
    p.add_argument("--half", action="store_true",
                   help="a five-particle word W = X·m(X) up to rotation (m: a<->d, b<->c): the half route, from "
                        "N = J·M_X with M_W = N² and a run over X (the same stable set, an order of magnitude faster; "
                        "docs/particles.md)")

    p = add_command(commands, "family", cmd_family, help="the stability windows of (ab)^n(cb)^n for n = 2..N",
                    description="For n = 2..N, the stable set of (ab)^n(cb)^n by `pattern`'s exact analysis, "
                    "checked to be one interval ]lo_n, hi_n[ above 7-4√3 with hi_n a zero of q_2(0) on its branch, "
                    "and hi_{n+1} < lo_n.  Writes DIR/family.json (docs/family.md).")
    p.add_argument("--n-max", type=positive_int, required=True, metavar="N", help="the largest n (at least 2)")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, metavar="DIR", help="output directory (default: reports)")
    p.add_argument("--force", action="store_true",
                   help="replace a family of a larger n already in DIR (refused without it)")
    add_jobs(p)

    p = add_command(commands, "orbit", cmd_orbit,
                    help="certify the periodic orbits of the reduction (Section 4) with one word",
                    description="For each real eigenvalue of M_w: where in r the periodic orbit of the "
                    "reduction with this word exists and is feasible, and whether it is attracting, a saddle "
                    "or repelling (in-plane pair real or complex), with algebraic end points.  Same words as "
                    "`pattern`; a five-particle word (a, b, c, d): where its plane's periodic orbit exists, is "
                    "feasible and attracts (real or complex in-plane pair).")
    add_word_options(p, "a period over a, b, c; powers (…)^n", "orbit.schema.json")
    p.add_argument("--trap", default=None, metavar="R",
                   help="instead: certify a trapping ellipse of the attracting orbit at the rational R in ]0,1[ "
                        "(exit 1 when none is found; with --json: certify/schemas/trap.schema.json; "
                        "not with --r-range)")
    p.add_argument("--self-similar", action="store_true",
                   help="the physics line's self-similar data (certify pattern's analysis) for a word longer than "
                        "40 letters too (by default not computed there: most of the time of a long word)")

    p = add_command(commands, "particles", cmd_particles, help="simulate four particles exactly",
                    description="Four particles on a line, equal masses, restitution "
                    "coefficient r: the collisions (a: 1-2, b: 2-3, c: 3-4, ac: a and c "
                    "at once) and their exact times.  Numbers: -2, 3/7, 0.25, 1e-2 (exact).")
    p.add_argument("--x", nargs=4, type=number, required=True, metavar=("X1", "X2", "X3", "X4"),
                   help="initial positions, x1 <= x2 <= x3 <= x4")
    p.add_argument("--v", nargs=4, type=number, required=True, metavar=("V1", "V2", "V3", "V4"),
                   help="initial velocities")
    p.add_argument("--r", type=restitution, required=True, metavar="R", help="restitution coefficient in ]0,1[")
    p.add_argument("--collisions", type=positive_int, default=100, metavar="N",
                   help="stop after N collisions, ac counting as one (default: 100)")
    p.add_argument("--digits", type=positive_int, default=20, metavar="D",
                   help="significant digits of the decimal times, correctly rounded (default: 20)")
    p.add_argument("--exact", action="store_true",
                   help="print every time as a full fraction, however long")
