"""``certify orbit WORD``: the periodic orbits of the reduction of Section 4, certified.

The reduction (:mod:`certify.dynamics.reduction`) acts on states (c, n): the contact c
just made and the normal n of the plane P = Span(p, q), oriented by e_t · n > 0
(t = y, z, x for c = a, b, c, l. 950).  With i = INDEX[c] and the orientation
n_{i+1} > 0 (indices mod 3; t = i + 1 for every contact), the position p ∝ n ∧ e_i lies
inside the face c iff n_{i+2} < 0, and the next contact is the cyclic successor of c
(index i + 1) iff n_i > 0, the other one (index i + 2) iff n_i < 0 (n_i n_j > 0, and
:func:`~certify.dynamics.reduction._next_letter_exact`); the new normal is
cof(K_j) n, re-oriented if needed.

**The periodic orbits of a word.**  Let w = c_1 … c_L be the normal form (it ends with
b; c_0 = c_L = b), M_w = K_{c_L} ··· K_{c_1}, N_w = cof(M_w) = cof(K_{c_L}) ··· cof(K_{c_1})
(cof(AB) = cof(A) cof(B)).  For a real eigenvalue λ = λ_x of M_w (a real branch of
cp = det(ΛI - M_w)) let n* = (n_1, n_2, 1) solve M_wᵀ n* = λ n* (two rows of the
eigen-equation, Cramer's rule over Q(λ, r): :func:`left_eigenvector`), and
n_0 = n*, n_k = cof(K_{c_k}) n_{k-1}.  Then (b, n*) is a periodic orbit of the
reduction with word w, strictly (every contact decided by a non-zero sign), iff

* *exists*: n* is the oriented normal of a state at b inside the face:
  n*_z = 1 > 0 (the normalisation is the orientation at b), n*_x < 0; and
  det M_w / λ > 0;
* *feasible*: moreover σ_k (n_{k-1})_{i_{k-1}} > 0 for k = 1..L, where i_{k-1} =
  INDEX[c_{k-1}] and σ_k = +1 if c_k is the cyclic successor of c_{k-1}, -1 otherwise.

Proof.  No re-orientation happens along the way, so the reduction's normals are
positive multiples of the n_k: if (c, n) is oriented with p inside the face and
the next contact j decided strictly, then cof(K_j) n is oriented at j with its
position inside the face j.  Indeed (the paper's physical reading) n is a positive
multiple of p ∧ w, w = |n|² e_i - n_i n the tangential velocity (its e_t component is
p_{t+1} w_i > 0 -- e.g. at a, (p ∧ w)_y = p_z w_x); the line p + τw meets {x_j = 0} at
τ = -p_j / w_j > 0 at p' with p'_i = τ w_i > 0 and p'_m = p_m + τ w_m > 0 for the third
index m (w_m = -n_i n_m > 0), and cof(K_j)(p ∧ w) = cof(K_j)(p' ∧ w) = K_j p' ∧ K_j w =
p' ∧ K_j w (K_j fixes {x_j = 0} pointwise) with (K_j w)_j = -r w_j > 0: the normal of a
state at j inside the face, hence oriented there (same computation).  So, given the
conditions at (b, n*), the orbit follows w iff each direction condition holds, and
returns after L steps to (b, cof... n*) = (b, N_w n*), N_w n* = det(M_w) M_w^{-T} n* =
(det M_w / λ) n*: a positive multiple of n* exactly when det M_w / λ > 0 (which the
orientation at the return implies anyway).  Conversely a periodic orbit (b, n) with
word w has N_w n ∝ n with a positive factor: n is an eigenvector of N_w, i.e. of
M_w^{-T}, i.e. M_wᵀ n = λ n for a real λ, and n is the oriented one (n_z > 0).  The
orientation and face conditions at every later contact are therefore implied; they
are re-checked on the certified sets by the tests (:func:`implied_requirements`).

**The multipliers are λ/λ_y and λ/λ_z** (λ_y, λ_z the other eigenvalues of M_w).  Near
n* every sign above keeps its value, so the return map is n ↦ N_w n up to a positive
factor: on the projective plane, the map [n] ↦ [N_w n].  N_w = det(M_w) M_w^{-T} has the
eigenvalues α_x = det/λ, α_y = det/λ_y, α_z = det/λ_z with the left eigenvectors of M_w
as eigenvectors.  In the affine chart {ℓ(n) = 1} around n* (ℓ linear, ℓ(n*) = 1,
ker ℓ = E = the sum of the eigenspaces of α_y, α_z, complexified if need be), write
n = n* + y, y ∈ E: N_w n / ℓ(N_w n) = (α_x n* + N_w y)/α_x = n* + (N_w|_E / α_x) y, as
ℓ(N_w y) = 0 (N_w E = E).  So in that chart the return map is linear, y ↦ N_w y / α_x,
with the eigenvalues α_y/α_x = λ/λ_y and α_z/α_x = λ/λ_z.  (A test compares them with
a finite-difference Jacobian of the exact reduction of :mod:`certify.dynamics.reduction`.)

**The type.**  Q(Λ) = cp(Λ)/(Λ - λ) = Λ² + pΛ + q has the roots λ_y, λ_z, q = λ_y λ_z =
det M_w / λ > 0 (imposed in *exists*), Q(λ) = cp'(λ), Q(-λ) = cp(-λ)/(-2λ).  The
multipliers ν = λ/λ_y, λ/λ_z are the roots of a(ν) = qν² + pλν + λ² = (λ_y ν - λ)(λ_z ν - λ),
with a(1) = Q(λ), a(-1) = Q(-λ).  By the Schur-Cohn-Jury criterion for a real quadratic
with leading coefficient q > 0 (both roots in the open unit disc iff a(1) > 0,
a(-1) > 0 and |a(0)| < q), the orbit is

* *attracting* (both |ν| < 1: λ strictly the smallest eigenvalue in modulus) iff
  cp'(λ) > 0, -λ cp(-λ) > 0, λ (det M_w - λ³) > 0 (q - λ² = (det - λ³)/λ);
* *repelling* (both |ν| > 1: λ strictly the largest in modulus; the same criterion on
  Q(|λ|z)/λ², roots of Q in the open disc of radius |λ|) iff cp'(λ) > 0, -λ cp(-λ) > 0,
  λ (λ³ - det M_w) > 0;
* a *saddle* (|ν_1| < 1 < |ν_2|) iff a(1) a(-1) = q²(1 - ν_1²)(1 - ν_2²) < 0, i.e.
  λ cp'(λ) cp(-λ) > 0 (for a complex pair (1 - ν²)(1 - ν̄²) = |1 - ν²|² ≥ 0: a saddle
  has a real pair).

The Jury criterion for z² + Pz + R (real): |R| < 1 and |P| < 1 + R.  Complex roots:
|z|² = R, and P² < 4R gives |P| < 2√R < 1 + R.  Real roots z_1 ≤ z_2: both in ]-1, 1[
iff (1 - z_1)(1 - z_2) > 0, (1 + z_1)(1 + z_2) > 0 and |z_1 z_2| < 1 (if both exceed 1 or
both are below -1, |z_1 z_2| > 1; if they straddle 1 or -1 a product is negative).

**The in-plane pair** (λ_y, λ_z) is complex iff disc_λ cp < 0 (a real cubic with one
real root), real iff disc_λ cp > 0.  A complex pair carries no velocity eigenvector in
the plane: the velocity turns in the plane by the argument of the pair each period,
and the particles leave the word within a period or two (the prefix of Remark 4.2,
S11): such an orbit of the reduction is not a collapse.

Every condition is a polynomial (or a rational function of two polynomials) in
(λ, r), without √Δ, certified over whole r-intervals on each real branch by
:class:`.feasibility.Analysis` (the machinery of ``certify pattern``).
"""
from __future__ import annotations

