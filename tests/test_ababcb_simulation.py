"""T25.2: Theorem 3.1 on the particle dynamics, certified in ball arithmetic."""
import flint
import pytest

from proofs import ababcb_simulation as T
from certify.algebra.balls import precision
from tests.shared import as_printed


@pytest.fixture(scope="module")
def outcome():
    return as_printed("T25.2")


def test_t25_2_reports_how_the_orbits_leave(outcome):
    text = "\n".join(outcome.evidence)
    assert "upper branch, x + ε: leaves the pattern" in text
    assert "lower branch, v + ε: leaves the pattern" in text
    assert "(ababcb)^20" in text


def test_formulas_are_evaluated_exactly():
    """No float enters: 1/3 r at r = 1 is a ball of radius ~2^-prec around 1/3."""
    f = T.ball_function("r/3 + λ/7")
    with precision(300):
        val = f(flint.arb(1), flint.arb(0))
        assert val.contains(flint.arb(flint.fmpq(1, 3))) and val.rad() < flint.arb(2) ** -290


def test_self_similar_run_reaches_the_scalings():
    data = T.branch_data("ababcb", flint.fmpq(1, 20), {k: T.ball_function(v) for k, v in (
        ("u", T.U_PRINTED), ("v", T.V_PRINTED), ("a", T.A_PRINTED), ("b", T.B_PRINTED),
        ("c", T.C_PRINTED), ("d", T.D_PRINTED))})
    run, prec = T.self_similar_run(data["upper"], "ababcb", 5)
    q_ok, p_ok, _ = T.scaling_checks(run, data["upper"], "ababcb", 5, prec)
    assert run.word == "ababcb" * 5 and q_ok and p_ok
