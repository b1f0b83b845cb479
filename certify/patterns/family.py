"""The family w_n = (ab)^n(cb)^n in closed form (issue 35).

The engine's matrix of a word is the product of its collision matrices in time order
(:func:`certify.dynamics.model.word_matrix`): M_ab = BA, M_cb = BC, and the period matrix
is M_n = (BC)^n (BA)^n.  With h = (1 + r)/2,

    BA = [[K, 0], [wᵀ, 1]],  K = [[h² − r, h], [−rh, −r]] (on q_1, q_2),  wᵀ = (h², h),

and BC = P·BA·P with P the reversal q_1 ↔ q_3 (the mirror a ↔ c: P A P = C, P B P = B).
K has trace t = (r² − 6r + 1)/4 and determinant r², so by Cayley–Hamilton

    K^j = s_j K − r² s_{j−1} I,   s_0 = 0, s_1 = 1, s_{j+1} = t s_j − r² s_{j−1}

(s_j = r^{j−1} U_{j−1}(t/(2r)), Chebyshev's U), and, as det(K − I) = 1 − t + r² = 3(1 + r)²/4 ≠ 0,
Σ_{i<j} K^i = (K − I)^{-1}(K^j − I).  Hence (BA)^j = [[K^j, 0], [wᵀ Σ_{i<j} K^i, 1]] and every prefix
matrix of the period (the velocities after the k-th collision, k = 1..4n) is a polynomial in r, s_j,
s_{j−1}; (s_n, s_{n−1}) costs O(log n) products by doubling (:func:`chebyshev_pair`).

**The positions in closed form.**  Write q(0) = (q_1, q_2, q_3), p(0) = (1, 0, x), and during the
(ab)^n phase Q_j = K^j (q_1, q_2) (the velocities of gaps 1, 2 at t_{2j}), y_j = (Q_j)_2.  With
p(t_{2j}) = (P_j, 0, ·), one step a then b gives (the time of a is −P_j/(Q_j)_1, the a-collision makes
q_2 + h q_1 = −y_{j+1}/r):

    P_{j+1} = P_j · r² y_j / y_{j+1},   t_{2j+2} − t_{2j} = h r P_j / y_{j+1},

so P_j = r^{2j} y_0 / y_j (a telescoping product), and with the Casoratian y_j s_{j+1} − y_{j+1} s_j =
r^{2j} y_0 the times telescope as well: t_{2n} = h r s_n / y_n.  Particle 4 is free during (ab)^n and
the centre of mass of particles 1-3 moves uniformly, so p_3 = x_4 − (x_1 + x_2 + x_3)/3 − (p_1 + 2p_2)/3
gives p_3(t_{2n}) = x + c₀ t_{2n} − (P_n − 1)/3 with c₀ = q_3 + (q_1 + 2q_2)/3.  The (cb)^n phase is
the mirror image started from p(t_{2n}), q(t_{2n}) (:func:`phase`).  All of this is exact in any
field holding r and q(0) (rationals, python-flint polynomials in r, the engine's Q(λ, r)); the
tests compare it with the engine's product of collision matrices and its run of the word
(tests/patterns/test_family.py).

**Which feasibility conditions bind.**  Of the conditions of
:func:`certify.patterns.feasibility.prefix_requirements` for w_n, the gaps p_3(t_k), k < 2n, and
p_1(t_k), 2n < k < 4n, are implied by the others: gap 3 only changes slope at the b-collisions of
the (ab)^n phase, where q_3 gains h q_2 < 0 (the conditions q_2(t_{2j+1}) < 0), and all times are
positive, so p_3 is concave on [0, t_{2n}] and positive at both ends (x > 0, p_3(t_{2n}) > 0); the
same for p_1 on [t_{2n}, t_{4n}] (p_1(t_{2n}) = P_n > 0, p_1(t_{4n}) > 0).  :func:`binding_conditions`
lists the others, as functions of (r, n) through s_j.
"""
from __future__ import annotations

from dataclasses import dataclass

import flint

HALF, THIRD, QUARTER = flint.fmpq(1, 2), flint.fmpq(1, 3), flint.fmpq(1, 4)


