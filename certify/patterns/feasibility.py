"""Where does the self-similar candidate of a word realise it?  Exact regions of r.

A *requirement* is a condition g = G₀ + x G₁ (G₀, G₁ ∈ Q(λ, r), x the position fixed
point) with the strict sign it must have for the candidate to realise a prefix of
its word (:func:`prefix_requirements`).  :class:`Analysis` imposes requirements one
at a time and keeps, per real branch and fixed point x₊/x₋, the exact set of r
where all hold: open intervals with algebraic ends, and points.  Signs come from the
certified sign tables of :mod:`certify.algebra.branches`; at a critical value they are
decided by balls, or, where a quantity vanishes or has a pole, by the exact zero
test in Q(r_c)[λ]; where c = 0 the map f is affine and its fixed point b/(d - a) is
used.  Conditions are reduced modulo cp (monic in λ), which keeps their values on
every branch.
"""
from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy as sp

from certify import caches
from certify.algebra.algebraic import Algebraic
from certify.algebra.branches import (
    NO_BRANCH,
    X_MINUS,
    X_PLUS,
    Condition,
    Spectrum,
    less,
    same,
    simplest_between,
    strictly_between,
)
from certify.algebra.poly import (
    FIELD,
    Q,
    field_to_frac,
    frac_to_field,
    lam,
    ring_to_lrq,
    to_field,
    to_ring,
)
from certify.dynamics.systems import FOUR, System, run_in
from certify.dynamics.words import Candidate
from certify.errors import UNDECIDED

from .eigenspace import Eigenspace, Witness, decide_on_cells, polynomial_at

WORD_VELOCITIES = "no datum of the eigenspace (dimension {dim}) of the multiple eigenvalue meets the velocities' " \
    "requirements of the whole word (exact): none realises the word"
NO_X = "—"                   # the label of the only "fixed point" of a two-gap system (no x)
EIGENSPACE_NOTE = "a multiple eigenvalue: a datum of its eigenspace"


@dataclass
class Requirement:
    """A condition g = G0 + x G1 (G0, G1 in Q(r, λ)) and the strict sign it must have."""

    name: str
    G: tuple
    sign: int
    other: tuple = ()          # other representations of the same function on the branches

    @property
    def has_x(self) -> bool:
        return self.G[1] != FIELD.zero


def mod_cp(e, cp):
    """A polynomial in r, λ reduced modulo cp (monic in λ; an expression or, cheaper,
    an element of the engine's ring): the same values on every branch, λ-degree below
    deg cp."""
    return to_ring(e).rem(to_ring(cp))


@dataclass
class FixedPointData:
    """x = (a - d + σ√Δ)/(2c), Δ = (a - d)² + 4bc, all reduced modulo cp."""

    label: str
    sigma: int
    amd: object                 # polynomials of the engine's ring
    c: object
    delta: object
    b: object = None            # b modulo cp (the split of the numerator's norm, :func:`_norm_split`)


def fixed_point_data(abcd, cp) -> list[FixedPointData]:
    a, b, c, d = (to_ring(e) for e in abcd)
    amd = mod_cp(a - d, cp)
    delta = mod_cp((a - d) ** 2 + 4 * b * c, cp)
    cc = mod_cp(c, cp)
    bb = mod_cp(b, cp)
    return [FixedPointData(X_PLUS, 1, amd, cc, delta, bb), FixedPointData(X_MINUS, -1, amd, cc, delta, bb)]


def _norm_split(n0, d0, n1, d1, A, c, b, C) -> tuple:
    """((g, Q), (d₀, d₁)) with N₀² - N₁²Δ ≡ 4c·g²·Q and D₀ ≡ 2c·d₀d₁ modulo cp, for N₀ =
    2c n₀d₁ + A n₁d₀, N₁ = ±n₁d₀, D₀ = 2c d₀d₁ (:func:`condition`, A = a - d): with Δ = A² + 4bc,
    N₀² - N₁²Δ = 4c(c n₀²d₁² + A n₀n₁d₀d₁ - b n₁²d₀²), and with g = gcd(d₀, d₁), d₀ = g e₀,
    d₁ = g e₁, the bracket is g²(c n₀²e₁² + A n₀n₁e₀e₁ - b n₁²e₀²) = g²Q (fmpq_mpoly in (λ, r),
    reduced modulo cp).  The same for both fixed points (nothing depends on the sign of √Δ)."""
    g = d0.gcd(d1)
    e0, e1 = divmod(d0, g)[0], divmod(d1, g)[0]
    Q = c * n0 * n0 * e1 * e1 + A * n0 * n1 * e0 * e1 - b * n1 * n1 * e0 * e0
    return (divmod(g, C)[1], divmod(Q, C)[1]), (divmod(d0, C)[1], divmod(d1, C)[1])


