"""The four particles on the line, moved exactly: Theorem 3.1's self-similar datum on the dynamics
(T25.2, statements/3_simulation.txt).

Between two collisions the gaps p = (p_1, p_2, p_3) ≥ 0 move as p + t·q, q_k = v_{k+1} − v_k
(l. 154-157, 195-198); the pair k (a, b, c) collides when p_k reaches 0 with q_k < 0, at t_k =
−p_k/q_k; the next collision is the pair of the smallest t_k, strictly (a tie, a multiple
collision, stops the run); then p_k = 0 and q ↦ K q, K the kernel's collision matrix (l. 159-163).
No q_k < 0: the particles separate.

The datum lies in Q(λ, √Δ), λ a real root of cp(r₀, λ) at a rational r₀, Δ = (a − d)² + 4bc:
every number is an exact α + β√Δ (α, β polynomials in λ modulo λ's polynomial) and every sign the
dynamics asks for is decided exactly (Sturm at λ; α + β√Δ from the signs of α, β, α² − β²Δ).
``datum(r = R0, λ = upper(P), x = xplus(a, b, c, d), p = (...), q = (...))`` is the state at t = 0
(λ and x as the binders of ``forall`` read them); ``follows(D, W)``: the first |W| collisions spell
W; ``q_scaled(D, w, n)``, ``p_scaled(D, w, n)``: q(t_{k|w|}) = λ^k q(0), p(t_{k|w|}) = μ^k p(0)
(μ = p_1(t_{|w|})) for k = 1, ..., n; ``leaves(D, w, n)``: within n periods the collisions depart
from w w w ... (docs/statements.md).
"""
from __future__ import annotations

from fractions import Fraction

from .cells import _surd_sign
from .evaluate import FUNCTIONS, PREDICATES, NotVerified, Undefined, bind, collision, collisions_at, expand_word, value
from .poly import add, at_r, deg, divmod_, mul, scale, sub, trim
from .sturm import Algebraic, real_roots
from .values import RF, VARS, univariate


class Field:
    """Q(λ)(√Δ) at one real root λ of a square-free polynomial m: elements of Q(λ) are polynomials
    reduced modulo m (m shrinks to a factor still vanishing at λ when an inverse meets a common
    factor), their signs those at λ."""

    def __init__(self, lam: Algebraic):
        self.lam, self.delta = lam, []

    def reduce(self, f: list) -> list:
        return divmod_(trim(f), self.lam.p)[1] if deg(trim(f)) >= deg(self.lam.p) else trim(f)

    def sign(self, f: list) -> int:
        return self.lam.sign_of(f) if f else 0

    def inverse(self, f: list) -> list:
        """1/f(λ): Bézout's s·f + t·m = g; g = 1, or g vanishes at λ (f(λ) = 0), or m ← m/g."""
        while True:
            g, s = _bezout(f, self.lam.p)
            if deg(g) == 0:
                return self.reduce(scale(s, 1 / g[0]))
            if self.sign(g) == 0:
                raise Undefined("a division by 0 in the dynamics")
            self.lam = Algebraic(divmod_(self.lam.p, g)[0], self.lam.lo, self.lam.hi, check=False)


def _bezout(f: list, m: list) -> tuple[list, list]:
    """(g, s) with g = gcd(f, m) (not normalised) and s·f ≡ g modulo m (extended Euclid)."""
    r0, r1, s0, s1 = trim(m), trim(f), [], [Fraction(1)]
    while r1:
        quo, rem = divmod_(r0, r1)
        r0, r1, s0, s1 = r1, rem, s1, sub(s0, mul(quo, s1))
    return r0, s0


