"""Facts from the literature used by the paper, certified with the same engine.

T26 (remark after Theorem 3.1, l. 323-325): "The critical threshold of r, namely
r_crit,ababcb = 5-2√6, happens to be also the critical threshold for a different
periodic pattern, namely (ab)^3(cb)^3 (see [CDKK, Table 1])."

CDKK's Table 1 lists 5-2√6 as the *upper* end of the stability window of
(ab)^3(cb)^3 (CLAIMS L4, L5); CLAIMS L6 records CDKK's conjecture that the upper
threshold is where q_2(0) = 0 for the dominant eigenvector.  We build the
self-similar candidate of the word w = (ab)^3(cb)^3 exactly as for ababcb (the word
starts with a and ends with b, so q(0) = (-1, u, v), p(0) = (1, 0, x); M_w the
product of the collision matrices in time order; x a fixed point of the position map
f = p_3(t_12)/p_1(t_12)), find which condition changes at 5-2√6 by elimination, and
certify over whole r-intervals that on the dominant branch the candidate realises
the word with all inequalities strict and is stable just below 5-2√6 and does not
exist just above.
"""
from __future__ import annotations

import re

import flint
import sympy as sp

from certify.algebra import (Algebraic, Condition, Lf, RING, eliminate, lam, parse, resultant_lambda, show,
    show_factored_int, to_fmpz_poly, to_ring)
from certify.dynamics import K, candidate
from certify.patterns import Analysis, BRANCH_NAMES, Requirement, fmt, prefix_requirements, vanishes_on_branch
from certify.run import Check, certificate, conclude

Q = flint.fmpq

PRINTED_T26 = dict(pattern="(ab)^3(cb)^3", threshold=(5, -2, 6), quadratic="r^2 - 10*r + 1")
WINDOW = (Q(1, 10), Q(1, 9))          # our choice of an r-interval around 5-2√6 ≈ 0.10102


def divides_q(p, q) -> bool:
    """p divides q in Q[r] (exact division over Q)."""
    return (flint.fmpq_poly(q) % flint.fmpq_poly(p)).is_zero()


def expand_pattern(pattern: str) -> str:
    """"(ab)^3(cb)^3" -> "abababcbcbcb"."""
    out = ""
    for group, letters, power in re.findall(r"(\((\w+)\)\^(\d+)|\w)", pattern.replace(" ", "")):
        out += letters * int(power) if letters else group
    if not re.fullmatch(r"[abc]+", out):
        raise ValueError(f"cannot read the pattern {pattern!r}")
    return out


def stability_conditions(cand, fp) -> list[Condition]:
    """|f'(x)| < 1 at the fixed point x = (a - d + σ√Δ)/(2c), f'(x) = (ad - bc)/(cx + d)²:
    with cx + d = (a + d + σ√Δ)/2, the two conditions (cx + d)² ∓ (ad - bc) > 0 read
    ((a+d)² + Δ)/4 ∓ (ad - bc) + σ(a + d)√Δ/2 > 0 (multiplied by 4 below)."""
    a, b, c, d = (to_ring(e) for e in cand.abcd)
    C = to_ring(cand.cp)
    out = []
    for sg, name in ((-1, "(cx+d)² - (ad-bc)"), (1, "(cx+d)² + (ad-bc)")):
        N0 = ((a + d) ** 2 + fp.delta + 4 * sg * (a * d - b * c)).rem(C)
        N1 = (2 * fp.sigma * (a + d)).rem(C)
        out.append(Condition(name, (N0, N1), (RING.one, RING.zero), fp.delta, fp.c))
    return out


@certificate("T26", "l. 323-325",
             "5-2√6 is also the critical (upper stability) threshold of (ab)^3(cb)^3 (CDKK Table 1).",
             printed=PRINTED_T26)
