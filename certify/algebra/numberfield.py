"""Exact arithmetic in Q(α)[λ] for a real algebraic α, and the real roots there.

At a critical value r = α two eigenvalue branches may collide; cp(λ; α) is then
made squarefree exactly — Euclid's algorithm in Q(α)[λ], Q(α) = Q[r]/(m), m the minimal
polynomial of α — before its roots are enclosed by certified balls (python-flint's
acb root isolation).  Elements of Q(α) are python-flint ``fmpq_poly`` in r reduced
modulo m (inverses by the extended Euclid algorithm, ``xgcd``; a gcd is made monic modulo
primes, each result checked exactly: :func:`monic`); an element of Q(α)[λ] is the list of
its coefficients, highest first.
"""
from __future__ import annotations

import functools

import flint
import sympy as sp
from sympy.polys.rings import PolyElement

from .algebraic import Algebraic
from .balls import GUARD, ordered, precision
from .poly import Q, expr, lam, r, ring_terms


def modulus(alpha: Algebraic) -> flint.fmpq_poly:
    """The minimal polynomial of α (r - α for a rational α) as an fmpq_poly in r."""
    if alpha.is_rational:
        return flint.fmpq_poly([-alpha.lo, 1])
    return flint.fmpq_poly(alpha.minimal_polynomial())


def reduce(c, m: flint.fmpq_poly) -> flint.fmpq_poly:
    """An element of Q(α) in normal form."""
    return flint.fmpq_poly(c) % m


def kpoly(e, m: flint.fmpq_poly) -> list[flint.fmpq_poly]:
    """A polynomial in λ over Q[r] as an element of Q(α)[λ] (coefficients highest first):
    a SymPy expression, a text, or an element of Q[λ, r, x, u, v, s] (``poly.RING``)
    free of x, u, v, s, read term by term without going through an expression."""
    if isinstance(e, PolyElement):
        terms = [(i, j, c) for c, j, i in ring_terms(e)]
    else:
        terms = [(i, j, Q(int(sp.numer(c)), int(sp.denom(c)))) for (i, j), c in sp.Poly(expr(e), lam, r).terms()]
    degree = max((i for i, _j, _c in terms), default=0)
    coeffs: list[dict[int, flint.fmpq]] = [dict() for _ in range(degree + 1)]
    for i, j, c in terms:
        coeffs[degree - i][j] = c
    return _strip([reduce(_from_dict(d), m) for d in coeffs])


def _from_dict(d: dict) -> flint.fmpq_poly:
    """The polynomial Σ d[j] r^j."""
    out = [Q(0)] * (max(d, default=0) + 1)
    for j, c in d.items():
        out[j] = c
    return flint.fmpq_poly(out)


def _strip(p):
    while p and p[0].is_zero():
        p = p[1:]
    return p


def monic(p, m):
    """p ∈ Q(α)[λ] divided by its leading coefficient: the quotients c / p[0] in Q(α) by
    :func:`_monic_modular` (their images modulo primes, lifted, then checked exactly), else by an
    inverse of p[0] in Q(α) (xgcd in Q[r]).  The same polynomial either way (a monic polynomial of
    Q(α)[λ] with the roots of p is unique)."""
    lifted = _monic_modular(p, m)
    if lifted is not None:
        return lifted
    g, inv, _ = p[0].xgcd(m)          # g = inv·p[0] + _·m, g monic
    if g != 1:
        raise ZeroDivisionError(f"{p[0]} is not invertible modulo {m}")
    return [reduce(c * inv, m) for c in p]


MODULAR_PRIMES = 1024    # the most primes :func:`_monic_modular` lifts from before the xgcd route


@functools.cache
def _primes() -> list[int]:
    """The 2·:data:`MODULAR_PRIMES` largest primes below 2⁶² (SymPy's ``prevprime``), largest first: the
    moduli of :func:`_monic_modular` (0.1 s, once)."""
    out = [sp.prevprime(1 << 62)]
    while len(out) < 2 * MODULAR_PRIMES:
        out.append(sp.prevprime(out[-1]))
    return out


def _image(c: flint.fmpq_poly, P: int) -> flint.nmod_poly | None:
    """c modulo the prime P (None when P divides its denominator)."""
    d = int(c.denom()) % P
    if d == 0:
        return None
    return flint.nmod_poly(c.numer(), P) * pow(d, -1, P)


