"""The engines behind :func:`certify.numerics.simulate`, one orbit at a time.

* ``float64``: the numba kernel (:mod:`.kernel`), parallel over orbits; here only a
  one-orbit wrapper (:func:`float64_orbit`).
* ``mp``: mpmath at ``dps`` decimal digits (gmpy2 backend when installed,
  ``mpmath.libmp.BACKEND``), with the same margin rule at TOL = SAFETY · 2^-prec.
* ``ball``: python-flint arb.  A sign is used only when the ball proves it; when a
  choice is undecided the orbit is recomputed from its datum at twice the precision,
  up to a cap; the result is the certified horizon (the collisions proven) and, at
  the cap, the break that stopped it.  The datum is the float (θ0, φ0) read exactly.

All three run :func:`.rules.classify` and :func:`.rules.advance` (the kernel is their
transcription).  An :class:`OrbitResult` holds the break, the count, the φ of the
last ``keep`` b-collisions, optionally the word and the normals at checkpoints.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import flint
import mpmath
import numpy as np

from certify.algebra.balls import precision
from . import kernel, rules

ENGINES = ("float64", "mp", "ball")
MP_DPS = 30                    # default digits of the mp engine
BALL_START = 64                # first precision (bits) of the ball engine
BALL_CAP_DPS = 5000          # default cap of the ball engine, decimal digits (~16600 bits)
BITS_PER_DIGIT = math.log2(10)


@dataclass
class OrbitResult:
    code: int
    collisions: int
    phi: np.ndarray                         # (keep,), NaN-padded at the front
    word: str = ""                          # the collision letters, when asked
    checkpoints: dict = field(default_factory=dict)   # collision -> (letter index, normal in the engine's numbers)
    bits: int = 53                          # the precision that gave this result


def _ring_to_phi(ring: list, keep: int) -> np.ndarray:
    out = np.full(keep, np.nan)
    have = ring[-keep:] if keep else []
    if have:
        out[keep - len(have):] = have
    return out


def float64_orbit(r, theta0, phi0, collisions, keep=0, word=False, checkpoints=(), letter=rules.START,
                  normal=None) -> OrbitResult:
    """One orbit on the float64 kernel (``trace`` when the word or checkpoints are asked)."""
    rows = np.array(rules.float_rows(r))
    absrows = np.array(rules.row_abs(rules.float_rows(r)))
    n0 = np.array(normal if normal is not None else rules.initial_normal(theta0, phi0, letter), dtype=float)
    i0 = rules.INDEX[letter]
    if word or checkpoints:
        letters = np.zeros(collisions, dtype=np.int8)
        normals = np.zeros((collisions, 3))
        code, done = kernel.trace(i0, n0, rows, absrows, rules.TOL64, collisions, letters, normals)
        b = [rules.phi_of(1, normals[c]) for c in range(done) if letters[c] == 1]
        cps = {c: (int(letters[c - 1]), tuple(normals[c - 1])) for c in checkpoints if 0 < c <= done}
        return OrbitResult(code, done, _ring_to_phi(b, keep),
                           "".join(rules.LETTERS[x] for x in letters[:done]) if word else "", cps)
    phi = np.empty(keep)
    code, done = kernel._orbit(i0, n0, rows, absrows, rules.TOL64, collisions, keep, phi)
    return OrbitResult(int(code), int(done), phi)


def _iterate(i, n, bounds, rows, absrows, tolerance, collisions, keep, word, checkpoints, sign, finite, phi):
    """The generic loop of the mp and ball engines (rules.classify / rules.advance)."""
    ring, letters, cps = [], [], {}
    want = set(checkpoints)
    code, done = 0, 0
    for c in range(collisions):
        code, j = rules.classify(i, n, bounds, sign, finite)
        if code:
            break
        if tolerance is not None:
            bounds = rules.step_bounds(j, n, absrows, tolerance)
        n = rules.advance(j, n, rows)
        i, done = j, c + 1
        if j == 1:
            ring.append(phi(n))
            if len(ring) > 2 * keep + 64:
                del ring[:len(ring) - keep]
        if word:
            letters.append(rules.LETTERS[j])
        if done in want:
            cps[done] = (j, n)
    return code, done, ring, "".join(letters), cps


def mp_orbit(r, theta0, phi0, collisions, keep=0, dps=MP_DPS, word=False, checkpoints=(),
             letter=rules.START, normal=None) -> OrbitResult:
    """One orbit in mpmath at ``dps`` digits."""
    ctx = mpmath.mp.clone()
    ctx.dps = dps
    mpf = ctx.mpf
    rows = [[[mpf(int(z)) for z in row] for row in K] for K in rules.integer_rows(r)]
    absrows = rules.abs_rows(rows)
    if normal is not None:
        n = tuple(mpf(z) for z in normal)
    else:
        n = rules.initial_normal(mpf(theta0), mpf(phi0), letter, ctx.cos, ctx.sin)
    tolerance = mpf(rules.tol(ctx.prec).numerator) / rules.tol(ctx.prec).denominator
    top = max(abs(z) for z in n)
    bounds = (tolerance * top,) * 3

    def finite(z):
        return ctx.isfinite(z)

    def phi(v):
        return float(ctx.atan2(ctx.hypot(v[2], v[0]), v[1]))

    code, done, ring, w, cps = _iterate(rules.INDEX[letter], n, bounds, rows, absrows, tolerance, collisions, keep,
                                        word, checkpoints, rules.margin_sign, finite, phi)
    return OrbitResult(code, done, _ring_to_phi(ring, keep), w, cps, bits=ctx.prec)


def _ball_attempt(r, theta0, phi0, collisions, keep, word, checkpoints, letter, normal, prec):
    with precision(prec):
        rows = [[[flint.arb(int(z)) for z in row] for row in K] for K in rules.integer_rows(r)]
        if normal is not None:
            n = tuple(flint.arb(rules.exact_r(z)) if not isinstance(z, flint.arb) else z for z in normal)
        else:
            n = rules.initial_normal(flint.arb(theta0), flint.arb(phi0), letter, flint.arb.cos, flint.arb.sin)

        def phi(v):
            return float(flint.arb.atan2((v[2] ** 2 + v[0] ** 2).sqrt(), v[1]).mid())

        return _iterate(rules.INDEX[letter], n, (0, 0, 0), rows, None, None, collisions, keep, word, checkpoints,
                        rules.ball_sign, flint.arb.is_finite, phi)


def ball_orbit(r, theta0, phi0, collisions, keep=0, dps=None, word=False, checkpoints=(), letter=rules.START,
               normal=None, start_bits=BALL_START) -> OrbitResult:
    """One certified orbit: every collision choice proven by arb balls; precision
    doubled from ``start_bits`` on an undecided choice, up to ``dps`` digits (default
    :data:`BALL_CAP_DPS`).  ``collisions`` of the result is the certified horizon."""
    cap = int((dps or BALL_CAP_DPS) * BITS_PER_DIGIT) + 1
    prec = min(start_bits, cap)
    while True:
        code, done, ring, w, cps = _ball_attempt(r, theta0, phi0, collisions, keep, word, checkpoints, letter,
                                                 normal, prec)
        if code not in (rules.UNDECIDED, rules.SHORT_STEP) or prec >= cap:
            return OrbitResult(code, done, _ring_to_phi(ring, keep), w, cps, bits=prec)
        prec = min(2 * prec, cap)


def run_orbit(engine: str, r, theta0, phi0, collisions, keep=0, dps=None, **kw) -> OrbitResult:
    """One orbit on the named engine."""
    if engine == "float64":
        return float64_orbit(r, theta0, phi0, collisions, keep, **kw)
    if engine == "mp":
        return mp_orbit(r, theta0, phi0, collisions, keep, dps or MP_DPS, **kw)
    if engine == "ball":
        return ball_orbit(r, theta0, phi0, collisions, keep, dps, **kw)
    raise ValueError(f"unknown engine {engine!r}")


def task(engine, r, theta0, phi0, collisions, keep, dps):
    """A picklable unit of work for an executor: (phi, code, collisions) of one orbit."""
    res = run_orbit(engine, r, theta0, phi0, collisions, keep, dps)
    return res.phi, res.code, res.collisions


def certified(r, theta0, phi0, collisions, checkpoints=(), dps=None, start_bits=BALL_START):
    """The certified orbit as plain, picklable data (for a worker process): (break,
    certified horizon, bits, word, {collision: (letter index, [(p, q)] the exact
    midpoints of the normal's balls)})."""
    res = ball_orbit(r, theta0, phi0, collisions, word=True, checkpoints=checkpoints, dps=dps, start_bits=start_bits)
    cps = {}
    with precision(res.bits):                  # mid() rounds to the working precision
        for k, (j, n) in res.checkpoints.items():
            mids = [z.mid().fmpq() for z in n]
            cps[k] = (j, [(int(q.p), int(q.q)) for q in mids])
    return res.code, res.collisions, res.bits, res.word, cps
