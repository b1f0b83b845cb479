"""Polynomials over Q and Z, in the Python standard library alone.

Univariate polynomials are lists of coefficients (Fractions, or ints), lowest degree first, with
no trailing zero (the zero polynomial is ``[]``); a polynomial in (r, λ) is also a list over the
powers of λ of polynomials in r (:func:`badd`, :func:`bmul`).  Multivariate polynomials are dicts
mapping an exponent tuple to a non-zero Fraction.  Everything is exact.
"""
from __future__ import annotations

from fractions import Fraction
from math import factorial
from math import gcd as igcd


def trim(p) -> list:
    """p without trailing zero coefficients (or zero polynomials): the same polynomial."""
    p = list(p)
    while p and not p[-1]:
        p.pop()
    return p


def deg(p: list) -> int:
    """The degree (−1 for the zero polynomial)."""
    return len(p) - 1


def add(p: list, q: list, c=1) -> list:
    """p + c·q, coefficient by coefficient."""
    out = list(p) + [0] * (len(q) - len(p))
    for i, y in enumerate(q):
        out[i] += y if c == 1 else c * y
    return trim(out)


def scale(p: list, c) -> list:
    """c·p."""
    return trim(c * a for a in p)


def sub(p: list, q: list) -> list:
    """p − q."""
    return add(p, q, -1)


def mul(p: list, q: list) -> list:
    """p·q, the Cauchy product; long integer ones by Kronecker substitution (one integer product of
    p(2^k), q(2^k), whose base-2^k digits, |digit| < 2^(k−1), are the coefficients)."""
    if not p or not q:
        return []
    ints = type(p[0]) is int and type(q[0]) is int
    if ints and min(len(p), len(q)) >= 16 and all(type(a) is int for a in p + q):
        k = (max(map(abs, p)) * max(map(abs, q)) * min(len(p), len(q))).bit_length() + 1
        C = sum(a << (k * i) for i, a in enumerate(p)) * sum(b << (k * i) for i, b in enumerate(q))
        out, mask = [], (1 << k) - 1
        for _ in range(len(p) + len(q) - 1):
            d = C & mask
            d -= (1 << k) if d >> (k - 1) else 0
            out.append(d)
            C = (C - d) >> k
        return trim(out)
    out = [0 if ints else Fraction(0)] * (len(p) + len(q) - 1)
    for i, a in enumerate(p):
        if a:
            for j, b in enumerate(q):
                out[i + j] += a * b
    return trim(out)


def badd(P: list, Q: list, c=1) -> list:
    """P + c·Q in Q[r][λ]."""
    return trim(add(P[j] if j < len(P) else [], Q[j] if j < len(Q) else [], c) for j in range(max(len(P), len(Q))))


def bmul(P: list, Q: list) -> list:
    """P·Q in Q[r][λ] (the Cauchy product over Q[r])."""
    out: list = [[] for _ in range(max(len(P) + len(Q) - 1, 0))]
    for i, a in enumerate(P):
        for j, b in enumerate(Q):
            if a and b:
                out[i + j] = add(out[i + j], mul(a, b))
    return trim(out)


def bderiv(P: list) -> list:
    """∂P/∂λ in Q[r][λ]."""
    return [scale(c, i) for i, c in enumerate(P)][1:]


def divmod_(p: list, q: list) -> tuple[list, list]:
    """(quotient, remainder) of Euclidean division over the field Q: p = quotient·q +
    remainder with deg remainder < deg q (q ≠ 0)."""
    if not q:
        raise ZeroDivisionError("division by the zero polynomial")
    r, quo = list(p), [Fraction(0)] * max(len(p) - len(q) + 1, 0)
    lead = q[-1]
    while len(r) >= len(q):
        c = Fraction(r[-1]) / lead
        k = len(r) - len(q)
        quo[k] = c
        for j, b in enumerate(q):
            r[k + j] -= c * b
        r = trim(r)
    return trim(quo), r


def monic(p: list) -> list:
    """p divided by its leading coefficient (same roots)."""
    return scale(p, Fraction(1) / p[-1]) if p else []


