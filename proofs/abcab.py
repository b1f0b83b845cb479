"""Remark after Theorem 3.1 (l. 513-515): the pattern abcab has no self-similar datum.

As printed: "for the initial data that are the obvious candidates - that is, the
eigenvector of the corresponding matrix BACBA for the velocities and a fixed point
for the distance map f for the positions - the collision after the first b
collision is a, not c (and these collisions do not take place at the same time, so
that the order really is a and then, after a strictly positive time, c)".

The candidate, with the paper's normalisation for a word that starts with a and
ends with b (l. 270-280): q(0) = (-1, u, v), an eigenvector of M_w = K_b K_a K_c K_b K_a
for a real eigenvalue λ (any real branch), and p(0) = (1, 0, x) with x a positive
fixed point of f(x) = p_3(t_5)/p_1(t_5) = (ax + b)/(cx + d).  The collisions a and
b are *assumed* (times defined by p_i(t_k) = 0) and then checked:

* the candidate exists and realises a, b as its first two collisions when
  x > 0, u = q_2(0) > 0 (p_2(0) = 0 after the last b), p_3(t_1) > 0 (a comes
  before c), q_2(t_1) < 0 and p_3(t_2) > 0 (then b, before c);
* the claim: q_1(t_2) < 0 (a comes next) and, at the time t_3 of that a,
  p_3(t_3) > 0, i.e. the a collision happens strictly before any c:
  p_3(t_3) = p_3(t_2) + τ_a q_3(t_2) = -q_3(t_2)(τ_c - τ_a) when q_3(t_2) < 0.

Each condition is a rational function of r, λ and x (x through x₊ or x₋); its sign
on each real eigenvalue branch is certified over whole r-intervals by
``Spectrum.sign_table`` (critical values from resultants and discriminants, one
exact sample per cell, balls with proven signs).  The tables are merged on the
common refinement of their critical values, and at each critical value the signs
are decided by ball arithmetic or, where a quantity vanishes there, by an exact
zero test (the resultant vanishes and every other root of cp is separated).

The helpers below (fast symbolic runs of a word over Q(r, λ), merged sign tables,
exact zero tests at critical values) are shared with ``proofs/literature.py``.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import flint
import sympy as sp

from certify.algebraic import Algebraic
from certify.branches import Condition, Spectrum
from certify.model import INDEX, collision_matrix
from certify.poly import lam, r, resultant_lambda, show, to_fmpz_poly, x
from certify.runner import Check, certificate, conclude

Q = flint.fmpq
K, _LAM, _R = sp.field([lam, r], sp.QQ, sp.lex)     # Q(λ, r); its ring Q[λ, r] is ordered lex λ > r
RING = K.ring
BRANCH_NAMES = ("upper", "middle", "lower")


# ---------------------------------------------------------------- symbolic candidate
@dataclass
class Candidate:
    """The self-similar candidate of a word w starting with a and ending with b.

    Rational functions of r and λ are kept with numerator and denominator reduced
    modulo cp (monic in λ): they take the same values on every eigenvalue branch."""

    word: str
    M: sp.Matrix                # M_w = K_{c_n} ... K_{c_1}
    cp: sp.Expr                 # det(λI - M_w)
    spectrum: Spectrum
    q0: tuple                   # (-1, u, v), elements of K
    abcd: tuple                 # (a, b, c, d) polynomials in r, λ: f(x) = (ax + b)/(cx + d)

    def fixed_points(self) -> dict[str, "FixedPointData"]:
        """x₊ = (a - d + √Δ)/(2c) and x₋ = (a - d - √Δ)/(2c), reduced modulo cp."""
        return {fp.label: fp for fp in fixed_point_data(self.abcd, self.cp)}

    def reducer(self) -> "Reducer":
        """Identity: reducing along a run spoils the cancellations of K (spurious
        factors in the resultants); conditions are reduced at the end instead."""
        return Reducer(None)


def expr_of(e) -> sp.Expr:
    """An element of K (or a pair P0 + x P1) back as a SymPy expression."""
    if isinstance(e, tuple):
        return e[0].as_expr() + x * e[1].as_expr()
    return e.as_expr()


class Reducer:
    """Reduction modulo cp of the numerator and the denominator of elements of K."""

    def __init__(self, cp_ring):
        self.cp = cp_ring

    def __call__(self, e):
        if self.cp is None:
            return e
        n, d = e.numer.rem(self.cp), e.denom.rem(self.cp)
        if d == 0:
            raise ZeroDivisionError("a denominator vanishes on every branch")
        return K.new(n, d)


def collide_k(letter: str, q: tuple) -> tuple:
    """K q over Q(r, λ)."""
    h = (1 + _R) / 2
    q1, q2, q3 = q
    return {"a": (-_R * q1, q2 + h * q1, q3),
            "b": (q1 + h * q2, -_R * q2, q3 + h * q2),
            "c": (q1, q2 + h * q3, -_R * q3)}[letter]


@dataclass
class SymbolicStep:
    """The state right after a collision: p_i = P0_i + x P1_i, q_i over Q(r, λ)."""

    letter: str
    p: list                    # [(P0, P1)] * 3
    q: tuple


def run_letters(letters: str, q0: tuple, reduce=None) -> list[SymbolicStep]:
    """From p(0) = (1, 0, x), q(0) = q0, apply the collisions in ``letters`` with
    times *defined* by p_i(t_k) = 0 (l. 460-463): positions stay affine in x."""
    red = reduce or (lambda e: e)
    p = [(K.one, K.zero), (K.zero, K.zero), (K.zero, K.one)]
    q = tuple(q0)
    out = []
    for letter in letters:
        i = INDEX[letter]
        if q[i] == K.zero:
            raise ZeroDivisionError(f"q_{i + 1} vanishes identically before {letter}")
        t = (-p[i][0] / q[i], -p[i][1] / q[i])
        p = [(red(P0 + t[0] * qj), red(P1 + t[1] * qj)) for (P0, P1), qj in zip(p, q)]
        p[i] = (K.zero, K.zero)
        q = tuple(red(e) for e in collide_k(letter, q))
        out.append(SymbolicStep(letter, p, q))
    return out


def word_matrix_k(word: str) -> list[list]:
    """M_w = K_{c_n} ... K_{c_1} with entries in K."""
    h = (1 + _R) / 2
    o, z = K.one, K.zero
    mats = {"a": [[-_R, z, z], [h, o, z], [z, z, o]], "b": [[o, h, z], [z, -_R, z], [z, h, o]],
            "c": [[o, z, z], [z, o, h], [z, z, -_R]]}
    M = [[o if i == j else z for j in range(3)] for i in range(3)]
    for letter in word:
        Kc = mats[letter]
        M = [[sum((Kc[i][k] * M[k][j] for k in range(3)), z) for j in range(3)] for i in range(3)]
    return M


def det3(A) -> object:
    return (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
            + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]))


def eigenvector_k(m, red) -> tuple:
    """q = (-1, u, v) solving rows 1 and 2 of M q = λ q (Cramer's rule over K)."""
    a11, a12, a21, a22 = m[0][1], m[0][2], m[1][1] - _LAM, m[1][2]
    b1, b2 = m[0][0] - _LAM, m[1][0]
    det = a11 * a22 - a12 * a21
    return (-K.one, red((b1 * a22 - a12 * b2) / det), red((a11 * b2 - b1 * a21) / det))


def polynomial_abcd(steps: list[SymbolicStep], cp_ring) -> tuple:
    """(a, b, c, d) with p_3(t_n) = ax + b, p_1(t_n) = cx + d, over a common
    denominator (a common factor does not change f; x₊ and x₋ may swap, and both
    are considered), reduced modulo cp (polynomials in Q[λ, r], not in K: K
    normalises constants and would scale a, b, c, d differently)."""
    (d0, c0), (b0, a0) = steps[-1].p[0], steps[-1].p[2]
    den = RING.one
    for e in (a0, b0, c0, d0):
        den = den.lcm(e.denom)
    return tuple((e.numer * den.quo(e.denom)).rem(cp_ring).as_expr() for e in (a0, b0, c0, d0))


@lru_cache(maxsize=None)
def candidate(word: str) -> Candidate:
    """M_w, cp, the branches, q(0) and the position map of a word (a ... b)."""
    if not word or word[0] != "a" or word[-1] != "b" or any(c not in "abc" for c in word):
        raise ValueError(f"the normalisation q(0) = (-1, u, v), p(0) = (1, 0, x) needs a word a...b, not {word!r}")
    Mk = word_matrix_k(word)
    cpk = det3([[(_LAM if i == j else K.zero) - Mk[i][j] for j in range(3)] for i in range(3)])
    if cpk.denom.is_ground is False:
        raise ArithmeticError("cp has a denominator in r")
    cp_ring = cpk.numer.quo_ground(cpk.denom.LC)          # monic in λ
    red = Reducer(None)
    q0 = eigenvector_k(Mk, red)
    steps = run_letters(word, q0, red)
    if steps[-1].p[1] != (K.zero, K.zero):
        raise ArithmeticError("p_2 does not vanish after the last b")
    M = sp.Matrix(3, 3, lambda i, j: sp.factor(Mk[i][j].as_expr()))
    cp = cp_ring.as_expr()
    return Candidate(word, M, cp, Spectrum(cp), q0, polynomial_abcd(steps, cp_ring))


def matrix_of_name(name: str) -> sp.Matrix:
    """The product of collision matrices named left to right, e.g. "BACBA" = B·A·C·B·A."""
    out = sp.eye(3)
    for letter in name:
        out = out * collision_matrix(letter.lower())
    return out


# ---------------------------------------------------------------- conditions reduced modulo cp


@dataclass
class Requirement:
    """A condition g = G0 + x G1 (G0, G1 in Q(r, λ)) and the strict sign it must have."""

    name: str
    G: tuple
    sign: int

    @property
    def has_x(self) -> bool:
        return self.G[1] != K.zero


def _ring(e):
    if isinstance(e, sp.polys.rings.PolyElement):
        return e if e.ring == RING else RING.from_expr(e.as_expr())
    return RING.from_expr(e)


@lru_cache(maxsize=None)
def _cp_ring(cp):
    return _ring(cp)


def mod_cp(e, cp):
    """A polynomial in r, λ reduced modulo cp (monic in λ): the same values on
    every branch, λ-degree below 3."""
    return _ring(e).rem(_cp_ring(cp)).as_expr()


@dataclass
class FixedPointData:
    """x = (a - d + σ√Δ)/(2c), Δ = (a - d)² + 4bc, all reduced modulo cp."""

    label: str
    sigma: int
    amd: sp.Expr
    c: sp.Expr
    delta: sp.Expr


def fixed_point_data(abcd, cp) -> list[FixedPointData]:
    a, b, c, d = abcd
    amd = mod_cp(sp.expand(a - d), cp)
    delta = mod_cp(sp.expand((a - d) ** 2 + 4 * b * c), cp)
    cc = mod_cp(c, cp)
    return [FixedPointData("x₊", 1, amd, cc, delta), FixedPointData("x₋", -1, amd, cc, delta)]


def condition(req: Requirement, cp, fp: FixedPointData | None = None, x_value=None) -> Condition:
    """The engine's Condition for g = G0 + x G1 with numerator and denominator
    reduced modulo cp, x the fixed point ``fp`` (or the rational function ``x_value``)."""
    G0, G1 = req.G
    n0, d0 = G0.numer.as_expr(), G0.denom.as_expr()
    n1, d1 = G1.numer.as_expr(), G1.denom.as_expr()
    if not req.has_x:
        return Condition(req.name, (mod_cp(n0, cp), sp.Integer(0)), (mod_cp(d0, cp), sp.Integer(0)), None, None)
    if x_value is not None:                  # x = X0/X1
        X0, X1 = sp.fraction(sp.cancel(x_value))
        N = sp.expand(n0 * d1 * X1 + n1 * d0 * X0)
        return Condition(req.name, (mod_cp(N, cp), sp.Integer(0)), (mod_cp(sp.expand(d0 * d1 * X1), cp), sp.Integer(0)),
                         None, None)
    # g = (n0 d1 + x n1 d0)/(d0 d1), x = (A + σ s)/(2c)
    A, c = fp.amd, fp.c
    N0 = sp.expand(2 * c * n0 * d1 + A * n1 * d0)
    N1 = sp.expand(fp.sigma * n1 * d0)
    D0 = sp.expand(2 * c * d0 * d1)
    return Condition(req.name, (mod_cp(N0, cp), mod_cp(N1, cp)), (mod_cp(D0, cp), sp.Integer(0)), fp.delta, fp.c)


def _table(spec: Spectrum, req: Requirement, fp, lo, hi):
    return spec.sign_table(condition(req, spec.cp, fp if req.has_x else None), lo, hi)


# ---------------------------------------------------------------- exact zero tests at a point
def _acb_roots(spec: Spectrum, rc: Algebraic, prec: int):
    """Certified enclosures of the three complex roots of cp(λ; rc), or None."""
    old = flint.ctx.prec
    flint.ctx.prec = prec + 30
    try:
        R = rc.arb(prec)
        coeffs = []
        for c in spec.P.all_coeffs()[::-1]:
            coeffs.append(flint.acb(_eval_r(c, R)))
        return flint.acb_poly(coeffs).roots(), R
    except ValueError:
        return None, None
    finally:
        flint.ctx.prec = old


def _eval_r(c, R):
    P = sp.Poly(c, r)
    val = flint.arb(0)
    for (k,), co in P.terms():
        val += flint.arb(Q(int(sp.numer(co)), int(sp.denom(co)))) * R ** k
    return val


def _eval_rl(g, R, L):
    """A polynomial in r, λ at balls R (arb) and L (acb)."""
    P = sp.Poly(sp.expand(g), r, lam)
    val = flint.acb(0)
    for (i, j), co in P.terms():
        val += flint.acb(flint.arb(Q(int(sp.numer(co)), int(sp.denom(co))))) * flint.acb(R) ** i * L ** j
    return val


def vanishes_on_branch(spec: Spectrum, g: sp.Expr, rc: Algebraic, branch: int, maxprec: int = 2048) -> bool:
    """Exact: the polynomial g(r, λ) vanishes at r = rc on the real branch ``branch``.

    Either every λ-coefficient of g vanishes at rc (g ≡ 0 there), or Res_λ(g, cp)
    vanishes at rc (cp is monic in λ: the resultant is the product of g over the
    roots of cp, so one factor is zero) and g is proven non-zero at every other
    root of cp(·; rc) (complex balls).  False when neither can be proven."""
    m = rc.minimal_polynomial() if not rc.is_rational else flint.fmpz_poly([-rc.lo.p, rc.lo.q])

    def divides(P) -> bool:                  # m irreducible and primitive: m | P iff gcd = m
        return P.is_zero() or P.gcd(m) == m
    coeffs = sp.Poly(sp.expand(g), lam).all_coeffs()
    if all(divides(to_fmpz_poly(c)) for c in coeffs):
        return True
    if not divides(resultant_lambda(g, spec.cp)):
        return False
    prec = 128
    while prec <= maxprec:
        roots, R = _acb_roots(spec, rc, prec)
        if roots is not None:
            old = flint.ctx.prec
            flint.ctx.prec = prec + 30
            try:
                reals = sorted([z for z in roots if z.imag.contains(0) and not _paired(z, roots)],
                               key=lambda z: -float(z.real.mid()))
                if branch < len(reals):
                    target = reals[branch]
                    others = [z for z in roots if z is not target]
                    if all(not _eval_rl(g, R, z).contains(0) for z in others):
                        return True
            finally:
                flint.ctx.prec = old
        prec *= 2
    return False


def _paired(z, roots) -> bool:
    """z overlaps the conjugate of another enclosure: possibly non-real."""
    conj = z.conjugate()
    return any(w is not z and w.overlaps(conj) for w in roots)


# ---------------------------------------------------------------- regions of r, branch by branch
@dataclass
class Piece:
    """An open interval ]lo, hi[ of r, or the single point lo (hi None).  At a point
    where f degenerates, ``x_value`` is the fixed point used there instead of x±."""

    lo: Algebraic
    hi: Algebraic | None = None
    x_value: sp.Expr | None = None
    note: str = ""

    @property
    def is_point(self) -> bool:
        return self.hi is None

    def __str__(self) -> str:
        if self.is_point:
            return "{" + _fmt(self.lo) + "}" + (f" ({self.note})" if self.note else "")
        return f"]{_fmt(self.lo)}, {_fmt(self.hi)}["


@dataclass
class Region:
    """The set of r where every requirement imposed so far holds, for one real
    branch and one fixed point; ``undecided`` lists the points no test settled."""

    branch: int
    fixed_point: str
    pieces: list
    undecided: list
    dropped: list                  # (point, reason) settled exactly as failing

    def describe(self) -> str:
        return " ∪ ".join(str(p) for p in self.pieces) or "∅"


def _fmt(a: Algebraic) -> str:
    return str(a.lo) if a.is_rational else "≈" + a.digits(6)


def _meets(sg, want) -> bool | None:
    if sg == "?":
        return None
    if sg in (None, "missing"):
        return False
    return sg == want


def sign_in_cell(T, branch: int, lo, hi):
    """The sign of table T on ``branch`` over ]lo, hi[, inside one cell of T."""
    signs = T.signs(branch, lo, hi, include_points=False)
    if len(signs) != 1:
        raise ArithmeticError(f"{T.condition}: signs {signs} on ]{lo}, {hi}[")
    return next(iter(signs))


def sign_at(T, rc: Algebraic, branch: int):
    """The sign of table T at rc on ``branch``: its point value when rc is one of
    T's critical values, else the sign of the cell holding rc."""
    for c, pt in zip(T.critical, T.points):
        if c == rc:
            if pt is None:
                return "?"
            return pt[branch] if branch < len(pt) else "missing"
    for cell in T.cells:
        if cell.lo < rc < cell.hi:
            return cell.signs[branch] if branch < len(cell.signs) else "missing"
    raise ArithmeticError(f"{rc} outside the table of {T.condition}")


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


def simplest_between(lo: flint.fmpq, hi: flint.fmpq) -> flint.fmpq:
    """The rational with the smallest denominator in [lo, hi] (continued fractions)."""
    lo, hi = Q(lo), Q(hi)
    if lo > hi:
        raise ValueError("empty interval")
    fl = lo.floor()
    if Q(fl) == lo:
        return lo
    if Q(fl) + 1 <= hi:
        return Q(fl) + 1
    # lo and hi share the integer part: recurse on the reciprocals of the fractional parts
    return Q(fl) + 1 / simplest_between(1 / (hi - fl), 1 / (lo - fl))


class Analysis:
    """Impose requirements one at a time on the candidate of a word and keep, per
    real branch and fixed point, the region of r where all hold (certified)."""

    def __init__(self, cand: Candidate, lo=0, hi=1):
        self.cand, self.spec, self.lo, self.hi = cand, cand.spectrum, lo, hi
        self.fps = cand.fixed_points()
        self.tables = {}
        base = self.spec.sign_table(Condition.of("λ", lam), lo, hi)
        nb = max(len(c.branches) for c in base.cells)
        self.regions = [Region(k, f, [], [], []) for k in range(nb) for f in self.fps]
        for R in self.regions:
            ends = [Algebraic.rational(lo)] + base.critical + [Algebraic.rational(hi)]
            for a, b in zip(ends, ends[1:]):
                if R.branch < len(next(c for c in base.cells if c.lo == a).branches):
                    R.pieces.append(Piece(a, b))
            for c, pt in zip(base.critical, base.points):
                if pt is None:
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
        key = (req.name, fname if req.has_x else "", repr(hull))
        if key not in self.tables:
            self.tables[key] = self.spec.sign_table(condition(req, self.spec.cp, self.fps[fname] if req.has_x else None),
                                                    *hull)
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
            cuts = [c for c in T.critical if p.lo < c < p.hi]
            ends = [p.lo] + cuts + [p.hi]
            for a, b in zip(ends, ends[1:]):
                ok = _meets(sign_in_cell(T, R.branch, a, b), req.sign)
                yield Piece(a, b), "holds" if ok else "fails", ""
            for c in cuts:
                yield self._point(R, Piece(c), req, T)

    # -- a single point: balls first, exact zero tests where balls cannot decide
    def _point(self, R: Region, p: Piece, req: Requirement, T):
        rc, k = p.lo, R.branch
        sg = self._sign_with_x(req, rc, k, p.x_value) if (p.x_value is not None and req.has_x) else sign_at(T, rc, k)
        ok = _meets(sg, req.sign)
        if ok is not None:
            return p, "holds" if ok else "fails", "" if ok else f"{req.name} has the wrong sign"
        a, b, c, d = self.cand.abcd
        if req.has_x and p.x_value is None and vanishes_on_branch(self.spec, c, rc, k):
            xv = sp.cancel(b / (d - a))
            if _meets(self._sign_with_x(Requirement("x", (K.zero, K.one), 1), rc, k, xv), 1):
                return self._point(R, Piece(rc, None, xv, "c = 0: f affine, fixed point b/(d-a)"), req, T)
            return p, "fails", "c = 0 there (exact): f is affine, its fixed point b/(d-a) is not positive"
        if not req.has_x or p.x_value is not None:
            cond = condition(req, self.spec.cp, x_value=p.x_value) if req.has_x else condition(req, self.spec.cp)
            if vanishes_on_branch(self.spec, sp.expand(cond.N[0] * cond.D[0]), rc, k):
                return p, "fails", f"{req.name} vanishes or has a pole there (exact)"
        return p, "undecided", req.name

    def _sign_with_x(self, req, rc, k, xv):
        sg = self.spec.sign_at_point(condition(req, self.spec.cp, x_value=xv), rc)
        return "?" if sg is None else (sg[k] if k < len(sg) else "missing")
# ---------------------------------------------------------------- the requirements of a prefix
def prefix_requirements(word: str, m: int, q0, reduce=None) -> tuple[list[Requirement], list[SymbolicStep]]:
    """The candidate of ``word`` realises its first m collisions (strictly, l. 449-486):
    u = q_2(0) > 0 (p_2(0) = 0 right after the last b), x > 0, and at each collision
    k the pair approaches (q_i(t_{k-1}) < 0) and the other gaps stay open (p_j(t_k) > 0).
    The gap that closed at the previous collision is open again automatically
    (p_j(t_k) = τ_k q_j(t_{k-1}) with q_j(t_{k-1}) > 0 and τ_k > 0), so it is not listed."""
    steps = run_letters(word[:m], q0, reduce)
    reqs = [Requirement("u = q_2(0)", (q0[1], K.zero), 1), Requirement("x", (K.zero, K.one), 1)]
    previous = INDEX[word[-1]]
    for k, st in enumerate(steps):
        i = INDEX[st.letter]
        before = q0 if k == 0 else steps[k - 1].q
        if not _positive_constant(-before[i]):
            reqs.append(Requirement(f"q_{i + 1}(t_{k})", (before[i], K.zero), -1))
        for j in range(3):
            if j not in (i, previous):
                reqs.append(Requirement(f"p_{j + 1}(t_{k + 1})", st.p[j], 1))
        previous = i
    return reqs, steps


def _positive_constant(e) -> bool:
    v = e.as_expr()
    return v.is_number and v > 0


# ---------------------------------------------------------------- T27
PRINTED_T27 = dict(word="abcab", matrix="BACBA", after="b", next="a", other="c")


@certificate("T27", "l. 513-515",
             "abcab (matrix BACBA) has no self-similar datum: for the candidate (eigenvector of BACBA, a fixed "
             "point of f), the collision after the first b is a, not c, at a strictly earlier time.",
             printed=PRINTED_T27)
def abcab_has_no_self_similar_datum(word, matrix, after, next, other):
    """On every real branch, for every r in ]0,1[ and both fixed points x±: wherever
    the candidate realises its first collisions up to the first b, the next
    collision is a (q_1 < 0 after b) and it comes strictly before c (p_3 > 0 at
    that a)."""
    cand = candidate(word)
    same = (matrix_of_name(matrix) - cand.M).applyfunc(sp.cancel) == sp.zeros(3, 3)
    checks = [Check(f"the matrix of the word {word} (collisions in time order) is {matrix}", same,
                    [f"M_w = `{show(cand.M.tolist())}`", f"cp(M_w) = `{show(sp.collect(cand.cp, lam))}`"])]
    m = word.index(after) + 1
    red = cand.reducer()
    feas, steps = prefix_requirements(word, m, cand.q0, red)
    i, o = INDEX[next], INDEX[other]
    tail = run_letters(word[:m] + next, cand.q0, red)[-1]
    claim = [Requirement(f"q_{i + 1}(t_{m})", (steps[-1].q[i], K.zero), -1),
             Requirement(f"p_{o + 1}(t_{m + 1})", tail.p[o], 1)]
    an = Analysis(cand)
    for req in feas:
        an.impose(req)
    bad = [v for req in claim for v in an.violations(req)]
    undecided = [(R, u) for R in an.regions for u in R.undecided]
    feasible = [R for R in an.regions if R.pieces]
    a, b, c, d = cand.abcd
    ev = [f"q(0) = (-1, u, v), u = `{show(sp.factor(expr_of(cand.q0[1])))}`, "
          f"v = `{show(sp.factor(expr_of(cand.q0[2])))}`; p(0) = (1, 0, x)",
          f"f(x) = (ax + b)/(cx + d), a = `{show(sp.factor(a))}`, b = `{show(sp.factor(b))}`, "
          f"c = `{show(sp.factor(c))}`, d = `{show(sp.factor(d))}`; x± = (a - d ± √((a-d)² + 4bc))/(2c)",
          f"the candidate realises {', '.join(word[:m])} iff " + ", ".join(f"{q.name} {'>' if q.sign > 0 else '<'} 0"
                                                                        for q in feas),
          f"claim: {claim[0].name} < 0 ({next} approaches) and {claim[1].name} > 0 (at the time of that {next}, "
          f"the gap {other} is still open: τ_{next} < τ_{other})"]
    for R in an.regions:
        ev.append(f"{BRANCH_NAMES[R.branch]} branch, {R.fixed_point}: candidate realised on {R.describe()}"
                  + (f"; excluded exactly at {', '.join(f'{_fmt(rc)} ({why})' for rc, why in R.dropped)}"
                     if R.dropped else ""))
    for key, T in an.tables.items():
        if key[0] in ("x", claim[0].name, claim[1].name):
            ev.append(f"sign of {key[0]} {key[1]} over ]{_fmt(Algebraic.rational(T.interval[0]) if not isinstance(T.interval[0], Algebraic) else T.interval[0])}, "
                      f"{_fmt(T.interval[1] if isinstance(T.interval[1], Algebraic) else Algebraic.rational(T.interval[1]))}[:\n\n{T.markdown()}")
    q_other = Requirement(f"q_{o + 1}(t_{m})", (steps[-1].q[o], K.zero), -1)
    ev.append(f"{q_other.name} < 0 ({other} approaching after {after}) on the same region: "
              + ("yes" if not an.violations(q_other) else "no (where it is ≥ 0, c does not come next at all)"))
    checks += [
        Check("every cell and critical value of ]0,1[ decided on every branch, for x₊ and x₋", not undecided,
              [f"undecided: {BRANCH_NAMES[R.branch]} {R.fixed_point} at {_fmt(rc)} ({why})" for R, (rc, why) in undecided]),
        Check(f"wherever the candidate realises {', '.join(word[:m])}, the next collision is {next}, "
              f"strictly before {other}", not bad and not undecided,
              [f"fails on {BRANCH_NAMES[R.branch]} {R.fixed_point} {p}: {why}" for R, p, why in bad]),
        Check("and the candidate does realise them somewhere (the remark is not vacuous)", bool(feasible)),
    ]
    return conclude(checks, evidence=ev)
