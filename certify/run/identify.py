"""``certify identify``: each orbit classified, and certified for ever where a proof stands.

For each r (an exact rational: 0.3 is 3/10) and initial datum (θ0, φ0) at the contact b
(the tool's grid of 8 initial data by default, :func:`certify.numerics.grid`; the doubles
θ0, φ0 are read as exact dyadic rationals), one class:

* **island**: the state at b after some collision k, computed rigorously from the datum
  (arb balls from the first collision, :func:`certify.numerics.engines.ball_states`),
  lies in the island U_r = {Q < c_max} of :mod:`certify.dynamics.island`, the whole
  ball (:func:`~certify.dynamics.island.inside`, the membership test the certified points of
  Section 5's figures share; r in ]3−2√2, 1[, decided exactly): by the island theorem (``certify island``) the orbit
  stays in U_r for ever and is quasi-periodic.  No word is needed.
* **attracting periodic**: the float64 run (an observation) settles on a periodic word w;
  :func:`~certify.patterns.reduction_orbits.orbit_at` decides exactly that w has an
  attracting periodic orbit at r; :func:`~certify.numerics.trapping.attempt` certifies a
  trapping ellipse U at the contact c_0 = w[-1] (the rotation of w the orbit follows,
  ending with b); the rigorous orbit's state at c_0 after collision k lies in U
  (:meth:`~certify.numerics.trapping.Trap.ball_sign`).  Then the orbit follows w for
  ever and converges to the periodic orbit (the trap's theorem): the word is certified.
* **unresolved**: neither, said with what was observed.

Each proof is checked again before it is reported (:func:`verify`), by a second route to
the state: the reduction's own ball steps (:func:`certify.dynamics.reduction.ball_run`,
precision raised by powers of 2 until every sign is decided; up to :data:`VERIFY_MAX` collisions, beyond
which the first route's state is used), the island's membership decided again on that state,
the trapping ellipse re-certified from its exact data (:func:`trapping.check`) and the
word re-decided by ``orbit_at``.  A word is "certified" only in the second class;
otherwise it is what the float64 run shows past its certified horizon: "observed".

The period search: the shortest period p of the last half of the run (the prefix
function, linear time), at most a quarter of that half (4 periods at least): no cap
(r = 0.173 settles on a word of 122 letters).  The attracting window of ``certify orbit``
over ]0, 1[ (:func:`window_at`) is added with ``windows=True`` for words of at most
:data:`WINDOW_MAX` letters (cached; not needed by the classification).
"""
from __future__ import annotations

import json
import sys
from dataclasses import dataclass, field
from fractions import Fraction
from functools import cache

import flint
import numpy as np

from certify import caches
from certify.algebra.algebraic import Algebraic
from certify.algebra.balls import precision
from certify.algebra.branches import BRANCH_NAMES
from certify.dynamics import island
from certify.dynamics.model import INDEX, LETTERS
from certify.dynamics.reduction import ball_run
from certify.errors import UsageError
from certify.numerics import engines, grid, rules, trapping
from certify.numerics.leaps import period_of
from certify.patterns import compact, island_theorem, show_word
from certify.patterns.pattern import end_data
from certify.patterns.periodic import MAX_LENGTH
from certify.patterns.reduction_orbits import OrbitResult, analyse, orbit_at, read_plain

SCHEMA = "certify-identify"
VERSION = 2
ISLAND, ATTRACTING, UNRESOLVED = "island", "attracting periodic", "unresolved"
CLASSES = (ISLAND, ATTRACTING, UNRESOLVED)
COLLISIONS = 100_000       # default length of the float64 run (and of the rigorous scan)
WINDOW_MAX = 24            # the window over ]0, 1[ only for words up to this length
MAX_ANALYSED = 1000        # longer observed periods are never analysed (orbit_at, the trap); see classify's word_max
SHOWN = 200                # an island orbit's observed quasi-period is shown up to this length
VERIFY_START = 128         # bits of the second route's balls, raised by powers of 2 up to VERIFY_CAP
VERIFY_CAP = 1 << 16
VERIFY_MAX = 20_000        # the second route re-runs at most this many collisions (beyond: the first route)
REFUSALS = 3               # a kind of proof refused this often by the second route is dropped
GRID = "the tool's grid of 8 initial data"


