"""Section 1.3 (l. 126-142) and Section 5 (l. 1096-1128, 1212-1215): the facts from the
literature that the paper quotes, certified with the same engine as ``certify pattern``.

L1  three particles (ab): no collapse above 7-4√3, stable collapse below (l. 131);
L2  the symmetric system [ac]b: no collapse above 3-2√2 (l. 132);
L3  abcb: collapsing data exactly below r_exist ≈ 0.19166, the only root of P in [0,1],
    and unstable (l. 132, 1101);
L4  the upper stability thresholds of (ab)^n(cb)^n, n = 2..6, as printed (l. 1114-1120);
L5  the stability windows of (ab)^2(cb)^2 and (ab)^3(cb)^3 (l. 1123-1125); for every n ≥ 2, the
    windows disjoint, accumulating on 7-4√3 from above (l. 1215, the paper's open problem);
L6  CDKK's conjecture: the upper threshold is where q_2(0) = 0 (l. 1215), for every n ≥ 2.

L5 and L6 for every n: n ≤ N0 = 30 from reports/family.json (``certify family --n-max 30``, the
exact windows, read back only while its digest is that of the source), n > 30 from the proof of
certify/patterns/family_limit.py (``prove``, re-verified by ``check``, within the run).

Remark 3.2 (T26, the threshold 5-2√6 of (ab)^3(cb)^3) is in proofs/section3_remarks.py.
"""
from __future__ import annotations

import json
import re
from fractions import Fraction

from certify.algebra import Algebraic, parse, radical, to_field, to_fmpz_poly
from certify.dynamics import candidate
from certify.patterns import analyse, end_number, family_windows, fmt, known_factors, vanishes_on_branch
from certify.patterns import parse as parse_word
from certify.run import (
    PASS,
    Check,
    certificate,
    conclude,
    for_a_run,
    load_findings,
    named,
    overridden,
    plots,
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


def witnessed(check: Check, ref: str, *words: str, data: list = ()) -> Check:
    """``check`` deciding the formal statement ``ref``, with the factors of the words' candidates
    as its witness, and the ``data`` found at multiple eigenvalues (``PatternResult.data``: the
    kernel re-runs each where its candidate degenerates)."""
    check.witnesses = list(check.witnesses or []) + witness("factors", words=list(words),
                                                              factors=known_factors(*words)) \
        + [i for d in data for i in witness("datum", **d)]
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


def stable_sets(word: str):
    """`certify pattern word` over ]0, 1[ without the eigenspace route (L4-L6 read only the stable
    sets, which it does not change: no point of a multiple eigenvalue is stable)."""
    return analyse(word, eigenspace=False)


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
                                       "undecided: " + ("; ".join(res.undecided) or "none")]), "L3.3", word,
                  data=res.data),
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
                         "discriminant): there the eigenvector is not determined by the eigen-equation's rows; the "
                         "engine decides the point on the plane of eigenvectors of the double eigenvalue, and gives "
                         "the kernel a datum of that plane realising abcb, which the kernel moves exactly.")


def ab_cb(n: int) -> str:
    return f"(ab)^{n}(cb)^{n}"


KERNEL_FACTORS = tuple(ab_cb(n) for n in range(2, 6))   # L5.3 and L6.6: the kernel decides n = 2..5 as in L4 (their factors)


@quantity("ab_cb_patterns")
def ab_cb_patterns():
    """`certify pattern (ab)^n(cb)^n` over ]0, 1[ for n = 2..N_MAX: the heavy part of L4-L6,
    computed once per run (the three certificates form one unit of the runner)."""
    return {n: stable_sets(ab_cb(n)) for n in range(2, N_MAX + 1)}


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
            ev.append(f"{ab_cb(n)}: {ab_cb_patterns[n].verdict}" + (
                " (points of a multiple eigenvalue, undecided here for existence and feasibility only: the eigenspace "
                "route is not run for L4-L6, and no such point is stable; `certify pattern` decides them)"
                if ab_cb_patterns[n].undecided else ""))
    return conclude(checks, evidence=ev)


