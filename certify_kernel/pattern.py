"""The self-similar candidate of a periodic collision word and where it realises the word (l. 265-321,
441-516; the literature, l. 130-132, 1099-1130): the atoms selfsimilar, feasible, stable, realises,
next and the functions eigenvector, posmap of the statement language (docs/statements.md).

The candidate.  A word w = c_1 ··· c_n (four particles: a, b, c, the pairs 1-2, 2-3, 3-4; three
particles: a, b; the symmetric system p_1 = p_3, q_1 = q_3 of l. 132: [ac], b) starts with the
first gap's collision and ends with b (l. 270-280).  M_w = K_{c_n} ··· K_{c_1}, the K the kernel's
collision matrices (three particles: the leading 2×2 blocks of A and B, which do not read q_3; the
symmetric system: A·C and B on (q_1, q_2, q_1)).  On a real eigenvalue λ of M_w (a branch, the
largest first): q(0) = (-1, u[, v]) solving rows 1 and 2 of (M_w - λ) q = 0 by Cramer (l. 366;
where that is 0/0, undecided), p(0) = (1, 0[, x]), the collisions *assumed*
(l. 460-463): at collision k, of gap i, p(t_k) = p(t_{k-1}) - (p_i/q_i) q(t_{k-1}), q(t_k) =
K q(t_{k-1}).  Then p_2(t_n) = 0 and p_3/p_1 = f(x) = (ax + b)/(cx + d), x a fixed point
x± = (a - d ± √Δ)/(2c), Δ = (a - d)² + 4bc (where c = 0, f is affine: x = b/(d - a)).

What is decided.  The candidate *realises* a word v (its first |v| collisions, strictly) iff u > 0,
x > 0, at each collision k of gap i q_i(t_{k-1}) < 0 and p_i(t_{k-1}) > 0 (automatic for k = 1 and
when the pair collided at k - 2), and every gap that does not collide at the last two collisions is
open at the end.  Enough: a collision b adds (1+r)/2·q_2 < 0 to q_1 and q_3, a or c adds
(1+r)/2·q_1 or (1+r)/2·q_3 < 0 to q_2 ([ac]: (1+r)q_1), so each gap is concave between two
collisions of its own pair, positive inside when positive at both ends: no other pair collides
first, no triple collision (l. 478-480).  *selfsimilar*: λ > 0, u > 0, x real and > 0; *feasible*:
λ > 0 and the candidate realises w; *stable*: moreover λ strictly dominant (|μ| < λ for the other
eigenvalues: with Q = cp/(Λ - λ), Q(λ) = cp'(λ) > 0, Q(-λ) > 0 and, for a cubic, μν = det M/λ < λ²:
Schur-Cohn) and the fixed point attracting, |f'(x)| < 1, i.e. (cx + d)² ∓ (ad - bc) > 0, (cx + d)² =
c(a + d)x + bc + d² at a fixed point.  Each atom holds at r when it holds on some branch and fixed
point (next: on every one where the candidate realises v).

How.  With K' = 2K, M' = 2ⁿM_w and Λ = 2ⁿλ, cp = det(Λ - M') is monic in Λ over Z[r].  Every
quantity is an element (c₀ + c₁Λ + c₂Λ²)/δ(r) of Z[r][Λ]/(cp) over a denominator in r alone, its
value on a branch the quantity's wherever δ(r₀) ≠ 0 (cp monic).  Each requirement is imposed where
the previous ones hold, per branch and fixed point (a *region*), by a decomposition of r
(:mod:`certify_kernel.cells`): its cut points are the roots of the norms Res_Λ(cp, ·) of its parts
(numerator, denominator, c and Δ of x) and of disc cp, split over the witness's factors (used only
through exact divisions); one exact sample per cell; at a cut point the sign follows from the
neighbouring cells where multiplicities show that it must (:class:`_Reader`), else from rational
enclosures (:func:`_enclosed`), else exactly in Q(r₀) (cells.Point); where the forms degenerate
(δ(r₀) = 0, or (a, b, c, d) share a zero) exactly on the division-free run (:class:`_Reduced`).
Points no route decides are undecided.
"""
from __future__ import annotations

from fractions import Fraction
from functools import cached_property
from math import ceil
from math import gcd as igcd

from .cells import ORDER, Condition, Point, Undecided, _between, cut_points
from .evaluate import ATOMS, FUNCTIONS, Matrix, NotVerified, collision, expand_word
from .particles import witnessed_feasible
from .poly import (
    add,
    badd,
    bderiv,
    bmul,
    enclose,
    iadd,
    imul,
    in_lambda,
    integer_primitive,
    mul,
    squarefree,
    trim,
    value,
)
from .poly import gcd as qgcd
from .sturm import Algebraic
from .values import RF, Undefined, _root_above, _root_below, number, univariate

LONGEST = 20               # words of more collisions are not analysed (the kernel's time budget)
LARGEST = 40               # a cut polynomial left unsplit of larger degree is not isolated (Sturm is slow)
GAP = {"a": 0, "s": 0, "b": 1, "c": 2}


# ----------------------------------------------------------------- integer polynomials
# in r: lists of ints, lowest degree first; in (r, Λ): lists over the powers of Λ of those (poly.py)

def _brem(P: list, cp: list) -> list:
    """P modulo cp, monic in Λ (Λ^m = -(the rest)): the same value on every branch."""
    m, P = len(cp) - 1, [list(c) for c in P]
    while len(P) > m:
        top, k = P.pop(), len(P) - m
        for j in range(m):
            P[k + j] = add(P[k + j], mul(top, cp[j]), -1)
        P = trim(P)
    return P


def _content(polys) -> int:
    g = 0
    for p in polys:
        for a in p:
            g = igcd(g, a)
    return g


def _exact(p: list, f: list) -> list | None:
    """p/f in Z[r] when f (primitive) divides p (Gauss's lemma), else None."""
    if not p:
        return []
    p, q = list(p), [0] * (len(p) - len(f) + 1)
    for k in range(len(q) - 1, -1, -1):
        a, rem = divmod(p[k + len(f) - 1], f[-1])
        if rem:
            return None
        q[k] = a
        for j, b in enumerate(f):
            p[k + j] -= a * b
    return trim(q) if q and not any(p) else None


