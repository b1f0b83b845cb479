"""Sections 2-3 beyond their mutants (tests/proofs/test_mutants.py): the errata and their stated
corrections, and the checks that rest only on what could fail."""
from certify.run.runner import ERRATUM, FAIL, PASS, altered
from tests.shared import outcome


def test_t16_erratum_shows_the_corrected_sign():
    o = outcome("T16")
    assert any("c < 0 for r > 5-2√6" in c.statement and c.holds for c in o.corrected)
    assert any("5-2√6 < r < 1" in e for c in o.corrected for e in c.evidence)


def test_t24_with_the_two_stated_corrections_passes():
    """Two misprints: q displayed at l. 493 inverted, and d^2 + 4bc for (a-d)^2 + 4bc at l. 495.
    With q = (cx₋+d)/(cx₊+d) = f'(x₊) every sentence of l. 495-505 holds as printed.  Keeping
    the displayed q instead takes three corrections (every relation reversed); one of them alone
    keeps it false, and then the one stated correction of q no longer makes it true."""
    q_one = altered("T24", "q_is_one", "d^2 + 4*b*c", "(a - d)^2 + 4*b*c")
    assert outcome("T24", **altered("T24", "q", "(c x₊ + d)/(c x₋ + d)", "(c x₋ + d)/(c x₊ + d)"),
                   **q_one).status == PASS
    reversed_ = {"upper": "|q|<1", "lower": "|q|>1", "stable_when": "|q|>1"}
    assert outcome("T24", **reversed_, **q_one).status == PASS
    for name, text in reversed_.items():
        o = outcome("T24", **{name: text})
        assert o.status == FAIL and not o.printed[0].holds


def test_t24_erratum_is_two_misprints():
    o = outcome("T24")
    assert o.status == ERRATUM and o.kind == "misprint" and [m[:6] for m in o.misprint] == ["l. 493", "l. 495"]
    assert len([c for c in o.printed if not c.holds]) == 2
    with_q = outcome("T24", **altered("T24", "q", "(c x₊ + d)/(c x₋ + d)", "(c x₋ + d)/(c x₊ + d)"))
    assert with_q.status == ERRATUM and [m[:6] for m in with_q.misprint] == ["l. 495"]


def test_t16_with_the_stated_correction_passes():
    assert outcome("T16", **altered("T16", "above", "c > 0", "c < 0")).status == PASS


def test_t10_rests_on_checks_that_can_fail():
    """The collision word and p_2(t6) = 0 hold by construction: evidence, not checks."""
    o = outcome("T10")
    assert not any("collisions applied" in c.statement or "p_2(t6) = 0" in c.statement for c in o.printed)
    assert any("by construction" in e for e in o.evidence)


def test_t3_rests_on_checks_that_can_fail():
    """cp(0) = -det M holds for every 3×3 matrix: evidence, not a check."""
    o = outcome("T3")
    assert not any("cp(0" in c.statement for c in o.printed)
    assert any("every 3×3 matrix" in e for e in o.evidence)
