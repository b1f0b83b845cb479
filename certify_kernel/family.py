"""The family (ab)^n(cb)^n for every n: the kernel's own route (CDKK's point, l. 1215).

The predicate ``q2_sign_family("(ab)^n(cb)^n", n ≥ N, r in ]0, R], n·θ = cπ)`` of the statement
language (docs/statements.md) says: for every integer n ≥ N and every r in ]0, R],

* the characteristic polynomial of M_n = word("(ab)^n(cb)^n") has a real, simple, positive root λ
  that strictly dominates the other two in modulus (the *dominant branch*), and
* on it q_2(0) = eigenvector(w_n)[2] has the sign of sin(nθ), cos θ = tr K/(2r) (θ = 0 at and below
  r* = 7 − 4√3, where q_2(0) > 0): q_2(0) > 0 below r_n, = 0 at r_n and < 0 just above, r_n the r
  where nθ = cπ (cos θ = cos(π/n): r_n is the root in ]0, 1[ of r² − (6 + 8cos(π/n))r + 1);

it is true exactly when c = 1 (the first zero of sin(nθ) above r*), and the kernel proves it for
every n ≥ N at once.  Everything is built here from the kernel's collision matrices
(:func:`certify_kernel.evaluate.word_matrix`); nothing is read from the engine.  The proof
(docs/family-limit.md, parts 1, 2, 7, 8 and 10, numbered 1-6 here; the engine's
certify/patterns/family_limit.py is not imported, its facts not read):

1. *The block* (:func:`block`, exact polynomials in r).  M_ab = [[K, 0], [wᵀ, 1]] on (q₁, q₂ | q₃),
   M_cb = J M_ab J (J: q₁ ↔ q₃), det K = r², tr K = t = (r² − 6r + 1)/4, K² = tK − r²I (Cayley–Hamilton),
   wᵀ = (1/3, 2/3)(I − K), det(I − K) = 3(r + 1)²/4 ≠ 0, det M_ab = r².  Hence M_ab^n = [[P, 0], [Wᵀ, 1]]
   with P = K^n, Wᵀ = wᵀ(I + … + K^{n−1}) = (1/3, 2/3)(I − P), and M_n = (J M_ab^n J) M_ab^n = N²,
   N = J M_ab^n = [[W₁, W₂, 1], [c, d, 0], [a, b, 0]] ((a, b), (c, d) = P), det M_n = r^{4n}.
   By induction K^j = s_j K − r² s_{j−1} I, s₀ = 0, s₁ = 1, s_{j+1} = t s_j − r² s_{j−1}.
2. *The identity of q_2(0)* (:func:`check_q2_identity`, exact in Q[a, b, c, d, W₁, W₂, λ, u, v]).
   With q(0) = (−1, u, v) and q₃(t_{2n}) = v − W₁ + W₂u (the third entry of M_ab^n q(0)),
   (M_n q(0) − λ q(0))₂ = −[u(λ − d²) − c(q₃(t_{2n}) − d)]: on every eigenvector,
   u(λ − d²) = c(q₃(t_{2n}) − d), c = P₂₁ = −rh s_n (h = (1 + r)/2, from K^n = s_n K − r² s_{n−1} I).
3. *s_n* (:func:`theta_facts`).  The eigenvalues κ₁, κ₂ of K have κ₁κ₂ = r², κ₁ + κ₂ = t and
   s_j = Σ_{i<j} κ₁^i κ₂^{j−1−i}.  Where t² ≥ 4r² (r ≤ r*) they are real of the sign of t > 0, so
   s_n > 0.  Above r*, κ = r e^{±iθ}, cos θ = t/(2r) ∈ ]−1, 1[, and s_j = r^{j−1} sin jθ / sin θ (it
   satisfies the recursion: sin(j+1)θ + sin(j−1)θ = 2 cos θ sin jθ); 1 − cos θ = (14 − r − 1/r)/8
   increases with r, and cos θ < 0 at r = R ≥ 3 − 2√2: so nθ runs over ]0, nθ(R)] ⊃ ]0, π] and s_n
   has the sign of sin nθ: > 0 for nθ < π, 0 at nθ = π, < 0 just above (and nothing else is its
   first zero above r*).
4. *Dominance* (:func:`dominant`, one interval computation over all of ]0, R], R ≤ 1/4, for every
   n ≥ N).  The spectral radius of K is ≤ ρ̄ = 1/4 (complex: |κ| = r; real: |κ| ≤ |t| ≤ 1/4), so
   |s_j| ≤ j ρ̄^{j−1} and |P_ij| ≤ n ρ̄^{n−1}(|K_ij| + r) ≤ δ = N ρ̄^{N−1} max(1, |K_ij| + r) (n ρ̄^{n−1}
   decreases from n = N when (N + 1)ρ̄ ≤ N).  So W = (1/3, 2/3) + O(δ), M_n = N² = [[1/9, 2/9, 1/3],
   0, 0] + O(δ) in intervals, det M_n ∈ [0, ρ̄^{4N}]: the characteristic polynomial changes sign on
   [1/9 − ω, 1/9 + ω] (ω = 16δ), so it has a real root λ there; the other two, roots of
   x² − (tr M − λ)x + det M/λ, have modulus ≤ |S|/2 + √(S²/4 + |Π|) < λ: λ is real, simple, strictly
   dominant.  Its eigenvector (−1, u, v) (rows 2 and 3, Cramer, D > 0) has q₃(t_{2n}) − d < 0 < λ − d²,
   so by 2, u = −rh s_n (q₃(t_{2n}) − d)/(λ − d²) has the sign of s_n.
5. *Above nθ = 2π* (:func:`arcs`, family_limit's part 10): a b of (ab)^n separates.
6. *Below r_n* (:func:`velocities`, family_limit's part 8): every pair approaches.

Two more predicates use them: ``family_unstable("(ab)^n(cb)^n", n ≥ N, r in ]0, R], n·θ > cπ)``
(nothing stable there: parts 1-5) and ``family_approaching("(ab)^n(cb)^n", n ≥ N, n·θ < cπ)``
(every pair approaches above r*: parts 1-4, 6).  The kernel reads no witness for any of them.
"""
from __future__ import annotations

from fractions import Fraction

from .evaluate import PREDICATES, NotVerified, collision, interval, word_matrix
from .intervals import Iv, sqrt
from .poly import add, madd, mmul, mul, scale, sub
from .poly import value as at
from .sturm import count
from .values import Undefined, univariate

WORD = "(ab)^n(cb)^n"
RHO = Fraction(1, 4)           # the bound of K's spectral radius on ]0, 1/4]
R_MAX = Fraction(1, 4)         # the range of r the route covers: ]0, R], R ≤ 1/4
WIDTH = 16                     # the interval of λ: 1/9 ± WIDTH·δ
RSTAR_ABOVE = Fraction(72, 1000)   # above r* = 7 − 4√3 ≈ 0.07180 (checked: r² − 14r + 1 < 0 there)

R, ONE = [Fraction(0), Fraction(1)], [Fraction(1)]
H = [Fraction(1, 2), Fraction(1, 2)]                                 # h = (1 + r)/2
T = [Fraction(1, 4), Fraction(-3, 2), Fraction(1, 4)]                # t = (r² − 6r + 1)/4


def _rows(M) -> list:
    """The kernel's matrix of rational functions in r as lists of polynomials in r."""
    return [[univariate(e) for e in row] for row in M.rows]


def _det2(M: list) -> list:
    return sub(mul(M[0][0], M[1][1]), mul(M[0][1], M[1][0]))


