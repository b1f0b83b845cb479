"""One checker per kind of obligation (docs/verify.md).  A checker returns nothing when the
obligation holds, raises :class:`Failed` with the reason when it does not, and
:class:`Unsupported` when checking it needs something the kernel does not have."""
from __future__ import annotations

from fractions import Fraction

from .field import AtR0
from .poly import (
    at_r,
    d_lambda,
    deg,
    in_lambda,
    madd,
    mmul,
    mpoly,
    mul,
    rat,
    reduce_circles,
    resultant_in,
    sign,
    squarefree,
    sub,
    trim,
    upoly,
    value,
)
from .sturm import Algebraic, count, real_roots


class Failed(Exception):
    """The obligation is false (or malformed)."""


class Unsupported(Exception):
    """The kernel cannot check this obligation (the reason names what it lacks)."""


def _end(x):
    return None if x is None else rat(x)


def root_count(ob: dict, env) -> None:
    """Sturm's theorem: the number of distinct real roots of p in ]lo, hi] is V(lo) − V(hi)."""
    n = count(upoly(ob["poly"]), _end(ob.get("lo")), _end(ob.get("hi")))
    if n != ob["count"]:
        raise Failed(f"Sturm counts {n} roots in ]{ob.get('lo')}, {ob.get('hi')}], not {ob['count']}")


def algebraic(ob: dict, env) -> None:
    """A square-free polynomial with an interval holding exactly one of its roots (Sturm)."""
    try:
        Algebraic.of(ob["number"])
    except ValueError as exc:
        raise Failed(f"not an isolated algebraic number: {exc}") from None


def digits(ob: dict, env) -> None:
    """The number lies in [d − h, d + h], h half a unit of the last printed digit, exactly when
    it rounds to the printed decimal d; decided by comparing it with the two rationals."""
    a = Algebraic.of(ob["number"])
    text = ob["printed"]
    d = Fraction(text)
    places = len(text.split(".")[1]) if "." in text else 0
    h = Fraction(1, 2 * 10 ** places)
    inside = a.compare_rational(d - h) >= 0 and a.compare_rational(d + h) <= 0
    if inside != ob["holds"]:
        raise Failed(f"the number is {'inside' if inside else 'outside'} the rounding interval of {text}")


def compare(ob: dict, env) -> None:
    """sign(a − b) for two algebraic numbers (disjoint intervals, or a common root of the two
    polynomials in both intervals)."""
    s = Algebraic.of(ob["a"]).compare(Algebraic.of(ob["b"]))
    if s != ob["sign"]:
        raise Failed(f"sign(a − b) is {s}, not {ob['sign']}")


def sign_at(ob: dict, env) -> None:
    """The sign of a polynomial at an algebraic number (gcd for 0, else bisection until the
    polynomial has no root in the interval, then its value at an end)."""
    s = Algebraic.of(ob["number"]).sign_of(upoly(ob["poly"]))
    if s != ob["sign"]:
        raise Failed(f"the sign is {s}, not {ob['sign']}")


def _fraction_parts(data: dict, names: list) -> tuple[dict, dict]:
    def conv(part):
        return mpoly({"vars": names, "terms": part})
    return conv(data["num"]), conv(data.get("den", [["1", [0] * len(names)]]))


def _rf_mul(a: tuple, b: tuple) -> tuple:
    return mmul(a[0], b[0]), mmul(a[1], b[1])


def _rf_add(a: tuple, b: tuple) -> tuple:
    return madd(mmul(a[0], b[1]), mmul(b[0], a[1])), mmul(a[1], b[1])


def _det(entries: list, n: int, nvars: int) -> tuple:
    """The determinant by Laplace expansion along the first row (its definition, regrouped)."""
    if n == 1:
        return entries[0]
    total = ({}, {tuple([0] * nvars): Fraction(1)})
    for j in range(n):
        minor = [entries[i * n + c] for i in range(1, n) for c in range(n) if c != j]
        term = _rf_mul(entries[j], _det(minor, n - 1, nvars))
        if j % 2:
            term = ({k: -v for k, v in term[0].items()}, term[1])
        total = _rf_add(total, term)
    return total


