"""``certify pattern WORD`` for five particles (issue 39): the self-similar datum through κ = λμ.

For N particles the self-similar datum of a word w has q(0) an eigenvector of M_w for λ and p(0) in
the plane of q(0) and a second eigenvector e_μ, on the face Y of the last letter (docs/particles.md).
For five particles μ is a root of a cubic over Q(r, λ); the route here avoids it:

* the plane Π = Span(q(0), e_μ) is the eigenvector of the second compound Λ²M_w for κ = λμ, a
  root of the sextic cp(Λ²M_w) (the spectrum's variable, written λ in the engine's ring);
* p(0) is Π contracted with the face's coordinate: with Π = p ∧ q and p_Y = 0,
  Π_{lY} = q_Y p_l (l < Y) and Π_{Yl} = -q_Y p_l (l > Y): p(0) ∝ p̂ = (Π_{lY}, …, 0, …, -Π_{Yl}),
  normalised by one of its coordinates, rational in (r, κ);
* λ and μ are the roots of x² - t x + κ, t = λ + μ the trace of M_w on Π (Cayley–Hamilton on Π:
  M²p̂ - t M p̂ + κ p̂ = 0, so t = (M²p̂ + κp̂)_j / (M p̂)_j); the engine's position fixed point x
  (:mod:`.feasibility`, x = (A ± √Δ)/(2c)) is λ, with a - d = T_num, c = T_den, b = -κ T_den,
  d = 0: c x² = (a - d)x + b is x² = t x - κ, both roots analysed (x₊ and x₋, the two orderings);
* q(0) ∝ M p(0) - μ p(0) (p(0) = α e_λ + β e_μ, so M p - μ p = α(λ - μ) e_λ); with y = Dλ and
  T = Dt: q̄ = D M p̂ - (T - y) p̂, affine in y over Q[κ, r], and y² = T y - κD²; the true q(0) is
  -sign(q̄_{i₁}(0)) q̄ for the first letter's gap i₁ (the pair approaches).

Every quantity is a polynomial in (κ, r), or affine in y, reduced modulo y² = T y - κD² and modulo
the sextic: the engine's requirements G₀ + y G₁ (its position fixed point y = (a - d ± √Δ)/(2c) with
c = 1, a - d = T, b = -κD²), certified by :class:`.feasibility.Analysis` over r-cells of the sextic's
spectrum like the four particles' (critical values from resultants and discriminants, one exact
sample per cell, signs by balls, exact zero tests).  x₊ and x₋ are the two orderings of the pair.

**The run through the plane** (certificate B1: each K_i fixes its face pointwise, free flight keeps
p ∧ q): P_k = Λ²K_{i_k} P_{k-1}, P_0 = Π = c p(0) ∧ q(0), and as p_{i_k}(t_k) = 0 the contraction
p̂_k = ι_{i_k} P_k is c q_{i_k}(t_k⁺) p(t_k) with q_{i_k}(t_k⁺) = -r q_{i_k}(t_{k-1}) > 0 where the
pair approaches: p_m(t_k) has the sign of p̂_{k,m} p̂_{0,j₀} (p̂_0 = c q_Y(0) p(0), q_Y(0) > 0 as the
face Y separates after the period's last collision).  So the positions are polynomials in (κ, r) of
degree growing by 2 a collision, and only the approach conditions q̄_{i_k}(t_{k-1}) q̄_{i₁}(0) > 0 hold y.

Requirements (each strict): *exists*: λ > 0 (Dy > 0), μ > 0 (D(T - y) > 0), p_j(0) > 0 for the
gaps j ≠ Y (p̂_{0,j} p̂_{0,j₀} > 0); *feasible*: at each collision k the pair approaches
(q̄_{i₁}(0)² > 0 for k = 1), and every gap but the one colliding is open at t_k (the gap that
collided at k - 1 is open at t_k by itself: it separates at t_{k-1}; the gaps are affine in t
between collisions, open at both ends, so open between: no other pair touches first, no triple
collision); the positions then return as μ p(0) (p(t_n) lies on Π and on the face Y, a line
through p(0)).  *stable*: λ > μ > |ν| for the two other eigenvalues ν (velocities: λ dominant;
the plane, the fixed point of the reduction on Gr(2, 4), attracts iff κ = λμ strictly dominates
the five other products of two eigenvalues, which with λ > μ > 0 is the same: |λμ| > |λν| and
|λμ| > |μν| give μ > |ν| and λ > |ν|, and conversely; tests/patterns/test_five.py checks it):
D(2y - T) > 0 and, with cp(z) = (z² - tz + κ)(z² + sz + p) (s = c₁ + t, p = c₂ + ts - κ), Jury's
criterion for z² + sz + p in the open disc of radius μ > 0, times D²: μ² - p > 0,
μ² + sμ + p > 0, μ² - sμ + p > 0, with D²μ² = T² - κD² - T y.
"""
from __future__ import annotations

import functools
import itertools
from dataclasses import dataclass

import flint

from certify.algebra.branches import Spectrum, less
from certify.algebra.poly import (
    FIELD,
    LR_LAMBDA,
    LR_R,
    LRCTX,
    RING,
    Frac,
    flint_poly_to_frac,
    frac_to_field,
    lr_to_ring,
    mpoly_to_ring,
    primitive,
    ring_to_lrq,
    ring_to_mpoly,
)
from certify.dynamics.model import alphabet, charpoly_coefficients, charpoly_ring, collide_gaps
from certify.dynamics.systems import of_particles, system_matrix_flint

from .family import matmul
from .feasibility import Analysis, Region, Requirement
from .pattern import PatternResult, _cond, _copy, _nonempty, _short, check_range, end_data, verdict
from .periodic import primitive_root
from .reduction_orbits import _lr

PAIRS = list(itertools.combinations(range(4), 2))       # the coordinates of Λ²R⁴: e_k ∧ e_l, k < l


def second_compound(M) -> list:
    """Λ²M on the basis e_k ∧ e_l (k < l): the 2×2 minors of M (python-flint polynomials in r)."""
    return [[M[i][k] * M[j][m] - M[i][m] * M[j][k] for (k, m) in PAIRS] for (i, j) in PAIRS]


