"""The stability windows of (ab)^n(cb)^n for n = 2..N, one by one (``certify family``).

For each n, :func:`window` runs ``certify pattern``'s exact analysis of w_n (the family route of
:mod:`.family`) over ]0, 1[ and reads off its stable set; then it checks, exactly:

1. the stable set is one open interval W_n = ]lo_n, hi_n[ on one branch and fixed point (no
   isolated point);
2. lo_n > r* = 7 − 4√3 (comparison of algebraic numbers);
3. hi_n is a zero of q_2(0) on that branch (CDKK's conjecture, L6): the numerator of u = q_2(0)
   vanishes there on the branch and its denominator does not (exact zero tests in Q(hi_n)[λ]);

and :func:`check_windows` checks across n that hi_{n+1} < lo_n.  A check that fails is reported
with its n, never assumed.  The sets are certified as in ``certify pattern`` (algebraic end
points); the undecided points of the analysis are counted in each record.  The analysis runs without
the eigenspace route (``analyse(eigenspace=False)``, as L4-L6 do): that route decides points where two
eigenvalues meet, where nothing is stable, so the stable set is the same and the undecided points are
such points (n = 30 in about 6 min instead of hours).

The document carries :func:`code_digest`, the sha256 of the source it was computed with (the exact
algebra, the models, the pattern analysis): a reader (L5, L6) uses a committed family.json only
while :func:`is_current` holds, and asks for ``certify family --n-max N`` otherwise.
"""
from __future__ import annotations

import functools
import hashlib
import time
from concurrent.futures import as_completed
from pathlib import Path

import flint

from certify.algebra.algebraic import Algebraic
from certify.algebra.branches import BRANCH_NAMES, less
from certify.algebra.poly import to_field
from certify.dynamics.systems import candidate_in

from . import family_limit
from .census import end_number
from .family import family_word, turning_bound
from .feasibility import vanishes_on_branch
from .pattern import analyse, end_data

SCHEMA = "certify-family"

CERTIFY = Path(__file__).resolve().parent.parent
# the source the windows depend on (what `import certify.patterns.family_windows` loads, less the
# patterns' __init__ and island theorem, which the analysis does not call), relative to certify/
DEPENDS = ("algebra", "dynamics", "caches.py", "errors.py", "witnesses.py", "patterns/census.py",
           "patterns/eigenspace.py", "patterns/family.py", "patterns/family_windows.py", "patterns/feasibility.py",
           "patterns/pattern.py", "patterns/periodic.py")


