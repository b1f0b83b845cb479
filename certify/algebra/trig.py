"""Identities in cos/sin of θ and φ (Section 4), proved in exact polynomial arithmetic.

A printed formula is transcribed as text close to the paper
(``"sin(φ)*cos(θ) - (1+r)/2*cos(φ)*sin(θ)"``, ``tan(θ)`` allowed) and parsed by
:func:`certify.algebra.poly.parse` with sin θ → sθ, cos θ → cθ, sin φ → sφ, cos φ → cφ:
a rational function of cθ, sθ, cφ, sφ, r, λ (λ: the radial component of q, l. 611-614)
and whatever other symbol the text names.  Vectors are 3×1 matrices, written
``(a, b, c)`` or ``V(a, b, c)`` inside formulas, with ``cross``, ``dot`` and
``M([[...]])`` for a printed matrix.

An identity E = 0 holds when cθ² + sθ² = 1 and cφ² + sφ² = 1.  :func:`is_zero`
proves it by two independent routes, which must agree (else :class:`RoutesDisagree`,
a FAIL of the certificate):

(a) SymPy: the numerator of E in lowest terms (``together``/``cancel`` done in SymPy's
    sparse rational functions) has normal form 0 modulo the ideal (cθ²+sθ²−1,
    cφ²+sφ²−1), which ``groebner`` confirms is its own Gröbner basis (grevlex), and
    the denominator does not reduce to 0;
(b) python-flint: the Weierstrass substitution cθ = (1−a²)/(1+a²), sθ = 2a/(1+a²),
    cφ = (1−b²)/(1+b²), sφ = 2b/(1+b²), evaluated in Q(a, b, r, λ, ...), is 0.

The ideal is prime and the parametrisation birational, so both routes decide the
same question.  Signs (:func:`sign`) are proved by inspection: each factor is a
hypothesis (cθ, sθ, sφ > 0, the sign of cφ, 0 < r < 1, named quantities such as
t_b < 0) or a polynomial all of whose terms have the same strict sign, possibly
after rewriting with the circle relations, or a polynomial in r alone without
root in ]0, 1[ (Sturm).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from functools import cache, cmp_to_key

import flint
import sympy as sp
from sympy.core.mul import _keep_coeff
from sympy.polys.polyutils import _sort_gens

from certify import caches
from certify.witnesses import witnessing

from . import facts
from .poly import fraction_tree, lam, r
from .poly import parse as parse_paper
from .sturm import count_roots

θ, φ = sp.symbols("θ φ")
cθ, sθ, cφ, sφ = sp.symbols("cosθ sinθ cosφ sinφ")
CIRCLE_SYMBOLS = (cθ, sθ, cφ, sφ)
CIRCLES = (cθ**2 + sθ**2 - 1, cφ**2 + sφ**2 - 1)
IDEAL = "(cos²θ+sin²θ−1, cos²φ+sin²φ−1)"
E_X, E_Y, E_Z = (sp.Matrix([1, 0, 0]), sp.Matrix([0, 1, 0]), sp.Matrix([0, 0, 1]))
ANGLE = {"0": {cθ: 1, sθ: 0}, "π/2": {cθ: 0, sθ: 1}}      # the limit cases θ = 0, π/2


class RoutesDisagree(ArithmeticError):
    """The Gröbner route and the Weierstrass route gave different answers."""


# ---------------------------------------------------------------- parsing
def _on_circles(e: sp.Expr) -> sp.Expr:
    """sin/cos of θ, φ (and of sums and multiples, after expansion) as cθ, sθ, cφ, sφ."""
    e = sp.expand_trig(e).xreplace({sp.cos(θ): cθ, sp.sin(θ): sθ, sp.cos(φ): cφ, sp.sin(φ): sφ})
    if e.has(sp.sin, sp.cos, sp.tan):
        raise ValueError(f"not a polynomial in cos/sin of θ, φ: {e}")
    return e


def _vec(*components) -> sp.Matrix:
    """A column vector of the paper, ``V(a, b, c)``."""
    return sp.Matrix([sp.sympify(c) for c in components])


NAMES = {"θ": θ, "φ": φ, "sin": lambda x: _on_circles(sp.sin(x)), "cos": lambda x: _on_circles(sp.cos(x)),
         "tan": lambda x: _on_circles(sp.sin(x)) / _on_circles(sp.cos(x)), "V": _vec,
         "M": lambda rows: sp.Matrix(rows), "cross": lambda u, v: u.cross(v), "dot": lambda u, v: u.dot(v)}


def parse(text: str, **names):
    """A printed formula (scalar, ``(a, b, c)`` vector or ``[[...]]`` matrix) in cθ, sθ, cφ, sφ;
    ``names`` binds further names (vectors, matrices) the text uses."""
    e = parse_paper(text, {**NAMES, **names})
    if isinstance(e, (sp.Tuple, tuple, list)):
        e = sp.Matrix(list(e))
    return e


def vector(text: str, **names) -> sp.Matrix:
    """A printed vector as a 3×1 matrix."""
    v = parse(text, **names)
    if not isinstance(v, sp.MatrixBase) or v.shape != (3, 1):
        raise ValueError(f"not a 3-vector: {text!r}")
    return v


def members(text: str) -> list[str]:
    """The members of a printed chain ``X = Y = Z`` as texts: each further member on a
    line starting with ``=``, a member may span lines."""
    parts = [" ".join(m.split()) for m in ("\n" + text.strip()).split("\n=")]
    return [m for m in parts if m]


def chain(text: str, **names) -> list:
    """The members of a printed chain, parsed."""
    return [parse(m, **names) for m in members(text)]


def show(e) -> str:
    """A formula for reports: ``-r cosφ^2 sinθ``; vectors as ``(a, b, c)``.  The text of a SymPy
    expression is kept for a run (evidence shows the same factors again and again)."""
    if isinstance(e, sp.MatrixBase):
        return "(" + ", ".join(show(c) for c in e) + ")"
    if not isinstance(e, sp.Basic):
        return _show(e)
    found = _SHOWN.get(e)
    if found is None:
        found = _SHOWN[e] = _show(e)
    return found


def _show(e) -> str:
    return sp.sstr(sp.sympify(e), order="grlex").replace("**", "^").replace("*", " ")


_SHOWN: dict = {}               # expression -> its text (equal expressions print alike)
caches.register(_SHOWN.clear)


def short(e, limit: int = 160) -> str:
    """:func:`show`, or its term count and its first characters when long."""
    text = show(e)
    if len(text) <= limit:
        return f"`{text}`"
    if isinstance(e, sp.MatrixBase):
        return "a vector of " + ", ".join(str(len(sp.Add.make_args(sp.expand(c)))) for c in e) + " terms"
    n = len(sp.Add.make_args(sp.expand(e)))
    return f"{n} terms, `{text[:limit]} …`"


# ---------------------------------------------------------------- route (a): Gröbner normal form
def _gens(*exprs) -> tuple:
    """The circle symbols first, then every other symbol by name."""
    others = set().union(*(sp.sympify(e).free_symbols for e in exprs)) - set(CIRCLE_SYMBOLS)
    return CIRCLE_SYMBOLS + tuple(sorted(others, key=str))


@cache
def groebner_basis(gens: tuple) -> sp.GroebnerBasis:
    """The reduced Gröbner basis (grevlex) of the circle ideal; it is the two circles
    themselves (their leading terms cθ², cφ² are coprime)."""
    G = sp.groebner(CIRCLES, *gens, order="grevlex", domain=sp.QQ)
    if [sp.expand(g) for g in G.exprs] != [sp.expand(c) for c in CIRCLES]:
        raise ArithmeticError("the circle relations are not their own Gröbner basis")
    return G


@cache
def _field(gens: tuple, order: str = "grevlex"):
    """Q(gens) as SymPy sparse rational functions, and the circles in its ring."""
    K = sp.field(gens, sp.QQ, order)[0]
    return K, [K.ring.from_expr(c) for c in CIRCLES]


def _lowest_terms(E):
    """E in lowest terms in Q(cθ, sθ, cφ, sφ, ...): numerator and denominator as ring elements
    (those of SymPy's field, computed by python-flint when E is a rational function of its
    symbols: :func:`_flint_lowest_terms`)."""
    E = sp.sympify(E)
    gens = _gens(E)
    K, _ = _field(gens)
    found = _flint_lowest_terms(E, gens)
    if found is not None:
        ring = K.ring
        return ring.from_dict(found[0]), ring.from_dict(found[1])
    f = K.from_expr(E)
    return f.numer, f.denom


def _flint_lowest_terms(E, gens: tuple) -> tuple[dict, dict] | None:
    """The numerator and denominator SymPy's field Q(gens) gives E, as {exponents: fmpq}, from
    :func:`_flint_fraction` in grevlex (the order of the field's ring); None when E is not a
    rational function of the gens.  The field inverts without normalising: for E = b^(−k) its
    numerator and denominator are d^k, n^k from b's n, d (the sign of the denominator as it falls)."""
    if E.is_Pow and E.exp.is_Integer and E.exp < 0:
        found = _flint_fraction(E.base, gens, "degrevlex")
        if found is None or found[0] == 0:
            return None
        k = -int(E.exp)
        found = found[1] ** k, found[0] ** k
    else:
        found = _flint_fraction(E, gens, "degrevlex")
    if found is None:
        return None
    n, d = found
    return dict(zip(n.monoms(), n.coeffs())), dict(zip(d.monoms(), d.coeffs()))


def _flint_fraction(E, gens: tuple, order: str):
    """E = n/d in lowest terms as fmpq_mpoly in ``gens`` (ordered by ``order``), in the unique
    normal form SymPy's cancellations keep (PolyElement.cancel, dmp_cancel): n, d with integer
    coefficients, their contents coprime, the leading coefficient of d > 0 in that order (n = 0:
    d = 1).  E's fraction is multiplied out and divided by the gcd once.  None when E is not
    built from the gens and rationals by +, ·, integer powers (or divides by 0)."""
    ctx = flint.fmpq_mpoly_ctx.get(tuple(f"x{k}" for k in range(len(gens))), order)
    index = dict(zip(gens, ctx.gens()))
    one = ctx.from_dict({(0,) * len(gens): 1})
    found = fraction_tree(E, index.get, lambda q: ctx.from_dict({(0,) * len(gens): flint.fmpq(int(q.p), int(q.q))}))
    if found is None:
        return None
    n, d = found
    if n == 0:
        return n, one
    g = n.gcd(d)
    n, d = n / g, d / g
    den = flint.fmpz(1)
    for c in n.coeffs() + d.coeffs():
        den = den.lcm(c.q)
    n, d = n * den, d * den
    content = flint.fmpz(0)
    for c in n.coeffs() + d.coeffs():
        content = content.gcd(c.p)
    if d.leading_coefficient() < 0:
        content = -content
    return n / content, d / content


def _expr(P, gens: tuple) -> sp.Expr:
    """The fmpq_mpoly P in ``gens`` as a SymPy expression (the sum of its terms, as Poly.as_expr)."""
    return sp.Add(*[sp.Rational(int(c.p), int(c.q)) * sp.Mul(*[x ** e for x, e in zip(gens, m) if e])
                    for m, c in zip(P.monoms(), P.coeffs())])


@caches.for_a_run
def fraction(E) -> tuple[sp.Expr, sp.Expr]:
    """Numerator and denominator of E in lowest terms (``together`` and ``cancel`` done by
    SymPy's sparse rational functions)."""
    n, d = _lowest_terms(E)
    return n.as_expr(), d.as_expr()


def normal_form(n) -> sp.Expr:
    """The normal form of the polynomial n modulo the circle ideal (route a): the remainder
    of the division by its Gröbner basis, grevlex with cθ > sθ > cφ > sφ > the others."""
    n = sp.expand(n)
    if n == 0:
        return sp.Integer(0)
    gens = _gens(n)
    groebner_basis(gens)
    K, G = _field(gens)
    return K.ring.from_expr(n).rem(G).as_expr()


def groebner_is_zero(E) -> tuple[bool, list[str]]:
    """Route (a): the numerator of E reduces to 0 and its denominator does not."""
    zero, evidence = _groebner_is_zero(E)
    return zero, list(evidence)


@caches.for_a_run
def _groebner_is_zero(E) -> tuple[bool, tuple[str, ...]]:
    gens = _gens(E)
    groebner_basis(gens)
    n, d = _lowest_terms(E)
    G = _field(gens)[1]
    if d.rem(G) == 0:
        raise ZeroDivisionError(f"the denominator of {show(E)} vanishes on the circles")
    nf = n.rem(G)
    return nf == 0, (short(n.as_expr()), short(nf.as_expr()))


# ---------------------------------------------------------------- route (b): Weierstrass substitution
def weierstrass(E) -> tuple[flint.fmpq_mpoly, flint.fmpq_mpoly]:
    """E under cθ = (1−a²)/(1+a²), sθ = 2a/(1+a²), cφ = (1−b²)/(1+b²), sφ = 2b/(1+b²):
    numerator and denominator in Q[a, b, ...] (python-flint), reduced by their gcd."""
    E = sp.sympify(E)
    others = _gens(E)[4:]
    ctx = flint.fmpq_mpoly_ctx.get(("a", "b") + tuple(f"x{k}" for k in range(len(others))), "lex")
    a, b, *xs = ctx.gens()
    one = ctx.constant(1)
    images = {cθ: (1 - a**2, 1 + a**2), sθ: (2 * a, 1 + a**2), cφ: (1 - b**2, 1 + b**2), sφ: (2 * b, 1 + b**2)}
    images.update({s: (x, one) for s, x in zip(others, xs)})
    return _evaluate(E, images, ctx, {})


def _reduce(n, d):
    if n.is_zero():
        return n, d.context().constant(1)
    g = n.gcd(d)
    return n / g, d / g


def _evaluate(e, images, ctx, memo):
    """The expression tree of e, evaluated as fractions of python-flint polynomials."""
    if e in memo:
        return memo[e]
    if e.is_Rational:
        out = (ctx.constant(flint.fmpq(int(e.p), int(e.q))), ctx.constant(1))
    elif e.is_Symbol:
        out = images[e]
    elif e.is_Add or e.is_Mul:
        args = [_evaluate(x, images, ctx, memo) for x in e.args]
        n, d = args[0]
        for n2, d2 in args[1:]:
            n, d = _reduce(n * d2 + n2 * d, d * d2) if e.is_Add else _reduce(n * n2, d * d2)
        out = (n, d)
    elif e.is_Pow and e.exp.is_Integer:
        n, d = _evaluate(e.base, images, ctx, memo)
        k = int(e.exp)
        if k < 0:
            if n.is_zero():
                raise ZeroDivisionError(f"{e.base} vanishes under the Weierstrass substitution")
            n, d, k = d, n, -k
        out = (n**k, d**k)
    else:
        raise ValueError(f"not a rational function: {e}")
    memo[e] = out
    return out


def weierstrass_is_zero(E) -> tuple[bool, list[str]]:
    """Route (b): the Weierstrass substitution of E is the zero rational function."""
    zero, evidence = _weierstrass_is_zero(E)
    return zero, list(evidence)


@caches.for_a_run
def _weierstrass_is_zero(E) -> tuple[bool, tuple[str, ...]]:
    n, _d = weierstrass(E)
    return n.is_zero(), ("0" if n.is_zero() else f"non-zero ({len(list(n.terms()))} terms)",)


# ---------------------------------------------------------------- identities
@dataclass
class Result:
    """A proved (holds) or refuted statement, with the evidence lines for the report."""

    holds: bool
    evidence: list[str] = field(default_factory=list)
    routes: tuple = ()          # (numerator, normal form, Weierstrass) of an identity
    witnesses: list | None = field(default=None, compare=False, repr=False)   # the ids of its witnesses (a sign)

    def __bool__(self):
        return self.holds


def is_zero(E) -> Result:
    """E ≡ 0 on the circles, by both routes; RoutesDisagree if they differ."""
    za, ea = groebner_is_zero(E)
    zb, eb = weierstrass_is_zero(E)
    if za != zb:
        raise RoutesDisagree(f"Gröbner route says {'0' if za else '≠ 0'}, Weierstrass route says "
                             f"{'0' if zb else '≠ 0'} for {show(E)}")
    return Result(za, [f"numerator: {ea[0]}", f"normal form mod {IDEAL}: {ea[1]}",
                       f"Weierstrass substitution: {eb[0]}"], (ea[0], ea[1], eb[0]))


def equal(lhs, rhs) -> Result:
    """lhs ≡ rhs (scalars, or vectors component by component)."""
    if isinstance(lhs, sp.MatrixBase) or isinstance(rhs, sp.MatrixBase):
        if lhs.shape != rhs.shape:
            return Result(False, [f"shapes differ: {lhs.shape} and {rhs.shape}"])
        parts = [is_zero(x - y) for x, y in zip(lhs, rhs)]
        return Result(all(parts), _merge(parts))
    return is_zero(sp.sympify(lhs) - sp.sympify(rhs))


def _merge(parts: list[Result]) -> list[str]:
    """The evidence of a vector identity, component by component, route by route."""
    heads = ("numerators of the differences", f"normal forms mod {IDEAL}", "Weierstrass substitution")
    return [f"{head}: " + ", ".join(p.routes[k] for p in parts) for k, head in enumerate(heads)]


def parallel(v, w) -> Result:
    """v ∧ w ≡ 0 (v, w colinear wherever both are non-zero)."""
    c = v.cross(w)
    res = equal(c, sp.zeros(3, 1))
    return Result(res.holds, [f"v ∧ w = {short(c.applyfunc(sp.cancel))}"] + res.evidence)


# ---------------------------------------------------------------- signs by inspection
@dataclass(frozen=True)
class Signs:
    """Hypotheses: strict signs of atoms (cθ, sθ, sφ > 0, r > 0, the sign of cφ, named
    quantities such as t_b) and the definitions of the named quantities; 0 < r < 1."""

    atoms: tuple = ((cθ, 1), (sθ, 1), (sφ, 1), (r, 1))
    defs: tuple = ()

    def sign(self, s):
        return dict(self.atoms).get(s)

    def assume(self, symbol, sign: int, definition=None) -> Signs:
        """The hypotheses with ``symbol`` of sign ``sign`` (and its definition)."""
        atoms = tuple((a, s) for a, s in self.atoms if a != symbol) + ((symbol, sign),)
        defs = self.defs + (((symbol, definition),) if definition is not None else ())
        return Signs(atoms, defs)

    def unfold(self, e):
        """e with the named quantities replaced by their definitions."""
        for s, d in reversed(self.defs):
            e = e.subs(s, d)
        return e

    def describe(self) -> str:
        names = {cθ: "cos θ", sθ: "sin θ", cφ: "cos φ", sφ: "sin φ", r: "r"}
        text = [f"{names.get(a, show(a))} {'>' if s > 0 else '<'} 0" for a, s in self.atoms]
        return ", ".join(text) + ", r < 1"


def hypotheses(cos_phi: int | None = None) -> Signs:
    """θ ∈ ]0, π/2[, sin φ > 0, 0 < r < 1, and cos φ of the given sign (if any)."""
    H = Signs()
    return H.assume(cφ, cos_phi) if cos_phi else H


def _term_sign(P: sp.Poly, H: Signs) -> int | None:
    """The common strict sign of all terms of P under H (weak terms allowed: even powers
    of unknown symbols), or None."""
    signs, strict = set(), False
    for monom, coeff in P.terms():
        s, st = (1 if coeff > 0 else -1), True
        for g, e in zip(P.gens, monom):
            if e == 0:
                continue
            sg = H.sign(g)
            if sg is None and e % 2:
                return None
            s, st = (s * sg**e, st) if sg is not None else (s, False)
        signs.add(s)
        strict = strict or st
    return signs.pop() if len(signs) == 1 and strict else None


LEADING = ((cθ, sθ, cφ, sφ), (cθ, sθ, sφ, cφ), (sθ, cθ, cφ, sφ), (sθ, cθ, sφ, cφ))   # the lex orders of _rewrites


def _rewrites(f):
    """f as written, then rewritten with cθ² → 1−sθ² or sθ² → 1−cθ² (same for φ): the
    normal forms for the four lex orders with one of each pair leading (lazily)."""
    for k in range(1 + len(LEADING)):
        yield _rewrite(f, k)


@caches.for_a_run
def _rewrite(f, k: int):
    """The k-th form of :func:`_rewrites` (0: f expanded).  Memoised for a run: a sign and
    the witness that records it (:func:`signed_witness`) read the same forms, and the step
    lemmas ask the same signs again (pure SymPy; nothing here records)."""
    f = sp.expand(f)
    if k == 0:
        return f
    K, G = _field(LEADING[k - 1] + _gens(f)[4:], "lex")
    return K.ring.from_expr(f).rem(G).as_expr()


@caches.for_a_run
def _factor_list(g) -> tuple:
    """sp.factor_list(g) as (constant, ((factor, multiplicity), ...)), memoised like :func:`_rewrite`;
    by python-flint for a sum with integer coefficients (:func:`_flint_factor_list`)."""
    found = _flint_factor_list(g)
    if found is not None:
        return found
    c, factors = sp.factor_list(g)
    return c, tuple(factors)


def _flint_factor_list(g) -> tuple | None:
    """What :func:`_factor_list` returns from SymPy, for a sum g of terms c·x^e (c an integer, x
    symbols, e natural), the irreducible factors found by python-flint's fmpz_mpoly; None for
    anything else.  SymPy's factor_list first writes g as ``together`` does: the integer content,
    the symbols common to every term (each a factor (x, min e) of its own polynomial in x alone)
    and the rest, one polynomial in its own symbols (_sort_gens: SymPy's order); its factors,
    primitive with a positive leading coefficient in lex order, are unique.  All are sorted by
    SymPy's key (length of the dense representation, number of generators, multiplicity, domain,
    the representation; ties, among the common symbols, in the order of together's product), and
    the constant is what remains."""
    if not g.is_Add:
        return None
    terms = []
    for t in g.args:
        c, m = t.as_coeff_Mul()
        if not c.is_Integer:
            return None
        powers: dict = {}
        for f in sp.Mul.make_args(m):
            b, e = f.as_base_exp()
            if not (b.is_Symbol and e.is_Integer and e > 0):
                if f == 1:
                    continue
                return None
            powers[b] = powers.get(b, 0) + int(e)
        terms.append((int(c), powers))
    symbols = set().union(*(p.keys() for _, p in terms))
    common = {x: min(p.get(x, 0) for _, p in terms) for x in symbols}
    common = {x: e for x, e in common.items() if e > 0}
    gens = _sort_gens([x for x in symbols if any(p.get(x, 0) > common.get(x, 0) for _, p in terms)])
    ctx = flint.fmpz_mpoly_ctx.get(tuple(f"x{k}" for k in range(len(gens))), "lex")
    rest = ctx.from_dict({tuple(p.get(x, 0) - common.get(x, 0) for x in gens): c for c, p in terms})
    content, found = rest.factor()
    # the common symbols as together's product holds them (Basic.compare): SymPy's sort is stable
    order = sorted(common, key=cmp_to_key(lambda a, b: sp.Basic.compare(a ** common[a], b ** common[b])))
    keyed = [((2, 1, common[x], [1, 0]), x, common[x]) for x in order]
    for f, k in found:
        if f.leading_coefficient() < 0:
            f, content = -f, content * (-1) ** k
        d = f.to_dict()
        rep = _dense(d, len(gens))
        expr = sp.Add(*[sp.Integer(int(c)) * sp.Mul(*[x ** e for x, e in zip(gens, m) if e]) for m, c in d.items()])
        keyed.append(((len(rep), len(gens), int(k), rep), expr, int(k)))
    keyed.sort(key=lambda item: item[0])
    return sp.Integer(int(content)), tuple((f, k) for _, f, k in keyed)


def _dense(d: dict, n: int) -> list:
    """The dense recursive representation (SymPy's DMP, ``Poly.rep.to_list()``) of the polynomial
    {exponents: coefficient} in n generators: coefficients by falling powers of the first one,
    each in the others; the zero polynomial is [] wrapped n − 1 times."""
    if not d:
        z: list = []
        for _ in range(n - 1):
            z = [z]
        return z
    top = max(m[0] for m in d)
    if n == 1:
        out = [0] * (top + 1)
        for m, c in d.items():
            out[top - m[0]] = int(c)
        return out
    parts: dict = {}
    for m, c in d.items():
        parts.setdefault(m[0], {})[m[1:]] = c
    return [_dense(parts.get(top - k, {}), n - 1) for k in range(top + 1)]


def _factored(g) -> sp.Expr:
    """sp.factor(g) for a polynomial g, rebuilt as SymPy's factor builds it (the constant kept
    before the product of the factors' powers) from the memoised :func:`_factor_list`, not
    factored a second time."""
    c, factors = _factor_list(g)
    return _keep_coeff(sp.sympify(c), sp.Mul(*[f**m for f, m in factors]))


@caches.for_a_run
def _factor_sign(f, H: Signs) -> int | None:
    """The strict sign of one irreducible factor under H, or None."""
    syms = sp.sympify(f).free_symbols
    if syms == {r}:
        P = flint.fmpq_poly([flint.fmpq(int(sp.numer(c)), int(sp.denom(c))) for c in sp.Poly(f, r).all_coeffs()[::-1]])
        if count_roots(P, 0, 1) - (P(1) == 0) == 0:
            return 1 if P(flint.fmpq(1, 2)) > 0 else -1
        return None
    for g in _rewrites(f):
        if g.free_symbols:
            s = _term_sign(sp.Poly(g, *sorted(g.free_symbols, key=str)), H)
        else:
            s = int(sp.sign(g)) or None
        if s:
            return s
    return None



def _poly_sign(p, H: Signs) -> tuple[int | None, list[str]]:
    """Strict sign of a polynomial from its factors (even powers need a known factor
    sign), the polynomial taken as written or rewritten with the circle relations
    (:func:`_poly_sign_kept`, memoised for a run; the reasons as a fresh list)."""
    s, why = _poly_sign_kept(p, H)
    return s, list(why)


@caches.for_a_run
def _poly_sign_kept(p, H: Signs) -> tuple[int | None, tuple[str, ...]]:
    s, why = _poly_sign_of(p, H)
    return s, tuple(why)


def _poly_sign_of(p, H: Signs) -> tuple[int | None, list[str]]:
    if p == 0:
        return None, ["`0`: no strict sign"]
    undecided = []
    for g in _rewrites(p):
        c, factors = _factor_list(g)
        s, why = (1 if c > 0 else -1), []
        for f, m in factors:
            fs = _factor_sign(f, H)
            if fs is None:
                undecided.append(f"`{show(f)}`: sign undecided")
                break
            s *= fs**m
            why.append(f"`{show(f)}` {'>' if fs > 0 else '<'} 0")
        else:
            return s, [f"`{show(_factored(g))}`: " + ", ".join(why or ["constant"])]
    return None, [f"`{show(_factored(_rewrite(p, 0)))}`: " + undecided[0]]     # p expanded, factored above


def _sign_witness(answer, E, H: Signs) -> dict | None:
    return None if answer[0] is None else signed_witness(E, H)


@witnessing(_sign_witness)
def sign(E, H: Signs) -> tuple[int | None, list[str]]:
    """The strict sign of E under the hypotheses H, by inspection of its factors."""
    n, d = fraction(E)
    sn, wn = _poly_sign(n, H)
    sd, wd = _poly_sign(d, H)
    why = [f"numerator {wn[0]}"] + ([f"denominator {wd[0]}"] if d != 1 else [])
    return (sn * sd if sn and sd else None), why


@caches.for_a_run
def _factor_data(f, H: Signs) -> dict | None:
    """How one factor's sign is proved (:func:`_factor_sign`), as data for the kernel (memoised
    for a run, like :func:`_factor_sign`; its readers copy it)."""
    syms = sp.sympify(f).free_symbols
    if syms == {r}:
        fs = _factor_sign(f, H)
        return None if fs is None else {"poly": f, "how": "r", "sign": fs}
    for g in _rewrites(f):
        if g.free_symbols:
            sg = _term_sign(sp.Poly(g, *sorted(g.free_symbols, key=str)), H)
        else:
            sg = int(sp.sign(g)) or None
        if sg:
            return {"poly": f, "how": "terms", "form": g, "sign": sg}
    return None


@caches.for_a_run
def _poly_data(p, H: Signs) -> dict | None:
    """:func:`_poly_sign` as data: the rewritten form, its constant and factors with their proofs
    (memoised for a run: a sign's witness is built again for each check that reads it;
    :func:`certify.algebra.facts.signed` reads it without changing it)."""
    if p == 0:
        return None
    for g in _rewrites(p):
        c, factors = _factor_list(g)
        data = []
        for f, m in factors:
            d = _factor_data(f, H)
            if d is None:
                break
            data.append({**d, "mult": int(m)})
        else:
            return {"form": g, "constant": c, "factors": data}
    return None


def signed_witness(E, H: Signs) -> dict:
    """The strict sign of E under H by inspection, as a witness for the kernel (``signed``;
    ValueError if undecided)."""
    n, d = fraction(E)
    found = [_poly_data(n, H), _poly_data(d, H)]
    parts = [x for x in found if x is not None]
    if len(parts) != len(found):
        raise ValueError("sign undecided by inspection")
    sign_of = {1: 1, -1: -1}
    total = 1
    for part in parts:
        total *= (1 if part["constant"] > 0 else -1)
        for f in part["factors"]:
            total *= sign_of[f["sign"]] ** f["mult"]
    return facts.signed(E, n, d, parts, {str(a): int(sg) for a, sg in H.atoms}, total)


def _has_sign_witness(res, target, expected, H, witness=None) -> dict:
    return signed_witness(target if witness is None else witness, H)


def cancel(E) -> sp.Expr:
    """sp.cancel(E), by :func:`_flint_cancel` for a rational function of its symbols."""
    found = _flint_cancel(E)
    return found if found is not None else sp.cancel(E)


@caches.for_a_run
def _ratio(x, y) -> sp.Expr:
    """x / y in lowest terms (memoised for a run: a proportionality and its witness read the same ratios):
    sp.cancel's expression, by :func:`_flint_cancel` for a rational function of its symbols."""
    return cancel(x / y)


def _flint_cancel(E) -> sp.Expr | None:
    """sp.cancel(E) for a rational function E of its symbols: SymPy writes E = p/q, cancels in
    Poly over its symbols (_sort_gens: SymPy's order, lex) to the normal form of
    :func:`_flint_fraction` and returns P/Q as expressions; None for anything else."""
    E = sp.sympify(E)
    if E.is_Number:
        return None
    gens = tuple(_sort_gens(E.free_symbols))
    found = _flint_fraction(E, gens, "lex")
    if found is None:
        return None
    n, d = found
    return 1 * (_expr(n, gens) / _expr(d, gens))


def _ratios(v, w):
    """The ratios v_i / w_i where w_i ≢ 0 on the circles, in order, computed as they are asked for."""
    for x, y in zip(v, w):
        if normal_form(fraction(y)[0]) != 0:
            yield _ratio(x, y)


def _proportional_witness(res, v, w, H, ratio=None) -> dict | None:
    candidates = [ratio] if ratio is not None else _ratios(v, w)
    return next((signed_witness(k, H) for k in candidates if sign(k, H)[0] == 1), None)


@witnessing(_has_sign_witness)
def has_sign(target, expected: int, H: Signs, witness=None) -> Result:
    """target has the strict sign ``expected`` under H.  With a ``witness`` W (written in
    the named quantities of H): target ≡ W after unfolding their definitions, and W has
    the sign by inspection."""
    W = target if witness is None else witness
    ev = []
    if witness is not None:
        same = equal(target, H.unfold(W))
        ev.append(f"`{show(target)}` = `{show(W)}` " + ("(identity, both routes)" if same else "FAILS"))
        if not same:
            return Result(False, ev + same.evidence)
    s, why = sign(W, H)
    word = {1: "> 0", -1: "< 0", None: "sign undecided"}[s]
    return Result(s == expected, ev + [f"under {H.describe()}: {word}"] + why)


@witnessing(_proportional_witness)
def positively_proportional(v, w, H: Signs, ratio=None) -> Result:
    """v = k w with k > 0 under H: k is ``ratio`` if given, else v_i / w_i for the first
    component i where that quotient has a sign by inspection; then v − k w ≡ 0."""
    candidates = [ratio] if ratio is not None else _ratios(v, w)
    seen = []
    for k in candidates:          # the first ratio with a proved positive sign: the later ones are not formed
        seen.append(k)
        s, why = sign(k, H)
        if s == 1:
            same = equal(v, k * w)
            return Result(same.holds, [f"ratio k = `{show(sp.factor(k))}` > 0 under {H.describe()}: " + "; ".join(why),
                                       "v − k w ≡ 0: " + ("yes" if same else "no")] + same.evidence)
    tried = ", ".join(show(sp.factor(k)) for k in seen)
    return Result(False, [f"no ratio with a proved positive sign among {tried}"])


# ---------------------------------------------------------------- exact rational points
def circle_point(t) -> tuple[sp.Rational, sp.Rational]:
    """(cos, sin) of the angle with tan(angle/2) = t, a rational point of the circle."""
    t = sp.Rational(t)
    return (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)


def point(tθ, tφ, **values) -> dict:
    """A rational point of the circles (θ, φ from tan(θ/2) = tθ, tan(φ/2) = tφ) with values
    for r, λ and other symbols (by name)."""
    (c1, s1), (c2, s2) = circle_point(tθ), circle_point(tφ)
    pt = {cθ: c1, sθ: s1, cφ: c2, sφ: s2}
    names = {"r": r, "λ": lam}
    pt.update({names.get(k, sp.Symbol(k)): sp.Rational(x) for k, x in values.items()})
    return pt


def at(e, pt: dict):
    """The exact value of e (scalar or vector) at a rational point."""
    return sp.sympify(e).xreplace(pt)


def satisfied(H: Signs, pt: dict) -> bool:
    """Every hypothesis of H holds at the rational point (named quantities unfolded), and 0 < r < 1."""
    ok = all(sp.sign(at(H.unfold(a), pt)) == s for a, s in H.atoms)
    return ok and (r not in pt or 0 < pt[r] < 1)
