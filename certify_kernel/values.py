"""The values formulas denote: rational functions over Q in the declared variables, vectors and
matrices of them, real algebraic numbers (the printed constants 5-2√6, (7-2√10)/3, ...), and
intervals.  Every operation is exact and follows its definition (the sum and product of
polynomials, the product of matrices, the cross product); a constant made of radicals is an
algebraic number whose polynomial comes from resultants and whose root is picked by interval
arithmetic.
"""
from __future__ import annotations

from fractions import Fraction

from .intervals import root_above as _root_above
from .intervals import root_below as _root_below
from .poly import divmod_, gcd, madd, mmul, reduce_circles, resultant_in, squarefree, trim, value
from .sturm import Algebraic, count, real_roots

VARS: list[str] = ["r", "λ"]           # the declared variables, r and λ first (sign tables read (r, λ))
CIRCLES: list[tuple[int, int]] = []     # (index of cos θ, index of sin θ) for each declared angle θ


class Undefined(ValueError):
    """An operation without a value (a division by 0, an entry out of range, a type mismatch)."""


def declare(name: str) -> int:
    """The index of a variable (declared once; a statement file's `vars` line)."""
    if name not in VARS:
        VARS.append(name)
    return VARS.index(name)


def declare_angle(name: str) -> None:
    """An angle θ: the variables cos θ and sin θ, tied by cos² θ + sin² θ = 1."""
    c, s = declare(f"cos {name}"), declare(f"sin {name}")
    if (c, s) not in CIRCLES:
        CIRCLES.append((c, s))


def _pad(p: dict) -> dict:
    n = len(VARS)
    return {k + (0,) * (n - len(k)): v for k, v in p.items()} if any(len(k) < n for k in p) else p


class RF:
    """A rational function num/den of polynomials over Q (dicts exponent tuple -> Fraction over
    VARS), den ≠ 0.  Equality of two is decided by :meth:`same` (cross-multiplication, modulo the
    circles), never by the representation."""

    __slots__ = ("num", "den")

    def __init__(self, num: dict, den: dict | None = None):
        num = _pad(num)
        den = _pad(den) if den is not None else {(0,) * len(VARS): Fraction(1)}
        if not den:
            raise Undefined("division by 0")
        if len(den) == 1:                        # a monomial denominator: a constant is folded in
            (k, c), = den.items()
            if not any(k):
                num, den = {m: v / c for m, v in num.items()}, {k: Fraction(1)}
        self.num, self.den = num, den

    @classmethod
    def const(cls, c) -> RF:
        c = Fraction(c)
        return cls({(0,) * len(VARS): c} if c else {})

    @classmethod
    def var(cls, name: str) -> RF:
        if name not in VARS:
            raise Undefined(f"no variable {name}")
        k = VARS.index(name)
        return cls({tuple(1 if i == k else 0 for i in range(len(VARS))): Fraction(1)})

    def is_zero(self) -> bool:
        return not reduce_circles(self.num, CIRCLES)

    def constant(self):
        """The value as a Fraction when the function is a constant, else None."""
        if any(any(k) for k in self.den) or any(any(k) for k in self.num):
            return None
        return next(iter(self.num.values()), Fraction(0)) / next(iter(self.den.values()))

    def used(self) -> set[str]:
        """The variables that occur."""
        out = set()
        for p in (self.num, self.den):
            for k in p:
                out |= {VARS[i] for i, e in enumerate(k) if e}
        return out

    def __add__(self, o: RF) -> RF:
        if self.den == o.den:
            return RF(madd(self.num, o.num), self.den)
        return _reduce(madd(mmul(self.num, o.den), mmul(o.num, self.den)), mmul(self.den, o.den))

    def __neg__(self) -> RF:
        return RF({k: -v for k, v in self.num.items()}, self.den)

    def __sub__(self, o: RF) -> RF:
        return self + (-o)

    def __mul__(self, o: RF) -> RF:
        return _reduce(mmul(self.num, o.num), mmul(self.den, o.den))

    def inverse(self) -> RF:
        if self.is_zero():
            raise Undefined("division by 0")
        return RF(self.den, self.num)

    def __truediv__(self, o: RF) -> RF:
        return self * o.inverse()

    def __pow__(self, n: int) -> RF:
        base, out = (self, RF.const(1)) if n >= 0 else (self.inverse(), RF.const(1))
        for _ in range(abs(n)):
            out = out * base
        return out

    def same(self, o: RF, modulo=None) -> bool:
        """self ≡ o: num·den' − num'·den reduces to 0 modulo the circles (and modulo a polynomial
        monic in one variable, :func:`reduce_monic`)."""
        diff = reduce_circles(madd(mmul(self.num, o.den), mmul(o.num, self.den), -1), CIRCLES)
        if modulo is not None:
            diff = reduce_circles(reduce_monic(diff, *modulo), CIRCLES)
        return not diff

    def __repr__(self) -> str:
        return f"RF({self.num}, {self.den})"


