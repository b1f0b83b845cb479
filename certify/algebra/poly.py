"""Polynomials over Q: the paper's notation in, python-flint out.

Printed formulas are transcribed as text (``"41*r**10 - 646*r**9 + ..."``) and
parsed by SymPy with the paper's names: ``r`` the restitution coefficient, ``λ``
(or ``lam``) the eigenvalue, ``x`` the position fixed point, ``u``, ``v``.
Heavy arithmetic (Sturm sequences, resultants, root isolation) runs on
python-flint's ``fmpz_poly``/``fmpq_poly`` and ``fmpz_mpoly``.
"""
from __future__ import annotations

import math
from fractions import Fraction
from functools import reduce

import flint
import sympy as sp
from flint.utils.flint_exceptions import DomainError
from sympy.polys.fields import FracElement, field
from sympy.polys.orderings import lex
from sympy.polys.rings import PolyElement

from certify import caches

from . import printing

Q = flint.fmpq                 # an exact rational: Q(3, 7), Q(1, 2) (the one name of python-flint's fmpq)

r, lam, x, u, v, s = sp.symbols("r λ x u v s")

# Q(λ, r, x, u, v, s) as sparse rational functions (SymPy's polys), λ first in lex
# order, so that division by a cp monic in λ is the remainder in λ over Q(r).
FIELD, Lf, Rf, Xf, Uf, Vf, Sf = field("λ,r,x,u,v,s", sp.QQ, lex)
RING = FIELD.ring
caches.register(sp.core.cache.clear_cache)  # SymPy's own memo of expressions

NAMES = {"r": r, "λ": lam, "lam": lam, "lambda": lam, "la": lam, "x": x, "u": u, "v": v}


def parse(text: str, names: dict | None = None) -> sp.Expr:
    """A formula transcribed from the paper, as a SymPy expression (exact); ``names``
    adds local names (functions, vectors) to the paper's (see :mod:`certify.algebra.trig`).
    With the paper's names only, memoised for the run (the same formula is read by many
    claims; a SymPy expression is immutable)."""
    if names:
        return _parse(text, names)
    return _parse_paper(text)


def _parse(text: str, names: dict | None) -> sp.Expr:
    text = text.replace("λ", "lam").replace("^", "**").replace("−", "-")
    return sp.sympify(text, locals={**NAMES, **names} if names else NAMES, rational=True)


@caches.for_a_run
def _parse_paper(text: str) -> sp.Expr:
    return _parse(text, None)


def expr(e) -> sp.Expr:
    """Accept a string (parsed) or a SymPy expression."""
    return parse(e) if isinstance(e, str) else sp.sympify(e)


def to_fmpq(a) -> flint.fmpq:
    """An exact rational from int, Fraction, SymPy Rational, str or fmpq."""
    if isinstance(a, flint.fmpq):
        return a
    if isinstance(a, (int, flint.fmpz)):
        return flint.fmpq(a)
    if isinstance(a, str):
        a = Fraction(a)
    if isinstance(a, Fraction):
        return flint.fmpq(a.numerator, a.denominator)
    a = sp.Rational(a)
    return flint.fmpq(int(a.p), int(a.q))


def to_fmpq_poly(e, var=r) -> flint.fmpq_poly:
    """A univariate polynomial with rational coefficients as ``fmpq_poly`` (a product or
    power of polynomials multiplied out by python-flint, not expanded by SymPy)."""
    e = expr(e)
    p = _flint_tree(e, var)
    if p is not None:
        return p
    coeffs = sp.Poly(e, var).all_coeffs()[::-1]
    return flint.fmpq_poly([flint.fmpq(int(sp.numer(c)), int(sp.denom(c))) for c in coeffs])


def _flint_tree(e: sp.Expr, var) -> flint.fmpq_poly | None:
    """``e`` built from rationals and ``var`` by +, × and natural powers, as ``fmpq_poly``;
    None for anything else (another symbol, a fraction of polynomials, a function)."""
    if e.is_Rational:
        return flint.fmpq_poly([flint.fmpq(int(e.p), int(e.q))])
    if e.is_Symbol:
        return flint.fmpq_poly([0, 1]) if e == var else None
    if e.is_Add or e.is_Mul:
        found = [_flint_tree(a, var) for a in e.args]
        parts = [q for q in found if q is not None]
        if len(parts) < len(found):
            return None
        return reduce(lambda a, b: a + b, parts) if e.is_Add else reduce(lambda a, b: a * b, parts)
    if e.is_Pow and e.exp.is_Integer and e.exp >= 0:
        base = _flint_tree(e.base, var)
        return None if base is None else base ** int(e.exp)
    return None