import json
import time
from dataclasses import dataclass, field, replace
from functools import cached_property
from pathlib import Path

import flint

from certify.algebra.algebraic import Algebraic, sign_at
from certify.algebra.branches import BRANCH_NAMES
from certify.algebra.poly import (
    FIELD,
    LR_LAMBDA,
    LRCTX,
    LRQCTX,
    Frac,
    flint_poly_to_frac,
    frac_to_field,
    lr_to_ring,
    show,
    show_collected,
)
from certify.dynamics.model import INDEX, LETTERS
from certify.dynamics.reduction import ORIENTATION, cofactor, cofactor_columns
from certify.dynamics.systems import candidate_in
from certify.dynamics.words import Candidate, spectrum_of
from certify.errors import UsageError

from .feasibility import NO_X, Analysis, Requirement
from .pattern import _cap, _cond, _copy, _nonempty, algebraic_ends, check_range, end_data
from .pattern import analyse as analyse_pattern
from .periodic import MAX_LENGTH, compact, normal_form, read, validate
from .periodic import show as show_word

SCHEMA_PATH = Path(__file__).with_name("orbit.schema.json")
SCHEMA_VERSION = 1
TYPES = ("attracting", "saddle", "repelling")


# ------------------------------------------------------------------ the normal n* and its run
def _lrq(F: Frac) -> flint.fmpq_mpoly:
    """A Frac with a constant denominator as fmpq_mpoly in (λ, r)."""
    if not F.den.is_constant():
        raise ValueError("not a polynomial")
    d = flint.fmpq(int(F.den.leading_coefficient()))
    return LRQCTX.from_dict({m: flint.fmpq(int(c)) / d for m, c in F.num.to_dict().items()})


def _lr(p: flint.fmpq_mpoly) -> tuple:
    """(P, d): p = P/d, P an fmpz_mpoly in (λ, r), d > 0 an integer."""
    terms = p.to_dict()
    d = flint.fmpz(1)
    for c in terms.values():
        d = d.lcm(c.q)
    return LRCTX.from_dict({m: int(c * d) for m, c in terms.items()}), d


def left_eigenvector(Mq, rows=(0, 1)) -> tuple:
    """(N_1, N_2, N_3), polynomials in (λ, r) (fmpq_mpoly), with n* = (N_1, N_2, N_3)/N_3
    = (n_1, n_2, 1) solving the rows ``rows`` of (M_wᵀ - λI) n = 0 by Cramer's rule;
    N_3 is their 2x2 determinant.  The three choices of rows agree on the branches
    wherever their determinants do not vanish (M_wᵀ - λI has rank 2 off the zeros of
    disc_λ cp)."""
    M = [[flint_poly_to_frac(e) for e in row] for row in Mq]
    A = [[M[j][i] - LR_LAMBDA if i == j else M[j][i] for j in range(3)] for i in range(3)]   # Mᵀ - λI
    (a11, a12), (a21, a22) = [(A[i][0], A[i][1]) for i in rows]
    b1, b2 = (-A[i][2] for i in rows)
    return tuple(_lrq(e) for e in (b1 * a22 - a12 * b2, a11 * b2 - b1 * a21, a11 * a22 - a12 * a21))


