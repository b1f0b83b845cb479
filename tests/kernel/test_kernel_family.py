"""The kernel's route for the family (ab)^n(cb)^n (certify_kernel/family.py, L6.6.1) and its interval
arithmetic (certify_kernel/intervals.py): the statement verified as written, mutants of the statement
and of the proof refused, the exact identities against the kernel's own word matrices, and the
intervals against fractions and math at many points (enclosure, with hypothesis)."""
from __future__ import annotations

import json
import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from certify_kernel import family, intervals
from certify_kernel.evaluate import Context, NotVerified
from certify_kernel.intervals import Iv
from certify_kernel.language import parse
from tests.kernel.kernel_support import ROOT, outcome, repository_statements

L661 = 'q2_sign_family("(ab)^n(cb)^n", n ≥ 8, r in ]0, 1/4], n·θ = π)'


def test_the_statement_file_says_what_the_kernel_checks():
    stmts = {s.id: s for c in repository_statements().certificates for s in c.statements}
    assert stmts["L6.6.1"].formula == L661
    assert stmts["L6.6.5"].formula == REACHES
    assert not stmts["L6.6"].unformalised        # the whole conjecture: n = 2..5, 6, 7 and every n ≥ 8
    for part in (L661, UNSTABLE, APPROACHING, REACHES, L661.replace("n ≥ 8", "n = 6"),
                 REACHES.replace("n ≥ 8", "n = 7"), stmts["L6.6.3"].formula.split(" and ")[0]):
        assert part in stmts["L6.6"].formula, part
    assert "family_window(\"(ab)^n(cb)^n\", n ≥ 8)" in stmts["L5.3"].formula


def test_cdkk_point_is_verified_for_every_n_from_8_and_from_7():
    assert outcome(L661) == "verified"
    assert outcome(L661.replace("n ≥ 8", "n ≥ 7")) == "verified"


@pytest.mark.parametrize("threshold, sign", [("π/2", ">"), ("2·π", "<"), ("3·π/4", ">"), ("5·π/4", "<")])
def test_a_wrong_threshold_is_false_at_a_computed_point(threshold, sign):
    """False with the point that refutes it: an n and an exact r₀ where s_n(r₀) (computed) has the
    sign the claim denies (below nθ = cπ, c > 1, the claim has q_2(0) > 0; above it, c < 1, < 0 ...)."""
    got = outcome(L661.replace("n·θ = π", f"n·θ = {threshold}"))
    assert got.startswith("failed:") and "finds it false" in got and f"s_8 {sign} 0 there" in got, got


def test_a_wrong_threshold_without_its_point_is_not_false(monkeypatch):
    """The review: False used to follow from c alone.  Without the kernel's refuting point the
    wrong threshold is left undecided."""
    monkeypatch.setattr(family, "theta_point", lambda *a: None)
    for threshold in ("π/2", "2·π"):
        got = outcome(L661.replace("n·θ = π", f"n·θ = {threshold}"))
        assert got.startswith("not verified") and "no point refuting" in got, got


@pytest.mark.parametrize("j_lo, j_hi", [(8, 8), (9, 16), (2, 2), (30, 40)])
def test_theta_point_places_theta_exactly(j_lo, j_hi):
    """The refuting point: s_1..s_{j₀−1} > 0 > s_{j₀} at r₀, checked against θ from math (π/j₀ < θ < π/(j₀ − 1))."""
    r0, j0 = family.theta_point(j_lo, j_hi, Fraction(1, 4))
    assert j_lo <= j0 <= j_hi
    theta = math.acos(float(family.at(family.T, r0)) / (2 * float(r0)))
    assert math.pi / j0 < theta < math.pi / (j0 - 1) if j0 > 1 else True


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


def _sci(x: Fraction) -> str:
    """x as the docs print it: 2 digits, ·10⁻ᵏ."""
    mant, exp = f"{float(x):.1e}".split("e")
    sup = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
    return f"{mant}·10{str(int(exp)).translate(sup)}"