def primitive(p) -> flint.fmpz_poly:
    """The primitive integer polynomial proportional to ``p`` (positive leading coefficient)."""
    if isinstance(p, flint.fmpz_poly):
        q = p
    else:
        # the numerator of the canonical fmpq_poly: p times the lcm of its denominators
        q = flint.fmpq_poly(p).numer()
    if q.is_zero():
        return q
    q = q / q.content()                 # exact division (python-flint)
    if q.leading_coefficient() < 0:
        q = -q
    return q


def divides(p, q) -> bool:
    """p divides q in Q[r] (exact division over Q)."""
    return (flint.fmpq_poly(q) % flint.fmpq_poly(p)).is_zero()


def same_up_to_constant(p, q) -> bool:
    """p = k q for a non-zero rational k (both univariate over Q, as flint polynomials)."""
    return primitive(p) == primitive(q)


def _lcm(values):
    out = flint.fmpz(1)
    for v_ in values:
        out = out.lcm(v_)
    return out


def to_fmpz_poly(e, var=r) -> flint.fmpz_poly:
    """The primitive integer polynomial proportional to a univariate ``e``."""
    if isinstance(e, (flint.fmpz_poly, flint.fmpq_poly)):
        return primitive(e)
    return primitive(to_fmpq_poly(e, var))


def from_flint(p, var=r) -> sp.Expr:
    """An ``fmpz_poly``/``fmpq_poly`` back as a SymPy expression in ``var``."""
    return sum((sp.Rational(int(c.p), int(c.q)) if isinstance(c, flint.fmpq) else sp.Integer(int(c))) * var**k
               for k, c in enumerate(p.coeffs()))


def squarefree_part(p: flint.fmpz_poly) -> flint.fmpz_poly:
    """The product of the distinct irreducible factors of ``p``."""
    _, factors = p.factor_squarefree()
    return primitive(reduce(lambda a, b: a * b, (f for f, _ in factors), flint.fmpz_poly([1])))


def poly_key(p) -> tuple:
    """A hashable key of a univariate polynomial over Q (fmpz_poly or fmpq_poly), a function
    of the polynomial alone: its integer numerator's coefficients and its denominator
    (python ints hash ten times faster than a tuple of fmpq)."""
    if isinstance(p, flint.fmpz_poly):
        return tuple(int(c) for c in p.coeffs()), 1
    p = flint.fmpq_poly(p)
    return tuple(int(c) for c in p.numer().coeffs()), int(p.denom())


def factor_order(fm) -> tuple:
    """The order of :func:`irreducible_factors`: by degree, then coefficients."""
    return fm[0].degree(), [int(c) for c in fm[0].coeffs()]


_FACTORS: dict = {}              # coefficients of p -> its irreducible factors
caches.register(_FACTORS.clear)


def irreducible_factors(p: flint.fmpz_poly) -> list[tuple[flint.fmpz_poly, int]]:
    """The irreducible factors of ``p`` over Q with multiplicities, primitive, sorted
    (memoised: the same discriminant and resultants recur in every sign table)."""
    key = poly_key(p)
    out = _FACTORS.get(key)
    if out is None:
        _, factors = p.factor()
        out = [(primitive(f), m) for f, m in factors if f.degree() > 0]
        out = _FACTORS[key] = sorted(out, key=factor_order)
        if len(_FACTORS) > 20000:
            _FACTORS.clear()
    return list(out)


_PRIME = 2 ** 61 - 1             # a word-size prime for the trial divisions of irreducible_factors_knowing


@caches.by_identity
def _mod_prime(f: flint.fmpz_poly) -> flint.nmod_poly:
    """f modulo the prime, memoised by identity (the known factors of a spectrum recur)."""
    return flint.nmod_poly(f.coeffs(), _PRIME)


