"""A proved leap of the certified orbit along a repelling periodic block: J periods at once.

Near a periodic orbit of the reduction that repels slowly (near r = 1 the orbit of abcb is a
focus whose multipliers have modulus 1 + 10⁻⁵ or less), an orbit winds out along the block for
10⁵-10⁷ collisions before it leaves it; the ball engine (:func:`.engines.ball_states`) would
decide every one of them.  A leap decides them all at once, exactly as follows.

Let the ball state m (at contact i, oriented) be about to follow the block s = s_1 ··· s_L
(s_L = i: the period returns to contact i), C_t = cof(K_{s_t}) ··· cof(K_{s_1}) the integer
cofactor products (C_0 = I) and N = C_L.  The L collisions from a normal n are decided by the
signs of the 3L linear forms ℓ_{t,x}(n) = (C_t n)_x, x = 0, 1, 2, t = 0 ... L−1: the contact's
two in-face entries and its own entry (:func:`.rules.classify`) and the orientation after each
collision are signs of these, so the letters are a function of the sign pattern, unchanged when
every sign flips (n and −n are one plane).

With N = R D R⁻¹ (python-flint's rigorous eigen-decomposition, ``acb_mat.eig``: eigenvalues λ_i
in disjoint balls, right eigenvectors the columns of R; R⁻¹ by ``acb_mat.inv``), ℓ(Nᵖ m) =
Σ_i c_i λ_iᵖ with c_i = ℓ(R e_i)(R⁻¹ m)_i.
Let λ_0 be a real eigenvalue (its ball meets no other's conjugate) with s_i = |λ_i/λ_0| > 1 for the
two others: the periodic orbit (the eigenvector of λ_0) repels.  If for every form

    |c_0| > Σ_{i≠0} |c_i| s_i^(J−1),

then for 0 ≤ p < J the sign of ℓ(Nᵖ m) is that of λ_0ᵖ c_0: every period from Nᵖ m has the
sign pattern of the period from m, up to one global sign.

When the two others are a complex pair λ, λ̄ (a focus: λ/λ_0 = s e^{iω}), the spectral parts of the
real m on them are conjugate, so ℓ(Nᵖ m)/λ_0ᵖ = c_0 + 2|c| sᵖ cos(φ + pω), φ = arg c.  Near r = 1
abcb's focus turns by nearly 2π/3 a period: an orbit that returns to the block far from its
periodic orbit (2|c| ≈ |c_0|, where the inequality above fails) keeps its signs while the slow
drift δ = 3ω − 2π has not turned a cosine the wrong way.  With k/m the fraction nearest ω/2π
(m ≤ :data:`TURNS`) and δ = mω − 2πk, the periods p = mq + t of one residue t see the angles
φ + tω + qδ, an arc of length |δ|(Q_t − 1) for the Q_t of them below J.  If μ ≤ min sgn(c_0) cos on
every arc, then |c_0| + 2|c| s^(J−1) min(μ, 0) > 0 proves the same conclusion
(:func:`_turning_periods`; the arcs of a full turn give μ = −1 and the inequality above).

So when the period from m follows s (decided here by the engine's own classification,
collision by collision), the orbit follows s^J from m, and its state after the J periods is a
positive multiple of ±N^J m, evaluated as the ball (N)^J m (``arb_mat`` powers: rigorous).  Only
repelling blocks leap: near an attracting one the trapping ellipse decides instead (a leap
would skip the states it reads).

A leap stops :data:`LEAP_MARGIN` letters (and a period) before the end of what is proved, so
every state it skips is followed by the block for at least that many letters.  Such a state is
in no trapping ellipse of a word w' of at most LEAP_MARGIN − L letters (``certify identify``
decides blocks up to 1000): from it the orbit would follow both w'^∞ and the block for
|w'| + L letters, so w' and the block would be powers of one word (Fine and Wilf), whose
periodic orbit repels.  Nor is it in the island: from there every b-to-b segment is acb or
cab for ever, so the block would be the island's coding, whose period matrix is elliptic
(|λ_i| all equal), not repelling."""
from __future__ import annotations

import math
from dataclasses import dataclass

import flint
import numpy as np

from certify.algebra.balls import precision
from certify.dynamics.model import LETTERS

