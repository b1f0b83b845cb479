"""Section 1.3 (l. 126-142) and Section 5 (l. 1096-1128, 1212-1215): the facts from the
literature that the paper quotes, certified with the same engine as ``certify pattern``.

L1  three particles (ab): no collapse above 7-4√3, stable collapse below (l. 131);
L2  the symmetric system [ac]b: no collapse above 3-2√2 (l. 132);
L3  abcb: collapsing data exactly below r_exist ≈ 0.19166, the only root of P in [0,1],
    and unstable (l. 132, 1101);
L4  the upper stability thresholds of (ab)^n(cb)^n, n = 2..6, as printed (l. 1114-1120);
L5  the stability windows of (ab)^2(cb)^2 and (ab)^3(cb)^3, disjoint, accumulating on
    7-4√3 from above (l. 1123-1125, 1215);
L6  CDKK's conjecture: the upper threshold is where q_2(0) = 0 (l. 1215).

Remark 3.2 (T26, the threshold 5-2√6 of (ab)^3(cb)^3) is in proofs/section3_remarks.py.
"""
from __future__ import annotations

import re

from certify.algebra import Algebraic, parse, radical, to_field, to_fmpz_poly
from certify.dynamics import candidate
from certify.patterns import analyse, fmt, known_factors, vanishes_on_branch
from certify.patterns import parse as parse_word
from certify.run import (
    PASS,
    Check,
    certificate,
    conclude,
    for_a_run,
    named,
    overridden,
    quantity,
    replaced,
    witness,
)


def expand_pattern(pattern: str) -> str:
    """"(ab)^3(cb)^3" -> "abababcbcbcb" (:func:`certify.patterns.parse`; ValueError on a bad word)."""
    try:
        word = parse_word(pattern)
    except Exception as exc:          # the engine's UsageError: one line
        raise ValueError(f"cannot read the pattern {pattern!r}: {exc}") from None
    if "s" in word:
        raise ValueError(f"cannot read the pattern {pattern!r} as a four-particle word")
    return word


def witnessed(check: Check, ref: str, *words: str) -> Check:
    """``check`` deciding the formal statement ``ref``, with the factors of the words' candidates
    as its witness."""
    check.witnesses = list(check.witnesses or []) + witness("factors", words=list(words),
                                                              factors=known_factors(*words))
    return named(ref, check)


# ---------------------------------------------------------------- L1-L6: the literature, through `certify pattern`
# Every certificate below reads the printed numbers as text (radicals by certify.algebra.radical,
# decimals by Algebraic.in_rounding_interval) and compares them with the exact regions of
# certify.patterns.analyse: the same analysis as `python -m certify pattern WORD`.

N_MAX = 6                      # (ab)^n(cb)^n analysed for n = 2..N_MAX (about a minute in all)


@for_a_run
def pattern(word: str):
    """`certify pattern word` over ]0, 1[ (memoised for the certificates of one run)."""
    return analyse(word)


def _pieces(res, stage: str, branch: int | None = None) -> list:
    return [(R, p) for R in res.regions[stage] if branch is None or R.branch == branch for p in R.pieces]


def _top(pieces):
    return max((p.lo if p.is_point else p.hi) for _, p in pieces) if pieces else None


def _sets(res, stage: str) -> str:
    return "; ".join(f"{s['branch']} {s['fixed_point']}: {s['set']}" for s in getattr(res, stage)) or "∅"


def _printed_value(text: str):
    """"3-2√2 ≃ 0.17157" -> (the radical, "0.17157")."""
    value, _, digits = (t.strip() for t in text.replace("≈", "≃").partition("≃"))
    return radical(value), digits


def _digits_check(name: str, a, digits: str) -> Check:
    return Check(f"{name} ≈ {digits} (the printed digits)", bool(digits) and a.in_rounding_interval(digits),
                 [f"{name} = {a.describe()}"])


