"""Sturm sequences over Q: exact real-root counting and isolation.

Two routes to the real roots of a polynomial over Q, kept apart:

* :func:`sturm_count`, the first route: Sturm's theorem alone, the sign changes of
  our Sturm sequence at rational points (or ±∞), every sign an exact rational
  evaluation.  It never calls python-flint's root finder.
* :func:`flint_real_roots`, the second route: python-flint's certified complex root
  isolation, keeping the roots it proves real.

:func:`checked_real_root_count` compares the two over the whole line (a disagreement
is an ArithmeticError: a FAIL, not a warning).  For speed, :func:`count_roots` and
:func:`isolate` use python-flint's root balls as *enclosures*, each checked by an
exact sign change and their number by the Sturm count over the line; where that
check fails they fall back to Sturm sign changes.  Counts are of *distinct* real
roots; a polynomial with multiple roots is first divided by gcd(p, p').

>>> import flint
>>> p = flint.fmpq_poly([-2, 0, 1])                 # r² - 2
>>> sturm_count(p), sturm_count(p, 0, 2), len(flint_real_roots(p))
(2, 1, 2)
"""
from __future__ import annotations

import flint

from certify import caches

from .balls import ordered, precision
from .poly import Q, poly_key, primitive, squarefree_part, to_fmpq

_SEQUENCES: dict = {}            # the coefficients of p -> its Sturm sequence (memoised)
caches.register(_SEQUENCES.clear)
_ball_poly = caches.by_identity(flint.arb_poly, limit=4096)     # a sequence member as a ball polynomial


def sturm_sequence(p) -> list[flint.fmpq_poly]:
    """The Sturm sequence p0 = p/gcd(p,p'), p1 = p0', p_{k+1} = -rem(p_{k-1}, p_k);
    memoised per polynomial (the same polynomials recur in every comparison)."""
    p = flint.fmpq_poly(p)
    key = poly_key(p)
    seq = _SEQUENCES.get(key)
    if seq is None:
        seq = _SEQUENCES[key] = _sturm_sequence(p)
        if len(_SEQUENCES) > 20000:
            _SEQUENCES.clear()
    return seq


def _sturm_sequence(p) -> list[flint.fmpq_poly]:
    """p0, p0', then each -rem(p_{k-1}, p_k) replaced by its positive multiple with coprime
    integer coefficients (0 stays 0): Sturm's sign changes count the same (a positive factor changes
    no sign, and the remainder of positive multiples is a positive multiple of the
    remainder), while the rationals of the plain remainder sequence grow without bound
    (a degree-140 discriminant: 10 s plain, 0.2 s so)."""
    g = p.gcd(p.derivative())
    p0 = p // g if g.degree() > 0 else p
    seq = [p0, p0.derivative()]
    a, b = _primitive_multiple(p0), _primitive_multiple(seq[1])
    while b.degree() > 0:
        rem = -(a % b)
        if rem.is_zero():
            break
        rem = _primitive_multiple(rem)
        seq.append(rem)
        a, b = b, rem
    return seq


def _primitive_multiple(q: flint.fmpq_poly) -> flint.fmpq_poly:
    """The positive multiple of q with coprime integer coefficients (q ≠ 0): its numerator
    (q times its positive common denominator) divided by the numerator's positive content;
    0 stays 0."""
    if q.is_zero():
        return q
    n = q.numer()
    return flint.fmpq_poly(n) / n.content()


def _sign(a) -> int:
    return (a > 0) - (a < 0)


def sign_at_rational(p: flint.fmpq_poly, a: flint.fmpq) -> int:
    """The sign of p(a), exact: a ball evaluation when it excludes 0 (cheap for the
    long rationals of bisection), else the exact rational value."""
    if p.degree() > 8:
        with precision(128):
            v = _ball_poly(p)(flint.arb(a))
        if v > 0:
            return 1
        if v < 0:
            return -1
    return _sign(p(a))


def sign_changes(seq, a) -> int:
    """Number of sign changes of the Sturm sequence at the rational a (zeros skipped)."""
    a = to_fmpq(a)
    signs = [s for s in (sign_at_rational(p, a) for p in seq) if s != 0]
    return sum(1 for s, t in zip(signs, signs[1:]) if s != t)


@caches.by_identity
def _at_infinity(seq) -> dict[int, int]:
    """{±1: the sign changes of the sequence ``seq`` at ±∞}, filled as asked."""
    return {}


