"""The windows of (ab)^n(cb)^n for large n: what is proved for every n, exactly.

Issue 35 asks for the stable set W_n = ]lo_n, hi_n[ of w_n = (ab)^n(cb)^n for every n.
This module proves where the two ends of that window are, for every n (parts 1-4 for all n,
parts 5-6 for n > N₀), that the windows they bound are disjoint and decrease, (parts 7-11) that
on ]0, 1[ the stable set is everything between r_n and a thin strip around the lower end, and (part 12)
that it is exactly ]ℓ_n, r_n[, ℓ_n the one zero of F_n in the strip:

1. **The block structure** (:func:`block_facts`, exact polynomials in r): M_ab = [[K, 0],
   [wᵀ, 1]] in (q₁, q₂ | q₃), M_cb the same K on (q₃, q₂), K = [[h² - r, h], [-rh, -r]]
   (h = (1 + r)/2), det K = r², tr K = t = (r² - 6r + 1)/4 and t² - 4r² =
   (r² - 14r + 1)(r + 1)²/16: K has a double eigenvalue exactly at r* = 7 - 4√3 (and
   r** = 7 + 4√3), complex ones r e^{±iθ} on ]r*, 1[ with 1 - cos θ = (r - r*)(r** - r)/(8r).
   Cayley–Hamilton: K^n = s_n K - r² s_{n-1} I, s_j = r^{j-1} sin(jθ)/sin θ.

2. **CDKK's point, in closed form** (:func:`check_u_identity`, proof in
   docs/family-limit.md): write P = K^n and q₃(t_{2n}) the relative velocity of pair 3
   just before the first c.  On every eigenvalue branch,

       u (λ - P₂₂²) = P₂₁ (q₃(t_{2n}) - P₂₂),   P₂₁ = -r h s_n,

   so q₂(0) = u vanishes where sin(nθ) = 0 (wherever λ ≠ P₂₂²), and its sign is that of
   s_n where λ > P₂₂² and q₃(t_{2n}) < P₂₂.  The first zero above r* is nθ = π:

       r_n = a - √(a² - 1),  a = 3 + 4 cos(π/n),  the root in ]0, 1[ of r² - (6 + 8 cos(π/n)) r + 1
       (r_2 = 3 - 2√2, r_3 = 5 - 2√6: the ends of L5/L6).

3. **Its expansion** (:func:`s_hi`, :func:`prove`): with ε = 1/n, s_hi(ε) = n²(r_n - r*)
   = 4π² r_n sinc_π(ε/2)² / (r** - r_n) exactly, even in ε, s_hi(0) = s* = π²r*/(2√3) =
   π²(7√3 - 12)/6 ≈ 0.2045568, s_hi = s* + κε² + O(ε⁴), κ = s*π²(3 + 4√3)/48 ≈ 0.4176;
   r_{n+1} < r_n for every n (a = 3 + 4cos(π/n) increases).  Ball enclosures over boxes
   covering ε ∈ [0, 1/N₀] are returned as rational inequalities (:func:`check` re-verifies).

4. **The lower end is a zero of F_n** (:func:`check_lower_identity`): at a fixed point x of the
   position map the plane of q(0) and p(0) = (1, 0, x) is M-invariant (p ∧ q is mapped by
   Λ²M over a period), so x₊ = 0 makes e₁, Me₁, M²e₁ dependent: D = M₂₁(M²)₃₁ - M₃₁(M²)₂₁ =
   P₂₁ det(P) F_n = 0, F_n = W₁(a - W₁d + W₂c) + (bc + W₂cd - W₁d²) (a, b, c, d = K^n, W as in
   :func:`period_parts`).

5. **Its zeros, for every n > N₀** (:func:`f_hat`, :func:`prove_lower`): in the blow-up
   φ = nθ = π - εη, F_n's sign is that of F̂(η, ε), a function with a limit at ε = 0, the
   exponentially small parts in balls; balls over boxes of (η, ε) ∈ [0, 4] × [0, 1/(N₀+1)]
   put every zero of F_n in [r_{n+1}, r_n] in a strip η ∈ [η₋, η₊] ⊂ [0.89, 0.93], far from
   r_{n+1} (η = π/(1 + ε)): the windows ]ℓ_n, r_n[ are disjoint and decrease.

6. **The limit** (:func:`limit_constants`, exact in Q(√3)): η₀ = π√3/6, s_lo = s* - αε + O(ε²)
   with α = s*/√3 = π²r*/6 ≈ 0.1181.

7. **The dominant branch** (:func:`dominant_facts`, for every n ≥ 7 and r ∈ ]0, 1/4], one ball
   computation): λ = 1/9 + O(n 4^{-n}) is real, simple and strictly dominant (wᵀ(I - K)⁻¹ =
   (1/3, 2/3) exactly), and the hypotheses of part 2 hold: q₂(0) has the sign of s_n there.

8. **The velocity conditions** (:func:`velocity_facts`, for every n ≥ 8): every collision's pair
   approaches on ]r*, r_n[, in both phases (exact formulas in s̃_k = sin kθ/sin θ, balls over r).

9. **The positions** (:func:`graded_quantities`, :func:`position_facts`, :func:`below_facts`, for every
   n ≥ 7): p(0) = (1, 0, x) ↦ p(T) is the map Q induced by M on R³/q(0); its entries Q₁₂, Q₂₁, its trace
   μ + ν and p₃(t_{2n}) - x are exact polynomials in z = r^(n-1), the rest y of λ and K^n/z, whose parts
   at z = 0 are multiples of one linear form L = 3A + 2C - D (μ + ν: L² + 6r²).  Q₁₂, Q₂₁ > 0 < μ + ν makes
   the positive fixed point attracting with p₁(T), p₃(t_{2n}) > 0; Q₁₂, Q₂₁ < 0 < μ + ν leaves nothing
   stable.  Balls: 'inside' from r_n down to a strip η ∈ [η_in, η_out] of the blow-up (width ≤ 3/256 for
   N₁ = 31), 'below' from the strip down to 0 (three charts), and inside the strip L increasing with
   the O(z) rests bounded (:func:`thin_strip`): the undecided set is one interval I_n of η-length
   ≤ 2.87·10⁻³⁵ for every n ≥ 31.

10. **Above r_n** (:func:`arc_facts`, for every n ≥ 7): where π < nθ ≤ 2π, u ≤ 0 (part 7); where
    nθ > 2π, some b of the ab-phase has sin j'θ ≤ -min(2/n, sin θ_max, sin(3θ_max/2)), and its pair
    separates (part 8's formula): nothing in ]r_n, R] is stable, R = 5/8 for N₁ = 31 (part 7 re-proved on
    boxes of ]1/4, 5/8]), 1/4 for N₁ = 7.

11. **Where t = tr K ≤ 0** (:func:`third_a_facts`, for every n ≥ 3, exact): on [429/2500, 1[ (429/2500 >
    3 - 2√2, the zero of t) q₁ before the a's of the ab-phase obeys ℓ_{j+2} = tℓ_{j+1} - r²ℓ_j with ℓ₀ = -1,
    so ℓ₁ < 0 forces ℓ₂ ≥ r² > 0: for any q(0) the second or the third a has its pair separating, nothing
    is feasible.  With parts 9 and 10 this closes ]0, 1[ for every n ≥ 31 (and n ≥ 8 with N₁ = 7).

12. **The reflection** (:func:`reflection_facts`, exact; :func:`f_slope`, balls): M_cb = J M_ab J (J: q₁ ↔ q₃),
    so M = N² with N = J M_ab^n; on R³/q(0) N induces N̄ = [[τ, 1], [γ, 0]] (N e₃ = e₁, γ = r^{2n}/σ₀ > 0,
    σ₀ = -q₃(t_{2n})), Q = N̄², and e₂(N) tr N - det N = τ(σ₀ + σ₊)(σ₀ + σ₋) = -F_n: on ]r*, r_n[ r is stable
    exactly where F_n < 0.  dF/dη > 0 on part 9's strips: F_n has one zero ℓ_n in ]r_{n+1}, r_n[, and the
    stable set in ]0, 1[ is exactly ]ℓ_n, r_n[ for every n ≥ 31 (n ≥ 8 with N₁ = 7).

Not proved here (docs/family-limit.md): ℓ_n in closed form (it is enclosed); n ≤ N₀ is certified n by n by
the family's exact certificates, and an independent mpmath computation is observed (n = 35, 50, 80 in
the tests).
"""
from __future__ import annotations

import functools
import itertools
import math
from fractions import Fraction

import flint

from certify.algebra.balls import ends, precision
from certify.dynamics.model import word_matrix_flint

R = flint.fmpq_poly([0, 1])
H = (1 + R) / 2
T = (R * R - 6 * R + 1) / 4            # tr K
ROOT_POLY = R * R - 14 * R + 1          # (r - r*)(r - r**): where K's eigenvalues meet


# ------------------------------------------------------------------ 1. the block
def block() -> tuple[list, list]:
    """(K, w) read from the engine's M_ab = word_matrix('ab'): K its upper-left 2×2 block
    (on q₁, q₂), wᵀ the first two entries of its last row; ArithmeticError unless M_ab is
    [[K, 0], [wᵀ, 1]] exactly."""
    M = word_matrix_flint("ab")
    if not (M[0][2] == 0 and M[1][2] == 0 and M[2][2] == 1):
        raise ArithmeticError("M_ab is not [[K, 0], [w, 1]]")
    return [M[0][:2], M[1][:2]], M[2][:2]


def block_facts() -> list[str]:
    """The exact identities of the block (polynomials over Q in r), each checked here:
    K as printed, det K = r², tr K = t, t² - 4r² = (r² - 14r + 1)(r + 1)²/16, M_cb =
    [[1, w'ᵀ], [0, K]] on (q₁ | q₃, q₂) with the same K and w' = w, and the identity
    behind 1 - cos θ = (r - r*)(r** - r)/(8r): 2r - t = -(r² - 14r + 1)/4."""
    K, w = block()
    Mcb = word_matrix_flint("cb")
    Kcb = [[Mcb[2][2], Mcb[2][1]], [Mcb[1][2], Mcb[1][1]]]            # on (q₃, q₂)
    checks = {
        "K = [[h² - r, h], [-rh, -r]]": K == [[H * H - R, H], [-R * H, -R]],
        "det K = r²": K[0][0] * K[1][1] - K[0][1] * K[1][0] == R * R,
        "tr K = (r² - 6r + 1)/4": K[0][0] + K[1][1] == T,
        "t² - 4r² = (r² - 14r + 1)(r + 1)²/16": T * T - 4 * R * R == ROOT_POLY * (R + 1) ** 2 / 16,
        "2r - t = -(r² - 14r + 1)/4": 2 * R - T == -ROOT_POLY / 4,
        "M_cb = [[1, wᵀ], [0, K]] on (q₁ | q₃, q₂)": (Kcb == K and Mcb[0][0] == 1 and Mcb[1][0] == 0
                                                    and Mcb[2][0] == 0 and [Mcb[0][2], Mcb[0][1]] == w),
        "w = (h², h)": w == [H * H, H],
    }
    bad = [k for k, ok in checks.items() if not ok]
    if bad:
        raise ArithmeticError("block identities fail: " + "; ".join(bad))
    return list(checks)


