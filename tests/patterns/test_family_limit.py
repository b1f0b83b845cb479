"""The windows of (ab)^n(cb)^n beyond N₀ (certify.patterns.family_limit): the proved
closed form of the upper end r_n (nθ = π, where q₂(0) = 0) against an independent mpmath
computation of the stable set straight from the matrices (tests/patterns/mp_family.py),
the exact identity behind it on the engine's candidate, and mutants of the proof's facts."""
import functools
from fractions import Fraction

import flint
import mpmath as mp
import pytest

from certify.algebra.balls import ends, precision
from certify.patterns import family_limit as F
from tests.patterns import mp_family as ref


@functools.cache
def _window(n):
    """lo_n, hi_n of the mpmath reference at 4n + 60 digits (computed once per n)."""
    with mp.workdps(4 * n + 60):
        return ref.window(n, steps=70)


def _mp(ball) -> mp.mpf:
    lo, hi = ends(ball)
    return (mp.mpf(int(lo.p)) / int(lo.q) + mp.mpf(int(hi.p)) / int(hi.q)) / 2


def test_block_identities_hold_and_name_the_structure():
    assert len(F.block_facts()) == 7


@pytest.mark.parametrize("n", [2, 3, 4])
def test_u_identity_holds_exactly_on_the_engine_candidate(n):
    assert F.check_u_identity(n)


def test_u_identity_fails_with_the_wrong_power(monkeypatch):
    real = F.power
    monkeypatch.setattr(F, "power", lambda K, n: real(K, n + 1))
    assert not F.check_u_identity(3)


def test_upper_end_is_the_known_end_for_n_2_3():
    # 3 - 2√2 and 5 - 2√6: L5's and L6's certified upper ends
    assert F.upper_end(2).overlaps(3 - 2 * flint.arb(2).sqrt())
    assert F.upper_end(3).overlaps(5 - 2 * flint.arb(6).sqrt())
    assert not F.upper_end(4).overlaps(F.upper_end(5))


@pytest.mark.parametrize("n", [35, 50, 80])
def test_upper_end_and_window_against_mpmath(n):
    """hi_n from bisection of the stable set (mpmath, 4n + 60 digits) is r_n; above it u < 0
    is what fails; lo_n lies in ]r_{n+1}, r_n[ (disjoint windows, observed)."""
    lo, hi = _window(n)
    with mp.workdps(4 * n + 60):
        rn, rn1 = _mp(F.upper_end(n, 400)), _mp(F.upper_end(n + 1, 400))
        width = rn - lo
        assert abs(hi - rn) < width * mp.mpf(2) ** -50
        assert ref.analyse(n, rn + width / 10 ** 6) == (False, "u")
        assert ref.analyse(n, rn - width / 10 ** 6)[0]
        assert rn1 < lo < rn
        assert "x" in ref.analyse(n, lo - width / 10 ** 6)[1]          # the lower end: x₊ crosses 0
        s_lo = n ** 2 * (lo - (7 - 4 * mp.sqrt(3)))
        assert 0.08 < (_mp(F.s_star()) - s_lo) * n < 0.13             # s_lo ≈ s* - 0.117/n (observed)


def test_s_hi_formula_against_the_direct_difference():
    n = 40
    with precision(300):
        direct = n ** 2 * (F.upper_end(n, 300) - (7 - 4 * flint.arb(3).sqrt()))
        assert F.s_hi(flint.arb(flint.fmpq(1, n))).overlaps(direct)
        assert (F.s_hi(flint.arb(0)) - F.s_star()).abs_upper() < flint.arb(2) ** -250


def _check_but_parts_9_10(facts):
    """F.check on the facts without the keys of parts 9 and 10 (checked by their own tests): a mutant of
    another part must fail on its own."""
    return F.check({k: v for k, v in facts.items() if k not in ("positions", "below", "arcs")})


@pytest.fixture(scope="module")
def small():
    return F.prove(N0=30, boxes=16)


def test_proof_facts_check(small):
    assert F.check(small) == []


def test_mutant_smaller_constant_fails(small):
    import copy
    facts = copy.deepcopy(small)
    facts["C"] = Fraction(1, 3)                       # below κ ≈ 0.418: |s_hi - s*| ≤ ε²/3 is false
    assert any("C ε²" in b for b in _check_but_parts_9_10(facts))


