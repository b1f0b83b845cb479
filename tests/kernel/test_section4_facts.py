"""Section 4's recordings for the kernel: the lemmas on the six cones keep the facts they were
computed from (certify.obligations.captured), and a certificate that reads a lemma records them
again (certify.run.kept_facts); an identity at r = r₀ is an identity modulo r − r₀.  Each is
verified by the kernel, and a tampered one is rejected, naming it."""
from __future__ import annotations

import copy
import json
from fractions import Fraction

import pytest
import sympy as sp

import certify_kernel
from certify import obligations
from certify.algebra import facts
from certify.algebra.poly import r
from certify.dynamics import cones as RC
from certify.run import identity_modulo_facts, kept_facts, report, runner
from proofs.section4_1_reduction_theorem import SECTION2_K


def as_certificate(cid: str, data: list[dict]) -> dict:
    """One sub-claim resting on the obligations ``data``, as the kernel reads a certificate."""
    obs = [{"id": f"{cid}:{k + 1}", **ob} for k, ob in enumerate(data)]
    return {"id": cid, "status": "PASS", "obligations": obs,
            "subclaims": [{"role": "printed", "statement": "s", "holds": True, "counts": True,
                           "obligations": [ob["id"] for ob in obs]}]}


def rejected(c: dict, oid: str) -> None:
    out = certify_kernel.verify_certificate(c)
    assert not out["ok"] and oid in out["failure"], out


@pytest.fixture(scope="module")
def cones():
    with obligations.recording("X") as rec:     # a certificate's recording around the lemmas
        steps = RC.steps(SECTION2_K)
    assert rec.items == [] and rec.pending == []   # the lemmas record apart, and keep their facts
    return steps


def test_the_lemmas_on_the_cones_keep_facts_the_kernel_verifies(cones):
    for st in cones.values():
        assert st.holds and st.motion.holds
        assert all(c.facts for c in st.checks) and st.motion.facts, st.label
        kinds = {ob["kind"] for ob in RC.facts([st], motion=True)}
        assert kinds <= {"identity", "signed"} and "signed" in kinds
    c = as_certificate("S11", RC.facts(cones.values(), motion=True))
    out = certify_kernel.verify_certificate(c)
    assert out["ok"] and out["verified"] == 1, out["failure"]


def test_a_tampered_fact_of_a_lemma_is_rejected(cones):
    c = as_certificate("S11", RC.facts([cones[("a", 1)]], motion=True))
    ob = next(ob for ob in c["obligations"] if ob["kind"] == "signed")
    ob["sign"] = -ob["sign"]
    rejected(c, ob["id"])
    c = as_certificate("S11", RC.facts([cones[("c", -1)]]))
    ob = next(ob for ob in c["obligations"] if ob["kind"] == "identity" and ob["holds"])
    coef, exps = ob["rhs"][0]["num"][0] if ob["rhs"][0]["num"] else ob["lhs"][0]["num"][0]
    side = "rhs" if ob["rhs"][0]["num"] else "lhs"
    ob[side][0]["num"][0] = [str(Fraction(coef) + 1), exps]
    rejected(c, ob["id"])


def test_a_check_records_the_kept_facts_again(cones):
    st = cones[("b", -1)]
    with obligations.recording("S") as rec:
        first = kept_facts(RC.facts([st]))
        again = kept_facts(RC.facts([st]))          # a fact a check took is given to the next one that keeps it
    assert first and first == again and set(first) <= {ob["id"] for ob in rec.items}
    assert rec.pending == []


def test_an_identity_at_a_rational_r_is_one_modulo_r_minus_r0():
    K = sp.Matrix([[-r, 0, 0], [(1 + r) / 2, 1, 0], [0, 0, 1]])
    at = K.subs(r, sp.Rational(1, 3)) * 6
    with obligations.recording("S6") as rec:
        ids = identity_modulo_facts(r - sp.Rational(1, 3), (True, at, 6 * K), var=r)
    ob = rec.items[0]
    assert ids == [ob["id"]] and ob["modulo"]["var"] == "r"
    c = as_certificate("S6", [{k: v for k, v in ob.items() if k != "id"}])
    assert certify_kernel.verify_certificate(c)["ok"]
    moved = copy.deepcopy(c)                       # the identity at another r
    moved["obligations"][0]["modulo"]["poly"] = [t if t[1] == [1] else [str(Fraction(t[0]) - 1), t[1]]
                                                 for t in moved["obligations"][0]["modulo"]["poly"]]
    rejected(moved, "S6:1")
    wrong = facts.identity(True, at + sp.ones(3, 3), 6 * K, r - sp.Rational(1, 3), r)
    rejected(as_certificate("S6", [wrong]), "S6:1")


@pytest.mark.slow
def test_the_section4_certificates_name_facts_the_kernel_verifies():
    """S6, S10, S11 rest on the lemmas on the cones: every sub-claim names obligations, all verified."""
    results, _ = runner.run_selected(["S6", "S10", "S11"])
    data = json.loads(report.render_certificates(results))
    for c in data["certificates"]:
        out = certify_kernel.verify_certificate(c)
        assert out["ok"], out["failure"]
        assert out["verified"] == len(c["subclaims"]), c["id"]
    s6 = next(c for c in data["certificates"] if c["id"] == "S6")
    ob = next(ob for ob in s6["obligations"] if ob.get("modulo", {}).get("var") == "r")
    ob["rhs"][0]["num"][0][0] = str(Fraction(ob["rhs"][0]["num"][0][0]) + 1)
    rejected(s6, ob["id"])
