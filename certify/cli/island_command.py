"""The command ``island``: the island theorem of :mod:`certify.patterns.island_theorem` at
rational values of r, with the rotation number, the island's share of the b-section and
the resonances.  (The module is not named ``island``: :mod:`certify.dynamics.island` holds
that name, and one name under ``certify/`` is one module.)

    island (--r R | --r-range LO HI [COUNT]) [--json] [--resonances Q] [--symbolic] [--depth D]
    island --resonances Q [--json]
"""
from __future__ import annotations

import json

import flint

from certify.errors import UsageError
from certify.run import census_report, progress

from .options import add_command, integer, positive_int, r_grid, restitution

MAX_RESONANCE_Q = 60          # --resonances: the degrees grow like φ(q)/2
MAX_DEPTH = 14                # --depth: 4^depth boxes at worst
MAX_COUNT = 1000              # --r-range COUNT


def r_list(args) -> list:
    """The exact rationals of ``--r`` or ``--r-range LO HI [COUNT]`` (COUNT values, ends
    included, default 5), read by the one syntax of numbers (certify.cli.options)."""
    if args.r is not None:
        return [flint.fmpq(args.r.numerator, args.r.denominator)]
    if len(args.r_range) not in (2, 3):
        raise UsageError("--r-range takes LO HI [COUNT]")
    count = args.r_range[2] if len(args.r_range) == 3 else "5"
    if integer(count, "--r-range COUNT") > MAX_COUNT:
        raise UsageError(f"--r-range COUNT must lie in 1..{MAX_COUNT}, not {count}")
    return [flint.fmpq(x.numerator, x.denominator) for x in r_grid(args.r_range[0], args.r_range[1], count)]


def cmd_island(args) -> int:
    """The island theorem at each r (text or JSON); the resonances with --resonances."""
    from certify.patterns import island_theorem as it
    if args.r is None and args.r_range is None and args.resonances is None and not args.symbolic:
        raise UsageError("island: give --r R, --r-range LO HI [COUNT], --resonances Q or --symbolic")
    if args.resonances is not None and args.resonances > MAX_RESONANCE_Q:
        raise UsageError(f"--resonances is at most {MAX_RESONANCE_Q}")
    if args.depth > MAX_DEPTH:
        raise UsageError(f"--depth is at most {MAX_DEPTH}")
    rs = r_list(args) if args.r is not None or args.r_range is not None else []
    if args.figure is not None:
        from certify.run.files import ensure_writable_file
        ensure_writable_file(args.figure, "--figure")
    bar = progress.Bar("r")
    records = []
    for k, r in enumerate(rs):
        records.append(it.report(r, depth=args.depth))
        if len(rs) > 1:
            bar(k + 1, len(rs), str(r))
    doc: dict = {"schema": "certify-island", "version": 1}
    doc.update(records[0] if args.r is not None else {"islands": records} if rs else {})
    if args.resonances is not None:
        doc["resonances"] = [s.as_json() for s in it.resonances(args.resonances)]
        committed = census_report.committed_windows()
        windows = None if committed is None else committed[0]
        if windows is not None:
            doc["window_resonances"] = [{"word": w, "end": side, "digits": d, "p": p, "q": q}
                                        for w, side, d, (p, q) in it.window_resonances(windows, args.resonances)]
    if args.symbolic:
        T = it.symbolic_theorem()
        doc["symbolic"] = {"interval": "]3-2√2, 1[", "holds": T.holds, "c_max": str(T.c_max),
                           "steps": [{"name": s.name, "holds": s.holds, "evidence": s.evidence} for s in T.steps]}
    if args.figure is not None:
        from certify.run import island_figures
        island_figures.island_figure(args.figure, rs[0] if rs else None, args.resonances or 12)
    print(json.dumps(doc, indent=2, ensure_ascii=False) if args.json else "\n".join(text_lines(doc)))
    return 0