def test_dominance_constants_match_the_documented_ones():
    """The constants docs/family-limit.md ("What the kernel checks") prints for part 7's δ, λ and the
    other eigenvalues, recomputed by the kernel: N = 8 and N = 31.  On ]0, 1/4] every |K_ij| + r < 1,
    so δ = N 4^(1−N) exactly (the interval ends are dyadic)."""
    doc = (ROOT / "docs" / "family-limit.md").read_text(encoding="utf-8")
    K, _ = family.block()
    f8, f31 = family.dominant(K, 8, Fraction(1, 4)), family.dominant(K, 31, Fraction(1, 4))
    assert f8["delta"] == 8 * Fraction(1, 4) ** 7 and f31["delta"] == 31 * Fraction(1, 4) ** 30
    for f in (f8, f31):                           # λ encloses 1/9 and strictly dominates the other two
        assert f["lambda"][0] < Fraction(1, 9) < f["lambda"][1]
        assert f["others"] < f["lambda"][0]
    lo, hi = f8["lambda"]
    assert f"N = 8: δ = {_sci(f8['delta'])}, λ ∈ [{float(lo):.5f}, {float(hi):.5f}], |μ|, |ν| ≤ " \
           f"{float(f8['others']):.2g}" in doc
    assert f"N = 31: δ ≈ {_sci(f31['delta'])}" in doc


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
    assert got.startswith("failed:") and "finds it false" in got and "the last b of (ab)^n separates" in got
    assert "n = 8" in got and "s_8 < 0" in got


def test_not_approaching_needs_the_last_b_bound(monkeypatch):
    """The review: "not approaching below 2π" was decided from c alone, its bracket argument in the
    docstring.  Now the kernel bounds the last b's bracket by part 6's b-margin (velocities); with that
    margin not proved (C_u inflated 10⁷-fold: a margin ≤ 0) the negated half is undecided, and L6.6.4 is
    not verified."""
    real = family.velocities
    monkeypatch.setattr(family, "velocities", lambda K, N1, facts: real(K, N1, {**facts, "Cu": 10 ** 7 * facts["Cu"]}))
    got = outcome(APPROACHING.replace("n·θ < π", "n·θ < 2·π"))
    assert got.startswith("not verified") and "velocity margins" in got, got
    stmts = {s.id: s for c in repository_statements().certificates for s in c.statements}
    assert outcome(stmts["L6.6.4"].formula).startswith("not verified")


def test_the_last_b_margin_and_an_inflated_constant():
    """The last b's bracket ≥ rh(1 − C_u h² n r^(n−1)) (n ≥ N = 8, r ≤ 8/100): velocities' b-margin
    1 − C h² N² (8/100)^(N−1) (C ≥ C_u, N² ≥ N) is no larger than that bound, computed here at the worst
    r = 8/100, and about 0.99999 at N = 8; the refutation of nθ < 2π prints it.  With C_u inflated 10⁷-fold
    velocities refuses (the margin ≤ 0), so there is no last-b margin to print."""
    facts = family._proved(8, Fraction(1, 4))
    m_b = family.velocities(facts["K"], 8, facts)["margins"][1]
    hi = family.VELOCITY_RANGE[1]
    h = (1 + hi) / 2
    last = 1 - facts["Cu"] * h * h * 8 * hi ** 7
    assert Fraction(9999, 10000) < m_b <= last < 1
    got = outcome(APPROACHING.replace("n·θ < π", "n·θ < 2·π"))
    assert f"its bracket ≥ rh·{float(m_b):.4f}" in got, got
    with pytest.raises(NotVerified, match="velocity margins"):
        family.velocities(facts["K"], 8, {**facts, "Cu": 10 ** 7 * facts["Cu"]})


def test_the_velocity_margins_and_an_inflated_constant():
    """Part 6's margins (docs/family-limit.md, part 8: ≥ 0.051 before each a, about 1 before each b),
    recomputed at N₁ = 8; with C_u inflated 10⁶-fold they are no longer proved (the margins are wide:
    n² r^(n−1) ≤ 64·0.08⁷ ≈ 1.3·10⁻⁶)."""
    facts = family._proved(8, Fraction(1, 4))
    m_a, m_b = family.velocities(facts["K"], 8, facts)["margins"]
    assert Fraction(5, 100) < m_a < Fraction(6, 100) and Fraction(99, 100) < m_b < 1
    with pytest.raises(NotVerified, match="velocity margins"):
        family.velocities(facts["K"], 8, {**facts, "Cu": 10 ** 6 * facts["Cu"]})


REACHES = 'family_reaches("(ab)^n(cb)^n", n ≥ 8, n·θ = π)'


def test_stable_points_reach_r_n_from_below():
    """L6.6.5: the reflection (family_limit's part 12) in the kernel: stable just below r_n, every n ≥ 8."""
    assert outcome(REACHES) == "verified"
    assert outcome(REACHES.replace("n ≥ 8", "n ≥ 7")) == "verified"