def block() -> tuple[list, list]:
    """(K, w) from the kernel's own M_ab = word_matrix('ab') and M_cb = word_matrix('cb'), after
    checking exactly (polynomials over Q in r): M_ab = [[K, 0], [wᵀ, 1]] on (q₁, q₂ | q₃);
    M_cb = J M_ab J (J the reflection q₁ ↔ q₃); det K = r²; tr K = (r² − 6r + 1)/4; K² = tK − r²I;
    wᵀ = (1/3, 2/3)(I − K); det(I − K) = 3(r + 1)²/4; det M_ab = r².  ArithmeticError otherwise."""
    ab, cb = _rows(word_matrix("ab")), _rows(word_matrix("cb"))
    K, w = [ab[0][:2], ab[1][:2]], ab[2][:2]
    r2 = mul(R, R)
    KK = [[add(mul(K[i][0], K[0][j]), mul(K[i][1], K[1][j])) for j in range(2)] for i in range(2)]
    third = [Fraction(1, 3), Fraction(2, 3)]
    I_K = [[sub(ONE if i == j else [], K[i][j]) for j in range(2)] for i in range(2)]
    det_ab = sub(mul(ab[2][2], _det2(K)), [])                      # last column (0, 0, 1)
    checks = {
        "M_ab = [[K, 0], [wᵀ, 1]]": ab[0][2] == [] and ab[1][2] == [] and ab[2][2] == ONE,
        "M_cb = J M_ab J": all(cb[i][j] == ab[2 - i][2 - j] for i in range(3) for j in range(3)),
        "det K = r²": _det2(K) == r2,
        "tr K = t": add(K[0][0], K[1][1]) == T,
        "K² = tK − r²I": all(KK[i][j] == sub(mul(T, K[i][j]), r2 if i == j else []) for i in range(2)
                             for j in range(2)),
        "wᵀ = (1/3, 2/3)(I − K)": all(w[j] == add(scale(I_K[0][j], third[0]), scale(I_K[1][j], third[1]))
                                      for j in range(2)),
        "det(I − K) = 3(r + 1)²/4": _det2(I_K) == [Fraction(3, 4), Fraction(3, 2), Fraction(3, 4)],
        "det M_ab = r²": det_ab == r2,
        "K₂₁ = −rh": K[1][0] == scale(mul(R, H), -1),
        "K₁₂ = h": K[0][1] == H,
    }
    bad = [k for k, ok in checks.items() if not ok]
    if bad:
        raise ArithmeticError("the block of (ab)^n(cb)^n: " + "; ".join(bad))
    return K, w


# ------------------------------------------------------------- 2. q_2(0): an identity in 9 variables
_NAMES = ("a", "b", "c", "d", "W1", "W2", "λ", "u", "v")


def _var(name: str) -> dict:
    k = _NAMES.index(name)
    return {tuple(1 if i == k else 0 for i in range(len(_NAMES))): Fraction(1)}


def _const(c) -> dict:
    return {(0,) * len(_NAMES): Fraction(c)} if c else {}


def _n_rows(a, b, c, d, W1, W2) -> list:
    """N = J M_ab^n = J [[a, b, 0], [c, d, 0], [W₁, W₂, 1]] (J reverses the rows)."""
    one, zero = _const(1), {}
    return [[W1, W2, one], [c, d, zero], [a, b, zero]]


def check_q2_identity() -> bool:
    """Exact, in Q[a, b, c, d, W₁, W₂, λ, u, v]: with N = [[W₁, W₂, 1], [c, d, 0], [a, b, 0]] (J M_ab^n,
    part 1), q(0) = (−1, u, v) and q₃ = v − W₁ + W₂u, the second entry of N²q(0) − λq(0) plus
    u(λ − d²) − c(q₃ − d) is the zero polynomial.  True when it is."""
    a, b, c, d, W1, W2, lam, u, v = (_var(x) for x in _NAMES)
    N = _n_rows(a, b, c, d, W1, W2)
    q0 = [_const(-1), u, v]
    Nq = [madd(madd(mmul(row[0], q0[0]), mmul(row[1], q0[1])), mmul(row[2], q0[2])) for row in N]
    NNq2 = madd(madd(mmul(N[1][0], Nq[0]), mmul(N[1][1], Nq[1])), mmul(N[1][2], Nq[2]))
    e2 = madd(NNq2, mmul(lam, u), -1)
    q3 = madd(madd(v, W1, -1), mmul(W2, u))
    claim = madd(mmul(u, madd(lam, mmul(d, d), -1)), mmul(c, madd(q3, d, -1)), -1)
    return not madd(e2, claim)


def check_u_factor() -> bool:
    """Exact, in the same ring: the numerator of u by Cramer on rows 2 and 3 of (N² − λ)q = 0,
    −(N²)₂₁(λ − (N²)₃₃) − (N²)₂₃(N²)₃₁, is c·X with X = −(d + W₁)(λ − (N²)₃₃) − (bc + aW₁): so
    u = cX/D, |u| ≤ C_u|c| with C_u a bound of |X|/D (part 4 returns it)."""
    a, b, c, d, W1, W2, lam, u, v = (_var(x) for x in _NAMES)
    N = _n_rows(a, b, c, d, W1, W2)
    M = [[madd(madd(mmul(N[i][0], N[0][j]), mmul(N[i][1], N[1][j])), mmul(N[i][2], N[2][j])) for j in range(3)]
         for i in range(3)]
    lam_33 = madd(lam, M[2][2], -1)
    num = madd(mmul(mmul(_const(-1), M[1][0]), lam_33), mmul(M[1][2], M[2][0]), -1)
    X = madd(mmul(mmul(_const(-1), madd(d, W1)), lam_33), madd(mmul(b, c), mmul(a, W1)), -1)
    return not madd(num, mmul(c, X), -1)


def check_period_matrix(n: int) -> bool:
    """Exact, for one n: N² with N = J M_ab^n is the kernel's word_matrix((ab)^n(cb)^n) (a check of
    part 1's algebra on the kernel's own matrices; part 1 proves it for every n)."""
    Mab = word_matrix("ab" * n)
    N = [[Mab.rows[2 - i][j] for j in range(3)] for i in range(3)]
    M = word_matrix("ab" * n + "cb" * n).rows
    for i in range(3):
        for j in range(3):
            s = N[i][0] * N[0][j] + N[i][1] * N[1][j] + N[i][2] * N[2][j]
            if not (s - M[i][j]).is_zero():
                return False
    return True


# ------------------------------------------------------------- 3. s_n and θ
def _positive_on(p: list, lo: Fraction, hi: Fraction) -> bool:
    """p > 0 on [lo, hi]: positive at lo and no root in ]lo, hi] (Sturm)."""
    return at(p, lo) > 0 and count(p, lo, hi) == 0


