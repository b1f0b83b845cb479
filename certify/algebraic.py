"""Real algebraic numbers as (squarefree integer polynomial, isolating interval).

``Algebraic(p, lo, hi)`` is the unique root of p in ]lo, hi[ (or the rational lo
when lo == hi).  Comparisons are exact: intervals are refined until they are
disjoint, and two numbers whose intervals keep overlapping are proven equal by a
common factor of their polynomials having a root in the overlap.  Digits are
printed from certified enclosures only.
"""
from __future__ import annotations

from fractions import Fraction
from functools import total_ordering

import flint
import sympy as sp

from .poly import primitive, squarefree_part, to_fmpz_poly, show
from .sturm import count_roots, isolate, refine

Q = flint.fmpq


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
    def rational(cls, a) -> "Algebraic":
        a = Q(a) if not isinstance(a, Fraction) else Q(a.numerator, a.denominator)
        return cls(flint.fmpq_poly([-a, 1]), a, a)

    @classmethod
    def roots(cls, p, a=None, b=None) -> list["Algebraic"]:
        """The distinct real roots of p in ]a, b[, increasing (Sturm isolation)."""
        p = primitive(flint.fmpq_poly(p)) if not isinstance(p, flint.fmpz_poly) else p
        return [cls(p, lo, hi) for lo, hi in isolate(p, a, b)]

    @classmethod
    def surd(cls, a, b, n) -> "Algebraic":
        """a + b·√n for rationals a, b and a positive integer n, not a square."""
        a, b = Q(a), Q(b)
        # (t - a)^2 - b^2 n = 0
        p = flint.fmpq_poly([a * a - b * b * n, -2 * a, 1])
        roots = cls.roots(p)
        return roots[1] if b > 0 else roots[0]

    @property
    def is_rational(self) -> bool:
        return self.lo == self.hi

    def refine(self, width) -> "Algebraic":
        """Shrink the isolating interval below ``width`` (in place) and return self."""
        if not self.is_rational:
            self.lo, self.hi = refine(self.p, self.lo, self.hi, width)
        return self

    def arb(self, prec: int = 64) -> flint.arb:
        """A ball containing the number, radius about 2^-prec."""
        self.refine(Q(1, 2 ** prec))
        mid = (self.lo + self.hi) / 2
        rad = (self.hi - self.lo) / 2
        old = flint.ctx.prec
        flint.ctx.prec = max(old, prec + 20)
        try:
            return flint.arb(mid, flint.arb(rad).upper())
        finally:
            flint.ctx.prec = old

    def digits(self, n: int = 10) -> str:
        """The number rounded to n significant digits, from a certified enclosure."""
        self.refine(Q(1, 10 ** (n + 3)))
        return _fmt((self.lo + self.hi) / 2, n)

    def __float__(self) -> float:
        self.refine(Q(1, 2 ** 60))
        m = (self.lo + self.hi) / 2
        return int(m.p) / int(m.q)

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

    def _cmp(self, other: "Algebraic") -> int:
        if not isinstance(other, Algebraic):
            return self.compare_rational(other)
        if other.is_rational:
            return self.compare_rational(other.lo)
        if self.is_rational:
            return -other.compare_rational(self.lo)
        g = self.p.gcd(other.p)
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
        raise ArithmeticError("comparison did not terminate")

    def __eq__(self, other):
        return self._cmp(other) == 0

    def __lt__(self, other):
        return self._cmp(other) < 0

    def __hash__(self):
        return hash((str(self.p),))

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
        """'root of p in ]lo, hi[ ≈ digits' for the report."""
        if self.is_rational:
            return f"{self.lo}"
        return f"the root of {show(self.p)} in ]{self.lo}, {self.hi}[ ≈ {self.digits(12)}"

    def __repr__(self):
        return f"Algebraic({self.describe()})"


def _fmt(q: flint.fmpq, n: int) -> str:
    """q to n significant digits (q is a certified midpoint of a tiny interval)."""
    f = sp.Rational(int(q.p), int(q.q))
    return str(sp.Float(f, n))


def sign_at(poly, alpha: Algebraic, prec: int = 64, maxprec: int = 4096) -> int:
    """The sign of a univariate rational polynomial at an algebraic number, exact:
    0 when the polynomial and the minimal factor share the root, otherwise decided
    by ball evaluation at increasing precision."""
    P = flint.fmpq_poly(poly) if not isinstance(poly, flint.fmpq_poly) else poly
    if alpha.is_rational:
        return _sign(P(alpha.lo))
    g = primitive(P).gcd(alpha.p) if P.degree() >= 0 else flint.fmpz_poly([0])
    if g.degree() > 0 and count_roots(g, alpha.lo, alpha.hi) - (g(alpha.hi) == 0) == 1:
        return 0
    while prec <= maxprec:
        old = flint.ctx.prec
        flint.ctx.prec = prec + 20
        try:
            val = flint.arb_poly([flint.arb(c) for c in P.coeffs()])(alpha.arb(prec))
        finally:
            flint.ctx.prec = old
        if val > 0:
            return 1
        if val < 0:
            return -1
        prec *= 2
    raise ArithmeticError("sign undecided")
