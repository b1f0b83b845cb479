"""The model of Section 2: the collision law, collision matrices, words and their matrices.

The law (l. 158-163) acts on the velocities v = (v1, v2, v3, v4) of the particles:
:func:`collide_particles`.  In relative coordinates p_i = x_{i+1} - x_i,
q_i = v_{i+1} - v_i (i = 1, 2, 3), a collision of type a, b, c (pairs 1-2, 2-3, 3-4)
maps q to A q, B q, C q (:func:`collide`, the printed matrices).  A word
w = c_1 c_2 ... c_n (collisions in time order) has the matrix
M_w = K_{c_n} ... K_{c_1}; for ababcb, M = BCBABA.
"""
from __future__ import annotations

import re

import flint
import sympy as sp
from sympy.core.mul import _keep_coeff

from certify.algebra.poly import RING, from_flint, lam, primitive, r, to_ring
from certify.errors import UsageError

LETTERS = "abc"
INDEX = {"a": 0, "b": 1, "c": 2}          # the component p_i that vanishes at the collision
NEXT = ((1, 2), (2, 0), (0, 1))      # the other two indices of a contact i: (i + 1, i + 2) mod 3


def collide(letter: str, q, rr=r) -> tuple:
    """K q for K = A, B, C (l. 209-232), h = (1 + r)/2, in any ring holding r and q
    (SymPy, rationals, balls, rational functions):
    a: (-r q1, q2 + h q1, q3);  b: (q1 + h q2, -r q2, q3 + h q2);  c: (q1, q2 + h q3, -r q3)."""
    q1, q2, q3 = q
    h = (1 + rr) / 2
    if letter == "a":
        return (-rr * q1, q2 + h * q1, q3)
    if letter == "b":
        return (q1 + h * q2, -rr * q2, q3 + h * q2)
    if letter == "c":
        return (q1, q2 + h * q3, -rr * q3)
    raise ValueError(f"unknown collision {letter!r}")


def collide_integral(letter: str, q, rr) -> tuple:
    """2d·K q for a rational r = m/d (d > 0): the positive multiple of :func:`collide` whose
    matrix has the integer entries −2m (for −r), 2d (for 1) and m + d (for h); integer q
    stay integer."""
    m, d = rr.p, rr.q
    q1, q2, q3 = q
    if letter == "a":
        return (-2 * m * q1, 2 * d * q2 + (m + d) * q1, 2 * d * q3)
    if letter == "b":
        return (2 * d * q1 + (m + d) * q2, -2 * m * q2, 2 * d * q3 + (m + d) * q2)
    if letter == "c":
        return (2 * d * q1, 2 * d * q2 + (m + d) * q3, -2 * m * q3)
    raise ValueError(f"unknown collision {letter!r}")


def collide_particles(letter: str, v, rr=r) -> tuple:
    """The collision law (l. 158-163) on the velocities v = (v1, v2, v3, v4) of the
    particles, equal masses: the pair i, i+1 of ``letter`` (a: 1-2, b: 2-3, c: 3-4)
    keeps its momentum v_i + v_{i+1}, its relative velocity v_{i+1} - v_i becomes
    -r (v_{i+1} - v_i), the other particles keep their velocities.  With h = (1 + r)/2:
    v_i' = v_i + h (v_{i+1} - v_i),  v_{i+1}' = v_{i+1} - h (v_{i+1} - v_i).

    In any ring holding r and v.  It is written independently of :func:`collide` (the
    printed A, B, C), not derived from it: that the differences of this law are A, B, C
    (l. 208-232) is a check (tests/dynamics/test_particles.py), and the two simulators built on
    them (certify.dynamics.particles, certify.dynamics.simulate) cross-check each other."""
    if letter not in INDEX:
        raise ValueError(f"unknown collision {letter!r}")
    i = INDEX[letter]
    d = (1 + rr) / 2 * (v[i + 1] - v[i])
    w = list(v)
    w[i], w[i + 1] = v[i] + d, v[i + 1] - d
    return tuple(w)


