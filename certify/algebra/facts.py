"""The engine's witnesses as data for the independent kernel (docs/verify.md): a strict sign by
inspection (:func:`signed`, built by :func:`certify.algebra.trig.signed_witness` for
:func:`certify.witnesses.witnessing`).  Polynomials become lists of terms with exact
coefficients, numbers "p/q" strings."""
from __future__ import annotations

from fractions import Fraction

import flint
import sympy as sp

from certify import caches

from .poly import fraction_tree


def rational(q) -> str:
    """A rational (fmpq, Fraction, SymPy Rational, int) as "p/q"."""
    kind = type(q)
    if kind is flint.fmpz:           # an integer coefficient (fmpz_poly, fmpz_mpoly): its digits
        return str(q)
    if kind is flint.fmpq or isinstance(q, sp.Rational):
        num, den = q.p, q.q          # lowest terms, den > 0: as each of these types keeps it
    elif isinstance(q, int):
        return str(int(q))
    elif kind is Fraction:
        num, den = q.numerator, q.denominator
    else:                            # anything else (fmpz, a numeral as text): as SymPy reads it
        q = sp.Rational(str(q))
        num, den = q.p, q.q
    return str(num) if den == 1 else f"{num}/{den}"


def rational_function(e, gens: list) -> dict:
    """A SymPy expression, a rational function of ``gens`` over Q, as {"num": terms, "den": terms}
    (a fresh copy of the one computed for the same expression and generators since the caches'
    last reset: the same witnesses are recorded over and over)."""
    try:
        key = (e, tuple(gens))
        found = _RATIONAL_FUNCTIONS.get(key)
    except TypeError:                # an unhashable expression: computed every time
        return _rational_function(e, gens)
    if found is None:
        found = _RATIONAL_FUNCTIONS[key] = _rational_function(e, gens)
    return {part: [[c, list(m)] for c, m in terms] for part, terms in found.items()}


_RATIONAL_FUNCTIONS: dict = {}
caches.register(_RATIONAL_FUNCTIONS.clear)


def _rational_function(e, gens: list) -> dict:
    e = sp.sympify(e)
    if gens and _integral(e):        # together leaves it whole over 1: the terms of e itself
        try:
            return {"num": polynomial_terms(e, gens), "den": [["1", [0] * len(gens)]]}
        except _NotPolynomial:
            pass
    if gens and _expanded_over_q(e):   # together clears the denominators: the terms of L·e over L
        try:
            return _cleared(e, gens)
        except _NotPolynomial:
            pass
    n, d = sp.fraction(sp.together(e))
    def terms(x):
        if not gens:
            return [[rational(sp.Rational(x)), []]] if x != 0 else []
        try:
            return polynomial_terms(x, gens)
        except _NotPolynomial:
            pass
        P = sp.Poly(sp.expand(x), *gens, domain="QQ")
        return sorted([rational(c), list(m)] for m, c in P.terms())
    return {"num": terms(n), "den": terms(d)}


def _expanded_over_q(e) -> bool:
    """e is a sum of terms c·m (or one term), c rational and m a product of natural powers of
    symbols and function atoms: a polynomial over Q written expanded (distinct monomials)."""
    for t in sp.Add.make_args(e):
        c, m = t.as_coeff_Mul()
        if not c.is_Rational:
            return False
        for f in sp.Mul.make_args(m):
            b, x = f.as_base_exp()
            if not ((b.is_Symbol or isinstance(b, sp.Function)) and x.is_Integer and x > 0) and f != 1:
                return False
    return True


def _cleared(e, gens: list) -> dict:
    """What ``sp.fraction(sp.together(e))`` gives for an expanded polynomial e over Q, as terms:
    together takes out the gcd of the terms, G/L times a monomial (G the gcd of the numerators
    and L the lcm of the denominators of the coefficients, G/L in lowest terms), and leaves a
    sum with integer coefficients; so the numerator is L·e and the denominator L."""
    P = _mpoly(e, gens)
    L = flint.fmpz(1)
    for c in P.coeffs():
        L = L.lcm(c.q)
    zeros = [0] * len(gens)
    return {"num": _terms(P * L, len(gens)), "den": [[rational(flint.fmpq(L)), zeros]]}


def _integral(e) -> bool:
    """e is written with integers, symbols, function atoms, sums, products and natural powers
    only (no fraction anywhere): ``sp.fraction(sp.together(e))`` is then (e, 1), up to the
    grouping of its terms."""
    todo = [e]
    while todo:
        x = todo.pop()
        if x.is_Rational:
            if not x.is_Integer:
                return False
        elif x.is_Pow:
            if not (x.exp.is_Integer and x.exp >= 0):
                return False
            todo.append(x.base)
        elif x.is_Add or x.is_Mul:
            todo.extend(x.args)
        elif not (x.is_Symbol or isinstance(x, sp.Function)):
            return False
    return True


class _NotPolynomial(ValueError):
    """Not a sum of products of rationals, ``gens`` and their powers, as read by :func:`polynomial_terms`."""