def _sign_changes_at_infinity(seq, sign: int) -> int:
    known = _at_infinity(seq)
    if sign not in known:
        known[sign] = _changes_at_infinity(seq, sign)
    return known[sign]


def _changes_at_infinity(seq, sign: int) -> int:
    signs = []
    for p in seq:
        lc = _sign(p[p.degree()]) if p.degree() >= 0 else 0
        signs.append(lc * (sign ** p.degree()) if p.degree() >= 0 else 0)
    signs = [s for s in signs if s]
    return sum(1 for s, t in zip(signs, signs[1:]) if s != t)


_BALLS: dict = {}                # coefficients of p0 -> [(a, b, sign p0(a))] or None
caches.register(_BALLS.clear)
_COMPLEX: dict = {}              # (coefficients of P, working precision) -> P.complex_roots()
caches.register(_COMPLEX.clear)
BALL_BITS = 64 + 30              # the working precision of the root balls of both uses below


def complex_roots(P) -> list:
    """python-flint's certified complex roots of P, (acb, multiplicity) pairs, at the current
    working precision; memoised by the primitive integer polynomial proportional to P, so
    every caller shares one isolation of a polynomial (the enclosures of :func:`count_roots`,
    the second route's count, :func:`flint_real_roots`, and the balls of algebraic numbers
    isolate the same factors)."""
    P = primitive(P)
    key = (poly_key(P), flint.ctx.prec)
    out = _COMPLEX.get(key)
    if out is None:
        if len(_COMPLEX) > 20000:
            _COMPLEX.clear()
        out = _COMPLEX[key] = P.complex_roots()
    return out


def isolated_real_root(p, lo, hi):
    """The real root ball of p inside ]lo, hi[ from an isolation of p already made at the
    working precision of the root balls (``BALL_BITS``), when that isolation holds exactly
    one real ball inside ]lo, hi[, it is a simple root, and no ball straddles an end; else
    None (nothing is isolated here: the caller isolates)."""
    roots = _COMPLEX.get((poly_key(primitive(p)), BALL_BITS))
    hit = real_ball_inside(roots, lo, hi) if roots is not None else None
    return hit[0] if hit is not None and hit[1] == 1 else None


def real_ball_inside(roots, lo, hi):
    """(x, multiplicity) of the one real ball x among python-flint's roots (acb, multiplicity)
    that lies strictly inside ]lo, hi[ (rational ends); None when there is none, more than
    one, or a real ball straddles an end (undecided here)."""
    hits = []
    for c, m in roots:
        if not c.imag.is_zero():
            continue
        x = c.real
        a, b = x.mid().fmpq() - x.rad().fmpq(), x.mid().fmpq() + x.rad().fmpq()
        if lo < a and b < hi:
            hits.append((x, m))
        elif not (b < lo or a > hi):
            return None
    return hits[0] if len(hits) == 1 else None


def _root_enclosures(seq):
    """The real roots of p0 = seq[0] (squarefree) as disjoint increasing intervals
    ]a, b[ with exact rational ends, from python-flint's certified root balls, each
    checked by an exact sign change of p0 at its ends, as many as the Sturm count over
    the whole line: then each holds exactly one root and every root is in one.
    [(a, b, sign p0(a))], or None when that check fails.  Memoised."""
    p0 = seq[0]
    known = _BALLS_OF.get(id(seq))
    if known is not None and known[0] is seq:        # the same sequence object: no key to build
        return known[1]
    key = poly_key(p0)
    if key in _BALLS:
        _remember(seq, _BALLS[key])
        return _BALLS[key]
    if len(_BALLS) > 20000:
        _BALLS.clear()
    out = None
    try:
        with precision(BALL_BITS):
            roots = [c.real for c, _m in complex_roots(p0.numer()) if c.imag.is_zero()]
        cand = []
        for z in roots:
            m, d = z.mid().fmpq(), z.rad().fmpq()
            a, b = m - d, m + d
            sa, sb = _sign(p0(a)), _sign(p0(b))
            if sa == 0 or sb == 0 or sa == sb:
                cand = None
                break
            cand.append((a, b, sa))
        if cand is not None:
            cand.sort(key=lambda e: e[0])
            total = _sign_changes_at_infinity(seq, -1) - _sign_changes_at_infinity(seq, 1)
            if len(cand) == total and all(e[1] < f[0] for e, f in zip(cand, cand[1:])):
                out = cand
    except (ValueError, ArithmeticError):
        out = None
    _BALLS[key] = out
    _remember(seq, out)
    return out


