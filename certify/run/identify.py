"""``certify identify``: the periodic word each simulated orbit settles on, certified.

For each r and initial datum (θ0, φ0) (the paper's grid by default) the float64 engine
(:func:`certify.numerics.simulate`, with the words) runs the reduction map; the tail of
the collision word is read for its shortest period (:func:`period_of`: the last half
of the word, at least 4 periods, is periodic), and that block, in the normal form of
``certify pattern``, is analysed by ``certify orbit``
(:func:`certify.patterns.reduction_orbits.analyse`, once per word over ]0, 1[): the
attracting window that contains r, with its branch and in-plane pair, or why there
is none (the orbit at r is a saddle or repelling, or the word is not realised there).

What is certified and what is not: the window and its type are exact; the word is
the one the float64 simulation shows (a shadowing orbit past its certified horizon,
docs/engines.md), so "this orbit settles on w" is the observation and "w has an
attracting periodic orbit of the reduction at r" the certificate.  r is the exact
rational typed (0.3 is 3/10); the simulation runs at its nearest double.
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from fractions import Fraction
from functools import cache

import flint
import numpy as np

from certify.algebra.algebraic import Algebraic
from certify.algebra.branches import BRANCH_NAMES
from certify.errors import UsageError
from certify.numerics import grid, iterate
from certify.patterns import compact, read, show_word
from certify.patterns.pattern import end_data
from certify.patterns.reduction_orbits import OrbitResult, analyse

MAX_PERIOD = 120
SCHEMA = "certify-identify"


def period_of(word: str, max_period: int = MAX_PERIOD) -> str | None:
    """The shortest block B (|B| ≤ max_period) such that the last half of ``word`` (at
    least 4|B| letters) is periodic with period |B|; B = the last |B| letters.  None
    when no such block exists (a transient, or no short periodic orbit)."""
    tail = len(word) // 2
    for p in range(2, max_period + 1):
        if 4 * p > tail:
            break
        if all(word[i] == word[i + p] for i in range(len(word) - tail, len(word) - p)):
            return word[-p:]
    return None


@cache
def orbit_analysis(normal: str) -> OrbitResult:
    """``certify orbit`` on a normal form over ]0, 1[, once per word."""
    return analyse(normal)


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


@dataclass
class Identified:
    r: str
    theta0: float
    phi0: float
    collisions: int
    breaks: int
    word: str | None                 # the normal form, or None
    compact: str | None
    window: dict | None
    why: str

    def to_json(self) -> dict:
        return {"r": self.r, "theta0": self.theta0, "phi0": self.phi0, "collisions": self.collisions,
                "break": self.breaks, "word": self.word, "compact": self.compact, "window": self.window,
                "why": self.why}

    def line(self) -> str:
        head = f"r = {self.r}, θ0 = {self.theta0:.6f}, φ0 = {self.phi0:.6f}: "
        if self.word is None:
            return head + self.why
        return head + f"settles on {self.word} (= {self.compact}); {self.why}"


def identify(rs: list[Fraction], theta0=None, phi0=None, orbits: int = 8, collisions: int = 4000) -> list[Identified]:
    """Simulate, read the periodic word of each orbit, certify it (module docstring)."""
    if theta0 is None:
        theta0, phi0 = grid(orbits)
    sims = iterate(np.array([float(x) for x in rs]), theta0, phi0, collisions=collisions, keep=0, words=True)
    out = []
    for a, r in enumerate(rs):
        ra = Algebraic.rational(flint.fmpq(r.numerator, r.denominator))
        for b in range(len(theta0)):
            w, code, done = str(sims.word[a, b]), int(sims.breaks[a, b]), int(sims.collisions[a, b])
            args = (str(r), float(theta0[b]), float(phi0[b]), done, code)
            block = period_of(w) if code == 0 else None
            if block is None:
                why = (f"the orbit stopped with break {code} after {done} collisions" if code else
                       f"no periodic word within {done} collisions (a transient, or not a short periodic orbit)")
                out.append(Identified(*args, None, None, None, why))
                continue
            try:
                normal = read(block)[0]
            except UsageError as exc:
                out.append(Identified(*args, show_word(block), block, None, f"not a periodic word to analyse: {exc}"))
                continue
            try:
                res = orbit_analysis(normal)
            except UsageError as exc:
                out.append(Identified(*args, show_word(normal), compact(normal), None, str(exc)))
                continue
            window, why = window_at(res, ra)
            out.append(Identified(*args, show_word(normal), compact(normal), window, why))
    return out


def json_text(found: list[Identified]) -> str:
    return json.dumps({"schema": SCHEMA, "version": 1, "orbits": [x.to_json() for x in found]},
                      ensure_ascii=False, indent=2, sort_keys=True)

