"""Section 4 identities: the engine certify.algebra.trig (both routes, signs, parsing) and the
certificates of proofs/reduction_identities.py (their mutants: tests/test_mutants.py)."""
import pytest
import sympy as sp

from certify.algebra import trig as T
from certify.algebra.poly import lam, r
from certify.run.runner import CERTIFICATES, FAIL, PASS, altered, run_certificate
from certify.algebra.trig import cθ, cφ, sθ, sφ
from tests.shared import outcome


# ---------------------------------------------------------------- the engine
def test_identities_that_hold_reduce_to_zero_by_both_routes():
    for text in ("cos(θ)^2 + sin(θ)^2 - 1", "cos(2*θ) - (1 - 2*sin(θ)^2)", "tan(θ) - sin(θ)/cos(θ)",
                 "sin(θ + φ) - (sin(θ)*cos(φ) + cos(θ)*sin(φ))", "(cos(φ)^2 - 1)/sin(φ) + sin(φ)"):
        E = T.parse(text)
        assert T.groebner_is_zero(E)[0] and T.weierstrass_is_zero(E)[0]
        res = T.is_zero(E)
        assert res.holds and "Weierstrass substitution: 0" in res.evidence


def test_a_reduction_is_shown_when_the_numerator_is_not_zero():
    res = T.is_zero(T.parse("λ*(cos(θ)^2 + sin(θ)^2) - λ"))
    assert res.holds
    assert res.evidence[0] != "numerator: `0`" and res.evidence[1].endswith("`0`")


def test_identities_that_fail_are_nonzero_by_both_routes():
    for text in ("cos(θ)^2 - sin(θ)^2 - 1", "sin(2*θ) - sin(θ)", "cos(φ)*sin(θ) - cos(θ)*sin(φ)", "r*λ"):
        E = T.parse(text)
        assert not T.groebner_is_zero(E)[0] and not T.weierstrass_is_zero(E)[0]
        assert not T.is_zero(E).holds


def test_a_denominator_vanishing_on_the_circles_is_an_error():
    with pytest.raises(ZeroDivisionError):
        T.is_zero(1 / (cθ**2 + sθ**2 - 1))


def test_routes_that_disagree_raise(monkeypatch):
    monkeypatch.setattr(T, "weierstrass_is_zero", lambda E: (False, ["broken"]))
    with pytest.raises(T.RoutesDisagree):
        T.is_zero(T.parse("cos(θ)^2 + sin(θ)^2 - 1"))


def test_routes_that_disagree_make_a_certificate_fail(monkeypatch):
    monkeypatch.setattr(T, "groebner_is_zero", lambda E: (False, ["broken", "broken"]))
    assert run_certificate(CERTIFICATES["S1"]).status == FAIL


def test_parse_reads_the_paper_notation():
    assert sp.expand(T.parse("λ^2 − r*sin(φ)") - (lam**2 - r * sφ)) == 0
    assert T.parse("(1, cos(θ), 0)") == sp.Matrix([1, cθ, 0])
    assert T.chain("V(1, 2, 3)\n= (1,\n 2, 3)") == [sp.Matrix([1, 2, 3])] * 2
    with pytest.raises(ValueError):
        T.parse("sin(r)")


def test_vectors_parallel_and_proportional():
    v, w = sp.Matrix([cθ, sθ, 0]), sp.Matrix([2 * cθ * cφ, 2 * sθ * cφ, 0])
    assert T.parallel(v, w).holds and not T.parallel(v, sp.Matrix([sθ, cθ, 0])).holds
    assert T.positively_proportional(w, v, T.hypotheses(1)).holds
    assert not T.positively_proportional(w, v, T.hypotheses(-1)).holds


def test_signs_by_inspection():
    H = T.hypotheses(-1)
    assert T.sign(T.parse("(r - 1)*cos(φ)/(cos(θ)^2*sin(φ)^2 + cos(φ)^2)"), H)[0] == 1
    assert T.sign(T.parse("1 - sin(θ)^2"), H)[0] == 1          # = cos²θ after rewriting
    assert T.sign(T.parse("cos(θ) - sin(θ)"), H)[0] is None
    assert T.sign(sp.Integer(0), H)[0] is None
    t = sp.Symbol("t")
    res = T.has_sign(lam - 1, 1, H.assume(t, -1, 1 / (1 - lam)), witness=-1 / t)
    assert res.holds and not T.has_sign(lam - 1, -1, H.assume(t, -1, 1 / (1 - lam)), witness=-1 / t).holds


# ---------------------------------------------------------------- the certificates
def test_s2_erratum_is_the_word_smaller():
    assert outcome("S2", **altered("S2", "order", "smaller", "larger")).status == PASS
    wrong = [c for c in outcome("S2").printed if not c.holds]
    assert len(wrong) == 1 and "smaller" in wrong[0].statement
    assert any("t_c is larger than t_b" in c.statement and c.holds for c in outcome("S2").corrected)


def test_s4_erratum_is_cos_theta_for_cos_phi_in_l_734():
    fixed = altered("S4", "cross_chain", "cross(V(-sin(φ)*sin(θ), cos(θ), 0), C*q0)",
                    "cross(V(-sin(φ)*sin(θ), cos(φ), 0), C*q0)")
    assert outcome("S4", **fixed).status == PASS
    assert any("conclusion" in c.statement and c.holds for c in outcome("S4").printed)


def test_s8_erratum_is_e_y_for_e_z_in_the_c_formula():
    fixed = altered("S8.1", "trilinear_c", "cross(u0, ey)", "cross(u0, ez)")
    assert outcome("S8.1", **fixed).status == PASS
    wrong = [c for c in outcome("S8.1").printed if not c.holds]
    assert len(wrong) == 1 and "ũ(1)·p(1) = " in wrong[0].evidence[-1]


def test_s9_erratum_keeps_the_proposition():
    o = outcome("S9.1")
    wrong = [c for c in o.printed if not c.holds]
    assert len(wrong) == 1 and "P(k+1)" in wrong[0].statement
    assert any("no aca" in c.statement and c.holds for c in o.printed)
    assert any("no cac" in c.statement and c.holds for c in o.corrected)