def _threshold_certificate(word, threshold, digits, what, refs: dict):
    """No self-similar datum above the threshold, stable self-similar data on all of
    ]0, threshold[ (an open set of initial data: positive measure), the feasible set's
    supremum; ``refs``: the formal statements (statements/1_literature.txt) the checks decide,
    by "digits", "above", "stable", "sup" (those printed)."""
    res = pattern(word)
    thr = radical(threshold)
    exists = _pieces(res, "exists")
    feas = _pieces(res, "feasible")
    checks = [_digits_check(threshold, thr, digits),
              Check(f"for r > {threshold} no self-similar datum of {word} exists on any branch "
                    f"(λ > 0 real, u > 0{', x > 0' if res.system == 'four' else ''})",
                    bool(exists) and _top(exists) <= thr, [f"exists: {_sets(res, 'exists')}"]),
              Check(f"for every r in ]0, {threshold}[ the self-similar datum of {word} (upper branch) is feasible "
                    f"and stable ({what})",
                    any(lo == 0 and hi == thr for _, _, lo, hi in res.intervals("stable", 0)),
                    [f"stable: {_sets(res, 'stable')}", f"conditions: {'; '.join(res.conditions['stable'])}"]),
              Check(f"{threshold} is the largest r where the self-similar datum of {word} is feasible",
                    bool(feas) and _top(feas) == thr, [f"feasible: {_sets(res, 'feasible')}"]),
              Check("every point of ]0, 1[ decided", not res.undecided, res.undecided)]
    for check, key in zip(checks, ("digits", "above", "stable", "sup")):
        if key in refs:
            witnessed(check, refs[key], word) if key != "digits" else named(refs[key], check)
    ev = [f"`certify pattern {word}`: {res.verdict}", "M = `[" + ", ".join("[" + ", ".join(row) + "]" for row in res.matrix) + "]`", f"cp = `{res.cp}`",
          f"disc = `{res.discriminant}`", f"feasible: {_sets(res, 'feasible')}"]
    return checks, ev


PRINTED_L1 = dict(word="ab", threshold="7-4√3", digits="0.07180")


@certificate("L1", printed=PRINTED_L1,
             expect=PASS,
             mutants=[replaced("threshold", "7-4√3", "7-4√2", "another radical"),
                      replaced("digits", "0.07180", "0.07181", "a digit"),
                      replaced("word", "ab", "[ac]b", "the symmetric four-particle word"),
                      overridden({"threshold": "7-4√"}, "a radical without its argument")])
def three_particles(word, threshold, digits):
    """`certify pattern ab` (three particles, 2x2 matrices): the self-similar data exist
    exactly for r ≤ 7-4√3 and are stable on ]0, 7-4√3[."""
    checks, ev = _threshold_certificate(word, threshold, digits, "λ dominant: an open set of initial data",
                                        dict(digits="L1.1", above="L1.2", stable="L1.3", sup="L1.4"))
    return conclude(checks, evidence=ev,
                    note="Three particles collapse only through the pattern ab repeated (CDKK, McNamara-Young); "
                         "what is certified is that pattern's self-similar datum: none for r > 7-4√3, a stable "
                         "one for every r < 7-4√3 (at r = 7-4√3 itself the eigenvalue is double: a datum exists, "
                         "not stable).")


PRINTED_L2 = dict(word="[ac]b", threshold="3-2√2", digits="0.17157")


@certificate("L2", printed=PRINTED_L2,
             expect=PASS,
             mutants=[replaced("threshold", "3-2√2", "3-2√3", "another radical"),
                      replaced("digits", "0.17157", "0.17158", "a digit")])
def symmetric_system(word, threshold, digits):
    """`certify pattern [ac]b` (p_1 = p_3, the [ac] collision applies A and C at once,
    reduced to two gaps): no self-similar datum for r > 3-2√2, stable below."""
    checks, ev = _threshold_certificate(word, threshold, digits, "in the symmetric system", dict(above="L2.1"))
    return conclude(checks, evidence=ev,
                    note="The symmetric system's only pattern is [ac]b repeated; its self-similar datum exists "
                         "exactly for r ≤ 3-2√2.")


PRINTED_L3 = dict(word="abcb", P="17r^6-138r^5+831r^4-3148r^3+831r^2-138r+17", r_exist="0.19166",
                  stability="unstable")