def _multiplicity_mod_prime(pm, fm) -> tuple:
    """(m, pm / fm^m): the largest m with fm^m | pm in GF(p)[r] (nmod_poly), by divisions by
    fm, fm², fm⁴, ... and back down (about 2 log₂ m divisions, not m)."""
    q, rem = divmod(pm, fm)
    if not rem.is_zero():
        return 0, pm
    pm, m = q, 1
    powers = [(fm, 1)]
    while 2 * powers[-1][0].degree() <= pm.degree():
        powers.append((powers[-1][0] * powers[-1][0], 2 * powers[-1][1]))
    for pw, s in reversed(powers):
        while pm.degree() >= pw.degree():
            q, rem = divmod(pm, pw)
            if not rem.is_zero():
                break
            pm, m = q, m + s
    return m, pm


def irreducible_factors_knowing(p: flint.fmpz_poly, known: list) -> tuple[list, list]:
    """:func:`irreducible_factors` of ``p`` (the same factors, multiplicities and order) when
    ``known`` lists irreducible primitive polynomials (from python-flint's factorisations of
    other polynomials).  The multiplicity m_f of each known f is first read modulo a prime
    (an upper bound of the true one: f^m | p over Z gives it modulo the prime), then f^m_f
    is divided out of p exactly over Z (python-flint's exact division; where one is not
    exact the bound was too high, and p is factored whole instead).  When every division
    is exact, m_f is the true multiplicity (by induction along ``known``: the earlier ones
    took out exactly their own powers, so f's count modulo the prime is still at least its
    true one, and at most, f^m_f dividing p), and by unique factorisation in Z[r]
    the factors of p are the known f with m_f > 0 and those of the cofactor, the only
    polynomial python-flint factors.  Returns (factors, the factors not known before).

    >>> r2 = flint.fmpz_poly([1, -10, 1])                   # r² - 10r + 1
    >>> p = flint.fmpz_poly([0, 1]) ** 3 * r2 ** 2 * flint.fmpz_poly([-2, 0, 1])
    >>> irreducible_factors_knowing(p, [flint.fmpz_poly([0, 1]), r2]) == (irreducible_factors(p),
    ...                                                                    [flint.fmpz_poly([-2, 0, 1])])
    True"""
    pm = flint.nmod_poly(p.coeffs(), _PRIME)
    found = []
    for f in known:
        fm = _mod_prime(f)
        if fm.degree() != f.degree() or fm.degree() > pm.degree():
            continue                         # (a leading coefficient divisible by the prime: not stripped)
        m, pm = _multiplicity_mod_prime(pm, fm)
        if m:
            found.append((f, m))
    rest = p
    try:
        for f, m in found:
            rest = rest / f ** m             # exact division, or DomainError
    except DomainError:
        return _factored(p, known)
    new = _factored(rest, [])[0] if rest.degree() > 0 else []
    return sorted(found + new, key=factor_order), [f for f, _m in new]


def _factored(p: flint.fmpz_poly, known: list) -> tuple[list, list]:
    """(python-flint's factors of p, primitive, sorted, each the very object of ``known``
    where it is one of them; the others)."""
    _, factors = p.factor()
    out = []
    for f, m in factors:
        if f.degree() > 0:
            f = primitive(f)
            out.append((next((k for k in known if k == f), f), m))
    out.sort(key=factor_order)
    return out, [f for f, _m in out if not any(f is k for k in known)]


def _show_integer_poly(p: flint.fmpz_poly) -> str:
    """:func:`show` of an integer polynomial in r, written directly (the very text SymPy's
    printer gives, descending powers, without building an expression)."""
    out: list[str] = []
    for k in range(p.degree(), -1, -1):
        c = int(p[k])
        if c == 0:
            continue
        mono = "" if k == 0 else "r" if k == 1 else f"r^{k}"
        body = str(abs(c)) if k == 0 else mono if abs(c) == 1 else f"{abs(c)}{mono}"
        out.append(("-" if c < 0 else "") + body if not out else (" - " if c < 0 else " + ") + body)
    return "".join(out) or "0"


def show(e) -> str:
    """A polynomial in the paper's notation (``r^2 - 10r + 1``) for reports: SymPy's
    ``sstr(e, order="lex")`` with ``^`` for ``**`` and no ``*`` (a polynomial of the engine's
    ring written directly, :mod:`.printing`, the very text)."""
    if isinstance(e, flint.fmpq_poly) and e.denom() == 1:
        e = e.numer()
    if isinstance(e, flint.fmpz_poly):
        return _show_integer_poly(e)
    if isinstance(e, flint.fmpq_poly):
        e = from_flint(e)
    if isinstance(e, PolyElement) and e.ring is RING:
        return notation(printing.expanded(*printing.ring_terms(e)))
    if isinstance(e, (PolyElement, FracElement)):
        e = e.as_expr()
    return notation(sp.sstr(sp.sympify(e), order="lex"))