def power(K: list, n: int) -> list:
    """K^n by repeated squaring (exact polynomials in r)."""
    out = [[flint.fmpq_poly([1]), flint.fmpq_poly([0])], [flint.fmpq_poly([0]), flint.fmpq_poly([1])]]
    base = K
    while n:
        if n & 1:
            out = _mul(out, base)
        base = _mul(base, base)
        n >>= 1
    return out


def _mul(A, B):
    return [[A[i][0] * B[0][j] + A[i][1] * B[1][j] for j in range(2)] for i in range(2)]


# ------------------------------------------------------------------ 2. CDKK's point
def check_u_identity(n: int) -> bool:
    """Exact, on the engine's candidate of (ab)^n(cb)^n (all branches at once, modulo cp):
    u(λ - P₂₂²) = P₂₁(q₃(t_{2n}) - P₂₂), P = K^n, and P₂₁ = -rh·s_n with s_n the
    Chebyshev recursion s_1 = 1, s_2 = t, s_{j+1} = t s_j - r² s_{j-1}.  True when both hold."""
    from certify.algebra.poly import FIELD
    from certify.dynamics.words import candidate, reduce_mod

    K, _ = block()
    P = power(K, n)
    s = [flint.fmpq_poly([0]), flint.fmpq_poly([1])]
    for _ in range(n - 1):
        s.append(T * s[-1] - R * R * s[-2])
    if P[1][0] != -R * H * s[n] or P[1][1] != -R * s[n] - R * R * s[n - 1]:
        return False
    c = candidate("ab" * n + "cb" * n)
    lam, rr = FIELD.gens[0], FIELD.gens[1]

    def f(p):
        return sum((FIELD(int(k.p)) / int(k.q) * rr ** i for i, k in enumerate(p.coeffs())), FIELD.zero)

    u, q3 = c.q0[1], c.steps[2 * n - 1].q[2]
    P21, P22 = f(P[1][0]), f(P[1][1])
    return reduce_mod(u * (lam - P22 ** 2) - P21 * (q3 - P22), c.cp) == 0


def upper_end(n: int, prec: int = 128) -> flint.arb:
    """r_n = a - √(a² - 1) = 1/(a + √(a² - 1)), a = 3 + 4cos(π/n): the root in ]0, 1[ of
    r² - (6 + 8cos(π/n))r + 1, where nθ = π (cos θ = t/(2r) = cos(π/n)); a ball."""
    with precision(prec):
        a = 3 + 4 * flint.arb(flint.fmpq(1, n)).cos_pi()
        return 1 / (a + (a * a - 1).sqrt())


# ------------------------------------------------------------------ 4. the lower end
def period_parts(n: int) -> tuple:
    """(P, W): P = K^n and Wᵀ = wᵀ(I + K + … + K^{n-1}) (exact polynomials in r), the two
    pieces of the period matrix: M_ab^n = [[P, 0], [Wᵀ, 1]] on (q₁, q₂ | q₃)."""
    K, w = block()
    P = power(K, n)
    S = [[flint.fmpq_poly([0])] * 2 for _ in range(2)]
    Kj = power(K, 0)
    for _ in range(n):
        S = [[S[i][j] + Kj[i][j] for j in range(2)] for i in range(2)]
        Kj = _mul(Kj, K)
    return P, [w[0] * S[0][j] + w[1] * S[1][j] for j in range(2)]


def period_matrix(n: int) -> list:
    """M = M_cb^n M_ab^n from (P, W), with a, b, c, d = P₁₁, P₁₂, P₂₁, P₂₂:
    row 1 = (a + W₂c + W₁², b + W₂d + W₁W₂, W₁), row 2 = (c(d + W₁), d² + cW₂, c),
    row 3 = (bc + aW₁, bd + aW₂, a)."""
    ((a, b), (c, d)), (W1, W2) = period_parts(n)
    return [[a + W2 * c + W1 * W1, b + W2 * d + W1 * W2, W1],
            [c * (d + W1), d * d + c * W2, c],
            [b * c + a * W1, b * d + a * W2, a]]


def lower_polynomial(n: int):
    """F_n = W₁(a - W₁d + W₂c) + (bc + W₂cd - W₁d²) (a, b, c, d = K^n, W as in
    :func:`period_parts`): D = det[e₁, M e₁, M² e₁] = c (ad - bc) F_n, and D = 0 wherever
    p(0) = (1, 0, 0) lies in an invariant plane of M, in particular where x₊ = 0."""
    ((a, b), (c, d)), (W1, W2) = period_parts(n)
    return W1 * (a - W1 * d + W2 * c) + (b * c + W2 * c * d - W1 * d * d)


def check_lower_identity(n: int) -> bool:
    """Exact: :func:`period_matrix` is the engine's word_matrix((ab)^n(cb)^n), and
    M₂₁(M²)₃₁ - M₃₁(M²)₂₁ = P₂₁ det(P) F_n (polynomials in r)."""
    M = period_matrix(n)
    if M != word_matrix_flint("ab" * n + "cb" * n):
        return False
    M2 = [[sum((M[i][k] * M[k][j] for k in range(3)), flint.fmpq_poly([0])) for j in range(3)] for i in range(3)]
    (a, b), (c, d) = period_parts(n)[0]
    return M[1][0] * M2[2][0] - M[2][0] * M2[1][0] == c * (a * d - b * c) * lower_polynomial(n)


# ------------------------------------------------------------------ 3. the expansion
def _r_of(eps: flint.arb) -> flint.arb:
    a = 3 + 4 * eps.cos_pi()
    return 1 / (a + (a * a - 1).sqrt())


def s_hi(eps: flint.arb) -> flint.arb:
    """s_hi(ε) = n²(r_n - r*) at ε = 1/n, on a ball of ε that may contain 0: from
    r² - (6 + 8cos πε)r + 1 = 0 and r² - 14r + 1 = (r - r*)(r - r**),
    (r - r*)(r** - r) = 16 r sin²(πε/2), so s_hi = 4π² r sinc_π(ε/2)²/(r** - r)."""
    r = _r_of(eps)
    r2 = 7 + 4 * flint.arb(3).sqrt()
    return 4 * flint.arb.pi() ** 2 * r * (eps / 2).sinc_pi() ** 2 / (r2 - r)


def s_star() -> flint.arb:
    """s* = s_hi(0) = π² r*/(2√3) = π²(7√3 - 12)/6."""
    return flint.arb.pi() ** 2 * (7 * flint.arb(3).sqrt() - 12) / 6


def kappa() -> flint.arb:
    """κ in s_hi(ε) = s* + κε² + O(ε⁴): κ = s*π²(3 + 4√3)/48 (from r/(r** - r) =
    r*/(8√3) + r**(r - r*)/192 + … and sinc_π(ε/2)² = 1 - π²ε²/12 + …)."""
    return s_star() * flint.arb.pi() ** 2 * (3 + 4 * flint.arb(3).sqrt()) / 48


def r_of_theta(theta: flint.arb) -> flint.arb:
    """The r in ]r*, 1[ with cos θ = t/(2r): r² - (6 + 8cos θ)r + 1 = 0, r = 1/(a + √(a² - 1))."""
    a = 3 + 4 * theta.cos()
    return 1 / (a + (a * a - 1).sqrt())


def _k_w_n(r: flint.arb) -> tuple:
    """K, w and N = (I - K)^{-1} at r (balls)."""
    h = (1 + r) / 2
    K = [[h * h - r, h], [-r * h, -r]]
    det = (1 - K[0][0]) * (1 - K[1][1]) - K[0][1] * K[1][0]
    N = [[(1 - K[1][1]) / det, K[0][1] / det], [K[1][0] / det, (1 - K[0][0]) / det]]
    return K, [h * h, h], N


def smallness(N1: int) -> tuple[flint.arb, flint.arb]:
    """(δ₁, δ₂) = (N₁ r̄^{N₁-1}, N₁² r̄^{N₁-1}), r̄ = r_{N₁}: bounds of n r^{n-1} and n² r^{n-1}
    for every n ≥ N₁ and r ≤ r_n: both increase with r ≤ r_n ≤ r_{N₁} and decrease in n, as
    (n + 1)² r/n² < 1 there."""
    rbar = upper_end(N1).upper()
    if not (N1 + 1) ** 2 * rbar < N1 ** 2:
        raise ArithmeticError(f"n² r^(n-1) is not proven to decrease from n = {N1}")
    return N1 * rbar ** (N1 - 1), N1 ** 2 * rbar ** (N1 - 1)


def f_hat(eta: flint.arb, eps: flint.arb, N1: int) -> flint.arb:
    """F_n sin θ/(ε r^{n-1}) (the sign of F_n) at r = r(θ), θ = εφ, φ = nθ = π - εη, for every
    n ≥ N₁ with 1/n in ``eps`` (a ball that may contain 0): with s_j = r^{j-1} sin jθ/sin θ,
    K^n = s_n K - r² s_{n-1} I gives a - W₁d + W₂c = (r^{n-1}/sin θ)(A sin φ - rB sin(φ - θ)),
    A = K₁₁ - W₁K₂₂ + W₂K₂₁, B = 1 - W₁, and sin φ = sin εη, sin(φ - θ) = sin ε(η + φ): so
    F̂ = W₁[Aη sinc(εη) - rB(η + φ) sinc(ε(η + φ))] + R.  W = wᵀN - wᵀK^nN, the second term
    in a ball of radius δ₁(w₁ + w₂) max_i Σ_k|N_ki| (|(K^n)_ij| ≤ n r^{n-1}(|K_ij| + r) ≤ n r^{n-1});
    |R| = |bc + W₂cd - W₁d²| sin θ/(ε r^{n-1}) ≤ (1 + |W₁| + |W₂|) π δ₂."""
    d1, d2 = smallness(N1)
    phi = flint.arb.pi() - eps * eta
    r = r_of_theta(eps * phi)
    K, w, N = _k_w_n(r)
    if not max(abs(k) for row in K for k in row) + r < 1:
        raise ArithmeticError("|K_ij| + r < 1 not proven: the bound |(K^n)_ij| ≤ n r^(n-1) needs it")
    spread = d1 * (w[0] + w[1]) * max((N[0][i].abs_upper() + N[1][i].abs_upper()) for i in range(2))
    W = [w[0] * N[0][i] + w[1] * N[1][i] + flint.arb(0, spread.upper()) for i in range(2)]
    A = K[0][0] - W[0] * K[1][1] + W[1] * K[1][0]
    B = 1 - W[0]
    G = A * eta * (eps * eta).sinc() - r * B * (eta + phi) * (eps * (eta + phi)).sinc()
    R = (1 + W[0].abs_upper() + W[1].abs_upper()) * flint.arb.pi() * d2
    return W[0] * G + flint.arb(0, R.upper())


def s_of(eta: flint.arb, eps: flint.arb) -> flint.arb:
    """s = n²(r - r*) at φ = π - εη, θ = εφ: (r - r*)(r** - r) = 16 r sin²(θ/2), so
    s = 4 r φ² sinc(θ/2)²/(r** - r)."""
    phi = flint.arb.pi() - eps * eta
    theta = eps * phi
    r = r_of_theta(theta)
    return 4 * r * phi ** 2 * (theta / 2).sinc() ** 2 / (7 + 4 * flint.arb(3).sqrt() - r)


def _ball(e0, e1) -> flint.arb:
    e0, e1 = flint.fmpq(e0.numerator, e0.denominator), flint.fmpq(e1.numerator, e1.denominator)
    return flint.arb((e0 + e1) / 2, (e1 - e0) / 2)