def r_poly() -> flint.fmpq_poly:
    """r as a python-flint polynomial."""
    return flint.fmpq_poly([0, 1])


def family_word(n: int) -> str:
    """(ab)^n(cb)^n written out: the normal form of the family (it starts with a, ends with b)."""
    if n < 1:
        raise ValueError(f"the family (ab)^n(cb)^n needs n ≥ 1, not {n}")
    return "ab" * n + "cb" * n


def family_n(word: str) -> int | None:
    """n when ``word`` (a normal form) is (ab)^n(cb)^n with n ≥ 1, else None."""
    n = len(word) // 4
    return n if n >= 1 and word == family_word(n) else None


def implied_names(n: int) -> set[str]:
    """The feasibility conditions of (ab)^n(cb)^n implied by the others on the set where those hold
    (the module's docstring: p_3 concave on [0, t_2n], p_1 on [t_2n, t_4n]): p_3(t_k) > 0 for
    1 ≤ k < 2n and p_1(t_k) > 0 for 2n < k < 4n, as prefix_requirements names them."""
    return {f"p_3(t_{k})" for k in range(1, 2 * n)} | {f"p_1(t_{k})" for k in range(2 * n + 1, 4 * n)}


def reduced_names(n: int) -> set[str]:
    """The feasibility conditions of (ab)^n(cb)^n that, with r < ρ_{n−1} (:func:`turning_bound`),
    are equivalent to all of them (:func:`prefix_requirements`'s names): u = q_2(0) > 0, x > 0,
    q_1(t_{2n−2}) < 0, q_2(t_{2n−3}) < 0, q_2(t_{2n−1}) < 0, q_3(t_{2n}) < 0, p_3(t_{2n}) > 0,
    q_3(t_{4n−2}) < 0, q_2(t_{4n−3}) < 0, q_2(t_{4n−1}) < 0, p_1(t_{4n}) > 0.

    Why (the quadrant proposition).  In the (ab)^n phase the velocities of gaps 1, 2 at t_{2j}
    are Q_j = K^j Q_0, and the conditions on them are: Q_j in the open quadrant
    {q_1 < 0 < q_2} for 0 ≤ j ≤ n − 1 ((Q_j)_1 = q_1(t_{2j}), (Q_j)_2 = y_j = −r q_2(t_{2j−1})),
    and (Q_n)_2 > 0.  For m ≥ 1 and r ∈ ]0, 1[:

        Q_0, …, Q_m all in the quadrant  ⟺  Q_0, Q_m in the quadrant and s_j > 0 for 1 ≤ j ≤ m.

    Proof.  det(Q_0, Q_j) = s_j det(Q_0, K Q_0) and det(Q_j, Q_{j+1}) = r^{2j} det(Q_0, K Q_0)
    (Cayley–Hamilton; det K = r²).  If det(Q_0, K Q_0) = 0, Q_0 is a real eigenvector of K,
    which exists only for r ≤ r* = 7 − 4√3 where both eigenvalues are positive (t ≥ 2r > 0),
    so every Q_j is a positive multiple of Q_0 and every s_j > 0: both sides hold.  Otherwise,
    say det(Q_0, K Q_0) > 0.  (⇐) The angles φ_j ∈ ]0, π[ from Q_0 to Q_j (s_j > 0) increase
    (det(Q_j, Q_{j+1}) > 0), so every Q_j lies in the cone spanned by Q_0 and Q_m, of opening
    < π, inside the (convex) quadrant.  (⇒) Inside the quadrant the angles increase by less than
    π/2 in all, so det(Q_0, Q_j) > 0 and s_j > 0.  The (cb)^n phase is the mirror image with the
    same K (Q'_j = K^j (q_3, q_2)(t_{2n}), Q'_0 in the quadrant iff q_3(t_{2n}) < 0 and y_n > 0).
    And s_j > 0 for 1 ≤ j ≤ m iff r < ρ_m (:func:`turning_bound`).  ∎"""
    if n < 2:
        raise ValueError("the reduction needs n ≥ 2")
    return {"u = q_2(0)", "x", f"q_1(t_{2 * n - 2})", f"q_2(t_{2 * n - 3})", f"q_2(t_{2 * n - 1})",
            f"q_3(t_{2 * n})", f"p_3(t_{2 * n})", f"q_3(t_{4 * n - 2})", f"q_2(t_{4 * n - 3})",
            f"q_2(t_{4 * n - 1})", f"p_1(t_{4 * n})"}


