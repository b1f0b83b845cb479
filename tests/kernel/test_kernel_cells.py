"""The univariate cylindrical decomposition (certify_kernel.cells) and the arithmetic at an
algebraic r₀ (certify_kernel.field): the bounding polynomials of a condition (the discriminant
and leading coefficient of cp, the norms' resultants, Δ), the pieces of an interval (a rational
sample strictly inside each open cell, the cut points between them), and exact signs at a
sample, at an algebraic point and on each eigenvalue branch."""
from __future__ import annotations

from fractions import Fraction as F

import pytest

from certify_kernel.cells import Condition, Point, Undecided, _between, _simplest, condition_sign, pieces
from certify_kernel.field import AtR0
from certify_kernel.poly import sign, value
from certify_kernel.sturm import Algebraic, real_roots
from certify_kernel.values import Undefined, number
from tests.kernel.kernel_support import value_of

ONE = {(0, 0): F(1)}


def poly_r(*coeffs) -> dict:
    """A polynomial in r alone, lowest degree first, as a condition's part over (r, λ)."""
    return {(k, 0): F(c) for k, c in enumerate(coeffs) if c}


def g_of_r(*coeffs) -> Condition:
    return Condition(None, poly_r(*coeffs), ONE)


# ------------------------------------------------------------------ samples

@pytest.mark.parametrize("lo, hi, simplest", [
    (F(0), F(1), F(1, 2)), (F(1, 3), F(1, 2), F(2, 5)), (F(-1), F(1), F(0)), (F(1, 2), F(3), F(1)),
    (F(-3), F(-1, 2), F(-1)), (F(3, 10), F(31, 100), F(4, 13)), (F(0), F(1, 100), F(1, 101)),
])
def test_simplest_fraction_between(lo, hi, simplest):
    assert _simplest(lo, hi) == simplest
    assert lo < simplest < hi


def close_pairs():
    """Pairs a < b of algebraic numbers with wide isolating intervals (as real_roots leaves them),
    some very close, some rational, and ∓∞ (None)."""
    sqrt2 = lambda: Algebraic([F(-2), F(0), F(1)], 1, 2)                 # noqa: E731
    out = [(sqrt2(), number(F(3, 2))), (number(F(7, 5)), sqrt2()), (sqrt2(), number(F(14143, 10000))),
           (number(F(14142, 10000)), sqrt2()), (number(0), number(1)), (None, number(0)), (number(1), None),
           (None, sqrt2())]
    roots = real_roots([F(c) for c in (-6, 11, -6, 1)]) + real_roots([F(-2), F(0), F(1)])   # 1, 2, 3, ±√2
    roots.sort(key=lambda a: float(a.lo + a.hi))
    out += [(a, b) for a, b in zip(roots, roots[1:])]
    P0 = [F(c) for c in (41, -646, 3733, -14600, 42306, -78052, 42306, -14600, 3733, -646, 41)]
    rstar = real_roots(P0)[-1]                                             # r* ≈ 0.11384
    out += [(number(F(11383, 100000)), rstar), (rstar, number(F(11384, 100000)))]
    return out


def test_a_sample_lies_strictly_inside_its_cell():
    for a, b in close_pairs():
        x = _between(a, b)
        assert a is None or number(a).compare_rational(x) < 0, (a, b, x)
        assert b is None or number(b).compare_rational(x) > 0, (a, b, x)


# ------------------------------------------------------------------ bounding polynomials and pieces

def roots_of(polys) -> list[float]:
    """The real roots of the polynomials, to 1e-12."""
    out = []
    for p in polys:
        for a in real_roots(p):
            while a.hi - a.lo > F(1, 10 ** 12):
                a.bisect()
            out.append(round(float(a.hi), 9))
    return sorted(out)


def test_the_bounding_polynomials_of_a_condition_on_a_branch():
    cp = {(0, 2): F(1), (1, 0): F(-1), (0, 0): F(1, 4)}                   # λ² − (r − 1/4): real for r ≥ 1/4
    g = Condition(cp, {(0, 1): F(1), (0, 0): F(-5)}, ONE)                  # λ − 5: λ = 5 at r = 101/4
    assert roots_of(g.bounding()) == [0.25, 25.25]                         # the discriminant, the resultant
    cp2 = {(1, 2): F(1), (0, 2): F(-1, 2), (0, 0): F(-1)}                  # (r − 1/2)λ² − 1: a branch escapes at 1/2
    assert 0.5 in roots_of(Condition(cp2, {(0, 1): F(1)}, ONE).bounding())
    h = Condition(cp, ONE, {(0, 1): F(1), (0, 0): F(-1)})                  # 1/(λ − 1): a pole at r = 5/4
    assert 1.25 in roots_of(h.bounding())


