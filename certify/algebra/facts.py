"""The engine's answers as obligations for the independent kernel (docs/verify.md): the
builders that :func:`certify.obligations.fact` calls with a deciding function's arguments
and answer.  Polynomials become lists of exact coefficients, numbers "p/q" strings."""
from __future__ import annotations

import copy
from fractions import Fraction

import flint
import sympy as sp

from certify import caches
from certify.obligations import recording_now


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


def upoly(p) -> list:
    """A univariate polynomial (fmpz_poly, fmpq_poly) as coefficients, lowest first."""
    return [rational(c) for c in p.coeffs()]


def ring_terms_data(terms) -> list:
    """Terms (c, i, j) of a polynomial in r, λ (c r^i λ^j) as [["p/q", [i, j]], ...], sorted."""
    return sorted([rational(c), [int(i), int(j)]] for c, i, j in terms)


@caches.by_identity
def _cp_data(ring_cp) -> list:
    """The terms of a spectrum's cp (``spectrum.ring_cp``: the same object in every query of a
    table) as a record holds them; the list is shared by the records that hold it (a record is
    never modified)."""
    from .poly import ring_terms
    return ring_terms_data(ring_terms(ring_cp))


@caches.by_identity
def _terms_data(terms) -> list:
    """:func:`ring_terms_data` of a condition's terms, memoised by identity (shared as above)."""
    return ring_terms_data(terms)


def _parts_data(cond) -> dict:
    """The non-zero parts of a condition (N0, N1, D0, D1, delta) as a record holds them."""
    return {k: _terms_data(v) for k, v in cond.terms.items() if v}


_CIRCLE_ARGS = ("θ", "φ")


def rational_function(e, gens: list) -> dict:
    """A SymPy expression, a rational function of ``gens`` over Q, as {"num": terms, "den": terms}
    (a fresh copy of the one computed for the same expression and generators since the caches'
    last reset: the same facts are recorded over and over)."""
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
    from .poly import fraction_tree
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
    """The variables of an identity: its symbols, and cos, sin of a symbol that occurs only
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


def identity(answer: bool, lhs, rhs, modulo=None, var=None) -> dict:
    """lhs ≡ rhs (scalars or vectors) on the circles cos² + sin² = 1 (and modulo ``modulo``, a
    polynomial monic in λ, or in ``var`` when given: r − r₀ for the value at r₀), with the
    engine's answer."""
    if isinstance(lhs, sp.MatrixBase) or isinstance(rhs, sp.MatrixBase):
        left, right = list(lhs), list(rhs)
        if lhs.shape != rhs.shape:
            raise ValueError("shapes differ")
    else:
        left, right = [lhs], [rhs]
    gens, circles = generators(*left, *right, *([modulo] if modulo is not None else []))
    names = [str(g) for g in gens]
    out = {"kind": "identity", "vars": names, "circles": circles,
           "lhs": [rational_function(e, gens) for e in left],
           "rhs": [rational_function(e, gens) for e in right], "holds": bool(answer)}
    if modulo is not None:
        from .poly import lam
        out["modulo"] = {"var": str(lam if var is None else var), "poly": rational_function(modulo, gens)["num"]}
    return out


def number_of(a) -> dict | str:
    """An Algebraic as {"poly", "lo", "hi"} with a canonical interval: the dyadic
    [⌊2^k α⌋/2^k, (⌊2^k α⌋+1)/2^k] for the first k in 8, 16, 32, ... that isolates α (so that
    the record depends on the number only, not on how far its interval was refined)."""
    if not (hasattr(a, "p") and hasattr(a, "floor_scaled")):
        return rational(a)
    if a.is_rational:
        return rational(a.lo)
    if recording_now():
        # outside a fact's builder the comparisons made here are facts of the certificate
        # (compare_rational records them): made every time
        return _dyadic(a)
    key = a.key()                    # equal keys, equal numbers: the same record (memoised)
    found = _NUMBERS.get(key)
    if found is None:
        found = _NUMBERS[key] = _dyadic(a)
    return dict(found, poly=list(found["poly"])) if isinstance(found, dict) else found


_NUMBERS: dict = {}              # key of an Algebraic -> its record by number_of
caches.register(_NUMBERS.clear)


def _dyadic(a) -> dict | str:
    """:func:`number_of` of an irrational-looking Algebraic, computed."""
    from .poly import Q
    from .sturm import count_roots
    b = copy.copy(a)
    for k in (8, 16, 32, 64, 128, 256, 512, 1024):
        s = 2 ** k
        L = b.floor_scaled(s)
        lo, hi = Q(L, s), Q(L + 1, s)
        if b.compare_rational(lo) == 0:
            return rational(lo)
        if b.p(lo) != 0 and b.p(hi) != 0 and count_roots(b.p, lo, hi) == 1:
            return {"poly": upoly(b.p), "lo": rational(lo), "hi": rational(hi)}
    raise ValueError("no dyadic isolating interval up to 2^-1024")