@pytest.mark.parametrize("change, why", [
    ("n ≥ 6", "change sign around 1/9"),                     # part 4 no longer closes
    ("n·θ = 2·π", "just below nθ = π only"),                 # the upper end moved
    ("n·θ = π/2", "just below nθ = π only"),
])
def test_mutants_of_reaches_are_not_verified(change, why):
    old = "n ≥ 8" if change.startswith("n ≥") else "n·θ = π"
    got = outcome(REACHES.replace(old, change))
    assert got.startswith("not verified") and why in got, got


def test_reaches_refuses_another_threshold_before_the_work(monkeypatch):
    """c ≠ 1 is refused from the arguments alone: parts 1-4, 6 and 7 are not run for it."""
    ran = []
    monkeypatch.setattr(family, "_proved", lambda *args: ran.append(args))
    got = outcome(REACHES.replace("n·θ = π", "n·θ = 2·π"))
    assert got.startswith("not verified") and "just below nθ = π only" in got, got
    assert ran == []


def test_the_identities_of_the_reflection():
    assert all(family.check_reflection().values())
    assert family.collisions_fix_their_pair()


@pytest.mark.parametrize("key", ["N̄", "γσ₀", "F_n", "e₁e₂ − e₃", "F_n(r_n)", "collisions"])
def test_a_broken_reflection_identity_is_not_verified(monkeypatch, key):
    real = family.check_reflection
    monkeypatch.setattr(family, "check_reflection", lambda: {**real(), key: False})
    got = outcome(REACHES)
    assert got.startswith("not verified") and key in got, got


def test_f_n_at_r_n_is_negative_and_a_wrong_f_n_is_caught(monkeypatch):
    """F_n(r_n) = −(2/9) r_n^n (1 + r_n^n)²: with F_n's last term's sign flipped (bc + W₂cd + W₁d²) both
    the identity e₂ tr − det = −F_n and the value at r_n fail."""
    real = family.f_n

    def flipped(a, b, c, d, W1, W2):
        k = len(next(iter(a)))
        return family.madd(real(a, b, c, d, W1, W2), family.mmul(family.mmul(family._c(2, k), W1), family.mmul(d, d)))
    monkeypatch.setattr(family, "f_n", flipped)
    got = family.check_reflection()
    assert not got["F_n"] and not got["F_n(r_n)"]


def test_a_collision_that_moves_another_gap_is_caught(monkeypatch):
    """The position lemma needs G x = x when x_i = 0: a matrix with an entry outside column i breaks it."""
    from certify_kernel.evaluate import Matrix
    from certify_kernel.values import RF
    real = family.collision

    def moved(pair):
        rows = [list(row) for row in real(pair).rows]
        j = (pair + 1) % 3
        rows[0][j] = rows[0][j] + RF.const(Fraction(1, 7))
        return Matrix(rows)
    monkeypatch.setattr(family, "collision", moved)
    assert not family.collisions_fix_their_pair()


SIX = [f.replace("n ≥ 8", "n = 6") for f in (L661, UNSTABLE, APPROACHING, REACHES)]


@pytest.mark.parametrize("formula", SIX + [f.replace("n = 6", "n = 7") for f in SIX])
def test_n_6_and_7_by_the_family_route(formula):
    """24 and 28 collisions: part 4 for the one n on 32 boxes of r (K^n exact), the rest as for every n."""
    assert outcome(formula) == "verified"


def test_n_6_margins():
    """n = 6's margins (the kernel's, recomputed): part 5 ≥ 1.94 and 0.429, part 6 ≥ 0.0515 and 0.9998."""
    facts = family._proved(6, Fraction(1, 4), True)
    m1, m2 = family.arcs(facts["K"], 6, Fraction(1, 4), facts["Cu"])["margins"]
    m_a, m_b = family.velocities(facts["K"], 6, facts)["margins"]
    assert m1 > Fraction(194, 100) and m2 > Fraction(429, 1000)
    assert m_a > Fraction(515, 10000) and m_b > Fraction(9998, 10000)


@pytest.mark.parametrize("change, why", [
    ("n = 5", "n ≥ 6"),                                    # part 5 needs 3π/n ≤ π/2
    ("n = 6", "(n = 6, r ∈ [0, 1/4])"),                    # part 4 on one box (below): not proved there
])
def test_mutants_of_n_6_are_not_verified(monkeypatch, change, why):
    f = UNSTABLE.replace("n ≥ 8", change)
    if change == "n = 6":
        real = family.dominant_at
        monkeypatch.setattr(family, "dominant_at", lambda K, n, r_max: real(K, n, r_max, boxes=1))
    got = outcome(f)
    assert got.startswith("not verified") and why in got, got