@certificate("L3", printed=PRINTED_L3,
             expect=PASS,
             mutants=[replaced("P", "831r^4", "832r^4", "a coefficient of P"),
                      replaced("r_exist", "0.19166", "0.19167", "a digit of r_exist"),
                      replaced("stability", "unstable", "stable", "the stability")])
def abcb_exists(word, P, r_exist, stability):
    """`certify pattern abcb`: the union over branches and fixed points of the feasible
    sets is ]0, r_exist] minus the points the engine leaves undecided; nothing stable."""
    res = pattern(word)
    poly = to_fmpz_poly(parse(re.sub(r"(\d)\s*r", r"\1*r", P)))     # "17r^6": implicit products
    roots = Algebraic.roots(poly, 0, 1)
    at_ends = [e for e in (0, 1) if poly(e) == 0]
    re_ = roots[0] if len(roots) == 1 else None
    feas = _pieces(res, "feasible")
    checks = [named("L3.1", Check(f"P = {P} has exactly one root in [0,1]", len(roots) == 1 and not at_ends,
                                  ["roots in ]0,1[: " + ("; ".join(a.describe() for a in roots) or "none")]))]
    if re_ is None:
        return conclude(checks)
    checks.append(named("L3.2", _digits_check("r_exist", re_, r_exist)))
    # the feasible set covers ]0, r_exist[ up to the undecided points
    cuts = sorted({p.lo for _, p in feas if not p.is_point} | {p.hi for _, p in feas if not p.is_point})
    ends = [Algebraic.rational(0)] + [c for c in cuts if 0 < c < re_] + [re_]
    gaps = []
    for a, b in zip(ends, ends[1:]):
        if not any(not p.is_point and p.lo <= a and b <= p.hi for _, p in feas):
            gaps.append(f"]{fmt(a)}, {fmt(b)}[")
    inner = [c for c in ends[1:-1]]
    uncovered_points = [c for c in inner if not any((p.is_point and p.lo == c) or (not p.is_point and p.lo < c < p.hi)
                                                    for _, p in feas)]
    undecided = [u for R in res.regions["feasible"] for u in R.undecided]
    explained = all(any(c == rc for rc, _ in undecided) for c in uncovered_points)
    ends_at_root = bool(feas) and _top(feas) == re_
    checks += [
        witnessed(Check(f"for every r in ]0, r_exist[ (r_exist = the root of P) the candidate of {word} is feasible on some "
              f"branch and fixed point, except at the point(s) "
              f"{', '.join(fmt(c) for c in uncovered_points) or 'none'} where the engine is undecided "
              "(a double eigenvalue: u is 0/0 in every row of the eigen-equation)",
              not gaps and explained, [f"feasible: {_sets(res, 'feasible')}", f"gaps: {gaps or 'none'}",
                                       "undecided: " + ("; ".join(res.undecided) or "none")]), "L3.3", word),
        witnessed(Check(f"for r > r_exist no feasible candidate of {word}", ends_at_root,
                        [f"sup of the feasible set: {fmt(_top(feas)) if feas else '∅'}"]), "L3.4", word),
        witnessed(Check(f"{word} is {stability}: no stable self-similar datum for any r in ]0,1[",
                        stability == "unstable" and not res.stable and bool(res.feasible),
                        [f"stable: {_sets(res, 'stable')}; conditions {'; '.join(res.conditions['stable'])}"]),
                  "L3.5", word),
    ]
    return conclude(checks, evidence=[f"`certify pattern {word}`: {res.verdict}", f"cp = `{res.cp}`",
                                      f"disc = `{res.discriminant}`", f"exists: {_sets(res, 'exists')}"],
                    note="r_exist is where the feasible branches end (a root of the discriminant: two eigenvalues "
                         "meet). At 3-2√2 the two upper eigenvalues cross (the factor (r²-6r+1)² of the "
                         "discriminant): there the eigenvector is not determined by the eigen-equation's rows and "
                         "the engine leaves the point undecided; it is named in the check.")


def ab_cb(n: int) -> str:
    return f"(ab)^{n}(cb)^{n}"