def root_count(n, p, a=None, b=None, *rest, **kw) -> dict:
    """The number of distinct real roots of p in ]a, b] (None: ∓∞)."""
    return {"kind": "root_count", "poly": upoly(p), "lo": None if a is None else rational(a),
            "hi": None if b is None else rational(b), "count": int(n)}


def compare(s, a, b) -> dict:
    """sign(a − b) of two algebraic numbers (or one and a rational)."""
    return {"kind": "compare", "a": number_of(a), "b": number_of(b), "sign": int(s)}


def digits(inside, a, printed) -> dict:
    """The number rounds (or not) to the printed decimal."""
    return {"kind": "digits", "number": number_of(a), "printed": str(printed), "holds": bool(inside)}


def sign_at(s, poly, alpha, *rest, **kw) -> dict:
    """The sign of a univariate polynomial at an algebraic number."""
    import flint
    P = flint.fmpq_poly(poly) if not isinstance(poly, flint.fmpq_poly) else poly
    return {"kind": "sign_at", "poly": upoly(P), "number": number_of(alpha), "sign": int(s)}


def _sign_code(s):
    """A sign as the kernel reads it: 1, -1, 0, null (x not real), "missing", "undecided",
    "nonzero"."""
    if s is None or s in (1, -1, 0) and not isinstance(s, str):
        return s if s is None else int(s)
    return s if s in ("missing", "nonzero") else "undecided"


def cell_branches(answer, cell) -> dict:
    """The number of real eigenvalues on a cell of a sign table (no sign claimed)."""
    if cell.table is None:
        raise ValueError("a cell outside a sign table")
    spectrum, cond = cell.table.source
    return {"kind": "sign_table", "cp": _cp_data(spectrum.ring_cp), "parts": _parts_data(cond),
            "ends": [number_of(cell.lo), number_of(cell.hi)], "samples": [rational(cell.sample)],
            "signs": [["?"] * len(answer)]}


def sign_around(answer, table, branch, point) -> list:
    """changes_at / keeps_sign_at: the signs on ``branch`` over the two cells beside ``point``."""
    cells = table._around(point)
    if cells is None:
        raise ValueError("no cell on one side of the point")
    out = []
    for cell in cells:
        sign = cell.signs[branch] if branch < len(cell.signs) else "missing"
        out.append(sign_query([sign], table, branch, cell.lo, cell.hi, include_points=False))
    return out


def sign_query(result, table, branch, lo=None, hi=None, include_points=True):
    """The signs a sign table gives on one branch over ]lo, hi[, with the part of the table
    it reads: the cells that meet ]lo, hi[, their samples and the signs on that branch."""
    spectrum, cond = table.source
    if cond.degenerate:
        raise ValueError("a degenerate condition (a norm vanishing on a whole branch)")
    lo_ = table.interval[0] if lo is None else lo
    hi_ = table.interval[1] if hi is None else hi
    cells = [c for c in table.cells if not (c.hi <= lo_ or c.lo >= hi_)]
    rows = []
    for c in cells:
        row = ["?"] * len(c.branches)
        if branch < len(row):
            row[branch] = _sign_code(c.signs[branch])
        rows.append(row)
    data = {"kind": "sign_table", "cp": _cp_data(spectrum.ring_cp), "parts": _parts_data(cond),
            "ends": [number_of(cells[0].lo)] + [number_of(c.hi) for c in cells],
            "samples": [rational(c.sample) for c in cells], "signs": rows}
    return {"kind": "signs_query", "table": data, "branch": int(branch),
            "lo": None if lo is None else number_of(lo), "hi": None if hi is None else number_of(hi),
            "include_points": bool(include_points), "result": sorted((_sign_code(s) for s in result), key=str)}


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


def product_identity(holds: bool, factors: list, rhs, entry: int | None = None) -> dict:
    """The product of the matrices ``factors`` (left to right) equals ``rhs`` (a matrix, or its
    entry number ``entry`` read row by row), as the kernel multiplies it."""
    rhs_list = list(rhs) if isinstance(rhs, sp.MatrixBase) else [rhs]
    if entry is not None and len(rhs_list) > 1:
        rhs_list = [rhs_list[entry]]
    gens, circles = generators(*[e for F in factors for e in F], *rhs_list)
    names = [str(g) for g in gens]
    product: dict[str, object] = {"product": [{"rows": F.shape[0], "cols": F.shape[1],
                            "entries": [rational_function(e, gens) for e in F]} for F in factors]}
    if entry is not None:
        product["entry"] = int(entry)
    return {"kind": "identity", "vars": names, "circles": circles, "lhs": product,
            "rhs": [rational_function(e, gens) for e in rhs_list], "holds": bool(holds)}


