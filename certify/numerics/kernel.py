"""The float64 engine: a numba transcription of :func:`.rules.classify`,
:func:`.rules.advance`, :func:`.rules.step_bounds` and :func:`.rules.carry_bound`,
parallel over (r, orbit) pairs with ``prange``.

The matrices are ``rules.float_rows(r)`` (``reduction.cofactor`` converted to float),
passed flat, as ``benchmarks/loop.c`` takes them: ``rows[r_index, 9 letter + 3 row +
column]`` (a contiguous 1-d row per r: constant offsets, as in C).  Two bounds travel with
the normal n, componentwise:

* ``bnd``, the rounding of the last step alone (``TOL · |Ĉ||n|``): the margin rule
  that decides the breaks 1-4 (a shadowing orbit goes on while it holds);
* ``err``, the rigorous bound of the accumulated error (:func:`.rules.carry_bound`,
  whose docstring proves it): while it decides every contact the collisions are
  certified; the first one it does not decide is the orbit's certified horizon.
  With ``strict`` the orbit stops there with break 5 (``rules.HORIZON``).

The normal is rescaled by a power of 2 when its largest entry leaves
[2^-256, 2^256] (exact in floats but for underflowing entries; both bounds are
rescaled with it, ``err`` as in step (v) of the proof).  Only the normals of the last
``keep`` b-collisions are kept (a ring buffer); φ is computed from them at the end.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

BIG = 2.0 ** 256
SMALL = 2.0 ** -256
B = 1                                 # the index of the contact b
HORIZON = 5                           # rules.HORIZON


@njit(cache=True, inline="always")
def _next(i):
    """(i + 1) mod 3 without a division (i in 0, 1, 2)."""
    return 0 if i == 2 else i + 1


@njit(cache=True, inline="always")
def _classify(i, n, bnd):
    """rules.classify with margin_sign: (code, next contact)."""
    if not (math.isfinite(n[0]) and math.isfinite(n[1]) and math.isfinite(n[2])):
        return 4, -1
    if n[0] == 0.0 and n[1] == 0.0 and n[2] == 0.0:
        return 3, -1
    j = _next(i)
    k = _next(j)
    if n[j] < -bnd[j] or n[k] > bnd[k]:
        return 3, -1
    if n[j] <= bnd[j] or n[k] >= -bnd[k]:
        return 2, -1
    if n[i] > bnd[i]:
        return 0, j
    if n[i] < -bnd[i]:
        return 0, k
    return 1, -1


@njit(cache=True, inline="always")
def _certifies(i, n, err, j):
    """rules.certifies: the accumulated bound decides the contact j.  A nan or inf
    bound decides nothing (the comparisons fail)."""
    a = _next(i)
    b = _next(a)
    if not (n[a] > err[a] and n[b] < -err[b]):
        return False
    if j == a:
        return n[i] > err[i]
    return n[i] < -err[i]


@njit(cache=True, inline="always")
def _advance(j, n, err, rows, tol, g, kappa, tiny):
    """rules.advance, rules.step_bounds and rules.carry_bound, then the power-of-2
    rescaling (both bounds with it): the new (n, bnd, err), as tuples (registers, not
    arrays: no aliasing to fear)."""
    R = 9 * j
    m0 = rows[R + 0] * n[0] + rows[R + 1] * n[1] + rows[R + 2] * n[2]
    m1 = rows[R + 3] * n[0] + rows[R + 4] * n[1] + rows[R + 5] * n[2]
    m2 = rows[R + 6] * n[0] + rows[R + 7] * n[1] + rows[R + 8] * n[2]
    t = _next(j)
    mt = m0 if t == 0 else (m1 if t == 1 else m2)
    if mt < 0.0:
        m0, m1, m2 = -m0, -m1, -m2
    a0, a1, a2 = abs(n[0]), abs(n[1]), abs(n[2])
    c00, c01, c02 = abs(rows[R + 0]), abs(rows[R + 1]), abs(rows[R + 2])
    c10, c11, c12 = abs(rows[R + 3]), abs(rows[R + 4]), abs(rows[R + 5])
    c20, c21, c22 = abs(rows[R + 6]), abs(rows[R + 7]), abs(rows[R + 8])
    b0 = tol * (c00 * a0 + c01 * a1 + c02 * a2)
    b1 = tol * (c10 * a0 + c11 * a1 + c12 * a2)
    b2 = tol * (c20 * a0 + c21 * a1 + c22 * a2)
    t0 = err[0] + g * a0                    # rules.carry_bound, in its order
    t1 = err[1] + g * a1
    t2 = err[2] + g * a2
    e0 = (c00 * t0 + c01 * t1 + c02 * t2) * kappa + tiny
    e1 = (c10 * t0 + c11 * t1 + c12 * t2) * kappa + tiny
    e2 = (c20 * t0 + c21 * t1 + c22 * t2) * kappa + tiny
    new_top = max(abs(m0), max(abs(m1), abs(m2)))
    if new_top > BIG or (new_top < SMALL and new_top > 0.0):
        e = math.frexp(new_top)[1]
        f = math.ldexp(1.0, -e)
        m0 *= f
        m1 *= f
        m2 *= f
        b0 *= f
        b1 *= f
        b2 *= f
        e0 = e0 * f + tiny
        e1 = e1 * f + tiny
        e2 = e2 * f + tiny
    return (m0, m1, m2), (b0, b1, b2), (e0, e1, e2)


@njit(cache=True)
def _phi(i, n0, n1, n2):
    """rules.phi_of."""
    v = (n0, n1, n2)
    return math.atan2(math.hypot(v[(i + 1) % 3], v[(i + 2) % 3]), v[i])


@njit(cache=True, inline="always")
def _start(n_init, tol):
    """The initial normal and its rounding bound, componentwise: tol · max |n_i|
    (the same for both bounds)."""
    n = (n_init[0], n_init[1], n_init[2])
    top = tol * max(abs(n[0]), max(abs(n[1]), abs(n[2])))
    return n, (top, top, top)


@njit(cache=True, inline="always")
def _decide(i, n, bnd, err, certified, done, strict):
    """One classification: (code, next contact, certified horizon so far; -1 while
    every collision is certified)."""
    code, j = _classify(i, n, bnd)
    if code == 0 and certified < 0 and not _certifies(i, n, err, j):
        certified = done
        if strict:
            code = HORIZON
    return code, j, certified


@njit(cache=True)
def _orbit(i0, n_init, rows, tol, g, kappa, tiny, collisions, keep, strict, out_phi):
    """One orbit: (break code, collisions done, collisions certified); the φ of the
    last ``keep`` b-collisions into out_phi, oldest first, NaN-padded at the front."""
    n, bnd = _start(n_init, tol)
    err = bnd
    ring = np.empty((max(keep, 1), 3))
    pos = 0
    stored = 0
    i = i0
    code = 0
    done = 0
    certified = -1
    for _ in range(collisions):
        code, j, certified = _decide(i, n, bnd, err, certified, done, strict)
        if code != 0:
            break
        n, bnd, err = _advance(j, n, err, rows, tol, g, kappa, tiny)
        i = j
        done += 1
        if j == B and keep > 0:
            ring[pos, 0] = n[0]
            ring[pos, 1] = n[1]
            ring[pos, 2] = n[2]
            pos += 1
            stored += 1
            if pos == keep:
                pos = 0
    have = min(stored, keep)
    for a in range(keep - have):
        out_phi[a] = np.nan
    start = (pos - have) % keep if keep > 0 else 0
    for a in range(have):
        q = (start + a) % keep
        out_phi[keep - have + a] = _phi(B, ring[q, 0], ring[q, 1], ring[q, 2])
    return code, done, (done if certified < 0 else certified)


@njit(cache=True, parallel=True)
def sweep(letters0, normals0, rows, tol, g, kappa, tiny, collisions, keep, strict, phi, breaks, counts, certified):
    """Every (r, orbit) pair, in parallel: rows (n_r, 27), normals0 (n_o, 3),
    letters0 (n_o,); fills phi (n_r, n_o, keep), breaks, counts and certified
    (n_r, n_o)."""
    n_r = rows.shape[0]
    n_o = normals0.shape[0]
    for idx in prange(n_r * n_o):
        a = idx // n_o
        b = idx % n_o
        code, done, cert = _orbit(letters0[b], normals0[b], rows[a], tol, g, kappa, tiny, collisions, keep, strict,
                                  phi[a, b])
        breaks[a, b] = code
        counts[a, b] = done
        certified[a, b] = cert


@njit(cache=True)
def trace(i0, n_init, rows, tol, g, kappa, tiny, collisions, strict, letters, normals, errors):
    """One orbit with every state recorded (tests, benchmarks): letters[k], normals[k]
    and the accumulated bound errors[k] after the collision k + 1; the letters alone when
    ``normals`` has no row (the word without the 48 bytes a collision of the states).
    Returns (code, collisions done, collisions certified)."""
    n, bnd = _start(n_init, tol)
    err = bnd
    i = i0
    certified = -1
    for c in range(collisions):
        code, j, certified = _decide(i, n, bnd, err, certified, c, strict)
        if code != 0:
            return code, c, (c if certified < 0 else certified)
        n, bnd, err = _advance(j, n, err, rows, tol, g, kappa, tiny)
        i = j
        letters[c] = j
        if normals.shape[0] > 0:
            for a in range(3):
                normals[c, a] = n[a]
                errors[c, a] = err[a]
    return 0, collisions, (collisions if certified < 0 else certified)


@njit(cache=True)
def shortest_period(s):
    """The shortest period of the array s (len(s) ≥ 1): len(s) − π, π the longest proper border
    (the prefix function, linear time)."""
    m = len(s)
    border = np.zeros(m, dtype=np.int64)
    k = 0
    for i in range(1, m):
        while k > 0 and s[k] != s[i]:
            k = border[k - 1]
        if s[k] == s[i]:
            k += 1
        border[i] = k
    return m - border[m - 1]


@njit(cache=True)
def count_steps(i0, n_init, rows, tol, g, kappa, tiny, collisions):
    """The bare loop (benchmarks): (code, collisions done, collisions certified, a
    checksum of the word: the letters in base 3, mod 2^48, as benchmarks/loop.c)."""
    n, bnd = _start(n_init, tol)
    err = bnd
    i = i0
    h = 0
    certified = -1
    for c in range(collisions):
        code, j, certified = _decide(i, n, bnd, err, certified, c, False)
        if code != 0:
            return code, c, (c if certified < 0 else certified), h
        n, bnd, err = _advance(j, n, err, rows, tol, g, kappa, tiny)
        i = j
        h = (h * 3 + j) & 0xFFFFFFFFFFFF    # the word in base 3, mod 2^48
    return 0, collisions, (collisions if certified < 0 else certified), h
