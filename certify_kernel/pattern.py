"""The self-similar candidate of a periodic collision word, and where it realises the word
(l. 265-321, 441-516; the literature, l. 130-132, 1099-1130), decided exactly.

A word w = c_1 ... c_n of collisions (four particles: a, b, c for the pairs 1-2, 2-3, 3-4; three
particles: a, b; the symmetric system p_1 = p_3, q_1 = q_3 of l. 132: [ac], b) starts with the
collision of the first gap and ends with b (the paper's normalisation, l. 270-280).  The
velocities after it are M_w q, M_w = K_{c_n} ··· K_{c_1}, the K the kernel's collision matrices
(:func:`evaluate.collision`; three particles: the leading 2×2 blocks of A and B, which do not
read q_3; the symmetric system: A·C and B on the vectors (q_1, q_2, q_1)).  Its *candidate*, on
a real eigenvalue λ of M_w (a branch, the largest first): q(0) = (-1, u[, v]) solving the first
rows of (M_w - λ) q = 0 (rows 1 and 2, l. 366; where they are 0/0, rows 1 and 3, then 2 and 3),
p(0) = (1, 0[, x]); the collisions are *assumed* (l. 460-463): at collision k, of gap i,
p(t_k) = p(t_{k-1}) - (p_i/q_i) q(t_{k-1}), q(t_k) = K q(t_{k-1}).  After the period p_2 = 0 and
(four particles) p_3/p_1 = f(x) = (ax + b)/(cx + d); x is a fixed point x± = (a - d ± √Δ)/(2c),
Δ = (a - d)² + 4bc (where c = 0, f is affine: x = b/(d - a)).

The candidate *realises* a word v (its first |v| collisions, strictly) iff u > 0 (p_2 opens
after the b before t = 0), x > 0, and at each collision k of gap i the pair approaches,
q_i(t_{k-1}) < 0, its gap is open, p_i(t_{k-1}) > 0 (automatic for k = 1 and when the pair
collided at k - 2), and every gap that does not collide at the last two collisions is open at
the end.  Enough: a collision b adds (1+r)/2·q_2 < 0 to q_1 and q_3, a or c adds (1+r)/2·q_1 or
q_3 < 0 to q_2 ([ac]: (1+r) q_1), so every gap is concave between two collisions of its own
pair; positive at both ends, it is positive inside: no other pair collides first, no triple
collision (the paper's argument, l. 478-480, for every gap).  Self-similar data *exist* where λ > 0,
u > 0, x real and > 0; the word is *feasible* where moreover the candidate realises it; *stable*
where moreover λ is strictly dominant (|μ| < λ for the other eigenvalues μ: with Q = cp/(Λ - λ),
Q(λ) = cp'(λ) > 0, Q(-λ) > 0 and, for a cubic, μν = det M/λ < λ², Schur-Cohn) and the fixed
point attracts, |f'(x)| < 1, i.e. (cx + d)² ∓ (ad - bc) > 0, with (cx + d)² = c(a + d)x + bc + d²
at a fixed point.

How it is computed.  With K' = 2K (integer matrices) M' = 2ⁿ M_w and Λ = 2ⁿ λ, cp' = det(Λ - M')
is monic in Λ with integer coefficients; every quantity is an element of Q(r)[Λ]/(cp') written
(c₀ + c₁Λ + c₂Λ²)/δ(r), divided by the gcd of its parts (univariate gcds), inverses by the
adjugate of the multiplication matrix over its determinant, the norm (Res_Λ(cp', ·)).  Its
value on a branch is the quantity's wherever δ(r₀) ≠ 0 (cp' is monic: the identities hold in
Z[r][Λ]/(cp')).  At a point where δ(r₀) = 0 the same requirement is read on the division-free
run (p̃(t_k) = q̃_i p̃(t_{k-1}) - p̃_i q̃, the velocities q̃ = det·q: p̃(t_k) = s_k p(t_k) with
sign s_k = (-sign det)^k once the velocity requirements hold).  A sign on a branch over an
interval of r is decided by :mod:`certify_kernel.cells` (cut points: the roots of the norms of a
requirement's parts; one exact sample per cell).  The requirements are imposed one at a time,
each only where all the previous ones hold (the region of each branch and fixed point).  The
norms are split over the certificate's witness of irreducible factors (each checked by exact
division; what is left is treated as it is), so that the cut points are roots of small
polynomials.
"""
from __future__ import annotations

from fractions import Fraction
from math import gcd as igcd

from .cells import Condition, Point, Undecided, _between, _OrderKey
from .poly import gcd as qgcd
from .poly import divmod_, integer_primitive, squarefree, trim
from .sturm import Algebraic
from .values import RF, Undefined, number, roots_in

# ----------------------------------------------------------------- integer polynomials
# in r: lists of ints, lowest degree first; in (r, Λ): lists over the powers of Λ of those.


def _add(p: list, q: list, c: int = 1) -> list:
    out = list(p) + [0] * (len(q) - len(p))
    for i, y in enumerate(q):
        out[i] += c * y
    return _trim(out)


def _trim(p: list) -> list:
    """Without its trailing zeros (numbers, or empty polynomials)."""
    while p and (p[-1] == 0 or p[-1] == []):
        p.pop()
    return p


def _mul(p: list, q: list) -> list:
    """p·q; long ones by Kronecker substitution (p(2^k)·q(2^k) in one integer product, its
    digits the coefficients: 2^(k-1) bounds them)."""
    if not p or not q:
        return []
    if min(len(p), len(q)) < 16 or not all(type(a) is int for a in p + q):
        out = [0] * (len(p) + len(q) - 1)
        for i, a in enumerate(p):
            if a:
                for j, b in enumerate(q):
                    out[i + j] += a * b
        return _trim(out)
    k = (max(map(abs, p)) * max(map(abs, q)) * min(len(p), len(q))).bit_length() + 1
    C = sum(a << (k * i) for i, a in enumerate(p)) * sum(b << (k * i) for i, b in enumerate(q))
    out, mask, half = [], (1 << k) - 1, 1 << (k - 1)
    for _ in range(len(p) + len(q) - 1):
        d = C & mask
        d = d - (1 << k) if d >= half else d
        out.append(d)
        C = (C - d) >> k
    return _trim(out)


def _badd(P: list, Q: list, c: int = 1) -> list:
    return _trim([_add(P[j] if j < len(P) else [], Q[j] if j < len(Q) else [], c)
                  for j in range(max(len(P), len(Q)))])


def _bmul(P: list, Q: list) -> list:
    out: list = [[] for _ in range(max(len(P) + len(Q) - 1, 0))]
    for i, a in enumerate(P):
        for j, b in enumerate(Q):
            if a and b:
                out[i + j] = _add(out[i + j], _mul(a, b))
    return _trim(out)


def _brem(P: list, cp: list) -> list:
    """P modulo cp, monic in Λ (Λ^m = -(the rest of cp)): the same value on every branch."""
    m, P = len(cp) - 1, [list(c) for c in P]
    while len(P) > m:
        top, k = P.pop(), len(P) - m
        for j in range(m):
            P[k + j] = _add(P[k + j], _mul(top, cp[j]), -1)
        _trim(P)
    return P