def theta_facts(r_max: Fraction) -> None:
    """The exact facts of part 3 on ]0, R], R = r_max ≤ 1/4 (ArithmeticError when one fails):
    1/4 − t = r(6 − r)/4 ≥ 0 and t + 1/4 > 0 (so |t| ≤ 1/4); where t² ≥ 4r², t > 0 (t² − 4r² =
    (r² − 14r + 1)(r + 1)²/16 ≥ 0 on ]0, R] only below its one root r* < 72/1000, and t > 0 on
    [0, 72/1000]); t + 2r = (r + 1)²/4 > 0 and
    2r − t ≥ 0 where t² < 4r² (cos θ = t/(2r) ∈ ]−1, 1[); 8r(1 − t/(2r)) = −r² + 14r − 1, so
    d/dr (1 − cos θ) = (1/r² − 1)/8 > 0 (θ increases with r); 3 − 2√2 ≤ R ((3 − R)² ≤ 8: every r_n ≤ r_2
    lies in ]0, R]) and cos θ(R) < 0, i.e. t(R) < 0 (so nθ(R) > π for n ≥ 2)."""
    lo = Fraction(0)
    r2 = mul(R, R)
    t2_4r2 = sub(mul(T, T), scale(r2, 4))
    root = [Fraction(1), Fraction(-14), Fraction(1)]              # r² − 14r + 1
    facts = {
        "R ≤ 1/4": 0 < r_max <= R_MAX,
        "1/4 − t ≥ 0 on [0, R]": sub([Fraction(1, 4)], T) == scale(mul(R, [Fraction(6), Fraction(-1)]), Fraction(1, 4))
        and 0 < r_max < 6,
        "t + 1/4 > 0 on [0, R]": _positive_on(add(T, [Fraction(1, 4)]), lo, r_max),
        "t² − 4r² = (r² − 14r + 1)(r + 1)²/16": t2_4r2 == scale(mul(root, mul([1, 1], [1, 1])), Fraction(1, 16)),
        "t > 0 where t² ≥ 4r²": count(root, lo, r_max) == 1 and at(root, RSTAR_ABOVE) < 0
        and _positive_on(T, lo, RSTAR_ABOVE),
        "t + 2r = (r + 1)²/4": add(T, scale(R, 2)) == scale(mul([1, 1], [1, 1]), Fraction(1, 4)),
        "2r − t = −(r² − 14r + 1)/4": sub(scale(R, 2), T) == scale(root, Fraction(-1, 4)),
        "3 − 2√2 ≤ R": (3 - r_max) ** 2 <= 8,
        "t(R) < 0": at(T, r_max) < 0,
    }
    bad = [k for k, ok in facts.items() if not ok]
    if bad:
        raise ArithmeticError("part 3: " + "; ".join(bad))


# ------------------------------------------------------------- 4. dominance, in intervals
def dominant(K: list, N1: int, r_max: Fraction) -> dict:
    """Part 4 for every n ≥ N1 and r ∈ ]0, R] (R = r_max ≤ 1/4), in intervals: returns the bounds
    (δ, the interval of λ, the bound of the other two eigenvalues, u, q₃ − d, λ − d²).
    NotVerified when an inequality is not proved."""
    r = Iv(0, r_max)
    if not (N1 + 1) * RHO <= N1:
        raise NotVerified(f"n ρ̄^(n−1) is not shown to decrease from n = {N1}")
    kmax = max((at(K[i][j], r).abs() + r).hi for i in range(2) for j in range(2))
    delta = N1 * RHO ** (N1 - 1) * max(Fraction(1), kmax)
    small = Iv(-delta, delta)
    return _dominance(small, small, small, small, Iv(0, RHO ** (4 * N1)), delta, f"n ≥ {N1}")


def dominant_at(K: list, n: int, r_max: Fraction, boxes: int = 32) -> dict:
    """Part 4 for the one n and r ∈ ]0, R], in intervals over `boxes` equal boxes of [0, R]: P = K^n
    computed exactly (polynomials in r), its entries enclosed on each box, δ their largest modulus
    there, det M = r^{4n} on the box; :func:`_dominance` on each, the bounds combined (the worst).
    NotVerified when an inequality is not proved on some box."""
    P = [[ONE, []], [[], ONE]]
    for _ in range(n):
        P = [[add(mul(P[i][0], K[0][j]), mul(P[i][1], K[1][j])) for j in range(2)] for i in range(2)]
    out: dict = {}
    for k in range(boxes):
        r = Iv(r_max * k / boxes, r_max * (k + 1) / boxes)
        a, b, c, d = (at(P[i][j], r) for i in range(2) for j in range(2))
        delta = max(x.mag() for x in (a, b, c, d))
        f = _dominance(a, b, c, d, r ** (4 * n), delta, f"n = {n}, r ∈ [{r.lo}, {r.hi}]")
        if not out:
            out = f
            continue
        worst = {"delta": max, "others": max, "u": max, "q3_minus_d": max, "Cu": max,
                 "lambda_minus_d2": min, "q3_abs": min}
        out = {**{k2: g(out[k2], f[k2]) for k2, g in worst.items()},
               "lambda": (min(out["lambda"][0], f["lambda"][0]), max(out["lambda"][1], f["lambda"][1]))}
    return out


def _dominance(a: Iv, b: Iv, c: Iv, d: Iv, det: Iv, delta: Fraction, where: str) -> dict:
    """The interval steps of part 4 from enclosures of P's entries (|P_ij| ≤ δ) and of det M = r^{4n}:
    W = (1/3, 2/3)(I − P), M = N², cp changes sign on 1/9 ± WIDTH·δ (a real root λ there), the other two
    roots have modulus < λ, Cramer's D > 0, q₃(t_2n) − d < 0 < λ − d², C_u ≥ |X|/D.  NotVerified (naming
    `where`) when an inequality is not proved."""
    W1 = Fraction(1, 3) - a / 3 - 2 * c / 3                        # Wᵀ = (1/3, 2/3)(I − P)
    W2 = Fraction(2, 3) - b / 3 - 2 * d / 3
    N = [[W1, W2, Iv(1)], [c, d, Iv(0)], [a, b, Iv(0)]]
    M = [[N[i][0] * N[0][j] + N[i][1] * N[1][j] + N[i][2] * N[2][j] for j in range(3)] for i in range(3)]
    tr = M[0][0] + M[1][1] + M[2][2]
    e2 = sum((M[i][i] * M[j][j] - M[i][j] * M[j][i] for i, j in ((0, 1), (0, 2), (1, 2))), Iv(0))

    def cp(x):
        return x ** 3 - tr * x ** 2 + e2 * x - det
    omega = WIDTH * delta
    lo, hi = Fraction(1, 9) - omega, Fraction(1, 9) + omega
    if lo <= 0:
        raise NotVerified(f"the interval of λ reaches 0 ({where}: δ = {float(delta):.3g} is too large)")
    if not (cp(Iv(lo)).negative() and cp(Iv(hi)).positive()):
        raise NotVerified(f"the characteristic polynomial is not shown to change sign around 1/9 ({where})")
    lam = Iv(lo, hi)
    S, Pi = (tr - lam).mag(), (det / lam).mag()
    others = (S / 2 + sqrt(Iv(S * S / 4 + Pi))).hi
    if not others < lam.lo:
        raise NotVerified(f"strict dominance is not proved ({where})")
    D = (lam - M[1][1]) * (lam - M[2][2]) - M[1][2] * M[2][1]
    if not D.positive():
        raise NotVerified("Cramer's determinant of rows 2, 3 is not shown positive")
    u = (-M[1][0] * (lam - M[2][2]) - M[1][2] * M[2][0]) / D
    v = (-M[2][0] * (lam - M[1][1]) - M[2][1] * M[1][0]) / D
    q3 = v - W1 + W2 * u
    if not ((q3 - d).negative() and (lam - d * d).positive()):
        raise NotVerified("q₃(t_2n) − d < 0 < λ − d² is not proved")
    X = -(d + W1) * (lam - M[2][2]) - (b * c + a * W1)            # u = cX/D: M₂₁ = c(d + W₁), M₂₃ = c
    return {"delta": delta, "lambda": (lam.lo, lam.hi), "others": others, "u": u.mag(),
            "q3_minus_d": (q3 - d).hi, "lambda_minus_d2": (lam - d * d).lo, "Cu": (X.abs() / D).hi,
            "q3_abs": (-q3).lo if q3.negative() else Fraction(0)}


