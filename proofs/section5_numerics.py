"""Section 5, the numerical simulations (l. 1053-1210): N1-N7, observed, never proven.

Each certificate reads the numbers and words printed in the paper (``printed=``),
runs the float64 engine (certify.numerics) at the *preview* resolution of the figures
(a regular sub-grid of the paper's r values, 2000 collisions, the last 200 b-angles)
plus a few probes with the paper's lengths (10^4 collisions, 500 kept), and says
whether what it sees agrees with the print (:func:`certify.run.observe`: status
OBSERVED with "agrees" / "does not agree").  The figures at the paper's resolution
are drawn by ``python -m certify figures --resolution paper``, which also writes
``reports/numerics-paper.json``; ``--n4 NMAX`` writes ``reports/numerics-n4.json``.
The certificates quote those committed findings in their notes.

Floats decide nothing here: an accumulation-point count is a count of clusters of
kept angles (gap 10^-3 rad, each narrower than 10^-6 rad), an observation with its
tolerances stated (certify.numerics.limits).
"""
from __future__ import annotations

import math

import flint
import numpy as np
import sympy as sp

import certify.numerics as F
from certify.algebra import Algebraic, Q, radical
from certify.numerics import BREAKS, paper_grid
from certify.patterns import island_theorem as island
from certify.run import (
    EXPLANATION,
    OBSERVED,
    PASS,
    Check,
    certificate,
    committed,
    committed_windows,
    conclude,
    explanations,
    island_figure,
    load_findings,
    observe,
    overridden,
    quantity,
    replaced,
    section5_figure,
)

PAPER_FINDINGS = "numerics-paper.json"
ORBIT_FINDINGS = "section5-orbits.json"   # `certify identify --section5`: the periodic orbits behind N2, N5, N6
N4_FINDINGS = "numerics-n4.json"


def number(text) -> float:
    """A printed number: ``10^4``, ``5\\times 10^2``, ``2.5e-4``, ``0.072``."""
    t = str(text).replace("\\times", "*").replace("×", "*").replace("^", "**").replace(" ", "")
    if not all(ch in "0123456789.*e-+" for ch in t):
        raise ValueError(f"cannot read the printed number {text!r}")
    return float(eval(t, {"__builtins__": {}}, {}))  # digits and * ** only (checked above)


@quantity("float64_engine")
def float64_engine():
    """The float64 engine started (numba imported, its compiled sweep loaded: about 0.5 s, once
    per process).  What needs it runs in one process: the preview runs below and N4's probe."""
    F.load_float64()
    return "float64"


@quantity("section5_preview", needs=("float64_engine",))
def section5_preview(float64_engine):
    """The preview runs of Figures 5.1-5.8 (float64), one run per figure (magnifications reuse 5.2)."""
    return {fig: F.compute(fig, "preview", engine=float64_engine) for fig in F.SPECS}


def paper_note(key: str, render) -> str:
    """The committed paper-resolution finding ``key``, rendered, or a pointer to the command."""
    found = load_findings(PAPER_FINDINGS)
    if not found or key not in found:
        return ("Paper resolution: not computed in this checkout (run `python -m certify figures "
                "--resolution paper`).")
    return "Paper resolution (`certify figures --resolution paper`, committed in reports/numerics-paper.json): " \
        + render(found[key])


def figure_links(*figs: str) -> str:
    """Links to the committed paper-resolution PNGs."""
    return " Figures at the paper's resolution: " + ", ".join(
        f"[{F.cite(f)}](figures/fig{f}-paper.png)" for f in figs) + "."


# --------------------------------------------------------------------------
# N1: the setup

PRINTED_N1 = dict(
    collisions="10^4", kept="5\\times 10^2", theta_values="2", phi_values="4",
    velocity=("cos(theta)*cos(phi)", "sin(phi)", "-sin(theta)*cos(phi)"),
    breaks=("the difference between two collision times becomes smaller than the computer precision",
            "|cos(phi)| is smaller than the computer precision"),
)


@certificate("N1", printed=PRINTED_N1,
             expect=OBSERVED,
             mutants=[replaced("collisions", "10^4", "10^3", "fewer collisions computed"),
                      overridden({"velocity": ("cos(theta)*cos(phi)", "cos(phi)", "-sin(theta)*cos(phi)")}, "another component of q(b_n)")])
def setup(collisions, kept, theta_values, phi_values, velocity, breaks):
    """The figures' parameters are the printed ones; the engine's φ is the printed φ; its
    break rules are the printed two (and two more that the print does not need)."""
    theta0, phi0 = paper_grid()
    checks = [
        Check(f"the figures at the paper's resolution run to the {collisions}-th collision",
              F.PAPER["collisions"] == number(collisions), [f"certify.numerics.figures.PAPER = {F.PAPER}"], ref="N1.1"),
        Check(f"they keep the last {kept} b-collisions", F.PAPER["keep"] == number(kept), ref="N1.2"),
        Check(f"the orbits of a figure are a regular grid of {theta_values} values of θ0 × {phi_values} of φ0",
              len(set(np.round(theta0, 12))) == number(theta_values) and len(set(np.round(phi0, 12))) == number(phi_values)
              and len(theta0) == number(theta_values) * number(phi_values),
              [f"θ0 = {', '.join(f'{t:.6f}' for t in sorted(set(np.round(theta0, 6))))}, φ0 = "
               f"{', '.join(f'{t:.6f}' for t in sorted(set(np.round(phi0, 6))))} (paper_grid; the "
               "paper does not print its grid)"], ref="N1.3"),
    ]
    # the φ the engine keeps is the φ of the printed velocity q(b_n)
    env = {"cos": math.cos, "sin": math.sin}
    worst, samples = 0.0, [(0.3, 0.4), (1.1, 2.5), (0.7, 1.6), (1.4, 0.05), (0.2, 3.0)]
    for theta, phi in samples:
        p = (math.sin(theta), 0.0, math.cos(theta))            # p(b_n) at contact b (l. 894)
        q = tuple(eval(e, {"__builtins__": {}}, {**env, "theta": theta, "phi": phi}) for e in velocity)
        worst = max(worst, abs(F.phi_at_b(p, q) - phi))
    checks.append(Check(f"the angle the engine keeps is the φ of q(b_n) = ({', '.join(velocity)})", worst < 1e-12,
                        [f"largest |φ_engine − φ| over {len(samples)} states: {worst:.1e}"], ref="N1.4"))
    names = list(BREAKS.values())
    rules = {"time": any("time step" in b for b in names), "cos": any("cos φ" in b for b in names)}
    printed_rules = [("time" if "collision times" in b else "cos" if "cos" in b else None) for b in breaks]
    checks.append(Check("the engine breaks on each printed rule: " + "; ".join(breaks),
                        all(k is not None and rules[k] for k in printed_rules),
                        ["the engine's break codes: " + "; ".join(f"{c}: {b}" for c, b in BREAKS.items())], ref="N1.5"))
    return observe(checks, note="The paper does not print its 8 initial data; the tool's grid of 8: θ0 ∈ {π/6, π/3}, "
                                "φ0 ∈ {π/5, 2π/5, 3π/5, 4π/5} at contact b.")


