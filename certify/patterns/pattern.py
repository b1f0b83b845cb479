"""``certify pattern WORD``: the exact analysis of one periodic collision word.

For the normal form of the word (:mod:`.periodic`) in its system (four particles,
three particles, or the symmetric system [ac]b, :mod:`certify.dynamics.systems`) we
build the self-similar candidate (M_w, cp(M_w), q(0) an eigenvector, for four particles
p(0) = (1, 0, x) with x a fixed point x± of the position map f) and certify, per real
eigenvalue branch and fixed point, three nested subsets of ]lo, hi[ ⊆ ]0, 1[:

1. *exists*: self-similar data exist: λ > 0 (the velocities come back as a positive
   multiple), the eigenvector has the right signs (q(0) = (-1, u, …) with u = q_2(0) > 0:
   pair 1 approaches, pair 2 separates right after the b that ends the period), and,
   for four particles, x real and x > 0 (a positive fixed point of f);
2. *feasible*: moreover every collision of the period is the true next collision
   (:func:`.feasibility.prefix_requirements` with m = the length of the word: the pair
   approaches, its gap is open, every other gap stays open, hence no other pair touches
   first and there is no triple collision);
3. *stable*: moreover λ is strictly dominant, |μ| < λ for every other eigenvalue μ,
   real or complex (:func:`dominance_requirements`), and, for four particles, the
   fixed point attracts, |f'(x)| < 1 (:func:`stability_conditions`).

Every condition is a sign of a function of (r, λ[, x]) on a branch, certified over whole
r-intervals by :class:`.feasibility.Analysis` (critical values from resultants and
discriminants, one exact sample per cell, signs by balls, exact zero tests at critical
values).  Every end point is an algebraic number (minimal polynomial, isolating interval,
digits).  When nothing is feasible, the first collision that goes wrong is named, with
the collision that happens instead (:func:`diagnose`).  Nothing about a particular word
is written here: the paper's numbers are in the certificates and tests only.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import cached_property
from math import gcd
from pathlib import Path
from typing import NamedTuple

import flint
import sympy as sp
from sympy.polys.fields import FracElement
from sympy.polys.rings import PolyElement

from certify.algebra import printing
from certify.algebra.algebraic import Algebraic
from certify.algebra.branches import BRANCH_NAMES, X_MINUS, X_PLUS
from certify.algebra.poly import (
    FIELD,
    RING,
    Lf,
    Q,
    lr_to_ring,
    mpoly_to_univariate,
    notation,
    ring_to_lrq,
    show,
    show_collected,
    show_factored,
    to_field,
    to_ring,
)
from certify.dynamics.model import factor_lr
from certify.dynamics.systems import BY_NAME, candidate_in, run_in
from certify.errors import UsageError

from . import family
from .feasibility import NO_X, Analysis, Region, Requirement, prefix_requirements
from .periodic import compact, read
from .periodic import show as show_word

SCHEMA_PATH = Path(__file__).with_name("pattern.schema.json")
SCHEMA_VERSION = 1


# ------------------------------------------------------------------ stability
def dominance_requirements(cp) -> list[Requirement]:
    """λ (a real branch, λ > 0 imposed separately) strictly dominant: |μ| < λ for
    every other root μ of cp, real or complex.

    Let n = deg cp ∈ {2, 3} and Q(Λ) = cp(Λ)/(Λ - λ), monic of degree n - 1 with real
    coefficients (λ is real), whose roots are the other eigenvalues.  Scaling Λ = λz,
    the roots of Q lie in the open disc |Λ| < λ iff those of Q(λz)/λ^(n-1) lie in the
    open unit disc; for a real monic z + q0 (n = 2) this is |q0| < 1, for a real monic
    z² + p z + q (n = 3) it is the Schur-Cohn-Jury criterion |q| < 1 and |p| < 1 + q.
    In terms of cp, with Q(λ) = cp'(λ) (differentiate cp = (Λ - λ)Q at Λ = λ) and
    Q(-λ) = cp(-λ)/(-2λ):

    * n = 2: Q(Λ) = Λ - μ, |μ| < λ iff Q(λ) > 0 and Q(-λ) < 0, i.e. cp'(λ) > 0 and
      cp(-λ) > 0;
    * n = 3: Q(λ) = λ² + pλ + q > 0 and Q(-λ) = λ² - pλ + q > 0 (i.e. |p|λ < λ² + q)
      and q < λ² (with q > -λ² implied by the two); q = μν = det M/λ, so with λ > 0:
      cp'(λ) > 0, -cp(-λ) > 0 and λ³ - det M > 0 (det M = -cp(0)).

    * n = 4 (five particles, issue 39): Q(Λ) = Λ³ + AΛ² + BΛ + C (A, B, C polynomials in
      (r, λ): the quotient of cp by Λ - λ) and z³ + a z² + b z + c = Q(λz)/λ³ with a = A/λ,
      b = B/λ², c = C/λ³; Jury's criterion for a real cubic, Q(λ) > 0, -Q(-λ) > 0, |c| < 1 and
      1 - c² > |ca - b|, where the last implies |c| < 1 (1 - c² > |ca - b| ≥ 0); times positive
      powers of λ: cp'(λ) > 0, cp(-λ) > 0 and λ⁶ - C² ∓ (CAλ² - Bλ⁴) > 0.

    All strict, so a double eigenvalue λ = μ (Q(λ) = 0) is not dominant.  These are
    polynomials in (r, λ), certified on the branch like any other condition."""
    C = to_ring(cp)                                   # in the engine's ring: no SymPy expression
    L = RING.gens[0]
    n = C.degree(L)
    d = C.diff(L)
    minus = RING.from_dict({(e[0],) + e[1:]: (-c if e[0] % 2 else c) for e, c in C.terms()})   # cp(-λ)
    if n == 2:
        out = [("cp'(λ)", d), ("cp(-λ)", minus)]
    elif n == 3:
        det = -C.coeff_wrt(L, 0)
        out = [("cp'(λ)", d), ("-cp(-λ)", -minus), ("λ³ - det M", L ** 3 - det)]
    elif n == 4:
        A, B, C3 = quotient_by_root(C, L)
        mixed = C3 * A * L ** 2 - B * L ** 4
        out = [("cp'(λ)", d), ("cp(-λ)", minus), ("λ⁶ - C² - (CAλ² - Bλ⁴)", L ** 6 - C3 ** 2 - mixed),
               ("λ⁶ - C² + (CAλ² - Bλ⁴)", L ** 6 - C3 ** 2 + mixed)]
    else:
        raise ValueError(f"dominance is implemented for 2x2, 3x3 and 4x4 matrices, not degree {n}")
    return [Requirement(f"dominance: {name}", (to_field(e), FIELD.zero), 1) for name, e in out]


def quotient_by_root(C, L) -> tuple:
    """(A, B, C) with cp(Λ) = (Λ - λ)(Λ³ + AΛ² + BΛ + C) for a quartic cp monic in λ, as
    polynomials in (r, λ) of the engine's ring (synthetic division by Λ - λ: A = c₁ + λ,
    B = c₂ + λA, C = c₃ + λB for cp = Λ⁴ + c₁Λ³ + c₂Λ² + c₃Λ + c₄)."""
    c = [C.coeff_wrt(L, 4 - k) for k in range(5)]
    if c[0] != 1:
        raise ValueError("cp must be monic in λ")
    A = c[1] + L
    B = c[2] + L * A
    return A, B, c[3] + L * B


def stability_conditions(abcd) -> list[Requirement]:
    """|f'(x)| < 1 at a fixed point x of f(x) = (ax + b)/(cx + d): f'(x) = (ad - bc)/(cx + d)²,
    so the two conditions (cx + d)² - (ad - bc) > 0 and (cx + d)² + (ad - bc) > 0.
    At a fixed point c x² = (a - d) x + b, hence (cx + d)² = c(a + d) x + bc + d²,
    affine in x: the conditions are requirements G₀ + x G₁ > 0 like the others.
    A common factor of a, b, c, d (of either sign) leaves f' unchanged."""
    if all(isinstance(e, PolyElement) for e in abcd):    # polynomials: the products by python-flint
        a, b, c, d = (ring_to_lrq(e) for e in abcd)
        parts = [(sg, b * c + d * d + sg * (a * d - b * c), c * (a + d)) for sg in (-1, 1)]
        parts = [(sg, FIELD(lr_to_ring(G0)), FIELD(lr_to_ring(G1))) for sg, G0, G1 in parts]
    else:
        a, b, c, d = (to_field(e) for e in abcd)
        parts = [(sg, b * c + d * d + sg * (a * d - b * c), c * (a + d)) for sg in (-1, 1)]
    names = {-1: "(cx+d)² - (ad-bc)", 1: "(cx+d)² + (ad-bc)"}
    return [Requirement(f"attracting: {names[sg]}", (G0, G1), 1) for sg, G0, G1 in parts]