def settled_from(word: str, p: int) -> int:
    """The first collision from which ``word`` is p-periodic to its end (observed): one past the
    last i with word[i] ≠ word[i + p] (compared as byte arrays)."""
    w = np.frombuffer(word.encode("ascii"), dtype=np.uint8)
    differ = np.flatnonzero(w[:-p] != w[p:]) if p < len(w) else []
    return int(differ[-1]) + 1 if len(differ) else 0


def followed(block: str, normal: str) -> str:
    """The rotation of the observed block the orbit follows, ending with b (the trap's
    contact c_0): the normal form when it is a rotation of the block, else the least
    rotation ending with b (the block is then a mirror image of the normal form)."""
    rotations = [block[k:] + block[:k] for k in range(len(block))]
    if normal in rotations:
        return normal
    return min(x for x in rotations if x[-1] == "b")


@cache
def orbit_analysis(normal: str) -> OrbitResult:
    """``certify orbit`` on a normal form over ]0, 1[, once per word."""
    return analyse(normal)


def _orbit_at(normal: str, r) -> list:
    """``orbit_at`` reading the word up to :data:`MAX_ANALYSED` letters (:func:`read_plain`): the
    words reaching it were admitted by :func:`classify`'s ``word_max``."""
    return orbit_at(normal, r, MAX_ANALYSED)


orbits_at = caches.for_a_run(_orbit_at)
"""``orbit_at`` once per (normal form, r) in a run (Section 5's explanations decide a committed
word, then verify re-decides it: one computation)."""


@cache
def decided(normal: str, r: flint.fmpq):
    """``orbit_at``: the periodic orbit of the word at r, decided exactly (the feasible
    branch, else None), once per (word, r)."""
    return next((x for x in orbits_at(normal, r) if x.feasible), None)


@cache
def trap_of(word: str, r: flint.fmpq) -> trapping.Trap | str:
    """The certified trapping ellipse of the rotation ``word`` at r, or the reason why none."""
    return trapping.attempt(word, r)


@caches.for_a_run
def recheck(word: str, r: flint.fmpq, centre: tuple, frame: tuple, radius: flint.fmpq, pair: str):
    """The trapping ellipse (centre, frame, radius) of the rotation ``word`` at r re-certified
    from its exact data (:func:`trapping.check`, the second route), once per run: every orbit
    of the grid that follows the word at r asks for the same."""
    return trapping.check(word, r, centre, frame, radius, pair)


def window_at(res: OrbitResult, r: Algebraic) -> tuple[dict | None, str]:
    """(the attracting window containing r, or None; a sentence saying which, or why not)."""
    for a in res.attracting():
        k = BRANCH_NAMES.index(a["branch"])
        for R in res.regions["attracting"]:
            if R.branch != k:
                continue
            for lo, hi in R.merged()[0]:
                if lo < r < hi and end_data(lo) == a["lo"]:
                    return a, (f"attracting on the {a['branch']} branch for r in ]{_end(a['lo'])}, {_end(a['hi'])}[ "
                               f"({a['pair']} in-plane pair" +
                               (": not a collapse)" if a["pair"] == "complex" else ")"))
    for stage, says in (("saddle", "a saddle"), ("repelling", "repelling")):
        for R in res.regions[stage]:
            if any(lo < r < hi for lo, hi in R.merged()[0]):
                branch = BRANCH_NAMES[R.branch]
                return None, f"not attracting at r: the periodic orbit is {says} there ({branch} branch)"
    if any(lo < r < hi for R in res.regions["feasible"] for lo, hi in R.merged()[0]):
        return None, "not attracting at r: a multiplier of modulus 1 (a point of the boundary)"
    if any(lo < r < hi for R in res.regions["exists"] for lo, hi in R.merged()[0]):
        return None, "no periodic orbit with this word at r: the eigen-normal n* does not realise the word there"
    return None, "no periodic orbit with this word at r: no oriented eigen-normal inside the face b"


def _end(e: dict) -> str:
    return e["exact"] if e["exact"] is not None else "≈" + e["digits"]


