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

from .evaluate import PREDICATES, NotVerified, interval, word_matrix
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
    a = b = c = d = small
    W1 = Fraction(1, 3) - a / 3 - 2 * c / 3                        # Wᵀ = (1/3, 2/3)(I − P)
    W2 = Fraction(2, 3) - b / 3 - 2 * d / 3
    N = [[W1, W2, Iv(1)], [c, d, Iv(0)], [a, b, Iv(0)]]
    M = [[N[i][0] * N[0][j] + N[i][1] * N[1][j] + N[i][2] * N[2][j] for j in range(3)] for i in range(3)]
    det = Iv(0, RHO ** (4 * N1))                                   # det M = r^{4n}
    tr = M[0][0] + M[1][1] + M[2][2]
    e2 = sum((M[i][i] * M[j][j] - M[i][j] * M[j][i] for i, j in ((0, 1), (0, 2), (1, 2))), Iv(0))

    def cp(x):
        return x ** 3 - tr * x ** 2 + e2 * x - det
    omega = WIDTH * delta
    lo, hi = Fraction(1, 9) - omega, Fraction(1, 9) + omega
    if lo <= 0:
        raise NotVerified(f"the interval of λ reaches 0 (n ≥ {N1}: δ = {float(delta):.3g} is too large)")
    if not (cp(Iv(lo)).negative() and cp(Iv(hi)).positive()):
        raise NotVerified(f"the characteristic polynomial is not shown to change sign around 1/9 (n ≥ {N1})")
    lam = Iv(lo, hi)
    S, Pi = (tr - lam).mag(), (det / lam).mag()
    others = (S / 2 + sqrt(Iv(S * S / 4 + Pi))).hi
    if not others < lam.lo:
        raise NotVerified(f"strict dominance is not proved (n ≥ {N1})")
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
    h2max = ((1 + r_max) / 2) ** 2
    dn = N1 * RHO ** (N1 - 1)
    m1 = 2 - Cu * h2max * N1 * dn
    m2 = s3 - Cu * h2max * dn
    if not (m1 > 0 and m2.positive()):
        raise NotVerified(f"the separating b is not proved (n ≥ {N1})")
    return {"margins": (m1, m2.lo)}


# ------------------------------------------------------------- 6. below r_n: every pair approaches
VELOCITY_RANGE = (Fraction(7, 100), Fraction(8, 100))     # ⊃ ]r*, r_n[ for every n ≥ 7


def velocities(K: list, N1: int, facts: dict) -> dict:
    """Part 6 for every n ≥ N1 ≥ 7 and r ∈ ]r*, r_n[ (0 < nθ < π), on the dominant branch: before every
    collision of (ab)^n(cb)^n its pair approaches.  Exactly (K^j = s_j K − r² s_{j−1}I, K₁₂ = h,
    (h, 1)K = (ht, K₁₁)), with y = K^j(−1, u) and s_j = r^{j−1} s̃_j, s̃_j = sin jθ/sin θ:
    q₁ before the (j+1)-th a is y₁ = −r^{j−1}[K₁₁s̃_j − r s̃_{j−1} − uh s̃_j], q₂ before the (j+1)-th b is
    −r^{j−1}[rh s̃_{j+1} − u(K₁₁s̃_j − r s̃_{j−1})].  For 1 ≤ k ≤ n − 1, 1 ≤ s̃_k ≤ n (θ ≤ kθ ≤ π − θ), and
    K₁₁ sin jθ − r sin(j−1)θ = sin jθ(K₁₁ − r cos θ) + r cos jθ sin θ ≥ sin θ(K₁₁ − 2r).  u = cX/D =
    s̃_n ω, c = −rh r^{n−1}s̃_n, |ω| ≤ rh r^{n−1}C_u, |u| ≤ n|ω|.  So the a-brackets are ≥ K₁₁ − 2r −
    rh²C n² r^{n−1}, the b-brackets with j ≤ n − 2 are ≥ rh(1 − Ch² n² r^{n−1}), and the last b's is
    s̃_n(rh − |ω| n h²) > 0 with s̃_n > 0.  The cb-phase is the same map on (q₃, q₂) from
    (q₃, q₂)(t_2n) = |q₃|(−1, u′), q₃(t_2n) < d < 0 (part 4, and d = −r s_n − r² s_{n−1} < 0),
    u′ = q₂(t_2n)/|q₃| = s̃_n ω′, q₂(t_2n) = −c + du = −c(1 − dX/D): |ω′| ≤ rh r^{n−1}(1 + δC_u)/|q₃|.
    With C = max(C_u, (1 + δC_u)/|q₃|), r ∈ [7/100, 8/100] (7/100 < r*, and r_n < 8/100 as cos θ(8/100) <
    √3/2 < cos(π/n) for n ≥ 7) and n² r^{n−1} ≤ N1²(8/100)^{N1−1} (decreasing): both margins are checked
    positive in intervals over 16 boxes of the range.  Returns the smallest margins."""
    lo, hi = VELOCITY_RANGE
    c08 = at(T, hi) / (2 * hi)
    root = [Fraction(1), Fraction(-14), Fraction(1)]
    if not (N1 >= 7 and at(root, lo) > 0 and 0 < c08 and c08 * c08 < Fraction(3, 4)
            and (N1 + 1) ** 2 * hi <= N1 ** 2):
        raise NotVerified("[7/100, 8/100] ⊃ ]r*, r_n[ or the decrease of n² r^(n−1) is not proved")
    q3 = Iv(facts["q3_abs"])
    C = max(facts["Cu"], ((1 + facts["delta"] * facts["Cu"]) / q3).hi)
    big = N1 * N1 * hi ** (N1 - 1)
    m_a = m_b = None
    for k in range(16):
        r = Iv(lo + (hi - lo) * k / 16, lo + (hi - lo) * (k + 1) / 16)
        h = (1 + r) / 2
        K11 = at(K[0][0], r)
        a_ = K11 - 2 * r - r * h * h * C * big
        b_ = 1 - C * h * h * big
        m_a = a_.lo if m_a is None else min(m_a, a_.lo)
        m_b = b_.lo if m_b is None else min(m_b, b_.lo)
    if not (m_a > 0 and m_b > 0):
        raise NotVerified(f"the velocity margins are not proved (n ≥ {N1})")
    return {"margins": (m_a, m_b)}


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