# --------------------------------------------------------------------------
# N2: Figure 6 (fig:Simul_1), our id 5.1

PRINTED_N2 = dict(lo="0.072", hi="0.999", step="2.5\\times 10^{-4}", count="3709",
                  windows_below="0.17", chaos_until="0.9", discrete_near="1", segment_at="(0.08,\\pi/2)",
                  breaks_near="0.072", explained=ORBIT_FINDINGS)
NEAR = 0.001     # "close to the region r ≃ 0.072" (l. 1090): within 10^-3 of it, either side
SEGMENT = 0.005  # "a short horizontal segment ... around (0.08, π/2)" (l. 1089): breaks within 0.005 of 0.08


@certificate("N2", needs=("section5_preview",), printed=PRINTED_N2,
             expect="OBSERVED, disagrees",
             mutants=[overridden({"windows_below": "0.9"}, "the edge of the windows moved from 0.17 to 0.9"),
                      committed("explained", (ORBIT_FINDINGS, {"word": "abcb"}), "the committed word at r = 1/5 "
                                "replaced by abcb, repelling there"),
                      committed("explained", (ORBIT_FINDINGS, {"r": "1/10"}), "the committed r of the first word "
                                "moved to 1/10, outside its window")])
def figure_5_1(section5_preview, lo, hi, step, count, windows_below, chaos_until, discrete_near, segment_at,
               breaks_near, explained):
    """The preview of Figure 5.1, probes with the paper's lengths around the printed segment
    of breaks (l. 1089) and near r = 0.072 on both sides of the figure's lower end (l. 1090)."""
    lo_, hi_, step_, count_ = number(lo), number(hi), number(step.replace("{", "").replace("}", "")), number(count)
    below, until, near1, near_b = (number(x) for x in (windows_below, chaos_until, discrete_near, breaks_near))
    seg = number(segment_at.strip("()").split(",")[0])
    segment_at = segment_at.replace("\\pi", "π").replace(",", ", ")
    d = section5_preview["5.1"]
    spec = F.SPECS["5.1"]
    points_below = F.fraction(d, lo_, below, lambda w: w.discrete)
    points_above = F.fraction(d, below + 0.01, until, lambda w: w.discrete)
    spread = F.fraction(d, below + 0.01, until, lambda w: w.kind == "spread")
    top = F.fraction(d, near1 - 0.01, near1, lambda w: w.visually_discrete)
    edge = F.probe(np.linspace(lo_, lo_ + 0.0025, 11))
    around = F.probe(np.linspace(seg - SEGMENT, seg + SEGMENT, 11))
    breaks = np.concatenate([d.break_r(), edge.break_r(), around.break_r()])     # in the figure's range
    outside = F.probe(np.linspace(near_b - 0.0004, near_b - 0.0001, 7)).break_r()   # just below it
    on_segment = breaks[np.abs(breaks - seg) <= SEGMENT]
    seen = np.concatenate([breaks, outside])
    checks = [
        Check(f"the printed grid is consistent: {lo} + k·{step}, k < {count}, ends at {hi}",
              abs(lo_ + (count_ - 1) * step_ - hi_) < 1e-9 and spec.count == count_ and spec.lo == lo_ and spec.hi == hi_,
              [f"{lo} + ({count} − 1)·{step_:g} = {lo_ + (count_ - 1) * step_:.6f}"], ref="N2.1"),
        Check(f"windows of stability for r ≤ {windows_below}: the 8 orbits converge to finitely many points on a "
              f"good part (≥ 30 %) of the r values there, and on few (< 10 %) of those in [{below + 0.01:g}, {until:g}]",
              points_below[0] >= 0.3 and points_above[0] < 0.1,
              [f"finitely many points: {points_below[0]:.0%} of {points_below[1]} r in [{lo}, {windows_below}], "
               f"{points_above[0]:.0%} of {points_above[1]} r in [{below + 0.01:g}, {chaos_until}]"], ref="N2.2"),
        Check(f"apparent chaos up to r ≈ {chaos_until}: the orbits spread (more than {F.MAX_PIECES} clusters) for "
              f"most (≥ 70 %) r in [{below + 0.01:g}, {until:g}]", spread[0] >= 0.7,
              [f"spread at {spread[0]:.0%} of {spread[1]} values of r"], ref="N2.3"),
        Check(f"discrete ω-limit sets near r = {discrete_near}: in [{near1 - 0.01:g}, {near1:g}] every orbit's points "
              f"lie in at most {F.MAX_PIECES} clusters narrower than a pixel (π/1000)", top[1] > 0 and top[0] == 1.0,
              [f"{top[0]:.0%} of {top[1]} values of r"], ref="N2.4"),
        Check(f"l. 1089: a short segment of breaks around {segment_at}: the engine breaks at some r of the "
              f"figure's range within {SEGMENT} of {seg:g}", on_segment.size > 0,
              [f"{breaks.size} breaks in the figure's range (its preview; probes of 11 r in [{lo}, {lo_ + 0.0025:g}] "
               f"and 11 r in [{seg - SEGMENT:g}, {seg + SEGMENT:g}], 10^4 collisions)"
               + (f", at r in [{breaks.min():.5f}, {breaks.max():.5f}]" if breaks.size else "")], ref="N2.5"),
        Check(f"l. 1090: the breaks accumulate close to r ≃ {breaks_near}: the engine breaks, in the figure's range "
              f"or just below it, and every break lies within {NEAR} of {breaks_near}",
              seen.size > 0 and bool(np.all(np.abs(seen - near_b) <= NEAR)),
              [f"just below the figure's range, 7 values of r in [{near_b - 0.0004:g}, {near_b - 0.0001:g}] "
               f"(7 − 4√3 ≈ 0.071797): {outside.size} breaks of 56 orbits"
               + (f", at r ≤ {outside.max():.5f}" if outside.size else "")], ref="N2.6"),
    ]
    reason = (f"no break in the figure's range {lo} ≤ r ≤ {hi} (the paper's segment of breaks around {segment_at}, "
              "l. 1089, is not there); " + (f"the engine breaks only just below it, at r ≤ {outside.max():.4f} "
                                            f"(7 − 4√3 ≈ 0.07180), which is close to r ≃ {breaks_near} as l. 1090 says"
                                            if outside.size else f"nor just below {lo}")
              if not breaks.size else "")
    note = paper_note("5.1", lambda s: f"{s['r'][2]} values of r, {breaks_text(s['breaks'])}; ω-limits per "
                      "r: " + ", ".join(f"{v} {k}" for k, v in s["kinds"].items()) + "." + points_text(s)) \
        + figure_links("5.1")
    return observe(checks + explanations("N2", explained), figures=[section5_figure(d)], note=note, reason=reason)


