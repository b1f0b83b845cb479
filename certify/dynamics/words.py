"""The dynamics of a prescribed collision word, in exact arithmetic.

For a word w = c_1 ... c_n starting with a and ending with b (the paper's
normalisation, l. 270-280): q(0) = (-1, u, v) is an eigenvector of
M_w = K_{c_n} ... K_{c_1} for an eigenvalue λ, found from two rows of the
eigen-equation over the field Q(λ, r) (``FIELD``); p(0) = (1, 0, x).  The collision times are
*defined* as if the word were realised (t_k = t_{k-1} - p_i/q_i for the letter's
component i, l. 460-463), so p(t_k) = P₀ + x P₁ stays affine in x and q(t_k) is in
K; the position map is f(x) = p_3(t_n)/p_1(t_n) = (ax + b)/(cx + d).  Everything is
exact; identities are checked modulo cp(λ; r), which keeps the values on every
eigenvalue branch.  The arithmetic runs on python-flint's fmpz_mpoly in (λ, r)
(:class:`certify.algebra.poly.Frac`, canonical like SymPy's fractions); the results
are handed out as the equal elements of SymPy's field ``FIELD``.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cache, cached_property

import flint
import sympy as sp

from certify import caches
from certify.algebra.balls import GUARD, precision
from certify.algebra.branches import Condition, Spectrum, ball_value
from certify.algebra.poly import (
    FIELD,
    LR_LAMBDA,
    LR_R,
    LRCTX,
    LRQCTX,
    RING,
    Frac,
    field_to_frac,
    flint_poly_to_frac,
    frac_to_field,
    lr_to_ring,
    ring_to_lrq,
    to_field,
    to_ring,
)

from .model import (
    INDEX,
    charpoly_flint,
    charpoly_ring,
    check_word,
    collide,
    collision_matrix,
    factor_flint,
    word_matrix_flint,
)


def eigenvector_lr(M, rows=(0, 1)) -> tuple:
    """:func:`eigenvector` on a matrix of :class:`Frac`, q as :class:`Frac`."""
    A = [[M[i][j] - LR_LAMBDA if i == j else M[i][j] for j in range(3)] for i in range(3)]
    (a11, a12), (a21, a22) = [(A[i][1], A[i][2]) for i in rows]
    b1, b2 = (A[i][0] for i in rows)
    det = a11 * a22 - a12 * a21
    return (Frac.of(-1), (b1 * a22 - a12 * b2) / det, (a11 * b2 - b1 * a21) / det)


def eigenvector(M, rows=(0, 1)) -> tuple:
    """q = (-1, u, v) solving two rows of (M - λI) q = 0 by Cramer's rule over K; the
    paper uses rows 1 and 2 (l. 366).  The three choices of rows agree on the
    branches wherever their determinants do not vanish."""
    Mf = [[field_to_frac(e) for e in row] for row in M]
    return tuple(frac_to_field(e) for e in eigenvector_lr(Mf, rows))


@dataclass
class Step:
    """The state right after a collision: p_i = P0_i + x P1_i, q_i ∈ K."""

    letter: str
    p: list                    # [(P0, P1)] * 3
    q: tuple

    def position(self, i: int):
        """p_i as an element of Q(λ, r, x)."""
        P0, P1 = self.p[i]
        return P0 + P1 * FIELD.gens[2]


def run_lr(word: str, q0: tuple, index=INDEX, law=collide, gaps: int = 3) -> list[tuple]:
    """The run of :func:`run_word` on :class:`Frac`: [(letter, p, q)] with p a list of
    pairs (P0, P1) and q a tuple, on 2 or 3 gaps (p(0) = (1, 0) or (1, 0, x)); q0 of
    :class:`Frac` or of ``FIELD``."""
    q = tuple(e if isinstance(e, Frac) else field_to_frac(e) for e in q0)
    zero, one = Frac.of(0), Frac.of(1)
    p = [(one, zero), (zero, zero)] + ([(zero, one)] if gaps == 3 else [])
    out = []
    for letter in word:
        i = index[letter]
        if q[i].is_zero():
            raise ZeroDivisionError(f"q_{i + 1} vanishes identically before {letter}")
        w = -q[i].inverse()
        t = (p[i][0] * w, p[i][1] * w)
        p = [(P0 + t[0] * qj, P1 + t[1] * qj) for (P0, P1), qj in zip(p, q)]
        p[i] = (zero, zero)
        q = law(letter, q, LR_R)
        out.append((letter, p, q))
    return out


def steps_of(run: list[tuple]) -> list[Step]:
    """The steps of :func:`run_lr` as :class:`Step` over K (equal elements, no gcd)."""
    conv = frac_to_field
    return [Step(letter, [(conv(P0), conv(P1)) for P0, P1 in p], tuple(conv(e) for e in q)) for letter, p, q in run]


def run_word(word: str, q0: tuple) -> list[Step]:
    """From p(0) = (1, 0, x), q(0) = q0, apply the collisions of ``word`` with times
    *defined* by p_i(t_k) = 0 (l. 460-463).  Nothing is reduced modulo cp here:
    that would spoil FIELD's cancellations; conditions are reduced at the end."""
    return steps_of(run_lr(word, q0))


