"""The candidate of a collision word (certify.dynamics.words) and its requirements
(certify.patterns.feasibility), against the paper's printed ababcb."""
import flint
import pytest
import sympy as sp

from certify.algebra.branches import simplest_between
from certify.algebra.poly import parse
from certify.dynamics.words import candidate, check_position_map
from certify.patterns.feasibility import mod_cp, prefix_requirements

Q = flint.fmpq


def test_candidate_of_ababcb_matches_the_paper():
    """The generic candidate reproduces the paper's u (l. 279) and its position map
    (l. 291-300, up to a common factor modulo cp)."""
    c = candidate("ababcb")
    u_printed = parse("r*(16*λ - r^4 + 8*r^3 + 2*r^2 + 8*r - 1)/(2*(r + 1)*(-r^3 + 6*r^2 - r + 4*λ))")
    diff = sp.fraction(sp.cancel(c.q0[1].as_expr() - u_printed))[0]
    assert mod_cp(sp.expand(diff), c.cp) == 0
    a, b, cc, d = (parse(e) for e in (
        "-64*r^2*(r^4 - 8*r^3 - 2*r^2 - 8*r + 1)*λ + 1024*r^6",
        "256*r^2*(r^2 - 6*r + 1)*λ^2 - 4*r^2*(r - 1)^2*(r - 3)^2*(r^4 - 8*r^3 - 2*r^2 - 8*r + 1)*λ"
        " + 64*r^6*(r^4 - 8*r^3 + 18*r^2 + 5)",
        "16*(r - 1)^2*(r + 1)^2*(r^2 - 10*r + 1)*λ",
        "-64*(r^4 - 8*r^3 - 2*r^2 - 8*r + 1)*λ^2 + (r^10 - 18*r^9 + 101*r^8 - 216*r^7 + 66*r^6"
        " + 372*r^5 + 594*r^4 - 24*r^3 + 253*r^2 - 114*r + 9)*λ"))
    A, B, C, D = c.abcd
    for e in (a * B - b * A, a * C - cc * A, a * D - d * A, cc * D - d * C):
        assert mod_cp(sp.expand(e), c.cp) == 0


def test_prefix_requirements_of_ababcb_are_the_papers():
    """Step 3 of the paper (l. 449-486): the velocity inequalities q2(t1), q1(t2),
    q2(t3), q3(t4), q2(t5) and the distances p3(t4); our list has p1(t6) (> 0 implies
    p1(t5) > 0 by concavity) where the paper lists p1(t5)."""
    c = candidate("ababcb")
    reqs, _ = prefix_requirements("ababcb", 6, c.q0, c.steps)
    assert [q.name for q in reqs] == ["u = q_2(0)", "x", "q_2(t_1)", "q_1(t_2)", "q_2(t_3)", "q_3(t_4)",
                                      "p_3(t_4)", "q_2(t_5)", "p_1(t_6)"]
    u = c.q0[1].as_expr()
    printed = {"q_2(t_1)": "u - (1+r)/2", "q_1(t_2)": "(1+r)/2*u - (r-1)^2/4",
               "q_2(t_3)": "(r-1)^2/4*u - (r^3 - 5*r^2 - 5*r + 1)/8"}
    for q in reqs:
        if q.name in printed:
            diff = sp.cancel(q.G[0].as_expr() - parse(printed[q.name]).subs(sp.Symbol("u"), u))
            assert diff == 0, q.name


def test_position_map_check_catches_a_wrong_map():
    c = candidate("abcab")
    a, b, cc, d = c.abcd
    check_position_map(c.steps, c.abcd, c.cp)
    with pytest.raises(ArithmeticError):
        check_position_map(c.steps, (2 * a, b, 2 * cc, d), c.cp)


def test_simplest_between():
    assert simplest_between(Q(1, 3), Q(1, 2)) == Q(1, 2)
    assert simplest_between(Q(31, 100), Q(32, 100)) == Q(5, 16)
    assert simplest_between(Q(0), Q(1, 10)) == 0