def points_text(s: dict) -> str:
    """The certified fraction of the plotted points (`figures --certify-points`), when computed."""
    p = s.get("points")
    if not p or not p["all"]["points"]:
        return ""
    a, b = p["all"], p["above_3-2sqrt2"]
    return (f" Certified points (each within a pixel of the true orbit: island, certified trap or ball engine; "
            f"every {p['every']}th r): {a['fraction']:.2%} of {a['points']}"
            + (f", {b['fraction']:.2%} for r > 3−2√2" if b["points"] else "") + ".")


def breaks_text(b: dict) -> str:
    """``N breaks at r in [lo, hi]``, or ``no break``."""
    return f"{b['count']} breaks at r in [{b['r_min']}, {b['r_max']}]" if b.get("count") else "no break"


# --------------------------------------------------------------------------
# N3: Figure 7 (fig:Simul_2), our id 5.2, accumulation points per window

PRINTED_N3 = dict(lo="0.075", hi="0.192", step="2.5\\times 10^{-5}", count="4681",
                  points=("4", "6", "8", "10"), windows=("(ab)^2(cb)^2", "(ab)^3(cb)^3", "third", "fourth"))


@certificate("N3", needs=("section5_preview",), printed=PRINTED_N3,
             expect=OBSERVED,
             mutants=[overridden({"points": ("5", "6", "8", "10")}, "another number of points in the first window")])
def figure_5_2(section5_preview, lo, hi, step, count, points, windows):
    """Clusters of the kept φ of the 8 orbits, counted at each r of each window (from the
    next threshold of L4, or the lower end of L5, to the window's upper threshold)."""
    lo_, hi_, step_, count_ = number(lo), number(hi), number(step.replace("{", "").replace("}", "")), number(count)
    d = section5_preview["5.2"]
    probes = F.probe(F.n3_window_probes())
    stats = F.n3_stats(d, probes)
    checks = [Check(f"the printed grid is consistent: {lo} + k·{step}, k < {count}, ends at {hi}",
                    abs(lo_ + (count_ - 1) * step_ - hi_) < 1e-9 and F.SPECS["5.2"].count == count_, ref="N3.1")]
    for k, (n, want, name) in enumerate(zip((2, 3, 4, 5), points, windows)):
        s = stats[str(n)]
        checks.append(Check(f"{want} accumulation points in the {name} window (n = {n}, r in "
                            f"[{s['window'][0]:.5f}, {s['window'][1]:.5f}])",
                            s["count"] == int(number(want)),
                            [f"most frequent count {s['count']} at {s['shown_by']} of {s['of']} values of r; all counts "
                             f"(count: values of r; none = not finitely many points): {s['counts']}"],
                            ref=f"N3.{k + 2}"))
    note = paper_note("n3", lambda s: "; ".join(
        f"n = {n}: {v['count']} points at {v['shown_by']} of {v['of']} values of r" for n, v in s.items()) + ".") \
        + figure_links("5.2", "5.3a")
    return observe(checks, figures=[section5_figure(d), section5_figure(section5_preview["5.3a"])], note=note)


# --------------------------------------------------------------------------
# N4: below r ≈ 0.078, (ab)^n(cb)^n for n ≥ 6

PRINTED_N4 = dict(r_below="0.078", n_from="6", accumulate_above="7-4\\sqrt{3}")


@certificate("N4", printed=PRINTED_N4,
             needs=("float64_engine",), expect="OBSERVED, disagrees")
