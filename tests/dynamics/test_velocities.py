"""certify.dynamics.words.velocities multiplies a polynomial q(0) in the sparse ring: the
same expanded expressions as SymPy's expand of the matrix products."""
import pytest
import sympy as sp

from certify.algebra import u, v
from certify.dynamics import collision_matrix, velocities


@pytest.mark.parametrize("word, q0", [("ababcb", [-1, u, v]), ("acbcab", [u, v / 3, -1]),
                                      ("abcb", [sp.Symbol("w"), u, 1])])
def test_velocities_are_the_expanded_products(word, q0):
    expected = [sp.Matrix(q0)]
    for letter in word:
        expected.append((collision_matrix(letter) * expected[-1]).applyfunc(sp.expand))
    got = velocities(word, sp.Matrix(q0))
    assert [sp.srepr(x) for x in got] == [sp.srepr(x) for x in expected]


@pytest.mark.parametrize("word", ["ababcb", "abcb", "acbcab"])
def test_the_characteristic_polynomial_is_sympys_charpoly(word):
    from certify.algebra import lam
    from certify.dynamics import characteristic_polynomial, word_matrix
    M = word_matrix(word)
    assert sp.srepr(characteristic_polynomial(M)) == sp.srepr(sp.expand(M.charpoly(lam).as_expr()))
