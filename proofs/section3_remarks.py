"""Section 3, the remarks after Theorem 3.1 (l. 323-325, 513-515).

Remark 3.2 (l. 323-325): "The critical threshold of r, namely r_crit,ababcb = 5-2√6,
happens to be also the critical threshold for a different periodic pattern, namely
(ab)^3(cb)^3 (see [CDKK, Table 1])" (T26).

Remark 3.3 (l. 513-515): the pattern abcab has no self-similar datum: for its obvious
candidate the collision after the first b is a, not c (T27); and "patterns containing
abcab do not seem to have feasible self-similar data", an empirical remark tested on a
census (T28).

Each certificate below is introduced by what it reads in the paper and how it is checked.
The candidates are built by :func:`certify.dynamics.candidate`, their regions by
:class:`certify.patterns.Analysis` (the engine of ``certify pattern``).
"""
from __future__ import annotations

import re
from fractions import Fraction
from itertools import product

import flint
import sympy as sp

from certify.algebra import (
    FIELD,
    RING,
    X_PLUS,
    Algebraic,
    Condition,
    Lf,
    Q,
    divides,
    eliminate,
    lam,
    parse,
    resultant_lambda,
    show,
    show_factored_int,
    simplest_between,
    to_fmpz_poly,
    to_ring,
)
from certify.dynamics import INDEX, candidate, collision_matrix, run_word, simulate
from certify.dynamics import simulate as sim
from certify.patterns import (
    BRANCH_NAMES,
    Analysis,
    Requirement,
    analyse,
    census,
    fmt,
    prefix_requirements,
    vanishes_on_branch,
)
from certify.run import (
    ERRATUM,
    PASS,
    REFUTED_REMARK,
    Check,
    census_report,
    certificate,
    conclude,
    for_a_run,
    named,
    overridden,
    read_first_member,
    replaced,
)
from proofs.section1_literature import expand_pattern, stable_window, witnessed
from proofs.section1_literature import pattern as whole_pattern

# ---------------------------------------------------------------- Remark 3.2 (l. 323-325): 5-2√6 is also the threshold of (ab)^3(cb)^3
# T26 (Remark 3.2, l. 323-325): "The critical threshold of r, namely
# r_crit,ababcb = 5-2√6, happens to be also the critical threshold for a different
# periodic pattern, namely (ab)^3(cb)^3 (see [CDKK, Table 1])."
#
# CDKK's Table 1 lists 5-2√6 as the *upper* end of the stability window of
# (ab)^3(cb)^3 (CLAIMS L4, L5); CLAIMS L6 records CDKK's conjecture that the upper
# threshold is where q_2(0) = 0 for the dominant eigenvector.  We build the
# self-similar candidate of the word w = (ab)^3(cb)^3 exactly as for ababcb (the word
# starts with a and ends with b, so q(0) = (-1, u, v), p(0) = (1, 0, x); M_w the
# product of the collision matrices in time order; x a fixed point of the position map
# f = p_3(t_12)/p_1(t_12)), find which condition changes at 5-2√6 by elimination, and
# certify over whole r-intervals that on the dominant branch the candidate realises
# the word with all inequalities strict and is stable just below 5-2√6 and does not
# exist just above.
PRINTED_T26 = dict(pattern="(ab)^3(cb)^3", threshold=(5, -2, 6), quadratic="r^2 - 10*r + 1")
WINDOW = (Q(1, 10), Q(1, 9))          # our choice of an r-interval around 5-2√6 ≈ 0.10102