def below_0078(float64_engine, r_below, n_from, accumulate_above):
    """Our float64 engine at r just below r_max(n) for n = n_from..n_from+4 (8 orbits, 10^4
    collisions); the smallest component of the dominant eigenvector of M_w (mpmath); the
    committed mp search of ``certify figures --n4``."""
    n0 = int(number(n_from))
    committed = load_findings(N4_FINDINGS)
    ev, checks = [], []
    th = {n: F.r_max(n) for n in F.N_LINES}
    if committed:
        th.update({int(n): v["mp"]["r_max"] for n, v in committed["windows"].items()})
    missing = [n for n in range(n0, n0 + 6) if n not in th]
    for n in missing:
        th[n] = float(F.upper_threshold(n, 20))
    rs = [th[n] - 0.05 * (th[n] - th[n + 1]) for n in range(n0, n0 + 5)]
    d = F.probe(rs, engine=float64_engine)
    seen = {n: F.accumulation_points(d, int(np.argmin(np.abs(d.r - r)))) for n, r in zip(range(n0, n0 + 5), rs)}
    followed = [n for n in seen if seen[n] == 2 * n]
    checks.append(Check(f"a float64 program cannot follow (ab)^n(cb)^n for n ≥ {n_from} below r = {r_below}",
                        not followed,
                        ["our float64 engine (margin rule, rescaled normals), at r = r_max(n) − 5 % of the gap to "
                         "r_max(n+1): " + ", ".join(f"n = {n}: {seen[n]} points" for n in seen)], ref="N4.1"))
    r6 = th[n0] - 0.05 * (th[n0] - th[n0 + 1])
    small = F.min_component(n0, r6)
    checks.append(Check(f"at n = {n_from} the dominant eigenvector has a component below the float64 precision "
                        f"(2^-52 ≈ 2.2e-16, relative to its largest)", small < 2.0 ** -52,
                        [f"min |e_i| / max |e_i| = {small:.2e} at r = {r6:.10f} (mpmath, {F.digits_for(n0)} digits; M_w with "
                         f"w = (ab)^{n0}(cb)^{n0}, whose dominant eigenvector is that of J(BA)^n up to the order "
                         "of the product)"], ref="N4.2"))
    if committed:
        ns = [int(n) for n in committed["ns"]]
        found = [n for n in ns if committed["windows"][str(n)]["mp"]["found"]]
        rmax = [committed["windows"][str(n)]["mp"]["r_max"] for n in ns]
        below = [committed["windows"][str(n)].get("min_component") for n in ns]
        rcrit = 7 - 4 * math.sqrt(3)
        checks.append(Check(f"the windows exist beyond n = {n_from}: with enough digits (mp engine) the orbits "
                            "converge to 2n points and follow (ab)^n(cb)^n for every n tried",
                            found == ns, [f"n tried: {ns}; found: {found}; largest n: {committed['largest_n_mp']}"],
                            ref="N4.3"))
        checks.append(Check(f"they accumulate above {accumulate_above}: r_max(n) decreases to 7-4√3 ≈ {rcrit:.6f}, "
                            "staying above it", all(a > b > rcrit for a, b in zip(rmax, rmax[1:])),
                            [", ".join(f"r_max({n}) = {r:.10f}" for n, r in zip(ns, rmax))], ref="N4.4"))
        f64 = committed.get("largest_n_float64")
        ev.append(f"committed search (`certify figures --n4 {max(ns)}`): mp engine at "
                  f"40 + 1.5n digits, 2 orbits, max(10^4, 400n) collisions, r = r_max(n) − f (r_max(n) − r_max(n+1)) "
                  f"for f = 0.05, 0.2; float64 at the same r: largest n {f64}. Smallest relative component of the "
                  "dominant eigenvector: " + ", ".join(f"n = {n}: {c:.1e}" for n, c in zip(ns, below) if c))
    else:
        checks.append(Check("the windows exist beyond n = 6 (mp search)", False,
                            ["no committed search: run `python -m certify figures --n4 NMAX`"], ref="N4.3"))
        checks.append(Check(f"they accumulate above {accumulate_above} (mp search)", False,
                            ["no committed search: run `python -m certify figures --n4 NMAX`"], ref="N4.4"))
    f64 = committed.get("largest_n_float64") if committed else None
    note = ("The thresholds r_max(n) for n > 6 are computed numerically (mpmath: the root of q_2(0) = 0 for the "
            "dominant eigenvector of M_w, CLAIMS L6; for n = 2..6 they reproduce the printed values of L4). "
            "The printed n ≥ 6 is a property of the paper's program. Ours, in float64 with the same precision, "
            + (f"follows the pattern up to n = {f64} in the committed search, " if f64 else "")
            + "although the smallest component of the eigenvector is far below 2^-52 there: the normal is "
            "rescaled by powers of 2 and every sign is taken with a componentwise margin, so a small component "
            "keeps its relative accuracy. What limits a float program is the exponent range and the slow "
            "convergence of the orbit, not the 53-bit mantissa alone.")
    first_below = next((n for n, c in zip(ns, below) if c and c < 2.0 ** -52), None) if committed else None
    reason = (f"our float64 engine follows (ab)^n(cb)^n below r = {r_below} for n = {', '.join(map(str, followed))}"
              + (f" (up to n = {f64} in the committed search)" if f64 else "")
              + f"; and at n = {n_from} the smallest component of the eigenvector is {small:.1e}, far above 2^-52"
              + (f" (it first drops below at n = {first_below})" if first_below else "")
              + ": the printed cause does not hold")
    return observe(checks, evidence=ev, note=note, reason=reason if followed and small >= 2.0 ** -52 else "")


# --------------------------------------------------------------------------
# N5: the transitory region

PRINTED_N5 = dict(lo="0.172", hi="0.176", fig_lo="0.171", fig_hi="0.176", step="10^{-6}", count="5001",
                  explained=ORBIT_FINDINGS)


@certificate("N5", needs=("section5_preview",),
             printed=PRINTED_N5,
             expect=OBSERVED,
             mutants=[overridden({"lo": "0.181", "hi": "0.185"}, "the transitory region moved"),
                      committed("explained", (ORBIT_FINDINGS, {"word": "abcb"}), "a committed word replaced by abcb"),
                      committed("explained", (ORBIT_FINDINGS, {"r": "1/10"}), "the committed r of the first word moved "
                                "to 1/10, where its orbit is a saddle")])