def collision_matrix(letter: str, rr=r) -> sp.Matrix:
    """A, B or C of the paper (l. 209-232): the matrix of :func:`collide`."""
    columns = [collide(letter, e, rr) for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    return sp.Matrix(3, 3, lambda i, j: sp.sympify(columns[j][i]))


A, B, C = (collision_matrix(k) for k in LETTERS)


def check_word(word: str) -> str:
    """A collision word over a, b, c, with no letter repeated consecutively
    (cyclically, as the word is a period); raise UsageError otherwise."""
    if not isinstance(word, str) or not re.fullmatch(r"[abc]+", word or ""):
        raise UsageError(f"invalid pattern word {word!r}: use the letters a, b, c")
    if len(word) < 2 or any(x == y for x, y in zip(word, word[1:] + word[0])):
        raise UsageError(f"invalid pattern word {word!r}: the same pair cannot collide twice in a row")
    return word


def word_matrix(word: str, rr=r) -> sp.Matrix:
    """M_w = K_{c_n} ... K_{c_1}: the velocities after one period are M_w q(0), its
    entries factored.  With rr the symbol r the product is formed on python-flint
    polynomials in r (:func:`collide` works in any ring), not on SymPy expressions
    expanded after every letter.

    >>> M = word_matrix("ab")                  # B A: the velocities after a, then b
    >>> M[0, :]
    Matrix([[(r - 1)**2/4, (r + 1)/2, 0]])
    >>> word_matrix("ababcb").det()            # det M = r^6 (l. 340): each letter has det -r
    r**6

    Exact: polynomials over Q in r, no numerical value of r is involved."""
    if rr is r:
        M = word_matrix_flint(word)
        return sp.Matrix(3, 3, lambda i, j: factor_flint(M[i][j]))
    M = sp.eye(3)
    for letter in word:
        M = (collision_matrix(letter, rr) * M).applyfunc(sp.expand)
    return M.applyfunc(sp.factor)


def word_matrix_flint(word: str, law=collide, gaps: int = 3) -> list[list[flint.fmpq_poly]]:
    """M_w = K_{c_n} ... K_{c_1} as rows of python-flint polynomials in r, for the collision
    ``law`` on ``gaps`` gaps (the four particles by default; the systems of two gaps pass theirs)."""
    R = flint.fmpq_poly([0, 1])
    M = [[flint.fmpq_poly([int(i == j)]) for j in range(gaps)] for i in range(gaps)]
    for letter in word:
        columns = [law(letter, tuple(M[i][j] for i in range(gaps)), R) for j in range(gaps)]
        M = [[columns[j][i] for j in range(gaps)] for i in range(gaps)]
    return M


def factor_flint(p) -> sp.Expr:
    """sp.factor(from_flint(p, r)) (the same expression: the rational coefficient kept in
    front of the product of the primitive irreducible factors with positive leading
    coefficient), by python-flint's factorisation of a polynomial in r."""
    p = flint.fmpq_poly(p)
    if p.degree() <= 0:
        return sp.factor(from_flint(p, r))
    _, factors = p.numer().factor()
    coeff = flint.fmpq(p.coeffs()[-1])
    prod = []
    for f, m in factors:
        f = primitive(f)
        coeff /= f.coeffs()[-1] ** m
        prod.append(from_flint(f, r) ** int(m))
    return _keep_coeff(sp.Rational(int(coeff.p), int(coeff.q)), sp.Mul(*prod))


_LR = flint.fmpz_mpoly_ctx.get(("r", "lam"), "lex")     # SymPy's order of the gens r, λ


def factor_lr(e) -> sp.Expr:
    """sp.factor(e) for a polynomial e in r, λ over Q (the same expression: the rational
    coefficient in front of the primitive irreducible factors, each with a positive
    leading coefficient in SymPy's lex order of (r, λ)), by python-flint's multivariate
    factorisation (an order of magnitude faster on the datum of (ab)^6(cb)^6)."""
    P = sp.Poly(e, r, lam)
    if P.total_degree() <= 0:
        return sp.factor(e)
    den = 1
    for c in P.coeffs():
        den = sp.ilcm(den, sp.Rational(c).q)
    F = _LR.from_dict({m: int(c * den) for m, c in P.terms()})
    content, factors = F.factor()
    coeff = sp.Rational(int(content), den)
    prod = []
    for f, m in factors:
        if f.leading_coefficient() < 0:
            f, coeff = -f, coeff * (-1) ** int(m)
        prod.append(sp.Add(*[sp.Integer(int(k)) * r ** i * lam ** j for (i, j), k in f.to_dict().items()]) ** int(m))
    return _keep_coeff(coeff, sp.Mul(*prod))


def charpoly_flint(M) -> sp.Expr:
    """det(λI - M) for a 2x2 or 3x3 matrix of python-flint polynomials in r, as the
    expanded SymPy expression (equal to ``sp.expand(Matrix.charpoly(λ).as_expr())``)."""
    coeffs = charpoly_coefficients(M)
    n = len(coeffs) - 1
    terms = []
    for k, c in enumerate(coeffs):
        for j, cj in enumerate(flint.fmpq_poly(c).coeffs()):
            if cj:
                terms.append(sp.Rational(int(cj.p), int(cj.q)) * r**j * lam**(n - k))
    return sp.Add(*terms)


def charpoly_ring(M):
    """det(λI - M) as an element of the engine's ring Q[λ, r, ...] (the same polynomial as
    :func:`charpoly_flint`, built from python-flint without a SymPy expression)."""
    coeffs = charpoly_coefficients(M)
    n, zeros = len(coeffs) - 1, (0,) * (len(RING.gens) - 2)
    terms = {(n - k, j) + zeros: RING.domain(cj) for k, c in enumerate(coeffs)
             for j, cj in enumerate(flint.fmpq_poly(c).coeffs()) if cj}
    return RING.from_dict(terms)


def det3(rows):
    """The determinant of a 3×3 matrix given by its rows, by cofactors along the first row
    (entries in any ring: integers, python-flint or SymPy polynomials)."""
    (a, b, c), (d, e, f), (g, h, i) = rows
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)


def charpoly_coefficients(M) -> list:
    """The coefficients of det(λI - M), highest power of λ first, as python-flint
    polynomials in r (M a 2x2 or 3x3 matrix of them)."""
    n = len(M)
    one = flint.fmpq_poly([1])
    if n == 2:
        coeffs = [one, -(M[0][0] + M[1][1]), M[0][0] * M[1][1] - M[0][1] * M[1][0]]
    elif n == 3:
        (a, b, c), (d, e, f), (g, h, i) = M
        det = det3(M)
        minors = (a * e - b * d) + (a * i - c * g) + (e * i - f * h)
        coeffs = [one, -(a + e + i), minors, -det]
    else:
        raise ValueError("a 2x2 or 3x3 matrix")
    return coeffs


def characteristic_polynomial(M: sp.Matrix) -> sp.Expr:
    """cp(M) = det(λI - M), expanded in λ and r: for a 3×3 matrix of polynomials in the
    paper's variables, the determinant by cofactors in the sparse ring Q[λ, r, ...] (its
    terms are the expanded expression); SymPy's charpoly otherwise."""
    if M.shape == (3, 3):
        try:
            L = [[to_ring(lam if i == j else 0) - to_ring(M[i, j]) for j in range(3)] for i in range(3)]
        except ValueError:
            L = None
        if L is not None:
            return det3(L).as_expr()
    return sp.expand(M.charpoly(lam).as_expr())