@certificate("T26", printed=PRINTED_T26,
             expect=PASS,
             mutants=[overridden({"pattern": "(ab)^2(cb)^2"}, "another pattern (its threshold is 3-2√2)"),
                      overridden({"threshold": (5, -2, 7)}, "a digit of the threshold"),
                      overridden({"quadratic": "r^2 - 10*r + 2"}, "a coefficient of the quadratic")])
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
    ev = [f"w = {word}; M_w = `{show(cand.M.tolist())}`", f"cp(M_w) = `{show(sp.collect(cp, lam))}`",
          f"q(0) = (-1, u, v), u = q_2(0) = `{show(sp.factor(u_num))}` / `{show(sp.factor(u_den))}`"]
    # which basic quantity vanishes at r1: resultants with cp, and the exact Gröbner route for u
    # a - d and Δ in the engine's ring (the same polynomials as SymPy's expansions, without them)
    A, B, C, D = cand.abcd_ring
    quantities = {"u = q_2(0) (numerator)": sp.expand(u_num), "u (denominator)": sp.expand(u_den),
                  "v = q_3(0) (numerator)": sp.expand(sp.fraction(sp.cancel(cand.q0[2].as_expr()))[0]),
                  "a - d": A - D, "b": B, "c": C, "Δ = (a-d)² + 4bc": (A - D) ** 2 + 4 * B * C}
    hits = []
    for name, g in quantities.items():
        R = resultant_lambda(g, cand.spectrum.ring_cp)
        if not R.is_zero() and divides(quad, R):
            hits.append(name)
        ev.append(f"Res_λ({name}, cp) = `{show_factored_int(R)}`")
    ev.append(f"the resultants containing {show(quad)}: {', '.join(hits) or 'none'}")
    E = eliminate(sp.expand(u_num), cp)
    checks.append(Check(f"{show(quad)} divides the eliminant of {{q_2(0), cp(M_w)}} on both routes",
                        E.agree and divides(quad, E.groebner) and divides(quad, E.resultant), E.evidence()))
    # the regions, on ]lo, hi[
    an = Analysis(cand, lo, hi)
    base = cand.spectrum.sign_table(Condition.of("λ", lam), lo, hi)
    three_positive = all(len(cell.branches) == 3 for cell in base.cells) and all(base.holds(k, 1) for k in range(3))
    checks.append(Check(f"on ]{lo}, {hi}[ the three eigenvalues are real and positive, so the largest is the "
                        f"dominant one (strictly)", three_positive, ["sign of λ per branch:\n\n" + base.markdown()]))
    reqs, steps = prefix_requirements(word, len(word), cand.q0, cand.steps, cand.q0_other)
    reqs.append(Requirement("λ (q(t_12) = λ q(0) keeps the signs)", (FIELD(Lf), FIELD.zero), 1))
    for req in reqs:
        an.impose(req)
    undecided = [(R, u) for R in an.regions for u in R.undecided]
    ev.append("the candidate realises w with every inequality strict iff " + ", ".join(
        f"{q.name} {'>' if q.sign > 0 else '<'} 0" for q in reqs))
    for key, T in an.tables.items():
        if key[0] == reqs[0].name:
            ev.append(f"sign of {key[0]} per branch:\n\n{T.markdown()}")
    for R in an.regions:
        ev.append(f"{BRANCH_NAMES[R.branch]} branch, {R.fixed_point}: feasible on {R.describe()}"
                  + (f"; excluded exactly at {', '.join(f'{fmt(rc)} ({why})' for rc, why in R.dropped)}"
                     if R.dropped else ""))
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
    # stability just below: `certify pattern` on the same window (λ dominant, |f'(x)| < 1)
    res = analyse(pattern, lo, hi)
    stable_upper = [p for R in res.regions["stable"] if R.branch == 0 for p in R.pieces]
    stable = bool(below) and any(not p.is_point and p.hi == r1 and any(p.lo == q.lo for _, q in below)
                                 for p in stable_upper)
    ev.append(f"`certify pattern {pattern} --r-range {lo} {hi}`: stable on " + "; ".join(
        f"{s['branch']} {s['fixed_point']}: {s['set']}" for s in res.stable) + f" ({'; '.join(res.conditions['stable'])})")
    checks.append(Check("just below 5-2√6 the candidate is stable: dominant eigenvalue (|μ| < λ for the other "
                        "eigenvalues) and |f'(x)| < 1 on the whole interval ]s, 5-2√6[ (certify pattern)", stable))
    whole = whole_pattern(pattern)             # `certify pattern` over ]0, 1[ (shared with L4, L5)
    w = stable_window({3: whole}, 3)
    checks.append(witnessed(Check(f"over ]0, 1[ the stable set of {pattern} is one interval of the dominant branch, "
                                  "whose upper end is 5-2√6", w is not None and w[1] == r1,
                                  [f"stable: {'; '.join(s_['branch'] + ' ' + s_['fixed_point'] + ': ' + s_['set'] for s_ in whole.stable)}"]),
                            "T26.1", pattern))
    others = [f"{BRANCH_NAMES[R.branch]} {R.fixed_point}: {R.describe()}" for R in an.regions
              if R.branch > 0 and R.pieces]
    if others:
        ev.append("feasible also on the non-dominant branches (not self-similar attractors: the velocities leave "
                  "the eigendirection): " + "; ".join(others))
    return conclude(checks, evidence=ev,
                    note="Reading: the paper's 'critical threshold' of (ab)^3(cb)^3 is CDKK's upper stability "
                         "threshold (CLAIMS L4, L5): the end of the r-interval where the self-similar candidate on "
                         f"the dominant branch exists and is stable. Window ]{lo}, {hi}[ chosen by us.")