def transitory(section5_preview, lo, hi, fig_lo, fig_hi, step, count, explained):
    """The kind of ω-limit of the 8 orbits at 21 values of r in the printed region and 9 just
    above it (10^4 collisions, 500 kept); the figures are the previews of 5.3b and 5.4."""
    lo_, hi_, flo, fhi = (number(x) for x in (lo, hi, fig_lo, fig_hi))
    step_, count_ = number(step.replace("{", "").replace("}", "")), number(count)
    d = section5_preview["5.4"]
    inside = F.probe(np.linspace(lo_, hi_, 21))
    above = F.probe(np.linspace(hi_ + 0.002, hi_ + 0.006, 9))
    finite = F.fraction(inside, lo_, hi_, lambda w: w.few_points)
    outside = F.fraction(above, hi_ + 0.002, hi_ + 0.006, lambda w: w.few_points)
    counts = sorted({w.clusters for w in F.per_r(inside) if w.few_points})
    checks = [
        Check(f"the printed grid is consistent: {fig_lo} + k·{step}, k < {count}, ends at {fig_hi}",
              abs(flo + (count_ - 1) * step_ - fhi) < 1e-9 and F.SPECS["5.4"].count == count_, ref="N5.1"),
        Check(f"for most r in [{lo}, {hi}] (≥ 50 %) the orbits accumulate on finitely many points (at most "
              f"{F.FEW} clusters, each narrower than a pixel, π/1000)",
              finite[0] >= 0.5, [f"{finite[0]:.0%} of {finite[1]} values of r; the numbers of points seen: {counts}"],
              ref="N5.2"),
        Check(f"the region is transitory: just above it ([{hi_ + 0.002:g}, {hi_ + 0.006:g}]) this is rare (< 20 %)",
              outside[0] < 0.2, [f"{outside[0]:.0%} of {outside[1]} values of r"], ref="N5.3"),
    ]
    note = paper_note("n5", lambda s: f"finitely many points at {s['finite']:.0%} of {s['of']} values of r in "
                      f"[0.172, 0.176]; the numbers of points seen: {s['counts']}.") + figure_links("5.3b", "5.4")
    return observe(checks + explanations("N5", explained),
                   figures=[section5_figure(section5_preview["5.3b"]), section5_figure(d)], note=note)


# --------------------------------------------------------------------------
# N6: thin stripes

PRINTED_N6 = dict(stripes=("0.1845", "0.1896"), special="0.184525", lo="0.1845", hi="0.1846", step="10^{-7}",
                  count="1001", explained=ORBIT_FINDINGS)


@certificate("N6", needs=("section5_preview",),
             printed=PRINTED_N6,
             expect=OBSERVED,
             mutants=[replaced("special", "0.184525", "0.18455", "the special r moved"),
                      committed("explained", (ORBIT_FINDINGS, {"word": "abcb"}), "a committed word replaced by abcb"),
                      committed("explained", (ORBIT_FINDINGS, {"r": "1/10"}), "the committed r of the first word moved "
                                "to 1/10, where the word has no periodic orbit")])
def stripes(section5_preview, stripes, special, lo, hi, step, count, explained):
    """Probes at Δr = 2.5e-5 (the step of Figure 7) around each printed stripe: the coverage of
    [0, π] by the 8 orbits drops there; a probe at Δr = 1e-7 around the printed special value:
    the r where the widest cluster of any orbit is narrowest, and whether every orbit is discrete."""
    lo_, hi_, step_, count_, r_star = (number(x.replace("{", "").replace("}", ""))
                                       for x in (lo, hi, step, count, special))
    checks = [Check(f"the printed grid is consistent: {lo} + k·{step}, k < {count}, ends at {hi}",
                    abs(lo_ + (count_ - 1) * step_ - hi_) < 1e-9 and F.SPECS["5.6"].count == count_, ref="N6.1")]
    for k, s in enumerate(stripes):
        c = number(s)
        scan = F.stripe_scan(F.probe(c + 2.5e-5 * np.arange(-8, 9)))
        others = [row[1] for row in scan]
        best = scan[0]
        checks.append(Check(f"a thin stripe near r ≈ {s}: within 2·10^-4 of it the coverage of [0, π] by the orbits "
                            "has a sharp minimum (below half the median), within 10^-4 of the printed value",
                            abs(best[0] - c) <= 1e-4 and best[1] < 0.5 * float(np.median(others)),
                            [f"lowest coverage {best[1]:.3f} ({best[2]}) at r = {best[0]:.6f}; median "
                             f"{np.median(others):.3f} over 17 values of r at Δr = 2.5e-5"], ref=f"N6.{k + 2}"))
    fine = F.probe(r_star + 1e-7 * np.arange(-20, 21))
    widest = F.widest_orbit(fine)
    k = int(np.argmin(widest))
    ends = float(min(widest[0], widest[-1]))
    checks.append(Check(f"at r ≈ {special} all orbits have discrete ω-limit sets: the r where the widest cluster "
                        f"of the 8 orbits is narrowest lies within 2·10^-6 of {special}, and there every orbit's "
                        "points lie in clusters narrower than a pixel (π/1000), unlike 2·10^-6 away",
                        abs(fine.r[k] - r_star) <= 2e-6 and widest[k] < F.PIXEL < ends,
                        [f"narrowest at r = {fine.r[k]:.7f}: widest cluster {widest[k]:.1e} rad, clusters per orbit "
                         f"{[F.omega(fine.phi[k, m]).clusters for m in range(fine.phi.shape[1])]}; at r ± 2e-6: "
                         f"{widest[0]:.1e}, {widest[-1]:.1e} rad (41 values of r at Δr = 1e-7, 10^4 collisions)"],
                        ref="N6.4"))
    figs = [section5_figure(section5_preview[f]) for f in ("5.5", "5.6", "5.7", "5.8")]
    note = paper_note("n6", lambda s: f"the four lowest coverages of [0, π] in Figure 10 at r = {s['stripes']} "
                      f"({s['coverages']}); in Figure 11a the "
                      f"widest cluster is narrowest at r = {s['special_r']:.7f} ({s['special_width']:.1e} rad).") \
        + figure_links("5.5", "5.6", "5.7", "5.8")
    return observe(checks + explanations("N6", explained), figures=figs, note=note)


# --------------------------------------------------------------------------
# N7: quasi-periodicity

ISLAND_SENTENCE = ("the island theorem (N7.1) proves quasi-periodic orbits in the island at every rational r in "
                   "]3−2√2, 1[ (wherever the rotation number is irrational; at the resonances, where it is rational, "
                   "such as r = 2−√3 where it is 1/3, the island's orbits are periodic).")

PRINTED_N7 = dict(grows_below="1", not_discrete_at="0.92")


@certificate("N7", needs=("section5_preview", "island_theorem"), printed=PRINTED_N7,
             expect=OBSERVED,
             mutants=[replaced("not_discrete_at", "0.92", "0.999", "where the ω-limit sets are not discrete")])