# ------------------------------------------------------------- 5. above nθ = 2π: a b separates
def arcs(K: list, N1: int, r_max: Fraction, Cu: Fraction) -> dict:
    """Part 5 for every n ≥ N1 and r ∈ ]r*, R] with nθ > 2π (R = r_max ≤ 1/4): some b of the ab-phase
    comes with its pair separating, so the word is not realised.  Exactly: (h, 1)K = (ht, K₁₁) and
    K₁₁ + r = h², K₁₁ = (1 − r)²/4 ≥ 0; so with y = K^{j−1}(−1, u) and K^j = s_j K − r² s_{j−1} I, q₂
    before the j-th b is (y₂ + hy₁ =) −h s_j + u(K₁₁ s_{j−1} − r² s_{j−2}) = (r^{j−2}/sin θ)[−rh sin jθ +
    u(K₁₁ sin(j−1)θ − r sin(j−2)θ)].  θ ≤ θ_max, cos θ_max = t(R)/(2R) > −1/2 (θ_max < 2π/3, so j₀, the
    largest j with jθ < 2π, is ≥ 3 and ≤ n − 1); j' = j₀ if j₀θ ≤ 2π − θ/2, else j₀ − 1: 2π − j'θ ∈
    [θ/2, 3θ/2] ⊂ ]0, π[, so sin j'θ ≤ −m, m = min(sin(θ/2), sin(3θ/2)) ≥ min(2/n, sin(3θ_max/2)) for
    θ ∈ [2π/n, θ_max] (sin x ≥ 2x/π on [0, π/2], sin concave on [0, π], 3π/n ≤ π/2), sin(3x) =
    sin x(1 + 2cos 2x).  |u| ≤ C_u|c|, |c| = rh|s_n| ≤ rh n ρ̄^{n−1} = rh δ_n (|sin nθ| ≤ n sin θ), and
    |K₁₁ sin(j−1)θ − r sin(j−2)θ| ≤ h²: at j = j' the bracket is ≥ rh(m − C_u h² δ_n) > 0 (q₂ > 0 before
    that b) when 2 > C_u h² n² ρ̄^{n−1} and sin(3θ_max/2) > C_u h² δ_n, both decreasing in n ((N + 1)² ρ̄ ≤
    N²): checked at N1 in intervals.  Returns the two margins."""
    r, h2 = R, mul(H, H)
    exact = {
        "(h, 1)K = (ht, K₁₁)": add(mul(H, K[0][0]), K[1][0]) == mul(H, T) and add(mul(H, K[0][1]), K[1][1]) == K[0][0],
        "K₁₁ + r = h²": add(K[0][0], r) == h2,
        "K₁₁ = (1 − r)²/4": K[0][0] == scale(mul([1, -1], [1, -1]), Fraction(1, 4)),
        "h² − 2r = t": sub(h2, scale(r, 2)) == T,
    }
    bad = [k for k, ok in exact.items() if not ok]
    if bad:
        raise ArithmeticError("part 5: " + "; ".join(bad))
    cmax = at(T, r_max) / (2 * r_max)
    if N1 < 6:
        raise NotVerified("part 5 needs n ≥ 6 (3π/n ≤ π/2)")
    if not (cmax > Fraction(-1, 2) and (N1 + 1) ** 2 * RHO <= N1 ** 2):
        raise NotVerified("θ_max < 2π/3 or the decrease of n²ρ̄^(n−1) is not proved")
    s3 = sqrt(Iv((1 - cmax) / 2)) * (1 + 2 * cmax)                # sin(3θ_max/2)
    h2max = at(H, r_max) ** 2
    dn = N1 * RHO ** (N1 - 1)
    m1 = 2 - Cu * h2max * N1 * dn
    m2 = s3 - Cu * h2max * dn
    if not (m1 > 0 and m2.positive()):
        raise NotVerified(f"the separating b is not proved (n ≥ {N1})")
    return {"margins": (m1, m2.lo)}


# ------------------------------------------------------------- 6. below r_n: every pair approaches
VELOCITY_RANGE = (Fraction(7, 100), Fraction(8, 100))     # ⊃ ]r*, r_n[ for every n ≥ 6


def velocities(K: list, N1: int, facts: dict) -> dict:
    """Part 6 for every n ≥ N1 ≥ 6 (or n = N1 alone, with part 4's facts for it) and r ∈ ]r*, r_n[
    (0 < nθ < π), on the dominant branch: before every collision of (ab)^n(cb)^n its pair approaches.
    Exactly (K^j = s_j K − r² s_{j−1}I, K₁₂ = h, (h, 1)K = (ht, K₁₁)), with y = K^j(−1, u) and
    s_j = r^{j−1} s̃_j, s̃_j = sin jθ/sin θ:
    q₁ before the (j+1)-th a is y₁ = −r^{j−1}[K₁₁s̃_j − r s̃_{j−1} − uh s̃_j], q₂ before the (j+1)-th b is
    −r^{j−1}[rh s̃_{j+1} − u(K₁₁s̃_j − r s̃_{j−1})].  For 1 ≤ k ≤ n − 1, 1 ≤ s̃_k ≤ n (θ ≤ kθ ≤ π − θ), and
    K₁₁ sin jθ − r sin(j−1)θ = sin jθ(K₁₁ − r cos θ) + r cos jθ sin θ ≥ sin θ(K₁₁ − 2r).  u = cX/D =
    s̃_n ω, c = −rh r^{n−1}s̃_n, |ω| ≤ rh r^{n−1}C_u, |u| ≤ n|ω|.  So the a-brackets are ≥ K₁₁ − 2r −
    rh²C n² r^{n−1}, the b-brackets with j ≤ n − 2 are ≥ rh(1 − Ch² n² r^{n−1}), and the last b's (j = n − 1,
    u = s̃_n ω): q₂ = −r^{n−2} s̃_n [rh − ω(K₁₁ s̃_{n−1} − r s̃_{n−2})] with |K₁₁ s̃_{n−1} − r s̃_{n−2}| ≤ (K₁₁ + r)n
    = h²n, so its bracket is ≥ rh(1 − C_u h² n r^{n−1}) ≥ rh(1 − Ch² n² r^{n−1}) (C ≥ C_u, n² ≥ n), whatever the
    sign of s̃_n: the same b-margin, and where s̃_n < 0 (π < nθ < 2π) that b's pair separates
    (:func:`family_approaching`).  The cb-phase is the same map on (q₃, q₂) from
    (q₃, q₂)(t_2n) = |q₃|(−1, u′), q₃(t_2n) < d < 0 (part 4, and d = −r s_n − r² s_{n−1} < 0),
    u′ = q₂(t_2n)/|q₃| = s̃_n ω′, q₂(t_2n) = −c + du = −c(1 − dX/D): |ω′| ≤ rh r^{n−1}(1 + δC_u)/|q₃|.
    With C = max(C_u, (1 + δC_u)/|q₃|), r ∈ [7/100, 8/100] (7/100 < r*, and r_n < 8/100 as cos θ(8/100) <
    √3/2 ≤ cos(π/n) for n ≥ 6) and n² r^{n−1} ≤ N1²(8/100)^{N1−1} (decreasing): both margins are checked
    positive in intervals over 16 boxes of the range.  Returns the smallest margins."""
    lo, hi = VELOCITY_RANGE
    c08 = at(T, hi) / (2 * hi)
    root = [Fraction(1), Fraction(-14), Fraction(1)]
    if not (N1 >= 6 and at(root, lo) > 0 and 0 < c08 and c08 * c08 < Fraction(3, 4)
            and (N1 + 1) ** 2 * hi <= N1 ** 2):
        raise NotVerified("[7/100, 8/100] ⊃ ]r*, r_n[ or the decrease of n² r^(n−1) is not proved")
    q3 = Iv(facts["q3_abs"])
    C = max(facts["Cu"], ((1 + facts["delta"] * facts["Cu"]) / q3).hi)
    big = N1 * N1 * hi ** (N1 - 1)
    m_a = m_b = None
    for k in range(16):
        r = Iv(lo + (hi - lo) * k / 16, lo + (hi - lo) * (k + 1) / 16)
        h = at(H, r)
        K11 = at(K[0][0], r)
        a_ = K11 - 2 * r - r * h * h * C * big
        b_ = 1 - C * h * h * big
        m_a = a_.lo if m_a is None else min(m_a, a_.lo)
        m_b = b_.lo if m_b is None else min(m_b, b_.lo)
    if not (m_a > 0 and m_b > 0):
        raise NotVerified(f"the velocity margins are not proved (n ≥ {N1})")
    return {"margins": (m_a, m_b)}