def _side(side, names: list) -> list:
    """The components of one side: a list of rational functions, or {"product": [matrices],
    "entry": k} (the matrices multiplied by the definition of the product, then read row by row)."""
    if isinstance(side, list):
        return [_fraction_parts(x, names) for x in side]
    if "det" in side:
        m = side["det"]
        if m["rows"] != m["cols"]:
            raise Failed("the determinant of a matrix that is not square")
        return [_det([_fraction_parts(x, names) for x in m["entries"]], m["rows"], len(names))]
    mats = []
    for m in side["product"]:
        entries = [_fraction_parts(x, names) for x in m["entries"]]
        mats.append((m["rows"], m["cols"], entries))
    rows, cols, acc = mats[0]
    for r2, c2, e2 in mats[1:]:
        if cols != r2:
            raise Failed("the matrices of a product do not fit")
        zero = ({}, {tuple([0] * len(names)): Fraction(1)})
        out = []
        for i in range(rows):
            for j in range(c2):
                t = zero
                for k in range(cols):
                    t = _rf_add(t, _rf_mul(acc[i * cols + k], e2[k * c2 + j]))
                out.append(t)
        cols, acc = c2, out
    return [acc[side["entry"]]] if "entry" in side else acc


def identity(ob: dict, env) -> None:
    """lhs ≡ rhs, component by component, as rational functions of the variables, on the
    circles cos² + sin² = 1 of each pair: n_l·d_r − n_r·d_l reduces to 0 modulo the circles
    (a Gröbner basis, :func:`reduce_circles`), which holds exactly when the difference lies in
    the ideal; the ideal is prime and its real points are Zariski-dense in its zero set, so a
    non-zero normal form means the identity is false."""
    names = ob["vars"]
    pairs = [(names.index(c), names.index(s)) for c, s in ob.get("circles", [])]
    modulo = None
    if ob.get("modulo"):
        k = names.index(ob["modulo"]["var"])
        modulo = (k, mpoly({"vars": names, "terms": ob["modulo"]["poly"]}))
        top = max((key[k] for key in modulo[1]), default=0)
        lead = {key: v for key, v in modulo[1].items() if key[k] == top}
        unit = tuple(top if i == k else 0 for i in range(len(names)))
        if top < 1 or list(lead) != [unit]:
            raise Failed("the modulus is not monic in its variable (up to a constant)")
        modulo = (k, {key: v / lead[unit] for key, v in modulo[1].items()})
    left, right = _side(ob["lhs"], names), _side(ob["rhs"], names)
    if len(left) != len(right):
        raise Failed("the two sides have different numbers of components")
    zero = True
    for k, ((nl, dl), (nr, dr)) in enumerate(zip(left, right)):
        if not reduce_circles(dl, pairs) or not reduce_circles(dr, pairs):
            raise Failed(f"component {k + 1}: a denominator vanishes identically")
        diff = reduce_circles(madd(mmul(nl, dr), mmul(nr, dl), -1), pairs)
        if modulo is not None:
            diff = reduce_monic(diff, *modulo)
        if diff:
            zero = False
    if zero != ob["holds"]:
        raise Failed("the two sides are " + ("equal" if zero else "not equal") +
                     f" (the obligation says {'equal' if ob['holds'] else 'not equal'})")


def reduce_monic(p: dict, k: int, m: dict) -> dict:
    """The remainder of p by m, m monic in variable k of degree d (division by a monic
    polynomial needs no fraction, and the remainder, of degree < d in that variable, is 0 exactly
    when m divides p)."""
    d = max(key[k] for key in m)
    lower = {key: v for key, v in m.items() if key[k] < d}          # λ^d ≡ −lower
    while True:
        high = {key: v for key, v in p.items() if key[k] >= d}
        if not high:
            return p
        key, v = max(high.items(), key=lambda kv: kv[0][k])
        shift = tuple(e - d if i == k else e for i, e in enumerate(key))
        p = madd(p, {key: v}, -1)                                    # remove v·x^shift·λ^d ...
        p = madd(p, mmul({shift: v}, lower), -1)                     # ... and add v·x^shift·(−lower)