# ---------------------------------------------------------------- L5, L6 for every n ≥ 2
# n = 2..7: `certify pattern`'s exact analysis of each w_n (ab_cb_patterns, ab_cb_seven).
# n ≥ 8: family_limit's theorem (prove(7), re-verified by check: family_windows.theorem), and for
# n = 8..N0 its windows as exact algebraic numbers (family_windows.proved_window: ℓ_n the one root of
# F_n in ]r_(n+1), r_n[, counted exactly).  reports/family.json (`certify family --n-max 30`, the
# engine's analysis of each n, half an hour) is the second route for n = 8..30: compared where current.

N0 = family_windows.EXACT_N0                 # the exact windows listed: n = 2..30
PROVED_FROM = family_windows.PROVED_N0 + 1   # the theorem: every n ≥ 8
FAMILY = "family.json"
FAMILY_COMMAND = f"python -m certify family --n-max {N0}"


@quantity("ab_cb_seven")
def ab_cb_seven():
    """`certify pattern (ab)^7(cb)^7` over ]0, 1[ (about 25 s): the last n below the theorem."""
    return stable_sets(ab_cb(PROVED_FROM - 1))


@quantity("ab_cb_limit")
def ab_cb_limit():
    """family_limit's proof for every n ≥ 8 (prove(7), then check: about 8 s) and the exact windows it
    gives for n = 8..N0 (about 10 s): {"facts", "failures", "windows": {n: (ℓ_n, r_n)}}."""
    return {**family_windows.theorem(), "windows": {n: family_windows.proved_window(n)
                                                    for n in range(PROVED_FROM, N0 + 1)}}


def family_document(source=FAMILY) -> dict | None:
    """The committed reports/family.json (None when absent), or ``(name, edits)`` for the mutation
    tests: ``{"digest": text}`` replaces its digest (a stale document); ``{"lo": n}`` moves lo_n to
    lo_(n+1) (the engine's route then disagrees with the proof's)."""
    name, edits = (source, {}) if isinstance(source, str) else source
    doc = load_findings(name)
    if not doc or not edits:
        return doc
    doc = json.loads(json.dumps(doc))
    if "digest" in edits:
        doc["digest"] = edits["digest"]
    if "lo" in edits:
        recs = {w["n"]: w for w in doc["windows"]}
        recs[edits["lo"]]["lo"] = recs[edits["lo"] + 1]["lo"]
    return doc


def second_route(doc: dict | None, proved: dict) -> Check | None:
    """The engine's windows of family.json (when current: computed by this source) against the
    proof's for n = 8..N0, exact comparisons; None (a line of evidence instead) when it is absent or
    stale: the proof does not need it."""
    if doc is None or not family_windows.is_current(doc):
        return None
    recs = {rec["n"]: rec for rec in doc.get("windows", [])}
    differ = []
    for n, (lo, hi) in sorted(proved.items()):
        rec = recs.get(n)
        if not (rec and rec.get("one_interval") and end_number(rec["lo"]) == lo and end_number(rec["hi"]) == hi):
            differ.append(n)
    return Check(f"the second route: the engine's exact analysis of each w_n (reports/{FAMILY}) gives the same "
                 f"window for n = {PROVED_FROM}..{N0}", not differ,
                 [f"differs at n = {', '.join(map(str, differ))}" if differ else "the same ends, exactly"])


def _route_note(doc: dict | None) -> str:
    """Why family.json was not compared (absent or stale)."""
    if doc is None:
        return f"reports/{FAMILY} (the engine's route for n ≤ {N0}) is absent: not compared"
    if not family_windows.is_current(doc):
        return (f"reports/{FAMILY} (the engine's route for n ≤ {N0}) was computed by another source (digest "
                f"{str(doc.get('digest'))[:12]}…): not compared; `{FAMILY_COMMAND}` recomputes it (about 30 min)")
    return f"reports/{FAMILY} compared"


def _fq(x: Fraction) -> float:
    return float(x)


