"""The one definition of the numerical reduction map and of its break rules.

Every engine (float64, mp, ball) iterates the projective form of the reduction map of
:mod:`certify.dynamics.reduction`: the state right after a collision is the contact
i (0, 1, 2 for a, b, c) and a normal vector n of the plane P, oriented so that
n_j > 0 with j = i + 1 (mod 3) (``reduction.ORIENTATION``); the position lies inside
the face iff also n_k < 0, k = i + 2; the next contact is j when n_i > 0 (cos φ > 0)
and k when n_i < 0 (``reduction.next_letter``: n_i n_j > 0); the new normal is
cof(K) n with the rows ``reduction.cofactor(letter, r)``, re-oriented.  The float64
kernel (:mod:`.kernel`) is a compiled transcription of :func:`classify` and
:func:`advance`, checked against them and against ``reduction.step``.

Break rules (:data:`BREAKS`).  A sign is used only when it is decided by a safe
margin: |x| > bound, where for the floating engines the bound of an entry of
n' = cof(K) n is ``TOL · Σ_c |cof(K)_{mc}| |n_c|`` with TOL = SAFETY · 2^-precision
(the rounding of that product, componentwise, with a margin), and ``TOL · max|n|`` for the initial
normal (the rounding of its conversion from θ0, φ0).  A ball decides a sign when it
excludes 0.  In order:

1. ``UNDECIDED``: the sign of n_i, i.e. of cos φ = n_i/|n|, is not decided: the next
   contact is not determined (the paper's |cos φ| below the precision, l. 1066-1068;
   for a ball also an exact 0, the orbit heading for a corner).
2. ``SHORT_STEP``: an in-face entry n_j or n_k is not decided: the position is within
   the rounding of a vertex of the triangle (θ near 0 or π/2), two gaps vanish at
   once to working precision, the time between two collisions is below the
   precision (the paper's first break, l. 1065).
3. ``CORNER``: the normal is zero or an in-face entry has the wrong sign, decided:
   the datum is not a state inside the face (e.g. θ0 outside ]0, π/2[).
4. ``NONFINITE``: an entry is inf or nan (a nan datum).
5. ``HORIZON`` (only with ``strict``): the contact is decided by the margin rule above
   but not by the accumulated error bound (:func:`carry_bound`): the orbit has reached
   its certified horizon.

0 is a completed orbit.  The engines never continue past a break.

The certified horizon.  The margin rule decides each step against the rounding of
*that step*; along a chaotic orbit the rounding errors of the earlier steps grow, and
a floating orbit can leave the true one while every step is decided (a shadowing
orbit).  The floating engines therefore also carry a rigorous bound ``err`` of the
accumulated error of the normal (:func:`carry_bound`): a collision is *certified*
when :func:`classify` at the bounds ``err`` decides it (the same contact); the number
of collisions before the first one that is not is the orbit's certified horizon,
reported by every engine (the ball engine certifies every collision it does).
"""
from __future__ import annotations

import math
from fractions import Fraction

import flint

from certify.dynamics import reduction
from certify.dynamics.model import INDEX, LETTERS
from certify.errors import UsageError

COMPLETED, UNDECIDED, SHORT_STEP, CORNER, NONFINITE, HORIZON = 0, 1, 2, 3, 4, 5
BREAKS = {
    COMPLETED: "completed",
    UNDECIDED: "undecided contact: |cos φ| below the rounding bound",
    SHORT_STEP: "time step below precision: the position within rounding of a vertex",
    CORNER: "corner: zero normal, or the state outside the face",
    NONFINITE: "non-finite number",
    HORIZON: "certified horizon: the accumulated error bound no longer decides the contact (strict)",
}
SAFETY = 64                         # the margin over one rounding of a step
START = "b"                         # the contact of the initial data (paper: b-collisions)


def tol(bits: int) -> float | Fraction:
    """TOL = SAFETY · 2^-bits, the relative margin at ``bits`` of mantissa."""
    return SAFETY * Fraction(1, 2 ** bits)


TOL64 = float(tol(53))              # 2^-47 ≈ 7.1e-15


# --- the shared step --------------------------------------------------------

def margin_sign(x, bound) -> int:
    """+1 / -1 when |x| > bound, else 0 (not decided)."""
    if x > bound:
        return 1
    if x < -bound:
        return -1
    return 0


def ball_sign(x, bound=None) -> int:
    """+1 / -1 when the ball excludes 0, else 0 (not decided; also an exact 0)."""
    if x > 0:
        return 1
    if x < 0:
        return -1
    return 0


