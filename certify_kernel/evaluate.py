"""What a formula means: its objects built from the kernel's own definitions, its truth decided.

Names are looked up in this order: the definitions (`let`) of the statement files, the kernel's
objects (:data:`BUILTIN`: the collision matrices A, B, C from the collision law, I, e_x, e_y, e_z),
the declared variables (those the binders range over among them).  Functions (:data:`FUNCTIONS`) build
the rest: the matrix of a word, det, charpoly, the discriminant and resultants in λ, roots,
cross and dot products, cos and sin of an angle.  A formula is decided exactly: an identity of
rational functions (modulo cos² + sin² = 1 and, with ``mod P``, modulo P), a comparison of real
algebraic numbers, printed digits, a root count, and ``forall``/``{r in I : F}`` over an interval
of r by a cylindrical decomposition (:mod:`certify_kernel.cells`); over several real variables
(angles) by signs read off a factorisation that the certificate supplies as a witness.
"""
from __future__ import annotations

import re
from fractions import Fraction
from functools import cache

from . import cells
from .cells import Condition, Undecided
from .language import parse
from .poly import d_lambda, divmod_, madd, mmul, resultant_ints, squarefree
from .poly import value as at
from .sturm import Algebraic
from .values import (
    RF,
    VARS,
    Undefined,
    combine,
    monic_in,
    number,
    roots_in,
    sqrt,
    two,
    univariate,
)


class NotVerified(Exception):
    """The kernel cannot decide the statement (the reason names what is missing)."""


class Matrix:
    """A matrix of rational functions, row by row."""

    def __init__(self, rows):
        self.rows = tuple(tuple(row) for row in rows)
        if not self.rows or any(len(row) != len(self.rows[0]) for row in self.rows):
            raise Undefined("a matrix has rows of different lengths")

    @property
    def n(self) -> int:
        return len(self.rows)

    def __mul__(self, o):
        if isinstance(o, Matrix):
            if len(self.rows[0]) != o.n:
                raise Undefined("the matrices of a product do not fit")
            return Matrix([[_sum(a * o.rows[k][j] for k, a in enumerate(row)) for j in range(len(o.rows[0]))]
                           for row in self.rows])
        if isinstance(o, tuple):
            if len(self.rows[0]) != len(o):
                raise Undefined("a matrix and a vector that do not fit")
            return tuple(_sum(a * b for a, b in zip(row, o)) for row in self.rows)
        raise Undefined("a matrix times something that is not a matrix or a vector")


NEG, POS = "-∞", "+∞"


class Interval:
    """An interval of real numbers: ends algebraic numbers or NEG, POS (∓∞); for an angle, multiples
    of π (kept as the Fraction k in kπ, ``angular``)."""

    def __init__(self, lo, hi, lo_closed: bool, hi_closed: bool, angular: bool = False):
        self.lo, self.hi, self.lo_closed, self.hi_closed, self.angular = lo, hi, lo_closed, hi_closed, angular


class RSet:
    """A finite union of disjoint intervals of r, in increasing order: (lo, hi, lo_closed,
    hi_closed), a point being (a, a, True, True)."""

    def __init__(self, parts: list):
        self.parts = merge(parts)


def order(a, b) -> int:
    """sign(a − b) for algebraic numbers and ∓∞."""
    ra, rb = ({NEG: -1, POS: 1}.get(x, 0) if isinstance(x, str) else 0 for x in (a, b))
    return (ra > rb) - (ra < rb) if ra or rb else number(a).compare(number(b))


def merge(parts: list) -> list:
    """Touching parts joined: ]a, b[ ∪ {b} = ]a, b], ]a, b] ∪ ]b, c[ = ]a, c[ (parts increasing)."""
    out: list = []
    for part in parts:
        if out and order(out[-1][1], part[0]) == 0 and (out[-1][3] or part[2]):
            out[-1] = (out[-1][0], part[1], out[-1][2], part[3])
        else:
            out.append(part)
    return out


def subset(A: RSet, B: RSet) -> bool:
    """Every part of A lies inside one part of B."""
    def inside(p, q) -> bool:
        lo, hi = order(q[0], p[0]), order(p[1], q[1])
        return (lo < 0 or lo == 0 and (q[2] or not p[2])) and (hi < 0 or hi == 0 and (q[3] or not p[3]))
    return all(any(inside(p, q) for q in B.parts) for p in A.parts)


def _sum(items) -> RF:
    out = RF.const(0)
    for x in items:
        out = out + x
    return out


def collision(pair: int, gaps: int = 3) -> Matrix:
    """The matrix K with q' = K q for a collision of the particles pair+1, pair+2 (l. 160-166) among
    gaps + 1 particles (four in the paper): v_i' + v_j' = v_i + v_j and v_i' − v_j' = −r(v_i − v_j),
    j = i + 1, the others unchanged; q_k = v_{k+1} − v_k.  Column k is q' for the velocities
    v = (0, ..., 0, 1, ..., 1) whose q is e_k."""
    r = RF.var("r")
    half = RF.const(Fraction(1, 2))
    cols = []
    for k in range(gaps):
        v = [RF.const(0 if m <= k else 1) for m in range(gaps + 1)]
        s, d = v[pair] + v[pair + 1], v[pair] - v[pair + 1]
        v[pair], v[pair + 1] = half * (s - r * d), half * (s + r * d)
        cols.append([v[m + 1] - v[m] for m in range(gaps)])
    return Matrix([[cols[k][i] for k in range(gaps)] for i in range(gaps)])


