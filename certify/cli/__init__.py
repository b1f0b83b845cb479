"""The command line: ``python -m certify COMMAND`` (or the ``certify`` script).

    all [--check] [--out DIR] [--jobs N]
                                run every certificate, write DIR/REPORT.md,
                                DIR/report.json, DIR/timings.json, DIR/figures/
    run ID [ID ...] [--out DIR] [--jobs N]
                                run some certificates, print their verdicts
    list                        list the certificates: id, paper line, statement
    bench [--repeat N] [--jobs N] [--reduction [--long]] [--numerics [--quick]] [--patterns] [--family]
                                time the whole run (benchmarks/bench.py), or the
                                exact simulator and reduction map (bench_reduction.py),
                                the numerical engines (bench_numerics.py), or
                                pattern and census (bench_patterns.py, bench_census.py),
                                or pattern on (ab)^n(cb)^n, n = 8, 12, 31, 40, 60 (--family)
    census --max-length L [--json] [--out DIR] [--jobs N | --scheduler ADDRESS]
           [--state FILE] [--resume] [--force]
                                every periodic pattern of blocks up to length L,
                                its feasible and stable r-sets: DIR/CENSUS.md,
                                DIR/census.json, census-words.csv.gz (a row a
                                word), census-windows.png
    census --particles 5 --max-length L [--out DIR] [--state FILE] [--resume] [--check]
                                every five-particle word class up to length L ≤ 11:
                                the largest r of stable and of feasible collapse,
                                DIR/CENSUS5.md, census5.json (certify.run.census5);
                                --check analyses the committed words again
    pattern WORD [--json] [--r-range LO HI]
                                the exact analysis of one periodic word (ababcb,
                                (ab)^3(cb)^3, [ac]b, ab; five particles: abadcbcabc):
                                where in r self-similar data exist, are feasible,
                                are stable (certify.patterns.pattern, .five)
    family --n-max N [--out DIR] [--force]
                                the stability windows of (ab)^n(cb)^n for n = 2..N,
                                checked (one interval, above 7-4√3, hi_n a zero of q_2(0),
                                disjoint and decreasing): DIR/family.json
    orbit WORD [--json] [--r-range LO HI | --trap R]
                                the periodic orbits of the reduction with one word:
                                where they exist, are feasible, attracting, saddles,
                                repelling (certify.patterns.reduction_orbits); --trap:
                                a certified trapping ellipse at R
    identify (--r R [R ...] | --r-range LO HI COUNT) [--orbits N] [--collisions N] [--json]
                                the periodic word each simulated orbit settles on,
                                certified by orbit (certify.run.identify)
    particles --x X1 X2 X3 X4 --v V1 V2 V3 V4 --r R [--collisions N]
              [--digits D] [--exact]
                                simulate the four particles exactly, print the
                                collisions and their times (certify.dynamics.particles)
    figures [--resolution preview|paper] [--only FIG ...] [--n4 NMAX] [--out DIR] [--force]
                                Figures 6-11 of the paper (our ids 5.1-5.8) into
                                DIR/figures; paper: also
                                DIR/numerics-paper.json; --n4: DIR/numerics-n4.json;
                                --certify-points EVERY: the plotted points certified
                                (certify.run.figure_points)
    simulate (--r R [R ...] | --r-range LO HI COUNT)
             [--orbits N | --theta0 T [T ...] --phi0 P [P ...]] [--collisions N]
             [--keep N] [--engine float64|mp|ball] [--dps D] [--strict] [--words]
             [--out FILE.npz] [--jobs N] [--scheduler ADDRESS]
                                iterate the reduction map numerically (Section 5,
                                certify.numerics); the φ of the last b-collisions
    island (--r R | --r-range LO HI [COUNT]) [--json] [--resonances Q] [--symbolic] [--depth D]
                                the island theorem at each rational r: quasi-periodic
                                orbits around [ac]b, proved (certify.patterns.island_theorem)
    atlas [--r-range LO HI] [--resolution N] [--data M] [--out DIR] [--jobs N | --scheduler ADDRESS]
          [--resume] [--json] [--force]
                                the attractors of the reduction over ]0, 1[: each orbit's
                                class, the certified windows stitched into cells, families:
                                DIR/ATLAS.md, atlas.json, atlas.png (certify.run.atlas)
    stress [--out FILE] [--quick] [--jobs N] [--force]
                                near-singular, long and 1000 random orbits on every
                                engine against the certified one: reports/STRESS.md
    chaos --r R [--json]        a horseshoe of the b-to-b map at r, proved by covering
                                relations in rationals (certify.numerics.horseshoe)
    schema [NAME] [--validate FILE]
                                the JSON Schema of every JSON output; check a file

The commands by topic: :mod:`.claims` (all, run, list, bench), :mod:`.exact` (census,
pattern, orbit, particles), :mod:`.section5` (simulate, identify, stress, figures),
:mod:`.island_command` (island), :mod:`.chaos_command` (chaos),
:mod:`.atlas_command` (atlas), :mod:`.schemas` (schema); :mod:`.options` holds what they share
(the parser, the one syntax of numbers) and :func:`~certify.cli.options.add_command`, the one way a command is
registered (each topic's ``register(commands)`` calls it for its commands).

Exit codes (:data:`EXIT_CODES`): 0 when every selected certificate is PASS, ERRATUM or
OBSERVED; 1 when one FAILs (or, with ``all --check``, when the committed REPORT.md is
stale; ``orbit --trap``: no trapping neighbourhood found; ``stress``: a silent wrong
collision); 2 for a usage error (a bad option or value, an input beyond a stated limit);
3 for an internal error, or a question the certified enclosures left undecided at their
precision cap (nothing is claimed); 130 when interrupted.  Errors are reported in one
line on stderr, never as a traceback (set ``CERTIFY_DEBUG=1`` to see one).
"""
from __future__ import annotations

