"""The kernel's route for the family (ab)^n(cb)^n (certify_kernel/family.py, L6.6.1) and its interval
arithmetic (certify_kernel/intervals.py): the statement verified as written, mutants of the statement
and of the proof refused, the exact identities against the kernel's own word matrices, and the
intervals against fractions and math at many points (enclosure, with hypothesis)."""
from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from certify_kernel import family, intervals
from certify_kernel.evaluate import NotVerified
from certify_kernel.intervals import Iv
from tests.kernel.kernel_support import outcome, repository_statements

L661 = 'q2_sign_family("(ab)^n(cb)^n", n ≥ 8, r in ]0, 1/4], n·θ = π)'


def test_the_statement_file_says_what_the_kernel_checks():
    stmts = {s.id: s for c in repository_statements().certificates for s in c.statements}
    assert stmts["L6.6.1"].formula == L661
    assert stmts["L6.6"].unformalised           # the whole conjecture: not claimed verified


def test_cdkk_point_is_verified_for_every_n_from_8_and_from_7():
    assert outcome(L661) == "verified"
    assert outcome(L661.replace("n ≥ 8", "n ≥ 7")) == "verified"


@pytest.mark.parametrize("threshold", ["π/2", "2·π", "3·π/4"])
def test_a_wrong_threshold_is_false(threshold):
    got = outcome(L661.replace("n·θ = π", f"n·θ = {threshold}"))
    assert got.startswith("failed:") and "finds it false" in got


def test_the_refuted_verdict_is_not_verified():
    assert outcome(L661, verdict="refuted").startswith("failed:")


@pytest.mark.parametrize("change, why", [
    ("n ≥ 6", "change sign around 1/9"),          # the intervals no longer prove a root near 1/9
    ("n ≥ 5", "reaches 0"),
    ("r in ]0, 1/2]", "r ≤ 1/4"),                # the spectral radius bound holds on ]0, 1/4] only
    ("r in ]0, 1/8]", "3 − 2√2 ≤ R"),             # r_2 = 3 − 2√2 would lie outside
])
def test_mutants_of_the_range_are_not_verified(change, why):
    old = "n ≥ 8" if change.startswith("n") else "r in ]0, 1/4]"
    got = outcome(L661.replace(old, change))
    assert got.startswith("not verified") and why in got, got


@pytest.mark.parametrize("formula", [
    'q2_sign_family("(ab)^n(ca)^n", n ≥ 8, r in ]0, 1/4], n·θ = π)',
    'q2_sign_family("(ab)^n(cb)^n", n > 8, r in ]0, 1/4], n·θ = π)',
    'q2_sign_family("(ab)^n(cb)^n", n ≥ 8, r in [0, 1/4], n·θ = π)',
    'q2_sign_family("(ab)^n(cb)^n", n ≥ 8, r in ]0, 1/4], θ = π)',
])
def test_other_forms_are_refused_with_one_line(formula):
    got = outcome(formula)
    assert got.startswith("failed:") and "\n" not in got


def test_the_block_and_the_identity_of_q2_on_the_kernels_matrices():
    K, w = family.block()
    assert K[0][1] == family.H and w[1] == family.H              # K₁₂ = h, w₂ = h
    assert family.check_q2_identity()
    assert all(family.check_period_matrix(n) for n in (1, 2, 3, 4))


def test_a_false_identity_is_caught(monkeypatch):
    """Without the reflection J (N = M_ab^n itself) the identity of q_2(0) is false."""
    def unreflected(a, b, c, d, W1, W2):
        return [[a, b, {}], [c, d, {}], [W1, W2, family._const(1)]]
    monkeypatch.setattr(family, "_n_rows", unreflected)
    assert not family.check_q2_identity()


def test_a_wrong_block_is_caught(monkeypatch):
    monkeypatch.setattr(family, "T", [Fraction(1, 4), Fraction(-3, 2), Fraction(1, 3)])
    with pytest.raises(ArithmeticError, match="tr K"):
        family.block()


def test_dominance_constants_match_the_proof():
    """δ = N₁ 4^(1−N₁) max(1, |K_ij| + r) and λ ∈ 1/9 ± 16δ (docs/family-limit.md, part 7: N₁ = 31,
    δ ≈ 2.7·10⁻¹⁷), recomputed here from the kernel's K."""
    K, _ = family.block()
    facts = family.dominant(K, 31, Fraction(1, 4))
    kmax = max(abs(family.at(K[i][j], Fraction(k, 400))) + Fraction(k, 400) for i in range(2) for j in range(2)
               for k in range(101))
    assert facts["delta"] >= 31 * Fraction(1, 4) ** 30 * max(1, kmax)
    assert facts["lambda"][0] < Fraction(1, 9) < facts["lambda"][1]
    assert facts["others"] < facts["lambda"][0]


def test_a_tightened_margin_is_not_proved(monkeypatch):
    """The interval of λ shrunk from 1/9 ± 16δ to 1/9 ± δ/4096 (a margin tightened): the sign change
    of the characteristic polynomial is no longer proved, and the statement is not verified."""
    K, _ = family.block()
    family.dominant(K, 8, Fraction(1, 4))
    monkeypatch.setattr(family, "WIDTH", Fraction(1, 4096))
    with pytest.raises(NotVerified, match="change sign"):
        family.dominant(K, 8, Fraction(1, 4))
    assert outcome(L661).startswith("not verified")


