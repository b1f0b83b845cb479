"""Property tests for the exact-algebra core: Sturm sequences (certify.algebra.sturm) and
real algebraic numbers (certify.algebra.algebraic).

Every property is checked against an independent computation:

* python-flint's certified complex root isolation (``fmpz_poly.complex_roots``,
  real roots have an exactly zero imaginary part), called directly on the
  non-squarefree polynomial, with the working precision raised until every ball
  is separated from the interval ends (or the end is an exact rational root);
* SymPy's own real-root machinery (``Poly.count_roots`` on closed intervals,
  ``Poly.real_roots`` evaluated to 100+ digits, ``sqf_part``);
* exact rational evaluation.
"""
from __future__ import annotations

import itertools
from contextlib import contextmanager
from decimal import Decimal, localcontext
from fractions import Fraction

import flint
import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from certify.algebra.algebraic import Algebraic, sign_at
from certify.algebra.sturm import count_roots, flint_real_roots, isolate, refine, sturm_sequence

Q = flint.fmpq
X = sp.Symbol("x")

SETTINGS = dict(deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


# --- independent helpers ------------------------------------------------------------

def fq(a) -> flint.fmpq:
    a = Fraction(a)
    return Q(a.numerator, a.denominator)


def sr(a) -> sp.Rational:
    a = Fraction(a)
    return sp.Rational(a.numerator, a.denominator)


def frac(q) -> Fraction:
    return Fraction(int(q.p), int(q.q))


def sp_poly(p) -> sp.Poly:
    """An fmpz_poly / fmpq_poly as a SymPy Poly in x (exact)."""
    cs = []
    for c in p.coeffs():
        cs.append(sp.Rational(int(c.p), int(c.q)) if isinstance(c, flint.fmpq) else sp.Integer(int(c)))
    return sp.Poly(list(reversed(cs)) or [0], X)


def ev(p, a) -> Fraction:
    """p(a) exactly, via SymPy (not via flint)."""
    return Fraction(str(sp_poly(p).eval(sr(a))))


@contextmanager
def precision(bits):
    old = flint.ctx.prec
    flint.ctx.prec = bits
    try:
        yield
    finally:
        flint.ctx.prec = old


class Undecided(Exception):
    pass


def _where(ball, e, p) -> int:
    """+1 if the isolated root in ``ball`` is > e, -1 if < e, 0 if it is e."""
    if ball > fq(e):
        return 1
    if ball < fq(e):
        return -1
    if ev(p, e) == 0:
        return 0   # the ball isolates one root and contains the rational root e
    raise Undecided


def flint_roots_where(p, ends):
    """For each distinct real root of p (flint route), its position relative to
    each rational in ``ends``: a list of tuples of -1/0/+1."""
    p = flint.fmpz_poly(p)
    for bits in (64, 256, 1024, 4096):
        with precision(bits):
            balls = [c.real for c, _m in p.complex_roots() if c.imag.is_zero()]
            try:
                return [tuple(_where(b, e, p) for e in ends) for b in balls]
            except Undecided:
                continue
    raise AssertionError("flint balls never separated from the ends")


def flint_count(p, a=None, b=None, closed_right=True) -> int:
    ends = [e for e in (a, b) if e is not None]
    n = 0
    for pos in flint_roots_where(p, ends):
        pos = dict(zip([k for k, e in (("a", a), ("b", b)) if e is not None], pos))
        ok_a = "a" not in pos or pos["a"] > 0
        ok_b = "b" not in pos or pos["b"] < 0 or (closed_right and pos["b"] == 0)
        n += ok_a and ok_b
    return n


def sympy_count(p, a=None, b=None) -> int:
    """Distinct real roots in ]a, b] by SymPy (its count_roots is on [a, b])."""
    P = sp_poly(p)
    if P.degree() <= 0:
        return 0
    if a is None and b is None:
        return P.count_roots()
    n = P.count_roots(None if a is None else sr(a), None if b is None else sr(b))
    if a is not None and P.eval(sr(a)) == 0:
        n -= 1
    return n


def sympy_values(p, dps=110) -> list[sp.Float]:
    """The distinct real roots of p, increasing, to ``dps`` digits (SymPy CRootOf)."""
    P = p if isinstance(p, sp.Poly) else sp_poly(p)
    if P.degree() <= 0:
        return []
    S = P.sqf_part()
    return [rt.evalf(dps) for rt in S.real_roots()]


def sgn(v) -> int:
    return int(bool(v > 0)) - int(bool(v < 0))


TOL_90 = sp.Float("1e-90", 110)


def num_sign(a, b, tol=TOL_90) -> int:
    d = a - b
    return 0 if abs(d) < tol else sgn(d)


def fz(coeffs) -> flint.fmpz_poly:
    return flint.fmpz_poly(list(coeffs))


# --- strategies ---------------------------------------------------------------------

@st.composite
def polys(draw, max_degree=14, max_random_degree=8):
    """(p, rational roots of its linear factors): products of small linear and
    quadratic factors raised to random multiplicities times a random integer
    polynomial with coefficients in [-20, 20]."""
    budget = max_degree
    p = fz([1])
    rat = []
    for _ in range(draw(st.integers(0, 3))):
        if budget < 1:
            break
        a, b = draw(st.integers(1, 6)), draw(st.integers(-12, 12))
        m = draw(st.integers(1, min(3, budget)))
        p *= fz([b, a]) ** m
        budget -= m
        rat.append(Fraction(-b, a))
    for _ in range(draw(st.integers(0, 2))):
        if budget < 2:
            break
        a, b, c = draw(st.integers(1, 4)), draw(st.integers(-10, 10)), draw(st.integers(-10, 10))
        m = draw(st.integers(1, min(3, budget // 2)))
        p *= fz([c, b, a]) ** m
        budget -= 2 * m
        if b * b - 4 * a * c == 0:
            rat.append(Fraction(-b, 2 * a))
    coeffs = draw(st.lists(st.integers(-20, 20), min_size=1,
                           max_size=1 + min(max_random_degree, budget)).filter(any))
    p *= fz(coeffs)
    return p, rat


def ends(rat):
    base = st.fractions(min_value=-15, max_value=15, max_denominator=16)
    return st.one_of(base, st.sampled_from(rat)) if rat else base


as_fmpq = st.sampled_from([Fraction(1), Fraction(-1), Fraction(3, 7), Fraction(-22, 5)])


def scaled(p, s):
    """p times a nonzero rational, as fmpq_poly (same roots)."""
    return flint.fmpq_poly(p) * fq(s)


# --- 1. Sturm counts vs flint vs SymPy ---------------------------------------------

@settings(max_examples=60, **SETTINGS)
@given(polys(), as_fmpq)
def test_count_roots_on_R(pr, s):
    p, _ = pr
    n = count_roots(scaled(p, s))
    roots = p.complex_roots()
    assert sum(m for _c, m in roots) == p.degree()
    n_flint = sum(1 for c, _m in roots if c.imag.is_zero())
    assert n == n_flint == sympy_count(p)
    assert n == len(sympy_values(p, 15))


@settings(max_examples=80, **SETTINGS)
@given(st.data())
def test_count_roots_on_intervals(data):
    p, rat = data.draw(polys())
    a, b = data.draw(ends(rat)), data.draw(ends(rat))
    assume(a != b)
    a, b = min(a, b), max(a, b)
    s = data.draw(as_fmpq)
    n = count_roots(scaled(p, s), fq(a), fq(b))
    assert n == sympy_count(p, a, b) == flint_count(p, a, b)
    # half-lines, with the same endpoint conventions (]a, +inf[ and ]-inf, b])
    assert count_roots(p, fq(a), None) == flint_count(p, a, None) == sympy_count(p, a, None)
    assert count_roots(p, None, fq(b)) == flint_count(p, None, b) == sympy_count(p, None, b)
    # an endpoint at a rational root: excluded on the left, included on the right
    for r in rat:
        if a < r < b:
            assert count_roots(p, fq(r), fq(b)) == count_roots(p, fq(a), fq(b)) - count_roots(p, fq(a), fq(r))
            assert count_roots(p, fq(a), fq(r)) == flint_count(p, a, r) >= 1


# --- 2. isolate / refine ------------------------------------------------------------

def check_isolation(p, ivs, a, b):
    S = sp_poly(p).sqf_part()
    for (lo, hi), (lo2, hi2) in zip(ivs, ivs[1:]):
        assert hi <= lo2 and (lo, hi) != (lo2, hi2), "intervals overlap or are not increasing"
    for lo, hi in ivs:
        if a is not None:
            assert lo >= fq(a) and (lo > fq(a) or hi > lo)
        if b is not None:
            assert hi <= fq(b) and (hi < fq(b) or hi > lo)
        if lo == hi:
            assert ev(p, frac(lo)) == 0
        else:
            assert lo < hi
            slo, shi = S.eval(sr(frac(lo))), S.eval(sr(frac(hi)))
            assert slo != 0 and shi != 0 and sgn(slo) != sgn(shi)
            assert count_roots(p, lo, hi) == 1
            assert sympy_count(p, frac(lo), frac(hi)) == 1
    # each real root of p in ]a, b[ (flint route) lies in exactly one interval
    pts = []
    for lo, hi in ivs:
        pts += [frac(lo), frac(hi)]
    where = flint_roots_where(p, ([a] if a is not None else []) + ([b] if b is not None else []) + pts)
    off = (a is not None) + (b is not None)
    inside = 0
    for pos in where:
        if a is not None and pos[0] <= 0:
            continue
        if b is not None and pos[off - 1] >= 0:
            continue
        inside += 1
        hits = 0
        for k, (lo, hi) in enumerate(ivs):
            plo, phi = pos[off + 2 * k], pos[off + 2 * k + 1]
            hits += (plo == 0) if lo == hi else (plo > 0 and phi < 0)
        assert hits == 1
    assert inside == len(ivs)


@settings(max_examples=60, **SETTINGS)
@given(st.data())
def test_isolate(data):
    p, rat = data.draw(polys())
    a = data.draw(st.none() | ends(rat))
    b = data.draw(st.none() | ends(rat))
    if a is not None and b is not None:
        assume(a != b)
        a, b = min(a, b), max(a, b)
    ivs = isolate(p, None if a is None else fq(a), None if b is None else fq(b))
    check_isolation(p, ivs, a, b)
    # total = Sturm count of the open interval = SymPy's = flint's
    expected = count_roots(p, None if a is None else fq(a), None if b is None else fq(b))
    if b is not None and ev(p, b) == 0:
        expected -= 1
    assert len(ivs) == expected == flint_count(p, a, b, closed_right=False)

    # refine: below the width, still isolating the same root
    S = sp_poly(p).sqf_part()
    sqf = flint.fmpq_poly([fq(Fraction(str(c))) for c in reversed(S.all_coeffs())])
    widths = [Fraction(1, 2 ** k) for k in (1, 7, 30, 70)] + [Fraction(1, 3), Fraction(1, 10 ** 9)]
    w = data.draw(st.sampled_from(widths))
    for lo, hi in ivs:
        l2, h2 = refine(sqf, lo, hi, fq(w))
        assert lo <= l2 <= h2 <= hi and h2 - l2 <= fq(w)
        if l2 == h2:
            assert ev(p, frac(l2)) == 0
        else:
            assert sgn(S.eval(sr(frac(l2)))) * sgn(S.eval(sr(frac(h2)))) == -1
            assert count_roots(p, l2, h2) == 1
    ivw = isolate(p, None if a is None else fq(a), None if b is None else fq(b), width=fq(w))
    assert len(ivw) == len(ivs)
    assert all(hi - lo <= fq(w) for lo, hi in ivw)
    check_isolation(p, ivw, a, b)


@settings(max_examples=25, **SETTINGS)
@given(polys(max_degree=10))
def test_flint_real_roots_route(pr):
    """The second route in certify.algebra.sturm agrees with the Sturm isolation."""
    p, _ = pr
    ivs = isolate(p)
    balls = flint_real_roots(p)
    assert len(balls) == len(ivs)
    for (lo, hi), ball in zip(ivs, balls):
        if lo == hi:
            with precision(1024):      # lo as a tight ball (it may not be a dyadic)
                assert ball.contains(flint.arb(lo))
        else:
            assert not ball < lo and not ball > hi


# --- 3. Algebraic comparisons vs 100-digit values ----------------------------------

@st.composite
def related_pairs(draw):
    """Two polynomials sharing a factor (often), so that some roots coincide."""
    f, _ = draw(polys(max_degree=4, max_random_degree=3))
    g1, _ = draw(polys(max_degree=5, max_random_degree=4))
    g2, _ = draw(polys(max_degree=5, max_random_degree=4))
    m1, m2 = draw(st.integers(1, 2)), draw(st.integers(0, 2))
    return f ** m1 * g1, f ** m2 * g2


@settings(max_examples=40, **SETTINGS)
@given(related_pairs(), st.data())
def test_algebraic_comparisons(pq, data):
    p, q = pq
    A, B = Algebraic.roots(p), Algebraic.roots(q)
    va, vb = sympy_values(p), sympy_values(q)
    assert len(A) == len(va) and len(B) == len(vb)
    for x, y in zip(A, A[1:]):
        assert x < y and not x == y
    pairs = list(itertools.product(range(len(A)), range(len(B))))
    if len(pairs) > 30:
        pairs = data.draw(st.lists(st.sampled_from(pairs), min_size=30, max_size=30))
    for i, j in pairs:
        expect = num_sign(va[i], vb[j])
        x, y = A[i], B[j]
        assert (x == y) == (expect == 0)
        assert (x < y) == (expect < 0)
        assert (y < x) == (expect > 0)
        assert (x > y) == (expect > 0)
        assert (x <= y) == (expect <= 0)
        if expect == 0:
            assert hash(x) == hash(y)
        # fresh objects (unrefined) give the same answers
        assert Algebraic(x.p, x.lo, x.hi)._cmp(Algebraic(y.p, y.lo, y.hi)) == expect
    # the shared roots: each root of p * q appears in both lists when it is a root of both
    common = [v for v in va if any(num_sign(v, w) == 0 for w in vb)]
    assert len({*A} & {*B}) == len(common)


@settings(max_examples=40, **SETTINGS)
@given(polys(max_degree=10), st.data())
def test_compare_rational(pr, data):
    p, rat = pr
    A = Algebraic.roots(p)
    va = sympy_values(p)
    assume(A)
    k = data.draw(st.integers(0, len(A) - 1))
    alpha, v = A[k], va[k]
    cands = [frac(alpha.lo), frac(alpha.hi), (frac(alpha.lo) + frac(alpha.hi)) / 2] + rat
    cands += data.draw(st.lists(ends(rat), max_size=4))
    for c in cands:
        expect = num_sign(v, sr(c))
        assert Algebraic(alpha.p, alpha.lo, alpha.hi).compare_rational(fq(c)) == expect
        assert (alpha == Algebraic.rational(fq(c))) == (expect == 0)
        assert (alpha < Algebraic.rational(fq(c))) == (expect < 0)
    # arb(): a ball around the number, of the requested size
    ball = alpha.arb(200)
    assert ball.rad() <= flint.arb(2) ** -190
    with precision(600):
        exact = flint.arb(str(v), flint.arb(10) ** -120)
    assert ball.overlaps(exact)


@settings(max_examples=30, **SETTINGS)
@given(st.integers(-20, 20), st.integers(-9, 9).filter(bool), st.sampled_from([2, 3, 5, 6, 7, 10, 11, 13]),
       st.integers(-20, 20), st.integers(-9, 9).filter(bool), st.sampled_from([2, 3, 5, 6, 7, 10]),
       st.integers(1, 3))
def test_surds(a, b, n, c, d, m, k):
    x, y = Algebraic.surd(a, b, n), Algebraic.surd(c, d, m)
    vx = sp.Integer(a) + b * sp.sqrt(n)
    vy = sp.Integer(c) + d * sp.sqrt(m)
    expect = num_sign(vx.evalf(110), vy.evalf(110))
    assert (x == y) == (expect == 0) and (x < y) == (expect < 0) and (y < x) == (expect > 0)
    # the same number written differently: a + (b k) √n = a + b √(n k²)
    z = Algebraic.surd(a, b * k, n)
    w = Algebraic.surd(a, b, n * k * k)
    assert z == w and not z < w and not w < z and hash(z) == hash(w)
    # rational shifts
    assert Algebraic.surd(fq(Fraction(a, 3)), b, n) < Algebraic.surd(fq(Fraction(a, 3) + Fraction(1, 10 ** 30)), b, n)


def test_surd_examples():
    r = Algebraic.roots(fz([1, -10, 1]), 0, 1)
    assert len(r) == 1
    s = Algebraic.surd(5, -2, 6)
    assert s == r[0] and r[0] == s and hash(s) == hash(r[0])
    big = fz([41, -646, 3733, -14600, 42306, -78052, 42306, -14600, 3733, -646, 41])
    roots = Algebraic.roots(big, 0, 1)
    assert len(roots) == 1
    assert s < roots[0] and not roots[0] < s and not s == roots[0]
    assert roots[0].in_rounding_interval("0.11384")
    assert not roots[0].in_rounding_interval("0.11383")
    assert not roots[0].in_rounding_interval("0.11385")
    assert roots[0].digits(5) == "0.11384"
    assert Algebraic.surd(7, -4, 3) < Algebraic.surd(3, -2, 2)
    assert not Algebraic.surd(3, -2, 2) < Algebraic.surd(7, -4, 3)
    # the same root of p and of p * q, where q has a root close by
    p = fz([-2, 0, 1])
    q = fz([-141421356237, 100000000000])   # 1.41421356237 < √2
    a, b = Algebraic.roots(p)[1], Algebraic.roots(p * q * p)[2]
    assert a == b and hash(a) == hash(b) and len({a, b}) == 1
    assert Algebraic.roots(p * q)[1] < a


def test_equal_rational_with_wide_interval():
    """A rational number given by a non-degenerate isolating interval equals the
    same rational given exactly, and compares correctly with its neighbours."""
    half = Algebraic(fz([-1, 2]) * fz([-7, 1]), 0, Q(3, 4))
    assert half == Algebraic.rational(Fraction(1, 2))
    assert Algebraic.rational(Fraction(1, 2)) == half
    assert half == Algebraic(fz([-1, 2]) * fz([-2, 0, 1]), Q(1, 3), 1)
    assert half < Algebraic.surd(0, 1, 2) and Algebraic.surd(0, Fraction(1, 3), 2) < half
    assert half.compare_rational(Q(1, 2)) == 0
    assert half.digits(3) == "0.500"
    assert len({half, Algebraic.rational(Fraction(1, 2))}) == 1


# --- 4. rounding intervals and digits ------------------------------------------------

def correctly_rounded(v: sp.Float, k: int):
    """(string with k decimals, distance to the nearest rounding boundary in units of
    the last digit), from a 120-digit value."""
    with localcontext() as ctx:
        ctx.prec = 150
        d = Decimal(str(v)) * (Decimal(10) ** k)
        fl = d.to_integral_value(rounding="ROUND_FLOOR")
        gap = abs(d - fl - Decimal("0.5"))
        D = int(fl) + (1 if d - fl > Decimal("0.5") else 0)
    return D, float(gap)


def fmt(D: int, k: int) -> str:
    sign = "-" if D < 0 else ""
    D = abs(D)
    return f"{sign}{D // 10 ** k}.{D % 10 ** k:0{k}d}" if k else f"{sign}{D}"


@st.composite
def algebraic_with_value(draw, max_degree=10):
    p, _ = draw(polys(max_degree=max_degree))
    A = Algebraic.roots(p)
    assume(A)
    k = draw(st.integers(0, len(A) - 1))
    return A[k], sympy_values(p, 130)[k]


@settings(max_examples=60, **SETTINGS)
@given(algebraic_with_value(), st.integers(0, 14))
def test_in_rounding_interval(av, k):
    alpha, v = av
    D, gap = correctly_rounded(v, k)
    assume(gap > 1e-30)            # not (numerically) on a rounding boundary
    assert alpha.in_rounding_interval(fmt(D, k))
    assert not alpha.in_rounding_interval(fmt(D + 1, k))
    assert not alpha.in_rounding_interval(fmt(D - 1, k))


def test_in_rounding_interval_exact_boundaries():
    eighth = Algebraic.rational(Fraction(1, 8))
    assert eighth.in_rounding_interval("0.125")
    assert eighth.in_rounding_interval("0.12") and eighth.in_rounding_interval("0.13")  # closed interval
    assert not eighth.in_rounding_interval("0.11") and not eighth.in_rounding_interval("0.14")
    neg = -Fraction(2, 3)
    a = Algebraic(fz([2, 3]) * fz([-5, 0, 1]), -1, 0)
    assert a == Algebraic.rational(neg)
    assert a.in_rounding_interval("-0.667") and a.in_rounding_interval("-0.7") and a.in_rounding_interval("-1")
    assert not a.in_rounding_interval("-0.666") and not a.in_rounding_interval("-0.6")


@settings(max_examples=60, **SETTINGS)
@given(algebraic_with_value(max_degree=8), st.integers(1, 12), st.integers(-12, 12))
def test_digits(av, n, e):
    """digits(n): the number rounded to n significant digits, also for numbers far
    from 1 (scaled by 10^e through the polynomial: p(10^e x) has roots α 10^-e)."""
    alpha, v = av
    assume(v != 0)
    s = fq(Fraction(10) ** e)
    P = flint.fmpq_poly([c * s ** i for i, c in enumerate(alpha.p.coeffs())])
    beta = Algebraic(P, alpha.lo / s, alpha.hi / s)
    w = v * sp.Rational(10) ** (-e)
    with localcontext() as ctx:
        ctx.prec = 150
        dw = Decimal(str(w))
        E = dw.adjusted()
    D, gap = correctly_rounded(w, n - 1 - E)
    assume(gap > 1e-30)
    got = beta.digits(n)
    with localcontext() as ctx:
        ctx.prec = 150
        want = Decimal(D).scaleb(-(n - 1 - E))
        assert Decimal(got) == want, (got, str(want))
    assert float(beta) == pytest.approx(float(w), rel=1e-15)


def test_digits_examples():
    assert Decimal(Algebraic.surd(0, Q(1, 10 ** 6), 2).digits(10)) == Decimal("1.414213562e-6")
    assert Decimal(Algebraic.surd(0, -Q(1, 10 ** 40), 3).digits(4)) == Decimal("-1.732e-40")
    # just below / above the tie 1.255 (3 digits)
    assert Algebraic.surd(Q(251, 200), -Q(1, 10 ** 12), 2).digits(3) == "1.25"
    assert Algebraic.surd(Q(251, 200), Q(1, 10 ** 12), 2).digits(3) == "1.26"
    assert Algebraic.surd(Q(-251, 200), Q(1, 10 ** 12), 2).digits(3) == "-1.25"
    # a rational on a tie, given by a wide interval, prints like the exact rational
    eighth = Algebraic(fz([-1, 8]) * fz([-7, 1]), 0, Q(1, 2))
    assert eighth.digits(2) == Algebraic.rational(Q(1, 8)).digits(2)
    assert Decimal(eighth.digits(2)) in (Decimal("0.12"), Decimal("0.13"))
    assert float(Algebraic.surd(0, Q(1, 10 ** 30), 2)) == pytest.approx(2 ** 0.5 * 1e-30, rel=1e-15)



def test_digits_compares_roundings_not_texts():
    # digits stops when both ends round to one value (_rounded), then prints it (_fmt): the
    # roundings are equal exactly when the texts are, across a power of ten (9.99… and 10.0
    # are one value), ties (half to even), signs and zero
    from certify.algebra.algebraic import _fmt, _rounded
    cases = [(Q(99999996, 10 ** 7), Q(10)), (Q(99999994, 10 ** 7), Q(10)), (Q(1255, 1000), Q(1265, 1000)),
             (Q(125, 100), Q(1251, 1000)), (Q(-1255, 1000), Q(-125, 100)), (Q(0), Q(1, 10 ** 30)),
             (Q(1, 8), Q(3, 24)), (Q(12345678, 10 ** 9), Q(123456781, 10 ** 10))]
    for n in (2, 3, 6):
        for a, b in cases:
            assert (_rounded(a, n) == _rounded(b, n)) == (_fmt(a, n) == _fmt(b, n)), (a, b, n)
    assert _rounded(Q(99999996, 10 ** 7), 6) == _rounded(Q(10), 6) == (1, 1)
    # the text digits returns is that of both ends of the refined interval
    for beta in (Algebraic.surd(Q(251, 200), -Q(1, 10 ** 12), 2), Algebraic.surd(10, -Q(1, 10 ** 9), 2)):
        for n in (3, 6, 10):
            t = beta.digits(n)
            assert t == _fmt(beta.lo, n) == _fmt(beta.hi, n)


# --- 5. sign_at ----------------------------------------------------------------------

@settings(max_examples=60, **SETTINGS)
@given(algebraic_with_value(max_degree=8),
       st.lists(st.integers(-20, 20), min_size=1, max_size=7),
       st.integers(-5, 5), st.sampled_from(["random", "multiple", "shift", "close"]))
def test_sign_at(av, coeffs, c, kind):
    alpha, v = av
    h = fz(coeffs)
    if kind == "random":
        P = flint.fmpq_poly(h) * Q(3, 7)
        val = sp_poly(P).as_expr().subs(X, v)
        expect = num_sign(val, 0, sp.Float("1e-80", 110))
        if expect == 0:      # a genuine common root: confirm exactly with SymPy's gcd
            g = sp.gcd(sp_poly(P), sp_poly(alpha.p))   # a SymPy Poly
            assert any(num_sign(w, v) == 0 for w in sympy_values(g))
    elif kind == "multiple":
        # a multiple of the defining polynomial (the zero polynomial when h = 0): P(α) = 0
        P = flint.fmpq_poly(alpha.p * h) * Q(-5, 3)
        expect = 0
    elif kind == "shift":
        # P = p·h + c with p(α) = 0: P(α) = c exactly
        P = flint.fmpq_poly(alpha.p * h + c)
        expect = sgn(c)
    else:
        # (x - q)·c for a rational q within 2^-300 of α: the ball precision must grow
        t = Algebraic(alpha.p, alpha.lo, alpha.hi).refine(Q(1, 2 ** 300))
        q = t.lo if c % 2 else t.hi
        P = flint.fmpq_poly([-q, 1]) * (c or 1)
        expect = num_sign((v - sr(frac(q))) * (c or 1), 0, sp.Float("1e-125", 130))
        assume(expect != 0 or t.is_rational)
    assert sign_at(P, alpha) == expect
    if not alpha.is_rational:
        assert sign_at(P, Algebraic.rational(alpha.lo)) == sgn(ev(P, frac(alpha.lo)))


def test_sign_at_zero_polynomial():
    a = Algebraic.surd(1, 1, 2)
    assert sign_at(flint.fmpq_poly([0]), a) == 0
    assert sign_at(flint.fmpq_poly([0]), Algebraic.rational(3)) == 0


# --- plain unit tests ----------------------------------------------------------------

def test_count_roots_multiple_roots():
    p = fz([-1, 1]) ** 3 * fz([2, 1]) ** 2
    assert count_roots(p) == 2
    assert count_roots(p, -2, 1) == 1        # ]-2, 1]: 1 in, -2 out
    assert count_roots(p, -3, -2) == 1
    assert count_roots(p, 1, 5) == 0
    assert count_roots(p, Q(-5, 2), Q(3, 2)) == 2
    assert sturm_sequence(p)[0].degree() == 2


def test_isolate_sqrt2():
    ivs = isolate(fz([-2, 0, 1]), 0, 2)
    assert len(ivs) == 1
    lo, hi = ivs[0]
    assert 0 <= lo < hi <= 2 and lo * lo < 2 < hi * hi
    lo, hi = refine(fz([-2, 0, 1]), lo, hi, Q(1, 10 ** 12))
    assert hi - lo <= Q(1, 10 ** 12) and lo * lo < 2 < hi * hi


def test_isolate_rational_root_at_midpoint():
    # x^3 - 2x on its Cauchy interval ]-3, 3[: the first midpoint 0 is a root
    ivs = isolate(fz([0, -2, 0, 1]))
    assert (Q(0), Q(0)) in ivs and len(ivs) == 3
    # a root hit by a later bisection: (4x - 1)(x - 3) on ]-1, 1[ ∪ ... : ]0, 1[ has
    # midpoints 1/2, 1/4
    ivs = isolate(fz([-1, 4]) * fz([-1, 2]), 0, 1)
    assert (Q(1, 4), Q(1, 4)) in ivs and (Q(1, 2), Q(1, 2)) in ivs and len(ivs) == 2
    # roots at the ends of ]a, b[ are excluded
    assert isolate(fz([-1, 4]) * fz([-1, 2]), Q(1, 4), Q(1, 2)) == []
    assert len(isolate(fz([-1, 4]) * fz([-1, 2]), Q(1, 4), 1)) == 1


def test_flint_route_undecided_at_root_endpoint():
    with pytest.raises(ValueError):
        flint_real_roots(fz([-1, 1]) * fz([-2, 0, 1]), 1, 2)
    assert len(flint_real_roots(fz([-1, 1]) * fz([-2, 0, 1]), Q(1, 2), 2)) == 2


# --- ordering certified balls exactly (no float decides) -----------------------------

EPS = Q(1, 10 ** 25)          # two roots that agree to 24 digits: equal as floats


def test_ordered_balls_that_agree_to_20_digits():
    """Balls around 1/3 and 1/3 + 10^-25 given in the wrong order: their floats tie, so a
    float key keeps the wrong order; the exact ends order them, and overlap is refused."""
    from certify.algebra.balls import ends, ordered
    with precision(200):
        lo, hi = flint.arb(Q(1, 3)), flint.arb(Q(1, 3) + EPS)
        assert float(lo.mid()) == float(hi.mid())
        assert sorted([hi, lo], key=lambda z: float(z.mid()))[0] is hi       # what a float key did
        assert ordered([hi, lo]) == [lo, hi] and ordered([lo, hi], reverse=True) == [hi, lo]
        a, b = ends(lo)
        assert a <= Q(1, 3) <= b and b < ends(hi)[0]
    with precision(64):                      # at 64 bits the two balls overlap: undecided
        assert ordered([flint.arb(Q(1, 3) + EPS), flint.arb(Q(1, 3))]) is None


def test_tight_is_decided_exactly():
    """rad < 2^-40 |mid| on the exact rationals: with mid = 1 + 2^-60, rad = 2^-40 the
    float of mid is 1.0 and a float test says "not tight"; exactly it is tight."""
    from certify.algebra.balls import tight
    with precision(128):
        z = flint.arb((2 ** 60 + 1, -60), (1, -40))                           # exact mid and rad
        assert z.rad().fmpq() == Q(1, 2 ** 40) and z.mid().fmpq() == Q(1) + Q(1, 2 ** 60)
        assert float(z.rad()) / float(z.mid()) == 2.0 ** -40                # the float test: not < 2^-40
        assert tight(z, 40) and not tight(z, 41)
        assert not tight(flint.arb((1, 0), (1, -40)), 40)                    # equality is not tight
        assert tight(flint.arb((0, 0), (1, -41)), 40) and not tight(flint.arb((0, 0), (1, -40)), 40)


def test_flint_real_roots_ordered_when_they_agree_to_20_digits():
    """Three roots within 10^-25 of 1/3: increasing, each ball holding its root."""
    roots = [Q(1, 3) - EPS, Q(1, 3), Q(1, 3) + EPS]
    p = flint.fmpq_poly([1])
    for z in reversed(roots):
        p *= flint.fmpq_poly([-z, 1])
    balls = flint_real_roots(p)
    assert len(balls) == 3 and len({float(b.mid()) for b in balls}) == 1
    from certify.algebra.balls import ends
    assert all(ends(b)[0] <= z <= ends(b)[1] for b, z in zip(balls, roots))


def test_numberfield_names_close_branches_in_order():
    """Over K = Q(√2): f = (λ - 1/3)(λ - 1/3 - 10^-25)(λ - 1/3 - √2·10^-30) has three real
    roots equal as floats; real_roots gives them largest first, as the branches are named."""
    from certify.algebra import numberfield as nf
    from certify.algebra.poly import lam, r
    alpha = Algebraic.surd(0, 1, 2)
    m = nf.modulus(alpha)
    third, eps = sp.Rational(1, 3), sp.Rational(1, 10 ** 25)
    f = nf.kpoly(sp.expand((lam - third) * (lam - third - eps) * (lam - third - r * eps / 10 ** 5)), m)
    prec, balls = 64, None
    while balls is None and prec <= 4096:
        balls = nf.real_roots(f, alpha, prec)
        prec *= 2
    assert balls is not None and len(balls) == 3 and len({float(b.mid()) for b in balls}) == 1
    with precision(400):
        s2 = flint.arb(2).sqrt()
        values = [flint.arb(Q(1, 3) + EPS), flint.arb(Q(1, 3)) + s2 * flint.arb(EPS / 10 ** 5), flint.arb(Q(1, 3))]
        assert all(b.overlaps(v) for b, v in zip(balls, values))          # upper, middle, lower
        assert all(b > c for b, c in zip(balls, balls[1:]))


@pytest.mark.parametrize("refined", [0, 13, 20, 47])
def test_describe_depends_on_the_number_only(refined):
    """The report prints an algebraic number the same way however far its isolating
    interval was refined before (a run on several processes refines in another order)."""
    def numbers():
        return [Algebraic.surd(sp.Rational(7, 3), sp.Rational(-2, 3), 10), Algebraic.surd(5, -2, 6),
                Algebraic.surd(3, -2, 2)]
    for a, b in zip(numbers(), numbers()):
        if refined:
            a.refine(flint.fmpq(1, 10 ** refined))
        assert a.describe() == b.describe()


# --------------------------------------------------------------- two routes to real roots
from certify.algebra.sturm import checked_real_root_count, sturm_count  # noqa: E402

_root = st.fractions(min_value=-3, max_value=3, max_denominator=50)


@settings(max_examples=60, deadline=None, database=None)
@given(st.lists(st.tuples(_root, st.integers(1, 3)), min_size=0, max_size=5),
       st.integers(0, 2), st.integers(1, 40), _root, _root)
def test_the_sturm_count_and_python_flint_count_the_known_roots(roots, quadratics, gap, a, b):
    """p = Π (r - ρ_i)^{m_i} · (r - ρ_0 - 10^-gap) · Π (r² + k): distinct real roots known
    exactly (multiple factors, two roots 10^-gap apart, factors without real roots).
    The pure Sturm count over the line and in ]a, b], python-flint's count, and the
    checked count all give them."""
    p = flint.fmpq_poly([1])
    distinct = set()
    for rho, m in roots:
        p *= flint.fmpq_poly([-flint.fmpq(rho.numerator, rho.denominator), 1]) ** m
        distinct.add(Fraction(rho))
    if roots:
        close = Fraction(roots[0][0]) + Fraction(1, 10 ** gap)
        p *= flint.fmpq_poly([-flint.fmpq(close.numerator, close.denominator), 1])
        distinct.add(close)
    for k in range(1, quadratics + 1):
        p *= flint.fmpq_poly([k, 0, 1])
    assert sturm_count(p) == len(flint_real_roots(p)) == checked_real_root_count(p) == len(distinct)
    lo, hi = min(a, b), max(a, b)
    inside = sum(1 for rho in distinct if lo < rho <= hi)
    assert sturm_count(p, flint.fmpq(lo.numerator, lo.denominator), flint.fmpq(hi.numerator, hi.denominator)) == inside


def test_the_sturm_count_calls_no_root_finder(monkeypatch):
    """The first route is Sturm's theorem alone: it still counts with python-flint's root
    isolation made unavailable (and the checked count then fails loudly)."""
    import certify.algebra.sturm as sturm
    p = flint.fmpq_poly([-2, 0, 1]) * flint.fmpq_poly([-3, 1])            # (r² - 2)(r - 3)

    def refuse(*args, **kwargs):
        raise AssertionError("root finder called")
    monkeypatch.setattr(flint.fmpz_poly, "complex_roots", refuse, raising=False)
    monkeypatch.setattr(flint.fmpq_poly, "complex_roots", refuse, raising=False)
    monkeypatch.setattr(sturm, "_BALLS", {})
    assert sturm.sturm_count(p) == 3 and sturm.sturm_count(p, 0, 2) == 1


def test_a_disagreement_of_the_two_routes_is_an_error(monkeypatch):
    import certify.algebra.sturm as sturm
    p = flint.fmpq_poly([-5, 0, 1])
    monkeypatch.setattr(sturm, "flint_real_roots", lambda q: [flint.arb(1)])
    monkeypatch.setattr(sturm, "_CHECKED", {})
    with pytest.raises(ArithmeticError, match="disagree"):
        sturm.checked_real_root_count(p)


@settings(max_examples=200, deadline=None, database=None)
@given(st.lists(st.sampled_from([0, 0, 1, -1, 2, -7, 13, -100, 10 ** 20 + 1]), min_size=1, max_size=9))
def test_show_writes_an_integer_polynomial_as_sympy_prints_it(coeffs):
    """The direct printer of integer polynomials gives SymPy's text, in the paper's notation."""
    from certify.algebra.poly import from_flint, show
    p = flint.fmpz_poly(coeffs)
    printed = sp.sstr(sp.sympify(from_flint(p)), order="lex").replace("**", "^").replace("*", "")
    assert show(p) == show(flint.fmpq_poly(p)) == printed


# ---------------------------------------------------------------- helpers moved here from the proofs
def test_roots_in_unit_interval_unique_root_and_constant_multiples():
    from certify.algebra import divides, roots_in_unit_interval, same_up_to_constant, unique_root
    roots, counts = roots_in_unit_interval("r^2 - 10*r + 1")        # 5 ± 2√6: one in ]0,1[
    assert counts == (1, 1) and len(roots) == 1 and roots[0] == Algebraic.surd(5, -2, 6)
    assert unique_root("r^2 - 10*r + 1") == roots[0] and unique_root("r^2 - 10*r + 1").short() == "≈0.10102051"
    half = Algebraic.rational(flint.fmpq(1, 2))
    assert half.short() == "1/2" and unique_root("2*r - 1") == half
    with pytest.raises(ArithmeticError):
        unique_root("(2*r - 1)*(3*r - 1)")
    assert same_up_to_constant(flint.fmpq_poly([1, 2]), flint.fmpq_poly([-3, -6]))
    assert not same_up_to_constant(flint.fmpq_poly([1, 2]), flint.fmpq_poly([1, 3]))
    assert divides(flint.fmpq_poly([1, 2]), flint.fmpq_poly([1, 2]) * flint.fmpq_poly([5, 1, 7]))
    assert not divides(flint.fmpq_poly([1, 2]), flint.fmpq_poly([1, 3]))


@pytest.mark.parametrize("a, b", [(2, 0), (1, 1), (0, -1)])
def test_isolate_refuses_an_empty_or_reversed_interval(a, b):
    """isolate(p, a, b) with a ≥ b: a ValueError at once (it used to bisect for ever)."""
    with pytest.raises(ValueError, match="empty or reversed"):
        isolate(flint.fmpq_poly([-1, 0, 1]), fq(a), fq(b))


def test_isolate_with_one_end_omitted_beyond_the_roots():
    """An omitted end is taken beyond the roots and beyond the other end: ]-∞, -5[ and ]5, ∞[
    hold no root of x² - 1 (its Cauchy bound is 2), ]-∞, 0[ and ]0, ∞[ one each."""
    p = flint.fmpq_poly([-1, 0, 1])
    assert isolate(p, None, fq(-5)) == [] and isolate(p, fq(5), None) == []
    assert len(isolate(p, None, fq(0))) == 1 and len(isolate(p, fq(0), None)) == 1


def test_one_polynomial_nested_intervals_are_one_number_and_others_are_not():
    # Algebraic._cmp: a copy refined apart from its original is equal to it; the other roots
    # of the same polynomial (disjoint or overlapping intervals) are not
    import copy

    import flint

    from certify.algebra.algebraic import Algebraic
    p = flint.fmpq_poly([-2, 0, 0, 1]) * flint.fmpq_poly([-3, 0, 1])     # ∛2 ≈ 1.26, ±√3
    lo, mid, hi = Algebraic.roots(p)
    inner = copy.copy(mid).refine(flint.fmpq(1, 2 ** 30))
    assert inner == mid and mid == inner and not inner < mid and not mid < inner
    # overlapping, not nested: decided as before (the same root, then another one)
    same, other = Algebraic(p, flint.fmpq(5, 4), flint.fmpq(3, 2)), Algebraic(p, flint.fmpq(13, 10), 2)
    assert same == mid and other != mid and other == hi and mid < other
    assert lo < mid < hi and hi > inner