# ring_to_lrq memoised by identity: a requirement's parts and a fixed point's a - d, b, c are
# converted once, not for every table and point (the flint polynomials are never changed in place)
_lrq = caches.by_identity(ring_to_lrq)


def condition(req: Requirement, cp, fp: FixedPointData | None = None, x_value=None) -> Condition:
    """The engine's Condition for g = G0 + x G1, numerator and denominator reduced
    modulo cp, x the fixed point ``fp`` (x = (A + σ√Δ)/(2c), A = a - d) or the
    rational function ``x_value``.  The products and remainders run on python-flint
    (fmpq_mpoly in λ, r): the same polynomials as in SymPy's ring."""
    C = cp if isinstance(cp, flint.fmpq_mpoly) else ring_to_lrq(to_ring(cp))
    G0, G1 = req.G
    n0, d0, n1, d1 = (_lrq(e) for e in (G0.numer, G0.denom, G1.numer, G1.denom))
    zero = n0 - n0
    delta = c = split = None
    if not req.has_x:
        N0, N1, D0 = n0, zero, d0
    elif x_value is not None:                               # x = X0/X1
        X = to_field(x_value)
        xn, xd = ring_to_lrq(X.numer), ring_to_lrq(X.denom)
        N0, N1, D0 = n0 * d1 * xd + n1 * d0 * xn, zero, d0 * d1 * xd
    else:                                                   # g = (n0 d1 + x n1 d0)/(d0 d1)
        assert fp is not None, "a condition with x needs its fixed point or x_value"
        A, cc = _lrq(fp.amd), _lrq(fp.c)
        N0, N1, D0 = 2 * cc * n0 * d1 + A * n1 * d0, fp.sigma * n1 * d0, 2 * cc * d0 * d1
        delta, c = fp.delta, fp.c
        if fp.b is not None and not n1.is_zero():
            split = _norm_split(n0, d0, n1, d1, A, cc, _lrq(fp.b), C)
    N0, N1, D0 = (divmod(e, C)[1] for e in (N0, N1, D0))
    return Condition(req.name, None, None, delta, c, lrq=(N0, N1, D0), split=split)


def _twin(cond: Condition, name: str) -> Condition:
    """The condition of the same requirement at the other fixed point (σ → -σ): the
    polynomials of :func:`condition` with N₁ negated (the products and remainders of N₀,
    σN₁, D₀ are linear in σ); the terms of N₀, D₀ and Δ shared, those of N₁ negated."""
    N0, N1, D0 = cond._lrq
    terms = dict(cond.terms, N1=[(-c, i, j) for c, i, j in cond.terms["N1"]])     # the terms of -N₁
    return Condition(name, None, None, cond.delta, cond.c, lrq=(N0, -N1, D0), terms=terms, split=cond.split)


def vanishes_on_branch(spec: Spectrum, g, rc: Algebraic, branch: int) -> bool:
    """Exact: the polynomial g(r, λ) (an expression or an element of the engine's ring)
    vanishes at r = rc on the real branch ``branch`` (the engine's gcd test in
    Q(rc)[λ]); False when it cannot be proven."""
    try:
        return spec.vanishes_at(g, rc, branch)
    except ArithmeticError:
        return False


