"""The command line: ``python -m certify COMMAND`` (or the ``certify`` script).

    all [--check] [--out DIR] [--jobs N]
                                run every certificate, write DIR/REPORT.md,
                                DIR/report.json, DIR/timings.json, DIR/figures/
    run ID [ID ...] [--out DIR] [--jobs N]
                                run some certificates, print their verdicts
    list                        list the certificates: id, paper line, statement
    bench [--repeat N] [--jobs N] [--reduction [--long]] [--numerics [--quick]] [--patterns]
                                time the whole run (benchmarks/bench.py), or the
                                exact simulator and reduction map (bench_reduction.py),
                                the numerical engines (bench_numerics.py), or
                                pattern and census (bench_patterns.py, bench_census.py)
    census --max-length L [--json] [--out DIR] [--jobs N | --scheduler ADDRESS]
           [--state FILE] [--resume] [--force]
                                every periodic pattern of blocks up to length L,
                                its feasible and stable r-sets: DIR/CENSUS.md,
                                DIR/census.json, DIR/census-windows.png
    pattern WORD [--json] [--r-range LO HI]
                                the exact analysis of one periodic word (ababcb,
                                (ab)^3(cb)^3, [ac]b, ab): where in r self-similar data
                                exist, are feasible, are stable (certify.patterns.pattern)
    orbit WORD [--json] [--r-range LO HI]
                                the periodic orbits of the reduction with one word:
                                where they exist, are feasible, attracting, saddles,
                                repelling (certify.patterns.reduction_orbits)
    identify (--r R [R ...] | --r-range LO HI COUNT) [--orbits N] [--collisions N] [--json]
                                the periodic word each simulated orbit settles on,
                                certified by orbit (certify.run.identify)
    particles --x X1 X2 X3 X4 --v V1 V2 V3 V4 --r R [--collisions N]
              [--digits D] [--exact]
                                simulate the four particles exactly, print the
                                collisions and their times (certify.dynamics.particles)
    figures [--resolution preview|paper] [--only FIG ...] [--n4 NMAX] [--out DIR]
                                Figures 6-11 of the paper (our ids 5.1-5.8) into
                                DIR/figures; paper: also
                                DIR/numerics-paper.json; --n4: DIR/numerics-n4.json
    simulate (--r R [R ...] | --r-range LO HI COUNT)
             [--orbits N | --theta0 T [T ...] --phi0 P [P ...]] [--collisions N]
             [--keep N] [--engine float64|mp|ball] [--dps D] [--strict] [--words]
             [--out FILE.npz] [--jobs N] [--scheduler ADDRESS]
                                iterate the reduction map numerically (Section 5,
                                certify.numerics); the φ of the last b-collisions
    stress [--out FILE] [--quick] [--jobs N]
                                near-singular, long and 1000 random orbits on every
                                engine against the certified one: reports/STRESS.md

Exit codes: 0 when every selected certificate is PASS, ERRATUM or OBSERVED;
1 when one FAILs (or, with ``all --check``, when the committed REPORT.md is
stale); 2 for a usage error; 130 when interrupted.  Errors are reported in one
line on stderr, never as a traceback (set ``CERTIFY_DEBUG=1`` to see one).
"""
from __future__ import annotations

import argparse
import importlib.util
import json
import os
import re
import shutil
import sys
import traceback
from contextlib import nullcontext
from fractions import Fraction
from pathlib import Path

from certify.dynamics import particles
from certify.errors import UsageError
from certify.run import ERRATUM, FAIL, OBSERVED, figures, progress, report, runner
from certify.run.files import ensure_writable, read_text_or_none

DEFAULT_OUT = Path("reports")
MAX_DIGITS = 1000             # particles --digits
REPO_ROOT = Path(__file__).resolve().parent.parent


# --------------------------------------------------------------------------
# Running certificates

def prepare_output(out: Path) -> Path:
    """Check that ``out`` and ``out/figures`` can be written, before any work."""
    ensure_writable(out)
    ensure_writable(out / "figures")
    return out


def estimates(out: Path | None) -> dict[str, float]:
    """Seconds per certificate in the last run's timings (DIR/timings.json, else
    reports/timings.json), to start the heaviest work first; {} when there are none."""
    for path in ([out / "timings.json"] if out is not None else []) + [DEFAULT_OUT / "timings.json"]:
        text = read_text_or_none(path)
        if text:
            try:
                return {k: float(v["seconds"]) for k, v in json.loads(text)["certificates"].items()}
            except (ValueError, KeyError, TypeError, AttributeError):
                continue
    return {}