def laplace_determinant(A: list) -> flint.fmpz_poly:
    """det A for a square matrix of fmpz_poly (in r), without a division: Laplace's expansion along
    the first h = n // 2 rows, det A = Σ_S (-1)^(Σ_{i<h} i + Σ_{j∈S} j) det A[:h, S] det A[h:, S̄] over
    the h-subsets S of the columns (S̄ the others), each minor by :func:`row_minors`.  Every step is a
    ring operation of Z[r], so the result is det A exactly (for n = 6: 200 products, the largest of two
    3×3 minors; Bareiss's exact divisions, 60 % of its time on the resultants, are gone)."""
    n = len(A)
    h = n // 2
    top, bottom = row_minors(A[:h], n), row_minors(A[h:], n)
    total = flint.fmpz_poly(0)
    for S in itertools.combinations(range(n), h):
        rest = tuple(j for j in range(n) if j not in S)
        term = top[S] * bottom[rest]
        total = total - term if (sum(S) + h * (h - 1) // 2) % 2 else total + term
    return total


def row_minors(rows: list, n: int) -> dict:
    """{S: det rows[:, S]} for every k-subset S of the n columns (k = len(rows)), by expansion along
    the last row, level by level: M(S) = Σ_p (-1)^(k-1+p) rows[k-1][S_p] M(S without S_p)."""
    minors = {(): flint.fmpz_poly(1)}
    for k, row in enumerate(rows):
        level = {}
        for S in itertools.combinations(range(n), k + 1):
            total = flint.fmpz_poly(0)
            for p, j in enumerate(S):
                if not row[j].is_zero():
                    term = row[j] * minors[S[:p] + S[p + 1:]]
                    total = total - term if (k - p) % 2 else total + term
            level[S] = total
        minors = level
    return minors


def bezout_matrix(f: list, g: list) -> list:
    """The Bézout matrix of f and g ∈ Z[r][κ] (coefficients lowest first, fmpz_poly in r), n = deg f ≥
    deg g: B[i][j] the coefficient of x^i y^j in (f(x)g(y) - f(y)g(x))/(x - y).  A pair a > b of
    exponents gives (f_a g_b - f_b g_a) x^b y^b (x^(a-b) - y^(a-b))/(x - y), whose monomials are
    x^(b+t) y^(a-1-t), 0 ≤ t < a - b: so B[i][j] = Σ (f_a g_b - f_b g_a) over b ≤ min(i, j) with
    a = i + j + 1 - b ≤ n.  det B = ±lc(f)^(n - deg g) Res_κ(f, g) (Bézout's form of the resultant)."""
    n = len(f) - 1
    zero = flint.fmpz_poly(0)
    g = list(g) + [zero] * (n + 1 - len(g))
    B = [[zero] * n for _ in range(n)]
    for i in range(n):
        for j in range(n):
            total = zero
            for b in range(max(0, i + j + 1 - n), min(i, j) + 1):
                a = i + j + 1 - b
                total = total + f[a] * g[b] - f[b] * g[a]
            B[i][j] = total
    return B


def bezout_resultant(g: list, cp: list) -> flint.fmpz_poly:
    """primitive(Res_κ(g, cp)) for cp ∈ Z[r][κ] of constant leading coefficient c (coefficients in κ
    lowest first, fmpz_poly in r; g likewise, of lower degree in κ): the Bézout determinant of cp and g
    with g's content removed (:func:`bezout_matrix`), ±c^k·Res_κ(cp, g)/content(g)^(deg cp), a non-zero
    rational multiple of the resultant when it is not 0, so the same primitive polynomial; 0 when the
    resultant is 0.  Entries of degree deg g + deg cp in r with the bits of g and cp (no reduction
    modulo cp, no power of c in them), the determinant by :func:`laplace_determinant` (division-free):
    about 3 times faster than Bareiss on the multiplication matrix it replaces (benchmarks/bench_census5.py;
    tests/run/test_census5.py compares it with the engine's subresultant)."""
    if cp[-1].degree() > 0:
        raise ValueError("cp's leading coefficient in κ depends on r")
    g = pseudo_remainder(g, cp)
    content = flint.fmpz(0)
    for e in g:
        content = content.gcd(e.content())
    if content == 0:
        return flint.fmpz_poly(0)
    return primitive(laplace_determinant(bezout_matrix(cp, [e / content for e in g])))


def pseudo_remainder(g: list, cp: list) -> list:
    """c^k g modulo cp in Z[r][κ] (c = lc(cp), a constant; coefficients lowest first), of degree below
    n = deg cp: κ^m ≡ -(Σ_{i<n} cp_i κ^(m-n+i))/c, so each top term is cancelled after multiplying by c.
    Res(cp, g) = ±c^(deg g - deg h) Res(cp, h) for h = g mod cp, and Res(cp, c^k h) = c^(kn) Res(cp, h):
    the same resultant up to a non-zero constant."""
    n = len(cp) - 1
    g = list(g)
    c = cp[n]
    for m in range(len(g) - 1, n - 1, -1):
        t = g[m]
        if t.is_zero():
            continue
        g = [e * c for e in g]
        for i in range(n):
            g[m - n + i] -= t * cp[i]
        g[m] = flint.fmpz_poly(0)
    return g[:n] if len(g) > n else g


# the precision to which the common roots of a gcd in Q(r₀)[κ] taken as it comes are enclosed where the
# engine's zero test stops at 1024 bits (FiveSpectrum._attempts): its coefficients reach tens of thousands of bits
AS_IT_COMES_PRECISION = 1 << 16


class FiveSpectrum(Spectrum):
    """:class:`~certify.algebra.branches.Spectrum` of a sextic (or a factor) monic in κ up to a constant,
    with two cheaper routes to the same answers:

    * its resultants free of s by :func:`bezout_resultant` (a 6×6 Bézout determinant over Z[r],
      division-free) instead of the multivariate subresultant: the same primitive polynomial, memoised by
      the engine (:meth:`_resultant_free_of_s`);
    * the zero test encloses the common roots of a gcd taken as it comes up to
      :data:`AS_IT_COMES_PRECISION` bits where the engine stops at 1024 (:meth:`_attempts`): after the
      monic gcd, which :func:`certify.algebra.numberfield.monic` makes modulo primes in milliseconds (an
      inverse in Q(r₀) by xgcd took 10-14 s on words of length 9, whose gcds have coefficients of 24 000
      bits, so these precisions came first until 2026-11-30)."""

    def _resultant_free_of_s(self, g: list) -> flint.fmpz_poly:
        """primitive(Res_κ(g, cp)) by :func:`bezout_resultant`, whatever cp's degree (the engine's
        memo, :meth:`Spectrum.resultant`, keeps it)."""
        return bezout_resultant(g, self._cp_coeffs)

    def _attempts(self, G, maxprec: int):
        """The engine's attempts (a gcd as it comes, then the monic gcd, each to ``maxprec``), then, on a
        gcd taken as it comes, the same from 2·maxprec to :data:`AS_IT_COMES_PRECISION` bits: tried after
        the monic gcd, which costs milliseconds (the answers are the same in any order)."""
        yield from super()._attempts(G, maxprec)
        if getattr(G, "fallback", None) is not None and AS_IT_COMES_PRECISION > maxprec:
            yield G, 2 * maxprec, AS_IT_COMES_PRECISION


class Reducer:
    """Reduction of :class:`Frac` in (κ, r) modulo the sextic (monic in κ): numerator and
    denominator separately, the same values on every branch κ(r)."""

    def __init__(self, ring_cp):
        C = ring_to_lrq(ring_cp)
        scale = flint.fmpz(1)
        for c in C.coeffs():
            scale = scale.lcm(c.q)
        self.Z = LRCTX.from_dict({m: int(c * scale) for m, c in C.to_dict().items()})
        self.n, self.L = self.Z.degrees()[0], self.Z.leading_coefficient()
        if self.Z.monoms()[0] != (self.n, 0):
            raise ArithmeticError("a reduction modulo a polynomial not monic in κ up to a constant")

    def poly(self, p):
        """An fmpz_mpoly in (κ, r) reduced modulo cp, as (fmpz_mpoly, positive integer scale), over Z:
        with C = a multiple of cp in Z[r][κ] of constant leading coefficient L and k = deg_κ p - deg C + 1,
        L^k p = Q C + R (a pseudo-division: python-flint's division meets a leading coefficient divisible
        by L at every step), so p ≡ R / L^k, written with the least scale (the lcm of the denominators)."""
        k = p.degrees()[0] - self.n + 1
        if k <= 0:
            return p, flint.fmpz(1)
        N = self.L ** k
        R = divmod(p * N, self.Z)[1]
        if N < 0:
            R, N = -R, -N
        g = N.gcd(R.content())
        return (R / g, N / g) if g != 1 else (R, N)

    def __call__(self, F: Frac) -> Frac:
        n, a = self.poly(F.num)
        d, b = self.poly(F.den)
        if d.is_zero():
            raise ZeroDivisionError("a denominator vanishes modulo the sextic")
        return Frac(n * b, d * a)


class Ext:
    """Polynomials in (κ, r) (:class:`Frac` with a constant denominator) affine in y, with
    y² = T y - κ D² (y = D λ, T = D t: :func:`five_candidate`), reduced modulo the sextic."""

    def __init__(self, T: Frac, D: Frac, red: Reducer, kappa: Frac = LR_LAMBDA):
        self.T, self.D2k, self.red = T, red(kappa * D * D), red

    def mul(self, u: tuple, v: tuple) -> tuple:
        """(A + yB)(C + yE) = AC - κD²BE + y(AE + BC + T BE)."""
        be = self.red(u[1] * v[1])
        return (self.red(u[0] * v[0] - self.D2k * be), self.red(u[0] * v[1] + u[1] * v[0] + self.T * be))


@dataclass
class FiveCandidate:
    """The κ-route candidate of a five-particle word: what :class:`.feasibility.Analysis` reads
    (``spectrum`` of the sextic, ``abcd`` with c y² = (a - d) y + b the relation of y = Dλ,
    ``Mq``, ``word``) and the data, all polynomials in (κ, r) (affine in y) reduced modulo the sextic."""

    word: str
    Mq: list
    spectrum: Spectrum
    abcd: tuple
    abcd_ring: tuple
    T: Frac                  # D t (t = λ + μ)
    D: Frac                  # y = D λ
    p0: list                 # p̂ ∝ p(0) (an unknown sign, the same for every gap), p̂_Y = 0
    q0: list                 # (A, B): q̄ = A + yB, the true q(0) is -sign(q̄_{i₁}(0)) times q̄
    cp4: list                # the quartic's coefficients c₁..c₄ (Frac in r)
    ext: Ext
    face: int                # Y, the gap of the last letter
    steps: list              # [(letter, p̂_k = ι P_k, q̄(t_{k-1}), q̄(t_k))]
    q0_other: tuple = ()
    repeated: bool = False   # the branch variable is t = λ + μ, κ = κ₀(r) a repeated root (:data:`REPEATED_ROUTE`)
    plane: tuple = ()        # Π, the bivector p̂ contracts (integral in (κ, r)): the reduction's state (five_orbits)


def eigen_plane(W, red) -> list:
    """A κ-eigenvector Π of Λ²M (Frac in (κ, r)): the last coordinate 1, the others from the first
    five rows of (Λ²M - κI)Π = 0 by elimination over Q(κ, r), every pivot non-zero modulo κ's
    polynomial (ArithmeticError otherwise: the route needs another normalisation there)."""
    A = [[flint_poly_to_frac(W[i][j]) - (LR_LAMBDA if i == j else Frac.of(0)) for j in range(6)] for i in range(6)]
    rows = [A[i][:5] + [-A[i][5]] for i in range(5)]
    for c in range(5):
        piv = next((i for i in range(c, 5) if not red(rows[i][c]).is_zero()), None)
        if piv is None:
            raise ArithmeticError("Λ²M - κI has no pivot in a column: the plane is not normalised by its last "
                                  "coordinate")
        rows[c], rows[piv] = rows[piv], rows[c]
        inv = rows[c][c].inverse()
        rows[c] = [e * inv for e in rows[c]]
        for i in range(5):
            if i != c and not rows[i][c].is_zero():
                f = rows[i][c]
                rows[i] = [a - f * b for a, b in zip(rows[i], rows[c])]
    return [rows[i][5] for i in range(5)] + [Frac.of(1)]


def matvec(M, v, red) -> list:
    return [red(sum((flint_poly_to_frac(M[i][j]) * v[j] for j in range(len(v))), Frac.of(0))) for i in range(len(M))]


def _polynomial(F: Frac) -> bool:
    return F.den.total_degree() <= 0


@dataclass(frozen=True)
class Sextic:
    """What a word's analysis builds once: M_w (python-flint polynomials in r), W = Λ²M_w and the
    sextic cp(Λ²M_w) = det(κI - W) in the engine's ring (κ written λ)."""

    M: list
    W: list
    cp: object

    @classmethod
    def of(cls, word: str) -> Sextic:
        M = system_matrix_flint(of_particles(5), word)
        W = second_compound(M)
        return cls(M, W, charpoly_ring(W))


HALF_ROUTE = """The half route, for a word W = X·m(X) (m the mirror, a <-> d, b <-> c; every rotation of such a
word is one: rotating by k letters gives X'·m(X') with X' = X[k:]·m(X[:k])).  With J the reversal of the
gaps, J K_i J = K_{m(i)}, so M_W = M_{m(X)} M_X = J M_X J M_X = N² with N = J·M_X, of half the degree in r.

A datum (p(0), q(0)) on the face Y of W's last letter is *half-symmetric* when the run of X from it is
feasible and ends at J(α p(0), β q(0)) with α, β > 0.  Such a datum is a self-similar datum of W: the
dynamics commutes with J and with (p, q) -> (α p, β q) (time scaled by α/β > 0), so the run of m(X) from
J(α p(0), β q(0)) is the mirror image of X's run from (α p(0), β q(0)), feasible, and ends at
(α² p(0), β² q(0)): λ_W = β², μ_W = α².  In N's terms q(0) is an eigenvector of N for β, and the plane
Π = p(0) ∧ q(0) one of Λ²N for ν = αβ, on which N has the eigenvalues β and α: the κ route of this module
applied to (X, N, face Y) instead of (W, M_W), with the run over X's |X| collisions and N's quartic for
the other eigenvalues.  Stable: β > α > |ν'| for N's two other eigenvalues ν', which is β² > α² > |ν'|²,
W's criterion λ > μ > |ν| (the eigenvalues of M_W are the squares of N's).

Conversely a datum of W whose κ = λμ is a simple root of cp(Λ²M_W) is half-symmetric: Λ²N commutes with
Λ²M_W = (Λ²N)², so the κ-eigenplane Π is Λ²N-invariant and N acts on it with eigenvalues ±√λ, ±√μ;
q(t_X) = M_X q(0) = J N q(0) = ±√λ J q(0), and the first collision of m(X), pair m(i₁), needs
q_{m(i₁)}(t_X) = ±√λ q_{i₁}(0) < 0 where q_{i₁}(0) < 0: the sign is +; p(t_X) lies on JΠ and on the
face of X's last letter, the line of J p(0), as a positive multiple (the gaps are positive).  A stable
datum has κ simple (see REPEATED_NOT_STABLE): so the stable sets of the two routes are the same, and the
half route's existence and feasibility sets are those of the half-symmetric data (all data where κ is a
simple root of cp(Λ²M_W))."""


HALF_MARK = "; the half route: "        # in the explanation of a result of the half route


def half_of(word: str, particles: int = 5) -> str | None:
    """X when ``word`` = X·m(X) (m the mirror of ``particles`` particles), else None.  A rotation of
    X·m(X) is X'·m(X') (:data:`HALF_ROUTE`), so no other rotation need be tried."""
    n, odd = divmod(len(word), 2)
    return word[:n] if not odd and word[n:] == mirror(word[:n], particles) else None


def half_sextic(half: str) -> Sextic:
    """The :class:`Sextic` of the half route (:data:`HALF_ROUTE`): N = J·M_X (M_X's rows reversed),
    Λ²N and cp(Λ²N) = det(νI - Λ²N) in the engine's ring (ν written λ)."""
    M = system_matrix_flint(of_particles(5), half)
    N = [list(M[3 - i]) for i in range(4)]
    W = second_compound(N)
    return Sextic(N, W, charpoly_ring(W))


A_BLOCK = "abacbc"                      # A of the five-particle families (docs/particles.md)
FAMILY_CORES = {"F₁": "abc", "F₂": "abacbacbc"}     # F(k) = A^k·core·A^k·b: rotations of two atlas families


def family_word(core: str, k: int, j: int = 1) -> str:
    """The normal form of X·m(X) for X = F(k)·A^j = A^k·core·A^k·b·A^j (A = abacbc, ``core`` one of
    :data:`FAMILY_CORES`): the member (k, j) of a five-particle family, whose first half is a
    four-particle atlas word of particles 1-4 and second half its mirror image on particles 2-5."""
    X = A_BLOCK * k + core + A_BLOCK * k + "b" + A_BLOCK * j
    return normal_form(X + mirror(X))[0]


def sextic_factors(word: str, sextic: Sextic | None = None) -> list:
    """The irreducible factors of cp(Λ²M_w) in κ (over Q[r], monic: the sextic is monic), each with
    its multiplicity, as elements of the engine's ring (κ written λ)."""
    sextic = sextic or Sextic.of(word)
    _, terms = ring_to_mpoly(sextic.cp).factor()
    out = []
    for f, e in terms:
        if f.degrees()[1] == 0:
            continue                                   # a constant in κ (the sextic is monic: none but ±1)
        g = mpoly_to_ring(f)
        lead = g.coeff_wrt(RING.gens[0], g.degree(RING.gens[0]))
        if not lead.is_ground:
            raise ArithmeticError("a factor of the monic sextic with a leading coefficient in r")
        out.append((g.quo_ground(lead.LC), int(e)))
    return out


def five_candidate(word: str, factor=None, sextic: Sextic | None = None, face: str | None = None) -> FiveCandidate:
    """The κ-route candidate of a word of five particles (see the module's docstring), κ a root of
    ``factor`` (an irreducible factor of cp(Λ²M) of multiplicity 1, by default the sextic itself);
    ``sextic`` the word's :class:`Sextic` when the caller has it (not memoised: a census holds no
    candidate after its word).  The half route (:func:`half_sextic`): ``word`` is the half X of
    W = X·m(X), ``sextic`` N = J·M_X's and ``face`` W's last letter m(x_last), the face of p(0)."""
    sextic = sextic or Sextic.of(word)
    M, W = sextic.M, sextic.W
    ring_cp = sextic.cp if factor is None else factor      # det(κI - Λ²M), κ written λ in the ring
    red = Reducer(ring_cp)
    Pi = eigen_plane(W, red)
    common = Frac(Pi[0].den)
    for e in Pi[1:]:
        common = Frac(common.num * e.den / common.num.gcd(e.den)) if not e.den.is_one() else common
    Pi = [red(e * common) for e in Pi]
    if not all(_polynomial(e) for e in Pi) or all(e.is_zero() for e in Pi):
        raise ArithmeticError("the eigenvector of Λ²M did not clear its denominators")
    Y = alphabet(5).index(face or word[-1])
    p_hat = contract(Pi, Y)
    Mp = matvec(M, p_hat, red)
    MMp = matvec(M, Mp, red)
    j = next((j for j in range(4) if not Mp[j].is_zero()), None)
    if j is None:
        raise ArithmeticError("M p̂ vanishes")
    T, D = red(MMp[j] + LR_LAMBDA * p_hat[j]), Mp[j]          # t = T/D
    cp4 = [flint_poly_to_frac(flint.fmpq_poly(cf)) for cf in charpoly_coefficients(M)[1:]]
    return _candidate(word, M, ring_cp, red, Pi, Y, p_hat, Mp, T, D, cp4)


def _candidate(word: str, M, ring_cp, red: Reducer, Pi: list, Y: int, p_hat: list, Mp: list, T: Frac, D: Frac,
               cp4: list, kappa: Frac = LR_LAMBDA, repeated: bool = False) -> FiveCandidate:
    """The rest of a candidate of either route once the plane Π, p̂ = ι_Y Π, M p̂ and t = T/D are known:
    q̄ = D(M p̂ - μ p̂) affine in y = Dλ, the engine's position fixed point c y² = (a - d) y + b with
    c = 1, a = T, b = -κD², d = 0, and the run through the plane."""
    ext = Ext(T, D, red, kappa)
    q0 = [(red(D * Mp[k] - T * p_hat[k]), p_hat[k]) for k in range(4)]      # D(M p - μ p), y = Dλ
    a, b, c, d = (T, -ext.D2k, Frac.of(1), Frac.of(0))
    abcd_ring = tuple(_ring(e) for e in (a, b, c, d))
    abcd = tuple(frac_to_field(e) for e in (a, b, c, d))
    steps = run(word, Pi, q0, red)
    return FiveCandidate(word, M, FiveSpectrum(None, ring_cp), abcd, abcd_ring, T, D, p_hat, q0, cp4, ext, Y, steps,
                         repeated=repeated, plane=tuple(Pi))


def _ring(F: Frac):
    """A Frac with a constant denominator as an element of the engine's ring."""
    if not _polynomial(F):
        raise ValueError("not a polynomial")
    return lr_to_ring(F.num, int(F.den.coeffs()[0]))



def entry(P: list, k: int, m: int) -> Frac:
    """P_km of a bivector in the coordinates P_kl, k < l (:data:`PAIRS`), for any k ≠ m (P_mk = -P_km)."""
    return P[PAIRS.index((k, m))] if k < m else -P[PAIRS.index((m, k))]


def contract(P: list, i: int) -> list:
    """ι_i P: the vector (P_{li})_l (0 at l = i) of a bivector P = p ∧ q with p_i = 0, which is q_i·p
    (P_{li} = p_l q_i - p_i q_l)."""
    return [entry(P, m, i) if m != i else Frac.of(0) for m in range(4)]


def wedge_collide(letter: str, P: list, red) -> list:
    """Λ²K_i P: the bivector of the plane after the collision (K_i fixes the face of pair i
    pointwise, so p ∧ q ↦ p ∧ K_i q; certificate B1); K_i is the period matrix of the one-letter word."""
    return matvec(_collision_compound(letter), P, red)


@functools.cache
def _collision_compound(letter: str) -> list:
    """Λ²K_i for a letter of five particles (four of them: memoised)."""
    return second_compound(system_matrix_flint(of_particles(5), letter))


def run(word: str, Pi: list, q0: list, red) -> list:
    """The run through the plane: P_k = Λ²K_{i_k} P_{k-1} (free flight keeps p ∧ q), p̂_k = ι_{i_k} P_k =
    q_{i_k}(t_k⁺)·c·p(t_k) (c the scale of Π against p(0) ∧ q(0)), q̄(t_k) = K_{i_k} q̄(t_{k-1}) (q̄ a
    multiple of q(0), affine in y); [(letter, p̂_k, q̄(t_{k-1}), q̄(t_k))]."""
    letters = alphabet(5)
    P, q, out = list(Pi), list(q0), []
    for letter in word:
        i = letters.index(letter)
        P = wedge_collide(letter, P, red)
        before = q
        parts = [collide_gaps(letter, tuple(e[part] for e in q), LR_R) for part in (0, 1)]
        q = [(red(a), red(b)) for a, b in zip(*parts)]
        out.append((letter, contract(P, i), before, q))
    return out


def _req(name: str, u: tuple, sign: int) -> Requirement:
    return Requirement(name, (frac_to_field(u[0]), frac_to_field(u[1])), sign)


def requirements(cand: FiveCandidate) -> dict:
    """The requirements of each stage (see the module's docstring), in the order imposed:
    {"exists": [...], "feasible": [[...] per collision], "stable": [...]}.  With y = Dλ,
    T = Dt: λ > 0 is D y > 0, μ > 0 is D(T - y) > 0, λ - μ > 0 is D(2y - T) > 0, and D²(μ² ∓ …)
    are affine in y (D²μ² = T² - κD² - T y)."""
    Y, T, D, red, ext = cand.face, cand.T, cand.D, cand.ext.red, cand.ext
    zero = Frac.of(0)
    j0 = next(j for j in range(4) if j != Y and not cand.p0[j].is_zero())
    exists = [_req("λ", (zero, D), 1), _req("μ", (red(D * T), -D), 1)]
    exists += [_req(f"p_{j + 1}(0)", (red(cand.p0[j] * cand.p0[j0]), zero), 1) for j in range(4) if j not in (Y, j0)]
    feasible = []
    letters = alphabet(5)
    i1 = letters.index(cand.word[0])
    sign_q = cand.q0[i1]                  # the true q(0) is -sign(q̄_{i₁}(0)) q̄
    previous = Y
    for k, (letter, p, before, _after) in enumerate(cand.steps, 1):
        i = letters.index(letter)
        name = f"q_{i + 1}(t_{k - 1})·q̄_{i1 + 1}(0)" if k > 1 else f"q̄_{i1 + 1}(0)²"
        group = [_req(name, ext.mul(before[i], sign_q), 1)]
        # with the approach at k, p_m(t_k) has the sign of p̂_k,m · p̂_0,j₀
        group += [_req(f"p_{m + 1}(t_{k})", (red(p[m] * cand.p0[j0]), zero), 1) for m in range(4)
                  if m not in (i, previous)]
        feasible.append(group)
        previous = i
    if cand.repeated:                 # REPEATED_NOT_STABLE: nothing to impose, no branch is stable
        return {"exists": exists, "feasible": feasible, "stable": []}
    return {"exists": exists, "feasible": feasible, "stable": stable_requirements(cand)}


def other_factor(cand: FiveCandidate) -> tuple[Frac, Frac]:
    """(D s, D² p) for the other factor of cp(M) = (z² - tz + κ)(z² + sz + p) (s = c₁ + t,
    p = c₂ + ts - κ, t = T/D), reduced modulo the branch polynomial."""
    red, T, D = cand.ext.red, cand.T, cand.D
    Ds = red(cand.cp4[0] * D + T)
    return Ds, red(cand.cp4[1] * D * D + T * Ds - LR_LAMBDA * D * D)


def stable_requirements(cand: FiveCandidate) -> list:
    """λ - μ > 0 and Jury's criterion for z² + sz + p in the open disc of radius μ (the module's
    docstring), each times a positive power of D, affine in y = Dλ."""
    red, T, D = cand.ext.red, cand.T, cand.D
    Ds, D2p = other_factor(cand)
    D2mu2 = (red(T * T - LR_LAMBDA * D * D), -T)             # D² μ² = T² - κD² - T y
    sDmu = (red(Ds * T), -Ds)                                # D s · D μ
    return [_req("λ - μ", (red(-D * T), red(Frac.of(2) * D)), 1),
            _req("μ² - p", (D2mu2[0] - D2p, D2mu2[1]), 1),
            _req("μ² + sμ + p", (D2mu2[0] + sDmu[0] + D2p, D2mu2[1] + sDmu[1]), 1),
            _req("μ² - sμ + p", (D2mu2[0] - sDmu[0] + D2p, D2mu2[1] - sDmu[1]), 1)]


def mirror(word: str, particles: int = 5) -> str:
    """The word's mirror image: the particles numbered from the right (for five a <-> d, b <-> c)."""
    letters = alphabet(particles)
    return word.translate(str.maketrans(letters, letters[::-1]))


def normal_form(word: str, particles: int = 5) -> tuple[str, str]:
    """The least rotation of the word or of its mirror image (particles numbered from the right: for
    five a <-> d, b <-> c), and why it is the same orbit."""
    letters = alphabet(particles)
    image = mirror(word, particles)
    best = min((w[k:] + w[:k], w is image) for w in (word, image) for k in range(len(word)))
    pairs = ", ".join(f"{a}<->{b}" for a, b in zip(letters, letters[::-1]) if a < b)
    why = "the least rotation" + (f" of the mirror image ({pairs})" if best[1] else "")
    return best[0], why


def read_five(text: str) -> tuple[str, str]:
    """(normal form, explanation) of a five-particle word over a, b, c, d; UsageError (one line)
    for another letter, a pair twice in a row (cyclically), a pair never used, or a proper power."""
    from certify.dynamics.model import check_word
    from certify.errors import UsageError
    word = check_word("".join(str(text).split()), 5)
    if set(word) != set(alphabet(5)):
        raise UsageError(f"invalid pattern word {text!r}: a five-particle word uses every pair a, b, c, d")
    root, k = primitive_root(word)
    if k > 1:
        raise UsageError(f"invalid pattern word {text!r}: a proper power of {root!r}")
    return normal_form(word)


REPEATED_NOT_STABLE = """A factor f of cp(Λ²M) of multiplicity m > 1 holds no stable datum.  The roots of
cp(Λ²M) with multiplicity are the six products λ_iλ_j (i < j) of the eigenvalues of M, so at every r a root
κ of f is the product of two different index pairs.  A stable datum has κ = λμ with λ > μ > |ν| for the
two other eigenvalues ν, ν', hence |λμ| > |λν|, |λν'|, |μν|, |μν'|, |νν'|: λμ is the product of one index
pair only.  So no branch of f is stable, at any r; existence and feasibility on f are analysed on its planes
by :data:`REPEATED_ROUTE` (the plane is not the κ-eigenvector: the eigenspace of κ has dimension 2, or it is
not semisimple, where that route does not apply)."""


REPEATED_ROUTE = """The route of a repeated factor κ - κ₀(r) of cp(Λ²M) (κ₀ ∈ Q[r]; every repeated factor of the
census to 10 is one, κ₀ = ±r^(n/2)).  When cp(M) = (x² - t₁x + κ₀)(x² - t₂x + κ₀) (checked: c₃ = κ₀c₁ and
c₄ = κ₀², cp(M) = x⁴ + c₁x³ + c₂x² + c₃x + c₄), t₁ and t₂ are the roots of Q(t) = t² + c₁t + c₂ - 2κ₀, and
at every r where t₁ ≠ t₂ (Q's discriminant, a critical point of the analysis, is not zero):

* a datum with κ = λμ = κ₀ has its plane Π invariant under M, where M has x² - (λ + μ)x + κ₀, so
  λ + μ ∈ {t₁, t₂}: else λ, μ are λ₁, λ₃ (one root of each quadratic, the roots of x² - t_ix + κ₀
  named λ₁, λ₂ and λ₃, λ₄), and λ₁λ₃ = κ₀ = λ₁λ₂ = λ₃λ₄ gives λ₃ = λ₂ and λ₁ = λ₄ (κ₀ ≠ 0), t₁ = t₂;
* the two quadratics are coprime (a common root z has (t₁ - t₂)z = 0, z = 0, but κ₀ ≠ 0), so with
  t = λ + μ and t' = -c₁ - t the other root, Π = ker(M² - tM + κ₀) = im(M² - t'M + κ₀), of dimension
  2: its bivector is a non-zero column of Λ²(M² - t'M + κ₀), of rank 1, polynomial in (t, r);
* the rest is the κ-route's (the module's docstring) with t the branch, a real root of Q, in place of
  κ, y = λ (D = 1, T = t, y² = t y - κ₀), q̄ = M p̂ - (t - y) p̂, the same requirements for existence and
  feasibility; stability none (:data:`REPEATED_NOT_STABLE`).

Q irreducible over Q(r) is required (else ArithmeticError: not analysed), as are κ₀ ∈ Q[r] and the
factorisation of cp(M).  Π is the first column of Λ²(M² - t'M + κ₀) not zero modulo Q, divided by the
gcd of its entries: where it vanishes at one r, that r is not in any set (as for the κ-route's Π)."""


def repeated_candidate(word: str, factor, sextic: Sextic) -> FiveCandidate:
    """The candidate of :data:`REPEATED_ROUTE` for a repeated factor κ - κ₀(r) of cp(Λ²M_w) (monic in κ,
    as :func:`sextic_factors` gives it): the branch variable (λ in the engine's ring) is t = λ + μ, a root
    of Q(t) = t² + c₁t + c₂ - 2κ₀; ArithmeticError where the route does not apply."""
    M = sextic.M
    n, scale = _lr(ring_to_lrq(factor))
    if n.degrees()[0] != 1:
        raise ArithmeticError("a repeated factor of degree > 1 in κ")
    kappa = LR_LAMBDA - Frac(n, LRCTX.from_dict({(0, 0): int(scale)}))
    if not kappa.num.degrees()[0] == 0 or not _polynomial(kappa):
        raise ArithmeticError("a repeated factor κ - κ₀ with κ₀ not a polynomial in r")
    c1, c2, c3, c4 = [flint_poly_to_frac(flint.fmpq_poly(cf)) for cf in charpoly_coefficients(M)[1:]]
    if not (c3 == c1 * kappa and c4 == kappa * kappa):
        raise ArithmeticError("cp(M) is not (x² - t₁x + κ₀)(x² - t₂x + κ₀)")
    t = LR_LAMBDA
    Q = _ring(t * t + c1 * t + c2 - Frac.of(2) * kappa)
    _, terms = ring_to_mpoly(Q).factor()
    if [int(e) for f, e in terms if f.degrees()[1] > 0] != [1] or ring_to_mpoly(Q).degrees()[1] != 2:
        raise ArithmeticError("Q(t) = t² + c₁t + c₂ - 2κ₀ is reducible over Q(r)")
    red = Reducer(Q)
    Mf = [[flint_poly_to_frac(e) for e in row] for row in M]
    M2 = matmul(Mf, Mf)
    other = c1 + t                                       # -t' = c₁ + t
    B = [[red(M2[i][j] + other * Mf[i][j] + (kappa if i == j else Frac.of(0))) for j in range(4)] for i in range(4)]
    W = [[red(e) for e in row] for row in second_compound(B)]
    column = next((col for col in range(6) if not all(W[k][col].is_zero() for k in range(6))), None)
    if column is None:
        raise ArithmeticError("Λ²(M² - t'M + κ₀) vanishes modulo Q")
    Pi = [W[k][column] for k in range(6)]
    if not all(_polynomial(e) for e in Pi):
        raise ArithmeticError("the plane of the repeated factor has a denominator")
    scale = functools.reduce(lambda a, b: a.lcm(b), (flint.fmpz(e.den.coeffs()[0]) for e in Pi))
    Pi = [e * Frac.of(scale) for e in Pi]                # integer coefficients, then their gcd divided out
    g = functools.reduce(lambda a, b: a.gcd(b), (e.num for e in Pi if not e.is_zero()))
    Pi = [Frac(e.num / g) if not e.is_zero() else e for e in Pi]
    Y = alphabet(5).index(word[-1])
    p_hat = contract(Pi, Y)
    if all(e.is_zero() for e in p_hat):
        raise ArithmeticError("the plane of the repeated factor contracts to zero")
    # y = λ, t = λ + μ: T = t, D = 1
    return _candidate(word, M, Q, red, Pi, Y, p_hat, matvec(M, p_hat, red), t, Frac.of(1), [c1, c2, c3, c4], kappa,
                      repeated=True)


def impose(an: Analysis, q: Requirement) -> None:
    """``an.impose(q)``, and for a requirement identically zero on the branches (G₀ = G₁ = 0 modulo the
    branch polynomial: a gap that stays closed, met on repeated factors) the strict sign held nowhere."""
    if all(g == FIELD.zero for g in q.G):
        for R in an.regions:
            R.pieces = []
        an.imposed.append(q)
    else:
        an.impose(q)


def _kept(shared: dict | None, key: tuple, make):
    """``make()``, kept in ``shared`` under ``key`` when ``shared`` is given (see :func:`built`)."""
    if shared is None:
        return make()
    if key not in shared:
        shared[key] = make()
    return shared[key]


def built(word: str, shared: dict | None = None) -> tuple[Sextic, list]:
    """The :class:`Sextic` of a normal form and its factors (:func:`sextic_factors`), kept in ``shared``
    when given: a dict the caller holds for one word, so that two analyses of it (the census's two parts)
    build them once."""
    def make():
        sextic = Sextic.of(word)
        return sextic, sextic_factors(word, sextic)
    return _kept(shared, ("sextic", word), make)


def shared_candidate(word: str, factor, sextic: Sextic, shared: dict | None = None) -> FiveCandidate:
    """:func:`five_candidate` of ``word`` for ``factor``, kept in ``shared`` when given (see :func:`built`):
    the second analysis gets the same candidate, whose spectrum has memoised the resultants, the sign
    tables and the branches at critical values that the first one computed (each exact: the same answers)."""
    return _kept(shared, ("candidate", word, factor), lambda: five_candidate(word, factor, sextic))


def analyse_five(text: str, lo=0, hi=1, progress=None, half: bool = False, shared: dict | None = None):
    """The exact analysis of a five-particle word over ]lo, hi[ (certified like
    :func:`.pattern.analyse`: the κ-route candidate, the requirements of :func:`requirements`
    imposed by :class:`.feasibility.Analysis`), as a :class:`.pattern.PatternResult`.  ``half``: the
    word is X·m(X) and the analysis is the half route's (:data:`HALF_ROUTE`: the same stable set, from
    N = J·M_X of half the degree and a run of |X| collisions); UsageError for another word.  ``shared``:
    see :func:`built` (not used by the half route)."""
    import time

    from certify.algebra.branches import BRANCH_NAMES
    from certify.algebra.poly import mpoly_to_univariate, show_collected, show_factored
    from certify.errors import UsageError

    start = time.perf_counter()
    lo, hi = check_range(lo, hi)
    normal, why = read_five(text)
    X = half_of(normal) if half else None
    if half and X is None:
        raise UsageError(f"--half: {text!r} is not X·m(X) up to rotation (m the mirror a <-> d, b <-> c)")
    if X is not None:
        why += f"{HALF_MARK}W = X·m(X), X = {X}, M_W = N², N = J·M_X (J the reversal of the gaps)"
    if X is not None:
        sextic = half_sextic(X)
        factors = sextic_factors(normal, sextic)
    else:
        sextic, factors = built(normal, shared)
    run_word, face = (X, normal[-1]) if X is not None else (normal, None)
    not_analysed: list = []
    regions: dict = {"exists": [], "feasible": [], "stable": []}
    sets: dict = {"exists": [], "feasible": [], "stable": []}
    undecided: list = []
    conditions: dict = {}
    cands = []
    tick = progress or (lambda k, n, label="": None)
    for number, (factor, multiplicity) in enumerate(factors, 1):
        label = f"factor {number} of cp(Λ²M), " if len(factors) > 1 else ""
        kappa = show_collected(factor, "λ").replace("λ", "κ")
        try:
            if multiplicity > 1 and X is not None:
                raise ArithmeticError("the half route's proof needs κ simple")
            simple = factor if len(factors) > 1 else None
            cand = (repeated_candidate(run_word, factor, sextic) if multiplicity > 1    # REPEATED_ROUTE: never stable
                    else five_candidate(run_word, simple, sextic, face) if X is not None    # the half route's N
                    else shared_candidate(run_word, simple, sextic, shared))
        except ArithmeticError as e:
            if multiplicity == 1:
                not_analysed.append({"factor": kappa, "multiplicity": 1, "stable": f"not analysed: {e}"})
                undecided.append(f"{label}on all of ]{lo}, {hi}[: {e} (not analysed)")
                continue
            # never stable there (REPEATED_NOT_STABLE); existence and feasibility not analysed
            not_analysed.append({"factor": kappa, "multiplicity": multiplicity, "stable": "none (proved)"})
            undecided.append(f"{label}κ a root of multiplicity {multiplicity} of cp(Λ²M) on all of ]{lo}, {hi}[: "
                             f"its eigenplane is not unique (not analysed: {e}; never stable: a multiple eigenvalue "
                             "of Λ²M is not strictly dominant)")
            continue
        if cand.repeated:
            label = f"factor {number} of cp(Λ²M) ({kappa} = 0, multiplicity {multiplicity}; t = λ + μ), "
        cands.append(cand)
        reqs = requirements(cand)
        total = len(reqs["feasible"]) + 2
        an = Analysis(cand, lo, hi)
        stage_regions = {}
        for q in reqs["exists"]:
            impose(an, q)
        stage_regions["exists"] = _copy(an.regions)
        tick(1, total, "exists")
        for m, group in enumerate(reqs["feasible"], 1):
            for q in sorted(group, key=lambda q: q.has_x):
                impose(an, q)
            tick(1 + m, total, f"collision {m} of {len(reqs['feasible'])}")
        stage_regions["feasible"] = _copy(an.regions)
        for q in reqs["stable"]:
            an.impose(q)
        # REPEATED_NOT_STABLE: no branch of a repeated factor is stable
        stage_regions["stable"] = ([Region(R.branch, R.fixed_point, [], [], []) for R in an.regions] if cand.repeated
                                   else _copy(an.regions))
        tick(total, total, "stable")
        for stage, rs in stage_regions.items():
            regions[stage] += rs
            sets[stage] += [dict(d, branch=label + d["branch"]) for d in _nonempty(rs)]
        if not cand.repeated or not conditions:     # a simple factor's conditions, when the word has one
            conditions = {"exists": [_cond(q) for q in reqs["exists"]] + ["λ real"],
                          "feasible": [_cond(q) for g in reqs["feasible"] for q in g],
                          "stable": [_cond(q) for q in reqs["stable"]] if not cand.repeated else
                          ["none on a repeated factor (REPEATED_NOT_STABLE)"]}
        names = [BRANCH_NAMES[R.branch] if R.branch < len(BRANCH_NAMES) else f"κ{R.branch}" for R in an.regions]
        undecided += sorted({f"{label}{name} {R.fixed_point} at {_short(rc)}: {why_}"
                             for name, R in zip(names, an.regions) for rc, why_ in R.undecided})
    if not conditions:
        conditions = {stage: [] for stage in ("exists", "feasible", "stable")}

    def printed():
        M = [[show_factored(e) for e in sextic.M[i]] for i in range(4)]
        datum = {"κ": "λμ, a root of cp(Λ²M) (the branch)", "λ": "x = (T ± √(T² - 4κD²))/(2D) (x₊, x₋: the two "
                 "orderings of the pair)", "p(0)": "ι_Y Π, Π the κ-eigenvector of Λ²M, Y the last letter's gap",
                 "q(0)": "∝ M p(0) - μ p(0), q of the first letter's gap < 0"}
        if X is not None:
            datum = {"ν": "αβ, a root of cp(Λ²N) (the branch); κ = ν², λ = β², μ = α² for M_W = N²",
                     "β": "x = (T ± √(T² - 4νD²))/(2D) (x₊, x₋: the two orderings of the pair)",
                     "p(0)": "ι_Y Π, Π the ν-eigenvector of Λ²N, Y the last letter's gap",
                     "q(0)": "∝ N p(0) - α p(0), q of the first letter's gap < 0; the run over X only"}
        if any(c.repeated for c in cands):
            datum["t"] = ("on a repeated factor κ - κ₀ of cp(Λ²M): λ + μ, a root of Q(t) = t² + c₁t + c₂ - 2κ₀ (the "
                          "branch), λ = (t ± √(t² - 4κ₀))/2, Π a column of Λ²(M² - t'M + κ₀), t' = -c₁ - t "
                          "(REPEATED_ROUTE)")
        return M, show_factored(primitive(mpoly_to_univariate(ring_to_mpoly(sextic.cp).discriminant("lam")))), datum
    cp_text = lambda: show_collected(sextic.cp, "λ").replace("λ", "κ")  # noqa: E731
    res = FiveResult(text, normal, "five", why, (lo, hi), cp_text, sets["exists"], sets["feasible"], sets["stable"],
                     undecided, conditions, None, "", 0.0, regions, printed)
    res.not_analysed, res.half = not_analysed, X
    res.verdict = verdict(res)
    if not_analysed:          # the verdict speaks of the factors analysed only: say which are not
        res.verdict = (f"{res.verdict}; on all of ]{lo}, {hi}[, not analysed: the factor(s) "
                       + ", ".join(f"{n['factor']} (multiplicity {n['multiplicity']})" for n in not_analysed)
                       + " of cp(Λ²M)")
    res.seconds = time.perf_counter() - start
    return res



class FiveResult(PatternResult):
    """The :class:`.pattern.PatternResult` of a five-particle word: cp is the sextic cp(Λ²M) in κ = λμ,
    and stability is λ > μ > |ν| (its Markdown names them; the JSON's fields are the pattern schema's)."""

    not_analysed: list        # the factors of cp(Λ²M) not analysed: {"factor", "multiplicity", "stable"}
    half: str | None = None   # X of the half route (W = X·m(X), M_W = N², N = J·M_X), or None

    def markdown(self) -> str:
        text = super().markdown()
        M, k, kappa = ("N", "ν", "ν = αβ (N = J·M_X, M_W = N²)") if self.half else ("M", "κ", "κ = λμ")
        for old, new in (("cp(M) = `", f"cp(Λ²{M}) in {kappa} = `"), ("disc_λ cp(M) = `", f"disc_{k} cp(Λ²{M}) = `"),
                         ("## Stable (λ dominant, fixed point attracting)",
                          "## Stable (λ > μ > |ν| for the other eigenvalues ν: λ dominant, the plane attracting)")):
            text = text.replace(old, new, 1)
        return text


def word_classes(max_length: int, particles: int = 5):
    """One word per class (rotations, mirror image) of the periods of N particles of N - 1 to max_length
    collisions: every pair used, no pair twice in a row (cyclically), not a proper power; each its
    :func:`normal_form`, shortest first, then in lexicographic order.  Every class has a rotation
    starting with a, so the words starting with a and never repeating a letter (3^(n-1) of them for five
    particles, not 4^(n-1)) are enough."""
    letters = alphabet(particles)
    for n in range(len(letters), max_length + 1):
        found = set()
        stack = ["a"]
        while stack:
            w = stack.pop()
            if len(w) < n:
                stack += [w + x for x in letters if x != w[-1]]
            elif w[-1] != w[0] and len(set(w)) == len(letters) and primitive_root(w)[1] == 1:
                found.add(normal_form(w, particles)[0])
        yield from sorted(found)


def census_record(word: str, shared: dict | None = None) -> dict:
    """The record of one word of the five-particle census (the job :func:`certify.run.census5.run`
    hands its executor; ``word`` a normal form): :func:`analyse_five` over ]0, 1[, timed once.  Its
    certified sets (``exists``, ``feasible``, ``stable``, as r-set texts), its undecided points, the
    factors of cp(Λ²M) not analysed (``not_analysed``, from the analysis, not from its messages), and the
    largest r of each (``top``: the largest upper end or isolated point of the set, exact; for
    ``undecided`` the largest undecided point of the stable stage).  ``seconds``, the CPU seconds of the
    analysis (``time.process_time``: the measure on a shared machine), is kept in the state file only
    (:data:`certify.patterns.census.SECONDS`): the rest is the same bytes on a rerun.  ``shared``: see
    :func:`built`."""
    import time

    from .census import SECONDS
    start = time.process_time()
    res = analyse_five(word, shared=shared)
    rec = {"word": word, "length": len(word), "verdict": str(res.verdict),
           "exists": [s["set"] for s in res.exists], "feasible": [s["set"] for s in res.feasible],
           "stable": [s["set"] for s in res.stable], "undecided": list(res.undecided),
           "not_analysed": list(res.not_analysed), "top": {}}
    for stage in ("stable", "feasible", "undecided"):
        if stage == "undecided":
            tops = [rc for R in res.regions["stable"] for rc, _ in R.undecided]
        else:
            tops = [w.hi for w in res.intervals(stage)] + [at for *_, at in res.points(stage)]
        rec["top"][stage] = top_data(tops)
    rec[SECONDS] = round(time.process_time() - start, 3)
    return rec


def top_data(ends) -> dict | None:
    """The largest of exact end points (compared by :func:`certify.algebra.branches.less`) as
    :func:`.pattern.end_data` prints it, or None for none: a census record's ``top``."""
    best = None
    for end in ends:
        if best is None or less(best, end):
            best = end
    return None if best is None else end_data(best)
