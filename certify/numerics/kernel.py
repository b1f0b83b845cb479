"""The float64 engine: a numba transcription of :func:`.rules.classify` and
:func:`.rules.advance`, parallel over (r, orbit) pairs with ``prange``.

The matrices are ``rules.float_rows(r)`` (``reduction.cofactor`` converted to float),
passed as an array ``rows[r_index, letter, row, column]``; ``absrows[r_index, letter,
row]`` their absolute row sums (unused since the bound is componentwise, kept in the
signature).  The normal is rescaled
by a power of 2 when its largest entry leaves [2^-256, 2^256] (exact in floats, and
the bounds are rescaled with it).  Only the normals of the last ``keep``
b-collisions are kept (a ring buffer); φ is computed from them at the end.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

BIG = 2.0 ** 256
SMALL = 2.0 ** -256
B = 1                                 # the index of the contact b


@njit(cache=True, inline="always")
def _classify(i, n, bnd):
    """rules.classify with margin_sign: (code, next contact)."""
    for a in range(3):
        if not math.isfinite(n[a]):
            return 4, -1
    if n[0] == 0.0 and n[1] == 0.0 and n[2] == 0.0:
        return 3, -1
    j = (i + 1) % 3
    k = (i + 2) % 3
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
def _advance(j, n, bnd, rows, absrows, tol):
    """rules.advance and rules.step_bounds in place, then the power-of-2 rescaling."""
    m0 = rows[j, 0, 0] * n[0] + rows[j, 0, 1] * n[1] + rows[j, 0, 2] * n[2]
    m1 = rows[j, 1, 0] * n[0] + rows[j, 1, 1] * n[1] + rows[j, 1, 2] * n[2]
    m2 = rows[j, 2, 0] * n[0] + rows[j, 2, 1] * n[1] + rows[j, 2, 2] * n[2]
    t = (j + 1) % 3
    mt = m0 if t == 0 else (m1 if t == 1 else m2)
    if mt < 0.0:
        m0, m1, m2 = -m0, -m1, -m2
    a0, a1, a2 = abs(n[0]), abs(n[1]), abs(n[2])
    b0 = tol * (abs(rows[j, 0, 0]) * a0 + abs(rows[j, 0, 1]) * a1 + abs(rows[j, 0, 2]) * a2)
    b1 = tol * (abs(rows[j, 1, 0]) * a0 + abs(rows[j, 1, 1]) * a1 + abs(rows[j, 1, 2]) * a2)
    b2 = tol * (abs(rows[j, 2, 0]) * a0 + abs(rows[j, 2, 1]) * a1 + abs(rows[j, 2, 2]) * a2)
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
    n[0] = m0
    n[1] = m1
    n[2] = m2
    bnd[0] = b0
    bnd[1] = b1
    bnd[2] = b2


@njit(cache=True)
def _phi(i, n0, n1, n2):
    """rules.phi_of."""
    v = (n0, n1, n2)
    return math.atan2(math.hypot(v[(i + 1) % 3], v[(i + 2) % 3]), v[i])


@njit(cache=True)
def _initial_bound(n, tol):
    """The rounding bound of the initial normal, componentwise: tol · max |n_i|."""
    bnd = np.empty(3)
    top = max(abs(n[0]), max(abs(n[1]), abs(n[2])))
    for a in range(3):
        bnd[a] = tol * top
    return bnd


@njit(cache=True)
def _orbit(i0, n_init, rows, absrows, tol, collisions, keep, out_phi):
    """One orbit: (break code, collisions done); the φ of the last ``keep``
    b-collisions into out_phi, oldest first, NaN-padded at the front."""
    n = n_init.copy()
    bnd = _initial_bound(n, tol)
    ring = np.empty((max(keep, 1), 3))
    pos = 0
    stored = 0
    i = i0
    code = 0
    done = 0
    for _ in range(collisions):
        code, j = _classify(i, n, bnd)
        if code != 0:
            break
        _advance(j, n, bnd, rows, absrows, tol)
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
    return code, done


@njit(cache=True, parallel=True)
def sweep(letters0, normals0, rows, absrows, tol, collisions, keep, phi, breaks, counts):
    """Every (r, orbit) pair, in parallel: rows (n_r, 3, 3, 3), normals0 (n_o, 3),
    letters0 (n_o,); fills phi (n_r, n_o, keep), breaks and counts (n_r, n_o)."""
    n_r = rows.shape[0]
    n_o = normals0.shape[0]
    for idx in prange(n_r * n_o):
        a = idx // n_o
        b = idx % n_o
        code, done = _orbit(letters0[b], normals0[b], rows[a], absrows[a], tol, collisions, keep, phi[a, b])
        breaks[a, b] = code
        counts[a, b] = done


@njit(cache=True)
def trace(i0, n_init, rows, absrows, tol, collisions, letters, normals):
    """One orbit with every state recorded (tests, benchmarks): letters[k] and
    normals[k] after the collision k + 1.  Returns (code, collisions done)."""
    n = n_init.copy()
    bnd = _initial_bound(n, tol)
    i = i0
    for c in range(collisions):
        code, j = _classify(i, n, bnd)
        if code != 0:
            return code, c
        _advance(j, n, bnd, rows, absrows, tol)
        i = j
        letters[c] = j
        normals[c, 0] = n[0]
        normals[c, 1] = n[1]
        normals[c, 2] = n[2]
    return 0, collisions


@njit(cache=True)
def count_steps(i0, n_init, rows, absrows, tol, collisions):
    """The bare loop (benchmarks): (code, collisions done, a checksum of the word)."""
    n = n_init.copy()
    bnd = _initial_bound(n, tol)
    i = i0
    h = 0
    for c in range(collisions):
        code, j = _classify(i, n, bnd)
        if code != 0:
            return code, c, h
        _advance(j, n, bnd, rows, absrows, tol)
        i = j
        h = (h * 3 + j) % 1000000007
    return 0, collisions, h