def classify(i: int, n, bounds, sign=margin_sign, finite=math.isfinite) -> tuple[int, int]:
    """(break code, next contact index): the break rules of the module docstring at the
    state (i, n) whose entries carry the rounding ``bounds``; (0, j) when the next
    contact j is decided."""
    if not all(finite(z) for z in n):
        return NONFINITE, -1
    if all(z == 0 for z in n):
        return CORNER, -1
    j, k = (i + 1) % 3, (i + 2) % 3
    sj, sk = sign(n[j], bounds[j]), sign(n[k], bounds[k])
    if sj < 0 or sk > 0:
        return CORNER, -1
    if sj == 0 or sk == 0:
        return SHORT_STEP, -1
    si = sign(n[i], bounds[i])
    if si == 0:
        return UNDECIDED, -1
    return COMPLETED, (j if si > 0 else k)


def advance(j: int, n, rows) -> tuple:
    """The normal after the collision j: cof(K_j) n, oriented so that its entry
    j + 1 (mod 3) is not negative (``reduction.canonical``, unnormalised)."""
    K = rows[j]
    m = tuple(K[a][0] * n[0] + K[a][1] * n[1] + K[a][2] * n[2] for a in range(3))
    t = (j + 1) % 3
    return tuple(-z for z in m) if m[t] < 0 else m


def step_bounds(j: int, n, absrows, tolerance) -> tuple:
    """The rounding bounds of the entries of :func:`advance` (j, n): TOL · (|K| |n|)_m,
    K = cof(K_j) (``absrows``: the matrices of absolute values), for a vector of any length
    (the five-particle bivectors too, :mod:`.five_reduction`), the sum left to right as the
    kernels add it."""
    a = [abs(z) for z in n]
    bounds = []
    for row in absrows[j]:
        s = row[0] * a[0]
        for c in range(1, len(a)):
            s = s + row[c] * a[c]
        bounds.append(tolerance * s)
    return tuple(bounds)


# --- the accumulated error bound (the certified horizon) ----------------------

def gamma_bound(bits: int, length: int = 3) -> Fraction:
    """g = L u (1 + 2 L u), u = 2^-bits, L the least power of 2 ≥ ``length`` + 1: a
    representable number ≥ γ_(length+1) = (length+1)u/(1 − (length+1)u) (since
    1/(1 − x) ≤ 1 + 2x for x ≤ 1/2); see :func:`carry_bound`.  For the four-particle normals
    (length 3) g = 4u(1 + 8u); for the five-particle bivectors (length 6, :mod:`.five_reduction`)
    g = 8u(1 + 16u).

    >>> from fractions import Fraction
    >>> u = Fraction(1, 2 ** 53)
    >>> gamma_bound(53) >= 4 * u / (1 - 4 * u), float(gamma_bound(53)) == gamma_bound(53)
    (True, True)
    >>> gamma_bound(53, 6) >= 7 * u / (1 - 7 * u), float(gamma_bound(53, 6)) == gamma_bound(53, 6)
    (True, True)

    Exact rationals: the bound holds for any ``bits`` ≥ 2 log2 L + 2, and at 53 bits it is a
    float64 number, so the float engines use it without a rounding of their own."""
    u = Fraction(1, 2 ** bits)
    L = 1 << length.bit_length()          # the least power of 2 > length
    return L * u * (1 + 2 * L * u)


def inflation(bits: int) -> Fraction:
    """κ = 1 + 32u, u = 2^-bits: the factor that makes the computed bound an upper
    bound in spite of its own roundings (:func:`carry_bound`)."""
    return 1 + 32 * Fraction(1, 2 ** bits)


G64 = float(gamma_bound(53))        # exact: 2^-51 (1 + 2^-50)
K64 = float(inflation(53))          # exact: 1 + 2^-48
TINY64 = 2.0 ** -1000               # the absolute term that covers underflow (float64 only)
NORMAL64 = 2.0 ** -1022             # the smallest normal float64: float_rows needs its entries above it