def notation(text: str) -> str:
    """SymPy's printed text in the paper's notation: ``^`` for ``**``, no ``*``."""
    return text.replace("**", "^").replace("*", "")


def show_factored(p) -> str:
    """:func:`show` of ``sp.factor(p)`` for a polynomial in r over Q (fmpz_poly or fmpq_poly;
    ``certify.dynamics.model.factor_flint(p)`` is that expression), written directly by
    python-flint's factorisation (:func:`.printing.factored_univariate`).

    >>> show_factored(flint.fmpq_poly([-1, 0, 1]) * flint.fmpq_poly([1, 1]) / 4)     # (r² - 1)(r + 1)/4
    '(r - 1)(r + 1)^2/4'
    >>> show_factored(flint.fmpq_poly([-1, 10, -1]))                                  # -(r² - 10r + 1)
    '-r^2 + 10r - 1'
    """
    return notation(printing.factored_univariate(p))


def show_collected(p: PolyElement, var: str = "λ") -> str:
    """:func:`show` of ``sp.collect(p, var)`` for a polynomial of the engine's ring, written
    directly (:func:`.printing.collected`).

    >>> show_collected(to_ring("lam^2 - (r^2 + 1)*lam - r/2 + 3"))
    '-r/2 + λ^2 + λ(-r^2 - 1) + 3'
    """
    names, terms = printing.ring_terms(p)
    return notation(printing.collected(names, terms, var) if var in names else printing.expanded(names, terms))


# --- polynomials in (r, λ, s) on fmpz_mpoly: resultants and discriminants -------

MCTX = flint.fmpz_mpoly_ctx.get(("r", "lam", "s"), "lex")


def to_mpoly(e) -> flint.fmpz_mpoly:
    """An integer polynomial in r, λ (and s) as ``fmpz_mpoly``; rational input is cleared
    of denominators (a positive constant multiple, so signs are kept)."""
    if isinstance(e, PolyElement):
        return ring_to_mpoly(e)
    e = expr(e)
    pair = _ring_pair(e)          # multiplied out in RING; SymPy's Poly only for what that does not read
    if pair is not None and pair[1].is_ground and not any(m[2] or m[3] or m[4] for m in pair[0].monoms()):
        return ring_to_mpoly(pair[0] * (1 / pair[1].LC))
    P = sp.Poly(e, r, lam, s)
    den = _lcm([int(sp.denom(c)) for c in P.coeffs()] or [1])
    terms = {m: int(c * int(den)) for m, c in P.terms()}
    return MCTX.from_dict(terms)


def mpoly_to_univariate(p: flint.fmpz_mpoly) -> flint.fmpz_poly:
    """An ``fmpz_mpoly`` in r alone as ``fmpz_poly``."""
    d = p.to_dict()
    deg = max((m[0] for m in d), default=0)
    coeffs = [0] * (deg + 1)
    for m, c in d.items():
        if m[1] or m[2]:
            raise ValueError("polynomial still depends on λ or s")
        coeffs[m[0]] = int(c)
    return flint.fmpz_poly(coeffs)


def resultant_lambda(f, g) -> flint.fmpz_poly:
    """Res_λ(f, g) ∈ Z[r] by python-flint (f, g integer polynomials in r, λ)."""
    return mpoly_to_univariate(to_mpoly(f).resultant(to_mpoly(g), "lam"))


def discriminant_lambda(f) -> flint.fmpz_poly:
    """Disc_λ(f) ∈ Z[r] by python-flint."""
    return mpoly_to_univariate(to_mpoly(f).discriminant("lam"))


# --- sparse rational functions in the paper's variables --------------------------

def to_field(e) -> FracElement:
    """An element of Q(λ, r, x, u, v, s) (from a SymPy expression, text or itself)."""
    if isinstance(e, FracElement):
        return e
    if isinstance(e, PolyElement):
        return FIELD(e)
    return _field_of(e if isinstance(e, (str, sp.Basic)) else expr(e))


