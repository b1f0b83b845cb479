"""The commands of Section 5, numerical: ``simulate`` (the reduction map iterated),
``stress`` (the engines against the certified one), ``figures`` (Figures 6-11 of the
paper, our 5.1-5.8, and the findings N2-N7 quote).
"""
from __future__ import annotations

from contextlib import nullcontext
from pathlib import Path

from certify.errors import UsageError
from certify.run import executors, progress, saving
from certify.run.files import (
    atomic_path,
    ensure_writable,
    ensure_writable_file,
    keep_larger,
    load_findings,
    read_text_or_none,
    write_atomic,
    write_findings,
)

from .options import (
    DEFAULT_OUT,
    add_command,
    add_jobs,
    number,
    positive_int,
    prepare_output,
    r_grid,
    r_value,
    restitution,
)

DEFAULT_STRESS = DEFAULT_OUT / "STRESS.md"

def r_values(args):
    """The r of ``--r`` or ``--r-range LO HI COUNT`` (COUNT values, ends included), read
    exactly (certify.cli.options) and rounded to float64 for the engines."""
    import numpy as np
    return np.array([float(x) for x in float64_r(r_grid(*args.r_range) if args.r_range is not None else args.r)])


def float64_r(rs):
    """The exact r that the float64 simulator tells from 1 (UsageError for the others, as
    1 - 10^-17, which rounds to 1.0)."""
    for x in rs:
        if float(x) >= 1:
            raise UsageError(f"r = {x} rounds to 1.0 in float64, the simulator's numbers: use r ≤ 1 - 2^-53")
    return rs


def initial_data(args):
    """(θ0, φ0): paired from ``--theta0`` and ``--phi0`` (θ0 in [0, π/2], φ0 in [0, π]),
    else the first ``--orbits`` of the tool's grid of 8 initial data."""
    import math

    import numpy as np

    from certify import numerics
    if args.theta0 is None and args.phi0 is None:
        return numerics.grid(args.orbits if args.orbits is not None else 8)
    if args.theta0 is None or args.phi0 is None:
        raise UsageError("--theta0 and --phi0 go together (one φ0 per θ0)")
    if args.orbits is not None:
        raise UsageError("--orbits chooses from the tool's grid of initial data: not with --theta0/--phi0")
    if len(args.theta0) != len(args.phi0):
        raise UsageError(f"--theta0 has {len(args.theta0)} value(s), --phi0 {len(args.phi0)}: they are paired")
    for name, values, top, text in (("theta0", args.theta0, math.pi / 2, "π/2"), ("phi0", args.phi0, math.pi, "π")):
        bad = [x for x in values if not 0 <= x <= top]
        if bad:
            raise UsageError(f"--{name} must lie in [0, {text}], got {float(bad[0]):g}")
    return np.array(args.theta0, dtype=float), np.array(args.phi0, dtype=float)


def cmd_simulate(args) -> int:
    """Iterate the reduction map from the tool's grid of 8 initial data (or the given
    ones) for every r; ``--particles 5``: the five-particle reduction (:func:`simulate_five`)."""
    from certify import numerics
    if args.particles == 5:
        return simulate_five(args)
    if args.seed is not None:
        raise UsageError("--seed chooses the random data of --particles 5; four particles start on the tool's grid")
    r = r_values(args)
    theta0, phi0 = initial_data(args)
    if args.out is not None:
        ensure_writable_file(args.out, "--out")
    if args.dps is not None and args.engine == "float64":
        raise UsageError("--dps is for the mp and ball engines")
    if args.words and args.out is None:
        raise UsageError("--words stores the words in --out FILE.npz: give --out")
    with executors.executor(args.jobs, args.scheduler) if args.engine != "float64" else nullcontext() as ex:
        orbits = numerics.iterate(r, theta0, phi0, collisions=args.collisions,
                                   keep=args.keep if args.keep is not None else 500,
                                   engine=args.engine, dps=args.dps, executor=ex, progress=progress.Bar("r"),
                                   strict=args.strict, words=args.words)
    return _save_and_summarise(orbits, args.out)


def _save_and_summarise(orbits, out) -> int:
    """Write the orbits to ``out`` (atomically) when given, then print their summary."""
    if out is not None:
        with atomic_path(out) as tmp, open(tmp, "wb") as handle:
            orbits.save(handle)
        print(f"wrote {out}")
    print(orbits.summary())
    return 0