def test_numerator_norm_of_the_conditions_with_x():
    """For each requirement with x of ababcb and each fixed point, the norm a condition
    holds for the exact zero test (Condition.numerator_norm, from the python-flint parts)
    is the polynomial norm_mpoly makes of its N₀, N₁, Δ as ring elements."""
    from certify.algebra.branches import Spectrum, norm_mpoly
    from certify.patterns.feasibility import condition, fixed_point_data
    c = candidate("ababcb")
    S = Spectrum(c.cp)
    reqs, _ = prefix_requirements("ababcb", 6, c.q0, c.steps)
    with_x = [q for q in reqs if q.has_x]
    assert with_x
    for q in with_x:
        for f in fixed_point_data(c.abcd_ring or c.abcd, S.ring_cp):
            cond = condition(q, S.lrq_cp, f)
            M = cond.numerator_norm()
            assert (M is None) == (not cond.N[1])
            if M is not None:
                assert M == norm_mpoly(*cond.N, cond.delta)


@pytest.mark.parametrize("word", ["ababcbcb", "acb", "abacbc", "(ab)^3(cb)^3"])
def test_the_split_norm_gives_the_critical_values_of_the_norm(word):
    """condition() splits the numerator's norm N₀² - N₁²Δ ≡ 4c·g²·Q modulo cp; the critical
    values read from the parts c, g, Q (Condition.critical_norms) are those read from the norm
    itself: for every requirement with x and both fixed points, a fresh Spectrum given the
    condition without its split finds the same critical values over ]0, 1[, and where no
    part's resultant vanishes, Res(norm) ∝ Res(c)·Res(g)²·Res(Q).  (acb: Q ≡ 0 modulo cp,
    the norm's resultant vanishes: the degenerate route of the norm itself.)"""
    from certify.algebra.branches import Condition, Spectrum, _integer_delta, _lrq_to_mpoly
    from certify.algebra.poly import primitive
    from certify.dynamics.systems import candidate_in
    from certify.patterns.feasibility import condition, fixed_point_data
    from certify.patterns.periodic import read
    normal = read(word)[0]
    c = candidate_in("four", normal)
    reqs, _ = prefix_requirements(normal, len(normal), c.q0, c.steps, c.q0_other)
    split = plain = 0
    for q in [q for q in reqs if q.has_x]:
        for f in fixed_point_data(c.abcd_ring, c.spectrum.ring_cp):
            cond = condition(q, c.spectrum.lrq_cp, f)
            bare = Condition(cond.name, None, None, cond.delta, cond.c, lrq=cond._lrq)
            S1, S2 = Spectrum(c.cp, c.spectrum.ring_cp), Spectrum(c.cp, c.spectrum.ring_cp)
            assert cond.split is not None and bare.split is None
            assert S1.critical_values(cond, 0, 1) == S2.critical_values(bare, 0, 1)
            Rc, Rg, RQ, R0, R1 = (S1.resultant(p) for p in [_integer_delta(cond.c)[0]] +
                                  [_lrq_to_mpoly(x)[0] for x in cond.split[0] + cond.split[1]])
            assert primitive(Rc * R0 * R1) == S2.resultant(dict(bare.labelled_norms())["D"])
            # the exact zero test's resultant of the norm, from the split (Spectrum._split_norm_resultant)
            assert S1._split_norm_resultant(cond) == S2.resultant(dict(bare.labelled_norms())["N"])
            if not any(R.is_zero() for R in (Rc, Rg, RQ)):
                norm = dict(bare.labelled_norms())["N"]
                assert primitive(Rc * Rg * Rg * RQ) == S2.resultant(norm)
                split += 1
            else:
                plain += 1
    assert split and (plain or word != "acb")


