"""Every certificate of Sections 2-3 turns FAIL when the printed statement it checks
is altered (a coefficient, a digit, an inequality direction, a sign, a branch)."""
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
    "M2": lambda: {"pair": "AB"},
    "M3": lambda: altered("M3", "C", "-r", "-r/2"),
    "M4": lambda: {"time_factor": "beta/alpha"},
    "T1": lambda: altered("T1", "M_text", "7*r + 9", "7*r + 8"),
    "T2": lambda: altered("T2", "cp_text", "74*r + 25", "74*r + 24"),
    "T3": lambda: {"det_text": "-r^6"},
    "T4": lambda: {"three_real_when": ">"},
    "T5": lambda: {"digits": "0.11385"},
    "T6": lambda: {"below": ">"},
    "T7": lambda: {"repeated_sign": 1},
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
    "T21": lambda: {"direction": ">"},
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
    assert any("c < 0 for 5-2√6 < r < 1" in c.statement and c.holds for c in o.corrected)