def _gcd(p: list, q: list) -> list:
    """The primitive gcd in Z[r] (:func:`poly.gcd` over Q, made integral)."""
    if len(p) == 1 or len(q) == 1:
        return [1]
    return integer_primitive(qgcd(p, q))


def _det(rows: list, add=add, mul=mul) -> list:
    """The determinant of a 2×2 or 3×3 matrix of polynomials (Laplace along row 1)."""
    if len(rows) == 2:
        (a, b), (c, d) = rows
        return add(mul(a, d), mul(b, c), -1)
    out: list = []
    for j in range(3):
        minor = _det([[r[k] for k in range(3) if k != j] for r in rows[1:]], add, mul)
        out = add(out, mul(rows[0][j], minor), (-1) ** j)
    return out


# ----------------------------------------------------------------- Z[r][Λ]/(cp) over denominators in r
class El:
    """(c₀ + c₁Λ + ···)/δ(r): the parts without common factor, δ with a positive leading coefficient."""

    __slots__ = ("c", "d")

    def __init__(self, c: list, d: list):
        self.c, self.d = c, d


def _el(c: list, d: list, cp: list) -> El:
    c = _brem(c, cp)
    if not c:
        return El([], [1])
    g = d
    for p in c:
        g = _gcd(g, p) if len(g) > 1 and p else g
    if len(g) > 1:
        c, d = [_exact(p, g) for p in c], _exact(d, g)
    k = _content(c + [d]) * (1 if d[-1] > 0 else -1)
    return El([[a // k for a in p] for p in c], [a // k for a in d])


def _mult_matrix(P: list, cp: list) -> list:
    """The multiplication by P in the basis 1, Λ, ...: column j is P·Λ^j."""
    m = len(cp) - 1
    cols = [_brem([[]] * j + P, cp) for j in range(m)]
    return [[cols[j][i] if i < len(cols[j]) else [] for j in range(m)] for i in range(m)]


def norm(P: list, cp: list) -> list:
    """Res_Λ(cp, P) = Π P(λ_i) (cp monic): the determinant of the multiplication by P."""
    if len(P) < 2:
        out = [1]
        for _ in range(len(cp) - 1):
            out = mul(out, P[0] if P else [])
        return out
    return _det(_mult_matrix(P, cp))


def _emul(x: El, y: El, cp: list) -> El:
    return _el(bmul(x.c, y.c), mul(x.d, y.d), cp)


def _esub(x: El, y: El, cp: list) -> El:
    return _el(badd(bmul(x.c, [y.d]), bmul(y.c, [x.d]), -1), mul(x.d, y.d), cp)


def _inverse(P: list, cp: list) -> El:
    """1/P: the solution y of M_P y = e₁, adj(M_P)e₁/det M_P (adj(M)_k1 = (-1)^k·minor(1, k))."""
    M = _mult_matrix(P, cp)
    adj = [M[1][1], [-a for a in M[1][0]]] if len(M) == 2 else \
        [[(-1) ** k * a for a in _det([[M[i][j] for j in range(3) if j != k] for i in (1, 2)])] for k in range(3)]
    n = _det(M)
    if not n:
        raise Undefined("a velocity of the candidate vanishes on a whole branch")
    return _el(adj, n, cp)


def _sum(items, add=badd) -> list:
    out: list = []
    for P in items:
        out = add(out, P)
    return out


# ----------------------------------------------------------------- the systems, the candidate
def read_word(text: str) -> tuple[str, str]:
    """(system, letters) of a word as printed: (ab)^n powers, [ac] the simultaneous collision (letter
    s); a word without c is one of three particles."""
    letters = expand_word(text.replace("[ac]", "s"))
    system = "symmetric" if "[ac]" in text else "four" if "c" in letters else "three"
    allowed = {"symmetric": "sb", "four": "abc", "three": "ab"}[system]
    if set(letters) - set(allowed) or letters[0] not in "as" or letters[-1] != "b":
        raise Undefined(f"{text!r}: a word of the collisions {', '.join(allowed)}, from the first gap's to b")
    return system, letters


def _matrices(system: str) -> dict:
    """2K for each letter, integer polynomials in r, from the kernel's collision matrices."""
    A, B, C = collision(0), collision(1), collision(2)

    def ints(K, size):
        return [[trim([int(2 * c) for c in univariate(e)]) if not e.is_zero() else [] for e in row[:size]]
                for row in K.rows[:size]]

    def symmetric(K):                 # on (q_1, q_2, q_1): rows 1, 2 and columns 1 + 3, 2
        R = K.rows
        if not ((R[2][0] + R[2][2] - R[0][0] - R[0][2]).is_zero() and (R[2][1] - R[0][1]).is_zero()):
            raise Undefined("a collision of the symmetric system does not keep q_1 = q_3")
        return Matrix([[R[i][0] + R[i][2], R[i][1]] for i in range(2)])
    if system == "four":
        return {"a": ints(A, 3), "b": ints(B, 3), "c": ints(C, 3)}
    if system == "three":            # particles 1, 2, 3: A and B do not read q_3
        return {"a": ints(A, 2), "b": ints(B, 2)}
    return {"s": ints(symmetric(A * C), 2), "b": ints(symmetric(B), 2)}


class Run:
    """The assumed collisions of a word from q̃(0), p(0) = (1, 0[, x]): after each, the velocities
    q̃ (polynomials in r, Λ: det·2^k·q) and the positions (P0, P1) per gap, p = P0 + x·P1 (:class:`El`)."""

    def __init__(self, cand, word: str):
        self.word, cp, q, g = word, cand.cp, list(cand.q0), len(cand.q0)
        one, zero = El([[1]], [1]), El([], [1])
        P = [(one, zero), (zero, zero)] + ([(zero, one)] if g == 3 else [])
        self.q, self.p = [q], [P]
        for letter in word:
            i, K = GAP[letter], cand.K[letter]
            w = _inverse(q[i], cp)
            t = [_emul(P[i][h], w, cp) for h in (0, 1)]                                # p_i/q̃_i
            P = [tuple(_esub(P[j][h], _emul(t[h], El(q[j], [1]), cp), cp) for h in (0, 1)) for j in range(g)]
            P[i] = (zero, zero)
            q = [_sum([bmul(q[j], [K[row][j]]) for j in range(g) if K[row][j]]) for row in range(g)]
            self.q.append(q)
            self.p.append(P)


class Candidate:
    """cp = det(Λ - M'), q̃(0) = det·(-1, u[, v]) from rows 1 and 2 of (M' - Λ)q = 0 (Cramer),
    the runs, and (four particles) the position map (a, b, c, d) = L1·L3/h·(p(t_n)'s coefficients)."""

    def __init__(self, text: str):
        self.runs, self.points = {}, {}
        self.system, self.word = read_word(text)
        self.K = _matrices(self.system)
        g = 3 if self.system == "four" else 2
        M = [[[1] if i == j else [] for j in range(g)] for i in range(g)]
        for letter in self.word:
            K = self.K[letter]
            M = [[_sum([mul(K[i][k], M[k][j]) for k in range(g)], add) for j in range(g)] for i in range(g)]
        self.M = M
        B = [[trim([M[i][j], [-1]] if i == j else [M[i][j]]) for j in range(g)] for i in range(g)]   # M' - Λ
        self.cp = _det([[badd([], e, -1) for e in row] for row in B], badd, bmul)
        if g == 3:
            (b1, a11, a12), (b2, a21, a22) = B[0], B[1]
            det = _det([[a11, a12], [a21, a22]], badd, bmul)
            q0 = [badd([], det, -1), _det([[b1, a12], [b2, a22]], badd, bmul), _det([[a11, b1], [a21, b2]], badd, bmul)]
        else:                          # row 1: (m11 - Λ)(-1) + m12 u = 0, row 2: m21(-1) + (m22 - Λ)u = 0
            det, U = B[0][1], B[0][0]
            q0 = [badd([], det, -1), U]
        self.det, self.q0 = _brem(det, self.cp), [_brem(e, self.cp) for e in q0]
        self.cp_dict = _dict(self.cp)

    @cached_property
    def run(self) -> Run:
        return self.run_of(self.word)

    @cached_property
    def position_map(self) -> tuple:
        """(a, b, c, d) = L1·L3/h·(the coefficients of p_3(t_n) = b + xa, p_1(t_n) = d + xc), over
        L3 = lcm(δ_a, δ_b), L1 = lcm(δ_c, δ_d), h the content; and L1·L3."""
        (d, c), _, (b, a) = self.run.p[-1]
        L1, L3 = _lcm(d.d, c.d), _lcm(b.d, a.d)
        abcd = [bmul(e.c, [mul(_exact(L, e.d), L2)]) for e, L, L2 in ((a, L3, L1), (b, L3, L1), (c, L1, L3),
                                                                       (d, L1, L3))]
        h = _content(x for P in abcd for x in P)
        return [[[y // h for y in x] for x in P] for P in abcd], mul(L1, L3)

    @property
    def abcd(self) -> list:
        return self.position_map[0]

    @cached_property
    def disc(self) -> list:
        """The factors of disc cp = Res_Λ(cp, ∂cp/∂Λ) (where two branches meet)."""
        return [f for f, _ in _factors(norm(bderiv(self.cp), self.cp))]

    def run_of(self, word: str) -> Run:
        if word not in self.runs:
            self.runs[word] = Run(self, word)
        return self.runs[word]

    def relabel(self, p: Point, k: int):
        """ε: x_s of (a, b, c, d) is x_{εs} of the division-free ones at p on branch k (the signs of
        L1·L3, 1 where it vanishes, and of s_n = Π q̃_i); None where s_n = 0."""
        e = _sign(p, _cond(self, [self.position_map[1]]), k) or 1
        for k_, letter in enumerate(self.word):
            e *= _sign(p, _cond(self, self.run.q[k_][GAP[letter]]), k)
        return e or None


_CANDIDATES: dict = {}


def candidate(text: str) -> Candidate:
    if text not in _CANDIDATES:
        _CANDIDATES[text] = Candidate(text)
    return _CANDIDATES[text]


def _lcm(a: list, b: list) -> list:
    return mul(a, _exact(b, _gcd(a, b)))


# ----------------------------------------------------------------- requirements and their conditions
def _dict(P: list) -> dict:
    """A polynomial in (r, Λ) as the cells' dict (e_r, e_Λ) -> coefficient."""
    return {(i, j): Fraction(a) for j, c in enumerate(P) for i, a in enumerate(c) if a}


class Req:
    """A quantity g = (G0 + x·G1)/D (G0, G1, D polynomials in r, Λ) and the strict sign it must have;
    for the positions' ones, their division-free form ``free`` (a function of a :class:`_Reduced`),
    read where this one degenerates."""

    def __init__(self, name: str, sign: int, G0: list, G1: list, D: list, free=None):
        self.name, self.sign, self.G0, self.G1, self.D, self.free = name, sign, G0, G1, D, free
        self._conds: dict = {}

    def cond(self, cand, s, affine: bool = False):
        if (s, affine) not in self._conds:
            abcd = cand.abcd if self.G1 else None
            self._conds[(s, affine)] = _condition(cand, self.G0, self.G1, self.D, s, abcd, affine)
        return self._conds[(s, affine)]


class _Cond(Condition):
    """The cells' Condition of g on the branches, whose cut points are the roots of disc cp and of
    the norms Res_Λ(cp, P) of labelled parts ("N": the zeros, "D": the poles, "c", "delta": those
    of x), split over the factor base."""

    def __init__(self, cand, parts: dict, norms=()):
        super().__init__(cand.cp_dict, *(_dict(parts.get(k, [])) for k in ("N0", "D0", "N1")), None,
                         _dict(parts["delta"]) if parts.get("delta") else None)
        self.cand, self.norms, self._cuts = cand, norms, None

    def cuts(self) -> dict:
        """factor -> (the labels of the norms it divides, its exponent in the norm "N")."""
        if self._cuts is None:
            out = {tuple(f): ({"disc"}, 0) for f in self.cand.disc}
            for label, P in (self.norms() if callable(self.norms) else self.norms):
                for f, e in _factors(norm(P, self.cand.cp)):
                    labels, m = out.get(tuple(f), (set(), 0))
                    out[tuple(f)] = (labels | {label}, m + (e if label == "N" else 0))
            self._cuts = out
        return self._cuts


def _cond(cand, P: list, D: list | None = None) -> _Cond:
    """The condition P/D (D = 1 by default), for signs at points."""
    return _Cond(cand, {"N0": P, "D0": D or [[1]]})


def _condition(cand, G0, G1, D, s, abcd, affine):
    """g as a Condition, x = x_s = (A + s√Δ)/(2c), A = a - d (``cand``: the candidate, or a
    :class:`_Reduced` at a point): N₀ = 2cG0 + A·G1, N₁ = s·G1, D₀ = 2cD; the norm of the
    numerator is N₀² - N₁²Δ = 4c·Q, Q = cG0² + A·G0·G1 - b·G1².  ``affine``: x = b/(d - a).  None
    where the denominator is 0."""
    cp, red = cand.cp, getattr(cand, "reduce", lambda P: P)
    if not G1:
        return _Cond(cand, {"N0": G0, "D0": D}, [("N", G0), ("D", D)]) if D else None
    a, b, c, d = abcd
    if affine:
        dma = badd(d, a, -1)
        D0 = red(_brem(bmul(dma, D), cp))
        return _Cond(cand, {"N0": red(_brem(badd(bmul(G0, dma), bmul(b, G1)), cp)), "D0": D0}) if D0 else None
    A = badd(a, d, -1)
    delta = red(_brem(badd(bmul(A, A), bmul([[4]], bmul(b, c))), cp))
    N0 = red(_brem(badd(bmul([[2]], bmul(c, G0)), bmul(A, G1)), cp))
    D0 = red(_brem(bmul([[2]], bmul(c, D)), cp))

    def norms():
        Q = _brem(badd(badd(bmul(c, bmul(G0, G0)), bmul(A, bmul(G0, G1))), bmul(b, bmul(G1, G1)), -1), cp)
        return [("N", Q), ("c", c), ("D", D), ("delta", delta)]
    return _Cond(cand, {"N0": N0, "D0": D0, "N1": [[s * x for x in p] for p in G1], "delta": delta}, norms) \
        if D0 else None


def requirements(cand, stage: str, v: str | None = None) -> list:
    """The requirements of a stage, in the order they are imposed: datum (λ, u, x), realises v (u,
    the velocities of v, x, its gaps), feasible (λ, realises w), stable (λ, dominance, realises w,
    |f'(x)| < 1)."""
    one, four = [[1]], len(cand.q0) == 3
    lam, u = Req("λ", 1, [[], [1]], [], one), Req("u", 1, cand.q0[1], [], cand.det)
    x = Req("x", 1, [], one, one, free=lambda R: ([], one, one))
    if stage == "datum":
        return [lam, u] + ([x] if four else [])
    v = cand.word if v is None else v
    run, gaps = cand.run_of(v), [GAP[cand.word[-1]]] + [GAP[ch] for ch in v]     # gaps[k]: the gap of collision k
    speeds, places = [], []
    for k in range(1, len(v) + 1):
        i = gaps[k]
        if k > 1 or i != 0:                     # q_1(0) = -1
            speeds.append(Req(f"q_{i + 1}(t_{k - 1})", -1, run.q[k - 1][i], [], cand.det))
        if k > 1 and gaps[k - 2] != i:
            places.append(_position(cand, run, k - 1, i))
    m = len(v)
    places += [_position(cand, run, m, j) for j in range(len(cand.q0)) if j not in (gaps[m], gaps[m - 1])]
    out = [u] + speeds + ([x] if four else []) + places
    if stage == "feasible":
        out = [lam] + out
    if stage == "stable":
        out = [lam] + _dominance(cand) + out + (_attracting(cand) if four else [])
    return out


def _position(cand, run, k: int, j: int) -> Req:
    """p_j(t_k) > 0: P0 + x·P1 over one denominator in r; division-free, over (-det)^k."""
    P0, P1 = run.p[k][j]
    L = _lcm(P0.d, P1.d)
    G0, G1 = (bmul(e.c, [_exact(L, e.d)]) if e.c else [] for e in (P0, P1))

    def free(R):
        F0, F1 = R.free(run.word)[k][j]
        return F0, F1, (R.minus_det if k % 2 else [[1]])
    return Req(f"p_{j + 1}(t_{k})", 1, G0, G1, [L], free=free)


def _dominance(cand) -> list:
    """λ strictly dominant: cp'(λ) > 0, cp(-λ) > 0 (quadratic); cp'(λ) > 0, -cp(-λ) > 0,
    λ³ - det M > 0 (cubic) (cp(Λ) = 2^(3n)cp(λ): positive multiples)."""
    cp, one = cand.cp, [[1]]
    d = bderiv(cp)
    minus = [[(-1) ** i * a for a in c] for i, c in enumerate(cp)]
    if len(cp) == 3:
        return [Req("cp'(λ)", 1, d, [], one), Req("cp(-λ)", 1, minus, [], one)]
    return [Req("cp'(λ)", 1, d, [], one), Req("-cp(-λ)", -1, minus, [], one),
            Req("λ³ - det M", 1, badd([[], [], [], [1]], [cp[0]]), [], one)]


def _attracting(cand) -> list:
    """|f'(x)| < 1 at a fixed point: (cx + d)² ∓ (ad - bc) > 0, (cx + d)² = c(a + d)x + bc + d²
    (homogeneous of degree 2 in (a, b, c, d): a common factor changes no sign)."""
    out = []
    for sg in (-1, 1):
        def parts(abcd, sg=sg):
            a, b, c, d = abcd
            return badd(badd(bmul(b, c), bmul(d, d)), badd(bmul(a, d), bmul(b, c), -1), sg), \
                bmul(c, badd(a, d)), [[1]]
        G0, G1, D = parts(cand.abcd)
        out.append(Req(f"(cx+d)² {'+' if sg > 0 else '-'} (ad-bc)", 1, _brem(G0, cand.cp), _brem(G1, cand.cp), D,
                       free=lambda R, parts=parts: tuple(R.reduce(P) for P in parts(R.abcd))))
    return out


# ----------------------------------------------------------------- cut points: norms over the factor base
BASE: list = []            # primitive integer polynomials in r (witnesses' factors), with their values at 2


def learn(factors) -> None:
    """Add a witness's factors to the base (each is used only through exact divisions)."""
    known = {tuple(f) for f, _ in BASE}
    for f in factors:
        f = integer_primitive([Fraction(a) for a in f])
        if len(f) > 1 and tuple(f) not in known:
            known.add(tuple(f))
            BASE.append((f, value(f, 2)))


def _factors(p: list) -> list:
    """p = Π f^e · rest, the f from the base (exact divisions; f(2) | p(2) first): [(f, e)] and (the
    square-free part of rest, 1 if rest is square-free, else 2)."""
    p = integer_primitive(p)
    if len(p) < 2:
        return []
    out, at2 = [], value(p, 2)
    for f, f2 in BASE:
        e = 0
        while len(p) >= len(f) and (f2 == 0 or at2 % f2 == 0):
            q = _exact(p, f)
            if q is None:
                break
            p, at2, e = q, value(q, 2), e + 1
        if e:
            out.append((f, e))
    if len(p) > 1:
        sq = squarefree([Fraction(a) for a in p])
        if len(sq) - 1 > LARGEST:
            raise NotVerified(f"a cut polynomial of degree {len(sq) - 1} that the witness's factors do not split")
        out.append((integer_primitive(sq), 1 if len(sq) == len(p) else 2))
    return out


# ----------------------------------------------------------------- signs at a piece
def _sign(p: Point, cond, k: int):
    """cond's sign on branch k at p: -1, 0, 1, None (x not real), or Undecided (a pole; cond None);
    at an algebraic point by enclosures first (:func:`_enclosed`)."""
    if cond is None:
        return Undecided
    g = 0 if p.cell else _enclosed(p, cond, k)
    if g != 0:
        return g
    try:
        return p.sign(cond, k)
    except Undecided:
        return Undecided


def _enclosed(p: Point, cond, k: int):
    """cond's sign on branch k at the algebraic point p by rational intervals, r₀ and λ_k(r₀)
    enclosed ever more narrowly (2^-24, 2^-64, 2^-160): -1, 1, None (Δ < 0), or 0 (undecided)."""
    memo = p.__dict__.setdefault("_enclosures", {})
    if (cond.key, k) not in memo:
        memo[(cond.key, k)] = 0
        for bits in (24, 64, 160):
            lam = _lambda_interval(p, cond.cp, k, Fraction(1, 2 ** bits))
            if lam is None:
                break
            parts = {n: _box(P, p.r0, lam) for n, P in cond.parts.items() if P}
            D, N = parts["D0"], parts.get("N0", (Fraction(0), Fraction(0)))
            if "N1" in parts:
                dl, dh = parts["delta"]
                if dh < 0:
                    memo[(cond.key, k)] = None
                    break
                if dl <= 0:
                    continue
                N = iadd(N, imul(parts["N1"], (_root_below(dl, bits + 32), _root_above(dh, bits + 32))))
            if not (D[0] <= 0 <= D[1] or N[0] <= 0 <= N[1]):
                memo[(cond.key, k)] = (1 if N[0] > 0 else -1) * (1 if D[0] > 0 else -1)
                break
    return memo[(cond.key, k)]


def _lambda_interval(p: Point, cp: dict, k: int, width: Fraction):
    """[α, β] holding λ_k(r₀) and no other root, narrower than width, r₀'s interval narrower than
    width²: bisected by the sign of cp(r₀, ·) at the middle (enclosed, exactly when that does not
    decide).  None at a multiple root."""
    if k >= p.branches(cp):
        return None
    cache = p.__dict__.setdefault("_lam", {})
    if k not in cache:
        cpl, roots = p._roots[repr(sorted(cp.items()))]
        if roots.count(roots[k]) > 1:
            return None
        a, b = (Fraction(e) for e in roots[k])
        cache[k] = [a, b, p._at.at(cpl, a), cpl]
    a, b, sa, cpl = cache[k]
    while not p.r0.rational and p.r0.hi - p.r0.lo > width ** 2:
        p.r0.bisect()
    while b - a > width:
        mid = (a + b) / 2
        e = _box(cpl, p.r0, (mid, mid))
        sm = 1 if e[0] > 0 else -1 if e[1] < 0 else p._at.at(cpl, mid)
        if sm == 0:
            a = b = mid
        elif sm == sa:
            a = mid
        else:
            b = mid
    cache[k][:2] = [a, b]
    return a, b


def _box(P, r0, lam: tuple) -> tuple:
    """An enclosure of P(r₀, λ) for r₀ in its interval and λ in lam (P a cells dict, or dense)."""
    out = (Fraction(0), Fraction(0))
    for c in reversed(in_lambda(P) if isinstance(P, dict) else P):
        out = iadd(imul(out, lam), enclose(c, r0.lo, r0.hi))
    return out


class _Reduced:
    """The division-free run at an algebraic point r₀, in integers: m the integer polynomial of r₀
    (leading coefficient L > 0, degree d), n = deg cp; y = L·r and M = L^t·Λ make m̃(y) =
    L^(d-1)·m(y/L) and cp̃(y, M) = L^(nt)·cp(y/L, M/L^t) monic with integer coefficients
    (t(n - j) ≥ the degree in r of cp's coefficient of Λ^j); a polynomial P(r, Λ) becomes
    L^E·P(y/L, M/L^t), E ≥ tj + deg p_j (a positive multiple), reduced modulo m̃ and cp̃ (the same
    value at y₀ = L·r₀ and M = L^t·λ).  One E for the velocities of a step, so that p̃(t_k) =
    q̃_i·p̃(t_{k-1}) - p̃_i·q̃(t_{k-1}) is s_k·p(t_k), s_k a positive multiple of Π q̃_i, of sign
    (-sign det)^k where the velocity requirements hold."""

    def __init__(self, cand, p: Point):
        m = integer_primitive(p.r0.p)
        m = m if m[-1] > 0 else [-a for a in m]
        L, d, n = m[-1], len(m) - 1, len(cand.cp) - 1
        self.m, self.L, self.cand, self.runs = [a * L ** (d - 1 - i) for i, a in enumerate(m[:-1])] + [1], L, cand, {}
        self.t = max([ceil((len(c) - 1) / (n - j)) for j, c in enumerate(cand.cp[:-1]) if c] + [0])
        self.cp = []                                         # reduce() modulo m̃ only, for cp̃ itself
        self.cp = self.scaled(cand.cp, n * self.t)
        self.cp_dict, r0 = _dict(self.cp), p.r0
        self.point = Point(number(L * r0.lo) if r0.rational else
                           Algebraic([Fraction(a) for a in self.m], L * r0.lo, L * r0.hi, check=False), False)
        self.minus_det = self.scaled(badd([], cand.det, -1))
        F = self.free(cand.word)[-1]
        self.abcd = [F[2][1], F[2][0], F[0][1], F[0][0]] if len(F) == 3 else None

    def scaled(self, P: list, E: int | None = None) -> list:
        t, L = self.t, self.L
        E = max((t * j + len(c) - 1 for j, c in enumerate(P) if c), default=0) if E is None else E
        return self.reduce([[a * L ** (E - t * j - i) for i, a in enumerate(c)] for j, c in enumerate(P)])

    def reduce(self, P: list) -> list:
        P, d = (_brem(P, self.cp) if self.cp else P), len(self.m) - 1
        out = []
        for c in P:
            c = list(c)
            for k in range(len(c) - 1, d - 1, -1):
                for i in range(d):
                    c[k - d + i] -= c[k] * self.m[i]
                c[k] = 0
            out.append(trim(c))
        return trim(out)

    def free(self, word: str) -> list:
        if word not in self.runs:
            run, g = self.cand.run_of(word), len(self.cand.q0)
            F = [([[1]], []), ([], [])] + ([([], [[1]])] if g == 3 else [])
            self.runs[word] = [F]
            for k, letter in enumerate(word):
                E = max(self.t * j + len(c) - 1 for P in run.q[k] for j, c in enumerate(P) if c)
                i, q = GAP[letter], [self.scaled(P, E) for P in run.q[k]]
                F = [tuple(self.reduce(badd(bmul(q[i], F[j][h]), bmul(F[i][h], q[j]), -1)) for h in (0, 1))
                     for j in range(g)]
                F[i] = ([], [])
                self.runs[word].append(F)
        return self.runs[word]


def _reduced(cand, p: Point) -> _Reduced:
    cache = p.__dict__.setdefault("_reduced", {})
    if id(cand) not in cache:
        cache[id(cand)] = _Reduced(cand, p)
    return cache[id(cand)]


def holds(p: Point, req: Req, cand, k: int, s) -> bool | None:
    """req on branch k with the fixed point x_s at the piece p: True, False or None (undecided).  At
    a point, where the forms are valid (δ(r₀) ≠ 0, L1·L3 ≠ 0): by enclosures, where c = 0 with the
    affine f, else exactly; where they degenerate: exactly on the division-free run (x named as the
    candidate's: :meth:`Candidate.relabel`)."""
    cond = req.cond(cand, s)
    if p.cell:
        g = _sign(p, cond, k)
    else:
        valid = (len(req.D) > 1 or p.r0.sign_of(req.D[0]) != 0) and \
            (not req.G1 or p.r0.sign_of(cand.position_map[1]) != 0)
        g = _enclosed(p, cond, k) if valid else 0
        if g == 0 and valid and req.G1 and _sign(p, _cond(cand, cand.abcd[2]), k) == 0:
            g = _affine(p, cand, k, cand.abcd, lambda: req.cond(cand, s, affine=True), req.G0, req.G1, req.D)
        elif g == 0:
            g = _sign(p, cond, k) if valid or req.free is None else Undecided
    if g is Undecided and req.free is not None and not p.cell:
        R = _reduced(cand, p)
        G0, G1, D = req.free(R)
        e = cand.relabel(p, k) if G1 else 1
        if e is None:
            return None
        if G1 and _sign(R.point, _cond(R, R.abcd[2]), k) == 0:
            g = _affine(R.point, R, k, R.abcd, lambda: _condition(R, G0, G1, D, s, R.abcd, True), G0, G1, D)
        else:
            g = _sign(R.point, _condition(R, G0, G1, D, e * s, R.abcd, False), k)
    return None if g is Undecided else g is not None and g == req.sign


def _affine(p: Point, cand, k: int, abcd: list, cond, G0, G1, D):
    """Where c = 0, f(x) = (ax + b)/d: the fixed point b/(d - a) (``cond``: the condition there); none
    where d = a and b ≠ 0 (a translation: as an x that is not real, None); where f is the identity
    (every x fixed), the requirement's value if it does not depend on x (G1 = 0), else Undecided."""
    a, b, _, d = abcd
    if _sign(p, _cond(cand, badd(d, a, -1)), k) != 0:
        return _sign(p, cond(), k)
    if _sign(p, _cond(cand, b), k):
        return None
    return _sign(p, _cond(cand, G0, D), k) if _sign(p, _cond(cand, G1), k) == 0 else Undecided


def _u(p: Point, req: Req, cand, k: int, s):
    """u > 0; at a point where the rows' determinant vanishes on the branch and U or V does not, the
    eigenvector has q_1 = 0 (no datum with q_1(0) = -1): False."""
    v = holds(p, req, cand, k, s)
    if v is not None or p.cell or _sign(p, _cond(cand, cand.det), k) != 0:
        return v
    return False if any(_sign(p, _cond(cand, P), k) != 0 for P in cand.q0[1:]) else None


# ----------------------------------------------------------------- regions: where the requirements hold
class Region:
    """For one branch k (0: the largest real eigenvalue) and fixed point s (±1, or None for two
    gaps): the pieces of ]0, 1[ where every requirement imposed so far holds — open intervals
    (lo, hi) and points (a, a) — and the pieces left undecided."""

    def __init__(self, k: int, s, pieces=None, undecided=None):
        self.k, self.s, self.pieces, self.undecided = k, s, pieces or [], undecided or []


def analyse(cand, stage: tuple, regions: list | None = None, reqs: list | None = None) -> list:
    """The regions (one per real branch k, 0 the largest, and fixed point x_s) after imposing the
    requirements of the stage (:func:`requirements`, or ``reqs``) one at a time over ]0, 1[ (or
    on copies of ``regions``), each only where the previous ones hold."""
    zero, one = number(0), number(1)
    points = cand.points
    sigmas = (1, -1) if len(cand.q0) == 3 else (None,)
    if regions is None:
        ends = [zero] + [a for a, _ in cut_points(_cond(cand, [[1]]).cuts(), zero, one)] + [one]
        found: dict = {}
        for a, b in zip(ends, ends[1:]):
            for piece in [(a, b)] + ([(b, b)] if b is not one else []):
                for k in range(_point(piece, points).branches(cand.cp_dict)):
                    for s in sigmas:
                        found.setdefault((k, s), Region(k, s)).pieces.append(piece)
        regions = list(found.values())
    else:
        regions = [Region(R.k, R.s, list(R.pieces), list(R.undecided)) for R in regions]
    for req in requirements(cand, *stage) if reqs is None else reqs:
        live = [pc for R in regions for pc in R.pieces + R.undecided]
        if not live:
            break
        lo = min((pc[0] for pc in live), key=ORDER)
        hi = max((pc[1] for pc in live), key=ORDER)
        cond = req.cond(cand, sigmas[0])
        cuts = cut_points(cond.cuts(), lo, hi) if lo.compare(hi) < 0 else []
        at = _Reader(req, cand, cond, lo, hi, cuts, points)
        split: dict = {}
        for R in regions:
            kept, unsure = [], []
            for piece, was in [(pc, True) for pc in R.pieces] + [(pc, None) for pc in R.undecided]:
                if id(piece) not in split:
                    split[id(piece)] = _split(piece, [c for c, _ in cuts])
                for sub in split[id(piece)]:
                    v = at.holds(sub, R.k, R.s)
                    if v is not False:
                        (kept if v and was else unsure).append(sub)
            R.pieces, R.undecided = kept, unsure
    return regions


class _Reader:
    """A requirement read on the pieces of its decomposition of ]lo, hi[ (its cut points
    ``cuts``).  An interval: at its sample.  A point r₀ that is not a cut point: at the sample of
    the cell holding it (nothing of the requirement changes there, disc cp included).  A cut
    point r₀, root of one factor f only: (i) f divides only disc cp: the requirement has no zero,
    pole or change of x at r₀ on any root λ of cp(r₀, λ), and the k-th largest real root is
    continuous: the sign of a neighbouring cell where branch k exists; (ii) f divides only the
    numerator's norm Res_Λ(cp, N), exactly once, r₀ a simple root of f: exactly one eigenvalue
    branch (real or not) has N = 0 at r₀, a simple zero in r (the multiplicity of r₀ in the norm
    is the sum of the orders of N on the branches), where N changes sign; so on a branch whose
    two neighbouring cells have one sign N(r₀) ≠ 0 has that sign, and with opposite signs
    N(r₀) = 0 (with √Δ: N₀ ± N₁√Δ, both in the norm 4cQ).  Any other point: exactly, in Q(r₀)
    (cells.Point)."""

    def __init__(self, req, cand, cond, lo, hi, cuts, points):
        self.req, self.cand, self.cond, self.points = req, cand, cond, points
        self.ends = [lo] + [c for c, _ in cuts] + [hi]
        self.cuts = cuts

    def holds(self, piece: tuple, k: int, s):
        a, b = piece
        i = self._where(a) if a is b else None
        if i is None:
            return self.exact(_point(piece, self.points), k, s)
        if i[0] == "cell":
            j = i[1]
            return self.exact(_point((self.ends[j], self.ends[j + 1]), self.points), k, s)
        j, f = i[1], self.cuts[i[1]][1]
        sides = [_point((self.ends[j], a), self.points), _point((a, self.ends[j + 2]), self.points)]
        labels = self.cond.cuts()[tuple(f)][0]
        if labels == {"disc"} and self._alone(a, f):
            here = [p for p in sides if k < p.branches(self.cand.cp_dict)]
            if here:
                return self.exact(here[0], k, s)
        elif self._simple(a, f):
            left, right = (self.exact(p, k, s) for p in sides)
            return left if left == right else False
        return self.exact(_point(piece, self.points), k, s)

    def exact(self, p: Point, k: int, s):
        return _u(p, self.req, self.cand, k, s) if self.req.name == "u" else \
            holds(p, self.req, self.cand, k, s)

    def _where(self, a):
        """("cut", j) when a is the j-th cut point, ("cell", j) when it lies in the j-th cell, None
        at an end of ]lo, hi[."""
        lo, hi = 0, len(self.ends) - 1
        if a.compare(self.ends[lo]) <= 0 or a.compare(self.ends[hi]) >= 0:
            return None
        while hi - lo > 1:
            mid = (lo + hi) // 2
            c = a.compare(self.ends[mid])
            if c == 0:
                return ("cut", mid - 1)
            lo, hi = (mid, hi) if c > 0 else (lo, mid)
        return ("cell", lo)

    def _simple(self, a, f) -> bool:
        labels, m = self.cond.cuts()[tuple(f)]
        return labels == {"N"} and m == 1 and len(a.p) == len(f) and self._alone(a, f)

    def _alone(self, a, f) -> bool:
        """a is a root of no other cut factor."""
        return all(a.sign_of([Fraction(x) for x in g]) != 0 for g in self.cond.cuts() if g != tuple(f))


def _split(piece: tuple, cuts: list) -> list:
    """A piece cut at the cut points inside it: its open intervals and the points between."""
    lo, hi = piece
    if lo is hi:
        return [piece]
    inner = [c for c in cuts if lo.compare(c) < 0 < hi.compare(c)]
    ends = [lo] + inner + [hi]
    out = []
    for k, (a, b) in enumerate(zip(ends, ends[1:])):
        out.append((a, b))
        if k < len(inner):
            out.append((b, b))
    return out


def _point(piece: tuple, points: dict) -> Point:
    """The Point of a piece (a rational sample of an interval, or the point), one per number."""
    a, b = piece
    if a is not b:
        x = _between(a, b)
        return points.setdefault(("q", x), Point(x, True))
    for c, p in points.get(tuple(a.p), []):
        if c is a or c.compare(a) == 0:
            return p
    p = Point(a, False)
    points.setdefault(tuple(a.p), []).append((a, p))
    return p


# ----------------------------------------------------------------- atoms of the statement language
BRANCH = {"upper": 0, "middle": 1, "lower": "lower"}
_SETS: dict = {}


def _text(t) -> str:
    if t[0] not in ("name", "str"):
        raise Undefined("a word is written as letters (or as a string: \"(ab)^3(cb)^3\")")
    return t[1]


def _branches(args, at: int):
    if len(args) <= at:
        return None
    b = _text(args[at])
    if b not in BRANCH:
        raise Undefined(f"{b}: a branch is upper, middle or lower")
    return (BRANCH[b],) if b != "lower" else "lower"


def _regions(ctx, text: str, stage: tuple, branches) -> list:
    """The regions of a stage of the candidate of a word (memoised; "stable" continues from
    "feasible" when that is known), those of the branches asked for; the witness's factors
    learned first."""
    for w in ctx.witnesses or []:
        if isinstance(w, dict) and w.get("kind") == "factors":
            learn(w.get("factors") or [])
    key = (text, stage)
    if key not in _SETS:
        n = len(read_word(text)[1])
        if LONGEST and n > LONGEST:
            raise NotVerified(f"{text} has {n} collisions: beyond the kernel's budget of {LONGEST}")
        cand = candidate(text)
        known = _SETS.get((text, ("feasible", None)))
        if stage[0] == "stable" and known is not None:
            extra = _dominance(cand) + (_attracting(cand) if len(cand.q0) == 3 else [])
            _SETS[key] = analyse(cand, stage, known, extra)
        else:
            _SETS[key] = analyse(cand, stage)
    last = len(candidate(text).cp) - 2
    return [R for R in _SETS[key] if branches is None or (R.k == last if branches == "lower" else R.k in branches)]



def _ends(regions: list) -> list:
    """Conditions in r whose roots are the ends of the regions' pieces (cut points for the
    statement's own decomposition, so that the atom is constant on each of its pieces)."""
    polys = {}
    for R in regions:
        for a, b in R.pieces + R.undecided:
            for e in (a, b):
                if not e.rational:
                    polys.setdefault(tuple(e.p), e.p)
                elif 0 < e.lo < 1:
                    polys.setdefault((e.lo,), [-e.lo, Fraction(1)])
    return [Condition(None, {(i, 0): c for i, c in enumerate(p) if c}, {(0, 0): Fraction(1)}) for p in polys.values()]


def _inside(p: Point, piece: tuple) -> bool:
    a, b = piece
    if a is b or a.compare(b) == 0:
        return not p.cell and number(p.r0).compare(a) == 0
    r0 = number(p.r0)
    return a.compare(r0) < 0 < b.compare(r0)


def _member(p: Point, R) -> bool | None:
    if any(_inside(p, pc) for pc in R.pieces):
        return True
    return None if any(_inside(p, pc) for pc in R.undecided) else False


def _exists(p: Point, regions: list) -> bool:
    """Some branch and fixed point: True; else Undecided where some is undecided."""
    got = [_member(p, R) for R in regions]
    if True in got:
        return True
    if None in got:
        raise Undecided("a region undecided here")
    return False


def _stage_atom(stage: str):
    def args_of(ctx, args):
        at = 2 if stage == "realises" else 1
        v = _letters(_text(args[1])) if stage == "realises" else None
        return _text(args[0]), (stage, v), _branches(args, at)

    def conditions(ctx, args):
        return _ends(_regions(ctx, *args_of(ctx, args)))

    def truth(p, ctx, args, conds):
        text, st, branches = args_of(ctx, args)
        try:
            return _exists(p, _regions(ctx, text, st, branches))
        except Undecided:
            if stage == "feasible" and branches is None and not p.cell and \
                    witnessed_feasible(ctx.witnesses, expand_word(text), p.r0):
                return True            # a degenerate point: a witnessed datum realises the word
            raise
    return conditions, truth


def _letters(text: str) -> str:
    return expand_word(text.replace("[ac]", "s"))


def _next_parts(ctx, args):
    w, v, letter = (_text(a) for a in args)
    v = _letters(v)
    return (_regions(ctx, w, ("realises", v), None), _regions(ctx, w, ("realises", v + _letters(letter)), None))


def _next_conditions(ctx, args):
    before, after = _next_parts(ctx, args)
    return _ends(before + after)


def _next_truth(p, ctx, args, conds):
    """Wherever (branch, fixed point) the candidate realises v, it realises v + letter: the
    next collision is that letter, strictly before any other."""
    before, after = _next_parts(ctx, args)
    out = True
    for R, S in zip(before, after):
        a, b = _member(p, R), _member(p, S)
        if a is False or b is True:
            continue
        if a is True and b is False:
            return False
        out = None
    if out is None:
        raise Undecided("a region undecided here")
    return True


def eigenvector(ctx, w) -> tuple:
    """q(0) = (-1, u, v) (two gaps: (-1, u)) of the candidate: rows 1 and 2 of (M_w - λ) q = 0 by
    Cramer's rule (l. 366), as rational functions of r and λ (Λ = 2ⁿλ put back)."""
    cand = candidate(_text(w))
    det = _rf(El(cand.det, [1]), len(cand.word))
    return (RF.const(-1),) + tuple(_rf(El(P, [1]), len(cand.word)) / det for P in cand.q0[1:])


def posmap(ctx, w) -> RF:
    """f(x) = p_3(t_n)/p_1(t_n) of the candidate of a four-particle word (l. 270-280), a rational
    function of r, λ and the declared variable x (Λ = 2ⁿλ put back)."""
    cand = candidate(_text(w))
    if len(cand.q0) != 3:
        raise Undefined("the position map of a word of four particles")
    (d, c), _, (b, a) = cand.run.p[-1]
    x = RF.var("x")
    rf = [_rf(e, len(cand.word)) for e in (a, b, c, d)]
    return (rf[0] * x + rf[1]) / (rf[2] * x + rf[3])


def _rf(e: El, n: int) -> RF:
    """An element (c₀ + c₁Λ + c₂Λ²)/δ(r) as a rational function of r and λ = Λ/2ⁿ."""
    return RF({(i, j): Fraction(a * 2 ** (n * j)) for j, c in enumerate(e.c) for i, a in enumerate(c) if a},
              {(i,): Fraction(a) for i, a in enumerate(e.d) if a})


for _name, _stage in (("selfsimilar", "datum"), ("feasible", "feasible"), ("stable", "stable"),
                      ("realises", "realises")):
    ATOMS[_name] = _stage_atom(_stage)
ATOMS["next"] = (_next_conditions, _next_truth)
FUNCTIONS["eigenvector"], FUNCTIONS["posmap"] = eigenvector, posmap