def execute(ids, out: Path | None, jobs: int):
    """Run the certificates ``ids`` (all when None) on ``jobs`` processes, figures
    going to ``out/figures``.  Returns the runner's ``(results, timings)``."""
    saving = figures.output_dir(out / "figures") if out is not None else nullcontext()
    with saving:
        return runner.run(ids, progress=progress.Bar("certificate"), jobs=jobs, estimates=estimates(out))


def failing(results) -> list[str]:
    """The ids of the certificates that FAIL."""
    return [cert.id for cert, outcome in results if outcome.status == FAIL]


def exit_code(results) -> int:
    """0 when nothing FAILs, 1 otherwise."""
    return 1 if failing(results) else 0


def say(message: str) -> None:
    """One line on stderr, prefixed with the program name."""
    print(f"certify: {message}", file=sys.stderr)


def warn_missing_figures(results, out: Path) -> None:
    """Warn about figures an outcome lists but no certificate wrote."""
    for cert, outcome in results:
        for name in outcome.figures:
            if not (out / "figures" / name).is_file():
                say(f"warning: {cert.id} lists figure {name!r}, which was not written")


def finish(results) -> int:
    """Print the summary line, the errata by distinct error of the paper and the
    observations that disagree with it, each with its one-line reason (stdout); the
    failing ids (stderr); return the exit code."""
    print(report.summary_line(results))
    if report.errata_line(results):
        print("errata (the paper is wrong, a correction is certified): " + report.errata_line(results))
        for key, kind, members in report.misprints(results):
            print(f"  {', '.join(cert.id for cert, _ in members)}: {kind}: {' '.join(key.split())}")
    against = report.disagreements(results)
    if against:
        print("disagree with the paper (numerical observations):")
        for cert, outcome in against:
            print(f"  {cert.id}: {' '.join(outcome.reason.split())}")
    if failing(results):
        say("FAIL: " + ", ".join(failing(results)))
    return exit_code(results)


def wrote(out: Path, results) -> None:
    """Say where the report went: ``wrote reports/REPORT.md, report.json, figures/ (N files)``."""
    n = len({name for _, outcome in results for name in outcome.figures})
    print(f"wrote {out / 'REPORT.md'}, report.json, figures/ ({n} file{'s' if n != 1 else ''})")


# --------------------------------------------------------------------------
# The commands

def cmd_all(args) -> int:
    """Run everything, write the report; with --check, also fail on a stale report."""
    out = prepare_output(args.out)
    committed = read_text_or_none(out / "REPORT.md")
    results, timings = execute(None, out, args.jobs)
    markdown = report.write_report(results, timings, out)
    figures.prune(out / "figures", keep={name for _, o in results for name in o.figures})
    warn_missing_figures(results, out)
    code = finish(results)
    wrote(out, results)
    if args.check:
        stale = report.changed_parts(committed, markdown)
        if stale == ["missing"]:
            say(f"{out / 'REPORT.md'} was missing: generated it now, commit it")
        elif stale:
            say(f"{out / 'REPORT.md'} was stale (changed: {', '.join(stale)}): "
                "regenerated it, commit the new one")
        code = 1 if stale else code
    return code


def _clip(text: str, width: int | None) -> str:
    return text if width is None or len(text) <= width else text[: max(width - 1, 0)] + "…"


def _under(results) -> dict[str, list[str]]:
    """The lines to print under each certificate: the failing checks of a FAIL (with
    their first evidence line); for an ERRATUM each false printed check (✗), its
    certified correction (✓) and what changed."""
    out = {}
    for cert, outcome in results:
        lines = []
        if outcome.status == FAIL:
            for check in outcome.printed + outcome.corrected:
                if not runner.holds(check):
                    first = str(check.evidence[0]).strip().split("\n")[0] if check.evidence else ""
                    lines.append("✗ " + " ".join(check.statement.split()) + (f": {first}" if first else ""))
        elif outcome.status == OBSERVED and outcome.agrees is False:
            lines.append("≠ does not agree with the paper: " + " ".join(outcome.reason.split()))
        elif outcome.status == ERRATUM:
            lines.append(f"{outcome.kind}: " + " ".join(outcome.misprint.split()))
            for printed, fixes in report.erratum_pairs(outcome):
                lines.append("✗ as printed: " + " ".join(printed.statement.split()))
                for fix in fixes:
                    lines.append("✓ corrected:  " + " ".join(fix.statement.split()))
                    change = report.changes(" ".join(printed.statement.split()), " ".join(fix.statement.split()))
                    if change:
                        lines.append("  changed:    " + change.replace("`", ""))
        out[cert.id] = lines
    return out


