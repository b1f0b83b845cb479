"""``certify atlas``: the attractors of the reduction over ]0, 1[, certified windows stitched.

Over a grid of rationals r (:func:`r_values`) and a grid of initial data on the b-section
(:func:`data_grid`: the tool's 8 and a Halton sequence in (θ0, φ0) ∈ ]0, π/2[ × ]0, π[),
every orbit is classified by ``certify identify`` (:func:`certify.run.identify.classify`):
island (quasi-periodic for ever, proved), attracting periodic (its word certified for ever:
the rigorous orbit enters a certified trapping ellipse) or unresolved (observed).  An
*attractor* is a certified word w with the real eigenvalue branch of its periodic orbit at r
(:func:`~certify.run.identify.decided`).  Each new word is certified once over ]0, 1[ by
``certify orbit`` (:func:`certify.patterns.reduction_orbits.analyse`): its exact attracting
windows (algebraic ends), per branch; a word longer than ``word_max`` letters, or whose
analysis exceeds ``word_seconds``, gets no window: it is known only at the r where it was
seen (``orbit_at`` there, through identify), and the atlas says so.

The windows are stitched into *cells*: the open intervals of ]0, 1[ between consecutive
window ends (and 3 − 2√2, where the island appears), compared exactly as algebraic
numbers.  In each cell the attractors whose certified windows contain it coexist
(certified: each has an attracting periodic orbit at every r of the cell; only the words the
atlas met are listed); at the sampled r of the cell, the share of the initial data that
reaches each attractor, the island, or stays unresolved is *observed* (a finite grid of
data), and the island's area on the b-section is certified as an interval
(:func:`certify.patterns.island_theorem.island_fraction`).

Families are rules (:data:`FAMILIES`): member k's word and the resonance at which its window
closes, each member and the next one predicted certified by ``orbit``.  Every window end gets
the island's rotation number (:func:`end_rotation`: a resonance p/q, q ≤ :data:`RESONANCE_Q`,
decided exactly by :func:`~certify.patterns.island_theorem.end_rotation`, else the certified ρ
and the nearest p/q with q ≤ :data:`NEAR_Q`, said "near": observed).

At each sampled r the horseshoe search of ``certify chaos`` runs (:func:`chaos_job`): where it
proves one, chaos is certified at that r (on a set of measure zero); the unresolved orbits are
said what they show (observed): a long transient, near a certified horseshoe, a word repeated
without converging (the rotation number of its loop), or nothing recognised.  Long transients,
runs with no period and runs repeating a word not attracting at r are run again longer
(:func:`classify_late`), their class kept only where identify proves it on that run; an
orbit's block is decided at its r up to :data:`LONG_WORD` letters (past the parser's 400).  The shares get
95 % intervals (:func:`wilson`, observed).

:func:`run_atlas` runs the jobs (one per r, one per word, one horseshoe search per r) on any executor
(:mod:`.executors`), appending each record to a JSON-lines state file as it arrives; with
``resume`` the records already there (same data and collisions) are reused.
:func:`check_atlas` re-derives a document: the windows by ``orbit``, the cells by stitching
again, each cell's attractors by ``orbit_at`` at an r inside, each orbit's class by
``identify``, the island by ``island``, each horseshoe by its exact proof again.
"""
from __future__ import annotations

import json
import math
import re
import signal
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from functools import cmp_to_key
from pathlib import Path

import flint

from certify.algebra import Algebraic, ends
from certify.algebra.balls import precision
from certify.algebra.branches import simple_rational_between, simplest_between
from certify.algebra.poly import to_fmpq
from certify.dynamics.island import elliptic_polynomial
from certify.errors import UsageError
from certify.numerics import grid
from certify.patterns import compact, island_theorem, read
from certify.patterns.island_theorem import LOWER_END, algebraic_of
from certify.patterns.pattern import end_data
from certify.patterns.periodic import MAX_LENGTH
from certify.patterns.reduction_orbits import MAX_ORBIT_LENGTH, analyse, read_plain

from . import identify as ident
from .census_report import committed_windows, dumps
from .executors import wait_first
from .files import load_findings, read_text_or_none, write_atomic
from .section5_orbits import FINDINGS as SECTION5

SCHEMA = "certify-atlas"
VERSION = 9
SCHEMA_PATH = Path(__file__).parents[1] / "schemas" / "atlas.schema.json"
LO, HI = Fraction(359, 5000), Fraction(1)     # 0.0718: just above 7 − 4√3 ≈ 0.0717968 (issue 37's range)
RESOLUTION = 200                              # r values of the first grid (refined: :func:`refinement`)
DATA = 24                                     # initial data per r, besides the tool's 8
COLLISIONS = 20_000                           # of each float64 run and rigorous scan
WORD_MAX = MAX_ORBIT_LENGTH                   # longer words: no window (orbit_at at the r seen)
WORD_SECONDS = 600                            # time limit of one word's window (CPU seconds)
WORD_CLOCK = "cpu"                            # what a "time limit" record's seconds count (before: wall time, unmarked)
REFINE = 3                                    # rounds of refinement after the first grid (not to a fixpoint:
                                              # rule (3) of refinement halves its intervals in every round)
LATE = 4                                      # an orbit :func:`late` selects is run again LATE times longer
LONGER = 16                                   # ... and one repeating a word not attracting at r, LONGER times
SPIRAL_EFOLDS = 4                             # a repelling word's orbit run again over this many of its e-folds ...
SPIRAL_MAX = 512                              # ... when that is at most SPIRAL_MAX times the first run (rule 5)
LATE_RULE = 5                                 # :func:`late`'s rule (1: long transients; 2: and runs with no period;
                                              # 3: and words not attracting at r, LONGER; blocks up to LONG_WORD read;
                                              # 4: runs with no period above 3 − 2√2, LONGER; 5: words repelling at
                                              # r, then over SPIRAL_EFOLDS e-folds of their repulsion)
LONG_WORD = ident.MAX_ANALYSED                # the longest block identify decides at one r for the atlas (below)
TRANSIENT, NOT_ATTRACTING, NOTHING = "long transient", "repeats a word not attracting at r", "nothing recognised"
NEAR_HORSESHOE = "near a certified horseshoe"   # an unresolved orbit whose float64 run enters a proved horseshoe's box
RESONANCE_Q = 120                             # window ends decided to be resonances p/q, q ≤ 120
NEAR_Q = 24                                   # a non-resonant end: the nearest p/q with q ≤ 24 (observed)
# an orbit's record: the keys every run writes, then those written only where they apply
ORBIT_KEYS = ("theta0", "phi0", "class", "certified_from", "word", "branch", "observed", "why")
ORBIT_LATE_KEYS = ("rerun", "unresolved")
STATE = "atlas-state.jsonl"
FIGURE = "atlas.png"
WINDOW = 16                                   # jobs in flight
ISLAND_DEPTH = 8
ISLAND, ATTRACTING, UNRESOLVED = ident.ISLAND, ident.ATTRACTING, ident.UNRESOLVED


# ------------------------------------------------------------------ the grids
def r_values(lo: Fraction, hi: Fraction, n: int) -> list[Fraction]:
    """``n`` rationals in ]lo, hi[ (0 ≤ lo < hi ≤ 1 exact, as the CLI's one reader gives them,
    :func:`certify.cli.options.r_range`): the midpoints of n equal cells, rounded to d decimals
    (d = 4, more when n needs it), without repeats."""
    a, b = Fraction(lo), Fraction(hi)
    d = max(4, len(str(n)) + 2)
    out = []
    for k in range(n):
        mid = a + (b - a) * (2 * k + 1) / (2 * n)
        x = Fraction(round(mid * 10 ** d), 10 ** d)
        if a < x < b and 0 < x < 1 and x not in out:
            out.append(x)
    return out


def _radical_inverse(i: int, base: int) -> Fraction:
    x, f = Fraction(0), Fraction(1, base)
    while i:
        i, digit = divmod(i, base)
        x += digit * f
        f /= base
    return x


def data_grid(m: int) -> list[tuple[float, float]]:
    """The tool's 8 initial data (:func:`certify.numerics.grid`) and then the first ``m``
    points of the Halton sequence (bases 2, 3) in the b-section: θ0 = π s/2, φ0 = π t
    (s, t ∈ ]0, 1[; t never 1/2, the corner φ0 = π/2).  Nested: m data are the first m of
    any larger grid.  Uniform in (θ0, φ0), as the island's share is measured."""
    if m < 0:
        raise UsageError(f"--data must be a non-negative integer, got {m}")
    th, ph = grid(8)
    out = [(float(t), float(p)) for t, p in zip(th, ph)]
    for i in range(1, m + 1):
        s, t = _radical_inverse(i, 2), _radical_inverse(i, 3)
        out.append((math.pi * float(s) / 2, math.pi * float(t)))
    return out


# ------------------------------------------------------------------ the seeds and the families' rules
@dataclass(frozen=True)
class Rule:
    """A family of attractors as a rule: member k's word is ``spelling`` with k written in
    ({k}; {j} is k − 1, a power ^0 dropped), or ``build(k)`` where the rule is not one spelling
    (then ``spelling`` is how the rule reads), for k = ``first`` .. ``last`` (certified
    members) and k = ``last`` + 1 (the prediction); its window closes (upper end) where the
    island's rotation number is p_k/q_k = (a k + b)/(c k + d), ``closing`` = (a, b, c, d)
    (1/4: the window ends at r = 1, where ρ → 1/4), or ``closing`` None (windows below
    3 − 2√2, where there is no island).  The rule is a conjecture read off the members; the
    atlas certifies each member's window with ``certify orbit`` and decides its closing
    exactly."""

    name: str
    spelling: str
    first: int
    last: int
    closing: tuple[int, int, int, int] | None
    build: Callable[[int], str] | None = None

    def word(self, k: int) -> str:
        """Member k's word (normal form), up to :data:`LONG_WORD` letters (:func:`read_plain`)."""
        text = self.build(k) if self.build else self.spelling.format(k=k, j=k - 1)
        return read_plain(_written_out(text), LONG_WORD)[0]

    def resonance(self, k: int) -> tuple[int, int] | None:
        """p_k/q_k in lowest terms, or None."""
        if self.closing is None:
            return None
        a, b, c, d = self.closing
        g = math.gcd(a * k + b, c * k + d)
        return (a * k + b) // g, (c * k + d) // g

    def members(self) -> range:
        """The members the atlas certifies: first .. last, and the prediction last + 1."""
        return range(self.first, self.last + 2)

    def reads(self) -> str:
        """The rule as ATLAS.md prints it."""
        return self.spelling.replace("{k}", "k").replace("{j}", "(k−1)")


def _written_out(text: str) -> str:
    """A rule's spelling in plain letters: each power (x)^n of a group of letters written out, n = 0
    dropping the group (the rules' spellings nest no group).  The parser (``read``) expands powers
    too, but only up to its 400 letters; :func:`read_plain` reads longer words as plain letters."""
    return re.sub(r"\(([abc]+)\)\^(\d+)", lambda m: m.group(1) * int(m.group(2)), text)


def _swap(text: str) -> str:
    return text.replace("bac", "#").replace("bca", "bac").replace("#", "bca")


def near_one(k: int) -> str:
    """Member k of the family whose windows end at r = 1 (ρ → 1/4), 24k + 14 letters: with
    m = k + ⌈k/2⌉ + 1, t = ⌊(k − 1)/2⌋ and M_t = B_1 ⋯ B_t c_t B_t ⋯ B_1 (B_i = (bac)^2, (bca)^2
    alternately, the centre c_t = bac for t even, bca for t odd), M' = M with bac and bca
    exchanged: k odd, abca M_t bc (abcb)^m ac M_t' ba (cbab)^(m−1) cb; k even, with
    N = M_t (bca)^2, abca N ba (cbab)^m cbac N' bc (abcb)^m."""
    t, m = (k - 1) // 2, k + (k + 1) // 2 + 1
    blocks = ["(bac)^2" if i % 2 == 0 else "(bca)^2" for i in range(t)]
    M = "".join(blocks) + ("bac" if t % 2 == 0 else "bca") + "".join(reversed(blocks))
    if k % 2:
        return f"abca{M}bc(abcb)^{m}ac{_swap(M)}ba(cbab)^{m - 1}cb"
    N = M + "(bca)^2"
    return f"abca{N}ba(cbab)^{m}cbac{_swap(N)}bc(abcb)^{m}"