def test_mutant_widened_box_fails(small):
    import copy
    facts = copy.deepcopy(small)
    facts["boxes"][-1]["eps"][1] = Fraction(1, 10)    # the last box widened to ε = 1/10
    assert any("not in" in b for b in _check_but_parts_9_10(facts))


def test_mutant_shifted_s_star_fails(small):
    import copy
    facts = copy.deepcopy(small)
    facts["s_star"] = [facts["s_star"][0] + Fraction(1, 10 ** 12), facts["s_star"][1] + Fraction(1, 10 ** 12)]
    assert any("s_star" in b for b in _check_but_parts_9_10(facts))


def test_mutant_gap_in_the_cover_fails(small):
    import copy
    facts = copy.deepcopy(small)
    del facts["boxes"][3]
    assert "the boxes do not cover [0, 1/N0]" in _check_but_parts_9_10(facts)


# ------------------------------------------------------------------ the lower end
@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_period_matrix_and_lower_identity_exact(n):
    assert F.check_lower_identity(n)


def test_lower_identity_fails_for_a_wrong_lower_polynomial(monkeypatch):
    real = F.lower_polynomial
    monkeypatch.setattr(F, "lower_polynomial", lambda n: real(n) + 1)
    assert not F.check_lower_identity(3)


def test_limit_constants_exact():
    import sympy as sp
    c = F.limit_constants()
    assert c["W"] == (sp.Rational(1, 3), sp.Rational(2, 3)) and c["rho"] == sp.sqrt(3) / 6
    with precision(100):
        assert flint.arb(str(sp.N(c["alpha"], 30))).overlaps(F.s_star() / flint.arb(3).sqrt())


@functools.cache
def _facts_from_7():
    """prove(N0=5): parts 5, 7, 9 from n = 6, 7, 7 on, part 8 from n = 8 (computed once)."""
    return F.prove(N0=5)


def test_the_proof_from_n_6_checks():
    assert F.check(_facts_from_7()) == []


@pytest.fixture(scope="module")
def facts():
    return F.prove(N0=30)


@pytest.mark.parametrize("n", [35, 50, 80])
def test_lower_strip_holds_the_mpmath_lower_end(n, facts):
    """The observed lower end lo_n (bisection of the stable set, mpmath) is a zero of F_n (the
    independent matrices' D = det[e₁, Me₁, M²e₁] vanishes there) and n²(lo_n - r*) lies in the
    proof's enclosure for the ε-box of 1/n."""
    row = next(b for b in facts["lower"]["boxes"] if b["eps"][0] <= Fraction(1, n) <= b["eps"][1])
    lo, hi = _window(n)
    with mp.workdps(4 * n + 60):
        s_lo = n ** 2 * (lo - (7 - 4 * mp.sqrt(3)))
        assert mp.mpf(row["s_lo"][0].numerator) / row["s_lo"][0].denominator < s_lo
        assert s_lo < mp.mpf(row["s_lo"][1].numerator) / row["s_lo"][1].denominator

        def D(r):
            M = ref.matrix("cb", r) ** n * ref.matrix("ab", r) ** n
            M2 = M * M
            return M[1, 0] * M2[2, 0] - M[2, 0] * M2[1, 0]
        h = (hi - lo) / 10 ** 8
        assert D(lo - h) * D(lo + h) < 0                  # D changes sign at lo_n


def test_mutant_narrowed_strip_fails(facts):
    import copy
    f = copy.deepcopy(facts)
    row = f["lower"]["boxes"][-1]
    row["eta"][1] = row["eta"][0]                     # the strip shrunk to its left end
    assert any("F̂ > 0 not proven" in b for b in _check_but_parts_9_10(f))


def test_mutant_lower_box_widened_fails(facts):
    import copy
    f = copy.deepcopy(facts)
    f["lower"]["boxes"][-1]["eps"][1] = Fraction(1, 5)   # ε up to 1/5: n ≥ 5 is not proved
    assert _check_but_parts_9_10(f)


def test_mutant_margin_too_large_fails(facts):
    import copy
    f = copy.deepcopy(facts)
    f["lower"]["boxes"][0]["margin"] = Fraction(3)       # more room than π/(1 + ε) - η₊ ≈ 2.2
    assert any("margin" in b for b in _check_but_parts_9_10(f))