# ------------------------------------------------------------------ results
def end_data(a: Algebraic) -> dict:
    """An end point: exact value (rational) or minimal polynomial, an isolating interval
    with decimal ends, and 12 certified significant digits."""
    if a.is_rational:
        return {"exact": str(a.lo), "minimal_polynomial": show(a.minimal_polynomial()),
                "interval": [str(a.lo), str(a.lo)], "digits": a.digits(12)}
    text = a.describe()            # "the root of P in ]lo, hi[ ≈ digits"
    inner = text[text.index("]") + 1:text.index("[")]
    lo, hi = (t.strip() for t in inner.split(","))
    return {"exact": None, "minimal_polynomial": show(a.minimal_polynomial()), "interval": [lo, hi],
            "digits": a.digits(12)}


def algebraic_ends(sets) -> dict:
    """The irrational end points of the pieces of ``sets`` (r-sets in the JSON form), by
    their decimal digits: what the Markdown lists under "End points"."""
    ends = {}
    for s in sets:
        for p in s["pieces"]:
            for e in ([p["lo"], p["hi"]] if p["kind"] == "interval" else [p["at"]]):
                if e["exact"] is None:
                    ends[e["digits"]] = e
    return ends


def _poly(a: Algebraic):
    c = [int(x) for x in a.minimal_polynomial().coeffs()]
    rr = sp.Symbol("r")
    return sp.Add(*[ci * rr ** i for i, ci in enumerate(c)])


