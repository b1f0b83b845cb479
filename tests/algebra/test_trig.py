"""certify.algebra.trig's shortcuts against the SymPy computations they replace (the evidence
strings of the certificates must not change)."""
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from certify.algebra import trig as T

x, y, r = sp.symbols("x y r")
atoms = st.sampled_from([x, y, r, T.cθ, T.sφ, sp.Rational(1, 2), sp.Rational(-3, 7), sp.Integer(2), sp.Integer(-1)])
polys = st.recursive(atoms, lambda sub: st.one_of(
    st.lists(sub, min_size=2, max_size=3).map(lambda a: sp.Add(*a)),
    st.lists(sub, min_size=2, max_size=3).map(lambda a: sp.Mul(*a)),
    st.tuples(sub, st.integers(1, 3)).map(lambda a: a[0] ** a[1])), max_leaves=10)


@settings(max_examples=150, deadline=None)
@given(polys)
def test_factored_is_sympys_factor(p):
    """_factored (from the memoised factor list) is the expression sp.factor gives, printed alike."""
    g = sp.expand(p)
    assert T._factored(g) == sp.factor(g)
    assert T.show(T._factored(g)) == T.show(sp.factor(g))


def test_undecided_sign_shows_sympys_factor():
    """An undecided sign shows the polynomial factored as sp.factor shows it (from the memoised
    factor list of its expanded form)."""
    H = T.Signs(atoms=((r, 1),))
    p = sp.expand((x - y) * (x + 2 * y) * (r + 1) * 3)
    s, why = T._poly_sign(p, H)
    assert s is None and why[0].startswith(f"`{T.show(sp.factor(p))}`: ")
