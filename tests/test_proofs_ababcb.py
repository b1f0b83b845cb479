"""Every certificate of Sections 2-3 turns FAIL when the printed statement it checks
is altered (a coefficient, a digit, an inequality direction, a sign, a branch); a
printed condition is read whole, and altering its wording shows as a failing printed
check with the altered text."""
import pytest

from certify.run.runner import CERTIFICATES, Context, ERRATUM, FAIL, PASS, altered, load_all, run_certificate

load_all()
CTX = Context()          # shared quantities computed once for the whole module


def outcome(id, **overrides):
    return run_certificate(CERTIFICATES[id], CTX, overrides or None)


EXPECTED = {"M1": PASS, "M2": PASS, "M3": PASS, "M4": PASS, "T1": PASS, "T2": PASS, "T3": PASS, "T4": PASS,
            "T5": PASS, "T6": PASS, "T7": PASS, "T8": PASS, "T9": PASS, "T10": PASS, "T11": PASS, "T12": PASS,
            "T13": PASS, "T14": PASS, "T15": PASS, "T16": ERRATUM, "T17": ERRATUM, "T18": PASS, "T19": PASS,
            "T20": PASS, "T21": PASS, "T22": PASS, "T23": PASS, "T24": ERRATUM, "T25.1": PASS}

MUTATIONS = {
    "M1": lambda: altered("M1", "B", "-r", "r"),
    "M2": lambda: altered("M2", "equality", "AC = CA", "AB = BA"),
    "M3": lambda: altered("M3", "C", "-r", "-r/2"),
    "M4": lambda: {"time_factor": "beta/alpha"},
    "T1": lambda: altered("T1", "M_text", "7*r + 9", "7*r + 8"),
    "T2": lambda: altered("T2", "cp_text", "74*r + 25", "74*r + 24"),
    "T3": lambda: {"det_text": "-r^6"},
    "T4": lambda: altered("T4", "three_real_when", "<", ">"),
    "T5": lambda: {"digits": "0.11385"},
    "T6": lambda: altered("T6", "below", "Δ_cp <", "Δ_cp >"),
    "T7": lambda: {"repeated": "positive"},
    "T8": lambda: altered("T8", "P0_text", "41*r^10", "40*r^10"),
    "T9": lambda: altered("T9", "U", "16*λ", "15*λ"),
    "T10": lambda: altered("T10", "d", "372*r^5", "373*r^5"),
    "T11": lambda: altered("T11", "amd", "1024*r^6", "1023*r^6"),
    "T12": lambda: altered("T12", "P1_text", "35", "36"),
    "T13": lambda: {"digits": "0.13146"},
    "T14": lambda: {"at_r1": "upper"},
    "T15": lambda: altered("T15", "quartic", "102*r^2", "20*r^2"),
    "T16": lambda: altered("T16", "c", "(r^2 - 10*r + 1)", "(r^2 - 9*r + 1)"),
    "T17": lambda: altered("T17", "c", "16*", "-16*"),
    "T18": lambda: altered("T18", "c", "16*", "-16*"),
    "T19": lambda: altered("T19", "c", "16*", "-16*"),
    "T20": lambda: {"digits": "0.11377"},
    "T21": lambda: altered("T21", "inequality", "q <", "q >"),
    "T22": lambda: altered("T22", "p3t4", "x + ", "-x + "),
    "T23": lambda: altered("T23", "P2_text", "25*r^8", "24*r^8"),
    "T24": lambda: altered("T24", "a", "1024*r^6", "-1024*r^6"),
    "T25.1": lambda: altered("T25.1", "U", "16*λ", "-16*λ"),
}


@pytest.mark.parametrize("id", sorted(EXPECTED))
def test_certificate_as_printed(id):
    assert outcome(id).status == EXPECTED[id]


@pytest.mark.parametrize("id", sorted(MUTATIONS))
def test_altered_statement_fails(id):
    assert outcome(id, **MUTATIONS[id]()).status == FAIL


def test_every_certificate_of_this_part_is_mutated():
    ours = {c.id for c in CERTIFICATES.values() if c.module in ("proofs.model", "proofs.ababcb")}
    assert ours == set(MUTATIONS) == set(EXPECTED)


def test_t16_erratum_shows_the_corrected_sign():
    o = outcome("T16")
    assert any("c < 0 for r > 5-2√6" in c.statement and c.holds for c in o.corrected)
    assert any("5-2√6 < r < 1" in e for c in o.corrected for e in c.evidence)