FAMILIES = (
    Rule("(ab)^k(cb)^k", "(ab)^{k}(cb)^{k}", 2, 12, None),
    Rule("(abacbc)^k a(bcabac)^k bcb", "(abacbc)^{k}a(bcabac)^{k}bcb", 1, 13, (2, 0, 4, 1)),
    Rule("(abacbc)^k a(bac)^2(bcabac)^k bcb", "(abacbc)^{k}a(bac)^2(bcabac)^{k}bcb", 1, 13, (2, 1, 4, 3)),
    Rule("(abacbc)^k a(bcabac)^(k−1) bc(ab)^2(cbcaba)^k c(bacbca)^(k−1) ba(cb)^2",
         "(abacbc)^{k}a(bcabac)^{j}bc(ab)^2(cbcaba)^{k}c(bacbca)^{j}ba(cb)^2", 1, 8, (4, -1, 8, 0)),
    Rule("(abacbc)^k a(bac)^2(bcabac)^(k−1) bc(ab)^2(cbcaba)^k c(bca)^2(bacbca)^(k−1) ba(cb)^2",
         "(abacbc)^{k}a(bac)^2(bcabac)^{j}bc(ab)^2(cbcaba)^{k}c(bca)^2(bacbca)^{j}ba(cb)^2", 1, 8, (4, 1, 8, 4)),
    # near r = 1: k = 8 and the prediction k = 9 (206 and 230 letters) were met by the atlas's orbits before they
    # were seeded (their analyses: 308 s and 515 s of CPU); k = 10 has 254 letters, past orbit's 240
    Rule("abca M bc(abcb)^m ac M' ba(cbab)^(m−1) cb, near r = 1",
         "k odd: abca M bc(abcb)^m ac M' ba(cbab)^(m−1)cb; k even: abca N ba(cbab)^m cbac N' bc(abcb)^m "
         "(m = k + ⌈k/2⌉ + 1; M = B_1⋯B_t c B_t⋯B_1, t = ⌊(k−1)/2⌋, B_i = (bac)^2, (bca)^2 alternately, c = bac "
         "for t even, bca for t odd; N = M(bca)^2; ' exchanges bac and bca)", 1, 8, (0, 1, 0, 4), near_one),
)


def seeds() -> dict[str, str]:
    """The certified attractors the atlas starts from, normal form → where known: every
    member of :data:`FAMILIES` (the prediction included), the census's attracting words
    (read by :func:`.census_report.committed_windows`) and the words ``certify identify
    --section5`` proved some orbit to follow for ever (reports/section5-orbits.json)."""
    out: dict[str, str] = {}
    for rule in FAMILIES:
        for k in rule.members():
            out.setdefault(rule.word(k), f"family {rule.name}, k = {k}")
    found = committed_windows()
    for w in sorted(found[0] if found else {}):
        out.setdefault(read(w)[0], "census")
    for entries in (load_findings(SECTION5) or {}).get("claims", {}).values():
        for e in entries:
            for w in e["words"]:
                if w["certified"] and w["kind"] == "attracting":
                    out.setdefault(w["word"], f"identify --section5 at r = {e['r']}")
    return out


# ------------------------------------------------------------------ the jobs
def unresolved_kind(observed: str | None, r: flint.fmpq) -> str:
    """What an unresolved orbit shows (observed; the word's type at r is exact): a *long
    transient* when the word its float64 run repeats has an attracting periodic orbit at r
    (``orbit_at``) that the orbit had not been proved to enter; a word whose periodic orbit
    at r is *not attracting* (a saddle, repelling, of multiplier modulus 1, or none: the run
    repeats the word without converging, an invariant curve or a slow transient); else
    nothing recognised (no period within the run, a block too long, not a word)."""
    if observed is None:
        return NOTHING
    try:
        normal = read_plain(observed, LONG_WORD)[0]
    except UsageError:
        return NOTHING
    o = ident.decided(normal, r)
    return TRANSIENT if o is not None and o.kind == "attracting" else NOT_ATTRACTING


def spiral_factor(observed: str, r: flint.fmpq, collisions: int = COLLISIONS) -> int | None:
    """Rule 5: when the periodic orbit of the word ``observed`` at r repels (``orbit_at``, decided
    exactly), an orbit winding out of it leaves after about L/ln ρ collisions an e-fold (L letters,
    ρ the largest multiplier modulus: near r = 1, abcb repels with ρ − 1 ≈ 10⁻⁵ or less, 10⁵-10⁶
    collisions, and such an orbit settles on an attractor after).  The least power of 2 above
    :data:`LONGER` whose run covers :data:`SPIRAL_EFOLDS` e-folds, when the run LONGER times
    longer does not and it is at most :data:`SPIRAL_MAX`; else None.  The run is an observation's
    length, not a proof: the ball scan leaps over the winding (:mod:`certify.numerics.leaps`), and
    a class is proved as any other."""
    o = ident.decided(read_plain(observed, LONG_WORD)[0], r)
    if o is None or o.kind != "repelling" or not o.modulus > 1:
        return None
    efold = len(observed) / math.log(float(o.modulus.lower()))
    if SPIRAL_EFOLDS * efold <= LONGER * collisions:
        return None
    f = 2 * LONGER
    while f * collisions < SPIRAL_EFOLDS * efold and f <= SPIRAL_MAX:
        f *= 2
    return f if f <= SPIRAL_MAX else None


def late_stages(kind: str | None, observed: str | None, r: flint.fmpq) -> tuple[int, ...]:
    """How many times longer an unresolved orbit of this kind (:func:`unresolved_kind`) and
    observed word is run again at r (:func:`classify_late`), stage after stage until one proves
    a class; () when it is not: :data:`LATE` for a long transient (its word attracts at r) and
    for a run with no period at all (nothing recognised, no word repeated: it may settle later
    than the run) at r ≤ 3 − 2√2, where horseshoes are proved; :data:`LATE` then :data:`LONGER`
    for such a run above 3 − 2√2 (the island's interval, where no horseshoe is proved: near
    r = 1 a run can wander for 10⁵ collisions before it settles); :data:`LONGER` for a run
    repeating a word not attracting at r (near r = 1, abcb: a slow transient can wind along the
    loop for 10⁵ collisions before it settles elsewhere), then :func:`spiral_factor` when the word
    repels."""
    if kind == NOTHING and observed is None:
        return (LATE, LONGER) if elliptic_polynomial(r) < 0 else (LATE,)
    if kind == TRANSIENT:
        return (LATE,)
    if kind != NOT_ATTRACTING:
        return ()
    spiral = spiral_factor(observed, r) if observed is not None else None
    return (LONGER,) if spiral is None else (LONGER, spiral)


def late_factor(kind: str | None, observed: str | None, r: flint.fmpq) -> int | None:
    """The longest run :func:`late_stages` asks, as a factor of the first run's length, or None."""
    stages = late_stages(kind, observed, r)
    return stages[-1] if stages else None


def late(o: dict, r: flint.fmpq) -> bool:
    """Whether an orbit record at r is unresolved and run again longer (:func:`late_factor`)."""
    return o["class"] == UNRESOLVED and late_factor(o["unresolved"], o["observed"], r) is not None


def unread(o: dict) -> bool:
    """Whether an orbit record is unresolved on a block that the rule before :data:`LATE_RULE` 3
    could not read (longer than the parser's MAX_LENGTH, at most :data:`LONG_WORD`): run again."""
    return o["class"] == UNRESOLVED and o["observed"] is not None and MAX_LENGTH < len(o["observed"]) <= LONG_WORD


def rerun_due(o: dict, r: flint.fmpq, collisions: int) -> bool:
    """Whether :func:`r_job` runs an orbit record (at r, of a run of ``collisions``) of an older r record
    again under :data:`LATE_RULE`: unresolved, selected by :func:`late` and not yet run again as long as
    :func:`late_factor` now asks (never, or shorter), or on a block :func:`unread`."""
    return (late(o, r) and (o["rerun"] or 0) < late_factor(o["unresolved"], o["observed"], r) * collisions) \
        or unread(o)


def current(rec: dict) -> bool:
    """Whether an r record of the state is reused as it is (made under :data:`LATE_RULE`, its ``late``
    mark); else :func:`r_job` upgrades it."""
    return rec.get("late") == LATE_RULE


def classify_late(q: Fraction, fq, th, ph, collisions: int) -> tuple:
    """(identify's class of the orbit (θ0, φ0) at r, the collisions it was run again with, its
    unresolved kind): an unresolved orbit that :func:`late` selects is run again longer, stage
    after stage (:func:`late_stages`), and the first run's class that proves one kept (its kind
    then None); otherwise the first run's, with the longest run and the kind (:func:`unresolved_kind`,
    computed once).  Observed blocks are decided up to :data:`LONG_WORD` letters (identify's
    ``word_max``): the exact route at one r (``orbit_at``, the trapping ellipse) needs no
    parser; a longer block is "not analysed" (its exact products and the ball scan grow with
    its length, and the atlas met none between 868 and 1000 letters).  The runs share the datum's
    rigorous orbit (:class:`~certify.run.identify.Scan`): a longer run goes on from where the last
    one's ball scan stopped when its trapping ellipse is the same (the same classes)."""
    scan = ident.Scan()
    x = ident.classify(q, th, ph, collisions, word_max=LONG_WORD, scan=scan)
    if x.cls != UNRESOLVED:
        return x, None, None
    kind = unresolved_kind(x.word, fq)
    stages = late_stages(kind, x.word, fq)
    for f in stages:
        y = ident.classify(q, th, ph, f * collisions, word_max=LONG_WORD, scan=scan)
        if y.cls != UNRESOLVED:
            return y, f * collisions, None
    return x, (stages[-1] * collisions if stages else None), kind


def _orbit_record(x, rerun, kind, th, ph, fq) -> dict:
    """The atlas's record of one orbit classified by :func:`classify_late`."""
    rec = {"theta0": th, "phi0": ph, "class": x.cls, "certified_from": x.certified_from,
           "word": None, "branch": None, "observed": None, "why": x.why if x.cls == UNRESOLVED else "",
           "rerun": rerun, "unresolved": kind}
    if x.cls == ATTRACTING:
        normal = read_plain(x.word, LONG_WORD)[0]
        rec["word"], rec["branch"] = normal, ident.decided(normal, fq).branch_name
    elif x.cls == UNRESOLVED and x.word is not None:
        rec["observed"] = x.word
    return rec


def r_job(r: str, data: list, collisions: int, previous: dict | None = None) -> dict:
    """Every orbit of ``data`` at r classified by identify (an unresolved orbit that
    :func:`late` selects run again, :func:`late_factor` times longer, its class kept if that run
    proves one); the island at r (the theorem, the rotation number, the certified share of
    the b-section).  ``previous``: a record of r made before the rule :data:`LATE_RULE`; its
    island and the orbits that rule does not run again (:func:`late`, not yet run again) nor
    read anew (:func:`unread`) are kept (the same computation), the others run again.  Plain data."""
    start = time.perf_counter()
    q = Fraction(r)
    fq = flint.fmpq(q.numerator, q.denominator)
    orbits = []
    for i, (th, ph) in enumerate(data):
        old = previous["orbits"][i] if previous is not None else None
        if old is not None and not rerun_due(old, fq, collisions):
            orbits.append(old)
            continue
        orbits.append(_orbit_record(*classify_late(q, fq, th, ph, collisions), th, ph, fq))
    island = previous["island"] if previous is not None else None
    if previous is None and elliptic_polynomial(fq) < 0:
        lo, hi = island_theorem.island_fraction(fq, ISLAND_DEPTH)
        island = {"theorem": ident.elliptic(fq), "rotation_number": island_theorem.rotation_number(fq, 8),
                  "fraction": [str(lo), str(hi)], "depth": ISLAND_DEPTH}
    return {"kind": "r", "r": str(q), "data": len(data), "collisions": collisions, "orbits": orbits,
            "island": island, "late": LATE_RULE, "seconds": round(time.perf_counter() - start, 3)}