@pytest.mark.parametrize("n", [6, 7, 10])
def test_the_lower_proof_closes_from_n_6(n):
    """prove(N0=5): the strip and the disjointness hold from n = 6 on, and hold lo_n there."""
    f = _facts_from_7()
    row = next(b for b in f["lower"]["boxes"] if b["eps"][0] <= Fraction(1, n) <= b["eps"][1])
    lo, _ = _window(n)
    with mp.workdps(4 * n + 60):
        s_lo = n ** 2 * (lo - (7 - 4 * mp.sqrt(3)))
        lo_s, hi_s = (mp.mpf(q.numerator) / q.denominator for q in row["s_lo"])
        assert lo_s < s_lo < hi_s


def test_the_lower_proof_does_not_close_from_n_3():
    with pytest.raises(ArithmeticError):
        F.prove(N0=2)


# ------------------------------------------------------------------ the dominant branch
def test_w_limit_is_one_third_two_thirds():
    assert F.check_w_limit()


def test_dominant_branch_from_n_7_not_6():
    assert F.dominant_facts(7)["q3_minus_d"] < 0
    with pytest.raises(ArithmeticError):
        F.dominant_facts(6)


def test_dominant_branch_and_sign_of_u_against_mpmath(facts):
    """n = 35: mpmath's dominant eigenvalue lies in the proved interval, and q₂(0) has the sign
    of sin(nθ) below r*, inside the window, just above r_n and where nθ = 3π/2 and 5π/2 (the
    last two: u < 0, then u > 0 again on the dominant branch)."""
    n, d = 35, facts["dominant"]
    with mp.workdps(4 * n + 60):
        rs = 7 - 4 * mp.sqrt(3)

        def r_at(phi):                       # nθ = phi
            a = 3 + 4 * mp.cos(phi / n)
            return a - mp.sqrt(a * a - 1)
        for r in (rs / 2, rs - mp.mpf(10) ** -6, r_at(mp.pi * 0.99), r_at(mp.pi * 1.01), r_at(1.5 * mp.pi),
                  r_at(2.5 * mp.pi), mp.mpf("0.2")):
            M = ref.matrix("cb", r) ** n * ref.matrix("ab", r) ** n
            ev = sorted(mp.eig(M)[0], key=abs, reverse=True)
            lam = mp.re(ev[0])
            lo_l, hi_l = (mp.mpf(q.numerator) / q.denominator for q in d["lambda"])
            assert lo_l < lam < hi_l
            A = M - lam * mp.eye(3)
            u = (A[0, 0] * A[1, 2] - A[0, 2] * A[1, 0]) / (A[0, 1] * A[1, 2] - A[0, 2] * A[1, 1])
            c = (r * r - 6 * r + 1) / (8 * r)
            sn = mp.sin(n * mp.acos(c)) if r > rs else 1
            assert mp.sign(u) == mp.sign(sn)


def test_mutant_dominant_lambda_shifted_fails(facts):
    import copy
    f = copy.deepcopy(facts)
    f["dominant"]["lambda"] = [Fraction(1, 8), Fraction(1, 7)]
    assert any("λ not in" in b for b in _check_but_parts_9_10(f))


def test_mutant_dominant_range_widened_fails(facts):
    import copy
    f = copy.deepcopy(facts)
    f["dominant"]["r"] = [Fraction(0), Fraction(1, 2)]
    assert any("]0, 1/4]" in b for b in _check_but_parts_9_10(f))


# ------------------------------------------------------------------ the velocity conditions
def test_velocity_conditions_from_n_8_not_7():
    assert all(m > 0 for m in F.velocity_facts(8)["margins"].values())
    with pytest.raises(ArithmeticError):
        F.velocity_facts(7)


def _velocity_signs(n, r):
    """Every velocity condition of (ab)^n(cb)^n on the dominant branch at r (mpmath): the pair
    of each collision approaches just before it."""
    M = ref.matrix("cb", r) ** n * ref.matrix("ab", r) ** n
    lam = mp.re(sorted(mp.eig(M)[0], key=abs, reverse=True)[0])
    A = M - lam * mp.eye(3)
    det = A[0, 1] * A[1, 2] - A[0, 2] * A[1, 1]
    q = [mp.mpf(-1), (A[0, 0] * A[1, 2] - A[0, 2] * A[1, 0]) / det, (A[0, 1] * A[1, 0] - A[0, 0] * A[1, 1]) / det]
    ok = True
    for letter in "ab" * n + "cb" * n:
        ok = ok and q[ref.IDX[letter]] < 0
        q = ref.collide(letter, q, r)
    return ok