def _content(polys) -> int:
    g = 0
    for p in polys:
        for a in p:
            g = igcd(g, a)
    return g


def _exact(p: list, f: list) -> list | None:
    """p/f in Z[r] when f divides p (f primitive: Gauss), else None."""
    if not p:
        return []
    p, q = list(p), [0] * (len(p) - len(f) + 1)
    if len(q) < 1:
        return None
    for k in range(len(q) - 1, -1, -1):
        a, rem = divmod(p[k + len(f) - 1], f[-1])
        if rem:
            return None
        q[k] = a
        if a:
            for j, b in enumerate(f):
                p[k + j] -= a * b
    return _trim(q) if not any(p) else None


def _gcd(p: list, q: list) -> list:
    """The primitive gcd in Z[r] (:func:`poly.gcd` over Q, made integral)."""
    if not p or not q:
        return integer_primitive(p or q)
    if len(p) == 1 or len(q) == 1:
        return [1]
    return [int(c) for c in integer_primitive(qgcd(p, q))]


# ----------------------------------------------------------------- Q(r)[Λ]/(cp)
class El:
    """(c₀ + c₁Λ + ...)/δ(r) in Z[r][Λ]/(cp), δ ≠ 0 with a positive leading coefficient, the
    parts without common factor."""

    __slots__ = ("c", "d")

    def __init__(self, c: list, d: list):
        self.c, self.d = c, d


