"""The kernel's values (certify_kernel.values, sturm, poly): rational functions and their
identities, real algebraic numbers built from printed closed forms (each checked against its
minimal polynomial, computed independently and written here), comparisons, printed digits, and
Sturm's root counts."""
from __future__ import annotations

from fractions import Fraction as F

import pytest

from certify_kernel.poly import gcd, resultant_in, squarefree
from certify_kernel.sturm import Algebraic, count, real_roots
from certify_kernel.values import RF, Undefined, combine, number, roots_in, sqrt
from tests.kernel.kernel_support import truth_of, value_of

# closed form, its minimal polynomial (lowest degree first; sympy's minimal_polynomial), its value to 12 digits
CLOSED = [
    ("5-2√6", [1, -10, 1], "0.101020514434"),                           # l. 291
    ("(7-2√10)/3", [3, -14, 3], "0.225148226554"),                      # l. 349
    ("3+2√2-2√(4+3√2)", [1, -12, 6, -12, 1], "0.086427233726"),
    ("√2+√3", [1, 0, -10, 0, 1], "3.146264369942"),
    ("1/(1+√2)", [-1, 2, 1], "0.414213562373"),
    ("(1+√5)/2*(1-√5)/2", [1, 1], "-1.000000000000"),
]


@pytest.mark.parametrize("text, minimal, digits", CLOSED)
def test_a_closed_form_is_the_root_of_its_minimal_polynomial(text, minimal, digits):
    a = number(value_of(text))
    assert a.sign_of([F(c) for c in minimal]) == 0
    h = F(1, 10 ** 12)
    assert a.compare_rational(F(digits) - h) > 0 and a.compare_rational(F(digits) + h) < 0
    if not a.rational:
        a.validate()                        # its polynomial square-free, its interval isolating


@pytest.mark.parametrize("text, other", [("√2*√2", "2"), ("√8/√2", "2"), ("(√3+1)*(√3-1)", "2"),
                                         ("5-2√6", "1/(5+2√6)"), ("√(5+2√6)", "√2+√3"), ("√4", "2")])
def test_equal_closed_forms_compare_equal(text, other):
    assert number(value_of(text)).compare(number(value_of(other))) == 0
    assert truth_of(f"{text} = {other}")


@pytest.mark.parametrize("formula", ["5-2√6 < 5-2√5", "√2 + √3 > 3146/1000", "√2 + √3 < 3147/1000",
                                     "(7-2√10)/3 > 5-2√6", "3+2√2-2√(4+3√2) < 5-2√6", "√2 ≠ 1.41421356",
                                     "-√2 < 0", "5-2√6 ≤ 1/(5+2√6)", "5-2√6 ≥ 1/(5+2√6)"])
def test_comparisons_are_exact(formula):
    assert truth_of(formula)


@pytest.mark.parametrize("formula, holds", [
    ("5-2√6 ≈ 0.10102", True), ("5-2√6 ≈ 0.10103", False), ("5-2√6 ≈ 0.10101", False),
    ("5-2√6 ≈ 0.1010", True), ("5-2√6 ≈ 0.101", True), ("5-2√6 ≈ 0.1", True), ("5-2√6 ≈ 0.2", False),
    ("(7-2√10)/3 ≈ 0.22515", True), ("(7-2√10)/3 ≈ 0.22514", False),
    ("1/3 ≈ 0.333", True), ("1/3 ≈ 0.334", False), ("2/3 ≈ 0.667", True), ("2/3 ≈ 0.666", False),
    ("1/8 ≈ 0.125", True), ("1/8 ≈ 0.12", True), ("1/8 ≈ 0.13", True),     # an end of the rounding interval
    ("0.1251 ≈ 0.13", True), ("0.1249 ≈ 0.13", False),
])
def test_printed_digits_are_a_rounding_interval(formula, holds):
    """x ≈ d: x lies in [d − h, d + h], h half a unit of d's last digit (docs/statements.md)."""
    assert truth_of(formula) is holds


def test_digits_need_a_printed_decimal():
    with pytest.raises(Undefined):
        truth_of("1/3 ≈ 1/3")


def test_arithmetic_errors_are_undefined():
    for text in ("√(-2)", "1/(√2-√2)", "1/(r - r)"):
        with pytest.raises(Undefined):
            value_of(text)
    with pytest.raises(Undefined):
        combine("/", number(1), number(0))


def test_square_roots():
    assert sqrt(number(F(9, 4))).rational and sqrt(number(F(9, 4))).lo == F(3, 2)
    s = sqrt(number(2))
    assert s.sign_of([F(-2), F(0), F(1)]) == 0 and s.compare_rational(0) > 0