def chaos_job(r: str, unresolved: list, collisions: int) -> dict:
    """At r: the horseshoe of ``certify chaos`` (:func:`certify.numerics.horseshoe.find`: a float
    search, an exact proof), and for each unresolved orbit [index, θ0, φ0, the word its run
    repeats or None] what its float64 run's states at b show (observed): whether one enters a
    box of the proved horseshoe after the first returns, and, when it repeats a word, the
    rotation number of its loop under G = f^k, k the b's of the word
    (:func:`certify.numerics.curves.rotation_estimate`).  Plain data."""
    from certify.numerics import curves, horseshoe
    start = time.perf_counter()
    q = Fraction(r)
    fq = flint.fmpq(q.numerator, q.denominator)
    found = horseshoe.find(q)
    search = time.perf_counter() - start
    P = found.proof if found.proof is not None and found.proof.holds else None
    hs: dict = {"certified": P is not None, "tried": found.tried}
    if P is not None:
        hs.update({"saddle": found.saddle, "returns": P.k, "rho_lower": str(P.beta), "entropy_lower": P.entropy,
                   "boxes": [{k: v for k, v in b.as_json().items() if k != "vertices"} for b in P.boxes],
                   "edges": [list(e) for e in P.covers]})
    frames = horseshoe.box_frames(P.boxes) if P is not None else None
    orbits = []
    for index, th, ph, word in unresolved:
        pts = curves.b_states(fq, th, ph, collisions)
        visits = None if frames is None else horseshoe.any_in_boxes(frames, pts[horseshoe.TRANSIENT_RETURNS:])
        curve = curves.rotation_estimate(pts, max(word.count("b"), 1)) if word else None
        if curve is not None:
            near = Fraction(curve["rotation"]).limit_denominator(NEAR_Q)     # the nearest p/q, q ≤ NEAR_Q
            curve["near"] = [near.numerator, near.denominator]
        orbits.append({"index": index, "visits_horseshoe": visits, "curve": curve})
    return {"kind": "chaos", "r": str(q), "collisions": collisions, "horseshoe": hs, "orbits": orbits,
            "search_seconds": round(search, 3), "seconds": round(time.perf_counter() - start, 3)}


def unresolved_of(rec: dict) -> list:
    """The unresolved orbits of an r record as :func:`chaos_job` takes them."""
    return [[i, o["theta0"], o["phi0"], o["observed"]] for i, o in enumerate(rec["orbits"]) if o["class"] == UNRESOLVED]


def explained(o: dict) -> str:
    """What an unresolved orbit of the document shows (observed): a long transient, near a
    certified horseshoe (its run enters a proved horseshoe's box), else its kind
    (:func:`unresolved_kind`: a word repeated without converging, or nothing recognised)."""
    kind = o.get("unresolved") or NOTHING
    return NEAR_HORSESHOE if kind != TRANSIENT and o.get("visits_horseshoe") else kind


class _TimeLimit(Exception):
    pass


def word_job(word: str, seconds: float | None = WORD_SECONDS, word_max: int = WORD_MAX) -> dict:
    """``certify orbit`` on one word over ]0, 1[: its attracting windows (exact ends), per
    branch; "too long" beyond ``word_max`` letters, "time limit" beyond ``seconds`` of the
    process's CPU time (a profiling timer, SIGPROF: the load of the machine does not move
    it; where the job runs in a process's main thread, elsewhere no limit)."""
    start, cpu = time.perf_counter(), time.process_time()
    rec = {"kind": "word", "word": word, "compact": compact(word), "length": len(word), "outcome": "analysed",
           "attracting": [], "attracting_points": [], "undecided": [], "word_max": word_max, "word_seconds": seconds}
    if len(word) > word_max:
        rec["outcome"], rec["seconds"] = "too long", 0.0
        return rec
    alarm = seconds is not None and threading.current_thread() is threading.main_thread()

    def stop(_signum, _frame):
        raise _TimeLimit()
    old = signal.signal(signal.SIGPROF, stop) if alarm else None
    try:
        if alarm:
            signal.setitimer(signal.ITIMER_PROF, seconds)
        res = analyse(word, self_similar=False)
        rec["attracting"], rec["attracting_points"] = res.attracting(), res.attracting_points()
        rec["undecided"] = list(res.undecided)
    except _TimeLimit:
        rec["outcome"], rec["clock"] = "time limit", WORD_CLOCK
    except (ArithmeticError, ValueError, UsageError) as exc:
        rec["outcome"], rec["error"] = "error", f"{type(exc).__name__}: {exc}"
    finally:
        if alarm:
            signal.setitimer(signal.ITIMER_PROF, 0)
            signal.signal(signal.SIGPROF, old)
    rec["seconds"], rec["cpu_seconds"] = round(time.perf_counter() - start, 3), round(time.process_time() - cpu, 3)
    return rec


# ------------------------------------------------------------------ the state and the run
def load_state(path) -> list[dict]:
    """The records of a state file (a line cut by an interruption is dropped)."""
    text = read_text_or_none(path)
    out = []
    for line in (text or "").splitlines():
        try:
            rec = json.loads(line)
            if rec["kind"] in ("r", "word", "chaos"):
                out.append(rec)
        except (ValueError, KeyError, TypeError):
            continue
    return out


def _words_of(rec: dict) -> list[str]:
    return sorted({o["word"] for o in rec["orbits"] if o["word"] is not None})


def run_atlas(rs: list[Fraction], data: list, collisions: int, executor, state=None, resume: bool = False,
              progress=None, word_seconds: float | None = WORD_SECONDS, word_max: int = WORD_MAX,
              seeds: dict | None = None, refine: int = 0, r_range: tuple | None = None) -> tuple:
    """(r records, word records): the r jobs, a word job for each seed (``seeds``: word →
    where known) and for each new certified word as soon as it is met, a horseshoe job
    (:func:`chaos_job`) for each r as soon as its r record is in (its record as the r
    record's ``chaos``); then up to ``refine``
    rounds of :func:`refinement` inside ``r_range`` (default: the grid's ends), each adding
    the r it asks for, until one asks for none.  The word records returned are those of the
    seeds and of the words the wanted r met: a state's other word records (met at r no round
    asks for now) stay in the state, unlisted, so a resume and a run from an empty state that
    end on the same r list the same words.  Records are appended to ``state`` as they arrive.  ``resume``: the r
    records of ``state`` with the same data and collisions, and its word records with the
    same limits, are reused (the rounds are decided from the records, so a resumed atlas
    asks for the same r; a horseshoe record is reused for the same collisions and unresolved orbits;
    an r record made before :data:`LATE_RULE` is upgraded: :func:`r_job` runs again only the
    orbits that rule runs longer)."""
    stored_r, done_r, done_w, stored_c, done_c = {}, {}, {}, {}, {}
    if state is not None:
        state = Path(state)
        if resume:
            for rec in load_state(state):
                if rec["kind"] == "r" and rec["data"] == len(data) and rec["collisions"] == collisions:
                    stored_r[rec["r"]] = rec
                elif rec["kind"] == "word" and rec["word_max"] == word_max and (
                        rec["outcome"] != "time limit"
                        or (rec["word_seconds"] == word_seconds and rec.get("clock") == WORD_CLOCK)):
                    done_w[rec["word"]] = rec
                elif rec["kind"] == "chaos" and rec["collisions"] == collisions:
                    stored_c[rec["r"]] = rec
        else:
            write_atomic(state, "")
    sources = dict(seeds or {})
    lo, hi = r_range or (min(rs), max(rs))
    wanted: list[str] = []
    queue: list[tuple[str, str]] = []
    asked: set[str] = set()                    # the seeds and the words the wanted r met: the atlas's words
    total, count = [0], [0]
    sink = state.open("a", encoding="utf-8") if state is not None else None

    def want_word(w):
        if w not in asked:
            asked.add(w)
            total[0] += 1
            if w in done_w:
                count[0] += 1
            else:
                queue.insert(0, ("word", w))      # words first: the longest jobs start early

    def want_chaos(r):
        total[0] += 1
        mine = stored_c.get(r)
        if mine is not None and [o["index"] for o in mine["orbits"]] == [u[0] for u in unresolved_of(done_r[r])]:
            done_c[r] = mine
            count[0] += 1
        else:
            queue.append(("chaos", r))

    def want_r(rs_new):
        for r in (str(x) for x in rs_new):
            if r in wanted:
                continue
            wanted.append(r)
            total[0] += 1
            if r in stored_r and current(stored_r[r]):
                done_r[r] = stored_r[r]
                count[0] += 1
                for w in _words_of(done_r[r]):
                    want_word(w)
                want_chaos(r)
            else:
                queue.append(("r", r))

    for w in sources:
        want_word(w)
    want_r(rs)
    if progress:
        progress(count[0], total[0], "")

    def collect(kind, key, rec):
        if sink is not None:
            sink.write(dumps(rec) + "\n")
            sink.flush()
        if kind == "r":
            done_r[key] = rec
            for w in _words_of(rec):
                want_word(w)
            want_chaos(key)
        elif kind == "chaos":
            done_c[key] = rec
        else:
            done_w[key] = rec
        count[0] += 1
        if progress:
            progress(count[0], total[0], f"{'r' if kind == 'r' else 'horseshoe at r'} = {key}" if kind != "word"
                     else f"{len(key)}-letter word")

    def submit(kind, key):
        if kind == "r":
            return executor.submit(r_job, key, data, collisions, stored_r.get(key))   # an older record: upgraded
        if kind == "chaos":
            return executor.submit(chaos_job, key, unresolved_of(done_r[key]), collisions)
        return executor.submit(word_job, key, word_seconds, word_max)

    try:
        pending: set = set()
        what: dict = {}
        rounds = 0
        while True:
            while queue or pending:
                while queue and len(pending) < WINDOW:
                    kind, key = queue.pop(0)
                    future = submit(kind, key)
                    if future.done():
                        collect(kind, key, future.result())
                    else:
                        what[future] = (kind, key)
                        pending.add(future)
                if pending:
                    finished, pending = wait_first(pending, 0.5)
                    for future in sorted(finished, key=lambda f: what[f]):
                        kind, key = what.pop(future)
                        collect(kind, key, future.result())
            if rounds >= refine:
                break
            rounds += 1
            more = refinement([done_r[r] for r in wanted], [done_w[w] for w in sorted(asked)], lo, hi)
            if not more:
                break
            want_r(more)
    finally:
        if sink is not None:
            sink.close()
    rows = sorted(({**done_r[r], "chaos": done_c.get(r)} for r in wanted), key=lambda rec: Fraction(rec["r"]))
    words = sorted((done_w[w] for w in asked), key=lambda w: (w["length"], w["word"]))
    for w in words:
        w["source"] = sources.get(w["word"], "met")
    return rows, words


# ------------------------------------------------------------------ refinement
def _fraction(x: flint.fmpq) -> Fraction:
    return Fraction(int(x.p), int(x.q))


def refinement(r_records: list[dict], word_records: list[dict], lo: Fraction, hi: Fraction) -> list[Fraction]:
    """The r the next round asks for, inside ]lo, hi[ (observed sampling; the windows are
    exact whatever is sampled): (1) in every cell of the stitched windows that no sampled r
    lies in, a simple rational of its middle half
    (:func:`~certify.algebra.branches.simple_rational_between`); (2) near each window end, inside
    the window, the simplest rational of the eighth of the cell next to the end; (3) where the grid
    meets a word without a window (too long, too slow), the simplest rational of the middle half
    between it and each neighbouring r.
    Increasing, without the r already sampled."""
    have = sorted(Fraction(rec["r"]) for rec in r_records)
    A = Algebraic.rational(flint.fmpq(lo.numerator, lo.denominator))
    B = Algebraic.rational(flint.fmpq(hi.numerator, hi.denominator))
    atts = attractors_of(word_records)
    out: set[Fraction] = set()
    cells = stitch(atts)
    for c in cells:
        a, b = _alg(c["lo"]), _alg(c["hi"])
        if not (a < B and A < b):
            continue
        a, b = (a if A < a else A), (b if b < B else B)
        if not any(_in_open(q, a, b) for q in have):
            out.add(_fraction(simple_rational_between(a, b)))
    for lo_end, hi_end in {(_alg(w["lo"]), _alg(w["hi"])) for x in atts for w in x["windows"]}:
        for e, toward_hi in ((lo_end, False), (hi_end, True)):
            if not (A < e < B):
                continue
            if toward_hi:
                c = next(c for c in cells if _alg(c["lo"]) < e and not _alg(c["hi"]) < e)
                u, v = _alg(c["lo"]), e
            else:
                c = next(c for c in cells if not e < _alg(c["lo"]) and e < _alg(c["hi"]))
                u, v = e, _alg(c["hi"])
            u, v = (u if A < u else A), (v if v < B else B)
            near = _eighth(u, v, toward_hi) if u < v else None
            if near is not None:
                out.add(near)
    lost = {w["compact"] for w in word_records if w["outcome"] != "analysed"}
    for rec in sorted(r_records, key=lambda x: Fraction(x["r"])):
        if not any(compact(w) in lost for w in _words_of(rec)):
            continue
        q = Fraction(rec["r"])
        k = have.index(q)
        for other in (have[k - 1] if k else lo, have[k + 1] if k + 1 < len(have) else hi):
            a, b = sorted((q, other))
            out.add(_fraction(simple_rational_between(Algebraic.rational(to_fmpq(a)), Algebraic.rational(to_fmpq(b)))))
    return sorted(x for x in out if lo < x < hi and x not in have and 0 < x < 1)