class Num:
    """α + β√Δ in a :class:`Field` (α, β reduced polynomials in λ)."""

    __slots__ = ("a", "b", "F")

    def __init__(self, F: Field, a: list, b: list | None = None):
        self.F, self.a, self.b = F, F.reduce(a), F.reduce(b or [])

    def _of(self, o) -> Num:
        return o if isinstance(o, Num) else Num(self.F, [Fraction(o)])

    def __add__(self, o):
        o = self._of(o)
        return Num(self.F, add(self.a, o.a), add(self.b, o.b))

    def __sub__(self, o):
        o = self._of(o)
        return Num(self.F, sub(self.a, o.a), sub(self.b, o.b))

    def __mul__(self, o):
        o, F = self._of(o), self.F
        return Num(F, add(mul(self.a, o.a), F.reduce(mul(mul(self.b, o.b), F.delta))),
                   add(mul(self.a, o.b), mul(self.b, o.a)))

    __rmul__ = __mul__

    def __truediv__(self, o):
        """(α + β√Δ)⁻¹ = (α − β√Δ)/(α² − β²Δ); the norm α² − β²Δ vanishes at λ only if α + β√Δ or
        its conjugate is 0."""
        o, F = self._of(o), self.F
        norm = F.reduce(sub(mul(o.a, o.a), F.reduce(mul(mul(o.b, o.b), F.delta))))
        if F.sign(norm) == 0:
            raise Undefined("a division by 0 (or √Δ in Q(λ)) in the dynamics")
        inv = F.inverse(norm)
        return self * Num(F, mul(o.a, inv), scale(mul(o.b, inv), -1))

    def sign(self) -> int:
        F = self.F
        return _surd_sign(self.a, self.b, F.delta, F.sign, lambda x, y: F.reduce(mul(x, y)), sub)


class Datum:
    """The state at t = 0, its field, λ, and the collisions computed so far (each proved); r₀ a
    rational, or K the collision matrices in F (r₀ algebraic, F = Q(r₀))."""

    def __init__(self, F: Field, lam: Num, p: tuple, q: tuple, r0: Fraction | None, K: list | None = None):
        self.F, self.lam, self.r0 = F, lam, r0
        self.K = collisions_at(r0) if K is None else K
        self.states, self.word, self.stop = [(p, q)], "", ""

    def run(self, n: int, pattern: str = "") -> None:
        """The collisions up to the n-th (fewer when the dynamics stops: ``stop`` says why, or when
        the word departs from the periodic ``pattern``)."""
        while len(self.word) < n and not self.stop:
            if pattern and self.word and self.word[-1] != pattern[(len(self.word) - 1) % len(pattern)]:
                return
            p, q = self.states[-1]
            approach = [k for k in range(3) if q[k].sign() < 0]
            if not approach:
                self.stop = "no further collision: every q_k ≥ 0, the particles separate"
                return
            first = approach[0]
            for k in approach[1:]:              # t_k < t_first ⇔ p_k q_first − p_first q_k > 0 (q_k q_first > 0)
                if (p[k] * q[first] - p[first] * q[k]).sign() > 0:
                    first = k
            if any((p[k] * q[first] - p[first] * q[k]).sign() == 0 for k in approach if k != first):
                self.stop = "a multiple collision"
                return
            t = Num(self.F, []) - p[first] / q[first]
            p = tuple(Num(self.F, []) if k == first else p[k] + t * q[k] for k in range(3))
            q = tuple(sum((q[j] * c for j, c in enumerate(self.K[first][i]) if c), Num(self.F, [])) for i in range(3))
            self.states.append((p, q))
            self.word += "abc"[first]


def _rf_at(e: RF, r0: Fraction, nums: dict, F: Field) -> Num:
    """A rational function of r, λ, x at r = r₀ and λ, x the given elements."""
    def poly(d: dict) -> Num:
        out = Num(F, [])
        for key, c in d.items():
            if any(e for i, e in enumerate(key) if VARS[i] not in ("r", *nums)):
                raise Undefined("the datum has a variable other than r, λ and x")
            term = Num(F, [c * r0 ** key[VARS.index("r")]])
            for name, x in nums.items():
                for _ in range(key[VARS.index(name)]):
                    term = term * x
            out = out + term
        return out
    return poly(e.num) / poly(e.den)