# ------------------------------------------------------------- 7. just below r_n: stable (the reflection)
def _vars(names: tuple) -> list:
    """The variables of Q[names] as polynomials (dicts of exponent tuples)."""
    return [{tuple(1 if i == k else 0 for i in range(len(names))): Fraction(1)} for k in range(len(names))]


def _c(c, n: int) -> dict:
    return {(0,) * n: Fraction(c)} if c else {}


def _msum(*terms) -> dict:
    out: dict = {}
    for t in terms:
        out = madd(out, t)
    return out


def f_n(a, b, c, d, W1, W2) -> dict:
    """F_n = W₁(a − W₁d + W₂c) + (bc + W₂cd − W₁d²) (docs/family-limit.md, part 4)."""
    return _msum(mmul(W1, _msum(a, mmul(mmul(W1, d), _c(-1, len(next(iter(a))))), mmul(W2, c))),
                 mmul(b, c), mmul(mmul(W2, c), d), mmul(mmul(_c(-1, len(next(iter(a)))), W1), mmul(d, d)))


def collisions_fix_their_pair() -> bool:
    """Exact, on the kernel's collision matrices A, B, C (pairs i = 1, 2, 3): G − I is 0 outside column i,
    so G x = x whenever x_i = 0.  Hence the positions of a word, p(t_k) = p(t_{k−1}) − (p_i/q_i) q(t_{k−1})
    with p_i(t_k) = 0, satisfy p(t_k) = G p(t_k) = G p(t_{k−1}) − (p_i/q_i) q(t_k): p(t_k) ≡ G p(t_{k−1})
    modulo q(t_k), and over a prefix of matrix M', p ≡ M' p(0) modulo q = M' q(0)."""
    for i in range(3):
        G = _rows(collision(i))
        for row in range(3):
            for col in range(3):
                if col != i and G[row][col] != (ONE if row == col else []):
                    return False
    return True


def check_reflection() -> dict:
    """The exact identities of the reflection (family_limit's part 12), each True when it holds:

    * ``N̄``: in Q[a, b, c, d, W₁, W₂, u, v], with N = [[W₁, W₂, 1], [c, d, 0], [a, b, 0]], q = (−1, u, v),
      uτ = uW₁ + c and uγ = ua − cv: u·Ne₁ = (uτ)e₁ + (uγ)e₃ + c·q, and Ne₃ = e₁;
    * ``γσ₀``: with σ₀u = −c + du and σ₀v = −a + bu (rows 2, 3 of Nq = σ₀q), a(σ₀u) − c(σ₀v) = u(ad − bc),
      i.e. (uγ)σ₀ = u·det P;
    * ``F_n``: e₂(N) tr N − det N = −F_n;
    * ``e₁e₂ − e₃``: in Q[x, y, z], (x + y + z)(xy + yz + zx) − xyz = (x + y)(y + z)(z + x);
    * ``F_n(r_n)``: in Q[ρ], at P = −ρI and W = (1 + ρ)(1/3, 2/3): F_n = −(2/9)ρ(1 + ρ)²;
    * ``collisions``: :func:`collisions_fix_their_pair`."""
    names = ("a", "b", "c", "d", "W1", "W2", "u", "v")
    a, b, c, d, W1, W2, u, v = _vars(names)
    k = len(names)
    one, m1 = _c(1, k), _c(-1, k)
    N = [[W1, W2, one], [c, d, {}], [a, b, {}]]
    q = [m1, u, v]
    u_tau, u_gamma = madd(mmul(u, W1), c), madd(mmul(u, a), mmul(c, v), -1)
    Ne1 = [N[i][0] for i in range(3)]
    rhs = [madd(u_tau, mmul(c, q[0])), mmul(c, q[1]), madd(u_gamma, mmul(c, q[2]))]
    out = {"N̄": all(not madd(mmul(u, Ne1[i]), rhs[i], -1) for i in range(3))
           and [N[i][2] for i in range(3)] == [one, {}, {}]}
    sig_u, sig_v = madd(mmul(d, u), c, -1), madd(mmul(b, u), a, -1)
    det_P = madd(mmul(a, d), mmul(b, c), -1)
    out["γσ₀"] = not madd(madd(mmul(a, sig_u), mmul(c, sig_v), -1), mmul(u, det_P), -1)
    tr = _msum(N[0][0], N[1][1], N[2][2])
    e2 = _msum(*(madd(mmul(N[i][i], N[j][j]), mmul(N[i][j], N[j][i]), -1) for i, j in ((0, 1), (0, 2), (1, 2))))
    det = _msum(*(mmul(mmul(_c(sg, k), N[0][p0]), madd(mmul(N[1][p1], N[2][p2]), mmul(N[1][p2], N[2][p1]), -1))
                  for sg, p0, p1, p2 in ((1, 0, 1, 2), (-1, 1, 0, 2), (1, 2, 0, 1))))
    out["F_n"] = not madd(madd(mmul(e2, tr), det, -1), f_n(a, b, c, d, W1, W2))
    x, y, z = _vars(("x", "y", "z"))
    lhs = madd(mmul(_msum(x, y, z), _msum(mmul(x, y), mmul(y, z), mmul(z, x))), mmul(mmul(x, y), z), -1)
    out["e₁e₂ − e₃"] = not madd(lhs, mmul(mmul(madd(x, y), madd(y, z)), madd(z, x)), -1)
    (rho,) = _vars(("ρ",))
    one1, zero = _c(1, 1), {}
    W = madd(one1, rho)
    at_rn = f_n(mmul(_c(-1, 1), rho), zero, zero, mmul(_c(-1, 1), rho), mmul(_c(Fraction(1, 3), 1), W),
                mmul(_c(Fraction(2, 3), 1), W))
    out["F_n(r_n)"] = not madd(at_rn, mmul(mmul(_c(Fraction(-2, 9), 1), rho), mmul(W, W)), -1)
    out["collisions"] = collisions_fix_their_pair()
    return out