_NAMES = ("N0", "N1", "D0", "D1", "delta")


def _norm(p0: dict, p1: dict, delta: dict) -> dict:
    """N₀² − N₁²Δ: the product of N₀ + N₁√Δ and its conjugate, zero where either is."""
    return madd(mmul(p0, p0), mmul(mmul(p1, p1), delta), -1) if p1 else p0


def bounding(cp: dict, parts: dict) -> list:
    """The polynomials in r whose real roots bound the cells: Res_λ(cp, ∂cp/∂λ) (zero where
    two eigenvalues meet, or where the leading coefficient vanishes), the leading coefficient
    of cp in λ, and Res_λ(P, cp) for P the norms of the numerator and denominator of g and Δ
    (a resultant vanishes at r where P and cp have a common root λ).  Off their roots the real
    branches are continuous and separate, and g keeps its sign on each (continuity, no zero)."""
    out = [resultant_in(cp, d_lambda(cp)), in_lambda(cp)[-1]]
    delta = parts.get("delta") or {}
    polys = [_norm(parts["N0"], parts.get("N1") or {}, delta), _norm(parts["D0"], parts.get("D1") or {}, delta)]
    if delta:
        polys.append(delta)
    for P in polys:
        if not P:
            raise Unsupported("a part of the condition is identically 0")
        if any(any(k) for k in P):
            R = resultant_in(P, cp)
            if not R:
                raise Unsupported("a norm of the condition vanishes on a whole branch (Res_λ ≡ 0): the "
                                  "kernel lacks factoring cp over Q(r)")
            out.append(R)
    return [squarefree(b) for b in out if deg(b) > 0]


def _roots_inside(B: list, lo: Algebraic, hi: Algebraic) -> int:
    """The number of roots of B in ]lo, hi[ (lo < hi algebraic): refine each end until B has
    no root in its interval but the end itself, then count on ]lo.hi, hi.lo] (Sturm)."""
    for a in (lo, hi):
        if not a.rational:
            for _ in range(10_000):
                own = 1 if a.sign_of(B) == 0 else 0
                if count(B, a.lo, a.hi) == own:
                    break
                a.bisect()
    while not (lo.hi <= hi.lo):
        lo.bisect()
        hi.bisect()
    n = count(B, lo.hi, hi.lo)
    if hi.rational and hi.sign_of(B) == 0:
        n -= 1
    return n


def _sign_of_surd(p0, p1, delta, sg, mul_, sub_) -> int:
    """sign(P₀ + P₁√Δ) at a point where Δ ≥ 0, sg the sign of a polynomial there: the signs of
    P₀ and P₁ decide unless they differ; then P₀ + P₁√Δ has the sign of P₀ when P₀² > P₁²Δ
    and the opposite one otherwise."""
    s0 = sg(p0) if p0 else 0
    s1 = sg(p1) if p1 else 0
    if s1 == 0 or s0 == s1:
        return s0 if s0 else s1
    if s0 == 0:
        return s1
    return s0 * sg(sub_(mul_(p0, p0), mul_(mul_(p1, p1), delta)))


def sign_of_condition(at: dict, sg, mul_=mul, sub_=sub):
    """The sign of g = (N₀ + N₁√Δ)/(D₀ + D₁√Δ) at a point (r, λ), from its parts specialised
    there (``at``: their products by mul_, sub_; their signs by sg): None when Δ < 0 (x not
    real); √Δ = 0 when Δ = 0."""
    delta = at.get("delta") or []
    if delta:
        sd = sg(delta)
        if sd < 0:
            return None
        if sd == 0:
            at = {k: v for k, v in at.items() if k not in ("N1", "D1")}
    sn = _sign_of_surd(at["N0"], at.get("N1") or [], delta, sg, mul_, sub_)
    sden = _sign_of_surd(at["D0"], at.get("D1") or [], delta, sg, mul_, sub_)
    if sden == 0:
        raise Failed("the condition has a pole there")
    return sn * sden