def lower_strip(e0: Fraction, e1: Fraction, N1: int, pieces: int = 256) -> dict:
    """For ε ∈ [e0, e1] and η ∈ [0, π], cut into ``pieces`` equal η-boxes (η ≤ 4 > π): the sign
    of F̂ on each; the proof needs F̂ < 0 on the first boxes, F̂ > 0 on the last ones, and
    the undecided ones contiguous (the strip [η₋, η₊] holding every zero of F_n between
    r_{n+1} and r_n).  Returns η₋, η₊ (rational) or raises ArithmeticError."""
    eps = _ball(e0, e1)
    cut = [Fraction(4 * k, pieces) for k in range(pieces + 1)]
    signs = []
    for a, b in zip(cut, cut[1:]):
        v = f_hat(_ball(a, b), eps, N1)
        signs.append(-1 if v < 0 else 1 if v > 0 else 0)
    first = next(i for i, sg in enumerate(signs) if sg != -1)
    last = max(i for i, sg in enumerate(signs) if sg != 1)
    if any(sg == -1 for sg in signs[first:]) or any(sg == 1 for sg in signs[:last + 1]):
        raise ArithmeticError(f"F̂ changes sign more than once on ε ∈ [{e0}, {e1}]")
    return {"eps": [e0, e1], "pieces": pieces, "eta": [cut[first], cut[last + 1]]}


def check_lower(facts: dict, prec: int = 200) -> list[str]:
    """Re-verify :func:`prove_lower`'s facts at another precision: the ε-boxes cover
    [0, 1/(N₀ + 1)]; on each, F̂ < 0 on every η-piece inside [0, η₋] and F̂ > 0 on every piece
    inside [η₊, 4]; s at the strip's ends within the stated s_lo interval; η₊ + margin ≤
    π/(1 + ε₁) with margin > 0.  The list of failures (empty: the facts hold)."""
    bad = []
    N1 = facts["N0"] + 1
    rows = facts["boxes"]
    if rows[0]["eps"][0] != 0 or rows[-1]["eps"][1] < Fraction(1, N1) or any(
            a["eps"][1] != b["eps"][0] for a, b in zip(rows, rows[1:])):
        bad.append("the ε-boxes do not cover [0, 1/(N0 + 1)]")
    with precision(prec):
        for row in rows:
            e0, e1 = row["eps"]
            eps = _ball(e0, e1)
            lo_eta, hi_eta = row["eta"]
            cut = [Fraction(4 * k, row["pieces"]) for k in range(row["pieces"] + 1)]
            for a, b in zip(cut, cut[1:]):
                if b <= lo_eta and not f_hat(_ball(a, b), eps, N1) < 0:
                    bad.append(f"F̂ < 0 not proven on η ∈ [{a}, {b}], ε ∈ [{e0}, {e1}]")
                if a >= hi_eta and not f_hat(_ball(a, b), eps, N1) > 0:
                    bad.append(f"F̂ > 0 not proven on η ∈ [{a}, {b}], ε ∈ [{e0}, {e1}]")
            if lo_eta not in cut or hi_eta not in cut:
                bad.append(f"the strip's ends are not piece ends on ε ∈ [{e0}, {e1}]")
            s_hi_end = ends(s_of(_ball(lo_eta, lo_eta), eps))[1]
            s_lo_end = ends(s_of(_ball(hi_eta, hi_eta), eps))[0]
            if not (row["s_lo"][0] <= _q(s_lo_end) and _q(s_hi_end) <= row["s_lo"][1]):
                bad.append(f"s at the strip's ends not in {row['s_lo']} on ε ∈ [{e0}, {e1}]")
            room = flint.arb.pi() / (1 + flint.arb(flint.fmpq(e1.numerator, e1.denominator)))
            m = row["margin"]
            if not (m > 0 and room - flint.arb(flint.fmpq((hi_eta + m).numerator, (hi_eta + m).denominator)) >= 0):
                bad.append(f"η₊ + margin > π/(1 + ε) on ε ∈ [{e0}, {e1}]")
    return bad


def limit_constants() -> dict:
    """The ε → 0 limit, exact in Q(√3) (SymPy, for a reader): at r*, h² = 4r*, wᵀ(I - K)⁻¹ =
    (1/3, 2/3), A = (20√3 - 34)/3, B = 2/3, and F̂(η, 0) = W₁(Aη - r*B(η + π)) vanishes at
    η₀ = πρ, ρ = r*B/(A - r*B) = √3/6; s = s*(1 - εη/π)² + O(ε²) gives s_lo = s* - αε + O(ε²),
    α = 2s*ρ = s*/√3 = π²r*/6, and s_hi = s* + O(ε²): the window's width is αε/n² in r."""
    import sympy as sp
    rs = 7 - 4 * sp.sqrt(3)
    h = (1 + rs) / 2
    K = sp.Matrix([[h ** 2 - rs, h], [-rs * h, -rs]])
    W = sp.Matrix([[h ** 2, h]]) * (sp.eye(2) - K).inv()
    W1, W2 = (sp.radsimp(sp.simplify(e)) for e in W)
    A = sp.radsimp(sp.simplify(K[0, 0] - W1 * K[1, 1] + W2 * K[1, 0]))
    B = 1 - W1
    rho = sp.radsimp(sp.simplify(rs * B / (A - rs * B)))
    s_star_exact = sp.pi ** 2 * (7 * sp.sqrt(3) - 12) / 6
    alpha = sp.radsimp(sp.simplify(2 * s_star_exact * rho))
    return {"W": (W1, W2), "A": A, "B": B, "rho": rho, "eta0": sp.pi * rho, "s_star": s_star_exact,
            "alpha": alpha}


def prove_lower(N0: int = 30, boxes: int = 32, pieces: int = 256, prec: int = 128) -> dict:
    """The lower end for every n > N₀, as rational facts: per ε-box of [0, 1/(N₀ + 1)], the strip
    [η₋, η₊] (F_n < 0 for η < η₋, F_n > 0 for η₊ < η ≤ 4, F̂ as in :func:`f_hat`), the
    enclosure of s at the strip's ends, and the disjointness η₊ < π/(1 + ε₁): the strip lies
    strictly between r_{n+1} (η = π/(1 + ε)) and r_n (η = 0)."""
    N1 = N0 + 1
    with precision(prec):
        cut = [Fraction(k, boxes * N1) for k in range(boxes + 1)]
        rows = []
        for e0, e1 in zip(cut, cut[1:]):
            row = lower_strip(e0, e1, N1, pieces)
            eps = _ball(e0, e1)
            lo = ends(s_of(_ball(row["eta"][1], row["eta"][1]), eps))[0]
            hi = ends(s_of(_ball(row["eta"][0], row["eta"][0]), eps))[1]
            row["s_lo"] = [_q(lo), _q(hi)]
            room = flint.arb.pi() / (1 + flint.arb(flint.fmpq(e1.numerator, e1.denominator)))
            top = row["eta"][1]
            row["margin"] = _q(ends(room - flint.arb(flint.fmpq(top.numerator, top.denominator)))[0])
            if not row["margin"] > 0:
                raise ArithmeticError(f"the strip reaches r_(n+1) on ε ∈ [{e0}, {e1}]")
            rows.append(row)
    return {"N0": N0, "boxes": rows}


# ------------------------------------------------------------------ 7. the dominant branch
R_MAX = flint.fmpq(1, 4)     # part 7 holds for r in ]0, 1/4]: the spectral radius of K is ≤ 1/4 there


def dominant_facts(N1: int, r0: Fraction = Fraction(0), r1: Fraction = Fraction(1, 4)) -> dict:
    """For every n ≥ N₁ and every r ∈ ]r₀, r₁] (by default ]0, 1/4]), with balls over that whole range:

    * the spectral radius of K is ≤ ρ̄ = max(r₁, 1/4) (r ≥ r*: it is r; r < r*: the larger root is
      ≤ t ≤ 1/4), so |s_j| ≤ j ρ̄^{j-1} and |(K^n)_ij| ≤ n ρ̄^{n-1}(|K_ij| + r) ≤ δ = N₁ ρ̄^{N₁-1} max(1, |K_ij| + r);
    * wᵀ(I - K)⁻¹ = (1/3, 2/3) exactly (:func:`check_w_limit`), so W = (1/3, 2/3) + O(δ) and
      M = [[1/9, 2/9, 1/3], [0, 0, 0], [0, 0, 0]] + O(δ) (:func:`period_matrix`'s formula);
    * cp changes sign on [1/9 - ω, 1/9 + ω] (ω = 16δ rounded up): a real eigenvalue λ there; the other two
      have |μ|, |ν| ≤ |S|/2 + √(|S|²/4 + |Π|), S = tr M - λ, Π = det M/λ = r^{4n}/λ, below λ:
      λ is real, simple, positive and strictly dominant;
    * its eigenvector (-1, u, v) (rows 2, 3 by Cramer) has q₃(t_{2n}) = v - W₁ + W₂u and
      P₂₂ = d in balls with q₃(t_{2n}) - d < 0 < λ - d²: by part 2, **u has the sign of s_n**.

    Returns the rational bounds; ArithmeticError when a ball does not decide."""
    rbar = _fmpq(max(r1, Fraction(1, 4)))
    with precision(128):
        r = _ball(r0, r1)                                          # ]r₀, r₁] (and r₀)
        h = (1 + r) / 2
        K, w, N = _k_w_n(r)
        kmax = (max(abs(k) for row in K for k in row) + r).upper()
        if not (N1 + 1) * rbar < N1:
            raise ArithmeticError("n ρ̄^(n-1) is not proven to decrease")
        delta = N1 * flint.arb(rbar) ** (N1 - 1) * (kmax if kmax > 1 else 1)
        small = flint.arb(0, delta.upper())
        width = (16 * delta).upper().mid().fmpq()
        a = b = c = d = small
        spread = delta * (w[0] + w[1]) * max((N[0][i].abs_upper() + N[1][i].abs_upper()) for i in range(2))
        W1 = flint.arb(flint.fmpq(1, 3)) + flint.arb(0, spread.abs_upper())
        W2 = flint.arb(flint.fmpq(2, 3)) + flint.arb(0, spread.abs_upper())
        M = [[a + W2 * c + W1 * W1, b + W2 * d + W1 * W2, W1],
             [c * (d + W1), d * d + c * W2, c],
             [b * c + a * W1, b * d + a * W2, a]]
        det = flint.arb(0, (rbar ** (4 * N1)))                     # det M = r^{4n} ∈ [0, ρ̄^{4N₁}]
        tr = M[0][0] + M[1][1] + M[2][2]
        e2 = sum((M[i][i] * M[j][j] - M[i][j] * M[j][i] for i, j in ((0, 1), (0, 2), (1, 2))), flint.arb(0))

        def cp(t):
            return t ** 3 - tr * t ** 2 + e2 * t - det
        lo, hi = flint.arb(flint.fmpq(1, 9) - width), flint.arb(flint.fmpq(1, 9) + width)
        if not (cp(lo) < 0 and cp(hi) > 0):
            raise ArithmeticError("cp does not change sign around 1/9")
        lam = flint.arb((flint.fmpq(1, 9)), width)
        S, Pi = (tr - lam).abs_upper(), (det / lam).abs_upper()
        others = S / 2 + (S * S / 4 + Pi).sqrt()
        if not others < lam:
            raise ArithmeticError("strict dominance not proven")
        D = (lam - M[1][1]) * (lam - M[2][2]) - M[1][2] * M[2][1]
        u = (-M[1][0] * (lam - M[2][2]) - M[1][2] * M[2][0]) / D
        v = (-M[2][0] * (lam - M[1][1]) - M[2][1] * M[1][0]) / D
        q3 = v - W1 + W2 * u
        if not (q3 - d < 0 and lam - d * d > 0 and h > 0):
            raise ArithmeticError("the hypotheses of part 2 are not proven")
        X = -(d + W1) * (lam - M[2][2]) - (b * c + a * W1)       # u = c X/D: every term of u's numerator has c
        return {"N1": N1, "r": [r0, r1], "delta": _q(ends(delta)[1]),
                "lambda": [_q(ends(lo)[0]), _q(ends(hi)[1])], "others": _q(ends(others)[1]),
                "u": _q(max(abs(e) for e in ends(u))), "Cu": _q(ends(X.abs_upper() / D.abs_lower())[1]),
                "q3_minus_d": _q(ends(q3 - d)[1]), "q3_abs": _q(ends(q3.abs_lower())[0])}