def print_results(results) -> None:
    """A compact table: id, status, statement; what failed under a FAIL; the false
    printed statement and its correction under an ERRATUM."""
    width = shutil.get_terminal_size().columns if sys.stdout.isatty() else None
    w = max((len(cert.id) for cert, _ in results), default=2)
    under = _under(results)
    sw = max((len(report.status_label(outcome)) for _, outcome in results), default=8)
    for cert, outcome in results:
        head = f"{cert.id:<{w}}  {report.status_label(outcome):<{sw}}  "
        print(head + _clip(" ".join(cert.statement.split()), width and width - len(head)))
        for line in under[cert.id]:
            print(" " * len(head) + _clip(line, width and width - len(head)))


def cmd_run(args) -> int:
    """Run the named certificates; write a report only when --out is given."""
    runner.select(args.ids)  # an unknown id is a usage error before anything is created
    out = prepare_output(args.out) if args.out is not None else None
    results, timings = execute(args.ids, out, args.jobs)
    print_results(results)
    if out is not None:
        report.write_report(results, timings, out)
        warn_missing_figures(results, out)
    code = finish(results)
    if out is not None:
        wrote(out, results)
    return code


def cmd_list(args) -> int:
    """One line per certificate: id, paper line, statement."""
    certs = runner.select()
    w = max((len(c.id) for c in certs), default=2)
    lw = max((len(c.line) for c in certs), default=4)
    for c in certs:
        print(f"{c.id:<{w}}  {c.line:<{lw}}  {' '.join(c.statement.split())}")
    return 0


