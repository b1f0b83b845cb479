"""Derivations (certify_kernel.derive, docs/verify.md): the run writes, per sub-claim, how its
obligations give it; the kernel checks each and that the sub-claim's verdict is what it
concludes; every tampering of a derivation is rejected with a message naming the sub-claim or
the obligation.  The file is made from T5 (a root count), T8 (a printed relation read on sign tables), T14
(sign changes on branches: covers), T17 (signs on a branch over an interval) and S2 (signs by
inspection)."""
from __future__ import annotations

import json

import pytest

import certify_kernel
from certify import obligations
from certify.run import Check
from tests.shared import certificate_of, certificates_file

IDS = ["T5", "T8", "T14", "T17", "S2"]


@pytest.fixture(scope="module")
def data() -> dict:
    return certificates_file(IDS)


cert = certificate_of


def sub(c: dict, start: str) -> dict:
    return next(s for s in c["subclaims"] if s["statement"].startswith(start))


def rejected(c: dict, *names: str) -> str:
    """The kernel rejects ``c``, naming each of ``names``; its message."""
    out = certify_kernel.verify_certificate(c)
    assert not out["ok"], "the tampered certificate was accepted"
    for name in names:
        assert name in out["failure"], out["failure"]
    return out["failure"]


def where(c: dict, s: dict) -> str:
    return f"sub-claim {c['subclaims'].index(s) + 1} ({s['statement'][:20]}"


def change(c: dict) -> tuple[dict, dict, dict]:
    """T14's "a-d changes sign at r1": the sub-claim, and its covers left and right of r1."""
    s = sub(c, "a-d changes sign at r1")
    left, right = s["derivation"]["of"]
    return s, left, right


def test_the_run_writes_derivations_that_the_kernel_checks(data):
    for c in data["certificates"]:
        out = certify_kernel.verify_certificate(c)
        assert out["ok"], out["failure"]
        assert 0 < out["derived"] <= out["verified"], c["id"]
    c = cert(data, "T14")
    assert certify_kernel.verify_certificate(c)["derived"] == 3
    s, left, right = change(c)
    assert left["rule"] == right["rule"] == "cover" and left["signs"] == [-right["signs"][0]]
    assert json.dumps(left["hi"]) == json.dumps(right["lo"])       # the two cells meet at r1


def test_a_printed_relation_on_sign_tables_is_a_cover_of_its_range(data):
    """T8, "all three eigenvalues: λ > 0 for 0 < r < 5-2√6": a cover of ]0, 5-2√6[ with the sign
    +1 on each branch; the facts it reads belong to it, not to the check made before it."""
    c = cert(data, "T8")
    s = sub(c, "all three eigenvalues")
    covers = s["derivation"]["of"]
    assert [(d["rule"], d["branch"], d["lo"], d["signs"]) for d in covers] == [("cover", k, "0", [1]) for k in range(3)]
    assert not set(s["obligations"]) & set(sub(c, "three distinct real eigenvalues")["obligations"])


def test_a_removed_cell_of_a_cover_is_rejected(data):
    """One cover of ]0, r2[ from the two cells beside r1, the second removed: it does not reach r2."""
    c = cert(data, "T14")
    s, left, right = change(c)
    s["derivation"] = {**left, "hi": right["hi"], "signs": [-1, 1]}
    assert "not end at hi" in rejected(c, where(c, s))


def test_a_join_without_the_sign_at_it_is_rejected(data):
    """The two cells tile ]0, r2[ but leave r1 out: the sign there is needed."""
    c = cert(data, "T14")
    s, left, right = change(c)
    s["derivation"] = {**left, "hi": right["hi"], "signs": [-1, 1], "queries": left["queries"] + right["queries"]}
    assert "leave out" in rejected(c, where(c, s))


def test_a_query_on_the_wrong_branch_is_rejected(data):
    c = cert(data, "T14")
    s, left, _ = change(c)
    left["branch"] = 0
    rejected(c, where(c, s), left["queries"][0], "not 0")


def test_a_query_of_another_condition_is_rejected(data):
    """T17: a-d > 0 on the upper branch below r1 read from the table of b."""
    c = cert(data, "T17")
    s = sub(c, "a-d, b, c > 0")
    first, second = s["derivation"]["of"][:2]
    first["queries"] = first["queries"] + second["queries"]
    rejected(c, where(c, s), second["queries"][0], "another condition")


def test_a_result_outside_the_allowed_signs_is_rejected(data):
    c = cert(data, "T14")
    s, left, _ = change(c)
    left["signs"] = [-left["signs"][0]]
    assert "derivation concludes false" in rejected(c, where(c, s))


def test_a_shifted_interval_end_is_rejected(data):
    c = cert(data, "T17")
    s = sub(c, "exactly one positive fixed point")
    cover = s["derivation"]["of"][0]
    cover["hi"] = "1/10"                              # 5-2√6 ≈ 0.1010
    rejected(c, where(c, s), cover["queries"][0], "not end at hi")


def test_an_altered_expected_value_is_rejected(data):
    c = cert(data, "T5")
    s = sub(c, "P0 has exactly 1 root")
    s["derivation"]["facts"][0]["count"] += 1
    assert "derivation concludes false" in rejected(c, where(c, s))


def test_a_fact_the_sub_claim_does_not_name_is_rejected(data):
    c = cert(data, "S2")
    s = next(s for s in c["subclaims"] if s.get("derivation", {}).get("rule") == "expect")
    other = next(ob["id"] for ob in c["obligations"] if ob["id"] not in s["obligations"] and ob["kind"] == "identity")
    s["derivation"]["facts"][0] = {"id": other, "holds": True}
    rejected(c, where(c, s), other, "does not name")


def test_a_flipped_verdict_is_rejected(data):
    c = cert(data, "S2")
    s = next(s for s in c["subclaims"] if s.get("derivation") and s["counts"])
    s["holds"] = not s["holds"]
    rejected(c, where(c, s), "its derivation concludes")


def test_a_false_identity_is_derived_false_and_a_negated_one_gets_no_derivation():
    """The engine keeps a derivation only when it concludes the check's verdict."""
    fact = {"kind": "identity", "vars": ["r"], "circles": [], "lhs": [{"num": [["1", [1]]], "den": [["1", [0]]]}],
            "rhs": [{"num": [["1", [0]]], "den": [["1", [0]]]}], "holds": False}
    with obligations.recording("X"):
        obligations.emit(fact)
        false = Check("r = 1 identically", False)
        obligations.emit({**fact, "vars": ["λ"]})
        negated = Check("r is not 1 identically", True)
    assert false.derivation == {"rule": "expect", "facts": [{"id": "X:1", "holds": True}]}
    assert negated.obligations == ["X:2"] and negated.derivation is None