def test_the_whole_conjecture_for_n_from_6():
    """L6.6's formula for n ≥ 6 (its part after n = 2..5, which is L4's and L6.1-L6.4's analysis, decided
    with the committed witnesses by certify verify) is verified; with an upper end moved it is not."""
    stmts = {s.id: s for c in repository_statements().certificates for s in c.statements}
    f = stmts["L6.6"].formula
    tail = f[f.index('q2_sign_family("(ab)^n(cb)^n", n = 6'):]
    assert outcome(tail) == "verified"
    seven = 'family_reaches("(ab)^n(cb)^n", n = 7, n·θ = π)'
    moved = tail.replace(seven, seven.replace("= π", "= 2·π"))
    assert moved != tail and outcome(moved).startswith("not verified")


WINDOW = 'family_window("(ab)^n(cb)^n", n ≥ 8)'


@pytest.mark.parametrize("formula", [WINDOW, WINDOW.replace("n ≥ 8", "n = 6"), WINDOW.replace("n ≥ 8", "n = 7")])
def test_the_stable_set_lies_between_r_n_plus_1_and_r_n(formula):
    """L5.3 for n ≥ 6: nothing stable on ]0, r_(n+1)] (F_n > 0 there), the rest as in L6.6."""
    assert outcome(formula) == "verified"


@pytest.mark.parametrize("n_bound, single", [("n = 6", True), ("n ≥ 8", False)])
def test_the_arguments_give_one_n_or_every_n_without_state(n_bound, single):
    """_arguments returns whether n is one n (part 4 on boxes of r) with N, R and c, and leaves the context
    as it was (no state for the next predicate); family_window passes no threshold (c = None)."""
    _, _, (word, bound) = parse(f'family_window("(ab)^n(cb)^n", {n_bound})')
    _, _, (_, _, threshold) = parse(f'family_reaches("(ab)^n(cb)^n", {n_bound}, n·θ = π)')
    ctx = Context({})
    before = dict(vars(ctx))
    N1 = int(n_bound[-1])
    assert family._arguments(ctx, word, bound) == (N1, Fraction(1, 4), None, single)
    assert family._arguments(ctx, word, bound, threshold, "=") == (N1, Fraction(1, 4), 1, single)
    assert vars(ctx) == before


@pytest.mark.parametrize("change, why", [
    ("n = 5", "n ≥ 6"),
    ("n ≥ 6", "change sign around 1/9"),
])
def test_mutants_of_the_window_are_not_verified(change, why):
    got = outcome(WINDOW.replace("n ≥ 8", change))
    assert got.startswith("not verified") and why in got, got


def test_f_n_is_positive_below_r_n_plus_1_against_exact_values():
    """F_n > 0 on ]0, r_(n+1)] (the kernel's interval bound), and F_n from K^n in exact rationals: > 0 at
    rationals below r_(n+1) and < 0 just below r_n (math's r_n, only to pick the points)."""
    assert family.below(8, False) > 0 and family.below(6, True) > 0
    for n in (6, 8, 12):
        a = 3 + 4 * math.cos(math.pi / n)
        r_n = a - math.sqrt(a * a - 1)
        a1 = 3 + 4 * math.cos(math.pi / (n + 1))
        r_n1 = a1 - math.sqrt(a1 * a1 - 1)
        for x, sign in ((r_n1 / 2, 1), (r_n1 * 0.999, 1), (r_n * 0.99999, -1)):
            r = Fraction(x)
            h = (1 + r) / 2
            K = [[h * h - r, h], [-r * h, -r]]
            P = [[Fraction(1), Fraction(0)], [Fraction(0), Fraction(1)]]
            for _ in range(n):
                P = [[P[i][0] * K[0][j] + P[i][1] * K[1][j] for j in range(2)] for i in range(2)]
            (pa, pb), (pc, pd) = P
            W1, W2 = Fraction(1, 3) - pa / 3 - 2 * pc / 3, Fraction(2, 3) - pb / 3 - 2 * pd / 3
            F = W1 * (pa - W1 * pd + W2 * pc) + (pb * pc + W2 * pc * pd - W1 * pd * pd)
            assert (F > 0) == (sign > 0), (n, x)


