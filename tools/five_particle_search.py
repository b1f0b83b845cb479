"""Observed, not certified: five-particle words with stable self-similar collapse (issue 39).

    python tools/five_particle_search.py --max-length 10 --r 0.2505 0.2675 8      # words, r grid
    python tools/five_particle_search.py --word abadcbcabc --r 0.2 0.3 1001 --ends
    python tools/five_particle_search.py --word abacbacbdcbcdcdbcdbcabcb --half --r 0.21 0.214 401
    python tools/five_particle_search.py --word W --half --digits 50 --r LO HI POINTS      # long words

The self-similar datum of a word w of N particles (N - 1 gaps), as for four particles
(certify pattern), from two eigenvalues of M_w.  The run from (p, q) gives after the period
p(t_n) = M_w (p + T q), q(t_n) = M_w q (free flight p + τq, and each K_i fixes its collision face
pointwise), T the period's duration.  With q = q(0) an eigenvector for λ and p(t_n) = μ p(0),
p(0) = αq + Σ β_k e_k in the eigenvectors e_k of M_w gives μα = λ(α + T), μβ_k = λ_k β_k: p(0)
lies in the plane of q and one eigenvector e_μ (μ > 0 another eigenvalue), and on the face of
the last letter Y: p(0) ∝ (e_μ)_Y q - q_Y e_μ.  The datum is *feasible* when the run from it
follows w (every collision the true next one), and *stable* when λ > μ > |ν| for the two other
eigenvalues ν (λ dominant: the velocities; μ above the rest: the plane Span(p, q), a fixed point of
the reduction on Gr(2, N - 1), attracts).  For N = 4 the two other eigenvalues are the fixed points
x₊, x₋ of the position map, and this reproduces certify pattern's exact stable and feasible sets
(ababcb, abcb, abcbcb, ababcbcb on a grid of step 0.001).

Floats (numpy) on a grid of r, bisection for the ends: what it prints is observed.  ``--ends``
then names, for each observed end, the exact polynomial in r (a factor of disc_λ cp, of the
resultant whose roots are the r where the modulus of a real eigenvalue equals that of another,
Res_y(cp_{M²}(y), cp_{Λ²M}(y)), or of Res_λ(cp, cp of M without the first letter's gap: a
component of q(0) vanishes)) with a root there, isolated exactly (python-flint's certified roots).
``--half``, for a symmetric word W = X·m(X) (up to rotation; m the mirror, a <-> d, b <-> c for five
particles), computes the same datum from the half map N = J·M_X, J the reversal of the gaps (see
half_map).  Near r ≈ 0.175 the second eigenvalue μ of M_W is below the rounding of λ past about 60
letters; N's eigenvalues are the square roots, so floats resolve words to about 140 letters.
What this prints is observed; ``certify pattern WORD`` certifies a five-particle word's sets exactly
(certify/patterns/five.py).
"""
from __future__ import annotations

import argparse
import functools
import itertools
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from certify.dynamics.model import alphabet, collide_gaps  # noqa: E402
from certify.patterns.five import half_of, normal_form, word_classes  # noqa: E402


def canonical(word: str, letters: str) -> str:
    """The least rotation of the word or of its mirror image (a <-> the last letter, ...): the engine's
    normal form (certify.patterns.five.normal_form), not a copy."""
    return normal_form(word, len(letters) + 1)[0]


def words(max_length: int, particles: int):
    """One word per class (rotations, mirror) of primitive periods of N - 1..max_length letters over
    the pairs of N particles, every pair used, no pair twice in a row (cyclically): the engine's
    (certify.patterns.five.word_classes)."""
    yield from word_classes(max_length, particles)


def period_matrix(word: str, gaps: int, r: float) -> np.ndarray:
    """M_w at a float r, by the engine's law (collide_gaps in floats)."""
    M = np.eye(gaps)
    for letter in word:
        M = np.array([collide_gaps(letter, tuple(M[:, j]), r) for j in range(gaps)]).T
    return M


def symmetric(word: str, particles: int) -> str | None:
    """The word when it is X·m(X), m the mirror (a <-> the last letter, ...), else None
    (certify.patterns.five.half_of: every rotation of X·m(X) is of that form, so none other is tried)."""
    return word if half_of(word, particles) is not None else None