from . import rules

LEAP_BITS = 256                # the least precision of a leap's eigen-decomposition and power
LEAP_WINDOW = 1024             # the letters of the ball orbit read for a repeated block
LEAP_EVERY = 2048              # collisions between two attempts of a leap
LEAP_MIN = 16                  # periods: a shorter proved leap is not taken
LEAP_MARGIN = 1024             # letters of the block proved followed beyond a leap's end (below)
TURNS = 12                     # a focus's rotation ω is read near the m-th roots of unity, m ≤ TURNS


def period_of(word: str, max_period: int | None = None) -> str | None:
    """The shortest block B such that the last half of ``word`` is periodic with period
    |B| and holds at least 4 periods (|B| ≤ half/4, and ≤ ``max_period`` when given);
    B = the last |B| letters.  None when there is none.  Linear time: the shortest
    period of a string s is |s| − π(s), π the longest proper border (prefix function, compiled:
    :func:`.kernel.shortest_period`)."""
    from . import kernel  # numba, imported where it first runs
    tail = word[len(word) - len(word) // 2:]
    m = len(tail)
    if m < 8:
        return None
    p = int(kernel.shortest_period(np.frombuffer(tail.encode(), dtype=np.uint8)))
    bound = m // 4 if max_period is None else min(m // 4, max_period)
    return word[-p:] if p <= bound else None


@dataclass(frozen=True)
class Leap:
    """J periods of a block proved followed: the state after them is ``sign``·N^J times the
    state before (a positive multiple of the reduction's normal)."""

    N: flint.fmpz_mat
    J: int
    sign: int
    length: int                 # L, the block's letters
    rate: str                   # min s_i − 1: the slowest repulsion per period (printed, 3 digits)

    def apply(self, n, prec: int) -> tuple:
        """A ball vector containing sign·N^J n, at ``prec`` bits (at least :data:`LEAP_BITS`)."""
        with precision(max(prec, LEAP_BITS)):
            v = (flint.arb_mat(self.N) ** self.J) * flint.arb_mat([[n[0]], [n[1]], [n[2]]])
            return tuple(self.sign * v[x, 0] for x in range(3))


def _follows(mats: list, i: int, n, block: str) -> list | None:
    """The cofactor products C_0 ... C_L (exact) of one period of ``block`` from the ball state n at
    contact i, when the engine's classification (:func:`.rules.classify` on balls, every sign
    decided) follows the block; None otherwise."""
    C = flint.fmpz_mat([[1, 0, 0], [0, 1, 0], [0, 0, 1]])
    products = [C]
    m = n
    for x in block:
        code, nxt = rules.classify(i, m, (0, 0, 0), rules.ball_sign, flint.arb.is_finite)
        if code != rules.COMPLETED or LETTERS[nxt] != x:
            return None
        C = mats[nxt] * C
        v = flint.arb_mat(C) * flint.arb_mat([[n[0]], [n[1]], [n[2]]])
        m = (v[0, 0], v[1, 0], v[2, 0])
        t = (nxt + 1) % 3
        if not (m[t] > 0 or m[t] < 0):
            return None
        if m[t] < 0:
            m = tuple(-z for z in m)
        i = nxt
        products.append(C)
    return products


def leap_along(mats: list, i: int, n, block: str, most: int, prec: int, refused: set | None = None) -> Leap | None:
    """The longest proved leap (module docstring) of at most ``most`` periods of ``block`` from
    the ball state n at contact i (block[-1] = LETTERS[i]; ``mats`` the integer cofactor matrices
    of a, b, c, fmpz_mat), or None (the period from n does not
    follow the block, the block does not repel, or fewer than :data:`LEAP_MIN` periods are proved).
    ``refused``: the blocks whose period matrix at this r is not proved to repel, added to and read
    (they are not tried again: N depends on the block and r only)."""
    extra = -(-LEAP_MARGIN // len(block)) + 1          # periods proved beyond the leap
    if most < LEAP_MIN or LETTERS[i] != block[-1] or (refused is not None and block in refused):
        return None
    with precision(max(prec, LEAP_BITS)):
        C = _follows(mats, i, n, block)
        if C is None:
            return None
        N = C[-1]
        try:
            E, R = flint.acb_mat(N).eig(right=True)
            Rinv = R.inv()
        except (ValueError, ZeroDivisionError):    # eigenvalues not isolated, R not inverted, at this precision
            return None
        real = [a for a in range(3) if all(not E[a].conjugate().overlaps(E[b]) for b in range(3) if b != a)]
        repelling = [a for a in real if all(abs(E[b] / E[a]) > 1 for b in range(3) if b != a)]
        if not repelling and refused is not None:
            refused.add(block)
        best = None
        for a in repelling:
            periods = _turning_periods if _pair(E, a) is not None else _periods
            J = periods(C[:-1], E, R, Rinv, a, n, most + extra, LEAP_MIN + extra)
            if best is None or J[0] > best[0]:
                best = (J[0], J[1], a)
        if best is None or best[0] - extra < LEAP_MIN:
            return None
        J, rate = min(best[0] - extra, most), best[1]
        v = (flint.arb_mat(N) ** J) * flint.arb_mat([[n[0]], [n[1]], [n[2]]])
        t = (i + 1) % 3
        if not (v[t, 0] > 0 or v[t, 0] < 0):
            return None
        return Leap(N, J, 1 if v[t, 0] > 0 else -1, len(block), (rate - 1).str(3, radius=False))


def _periods(products: list, E, R, Rinv, a: int, n, most: int, least: int = 1) -> tuple:
    """(J, min s_i): the largest J ≤ ``most`` with |c_a| > Σ_{i≠a} |c_i| s_i^(J−1) for every form
    ℓ_{t,x} (module docstring), λ_a the eigenvalue at the fixed point, from which the others are
    larger in modulus (s_i = |λ_i/λ_a| > 1, checked by the caller); J = 0 when none holds
    (``least``, the caller's shortest leap, is read by :func:`_turning_periods` only: here J
    comes from one bound)."""
    others = [b for b in range(3) if b != a]
    s = [abs(E[b] / E[a]) for b in others]
    top = max((x.upper() for x in s), key=float)     # the bound of J uses s_i ≤ top; checked again below
    forms = [(abs(c[a].real), [abs(c[b]) for b in others]) for c in _spectral(products, R, Rinv, n)]
    J = most
    for lead, rest in forms:
        total = sum(rest, flint.arb(0))
        if not lead > total:
            return 0, min(s, key=lambda x: x.mid())
        bound = ((lead.log() - total.log()) / top.log()).lower()   # J − 1 below it
        if bound.is_finite():
            J = min(J, max(int(bound.floor().unique_fmpz()) + 1, 0))
    if not all(lead > sum((c * x ** (J - 1) for c, x in zip(rest, s)), flint.arb(0)) for lead, rest in forms):
        J = 0                                      # the inequality at J, checked again in balls
    return J, min(s, key=lambda x: x.mid())


def _spectral(products: list, R, Rinv, n) -> list:
    """The spectral coefficients of every form ℓ_{t,x} (module docstring): for each product C of
    ``products`` and each row x, [c_0, c_1, c_2] with c_i = ℓ_{t,x}(R e_i)·(R⁻¹n)_i, so that
    ℓ_{t,x}(Nᵖ n) = Σ_i c_i λ_iᵖ (R the eigenvectors of N, columns)."""
    Lm = Rinv * flint.acb_mat([[n[0]], [n[1]], [n[2]]])
    out = []
    for C in products:
        FR = flint.acb_mat(C) * R                  # row x: ℓ_{t,x}(R e_i) for i = 0, 1, 2
        out.extend([FR[x, i] * Lm[i, 0] for i in range(3)] for x in range(3))
    return out


def _pair(E, a: int) -> int | None:
    """The index b of the eigenvalue of positive imaginary part when the two other than λ_a are a
    complex pair (their imaginary parts decided nonzero), else None."""
    for b in range(3):
        if b != a and E[b].imag > 0:
            return b
    return None


def _drift(omega) -> tuple[int, flint.arb]:
    """(m, δ) with m ≤ :data:`TURNS` and δ = mω − 2πk, k the integer nearest mω/2π, for the fraction
    k/m nearest ω/2π (|δ|/m least, read at the midpoints: a choice; δ is a ball), the least m of
    a tie (k/m and 2k/2m are one fraction): after p = mq + t periods the rotation is tω + qδ
    modulo 2π."""
    two_pi = 2 * flint.arb.pi()
    best, gap = None, math.inf
    for m in range(1, TURNS + 1):
        k = round(float((m * omega / two_pi).mid()))
        d = m * omega - k * two_pi
        if abs(float(d.mid())) / m < gap * (1 - 1e-9):
            best, gap = (m, d), abs(float(d.mid())) / m
    return best


def _least_cos(lo, hi) -> flint.arb:
    """A ball below min cos θ over the arc lo ≤ θ ≤ hi (lo, hi balls: the arc from lo's lower end
    to hi's upper end): −1 when it may hold an odd multiple of π or turn once, else the lesser
    cosine of its ends (cos has no other interior minimum)."""
    a, b = flint.arb(lo.lower()), flint.arb(hi.upper())
    two_pi = 2 * flint.arb.pi()
    if not b - a < two_pi:
        return flint.arb(-1)
    first = ((a - flint.arb.pi()) / two_pi).lower().ceil()        # odd multiples (2k + 1)π with k ≥ first ...
    last = ((b - flint.arb.pi()) / two_pi).upper().floor()        # ... and k ≤ last lie in the arc
    if not last < first:
        return flint.arb(-1)
    return a.cos().min(b.cos())


def _turning_periods(products: list, E, R, Rinv, a: int, n, most: int, least: int = 1) -> tuple:
    """(J, s): the largest J ≤ ``most`` (0 when it is below ``least``: one check, no search) for
    which every form ℓ_{t,x} keeps its sign over the periods 0 … J−1, when the eigenvalues other
    than λ_a are a complex pair λ, λ̄ with s = |λ/λ_a| > 1 and
    λ/λ_a = s e^{iω}: a repelling focus.  Then ℓ(Nᵖ m)/λ_aᵖ = c_a + 2|c| sᵖ cos(φ + pω) (c = c_λ, φ its
    argument: the spectral parts of a real vector on conjugate eigenvalues are conjugate).  With
    (m, δ) of :func:`_drift`, p = mq + t gives the angle φ + tω + qδ modulo 2π: for each residue t
    it stays on an arc of length |δ|(Q_t − 1), Q_t the periods p < J of that residue.  If μ ≤ min
    sgn(c_a) cos over every arc (:func:`_least_cos`), |c_a| + 2|c| s^(J−1) min(μ, 0) > 0 proves
    sgn ℓ(Nᵖ m) = sgn(c_a λ_aᵖ) for p < J.  A focus that turns slowly near an m-th root of unity
    (near r = 1, abcb's turns by ≈ 2π/3 a period) keeps the signs long after the bound of
    :func:`_periods` (the arcs of a full turn, μ = −1, which this criterion reduces to) fails."""
    b = _pair(E, a)
    z = E[b] / E[a]
    s, omega = abs(z), z.arg()
    m, delta = _drift(omega)
    forms = []                                     # (|c_a|, 2|c|, the angle φ, plus π when c_a < 0)
    for coefficients in _spectral(products, R, Rinv, n):
        lead, c = coefficients[a], coefficients[b]
        if not (lead.real > 0 or lead.real < 0):
            return 0, s
        turn = c.arg() if lead.real > 0 else c.arg() + flint.arb.pi()
        forms.append((abs(lead.real), 2 * abs(c), turn))

    def keeps(J: int) -> bool:
        grow = s ** (J - 1)
        for lead, c, turn in forms:
            for t in range(min(m, J)):
                span = abs(delta) * ((J - t + m - 1) // m - 1)
                start = turn + t * omega
                lo = start - span if not delta > 0 else start
                hi = start + span if not delta < 0 else start
                mu = _least_cos(lo, hi)
                if not (mu >= 0 or lead + c * grow * mu > 0):
                    return False
        return True

    if most < 1 or not keeps(min(most, least)):
        return 0, s
    good, bad = 1, 2
    while bad <= most and keeps(bad):
        good, bad = bad, 2 * bad
    bad = min(bad, most + 1)
    while bad - good > 1:
        mid = (good + bad) // 2
        good, bad = (mid, bad) if keeps(mid) else (good, mid)
    return good, s