def cofactor_rows(letter: str) -> list:
    """The rows of cof(K) for K = A, B, C, polynomials in r (fmpq_mpoly in (λ, r)), from
    :func:`certify.dynamics.reduction.cofactor_columns` (cof(K) e_m = K e_{m+1} ∧ K e_{m+2})."""
    one, zero, R = Frac.of(1), Frac.of(0), Frac(LRCTX.gen(1))
    unit = ((one, zero, zero), (zero, one, zero), (zero, zero, one))
    cols = cofactor_columns(letter, R, unit)
    return [[_lrq(Frac.of(cols[m][k])) for m in range(3)] for k in range(3)]


def normals(word: str, N: tuple, C) -> list:
    """[n_0, ..., n_{L-1}] (numerators over the common denominator N_3): n_0 = N,
    n_k = cof(K_{c_k}) n_{k-1}, reduced modulo cp (``C``, fmpq_mpoly monic in λ): the
    same values on every branch, λ-degree below 3."""
    rows = {L: cofactor_rows(L) for L in LETTERS}
    out = [tuple(divmod(e, C)[1] for e in N)]
    for letter in word[:-1]:
        n = out[-1]
        out.append(tuple(divmod(row[0] * n[0] + row[1] * n[1] + row[2] * n[2], C)[1] for row in rows[letter]))
    return out


def _ratio(num, den) -> object:
    """num/den (fmpq_mpoly) as an element of FIELD = Q(λ, r) in lowest terms (python-flint's gcd)."""
    (P, a), (Q_, b) = _lr(num), _lr(den)
    return frac_to_field(Frac(P * int(b), Q_ * int(a)))


def contact_requirements(word: str, Mq, C) -> tuple[list[Requirement], list[Requirement]]:
    """(exists, feasible) requirements of the module docstring, each a ratio of
    polynomials in (λ, r) and a strict sign.  n* from rows (0, 1); the choices (0, 2) and
    (1, 2) are the ``other`` representations used at points where the first is 0/0."""
    Ns = [left_eigenvector(Mq, rows) for rows in ((0, 1), (0, 2), (1, 2))]
    runs = [normals(word, N, C) for N in Ns]
    c0 = word[-1]
    if ORIENTATION[c0] != 2:
        raise ValueError("the normal form ends with b: n* is normalised by n_z = 1, the orientation at b")

    def req(name, k, comp, sign):
        reps = [(_ratio(run[k][comp], run[0][2]), FIELD.zero) for run in runs]
        return Requirement(name, reps[0], sign, tuple(reps[1:]))

    i0 = INDEX[c0]
    exists = [req("n*_x (inside the face b)", 0, (i0 + 2) % 3, -1)]
    feasible = []
    letters = c0 + word
    for k in range(1, len(word) + 1):
        i, j = INDEX[letters[k - 1]], INDEX[letters[k]]
        sigma = 1 if j == (i + 1) % 3 else -1
        feasible.append(req(f"n_{k - 1}[{'xyz'[i]}] (contact {k}: {letters[k]})", k - 1, i, sigma))
    return exists, feasible


def implied_requirements(word: str, Mq, C) -> list[Requirement]:
    """The orientation (n_k)_{i+1} > 0 and face (n_k)_{i+2} < 0 conditions at every contact
    k = 1..L-1: implied by the others (module docstring); the tests check that they hold
    on the certified sets."""
    N = left_eigenvector(Mq)
    run = normals(word, N, C)
    out = []
    for k in range(1, len(word)):
        i = INDEX[word[k - 1]]
        out.append(Requirement(f"orientation n_{k}", (_ratio(run[k][(i + 1) % 3], run[0][2]), FIELD.zero), 1))
        out.append(Requirement(f"face n_{k}", (_ratio(run[k][(i + 2) % 3], run[0][2]), FIELD.zero), -1))
    return out


# ------------------------------------------------------------------ the type
def type_requirements(cp_ring) -> dict[str, list[Requirement]]:
    """The conditions of attracting / saddle / repelling (module docstring), polynomials
    in (λ, r) of the engine's ring, given det M_w / λ > 0."""
    from certify.algebra.poly import RING, to_field
    C = cp_ring
    L = RING.gens[0]
    d = C.diff(L)
    minus = RING.from_dict({(e[0],) + e[1:]: (-c if e[0] % 2 else c) for e, c in C.terms()})   # cp(-λ)
    det = -C.coeff_wrt(L, 0)

    def R(name, e, sign=1):
        return Requirement(name, (to_field(e), FIELD.zero), sign)
    common = [R("cp'(λ)", d), R("-λ cp(-λ)", -L * minus)]
    return {"attracting": common + [R("λ (det M - λ³)", L * (det - L ** 3))],
            "repelling": common + [R("λ (λ³ - det M)", L * (L ** 3 - det))],
            "saddle": [R("λ cp'(λ) cp(-λ)", L * d * minus)]}


def mu_requirement(cp_ring) -> Requirement:
    """det M_w / λ > 0: the N_w-eigenvalue of n* is positive (det M_w = -cp(0))."""
    from certify.algebra.poly import RING, to_field
    L = RING.gens[0]
    det = -cp_ring.coeff_wrt(L, 0)
    return Requirement("det M / λ", (to_field(det) / to_field(L), FIELD.zero), 1)