def polynomial_terms(x, gens: list) -> list:
    """The terms of the polynomial x in ``gens`` over Q as [["p/q", exponents], ...], sorted: what
    ``sp.Poly(sp.expand(x), *gens, domain="QQ").terms()`` gives (the zero polynomial as one term
    0), multiplied out in flint's fmpq_mpoly instead of SymPy's expand.  The terms of a polynomial
    are unique, so both give the same list.  _NotPolynomial for anything but rationals, ``gens``,
    sums, products and powers with a natural exponent (the caller then asks SymPy)."""
    return _terms(_mpoly(x, gens), len(gens))


def _mpoly(x, gens: list):
    """x as an fmpq_mpoly in ``gens`` (:func:`polynomial_terms`; _NotPolynomial otherwise)."""
    ctx = flint.fmpq_mpoly_ctx.get(tuple(f"x{k}" for k in range(len(gens))), "lex")
    zeros = (0,) * len(gens)
    found = fraction_tree(sp.sympify(x), dict(zip(gens, ctx.gens())).get,
                          lambda q: ctx.from_dict({zeros: flint.fmpq(int(q.p), int(q.q))}))
    if found is None or found[1].total_degree() > 0:
        raise _NotPolynomial(f"{x} is not read as a polynomial")
    return found[0] / found[1].coeffs()[0]


def _terms(P, n: int) -> list:
    """The terms of the fmpq_mpoly P in n generators as :func:`polynomial_terms` lists them."""
    if P == 0:
        return [["0", [0] * n]]
    return sorted([rational(c), [int(k) for k in m]] for m, c in zip(P.monoms(), P.coeffs()))


def _atoms(e) -> tuple[set, set, set]:
    """``e.atoms(sp.Function)``, ``e.atoms(sp.Pow)`` and the bare symbols of e (not Dummy) that
    occur outside its function atoms (the free symbols of e with each function atom replaced by
    a Dummy), in one walk of e in preorder (the order in which atoms() fills its sets)."""
    functions, powers, bare = set(), set(), set()
    todo = [(e, False)]
    while todo:
        x, inside = todo.pop()
        if isinstance(x, sp.Function):
            functions.add(x)
            inside = True
        elif x.is_Pow:
            powers.add(x)
        elif x.is_Symbol and not inside and not isinstance(x, sp.Dummy):
            bare.add(x)
        todo.extend((a, inside) for a in reversed(x.args))
    return functions, powers, bare


def generators(*exprs) -> tuple[list, list]:
    """The variables of expressions: their symbols, and cos, sin of a symbol that occurs only
    inside them; with the pairs (cos a, sin a).  ValueError when another function occurs (a
    square root, ...) or a symbol occurs both alone and inside cos, sin."""
    trig, symbols = set(), set()
    for e in map(sp.sympify, exprs):
        functions, powers, bare = _atoms(e)
        for f in functions:
            if f.func not in (sp.cos, sp.sin) or not f.args[0].is_Symbol:
                raise ValueError(f"the function {f} is outside Q[variables, cos, sin]")
            trig.add(f.args[0])
        for p in powers:
            if not p.exp.is_Integer:
                raise ValueError(f"a non-integer power {p}")
        symbols |= bare
    if symbols & trig:
        raise ValueError("a symbol occurs both alone and inside cos, sin")
    # the engine's own names for cos θ, sin θ (certify.algebra.trig): the symbols cosX, sinX
    named = {str(x)[3:] for x in symbols if str(x)[:3] in ("cos", "sin") and len(str(x)) > 3}
    symbols |= {sp.Symbol(f + a) for a in named for f in ("cos", "sin")}
    gens = sorted(symbols, key=str) + [f(a) for a in sorted(trig, key=str) for f in (sp.cos, sp.sin)]
    circles = [[str(sp.cos(a)), str(sp.sin(a))] for a in sorted(trig, key=str)]
    return gens, circles + [["cos" + a, "sin" + a] for a in sorted(named)]


def signed(E, n, d, parts: list, hyp: dict, total: int) -> dict:
    """E = n/d has the strict sign ``total`` under the sign hypotheses ``hyp`` (and 0 < r < 1):
    for n and d, a form congruent modulo the circles, its factorisation, and for each factor
    either (r alone) no root in ]0, 1[ or a form whose terms all have one strict sign."""
    factors = [f["poly"] for part in parts for f in part["factors"]] + \
        [f["form"] for part in parts for f in part["factors"] if "form" in f]
    gens, circles = generators(E, n, d, *[part["form"] for part in parts], *factors)
    names = [str(g) for g in gens]

    def terms(x):
        return rational_function(x, gens)["num"]

    def part_data(part):
        return {"form": terms(part["form"]), "constant": rational(part["constant"]),
                "factors": [{"poly": terms(f["poly"]), "mult": f["mult"], "how": f["how"], "sign": int(f["sign"]),
                             **({"form": terms(f["form"])} if "form" in f else {})} for f in part["factors"]]}
    return {"kind": "signed", "vars": names, "circles": circles,
            "hyp": {k: v for k, v in sorted(hyp.items()) if k in names},
            "expr": {"num": terms(n), "den": terms(d)}, "num": part_data(parts[0]), "den": part_data(parts[1]),
            "sign": int(total)}