@cache
def elliptic(r: flint.fmpq) -> bool:
    """The island exists at r and every orbit in it is quasi-periodic: r in ]3−2√2, 1[
    (r² − 6r + 1 < 0, exactly) and the island theorem at r proved step by step
    (:func:`certify.patterns.island_theorem.theorem`, ``certify island --r``)."""
    return bool(r < 1 and island.elliptic_polynomial(r) < 0 and island_theorem.theorem(r).quasi_periodic)


# ------------------------------------------------------------------ the second route
def _state(r: flint.fmpq, theta0: float, phi0: float, k: int, first=None) -> tuple[str, tuple, int] | str:
    """The state after collision k from the datum by :func:`ball_run` (contact, oriented
    ball normal, bits), the precision raised from VERIFY_START along the rungs
    VERIFY_START·2^m (:func:`next_precision`) until all k collisions are decided; a reason
    when VERIFY_CAP does not suffice.  Beyond VERIFY_MAX collisions (the second route's
    balls wrap, about a bit per collision: minutes) the state is the first route's
    (:func:`certify.numerics.engines.ball_states`, exact products, seconds): ``first``, the
    state (contact, normal, bits) the caller's scan has from ball_states at k, when given
    (the same state: ball_states's last state is its k-th, tests/numerics/test_ball_states.py)."""
    if k > VERIFY_MAX and first is not None:
        return first
    if k > VERIFY_MAX:
        for done, j, n, bits in engines.ball_states(r, theta0, phi0, k, every=False):   # the last state
            if done == k:
                return LETTERS[j], n, bits
        return f"the certified orbit stopped undecided before collision {k}"
    prec = VERIFY_START
    while True:
        with precision(prec):
            n0 = rules.initial_normal(flint.arb(theta0), flint.arb(phi0), "b", flint.arb.cos, flint.arb.sin)
        letters, last, n = ball_run("b", n0, r, k, prec)
        if len(letters) == k:
            return last, n, prec
        if prec >= VERIFY_CAP:
            return f"the second route lost precision at collision {len(letters) + 1} ({prec} bits)"
        prec = next_precision(prec, len(letters), k)


def next_precision(prec: int, reached: int, k: int) -> int:
    """The next rung of the ladder VERIFY_START·2^m after a run at ``prec`` bits decided
    ``reached`` < k collisions: doubled at least once, and as often as the run's rate
    (collisions per bit, taken 1/16 higher: the balls lose about a bit per collision, a few
    per cent less at higher precision) says is needed to reach k, up to VERIFY_CAP; only
    doubled when the run stopped early, before prec/2 collisions (no rate to go by).
    Skipping rungs that would fail changes nothing (the rung that succeeds is the same); a
    rung too low fails and the ladder goes on from there; a rung too high decides the same
    signs with narrower balls."""
    rung = 2 * prec
    while reached * 2 >= prec and rung < VERIFY_CAP and 17 * rung * reached < 16 * k * prec:
        rung *= 2
    return min(rung, VERIFY_CAP)


def verify(r, theta0: float, phi0: float, cls: str, k: int, word: str | None = None, first=None) -> str | None:
    """None when the claim "the orbit from (θ0, φ0) at r is of class ``cls`` from collision
    k" (``word``: the rotation followed, for the attracting class) is proved by the second
    route of the module docstring; otherwise the reason it is refused.  ``first``: the first
    route's state at k (contact, normal, bits), used beyond VERIFY_MAX (:func:`_state`)."""
    r = flint.fmpq(r.numerator, r.denominator) if isinstance(r, Fraction) else rules.exact_r(r)
    if cls not in (ISLAND, ATTRACTING):
        return f"{cls!r} is not a class with a proof"
    if cls == ISLAND and not elliptic(r):
        return f"no island at r = {r}: r² − 6r + 1 ≥ 0 (A(r) not elliptic)"
    if cls == ATTRACTING:
        if not word:
            return "no word"
        o = decided(read_plain(word, MAX_ANALYSED)[0], r)
        if o is None or o.kind != "attracting":
            return f"{word} has no attracting periodic orbit at r = {r} (orbit_at)"
        U = trap_of(word, r)
        if isinstance(U, str):
            return f"no certified trapping ellipse for {word} at r = {r}: {U}"
        U = recheck(word, r, U.centre, U.frame, U.radius, U.pair)
        if isinstance(U, str):
            return f"the trapping ellipse of {word} is not re-certified: {U}"
    state = _state(r, theta0, phi0, k, first)
    if isinstance(state, str):
        return state
    last, n, prec = state
    with precision(prec):
        if cls == ISLAND:
            if last != "b":
                return f"the state after collision {k} is at contact {last}, not b"
            inside = island.inside(n, r)
            return None if inside else f"the state at b after collision {k} is not proved inside the island (Q < c_max)"
        if last != word[-1]:
            return f"the state after collision {k} is at contact {last}, not {word[-1]} (the start of {word})"
        inside = U.ball_sign(n) > 0
        return None if inside else f"the state after collision {k} is not proved inside the trapping ellipse"