def pair_requirement(spectrum, sign: int) -> Requirement:
    """disc_λ cp < 0 (sign -1: the in-plane pair complex) or > 0 (real)."""
    from certify.algebra.poly import RING, to_field
    zeros = (0,) * (len(RING.gens) - 2)
    disc = RING.from_dict({(0, k) + zeros: RING.domain(int(c)) for k, c in enumerate(spectrum.disc.coeffs()) if c})
    return Requirement("disc_λ cp", (to_field(disc), FIELD.zero), sign)


# ------------------------------------------------------------------ results
def _pieces(regions) -> list:
    """The open intervals ]a, b[ (algebraic ends) of a list of regions, with their branch."""
    return [(R.branch, a, b) for R in regions for a, b in R.merged()[0]]


def _overlaps(spans, branch, a, b) -> bool:
    return any(k == branch and x < b and y > a for k, x, y in spans)


@dataclass
class OrbitResult:
    """The periodic orbits of the reduction for one word; ``to_json()`` follows
    orbit.schema.json."""

    input: str
    normal: str
    system: str
    explanation: str
    interval: tuple
    cp: str
    conditions: dict                  # stage -> [condition text]
    regions: dict                     # stage -> [Region]: exists, feasible, attracting, saddle, repelling, complex
    undecided: list
    pattern: object                   # the PatternResult of the same word (self-similar collapse data)
    verdict: str = ""
    not_computed: str = ""            # why ``pattern`` is None when the physics line should say so
    physics: str = ""
    seconds: float = 0.0
    formulas: object = field(default=None, repr=False)     # () -> {name: formula} of n*

    @cached_property
    def eigenvector(self) -> dict:
        """The formulas of n* = (n_1, n_2, 1)."""
        return self.formulas() if self.formulas is not None else {}

    @property
    def written(self) -> str:
        return show_word(self.normal)

    def sets(self, stage: str) -> list:
        return _nonempty(self.regions[stage])

    def attracting(self) -> list[dict]:
        """The maximal open r-intervals where the orbit is attracting, per branch, with the
        in-plane pair there (real, complex, or real and complex: the pair changes at a
        zero of disc_λ cp inside)."""
        cx = _pieces(self.regions["complex"])
        re_ = _pieces(self.regions["real"])
        out = []
        for k, a, b in _pieces(self.regions["attracting"]):
            c, r_ = _overlaps(cx, k, a, b), _overlaps(re_, k, a, b)
            pair = "real and complex" if c and r_ else "complex" if c else "real"
            out.append({"branch": BRANCH_NAMES[k], "pair": pair, "lo": end_data(a), "hi": end_data(b)})
        return out

    def attracting_points(self) -> list[dict]:
        return [{"branch": BRANCH_NAMES[R.branch], "at": end_data(q.lo)}
                for R in self.regions["attracting"] for q in R.merged()[1]]

    def to_json(self) -> dict:
        p = self.pattern
        return {"schema": "certify-orbit", "version": SCHEMA_VERSION, "input": self.input,
                "normal_form": self.written, "compact": compact(self.normal), "system": self.system,
                "explanation": self.explanation, "r_range": [str(self.interval[0]), str(self.interval[1])],
                "characteristic_polynomial": self.cp, "conditions": self.conditions,
                "exists": self.sets("exists"), "feasible": self.sets("feasible"),
                "types": {t: self.sets(t) for t in TYPES}, "complex_pair": self.sets("complex"),
                "attracting": self.attracting(), "attracting_points": self.attracting_points(),
                "undecided": self.undecided, "eigenvector": self.eigenvector,
                "self_similar": None if p is None else {"stable": p.stable, "feasible": p.feasible,
                                                        "verdict": p.verdict},
                "physics": self.physics, "verdict": self.verdict}

    def json_text(self) -> str:
        return json.dumps(self.to_json(), ensure_ascii=False, indent=2, sort_keys=True)

    def markdown(self) -> str:
        lo, hi = self.interval
        out = [f"# Periodic orbits of the reduction: {self.written}", "",
               f"- input: `{self.input}`; normal form analysed: `{self.written}` (= `{compact(self.normal)}`)",
               f"- same orbit: {self.explanation}", f"- r in ]{lo}, {hi}[", "",
               f"cp(M_w) = `{self.cp}`", "",
               ("A periodic orbit (b, n*) of the reduction (Section 4) with this word, for each real eigenvalue "
                "λ = λ_x of M_w: n* = (n_1, n_2, 1) with M_wᵀ n* = λ n*, the oriented normal at the contact b "
                "(l. 950); the plane n*^⊥ is spanned by the eigenvectors of the two other eigenvalues (the "
                "in-plane pair), and its position at b is p* = (1, 0, -n_1). The return map's multipliers are "
                "λ/λ_y and λ/λ_z."), ""]
        titles = (("exists", "The orbit exists (n* oriented, inside the face b, N_w-eigenvalue det M/λ > 0)"),
                  ("feasible", "Feasible (every contact of the word decided strictly from n*)"),
                  ("attracting", "Attracting (λ strictly the smallest eigenvalue in modulus)"),
                  ("saddle", "Saddle (one multiplier inside the unit circle, one outside)"),
                  ("repelling", "Repelling (λ strictly the largest eigenvalue in modulus)"),
                  ("complex", "Feasible with a complex in-plane pair (disc_λ cp < 0): not collapse"))
        ends = {}
        for stage, title in titles:
            out += [f"## {title}", ""]
            if stage in self.conditions:
                out += ["Conditions: " + "; ".join(self.conditions[stage]), ""]
            sets = self.sets(stage)
            out += [f"- {s['branch']} branch: {s['set']}" for s in sets] or ["∅ on every branch."]
            out.append("")
            ends.update(algebraic_ends(sets))
        if ends:
            out += ["End points:", ""] + [f"- {k}: the root of `{e['minimal_polynomial']}` in ]{e['interval'][0]}, "
                                          f"{e['interval'][1]}[" for k, e in sorted(ends.items())] + [""]
        if self.undecided:
            out += ["## Undecided", ""] + [f"- {u}" for u in self.undecided] + [""]
        out += ["## The normal n*", ""] + [f"- {k} = `{v}`" for k, v in self.eigenvector.items()] + [""]
        out += ["## Physics", "", self.physics, "", "## Verdict", "", self.verdict, ""]
        return "\n".join(out + resonance_lines(self))