FIVE_REFUSED = (("theta0", "--theta0"), ("phi0", "--phi0"), ("dps", "--dps"), ("keep", "--keep"),
                ("jobs", "--jobs"), ("scheduler", "--scheduler"))


def simulate_five(args) -> int:
    """``simulate --particles 5``: the five-particle reduction (certify.numerics.five_reduction) on the
    float64 engine from ``--orbits N`` seeded random states on face b (``--seed``), every r."""
    from certify.numerics import five_reduction as five
    for name, option in FIVE_REFUSED:
        if getattr(args, name) is not None:
            raise UsageError(f"{option} is for four particles; five start from --orbits N random states (--seed S)")
    if args.engine != "float64":
        raise UsageError("five particles run on the float64 engine only (--engine float64)")
    if args.out is not None:
        ensure_writable_file(args.out, "--out")
    if args.words and args.out is None:
        raise UsageError("--words stores the words in --out FILE.npz: give --out")
    p0, q0 = five.random_data(args.orbits if args.orbits is not None else 8, args.seed or 0)
    orbits = five.iterate(r_values(args), p0, q0, collisions=args.collisions, strict=args.strict,
                          words=args.words, progress=progress.Bar("r"))
    return _save_and_summarise(orbits, args.out)


def cmd_stress(args) -> int:
    """Near-singular, long and random orbits on every engine: reports/STRESS.md."""
    from certify.numerics import stress
    ensure_writable_file(args.out, "--out")
    spec = stress.RANDOM_QUICK if args.quick else stress.RANDOM
    keep_larger(args.out, "stress report", committed_stress(args.out),
                {"random orbits": spec["count"], "collisions each": spec["collisions"]}, args.force, "--out FILE")
    with executors.executor(args.jobs) as ex:
        text, silent = stress.report(quick=args.quick, progress=progress.Bar("orbit"), executor=ex)
    write_atomic(args.out, text)
    print(f"wrote {args.out}: {silent} silent wrong collision(s)")
    return 1 if silent else 0

def committed_stress(path: Path) -> dict | None:
    """The size of the stress report already at ``path`` (its random orbits and their
    collisions, from its heading), or None."""
    import re
    found = re.search(r"^## (\d+) random orbits, (\d+) collisions each$", read_text_or_none(path) or "", re.M)
    return {"random orbits": int(found[1]), "collisions each": int(found[2])} if found else None


FIGURE_DPI = {"preview": None, "paper": 150}


def points_share(every: int | None):
    """The share of the r of a figure whose plotted points are certified (--certify-points
    EVERY: 1/EVERY; none: 0), a measure of the paper figures' size for keep_larger."""
    from fractions import Fraction
    return Fraction(1, every) if every else Fraction(0)


def committed_figures(out: Path) -> tuple[dict | None, dict | None]:
    """The sizes of the findings already in OUT: the paper figures (the share of r with
    certified points, numerics-paper.json) and the N4 search (its largest n,
    numerics-n4.json); None for a file absent or unreadable."""
    paper, n4 = load_findings("numerics-paper.json", out), load_findings("numerics-n4.json", out)
    try:
        every = {(f.get("points") or {}).get("every") for k, f in (paper or {}).items() if k.startswith("5.")}
        share = None if not every else {"share of r with certified points": min(points_share(e) for e in every)}
    except (AttributeError, TypeError, ValueError, ZeroDivisionError):
        share = None
    try:
        largest = {"largest n searched": max(int(n) for n in n4["ns"])} if n4 else None
    except (KeyError, TypeError, ValueError):
        largest = None
    return share, largest


