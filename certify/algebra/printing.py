"""Polynomials printed as SymPy prints them, without building a SymPy expression.

The reports print polynomials as ``sstr(e, order="lex")`` prints the SymPy expression
(:func:`certify.algebra.poly.show` then writes ``^`` and drops ``*``).  For the three
shapes the reports use, this module writes that very text from the terms of a
python-flint or sparse polynomial, an order of magnitude faster than building the
expression and printing it:

* :func:`expanded`: an expanded polynomial (``Add`` of monomials): terms in lex order
  of the symbols sorted by name (r < s < u < v < x < λ), each ``c*r**2*λ/q``;
* :func:`factored`: SymPy's ``factor`` of it (``_keep_coeff(c, Mul(*factors))``):
  the factors in SymPy's canonical order of a product (``Mul.as_ordered_factors``:
  a symbol before a sum, sums by number of terms, then term by term, then exponent);
* :func:`collected`: ``collect(p, λ)``: λ^k times the sum of its coefficient's terms,
  the terms free of λ spliced in, in lex order of the monomials (r before λ).

A polynomial here is ``(names, terms)``: ``names`` the symbols, sorted by name, and
``terms`` a list of (coefficient, exponents), the coefficient a non-zero Fraction, the
exponents a tuple aligned with ``names``.  The SymPy route stays the reference:
tests/algebra/test_printing.py compares both on random polynomials.
"""
from __future__ import annotations

from fractions import Fraction
from math import gcd

import flint

# SymPy's sort keys (Basic.sort_key): class keys, then args, exponent, coefficient
_NUMBER, _SYMBOL, _MUL, _ADD = (1, 0, "Number"), (2, 0, "Symbol"), (3, 0, "Mul"), (3, 1, "Add")
_ONE = Fraction(1)


def _number_key(n) -> tuple:
    return (_NUMBER, (0, ()), (), Fraction(n))


def _term_key(c: Fraction, e: tuple, names: tuple) -> tuple:
    """default_sort_key of the monomial c·Π name^e."""
    syms = [(n, k) for n, k in zip(names, e) if k]
    if not syms:
        return _number_key(c)
    if len(syms) == 1:
        n, k = syms[0]
        return (_SYMBOL, (1, (n,)), _number_key(k), c)
    factors = tuple((_SYMBOL, (1, (n,)), _number_key(k), _ONE) for n, k in syms)    # names sorted already
    return (_MUL, (len(syms), factors), _number_key(1), c)


def rational(c: Fraction) -> str:
    """A rational as SymPy prints it: ``-3/7``, ``5``."""
    return str(c.numerator) if c.denominator == 1 else f"{c.numerator}/{c.denominator}"


def _term(c: Fraction, e: tuple, names: tuple) -> str:
    """sstr of the monomial c·Π name^e: ``-3*r**2*λ/4``."""
    factors = [n if k == 1 else f"{n}**{k}" for n, k in zip(names, e) if k]
    if not factors:
        return rational(c)
    p = abs(c.numerator)
    body = "*".join(([str(p)] if p != 1 else []) + factors)
    return ("-" if c < 0 else "") + body + (f"/{c.denominator}" if c.denominator != 1 else "")


def _lex(terms: list) -> list:
    """The terms in SymPy's lex order (``as_ordered_terms(order="lex")``): exponents descending."""
    return sorted(terms, key=lambda t: t[1], reverse=True)


def _default_order(terms: list, names: tuple) -> list:
    """``as_ordered_terms()`` (order None): lex, but for SymPy's special case of two terms,
    a positive number and a negative multiple of one power (``1 - 2*r``: the number first)."""
    out = _lex(terms)
    if len(out) == 2:
        (c1, e1), (c0, e0) = out
        if not any(e0) and c0 > 0 and c1 < 0 and sum(1 for k in e1 if k) == 1:
            return [out[1], out[0]]
    return out


def _add(items: list[str]) -> str:
    """StrPrinter._print_Add on the printed terms, in order."""
    out: list[str] = []
    for t in items:
        sign, t = ("-", t[1:]) if t.startswith("-") else ("+", t)
        out += [sign, t]
    sign = out.pop(0)
    return ("" if sign == "+" else sign) + " ".join(out)