def resonance_lines(res: OrbitResult) -> list[str]:
    """The ends of the attracting windows that are resonances of the island around [ac]b (the
    same algebraic number: :func:`.island_theorem.window_resonances`), as a section of the
    text output; nothing when there are none."""
    from .island_theorem import RESONANCE_Q, resonance_phrase, window_resonances
    found = window_resonances({res.written: res.attracting()}, RESONANCE_Q)
    if not found:
        return []
    return ["## Window ends at resonances of the island", ""] + [
        f"- an attracting window: {resonance_phrase(side, d, p, q)} (`certify island --resonances {RESONANCE_Q}`)"
        for _w, side, d, (p, q) in found] + [""]


def verdict(res: OrbitResult) -> str:
    w, (lo, hi) = res.written, res.interval
    where = f"for r in ]{lo}, {hi}["
    att = res.attracting()
    if att:
        parts = [f"{a['branch']}: ]{_digits(a['lo'])}, {_digits(a['hi'])}[ ({a['pair']} pair)" for a in att]
        v = f"{w}: attracting periodic orbit of the reduction {where} on " + "; ".join(parts)
    elif res.sets("feasible"):
        kinds = [t for t in ("saddle", "repelling") if res.sets(t)]
        v = f"{w}: periodic orbits of the reduction exist {where}, never attracting" + \
            (f" ({' and '.join(kinds)})" if kinds else "")
    elif res.sets("exists"):
        v = f"{w}: the eigen-normals n* exist but never realise the word {where}: no periodic orbit of the reduction"
    else:
        v = f"{w}: no oriented eigen-normal n* inside the face b {where}: no periodic orbit of the reduction"
    if res.undecided:
        v += f"; {len(res.undecided)} point(s) undecided"
    return v


def _digits(e: dict) -> str:
    return e["exact"] if e["exact"] is not None else "≈" + e["digits"]


# One output, two objects named by branches: the orbit's branch is the eigenvalue λ of its
# normal n* (a left eigenvector), the self-similar datum's the eigenvalue of its velocity q(0)
# (a right eigenvector, in the plane n*^⊥).  (ab)^3(cb)^3's window is "lower" for the orbit and
# "upper x₊" for the datum: the same r-interval, two eigenvalues.
BRANCH_WORDS = ("there a branch names the eigenvalue of q(0); in the sets above and in the verdict it names "
                "the eigenvalue λ of the normal n*, whose plane n*^⊥ holds the eigenvectors of the two other "
                "branches: an orbit on the lower branch turns in the plane of the upper and middle ones")


def physics(res: OrbitResult) -> str:
    """Where self-similar collapse data exist (``certify pattern``, the real-pair case) and
    where the in-plane pair is complex (not collapse); the two meanings of a branch's name
    said once (:data:`BRANCH_WORDS`)."""
    p = res.pattern

    def sets(lst):
        return "; ".join(f"{s['branch']}{'' if s['fixed_point'] == NO_X else ' ' + s['fixed_point']}: {s['set']}"
                         for s in lst) or "∅"
    text = (res.not_computed + " " if res.not_computed else "") if p is None else (
        f"Self-similar collapse data of {res.written} (certify pattern, the real-pair case: the velocity q(0) an "
        f"eigenvector of M_w for λ > 0 in the invariant plane; {BRANCH_WORDS}): stable on {sets(p.stable)}; "
        f"feasible on {sets(p.feasible)}. ")
    cx = res.sets("complex")
    if cx:
        text += (f"Complex in-plane pair on {sets(cx)}: no velocity eigenvector lies in the plane, the velocity "
                 "turns in it by the argument of the pair each period, and the particles leave the word within a "
                 "period or two (the prefix of Remark 4.2, S11): there the orbit of the reduction is not a collapse.")
    else:
        text += "No feasible orbit has a complex in-plane pair."
    return text


# ------------------------------------------------------------------ the analysis
SELF_SIMILAR_MAX_LENGTH = 40
"""The longest normal form whose physics line runs ``certify pattern``'s analysis by default.
That analysis certifies every collision with the fixed point x (norms with √Δ, of several
times the degree of the orbit's own conditions) and grows faster: half of the 38 letters near
r = 0.5, but 80% of the 122 letters of r = 0.173.  Longer words get a physics line saying the
self-similar data were not computed and how to get them (``--self-similar``, or ``certify
pattern``); everything about the orbit itself is computed whatever the length."""

