"""The kernel's arithmetic in Q(r0)[λ] (certify_kernel.field) and the obligations that use it:
signs of a condition on the eigenvalue branches at an algebraic r (`branch_signs_at`, T7: the
double eigenvalue at r0 = (7 − 2√10)/3) and a sign table's query that includes its critical
values (`signs_query` with include_points, T3).  A true fact from the run is accepted; a changed
sign, r0 or coefficient of cp is rejected with a message naming the obligation."""
from __future__ import annotations

import copy
import json
from fractions import Fraction as F

import pytest

import certify_kernel
from certify.run import report, runner
from certify_kernel.field import AtR0
from certify_kernel.sturm import Algebraic


@pytest.fixture(scope="module")
def data() -> dict:
    results, _ = runner.run_selected(["T3", "T7"])
    return json.loads(report.render_certificates(results))


def cert(data: dict, cid: str) -> dict:
    return copy.deepcopy(next(c for c in data["certificates"] if c["id"] == cid))


def point_fact(c: dict) -> dict:
    return next(ob for ob in c["obligations"] if ob["kind"] == "branch_signs_at")


def rejected(c: dict, oid: str) -> str:
    out = certify_kernel.verify_certificate(c)
    assert not out["ok"], "the tampered certificate was accepted"
    assert f"obligation {oid} " in out["failure"], out["failure"]
    return out["failure"]


def test_sturm_tarski_over_q_sqrt2():
    """λ² − r at r = √2: roots ±2^(1/4); λ − 1 is positive at the larger, negative at the
    smaller; (λ − r)²(λ + 1) has the double root √2 (listed twice), where λ² − 2 vanishes."""
    A = AtR0(Algebraic([F(-2), F(0), F(1)], 1, 2))
    P = [[F(0), F(-1)], [], [F(1)]]
    assert [A.taq([[F(-1)], [F(1)]], P, a, b) for a, b in A.roots(P)[1]] == [1, -1]
    P2 = A.mul([[F(0), F(0), F(1)], [F(0), F(-2)], [F(1)]], [[F(1)], [F(1)]])
    branches = A.branches(P2)
    assert len(branches) == 3 and branches[0] == branches[1]
    assert [A.taq([[F(-2)], [], [F(1)]], P2, a, b) for a, b in A.roots(P2)[1]] == [0, -1]
    # a leading coefficient vanishing at r0: (r² − 2)λ³ + λ − r is λ − √2 there
    assert len(A.branches([[F(0), F(-1)], [F(1)], [], [F(-2), F(0), F(1)]])) == 1


def test_the_run_records_signs_at_algebraic_r_that_the_kernel_verifies(data):
    kinds = {ob["kind"] for c in data["certificates"] for ob in c["obligations"]}
    assert "branch_signs_at" in kinds and "unsupported" not in kinds
    for cid in ("T3", "T7"):
        out = certify_kernel.verify_certificate(cert(data, cid))
        assert out["ok"] and not out["unsupported"], out
    assert certify_kernel.verify_certificate(cert(data, "T7"))["verified"] == 4


def test_a_changed_sign_at_r0_is_rejected(data):
    c = cert(data, "T7")
    ob = point_fact(c)
    k = next(i for i, s in enumerate(ob["signs"]) if s in (1, -1))
    ob["signs"][k] = -ob["signs"][k]
    assert "the sign at r0" in rejected(c, ob["id"])


def test_a_changed_interval_end_of_r0_is_rejected(data):
    c = cert(data, "T7")
    ob = point_fact(c)
    assert ob["r"]["poly"] == ["3", "-14", "3"]
    ob["r"]["hi"] = "5"                 # two roots of 3r² − 14r + 3 in ]lo, 5]
    assert "roots" in rejected(c, ob["id"])