def _polys(ob: dict) -> tuple[dict, dict]:
    names = ["r", "λ"]
    cp = mpoly({"vars": names, "terms": ob["cp"]})
    parts = {k: mpoly({"vars": names, "terms": ob["parts"][k]}) for k in _NAMES if ob["parts"].get(k)}
    parts.setdefault("N0", {})
    parts.setdefault("D0", {})
    return cp, parts


def point_signs(ob: dict, r0, env: dict) -> tuple[int, object]:
    """(the number of real roots of cp(r0, λ) with multiplicity, branch k -> the sign of g at the
    k-th largest), r0 algebraic: exact arithmetic in Q(r0)[λ] (:class:`field.AtR0`), the roots
    isolated by Sturm's theorem, the sign of each polynomial g needs at a root by its Tarski
    query on the root's interval (the sign itself: one root there)."""
    memo, key = env.setdefault("points", {}), (str(ob["cp"]), str(r0))
    if key not in memo:
        cp, _parts = _polys(ob)
        A, cpl = AtR0(Algebraic.of(r0)), in_lambda(cp)
        memo[key] = (A, cpl, A.branches(cpl))
    A, cpl, branches = memo[key]
    done, pkey = env.setdefault("point_signs", {}), key + (str(ob["parts"]),)

    def sign_on(k: int):
        if (pkey, k) not in done:
            at = {name: in_lambda(P) for name, P in _polys(ob)[1].items()}
            done[pkey, k] = sign_of_condition(at, lambda P: A.taq(P, cpl, *branches[k]), A.mul, A.sub)
        return done[pkey, k]
    return len(branches), sign_on


def branch_signs_at(ob: dict, env) -> None:
    """The signs of g on the real eigenvalue branches of cp at an algebraic r0 (largest first,
    each root by its multiplicity): :func:`point_signs`; "?" not claimed, "nonzero" ≠ 0."""
    n, sign_on = point_signs(ob, ob["r"], env)
    if n != len(ob["signs"]):
        raise Failed(f"cp(r0, λ) has {n} real roots (with multiplicity), not {len(ob['signs'])}")
    for j, s in enumerate(ob["signs"]):
        got = "?" if s == "?" else sign_on(j)
        if got != s and not (s == "nonzero" and got in (1, -1)):
            raise Failed(f"branch {j}: the sign at r0 is {got}, not {s}")


def load_table(ob: dict):
    """The table's polynomials and cell ends, read."""
    cp, parts = _polys(ob)
    ends = [Algebraic.of(e) for e in ob["ends"]]
    return cp, parts, ends


def sign_table(ob: dict, env) -> None:
    """The signs of g on the real eigenvalue branches λ₀ > λ₁ > ... of cp(λ, r) over each cell
    ]e_i, e_{i+1}[: no bounding polynomial (:func:`bounding`) has a root in the cell, so the
    number of real branches and g's sign on each are those at the cell's sample (real roots of
    cp(λ, r₀) isolated by Sturm, the sign of g by exact arithmetic at each)."""
    cp, parts, ends = load_table(ob)
    if len(ob["samples"]) != len(ends) - 1 or len(ob["signs"]) != len(ends) - 1:
        raise Failed("cells, samples and signs do not match")
    for a, b in zip(ends, ends[1:]):
        if a.compare(b) >= 0:
            raise Failed("the cell ends are not increasing")
    key = (str(ob["cp"]), str(ob["parts"]))
    if key not in env.setdefault("bounding", {}):
        env["bounding"][key] = bounding(cp, parts)
    for k, (a, b) in enumerate(zip(ends, ends[1:])):
        for B in env["bounding"][key]:
            if _roots_inside(B, a, b):
                raise Failed(f"cell {k + 1}: a bounding polynomial of degree {deg(B)} has a root inside")
        r0 = rat(ob["samples"][k])
        if a.compare_rational(r0) >= 0 or b.compare_rational(r0) <= 0:
            raise Failed(f"cell {k + 1}: the sample {r0} is not inside the cell")
        lams = real_roots(at_r(cp, r0))
        claimed = ob["signs"][k]
        if len(lams) != len(claimed):
            raise Failed(f"cell {k + 1}: cp(λ, {r0}) has {len(lams)} real roots, not {len(claimed)}")
        for j, (lam, s) in enumerate(zip(lams, claimed)):
            if s == "?":            # a sign this table does not claim
                continue
            if s == "undecided":
                raise Unsupported(f"cell {k + 1}: the engine left branch {j} undecided")
            got = sign_of_condition({name: at_r(P, r0) for name, P in parts.items()}, lam.sign_of)
            if got != s:
                raise Failed(f"cell {k + 1}, branch {j}: the sign at r = {r0} is {got}, not {s}")