_DATA: dict = {}


def datum(ctx, *args) -> Datum:
    """datum(r = R0, λ = BRANCH(P), x = xplus(a, b, c, d) or xminus(...), p = (...), q = (...)): λ and x
    read as the binders of ``forall`` read them (:func:`certify_kernel.evaluate.bind`), at r = R0."""
    given = {}
    for t in args:
        if t[0] != "cmp" or t[1] != ("=",) or t[2][0][0] != "name":
            raise Undefined("datum(r = ..., λ = ..., x = ..., p = (...), q = (...))")
        given[t[2][0][1]] = t[2][1]
    key = (repr(sorted(given.items())), id(ctx.lets))
    if key not in _DATA:
        _DATA[key] = _datum(ctx, given)
    return _DATA[key]


def _datum(ctx, given: dict) -> Datum:
    r0 = value(given["r"], ctx).constant()
    B = bind([(name, "=", given[name]) for name in ("λ", "x") if name in given], ctx)
    if r0 is None or B.cp is None or B.branch == "all" or len(B.sigmas) > 1:
        raise Undefined("datum(): r a rational, λ one branch, x one fixed point")
    cp = at_r(B.cp, r0)
    roots = real_roots(cp)                                     # largest first, as the binders count them
    k = len(roots) - 1 if B.branch == "last" else B.branch
    if k >= len(roots) or B.branch in ("last", 1) and len(roots) < deg(cp):
        raise Undefined(f"λ: no such branch at r = {r0}")
    F = Field(roots[k])
    lam = Num(F, [Fraction(0), Fraction(1)])
    nums = {"λ": lam}
    if B.mobius is not None:
        a, b, c, d = (_rf_at(e, r0, nums, F) for e in B.mobius)
        disc = (a - d) * (a - d) + 4 * b * c
        if disc.sign() < 0:
            raise Undefined("the fixed point x is not real")
        F.delta = disc.a                                       # x = (a − d + σ√Δ)/(2c)
        nums["x"] = (a - d + Num(F, [], [Fraction(B.sigmas[0])])) / (2 * c)
    p, q = (tuple(_rf_at(value(e, ctx), r0, nums, F) for e in _triple(given[k])) for k in "pq")
    if any(g.sign() < 0 for g in p):
        raise Undefined("the datum has a negative gap")
    return Datum(F, lam, p, q, r0)


def _triple(t) -> tuple:
    if t[0] != "tuple" or len(t[1]) != 3:
        raise Undefined("p and q are written (p_1, p_2, p_3), (q_1, q_2, q_3)")
    return t[1]


def _word(t) -> str:
    """A word written as letters, (w)^n or their products."""
    if t[0] == "name":
        return t[1]
    if t[0] == "bin" and t[1] == "^" and t[3][0] == "num":
        return "(" + _word(t[2]) + ")^" + t[3][1]
    if t[0] == "bin" and t[1] == "*":
        return _word(t[2]) + _word(t[3])
    raise Undefined("a word is written as letters and (w)^n")


def _periodic(ctx, D, w, n) -> tuple[Datum, str, int]:
    D, word, n = value(D, ctx), expand_word(_word(w)), value(n, ctx).constant()
    if not isinstance(D, Datum) or n is None or n.denominator != 1 or n < 1:
        raise Undefined("(datum, word, number of periods)")
    return D, word, int(n)


def follows(ctx, D, W) -> bool:
    D, word, _ = _periodic(ctx, D, W, ("num", "1"))
    D.run(len(word))
    return D.word[:len(word)] == word


def _scaled(which: int):
    def predicate(ctx, D, w, n) -> bool:
        D, word, n = _periodic(ctx, D, w, n)
        D.run(len(word) * n)
        if D.word[:len(word) * n] != word * n:
            return False
        start = D.states[0][which]
        factor = D.lam if which else D.states[len(word)][0][0]          # λ for q, μ = p_1(t_|w|) for p
        power = Num(D.F, [Fraction(1)])
        for k in range(1, n + 1):
            power = power * factor
            now = D.states[k * len(word)][which]
            if any((now[i] - power * start[i]).sign() for i in range(3)):
                return False
        return True
    return predicate