def collision_of(ctx, N, i) -> Matrix:
    """K(N, i): the collision matrix of the pair i, i + 1 among N particles, on the N − 1 gaps
    (beyond the paper: statements/6_beyond.txt); K(4, 1), K(4, 2), K(4, 3) are A, B, C."""
    n, k = _integer(value(N, ctx)), _integer(value(i, ctx))
    if not 3 <= n <= 12 or not 1 <= k < n:
        raise Undefined("K(N, i): N particles (3 to 12) and a pair i from 1 to N − 1")
    return collision(k - 1, n - 1)


def _pairs(n: int) -> list:
    return [(j, k) for j in range(n) for k in range(j + 1, n)]


def wedge(u: tuple, v: tuple) -> tuple:
    """The bivector u ∧ v of two vectors of R^n: its coordinates u_j v_k − u_k v_j, j < k in
    lexicographic order (12, 13, ..., 1n, 23, ...)."""
    if not isinstance(u, tuple) or not isinstance(v, tuple) or len(u) != len(v) or len(u) < 2:
        raise Undefined("wedge(u, v): two vectors of one length")
    return tuple(u[j] * v[k] - u[k] * v[j] for j, k in _pairs(len(u)))


def compound(M: Matrix) -> Matrix:
    """Λ²M, the matrix of u ∧ v ↦ Mu ∧ Mv on the coordinates of :func:`wedge`: entry ((j, k), (l, m))
    is the minor M_jl M_km − M_jm M_kl."""
    if not isinstance(M, Matrix) or M.n != len(M.rows[0]):
        raise Undefined("compound(M): a square matrix")
    P, a = _pairs(M.n), M.rows
    return Matrix([[a[j][c] * a[k][d] - a[j][d] * a[k][c] for c, d in P] for j, k in P])


@cache
def collisions_at(r0: Fraction) -> list:
    """The entries of A, B, C at r = r₀ (rationals)."""
    return [[[at(univariate(e), r0) for e in row] for row in collision(k).rows] for k in range(3)]


def word_matrix(word: str) -> Matrix:
    """M_w = K_{c_n} ··· K_{c_1}: the velocities after the collisions of w, in time order."""
    M = identity(3)
    for letter in expand_word(word):
        if letter not in "abc":
            raise Undefined(f"{letter!r} is not a collision (a, b or c)")
        M = collision("abc".index(letter)) * M
    return M


def expand_word(text: str) -> str:
    """A word as printed: letters, (...)^n repeated n times (the innermost parentheses first)."""
    w = text.replace(" ", "")
    while "(" in w or ")" in w:
        w, n = re.subn(r"\(([^()]*)\)(?:\^(\d+))?", lambda m: m[1] * int(m[2] or 1), w)
        if not n:
            raise Undefined(f"not a word: {text!r}")
    return w


def identity(n: int) -> Matrix:
    return Matrix([[RF.const(1 if i == j else 0) for j in range(n)] for i in range(n)])


def det(M: Matrix) -> RF:
    """The determinant by Laplace expansion along the first row."""
    if M.n != len(M.rows[0]):
        raise Undefined("the determinant of a matrix that is not square")
    if M.n == 1:
        return M.rows[0][0]
    out = RF.const(0)
    for j, a in enumerate(M.rows[0]):
        minor = Matrix([row[:j] + row[j + 1:] for row in M.rows[1:]])
        out = out + a * det(minor) * RF.const((-1) ** j)
    return out


def cofactors(M: Matrix) -> Matrix:
    """cof(M): entry (i, j) is (−1)^(i+j) times the minor without row i and column j."""
    n = M.n
    return Matrix([[RF.const((-1) ** (i + j)) * det(Matrix([row[:j] + row[j + 1:] for k, row in enumerate(M.rows)
                                                            if k != i])) for j in range(n)] for i in range(n)])


def charpoly(M: Matrix) -> RF:
    """cp(λ) = det(λI − M)."""
    lam = RF.var("λ")
    return det(Matrix([[(lam if i == j else RF.const(0)) - a for j, a in enumerate(row)]
                       for i, row in enumerate(M.rows)]))


def resultant(P: RF, Q: RF) -> RF:
    """Res_λ(P, Q) ∈ Q[r], exactly (:func:`poly.resultant_ints`, its positive scale divided out)."""
    p, q = two(P), two(Q)
    if max((k[1] for k in p), default=-1) < 1 and max((k[1] for k in q), default=-1) < 1:
        raise Undefined("a resultant in λ of two polynomials without λ")
    ints, s = resultant_ints(p, q)
    return RF({(k,): Fraction(c, s) for k, c in enumerate(ints) if c})


