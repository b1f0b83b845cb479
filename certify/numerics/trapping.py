"""Certified trapping neighbourhoods of an attracting periodic orbit of the reduction.

``trap(word, r)`` proves, for a word w = c_1 … c_L (c_0 = c_L, the contact the period
starts from; the normal form of ``certify orbit`` ends with b) and a rational r, a
theorem of this form:

    *U is a closed ellipse of oriented normals at the contact c_0 such that every
    orbit of the reduction (Section 4, :mod:`certify.dynamics.reduction`) that is at
    (c_0, n) with n ∈ U follows the word w for ever, every contact decided strictly,
    and converges, at the rate κ < 1 per period, to the periodic orbit (c_0, n*),
    n* ∈ U the unique fixed point of the return map in U.*

**The chart.**  With t = ORIENTATION[c_0] (the paper's orientation, l. 950: e_t · n > 0)
a state at c_0 is a point of the affine chart {n_t = 1}.  U = {c + T u : |u| ≤ ρ}, with
c a rational centre (c_t = 1), T a rational 3x2 frame (its row t zero, its other rows
invertible) and ρ a rational radius; |·| is the Euclidean norm of u ∈ R².  Everything
below is exact in Q (the matrices, c, T, ρ and every coefficient) except norms, which are
arb balls (python-flint, rigorous enclosures); a condition holds only when the ball
proves it.  No float enters the proof; floats are not used at all (the choice of c, T
and ρ is made with arb midpoints and rounded to rationals, and needs no rigour: it is
what is then checked).

**The walls: the word is realised on U.**  Let P_0 = I and P_k = cof(K_{c_k}) P_{k-1},
each cof(K) the positive integer multiple of det(K) K^{-T} of
:func:`~certify.dynamics.reduction.cofactor`; N = P_L is a positive multiple of
N_w = cof(M_w).  The reduction started at (c_0, n) is, step by step
(:func:`~certify.dynamics.reduction._next_letter_exact`, :func:`~.reduction.canonical`):
at the state (c_k, m), i = INDEX[c_k], the position lies inside the face iff m_{i+1} and
-m_{i+2} have the same non-zero sign; with the orientation m_{i+1} > 0 the next contact is
the cyclic successor of c_k iff m_i > 0, the other one iff m_i < 0; the new normal is
cof(K_j) m, flipped iff its component ORIENTATION[j] is negative.  So if, for
k = 0 … L-1, the linear forms

    orientation  e_{i+1} · P_k n > 0,   face  -e_{i+2} · P_k n > 0,   direction  σ_k e_i · P_k n > 0

(σ_k = +1 when c_{k+1} is the cyclic successor of c_k, -1 otherwise), and at k = L the
orientation e_t · N n > 0, all hold, then by induction the reduction's state k is
(c_k, a positive multiple of P_k n) for k = 0 … L: the letters are exactly w, every sign
decided strictly, no re-orientation.  A linear form ℓ is positive on U iff
ℓ(c) - ρ |Tᵀℓ| > 0 (the minimum of ℓ(c + Tu) over |u| ≤ ρ); ℓ(c) is an exact rational,
|Tᵀℓ| a ball: each wall is checked in arb, rigorously, on the whole of U.

**The return map sends U into itself.**  After one period the state is (c_0, N n up to a
positive factor); in the chart F(n) = N n / (N n)_t.  In the frame, with a = N c,
B = N T, α = a_t, β = B_t (a row), S the inverse of T's rows other than t (all exact):

    g(u) = S (F(c + Tu) - c) = (g_0 + A u) / (α + β u),   g_0 = S (a - α c),  A = S (B - c β).

The denominator α + β u ≥ α - |β| ρ > 0 on U (it is the wall at k = L).  Hence, on
|u| ≤ ρ, |g(u)| ≤ R := (|g_0| + ‖A‖ ρ) / (α - |β| ρ), and the Jacobian
Dg = A/d - (g_0 + Au) βᵀ/d² has ‖Dg‖ ≤ κ := ‖A‖/(α - |β|ρ) + R |β|/(α - |β|ρ)
(‖A‖ the spectral norm, bounded in arb by the closed form of a 2x2 matrix).  The
certificate requires R < ρ (F(U) strictly inside U) and κ < 1.

**The theorem.**  U is convex, so by the mean value inequality F is a κ-contraction of U
(in the frame norm) mapping U into itself: by Banach's theorem it has exactly one fixed
point n* ∈ U, and F^m(n) → n* with |F^m(n) - n*| ≤ κ^m |n - n*|.  n* is a real
eigenvector of N_w whose state realises w (the walls): it is the periodic orbit of the
reduction with word w, and, its multipliers being eigenvalues of DF(n*) of modulus
≤ κ < 1, the attracting one (λ_x the smallest eigenvalue of M_w in modulus,
``certify orbit``).  Every orbit that enters U at the contact c_0 stays on the walls'
side for ever (F(U) ⊂ U), so it follows w for ever and converges to n*.  Also
|u*| ≤ |g(0)| / (1 - κ) = |g_0| / (α (1 - κ)): the centre is that close to n*.

**The choice of U** (heuristics, then checked).  The centre: the eigenvector of N for its
eigenvalue of largest modulus, which must be strictly dominant (N_w's eigenvalues are
det M_w/λ: the attracting orbit is the dominant one; otherwise no orbit of w attracts at
r, and :func:`attempt` says so).  The frame: the real Jordan basis of DF(c) in the
chart, a rotation-scaling block [[a, b], [-b, a]] for a complex pair (multipliers
λ_x/λ_y, λ_x/λ̄_y), diagonal for a real pair, so that ‖A‖/α is about the spectral
radius |ν| and an ellipse contracts even where a box would not.  The radius: 4/5 of the
distance to the nearest wall, shrunk by 4/5 until everything is proved, then enlarged by
bisection towards the last refused radius.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import flint

from certify.algebra.balls import precision
from certify.dynamics.model import INDEX, LETTERS, check_word
from certify.dynamics.particles import check_r
from certify.dynamics.reduction import ORIENTATION, cofactor
from certify.errors import UsageError

PREC = 256               # working precision of the balls (bits)
FRAME_BITS = 64          # the frame T and the radius ρ: dyadic rationals with this many bits
SHRINK = flint.fmpq(4, 5)
TRIES = 80
BISECTIONS = 10         # then the radius is enlarged by bisection towards a refused one
SIEVE_MARGIN = 1e-9     # :meth:`Trap.surely_outside`: the float64 margin, relative to the scale of |u|² and ρ²


@dataclass(frozen=True)
class Wall:
    """A linear form ℓ (exact rationals) that must be > 0 on U: one sign decided by the
    reduction at the state k of the word."""

    name: str
    row: tuple


@dataclass(frozen=True)
class Trap:
    """A certified trapping ellipse U = {centre + T u : |u| ≤ radius} at the contact
    ``word[-1]`` (module docstring): exact rationals, bounds as rational upper bounds."""

    word: str
    r: flint.fmpq
    centre: tuple            # c, 3 rationals, c_t = 1 (t = ORIENTATION[word[-1]])
    frame: tuple             # T, two columns of 3 rationals, zero at t
    radius: flint.fmpq       # ρ
    contraction: flint.fmpq  # κ: F is a κ-contraction of U in the frame norm
    image: flint.fmpq        # R/ρ: F(U) lies in the ellipse of radius (R/ρ)·ρ
    distance: flint.fmpq     # |u*| ≤ distance: n* lies that close to the centre
    inner: flint.fmpq        # U contains the chart disc of this radius around c
    outer: flint.fmpq        # and lies in the chart disc of this radius
    pair: str                # "complex" or "real": the frame's block

    @property
    def chart(self) -> int:
        return ORIENTATION[self.word[-1]]

    def coordinates(self, n) -> tuple:
        """u with n ∝ c + T u (n a rational normal with n_t ≠ 0), exactly."""
        t = self.chart
        n = [flint.fmpq(z) / flint.fmpq(n[t]) for z in n]
        f = _free(t)
        d = [n[k] - self.centre[k] for k in f]
        (p, q), (s, v) = [[self.frame[j][k] for j in range(2)] for k in f]
        det = p * v - q * s
        return ((v * d[0] - q * d[1]) / det, (p * d[1] - s * d[0]) / det)

    def contains(self, n) -> bool:
        """Whether the rational normal n (any positive multiple) lies in U, exactly."""
        if flint.fmpq(n[self.chart]) <= 0:
            return False
        u = self.coordinates(n)
        return u[0] ** 2 + u[1] ** 2 <= self.radius ** 2

    def ball_sign(self, n) -> int:
        """For a ball vector n (arb, or exact) containing a positive multiple of a normal at
        the contact ``word[-1]``: +1 when every point of the ball lies in U (ρ² − |u|² > 0
        proved, with n_t > 0 proved), −1 when every point lies outside, 0 when the balls do
        not decide.  Exact rationals for c and T, arb for n (at the caller's precision)."""
        if not n[self.chart] > 0:
            return 0
        u = self.ball_coordinates(n)
        gap = self.radius * self.radius - (u[0] * u[0] + u[1] * u[1])     # x * x: arb's x ** 2 is nan at 0 ± ε
        return 1 if gap > 0 else -1 if gap < 0 else 0

    @cached_property
    def _floats(self) -> tuple:
        """c, T (rows of the two free coordinates), the norm of T⁻¹ and ρ, rounded to float64 once."""
        f = _free(self.chart)
        c = tuple(float(self.centre[k]) for k in f)
        (p, q), (s, v) = [[float(self.frame[j][k]) for j in range(2)] for k in f]
        det = p * v - q * s
        norm = (abs(p) + abs(q) + abs(s) + abs(v)) / abs(det) if det else math.inf
        return c, (p, q, s, v, det), norm, float(self.radius)

    def surely_outside(self, n) -> bool:
        """A sieve before :meth:`ball_sign` (which proves): True only when ``ball_sign(n)`` is
        certainly not +1.  The coordinates u of the midpoints of the ratio balls n_k / n_t (the
        balls :meth:`ball_coordinates` divides, at the caller's precision), computed in float64:
        when |u|² exceeds ρ² by :data:`SIEVE_MARGIN` times the scale of the terms (far above the
        rounding of float64 and of the midpoints), a point of the coordinate balls lies outside U,
        so ρ² − |u|² > 0 is not proved for the whole ball.  False (decide by ball_sign) whenever
        the floats are not finite."""
        t = self.chart
        c, (p, q, s, v, det), norm, rho = self._floats
        if not det:
            return False
        a, b = (float(n[k] / n[t]) for k in _free(t))
        d0, d1 = a - c[0], b - c[1]
        u0, u1 = (v * d0 - q * d1) / det, (p * d1 - s * d0) / det
        gap = u0 * u0 + u1 * u1 - rho * rho
        scale = (norm * (abs(a) + abs(b) + abs(c[0]) + abs(c[1])) + abs(u0) + abs(u1) + rho) ** 2
        return gap > SIEVE_MARGIN * scale       # False for nan and inf

    def ball_coordinates(self, n) -> tuple:
        """Balls containing u with n ∝ c + T u, for a ball vector n (n_t ≠ 0): the frame
        coordinates of :meth:`coordinates` in arb, at the caller's precision."""
        t = self.chart
        m = [flint.arb(z) / n[t] for z in n]
        f = _free(t)
        d = [m[k] - self.centre[k] for k in f]
        (p, q), (s, v) = [[self.frame[j][k] for j in range(2)] for k in f]
        det = p * v - q * s
        return ((v * d[0] - q * d[1]) / det, (p * d[1] - s * d[0]) / det)

    def image_bound(self) -> tuple:
        """(|g_0|, ‖A‖, α, |β|) of the return map in the frame (module docstring), balls at
        the caller's precision: |g(u)| ≤ R(|u|) = (|g_0| + ‖A‖ |u|)/(α − |β| |u|) on U."""
        g0, A, alpha, beta = _return_map(products(self.word, self.r)[-1], self.centre, self.frame, self.chart)
        return _norm(g0), _spectral(A), flint.arb(alpha), _norm(beta)

    def lines(self) -> list[str]:
        """The summary, then the exact data of U (centre and frame to 12 digits, ρ exact)."""
        def vec(v):
            return "(" + ", ".join(_dec(z, 12) for z in v) + ")"
        return [self.summary(), f"centre c = {vec(self.centre)}",
                f"frame T = [{vec(self.frame[0])}, {vec(self.frame[1])}] (columns)",
                f"radius ρ = {self.radius} (exact)"]

    def summary(self) -> str:
        t = "xyz"[self.chart]
        return (f"{self.word} at r = {self.r}: certified trapping ellipse U at contact {self.word[-1]} "
                f"(chart n_{t} = 1, "
                f"{self.pair} frame) of radius ρ = {_dec(self.radius)} (contains the chart disc of radius "
                f"{_dec(self.inner)}, inside that of radius {_dec(self.outer)}); F(U) ⊂ {_dec(self.image)}·U, "
                f"contraction κ ≤ {_dec(self.contraction)} per period; n* within {_dec(self.distance)} of the centre: "
                f"every orbit entering U follows {self.word} for ever and converges to the periodic orbit")


def _dec(q: flint.fmpq, digits: int = 6) -> str:
    """A certified rational printed with ``digits`` significant digits (for reading only)."""
    with precision(64):
        return flint.arb(q).str(digits, radius=False)


def _free(t: int) -> tuple:
    return ((t + 1) % 3, (t + 2) % 3)


def _dyadic(x: flint.arb, bits: int = FRAME_BITS) -> flint.fmpq:
    """A dyadic rational near the midpoint of x (a choice, not a bound)."""
    m = x.mid().fmpq()
    return flint.fmpq((m.p * 2 ** bits) // m.q, 2 ** bits)


def _upper(x: flint.arb) -> flint.fmpq:
    """An exact rational ≥ every point of the ball x."""
    return x.mid().fmpq() + x.rad().fmpq()


def _lower(x: flint.arb) -> flint.fmpq:
    """An exact rational ≤ every point of the ball x."""
    return x.mid().fmpq() - x.rad().fmpq()


# ------------------------------------------------------------------ the exact data
def products(word: str, r) -> list:
    """[P_0, …, P_L] (fmpz_mat): P_0 = I, P_k = cof(K_{c_k}) P_{k-1}, positive multiples."""
    out = [flint.fmpz_mat(3, 3, [1, 0, 0, 0, 1, 0, 0, 0, 1])]
    for letter in word:
        out.append(flint.fmpz_mat([list(row) for row in cofactor(letter, r)]) * out[-1])
    return out


def walls(word: str, P: list) -> list[Wall]:
    """The linear forms of the module docstring (orientation, face, direction at each
    state k = 0 … L-1, orientation at the return)."""
    letters = word[-1] + word
    out = []

    def row(k, m, s):
        return tuple(flint.fmpq(s * P[k][m, j]) for j in range(3))
    for k in range(len(word)):
        i = INDEX[letters[k]]
        sigma = 1 if INDEX[letters[k + 1]] == (i + 1) % 3 else -1
        out += [Wall(f"orientation at state {k} ({letters[k]})", row(k, (i + 1) % 3, 1)),
                Wall(f"face at state {k} ({letters[k]})", row(k, (i + 2) % 3, -1)),
                Wall(f"contact {k + 1} ({letters[k + 1]})", row(k, i, sigma))]
    out.append(Wall(f"orientation at the return ({letters[0]})", row(len(word), ORIENTATION[letters[0]], 1)))
    return out


def _dot(a, b):
    """a · b, exact (rationals: the order of the terms does not matter)."""
    if len(a) == 3:
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    return sum((x * y for x, y in zip(a, b)), flint.fmpq(0))


def _norm(v) -> flint.arb:
    return sum((flint.arb(z) * flint.arb(z) for z in v), flint.arb(0)).sqrt()


def _spectral(A) -> flint.arb:
    """An enclosure of ‖A‖₂ for a rational 2x2 A: σ² = (f + √(f² - 4d²))/2, f the squared
    Frobenius norm, d = det A (f² - 4d² ≥ 0; its ball is made non-negative by abs)."""
    f = flint.arb(sum(z * z for row in A for z in row))
    d = flint.arb(A[0][0] * A[1][1] - A[0][1] * A[1][0])
    return ((f + abs(f * f - 4 * d * d).sqrt()) / 2).sqrt()


def _return_map(N, c, T, t) -> tuple:
    """(g_0, A, α, β) of the module docstring, exact rationals."""
    f = _free(t)
    Nq = [[flint.fmpq(N[i, j]) for j in range(3)] for i in range(3)]
    a = [_dot(Nq[i], c) for i in range(3)]
    B = [[_dot(Nq[i], T[j]) for j in range(2)] for i in range(3)]
    alpha, beta = a[t], B[t]
    (p, q), (s, v) = [[T[j][k] for j in range(2)] for k in f]
    det = p * v - q * s
    S = ((v / det, -q / det), (-s / det, p / det))
    x = [a[k] - alpha * c[k] for k in f]
    Y = [[B[k][j] - c[k] * beta[j] for j in range(2)] for k in f]
    g0 = tuple(S[m][0] * x[0] + S[m][1] * x[1] for m in range(2))
    A = tuple(tuple(S[m][0] * Y[0][j] + S[m][1] * Y[1][j] for j in range(2)) for m in range(2))
    return g0, A, alpha, beta


# ------------------------------------------------------------------ the choice of U
def dominant_normal(N, t: int) -> tuple | str:
    """A rational approximation c (c_t = 1) of the eigenvector of N for its eigenvalue of
    strictly largest modulus, or the reason why there is none."""
    roots = [z for z, _m in N.charpoly().complex_roots()]
    roots.sort(key=lambda z: abs(z).mid(), reverse=True)
    if not abs(roots[0]) > abs(roots[1]):
        return ("N_w has no eigenvalue of strictly largest modulus at this r (λ_x is not strictly the smallest "
                "eigenvalue of M_w in modulus): no periodic orbit of the reduction with this word attracts")
    alpha = roots[0].real
    rows = [[flint.arb(N[i, j]) - (alpha if i == j else 0) for j in range(3)] for i in range(3)]
    cands = [_cross(rows[i], rows[j]) for i, j in ((0, 1), (0, 2), (1, 2))]
    v = max(cands, key=lambda w: abs(w[t]).mid())
    if not (v[t] > 0 or v[t] < 0):
        return "the dominant eigenvector of N_w has n_t = 0: not a state inside a face"
    return tuple(flint.fmpq(1) if k == t else _dyadic(v[k] / v[t], PREC - 32) for k in range(3))


def _cross(v, w) -> tuple:
    return (v[1] * w[2] - v[2] * w[1], v[2] * w[0] - v[0] * w[2], v[0] * w[1] - v[1] * w[0])


def frame(N, c, t: int) -> tuple[tuple, str]:
    """A rational frame T adapted to DF(c) (the real Jordan basis), and its pair type."""
    f = _free(t)
    E = tuple(tuple(flint.fmpq(1 if k == m else 0) for k in range(3)) for m in f)
    _g0, D, alpha, _beta = _return_map(N, c, E, t)
    d = [[flint.arb(z) / flint.arb(alpha) for z in row] for row in D]
    tr, det = d[0][0] + d[1][1], d[0][0] * d[1][1] - d[0][1] * d[1][0]
    disc = tr * tr - 4 * det
    if disc.mid() < 0:
        a, b = tr / 2, (-disc).sqrt() / 2
        cols, pair = ((d[0][1], a - d[0][0]), (flint.arb(0), b)), "complex"
    else:
        s = abs(disc).sqrt()
        cols = tuple((d[0][1], (tr + e * s) / 2 - d[0][0]) for e in (1, -1))
        pair = "real"
    top = max(abs(z).mid() for col in cols for z in col)
    T = []
    for col in cols:
        v = [flint.fmpq(0)] * 3
        for k, z in zip(f, col):
            v[k] = _dyadic(z / top)
        T.append(tuple(v))
    # degenerate (DF(c) nearly triangular): the chart's axes
    if T[0][f[0]] * T[1][f[1]] == T[1][f[0]] * T[0][f[1]]:
        return E, "axes"
    return tuple(T), pair


# ------------------------------------------------------------------ the certificate
@dataclass(frozen=True)
class Shape:
    """What :func:`check` reads of U = {c + T u : |u| ≤ ρ} that does not depend on ρ, as
    balls at :data:`PREC`: each wall's value at the centre and its slope (the norm of its
    row on the frame), the return map's α and the norms of β, g_0 and A, and the frame's
    σ_max and |det| (on the free coordinates); computed once for the radii tried."""

    walls: tuple             # (name, ℓ(c), ‖ℓ T‖)
    alpha: flint.arb
    norm_beta: flint.arb
    norm_g: flint.arb
    norm_a: flint.arb
    sv: flint.arb
    dt: flint.arb


def shape(word: str, c: tuple, T: tuple, P: list, forms: list | None = None) -> Shape:
    """The :class:`Shape` of the ellipse with centre c and frame T for the word (P: its
    products; ``forms``: its :func:`walls`, when the caller has them)."""
    t = ORIENTATION[word[-1]]
    with precision(PREC):
        ws = tuple((w.name, flint.arb(_dot(w.row, c)), _norm([_dot(w.row, col) for col in T]))
                   for w in (forms or walls(word, P)))
        g0, A, alpha, beta = _return_map(P[-1], c, T, t)
        f = _free(t)
        Tf = tuple(tuple(T[j][k] for j in range(2)) for k in f)
        return Shape(ws, flint.arb(alpha), _norm(beta), _norm(g0), _spectral(A), _spectral(Tf),
                     abs(flint.arb(Tf[0][0] * Tf[1][1] - Tf[0][1] * Tf[1][0])))


def check(word: str, r, c: tuple, T: tuple, rho: flint.fmpq, pair: str = "given", P: list | None = None,
          form: Shape | None = None) -> Trap | str:
    """The certificate of the module docstring for U = {c + T u : |u| ≤ ρ}: a Trap when
    every wall and both inequalities (R < ρ, κ < 1) are proved in arb, else the reason.
    ``form``: its :class:`Shape` (of c and T), when the caller has it."""
    form = form or shape(word, c, T, P or products(word, r))
    with precision(PREC):
        for name, value, slope in form.walls:
            low = value - rho * slope
            if not low > 0:
                return f"the wall '{name}' is not proved positive on U"
        den = form.alpha - rho * form.norm_beta
        if not den > 0:                                    # the wall at the return, again: R and κ need it
            return "the return's denominator α - |β|ρ is not proved positive"
        norm_a, norm_g, alpha = form.norm_a, form.norm_g, form.alpha
        R = (norm_g + norm_a * rho) / den
        kappa = norm_a / den + R * form.norm_beta / den
        if not R < rho:
            return f"F(U) ⊂ U is not proved (image radius ≤ {R.str(5)} against ρ = {flint.arb(rho).str(5)})"
        if not kappa < 1:
            return f"the contraction κ < 1 is not proved (κ ≤ {kappa.str(5)})"
        sv, dt = form.sv, form.dt
        inner = rho * dt / sv                              # σ_min(T) = |det T| / σ_max(T)
        return Trap(word, flint.fmpq(r), tuple(c), tuple(T), rho, _upper(kappa), _upper(R / rho),
                    _upper(norm_g / alpha / (1 - kappa)), max(_lower(inner), flint.fmpq(0)),
                    _upper(rho * sv), pair)


def attempt(word: str, r, centre: tuple | None = None) -> Trap | str:
    """A certified trapping ellipse for the word at the rational r (module docstring), or
    a one-line reason why none was found.  ``word``: the letters c_1 … c_L, the period
    starting from the contact c_0 = c_L (e.g. the normal form of ``certify orbit``);
    ``centre``: an approximate n* (c_t = 1), by default the dominant eigenvector of N_w.
    UsageError for a bad word (not over a, b and c, a letter repeated) or r (not a rational in ]0, 1[)."""
    word, r = check_word(word), check_r(r)
    if set(word) != set(LETTERS):
        raise UsageError(f"{word!r} is not a word of the four-particle reduction of Section 4: it needs a, b and c")
    t = ORIENTATION[word[-1]]
    P = products(word, r)
    with precision(PREC):
        c = centre if centre is not None else dominant_normal(P[-1], t)
    if isinstance(c, str):
        return c
    c = tuple(flint.fmpq(z) / flint.fmpq(c[t]) for z in c)
    forms = walls(word, P)
    for w in forms:
        if _dot(w.row, c) <= 0:
            return (f"the dominant eigen-normal of N_w does not realise {word} at r = {r} ({w.name} fails): "
                    "no periodic orbit with this word attracts there")
    with precision(PREC):
        T, pair = frame(P[-1], c, t)
    form = shape(word, c, T, P, forms)               # each wall's value at c and slope on T
    with precision(PREC):
        rho0 = min(value / slope for _name, value, slope in form.walls if slope > 0)
        rho, bad = _dyadic(rho0 * flint.arb(SHRINK)), _dyadic(rho0)
    why = "no radius tried"
    for _ in range(TRIES):
        found = check(word, r, c, T, rho, pair, P, form)
        if isinstance(found, Trap):
            return _largest(found, bad, P, form)
        why, bad, rho = found, rho, rho * SHRINK
    return f"no trapping ellipse found down to ρ = {_dec(rho)}: {why}"


def _largest(good: Trap, bad: flint.fmpq, P: list, form: Shape | None = None, steps: int = BISECTIONS) -> Trap:
    """A larger certified radius between good.radius and a refused one, by bisection
    (``form``: the :class:`Shape` of good's centre and frame, when the caller has it)."""
    form = form or shape(good.word, good.centre, good.frame, P)
    for _ in range(steps):
        mid = (good.radius + bad) / 2
        mid = flint.fmpq((mid.p * 2 ** FRAME_BITS) // mid.q, 2 ** FRAME_BITS)
        found = check(good.word, good.r, good.centre, good.frame, mid, good.pair, P, form)
        if isinstance(found, Trap):
            good = found
        else:
            bad = mid
    return good


def trap(word: str, r) -> Trap | None:
    """The certified trapping ellipse of :func:`attempt`, or None."""
    found = attempt(word, r)
    return found if isinstance(found, Trap) else None