_BALLS_OF: dict = {}             # id of a sequence -> (sequence, its enclosures): _BALLS without the key
caches.register(_BALLS_OF.clear)


def _remember(seq, enclosures) -> None:
    if len(_BALLS_OF) > 20000:
        _BALLS_OF.clear()
    _BALLS_OF[id(seq)] = (seq, enclosures)


def _compare_root(p0, enclosure, x) -> int:
    """sign(ρ - x) for the one root ρ of p0 in the enclosure ]a, b[ and a rational x, exact."""
    a, b, sa = enclosure
    if b <= x:
        return -1
    if a >= x:
        return 1
    sx = sign_at_rational(p0, x)
    if sx == 0:
        return 0
    return 1 if sx == sa else -1          # no sign change on ]a, x]: ρ lies above x


def count_roots(p, a=None, b=None, seq=None) -> int:
    """Number of distinct real roots of p in ]a, b] (a = -∞, b = +∞ when None), fast: by
    the certified root enclosures of :func:`_root_enclosures` when they are available
    (the same number, fewer evaluations), else by the sign changes of the Sturm
    sequence.  What isolation uses; the count reported as "Sturm" is :func:`sturm_count`."""
    seq = seq or sturm_sequence(p)
    if a is not None or b is not None:
        encl = _root_enclosures(seq) if seq[0].degree() > 2 else None
        if encl is not None:
            a = None if a is None else to_fmpq(a)
            b = None if b is None else to_fmpq(b)
            return sum(1 for e in encl if (a is None or _compare_root(seq[0], e, a) > 0)
                       and (b is None or _compare_root(seq[0], e, b) <= 0))
    va = _sign_changes_at_infinity(seq, -1) if a is None else sign_changes(seq, a)
    vb = _sign_changes_at_infinity(seq, 1) if b is None else sign_changes(seq, b)
    return va - vb


def sturm_count(p, a=None, b=None) -> int:
    """The number of distinct real roots of p in ]a, b] (a = -∞, b = +∞ when None) by
    Sturm's theorem alone: V(a) - V(b), the sign changes of the Sturm sequence, each
    sign an exact rational evaluation (no ball, no root finder).  The first route.

    x³ - 2x has the roots -√2, 0, √2; one of them in ]0, 2]:

    >>> import flint
    >>> p = flint.fmpq_poly([0, -2, 0, 1])
    >>> sturm_count(p), sturm_count(p, 0, 2)
    (3, 1)
    >>> sturm_count(p * p)          # distinct roots: a double root counts once
    3

    What is guaranteed: the count is exact for any p over Q and rational ends (no
    precision is involved).  What is not: the interval is half-open, so a root at b
    is counted and a root at a is not."""
    seq = sturm_sequence(p)

    def changes(t):
        signs = [s for s in (_sign(q(t)) for q in seq) if s != 0]
        return sum(1 for s, u in zip(signs, signs[1:]) if s != u)
    va = _sign_changes_at_infinity(seq, -1) if a is None else changes(to_fmpq(a))
    vb = _sign_changes_at_infinity(seq, 1) if b is None else changes(to_fmpq(b))
    return va - vb


_CHECKED: dict = {}              # coefficients of p -> its number of distinct real roots
caches.register(_CHECKED.clear)


def checked_real_root_count(p) -> int:
    """The number of distinct real roots of p, counted by both routes: the Sturm count
    over the line (:func:`sturm_count`) and python-flint's isolation
    (:func:`flint_real_roots`); ArithmeticError when they disagree.  Memoised.

    >>> import flint
    >>> checked_real_root_count(flint.fmpq_poly([1, -10, 1]))       # r² - 10r + 1: 5 ± 2√6
    2
    >>> checked_real_root_count(flint.fmpq_poly([5, -40, 102, -40, 5]))   # T15's quartic
    0

    The two routes share nothing but p: a disagreement is an error, never a count."""
    key = poly_key(p)
    if key not in _CHECKED:
        n = sturm_count(p)
        with precision(BALL_BITS):          # the balls the enclosures of count_roots use too
            m = len(flint_real_roots(p))
        if n != m:
            raise ArithmeticError(f"Sturm ({n}) and python-flint ({m}) disagree on the real roots of {p}")
        if len(_CHECKED) > 20000:
            _CHECKED.clear()
        _CHECKED[key] = n
    return _CHECKED[key]