def reduce_mod(e, cp):
    """The numerator of a rational function of λ reduced modulo cp(λ; r), monic in λ
    (λ leads the lex order): zero exactly when e vanishes on every root λ of cp where
    its denominator does not."""
    return to_field(e).numer.rem(to_ring(cp))


def _lrq_to_frac(p) -> Frac:
    """An fmpq_mpoly in (λ, r) as :class:`Frac`."""
    d = p.to_dict()
    den = flint.fmpz(1)
    for c in d.values():
        den = den.lcm(c.q)
    return Frac(LRCTX.from_dict({m: c.p * (den // c.q) for m, c in d.items()}), LRCTX.from_dict({(0, 0): den}))


def position_map_lr(last_p: list, C) -> tuple:
    """:func:`position_map` from the final p of :func:`run_lr` and cp as fmpq_mpoly:
    (a, b, c, d) as fmpq_mpoly, the same polynomials as SymPy's (monic lcm of the
    denominators, remainder modulo cp monic in λ)."""
    (d0, c0), (b0, a0) = last_p[0], last_p[2]
    L = None
    for e in (a0, b0, c0, d0):
        L = e.den if L is None else (L * e.den) / L.gcd(e.den)
    lc = flint.fmpq(L.leading_coefficient())
    out = []
    for e in (a0, b0, c0, d0):
        val = LRQCTX.from_dict({m: flint.fmpq(c) / lc for m, c in (e.num * (L / e.den)).to_dict().items()})
        out.append(divmod(val, C)[1])
    return tuple(out)


def position_map(steps: list[Step], cp) -> tuple:
    """(a, b, c, d), polynomials in r, λ reduced modulo cp, with p_3(t_n) ∝ ax + b and
    p_1(t_n) ∝ cx + d over a common denominator: f(x) = (ax + b)/(cx + d).  The common
    factor may be negative, which swaps x₊ and x₋ (both are always considered)."""
    last = [tuple(field_to_frac(e) for e in pair) for pair in steps[-1].p]
    return tuple(lr_to_ring(e).as_expr() for e in position_map_lr(last, ring_to_lrq(to_ring(cp))))


def check_position_map_lr(last_p: list, abcd: tuple, C) -> None:
    """:func:`check_position_map` on Frac/fmpq_mpoly data."""
    (d1, c1), (b1, a1) = last_p[0], last_p[2]
    a, b, c, d = (_lrq_to_frac(e) for e in abcd)
    for e in (a * c1 - c * a1, a * d1 + b * c1 - c * b1 - d * a1, b * d1 - d * b1):
        num = LRQCTX.from_dict({m: flint.fmpq(k) for m, k in e.num.to_dict().items()})
        if not divmod(num, C)[1].is_zero():
            raise ArithmeticError("the position map (a, b, c, d) does not reproduce p_3/p_1")


def check_position_map(steps, abcd, cp):
    """(ax + b)/(cx + d) = p_3(t_n)/p_1(t_n) identically in x, modulo cp:
    a c₁ = c a₁, a d₁ + b c₁ = c b₁ + d a₁, b d₁ = d b₁ with p_1 = d₁ + c₁x, p_3 = b₁ + a₁x."""
    (d1, c1), (b1, a1) = steps[-1].p[0], steps[-1].p[2]
    a, b, c, d = (to_field(e) for e in abcd)
    for e in (a * c1 - c * a1, a * d1 + b * c1 - c * b1 - d * a1, b * d1 - d * b1):
        if reduce_mod(e, cp) != 0:
            raise ArithmeticError("the position map (a, b, c, d) does not reproduce p_3/p_1")


def velocities(word: str, q0: sp.Matrix) -> list[sp.Matrix]:
    """q(t_0), q(t_1), ..., q(t_n) for a symbolic q(0) (no eigenvalue needed), expanded.
    A polynomial q(0) in the paper's variables is multiplied in the sparse ring (the same
    expanded expressions, without SymPy's expand)."""
    out = [sp.Matrix(q0)]
    try:
        q = [to_ring(e) for e in out[0]]
    except (ValueError, sp.PolynomialError, sp.polys.polyerrors.CoercionFailed):
        q = None
    for letter in check_word(word):
        if q is None:
            out.append((collision_matrix(letter) * out[-1]).applyfunc(sp.expand))
            continue
        K = [[to_ring(k) for k in collision_matrix(letter).row(i)] for i in range(3)]
        q = [sum((K[i][j] * q[j] for j in range(3)), RING.zero) for i in range(3)]
        out.append(sp.Matrix([p.as_expr() for p in q]))
    return out


@dataclass
class Candidate:
    """The self-similar candidate of a word a ... b: its matrix, cp, branches, q(0)
    (rows 1, 2 of the eigen-equation, and the two other choices for the points
    where those degenerate), the symbolic run and the position map."""

    word: str
    Mq: list                           # M_w as python-flint polynomials in r
    cp: sp.Expr
    spectrum: Spectrum
    q0: tuple
    q0_other: list
    abcd: tuple
    steps: list
    abcd_ring: tuple | None = None     # a, b, c, d as elements of the engine's ring (the same polynomials)

    @cached_property
    def M(self) -> sp.Matrix:
        """M_w with its entries factored, as SymPy expressions (for readers; = word_matrix)."""
        n = len(self.Mq)
        return sp.Matrix(n, n, lambda i, j: factor_flint(self.Mq[i][j]))

    def balls(self, r0, branch: int, sigma: int, prec: int):
        """(p(0), q(0), r) at a rational r0 on a real branch, x = x₊ (sigma = 1) or
        x₋ (sigma = -1), as python-flint balls of about ``prec`` bits."""
        lams = self.spectrum.real_eigenvalues(r0)
        with precision(prec + GUARD):
            R, L = flint.arb(flint.fmpq(r0)), lams[branch].arb(prec + GUARD)
            u, v = (ball_value(Condition.of(n, e.as_expr()), R, L) for n, e in (("u", self.q0[1]), ("v", self.q0[2])))
            a, b, c, d = (ball_value(Condition.of(n, e), R, L) for n, e in zip("abcd", self.abcd))
            x = fixed_point_ball(a, b, c, d, sigma)
            return (flint.arb(1), flint.arb(0), x), (flint.arb(-1), u, v), R


def fixed_point_ball(a, b, c, d, sigma: int = 1) -> flint.arb:
    """x = (a - d + σ√Δ)/(2c), Δ = (a-d)² + 4bc, from balls; ArithmeticError unless Δ > 0 is proven."""
    disc = (a - d) ** 2 + 4 * b * c
    if not disc > 0:
        raise ArithmeticError("(a-d)² + 4bc not proven positive")
    return (a - d + sigma * disc.sqrt()) / (2 * c)


@cache
def spectrum_of(word: str) -> tuple:
    """(M_w, cp, cp in the engine's ring, the Spectrum) of a word a ... b: what
    :func:`candidate` starts from, and all that ``certify orbit`` needs (without the run
    of q(0), which takes most of a long word's candidate); one Spectrum per word, so both
    share its sign tables."""
    check_word(word)
    if word[0] != "a" or word[-1] != "b":
        raise ValueError(f"the normalisation q(0) = (-1, u, v), p(0) = (1, 0, x) needs a word a...b, not {word!r}")
    Mq = word_matrix_flint(word)
    cp = charpoly_flint(Mq)                                           # = characteristic_polynomial(M)
    ring_cp = charpoly_ring(Mq)                                       # the same, in the engine's ring
    return Mq, cp, ring_cp, Spectrum(cp, ring_cp)


@cache
def candidate(word: str) -> Candidate:
    """M_w, cp, the branches, q(0) and the position map of a word a ... b."""
    Mq, cp, ring_cp, spectrum = spectrum_of(word)
    Mf = [[flint_poly_to_frac(e) for e in row] for row in Mq]
    q0 = eigenvector_lr(Mf)
    run = run_lr(word, q0)
    last = run[-1][1]
    if not (last[1][0].is_zero() and last[1][1].is_zero()):
        raise ArithmeticError("p_2 does not vanish after the last b")
    C = ring_to_lrq(ring_cp)
    abcd_lr = position_map_lr(last, C)
    check_position_map_lr(last, abcd_lr, C)
    abcd_ring = tuple(lr_to_ring(e) for e in abcd_lr)
    abcd = tuple(e.as_expr() for e in abcd_ring)
    q0_other = [tuple(frac_to_field(e) for e in eigenvector_lr(Mf, rows)) for rows in ((0, 2), (1, 2))]
    q0 = tuple(frac_to_field(e) for e in q0)
    return Candidate(word, Mq, cp, spectrum, q0, q0_other, abcd, steps_of(run), abcd_ring)



caches.register(candidate.cache_clear, of_a_word=True)
caches.register(spectrum_of.cache_clear, of_a_word=True)