def _short(a: Algebraic) -> str:
    return str(a.lo) if a.is_rational else "≈" + a.digits(10)


def region_set(R: Region) -> dict:
    """The pieces of a region as JSON: merged intervals ]lo, hi[ and isolated points."""
    spans, points = R.merged()
    pieces = [{"kind": "interval", "lo": end_data(a), "hi": end_data(b)} for a, b in spans]
    pieces += [{"kind": "point", "at": end_data(q.lo), "note": q.note} for q in sorted(points, key=lambda q: q.lo)]
    text = " ∪ ".join([f"]{_short(a)}, {_short(b)}[" for a, b in spans]
                      + ["{" + _short(q.lo) + "}" + (f" ({q.note})" if q.note else "") for q in points]) or "∅"
    return {"branch": BRANCH_NAMES[R.branch] if R.branch < len(BRANCH_NAMES) else f"λ{R.branch}",
            "fixed_point": R.fixed_point, "set": text, "pieces": pieces}


def _copy(regions) -> list[Region]:
    return [Region(R.branch, R.fixed_point, list(R.pieces), list(R.undecided), list(R.dropped)) for R in regions]


STAGES = ("exists", "feasible", "stable")     # the stages of an analysis, each set inside the one before


def check_stage(stage: str) -> None:
    """ValueError naming the stages when ``stage`` is none of them."""
    if stage not in STAGES:
        raise ValueError(f"stage must be one of {', '.join(map(repr, STAGES))}, not {stage!r}")


class Window(NamedTuple):
    """A maximal open interval ]lo, hi[ of r in one stage's set (exists, feasible or stable), on
    one eigenvalue branch (0, 1, 2: :data:`BRANCH_NAMES`) with the fixed point x₊ or x₋: certified,
    with exact algebraic ends.  A tuple (branch, fixed point, lo, hi); a notebook shows it in LaTeX."""

    branch: int
    fixed_point: str
    lo: Algebraic
    hi: Algebraic

    @property
    def branch_name(self) -> str:
        return BRANCH_NAMES[self.branch] if self.branch < len(BRANCH_NAMES) else f"λ{self.branch}"

    def latex(self) -> str:
        """r ∈ ]r₁, r₂[ with its branch and fixed point, then the ends as :meth:`Algebraic.latex`,
        one a line (a LaTeX ``aligned`` block)."""
        point = self.fixed_point.replace("x₊", "x_+").replace("x₋", "x_-")
        return (f"\\begin{{aligned}} & r \\in \\left]r_1, r_2\\right[ \\quad "
                f"\\text{{({self.branch_name} branch, }} {point}\\text{{)}} \\\\ "
                f"& r_1 = {self.lo.latex()} \\\\ & r_2 = {self.hi.latex()} \\end{{aligned}}")

    def _repr_latex_(self) -> str:
        """A notebook shows the window as :meth:`latex`."""
        return f"$${self.latex()}$$"

    def _repr_markdown_(self) -> str:
        """A notebook's Markdown: the window, then its ends one an item."""
        return (f"$r \\in \\left]r_1, r_2\\right[$ ({self.branch_name} branch, {self.fixed_point}):\n\n"
                f"- $r_1 = {self.lo.latex()}$\n- $r_2 = {self.hi.latex()}$")


