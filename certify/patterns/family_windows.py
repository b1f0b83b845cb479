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
points); the undecided points of the analysis are counted in each record.

The document carries :func:`code_digest`, the sha256 of the source it was computed with (the exact
algebra, the models, the pattern analysis): a reader (L5, L6) uses a committed family.json only
while :func:`is_current` holds, and asks for ``certify family --n-max N`` otherwise.
"""
from __future__ import annotations

import hashlib
import time
from concurrent.futures import as_completed
from pathlib import Path

import flint

from certify.algebra.algebraic import Algebraic
from certify.algebra.branches import BRANCH_NAMES, less
from certify.algebra.poly import to_field
from certify.dynamics.systems import candidate_in

from .census import end_number
from .family import family_word
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
    res = analyse(word, formulas=False)
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