# the wording of every printed condition: a relation or a word altered so that the
# statement is false; it must FAIL and show the altered text in a failing printed check
WORDING = [
    ("M2", "equality", "=", "≠"),
    ("M3", "separating", ">", "<"),
    ("M3", "approaching", "<", ">"),
    ("T3", "det_sign", "positive", "negative"),
    ("T3", "det_sign", "positive", "zero"),
    ("T4", "three_real_when", "<", "≤"),                 # Δ_cp = 0 is a double root, not three
    ("T6", "below", "r < r*", "r > r*"),
    ("T6", "above", "≥", ">"),                           # Δ_cp vanishes at (7-2√10)/3 > r*
    ("T6", "above", "Δ_cp ≥", "Δ_cp ≤"),
    ("T7", "repeated", "negative", "non-negative"),
    ("T8", "positive", "λ > 0", "λ < 0"),
    ("T8", "positive", "5-2√6", "1"),                    # the lower branches end at r*
    ("T14", "at_r1", "middle", "lower"),
    ("T14", "at_r2", "upper", "middle"),
    ("T16", "below", "c > 0", "c < 0"),
    ("T16", "above", "c > 0", "c ≥ 0"),                  # the stated correction no longer applies
    ("T20", "position", "larger", "smaller"),
    ("T21", "inequality", "5-2√6", "1"),
    ("T21", "inequality", "q < 0", "q ≥ 0"),
    ("T23", "position", "above", "below"),
    ("T24", "upper", "|q|>1", "|q|<1"),                  # (|q|≥1 holds with q = f'(x₊): not an alteration that must fail)
    ("T24", "lower", "|q|<1", "|q|>1"),
    ("T24", "stable_when", "|q|<1", "|q|≤1"),
    ("T24", "q", "(c x₊ + d)/(c x₋ + d)", "(c x₊ + d)/(c x₋ - d)"),
]


@pytest.mark.parametrize("id,name,old,new", WORDING)
def test_altered_wording_fails_and_shows_the_text(wording_fails, id, name, old, new):
    wording_fails(outcome, id, name, old, new)


@pytest.mark.parametrize("id,name,text", [
    ("T4", "three_real_when", "Δ_cp << 0"),              # not a relation
    ("T6", "below", "Δ_cp < 0 for r ≤ r*"),              # a closed end is not read
    ("T7", "repeated", "small"),                         # not a sign word
    ("T8", "positive", "μ > 0 for 0 < r < 5-2√6"),       # an unknown name
    ("T14", "at_r1", "central"),                         # not a branch
    ("T16", "below", "c > 0 for r < 5-2√6 for r > 0"),   # two ranges
    ("T24", "upper", "|q| > 2"),                         # not a multiple of |q| - 1: not evaluated
    ("M2", "equality", "AD = DA"),                       # a matrix that is not printed
])
def test_unread_wording_fails_with_the_reason(unread_fails, id, name, text):
    unread_fails(outcome, id, name, text)


@pytest.mark.parametrize("id,name,old,new", WORDING)
def test_the_wording_tests_alter_a_printed_condition(id, name, old, new):
    assert isinstance(CERTIFICATES[id].printed[name], str) and old in CERTIFICATES[id].printed[name]


def test_every_certificate_reading_a_condition_has_a_wording_test():
    readers = {"M2", "M3", "T3", "T4", "T6", "T7", "T8", "T14", "T16", "T20", "T21", "T23", "T24"}
    assert {id for id, *_ in WORDING} == readers


def test_t24_with_the_one_stated_correction_passes():
    """One misprint: q displayed at l. 493 inverted.  With q = (cx₋+d)/(cx₊+d) = f'(x₊)
    every sentence of l. 495-505 holds as printed.  Keeping the displayed q instead takes
    three corrections (every relation reversed); one of them alone keeps it false, and
    then the one stated correction of q no longer makes it true."""
    assert outcome("T24", **altered("T24", "q", "(c x₊ + d)/(c x₋ + d)", "(c x₋ + d)/(c x₊ + d)")).status == PASS
    reversed_ = {"upper": "|q|<1", "lower": "|q|>1", "stable_when": "|q|>1"}
    assert outcome("T24", **reversed_).status == PASS
    for name, text in reversed_.items():
        o = outcome("T24", **{name: text})
        assert o.status == FAIL and not o.printed[0].holds


def test_t24_erratum_is_one_misprint():
    o = outcome("T24")
    assert o.status == ERRATUM and o.kind == "misprint" and "l. 493" in o.misprint
    assert len([c for c in o.printed if not c.holds]) == 1


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
