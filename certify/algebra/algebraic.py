"""Real algebraic numbers as (squarefree integer polynomial, isolating interval).

``Algebraic(p, lo, hi)`` is the unique root of p in ]lo, hi[ (or the rational lo
when lo == hi).  Comparisons are exact: intervals are refined until they are
disjoint, and two numbers whose intervals keep overlapping are proven equal by a
common factor of their polynomials having a root in the overlap.  Digits are
printed from certified enclosures only.
"""
from __future__ import annotations

import copy
import itertools
from fractions import Fraction
from functools import total_ordering

import flint
import sympy as sp

from certify import caches
from certify.errors import UNDECIDED, Undecided

from .balls import GUARD, decide, precision
from .poly import Q, from_flint, parse, poly_key, primitive, show, squarefree_part, to_fmpq, to_fmpz_poly
from .sturm import (
    complex_roots,
    count_roots,
    flint_real_roots,
    isolate,
    isolated_real_root,
    real_ball_inside,
    refine,
    sturm_count,
)

_ISOLATED: dict = {}             # (p, a, b) -> its roots in ]a, b[ as first isolated (copied out)
caches.register(_ISOLATED.clear)
_key_of = caches.by_identity(poly_key)   # a spectrum's critical factors: the same objects in every table


def _sign(a) -> int:
    return (a > 0) - (a < 0)


