"""The windows of (ab)^n(cb)^n for large n: what is proved for every n, exactly.

Issue 35 asks for the stable set W_n = ]lo_n, hi_n[ of w_n = (ab)^n(cb)^n for every n.
This module proves, for *every* n ≥ 2 (not only n ≤ N₀), the part that has a closed form:

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

What is *not* proved here (measured, docs/family-limit.md): that the stable set is exactly
one interval whose upper end is r_n (observed to n = 80 by an independent mpmath
computation; certified per n ≤ N₀ by the family's exact certificates), and the lower end
lo_n (where the fixed point x₊ crosses 0: observed s_lo(ε) ≈ s* - 0.117ε), hence the
disjointness r_{n+1} < lo_n (observed margin ≈ 0.28/n³).
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
            "monotone": "r_{n+1} < r_n for every n ≥ 2"}


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
    return bad