def reach(K: list, facts: dict) -> dict:
    """Part 7 for every n with parts 1-4 and 6 (n ≥ N1 ≥ 7, or n = 6 alone): every r of some left neighbourhood
    ]r_n − ε_n, r_n[ of r_n is stable (the kernel's *stable*: λ > 0 strictly dominant, u > 0, x > 0 a
    fixed point of the position map f, every collision's pair approaching, every gap that must be open
    open, |f'(x)| < 1).  Let r ∈ ]r*, r_n[ (0 < nθ < π).  By parts 4 and 6: λ is simple and strictly
    dominant, u > 0, q₃(t_2n) ≤ −|q₃| < 0, every pair approaches.  N = J M_ab^n commutes with M = N²,
    so N q(0) = σ₀ q(0) (λ simple); row 1 gives σ₀ = −q₃(t_2n) > 0, and σ₀² = λ.  As u ≠ 0, (q(0), e₁, e₃)
    is a basis, and by the identity ``N̄`` N = [[σ₀, *], [0, N̄]] there with N̄ = [[τ, 1], [γ, 0]] on
    (e₁, e₃) modulo q(0): cp_N = (X − σ₀)(X² − τX − γ), and γ = det P/σ₀ = r^{2n}/σ₀ > 0 (``γσ₀``; det K =
    r²).  So N̄'s eigenvalues σ₊ > 0 > σ₋ are real (σ₊σ₋ = −γ), σ±² are M's other eigenvalues, |σ±| < σ₀
    (strict dominance), and by ``F_n`` and ``e₁e₂ − e₃`` on (σ₀, σ₊, σ₋):

        −F_n = (σ₀ + σ₊)(σ₀ + σ₋)(σ₊ + σ₋) = τ · (positive).

    The positions (``collisions``): p(t_2n) ≡ M_ab^n p(0) modulo q(t_2n) = M_ab^n q(0), and p₂(t_2n) = 0
    (its last collision is b), so J p(t_2n) = (p₃, 0, p₁)(t_2n) is the representative of N̄(1, x) =
    (τ + x, γ); with M_cb^n = J M_ab^n J = NJ, p(T) represents N̄²(1, x): f is the Möbius map of N̄².
    For τ ≠ 0 its fixed points are N̄'s eigenvectors (1, x±), x₊ = −σ₋ > 0, x₋ = −σ₊ < 0 (not admissible);
    at x₊: p₃(t_2n) = σ₊ > 0, p₁(T) = σ₊² > 0 (the gap of the first a open at the end; every other gap
    collided two collisions before, or is the first b's, p₂(t₁) = u > 0) and f'(x₊) = det N̄²/σ₊⁴ =
    σ₋²/σ₊² < 1 exactly when τ = σ₊ + σ₋ > 0 (τ = 0: f = id; τ < 0: |f'(x₊)| > 1).  So on ]r*, r_n[,
    r is stable exactly when F_n(r) < 0.  At r_n (nθ = π, s_n = 0 and r² s_{n−1} = r^n sin(π − θ)/sin θ =
    r^n, part 3): P = K^n = −r_n^n I and W = (1 + r_n^n)(1/3, 2/3), so by ``F_n(r_n)`` F_n(r_n) =
    −(2/9) r_n^n (1 + r_n^n)² < 0; F_n is a polynomial in r (the entries of K^n and W are), so F_n < 0
    on some ]r_n − ε_n, r_n]: every r there above r* is stable.  NotVerified when an identity fails or
    part 4 gave no bound of |q₃(t_2n)|.  Returns σ₀'s lower bound."""
    bad = [k for k, ok in check_reflection().items() if not ok]
    if bad:
        raise NotVerified("part 7 (the reflection): " + "; ".join(bad) + " fails")
    if not (facts["q3_abs"] > 0 and K[1][1] == scale(R, -1)):
        raise NotVerified("σ₀ = −q₃(t_2n) > 0 is not proved")
    return {"sigma0": facts["q3_abs"]}


# ------------------------------------------------------------- 8. below r_{n+1}: F_n > 0, nothing stable
def f_n_in_s() -> dict:
    """F_n/x as an exact polynomial in (r, x, w), x = s_n, w = r² s_{n−1}/s_n: F_n is :func:`f_n` at P = K^n =
    s_n K − r² s_{n−1} I (part 1) and W = (1/3, 2/3)(I − P), with K the kernel's block; every term of F_n has
    a factor x (ArithmeticError otherwise), divided out exactly."""
    K, _ = block()
    names = ("r", "x", "w")
    rr, x, w = _vars(names)

    def lift(p: list) -> dict:                          # a polynomial in r
        return {(k, 0, 0): Fraction(c) for k, c in enumerate(p) if c}
    y = mmul(x, w)
    P = [[madd(mmul(x, lift(K[i][j])), y if i == j else {}, -1) for j in range(2)] for i in range(2)]
    third = (_c(Fraction(1, 3), 3), _c(Fraction(2, 3), 3))
    W = [madd(third[j], madd(mmul(third[0], P[0][j]), mmul(third[1], P[1][j])), -1) for j in range(2)]
    F = f_n(P[0][0], P[0][1], P[1][0], P[1][1], W[0], W[1])
    if any(k[1] == 0 for k in F):
        raise ArithmeticError("F_n has a term without s_n")
    return {(k[0], k[1] - 1, k[2]): v for k, v in F.items()}


def _mvalue(p: dict, point: tuple) -> Iv:
    """A polynomial of (r, x, w) on intervals, term by term."""
    out = Iv(0)
    for k, v in p.items():
        term = Iv(v)
        for e, z in zip(k, point):
            if e:
                term = term * z ** e
        out = out + term
    return out


def below(N1: int, single: bool, boxes: int = 16) -> Fraction:
    """Part 8 for every n ≥ N1 (or n = N1 alone): F_n > 0 on ]0, r_{n+1}], so (part 7) nothing there is
    stable.  On ]0, r_{n+1}], (n + 1)θ ≤ π (θ = 0 up to r*), so s_{n−1}, s_n > 0 and s_{n+1} = t s_n − r² s_{n−1}
    ≥ 0 (part 3): with x = s_n > 0 and w = r² s_{n−1}/s_n, 0 ≤ w ≤ t ≤ 1/4, and x ≤ n ρ̄^{n−1} ≤ N1 4^{1−N1}
    (one n: the largest |s_n| on the box, s_n exact).  F_n = x·Q(r, x, w) (:func:`f_n_in_s`), and
    Q's part free of x is (3 − 6r − r² − 8w)/36 ≥ (1 + 6r − 3r²)/36 > 0 at w = t: Q > 0 is checked in
    intervals over `boxes` boxes of r ∈ [0, 8/100] ⊃ ]0, r_{n+1}] (n ≥ 6: cos θ(8/100) < √3/2 < cos(π/(n + 1)))
    with w ∈ [0, t(box)], x ∈ [0, x̄].  Returns the smallest Q;
    NotVerified unless it is positive.  Why nothing is stable where F_n > 0: on ]0, r_n[, u > 0 and σ₀ > 0
    (part 4), so (part 7) −F_n = τ (σ₀ + σ₊)(σ₀ + σ₋) with the second factor > 0: F_n > 0 gives τ < 0, and
    then the only admissible fixed point x₊ = −σ₋ > 0 has |f'(x₊)| = σ₋²/σ₊² > 1."""
    try:
        Q = f_n_in_s()
    except ArithmeticError as exc:
        raise NotVerified(f"part 8: {exc}") from None
    S = [[], ONE]
    for _ in range(N1 - 1):
        S.append(sub(mul(T, S[-1]), mul(mul(R, R), S[-2])))
    worst = None
    if not (single or (N1 + 1) * RHO <= N1):
        raise NotVerified(f"n ρ̄^(n−1) is not shown to decrease from n = {N1}")
    top = VELOCITY_RANGE[1]                        # r_{n+1} < 8/100 for n ≥ 6 (as in part 6: cos θ(8/100) < √3/2)
    c08 = at(T, top) / (2 * top)
    if not (N1 >= 6 and 0 < c08 and c08 * c08 < Fraction(3, 4)):
        raise NotVerified("r_(n+1) < 8/100 is not proved")
    for k in range(boxes):
        r = Iv(top * k / boxes, top * (k + 1) / boxes)
        t = at(T, r)
        if not t.positive():
            raise NotVerified("t > 0 on ]0, 8/100] is not proved")
        xbar = at(S[N1], r).mag() if single else N1 * RHO ** (N1 - 1)
        q = _mvalue(Q, (r, Iv(0, xbar), Iv(0, t.hi))).lo
        worst = q if worst is None else min(worst, q)
    if not worst > 0:
        raise NotVerified(f"F_n > 0 below r_(n+1) is not proved ({'n =' if single else 'n ≥'} {N1})")
    return worst