def cmd_figures(args) -> int:
    """Figures 5.1-5.8 at ``--resolution`` into DIR/figures (``fig5.2-paper.png``); at the
    paper's resolution also DIR/numerics-paper.json, the findings N2-N7 quote; with
    ``--n4 NMAX`` the windows of (ab)^n(cb)^n up to n = NMAX (mp), DIR/numerics-n4.json."""
    from certify import numerics
    from certify.run import plots
    unknown = [f for f in args.only or () if f not in numerics.SPECS]
    if unknown:
        raise UsageError(f"unknown figure {unknown[0]!r} (one of {', '.join(numerics.SPECS)})")
    out = prepare_output(args.out)
    paper, n4 = committed_figures(out)
    if args.n4 is not None:
        keep_larger(out / "numerics-n4.json", "N4 search", n4, {"largest n searched": args.n4}, args.force)
    if args.resolution == "paper":
        keep_larger(out / "numerics-paper.json", "set of paper figures", paper,
                    {"share of r with certified points": points_share(args.certify_points)}, args.force)
    if args.n4 is not None:
        with executors.executor(args.jobs) as ex:                      # one n per job
            found = numerics.n4_search(args.n4, progress=progress.Bar("n"), executor=ex if args.jobs > 1 else None)
        write_findings(out / "numerics-n4.json", found)
        print(f"N4: largest n with 2n accumulation points (mp): {found['largest_n_mp']}; "
              f"float64: {found['largest_n_float64']}; {found['seconds']} s; wrote {out / 'numerics-n4.json'}")
        if not args.only and args.resolution is None:
            return 0
    resolution = args.resolution or "preview"
    datas, names, points = {}, [], {}
    with saving.output_dir(out / "figures"):
        for fig in args.only or numerics.SPECS:
            datas[fig] = numerics.compute(fig, resolution, progress=progress.Bar(f"figure {fig}"))
            if args.certify_points is not None:
                datas[fig].extra["points"] = points[fig] = certified_points(fig, datas[fig], args, points)
            names.append(plots.section5_figure(datas[fig], dpi=FIGURE_DPI[resolution]))
            print(f"figure {fig}: {len(datas[fig].r)} values of r, {int((datas[fig].breaks != 0).sum())} breaks, "
                  f"{datas[fig].seconds:.1f} s -> {out / 'figures' / names[-1]}")
            if fig in points:
                print("  " + points_line(points[fig]))
    if resolution == "paper" and not args.only:
        found = numerics.findings(datas)
        for fig, summary in points.items():
            found[fig]["points"] = summary
        write_findings(out / "numerics-paper.json", found)
        print(f"wrote {out / 'numerics-paper.json'}")
    return 0


_CERTIFIED_RUNS: dict = {}


def certified_points(fig: str, data, args, done: dict) -> dict:
    """``figures --certify-points EVERY``: the plotted points of figure ``fig`` certified
    (certify.run.figure_points) on every EVERY-th r of its run; a magnification reuses its
    source's certification, restricted to its range of r."""
    from certify import numerics
    from certify.run import figure_points
    spec = numerics.SPECS[fig]
    source = spec.source or fig
    if source not in _CERTIFIED_RUNS:
        run = data if spec.source is None else numerics.compute(source, data.resolution)
        with executors.executor(args.jobs) as ex:
            _CERTIFIED_RUNS[source] = figure_points.certify_figure(
                run, args.certify_points, executor=ex if args.jobs != 1 else None,
                progress=progress.Bar(f"points {source}"))
    lo, hi = (spec.lo, spec.hi) if spec.source is not None else (None, None)
    return figure_points.summary(_CERTIFIED_RUNS[source], lo, hi)


def points_line(s: dict) -> str:
    """One line: the certified fraction of the plotted points (all; r > 3−2√2)."""
    def part(x):
        return f"{x['certified']}/{x['points']} ({x['fraction']:.2%})" if x["points"] else "none"
    return (f"certified points: {part(s['all'])} on {s['r_values']} values of r (every {s['every']}); "
            f"for r > 3−2√2: {part(s['above_3-2sqrt2'])}; classes {s['classes']}; {s['seconds']} s")


def cmd_identify(args) -> int:
    """Classify each orbit: island, attracting periodic (its word certified for ever) or
    unresolved; one line per orbit, or JSON with --json (certify.run.identify)."""
    from certify.run import identify as ident
    from certify.run.progress import Bar
    if args.section5:
        return section5_findings(args)
    if args.out is not None:
        raise UsageError("--out goes with --section5 (the findings file); without it identify prints")
    if (args.r is None) == (args.r_range is None):
        raise UsageError("give --r R [R ...] or --r-range LO HI COUNT")
    rs = float64_r([r_value(x, "--r") for x in args.r] if args.r is not None else r_grid(*args.r_range))
    found = ident.identify(rs, orbits=args.orbits, collisions=args.collisions, windows=args.windows,
                           progress=Bar("orbit"))
    if args.json:
        print(ident.json_text(found))
    else:
        for x in found:
            print(x.line())
    return 0