def _limit_evidence(limit: dict) -> list[str]:
    """The constants and margins of family_limit's facts, and its check's verdict."""
    facts, bad = limit["facts"], limit["failures"]
    ev = [f"family_limit.check: {'every fact re-verified (200 bits)' if not bad else 'FAILS: ' + '; '.join(bad[:5])}",
          f"s* = π²(7√3 − 12)/6 ∈ [{_fq(facts['s_star'][0]):.12f}, {_fq(facts['s_star'][1]):.12f}], "
          f"κ ∈ [{_fq(facts['kappa'][0]):.9f}, {_fq(facts['kappa'][1]):.9f}]; |n²(r_n − r*) − s*| ≤ C/n², C = {facts['C']} "
          f"({len(facts['boxes'])} ε-boxes over [0, 1/{facts['N0']}])"]
    lower = facts.get("lower")
    if lower:
        boxes = lower["boxes"]
        ev.append(f"the lower end: every zero of F_n in [r_(n+1), r_n] in a strip η ∈ "
                  f"[{_fq(min(b['eta'][0] for b in boxes)):.4f}, {_fq(max(b['eta'][1] for b in boxes)):.4f}] of the "
                  f"blow-up φ = nθ = π − η/n; n²(ℓ_n − r*) ∈ [{_fq(min(b['s_lo'][0] for b in boxes)):.7f}, "
                  f"{_fq(max(b['s_lo'][1] for b in boxes)):.7f}]; margin to r_(n+1): η ≥ "
                  f"{_fq(min(b['margin'] for b in boxes)):.3f} ({len(boxes)} ε-boxes over [0, 1/{lower['N0'] + 1}])")
    return ev


def large_n_windows(limit: dict, lim, order: str) -> Check:
    """L5.3 for every n ≥ 8, from family_limit's facts (parts 3, 5): r_{n+1} < ℓ_n < r_n, and
    n²(ℓ_n − r*), n²(r_n − r*) in proved boxes above 0 and bounded."""
    facts, bad = limit["facts"], limit["failures"]
    lower = facts.get("lower")
    ends_ok = (not bad and facts["N0"] == PROVED_FROM - 1 and lower is not None and lower["N0"] == PROVED_FROM - 1
               and all(b["margin"] > 0 and b["s_lo"][0] > 0 for b in lower["boxes"])
               and all(b["s_hi"][0] > 0 for b in facts["boxes"]))
    holds = ends_ok and lim == family_windows.r_star() and "disjoint" in order and "above" in order
    return Check(f"for every n ≥ {PROVED_FROM}: the window W_n = ]ℓ_n, r_n[ — r_n where q_2(0) = 0 (nθ = π, the root "
                 "of r² − (6 + 8cos(π/n))r + 1), ℓ_n where x₊ crosses 0 (a zero of F_n) — has r_(n+1) < ℓ_n < r_n, "
                 f"and n²(ℓ_n − r*), n²(r_n − r*) lie in proved boxes above 0 and bounded: the windows are "
                 f"{order.split(',')[0]} and decreasing, and accumulate on {lim.digits(10)} from above "
                 "(family_limit parts 3, 5)", holds, _limit_evidence(limit))