def test_the_bounding_polynomials_with_a_square_root():
    """g = N0 + N1√Δ: zero where the norm N0² − N1²Δ is; Δ's roots bound the cells too."""
    g = Condition(None, poly_r(-1), ONE, poly_r(1), None, poly_r(0, 1))    # −1 + √r: zero at r = 1
    assert roots_of(g.bounding()) == [0.0, 1.0]


def test_a_condition_that_vanishes_on_a_branch_is_refused():
    cp = {(0, 2): F(1), (1, 0): F(-1)}                                     # λ² − r
    with pytest.raises(Undefined):
        Condition(cp, {(0, 2): F(1), (1, 0): F(-1)}, ONE).bounding()       # λ² − r ≡ 0 on every branch


def test_pieces_alternate_cells_and_cut_points():
    ps = pieces([g_of_r(F(3, 16), -1, 1)], number(0), number(1))          # (r − 1/4)(r − 3/4)
    assert [p.cell for p in ps] == [True, False, True, False, True]
    assert [float(number(p.r0).lo) for p in ps[1::2]] == [0.25, 0.75]
    samples = [p.r0 for p in ps[0::2]]
    assert all(isinstance(x, F) for x in samples)
    assert 0 < samples[0] < F(1, 4) < samples[1] < F(3, 4) < samples[2] < 1
    assert ps[1].left is ps[0] and ps[1].right is ps[2] and ps[3].left is ps[2] and ps[3].right is ps[4]


def test_closed_ends_are_points_and_outside_cuts_are_dropped():
    ps = pieces([g_of_r(-2, 1)], number(0), number(1), True, True)        # r − 2: its root is outside
    assert [p.cell for p in ps] == [False, True, False]
    assert ps[0].r0.compare_rational(0) == 0 and ps[2].r0.compare_rational(1) == 0
    assert ps[0].right is ps[1] and ps[2].left is ps[1]


def test_a_point_interval_and_empty_intervals():
    ps = pieces([], number(F(1, 2)), number(F(1, 2)), True, True)
    assert len(ps) == 1 and not ps[0].cell
    for closed in ((False, False), (True, False), (False, True)):
        with pytest.raises(Undefined):
            pieces([], number(F(1, 2)), number(F(1, 2)), *closed)


# ------------------------------------------------------------------ signs

def constant_sign(part: list) -> int:
    return sign(value(part, 0)) if part else 0


@pytest.mark.parametrize("parts, expected", [
    (dict(N0=[F(1)], N1=[F(-1)], delta=[F(2)], D0=[F(1)]), -1),                  # 1 − √2
    (dict(N0=[F(-1)], N1=[F(1)], delta=[F(2)], D0=[F(1)]), 1),                   # −1 + √2
    (dict(N0=[F(2)], N1=[F(-1)], delta=[F(3)], D0=[F(1)]), 1),                   # 2 − √3
    (dict(N0=[F(1)], N1=[F(1)], delta=[F(2)], D0=[F(1)], D1=[F(-1)]), -1),      # (1 + √2)/(1 − √2)
    (dict(N0=[F(-3)], N1=[F(1)], delta=[F(2)], D0=[F(-1)]), 1),                  # (−3 + √2)/(−1)
    (dict(N0=[], N1=[F(-1)], delta=[F(2)], D0=[F(1)]), -1),                      # −√2
    (dict(N0=[F(1)], N1=[F(5)], delta=[], D0=[F(1)]), 1),                        # Δ = 0: 1
    (dict(N0=[F(-1)], N1=[F(5)], delta=[F(-1)], D0=[F(1)]), None),               # Δ < 0: x not real
    (dict(N0=[F(1)], D0=[F(-2)]), -1), (dict(N0=[], D0=[F(3)]), 0),
])
def test_condition_sign_of_a_quadratic_surd(parts, expected):
    assert condition_sign(parts, constant_sign) == expected


