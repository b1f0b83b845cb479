"""The command line: ``python -m certify COMMAND`` (or the ``certify`` script).

    all [--check] [--out DIR] [--jobs N]
                                run every certificate, write DIR/REPORT.md,
                                DIR/report.json, DIR/timings.json, DIR/figures/
    run ID [ID ...] [--out DIR] [--jobs N]
                                run some certificates, print their verdicts
    list                        list the certificates: id, paper line, statement
    bench [--repeat N] [--jobs N] [--reduction [--long]] [--patterns]
                                time the whole run (benchmarks/bench.py), or the
                                exact simulator and reduction map (bench_reduction.py)
    census --max-length L [--json] [--out DIR] [--jobs N | --scheduler ADDRESS]
           [--state FILE] [--resume]
                                every periodic pattern of blocks up to length L,
                                its feasible and stable r-sets: DIR/CENSUS.md,
                                DIR/census.json, DIR/census-windows.png
    pattern WORD [--json] [--r-range LO HI]
                                the exact analysis of one periodic word (ababcb,
                                (ab)^3(cb)^3, [ac]b, ab): where in r self-similar data
                                exist, are feasible, are stable (certify.patterns.pattern)
    particles --x X1 X2 X3 X4 --v V1 V2 V3 V4 --r R [--collisions N]
              [--digits D] [--exact]
                                simulate the four particles exactly, print the
                                collisions and their times (certify.dynamics.particles)

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
from pathlib import Path

from certify.dynamics import particles
from certify.errors import UsageError
from certify.run import ERRATUM, FAIL, figures, progress, report, runner
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
    """Print the summary line and the errata ids (stdout), the failing ids (stderr);
    return the exit code."""
    print(report.summary_line(results))
    errata = [cert.id for cert, outcome in results if outcome.status == ERRATUM]
    if errata:
        print("errata (the paper is wrong, a correction is certified): " + ", ".join(errata))
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
        elif outcome.status == ERRATUM:
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
    for cert, outcome in results:
        head = f"{cert.id:<{w}}  {outcome.status:<8}  "
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
    if args.reduction:
        return load_bench("bench_reduction").main(["--repeat", str(args.repeat)] + ["--long"] * args.long)
    if args.patterns:
        return load_bench("bench_patterns").main(["--repeat", str(args.repeat)])
    return load_bench().main(["--repeat", str(args.repeat)] + (["--jobs", str(args.jobs)] if args.jobs else []))


def cmd_census(args) -> int:
    """The census of periodic patterns (certify/run/census.py): records stream to the
    state file, --resume skips the words already there."""
    import signal
    from certify.run import census, executors
    signal.signal(signal.SIGTERM, signal.default_int_handler)     # `kill` stops it like Ctrl-C: workers too
    out = ensure_writable(args.out)
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


def cmd_particles(args) -> int:
    """Simulate the four particles exactly; one line per collision, then why it stopped."""
    if args.digits > MAX_DIGITS:
        raise UsageError(f"--digits is at most {MAX_DIGITS} (--exact prints the full fractions)")
    history = particles.simulate(args.x, args.v, args.r, args.collisions, progress=progress.Bar("collision"))
    for line in particles.report_lines(history, digits=args.digits, full=args.exact):
        print(line)
    return 0


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
                   help="time `pattern (ab)^n(cb)^n` instead (benchmarks/bench_patterns.py)")
    p.add_argument("--jobs", type=positive_int, default=None, metavar="N",
                   help="time only the run on N processes (default: both --jobs 1 and all cores)")
    p.set_defaults(func=cmd_bench)

    p = commands.add_parser("census", help="analyse every periodic pattern of blocks up to a length")
    p.add_argument("--max-length", type=positive_int, required=True, metavar="L", help="longest period, in collisions")
    p.add_argument("--json", action="store_true", help="also print the census as JSON on stdout")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, metavar="DIR", help="output directory (default: reports)")
    p.add_argument("--state", type=Path, default=None, metavar="FILE",
                   help="JSON lines, one per word analysed (default: DIR/census-state.jsonl)")
    p.add_argument("--resume", action="store_true", help="do not analyse again the words already in the state file")
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
    return parser


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
