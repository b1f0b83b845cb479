"""Section 3 (l. 250-516): Theorem 3.1, the pattern ababcb.

Theorem 3.1 (l. 286-321).  For 0 < r < 5-2√6 there are self-similar data of the pattern
ababcb, q(0) = (-1, u, v) and p(0) = (1, 0, x) with u, v, x given by the printed formulas,
on the upper and on the lower eigenvalue branch of M = BCBABA; for r > 5-2√6 there are
none; and the self-similar data are unstable.

The claims, in the order of the paper's proof: the statement (T1 the matrix M), Step 1
the spectrum of M (T2-T9), Step 2 the positive fixed points of f (T10; 2.1 a-d: T11-T14;
2.2 b: T15; 2.3 c: T16; 2.4 the fixed points: T17-T19), Step 3.1 the velocity
inequalities (T20, T21), Step 3.2 the distance inequalities (T22), Step 4 stability
(T23, T24), and the conclusion: the theorem as a whole (T25.1), and on the dynamics of
the particles (T25.2).  Remarks 3.2 and 3.3 are in proofs/section3_remarks.py.

Read next to the paper: each certificate states the claim as printed, with its
line, then computes.  Printed formulas are transcribed below as text, exactly as
they stand in the paper (only the stray parenthesis of l. 259 is dropped).
Branches: 0 = upper (largest real eigenvalue), 1 = middle, 2 = lower.  General lemmas
(roots in ]0,1[, sign tables, eliminants, digit and count checks) are in the layers.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

import flint
import sympy as sp

from certify.algebra import (
    BRANCH_NAMES,
    GUARD,
    LOWER,
    MIDDLE,
    UPPER,
    Algebraic,
    Condition,
    FixedPoint,
    Q,
    ball_value,
    discriminant_lambda,
    eliminate,
    flint_real_roots,
    from_flint,
    lam,
    parse,
    precision,
    r,
    roots_in_unit_interval,
    same_up_to_constant,
    show,
    sign_intervals,
    sign_word,
    statements,
    sturm_count,
    tight,
    to_field,
    to_fmpq,
    to_fmpq_poly,
    to_fmpz_poly,
    to_ring,
    u,
    unique_root,
    v,
    x,
)
from certify.dynamics import A as A_
from certify.dynamics import B as B_
from certify.dynamics import C as C_
from certify.dynamics import (
    candidate,
    characteristic_polynomial,
    check_word,
    det3,
    fixed_point_ball,
    reduce_mod,
    velocities,
)
from certify.dynamics import simulate as sim
from certify.patterns import Analysis, fmt, prefix_requirements
from certify.run import (
    ERRATUM,
    FALSE_STATEMENT,
    MISPRINT,
    PASS,
    Check,
    certificate,
    conclude,
    count_check,
    digits_check,
    eliminant_check,
    for_a_run,
    named,
    overridden,
    quantity,
    replaced,
    reworded,
    unread,
)
from proofs.section1_literature import witnessed

WORD = "ababcb"
ZERO = Q(0)                  # an exact 0 (fmpq is immutable: safe as a default argument)

# ---------------------------------------------------------------- as printed
M_PRINTED = """[[(r - 1)^3*(r^3 - 3*r^2 - 5*r - 9)/64, (r - 1)^2*(r^3 - r^2 + 7*r + 9)/32, (r + 1)^2/4],
 [-r*(r^5 - 7*r^4 + 10*r^3 + 18*r^2 + 5*r + 5)/32, -r*(r^4 - 4*r^3 + 10*r^2 + 4*r + 5)/16, -r*(r+1)/2],
 [(r + 1)^2*(r^4 - 12*r^3 + 42*r^2 - 20*r + 5)/64, (r - 1)^3*(r^2 - 4*r - 5)/32, (r - 1)^2/4]]"""
CP_PRINTED = ("λ^3 - λ^2/64*(r^6 - 10*r^5 + 23*r^4 - 44*r^3 + 15*r^2 - 74*r + 25)"
              " + λ/64*(25*r^6 - 74*r^5 + 15*r^4 - 44*r^3 + 23*r^2 - 10*r + 1) - r^6")
P0_PRINTED = ("41*r^10 - 646*r^9 + 3733*r^8 - 14600*r^7 + 42306*r^6 - 78052*r^5"
              " + 42306*r^4 - 14600*r^3 + 3733*r^2 - 646*r + 41")
DELTA_PRINTED = "-(1/1811939328)*(r - 1)^4*(r + 1)^6*(3*r^2 - 14*r + 3)^2*P0"
U_PRINTED = "r*(16*λ - r^4 + 8*r^3 + 2*r^2 + 8*r - 1)/(2*(r + 1)*(-r^3 + 6*r^2 - r + 4*λ))"
V_PRINTED = ("-(λ*(64*λ - r^6 + 10*r^5 - 23*r^4 + 44*r^3 + r^2 + 42*r - 9) + r^2*(20*r^4 - 32*r^3 + 8*r^2 + 4))"
             "/(4*(r + 1)^2*(-r^3 + 6*r^2 - r + 4*λ))")
A_PRINTED = "-64*r^2*(r^4 - 8*r^3 - 2*r^2 - 8*r + 1)*λ + 1024*r^6"
B_PRINTED = ("256*r^2*(r^2 - 6*r + 1)*λ^2 - 4*r^2*(r - 1)^2*(r - 3)^2*(r^4 - 8*r^3 - 2*r^2 - 8*r + 1)*λ"
             " + 64*r^6*(r^4 - 8*r^3 + 18*r^2 + 5)")
C_PRINTED = "16*(r - 1)^2*(r + 1)^2*(r^2 - 10*r + 1)*λ"
D_PRINTED = ("-64*(r^4 - 8*r^3 - 2*r^2 - 8*r + 1)*λ^2 + (r^10 - 18*r^9 + 101*r^8 - 216*r^7 + 66*r^6"
             " + 372*r^5 + 594*r^4 - 24*r^3 + 253*r^2 - 114*r + 9)*λ")
AMD_PRINTED = ("λ^2*(64*r^4 - 512*r^3 - 128*r^2 - 512*r + 64) + λ*(r - 1)^2*(-r^8 + 16*r^7 - 68*r^6"
               " + 64*r^5 + 66*r^4 + 208*r^3 - 116*r^2 + 96*r - 9) + 1024*r^6")
P1_PRINTED = ("17*r^11 - 435*r^10 + 4363*r^9 - 22753*r^8 + 61530*r^7 - 65806*r^6 - 27194*r^5"
              " + 24494*r^4 - 9499*r^3 + 3025*r^2 - 545*r + 35")
R1_PRINTED = (5, -2, 6)                     # r1 = 5 - 2√6 ≈ 0.10102
QUARTIC_B_PRINTED = "5*r^4 - 40*r^3 + 102*r^2 - 40*r + 5"
P2_PRINTED = "25*r^8 - 224*r^7 + 284*r^6 - 416*r^5 + 150*r^4 - 416*r^3 + 284*r^2 - 224*r + 25"
P3_PRINTED = "r^5 - 15*r^4 + 66*r^3 - 86*r^2 - 35*r + 5"
VELOCITIES_PRINTED = {
    "q2(t1)": (1, 1, "u - (1+r)/2"),
    "q1(t2)": (2, 0, "(1+r)/2*u - (r-1)^2/4"),
    "q2(t3)": (3, 1, "(r-1)^2/4*u - (r^3 - 5*r^2 - 5*r + 1)/8"),
    "q3(t4)": (4, 2, "(r^3 - r^2 + 3*r + 5)/8*u + v - (r + 1)^2*(r^2 - 6*r + 5)/16"),
    "q2(t5)": (5, 1, "(r^4 - 4*r^3 + 10*r^2 + 4*r + 5)/16*u + (1+r)/2*v - (r + 1)*(r^4 - 8*r^3 + 18*r^2 + 5)/32"),
}
P3_T4_PRINTED = ("x + ((-64*r^2 + 384*r - 64)*λ^2 + (r^8 - 16*r^7 + 84*r^6 - 192*r^5 + 222*r^4 - 208*r^3"
                 " + 196*r^2 - 96*r + 9)*λ + (-16*r^8 + 128*r^7 - 288*r^6 - 80*r^4))"
                 "/((16*r^4 - 128*r^3 - 32*r^2 - 128*r + 16)*λ - 256*r^4)")
P1_T5_PRINTED = ("λ*(r^2 - 1)^2*(r^2 - 10*r + 1)/(-64*λ^2 + 4*(-r^5 + 9*r^4 - 6*r^3 + 6*r^2 - 9*r + 1)*λ + 64*r^5)*x"
                 " + ((64*r^4 - 512*r^3 - 128*r^2 - 512*r + 64)*λ^2 + (-r^10 + 18*r^9 - 101*r^8 + 216*r^7"
                 " - 66*r^6 + 652*r^5 - 594*r^4 + 24*r^3 - 253*r^2 + 114*r - 9)*λ + (-64*r^9 + 512*r^8"
                 " + 128*r^7 + 512*r^6 - 64*r^5))/(1024*λ^2 + (64*r^5 - 576*r^4 + 384*r^3 - 384*r^2"
                 " + 576*r - 64)*λ - 1024*r^5)")


# the quantities the printed conditions are about (statements.relation reads them by these names)
DET, DELTA, C_SIGN, Q_VELOCITY, DOUBLE = sp.symbols("det_M Δ_cp c q λ₀")
MARK = {True: "✓", False: "✗"}
Q_MOBIUS = sp.Symbol("q", real=True)          # the paper's q = (cx₊+d)/(cx₋+d) (l. 496), real where Δ > 0


# ---------------------------------------------------------------- shared quantities
@quantity("candidate")
def ababcb_candidate():
    """M = BCBABA, cp(M), the branches, q(0) = (-1, u, v) from rows 1, 2 of M q = λ q,
    the run a, b, a, b, c, b from p(0) = (1, 0, x), and f (certify.dynamics.words)."""
    return candidate(WORD)


@quantity("M", needs=["candidate"])
def ababcb_matrix(candidate):
    """M = BCBABA: the velocities after one period ababcb are M q(0)."""
    return candidate.M


@quantity("cp", needs=["candidate"])
def ababcb_cp(candidate):
    """cp(M) = det(λI - M)."""
    return candidate.cp


@quantity("spectrum", needs=["candidate"])
def ababcb_spectrum(candidate):
    """The real eigenvalue branches of M over r."""
    return candidate.spectrum


# ---------------------------------------------------------------- helpers of this proof
def r1_of(printed) -> Algebraic:
    """The printed threshold a + b√n (5 - 2√6) as an algebraic number."""
    return Algebraic.surd(*printed)


@for_a_run
def fixed_point(a, b, c, d) -> FixedPoint:
    """The fixed point x₊ of the printed f(x) = (ax + b)/(cx + d)."""
    return FixedPoint(parse(a), parse(b), parse(c), parse(d))


def field_matrix(K) -> list[list]:
    """A matrix of rational functions as rows of elements of Q(λ, r, ...) (canonical: equal
    entries are equal elements)."""
    return [[to_field(K[i, j]) for j in range(K.cols)] for i in range(K.rows)]


def field_product(factors) -> list[list]:
    """The product of the matrices ``factors`` (left to right), computed in Q(λ, r, ...)."""
    out = field_matrix(factors[0])
    for K in factors[1:]:
        Kf = field_matrix(K)
        out = [[sum((row[k] * Kf[k][j] for k in range(len(Kf))), to_field(0)) for j in range(len(Kf[0]))]
               for row in out]
    return out


@for_a_run
def cancelled(e: sp.Expr) -> sp.Expr:
    """sp.cancel(e), memoised for the run (the same quotients recur in several claims)."""
    return sp.cancel(e)


def printed_uv(U, V):
    """The substitution u, v -> the printed formulas (l. 279-281)."""
    return {u: parse(U), v: parse(V)}



# ---------------------------------------------------------------- The statement (l. 250-321): the matrix M of the word
@certificate("T1", needs=["M"], printed=dict(M_text=M_PRINTED),
             expect=PASS,
             mutants=[replaced("M_text", "7*r + 9", "7*r + 8", "a coefficient of M")])
def matrix_of_ababcb(M, M_text):
    """The product of the collision matrices in time order a, b, a, b, c, b."""
    printed = sp.Matrix(parse(M_text))
    word = [B_, C_, B_, A_, B_, A_]
    direct = field_product(word)
    computed = field_matrix(M)
    checks = []
    for i in range(3):
        for j in range(3):
            ok = computed[i][j] == to_field(printed[i, j])      # equal in Q(r): the difference is 0
            checks.append(Check(f"entry ({i + 1},{j + 1}) as printed", ok, [f"computed `{show(M[i, j])}`"],
                                ref=f"T1.{3 * i + j + 1}"))
    checks.append(Check("word_matrix('ababcb') is the product BCBABA", direct == computed, ref="T1.10"))
    return conclude(checks, note="l. 259 has an unbalanced parenthesis, `(r^3 - r^2 + 7r + 9))/32`; read without it.")



# ---------------------------------------------------------------- Step 1: Studying the spectrum of M (l. 334-371)
@certificate("T2", needs=["cp"], printed=dict(cp_text=CP_PRINTED),
             expect=PASS,
             mutants=[replaced("cp_text", "74*r + 25", "74*r + 24", "a coefficient of cp")])
def characteristic_polynomial_of_M(cp, cp_text):
    """det(λI - M) expanded, against the print."""
    diff = sp.expand(cp - parse(cp_text))
    return conclude([Check("det(λI - M) - printed cp = 0", diff == 0, [f"det(λI - M) = `{show(sp.collect(cp, lam))}`"],
                           ref="T2.1")])


@certificate("T3", needs=["M", "spectrum"], printed=dict(det_text="r^6", det_sign="positive"),
             expect=PASS,
             mutants=[overridden({"det_text": "-r^6"}, "the sign of det M"),
                      reworded("det_sign", "positive", "negative"),
                      reworded("det_sign", "positive", "zero")])
def determinant_and_positive_eigenvalue(M, spectrum, det_text, det_sign):
    """det M as printed, and its printed sign ("the determinant of M is r^6, which is
    positive") read and checked on the exact sign intervals of det M over ]0,1[; the
    positive eigenvalue certified on the branch table: the largest eigenvalue is > 0
    on ]0,1[.  The paper's argument, cp(0) = -det M < 0 and cp(λ) → +∞, rests on
    cp(0) = -det M, which holds for every 3×3 matrix: evidence, not a check."""
    det = sp.factor(det3(field_matrix(M)).as_expr())     # by cofactors in Q(λ, r, ...)
    T = spectrum.table("λ", lam, 0, 1)
    as_printed = to_field(det) == to_field(parse(det_text))
    ivs = sign_intervals(to_fmpq_poly(det), 0, 1)
    sign = statements.statement(det_sign, {"det M": DET}, subject="det M")   # the printed sign and range
    signs = sign.range.signs(ivs)                                            # read on the sign intervals
    return conclude([
        Check(f"det M = {det_text}", as_printed, [f"det M = `{show(det)}`"], ref="T3.1"),
        Check(f"det M is {det_sign} on ]0,1[", sign.relation.holds_on(DET, signs),
              [f"signs of det M on ]0,1[ (exact sign intervals): {sign_word(signs)}"], ref="T3.2"),
        Check("the largest real eigenvalue is positive on all of ]0,1[", T.holds(UPPER, 1),
              ["sign of λ per branch:\n\n" + T.markdown()], ref="T3.3"),
    ], evidence=["the paper's argument (l. 340): cp(0) = det(-M) = -det M < 0 and cp(λ) → +∞ as λ → +∞, so cp has a "
                 "root λ > 0; cp(0) = -det M holds for every 3×3 matrix, so it is no check"])


def cardano(cp):
    """(q/2)² + (p/3)³ for the depressed cubic t³ + pt + q of the monic cubic cp in λ."""
    P = to_ring(cp)
    L = P.ring.gens[0]                      # λ, the first generator of the ring
    c = [P.coeff_wrt(L, k) for k in range(P.degree(L), -1, -1)]
    if len(c) != 4 or not c[0].is_ground:
        raise ValueError("cp is not a cubic in λ with a constant leading coefficient")
    a2, a1, a0 = [ci * (1 / c[0].LC) for ci in c[1:]]
    third, half = sp.Rational(1, 3), sp.Rational(1, 2)
    p = a1 - a2 ** 2 * third
    q = a2 ** 3 * sp.Rational(2, 27) - a2 * a1 * third + a0
    return ((q * half) ** 2 + (p * third) ** 3).as_expr()     # expanded: the sparse polynomial's terms


@certificate("T4", needs=["cp", "spectrum"], printed=dict(delta_text=DELTA_PRINTED, P0_text=P0_PRINTED,
                                                             three_real_when="Δ_cp < 0"),
             expect=PASS,
             mutants=[replaced("three_real_when", "<", ">", "the direction of the condition"),
                      reworded("three_real_when", "<", "≤", "Δ_cp = 0 is a double root, not three"),
                      unread("three_real_when", "Δ_cp << 0", "not a relation")])
def discriminant_of_cp(cp, spectrum, delta_text, P0_text, three_real_when):
    """The printed Δ_cp is -Disc_λ(cp)/108 = (q/2)² + (p/3)³ (Cardano's form for the
    depressed cubic), not the discriminant itself; with that normalisation, three
    distinct real eigenvalues iff Δ_cp < 0 (Disc > 0).  The printed condition is read
    and its truth, for each sign of Δ_cp, compared with that of Disc > 0."""
    delta = parse(delta_text.replace("P0", f"({P0_text})"))
    disc = sp.discriminant(cp, lam)
    ratio = (to_field(disc) / to_field(delta)).as_expr() if delta != 0 else None   # canceled
    card = cardano(cp)
    card_same = to_field(card) == to_field(delta)
    constant = ratio is not None and ratio.is_number and ratio != 0
    condition = statements.relation(three_real_when, {"Δ_cp": DELTA})
    three_real = {s: constant and int(sp.sign(ratio)) * s > 0 for s in (-1, 0, 1)}   # Disc = ratio·Δ_cp > 0
    flint_same = same_up_to_constant(discriminant_lambda(cp), to_fmpz_poly(delta))
    # on ]0,1[: the number of real eigenvalues per cell of the spectrum (cut at the roots of Disc_λ(cp),
    # where Δ_cp keeps its sign) against the sign of Δ_cp at the cell's sample; at the zeros of Δ_cp
    # (critical values of the table) the eigenvalues with multiplicity (a double one and a simple one: 3)
    T = spectrum.table("λ", lam, 0, 1)
    dpoly = flint.fmpq_poly(to_fmpq_poly(delta))
    sign_at = {c.sample: int(dpoly(c.sample) > 0) - int(dpoly(c.sample) < 0) for c in T.cells}
    zeros = [b_ for _a, b_, _s in sign_intervals(dpoly, 0, 1)[:-1]]
    at_zeros = [next((k for k, rc in enumerate(T.critical) if rc == z), None) for z in zeros]
    double = bool(zeros) and all(k is not None and T.points[k] is not None and len(T.points[k]) == 3 for k in at_zeros)
    # the sign of Δ_cp changes only where P0's does (l. 349: the other factors have even powers)
    p0_ivs = sign_intervals(flint.fmpq_poly(to_fmpq_poly(parse(P0_text))), 0, 1)
    d_ivs = sign_intervals(dpoly, 0, 1)
    d_changes = [b_ for (_a, b_, s1), (_a2, _b2, s2) in zip(d_ivs, d_ivs[1:]) if s1 != s2]
    p0_changes = [b_ for (_a, b_, s1), (_a2, _b2, s2) in zip(p0_ivs, p0_ivs[1:]) if s1 != s2]
    return conclude([
        Check("the printed Δ_cp is a constant multiple of Disc_λ(cp)", constant, [f"Disc_λ(cp) / Δ_cp = {ratio}"],
              ref="T4.1"),
        Check("Δ_cp = (q/2)² + (p/3)³ of the depressed cubic (Cardano's convention), Disc_λ(cp) = −108·Δ_cp",
              card_same and ratio == -108, ref="T4.2"),
        Check(f"three distinct real roots iff {three_real_when} (Disc > 0 iff three distinct real roots)",
              constant and condition.truth(DELTA) == three_real,
              [f"Disc_λ(cp) = ({ratio})·Δ_cp; for Δ_cp < 0, = 0, > 0: three distinct real roots "
               + ", ".join("yes" if three_real[s] else "no" for s in (-1, 0, 1)) + "; the printed condition "
               + ", ".join("yes" if condition.holds({DELTA: s}) else "no" for s in (-1, 0, 1))], ref="T4.3"),
        Check("on ]0,1[: three real eigenvalues on every cell where Δ_cp < 0",
              all(len(c.branches) == 3 for c in T.cells if sign_at[c.sample] < 0), ref="T4.3"),
        Check("on ]0,1[: where Δ_cp = 0, a double eigenvalue and a simple one (two distinct real eigenvalues)",
              double, [f"zeros of Δ_cp in ]0,1[: {', '.join(z.describe() for z in zeros)}"], ref="T4.4"),
        Check("on ]0,1[: one real eigenvalue on every cell where Δ_cp > 0",
              all(len(c.branches) == 1 for c in T.cells if sign_at[c.sample] > 0), ref="T4.5"),
        Check("the sign of Δ_cp changes only where P0 changes sign (the other factors have even powers), on ]0,1[",
              all(any(z == w for w in p0_changes) for z in d_changes),
              [f"Δ_cp changes sign at {', '.join(z.describe() for z in d_changes)}; P0 at "
               f"{', '.join(z.describe() for z in p0_changes)}"], ref="T4.6"),
        Check("flint's Disc_λ(cp) has the same factors", flint_same),
    ], note="Convention: the paper's Δ_cp is −Disc/108 = (q/2)²+(p/3)³ (the paper says 'determinant' for "
            "'discriminant', l. 341). Disc_λ(cp) = −108·Δ_cp.")


@certificate("T5", needs=["cp"], printed=dict(P0_text=P0_PRINTED, count=1, digits="0.11384"),
             expect=PASS,
             mutants=[overridden({"digits": "0.11385"}, "a digit of r*")])
def P0_has_one_root(cp, P0_text, count, digits):
    """Sturm count and python-flint count; the digits certified by an isolating interval."""
    roots, nf = roots_in_unit_interval(P0_text)
    checks = [Check("P0 divides Disc_λ(cp)", discriminant_lambda(cp) % to_fmpz_poly(parse(P0_text)) == 0, ref="T5.1"),
              named("T5.2", count_check("P0", roots, nf, count))]
    if roots:
        checks.append(named("T5.3", digits_check("r*", roots[0], digits)))
    return conclude(checks)



@certificate("T6", printed=dict(delta_text=DELTA_PRINTED, P0_text=P0_PRINTED, r0=(sp.Rational(7, 3), sp.Rational(-2, 3), 10),
                          below="Δ_cp < 0 for r < r*", above="Δ_cp ≥ 0 for r > r*"),
             expect=PASS,
             mutants=[replaced("below", "Δ_cp <", "Δ_cp >", "the direction below r*"),
                      reworded("below", "r < r*", "r > r*"),
                      reworded("above", "≥", ">", "Δ_cp vanishes at (7-2√10)/3 > r*"),
                      reworded("above", "Δ_cp ≥", "Δ_cp ≤"),
                      unread("below", "Δ_cp < 0 for r ≤ r*", "a closed end is not read")])
def sign_of_delta(delta_text, P0_text, r0, below, above):
    """Exact sign intervals of the printed Δ_cp (a polynomial in r) on ]0,1[; each
    printed condition read (a relation on Δ_cp, a range of r) and evaluated on the
    signs Δ_cp takes over that range, its roots there included."""
    delta_expr = parse(delta_text.replace("P0", f"({P0_text})"))
    delta = flint.fmpq_poly(to_fmpq_poly(delta_expr))
    ivs = sign_intervals(delta, 0, 1)
    rs, rz = unique_root(P0_text), Algebraic.surd(*r0)
    zeros = [b for a, b, sg in ivs[:-1]]
    evidence = [f"sign on ]{a.short()}, {b.short()}[: {'+' if sg > 0 else '−'}" for a, b, sg in ivs]
    checks = []
    for text in (below, above):
        st = statements.statement(text, {"Δ_cp": DELTA, "r*": rs})
        signs = st.range.signs(ivs)
        checks.append(Check(text, st.relation.holds_on(DELTA, signs),
                            [f"signs of Δ_cp for {st.range}: {sign_word(signs)}"] + evidence,
                            ref=f"T6.{len(checks) + 1}"))
        evidence = []
    return conclude(checks + [
        Check("in ]0,1[, Δ_cp vanishes only at r* and (7-2√10)/3", len(zeros) == 2 and zeros[0] == rs and zeros[1] == rz,
              [f"zeros: {', '.join(z.describe() for z in zeros)}"], ref="T6.3"),
    ])


@certificate("T7", needs=["spectrum"],
             printed=dict(quadratic="3*r^2 - 14*r + 3", r0=(sp.Rational(7, 3), sp.Rational(-2, 3), 10),
                          digits="0.22515", repeated="negative"),
             expect=PASS,
             mutants=[overridden({"repeated": "positive"}, "the sign of the repeated eigenvalue"),
                      reworded("repeated", "negative", "non-negative"),
                      unread("repeated", "small", "not a sign word")])
def repeated_eigenvalue(spectrum, quadratic, r0, digits, repeated):
    """At r0 the gcd of cp and ∂cp/∂λ, computed exactly in Q(r0)[λ], is linear: its
    root is the double eigenvalue, whose sign is certified by ball arithmetic."""
    roots, nf = roots_in_unit_interval(quadratic)
    rz = Algebraic.surd(*r0)
    checks = [named("T7.1", count_check(quadratic, roots, nf, 1)),
              Check("the root is (7-2√10)/3", bool(roots) and roots[0] == rz, ref="T7.2")]
    if roots:
        checks.append(named("T7.3", digits_check("(7-2√10)/3", roots[0], digits)))
        signs = spectrum.sign_at_point(Condition.of("λ", lam), roots[0])
        double = signs is not None and len(signs) == 3 and signs[1] == signs[2]
        sign = statements.relation(repeated, {"λ₀": DOUBLE}, subject="λ₀")
        checks.append(Check(f"there is a double eigenvalue λ₀ at r0, and it is {repeated}",
                            double and sign.holds_on(DOUBLE, {signs[1]}),
                            [f"signs of the eigenvalues at r0, largest first (the double one listed twice): {signs}"],
                            ref="T7.4"))
    return conclude(checks)


@certificate("T8", needs=["spectrum"], printed=dict(P0_text=P0_PRINTED, r1=R1_PRINTED, positive="λ > 0 for 0 < r < 5-2√6"),
             expect=PASS,
             mutants=[replaced("P0_text", "41*r^10", "40*r^10", "a coefficient of P0"),
                      reworded("positive", "λ > 0", "λ < 0"),
                      reworded("positive", "5-2√6", "1", "the lower branches end at r*"),
                      unread("positive", "μ > 0 for 0 < r < 5-2√6", "an unknown name")])
def branches_of_the_spectrum(spectrum, P0_text, r1, positive):
    """Number of real eigenvalues per cell (Sturm at one sample per cell, constant
    between the zeros of Disc_λ(cp)); the sign of λ on each branch, against the
    printed condition (l. 491: "all eigenvalues up to r = 5-2√6 are positive") read
    whole, its range included."""
    from certify.run import spectrum_figures
    rs, rr1 = unique_root(P0_text), r1_of(r1)
    T = spectrum.table("λ", lam, 0, 1)
    three = all((len(c.branches) == 3) == (c.hi <= rs) for c in T.cells)
    st = statements.statement(positive, {"λ": lam})
    signs = [T.signs(k, st.range.lo, st.range.hi) for k in range(3)]
    all_three = all(st.relation.holds_on(lam, sg) for sg in signs)
    pos_rstar = all(T.holds(k, 1, 0, rs) for k in range(3))
    figs = spectrum_figures(spectrum, T, marks={"r*": rs, "5-2√6": rr1, "(7-2√10)/3": unique_root("3*r^2 - 14*r + 3")})
    return conclude([
        Check("three distinct real eigenvalues exactly on ]0, r*[ (one real eigenvalue on ]r*, 1[ but a double "
              "one at (7-2√10)/3)", three and T.critical[0] == rs, ["number of real eigenvalues and sign of λ per cell:\n\n"
                                                                     + T.markdown()], ref="T8.1"),
        Check("the upper branch exists on all of ]0,1[", all(len(c.branches) >= 1 for c in T.cells)
              and all(p is not None and len(p) >= 1 for p in T.points),
              ["true of every real cubic (odd degree): the check is that the table isolates it in every cell and at "
               "every critical value"], ref="T8.2"),
        Check("5-2√6 < r* (exact comparison of algebraic numbers)", rr1 < rs, [f"5-2√6 is {rr1.describe()}",
                                                                             f"r* is {rs.describe()}"], ref="T8.3"),
        Check(f"all three eigenvalues: {positive}", all_three,
              [f"{BRANCH_NAMES[k]}: {sign_word(sg)}" for k, sg in enumerate(signs)], ref="T8.4"),
        Check("hence the middle and lower eigenvalues are smaller in absolute value than the upper one on ]0, r*[ "
              "(all positive there, ordered)", pos_rstar, ref="T8.5"),
    ], figures=figs)


@certificate("T9", needs=["M"], printed=dict(U=U_PRINTED, V=V_PRINTED),
             expect=PASS,
             mutants=[replaced("U", "16*λ", "15*λ", "a coefficient of u")])
def eigenvector_components(M, U, V):
    """Substitute q(0) = (-1, u, v) into rows 1 and 2 of M q - λ q: zero in Q(r, λ)."""
    q0 = sp.Matrix([-1, parse(U), parse(V)])
    Mf, qf = field_matrix(M), [to_field(e) for e in q0]
    res = [sum((Mf[i][j] * qf[j] for j in range(3)), -to_field(lam) * qf[i]) for i in range(3)]   # in Q(λ, r)
    cpM = characteristic_polynomial(M)
    third = reduce_mod(res[2], cpM)
    return conclude([
        Check("first component of M q(0) - λ q(0) vanishes identically", res[0] == 0, ref="T9.1"),
        Check("second component vanishes identically", res[1] == 0, ref="T9.2"),
        Check("and the third vanishes modulo cp(M): q(0) is an eigenvector", third == 0,
              [f"third component reduced modulo cp: `{show(third)}`"], ref="T9.3"),
    ])



# ---------------------------------------------------------------- Step 2: Studying when f has a positive fixed point (l. 372-386)
@certificate("T10", needs=["candidate"],
             printed=dict(a=A_PRINTED, b=B_PRINTED, c=C_PRINTED, d=D_PRINTED),
             expect=PASS,
             mutants=[replaced("d", "372*r^5", "373*r^5", "a coefficient of d")])
def position_map_of_ababcb(candidate, a, b, c, d):
    """The computed (a, b, c, d) and the printed ones are proportional modulo cp:
    every 2×2 minor of the two quadruples reduces to zero.  That the collisions are
    a, b, a, b, c, b and p_2(t6) = 0 holds by construction (the engine applies the
    word, and t6 is the time when p_2 vanishes): evidence, not checks."""
    steps, abcd, cp = candidate.steps, candidate.abcd, candidate.cp
    P = [to_field(parse(e)) for e in (a, b, c, d)]
    comp = [to_field(e) for e in abcd]
    names = "abcd"
    minors = {f"{names[i]}{names[j]}": reduce_mod(P[i] * comp[j] - P[j] * comp[i], cp)
              for i in range(4) for j in range(i + 1, 4)}
    word = "".join(s.letter for s in steps)
    ratio = P[2] / comp[2]
    constant = ratio.numer.is_ground and ratio.denom.is_ground
    factor = ratio.as_expr() if constant else sp.cancel(P[2].as_expr() / comp[2].as_expr())
    p1 = steps[-1].position(0)
    scaled = P[2] == to_field(factor) * comp[2]
    pa, pb, pc, pd = (parse(e) for e in (a, b, c, d))          # x± as printed at l. 384 (s = √Δ)
    s_ = sp.Symbol("s")
    xs = (pa - pd + s_) / (2 * pc)
    fixed_points_ok = (sp.cancel((pa * x + pb) / (pc * x + pd) - x + (pc * x ** 2 + (pd - pa) * x - pb) / (pc * x + pd)) == 0
                       and sp.cancel(pc * xs ** 2 + (pd - pa) * xs - pb - (s_ ** 2 - ((pa - pd) ** 2 + 4 * pb * pc)) / (4 * pc)) == 0)
    return conclude([
        Check("p_1(t6) ≢ 0, so that f(x) = p_3(t6)/p_1(t6) is defined", p1 != 0, ref="T10.1"),
        Check("f is a Möbius map (ax+b)/(cx+d) proportional to the printed one modulo cp",
              all(m == 0 for m in minors.values()),
              [f"computed (modulo cp): a = `{show(abcd[0])}`, c = `{show(abcd[2])}`",
               f"printed c / computed c = {factor}"] +
              [f"minor {k} modulo cp: `{show(m)}`" for k, m in minors.items()], ref="T10.2"),
        Check("any fixed point of f is x± = (a-d ± √((a-d)^2+4bc))/(2c): f(x) - x = -(cx^2 + (d-a)x - b)/(cx+d), and "
              "(a-d ± s)/(2c) is a root of cx^2 + (d-a)x - b exactly when s^2 = (a-d)^2+4bc", fixed_points_ok,
              ref="T10.3"),
        Check(f"the factor printed/computed is a negative constant, {factor}: x± = (a-d ± √Δ)/(2c) swap, so the "
              "paper's x₊ is the computed x₋ (as `certify pattern ababcb` prints)",
              bool(factor.is_Rational) and factor < 0 and scaled),
    ], evidence=[f"by construction: the engine applies the collisions {', '.join(word)} (q(t_k) = K q(t_(k-1))) and "
                 "defines t6 by p_2(t6) = 0, so p(t6) = (p_1(t6), 0, p_3(t6)) = p_1(t6)(1, 0, f(x))"])



# ---------------------------------------------------------------- Step 2.1: Studying the sign of a-d (l. 387-417)
@certificate("T11", printed=dict(a=A_PRINTED, d=D_PRINTED, amd=AMD_PRINTED),
             expect=PASS,
             mutants=[replaced("amd", "1024*r^6", "1023*r^6", "a coefficient of a-d")])
def expansion_of_a_minus_d(a, d, amd):
    """a - d from the printed a and d, expanded, against the printed expansion."""
    diff = sp.expand(parse(a) - parse(d) - parse(amd))
    return conclude([Check("(a) - (d) - (printed a-d) = 0", diff == 0, [f"difference: `{show(diff)}`"], ref="T11.1")])



@certificate("T12", needs=["cp"], printed=dict(amd=AMD_PRINTED, P1_text=P1_PRINTED, r1=R1_PRINTED, r1_digits="0.10102"),
             expect=PASS,
             mutants=[replaced("P1_text", "35", "36", "a coefficient of P1"),
                      overridden({"r1_digits": "0.10103"}, "a digit of r1")])
def eliminant_of_a_minus_d(cp, amd, P1_text, r1, r1_digits):
    """The eliminant both ways (l. 392-400), and its roots in ]0,1[: r1 = 5-2√6, the root of r^2-10r+1,
    and those of P1 (l. 401)."""
    product = to_fmpz_poly(parse(f"r^6*(r-1)^4*(r+1)^4*(r^2-10*r+1)*({P1_text})"))
    quad = to_fmpz_poly(parse("r^2-10*r+1"))
    inside = Algebraic.roots(product, 0, 1)
    wanted = Algebraic.roots(quad * to_fmpz_poly(parse(P1_text)), 0, 1)
    rr1, quad_roots = r1_of(r1), Algebraic.roots(quad, 0, 1)
    checks = eliminant_check("a-d", parse(amd), cp, f"r^6*(r-1)^4*(r+1)^4*(r^2-10*r+1)*({P1_text})")
    checks[0].ref = "T12.1"
    checks += [Check("the printed polynomial has roots in ]0,1[ at r1 := 5-2√6 (the root of r^2-10r+1) and at the "
                     "roots of P1", len(inside) == len(wanted) and all(x_ == y_ for x_, y_ in zip(inside, wanted))
                     and len(quad_roots) == 1 and quad_roots[0] == rr1,
                     [f"roots in ]0,1[: {', '.join(z.describe() for z in inside)}"], ref="T12.2"),
               named("T12.2", digits_check("r1 = 5-2√6", rr1, r1_digits))]
    return conclude(checks)


@certificate("T13", printed=dict(P1_text=P1_PRINTED, real=3, inside=1, digits="0.13145"),
             expect=PASS,
             mutants=[overridden({"digits": "0.13146"}, "a digit of r2")])
def roots_of_P1(P1_text, real, inside, digits):
    """Sturm counts over R, ]-∞,0] and [1,∞[, with python-flint's count beside them."""
    P = to_fmpz_poly(parse(P1_text))
    all_roots = Algebraic.roots(P)
    roots, nf = roots_in_unit_interval(P1_text)
    n_flint, n_sturm = len(flint_real_roots(P)), sturm_count(P)
    checks = [Check(f"P1 has exactly {real} real roots (Sturm and python-flint)",
                    n_sturm == real and n_flint == real and len(all_roots) == real,
                    [f"Sturm {n_sturm}, python-flint {n_flint}; "
                                                                  + "; ".join(a.describe() for a in all_roots)],
                    ref="T13.1"),
              named("T13.2", count_check("P1", roots, nf, inside)),
              Check("the others are ≤ 0 and ≥ 1", len(all_roots) == 3 and all_roots[0] <= 0 and all_roots[2] >= 1,
                    ref="T13.3")]
    if roots:
        checks.append(named("T13.4", digits_check("r2", roots[0], digits)))
    return conclude(checks)



@certificate("T14", needs=["spectrum"],
             printed=dict(amd=AMD_PRINTED, r1=R1_PRINTED, P1_text=P1_PRINTED, at_r1="middle", at_r2="upper"),
             expect=PASS,
             mutants=[overridden({"at_r1": "upper"}, "the branch where a-d changes sign at r1"),
                      reworded("at_r1", "middle", "lower"),
                      reworded("at_r2", "upper", "middle"),
                      unread("at_r1", "central", "not a branch")])
def sign_of_a_minus_d(spectrum, amd, r1, P1_text, at_r1, at_r2):
    """The sign table of a-d over ]0,1[ (Figure 3, fig: sign changes a-d)."""
    from certify.run import sign_chart
    rr1, rr2 = r1_of(r1), unique_root(P1_text)
    T = spectrum.table("a-d", parse(amd), 0, 1)
    k1, k2 = statements.branch(at_r1), statements.branch(at_r2)
    fig = sign_chart(spectrum, T, "sign_a_minus_d.png", "certified sign of a − d on the branches of M",
                     marks={"5-2√6": rr1, "r2": rr2})
    return conclude([
        Check(f"a-d changes sign at r1 on the {at_r1} branch", T.changes_at(k1, rr1), ["sign table of a-d:\n\n" + T.markdown()],
              ref="T14.1"),
        Check(f"a-d changes sign at r2 on the {at_r2} branch", T.changes_at(k2, rr2), ref="T14.2"),
        Check("and nowhere else on any branch (other critical values keep every sign)",
              all(T.keeps_sign_at(k, pt) for pt in T.critical for k in range(3) if (pt, k) not in ((rr1, k1), (rr2, k2))),
              ref="T14.3"),
    ], figures=[fig])



# ---------------------------------------------------------------- Step 2.2: Studying the sign of b (l. 418-427)
@certificate("T15", needs=["cp", "spectrum"], printed=dict(b=B_PRINTED, quartic=QUARTIC_B_PRINTED, r1=R1_PRINTED),
             expect=PASS,
             mutants=[replaced("quartic", "102*r^2", "20*r^2", "a quartic with real roots")])
def sign_of_b(cp, spectrum, b, quartic, r1):
    """Elimination both ways, the quartic's real roots counted both ways, and the
    sign table of b (Figure 4, fig: sign change b)."""
    from certify.run import sign_chart
    rr1 = r1_of(r1)
    Q4 = to_fmpz_poly(parse(quartic))
    T = spectrum.table("b", parse(b), 0, 1)
    fig = sign_chart(spectrum, T, "sign_b.png", "certified sign of b on the branches of M", marks={"5-2√6": rr1})
    checks = eliminant_check("b", parse(b), cp, f"r^6*(r-1)^4*(r+1)^4*(r^2-10*r+1)*({quartic})")
    checks[0].ref = "T15.1"
    checks += [
        Check("the quartic has no real root (Sturm and python-flint)",
              sturm_count(Q4) == 0 and len(flint_real_roots(Q4)) == 0, ref="T15.2"),
        Check("b changes sign at 5-2√6 on one of the two lower branches (the middle one), not on the lowest one nor on "
              "the upper one", T.changes_at(MIDDLE, rr1) and T.keeps_sign_at(LOWER, rr1) and T.keeps_sign_at(UPPER, rr1),
              ["sign table of b:\n\n" + T.markdown()],
              ref="T15.3"),
    ]
    return conclude(checks, figures=[fig], note="Precisely: b changes sign at 5-2√6 on the middle branch only; "
                                                "on the lower branch b keeps its sign there.")


T16_CORRECTION = ("c > 0", "c < 0")          # in the second half, l. 433



# ---------------------------------------------------------------- Step 2.3: Studying the sign of c (l. 428-434)
@certificate("T16", printed=dict(c=C_PRINTED, below="c > 0 for r < 5-2√6", above="c > 0 for r > 5-2√6"),
             expect=ERRATUM,
             mutants=[replaced("c", "(r^2 - 10*r + 1)", "(r^2 - 9*r + 1)", "a coefficient of c"),
                      reworded("below", "c > 0", "c < 0"),
                      reworded("above", "c > 0", "c ≥ 0", "the stated correction no longer applies"),
                      unread("below", "c > 0 for r < 5-2√6 for r > 0", "two ranges")])
def sign_of_c(c, below, above):
    """c/λ is a polynomial in r: its exact sign intervals on ]0,1[, and sign c = sign c/λ
    as λ > 0 (l. 432).  Each half of the printed sentence is read (a relation on c, a
    range of r) and evaluated on the signs c takes over its range.  The corrected
    statement is the printed one with the stated correction c > 0 → c < 0 in its second
    half, the first half as printed."""
    cr = sp.cancel(parse(c) / lam)
    quad = parse("r^2 - 10*r + 1")
    ratio = sp.cancel(cr / quad)
    ivs = sign_intervals(to_fmpq_poly(sp.expand(cr)), 0, 1)
    ratio_pos = False
    if not ratio.has(lam) and ratio.is_polynomial(r):
        ratio_ivs = sign_intervals(to_fmpq_poly(sp.expand(ratio)), 0, 1)
        ratio_pos = all(sg > 0 for _a, _b, sg in ratio_ivs)

    def half(text, evidence=()):
        st = statements.statement(text, {"c": C_SIGN})
        signs = st.range.signs(ivs)              # the range read, compared with the ends of the intervals
        return Check(text, st.relation.holds_on(C_SIGN, signs), [f"signs of c for {st.range}: {sign_word(signs)}",
                                                                 *evidence])
    printed = [Check("c/λ = (r^2-10r+1)·(positive on ]0,1[), so sign c = sign(r^2-10r+1) when λ > 0", ratio_pos,
                     [f"c/λ ÷ (r^2-10r+1) = `{show(sp.factor(ratio))}`"], ref="T16.1"),
               named("T16.2", half(below)),
               named("T16.3", half(above, [f"sign of c/λ on ]{a.short()}, {b_.short()}[: {'+' if sg > 0 else '−'}"
                                           for a, b_, sg in ivs]))]
    fixed = statements.corrected(above, *T16_CORRECTION)
    correction = half(fixed) if fixed else Check(f"the stated correction {' → '.join(T16_CORRECTION)} applies to "
                                                 f"the printed `{above}`", False)
    correction.corrects, correction.ref = printed[2], "T16.4"
    return conclude(printed, [correction, printed[0], printed[1]], kind=MISPRINT,
                    misprint="l. 433: c > 0 printed for c < 0 (r > 5-2√6)")



# ---------------------------------------------------------------- Step 2.4: Deducing the sign of the fixed points of f (l. 435-441)
def fixed_point_tables(spectrum, a, b, c, d, lo, hi):
    """Sign tables of x₊ and x₋ = (a-d)/c - x₊ (x real only where Δ ≥ 0)."""
    fp = fixed_point(a, b, c, d)
    xp = spectrum.table("x₊", x, lo, hi, fp)
    xm = spectrum.table("x₋", cancelled((parse(a) - parse(d)) / parse(c)) - x, lo, hi, fp)
    return fp, xp, xm


def fixed_point_signs_at(spectrum, fp, rc, branch) -> set:
    """Signs of the real fixed points x₊, x₋ on ``branch`` at the algebraic r = rc:
    where Δ vanishes exactly there, the double fixed point (a-d)/(2c)."""
    if spectrum.vanishes_at(fp.delta, rc, branch):
        pt = spectrum.sign_at_point(Condition.of("(a-d)/c", (fp.a - fp.d) / fp.c), rc)
        return {pt[branch] if pt else "?"}
    out = set()
    for name, g in (("x₊", x), ("x₋", cancelled((fp.a - fp.d) / fp.c) - x)):
        pt = spectrum.sign_at_point(Condition.of(name, g, fp), rc)
        out.add(pt[branch] if pt else "?")
    return out


def no_positive_fixed_point(spectrum, fp, xp, xm, branch, lo, hi, skip=()) -> tuple[bool, list[str]]:
    """x₊, x₋ are negative or not real on ``branch`` over ]lo, hi[: cells from the sign
    tables, interior critical values one by one (except those in ``skip``)."""
    cells = (xp.signs(branch, lo, hi, include_points=False) | xm.signs(branch, lo, hi, include_points=False)) - {"missing"}
    ok, ev = cells <= {-1, None}, [f"on the cells: {sign_word(cells)}"]
    for rc in xp.critical:
        if lo < rc < hi and not any(rc == s_ for s_ in skip):
            exists = any(c.hi == rc and branch < len(c.branches) for c in xp.cells)
            if not exists:
                continue
            signs = fixed_point_signs_at(spectrum, fp, rc, branch)
            ok = ok and signs <= {-1, None}
            ev.append(f"at r ≈ {rc.digits(8)}: {sign_word(signs)}")
    return ok, ev


@certificate("T17", needs=["spectrum"],
             printed=dict(a=A_PRINTED, b=B_PRINTED, c=C_PRINTED, d=D_PRINTED, U=U_PRINTED, V=V_PRINTED,
                          r1=R1_PRINTED, P1_text=P1_PRINTED),
             expect=ERRATUM,
             mutants=[replaced("c", "16*", "-16*", "the sign of c")])
def upper_branch_fixed_points(spectrum, a, b, c, d, U, V, r1, P1_text):
    """a-d, b, c > 0 on the upper branch below r1, so x₊ > 0 > x₋; the sign tables of
    x₊, x₋ and Δ = (a-d)² + 4bc on the upper branch over ]0,1[, and exact zero tests
    of Δ at the critical values."""
    rr1, rr2 = r1_of(r1), unique_root(P1_text)
    amd, bb, cc = (spectrum.table(n, g, 0, 1) for n, g in (("a-d", parse(a) - parse(d)), ("b", parse(b)), ("c", parse(c))))
    fp, xp, xm = fixed_point_tables(spectrum, a, b, c, d, 0, 1)
    D = spectrum.table("Δ", fp.delta, 0, 1)
    r0 = Algebraic.surd(sp.Rational(7, 3), sp.Rational(-2, 3), 10)
    at_r2 = spectrum.sign_at_point(Condition.of("Δ", fp.delta), rr2)
    bc_r2 = spectrum.sign_at_point(Condition.of("bc", parse(b) * parse(c)), rr2)
    amd_r2 = spectrum.vanishes_at(fp.a - fp.d, rr2, UPPER)
    between, ev_between = no_positive_fixed_point(spectrum, fp, xp, xm, UPPER, rr1, rr2)
    zeros = [rc for rc in D.critical if rr2 < rc and spectrum.vanishes_at(fp.delta, rc, UPPER)]
    cells_negative = D.signs(UPPER, rr2, 1, include_points=False) == {-1}
    above, ev_above = no_positive_fixed_point(spectrum, fp, xp, xm, UPPER, rr1, 1)
    above_but_r0, _ev = no_positive_fixed_point(spectrum, fp, xp, xm, UPPER, rr1, 1, skip=(r0,))
    printed = [
        Check("a-d, b, c > 0 on the upper branch for r < 5-2√6",
              all(T.holds(UPPER, 1, 0, rr1) for T in (amd, bb, cc)), ref="T17.1"),
        Check("exactly one positive fixed point, x₊, for r < 5-2√6", xp.holds(UPPER, 1, 0, rr1) and xm.holds(UPPER, -1, 0, rr1),
              ["x₊ on the branches:\n\n" + xp.markdown(), "x₋ on the branches:\n\n" + xm.markdown()], ref="T17.2"),
        Check("no positive fixed point for 5-2√6 < r < r2", between, ev_between, ref="T17.3"),
        Check("at r2 the fixed points are not real: a-d = 0 and 4bc < 0, so Δ < 0 on the upper branch",
              at_r2 is not None and at_r2[0] == -1 and amd_r2 and bc_r2 is not None and bc_r2[0] == -1, ref="T17.4"),
        Check("(a-d)^2 + 4bc < 0 on the upper branch from r2 until r = 1", cells_negative and not zeros,
              ["Δ on the branches:\n\n" + D.markdown()] +
              [f"Δ = 0 exactly on the upper branch at {z.describe()}" for z in zeros], ref="T17.5"),
        Check("so that a positive fixed point on the upper branch can only exist up to r = 5-2√6", above, ev_above,
              ref="T17.7"),
    ]
    corrected = printed[:4] + [Check("(a-d)^2 + 4bc < 0 on the upper branch from r2 until r = 1, except at the one point "
                                     "r0 = (7-2√10)/3, where it vanishes",
                                     cells_negative and len(zeros) == 1 and zeros[0] == r0,
                                     corrects=printed[4], ref="T17.6")]
    x0 = cancelled((fp.a - fp.d) / (2 * fp.c))
    sx = spectrum.sign_at_point(Condition.of("(a-d)/(2c)", x0), r0)
    tc = spectrum.sign_at_point(Condition.of("t_c - t_a", x0 / (-parse(V)) - 1), r0)
    sv = spectrum.sign_at_point(Condition.of("v", parse(V)), r0)
    su = spectrum.sign_at_point(Condition.of("u", parse(U)), r0)
    corrected.append(Check("above 5-2√6 a positive fixed point exists on the upper branch only at r0 = (7-2√10)/3: the "
                           "double fixed point x = (a-d)/(2c) > 0, from which (p(0) = (1,0,x), q(0) = (-1,u,v)) the first "
                           "collision is c (u > 0: b does not come first; v < 0 and t_c = x/(-v) < 1 = t_a), not a: no "
                           "self-similar datum there",
                           above_but_r0 and zeros == [r0] and bool(sx and tc and sv and su) and sx[UPPER] == 1
                           and su[UPPER] == 1 and sv[UPPER] == -1 and tc[UPPER] == -1,
                           [f"signs at r0 on the upper branch: x {sx and sx[UPPER]}, u {su and su[UPPER]}, "
                            f"v {sv and sv[UPPER]}, t_c - t_a {tc and tc[UPPER]}"], corrects=printed[5], ref="T17.8"))
    return conclude(printed, corrected, kind=FALSE_STATEMENT,
                    misprint="l. 436: Δ < 0 'until r = 1' misses the zero of Δ at (7-2√10)/3",
                    note="The printed 'until r = 1' misses one point: at r = (7-2√10)/3 the upper "
                    "branch has Δ = 0 and a positive double fixed point; it does not give a self-similar datum.")


@certificate("T18", needs=["spectrum"],
             printed=dict(a=A_PRINTED, b=B_PRINTED, c=C_PRINTED, d=D_PRINTED, U=U_PRINTED, r1=R1_PRINTED, P0_text=P0_PRINTED),
             expect=PASS,
             mutants=[replaced("c", "16*", "-16*", "the sign of c")])
def middle_branch_fixed_points(spectrum, a, b, c, d, U, r1, P0_text):
    """The middle branch exists on ]0, r*]; x₊ and x₋ are negative or not real there
    except at r1, where a - d = b = c = 0 exactly on this branch: f is the identity."""
    rr1, rs = r1_of(r1), unique_root(P0_text)
    fp, xp, xm = fixed_point_tables(spectrum, a, b, c, d, 0, 1)
    amd = spectrum.table("a-d", parse(a) - parse(d), 0, 1)
    bc = spectrum.table("bc", parse(b) * parse(c), 0, 1)
    cc = spectrum.table("c", parse(c), 0, 1)
    away, ev = no_positive_fixed_point(spectrum, fp, xp, xm, MIDDLE, 0, rs, skip=(rr1,))
    at_rs = fixed_point_signs_at(spectrum, fp, rs, MIDDLE)       # r*, where the middle branch meets the lower
    away, ev = away and at_rs <= {-1, None}, ev + [f"at r*: {sign_word(at_rs)}"]
    degenerate = all(spectrum.vanishes_at(g, rr1, MIDDLE) for g in (fp.a, fp.b, fp.c, fp.d))
    reasoning = [
        Check("the middle branch exists exactly on ]0, r*[ (and at r*)", all((len(cl.branches) >= 2) == (cl.hi <= rs) for cl in xp.cells)),
        Check("for r < 5-2√6: a-d < 0, bc < 0, c > 0 on the middle branch",
              amd.holds(MIDDLE, -1, 0, rr1) and bc.holds(MIDDLE, -1, 0, rr1) and cc.holds(MIDDLE, 1, 0, rr1), ref="T18.3"),
        Check("for 5-2√6 < r < r*: a-d > 0, bc < 0, c < 0 on the middle branch",
              amd.holds(MIDDLE, 1, rr1, rs) and bc.holds(MIDDLE, -1, rr1, rs) and cc.holds(MIDDLE, -1, rr1, rs),
              ref="T18.4"),
    ]
    return conclude([Check("x₊ and x₋ are never positive on the middle branch wherever f is defined", away, ev,
                           ref="T18.1"),
                     Check("at r = 5-2√6 the printed f is undefined on the middle branch: a = b = c = d = 0 exactly",
                           degenerate, ref="T18.2")] + reasoning,
                    note="At r = 5-2√6 on the middle branch a, b, c, d (and the numerators and denominators of u, v) "
                         "all vanish: the printed formulas define no datum there, so the claim holds vacuously at that point.")


@certificate("T19", needs=["spectrum"],
             printed=dict(a=A_PRINTED, b=B_PRINTED, c=C_PRINTED, d=D_PRINTED, r1=R1_PRINTED),
             expect=PASS,
             mutants=[replaced("c", "16*", "-16*", "the sign of c")])
def lower_branch_fixed_points(spectrum, a, b, c, d, r1):
    rr1 = r1_of(r1)
    fp, xp, xm = fixed_point_tables(spectrum, a, b, c, d, 0, 1)
    amd, bb, cc = (spectrum.table(n, g, 0, 1) for n, g in (("a-d", parse(a) - parse(d)), ("b", parse(b)), ("c", parse(c))))
    return conclude([
        Check("a-d, b, c > 0 on the lower branch for r < 5-2√6", all(T.holds(LOWER, 1, 0, rr1) for T in (amd, bb, cc)),
              ref="T19.1"),
        Check("x₊ > 0 > x₋ on the lower branch for r < 5-2√6", xp.holds(LOWER, 1, 0, rr1) and xm.holds(LOWER, -1, 0, rr1),
              [f"x₊: {sign_word(xp.signs(LOWER, 0, rr1))}; x₋: {sign_word(xm.signs(LOWER, 0, rr1))}"], ref="T19.2"),
    ])



# ---------------------------------------------------------------- Step 3.1: The velocity inequalities (l. 442-459)
@certificate("T20", needs=["cp", "spectrum"], printed=dict(U=U_PRINTED, quintic=P3_PRINTED, digits="0.11376", r1=R1_PRINTED,
                                                    position="larger than 5-2√6"),
             expect=PASS,
             mutants=[overridden({"digits": "0.11377"}, "a digit of the quintic's root"),
                      reworded("position", "larger", "smaller")])
def sign_of_u(cp, spectrum, U, quintic, digits, r1, position):
    """u = 0 iff its numerator 16λ - (r^4 - 8r^3 - 2r^2 - 8r + 1) vanishes (r > 0):
    eliminate λ both ways; then the sign table of u."""
    rr1 = r1_of(r1)
    num, _den = sp.fraction(sp.factor(parse(U)))
    E = eliminate(num, cp)
    wanted = {str(f) for f, _ in E.factors if f.degree() > 1 or f(0) != 0}
    target = {str(f) for f, _ in to_fmpz_poly(parse(f"(r^2-10*r+1)*({quintic})")).factor()[1]}
    others = [f for f, _ in E.factors if str(f) not in target]
    roots, nf = roots_in_unit_interval(quintic)
    T = spectrum.table("u", parse(U), 0, 1)
    quad_roots = Algebraic.roots(to_fmpz_poly(parse("r^2-10*r+1")), 0, 1)
    checks = [Check("the eliminant's factors vanishing in ]0,1[ are r^2-10r+1 and the quintic",
                    wanted >= target and all(not Algebraic.roots(f, 0, 1) for f in others),
                    E.evidence(), ref="T20.1"),
              Check("both routes agree", E.agree),
              Check("the first factor, r^2-10r+1, only has one root in ]0,1[, 5-2√6",
                    len(quad_roots) == 1 and quad_roots[0] == rr1, ref="T20.2"),
              named("T20.3", count_check("the quintic", roots, nf, 1))]
    if roots:
        checks += [named("T20.4", digits_check("its root", roots[0], digits)),
                   Check(f"it is {position}", statements.relation(position, {"ρ": roots[0]}, subject="ρ").compare(),
                         [f"its root is {roots[0].describe()}"], ref="T20.5")]
    checks.append(Check("u > 0 on the upper and lower branches for r < 5-2√6",
                        T.holds(UPPER, 1, 0, rr1) and T.holds(LOWER, 1, 0, rr1), ["sign table of u:\n\n" + T.markdown()],
                        ref="T20.6"))
    return conclude(checks)


@certificate("T21", needs=["spectrum"],
             printed=dict(velocities=VELOCITIES_PRINTED, U=U_PRINTED, V=V_PRINTED,
                          inequality="q < 0 for 0 < r < 5-2√6"),
             expect=PASS,
             mutants=[replaced("inequality", "q <", "q >", "the sign of the velocities"),
                      reworded("inequality", "5-2√6", "1"),
                      reworded("inequality", "q < 0", "q ≥ 0")])
def velocity_inequalities(spectrum, velocities, U, V, inequality):
    """Each expression against the velocities A q(0), BA q(0), ... for q(0) = (-1, u, v)
    with u, v free (an identity), then its sign table with the printed u, v, against
    the printed inequality (q standing for each velocity) read with its range."""
    st = statements.statement(inequality, {"q": Q_VELOCITY})
    lo, hi = st.range.lo, st.range.hi
    qs = velocities_of(WORD)
    checks = []
    for n, (name, (k, i, text)) in enumerate(velocities.items()):
        same = to_field(qs[k][i]) == to_field(parse(text))
        T = spectrum.table(name, parse(text).subs(printed_uv(U, V)), 0, 1)
        up, low = T.signs(UPPER, lo, hi), T.signs(LOWER, lo, hi)
        ok = st.relation.holds_on(Q_VELOCITY, up) and st.relation.holds_on(Q_VELOCITY, low)
        checks.append(Check(f"{name} = {text} is the dynamics, and {inequality} with q = {name} on the upper and "
                            "lower branches", same and ok,
                            [f"{name}: identity {'holds' if same else 'FAILS'}; for {st.range}, upper: "
                             f"{sign_word(up)}, lower: {sign_word(low)}"], ref=f"T21.{n + 1}"))
    return conclude(checks)


@for_a_run
def velocities_of(word):
    """q(t_0), ..., q(t_n) for q(0) = (-1, u, v) with u, v free."""
    return velocities(word, sp.Matrix([-1, u, v]))



# ---------------------------------------------------------------- Step 3.2: The distance inequalities (l. 460-487)
@certificate("T22", needs=["candidate"],
             printed=dict(p3t4=P3_T4_PRINTED, p1t5=P1_T5_PRINTED, a=A_PRINTED, b=B_PRINTED, c=C_PRINTED,
                          d=D_PRINTED, U=U_PRINTED, V=V_PRINTED, r1=R1_PRINTED),
             expect=PASS,
             mutants=[replaced("p3t4", "x + ", "-x + ", "a sign in p3(t4)")])
def distance_inequalities(candidate, p3t4, p1t5, a, b, c, d, U, V, r1):
    """Both distances against the dynamics (modulo cp), their sign tables with x = x₊,
    and the printed argument for p3(t1..t3): A leaves q3 unchanged and B adds
    (1+r)/2·q2 with q2 < 0 before each b, so p3 is concave on [0, t4]."""
    steps, cp, spectrum = candidate.steps, candidate.cp, candidate.spectrum
    rr1 = r1_of(r1)
    fp = fixed_point(a, b, c, d)
    checks = []
    for ref, name, text, k, i in (("T22.1", "p3(t4)", p3t4, 3, 2), ("T22.2", "p1(t5)", p1t5, 4, 0)):
        same = reduce_mod(steps[k].position(i) - to_field(parse(text)), cp) == 0
        T = spectrum.table(name, parse(text), 0, 1, fp)
        ok = T.holds(UPPER, 1, 0, rr1) and T.holds(LOWER, 1, 0, rr1)
        checks.append(Check(f"{name} as printed is the dynamics (modulo cp) and is > 0 on the upper and lower branches "
                            "for r < 5-2√6 with x = x₊", same and ok,
                            [f"{name}: identity {'holds' if same else 'FAILS'}", f"sign table of {name}:\n\n" + T.markdown()],
                            ref=ref))
    qs = velocities_of(WORD)
    h = (1 + r) / 2
    concave = all(sp.expand(qs[k + 1][2] - qs[k][2] - (h * qs[k][1] if WORD[k] == "b" else 0)) == 0 for k in range(4))
    q2_before_b = [spectrum.table(f"q2(t{k})", qs[k][1].subs(printed_uv(U, V)), 0, 1) for k in (1, 3)]
    neg = all(T.holds(UPPER, -1, 0, rr1) and T.holds(LOWER, -1, 0, rr1) for T in q2_before_b)
    checks.append(Check("q3 is non-increasing over the first four collisions (A keeps it, B adds (1+r)/2·q2 < 0), so "
                        "p3 is concave on [0, t4] and p3(t1), p3(t2), p3(t3) > 0 follow from x > 0 and p3(t4) > 0",
                        concave and neg, ref="T22.3"))
    # the conclusion itself, on the sign tables of p3(t1), p3(t2), p3(t3) with x = x₊
    p3s = [spectrum.table(f"p3(t{k + 1})", steps[k].position(2).as_expr(), 0, 1, fp) for k in range(3)]
    checks.append(Check("hence p3(t1), p3(t2), p3(t3) > 0 on the upper and lower branches for r < 5-2√6 with x = x₊",
                        all(T.holds(UPPER, 1, 0, rr1) and T.holds(LOWER, 1, 0, rr1) for T in p3s),
                        [f"p3(t{k + 1}): upper {sign_word(T.signs(UPPER, 0, rr1))}, lower {sign_word(T.signs(LOWER, 0, rr1))}"
                         for k, T in enumerate(p3s)], ref="T22.4"))
    return conclude(checks)



# ---------------------------------------------------------------- Step 4: Studying if the pattern is stable (l. 488-506)
@certificate("T23", needs=["cp"],
             printed=dict(a=A_PRINTED, d=D_PRINTED, P2_text=P2_PRINTED, P3_text=P3_PRINTED, d2="0.12879",
                          d3="0.11376", degree=30, position="above 5-2√6"),
             expect=PASS,
             mutants=[replaced("P2_text", "25*r^8", "24*r^8", "a coefficient of P2"),
                      reworded("position", "above", "below")])
def eliminant_of_a_plus_d(cp, a, d, P2_text, P3_text, d2, d3, degree, position):
    product = f"r^6*(r-1)^6*(r+1)^3*(r^2-10*r+1)*({P2_text})*({P3_text})"
    checks = eliminant_check("a+d", parse(a) + parse(d), cp, product)
    checks[0].ref = "T23.1"
    checks.append(Check(f"the polynomial has degree {degree}", to_fmpz_poly(parse(product)).degree() == degree,
                        ref="T23.2"))
    for n, (name, text, digits) in enumerate((("P2", P2_text, d2), ("P3", P3_text, d3))):
        roots, nf = roots_in_unit_interval(text)
        checks.append(named(f"T23.{3 * n + 3}", count_check(name, roots, nf, 1)))
        if roots:
            checks += [named(f"T23.{3 * n + 4}", digits_check(f"the root of {name}", roots[0], digits)),
                       Check(f"the root of {name} lies {position}",
                             statements.relation(position, {"ρ": roots[0]}, subject="ρ").compare(), ref=f"T23.{3 * n + 5}")]
    return conclude(checks)


T24_CORRECTION = ("(c x₊ + d)/(c x₋ + d)", "(c x₋ + d)/(c x₊ + d)")   # l. 493: the fraction inverted


def mobius_symbols():
    """a, c, d, s = √Δ > 0 and the fixed points x± = (a - d ± s)/(2c) of any Möbius map
    (ax + b)/(cx + d), with b eliminated by Δ = (a-d)² + 4bc = s²."""
    A, C, D = sp.symbols("a c d")
    s = sp.Symbol("s", positive=True)
    B = (s ** 2 - (A - D) ** 2) / (4 * C)
    return A, B, C, D, s, (A - D + s) / (2 * C), (A - D - s) / (2 * C)


def read_q(text: str) -> sp.Expr:
    """The printed q, ``(c x₊ + d)/(c x₋ + d)``, as a function of a, c, d, s."""
    A, B, C, D, s, xp, xm = mobius_symbols()
    t = text.replace("x₊", " xp ").replace("x₋", " xm ")
    if not re.fullmatch(r"[\sacdxpm+\-*/()0-9]*", t):
        raise statements.StatementError(f"cannot read q = {text!r}: only a, c, d, x₊, x₋ and + - * / ( )")
    t = re.sub(r"(?<=[\w)])\s+(?=[\w(])", "*", t.strip())
    return sp.sympify(t, locals={"a": A, "c": C, "d": D, "xp": xp, "xm": xm})


@for_a_run
def modulus_ratio(e: sp.Expr) -> tuple:
    """(P, Q, κ) with e = P/Q canceled and κ = (P² - Q²)/((a + d)·s) canceled (a Möbius map's
    a, d and s = √Δ, :func:`mobius_symbols`)."""
    A, B, C, D, s, xp, xm = mobius_symbols()
    num, den = sp.fraction(sp.cancel(sp.together(e)))
    return num, den, sp.cancel((num ** 2 - den ** 2) / ((A + D) * s))


def modulus_sign_factor(e: sp.Expr) -> int | None:
    """k with sign(|e| - 1) = k·sign(a + d) for every Möbius map with real fixed points
    (s > 0), when e = P/Q and P² - Q² = (a+d)·s·(a nonzero constant k·κ); None otherwise.
    As |e| > 1 iff P² > Q², this reads the sign of |e| - 1 off the sign of a + d."""
    num, den, ratio = modulus_ratio(e)
    return int(sp.sign(ratio)) if ratio.is_number and ratio != 0 else None


def f_prime_at_fixed_point() -> sp.Expr:
    """f'(x₊) = (ad - bc)/(cx₊ + d)² for f(x) = (ax + b)/(cx + d)."""
    A, B, C, D, s, xp, xm = mobius_symbols()
    return (A * D - B * C) / (C * xp + D) ** 2


T24_Q_ONE = ("d^2 + 4*b*c", "(a - d)^2 + 4*b*c")     # l. 495: q = 1 where (a-d)^2 + 4bc = 0 (Step 2's Δ), not d^2 + 4bc


def mobius_sum(text: str, a, b, c, d) -> sp.Expr:
    """A printed expression in a, b, c, d (``d^2 + 4*b*c``) with the printed a, b, c, d put in."""
    e = parse(text)
    put = {sym: parse(v) for sym in e.free_symbols for n, v in zip("abcd", (a, b, c, d)) if sym.name == n}
    if set(map(str, e.free_symbols)) - set("abcd"):
        raise statements.StatementError(f"cannot read {text!r}: only a, b, c, d")
    return e.subs(put)


@certificate("T24", needs=["spectrum"],
             printed=dict(a=A_PRINTED, b=B_PRINTED, c=C_PRINTED, d=D_PRINTED, r1=R1_PRINTED,
                          q="(c x₊ + d)/(c x₋ + d)", upper="|q|>1", lower="|q|<1", stable_when="|q|<1",
                          q_is_one="d^2 + 4*b*c"),
             expect=ERRATUM,
             mutants=[replaced("a", "1024*r^6", "-1024*r^6", "a coefficient of a"),
                      reworded("upper", "|q|>1", "|q|<1", "(|q|≥1 holds with q = f'(x₊): not an alteration that must fail)"),
                      reworded("lower", "|q|<1", "|q|>1"),
                      reworded("stable_when", "|q|<1", "|q|≤1"),
                      reworded("q", "(c x₊ + d)/(c x₋ + d)", "(c x₊ + d)/(c x₋ - d)"),
                      replaced("q_is_one", "4*b*c", "4*b*c + 1", "another quantity for q = 1"),
                      unread("upper", "|q| > 2", "not a multiple of |q| - 1: not evaluated")])
def stability_of_the_fixed_point(spectrum, a, b, c, d, r1, q, upper, lower, stable_when, q_is_one):
    """For every Möbius map with real fixed points, |f'(x₊)| - 1 has the sign of -(a+d)
    (:func:`modulus_sign_factor`), and the printed q = (cx₊+d)/(cx₋+d) is 1/f'(x₊): its
    |q| - 1 has the sign of a+d.  The signs of Δ and a+d per branch are certified.  The
    sentences of l. 495-505 (x₊ stable iff |q| < 1; |q| > 1 on the upper branch, |q| < 1 on
    the lower) are read and evaluated with q as displayed at l. 493, then with the one
    stated correction: q = (cx₋+d)/(cx₊+d) = f'(x₊), the displayed fraction inverted.
    l. 495 also says that q = 1 corresponds to d^2 + 4bc = 0: q = 1 iff √Δ = 0, Δ = (a-d)^2 + 4bc
    (false as printed at r0 = (7-2√10)/3 on the upper branch, where Δ = 0 and d^2 + 4bc ≠ 0)."""
    rr1 = r1_of(r1)
    r0 = Algebraic.surd(sp.Rational(7, 3), sp.Rational(-2, 3), 10)
    fp = fixed_point(a, b, c, d)
    apd = spectrum.table("a+d", fp.a + fp.d, 0, rr1)
    real = spectrum.table("Δ", fp.delta, 0, 1)          # q real and √Δ > 0 where Δ > 0 (shared with T17)
    lam_gap = spectrum.sign_table(Condition.of("λ", lam), 0, rr1)
    k_f = modulus_sign_factor(f_prime_at_fixed_point())   # -1: |f'(x₊)| > 1 iff a+d < 0
    names = {"q": Q_MOBIUS}
    excess = sp.Abs(Q_MOBIUS) - 1

    def sentences(q_text) -> tuple[bool, list[str]]:
        """The three sentences of l. 495-505 with q = ``q_text``: each verdict, and all."""
        k = modulus_sign_factor(read_q(q_text))
        if k is None:
            return False, [f"|q| - 1 for q = {q_text} has no sign fixed by that of a+d: not evaluated"]

        def on_branch(text, branch):
            return real.holds(branch, 1, 0, rr1) and statements.relation(text, names).holds_on(
                excess, {k * sg for sg in apd.signs(branch)})
        rel = statements.relation(stable_when, names)
        verdicts = {f"x₊ stable (|f'(x₊)| < 1) iff {stable_when}":
                    all(rel.holds({excess: k * sg}) == (k_f * sg == -1) for sg in (-1, 0, 1)),
                    f"upper branch, r < 5-2√6: {upper}": on_branch(upper, UPPER),
                    f"lower branch, r < 5-2√6: {lower}": on_branch(lower, LOWER)}
        return all(verdicts.values()), [f"with q = {q_text}, sign(|q| - 1) = {'+' if k > 0 else '−'}sign(a+d): "
                                        + "; ".join(f"{t}: {MARK[v]}" for t, v in verdicts.items())]

    def q_one(text) -> Check:
        """l. 495: the case q = 1 corresponds to E = 0 (E = ``text``): for every Möbius map q - 1 =
        2√Δ/(a+d-√Δ), so the claim holds when E is Δ = (a-d)^2 + 4bc; and at r0 on the upper branch,
        where Δ = 0 (q = 1), E vanishes too."""
        A, B, C, D, s_, _xp, _xm = mobius_symbols()
        generic = sp.cancel(parse(text).subs({sym: {"a": A, "b": B, "c": C, "d": D}[sym.name]
                                              for sym in parse(text).free_symbols if sym.name in "abcd"})
                            - ((A - D) ** 2 + 4 * B * C)) == 0
        E = mobius_sum(text, a, b, c, d)
        at_r0 = spectrum.vanishes_at(fp.delta, r0, UPPER) == spectrum.vanishes_at(E, r0, UPPER)
        return Check(f"l. 495: the case q = 1 corresponds to {text} = 0 (q - 1 = 2√Δ/(a+d-√Δ) for every Möbius map: "
                     "q = 1 iff Δ = (a-d)^2 + 4bc = 0; on the upper branch at r0 = (7-2√10)/3, Δ = 0)", generic and at_r0,
                     [f"{text} is (a-d)^2 + 4bc: {MARK[generic]}; at r0 on the upper branch, Δ = 0 and {text} = 0 "
                      f"alike: {MARK[at_r0]}"])
    sentence_text = f"x₊ stable iff {stable_when} (l. 495); {upper} on the upper branch and {lower} on the lower, r < 5-2√6 (l. 505)"
    ok, ev = sentences(q)
    a_d = ["a+d on the branches:\n\n" + apd.markdown(),
           f"Δ = (a-d)² + 4bc > 0 on the upper branch: {MARK[real.holds(UPPER, 1, 0, rr1)]}, on the lower branch: "
           f"{MARK[real.holds(LOWER, 1, 0, rr1)]} (r < 5-2√6), so q is real and √Δ > 0",
           f"for every Möbius map, f'(x₊) = (ad-bc)/(cx₊+d)² = (cx₋+d)/(cx₊+d) and |f'(x₊)| - 1 has the sign of "
           f"{'a+d' if k_f == 1 else '-(a+d)'}"]
    upper_repels = k_f == -1 and apd.holds(UPPER, -1)
    lower_dominated = k_f == -1 and apd.holds(LOWER, 1) and all(lam_gap.holds(k, 1) for k in (UPPER, MIDDLE, LOWER))
    A, B, C, D, s_, xp, xm = mobius_symbols()
    two_forms = sp.cancel(C * xp + D - (A + D + s_) / 2) == 0 and sp.cancel(C * xm + D - (A + D - s_) / 2) == 0
    minus_one = sp.cancel((A + D + s_) / (A + D - s_) + 1 - 2 * (A + D) / (A + D - s_)) == 0
    printed = [
        Check(f"l. 493: q = {q}; with it, {sentence_text}", ok, ev + a_d, ref="T24.1"),
        Check("so on the upper branch a+d < 0 and |f'(x₊)| > 1: x₊ is repelling (unstable)", upper_repels, ref="T24.3"),
        Check("and on the lower branch a+d > 0 and |f'(x₊)| < 1, but λ_lower < λ_upper, both > 0: λ is not dominant "
              "(unstable in the velocities)", lower_dominated, ref="T24.4"),
        Check("l. 493: the two forms of q agree, cx± + d = (a+d ± √Δ)/2 for x± = (a-d ± √Δ)/(2c)", two_forms, ref="T24.5"),
        named("T24.6", q_one(q_is_one)),
        Check("which does not happen below 5-2√6: Δ > 0, so q ≠ 1, on the upper and lower branches",
              real.holds(UPPER, 1, 0, rr1) and real.holds(LOWER, 1, 0, rr1), ref="T24.8"),
        Check("l. 495: the case q = -1 corresponds to a+d = 0 (q + 1 = 2(a+d)/(a+d-√Δ))", minus_one, ref="T24.9"),
    ]
    if all(c.holds for c in printed):
        return conclude(printed)
    corrected, slips = [], []
    if not printed[0].holds:
        if T24_CORRECTION[0] not in q:
            corrected.append(Check(f"the stated correction {' → '.join(T24_CORRECTION)} applies to the printed q = {q}",
                                   False, corrects=printed[0]))
        else:
            q_fixed = q.replace(*T24_CORRECTION)
            ok_fixed, ev_fixed = sentences(q_fixed)
            is_fprime = sp.cancel(read_q(q_fixed) - f_prime_at_fixed_point()) == 0
            corrected.append(Check(f"l. 493: q = {q_fixed}; with it, {sentence_text}", ok_fixed and is_fprime,
                                   ev_fixed + [f"q = {q_fixed} is f'(x₊) identically: {MARK[is_fprime]}"],
                                   corrects=printed[0], ref="T24.2"))
        slips.append("l. 493: q displayed as 1/f'(x₊), the fraction inverted")
    if not printed[4].holds:
        fixed = q_is_one.replace(*T24_Q_ONE) if T24_Q_ONE[0] in q_is_one else None
        fix = named("T24.7", q_one(fixed)) if fixed else \
            Check(f"the stated correction {' → '.join(T24_Q_ONE)} applies to the printed {q_is_one}", False)
        fix.corrects = printed[4]
        corrected.append(fix)
        slips.append("l. 495: d^2+4bc printed for (a-d)^2+4bc")
    corrected += [c for c in printed if c.holds]
    return conclude(printed, corrected, kind=MISPRINT, misprint=tuple(slips),
                    note="Two misprints: the q displayed at l. 493, (cx₊+d)/(cx₋+d), is 1/f'(x₊). With q = f'(x₊) = "
                    "(cx₋+d)/(cx₊+d), every sentence of l. 495-505 holds as printed, and the theorem's conclusion "
                    "(instability on both branches) stands. And q = 1 (l. 495) where (a-d)^2 + 4bc = 0 (Step 2's Δ), "
                    "not d^2 + 4bc = 0; neither vanishes below 5-2√6 on the upper and lower branches.")


# ---------------------------------------------------------------- Conclusion (l. 507-512): the theorem as a whole
@certificate("T25.1", needs=["candidate"],
             printed=dict(a=A_PRINTED, b=B_PRINTED, c=C_PRINTED, d=D_PRINTED, U=U_PRINTED, V=V_PRINTED,
                          velocities=VELOCITIES_PRINTED, p3t4=P3_T4_PRINTED, p1t5=P1_T5_PRINTED, r1=R1_PRINTED,
                          r1_digits="0.10102"),
             expect=PASS,
             mutants=[replaced("U", "16*λ", "-16*λ", "the sign of a coefficient of u"),
                      replaced("r1_digits", "0.10102", "0.10103", "a digit of 5-2√6")])
def theorem_3_1(candidate, a, b, c, d, U, V, velocities, p3t4, p1t5, r1, r1_digits):
    """Two routes.  (1) The exact region analysis of the computed candidate
    (certify.patterns.feasibility): every inequality needed to realise ababcb — all the gaps,
    p_1(t_6) > 0 included, which the paper does not list — imposed on every branch
    and both fixed points over ]0,1[, critical values included.  (2) The printed
    formulas: x₊ > 0, u > 0, the five velocities < 0 and the two distances > 0 on the
    upper and lower branches below r1, from the sign tables shared with T17-T22.
    Instability as in T24 (corrected reading).  The formal statements T25.1.1-8
    (statements/3_pattern.txt): the checks naming them."""
    spectrum, rr1 = candidate.spectrum, r1_of(r1)
    an = Analysis(candidate)
    reqs, _ = prefix_requirements(WORD, len(WORD), candidate.q0, candidate.steps, candidate.q0_other)
    for q in reqs:
        an.impose(q)
    undecided = [(R, u_) for R in an.regions for u_ in R.undecided]
    where = {k: [p for R in an.regions if R.branch == k for p in R.pieces] for k in range(3)}
    exactly_below = {k: len(where[k]) == 1 and not where[k][0].is_point and where[k][0].lo == Algebraic.rational(0)
                     and where[k][0].hi == rr1 for k in (UPPER, LOWER)}
    pieces = [p for k in range(3) for p in where[k]]
    below = any(not p.is_point and p.lo == Algebraic.rational(0) and p.hi == rr1 for p in pieces)
    above = any((p.lo >= rr1) if p.is_point else (p.hi > rr1) for p in pieces)
    regions = [f"{BRANCH_NAMES[R.branch]} branch, {R.fixed_point} of the computed f: realised on {R.describe()}"
               + (f"; excluded exactly at {', '.join(f'{fmt(rc)} ({why})' for rc, why in R.dropped)}" if R.dropped else "")
               for R in an.regions]
    fp, xp, xm = fixed_point_tables(spectrum, a, b, c, d, 0, 1)
    uv = printed_uv(U, V)
    tables = [spectrum.table("u", parse(U), 0, 1)]
    tables += [spectrum.table(name, parse(text).subs(uv), 0, 1) for name, (_k, _i, text) in velocities.items()]
    dist = [spectrum.table(name, parse(text), 0, 1, fp) for name, text in (("p3(t4)", p3t4), ("p1(t5)", p1t5))]
    printed_ok = all(xp.holds(k, 1, 0, rr1) and tables[0].holds(k, 1, 0, rr1)
                     and all(T.holds(k, -1, 0, rr1) for T in tables[1:]) and all(T.holds(k, 1, 0, rr1) for T in dist)
                     for k in (UPPER, LOWER))
    minus_negative = all(xm.holds(k, -1, 0, rr1) for k in (UPPER, LOWER))   # the other fixed point
    apd = spectrum.table("a+d", fp.a + fp.d, 0, rr1)
    lam_t = spectrum.table("λ", lam, 0, rr1)
    unstable = apd.holds(UPPER, -1) and lam_t.holds(LOWER, 1) and lam_t.holds(UPPER, 1)   # |f'(x₊)| > 1 iff a+d < 0 (T24)
    cp = candidate.cp
    same_q = [reduce_mod(to_field(parse(e)) - candidate.q0[i + 1], cp) == 0 for i, e in enumerate((U, V))]
    P, comp = [to_field(parse(e)) for e in (a, b, c, d)], [to_field(e) for e in candidate.abcd]
    same_f = all(reduce_mod(P[i] * comp[j] - P[j] * comp[i], cp) == 0 for i in range(4) for j in range(i + 1, 4))
    return conclude([
        Check("every cell and critical value of ]0,1[ decided, on every branch, for both fixed points", not undecided,
              [f"undecided: {BRANCH_NAMES[R.branch]} {R.fixed_point} at {fmt(rc)} ({why})" for R, (rc, why) in undecided]),
        named("T25.1.1", Check(f"5-2√6 ≃ {r1_digits}", rr1.in_rounding_interval(r1_digits), [rr1.describe()])),
        witnessed(Check("the candidate realises ababcb, every inequality strict, for every r in ]0, 5-2√6[ on some "
                        "branch", below, regions), "T25.1.2", WORD),
        witnessed(Check("and for no r in [5-2√6, 1[, on any branch, for either fixed point", not above, regions),
                  "T25.1.3", WORD),
        named("T25.1.4", Check("u, v as printed are the components of q(0) (rows 1 and 2 of M q = λ q), modulo cp(M)",
                               all(same_q), [f"u as printed is the computed u: {'yes' if same_q[0] else 'no'}; v: {'yes' if same_q[1] else 'no'}"])),
        named("T25.1.5", Check("the printed (a, b, c, d) is proportional to the computed position map modulo cp(M)",
                               same_f, [f"computed a = `{show(candidate.abcd[0])}`"])),
        witnessed(Check("the candidate realises ababcb, with every inequality strict, exactly for 0 < r < 5-2√6 on the "
                        "upper branch and on the lower branch, and nowhere on the middle branch",
                        exactly_below[UPPER] and exactly_below[LOWER] and not where[MIDDLE],
                        ["the inequalities: " + ", ".join(f"{q.name} {'>' if q.sign > 0 else '<'} 0" for q in reqs)]
                        + regions), "T25.1.6", WORD),
        named("T25.1.7", Check("on the upper and lower branches the printed x₋ is negative for r < 5-2√6: the datum is "
                               "x₊", minus_negative)),
        Check("with the printed formulas (x = x₊, u, v): x₊ > 0, u > 0, the five velocities < 0 and p3(t4), p1(t5) > 0 "
              "on the upper and lower branches for r < 5-2√6", printed_ok),
        witnessed(Check("unstable: upper branch |f'(x₊)| > 1 (a+d < 0), lower branch λ not dominant", unstable),
                  "T25.1.8", WORD),
    ], note="p_1(t_6) > 0 (μ > 0) is needed too and is not in the paper's list (l. 470-486); it holds on the same "
            "region. The computed (a, b, c, d) is the printed one times a negative constant (T10), so the paper's x₊ "
            "is the computed x₋.")


# ---------------------------------------------------------------- Conclusion, on the dynamics of the four particles
# At a rational restitution coefficient of our choice (r = 1/20 < 5-2√6), the
# self-similar datum of Theorem 3.1 is built from the printed formulas:
#
# * λ a real root of cp(M_w) at r (M_w the matrix of the printed word), isolated
#   exactly (Sturm) and enclosed in a ball;
# * q(0) = (-1, u, v) with u, v as printed (l. 279-281);
# * p(0) = (1, 0, x), x = x₊ = (a - d + √((a-d)² + 4bc))/(2c), a, b, c, d as printed
#   (l. 291-300).
#
# The particles are then moved by ``certify.dynamics.simulate`` in ball arithmetic: every
# collision choice is proven (the smallest collision time strictly below the others),
# the precision is raised when a choice cannot be proven.  We check that the orbit
# repeats the word for the requested number of periods with q(t_6k) = λ^k q(0) and
# p(t_6k) = μ^k p(0) (μ = p_1(t_6)), and that a perturbation of 10^-30 (an exact
# rational added to x or to q) leaves the pattern after finitely many periods.
# Ball enclosures cannot prove the identities q(t_6) = λ q(0) exactly (T9, T10 do so
# algebraically); here they are checked as "the enclosures overlap and are tight"
# (relative radius below 2^-TIGHT_BITS, decided exactly on the rational midpoints and
# radii, not on floats), which a wrong formula fails by many orders of magnitude.  The
# kernel decides the statements T25.2.1-T25.2.8 (statements/3_simulation.txt) by the exact
# dynamics in Q(λ, √Δ) (certify_kernel/particles.py): every collision and identity exactly.
PRINTED_T25_2 = dict(U=U_PRINTED, V=V_PRINTED, a=A_PRINTED, b=B_PRINTED, c=C_PRINTED, d=D_PRINTED, word="ababcb",
                     r="1/20", periods=20, perturbation="1/10^30")
MAX_PERIODS = 200                      # how long a perturbed orbit is followed at most
TIGHT_BITS = 40                        # "tight": relative radius < 2^-40 (decided exactly)


def ball_function(text: str):
    """A printed rational function of r, λ as a function of balls (R, L), exact
    rational coefficients (no float ever enters)."""
    cond = Condition.of(text, parse(text))
    return lambda R, L: ball_value(cond, R, L)


@dataclass
class Datum:
    """The self-similar datum on one branch, as a function of the precision."""

    branch: str
    lam: Algebraic
    r0: flint.fmpq
    formulas: dict

    def values(self, R, L) -> dict:
        """u, v, a, b, c, d and x₊ at balls R, L."""
        f = {k: g(R, L) for k, g in self.formulas.items()}
        f["x"] = fixed_point_ball(f["a"], f["b"], f["c"], f["d"])
        return f

    def balls(self, prec: int, dx=ZERO, dq=(ZERO, ZERO, ZERO)):
        """(p(0), q(0), r) as balls at ``prec`` bits, x and q shifted by exact rationals."""
        with precision(prec + GUARD):
            R = flint.arb(self.r0)
            f = self.values(R, self.lam.arb(prec + GUARD))
            p0 = (flint.arb(1), flint.arb(0), f["x"] + flint.arb(dx))
            q0 = (flint.arb(-1) + flint.arb(dq[0]), f["u"] + flint.arb(dq[1]), f["v"] + flint.arb(dq[2]))
            return p0, q0, R

    def mobius(self, prec: int):
        """(f'(x₊), q): the multiplier f'(x₊) = (ad - bc)/(cx₊ + d)² of the fixed point
        and the paper's q = (a + d + √Δ)/(a + d - √Δ) (l. 496-498), computed independently."""
        with precision(prec):
            f = self.values(flint.arb(self.r0), self.lam.arb(prec))
            a, b, c, d, x = f["a"], f["b"], f["c"], f["d"], f["x"]
            sq = ((a - d) ** 2 + 4 * b * c).sqrt()
            return (a * d - b * c) / (c * x + d) ** 2, (a + d + sq) / (a + d - sq)


def rel_radius(z) -> float:
    """rad/|mid| of a ball, a float for printing only: every decision uses :func:`tight`."""
    m = abs(float(z.mid()))
    return float(z.rad()) / m if m else float(z.rad())


# ---------------------------------------------------------------- the checks
def self_similar_run(datum: Datum, word: str, periods: int, prec: int = 512, maxprec: int = 1 << 13):
    """Follow the exact datum for ``periods`` periods; raise the precision until every
    collision is proven and the final enclosures are tight (relative radius < 2^-40,
    decided exactly)."""
    n = len(word) * periods
    while prec <= maxprec:
        run = sim.follow(*datum.balls(prec), n, prec)
        if run.stop in ("free", "multiple"):            # decided: the orbit stops colliding
            return run, prec
        if run.stop == "n":
            last = run.states[-1]
            if all(tight(z, TIGHT_BITS) for z in last.q + (last.p[0], last.p[2])):
                return run, prec
        prec *= 2
    raise sim.Undecided(f"self-similar run not decided at {maxprec} bits")


def scaling_checks(run: sim.Run, datum: Datum, word: str, periods: int, prec: int) -> tuple[bool, bool, list[str]]:
    """q(t_nk) ∋ λ^k q(0) and p(t_nk) ∋ μ^k p(0) (overlapping balls, each of relative radius
    < 2^-TIGHT_BITS, decided exactly), k = 1..periods."""
    n = len(word)
    if len(run.states) <= n * periods:
        return False, False, [f"the orbit stops after {len(run.events)} collisions ({run.stop})"]
    with precision(prec + 30):
        L = datum.lam.arb(prec + 30)
        s0 = run.states[0]
        mu = run.states[n].p[0]
        q_ok, p_ok, worst_q, worst_p = True, True, 0.0, 0.0
        for k in range(1, periods + 1):
            s = run.states[n * k]
            for i in range(3):
                pred_q = L ** k * s0.q[i]
                q_ok &= s.q[i].overlaps(pred_q) and tight(s.q[i], TIGHT_BITS)
                worst_q = max(worst_q, rel_radius(s.q[i]))
                pred_p = mu ** k * s0.p[i]
                p_ok &= (s.p[i].overlaps(pred_p) and tight(s.p[i], TIGHT_BITS)) if i != 1 else s.p[1].is_zero()
                if i != 1:
                    worst_p = max(worst_p, rel_radius(s.p[i]))
    ev = [f"μ = p_1(t_{n}) ∈ {mu.str(12, radius=False)} (λ ∈ {L.str(12, radius=False)})",
          f"largest relative radius of q(t_{n}k): {worst_q:.1e}, of p(t_{n}k): {worst_p:.1e} (k ≤ {periods})"]
    return q_ok, p_ok, ev


def perturbed_run(datum: Datum, word: str, dx, dq, periods: int = MAX_PERIODS, prec: int = 512,
                  maxprec: int = 1 << 14):
    """Follow a perturbed datum until its word leaves the periodic pattern (proven
    collision by collision), at most ``periods`` periods; (run, precision, index of
    the first collision off the pattern or None)."""
    n = len(word) * periods

    def off_pattern(run):
        k = len(run.events) - 1
        return run.events[-1] != word[k % len(word)]
    run, used = sim.run_certified(lambda p: datum.balls(p, dx, dq), n, prec, maxprec, until=off_pattern)
    if run.stop == "until":
        return run, used, len(run.events) - 1
    if run.stop in ("free", "multiple"):          # the next collision of the pattern never comes
        return run, used, len(run.events)
    return run, used, None


def branch_data(word: str, r0: flint.fmpq, formulas: dict) -> dict[str, Datum]:
    """The upper (largest) and lower (smallest) real eigenvalue of M_w at r0."""
    lams = candidate(check_word(word)).spectrum.real_eigenvalues(r0)
    return {"upper": Datum("upper", lams[0], r0, formulas), "lower": Datum("lower", lams[-1], r0, formulas)}


@certificate("T25.2", printed=PRINTED_T25_2,
             expect=PASS,
             mutants=[replaced("U", "16*λ", "17*λ", "a coefficient of u"),
                      replaced("V", "64*λ", "65*λ", "a coefficient of v"),
                      replaced("a", "1024*r^6", "1025*r^6", "a coefficient of a"),
                      overridden({"word": "abacbc"}, "another word (its matrix, its eigenvalues)"),
                      overridden({"word": "abcbab"}, "another word (its matrix, its eigenvalues)")])
def ababcb_on_the_dynamics(U, V, a, b, c, d, word, r, periods, perturbation):
    """Certified ball simulation of the printed datum and of perturbed data."""
    r0, eps = to_fmpq(parse(r)), to_fmpq(parse(perturbation))
    formulas = {k: ball_function(text) for k, text in (("u", U), ("v", V), ("a", a), ("b", b), ("c", c), ("d", d))}
    data = branch_data(word, r0, formulas)
    checks, evidence = [], [f"r = {r0} (our choice in ]0, 5-2√6[); perturbation ε = {perturbation}; "
                            f"collision choices proven in ball arithmetic (python-flint arb)"]
    for name, datum in data.items():
        first_ref = {"upper": 1, "lower": 4}[name]          # T25.2.1-3, T25.2.4-6
        run, prec = self_similar_run(datum, word, periods)
        ok_word = run.word == word * periods
        q_ok, p_ok, ev = scaling_checks(run, datum, word, periods, prec)
        p0, q0, _ = datum.balls(64)
        evidence.append(f"{name} branch: λ ≈ {datum.lam.digits(12)}, a root of {show(from_flint(datum.lam.p, lam))}; u ∈ {q0[1].str(10, radius=False)}, "
                        f"v ∈ {q0[2].str(10, radius=False)}, x₊ ∈ {p0[2].str(10, radius=False)}; "
                        f"{len(run.events)} collisions proven at {prec} bits: "
                        f"{'(' + word + ')^' + str(periods) if ok_word else run.word}; " + "; ".join(ev)
                        + "; multiplier f'(x₊) = (ad-bc)/(cx₊+d)² ∈ {}, the paper's q (l. 496) ∈ {} "
                          "(f'(x₊) = 1/q)".format(*(z.str(8, radius=False) for z in datum.mobius(256))))
        checks += [
            Check(f"{name} branch: the printed datum repeats {word} for {periods} periods (every collision proven)",
                  ok_word, [f"word: {run.word[:6 * periods]}"] if not ok_word else [], ref=f"T25.2.{first_ref}"),
            Check(f"{name} branch: q(t_{len(word)}k) = λ^k q(0), k = 1..{periods} (the enclosures overlap and have "
                  f"relative radius < 2^-{TIGHT_BITS}, decided exactly)", q_ok, ref=f"T25.2.{first_ref + 1}"),
            Check(f"{name} branch: p(t_{len(word)}k) = μ^k p(0), k = 1..{periods} (the same)", p_ok,
                  ref=f"T25.2.{first_ref + 2}"),
        ]
    # instability: upper branch through the positions, lower branch through the velocities
    cases = [("upper", "x + ε", eps, (Q(0), Q(0), Q(0)), MAX_PERIODS),
             ("upper", "v + ε", Q(0), (Q(0), Q(0), eps), MAX_PERIODS),
             ("lower", "v + ε", Q(0), (Q(0), Q(0), eps), MAX_PERIODS),
             ("lower", "x + ε", eps, (Q(0), Q(0), Q(0)), 2 * periods)]
    for name, what, dx, dq, most in cases:
        run, prec, first = perturbed_run(data[name], word, dx, dq, most)
        n = len(word)
        if first is None:
            evidence.append(f"{name} branch, {what}: the pattern is kept for all {len(run.events) // n} periods "
                            f"followed ({prec} bits){_x_drift(run, n, dx, prec)}")
        elif first == len(run.events):
            why = ("no further collision: every q_i(t) > 0 is proven, the particles separate"
                   if run.stop == "free" else run.reason)
            evidence.append(f"{name} branch, {what}: leaves the pattern after collision {first} (period "
                            f"{first // n + 1}, {first // n} full periods; expected {word[first % n]}): {why} "
                            f"(proven at {prec} bits)")
        else:
            evidence.append(f"{name} branch, {what}: leaves the pattern at collision {first + 1} (period "
                            f"{first // n + 1}, {first // n} full periods): `{run.word[max(0, first - 11):first + 1]}` "
                            f"ends with {run.events[first]} instead of {word[first % n]} (proven at {prec} bits)")
        if (name, what) in (("upper", "x + ε"), ("lower", "v + ε")):
            checks.append(Check(f"{name} branch: the datum with {what} (ε = {perturbation}) leaves the pattern "
                                f"{word} within {MAX_PERIODS} periods", first is not None,
                                ref="T25.2.7" if name == "upper" else "T25.2.8"))
    return conclude(checks, evidence=evidence,
                    note="Instability is shown the way the paper argues it: on the upper branch through the positions "
                         "(x perturbed), on the lower branch through the velocities (q perturbed); the other two "
                         "perturbations are reported as evidence.")


def _x_drift(run: sim.Run, n: int, dx, prec: int) -> str:
    """x_k - x₊, x_k = p_3/p_1 after k periods, for k = 1 and the last K (evidence)."""
    def xk(k):
        s = run.states[n * k]
        return s.p[2] / s.p[0]
    K = (len(run.states) - 1) // n
    if K < 2:
        return ""
    with precision(prec):
        x0 = run.states[0].p[2] - flint.arb(dx)
        d1, dK = xk(1) - x0, xk(K) - x0
    return f"; x_k - x₊ after 1 period ∈ {d1.str(3, radius=False)}, after {K} ∈ {dK.str(3, radius=False)}"
