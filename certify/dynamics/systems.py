"""The systems of collision words, with one law each, and their candidates.

* ``four``: four particles, gaps p_1, p_2, p_3; letters a, b, c (:func:`.model.collide`).
* ``three``: three particles, gaps p_1, p_2; a on gap 1, b on gap 2, the same law
  (h = (1 + r)/2): a: (q_1, q_2) -> (-r q_1, q_2 + h q_1); b: (q_1 + h q_2, -r q_2).
  A word over c and b is its mirror image (renamed to a and b by the caller).
* ``symmetric``: four particles with p_1 = p_3 and q_1 = q_3 (the symmetric system of
  the paper's l. 132), reduced to the gaps (p_1, p_2).  The simultaneous collision
  [ac] (letter ``s``) applies A and C at once (AC = CA): q_1 -> -r q_1, q_3 -> -r q_3,
  q_2 -> q_2 + h q_1 + h q_3 = q_2 + 2h q_1; b keeps the symmetry:
  (q_1, q_2) -> (q_1 + h q_2, -r q_2).

* N particles (beyond the paper, issue 39; :func:`of_particles`): gaps p_1, ..., p_{N-1},
  letters a, b, c, d, ... (:func:`.model.alphabet`), the law K_i = I + w_i e_iᵀ of
  :func:`.model.collide_gaps`; N = 4 is ``four`` and N = 3 is ``three``.

For a two-gap system the candidate of a word (first-gap letter ... b) is q(0) = (-1, u),
an eigenvector of the 2x2 M_w for an eigenvalue λ, and p(0) = (1, 0): after the last b
the state is fixed up to scale by p_2 = 0, so there is no position variable x and no
position map (``abcd`` is None).  For four particles the candidate is
:func:`.words.candidate` (q(0) = (-1, u, v), p(0) = (1, 0, x), x a fixed point of f).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import flint
import sympy as sp

from certify import caches
from certify.algebra.branches import Spectrum
from certify.algebra.poly import LR_LAMBDA, Frac, flint_poly_to_frac, frac_to_field, r

from .model import (
    INDEX,
    alphabet,
    charpoly_flint,
    charpoly_ring,
    collide,
    collide_gaps,
    factor_flint,
    word_matrix_flint,
)
from .words import Candidate, Step, candidate, run_lr, steps_of


@dataclass(frozen=True)
class System:
    """A collision law on ``gaps`` gaps: the gap that closes at each letter and the
    map of the relative velocities."""

    name: str
    gaps: int
    index: dict               # letter -> the gap (0-based) that closes

    def collide(self, letter: str, q, rr=r) -> tuple:
        """The velocities after a collision ``letter`` (any ring holding r and q)."""
        if self.name == "four":
            return collide(letter, q, rr)
        if self.gaps > 2:
            if letter not in self.index:
                raise ValueError(f"unknown collision {letter!r} in the {self.name} system")
            return collide_gaps(letter, q, rr)
        h = (1 + rr) / 2
        q1, q2 = q
        if letter in ("a", "s"):
            k = h if letter == "a" else 2 * h
            return (-rr * q1, q2 + k * q1)
        if letter == "b":
            return (q1 + h * q2, -rr * q2)
        raise ValueError(f"unknown collision {letter!r} in the {self.name} system")


FOUR = System("four", 3, dict(INDEX))
THREE = System("three", 2, {"a": 0, "b": 1})
SYMMETRIC = System("symmetric", 2, {"s": 0, "b": 1})
BY_NAME = {S.name: S for S in (FOUR, THREE, SYMMETRIC)}


def of_particles(particles: int) -> System:
    """The system of N particles on a line: ``three`` (N = 3), ``four`` (N = 4, the paper's),
    and for N >= 5 the N - 1 gaps with the letters of :func:`.model.alphabet` and the law
    K_i = I + w_i e_iᵀ; UsageError for an N the alphabet does not cover."""
    letters = alphabet(particles)
    if particles == 3:
        return THREE
    if particles == 4:
        return FOUR
    return System(f"{particles} particles", particles - 1, {L: i for i, L in enumerate(letters)})


def system_matrix_flint(system: System, word: str) -> list[list[flint.fmpq_poly]]:
    """M_w = K_{c_n} ... K_{c_1} of the system as rows of python-flint polynomials in r."""
    return word_matrix_flint(word, system.collide, system.gaps)


def system_matrix(system: System, word: str) -> sp.Matrix:
    """M_w = K_{c_n} ... K_{c_1} of the system, entries factored (python-flint in r)."""
    M = system_matrix_flint(system, word)
    return sp.Matrix(system.gaps, system.gaps, lambda i, j: factor_flint(M[i][j]))


def run_in(system: System, word: str, q0: tuple) -> list[Step]:
    """The collisions of ``word`` from p(0) = (1, 0[, x]), q(0) = q0, times defined by
    p_i(t_k) = 0 (as :func:`.words.run_word`, in any system)."""
    return steps_of(run_lr(word, q0, system.index, system.collide, system.gaps))


def eigenvector2(M) -> list[tuple]:
    """q = (-1, u) from row 1 of (M - λI) q = 0, and from row 2 (the other choice,
    for points where the first degenerates); entries :class:`Frac` (then so is q) or of ``FIELD``."""
    if not isinstance(M[0][0], Frac):
        from certify.algebra.poly import field_to_frac
        out = eigenvector2([[field_to_frac(e) for e in row] for row in M])
        return [tuple(frac_to_field(e) if e is not None else None for e in q) for q in out]
    (m11, m12), (m21, m22) = M
    return [(Frac.of(-1), (m11 - LR_LAMBDA) / m12 if not m12.is_zero() else None),
            (Frac.of(-1), m21 / (m22 - LR_LAMBDA))]


@cache
def candidate_in(system_name: str, word: str) -> Candidate:
    """The candidate of a word first-gap-letter ... b in the system ``system_name``."""
    system = BY_NAME[system_name]
    if system is FOUR:
        return candidate(word)
    if set(word) - set(system.index):
        raise ValueError(f"{word!r} is not a word of the {system.name} system")
    if word[-1] != "b" or system.index[word[0]] != 0:
        raise ValueError(f"the normalisation q(0) = (-1, u), p(0) = (1, 0) needs a word starting on gap 1 "
                         f"and ending with b, not {word!r}")
    Mq = system_matrix_flint(system, word)
    cp = charpoly_flint(Mq)                                   # = sp.expand(M.charpoly(λ).as_expr())
    Mf = [[flint_poly_to_frac(e) for e in row] for row in Mq]
    first, second = eigenvector2(Mf)
    q0 = first if first[1] is not None else second
    run = run_lr(word, q0, system.index, system.collide, system.gaps)
    last = run[-1][1]
    if not (last[1][0].is_zero() and last[1][1].is_zero()):
        raise ArithmeticError("p_2 does not vanish after the last b")
    others = [tuple(frac_to_field(e) for e in second)] if first[1] is not None else []
    return Candidate(word, Mq, cp, Spectrum(cp, charpoly_ring(Mq)), tuple(frac_to_field(e) for e in q0), others, None,
                     steps_of(run))


caches.register(candidate_in.cache_clear, of_a_word=True)