def velocity_facts(N1: int) -> dict:
    """Every velocity condition of w_n holds on ]r*, r_n[ for every n ≥ N₁ ≥ 7 (ball checks over
    r ∈ [7/100, 8/100] ⊃ ]r*, r_7]).  Exactly, with s̃_k = sin kθ/sin θ and y = K^j(-1, u):

        y₁ = -r^{j-1}[K₁₁s̃_j - r s̃_{j-1} - uh s̃_j],   (Ay)₂ = y₂ + hy₁ = -r^{j-1}[rh s̃_{j+1} - u(K₁₁s̃_j - r s̃_{j-1})].

    For nθ ≤ π and 1 ≤ k ≤ n - 1, s̃_k ≥ 1, and K₁₁ sin jθ - r sin(j-1)θ = sin jθ(K₁₁ - r cos θ) +
    r cos jθ sin θ ≥ sin θ(K₁₁ - 2r); |K₁₁s̃_j - r s̃_{j-1}| ≤ n(K₁₁ + r).  Part 7 gives u = cX/D with
    |X|/D ≤ C_u, c = -rh r^{n-1}s̃_n, so u = s̃_n ω, |u| ≤ C_u δ_n, |ω| ≤ rh C_u δ_n/n (δ_n = n4^{1-n},
    r^{n-1} ≤ 4^{1-n}).  Hence before each a (j = 1..n-1): K₁₁ - 2r > hnC_uδ_n; before each b, j ≤ n-2:
    rh > nC_uδ_n(K₁₁ + r), and j = n-1: the bracket is s̃_n(rh - ω(…)) > 0 as δ_nC_u(K₁₁ + r) < 1.
    The cb-phase is the same with (q₃, q₂)(t_{2n}) = |q₃|(-1, u'), u' = q₂(t_{2n})/|q₃| = s̃_n ω',
    q₂(t_{2n}) = -c + du = rh r^{n-1}s̃_n(1 - dX/D): C_u' = rh(1 + δC_u)/|q₃|.  n δ_n decreases."""
    dom = dominant_facts(N1)
    with precision(128):
        if not (flint.arb(flint.fmpq(7, 100)) < 7 - 4 * flint.arb(3).sqrt() and upper_end(7) < flint.fmpq(8, 100)):
            raise ArithmeticError("[7/100, 8/100] does not cover ]r*, r_7]")
        margins: dict = {}
        for k in range(16):                                        # 16 r-boxes of [7/100, 8/100]
            r = flint.arb(flint.fmpq(7, 100) + flint.fmpq(2 * k + 1, 3200), flint.fmpq(1, 3200))
            for name, m in _velocity_margins(r, dom, N1).items():
                margins[name] = m if name not in margins else margins[name].min(m)
        bad = [k for k, m in margins.items() if not m > 0]
        if bad:
            raise ArithmeticError("velocity margins not proven: " + ", ".join(bad))
        return {"N1": N1, "r": [Fraction(7, 100), Fraction(8, 100)],
                "margins": {k: _q(ends(m)[0]) for k, m in margins.items()}}


def _velocity_margins(r: flint.arb, dom: dict, N1: int) -> dict:
    """The six margins of :func:`velocity_facts` on a ball of r: with |u| ≤ C δ_n and |ω| n ≤ rh Ω δ_n
    (ab: C = Ω = C_u; cb: Ω = (1 + δC_u)/|q₃|, C = rhΩ) and n δ_n ≤ N₁ δ (δ = δ_{N₁})."""
    def rat(x):
        return flint.arb(flint.fmpq(x.numerator, x.denominator))
    h = (1 + r) / 2
    K11 = h * h - r
    delta, Cu, Q3 = rat(dom["delta"]), rat(dom["Cu"]), rat(dom["q3_abs"])
    dn = N1 * delta
    Om = (1 + delta * Cu) / Q3
    margins = {}
    for name, C, Omega in (("ab", Cu, Cu), ("cb", r * h * Om, Om)):
        margins[f"{name}: before a/c"] = K11 - 2 * r - h * dn * C
        margins[f"{name}: before b, j < n - 1"] = r * h - dn * C * (K11 + r)
        margins[f"{name}: before b, j = n - 1"] = 1 - delta * Omega * (K11 + r)
    return margins


# ------------------------------------------------------------------ 9. the positions, inside and below
GRADED_VARS = ("z", "y", "A", "B", "C", "D")


@functools.cache
def graded_quantities() -> dict:
    """The quantities deciding the positions' conditions, as exact polynomials over Q in
    (z, y, A, B, C, D), where K^n = z·[[A, B], [C, D]] (z = r^(n-1), so A, B, C, D are O(1) in the
    blow-up) and λ = 1/9 + zλ₁ + z²λ₂ + z³y (λ₁, λ₂ polynomials in A..D from cp(λ) = 0, y the rest):
    W = w̄(I - K^n) with w̄ = wᵀ(I - K)⁻¹ = (1/3, 2/3) (:func:`check_w_limit`), M as in
    :func:`period_matrix`, e₁, e₂, e₃ its symmetric functions (e₃ = (ad - bc)² is checked), and

    * ``lambda`` = λ itself, ``G`` = cp(λ)/z³ (its root in y is λ's), ``X`` = -(d + W₁)(λ - a) - (bc + aW₁) (u = cX/Δ),
      ``Delta`` = Δ = (λ - M₂₂)(λ - a) - cM₃₂, ``Dmix`` = Δ - dX;
    * ``E`` = (W₁X + Δ)/z: the coefficient of p₃(0) in p₁(T) is Q₁₂ = W₁ + Δ/X = zE/X;
    * ``Y`` = (M₃₁X + (d + W₁)(M₃₁(λ - M₂₂) + M₃₂M₂₁))/(z³(AD - BC)) (λ cancels, and the division by
      AD - BC = det(K^n)/z² is exact): the coefficient of p₁(0) in p₃(T) is Q₂₁ = r^{2n} zY/X;
    * ``S`` = (e₁ - λ)/z²: μ + ν = tr M - λ = z²S (μν = e₃/λ);
    * ``Z`` = (W₁(Δ - dX) + q₃(t_{2n})Δ)/z: p₃(t_{2n}) = x + zZ/(Δ - dX);
    * ``F`` = F_n/z (part 4's polynomial, λ-free).

    Every division by a power of z is exact (checked: the lower coefficients vanish identically)."""
    ctx = flint.fmpq_mpoly_ctx.get(GRADED_VARS, "lex")
    z, y, A, B, C, D = ctx.gens()
    third = flint.fmpq(1, 3)
    a, b, c, d = z * A, z * B, z * C, z * D
    W1, W2 = third - third * a - 2 * third * c, 2 * third - third * b - 2 * third * d
    M = [[a + W2 * c + W1 * W1, b + W2 * d + W1 * W2, W1],
         [c * (d + W1), d * d + c * W2, c],
         [b * c + a * W1, b * d + a * W2, a]]
    e1 = M[0][0] + M[1][1] + M[2][2]
    e2 = sum((M[i][i] * M[j][j] - M[i][j] * M[j][i] for i, j in ((0, 1), (0, 2), (1, 2))), ctx.from_dict({}))
    e3 = (a * d - b * c) ** 2
    det = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
           + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]))
    if det != e3:
        raise ArithmeticError("det M ≠ (ad - bc)²")

    def cp(t):
        return t ** 3 - e1 * t ** 2 + e2 * t - e3
    lam = ctx.from_dict({}) + flint.fmpq(1, 9)
    for k in (1, 2):                                   # cp'(1/9) = 1/81 at z = 0
        lam = lam - 81 * _z_part(cp(lam), k) * z ** k
    lam = lam + z ** 3 * y
    X = -(d + W1) * (lam - a) - (b * c + a * W1)
    Delta = (lam - M[1][1]) * (lam - a) - c * M[2][1]
    N31 = M[2][0] * (lam - M[1][1]) + M[2][1] * M[1][0]
    q3Delta = -N31 - W1 * Delta + W2 * c * X           # q₃(t_2n)Δ = (v - W₁ + W₂u)Δ
    out = {"G": (cp(lam), 3), "X": (X, 0), "Delta": (Delta, 0), "Dmix": (Delta - d * X, 0),
           "E": (W1 * X + Delta, 1), "Y": (M[2][0] * X + (d + W1) * N31, 3), "S": (e1 - lam, 2),
           "Z": (W1 * (Delta - d * X) + q3Delta, 1),
           "F": (W1 * (a - W1 * d + W2 * c) + (b * c + W2 * c * d - W1 * d * d), 1)}
    qs = {"lambda": lam} | {name: _divide_z(p, k, name) for name, (p, k) in out.items()}
    qs["Y"], rest = divmod(qs["Y"], A * D - B * C)
    if rest != 0:
        raise ArithmeticError("Y is not divisible by AD - BC")
    return qs


def _z_part(p, k: int):
    """The coefficient of z^k in p (a polynomial in the other variables)."""
    ctx = p.context()
    return ctx.from_dict({(0,) + e[1:]: v for e, v in p.to_dict().items() if e[0] == k})


def _divide_z(p, k: int, name: str):
    """p/z^k, exact: ArithmeticError if a term of degree < k in z is left."""
    if any(e[0] < k for e in p.to_dict()):
        raise ArithmeticError(f"{name} is not divisible by z^{k}")
    return p.context().from_dict({(e[0] - k,) + e[1:]: v for e, v in p.to_dict().items()})


def _evaluate(p, values: list) -> flint.arb:
    """p at balls (one per variable of GRADED_VARS), term by term with a table of powers."""
    degs = p.degrees()
    powers = []
    for v, m in zip(values, degs):
        row = [flint.arb(1)]
        for _ in range(m):
            row.append(row[-1] * v)
        powers.append(row)
    total = flint.arb(0)
    for e, coeff in p.to_dict().items():
        term = flint.arb(coeff)
        for i, k in enumerate(e):
            if k:
                term *= powers[i][k]
        total += term
    return total