def _rational(a: int, M: int) -> flint.fmpq | None:
    """The fraction u/v with u ≡ a·v modulo M and |u|, v ≤ √(M/2) (Wang's rational reconstruction,
    unique when it exists), or None."""
    bound = int(flint.fmpz(M // 2).isqrt())
    r0, r1, t0, t1 = M, a % M, 0, 1
    while r1 > bound:
        q = r0 // r1
        r0, r1, t0, t1 = r1, r0 - q * r1, t1, t0 - q * t1
    if t1 == 0 or abs(t1) > bound:
        return None
    return flint.fmpq(r1, t1) if t1 > 0 else flint.fmpq(-r1, -t1)


def _monic_modular(p, m) -> list[flint.fmpq_poly] | None:
    """[1, p[1]/p[0], ...] in Q(α)[λ], or None where this route gives up.  Each quotient q is found
    modulo primes P (an inverse in GF(P)[r]/(m)), its coefficients lifted by the Chinese remainder
    theorem and read as fractions (:func:`_lift`) after 2, 4, 8, ... primes.  A lift that agrees
    with the quotients modulo the next prime is checked exactly, and returned only when p[0]·q ≡ p[i]
    modulo m holds in Q[r] for every i, which makes it the quotient.  The gcds of pseudo-remainders it
    is called on have leading coefficients of 10⁵ digits and quotients of 10³: xgcd over Q pays for the
    first, this route for the second (100× faster)."""
    d, rows, M, used, lifted = m.degree(), [[0] * m.degree() for _ in p[1:]], 1, 0, None
    for P in _primes():
        if used >= MODULAR_PRIMES and lifted is None:
            break
        quotients = _quotients_modulo(p, m, P)
        if quotients is None:
            continue
        if lifted is not None:
            if [_image(q, P) for q in lifted] == quotients and \
                    all(((p[0] * q - c) % m).is_zero() for q, c in zip(lifted, p[1:])):
                return [flint.fmpq_poly(1)] + lifted
            lifted = None
        step = pow(M % P, -1, P)
        for row, q in zip(rows, quotients):
            residues = [int(x) for x in q.coeffs()] + [0] * d
            for j in range(d):
                row[j] += M * ((residues[j] - row[j]) * step % P)
        M, used = M * P, used + 1
        if used & (used - 1) == 0 and used > 1:
            lifted = _lift(rows, M)
    return None


def _quotients_modulo(p, m, P: int) -> list[flint.nmod_poly] | None:
    """p[i]/p[0] in GF(P)[r]/(m) for i ≥ 1, or None when P divides a denominator or m's leading
    coefficient, or p[0] is not invertible modulo (m, P)."""
    images = []
    for c in [m, *p]:
        image = _image(c, P)
        if image is None:
            return None
        images.append(image)
    mP, lead, rest = images[0], images[1], images[2:]
    if mP.degree() != m.degree():
        return None
    g, s, _ = lead.xgcd(mP)
    if g.degree() != 0:
        return None
    s = s * pow(int(g[0]), -1, P)
    return [c * s % mP for c in rest]


def _lift(rows: list[list[int]], M: int) -> list[flint.fmpq_poly] | None:
    """The polynomials whose coefficients are fractions read in ``rows`` (residues modulo M), or None
    when one is not read.  The coefficients of an element of Q(α) share most of their denominator: each
    residue times the denominator D found so far is read as an integer over D when it is small (at most
    √(M/2) in absolute value), else as a fraction (:func:`_rational`) whose denominator joins D.  Any
    reading is only a candidate: :func:`_monic_modular` checks it exactly."""
    bound = int(flint.fmpz(M // 2).isqrt())
    out, D = [], 1
    for row in rows:
        coeffs = []
        for x in row:
            y = x * D % M
            y = y - M if y > M // 2 else y
            if abs(y) <= bound:
                coeffs.append(flint.fmpq(y, D))
                continue
            c = _rational(y, M)
            if c is None or D * int(c.q) > bound:
                return None
            coeffs.append(flint.fmpq(int(c.p), int(c.q) * D))
            D *= int(c.q)
        out.append(flint.fmpq_poly(coeffs))
    return out


def gcd(f, g, m, make_monic: bool = True) -> list[flint.fmpq_poly]:
    """The monic gcd in Q(α)[λ] (m irreducible, so Q(α) is a field).  Euclid by
    pseudo-remainders (f <- lc(g) f - lc(f) λ^k g: no inverse in Q(α), which costs an
    extended gcd in Q[r] each), each remainder scaled by a rational to keep its
    numbers small; one inverse at the end, none when the gcd is a constant (1).  (Without
    that inverse the roots are the same, but their enclosures from a non-monic gcd left a zero
    test undecided on r = 0.173's 122-letter attractor.)  ``make_monic=False``: that gcd
    before the inverse (a multiple of the monic one by a unit of Q(α): the same roots)."""
    f, g = _strip(f), _strip(g)
    while g:
        a = g[0]
        while len(f) >= len(g):
            q = f[0]
            shifted = g + [flint.fmpq_poly(0)] * (len(f) - len(g))
            f = _strip([reduce(a * x - q * b, m) for x, b in zip(f, shifted)])
            if f:
                lead = f[0][f[0].degree()]
                f = [c / lead for c in f]
        f, g = g, f
    if not f:
        return f
    if len(f) == 1:
        return [flint.fmpq_poly(1)]
    return monic(f, m) if make_monic else f


def squarefree_quadratic(f, m) -> bool:
    """Whether a f = aλ² + bλ + c ∈ Q(α)[λ] (a ≠ 0) has two distinct roots: b² - 4ac ≠ 0
    in Q(α), exactly (no inverse)."""
    a, b, c = f
    return not reduce(b * b - 4 * a * c, m).is_zero()


def divide(f, g, m) -> list[flint.fmpq_poly]:
    """The exact quotient f / g in Q(α)[λ], g monic."""
    f, out = list(f), []
    while len(f) >= len(g):
        q = f[0]
        out.append(q)
        shifted = g + [flint.fmpq_poly(0)] * (len(f) - len(g))
        f = [reduce(a - q * b, m) for a, b in zip(f, shifted)][1:]
    return out


def divides(g, f, m) -> bool | None:
    """Whether g divides f in Q(α)[λ], exactly, for g with a rational leading coefficient
    (no inverse in Q(α) needed); None when g's leading coefficient is not rational."""
    g = _strip(g)
    if not g or g[0].degree() > 0:
        return None
    lead = g[0][0]
    g = [c / lead for c in g]
    f = _strip(list(f))
    while len(f) >= len(g):
        q = f[0]
        shifted = g + [flint.fmpq_poly(0)] * (len(f) - len(g))
        f = _strip([reduce(a - q * b, m) for a, b in zip(f, shifted)][1:])
    return not f


def derivative(f, m) -> list[flint.fmpq_poly]:
    n = len(f) - 1
    return _strip([reduce(c * (n - i), m) for i, c in enumerate(f[:-1])])


def squarefree(f, m) -> tuple[list[flint.fmpq_poly], list[flint.fmpq_poly]]:
    """(f / gcd(f, f'), gcd(f, f')) in Q(α)[λ]."""
    g = gcd(f, derivative(f, m), m)
    return (divide(f, g, m) if len(g) > 1 else f), g


def arb_of(c: flint.fmpq_poly, R: flint.arb) -> flint.arb:
    """An element of Q(α) evaluated at a ball around α (its terms from the highest).  Each coefficient
    is the ball of n_k / D (c's numerators over their common denominator), a quotient of exact balls:
    the ball of the reduced fraction bit for bit (both are the quotient rounded once at the working
    precision), without the gcd of every n_k with D that reading the fractions costs (5 ms each at
    10⁵ bits: most of the census's slowest words' time)."""
    val = flint.arb(0)
    numer, D = c.numer().coeffs(), flint.arb(c.denom())
    for k in range(len(numer) - 1, -1, -1):
        if numer[k] != 0:
            val += flint.arb(numer[k]) / D * R ** k
    return val


def evaluate(f, R: flint.arb, z: flint.arb) -> flint.arb:
    """f(z) for f in Q(α)[λ], at a ball R around α."""
    val = flint.arb(0)
    for c in f:
        val = val * z + arb_of(c, R)
    return val


def root_balls(f, alpha: Algebraic, prec: int):
    """Certified complex balls around all the roots of a squarefree f ∈ Q(α)[λ], one per
    root (python-flint's acb root isolation); None when they cannot be isolated at this
    precision."""
    try:
        with precision(prec + GUARD):
            R = alpha.arb(prec)
            poly = flint.acb_poly([flint.acb(arb_of(c, R)) for c in f][::-1])
            try:
                return poly.roots(tol=flint.arb(2) ** -(prec // 2))
            except ValueError:
                return poly.roots()
    except ValueError:
        return None


def real_roots(f, alpha: Algebraic, prec: int):
    """Certified balls around the real roots of a squarefree f ∈ Q(α)[λ], largest first
    (the order decided on the exact rational ends of the balls, so that the upper,
    middle and lower branches are named right however close they are); None when
    python-flint cannot isolate or order them at this precision.  A root ball is
    real when it meets its own conjugate and no other root ball does."""
    try:
        with precision(prec + GUARD):
            R = alpha.arb(prec)
            poly = flint.acb_poly([flint.acb(arb_of(c, R)) for c in f][::-1])
            try:
                # refined with the precision: roots() alone stops at the first isolation
                # (32-bit balls, radius ~1e-9, whatever the precision)
                roots = poly.roots(tol=flint.arb(2) ** -(prec // 2))
            except ValueError:
                roots = poly.roots()
            reals = []
            for i, z in enumerate(roots):
                if z.imag > 0 or z.imag < 0:
                    continue
                # at the working precision: conjugate() rounds to it (at the default 53 bits
                # the conjugates of roots closer than 1e-16 would all overlap)
                conj = z.conjugate()
                if any(j != i and w.overlaps(conj) for j, w in enumerate(roots)) or not z.overlaps(conj):
                    return None
                reals.append(z.real)
    except ValueError:
        return None
    return ordered(reals, reverse=True)
