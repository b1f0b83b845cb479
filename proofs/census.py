"""T28 (l. 515): "patterns containing abcab do not seem to have feasible self-similar
data" — an empirical remark, tested on a census.

Which patterns.  A periodic pattern is a cyclic sequence of the blocks ab, cb, acb,
cab (Corollary 4.5, l. 1037-1051, with the correction certified in S10); a class of
rotations and of the mirror a<->c is one set of orbits.  *Containing abcab* is read in
the bi-infinite periodic word, for some member of the class: the word contains abcab
or its mirror cbacb (so (cab)^∞ = …cabcab… and its mirror (acb)^∞ count).

What is checked.  Every class of at most :data:`LENGTH` collisions
(:func:`certify.patterns.census.words`, the FKM tree of Lyndon block words, checked
here against a brute-force enumeration of block sequences) whose word contains the
printed pattern is analysed by ``certify pattern`` (:func:`certify.patterns.analyse`):
feasible means that on some real eigenvalue branch and fixed point x± its
self-similar candidate realises every collision of the period, strictly.  The remark
is PASS for what was checked when every such word is decided and none is feasible;
the bound is part of the statement.  A feasible word is a counterexample: ERRATUM,
with the corrected statement beside it (the counterexamples, their certified r-sets,
and the exact dynamics from each datum at a rational r repeating the word, in balls).
A word whose analysis errs or leaves a point undecided is not checked: FAIL, the word
named, unless a counterexample refutes the remark anyway.

The census (``certify census``, reports/CENSUS.md) found counterexamples from 10
collisions on; :data:`FOUND` names the shortest ones, which are analysed here too
(a census to 10 would take minutes inside ``certify all``): abacbacbcb (its mirror
cbcabcabab contains abcab) and abacbcabcab = ab acb cab cab (contains abcab as written).  ``python -m certify census --max-length L`` runs the same
analysis on every class up to L (reports/CENSUS.md).
"""
from __future__ import annotations

import re
from itertools import product

from fractions import Fraction

import flint

from certify.algebra import X_PLUS, simplest_between
from certify.dynamics import candidate, simulate
from certify.patterns import BRANCH_NAMES, census
from certify.run import ERRATUM, REFUTED_REMARK, Check, certificate, conclude, overridden

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
    out = []
    for name, reads in READINGS.items():
        with_mirror = sum(any(reads(v, pattern) for v in orientations(w)) for w in words)
        without = sum(reads(v, pattern) for w in words for v in orientations(w))
        out.append((name, with_mirror, without))
    return out


def committed_census() -> dict | None:
    """reports/census.json of the source checkout (``certify census``), or None."""
    import json
    from pathlib import Path
    try:
        return json.loads((Path(__file__).resolve().parents[1] / "reports" / "census.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def readings_evidence(pattern: str) -> str:
    """The counterexamples of the committed census under each reading of l. 515."""
    doc = committed_census()
    if not doc:
        return "No committed census (reports/census.json): run `python -m certify census --max-length 16`."
    feasible = doc["census"]["feasible"]
    rows = [f"| {name} | {a} | {b} |" for name, a, b in reading_counts(feasible, pattern)]
    return ("How \"contains ... as a subsequence\" is read, and the counterexamples under each reading among the "
            f"{len(feasible)} classes with feasible self-similar data of the committed census (periods of at most "
            f"{doc['census']['max_length']} collisions, reports/CENSUS.md):\n\n"
            f"| Reading of \"contains {pattern}\" | classes, with the mirror {mirrored(pattern)} | oriented patterns, "
            "without the mirror |\n|---|---:|---:|\n" + "\n".join(rows))


@certificate("T28", "l. 515",
             f"Remark 3.3: \"{QUOTE_T28}\" (a hedged remark, tested on a census of the periodic patterns of blocks "
             "ab, cb, acb, cab).",
             printed=PRINTED_T28,
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
    corrected = []
    if feasible:
        replays = [replay(r) for r in feasible]
        corrected.append(Check(
            f"periodic patterns containing {pattern} (or {mirror}) can have feasible self-similar data: "
            + "; ".join(f"{r['word']} = {' '.join(r['blocks'])} on {_sets(r, 'feasible')}" for r in feasible)
            + f" (certified), the exact dynamics from each datum repeating the word for {PERIODS} periods",
            all(ok for ok, _ in replays), [text for _, text in replays], corrects=printed))
    return conclude(checks + [printed], corrected, evidence=ev, kind=REFUTED_REMARK,
                    misprint="l. 515, Remark 3.3: patterns containing abcab 'do not seem to have feasible initial data'",
                    note=f"An empirical remark, tested on every pattern of at most {LENGTH} collisions containing "
                         f"{pattern} and on the shortest counterexamples of the census (reports/CENSUS.md: "
                         "`python -m certify census --max-length L`).")