def quasi_periodic(section5_preview, island_theorem, grows_below, not_discrete_at):
    """Cluster counts and widths of each orbit's kept φ (gap 10^-3): near r = 1, in the region
    of apparent chaos, and in the thin stripe."""
    top, r92 = number(grows_below), number(not_discrete_at)
    rs = [top - 0.001, top - 0.01, top - 0.03, top - 0.05, r92]
    d = F.probe(rs)
    widths = {float(r): float(np.median(F.orbit_widths(d, k))) for k, r in enumerate(d.r)}
    order = sorted(widths, reverse=True)
    grows = all(widths[a] < widths[b] for a, b in zip(order, order[1:]))
    k92 = int(np.argmin(np.abs(d.r - r92)))
    at92 = F.per_orbit(d, k92)
    chaos = F.probe(np.linspace(0.2, 0.9, 8))
    single = [np.mean([F.omega(chaos.phi[k, m]).coverage for m in range(chaos.phi.shape[1])]) for k in range(len(chaos.r))]
    union = [F.coverage(chaos.phi[k]) for k in range(len(chaos.r))]
    stripe = section5_preview["5.6"]
    coarse = F.PIECE_GAP
    pieces = [F.omega(x.phi[k, m], gap=coarse).clusters for x in (stripe, chaos)
              for k in range(len(x.r)) for m in range(x.phi.shape[1]) if x.breaks[k, m] == 0]
    checks = [
        Check(f"the ω-limit sets grow as r decreases from {grows_below}: the median width of the orbits' widest "
              "cluster increases", grows, [", ".join(f"r = {r:g}: {widths[r]:.1e} rad" for r in order)], ref="N7.1"),
        Check(f"they are not discrete at r ≈ {not_discrete_at}: some orbit has a cluster wider than a pixel (π/1000)",
              any(w.width > F.PIXEL for w in at92),
              [f"clusters per orbit {[w.clusters for w in at92]}, widest {max(w.width for w in at92):.1e} rad"],
              ref="N7.2"),
        Check("in the region of apparent chaos each orbit covers only part of what the 8 orbits cover together",
              all(s < 0.8 * u for s, u in zip(single, union)),
              [", ".join(f"r = {r:.2f}: one orbit {s:.2f}, union {u:.2f}" for r, s, u in zip(chaos.r, single, union))
               + f" (fractions of {F.BINS} bins of [0, π])"], ref="N7.3"),
        Check(f"each orbit's ω-limit looks like a finite union of intervals: its kept points form at most "
              f"{F.MAX_INTERVALS} intervals at a resolution of {coarse} rad (in the thin stripe and in the region "
              "of apparent chaos)", bool(pieces) and max(pieces) <= F.MAX_INTERVALS,
              [f"intervals per orbit over {len(pieces)} orbits (preview of Figure 11a and the 8 values of r above): "
               + ", ".join(f"{c}: {pieces.count(c)}" for c in sorted(set(pieces)))], ref="N7.4"),
    ]
    checks += island_explanations(island_theorem, not_discrete_at)
    note = ("The cluster counts are evidence, not a proof; the explanations are ours and certified: "
            + ISLAND_SENTENCE + " " + paper_note("n7", lambda s: f"intervals per orbit (resolution {F.PIECE_GAP} rad) in Figure 11a: "
                                        f"{s['stripe_intervals']}; in Figure 6 for 0.2 ≤ r ≤ 0.9: {s['chaos_intervals']}."))
    return observe(checks, note=note)


# --------------------------------------------------------------------------
# N7.1: the paper's suggestion, proved for the island around [ac]b (ours)

ISLAND_R = ("1/5", "3/10", "1/2", "4/5", "23/25")     # r of Figure 6 above 3−2√2 (0.92: l. 1093)
ISLAND_DEPTH = 8                                      # bisections of the section for the island's share


@quantity("island_theorem")
def island_theorem():
    """The island theorem for r a symbol on ]3−2√2, 1[ and at the rationals ISLAND_R, with the
    island's share of the b-section (``certify island``)."""
    at = {}
    for text in ISLAND_R:
        r = Q(text)
        at[text] = (island.theorem(r), island.rotation_number(r, 15), island.island_fraction(r, depth=ISLAND_DEPTH))
    return {"symbolic": island.symbolic_theorem(), "at": at}


def island_explanations(island_theorem, at_text) -> list:
    """N7's explanation lines: the island theorem, and the island's share of the section."""
    T = island_theorem["symbolic"]
    shares = "; ".join(f"r = {r}: [{float(lo):.3f}, {float(hi):.3f}]"
                       for r, (_, _, (lo, hi)) in island_theorem["at"].items())
    return [Check(f"{EXPLANATION} quasi-periodic orbits exist at every rational r in ]3−2√2, 1[ (so at r = "
                  f"{at_text}): the orbits in the island U_r around [ac]b turn densely on invariant ellipses wherever "
                  "the rotation number is irrational, and are periodic at its rational values, the resonances (the "
                  "island theorem, N7.1)", T.quasi_periodic,
                  [f"the theorem for r a symbol: {sum(s.holds for s in T.steps)} of {len(T.steps)} steps proved",
                   f"the island's share of the b-section (θ, φ) ∈ ]0, π/2[ × ]0, π[, certified intervals: {shares}"],
                  counts=False)] + grid_classes()


def grid_classes() -> list:
    """N7's summary of the committed classes of the tool's grid (each re-checked in N2, N5, N6)."""
    found = load_findings(ORBIT_FINDINGS) or {}
    entries = [e for claim in ("N2", "N5", "N6") for e in found.get("claims", {}).get(claim, [])]
    if not entries:
        return []
    text = "; ".join(f"r = {e['r']}: " + ", ".join(f"{n} {c}" for c, n in e["classes"].items() if n) for e in entries)
    # each orbit has one class, and the counts are those of the orbits listed
    whole = all(len(e["classified"]) == e["orbits"] and
                all(sum(o["class"] == c for o in e["classified"]) == n for c, n in e["classes"].items())
                for e in entries)
    return [Check(f"{EXPLANATION} every orbit of the tool's grid is classified at the r of {ORBIT_FINDINGS} "
                  "(island: quasi-periodic, proved; attracting periodic: its word certified for ever; unresolved: "
                  "observed only), each proof re-checked in N2, N5 and N6", whole, [text], counts=False)]


