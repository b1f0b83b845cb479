"""The windows of (ab)^n(cb)^n for large n: what is proved for every n, exactly.

Issue 35 asks for the stable set W_n = ]lo_n, hi_n[ of w_n = (ab)^n(cb)^n for every n.
This module proves where the two ends of that window are, for every n (parts 1-4 for all n,
parts 5-6 for n > N₀), and that the windows they bound are disjoint and decrease:

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

Not proved here (docs/family-limit.md): that the stable set is exactly ]ℓ_n, r_n[ for n > N₀
(inside: x₊ > 0, p₃(t_{2n}) > 0, p₁(T) > 0, |f'(x₊)| < 1; outside: one condition failing);
certified per n ≤ N₀ by the family's exact certificates, observed beyond by an independent
mpmath computation (n = 35, 50, 80 in the tests).
"""
from __future__ import annotations

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


def dominant_facts(N1: int) -> dict:
    """For every n ≥ N₁ and every r ∈ ]0, 1/4], with balls over that whole range (no boxes):

    * the spectral radius of K is ≤ 1/4 (r ≥ r*: it is r; r < r*: the larger root is ≤ t ≤ 1/4),
      so |s_j| ≤ j 4^{1-j} and |(K^n)_ij| ≤ n 4^{1-n}(|K_ij| + r) ≤ δ = N₁ 4^{1-N₁};
    * wᵀ(I - K)⁻¹ = (1/3, 2/3) exactly (:func:`check_w_limit`), so W = (1/3, 2/3) + O(δ) and
      M = [[1/9, 2/9, 1/3], [0, 0, 0], [0, 0, 0]] + O(δ) (:func:`period_matrix`'s formula);
    * cp changes sign on [1/9 - ω, 1/9 + ω] (ω = 16δ rounded up): a real eigenvalue λ there; the other two
      have |μ|, |ν| ≤ |S|/2 + √(|S|²/4 + |Π|), S = tr M - λ, Π = det M/λ = r^{4n}/λ, below λ:
      λ is real, simple, positive and strictly dominant;
    * its eigenvector (-1, u, v) (rows 2, 3 by Cramer) has q₃(t_{2n}) = v - W₁ + W₂u and
      P₂₂ = d in balls with q₃(t_{2n}) - d < 0 < λ - d²: by part 2, **u has the sign of s_n**.

    Returns the rational bounds; ArithmeticError when a ball does not decide."""
    with precision(128):
        r = flint.arb(R_MAX / 2, R_MAX / 2)                       # ]0, 1/4] (and 0)
        h = (1 + r) / 2
        K, w, N = _k_w_n(r)
        if not max(abs(k) for row in K for k in row) + r < 1:
            raise ArithmeticError("|K_ij| + r < 1 not proven on ]0, 1/4]")
        if not (N1 + 1) * R_MAX < N1:
            raise ArithmeticError("n 4^(1-n) is not proven to decrease")
        delta = N1 * flint.arb(R_MAX) ** (N1 - 1)
        small = flint.arb(0, delta.upper())
        width = (16 * delta).upper().mid().fmpq()
        a = b = c = d = small
        spread = delta * (w[0] + w[1]) * max((N[0][i].abs_upper() + N[1][i].abs_upper()) for i in range(2))
        W1 = flint.arb(flint.fmpq(1, 3)) + flint.arb(0, spread.abs_upper())
        W2 = flint.arb(flint.fmpq(2, 3)) + flint.arb(0, spread.abs_upper())
        M = [[a + W2 * c + W1 * W1, b + W2 * d + W1 * W2, W1],
             [c * (d + W1), d * d + c * W2, c],
             [b * c + a * W1, b * d + a * W2, a]]
        det = flint.arb(0, (R_MAX ** (4 * N1)))                    # det M = r^{4n} ∈ [0, 4^{-4N₁}]
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
        return {"N1": N1, "r": [Fraction(0), _q(R_MAX)], "delta": _q(ends(delta)[1]),
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
    """The facts of parts 1-3 as rational statements a checker re-verifies (:func:`check`):
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
    return {"N0": N0, "block": block_facts(), "s_star": [_q(star_lo), _q(star_hi)],
            "kappa": [_q(ends(kap)[0]), _q(ends(kap)[1])], "C": C, "boxes": rows,
            "monotone": "r_{n+1} < r_n for every n ≥ 2", "lower": prove_lower(N0, prec=prec),
            "dominant": dominant_facts(max(N0 + 1, 7)), "w_limit": check_w_limit(),
            "velocity": velocity_facts(max(N0 + 1, 8))}


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
    if "lower" in facts:
        bad += check_lower(facts["lower"])
    if "dominant" in facts:
        bad += check_dominant(facts["dominant"])
    if "velocity" in facts:
        bad += check_velocity(facts["velocity"])
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