MAX_ORBIT_LENGTH = 240
"""The longest normal form ``analyse`` takes: twice the longest attractor met so far (the
122 letters of r = 0.173, about 20 s of one core without the self-similar data, 100 s with
them).  M_w has entries of degree L in r, the
conditions degree about 2L in r with coefficients of about 3L bits, their resultants and
norms degree several times that, and the work grows faster than L³; longer words (up to
the reader's 400 letters: (ab)^100(cb)^100 ran silently for over 10 minutes) are refused
with this reason (:func:`check_length`), shorter ones show progress on a terminal."""


def check_length(normal: str) -> None:
    """UsageError (one line, exit 2) for a normal form longer than :data:`MAX_ORBIT_LENGTH`."""
    if len(normal) > MAX_ORBIT_LENGTH:
        raise UsageError(f"orbit: {len(normal)} letters, more than {MAX_ORBIT_LENGTH}: the exact analysis grows "
                         f"faster than the cube of the length (122 letters take under a minute; 400 letters ran "
                         f"for over 10 minutes without an end)")


def analyse(word: str, lo=0, hi=1, self_similar: bool | None = None, progress=None) -> OrbitResult:
    """The periodic orbits of the reduction with the word ``word`` (any rotation or mirror),
    over ]lo, hi[: the sets of the module docstring, per real branch, certified.
    ``self_similar=False`` skips the pattern analysis of the physics line (the census has
    it already): ``pattern`` is then None and the physics line says only where the pair
    is complex.  ``None`` (the default) runs it up to :data:`SELF_SIMILAR_MAX_LENGTH`
    letters and beyond says in the physics line that it was not computed; ``True`` always.
    ``progress(k, n, label)`` (e.g. :class:`certify.run.progress.Bar`) is told after each
    step: M_w, the branches, each condition imposed, the physics line.  A normal form
    longer than :data:`MAX_ORBIT_LENGTH` is refused (UsageError)."""
    start = time.perf_counter()
    lo, hi = check_range(lo, hi)
    normal, system_name, why = read(word)
    if system_name != "four":
        raise UsageError(f"orbit: {show_word(normal)!r} is a word of the {system_name} system (two gaps); the "
                         "reduction of Section 4 is the four-particle one: a word with a, b and c")
    check_length(normal)
    not_computed = ""
    if self_similar is None:
        self_similar = len(normal) <= SELF_SIMILAR_MAX_LENGTH
        if not self_similar:
            not_computed = (f"Self-similar collapse data of {show_word(normal)}: not computed ({len(normal)} letters, "
                            f"more than {SELF_SIMILAR_MAX_LENGTH}: `certify orbit --self-similar` or `certify pattern` "
                            "computes them).")
    total, done = len(normal) + 14 + self_similar, [0]

    def step(label):
        done[0] += 1
        if progress is not None:
            progress(done[0], total, label)
    cand = candidate_in(system_name, normal) if self_similar else orbit_candidate(normal)
    spec = cand.spectrum
    step("M_w and cp")
    an = Analysis(replace(cand, abcd=None, abcd_ring=None), lo, hi)   # no position variable x here
    step("the real branches")
    C = spec.lrq_cp
    exists, feasible = contact_requirements(normal, cand.Mq, C)
    step("n* and its run")
    mu = mu_requirement(spec.ring_cp)
    conditions = {"exists": [_cond(q) for q in [mu] + exists], "feasible": [_cond(q) for q in feasible]}
    for q in [mu] + exists:
        an.impose(q)
        step(q.name)
    regions = {"exists": _copy(an.regions)}
    for q in feasible:
        an.impose(q)
        step(q.name)
    regions["feasible"] = _copy(an.regions)
    types = type_requirements(spec.ring_cp)
    undecided = set()
    for t in TYPES:
        sub = _fork(an)
        conditions[t] = [_cond(q) for q in types[t]]
        for q in types[t]:
            sub.impose(q)
            step(f"{t}: {q.name}")
        regions[t] = sub.regions
        undecided |= _undecided(sub)
    for name, sign in (("complex", -1), ("real", 1)):
        sub = _fork(an)
        q = pair_requirement(spec, sign)
        sub.impose(q)
        step(f"{name} pair")
        regions[name] = sub.regions
        if name == "complex":
            conditions["complex"] = [_cond(q)]
    undecided |= _undecided(an)
    pat = analyse_pattern(normal, lo, hi, formulas=False, diagnosis=False) if self_similar else None
    if self_similar:
        step("self-similar data (the physics line)")

    def formulas():
        N = left_eigenvector(cand.Mq)
        den = divmod(N[2], C)[1]
        out = {name: _cap(_factored(divmod(N[k], C)[1], den)) for name, k in (("n_1", 0), ("n_2", 1))}
        out["n*"] = "(n_1, n_2, 1), λ a root of cp (the formulas reduced modulo cp)"
        return out
    res = OrbitResult(word, normal, system_name, why, (lo, hi), show_collected(cand.spectrum.ring_cp), conditions,
                      regions, sorted(undecided), pat, not_computed=not_computed, formulas=formulas)
    res.verdict, res.physics = verdict(res), physics(res)
    res.seconds = time.perf_counter() - start
    return res


def orbit_candidate(normal: str) -> Candidate:
    """What the orbit's analysis reads of a word's candidate: M_w, cp and the Spectrum
    (shared with ``certify pattern``'s candidate, :func:`certify.dynamics.words.spectrum_of`),
    without q(0)'s run and the position map (no position variable x here)."""
    Mq, cp, _ring_cp, spectrum = spectrum_of(normal)
    return Candidate(normal, Mq, cp, spectrum, (), [], None, [], None)