@dataclass
class PatternResult:
    """The analysis of one word; ``to_json()`` follows pattern.schema.json."""

    input: str
    normal: str                       # internal letters (s for [ac])
    system: str
    explanation: str
    interval: tuple
    cp_text: object                   # cp printed, or () -> that text (printed when first read)
    exists: list                      # [{branch, fixed_point, set, pieces}], non-empty sets only
    feasible: list
    stable: list
    undecided: list                   # [str]
    conditions: dict                  # stage -> [condition text]
    diagnosis: dict | None
    verdict: str
    seconds: float = 0.0
    regions: dict = field(default_factory=dict, repr=False)   # stage -> [Region] (for certificates)
    formulas: object = field(default=None, repr=False)      # () -> (matrix, discriminant, datum), or None
    data: list = field(default_factory=list, repr=False)    # the data found at multiple eigenvalues (kernel witnesses)

    @cached_property
    def _printed(self) -> tuple:
        """What only a reader needs, computed when first read: the period matrix, the
        factored discriminant and the datum's formulas (empty without ``formulas``)."""
        return self.formulas() if self.formulas is not None else ([], "", {})

    @property
    def cp(self) -> str:
        """cp(M_w) as printed (collected in λ), computed when first read."""
        if callable(self.cp_text):
            self.cp_text = self.cp_text()
        return self.cp_text

    @property
    def matrix(self) -> list:
        return self._printed[0]

    @property
    def discriminant(self) -> str:
        return self._printed[1]

    @property
    def datum(self) -> dict:
        """The formulas of u, v, x."""
        return self._printed[2]

    def intervals(self, stage: str, branch: int | None = None) -> list[Window]:
        """A :class:`Window` (branch, fixed point, lo, hi) for each maximal open interval of the
        stage's set, on every branch or on ``branch`` (ValueError for another stage or branch)."""
        return [Window(R.branch, R.fixed_point, lo, hi) for R in self._regions(stage, branch)
                for lo, hi in R.merged()[0]]

    def points(self, stage: str, branch: int | None = None) -> list[tuple[int, str, Algebraic]]:
        """(branch, fixed point, r) for each isolated point of the stage's set (as :meth:`intervals`)."""
        return [(R.branch, R.fixed_point, q.lo) for R in self._regions(stage, branch) for q in R.merged()[1]]

    def _regions(self, stage: str, branch: int | None) -> list[Region]:
        """The regions of ``stage`` on ``branch`` (every branch when None); ValueError naming the
        allowed values for anything else (a branch given by name, a stage misspelt)."""
        check_stage(stage)
        known = sorted(set(range(len(BRANCH_NAMES))) | {R.branch for Rs in self.regions.values() for R in Rs})
        if branch is not None and (isinstance(branch, bool) or not isinstance(branch, int) or branch not in known):
            named = ", ".join(f"{k} ({BRANCH_NAMES[k] if k < len(BRANCH_NAMES) else f'λ{k}'})" for k in known)
            raise ValueError(f"branch must be None (every branch) or one of {named}, not {branch!r}")
        return [R for R in self.regions[stage] if branch is None or R.branch == branch]

    def _repr_markdown_(self) -> str:
        """A notebook shows the analysis as ``certify pattern`` prints it (:meth:`markdown`)."""
        return self.markdown()

    @property
    def written(self) -> str:
        return show_word(self.normal)

    def to_json(self) -> dict:
        return {"schema": "certify-pattern", "version": SCHEMA_VERSION, "input": self.input,
                "normal_form": self.written, "compact": compact(self.normal), "system": self.system,
                "explanation": self.explanation,
                "r_range": [str(self.interval[0]), str(self.interval[1])],
                "matrix": self.matrix, "characteristic_polynomial": self.cp, "discriminant": self.discriminant,
                "conditions": self.conditions, "exists": self.exists, "feasible": self.feasible,
                "stable": self.stable, "undecided": self.undecided, "datum": self.datum,
                "diagnosis": self.diagnosis, "verdict": self.verdict}

    def json_text(self) -> str:
        return json.dumps(self.to_json(), ensure_ascii=False, indent=2, sort_keys=True)

    def fixed_point_name(self, name: str) -> str:
        """``x₋ (the paper's x₊)`` where the paper prints (a, b, c, d) for this word times a
        negative constant (:data:`PAPER_NORMALISATION`), else ``name``."""
        if self.normal not in PAPER_NORMALISATION or name not in SWAP:
            return name
        return f"{name} (the paper's {SWAP[name]})"

    def markdown(self) -> str:
        lo, hi = self.interval
        out = [f"# Pattern {self.written}", "",
               f"- input: `{self.input}`; normal form analysed: `{self.written}` (= `{compact(self.normal)}`), "
               f"{self.system} system", f"- same orbit: {self.explanation}", f"- r in ]{lo}, {hi}[", "",
               "## Period matrix", "",
               "M = `[" + ", ".join("[" + ", ".join(row) + "]" for row in self.matrix) + "]`", "",
               f"cp(M) = `{self.cp}`", "",
               f"disc_λ cp(M) = `{self.discriminant}`", ""]
        for stage, title in (("exists", "Self-similar data exist"), ("feasible", "Feasible (every collision is the "
                                                                                 "true next one)"),
                             ("stable", "Stable (λ dominant, fixed point attracting)")):
            out += [f"## {title}", "", "Conditions: " + "; ".join(self.conditions[stage]), ""]
            sets = getattr(self, stage)
            if not sets:
                out += ["∅ on every branch.", ""]
            for s in sets:
                fp = "" if s["fixed_point"] == NO_X else f", {self.fixed_point_name(s['fixed_point'])}"
                out.append(f"- {s['branch']} branch{fp}: {s['set']}")
            ends = algebraic_ends(sets)
            if ends:
                out += ["", "End points:"]
                out += [f"  - {k}: the root of `{e['minimal_polynomial']}` in ]{e['interval'][0]}, "
                        f"{e['interval'][1]}[" for k, e in sorted(ends.items())]
            out.append("")
        if self.undecided:
            out += ["## Undecided", ""] + [f"- {u}" for u in self.undecided] + [""]
        out += ["## The datum", ""] + [f"- {k} = `{v}`" for k, v in self.datum.items()] + [""]
        if self.normal in PAPER_NORMALISATION:
            out += [PAPER_NORMALISATION[self.normal], ""]
        if self.diagnosis:
            out += ["## First collision that goes wrong", "", self.diagnosis["text"], ""]
        out += ["## Verdict", "", self.verdict, ""]
        return "\n".join(out)