def leaves(ctx, D, w, n) -> bool:
    D, word, n = _periodic(ctx, D, w, n)
    D.run(len(word) * n, pattern=word)
    if D.stop == "a multiple collision":
        raise NotVerified("a multiple collision before the pattern is left")
    return D.word != (word * n)[:len(D.word)] or len(D.word) < len(word) * n


# ----------------------------------------------------------------- a datum witnessed at an algebraic r₀
def witnessed_feasible(witnesses: list, word: str, r0: Algebraic) -> bool:
    """Some witness of kind "datum" for ``word`` at r₀ proves it *feasible* there: at a point where
    the candidate degenerates (Cramer's q(0) is 0/0 on a multiple eigenvalue: a line of data) any
    eigenvector is a datum, and one that realises the word is enough (the atom is an existence).
    Nothing of the witness is trusted: :func:`realised_at`."""
    return any(isinstance(w, dict) and w.get("kind") == "datum" and realised_at(w, r0, word) for w in witnesses or [])


def realised_at(w: dict, r0: Algebraic, word: str | None = None) -> bool:
    """The witness's datum at r₀, checked exactly in Q(r₀)(√Δ) with the kernel's collision matrices:
    its r is r₀ (its polynomial and isolating interval, checked, equal r₀); λ > 0; q(0) = (-1, u, v)
    with u > 0 and M_w q(0) = λ q(0); x = α + β√Δ > 0 (Δ > 0 where β ≠ 0); and the four particles
    from p(0) = (1, 0, x), q(0), moved exactly (:meth:`Datum.run`: each collision the strict first),
    spell the word and return scaled: p(t_n) = μ p(0) with μ > 0 (so x is a fixed point of the
    position map) and q(t_n) = λ q(0) (so q(0) is an eigenvector of M_w for λ).  Elements of Q(r₀)
    are polynomials in r (lowest first); ``word``, when given, the (expanded) word it must be for."""
    try:
        if word is not None and expand_word(w["word"]) != word:
            return False
        F = Field(r0)
        mine = Algebraic([Fraction(c) for c in w["r"]["polynomial"]], *(Fraction(e) for e in w["r"]["interval"]))
        if mine.compare(r0) != 0:
            return False
        of = lambda c: Num(F, [Fraction(a) for a in c])          # noqa: E731
        lam, q0 = of(w["lambda"]), tuple(of(c) for c in w["q"])
        alpha, beta, delta = (of(w["x"][k]) for k in ("alpha", "beta", "delta"))
        if len(q0) != 3:
            return False
    except (KeyError, TypeError, ValueError, ZeroDivisionError, Undefined):
        return False
    if beta.a and delta.sign() <= 0:
        return False
    F.delta = delta.a
    x = Num(F, alpha.a, beta.a)
    word = expand_word(w["word"])
    K = [[[Num(F, univariate(e)) for e in row] for row in collision(k).rows] for k in range(3)]
    if (q0[0] + 1).sign() or q0[1].sign() <= 0 or lam.sign() <= 0 or x.sign() <= 0:
        return False
    one, zero = Num(F, [Fraction(1)]), Num(F, [])
    D = Datum(F, lam, (one, zero, x), q0, None, K)
    D.run(len(word))
    if D.word != word:
        return False
    (p_end, q_end), p0 = D.states[-1], D.states[0][0]
    mu = p_end[0]
    return mu.sign() > 0 and not any((p_end[i] - mu * p0[i]).sign() or (q_end[i] - lam * q0[i]).sign()
                                     for i in range(3))


FUNCTIONS["datum"] = datum
PREDICATES.update(follows=follows, q_scaled=_scaled(1), p_scaled=_scaled(0), leaves=leaves)
