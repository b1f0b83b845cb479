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
    """M_w = K_{c_n} ... K_{c_1} at an mpmath r (the printed A, B, C: ``model.collide``), its
    columns pushed through the letters one by one."""
    import mpmath

    from certify.dynamics import collide
    one, zero = mpmath.mpf(1), mpmath.mpf(0)
    cols = [(one, zero, zero), (zero, one, zero), (zero, zero, one)]
    for letter in word:
        cols = [collide(letter, c, r) for c in cols]
    return mpmath.matrix([[cols[j][i] for j in range(3)] for i in range(3)])


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


SCREEN_MARGIN = 4        # digits: a screened sign is kept when |q_2(0)/(−q_1(0))| > 10^(margin − dps)


def screened_sign(n: int, r) -> int | None:
    """The sign of :func:`q2_of_dominant` at the mpmath number r as the mpmath evaluation at
    the current precision gives it, read from python-flint's certified enclosure of the
    dominant eigenvector (``acb_mat.eig``, about ten times faster) when it is far from 0:
    the ball excludes 0 and its modulus exceeds 10^(SCREEN_MARGIN − dps), where the mpmath
    value, accurate to about 10^-dps (relative to the largest component, q_1), has the same
    sign.  None otherwise (too close to 0, or the eigenvalues not isolated): ask mpmath.

    >>> import mpmath
    >>> with mpmath.workdps(20):
    ...     x = 7 - 4 * mpmath.sqrt(3) + mpmath.mpf(0.2) / 36
    ...     screened_sign(6, x), int(mpmath.sign(q2_of_dominant(6, x)))
    (1, 1)
    """
    import flint
    import mpmath

    from certify.algebra.balls import precision
    from certify.dynamics import collide
    dps = mpmath.mp.dps
    man, exp = mpmath.mpf(r).man_exp
    x = flint.fmpq(int(man)) * flint.fmpq(2) ** int(exp)          # the mpmath number, exactly
    with precision(4 * dps + 16 * n):
        ball = flint.arb(x)
        K = {}
        for L in "abc":
            cols = [collide(L, e, ball) for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
            K[L] = flint.arb_mat([[cols[j][i] for j in range(3)] for i in range(3)])
        M = (K["b"] * K["c"]) ** n * (K["b"] * K["a"]) ** n          # M_w, w = (ab)^n(cb)^n
        try:
            E, V = flint.acb_mat(M).eig(right=True)
        except ValueError:
            return None
        k = max(range(3), key=lambda i: abs(E[i]).mid())
        q = (V[1, k] / (-V[0, k])).real
        if not abs(q) > flint.arb(10) ** (SCREEN_MARGIN - dps):
            return None
        return 1 if q > 0 else -1


def upper_threshold(n: int, dps: int | None = None):
    """The upper threshold r_max(n) of (ab)^n(cb)^n, numerically (mpmath, ``dps`` digits):
    the root of q_2(0) = 0 (dominant eigenvector, CLAIMS L6) in ]R_CRIT + 0.12/n², R_CRIT + 0.32/n²[
    (r_max(n) − R_CRIT ≈ 0.2/n², found by a scan of 40 cells and the Illinois method).
    For n = 2..6 it gives the five thresholds printed in L4.  ``dps``: default
    :func:`digits_for` (the eigenvector's smallest component is about 10^-1.13n).  The scan
    reads only signs, screened (:func:`screened_sign`; mpmath where the screen does not
    decide): the same first cell, and the same root (``findroot`` evaluates q_2 itself).
    Returns an mpmath number."""
    import mpmath
    with mpmath.workdps(dps or digits_for(n)):
        rc = 7 - 4 * mpmath.sqrt(3)
        f = lambda x: q2_of_dominant(n, x)   # noqa: E731
        lo_c, hi_c = (0.12, 0.32) if n > 6 else (0.05, 0.8)
        xs = [rc + mpmath.mpf(lo_c + (hi_c - lo_c) * k / 40) / n ** 2 for k in range(41)]
        a, sa = xs[0], scan_sign(n, xs[0])
        for b in xs[1:]:                     # the first cell where q_2(0) changes sign (signs up to it only)
            sb = scan_sign(n, b)
            if sa * sb < 0:
                return mpmath.findroot(f, (a, b), solver="illinois")
            a, sa = b, sb
    raise ArithmeticError(f"no root of q_2(0) found for n = {n}")


def scan_sign(n: int, r) -> int:
    """The sign of the mpmath :func:`q2_of_dominant` at r: screened, else computed."""
    s = screened_sign(n, r)
    if s is None:
        v = q2_of_dominant(n, r)
        s = (v > 0) - (v < 0)
    return s


def min_component(n: int, r, dps: int | None = None) -> float:
    """min |e_i| / max |e_i| for the dominant eigenvector e of M_w, w = (ab)^n(cb)^n, at r (mpmath)."""
    import mpmath
    with mpmath.workdps(dps or digits_for(n)):
        E, V = mpmath.eig(word_matrix_mp("ab" * n + "cb" * n, mpmath.mpf(r)))
        k = max(range(3), key=lambda i: abs(E[i]))
        v = [abs(V[i, k]) for i in range(3)]
        return float(min(v) / max(v))