# ---------------------------------------------------------------- Remark 3.3 (l. 513-515): abcab has no self-similar datum
# Remark 3.3 (l. 513-515): the pattern abcab has no self-similar datum.
#
# As printed: "for the initial data that are the obvious candidates - that is, the
# eigenvector of the corresponding matrix BACBA for the velocities and a fixed point
# for the distance map f for the positions - the collision after the first b
# collision is a, not c (and these collisions do not take place at the same time, so
# that the order really is a and then, after a strictly positive time, c)".
#
# The candidate, with the paper's normalisation for a word that starts with a and
# ends with b (l. 270-280): q(0) = (-1, u, v), an eigenvector of M_w = K_b K_a K_c K_b K_a
# for a real eigenvalue λ (any real branch), and p(0) = (1, 0, x) with x a fixed point
# x₊ or x₋ of f(x) = p_3(t_5)/p_1(t_5) = (ax + b)/(cx + d).  The collisions are
# *assumed* (times defined by p_i(t_k) = 0, as in l. 460-463) and then checked:
#
# * the candidate realises a, b as its first two collisions iff u = q_2(0) > 0
#   (p_2(0) = 0 right after the last b), x > 0, q_2(t_1) < 0 and p_3(t_2) > 0
#   (see :func:`prefix_requirements` for why the other gaps need no condition);
# * the claim: q_1(t_2) < 0 (a comes next) and, at the time t_3 of that a,
#   p_3(t_3) > 0, i.e. the a collision happens strictly before any c:
#   p_3(t_3) = p_3(t_2) + τ_a q_3(t_2) = -q_3(t_2)(τ_c - τ_a) when q_3(t_2) < 0.
#
# Each condition is a rational function of r, λ and x; its sign on each real
# eigenvalue branch is certified over whole r-intervals (critical values from
# resultants and the discriminant, one exact sample per cell, the branches isolated
# by Sturm sequences, signs proven by balls).  :class:`Analysis` imposes the
# conditions one at a time and keeps, per branch and fixed point, the exact set of r
# where all hold (open intervals with algebraic ends, and points).  At a critical
# value the signs are decided by balls, or, where a quantity vanishes or has a pole,
# by the engine's exact zero test in Q(r_c)[λ]; where c = 0 the map f is affine and
# its fixed point b/(d - a) is used.  The dynamics itself (``certify.dynamics.simulate``,
# balls) is run from the candidate at one rational r per piece as a cross-check.
#
# The candidate is built by :func:`certify.dynamics.candidate`, the regions by
# :class:`certify.patterns.feasibility.Analysis` (shared with ``proofs/section1_literature.py``).
def matrix_of_name(name: str) -> sp.Matrix:
    """The product of collision matrices named left to right, e.g. "BACBA" = B·A·C·B·A."""
    out = sp.eye(3)
    for letter in name:
        out = out * collision_matrix(letter.lower())
    return out


PRINTED_T27 = dict(word="abcab", matrix="BACBA", after="b", next="a", other="c")


@certificate("T27", printed=PRINTED_T27,
             expect=PASS,
             mutants=[overridden({"matrix": "BACAB"}, "a letter of the matrix name"),
                      overridden({"matrix": "ABCAB"}, "a letter of the matrix name"),
                      overridden({"next": "c", "other": "a"}, "the claimed collision order reversed"),
                      overridden({"word": "acbab"}, "a different word: its matrix BABCA is not BACBA")])