def expanded(names: tuple, terms: list, order: str | None = "lex") -> str:
    """sstr(p, order="lex") of the expanded polynomial (``order=None``: ``str(p)``, SymPy's
    default order, the same text but for the special case of :func:`_default_order`).

    >>> from fractions import Fraction as F
    >>> expanded(("r", "λ"), [(F(1), (0, 0)), (F(-3, 4), (1, 1)), (F(-2), (2, 0))])
    '-2*r**2 - 3*r*λ/4 + 1'
    """
    if not terms:
        return "0"
    ordered = _lex(terms) if order == "lex" else _default_order(terms, names)
    if len(ordered) == 1:
        c, e = ordered[0]
        return _term(c, e, names)
    return _add([_term(c, e, names) for c, e in ordered])


def _factor_key(names: tuple, terms: list, m: int) -> tuple:
    """sort_key of factor**m: a symbol's, or a sum's (its terms' keys in default order)."""
    if len(terms) == 1:
        (_, e), = terms
        n = next(n for n, k in zip(names, e) if k)
        return (_SYMBOL, (1, (n,)), _number_key(m), _ONE)
    keys = tuple(_term_key(c, e, names) for c, e in _default_order(terms, names))
    return (_ADD, (len(terms), keys), _number_key(m), _ONE)


def _power(names: tuple, terms: list, m: int) -> str:
    """A factor**m inside a product: a sum in parentheses, ``**m`` when m > 1."""
    base = expanded(names, terms) if len(terms) == 1 else f"({expanded(names, terms)})"
    return base if m == 1 else f"{base}**{m}"


def factored(names: tuple, c: Fraction, factors: list) -> str:
    """sstr(_keep_coeff(c, Mul(*[f**m])), order="lex") for primitive irreducible factors f
    (``[(terms, m)]``, a single-term factor being one symbol): what ``sp.factor`` gives."""
    if not factors or c == 0:
        return rational(c)
    ordered = sorted(factors, key=lambda fm: _factor_key(names, *fm))
    if len(ordered) == 1 and ordered[0][1] == 1 and len(ordered[0][0]) > 1 and c in (1, -1):
        terms = ordered[0][0]                              # a sum alone, times ±1: the sum itself
        return expanded(names, terms if c == 1 else [(-k, e) for k, e in terms])
    if c == 1 and len(ordered) == 1:
        terms, m = ordered[0]
        return _power(names, terms, m)
    p, q = abs(c.numerator), c.denominator
    body = "*".join(([str(p)] if p != 1 else []) + [_power(names, t, m) for t, m in ordered])
    return ("-" if c < 0 else "") + body + (f"/{q}" if q != 1 else "")


def collected(names: tuple, terms: list, var: str) -> str:
    """sstr(collect(p, var), order="lex"): each power var^k (k ≥ 1) times the sum of its
    coefficient's terms (a single term stays a monomial), the terms free of var spliced in."""
    i = names.index(var)
    groups: dict[int, list] = {}
    for c, e in terms:
        groups.setdefault(e[i], []).append((c, e))
    items = []                    # (exponents for the order, printed)
    for k, group in groups.items():
        if k == 0 or len(group) == 1:
            items += [(e, _term(c, e, names)) for c, e in group]
            continue
        rest = [(c, e[:i] + (0,) + e[i + 1:]) for c, e in group]
        power = var if k == 1 else f"{var}**{k}"
        items.append((tuple(k if j == i else 0 for j in range(len(names))), f"{power}*({expanded(names, rest)})"))
    if not items:
        return "0"
    items.sort(key=lambda t: t[0], reverse=True)
    return items[0][1] if len(items) == 1 else _add([t for _, t in items])


# --- from python-flint and SymPy's sparse polynomials ---------------------------------

def fraction(c) -> Fraction:
    """A Fraction from an int, fmpz, fmpq or SymPy's QQ element."""
    if isinstance(c, (int, flint.fmpz)):
        return Fraction(int(c))
    return Fraction(int(c.numerator), int(c.denominator))


def ring_terms(p) -> tuple[tuple, list]:
    """(names, terms) of an element of a SymPy PolyRing (any symbols)."""
    order = sorted(range(len(p.ring.symbols)), key=lambda j: p.ring.symbols[j].name)
    used = [j for j in order if any(m[j] for m in p.monoms())]
    names = tuple(p.ring.symbols[j].name for j in used)
    return names, [(fraction(c), tuple(m[j] for j in used)) for m, c in p.terms()]