def stable_cover(limit: dict) -> tuple[Check | None, object]:
    """What family_limit proves of the whole stable set for n ≥ 8 (parts 9-12, when its facts have
    them): the check, and R (the stable set is known on ]0, R]; None: nowhere).  Part 11 (nothing
    feasible on [r₀, 1[ for every n ≥ 3) extends R to 1 when r₀ ≤ part 10's R; parts 12 (the
    reflection M = N² and one zero of F_n per strip) decide the points of the strip I_n."""
    facts, bad = limit["facts"], limit["failures"]
    if not all(k in facts for k in ("positions", "below", "arcs")):
        return None, None
    R = facts["arcs"]["r"][1]
    third = facts.get("third_a")
    if third and third["r"][0] <= R and third["r"][1] >= 1 and third["n_min"] <= PROVED_FROM:
        R = third["r"][1]
    exact = "one_zero" in facts and "reflection" in facts
    inside = ("the stable set is exactly ]ℓ_n, r_n[, ℓ_n the one zero of F_n in its strip (family_limit parts 9-12)"
              if exact else "which points of one interval I_n inside the strip are stable is not decided "
              "(family_limit parts 9, 10)")
    return Check(f"for every n ≥ {PROVED_FROM}: in ]0, {R}] the stable set of (ab)^n(cb)^n lies in ]r_(n+1), r_n[ "
                 f"(nothing stable in ]0, r_(n+1)] nor in ]r_n, {R}]) and holds every r from the strip of the lower end "
                 f"up to r_n; {inside}", not bad,
                 [f"positions: {len(facts['positions']['boxes'])} ε-boxes; below: {len(facts['below']['far'])} + "
                  f"{len(facts['below']['low'])} leaves; above r_n: up to {facts['arcs']['r'][1]} (part 10)"
                  + (f", and nothing feasible on [{third['r'][0]}, 1[ for every n ≥ {third['n_min']} (part 11: "
                     f"t ≤ {third['t_max']} there, so the second or third a's pair separates)" if third else "")
                  + ("; part 12: M = N² (N = J M_ab^n), stable exactly where F_n < 0, dF_n/dη > 0 on every strip"
                     if exact else ""),
                  "family_limit.check: " + ("every fact re-verified" if not bad else "FAILS")]), R


def engine_windows(ab_cb_patterns: dict, ab_cb_seven) -> dict:
    """The engine's windows of n = 2..7 (None where the stable set is not one interval)."""
    return {**{n: stable_window(ab_cb_patterns, n) for n in range(2, N_MAX + 1)},
            PROVED_FROM - 1: stable_window({PROVED_FROM - 1: ab_cb_seven}, PROVED_FROM - 1)}


def exact_windows(engine: dict, proved: dict, lim, limit: str, order: str) -> Check:
    """L5.3 for n = 2..N0, exact: n ≤ 7 the engine's stable sets (each one open interval), n = 8..N0 the
    proof's ]ℓ_n, r_n[ (exact ends); every window above the limit and hi_{n+1} < lo_n (exact comparisons
    of algebraic numbers, r_8 < lo_7 joining the two routes)."""
    ws = {**engine, **proved}
    missing = [n for n in range(2, N0 + 1) if ws.get(n) is None]
    meets = [n for n in range(2, N0) if n not in missing and n + 1 not in missing and not ws[n + 1][1] < ws[n][0]]
    low = [n for n, w in ws.items() if w is not None and not lim < w[0]]
    holds = not missing and not meets and not low and "disjoint" in order and "above" in order
    rows = [f"n = {n}: ]{w[0].digits(10)}, {w[1].digits(10)}[" + (" (engine)" if n in engine else " (proof)")
            for n, w in sorted(ws.items()) if w is not None]
    return Check(f"for n = 2..{N0}, exact: each stable set is one open interval W_n = ]lo_n, hi_n[ (n ≤ "
                 f"{PROVED_FROM - 1}: `certify pattern`; n ≥ {PROVED_FROM}: the proof's ]ℓ_n, r_n[, ℓ_n the one root of "
                 f"F_n in ]r_(n+1), r_n[), above {limit}, and W_(n+1) lies below W_n with a gap (hi_(n+1) < lo_n): "
                 f"{order.split(',')[0]}, decreasing", holds,
                 [f"n = {n}: the stable set is not one interval" for n in missing]
                 + [f"W_{n + 1} meets W_{n}: hi_{n + 1} ≥ lo_{n}" for n in meets]
                 + [f"lo_{n} ≤ {limit}" for n in low] + rows)