def turning_bound(m: int):
    """ρ_m: s_j(r) > 0 for every 1 ≤ j ≤ m exactly on ]0, ρ_m[ (within ]0, 1[), as an Algebraic
    number, the least root of s_m in ]0, 1[; None for m = 1 (s_1 = 1: no bound).

    Proof.  On ]0, r*] both eigenvalues μ₁, μ₂ of K are positive (t ≥ 2r > 0) and
    s_j = (μ₁^j − μ₂^j)/(μ₁ − μ₂) > 0 (j μ^{j−1} at r*): no root of any s_j there.  On ]r*, 1[,
    s_j = r^{j−1} sin(jθ)/sin θ with cos θ = t/(2r) = (r + 1/r − 6)/8, decreasing in r, so θ ∈ ]0, 2π/3[
    increases with r; all s_j > 0 (j ≤ m) iff mθ < π (if mθ ≥ π, the first j with jθ ≥ π has
    jθ < 2π, so s_j ≤ 0).  The roots of s_m on ]r*, 1[ are where θ = kπ/m, the least one at
    k = 1: that is ρ_m (r² − (6 + 8 cos(π/m)) r + 1 = 0; none in ]0, 1[ for m = 1, as θ < 2π/3)."""
    from certify.algebra.algebraic import Algebraic
    if m < 2:
        return None
    roots = Algebraic.roots(chebyshev(m, r_poly())[m], 0, 1)
    return roots[0]


def cut_below(regions: list, rho) -> None:
    """Keep, in each region of an Analysis, only the r < ρ (ρ an Algebraic): a piece across ρ
    becomes ]lo, ρ[, the points ≥ ρ are dropped (exact comparisons)."""
    from certify.algebra.branches import less, same
    from certify.patterns.feasibility import Piece
    for R in regions:
        out = []
        for p in R.pieces:
            if p.is_point:
                if less(p.lo, rho):
                    out.append(p)
            elif less(p.lo, rho):
                out.append(p if less(p.hi, rho) or same(p.hi, rho) else Piece(p.lo, rho, p.x_value, p.note))
        R.pieces = out


# ------------------------------------------------------------------ the block K and s_j
def trace(rr):
    """t = tr K = (r² − 6r + 1)/4 (det K = r²)."""
    return (rr * rr - 6 * rr + 1) * QUARTER


def block_K(rr) -> list:
    """K = [[h² − r, h], [−rh, −r]], h = (1 + r)/2: BA restricted to (q_1, q_2)."""
    h = (rr + 1) * HALF
    return [[h * h - rr, h], [-(rr * h), -rr]]


def chebyshev(n: int, rr) -> list:
    """[s_0, s_1, …, s_n]: s_0 = 0, s_1 = 1, s_{j+1} = t s_j − r² s_{j−1} (t the trace of K)."""
    t, r2 = trace(rr), rr * rr
    s = [rr * 0, rr * 0 + 1]
    while len(s) <= n:
        s.append(t * s[-1] - r2 * s[-2])
    return s[:n + 1]


def chebyshev_pair(n: int, rr) -> tuple:
    """(s_n, s_{n−1}) for n ≥ 1 by doubling, O(log n) products: from s_{j+m} = s_j s_{m+1} −
    r² s_{j−1} s_m (K^j K^m = K^{j+m}), s_{2j} = s_j (t s_j − 2r² s_{j−1}) and
    s_{2j−1} = s_j² − r² s_{j−1}²; one step of the recurrence for an odd index."""
    if n < 1:
        raise ValueError("chebyshev_pair needs n ≥ 1")
    t, r2 = trace(rr), rr * rr
    a, b = rr * 0 + 1, rr * 0                 # (s_1, s_0)
    for bit in bin(n)[3:]:
        a, b = a * (t * a - 2 * r2 * b), a * a - r2 * b * b          # (s_{2j}, s_{2j−1})
        if bit == "1":
            a, b = t * a - r2 * b, a                                   # (s_{2j+1}, s_{2j})
    return a, b


