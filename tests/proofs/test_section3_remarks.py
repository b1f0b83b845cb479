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
