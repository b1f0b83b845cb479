"""Signs of a condition on each real eigenvalue branch, certified over r-intervals.

Given cp(λ; r) ∈ Q[r][λ] and a condition g — a rational function of r and λ, or of
r, λ and the position fixed point x = (a - d + √Δ)/(2c), Δ = (a - d)² + 4bc — we
prove the sign of g on every real branch λ_k(r) (k = 0 the largest real root) over
an interval of r:

1. critical values: real roots in the interval of disc_λ(cp), of the leading
   coefficient, of Res_λ(norm(numerator of g), cp), Res_λ(norm(denominator), cp)
   and, when x occurs, of Res_λ(Δ, cp) and Res_λ(c, cp) (norm(N₀ + N₁√Δ) = N₀² - N₁²Δ);
2. between consecutive critical values, the number of real branches and the sign
   of g on each are constant (g is continuous and has no zero there);
3. one exact rational sample per cell; the branches at the sample isolated by
   Sturm sequences over Q; g evaluated in ball arithmetic (python-flint arb),
   precision raised until the sign is proven.
At a critical value itself the sign is decided when the branches are simple
there (isolated by certified complex root enclosures), otherwise left undecided.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import flint
import sympy as sp

from .algebraic import Algebraic
from .poly import (discriminant_lambda, expr, lam, primitive, r, resultant_lambda, s,
                   squarefree_part, to_mpoly, x, show)
from .sturm import isolate, refine

Q = flint.fmpq
SIGN = {1: "+", -1: "−", 0: "0", None: "·"}


@dataclass
class FixedPoint:
    """The fixed point x₊ = (a - d + √Δ)/(2c) of f(x) = (ax + b)/(cx + d), Δ = (a-d)² + 4bc."""

    a: sp.Expr
    b: sp.Expr
    c: sp.Expr
    d: sp.Expr

    @property
    def delta(self) -> sp.Expr:
        return sp.expand((self.a - self.d) ** 2 + 4 * self.b * self.c)

    @property
    def x_plus(self) -> sp.Expr:
        return (self.a - self.d + s) / (2 * self.c)


def _split_sqrt(e: sp.Expr, delta) -> tuple[sp.Expr, sp.Expr]:
    """Write a polynomial in s as P₀ + P₁ s using s² = Δ."""
    P = sp.Poly(sp.expand(e), s)
    p0, p1 = sp.Integer(0), sp.Integer(0)
    for (k,), c in P.terms():
        term = c * (delta ** (k // 2) if delta is not None else (s ** k if k else 1))
        if k % 2:
            p1 += term
        else:
            p0 += term
    return sp.expand(p0), sp.expand(p1)


class Polynomial3:
    """An integer polynomial in r, λ, s ready for ball evaluation."""

    def __init__(self, e):
        self.e = sp.expand(expr(e))
        self.terms = [(int(c), m) for m, c in to_mpoly(self.e).to_dict().items()] if self.e != 0 else []
        den = sp.Poly(self.e, r, lam, s).coeffs() if self.e != 0 else []
        # to_mpoly clears a positive denominator; the sign is unchanged
        self.is_zero = self.e == 0

    def __call__(self, R, L, S) -> flint.arb:
        total = flint.arb(0)
        cache = {}
        for c, (i, j, k) in self.terms:
            key = (i, j, k)
            total += c * (R ** i) * (L ** j) * (S ** k if k else 1)
        return total


@dataclass
class Condition:
    """g = N/D with N = N₀ + N₁√Δ, D = D₀ + D₁√Δ over Q[r, λ]."""

    name: str
    N: tuple
    D: tuple
    delta: sp.Expr | None
    c: sp.Expr | None

    @classmethod
    def of(cls, name: str, g, fixed_point: FixedPoint | None = None) -> "Condition":
        g = expr(g)
        if fixed_point is not None and g.has(x):
            g = g.subs(x, fixed_point.x_plus)
            delta, c = fixed_point.delta, sp.expand(fixed_point.c)
        else:
            delta, c = None, None
        num, den = sp.fraction(sp.together(sp.expand(g)))
        N = _split_sqrt(num, delta)
        D = _split_sqrt(den, delta)
        return cls(name, N, D, delta, c)

    def norms(self) -> list[sp.Expr]:
        """Polynomials in r, λ whose zeros contain every zero and pole of g."""
        out = []
        for P0, P1 in (self.N, self.D):
            out.append(sp.expand(P0 ** 2 - P1 ** 2 * self.delta) if P1 != 0 else P0)
        if self.delta is not None:
            out += [self.delta, self.c]
        return [e for e in out if sp.Poly(e, r, lam).total_degree() > 0]


@dataclass
class Cell:
    """An open r-interval between consecutive critical values, with its sample."""

    lo: Algebraic
    hi: Algebraic
    sample: flint.fmpq
    branches: list[Algebraic]          # real λ at the sample, largest first
    signs: list[int | None]            # sign of g on each branch (None: x not real)


@dataclass
class SignTable:
    """The certified sign of a condition on each branch, cell by cell."""

    condition: str
    interval: tuple
    critical: list[Algebraic]
    cells: list[Cell]
    points: list[list[int | None] | None] = field(default_factory=list)

    def signs(self, branch: int, lo=None, hi=None, include_points=True) -> set:
        """Signs taken by g on branch ``branch`` (0 = largest real eigenvalue) over
        ]lo, hi[ (default: the whole interval), interior critical values included.
        'missing' is in the set where the branch does not exist, '?' where undecided."""
        lo = self.interval[0] if lo is None else lo
        hi = self.interval[1] if hi is None else hi
        out = set()
        for cell in self.cells:
            if cell.hi <= lo or cell.lo >= hi:
                continue
            out.add(cell.signs[branch] if branch < len(cell.signs) else "missing")
        if include_points:
            for rc, pt in zip(self.critical, self.points):
                if lo < rc < hi:
                    if pt is None:
                        out.add("?")
                    else:
                        out.add(pt[branch] if branch < len(pt) else "missing")
        return out

    def holds(self, branch: int, sign: int, lo=None, hi=None) -> bool:
        """g has the sign ``sign`` at every point of branch ``branch`` over ]lo, hi[."""
        return self.signs(branch, lo, hi) == {sign}

    def markdown(self, names=("upper", "middle", "lower")) -> str:
        """The sign table: one row per cell and per critical value."""
        width = max([len(c.signs) for c in self.cells] + [1])
        head = "| r | sample | real λ | " + " | ".join(names[k] if k < len(names) else f"λ{k}" for k in range(width)) + " |"
        rows = [head, "|" + "---|" * (3 + width)]
        for k, cell in enumerate(self.cells):
            signs = [SIGN[sg] for sg in cell.signs] + [""] * (width - len(cell.signs))
            rows.append(f"| ]{_short(cell.lo)}, {_short(cell.hi)}[ | {cell.sample} | {len(cell.branches)} | " + " | ".join(signs) + " |")
            if k < len(self.critical) and k < len(self.points):
                pt = self.points[k]
                signs = ["?"] * width if pt is None else [SIGN.get(sg, "?") for sg in pt] + [""] * (width - len(pt))
                rows.append(f"| {_short(self.critical[k])} | (critical) | {'' if pt is None else len(pt)} | " + " | ".join(signs) + " |")
        return "\n".join(rows)


def _short(a) -> str:
    if isinstance(a, Algebraic):
        return str(a.lo) if a.is_rational else f"≈{a.digits(6)}"
    return str(a)


class Spectrum:
    """The real eigenvalue branches of cp(λ; r), cp ∈ Q[r][λ]."""

    def __init__(self, cp):
        self.cp = sp.expand(expr(cp))
        self.P = sp.Poly(self.cp, lam)
        self.degree = self.P.degree()
        self.disc = primitive(discriminant_lambda(self.cp))
        self.lc = primitive(flint.fmpq_poly([0]) + _univariate(self.P.LC()))
        self._resultants = {}
        self._tables = {}

    def at(self, r0) -> flint.fmpq_poly:
        """cp(λ; r0) ∈ Q[λ] for a rational r0."""
        r0 = Q(r0)
        coeffs = [sp.Poly(c, r).eval(sp.Rational(int(r0.p), int(r0.q))) if c.has(r) else c
                  for c in self.P.all_coeffs()[::-1]]
        return flint.fmpq_poly([Q(int(sp.numer(c)), int(sp.denom(c))) for c in coeffs])

    def real_eigenvalues(self, r0) -> list[Algebraic]:
        """The real roots λ of cp(λ; r0), largest first, as algebraic numbers (Sturm)."""
        p = self.at(r0)
        return [Algebraic(p, lo, hi) for lo, hi in isolate(p)][::-1]

    def resultant(self, g) -> flint.fmpz_poly:
        key = sp.srepr(g)
        if key not in self._resultants:
            self._resultants[key] = primitive(resultant_lambda(g, self.cp))
        return self._resultants[key]

    def critical_values(self, cond: Condition | None, lo, hi) -> list[Algebraic]:
        """The critical values in ]lo, hi[, increasing."""
        polys = [self.disc]
        if self.lc.degree() > 0:
            polys.append(self.lc)
        if cond is not None:
            for e in cond.norms():
                R = self.resultant(e)
                if R.is_zero():
                    raise ArithmeticError(f"{cond.name}: a factor vanishes on a whole branch")
                polys.append(R)
        prod = flint.fmpz_poly([1])
        for p in polys:
            prod *= squarefree_part(p)
        P = squarefree_part(prod)
        return Algebraic.roots(P, _q(lo), _q(hi)) if not (isinstance(lo, Algebraic) or isinstance(hi, Algebraic)) \
            else [a for a in Algebraic.roots(P, _outer(lo, -1), _outer(hi, 1)) if lo < a < hi]

    def sign_table(self, cond: Condition, lo, hi) -> SignTable:
        """Certified signs of ``cond`` on every branch over ]lo, hi[ (memoised per
        condition and interval, so certificates sharing a condition share the work)."""
        key = (sp.srepr(cond.N), sp.srepr(cond.D), sp.srepr(cond.delta), repr(lo), repr(hi))
        if key not in self._tables:
            self._tables[key] = self._sign_table(cond, lo, hi)
        return self._tables[key]

    def _sign_table(self, cond: Condition, lo, hi) -> SignTable:
        crit = self.critical_values(cond, lo, hi)
        ends = [_alg(lo)] + crit + [_alg(hi)]
        cells = []
        for a, b in zip(ends, ends[1:]):
            t = simple_rational_between(a, b)
            lams = self.real_eigenvalues(t)
            cells.append(Cell(a, b, t, lams, [evaluate_sign(cond, t, L) for L in lams]))
        points = [self.sign_at_point(cond, rc) for rc in crit]
        return SignTable(cond.name, (_alg(lo), _alg(hi)), crit, cells, points)

    def vanishes_at(self, h, rc: Algebraic, branch: int, maxprec: int = 1024) -> bool:
        """Exact test that the polynomial h(r, λ) vanishes on branch ``branch`` at r = rc:
        G = gcd(cp(λ; rc), h(rc, λ)) is computed in Q(rc)[λ]; h vanishes there iff
        the branch's eigenvalue is a root of G, decided by disjoint certified balls."""
        m = sp.Poly(r - sp.Rational(int(rc.lo.p), int(rc.lo.q)), r) if rc.is_rational \
            else _mod_poly(rc.minimal_polynomial())
        H = sp.Poly(sp.expand(expr(h)), lam)
        f = [_kred(c, m) for c in self.P.all_coeffs()]
        hk = [_kred(c, m) for c in H.all_coeffs()]
        while hk and hk[0].is_zero:
            hk = hk[1:]
        if not hk:
            return True
        G = _kpoly_gcd(f, hk, m)
        if len(G) == 1:
            return False
        dG = [_kred((c * (len(G) - 1 - i)).as_expr(), m) for i, c in enumerate(G[:-1])]
        g2 = _kpoly_gcd(G, dG, m)
        G = _kpoly_div(G, g2, m) if len(g2) > 1 else G
        branches = _branches_at(self.P, rc, maxprec)
        if branches is None or branch >= len(branches):
            raise ArithmeticError("branch not isolated at this point")
        prec = 128
        while prec <= maxprec:
            zeros = _sorted_real_roots(G, rc, prec)
            balls = [b(prec) for b in branches]
            if zeros is not None:
                mine = balls[branch]
                others = [b for k, b in enumerate(balls) if k != branch and not (b.overlaps(mine))]
                hit = [z for z in zeros if z.overlaps(mine)]
                if all(not z.overlaps(o) for z in hit for o in others):
                    return bool(hit)
            prec *= 2
        raise ArithmeticError("zero test undecided")

    def sign_at_point(self, cond: Condition, rc: Algebraic, maxprec: int = 1024):
        """Signs of g on the branches at an algebraic r ('?' where undecided: g
        vanishing or a pole there), or None when the branches cannot be isolated.
        Where two branches collide at rc, cp(λ; rc) is made squarefree exactly in
        Q(rc)[λ] first, and the multiple root is listed once per branch."""
        roots = _branches_at(self.P, rc, maxprec)
        if roots is None:
            return None
        prec, out = 128, None
        while prec <= maxprec:
            old = flint.ctx.prec
            flint.ctx.prec = prec + 30
            try:
                R = rc.arb(prec)
                out = [_sign_ball(cond, R, L(prec)) for L in roots]
            finally:
                flint.ctx.prec = old
            if "?" not in out:
                return out
            prec *= 2
        return out


def _mod_poly(m):
    return sp.Poly(from_flint_int(m), r)


def from_flint_int(m):
    return sum(sp.Integer(int(c)) * r ** k for k, c in enumerate(m.coeffs()))


def _kred(c, m):
    """An element of Q(rc) = Q[r]/(m) in normal form."""
    return sp.Poly(c, r).rem(m)


def _kpoly_gcd(f, g, m):
    """gcd in K[λ], K = Q[r]/(m), m irreducible; polynomials as lists of K-elements
    (sympy Polys in r), highest degree first; the result is monic."""
    def strip(p):
        while p and p[0].is_zero:
            p = p[1:]
        return p

    def monic(p):
        inv = sp.Poly(sp.invert(p[0].as_expr(), m.as_expr(), r), r)
        return [_kred((c * inv).as_expr(), m) for c in p]

    f, g = strip(f), strip(g)
    while g:
        g = monic(g)
        while len(f) >= len(g):
            q = f[0]
            shifted = g + [sp.Poly(0, r)] * (len(f) - len(g))
            f = strip([_kred((a - q * b).as_expr(), m) for a, b in zip(f, shifted)])
        f, g = g, f
    return monic(f)


def _kpoly_div(f, g, m):
    """Exact quotient f / g in K[λ] (g monic)."""
    f, out = list(f), []
    while len(f) >= len(g):
        q = f[0]
        out.append(q)
        shifted = g + [sp.Poly(0, r)] * (len(f) - len(g))
        f = [_kred((a - q * b).as_expr(), m) for a, b in zip(f, shifted)][1:]
    return out


def _branches_at(P: sp.Poly, rc: Algebraic, maxprec: int):
    """The real roots of cp(λ; rc), largest first, each repeated by its multiplicity
    (1, or 2 for the root of a linear gcd(cp, cp')), as functions prec -> arb ball;
    None when they cannot be isolated."""
    if rc.is_rational:
        m = sp.Poly(r - sp.Rational(int(rc.lo.p), int(rc.lo.q)), r)
    else:
        m = _mod_poly(rc.minimal_polynomial())
    f = [_kred(c, m) for c in P.all_coeffs()]
    df = [_kred(c, m) for c in P.diff(lam).all_coeffs()]
    g = _kpoly_gcd(f, df, m)
    if len(g) > 2:
        return None                      # a root of multiplicity > 2: not handled
    sqf = _kpoly_div(f, g, m) if len(g) > 1 else f
    prec = 128
    while prec <= maxprec:
        reals = _sorted_real_roots(sqf, rc, prec)
        if reals is not None:
            mult = [1] * len(reals)
            if len(g) == 2:
                old = flint.ctx.prec
                flint.ctx.prec = prec + 30
                try:
                    vals = [_kpoly_eval(g, rc.arb(prec), z) for z in reals]
                finally:
                    flint.ctx.prec = old
                hits = [i for i, val in enumerate(vals) if val.contains(0)]
                if len(hits) != 1:
                    prec *= 2
                    continue
                mult[hits[0]] = 2
            return [_root_function(sqf, rc, k) for k in range(len(reals)) for _ in range(mult[k])]
        prec *= 2
    return None


def _sorted_real_roots(sqf, rc, prec):
    """Certified real roots of a squarefree K[λ] polynomial at rc, largest first."""
    old = flint.ctx.prec
    flint.ctx.prec = prec + 30
    try:
        R = rc.arb(prec)
        coeffs = [_arb_eval_r(c.as_expr(), R) for c in sqf][::-1]
        reals = _real_roots(flint.acb_poly(coeffs).roots())
    except ValueError:
        return None
    finally:
        flint.ctx.prec = old
    if reals is None:
        return None
    return sorted(reals, key=lambda z: float(z.mid()), reverse=True)


def _kpoly_eval(g, R, z):
    val = flint.arb(0)
    for c in g:
        val = val * z + _arb_eval_r(c.as_expr(), R).real
    return val


def _root_function(sqf, rc, k):
    """prec -> a ball around the k-th largest real root of the squarefree polynomial."""
    def ball(prec):
        reals = _sorted_real_roots(sqf, rc, prec)
        if reals is None:
            raise ValueError("roots lost at higher precision")
        return reals[k]
    return ball


def _real_roots(roots):
    """Which certified root enclosures hold real roots (None if undecidable)."""
    reals = []
    for i, z in enumerate(roots):
        conj = z.conjugate()
        others = [j for j, w in enumerate(roots) if j != i and w.overlaps(conj)]
        if z.imag > 0 or z.imag < 0:
            continue
        if not others and z.overlaps(conj):
            reals.append(z.real)
        else:
            return None
    return reals


def _arb_eval_r(c, R):
    P = sp.Poly(c, r)
    val = flint.arb(0)
    for (k,), co in P.terms():
        val += flint.arb(Q(int(sp.numer(co)), int(sp.denom(co)))) * R ** k
    return flint.acb(val)


def _sign_ball(cond: Condition, R, L):
    """Sign of g at balls R, L (r and λ); '?' if the balls do not decide it."""
    S = flint.arb(0)
    if cond.delta is not None:
        dv = _poly3(cond.delta)(R, L, S)
        if dv < 0:
            return None
        if not dv > 0:
            return "?"
        S = dv.sqrt()
    n = _poly3(cond.N[0])(R, L, S) + _poly3(cond.N[1])(R, L, S) * S
    d = _poly3(cond.D[0])(R, L, S) + _poly3(cond.D[1])(R, L, S) * S
    sn = 1 if n > 0 else -1 if n < 0 else None
    sd = 1 if d > 0 else -1 if d < 0 else None
    if sn is None or sd is None:
        return "?"
    return sn * sd


_POLY_CACHE = {}


def _poly3(e) -> Polynomial3:
    key = sp.srepr(e)
    if key not in _POLY_CACHE:
        _POLY_CACHE[key] = Polynomial3(e)
    return _POLY_CACHE[key]


def evaluate_sign(cond: Condition, r0, L: Algebraic, prec: int = 64, maxprec: int = 8192):
    """The sign of g at r = r0 (rational) on the branch λ = L, proven in ball
    arithmetic; None when x is not real there (Δ < 0)."""
    while prec <= maxprec:
        old = flint.ctx.prec
        flint.ctx.prec = prec + 20
        try:
            sg = _sign_ball(cond, flint.arb(Q(r0)), L.arb(prec))
        finally:
            flint.ctx.prec = old
        if sg != "?":
            return sg
        prec *= 2
    raise ArithmeticError(f"sign of {cond.name} undecided at r = {r0}")


def _q(a):
    return a if isinstance(a, flint.fmpq) else Q(a) if not isinstance(a, Algebraic) else a


def _alg(a) -> Algebraic:
    return a if isinstance(a, Algebraic) else Algebraic.rational(a)


def _outer(a, direction):
    if isinstance(a, Algebraic):
        return a.lo if direction < 0 else a.hi
    return Q(a)


def _univariate(e):
    from .poly import to_fmpq_poly
    return to_fmpq_poly(e, r)


def simple_rational_between(a: Algebraic, b: Algebraic) -> flint.fmpq:
    """A rational strictly between a < b with a small denominator (readable samples)."""
    width = Q(1, 2)
    while True:
        a.refine(width)
        b.refine(width)
        lo, hi = a.hi, b.lo
        if lo < hi:
            for den in range(1, 10 ** 6):
                k = (lo * den).floor() + 1
                t = Q(k, den)
                if lo < t < hi or (t == hi and not b.is_rational and False):
                    if a < t < b:
                        return t
                if den > 64 and hi - lo > 0:
                    break
            mid = (lo + hi) / 2
            if a < mid < b:
                return mid
        width /= 16
