"""T27 (l. 513-515): abcab has no self-similar datum."""
import flint
import pytest
import sympy as sp

from certify.dynamics.words import candidate
from certify.patterns.feasibility import Analysis, prefix_requirements
from proofs import section3_remarks as T
from tests.shared import as_printed

Q = flint.fmpq


@pytest.fixture(scope="module")
def outcome():
    return as_printed("T27")


def test_t27_evidence_names_the_region(outcome):
    text = "\n".join(outcome.evidence)
    assert "upper branch, x₊: candidate realised on ]0, ≈0.171573[" in text
    assert "upper x₊ r = 1/10: aba" in text          # the dynamic cross-check


def test_t27_region_ends_exactly_at_3_minus_2_sqrt2():
    """Where abcab's candidate realises a, b: upper and middle branch, x₊, r in ]0, 3-2√2[
    (c vanishes at 3-2√2 and changes sign)."""
    from certify.algebra.algebraic import Algebraic
    c = candidate("abcab")
    feas, _ = prefix_requirements("abcab", 2, c.q0, c.steps, c.q0_other)
    an = Analysis(c)
    for q in feas:
        an.impose(q)
    end = Algebraic.surd(3, -2, 2)
    live = {(R.branch, R.fixed_point): R for R in an.regions if R.pieces}
    assert set(live) == {(0, "x₊"), (1, "x₊")}
    for R in live.values():
        intervals = [p for p in R.pieces if not p.is_point]
        assert intervals[0].lo == 0 and intervals[-1].hi == end
        assert not any(p.is_point and p.lo == end for p in R.pieces)


def test_matrix_of_name():
    """BACBA is the matrix of abcab; since AC = CA (l. 240) it is also that of abacb."""
    for word in ("abcab", "abacb"):
        assert (T.matrix_of_name("BACBA") - candidate(word).M).applyfunc(sp.cancel) == sp.zeros(3, 3)
    assert (T.matrix_of_name("BABCA") - candidate("abcab").M).applyfunc(sp.cancel) != sp.zeros(3, 3)




def test_the_committed_census_summary_is_read_from_the_head_of_the_file():
    # committed_census reads reports/census.json only up to the end of its summary: the same
    # object as parsing the whole file
    import json
    from pathlib import Path
    path = Path(__file__).resolve().parents[2] / "reports" / "census.json"
    if not path.exists():
        pytest.skip("no committed census")
    assert T.committed_census() == json.loads(path.read_text(encoding="utf-8"))["census"]


# T28.3, T28.4 (l. 1214-1215): the threshold of collapse and the stable patterns, read on the committed census
COMMITTED_CENSUS = T.census_records        # before any test replaces it


def _census_with(change):
    """The committed census's (summary, records) with ``change`` applied to a copy of the records."""
    import copy
    summary, records = COMMITTED_CENSUS()
    records = copy.deepcopy(records)
    change(records)
    return summary, records


def _record(records, word):
    return next(r for r in records if r["word"] == word)


def test_t29_t30_pass_on_the_committed_census():
    o29, o30 = as_printed("T28.3"), as_printed("T28.4")
    assert o29.status == "PASS" and o30.status == "PASS"
    text = "\n".join(e for c in o29.printed for e in c.evidence)
    assert "reached by abcb" in text and "undecided points at or above r_exist: none" in text


def test_t29_fails_on_an_undecided_point_above_r_exist(monkeypatch):
    """Not certified while a point above r_exist is undecided: the census as it was before this
    engine (87 words with such points) would FAIL."""
    def add(records):
        _record(records, "abacbacbacbacbacb")["result"]["undecided"] = ["upper x₊ at ≈0.2679491924: u = q_2(0)"]
    monkeypatch.setattr(T, "census_records", lambda: _census_with(add))
    o = T.threshold_of_collapse(**T.PRINTED_T28_3)
    assert o.status == "FAIL"
    assert any("abacbacbacbacbacb: upper x₊ at ≈0.2679491924" in e for c in o.printed for e in c.evidence)


def test_t29_fails_on_a_feasible_end_above_r_exist(monkeypatch):
    """A feasible set reaching above r_exist in another word (its end moved to 1/5)."""
    end = {"digits": "0.2", "exact": "1/5", "interval": ["1/5", "1/5"], "minimal_polynomial": "5r - 1"}

    def move(records):
        rec = next(r for r in records if r["feasible"] and r["word"] != "abcb")
        rec["result"]["feasible"][0]["pieces"][0]["hi"] = end
    monkeypatch.setattr(T, "census_records", lambda: _census_with(move))
    assert T.threshold_of_collapse(**T.PRINTED_T28_3).status == "FAIL"


def test_t30_fails_on_an_asymmetric_stable_word_or_a_doubtful_point(monkeypatch):
    def stable(records):
        _record(records, "ababcb")["stable"] = True

    def doubtful(records):
        _record(records, "abacbcbabcabcb")["result"]["undecided"] = ["upper x₊ at ≈0.1: p_3(t_1)"]

    def abcb(records):                     # (ab)^1(cb)^1 is not of the family (n ≥ 2): abcb stable is a failure
        _record(records, "abcb")["stable"] = True
    for change in (stable, doubtful, abcb):
        monkeypatch.setattr(T, "census_records", lambda change=change: _census_with(change))
        assert T.stable_patterns(**T.PRINTED_T28_4).status == "FAIL"