def _in_open(q: Fraction, a: Algebraic, b: Algebraic) -> bool:
    x = Algebraic.rational(flint.fmpq(q.numerator, q.denominator))
    return a < x < b


def _eighth(u: Algebraic, v: Algebraic, toward_hi: bool) -> Fraction | None:
    """The simplest rational (:func:`~certify.algebra.branches.simplest_between`) of the eighth
    of ]u, v[ next to v (``toward_hi``) or to u."""
    with precision(128):
        lu, uu = ends(u.arb(128))
        lv, uv = ends(v.arb(128))
    if not uu < lv:
        return None
    width = (lv - uu) / 8
    q = _fraction(simplest_between(lv - width, lv) if toward_hi else simplest_between(uu, uu + width))
    return q if _in_open(q, u, v) else None


# ------------------------------------------------------------------ stitching
def _cmp(x: Algebraic, y: Algebraic) -> int:
    return 0 if x == y else -1 if x < y else 1


_ALGEBRAIC: dict = {}


def _alg(end) -> Algebraic:
    """The algebraic number of a window end as printed (:func:`algebraic_of`), read once per end."""
    if isinstance(end, Algebraic):
        return end
    key = _end_key(end)
    if key not in _ALGEBRAIC:
        _ALGEBRAIC[key] = algebraic_of(end)
    return _ALGEBRAIC[key]


def attractors_of(words: list[dict]) -> list[dict]:
    """One attractor per (word, branch) with an attracting window, its windows (exact ends)."""
    out = {}
    for w in words:
        for a in w["attracting"]:
            key = (w["word"], a["branch"])
            out.setdefault(key, {"word": w["word"], "compact": w["compact"], "length": w["length"],
                                 "branch": a["branch"], "windows": []})
            out[key]["windows"].append({"lo": a["lo"], "hi": a["hi"], "pair": a["pair"]})
    return [out[k] for k in sorted(out, key=lambda k: (len(k[0]), k))]


def name(word: str, branch: str) -> str:
    return f"{compact(word)} ({branch})"


def stitch(attractors: list[dict]) -> list[dict]:
    """The cells of ]0, 1[: the open intervals between consecutive distinct window ends (and
    3 − 2√2), exact; each with the attractors (names) whose certified windows contain it."""
    pts = [Algebraic.rational(flint.fmpq(0)), Algebraic.rational(flint.fmpq(1)), LOWER_END]
    for a in attractors:
        for win in a["windows"]:
            pts += [_alg(win["lo"]), _alg(win["hi"])]
    pts = sorted(pts, key=cmp_to_key(_cmp))
    uniq = [pts[0]]
    for x in pts[1:]:
        if not x == uniq[-1]:
            uniq.append(x)
    wins = [(name(a["word"], a["branch"]), _alg(w["lo"]), _alg(w["hi"])) for a in attractors for w in a["windows"]]
    cells = []
    for lo, hi in zip(uniq, uniq[1:]):
        inside = sorted({n for n, a, b in wins if not lo < a and not b < hi})
        cells.append({"lo": end_data(lo), "hi": end_data(hi), "attractors": inside,
                      "island": not lo < LOWER_END})
    return cells


def _in_cell(q: Fraction, cell: dict) -> bool:
    x = Algebraic.rational(flint.fmpq(q.numerator, q.denominator))
    return _alg(cell["lo"]) < x < _alg(cell["hi"])


# ------------------------------------------------------------------ families and rotation numbers
_ROTATIONS: dict = {}


def end_rotation(end: dict, Q: int = RESONANCE_Q) -> dict | None:
    """The island's rotation number at a window end in [3 − 2√2, 1]: a resonance p/q (q ≤ Q)
    decided exactly by :func:`~certify.patterns.island_theorem.end_rotation` (1/2 at 3 − 2√2,
    1/4 at r = 1: the island's own ends), else ρ (8 certified digits) and the nearest p/q with
    q ≤ :data:`NEAR_Q` ("near", with the distance: an observation); None below 3 − 2√2.
    Computed once per end (the same end anywhere in the atlas)."""
    key = (_end_key(end), Q)
    if key not in _ROTATIONS:
        _ROTATIONS[key] = _rotation(_alg(end), Q)
    return _ROTATIONS[key]


def _end_key(end) -> tuple:
    if isinstance(end, Algebraic):
        return (str(end.minimal_polynomial()), str(end.lo), str(end.hi))
    return (end.get("exact"), end.get("minimal_polynomial"), tuple(end.get("interval") or ()))


def _rotation(x: Algebraic, Q: int) -> dict | None:
    """:func:`end_rotation`'s record from :func:`~certify.patterns.island_theorem.end_rotation`
    (the one decision; ρ's ball computed once)."""
    e = island_theorem.end_rotation(x, Q)
    if e is None:
        return None
    if e.island_end:
        return {"rho": "0.5" if e.resonance == (1, 2) else "0.25", "resonance": list(e.resonance), "near": None,
                "island_end": True}
    lo, hi = e.ball
    digits = f"{float((lo + hi) / 2):.8f}"
    if e.resonance is not None:
        return {"rho": digits, "resonance": list(e.resonance), "near": None, "island_end": False}
    mid = _fraction((lo + hi) / 2)
    best = mid.limit_denominator(NEAR_Q)                         # the nearest p/q with q ≤ NEAR_Q
    return {"rho": digits, "resonance": None, "near": [best.numerator, best.denominator],
            "distance": f"{float(abs(best - mid)):.2e}", "island_end": False}


def closes_at(end: dict, p: int, q: int) -> bool:
    """Whether a window end is exactly where the island's rotation number is p/q
    (:func:`end_rotation`: 1/2 at 3 − 2√2, 1/4 at r = 1)."""
    return (end_rotation(end, max(q, RESONANCE_Q)) or {}).get("resonance") == [p, q]


def families(attractors: list[dict], words: list[dict]) -> list[dict]:
    """Each rule of :data:`FAMILIES` whose members the atlas all analysed: member k's word, its
    certified windows, the resonance p_k/q_k the rule predicts at the upper end and whether
    the window closes there exactly; a member is *certified* when it has an attracting window
    (closing at p_k/q_k where the rule says one); then the prediction; then, marked
    ``beyond``, the members k ≤ :data:`RULE_K` past the prediction whose windows the atlas
    computed because its orbits met them (not counted among the certified members: the rule
    did not ask for them, they test it; a member met but too long or too slow for a window is
    listed under the attractors without one)."""
    by_word: dict[str, list] = {}
    for a in attractors:
        by_word.setdefault(a["word"], []).append(a)
    analysed = {w["word"]: w for w in words}
    out = []
    for rule in FAMILIES:
        spelt = {k: rule.word(k) for k in rule.members()}
        if any(w not in analysed for w in spelt.values()):
            continue                          # not analysed in this atlas (seeded without its family)
        met = {k: w for k in range(rule.last + 2, RULE_K + 1)
               if (w := rule.word(k)) in analysed and analysed[w]["outcome"] == "analysed"}
        members = []
        for k, w in {**spelt, **met}.items():
            wins = [(a, win) for a in by_word.get(w, []) for win in a["windows"]]
            pq = rule.resonance(k)
            closes = None if pq is None else any(closes_at(win["hi"], *pq) for _a, win in wins)
            members.append({"k": k, "word": w, "compact": compact(w), "length": len(w),
                            "predicted": k == rule.last + 1, "outcome": analysed[w]["outcome"],
                            "windows": [{"branch": a["branch"], "lo": win["lo"]["digits"], "hi": win["hi"]["digits"],
                                         "pair": win["pair"]} for a, win in wins],
                            "closing": list(pq) if pq else None, "closes": closes,
                            "certified": bool(wins) and closes is not False, **({"beyond": True} if k in met else {})})
        p1, p0, q1, q0 = rule.closing or (0, 0, 0, 0)
        closing = (None if rule.closing is None else f"{p0}/{q0} (r = 1)" if p1 == q1 == 0 else
                   f"({_affine(p1, p0)})/({_affine(q1, q0)})")
        out.append({"family": rule.name, "rule": rule.reads(), "closing": closing,
                    "members": members,
                    "certified_members": sum(m["certified"] for m in members
                                             if not (m["predicted"] or m.get("beyond"))),
                    "prediction_certified": any(m["certified"] for m in members if m["predicted"])})
    return out


def _affine(a: int, b: int) -> str:
    return f"{a}k" + (f" + {b}" if b > 0 else f" − {-b}" if b < 0 else "")


def family_of(fams: list[dict]) -> dict[str, str]:
    """Each member's word → the name of its family (of :func:`families`' output, parsed once)."""
    return {m["word"]: f["family"] for f in fams for m in f["members"]}


def by_resonance(resonant: list[dict]) -> list[dict]:
    """The attractors grouped by the resonance p/q at which their windows end (the summary's
    ``resonant_upper_ends``), by decreasing p/q (increasing r)."""
    groups: dict[tuple, list] = {}
    for x in resonant:
        groups.setdefault((x["p"], x["q"]), []).append(x["attractor"])
    return [{"p": p, "q": q, "attractors": sorted(groups[(p, q)])}
            for p, q in sorted(groups, key=lambda pq: -Fraction(*pq))]


# ------------------------------------------------------------------ the document
def _counts(orbits: list[dict]) -> dict:
    c: dict[str, int] = {}
    for o in orbits:
        k = name(o["word"], o["branch"]) if o["class"] == ATTRACTING else o["class"]
        c[k] = c.get(k, 0) + 1
    return dict(sorted(c.items()))


def _timeless(rec: dict) -> dict:
    return {k: v for k, v in rec.items() if k not in ("seconds", "cpu_seconds")}