def products_identity(holds: bool, left: list, right: list) -> dict:
    """The product of the matrices ``left`` equals that of ``right`` (each multiplied by the kernel)."""
    gens, circles = generators(*[e for F in left + right for e in F])
    names = [str(g) for g in gens]

    def product(factors):
        return {"product": [{"rows": F.shape[0], "cols": F.shape[1],
                             "entries": [rational_function(e, gens) for e in F]} for F in factors]}
    return {"kind": "identity", "vars": names, "circles": circles, "lhs": product(left), "rhs": product(right),
            "holds": bool(holds)}


def resultant(holds: bool, f, g, poly, relation: str) -> dict:
    """Res_λ(f, g) (g "d/dλ" for ∂f/∂λ) is proportional to, or has the factors of, ``poly``."""
    from .poly import lam, r
    def terms(e):
        P = sp.Poly(sp.expand(e), r, lam, domain="QQ")
        return sorted([rational(c), list(m)] for m, c in P.terms())
    P = sp.Poly(sp.expand(poly), r, domain="QQ")
    return {"kind": "resultant", "f": terms(f), "g": g if isinstance(g, str) else terms(g),
            "poly": [rational(c) for c in P.all_coeffs()[::-1]], "relation": relation, "holds": bool(holds)}


def _point_claims(signs, only=None) -> list:
    """Signs on the branches at a point as the kernel reads them; "?" where nothing is claimed
    (an undecided sign, or a branch other than ``only``)."""
    out = []
    for k, s in enumerate(signs):
        code = _sign_code(s)
        out.append("?" if code in ("undecided", "missing") or (only is not None and k != only) else code)
    return out


def branch_signs(signs, spectrum, cond, rc, only=None) -> dict:
    """The signs of a condition on the real branches of cp at the algebraic r = rc (largest
    first, a double root twice): the kernel isolates them in Q(rc)[λ] and signs g exactly."""
    if signs is None:
        raise ValueError("the branches at this r were not isolated")
    return {"kind": "branch_signs_at", "cp": _cp_data(spectrum.ring_cp), "parts": _parts_data(cond), "r": number_of(rc),
            "signs": _point_claims(signs, only)}


def point_signs(answer, spectrum, cond, rc, *rest, **kw) -> dict:
    """Spectrum.sign_at_point: the signs of a condition on every branch at rc."""
    return branch_signs(answer, spectrum, cond, rc)


def table_points(answer, table) -> list:
    """SignTable.points: the signs at every critical value of the table."""
    spectrum, cond = table.source
    return [branch_signs(answer[k], spectrum, cond, rc) for k, rc in enumerate(table.critical)]


def vanishing(answer, spectrum, h, rc, branch, *rest, **kw) -> dict:
    """Spectrum.vanishes_at: the polynomial h is 0 (or not) on ``branch`` at rc."""
    from sympy.polys.rings import PolyElement

    from .branches import Condition
    from .poly import RING, to_ring
    H = h if isinstance(h, PolyElement) else to_ring(sp.expand(sp.sympify(h)))
    cond = Condition("h", (H, RING.zero), (RING.one, RING.zero), None, None)
    n = len(spectrum.branches_at(rc) or [])
    if branch >= n:
        raise ValueError("the branch is not isolated at this r")
    return branch_signs([0 if answer else "nonzero"] * n, spectrum, cond, rc, only=branch)


def table_point(answer, table, rc, branch) -> dict:
    """The sign of a table on ``branch`` at its critical value rc."""
    spectrum, cond = table.source
    k = next(i for i, c in enumerate(table.critical) if c == rc)
    return branch_signs(table.points[k], spectrum, cond, rc, only=branch)


def determinant_identity(holds: bool, matrix, rhs) -> dict:
    """det(matrix) = rhs, the determinant expanded by the kernel."""
    gens, circles = generators(*list(matrix), rhs)
    return {"kind": "identity", "vars": [str(g) for g in gens], "circles": circles,
            "lhs": {"det": {"rows": matrix.shape[0], "cols": matrix.shape[1],
                            "entries": [rational_function(e, gens) for e in matrix]}},
            "rhs": [rational_function(rhs, gens)], "holds": bool(holds)}