def integer_primitive(p: list) -> list:
    """p times a positive rational, with coprime integer coefficients (same roots, same signs)."""
    den = 1
    for a in p:
        den = den * Fraction(a).denominator // igcd(den, Fraction(a).denominator)
    ints = [int(a * den) for a in p]
    g = 0
    for a in ints:
        g = igcd(g, a)
    return [a // g for a in ints] if g else []


def pseudo_remainder(a: list, b: list) -> list:
    """prem(a, b) = lc(b)^(deg a − deg b + 1)·a mod b, in integers (b ≠ 0): Euclidean division
    of lc(b)^k·a needs no fraction."""
    r, lb, n = list(a), b[-1], len(b)
    for _ in range(max(len(a) - n + 1, 0)):
        if len(r) < n:
            r = [x * lb for x in r]
            continue
        c, k = r[-1], len(r) - n
        r = [x * lb for x in r]
        for j, y in enumerate(b):
            r[k + j] -= c * y
        r = trim(r)
    return r


def gcd(p: list, q: list) -> list:
    """The monic gcd by Euclid's algorithm (Q[x] is a Euclidean domain), run on primitive
    integer polynomials with pseudo-remainders (each differs from the remainder by a non-zero
    constant factor, which changes no gcd)."""
    a, b = integer_primitive(p), integer_primitive(q)
    while b:
        a, b = b, integer_primitive(pseudo_remainder(a, b))
    return monic([Fraction(x) for x in a])


def derivative(p: list) -> list:
    """p' (term by term)."""
    return trim(i * a for i, a in enumerate(p) if i > 0)


def value(p: list, x):
    """p(x) by Horner's rule."""
    v = 0
    for a in reversed(p):
        v = v * x + a
    return v


def sign(x) -> int:
    """−1, 0 or 1."""
    return (x > 0) - (x < 0)


def squarefree(p: list) -> list:
    """p / gcd(p, p'): the same real roots, each simple (a multiple root of p is a root of p')."""
    g = gcd(p, derivative(p))
    return monic(divmod_(p, g)[0]) if len(g) > 1 else monic(p)


# --- multivariate: dict exponent-tuple -> Fraction -------------------------------------

def madd(p: dict, q: dict, c=1) -> dict:
    """p + c·q."""
    out = dict(p)
    for k, v in q.items():
        w = out.get(k, Fraction(0)) + c * v
        if w:
            out[k] = w
        else:
            out.pop(k, None)
    return out


def mmul(p: dict, q: dict) -> dict:
    """p·q, term by term (distributivity; exponents add)."""
    out: dict = {}
    for k1, v1 in p.items():
        for k2, v2 in q.items():
            k = tuple(a + b for a, b in zip(k1, k2))
            out[k] = out.get(k, Fraction(0)) + v1 * v2
    return {k: v for k, v in out.items() if v}


def reduce_circles(p: dict, pairs: list) -> dict:
    """The normal form of p modulo the ideal (c² + s² − 1 for each pair of variable indices
    (c, s)): every s² rewritten as 1 − c² until s has degree ≤ 1.  The leading terms s²
    (lex, s first) of these generators are pairwise coprime, so they form a Gröbner basis and
    the normal form is 0 exactly when p lies in the ideal (Buchberger's first criterion)."""
    out: dict = {}
    todo = list(p.items())
    while todo:
        k, v = todo.pop()
        for c, s in pairs:
            if k[s] >= 2:
                k2 = list(k)
                k2[s] -= 2
                k3 = list(k2)
                k3[c] += 2
                todo += [(tuple(k2), v), (tuple(k3), -v)]
                break
        else:
            w = out.get(k, Fraction(0)) + v
            if w:
                out[k] = w
            else:
                out.pop(k, None)
    return out


def in_lambda(p: dict) -> list:
    """A polynomial in (r, λ) as a list of univariate polynomials in r: the coefficients of
    λ⁰, λ¹, ... (a bivariate polynomial is a polynomial in λ over Q[r])."""
    n = max((k[1] for k in p), default=-1)
    out = [dict() for _ in range(n + 1)]
    for (i, j), v in p.items():
        out[j][i] = v
    return [trim(d.get(i, Fraction(0)) for i in range(max(d, default=-1) + 1)) for d in out]


def at_r(p: dict, r0) -> list:
    """p(r0, λ) as a univariate polynomial in λ."""
    return trim(value(c, r0) for c in in_lambda(p))


def d_lambda(p: dict) -> dict:
    """∂p/∂λ for p in (r, λ)."""
    return {(i, j - 1): j * v for (i, j), v in p.items() if j > 0}


def bareiss(rows: list) -> int:
    """The determinant of an integer matrix by Bareiss' fraction-free elimination (every
    division is exact, by Sylvester's identity)."""
    a = [list(r) for r in rows]
    n, sgn, prev = len(a), 1, 1
    for k in range(n - 1):
        piv = next((i for i in range(k, n) if a[i][k]), None)
        if piv is None:
            return 0
        if piv != k:
            a[k], a[piv] = a[piv], a[k]
            sgn = -sgn
        for i in range(k + 1, n):
            for j in range(k + 1, n):
                a[i][j] = (a[i][j] * a[k][k] - a[i][k] * a[k][j]) // prev
        prev = a[k][k]
    return sgn * a[n - 1][n - 1] if n else 1


def interpolate_integers(ys: list) -> list:
    """D!·p for the polynomial p of degree ≤ D through (0, y_0), ..., (D, y_D), integers: by
    Newton's forward differences, p(x) = Σ_k Δ^k y_0 · x(x−1)···(x−k+1)/k!, each term
    multiplied by D! (an integer multiple has the same roots)."""
    D = len(ys) - 1
    diffs, row = [], list(ys)
    for _ in range(D + 1):
        diffs.append(row[0])
        row = [b - a for a, b in zip(row, row[1:])]
    out = [0] * (D + 1)
    falling = [1]                        # x(x−1)···(x−k+1), integer coefficients
    for k in range(D + 1):
        c = diffs[k] * (factorial(D) // factorial(k))
        if c:
            for i, a in enumerate(falling):
                out[i] += c * a
        falling = [0] + falling          # times x ...
        for i in range(len(falling) - 1):
            falling[i] -= k * falling[i + 1]   # ... minus k times
    return trim(out)


def resultant_ints(p: dict, q: dict) -> tuple[list, int]:
    """(s·Res_λ(p, q) as integers in r, s > 0) for p, q ∈ Q[r][λ]: the rows scaled to integers
    (by d_p, d_q: Res by d_p^n·d_q^m), the Sylvester determinant at r = 0, 1, ..., D (Bareiss),
    interpolated (times D!).  The determinant with the formal λ-degrees m, n commutes with
    r ↦ x, and D = n·deg_r p + m·deg_r q bounds its degree in r."""
    (P, dp), (Q, dq) = _integer_rows(p), _integer_rows(q)
    m, n = len(P) - 1, len(Q) - 1
    if m < 0 or n < 0:
        return [], 1
    D = n * max(len(c) - 1 for c in P) + m * max(len(c) - 1 for c in Q)
    ys = []
    for x in range(D + 1):
        a, b = [value(c, x) for c in reversed(P)], [value(c, x) for c in reversed(Q)]
        ys.append(bareiss([[0] * i + a + [0] * (n - 1 - i) for i in range(n)] +
                          [[0] * i + b + [0] * (m - 1 - i) for i in range(m)]))
    return (interpolate_integers(ys) if any(ys) else []), factorial(D) * dp ** n * dq ** m


def _integer_rows(p: dict) -> tuple[list, int]:
    """(d·p as integer coefficient lists in r, one per power of λ; d > 0 the lcm of the denominators)."""
    den = 1
    for v in p.values():
        den = den * v.denominator // igcd(den, v.denominator)
    return [[int(c * den) for c in row] for row in in_lambda(p)], den


_RESULTANTS: dict = {}


def resultant_in(p: dict, q: dict) -> list:
    """Res_λ(p, q) ∈ Q[r] times a positive constant (coprime integer coefficients: the same roots)."""
    key = (tuple(sorted(p.items())), tuple(sorted(q.items())))
    if key not in _RESULTANTS:
        if len(_RESULTANTS) > 500:
            _RESULTANTS.clear()
        _RESULTANTS[key] = [Fraction(c) for c in integer_primitive(resultant_ints(p, q)[0])]
    return _RESULTANTS[key]


# --- interval arithmetic: (lo, hi) pairs of rationals --------------------------------

def enclose(c: list, lo: Fraction, hi: Fraction) -> tuple:
    """An enclosure of Σ c_i x^i over [lo, hi] ⊆ [X − W, X + W]/S (dyadic, S = 2^(bits+1) finer than
    the interval): the value at the centre ± Σ i|c_i|(|X| + W)^(i−1)·W (the mean value theorem), in
    integers (homogeneous Horner)."""
    if not c:
        return Fraction(0), Fraction(0)
    w, den = hi - lo, 1
    bits = max(64, w.denominator.bit_length() - w.numerator.bit_length() + 32) if w else 64
    for a in c:
        den = den * Fraction(a).denominator // igcd(den, Fraction(a).denominator)
    ints = [int(Fraction(a) * den) for a in c]
    n, S = len(c) - 1, 1 << (bits + 1)
    lo2, hi2 = (lo.numerator << bits) // lo.denominator, -((-hi.numerator << bits) // hi.denominator)
    X, W = lo2 + hi2, hi2 - lo2
    M, val, err, Sk = abs(X) + W, ints[n], n * abs(ints[n]), S
    for i in range(n - 1, -1, -1):
        val = val * X + ints[i] * Sk
        err = err * M + i * abs(ints[i]) * Sk if i else err
        Sk *= S
    q = den * S ** n
    return Fraction(val - err * W, q), Fraction(val + err * W, q)


def imul(a: tuple, b: tuple) -> tuple:
    """The product of two intervals."""
    ps = (a[0] * b[0], a[0] * b[1], a[1] * b[0], a[1] * b[1])
    return min(ps), max(ps)


def iadd(a: tuple, b: tuple, c: int = 1) -> tuple:
    """a + b (c = 1) or a − b (c = −1)."""
    return (a[0] + c * b[0], a[1] + c * b[1]) if c > 0 else (a[0] - b[1], a[1] - b[0])