@caches.for_a_run
def _field_of(e) -> FracElement:
    """:func:`to_field` of a text or SymPy expression, memoised for the run (the same
    formulas and matrix entries are converted by many claims)."""
    e = expr(e)
    pair = _ring_pair(e)
    if pair is None:
        return FIELD.from_expr(e)
    return FIELD.new(*pair)          # one cancellation: the canonical element, as from_expr gives it


_RING_GENS = dict(zip(FIELD.symbols, RING.gens))


def fraction_tree(e: sp.Expr, leaf, rational):
    """``e`` built from rationals and leaves by +, ×, integer powers, as (numerator, denominator),
    not canceled, in the ring where ``leaf(symbol)`` (None: not a leaf) and ``rational(q)`` (q a
    SymPy Rational) live; None for anything else, or for 0 to a negative power."""
    g = leaf(e)
    if g is not None:
        return g, rational(sp.S.One)
    if e.is_Rational:
        return rational(e), rational(sp.S.One)
    if e.is_Add or e.is_Mul:
        pairs = [fraction_tree(a, leaf, rational) for a in e.args]
        if any(pa is None for pa in pairs):
            return None
        num, den = pairs[0]
        for n, d in pairs[1:]:
            if e.is_Mul:
                num, den = num * n, den * d
            elif d == den:
                num = num + n
            else:
                num, den = num * d + n * den, den * d
        return num, den
    if e.is_Pow and e.exp.is_Integer:
        pb = fraction_tree(e.base, leaf, rational)
        if pb is None:
            return None
        k = int(e.exp)
        n, d = pb if k >= 0 else pb[::-1]
        if d == 0:
            return None
        return n ** abs(k), d ** abs(k)
    return None


def _ring_pair(e: sp.Expr) -> tuple[PolyElement, PolyElement] | None:
    """``e`` built from rationals and the field's symbols by +, ×, integer powers, as
    (numerator, denominator) in RING, not canceled (:func:`fraction_tree`); None otherwise."""
    return fraction_tree(e, _RING_GENS.get, lambda q: RING(sp.QQ(int(q.p), int(q.q))))


def to_ring(e) -> PolyElement:
    """A polynomial of Q[λ, r, x, u, v, s]; ValueError for a proper fraction."""
    if isinstance(e, PolyElement) and e.ring is RING:
        return e
    f = to_field(e)
    if f.denom != 1:
        if f.denom.is_ground:
            return f.numer * (1 / f.denom.LC)
        raise ValueError("not a polynomial")
    return f.numer


def coefficients_in(p: PolyElement, gen: PolyElement) -> dict[int, PolyElement]:
    """p as Σ p_k gen^k: {k: p_k}."""
    deg = p.degree(gen)
    return {k: p.coeff_wrt(gen, k) for k in range(max(deg, 0) + 1) if p.coeff_wrt(gen, k)}


def ring_to_mpoly(p: PolyElement) -> flint.fmpz_mpoly:
    """A polynomial in λ, r, s as ``fmpz_mpoly`` in (r, λ, s), times a positive integer
    clearing the denominators (signs are kept)."""
    den = _lcm([int(c.denominator) for c in p.values()] or [1])
    terms: dict[tuple[int, ...], int] = {}
    for (el, er, ex, eu, ev, es), c in p.terms():
        if ex or eu or ev:
            raise ValueError("polynomial still depends on x, u or v")
        terms[(er, el, es)] = int(c * int(den))
    return MCTX.from_dict(terms)


def mpoly_to_ring(p: flint.fmpz_mpoly) -> PolyElement:
    """An ``fmpz_mpoly`` in (r, λ, s) as an element of RING (the inverse of
    :func:`ring_to_mpoly` up to its positive factor)."""
    dom = RING.domain
    conv = flint.fmpq if dom.dtype is flint.fmpq else (lambda c: dom(int(c)))
    return RING.zero.new({(el, er, 0, 0, 0, es): conv(c) for (er, el, es), c in p.to_dict().items()})


def ring_terms(p: PolyElement) -> list[tuple[flint.fmpq, int, int]]:
    """The terms (coefficient, exponent of r, exponent of λ) of a polynomial in r, λ."""
    out = []
    for (el, er, ex, eu, ev, es), c in p.terms():
        if ex or eu or ev or es:
            raise ValueError("polynomial still depends on x, u, v or s")
        out.append((flint.fmpq(int(c.numerator), int(c.denominator)), er, el))
    return out