# Words whose a, b, c, d the paper prints, in another normalisation.  x± = (a - d ± √Δ)/(2c)
# swap under a common negative factor, so the names are shown both ways.
SWAP = {X_PLUS: X_MINUS, X_MINUS: X_PLUS}
PAPER_NORMALISATION = {
    "ababcb": "Names: a, b, c, d above are the paper's (Theorem 3.1, l. 373-379) divided by −1024 (certificate T10), "
              "a negative factor, which swaps x₊ and x₋: this x₋ is the paper's x₊, the fixed point of the theorem.",
}


# ------------------------------------------------------------------ the analysis
def _rational(value, what: str) -> flint.fmpq:
    try:
        from fractions import Fraction
        f = Fraction(str(value))
    except (ValueError, ZeroDivisionError):
        raise UsageError(f"--r-range: {what} {value!r} is not a rational number") from None
    return Q(f.numerator, f.denominator)


def check_range(lo, hi) -> tuple:
    lo, hi = _rational(lo, "LO"), _rational(hi, "HI")
    if not (0 <= lo < hi <= 1):
        raise UsageError(f"--r-range: need 0 ≤ LO < HI ≤ 1, not {lo}, {hi}")
    return lo, hi


def _cap(text: str, n: int = 4000) -> str:
    return text if len(text) <= n else text[:n] + f" … ({len(text)} characters)"


def _nonempty(regions) -> list[dict]:
    return [region_set(R) for R in regions if R.pieces]


def known_factors(*words: str) -> list[list[int]]:
    """The irreducible factors (integer coefficients, lowest degree first) that the sign tables of
    each word's candidate met (its Spectrum's), the analysis run first where the word caches were
    reset: a witness for the kernel (certify_kernel/pattern.py divides its own cut polynomials by
    those that divide them exactly, so that their roots are roots of small polynomials)."""
    found: set = set()
    for word in words:
        normal, system, _ = read(word)
        spec = candidate_in(system, normal).spectrum
        if not spec.known_factors():        # the word caches were reset (a census): find them again
            analyse(word)
            spec = candidate_in(system, normal).spectrum
        found |= {tuple(int(c) for c in f.coeffs()) for f in spec.known_factors()}
    return [list(f) for f in sorted(found)]