def test_the_bound_below_is_tightened_or_broken(monkeypatch):
    """A margin tightened: F_n/x with its x-free part lowered by 1/36 (1 + 6r − 3r² − 1 ≥ 0 only) is no
    longer proved positive; an F_n with a term free of s_n is refused."""
    real = family.f_n_in_s

    def lowered():
        Q = dict(real())
        Q[(0, 0, 0)] = Q.get((0, 0, 0), Fraction(0)) - Fraction(2, 36)
        return Q
    monkeypatch.setattr(family, "f_n_in_s", lowered)
    with pytest.raises(NotVerified, match="F_n > 0 below"):
        family.below(8, False)
    monkeypatch.setattr(family, "f_n_in_s", lambda: (_ for _ in ()).throw(ArithmeticError("a term without s_n")))
    with pytest.raises(NotVerified, match="without s_n"):
        family.below(8, False)


def test_the_third_a_range_moved(monkeypatch):
    """t < 0 on [429/2500, 1[ (exact); with t shifted up by 1/100 its root moves above 429/2500: refused."""
    family.third_a()
    monkeypatch.setattr(family, "T", [Fraction(1, 4) + Fraction(1, 100), Fraction(-3, 2), Fraction(1, 4)])
    with pytest.raises(NotVerified, match="429/2500"):
        family.third_a()


def test_l53_is_formalised_and_its_family_part_verified():
    """L5.3: n = 2..5 by the words' own analysis (decided with the committed witnesses by certify verify),
    n = 5 above r_6 by a rational point, every n ≥ 6 by family_window.  A separating point below r_6 is
    decided false."""
    stmts = {s.id: s for c in repository_statements().certificates for s in c.statements}
    f = stmts["L5.3"].formula
    assert not stmts["L5.3"].unformalised
    tail = f[f.index("((79/1000)^2"):]
    assert outcome(tail) == "verified"
    got = outcome(tail.replace("79/1000", "77/1000"))
    assert got.startswith("failed:") and "finds it false" in got


def test_the_window_cannot_reach_r_n_from_the_bound_below():
    """The mutant "ℓ_n above r_n" (nothing stable up to r_n): below r_(n+1) the bound uses w ≤ t (s_(n+1) ≥ 0);
    between r_(n+1) and r_n, w = r²s_(n−1)/s_n is unbounded (s_n → 0), and Q's x-free part is negative once
    w > (3 − 6r − r²)/8: the proof cannot be stretched to r_n."""
    Q = family.f_n_in_s()
    r = Iv(Fraction(75, 1000))
    assert family._mvalue(Q, (r, Iv(0), Iv(family.at(family.T, r).hi))).positive()
    assert family._mvalue(Q, (r, Iv(0), Iv(Fraction(1, 2)))).negative()


def test_l53_without_the_words_factors_is_not_verified():
    """A witness dropped: n = 2..5 are decided with the words' factors, which the run writes into L5.3's and
    L6.6's entries of certificates.json; without them the n = 5 part is not verified (a cut polynomial the
    kernel does not split)."""
    stmts = {s.id: s for c in repository_statements().certificates for s in c.statements}
    part = next(p for p in stmts["L5.3"].formula.split(" and ") if '"(ab)^5(cb)^5")}) > 79/1000' in p)
    got = outcome(part)
    assert got.startswith("not verified") and "witness" in got, got
    data = json.loads((ROOT / "reports" / "certificates.json").read_text(encoding="utf-8"))
    entries = {c["id"]: c for c in data["certificates"]}
    for cid, sid in (("L5", "L5.3"), ("L6", "L6.6")):
        words = [w for x in entries[cid]["statements"][sid]["witness"] if x["kind"] == "factors" for w in x["words"]]
        assert words == [f"(ab)^{n}(cb)^{n}" for n in range(2, 6)]


def test_l49_the_sixth_threshold_by_the_family_route():
    """L4.9 (l. 1119, 24 collisions, beyond the word analysis): sup(stable) = r_6 by the family route, one
    family_window for n = 6 (its arcs, velocities, reach, below and third a, not the same clauses spelt out again),
    and rmax6 = 3 + 2√3 − 2√(5 + 3√3) is r_6 (cos θ = √3/2 there); with cos(π/4) in its place (48 → 32)
    the kernel finds it false at rmax6."""
    paper = repository_statements()
    l49 = next(s for c in paper.certificates for s in c.statements if s.id == "L4.9")
    family_part, _, rmax6_part = l49.formula.partition(" and ")
    assert family_part == 'family_window("(ab)^n(cb)^n", n = 6)'
    assert "family_" not in rmax6_part and "word(" not in rmax6_part
    assert outcome(l49.formula, lets=paper.lets) == "verified"
    wrong = l49.formula.replace("= 48*r^2", "= 32*r^2")
    assert wrong != l49.formula
    assert outcome(wrong, lets=paper.lets).startswith("failed: ")
