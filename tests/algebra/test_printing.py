"""certify.algebra.printing writes the text SymPy's printer gives (``show``: sstr with
order="lex", ``^``, no ``*``) for the expanded, factored and collected polynomials and the
cancelled fractions of the reports: compared with the SymPy route on random polynomials
and rational functions in r, λ (tests/expressions.py)."""
import flint
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from certify.algebra import printing
from certify.algebra.poly import from_flint, lam, notation, r, show, show_collected, show_factored, to_field, to_ring
from certify.dynamics.model import factor_flint, factor_lr
from certify.patterns import pattern
from tests.expressions import expressions

ATOMS = [r, lam, sp.Integer(1), sp.Integer(-1), sp.Integer(2), sp.Integer(-3), sp.Rational(1, 2), sp.Rational(-5, 4)]
SETTINGS = settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])

polynomials = expressions(ATOMS, exponents=(0, 3), max_leaves=12).map(sp.expand)
fractions = expressions(ATOMS, exponents=(-2, 3), max_leaves=10)
_terms = st.tuples(st.integers(-3, 3).filter(bool), st.integers(0, 2), st.integers(0, 2))
_small = st.lists(_terms, min_size=1, max_size=3).map(lambda ts: sp.Add(*[c * r ** a * lam ** b for c, a, b in ts]))
products = st.tuples(st.lists(st.tuples(_small, st.integers(1, 3)), min_size=1, max_size=4),
                     st.sampled_from([1, -1, 2, sp.Rational(-3, 4), sp.Rational(1, 6)])).map(
    lambda fs: sp.expand(fs[1] * sp.Mul(*[f ** m for f, m in fs[0]])))   # several factors, repeated, scaled


def univariate(e) -> flint.fmpq_poly:
    """e at λ = 1 - r (a polynomial in r alone, often with repeated factors), as fmpq_poly."""
    coeffs = sp.Poly(sp.expand(e.subs(lam, 1 - r)), r).all_coeffs()[::-1]
    return flint.fmpq_poly([flint.fmpq(int(sp.numer(c)), int(sp.denom(c))) for c in coeffs])


@SETTINGS
@given(polynomials)
def test_the_ring_is_shown_as_sympy_shows_its_expression(e):
    p = to_ring(e)
    assert show(p) == show(p.as_expr())            # the direct route against sstr of the expression
    names, terms = printing.ring_terms(p)
    assert printing.expanded(names, terms, order=None) == str(p.as_expr())     # SymPy's default order


@SETTINGS
@given(st.one_of(polynomials, products))
def test_factored_univariate_is_sympy_factor(e):
    p = univariate(e)
    assert show_factored(p) == show(factor_flint(p)) == show(sp.factor(from_flint(p, r)))


@SETTINGS
@given(st.one_of(polynomials, products))
def test_factored_bivariate_is_sympy_factor(e):
    p = to_ring(e)
    den = 1
    for c in p.values():
        den = den * int(c.denominator) // flint.fmpz(den).gcd(int(c.denominator))
    F = printing.RL.from_dict({(m[1], m[0]): int(c * den) for m, c in p.terms()})
    assert notation(printing.factored_mpoly(F, int(den))) == show(factor_lr(e)) == show(sp.factor(e))


@SETTINGS
@given(polynomials)
def test_collected_is_sympy_collect(e):
    assert show_collected(to_ring(e), "λ") == show(sp.collect(e, lam))


@SETTINGS
@given(fractions, st.sampled_from([10, 40, 3000]))
def test_the_datum_fraction_is_sympy_cancel(monkeypatch_long, e, long):
    """The cancelled fraction, each side factored or expanded by its printed length (LONG
    lowered so that both branches are taken)."""
    try:
        f = to_field(e)
    except ZeroDivisionError:
        return
    monkeypatch_long(long)
    assert pattern._fraction_text_lr(f) == pattern._fraction_text(f)


@pytest.fixture(scope="module")
def monkeypatch_long():
    old = pattern.LONG

    def set_long(value):
        pattern.LONG = value
    yield set_long
    pattern.LONG = old


def test_sympy_special_order_of_two_terms_is_kept():
    """``1 - 2*r`` is printed number first by str() (SymPy's special case), not in lex order."""
    p = to_ring(1 - 2 * r)
    names, terms = printing.ring_terms(p)
    assert printing.expanded(names, terms, order=None) == str(p.as_expr()) == "1 - 2*r"
    assert printing.expanded(names, terms) == sp.sstr(p.as_expr(), order="lex") == "-2*r + 1"


def test_the_ring_alone_is_printed_directly():
    """Another ring (or an expression) still goes through SymPy."""
    x = sp.Symbol("x")
    _, X = sp.ring("x", sp.QQ)
    assert show(X ** 2 - 2) == show(x ** 2 - 2) == "x^2 - 2"