def analyse(word: str, lo=0, hi=1, formulas: bool = True, diagnosis: bool = True, progress=None,
            eigenspace: bool = True) -> PatternResult:
    """The exact analysis of a written period (any rotation / mirror) over ]lo, hi[.

    ``formulas=False`` (the census) skips what only the report prints: the period
    matrix, the factored discriminant and the datum's formulas (left empty); the
    certified sets, the undecided points, the diagnosis and the verdict are the same.
    With ``formulas`` they are computed when first read.  ``diagnosis=False`` (the
    physics line of ``certify orbit``, which reads only the certified sets) skips the
    search for the collision that comes instead where the word is never feasible
    (``diagnosis`` None, the verdict without it); the certified sets are the same.
    ``progress(k, n, label)`` (a :class:`certify.run.progress.Bar`): k of the n steps done (existence,
    each collision's conditions, stability; the family route decides feasibility at once), from 0.
    ``eigenspace=False`` (L4-L6, which read only the stable sets of (ab)^n(cb)^n) does not run the eigenspace
    route (:mod:`.eigenspace`, slow on long words): its points stay undecided for existence and
    feasibility; the stable sets are the same, as no point of a multiple eigenvalue is stable (strict
    dominance fails there, exactly)."""
    import time
    start = time.perf_counter()
    diagnose_failure = diagnosis
    lo, hi = check_range(lo, hi)
    normal, system_name, why = read(word)
    tick = progress or (lambda k, n, label="": None)
    total = len(normal) + 2                          # existence, each collision's conditions, stability
    tick(0, total, "")
    system = BY_NAME[system_name]
    cand = candidate_in(system_name, normal)
    an = Analysis(cand, lo, hi, eigenspace)
    n = len(normal)
    reqs, steps = prefix_requirements(normal, n, cand.q0, cand.steps, cand.q0_other, system=system)
    lam_req = Requirement("λ", (FIELD(Lf), FIELD.zero), 1)
    first = [lam_req] + [q for q in reqs if q.name in ("u = q_2(0)", "x")]
    conditions = {"exists": [_cond(q) for q in first] + (["x real"] if system.gaps == 3 else [])}
    for q in first:
        an.impose(q)
    regions = {"exists": _copy(an.regions)}
    an.settle_by_word()             # points of existence undecided where no datum can realise the word
    tick(1, total, "exists")
    # feasibility, collision by collision: the first one that empties every region is named
    seen = {q.name for q in first}
    groups = []
    for m in range(1, n + 1):
        rm, _ = prefix_requirements(normal, m, cand.q0, cand.steps, cand.q0_other, system=system)
        new = [q for q in rm if q.name not in seen]
        seen |= {q.name for q in new}
        groups.append(new)
    conditions["feasible"] = [_cond(q) for g in groups for q in g]
    diagnosis, before = None, _copy(an.regions)
    k = family.family_n(normal) if system_name == "four" else None
    if k is not None and k >= 2 and _family_feasible(an, groups, k):
        groups = []                 # (ab)^n(cb)^n: the feasible set, from the equivalent reduced conditions
    for m, group in enumerate(groups, 1):
        # the same set whatever the order: those without x first (cheap, no √Δ), so
        # that the regions shrink before the tables with x (norms of twice the degree)
        for q in sorted(group, key=lambda q: q.has_x):
            an.impose(q)
        if diagnose_failure and any(R.pieces for R in before) and not any(R.pieces for R in an.regions) \
                and diagnosis is None:
            diagnosis = diagnose(system, cand, normal, m, before, lo, hi)
        before = _copy(an.regions)
        tick(1 + m, total, f"collision {m} of {len(groups)}")
    regions["feasible"] = _copy(an.regions)
    data = an.feasible_data()
    stab = dominance_requirements(cand.spectrum.ring_cp)
    if cand.abcd is not None:
        stab = stab + stability_conditions(cand.abcd_ring or cand.abcd)
    conditions["stable"] = [_cond(q) for q in stab]
    for q in stab:
        an.impose(q)
    tick(total, total, "stable")
    regions["stable"] = _copy(an.regions)
    undecided = sorted({f"{BRANCH_NAMES[R.branch]} {R.fixed_point} at {_short(rc)}: {why_}"
                        for R in an.regions for rc, why_ in R.undecided})
    def printed():
        M = [[show_factored(e) for e in row] for row in cand.Mq]          # = show(factor_flint(e)), cand.M's entries
        return M, show_factored(discriminant(cand.spectrum)), datum(cand)
    res = PatternResult(word, normal, system_name, why, (lo, hi), lambda: show_collected(cand.spectrum.ring_cp, "λ"),
                        _nonempty(regions["exists"]), _nonempty(regions["feasible"]), _nonempty(regions["stable"]),
                        undecided, conditions, diagnosis, "", 0.0, regions, printed if formulas else None, data)
    res.verdict = verdict(res)
    res.seconds = time.perf_counter() - start
    return res


