"""The engines behind :func:`certify.numerics.iterate`, one orbit at a time.

* ``float64``: the numba kernel (:mod:`.kernel`), parallel over orbits; here only a
  one-orbit wrapper (:func:`float64_orbit`).
* ``mp``: mpmath at ``dps`` decimal digits (gmpy2 backend when installed,
  ``mpmath.libmp.BACKEND``), with the same margin rule at TOL = SAFETY · 2^-prec and
  the same accumulated bound (:func:`.rules.carry_bound`) at its precision.
* ``ball``: python-flint arb, without wrapping.  The state after k collisions is
  P_k n0 with P_k = ±cof(K_{j_k}) ⋯ cof(K_{j_1}) the product of the integer cofactor
  matrices, kept *exactly* (fmpz), and n0 the ball of the initial normal; only the
  product is evaluated in balls, at each step, from P_k rounded to the working
  precision by arb (with a rigorous radius).  The radius of the normal is
  therefore |P_k| rad(n0) + O(2^-prec |P_k| |n0|): the bits lost along the orbit are
  log2(|P_k||n0| / |P_k n0|), the true condition of the product, not the wrapping of
  a ball pushed through k matrices (1-1.6 bits per collision).  When a choice is
  undecided only n0 is recomputed at twice the precision (P_k does not depend on it),
  up to a cap; the result is the certified horizon (the collisions proven) and, at
  the cap, the break that stopped it.  The datum is the float (θ0, φ0) read exactly.

All three run :func:`.rules.classify` and :func:`.rules.advance` (the kernel is their
transcription).  An :class:`OrbitResult` holds the break, the count, the collisions
certified, the φ of the last ``keep`` b-collisions, optionally the word and the
normals at checkpoints.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import flint
import mpmath
import numpy as np

from certify.algebra.balls import precision
from certify.dynamics.model import NEXT

from . import rules
from .leaps import LEAP_EVERY, LEAP_WINDOW, Leap, leap_along, period_of

ENGINES = ("float64", "mp", "ball")
MP_DPS = 30                    # default digits of the mp engine
BALL_START = 64                # first precision (bits) of the ball engine
BALL_CAP_DPS = 5000          # default cap of the ball engine, decimal digits (~16600 bits)
BITS_PER_DIGIT = math.log2(10)
SEGMENT = 512                  # collisions per exact product of the ball engine (_Product)


@dataclass
class OrbitResult:
    code: int
    collisions: int
    phi: np.ndarray                         # (keep,), NaN-padded at the front
    word: str = ""                          # the collision letters, when asked
    checkpoints: dict = field(default_factory=dict)   # collision -> (letter index, normal in the engine's numbers)
    bits: int = 53                          # the precision that gave this result
    certified: int = -1                     # the collisions certified (the certified horizon)

    def __post_init__(self):
        if self.certified < 0:
            self.certified = self.collisions


def _ring_to_phi(ring: list, keep: int) -> np.ndarray:
    out = np.full(keep, np.nan)
    have = ring[-keep:] if keep else []
    if have:
        out[keep - len(have):] = have
    return out


_CODES = np.frombuffer("".join(rules.LETTERS).encode("ascii"), dtype=np.uint8)


def _letters(indices: np.ndarray) -> str:
    """The word of the contact indices (0, 1, 2 → a, b, c), in one array operation."""
    return _CODES[indices].tobytes().decode("ascii")


def float64_orbit(r, theta0, phi0, collisions, keep=0, word=False, checkpoints=(), letter=rules.START,
                  normal=None, strict=False) -> OrbitResult:
    """One orbit on the float64 kernel (``trace`` when the word or checkpoints are asked: the
    letters alone, no state kept, when the word alone is); ``strict``: stop at the certified
    horizon (break 5)."""
    from . import kernel  # numba, imported where the float64 engine first runs, not at every command's start
    rows = np.array(rules.float_rows(r)).reshape(27)           # the kernel's flat layout
    n0 = np.array(normal if normal is not None else rules.initial_normal(theta0, phi0, letter), dtype=float)
    i0 = rules.INDEX[letter]
    constants = (rules.TOL64, rules.G64, rules.K64, rules.TINY64)
    if word and not checkpoints and not keep:           # the word alone: no state kept
        letters = np.zeros(collisions, dtype=np.int8)
        none = np.empty((0, 3))
        code, done, cert = kernel.trace(i0, n0, rows, *constants, collisions, strict, letters, none, none)
        return OrbitResult(int(code), int(done), _ring_to_phi([], 0), _letters(letters[:done]), {},
                           certified=int(cert))
    if word or checkpoints:
        letters = np.zeros(collisions, dtype=np.int8)
        normals = np.zeros((collisions, 3))
        errs = np.zeros((collisions, 3))
        code, done, cert = kernel.trace(i0, n0, rows, *constants, collisions, strict, letters, normals, errs)
        b = [rules.phi_of(1, normals[c]) for c in range(done) if letters[c] == 1] if keep else []   # the kept φ
        cps = {c: (int(letters[c - 1]), tuple(normals[c - 1])) for c in checkpoints if 0 < c <= done}
        return OrbitResult(int(code), int(done), _ring_to_phi(b, keep),
                           _letters(letters[:done]) if word else "", cps,
                           certified=int(cert))
    phi = np.empty(keep)
    code, done, cert = kernel._orbit(i0, n0, rows, *constants, collisions, keep, strict, phi)
    return OrbitResult(int(code), int(done), phi, certified=int(cert))


class _Record:
    """What an engine keeps of an orbit: the φ of the last b-collisions (a ring), the
    word when asked, the normals at the checkpoints."""

    def __init__(self, keep, word, checkpoints, phi):
        self.keep, self.word, self.want, self.phi = keep, word, set(checkpoints), phi
        self.ring, self.letters, self.cps = [], [], {}

    def add(self, j, n, done):
        if j == 1:
            self.ring.append(self.phi(n))
            if len(self.ring) > 2 * self.keep + 64:
                del self.ring[:len(self.ring) - self.keep]
        if self.word:
            self.letters.append(rules.LETTERS[j])
        if done in self.want:
            self.cps[done] = (j, n)


def _iterate(i, n, bounds, rows, absrows, tolerance, collisions, keep, word, checkpoints, sign, finite, phi,
             carry=None, err=None, strict=False):
    """The loop of the mp engine (rules.classify / rules.advance; ``carry(j, n, err)``
    the accumulated bound, rules.carry_bound).  Returns (code, done, certified, ring of
    b-angles, word, checkpoints)."""
    rec = _Record(keep, word, checkpoints, phi)
    code, done, certified = 0, 0, -1
    for c in range(collisions):
        code, j = rules.classify(i, n, bounds, sign, finite)
        if code == 0 and err is not None and not rules.certifies(i, n, err, j, sign, finite):
            certified, err = c, None            # the horizon: no need to carry the bound further
            if strict:
                code = rules.HORIZON
        if code:
            break
        if tolerance is not None:
            bounds = rules.step_bounds(j, n, absrows, tolerance)
        if err is not None:
            err = carry(j, n, err)
        n = rules.advance(j, n, rows)
        i, done = j, c + 1
        rec.add(j, n, done)
    return code, done, (done if certified < 0 else certified), rec.ring, "".join(rec.letters), rec.cps


def mp_orbit(r, theta0, phi0, collisions, keep=0, dps=MP_DPS, word=False, checkpoints=(),
             letter=rules.START, normal=None, strict=False) -> OrbitResult:
    """One orbit in mpmath at ``dps`` digits; ``strict``: stop at the certified horizon."""
    ctx = mpmath.mp.clone()
    ctx.dps = dps
    mpf = ctx.mpf

    def exact(q):                          # an exact rational as an mpf: numerator / denominator, rounded
        return mpf(q.numerator) / q.denominator

    rows = [[[mpf(int(z)) for z in row] for row in K] for K in rules.integer_rows(r)]
    absrows = rules.abs_rows(rows)
    if normal is not None:
        n = tuple(mpf(z) for z in normal)
    else:
        n = rules.initial_normal(mpf(theta0), mpf(phi0), letter, ctx.cos, ctx.sin)
    tolerance = exact(rules.tol(ctx.prec))
    g, kappa = exact(rules.gamma_bound(ctx.prec)), exact(rules.inflation(ctx.prec))   # both exact at prec bits
    top = max(abs(z) for z in n)
    bounds = (tolerance * top,) * 3

    def finite(z):
        return ctx.isfinite(z)

    def phi(v):
        return float(ctx.atan2(ctx.hypot(v[2], v[0]), v[1]))

    def carry(j, v, err):
        return rules.carry_bound(j, v, err, absrows, g, kappa)

    code, done, cert, ring, w, cps = _iterate(rules.INDEX[letter], n, bounds, rows, absrows, tolerance, collisions,
                                              keep, word, checkpoints, rules.margin_sign, finite, phi, carry, bounds,
                                              strict)
    return OrbitResult(code, done, _ring_to_phi(ring, keep), w, cps, bits=ctx.prec, certified=cert)


class _Product:
    """The orbit as exact products of the integer cofactor matrices (fmpz_mat): the
    finished segments ``done`` (each the product of :data:`SEGMENT` collisions) and
    ``P``, the product since the last one; ``base`` the ball of the normal at the
    start of ``P``: the datum n0 pushed through the segments, one evaluation per
    segment (a re-centring in the manner of Lohner's method: the wrapping of one ball
    evaluation happens once a segment, not once a collision, and the integers stay
    below SEGMENT times the size of a cofactor)."""

    def __init__(self, r, n0):
        self.mats = [flint.fmpz_mat([[int(z) for z in row] for row in K]) for K in rules.integer_rows(r)]
        self.P = flint.fmpz_mat([[1, 0, 0], [0, 1, 0], [0, 0, 1]])
        self.done = []
        self.steps = 0
        self.base = n0
        self._column, self._of = None, None

    def times(self, j):
        return self.mats[j] * self.P

    def push(self, P, n):
        """P becomes the current product, n = its evaluation; a new segment every SEGMENT."""
        self.P = P
        self.steps += 1
        if self.steps == SEGMENT:
            self.done.append(P)
            self.P = flint.fmpz_mat([[1, 0, 0], [0, 1, 0], [0, 0, 1]])
            self.steps = 0
            self.base = n

    def leap(self, jump: Leap, n, prec):
        """The proved leap ``jump`` from the current state n (the evaluation of P): P closes its
        segment, the leap is a segment of its own (evaluated again, as a power, at a new
        precision), and a new segment starts at the state after it, which is returned."""
        if self.steps:
            self.done.append(self.P)
        self.done.append(jump)
        self.P = flint.fmpz_mat([[1, 0, 0], [0, 1, 0], [0, 0, 1]])
        self.steps = 0
        self.base = jump.apply(n, prec)
        return self.base

    def rebase(self, n0, prec):
        """The datum at a new precision pushed through the finished segments."""
        for S in self.done:
            n0 = self.evaluate(S, n0, prec)
        self.base = n0
        return self.evaluate(self.P, n0, prec)

    def value(self, P):
        """:meth:`evaluate` of P at the base (the base's column built once a base: a column
        of balls is copied exactly, whatever the precision)."""
        if self._of is not self.base:
            n0 = self.base
            self._column, self._of = flint.arb_mat([[n0[0]], [n0[1]], [n0[2]]]), n0
        v = flint.arb_mat(P) * self._column
        return (v[0, 0], v[1, 0], v[2, 0])

    @staticmethod
    def evaluate(P, n0, prec):
        """A ball vector containing P n0: P rounded to arb at the working precision
        (``prec``, the caller's context; arb_mat rounds each integer with a rigorous
        radius) times the column of balls n0, in one arb_mat product; a :class:`.leaps.Leap`
        by its own power."""
        if isinstance(P, Leap):
            return P.apply(n0, prec)
        v = flint.arb_mat(P) * flint.arb_mat([[n0[0]], [n0[1]], [n0[2]]])
        return (v[0, 0], v[1, 0], v[2, 0])


def _initial_ball(theta0, phi0, letter, normal):
    if normal is not None:
        return tuple(flint.arb(rules.exact_r(z)) if not isinstance(z, flint.arb) else z for z in normal)
    return rules.initial_normal(flint.arb(theta0), flint.arb(phi0), letter, flint.arb.cos, flint.arb.sin)


def _ball_classify(i: int, n) -> tuple[int, int]:
    """:func:`.rules.classify` of a ball normal (signs by :func:`.rules.ball_sign`, zero
    bounds), the same answer: the usual state (finite, n_j > 0 > n_k and n_i decided:
    no break, the next contact j or k) read from three comparisons; any other by
    ``rules.classify`` itself."""
    j, k = NEXT[i]
    a, b, c = n[i], n[j], n[k]
    if b > 0 and c < 0 and a.is_finite() and b.is_finite() and c.is_finite():
        if a > 0:
            return rules.COMPLETED, j
        if a < 0:
            return rules.COMPLETED, k
    return rules.classify(i, n, (0, 0, 0), rules.ball_sign, flint.arb.is_finite)


def ball_states(r, theta0, phi0, collisions, dps=None, letter=rules.START, normal=None, start_bits=BALL_START,
                stop: dict | None = None, every: bool = True, leap: dict | None = None):
    """The certified orbit, state by state: yields ``(k, j, n, bits)`` for the state right
    after collision k (k = 0: the datum, at contact ``letter``), j its contact's index and
    n a ball vector containing a positive multiple of the reduction's normal (oriented,
    e_t · n > 0), computed at ``bits`` of precision (:class:`_Product`; the precision of
    the datum doubled from ``start_bits`` when a choice is undecided, up to ``dps``
    digits, default :data:`BALL_CAP_DPS`).  Every collision choice is proven by the balls.
    Ends after ``collisions`` collisions or at the first choice the cap cannot decide;
    ``stop``, when given, receives the break code and the precision (``stop["code"]``,
    ``stop["bits"]``).  ``every=False``: only the last state is yielded (the same state,
    computed without a yield and a precision context a collision).

    ``leap``, when given (a dict, read at every attempt: ``leap["until"]`` the last collision a
    leap may reach, default ``collisions``): every :data:`.leaps.LEAP_EVERY` collisions, when the
    last :data:`.leaps.LEAP_WINDOW` letters repeat a block, the orbit leaps over the periods of
    the block that :func:`.leaps.leap_along` proves it follows (a repelling periodic orbit only);
    the states inside a leap are not yielded, and ``leap["leaps"]`` lists (collision, periods,
    letters, s − 1) of each."""
    cap = int((dps or BALL_CAP_DPS) * BITS_PER_DIGIT) + 1
    prec = min(start_bits, cap)
    with precision(prec):
        prod = _Product(r, _initial_ball(theta0, phi0, letter, normal))
        n = prod.evaluate(prod.P, prod.base, prec)
    i = rules.INDEX[letter]
    code, done = 0, 0

    def more(P):
        """Double the precision: the datum again, through the segments, then P."""
        nonlocal prec
        prec = min(2 * prec, cap)
        with precision(prec):
            prod.rebase(_initial_ball(theta0, phi0, letter, normal), prec)
            return prod.evaluate(P, prod.base, prec)

    last = (0, i, n, prec)
    if every:
        yield last
    history: list[int] = []
    attempt = LEAP_EVERY
    refused: set[str] = set()           # blocks whose period matrix does not repel at r: not tried again

    def leapt() -> bool:
        """A proved leap from the current state (``leap``), taken; whether one was."""
        nonlocal n, done, last, history
        if len(history) > 2 * LEAP_WINDOW:
            history = history[-LEAP_WINDOW:]
        block = period_of("".join(rules.LETTERS[x] for x in history[-LEAP_WINDOW:]))
        if block is None:
            return False
        until = min(collisions, leap.get("until", collisions))
        jump = leap_along(prod.mats, i, n, block, (until - done) // len(block), prec, refused)
        if jump is None:
            return False
        leap.setdefault("leaps", []).append((done, jump.J, jump.length, jump.rate))
        n = prod.leap(jump, n, prec)
        done += jump.J * jump.length
        history = []
        last = (done, i, n, prec)
        return True

    while done < collisions:
        bits, before = prec, done
        with precision(prec):          # one context a collision, or (every=False) a precision
            while done < collisions and prec == bits:
                code, j = _ball_classify(i, n)
                if code in (rules.UNDECIDED, rules.SHORT_STEP) and prec < cap:
                    n, code = more(prod.P), 0    # a new precision: a new context
                    continue
                if code:
                    break
                P = prod.times(j)
                m = prod.value(P)
                t = (j + 1) % 3
                while not (m[t] > 0 or m[t] < 0) and prec < cap:     # the orientation undecided
                    m = more(P)
                if m[t] < 0:
                    P, m = -P, tuple(-z for z in m)
                prod.push(P, m)
                n = m
                i, done = j, done + 1
                last = (done, j, n, prec)
                if leap is not None:
                    history.append(j)
                    if done >= attempt:
                        attempt = done + LEAP_EVERY
                        if leapt() and every:
                            break
                if every:
                    break
        if code:
            break
        if every and done > before:
            yield last
    if not every:
        yield last
    if stop is not None:
        stop.update(code=code, bits=prec)


def ball_orbit(r, theta0, phi0, collisions, keep=0, dps=None, word=False, checkpoints=(), letter=rules.START,
               normal=None, start_bits=BALL_START, strict=False) -> OrbitResult:
    """One certified orbit: every collision choice proven by arb balls, the normal
    evaluated from exact products of cofactor matrices (module docstring,
    :class:`_Product`, :func:`ball_states`); the precision of the datum doubled from
    ``start_bits`` when a choice is undecided, up to ``dps`` digits (default
    :data:`BALL_CAP_DPS`).  ``collisions`` of the result is the certified horizon
    (``strict`` changes nothing: every collision is certified)."""
    stop = {"code": 0, "bits": start_bits}
    prec = [start_bits]

    def phi(v):
        with precision(prec[0]):
            return float(flint.arb.atan2((v[2] * v[2] + v[0] * v[0]).sqrt(), v[1]).mid())

    rec = _Record(keep, word, checkpoints, phi)
    done = 0
    for done, j, n, prec[0] in ball_states(r, theta0, phi0, collisions, dps, letter, normal, start_bits, stop):
        if done:
            rec.add(j, n, done)
    return OrbitResult(stop["code"], done, _ring_to_phi(rec.ring, keep), "".join(rec.letters), rec.cps,
                       bits=stop["bits"])


def run_orbit(engine: str, r, theta0, phi0, collisions, keep=0, dps=None, **kw) -> OrbitResult:
    """One orbit on the named engine."""
    if engine == "float64":
        return float64_orbit(r, theta0, phi0, collisions, keep, **kw)
    if engine == "mp":
        return mp_orbit(r, theta0, phi0, collisions, keep, dps or MP_DPS, **kw)
    if engine == "ball":
        return ball_orbit(r, theta0, phi0, collisions, keep, dps, **kw)
    raise ValueError(f"unknown engine {engine!r}")


def task(engine, r, theta0, phi0, collisions, keep, dps, strict=False, word=False):
    """A picklable unit of work for an executor: (phi, code, collisions, certified,
    word) of one orbit."""
    res = run_orbit(engine, r, theta0, phi0, collisions, keep, dps, strict=strict, word=word)
    return res.phi, res.code, res.collisions, res.certified, res.word


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