def _arguments(ctx, word, n_bound, threshold, relation: str, r_range=None) -> tuple:
    """(N, R, c) from the predicate's arguments, each checked for its form (R = 1/4 without a range)."""
    if word[0] != "str" or word[1].replace(" ", "") != WORD:
        raise Undefined(f"the kernel's family route knows the word {WORD} only")
    if n_bound[0] != "cmp" or n_bound[1] != ("≥",) or n_bound[2][0] != ("name", "n") or n_bound[2][1][0] != "num":
        raise Undefined("the range of n is written n ≥ N")
    N1 = int(Fraction(n_bound[2][1][1]))
    r_max = R_MAX
    if r_range is not None:
        if r_range[0] != "cmp" or r_range[1] != ("in",) or r_range[2][0] != ("name", "r"):
            raise Undefined("the range of r is written r in ]0, R]")
        iv = interval(r_range[2][1], ctx)
        lo, hi = iv.lo, iv.hi
        if not (lo.rational and hi.rational) or lo.lo != 0 or iv.lo_closed or not iv.hi_closed:
            raise Undefined("the range of r is ]0, R], R rational")
        r_max = Fraction(hi.lo)
    if (threshold[0] != "cmp" or threshold[1] != (relation,) or threshold[2][0][0] != "bin"
            or threshold[2][0][1:3] != ("·", ("name", "n")) or threshold[2][0][3] != ("name", "θ")):
        raise Undefined(f"the threshold is written n·θ {relation} cπ")
    return N1, r_max, _pi_multiple(threshold[2][1])


def q2_sign_family(ctx, word, n_bound, r_range, threshold) -> bool:
    """The predicate of the module docstring: True when c = 1 and parts 1-4 are proved for every
    n ≥ N on ]0, R]; False when c ≠ 1 (nθ = cπ is not where q_2(0) first vanishes: for 0 < c < 1
    q_2(0) > 0 there, for c > 1 it vanished before, at nθ = π); NotVerified when a step is not proved
    (R > 1/4, N too small for the intervals)."""
    N1, r_max, c = _arguments(ctx, word, n_bound, threshold, "=", r_range)
    _proved(N1, r_max)
    if c != 1:
        ctx.counterexample = f"n·θ = {c}π: sin(nθ) {'> 0' if c < 1 else 'vanished first at nθ = π'}"
        return False
    return True


def _proved(N1: int, r_max: Fraction) -> dict:
    """Parts 1-4 for every n ≥ N1 on ]0, R]: the facts of :func:`dominant` (NotVerified when a step
    is not proved)."""
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
    return {"K": K, **dominant(K, N1, r_max)}


def family_unstable(ctx, word, n_bound, r_range, threshold) -> bool:
    """``family_unstable("(ab)^n(cb)^n", n ≥ N, r in ]0, R], n·θ > cπ)``: for every n ≥ N no r of ]0, R]
    with nθ > cπ is stable.  Proved for c ≥ 1: where π < nθ < 2π, q_2(0) < 0 on the dominant branch and
    at nθ = 2π it is 0 (parts 1-4), and where nθ > 2π a b of the ab-phase separates (part 5): the word
    is not realised.  For c < 1, NotVerified (the kernel proves no stability)."""
    N1, r_max, c = _arguments(ctx, word, n_bound, threshold, ">", r_range)
    facts = _proved(N1, r_max)
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
    approaching.  Proved for c ≤ 1 (part 6); false for c > 1: just above r_n (nθ slightly above π, r
    still in [7/100, 8/100]) the last b of (ab)^n has the bracket s̃_n(rh − ω(…)) < 0 as s̃_n < 0, so
    its pair separates."""
    N1, _, c = _arguments(ctx, word, n_bound, threshold, "<")
    facts = _proved(N1, R_MAX)
    velocities(facts["K"], N1, facts)
    if c > 1:
        ctx.counterexample = "just above r_n (nθ slightly above π): the last b of (ab)^n separates"
        return False
    return True


PREDICATES["q2_sign_family"] = q2_sign_family
PREDICATES["family_approaching"] = family_approaching
PREDICATES["family_unstable"] = family_unstable