# --- Q(λ, r) on fmpz_mpoly: the fast field of the symbolic runs --------------------
#
# An element of K = Q(λ, r) as a pair (num, den) of fmpz_mpoly in (λ, r), lex, λ first
# (SymPy's FIELD order restricted to λ, r), always in the canonical form of SymPy's
# FracElement: num and den coprime over Z (contents included), den's leading
# coefficient positive.  So the conversion back to FIELD is exact and needs no gcd:
# ``to_field(Frac)`` gives the very numerator and denominator SymPy's cancel gives.

LRCTX = flint.fmpz_mpoly_ctx.get(("lam", "r"), "lex")
LRQCTX = flint.fmpq_mpoly_ctx.get(("lam", "r"), "lex")
_LR_ONE = LRCTX.from_dict({(0, 0): 1})
_LR_ZERO = LRCTX.from_dict({})


class Frac:
    """num/den ∈ Q(λ, r), fmpz_mpoly in (λ, r), canonical (see above)."""

    __slots__ = ("num", "den")

    def __init__(self, num, den=None, reduced: bool = False):
        if den is None:
            den = _LR_ONE
            reduced = True
        if not reduced:
            if num.is_zero():
                num, den = _LR_ZERO, _LR_ONE
            else:
                g = num.gcd(den)
                if not g.is_one():
                    num, den = num / g, den / g
                if den.leading_coefficient() < 0:
                    num, den = -num, -den
        self.num, self.den = num, den

    @staticmethod
    def of(a) -> Frac:
        if isinstance(a, Frac):
            return a
        if isinstance(a, (int, flint.fmpz)):
            return Frac(LRCTX.from_dict({(0, 0): a}) if a else _LR_ZERO)
        if isinstance(a, (Fraction, flint.fmpq)):
            a = flint.fmpq(a.numerator, a.denominator) if isinstance(a, Fraction) else a
            if a == 0:
                return Frac(_LR_ZERO)
            return Frac(LRCTX.from_dict({(0, 0): a.p}), LRCTX.from_dict({(0, 0): a.q}), True)
        return field_to_frac(to_field(a))

    def is_zero(self) -> bool:
        return self.num.is_zero()

    def __eq__(self, g):
        g = Frac.of(g)
        return self.num == g.num and self.den == g.den

    __hash__ = None  # type: ignore[assignment]  # unhashable on purpose; typeshed types object.__hash__ as a method

    def __neg__(self):
        return Frac(-self.num, self.den, True)

    def __add__(self, g):
        g = Frac.of(g)
        if self.num.is_zero():
            return g
        if g.num.is_zero():
            return self
        if self.den == g.den:
            return Frac(self.num + g.num, self.den)
        return _sum(self, g)

    __radd__ = __add__

    def __sub__(self, g):
        return self + (-Frac.of(g))

    def __rsub__(self, g):
        return Frac.of(g) + (-self)

    def __mul__(self, g):
        g = Frac.of(g)
        if self.num.is_zero() or g.num.is_zero():
            return Frac(_LR_ZERO)
        # cross cancellation keeps the products small
        g1, g2 = self.num.gcd(g.den), g.num.gcd(self.den)
        n1, d2 = (self.num / g1, g.den / g1) if not g1.is_one() else (self.num, g.den)
        n2, d1 = (g.num / g2, self.den / g2) if not g2.is_one() else (g.num, self.den)
        num, den = n1 * n2, d1 * d2
        if den.leading_coefficient() < 0:
            num, den = -num, -den
        return Frac(num, den, True)

    __rmul__ = __mul__

    def inverse(self):
        if self.num.is_zero():
            raise ZeroDivisionError("division by zero in Q(λ, r)")
        num, den = self.den, self.num
        if den.leading_coefficient() < 0:
            num, den = -num, -den
        return Frac(num, den, True)

    def __truediv__(self, g):
        return self * Frac.of(g).inverse()

    def __rtruediv__(self, g):
        return Frac.of(g) * self.inverse()