def load_bench(name: str = "bench"):
    """Import ``benchmarks/<name>.py`` from the source checkout (it is not a package)."""
    path = REPO_ROOT / "benchmarks" / f"{name}.py"
    if not path.is_file():
        raise UsageError(f"no benchmark script at {path} (bench needs a source checkout)")
    spec = importlib.util.spec_from_file_location(f"certify_{name}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def cmd_bench(args) -> int:
    """Time the whole run (benchmarks/bench.py), or with --reduction the exact
    simulator and reduction map against bit growth (benchmarks/bench_reduction.py)."""
    if args.numerics:
        return load_bench("bench_numerics").main(["--quick"] * args.quick)
    if args.reduction:
        return load_bench("bench_reduction").main(["--repeat", str(args.repeat)] + ["--long"] * args.long)
    if args.patterns:      # pattern (ab)^n(cb)^n for n = 2..12, then the census for L = 8..16
        jobs = ["--jobs", str(args.jobs)] if args.jobs else []
        return load_bench("bench_patterns").main(["--repeat", str(args.repeat)]) or \
            load_bench("bench_census").main(jobs)
    return load_bench().main(["--repeat", str(args.repeat)] + (["--jobs", str(args.jobs)] if args.jobs else []))


def cmd_census(args) -> int:
    """The census of periodic patterns (certify/run/census.py): records stream to the
    state file, --resume skips the words already there."""
    import signal
    from certify.run import census, executors
    signal.signal(signal.SIGTERM, signal.default_int_handler)     # `kill` stops it like Ctrl-C: workers too
    out = ensure_writable(args.out)
    longer = census.written_length(out)
    if longer is not None and longer > args.max_length and not args.force:
        raise UsageError(f"{out / 'census.json'} holds a census up to length {longer}; one up to {args.max_length} "
                         "would replace it: write it elsewhere with --out DIR, or pass --force")
    state = args.state if args.state is not None else out / "census-state.jsonl"
    ensure_writable(state.parent)
    with executors.executor(args.jobs, args.scheduler) as ex:
        records = census.run(args.max_length, ex, state, args.resume, progress=progress.Bar("word"))
    doc = census.write_outputs(records, args.max_length, out)
    if args.json:
        print(census.to_json(doc), end="")
    else:
        s = doc["census"]
        print(f"{s['words']} words up to length {s['max_length']}: {len(s['feasible'])} with feasible data, "
              f"{len(s['stable'])} stable, {len(s['undecided'])} with undecided points, {len(s['errors'])} errors; "
              f"with abcab: {s['abcab']['words']}, feasible {len(s['abcab']['feasible'])}")
        print(f"wrote {out / 'CENSUS.md'}, census.json, {census.FIGURE}; state {state}")
    return 0


def cmd_pattern(args) -> int:
    """The exact analysis of one periodic word: Markdown on stdout, or JSON with --json
    (schema certify/patterns/pattern.schema.json).  A bad word is a UsageError (exit 2),
    raised before any work; nothing is written to a file."""
    from certify.patterns import analyse, check_range, read
    lo, hi = check_range(*args.r_range) if args.r_range else (0, 1)
    read(args.word)                       # validate first: one line, exit 2
    result = analyse(args.word, lo, hi)
    print(result.json_text() if args.json else result.markdown())
    return 0


def cmd_orbit(args) -> int:
    """The periodic orbits of the reduction with one word: Markdown on stdout, or JSON
    with --json (schema certify/patterns/orbit.schema.json).  A bad word is a UsageError
    (exit 2), raised before any work."""
    from certify.patterns import check_range, read
    from certify.patterns.reduction_orbits import analyse as analyse_orbit
    lo, hi = check_range(*args.r_range) if args.r_range else (0, 1)
    read(args.word)                       # validate first: one line, exit 2
    result = analyse_orbit(args.word, lo, hi)
    print(result.json_text() if args.json else result.markdown())
    return 0


def cmd_identify(args) -> int:
    """Simulate, read the periodic word each orbit settles on, certify it with `orbit`:
    one line per orbit, or JSON with --json (certify.run.identify)."""
    from certify.run import identify as ident
    if (args.r is None) == (args.r_range is None):
        raise UsageError("give --r R [R ...] or --r-range LO HI COUNT")
    rs = ident.rationals(args.r) if args.r is not None else ident.r_grid(*args.r_range)
    found = ident.identify(rs, orbits=args.orbits, collisions=args.collisions)
    if args.json:
        print(ident.json_text(found))
    else:
        for x in found:
            print(x.line())
    return 0


def cmd_particles(args) -> int:
    """Simulate the four particles exactly; one line per collision, then why it stopped."""
    if args.digits > MAX_DIGITS:
        raise UsageError(f"--digits is at most {MAX_DIGITS} (--exact prints the full fractions)")
    history = particles.simulate(args.x, args.v, args.r, args.collisions, progress=progress.Bar("collision"))
    for line in particles.report_lines(history, digits=args.digits, full=args.exact):
        print(line)
    return 0


# --------------------------------------------------------------------------
# Numerics (Section 5): simulate, stress

DEFAULT_STRESS = DEFAULT_OUT / "STRESS.md"


def number(text: str) -> float:
    """A real number: decimal or fraction ("0.15", "3/20")."""
    try:
        return float(Fraction(text))
    except (ValueError, ZeroDivisionError):
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None


def count(text: str) -> int:
    """A non-negative integer: 10000, 1e4 or 10^4."""
    try:
        if "^" in text:
            base, exp = text.split("^")
            value = int(base) ** int(exp)
        else:
            f = float(text)
            value = int(f) if f == int(f) else -1
    except (ValueError, OverflowError):
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError(f"expected a non-negative integer, got {text!r}")
    return value


def r_values(args):
    """The r of ``--r`` or ``--r-range LO HI COUNT`` (COUNT values, ends included)."""
    import numpy as np
    if args.r_range is not None:
        lo, hi, n = args.r_range
        if n != int(n) or n < 1:
            raise UsageError(f"--r-range COUNT must be a positive integer, not {n:g}")
        if lo > hi or (lo == hi and n > 1):
            raise UsageError(f"--r-range LO HI COUNT needs LO < HI (or LO = HI with COUNT 1), got LO = {lo:g}, HI = {hi:g}")
        r = np.linspace(lo, hi, int(n))
    else:
        r = np.array(args.r, dtype=float)
    bad = [x for x in r if not 0 < x < 1]
    if bad:
        raise UsageError(f"r must lie in ]0,1[, got {bad[0]:g}")
    return r


def initial_data(args):
    """(θ0, φ0): paired from ``--theta0`` and ``--phi0`` (θ0 in [0, π/2], φ0 in [0, π]),
    else the first ``--orbits`` of the paper's grid."""
    import math
    from certify import numerics
    import numpy as np
    if args.theta0 is None and args.phi0 is None:
        return numerics.grid(args.orbits if args.orbits is not None else 8)
    if args.theta0 is None or args.phi0 is None:
        raise UsageError("--theta0 and --phi0 go together (one φ0 per θ0)")
    if args.orbits is not None:
        raise UsageError("--orbits chooses from the paper's grid: not with --theta0/--phi0")
    if len(args.theta0) != len(args.phi0):
        raise UsageError(f"--theta0 has {len(args.theta0)} value(s), --phi0 {len(args.phi0)}: they are paired")
    for name, values, top, text in (("theta0", args.theta0, math.pi / 2, "π/2"), ("phi0", args.phi0, math.pi, "π")):
        bad = [x for x in values if not 0 <= x <= top]
        if bad:
            raise UsageError(f"--{name} must lie in [0, {text}], got {bad[0]:g}")
    return np.array(args.theta0, dtype=float), np.array(args.phi0, dtype=float)


def cmd_simulate(args) -> int:
    """Iterate the reduction map from the paper's grid of initial data (or the given
    ones) for every r."""
    from certify import numerics
    from certify.run import executors
    from certify.run.files import atomic_path
    r = r_values(args)
    theta0, phi0 = initial_data(args)
    if args.out is not None:
        ensure_writable(args.out.parent if str(args.out.parent) else Path("."))
        if args.out.is_dir():
            raise UsageError(f"--out {str(args.out)!r} is a directory, not a file")
    if args.dps is not None and args.engine == "float64":
        raise UsageError("--dps is for the mp and ball engines")
    if args.words and args.out is None:
        raise UsageError("--words stores the words in --out FILE.npz: give --out")
    with executors.executor(args.jobs, args.scheduler) if args.engine != "float64" else nullcontext() as ex:
        orbits = numerics.simulate(r, theta0, phi0, collisions=args.collisions, keep=args.keep,
                                   engine=args.engine, dps=args.dps, executor=ex, progress=progress.Bar("r"),
                                   strict=args.strict, words=args.words)
    if args.out is not None:
        with atomic_path(args.out) as tmp, open(tmp, "wb") as handle:
            orbits.save(handle)
        print(f"wrote {args.out}")
    print(orbits.summary())
    return 0


def cmd_stress(args) -> int:
    """Near-singular, long and random orbits on every engine: reports/STRESS.md."""
    from certify.numerics import stress
    from certify.run import executors
    from certify.run.files import write_atomic
    ensure_writable(args.out.parent if str(args.out.parent) else Path("."))
    with executors.executor(args.jobs) as ex:
        text, silent = stress.report(quick=args.quick, progress=progress.Bar("orbit"), executor=ex)
    write_atomic(args.out, text)
    print(f"wrote {args.out}: {silent} silent wrong collision(s)")
    return 1 if silent else 0


def add_numerics(commands) -> None:
    """The parsers of ``simulate`` and ``stress``."""
    from certify.numerics.engines import ENGINES
    p = commands.add_parser("simulate", help="iterate the reduction map numerically (Section 5)",
                            description="The spherical billiard reduction iterated from collision to "
                            "collision from the paper's grid of initial data (θ0, φ0) at a b-contact; "
                            "keeps the φ of the last b-collisions.  Breaks: 1 undecided contact "
                            "(|cos φ| below the rounding bound), 2 time step below precision, "
                            "3 corner, 4 non-finite, 5 certified horizon (--strict).  Every orbit reports "
                            "the collisions it certifies (float64, mp: an accumulated rigorous error bound; "
                            "ball: all).")
    which = p.add_mutually_exclusive_group(required=True)
    which.add_argument("--r", nargs="+", type=number, metavar="R", help="restitution coefficients in ]0,1[")
    which.add_argument("--r-range", nargs=3, type=number, metavar=("LO", "HI", "COUNT"),
                       help="COUNT values from LO to HI, ends included (paper Figure 6: 0.072 0.999 3709)")
    p.add_argument("--orbits", type=positive_int, default=None, metavar="N",
                   help="initial data per r: the first N of the paper's grid, 2 θ0 × 4 φ0 (default: 8)")
    p.add_argument("--theta0", nargs="+", type=number, metavar="T",
                   help="initial θ0 in [0, π/2], paired with --phi0 (instead of the grid)")
    p.add_argument("--phi0", nargs="+", type=number, metavar="P", help="initial φ0 in [0, π], one per --theta0")
    p.add_argument("--strict", action="store_true",
                   help="stop each orbit at its certified horizon (break 5); without it float64 and mp orbits "
                        "go on past it and --out's `certified` says how far they are proven")
    p.add_argument("--words", action="store_true",
                   help="also store each orbit's collision word in --out (an array `word` of strings)")
    p.add_argument("--collisions", type=count, default=10_000, metavar="N", help="collisions per orbit (default: 10^4)")
    p.add_argument("--keep", type=count, default=500, metavar="N",
                   help="keep the φ of the last N b-collisions (default: 500)")
    p.add_argument("--engine", choices=ENGINES, default="float64",
                   help="float64 (numba, parallel), mp (mpmath at --dps), ball (certified arb, precision up to --dps)")
    p.add_argument("--dps", type=positive_int, default=None, metavar="D",
                   help="decimal digits: of mp (default 30), the cap of ball (default 5000)")
    p.add_argument("--out", type=Path, default=None, metavar="FILE.npz",
                   help="write r, theta0, phi0, phi, breaks, collisions, certified [, word] (npz); "
                        "a summary is printed in any case")
    p.add_argument("--jobs", type=positive_int, default=None, metavar="N",
                   help="processes for the mp and ball engines (default: all cores)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run the mp and ball orbits on this Dask scheduler instead")
    p.set_defaults(func=cmd_simulate)

    p = commands.add_parser("stress", help="stress the numerical engines against the certified one",
                            description="Near-singular data, 1000 seeded random orbits of 2000 collisions over "
                            "the whole r range and long orbits, on float64 and mp against the certified ball "
                            "engine: certified horizons, departures, silent wrong collisions (exit 1 if any).")
    p.add_argument("--out", type=Path, default=DEFAULT_STRESS, metavar="FILE",
                   help="the report (default: reports/STRESS.md)")
    p.add_argument("--quick", action="store_true", help="smaller cases (a smoke test): 40 random orbits of 300")
    p.add_argument("--jobs", type=positive_int, default=None, metavar="N",
                   help="processes for the random orbits (default: all cores)")
    p.set_defaults(func=cmd_stress)


# --------------------------------------------------------------------------
# Parsing

class Parser(argparse.ArgumentParser):
    """An argument parser whose errors are UsageErrors: one line, exit code 2.
    Negative numbers, fractions and decimals included ("-3/7", "-.5"), are values,
    not options."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = re.compile(r"^-(\d+(/\d+)?|\d+\.\d*|\.\d+)$")

    def error(self, message):
        raise UsageError(message)


def positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {text!r}")
    return value


def add_jobs(p) -> None:
    """The --jobs option of the commands that run certificates."""
    p.add_argument("--jobs", type=positive_int, default=runner.default_jobs(), metavar="N",
                   help="worker processes (default: all cores, here %(default)s; 1: one after another)")


def build_parser() -> Parser:
    """The parser of ``certify COMMAND [options]``."""
    parser = Parser(prog="certify", description="Check every claim of arXiv:2411.10324 "
                    "in exact arithmetic and write the report.",
                    epilog="exit codes: 0 all PASS/ERRATUM/OBSERVED, 1 a FAIL or a stale "
                    "report, 2 usage error, 130 interrupted")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    p = commands.add_parser("all", help="run every certificate and write the report")
    p.add_argument("--check", action="store_true",
                   help="exit 1 also when the existing DIR/REPORT.md was stale")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, metavar="DIR",
                   help="output directory (default: reports)")
    add_jobs(p)
    p.set_defaults(func=cmd_all)

    p = commands.add_parser("run", help="run some certificates and print their verdicts")
    p.add_argument("ids", nargs="+", metavar="ID",
                   help="claim ids such as T5; T10 also selects T10.1, T10.2, ...")
    p.add_argument("--out", type=Path, default=None, metavar="DIR",
                   help="also write a report of these certificates into DIR")
    add_jobs(p)
    p.set_defaults(func=cmd_run)

    p = commands.add_parser("list", help="list the certificates")
    p.set_defaults(func=cmd_list)

    p = commands.add_parser("bench", help="time the whole run")
    p.add_argument("--repeat", type=positive_int, default=5, metavar="N",
                   help="number of runs (default: 5)")
    p.add_argument("--reduction", action="store_true",
                   help="time the exact simulator and reduction map instead (benchmarks/bench_reduction.py)")
    p.add_argument("--long", action="store_true", help="with --reduction: also 10^4 collisions, 10^5 steps")
    p.add_argument("--patterns", action="store_true",
                   help="time `pattern (ab)^n(cb)^n` for n = 2..12 and the census for L = 8..16 instead "
                        "(benchmarks/bench_patterns.py, bench_census.py; about an hour)")
    p.add_argument("--jobs", type=positive_int, default=None, metavar="N",
                   help="time only the run on N processes (default: both --jobs 1 and all cores)")
    p.add_argument("--numerics", action="store_true",
                   help="time the numerical engines against error instead (benchmarks/bench_numerics.py)")
    p.add_argument("--quick", action="store_true", help="with --numerics: smaller sizes (no BENCH.md)")
    p.set_defaults(func=cmd_bench)

    p = commands.add_parser("census", help="analyse every periodic pattern of blocks up to a length")
    p.add_argument("--max-length", type=positive_int, required=True, metavar="L", help="longest period, in collisions")
    p.add_argument("--json", action="store_true", help="also print the census as JSON on stdout")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, metavar="DIR", help="output directory (default: reports)")
    p.add_argument("--state", type=Path, default=None, metavar="FILE",
                   help="JSON lines, one per word analysed (default: DIR/census-state.jsonl)")
    p.add_argument("--resume", action="store_true", help="do not analyse again the words already in the state file")
    p.add_argument("--force", action="store_true",
                   help="replace a census of longer periods already in DIR (refused without it)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run on the Dask cluster at ADDRESS (needs certify[distributed]) instead of local processes")
    add_jobs(p)
    p.set_defaults(func=cmd_census)

    p = commands.add_parser("pattern", help="analyse one periodic collision word exactly",
                            description="Where in r the self-similar data of a periodic word exist, are "
                            "feasible and are stable, with algebraic end points.  WORD: ababcb, (ab)^3(cb)^3, "
                            "[ac]b (a and c at once, the symmetric system), ab (three particles); any rotation "
                            "or the mirror a<->c.")
    p.add_argument("word", metavar="WORD", help="a period over a, b, c; powers (…)^n; [ac]")
    p.add_argument("--json", action="store_true", help="print JSON (certify/patterns/pattern.schema.json)")
    p.add_argument("--r-range", nargs=2, default=None, metavar=("LO", "HI"),
                   help="restrict to ]LO, HI[ (rationals, 0 <= LO < HI <= 1)")
    p.set_defaults(func=cmd_pattern)

    p = commands.add_parser("orbit", help="certify the periodic orbits of the reduction (Section 4) with one word",
                            description="For each real eigenvalue of M_w: where in r the periodic orbit of the "
                            "reduction with this word exists and is feasible, and whether it is attracting, a saddle "
                            "or repelling (in-plane pair real or complex), with algebraic end points.  Same words as "
                            "`pattern` (four particles: a, b and c).")
    p.add_argument("word", metavar="WORD", help="a period over a, b, c; powers (…)^n")
    p.add_argument("--json", action="store_true", help="print JSON (certify/patterns/orbit.schema.json)")
    p.add_argument("--r-range", nargs=2, default=None, metavar=("LO", "HI"),
                   help="restrict to ]LO, HI[ (rationals, 0 <= LO < HI <= 1)")
    p.set_defaults(func=cmd_orbit)

    p = commands.add_parser("identify", help="the periodic word each simulated orbit settles on, certified by `orbit`",
                            description="Runs the float64 simulator (the paper's eight orbits by default), reads the "
                            "shortest period of each orbit's last collisions, and certifies that word with `orbit`: "
                            "its normal form and the attracting window that contains r, or why there is none.")
    p.add_argument("--r", nargs="+", default=None, metavar="R", help="values of r (exact rationals: 0.3 is 3/10)")
    p.add_argument("--r-range", nargs=3, default=None, metavar=("LO", "HI", "COUNT"),
                   help="COUNT equally spaced r from LO to HI, ends included")
    p.add_argument("--orbits", type=positive_int, default=8, metavar="N",
                   help="the first N initial data of the paper's grid (default: 8)")
    p.add_argument("--collisions", type=positive_int, default=10_000, metavar="N",
                   help="collisions simulated per orbit (default: 10000)")
    p.add_argument("--json", action="store_true",
                   help="print JSON: a list of orbits, each with r, theta0, phi0, word and window")
    p.set_defaults(func=cmd_identify)

    p = commands.add_parser("particles", help="simulate four particles exactly",
                            description="Four particles on a line, equal masses, restitution "
                            "coefficient r: the collisions (a: 1-2, b: 2-3, c: 3-4, ac: a and c "
                            "at once) and their exact times.  Numbers: -2, 3/7, 0.25 (exact).")
    p.add_argument("--x", nargs=4, required=True, metavar=("X1", "X2", "X3", "X4"),
                   help="initial positions, x1 <= x2 <= x3 <= x4")
    p.add_argument("--v", nargs=4, required=True, metavar=("V1", "V2", "V3", "V4"),
                   help="initial velocities")
    p.add_argument("--r", required=True, metavar="R", help="restitution coefficient in ]0,1[")
    p.add_argument("--collisions", type=positive_int, default=100, metavar="N",
                   help="stop after N collisions, ac counting as one (default: 100)")
    p.add_argument("--digits", type=positive_int, default=20, metavar="D",
                   help="significant digits of the decimal times, correctly rounded (default: 20)")
    p.add_argument("--exact", action="store_true",
                   help="print every time as a full fraction, however long")
    p.set_defaults(func=cmd_particles)
    add_numerics(commands)
    add_figures(commands)
    return parser


# --------------------------------------------------------------------------
# Figures 5.1-5.8 (certify.numerics.figures, drawn by certify.run.plots)

FIGURE_DPI = {"preview": None, "paper": 150}


def cmd_figures(args) -> int:
    """Figures 5.1-5.8 at ``--resolution`` into DIR/figures (``fig5.2-paper.png``); at the
    paper's resolution also DIR/numerics-paper.json, the findings N2-N7 quote; with
    ``--n4 NMAX`` the windows of (ab)^n(cb)^n up to n = NMAX (mp), DIR/numerics-n4.json."""
    import json
    from certify.numerics import figures as numfig
    from certify.run import plots
    from certify.run.files import write_atomic
    unknown = [f for f in args.only or () if f not in numfig.SPECS]
    if unknown:
        raise UsageError(f"unknown figure {unknown[0]!r} (one of {', '.join(numfig.SPECS)})")
    out = prepare_output(args.out)
    if args.n4 is not None:
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor
        with ProcessPoolExecutor(args.jobs, mp_context=multiprocessing.get_context("fork")) as pool:  # one n per job
            found = numfig.n4_search(args.n4, progress=progress.Bar("n"), executor=pool if args.jobs > 1 else None)
        write_atomic(out / "numerics-n4.json", json.dumps(found, indent=1) + "\n")
        print(f"N4: largest n with 2n accumulation points (mp): {found['largest_n_mp']}; "
              f"float64: {found['largest_n_float64']}; {found['seconds']} s; wrote {out / 'numerics-n4.json'}")
        if not args.only and args.resolution is None:
            return 0
    resolution = args.resolution or "preview"
    datas, names = {}, []
    with figures.output_dir(out / "figures"):
        for fig in args.only or numfig.SPECS:
            datas[fig] = numfig.compute(fig, resolution, progress=progress.Bar(f"figure {fig}"))
            names.append(plots.section5_figure(datas[fig], dpi=FIGURE_DPI[resolution]))
            print(f"figure {fig}: {len(datas[fig].r)} values of r, {int((datas[fig].breaks != 0).sum())} breaks, "
                  f"{datas[fig].seconds:.1f} s -> {out / 'figures' / names[-1]}")
    if resolution == "paper" and not args.only:
        write_atomic(out / "numerics-paper.json", json.dumps(numfig.findings(datas), indent=1) + "\n")
        print(f"wrote {out / 'numerics-paper.json'}")
    return 0


def add_figures(commands) -> None:
    """The parser of ``certify figures``."""
    p = commands.add_parser("figures", help="draw Figures 6-11 of the paper, Section 5 (ids 5.1-5.8)",
                            description="Figures 6-11 of the paper (Section 5; our ids 5.1-5.8: 5.1 = Figure 6, 5.2 = 7, 5.3a/b = 8a/b, "
                            "5.4 = 9, 5.5 = 10, 5.6-5.8 = 11a-c): the last kept b-angles φ of the paper's 8 "
                            "orbits against r (float64), breaks as red dots at (r, π/2), the CDKK thresholds as red "
                            "lines.  preview: the cheap version `certify all` draws; paper: the captions' grids, "
                            "10^4 collisions, 500 kept (about a minute on two cores).")
    p.add_argument("--resolution", choices=("preview", "paper"), default=None,
                   help="preview (default) or the paper's parameters")
    p.add_argument("--only", nargs="+", metavar="FIG", help="only these figures, e.g. 5.2 5.3a")
    p.add_argument("--n4", type=positive_int, default=None, metavar="NMAX",
                   help="find the windows of (ab)^n(cb)^n up to n = NMAX with the mp engine (minutes)")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, metavar="DIR", help="output directory (default: reports)")
    add_jobs(p)
    p.set_defaults(func=cmd_figures)


def describe(exc: BaseException) -> str:
    """An unexpected exception in one line: type, message, and where it was raised."""
    text = f"{type(exc).__name__}: {' '.join(str(exc).split())}"
    frames = traceback.extract_tb(exc.__traceback__)
    if frames:
        where = frames[-1]
        try:
            name = os.path.relpath(where.filename)
        except ValueError:
            name = where.filename
        text += f" (at {name}:{where.lineno})"
    return text


def main(argv=None) -> int:
    """Run the command line ``argv`` (default: sys.argv[1:]); return the exit code."""
    for stream in (sys.stdout, sys.stderr):  # never die on a character the terminal lacks
        if hasattr(stream, "reconfigure"):
            stream.reconfigure(errors="replace")
    try:
        args = build_parser().parse_args(argv)
        return args.func(args)
    except UsageError as exc:
        progress.clear()
        say(f"error: {exc}")
        return 2
    except KeyboardInterrupt:
        progress.clear()
        say("interrupted")
        return 130
    except SystemExit as exc:  # --help
        return exc.code if isinstance(exc.code, int) else 0
    except BrokenPipeError:  # e.g. `certify list | head`
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except Exception as exc:
        if os.environ.get("CERTIFY_DEBUG"):
            raise
        progress.clear()
        say(f"internal error: {describe(exc)}; set CERTIFY_DEBUG=1 for the traceback")
        return 1