def _blowup_entries(eta: flint.arb, eps: flint.arb) -> tuple[flint.arb, list]:
    """(r, [A, B, C, D]) at φ = nθ = π - εη, θ = εφ: K^n = r^(n-1)(s̃_n K - r s̃_(n-1) I) with
    s̃_n = sin εη/sin θ and s̃_(n-1) = sin ε(η + φ)/sin θ (both written with sinc: no 0/0 at ε = 0)."""
    phi = flint.arb.pi() - eps * eta
    r = r_of_theta(eps * phi)
    den = phi * (eps * phi).sinc()
    sn = eta * (eps * eta).sinc() / den
    sn1 = (eta + phi) * (eps * (eta + phi)).sinc() / den
    h = (1 + r) / 2
    K = [[h * h - r, h], [-r * h, -r]]
    return r, [sn * K[0][0] - r * sn1, sn * K[0][1], sn * K[1][0], sn * K[1][1] - r * sn1]


def _lambda_rest(entries: list, z: flint.arb) -> flint.arb:
    """A ball holding y, where λ = 1/9 + zλ₁ + z²λ₂ + z³y is the root of cp near 1/9 (the dominant
    eigenvalue of part 7): G = cp(λ)/z³ has slope 1/81 + O(z) in y and changes sign on it."""
    G = graded_quantities()["G"]
    g0 = _evaluate(G, [z, flint.arb(0)] + entries)
    R = 200 * g0.abs_upper() + 1
    lo, hi = (_evaluate(G, [z, flint.arb(x)] + entries) for x in (-R, R))
    if not (lo < 0 < hi):
        raise ArithmeticError("λ's rest y is not enclosed")
    return flint.arb(0, R)


def position_signs(eta: flint.arb, eps: flint.arb, N1: int) -> dict:
    """The balls of :func:`graded_quantities` (X, Δ, Δ - dX, E, Y, S, Z) for every n ≥ N₁ with 1/n
    in ``eps`` and r at η in ``eta`` of the blow-up, z = r^(n-1) in [0, r_{N₁}^(N₁-1)]."""
    r, entries = _blowup_entries(eta, eps)
    zmax = upper_end(N1).upper() ** (N1 - 1)
    z = flint.arb(zmax / 2, zmax / 2)
    y = _lambda_rest(entries, z)
    return {name: _evaluate(p, [z, y] + entries) for name, p in graded_quantities().items()
            if name not in ("G", "lambda")}


INSIDE = {"X": -1, "Delta": 1, "Dmix": 1, "E": -1, "Y": -1, "S": 1, "Z": 1, "F": -1}
BELOW = {"X": -1, "Delta": 1, "E": 1, "Y": 1, "S": 1, "F": 1}             # F: F_n ≠ 0 there too


def position_label(eta: flint.arb, eps: flint.arb, N1: int) -> str:
    """'inside' when every sign of :data:`INSIDE` is proved on the box (then Q₁₂, Q₂₁ > 0, μ + ν > 0
    and p₃(t_{2n}) > x: the positive fixed point is attracting with p₁(T) > 0 and p₃(t_{2n}) > 0),
    'below' when those of :data:`BELOW` are (Q₁₂, Q₂₁ < 0, μ + ν > 0: no fixed point with x > 0 is
    attracting with p₁(T) > 0), else '?'."""
    v = position_signs(eta, eps, N1)

    def holds(signs):
        return all((v[k] < 0) if sg < 0 else (v[k] > 0) for k, sg in signs.items())
    return "inside" if holds(INSIDE) else "below" if holds(BELOW) else "?"


def position_strip(e0: Fraction, e1: Fraction, N1: int, start: int = 32, depth: int = 5) -> dict:
    """On ε ∈ [e0, e1]: [0, 4] cut into ``start`` pieces, each undecided piece halved up to ``depth``
    times; the pieces labelled 'inside' must be the first ones and those labelled 'below' the last
    ones, one undecided strip [η_in, η_out] between.  Returns the labelled pieces."""
    eps = _ball(e0, e1)
    todo = [(Fraction(4 * k, start), Fraction(4 * (k + 1), start), 0) for k in range(start)]
    pieces = []
    while todo:
        a, b, level = todo.pop(0)
        label = position_label(_ball(a, b), eps, N1)
        if label == "?" and level < depth:
            m = (a + b) / 2
            todo[:0] = [(a, m, level + 1), (m, b, level + 1)]
        else:
            pieces.append([a, b, label])
    labels = "".join({"inside": "i", "below": "b", "?": "?"}[p[2]] for p in pieces)
    if not (labels.startswith("i") and labels.endswith("b")) or labels.strip("i").strip("?").strip("b"):
        raise ArithmeticError(f"the positions are not decided as inside | strip | below on ε ∈ [{e0}, {e1}]: {labels}")
    undecided = [p for p in pieces if p[2] == "?"]
    strip = [undecided[0][0], undecided[-1][1]] if undecided else [pieces[labels.rfind("i")][1]] * 2
    row = {"eps": [e0, e1], "pieces": [p for p in pieces if p[2] != "?"], "strip": strip}
    row["thin"] = _round_up(thin_strip(row, N1))
    return row


def _round_up(x: Fraction) -> Fraction:
    """A rational with 3 significant digits at least 1.01 x (room for the re-check at another precision)."""
    e = 0
    while x * 10 ** e < 100:
        e += 1
    return Fraction(math.ceil(x * Fraction(101, 100) * 10 ** e), 10 ** e)


def _sinc_series(u0: flint.arb, scale: flint.arb) -> flint.arb_series:
    """sinc(u0 + scale·t) to first order in t, for |u0| ≤ 1: sinc'(u) = -u j(u), j(u) = (sin u - u cos u)/u³
    = 1/3 - u²/30 + u⁴/840 - … ∈ [1/3 - u²/30, 1/3] (an alternating series with decreasing terms)."""
    U = u0.abs_upper()
    if not U <= 1:
        raise ArithmeticError("sinc's slope bound needs |u| ≤ 1")
    j = flint.arb(flint.fmpq(1, 3)) - U * U / 60 + flint.arb(0, (U * U / 60).upper())
    return flint.arb_series([u0.sinc(), -u0 * j * scale], prec=2)


def _blowup_series(eta: flint.arb, eps: flint.arb) -> tuple:
    """(r, [A, B, C, D]) of :func:`_blowup_entries` as first-order series in η at the ball ``eta`` (ε fixed):
    the values and their η-derivatives (r = r(θ) through cos and √, the sinc's by :func:`_sinc_series`)."""
    t = flint.arb_series([eta, 1], prec=2)
    phi = flint.arb.pi() - eps * t
    theta = eps * phi
    a = 3 + 4 * theta.cos()
    r = 1 / (a + (a * a - 1).sqrt())
    phi0 = flint.arb.pi() - eps * eta
    den = phi * _sinc_series(eps * phi0, -eps * eps)
    sn = t * _sinc_series(eps * eta, eps) / den
    sn1 = (phi + t) * _sinc_series(eps * (phi0 + eta), eps * (1 - eps)) / den
    h = (1 + r) / 2
    K = [[h * h - r, h], [-r * h, -r]]
    return r, [sn * K[0][0] - r * sn1, sn * K[0][1], sn * K[1][0], sn * K[1][1] - r * sn1]


def l_slope(eta: flint.arb, eps: flint.arb) -> flint.arb:
    """dL/dη on a box, L = 3A + 2C - D = s̃_n(3K₁₁ + 2K₂₁ - K₂₂) - 2r s̃_(n-1) in the blow-up of
    :func:`_blowup_entries` (first-order series in η, :func:`_blowup_series`)."""
    _, (A, _, C, D) = _blowup_series(eta, eps)
    return (3 * A + 2 * C - D).coeffs()[1]


@functools.cache
def _rests() -> dict:
    """(E - L/27)/z, (Y - L/9)/z, (Z + L/81)/z, (F - L/9)/z with their weights 27, 9, 81, 9:
    E = (L + 27z·rest)/27, Y = (L + 9z·rest)/9, Z = -(L - 81z·rest)/81, F = (L + 9z·rest)/9."""
    qs = graded_quantities()
    ctx = qs["E"].context()
    _, _, A, B, C, D = ctx.gens()
    L = 3 * A + 2 * C - D
    return {"E": (_divide_z(qs["E"] - L / 27, 1, "E"), 27), "Y": (_divide_z(qs["Y"] - L / 9, 1, "Y"), 9),
            "Z": (_divide_z(qs["Z"] + L / 81, 1, "Z"), 81), "F": (_divide_z(qs["F"] - L / 9, 1, "F"), 9)}


def thin_strip(row: dict, N1: int, pieces: int = 8) -> Fraction:
    """On the ε-box and strip [η_in, η_out] of a :func:`position_strip` row: L is increasing (dL/dη ≥ m > 0)
    and |weight·rest| ≤ B for E, Y, Z, F, while X < 0 < Δ, Δ - dX and S > 0 hold; so 'inside' holds
    wherever L < -τ and 'below' wherever L > τ, τ = B r_{N₁}^(N₁-1), F_n ≠ 0 wherever |L| > τ, and the
    undecided set and every zero of F_n in the strip are inside one interval of η-length ≤ 2τ/m.
    Returns that bound (rational), ArithmeticError if a ball does not decide."""
    eps = _ball(*row["eps"])
    a, b = row["strip"]
    cut = [a + (b - a) * k / pieces for k in range(pieces + 1)]
    zmax = upper_end(N1).upper() ** (N1 - 1)
    z = flint.arb(zmax / 2, zmax / 2)
    m, B = None, flint.arb(0)
    for e0, e1 in zip(cut, cut[1:]):
        eta = _ball(e0, e1)
        slope = l_slope(eta, eps)
        if not slope > 0:
            raise ArithmeticError(f"dL/dη > 0 not proven on η ∈ [{e0}, {e1}]")
        m = slope if m is None else m.min(slope)
        _, entries = _blowup_entries(eta, eps)
        y = _lambda_rest(entries, z)
        v = position_signs(eta, eps, N1)
        if not (v["X"] < 0 and v["Delta"] > 0 and v["Dmix"] > 0 and v["S"] > 0):
            raise ArithmeticError(f"X < 0 < Δ, Δ - dX, S not proven on η ∈ [{e0}, {e1}]")
        for rest, weight in _rests().values():
            B = B.max(weight * _evaluate(rest, [z, y] + entries).abs_upper())
    width = 2 * B * zmax / m.lower()
    return _q(ends(width)[1])