def test_velocity_conditions_against_mpmath():
    """n = 35: they hold on ]r*, r_n[ (below, inside and at the top of the window) and fail just
    above r_n (where q₂(0) < 0 and the last b of the ab-phase comes with q₂ > 0)."""
    n = 35
    with mp.workdps(4 * n + 60):
        rs = 7 - 4 * mp.sqrt(3)
        rn = _mp(F.upper_end(n, 400))
        for r in (rs + (rn - rs) / 1000, (rs + rn) / 2, rn - (rn - rs) / 10 ** 6):
            assert _velocity_signs(n, r)
        assert not _velocity_signs(n, rn + (rn - rs) / 10 ** 6)


def test_mutant_velocity_margin_inflated_fails(facts):
    import copy
    f = copy.deepcopy(facts)
    key = next(iter(f["velocity"]["margins"]))
    f["velocity"]["margins"][key] = Fraction(1, 2)
    assert any("velocity margin" in b for b in _check_but_parts_9_10(f))


# ------------------------------------------------------------------ the positions (part 9)
def _mp_poly(p, values):
    """An fmpq_mpoly of graded_quantities() at mpmath values (z, y, A, B, C, D)."""
    total = mp.mpf(0)
    for e, c in p.to_dict().items():
        term = mp.mpf(int(c.p)) / int(c.q)
        for v, k in zip(values, e):
            term *= v ** int(k)
        total += term
    return total


def _reference_quotient(n, r):
    """From the independent reference: λ, the map p(0) = (1, 0, x) ↦ p(T) on the plane p₂ = 0 as
    p₁(T) = Q₁₁ + Q₁₂x, p₃(T) = Q₂₁ + Q₂₂x, and p₃(t_2n) = P₀ + P₁x (positions propagated letter by
    letter, each collision time from p_i = 0)."""
    M = ref.matrix("cb", r) ** n * ref.matrix("ab", r) ** n
    lam = mp.re(sorted(mp.eig(M)[0], key=abs, reverse=True)[0])
    A = M - lam * mp.eye(3)
    det = A[0, 1] * A[1, 2] - A[0, 2] * A[1, 1]
    q = [mp.mpf(-1), (A[0, 0] * A[1, 2] - A[0, 2] * A[1, 0]) / det, (A[0, 1] * A[1, 0] - A[0, 0] * A[1, 1]) / det]
    P = [(mp.mpf(1), mp.mpf(0)), (mp.mpf(0), mp.mpf(0)), (mp.mpf(0), mp.mpf(1))]
    for k, letter in enumerate("ab" * n + "cb" * n):
        i = ref.IDX[letter]
        t = (-P[i][0] / q[i], -P[i][1] / q[i])
        P = [(P[j][0] + t[0] * q[j], P[j][1] + t[1] * q[j]) for j in range(3)]
        P[i] = (mp.mpf(0), mp.mpf(0))
        q = ref.collide(letter, q, r)
        if k == 2 * n - 1:
            mid = P[2]
    return lam, P[0], P[2], mid