def _family_feasible(an: Analysis, groups: list, n: int) -> bool:
    """The feasible set of (ab)^n(cb)^n, n ≥ 2: the r < ρ_{n−1} (:func:`.family.turning_bound`)
    where the reduced conditions hold (:func:`.family.reduced_names`, imposed in the order of the
    collisions), the same set as all the conditions (the quadrant proposition, proved there).
    True when some r is left; else ``an`` is restored and the generic route names the collision
    that goes wrong."""
    saved = _copy(an.regions)
    rho = family.turning_bound(n - 1)
    if rho is not None:
        family.cut_below(an.regions, rho)
    keep = family.reduced_names(n)
    for group in groups:
        for q in sorted((q for q in group if q.name in keep), key=lambda q: q.has_x):
            an.impose(q)
    if any(R.pieces for R in an.regions):
        return True
    an.regions = saved
    return False


def discriminant(spec) -> flint.fmpq_poly:
    """disc_λ cp ∈ Q[r] (SymPy's ``discriminant(Poly(cp, λ))``, the same polynomial) by
    python-flint: the discriminant of the integer multiple den·cp held by the spectrum
    (den the lcm of cp's denominators), divided by den^(2n-2), n = deg_λ cp (the
    discriminant is homogeneous of degree 2n - 2 in the coefficients)."""
    den = 1
    for c in spec.ring_cp.values():
        den = den * int(c.denominator) // gcd(den, int(c.denominator))
    D = mpoly_to_univariate(spec.mpoly_cp.discriminant("lam"))
    return flint.fmpq_poly(D) / flint.fmpz(den) ** (2 * spec.degree - 2)


def _cond(q: Requirement) -> str:
    return f"{q.name} {'>' if q.sign > 0 else '<'} 0"


LONG = 3000          # a numerator or denominator of the datum printed longer than this is not factored


def _fraction_text(e) -> str:
    """``(num) / (den)``: SymPy's cancelled fraction of e, each side factored (sp.factor) when
    printed shorter than :data:`LONG`, else expanded; the SymPy route (the reference of
    :func:`_fraction_text_lr`, and for what is not a fraction in r, λ alone)."""
    e = e.as_expr() if hasattr(e, "as_expr") else e
    num, den = sp.fraction(sp.cancel(e))
    return (f"({show(factor_lr(num) if len(str(num)) < LONG else num)}) / "
            f"({show(factor_lr(den) if len(str(den)) < LONG else den)})")


def _fraction_text_lr(e: FracElement) -> str:
    """:func:`_fraction_text` of an element of Q(λ, r), the same text written from python-flint
    (the cancelled fraction, its factorisation and the lengths by :mod:`certify.algebra.printing`)."""
    sides = []
    for F, d in printing.sympy_fraction(e.numer, e.denom):
        names, terms = printing.mpoly_terms(F, d)
        short = len(printing.expanded(names, terms, order=None)) < LONG          # len(str(side))
        sides.append(notation(printing.factored_mpoly(F, d) if short else printing.expanded(names, terms)))
    return f"({sides[0]}) / ({sides[1]})"


def fraction_text(e) -> str:
    """The text of a formula of the datum: :func:`_fraction_text_lr` for an element of
    Q(λ, r), :func:`_fraction_text` (SymPy) for anything else."""
    if isinstance(e, FracElement):
        try:
            return _fraction_text_lr(e)
        except ValueError:                    # another variable than r, λ
            pass
    return _fraction_text(e)


def datum(cand) -> dict:
    """The formulas of the datum: u, v (q(0) = (-1, u, v)) and x± (four particles)."""
    fmt = lambda e: _cap(fraction_text(e))
    out = {"q(0)": "(-1, u" + (", v)" if len(cand.q0) == 3 else ")"), "u": fmt(cand.q0[1])}
    if len(cand.q0) == 3:
        out["v"] = fmt(cand.q0[2])
        out["p(0)"] = "(1, 0, x), x = x± = (a - d ± √((a-d)² + 4bc))/(2c), f(x) = (ax + b)/(cx + d)"
        for k, e in zip("abcd", cand.abcd_ring or cand.abcd):       # the same polynomials, the ring's printed directly
            out[k] = _cap(show(e))
    else:
        out["p(0)"] = "(1, 0)"
    return out