@dataclass
class Piece:
    """An open interval ]lo, hi[ of r, or the single point lo (hi None).  At a point
    where f degenerates, ``x_value`` is the fixed point used there instead of x±."""

    lo: Algebraic
    hi: Algebraic | None = None
    x_value: sp.Expr | None = None
    note: str = ""
    eigenspace: bool = False       # decided on the eigenspace of a multiple eigenvalue (:mod:`.eigenspace`)

    @property
    def is_point(self) -> bool:
        return self.hi is None

    def __str__(self) -> str:
        if self.is_point:
            return "{" + fmt(self.lo) + "}" + (f" ({self.note})" if self.note else "")
        return f"]{fmt(self.lo)}, {fmt(self.hi)}["


@dataclass
class Region:
    """The set of r where every requirement imposed so far holds, for one real
    branch and one fixed point; ``undecided`` lists the points no test settled."""

    branch: int
    fixed_point: str
    pieces: list
    undecided: list
    dropped: list                  # (point, reason) settled exactly as failing

    def merged(self) -> tuple[list, list]:
        """The pieces as maximal open intervals [lo, hi] (]a, b[ ∪ {b} ∪ ]b, c[ is ]a, c[)
        and the remaining isolated points (Pieces)."""
        intervals = sorted((p for p in self.pieces if not p.is_point), key=lambda p: p.lo)
        points = [p for p in self.pieces if p.is_point]
        out = []
        for p in intervals:
            if out and out[-1][1] == p.lo:
                joint = [q for q in points if q.lo == p.lo and not q.note]
                if joint:
                    points.remove(joint[0])
                    out[-1][1] = p.hi
                    continue
            out.append([p.lo, p.hi])
        return out, points

    def describe(self) -> str:
        """The pieces, with ]a, b[ ∪ {b} ∪ ]b, c[ shown as ]a, c[."""
        spans, points = self.merged()
        parts = [str(Piece(a, b)) for a, b in spans] + [str(q) for q in points]
        return " ∪ ".join(parts) or "∅"


def fmt(a: Algebraic) -> str:
    """A short name for an end of an interval."""
    return str(a.lo) if a.is_rational else "≈" + a.digits(6)


def _meets(sg, want):
    """Whether the sign ``sg`` is the required ``want``: True, False, or UNDECIDED when
    ``sg`` is (:mod:`certify.errors`); no branch or x not real: False."""
    if sg == UNDECIDED:
        return UNDECIDED
    if sg in (None, NO_BRANCH):
        return False
    return sg == want


def sign_in_cell(T, branch: int, lo, hi):
    """The sign of table T on ``branch`` over ]lo, hi[, inside one cell of T."""
    signs = T.signs(branch, lo, hi, include_points=False)
    if len(signs) != 1:
        raise ArithmeticError(f"{T.condition}: signs {signs} on ]{lo}, {hi}[")
    return next(iter(signs))


def table_sign_at(T, rc: Algebraic, branch: int):
    """The sign of table T at rc on ``branch``: its point value when rc is one of
    T's critical values, else the sign of the cell holding rc."""
    for k, c in enumerate(T.critical):
        if same(c, rc):
            if not T.has_point(k) and T.source is not None:
                # the entry T.points[k] would hold on this branch, for this branch alone
                # (Spectrum.sign_on_branch_at; UNDECIDED where the branches are not isolated)
                spec, cond = T.source
                return spec.sign_on_branch_at(cond, rc, branch)
            pt = T.points[k]
            if pt is None:
                return UNDECIDED
            return pt[branch] if branch < len(pt) else NO_BRANCH
    for cell in T.cells:
        if strictly_between(cell.lo, rc, cell.hi):
            return cell.signs[branch] if branch < len(cell.signs) else NO_BRANCH
    raise ArithmeticError(f"{rc} outside the table of {T.condition}")


def _key(a):
    """A cache key of an end (a rational or an Algebraic), a function of its value."""
    return a.key() if isinstance(a, Algebraic) else ("Q", str(a))