@pytest.mark.parametrize("n, eta", [(35, 0.3), (35, 0.95), (35, 2.5), (12, 0.5), (12, 1.5)])
def test_graded_quantities_against_the_reference(n, eta):
    """The closed forms of part 9 (Q₁₂ = zE/X, Q₂₁ = r^(2n) zY/X, Q₁₁ + Q₂₂ = z²S, p₃(t_2n) = x + zZ/(Δ - dX),
    with K^n = z[[A, B], [C, D]], z = r^(n-1)) against the reference's positions, at nθ = π - η/n."""
    qs = F.graded_quantities()
    with mp.workdps(4 * n + 60):
        a_ = 3 + 4 * mp.cos((mp.pi - mp.mpf(eta) / n) / n)
        r = a_ - mp.sqrt(a_ * a_ - 1)
        lam, (Q11, Q12), (Q21, Q22), mid = _reference_quotient(n, r)
        h = (1 + r) / 2
        Kn = mp.matrix([[h * h - r, h], [-r * h, -r]]) ** n
        z = r ** (n - 1)
        ent = [Kn[0, 0] / z, Kn[0, 1] / z, Kn[1, 0] / z, Kn[1, 1] / z]
        y = (lam - _mp_poly(qs["lambda"], [z, 0] + ent)) / z ** 3
        v = {k: _mp_poly(p, [z, y] + ent) for k, p in qs.items()}
        assert abs(v["G"]) < mp.mpf(10) ** -20                           # y is λ's rest: cp(λ) = 0
        for got, want in ((z * v["E"] / v["X"], Q12), (r ** (2 * n) * z * v["Y"] / v["X"], Q21),
                          (z ** 2 * v["S"], Q11 + Q22), (z * v["Z"] / (v["Delta"] - z * ent[3] * v["X"]), mid[0])):
            assert abs(got - want) <= abs(want) * mp.mpf(10) ** -20
        assert abs(mid[1] - 1) < mp.mpf(10) ** -20
        Fn = mp.polyval([mp.mpf(int(c.p)) / int(c.q) for c in reversed(F.lower_polynomial(n).coeffs())], r)
        assert abs(z * v["F"] - Fn) <= abs(Fn) * mp.mpf(10) ** -20


def test_leading_forms_are_one_linear_form():
    """At z = 0 every position quantity is a multiple of L = 3A + 2C - D (and S = L² + 6(AD - BC) > 0)."""
    qs = F.graded_quantities()
    ctx = qs["E"].context()
    _, _, A, B, C, D = ctx.gens()
    L = 3 * A + 2 * C - D
    third = flint.fmpq(1, 27)
    assert F._z_part(qs["E"], 0) == third * L
    assert F._z_part(qs["Y"], 0) == L / 9
    assert F._z_part(qs["Z"], 0) == -L / 81
    assert F._z_part(qs["F"], 0) == L / 9                                  # F_n = zL/9 + O(z²)
    assert F._z_part(qs["S"], 0) == L * L + 6 * (A * D - B * C)
    assert F._z_part(qs["X"], 0) == -third


@pytest.mark.parametrize("n, which", [(35, "N0=30"), (50, "N0=30"), (10, "N0=5")])
def test_positions_against_the_reference_stable_set(n, which, facts):
    """Where part 9 says 'inside' the reference finds r stable, where it says 'below' not; and below
    r_{n+1} (the far chart) and below r* (the low chart) nothing is stable."""
    f = facts if which == "N0=30" else _facts_from_7()
    row = next(b for b in f["positions"]["boxes"] if b["eps"][0] <= Fraction(1, n) <= b["eps"][1])
    with mp.workdps(4 * n + 60):
        def r_at(eta):
            a_ = 3 + 4 * mp.cos((mp.pi - mp.mpf(eta) / n) / n)
            return a_ - mp.sqrt(a_ * a_ - 1)
        for a, b, label in row["pieces"][::7]:
            mid = (a + b) / 2
            assert ref.analyse(n, r_at(mp.mpf(mid.numerator) / mid.denominator))[0] == (label == "inside")
        rs = 7 - 4 * mp.sqrt(3)
        for r in (rs / 3, rs * (1 - mp.mpf(10) ** -6), r_at(6), r_at(n * mp.pi / 2)):
            assert not ref.analyse(n, r)[0]


def test_positions_and_below_check(facts):
    assert F.check_positions(facts["positions"]) == [] and F.check_below(facts["below"]) == []
    assert facts["positions"]["N1"] == 31 and _facts_from_7()["positions"]["N1"] == 7


def test_mutant_positions_piece_relabelled_fails(facts):
    import copy
    f = copy.deepcopy(facts["positions"])
    piece = next(p for p in f["boxes"][5]["pieces"] if p[2] == "below")
    piece[2] = "inside"
    assert F.check_positions(f)


def test_mutant_positions_inside_into_the_strip_fails(facts):
    """Claiming 'inside' up to the strip's upper end (the strip closed from below) fails."""
    import copy
    f = copy.deepcopy(facts["positions"])
    row = f["boxes"][-1]
    last = [p for p in row["pieces"] if p[2] == "inside"][-1]
    last[1] = row["strip"][0] = row["strip"][1]
    assert any("not proven" in b for b in F.check_positions(f))