def test_the_norm_vanishes_where_a_part_of_its_split_does():
    """The exact zero test of the numerator's norm N₀² - N₁²Δ ≡ 4c·g²·Q (Spectrum._root_with_sqrt)
    tests c, g and Q: at every critical value of every condition with x,
    on every branch, some part vanishes exactly where the norm does (the norm's own test on a
    fresh Spectrum), over a few words, and both answers occur."""
    from certify.algebra.branches import Spectrum
    from certify.algebra.poly import mpoly_to_ring
    from certify.dynamics.systems import candidate_in
    from certify.patterns.feasibility import condition, fixed_point_data
    from certify.patterns.periodic import read
    answers = []
    for word in ("ababcbcb", "acb", "ababcb", "abcbacbcab", "(ab)^3(cb)^3"):
        normal = read(word)[0]
        c = candidate_in("four", normal)
        reqs, _ = prefix_requirements(normal, len(normal), c.q0, c.steps, c.q0_other)
        for q in [q for q in reqs if q.has_x]:
            for f in fixed_point_data(c.abcd_ring, c.spectrum.ring_cp):
                cond = condition(q, c.spectrum.lrq_cp, f)
                S1, S2 = Spectrum(c.cp, c.spectrum.ring_cp), Spectrum(c.cp, c.spectrum.ring_cp)
                parts = S1._split_ring_parts(cond)
                norm = mpoly_to_ring(cond.numerator_norm())
                for rc in S1.critical_values(cond, 0, 1):
                    for k in range(len(S1.branches_at(rc) or [])):
                        answers.append((word, any(S1.vanishes_at(h, rc, k) for h in parts),
                                        S2.vanishes_at(norm, rc, k)))
    assert [a for a in answers if a[1] != a[2]] == []
    assert {a[1] for a in answers} == {True, False}


def test_the_condition_at_the_other_fixed_point_is_the_twin_with_n1_negated():
    # feasibility._twin: x₋'s condition from x₊'s (N₁ negated, N₀ and D₀ shared) is the
    # condition built afresh for x₋, for every requirement with x of ababcb
    from certify.algebra.branches import X_MINUS, X_PLUS
    from certify.patterns.feasibility import Analysis, _twin, condition
    c = candidate("ababcb")
    an = Analysis(c)
    reqs, _ = prefix_requirements("ababcb", 6, c.q0, c.steps, c.q0_other)
    with_x = [q for q in reqs if q.has_x]
    assert len(with_x) >= 3
    for q in with_x:
        plus = condition(q, c.spectrum.lrq_cp, an.fps[X_PLUS])
        minus = condition(q, c.spectrum.lrq_cp, an.fps[X_MINUS])
        assert plus._lrq[1] != minus._lrq[1]              # σ matters
        assert _twin(plus, q.name)._lrq == minus._lrq
        assert _twin(minus, q.name)._lrq == plus._lrq
        # the terms it takes (N₀, D₀, Δ shared, N₁'s negated) are those read from its polynomials
        for cond, other in ((plus, minus), (minus, plus)):
            assert _twin(cond, q.name).terms == other.terms


def test_a_sign_at_a_critical_value_is_the_one_the_table_points_would_have():
    # table_sign_at at a critical value the table has not signed: the branch's sign alone
    # (Spectrum.sign_on_branch_at), the same as from every branch's signs (T.points)
    from certify.algebra.branches import Condition
    from certify.algebra.poly import lam
    from certify.patterns.feasibility import table_sign_at
    spec = candidate("abcb").spectrum
    T = spec.sign_table(Condition.of("λ - 1/4", lam - sp.Rational(1, 4)), 0, 1)
    assert len(T.critical) >= 2
    for k, rc in enumerate(T.critical):
        for branch in range(3):
            sg = table_sign_at(T, rc, branch)
            assert not T.has_point(k)
            pt = T.points[k]                       # every branch's signs, computed now
            T._points._done.pop(k)
            assert sg == (pt[branch] if branch < len(pt) else "missing")