# ------------------------------------------------------------------ the classification
@dataclass
class Identified:
    """One orbit's class (module docstring) and what was observed."""

    r: str
    theta0: float
    phi0: float
    collisions: int                  # of the float64 run
    breaks: int                      # its break code (0: it ran to the end)
    cls: str = UNRESOLVED
    certified_from: int | None = None
    word: str | None = None          # the normal form of the observed (or certified) word
    compact: str | None = None
    rotation: str | None = None      # the rotation followed (certified), ending with the trap's contact
    settled: int | None = None       # observed: the float64 word periodic from this collision
    why: str = ""
    trap: dict | None = None
    window: dict | None = None
    notes: list = field(default_factory=list)
    leaps: list = field(default_factory=list)    # the ball states' proved leaps (:attr:`Scan.leaps`)

    @property
    def word_status(self) -> str | None:
        if self.word is None:
            return None
        return "certified" if self.cls == ATTRACTING else "observed"

    def to_json(self) -> dict:
        return {"r": self.r, "theta0": self.theta0, "phi0": self.phi0, "collisions": self.collisions,
                "break": self.breaks, "class": self.cls, "certified_from": self.certified_from,
                "word": self.word, "compact": self.compact, "word_status": self.word_status,
                "rotation": self.rotation, "settled_from": self.settled, "trap": self.trap,
                "window": self.window, "why": self.why}

    def line(self) -> str:
        return f"r = {self.r}, θ0 = {self.theta0:.6f}, φ0 = {self.phi0:.6f}: {self.cls}: {self.why}"

    def _repr_markdown_(self) -> str:
        """A notebook shows the orbit's class in bold, then why (certified or observed)."""
        return f"r = {self.r}, θ0 = {self.theta0:.6f}, φ0 = {self.phi0:.6f}: **{self.cls}**: {self.why}"


def _observed(x: Identified, word: str, block: str | None) -> str:
    if x.breaks:
        return f"the float64 run stopped with break {x.breaks} after {x.collisions} collisions"
    if block is not None and x.word is None:
        return (f"the float64 run repeats a block of {len(block)} letters from about collision {x.settled} to its "
                f"end ({x.collisions}; observed, not certified)")
    if block is None:
        return (f"no period within {x.collisions} collisions (the last half of the float64 run has no period "
                f"≤ {x.collisions // 8})")
    return (f"the float64 run repeats {_named(x)} from about collision {x.settled} to its end "
            f"({x.collisions} collisions; not certified)")


def _named(x: Identified) -> str:
    return x.word if x.compact in (None, x.word) else f"{x.word} (= {x.compact})"