def f_slope(row: dict, N1: int, pieces: int = 8) -> Fraction:
    """On the ε-box and strip [η_in, η_out] of a :func:`position_strip` row, for every n ≥ N₁: F = F_n/z =
    L/9 + zR_F (R_F the exact rest of :func:`_rests`, free of λ) is strictly increasing in η,

        dF/dη = L'/9 + z Σ_v ∂R_F/∂v · v' + z'(R_F + z ∂R_F/∂z)  (v = A, B, C, D),

    with L' ≥ m (:func:`l_slope`), v' from :func:`_blowup_series`, z ∈ [0, r_{N₁}^(N₁-1)] and |z'| =
    z(n - 1)|dr/dη|/r ≤ z ε|dr/dθ|/r (dθ/dη = -ε², (n - 1)ε² ≤ ε).  So F_n has exactly one zero in the strip
    (it changes sign there: part 9).  Returns a rational lower bound of dF/dη on the strip; ArithmeticError
    if a ball does not decide."""
    eps = _ball(*row["eps"])
    a, b = row["strip"]
    cut = [a + (b - a) * k / pieces for k in range(pieces + 1)]
    zmax = upper_end(N1).upper() ** (N1 - 1)
    z = flint.arb(zmax / 2, zmax / 2)
    rest = _rests()["F"][0]
    if rest.degrees()[GRADED_VARS.index("y")] != 0:
        raise ArithmeticError("F's rest depends on λ")
    low = None
    for e0, e1 in zip(cut, cut[1:]):
        eta = _ball(e0, e1)
        r, series = _blowup_series(eta, eps)
        entries = [v.coeffs()[0] for v in series]
        values = [z, flint.arb(0)] + entries
        theta = flint.arb_series([(eps * (flint.arb.pi() - eps * eta)), 1], prec=2)
        ca = 3 + 4 * theta.cos()
        drdtheta = (1 / (ca + (ca * ca - 1).sqrt())).coeffs()[1]
        r0 = r.coeffs()[0]
        zdot = flint.arb(0, (zmax * eps.abs_upper() * drdtheta.abs_upper() / r0.abs_lower()).upper())
        slope = l_slope(eta, eps) / 9 + zdot * (_evaluate(rest, values)
                                                + z * _evaluate(rest.derivative("z"), values))
        for i, v in enumerate(series):
            slope += z * _evaluate(rest.derivative("ABCD"[i]), values) * v.coeffs()[1]
        if not slope > 0:
            raise ArithmeticError(f"dF/dη > 0 not proven on η ∈ [{e0}, {e1}]")
        low = slope if low is None else low.min(slope)
    return _round_down(_q(ends(low)[0]))


def _round_down(x: Fraction) -> Fraction:
    """A rational with 3 significant digits at most 0.99 x, for x > 0 (room for the re-check)."""
    e = 0
    while x * 10 ** e < 100:
        e += 1
    return Fraction(math.floor(x * Fraction(99, 100) * 10 ** e), 10 ** e)


def one_zero_facts(positions: dict, prec: int = 128) -> dict:
    """:func:`f_slope` on every strip of :func:`position_facts`: for every n ≥ N₁, F_n has exactly one zero
    in the strip, ℓ_n (with part 12: the stable set in ]0, 1[ is exactly ]ℓ_n, r_n[)."""
    N1 = positions["N1"]
    with precision(prec):
        return {"N1": N1, "boxes": [{"eps": row["eps"], "strip": row["strip"], "slope": f_slope(row, N1)}
                                    for row in positions["boxes"]]}


def check_one_zero(facts: dict, positions: dict | None = None, prec: int = 200) -> list[str]:
    """Recompute each strip's slope bound (at ``prec`` bits): it must be positive and at most the recomputed
    one; with the positions' facts, the strips must be theirs.  The list of failures."""
    with precision(prec):
        return _check_one_zero(facts, positions)


def _check_one_zero(facts: dict, positions: dict | None) -> list[str]:
    bad = []
    if positions is not None and [[b["eps"], b["strip"]] for b in facts["boxes"]] != [
            [row["eps"], row["strip"]] for row in positions["boxes"]]:
        bad.append("the strips of part 12 are not part 9's")
    for row in facts["boxes"]:
        try:
            new = f_slope(row, facts["N1"])
        except ArithmeticError as e:
            bad.append(f"one zero of F_n not proven on ε ∈ {row['eps']}: {e}")
            continue
        if not 0 < row["slope"] <= new:
            bad.append(f"dF/dη ≥ {row['slope']} on ε ∈ {row['eps']} not implied")
    return bad


def position_facts(N1: int, boxes: int = 32, prec: int = 128) -> dict:
    """For every n ≥ N₁ (≥ 7, for part 7), per ε-box of [0, 1/N₁]: the η-pieces of the blow-up where
    the positions' conditions all hold ('inside', from η = 0) and where they fail ('below', up to
    η = 4 > π/(1 + ε), i.e. down to r_{n+1}), the strip between them, and ``thin``: a bound of the
    η-length of the one interval of that strip where neither is proved (:func:`thin_strip`)."""
    if N1 < 7:
        raise ArithmeticError("part 9 needs part 7 (n ≥ 7)")
    with precision(prec):
        cut = [Fraction(k, boxes * N1) for k in range(boxes + 1)]
        return {"N1": N1, "boxes": [position_strip(e0, e1, N1) for e0, e1 in zip(cut, cut[1:])]}


def check_positions(facts: dict, prec: int = 200) -> list[str]:
    """Re-verify :func:`position_facts`: the ε-boxes cover [0, 1/N₁]; on each, the stated pieces with
    the undecided strip tile [0, 4] in order (inside pieces, strip, below pieces), every piece's
    label is recomputed at ``prec`` bits, and the strip's undecided interval (:func:`thin_strip`) is
    at most the stated width.  The list of failures."""
    bad = []
    N1, rows = facts["N1"], facts["boxes"]
    if N1 < 7:
        bad.append("part 9 needs n ≥ 7")
    if rows[0]["eps"][0] != 0 or rows[-1]["eps"][1] < Fraction(1, N1) or any(
            a["eps"][1] != b["eps"][0] for a, b in zip(rows, rows[1:])):
        bad.append("the ε-boxes do not cover [0, 1/N1]")
    with precision(prec):
        for row in rows:
            e0, e1 = row["eps"]
            inside = [p for p in row["pieces"] if p[2] == "inside"]
            below = [p for p in row["pieces"] if p[2] == "below"]
            ends_ = [(Fraction(0), row["strip"][0])] if not inside else []
            tiles = [(p[0], p[1]) for p in inside] + [tuple(row["strip"])] + [(p[0], p[1]) for p in below]
            if (inside + below != row["pieces"] or ends_ or tiles[0][0] != 0 or tiles[-1][1] != 4
                    or any(s[1] != t[0] for s, t in zip(tiles, tiles[1:]))):
                bad.append(f"the pieces do not tile [0, 4] as inside | strip | below on ε ∈ [{e0}, {e1}]")
                continue
            eps = _ball(e0, e1)
            for a, b, label in row["pieces"]:
                if position_label(_ball(a, b), eps, N1) != label:
                    bad.append(f"'{label}' not proven on η ∈ [{a}, {b}], ε ∈ [{e0}, {e1}]")
            try:
                if not thin_strip(row, N1) <= row["thin"]:
                    bad.append(f"the undecided interval is not proven ≤ {row['thin']} wide on ε ∈ [{e0}, {e1}]")
            except ArithmeticError as e:
                bad.append(f"the strip is not proven thin on ε ∈ [{e0}, {e1}]: {e}")
    return bad


def _far_entries(psi: flint.arb, rho: flint.arb, N1: int) -> tuple[flint.arb, list, flint.arb]:
    """Below r_{n+1}, the chart ψ = π - φ ∈ [0, π], ρ = 1/η ∈ [0, 1/4] (η ≥ 4), ε = ρψ: (ε, [A, B, C, D],
    z-range) with K^n = (r^(n-1)/ρ)·[[A, B], [C, D]], i.e. the entries ρ(s̃_n K - r s̃_(n-1) I):
    ρ s̃_n = sin ψ/(ψ φ sinc θ) and ρ s̃_(n-1) = (1 + ρφ) sin(ψ + θ)/((ψ + θ) φ sinc θ), θ = εφ, each written
    with sinc at the end of [0, π] the box is near; z = η r^(n-1) ≤ π n r^(n-1) ≤ π N₁ r_{N₁}^(N₁-1)."""
    phi = flint.arb.pi() - psi
    lo, hi = ends(rho * psi)
    eps = _ball(_q(max(lo, flint.fmpq(0))), _q(min(hi, flint.fmpq(1, N1))))      # ε = ρψ ≤ 1/N₁
    theta = eps * phi
    r = r_of_theta(theta)
    if psi.upper() < 2:
        sn = psi.sinc() / (phi * theta.sinc())
        sn1 = (1 + rho * phi) * (psi + theta).sinc() / (phi * theta.sinc())
    else:
        sn = phi.sinc() / (psi * theta.sinc())
        sn1 = (1 + rho * phi) * (1 - eps) * (phi - theta).sinc() / ((psi + theta) * theta.sinc())
    h = (1 + r) / 2
    K = [[h * h - r, h], [-r * h, -r]]
    zmax = flint.arb.pi() * smallness(N1)[0]
    return eps, [sn * K[0][0] - r * sn1, sn * K[0][1], sn * K[1][0], sn * K[1][1] - r * sn1], zmax



def _below_holds(entries: list, zmax: flint.arb) -> bool:
    """True when :data:`BELOW`'s signs are proved for K^n = z·[[A, B], [C, D]], z ∈ [0, zmax]."""
    z = flint.arb(zmax.upper() / 2, zmax.upper() / 2)
    y = _lambda_rest(entries, z)
    qs = graded_quantities()
    return all((_evaluate(qs[k], [z, y] + entries) < 0) if sg < 0 else (_evaluate(qs[k], [z, y] + entries) > 0)
               for k, sg in BELOW.items())


def far_holds(box: list, N1: int) -> bool | None:
    """The box [w₀, w₁] × [ρ₀, ρ₁] of the chart ψ = πw, ρ = 1/η (:func:`_far_entries`): None when no n ≥ N₁
    has a point there (ρ₀ψ₀ > 1/N₁), else whether 'below' is proved on it."""
    (w0, w1), (r0, r1) = box
    if flint.arb(flint.fmpq((r0 * w0).numerator, (r0 * w0).denominator)) * flint.arb.pi() > flint.fmpq(1, N1):
        return None
    _, entries, zmax = _far_entries(flint.arb.pi() * _ball(w0, w1), _ball(r0, r1), N1)
    return _below_holds(entries, zmax)


def _low_entries(r: flint.arb, N1: int) -> tuple[list, flint.arb]:
    """Below r* (K has real eigenvalues κ₁ ≥ κ₂ > 0, κ₁ ≤ 1/4): K^n = s_n(K - r²(s_(n-1)/s_n) I) with
    s_(n-1)/s_n = β/κ₁, β = (1 - g^(n-1))/(1 - g^n) ∈ [(N₁ - 1)/N₁, 1] (g = κ₂/κ₁ ∈ [0, 1]: the mean of
    g⁰..g^(n-2) is at least that of g⁰..g^(n-1)), and 0 < s_n ≤ n κ₁^(n-1) ≤ N₁ 4^(1-N₁).  ([A, B, C, D], z-range);
    the discriminant (r* - r)(r** - r)(r + 1)²/16 ≥ 0 is clamped at 0 (a ball reaching past r*)."""
    t = (r * r - 6 * r + 1) / 4
    disc = (7 - 4 * flint.arb(3).sqrt() - r) * (7 + 4 * flint.arb(3).sqrt() - r) * (r + 1) ** 2 / 16
    lo, hi = ends(disc)
    root = disc.sqrt() if lo > 0 else flint.arb(0, flint.arb(hi).sqrt().upper())    # √[0, hi] ⊂ [0, √hi]
    k1 = (t + root) / 2
    beta = _ball(Fraction(N1 - 1, N1), Fraction(1))
    h = (1 + r) / 2
    K = [[h * h - r, h], [-r * h, -r]]
    m = r * r * beta / k1
    return [K[0][0] - m, K[0][1], K[1][0], K[1][1] - m], N1 * flint.arb(flint.fmpq(1, 4)) ** (N1 - 1)