def cauchy_bound(p) -> flint.fmpq:
    """1 + max |a_i / a_n|: every complex root has modulus below it."""
    c = flint.fmpq_poly(p).coeffs()
    lead = abs(c[-1])
    return 1 + max((abs(a) / lead for a in c[:-1]), default=Q(0))


def isolate(p, a=None, b=None, width=None) -> list[tuple[flint.fmpq, flint.fmpq]]:
    """Isolating intervals (lo, hi) of the distinct real roots of p in the open
    interval ]a, b[, increasing.  Each interval holds exactly one root; lo == hi
    means the root is that rational; otherwise the root lies in ]lo, hi[ and p
    does not vanish at lo or hi.  ``width`` refines each interval below it.
    ValueError when a ≥ b (an empty or reversed interval: a caller's mistake; the
    bisection would never end)."""
    p = flint.fmpq_poly(p)
    seq = sturm_sequence(p)
    p0 = seq[0]
    bound = cauchy_bound(p0)
    a = None if a is None else to_fmpq(a)
    b = None if b is None else to_fmpq(b)
    if a is not None and b is not None and not a < b:
        raise ValueError(f"isolate: the interval ]{a}, {b}[ is empty or reversed (a ≥ b)")
    # an omitted end: beyond every root (all lie in ]-bound, bound[) and beyond the other end
    a = a if a is not None else -bound if b is None else min(-bound, b - 1)
    b = b if b is not None else max(bound, a + 1)
    out = []
    # roots exactly at b are excluded (open interval): count in ]a, b] minus root at b
    stack = [(a, b)]
    while stack:
        lo, hi = stack.pop()
        n = count_roots(p0, lo, hi, seq) - (1 if p0(hi) == 0 else 0)
        if n == 0:
            continue
        if n == 1 and p0(hi) != 0 and p0(lo) != 0:
            out.append((lo, hi))
            continue
        mid = (lo + hi) / 2
        if p0(mid) == 0 and lo < mid < hi:
            out.append((mid, mid))
        stack.append((lo, mid))
        stack.append((mid, hi))
    # a root at a itself is not in ]a, b[, and count_roots excludes it already
    out = sorted(set(out), key=lambda iv: iv[0])
    if width is not None:
        out = [refine(p0, lo, hi, width) for lo, hi in out]
    return out


def refine(p, lo, hi, width) -> tuple[flint.fmpq, flint.fmpq]:
    """Bisect an isolating interval of a simple root of p until hi - lo <= width."""
    p = flint.fmpq_poly(p)
    lo, hi, width = to_fmpq(lo), to_fmpq(hi), to_fmpq(width)
    if lo == hi:
        return lo, hi
    slo = sign_at_rational(p, lo)
    while hi - lo > width:
        mid = (lo + hi) / 2
        sm = sign_at_rational(p, mid)
        if sm == 0:
            return mid, mid
        if sm == slo:
            lo = mid
        else:
            hi = mid
    return lo, hi


def flint_real_roots(p, a=None, b=None) -> list[flint.arb]:
    """Second route: python-flint's certified complex root isolation, keeping the
    roots it proves real (imaginary part exactly zero) inside ]a, b[ (the ball
    must lie strictly inside, else ValueError: undecided), increasing: ordered by
    the exact rational ends of the balls (ValueError when two balls overlap)."""
    P = squarefree_part(primitive(flint.fmpq_poly(p)))
    out = []
    roots: list[tuple[flint.acb, int]] = complex_roots(P)  # type: ignore[assignment]  # stub says list[acb]; it returns (acb, multiplicity) pairs
    for c, _m in roots:
        if not c.imag.is_zero():
            continue
        x = c.real
        inside_a = a is None or x > to_fmpq(a)
        inside_b = b is None or x < to_fmpq(b)
        outside = (a is not None and x < to_fmpq(a)) or (b is not None and x > to_fmpq(b))
        if inside_a and inside_b:
            out.append(x)
        elif not outside:
            raise ValueError(f"root {x} not separated from the interval ends")
    increasing = ordered(out)
    if increasing is None:
        raise ValueError("two real root balls overlap: their order is undecided")
    return increasing
