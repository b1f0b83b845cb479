"""Rigorous interval arithmetic over the rationals, in the standard library alone.

An :class:`Iv` is a closed interval [lo, hi] of rationals.  Every operation returns an interval
that contains the exact result of the operation applied to every pair of points of its operands
(the enclosure property); the ends are then rounded *outward* to the dyadic grid 2^(-BITS), so
the sizes of the numbers stay bounded and the enclosure property is kept.  Comparisons are
certain: ``x.lt(y)`` is True only when every point of x is below every point of y.  Nothing here
is a float.
"""
from __future__ import annotations

from fractions import Fraction
from math import ceil, floor, isqrt

BITS = 160                     # the grid of the rounded ends: 2^-BITS


def _down(q: Fraction) -> Fraction:
    """The largest point of the grid ≤ q."""
    return Fraction(floor(q * (1 << BITS)), 1 << BITS)


def _up(q: Fraction) -> Fraction:
    """The smallest point of the grid ≥ q."""
    return Fraction(ceil(q * (1 << BITS)), 1 << BITS)


class Iv:
    """The closed interval [lo, hi] (lo ≤ hi, rationals), ends rounded outward to the grid."""

    __slots__ = ("lo", "hi")

    def __init__(self, lo, hi=None):
        lo = Fraction(lo)
        hi = lo if hi is None else Fraction(hi)
        if lo > hi:
            raise ValueError(f"an empty interval [{lo}, {hi}]")
        self.lo, self.hi = _down(lo), _up(hi)

    @classmethod
    def ball(cls, mid, rad) -> Iv:
        """[mid − |rad|, mid + |rad|]."""
        mid, rad = Fraction(mid), abs(Fraction(rad))
        return cls(mid - rad, mid + rad)

    def __repr__(self) -> str:
        return f"[{float(self.lo):.6g}, {float(self.hi):.6g}]"

    def __add__(self, o) -> Iv:
        o = _iv(o)
        return Iv(self.lo + o.lo, self.hi + o.hi)

    __radd__ = __add__

    def __neg__(self) -> Iv:
        return Iv(-self.hi, -self.lo)

    def __sub__(self, o) -> Iv:
        return self + (-_iv(o))

    def __rsub__(self, o) -> Iv:
        return _iv(o) - self

    def __mul__(self, o) -> Iv:
        o = _iv(o)
        ps = (self.lo * o.lo, self.lo * o.hi, self.hi * o.lo, self.hi * o.hi)
        return Iv(min(ps), max(ps))

    __rmul__ = __mul__

    def inverse(self) -> Iv:
        """1/x, for an interval that does not contain 0 (ZeroDivisionError otherwise)."""
        if self.lo <= 0 <= self.hi:
            raise ZeroDivisionError(f"1/x with 0 in {self}")
        return Iv(1 / self.hi, 1 / self.lo)

    def __truediv__(self, o) -> Iv:
        return self * _iv(o).inverse()

    def __rtruediv__(self, o) -> Iv:
        return _iv(o) * self.inverse()

    def __pow__(self, n: int) -> Iv:
        """x^n, n ≥ 0 (even powers of an interval across 0 start at 0)."""
        if n < 0:
            raise ValueError("a negative power: use inverse()")
        if n % 2 == 0 and self.lo < 0 < self.hi:
            return Iv(0, max(-self.lo, self.hi) ** n)
        a, b = self.lo ** n, self.hi ** n
        return Iv(min(a, b), max(a, b))

    def abs(self) -> Iv:
        """{|x|}."""
        if self.lo >= 0:
            return self
        if self.hi <= 0:
            return -self
        return Iv(0, max(-self.lo, self.hi))

    def mag(self) -> Fraction:
        """max |x| over the interval (an upper bound of every |x|)."""
        return max(-self.lo, self.hi)

    def hull(self, o) -> Iv:
        """The smallest interval holding both."""
        o = _iv(o)
        return Iv(min(self.lo, o.lo), max(self.hi, o.hi))

    def contains(self, q) -> bool:
        return self.lo <= Fraction(q) <= self.hi

    def lt(self, o) -> bool:
        """Certainly below: every point of self < every point of o."""
        return self.hi < _iv(o).lo

    def gt(self, o) -> bool:
        """Certainly above."""
        return self.lo > _iv(o).hi

    def positive(self) -> bool:
        return self.lo > 0

    def negative(self) -> bool:
        return self.hi < 0


def _iv(x) -> Iv:
    return x if isinstance(x, Iv) else Iv(x)


def root_below(q: Fraction, bits: int = 64) -> Fraction:
    """A point of the grid 2^-bits at most √q (q ≥ 0)."""
    scale = 1 << bits
    return Fraction(isqrt(q.numerator * scale * scale // q.denominator), scale)


def root_above(q: Fraction, bits: int = 64) -> Fraction:
    """A point of the grid 2^-bits at least √q (q ≥ 0)."""
    s = root_below(q, bits)
    return s if s * s >= q else s + Fraction(1, 1 << bits)


def sqrt(x: Iv) -> Iv:
    """√x for x ⊂ [0, ∞[ (ValueError for a negative point): √ is increasing."""
    if x.lo < 0:
        raise ValueError(f"√ of an interval with negative points {x}")
    return Iv(root_below(x.lo, BITS), root_above(x.hi, BITS))