def document(r_records: list[dict], word_records: list[dict], parameters: dict) -> dict:
    """The atlas as one JSON document (deterministic: no timing)."""
    atts = attractors_of(word_records)
    cells = stitch(atts)
    rows = []
    for rec in r_records:
        q = Fraction(rec["r"])
        chaos = rec.get("chaos")
        seen_by = {c["index"]: c for c in chaos["orbits"]} if chaos else {}
        rows.append({"r": rec["r"], "digits": f"{float(q):.6f}", "island": rec["island"],
                     "counts": _counts(rec["orbits"]), "total": len(rec["orbits"]),
                     "horseshoe": chaos["horseshoe"] if chaos else None,
                     "orbits": [{**{k: o[k] for k in ORBIT_KEYS},
                                 **{k: o.get(k) for k in ORBIT_LATE_KEYS},
                                 "visits_horseshoe": seen_by.get(i, {}).get("visits_horseshoe"),
                                 "curve": seen_by.get(i, {}).get("curve")} for i, o in enumerate(rec["orbits"])]})
    for cell in cells:
        sampled = [row for row in rows if _in_cell(Fraction(row["r"]), cell)]
        cell["sampled"] = [row["r"] for row in sampled]
        total = sum(row["total"] for row in sampled)
        counts: dict[str, int] = {}
        for row in sampled:
            for k, n in row["counts"].items():
                counts[k] = counts.get(k, 0) + n
        cell["orbits"] = total
        cell["counts"] = dict(sorted(counts.items()))
        cell["unresolved"] = counts.get(UNRESOLVED, 0)
        cell["intervals"] = {k: wilson(n, total) for k, n in cell["counts"].items()}
        proved = [row["horseshoe"] for row in sampled if (row["horseshoe"] or {}).get("certified")]
        cell["horseshoes"] = {"sampled": sum(row["horseshoe"] is not None for row in sampled), "proved": len(proved),
                              "entropy_lower": _entropy_range(proved)}
        fr = [row["island"]["fraction"] for row in sampled if row["island"]]
        cell["island_fraction"] = ([str(min(Fraction(f[0]) for f in fr)), str(max(Fraction(f[1]) for f in fr))]
                                   if fr else None)
    seen: dict[str, list] = {}
    for row in rows:
        for o in row["orbits"]:
            if o["class"] == ATTRACTING:
                seen.setdefault(name(o["word"], o["branch"]), []).append(row["r"])
    no_window = []
    for w in word_records:
        if w["outcome"] != "analysed":
            met = [k for k in sorted(seen) if k.startswith(w["compact"] + " (")] or [w["compact"]]
            for k in met:
                no_window.append({"attractor": k, "word": w["word"], "length": w["length"], "why": why_no_window(w),
                                  "source": w.get("source", "met"),
                                  "seen_at": sorted(set(seen.get(k, [])), key=Fraction)})
    source = {w["word"]: w.get("source", "met") for w in word_records}
    fams = families(atts, word_records)
    member = family_of(fams)
    attractors = [{"name": name(a["word"], a["branch"]), **a, "source": source[a["word"]],
                   "windows": [{**w, "rotation": end_rotation(w["hi"])} for w in a["windows"]],
                   "family": member.get(a["word"]),
                   "seen_at": sorted(set(seen.get(name(a["word"], a["branch"]), [])), key=Fraction)} for a in atts]
    inconsistent = []
    by_name = {a["name"]: a for a in attractors}
    analysed = {w["word"] for w in word_records if w["outcome"] == "analysed"}
    for row in rows:
        x = Algebraic.rational(flint.fmpq(Fraction(row["r"]).numerator, Fraction(row["r"]).denominator))
        for k in sorted({name(o["word"], o["branch"]) for o in row["orbits"] if o["class"] == ATTRACTING}):
            word = next(o["word"] for o in row["orbits"] if o["word"] and name(o["word"], o["branch"]) == k)
            if word in analysed and not any(_alg(w["lo"]) < x < _alg(w["hi"]) for w in
                                            (by_name[k]["windows"] if k in by_name else [])):
                inconsistent.append({"attractor": k, "r": row["r"]})
    resonant, above = [], 0
    for a in attractors:
        for w in a["windows"]:
            rot = w["rotation"]
            if rot is not None:
                above += 1
                if rot["resonance"]:
                    resonant.append({"attractor": name(a["word"], a["branch"]), "hi": w["hi"]["digits"],
                                     "p": rot["resonance"][0], "q": rot["resonance"][1],
                                     "island_end": rot["island_end"]})
    interior = interior_ends(attractors)
    totals = {k: sum(row["counts"].get(k, 0) for row in rows) for k in (ISLAND, UNRESOLVED)}
    totals[ATTRACTING] = sum(n for row in rows for k, n in row["counts"].items() if k not in (ISLAND, UNRESOLVED))
    return {"schema": SCHEMA, "version": VERSION, "parameters": parameters,
            "summary": {"r_values": len(rows), "orbits": sum(row["total"] for row in rows), "classes": totals,
                        "words": len(word_records), "attractors_with_windows": len(atts),
                        "attractors_without_windows": len(no_window), "inconsistent": inconsistent,
                        "upper_ends_above": above, "resonant_upper_ends": resonant, "interior_ends": interior,
                        "seeds": sum(w.get("source", "met") != "met" for w in word_records),
                        "families": len(fams), "certified_share_above": share_above(rows),
                        "unruled_closings": unruled(resonant, attractors),
                        "unresolved_by_kind": unresolved_by_kind(rows), "horseshoes": horseshoes(rows)},
            "attractors": attractors, "without_window": no_window, "cells": cells,
            "families": fams, "by_resonance": by_resonance(resonant), "curves": curves_of(rows),
            "observed_words": observed_words(rows),
            "words": [_timeless(w) for w in word_records], "r": rows}


def interior_ends(attractors: list[dict]) -> dict:
    """How many window ends lie strictly inside ]3 − 2√2, 1[ (not the island's own ends), lower and
    upper, and how many of them are resonances (:func:`end_rotation`, decided once per end)."""
    out = {"upper": 0, "lower": 0, "resonant_upper": 0, "resonant_lower": 0}
    for a in attractors:
        for w in a["windows"]:
            for side, end in (("lower", w["lo"]), ("upper", w["hi"])):
                rot = end_rotation(end)
                if rot is not None and not rot["island_end"]:
                    out[side] += 1
                    out["resonant_" + side] += bool(rot["resonance"])
    return out


def why_no_window(w: dict) -> str:
    """Why a word record has no window, in one phrase."""
    if w["outcome"] == "too long":
        return (f"too long: {w['length']} letters, over the {w['word_max']} whose window `certify orbit` computes "
                f"(MAX_ORBIT_LENGTH = {MAX_ORBIT_LENGTH}: the conditions' degree grows like 2L)")
    if w["outcome"] == "time limit":
        return f"time limit: the window's analysis took over {w['word_seconds']} s of CPU"
    return w["outcome"] + (f" ({w['error']})" if w.get("error") else "")


def unresolved_by_kind(rows: list[dict]) -> dict:
    """The unresolved orbits by what they show (:func:`explained`), and the orbits whose
    class the longer run of a long transient proved."""
    out = {k: 0 for k in (TRANSIENT, NEAR_HORSESHOE, NOT_ATTRACTING, NOTHING)}
    for row in rows:
        for o in row["orbits"]:
            if o["class"] == UNRESOLVED:
                out[explained(o)] += 1
    out["certified by a longer run"] = sum(1 for row in rows for o in row["orbits"]
                                           if o["rerun"] and o["class"] != UNRESOLVED)
    return out


def _entropy_range(proved: list[dict]) -> list[str] | None:
    """The least and the largest certified entropy bound of the proved horseshoes, or None."""
    hs = sorted((x["entropy_lower"] for x in proved), key=Fraction)
    return [hs[0], hs[-1]] if hs else None


def horseshoes(rows: list[dict]) -> dict:
    """At how many sampled r the horseshoe search ran and proved a horseshoe (certified), the
    range of the entropy bounds, below and above 3 − 2√2, and the unresolved orbits near one
    (observed)."""
    searched = [row for row in rows if row["horseshoe"] is not None]
    proved = [row for row in searched if row["horseshoe"]["certified"]]
    return {"searched": len(searched), "proved": len(proved),
            "proved_below": sum(row["island"] is None for row in proved),
            "proved_above": sum(row["island"] is not None for row in proved),
            "entropy_lower": _entropy_range([row["horseshoe"] for row in proved]),
            "r": [row["r"] for row in proved]}


def share_above(rows: list[dict]) -> dict:
    """The orbits sampled above 3 − 2√2 and how many have a certified class (island or
    attracting periodic): observed counts of certified classes, and the share's 95% interval
    (:func:`wilson`)."""
    n = sum(row["total"] for row in rows if row["island"] is not None)
    u = sum(row["counts"].get(UNRESOLVED, 0) for row in rows if row["island"] is not None)
    return {"orbits": n, "certified": n - u, "interval": wilson(n - u, n)}


Z95 = 1.959963984540054                       # the normal quantile of 97.5 %: two-sided 95 %


def wilson(n: int, total: int, z: float = Z95) -> list[str] | None:
    """The Wilson score interval of the share n/total at 95 % (observed: it reads the data as
    independent draws, which the grid's are not; docs/atlas.md says what it means), its ends
    to 4 decimals (the lower rounded down, the upper up); None for no data."""
    if not total:
        return None
    p, z2 = n / total, z * z
    centre = (p + z2 / (2 * total)) / (1 + z2 / total)
    half = z * math.sqrt(p * (1 - p) / total + z2 / (4 * total * total)) / (1 + z2 / total)
    return [f"{math.floor(max(centre - half, 0.0) * 10 ** 4) / 10 ** 4:.4f}",
            f"{math.ceil(min(centre + half, 1.0) * 10 ** 4) / 10 ** 4:.4f}"]


RULE_K = 16          # a window's word is given by a rule when it is member k ≤ RULE_K (certified range or not)


def unruled(resonant: list[dict], attractors: list[dict]) -> list[dict]:
    """The windows closing at an interior resonance whose word no rule of :data:`FAMILIES`
    spells for any k ≤ :data:`RULE_K` (members past a rule's certified ones count as given)."""
    spelt = {rule.word(k) for rule in FAMILIES for k in range(rule.first, RULE_K + 1)}
    ruled = {a["name"] for a in attractors if a["family"] or a["word"] in spelt}
    return [{"attractor": x["attractor"], "p": x["p"], "q": x["q"]} for x in resonant
            if not x["island_end"] and x["attractor"] not in ruled]


def observed_words(rows: list[dict]) -> dict[str, int]:
    """The words the unresolved orbits' runs repeat, one entry per cyclic word (its
    :func:`least_rotation`), with how many orbits; most frequent first."""
    out: dict[str, int] = {}
    for row in rows:
        for o in row["orbits"]:
            if o["observed"]:
                w = least_rotation(o["observed"])
                out[w] = out.get(w, 0) + 1
    return dict(sorted(out.items(), key=lambda kv: (-kv[1], kv[0])))


def least_rotation(word: str) -> str:
    """The least rotation of a cyclic word (the same periodic block read from another
    collision: one row per cyclic word in the tables of observed words; no validation, so
    blocks longer than the reader's 400 letters are normalised too)."""
    return min(word[k:] + word[:k] for k in range(len(word)))


def curves_of(rows: list[dict]) -> list[dict]:
    """The unresolved orbits that repeat a word without converging, by cyclic word (its
    :func:`least_rotation`): how many, where, and the rotation numbers of their loops
    (observed, :func:`chaos_job`)."""
    out: dict[str, dict] = {}
    for row in rows:
        for o in row["orbits"]:
            c = o.get("curve")
            if o["class"] != UNRESOLVED or c is None:
                continue
            w = least_rotation(o["observed"])
            g = out.setdefault(w, {"word": w, "returns": c["returns"], "orbits": 0,
                                               "r": [], "rotation": [], "near": set(), "radius_drift": []})
            g["orbits"] += 1
            g["r"].append(row["r"])
            g["rotation"].append(c["rotation"])
            g["near"].add(tuple(c["near"]))
            g["radius_drift"].append(c["radius_drift"])
    res = []
    for w, g in sorted(out.items(), key=lambda kv: (-kv[1]["orbits"], kv[0])):
        rot, drift = sorted(g["rotation"], key=Fraction), sorted(g["radius_drift"], key=float)
        res.append({"word": w, "returns": g["returns"], "orbits": g["orbits"],
                    "r": [min(g["r"], key=Fraction), max(g["r"], key=Fraction)], "rotation": [rot[0], rot[-1]],
                    "near": [list(x) for x in sorted(g["near"], key=lambda pq: Fraction(*pq))],
                    "radius_drift": [drift[0], drift[-1]]})
    return res


def to_json(doc: dict) -> str:
    return json.dumps(doc, sort_keys=True, ensure_ascii=False, indent=1) + "\n"


# ------------------------------------------------------------------ ATLAS.md
def _end(e: dict) -> str:
    return e["exact"] if e["exact"] is not None else "≈" + e["digits"]


def _share(n: int, total: int) -> str:
    return f"{n}/{total} ({100 * n / total:.0f}%)" if total else "—"


def _interval(iv: list | None) -> str:
    return f" [{iv[0]}, {iv[1]}]" if iv else ""


def _cell_horseshoes(h: dict) -> str:
    if not h["sampled"]:
        return "—"
    if not h["proved"]:
        return f"none found at {h['sampled']} r"
    lo, hi = h["entropy_lower"]
    return f"{h['proved']} of {h['sampled']} r; entropy ≥ {lo}" + (f" to ≥ {hi}" if hi != lo else "")


def _horseshoe_line(h: dict) -> str:
    if not h["searched"]:
        return "- chaos: no horseshoe search in this atlas"
    rng = (f"; entropy bounds from {h['entropy_lower'][0]} to {h['entropy_lower'][1]} (log ρ(T)/k, certified)"
           if h["entropy_lower"] else "")
    return (f"- chaos (certified): a horseshoe proved at {h['proved']} of the {h['searched']} sampled r "
            f"({h['proved_below']} below 3−2√2, {h['proved_above']} above){rng}; at the other r the search found none "
            "(nothing is claimed there). A horseshoe is an invariant set of measure zero: it proves chaos there, not "
            "that an unresolved orbit is chaotic")