def _factored(num, den) -> str:
    """num/den (fmpq_mpoly in (λ, r)) in lowest terms, numerator and denominator factored
    over Q (python-flint), in the paper's notation."""
    (P, a), (Q_, b) = _lr(num), _lr(den)
    F = Frac(P * int(b), Q_ * int(a))

    def text(p):
        c, factors = p.factor()
        parts = [(show(lr_to_ring(f)), int(m)) for f, m in factors]
        parts = [f"({t})" + (f"^{m}" if m > 1 else "") if len(parts) > 1 or c != 1 or m > 1 else t for t, m in parts]
        head = "" if c == 1 and parts else "-" if c == -1 and parts else str(c)
        return head + "".join(parts)
    return f"({text(F.num)}) / ({text(F.den)})"


def _fork(an: Analysis) -> Analysis:
    """A copy of the analysis with its regions, sharing the sign tables."""
    sub = Analysis.__new__(Analysis)
    sub.__dict__.update(an.__dict__)
    sub.regions = _copy(an.regions)
    return sub


def _undecided(an: Analysis) -> set:
    return {f"{BRANCH_NAMES[R.branch]} at {_short(rc)}: {why}" for R in an.regions for rc, why in R.undecided}


def _short(a) -> str:
    return str(a.lo) if a.is_rational else "≈" + a.digits(10)


# ------------------------------------------------------------------ n* at a rational r
def normal_at(word: str, r, branch: int, bits: int = 256) -> tuple:
    """A rational approximation of n* = (n_1, n_2, 1) at the rational r on the real
    branch ``branch`` (0 = the largest real eigenvalue) of the normal form ``word``:
    N(λ̃, r)/N_3(λ̃, r) with λ̃ a rational within 2^-bits of λ_x (an isolating interval
    refined by bisection); for simulations and tests, not a certificate."""
    cand = candidate_in("four", word)
    r = flint.fmpq(r)
    lams = cand.spectrum.real_eigenvalues(r)
    L = lams[branch]
    L.refine(flint.fmpq(1, 2 ** bits))
    lt = L.lo if L.is_rational else (L.lo + L.hi) / 2
    N = left_eigenvector(cand.Mq)
    v = [e(lt, r) for e in N]
    return (v[0] / v[2], v[1] / v[2], flint.fmpq(1))


# ------------------------------------------------------------------ the analysis at one rational r
@dataclass
class PointOrbit:
    """The periodic orbit (b, n*) of one real eigenvalue λ of M_w at a rational r, decided
    exactly (:func:`orbit_at`)."""

    branch: int                       # 0 = the largest real eigenvalue of M_w at r
    lam: object                       # λ, an Algebraic
    exists: bool                      # n* oriented, inside the face b, det M_w / λ > 0
    feasible: bool                    # moreover every contact of w decided strictly from n*
    kind: str                         # attracting, saddle, repelling, or "" (a multiplier of modulus 1, or no orbit)
    pair: str                         # the in-plane pair: real or complex
    modulus: object                   # the largest multiplier modulus max(|λ/λ_y|, |λ/λ_z|), an arb ball
    failed: str = ""                  # the first condition that fails, if any
    modulus_one: bool = False         # a multiplier of modulus exactly 1 (decided exactly)

    @property
    def branch_name(self) -> str:
        return BRANCH_NAMES[self.branch] if self.branch < len(BRANCH_NAMES) else str(self.branch)


def _matrix_at(word: str, r: flint.fmpq) -> flint.fmpq_mat:
    """M_w = K_{c_L} ··· K_{c_1} at the rational r, over Q."""
    from certify.dynamics.model import word_matrix_flint
    return flint.fmpq_mat([[e(r) for e in row] for row in word_matrix_flint(word)])


def _lin(c, x) -> flint.fmpq_poly:
    """The polynomial c + x λ (rationals c, x)."""
    return flint.fmpq_poly([c, x])


def _cramer(M: flint.fmpq_mat, lam_: Algebraic) -> tuple:
    """(N_1, N_2, N_3) in Q[λ] (degree ≤ 2) with n* = N/N_3 solving (M_wᵀ - λI) n = 0, from the
    first choice of two rows whose determinant N_3 does not vanish at λ; None if none."""
    A = [[_lin(M[j, i], -1 if i == j else 0) for j in range(3)] for i in range(3)]    # Mᵀ - λI
    for rows in ((0, 1), (0, 2), (1, 2)):
        (a11, a12), (a21, a22) = [(A[i][0], A[i][1]) for i in rows]
        b1, b2 = (-A[i][2] for i in rows)
        N = (b1 * a22 - a12 * b2, a11 * b2 - b1 * a21, a11 * a22 - a12 * a21)
        if sign_at(N[2], lam_) != 0:
            return N
    return None


def read_plain(text: str, max_length: int = MAX_LENGTH) -> tuple[str, str]:
    """(normal form, system) of a period.  Up to the parser's :data:`~.periodic.MAX_LENGTH`
    letters (or when ``max_length`` is not above it) by :func:`~.periodic.read` (powers,
    [ac]); a longer one only as plain letters a, b, c (no powers: a float64 run's block),
    at most ``max_length`` letters, validated and put in normal form by the same functions
    as ``read`` (:func:`~.periodic.validate`, :func:`~.periodic.normal_form`), so the word
    and its normal form are the ones ``read`` would give: the parser's limit guards what
    a user types, not the exact decision at one r.  UsageError (one line) otherwise."""
    if len(text) <= MAX_LENGTH or max_length <= MAX_LENGTH:
        normal, system, _ = read(text)
        return normal, system
    if len(text) > max_length:
        raise UsageError(f"invalid pattern word: {len(text)} letters, more than {max_length}")
    if set(text) - set(LETTERS):
        raise UsageError(f"invalid pattern word: a period longer than {MAX_LENGTH} letters is read as plain letters "
                         "a, b, c only")
    system = validate(text)
    return normal_form(text)[0], system