def _key(s):
    return "null" if s is None else str(s)


def signs_query(ob: dict, env) -> None:
    """The set of signs a verified table gives on one branch over ]lo, hi[: the union over the
    cells that meet it (a branch absent on a cell gives "missing"), and with include_points the
    signs at the interior cell ends (critical values, algebraic r₀: :func:`point_signs`)."""
    table = env["obligations"].get(ob["table"])
    if table is None or table.get("kind") != "sign_table":
        raise Failed(f"no sign table {ob['table']!r}")
    if ob["table"] not in env.setdefault("verified", set()):
        raise Failed(f"the sign table {ob['table']} is not verified")
    _cp, _parts, ends = load_table(table)
    lo = Algebraic.of(ob["lo"]) if ob.get("lo") is not None else ends[0]
    hi = Algebraic.of(ob["hi"]) if ob.get("hi") is not None else ends[-1]
    if ends[0].compare(lo) > 0 or ends[-1].compare(hi) < 0:
        raise Failed("the interval is not inside the table's")
    got = set()
    branch = ob["branch"]
    for k, (a, b) in enumerate(zip(ends, ends[1:])):
        if b.compare(lo) <= 0 or a.compare(hi) >= 0:
            continue
        row = table["signs"][k]
        got.add(_key(row[branch]) if branch < len(row) else "missing")
    if ob.get("include_points", True):
        if "undecided" in ob["result"]:
            raise Unsupported("the engine left a sign at a critical value undecided")
        for k, e in enumerate(ends[1:-1]):
            if lo.compare(e) < 0 < hi.compare(e):
                n, sign_on = point_signs(table, table["ends"][k + 1], env)
                got.add(_key(sign_on(branch)) if branch < n else "missing")
    claimed = {_key(s) for s in ob["result"]}
    if got != claimed:
        raise Failed(f"the signs on branch {branch} are {sorted(got)}, not {sorted(claimed)}")


def _term_signs(h: dict, hyp: list) -> set:
    """The signs of the terms of h under the hypotheses (a variable of unknown sign must occur
    to an even power: such a term is ≥ 0 times its coefficient's sign, "weak")."""
    out = set()
    for k, v in h.items():
        s, strict = sign(v), True
        for e, hs in zip(k, hyp):
            if e and hs is None:
                if e % 2:
                    return {None}
                strict = False
            elif e:
                s *= hs ** e
        out.add((s, strict))
    return out


def _factor_sign(f: dict, names: list, pairs: list, hyp: list) -> int:
    """The strict sign of a factor: a polynomial in r alone with no root in ]0, 1[ (Sturm) has
    the sign of its value at 1/2 on all of ]0, 1[ (intermediate values); otherwise a form
    congruent to it modulo the circles whose terms all have one strict sign under the
    hypotheses (a sum of terms of one sign, one of them strict, has that sign)."""
    poly = mpoly({"vars": names, "terms": f["poly"]})
    if f["how"] == "r":
        k = names.index("r")
        if any(e for key in poly for i, e in enumerate(key) if i != k):
            raise Failed("a factor said to be in r alone has other variables")
        u = [Fraction(0)] * (max((key[k] for key in poly), default=0) + 1)
        for key, v in poly.items():
            u[key[k]] += v
        u = trim(u)
        if count(u, Fraction(0), Fraction(1)) - (1 if not sum(u) else 0):
            raise Failed("a factor in r has a root in ]0, 1[")
        return sign(value(u, Fraction(1, 2)))
    form = mpoly({"vars": names, "terms": f["form"]})
    if reduce_circles(madd(poly, form, -1), pairs):
        raise Failed("a factor's rewritten form differs from it modulo the circles")
    signs = _term_signs(form, hyp)
    if not form:
        raise Failed("a factor is 0")
    if len({s for s, _ in signs}) != 1 or None in {s for s, _ in signs} or not any(st for _, st in signs):
        raise Failed("a factor's terms do not all have one strict sign")
    return next(iter(signs))[0]