def section5_findings(args) -> int:
    """``identify --section5``: the plan of certify.run.section5_orbits, written to
    DIR/section5-orbits.json (the findings the certificates N2, N5, N6 re-certify)."""
    from certify.run import section5_orbits
    if args.r is not None or args.r_range is not None or args.json:
        raise UsageError("--section5 runs its own plan of r (certify.run.section5_orbits.PLAN): "
                         "not with --r, --r-range or --json")
    out = ensure_writable(args.out if args.out is not None else DEFAULT_OUT)
    from certify.run.progress import Bar
    found = section5_orbits.findings(progress=Bar("r"))
    print(f"wrote {section5_orbits.write(found, out)}")
    return 0


def register(commands) -> None:
    """The parsers of ``simulate``, ``identify``, ``stress`` and ``figures``."""
    from certify.numerics.engines import ENGINES
    p = add_command(commands, "simulate", cmd_simulate, help="iterate the reduction map numerically (Section 5)",
                    description="The spherical billiard reduction iterated from collision to "
                    "collision from the tool's grid of 8 initial data (θ0, φ0) at a b-contact (the paper does not "
                    "print its own); "
                    "keeps the φ of the last b-collisions.  Breaks: 1 undecided contact "
                    "(|cos φ| below the rounding bound), 2 time step below precision, "
                    "3 corner, 4 non-finite, 5 certified horizon (--strict).  Every orbit reports "
                    "the collisions it certifies (float64, mp: an accumulated rigorous error bound; "
                    "ball: all).")
    which = p.add_mutually_exclusive_group(required=True)
    which.add_argument("--r", nargs="+", type=restitution, metavar="R",
                       help="restitution coefficients in ]0,1[ (3/10, 0.3, 1e-1)")
    which.add_argument("--r-range", nargs=3, metavar=("LO", "HI", "COUNT"),
                       help="COUNT values from LO to HI, ends included (paper Figure 6: 0.072 0.999 3709)")
    p.add_argument("--orbits", type=positive_int, default=None, metavar="N",
                   help="initial data per r: the first N of the tool's grid, 2 θ0 × 4 φ0 (default: 8; N > 8 adds "
                        "finer φ0, a superset of the eight)")
    p.add_argument("--theta0", nargs="+", type=number, metavar="T",
                   help="initial θ0 in [0, π/2], paired with --phi0 (instead of the grid)")
    p.add_argument("--phi0", nargs="+", type=number, metavar="P", help="initial φ0 in [0, π], one per --theta0")
    p.add_argument("--strict", action="store_true",
                   help="stop each orbit at its certified horizon (break 5); without it float64 and mp orbits "
                        "go on past it and --out's `certified` says how far they are proven")
    p.add_argument("--words", action="store_true",
                   help="also store each orbit's collision word in --out (an array `word` of strings)")
    p.add_argument("--collisions", type=positive_int, default=10_000, metavar="N",
                   help="collisions per orbit (default: 10^4)")
    p.add_argument("--keep", type=positive_int, default=None, metavar="N",
                   help="keep the φ of the last N b-collisions (default: 500; four particles)")
    p.add_argument("--particles", type=int, choices=(4, 5), default=4,
                   help="4: the paper's reduction; 5: the five-particle reduction on Gr⁺(2,4) ≅ S² × S² "
                        "(docs/particles.md; float64 only, from --orbits N random states on face b, --seed S; --out "
                        "stores r, p0, q0, breaks, collisions, certified, face, omega, angles [, word])")
    p.add_argument("--seed", type=int, default=None, metavar="S",
                   help="the seed of the random initial states of --particles 5 (default 0)")
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

    p = add_command(commands, "identify", cmd_identify,
                    help="classify each orbit: island (quasi-periodic, proved), attracting periodic (its word "
                         "certified for ever) or unresolved",
                    description="For each r and initial datum (the tool's grid of 8 initial data by default: the "
                    "paper does not print its own), one class: island (its state at b after some collision, in arb "
                    "balls from the datum, lies in the island U_r = {Q < c_max}: quasi-periodic for ever, the island "
                    "theorem); attracting periodic (the float64 run settles on a word w, orbit_at decides exactly "
                    "that w has an attracting periodic orbit at r, a trapping ellipse U of w is certified, and the "
                    "rigorous orbit enters U: it follows w for ever, certified); or unresolved (what the float64 run "
                    "shows, observed).  Each proof is re-checked by a second route; certified_from is the collision "
                    "from which the proof holds.")
    p.add_argument("--r", nargs="+", default=None, metavar="R", help="values of r (exact rationals: 0.3 is 3/10)")
    p.add_argument("--r-range", nargs=3, default=None, metavar=("LO", "HI", "COUNT"),
                   help="COUNT equally spaced r from LO to HI, ends included")
    p.add_argument("--orbits", type=positive_int, default=8, metavar="N",
                   help="the first N initial data of the tool's grid (default 8, the tool's eight; "
                        "N > 8 adds finer φ0, a superset of the eight)")
    p.add_argument("--collisions", type=positive_int, default=100_000, metavar="N",
                   help="collisions of the float64 run and of the rigorous scan, per orbit (default: 100000); "
                        "periods up to N/8 are searched")
    p.add_argument("--windows", action="store_true",
                   help="also give the attracting window over ]0, 1[ of each word of at most 24 letters (certify "
                        "orbit; slower, not needed by the classification)")
    p.add_argument("--json", action="store_true",
                   help="print JSON (certify/schemas/identify.schema.json): each orbit with r, theta0, phi0, class, "
                        "certified_from, word, word_status (certified | observed), why")
    p.add_argument("--section5", action="store_true",
                   help="run the plan of Section 5 (N2 near r = 1 and 0.2-0.9, N5, N6; 10^5 collisions near 1) on the "
                        "tool's grid of 8 initial data and write DIR/section5-orbits.json (no timing), the findings "
                        "the certificates re-certify")
    p.add_argument("--out", type=Path, default=None, metavar="DIR",
                   help="with --section5: the output directory (default: reports)")

    p = add_command(commands, "stress", cmd_stress, help="stress the numerical engines against the certified one",
                    description="Near-singular data, 1000 seeded random orbits of 2000 collisions over "
                    "the whole r range and long orbits, on float64 and mp against the certified ball "
                    "engine: certified horizons, departures, silent wrong collisions (exit 1 if any).")
    p.add_argument("--out", type=Path, default=DEFAULT_STRESS, metavar="FILE",
                   help="the report (default: reports/STRESS.md)")
    p.add_argument("--quick", action="store_true", help="smaller cases (a smoke test): 40 random orbits of 300")
    p.add_argument("--force", action="store_true",
                   help="replace a report of more random orbits already at FILE (refused without it)")
    p.add_argument("--jobs", type=positive_int, default=None, metavar="N",
                   help="processes for the random orbits (default: all cores)")

    p = add_command(commands, "figures", cmd_figures, help="draw Figures 6-11 of the paper, Section 5 (ids 5.1-5.8)",
                    description="Figures 6-11 of the paper (Section 5; our ids 5.1-5.8: 5.1 = Figure 6, 5.2 = 7, "
                    "5.3a/b = 8a/b, "
                    "5.4 = 9, 5.5 = 10, 5.6-5.8 = 11a-c): the last kept b-angles φ of the tool's 8 "
                    "orbits against r (float64), breaks as red dots at (r, π/2), the CDKK thresholds as red "
                    "lines.  preview: the cheap version `certify all` draws; paper: the captions' grids, "
                    "10^4 collisions, 500 kept (about a minute on two cores).")
    p.add_argument("--resolution", choices=("preview", "paper"), default=None,
                   help="preview (default) or the paper's parameters")
    p.add_argument("--only", nargs="+", metavar="FIG", help="only these figures, e.g. 5.2 5.3a")
    p.add_argument("--certify-points", type=positive_int, default=None, metavar="EVERY",
                   help="certify the plotted points on every EVERY-th r (1: all): each point within a pixel of "
                        "the true orbit, proved through the island or a certified trap (certify.run.figure_points); "
                        "the fractions in the captions and numerics-paper.json")
    p.add_argument("--n4", type=positive_int, default=None, metavar="NMAX",
                   help="find the windows of (ab)^n(cb)^n up to n = NMAX with the mp engine (minutes)")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, metavar="DIR", help="output directory (default: reports)")
    p.add_argument("--force", action="store_true",
                   help="replace findings of a larger search (--n4) or of more certified points (paper) already in "
                        "DIR (refused without it)")
    add_jobs(p)
