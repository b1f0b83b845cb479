"""certify.witnesses: what a certificate records for the kernel (certificates.json), and which
check names it."""
from certify import witnesses as W
from certify.algebra import trig as T
from certify.run import Check, captured, kept_witnesses, witness

H = T.hypotheses(1)                      # θ ∈ ]0, π/2[, sin φ > 0, cos φ > 0, 0 < r < 1


def test_a_decided_sign_records_its_witness_once_and_its_check_names_it():
    with W.recording("X") as rec:
        res = T.has_sign(T.sθ * T.cφ + T.cθ, 1, H)     # has_sign reads T.sign: one witness, not two
        check = Check("sin θ cos φ + cos θ > 0", res)
    assert [ob["kind"] for ob in rec.items] == ["signed"] and rec.items[0]["sign"] == 1
    assert res.witnesses == check.witnesses == ["X:1"]


def test_nothing_is_recorded_outside_a_recording_in_a_quiet_block_or_for_an_undecided_sign():
    assert T.has_sign(T.sθ, 1, H).witnesses is None
    with W.recording("X") as rec:
        with W.quiet():
            T.has_sign(T.sθ, 1, H)
        undecided = T.has_sign(T.cθ - T.sθ, 1, H)
        assert not undecided.holds and undecided.witnesses == []
        assert Check("no witness", True).witnesses == []
    assert rec.items == []


def test_the_same_witness_has_one_id_and_a_check_lists_its_witnesses_in_recording_order():
    with W.recording("X"):
        a, b, again = T.has_sign(T.sθ, 1, H), T.has_sign(T.sφ * T.cθ, 1, H), T.has_sign(T.sθ, 1, H)
        assert again.witnesses == a.witnesses == ["X:1"] and b.witnesses == ["X:2"]
        check = Check("both", a.holds and b.holds, witnesses=b.witnesses + again.witnesses)
    assert check.witnesses == ["X:1", "X:2"]


def test_kept_witnesses_are_recorded_again_by_the_certificate_that_reads_them():
    with W.recording("lemmas"), captured() as kept:      # a shared quantity's lemma keeps its witnesses
        T.sign(T.sθ, H)
    with W.recording("X") as rec:
        assert kept_witnesses(kept) == ["X:1"] and rec.items[0]["kind"] == "signed"
        assert witness("factors", words=["ab"], factors=[[1, 1]]) == ["X:2"]
    assert witness("factors", words=["ab"], factors=[[1, 1]]) == []