def test_mutant_below_leaf_removed_fails(facts):
    import copy
    f = copy.deepcopy(facts["below"])
    del f["far"][len(f["far"]) // 2]
    assert any("tile" in b for b in F.check_below(f))
    g = copy.deepcopy(facts["below"])
    g["low"] = g["low"][:-1]
    assert any("tile" in b for b in F.check_below(g))


def test_mutant_positions_thinner_strip_fails(facts):
    """The undecided part of the strip is proved ≤ 2τ/m wide (≈ 10⁻³⁵ in η for n ≥ 31); claiming a
    millionth of that bound fails."""
    import copy
    f = copy.deepcopy(facts["positions"])
    assert max(row["thin"] for row in f["boxes"]) < Fraction(1, 10 ** 30)
    f["boxes"][3]["thin"] /= 10 ** 6
    assert any("not proven ≤" in b for b in F.check_positions(f))


def test_l_slope_against_a_difference_quotient():
    with precision(200):
        eps = flint.arb(flint.fmpq(1, 40))

        def L(eta):
            _, e = F._blowup_entries(flint.arb(eta), eps)
            return 3 * e[0] + 2 * e[2] - e[3]
        h = flint.fmpq(1, 10 ** 20)
        quotient = (L(flint.fmpq(9, 10) + h) - L(flint.fmpq(9, 10) - h)) / (2 * h)
        slope = F.l_slope(flint.arb(flint.fmpq(9, 10)), eps)
        assert slope.overlaps(quotient) and slope.rad() < flint.arb(10) ** -6


# ------------------------------------------------------------------ above r_n (part 10)
def test_arcs_above_r_n_against_mpmath(facts):
    """n = 35: where nθ > 2π (and at r = 1/5, 1/4, 0.6) some velocity condition of the reference fails,
    and the point is not stable; part 10 reaches r = 5/8 for N₁ = 31, 1/4 for N₁ = 7."""
    assert facts["arcs"]["r"][1] == Fraction(5, 8) and _facts_from_7()["arcs"]["r"][1] == Fraction(1, 4)
    assert all(m > 0 for m in facts["arcs"]["margins"])
    n = 35
    with mp.workdps(4 * n + 60):
        def r_at(phi):
            a_ = 3 + 4 * mp.cos(phi / n)
            return a_ - mp.sqrt(a_ * a_ - 1)
        for r in (r_at(2.5 * mp.pi), r_at(4.5 * mp.pi), r_at(10.2 * mp.pi), mp.mpf("0.2"), mp.mpf("0.25"),
                  mp.mpf("0.6")):
            assert not _velocity_signs(n, r)
            assert not ref.analyse(n, r)[0]


def test_mutant_arc_margin_inflated_fails(facts):
    import copy
    f = copy.deepcopy(facts["arcs"])
    f["margins"][1] = Fraction(1, 2)                  # above min(sin θ_max, sin(3θ_max/2)) ≈ 0.439
    assert any("arc margin" in b for b in F.check_arcs(f))
    g = copy.deepcopy(facts["arcs"])
    g["r"] = [None, Fraction(7, 8)]                    # part 7 is re-proved up to 5/8 for N₁ = 31, not 7/8
    assert any("proved up to" in b for b in F.check_arcs(g))
    h = copy.deepcopy(facts["arcs"])
    h["upper"].append([Fraction(5, 8), Fraction(3, 4)])  # a box where part 7's dominance is not proven
    assert any("part 10 does not hold" in b for b in F.check_arcs(h))


# ------------------------------------------------------------------ t ≤ 0: the third a (part 11)
def _q1_before_the_a(n, r, u, v):
    """q₁ just before each a of the ab-phase, by the reference's collision law from q(0) = (-1, u, v)."""
    q, out = [mp.mpf(-1), u, v], []
    for letter in "ab" * n:
        if letter == "a":
            out.append(q[0])
        q = ref.collide(letter, q, r)
    return out


def test_third_a_separates_for_any_q0_against_mpmath():
    """Part 11 for every q(0): at r in [r₀, 1[ and arbitrary u, v, the second a's pair separates or the third's
    does by at least r₀²; at r = 0.17 < 3 - 2√2 (t > 0) some u (about -32 or less) lets the first three a's
    all approach, and the proof refuses r₀ = 17/100."""
    f = F.third_a_facts()
    with mp.workdps(50):
        margin = mp.mpf(f["margin"].numerator) / f["margin"].denominator
        for r in (mp.mpf(429) / 2500, mp.mpf("0.3"), mp.mpf(5) / 8, mp.mpf("0.8"), mp.mpf("0.999")):
            for u in (mp.mpf(-7), mp.mpf(0), mp.mpf("0.3"), mp.mpf(1) / 3, mp.mpf(2), mp.mpf(40)):
                l0, l1, l2 = _q1_before_the_a(3, r, u, mp.mpf("0.5"))[:3]
                assert l0 < 0 and (l1 >= 0 or l2 >= margin)
                assert mp.almosteq(l2, (r * r - 6 * r + 1) / 4 * l1 + r * r)
        r = mp.mpf("0.17")
        assert any(max(_q1_before_the_a(3, r, u, mp.mpf(0))) < 0 for u in mp.linspace(-60, 0, 61))
    with pytest.raises(ArithmeticError):
        F.third_a_facts(Fraction(17, 100))


@pytest.mark.parametrize("n", [31, 50])
def test_third_a_nothing_stable_against_the_reference(n):
    """The reference's stable-set analysis finds nothing stable at r in [5/8, 1[ (and 0.18, 0.3)."""
    with mp.workdps(4 * n + 60):
        for r in ("0.18", "0.3", "0.625", "0.7", "0.8", "0.9", "0.99"):
            assert not ref.analyse(n, mp.mpf(r))[0]


def test_mutants_of_the_third_a_fail():
    import copy
    f = F.third_a_facts()
    assert F.check_third_a(f) == [] and f["r"] == [Fraction(429, 2500), 1] and f["t_max"] < 0
    for key, value, words in (("r", [Fraction(1, 10), Fraction(1)], "does not hold"),
                              ("margin", f["margin"] * 2, "margin"),
                              ("n_min", 2, "third a"),
                              ("t_max", f["t_max"] * 2, "t ≤")):
        g = copy.deepcopy(f)
        g[key] = value
        assert any(words in b for b in F.check_third_a(g)), key


# ------------------------------------------------------------------ the reflection M = N² (part 12)
def test_reflection_identities_and_mutant():
    assert F.check_reflection(F.reflection_facts()) == []
    assert F.check_reflection(["M_cb = J M_ab J (J: q₁ ↔ q₃)", "M_cb = M_ab"]) != []


def _quotient(G, q0):
    """The map induced by G on R³/q(0) in the coordinates (p₁, p₃) of the representatives with p₂ = 0."""
    cols = []
    for k in (0, 2):
        w = G[:, k]
        w = w - (w[1] / q0[1]) * q0
        cols.append((w[0], w[2]))
    return mp.matrix([[cols[0][0], cols[1][0]], [cols[0][1], cols[1][1]]])


def _positions(n, r, q0):
    """The reference's positions, letter by letter from p(0) = (1, 0, x) and q(0): (p(t_{2n}), p(T)), each as
    pairs (coefficient of 1, coefficient of x) per particle gap."""
    q, P, half = list(q0), [(mp.mpf(1), mp.mpf(0)), (mp.mpf(0), mp.mpf(0)), (mp.mpf(0), mp.mpf(1))], None
    for k, letter in enumerate("ab" * n + "cb" * n):
        if k == 2 * n:
            half = list(P)
        i = ref.IDX[letter]
        t = (-P[i][0] / q[i], -P[i][1] / q[i])
        P = [(P[j][0] + t[0] * q[j], P[j][1] + t[1] * q[j]) for j in range(3)]
        P[i] = (mp.mpf(0), mp.mpf(0))
        q = ref.collide(letter, q, r)
    return half, P


@pytest.mark.parametrize("n", [10, 35])
def test_reflection_decides_the_points_near_the_lower_end_against_the_reference(n):
    """Part 12 against the reference: with N = J M_ab^n, N q(0) = σ₀ q(0) with σ₀ = -q₃(t_{2n}) > 0, the induced
    N̄ = [[τ, 1], [γ, 0]] with γ = r^{2n}/σ₀, Q = N̄² (the reference's own p(T)), τ = Q₁₂, and at points just
    below and above the reference's lower end (and mid-window) it is stable exactly where τ > 0, with
    p₃(t_{2n}) = σ₊ = τ + x₊ there."""
    lo, hi = _window(n)
    J = mp.matrix([[0, 0, 1], [0, 1, 0], [1, 0, 0]])
    with mp.workdps(4 * n + 60):
        for k in ("-1e-3", "-1e-8", "1e-8", "1e-3", "0.5"):
            r = lo + mp.mpf(k) * (hi - lo)
            Mab = ref.matrix("ab", r) ** n
            M = ref.matrix("cb", r) ** n * Mab
            ev, vec = mp.eig(M)
            i = max(range(3), key=lambda i: abs(ev[i]))
            q0 = mp.matrix([mp.re(x) for x in vec[:, i]]) / -mp.re(vec[0, i])
            N = J * Mab
            sigma0 = -(Mab * q0)[2]
            assert sigma0 > 0 and mp.norm(N * q0 - sigma0 * q0) < mp.mpf(10) ** (-3 * n)
            Nb, Q = _quotient(N, q0), _quotient(M, q0)
            gamma = r ** (2 * n) / sigma0
            tau = Nb[0, 0]
            scale = r ** (2 * n)
            assert abs(Nb[0, 1] - 1) + abs(Nb[1, 1]) < mp.mpf(10) ** (-2 * n)
            assert abs(Nb[1, 0] - gamma) < mp.mpf(10) ** (-20) * gamma
            assert mp.mnorm(Q - Nb * Nb, 1) < mp.mpf(10) ** (-20) * scale
            stable, why = ref.analyse(n, r)
            assert stable == (tau > 0), (k, why)
            # e₂(N) tr N - det N = τ(σ₀ + σ₊)(σ₀ + σ₋) = -F_n: stable exactly where F_n < 0
            a, b, c, d, W1, W2 = Mab[0, 0], Mab[0, 1], Mab[1, 0], Mab[1, 1], Mab[2, 0], Mab[2, 1]
            Fn = W1 * (a - W1 * d + W2 * c) + (b * c + W2 * c * d - W1 * d * d)
            e2 = sum(N[i, i] * N[j, j] - N[i, j] * N[j, i] for i, j in ((0, 1), (0, 2), (1, 2)))
            assert abs(e2 * (N[0, 0] + N[1, 1] + N[2, 2]) - mp.det(N) + Fn) < mp.mpf(10) ** (-20) * abs(Fn)
            assert stable == (Fn < 0)
            half, P = _positions(n, r, q0)              # the reference's p(T) = Q (1, x)
            assert all(abs(P[j][m] - Q[j // 2, m]) < mp.mpf(10) ** (-20) * scale for j in (0, 2) for m in (0, 1))
            x = (-tau + mp.sqrt(tau * tau + 4 * gamma)) / 2
            sigma = tau + x
            assert x > 0 and abs(P[0][0] + x * P[0][1] - sigma ** 2) < mp.mpf(10) ** (-20) * scale
            assert abs(half[2][0] + x * half[2][1] - sigma) < mp.mpf(10) ** (-20) * r ** n


def test_one_zero_of_f_in_each_strip_and_mutants(facts):
    """Part 12's slope: dF/dη > 0 on every strip of part 9 (N₁ = 31 and N₁ = 7), re-checked at 200 bits;
    an inflated slope, a strip moved off part 9's, or a row removed each fail."""
    import copy
    assert F.check_one_zero(facts["one_zero"], facts["positions"]) == []
    assert all(row["slope"] > 0 for row in facts["one_zero"]["boxes"])
    assert F.check_one_zero(_facts_from_7()["one_zero"], _facts_from_7()["positions"]) == []
    f = copy.deepcopy(facts["one_zero"])
    f["boxes"][5]["slope"] = Fraction(1, 20)                 # above the proved ≈ 0.0176
    assert any("not implied" in b for b in F.check_one_zero(f))
    g = copy.deepcopy(facts["one_zero"])
    g["boxes"][5]["strip"] = [Fraction(1, 2), Fraction(3, 4)]
    assert any("not part 9's" in b for b in F.check_one_zero(g, facts["positions"]))
    h = copy.deepcopy(facts["one_zero"])
    del h["boxes"][7]
    assert any("not part 9's" in b for b in F.check_one_zero(h, facts["positions"]))