@total_ordering
class Algebraic:
    """A real algebraic number with its defining polynomial and isolating interval."""

    def __init__(self, p, lo, hi):
        self.p = squarefree_part(primitive(flint.fmpq_poly(p)))
        self.lo, self.hi = Q(lo), Q(hi)
        if self.lo > self.hi:
            raise ValueError("empty interval")
        if self.lo == self.hi:
            if self.p(self.lo) != 0:
                raise ValueError("rational point is not a root")
        elif count_roots(self.p, self.lo, self.hi) - (self.p(self.hi) == 0) != 1 or self.p(self.lo) == 0:
            raise ValueError("interval does not isolate exactly one root")

    @classmethod
    def rational(cls, a) -> Algebraic:
        a = to_fmpq(a)
        return cls(flint.fmpq_poly([-a, 1]), a, a)

    @classmethod
    def roots(cls, p, a=None, b=None) -> list[Algebraic]:
        """The distinct real roots of p in ]a, b[, increasing (Sturm isolation).  The
        isolating intervals are memoised per (p, a, b); each call returns new numbers
        (a number refines its interval in place).

        The root of r² - 10r + 1 in ]0, 1[ is the paper's threshold 5 - 2√6:

        >>> import flint
        >>> [r1] = Algebraic.roots(flint.fmpq_poly([1, -10, 1]), 0, 1)
        >>> r1 == Algebraic.surd(5, -2, 6), r1.digits(12)
        (True, '0.101020514434')

        A number is exact: (p, isolating interval), compared and signed exactly.  Its
        digits are the correctly rounded decimal of the exact value; the interval
        printed by ``repr`` is only as narrow as the last refinement."""
        p = primitive(flint.fmpq_poly(p)) if not isinstance(p, flint.fmpz_poly) else p
        key = (_key_of(p), None if a is None else str(a), None if b is None else str(b))
        made = _ISOLATED.get(key)
        if made is None:
            made = _ISOLATED[key] = [cls(p, lo, hi) for lo, hi in isolate(p, a, b)]
            if len(_ISOLATED) > 20000:
                _ISOLATED.clear()
        return [copy.copy(x) for x in made]

    @classmethod
    def surd(cls, a, b, n) -> Algebraic:
        """a + b·√n for rationals a, b and a positive integer n, not a square."""
        a, b = to_fmpq(a), to_fmpq(b)
        # (t - a)^2 - b^2 n = 0
        p = flint.fmpq_poly([a * a - b * b * n, -2 * a, 1])
        roots = cls.roots(p)
        return roots[1] if b > 0 else roots[0]

    def minimal_polynomial(self) -> flint.fmpz_poly:
        """The irreducible factor of p vanishing at the number (p is replaced by it)."""
        if self.p.degree() > 1 and not getattr(self, "_minimal", False):
            _, factors = self.p.factor()
            for f, _m in factors:
                f = primitive(f)
                if self.is_rational:
                    if f(self.lo) == 0:
                        self.p = f
                        break
                elif count_roots(f, self.lo, self.hi) - (f(self.hi) == 0) == 1:
                    self.p = f
                    break
            self._minimal = True
        return self.p

    def key(self) -> tuple:
        """A hashable key of the number, cheap (unlike :meth:`describe`): its polynomial p
        and its index among the real roots of p, increasing.  Equal keys mean equal
        numbers; a number given by two polynomials has two keys (a cache miss, no
        error).  The index is the position of the number's root ball among python-flint's
        real root balls of p (all real roots, in increasing order, each checked by an
        exact sign change, as many as Sturm counts); else an exact Sturm count below the
        left end of the isolating interval.  Computed once."""
        k = getattr(self, "_key", None)
        if k is None:
            if self.is_rational:
                k = ("Q", str(self.lo))
            else:
                k = (str(self.p), self._index())
            self._key = k
        return k

    def _index(self) -> int:
        for prec in (64, 256):
            balls = _enclosures(self.p, prec)
            if len(balls) == count_roots(self.p) and \
                    all(b < a for (_a0, b), (a, _b1) in zip(balls, balls[1:])):
                hits = [i for i, (a, b) in enumerate(balls) if self.lo < a and b < self.hi]
                if len(hits) == 1:
                    return hits[0]
        return count_roots(self.p, None, self.lo)

    def enclosure(self, prec: int = 64):
        """Exact rational ends ]a, b[ ⊂ ]lo, hi[ of an interval holding the number,
        from python-flint's certified root balls of p (a sign change of p at a and b
        is checked exactly, so ]a, b[ holds a root of p inside the isolating interval:
        the number); None when no such ball is found at this precision.  Memoised."""
        cache = self.__dict__.setdefault("_enclosures", {})
        if prec not in cache:
            cache[prec] = next(((a, b) for a, b in _enclosures(self.p, prec)
                                if self.lo < a and b < self.hi), None)
        return cache[prec]
    @property
    def is_rational(self) -> bool:
        return self.lo == self.hi

    def refine(self, width) -> Algebraic:
        """Shrink the isolating interval below ``width`` (in place) and return self."""
        if not self.is_rational:
            self.lo, self.hi = refine(self.p, self.lo, self.hi, width)
        return self

    def arb(self, prec: int = 64) -> flint.arb:
        """A ball containing the number, radius about 2^-prec: from python-flint's
        certified root isolation of p (the one real root ball inside the isolating
        interval), or else by bisecting the interval."""
        balls = self.__dict__.setdefault("_balls", {})       # a ball stays true: memoised per prec
        if prec in balls:
            return balls[prec]
        if not self.is_rational and self.hi - self.lo > Q(1, 2 ** prec) and self.p.degree() > 2:
            coarser = [q for q in balls if q < prec]
            ball = _newton_ball(self.p, balls[max(coarser)], prec) if coarser else None
            if ball is None:
                ball = _root_ball(self.p, self.lo, self.hi, prec)
            if ball is not None:
                balls[prec] = ball
                return ball
        self.refine(Q(1, 2 ** prec))
        mid = (self.lo + self.hi) / 2
        rad = (self.hi - self.lo) / 2
        with precision(max(flint.ctx.prec, prec + GUARD)):
            balls[prec] = flint.arb(mid, flint.arb(rad).upper())
        return balls[prec]

    def short(self, n: int = 8) -> str:
        """The number in a line of evidence: itself when rational, else ``≈`` and n digits."""
        return str(self.lo) if self.is_rational else "≈" + self.digits(n)

    def digits(self, n: int = 10) -> str:
        """The number rounded to n significant digits, from a certified enclosure:
        the interval is refined until both of its ends round alike."""
        for k in itertools.count():
            # the ends' roundings compared as rationals (equal roundings, equal texts; the text,
            # a SymPy Float's, made once at the end)
            a = _rounded(self.lo, n)
            if a == _rounded(self.hi, n):
                return _fmt(self.lo, n)
            if k == 100 and self.minimal_polynomial().degree() == 1:
                # a rational number (possibly a rounding tie): make it exact
                c = self.p.coeffs()
                self.lo = self.hi = Q(-c[0], c[1])
            self.refine((self.hi - self.lo) / 2)
        raise AssertionError("unreachable: itertools.count() does not end")

    def __float__(self) -> float:
        # relative, not absolute, accuracy (a width of 2^-60 is useless near 0)
        return float(self.digits(20))

    def compare_rational(self, q) -> int:
        """sign(self - q), exact."""
        q = Q(q)
        if self.is_rational:
            return _sign(self.lo - q)
        while self.lo < q < self.hi or self.lo == q or self.hi == q:
            if self.p(q) == 0 and self.lo < q < self.hi:
                return 0
            if self.lo == q or self.hi == q:
                if self.lo == q:
                    return 1  # lo is not a root, the number lies strictly above
                return -1
            self.refine((self.hi - self.lo) / 4)
            if self.is_rational:
                return _sign(self.lo - q)
        return 1 if self.lo >= q else -1

    def _cmp(self, other: Algebraic) -> int:
        if not isinstance(other, Algebraic):
            return self.compare_rational(other)
        if other.is_rational:
            return self.compare_rational(other.lo)
        if self.is_rational:
            return -other.compare_rational(self.lo)
        if self.hi <= other.lo:
            return -1
        if other.hi <= self.lo:
            return 1
        if self.p is other.p or self.p == other.p:
            # one polynomial, nested isolating intervals (a copy refined apart from its original):
            # the inner one's root lies in the outer interval, which isolates one root of p
            if self.lo <= other.lo and other.hi <= self.hi or other.lo <= self.lo and self.hi <= other.hi:
                return 0
        g = self.p.gcd(other.p)
        # certified balls first (python-flint root isolation, ends checked exactly)
        for prec in (64, 256):
            A, B = self.enclosure(prec), other.enclosure(prec)
            if A is None or B is None:
                break
            if A[1] <= B[0]:
                return -1
            if B[1] <= A[0]:
                return 1
            if g.degree() > 0:
                lo, hi = max(self.lo, other.lo), min(self.hi, other.hi)
                if lo < hi and any(lo < a and b < hi for a, b in _enclosures(g, prec)):
                    # a root of the common factor inside both isolating intervals: both numbers
                    return 0
        for _ in range(10_000):
            if self.hi <= other.lo:
                return -1
            if other.hi <= self.lo:
                return 1
            lo, hi = max(self.lo, other.lo), min(self.hi, other.hi)
            if g.degree() > 0 and count_roots(g, lo, hi) - (g(hi) == 0) == 1 and g(lo) != 0:
                # the common factor has one root in the overlap: it is both numbers
                if count_roots(g, self.lo, self.hi) - (g(self.hi) == 0) == 1 and \
                        count_roots(g, other.lo, other.hi) - (g(other.hi) == 0) == 1:
                    return 0
            self.refine((self.hi - self.lo) / 2)
            other.refine((other.hi - other.lo) / 2)
        raise Undecided("comparison did not terminate")

    def __eq__(self, other):
        return self._cmp(other) == 0

    def __lt__(self, other) -> bool:
        return self._cmp(other) < 0

    def __hash__(self):
        # equal numbers may be given by different polynomials: hash the minimal one
        return hash((str(self.minimal_polynomial()),))

    def in_rounding_interval(self, printed: str) -> bool:
        """Whether the number rounds to the printed decimal ``printed`` (e.g. "0.11384"):
        it lies in [d - h, d + h] with h half a unit of the last printed digit."""
        d = Fraction(printed)
        decimals = len(printed.split(".")[1]) if "." in printed else 0
        h = Fraction(1, 2 * 10 ** decimals)
        lo, hi = d - h, d + h
        return self.compare_rational(Q(lo.numerator, lo.denominator)) >= 0 and \
            self.compare_rational(Q(hi.numerator, hi.denominator)) <= 0

    def describe(self) -> str:
        """'root of p in ]lo, hi[ ≈ digits' for the report (a function of the number
        alone, computed once)."""
        text = getattr(self, "_described", None)
        if text is None:
            text = self._described = self._describe()
        return text

    def _describe(self) -> str:
        if self.is_rational:
            return f"{self.lo}"
        lo, hi = self.decimal_ends()
        return f"the root of {show(self.p)} in ]{lo}, {hi}[ ≈ {self.digits(12)}"

    def decimal_ends(self) -> tuple[str, str]:
        """The ends of a short isolating interval of the minimal polynomial, as decimal texts
        (]L/10^k, (L+1)/10^k[, k = 12, 16, …: a function of the number alone; the rational ends
        of the current interval when no such k up to 36 isolates).  Memoised."""
        ends = getattr(self, "_decimal_ends", None)
        if ends is not None:
            return ends
        self.minimal_polynomial()
        for k in range(12, 40, 4):
            s = 10 ** k
            L = self.floor_scaled(s)
            lo, hi = Q(L, s), Q(L + 1, s)
            if self.p(lo) != 0 and self.p(hi) != 0 and count_roots(self.p, lo, hi) == 1:
                ends = (_dec(L, k), _dec(L + 1, k))
                break
        if ends is None:
            self.refine(Q(1, 10 ** 12))
            ends = (str(self.lo), str(self.hi))
        self._decimal_ends = ends
        return ends

    def latex(self) -> str:
        """The number in LaTeX, exactly: a rational as a fraction; else the root of its minimal
        polynomial in an isolating interval with decimal ends, ≈ 12 digits (:meth:`describe`).

        >>> print(Algebraic.surd(3, -2, 2).latex())  # doctest: +NORMALIZE_WHITESPACE
        \\text{the root of } r^{2} - 6 r + 1 \\text{ in }
        \\left]0.171572875253, 0.171572875254\\right[ \\approx 0.171572875254
        >>> print(Algebraic.rational(Q(-3, 7)).latex())
        - \\frac{3}{7}

        The digits are correctly rounded (:meth:`digits`); the interval holds exactly one root
        of the polynomial, the number."""
        if self.is_rational:
            return sp.latex(sp.Rational(int(self.lo.p), int(self.lo.q)))
        lo, hi = self.decimal_ends()
        return (f"\\text{{the root of }} {sp.latex(from_flint(self.p), order='lex')}"
                f" \\text{{ in }} \\left]{lo}, {hi}\\right[ \\approx {self.digits(12)}")

    def _repr_latex_(self) -> str:
        """A notebook shows the number as :meth:`latex` (IPython's rich display)."""
        return f"${self.latex()}$"

    def _repr_markdown_(self) -> str:
        """A notebook's Markdown: :meth:`latex` between dollars."""
        return f"${self.latex()}$"

    def floor_scaled(self, s: int) -> int:
        """⌊s·α⌋, exact: the isolating interval narrowed below 1/s, then one exact comparison.
        It depends on the number only, not on how far the interval was refined before."""
        self.refine(Q(1, s))
        L = int((self.lo * s).floor())
        return L + 1 if self.compare_rational(Q(L + 1, s)) >= 0 else L

    def __repr__(self):
        return f"Algebraic({self.describe()})"


