"""``certify orbit WORD`` for five particles: the periodic orbits of the five-particle reduction (issue 39).

The reduction's state after a collision is the face i (the gap p_i just closed) and the oriented plane
ω = p ∧ q (docs/particles.md, :mod:`certify.numerics.five_reduction`, certificate B1): the state lies in
its face iff −ω_ik > 0 for the three k ≠ i; the next face is the j with ω_jk > 0 for the two other
k ∉ {i, j}; the new plane is Λ²K_j ω, a positive multiple kept.

**The periodic orbits of a word.**  Let w = c_1 … c_n be the normal form, Y the gap of its last letter,
M = M_w.  A periodic orbit (Y, ω) with word w has Λ²M ω = κ ω with κ > 0 (the plane returns with its
orientation): ω is a κ-eigenvector of Λ²M, κ a real root of cp(Λ²M) (:mod:`.five`: the κ-eigenplane
Π, normalised, of a simple factor, reduced modulo it; ω = s Π for a sign s).  Conversely, for a simple
root κ > 0 with eigenplane Π, (Y, sΠ) is a periodic orbit with word w, every face decided strictly, iff

* *exists*: κ > 0 and sΠ lies in the face Y: −(sΠ)_{Yk} = s p̂_k > 0 for the three k ≠ Y, where
  p̂ = ι_Y Π (:func:`.five.contract`); so the three p̂_k have one sign, and s = sign p̂_{j₀};
* *feasible*: at each collision k the tournament picks c_k: with P_0 = Π, P_k = Λ²K_{c_k} P_{k−1}
  (:func:`.five.wedge_collide`), s·(P_{k−1})_{c_k m} > 0 for the two m ∉ {c_{k−1}, c_k} (c_0 = Y).

Proof.  The map keeps positive multiples (B1), so the state after k collisions is (c_k, s c P_k),
c > 0, as long as each next face is decided; the face conditions after the first are implied (a
state in its face whose next face is decided strictly lands inside the next face:
:mod:`certify.numerics.five_reduction`), and after n collisions P_n = Λ²M Π = κΠ, a positive multiple
of Π as κ > 0: the orbit closes.

**Attracting.**  Near ω every decided sign keeps its value, so the return map is the projective action
of Λ²M restricted to the Grassmannian Gr⁺(2, 4) (a quadric of P(Λ²R⁴)).  With λ, μ the eigenvalues of
M on Π (λμ = κ) and ν₁, ν₂ the other two, its tangent space at [Π] is Hom(Π, R⁴/Π), on which the
derivative has the eigenvalues λν_b/κ, μν_b/κ: the fixed point attracts iff |ν_b| < min(|λ|, |μ|) for
b = 1, 2.  With cp(M)(z) = (z² − tz + κ)(z² + sz + p) (t = T/D the trace of M on Π, as in :mod:`.five`;
s = c₁ + t, p = c₂ + ts − κ) and Δ = T² − 4κD²:

* *complex in-plane pair* (Δ < 0, |λ| = |μ| = √κ): Jury's criterion for z² + sz + p in the disc of radius
  √κ: κ − p > 0, κ + p > 0, (κ + p)² − s²κ > 0 (times D², D², D⁴);
* *real in-plane pair* (Δ > 0; λ, μ of one sign as κ > 0): with y = Dλ the larger in modulus,
  λ² − μ² = (2y − T)T/D² > 0, and Jury in the disc of radius |μ|, whose conditions do not depend on the
  sign of μ: μ² − p > 0, μ² ± sμ + p > 0 (times D²: :func:`.five.requirements`' stable ones).

An attracting orbit with a real pair λ, μ > 0 whose datum also exists is the self-similar collapse of
``certify pattern`` (the same plane); one with a complex pair is a periodic orbit of the reduction that
is not a collapse (as four particles' a(bac)²bcb).  A repeated factor of cp(Λ²M) (its eigenplanes not
unique) is not analysed here: never attracting (REPEATED_NOT_STABLE: a multiple root is not strictly
dominant); one κ − κ₀(r) with κ₀ < 0 on all of ]0, 1[ (decided exactly) holds no periodic orbit at all.
"""
from __future__ import annotations

import json
import time
from dataclasses import dataclass, field

import flint

from certify.algebra.branches import BRANCH_NAMES
from certify.algebra.poly import LR_LAMBDA, RING, Frac, mpoly_to_univariate, ring_to_mpoly, show_collected
from certify.algebra.sturm import sturm_count
from certify.dynamics.model import alphabet

from .feasibility import Analysis
from .five import (
    FiveCandidate,
    _req,
    built,
    entry,
    impose,
    other_factor,
    read_five,
    shared_candidate,
    stable_requirements,
    top_data,
    wedge_collide,
)
from .pattern import _copy, check_range, region_set

STAGES = ("orbit", "feasible", "attracting (real pair)", "attracting (complex pair)")
ZERO = Frac.of(0)