def text_lines(doc: dict):
    """The text output: each theorem's steps with ✓/✗ and evidence, then the numbers."""
    records = doc["islands"] if "islands" in doc else ([doc] if "r" in doc else [])
    for rec in records:
        yield f"island theorem at r = {rec['r']}: {verdict(rec)}"
        yield from _steps(rec["steps"])
        if rec["elliptic"]:
            rho = rec["rotation_number"]
            f = rec["island_fraction"]
            yield f"  c_max = {rec['c_max']}"
            yield f"  rotation number ρ = {rho['value']} ({rho['digits']} digits, certified)"
            yield f"    convention: {rho['convention']}"
            qp = "yes, proved: every orbit in U_r is dense on its ellipse" if rec["quasi_periodic"] else "not proved"
            yield f"  quasi-periodic: {qp}"
            yield (f"  island fraction of the b-section: in [{f['lo']}, {f['hi']}] "
                   f"≈ [{_float(f['lo']):.4f}, {_float(f['hi']):.4f}] (certified, depth {f['depth']})")
        else:
            yield "  not elliptic: no island, no quasi-periodic orbits from this theorem"
    if "symbolic" in doc:
        s = doc["symbolic"]
        yield f"island theorem for r a symbol on {s['interval']}: {'proved' if s['holds'] else 'REFUSED'}"
        yield from _steps(s["steps"])
        yield f"  c_max = {s['c_max']}"
    if "resonances" in doc:
        yield f"resonances in ]3-2√2, 1[ (rotation number p/q): {len(doc['resonances'])}"
        for x in doc["resonances"]:
            lo, hi = x["isolating_interval"]
            yield f"  ρ = {x['p']}/{x['q']}: r ≈ {x['digits']}, root of {x['minimal_polynomial']} in ]{lo}, {hi}["
    if "window_resonances" in doc:
        from certify.patterns import island_theorem
        yield "ends of the census's attracting windows that are resonances (the same algebraic number):"
        for x in doc["window_resonances"]:
            yield f"  {x['word']}: {island_theorem.resonance_phrase(x['end'], x['digits'], x['p'], x['q'])}"


def verdict(rec: dict) -> str:
    """What the island theorem proved at r, in a few words: an island, or (A not elliptic)
    that this theorem gives none."""
    if not rec["holds"]:
        return "REFUSED"
    if not rec["elliptic"]:
        return "proved, in its other case: A(r) is not elliptic (r² − 6r + 1 ≥ 0), so no island at this r"
    return "proved: an island of " + ("quasi-periodic orbits" if rec["quasi_periodic"] else "invariant ellipses") + \
        " around [ac]b"


def _steps(steps):
    for s in steps:
        yield f"  {'✓' if s['holds'] else '✗'} {s['name']}"
        yield f"      {s['evidence']}"


def _float(text: str) -> float:
    from fractions import Fraction
    return float(Fraction(text))


def register(commands) -> None:
    """The parser of ``island``."""
    p = add_command(commands, "island", cmd_island,
                    help="the elliptic island around [ac]b: quasi-periodic orbits, proved",
                    description="The island theorem at each rational r, every step certified exactly: "
                    "K_a K_c = K_c K_a; the branch region R from the reduction's sign rules; the b-to-b map "
                    "A(r) on R, det A = 1, elliptic iff r² − 6r + 1 < 0; Q∘A = Q; the island {Q < c_max} "
                    "inside R; e^{iθ} not a root of unity, so every orbit in the island is quasi-periodic.  "
                    "With the rotation number (certified digits) and the island's share of the b-section.  "
                    "Numbers: 3/10 or 0.3 (exact).")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--r", type=restitution, default=None, metavar="R",
                   help="a rational restitution coefficient in ]0,1[")
    g.add_argument("--r-range", nargs="+", default=None, metavar="LO HI [COUNT]",
                   help="COUNT rationals from LO to HI, ends included (default COUNT 5)")
    p.add_argument("--json", action="store_true", help="print JSON (certify/patterns/island.schema.json)")
    p.add_argument("--resonances", type=positive_int, default=None, metavar="Q",
                   help="also list every r in ]3-2√2, 1[ with rotation number p/q, q <= Q")
    p.add_argument("--symbolic", action="store_true",
                   help="also prove the theorem for r a symbol on ]3-2√2, 1[")
    p.add_argument("--depth", type=positive_int, default=10, metavar="D",
                   help=f"bisection depth of the island fraction (default 10; at most {MAX_DEPTH})")
    p.add_argument("--figure", default=None, metavar="PATH",
                   help="also draw the b-section with the island and the rotation number against r into PATH")