class Scan:
    """One datum's rigorous orbit at r, kept between the runs of :func:`classify` (``scan``)
    that ask it for more collisions (the atlas's longer runs of an unresolved orbit).

    :func:`engines.ball_states` gives the same states whatever its number of collisions (that
    number only ends it), and every check :func:`_scan` makes on a state is decided by the
    state, r and the trapping ellipse U (the island's, U's, the second route's :func:`verify`).
    So a scan of states 0..N with the same U (the same ``key``) as the last one, which checked
    states 0..``done`` ≤ N, goes on from state ``done`` + 1 with the tries and refusals left
    by it: the same answer as a scan from the datum, without computing states 0..``done`` again.
    A scan that ended (a class proved at k, every kind of proof refused, or the balls stopped
    undecided at their precision cap) ends there again.  Another key starts from the datum.

    The ball states leap over the periods of a repelling block the orbit is proved to follow
    (:mod:`certify.numerics.leaps`, up to the scan's budget): no state inside such a leap can be
    in the island (its letters are not the island's acb/cab) or in a trapping ellipse (the orbit
    would follow the ellipse's word for ever, not leave the block), so no state a check could
    accept is skipped.  The states after a leap are other balls than a scan of every state
    computes (one power instead of J·L products), so the first one the ball test accepts may come
    some collisions earlier or later (14 orbits of the committed atlas, by at most 474 collisions;
    the class never changed); ``leaps`` lists them."""

    def __init__(self):
        self.key: tuple | None = None
        self.done = -1                   # the last state checked
        self.ended: tuple | None = None  # the scan's answer once it ended before its budget
        self.tries: dict = {}
        self.notes: list = []            # the refusals so far, in order
        self.stop = {"code": 0, "bits": 0}
        self.leap: dict = {}
        self.states = iter(())
        self.floats = (0.0, 0.0)        # r and c_max(r) in float64, for the sieve of _check

    def start(self, key: tuple, r, theta0, phi0, budget: int, tries: dict) -> None:
        """Go on from the last scan when it had this key and checked no state beyond ``budget``;
        else a new scan from the datum (its ball states not bounded here: :func:`_scan` stops)."""
        if key == self.key and self.done <= budget:
            self.leap["until"] = budget
            return
        self.key, self.done, self.ended, self.tries, self.notes = key, -1, None, dict(tries), []
        self.stop = {"code": 0, "bits": 0}
        self.leap = {"until": budget}
        self.states = iter(engines.ball_states(r, theta0, phi0, sys.maxsize, stop=self.stop, leap=self.leap))
        self.floats = (float(r), float(island.c_max(r)))

    @property
    def leaps(self) -> list:
        """The leaps of the ball states so far: (collision, periods, letters, s − 1)."""
        return self.leap.setdefault("leaps", [])


def _scan(x: Identified, r, theta0, phi0, U, rotation, budget, scan: Scan | None = None):
    """The rigorous orbit, state by state up to collision ``budget``: the first (class, k)
    whose proof the second route accepts; refusals recorded in x.notes.  Returns (class, k)
    or (None, stop note).  ``scan``: the datum's :class:`Scan`, gone on from where it stopped."""
    tries = {ISLAND: REFUSALS if elliptic(r) else 0, ATTRACTING: REFUSALS if U is not None else 0}
    if not any(tries.values()):
        return None, ""
    s = Scan() if scan is None else scan
    s.start((r, theta0, phi0, rotation if U is not None else None), r, theta0, phi0, budget, tries)
    x.notes.extend(s.notes)
    b, c0 = INDEX["b"], INDEX[rotation[-1]] if rotation else -1
    x.leaps = s.leaps
    while s.ended is None and s.done < budget:
        state = next(s.states, None)
        if state is None:            # the balls stopped undecided (stop["code"] ≠ 0)
            s.ended = (None, f"the certified orbit (balls) stopped undecided at collision {s.done + 1} "
                             f"({s.stop['bits']} bits)")
            break
        k, j, n, bits = state
        s.done = k
        if j == b or j == c0:        # else nothing to check
            s.ended = _check(x, s, r, theta0, phi0, U, rotation, c0, k, j, n, bits)
    if s.ended is not None:
        return s.ended
    where = " or ".join(w for w, k in (("the island", ISLAND), ("the trapping ellipse", ATTRACTING)) if s.tries[k])
    return None, f"the certified orbit (balls) was not proved inside {where} within {s.done} collisions"


SIEVE = True               # _check skips the tests that float64 shows to fail (benchmarks turn it off)