def carry_bound(j: int, n, err, absrows, g, kappa, tiny=0):
    """The bound of the accumulated error after the collision j, from the state's
    computed normal ``n`` and its bound ``err``:

        err'_m = fl( fl(S_m · κ) + tiny ),   S_m = Σ_c |Ĉ_mc| (err_c + g |n_c|),

    computed left to right in the engine's numbers, with Ĉ the engine's matrix
    (``absrows[j]`` = |Ĉ|), ``g`` = :func:`gamma_bound`, ``kappa`` = κ = :func:`inflation` at
    the engine's precision, ``tiny`` = :data:`TINY64` in float64 (0 in mpmath, whose
    exponents do not underflow).

    Claim.  Let x be the exact normal (the exact orbit of the datum, with the same
    orientations and power-of-2 rescalings as the engine) with |n − x| ≤ err
    componentwise, C the exact matrix of which Ĉ is the rounding, n' = fl(Ĉ n) the
    engine's next normal and x' = C x.  Then |n' − x'| ≤ err' componentwise.

    The same for vectors of any length d ≤ 6 (the five-particle bivectors, :mod:`.five_reduction`, d = 6),
    with ``g`` = ``gamma_bound(bits, d)``: the changes to the proof are noted in brackets.

    Proof (u = 2^-p the unit roundoff, η = 2^-1074 the smallest subnormal of float64,
    0 in mpmath).  (i) The entries of Ĉ are correctly rounded (``float_rows``;
    ``mpf(int)``): |Ĉ − C| ≤ u|C|, so |C| ≤ |Ĉ|/(1 − u).  (ii) A dot product of
    length 3 evaluated in floating point (Higham, *Accuracy and Stability of Numerical
    Algorithms*, §3.1, with underflow: Thm 3.5 and §2.1) satisfies
    |fl(Ĉ n) − Ĉ n| ≤ γ_3 |Ĉ||n| + 3η, γ_k = ku/(1 − ku).  (iii) Hence

        |n' − x'| ≤ |fl(Ĉ n) − Ĉ n| + |Ĉ − C||n| + |C||n − x|
                  ≤ (γ_3 + u/(1 − u)) |Ĉ||n| + |Ĉ| err/(1 − u) + 3η
                  ≤ S/(1 − u) + 3η                      (γ_3 + u/(1 − u) ≤ γ_4 ≤ g).

    [Length d: γ_d and dη in (ii), γ_d + u/(1 − u) ≤ γ_(d+1) ≤ g in (iii).]

    (iv) The computed Ŝ_m takes five roundings on non-negative numbers, each
    fl(a ∘ b) ≥ (a ∘ b)(1 − u) − η/2: Ŝ_m ≥ S_m (1 − u)^5 − 5η (|Ĉ| ≤ 2).  If
    Ŝ_m ≥ 2^-1020, fl(Ŝ_m κ) ≥ Ŝ_m (1 + 32u)(1 − u) ≥ Ŝ_m (1 + 31u − 32u²), which exceeds
    (Ŝ_m + 5η)/(1 − u)^6 + 3η ≥ S_m/(1 − u) + 3η by at least 20u Ŝ_m (because 5u Ŝ_m ≥ 10η);
    adding tiny ≥ 0 does not decrease a float (rounding is monotone).  If
    Ŝ_m < 2^-1020 (float64 only) the bound needed is below 2^-1019 and
    fl(· + 2^-1000) ≥ 2^-1000.  (v) The engine negates n' or multiplies it by a power
    of 2, f: a negation is exact and is applied to x' too; f·n' is exact except for
    entries that underflow (error ≤ η/2 each), and the kernel then sets
    err'' = fl(fl(err' f) + tiny): when f ≥ 1 nothing underflows and fl(err' f) ≥ err' f
    (exact, or inf); when f < 1 either err' f ≥ 2^-947, it is exact and the slack
    20u Ŝ_m f ≥ η of (iv) covers the η/2, or fl(err' f + tiny) ≥ err' f − η/2 + tiny/2
    ≥ err' f + η/2.  [Length d ≤ 6: Ŝ_m takes d + 2 ≤ 8 roundings, Ŝ_m ≥ S_m (1 − u)^8 − 16η
    (|Ĉ| ≤ 2), and (Ŝ_m + 16η)/(1 − u)^9 + 6η ≤ Ŝ_m (1 + 9.1u) + 11u Ŝ_m when Ŝ_m ≥ 2^-1020
    (u Ŝ_m ≥ 2η), which leaves fl(Ŝ_m κ) a slack ≥ 10u Ŝ_m ≥ η for (v).]  ∎

    An inf or nan bound decides nothing (every comparison with it fails), so
    overflow of the bound ends the certified horizon, never extends it.  The initial
    bound is ``TOL · max|n|`` (:func:`tol`: 64u), which dominates the error of the
    normal computed from (θ0, φ0): each entry is at most two products and one sum of
    same-signed terms of cos and sin, each within one ulp (≤ 2u relative), an error
    ≤ 8u |n_c| ≤ 8u max|n|.
    """
    K_ = absrows[j]
    t = [err[c] + g * abs(n[c]) for c in range(len(n))]
    out = []
    for row in K_:
        s = row[0] * t[0]
        for c in range(1, len(t)):          # left to right, as the kernels add
            s = s + row[c] * t[c]
        out.append(s * kappa + tiny)
    return tuple(out)


def certifies(i: int, n, err, j: int, sign=margin_sign, finite=math.isfinite) -> bool:
    """True when :func:`classify` at the bounds ``err`` decides the contact j (the
    collision is certified)."""
    return classify(i, n, err, sign, finite) == (COMPLETED, j)