def _el(c: list, d: list, cp: list) -> El:
    c = _brem(c, cp)
    if not c:
        return El([], [1])
    g = d
    for p in c:
        if len(g) < 2:
            break
        g = _gcd(g, p)
    if len(g) > 1:
        c, d = [_exact(p, g) for p in c], _exact(d, g)
    k = _content(c + [d]) * (1 if d[-1] > 0 else -1)
    return El([[a // k for a in p] for p in c], [a // k for a in d])


def _emul(x: El, y: El, cp: list) -> El:
    return _el(_bmul(x.c, y.c), _mul(x.d, y.d), cp)


def _esub(x: El, y: El, cp: list) -> El:
    return _el(_badd(_bmul(x.c, [y.d]), _bmul(y.c, [x.d]), -1), _mul(x.d, y.d), cp)


def _det(rows: list) -> list:
    """The determinant of a 2×2 or 3×3 matrix of polynomials in r."""
    if len(rows) == 2:
        (a, b), (c, d) = rows
        return _add(_mul(a, d), _mul(b, c), -1)
    out: list = []
    for j in range(3):
        minor = [[row[k] for k in range(3) if k != j] for row in rows[1:]]
        out = _add(out, _mul(rows[0][j], _det(minor)), (-1) ** j)
    return out


def _mult_matrix(P: list, cp: list) -> list:
    """Rows of the matrix of multiplication by P in the basis 1, Λ, ... (column j: P·Λ^j)."""
    m = len(cp) - 1
    cols = [_brem(_bmul(P, [[]] * j + [[1]]), cp) for j in range(m)]
    return [[cols[j][i] if i < len(cols[j]) else [] for j in range(m)] for i in range(m)]


def norm(P: list, cp: list) -> list:
    """Res_Λ(cp, P) = Π P(λ_i) (cp monic): the determinant of the multiplication by P."""
    if len(P) < 2:
        return [a for a in (P[0] if P else [])] and _pow(P[0], len(cp) - 1)
    return _det(_mult_matrix(P, cp))


def _pow(p: list, n: int) -> list:
    out = [1]
    for _ in range(n):
        out = _mul(out, p)
    return out


def _einv(x: El, cp: list) -> El:
    """1/x = δ·adj(M_c)·e₁/det M_c (M_c the multiplication by x's numerator: the solution y of
    M_c y = e₁ is the numerator's inverse; adj(M)_{k1} = (-1)^k times the minor of row 1, column k)."""
    M = _mult_matrix(x.c, cp)
    m = len(M)
    if m == 2:
        adj = [M[1][1], [-a for a in M[1][0]]]
    else:
        adj = [_det([[M[i][j] for j in range(3) if j != k] for i in (1, 2)]) for k in range(3)]
        adj = [a if k % 2 == 0 else [-b for b in a] for k, a in enumerate(adj)]
    n = _det(M)
    if not n:
        raise Undefined("a quantity of the candidate vanishes on a whole branch")
    return _el([_mul(x.d, a) for a in adj], n, cp)


# ----------------------------------------------------------------- the systems and the candidate
def _int_matrix(M, size: int) -> list:
    """2K as integer polynomials in r (K: the kernel's RF matrix, entries in Q[r] with
    denominators dividing 2)."""
    from .values import univariate
    out = []
    for row in M.rows[:size]:
        out.append([_trim([int(2 * c) for c in univariate(e)]) if not e.is_zero() else [] for e in row[:size]])
    return out


def _matrices(system: str) -> dict:
    from .evaluate import Matrix, collision
    A, B, C = collision(0), collision(1), collision(2)
    if system == "four":
        return {"a": _int_matrix(A, 3), "b": _int_matrix(B, 3), "c": _int_matrix(C, 3)}
    if system == "three":               # particles 1, 2, 3: A and B do not read q_3
        return {"a": _int_matrix(A, 2), "b": _int_matrix(B, 2)}

    def restrict(K):                    # on (q_1, q_2, q_1): rows 1, 2; columns 1 + 3, 2
        R = K.rows
        if not ((R[2][0] + R[2][2] - R[0][0] - R[0][2]).is_zero() and (R[2][1] - R[0][1]).is_zero()):
            raise Undefined("a collision of the symmetric system does not keep q_1 = q_3")
        return Matrix([[R[i][0] + R[i][2], R[i][1]] for i in range(2)])
    return {"s": _int_matrix(restrict(A * C), 2), "b": _int_matrix(restrict(B), 2)}


def read_word(text: str) -> tuple[str, str]:
    """(system, letters) of a word as printed: (ab)^n powers, [ac] the simultaneous collision
    (letter s); a word without c is one of three particles."""
    from .evaluate import expand_word
    sym = "[ac]" in text
    letters = expand_word(text.replace("[ac]", "s"))
    system = "symmetric" if sym else "four" if "c" in letters else "three"
    allowed = {"symmetric": "sb", "four": "abc", "three": "ab"}[system]
    if set(letters) - set(allowed) or letters[0] not in "as" or letters[-1] != "b":
        raise Undefined(f"{text!r}: a word of the collisions {', '.join(allowed)}, from the first gap's to b")
    return system, letters


GAP = {"a": 0, "s": 0, "b": 1, "c": 2}


class Run:
    """The assumed collisions of a word from q̃(0), p(0) = (1, 0[, x]): after each collision the
    velocities q̃ (polynomials: det·2^k·q) and the positions, each gap's as the pair (P0, P1) of
    elements with p = P0 + x P1."""

    def __init__(self, cand, word: str):
        self.cand, self.word = cand, word
        cp, q = cand.cp, list(cand.q0)
        g = len(q)
        one, zero = El([[1]], [1]), El([], [1])
        P = [(one, zero), (zero, zero)] + ([(zero, one)] if g == 3 else [])
        self.q, self.p = [q], [P]
        for letter in word:
            i = GAP[letter]
            w = _einv(El(q[i], [1]), cp)
            t = [_emul(P[i][h], w, cp) for h in (0, 1)]
            P = [tuple(_esub(P[j][h], _emul(t[h], El(q[j], [1]), cp), cp) for h in (0, 1)) for j in range(g)]
            P[i] = (zero, zero)
            K = cand.K[letter]
            q = [_sum([_bmul(q[j], [K[row][j]]) for j in range(g) if K[row][j]]) for row in range(g)]
            self.q.append(q)
            self.p.append(P)


def _sum(items) -> list:
    out: list = []
    for P in items:
        out = _badd(out, P)
    return out


class Candidate:
    """M' = 2ⁿ M_w, cp' = det(Λ - M'), q̃(0) = det·(-1, u[, v]) from the rows ``rows`` of
    (M' - Λ) q = 0 (Cramer), the run of the word, and (four particles) the position map."""

    def __init__(self, text: str, rows: tuple = (0, 1)):
        self.text, self.rows = text, rows
        self.system, self.word = read_word(text)
        self.K = _matrices(self.system)
        g = 3 if self.system == "four" else 2
        M = [[[1] if i == j else [] for j in range(g)] for i in range(g)]
        for letter in self.word:
            K = self.K[letter]
            M = [[_sum([[_mul(K[i][k], M[k][j])] for k in range(g)])[:1] for j in range(g)] for i in range(g)]
            M = [[e[0] if e else [] for e in row] for row in M]
        self.M = M
        A = [[[[-a for a in M[i][j]]] if M[i][j] else [] for j in range(g)] for i in range(g)]   # -(M' - Λ)
        for i in range(g):
            A[i][i] = _badd(A[i][i], [[], [1]])
        self.cp = _det3b(A) if g == 3 else _badd(_bmul(A[0][0], A[1][1]), _bmul(A[0][1], A[1][0]), -1)
        B = [[[[-a for a in c] for c in A[i][j]] for j in range(g)] for i in range(g)]     # M' - Λ
        if g == 3:
            i, j = rows
            det = _badd(_bmul(B[i][1], B[j][2]), _bmul(B[i][2], B[j][1]), -1)
            U = _badd(_bmul(B[i][0], B[j][2]), _bmul(B[i][2], B[j][0]), -1)
            V = _badd(_bmul(B[i][1], B[j][0]), _bmul(B[i][0], B[j][1]), -1)
            self.q0 = [[[-a for a in c] for c in _brem(det, self.cp)], _brem(U, self.cp), _brem(V, self.cp)]
        else:                            # row 1: (m11 - Λ)(-1) + m12 u = 0; row 2: m21(-1) + (m22 - Λ) u = 0
            det, U = (B[0][1], B[0][0]) if rows[0] == 0 else (B[1][1], B[1][0])
            self.q0 = [[[-a for a in c] for c in det], U]
        self.det = _brem(det, self.cp)
        self.runs: dict = {}
        self.run = self.run_of(self.word)
        if g == 3:
            P = self.run.p[-1]
            (d, c), (b, a) = P[0], P[2]
            L1, L3 = _lcm(d.d, c.d), _lcm(b.d, a.d)
            abcd = [_bmul(e.c, [_mul(_exact(L, e.d), L2)]) for e, L, L2 in
                    ((a, L3, L1), (b, L3, L1), (c, L1, L3), (d, L1, L3))]
            h = _content(x for P_ in abcd for x in P_)        # f is the same for (a, b, c, d)/h
            self.abcd = [[[y // h for y in x] for x in P_] for P_ in abcd]
            self.scale = [_mul(L1, L3)]      # (a, b, c, d) = L1·L3/h times p(t_n)'s coefficients

    @property
    def cp_dict(self) -> dict:
        if getattr(self, "_cpd", None) is None:
            self._cpd = _dict(self.cp)
        return self._cpd

    def disc_factors(self) -> list:
        """The factors of Res_Λ(cp, ∂cp/∂Λ): where two branches meet."""
        if getattr(self, "_disc", None) is None:
            self._disc = _factors(norm([[i * a for a in c] for i, c in enumerate(self.cp)][1:], self.cp))
        return self._disc

    def disc_cond(self) -> _Cond:
        return _Cond(self, {"N0": [[1]], "D0": [[1]]}, [])

    def relabel(self, p: Point, k: int):
        """ε with x_s of (a, b, c, d) = x_{εs} of the division-free (a, b, c, d) at p on branch k:
        their common factors are L1·L3/h and s_n = Π q̃_i (where the first is 0 at p, the
        second's sign is used throughout at p); None where s_n = 0."""
        one = [[1]]
        e = _sign(p, _Cond(self, {"N0": self.scale, "D0": one}, []), k) or 1
        for k_, letter in enumerate(self.word):
            e *= _sign(p, _Cond(self, {"N0": self.run.q[k_][GAP[letter]], "D0": one}, []), k)
        return e or None

    def run_of(self, word: str) -> Run:
        if word not in self.runs:
            self.runs[word] = Run(self, word)
        return self.runs[word]


def _det3b(A: list) -> list:
    """The determinant of a 3×3 matrix of polynomials in (r, Λ)."""
    out: list = []
    for j in range(3):
        m = [[A[i][k] for k in range(3) if k != j] for i in (1, 2)]
        out = _badd(out, _bmul(A[0][j], _badd(_bmul(m[0][0], m[1][1]), _bmul(m[0][1], m[1][0]), -1)),
                    (-1) ** j)
    return out


def _lcm(a: list, b: list) -> list:
    g = _gcd(a, b)
    return _mul(a, _exact(b, g))


# ----------------------------------------------------------------- requirements and their conditions
def _dict(P: list) -> dict:
    """A polynomial in (r, Λ) as the cells' dict (e_r, e_Λ) -> coefficient."""
    return {(i, j): Fraction(a) for j, c in enumerate(P) for i, a in enumerate(c) if a}


class Req:
    """A quantity g = (G0 + x G1)/D and the strict sign it must have (G0, G1, D polynomials in
    r, Λ).  ``free``: the same from the division-free run, or None when the form has no
    division (velocities: q̃_i/det)."""

    def __init__(self, name: str, sign: int, G0: list, G1: list, D: list, free=None, kind: tuple = ()):
        self.name, self.sign, self.G0, self.G1, self.D, self.free, self.kind = name, sign, G0, G1, D, free, kind
        self._conds: dict = {}

    def cond(self, cand, s, abcd=None, affine: bool = False) -> Condition:
        """The cells' Condition of g on the branches, x the fixed point x_s of (a, b, c, d)
        (the candidate's, or the given ones; ``affine``: x = b/(d - a), f being affine)."""
        key = (s, id(abcd), affine)
        if key not in self._conds:
            self._conds[key] = _condition(cand, self.G0, self.G1, self.D, s, abcd or getattr(cand, "abcd", None),
                                          affine)
        return self._conds[key]


class _Cond(Condition):
    """A Condition whose cut points are the roots of the norms Res_Λ(cp, P) of labelled
    polynomials P ("N": its zeros, "D": its poles, "delta", "c": those of x), split by the factor
    base, and of the discriminant."""

    def __init__(self, cand, parts: dict, norms: list):
        super().__init__(cand.cp_dict, *(_dict(parts.get(k, [])) for k in ("N0", "D0", "N1")), None,
                         _dict(parts["delta"]) if parts.get("delta") else None)
        self.cand, self.norms, self._cuts = cand, norms, None

    def cuts(self) -> dict:
        """factor -> (the labels of the norms it divides, its exponent in the "N" norm)."""
        if self._cuts is None:
            out: dict = {}
            for f, _ in self.cand.disc_factors():
                out[tuple(f)] = ({"disc"}, 0)
            for label, P in (self.norms() if callable(self.norms) else self.norms):
                for f, e in _factors(norm(P, self.cand.cp) if len(P) > 1 else (P[0] if P else [])):
                    labels, m = out.get(tuple(f), (set(), 0))
                    out[tuple(f)] = (labels | {label}, m + (e if label == "N" else 0))
            self._cuts = out
        return self._cuts

    def bounding(self) -> list:
        return [[Fraction(a) for a in f] for f in self.cuts()]


def _condition(cand, G0, G1, D, s, abcd, affine) -> _Cond:
    """g = (G0 + x G1)/D with x = x_s of (a, b, c, d) (``cand``: the candidate, or a :class:`_Reduced`
    at a point), as the cells' Condition: N₀ = 2cG0 + (a - d)G1, N₁ = s·G1, D₀ = 2cD, Δ."""
    cp = cand.cp
    red = getattr(cand, "reduce", lambda P: P)
    if not G1:
        return _Cond(cand, {"N0": G0, "D0": D}, [("N", G0), ("D", D)]) if D else None
    a, b, c, d = abcd
    if affine:                                         # x = b/(d - a)
        dma = _badd(d, a, -1)
        D0 = red(_brem(_bmul(dma, D), cp))
        return _Cond(cand, {"N0": red(_brem(_badd(_bmul(G0, dma), _bmul(b, G1)), cp)), "D0": D0}, []) if D0 else None
    A = _badd(a, d, -1)
    delta = red(_brem(_badd(_bmul(A, A), _bmul([[4]], _bmul(b, c))), cp))
    N0 = red(_brem(_badd(_bmul([[2]], _bmul(c, G0)), _bmul(A, G1)), cp))
    D0 = red(_brem(_bmul([[2]], _bmul(c, D)), cp))
    if not D0:
        return None

    def norms():
        Q = _brem(_badd(_badd(_bmul(c, _bmul(G0, G0)), _bmul(A, _bmul(G0, G1))), _bmul(b, _bmul(G1, G1)), -1), cp)
        return [("N", Q), ("c", c), ("D", D), ("delta", delta)]
    return _Cond(cand, {"N0": N0, "D0": D0, "N1": [[s * x for x in p] for p in G1], "delta": delta}, norms)


def requirements(cand, stage: str, v: str | None = None) -> list:
    """The requirements of a stage, in the order they are imposed: datum (λ > 0, u > 0, x > 0),
    realises v (u > 0, x > 0, and the collisions of v), feasible (λ > 0 and realises w), stable
    (moreover λ dominant and |f'(x)| < 1)."""
    one, four = [[1]], len(cand.q0) == 3
    lam = Req("λ", 1, [[], [1]], [], one)
    u = Req("u", 1, cand.q0[1], [], cand.det)
    x = Req("x", 1, [], one, one, free=lambda R: ([], one, one), kind=("x",))
    if stage == "datum":
        return [lam, u] + ([x] if four else [])
    v = cand.word if v is None else v
    run, previous = cand.run_of(v), GAP[cand.word[-1]]
    gaps = [previous] + [GAP[ch] for ch in v]
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
    if stage in ("feasible", "stable"):
        out = [lam] + out
    if stage == "stable":
        out = out[:1] + _dominance(cand) + out[1:] + (_attracting(cand) if four else [])
    return out


def _position(cand, run, k: int, j: int) -> Req:
    """p_j(t_k) > 0: P0 + x P1 over one denominator; the division-free form over (-det)^k."""
    P0, P1 = run.p[k][j]
    L = _lcm(P0.d, P1.d)
    G0 = _bmul(P0.c, [_exact(L, P0.d)]) if P0.c else []
    G1 = _bmul(P1.c, [_exact(L, P1.d)]) if P1.c else []

    def free(R):
        F0, F1 = R.free(run.word)[k][j]
        return F0, F1, (R.minus_det if k % 2 else [[1]])
    return Req(f"p_{j + 1}(t_{k})", 1, G0, G1, [L], free=free, kind=("p", run.word, k, j))


def _dominance(cand) -> list:
    """λ strictly dominant: cp'(λ) > 0, cp(-λ) > 0 (quadratic); cp'(λ) > 0, -cp(-λ) > 0,
    λ³ - det M > 0 (cubic) (cp' monic in Λ = 2ⁿλ: positive multiples)."""
    cp, one = cand.cp, [[1]]
    d = [[i * a for a in c] for i, c in enumerate(cp)][1:]
    minus = [[(-1) ** i * a for a in c] for i, c in enumerate(cp)]
    if len(cp) == 3:
        return [Req("cp'(λ)", 1, d, [], one), Req("cp(-λ)", 1, minus, [], one)]
    return [Req("cp'(λ)", 1, d, [], one), Req("-cp(-λ)", -1, minus, [], one),
            Req("λ³ - det M", 1, _badd([[], [], [], [1]], [cp[0]]), [], one)]


def _attracting(cand) -> list:
    """|f'(x)| < 1 at a fixed point: (cx + d)² ∓ (ad - bc) > 0, (cx + d)² = c(a + d)x + bc + d²."""
    out = []
    for sg in (-1, 1):
        def parts(abcd, sg=sg):
            a, b, c, d = abcd
            ad_bc = _badd(_bmul(a, d), _bmul(b, c), -1)
            return _badd(_badd(_bmul(b, c), _bmul(d, d)), ad_bc, sg), _bmul(c, _badd(a, d)), [[1]]
        G0, G1, D = parts(cand.abcd)
        out.append(Req(f"(cx+d)² {'+' if sg > 0 else '-'} (ad-bc)", 1, _brem(G0, cand.cp), _brem(G1, cand.cp), D,
                       free=lambda R, parts=parts: tuple(R.reduce(P) for P in parts(R.abcd)), kind=("f'", sg)))
    return out


# ----------------------------------------------------------------- cut points: norms split by the factor base
BASE: list = []            # primitive integer polynomials in r (a witness's factors), with their values at 2
LARGEST = 40               # a cut polynomial left of larger degree is not isolated (the kernel's Sturm is slow)


def learn(factors) -> None:
    """Add a witness's factors to the base (each used only through an exact division)."""
    known = {tuple(f) for f, _ in BASE}
    for f in factors:
        f = [int(a) for a in integer_primitive([Fraction(a) for a in f])]
        if len(f) > 1 and tuple(f) not in known:
            known.add(tuple(f))
            BASE.append((f, sum(a << i for i, a in enumerate(f))))


def _factors(p: list) -> list:
    """p = Π f^e · rest with f from the base (exact divisions): [(f, e)], and (rest's square-free
    part, 1 if rest is square-free, else 2: its roots may be multiple)."""
    p = [int(a) for a in integer_primitive(p)] if p else []
    if len(p) < 2:
        return []
    out, at2 = [], sum(a << i for i, a in enumerate(p))
    for f, f2 in BASE:
        e = 0
        while len(p) >= len(f) and (f2 == 0 or at2 % f2 == 0):
            q = _exact(p, f)
            if q is None:
                break
            p, at2, e = q, sum(a << i for i, a in enumerate(q)), e + 1
        if e:
            out.append((f, e))
    if len(p) > 1:
        sq = squarefree([Fraction(a) for a in p])
        if len(sq) - 1 > LARGEST:
            from .evaluate import NotVerified
            raise NotVerified(f"a cut polynomial of degree {len(sq) - 1} that the witness's factors do not split")
        out.append(([int(a) for a in integer_primitive(sq)], 1 if len(sq) == len(p) else 2))
    return out


def _cuts(cond: _Cond, lo, hi) -> list:
    """The roots in ]lo, hi[ of the condition's cut factors, increasing, each once, with its factor."""
    pts: list = []
    for f in cond.cuts():
        for a in roots_in([Fraction(x) for x in f], lo, hi):
            if not any(a.compare(b) == 0 for b, _ in pts):
                pts.append((a, f))
    return sorted(pts, key=lambda e: _OrderKey(e[0]))


# ----------------------------------------------------------------- a requirement at a piece of r
def _sign(p: Point, cond, k: int):
    """The sign of cond on branch k at p: -1, 0, 1, None (x not real), or Undecided (a pole;
    cond None: a denominator ≡ 0).  At an algebraic point by enclosures first
    (:func:`_enclosed`), exactly when they do not decide (a zero, a pole)."""
    if cond is None:
        return Undecided
    if not p.cell:
        g = _enclosed(p, cond, k)
        if g != 0:
            return g
    try:
        return p.sign(cond, k)
    except Undecided:
        return Undecided


def _enclosed(p: Point, cond, k: int):
    """cond's sign on branch k at the algebraic point p by rational interval arithmetic: r₀ in
    its isolating interval, λ_k(r₀) in an interval [α, β] where cp(r₀, ·) changes sign (a simple
    root), each coefficient c_j(r) enclosed by the mean value theorem, then Horner in λ and the
    square roots of Δ's bounds; the intervals narrowed to 2^-24, 2^-56, 2^-88 until they decide:
    -1, 1, None (Δ < 0: x not real), or 0 when they do not decide."""
    memo = p.__dict__.setdefault("_enclosures", {})
    if (cond.key, k) not in memo:
        g = 0
        for bits in (24, 64, 160):
            g = _enclosed_at(p, cond, k, Fraction(1, 2 ** bits))
            if g != 0:
                break
        memo[(cond.key, k)] = g
    return memo[(cond.key, k)]


def _enclosed_at(p: Point, cond, k: int, width: Fraction):
    lam = _lambda_interval(p, cond.cp, k, width)
    if lam is None:
        return 0
    r0 = p.r0
    _narrow(r0, width)

    def box(P: dict):
        rows: dict = {}
        for (i, j), c in P.items():
            rows.setdefault(j, {})[i] = c
        out = (Fraction(0), Fraction(0))
        for j in range(max(rows, default=-1), -1, -1):
            out = _iadd(_imul(out, lam), _ipoly(rows.get(j, {}), r0.lo, r0.hi))
        return out
    parts = cond.parts
    D = box(parts["D0"])
    if D[0] <= 0 <= D[1]:
        return 0
    N = box(parts["N0"])
    if parts["N1"]:
        dl, dh = box(parts["delta"])
        if dh < 0:
            return None
        if dl <= 0:
            return 0
        from .values import _root_above, _root_below
        N = _iadd(N, _imul(box(parts["N1"]), (_root_below(dl, 96), _root_above(dh, 96))))
    if N[0] <= 0 <= N[1]:
        return 0
    return (1 if N[0] > 0 else -1) * (1 if D[0] > 0 else -1)


def _lambda_interval(p: Point, cp: dict, k: int, width: Fraction):
    """[α, β] holding λ_k(r₀) and no other root, narrower than width (None at a multiple root):
    bisected by the sign of cp(r₀, ·) at the middle (by enclosure, exactly when it does not
    decide)."""
    cache = p.__dict__.setdefault("_lam", {})
    if k >= p.branches(cp):
        return None
    if k not in cache:
        cpl, roots = p._roots[repr(sorted(cp.items()))]
        if roots.count(roots[k]) > 1:
            return None
        cache[k] = [Fraction(roots[k][0]), Fraction(roots[k][1]), p._at.at(cpl, roots[k][0]), cpl]
    a, b, sa, cpl = cache[k]
    r0 = p.r0
    while b - a > width:
        _narrow(r0, width ** 2)
        mid = (a + b) / 2
        e = (Fraction(0), Fraction(0))
        for c in reversed(cpl):
            e = _iadd(_imul(e, (mid, mid)), _ipoly(dict(enumerate(c)), r0.lo, r0.hi))
        sm = 1 if e[0] > 0 else -1 if e[1] < 0 else p._at.at(cpl, mid)
        if sm == 0:
            a = b = mid
        elif sm == sa:
            a = mid
        else:
            b = mid
    cache[k][:2] = [a, b]
    return a, b


def _ipoly(c: dict, lo: Fraction, hi: Fraction) -> tuple:
    """An enclosure of Σ c_i r^i over [lo, hi] ⊆ [X - W, X + W]/S (S = 2^(bits+1), dyadic X, W, a grid
    finer than the interval): its value at the centre ± Σ i|c_i|(|X| + W)^(i-1)·W (the mean value
    theorem), in integers."""
    if not c:
        return Fraction(0), Fraction(0)
    w = hi - lo
    bits = max(64, w.denominator.bit_length() - w.numerator.bit_length() + 32) if w else 64
    den = 1
    for a in c.values():
        den = den * Fraction(a).denominator // igcd(den, Fraction(a).denominator)
    ints = {i: int(Fraction(a) * den) for i, a in c.items()}
    n, S = max(ints), 1 << (bits + 1)
    lo2, hi2 = (lo.numerator << bits) // lo.denominator, -((-hi.numerator << bits) // hi.denominator)
    X, W = lo2 + hi2, hi2 - lo2                       # centre and half-width, times S
    M, val, err, Sk = abs(X) + W, ints.get(n, 0), n * abs(ints.get(n, 0)), S
    for i in range(n - 1, -1, -1):                    # homogeneous Horner: Σ a_i X^i S^(n-i)
        a = ints.get(i, 0)
        val = val * X + a * Sk
        if i:
            err = err * M + i * abs(a) * Sk
        Sk *= S
    err *= W
    q = den * S ** n
    return Fraction(val - err, q), Fraction(val + err, q)


def _imul(a: tuple, b: tuple) -> tuple:
    ps = (a[0] * b[0], a[0] * b[1], a[1] * b[0], a[1] * b[1])
    return min(ps), max(ps)


def _iadd(a: tuple, b: tuple) -> tuple:
    return a[0] + b[0], a[1] + b[1]


def _ball_sign(p: Point, req: Req, cand, k: int, s: int):
    """The sign of a requirement of the positions (p_j(t_k), x, |f'(x)| < 1) at the algebraic
    point p on branch k, from the run itself in rational intervals (:func:`_balls`): p(t_k) =
    p(t_{k-1}) - (p_i/q_i) q(t_{k-1}) with the velocities' enclosures, then the true (a, b, c, d)
    and x_s, s named as the candidate's fixed point (the sign of its common factor L1·L3/h,
    ``s`` given so); 0 when the intervals do not decide."""
    for bits in (60, 200):
        width = Fraction(1, 2 ** bits)
        end = _balls(cand, p, k, cand.word, width)
        if end is None:
            continue
        (d, c), _, (b, a) = end[-1]
        A = _isub(a, d)
        dl, dh = _iadd(_imul(A, A), _imul((4, 4), _imul(b, c)))
        if dh < 0:
            return None
        if dl <= 0 or c[0] <= 0 <= c[1]:
            return 0                      # Δ or c may vanish: the exact route decides
        from .values import _root_above, _root_below
        root = (_root_below(dl, bits), _root_above(dh, bits))
        x = _idiv(_iadd(A, root if s > 0 else (-root[1], -root[0])), _imul((2, 2), c))
        if req.kind[0] == "x":
            g = x
        elif req.kind[0] == "p":
            at = _balls(cand, p, k, req.kind[1], width)
            if at is None:
                continue
            G0, G1 = at[req.kind[2]][req.kind[3]]
            g = _iadd(G0, _imul(x, G1))
        else:
            cx_d = _iadd(_imul(c, x), d)
            g = _iadd(_imul(cx_d, cx_d), _imul((req.kind[1],) * 2, _isub(_imul(a, d), _imul(b, c))))
        if g[0] > 0 or g[1] < 0:
            return 1 if g[0] > 0 else -1
    return 0


def _balls(cand, p: Point, k: int, word: str, width: Fraction):
    """The positions (P0, P1), p = P0 + x P1, after each collision of word from p(0) = (1, 0, x)
    at (r₀, λ_k) in rational intervals (the velocities q̃ enclosed, :func:`_box`); None where a
    q̃_i's enclosure holds 0."""
    memo = p.__dict__.setdefault("_balls", {})
    key = (id(cand), k, word, width)
    if key not in memo:
        lam = _lambda_interval(p, cand.cp_dict, k, width)
        one, zero = (Fraction(1), Fraction(1)), (Fraction(0), Fraction(0))
        P = [(one, zero), (zero, zero), (zero, one)]
        out, run = [P], cand.run_of(word)
        for k_, letter in enumerate(word):
            if lam is None:
                break
            q, i = [_box(P_, p.r0, lam, width) for P_ in run.q[k_]], GAP[letter]
            if q[i][0] <= 0 <= q[i][1]:
                lam = None
                break
            t = [_idiv(P[i][h], q[i]) for h in (0, 1)]
            P = [tuple(_isub(P[j][h], _imul(t[h], q[j])) for h in (0, 1)) for j in range(3)]
            P[i] = (zero, zero)
            out.append(P)
        memo[key] = out if lam is not None else None
    return memo[key]


def _narrow(r0, width: Fraction) -> None:
    """r₀'s isolating interval halved by the sign of its (square-free) polynomial at the middle
    until narrower than width (a simple root: the signs at the ends differ)."""
    from .poly import value
    while not r0.rational and r0.hi - r0.lo > width:
        mid, s_lo = (r0.lo + r0.hi) / 2, value(r0.p, r0.lo)
        s_mid = value(r0.p, mid)
        if s_mid == 0:
            r0.lo = r0.hi = mid
        elif (s_mid > 0) == (s_lo > 0):
            r0.lo = mid
        else:
            r0.hi = mid


def _box(P: list, r0, lam: tuple, width: Fraction) -> tuple:
    """An enclosure of P(r₀, λ) (P dense in r, Λ) for r₀ in its interval narrowed to width²."""
    _narrow(r0, width ** 2)
    out = (Fraction(0), Fraction(0))
    for c in reversed(P):
        out = _iadd(_imul(out, lam), _ipoly(dict(enumerate(c)), r0.lo, r0.hi))
    return out


def _isub(a: tuple, b: tuple) -> tuple:
    return a[0] - b[1], a[1] - b[0]


def _idiv(a: tuple, b: tuple) -> tuple:
    return _imul(a, (1 / b[1], 1 / b[0]))


class _Reduced:
    """The division-free run at an algebraic point r₀, in integers: with m the integer
    polynomial of r₀ (leading coefficient L > 0, degree d) and n = deg cp, y = L·r and M = L^t·Λ
    make m̃(y) = L^(d-1)·m(y/L) and cp̃(y, M) = L^(nt)·cp(y/L, M/L^t) monic in y and M with
    integer coefficients (t(n - j) ≥ deg_r of the coefficient of Λ^j); a polynomial P(r, Λ)
    becomes L^E·P(y/L, M/L^t), E ≥ tj + deg p_j, a positive multiple, and is reduced modulo m̃
    and cp̃ (the same value at y₀ = L·r₀, M = L^t·λ).  The velocities of a step share one E, so
    that q̃_i p̃ - p̃_i q̃ is a positive multiple of the run's; :meth:`free`: its positions."""

    def __init__(self, cand, p: Point):
        from math import ceil
        m = [int(a) for a in integer_primitive(p.r0.p)]
        m = m if m[-1] > 0 else [-a for a in m]
        L, d, n = m[-1], len(m) - 1, len(cand.cp) - 1
        self.m, self.L = [a * L ** (d - 1 - i) for i, a in enumerate(m[:-1])] + [1], L
        self.t = max([ceil((len(c) - 1) / (n - j)) for j, c in enumerate(cand.cp[:-1]) if c] + [0])
        self.cp = [[]] * (n + 1)                                  # placeholder for reduce()
        self.cp = self.scaled(cand.cp, n * self.t)
        self.cp_dict, self.cand, self.runs = _dict(self.cp), cand, {}
        r0 = p.r0
        self.point = Point(Algebraic([Fraction(a) for a in self.m], L * r0.lo, L * r0.hi, check=False)
                           if not r0.rational else number(L * r0.lo), False)
        self.minus_det = self.scaled([[-a for a in c] for c in cand.det])
        F = self.free(cand.word)[-1]
        self.abcd = [F[2][1], F[2][0], F[0][1], F[0][0]] if len(F) == 3 else None

    def scaled(self, P: list, E: int | None = None) -> list:
        """L^E·P(y/L, M/L^t), reduced (E the least that makes it integral when None)."""
        t, L = self.t, self.L
        if E is None:
            E = max((t * j + len(c) - 1 for j, c in enumerate(P) if c), default=0)
        return self.reduce([[a * L ** (E - t * j - i) for i, a in enumerate(c)] for j, c in enumerate(P)])

    def reduce(self, P: list) -> list:
        """Modulo cp̃ (monic in M) and m̃ (monic in y): integers stay integers."""
        P = _brem(P, self.cp) if len(P) >= len(self.cp) and self.cp[-1] else P
        d = len(self.m) - 1
        out = []
        for c in P:
            c = list(c)
            for k in range(len(c) - 1, d - 1, -1):
                top = c[k]
                if top:
                    for i in range(d):
                        c[k - d + i] -= top * self.m[i]
                c[k] = 0
            out.append(_trim(c))
        return _trim(out)

    def free(self, word: str) -> list:
        """p̃(t_k) = q̃_i p̃(t_{k-1}) - p̃_i q̃(t_{k-1}) (pairs (F0, F1), p̃ = F0 + x F1): p̃(t_k) =
        s_k·p(t_k), s_k a positive multiple of Π q̃_i, of sign (-sign det)^k where the velocity
        requirements hold."""
        if word not in self.runs:
            run = self.cand.run_of(word)
            g = len(run.q[0])
            F = [([[1]], []), ([], [])] + ([([], [[1]])] if g == 3 else [])
            out = [F]
            for k, letter in enumerate(word):
                E = max(self.t * j + len(c) - 1 for P in run.q[k] for j, c in enumerate(P) if c)
                i, q = GAP[letter], [self.scaled(P, E) for P in run.q[k]]
                F = [tuple(self.reduce(_badd(_bmul(q[i], F[j][h]), _bmul(F[i][h], q[j]), -1)) for h in (0, 1))
                     for j in range(g)]
                F[i] = ([], [])
                out.append(F)
            self.runs[word] = out
        return self.runs[word]


def _reduced(cand, p: Point) -> _Reduced:
    cache = p.__dict__.setdefault("_reduced", {})
    if id(cand) not in cache:
        cache[id(cand)] = _Reduced(cand, p)
    return cache[id(cand)]


def holds(p: Point, req: Req, cand, k: int, s) -> bool | None:
    """req on branch k with the fixed point x_s at the piece p: True, False or None (undecided).
    At a point: by enclosures, else exactly; where the candidate's forms degenerate (a
    denominator δ(r₀) = 0, or the common factor of (a, b, c, d)), on the division-free run
    (:class:`_Reduced`; its sign factor is known where the velocity requirements, imposed
    before, hold; x named as the candidate's, :meth:`Candidate.relabel`); where c = 0, the
    affine f's fixed point b/(d - a)."""
    cond = req.cond(cand, s)
    if p.cell:
        g = _sign(p, cond, k)
    else:
        valid = (len(req.D) > 1 or p.r0.sign_of(req.D[0]) != 0) and (not req.G1 or p.r0.sign_of(cand.scale[0]) != 0)
        g = _enclosed(p, cond, k) if valid else 0
        if g != 0:
            pass
        elif valid and req.G1 and _sign(p, _Cond(cand, {"N0": cand.abcd[2], "D0": [[1]]}, []), k) == 0:
            g = _affine(p, cand, k, cand.abcd, lambda: req.cond(cand, s, affine=True), req.G0, req.G1, req.D)
        elif valid or req.free is None:
            g = _sign(p, cond, k)
        else:
            g = _ball_sign(p, req, cand, k, s * (p.r0.sign_of(cand.scale[0]) or 1)) if req.kind else 0
            g = Undecided if g == 0 else g
    if g is Undecided and req.free is not None and not p.cell:
        R = _reduced(cand, p)
        G0, G1, D = req.free(R)
        if not G1:
            g = _sign(R.point, _condition(R, G0, G1, D, s, None, False), k)
        else:
            e, abcd = cand.relabel(p, k), R.abcd
            if e is None:
                return None
            if _sign(R.point, _Cond(R, {"N0": abcd[2], "D0": [[1]]}, []), k) == 0:
                g = _affine(R.point, R, k, abcd, lambda: _condition(R, G0, G1, D, s, abcd, True), G0, G1, D)
            else:
                g = _sign(R.point, _condition(R, G0, G1, D, e * s, abcd, False), k)
    if g is Undecided:
        return None
    return g is not None and g == req.sign


def _affine(p: Point, cand, k: int, abcd: list, cond, G0, G1, D):
    """Where c = 0, f(x) = (ax + b)/d: its fixed point b/(d - a) (``cond``: the condition there);
    none when d = a and b ≠ 0 (a translation: None, as an x that is not real); f the identity
    (every x fixed): the requirement's value where it does not depend on x (G1 = 0), else
    Undecided."""
    a, b, _, d = abcd
    one = [[1]]
    if _sign(p, _Cond(cand, {"N0": _badd(d, a, -1), "D0": one}, []), k) != 0:
        return _sign(p, cond(), k)
    if _sign(p, _Cond(cand, {"N0": b, "D0": one}, []), k):
        return None
    if _sign(p, _Cond(cand, {"N0": G1, "D0": one}, []), k) == 0:
        return _sign(p, _Cond(cand, {"N0": G0, "D0": D}, []), k)
    return Undecided


def _conjunction(p: Point, cand, stage: tuple, k: int, s) -> bool | None:
    """All the requirements of the stage at p (False as soon as one fails, None when one is
    undecided and none fails)."""
    out = True
    for req in requirements(cand, *stage):
        v = holds(p, req, cand, k, s) if req.name != "u" else _u(p, req, cand, stage, k, s)
        if isinstance(v, tuple):
            return v[1]
        if v is False:
            return False
        if v is None:
            out = None
    return out


def _u(p: Point, req: Req, cand, stage: tuple, k: int, s):
    """u > 0, and where the rows' determinant vanishes on the branch (a point): if U or V does
    not, the eigenvector has q_1 = 0 (no datum with q_1(0) = -1); else the other rows decide
    every requirement there ("other": the answer for the whole conjunction)."""
    v = holds(p, req, cand, k, s)
    if v is not None or p.cell or _sign(p, _Cond(cand, {"N0": cand.det, "D0": [[1]]}, []), k) != 0:
        return v
    if any(_sign(p, _Cond(cand, {"N0": P, "D0": [[1]]}, []), k) != 0 for P in cand.q0[1:]):
        return False
    for rows in (((0, 2), (1, 2)) if len(cand.q0) == 3 else ((1,),)):
        if rows == cand.rows:
            continue
        other = candidate(cand.text, rows)
        if _sign(p, _Cond(other, {"N0": other.det, "D0": [[1]]}, []), k) not in (0, Undecided):
            return ("other", _conjunction(p, other, stage, k, s))
    return None


# ----------------------------------------------------------------- regions: where the requirements hold
class Region:
    """For one branch k (0: the largest real eigenvalue) and fixed point s (±1, or None for two
    gaps): the pieces of ]0, 1[ where every requirement imposed so far holds — open intervals
    (lo, hi) and points (a, a) — and the pieces left undecided."""

    def __init__(self, k: int, s, pieces=None, undecided=None, final=None):
        self.k, self.s = k, s
        self.pieces, self.undecided, self.final = pieces or [], undecided or [], final or set()


def analyse(cand, stage: tuple, regions: list | None = None, reqs: list | None = None) -> list:
    """The regions (one per real branch k, 0 the largest, and fixed point x_s) after imposing the
    requirements of the stage (:func:`requirements`, or ``reqs``) one at a time over ]0, 1[ (or
    on copies of ``regions``), each only where the previous ones hold."""
    zero, one = number(0), number(1)
    points: dict = cand.__dict__.setdefault("points", {})
    sigmas = (1, -1) if len(cand.q0) == 3 else (None,)
    if regions is None:
        ends = [zero] + [a for a, _ in _cuts(cand.disc_cond(), zero, one)] + [one]
        found: dict = {}
        for a, b in zip(ends, ends[1:]):
            for piece in [(a, b)] + ([(b, b)] if b is not one else []):
                for k in range(_point(piece, points).branches(cand.cp_dict)):
                    for s in sigmas:
                        found.setdefault((k, s), Region(k, s)).pieces.append(piece)
        regions = list(found.values())
    else:
        regions = [Region(R.k, R.s, list(R.pieces), list(R.undecided), set(R.final)) for R in regions]
    for req in requirements(cand, *stage) if reqs is None else reqs:
        live = [pc for R in regions for pc in R.pieces + R.undecided]
        if not live:
            break
        lo = min((pc[0] for pc in live), key=_OrderKey)
        hi = max((pc[1] for pc in live), key=_OrderKey)
        cond = req.cond(cand, sigmas[0])
        cuts = _cuts(cond, lo, hi) if lo.compare(hi) < 0 else []
        at = _Reader(req, cand, stage, cond, lo, hi, cuts, points)
        split: dict = {}
        for R in regions:
            kept, unsure = [], []
            for piece, was in [(pc, True) for pc in R.pieces] + [(pc, None) for pc in R.undecided]:
                if id(piece) not in split:
                    split[id(piece)] = _split(piece, [c for c, _ in cuts])
                for sub in split[id(piece)]:
                    v = True if sub[0] is sub[1] and id(sub[0]) in R.final else at.holds(sub, R.k, R.s)
                    if isinstance(v, tuple):
                        v = v[1]
                        if v:
                            R.final.add(id(sub[0]))
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

    def __init__(self, req, cand, stage, cond, lo, hi, cuts, points):
        self.req, self.cand, self.stage, self.cond, self.points = req, cand, stage, cond, points
        self.ends = [lo] + [c for c, _ in cuts] + [hi]
        self.cuts = cuts

    def holds(self, piece: tuple, k: int, s):
        a, b = piece
        if a is not b:
            return self.exact(_point(piece, self.points), k, s)
        i = self._where(a)
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
        return _u(p, self.req, self.cand, self.stage, k, s) if self.req.name == "u" else \
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


_CANDIDATES: dict = {}


def candidate(text: str, rows: tuple = (0, 1)) -> Candidate:
    key = (text, rows)
    if key not in _CANDIDATES:
        _CANDIDATES[key] = Candidate(text, rows)
    return _CANDIDATES[key]


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
            from .evaluate import NotVerified
            raise NotVerified(f"{text} has {n} collisions: beyond the kernel's budget of {LONGEST}")
        cand = candidate(text)
        known = _SETS.get((text, ("feasible", None)))
        if stage[0] == "stable" and known is not None:
            extra = _dominance(cand) + (_attracting(cand) if len(cand.q0) == 3 else [])
            _SETS[key] = analyse(cand, stage, known, extra)
        else:
            _SETS[key] = analyse(cand, stage)
    degree = len(candidate(text).cp) - 1
    return [R for R in _SETS[key] if branches is None or (R.k == degree - 1 if branches == "lower" else R.k in branches)]


LONGEST = 12               # words of more collisions are not analysed (the kernel's time budget: docs/statements.md)


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
        return _exists(p, _regions(ctx, *args_of(ctx, args)))
    return conditions, truth


def _letters(text: str) -> str:
    from .evaluate import expand_word
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
    """q(0) = (-1, u, v) (three particles, symmetric system: (-1, u)): rows 1 and 2 of
    (M_w - λ) q = 0 by Cramer's rule, the kernel's M_w (l. 366), as rational functions of r, λ."""
    text = _text(w)
    system, word = read_word(text)
    lam = RF.var("λ")
    if system == "four":
        from .evaluate import word_matrix
        M = word_matrix(word)
        A = [[M.rows[i][j] - (lam if i == j else RF.const(0)) for j in range(3)] for i in range(3)]
        det = A[0][1] * A[1][2] - A[0][2] * A[1][1]
        return (RF.const(-1), (A[0][0] * A[1][2] - A[0][2] * A[1][0]) / det,
                (A[0][1] * A[1][0] - A[0][0] * A[1][1]) / det)
    K = _matrices(system)
    M = None
    for letter in word:
        Kl = [[RF({(i,) + (0,) * (len(_vars()) - 1): Fraction(a, 2) for i, a in enumerate(e)}) for e in row]
              for row in K[letter]]
        M = Kl if M is None else [[Kl[i][0] * M[0][j] + Kl[i][1] * M[1][j] for j in range(2)] for i in range(2)]
    return (RF.const(-1), (M[0][0] - lam) / M[0][1])


def _vars():
    from .values import VARS
    return VARS


def register() -> None:
    """The atoms and functions of the statement language this module adds (docs/statements.md)."""
    from .evaluate import ATOMS, FUNCTIONS
    for name in ("datum", "feasible", "stable", "realises"):
        ATOMS[name] = _stage_atom(name)
    ATOMS["next"] = (_next_conditions, _next_truth)
    FUNCTIONS["eigenvector"] = eigenvector
    FUNCTIONS["posmap"] = posmap


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
    from .values import VARS
    k = len(VARS)
    num = {(i, j) + (0,) * (k - 2): Fraction(a * 2 ** (n * j)) for j, c in enumerate(e.c) for i, a in enumerate(c) if a}
    den = {(i,) + (0,) * (k - 1): Fraction(a) for i, a in enumerate(e.d) if a}
    return RF(num, den)