def figure(ws: dict, limit: dict) -> str:
    """n²(W_n − r*) against 1/n: the exact windows as bars, the proved boxes of the ends for n > N0."""
    rs = float(family_windows.r_star())
    exact = [(n, n * n * (float(lo) - rs), n * n * (float(hi) - rs)) for n, (lo, hi) in sorted(ws.items())]
    facts, band = limit["facts"], []
    for b in (facts.get("lower") or {}).get("boxes", []):
        e0, e1 = b["eps"]
        if e0 >= Fraction(1, N0):
            continue
        his = [h["s_hi"] for h in facts["boxes"] if h["eps"][0] < e1 and e0 < h["eps"][1]]
        if his:
            band.append((_fq(e0), _fq(min(e1, Fraction(1, N0))), (_fq(b["s_lo"][0]), _fq(b["s_lo"][1])),
                         (_fq(min(h[0] for h in his)), _fq(max(h[1] for h in his)))))
    return plots.family_windows_figure(exact, band)


PRINTED_L5 = dict(n2="[0.12754, 0.17157]", n3="[0.09452, 0.10102]", limit="7-4√3",
                  order="disjoint, accumulating on 7-4√3 from above", family=FAMILY)


@certificate("L5", needs=["ab_cb_patterns", "ab_cb_seven", "ab_cb_limit"], printed=PRINTED_L5,
             expect=PASS,
             mutants=[replaced("n2", "0.12754", "0.12755", "a digit of the n = 2 window"),
                      replaced("n3", "0.10102", "0.10103", "a digit of the n = 3 window"),
                      replaced("order", "disjoint", "overlapping", "the windows' order"),
                      replaced("order", "above", "below", "the side of the accumulation"),
                      replaced("limit", "7-4√3", "3-2√2", "the limit of the windows")])
def windows(ab_cb_patterns, ab_cb_seven, ab_cb_limit, n2, n3, limit, order, family):
    """The stable sets of (ab)^n(cb)^n: n = 2, 3 rounding to the printed windows (`certify pattern`);
    for every n ≥ 2 the whole stable set in ]0, 1[ one open interval W_n, the W_n disjoint, decreasing,
    accumulating on 7-4√3 from above — n ≤ 7 by the engine's exact analysis, n ≥ 8 by family_limit's
    theorem (its windows exact for n ≤ 30); family.json, the engine's route to n = 30, compared when current."""
    checks = []
    for n, text in ((2, n2), (3, n3)):
        lo_d, hi_d = (t.strip() for t in text.strip("[] ").split(","))
        w = stable_window(ab_cb_patterns, n)
        checks.append(witnessed(Check(f"the stability window of {ab_cb(n)} is ≈ {text}",
                                      w is not None and w[0].in_rounding_interval(lo_d) and w[1].in_rounding_interval(hi_d),
                                      [f"stable: {_sets(ab_cb_patterns[n], 'stable')}"]
                                      + ([f"lower end: {w[0].describe()}", f"upper end: {w[1].describe()}"] if w else [])),
                                f"L5.{n - 1}", ab_cb(n)))
    lim = radical(limit)
    engine, proved = engine_windows(ab_cb_patterns, ab_cb_seven), ab_cb_limit["windows"]
    cover, R = stable_cover(ab_cb_limit)
    doc = family_document(family)
    parts = [exact_windows(engine, proved, lim, limit, order), large_n_windows(ab_cb_limit, lim, order)]
    parts += [c for c in (cover, second_route(doc, proved)) if c is not None]
    holds = all(c.holds for c in parts)
    whole = holds and R is not None and R >= 1
    gap = ("the stable set outside the windows (family_limit's facts have no parts 9, 10)" if R is None
           else f"the stable set in ]{R}, 1[ (family_limit proves nothing there)")
    if not whole:
        parts[1].evidence.append(f"NOT proved: for n ≥ {PROVED_FROM}, {gap}; the windows W_n are disjoint, the whole "
                                 "stable sets are not certified to be")
    checks += parts
    checks.append(witnessed(Check(
        f"for every n ≥ 2 the windows of (ab)^n(cb)^n are {order}: the {len(parts)} checks above"
        + (" (the whole stable sets: the paper's open problem, proved)" if whole else ""), holds,
        ["every part holds" if holds else "a part fails: " + "; ".join(c.statement[:80] for c in parts if not c.holds)]
        + ([] if whole else [f"NOT certified: for n ≥ {PROVED_FROM}, {gap}"])),
        "L5.3", *KERNEL_FACTORS))
    note = ("The paper's open problem (l. 1215: the intervals of stability \"seem to be disjoint and accumulate from "
            "above … but this has also not been proven yet\"): " + (
                f"proved for every n ≥ 2: the stable set of (ab)^n(cb)^n in ]0, 1[ is one open interval W_n (n ≤ "
                f"{PROVED_FROM - 1}: `certify pattern`, exact; n ≥ {PROVED_FROM}: exactly ]ℓ_n, r_n[, r_n the root in "
                "]0, 1[ of r² − (6 + 8cos(π/n))r + 1, ℓ_n the one zero of F_n in ]r_(n+1), r_n[, by family_limit's "
                f"theorem, its ends exact for n ≤ {N0}), the W_n disjoint, decreasing and accumulating on 7−4√3 "
                "from above. " if whole else
                f"proved for the windows W_n of every n ≥ 2 and for the whole stable sets of n ≤ {PROVED_FROM - 1}. "
                f"NOT certified: for n ≥ {PROVED_FROM}, {gap}. ")
            + f"{_route_note(doc)}. The figure: n²(W_n − (7−4√3)) against 1/n, the exact windows of n ≤ {N0} as "
              f"bars, the proved boxes of the ends for n > {N0}; both ends tend to s* = π²(7√3−12)/6 ≈ 0.20456.")
    return conclude(checks, note=note, figures=[figure({**engine, **proved}, ab_cb_limit)],
                    evidence=[f"`certify pattern` for n ≤ {PROVED_FROM - 1}; certify/patterns/family_limit.py "
                              f"(prove({PROVED_FROM - 1}), check) for n ≥ {PROVED_FROM}; {_route_note(doc)}"])