def test_rational_functions_and_their_identities():
    assert truth_of("(r + 1)^2 = r^2 + 2*r + 1")
    assert not truth_of("(r + 1)^2 = r^2 + 1")
    assert truth_of("(r^2 - 1)/(r - 1) = r + 1")
    assert truth_of("1/r + 1/λ = (r + λ)/(r*λ)")
    assert truth_of("x*u - u*x = 0")
    assert truth_of("(r - λ)^3 = -(λ - r)^3")
    assert not truth_of("r/λ = λ/r")
    assert value_of("(r^2 - 1)/(r - 1)").same(RF.var("r") + RF.const(1))
    assert value_of("r^-2").same(RF.const(1) / (RF.var("r") * RF.var("r")))


def test_a_constant_and_the_variables_used():
    assert value_of("(r^2 - r^2 + 6)/3").constant() == 2
    assert value_of("r*λ + u").used() == {"r", "λ", "u"}
    assert value_of("r - r").is_zero()


def test_sturm_counts_distinct_roots_in_half_open_intervals():
    p = [F(c) for c in (-6, 11, -6, 1)]                 # (x−1)(x−2)(x−3)
    assert count(p) == 3
    assert count(p, F(1), F(3)) == 2                    # ]1, 3]
    assert count(p, F(0), F(1)) == 1
    assert count(p, F(3, 2), F(5, 2)) == 1
    assert count([F(1), F(-2), F(1)], F(0), F(2)) == 1  # (x−1)²: one distinct root
    assert count([F(1), F(0), F(1)]) == 0               # x² + 1
    with pytest.raises(ValueError):
        count([])


def test_real_roots_largest_first_and_roots_in_with_their_ends():
    p = [F(c) for c in (-6, 11, -6, 1)]
    roots = real_roots(p)
    assert [r.compare_rational(k) for r, k in zip(roots, (3, 2, 1))] == [0, 0, 0]
    assert len(roots_in(p, number(1), number(3))) == 1
    assert len(roots_in(p, number(1), number(3), True, False)) == 2
    assert len(roots_in(p, number(1), number(3), True, True)) == 3
    assert len(roots_in(p, None, number(2))) == 1
    assert len(roots_in(p, None, None)) == 3


def test_an_algebraic_number_checks_its_interval():
    Algebraic([F(-2), F(0), F(1)], 1, 2)                                 # √2
    for poly, lo, hi in (([F(-2), F(0), F(1)], -2, 2),                   # two roots
                         ([F(-2), F(0), F(1)], 2, 3),                    # none
                         ([F(4), F(-4), F(1)], 1, 3),                    # (x−2)²: not square-free
                         ([F(-1), F(1)], 1, 2),                          # an end is the root
                         ([F(3)], 0, 1)):                                # a constant
        with pytest.raises(ValueError):
            Algebraic(poly, lo, hi)


def test_bisection_keeps_the_root_and_compare_decides_equality():
    a = Algebraic([F(-2), F(0), F(1)], 0, 4)
    for _ in range(30):
        a.bisect()
    assert a.lo < F(14142135, 10 ** 7) < F(14142136, 10 ** 7) < a.hi or a.hi - a.lo < F(1, 10 ** 8)
    b = Algebraic([F(-2), F(0), F(0), F(0), F(1)], 0, 2)                # 2^(1/4)
    c = Algebraic([F(4), F(0), F(-6), F(0), F(1)], 1, 3)                 # x⁴ − 6x² + 4: √(3+√5) ≈ 2.288
    assert b.compare(Algebraic([F(-2), F(0), F(1)], 1, 2)) < 0
    assert c.compare(number(value_of("√(3+√5)"))) == 0
    assert Algebraic([F(-2), F(0), F(1)], 1, 2).sign_of([F(-1), F(1)]) == 1           # √2 − 1 > 0
    assert Algebraic([F(-2), F(0), F(1)], 1, 2).sign_of([F(-2), F(0), F(1)]) == 0


def test_numbers_whose_polynomials_share_a_factor_are_told_apart():
    """√2 (a root of x² − 2) and 29/20 as a root of (x² − 2)(x − 29/20): a common factor, two numbers."""
    sqrt2 = Algebraic([F(-2), F(0), F(1)], 1, F(3, 2))
    other = Algebraic([F(58, 20), F(-2), F(-29, 20), F(1)], F(142, 100), F(3, 2))
    assert sqrt2.compare(other) < 0 and other.compare(Algebraic([F(-2), F(0), F(1)], 1, F(3, 2))) > 0


def test_polynomial_helpers():
    assert gcd([F(-1), F(0), F(1)], [F(1), F(1)]) == [F(1), F(1)]
    assert squarefree([F(1), F(-2), F(1)]) == [F(-1), F(1)]
    # Res_λ(λ − r, λ² − 2) is r² − 2 up to a constant
    R = resultant_in({(1, 0): F(-1), (0, 1): F(1)}, {(0, 2): F(1), (0, 0): F(-2)})
    assert R[0] / R[2] == -2 and R[1] == 0
