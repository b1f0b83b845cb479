"""Hypothesis strategies of SymPy expressions, for the tests of the fast paths against SymPy."""
import sympy as sp
from hypothesis import strategies as st


def expressions(atoms: list, exponents: tuple = (0, 3), max_leaves: int = 12):
    """Sums and products of two or three, and integer powers (exponents in the closed range
    ``exponents``; 0 to a negative power left as 0), built from ``atoms``."""
    lo, hi = exponents

    def power(a):
        base, k = a
        return base ** k if k >= 0 or base != 0 else base

    return st.recursive(st.sampled_from(atoms), lambda sub: st.one_of(
        st.lists(sub, min_size=2, max_size=3).map(lambda a: sp.Add(*a)),
        st.lists(sub, min_size=2, max_size=3).map(lambda a: sp.Mul(*a)),
        st.tuples(sub, st.integers(lo, hi)).map(power)), max_leaves=max_leaves)
