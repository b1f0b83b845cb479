"""Exact arithmetic in Q(α)[λ] for a real algebraic α, and the real roots there.

At a critical value r = α two eigenvalue branches may collide; cp(λ; α) is then
made squarefree exactly — Euclid's algorithm in K[λ], K = Q[r]/(m), m the minimal
polynomial of α — before its roots are enclosed by certified balls (python-flint's
acb root isolation).  Elements of K are SymPy polynomials in r reduced modulo m.
"""
from __future__ import annotations

import flint
import sympy as sp

from .algebraic import Algebraic
from .balls import GUARD, ordered, precision
from .poly import expr, lam, r

Q = flint.fmpq


def modulus(alpha: Algebraic) -> sp.Poly:
    """The minimal polynomial of α (r - α for a rational α) as a SymPy Poly in r."""
    if alpha.is_rational:
        return sp.Poly(r - sp.Rational(int(alpha.lo.p), int(alpha.lo.q)), r)
    m = alpha.minimal_polynomial()
    return sp.Poly(sum(sp.Integer(int(c)) * r ** k for k, c in enumerate(m.coeffs())), r)


def reduce(c, m: sp.Poly) -> sp.Poly:
    """An element of K in normal form."""
    return sp.Poly(c, r).rem(m)


def kpoly(e, m: sp.Poly) -> list[sp.Poly]:
    """A polynomial in λ over Q[r] as an element of K[λ] (coefficients highest first)."""
    return _strip([reduce(c, m) for c in sp.Poly(expr(e), lam).all_coeffs()])


def _strip(p):
    while p and p[0].is_zero:
        p = p[1:]
    return p


def _monic(p, m):
    inv = sp.Poly(sp.invert(p[0].as_expr(), m.as_expr(), r), r)
    return [reduce((c * inv).as_expr(), m) for c in p]


def gcd(f, g, m) -> list[sp.Poly]:
    """The monic gcd in K[λ] (m irreducible, so K is a field)."""
    f, g = _strip(f), _strip(g)
    while g:
        g = _monic(g, m)
        while len(f) >= len(g):
            q = f[0]
            shifted = g + [sp.Poly(0, r)] * (len(f) - len(g))
            f = _strip([reduce((a - q * b).as_expr(), m) for a, b in zip(f, shifted)])
        f, g = g, f
    return _monic(f, m) if f else f


def divide(f, g, m) -> list[sp.Poly]:
    """The exact quotient f / g in K[λ], g monic."""
    f, out = list(f), []
    while len(f) >= len(g):
        q = f[0]
        out.append(q)
        shifted = g + [sp.Poly(0, r)] * (len(f) - len(g))
        f = [reduce((a - q * b).as_expr(), m) for a, b in zip(f, shifted)][1:]
    return out


def derivative(f, m) -> list[sp.Poly]:
    n = len(f) - 1
    return _strip([reduce((c * (n - i)).as_expr(), m) for i, c in enumerate(f[:-1])])


def squarefree(f, m) -> tuple[list[sp.Poly], list[sp.Poly]]:
    """(f / gcd(f, f'), gcd(f, f')) in K[λ]."""
    g = gcd(f, derivative(f, m), m)
    return (divide(f, g, m) if len(g) > 1 else f), g


def arb_of(c: sp.Poly, R: flint.arb) -> flint.arb:
    """An element of K evaluated at a ball around α."""
    val = flint.arb(0)
    for (k,), co in c.terms():
        val += flint.arb(Q(int(sp.numer(co)), int(sp.denom(co)))) * R ** k
    return val


def evaluate(f, R: flint.arb, z: flint.arb) -> flint.arb:
    """f(z) for f in K[λ], at a ball R around α."""
    val = flint.arb(0)
    for c in f:
        val = val * z + arb_of(c, R)
    return val


def real_roots(f, alpha: Algebraic, prec: int):
    """Certified balls around the real roots of a squarefree f ∈ K[λ], largest first
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