def surely_outside_island(n, r: float, c: float) -> bool:
    """A sieve before :func:`certify.dynamics.island.inside` (which proves): True only when
    ``inside(n, r)`` is certainly False.  At the midpoint of the ratio balls a = n_x/n_z and
    b = n_y/n_z (float64, r and c = c_max(r) rounded), the chart point u = (1 + a)/(1 − a),
    v = 2b/(1 − a) is that of the balls' midpoint normal, a point of the chart balls ``inside``
    evaluates; when Q(u, v) exceeds c by :data:`~certify.numerics.trapping.SIEVE_MARGIN` times the
    scale of Q's terms (far above float64's rounding, |1 − a| > 10⁻⁶ kept away from the chart's
    pole), c − Q < 0 at a point of those balls, so c − Q > 0 is not proved for the whole ball.
    False whenever undecided."""
    a, b = float(n[0] / n[2]), float(n[1] / n[2])
    if not abs(1 - a) > 1e-6:                       # also False for nan
        return False
    try:
        u, v = island.chart((a, b, 1.0))             # the normal (a, b, 1): n_z − n_x = 1 − a
    except ValueError:                              # not in the face b at its midpoint: inside decides
        return False
    terms = island.quadratic_form(abs(u), -abs(v), r)            # 2u² + (1 + r)|uv| + r v²
    return island.quadratic_form(u, v, r) - c > trapping.SIEVE_MARGIN * (terms + c)


def _check(x: Identified, s: Scan, r, theta0, phi0, U, rotation, c0, k, j, n, bits) -> tuple | None:
    """:func:`_scan`'s checks of the state after collision k: (class, k) when a proof is accepted,
    (None, "") when every kind of proof has been refused, else None (the scan goes on).  A test
    that the float64 sieve shows to fail is skipped (:func:`surely_outside_island`,
    :meth:`~certify.numerics.trapping.Trap.surely_outside`): the same answers, sooner."""
    found = []
    if (s.tries[ISLAND] and j == INDEX["b"]) or (s.tries[ATTRACTING] and j == c0):
        with precision(bits):
            if s.tries[ISLAND] and j == INDEX["b"] and not (SIEVE and surely_outside_island(n, *s.floats)) \
                    and island.inside(n, r):
                found.append(ISLAND)
            if s.tries[ATTRACTING] and j == c0 and not (SIEVE and U.surely_outside(n)) and U.ball_sign(n) == 1:
                found.append(ATTRACTING)
    for cls in found:
        why = verify(r, theta0, phi0, cls, k, rotation, (LETTERS[j], n, bits))
        if why is None:
            return cls, k
        s.tries[cls] -= 1
        note = f"{cls} at collision {k} refused by the second route: {why}"
        s.notes.append(note)
        x.notes.append(note)
    return (None, "") if not any(s.tries.values()) else None