def _unresolved_section(doc: dict) -> list[str]:
    """ATLAS.md's section on the unresolved orbits: by kind, the loops' rotation numbers."""
    from certify.numerics import horseshoe
    s = doc["summary"]
    out = ["", "## Unresolved orbits", "",
           "What each unresolved orbit shows (observed, never a proof): " + "; ".join(
               f"{k}: {n}" for k, n in s["unresolved_by_kind"].items() if k != "certified by a longer run") + ". "
           f"*Near a certified horseshoe*: its float64 run, after the first {horseshoe.TRANSIENT_RETURNS} returns to "
           "b, enters a box of the "
           "horseshoe proved at its r. That does not make the orbit chaotic: the horseshoe is a set of measure zero.",
           "", "*Repeats a word without converging* (the word's periodic orbit at r is not attracting, or none): the "
           "run's states at b, every k returns (k = the b's of the word), turn around a loop. Its rotation number "
           "(observed; the mean counterclockwise turn per k returns about the loop's centre, in coordinates where "
           "the loop is round, as the island's ρ is measured: on island orbits the estimate gives the certified ρ to "
           "6 digits) and the radius drift (the loop's size at the end of the run over that at its middle: ≈ 1, an "
           "invariant curve; away from 1, a spiral, a slow transient).", ""]
    if not doc["curves"]:
        return out + ["None in this atlas."]
    out += [f"| word | k | orbits | r | rotation number (observed) | nearest p/q (q ≤ {NEAR_Q}) | radius drift |",
            "|---|---:|---:|---|---|---|---|"]
    for c in doc["curves"]:
        w = compact(read(c["word"])[0]) if len(c["word"]) < 400 else c["word"][:40] + "…"
        out.append(f"| `{w}` | {c['returns']} | {c['orbits']} | {c['r'][0]} to {c['r'][1]} | "
                   f"{c['rotation'][0]} to {c['rotation'][1]} | {', '.join(f'{p}/{q}' for p, q in c['near'])} | "
                   f"{c['radius_drift'][0]} to {c['radius_drift'][1]} |")
    return out


def _rot(x: dict | None) -> str:
    if x is None:
        return "— (below 3−2√2: no island)"
    if x["resonance"]:
        return f"ρ = {x['resonance'][0]}/{x['resonance'][1]} exactly (a resonance)"
    return f"ρ ≈ {x['rho']}, near {x['near'][0]}/{x['near'][1]} (distance {x['distance']}; observed)"


def markdown(doc: dict, figure: str | None = None) -> str:
    """ATLAS.md: what was run, the cells (certified coexistence, observed shares), the
    attractors and their windows, those without a window, the families, the observed words."""
    p, s = doc["parameters"], doc["summary"]
    cls = s["classes"]
    out = ["# Atlas of the attractors of the reduction over ]0, 1[", "",
           f"Written by `{p['command']}` (certify/run/atlas.py); do not edit by hand.", "",
           f"- r: {s['r_values']} rationals in ]{p['r_range'][0]}, {p['r_range'][1]}[ (midpoints of equal cells); "
           f"initial data per r: the tool's 8 and {p['data']} Halton points of the b-section (θ0 ∈ ]0, π/2[, "
           f"φ0 ∈ ]0, π[); {p['collisions']} collisions per float64 run and per rigorous scan",
           f"- orbits: {s['orbits']}: island {cls[ISLAND]}, attracting periodic (certified) {cls[ATTRACTING]}, "
           f"unresolved {cls[UNRESOLVED]} (`certify identify`'s classes)",
           "- unresolved, by what they show (observed): " + "; ".join(
               f"{k}: {n}" for k, n in s["unresolved_by_kind"].items() if k != "certified by a longer run")
           + f" (a long transient: its word attracts at r; a long transient and a run with no period at all are run "
           f"again {LATE}× longer, a run with no period above 3−2√2 and a run repeating a word not attracting at r "
           f"{LONGER}× longer, then, when that word repels slowly, over {SPIRAL_EFOLDS} e-folds of its repulsion (up "
           f"to {SPIRAL_MAX}× longer; the ball scan leaps over the winding, proved), and "
           f"{s['unresolved_by_kind']['certified by a longer run']} orbits were proved so "
           "(identify's proof on the longer run) and are counted in their class; near a certified horseshoe: its "
           "float64 run enters a box of the horseshoe proved at r; a word not "
           "attracting at r: repeated without converging, a loop around an invariant curve or a slow transient, its "
           "rotation number under \"Unresolved orbits\" below)",
           _horseshoe_line(s["horseshoes"]),
           f"- words certified: {s['words']}; attractors (word, branch) with an exact window over ]0, 1[: "
           f"{s['attractors_with_windows']}; without one: {s['attractors_without_windows']} (longer than "
           f"{p['word_max']} letters, or over the time limit of {p['word_seconds']} s of CPU: known only at the r "
           "where "
           f"seen, by `orbit_at`); an orbit's block is decided at its r up to {LONG_WORD} letters (the parser's "
           f"{MAX_LENGTH} guards what users type: the exact decision at one r needs none; a longer block is not "
           "analysed)",
           f"- seeds: {s['seeds']} known attracting words analysed whether or not the grid meets them (the families' "
           "members, the census's and `identify --section5`'s attracting words); the grid: "
           f"{p['resolution']} r and {p.get('refine', 0)} rounds of refinement (an r in every unsampled cell, near "
           "each window end, around words without a window)",
           f"- interior window ends (strictly inside ]3−2√2, 1[, not the island's own ends) that are resonances of "
           f"the island (ρ = p/q exactly, q ≤ {RESONANCE_Q}): upper ends {s['interior_ends']['resonant_upper']} of "
           f"{s['interior_ends']['upper']}, lower ends {s['interior_ends']['resonant_lower']} of "
           f"{s['interior_ends']['lower']}; besides, {sum(x['island_end'] for x in s['resonant_upper_ends'])} "
           "windows end at the island's own ends (3−2√2, ρ = 1/2; r = 1, ρ → 1/4)",
           f"- families (rules with at least three certified members and the next member predicted): "
           f"{s['families']}; orbits sampled above 3−2√2 with a certified class: "
           f"{_share(s['certified_share_above']['certified'], s['certified_share_above']['orbits'])}"
           f"{_interval(s['certified_share_above']['interval'])}",
           "- certified orbits outside their word's certified window: "
           + (", ".join(f"{x['attractor']} at r = {x['r']}" for x in s["inconsistent"]) or "none"), "",
           "**Certified**: each orbit's class (island: quasi-periodic for ever, by the island theorem; attracting "
           "periodic: it follows its word for ever, by a certified trapping ellipse), each attractor's window (exact "
           "algebraic ends, `certify orbit`), the cells (the windows' ends compared exactly), the coexistence of the "
           "attractors in a cell (each is attracting at every r of the cell), the island's share of the b-section "
           "(an interval, `island_fraction`) and its rotation number. **Observed**: the share of the sampled initial "
           "data that reaches each class or attractor (a finite grid) and its 95% interval (Wilson's, reading the data "
           "as independent draws: a yardstick, see docs/atlas.md), the unresolved orbits' words, the rotation numbers "
           "of their loops, whether they visit a horseshoe's boxes, and a window end's nearness to a rotation number "
           "p/q that is not exactly a resonance. **Chaos** (certified where proved): at each sampled r the horseshoe "
           "search of `certify chaos` ran; where it proved one, the b-to-b map has positive topological entropy "
           "(the bound printed) and periodic orbits of infinitely many periods on an invariant set. That set has "
           "measure zero: a horseshoe proves chaos on it, not that every unresolved orbit is chaotic.", ""]
    if figure:
        out += [f"![the attractors' certified windows, the island's rotation number above]({figure})", ""]
    out += ["## Cells", "",
            "The open intervals between consecutive window ends (exact; 3−2√2 added, where the island appears). "
            "Attractors: those met by the atlas whose certified window contains the cell. Shares: over the "
            "initial data at the sampled r inside the cell (observed).", "",
            "| cell ]lo, hi[ | attractors (certified) | island | sampled r | shares of the orbits, 95% interval "
            "(observed) | unresolved | island's area (certified) | horseshoe at the sampled r (certified) |",
            "|---|---|---|---:|---|---:|---|---|"]
    for c in doc["cells"]:
        shares = "; ".join(f"{k}: {_share(n, c['orbits'])}{_interval(c['intervals'][k])}"
                           for k, n in c["counts"].items() if k != UNRESOLVED) or "—"
        fr = c["island_fraction"]
        unres = (_share(c["unresolved"], c["orbits"]) + _interval(c["intervals"].get(UNRESOLVED))
                 if c["unresolved"] else _share(0, c["orbits"]))
        out.append(f"| ]{_end(c['lo'])}, {_end(c['hi'])}[ | {', '.join(f'`{a}`' for a in c['attractors']) or '—'} | "
                   f"{'yes' if c['island'] else ''} | {len(c['sampled'])} | {shares} | "
                   f"{unres} | "
                   f"{f'[{float(Fraction(fr[0])):.3f}, {float(Fraction(fr[1])):.3f}]' if fr else '—'} | "
                   f"{_cell_horseshoes(c['horseshoes'])} |")
    out += ["", "## Attractors and their certified windows", "",
            "| attractor (word, branch) | length | window(s) (certified) | pair | ρ at the upper end | known from | "
            "sampled r where reached |", "|---|---:|---|---|---|---|---|"]
    for a in doc["attractors"]:
        wins = "; ".join(f"]{_end(w['lo'])}, {_end(w['hi'])}[" for w in a["windows"])
        pairs = ", ".join(sorted({w["pair"] for w in a["windows"]}))
        rot = "; ".join(_rot(w["rotation"]) for w in a["windows"])
        seen = ", ".join(a["seen_at"][:6]) + (f" … ({len(a['seen_at'])})" if len(a["seen_at"]) > 6 else "")
        known = a["source"] + (f" (family {a['family']})" if a["family"] and a["source"] == "met" else "")
        out.append(f"| `{a['name']}` | {a['length']} | {wins} | {pairs} | {rot} | {known} | {seen or '—'} |")
    if doc["without_window"]:
        out += ["", "### Attractors without a window", "",
                "Certified attracting at the r where reached (`orbit_at` and a trapping ellipse, through identify), "
                "or seeded; their window over ]0, 1[ was not computed.", "",
                "| attractor | length | why no window | known from | sampled r where reached |",
                "|---|---:|---|---|---|"]
        for a in doc["without_window"]:
            out.append(f"| `{a['attractor']}` | {a['length']} | {a['why']} | {a['source']} | "
                       f"{', '.join(a['seen_at']) or '—'} |")
    out += ["", "## Families", "",
            "Each family is a rule read off its members (a conjecture): member k's word, and the resonance "
            "p_k/q_k of the island at which its window closes (its upper end). Each member listed is certified by "
            "`certify orbit` (its exact window) and its closing decided exactly (the same algebraic number as the "
            "resonance r_{p/q}); then the rule's prediction, certified the same way; then the members past the "
            f"prediction (k ≤ {RULE_K}) that the atlas's orbits met, certified the same way: they test the rule, "
            "and are not counted among its certified members.", ""]
    for f in doc["families"]:
        out += [f"### `{f['family']}`: {f['certified_members']} certified members, the prediction "
                f"{'certified' if f['prediction_certified'] else 'NOT certified'}", "",
                f"Member k: `{f['rule']}`" + (f"; its window closes at ρ = {f['closing']}." if f["closing"] else
                                             "; below 3−2√2 (no island, no closing resonance)."), "",
                "| k | length | window(s) (certified) | closes at p_k/q_k | status |", "|---:|---:|---|---|---|"]
        for m in f["members"]:
            wins = "; ".join(f"]{w['lo']}, {w['hi']}[ ({w['branch']}, {w['pair']})" for w in m["windows"]) or \
                f"none ({m['outcome']})"
            closing = ("—" if m["closing"] is None else
                       f"{m['closing'][0]}/{m['closing'][1]}: {'yes, exactly' if m['closes'] else 'no'}")
            status = ("predicted, " if m["predicted"] else "met beyond the prediction, " if m.get("beyond") else
                      "") + ("certified" if m["certified"] else "not certified")
            out.append(f"| {m['k']} | {m['length']} | {wins} | {closing} | {status} |")
        out.append("")
    left = doc["summary"]["unruled_closings"]
    out += ["Windows closing at an interior resonance whose word no rule above spells, for any k ≤ "
            f"{RULE_K} (no rule found): "
            + (", ".join(f"`{x['attractor']}` ({x['p']}/{x['q']})" for x in left) if left else "none") + ".", ""]
    out += ["## By the resonance at which the windows end", "",
            "The island's rotation number at a window's upper end, when it is exactly p/q (decided as algebraic "
            "numbers): the windows that close at the same resonance.", "",
            "| ρ = p/q at the upper end | attractors |", "|---|---|"]
    out += [f"| {g['p']}/{g['q']} | {', '.join(f'`{a}`' for a in g['attractors'])} |" for g in doc["by_resonance"]]
    if doc["observed_words"]:
        out += ["", "## Words observed in unresolved orbits", "",
                "The float64 run repeats the word to its end, but no proof stands (the word's orbit is not "
                "attracting at r, or the rigorous orbit did not enter a trap): observed, with how many orbits.", ""]
        out += [f"- `{compact(read(w)[0]) if len(w) < 400 else w[:40] + '…'}`: {n}"
                for w, n in list(doc["observed_words"].items())[:30]]
    out += _unresolved_section(doc)
    out += ["", "## Per r", "",
            "| r | island (ρ; certified area) | orbits: shares (observed) | horseshoe (certified: entropy ≥) |",
            "|---:|---|---|---|"]
    for row in doc["r"]:
        isl = row["island"]
        it = (f"ρ = {isl['rotation_number']}; [{float(Fraction(isl['fraction'][0])):.3f}, "
              f"{float(Fraction(isl['fraction'][1])):.3f}]") if isl else "—"
        shares = "; ".join(f"{k}: {n}" for k, n in row["counts"].items())
        hs = row["horseshoe"]
        hs_text = ("not searched" if hs is None else
                   f"{hs['entropy_lower']} (saddle {hs['saddle']}, {len(hs['boxes'])} boxes)" if hs["certified"]
                   else "none found")
        out.append(f"| {row['r']} | {it} | {shares} (of {row['total']}) | {hs_text} |")
    return "\n".join(out) + "\n"


