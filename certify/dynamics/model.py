"""The model of Section 2: the collision law, collision matrices, words and their matrices.

The law (l. 158-163) acts on the velocities v = (v1, v2, v3, v4) of the particles:
:func:`collide_particles`.  In relative coordinates p_i = x_{i+1} - x_i,
q_i = v_{i+1} - v_i (i = 1, 2, 3), a collision of type a, b, c (pairs 1-2, 2-3, 3-4)
maps q to A q, B q, C q (:func:`collide`, the printed matrices).  A word
w = c_1 c_2 ... c_n (collisions in time order) has the matrix
M_w = K_{c_n} ... K_{c_1}; for ababcb, M = BCBABA.

N particles (beyond the paper, issue 39): the pair i, i+1 is the i-th letter of
a, b, c, d, ... (:func:`alphabet`); on the N - 1 gaps its collision matrix is
K_i = I + w_i e_iᵀ, w_i = h e_{i-1} - (1 + r) e_i + h e_{i+1} (:func:`collide_gaps`), the
law of :func:`collide_particles` read on the differences, and A, B, C for N = 4.
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
LETTERS_N = "abcdefghijklmnopqrstuvwxyz"   # the pairs 1-2, 2-3, ... of N <= 27 particles


def alphabet(particles: int) -> str:
    """The letters of the N - 1 pairs of N particles: a (1-2), b (2-3), ...; "abc" for four."""
    if isinstance(particles, bool) or not isinstance(particles, int) or not 3 <= particles <= len(LETTERS_N) + 1:
        raise UsageError(f"the number of particles must be an integer from 3 to {len(LETTERS_N) + 1}, "
                         f"got {particles!r}")
    return LETTERS_N[:particles - 1]


def particles_of(word: str) -> int:
    """N given by the alphabet of a word: one more than the pairs its last letter needs, at
    least four (a word over a, b, c is one of the paper's four particles; d gives five)."""
    return max(4, max(LETTERS_N.index(L) for L in word) + 2)


def collide_gaps(letter: str, q, rr=r) -> tuple:
    """K_i q for the pair i of ``letter`` among N = len(q) + 1 particles (q the relative
    velocities of the N - 1 gaps), in any ring holding r and q: K_i = I + w_i e_iᵀ with
    w_i = h e_{i-1} - (1 + r) e_i + h e_{i+1}, h = (1 + r)/2 (the entries of w_i outside
    the gaps dropped): q_i -> -r q_i, q_{i±1} -> q_{i±1} + h q_i, the others kept.
    For four particles it is :func:`collide` (A, B, C); tests/dynamics/test_n_particles.py
    checks it against the exact N-particle simulation, collision by collision."""
    i = LETTERS_N.find(letter) if len(letter) == 1 else -1
    if not 0 <= i < len(q):
        raise ValueError(f"unknown collision {letter!r} among {len(q) + 1} particles")
    h = (1 + rr) / 2
    out = list(q)
    out[i] = -rr * q[i]
    if i > 0:
        out[i - 1] = q[i - 1] + h * q[i]
    if i + 1 < len(q):
        out[i + 1] = q[i + 1] + h * q[i]
    return tuple(out)


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
    particles (or of N = len(v) particles, the pairs of :func:`alphabet`),
    equal masses: the pair i, i+1 of ``letter`` (a: 1-2, b: 2-3, c: 3-4, d: 4-5, ...)
    keeps its momentum v_i + v_{i+1}, its relative velocity v_{i+1} - v_i becomes
    -r (v_{i+1} - v_i), the other particles keep their velocities.  With h = (1 + r)/2:
    v_i' = v_i + h (v_{i+1} - v_i),  v_{i+1}' = v_{i+1} - h (v_{i+1} - v_i).

    In any ring holding r and v.  It is written independently of :func:`collide` (the
    printed A, B, C), not derived from it: that the differences of this law are A, B, C
    (l. 208-232) is a check (tests/dynamics/test_particles.py), and the two simulators built on
    them (certify.dynamics.particles, certify.dynamics.simulate) cross-check each other."""
    i = LETTERS_N.find(letter) if len(letter) == 1 else -1
    if not 0 <= i < len(v) - 1:
        raise ValueError(f"unknown collision {letter!r}")
    d = (1 + rr) / 2 * (v[i + 1] - v[i])
    w = list(v)
    w[i], w[i + 1] = v[i] + d, v[i + 1] - d
    return tuple(w)


def collision_matrix(letter: str, rr=r) -> sp.Matrix:
    """A, B or C of the paper (l. 209-232): the matrix of :func:`collide`."""
    columns = [collide(letter, e, rr) for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    return sp.Matrix(3, 3, lambda i, j: sp.sympify(columns[j][i]))


A, B, C = (collision_matrix(k) for k in LETTERS)


def check_word(word: str, particles: int = 4) -> str:
    """A collision word over a, b, c (the letters of :func:`alphabet` for ``particles``), with
    no letter repeated consecutively (cyclically, as the word is a period); raise
    UsageError otherwise."""
    letters = alphabet(particles)
    if not isinstance(word, str) or not re.fullmatch(f"[{letters}]+", word or ""):
        raise UsageError(f"invalid pattern word {word!r}: use the letters {', '.join(letters)}"
                         + ("" if particles == 4 else f" ({particles} particles)"))
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
    """det(λI - M) for a square matrix of python-flint polynomials in r, as the
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
    polynomials in r (M a square matrix of them; n x n for n >= 4 by
    :func:`faddeev_leverrier`)."""
    n = len(M)
    one = flint.fmpq_poly([1])
    if n == 2:
        coeffs = [one, -(M[0][0] + M[1][1]), M[0][0] * M[1][1] - M[0][1] * M[1][0]]
    elif n == 3:
        (a, b, c), (d, e, f), (g, h, i) = M
        det = det3(M)
        minors = (a * e - b * d) + (a * i - c * g) + (e * i - f * h)
        coeffs = [one, -(a + e + i), minors, -det]
    elif n >= 4 and all(len(row) == n for row in M):
        coeffs = faddeev_leverrier(M)
    else:
        raise ValueError("a square matrix of size at least 2")
    return coeffs


def faddeev_leverrier(M) -> list:
    """The coefficients 1, c_1, ..., c_n of det(λI - M) = λ^n + c_1 λ^(n-1) + ... + c_n for
    an n x n matrix of python-flint polynomials in r, exactly, by the Faddeev-LeVerrier
    recursion over Q[r]: N_1 = I, c_k = -tr(M N_k)/k, N_(k+1) = M N_k + c_k I."""
    n = len(M)
    one, zero = flint.fmpq_poly([1]), flint.fmpq_poly([])
    N = [[one if i == j else zero for j in range(n)] for i in range(n)]
    coeffs = [one]
    for k in range(1, n + 1):
        MN = [[sum((M[i][m] * N[m][j] for m in range(n)), zero) for j in range(n)] for i in range(n)]
        c = -sum((MN[i][i] for i in range(n)), zero) / k
        coeffs.append(c)
        N = [[MN[i][j] + c if i == j else MN[i][j] for j in range(n)] for i in range(n)]
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