def _reduce(num: dict, den: dict) -> RF:
    """num/den, cancelled by the gcd when both are polynomials in one and the same variable (a
    common factor changes no value where the denominator does not vanish)."""
    if num and len(den) > 1:
        used = {i for p in (num, den) for k in p for i, e in enumerate(k) if e}
        if len(used) == 1:
            (i,) = used
            n, d = _to_list(num, i), _to_list(den, i)
            g = gcd(n, d)
            if len(g) > 1:
                n, d = divmod_(n, g)[0], divmod_(d, g)[0]
                return RF(_from_list(n, i), _from_list(d, i))
    return RF(num, den)


def _to_list(p: dict, i: int) -> list:
    out = [Fraction(0)] * (max((k[i] for k in p), default=0) + 1)
    for k, v in p.items():
        out[k[i]] += v
    return trim(out)


def _from_list(c: list, i: int) -> dict:
    n = len(VARS)
    return {tuple(e if j == i else 0 for j in range(n)): v for e, v in enumerate(c) if v}


def reduce_monic(p: dict, k: int, m: dict) -> dict:
    """The remainder of p by m, m monic in variable k of degree d: λ^d ≡ −(the rest of m), applied
    to the highest power until none is left (division by a monic polynomial: no fraction; the
    remainder is 0 exactly when m divides p)."""
    d = max(key[k] for key in m)
    rest = {key: -v for key, v in m.items() if key[k] < d}
    p = dict(p)
    while True:
        top = max((key[k] for key in p), default=-1)
        if top < d:
            return p
        high = {key: v for key, v in p.items() if key[k] == top}
        for key in high:
            del p[key]
        shifted = {tuple(e - d if i == k else e for i, e in enumerate(key)): v for key, v in high.items()}
        p = madd(p, mmul(shifted, rest))


def monic_in(P: RF, name: str) -> tuple[int, dict]:
    """(index of the variable, P divided by its leading coefficient) when P is a polynomial whose
    leading coefficient in that variable is a non-zero constant (the modulus of an identity)."""
    k = VARS.index(name)
    if any(any(key) for key in P.den):
        raise Undefined("a modulus must be a polynomial")
    d = max((key[k] for key in P.num), default=0)
    lead = {key: v for key, v in P.num.items() if key[k] == d}
    unit = tuple(d if i == k else 0 for i in range(len(VARS)))
    if d < 1 or list(lead) != [unit]:
        raise Undefined(f"the modulus is not monic in {name} (up to a constant)")
    return k, {key: v / lead[unit] for key, v in P.num.items()}


# --------------------------------------------------------------- polynomials in one variable

def univariate(P: RF, name: str = "r") -> list:
    """P as a list of coefficients in one variable (lowest first): P a polynomial in it alone."""
    if P.used() - {name} or any(any(k) for k in P.den):
        raise Undefined(f"not a polynomial in {name} alone")
    c = next(iter(P.den.values()))
    return [x / c for x in _to_list(P.num, VARS.index(name))] if P.num else []


def two(P: RF) -> dict:
    """P, a polynomial in r and λ, as a dict (e_r, e_λ) -> coefficient (the sign tables' form)."""
    if P.used() - {"r", "λ"} or any(any(k) for k in P.den):
        raise Undefined("not a polynomial in r and λ")
    c = next(iter(P.den.values()))
    return {k[:2]: v / c for k, v in P.num.items()}


# --------------------------------------------------------------- real algebraic numbers

def number(x) -> Algebraic:
    """A rational or an algebraic number as an :class:`Algebraic`."""
    if isinstance(x, Algebraic):
        return x
    if isinstance(x, RF):
        c = x.constant()
        if c is None:
            raise Undefined("not a number: it has variables")
        x = c
    q = Fraction(x)
    return Algebraic([-q, Fraction(1)], q, q, check=False)