# ------------------------------------------------------------------ the figure
def _short(text: str, n: int = 34) -> str:
    return text if len(text) <= n else text[:n - 12] + "…" + text[-11:]


LABELLED_Q = 12        # atlas.png names the resonances p/q with q ≤ 12; the others (up to 40 near 3−2√2) are lines


ZOOM = (0.1712, 0.1800)   # atlas.png's zoom: the windows accumulating on 3−2√2 ≈ 0.171573 from above


def _bars(ax, atts: list[dict], colour: dict, lo: float, hi: float) -> None:
    """One row per attractor: its certified windows inside [lo, hi] as bars, the sampled r where
    data reached it as dots."""
    for k, a in enumerate(atts):
        for w in a["windows"]:
            x0, x1 = max(float(w["lo"]["digits"]), lo), min(float(w["hi"]["digits"]), hi)
            if x0 < x1:
                ax.barh(k, x1 - x0, left=x0, height=0.6, color=colour[w["pair"]])
        xs = [float(Fraction(r)) for r in a.get("seen_at", []) if lo <= float(Fraction(r)) <= hi]
        ax.plot(xs, [k] * len(xs), "k.", ms=2)


def figure(doc: dict, path) -> Path:
    """atlas.png: top, the island's rotation number ρ(r) on ]3−2√2, 1[ (certified digits at the
    sampled r) with the windows' resonant ends (dotted; labelled p/q where q ≤ LABELLED_Q); then
    one row per attractor, its certified windows as bars and the sampled r where data reached it
    as dots; then the observed shares at each sampled r (island, attracting, unresolved); bottom,
    a zoom on :data:`ZOOM`, near 3−2√2, where the windows are too narrow at full width (the
    attractors with a window there).  Floats: a drawing only."""
    from . import plots, saving
    plt = saving.pyplot()
    atts = doc["attractors"]
    rows = doc["r"]
    n = len(atts) + len(doc["without_window"])
    zoomed = [a for a in atts if any(float(w["lo"]["digits"]) < ZOOM[1] and float(w["hi"]["digits"]) > ZOOM[0]
                                     for w in a["windows"])]
    m = max(len(zoomed), 4)
    lo, hi = (float(Fraction(x)) for x in doc["parameters"]["r_range"])
    fig, (ax0, ax, bx, zx) = plt.subplots(4, 1, figsize=(9, 4.6 + 0.22 * (max(n, 4) + m)),
                                          gridspec_kw={"height_ratios": [1.2, max(n, 4) * 0.3, 1.4, m * 0.3]})
    ax.sharex(ax0)
    bx.sharex(ax0)
    isl = [(float(Fraction(r["r"])), float(r["island"]["rotation_number"])) for r in rows if r["island"]]
    if isl:
        ax0.plot(*zip(*isl), ".-", color="tab:green", ms=2, lw=0.8)
    ends = sorted({(float(x["hi"]), x["p"], x["q"]) for x in doc["summary"]["resonant_upper_ends"]})
    for x, _p, _q in ends:
        for panel, (a, b) in ((ax0, (lo, hi)), (ax, (lo, hi)), (zx, ZOOM)):
            if a <= x <= b:
                panel.axvline(x, color="grey", lw=0.4, ls=":")
    marks = {f"{p}/{q}": x for x, p, q in ends if lo <= x <= hi and q <= LABELLED_Q}   # the others: lines only
    ax0.set_ylabel("ρ", fontsize=8)
    colour = {"real": "tab:orange", "complex": "tab:red", "real and complex": "tab:purple"}
    _bars(ax, atts, colour, lo, hi)
    for k, a in enumerate(doc["without_window"], start=len(atts)):
        xs = [float(Fraction(r)) for r in a["seen_at"]]
        ax.plot(xs, [k] * len(xs), "k.", ms=2)
    labels = [_short(a["name"]) for a in atts]
    labels += [_short(a["attractor"]) + " (no window)" for a in doc["without_window"]]
    ax.set_yticks(range(len(labels)), labels, fontsize=6)
    ax.invert_yaxis()
    for panel in (ax, zx):
        panel.axvline(3 - 2 * 2 ** 0.5, color="grey", lw=0.6, ls="--")
    ax.set_title("certified attracting windows (bars; orange: real in-plane pair, red: complex) and the sampled r "
                 "where data reached each (dots)", fontsize=7)
    xs = [float(Fraction(r["r"])) for r in rows]
    parts = [(ISLAND, "tab:green"), (ATTRACTING, "tab:orange"), (UNRESOLVED, "lightgrey")]
    bottom = [0.0] * len(rows)
    for key, c in parts:
        ys = []
        for r in rows:
            n = sum(v for k, v in r["counts"].items() if (k == key) or (key == ATTRACTING and k not in
                                                                          (ISLAND, UNRESOLVED)))
            ys.append(n / r["total"] if r["total"] else 0)
        bx.bar(xs, ys, bottom=bottom, width=(hi - lo) / max(len(rows), 1), color=c, label=key, lw=0)
        bottom = [b + y for b, y in zip(bottom, ys)]
    bx.set_ylim(0, 1)
    bx.set_ylabel("share", fontsize=8)
    bx.legend(fontsize=6, loc="center right", bbox_to_anchor=(-0.1, 0.5))   # in the margin: it covers no bar
    bx.set_xlim(lo, hi)
    bx.set_xlabel("r")
    _bars(zx, zoomed, colour, *ZOOM)
    zx.set_yticks(range(len(zoomed)), [_short(a["name"]) for a in zoomed], fontsize=6)
    zx.set_ylim(len(zoomed) - 0.5 if zoomed else 3.5, -0.5)
    zx.set_xlim(*ZOOM)
    zx.set_xlabel("r", fontsize=8)
    zx.tick_params(axis="x", labelsize=7)
    zx.set_title(f"zoom on r in [{ZOOM[0]}, {ZOOM[1]}], just above 3−2√2 (dashed): the windows accumulating there, "
                 "the same bars and dots", fontsize=7)
    for panel in (ax0, ax):                       # each panel its own r ticks
        panel.tick_params(labelbottom=True)
    fig.tight_layout()
    fig.subplots_adjust(left=0.3)
    rows = plots.label_lines(ax0, marks, color="black")     # the axes placed: the labels in rows, none overlapping
    ax0.set_title(f"the island's rotation number ρ(r); dotted: windows ending at ρ = p/q exactly (named for "
                  f"q ≤ {LABELLED_Q}; all in ATLAS.md)", fontsize=7,
                  pad=plots.label_pad(rows))
    fig.tight_layout()
    fig.subplots_adjust(left=0.3)
    path = Path(path)
    with saving.output_dir(path.parent):
        saving.save_figure(fig, path.name)
    return path


def write_outputs(doc: dict, out) -> None:
    """OUT/ATLAS.md, OUT/atlas.json, OUT/atlas.png."""
    out = Path(out)
    figure(doc, out / FIGURE)
    write_atomic(out / "ATLAS.md", markdown(doc, FIGURE))
    write_atomic(out / "atlas.json", to_json(doc))


# ------------------------------------------------------------------ the check
def rational_inside(a: Algebraic, b: Algebraic) -> flint.fmpq:
    """A rational strictly between a < b (enclosures refined until they separate)."""
    prec = 64
    while True:
        ua, lb = ends(a.arb(prec))[1], ends(b.arb(prec))[0]
        if ua < lb:
            return (ua + lb) / 2
        prec *= 2


def _fq(r: str) -> flint.fmpq:
    q = Fraction(r)
    return flint.fmpq(q.numerator, q.denominator)


def _attracting_at(word: str, r: flint.fmpq) -> set[str]:
    """The names of the attracting periodic orbits of ``word`` (a normal form) at r, by ``orbit_at``
    (exact; up to :data:`LONG_WORD` letters; once per run with identify's decisions)."""
    return {name(word, o.branch_name) for o in ident.orbits_at(word, r)
            if o.feasible and o.kind == ATTRACTING.split()[0]}


def _same_end(x: dict, y: dict) -> bool:
    return _alg(x) == _alg(y)


def check_windows(doc: dict, window_max: int) -> list[str]:
    """Each analysed word of at most ``window_max`` letters: its windows recomputed by
    ``certify orbit`` equal the atlas's (branch, pair, ends exactly)."""
    problems = []
    mine = {(a["word"], a["branch"]): a["windows"] for a in doc["attractors"]}
    for w in doc["words"]:
        if w["outcome"] != "analysed" or w["length"] > window_max:
            continue
        fresh = analyse(w["word"], self_similar=False).attracting()
        want: dict = {}
        for a in fresh:
            want.setdefault(a["branch"], []).append(a)
        have = {br: wins for (word, br), wins in mine.items() if word == w["word"]}
        for br in sorted(set(want) | set(have)):
            x, y = want.get(br, []), have.get(br, [])
            if len(x) != len(y) or not all(_same_end(p["lo"], q["lo"]) and _same_end(p["hi"], q["hi"])
                                           and p["pair"] == q["pair"] for p, q in zip(x, y)):
                problems.append(f"{name(w['word'], br)}: window(s) "
                                f"{[(q['lo']['digits'], q['hi']['digits']) for q in y]} in the atlas, "
                                f"{[(p['lo']['digits'], p['hi']['digits']) for p in x]} by certify orbit")
    return problems


def check_cells(doc: dict) -> list[str]:
    """The cells stitched again from the attractors' windows, and each cell's attractors
    re-derived by ``orbit_at`` at a rational inside it (a sampled r, else one chosen): every
    analysed word attracting there is listed, and every listed one is attracting there."""
    problems = []
    fresh = stitch(doc["attractors"])
    key = lambda c: (c["lo"]["digits"], c["hi"]["digits"], tuple(c["attractors"]))     # noqa: E731
    if [key(c) for c in fresh] != [key(c) for c in doc["cells"]]:
        problems.append("the cells differ from the windows stitched again")
    analysed = [w["word"] for w in doc["words"] if w["outcome"] == "analysed"]
    for c in doc["cells"]:
        a, b = _alg(c["lo"]), _alg(c["hi"])
        r = _fq(c["sampled"][0]) if c["sampled"] else rational_inside(a, b)
        if not a < Algebraic.rational(r) < b:
            problems.append(f"cell ]{c['lo']['digits']}, {c['hi']['digits']}[: its sampled r = {r} is not inside")
            continue
        want = set().union(*[_attracting_at(w, r) for w in analysed]) if analysed else set()
        if want != set(c["attractors"]):
            problems.append(f"cell ]{c['lo']['digits']}, {c['hi']['digits']}[ at r = {r}: attractors "
                            f"{sorted(c['attractors'])} in the atlas, {sorted(want)} by orbit_at")
        if c["island"] != (LOWER_END < Algebraic.rational(r)):
            problems.append(f"cell ]{c['lo']['digits']}, {c['hi']['digits']}[: island {c['island']} wrong")
    return problems