def low_holds(box: list, N1: int) -> bool:
    """Whether 'below' is proved for every r in the box [r₀, r₁] ∩ ]0, r*] (:func:`_low_entries`)."""
    (r0, r1), = box
    entries, zmax = _low_entries(_ball(r0, r1), N1)
    return _below_holds(entries, zmax)


def _leaves(box: list, holds, depth: int) -> list:
    """Cut ``box`` (a list of rational [lo, hi] sides) in halves along every side until ``holds`` is True
    or None on each piece, at most ``depth`` times; ArithmeticError if a piece stays undecided."""
    try:
        ok = holds(box)
    except ArithmeticError:              # λ not enclosed on a box this wide: halve it
        ok = False
    if ok is None or ok:
        return [[list(side) for side in box] + ["none" if ok is None else "below"]]
    if depth == 0:
        raise ArithmeticError(f"'below' not proven on {box}")
    halves = [[(a, (a + b) / 2), ((a + b) / 2, b)] for a, b in box]
    out: list = []
    for combo in itertools.product(*halves):
        out += _leaves(list(combo), holds, depth - 1)
    return out


FAR_GRID = ([Fraction(k, 8) for k in range(9)], [Fraction(k, 32) for k in range(9)])   # w = ψ/π, ρ = 1/η
LOW_GRID = [Fraction(0), Fraction(7, 200), Fraction(7, 100), Fraction(72, 1000)]       # ]0, r*], r* < 0.0718


def below_facts(N1: int, depth: int = 6) -> dict:
    """Every r in ]0, r_{n+1}] is not stable, for every n ≥ N₁ (≥ 7): the leaves of the two charts,
    (ψ/π, 1/η) ∈ [0, 1] × [0, 1/4] (]r*, r_{n+1}], η ≥ 4) and r ∈ ]0, 72/1000] ∩ ]0, r*], each labelled
    'below' (proved) or 'none' (no n ≥ N₁ there)."""
    if N1 < 7:
        raise ArithmeticError("part 9 needs part 7 (n ≥ 7)")
    with precision(128):
        ws, rs = FAR_GRID
        far = []
        for w in zip(ws, ws[1:]):
            for rr in zip(rs, rs[1:]):
                far += _leaves([w, rr], lambda b: far_holds(b, N1), depth)
        low = []
        for rr in zip(LOW_GRID, LOW_GRID[1:]):
            low += _leaves([rr], lambda b: low_holds(b, N1), depth)
    return {"N1": N1, "far": far, "low": low}


def _tiles(leaves: list, outer: list) -> bool:
    """Whether the boxes tile ``outer``: inside it, pairwise without common interior, total volume equal."""
    def vol(b):
        out = Fraction(1)
        for a, c in b:
            out *= c - a
        return out
    boxes = [leaf[:-1] for leaf in leaves]
    if any(not all(o[0] <= a < c <= o[1] for (a, c), o in zip(b, outer)) for b in boxes):
        return False
    for i, b in enumerate(boxes):
        for d in boxes[i + 1:]:
            if all(a < f and e < c for (a, c), (e, f) in zip(b, d)):
                return False
    return sum(map(vol, boxes)) == vol(outer)


def check_below(facts: dict, prec: int = 200) -> list[str]:
    """Re-verify :func:`below_facts` at ``prec`` bits: the leaves tile each chart, and every leaf's label
    is recomputed ('none': ρ₀ψ₀ > 1/N₁).  The list of failures."""
    bad = []
    N1 = facts["N1"]
    ws, rs = FAR_GRID
    if N1 < 7:
        bad.append("part 9 needs n ≥ 7")
    if not _tiles(facts["far"], [[ws[0], ws[-1]], [rs[0], rs[-1]]]):
        bad.append("the far chart's leaves do not tile [0, 1] × [0, 1/4]")
    if not _tiles(facts["low"], [[LOW_GRID[0], LOW_GRID[-1]]]) or not (
            flint.arb(flint.fmpq(LOW_GRID[-1].numerator, LOW_GRID[-1].denominator)) > 7 - 4 * flint.arb(3).sqrt()):
        bad.append("the low chart's leaves do not tile ]0, r*]")
    with precision(prec):
        for leaf in facts["far"]:
            if {True: "below", None: "none", False: "?"}[far_holds(leaf[:-1], N1)] != leaf[-1]:
                bad.append(f"'{leaf[-1]}' not proven on the far box {leaf[:-1]}")
        for leaf in facts["low"]:
            if not (leaf[-1] == "below" and low_holds(leaf[:-1], N1)):
                bad.append(f"'{leaf[-1]}' not proven on the low box {leaf[:-1]}")
    return bad

# ------------------------------------------------------------------ 10. above r_n
UPPER_STEP = Fraction(1, 8)     # the boxes of ]1/4, R] on which part 7's dominance is re-proved


def upper_boxes(N1: int) -> list:
    """The boxes [1/4 + k/8, 1/4 + (k + 1)/8] on which :func:`dominant_facts` holds for N₁, from 1/4 up to
    the first that fails (or 7/8): the range ]1/4, R] where parts 7 and 10 extend."""
    boxes: list = []
    a = Fraction(1, 4)
    while a < Fraction(7, 8):
        try:
            dominant_facts(N1, a, a + UPPER_STEP)
        except ArithmeticError:
            break
        boxes.append([a, a + UPPER_STEP])
        a += UPPER_STEP
    return boxes


def arc_facts(N1: int, boxes: list | None = None) -> dict:
    """For every n ≥ N₁ (≥ 7) and every r in ]r*, R] with nθ > 2π, a b of the ab-phase comes with its
    pair separating: no stable point (R = 1/4, or the top of ``boxes``, where part 7's dominance is
    re-proved box by box).  Proof: θ ≤ θ_max < 2π/3 (cos θ_max = (R² - 6R + 1)/(8R) > -1/2); j₀ the
    largest j with jθ < 2π (j₀ ≤ n - 1 as nθ > 2π, j₀θ ≥ 2π - θ > π); if j₀θ ≤ 2π - θ/2 take j' = j₀, else
    j' = j₀ - 1: then 2π - j'θ ∈ [θ/2, 3θ/2] ⊂ ]0, π[, so sin j'θ ≤ -m, m = min(sin(θ/2), sin θ, sin(3θ/2))
    ≥ min(2/n, sin θ_max, sin(3θ_max/2)) on [2π/n, θ_max].  Before the j'-th b (part 8's formula, j = j' - 1)
    the bracket times sin θ is rh sin j'θ - u(K₁₁ sin(j'-1)θ - r sin(j'-2)θ) ≤ rh(-m + C_u δ_n h²), as
    |u| ≤ C_u|c| (part 7), |c| = rh r^(n-1)|sin nθ|/sin θ ≤ rh δ_n (δ_n = nρ̄^(n-1), ρ̄ = max(R, 1/4)) and
    K₁₁ + r = h² ≤ ((1 + R)/2)².  So q₂ ≥ 0 there when 2 > C_u h² n²ρ̄^(n-1) and min(sin θ_max, sin(3θ_max/2))
    > C_u h² δ_n, both decreasing in n: the margins at N₁ are returned (rational lower bounds)."""
    if N1 < 7:
        raise ArithmeticError("part 10 needs part 7 (n ≥ 7)")
    boxes = upper_boxes(N1) if boxes is None else boxes
    R = boxes[-1][1] if boxes else Fraction(1, 4)
    if boxes and (boxes[0][0] != Fraction(1, 4) or any(a[1] != b[0] for a, b in zip(boxes, boxes[1:]))):
        raise ArithmeticError("the boxes do not cover ]1/4, R]")
    Cu = max(_fmpq(dominant_facts(N1, *box)["Cu"]) for box in [[Fraction(0), Fraction(1, 4)]] + boxes)
    with precision(128):
        c = flint.arb(_fmpq((R * R - 6 * R + 1) / (8 * R)))
        rbar = flint.arb(_fmpq(max(R, Fraction(1, 4))))
        if not (c > flint.fmpq(-1, 2) and (N1 + 1) ** 2 * rbar < N1 ** 2):
            raise ArithmeticError("θ_max < 2π/3 or the decrease of n²ρ̄^(n-1) not proven")
        theta = c.acos()
        h2 = flint.arb(_fmpq(((1 + R) / 2) ** 2))
        dn = N1 * rbar ** (N1 - 1)
        m1 = 2 - Cu * h2 * N1 * dn
        m2 = theta.sin().min((3 * theta / 2).sin()) - Cu * h2 * dn
        if not (m1 > 0 and m2 > 0):
            raise ArithmeticError("the separating b is not proven")
        return {"N1": N1, "r": [None, R], "upper": boxes, "margins": [_q(ends(m1)[0]), _q(ends(m2)[0])]}

# ------------------------------------------------------------------ 11. t ≤ 0: the third a separates
THIRD_A_R0 = Fraction(429, 2500)    # 0.1716 > 3 - 2√2 ≈ 0.171573, the zero of t = tr K in ]0, 1[


def third_a_facts(r0: Fraction = THIRD_A_R0) -> dict:
    """For every n ≥ 3 and every r in [r₀, 1[ (r₀ ≥ 3 - 2√2, so t = tr K = (r² - 6r + 1)/4 ≤ 0) nothing is
    feasible, whatever q(0): before the (j+1)-th a of the ab-phase (j ≤ n - 1) pair 1 has q₁ = ℓ_j =
    (K^j (-1, u))₁, and Cayley–Hamilton (K² = tK - r²I, checked exactly) gives ℓ₂ = tℓ₁ - r²ℓ₀ = tℓ₁ + r²,
    so if the second a's pair approaches (ℓ₁ < 0) the third's separates: ℓ₂ ≥ r² ≥ r₀² > 0.  No dominance,
    no eigenvector, no bound in n: u and v are arbitrary.  t ≤ 0 on [r₀, 1] is checked exactly at both ends
    (t is convex).  Returns the range, n_min = 3 (the third a is in the word), t_max = max t ≤ 0 and the
    margin r₀² (a rational lower bound of ℓ₂ where ℓ₁ < 0); ArithmeticError if a step fails."""
    K, _ = block()
    one = flint.fmpq_poly([1])
    K2 = _mul(K, K)
    if any(K2[i][j] - T * K[i][j] + (R * R if i == j else 0) * one != 0 for i in range(2) for j in range(2)):
        raise ArithmeticError("K² ≠ tK - r²I")
    t0, t1 = (_q(T(_fmpq(x))) for x in (r0, Fraction(1)))
    if not (0 < r0 < 1 and t0 <= 0 and t1 <= 0):
        raise ArithmeticError(f"t = tr K ≤ 0 on [{r0}, 1] not proven")
    return {"r": [r0, Fraction(1)], "n_min": 3, "t_max": max(t0, t1), "margin": r0 * r0}


def check_third_a(facts: dict) -> list[str]:
    """Recompute :func:`third_a_facts` on the stated range: t_max must be ≥ the recomputed maximum and ≤ 0,
    the margin positive and at most r₀², n_min ≥ 3 (three a's in the ab-phase).  The list of failures."""
    r0, r1 = facts["r"]
    try:
        new = third_a_facts(r0)
    except ArithmeticError as e:
        return [f"part 11 does not hold: {e}"]
    bad = []
    if r1 != 1:
        bad.append(f"part 11 is stated on [{r0}, {r1}], not [r0, 1[")
    if facts["n_min"] < 3:
        bad.append(f"part 11 needs a third a: n ≥ 3, not n ≥ {facts['n_min']}")
    if not new["t_max"] <= facts["t_max"] <= 0:
        bad.append(f"t ≤ {facts['t_max']} not implied")
    if not 0 < facts["margin"] <= new["margin"]:
        bad.append(f"third a margin {facts['margin']} not implied")
    return bad