def code_digest(root: Path = CERTIFY) -> str:
    """sha256 of the source files of :data:`DEPENDS` under ``root``, each by its relative path."""
    h = hashlib.sha256()
    files = []
    for name in DEPENDS:
        path = root / name
        files += sorted(path.glob("*.py")) if path.is_dir() else [path]
    for path in files:
        h.update(path.relative_to(root).as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
    return h.hexdigest()


def is_current(doc: dict) -> bool:
    """Whether a family.json document was computed by this source (its digest matches)."""
    return doc.get("schema") == SCHEMA and doc.get("digest") == code_digest()


def r_star() -> Algebraic:
    """r* = 7 − 4√3, the root of r² − 14r + 1 in ]0, 1[."""
    return Algebraic.roots(flint.fmpq_poly([1, -14, 1]), 0, 1)[0]


def window(n: int) -> tuple[dict, tuple | None]:
    """The record of w_n (JSON, no timing: a committed report holds none) and its window (lo, hi) as
    Algebraic numbers (None when the stable set is not one interval)."""
    word = family_word(n)
    res = analyse(word, formulas=False, eigenspace=False)   # stable sets: the eigenspace route leaves them as they are
    spans, points = res.intervals("stable"), res.points("stable")
    record = {"n": n, "word": f"(ab)^{n}(cb)^{n}", "stable": [s["set"] for s in res.stable],
              "undecided": len(res.undecided)}
    if len(spans) != 1 or points:
        record.update(one_interval=False)
        return record, None
    branch, fixed_point, lo, hi = spans[0]
    cand = candidate_in("four", word)
    u = to_field(cand.q0[1])
    record.update(one_interval=True, branch=BRANCH_NAMES[branch], fixed_point=fixed_point,
                  lo=end_data(lo), hi=end_data(hi), above_r_star=less(r_star(), lo),
                  hi_zero_of_u=vanishes_on_branch(cand.spectrum, u.numer, hi, branch)
                  and not vanishes_on_branch(cand.spectrum, u.denom, hi, branch))
    return record, (lo, hi)


def check_windows(records: list[dict], ends: list) -> dict:
    """The checks across n: every record one interval above r* with hi_n a zero of q_2(0), and
    hi_{n+1} < lo_n for consecutive n (exact); the first n where one fails, with the reason."""
    for rec in records:
        for key, what in (("one_interval", "the stable set is not one interval"),
                          ("above_r_star", "lo_n ≤ 7 − 4√3"),
                          ("hi_zero_of_u", "q_2(0) does not vanish at hi_n on the branch")):
            if not rec.get(key):
                return {"all_hold": False, "first_failure": {"n": rec["n"], "reason": what}}
    for (a, pa), (b, pb) in zip(zip(records, ends), zip(records[1:], ends[1:])):
        if not less(pb[1], pa[0]):
            return {"all_hold": False, "first_failure": {"n": b["n"], "reason": f"hi_{b['n']} ≥ lo_{a['n']}"}}
    return {"all_hold": True, "first_failure": None}


def _timed_record(n: int) -> tuple[dict, float]:
    """w_n's record and its seconds (plain data, for a worker process)."""
    start = time.perf_counter()
    rec, _ = window(n)
    return rec, time.perf_counter() - start


def _ends(rec: dict) -> tuple | None:
    """The window's ends of a record, read back as algebraic numbers (each root recounted in its
    isolating interval)."""
    return (end_number(rec["lo"]), end_number(rec["hi"])) if rec.get("one_interval") else None


def windows(n_max: int, progress=None, pool=None) -> tuple[dict, list[float]]:
    """The document of ``certify family --n-max N`` (a record per n = 2..N and the checks) and the
    seconds each n took (printed, not recorded).  ``pool``: an executor (``submit``) that analyses
    the n in parallel, the largest first; the document is the same, record for record."""
    ns = list(range(2, n_max + 1))
    if pool is None:
        results = {}
        for i, n in enumerate(ns):
            if progress:
                progress(i, len(ns), f"n = {n}")
            start = time.perf_counter()
            rec, pair = window(n)
            results[n] = rec, pair, time.perf_counter() - start
    else:
        futures = {pool.submit(_timed_record, n): n for n in reversed(ns)}
        results = {}
        for i, fut in enumerate(as_completed(futures)):
            rec, sec = fut.result()
            results[futures[fut]] = rec, _ends(rec), sec
            if progress:
                progress(i + 1, len(ns), f"n = {futures[fut]}")
    if progress:
        progress(len(ns), len(ns), "")
    records = [results[n][0] for n in ns]
    ends = [results[n][1] for n in ns]
    seconds = [results[n][2] for n in ns]
    doc = {"schema": SCHEMA, "version": 1, "n_max": n_max, "digest": code_digest(), "windows": records,
           **check_windows(records, ends)}
    return doc, seconds


# ---------------------------------------------------------------- the windows the proof gives, n ≥ 8
PROVED_N0 = 7        # family_limit.prove(7) covers every part of the proof for n ≥ 8 (docs/family-limit.md)
EXACT_N0 = 30        # `certify pattern` runs the engine's exact analysis up to n = 30, the theorem beyond


@functools.lru_cache(maxsize=1)
def theorem(n0: int = PROVED_N0) -> dict:
    """family_limit's facts for every n > n0 (prove(n0)) and the failures of their re-verification at
    another precision (check: empty when every fact holds); about 8 s, once per process."""
    facts = family_limit.prove(n0)
    return {"facts": facts, "failures": family_limit.check(facts)}


def proved_window(n: int) -> tuple[Algebraic, Algebraic]:
    """(ℓ_n, r_n), exact, for n > PROVED_N0: r_n = ρ_n (turning_bound: the least root of s_n in ]0, 1[,
    where nθ = π), ℓ_n the root of F_n (family_limit.lower_polynomial) in ]r_(n+1), r_n[, counted
    exactly — ArithmeticError when there is not exactly one (the proof says there is).  That the stable
    set of w_n in ]0, 1[ is exactly ]ℓ_n, r_n[ is family_limit's theorem (parts 1-12), valid where
    :func:`theorem`'s failures are empty."""
    if n <= PROVED_N0:
        raise ValueError(f"the proof covers n ≥ {PROVED_N0 + 1}, not n = {n}")
    below, r_n = turning_bound(n + 1), turning_bound(n)
    F = family_limit.lower_polynomial(n)
    zeros = [a for a in Algebraic.roots(F, below.lo, r_n.hi) if less(below, a) and less(a, r_n)]
    if len(zeros) != 1:
        raise ArithmeticError(f"F_{n} has {len(zeros)} zeros in ]r_{n + 1}, r_{n}[, not one")
    return zeros[0], r_n


def theorem_record(n: int) -> dict:
    """The window of w_n (n > PROVED_N0) by the proof, as ``certify pattern`` gives it for n > N0:
    the stable set (one region, upper branch, x₊, exact ends), what proves it, what is not computed."""
    proof = theorem()
    lo, hi = proved_window(n)
    ok = not proof["failures"]
    word = family_word(n)
    return {"schema": THEOREM_SCHEMA, "version": 1, "input": f"(ab)^{n}(cb)^{n}", "normal_form": word, "n": n,
            "route": "theorem", "proof_holds": ok, "failures": proof["failures"][:5],
            "stable": [{"branch": "upper", "fixed_point": "x₊", "set": f"]≈{lo.digits(10)}, ≈{hi.digits(10)}[",
                        "pieces": [{"kind": "interval", "lo": end_data(lo), "hi": end_data(hi)}]}] if ok else [],
            "undecided": [] if ok else ["the whole of ]0, 1[: the proof's facts do not hold"],
            "lower_end": f"the only zero of F_{n} in ]r_{n + 1}, r_{n}[ (x₊ = 0: family_limit part 4)",
            "upper_end": f"r_{n}, where nθ = π: the root in ]0, 1[ of r² − (6 + 8cos(π/{n}))r + 1 (q_2(0) = 0, part 2)",
            "not_computed": "the feasible sets of every branch (the engine's route: hours beyond n = 30)",
            "verdict": (f"(ab)^{n}(cb)^{n}: stable self-similar collapse exactly for r in ]{lo.digits(10)}, "
                        f"{hi.digits(10)}[ (upper branch, x₊), proved for every n ≥ {PROVED_N0 + 1}" if ok else
                        f"(ab)^{n}(cb)^{n}: NOT decided: the proof's facts do not hold "
                        f"({'; '.join(proof['failures'][:2])})")}


THEOREM_SCHEMA = "certify-family-window"


def theorem_markdown(rec: dict) -> str:
    """``certify pattern``'s Markdown for a family word beyond N0 (:func:`theorem_record`)."""
    n = rec["n"]
    lines = [f"# Pattern {rec['input']}", "",
             f"- input: `{rec['input']}`, the family (ab)^n(cb)^n with n = {n}: decided by the theorem of "
             f"certify/patterns/family_limit.py (docs/family-limit.md), proved for every n ≥ {PROVED_N0 + 1} by "
             f"prove({PROVED_N0}), re-verified within this run by check: "
             + ("every fact holds" if rec["proof_holds"] else "FAILS: " + "; ".join(rec["failures"])), ""]
    if rec["proof_holds"]:
        lo, hi = rec["stable"][0]["pieces"][0]["lo"], rec["stable"][0]["pieces"][0]["hi"]
        lines += ["## Stable (λ dominant, fixed point attracting)", "",
                  f"- upper branch, x₊: ]≈{lo['digits']}, ≈{hi['digits']}[ — the whole stable set in ]0, 1[, "
                  "no undecided point", "", "End points:",
                  f"  - {lo['digits']}: {rec['lower_end']}; the root of `{lo['minimal_polynomial']}` in "
                  f"]{lo['interval'][0]}, {lo['interval'][1]}[",
                  f"  - {hi['digits']}: {rec['upper_end']}; the root of `{hi['minimal_polynomial']}` in "
                  f"]{hi['interval'][0]}, {hi['interval'][1]}[", ""]
    lines += [f"Not computed on this route: {rec['not_computed']}.", "", f"**Verdict:** {rec['verdict']}"]
    return "\n".join(lines) + "\n"
