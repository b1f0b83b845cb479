"""The fast paths of certify.algebra.facts against the SymPy computations they replace: the
witnesses must not change (reports/certificates.json byte for byte)."""
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from certify.algebra import facts
from tests.expressions import expressions

x, y, r, th = sp.symbols("x y r θ")
GENS = [r, x, y, sp.cos(th), sp.sin(th)]


def sympy_terms(e, gens):
    """What facts recorded before polynomial_terms: SymPy's expand and Poly."""
    P = sp.Poly(sp.expand(e), *gens, domain="QQ")
    return sorted([facts.rational(c), list(m)] for m, c in P.terms())


exprs = expressions(GENS + [sp.Rational(1, 2), sp.Rational(-3, 7), sp.Integer(0), sp.Integer(2)])


@settings(max_examples=200, deadline=None)
@given(exprs)
def test_polynomial_terms_are_sympys(e):
    """The same sorted terms, exponents as ints (JSON), the zero polynomial as one term 0."""
    got = facts.polynomial_terms(e, GENS)
    assert got == sympy_terms(e, GENS)
    assert all(type(k) is int for _, m in got for k in m)


@pytest.mark.parametrize("e", [1 / x, sp.sqrt(2) * x, x ** sp.Rational(1, 2), sp.Float(0.5) * x, sp.Symbol("z") * x,
                               sp.cos(x) * x])
def test_not_a_polynomial_is_left_to_sympy(e):
    """What polynomial_terms does not read (a negative or fractional power, a float, another symbol
    or function) raises, and _rational_function asks SymPy as before."""
    with pytest.raises(facts._NotPolynomial):
        facts.polynomial_terms(e, GENS)


def test_rational_function_of_a_fraction():
    e = (x ** 2 - 1) / (2 * x * y + sp.Rational(1, 3)) + sp.cos(th) * r
    gens, _ = facts.generators(e)
    n, d = sp.fraction(sp.together(e))
    assert facts.rational_function(e, gens) == {"num": sympy_terms(n, gens), "den": sympy_terms(d, gens)}


def bare_by_subs(e) -> set:
    """The bare symbols as generators() found them before: each function atom replaced by a Dummy."""
    bare = e.subs({f: sp.Dummy() for f in e.atoms(sp.Function)})
    return {s for s in bare.free_symbols if not isinstance(s, sp.Dummy)}


@settings(max_examples=200, deadline=None)
@given(exprs, st.sampled_from([x, th, r * sp.cos(x), sp.Dummy() * y, sp.sin(y) * y]))
def test_bare_symbols_are_those_outside_functions(e, extra):
    e = e + extra
    assert facts._atoms(e)[2] == bare_by_subs(e)


integral_exprs = expressions(GENS + [sp.Integer(-2), sp.Integer(0), sp.Integer(1), sp.Integer(3)])


@settings(max_examples=200, deadline=None)
@given(integral_exprs)
def test_an_expression_without_fractions_is_its_own_numerator(e):
    """For an expression without fractions, rational_function's shortcut (the terms of e over 1)
    is what SymPy's together and fraction give."""
    assert facts._integral(e)
    n, d = sp.fraction(sp.together(e))
    assert facts._rational_function(e, GENS) == {"num": sympy_terms(n, GENS), "den": sympy_terms(d, GENS)}


@pytest.mark.parametrize("e", [x / 2, x ** -1, sp.sqrt(x), sp.Float(2.0) * x, x * (r / 2 + sp.Rational(1, 2))])
def test_a_fraction_is_left_to_together(e):
    assert not facts._integral(e)


@settings(max_examples=300, deadline=None)
@given(exprs)
def test_an_expanded_polynomial_over_q_is_l_times_itself_over_l(e):
    """For a polynomial over Q written expanded, rational_function's shortcut (the terms of L·e
    over L, L the lcm of the denominators) is what SymPy's together and fraction give; an
    unexpanded one is left to together (whose numerator need not be L·e: (r+1)²/2 − (r−1)²/2)."""
    g = sp.expand(e)
    assert facts._expanded_over_q(g)
    n, d = sp.fraction(sp.together(g))
    assert facts._rational_function(g, GENS) == {"num": sympy_terms(n, GENS), "den": sympy_terms(d, GENS)}
    h = (r + 1) ** 2 / 2 - (r - 1) ** 2 / 2
    assert not facts._expanded_over_q(h) and sp.fraction(sp.together(h))[1] == 2 and sp.expand(h) == 2 * r


@pytest.mark.parametrize("e", [x / 2 + sp.cos(th) ** 2 * y / 6, -x * r / 4, sp.Rational(3, 2),
                               sp.Rational(-5, 6) * x ** 3 - y / 10, 2 * x * y / 3 + 4 * x / 9])
def test_expanded_polynomials_over_q(e):
    """Content, common monomials and signs: the same numerator and denominator as together's."""
    n, d = sp.fraction(sp.together(e))
    assert facts._expanded_over_q(e)
    assert facts._rational_function(e, GENS) == {"num": sympy_terms(n, GENS), "den": sympy_terms(d, GENS)}


@settings(max_examples=200, deadline=None)
@given(exprs, st.sampled_from([x, th, r * sp.cos(x), sp.Dummy() * y, sp.sin(y) * y, sp.sqrt(x), sp.cos(x ** 2)]))
def test_one_walk_finds_the_atoms(e, extra):
    """_atoms: the sets of atoms() (the same iteration order: filled in preorder) and the bare symbols."""
    e = e + extra
    functions, powers, bare = facts._atoms(e)
    assert functions == e.atoms(sp.Function) and list(functions) == list(e.atoms(sp.Function))
    assert powers == e.atoms(sp.Pow) and list(powers) == list(e.atoms(sp.Pow))
    assert bare == bare_by_subs(e)