def _hull(regions, lo0, hi0):
    """An interval ]L, H[ (rational or algebraic ends) containing every piece: an
    open end of a piece is used as it is, a point at an end is enclosed by a
    simple rational just outside it."""
    pieces = [p for R in regions for p in R.pieces]
    if not pieces:
        return None
    L = min(p.lo for p in pieces)
    H = max(p.lo if p.is_point else p.hi for p in pieces)
    eps = Q(1, 10 ** 4)
    if any(p.is_point and p.lo == L for p in pieces):
        L.refine(eps)
        top = L.lo if not L.is_rational else L.lo - eps / 2
        L = Algebraic.rational(simplest_between(max(Q(lo0), L.lo - eps), top))
    if any(p.is_point and p.lo == H for p in pieces):
        H.refine(eps)
        bottom = H.hi if not H.is_rational else H.hi + eps / 2
        H = Algebraic.rational(simplest_between(bottom, min(Q(hi0), H.hi + eps)))
    return (L.lo if L.is_rational else L), (H.lo if H.is_rational else H)


class Analysis:
    """Impose requirements one at a time on the candidate of a word and keep, per
    real branch and fixed point, the region of r where all hold (certified)."""

    def __init__(self, cand: Candidate, lo=0, hi=1, eigenspace: bool = True):
        self.cand, self.spec, self.lo, self.hi = cand, cand.spectrum, lo, hi
        # False: the eigenspace route is not run (its points stay undecided for existence and
        # feasibility); the stable sets are the same, as no point of a multiple eigenvalue is stable
        self.eigenspace_route = eigenspace
        # a two-gap system has no position variable: one pseudo fixed point "—", no condition uses x
        self.fps = {fp.label: fp for fp in fixed_point_data(cand.abcd_ring or cand.abcd, self.spec.ring_cp)} \
            if cand.abcd is not None else {NO_X: None}
        self.tables = {}
        self._twins: dict = {}          # id of a requirement with x -> (it, its first Condition, its x)
        self.imposed: list[Requirement] = []     # in the order imposed (the eigenspace route re-decides them)
        self._spaces: dict = {}         # r₀ -> Eigenspace or None
        self.data: dict = {}            # (r₀, branch, σ) -> the Witness that last met every requirement there
        base = self.spec.sign_table(Condition.of("λ", lam), lo, hi)
        nb = max(len(c.branches) for c in base.cells)
        self.regions = [Region(k, f, [], [], []) for k in range(nb) for f in self.fps]
        for R in self.regions:
            ends = [Algebraic.rational(lo)] + base.critical + [Algebraic.rational(hi)]
            for a, b in zip(ends, ends[1:]):
                if R.branch < len(next(c for c in base.cells if c.lo == a).branches):
                    R.pieces.append(Piece(a, b))
            for c, pt in zip(base.critical, base.points):
                if pt is None and self._eigenspace(c, R.branch) is not None:
                    R.pieces.append(Piece(c, note=EIGENSPACE_NOTE, eigenspace=True))
                elif pt is None:
                    R.undecided.append((c, "branches not isolated"))
                elif R.branch < len(pt):
                    R.pieces.append(Piece(c))
            R.pieces.sort(key=lambda p: p.lo)

    def table(self, req: Requirement, fname: str):
        """The sign table of a requirement over the hull of the current regions."""
        regions = [R for R in self.regions if R.fixed_point == fname or not req.has_x]
        hull = _hull(regions, self.lo, self.hi)
        if hull is None:
            return None
        key = (req.name, fname if req.has_x else "", tuple(_key(e) for e in hull))
        if key not in self.tables:
            twin = self._twins.get(id(req)) if req.has_x else None
            if twin is not None and twin[0] is req:
                # x₊ and x₋ differ only in the sign of N₁ (σ): N₀, D₀ and the norms N₀² - N₁²Δ,
                # D₀, Δ and c are the same polynomials, computed once for the requirement
                cond = _twin(twin[1], req.name) if twin[2] != fname else \
                    condition(req, self.spec.lrq_cp, self.fps[fname])
                cond.share_norms(twin[1])
            else:
                cond = condition(req, self.spec.lrq_cp, self.fps[fname] if req.has_x else None)
                if req.has_x:
                    self._twins[id(req)] = (req, cond, fname)
            self.tables[key] = self.spec.sign_table(cond, *hull)
        return self.tables[key]

    def impose(self, req: Requirement):
        """Keep only the r where req has its required sign."""
        tables = {f: self.table(req, f) for f in self.fps}       # over the hull before cutting
        for R in self.regions:
            if not R.pieces:
                continue
            T = tables[R.fixed_point]
            new = []
            for p, status, why in self._split(R, p_list=R.pieces, req=req, T=T):
                if status == "holds":
                    new.append(p)
                elif status == "undecided":
                    R.undecided.append((p.lo, why))
                elif p.is_point and why:
                    R.dropped.append((p.lo, why))
            R.pieces = sorted(new, key=lambda q: q.lo)
        self.imposed.append(req)

    def violations(self, req: Requirement) -> list[tuple[Region, Piece, str]]:
        """Where, in the current regions, req does not have its sign (or is undecided)."""
        bad = []
        tables = {f: self.table(req, f) for f in self.fps}
        for R in self.regions:
            if not R.pieces:
                continue
            T = tables[R.fixed_point]
            for p, status, why in self._split(R, R.pieces, req, T):
                if status != "holds":
                    bad.append((R, p, status + (f": {why}" if why else "")))
        return bad

    def _split(self, R: Region, p_list, req: Requirement, T):
        """Each piece cut at the critical values of T, with the status of req on each
        part: "holds", "fails" or "undecided" (and a reason at points)."""
        for p in p_list:
            if p.is_point:
                yield self._point(R, p, req, T)
                continue
            # exact comparisons, read off the isolating intervals first (branches.less)
            cuts = [c for c in T.critical if less(p.lo, c) and less(c, p.hi)]
            ends = [p.lo] + cuts + [p.hi]
            for a, b in zip(ends, ends[1:]):
                ok = _meets(sign_in_cell(T, R.branch, a, b), req.sign)
                # '?' on a whole cell: a degenerate condition (Spectrum._cell_sign)
                yield Piece(a, b), "undecided" if ok == UNDECIDED else "holds" if ok else "fails", \
                    f"{req.name}: undecided on a whole branch (a norm ≡ 0 there)" if ok == UNDECIDED else ""
            for c in cuts:
                yield self._point(R, Piece(c), req, T)

    # -- a single point: balls first, exact zero tests where balls cannot decide
    def _point(self, R: Region, p: Piece, req: Requirement, T):
        if p.eigenspace:
            return self._on_eigenspace(R, p, req) or (p, "undecided", f"{req.name} (no datum of the eigenspace found)")
        found = self._generic_point(R, p, req, T)
        if found[1] != "undecided" or p.x_value is not None:
            return found
        return self._on_eigenspace(R, Piece(p.lo, note=EIGENSPACE_NOTE, eigenspace=True), req) or found

    def _generic_point(self, R: Region, p: Piece, req: Requirement, T):
        rc, k = p.lo, R.branch
        with_x = p.x_value is not None and req.has_x
        sg = self._sign_with_x(req, rc, k, p.x_value) if with_x else \
            table_sign_at(T, rc, k)
        ok = _meets(sg, req.sign)
        if ok != UNDECIDED:
            return p, "holds" if ok else "fails", "" if ok else \
                f"{req.name} {'= 0' if sg == 0 else 'is not real' if sg is None else 'has the wrong sign'}"
        a, b, c, d = (self.cand.abcd_ring or self.cand.abcd) if self.cand.abcd is not None else (None,) * 4
        if req.has_x and p.x_value is None and vanishes_on_branch(self.spec, c, rc, k):
            xv = frac_to_field(field_to_frac(b) / field_to_frac(d - a))    # b/(d-a) in lowest terms
            if _meets(self._sign_with_x(Requirement("x", (FIELD.zero, FIELD.one), 1), rc, k, xv), 1) is True:
                return self._point(R, Piece(rc, None, xv, "c = 0: f affine, fixed point b/(d-a)"), req, T)
            return p, "fails", "c = 0 there (exact): f is affine, its fixed point b/(d-a) is not positive"
        if req.has_x and p.x_value is None:
            return self._other_rows_with_x(R, p, req)
        # g = N/D without √Δ: N = 0 (g = 0) or D = 0 (g undefined: a collision time or
        # the normalisation q_1(0) = -1 breaks down) both defeat a strict inequality;
        # N = D = 0 stays undecided.
        cond = self._condition_at_point(req, p, T)
        zero_n = vanishes_on_branch(self.spec, cond.N[0], rc, k)
        zero_d = vanishes_on_branch(self.spec, cond.D[0], rc, k)
        if zero_n != zero_d:
            return p, "fails", f"{req.name} {'vanishes' if zero_n else 'has a pole'} there (exact)"
        # 0/0: another representation of the same function, with a denominator not vanishing there
        for G in req.other:
            alt = Requirement(req.name, G, req.sign)
            cond = condition(alt, self.spec.lrq_cp, x_value=p.x_value if alt.has_x else None)
            if vanishes_on_branch(self.spec, cond.D[0], rc, k):
                continue
            if vanishes_on_branch(self.spec, cond.N[0], rc, k):
                return p, "fails", f"{req.name} vanishes there (exact, other rows of the eigen-equation)"
            ok = _meets(self._sign_on(cond, rc, k), req.sign)
            if ok != UNDECIDED:
                return p, "holds" if ok else "fails", "" if ok else \
                    f"{req.name} has the wrong sign (other rows of the eigen-equation)"
        return p, "undecided", req.name

    def _other_rows_with_x(self, R: Region, p: Piece, req: Requirement):
        """A requirement with x = x± at a point where its representation G₀ + xG₁ is 0/0 on the
        branch: its sign from another representation of the same function (q(0) from other rows
        of the eigen-equation, ``req.other``) whose denominator does not vanish there (exact), the
        same fixed point x±; "undecided" when none decides.  Sound: at a simple eigenvalue every
        representation is the same function of r near r₀, and one whose denominator is non-zero
        at r₀ gives its value there (continuity)."""
        k = R.branch
        if self._eigenspace(p.lo, k) is not None:
            return p, "undecided", req.name          # a multiple eigenvalue: its eigenspace decides
        for G in req.other:
            alt = Requirement(req.name, G, req.sign)
            cond = condition(alt, self.spec.lrq_cp, self.fps[R.fixed_point])
            if vanishes_on_branch(self.spec, cond.D[0], p.lo, k):
                continue
            ok = _meets(self._sign_on(cond, p.lo, k), req.sign)
            if ok != UNDECIDED:
                return p, "holds" if ok else "fails", "" if ok else \
                    f"{req.name} has the wrong sign (other rows of the eigen-equation)"
        return p, "undecided", req.name

    # -- a point where the branch's eigenvalue is multiple: the data of its eigenspace
    def _eigenspace(self, rc: Algebraic, branch: int) -> Eigenspace | None:
        """The eigenspace of λ_branch(r₀) when it is a multiple eigenvalue (exact in Q(r₀)),
        for a word of four particles; None otherwise."""
        if self.cand.abcd is None or len(self.cand.Mq) != 3:
            return None
        key = rc.key()
        if key not in self._spaces:
            es = Eigenspace(self.cand.word, self.cand.Mq, self.spec, rc)
            self._spaces[key] = es if es.ok else None
        es = self._spaces[key]
        if es is None:
            return None
        roots = self.spec.branches_at(rc)
        if roots is None:
            return es if es.multiplicity == 3 else None          # a triple root: every branch is λ₀
        return es if branch < len(roots) and es.contains(roots[branch]) else None

    def _on_eigenspace(self, R: Region, p: Piece, req: Requirement):
        """The status of req at the point p on the eigenspace route (:mod:`.eigenspace`): some
        datum of the eigenspace of the multiple eigenvalue λ₀ = λ_k(r₀) meets req and every
        requirement imposed before (one witness, certified signs; "holds"), none does (the
        linear ones cut an empty polyhedron, exact; or λ, dominance exact in Q(r₀): "fails"),
        or None (undecided, or λ_k(r₀) not a multiple eigenvalue, or the route not run)."""
        if not self.eigenspace_route:
            return None
        es = self._eigenspace(p.lo, R.branch)
        if es is None:
            return None
        if req.name == "λ" or req.name.startswith("dominance"):
            v = polynomial_at(req.G[0], es.F, es.lam0)
            if v is None:
                return None
            sg = v.sign()
            why = f"{req.name} {'= 0' if sg == 0 else 'has the wrong sign'} at the multiple eigenvalue (exact)"
            return (p, "holds", "") if sg == req.sign else (p, "fails", why)
        if es.q1_zero:
            return p, "fails", "q_1(0) = 0 on the whole eigenspace of the multiple eigenvalue (exact): a never comes"
        wanted = [q for q in self.imposed if q.name != "λ" and not q.name.startswith("dominance")] + [req]
        linear = [f for f in (es.linear(q.name, q.sign) for q in wanted) if f is not None]
        samples = es.polyhedron(linear)
        if samples is None:
            return p, "fails", f"{req.name}: no datum of the eigenspace (dimension {es.dim}) of the multiple " \
                "eigenvalue meets the velocities' requirements (exact)"
        sigma = -1 if R.fixed_point == X_MINUS else 1
        for s in samples:
            w = Witness(es, s, sigma)
            if all(w.value_sign(q.name) == q.sign for q in wanted):
                self.data[(p.lo.key(), R.branch, sigma)] = w
                return p, "holds", ""
        if es.dim == 2:
            status, w = decide_on_cells(es, wanted, sigma)
            if w is not None:
                self.data[(p.lo.key(), R.branch, sigma)] = w
            if status is not None:
                return p, status, "" if status == "holds" else f"{req.name}: no datum of the eigenspace (dimension " \
                    "2) of the multiple eigenvalue meets the requirements (exact cells of its line of data)"
        if req.name[:2] in ("q_", "p_") and es.realises_no_velocities():
            return p, "fails", WORD_VELOCITIES.format(dim=es.dim)       # else undecided: the whole word decides
        return None

    def feasible_data(self) -> list[dict]:
        """The data found at multiple eigenvalues that meet every requirement imposed so far
        (certified signs at the witness), in the kernel's witness form
        (:meth:`.eigenspace.Witness.kernel_form`)."""
        wanted = [q for q in self.imposed if q.name != "λ" and not q.name.startswith("dominance")]
        forms = [w.kernel_form() for w in self.data.values()
                 if w.x is not None and all(w.value_sign(q.name) == q.sign for q in wanted)]
        return [f for k, f in enumerate(forms) if f not in forms[:k]]

    def settle_by_word(self):
        """Move the points left undecided so far (by the requirements of existence: λ, u, x) at a
        multiple eigenvalue where no datum of the eigenspace meets the velocities' requirements of
        the whole word (exact, :meth:`.Eigenspace.realises_no_velocities`) to the dropped points: no
        datum there realises the word, so the point is in no feasible (or stable) set.  Whether data
        *exist* there (u, x > 0) stays undecided: the caller's copy of the regions before keeps it.
        Nothing is moved when the eigenspace route is not run."""
        if not self.eigenspace_route:
            return
        for R in self.regions:
            keep = []
            for rc, why in R.undecided:
                es = self._eigenspace(rc, R.branch)
                if es is not None and not es.q1_zero and es.realises_no_velocities():
                    R.dropped.append((rc, f"{why}; " + WORD_VELOCITIES.format(dim=es.dim)))
                else:
                    keep.append((rc, why))
            R.undecided = keep

    def _condition_at_point(self, req: Requirement, p: Piece, T):
        """The Condition of req at the point p: the table's own when req has no x (the same
        polynomials; unless marked degenerate, which a fresh one is not yet), else made afresh."""
        own = T.source[1] if T is not None and getattr(T, "source", None) else None
        if not req.has_x and own is not None and not own.degenerate:
            return own
        return condition(req, self.spec.lrq_cp, x_value=p.x_value if req.has_x else None)

    def _sign_with_x(self, req, rc, k, xv):
        return self._sign_on(condition(req, self.spec.lrq_cp, x_value=xv), rc, k)

    def _sign_on(self, cond, rc, k):
        """The sign of cond on branch k at rc (UNDECIDED where the branches are not isolated)."""
        return self.spec.sign_on_branch_at(cond, rc, k)