def test_a_pole_is_undecided():
    with pytest.raises(Undecided):
        condition_sign(dict(N0=[F(1)], D0=[F(1)], D1=[F(-1)], delta=[F(1)]), constant_sign)    # 1/(1 − √1)


def test_signs_at_a_rational_sample_and_at_an_algebraic_point():
    r0 = number(value_of("√2/2"))
    at = Point(r0, cell=False)
    assert at.sign(g_of_r(F(-1, 2), 0, 1), None) == 0                          # r² − 1/2 vanishes at √2/2
    assert at.sign(g_of_r(F(-1, 2), 1), None) == 1                             # r − 1/2 > 0 there
    assert at.sign(g_of_r(F(-7072, 10000), 1), None) == -1                     # √2/2 < 0.7072
    assert at.sign(Condition(None, ONE, poly_r(F(-7071, 10000), 1)), None) == 1   # 1/(r − 0.7071) > 0
    cell = Point(F(1, 3), cell=True)
    assert cell.sign(g_of_r(F(-1, 2), 0, 1), None) == -1
    with pytest.raises(Undecided):
        Point(F(1, 2), cell=True).sign(Condition(None, ONE, poly_r(F(-1, 2), 1)), None)      # 1/(r − 1/2) at 1/2


def test_signs_on_the_branches():
    cp = {(0, 2): F(1), (2, 0): F(-1), (0, 0): F(1, 2)}                    # λ² = r² − 1/2
    lam = Condition(cp, {(0, 1): F(1)}, ONE)
    at = Point(number(value_of("√2/2")), cell=False)
    assert at.branches(cp) == 2                                            # a double root, counted twice
    assert (at.sign(lam, 0), at.sign(lam, 1)) == (0, 0)
    cell = Point(F(1), cell=True)
    assert cell.branches(cp) == 2 and (cell.sign(lam, 0), cell.sign(lam, 1)) == (1, -1)   # ±√(1/2), largest first
    assert Point(F(0), cell=True).branches(cp) == 0
    with pytest.raises(Undefined):
        Point(F(0), cell=True).sign(lam, 0)                                # no such branch
    shifted = Condition(cp, {(0, 1): F(1), (1, 0): F(-1)}, ONE)            # λ − r < 0 on both branches at r = 1
    assert (cell.sign(shifted, 0), cell.sign(shifted, 1)) == (-1, -1)
    at_root = Point(number(value_of("√3/2")), cell=False)                  # λ² = 1/4 at r = √3/2
    quarter = Condition(cp, {(0, 1): F(1), (0, 0): F(-1, 2)}, ONE)
    assert (at_root.sign(quarter, 0), at_root.sign(quarter, 1)) == (0, -1)


def test_arithmetic_at_an_algebraic_r0():
    A = AtR0(number(value_of("√2")))
    assert A.sign([F(-2), F(0), F(1)]) == 0 and A.sign([F(-1), F(1)]) == 1 and A.sign([F(-3, 2), F(1)]) == -1
    assert A.reduce([F(0), F(0), F(1)]) == [F(2)]                         # r² ≡ 2 modulo r² − 2
    P = [[F(-2), F(0), F(1)], [], [F(1)]]                                  # λ² + (r² − 2) = λ² at √2
    assert len(A.branches(P)) == 2                                         # λ = 0, twice
    Q = [[F(-1)], [], [F(1)]]                                              # λ² − 1
    assert [iv[0] < 0 < iv[1] or iv[0] < -1 < iv[1] or iv[0] < 1 < iv[1] for iv in A.roots(Q)[1]] == [True, True]
    assert A.taq([[F(0), F(1)]], Q, "-inf", "+inf") == 2                  # Σ sign(r) over λ = ±1: 2·sign(√2)
    assert A.taq([[], [F(1)]], Q, "-inf", "+inf") == 0                    # Σ sign(λ) over λ = ±1
    assert A.taq([[F(-1)], [F(1)]], Q, "-inf", "+inf") == -1              # Σ sign(λ − 1): 0 − 1
    assert A.taq([], Q, 0, "+inf", A.sequence(Q, [[], [F(2)]])) == 1      # Sturm: one root in ]0, ∞[