# ------------------------------------------------------------------ 12. the reflection: M = N²
SWAP = (2, 1, 0)    # J: the reflection of the line, q₁ ↔ q₃ (and p₁ ↔ p₃)


def reflection_facts() -> list[str]:
    """The exact identities behind M = N², N = J M_ab^n (J swaps q₁ and q₃), read from the engine's matrices:
    M_cb = J M_ab J, M_ab e₃ = e₃ and det M_ab = r².  Consequences (docs/family-limit.md, part 12): N commutes
    with M, so N q(0) = σ₀ q(0) with σ₀ = -q₃(t_{2n}); N e₃ = e₁, so on R³/q(0) in (p₁, p₃) the induced map is
    N̄ = [[τ, 1], [γ, 0]] with γ = r^{2n}/σ₀, and Q = N̄² = [[τ² + γ, τ], [γτ, γ]]: the fixed points are
    x² + τx - γ = 0, p₁(T) = σ₊², p₃(t_{2n}) = σ₊ at x₊ > 0, and |f'(x₊)| < 1 exactly when τ = Q₁₂ > 0.
    ArithmeticError if an identity fails."""
    Mab, Mcb = word_matrix_flint("ab"), word_matrix_flint("cb")
    ctx = flint.fmpq_mpoly_ctx.get(("a", "b", "c", "d", "W1", "W2"), "lex")
    a, b, c, d, W1, W2 = ctx.gens()
    N = [[W1, W2, ctx.from_dict({(0,) * 6: 1})], [c, d, ctx.from_dict({})], [a, b, ctx.from_dict({})]]
    e2 = sum((N[i][i] * N[j][j] - N[i][j] * N[j][i] for i, j in ((0, 1), (0, 2), (1, 2))), ctx.from_dict({}))
    F = W1 * (a - W1 * d + W2 * c) + (b * c + W2 * c * d - W1 * d * d)
    checks = {
        "M_cb = J M_ab J (J: q₁ ↔ q₃)": all(Mcb[i][j] == Mab[SWAP[i]][SWAP[j]] for i in range(3) for j in range(3)),
        "M_ab e₃ = e₃": [Mab[i][2] for i in range(3)] == [0, 0, 1],
        "det M_ab = r²": _det3(Mab) == R * R,
        "e₂(N) tr N - det N = -F_n, N = J M_ab^n = [[W₁, W₂, 1], [c, d, 0], [a, b, 0]]":
            e2 * (W1 + d) - _det3(N) == -F,
    }
    bad = [k for k, ok in checks.items() if not ok]
    if bad:
        raise ArithmeticError("reflection identities fail: " + "; ".join(bad))
    return list(checks)


def _det3(M) -> flint.fmpq_poly:
    return (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
            + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]))


def check_reflection(facts: list[str]) -> list[str]:
    """Re-derive :func:`reflection_facts`: the stated identities must be the proved ones."""
    try:
        new = reflection_facts()
    except ArithmeticError as e:
        return [str(e)]
    return [f"reflection identity not proved: {k}" for k in facts if k not in new]


def _fmpq(x: Fraction) -> flint.fmpq:
    return flint.fmpq(x.numerator, x.denominator)


def check_arcs(facts: dict) -> list[str]:
    """Recompute :func:`arc_facts` on the stated boxes (part 7 re-proved on each): the stated range must be
    theirs, the margins positive and at most the recomputed ones."""
    try:
        new = arc_facts(facts["N1"], facts["upper"])
    except ArithmeticError as e:
        return [f"part 10 does not hold for N1 = {facts['N1']}: {e}"]
    if facts["r"] != new["r"]:
        return [f"part 10 is proved up to r = {new['r'][1]}, not {facts['r'][1]}"]
    return [f"arc margin {m} not implied" for m, k in zip(facts["margins"], new["margins"]) if not 0 < m <= k]


def check_w_limit() -> bool:
    """wᵀ(I - K)⁻¹ = (1/3, 2/3) for every r (exact: (1/3, 2/3)(I - K) = wᵀ as polynomials in r)."""
    K, w = block()
    third = flint.fmpq(1, 3)
    one = flint.fmpq_poly([1])
    IK = [[one - K[0][0], -K[0][1]], [-K[1][0], one - K[1][1]]]
    return [third * IK[0][j] + 2 * third * IK[1][j] for j in range(2)] == w


def _q(x) -> Fraction:
    x = flint.fmpq(x)
    return Fraction(int(x.p), int(x.q))


def prove(N0: int = 30, boxes: int = 64, prec: int = 128) -> dict:
    """The facts of parts 1-12 (parts 4-12 under their keys) as rational statements a checker
    re-verifies (:func:`check`); for parts 1-3:
    the block identities; s* and κ in rational intervals; for ε in each of ``boxes`` equal
    boxes covering [0, 1/N₀], a rational interval holding s_hi(ε) and |s_hi(ε) - s*| ≤ C ε₁²
    (ε₁ the box's right end) with one rational C; and that r_n decreases (exact: a = 3 + 4cos(π/n) increases in n, and
    r = 1/(a + √(a² - 1)) decreases in a ≥ 1)."""
    with precision(prec):
        star, kap = s_star(), kappa()
        star_lo, star_hi = ends(star)
        cut = [flint.fmpq(k, boxes * N0) for k in range(boxes + 1)]
        rows = []
        for e0, e1 in zip(cut, cut[1:]):
            box = flint.arb((e0 + e1) / 2, (e1 - e0) / 2)
            lo, hi = ends(s_hi(box))
            rows.append({"eps": [_q(e0), _q(e1)], "s_hi": [_q(lo), _q(hi)]})
        # one constant C with |s_hi(ε) - s*| ≤ C ε₁² on every box (ε₁ its right end)
        C = max(max(row["s_hi"][1] - _q(star_lo), _q(star_hi) - row["s_hi"][0]) / row["eps"][1] ** 2
                for row in rows)
        C = Fraction(int(C * 1000) + 1, 1000)
    positions = position_facts(max(N0 + 1, 7))
    return {"N0": N0, "block": block_facts(), "s_star": [_q(star_lo), _q(star_hi)],
            "kappa": [_q(ends(kap)[0]), _q(ends(kap)[1])], "C": C, "boxes": rows,
            "monotone": "r_{n+1} < r_n for every n ≥ 2", "lower": prove_lower(N0, prec=prec),
            "dominant": dominant_facts(max(N0 + 1, 7)), "w_limit": check_w_limit(),
            "velocity": velocity_facts(max(N0 + 1, 8)), "positions": positions,
            "one_zero": one_zero_facts(positions),
            "below": below_facts(max(N0 + 1, 7)), "arcs": arc_facts(max(N0 + 1, 7)),
            "third_a": third_a_facts(), "reflection": reflection_facts()}


def check(facts: dict, prec: int = 200) -> list[str]:
    """Re-verify the facts of :func:`prove` at another precision: each box's enclosure of
    s_hi is recomputed and must lie inside the stated rational interval, the boxes must
    cover [0, 1/N₀] without gaps, s* and κ must lie in their intervals, and every box's
    interval must lie in [s*_lo - C ε₁², s*_hi + C ε₁²].  The
    list of failures (empty: the facts hold)."""
    bad = []
    with precision(prec):
        for name, ball in (("s_star", s_star()), ("kappa", kappa())):
            lo, hi = ends(ball)
            if not (facts[name][0] <= _q(lo) and _q(hi) <= facts[name][1]):
                bad.append(f"{name} not in {facts[name]}")
        rows = facts["boxes"]
        if rows[0]["eps"][0] != 0 or rows[-1]["eps"][1] < Fraction(1, facts["N0"]) or any(
                a["eps"][1] != b["eps"][0] for a, b in zip(rows, rows[1:])):
            bad.append("the boxes do not cover [0, 1/N0]")
        star_lo, star_hi = facts["s_star"]
        for row in rows:
            e0, e1 = row["eps"]
            box = flint.arb(flint.fmpq((e0 + e1).numerator, 2 * (e0 + e1).denominator),
                            flint.fmpq((e1 - e0).numerator, 2 * (e1 - e0).denominator))
            lo, hi = (_q(e) for e in ends(s_hi(box)))
            S0, S1 = row["s_hi"]
            if not (S0 <= lo and hi <= S1):
                bad.append(f"s_hi on ε ∈ [{e0}, {e1}] not in [{S0}, {S1}]")
            if S1 > star_hi + facts["C"] * e1 ** 2 or S0 < star_lo - facts["C"] * e1 ** 2:
                bad.append(f"|s_hi - s*| > C ε² on ε ∈ [{e0}, {e1}]")
    for key, check_part in (("lower", check_lower), ("dominant", check_dominant), ("velocity", check_velocity),
                            ("positions", check_positions), ("below", check_below), ("arcs", check_arcs),
                            ("third_a", check_third_a), ("reflection", check_reflection)):
        if key in facts:
            bad += check_part(facts[key])
    if "one_zero" in facts:
        bad += check_one_zero(facts["one_zero"], facts.get("positions"))
    return bad


def check_velocity(facts: dict) -> list[str]:
    """Recompute :func:`velocity_facts` for N₁: every stated margin must be positive and at most
    the recomputed lower bound, on the stated r-range [7/100, 8/100].  The list of failures."""
    if facts["r"] != [Fraction(7, 100), Fraction(8, 100)]:
        return [f"the velocity conditions are proved on [7/100, 8/100], not {facts['r']}"]
    try:
        new = velocity_facts(facts["N1"])
    except ArithmeticError as e:
        return [f"part 8 does not hold for N1 = {facts['N1']}: {e}"]
    return [f"velocity margin {k} = {m} not implied" for k, m in facts["margins"].items()
            if not (0 < m <= new["margins"].get(k, Fraction(-1)))]


def check_dominant(facts: dict) -> list[str]:
    """Re-derive :func:`dominant_facts` for N₁ and compare: the stated λ-interval must hold the
    proved one, the bounds on |μ|, |ν|, |u| and q₃(t_{2n}) - d must be implied by the proved ones,
    q₃(t_{2n}) - d < 0 and |μ|, |ν| < λ's lower end.  The list of failures."""
    try:
        new = dominant_facts(facts["N1"])
    except ArithmeticError as e:
        return [f"part 7 does not hold for N1 = {facts['N1']}: {e}"]
    bad = []
    if not (facts["lambda"][0] <= new["lambda"][0] and new["lambda"][1] <= facts["lambda"][1]):
        bad.append(f"λ not in {facts['lambda']}")
    if not (new["others"] <= facts["others"] < facts["lambda"][0]):
        bad.append(f"|μ|, |ν| ≤ {facts['others']} < λ not proven")
    if not (new["u"] <= facts["u"] and new["q3_minus_d"] <= facts["q3_minus_d"] < 0):
        bad.append("the bounds on u and q₃(t_2n) - d are not implied")
    if facts["r"] != [Fraction(0), _q(R_MAX)]:
        bad.append(f"part 7 is proved for r in ]0, 1/4], not {facts['r']}")
    return bad