def half_map(word: str, gaps: int, r: float) -> np.ndarray:
    """N = J·M_X for the word X·m(X), J the reversal of the gaps.  The mirror reverses the gaps, so
    the matrix of m(X) is J·M_X·J and M_W = M_m(X)·M_X = (J·M_X)² = N² (J² = 1)."""
    return period_matrix(word[:len(word) // 2], gaps, r)[::-1]


def follows(word: str, p: np.ndarray, q: np.ndarray, r: float, letters: str) -> bool:
    """Does the float run from (p, q) follow the word (each collision the strict next one)?"""
    for letter in word:
        times = sorted((-p[j] / q[j], j) for j in range(len(q)) if q[j] < 0)
        if not times or letters[times[0][1]] != letter:
            return False
        if len(times) > 1 and times[1][0] <= times[0][0] * (1 + 1e-9):
            return False
        t, i = times[0]
        p = p + t * q
        if np.any(p < -1e-12 * np.abs(p).max()):
            return False
        p[i] = 0
        q = np.array(collide_gaps(letter, tuple(q), r))
    return True


def data(word: str, r: float, particles: int, half: bool = False) -> list[tuple[float, float, bool]]:
    """(λ, μ, stable) for every feasible self-similar datum of the word at r.

    half: the word is X·m(X) and the eigenpairs are N's (half_map), the eigenvalues of M_W their
    squares n².  The pairs used are those of N's real nonzero eigenvalues n (then n² > 0 is an
    eigenvalue of M_W), and stable means n_λ² > n_μ² > |n|² for N's two other eigenvalues.  This is
    exactly the stable condition λ > μ > |ν| of M_W: the eigenvalues of N² are the n², with
    multiplicity; n² is real only for n real or purely imaginary, and positive (as the datum's λ, μ
    must be) only for n real and nonzero; the strict inequalities make λ and μ simple
    eigenvalues of M_W, whose eigenvectors are then N's for n_λ, n_μ.  For a feasible datum that is
    not stable the two agree where n² is simple (N has not both n and -n): only there is the
    eigenvector of N the eigenvector of M_W.  Feasibility is the same test, the run on all of W."""
    gaps = particles - 1
    root, V = np.linalg.eig(half_map(word, gaps, r) if half else period_matrix(word, gaps, r))
    return _feasible_data(word, particles, half, list(root), lambda k: list(V[:, k].real),
                          lambda z: abs(z.imag) < 1e-12,
                          lambda p, q: follows(word, np.array(p), np.array(q), r, alphabet(particles)))


def _feasible_data(word: str, particles: int, half: bool, root: list, vector, is_real, follows_from) -> list[tuple]:
    """(λ, μ, stable) of :func:`data` from the eigenvalues ``root`` of M_w (of N with ``half``: M_W's are
    their squares) and ``vector(k)``, the real part of root[k]'s eigenvector: the pairs of real positive
    eigenvalues whose p(0) has every gap but the face's positive and whose run ``follows_from(p, q)``
    follows the word (q = ±q(0)); shared by the float and the mpmath datum."""
    letters, gaps = alphabet(particles), particles - 1
    ev = [z ** 2 for z in root] if half else root
    real = [k for k in range(gaps) if is_real(root[k]) and ev[k].real > 0]
    Y = letters.index(word[-1])
    out = []
    for a, b in itertools.permutations(real, 2):
        q0, e = vector(a), vector(b)
        p0 = [e[Y] * q0[i] - q0[Y] * e[i] for i in range(gaps)]
        p0[Y] = 0 * p0[Y]
        p0 = p0 if p0[(Y + 1) % gaps] > 0 else [-x for x in p0]
        if not all(p0[k] > 0 for k in range(gaps) if k != Y):
            continue
        if any(follows_from(p0, [s * x for x in q0]) for s in (1, -1)):
            rest = [abs(ev[k]) for k in range(gaps) if k not in (a, b)]
            out.append((float(ev[a].real), float(ev[b].real), bool(ev[a].real > ev[b].real > max(rest))))
    return out


def data_mp(word: str, r, particles: int, half: bool = False, digits: int = 50) -> list[tuple]:
    """:func:`data` in mpmath at ``digits`` digits (r a float or a decimal string), for long words whose
    μ/λ is below float64's rounding: the same datum, the same run, tolerances 10^(-digits/2) relative
    (observed, not certified)."""
    import mpmath as mp
    letters, gaps = alphabet(particles), particles - 1
    with mp.workdps(digits):
        r, tol = mp.mpf(r), mp.mpf(10) ** (-(digits // 2))
        cols = [tuple(mp.mpf(int(i == j)) for i in range(gaps)) for j in range(gaps)]
        for letter in (word[:len(word) // 2] if half else word):
            cols = [tuple(collide_gaps(letter, c, r)) for c in cols]
        rows = [[cols[j][i] for j in range(gaps)] for i in range(gaps)]
        root, V = mp.eig(mp.matrix(rows[::-1] if half else rows))
        return _feasible_data(word, particles, half, list(root), lambda k: [mp.re(V[i, k]) for i in range(gaps)],
                              lambda z: abs(mp.im(z)) < tol * abs(z),
                              lambda p, q: _follows_mp(word, p, q, r, letters, tol))


def _follows_mp(word: str, p: list, q: list, r, letters: str, tol) -> bool:
    """:func:`follows` in mpmath (the caller's precision), with the relative tolerance ``tol``."""
    for letter in word:
        times = sorted((-p[j] / q[j], j) for j in range(len(q)) if q[j] < 0)
        if not times or letters[times[0][1]] != letter:
            return False
        if len(times) > 1 and times[1][0] <= times[0][0] * (1 + tol):
            return False
        t, i = times[0]
        p = [x + t * v for x, v in zip(p, q)]
        if any(x < -tol * max(abs(y) for y in p) for x in p):
            return False
        p[i] = 0 * p[i]
        q = list(collide_gaps(letter, tuple(q), r))
    return True


def bisect(test, a: float, b: float) -> float:
    """The point where test changes between a and b (60 halvings)."""
    ta = test(a)
    for _ in range(60):
        m = (a + b) / 2
        a, b = (m, b) if test(m) == ta else (a, m)
    return (a + b) / 2


def window(word: str, grid, particles: int, stable: bool, half: bool = False, datum=data) -> list[float]:
    """The grid points where the word has a feasible (or stable) datum, and the ends bisected
    (``datum``: :func:`data`, or :func:`data_mp` at some digits)."""
    test = (lambda r: any(s for *_, s in datum(word, r, particles, half))) if stable else (
        lambda r: bool(datum(word, r, particles, half)))
    hits = [test(r) for r in grid]
    ends = [bisect(test, grid[k], grid[k + 1]) for k in range(len(grid) - 1) if hits[k] != hits[k + 1]]
    return ends, [r for r, h in zip(grid, hits) if h]


def exact_ends(word: str, ends: list[float], particles: int) -> None:
    """For each observed end, the exact polynomials with a certified root within 1e-8 of it."""
    import flint
    import sympy as sp

    from certify.dynamics.model import charpoly_coefficients
    from certify.dynamics.systems import of_particles, system_matrix_flint
    M = system_matrix_flint(of_particles(particles), word)
    n, r, y = len(M), sp.Symbol("r"), sp.Symbol("y")

    def expr(c):
        return sp.Add(*[sp.Rational(int(k.p), int(k.q)) * r ** i for i, k in enumerate(flint.fmpq_poly(c).coeffs())])

    def charpoly(A):
        cs = charpoly_coefficients(A)
        return sp.Add(*[expr(c) * y ** (len(cs) - 1 - k) for k, c in enumerate(cs)])

    zero = flint.fmpq_poly([])
    prod = [[sum((M[i][k] * M[k][j] for k in range(n)), zero) for j in range(n)] for i in range(n)]
    pairs = list(itertools.combinations(range(n), 2))
    wedge = [[M[i][k] * M[j][m] - M[i][m] * M[j][k] for (k, m) in pairs] for (i, j) in pairs]
    first = alphabet(particles).index(word[0])
    minor = [[M[i][j] for j in range(n) if j != first] for i in range(n) if i != first]
    cp = charpoly(M)
    sources = {"disc_λ cp": sp.discriminant(cp, y),
               "Res(cp_M², cp_Λ²M): equal moduli": sp.resultant(charpoly(prod), charpoly(wedge), y),
               f"Res(cp, cp of M without gap {first + 1}): q_{first + 1}(0) = 0": sp.resultant(cp, charpoly(minor), y)}
    for end in ends:
        print(f"end ≈ {end:.13f}")
        for name, poly in sources.items():
            for f, _ in sp.factor_list(sp.Poly(poly, r))[1]:
                fz = flint.fmpz_poly([int(c) for c in reversed(f.all_coeffs())])
                for z in fz.complex_roots():
                    z = z[0]
                    if abs(float(z.imag.mid())) < 1e-30 and abs(float(z.real.mid()) - end) < 1e-8:
                        print(f"   {name}: the root {z.real.str(16, radius=True)} of a factor of degree "
                              f"{fz.degree()}: {f.as_expr() if fz.degree() <= 4 else '…'}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--particles", type=int, default=5)
    ap.add_argument("--max-length", type=int, default=None)
    ap.add_argument("--word", default=None)
    ap.add_argument("--r", nargs=3, type=float, default=(0.01, 0.99, 99), metavar=("LO", "HI", "POINTS"))
    ap.add_argument("--ends", action="store_true", help="the exact polynomials at the ends of --word's window")
    ap.add_argument("--half", action="store_true", help="--word is X·m(X): the datum from N = J·M_X")
    ap.add_argument("--digits", type=int, default=None, help="--word's datum in mpmath at this many digits")
    args = ap.parse_args(argv)
    datum = data if args.digits is None else functools.partial(data_mp, digits=args.digits)
    grid = list(np.linspace(args.r[0], args.r[1], int(args.r[2])))
    if args.half:
        word = symmetric(args.word or "", args.particles)
        if not word:
            print(f"--half: {args.word!r} is not X·m(X) up to rotation (m the mirror)", file=sys.stderr)
            return 2
        args.word = word
    if args.word:
        for stable in (False, True):
            ends, hits = window(args.word, grid, args.particles, stable, args.half, datum)
            print(f"{'stable' if stable else 'feasible'}: {len(hits)} of {len(grid)} grid points; ends {ends}")
            if args.ends and stable:
                exact_ends(args.word, ends, args.particles)
        return 0
    count = 0
    for w in words(args.max_length, args.particles):
        count += 1
        hits = [r for r in grid if any(s for *_, s in data(w, r, args.particles))]
        if hits:
            print(f"{w}: stable on {len(hits)} grid points in [{min(hits):.6f}, {max(hits):.6f}]", flush=True)
    print(f"{count} words")
    return 0


if __name__ == "__main__":
    sys.exit(main())
