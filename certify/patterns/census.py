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

import traceback
from fractions import Fraction

from .pattern import analyse
from .periodic import MIRROR, compact, normal_form

BLOCKS = ("ab", "acb", "cab", "cb")          # Corollary 4.5 (l. 1050), in the order a < b < c
ABCAB = "abcab"                               # T27, T28 (l. 513-515)
KEPT = ("normal_form", "system", "characteristic_polynomial", "exists", "feasible", "stable", "undecided",
        "diagnosis", "verdict")                # of the pattern's JSON: the r-sets and why (no formulas)


def lyndon_block_words(max_length: int) -> list[tuple[int, ...]]:
    """Every Lyndon word over the blocks (indices into :data:`BLOCKS`) whose letters
    number at most ``max_length``: the FKM tree of pre-necklaces a_1 … a_t (a_t ≥
    a_{t-p}; p the length of the longest Lyndon prefix period), a node kept when
    p = t, a branch cut as soon as its length exceeds the bound."""
    sizes = [len(b) for b in BLOCKS]
    a = [0] * (max_length + 2)
    out: list[tuple[int, ...]] = []

    def grow(t: int, p: int, length: int) -> None:
        if t > 1 and t - 1 == p:
            out.append(tuple(a[1:t]))
        for j in range(a[t - p], len(BLOCKS)):
            if length + sizes[j] <= max_length:
                a[t] = j
                grow(t + 1, p if j == a[t - p] else t, length + sizes[j])

    if max_length >= min(sizes):
        grow(1, 1, 0)
    return out


def spell(blocks: tuple[int, ...]) -> str:
    """The letters of a block sequence."""
    return "".join(BLOCKS[j] for j in blocks)


def words(max_length: int) -> list[str]:
    """One word per class (rotations and the mirror a<->c) of primitive periods made of
    blocks, of length at most ``max_length``: the pattern module's normal forms, sorted
    by length, then alphabetically."""
    if max_length < 1:
        raise ValueError(f"the maximal length must be positive, not {max_length}")
    keys = {normal_form(spell(s))[0] for s in lyndon_block_words(max_length)}
    return sorted(keys, key=lambda w: (len(w), w))


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
    """The census record of one word (a normal form): its analysis as JSON, or the
    error that stopped it (one line), and the seconds it took (:data:`SECONDS`, which
    :func:`certify.run.census_report.run_census` keeps out of the census).  Never raises for a word's sake."""
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
        "abcab": {"words": len(abcab),
                  "feasible": [r["word"] for r in abcab if r["feasible"]],
                  "undecided_or_error": [r["word"] for r in abcab if r["outcome"] == "error" or r["undecided"]]},
    }