def power_K(n: int, rr, pair=None) -> list:
    """K^n = s_n K − r² s_{n−1} I (Cayley–Hamilton); n = 0 gives I."""
    if n == 0:
        return [[rr * 0 + 1, rr * 0], [rr * 0, rr * 0 + 1]]
    sn, sm = pair if pair is not None else chebyshev_pair(n, rr)
    K, r2 = block_K(rr), rr * rr
    return [[sn * K[i][j] - (r2 * sm if i == j else rr * 0) for j in range(2)] for i in range(2)]


def geometric_K(n: int, rr, Kn=None) -> list:
    """Σ_{i<n} K^i = adj(K − I)(K^n − I) / det(K − I), det(K − I) = 3(1 + r)²/4 ≠ 0 for r > −1."""
    Kn = Kn if Kn is not None else power_K(n, rr)
    K = block_K(rr)
    a, b, c, d = K[0][0] - 1, K[0][1], K[1][0], K[1][1] - 1
    adj = [[d, -b], [-c, a]]
    E = [[Kn[i][j] - (1 if i == j else 0) for j in range(2)] for i in range(2)]
    det = a * d - b * c
    return [[_exact_div(adj[i][0] * E[0][j] + adj[i][1] * E[1][j], det) for j in range(2)] for i in range(2)]


def power(a, k: int):
    """a^k, k ≥ 0, by squaring (for rings without ``**``, as the engine's Q(λ, r))."""
    out, base = a * 0 + 1, a
    while k:
        if k & 1:
            out = out * base
        base, k = base * base, k >> 1
    return out


def _exact_div(a, b):
    """a / b, exact (a polynomial quotient when both are python-flint polynomials)."""
    if isinstance(a, flint.fmpq_poly):
        q, rem = divmod(a, b)
        if not rem.is_zero():
            raise ArithmeticError("Σ K^i: the division by det(K − I) is not exact")
        return q
    return a / b


# ------------------------------------------------------------------ the velocity matrices
def power_ab(j: int, rr) -> list:
    """(BA)^j = [[K^j, 0], [wᵀ Σ_{i<j} K^i, 1]], wᵀ = (h², h): the velocities after (ab)^j."""
    Kj = power_K(j, rr)
    S = geometric_K(j, rr, Kj) if j else [[rr * 0, rr * 0], [rr * 0, rr * 0]]
    h = (rr + 1) * HALF
    w = (h * h, h)
    z, one = rr * 0, rr * 0 + 1
    return [[Kj[0][0], Kj[0][1], z], [Kj[1][0], Kj[1][1], z],
            [w[0] * S[0][0] + w[1] * S[1][0], w[0] * S[0][1] + w[1] * S[1][1], one]]


def mirror(M: list) -> list:
    """P M P with P the reversal q_1 ↔ q_3 (the mirror a ↔ c)."""
    return [[M[2 - i][2 - j] for j in range(3)] for i in range(3)]


def power_cb(j: int, rr) -> list:
    """(BC)^j = P (BA)^j P."""
    return mirror(power_ab(j, rr))


def matmul(X: list, Y: list) -> list:
    """The product of two square matrices (lists of rows) over any ring."""
    n = len(X)
    return [[sum((X[i][k] * Y[k][j] for k in range(1, n)), X[i][0] * Y[0][j]) for j in range(n)] for i in range(n)]


def letter_matrix(letter: str, rr) -> list:
    """A, B or C (l. 209-232) as rows, in any ring holding r."""
    from certify.dynamics.model import collide
    cols = [collide(letter, e, rr) for e in ((rr * 0 + 1, rr * 0, rr * 0), (rr * 0, rr * 0 + 1, rr * 0),
                                            (rr * 0, rr * 0, rr * 0 + 1))]
    return [[cols[j][i] for j in range(3)] for i in range(3)]


def period_matrix(n: int, rr=None) -> list:
    """M_n = (BC)^n (BA)^n, O(log n) products (r a python-flint polynomial by default)."""
    rr = r_poly() if rr is None else rr
    return matmul(power_cb(n, rr), power_ab(n, rr))