def orbit_requirements(cand: FiveCandidate) -> dict:
    """The requirements of each stage (the module's docstring), every one strict, > 0:
    {"exists": [...], "feasible": [[...] per collision], "real": [...], "complex": [...]}."""
    Y, T, D, red = cand.face, cand.T, cand.D, cand.ext.red
    letters = alphabet(5)
    j0 = next(j for j in range(4) if j != Y and not cand.p0[j].is_zero())
    s = cand.p0[j0]                                             # the orientation: s·p̂_{j₀} > 0
    exists = [_req("κ", (red(LR_LAMBDA), ZERO), 1)]
    exists += [_req(f"−ω_{Y + 1}{j + 1}", (red(cand.p0[j] * s), ZERO), 1) for j in range(4) if j not in (Y, j0)]
    feasible, P, previous = [], list(cand.plane), Y
    for k, letter in enumerate(cand.word, 1):
        i = letters.index(letter)
        feasible.append([_req(f"ω_{i + 1}{m + 1}(t_{k - 1})", (red(entry(P, i, m) * s), ZERO), 1)
                         for m in range(4) if m not in (previous, i)])
        P = wedge_collide(letter, P, red)
        previous = i
    stable = stable_requirements(cand)                          # [λ − μ, μ² − p, μ² + sμ + p, μ² − sμ + p]
    Ds, D2p = other_factor(cand)
    kD2 = red(LR_LAMBDA * D * D)
    delta = red(T * T - Frac.of(4) * kD2)
    real = [_req("Δ", (delta, ZERO), 1), _req("λ² − μ²", (red(-T * T), red(Frac.of(2) * T)), 1)] + stable[1:]
    complex_ = [_req("−Δ", (red(-delta), ZERO), 1), _req("κ − p", (red(kD2 - D2p), ZERO), 1),
                _req("κ + p", (red(kD2 + D2p), ZERO), 1),
                _req("(κ + p)² − s²κ", (red((kD2 + D2p) * (kD2 + D2p) - Ds * Ds * kD2), ZERO), 1)]
    return {"exists": exists, "feasible": feasible, "real": real, "complex": complex_}


@dataclass
class FiveOrbitResult:
    """The certified sets of :func:`analyse` (each {"branch", "set", "pieces"}, per stage of
    :data:`STAGES`), the undecided points, the factors not analysed, and how long it took."""

    word: str
    normal: str
    why: str
    r_range: tuple
    sets: dict
    undecided: list
    not_analysed: list
    conditions: dict
    seconds: float = 0.0
    regions: dict = field(default_factory=dict, repr=False)

    def markdown(self) -> str:
        lo, hi = self.r_range
        out = [f"# Periodic orbits of the five-particle reduction: {self.normal}", "",
               f"{self.normal} ({self.why}).  Every set certified over ]{lo}, {hi}[ (exact ends; "
               "certify/patterns/five_orbits.py has the proofs): the plane Π, a κ-eigenvector of Λ²M, on the "
               "face of the last letter, its run following the word, and attracting when κ = λμ strictly "
               "dominates.", ""]
        names = {"orbit": "A periodic orbit exists (κ > 0, the plane in its face)",
                 "feasible": "Feasible (the orbit follows the word)",
                 "attracting (real pair)": "Attracting, real in-plane pair (λ, μ real)",
                 "attracting (complex pair)": "Attracting, complex in-plane pair (not a collapse)"}
        for stage in STAGES:
            out.append(f"## {names[stage]}")
            out += [f"- {d['branch']}: {d['set']}" for d in self.sets[stage]] or ["- none"]
            out.append("")
        if self.not_analysed:
            out += ["## Not analysed", ""] + [f"- {n}" for n in self.not_analysed] + [""]
        if self.undecided:
            out += ["## Undecided points", ""] + [f"- {u}" for u in self.undecided] + [""]
        out.append(f"({self.seconds:.1f} s)")
        return "\n".join(out)

    def to_json(self) -> dict:
        return {"schema": "certify-five-orbit", "version": 1, "word": self.word, "normal_form": self.normal,
                "r_range": [str(x) for x in self.r_range], "sets": self.sets, "undecided": self.undecided,
                "not_analysed": self.not_analysed, "conditions": self.conditions}

    def json_text(self) -> str:
        return json.dumps(self.to_json(), ensure_ascii=False, indent=2, sort_keys=True)


