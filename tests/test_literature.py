"""T26 (l. 323-325): 5-2√6 is also the (upper stability) threshold of (ab)^3(cb)^3."""
import pytest

from proofs import literature as T
from tests.shared import as_printed


@pytest.fixture(scope="module")
def outcome():
    return as_printed("T26")


def test_t26_names_the_condition(outcome):
    text = "\n".join(e for c in outcome.printed for e in c.evidence) + "\n".join(outcome.evidence)
    assert "(r^2 - 10r + 1)" in text
    assert "upper branch, x₊: feasible on ]1/10, ≈0.101021[" in text


def test_expand_pattern():
    assert T.expand_pattern("(ab)^3(cb)^3") == "abababcbcbcb"
    assert T.expand_pattern("(ab)^2(cb)^2") == "ababcbcb"
    assert T.expand_pattern("ababcb") == "ababcb"
    with pytest.raises(ValueError):
        T.expand_pattern("(ax)^2")