def prefix_matrix(n: int, k: int, rr=None) -> list:
    """The product of the first k collision matrices of (ab)^n(cb)^n (q(t_k) = it · q(0)), 0 ≤ k ≤ 4n:
    (BA)^j for k = 2j, A (BA)^j for k = 2j + 1, and (BC)^j (BA)^n, C (BC)^j (BA)^n beyond 2n."""
    rr = r_poly() if rr is None else rr
    if not 0 <= k <= 4 * n:
        raise ValueError(f"a prefix of (ab)^{n}(cb)^{n} has 0..{4 * n} collisions, not {k}")
    if k <= 2 * n:
        M = power_ab(k // 2, rr)
        return matmul(letter_matrix("a", rr), M) if k % 2 else M
    j, odd = divmod(k - 2 * n, 2)
    M = matmul(power_cb(j, rr), power_ab(n, rr))
    return matmul(letter_matrix("c", rr), M) if odd else M


def charpoly(n: int, rr=None) -> list:
    """cp_n = det(λI − M_n): its coefficients, highest power of λ first (as
    :func:`certify.dynamics.model.charpoly_coefficients`); det M_n = r^{4n}."""
    from certify.dynamics.model import charpoly_coefficients
    return charpoly_coefficients(period_matrix(n, rr))


# ------------------------------------------------------------------ the positions
@dataclass
class Phase:
    """One phase (ab)^n (or its mirror) from p = (P, 0, X), q = (q_1, q_2, q_3): the closed forms."""

    s: tuple          # (s_n, s_{n−1})
    y: object         # y_n = (K^n (q_1, q_2))_2
    gap: object       # P_n = P r^{2n} q_2 / y_n: p_1 at the end of the phase
    time: object      # its duration h r P s_n / y_n
    far: object       # p_3 at the end: X + c₀·time − (P_n − P)/3
    q: tuple          # the velocities at the end, (BA)^n q


def phase(n: int, P, X, q: tuple, rr) -> Phase:
    """The phase (ab)^n from p = (P, 0, X) (gap 2 just closed by a b) with velocities q, in any field:
    P_n = P r^{2n} q_2 / y_n, duration h r P s_n / y_n, p_3 = X + c₀ · duration − (P_n − P)/3,
    c₀ = q_3 + (q_1 + 2 q_2)/3 (see the module's docstring)."""
    sn, sm = chebyshev_pair(n, rr)
    Kn = power_K(n, rr, (sn, sm))
    y = Kn[1][0] * q[0] + Kn[1][1] * q[1]
    gap = P * power(rr * rr, n) * q[1] / y
    time = (rr + 1) * HALF * rr * P * sn / y
    c0 = q[2] + (q[0] + 2 * q[1]) * THIRD
    far = X + c0 * time - (gap - P) * THIRD
    Mab = power_ab(n, rr)
    qn = tuple(sum((Mab[i][k] * q[k] for k in range(1, 3)), Mab[i][0] * q[0]) for i in range(3))
    return Phase((sn, sm), y, gap, time, far, qn)


def positions(n: int, q0: tuple, x, rr) -> dict:
    """p and q at t_{2n} and t_{4n} from p(0) = (1, 0, x), q(0) = q0, in any field holding r, q0, x:
    {"p(t_2n)": (P_n, 0, X), "q(t_2n)": …, "p(t_4n)": (p_1, 0, p_3), "q(t_4n)": …, "ab", "cb": the
    :class:`Phase` records}."""
    one = rr * 0 + 1
    ab = phase(n, one, x, q0, rr)
    X = ab.far
    rev = tuple(reversed(ab.q))
    cb = phase(n, X, ab.gap, rev, rr)              # the mirror image: gaps (p_3, p_2, p_1)
    return {"p(t_2n)": (ab.gap, rr * 0, X), "q(t_2n)": ab.q, "p(t_4n)": (cb.far, rr * 0, cb.gap),
            "q(t_4n)": tuple(reversed(cb.q)), "ab": ab, "cb": cb}


def binding_conditions(n: int, q0: tuple, x, rr) -> list[tuple[str, object, int]]:
    """The feasibility conditions of (ab)^n(cb)^n that are not implied by others (module docstring),
    as (name, value, required sign), in the names of prefix_requirements:
    u = q_2(0) > 0, x > 0, q_1(t_{2j}) = (K^j q)_1 < 0 (1 ≤ j < n), q_2(t_{2j+1}) = −y_{j+1}/r < 0,
    q_3(t_{2n+2j}) < 0, q_2(t_{2n+2j+1}) < 0, p_3(t_{2n}) > 0 and p_1(t_{4n}) > 0."""
    out = [("u = q_2(0)", q0[1], 1), ("x", x, 1)]
    s = chebyshev(n + 1, rr)
    K, r2 = block_K(rr), rr * rr

    def Kq(j, q1, q2):
        a = [[s[j] * K[i][k] - (r2 * s[j - 1] if i == k else rr * 0) for k in range(2)] for i in range(2)] \
            if j else [[1, 0], [0, 1]]
        return a[0][0] * q1 + a[0][1] * q2, a[1][0] * q1 + a[1][1] * q2

    pos = positions(n, q0, x, rr)
    qm = pos["q(t_2n)"]
    for j in range(n):
        if j:
            out.append((f"q_1(t_{2 * j})", Kq(j, q0[0], q0[1])[0], -1))
        out.append((f"q_2(t_{2 * j + 1})", -Kq(j + 1, q0[0], q0[1])[1] / rr, -1))
    for j in range(n):
        out.append((f"q_3(t_{2 * n + 2 * j})", Kq(j, qm[2], qm[1])[0], -1))
        out.append((f"q_2(t_{2 * n + 2 * j + 1})", -Kq(j + 1, qm[2], qm[1])[1] / rr, -1))
    out.append((f"p_3(t_{2 * n})", pos["p(t_2n)"][2], 1))
    out.append((f"p_1(t_{4 * n})", pos["p(t_4n)"][0], 1))
    return out


# ------------------------------------------------------------------ stability
def position_map(n: int, q0: tuple, rr) -> tuple:
    """(a, b, c, d) with p_3(t_4n) = a x + b and p_1(t_4n) = c x + d exactly (p(0) = (1, 0, x)):
    f(x) = (ax + b)/(cx + d), the engine's position map up to a common factor (whose sign may swap
    the names x₊, x₋).  Both are affine in x: read off at x = 0 and x = 1."""
    zero, one = rr * 0, rr * 0 + 1
    p0, p1 = positions(n, q0, zero, rr)["p(t_4n)"], positions(n, q0, one, rr)["p(t_4n)"]
    return p1[2] - p0[2], p0[2], p1[0] - p0[0], p0[0]


def dominance(n: int, lam, rr) -> list[tuple[str, object, int]]:
    """λ strictly dominant among the roots of cp_n = λ³ + c₁λ² + c₂λ + c₃ (Schur–Cohn–Jury, as
    :func:`certify.patterns.pattern.dominance_requirements`): cp'(λ) > 0, −cp(−λ) > 0, λ³ − det M > 0,
    det M = −c₃ = r^{4n}; the coefficients in closed form (:func:`charpoly`)."""
    _, c1, c2, c3 = charpoly(n) if isinstance(rr, flint.fmpq_poly) else charpoly(n, rr)
    if isinstance(rr, flint.fmpq_poly):
        c1, c2, c3 = (c(rr) for c in (c1, c2, c3))
    return [("dominance: cp'(λ)", 3 * lam * lam + 2 * c1 * lam + c2, 1),
            ("dominance: -cp(-λ)", lam * lam * lam - c1 * lam * lam + c2 * lam - c3, 1),
            ("dominance: λ³ - det M", lam * lam * lam + c3, 1)]


def attracting(abcd: tuple, x) -> list[tuple[str, object, int]]:
    """|f'(x)| < 1 at a fixed point x of f = (ax + b)/(cx + d), f'(x) = (ad − bc)/(cx + d)²:
    (cx + d)² − (ad − bc) > 0 and (cx + d)² + (ad − bc) > 0 (the engine's two conditions)."""
    a, b, c, d = abcd
    den, det = (c * x + d) * (c * x + d), a * d - b * c
    return [("attracting: (cx+d)² - (ad-bc)", den - det, 1), ("attracting: (cx+d)² + (ad-bc)", den + det, 1)]