def prefix_requirements(word: str, m: int, q0, steps=None, q0_other=(), system: System = FOUR,
                        previous: str | None = None) -> tuple[list[Requirement], list]:
    """The candidate of ``word`` realises its first m collisions, strictly, iff

    * u = q_2(0) > 0 (p_2(0) = 0 right after the last b of the previous period), x > 0
      (four particles; a two-gap system has p(0) = (1, 0) and no x);
    * at each collision k the pair i_k approaches: q_{i_k}(t_{k-1}) < 0;
    * the gap i_k is open just before: p_{i_k}(t_{k-1}) > 0, so that τ_k > 0, except
      when it is automatic: k = 1 (p_1(0) = 1), or the pair collided at k - 2
      (p_{i_k}(t_{k-1}) = τ_{k-1} q_{i_k}(t_{k-2}) with q_{i_k}(t_{k-2}) > 0 after that
      collision);
    * every gap that does not collide at m is open at t_m (same exception for the gap
      that collided at m - 1).

    ``previous`` is the collision before t = 0 (default: the last letter of ``word``,
    the end of the previous period), ``system`` the law (four particles by default).

    Why this is enough: each collision of type b adds (1+r)/2 q_2 < 0 to q_1 and q_3,
    a collision a or c adds (1+r)/2 q_1 < 0 or (1+r)/2 q_3 < 0 to q_2 (and [ac] adds
    (1+r) q_1 < 0 to q_2 in the symmetric system), so every gap p_j(t) is concave
    between two consecutive collisions of its own pair (the slopes only decrease; all
    τ_k > 0 by the above).  A concave function positive at both ends of an interval
    (or zero at the left end with a positive slope there) is positive inside, so the
    gap is open at every intermediate collision and no other pair collides in between
    (the paper's argument of l. 478-480, for every gap); a gap strictly open at each
    collision also excludes a triple collision."""
    steps = steps[:m] if steps is not None and len(steps) >= m else run_in(system, word[:m], q0)
    reqs = [Requirement("u = q_2(0)", (q0[1], FIELD.zero), 1, tuple((q[1], FIELD.zero) for q in q0_other))]
    if system.gaps == 3:
        reqs.append(Requirement("x", (FIELD.zero, FIELD.one), 1))
    index = system.index
    letters = [index[previous or word[-1]]] + [index[c] for c in word[:m]]   # letters[k] = i_k
    others_1 = _first_positions(q0_other, system, word[0])
    for k in range(1, m + 1):
        i = letters[k]
        before = q0 if k == 1 else steps[k - 2].q
        if not _positive_constant(-before[i]):
            reqs.append(Requirement(f"q_{i + 1}(t_{k - 1})", (before[i], FIELD.zero), -1))
        automatic = k == 1 or letters[k - 2] == i
        if not automatic:
            other = tuple(p[i] for p in others_1) if k == 2 else ()
            reqs.append(Requirement(f"p_{i + 1}(t_{k - 1})", steps[k - 2].p[i], 1, other))
    for j in range(system.gaps):
        if j != letters[m] and j != letters[m - 1]:
            other = tuple(p[j] for p in others_1) if m == 1 else ()
            reqs.append(Requirement(f"p_{j + 1}(t_{m})", steps[m - 1].p[j], 1, other))
    return reqs, steps


# a memo per candidate's q0_other (the same list in every call for its word): {(system, letter): positions}
_per_candidate = caches.by_identity(lambda q0_other: {})


def _first_positions(q0_other, system: System, letter: str) -> list:
    """p(t_1) after the first collision ``letter`` from each q(0) of the other rows of the
    eigen-equation (where q0's own rows give 0/0), computed once per candidate and letter."""
    memo = _per_candidate(q0_other)
    key = (system.name, letter)
    if key not in memo:
        memo[key] = [run_in(system, letter, q)[0].p for q in q0_other if all(e is not None for e in q)]
    return memo[key]


def _positive_constant(e) -> bool:
    """e ∈ FIELD is a positive rational constant (read from its numerator and denominator)."""
    f = to_field(e)
    return f.numer.is_ground and f.denom.is_ground and bool(f.numer.LC * f.denom.LC > 0)