def third_a() -> None:
    """The third a (family_limit's part 11, as L6.6.3): with ℓ_j = (K^j(−1, u))₁, K² = tK − r²I (part 1) gives
    ℓ₂ = tℓ₁ + r² for every u, so where t < 0 the second a's pair approaching (ℓ₁ < 0) makes the third a's
    separate (ℓ₂ > 0): for n ≥ 3 nothing on [429/2500, 1[ is feasible.  Exact: t(429/2500) < 0 and t has no
    root in [429/2500, 1] (Sturm).  NotVerified otherwise."""
    lo = Fraction(429, 2500)
    if not (at(T, lo) < 0 and count(T, lo, Fraction(1)) == 0):
        raise NotVerified("t < 0 on [429/2500, 1[ is not proved")


# ------------------------------------------------------------- the predicates
def _pi_multiple(t) -> Fraction:
    """c in an expression cπ written π, π/m, k·π, k·π/m or kπ (a tree of the language)."""
    if t in (("const", "π"), ("name", "π")):
        return Fraction(1)
    if t[0] == "bin" and t[1] == "/" and t[3][0] == "num":
        return _pi_multiple(t[2]) / Fraction(t[3][1])
    if t[0] == "bin" and t[1] in ("*", "·") and t[2][0] == "num":
        return Fraction(t[2][1]) * _pi_multiple(t[3])
    raise Undefined("the threshold is written n·θ = cπ (c rational)")


def _arguments(ctx, word, n_bound, threshold=None, relation: str = "=", r_range=None) -> tuple:
    """(N, R, c, single) from the predicate's arguments, each checked for its form (R = 1/4 without a range,
    c = None without a threshold); single is True for ``n = N`` (one n: part 4 on boxes of r, dominant_at),
    False for ``n ≥ N``."""
    if word[0] != "str" or word[1].replace(" ", "") != WORD:
        raise Undefined(f"the kernel's family route knows the word {WORD} only")
    if (n_bound[0] != "cmp" or n_bound[1] not in (("≥",), ("=",)) or n_bound[2][0] != ("name", "n")
            or n_bound[2][1][0] != "num" or Fraction(n_bound[2][1][1]).denominator != 1):
        raise Undefined("the range of n is written n ≥ N or n = N")
    N1 = int(Fraction(n_bound[2][1][1]))
    single = n_bound[1] == ("=",)
    r_max = R_MAX
    if r_range is not None:
        if r_range[0] != "cmp" or r_range[1] != ("in",) or r_range[2][0] != ("name", "r"):
            raise Undefined("the range of r is written r in ]0, R]")
        iv = interval(r_range[2][1], ctx)
        lo, hi = iv.lo, iv.hi
        if not (lo.rational and hi.rational) or lo.lo != 0 or iv.lo_closed or not iv.hi_closed:
            raise Undefined("the range of r is ]0, R], R rational")
        r_max = Fraction(hi.lo)
    if threshold is None:
        return N1, r_max, None, single
    if (threshold[0] != "cmp" or threshold[1] != (relation,) or threshold[2][0][0] != "bin"
            or threshold[2][0][1:3] != ("·", ("name", "n")) or threshold[2][0][3] != ("name", "θ")):
        raise Undefined(f"the threshold is written n·θ {relation} cπ")
    return N1, r_max, _pi_multiple(threshold[2][1]), single


def _s_values(r0: Fraction, n: int) -> list:
    """[s_0, ..., s_n] at the rational r0, exactly: s_0 = 0, s_1 = 1, s_{j+1} = t s_j − r² s_{j−1}."""
    t, r2 = at(T, r0), r0 * r0
    s = [Fraction(0), Fraction(1)]
    while len(s) <= n:
        s.append(t * s[-1] - r2 * s[-2])
    return s


def _first_nonpositive(r0: Fraction, n: int) -> int:
    """The first j ≥ 1 with s_j(r0) ≤ 0, or n + 1 when s_1, ..., s_n > 0."""
    s = _s_values(r0, n)
    return next((j for j in range(1, n + 1) if s[j] <= 0), n + 1)


def theta_point(j_lo: int, j_hi: int, r_max: Fraction) -> tuple[Fraction, int] | None:
    """A rational r₀ ∈ ]7/100, R] and j₀ ∈ [j_lo, j_hi] with s_1, ..., s_{j₀−1} > 0 > s_{j₀} at r₀
    (exact values, by bisection), or None.  By part 3 (s_j = r^{j−1} sin jθ / sin θ above r*, θ ∈ ]0, π[,
    and s_j > 0 for every j at and below r*) this places θ(r₀) strictly between π/j₀ and π/(j₀ − 1):
    (j₀ − 1)θ < π as s_1, ..., s_{j₀−1} > 0 (the first zero of sin jθ), j₀θ > π as s_{j₀} < 0."""
    lo, hi = VELOCITY_RANGE[0], r_max              # 7/100 < r*: every s_j > 0 there (checked below)
    if not (_first_nonpositive(lo, j_hi) > j_hi and _first_nonpositive(hi, j_hi) <= j_hi):
        return None
    for _ in range(400):
        j = _first_nonpositive(hi, j_hi)
        if j_lo <= j and _s_values(hi, j)[j] < 0:
            return hi, j
        mid = (lo + hi) / 2
        if _first_nonpositive(mid, j_hi) > j_hi:
            lo = mid
        else:
            hi = mid
    return None