def threshold_of_ab3cb3(pattern, threshold, quadratic):
    """Elimination (both routes) names the condition that changes at 5-2√6; sign
    tables over ]1/10, 5-2√6[ and ]5-2√6, 1/9[ certify that the candidate on the
    dominant branch is feasible and stable just below and does not exist just above."""
    word = expand_pattern(pattern)
    r1 = Algebraic.surd(*threshold)
    quad = to_fmpz_poly(parse(quadratic))
    roots = Algebraic.roots(quad, 0, 1)
    checks = [Check(f"the printed threshold {threshold[0]}{threshold[1]:+}√{threshold[2]} is the only root of "
                    f"{show(quad)} in ]0,1[", len(roots) == 1 and roots[0] == r1, [f"r1 = {r1.describe()}"])]
    lo, hi = WINDOW
    if not lo < r1 < hi:
        return conclude(checks + [Check(f"the threshold lies in our window ]{lo}, {hi}[", False)])
    cand = candidate(word)
    cp = cand.cp
    u_num, u_den = sp.fraction(sp.cancel(cand.q0[1].as_expr()))
    a, b, c, d = cand.abcd
    ev = [f"w = {word}; M_w = `{show(cand.M.tolist())}`", f"cp(M_w) = `{show(sp.collect(cp, lam))}`",
          f"q(0) = (-1, u, v), u = q_2(0) = `{show(sp.factor(u_num))}` / `{show(sp.factor(u_den))}`"]
    # which basic quantity vanishes at r1: resultants with cp, and the exact Gröbner route for u
    quantities = {"u = q_2(0) (numerator)": u_num, "u (denominator)": u_den,
                  "v = q_3(0) (numerator)": sp.fraction(sp.cancel(cand.q0[2].as_expr()))[0],
                  "a - d": sp.expand(a - d), "b": b, "c": c, "Δ = (a-d)² + 4bc": sp.expand((a - d) ** 2 + 4 * b * c)}
    hits = []
    for name, g in quantities.items():
        R = resultant_lambda(sp.expand(g), cp)
        if not R.is_zero() and divides_q(quad, R):
            hits.append(name)
        ev.append(f"Res_λ({name}, cp) = `{show_factored_int(R)}`")
    ev.append(f"the resultants containing {show(quad)}: {', '.join(hits) or 'none'}")
    E = eliminate(sp.expand(u_num), cp)
    checks.append(Check(f"{show(quad)} divides the eliminant of {{q_2(0), cp(M_w)}} on both routes",
                        E.agree and divides_q(quad, E.groebner) and divides_q(quad, E.resultant), E.evidence()))
    # the regions, on ]lo, hi[
    an = Analysis(cand, lo, hi)
    base = cand.spectrum.sign_table(Condition.of("λ", lam), lo, hi)
    three_positive = all(len(cell.branches) == 3 for cell in base.cells) and all(base.holds(k, 1) for k in range(3))
    checks.append(Check(f"on ]{lo}, {hi}[ the three eigenvalues are real and positive, so the largest is the "
                        f"dominant one (strictly)", three_positive, ["sign of λ per branch:\n\n" + base.markdown()]))
    reqs, steps = prefix_requirements(word, len(word), cand.q0, cand.steps, cand.q0_other)
    reqs.append(Requirement("λ (q(t_12) = λ q(0) keeps the signs)", (K(Lf), K.zero), 1))
    for req in reqs:
        an.impose(req)
    ev.append("the candidate realises w with every inequality strict iff " + ", ".join(
        f"{q.name} {'>' if q.sign > 0 else '<'} 0" for q in reqs))
    for key, T in an.tables.items():
        if key[0] == reqs[0].name:
            ev.append(f"sign of {key[0]} per branch:\n\n{T.markdown()}")
    for R in an.regions:
        ev.append(f"{BRANCH_NAMES[R.branch]} branch, {R.fixed_point}: feasible on {R.describe()}"
                  + (f"; excluded exactly at {', '.join(f'{fmt(rc)} ({why})' for rc, why in R.dropped)}"
                     if R.dropped else ""))
    undecided = [(R, u) for R in an.regions for u in R.undecided]
    upper = [R for R in an.regions if R.branch == 0]
    below = [(R, p) for R in upper for p in R.pieces if not p.is_point and p.hi == r1]
    above = [(R, p) for R in upper for p in R.pieces if (p.lo if p.is_point else p.hi) > r1]
    at_r1 = [(R, p) for R in upper for p in R.pieces if p.is_point and p.lo == r1]
    u_zero = vanishes_on_branch(cand.spectrum, sp.expand(u_num), r1, 0)
    den_sign = cand.spectrum.sign_at_point(Condition("denominator of u", (to_ring(u_den), RING.zero),
                                                     (RING.one, RING.zero), None, None), r1)
    den_sign = None if den_sign is None else den_sign[0]
    checks += [
        Check("every cell and critical value of the window decided", not undecided,
              [f"undecided: {BRANCH_NAMES[R.branch]} {R.fixed_point} {fmt(rc)} ({why})" for R, (rc, why) in undecided]),
        Check("dominant branch: the candidate realises w on an interval ]s, 5-2√6[ just below the threshold",
              bool(below), [f"{R.fixed_point}: {p}" for R, p in below]),
        Check("dominant branch: no feasible candidate on ]5-2√6, 1/9[ nor at 5-2√6 (for x₊ and x₋)",
              not above and not at_r1, [f"{R.fixed_point}: {p}" for R, p in above + at_r1]),
        Check("q_2(0) vanishes exactly at 5-2√6 on the dominant branch (the CDKK criterion, CLAIMS L6): its "
              "numerator vanishes there (exact test in Q(r1)[λ]) and its denominator does not (sign proven by balls)",
              u_zero and den_sign in (1, -1), [f"sign of the denominator of u at r1 on the dominant branch: {den_sign}"]),
    ]
    # stability just below: dominant eigenvalue (velocities) and |f'(x)| < 1 (positions)
    stable = bool(below)
    for R, p in below:
        fp = an.fps[R.fixed_point]
        for cond in stability_conditions(cand, fp):
            T = cand.spectrum.sign_table(cond, p.lo, p.hi)
            ok = T.holds(0, 1)
            stable &= ok
            ev.append(f"{cond.name} at {R.fixed_point} on {p} (|f'(x)| < 1 iff both > 0):\n\n{T.markdown()}")
    checks.append(Check("just below 5-2√6 the candidate is stable: dominant eigenvalue and |f'(x)| < 1 on the "
                        "whole interval ]s, 5-2√6[", stable))
    others = [f"{BRANCH_NAMES[R.branch]} {R.fixed_point}: {R.describe()}" for R in an.regions
              if R.branch > 0 and R.pieces]
    if others:
        ev.append("feasible also on the non-dominant branches (not self-similar attractors: the velocities leave "
                  "the eigendirection): " + "; ".join(others))
    return conclude(checks, evidence=ev,
                    note="Reading: the paper's 'critical threshold' of (ab)^3(cb)^3 is CDKK's upper stability "
                         "threshold (CLAIMS L4, L5): the end of the r-interval where the self-similar candidate on "
                         f"the dominant branch exists and is stable. Window ]{lo}, {hi}[ chosen by us.")