def _root_ball(p, lo, hi, prec: int):
    """The real root of p in ]lo, hi[ as a ball of radius ≤ 2^-prec: refined by
    :func:`_newton_ball` from the ball of an isolation of p made already, else from
    python-flint's certified complex root isolation at working precision ~prec (shared with
    every user, :func:`~certify.algebra.sturm.complex_roots`); None when that does not single
    out one real ball inside ]lo, hi[."""
    known = isolated_real_root(p, lo, hi)                 # p isolated already: refine its ball
    ball = _newton_ball(p, known, prec) if known is not None else None
    if ball is not None:
        return ball
    with precision(prec + GUARD + 16):
        try:
            hit = real_ball_inside(complex_roots(p), lo, hi)
        except (ValueError, ArithmeticError):
            hit = None
    if hit is None or hit[0].rad().fmpq() > Q(1, 2 ** prec):
        return None
    z = hit[0]
    m, d = z.mid().fmpq(), z.rad().fmpq()
    a, b = m - d, m + d
    pa, pb = p(a), p(b)                     # exact: the ball's ends bracket a sign change of p
    if pa == 0 or pb == 0 or (pa > 0) == (pb > 0):
        return None
    # radius about 2^-prec, as asked (a tighter ball is as true, but callers size by it)
    with precision(prec + GUARD + 16):
        return flint.arb(z.mid(), max(z.rad(), flint.arb(2) ** -(prec + 2)))