def check_orbits(doc: dict, rows=None) -> list[str]:
    """Each orbit of the rows (default: every r) classified again by identify (class, word,
    branch, and the collision it is certified from: inside the longer run for an orbit only
    that run proves), each attracting one re-decided by ``orbit_at`` and each island one by the island
    theorem at r; the counts recounted; the island's share and rotation number recomputed."""
    problems = []
    collisions = doc["parameters"]["collisions"]
    for row in doc["r"] if rows is None else rows:
        r, fq = Fraction(row["r"]), _fq(row["r"])
        if _counts(row["orbits"]) != row["counts"] or row["total"] != len(row["orbits"]):
            problems.append(f"r = {row['r']}: the counts are not those of its orbits")
        for o in row["orbits"]:
            x = _orbit_record(*classify_late(r, fq, o["theta0"], o["phi0"], collisions), o["theta0"], o["phi0"], fq)
            if o.get("rerun") != x["rerun"]:
                problems.append(f"r = {row['r']}, θ0 = {o['theta0']}, φ0 = {o['phi0']}: run again "
                                f"{o.get('rerun')} in the atlas, not what identify's class asks for")
            if o["class"] == UNRESOLVED and o.get("unresolved") != x["unresolved"]:
                problems.append(f"r = {row['r']}, θ0 = {o['theta0']}, φ0 = {o['phi0']}: unresolved "
                                f"{o.get('unresolved')} in the atlas, {x['unresolved']} by orbit_at")
            if (x["class"], x["word"], x["branch"], x["certified_from"]) != (
                    o["class"], o["word"], o["branch"], o.get("certified_from")):
                problems.append(f"r = {row['r']}, θ0 = {o['theta0']}, φ0 = {o['phi0']}: {o['class']} "
                                f"{o['word'] or ''} certified from {o.get('certified_from')} in the atlas, "
                                f"{x['class']} {x['word'] or ''} from {x['certified_from']} by identify")
            if o["class"] == ATTRACTING and name(o["word"], o["branch"]) not in _attracting_at(o["word"], fq):
                problems.append(f"r = {row['r']}: {name(o['word'], o['branch'])} is not attracting there (orbit_at)")
            if o["class"] == ISLAND and not ident.elliptic(fq):
                problems.append(f"r = {row['r']}: an island orbit where the island theorem does not hold")
        isl = row["island"]
        if (isl is not None) != (elliptic_polynomial(fq) < 0):
            problems.append(f"r = {row['r']}: the island is {'given' if isl else 'missing'}")
        elif isl is not None:
            lo, hi = island_theorem.island_fraction(fq, isl["depth"])
            if [str(lo), str(hi)] != isl["fraction"] or island_theorem.rotation_number(fq, 8) != isl["rotation_number"]:
                problems.append(f"r = {row['r']}: the island's share or rotation number differs from `certify island`")
    return problems


def check_seeds(doc: dict) -> list[str]:
    """Every seed the atlas was started from (:func:`seeds` again, when its parameters say
    ``seeds: known``; the words recorded as seeds otherwise), every word a certified orbit
    follows, and every member of a family it lists has its word record (an attractor dropped
    from the atlas is missed here)."""
    have = {w["word"] for w in doc["words"]}
    want = {w["word"]: w["source"] for w in doc["words"] if w.get("source", "met") != "met"}
    if doc["parameters"].get("seeds") == "known":
        want.update(seeds())
    for row in doc["r"]:
        for o in row["orbits"]:
            if o["class"] == ATTRACTING:
                want.setdefault(o["word"], f"met at r = {row['r']}")
    rules = {rule.name: rule for rule in FAMILIES}
    for f in doc["families"]:
        for k in rules[f["family"]].members() if f["family"] in rules else ():
            want.setdefault(rules[f["family"]].word(k), f"family {f['family']}, k = {k}")
    return [f"{compact(w)} ({src}): no word record in the atlas" for w, src in sorted(want.items()) if w not in have]


def check_families(doc: dict) -> list[str]:
    """The families recomputed from the atlas's attractors equal its own (each member's
    windows, its closing resonance decided again), and each has at least three certified
    members and its prediction certified."""
    problems = []
    fresh = families(doc["attractors"], doc["words"])
    if fresh != doc["families"]:
        mine = {f["family"]: f for f in doc["families"]}
        for f in fresh:
            if mine.get(f["family"]) != f:
                problems.append(f"family {f['family']}: differs from the attractors' windows and closings "
                                "decided again")
        for name_ in set(mine) - {f["family"] for f in fresh}:
            problems.append(f"family {name_}: no member in the atlas's words")
    for f in doc["families"]:
        if f["certified_members"] < 3 or not f["prediction_certified"]:
            problems.append(f"family {f['family']}: {f['certified_members']} certified members, prediction "
                            f"{'certified' if f['prediction_certified'] else 'not certified'}")
    return problems


def check_chaos(doc: dict, rows=None) -> list[str]:
    """Each row's horseshoe (default every r): a proved one proved again exactly from its printed
    boxes and covering relations (:func:`certify.numerics.horseshoe.prove`: the same ρ(T) bound
    and entropy bound); and the search and the unresolved orbits' visits and loops computed
    again (:func:`chaos_job`): a horseshoe the search proves that the atlas lacks, a visit or a
    rotation number that differs, each is a problem."""
    from certify.numerics import horseshoe
    problems = []
    for row in doc["r"] if rows is None else rows:
        hs, q = row["horseshoe"], Fraction(row["r"])
        if hs is not None and hs["certified"]:
            boxes = [horseshoe.Box.of_json(b) for b in hs["boxes"]]
            P = horseshoe.prove(q, boxes, [tuple(e) for e in hs["edges"]], hs["returns"])
            if not P.holds or P.entropy != hs["entropy_lower"] or str(P.beta) != hs["rho_lower"]:
                problems.append(f"r = {row['r']}: the horseshoe's boxes do not prove it (holds {P.holds}, entropy "
                                f"{P.entropy or '—'}, ρ(T) ≥ {P.beta}; the atlas says {hs['entropy_lower']}, "
                                f"{hs['rho_lower']})")
        fresh = chaos_job(row["r"], unresolved_of(row), doc["parameters"]["collisions"])
        if hs is None or fresh["horseshoe"]["certified"] != hs["certified"] or (
                hs["certified"] and fresh["horseshoe"]["entropy_lower"] != hs["entropy_lower"]):
            problems.append(f"r = {row['r']}: horseshoe {'not searched' if hs is None else hs['certified']} in the "
                            f"atlas, {fresh['horseshoe']['certified']} by certify chaos's search again")
        mine = {i: o for i, o in enumerate(row["orbits"])}
        for o in fresh["orbits"]:
            have = mine[o["index"]]
            if (have.get("visits_horseshoe"), have.get("curve")) != (o["visits_horseshoe"], o["curve"]):
                problems.append(f"r = {row['r']}, θ0 = {have['theta0']}, φ0 = {have['phi0']}: visits "
                                f"{have.get('visits_horseshoe')}, loop {have.get('curve')} in the atlas; "
                                f"{o['visits_horseshoe']}, {o['curve']} computed again")
    return problems


def check_summaries(doc: dict) -> list[str]:
    """What the document derives from its rows, derived again: each cell's 95% intervals
    (:func:`wilson` of its counts), the certified share above 3 − 2√2 and its interval, the
    unresolved orbits by kind, the horseshoes' counts and entropy range, the loops."""
    problems = []
    for c in doc["cells"]:
        if c["intervals"] != {k: wilson(n, c["orbits"]) for k, n in c["counts"].items()}:
            problems.append(f"cell ]{c['lo']['digits']}, {c['hi']['digits']}[: its 95% intervals differ from "
                            "Wilson's of its counts")
    s = doc["summary"]
    for key, fresh in (("certified_share_above", share_above(doc["r"])), ("unresolved_by_kind",
                                                                           unresolved_by_kind(doc["r"])),
                       ("horseshoes", horseshoes(doc["r"]))):
        if s[key] != fresh:
            problems.append(f"summary {key}: {s[key]} in the atlas, {fresh} from its rows")
    if doc["curves"] != curves_of(doc["r"]):
        problems.append("the loops' rotation numbers differ from the rows'")
    if doc["observed_words"] != observed_words(doc["r"]):
        problems.append("the observed words differ from the rows' (one entry per cyclic word: least_rotation)")
    return problems


def check_rotations(attractors: list[dict]) -> list[str]:
    """Each window's upper end's rotation record (:func:`end_rotation`: resonance, island end),
    decided again."""
    problems = []
    for a in attractors:
        for w in a["windows"]:
            if w["rotation"] != end_rotation(w["hi"]):
                problems.append(f"{a['name']}: the rotation number at the upper end ≈ {w['hi']['digits']} "
                                f"is {w['rotation']} in the atlas, {end_rotation(w['hi'])} decided again")
    return problems


def check_ends(doc: dict) -> list[str]:
    """Each window's upper end's rotation record (:func:`check_rotations`) and the interior
    ends' counts, decided again."""
    problems = check_rotations(doc["attractors"])
    if doc["summary"]["interior_ends"] != interior_ends(doc["attractors"]):
        problems.append(f"summary interior_ends: {doc['summary']['interior_ends']} in the atlas, "
                        f"{interior_ends(doc['attractors'])} decided again")
    return problems


def check_row(row: dict, collisions: int) -> list[str]:
    """:func:`check_orbits` and :func:`check_chaos` on one r row of an atlas of runs of
    ``collisions`` (a job of :func:`check_committed`)."""
    doc = {"parameters": {"collisions": collisions}, "r": [row]}
    return check_orbits(doc, [row]) + check_chaos(doc, [row])


def check_word(word: dict, attractors: list[dict], window_max: int) -> list[str]:
    """:func:`check_windows` on one word record and the atlas's attractors of that word (a job of
    :func:`check_committed`)."""
    return check_windows({"words": [word], "attractors": attractors}, window_max)


def check_counts(doc: dict) -> list[str]:
    """Each cell's sampled r and counts, summed again from the rows."""
    problems = []
    for c in doc["cells"]:
        rows_in = [row for row in doc["r"] if row["r"] in c["sampled"]]
        counts: dict[str, int] = {}
        for row in rows_in:
            for k, n in row["counts"].items():
                counts[k] = counts.get(k, 0) + n
        if counts != c["counts"] or [row["r"] for row in doc["r"] if _in_cell(Fraction(row["r"]), c)] != c["sampled"]:
            problems.append(f"cell ]{c['lo']['digits']}, {c['hi']['digits']}[: its sampled r or counts differ")
    return problems


def checked(doc: dict, sample: int = 1, window_max: int = WORD_MAX) -> tuple[list, list]:
    """The r rows and the analysed words (of at most ``window_max`` letters) that :func:`check_committed`
    derives again: every ``sample``-th of each."""
    words = [w for w in doc["words"] if w["outcome"] == "analysed" and w["length"] <= window_max]
    return doc["r"][::sample], words[::sample]


def check_committed(doc: dict, executor, sample: int = 1, window_max: int = WORD_MAX, progress=None) -> list[str]:
    """:func:`check_atlas` on a whole document through an executor: every ``sample``-th r row
    (:func:`check_row`) and every ``sample``-th analysed word of at most ``window_max`` letters
    (:func:`check_word`) as jobs, the rest (seeds, cells, families, summaries, ends, counts) here
    while they run.  With ``sample`` = 1 and ``window_max`` the atlas's word limit, everything a
    recomputation sees (about the time of the atlas from an empty state).  The problems in a fixed
    order (rows, then words, then the rest), whatever order the jobs end in."""
    collisions = doc["parameters"]["collisions"]
    rows, words = checked(doc, sample, window_max)
    futures = {executor.submit(check_row, row, collisions): ("r", i) for i, row in enumerate(rows)}
    futures.update({executor.submit(check_word, w, [a for a in doc["attractors"] if a["word"] == w["word"]],
                                    window_max): ("word", i) for i, w in enumerate(words)})
    rest = (check_seeds(doc) + check_cells(doc) + check_families(doc) + check_summaries(doc) + check_ends(doc)
            + check_counts(doc))
    found: dict = {}
    pending = set(futures)
    while pending:
        done, pending = wait_first(pending, timeout=1.0)
        for f in sorted(done, key=futures.get):         # a set: its order is not the jobs' order
            found[futures[f]] = f.result()
            if progress is not None:
                progress(len(found), len(futures), f"{futures[f][0]} {futures[f][1] + 1}")
    return [p for key in sorted(found) for p in found[key]] + rest


def check_atlas(doc: dict, window_max: int = 24, rows=None) -> list[str]:
    """Every way the document can be wrong that a recomputation sees (empty: it checks):
    the seeds and words (:func:`check_seeds`), the windows (:func:`check_windows`, words up
    to ``window_max`` letters), the cells (:func:`check_cells`), the families
    (:func:`check_families`), the orbits and the island (:func:`check_orbits` on ``rows``,
    default every r), the horseshoes, visits and loops (:func:`check_chaos` on ``rows``), the
    intervals and summaries (:func:`check_summaries`), the window ends' rotation numbers
    (:func:`check_ends`), the cells' counts."""
    return (check_seeds(doc) + check_windows(doc, window_max) + check_cells(doc) + check_families(doc)
            + check_orbits(doc, rows) + check_chaos(doc, rows) + check_summaries(doc) + check_ends(doc)
            + check_counts(doc))