def _sum(a: Frac, b: Frac) -> Frac:
    """a + b for canonical a = n₁/d₁, b = n₂/d₂ with d₁ ≠ d₂, in canonical form, without the gcd
    of the whole numerator and denominator (Henrici): with h = gcd(d₁, d₂), d₁ = h e₁,
    d₂ = h e₂, t = n₁e₂ + n₂e₁ is coprime to e₁e₂ (t ≡ n₁e₂ mod e₁, gcd(n₁, e₁) = gcd(e₂, e₁) = 1;
    Z[λ, r] is a UFD, contents included), so gcd(t, h·e₁e₂) = gcd(t, h) = k and the sum is
    (t/k)/(e₁e₂·h/k): the pair the full gcd gives (coprime, the sign of den fixed)."""
    h = a.den.gcd(b.den)
    e1, e2 = (a.den, b.den) if h.is_one() else (a.den / h, b.den / h)
    t = a.num * e2 + b.num * e1
    if t.is_zero():
        return Frac(_LR_ZERO)
    if not h.is_one():
        k = t.gcd(h)
        if not k.is_one():
            t, h = t / k, h / k
    den = e1 * e2 * h
    if den.leading_coefficient() < 0:
        t, den = -t, -den
    return Frac(t, den, True)


def _lr_from_ring(p: PolyElement):
    """(integer fmpz_mpoly in (λ, r), integer scale) with p = poly/scale; p only in λ, r."""
    den = 1
    for c in p.values():
        q = int(c.denominator)
        if q != 1:
            den = den * q // math.gcd(den, q)
    terms: dict[tuple[int, ...], int] = {}
    for (el, er, ex, eu, ev, es), c in p.terms():
        if ex or eu or ev or es:
            raise ValueError("polynomial depends on x, u, v or s, not only on λ, r")
        terms[(el, er)] = int(c.numerator) * (den // int(c.denominator))
    return LRCTX.from_dict(terms), den


def ring_to_lrq(p: PolyElement) -> flint.fmpq_mpoly:
    """A polynomial of RING in λ, r only as fmpq_mpoly in (λ, r) (lex, λ first: the
    remainder of ``divmod`` by a polynomial monic in λ is the remainder in λ over Q[r])."""
    terms: dict[tuple[int, ...], flint.fmpq] = {}
    for (el, er, *rest), c in p.terms():
        if any(rest):
            raise ValueError("polynomial depends on x, u, v or s")
        terms[(el, er)] = flint.fmpq(c)
    return LRQCTX.from_dict(terms)


def field_to_frac(f) -> Frac:
    """An element of FIELD in λ, r only as :class:`Frac` (canonical)."""
    f = to_field(f)
    n, a = _lr_from_ring(f.numer)
    d, b = _lr_from_ring(f.denom)
    return Frac(n * b, d * a)


def lr_to_ring(p, scale=1) -> PolyElement:
    """An fmpz_mpoly/fmpq_mpoly in (λ, r), divided by ``scale``, as an element of RING."""
    dom = RING.domain
    # SymPy's QQ over python-flint holds fmpq itself: build them directly (no domain dispatch)
    conv = flint.fmpq if dom.dtype is flint.fmpq else dom
    # the terms read off monoms() and coeffs() (to_dict's items, in its order, without its
    # Python loop over the terms)
    if scale == 1:
        d = {(el, er, 0, 0, 0, 0): conv(c) for (el, er), c in zip(p.monoms(), p.coeffs())}
    else:
        s = flint.fmpq(scale)
        d = {(el, er, 0, 0, 0, 0): conv(flint.fmpq(c) / s) for (el, er), c in zip(p.monoms(), p.coeffs())}
    return RING.zero.new(d)


def frac_to_field(F: Frac) -> FracElement:
    """A canonical :class:`Frac` as the equal FracElement of FIELD, without a gcd."""
    return FIELD.raw_new(lr_to_ring(F.num), lr_to_ring(F.den))


def flint_poly_to_frac(p) -> Frac:
    """An fmpz_poly/fmpq_poly in r as :class:`Frac`."""
    if isinstance(p, flint.fmpq_poly):
        den = p.denom()
        num = p.numer()
    else:
        den, num = flint.fmpz(1), p
    terms: dict[tuple[int, ...], int] = {(0, k): int(c) for k, c in enumerate(num.coeffs()) if c}
    return Frac(LRCTX.from_dict(terms), LRCTX.from_dict({(0, 0): int(den)}))


LR_LAMBDA = Frac(LRCTX.gen(0))
LR_R = Frac(LRCTX.gen(1))