def _newton_ball(p, z: flint.arb, prec: int):
    """The root of p in the ball z (z holds exactly one root, a simple one) narrowed to a
    radius about 2^-prec by the interval Newton operator N(X) = m - p(m)/p'(X), X ∩ N(X)
    (the root stays in it by the mean value theorem while p' ≠ 0 on X): a few
    evaluations instead of a new isolation of all the roots of p.  None when p' may
    vanish on X or the iteration stalls (the caller isolates afresh); the result is
    checked by an exact sign change of p at its rational ends."""
    with precision(prec + GUARD + 16):
        P, D = flint.arb_poly(p), flint.arb_poly(p.derivative())
        X, target = z, flint.arb(2) ** -(prec + 2)
        for _ in range(64):
            if X.rad() <= target:
                break
            d = D(X)
            if d.contains(0):
                return None
            m = flint.arb(X.mid())
            N = m - P(m) / d
            if not N.overlaps(X):
                return None
            Y = X.intersection(N)                  # python-flint's rigorous enclosure of X ∩ N
            if Y.rad() > X.rad() / 2 and N.rad() > 2 * target:
                return None
            X = Y
        if X.rad() > target * 4:
            return None
        a, b = X.mid().fmpq() - X.rad().fmpq(), X.mid().fmpq() + X.rad().fmpq()
        pa, pb = p(a), p(b)
        if pa == 0 or pb == 0 or (pa > 0) == (pb > 0):
            return None
        return flint.arb(X.mid(), max(X.rad(), flint.arb(2) ** -(prec + 2)))


