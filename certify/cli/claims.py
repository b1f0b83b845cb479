"""The commands that run the certificates: ``all`` (the report), ``run ID ...`` (some
verdicts), ``list``, and ``bench`` (the whole run timed, or the engines' benchmarks).
"""
from __future__ import annotations

import importlib.util
import json
import shutil
import sys
from contextlib import nullcontext
from pathlib import Path

from certify.errors import UsageError
from certify.run import ERRATUM, FAIL, OBSERVED, progress, report, runner, saving
from certify.run.files import CHECKOUT, read_text_or_none

from .options import DEFAULT_OUT, add_command, add_jobs, positive_int, prepare_output, say


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
    writing = saving.output_dir(out / "figures") if out is not None else nullcontext()
    with writing:
        return runner.run_selected(ids, progress=progress.Bar("certificate"), jobs=jobs, estimates=estimates(out))


def failing(results) -> list[str]:
    """The ids of the certificates that FAIL."""
    return [cert.id for cert, outcome in results if outcome.status == FAIL]


def exit_code(results) -> int:
    """0 when nothing FAILs, 1 otherwise."""
    return 1 if failing(results) else 0

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

def cmd_all(args) -> int:
    """Run everything, write the report; with --check, also fail on a stale report."""
    out = prepare_output(args.out)
    committed = read_text_or_none(out / "REPORT.md")
    committed_certificates = read_text_or_none(out / "certificates.json")
    committed_kernel = read_text_or_none(out / "kernel.json")
    results, timings = execute(None, out, args.jobs)
    markdown = report.write_report(results, timings, out, jobs=args.jobs)
    saving.prune(out / "figures", keep={name for _, o in results for name in o.figures})
    warn_missing_figures(results, out)
    code = finish(results)
    wrote(out, results)
    if args.check:
        stale = report.changed_parts(committed, markdown)
        if committed_certificates != read_text_or_none(out / "certificates.json") and stale != ["missing"]:
            stale = stale + ["certificates.json"]
        if committed_kernel != read_text_or_none(out / "kernel.json") and stale != ["missing"]:
            stale = stale + ["kernel.json"]
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
            lines.append(f"{outcome.kind}: " + " ".join(report.misprint_text(outcome).split()))
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
        report.write_report(results, timings, out, jobs=args.jobs)
        warn_missing_figures(results, out)
    code = finish(results)
    if out is not None:
        wrote(out, results)
    return code


