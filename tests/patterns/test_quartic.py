"""Five particles (issue 39): what the exact analysis of a word does with a quartic cp(M_w).

Works: the period matrix and its quartic, the real eigenvalue branches by exact root isolation
(Spectrum), sign tables of conditions in (r, λ), and the strict dominance of λ over the three
other eigenvalues, a complex pair included (Jury's criterion for the cubic cofactor)."""
import itertools
from fractions import Fraction

import flint
import numpy as np
import pytest
import sympy as sp

from certify import cli
from certify.algebra.branches import Spectrum
from certify.algebra.poly import Q, lam
from certify.dynamics.model import charpoly_flint, charpoly_ring
from certify.dynamics.systems import of_particles, system_matrix_flint
from certify.patterns.pattern import dominance_requirements, quotient_by_root

R = sp.Symbol("r")
ROOTS = [Fraction(k, 10) for k in range(-15, 16, 3)]   # inside and outside the unit circle


def dominant_by_roots(others) -> bool:
    return max(abs(complex(z)) for z in others) < 1


def requirement_signs(cp, lam0) -> list:
    return [q.G[0].as_expr().subs(lam, lam0) > 0 for q in dominance_requirements(cp)]


@pytest.mark.parametrize("others", [
    *[(a, b, c) for a, b, c in itertools.combinations_with_replacement(ROOTS, 3)],
    (sp.Rational(1, 2) + sp.I / 2, sp.Rational(1, 2) - sp.I / 2, sp.Rational(3, 10)),
    (sp.Rational(4, 5) + sp.I * sp.Rational(7, 10), sp.Rational(4, 5) - sp.I * sp.Rational(7, 10), 0),
    (sp.I * sp.Rational(99, 100), -sp.I * sp.Rational(99, 100), sp.Rational(-1, 2)),
    (sp.I * sp.Rational(101, 100), -sp.I * sp.Rational(101, 100), sp.Rational(1, 10)),
    (sp.Rational(-11, 10), sp.Rational(1, 10), 0),
    (-2, sp.Rational(-7, 5), sp.Rational(-3, 5)),      # only λ⁶ - C² - (CAλ² - Bλ⁴) fails
])
def test_quartic_dominance_is_the_moduli(others):
    """cp = (Λ - 1)(Λ - μ)(Λ - ν)(Λ - ρ): the six requirements hold at λ = 1 exactly when
    |μ|, |ν|, |ρ| < 1 (real roots, or a complex pair inside or outside the unit circle)."""
    cp = sp.expand((lam - 1) * sp.Mul(*[(lam - sp.nsimplify(z)) for z in others]))
    assert all(requirement_signs(cp, 1)) == dominant_by_roots(others)


def test_double_root_on_the_circle_is_not_dominant():
    cp = sp.expand((lam - 1) ** 2 * (lam - sp.Rational(1, 3)) * (lam + sp.Rational(1, 4)))
    assert not all(requirement_signs(cp, 1))


def test_quotient_by_root():
    from certify.algebra.poly import RING, to_ring
    cp = to_ring(sp.expand((lam - 2) * (lam ** 3 + 3 * lam ** 2 - 5 * lam + 7)))
    L = RING.gens[0]
    A, B, C = quotient_by_root(cp, L)
    assert sp.expand((A.as_expr(), B.as_expr(), C.as_expr())[0].subs(lam, 2)) == 3
    assert (B.as_expr().subs(lam, 2), C.as_expr().subs(lam, 2)) == (-5, 7)


@pytest.mark.parametrize("word, r0", [("abadcbcabc", Q(13, 50)), ("abcbdcb", Q(1, 5)), ("abcdcb", Q(1, 10)),
                                      ("abadcbcabc", Q(29, 100))])
def test_dominance_on_five_particle_words(word, r0):
    """On the real branches of a five-particle word's quartic at a rational r (isolated exactly by
    Spectrum), the requirements hold exactly when the branch is larger in modulus than the three
    other eigenvalues (numpy's, far from ties here)."""
    M = system_matrix_flint(of_particles(5), word)
    cp = charpoly_flint(M)
    S = Spectrum(cp, charpoly_ring(M))
    ev = np.linalg.eigvals(np.array([[float(e(r0)) for e in row] for row in M]))
    cp_r = sp.expand(cp.subs(R, sp.Rational(int(r0.p), int(r0.q))))
    for branch in S.real_eigenvalues(r0):
        value = float(branch.digits(15))
        k = int(np.argmin(abs(ev - value)))
        dominant = all(abs(ev[j]) < value for j in range(4) if j != k)
        reqs = [q.G[0].as_expr() for q in dominance_requirements(cp_r)]
        signs = [flint.arb(0) < sp.lambdify(lam, g)(branch.arb(200)) for g in reqs]
        assert all(signs) == dominant, (word, r0, value, ev)


def test_pattern_refuses_a_letter_beyond_five_particles(capsys):
    """`certify pattern` takes five-particle words (issue 39, tests/patterns/test_five.py); a letter beyond d
    is one line, exit 2."""
    assert cli.main(["pattern", "abadcbcabe"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and "use the letters a, b, c, d" in err
