"""Real roots by Sturm sequences, and real algebraic numbers (a polynomial with an isolating
interval), over Q with the standard library alone."""
from __future__ import annotations

from fractions import Fraction

from .poly import deg, derivative, enclose, gcd, integer_primitive, pseudo_remainder, sign, squarefree, trim, value

_SEQ: dict = {}


def sturm_sequence(p: list) -> list:
    """The Sturm sequence of p's square-free part s (the same distinct roots): s₀ = s, s₁ = s',
    s_{k+1} = −rem(s_{k−1}, s_k), each up to a positive factor (coprime integers).  Sturm's
    theorem: for a < b the number of roots of s in ]a, b] is V(a) − V(b), V the number of sign
    changes in the sequence (zeros dropped)."""
    key = tuple(p)
    if key not in _SEQ:
        p = squarefree(p)
        seq = [integer_primitive(p), integer_primitive(derivative(p))]
        while seq[-1] and deg(seq[-1]) > 0:
            a, b = seq[-2], seq[-1]
            rem = pseudo_remainder(a, b)       # lc(b)^k · rem(a, b), k = deg a − deg b + 1
            if not rem:
                break
            flip = -1 if b[-1] < 0 and (len(a) - len(b) + 1) % 2 else 1
            seq.append(integer_primitive([-flip * x for x in rem]))
        if len(_SEQ) > 5000:
            _SEQ.clear()
        _SEQ[key] = [s for s in seq if s]
    return _SEQ[key]


def changes(signs) -> int:
    """The sign changes of a sequence of signs, zeros dropped."""
    signs = [s for s in signs if s]
    return sum(1 for s, t in zip(signs, signs[1:]) if s != t)


def variations(seq: list, x) -> int:
    """V(x) for a sequence of integer polynomials; x None for +∞, "-inf" for −∞ (the sign of a
    polynomial there is that of its leading term).  At x = a/b (b > 0) the sign of q(x) is that of
    the integer b^deg·q(a/b) = Σ q_i a^i b^(deg − i) (Horner's rule, homogenised)."""
    if x is None or x == "-inf":
        return changes(sign(q[-1]) * (-1 if x and len(q) % 2 == 0 else 1) for q in seq)
    x, signs = Fraction(x), []
    for q in seq:
        v, bp = 0, 1
        for c in reversed(q):
            v, bp = v * x.numerator + c * bp, bp * x.denominator
        signs.append(sign(v))
    return changes(signs)


def count(p: list, a=None, b=None) -> int:
    """The number of distinct real roots of p in ]a, b] (None: −∞ or +∞), by Sturm's theorem."""
    if not p:
        raise ValueError("the zero polynomial has every number as a root")
    if deg(p) == 0:
        return 0
    seq = sturm_sequence(p)
    return variations(seq, "-inf" if a is None else a) - variations(seq, b)


class Algebraic:
    """A real algebraic number: a square-free p ∈ Q[x] and an interval ]lo, hi] holding exactly
    one root of p, lo and hi not roots (or lo = hi, a rational root)."""

    def __init__(self, p: list, lo, hi, check: bool = True):
        self.p, self.lo, self.hi = p, Fraction(lo), Fraction(hi)
        if check:
            self.validate()

    def validate(self) -> None:
        """p square-free (gcd(p, p') = 1, so Sturm counts each root once) and the interval
        isolating: one root of p in ]lo, hi], none at lo or hi (Sturm's theorem)."""
        if deg(self.p) < 1:
            raise ValueError("a constant polynomial defines no number")
        if deg(gcd(self.p, derivative(self.p))) > 0:
            raise ValueError("the polynomial is not square-free")
        if self.lo > self.hi:
            raise ValueError("empty interval")
        if self.lo == self.hi:
            if value(self.p, self.lo) != 0:
                raise ValueError(f"{self.lo} is not a root")
            return
        if value(self.p, self.lo) == 0 or value(self.p, self.hi) == 0:
            raise ValueError("an end of the interval is a root")
        n = count(self.p, self.lo, self.hi)
        if n != 1:
            raise ValueError(f"the interval holds {n} roots, not exactly one")

    @property
    def rational(self) -> bool:
        return self.lo == self.hi

    def bisect(self) -> None:
        """Halve the interval, keeping the half that holds the root (by Sturm's count), or the
        midpoint itself when p vanishes there."""
        if self.rational:
            return
        mid = (self.lo + self.hi) / 2
        if value(self.p, mid) == 0:
            self.lo = self.hi = mid
        elif count(self.p, self.lo, mid) == 1:
            self.hi = mid
        else:
            self.lo = mid

    def compare_rational(self, q) -> int:
        """sign(self − q): q outside ]lo, hi[ decides at once, else bisect (q a root of p in the
        interval is the number)."""
        q = Fraction(q)
        while True:
            if self.rational:
                return sign(self.lo - q)
            if q <= self.lo:
                return 1
            if q >= self.hi:
                return -1
            if value(self.p, q) == 0:
                return 0
            self.bisect()

    def sign_of(self, h: list) -> int:
        """The sign of h at the number: 0 exactly when gcd(h, p) has a root in ]lo, hi] (the only root
        of p there is the number); else that of an enclosure of h on the interval
        (:func:`poly.enclose`) without 0 (there is one after enough bisections, as h ≠ 0 there)."""
        tested = False
        while h:
            if self.rational:
                return sign(value(h, self.lo))
            lo, hi = enclose(h, self.lo, self.hi)
            if lo > 0 or hi < 0:
                return 1 if lo > 0 else -1
            if not tested:
                g, tested = gcd(h, self.p), True
                if deg(g) > 0 and count(g, self.lo, self.hi) == 1:
                    return 0
            for _ in range(8):
                self.bisect()
        return 0

    def compare(self, other: Algebraic) -> int:
        """sign(self − other).  Disjoint intervals decide.  If gcd of the two polynomials has
        exactly one root in the overlap, that root is a root of each in its isolating
        interval: both numbers, equal.  Else bisect both."""
        for _ in range(10_000):
            if other.rational:
                return self.compare_rational(other.lo)
            if self.rational:
                return -other.compare_rational(self.lo)
            if self.hi <= other.lo:
                return -1
            if other.hi <= self.lo:
                return 1
            g = gcd(self.p, other.p)
            lo, hi = max(self.lo, other.lo), min(self.hi, other.hi)
            if deg(g) > 0 and count(g, lo, hi) == 1:
                return 0
            self.bisect()
            other.bisect()
        raise ArithmeticError("comparison not decided in 10 000 bisections")

    def __repr__(self) -> str:
        return f"root of {self.p} in ]{self.lo}, {self.hi}]"


def real_roots(p: list) -> list:
    """The distinct real roots of p, largest first, as isolated algebraic numbers: bisection of
    ]−B, B] until each piece holds one root, by Sturm counts; B = 1 + max |p_i / p_n| bounds the
    modulus of every complex root (Cauchy)."""
    p = squarefree(trim(p))
    if deg(p) < 1:
        return []
    B = 1 + max((abs(a / p[-1]) for a in p[:-1]), default=Fraction(0))
    out, todo = [], [(-B, B, count(p, -B, B))]
    while todo:
        lo, hi, n = todo.pop()
        if n == 0:
            continue
        if n == 1:
            out.append(Algebraic(p, hi if value(p, hi) == 0 else lo, hi, check=False))
            continue
        mid = (lo + hi) / 2
        left = count(p, lo, mid)
        todo += [(lo, mid, left), (mid, hi, n - left)]
    return sorted(out, key=lambda a: a.hi, reverse=True)