PRINTED_N7_1 = dict(suggests="the orbits of such a system might be quasi-periodic",
                    tori="The $\\omega$-limit sets might indeed be invariant tori",
                    above="3-2√2")


@certificate("N7.1", needs=("island_theorem",), printed=PRINTED_N7_1, expect=PASS,
             mutants=[replaced("above", "3-2√2", "2-√3", "the threshold above which the tori appear"),
                      replaced("above", "3-2√2", "3-2√3", "a threshold outside ]0, 1["),
                      replaced("suggests", "quasi-periodic", "periodic", "the suggestion reworded"),
                      replaced("tori", "invariant tori", "periodic orbits", "what the ω-limit sets might be")])
def island_quasi_periodic(island_theorem, suggests, tori, above):
    """The island theorem (certify/patterns/island_theorem.py) for r a symbol, each step a check of
    its own (statements N7.1.2-N7.1.8), and at rationals of Figure 6; the printed threshold
    compared, as an algebraic number, with the end of the interval where A(r) is elliptic (the
    root of r² − 6r + 1 in ]0, 1[); the values −1, 0, 1 of tr A on the interval; the resonance
    r = 2−√3, where the rotation number is 1/3 and A³ = I (every island orbit periodic)."""
    T = island_theorem["symbolic"]
    step = {s.name.split()[0]: s for s in T.steps}
    lower = radical(above)
    at = island_theorem["at"]
    values_ok, values_ev = trace_values()
    resonant_ok, resonant_ev = resonance_one_third()

    def step_check(name: str, ref: str, extra: bool = True, evidence=(), text: str = "") -> Check:
        s = step[name]
        return Check(s.name + text, s.holds and extra, list(evidence), ref=ref)
    checks = [
        Check(f"l. 95: \"{suggests}\": proved for the island at every rational r in ]3−2√2, 1[ (wherever the "
              "rotation number is irrational; r a symbol, every step an identity in Q(r) or a sign certified on the "
              "interval); at the resonances (ρ = p/q, e.g. r = 2−√3) every island orbit is periodic instead",
              "quasi-periodic" in suggests and T.quasi_periodic,
              [f"the steps of the theorem for r a symbol: {sum(s.holds for s in T.steps)} of {len(T.steps)} proved"],
              ref="N7.1.1"),
        step_check("(a)", "N7.1.2"),
        step_check("(b)", "N7.1.3"),
        step_check("(c)", "N7.1.4"),
        step_check("(c′)", "N7.1.5", lower == island.LOWER_END,
                   [f"l. 1223-1226: the printed {above} = {lower}, the lower end of the interval where A(r) is elliptic"],
                   f"; l. 1223-1226: the quasi-periodic regimes lie above r = {above}"),
        step_check("(d)", "N7.1.6", "invariant tori" in tori,
                   ["A(r) is a rotation by θ, cos θ = −(1−r)²/(4r), in coordinates where Q is Euclidean"],
                   f"; l. 1210: \"{tori}\": the invariant ellipses Q = c, c < c_max"),
        step_check("(e)", "N7.1.7"),
        step_check("(f)", "N7.1.8", values_ok, values_ev,
                   "; tr A = 2cos θ takes the values −1, 0, 1 on ]3−2√2, 1[ only at r = 2−√3 (irrational)"),
        Check("at r = 2−√3 the rotation number is 1/3 and A³ = I: every island orbit is periodic there; no other r "
              "of the interval has ρ = 1/3", resonant_ok, resonant_ev, ref="N7.1.9"),
        Check("at the rationals r = " + ", ".join(at) + " of Figure 6 the theorem is proved step by step, θ/2π "
              "irrational (e^{iθ} is no root of unity)", all(t.quasi_periodic for t, _, _ in at.values()),
              [f"r = {r}: c_max = {t.c_max}, ρ = {rho}, island share in [{lo}, {hi}]"
               for r, (t, rho, (lo, hi)) in at.items()], ref="N7.1.10"),
    ]
    checks += window_resonance_explanation()
    note = ("The island exists on the whole of ]3−2√2, 1[, not only below r ≃ 0.19166 (l. 1226), where the paper "
            "saw its regimes; its orbits are quasi-periodic where the rotation number is irrational (at every "
            "rational r) and periodic at the resonances, where it is p/q (r = 2−√3: 1/3); outside the island the "
            "orbits may be attracted by periodic orbits (`certify identify`). "
            "The theorem and its steps: `python -m certify island --symbolic`, docs/island.md.  The figure: the "
            "b-section at r = 3/10 with the island's boundary ellipse over the tool's eight orbits, and the rotation "
            "number against r with its resonances over the attracting windows of the census.")
    return conclude(checks, note=note, figures=[island_figure(Q(3, 10))])


def trace_values() -> tuple[bool, list[str]]:
    """tr A = −(1−r)²/(2r) equals −1, 0, 1 where r² − 4r + 1, (1 − r)², r² + 1 vanish: their roots
    in ]3−2√2, 1[ (:func:`island_theorem.roots_inside`, Sturm and python-flint) are 2−√3 alone.  At
    a rational r, 2cos θ = tr A is rational, e^{iθ} has degree ≤ 2, and a root of unity of degree
    ≤ 2 has 2cos θ in {0, ±1, ±2}: the second route to step (f)."""
    R = flint.fmpq_poly([0, 1])
    numerators = {-1: R ** 2 - 4 * R + 1, 0: (1 - R) ** 2, 1: R ** 2 + 1}
    inside = {k: [x for x in Algebraic.roots(P, 0, 1) if island.LOWER_END < x < 1] for k, P in numerators.items()}
    counts = {k: island.roots_inside(P) for k, P in numerators.items()}
    found = [x for xs in inside.values() for x in xs]
    ok = all(len(inside[k]) == counts[k] for k in counts) and len(found) == 1 and found[0] == TWO_MINUS_ROOT3 \
        and inside[-1] == found
    names = {-1: "r² − 4r + 1", 0: "(1 − r)²", 1: "r² + 1"}
    return ok, [f"tr A = {k}: the roots of {names[k]} in ]3−2√2, 1[: {', '.join(map(str, inside[k])) or 'none'}"
                for k in numerators]