def _part_sign(part: dict, given: dict, names: list, pairs: list, hyp: list) -> int:
    """The sign of a polynomial from a congruent form c·Π f^m (expanded exactly and compared)."""
    form = mpoly({"vars": names, "terms": part["form"]})
    if reduce_circles(madd(given, form, -1), pairs):
        raise Failed("the rewritten form differs from the expression modulo the circles")
    c = rat(part["constant"])
    product = {tuple([0] * len(names)): c} if c else {}
    s = sign(c)
    for f in part["factors"]:
        poly = mpoly({"vars": names, "terms": f["poly"]})
        for _ in range(f["mult"]):
            product = mmul(product, poly)
        fs = _factor_sign(f, names, pairs, hyp)
        if fs != f["sign"]:
            raise Failed(f"a factor has the sign {fs}, not {f['sign']}")
        s *= fs ** f["mult"]
    if madd(product, form, -1):
        raise Failed("the factors do not multiply to the form")
    return s


def signed(ob: dict, env) -> None:
    """n/d has a strict sign under sign hypotheses on the variables (and 0 < r < 1): the sign
    of n and of d, each from a factorisation of a form congruent to it modulo the circles."""
    names = ob["vars"]
    pairs = [(names.index(c), names.index(s)) for c, s in ob.get("circles", [])]
    hyp = [ob["hyp"].get(n) for n in names]
    if any(h not in (None, 1, -1) for h in hyp):
        raise Failed("a hypothesis is not a strict sign")
    n = mpoly({"vars": names, "terms": ob["expr"]["num"]})
    d = mpoly({"vars": names, "terms": ob["expr"]["den"]})
    s = _part_sign(ob["num"], n, names, pairs, hyp) * _part_sign(ob["den"], d, names, pairs, hyp)
    if s != ob["sign"]:
        raise Failed(f"the sign is {s}, not {ob['sign']}")


def resultant(ob: dict, env) -> None:
    """Res_λ(f, g) (the Sylvester determinant, :func:`resultant_in`; for g = ∂f/∂λ with f monic
    in λ it is ± the discriminant) against a given polynomial P in r: "proportional" (equal up to
    a non-zero constant) or "same_factors" (the same square-free part: the same roots)."""
    names = ["r", "λ"]
    f = mpoly({"vars": names, "terms": ob["f"]})
    g = d_lambda(f) if ob["g"] == "d/dλ" else mpoly({"vars": names, "terms": ob["g"]})
    R, P = resultant_in(f, g), upoly(ob["poly"])
    if not R or not P:
        raise Failed("a resultant or the given polynomial is 0")
    if ob["relation"] == "proportional":
        same = [c / R[-1] for c in R] == [c / P[-1] for c in P]
    elif ob["relation"] == "same_factors":
        same = squarefree(R) == squarefree(P)
    else:
        raise Failed(f"unknown relation {ob['relation']!r}")
    if same != ob["holds"]:
        raise Failed(f"the resultant is {'' if same else 'not '}{ob['relation'].replace('_', ' ')} to the polynomial")


def unsupported(ob: dict, env) -> None:
    """A fact the engine used that has no obligation the kernel can check (the reason says why)."""
    raise Unsupported(ob.get("reason", "not expressible in the obligation language"))


CHECKERS = {f.__name__: f for f in (root_count, algebraic, digits, compare, sign_at, identity, sign_table,
                                    signs_query, branch_signs_at, signed, resultant, unsupported)}
