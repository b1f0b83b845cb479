"""Certified sign tables on eigenvalue branches (certify.algebra.branches), exact arithmetic
in Q(α)[λ] (certify.algebra.numberfield) and the two elimination routes (certify.algebra.elimination).

Expected values come from outside the code under test:

* hand-solvable spectra (λ² = r, two crossing lines, a cubic with a double root at
  r = √2/2, a fixed point whose value crosses 1/2 at r = (7 - √13)/8), worked out
  in the comments next to each test;
* for random spectra and conditions: SymPy's own discriminants, resultants, exact
  real-root counts and real roots, and mpmath (60 digits) root finding and
  evaluation at several rational points inside every cell and at the critical values.
"""
from __future__ import annotations

from fractions import Fraction

import flint
import mpmath
import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from certify.algebra import numberfield as nf
from certify.algebra.algebraic import Algebraic
from certify.algebra.branches import NO_BRANCH, Condition, FixedPoint, Spectrum
from certify.algebra.elimination import Elimination, eliminate
from certify.algebra.poly import from_flint, lam, r, x
from certify.errors import UNDECIDED

Q = flint.fmpq
HALF = sp.Rational(1, 2)
SETTINGS = dict(deadline=None, database=None, max_examples=15,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
DPS = 60


@pytest.fixture(autouse=True, scope="module")
def mp_precision():
    """mpmath at 60 digits for this module only."""
    old = mpmath.mp.dps
    mpmath.mp.dps = DPS
    yield
    mpmath.mp.dps = old


# --- independent numerics -----------------------------------------------------------

def mpq(q) -> mpmath.mpf:
    """An fmpq / Fraction / SymPy Rational as an mpmath number (to the working precision)."""
    if isinstance(q, flint.fmpq):
        return mpmath.mpf(int(q.p)) / int(q.q)
    q = Fraction(str(q)) if not isinstance(q, Fraction) else q
    return mpmath.mpf(q.numerator) / q.denominator


def srat(q) -> sp.Rational:
    return sp.Rational(int(q.p), int(q.q))


def mp_algebraic(a: Algebraic) -> mpmath.mpf:
    """An Algebraic to ~200 bits, from its exact isolating interval."""
    a.refine(Q(1, 2 ** 220))
    return (mpq(a.lo) + mpq(a.hi)) / 2


def lam_coeffs(cp) -> list:
    """cp's coefficients in λ (highest first), each a SymPy polynomial in r."""
    return sp.Poly(sp.expand(cp), lam).all_coeffs()


def mp_roots(cp, R, real_tol=None):
    """The real roots of cp(λ; R) (mpmath, 60 digits), largest first, repeated by
    multiplicity; ``real_tol`` the largest imaginary part counted as real."""
    cs = [sp.lambdify(r, c, "mpmath")(R) if c.has(r) else mpmath.mpf(sp.Rational(c).p) / sp.Rational(c).q
          for c in lam_coeffs(cp)]
    roots = mpmath.polyroots(cs, maxsteps=400, extraprec=400)
    tol = real_tol if real_tol is not None else mpmath.mpf(10) ** -(DPS // 2)
    return sorted((mpmath.re(z) for z in roots if abs(mpmath.im(z)) < tol), reverse=True)


def exact_real_root_count(cp, t) -> int:
    """Distinct real roots of cp(λ; t) for a rational t (SymPy, exact)."""
    return sp.Poly(sp.expand(cp).subs(r, srat(t)), lam).count_roots()


def inner_points(cell, n=5) -> list:
    """n rationals well inside the open cell ]lo, hi[ (the ends refined as Algebraic)."""
    a, b = cell.lo, cell.hi
    w = Q(1, 2)
    while True:
        a.refine(w)
        b.refine(w)
        L, H = a.hi, b.lo
        if L < H and 2 * (H - L) > b.hi - a.lo:
            return [L + (H - L) * Q(k, n + 1) for k in range(1, n + 1)]
        w /= 4


def mp_sign(v) -> int:
    return 1 if v > 0 else -1 if v < 0 else 0


def expected_critical(cp, polys, lo, hi) -> list:
    """The distinct real roots in ]lo, hi[ of disc_λ(cp)·Π Res_λ(p, cp) (SymPy, exact)."""
    P = sp.discriminant(sp.expand(cp), lam)
    for p in polys:
        P *= sp.resultant(sp.expand(p), sp.expand(cp), lam)
    P = sp.Poly(sp.expand(P), r)
    if P.is_zero:
        raise AssertionError("zero product")
    if P.degree() <= 0:
        return []
    roots = sp.Poly(P.sqf_part(), r).real_roots()
    lo, hi = srat(Q(lo)), srat(Q(hi))
    return sorted(set(z for z in roots if lo < z < hi), key=lambda z: z.evalf(40))


def assert_same_numbers(algebraics, sympy_roots):
    assert len(algebraics) == len(sympy_roots), (algebraics, sympy_roots)
    for a, z in zip(algebraics, sympy_roots):
        assert abs(mp_algebraic(a) - mpmath.mpf(str(sp.N(z, 50)))) < mpmath.mpf(10) ** -40, (a, z)


def signs_of(table):
    return [cell.signs for cell in table.cells]


# --- λ² = r: branches ±√r --------------------------------------------------------------

SQRT = lam ** 2 - r


def test_sqrt_branches_sign_of_lambda():
    S = Spectrum(SQRT)
    T = S.sign_table(Condition.of("λ", lam), 0, 1)
    # disc = 4r and Res(λ, cp) = -r vanish only at r = 0, an end of the interval
    assert T.critical == [] and T.points == []
    assert len(T.cells) == 1
    cell = T.cells[0]
    assert cell.signs == [1, -1]
    t = mpq(cell.sample)
    assert len(cell.branches) == 2
    assert abs(mp_algebraic(cell.branches[0]) - mpmath.sqrt(t)) < mpmath.mpf(10) ** -40
    assert abs(mp_algebraic(cell.branches[1]) + mpmath.sqrt(t)) < mpmath.mpf(10) ** -40
    assert T.holds(0, 1) and T.holds(1, -1)
    assert not T.holds(0, -1) and not T.holds(1, 1)
    assert T.signs(2) == {"missing"}


def test_sqrt_branches_lambda_minus_half(monkeypatch):
    S = Spectrum(SQRT)
    calls = []
    original = Spectrum.vanishes_at

    def spy(self, h, rc, branch, *args, **kwargs):
        out = original(self, h, rc, branch, *args, **kwargs)
        calls.append((sp.expand(h.as_expr() if hasattr(h, "as_expr") else sp.sympify(h)), rc, branch, out))
        return out

    monkeypatch.setattr(Spectrum, "vanishes_at", spy)
    cond = Condition.of("λ - 1/2", lam - HALF)
    T = S.sign_table(cond, 0, 1)
    # √r = 1/2 at r = 1/4; -√r < 0 < 1/2 throughout
    assert T.critical == [Algebraic.rational(Q(1, 4))]
    assert signs_of(T) == [[-1, -1], [1, -1]]
    assert T.points == [[0, -1]]
    # the 0 comes from the exact zero test (balls around λ = 1/2 always contain 0)
    assert any(branch == 0 and out is True and rc == Algebraic.rational(Q(1, 4)) for _h, rc, branch, out in calls)
    assert not any(branch == 1 for _h, _rc, branch, _out in calls)
    # sub-intervals
    assert T.signs(0) == {-1, 0, 1}
    assert T.signs(0, 0, Q(1, 4)) == {-1}
    assert T.signs(0, Q(1, 4), 1) == {1}
    assert T.signs(0, Q(1, 5), Q(1, 3)) == {-1, 0, 1}
    assert T.signs(0, Q(1, 5), Q(1, 3), include_points=False) == {-1, 1}
    assert T.holds(0, 1, Q(1, 4), 1) and not T.holds(0, 1, Q(1, 5), 1)
    assert T.holds(1, -1)
    # an interval ending at the critical value has no critical value inside
    T2 = S.sign_table(cond, 0, Q(1, 4))
    assert T2.critical == [] and signs_of(T2) == [[-1, -1]]
    T3 = S.sign_table(cond, Q(1, 4), 1)
    assert T3.critical == [] and signs_of(T3) == [[1, -1]]
    # the point directly, and one where it does not vanish
    assert S.sign_at_point(cond, Algebraic.rational(Q(1, 4))) == [0, -1]
    assert S.sign_at_point(cond, Algebraic.rational(Q(1, 9))) == [-1, -1]
    assert S.sign_at_point(cond, Algebraic.surd(0, HALF, 2)) == [1, -1]     # √(√2/2) > 1/2


def test_sqrt_branches_rational_condition_with_pole():
    # g = (λ - 1/2)/(λ + 1/2): a zero on branch 0 and a pole on branch 1, both at r = 1/4;
    # r < 1/4: (−)/(+) on both branches; r > 1/4: (+)/(+) on branch 0, (−)/(−) on branch 1
    S = Spectrum(SQRT)
    T = S.sign_table(Condition.of("g", (lam - HALF) / (lam + HALF)), 0, 1)
    assert T.critical == [Algebraic.rational(Q(1, 4))]
    assert signs_of(T) == [[-1, -1], [1, 1]]
    assert T.points == [[0, "?"]]
    assert T.signs(1) == {-1, "?", 1}
    # 1/(λ - 1/2): a pole, not a zero, on branch 0
    T = S.sign_table(Condition.of("1/(λ - 1/2)", 1 / (lam - HALF)), 0, 1)
    assert signs_of(T) == [[-1, -1], [1, -1]]
    assert T.points == [["?", -1]]


# --- two crossing branches λ = r, λ = 1 - r -----------------------------------------

CROSS = sp.expand((lam - r) * (lam - (1 - r)))


def test_crossing_branches():
    S = Spectrum(CROSS)
    # disc = (2r - 1)²: the branches cross at r = 1/2; λ > 0 on both over ]0, 1[
    T = S.sign_table(Condition.of("λ", lam), 0, 1)
    assert T.critical == [Algebraic.rational(HALF)]
    assert signs_of(T) == [[1, 1], [1, 1]]
    assert T.points == [[1, 1]]                       # the double root 1/2, listed twice
    for cell in T.cells:
        t = cell.sample
        expected = (max(t, 1 - t), min(t, 1 - t))
        assert [L == Algebraic.rational(v) for L, v in zip(cell.branches, expected)] == [True, True]
    assert len(S.branches_at(Algebraic.rational(HALF))) == 2
    # λ - 1/2: branch 0 = max(r, 1-r) > 1/2, branch 1 = min(r, 1-r) < 1/2, both 1/2 at r = 1/2
    T = S.sign_table(Condition.of("λ - 1/2", lam - HALF), 0, 1)
    assert T.critical == [Algebraic.rational(HALF)]
    assert signs_of(T) == [[1, -1], [1, -1]]
    assert T.points == [[0, 0]]
    # λ - 1/4: branch 1 = r hits 1/4 at r = 1/4, and = 1 - r at r = 3/4
    T = S.sign_table(Condition.of("λ - 1/4", lam - sp.Rational(1, 4)), 0, 1)
    assert T.critical == [Algebraic.rational(Q(1, 4)), Algebraic.rational(HALF), Algebraic.rational(Q(3, 4))]
    assert signs_of(T) == [[1, -1], [1, 1], [1, 1], [1, -1]]
    assert T.points == [[1, 0], [1, 1], [1, 0]]


@pytest.mark.parametrize("g", [lam - r, lam - 1 + r, (lam - r) * (lam + 5), 1 / (lam - r), (lam + 3) / (lam - 1 + r)])
def test_condition_vanishing_on_a_whole_branch(g):
    # cp = (λ - r)(λ - 1 + r) is reducible and g's numerator or denominator vanishes on
    # one of its branches: the analysis goes on, that branch gets the sign 0 (g ≡ 0 or a
    # pole: a strict inequality fails), the other its true sign
    S = Spectrum(CROSS)
    T = S.sign_table(Condition.of(str(g), g), 0, 1)
    assert T.critical == [Algebraic.rational(HALF)]
    for cell in T.cells:
        t = sp.Rational(int(cell.sample.p), int(cell.sample.q))
        for L, sg in zip((max(t, 1 - t), min(t, 1 - t)), cell.signs):
            num, den = sp.fraction(sp.cancel(g))
            n0, d0 = num.subs({lam: L, r: t}), den.subs({lam: L, r: t})
            assert sg == (0 if n0 == 0 or d0 == 0 else sp.sign(n0 / d0))


def test_fixed_point_whose_c_vanishes_on_a_branch():
    # c = λ - r ≡ 0 on the branch λ = r: x is undefined there, '?' (undecided), never a sign
    fp = FixedPoint(lam, r, lam - r, sp.Integer(1))
    T = Spectrum(CROSS).sign_table(Condition.of("x", x, fp), 0, 1)
    assert [c.signs for c in T.cells] == [[1, "?"], ["?", 1], ["?", None]]


def test_repeated_factor_is_rejected():
    # cp = (λ² - r)²(λ - 5) has disc ≡ 0: one real branch for r < 0, three for r > 0,
    # a change no discriminant can see; the spectrum must refuse it, not certify
    # a single cell over ]-1, 1[
    with pytest.raises(ValueError, match="repeated factor"):
        Spectrum(sp.expand((lam ** 2 - r) ** 2 * (lam - 5)))


# --- a double root at the irrational r = √2/2 -----------------------------------------

# cp = (λ + 2)(λ² - 2rλ + 1/2): roots -2 and r ± √(r² - 1/2), a double root
# λ = √2/2 at r = √2/2; Res_λ(λ + 2, ·) vanishes at r = -9/8 only
CUBIC = sp.expand((lam + 2) * (lam ** 2 - 2 * r * lam + HALF))
R2 = Algebraic.surd(0, HALF, 2)                     # √2/2


def test_double_root_at_irrational_point():
    S = Spectrum(CUBIC)
    T = S.sign_table(Condition.of("λ - r", lam - r), 0, 1)
    # Res(λ - r, cp) = cp(r) = (r + 2)(1/2 - r²): the same √2/2
    assert T.critical == [R2]
    assert not T.critical[0].is_rational
    # r > √2/2: λ - r = ±√(r² - 1/2) on the pair, -2 - r < 0
    assert signs_of(T) == [[-1], [1, -1, -1]]
    assert T.points == [[0, 0, -1]]
    balls = S.branches_at(R2)
    assert len(balls) == 3
    b0, b1, b2 = (b(128) for b in balls)
    assert b0.overlaps(b1) and not b0.overlaps(b2)
    assert abs(mpmath.mpf(b0.mid().str(50, radius=False)) - mpmath.sqrt(2) / 2) < mpmath.mpf(10) ** -30
    assert abs(mpmath.mpf(b2.mid().str(50, radius=False)) + 2) < mpmath.mpf(10) ** -30

    # λ - 1/2: Res = (5/2)(3/4 - r), so r = 3/4 too, where the pair is {1, 1/2}
    T = S.sign_table(Condition.of("λ - 1/2", lam - HALF), 0, 1)
    assert T.critical == [R2, Algebraic.rational(Q(3, 4))]
    assert signs_of(T) == [[-1], [1, 1, -1], [1, -1, -1]]
    assert T.points == [[1, 1, -1], [1, 0, -1]]
    assert T.signs(1) == {"missing", 1, 0, -1}
    assert T.holds(1, 1, R2, Q(3, 4))
    assert T.holds(0, 1, R2, 1) and not T.holds(0, 1)


def test_sign_at_point_decides_tiny_nonzero_values():
    # values of 1e-12 and 1e-15 at the point: the branch balls must shrink as the
    # precision rises (they once stayed ~1e-9 wide, leaving '?')
    eps = sp.Rational(1, 10 ** 12)
    S = Spectrum(SQRT)
    assert S.sign_at_point(Condition.of("λ - 1/2 - ε", lam - HALF - eps), Algebraic.rational(Q(1, 4))) == [-1, -1]
    assert S.sign_at_point(Condition.of("λ - 1/2 + ε", lam - HALF + eps), Algebraic.rational(Q(1, 4))) == [1, -1]
    S = Spectrum(CUBIC)                              # double root √2/2 at r = √2/2
    eps = sp.Rational(1, 10 ** 15)
    assert S.sign_at_point(Condition.of("λ - r - ε", lam - r - eps), R2) == [-1, -1, -1]
    assert S.sign_at_point(Condition.of("λ - r + ε", lam - r + eps), R2) == [1, 1, -1]


def test_triple_root_branches_not_isolated():
    # cp = λ³ - r has a triple root at r = 0: the branches there are not handled
    S = Spectrum(lam ** 3 - r)
    assert S.branches_at(Algebraic.rational(0)) is None
    assert S.sign_at_point(Condition.of("λ + 1", lam + 1), Algebraic.rational(0)) is None
    T = S.sign_table(Condition.of("λ + 1", lam + 1), -1, 1)
    assert T.critical == [Algebraic.rational(0)] and T.points == [None]
    assert signs_of(T) == [[1], [1]]
    assert T.signs(0) == {1, "?"}
    assert not T.holds(0, 1) and T.holds(0, 1, 0, 1)


# --- conditions with the fixed point x₊ -----------------------------------------------

def test_fixed_point_crossing_half():
    # f(x) = (λx + r)/(x + 1): Δ = (λ - 1)² + 4r > 0, x₊ = (λ - 1 + √Δ)/2.
    # x₊ = 1/2 iff f(1/2) = 1/2 iff λ = 3/2 - 2r; on λ = √r: 2r + √r = 3/2,
    # √r = (√13 - 1)/4, r = (7 - √13)/8 ≈ 0.4243; on λ = -√r only for r > 1.
    # r → 0: λ → 0, Δ → 1, x₊ → 0 < 1/2; r = 1, λ = -1: x₊ = √2 - 1 < 1/2.
    S = Spectrum(SQRT)
    fp = FixedPoint(lam, r, sp.Integer(1), sp.Integer(1))
    T = S.sign_table(Condition.of("x - 1/2", x - HALF, fp), 0, 1)
    rstar = Algebraic.surd(Q(7, 8), Q(-1, 8), 13)
    assert T.critical == [rstar]
    assert signs_of(T) == [[-1, -1], [1, -1]]
    assert T.points[0][1] == -1
    assert T.points[0][0] == 0                          # N₀ + N₁√Δ = 0 proven exactly (norm and signs)
    for cell in T.cells:
        for t in inner_points(cell, 3):
            for k, lv in enumerate(mp_roots(SQRT, mpq(t))):
                xp = (lv - 1 + mpmath.sqrt((lv - 1) ** 2 + 4 * mpq(t))) / 2
                assert mp_sign(xp - HALF.p / mpmath.mpf(HALF.q)) == cell.signs[k]


def test_fixed_point_not_real_and_delta_zero():
    # f(x) = (λx - r)/(x + 1): Δ = (λ - 1)² - 4r.  On λ = √r: Δ = (1 - 3√r)(1 + √r),
    # negative for r > 1/9; on λ = -√r: Δ = (1 + 3√r)(1 - √r) > 0 on ]0, 1[.
    # Δ < (λ - 1)² (as -4r < 0) and λ - 1 < 0, so x₊ < 0 wherever real.  At r = 1/9,
    # Δ = 0 exactly on branch 0 and x₊ = (λ - 1)/2 = -1/3.
    S = Spectrum(SQRT)
    fp = FixedPoint(lam, -r, sp.Integer(1), sp.Integer(1))
    assert sp.expand(fp.delta - ((lam - 1) ** 2 - 4 * r)) == 0
    T = S.sign_table(Condition.of("x", x, fp), 0, 1)
    assert T.critical == [Algebraic.rational(Q(1, 9))]
    assert signs_of(T) == [[-1, -1], [None, -1]]
    assert T.points == [[-1, -1]]
    assert S.vanishes_at(fp.delta, Algebraic.rational(Q(1, 9)), 0)
    assert not S.vanishes_at(fp.delta, Algebraic.rational(Q(1, 9)), 1)
    assert T.signs(0) == {-1, None}


# --- the exact zero test in Q(α)[λ] ---------------------------------------------------

def test_vanishes_at_rational_point():
    S = Spectrum(SQRT)
    q = Algebraic.rational(Q(1, 4))                  # branches 1/2, -1/2
    assert S.vanishes_at(lam - 2 * r, q, 0) and not S.vanishes_at(lam - 2 * r, q, 1)
    assert S.vanishes_at(lam + 2 * r, q, 1) and not S.vanishes_at(lam + 2 * r, q, 0)
    assert S.vanishes_at(SQRT, q, 0) and S.vanishes_at(SQRT, q, 1)
    assert not S.vanishes_at(lam + 5, q, 0) and not S.vanishes_at(lam + 5, q, 1)
    assert S.vanishes_at(4 * r - 1, q, 1)            # no λ: vanishes at r = 1/4 itself
    assert not S.vanishes_at(r, q, 0)
    assert S.vanishes_at(sp.Integer(0), q, 0)
    with pytest.raises(ArithmeticError):
        S.vanishes_at(lam - 2 * r, q, 2)



def test_point_answers_kept_per_condition_point_and_branch():
    # sign_on_branch_at and vanishes_at keep their answers (per condition / polynomial, point
    # and branch): asked again in any order, for another condition at the same point, they
    # are a fresh spectrum's answers
    fp = FixedPoint(lam, -r, sp.Integer(1), sp.Integer(1))
    conds = [Condition.of(name, g, fp) for name, g in
             (("x", x), ("x + 1/3", x + sp.Rational(1, 3)), ("λ - 1/3", lam - sp.Rational(1, 3)))]
    pts = [Algebraic.rational(Q(1, 9)), Algebraic.rational(Q(1, 4)), Algebraic.surd(3, -2, 2)]
    S = Spectrum(SQRT)
    for order in ((0, 1), (1, 0), (0, 1)):
        for cond in conds:
            for rc in pts:
                for k in order:
                    assert S.sign_on_branch_at(cond, rc, k) == Spectrum(SQRT).sign_on_branch_at(cond, rc, k)
    q = Algebraic.rational(Q(1, 4))
    for h in (lam - 2 * r, lam + 2 * r):
        for k in (1, 0, 1, 0):
            assert S.vanishes_at(h, q, k) == Spectrum(SQRT).vanishes_at(h, q, k) == \
                ((k == 0) == (h == lam - 2 * r))

def test_vanishes_at_irrational_point():
    # α = 3 - 2√2 = (√2 - 1)² ≈ 0.1716: the branches ±√α = ±(√2 - 1) = ±(1 - α)/2 lie in Q(α)
    S = Spectrum(SQRT)
    alpha = Algebraic.surd(3, -2, 2)
    assert alpha.minimal_polynomial() == flint.fmpz_poly([1, -6, 1])
    up, down = 2 * lam + r - 1, 2 * lam - r + 1
    assert S.vanishes_at(up, alpha, 0) and not S.vanishes_at(up, alpha, 1)
    assert S.vanishes_at(down, alpha, 1) and not S.vanishes_at(down, alpha, 0)
    # at r = √2/2, λ² - √2/2 is irreducible over Q(√2) (no square root of √2/2 there):
    # λ - r, i.e. λ - √2/2, vanishes on neither branch
    assert not S.vanishes_at(lam - r, R2, 0) and not S.vanishes_at(lam - r, R2, 1)
    # ... and the numbers agree: 2√α + α - 1 = 0
    a = mp_algebraic(alpha)
    assert abs(2 * mpmath.sqrt(a) + a - 1) < mpmath.mpf(10) ** -50
    # sign_at_point through the exact path on the same conditions
    assert S.sign_at_point(Condition.of("2λ + r - 1", up), alpha) == [0, -1]
    assert S.sign_at_point(Condition.of("2λ - r + 1", down), alpha) == [1, 0]


def test_vanishes_at_double_roots():
    S = Spectrum(CROSS)
    half = Algebraic.rational(HALF)                  # the double root 1/2
    assert S.vanishes_at(2 * lam - 1, half, 0) and S.vanishes_at(2 * lam - 1, half, 1)
    assert S.vanishes_at(lam - r, half, 0) and S.vanishes_at(lam - r, half, 1)
    assert not S.vanishes_at(lam - 2 * r, half, 0)
    third = Algebraic.rational(Q(1, 3))              # branches 2/3, 1/3
    assert S.vanishes_at(lam - r, third, 1) and not S.vanishes_at(lam - r, third, 0)
    S = Spectrum(CUBIC)                              # √2/2 double, -2 simple
    assert [S.vanishes_at(lam - r, R2, k) for k in range(3)] == [True, True, False]
    assert [S.vanishes_at(lam + 2, R2, k) for k in range(3)] == [False, False, True]
    assert [S.vanishes_at(2 * lam ** 2 - 1, R2, k) for k in range(3)] == [True, True, False]


def test_numberfield_gcd_and_squarefree():
    # in Q(√2)[λ]: gcd(λ² - 2, λ² - 2√2 λ + 2) = λ - √2
    m = nf.modulus(Algebraic.surd(0, 1, 2))
    assert from_flint(m) == r ** 2 - 2
    f, g = nf.kpoly(lam ** 2 - 2, m), nf.kpoly(lam ** 2 - 2 * r * lam + 2, m)
    G = nf.gcd(f, g, m)
    assert [from_flint(c) for c in G] == [1, -r]
    # (λ - √2)²(λ + 1): squarefree part (λ - √2)(λ + 1), gcd with the derivative λ - √2
    h = nf.kpoly(sp.expand((lam - r) ** 2 * (lam + 1)), m)
    sqf, g = nf.squarefree(h, m)
    assert [from_flint(c) for c in g] == [1, -r]
    assert [sp.expand(from_flint(c)) for c in sqf] == [1, 1 - r, -r]
    assert [from_flint(c) for c in nf.divide(h, sqf, m)] == [1, -r]
    # coprime: gcd 1
    assert [from_flint(c) for c in nf.gcd(f, nf.kpoly(lam - 1, m), m)] == [1]
    # real roots of λ² - 2 over Q(√2)... and of λ² + 1 (none)
    roots = nf.real_roots(f, Algebraic.surd(0, 1, 2), 128)
    assert len(roots) == 2 and roots[0] > 0 and roots[1] < 0
    assert abs(float(roots[0].mid()) - 2 ** 0.5) < 1e-12
    assert nf.real_roots(nf.kpoly(lam ** 2 + 1, m), Algebraic.surd(0, 1, 2), 128) == []
    # the balls shrink with the precision asked for
    for prec in (128, 512):
        z = nf.real_roots(f, Algebraic.surd(0, 1, 2), prec)[0]
        assert z.rad() < flint.arb(2) ** -(prec // 2)
        assert z.overlaps(flint.arb(2).sqrt())


def test_fixed_point_with_delta_identically_zero():
    # a = d, b = 0: Δ ≡ 0, x₊ = 0 double; no crash in the √Δ bookkeeping, but no sign either
    fp = FixedPoint(lam, sp.Integer(0), sp.Integer(1), lam)
    assert fp.delta == 0
    cond = Condition.of("x - 1/2", x - HALF, fp)
    # numerator (a - d + √Δ) - 2c·(1/2) = √Δ - 1: N₀ = -1, N₁ = 1; denominator 2c = 2
    parts = [cond.N[0].as_expr(), cond.N[1].as_expr(), cond.D[0].as_expr(), cond.D[1].as_expr()]
    assert all(p.is_number for p in parts) and parts[1] > 0
    assert [p / parts[1] for p in parts] == [-1, 1, 2, 0]
    T = Spectrum(SQRT).sign_table(cond, 0, 1)       # signs are computed when read
    with pytest.raises(ArithmeticError):
        T.signs(0)


# --- elimination ----------------------------------------------------------------------

def P(*coeffs):
    return flint.fmpz_poly(list(coeffs))


def test_eliminate_two_routes():
    # λ = r², λ² = r  ⇒  r⁴ = r: r(r - 1)(r² + r + 1)
    E = eliminate(lam - r ** 2, lam ** 2 - r)
    assert E.groebner == P(0, -1, 0, 0, 1)
    assert E.resultant == P(0, -1, 0, 0, 1)
    assert E.agree
    assert E.factors == [(P(-1, 1), 1), (P(0, 1), 1), (P(1, 1, 1), 1)]
    assert "yes" in E.evidence()[-1]


def test_eliminate_multiplicities_differ():
    # ⟨λ², λ² - r⟩ = ⟨λ², r⟩: Gröbner eliminant r; Res_λ(λ², λ² - r) = r²
    E = eliminate(lam ** 2, lam ** 2 - r)
    assert E.groebner == P(0, 1)
    assert E.resultant == P(0, 0, 1)
    assert E.agree
    # λ = 0 and λ² = r² + r³ ... ⟨λ, r²(1 + r)⟩: both routes r²(r + 1)
    E = eliminate(lam, lam ** 2 - r ** 2 - r ** 3)
    assert E.groebner == P(0, 0, 1, 1) and E.resultant == P(0, 0, 1, 1) and E.agree


def test_elimination_disagreement_is_seen():
    assert not Elimination(P(0, 1), P(0, -1, 1)).agree        # r vs r(r - 1)
    assert not Elimination(P(0, 1), P(-1, 1)).agree
    assert "NO" in Elimination(P(0, 1), P(-1, 1)).evidence()[-1]


small = st.integers(-3, 3)


@settings(**{**SETTINGS, "max_examples": 10})
@given(st.lists(small, min_size=4, max_size=4), st.lists(small, min_size=4, max_size=4))
def test_eliminate_random(gc, cc):
    # g = (g0 + g1 r) + (g2 + g3 r)λ, cp = λ² + (c0 + c1 r)λ + c2 + c3 r²
    g = sp.expand(gc[0] + gc[1] * r + (gc[2] + gc[3] * r) * lam)
    assume(g.has(lam))
    cp = sp.expand(lam ** 2 + (cc[0] + cc[1] * r) * lam + cc[2] + cc[3] * r ** 2)
    res = sp.resultant(g, cp, lam)
    assume(sp.expand(res) != 0 and sp.Poly(res, r).degree() > 0)
    E = eliminate(g, cp)
    assert E.agree
    assert E.groebner.degree() > 0
    # the resultant lies in the elimination ideal: the Gröbner eliminant divides it
    assert E.resultant % E.groebner == 0
    # SymPy's resultant, made primitive, is the flint route's
    sres = sp.Poly(res, r)
    assert E.resultant.degree() == sres.degree()
    ratio = {sp.Rational(int(a), 1) / b for a, b in zip(E.resultant.coeffs(), sres.all_coeffs()[::-1]) if b != 0}
    assert len(ratio) == 1


# --- random spectra: every cell against SymPy and mpmath --------------------------

coef = st.integers(-3, 3)
rpoly = st.lists(coef, min_size=1, max_size=3)             # c0 + c1 r + c2 r²


def from_coeffs(cs):
    return sum(c * r ** k for k, c in enumerate(cs))


def check_table(cp, T, cond_value, lo, hi):
    """Every cell of T against SymPy (critical values, exact branch counts) and mpmath
    (branches and signs) at 5 rational points inside it; ``cond_value(R, λ)`` the
    condition in mpmath (None where not real)."""
    assert len(T.cells) == len(T.critical) + 1 == len(T.points) + 1
    ends = [Algebraic.rational(Q(lo))] + T.critical + [Algebraic.rational(Q(hi))]
    for cell, a, b in zip(T.cells, ends, ends[1:]):
        assert cell.lo == a and cell.hi == b and a < cell.sample < b
        for t in [cell.sample] + inner_points(cell):
            assert exact_real_root_count(cp, t) == len(cell.branches)
            lams = mp_roots(cp, mpq(t))
            assert len(lams) == len(cell.branches)
            for k, lv in enumerate(lams):
                v = cond_value(mpq(t), lv)
                if v is None:
                    assert cell.signs[k] is None
                else:
                    assert abs(v) > mpmath.mpf(10) ** -40
                    assert mp_sign(v) == cell.signs[k], (t, k, v, cell.signs)


def check_degenerate_table(cp, T, cond_value, points: bool = True):
    """A table of a g sharing a factor with cp, against mpmath at each cell's sample:
    sign 0 exactly where g vanishes numerically on the branch (below 10^-40 at 60
    digits: a root of the common factor), the numerical sign elsewhere."""
    assert len(T.cells) == len(T.critical) + 1
    for cell in T.cells:
        lams = mp_roots(cp, mpq(cell.sample))
        assert len(lams) == len(cell.branches)
        for k, lv in enumerate(lams):
            v = cond_value(mpq(cell.sample), lv)
            if not points and cell.signs[k] == UNDECIDED:
                continue                       # degenerate data: "undecided" is an honest answer
            if v is None:                      # x₊ not real there (a fixed-point condition)
                assert cell.signs[k] is None, (cell.sample, k, list(cell.signs))
            elif abs(v) < mpmath.mpf(10) ** -40:
                assert cell.signs[k] == 0, (cell.sample, k, v, list(cell.signs))
            else:
                assert mp_sign(v) == cell.signs[k], (cell.sample, k, v, list(cell.signs))
    if points:
        check_points(cp, T, cond_value)


def check_points(cp, T, cond_value):
    """The signs at the critical values against mpmath: exact zeros numerically tiny,
    strict signs agreeing wherever the value is not tiny."""
    tiny = mpmath.mpf(10) ** -18
    for rc, pt in zip(T.critical, T.points):
        if pt is None:
            continue
        R = mp_algebraic(rc)
        lams = mp_roots(cp, R, real_tol=mpmath.mpf(10) ** -12)
        assert len(lams) == len(pt), (rc, lams, pt)
        assert "?" not in pt                         # a polynomial g: zeros are decided exactly
        for k, lv in enumerate(lams):
            v = cond_value(R, lv)
            if pt[k] == 0:
                assert v is not None and abs(v) < tiny
            elif pt[k] in (1, -1) and v is not None and abs(v) > tiny:
                assert mp_sign(v) == pt[k]
            elif pt[k] is None:
                assert v is None or abs(v) < tiny


@settings(**SETTINGS)
@given(rpoly, rpoly, rpoly, st.lists(coef, min_size=6, max_size=6),
       st.sampled_from([(Q(0), Q(1)), (Q(-1), Q(1)), (Q(1, 2), Q(2)), (Q(-2), Q(0))]))
def test_random_cubic_sign_tables(a, b, c, gc, interval):
    lo, hi = interval
    cp = sp.expand(lam ** 3 + from_coeffs(a) * lam ** 2 + from_coeffs(b) * lam + from_coeffs(c))
    # g = (g0 + g1 r + g2 r²) + (g3 + g4 r) λ + g5 λ²
    g = sp.expand(from_coeffs(gc[:3]) + from_coeffs(gc[3:5]) * lam + gc[5] * lam ** 2)
    assume(g != 0)
    assume(sp.expand(sp.discriminant(cp, lam)) != 0)
    S = Spectrum(cp)
    cond = Condition.of(str(g), g)
    if sp.expand(sp.resultant(g, cp, lam)) == 0:
        # g and cp share a factor G in Q(r)[λ]: g ≡ 0 on the branches that are roots of G
        # (sign 0 there, exactly), and is signed as usual on the others
        check_degenerate_table(cp, S.sign_table(cond, lo, hi), sp.lambdify((r, lam), g, "mpmath"))
        return
    T = S.sign_table(cond, lo, hi)
    assert_same_numbers(T.critical, expected_critical(cp, [g] if g.has(lam) or g.has(r) else [], lo, hi))
    gf = sp.lambdify((r, lam), g, "mpmath")
    check_table(cp, T, gf, lo, hi)
    check_points(cp, T, gf)


lin = st.lists(st.integers(-2, 2), min_size=3, max_size=3)   # c0 + c1 r + c2 λ


def from_lin(cs):
    return cs[0] + cs[1] * r + cs[2] * lam


@settings(**SETTINGS)
@given(lin, lin, lin, lin, rpoly, rpoly, st.sampled_from([0, HALF, -1, 2]))
def test_random_fixed_point_sign_tables(ac, bc, cc, dc, p1, p0, q):
    # cp = λ² + p1(r) λ + p0(r); f(x) = (ax + b)/(cx + d) with a, b, c, d linear in r, λ
    cp = sp.expand(lam ** 2 + from_coeffs(p1) * lam + from_coeffs(p0))
    A, B, C, D = (sp.expand(from_lin(v)) for v in (ac, bc, cc, dc))
    assume(C != 0)
    assume(sp.expand(sp.discriminant(cp, lam)) != 0)
    fp = FixedPoint(A, B, C, D)
    delta = sp.expand((A - D) ** 2 + 4 * B * C)
    # x₊ = q on a branch iff q solves cx² + (d - a)x - b = 0 there (and is the larger root)
    fixed_eq = sp.expand(C * q ** 2 + (D - A) * q - B)
    S = Spectrum(cp)
    cond = Condition.of(f"x - {q}", x - q, fp)
    nonconstant = [p for p in (C, delta, fixed_eq) if p.has(r) or p.has(lam)]
    if any(sp.expand(sp.resultant(p, cp, lam)) == 0 for p in nonconstant) or delta == 0:
        # degenerate data (c, Δ or the fixed-point equation share a factor with cp, or Δ ≡ 0):
        # the engine may say "undecided" (ArithmeticError), or decide exactly (x₊ ≡ q: sign 0;
        # no real branch at all: nothing to decide); what it decides must be right
        try:
            T = S.sign_table(cond, 0, 1)
            # the cells (a critical value of degenerate data may stay undecided)
            check_degenerate_table(cp, T, fixed_point_value(A, B, C, D, q), points=False)
        except ArithmeticError:
            return
        return
    if fixed_eq == 0:
        check_q_always_fixed(cp, A, B, C, D, q, S, cond)
        return
    T = S.sign_table(cond, 0, 1)
    assert_same_numbers(T.critical, expected_critical(cp, nonconstant, 0, 1))
    check_fixed_point_table(cp, T, A, B, C, D, q)


def fixed_point_value(A, B, C, D, q):
    """x₊ - q in mpmath as a function of (r, λ), None where x₊ is not real."""
    fa, fb, fc, fd = (sp.lambdify((r, lam), e, "mpmath") for e in (A, B, C, D))
    qq = mpmath.mpf(sp.Rational(q).p) / sp.Rational(q).q

    def value(R, L):
        av, bv, cv, dv = fa(R, L), fb(R, L), fc(R, L), fd(R, L)
        disc = (av - dv) ** 2 + 4 * bv * cv
        if disc < 0:
            return None
        return (av - dv + mpmath.sqrt(disc)) / (2 * cv) - qq
    return value


def check_fixed_point_table(cp, T, A, B, C, D, q):
    """The table of x₊ - q against mpmath, in the cells and at the critical values."""
    fa, fb, fc, fd = (sp.lambdify((r, lam), e, "mpmath") for e in (A, B, C, D))
    value = fixed_point_value(A, B, C, D, q)
    check_table(cp, T, value, 0, 1)
    for rc, pt in zip(T.critical, T.points):       # strict signs at the critical values
        if pt is None:
            continue
        R = mp_algebraic(rc)
        lams = mp_roots(cp, R, real_tol=mpmath.mpf(10) ** -12)
        assert len(lams) == len(pt)
        for k, lv in enumerate(lams):
            av, bv, cv, dv = fa(R, lv), fb(R, lv), fc(R, lv), fd(R, lv)
            disc = (av - dv) ** 2 + 4 * bv * cv
            if abs(disc) < mpmath.mpf(10) ** -18 or abs(cv) < mpmath.mpf(10) ** -18:
                continue                              # Δ = 0 or c = 0 there: checked by the hand examples
            v = value(R, lv)
            if v is None:
                assert pt[k] is None
            elif abs(v) > mpmath.mpf(10) ** -18:
                assert pt[k] == mp_sign(v)


def check_q_always_fixed(cp, A, B, C, D, q, S, cond):
    """q solves cx² + (d - a)x - b = 0 for every r, λ, so (a - d - 2cq)² = Δ: q = x₊ where
    h = 2cq - a + d > 0 and q = x₋ where h < 0.  Where h > 0 on a branch, x₊ - q vanishes
    on a whole cell and no sign can be certified: reading the table must be refused, and mpmath
    sees x₊ = q at the sample of such a cell.  Where h < 0 on every branch the table must
    come, and agree with mpmath.  Both paths assert."""
    h = sp.expand(2 * C * q - A + D)
    H = S.sign_table(Condition.of(f"2cq - a + d ({h})", h), 0, 1)
    where = [(cell, k) for cell in H.cells for k, sg in enumerate(cell.signs) if sg == 1]
    if where:
        T = S.sign_table(cond, 0, 1)           # signs are computed when read: refused then
        with pytest.raises(ArithmeticError):
            [list(c.signs) for c in T.cells]
        value = fixed_point_value(A, B, C, D, q)
        cell, k = where[0]
        t = mpq(cell.sample)
        v = value(t, mp_roots(cp, t)[k])
        assert v is not None and abs(v) < mpmath.mpf(10) ** -40          # x₊ = q there
    else:
        T = S.sign_table(cond, 0, 1)
        check_fixed_point_table(cp, T, A, B, C, D, q)


def test_q_fixed_for_every_r_lambda():
    """Both paths of :func:`check_q_always_fixed`.  cp = λ² - r (λ = ±√r):
    x² - λx = 0 (a = λ, b = 0, c = 1, d = 0) has the roots 0 and λ, so x₊ = 0 = q on the
    lower branch: refused; x² - (1 + r)x = 0 has x₊ = 1 + r ≠ 0 = q: a table, x₊ - q > 0."""
    cp = lam ** 2 - r
    S = Spectrum(cp)
    for A, sign in ((lam, None), (1 + r, 1)):
        fp = FixedPoint(A, sp.Integer(0), sp.Integer(1), sp.Integer(0))
        cond = Condition.of(f"x - 0 for a = {A}", x, fp)
        check_q_always_fixed(cp, A, sp.Integer(0), sp.Integer(1), sp.Integer(0), 0, S, cond)
        if sign is None:
            T = S.sign_table(cond, 0, 1)       # signs are computed when read: refused then
            with pytest.raises(ArithmeticError):
                [list(c.signs) for c in T.cells]
        else:
            T = S.sign_table(cond, 0, 1)
            assert all(set(c.signs) == {sign} for c in T.cells)


def test_a_condition_sharing_a_factor_with_cp_has_sign_zero_on_those_branches_only():
    """cp = (λ - r)(λ - 2)(λ + 3) and g = (λ - r)(λ² - 1): Res_λ(g, cp) ≡ 0, g ≡ 0 on the
    branch λ = r, and g has its own sign on the other two, (2 - r)·3 > 0 at λ = 2 and
    (-3 - r)·8 < 0 at λ = -3 (the kind of draw that made test_random_cubic_sign_tables
    fail at random)."""
    cp = sp.expand((lam - r) * (lam - 2) * (lam + 3))
    g = sp.expand((lam - r) * (lam ** 2 - 1))
    assert sp.expand(sp.resultant(g, cp, lam)) == 0
    T = Spectrum(cp).sign_table(Condition.of("g", g), Q(0), Q(1))
    assert [list(c.signs) for c in T.cells] == [[1, 0, -1]]          # λ = 2, λ = r, λ = -3
    check_degenerate_table(cp, T, sp.lambdify((r, lam), g, "mpmath"))


def test_the_resultant_by_multiplication_determinant_equals_python_flints():
    """Spectrum.resultant with a monic cp (the determinant of multiplication by g on
    Q[r][λ]/(cp), branches._norm_modulo) against python-flint's fmpz_mpoly resultant:
    the same primitive polynomial in r, for cp of degree 1, 2, 3 and g of any degree."""
    import random

    from certify.algebra.branches import _lambda_coefficients, _norm_modulo
    from certify.algebra.poly import MCTX, mpoly_to_univariate, primitive
    rr, ll, _s = MCTX.gens()
    rng = random.Random(7)

    def poly(dl, dr):
        return sum((rng.randint(-9, 9) * rr ** i * ll ** j for i in range(dr + 1) for j in range(dl + 1)),
                   MCTX.from_dict({}))
    for n in (1, 2, 3):
        for _ in range(20):
            cp = 7 * ll ** n + poly(n - 1, 4)
            g = poly(rng.randint(0, 5), 5)
            expected = primitive(mpoly_to_univariate(g.resultant(cp, "lam")))
            assert primitive(_norm_modulo(_lambda_coefficients(g), _lambda_coefficients(cp))) == expected


def test_a_ball_refined_by_interval_newton_holds_the_root_at_the_precision_asked():
    """Algebraic.arb at a higher precision starts from the coarser ball (interval Newton):
    the ball holds the root (it meets python-flint's fresh isolation, and p changes sign
    across its rational ends) and its radius is at most 2^-prec."""
    from certify.algebra.algebraic import _newton_ball, _root_ball
    a = Algebraic.roots(flint.fmpz_poly([5, -50, 107, -188, 107, -50, 5]), 0, 1)[0]
    coarse = a.arb(64)
    for prec in (128, 512, 2048):
        z = _newton_ball(a.p, coarse, prec)
        assert z is not None and z.overlaps(_root_ball(a.p, a.lo, a.hi, prec))
        assert z.rad() <= flint.arb(2) ** -prec
        lo, hi = z.mid().fmpq() - z.rad().fmpq(), z.mid().fmpq() + z.rad().fmpq()
        assert (a.p(lo) > 0) != (a.p(hi) > 0)
    assert _newton_ball(a.p, flint.arb(0, 10), 128) is None       # p' vanishes on a ball that wide


def test_a_ball_of_a_polynomial_isolated_already_is_refined_not_isolated_again(monkeypatch):
    """Once p's roots are isolated at the root balls' working precision (count_roots's
    enclosures, the second route's count), a ball of one of its roots at any precision is
    refined from that isolation by interval Newton: python-flint's root isolation is not
    called again, and the ball holds the root (p changes sign across its rational ends)."""
    import certify.algebra.sturm as sturm
    from certify.algebra.algebraic import _root_ball
    from certify.algebra.balls import precision
    p = flint.fmpz_poly([5, -50, 107, -188, 107, -50, 5])
    monkeypatch.setattr(sturm, "_COMPLEX", {})
    assert sturm.isolated_real_root(p, 0, 1) is None                  # nothing isolated yet
    with precision(sturm.BALL_BITS):
        sturm.complex_roots(-3 * p)                                    # the same isolation, p's multiple
    a = Algebraic.roots(p, 0, 1)[0]
    assert sturm.isolated_real_root(p, 0, 1) is not None
    assert sturm.isolated_real_root(p, 0, 10) is None                  # two real roots in ]0, 10[

    def refuse(*args, **kwargs):
        raise AssertionError("root finder called")
    monkeypatch.setattr(flint.fmpz_poly, "complex_roots", refuse, raising=False)
    monkeypatch.setattr(flint.fmpq_poly, "complex_roots", refuse, raising=False)
    for prec in (64, 300):
        z = _root_ball(p, a.lo, a.hi, prec)
        assert z is not None and z.rad() <= flint.arb(2) ** -prec
        lo, hi = z.mid().fmpq() - z.rad().fmpq(), z.mid().fmpq() + z.rad().fmpq()
        assert a.lo < lo and hi < a.hi and (p(lo) > 0) != (p(hi) > 0)


# ---------------------------------------------------------------- helpers moved here from the proofs
def test_sign_table_changes_and_keeps_sign_at_a_critical_value():
    """λ² = r: the branches ±√r; g = λ - 1/2 vanishes on the upper branch at r = 1/4 (√r = 1/2)
    and keeps its sign (−) on the lower branch there."""
    from certify.algebra import Algebraic, Spectrum, lam
    from certify.algebra import r as r_
    T = Spectrum(lam ** 2 - r_).table("λ-1/2", lam - sp.Rational(1, 2), 0, 1)
    quarter = Algebraic.rational(flint.fmpq(1, 4))
    assert quarter in T.critical
    assert T.changes_at(0, quarter) and not T.keeps_sign_at(0, quarter)
    assert T.keeps_sign_at(1, quarter) and not T.changes_at(1, quarter)
    assert not T.changes_at(5, quarter) and T.keeps_sign_at(5, quarter)      # no such branch


def test_sign_word_names_every_answer():
    from certify.algebra import sign_word
    from certify.algebra.branches import NO_BRANCH

    assert sign_word({1, -1}) == "< 0, > 0"
    assert sign_word({0, None, NO_BRANCH, UNDECIDED}) == "= 0, absent, not real, undecided"


def test_root_ball_uses_an_isolation_found_above_the_precision_asked():
    """Two roots 2^-100 apart are isolated only from 1024 bits on; a ball asked at 128 bits
    (as sign_at_point asks first) is the one isolated at 1024, not 'roots lost at higher
    precision' (the crash of `certify orbit` on the 122-letter word of r = 0.173)."""
    from certify.algebra.balls import ends
    from certify.algebra.branches import _root_ball
    eps = flint.fmpq(1, 2 ** 100)
    rc = Algebraic.rational(flint.fmpq(1, 3))
    m = nf.modulus(rc)
    # (λ - 1)(λ - 1 - eps) in Q(rc)[λ], highest coefficient first
    sqf = [nf.reduce(c, m) for c in (flint.fmpq(1), -(2 + eps), 1 + eps)]
    assert nf.real_roots(sqf, rc, 512) is None
    found = nf.real_roots(sqf, rc, 1024)
    assert found is not None and len(found) == 2
    isolated = {1024: found}
    roots = (1 + eps, flint.fmpq(1))                      # largest first
    for k in range(2):
        lo, hi = ends(_root_ball(sqf, rc, k, isolated)(128))
        assert lo <= roots[k] <= hi and not lo <= roots[1 - k] <= hi


def test_exact_zero_tests_agree_with_the_gcd_in_the_number_field(monkeypatch):
    """Spectrum.vanishes_at decides most zeros at an algebraic r by the resultant over Z and
    certified balls (routes 1-2 of _common_roots); with the resultant hidden, every one goes
    to the gcd in Q(rc)[λ] (route 3).  The two agree on every contact condition of the orbit
    of (ab)^2(cb)^2 and every condition with √Δ of its self-similar datum, at every critical
    value of its table, on every branch, numerator, denominator and norms, and both answers
    occur."""
    from certify.algebra.poly import mpoly_to_ring
    from certify.dynamics.systems import candidate_in
    from certify.patterns.feasibility import condition, fixed_point_data, prefix_requirements
    from certify.patterns.reduction_orbits import contact_requirements
    cand = candidate_in("four", "ababcbcb")
    fast = cand.spectrum
    slow = Spectrum(fast.cp, fast.ring_cp)
    monkeypatch.setattr(slow, "resultant", lambda g: flint.fmpz_poly(0))
    exists, feasible = contact_requirements("ababcbcb", cand.Mq, fast.lrq_cp)
    conds = [condition(req, fast.lrq_cp) for req in exists + feasible]
    fps = fixed_point_data(cand.abcd_ring, fast.ring_cp)         # the self-similar datum's, with √Δ
    reqs, _ = prefix_requirements("ababcbcb", 8, cand.q0, cand.steps, cand.q0_other)
    conds += [condition(req, fast.lrq_cp, fp) for req in reqs if req.has_x for fp in fps]
    answers = []
    for cond in conds:
        hs = [cond.N[0], cond.D[0]] + [mpoly_to_ring(e) for e in cond.norms()]
        for rc in fast.critical_values(cond, 0, 1):
            branches = fast.branches_at(rc)
            for k in range(len(branches or [])):
                for h in hs:
                    if h:
                        answers.append((fast.vanishes_at(h, rc, k), slow.vanishes_at(h, rc, k)))
    assert answers and all(a == b for a, b in answers)
    assert {a for a, _ in answers} == {True, False}


def test_the_gcd_as_it_comes_and_the_monic_gcd_give_the_same_zero_tests(monkeypatch):
    """Route 3 of _common_roots encloses the roots of the gcd in Q(rc)[λ] as it comes (no inverse
    in Q(rc)), and those of the monic gcd only where these leave the test undecided.  With the
    resultant hidden (every test goes to the gcd), three spectra agree on every zero test of the
    conditions with √Δ of (ab)^2(cb)^2 at the critical values of their tables: the plain one,
    one whose enclosures of a gcd as it comes always fail (the monic gcd decides every test
    then), and one without the monic fallback (what the gcd as it comes decides alone must
    be the same; where it decides nothing the test is Undecided, never another answer)."""
    from certify.algebra import numberfield as nf
    from certify.algebra.poly import mpoly_to_ring
    from certify.dynamics.systems import candidate_in
    from certify.errors import Undecided
    from certify.patterns.feasibility import condition, fixed_point_data, prefix_requirements
    cand = candidate_in("four", "ababcbcb")
    base = cand.spectrum
    plain, monic_only, raw_only = (Spectrum(base.cp, base.ring_cp) for _ in range(3))
    for spec in (plain, monic_only, raw_only):
        monkeypatch.setattr(spec, "resultant", lambda g: flint.fmpz_poly(0))
    real_roots, used = nf.real_roots, []

    def common_roots(spec, mode):
        own = spec._common_roots

        def patched(h, rc):
            G = own(h, rc)
            if callable(G) and getattr(G, "fallback", None) is not None:
                if mode == "monic":
                    def failing(prec):
                        used.append(prec)
                        return None
                    failing.fallback = G.fallback
                    return failing
                G.fallback = None
            return G
        return patched
    monkeypatch.setattr(monic_only, "_common_roots", common_roots(monic_only, "monic"))
    monkeypatch.setattr(raw_only, "_common_roots", common_roots(raw_only, "raw"))
    reqs, _ = prefix_requirements("ababcbcb", 8, cand.q0, cand.steps, cand.q0_other)
    fps = fixed_point_data(cand.abcd_ring, base.ring_cp)
    conds = [condition(req, base.lrq_cp, fp) for req in reqs if req.has_x for fp in fps]
    answers = []
    for cond in conds:
        hs = [cond.N[0], cond.D[0]] + [mpoly_to_ring(e) for e in cond.norms()]
        for rc in base.critical_values(cond, 0, 1):
            for k in range(len(base.branches_at(rc) or [])):
                for h in hs:
                    if h:
                        a, b = plain.vanishes_at(h, rc, k), monic_only.vanishes_at(h, rc, k)
                        try:
                            c = raw_only.vanishes_at(h, rc, k)
                        except Undecided:
                            c = a
                        answers.append((a, b, c))
    assert answers and all(a == b == c for a, b, c in answers)
    assert used and nf.real_roots is real_roots


# --- the fast paths of the sign tables (speed of `certify pattern`) agree with the plain ones
def test_horner_form_encloses_the_exact_value():
    """The Horner form of a condition's terms, evaluated at balls around rational r, λ,
    contains the exact rational value (SymPy); a wrong form (a dropped term) would not."""
    from certify.algebra.branches import _eval_form, _horner_form
    e = sp.Rational(3, 7) * r ** 5 * lam ** 2 - 11 * r ** 2 * lam + sp.Rational(1, 5) * lam ** 3 - r + 2
    terms = [(flint.fmpq(int(sp.Rational(c).p), int(sp.Rational(c).q)), i, j)
             for (i, j), c in sp.Poly(e, r, lam).terms()]
    form = _horner_form(terms)
    for r0, l0 in ((Fraction(1, 3), Fraction(-5, 4)), (Fraction(7, 9), Fraction(2, 1))):
        exact = e.subs({r: sp.Rational(r0.numerator, r0.denominator), lam: sp.Rational(l0.numerator, l0.denominator)})
        ball = _eval_form(form, flint.arb(flint.fmpq(r0.numerator, r0.denominator)),
                          flint.arb(flint.fmpq(l0.numerator, l0.denominator)))
        assert ball.contains(flint.fmpq(int(exact.p), int(exact.q)))
        wrong = _eval_form(_horner_form(terms[1:]), flint.arb(flint.fmpq(r0.numerator, r0.denominator)),
                           flint.arb(flint.fmpq(l0.numerator, l0.denominator)))
        assert not wrong.contains(flint.fmpq(int(exact.p), int(exact.q)))


def test_order_from_intervals_agrees_with_exact_comparison():
    """sorted_numbers, less, at_most, same and strictly_between give what the exact
    comparisons give, on roots of several polynomials (some equal, some close)."""
    from certify.algebra.branches import at_most, less, same, sorted_numbers, strictly_between
    nums = (Algebraic.roots(flint.fmpq_poly([-2, 0, 1]), 0, 2) + Algebraic.roots(flint.fmpq_poly([-3, 0, 1]), 0, 2)
            + Algebraic.roots(flint.fmpq_poly([1, -10, 1]), 0, 1) + [Algebraic.rational(flint.fmpq(7, 5))])
    assert [str(a.digits(8)) for a in sorted_numbers(nums)] == [str(a.digits(8)) for a in sorted(nums)]
    twin = Algebraic.roots(flint.fmpq_poly([-2, 0, 1]), 1, 2)[0]         # √2 again, another object
    for a in nums + [twin]:
        for b in nums + [twin]:
            assert less(a, b) == (a < b) and at_most(a, b) == (a <= b) and same(a, b) == (a == b)
    lo, hi = Algebraic.rational(flint.fmpq(1)), Algebraic.rational(flint.fmpq(3, 2))
    assert [strictly_between(lo, a, hi) for a in nums] == [lo < a < hi for a in nums]



def test_numerator_norm_is_the_norm_of_the_parts():
    """The norm the exact zero test takes from a condition (Condition.numerator_norm) is
    the very polynomial norm_mpoly makes of N₀, N₁, Δ (x - 1/2, x the fixed point of
    (λx + r)/(x + 1)); None where there is no √Δ (the norm would be N₀², not N₀).  The
    engine's conditions of a candidate: tests/patterns/test_feasibility.py."""
    from certify.algebra.branches import norm_mpoly
    fp = FixedPoint(lam, r, sp.Integer(1), sp.Integer(1))
    cond = Condition.of("x - 1/2", x - HALF, fp)
    assert cond.numerator_norm() is not None
    assert cond.numerator_norm() == norm_mpoly(*cond.N, cond.delta)
    assert Condition.of("λ - 1/2", lam - HALF).numerator_norm() is None


def test_ball_values_of_h_at_r_and_lambda_contain_the_exact_value():
    """The balls the single-common-root route evaluates (h's coefficients in λ as polynomials in
    r, then Horner in λ) contain h(t, z) for rationals t, z, and are narrow: an evaluation with
    the powers of λ or r crossed (an error) would miss it."""
    from certify.algebra.balls import precision
    from certify.algebra.branches import _horner, _lambda_polys
    from certify.algebra.poly import ring_terms, to_ring
    h = to_ring(3 * lam**3 * r - sp.Rational(2, 7) * lam**2 + lam * r**4 - 5 * r**2 + sp.Rational(1, 3))
    for t, z in ((Q(1, 5), Q(-3, 4)), (Q(2, 3), Q(7, 2)), (Q(-1, 2), Q(1, 9))):
        exact = 3 * z**3 * t - Q(2, 7) * z**2 + z * t**4 - 5 * t**2 + Q(1, 3)
        with precision(200):
            coeffs = [flint.arb_poly(p)(flint.arb(t)) for p in _lambda_polys(ring_terms(h))]
            v = _horner(coeffs, flint.acb(flint.arb(z)))
            # the exact value minus the ball's centre, exactly, within the radius
            assert abs(exact - v.real.mid().fmpq()) <= v.real.rad().fmpq() and v.imag.contains(0)
        assert v.real.rad().fmpq() < Q(1, 2**150)


def test_sign_on_branch_at_is_the_branchs_entry_of_sign_at_point():
    # the point signs computed for one branch alone (Spectrum.sign_on_branch_at) are the
    # entries of sign_at_point: signs None (x not real: Δ < 0 on branch 0 for r > 1/9), at
    # Δ = 0 (r = 1/9 on branch 0, x₊ = -1/3 there: undecided for x + 1/3), and a missing
    # branch past the last one
    S = Spectrum(SQRT)
    fp = FixedPoint(lam, -r, sp.Integer(1), sp.Integer(1))
    for name, g in (("x", x), ("x + 1/3", x + sp.Rational(1, 3)), ("λ - 1/3", lam - sp.Rational(1, 3))):
        cond = Condition.of(name, g, fp)
        for rc in (Algebraic.rational(Q(1, 9)), Algebraic.rational(Q(1, 4)), Algebraic.rational(Q(1, 16))):
            full = list(S.sign_at_point(cond, rc))
            assert [S.sign_on_branch_at(cond, rc, k) for k in range(len(full))] == full
            assert S.sign_on_branch_at(cond, rc, len(full)) == NO_BRANCH
    assert S.sign_on_branch_at(Condition.of("x", x, fp), Algebraic.rational(Q(1, 9)), 0) == -1
    assert S.sign_on_branch_at(Condition.of("x", x, fp), Algebraic.rational(Q(1, 4)), 0) is None


def test_lrq_terms_are_the_ring_terms_in_order():
    # a Condition built from fmpq_mpoly reads its terms with _lrq_terms (monomials and
    # coefficients read in order): the terms, in the order, of the equal element of the ring
    from certify.algebra.branches import _lrq_terms
    from certify.algebra.poly import ring_terms, ring_to_lrq, to_ring
    for e in (lam ** 3 * r ** 2 - sp.Rational(3, 7) * lam * r ** 5 + 2 * r - sp.Rational(1, 9),
              (lam - r) ** 4 * (2 * lam + 3 * r ** 2 - 1), sp.Integer(5), sp.Integer(0)):
        p = to_ring(e)
        q = ring_to_lrq(p)
        assert _lrq_terms(q) == ring_terms(p) == [(c, er, el) for (el, er), c in q.to_dict().items()]


def _irreducible(coeffs: list[int]) -> flint.fmpq_poly | None:
    """The polynomial Σ coeffs[i] r^i when it is irreducible over Q of degree ≥ 2, else None."""
    f = flint.fmpz_poly(coeffs)
    if f.degree() < 2:
        return None
    _, factors = f.factor()
    return flint.fmpq_poly(f) if len(factors) == 1 and factors[0][1] == 1 else None


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(st.lists(st.integers(-9, 9), min_size=3, max_size=7),
       st.lists(st.lists(st.integers(-10 ** 6, 10 ** 6), min_size=1, max_size=6), min_size=2, max_size=4),
       st.lists(st.integers(-10 ** 40, 10 ** 40), min_size=1, max_size=6), st.integers(1, 10 ** 30))
def test_monic_modulo_primes_is_the_monic_by_xgcd(m_coeffs, q_coeffs, c_coeffs, den):
    """nf.monic makes p ∈ Q(α)[λ] monic modulo primes (each lift checked exactly) or by an inverse in Q(α)
    (xgcd): the same polynomial.  p = c·q with q monic and small, c of 40-digit coefficients over a large
    denominator, as the gcds of pseudo-remainders the engine makes monic."""
    m = _irreducible(m_coeffs)
    assume(m is not None)
    c = nf.reduce(flint.fmpq_poly([flint.fmpq(x, den) for x in c_coeffs]), m)
    assume(not c.is_zero())
    q = [flint.fmpq_poly(1)] + [nf.reduce(flint.fmpq_poly(x), m) for x in q_coeffs[1:]]
    p = [nf.reduce(c * e, m) for e in q]
    g, inv, _ = p[0].xgcd(m)
    by_xgcd = [nf.reduce(e * inv, m) for e in p]
    assert by_xgcd == q
    assert nf._monic_modular(p, m) == q
    assert nf.monic(p, m) == q


def test_a_lift_that_fails_its_exact_check_is_never_returned(monkeypatch):
    """The modular route returns a lift only when p[0]·q ≡ p[i] modulo m holds exactly: with every lift
    altered (a coefficient off by one) it gives up, and nf.monic falls back to the inverse by xgcd."""
    m = flint.fmpq_poly([-2, 0, 0, 1])                                # r³ - 2
    c = flint.fmpq_poly([flint.fmpq(3 ** 60, 7 ** 30), 5, flint.fmpq(-11, 13)])
    q = [flint.fmpq_poly(1), flint.fmpq_poly([1, flint.fmpq(2, 3)]), flint.fmpq_poly([0, 0, 5])]
    p = [nf.reduce(c * e, m) for e in q]
    assert nf._monic_modular(p, m) == q
    lift = nf._lift
    monkeypatch.setattr(nf, "_lift", lambda rows, M: [e + 1 for e in lift(rows, M)] if lift(rows, M) else None)
    assert nf._monic_modular(p, m) is None
    assert nf.monic(p, m) == q
    zero = [flint.fmpq_poly(0)] + p[1:]                              # a leading coefficient 0: no inverse
    with pytest.raises(ZeroDivisionError):
        nf.monic(zero, m)


def test_a_quotient_of_ten_thousand_bits_is_lifted():
    """A quotient whose coefficients have 5000-bit numerators over a common 5000-bit denominator (as the
    60-letter five-particle word's gcd: 5486 and 5344 bits) needs about 160 primes of 62 bits: it is read
    with the common denominator, and the lift of the last batch of primes is checked (256 here)."""
    import random
    rng = random.Random(3)
    m = flint.fmpq_poly([-3, 1, 0, 0, 0, 1])                         # r⁵ + r - 3, irreducible
    D = rng.getrandbits(5000) | 1
    q = [flint.fmpq_poly(1), flint.fmpq_poly([flint.fmpq(rng.getrandbits(5000) - (1 << 4999), D) for _ in range(5)])]
    c = flint.fmpq_poly([flint.fmpq(rng.getrandbits(200), rng.getrandbits(200) | 1) for _ in range(5)])
    p = [nf.reduce(c * e, m) for e in q]
    assert nf._monic_modular(p, m) == q


def _fraction_by_fraction(c: flint.fmpq_poly, R: flint.arb) -> flint.arb:
    """An element of Q(α) at a ball, each coefficient read as a reduced fraction (nf.arb_of before it
    read numerators over the common denominator)."""
    val, coeffs = flint.arb(0), c.coeffs()
    for k in range(len(coeffs) - 1, -1, -1):
        if coeffs[k] != 0:
            val += flint.arb(coeffs[k]) * R ** k
    return val


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(st.integers(-2 ** 3000, 2 ** 3000), st.integers(1, 2 ** 3000)), min_size=0, max_size=8),
       st.integers(2 ** 40, 2 ** 62), st.integers(0, 2 ** 30), st.sampled_from([53, 128, 286, 1100]))
def test_arb_of_gives_the_ball_of_each_reduced_fraction(coeffs, mid, rad, prec):
    """nf.arb_of reads c's coefficients as numerators over the common denominator (the quotient of two
    exact balls, rounded once): the same ball, bit for bit, as each reduced fraction's ball, so that no
    zero test of the committed data can move between decided and undecided."""
    c = flint.fmpq_poly([flint.fmpq(p, q) for p, q in coeffs])
    with flint.ctx.workprec(prec):
        R = flint.arb(flint.fmpq(mid, 2 ** 62), flint.fmpq(rad, 2 ** 70))     # in ]0, 1], as α
        ours, theirs = nf.arb_of(c, R), _fraction_by_fraction(c, R)
        assert ours.mid().man_exp() == theirs.mid().man_exp() and ours.rad().man_exp() == theirs.rad().man_exp()


def test_the_gcd_in_the_number_field_is_made_once_for_the_conjugate_critical_values(monkeypatch):
    """Spectrum._gcd_modulo keeps gcd(cp, h) in Q[r]/(m)[λ] per h and m, and _monic_modulo its monic
    form: at conjugate critical values (roots of one m) the zero tests reuse them.  With the resultant
    hidden (every test goes to the gcd), the zero tests of abacbcb's conditions with √Δ at the critical
    values of their tables (one m has two roots in ]0, 1[) are those of a spectrum that computes every
    gcd again, with fewer gcds made."""
    from certify.algebra.poly import mpoly_to_ring
    from certify.dynamics.systems import candidate_in
    from certify.patterns.feasibility import condition, fixed_point_data, prefix_requirements
    cand = candidate_in("four", "abacbcb")
    base = cand.spectrum
    kept, again = Spectrum(base.cp, base.ring_cp), Spectrum(base.cp, base.ring_cp)
    for spec in (kept, again):
        monkeypatch.setattr(spec, "resultant", lambda g: flint.fmpz_poly(0))
    monkeypatch.setattr(again, "_gcd_modulo",
                        lambda h, hk, m: nf.gcd(nf.kpoly(again.ring_cp, m), hk, m, make_monic=False))
    gcd, monic, calls = nf.gcd, nf.monic, []                   # the gcds and their monic forms made
    monkeypatch.setattr(nf, "gcd", lambda *a, **k: calls.append(str(a[2])) or gcd(*a, **k))
    monkeypatch.setattr(nf, "monic", lambda *a: calls.append(str(a[1])) or monic(*a))
    reqs, _ = prefix_requirements("abacbcb", 7, cand.q0, cand.steps, cand.q0_other)
    fps = fixed_point_data(cand.abcd_ring, base.ring_cp)
    conds = [condition(req, base.lrq_cp, fp) for req in reqs if req.has_x for fp in fps]
    answers, counts, moduli = [], [0, 0], {}
    for cond in conds:
        hs = [cond.N[0], cond.D[0]] + [mpoly_to_ring(e) for e in cond.norms()]
        for rc in base.critical_values(cond, 0, 1):
            moduli.setdefault(str(nf.modulus(rc)), set()).add(rc.key())
            for k in range(len(base.branches_at(rc) or [])):
                for h in hs:
                    if h:
                        for i, spec in enumerate((kept, again)):
                            n = len(calls)
                            answers.append((i, spec.vanishes_at(h, rc, k)))
                            counts[i] += len(calls) - n
    assert answers and [a for i, a in answers if i == 0] == [a for i, a in answers if i == 1]
    assert any(len(keys) > 1 for keys in moduli.values())
    assert 0 < counts[0] < counts[1]