def factored_univariate(p, name: str = "r") -> str:
    """The text of ``sp.factor`` of a polynomial over Q in one variable (an fmpz_poly or
    fmpq_poly; :func:`certify.dynamics.model.factor_flint` is the same expression):
    the rational coefficient, then the primitive irreducible factors (positive leading
    coefficient) with their multiplicities."""
    p = flint.fmpq_poly(p)
    if p.degree() <= 0:
        return rational(fraction(p[0]) if p.degree() == 0 else Fraction(0))
    _, parts = p.numer().factor()
    coeff = fraction(p.coeffs()[-1])
    factors = []
    for f, m in parts:
        f = f / f.content()
        if f.coeffs()[-1] < 0:
            f = -f
        coeff /= fraction(f.coeffs()[-1]) ** int(m)
        factors.append(([(fraction(k), (j,)) for j, k in enumerate(f.coeffs()) if k], int(m)))
    return factored((name,), coeff, factors)


def factored_mpoly(F, den: int = 1, names: tuple = ("r", "λ")) -> str:
    """The text of ``sp.factor`` of F/den, F an fmpz_mpoly whose variables are ``names``
    (sorted by name, lex; :func:`certify.dynamics.model.factor_lr` is the same expression):
    its content over den, then the primitive irreducible factors with a positive leading
    coefficient in lex order."""
    if F.total_degree() <= 0:
        return rational(Fraction(int(F.leading_coefficient()) if not F.is_zero() else 0, den))
    content, parts = F.factor()
    coeff = Fraction(int(content), den)
    factors = []
    for f, m in parts:
        if f.leading_coefficient() < 0:
            f, coeff = -f, coeff * (-1) ** int(m)
        factors.append(([(Fraction(int(k)), tuple(map(int, e))) for e, k in f.to_dict().items()], int(m)))
    return factored(names, coeff, factors)


RL = flint.fmpz_mpoly_ctx.get(("r", "lam"), "lex")      # SymPy's order of the generators r, λ


def _rl_integer(p) -> tuple:
    """(F, L): F = L·p an fmpz_mpoly in (r, λ), L > 0 the lcm of the denominators, for p
    an element of a SymPy PolyRing in λ and r only."""
    names = [s.name for s in p.ring.symbols]
    il, ir = names.index("λ"), names.index("r")
    if any(k for m in p.monoms() for j, k in enumerate(m) if j not in (il, ir)):
        raise ValueError("not a polynomial in r and λ alone")
    terms = [(fraction(c), m) for m, c in p.terms()]
    L = 1
    for c, _ in terms:
        L = L * c.denominator // gcd(L, c.denominator)
    return RL.from_dict({(m[ir], m[il]): int(c * L) for c, m in terms}), L


def sympy_fraction(numer, denom) -> tuple:
    """``sp.fraction(sp.cancel(numer/denom))`` for polynomials in r, λ (elements of a SymPy
    PolyRing), as ((N, n), (D, d)), numerator N/n and denominator D/d with N, D in
    fmpz_mpoly over (r, λ): what SymPy's cancel makes of the quotient, coprime integer
    polynomials, contents coprime, the denominator's leading coefficient (lex in r, λ)
    positive; a constant denominator q is divided into a numerator of several terms
    (rational coefficients, denominator 1), but not into a single term."""
    (N, LN), (D, LD) = _rl_integer(numer), _rl_integer(denom)
    if N.is_zero():
        return (N, 1), (RL.from_dict({(0, 0): 1}), 1)
    cN, cD = int(N.content()), int(D.content())
    Np, Dp = N / cN, D / cD
    G = Np.gcd(Dp)
    if not G.is_one():
        Np, Dp = Np / G, Dp / G
    A, B = cN * LD, cD * LN
    g = gcd(A, B)
    A, B = A // g, B // g
    if Dp.total_degree() <= 0:
        lead = int(Dp.leading_coefficient())              # ±1
        if len(Np) == 1:                                  # c·monomial/q is a product: (c·monomial, q)
            return (Np * (A * lead), 1), (RL.from_dict({(0, 0): B}), 1)
        return (Np * (A * lead), B), (RL.from_dict({(0, 0): 1}), 1)
    num, den = Np * A, Dp * B
    if den.leading_coefficient() < 0:
        num, den = -num, -den
    return (num, 1), (den, 1)


def mpoly_terms(F, d: int = 1) -> tuple[tuple, list]:
    """(names, terms) of F/d, F an fmpz_mpoly in (r, λ)."""
    return ("r", "λ"), [(Fraction(int(k), d), tuple(map(int, e))) for e, k in F.to_dict().items()]