def analyse(text: str, lo=0, hi=1, progress=None, shared: dict | None = None) -> FiveOrbitResult:
    """The periodic orbits of the five-particle reduction with the word ``text`` over ]lo, hi[, certified
    (the sets of the module's docstring, per κ branch of each simple factor of cp(Λ²M)); ``shared``: see
    :func:`.five.built`."""
    start = time.perf_counter()
    lo, hi = check_range(lo, hi)
    normal, why = read_five(text)
    sextic, factors = built(normal, shared)
    sets: dict = {stage: [] for stage in STAGES}
    regions: dict = {stage: [] for stage in STAGES}
    undecided, not_analysed, conditions = [], [], {}
    tick = progress or (lambda k, n, label="": None)
    for number, (factor, multiplicity) in enumerate(factors, 1):
        label = f"factor {number} of cp(Λ²M), " if len(factors) > 1 else ""
        kappa = show_collected(factor, "λ").replace("λ", "κ")
        if multiplicity > 1 and _negative_root(factor):
            continue                                  # κ < 0 on ]0, 1[: no periodic orbit (κ > 0 is needed)
        if multiplicity > 1:
            not_analysed.append(f"{kappa} (multiplicity {multiplicity}): its eigenplanes are not unique; never "
                                "attracting (a multiple root is not strictly dominant)")
            continue
        try:
            cand = shared_candidate(normal, factor if len(factors) > 1 else None, sextic, shared)
        except ArithmeticError as e:
            not_analysed.append(f"{kappa}: {e}")
            continue
        reqs = orbit_requirements(cand)
        total = len(reqs["feasible"]) + 3
        an = Analysis(cand, lo, hi)
        for q in reqs["exists"]:
            impose(an, q)
        got = {"orbit": _copy(an.regions)}
        tick(1, total, "exists")
        for m, group in enumerate(reqs["feasible"], 1):
            for q in group:
                impose(an, q)
            tick(1 + m, total, f"collision {m} of {len(reqs['feasible'])}")
        feasible = _copy(an.regions)
        got["feasible"] = feasible
        for q in reqs["real"]:
            impose(an, q)
        got["attracting (real pair)"] = _copy(an.regions)
        an.regions = _copy(feasible)
        for q in reqs["complex"]:
            impose(an, q)
        got["attracting (complex pair)"] = _copy(an.regions)
        tick(total, total, "attracting")
        first = an.regions[0].fixed_point if an.regions else None
        for stage, rs in got.items():
            if stage != "attracting (real pair)":        # x plays no part: one fixed point label is enough
                rs = [R for R in rs if R.fixed_point == first]
            regions[stage] += rs
            sets[stage] += [dict(region_set(R), branch=label + _name(R.branch)) for R in rs if R.pieces]
        conditions = {k: [f"{q.name} > 0" for q in (v if k != "feasible" else [q for g in v for q in g])]
                      for k, v in reqs.items()}
        undecided += sorted({f"{label}{_name(R.branch)} at {rc.digits(10)}: {w}"
                             for stage in ("attracting (real pair)", "attracting (complex pair)")
                             for R in got[stage] for rc, w in R.undecided})
    return FiveOrbitResult(text, normal, why, (lo, hi), sets, undecided, not_analysed, conditions,
                           time.perf_counter() - start, regions)


def _negative_root(factor) -> bool:
    """Whether ``factor`` (monic in κ) is κ + c(r) with c > 0 on all of ]0, 1[ (exactly: no root of c in
    ]0, 1] by Sturm, and c(1/2) > 0): its root κ = −c(r) < 0 holds no periodic orbit."""
    if factor.degree(RING.gens[0]) != 1:
        return False
    c = flint.fmpq_poly(mpoly_to_univariate(ring_to_mpoly(factor.coeff_wrt(RING.gens[0], 0))))
    half = flint.fmpq(1, 2)
    return sturm_count(c, 0, 1) == 0 and c(half) > 0


def _name(branch: int) -> str:
    return BRANCH_NAMES[branch] if branch < len(BRANCH_NAMES) else f"κ{branch}"


PART = {"feasible": "feasible", "attracting_real": "attracting (real pair)",
        "attracting_complex": "attracting (complex pair)"}      # a census record's keys -> the stages


def census_part(word: str, shared: dict | None = None) -> dict:
    """The five-particle census's part on the periodic orbits of the reduction (``certify orbit WORD``
    over ]0, 1[, ``word`` a normal form): per key of :data:`PART` the r-sets as "branch: set" texts,
    the factors not analysed, the distinct undecided r (10 digits), and ``top``, the largest upper end
    or isolated point of each attracting set (exact, :func:`.pattern.end_data`; None when empty);
    ``shared``: see :func:`.five.built`."""
    res = analyse(word, shared=shared)
    part = {key: [f"{d['branch']}: {d['set']}" for d in res.sets[stage]] for key, stage in PART.items()}
    part["not_analysed"] = list(res.not_analysed)
    part["undecided"] = sorted({rc.digits(10) for stage in (PART["attracting_real"], PART["attracting_complex"])
                                for R in res.regions[stage] for rc, _why in R.undecided})
    part["top"] = {key: top_data(end for R in res.regions[PART[key]] for end in _ends(R))
                   for key in ("attracting_real", "attracting_complex")}
    return part


def _ends(R) -> list:
    """The upper ends of a region's maximal intervals and its isolated points."""
    spans, points = R.merged()
    return [b for _a, b in spans] + [q.lo for q in points]
