"""The periodic orbits of the five-particle reduction in floats (numpy): an independent route for
tests/patterns/test_five_orbits.py (observed, not certified).  M_w is evaluated exactly at a rational
r and then rounded; Λ²M_w, its eigenvectors and M_w's eigenvalues are numpy's; the face and the
tournament are read off the bivector as docs/particles.md states them."""
import itertools

import flint
import numpy as np

from certify.dynamics.systems import of_particles, system_matrix_flint

PAIRS = list(itertools.combinations(range(4), 2))
LETTERS = "abcd"


def matrix(word: str, r: flint.fmpq) -> np.ndarray:
    """M_w at the rational r, exactly, then as floats."""
    return np.array([[float(e(r)) for e in row] for row in system_matrix_flint(of_particles(5), word)])


def compound(M: np.ndarray) -> np.ndarray:
    """Λ²M in the coordinates ω_kl, k < l."""
    return np.array([[M[i, k] * M[j, m] - M[i, m] * M[j, k] for k, m in PAIRS] for i, j in PAIRS])


def entry(w, k: int, m: int) -> float:
    """ω_km for any k ≠ m."""
    return w[PAIRS.index((k, m))] if k < m else -w[PAIRS.index((m, k))]


def _attracting(ev: np.ndarray, kappa: float) -> str | None:
    """'real' or 'complex' (the in-plane pair) when the two eigenvalues of M with product κ have larger
    moduli than both others, else None."""
    pair = min(itertools.combinations(range(4), 2), key=lambda ab: abs(ev[ab[0]] * ev[ab[1]] - kappa))
    others = [ev[m] for m in range(4) if m not in pair]
    least = min(abs(ev[pair[0]]), abs(ev[pair[1]]))
    if not all(abs(n) < least * (1 - 1e-9) for n in others):
        return None
    return "complex" if abs(ev[pair[0]].imag) > 1e-12 * abs(ev[pair[0]]) else "real"


def resolved(word: str, r: flint.fmpq, floor: float = 1e-12) -> bool:
    """Whether floats resolve the spectrum of Λ²M_w at r: every eigenvalue at least ``floor`` times the
    largest in modulus.  Below, an eigenvalue is rounding noise (its sign, its being real), and which
    noise depends on numpy's version: numpy 2.4.6 found a "real κ > 0" of 7e-18 beside 3e-3 for the
    19-letter word at r = 1/20, where the exact route finds no orbit."""
    v = np.abs(np.linalg.eigvals(compound(matrix(word, r))))
    return bool(v.min() >= floor * v.max())


def orbits(word: str, r: flint.fmpq, tol: float = 1e-9) -> list[tuple[float, bool, str | None]]:
    """(κ, feasible, kind) for each simple real κ > 0 of Λ²M whose eigenvector, oriented, lies in the
    face of the last letter: feasible when the plane's run follows the word; kind 'real' or 'complex'
    when the feasible orbit attracts, else None."""
    return orbits_of(word, matrix(word, r), [compound(matrix(c, r)) for c in LETTERS], tol)


def orbits_of(word: str, M: np.ndarray, steps: list, tol: float = 1e-9) -> list[tuple[float, bool, str | None]]:
    """:func:`orbits` from M = M_word and the letters' Λ²M_c (``steps``, in the order a, b, c, d), as floats."""
    values, vectors = np.linalg.eig(compound(M))
    ev = np.linalg.eigvals(M)
    Y = LETTERS.index(word[-1])
    out = []
    for k, kappa in enumerate(values):
        if abs(kappa.imag) > tol * max(1, abs(kappa)) or kappa.real <= 0:
            continue
        if sum(abs(values - kappa) < 1e-7 * abs(kappa)) > 1:
            continue                                          # a multiple root: not analysed
        w = np.real(vectors[:, k])
        w = w / np.max(np.abs(w))
        face = [-entry(w, Y, j) for j in range(4) if j != Y]
        if not (all(f > tol for f in face) or all(f < -tol for f in face)):
            continue
        if face[0] < 0:
            w = -w
        i, feasible = Y, True
        for c in word:
            j = LETTERS.index(c)
            if not all(entry(w, j, m) > tol * np.max(np.abs(w)) for m in range(4) if m not in (i, j)):
                feasible = False
                break
            w, i = steps[j] @ w, j
        out.append((kappa.real, feasible, _attracting(ev, kappa.real) if feasible else None))
    return out
