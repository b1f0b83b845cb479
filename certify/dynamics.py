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
from .poly import FIELD, Xf, lam, r, to_field, u, v, x


@dataclass
class Step:
    """The state right after the k-th collision of the word (elements of Q(λ, r, x))."""

    letter: str
    t: object           # the time since the previous collision
    p: list
    q: list


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


def run_word(word: str, p0, q0) -> list[Step]:
    """Apply the word's collisions in order, times defined by p_i(t_k) = 0, in
    exact rational-function arithmetic over Q(λ, r, x)."""
    check_word(word)
    p, q = [to_field(e) for e in p0], [to_field(e) for e in q0]
    K = {k: [[to_field(e) for e in row] for row in collision_matrix(k).tolist()] for k in "abc"}
    steps = []
    for letter in word:
        i = INDEX[letter]
        t = -p[i] / q[i]
        p = [p[k] + t * q[k] for k in range(3)]
        p[i] = FIELD.zero
        q = [sum((K[letter][a][b] * q[b] for b in range(3)), FIELD.zero) for a in range(3)]
        steps.append(Step(letter, t, p, q))
    return steps


def velocities(word: str, q0: sp.Matrix) -> list[sp.Matrix]:
    """q(t_0), q(t_1), ..., q(t_n) for symbolic q(0) (no positions needed)."""
    out = [sp.Matrix(q0)]
    for letter in check_word(word):
        out.append((collision_matrix(letter) * out[-1]).applyfunc(sp.expand))
    return out


def reduce_mod(e, cp):
    """The numerator of a rational function of λ reduced modulo cp(λ; r) (monic in λ):
    zero exactly when e vanishes on every root λ of cp where its denominator does not."""
    return to_field(e).numer.rem(to_field(cp).numer)


def position_map(steps: list[Step]):
    """(a, b, c, d) ∈ Q[λ, r] with f(x) = p_3(t_n)/p_1(t_n) = (a x + b)/(c x + d)."""
    f = steps[-1].p[2] / steps[-1].p[0]
    N, D = f.numer, f.denom
    X = Xf.numer
    if N.degree(X) > 1 or D.degree(X) > 1:
        raise ArithmeticError("f is not a Möbius map in x")
    return (N.coeff_wrt(X, 1), N.coeff_wrt(X, 0), D.coeff_wrt(X, 1), D.coeff_wrt(X, 0))