def abcab_has_no_self_similar_datum(word, matrix, after, next, other):
    """On every real branch, for every r in ]0,1[ and both fixed points x±: wherever
    the candidate realises its first collisions up to the first b, the next
    collision is a (q_1 < 0 after b) and it comes strictly before c (p_3 > 0 at
    that a)."""
    cand = candidate(word)
    same = (matrix_of_name(matrix) - cand.M).applyfunc(sp.cancel) == sp.zeros(3, 3)
    checks = [Check(f"the matrix of the word {word} (collisions in time order) is {matrix}", same,
                    [f"M_w = `{show(cand.M.tolist())}`", f"cp(M_w) = `{show(sp.collect(cand.cp, lam))}`"], ref="T27.1")]
    m = word.index(after) + 1
    feas, steps = prefix_requirements(word, m, cand.q0, cand.steps, cand.q0_other)
    i, o = INDEX[next], INDEX[other]
    tail = run_word(word[:m] + next, cand.q0)[-1]
    claim = [Requirement(f"q_{i + 1}(t_{m})", (steps[-1].q[i], FIELD.zero), -1),
             Requirement(f"p_{o + 1}(t_{m + 1})", tail.p[o], 1)]
    an = Analysis(cand)
    for req in feas:
        an.impose(req)
    undecided = [(R, u) for R in an.regions for u in R.undecided]
    feasible = [R for R in an.regions if R.pieces]
    bad = [v for req in claim for v in an.violations(req)]
    a, b, c, d = cand.abcd
    ev = [f"q(0) = (-1, u, v), u = `{show(sp.factor(cand.q0[1].as_expr()))}`, "
          f"v = `{show(sp.factor(cand.q0[2].as_expr()))}`; p(0) = (1, 0, x)",
          f"f(x) = (ax + b)/(cx + d), a = `{show(sp.factor(a))}`, b = `{show(sp.factor(b))}`, "
          f"c = `{show(sp.factor(c))}`, d = `{show(sp.factor(d))}`; x± = (a - d ± √((a-d)² + 4bc))/(2c)",
          f"the candidate realises {', '.join(word[:m])} iff " + ", ".join(f"{q.name} {'>' if q.sign > 0 else '<'} 0"
                                                                        for q in feas),
          f"claim: {claim[0].name} < 0 ({next} approaches) and {claim[1].name} > 0 (at the time of that {next}, "
          f"the gap {other} is still open: τ_{next} < τ_{other})"]
    for R in an.regions:
        ev.append(f"{BRANCH_NAMES[R.branch]} branch, {R.fixed_point}: candidate realised on {R.describe()}"
                  + (f"; excluded exactly at {', '.join(f'{fmt(rc)} ({why})' for rc, why in R.dropped)}"
                     if R.dropped else ""))
    for key, T in an.tables.items():
        if key[0] in ("x", claim[0].name, claim[1].name):
            ev.append(f"sign of {key[0]} {key[1]} over ]{fmt(Algebraic.rational(T.interval[0]) if not isinstance(T.interval[0], Algebraic) else T.interval[0])}, "
                      f"{fmt(T.interval[1] if isinstance(T.interval[1], Algebraic) else Algebraic.rational(T.interval[1]))}[:\n\n{T.markdown()}")
    q_other = Requirement(f"q_{o + 1}(t_{m})", (steps[-1].q[o], FIELD.zero), -1)
    ev.append(f"{q_other.name} < 0 ({other} approaching after {after}) on the same region: "
              + ("yes" if not an.violations(q_other) else "no (where it is ≥ 0, c does not come next at all)"))
    dynamic = []
    for R in an.regions:
        for p in R.pieces:
            if p.is_point:
                continue
            p.lo.refine(Q(1, 10 ** 6)), p.hi.refine(Q(1, 10 ** 6))
            w = (p.hi.lo - p.lo.hi) / 8
            r0 = simplest_between(p.lo.hi + w, p.hi.lo - w)
            sigma = 1 if R.fixed_point == "x₊" else -1
            run, prec = sim.run_certified(lambda pr, r0=r0, k=R.branch, sigma=sigma: cand.balls(r0, k, sigma, pr), m + 1)
            dynamic.append((R, r0, run.word))
    want = word[:m] + next
    ev.append("the particle dynamics itself (certify.dynamics.simulate, every collision proven in balls) from the candidate "
              "at one rational r per piece: " + "; ".join(f"{BRANCH_NAMES[R.branch]} {R.fixed_point} r = {r0}: "
                                                          f"{w}" for R, r0, w in dynamic))
    checks += [
        Check(f"cross-check on the dynamics: from the candidate, the first {m + 1} collisions are {want}",
              all(w == want for _, _, w in dynamic) and bool(dynamic)),
        Check("every cell and critical value of ]0,1[ decided on every branch, for x₊ and x₋", not undecided,
              [f"undecided: {BRANCH_NAMES[R.branch]} {R.fixed_point} at {fmt(rc)} ({why})" for R, (rc, why) in undecided]),
        witnessed(Check(f"wherever the candidate realises {', '.join(word[:m])}, the next collision is {next}, "
              f"strictly before {other}", not bad and not undecided,
              [f"fails on {BRANCH_NAMES[R.branch]} {R.fixed_point} {p}: {why}" for R, p, why in bad]), "T27.3", word),
        Check("and the candidate does realise them somewhere (the remark is not vacuous)", bool(feasible)),
    ]
    # the same conclusion from `certify pattern abcab` (the whole period, every branch, x±)
    res = analyse(word)
    dg = res.diagnosis or {}
    checks.append(witnessed(Check(f"`certify pattern {word}`: no feasible datum; the first collision that goes wrong "
                                  f"is collision {m + 1} ({other}), and {next} comes instead, strictly before, wherever "
                                  f"the first {m} are realised",
                                  not res.feasible and dg.get("collision") == m + 1 and dg.get("expected") == other
                                  and [i["letter"] for i in dg.get("instead", [])] == [next]
                                  and dg.get("complete") is True and not res.undecided,
                                  [res.verdict, dg.get("text", "no diagnosis")]), "T27.2", word))
    where = "; ".join(f"{BRANCH_NAMES[R.branch]} branch with {R.fixed_point} on {R.describe()}" for R in feasible)
    return conclude(checks, evidence=ev,
                    note=f"The printed reason is checked wherever it applies: the candidate realises "
                         f"{', '.join(word[:m])} exactly on: {where or 'nowhere'}; elsewhere (other branches, "
                         f"other fixed point, other r) it fails earlier, so there is no self-similar datum either.")


# ---------------------------------------------------------------- Remark 3.3 (l. 515): patterns containing abcab, on a census
# T28 (l. 515): "patterns containing abcab do not seem to have feasible self-similar
# data" — an empirical remark, tested on a census.
#
# Which patterns.  A periodic pattern is a cyclic sequence of the blocks ab, cb, acb,
# cab (Corollary 4.5, l. 1037-1051, with the correction certified in S10); a class of
# rotations and of the mirror a<->c is one set of orbits.  *Containing abcab* is read in
# the bi-infinite periodic word, for some member of the class: the word contains abcab
# or its mirror cbacb (so (cab)^∞ = …cabcab… and its mirror (acb)^∞ count).
#
# What is checked.  Every class of at most :data:`LENGTH` collisions
# (:func:`certify.patterns.census.words`, the FKM tree of Lyndon block words, checked
# here against a brute-force enumeration of block sequences) whose word contains the
# printed pattern is analysed by ``certify pattern`` (:func:`certify.patterns.analyse`):
# feasible means that on some real eigenvalue branch and fixed point x± its
# self-similar candidate realises every collision of the period, strictly.  The remark
# is PASS for what was checked when every such word is decided and none is feasible;
# the bound is part of the statement.  A feasible word is a counterexample: ERRATUM,
# with the corrected statement beside it (the counterexamples, their certified r-sets,
# and the exact dynamics from each datum at a rational r repeating the word, in balls).
# A word whose analysis errs or leaves a point undecided is not checked: FAIL, the word
# named, unless a counterexample refutes the remark anyway.
#
# The census (``certify census``, reports/CENSUS.md) found counterexamples from 10
# collisions on; :data:`FOUND` names the shortest ones, which are analysed here too
# (a census to 10 would take minutes inside ``certify all``): abacbacbcb (its mirror
# cbcabcabab contains abcab) and abacbcabcab = ab acb cab cab (contains abcab as written).  ``python -m certify census --max-length L`` runs the same
# analysis on every class up to L (reports/CENSUS.md).
PRINTED_T28 = dict(pattern="abcab")
LENGTH = 7             # our bound: a census of seconds inside `certify all`; `certify census` goes further
FOUND = ("abacbacbcb", "abacbcabcab")     # counterexamples found by `certify census` (ours, re-analysed here)
PERIODS = 3                               # periods of the dynamics run from a counterexample's datum