def exact_r(r) -> flint.fmpq:
    """r as an exact rational (a float is read exactly, its binary value)."""
    if isinstance(r, flint.fmpq):
        return r
    if isinstance(r, float):
        num, den = Fraction(r).as_integer_ratio()
        return flint.fmpq(num, den)
    return flint.fmpq(r) if not isinstance(r, str) else flint.fmpq(*Fraction(r).as_integer_ratio())


def integer_rows(r) -> list[tuple]:
    """The three cofactor matrices cof(A), cof(B), cof(C) at r, as integer rows
    (``reduction.cofactor``), in the order a, b, c."""
    q = exact_r(r)
    return [reduction.cofactor(L, q) for L in LETTERS]


def float_rows(r) -> list[list[list[float]]]:
    """:func:`integer_rows` converted to float, each matrix scaled by a power of 2 so
    that its largest entry lies in [1, 2) (a positive multiple keeps the plane).

    UsageError when an entry is not zero and below the smallest normal float64
    (:data:`NORMAL64` = 2^-1022; r itself subnormal, e.g. 1e-310): such an entry is
    rounded to an absolute, not a relative, precision, step (i) of :func:`carry_bound`
    fails, and the kernel's power-of-2 rescaling of a subnormal normal overflows."""
    return scaled_rows(integer_rows(r), r)


def scaled_rows(matrices, r) -> list[list[list[float]]]:
    """Integer matrices (a positive multiple of the exact ones) converted to float, each
    scaled by a power of 2 so that its largest entry lies in [1, 2), correctly rounded;
    UsageError for an entry below :data:`NORMAL64` (:func:`float_rows`)."""
    out = []
    for rows in matrices:
        shift = max(abs(int(z)) for row in rows for z in row).bit_length() - 1
        out.append([[_scaled(int(z), shift) for z in row] for row in rows])
    tiny = [abs(z) for K in out for row in K for z in row if z and abs(z) < NORMAL64]
    if tiny:
        raise UsageError(f"r = {float(exact_r(r)):g} is too small for the float64 engine: its matrices have an "
                         f"entry {tiny[0]:g} below the smallest normal float64 2^-1022 ≈ {NORMAL64:.3g} "
                         "(no relative rounding bound there); use the mp or ball engine")
    return out


def _scaled(z: int, shift: int) -> float:
    """z · 2^-shift correctly rounded (z may exceed the float range)."""
    if shift < 900:                  # float(z) is correctly rounded, the power of 2 exact
        return math.ldexp(float(z), -shift)
    return float(Fraction(z, 1 << shift))


def row_abs(rows) -> list[list]:
    """Σ_c |K_{mc}| for each matrix K and row m (the float kernel's signature)."""
    return [[sum(abs(z) for z in row) for row in K] for K in rows]


def abs_rows(rows) -> list:
    """|K| entrywise for each matrix K: the rounding bound's factor."""
    return [[[abs(z) for z in row] for row in K] for K in rows]


# --- the angles ---------------------------------------------------------------

def initial_normal(theta, phi, letter: str = START, cos=math.cos, sin=math.sin) -> tuple:
    """The normal u = p(0) ∧ q(0) of the state (letter, θ, φ) of Section 4's
    trigonometric version (``reduction.Angles``: p(0) = P0[letter](cos θ, sin θ),
    q(0) = Q0[letter](..., cos φ, sin φ)); at b: (−cos θ sin φ, cos φ, sin θ sin φ)."""
    return reduction.Angles(letter, cos(theta), sin(theta), cos(phi), sin(phi)).u()


def phi_of(i: int, n) -> float:
    """φ ∈ [0, π] of the state (i, n), float: cos φ = n_i/|n| and sin φ =
    |(n_j, n_k)|/|n| ≥ 0 (``reduction.angles``: n = (cos φ, sin θ sin φ, −cos θ sin φ)
    relabelled for the contact)."""
    return math.atan2(math.hypot(n[(i + 1) % 3], n[(i + 2) % 3]), n[i])


def theta_of(i: int, n) -> float:
    """θ ∈ [0, π/2] of the state (i, n): sin θ sin φ = n_j, cos θ sin φ = −n_k."""
    return math.atan2(n[(i + 1) % 3], -n[(i + 2) % 3])


def letter_index(letter: str) -> int:
    return INDEX[letter]


def phi_at_b(p, q) -> float:
    """The φ the engines keep for the state (p, q) right after a b-collision: that of the
    normal p ∧ q, oriented as the engines orient it (:func:`phi_of`)."""
    n = reduction.cross(p, q)
    if n[2] < 0:
        n = tuple(-z for z in n)
    return phi_of(1, n)