def test_a_changed_coefficient_of_cp_at_r0_is_rejected(data):
    c = cert(data, "T7")
    ob = point_fact(c)
    coef, exps = ob["cp"][0]
    ob["cp"][0] = [str(F(coef) + 1), exps]
    rejected(c, ob["id"])


def test_a_changed_sign_at_a_critical_value_of_a_query_is_rejected(data):
    c = cert(data, "T3")
    ob = next(ob for ob in c["obligations"] if ob["kind"] == "signs_query" and ob["include_points"])
    ob["result"] = sorted(ob["result"] + [0], key=str)
    assert "the signs on branch" in rejected(c, ob["id"])


def synthetic(result: list) -> dict:
    """cp = λ − r, g = λ² − 2 over ]1, 2[: the cells ]1, √2[ (g < 0) and ]√2, 2[ (g > 0); at the
    critical value √2, g = 0 on the branch."""
    parts = {"N0": [["-2", [0, 0]], ["1", [0, 2]]], "D0": [["1", [0, 0]]]}
    cp = [["-1", [1, 0]], ["1", [0, 1]]]
    sqrt2 = {"poly": ["-2", "0", "1"], "lo": "1", "hi": "3/2"}
    table = {"id": "X:1", "kind": "sign_table", "cp": cp, "parts": parts, "ends": ["1", sqrt2, "2"],
             "samples": ["5/4", "3/2"], "signs": [[-1], [1]]}
    query = {"id": "X:2", "kind": "signs_query", "table": "X:1", "branch": 0, "lo": None, "hi": None,
             "include_points": True, "result": result}
    point = {"id": "X:3", "kind": "branch_signs_at", "cp": cp, "parts": parts, "r": sqrt2, "signs": [0]}
    return {"id": "X", "obligations": [table, query, point],
            "subclaims": [{"statement": "g changes sign at √2", "obligations": ["X:1", "X:2", "X:3"]}]}


def test_the_sign_at_a_critical_value_is_computed():
    assert certify_kernel.verify_certificate(synthetic([-1, 0, 1]))["verified"] == 1
    assert "the signs on branch 0" in rejected(synthetic([-1, 1]), "X:2")
    c = synthetic([-1, 0, 1])
    c["obligations"][2]["signs"] = ["nonzero"]
    assert "the sign at r0 is 0" in rejected(c, "X:3")


@pytest.mark.parametrize("eps, signs", [(F(1, 10 ** 15), [-1, -1, -1]), (-F(1, 10 ** 15), [1, 1, -1])])
def test_the_kernel_agrees_with_the_engine_at_a_double_root(eps, signs):
    """cp = (λ + 2)(λ² − 2rλ + 1/2) has the double root √2/2 at r = √2/2: λ − r ∓ 10⁻¹⁵ there,
    signed by the engine (balls, exact zero tests) and by the kernel (Tarski queries in
    Q(√2/2)[λ]); the obligation is the engine's record of its answer."""
    import sympy as sp

    from certify.algebra import facts
    from certify.algebra.algebraic import Algebraic as EngineAlgebraic
    from certify.algebra.branches import Condition, Spectrum
    from certify.algebra.poly import lam, r
    S = Spectrum(sp.expand((lam + 2) * (lam ** 2 - 2 * r * lam + sp.Rational(1, 2))))
    rc = EngineAlgebraic.surd(0, sp.Rational(1, 2), 2)
    cond = Condition.of("λ - r - ε", lam - r - sp.Rational(eps.numerator, eps.denominator))
    answer = S.sign_at_point(cond, rc)
    assert answer == signs
    ob = {"id": "X:1", **facts.point_signs(answer, S, cond, rc)}
    c = {"id": "X", "obligations": [ob], "subclaims": [{"statement": "the signs at √2/2", "obligations": ["X:1"]}]}
    assert certify_kernel.verify_certificate(c)["verified"] == 1
    ob["signs"][0] = -ob["signs"][0]
    assert "branch 0: the sign at r0" in rejected(c, "X:1")