def test_the_intervals_against_math_at_many_points():
    for k in range(1, 400):
        x = Fraction(k, 37)
        y = Fraction(400 - k, 53)
        for got, want in ((Iv(x) + Iv(y), x + y), (Iv(x) - Iv(y), x - y), (Iv(x) * Iv(y), x * y),
                          (Iv(x) / Iv(y), x / y), (Iv(x) ** 3, x ** 3)):
            assert got.contains(want)
            assert got.hi - got.lo <= Fraction(1, 2 ** (intervals.BITS - 8)) * (1 + abs(want))
        s = intervals.sqrt(Iv(x))
        assert s.lo ** 2 <= x <= s.hi ** 2
        assert abs(float(s.lo) - math.sqrt(k / 37)) < 1e-12


_q = st.fractions(min_value=-50, max_value=50, max_denominator=10 ** 6)


@settings(max_examples=300, deadline=None)
@given(_q, _q, _q, _q, st.floats(0, 1), st.floats(0, 1), st.sampled_from("+-*/"))
def test_enclosure(a, b, c, d, s, t, op):
    """Every point of the operands gives a result inside the interval of the operation."""
    x, y = Iv(min(a, b), max(a, b)), Iv(min(c, d), max(c, d))
    px = x.lo + (x.hi - x.lo) * Fraction(s)
    py = y.lo + (y.hi - y.lo) * Fraction(t)
    if op == "/" and y.lo <= 0 <= y.hi:
        with pytest.raises(ZeroDivisionError):
            x / y
        return
    got = {"+": x + y, "-": x - y, "*": x * y, "/": x / y if op == "/" else None}[op]
    want = {"+": px + py, "-": px - py, "*": px * py, "/": px / py if op == "/" else None}[op]
    assert got.contains(want)


@settings(max_examples=200, deadline=None)
@given(st.fractions(min_value=0, max_value=10 ** 6, max_denominator=10 ** 9))
def test_sqrt_encloses(q):
    s = intervals.sqrt(Iv(q))
    assert s.lo >= 0 and s.lo ** 2 <= q <= s.hi ** 2


def test_a_broken_identity_makes_the_statement_not_verified(monkeypatch):
    monkeypatch.setattr(family, "check_q2_identity", lambda: False)
    got = outcome(L661)
    assert got.startswith("not verified") and "identity of q_2(0)" in got


UNSTABLE = 'family_unstable("(ab)^n(cb)^n", n ≥ 8, r in ]0, 1/4], n·θ > π)'


def test_nothing_above_r_n_is_stable_for_every_n_from_8():
    stmts = {s.id: s for c in repository_statements().certificates for s in c.statements}
    assert stmts["L6.6.2"].formula == UNSTABLE
    assert outcome(UNSTABLE) == "verified"
    assert outcome(stmts["L6.6.3"].formula) == "verified"


@pytest.mark.parametrize("change, why", [
    ("n·θ > π/2", "below nθ = π"),               # inside the window: the kernel proves no instability there
    ("n ≥ 6", "change sign around 1/9"),
    ("r in ]0, 1/2]", "r ≤ 1/4"),
])
def test_mutants_of_unstable_are_not_verified(change, why):
    old = {"n·": "n·θ > π", "n ": "n ≥ 8", "r ": "r in ]0, 1/4]"}[change[:2]]
    got = outcome(UNSTABLE.replace(old, change))
    assert got.startswith("not verified") and why in got, got


def test_the_third_a_statement_fails_where_t_is_positive():
    stmts = {s.id: s for c in repository_statements().certificates for s in c.statements}
    f = stmts["L6.6.3"].formula
    assert outcome(f.replace("429/2500", "1/10")).startswith("failed:")          # t > 0 below 3 − 2√2
    assert outcome(f.replace("+ r^2", "- r^2")).startswith("failed:")            # ℓ₂ = tℓ₁ − r²: false


def test_the_arcs_margins_and_a_tightened_one(monkeypatch):
    """Part 5's margins at N₁ = 7 (docs/family-limit.md, part 10: 1.956 and 0.4328 with the engine's
    C_u), recomputed; with C_u inflated 200-fold the separating b is no longer proved."""
    facts = family._proved(7, Fraction(1, 4))
    m1, m2 = family.arcs(facts["K"], 7, Fraction(1, 4), facts["Cu"])["margins"]
    assert Fraction(19, 10) < m1 < 2 and Fraction(4, 10) < m2 < Fraction(45, 100)
    with pytest.raises(NotVerified, match="separating b"):
        family.arcs(facts["K"], 7, Fraction(1, 4), 200 * facts["Cu"])


def test_u_is_c_times_x_over_d():
    assert family.check_u_factor()


APPROACHING = 'family_approaching("(ab)^n(cb)^n", n ≥ 8, n·θ < π)'


def test_every_pair_approaches_below_r_n_and_not_above():
    stmts = {s.id: s for c in repository_statements().certificates for s in c.statements}
    assert stmts["L6.6.4"].formula.startswith(APPROACHING)
    assert outcome(stmts["L6.6.4"].formula) == "verified"
    assert outcome(APPROACHING) == "verified"
    got = outcome(APPROACHING.replace("n·θ < π", "n·θ < 2·π"))            # a wrong threshold: false
    assert got.startswith("failed:") and "finds it false" in got


def test_the_velocity_margins_and_an_inflated_constant():
    """Part 6's margins (docs/family-limit.md, part 8: ≥ 0.051 before each a, about 1 before each b),
    recomputed at N₁ = 8; with C_u inflated 10⁶-fold they are no longer proved (the margins are wide:
    n² r^(n−1) ≤ 64·0.08⁷ ≈ 1.3·10⁻⁶)."""
    facts = family._proved(8, Fraction(1, 4))
    m_a, m_b = family.velocities(facts["K"], 8, facts)["margins"]
    assert Fraction(5, 100) < m_a < Fraction(6, 100) and Fraction(99, 100) < m_b < 1
    with pytest.raises(NotVerified, match="velocity margins"):
        family.velocities(facts["K"], 8, {**facts, "Cu": 10 ** 6 * facts["Cu"]})
