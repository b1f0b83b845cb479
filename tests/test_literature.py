"""T26 (l. 323-325): 5-2√6 is also the (upper stability) threshold of (ab)^3(cb)^3."""
import pytest

from certify.run.runner import CERTIFICATES, FAIL, PASS, load_all, run_certificate
from proofs import literature as T

load_all()


@pytest.fixture(scope="module")
def outcome():
    return run_certificate(CERTIFICATES["T26"])


def test_t26_passes(outcome):
    assert outcome.status == PASS, [(c.statement, c.evidence) for c in outcome.printed if not c.holds]


def test_t26_names_the_condition(outcome):
    text = "\n".join(e for c in outcome.printed for e in c.evidence) + "\n".join(outcome.evidence)
    assert "(r^2 - 10r + 1)" in text
    assert "upper branch, x₊: feasible on ]1/10, ≈0.101021[" in text


@pytest.mark.parametrize("overrides", [
    {"pattern": "(ab)^2(cb)^2"},                  # another pattern (its threshold is 3-2√2)
    {"threshold": (5, -2, 7)},                    # a digit of the threshold
    {"quadratic": "r^2 - 10*r + 2"},              # a coefficient of the quadratic
])
def test_t26_mutations_fail(overrides):
    assert run_certificate(CERTIFICATES["T26"], overrides=overrides).status == FAIL


def test_expand_pattern():
    assert T.expand_pattern("(ab)^3(cb)^3") == "abababcbcbcb"
    assert T.expand_pattern("(ab)^2(cb)^2") == "ababcbcb"
    assert T.expand_pattern("ababcb") == "ababcb"
    with pytest.raises(ValueError):
        T.expand_pattern("(ax)^2")