import gc
import importlib
import os
import sys
import traceback

from certify.errors import Undecided, UsageError

from .options import Parser, clip, say

TOPICS = ("claims", "exact", "section5", "island_command", "atlas_command", "chaos_command",
          "schemas")   # in the order of ``--help``
# Each command's topic: running a command imports its topic's module alone (``pattern`` does not load the
# runner, the plots, numpy...).  tests/cli/test_cli.py checks the table against what the topics register.
COMMANDS = {**dict.fromkeys(("all", "run", "verify", "list", "bench"), "claims"),
            **dict.fromkeys(("census", "pattern", "family", "orbit", "particles"), "exact"),
            **dict.fromkeys(("simulate", "identify", "stress", "figures"), "section5"),
            "island": "island_command", "atlas": "atlas_command", "chaos": "chaos_command", "schema": "schemas"}
EXIT_CODES = {0: "all PASS/ERRATUM/OBSERVED", 1: "a FAIL or a stale report", 2: "usage error",
              3: "internal error or undecided", 130: "interrupted"}


def build_parser(command: str | None = None) -> Parser:
    """The parser of ``certify COMMAND [options]``: each topic registers its commands; with
    ``command`` (a name of :data:`COMMANDS`) only that command's topic, the only module imported."""
    parser = Parser(prog="certify", description="Check every claim of arXiv:2411.10324 "
                    "in exact arithmetic and write the report.",
                    epilog="exit codes: " + ", ".join(f"{k} {v}" for k, v in EXIT_CODES.items()))
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for topic in [COMMANDS[command]] if command in COMMANDS else TOPICS:
        importlib.import_module(f"{__name__}.{topic}").register(commands)
    return parser


def clear_progress() -> None:
    """Erase the progress bars still drawn (none unless a command loaded certify.run.progress)."""
    progress = sys.modules.get("certify.run.progress")
    if progress is not None:
        progress.clear()


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


def run() -> None:
    """The program (``python -m certify``, the ``certify`` script): :func:`main`, then exit
    without the interpreter's last garbage collections over everything the command built
    (``gc.freeze()``: 0.15 s after the analysis of (ab)^6(cb)^6, a tenth of the command;
    the atexit handlers still run, and every file is written and closed by then)."""
    code = main()
    gc.freeze()
    raise SystemExit(code)


def main(argv=None) -> int:
    """Run the command line ``argv`` (default: sys.argv[1:]); return the exit code."""
    for stream in (sys.stdout, sys.stderr):  # never die on a character the terminal lacks
        if hasattr(stream, "reconfigure"):
            stream.reconfigure(errors="replace")
    argv = sys.argv[1:] if argv is None else list(argv)
    try:
        args = build_parser(argv[0] if argv else None).parse_args(argv)
        return args.func(args)
    except UsageError as exc:
        clear_progress()
        say(f"error: {clip(' '.join(str(exc).split()))}")
        return 2
    except KeyboardInterrupt:
        clear_progress()
        say("interrupted")
        return 130
    except SystemExit as exc:  # --help
        return exc.code if isinstance(exc.code, int) else 0
    except BrokenPipeError:  # e.g. `certify list | head`
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except Undecided as exc:
        if os.environ.get("CERTIFY_DEBUG"):
            raise
        clear_progress()
        say(f"undecided: {' '.join(str(exc).split())[:300]}: the certified enclosures did not decide at their "
            "precision cap; nothing is claimed")
        return 3
    except Exception as exc:
        if os.environ.get("CERTIFY_DEBUG"):
            raise
        clear_progress()
        say(f"internal error: {describe(exc)}; set CERTIFY_DEBUG=1 for the traceback")
        return 3
