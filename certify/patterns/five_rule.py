"""Where the five-particle families F₁ and F₂ are stable: at the island's resonances (issue 39).

**The block.**  A = abacbc (:data:`.five.A_BLOCK`) uses the pairs a, b, c only: on the gaps 1-3 it acts
as the four-particle matrix M_A = M_abc² (a and c commute), and abc is a rotation of cab = [ca]b, the
symmetric orbit the island turns around.  Certified by :func:`block_identity`, exactly in Q(r)[x]:

    cp(M_A)(x) = (x − r²)(x² − 2r² cos 2θ · x + r⁴),    cos θ = −(1 − r)²/(4r),

θ the angle of the island of four particles (:mod:`.island_theorem`, ρ = θ/2π decreasing from 1/2 at
3 − 2√2 to 1/4 at r = 1).  So on ]3 − 2√2, 1[ A has the complex pair r² e^{±iθ_A} with
θ_A = 2π − 2θ = 2π(1 − 2ρ): the block turns by the island's rotation taken twice, and θ_A → 0 as
r → 3 − 2√2, where cp(M_A) = (x − r²)³.  Near there, 1 − cos(π − θ) = (r − L)(L' − r)/(4r) (L, L' = 3 ∓ 2√2)
gives θ_A² = (32 + 24√2)(r − L) + O((r − L)²) (by hand: the expansion is not machine-checked).

**The rule** (read off the members; observed on every member tried, certified on each member whose
window is certified: :func:`rule_problems`).  Member (k, j) of a family has the half
X = F(k)·A^j = A^k·core·A^k·b·A^j (:func:`.five.family_word`) and W = X·m(X), |W| = 6q + 2 letters with
q = 4k + 2j + 1 (F₁) or 4k + 2j + 3 (F₂); its stable window lies just below the resonance
ρ = p/q, p = (q − 1)/2, inside

    ]r_{(p+1)/(q+2)}, r_{p/q}[,

r_{p/q} the r where ρ(r) = p/q.  The four-particle atlas families of the halves, (abacbc)^k a(bcabac)^k bcb
and (abacbc)^k a(bac)²(bcabac)^k bcb, close at 2k/(4k + 1) and (2k + 1)/(4k + 3): the five-particle member
(k, j) sits at the resonance the four-particle family would have at k + j/2.  The intervals of
consecutive q are disjoint and decrease to 3 − 2√2 (ρ → 1/2): if the rule holds for every k, the
windows of F₂(k)·A accumulate on 3 − 2√2, with r − L ≈ π²/((8 + 6√2) q²) there (θ_A ≈ 2π/q), so
1/√(ℓ_k − L) grows by 4√(8 + 6√2)/π ≈ 5.16962 per member.
"""
from __future__ import annotations

from fractions import Fraction

import flint

from certify.algebra import Algebraic
from certify.dynamics.model import charpoly_coefficients
from certify.dynamics.systems import of_particles, system_matrix_flint

from .five import A_BLOCK, family_word
from .island_theorem import resonances_of_q


def block_identity(block: str = A_BLOCK) -> bool:
    """Whether cp(M_block) = (x − r²)(x² − 2r² cos 2θ x + r⁴) with cos θ = −(1 − r)²/(4r), exactly:
    the coefficients of both sides as polynomials in r (four particles; 4r²·2r² cos 2θ =
    (1 − r)⁴ − 8r², so the quadratic's middle coefficient is −((1 − r)⁴ − 8r²)/4)."""
    r = flint.fmpq_poly([0, 1])
    t = ((1 - r) ** 4 - 8 * r ** 2) / 4              # 2r² cos 2θ = t, a polynomial in r
    r2, r4 = r ** 2, r ** 4
    # (x − r²)(x² − t x + r⁴) = x³ − (t + r²) x² + (r⁴ + r² t) x − r⁶
    want = [flint.fmpq_poly([1]), -(t + r2), r4 + r2 * t, -(r2 * r4)]
    return charpoly_coefficients(system_matrix_flint(of_particles(4), block)) == want


def resonance(core: str, k: int, j: int = 1) -> tuple[int, int]:
    """(p, q) of member (k, j) of the family with ``core`` (one of :data:`.five.FAMILY_CORES`), read off
    its word W (:func:`.five.family_word`): q = (|W| − 2)/6, p = (q − 1)/2 (q = 4k + 2j + 1 for F₁,
    4k + 2j + 3 for F₂)."""
    q, rest = divmod(len(family_word(core, k, j)) - 2, 6)
    if rest or q % 2 == 0:
        raise ValueError(f"member ({k}, {j}) of core {core!r}: its length is not 6q + 2 with q odd")
    return (q - 1) // 2, q


def resonance_point(p: int, q: int) -> Algebraic:
    """r_{p/q}: the r in ]3 − 2√2, 1[ where the island's rotation number is p/q (exact, from
    :func:`.island_theorem.resonances_of_q`)."""
    for s in resonances_of_q(q):
        if s.p == p:
            return s.r
    raise ArithmeticError(f"no resonance {p}/{q} in ]3 − 2√2, 1[")


def rule_interval(core: str, k: int, j: int = 1) -> tuple[Algebraic, Algebraic]:
    """]r_{(p+1)/(q+2)}, r_{p/q}[ of member (k, j), its ends exact."""
    p, q = resonance(core, k, j)
    return resonance_point(p + 1, q + 2), resonance_point(p, q)


def rule_problems(core: str, k: int, j: int, lo: dict, hi: dict) -> list[str]:
    """What contradicts the rule for a certified window ]ℓ, h[ of member (k, j), its ends ``lo``, ``hi``
    as a pattern result prints them: empty when r_{(p+1)/(q+2)} < the left end of ℓ's isolating interval
    and the right end of h's < r_{p/q}, decided exactly (so the whole window lies in the rule's interval;
    the ends' minimal polynomials, of degree up to several hundred, are not needed)."""
    a, b = rule_interval(core, k, j)
    p, q = resonance(core, k, j)
    ell, h = (Algebraic.rational(flint.fmpq(x.numerator, x.denominator))
              for x in (Fraction(lo["interval"][0]), Fraction(hi["interval"][1])))
    out = []
    if not a < ell:
        out.append(f"({k}, {j}): the window reaches below r_{p + 1}/{q + 2} ≈ {a.digits(12)}")
    if not h < b:
        out.append(f"({k}, {j}): the window reaches above r_{p}/{q} ≈ {b.digits(12)}")
    return out
