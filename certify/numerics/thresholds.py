"""The thresholds of Section 5 as numbers: where the red lines of Figures 5.1-5.8 go,
and the upper thresholds of (ab)^n(cb)^n for any n (mpmath).

- :data:`R_CRIT`: 7 - 4√3, the three-particle collapse (CLAIMS L1).
- :func:`r_max`, :func:`upper_threshold`: the upper threshold of (ab)^n(cb)^n, the root of
  q_2(0) = 0 for the dominant eigenvector of M_w (CLAIMS L6), computed, not typed in;
  for n = 2..6 it is the printed radical of L4 (a test).
- :func:`r_exist`: the root of P (l. 1101) in [0, 1], ≈ 0.19166 (L3).
- :func:`red_lines`: the vertical red lines of the figures (L4 and L3).
- :func:`min_component`: how small the dominant eigenvector's smallest component is (N4).

Floats and mpmath numbers: for drawing and for choosing r, never a proof (the certified
thresholds are the certificates' L1-L6).
"""
from __future__ import annotations

import math
from functools import cache

import numpy as np

R_CRIT = 7 - 4 * math.sqrt(3)                              # three-particle collapse (L1)
N_LINES = (2, 3, 4, 5, 6)                                   # the thresholds drawn, as in L4


@cache
def r_max(n: int) -> float:
    """The upper threshold of (ab)^n(cb)^n as a float, computed (:func:`upper_threshold`,
    20 digits), not typed in: for n = 2..6 it is the printed radical of L4 (a test)."""
    return float(upper_threshold(n, 20))


P_EXIST = (17, -138, 831, -3148, 831, -138, 17)             # l. 1101


def r_exist() -> float:
    """The root of P (l. 1101) in [0, 1], ≈ 0.19166 (L3): the last red line of 5.2, 5.3b, 5.5."""
    roots = np.roots(P_EXIST)
    return float(min(z.real for z in roots if abs(z.imag) < 1e-12 and 0 < z.real < 1))


def red_lines() -> dict[str, float]:
    """The vertical red lines: the CDKK thresholds (L4) and r_exist (L3)."""
    lines = {f"(ab)^{n}(cb)^{n}": r_max(n) for n in N_LINES}
    lines["r_exist"] = r_exist()
    return lines


def word_matrix_mp(word: str, r):
    """M_w = K_{c_n} ... K_{c_1} at an mpmath r (the printed A, B, C: ``model.collide``)."""
    import mpmath

    from certify.dynamics import collide
    M = mpmath.eye(3)
    for letter in word:
        cols = [collide(letter, tuple(M[i, j] for i in range(3)), r) for j in range(3)]
        M = mpmath.matrix([[cols[j][i] for j in range(3)] for i in range(3)])
    return M


def q2_of_dominant(n: int, r) -> float:
    """u = q_2(0)/(−q_1(0)) of the dominant eigenvector of M_w, w = (ab)^n(cb)^n, at r
    (mpmath, at the current precision); CDKK's upper threshold is where it vanishes (L6)."""
    import mpmath
    E, V = mpmath.eig(word_matrix_mp("ab" * n + "cb" * n, r))
    k = max(range(3), key=lambda i: abs(E[i]))
    return mpmath.re(V[1, k] / (-V[0, k]))


def digits_for(n: int) -> int:
    """Decimal digits enough for (ab)^n(cb)^n: 40 + 1.5 n (the dominant eigenvector has a
    component of relative size about 10^-1.13n, N4)."""
    return 40 + (3 * n) // 2


def upper_threshold(n: int, dps: int | None = None):
    """The upper threshold r_max(n) of (ab)^n(cb)^n, numerically (mpmath, ``dps`` digits):
    the root of q_2(0) = 0 (dominant eigenvector, CLAIMS L6) in ]R_CRIT + 0.12/n², R_CRIT + 0.32/n²[
    (r_max(n) − R_CRIT ≈ 0.2/n², found by a scan of 40 cells and the Illinois method).
    For n = 2..6 it gives the five thresholds printed in L4.  ``dps``: default
    :func:`digits_for` (the eigenvector's smallest component is about 10^-1.13n).  Returns
    an mpmath number."""
    import mpmath
    with mpmath.workdps(dps or digits_for(n)):
        rc = 7 - 4 * mpmath.sqrt(3)
        f = lambda x: q2_of_dominant(n, x)   # noqa: E731
        lo_c, hi_c = (0.12, 0.32) if n > 6 else (0.05, 0.8)
        xs = [rc + mpmath.mpf(lo_c + (hi_c - lo_c) * k / 40) / n ** 2 for k in range(41)]
        a, fa = xs[0], f(xs[0])
        for b in xs[1:]:                     # the first cell where q_2(0) changes sign (f up to it only)
            fb = f(b)
            if fa * fb < 0:
                return mpmath.findroot(f, (a, b), solver="illinois")
            a, fa = b, fb
    raise ArithmeticError(f"no root of q_2(0) found for n = {n}")


def min_component(n: int, r, dps: int | None = None) -> float:
    """min |e_i| / max |e_i| for the dominant eigenvector e of M_w, w = (ab)^n(cb)^n, at r (mpmath)."""
    import mpmath
    with mpmath.workdps(dps or digits_for(n)):
        E, V = mpmath.eig(word_matrix_mp("ab" * n + "cb" * n, mpmath.mpf(r)))
        k = max(range(3), key=lambda i: abs(E[i]))
        v = [abs(V[i, k]) for i in range(3)]
        return float(min(v) / max(v))