def brute_force_classes(max_length: int) -> set[str]:
    """An independent enumeration: every sequence of blocks (all 4^k of them) of at most
    ``max_length`` letters, kept when primitive, keyed by the least rotation of the word
    or its mirror (letters, no normal form).  Exponential: for small bounds only."""
    keys = set()
    for k in range(1, max_length // 2 + 1):
        for seq in product(census.BLOCKS, repeat=k):
            w = "".join(seq)
            if len(w) > max_length or any(len(w) % d == 0 and w[:d] * (len(w) // d) == w
                                          for d in range(1, len(w))):
                continue
            keys.add(least_rotation(w))
    return keys


def least_rotation(word: str) -> str:
    """The least rotation of the word or of its mirror a<->c."""
    m = word.translate(str.maketrans("ac", "ca"))
    return min(v[k:] + v[:k] for v in (word, m) for k in range(len(v)))


def _sets(rec: dict, stage: str) -> str:
    return "; ".join(f"{b}: {s}" for b, s in census.r_sets(rec, stage)) or "∅"


def replay(rec: dict) -> tuple[bool, str]:
    """The exact dynamics (balls, every collision certified) from the candidate of a
    feasible record, at a simple rational r inside its first feasible interval: does it
    repeat the word for :data:`PERIODS` periods?"""
    s = rec["result"]["feasible"][0]
    piece = next(p for p in s["pieces"] if p["kind"] == "interval")
    lo, hi = (Fraction(piece["lo"]["interval"][1]), Fraction(piece["hi"]["interval"][0]))
    margin = (hi - lo) / 8
    r0 = simplest_between(flint.fmpq(*(lo + margin).as_integer_ratio()),
                          flint.fmpq(*(hi - margin).as_integer_ratio()))
    branch, fp = BRANCH_NAMES.index(s["branch"]), s["fixed_point"]
    cand = candidate(rec["word"])
    run, prec = simulate.run_certified(lambda pr: cand.balls(r0, branch, 1 if fp == X_PLUS else -1, pr),
                                       PERIODS * len(rec["word"]))
    got = "".join(run.events)
    return got == rec["word"] * PERIODS, (f"{rec['word']}, {s['branch']} branch, {fp}, r = {r0}: the dynamics "
                                          f"from the datum gives {got} ({prec} bits)")


QUOTE_T28 = ("for other patterns that we have tested, any pattern that contains this sequence of collisions "
             "(abcab) as a subsequence does not seem to have feasible initial data")


def mirrored(word: str) -> str:
    return word.translate(str.maketrans("ac", "ca"))


def block_rotations(word: str) -> list[str]:
    """The period written from each block boundary (the census's words are block-aligned)."""
    bl = census.blocks_of(word)
    return ["".join(bl[k:] + bl[:k]) for k in range(len(bl))]


def scattered(word: str, pattern: str) -> bool:
    """``pattern``'s letters occur in ``word`` in order, not necessarily next to each other."""
    it = iter(word)
    return all(letter in it for letter in pattern)


# How "contains ... as a subsequence" (l. 515) can be read, on one orientation of a period:
READINGS = {
    "consecutive letters of the periodic word (cyclically)": lambda w, p: census.contains(w, p),
    "consecutive letters of one period written from a block boundary (no wrap-around)":
        lambda w, p: any(p in v for v in block_rotations(w)),
    "letters in order, not necessarily consecutive, in one period written from a block boundary":
        lambda w, p: any(scattered(v, p) for v in block_rotations(w)),
}


def orientations(word: str) -> list[str]:
    """The word and its mirror a<->c, once when the mirror is a rotation of the word."""
    m = mirrored(word)
    return [word] if any(m == word[k:] + word[:k] for k in range(len(word))) else [word, m]


def reading_counts(words: list[str], pattern: str) -> list[tuple[str, int, int]]:
    """For each reading: how many of ``words`` (classes of rotations and mirror) contain
    ``pattern`` with the mirror (some orientation does), and how many oriented patterns
    do without it (the word and its mirror counted apart)."""
    oriented = [orientations(w) for w in words]          # each word's orientations, once
    out = []
    for name, reads in READINGS.items():
        hits = [[bool(reads(v, pattern)) for v in vs] for vs in oriented]
        out.append((name, sum(any(h) for h in hits), sum(sum(h) for h in hits)))
    return out


def committed_census() -> dict | None:
    """The summary "census" of reports/census.json of the source checkout (``certify census``),
    or None; its per-word records are not read (:func:`certify.run.files.read_first_member`)."""
    from pathlib import Path
    try:
        return read_first_member(Path(__file__).resolve().parents[1] / "reports" / "census.json", "census")
    except (KeyError, ValueError):
        return None


def readings_evidence(pattern: str) -> str:
    """The counterexamples of the committed census under each reading of l. 515."""
    doc = committed_census()
    if not doc:
        return "No committed census (reports/census.json): run `python -m certify census --max-length 16`."
    feasible = doc["feasible"]
    rows = [f"| {name} | {a} | {b} |" for name, a, b in reading_counts(feasible, pattern)]
    return ("How \"contains ... as a subsequence\" is read, and the counterexamples under each reading among the "
            f"{len(feasible)} classes with feasible self-similar data of the committed census (periods of at most "
            f"{doc['max_length']} collisions, reports/CENSUS.md):\n\n"
            f"| Reading of \"contains {pattern}\" | classes, with the mirror {mirrored(pattern)} | oriented patterns, "
            "without the mirror |\n|---|---:|---:|\n" + "\n".join(rows))


@certificate("T28", printed=PRINTED_T28,
             expect=ERRATUM,
             mutants=[overridden({"pattern": "abxab"}, "not a word of the letters a, b, c: not read")])
def abcab_census(pattern):
    """Every class of periodic block patterns of at most LENGTH collisions that contains
    the printed pattern (cyclically, or its mirror) analysed exactly, and the census's
    shortest counterexamples: is any feasible?"""
    if not re.fullmatch(r"[abc]+", pattern or ""):
        return conclude([Check(f"the printed pattern {pattern!r} was read (a word over a, b, c)", False)])
    mirror = pattern.translate(str.maketrans("ac", "ca"))
    words = census.words(LENGTH)
    brute = brute_force_classes(LENGTH)
    checks = [Check(f"the census enumerates every class of primitive block periods of at most {LENGTH} collisions "
                    f"once: {len(words)} normal forms (FKM tree), the same classes as the brute-force enumeration "
                    f"of all block sequences ({len(brute)})",
                    {least_rotation(w) for w in words} == brute and len(words) == len(brute), counts=False)]
    within = lambda w: census.contains(w, pattern) or census.contains(w, mirror)     # noqa: E731
    scope = [w for w in words if within(w)]
    extra = [w for w in FOUND if within(w) and w not in scope]
    records = [census.self_similar_record(w) for w in scope + extra]
    for r in records:
        r.pop(census.SECONDS, None)
    feasible = [r for r in records if r["feasible"]]
    unchecked = [r for r in records if r["outcome"] == "error" or r["undecided"]]
    ev = [f"words of at most {LENGTH} collisions: {len(words)} classes; containing {pattern} or {mirror} "
          f"cyclically: {len(scope)} ({', '.join(scope) or 'none'}); the others: "
          + ", ".join(w for w in words if w not in scope),
          f"counterexamples found by `certify census` and analysed here: {', '.join(extra) or 'none (not in scope)'}"]
    for r in records:
        line = f"`{r['compact']}` ({' '.join(r['blocks'])}): "
        if r["outcome"] == "error":
            line += f"analysis error: `{r['error']}`"
        else:
            line += f"{r['verdict']}; feasible on {_sets(r, 'feasible')}; stable on {_sets(r, 'stable')}"
            if r["undecided"]:
                line += "; undecided: " + "; ".join(r["result"]["undecided"])
        ev.append(line)
    ev.append(readings_evidence(pattern))
    named = f"{len(scope)} of at most {LENGTH} collisions" + (f" and {', '.join(extra)}" if extra else "")
    printed = Check(f"no periodic block pattern containing {pattern} (cyclically, or its mirror {mirror}) has "
                    f"feasible self-similar data: checked on the {named}, each decided and infeasible on every "
                    "branch and fixed point",
                    bool(records) and not feasible and not unchecked,
                    ([f"not decided: {', '.join(r['word'] for r in unchecked)}"] if unchecked else [])
                    + ([f"feasible: {', '.join(r['word'] for r in feasible)}"] if feasible else []))
    printed = witnessed(printed, "T28.1", *FOUND[1:])
    corrected = []
    if feasible:
        replays = [replay(r) for r in feasible]
        corrected.append(witnessed(Check(
            f"periodic patterns containing {pattern} (or {mirror}) can have feasible self-similar data: "
            + "; ".join(f"{r['word']} = {' '.join(r['blocks'])} on {_sets(r, 'feasible')}" for r in feasible)
            + f" (certified), the exact dynamics from each datum repeating the word for {PERIODS} periods",
            all(ok for ok, _ in replays), [text for _, text in replays], corrects=printed), "T28.2", *FOUND[1:]))
    return conclude(checks + [printed], corrected, evidence=ev, kind=REFUTED_REMARK,
                    misprint="l. 515, Remark 3.3: a pattern containing abcab 'does not seem to have feasible initial data'",
                    note=f"An empirical remark, tested on every pattern of at most {LENGTH} collisions containing "
                         f"{pattern} and on the shortest counterexamples of the census (reports/CENSUS.md: "
                         "`python -m certify census --max-length L`).")


# ---------------------------------------------------------------- the conclusion's open questions (l. 1214-1215), on the census
# T28.3 (l. 1215): "what is the upper threshold of r for which inelastic collapse can occur (stable or
# not)?"; the paper's known threshold is r_exist ≈ 0.19166, where abcb's self-similar collapse ends
# (l. 1099-1102, L3).  T28.4 (l. 1214-1215): whether "any such periodic and asymmetric pattern is always
# unstable", whether (ab)^n(cb)^n "are the only patterns that are stable in some region of r".
#
# What is checked.  The committed census (reports/census.json, ``certify census --max-length 20``):
# every class of primitive block periods (Corollary 4.5 with S10) of at most 20 collisions analysed
# exactly by ``certify pattern``; read here, not recomputed (an hour on two cores).  T28.3: the census
# has every class (its word count is the FKM tree's, :func:`certify.patterns.census.words`), none in
# error, no point left undecided above r_exist (the printed digits of each undecided point, certified
# to 10 digits, against r_exist's isolating interval), and the largest end of all the feasible sets
# (exact: algebraic ends compared by their isolating intervals and minimal polynomials) is r_exist,
# reached by abcb — re-analysed here.  So, over the periodic patterns of at most 20 collisions,
# feasible self-similar data exist exactly for r < r_exist: the threshold of *self-similar* collapse.
# (Collapse along a non-periodic pattern, or a periodic one of more collisions, is not covered: the
# bound is part of the statement.)  T28.4: the stable words of the census are the printed ones (ab and
# (ab)^n(cb)^n), and no point left undecided in another word could be stable: each is at a multiple
# eigenvalue of its branch (the eigenspace route), where strict dominance fails exactly.
PRINTED_T28_3 = dict(word="abcb", P="17r^6-138r^5+831r^4-3148r^3+831r^2-138r+17", r_exist="0.19166",
                   max_length="20")
PRINTED_T28_4 = dict(stable="ab, (ab)^n(cb)^n", max_length="20")
EIGENSPACE_ROUTE = "(no datum of the eigenspace found)"     # the undecided text of the eigenspace route


@for_a_run
def census_records() -> tuple[dict, list[dict]] | None:
    """(summary, records) of the committed census (reports/census.json), its records as written
    (:func:`certify.run.census_report.brief`); None without one."""
    import json
    from pathlib import Path
    try:
        doc = json.loads((Path(__file__).resolve().parents[1] / "reports" / "census.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return doc["census"], doc["words"]


def _undecided(record: dict) -> list[str]:
    """A record's undecided self-similar points (their texts)."""
    return (record.get("result") or {}).get("undecided") or []


def _bound(max_length: str) -> int:
    """The printed bound on the collisions, as an integer (-1 when it is not a number)."""
    return int(max_length) if max_length.isdigit() else -1


def _census_scope(max_length: str):
    """(summary, records, checks): the committed census read, and the check that it holds every
    class of at most ``max_length`` collisions, none in error."""
    found = census_records()
    if found is None:
        return None, [], [Check("the committed census reports/census.json was read", False)]
    summary, records = found
    bound = _bound(max_length)
    n = len(census.words(bound)) if 0 < bound <= summary["max_length"] else None
    errors = [r["word"] for r in records if r["outcome"] != "analysed"]
    return summary, records, [Check(
        f"the committed census holds every class of primitive block periods of at most {max_length} collisions "
        f"({n if n is not None else 'not covered'}: the FKM tree), each analysed exactly, none in error",
        n is not None and len({r["word"] for r in records}) == n == summary["words"] and not errors,
        [f"census to {summary['max_length']}: {summary['words']} words; errors: {', '.join(errors) or 'none'}"])]


@certificate("T28.3", printed=PRINTED_T28_3,
             expect=PASS,
             mutants=[replaced("r_exist", "0.19166", "0.19167", "a digit of r_exist"),
                      replaced("P", "831r^4", "832r^4", "a coefficient of P"),
                      overridden({"word": "ababcb"}, "another word (its data end at 5-2√6)"),
                      overridden({"max_length": "21"}, "a longer bound than the census's")])
def threshold_of_collapse(word, P, r_exist, max_length):
    """The largest r with feasible self-similar data over every periodic pattern of at most
    ``max_length`` collisions (the committed census) is r_exist, the root of P, where ``word``'s end."""
    poly = to_fmpz_poly(parse(re.sub(r"(\d)\s*r", r"\1*r", P)))
    roots = Algebraic.roots(poly, 0, 1)
    checks = [Check(f"P = {P} has exactly one root r_exist in ]0, 1[, ≈ {r_exist}",
                    len(roots) == 1 and roots[0].in_rounding_interval(r_exist),
                    ["roots in ]0,1[: " + ("; ".join(a.describe() for a in roots) or "none")])]
    if len(roots) != 1:
        return conclude(checks)
    re_ = roots[0]
    res = whole_pattern(expand_pattern(word))
    top = max((p.lo if p.is_point else p.hi) for R in res.regions["feasible"] for p in R.pieces) \
        if res.feasible else None
    checks.append(witnessed(Check(f"{word}'s feasible self-similar data reach r_exist and none lie above it: the "
                                  "supremum of its feasible set (every branch and fixed point) is the root of P",
                                  top is not None and top == re_, [f"feasible: {_sets_of(res)}"]), "T28.3.1", word))
    summary, records, scope = _census_scope(max_length)
    re_.refine(Fraction(1, 10 ** 12))
    above = [f"{r['word']}: {u}" for r in records for u in _undecided(r)
             if census_report.undecided_r(u) + Fraction(1, 10 ** 9) >= Fraction(int(re_.lo.p), int(re_.lo.q))]
    highest, at_top = census_report.highest_feasible(records)
    beyond = sorted({r["word"] for r in records for e in census_report.feasible_ends(r)
                     if re_ < census.end_number(e)})
    census_word = census.normal_form(expand_pattern(word))[0] if records else ""
    checks += scope + [named("T28.3.2", Check(
        f"no periodic pattern of at most {max_length} collisions has feasible self-similar data for r > r_exist: "
        f"the largest end of the feasible sets of the committed census is r_exist, reached by {word}, and no "
        "point above r_exist is left undecided",
        bool(records) and highest == re_ and census_word in at_top and not beyond and not above,
        [f"largest end: {highest.describe() if highest is not None else 'none'}, reached by "
         f"{', '.join(at_top) or 'none'}", f"ends above r_exist: {', '.join(beyond) or 'none'}",
         f"undecided points at or above r_exist: {'; '.join(above) or 'none'}",
         f"undecided points below it: {sum(len(_undecided(r)) for r in records) - len(above)} in "
         f"{len(summary['undecided']) if summary else 0} words (census.json)"]))]
    return conclude(checks, evidence=[f"`certify pattern {word}`: {res.verdict}"],
                    note="Self-similar collapse along a periodic pattern of at most "
                         f"{max_length} collisions exists exactly for r < r_exist ≈ {r_exist}: the threshold asked at "
                         "l. 1215, within the bound (the committed census, `python -m certify census --max-length "
                         f"{max_length}`; non-periodic patterns and longer periods are not covered).")


def _sets_of(res) -> str:
    return "; ".join(f"{s['branch']} {s['fixed_point']}: {s['set']}" for s in res.feasible) or "∅"


def _allowed(printed: str, max_length: int):
    """The normal forms of the printed words ("ab, (ab)^n(cb)^n": the family of L4-L6, n ≥ 2 — n = 1
    is abcb, unstable (L3.5) — expanded up to ``max_length`` collisions), as a list of (item, normal
    forms)."""
    out = []
    for item in (t.strip() for t in printed.split(",")):
        if "^n" in item:
            forms = [expand_pattern(item.replace("^n", f"^{n}")) for n in range(2, max_length // 4 + 1)]
        else:
            forms = [expand_pattern(item)]
        out.append((item, {census.normal_form(w)[0] for w in forms if len(w) <= max_length}))
    return out


@certificate("T28.4", printed=PRINTED_T28_4,
             expect=PASS,
             mutants=[overridden({"stable": "(ab)^n(cb)^n"}, "ab left out"),
                      overridden({"stable": "ab, (ab)^n(cb)^n, ababcb"}, "an asymmetric word named stable"),
                      overridden({"max_length": "21"}, "a longer bound than the census's")])
def stable_patterns(stable, max_length):
    """The periodic patterns of at most ``max_length`` collisions with stable self-similar data are
    exactly the printed ones (the committed census): every asymmetric one is unstable."""
    summary, records, checks = _census_scope(max_length)
    try:
        allowed = _allowed(stable, max(_bound(max_length), 0))
    except ValueError as exc:
        return conclude(checks + [Check(f"the printed words {stable!r} were read", False, [str(exc)])])
    names = set().union(*(forms for _, forms in allowed)) if allowed else set()
    found = [r["word"] for r in records if r["stable"]]
    others = [w for w in found if w not in names]
    missing = [item for item, forms in allowed if not forms & set(found)]
    doubtful = [f"{r['word']}: {u}" for r in records if r["word"] not in names for u in _undecided(r)
                if EIGENSPACE_ROUTE not in u]
    checks.append(named("T28.4.1", Check(
        f"up to {max_length} collisions the periodic patterns with stable self-similar data are {stable} (each "
        "has a stable member), no other: every asymmetric one is unstable; the points left undecided in the others "
        "are at a multiple eigenvalue (not strictly dominant: never stable)",
        bool(records) and not others and not missing and not doubtful,
        [f"stable in the census: {', '.join(found) or 'none'}", f"others: {', '.join(others) or 'none'}",
         f"printed but none stable: {', '.join(missing) or 'none'}",
         f"undecided points not at a multiple eigenvalue: {'; '.join(doubtful) or 'none'}"])))
    return conclude(checks, note=f"Read on the committed census (every class of at most {max_length} collisions); "
                                 "longer periods are not covered.")