PRINTED_L6 = dict(criterion="q_2(0) = 0", branch="dominant")


def large_n_q2(limit: dict) -> list[Check]:
    """L6 for every n ≥ 8 from family_limit (parts 2, 7; part 9 for the window's upper end)."""
    facts, bad = limit["facts"], limit["failures"]
    dom = facts.get("dominant")
    upto = dom['r'][1] if dom else '?'
    out = [named("L6.6.1", Check(f"for every n ≥ {PROVED_FROM}: on ]0, {upto}] the eigenvalue λ ≈ 1/9 is real, "
                 "simple and strictly dominant (part 7), and q_2(0) has the sign of sin(nθ) there (part 2): it vanishes "
                 "at r_n (nθ = π), is > 0 on ]r*, r_n[ and < 0 just above r_n", not bad and dom is not None,
                 _limit_evidence(limit)[:1] + ([f"λ ∈ [{_fq(dom['lambda'][0]):.9f}, {_fq(dom['lambda'][1]):.9f}], "
                                                f"|μ|, |ν| ≤ {_fq(dom['others']):.3g}"] if dom else ["no part 7"])))]
    out.append(named("L6.6.2", Check(f"for every n ≥ {PROVED_FROM} nothing in ]r_n, 1/4] is stable: q_2(0) < 0 where "
                                     "π < nθ < 2π, = 0 at 2π (part 7), a b of (ab)^n separates where nθ > 2π (part 10)",
                                     not bad and dom is not None and "arcs" in facts,
                                     [f"part 10 up to r = {facts['arcs']['r'][1]}" if "arcs" in facts else "no part 10"])))
    third = facts.get("third_a")
    out.append(named("L6.6.3", Check("for every n ≥ 3 nothing in [0.1716, 1[ is feasible: ℓ₂ = tℓ₁ + r² with t < 0 "
                                     "(part 11)", not bad and third is not None,
                                     [f"t ≤ {_fq(third['t_max']):.3g} on [{third['r'][0]}, 1]" if third else
                                      "no part 11"])))
    out.append(named("L6.6.4", Check(f"for every n ≥ {PROVED_FROM} every velocity condition holds on ]r*, r_n[ "
                                     "(part 8); just above r_n the last b of (ab)^n separates (part 2's sign of q_2)",
                                     not bad and "velocity" in facts,
                                     [f"margins ≥ {min(_fq(m) for m in facts['velocity']['margins'].values()):.3g}"
                                      if "velocity" in facts else "no part 8"])))
    out.append(named("L6.6.5", Check(f"for every n ≥ {PROVED_FROM} the stable set reaches r_n from below (every r "
                                     "between the lower end's strip and r_n stable, part 9): the window's upper end "
                                     "hi_n is r_n", not bad and "positions" in facts,
                                     [f"positions: {len(facts['positions']['boxes'])} ε-boxes" if "positions" in facts
                                      else "no part 9"])))
    return out