def cmd_verify(args) -> int:
    """Decide the statements with the independent kernel (certify_kernel: the standard library
    alone) on DIR/certificates.json, one line per certificate; exit 0, 1 when the kernel rejects a
    certificate (or, with --check, its results differ from DIR/kernel.json), 2 on bad input."""
    import certify_kernel.__main__ as kernel
    if not args.path.is_file():
        raise UsageError(f"no certificates file at {args.path} (run `python -m certify all` first)")
    argv = [str(args.path)] + (["--only", *args.only] if args.only else []) + \
        (["--jobs", str(args.jobs)] if args.jobs else []) + (["--verbose"] if args.verbose else [])
    if not args.check or args.only:
        return kernel.main(argv)
    from certify.run import verification
    data = verification.decide(args.path.read_text(encoding="utf-8"), args.jobs or 2)
    for r in data["certificates"].values():
        print(r["line"])
    print(f"{len(data['certificates'])} certificates; {data['verified']}/{data['statements']} statements verified")
    code = 0 if all(r["ok"] for r in data["certificates"].values()) else 1
    committed = args.path.parent / "kernel.json"
    if read_text_or_none(committed) != verification.render(data):
        say(f"{committed} is stale: the kernel's results differ (run `python -m certify all` and commit it)")
        code = code or 1
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
    path = CHECKOUT / "benchmarks" / f"{name}.py"
    if not path.is_file():
        raise UsageError(f"no benchmark script at {path} (bench needs a source checkout)")
    spec = importlib.util.spec_from_file_location(f"certify_{name}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def cmd_bench(args) -> int:
    """Time the whole run (benchmarks/bench.py), or with --reduction the exact
    simulator and reduction map against bit growth (benchmarks/bench_reduction.py), or with
    --targets issue 26's targets against the plain script and the census's words per second
    (benchmarks/bench_targets.py)."""
    if args.numerics:
        return load_bench("bench_numerics").main(["--quick"] * args.quick)
    if args.targets:
        return load_bench("bench_targets").main(["--all", "--census", "--repeat", str(args.repeat)]
                                                + ["--long"] * args.long)
    if args.reduction:
        return load_bench("bench_reduction").main(["--repeat", str(args.repeat)] + ["--long"] * args.long)
    if args.family:        # the whole command `pattern (ab)^n(cb)^n` for n = 8, 12, 31, 40, 60
        return load_bench("bench_patterns").main(["--family"])
    if args.patterns:      # pattern (ab)^n(cb)^n for n = 2..12, then the census for L = 8..16
        jobs = ["--jobs", str(args.jobs)] if args.jobs else []
        return load_bench("bench_patterns").main(["--repeat", str(args.repeat)]) or \
            load_bench("bench_census").main(jobs)
    return load_bench().main(["--repeat", str(args.repeat)] + (["--jobs", str(args.jobs)] if args.jobs else []))


def register(commands) -> None:
    """The parsers of ``all``, ``run``, ``list`` and ``bench``."""
    p = add_command(commands, "all", cmd_all, help="run every certificate and write the report",
                    description="Run every certificate of proofs/ (on every core by default) and write "
                    "DIR/REPORT.md, report.json, timings.json and figures/; print the counts, the errors of the "
                    "paper and the observations that disagree with it.  Exit 1 if a certificate FAILs (with "
                    "--check: also if the existing REPORT.md was stale).")
    p.add_argument("--check", action="store_true",
                   help="exit 1 also when the existing DIR/REPORT.md was stale")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, metavar="DIR",
                   help="output directory (default: reports)")
    add_jobs(p)

    p = add_command(commands, "run", cmd_run, help="run some certificates and print their verdicts",
                    description="Run the certificates named (T10 also selects T10.1, T10.2, ...) and print one "
                    "line each: id, status, statement, with the failing checks or the erratum under it.  Writes "
                    "a report only with --out.")
    p.add_argument("ids", nargs="+", metavar="ID",
                   help="claim ids such as T5; T10 also selects T10.1, T10.2, ...")
    p.add_argument("--out", type=Path, default=None, metavar="DIR",
                   help="also write a report of these certificates into DIR")
    add_jobs(p)

    p = add_command(commands, "verify", cmd_verify,
                    help="decide the paper's statements with the independent kernel (certify_kernel)",
                    description="Decide every formal statement of statements/*.txt with the independent kernel "
                    "(the Python standard library alone, its own definitions, the witnesses of "
                    "reports/certificates.json): one line per certificate with K/N statements verified and why any "
                    "is not, then the count.  With --check, also compare with the committed reports/kernel.json.")
    p.add_argument("path", nargs="?", type=Path, default=DEFAULT_OUT / "certificates.json", metavar="PATH",
                   help="the certificates file (default: reports/certificates.json)")
    p.add_argument("--only", nargs="+", metavar="ID", default=None, help="decide only these certificates")
    p.add_argument("--jobs", type=positive_int, default=None, metavar="N", help="processes (default: 2)")
    p.add_argument("--verbose", action="store_true", help="list every statement and its result")
    p.add_argument("--check", action="store_true",
                   help="fail when the kernel's results differ from kernel.json beside the certificates file")

    p = add_command(commands, "list", cmd_list, help="list the certificates",
                    description="One line per certificate: its id, the lines of the paper it checks, its statement.")

    p = add_command(commands, "bench", cmd_bench, help="time the whole run",
                    description="Time `certify all` (benchmarks/bench.py: serial, on every core, and the whole "
                    "command; writes reports/BENCH.md), or instead the exact simulator and reduction map "
                    "(--reduction), the numerical engines (--numerics), pattern and the census (--patterns), "
                    "or issue 26's targets against a plain SymPy script (--targets).")
    p.add_argument("--repeat", type=positive_int, default=5, metavar="N",
                   help="number of runs (default: 5)")
    p.add_argument("--reduction", action="store_true",
                   help="time the exact simulator and reduction map instead (benchmarks/bench_reduction.py)")
    p.add_argument("--long", action="store_true", help="with --reduction: also 10^4 collisions, 10^5 steps; with "
                   "--targets: also `orbit` on the 122-letter word")
    p.add_argument("--targets", action="store_true",
                   help="time issue 26's targets (orbit, pattern and all against a plain SymPy script, in one run; "
                   "benchmarks/bench_targets.py) and the census's words per second at lengths 8, 10, 12 instead, "
                   "and write them to reports/BENCH.md")
    p.add_argument("--patterns", action="store_true",
                   help="time `pattern (ab)^n(cb)^n` for n = 2..12 and the census for L = 8..16 instead "
                        "(benchmarks/bench_patterns.py, bench_census.py; about an hour)")
    p.add_argument("--family", action="store_true",
                   help="time the whole `certify pattern (ab)^n(cb)^n` for n = 8, 12, 31, 40, 60 instead "
                        "(benchmarks/bench_patterns.py --family; each stopped after 600 s)")
    p.add_argument("--jobs", type=positive_int, default=None, metavar="N",
                   help="time only the run on N processes (default: both --jobs 1 and all cores)")
    p.add_argument("--numerics", action="store_true",
                   help="time the numerical engines against error instead (benchmarks/bench_numerics.py)")
    p.add_argument("--quick", action="store_true", help="with --numerics: smaller sizes (no BENCH.md)")