TWO_MINUS_ROOT3 = Algebraic.surd(2, -1, 3)


def resonance_one_third() -> tuple[bool, list[str]]:
    """At r = 2−√3 the rotation number is 1/3 (the only r of ]3−2√2, 1[ with ρ = p/3:
    :func:`island_theorem.resonances_of_q`) and A(r)³ = I exactly (SymPy, in Q(√3))."""
    found = island.resonances_of_q(3)
    A = sp.Matrix(island.island.matrix_A(2 - sp.sqrt(3)))
    cube = (A ** 3).applyfunc(sp.radsimp)
    ok = len(found) == 1 and (found[0].p, found[0].q) == (1, 3) and found[0].r == TWO_MINUS_ROOT3 \
        and cube == sp.eye(2)
    return ok, [f"ρ = p/3 in ]3−2√2, 1[ at: {', '.join(f'{s.p}/{s.q} at r = {s.r}' for s in found)}; "
                f"A(2−√3)³ = {cube.tolist()}"]


def window_resonance_explanation() -> list:
    """N7.1's line on the census (ours): the attracting windows that close where the island's
    rotation number is rational (the same algebraic number, island_theorem.window_resonances)."""
    committed = committed_windows()
    if committed is None:
        return []
    windows, by = committed
    found = island.window_resonances(windows, 12)
    closing = {(w, "hi", i) for w, spans in windows.items() for i, span in enumerate(spans)
               if island.algebraic_of(span["hi"]) >= island.LOWER_END}
    named = {(w, side, i) for w, spans in windows.items() for i, span in enumerate(spans)
             for fw, side, d, _ in found if fw == w and side == "hi" and d == span["hi"]["digits"]}
    return [Check(f"{EXPLANATION} each of the {len(closing)} attracting windows of the census (reports/census.json) "
                  "that close in [3−2√2, 1] closes exactly where the island's rotation number is p/q (q ≤ 12)",
                  bool(closing) and closing <= named,
                  [", ".join(f"{by.get(w, w)}: {'upper' if side == 'hi' else 'lower'} end ≈ {d}, ρ = {p}/{q}"
                             for w, side, d, (p, q) in found)], counts=False)]


# N2.7: the paper's "apparent chaos", proved at two r by horseshoes (ours)

CHAOS_R = ("11/100", "9/100")          # in the gaps ]0.1010, 0.1275[ and ]0.0864, 0.0945[ between stability windows


@quantity("horseshoes")
def horseshoes():
    """The horseshoe ``certify chaos`` proves at each r of CHAOS_R (None where none is found)."""
    return {text: F.horseshoe.find(exact_r(text)) for text in CHAOS_R}


def exact_r(text: str):
    """The exact rational of a printed r ("11/100")."""
    from fractions import Fraction
    f = Fraction(text)
    return Q(f.numerator, f.denominator)


CHAOS_ENTROPY = "0.11"        # ours: the lower bound of the entropy claimed at r = 11/100 (statement N2.7.1)
PRINTED_N2_7 = dict(chaos="This could suggest a chaotic behaviour", windows="windows of apparent chaos")


@certificate("N2.7", needs=("horseshoes",), printed=PRINTED_N2_7, expect=PASS,
             mutants=[replaced("chaos", "chaotic", "periodic", "the suggestion reworded"),
                      replaced("windows", "apparent chaos", "apparent order", "the windows reworded")])
def chaos_proved(horseshoes, chaos, windows):
    """At r = 11/100 (the boxes of statements N2.7.2-N2.7.23, decided again by the kernel from its own
    collision matrices) and at r = 9/100: a horseshoe of the b-to-b map, each box in one branch,
    each covering relation, disjoint boxes and ρ(T) ≥ β > 1 decided in rationals
    (certify/numerics/horseshoe.py, docs/chaos.md); the conclusion (Zgliczyński–Gidea) is N2.7.1."""
    r = CHAOS_R[0]
    H = horseshoes[r]
    P = H.proof
    proved = P is not None and P.holds
    boxes = [] if P is None else [f"{b.name}: word {b.word}, centre ({b.c[0]}, {b.c[1]}), "
                                  f"U = ({b.U[0]}, {b.U[1]}), S = ({b.S[0]}, {b.S[1]})" for b in P.boxes]
    bound_ok = proved and float(P.entropy) >= float(exact_r(CHAOS_ENTROPY))
    checks = [
        Check(f"l. 1084: \"{chaos}\": proved at r = {r}: a horseshoe of the b-to-b map, topological entropy ≥ "
              f"{P.entropy if proved else '?'} ≥ {CHAOS_ENTROPY} on a compact invariant set, periodic orbits of "
              "infinitely many periods (Zgliczyński–Gidea's theorem on the covering relations below)",
              proved and "chaotic" in chaos and bound_ok,
              [f"saddle {H.saddle} ({P.k if P else '?'} b-returns), T = {P.T if P else '?'}, ρ(T) ≥ {P.beta if P else '?'}"]
              + boxes, ref="N2.7.1"),
        Check(f"l. 1086: \"{windows}\": chaos proved in the gaps between the stability windows, at r = "
              + " and ".join(CHAOS_R), "chaos" in windows and all(G.proof is not None and G.proof.holds
                                                                   for G in horseshoes.values()),
              [f"r = {x}: saddle {G.saddle}, entropy ≥ {G.proof.entropy if G.proof else '?'}"
               for x, G in horseshoes.items()])]
    if P is not None:
        checks += [Check(f"r = {r}: {text}", holds, [], ref=f"N2.7.{k}")
                   for k, (_, text, holds, _) in enumerate(F.horseshoe.facts(P), 2)]
    note = ("Chaos is proved on a horseshoe, a set of measure zero: this says nothing of a given orbit the simulator "
            "calls unresolved.  `python -m certify chaos --r 11/100`, docs/chaos.md.")
    return conclude(checks, note=note)