def verdict(res: PatternResult) -> str:
    w = res.written
    where = f"for r in ]{res.interval[0]}, {res.interval[1]}["
    if res.stable:
        s = "; ".join(f"{s['branch']}{'' if s['fixed_point'] == NO_X else ' ' + s['fixed_point']}: {s['set']}"
                      for s in res.stable)
        v = f"{w}: stable self-similar collapse {where} on {s}"
    elif res.feasible:
        v = f"{w}: feasible self-similar data, never stable {where}"
    elif res.exists:
        v = f"{w}: self-similar candidates exist but none is feasible {where}"
        if res.diagnosis:
            v += f" ({res.diagnosis['summary']})"
    else:
        v = f"{w}: no self-similar candidate (λ > 0, u > 0{', x > 0' if res.system == 'four' else ''}) {where}"
    if res.undecided:
        v += f"; {len(res.undecided)} point(s) undecided"
    return v


def diagnose(system, cand, word: str, m: int, regions, lo, hi) -> dict:
    """Where the candidate realises the first m - 1 collisions (``regions``) but never the
    m-th: which collision happens instead.  For each other letter j (not the gap that just
    closed), the region where j comes next, strictly before every other collision
    (the requirements of the prefix word[:m-1] + j, with the same previous collision)."""
    expected = word[m - 1]
    after = word[m - 2] if m > 1 else word[-1]
    found = []
    for j in sorted(set(system.index) - {after}):
        if j == expected:
            continue
        alt = word[:m - 1] + j
        steps = run_in(system, alt, cand.q0)
        reqs, _ = prefix_requirements(alt, m, cand.q0, steps, cand.q0_other, system=system, previous=word[-1])
        an = Analysis(cand, lo, hi)
        an.regions = _copy(regions)
        for q in sorted(reqs, key=lambda q: q.has_x):          # without x first (as in analyse)
            an.impose(q)
        live = _nonempty(an.regions)
        if live:
            found.append((j, live, an.regions))
    prefix = show_word(word[:m - 1])
    covered = all(_same(R, [S for _, _, rs in found for S in rs]) for R in regions if R.pieces)
    if found:
        parts = []
        for j, live, _ in found:
            where = "; ".join(f"{s['branch']}{'' if s['fixed_point'] == NO_X else ' ' + s['fixed_point']}: {s['set']}"
                              for s in live)
            parts.append(f"{show_word(j)} comes next, strictly before {show_word(expected)} and any other collision, "
                         f"on {where}")
        nexts = " or ".join(show_word(j) for j, _, _ in found)
        summary = (f"{f'after {prefix} ' if prefix else 'first '}comes {nexts}, "
                   f"strictly before {show_word(expected)}")
    else:
        parts = []
        summary = f"{f'after {prefix}, ' if prefix else ''}{show_word(expected)} is never the true next collision"
    realised = (f"realises {prefix} (collisions 1..{m - 1}) but never collision {m}" if m > 1
                else "never realises the first collision")
    tail = "" if covered else ("Elsewhere on the region of the prefix no single next collision is certified "
                               "(a tie, no approaching pair, or an undecided point).")
    text = " ".join(x for x in [f"The candidate {realised} ({show_word(expected)}).", *parts, tail] if x)
    return {"collision": m, "expected": show_word(expected), "prefix": show_word(word[:m - 1]),
            "instead": [{"letter": show_word(j), "where": live} for j, live, _ in found],
            "complete": covered, "summary": summary, "text": text}


def _same(R: Region, others) -> bool:
    """Whether the pieces of R are covered by the union of the matching regions' pieces."""
    theirs = [p for S in others if S.branch == R.branch and S.fixed_point == R.fixed_point for p in S.pieces]
    points = [q.lo for q in theirs if q.is_point]
    intervals = sorted((q for q in theirs if not q.is_point), key=lambda q: q.lo)

    def covered_point(a):
        return any(a == b for b in points) or any(q.lo < a < q.hi for q in intervals)
    for p in R.pieces:
        if p.is_point:
            if not covered_point(p.lo):
                return False
            continue
        pos, first = p.lo, True
        for q in intervals:
            if q.hi <= pos or q.lo >= p.hi:
                continue
            if q.lo > pos or (q.lo == pos and not first and not covered_point(pos)):
                return False
            pos, first = q.hi, False
            if pos >= p.hi:
                break
        if pos < p.hi:
            return False
    return True