@quantity("ab_cb_patterns")
def ab_cb_patterns():
    """`certify pattern (ab)^n(cb)^n` over ]0, 1[ for n = 2..N_MAX: the heavy part of L4-L6,
    computed once per run (the three certificates form one unit of the runner)."""
    return {n: pattern(ab_cb(n)) for n in range(2, N_MAX + 1)}


def stable_window(patterns: dict, n: int):
    """The stable set of (ab)^n(cb)^n on the upper branch: (lo, hi) when it is one open
    interval (for one fixed point), else None."""
    res = patterns[n]
    ivs = res.intervals("stable")
    if len(ivs) == 1 and not res.points("stable") and ivs[0][0] == 0:
        return ivs[0][2], ivs[0][3]
    return None


PRINTED_L4 = {f"n{n}": t for n, t in ((2, "3-2√2 ≃ 0.17157"), (3, "5-2√6 ≃ 0.10102"),
                                       (4, "3 + 2√2 - 2√(4 + 3√2) ≃ 0.08643"),
                                       (5, "4 + √5 - 2√(5 + 2√5) ≃ 0.08070"),
                                       (6, "3 + 2√3 - 2√(5 + 3√3) ≃ 0.07782"))}


@certificate("L4", needs=["ab_cb_patterns"], printed=PRINTED_L4,
             expect=PASS,
             mutants=[replaced("n4", "4 + 3√2", "4 + 3√3", "a radicand of the n = 4 threshold"),
                      replaced("n6", "0.07782", "0.07783", "a digit of the n = 6 threshold"),
                      replaced("n2", "3-2√2", "5-2√6", "the n = 3 threshold for n = 2")])
def upper_thresholds(ab_cb_patterns, **printed):
    """For each n the stable set of `certify pattern (ab)^n(cb)^n` is one interval of
    the upper branch; its upper end is proven equal to the printed radical (minimal
    polynomial and isolating interval), and the digits are its rounding."""
    checks, ev = [], []
    for i, key in enumerate(sorted(printed, key=lambda k: int(k[1:]))):
        n = int(key[1:])
        value, digits = _printed_value(printed[key])
        radical_text = printed[key].replace("≈", "≃").partition("≃")[0].strip()
        w = stable_window(ab_cb_patterns, n) if n in ab_cb_patterns else None
        checks.append(witnessed(Check(f"n = {n}: the upper stability threshold of {ab_cb(n)} is {radical_text}",
                                      w is not None and w[1] == value,
                                      [f"stable: {_sets(ab_cb_patterns[n], 'stable')}" if n in ab_cb_patterns
                                       else f"n = {n} is beyond the analysed n ≤ {N_MAX}",
                                       f"printed: {value.describe()}"] + ([f"computed: {w[1].describe()}"] if w else [])),
                              f"L4.{2 * i + 1}", *([ab_cb(n)] if n in ab_cb_patterns else [])))
        checks.append(named(f"L4.{2 * i + 2}", _digits_check(radical_text, value, digits)))
        if n in ab_cb_patterns:
            ev.append(f"{ab_cb(n)}: {ab_cb_patterns[n].verdict}")
    return conclude(checks, evidence=ev)


PRINTED_L5 = dict(n2="[0.12754, 0.17157]", n3="[0.09452, 0.10102]", limit="7-4√3",
                  order="disjoint, accumulating on 7-4√3 from above")


@certificate("L5", needs=["ab_cb_patterns"], printed=PRINTED_L5,
             expect=PASS,
             mutants=[replaced("n2", "0.12754", "0.12755", "a digit of the n = 2 window"),
                      replaced("n3", "0.10102", "0.10103", "a digit of the n = 3 window"),
                      replaced("order", "disjoint", "overlapping", "the windows' order"),
                      replaced("limit", "7-4√3", "3-2√2", "the limit of the windows")])