def classify(r: Fraction, theta0: float, phi0: float, collisions: int = COLLISIONS,
             windows: bool = False, word_max: int = MAX_LENGTH, scan: Scan | None = None) -> Identified:
    """One orbit's class (module docstring).  An observed block of more than ``word_max``
    letters (default: the parser's :data:`~certify.patterns.periodic.MAX_LENGTH`, at most
    :data:`MAX_ANALYSED`) is not analysed; a longer one than the parser reads is read as plain
    letters (:func:`read_plain`: the same normal form), and decided as any other.  ``scan``: the
    datum's rigorous orbit kept from an earlier run at r (:class:`Scan`; the same class)."""
    if not 0 < word_max <= MAX_ANALYSED:
        raise UsageError(f"word_max must be in [1, {MAX_ANALYSED}], got {word_max}")
    q = flint.fmpq(r.numerator, r.denominator)
    res = engines.float64_orbit(q, theta0, phi0, collisions, word=True)
    x = Identified(str(r), float(theta0), float(phi0), res.collisions, res.code)
    block = period_of(res.word) if res.code == 0 else None
    U, rotation, o, why_not = None, None, None, ""
    if block is not None:
        x.settled = settled_from(res.word, len(block))
    if block is not None and len(block) > word_max:
        why_not = f"a block of {len(block)} letters (longer than {word_max}: not analysed)"
    elif block is not None:
        try:
            normal = read_plain(block, word_max)[0]
        except UsageError as exc:
            normal, why_not = None, f"not a word of the reduction ({exc})"
            x.word = x.compact = block
        if normal is not None:
            x.word, x.compact = show_word(normal), compact(normal)
            o = decided(normal, q)
            if o is None:
                why_not = "no periodic orbit with this word at r (decided exactly, orbit_at)"
            elif o.kind != "attracting":
                kind = {"saddle": "a saddle", "repelling": "repelling"}.get(o.kind, "of multiplier modulus 1")
                why_not = (f"its periodic orbit at r is {kind} (decided exactly, orbit_at): proved, the word has no "
                           f"attracting periodic orbit at r; observed, the run repeats it without converging to that "
                           f"orbit (orbits near a periodic orbit share its word)")
            else:
                rotation = followed(block, normal)
                U = trap_of(rotation, q)
                if isinstance(U, str):
                    why_not, U = f"no certified trapping ellipse: {U}", None
            if windows and len(normal) <= WINDOW_MAX:
                x.window = window_at(orbit_analysis(normal), Algebraic.rational(q))[0]
    observed = _observed(x, res.word, block)
    cls, k = _scan(x, q, theta0, phi0, U, rotation, collisions, scan)
    if cls == ISLAND:
        x.cls, x.certified_from = ISLAND, k
        x.why = (f"quasi-periodic for ever, proved from collision {k}: the state at b after collision {k} "
                 "(arb balls from the datum) lies in the island U_r = {Q < c_max} (the island theorem, "
                 "`certify island`)")
        if x.word is not None and len(x.word) > SHOWN:
            x.word = x.compact = None                # a quasi-period of the island: not worth printing
        if x.word is not None:
            x.why += (f"; observed in float64: repeats {_named(x)} for {res.collisions - x.settled} collisions "
                      "(a coding of the island's rotation, not a periodic orbit)")
        x.rotation = None
    elif cls == ATTRACTING:
        x.cls, x.certified_from, x.rotation = ATTRACTING, k, rotation
        x.trap = {"contact": rotation[-1], "radius": str(U.radius), "contraction": trapping._dec(U.contraction)}
        pair = f"{o.pair} in-plane pair" + (": not a collapse" if o.pair == "complex" else "")
        x.why = (f"certified: follows {_named(x)} for ever from collision {k}, and converges to its "
                 f"attracting periodic orbit ({o.branch_name} branch, {pair}; decided exactly at r): its state at "
                 f"{rotation[-1]} after collision {k} (arb balls from the datum) lies in the certified trapping "
                 f"ellipse U (contraction κ ≤ {x.trap['contraction']} per period)")
    else:
        x.rotation = None
        reasons = [why for why in (why_not, k) if why]
        x.why = "observed: " + observed + ("; " + "; ".join(reasons) if reasons else "")
    if x.leaps and x.cls != UNRESOLVED:
        x.why += "; " + leaps_phrase(x.leaps)
    if x.notes and x.cls == UNRESOLVED:
        x.why += "; " + "; ".join(x.notes)
    return x


def leaps_phrase(leaps: list) -> str:
    """What the ball states' leaps proved (:mod:`certify.numerics.leaps`), in words."""
    parts = [f"{periods} periods of {letters} letters from collision {k} (multipliers ≥ 1 + {rate})"
             for k, periods, letters, rate in leaps]
    return ("the ball states leapt over " + ", ".join(parts) + ": the orbit proved to follow a repelling "
            "periodic block there (its period matrix's eigen-decomposition, certify.numerics.leaps)")


def identify(rs: list[Fraction], theta0=None, phi0=None, orbits: int = 8, collisions: int = COLLISIONS,
             windows: bool = False, progress=None) -> list[Identified]:
    """Classify every orbit (module docstring); ``progress(k, n, label)`` as they finish."""
    if theta0 is None:
        theta0, phi0 = grid(orbits)
    out, total = [], len(rs) * len(theta0)
    for r in rs:
        for b in range(len(theta0)):
            out.append(classify(r, float(theta0[b]), float(phi0[b]), collisions, windows))
            if progress is not None:
                progress(len(out), total, f"r = {r}")
    return out


def json_text(found: list[Identified]) -> str:
    return json.dumps({"schema": SCHEMA, "version": VERSION, "orbits": [x.to_json() for x in found]},
                      ensure_ascii=False, indent=2, sort_keys=True)

