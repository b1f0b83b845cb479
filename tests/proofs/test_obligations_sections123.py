"""Sections 1-3: the sub-claims whose verdicts were computed from facts now name them, the
independent kernel verifies them, and a tampered fact is rejected, naming its obligation
(the law's matrices of M1, the sign intervals of T3 and T16, the Gröbner eliminant of T12 as
an identity beside the resultant route, the modulus identity of T24); a check that rests on
something the kernel lacks names it (T27: the ball simulator)."""
from __future__ import annotations

import copy
import json
from fractions import Fraction

import pytest

import certify_kernel
from certify import obligations
from certify.run import report
from tests.shared import outcome, registry


def certificate_data(cid: str) -> dict:
    """The certificate ``cid`` as certificates.json holds it (run as printed)."""
    text = report.render_certificates([(registry()[cid], outcome(cid))])
    return json.loads(text)["certificates"][0]


def subclaim(c: dict, start: str) -> dict:
    return next(s for s in c["subclaims"] if s["statement"].startswith(start))


def obligation(c: dict, oid: str) -> dict:
    return next(ob for ob in c["obligations"] if ob["id"] == oid)


def verified(c: dict) -> int:
    out = certify_kernel.verify_certificate(c)
    assert out["ok"], out["failure"]
    return out["verified"]


def rejected(c: dict, oid: str) -> None:
    out = certify_kernel.verify_certificate(c)
    assert not out["ok"], "the tampered certificate was accepted"
    assert oid in out["failure"], out["failure"]


@pytest.mark.parametrize("cid", ["M1", "M3", "T4", "T10", "T12", "T16", "T20", "T24"])
def test_every_subclaim_is_independently_verified(cid):
    c = certificate_data(cid)
    assert all(s["obligations"] for s in c["subclaims"]), [s["statement"] for s in c["subclaims"]
                                                           if not s["obligations"]]
    assert verified(c) == len([s for s in c["subclaims"] if s["counts"]])


def test_m1_the_law_identity_is_the_printed_matrix():
    """Altering the printed B alters the obligation: the kernel refuses it as printed."""
    c = certificate_data("M1")
    s = subclaim(c, "the law for a collision of type b")
    ob = next(obligation(c, i) for i in s["obligations"] if obligation(c, i)["kind"] == "identity"
              and len(obligation(c, i)["lhs"]) == 9)
    entry = ob["rhs"][4]["num"]                      # B's entry (2,2), -r
    entry[0] = [str(-Fraction(entry[0][0])), entry[0][1]]
    rejected(c, ob["id"])


def test_t16_a_changed_sign_on_an_interval_is_rejected():
    c = certificate_data("T16")
    s = subclaim(c, "c < 0 for r > 5-2√6")
    assert s["role"] == "corrected" and s["obligations"]
    ob = next(obligation(c, i) for i in s["obligations"]
              if obligation(c, i)["kind"] == "sign_at" and obligation(c, i)["sign"] == -1)
    ob["sign"] = 1
    rejected(c, ob["id"])


def test_t3_a_changed_root_count_of_det_is_rejected():
    c = certificate_data("T3")
    s = subclaim(c, "det M is positive")
    ob = next(obligation(c, i) for i in s["obligations"] if obligation(c, i)["kind"] == "root_count")
    ob["count"] += 1
    rejected(c, ob["id"])


def test_t12_the_groebner_subclaim_names_the_eliminant_and_the_resultant():
    c = certificate_data("T12")
    s = subclaim(c, "Gröbner basis")
    kinds = sorted(obligation(c, i)["kind"] for i in s["obligations"])
    assert kinds == ["identity", "resultant"]
    bad = copy.deepcopy(c)
    ob = next(obligation(bad, i) for i in s["obligations"] if obligation(bad, i)["kind"] == "identity")
    coef, exps = ob["rhs"][0]["num"][0]
    ob["rhs"][0]["num"][0] = [str(Fraction(coef) + 1), exps]
    rejected(bad, ob["id"])


def test_t24_the_modulus_identity_is_checked():
    c = certificate_data("T24")
    s = subclaim(c, "so on the upper branch")
    ob = next(obligation(c, i) for i in s["obligations"] if obligation(c, i)["kind"] == "identity")
    coef, exps = ob["rhs"][0]["num"][0]
    ob["rhs"][0]["num"][0] = [str(-Fraction(coef)), exps]
    rejected(c, ob["id"])


def test_t27_names_what_the_dynamics_rests_on():
    c = certificate_data("T27")
    s = subclaim(c, "cross-check on the dynamics")
    reasons = [obligation(c, i).get("reason", "") for i in s["obligations"]]
    assert reasons and all("simulator" in why for why in reasons)


def test_gathered_again_names_a_fact_an_earlier_check_took():
    fact = {"kind": "compare", "a": "1", "b": "0", "sign": 1}
    with obligations.recording("X"):
        first = obligations.emit(fact)
        assert obligations.take() == [first]
        with obligations.gathered() as plain:
            obligations.emit(fact)
        with obligations.gathered(again=True) as again:
            obligations.emit(fact)
    assert plain == [] and again == [first]


def test_replaying_records_the_facts_at_every_call_and_keeps_nothing_outside_a_recording():
    """obligations.replaying: in one certificate's recording the first call runs and records its
    fact; in the next certificate's recording a call runs nothing and records the same fact
    again; a call outside a recording runs afresh and leaves nothing to replay (a memo filled
    there would replay no fact)."""
    runs: list = []
    fact = {"kind": "compare", "a": "2", "b": "1", "sign": 1}

    def compute(x):
        runs.append(x)
        obligations.emit(fact)
        return x * 2

    replayed = obligations.replaying(compute)
    assert replayed(3) == 6 and runs == [3]            # not recording: computed, nothing kept
    facts = []
    for cid in ("Y", "Z"):
        with obligations.recording(cid) as rec:
            assert replayed(3) == 6
            facts.append([rec.by_id[i]["sign"] for i in obligations.take()])
    assert runs == [3, 3] and facts == [[1], [1]]