_ENCLOSURES: dict = {}
caches.register(_ENCLOSURES.clear)


def _enclosures(p, prec: int) -> list:
    """Intervals ]a, b[ (exact rational ends of python-flint's real root balls of the
    squarefree p, at working precision ~prec) at whose ends p has opposite non-zero
    signs (checked exactly): each holds a root of p.  Memoised."""
    key = (poly_key(p), prec)
    out = _ENCLOSURES.get(key)
    if out is None:
        if len(_ENCLOSURES) > 4096:
            _ENCLOSURES.clear()
        out = []
        with precision(prec + GUARD):                      # at 64 bits, the isolation count_roots made
            try:
                roots = [c.real for c, _m in complex_roots(p) if c.imag.is_zero()]
            except (ValueError, ArithmeticError):
                roots = []
        for z in roots:
            m, d = z.mid().fmpq(), z.rad().fmpq()
            a, b = m - d, m + d
            pa, pb = p(a), p(b)
            if pa != 0 and pb != 0 and (pa > 0) != (pb > 0):
                out.append((a, b))
        _ENCLOSURES[key] = out
    return out


def _dec(n: int, k: int) -> str:
    """n / 10^k as an exact decimal string."""
    sign, n = ("-" if n < 0 else ""), abs(n)
    return f"{sign}{n // 10 ** k}.{str(n % 10 ** k).zfill(k)}"


def _rounded(q: flint.fmpq, n: int) -> tuple[int, int]:
    """The rational q correctly rounded (half to even) to n significant digits, as
    (d, e) with the value d·10^e (0 as (0, 0)); equal values give equal pairs."""
    f = Fraction(int(q.p), int(q.q))
    if f == 0:
        return 0, 0
    e = len(str(abs(f.numerator))) - len(str(f.denominator))
    while Fraction(10) ** e > abs(f):
        e -= 1
    while Fraction(10) ** (e + 1) <= abs(f):
        e += 1
    d = round(f / Fraction(10) ** (e - n + 1))          # exact integer rounding
    e = e - n + 1
    while d % 10 == 0:                                  # 9.99… rounded up to 10.0: one value, one pair
        d, e = d // 10, e + 1
    return d, e