def _refuting_point(c: Fraction, N1: int, r_max: Fraction, single: bool = False) -> tuple[int, Fraction, int]:
    """For c ≠ 1 (c > 0), an n ≥ N1 and an exact r₀ that refute "q_2(0) > 0 below nθ = cπ, = 0 at it,
    < 0 just above" (returns (n, r₀, j₀); NotVerified when none is found):

    * c > 1: the smallest n ≥ N1 with n/(n − 1) ≤ c and r₀ with j₀ = n (:func:`theta_point`), so
      π < nθ(r₀) < nπ/(n − 1) ≤ cπ: r₀ lies below the claimed zero, where the claim has q_2(0) > 0, but
      s_n(r₀) < 0 exactly, and q_2(0) has the sign of s_n (parts 2-4);
    * 0 < c < 1: the smallest n ≥ N1 with ⌊n/c⌋ ≥ n + 1 and r₀ with n < j₀ ≤ n/c, so cπ ≤ nπ/j₀ <
      nθ(r₀) < π: the claimed zero lies in ]r*, r₀] (θ increases with r, part 3), where 0 < nθ < π
      and q_2(0) > 0 (parts 2-4; exactly s_n(r₀) > 0 at its right end), not 0.

    With `single` n must be N1 itself (NotVerified when N1 does not fit c)."""
    if c > 1:
        n = max(N1, -(-c // (c - 1)))
        j_lo = j_hi = int(n)
    else:
        n = N1
        while (n / c) // 1 < n + 1:
            n += 1
        j_lo, j_hi = n + 1, int(n / c)
    found = theta_point(j_lo, j_hi, r_max) if not single or n == N1 else None
    if found is None:
        raise NotVerified(f"no point refuting n·θ = {c}·π was found on ]0, {r_max}]")
    return int(n), found[0], found[1]


def q2_sign_family(ctx, word, n_bound, r_range, threshold) -> bool:
    """The predicate of the module docstring: True when c = 1 and parts 1-4 are proved for every
    n ≥ N on ]0, R]; False when c ≠ 1 and parts 1-4 are proved and the kernel finds an n ≥ N and an
    exact rational r₀ that refutes the claim (:func:`_refuting_point`: the sign of s_n(r₀), computed,
    against the sign the claim gives there); NotVerified when a step is not proved (R > 1/4, N too
    small for the intervals) or no such point is found; Undefined for c ≤ 0 (no point of ]r*, R])."""
    N1, r_max, c, single = _arguments(ctx, word, n_bound, threshold, "=", r_range)
    if c <= 0:
        raise Undefined("the threshold n·θ = cπ needs c > 0")
    _proved(N1, r_max, single)
    if c != 1:
        n, r0, j0 = _refuting_point(c, N1, r_max, single)
        how = (f"s_{n} < 0 there (π/{n} < θ < π/{n - 1}: π < nθ < cπ, below the claimed zero)" if c > 1 else
               f"s_{n} > 0 there (π/{j0} < θ < π/{j0 - 1}: cπ < nθ < π, above the claimed zero)")
        ctx.counterexample = f"{r0} ≈ {float(r0):.6f}, n = {n}: {how}"
        return False
    return True


def _proved(N1: int, r_max: Fraction, single: bool = False) -> dict:
    """Parts 1-4 for every n ≥ N1 on ]0, R] (single: for n = N1 alone, part 4 by :func:`dominant_at`):
    the facts of part 4 (NotVerified when a step is not proved)."""
    if N1 < 2:
        raise Undefined("n ≥ N with N ≥ 2")
    if r_max > R_MAX:
        raise NotVerified(f"the kernel's route covers r ≤ {R_MAX} (the spectral radius of K is ≤ 1/4 there)")
    try:
        K, _ = block()
        if not check_q2_identity():
            raise ArithmeticError("the identity of q_2(0) fails")
        if not check_u_factor():
            raise ArithmeticError("u = cX/D fails")
        theta_facts(r_max)
    except ArithmeticError as exc:
        raise NotVerified(str(exc)) from None
    return {"K": K, **(dominant_at(K, N1, r_max) if single else dominant(K, N1, r_max))}


def family_unstable(ctx, word, n_bound, r_range, threshold) -> bool:
    """``family_unstable("(ab)^n(cb)^n", n ≥ N, r in ]0, R], n·θ > cπ)``: for every n ≥ N no r of ]0, R]
    with nθ > cπ is stable.  Proved for c ≥ 1: where π < nθ < 2π, q_2(0) < 0 on the dominant branch and
    at nθ = 2π it is 0 (parts 1-4), and where nθ > 2π a b of the ab-phase separates (part 5): the word
    is not realised.  For c < 1, NotVerified (the kernel proves no stability)."""
    N1, r_max, c, single = _arguments(ctx, word, n_bound, threshold, ">", r_range)
    facts = _proved(N1, r_max, single)
    try:
        arcs(facts["K"], N1, r_max, facts["Cu"])
    except ArithmeticError as exc:
        raise NotVerified(str(exc)) from None
    if c < 1:
        raise NotVerified("the kernel's route shows nothing unstable below nθ = π")
    return True


def family_approaching(ctx, word, n_bound, threshold) -> bool:
    """``family_approaching("(ab)^n(cb)^n", n ≥ N, n·θ < cπ)``: for every n ≥ N and every r above
    r* = 7 − 4√3 with nθ < cπ, on the dominant branch every collision of the word comes with its pair
    approaching.  Proved for c ≤ 1 (part 6).  False for c > 1 only once the kernel has the refuting
    point: an n ≥ N and an exact r₀ ∈ [7/100, 8/100] with π < nθ(r₀) < cπ (:func:`_refuting_point`:
    s_n(r₀) < 0, computed) and the last b's bracket proved positive there (:func:`velocities`' b-margin,
    which bounds it for every sign of s_n), so at r₀ q₂ > 0 before the last b of (ab)^n: its pair
    separates.  NotVerified when either is missing."""
    N1, _, c, single = _arguments(ctx, word, n_bound, threshold, "<")
    facts = _proved(N1, R_MAX, single)
    margin = velocities(facts["K"], N1, facts)["margins"][1]     # the b-brackets', the last b's too
    if c > 1:
        n, r0, _ = _refuting_point(c, N1, R_MAX, single)
        lo, hi = VELOCITY_RANGE
        if not lo <= r0 <= hi:
            raise NotVerified(f"the refuting point r = {float(r0):.6f} lies outside [7/100, 8/100]")
        ctx.counterexample = (f"{r0} ≈ {float(r0):.6f}, n = {n} (π < nθ < cπ, s_{n} < 0 there): the last "
                              f"b of (ab)^n separates (its bracket ≥ rh·{float(margin):.4f})")
        return False
    return True


def family_reaches(ctx, word, n_bound, threshold) -> bool:
    """``family_reaches("(ab)^n(cb)^n", n ≥ N, n·θ = cπ)``: for every n ≥ N, every r of some left
    neighbourhood of the r where nθ = cπ is stable.  Proved for c = 1 (parts 1-4, 6 and 7: just below
    r_n, F_n < 0, so τ > 0 and every condition of stability holds).  For c ≠ 1, NotVerified: the
    kernel's route decides the neighbourhood of r_n only."""
    N1, _, c, single = _arguments(ctx, word, n_bound, threshold, "=")
    if c != 1:
        raise NotVerified("the kernel's route decides stability just below nθ = π only")
    facts = _proved(N1, R_MAX, single)
    velocities(facts["K"], N1, facts)
    reach(facts["K"], facts)
    return True


def family_window(ctx, word, n_bound) -> bool:
    """``family_window("(ab)^n(cb)^n", n ≥ N)`` (or ``n = N``): for every such n the stable set of w_n in ]0, 1[
    is not empty, has sup r_n (nθ = π) and lies in ]r_{n+1}, r_n[.  So the stable sets of consecutive n are
    disjoint (r_{n+1} < r_n) and they accumulate from above on r* = 7 − 4√3 (r_n → r* as cos(π/n) → 1, r_n > r*).
    Proved from parts 1-8 (N ≥ 6): nothing stable on ]0, r_{n+1}] (part 8), at r_n (u = 0, part 4), on
    ]r_n, 1/4] (parts 4, 5) or on [429/2500, 1[ (:func:`third_a`, n ≥ 3); stable points just below r_n
    (parts 6, 7)."""
    N1, _, _, single = _arguments(ctx, word, n_bound)
    facts = _proved(N1, R_MAX, single)
    try:
        arcs(facts["K"], N1, R_MAX, facts["Cu"])
    except ArithmeticError as exc:
        raise NotVerified(str(exc)) from None
    velocities(facts["K"], N1, facts)
    reach(facts["K"], facts)
    below(N1, single)
    third_a()
    return True


PREDICATES["q2_sign_family"] = q2_sign_family
PREDICATES["family_approaching"] = family_approaching
PREDICATES["family_unstable"] = family_unstable
PREDICATES["family_reaches"] = family_reaches
PREDICATES["family_window"] = family_window