def _bivariate(p: list, q: list, how: str) -> dict:
    """The polynomial in (x, y) whose resultant in y with p(y) has the roots a ∘ b (a root of p, b
    of q): q(x − y) for a sum, y^n q(x/y) for a product (x as r, y as λ for resultant_in)."""
    out: dict = {}
    for k, c in enumerate(q):
        if not c:
            continue
        if how == "+":                      # c (x − y)^k
            binom = 1
            for j in range(k + 1):
                key = (k - j, j)
                out[key] = out.get(key, Fraction(0)) + c * binom * (-1) ** j
                binom = binom * (k - j) // (j + 1)
        else:                               # c x^k y^(n − k)
            out[(k, len(q) - 1 - k)] = out.get((k, len(q) - 1 - k), Fraction(0)) + c
    return {k: v for k, v in out.items() if v}


def _isolate(poly: list, lo: Fraction, hi: Fraction, refine) -> Algebraic:
    """The root of ``poly`` that the enclosure [lo, hi] (made narrower by ``refine()``) holds: an
    enclosure holding exactly one root of the square-free polynomial, ends not roots."""
    poly = squarefree(poly)
    for _ in range(200):
        if lo == hi and not value(poly, lo):
            return Algebraic([-lo, Fraction(1)], lo, hi, check=False)
        a, b = lo - (hi - lo) / 4 - Fraction(1, 10 ** 30), hi + (hi - lo) / 4 + Fraction(1, 10 ** 30)
        if count(poly, a, b) == 1 and value(poly, a) and value(poly, b):
            return Algebraic(poly, a, b)
        lo, hi = refine()
    raise Undefined("a root could not be isolated")


def combine(op: str, a, b) -> Algebraic:
    """a + b, a − b, a·b, a/b of real algebraic numbers: the polynomial by a resultant, the root by
    interval arithmetic on the two isolating intervals."""
    a, b = number(a), number(b)
    if op == "-":
        b = Algebraic([c * (-1) ** i for i, c in enumerate(b.p)], -b.hi, -b.lo) if not b.rational \
            else number(-b.lo)
        op = "+"
    if op == "/":
        if b.compare_rational(0) == 0:
            raise Undefined("division by 0")
        if b.rational:
            b = number(1 / b.lo)
        else:
            while b.lo <= 0 <= b.hi:
                b.bisect()
            b = Algebraic(list(reversed(b.p)), 1 / b.hi, 1 / b.lo)
        op = "*"
    if a.rational and b.rational:
        return number(a.lo + b.lo if op == "+" else a.lo * b.lo)
    pa = {(0, i): c for i, c in enumerate(a.p) if c}
    R = resultant_in(pa, _bivariate(a.p, b.p, op))

    def enclosure():
        if op == "+":
            return a.lo + b.lo, a.hi + b.hi
        ends = [x * y for x in (a.lo, a.hi) for y in (b.lo, b.hi)]
        return min(ends), max(ends)

    def refine():
        a.bisect()
        b.bisect()
        return enclosure()
    return _isolate(R, *enclosure(), refine)


def sqrt(a) -> Algebraic:
    """√a (a ≥ 0): a root of p(x²), the one in [√lo, √hi] (rational bounds of square roots)."""
    a = number(a)
    if a.compare_rational(0) < 0:
        raise Undefined("the square root of a negative number")
    p2 = [x for c in a.p for x in (c, Fraction(0))][:-1]          # p(x²)

    def bounds():
        return _root_below(max(a.lo, Fraction(0))), _root_above(max(a.hi, Fraction(0)))

    def refine():
        a.bisect()
        return bounds()
    if a.rational:
        q = a.lo
        s = _root_below(q)
        if s * s == q:
            return number(s)
    return _isolate(p2, *bounds(), refine)


def roots_in(p: list, lo, hi, lo_closed: bool = False, hi_closed: bool = False) -> list:
    """The distinct real roots of p in the interval (ends algebraic, or None for ∓∞), increasing,
    as isolated algebraic numbers (Sturm bisection of a Cauchy bound, then exact comparisons)."""
    out = []
    for a in reversed(real_roots(p)):
        left = 1 if lo is None else a.compare(number(lo))
        right = -1 if hi is None else a.compare(number(hi))
        if (left > 0 or left == 0 and lo_closed) and (right < 0 or right == 0 and hi_closed):
            out.append(a)
    return out

