"""The float64 engine of the five-particle reduction (:mod:`.five_reduction`): a numba transcription of
:func:`.five_reduction.classify`, :func:`.five_reduction.advance`, :func:`.rules.step_bounds`' margins (TOL · |Ĉ||ω|)
and :func:`.rules.carry_bound` at length 6, one orbit at a time.

``rows`` is ``five_reduction.float_rows(r)`` flat: ``rows[36 j + 6 m + c]``.  The bivector is rescaled by
a power of 2 when its largest entry leaves [2^-256, 2^256], both bounds with it (``err`` as in
step (v) of carry_bound's proof), as :mod:`.kernel` does for the four-particle normal.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

BIG = 2.0 ** 256
SMALL = 2.0 ** -256
HORIZON = 5                            # rules.HORIZON
# SLOT[k, l]: the index of ω_kl, k < l, in five_reduction.PAIRS
SLOT = np.array([[-1, 0, 1, 2], [0, -1, 3, 4], [1, 3, -1, 5], [2, 4, 5, -1]], dtype=np.int64)


@njit(cache=True, inline="always")
def _entry(w, k, m):
    """ω_km for k ≠ m."""
    return w[SLOT[k, m]] if k < m else -w[SLOT[k, m]]


@njit(cache=True)
def _classify(i, w, bnd):
    """five_reduction.classify with margin_sign: (code, next face)."""
    zero = True
    for m in range(6):
        if not math.isfinite(w[m]):
            return 4, -1
        if w[m] != 0.0:
            zero = False
    if zero:
        return 3, -1
    short = False
    for k in range(4):
        if k != i:
            x = -_entry(w, i, k)
            b = bnd[SLOT[i, k]]
            if x < -b:
                return 3, -1
            if not (x > b):             # margin_sign 0: a nan bound decides nothing
                short = True
    if short:
        return 2, -1
    for j in range(4):
        if j == i:
            continue
        wins = True
        for k in range(4):
            if k != i and k != j and not (_entry(w, j, k) > bnd[SLOT[j, k]]):
                wins = False
        if wins:
            return 0, j
    return 1, -1


@njit(cache=True)
def _certifies(i, w, err, j):
    """rules.certifies for the bivector: five_reduction.classify at the bounds ``err`` decides
    the face j, i.e. −ω_ik > err for the three k ≠ i and ω_jk > err for the two k ≠ i, j (the
    tournament's winner is unique).  Written positively: a nan or inf bound decides nothing
    (every comparison with it fails)."""
    for k in range(4):
        if k == i:
            continue
        if not (-_entry(w, i, k) > err[SLOT[i, k]]):
            return False
        if k != j and not (_entry(w, j, k) > err[SLOT[j, k]]):
            return False
    return True


@njit(cache=True)
def orbit(i0, w0, e0, rows, tol, g, kappa, tiny, collisions, strict, words, letters, out):
    """One orbit from the face i0 and the bivector w0 with the bound e0: (break code,
    collisions done, collisions certified, last face); the letters (0..3) into ``letters``
    when ``words``, the last bivector into ``out``."""
    w = w0.copy()
    bnd = e0.copy()
    err = e0.copy()
    nw = np.empty(6)
    nb = np.empty(6)
    ne = np.empty(6)
    t = np.empty(6)
    i = i0
    code = 0
    done = 0
    certified = -1
    for _ in range(collisions):
        code, j = _classify(i, w, bnd)
        if code == 0 and certified < 0:
            if not _certifies(i, w, err, j):
                certified = done
                if strict:
                    code = HORIZON
        if code != 0:
            break
        R = 36 * j
        for c in range(6):
            t[c] = err[c] + g * abs(w[c])
        for m in range(6):
            s = rows[R + 6 * m] * w[0]
            a = abs(rows[R + 6 * m]) * abs(w[0])
            e = abs(rows[R + 6 * m]) * t[0]
            for c in range(1, 6):
                s = s + rows[R + 6 * m + c] * w[c]
                a = a + abs(rows[R + 6 * m + c]) * abs(w[c])
                e = e + abs(rows[R + 6 * m + c]) * t[c]
            nw[m] = s
            nb[m] = tol * a
            ne[m] = e * kappa + tiny
        top = 0.0
        for m in range(6):
            top = max(top, abs(nw[m]))
        if top > BIG or (top < SMALL and top > 0.0):
            f = math.ldexp(1.0, -math.frexp(top)[1])
            for m in range(6):
                nw[m] *= f
                nb[m] *= f
                ne[m] = ne[m] * f + tiny
        for m in range(6):
            w[m] = nw[m]
            bnd[m] = nb[m]
            err[m] = ne[m]
        if words:
            letters[done] = j
        i = j
        done += 1
    for m in range(6):
        out[m] = w[m]
    return code, done, (done if certified < 0 else certified), i