def discriminant(P: RF) -> RF:
    """Disc_λ(P) = (−1)^(n(n−1)/2) Res_λ(P, ∂P/∂λ) / lc_λ(P) (n the degree in λ)."""
    p = two(P)
    n = max(k[1] for k in p)
    lc = RF({(k[0],): v for k, v in p.items() if k[1] == n})
    return RF.const((-1) ** (n * (n - 1) // 2)) * resultant(P, RF(d_lambda(p))) / lc


def coefficient(P: RF, k: int, var: str = "λ") -> RF:
    """The coefficient of var^k in the polynomial P."""
    if any(any(key) for key in P.den):
        raise Undefined("the coefficient of a rational function")
    i, c = VARS.index(var), next(iter(P.den.values()))
    return RF({tuple(0 if j == i else e for j, e in enumerate(key)): v / c for key, v in P.num.items() if key[i] == k})


def cross(u: tuple, v: tuple) -> tuple:
    """u ∧ v."""
    if len(u) != 3 or len(v) != 3:
        raise Undefined("a cross product of vectors that are not in R³")
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u: tuple, v: tuple) -> RF:
    if len(u) != len(v):
        raise Undefined("a dot product of vectors of different lengths")
    return _sum(a * b for a, b in zip(u, v))


def _e(k: int) -> tuple:
    return tuple(RF.const(1 if i == k else 0) for i in range(3))


BUILTIN = {"A": lambda: collision(0), "B": lambda: collision(1), "C": lambda: collision(2), "I": lambda: identity(3),
           "e_x": lambda: _e(0), "e_y": lambda: _e(1), "e_z": lambda: _e(2)}


class Context:
    """The definitions of the statement files and the witnesses of the statement being checked."""

    def __init__(self, lets: dict, witnesses=None):
        self.lets, self.values, self.witnesses = lets, {}, witnesses or []
        self.counterexample = None     # a piece where a forall fails

    def name(self, name: str):
        if name in self.lets:
            if name not in self.values:
                self.values[name] = None
                self.values[name] = value(parse(self.lets[name]), self)
            if self.values[name] is None:
                raise Undefined(f"{name} is defined in terms of itself")
            return self.values[name]
        if name in BUILTIN:
            if name not in self.values:
                self.values[name] = BUILTIN[name]()
            return self.values[name]
        if name in VARS:
            return RF.var(name)
        raise Undefined(f"{name} is not defined")


# --------------------------------------------------------------------- expressions

def value(t, ctx: Context):
    """The value of an expression."""
    kind = t[0]
    if kind == "num":
        return RF.const(Fraction(t[1]))
    if kind == "name":
        return ctx.name(t[1])
    if kind == "str":
        return t[1]
    if kind == "const":
        raise Undefined(f"{t[1]} only as the end of an interval of an angle")
    if kind == "neg":
        return arith("*", RF.const(-1), value(t[1], ctx))
    if kind == "bin":
        return arith(t[1], value(t[2], ctx), value(t[3], ctx))
    if kind == "sqrt":
        return sqrt(number(value(t[1], ctx)))
    if kind == "tuple":
        return tuple(value(x, ctx) for x in t[1])
    if kind == "matrix":
        return Matrix([[value(x, ctx) for x in row] for row in t[1]])
    if kind == "index":
        return _index(value(t[1], ctx), [_integer(value(i, ctx)) for i in t[2]])
    if kind == "interval":
        return interval(t, ctx)
    if kind == "call":
        f = FUNCTIONS.get(t[1])
        if f is None:
            raise Undefined(f"{t[1]}() is not a function of the language")
        return f(ctx, *t[2])
    if kind == "finite":
        pts = sorted((number(value(x, ctx)) for x in t[1]), key=cells.ORDER)
        return RSet([(a, a, True, True) for a in pts])
    if kind == "setof":
        return setof(t, ctx)
    raise Undefined(f"not an expression: {kind}")


def _integer(x) -> int:
    c = x.constant() if isinstance(x, RF) else None
    if c is None or c.denominator != 1:
        raise Undefined("an index or exponent that is not an integer")
    return int(c)


def _index(x, idx: list):
    try:
        if isinstance(x, Matrix) and len(idx) == 2:
            return x.rows[idx[0] - 1][idx[1] - 1]
        if isinstance(x, (tuple, list)) and len(idx) == 1:
            return x[idx[0] - 1]
    except IndexError:
        pass
    raise Undefined("an entry out of range")


def arith(op: str, a, b):
    """a op b for scalars, numbers, vectors and matrices."""
    if op == "^":
        n = _integer(b)
        if isinstance(a, Matrix):
            out = identity(a.n)
            for _ in range(n):
                out = out * a
            return out
        if isinstance(a, Algebraic):
            out = number(1)
            for _ in range(n):
                out = combine("*", out, a)
            return out
        return a ** n
    if op == "∧":
        return cross(a, b)
    if op == "·" and isinstance(a, tuple) and isinstance(b, tuple):
        return dot(a, b)
    if isinstance(a, Algebraic) or isinstance(b, Algebraic):
        return combine("*" if op == "·" else op, a, b)
    if isinstance(a, RF) and isinstance(b, RF):
        return {"+": a.__add__, "-": a.__sub__, "*": a.__mul__, "·": a.__mul__, "/": a.__truediv__}[op](b)
    if op in ("*", "·") and isinstance(a, Matrix):
        return a * b
    if op in ("*", "·", "/") and isinstance(a, (tuple, Matrix)) and isinstance(b, RF):
        return _map(a, lambda x: x * b if op != "/" else x / b)
    if op in ("*", "·") and isinstance(a, RF):
        return _map(b, lambda x: a * x)
    if op in ("+", "-") and type(a) is type(b) and isinstance(a, (tuple, Matrix)):
        if isinstance(a, Matrix):
            return Matrix([arith(op, x, y) for x, y in zip(ra, rb)] for ra, rb in zip(a.rows, b.rows))
        if len(a) != len(b):
            raise Undefined("a sum of vectors of different lengths")
        return tuple(x + y if op == "+" else x - y for x, y in zip(a, b))
    raise Undefined(f"{type(a).__name__} {op} {type(b).__name__} is not defined")


def _map(x, f):
    if isinstance(x, Matrix):
        return Matrix([[f(a) for a in row] for row in x.rows])
    if isinstance(x, tuple):
        return tuple(f(a) for a in x)
    raise Undefined("not a vector or a matrix")


def interval(t, ctx: Context) -> Interval:
    _, lo, hi, lc, hc = t

    def end(e):
        if e == ("const", "∞"):
            return POS, False
        if e == ("neg", ("const", "∞")):
            return NEG, False
        angle = _angle_end(e)
        if angle is not None:
            return angle, True
        return number(value(e, ctx)), False
    (a, aa), (b, ab) = end(lo), end(hi)
    return Interval(a, b, lc, hc, angular=aa or ab)


def _angle_end(e):
    """kπ for the ends 0, π, π/2, ... of an interval of an angle (k a Fraction), else None."""
    if e == ("num", "0"):
        return None
    if e in (("name", "π"), ("const", "π")):
        return Fraction(1)
    if e[0] == "bin" and e[1] == "/" and e[2] in (("name", "π"), ("const", "π")) and e[3][0] == "num":
        return Fraction(1, int(e[3][1]))
    if e[0] == "bin" and e[1] == "*" and e[3] in (("name", "π"), ("const", "π")) and e[2][0] == "num":
        return Fraction(e[2][1])
    return None


def _poly_r(P, name: str = "r") -> list:
    if not isinstance(P, RF):
        raise Undefined("not a polynomial")
    used = P.used()
    if len(used) > 1:
        raise Undefined("a polynomial in more than one variable")
    return univariate(P, next(iter(used)) if used else name)


def _roots(ctx, P, J=None):
    p, iv = _poly_r(value(P, ctx)), value(J, ctx) if J is not None else Interval(NEG, POS, False, False)
    return roots_in(p, None if iv.lo == NEG else iv.lo, None if iv.hi == POS else iv.hi, iv.lo_closed, iv.hi_closed)


def _root(ctx, P, J=None) -> Algebraic:
    roots = _roots(ctx, P, J)
    if len(roots) != 1:
        raise Undefined(f"root(): {len(roots)} roots in the interval, not exactly one")
    return roots[0]


def _count(ctx, P, J=None) -> RF:
    return RF.const(len(_roots(ctx, P, J)))


def _word_arg(t) -> str:
    if t[0] not in ("name", "str"):
        raise Undefined("a word is written as letters")
    return expand_word(t[1])


def _trig(kind: str):
    def f(ctx, angle):
        if angle[0] != "name":
            raise Undefined(f"{kind}() of an angle variable")
        c, s = RF.var(f"cos {angle[1]}"), RF.var(f"sin {angle[1]}")
        return {"cos": c, "sin": s, "tan": s / c}[kind]
    return f


def _squarefree(ctx, P) -> RF:
    p = _poly_r(value(P, ctx))
    return RF({(k,): c for k, c in enumerate(squarefree(p)) if c})


def _end(which: int):
    """sup (which = 1) or inf (0) of a bounded non-empty set."""
    def f(ctx, S):
        parts = as_set(value(S, ctx)).parts
        if not parts or parts[-which][which] in (NEG, POS):
            raise Undefined(f"the {('infimum', 'supremum')[which]} of an empty or unbounded set")
        return parts[-which][which]
    return f


FUNCTIONS = {
    "word": lambda ctx, w: word_matrix(_word_arg(w)),
    "det": lambda ctx, M: det(value(M, ctx)),
    "charpoly": lambda ctx, M: charpoly(value(M, ctx)),
    "cof": lambda ctx, M: cofactors(value(M, ctx)),
    "transpose": lambda ctx, M: Matrix(zip(*value(M, ctx).rows)),
    "disc": lambda ctx, P: discriminant(value(P, ctx)),
    "resultant": lambda ctx, P, Q: resultant(value(P, ctx), value(Q, ctx)),
    "coeff": lambda ctx, P, k: coefficient(value(P, ctx), _integer(value(k, ctx))),
    "sqfree": _squarefree,
    "cross": lambda ctx, u, v: cross(value(u, ctx), value(v, ctx)),
    "dot": lambda ctx, u, v: dot(value(u, ctx), value(v, ctx)),
    "K": collision_of,
    "wedge": lambda ctx, u, v: wedge(value(u, ctx), value(v, ctx)),
    "compound": lambda ctx, M: compound(value(M, ctx)),
    "roots": _roots, "root": _root, "count": _count,
    "cos": _trig("cos"), "sin": _trig("sin"), "tan": _trig("tan"),
    "sup": _end(1), "inf": _end(0),
    "deg": lambda ctx, P: RF.const(len(_poly_r(value(P, ctx))) - 1),
    "numerator": lambda ctx, E: RF(value(E, ctx).num),
    "denominator": lambda ctx, E: RF(value(E, ctx).den),
}


# --------------------------------------------------------------------- formulas

CONNECTIVES = ("and", "or", "implies", "iff", "not")


def connective(t, truth_of) -> bool:
    """not, and, or, implies, iff from the truths of the operands, left to right (the right one not
    read when the left decides)."""
    a = truth_of(t[1])
    if t[0] == "not":
        return not a
    if t[0] == "and" and not a or t[0] == "or" and a or t[0] == "implies" and not a:
        return t[0] != "and"
    b = truth_of(t[2])
    return a == b if t[0] == "iff" else b


def truth(t, ctx: Context) -> bool:
    """The truth of a closed formula (no variable left free but in identities)."""
    kind = t[0]
    if kind in CONNECTIVES:
        return connective(t, lambda u: truth(u, ctx))
    if kind == "mod":
        P = value(t[2], ctx)
        var = "λ" if "λ" in P.used() else next(iter(P.used()), "λ")
        MODULUS.append(monic_in(P, var))
        try:
            return truth(t[1], ctx)
        finally:
            MODULUS.pop()
    if kind == "cmp":
        return all(compare(op, value(a, ctx), value(b, ctx), b)
                   for op, a, b in zip(t[1], t[2], t[2][1:]))
    if kind == "forall":
        return forall(t, ctx)
    if kind == "call" and t[1] == "divides" and len(t[2]) == 2:
        P, Q = (_poly_r(value(x, ctx)) for x in t[2])
        if not P:
            raise Undefined("divides(0, Q)")
        return not divmod_(Q, P)[1]
    if kind == "call" and t[1] in ATOMS:
        raise Undefined(f"{t[1]}() is a property of r: inside forall or {{r in I : ...}}")
    if kind == "call" and t[1] in PREDICATES:
        return PREDICATES[t[1]](ctx, *t[2])
    raise Undefined("not a formula")


PREDICATES: dict = {}   # name -> truth(ctx, *argument trees): closed properties defined by the kernel's modules


def compare(op: str, a, b, b_tree=None) -> bool:
    """a op b for two closed values."""
    if op == "≈":
        return approx(a, b_tree)
    if op in ("=", "≠"):
        return equal(a, b) == (op == "=")
    if op == "~":
        return proportional(a, b)
    if op in ("⊆", "in"):
        return subset(as_set(a), as_set(b))
    s = number(a).compare(number(b))
    return {"<": s < 0, ">": s > 0, "≤": s <= 0, "≥": s >= 0}[op]


MODULUS: list = []      # the modulus of the identities inside `... mod P` (innermost last)


def equal(a, b) -> bool:
    """Equality: of rational functions as an identity (modulo the circles, and the modulus inside
    ``mod``), of vectors and matrices entry by entry, of numbers exactly, of sets piece by piece."""
    if isinstance(a, (RSet, Interval)) or isinstance(b, (RSet, Interval)):
        A, B = as_set(a), as_set(b)
        return subset(A, B) and subset(B, A)
    if isinstance(a, Algebraic) or isinstance(b, Algebraic):
        return number(a).compare(number(b)) == 0
    if isinstance(a, Matrix) and isinstance(b, Matrix):
        return a.n == b.n and all(equal(x, y) for ra, rb in zip(a.rows, b.rows) for x, y in zip(ra, rb))
    if isinstance(a, tuple) and isinstance(b, tuple):
        return len(a) == len(b) and all(equal(x, y) for x, y in zip(a, b))
    if isinstance(a, RF) and isinstance(b, tuple) and a.constant() == 0:       # v = 0
        return all(equal(a, y) for y in b)
    if isinstance(b, RF) and isinstance(a, tuple) and b.constant() == 0:
        return all(equal(x, b) for x in a)
    if isinstance(a, RF) and isinstance(b, RF):
        return a.same(b, MODULUS[-1] if MODULUS else None)
    raise Undefined(f"a {type(a).__name__} compared with a {type(b).__name__}")


def proportional(a, b) -> bool:
    """a ~ b: a = k·b for a non-zero constant k (polynomials, or vectors entry by entry)."""
    a, b = (a if isinstance(a, tuple) else (a,)), (b if isinstance(b, tuple) else (b,))
    if len(a) != len(b):
        return False
    k = None
    for x, y in zip(a, b):
        if y.is_zero() or x.is_zero():
            if not (x.is_zero() and y.is_zero()):
                return False
            continue
        ratio = x / y
        c = ratio.constant()
        if c is None:                 # a constant ratio not in lowest terms: its first coefficient, checked
            c = next(iter(ratio.num.values())) / next(iter(ratio.den.values())) if ratio.num else None
            if c is None or not ratio.same(RF.const(c)):
                return False
        if k is not None and k != c:
            return False
        k = c
    return k is not None


def approx(a, printed) -> bool:
    """The printed digits: a number lies in [d − h, d + h], h half a unit of the last digit (it
    rounds to d); a set (one interval) has ends that round to the printed ends."""
    if printed is None:
        raise Undefined("≈ needs printed digits on its right")
    if printed[0] == "interval":
        s = as_set(a)
        if len(s.parts) != 1 or s.parts[0][0] is s.parts[0][1]:
            return False
        return approx(s.parts[0][0], printed[1]) and approx(s.parts[0][1], printed[2])
    if printed[0] != "num" or "." not in printed[1]:
        raise Undefined("≈ compares with a printed decimal")
    d = Fraction(printed[1])
    h = Fraction(1, 2 * 10 ** len(printed[1].split(".")[1]))
    x = number(a)
    return x.compare_rational(d - h) >= 0 and x.compare_rational(d + h) <= 0


def as_set(x) -> RSet:
    if isinstance(x, RSet):
        return x
    if isinstance(x, Interval):
        return RSet([(x.lo, x.hi, x.lo_closed, x.hi_closed)])
    a = number(x)
    return RSet([(a, a, True, True)])


# --------------------------------------------------------------------- binders

QUANTIFIERS: dict = {}  # "angles" -> decide(B, body, ctx): forall over several variables, registered by .signs
ATOMS: dict = {}        # name -> (conditions(ctx, args) -> [Condition], value(point, ctx, args, conds)): a truth,
                        # or a count compared with a number (nroots(P) = 3)


class Binding:
    """What the binders of one forall say: the interval of r, the branch λ is (its polynomial and
    index, or every real root), and x (a fixed point of a Möbius map: σ = ±1, or both)."""

    def __init__(self):
        self.interval = None
        self.cp, self.branch = None, None        # branch: an index (0 = largest), "last", or "all"
        self.mobius, self.sigmas = None, ()      # (a, b, c, d) as RF; σ in (1,), (-1,) or (1, -1)
        self.angles: dict = {}                   # other binders: name -> Interval (the signed route)


def bind(binders, ctx: Context) -> Binding:
    B = Binding()
    for name, how, t in binders:
        if name == "r" and how == "in":
            B.interval = value(t, ctx)
        elif name == "λ" and how in ("=", "in") and t[0] == "call" and t[1] in ("upper", "middle", "lower",
                                                                                  "roots", "branch"):
            B.cp = two(value(t[2][0], ctx))
            B.branch = {"upper": 0, "middle": "middle", "lower": "last", "roots": "all"}.get(t[1])
            if t[1] == "branch":
                B.branch = _integer(value(t[2][1], ctx)) - 1
            if t[1] == "middle" and max(k[1] for k in B.cp) != 3:
                raise Undefined("middle() is the middle one of three real roots of a cubic")
        elif name == "x" and t[0] == "call" and t[1] in ("xplus", "xminus", "fixed"):
            B.mobius = tuple(value(a, ctx) for a in t[2])
            if len(B.mobius) != 4:
                raise Undefined(f"{t[1]}(a, b, c, d): the four coefficients of (ax + b)/(cx + d)")
            B.sigmas = {"xplus": (1,), "xminus": (-1,), "fixed": (1, -1)}[t[1]]
        elif how == "in":
            B.angles[name] = value(t, ctx)
        else:
            raise Undefined(f"the binder {name} {how} ... is not one of the language")
    return B


def forall(t, ctx: Context) -> bool:
    """forall binders: body.  Over an interval of r (λ a branch, x a fixed point): true when the
    body holds on every piece of the decomposition; over other variables: signs by inspection."""
    B = bind(t[1], ctx)
    if B.angles:
        if "angles" not in QUANTIFIERS:
            raise Undefined("forall over angles needs certify_kernel.signs")
        return QUANTIFIERS["angles"](B, t[2], ctx)
    if B.interval is None:
        raise Undefined("forall needs r in an interval (or angles)")
    found = decide(B, t[2], ctx)
    false = [p for p, v in found if v is False]
    if false:
        ctx.counterexample = false[0]
        return False
    undecided = [p for p, v in found if v is None]
    if undecided:
        raise NotVerified(f"undecided at r = {undecided[0]}")
    return True


def setof(t, ctx: Context) -> RSet:
    """{r in I, ... : F}: the union of the pieces where F holds (an undecided piece: not verified)."""
    B = bind(t[1], ctx)
    if B.interval is None or B.angles:
        raise Undefined("{r in I : F} needs r in an interval")
    out = []
    for p, v in decide(B, t[2], ctx):
        if v is None:
            raise NotVerified(f"undecided at r = {p}")
        if v:
            out.append(p.span)
    return RSet(out)


def decide(B: Binding, body, ctx: Context) -> list:
    """[(piece, truth)] over the interval of r: truth True, False, or None (undecided); each piece
    knows its span (lo, hi, lo_closed, hi_closed)."""
    iv = B.interval
    conds = conditions(body, B, ctx)
    lo, hi = (None if iv.lo == NEG else iv.lo), (None if iv.hi == POS else iv.hi)
    pts = cells.pieces(list(conds.values()), lo, hi, iv.lo_closed, iv.hi_closed)
    out = []
    for k, p in enumerate(pts):
        if p.cell:
            a = pts[k - 1].r0 if k and not pts[k - 1].cell else iv.lo
            b = pts[k + 1].r0 if k + 1 < len(pts) and not pts[k + 1].cell else iv.hi
            p.span = (a, b, False, False)
        else:
            p.span = (p.r0, p.r0, True, True)
        try:
            v = at_point(body, p, B, ctx, conds)
        except Undecided:
            v = None
        out.append((p, v))
    return out


def conditions(body, B: Binding, ctx: Context) -> dict:
    """The conditions of the body's atoms, by (id of the atom, σ)."""
    out: dict = {}

    def walk(t):
        if t[0] in CONNECTIVES:
            for u in t[1:]:
                walk(u)
        elif t[0] == "cmp":
            for k, (_op, a, b) in enumerate(zip(t[1], t[2], t[2][1:])):
                if a[0] == "call" and a[1] in ATOMS:          # nroots(P) = 3: a count of the piece
                    walk(a)
                    continue
                for s in B.sigmas or (None,):
                    out[(id(t), k, s)] = _point_condition(a, b, ctx) or atom_condition(a, b, B, ctx, s)
        elif t[0] == "call" and t[1] in ATOMS:
            for k, c in enumerate(ATOMS[t[1]][0](ctx, t[2])):
                out[(id(t), k)] = c
        elif t[0] == "call" and t[1] == "changes":
            for s in B.sigmas or (None,):
                out[(id(t), 0, s)] = atom_condition(t[2][0], ("num", "0"), B, ctx, s)
        else:
            raise Undefined("inside forall, a body is made of comparisons, and, or, not, implies")
    walk(body)
    return out


def _point_condition(a, b, ctx):
    """r = r₀, r < r₀, ... (r₀ an algebraic number): the condition m(r), m r₀'s polynomial, so that r₀
    is a cut point; the comparison itself is decided by comparing each piece with r₀ exactly."""
    if a != ("name", "r"):
        return None
    r0 = value(b, ctx)
    if not isinstance(r0, Algebraic):
        return None
    m = {(i, 0): c for i, c in enumerate(r0.p) if c}
    return Condition(None, m, {(0, 0): Fraction(1)})


def atom_condition(a, b, B: Binding, ctx: Context, sigma) -> Condition:
    """The condition g = a − b: a rational function of r (and λ, x), with x = (A + σ√Δ)/(2c) put in
    (A = a − d, Δ = (a − d)² + 4bc: numerator and denominator become P₀ + P₁√Δ)."""
    g = arith("-", value(a, ctx), value(b, ctx))
    if not isinstance(g, RF):
        raise Undefined("a sign condition on something that is not a function")
    extra = g.used() - {"r", "λ", "x"}
    if extra:
        raise Undefined(f"the condition has free variables {sorted(extra)}")
    cp = B.cp
    if "λ" in g.used() and cp is None:
        raise Undefined("λ is free: bind it to a branch (λ = upper(P), ...)")
    if "x" in g.used() and B.mobius is None:
        raise Undefined("x is free: bind it to a fixed point (x = xplus(a, b, c, d), ...)")
    if "x" not in g.used():
        return Condition(cp, _in_rl(g.num), _in_rl(g.den))
    if any(any(any(k) for k in e.den) for e in B.mobius):
        raise Undefined("the coefficients a, b, c, d of the Möbius map must be polynomials")
    return _with_x(g, [_in_rl(e.num) for e in B.mobius], sigma, cp)


def _in_rl(p: dict) -> dict:
    ix = [VARS.index("r"), VARS.index("λ")]
    if any(e for k in p for i, e in enumerate(k) if i not in ix):
        raise Undefined("a polynomial with variables other than r and λ")
    return {(k[ix[0]], k[ix[1]]): v for k, v in p.items()}


def _with_x(g: RF, abcd: list, sigma: int, cp) -> Condition:
    """g(x) at x = (A + σ√Δ)/(2c), A = a − d, Δ = A² + 4bc (a, ..., d polynomials): each power of x
    expanded in Q[r, λ][√Δ] (√Δ² = Δ) and multiplied by (2c)^deg."""
    a, b, c, d = abcd
    A, one, sg = madd(a, d, -1), {(0, 0): Fraction(1)}, {(0, 0): Fraction(sigma)}
    delta = madd(mmul(A, A), mmul({(0, 0): Fraction(4)}, mmul(b, c)))
    two_c = mmul({(0, 0): Fraction(2)}, c)

    def power_sum(poly: dict):
        """poly(x)·(2c)^deg as (P0, P1), poly in r, λ, x."""
        ix = VARS.index("x")
        deg_x = max((k[ix] for k in poly), default=0)
        P0, P1 = {}, {}
        for k, v in poly.items():
            rest, q0, q1, scale = {(k[0], k[1]): v}, one, {}, one
            for _ in range(k[ix]):                      # (q0 + q1√Δ)(A + σ√Δ)
                q0, q1 = madd(mmul(q0, A), mmul(mmul(q1, delta), sg)), madd(mmul(q0, sg), mmul(q1, A))
            for _ in range(deg_x - k[ix]):
                scale = mmul(scale, two_c)
            P0 = madd(P0, mmul(mmul(rest, q0), scale))
            P1 = madd(P1, mmul(mmul(rest, q1), scale))
        return P0, P1, deg_x
    N0, N1, dn = power_sum(g.num)
    D0, D1, dd = power_sum(g.den)
    for _ in range(dd - dn):        # g = N/(2c)^dn ÷ D/(2c)^dd: the surplus power of 2c on the numerator's side
        N0, N1 = mmul(N0, two_c), mmul(N1, two_c)
    for _ in range(dn - dd):
        D0, D1 = mmul(D0, two_c), mmul(D1, two_c)
    return Condition(cp, N0, D0, N1, D1, delta)


def at_point(body, p, B: Binding, ctx: Context, conds: dict) -> bool:
    """The body's truth at one piece: for every branch and fixed point the binders range over."""
    ks = [None] if B.cp is None else _branches(p, B)
    if ks is False:
        return False
    sigmas = B.sigmas or (None,)
    return all(_truth_at(body, p, k, s, B, ctx, conds) for k in ks for s in sigmas)


def _branches(p, B: Binding):
    """The branch indices the binder names at this piece (largest root first, with multiplicity),
    or False where the named branch does not exist (upper: one real root; middle, lower: all roots
    real)."""
    n, deg = p.branches(B.cp), max(k[1] for k in B.cp)
    if B.branch == "all":
        return list(range(n))
    k = {"last": deg - 1, "middle": 1}.get(B.branch, B.branch)
    if k >= n or B.branch in ("last", "middle") and n < deg:
        return False
    return [k]


def _truth_at(t, p, k, s, B, ctx, conds) -> bool:
    kind = t[0]
    if kind in CONNECTIVES:
        return connective(t, lambda u: _truth_at(u, p, k, s, B, ctx, conds))
    if kind == "cmp":
        for j, op in enumerate(t[1]):
            a = t[2][j]
            if a[0] == "call" and a[1] in ATOMS:
                if not compare(op, RF.const(_atom_at(a, p, ctx, conds)), value(t[2][j + 1], ctx)):
                    return False
                continue
            if t[2][j] == ("name", "r") and conds[(id(t), j, s)].cp is None and \
                    isinstance(value(t[2][j + 1], ctx), Algebraic):     # r op r₀: sign(r − r₀), not that of m(r)
                g = number(p.r0).compare(value(t[2][j + 1], ctx))
            else:
                g = p.sign(conds[(id(t), j, s)], k)
            if g is None:
                return False                     # x is not real: no statement about it holds
            if not {"<": g < 0, ">": g > 0, "≤": g <= 0, "≥": g >= 0, "=": g == 0, "≠": g != 0}.get(op, False):
                if op not in ("<", ">", "≤", "≥", "=", "≠"):
                    raise Undefined(f"{op} is not a sign condition")
                return False
        return True
    if kind == "call" and t[1] == "changes":
        if p.cell or p.left is None or p.right is None:
            return False
        c = conds[(id(t), 0, s)]
        if c.cp is not None and k >= min(p.left.branches(c.cp), p.right.branches(c.cp)):
            return False                         # the branch ends here: it has no sign on one side
        left, right = p.left.sign(c, k), p.right.sign(c, k)
        return left is not None and right is not None and left * right < 0
    if kind == "call" and t[1] in ATOMS:
        return _atom_at(t, p, ctx, conds)
    raise Undefined("not a formula")


def _atom_at(t, p, ctx, conds):
    """The value of an atom (:data:`ATOMS`) at a piece: a truth, or a count that a comparison reads."""
    mine, j = [], 0
    while (id(t), j) in conds:
        mine, j = mine + [conds[(id(t), j)]], j + 1
    return ATOMS[t[1]][1](p, ctx, t[2], mine)


def _nroots_conditions(ctx, args) -> list:
    """nroots(P): its cut points are those of P's branches (Res_λ(P, ∂P/∂λ) and lc_λ P, the
    bounding polynomials of a condition on P's branches that is the constant 1)."""
    if len(args) != 1:
        raise Undefined("nroots(P): one polynomial in r and λ")
    one = {(0, 0): Fraction(1)}
    return [Condition(two(value(args[0], ctx)), one, one)]


def _nroots(p, ctx, args, conds) -> int:
    """nroots(P) = k: P(r, λ) has k distinct real roots λ at this r (a multiple root counted once)."""
    return p.distinct(conds[0].cp)


ATOMS["nroots"] = (_nroots_conditions, _nroots)
