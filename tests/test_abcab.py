"""T27 (l. 513-515): abcab has no self-similar datum; and the helpers shared with T26."""
import flint
import pytest
import sympy as sp

from certify.poly import parse
from certify.runner import CERTIFICATES, FAIL, PASS, load_all, run_certificate
from proofs import abcab as T

load_all()
Q = flint.fmpq


@pytest.fixture(scope="module")
def outcome():
    return run_certificate(CERTIFICATES["T27"])


def test_t27_passes(outcome):
    assert outcome.status == PASS, [(c.statement, c.evidence) for c in outcome.printed if not c.holds]


def test_t27_evidence_names_the_region(outcome):
    text = "\n".join(outcome.evidence)
    assert "upper branch, x₊: candidate realised on ]0, ≈0.171573[" in text
    assert "upper x₊ r = 1/10: aba" in text          # the dynamic cross-check


def test_t27_region_ends_exactly_at_3_minus_2_sqrt2():
    """Where abcab's candidate realises a, b: upper and middle branch, x₊, r in ]0, 3-2√2[
    (c vanishes at 3-2√2 and changes sign)."""
    from certify.algebraic import Algebraic
    c = T.candidate("abcab")
    feas, _ = T.prefix_requirements("abcab", 2, c.q0, c.steps, c.q0_other)
    an = T.Analysis(c)
    for q in feas:
        an.impose(q)
    end = Algebraic.surd(3, -2, 2)
    live = {(R.branch, R.fixed_point): R for R in an.regions if R.pieces}
    assert set(live) == {(0, "x₊"), (1, "x₊")}
    for R in live.values():
        intervals = [p for p in R.pieces if not p.is_point]
        assert intervals[0].lo == 0 and intervals[-1].hi == end
        assert not any(p.is_point and p.lo == end for p in R.pieces)


@pytest.mark.parametrize("overrides", [
    {"matrix": "BACAB"},                             # a letter of the matrix name
    {"matrix": "ABCAB"},
    {"next": "c", "other": "a"},                     # the claimed collision order reversed
    {"word": "acbab"},                               # a different word: its matrix BABCA is not BACBA
])
def test_t27_mutations_fail(overrides):
    assert run_certificate(CERTIFICATES["T27"], overrides=overrides).status == FAIL


def test_candidate_of_ababcb_matches_the_paper():
    """The generic candidate reproduces the paper's u (l. 279) and its position map
    (l. 291-300, up to a common factor modulo cp)."""
    c = T.candidate("ababcb")
    u_printed = parse("r*(16*λ - r^4 + 8*r^3 + 2*r^2 + 8*r - 1)/(2*(r + 1)*(-r^3 + 6*r^2 - r + 4*λ))")
    diff = sp.fraction(sp.cancel(T.expr_of(c.q0[1]) - u_printed))[0]
    assert T.mod_cp(sp.expand(diff), c.cp) == 0
    a, b, cc, d = (parse(e) for e in (
        "-64*r^2*(r^4 - 8*r^3 - 2*r^2 - 8*r + 1)*λ + 1024*r^6",
        "256*r^2*(r^2 - 6*r + 1)*λ^2 - 4*r^2*(r - 1)^2*(r - 3)^2*(r^4 - 8*r^3 - 2*r^2 - 8*r + 1)*λ"
        " + 64*r^6*(r^4 - 8*r^3 + 18*r^2 + 5)",
        "16*(r - 1)^2*(r + 1)^2*(r^2 - 10*r + 1)*λ",
        "-64*(r^4 - 8*r^3 - 2*r^2 - 8*r + 1)*λ^2 + (r^10 - 18*r^9 + 101*r^8 - 216*r^7 + 66*r^6"
        " + 372*r^5 + 594*r^4 - 24*r^3 + 253*r^2 - 114*r + 9)*λ"))
    A, B, C, D = c.abcd
    for e in (a * B - b * A, a * C - cc * A, a * D - d * A, cc * D - d * C):
        assert T.mod_cp(sp.expand(e), c.cp) == 0


def test_prefix_requirements_of_ababcb_are_the_papers():
    """Step 3 of the paper (l. 449-486): the velocity inequalities q2(t1), q1(t2),
    q2(t3), q3(t4), q2(t5) and the distances p3(t4); our list has p1(t6) (> 0 implies
    p1(t5) > 0 by concavity) where the paper lists p1(t5)."""
    c = T.candidate("ababcb")
    reqs, _ = T.prefix_requirements("ababcb", 6, c.q0, c.steps)
    assert [q.name for q in reqs] == ["u = q_2(0)", "x", "q_2(t_1)", "q_1(t_2)", "q_2(t_3)", "q_3(t_4)",
                                      "p_3(t_4)", "q_2(t_5)", "p_1(t_6)"]
    u = T.expr_of(c.q0[1])
    printed = {"q_2(t_1)": "u - (1+r)/2", "q_1(t_2)": "(1+r)/2*u - (r-1)^2/4",
               "q_2(t_3)": "(r-1)^2/4*u - (r^3 - 5*r^2 - 5*r + 1)/8"}
    for q in reqs:
        if q.name in printed:
            diff = sp.cancel(T.expr_of(q.G[0]) - parse(printed[q.name]).subs(sp.Symbol("u"), u))
            assert diff == 0, q.name


def test_position_map_check_catches_a_wrong_map():
    c = T.candidate("abcab")
    a, b, cc, d = c.abcd
    T.check_position_map(c.steps, c.abcd, T._cp_ring(c.cp))
    with pytest.raises(ArithmeticError):
        T.check_position_map(c.steps, (2 * a, b, 2 * cc, d), T._cp_ring(c.cp))


def test_matrix_of_name():
    """BACBA is the matrix of abcab; since AC = CA (l. 240) it is also that of abacb."""
    for word in ("abcab", "abacb"):
        assert (T.matrix_of_name("BACBA") - T.candidate(word).M).applyfunc(sp.cancel) == sp.zeros(3, 3)
    assert (T.matrix_of_name("BABCA") - T.candidate("abcab").M).applyfunc(sp.cancel) != sp.zeros(3, 3)


def test_simplest_between():
    assert T.simplest_between(Q(1, 3), Q(1, 2)) == Q(1, 2)
    assert T.simplest_between(Q(31, 100), Q(32, 100)) == Q(5, 16)
    assert T.simplest_between(Q(0), Q(1, 10)) == 0


def test_fast_critical_values_agree_with_the_engine():
    """The factor-by-factor critical values are the engine's (same set)."""
    c = T.candidate("abcab")
    reqs, _ = T.prefix_requirements("abcab", 2, c.q0, c.steps)
    fp = c.fixed_points()["x₊"]
    for q in reqs[:3]:
        cond = T.condition(q, c.cp, fp if q.has_x else None)
        ours = T.critical_values(c.spectrum, cond, 0, 1)
        theirs = c.spectrum.critical_values(cond, 0, 1)
        assert len(ours) == len(theirs) and all(a == b for a, b in zip(ours, theirs))