def orbit_at(word: str, r, max_length: int = MAX_LENGTH) -> list[PointOrbit]:
    """The periodic orbits of the reduction with the word ``word`` (any rotation or mirror)
    at one rational r, decided exactly: M_w over Q, cp over Q, its real roots λ as
    algebraic numbers (Sturm), n* in Q[λ] (Cramer), its run n_k = cof(K_{c_k}) n_{k-1}
    (the integer rows of :func:`certify.dynamics.reduction.cofactor`, positive
    multiples), every sign of the module docstring's conditions decided by
    :func:`certify.algebra.algebraic.sign_at` (0 is a failure: the conditions are
    strict), the type by the same polynomial criteria as :func:`analyse` and the pair by
    the sign of disc_λ cp; a multiplier of modulus exactly 1 by λ³ = det M_w (a complex
    pair, |ν|² = λ³/det M_w) or cp'(λ) cp(-λ) = 0 (a real one).  The multiplier modulus is an
    arb ball (λ/λ_y, λ/λ_z from the quadratic factor of cp).  One entry per real eigenvalue, largest first.
    ``max_length``: a longer period is read as plain letters up to this many (:func:`read_plain`)."""
    normal, system_name = read_plain(word, max_length)
    if system_name != "four":
        raise UsageError(f"orbit: {show_word(normal)!r} is a word of the {system_name} system")
    r = flint.fmpq(r)
    if not 0 < r < 1:
        raise UsageError(f"r must lie in ]0,1[, got {r}")
    M = _matrix_at(normal, r)
    cp = flint.fmpq_poly(M.charpoly())                     # monic: λ³ + a λ² + b λ + c
    c, b, a = (cp[k] for k in range(3))
    det = -c
    disc = 18 * a * b * c - 4 * a ** 3 * c + a ** 2 * b ** 2 - 4 * b ** 3 - 27 * c ** 2
    pair = "complex" if disc < 0 else "real"
    L = flint.fmpq_poly([0, 1])
    minus = flint.fmpq_poly([cp[k] * (-1) ** k for k in range(4)])          # cp(-λ)
    d = cp.derivative()
    types = {"attracting": [d, -L * minus, L * (det - L ** 3)], "repelling": [d, -L * minus, L * (L ** 3 - det)],
             "saddle": [L * d * minus]}
    rows = {x: cofactor(x, r) for x in LETTERS}
    out = []
    for k, lam_ in enumerate(Algebraic.roots(cp)[::-1]):
        def s(p, lam_=lam_):
            return sign_at(p, lam_)
        failed, kind = "", ""
        N = _cramer(M, lam_)
        if det == 0 or s(L) * (1 if det > 0 else -1) <= 0:
            failed = "det M / λ"
        elif N is None:
            failed = "n* (M_wᵀ - λI of rank < 2)"
        else:
            s3 = s(N[2])
            run, n = [], N
            for letter in normal:
                run.append(n)
                n = tuple(sum((row[m] * n[m] for m in range(3)), flint.fmpq_poly([])) for row in rows[letter])
            if s(run[0][0]) * s3 >= 0:
                failed = "n*_x (inside the face b)" + (" = 0" if s(run[0][0]) == 0 else "")
            letters = normal[-1] + normal
            for j in range(1, len(normal) + 1):
                if failed:
                    break
                i, nxt = INDEX[letters[j - 1]], INDEX[letters[j]]
                sigma = 1 if nxt == (i + 1) % 3 else -1
                sign = s(run[j - 1][i])
                if sigma * sign * s3 <= 0:
                    failed = (f"n_{j - 1}[{'xyz'[i]}] (contact {j}: {letters[j]})"
                              + (" = 0: undecided" if sign == 0 else ""))
        exists = not failed or failed.startswith("n_")
        feasible = not failed
        if feasible:
            kind = next((t for t in TYPES if all(s(p) > 0 for p in types[t])), "")
        one = s(det - L ** 3) == 0 if pair == "complex" else s(d) == 0 or s(minus) == 0
        out.append(PointOrbit(k, lam_, exists, feasible, kind, pair, _modulus(cp, lam_), failed, one))
    return out


def _modulus(cp: flint.fmpq_poly, lam_, prec: int = 128):
    """max(|λ/λ_y|, |λ/λ_z|) as an arb ball: λ_y, λ_z the roots of cp(Λ)/(Λ - λ) =
    Λ² + (a + λ)Λ + (b + λ(a + λ)), in ball arithmetic at ``prec`` bits."""
    x = flint.acb(lam_.arb(prec))
    a, b = flint.acb(flint.arb(cp[2])), flint.acb(flint.arb(cp[1]))
    p = a + x
    q = b + x * p
    root = (p * p - 4 * q).sqrt()
    ys = ((-p + root) / 2, (-p - root) / 2)
    return max((abs(x / y) for y in ys), key=lambda m: m.mid())