@certificate("L6", needs=["ab_cb_patterns", "ab_cb_seven", "ab_cb_limit"], printed=PRINTED_L6,
             expect=PASS,
             mutants=[replaced("criterion", "q_2(0)", "q_3(0)", "another component of the eigenvector"),
                      replaced("branch", "dominant", "lower", "another eigenvalue branch")])
def q2_vanishes_at_threshold(ab_cb_patterns, ab_cb_seven, ab_cb_limit, criterion, branch):
    """For each n = 2..7 (`certify pattern`): at the upper end r_n of the stability window, the
    numerator of u = q_2(0) vanishes on the dominant (upper) branch (exact test in Q(r_n)[λ]) and
    its denominator does not; for every n ≥ 8 family_limit's proof (parts 2, 7, 9)."""
    if criterion.replace(" ", "") != "q_2(0)=0" or branch not in ("dominant", "upper"):
        return conclude([Check(f"the criterion read: {criterion} on the {branch} branch", False,
                               ["only `q_2(0) = 0` on the dominant branch is implemented"])])
    rows, results = [], {}
    engine = engine_windows(ab_cb_patterns, ab_cb_seven)
    for n, w in engine.items():
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
    checks = [named(f"L6.{n - 1}", Check(f"{ab_cb(n)}: q_2(0) = 0 on the dominant branch at the upper threshold",
                                          ok, [row for row in rows if row.startswith(f"n = {n}:")]))
              for n, ok in results.items() if n <= N_MAX]
    small = [n for n in results if n > N_MAX]
    parts = [Check(f"{ab_cb(n)}: q_2(0) = 0 on the dominant branch at the upper threshold", results[n],
                   [row for row in rows if row.startswith(f"n = {n}:")]) for n in small]
    parts.append(named("L6.6.6", Check(f"{ab_cb(6)} and {ab_cb(7)}: the stable set is one window whose upper end r_n "
                                       "is where q_2(0) = 0 on the dominant branch (`certify pattern`, exact)",
                                       all(results.get(n) for n in (6, 7)),
                                       [row for row in rows if row.startswith(("n = 6:", "n = 7:"))])))
    parts += large_n_q2(ab_cb_limit)
    whole = all(c.holds for c in parts)                # L6.6.5 (among parts) needs family_limit's part 9
    checks += parts
    checks.append(witnessed(Check(
        f"for every n ≥ 2, {criterion} on the {branch} branch at the upper end of the window: the checks above",
        all(c.holds for c in checks),
        ["every part holds" if all(c.holds for c in checks) else "a part fails"]
        + ([] if whole else [f"NOT certified: for n ≥ {PROVED_FROM}, that r_n is the upper end of the stable set"])),
        "L6.6", *KERNEL_FACTORS))
    note = ("CDKK's conjecture (l. 1215), tested, not assumed: " + (
        "proved for every n ≥ 2 — the upper end of the window of (ab)^n(cb)^n is where q_2(0) = 0 on the dominant "
        "branch, r_n, the root of r² − (6 + 8cos(π/n))r + 1 (n ≤ 7: exact zero tests; n ≥ 8: family_limit's theorem)."
        if whole else
        f"proved for n ≤ {PROVED_FROM - 1} (exact) and, for n ≥ {PROVED_FROM}, that q_2(0) vanishes exactly at r_n on "
        "the dominant branch and changes sign there; that r_n is the upper end of the stable set is NOT certified."))
    return conclude(checks, note=note)
