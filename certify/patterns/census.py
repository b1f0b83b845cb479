"""A census of periodic collision patterns: every primitive period made of the blocks
ab, cb, acb, cab up to a length, analysed for feasible and stable self-similar data.

Which words.  By Corollary 4.5 (l. 1037-1051), read with the correction certified
in S10 (the pattern *without its first letter when that is b* is a concatenation of
the blocks ab, cb, acb, cab), a periodic pattern is a cyclic sequence of those
blocks.  Every block ends with its only b, so a cyclic word cuts into blocks in one
way only (after each b): cyclic words over the letters that are made of blocks are
in one-to-one correspondence with cyclic sequences of blocks, and a word is
primitive iff its block sequence is.  The census therefore enumerates Lyndon words
(primitive necklaces) over the four blocks, of total letter length at most L, with
the FKM tree of pre-necklaces (Ruskey's ``gen(t, p)``) pruned by length: nothing of
size 4^n is generated.  Rotations and the mirror a<->c describe the same orbits; the
mirror of a Lyndon word is rotated to the pattern module's normal form
(:func:`certify.patterns.periodic.normal_form`), which is the key of a class.

What is computed.  For each class, :func:`analyse_word` runs the pattern analysis
(:func:`certify.patterns.analyse`) and returns a JSON record: the feasible and the
stable r-sets as certified there, words with undecided points, and words whose
analysis raised (with the error: listed, never dropped).  The records are plain data
(the same bytes wherever they were computed), so a census may run on any executor.

T28 (l. 515) is about words containing abcab: :func:`contains` looks for a factor in
the bi-infinite periodic word, and :data:`ABCAB` with its mirror cbacb (a class
contains a word with abcab iff its mirror contains cbacb).
"""
from __future__ import annotations

import re
import traceback
from fractions import Fraction

import flint

from .. import caches
from .pattern import analyse
from .periodic import MIRROR, compact, normal_form, read

BLOCKS = ("ab", "acb", "cab", "cb")          # Corollary 4.5 (l. 1050), in the order a < b < c
ABCAB = "abcab"                               # T27, T28 (l. 513-515)
KEPT = ("normal_form", "system", "characteristic_polynomial", "exists", "feasible", "stable", "undecided",
        "diagnosis", "verdict")                # of the pattern's JSON: the r-sets and why (no formulas)


def lyndon_block_words(max_length: int) -> list[tuple[int, ...]]:
    """Every Lyndon word over the blocks (indices into :data:`BLOCKS`) whose letters
    number at most ``max_length`` (:func:`iter_lyndon_block_words` as a list)."""
    return list(iter_lyndon_block_words(max_length))


def iter_lyndon_block_words(max_length: int, exact: int | None = None):
    """The Lyndon words over the blocks of at most ``max_length`` letters (of exactly
    ``exact`` letters if given), one at a time: the FKM tree of pre-necklaces a_1 … a_t
    (a_t ≥ a_{t-p}; p the length of the longest Lyndon prefix period), a node kept when
    p = t, a branch cut as soon as its length exceeds the bound."""
    sizes = [len(b) for b in BLOCKS]
    a = [0] * (max_length + 2)

    def grow(t: int, p: int, length: int):
        if t > 1 and t - 1 == p and (exact is None or length == exact):
            yield tuple(a[1:t])
        for j in range(a[t - p], len(BLOCKS)):
            if length + sizes[j] <= max_length:
                a[t] = j
                yield from grow(t + 1, p if j == a[t - p] else t, length + sizes[j])

    if max_length >= min(sizes):
        yield from grow(1, 1, 0)


def spell(blocks: tuple[int, ...]) -> str:
    """The letters of a block sequence."""
    return "".join(BLOCKS[j] for j in blocks)


def words(max_length: int) -> list[str]:
    """One word per class (rotations and the mirror a<->c) of primitive periods made of
    blocks, of length at most ``max_length``: the pattern module's normal forms, sorted
    by length, then alphabetically (:func:`iter_words` as a list)."""
    return list(iter_words(max_length))


