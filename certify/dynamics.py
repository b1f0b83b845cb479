"""The dynamics of a prescribed collision word, in exact arithmetic.

For a word w ending in letter e, a self-similar datum has p(0) with p_e(0) = 0 and
q(0) an eigenvector of M_w.  We follow the paper's normalisation for ababcb:
q(0) = (-1, u, v) (the first collision is a) and p(0) = (1, 0, x).  The collision
times are *defined* as if the word were realised (t_k = t_{k-1} - p_i/q_i for the
letter's component i), and p(t_k), q(t_k) are rational functions of r, λ and x;
identities are checked modulo cp(λ; r).
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from .model import INDEX, check_word, collision_matrix
from .poly import lam, r, u, v, x


@dataclass
class Step:
    """The state right after the k-th collision of the word."""

    letter: str
    t: sp.Expr          # the time since the previous collision
    p: sp.Matrix
    q: sp.Matrix


def eigenvector(M: sp.Matrix, first: int, rows=(0, 1)) -> sp.Matrix:
    """q with q_first = -1 solving the given two rows of M q = λ q, over Q(r, λ)."""
    unknowns = [k for k in range(3) if k != first]
    q = sp.zeros(3, 1)
    q[first] = -1
    sym = {k: sp.Symbol(f"q{k}") for k in unknowns}
    for k in unknowns:
        q[k] = sym[k]
    eqs = [(M * q - lam * q)[i] for i in rows]
    sol = sp.solve(eqs, list(sym.values()), dict=True)[0]
    return q.subs(sol).applyfunc(sp.factor)


def run_word(word: str, p0: sp.Matrix, q0: sp.Matrix) -> list[Step]:
    """Apply the word's collisions in order, times defined by p_i(t_k) = 0."""
    check_word(word)
    p, q = sp.Matrix(p0), sp.Matrix(q0)
    steps = []
    for letter in word:
        i = INDEX[letter]
        t = sp.cancel(-p[i] / q[i])
        p = (p + t * q).applyfunc(sp.cancel)
        p[i] = 0
        q = (collision_matrix(letter) * q).applyfunc(sp.cancel)
        steps.append(Step(letter, t, p, q))
    return steps


def velocities(word: str, q0: sp.Matrix) -> list[sp.Matrix]:
    """q(t_0), q(t_1), ..., q(t_n) for symbolic q(0) (no positions needed)."""
    out = [sp.Matrix(q0)]
    for letter in check_word(word):
        out.append((collision_matrix(letter) * out[-1]).applyfunc(sp.expand))
    return out


def reduce_mod(e, cp) -> sp.Expr:
    """The numerator of a rational function of λ reduced modulo cp(λ; r), factored:
    zero exactly when e vanishes on every root λ of cp where its denominator does not."""
    num, _den = sp.fraction(sp.cancel(sp.together(e)))
    return sp.factor(sp.Poly(num, lam).rem(sp.Poly(cp, lam)).as_expr())


def position_map(steps: list[Step]) -> tuple[sp.Expr, sp.Expr, sp.Expr, sp.Expr]:
    """(a, b, c, d) with f(x) = p_3(t_n)/p_1(t_n) = (a x + b)/(c x + d)."""
    f = sp.cancel(steps[-1].p[2] / steps[-1].p[0])
    num, den = sp.fraction(f)
    N, D = sp.Poly(num, x), sp.Poly(den, x)
    if N.degree() > 1 or D.degree() > 1:
        raise ArithmeticError("f is not a Möbius map in x")
    return (N.coeff_monomial(x), N.coeff_monomial(1), D.coeff_monomial(x), D.coeff_monomial(1))