def windows(ab_cb_patterns, n2, n3, limit, order):
    """The stable sets of (ab)^n(cb)^n (upper branch) for n = 2..N_MAX: each one open
    interval, ends rounding to the printed digits for n = 2, 3; pairwise disjoint,
    decreasing in n, all above 7-4√3."""
    checks = []
    for n, text in ((2, n2), (3, n3)):
        lo_d, hi_d = (t.strip() for t in text.strip("[] ").split(","))
        w = stable_window(ab_cb_patterns, n)
        checks.append(witnessed(Check(f"the stability window of {ab_cb(n)} is ≈ {text}",
                                      w is not None and w[0].in_rounding_interval(lo_d) and w[1].in_rounding_interval(hi_d),
                                      [f"stable: {_sets(ab_cb_patterns[n], 'stable')}"]
                                      + ([f"lower end: {w[0].describe()}", f"upper end: {w[1].describe()}"] if w else [])),
                                f"L5.{n - 1}", ab_cb(n)))
    ws = {n: stable_window(ab_cb_patterns, n) for n in range(2, N_MAX + 1)}
    lim = radical(limit)
    ok = all(w is not None for w in ws.values())
    decreasing = ok and all(ws[n + 1][1] <= ws[n][0] for n in range(2, N_MAX))
    strictly = ok and all(ws[n + 1][1] < ws[n][0] for n in range(2, N_MAX))
    above = ok and all(w[0] > lim for w in ws.values())
    rows = [f"n = {n}: ]{w[0].digits(10)}, {w[1].digits(10)}[" if w else f"n = {n}: not one interval"
            for n, w in ws.items()]
    checks.append(named("L5.3", Check(f"the windows of n = 2..{N_MAX} are {order.split(',')[0]} (each below the "
                                      f"previous, with a gap) and decreasing in n", "disjoint" in order and strictly, rows)))
    checks.append(named("L5.3", Check(f"every window n = 2..{N_MAX} lies above {limit} (= {lim.digits(10)}), the "
                                      f"distances decreasing", "above" in order and above and decreasing, rows)))
    return conclude(checks, note=f"The accumulation itself is a statement about all n: certified are the windows "
                                 f"n = 2..{N_MAX}, decreasing towards {limit} from above; the limit is the "
                                 "paper's (and CDKK's) belief, not proven here.")


PRINTED_L6 = dict(criterion="q_2(0) = 0", branch="dominant")


@certificate("L6", needs=["ab_cb_patterns"], printed=PRINTED_L6,
             expect=PASS,
             mutants=[replaced("criterion", "q_2(0)", "q_3(0)", "another component of the eigenvector")])
def q2_vanishes_at_threshold(ab_cb_patterns, criterion, branch):
    """For each n = 2..N_MAX: at the upper end r_n of the stability window, the numerator
    of u = q_2(0) vanishes on the dominant (upper) branch (exact test in Q(r_n)[λ]) and
    its denominator does not."""
    if criterion.replace(" ", "") != "q_2(0)=0" or branch not in ("dominant", "upper"):
        return conclude([Check(f"the criterion read: {criterion} on the {branch} branch", False,
                               ["only `q_2(0) = 0` on the dominant branch is implemented"])])
    rows, results = [], {}
    for n in range(2, N_MAX + 1):
        w = stable_window(ab_cb_patterns, n)
        cand = candidate(expand_pattern(ab_cb(n)))
        u = to_field(cand.q0[1].as_expr())
        if w is None:
            results[n] = False
            rows.append(f"n = {n}: no single stability window")
            continue
        zero = vanishes_on_branch(cand.spectrum, u.numer, w[1], 0)
        pole = vanishes_on_branch(cand.spectrum, u.denom, w[1], 0)
        results[n] = zero and not pole
        rows.append(f"n = {n}: r_n = {w[1].digits(10)}; numerator of q_2(0) = 0 there: {'yes' if zero else 'no'}; "
                    f"denominator = 0: {'yes' if pole else 'no'}")
    holds_for = [n for n, ok in results.items() if ok]
    return conclude([named(f"L6.{n - 1}", Check(f"{ab_cb(n)}: q_2(0) = 0 on the dominant branch at the upper threshold",
                                                 ok, [row for row in rows if row.startswith(f"n = {n}:")]))
                     for n, ok in results.items()],
                    note=f"Tested, not assumed: it holds for n = {', '.join(map(str, holds_for)) or 'none'}; "
                         "for larger n it is not tested here (see `certify pattern`).")