def _fmt(q: flint.fmpq, n: int) -> str:
    """The rational q correctly rounded (half to even) to n significant digits."""
    d, e = _rounded(q, n)
    if d == 0:
        return str(sp.Float(0, n))
    return str(sp.Float(sp.Rational(d) * sp.Rational(10) ** e, n))


def sign_at(poly, alpha: Algebraic, prec: int = 64, maxprec: int = 4096) -> int:
    """The sign of a univariate rational polynomial at an algebraic number, exact:
    0 when the polynomial and the minimal factor share the root, otherwise decided
    by ball evaluation at increasing precision.

    >>> import flint
    >>> r1 = Algebraic.surd(5, -2, 6)                               # 5 - 2√6 ≈ 0.10102
    >>> sign_at(flint.fmpq_poly([1, -10, 1]), r1)                  # r² - 10r + 1 vanishes there
    0
    >>> sign_at(flint.fmpq_poly([flint.fmpq(-1, 10), 1]), r1)      # r - 1/10 > 0
    1

    A zero is proven by the common factor, never by a small ball.  A non-zero sign is
    proven by a ball that excludes 0; ArithmeticError (Undecided) if ``maxprec`` bits
    do not suffice, which only a polynomial with a root extremely close to α can cause."""
    P = flint.fmpq_poly(poly) if not isinstance(poly, flint.fmpq_poly) else poly
    if P.is_zero():
        return 0
    if alpha.is_rational:
        return _sign(P(alpha.lo))
    g = primitive(P).gcd(alpha.p) if P.degree() >= 0 else flint.fmpz_poly([0])
    if g.degree() > 0 and count_roots(g, alpha.lo, alpha.hi) - (g(alpha.hi) == 0) == 1:
        return 0
    def attempt(p):
        val = flint.arb_poly([flint.arb(c) for c in P.coeffs()])(alpha.arb(p))
        return 1 if val > 0 else -1 if val < 0 else UNDECIDED
    sign = decide(attempt, prec, maxprec)
    if sign == UNDECIDED:
        raise Undecided("sign undecided")
    return sign


def sign_intervals(poly, lo, hi) -> list[tuple[object, object, int]]:
    """The sign of a univariate polynomial on each open interval between its
    consecutive real roots in ]lo, hi[: [(left end, right end, sign)], the ends
    rationals or Algebraic roots (exact Sturm isolation, exact sample signs)."""
    P = flint.fmpq_poly(poly) if not isinstance(poly, flint.fmpq_poly) else poly
    roots = Algebraic.roots(primitive(P), lo, hi)
    ends = [Algebraic.rational(lo)] + roots + [Algebraic.rational(hi)]
    return [(a, b, _sign(P(rational_between(a, b)))) for a, b in zip(ends, ends[1:])]


def rational_between(a: Algebraic, b: Algebraic):
    """A rational strictly between a < b: the middle of the gap between their isolating
    intervals (refined to 2^-20 first, then until there is a gap), checked exactly."""
    a.refine(Q(1, 2 ** 20))
    b.refine(Q(1, 2 ** 20))
    t = (a.hi + b.lo) / 2 if a.hi < b.lo else None
    while t is None or not (a < Algebraic.rational(t) < b):
        a.refine((a.hi - a.lo) / 16)
        b.refine((b.hi - b.lo) / 16)
        t = (a.hi + b.lo) / 2
    return t


def roots_in_unit_interval(poly_text: str) -> tuple[list[Algebraic], tuple[int, int]]:
    """The roots in ]0,1[ of a printed polynomial in r (isolated), and their number counted
    by both routes: Sturm's theorem alone and python-flint's root isolation."""
    P = to_fmpz_poly(parse(poly_text))
    return Algebraic.roots(P, 0, 1), (sturm_count(P, 0, 1) - (P(1) == 0), len(flint_real_roots(P, 0, 1)))


def unique_root(poly_text: str) -> Algebraic:
    """The only root in ]0,1[ of a printed polynomial in r (r*, r2, (7-2√10)/3, ...);
    ArithmeticError when it has not exactly one there."""
    roots = Algebraic.roots(to_fmpz_poly(parse(poly_text)), 0, 1)
    if len(roots) != 1:
        raise ArithmeticError(f"{poly_text} has {len(roots)} roots in ]0,1[, not one")
    return roots[0]