def words_of_length(length: int) -> list[str]:
    """The words of :func:`words` of exactly ``length`` letters, sorted (a class and its
    mirror have one length, so a length is enumerated on its own)."""
    return sorted({normal_form(spell(s))[0] for s in iter_lyndon_block_words(length, exact=length)})


def iter_words(max_length: int):
    """The words of :func:`words`, in that order, one length at a time: only the words of
    one length are held at once (2259 at 20, about 18 000 at 24), not the whole census."""
    if max_length < 1:
        raise ValueError(f"the maximal length must be positive, not {max_length}")
    for length in range(1, max_length + 1):
        yield from words_of_length(length)


def blocks_of(word: str) -> list[str]:
    """The cyclic block decomposition of a word made of blocks, read from its first
    letter (the normal form starts with a and ends with b, so it is block-aligned)."""
    out, start = [], 0
    for i, letter in enumerate(word):
        if letter == "b":
            out.append(word[start:i + 1])
            start = i + 1
    if start != len(word) or any(b not in BLOCKS for b in out):
        raise ValueError(f"{word!r} is not a concatenation of the blocks {', '.join(BLOCKS)}")
    return out


def contains(word: str, factor: str) -> bool:
    """``factor`` occurs in the bi-infinite periodic word …www…"""
    return factor in word * (len(factor) // len(word) + 2)


def contains_abcab(word: str) -> bool:
    """The class of ``word`` has a member containing abcab (cyclically): the word
    contains abcab or its mirror cbacb."""
    return contains(word, ABCAB) or contains(word, ABCAB.translate(MIRROR))


def analyse_word(word: str, lo=0, hi=1) -> dict:
    """The census record of one word (a normal form): its self-similar analysis as JSON
    (``certify pattern``), or the error that stopped it (one line), the seconds it took
    (:data:`SECONDS`, which :func:`certify.run.census_report.run_census` keeps out of the
    census), and its :data:`REDUCTION` part (:func:`add_reduction`).  Never raises for a
    word's sake.  The memos keyed by the word are forgotten after it
    (:func:`certify.caches.reset_words`): a census analyses a word once, and they held
    about 9 MB a word at 16 collisions, which ran a worker of the census to 20 out of
    memory at 12 GB."""
    try:
        return add_reduction(self_similar_record(word, lo, hi), lo, hi)
    finally:
        caches.reset_words()


def self_similar_record(word: str, lo=0, hi=1) -> dict:
    """The self-similar part of a census record (:func:`analyse_word`)."""
    import time
    start = time.perf_counter()
    record = {"word": word, "compact": compact(word), "length": len(word), "blocks": blocks_of(word),
              "contains_abcab": contains_abcab(word)}
    try:
        result = analyse(word, lo, hi, formulas=False)      # the census keeps no formulas (KEPT)
        data = {k: v for k, v in result.to_json().items() if k in KEPT}
        record.update(outcome="analysed", feasible=bool(result.feasible), stable=bool(result.stable),
                      undecided=bool(result.undecided), verdict=str(result.verdict), result=data, error=None)
    except Exception as exc:
        line = traceback.format_exception_only(type(exc), exc)[-1].strip()
        record.update(outcome="error", feasible=None, stable=None, undecided=None, verdict="error",
                      result=None, error=" ".join(line.split()))
    record[SECONDS] = round(time.perf_counter() - start, 3)
    return record


SECONDS = "seconds"          # the time of a record's analysis: kept in the state file, not in the census
REDUCTION = "reduction"      # the record's part on the periodic orbits of the reduction
REDUCTION_SECONDS = "reduction_seconds"      # its time: in the state file only, like SECONDS
TIMES = (SECONDS, REDUCTION_SECONDS)


def _brief(sets: list[dict]) -> list[dict]:
    """Per branch, the r-set as text only (the types other than attracting)."""
    return [{"branch": s["branch"], "set": s["set"]} for s in sets]


def reduction_part(word: str, lo=0, hi=1) -> dict:
    """The periodic orbits of the reduction with the word (:mod:`.reduction_orbits`,
    ``certify orbit``), without rerunning the pattern analysis: per real branch where
    the orbit exists and is feasible (r-sets in the end-point form of ``pattern``), the
    maximal open r-intervals where it is attracting with its in-plane pair, where it is a
    saddle or repelling and where the pair is complex (as text), the undecided points
    and the verdict.  A three-particle word has no orbit of the reduction of Section 4
    (outcome ``three particles``); an error is kept as one line."""
    from .reduction_orbits import analyse as analyse_orbits
    out = {"outcome": "analysed", "feasible": None, "attracting": None, "verdict": "", "result": None, "error": None}
    try:
        if read(word)[1] != "four":
            out.update(outcome="three particles", feasible=False, attracting=False,
                       verdict=f"{word}: a three-particle word: no orbit of the four-particle reduction (Section 4)")
            return out
        res = analyse_orbits(word, lo, hi, self_similar=False)
        att = res.attracting()
        out.update(feasible=bool(res.sets("feasible")), attracting=bool(att or res.attracting_points()),
                   verdict=res.verdict, result={
                       "exists": res.sets("exists"), "feasible": res.sets("feasible"), "attracting": att,
                       "attracting_points": res.attracting_points(), "saddle": _brief(res.sets("saddle")),
                       "repelling": _brief(res.sets("repelling")), "complex_pair": _brief(res.sets("complex")),
                       "undecided": res.undecided})
    except Exception as exc:
        line = traceback.format_exception_only(type(exc), exc)[-1].strip()
        out.update(outcome="error", verdict="error", error=" ".join(line.split()))
    return out


def add_reduction(record: dict, lo=0, hi=1) -> dict:
    """The record with its :data:`REDUCTION` part computed (and its seconds in
    :data:`REDUCTION_SECONDS`); the self-similar part is left as it is: a state record of
    an older census, which lacks the part, is completed without redoing the rest."""
    import time
    start = time.perf_counter()
    record = dict(record)
    record[REDUCTION] = reduction_part(record["word"], lo, hi)
    record[REDUCTION_SECONDS] = round(time.perf_counter() - start, 3)
    return record


def r_sets(record: dict, stage: str) -> list[tuple[str, str]]:
    """(branch and fixed point, set) of a record's r-sets at ``stage`` (exists, feasible,
    stable); [] for an error or an empty stage."""
    result = record.get("result") or {}
    return [(s["branch"] + ("" if s["fixed_point"] == "—" else " " + s["fixed_point"]), s["set"])
            for s in result.get(stage, [])]


def windows(record: dict, stage: str = "stable") -> list[tuple[float, float]]:
    """The open intervals of a record's r-sets at ``stage`` as floats (their certified
    12 digits), for drawing only."""
    result = record.get("result") or {}
    return sorted((float(p["lo"]["digits"]), float(p["hi"]["digits"])) for s in result.get(stage, [])
                  for p in s["pieces"] if p["kind"] == "interval")


SILVER = ("r^2 - 6r + 1", Fraction("0.171572875253809"), Fraction("0.171572875253810"))   # 3-2√2 (L2)


def is_ab_n_cb_n(word: str) -> bool:
    """The word is (ab)^n(cb)^n for some n ≥ 1, or ab (three particles)."""
    n = word.count("a")
    return word == "ab" or (n >= 1 and word == "ab" * n + "cb" * n)


def compare_end(end: dict, bound=SILVER) -> int | None:
    """The sign of (an end point of a pattern's r-set) - bound, from the certified data:
    equal when the minimal polynomials agree and the isolating intervals meet, else by
    disjoint certified intervals; None when neither decides."""
    lo, hi = (Fraction(x) for x in end["interval"])
    poly, blo, bhi = bound
    if end["minimal_polynomial"] == poly and lo <= bhi and blo <= hi:
        return 0
    if lo > bhi:
        return 1
    if hi < blo:
        return -1
    return None


def stable_findings(records) -> dict:
    """Stable words other than (ab)^n(cb)^n, and stable windows reaching above 3-2√2."""
    others, above, undecided = [], [], []
    for r in order(records):
        if not r["stable"]:
            continue
        if not is_ab_n_cb_n(r["word"]):
            others.append(r["word"])
        for s in r["result"]["stable"]:
            for p in s["pieces"]:
                end = p["hi"] if p["kind"] == "interval" else p["at"]
                sign = compare_end(end)
                if sign is None:
                    undecided.append(r["word"])
                elif sign > 0:
                    above.append(r["word"])
    return {"other_than_ab_n_cb_n": others, "above_3-2√2": sorted(set(above)),
            "undecided_against_3-2√2": sorted(set(undecided))}


def order(records) -> list[dict]:
    """Records in census order: by length, then word (the same order as :func:`words`)."""
    return sorted(records, key=lambda rec: (rec["length"], rec["word"]))


def summary(records, max_length: int) -> dict:
    """Counts and the lists a reader asks for first: the words with feasible data,
    with stable data, undecided, in error; the words with abcab and what they give."""
    recs = order(records)
    names = lambda pred: [r["word"] for r in recs if pred(r)]      # noqa: E731
    abcab = [r for r in recs if r["contains_abcab"]]
    return {
        "max_length": max_length,
        "words": len(recs),
        "feasible": names(lambda r: r["feasible"]),
        "stable": names(lambda r: r["stable"]),
        "undecided": names(lambda r: r["undecided"]),
        "errors": names(lambda r: r["outcome"] == "error"),
        "stable_findings": stable_findings(recs),
        "reduction": reduction_findings(recs),
        "abcab": {"words": len(abcab),
                  "feasible": [r["word"] for r in abcab if r["feasible"]],
                  "undecided_or_error": [r["word"] for r in abcab if r["outcome"] == "error" or r["undecided"]]},
    }


# --------------------------------------------------------------------------
# The reduction's findings: which words attract, the union of their windows, families

def _integer_poly(text: str) -> list[int]:
    """The coefficients (constant first) of an integer polynomial in r written as
    :func:`certify.algebra.poly.show` writes it (``r^4 - 10r^3 + 1``)."""
    coeffs: dict[int, int] = {}
    for term in re.findall(r"[+-]?[^+-]+", text.replace(" ", "")):
        head, r_, power = term.partition("r")
        c = int(head + "1") if head in ("", "+", "-") and r_ else int(head)
        e = (int(power[1:]) if power.startswith("^") else 1) if r_ else 0
        coeffs[e] = coeffs.get(e, 0) + c
    return [coeffs.get(k, 0) for k in range(max(coeffs) + 1)]


def end_number(end: dict):
    """An end point of a census r-set (the end-point form of ``pattern --json``) as an
    exact algebraic number: its minimal polynomial and isolating interval, checked
    (:class:`certify.algebra.algebraic.Algebraic` recounts the root in the interval)."""
    from certify.algebra.algebraic import Algebraic
    if end["exact"] is not None:
        return Algebraic.rational(flint.fmpq(Fraction(end["exact"]).numerator, Fraction(end["exact"]).denominator))
    lo, hi = (Fraction(x) for x in end["interval"])
    return Algebraic(_integer_poly(end["minimal_polynomial"]), flint.fmpq(lo.numerator, lo.denominator),
                     flint.fmpq(hi.numerator, hi.denominator))


def attracting_windows(record: dict) -> list[tuple[dict, dict, str]]:
    """(lo, hi, pair) of the open r-intervals where the record's periodic orbit of the
    reduction is attracting (every branch)."""
    part = record.get(REDUCTION) or {}
    return [(a["lo"], a["hi"], a["pair"]) for a in (part.get("result") or {}).get("attracting", [])]


def attracting_points(record: dict) -> list[dict]:
    part = record.get(REDUCTION) or {}
    return [p["at"] for p in (part.get("result") or {}).get("attracting_points", [])]


def union(intervals: list[tuple[dict, dict]], points: list[dict] = ()) -> dict:
    """The union of open r-intervals (end-point form), exact: ends compared as algebraic
    numbers, overlapping intervals merged (intervals that only touch stay apart: their
    common end is not covered unless a point covers it), isolated points kept where no
    interval covers them; and the gaps, the closed complement in ]0, 1[."""
    spans = sorted(((end_number(a), end_number(b), a, b) for a, b in intervals), key=lambda s: s[0])
    merged: list[list] = []
    for lo, hi, a, b in spans:
        if merged and lo < merged[-1][1]:
            if hi > merged[-1][1]:
                merged[-1][1], merged[-1][3] = hi, b
        else:
            merged.append([lo, hi, a, b])
    alone = {}
    for p in points:
        x = end_number(p)
        if not any(lo < x < hi for lo, hi, _a, _b in merged):
            alone[x.key()] = (x, p)
    out = {"intervals": [{"lo": a, "hi": b} for _lo, _hi, a, b in merged],
           "points": [p for _x, p in sorted(alone.values(), key=lambda t: t[0])]}
    gaps, left = [], {"exact": "0", "digits": "0.0", "interval": ["0", "0"], "minimal_polynomial": "r"}
    for _lo, _hi, a, b in merged:
        if not (a["exact"] == left["exact"] == "0"):
            gaps.append({"lo": left, "hi": a})
        left = b
    if left["exact"] != "1":
        gaps.append({"lo": left, "hi": {"exact": "1", "digits": "1.00000000000", "interval": ["1", "1"],
                                        "minimal_polynomial": "r - 1"}})
    out["gaps"] = gaps
    out["set"] = show_union(out)
    return out


def show_end(e: dict) -> str:
    """An end point as ``pattern`` prints it: exact, or ≈ and 10 certified digits."""
    return e["exact"] if e["exact"] is not None else "≈" + end_number(e).digits(10)


_end = show_end


def show_union(u: dict) -> str:
    """``]a, b[ ∪ ]c, d[ ∪ {e}`` with the certified decimal ends."""
    parts = [f"]{_end(i['lo'])}, {_end(i['hi'])}[" for i in u["intervals"]] + [f"{{{_end(p)}}}" for p in u["points"]]
    return " ∪ ".join(parts) or "∅"


def show_gaps(u: dict) -> str:
    """The gaps of a union in ]0, 1[ (closed, within ]0, 1[)."""
    def lo(e):
        return "]0" if e["exact"] == "0" else f"[{_end(e)}"

    def hi(e):
        return "1[" if e["exact"] == "1" else f"{_end(e)}]"
    return " ∪ ".join(f"{lo(g['lo'])}, {hi(g['hi'])}" for g in u["gaps"]) or "∅"


MIRROR_BLOCK = {b: b.translate(MIRROR) for b in BLOCKS}


def _cyclic_forms(word: str) -> list[tuple[str, ...]]:
    """The block sequences of a word's class: every rotation at a block boundary, of the
    word and of its mirror."""
    out = []
    for seq in (tuple(blocks_of(word)), tuple(MIRROR_BLOCK[b] for b in blocks_of(word))):
        out += [seq[k:] + seq[:k] for k in range(len(seq))]
    return out


def _key(seq) -> str | None:
    """The normal form of the class of a block sequence, None if it is not primitive."""
    word = "".join(seq)
    return normal_form(word)[0] if word not in (word + word)[1:-1] else None


def families(words, grow: int = 3, factors: int = 2, least: int = 3) -> list[dict]:
    """Families among ``words`` (normal forms, e.g. those with an attracting periodic
    orbit of the reduction): the classes of x_0 v_1^n x_1 … v_m^n x_m (cyclic block
    sequences; m ≤ ``factors`` repeated factors v_i of at most ``grow`` blocks each, all
    repeated n times) for at least ``least`` consecutive n, every member in ``words``.
    Found by growing each word: a factor v_i of a rotation (or of the mirror) inserted
    once more, again, … while the class stays in ``words``.  A family whose members all
    belong to a larger one is dropped.  Each: the members (normal forms, shortest first)
    and the repeated factors (blocks, spelled)."""
    members = set(words)
    found: dict[tuple, list] = {}
    for w in members:
        for seq in _cyclic_forms(w):
            L = len(seq)
            cuts = [(i, m) for i in range(L) for m in range(1, grow + 1) if i + m <= L]
            choices = [(c,) for c in cuts]
            if factors >= 2:
                choices += [(c, d) for c in cuts for d in cuts if d[0] >= c[0] + c[1]]
            for choice in choices:
                chain = [w]
                for j in range(2, 2 + len(members)):
                    grown, last = [], 0
                    for i, m in choice:
                        grown += list(seq[last:i]) + list(seq[i:i + m]) * j
                        last = i + m
                    key = _key(tuple(grown + list(seq[last:])))
                    if key not in members:
                        break
                    chain.append(key)
                if len(chain) >= least:
                    spelled = tuple(sorted({"".join(seq[i:i + m]) for i, m in choice}))
                    found.setdefault(tuple(chain), []).append(spelled)
    fams = sorted(found.items(), key=lambda kv: (-len(kv[0]), len(kv[0][0]), kv[0]))
    out = []
    for chain, spells in fams:
        if any(set(chain) <= set(f["members"]) for f in out):
            continue
        out.append({"members": list(chain), "compact": [compact(w) for w in chain],
                    "repeated": list(min(spells, key=lambda s: (sum(map(len, s)), s)))})
    return out


def reduction_findings(records) -> dict:
    """The periodic orbits of the reduction across the census: the words with an
    attracting window; for each length L, the union over the words of at most L
    collisions of their attracting windows (exact, with the gaps in ]0, 1[; a row where it
    grows, from the first word with a window); the words
    with a complex in-plane pair where attracting; the families (:func:`families`)."""
    recs = order(records)
    part = lambda r: r.get(REDUCTION) or {}                       # noqa: E731
    attracting = [r for r in recs if part(r).get("attracting")]
    lengths = sorted({r["length"] for r in recs})
    by_length = []
    for L in lengths:
        upto = [r for r in attracting if r["length"] <= L]
        u = union([(a, b) for r in upto for a, b, _p in attracting_windows(r)],
                  [p for r in upto for p in attracting_points(r)])
        if upto and (not by_length or u["set"] != by_length[-1]["set"]):
            by_length.append({"max_length": L, "words": [r["word"] for r in upto], **u})
    windows_of = {r["word"]: [{"lo": a, "hi": b, "pair": p} for a, b, p in attracting_windows(r)] for r in attracting}
    return {
        "analysed": sum(part(r).get("outcome") == "analysed" for r in recs),
        "missing": [r["word"] for r in recs if REDUCTION not in r],
        "feasible": [r["word"] for r in recs if part(r).get("feasible")],
        "attracting": [r["word"] for r in attracting],
        "attracting_windows": windows_of,
        "complex_pair_attracting": [r["word"] for r in attracting
                                    if any(p != "real" for _a, _b, p in attracting_windows(r))],
        "undecided": [r["word"] for r in recs if (part(r).get("result") or {}).get("undecided")],
        "errors": [r["word"] for r in recs if part(r).get("outcome") == "error"],
        "union_by_length": by_length,
        "families": families([r["word"] for r in attracting]),
    }
