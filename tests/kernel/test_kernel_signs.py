"""Strict signs over several variables (certify_kernel.signs): a witness (the engine's `signed`
fact, docs/verify.md) is accepted when every step checks, and every tampering is rejected: the
statement is then not verified (or, when the witness is right and the statement wrong, the
kernel finds it false).  The witnesses are written here by hand for

    E = (2 − sin²θ)(r² − 3r + 3) cos θ / (−cos φ)   on θ ∈ ]0, π/2[, φ ∈ ]π/2, π[, r ∈ ]0, 1[,

whose numerator has terms of both signs: 2 − sin²θ ≡ 1 + cos²θ modulo the circle, r² − 3r + 3
has no root in ]0, 1[, cos θ > 0 and −cos φ > 0 there."""
from __future__ import annotations

import copy
from fractions import Fraction as F

import pytest

from tests.kernel.kernel_support import outcome

NAMES = ["r", "cos θ", "sin θ", "cos φ"]
E = "(2 - sin(θ)^2)*(r^2 - 3*r + 3)*cos(θ)/(-cos(φ))"
BINDERS = "forall θ in ]0, π/2[, φ in ]π/2, π[, r in ]0, 1["


def mono(r=0, c=0, s=0, cphi=0):
    return (r, c, s, cphi)


def mul(p: dict, q: dict) -> dict:
    out: dict = {}
    for a, x in p.items():
        for b, y in q.items():
            k = tuple(i + j for i, j in zip(a, b))
            out[k] = out.get(k, 0) + x * y
    return {k: v for k, v in out.items() if v}


def terms(p: dict) -> list:
    return [[str(F(v)), list(k)] for k, v in sorted(p.items())]


TWO_MINUS_S2 = {mono(): 2, mono(s=2): -1}
ONE_PLUS_C2 = {mono(): 1, mono(c=2): 1}
QUADRATIC = {mono(r=2): 1, mono(r=1): -3, mono(): 3}
COS_T = {mono(c=1): 1}
COS_P = {mono(cphi=1): 1}
NUM = mul(mul(TWO_MINUS_S2, QUADRATIC), COS_T)


def witness() -> dict:
    return {"kind": "signed", "vars": NAMES,
            "expr": {"num": terms(NUM), "den": terms({mono(cphi=1): -1})},
            "num": {"form": terms(NUM), "constant": "1", "factors": [
                {"poly": terms(TWO_MINUS_S2), "mult": 1, "how": "form", "form": terms(ONE_PLUS_C2)},
                {"poly": terms(QUADRATIC), "mult": 1, "how": "r"},
                {"poly": terms(COS_T), "mult": 1, "how": "form", "form": terms(COS_T)}]},
            "den": {"form": terms({mono(cphi=1): -1}), "constant": "-1", "factors": [
                {"poly": terms(COS_P), "mult": 1, "how": "form", "form": terms(COS_P)}]},
            "sign": 1}


def decided(w, claim: str = "> 0", binders: str = BINDERS, expr: str = E) -> str:
    return outcome(f"{binders}: {expr} {claim}", witnesses=w if isinstance(w, list) else [w])


NO_WITNESS = "not verified: no witness shows the sign of an atom"


def test_a_witness_that_checks_is_accepted():
    assert decided(witness()) == "verified"
    assert decided(witness(), "< 0").startswith("failed: Z9.1: the statement file says it holds; the kernel finds "
                                                "it false")
    assert outcome(f"{BINDERS}: {E} < 0", verdict="refuted", witnesses=[witness()]) == "verified"


def test_without_a_witness_the_sign_is_not_shown():
    assert decided([]) == NO_WITNESS
    assert decided([], "< 0") == NO_WITNESS


def test_terms_of_one_strict_sign_need_no_witness():
    assert outcome(f"{BINDERS}: r*cos(θ) - cos(φ) > 0") == "verified"
    assert outcome(f"{BINDERS}: r*cos(θ)*cos(φ) < 0") == "verified"
    assert outcome("forall θ in ]0, π[, r in ]0, 1[: cos(θ)^2 + r > 0") == "verified"


def test_a_sign_by_inspection_of_terms_of_mixed_signs_is_refused():
    assert outcome(f"{BINDERS}: cos(θ) - sin(θ) > 0") == NO_WITNESS                    # false at θ = π/3
    assert outcome(f"{BINDERS}: r - 1/2 > 0") == NO_WITNESS
    assert outcome("forall θ in ]0, π[, r in ]0, 1[: cos(θ) > 0") == NO_WITNESS            # cos θ of either sign
    assert outcome("forall θ in ]0, π[, r in ]0, 1[: cos(θ)^2 > 0") == NO_WITNESS          # 0 at π/2: not strict
    assert outcome("forall θ in ]0, π[, r in ]0, 1[: cos(θ) + r > 0") == NO_WITNESS         # < 0 near θ = π


def tampered(edit) -> dict:
    w = copy.deepcopy(witness())
    edit(w)
    return w


TAMPERINGS = {
    "another expression (not the kernel's E)": lambda w: w["expr"]["num"].__setitem__(0, ["7", w["expr"]["num"][0][1]]),
    "a form not congruent to the numerator": lambda w: w["num"]["form"].__setitem__(0, ["7", w["num"]["form"][0][1]]),
    "factors that do not multiply to the form": lambda w: w["num"]["factors"][1]["poly"].__setitem__(
        0, ["4", [0, 0, 0, 0]]),
    "the constant's sign flipped": lambda w: w["den"].__setitem__("constant", "1"),
    "a multiplicity changed": lambda w: w["num"]["factors"][2].__setitem__("mult", 3),
    "a factor's form not congruent to it": lambda w: w["num"]["factors"][0].__setitem__(
        "form", terms({mono(): 1, mono(c=2): 2})),
    "a factor's form of mixed signs (its own terms)": lambda w: w["num"]["factors"][0].__setitem__(
        "form", terms(TWO_MINUS_S2)),
    "a factor read as a polynomial in r that is not one": lambda w: w["num"]["factors"][0].__setitem__("how", "r"),
    "a factor in r given a form of mixed signs": lambda w: w["num"]["factors"][1].update(
        how="form", form=terms(QUADRATIC)),
    "a variable that is not the kernel's": lambda w: w.__setitem__("vars", ["r", "cos θ", "sin θ", "cos ψ"]),
    "the variables permuted": lambda w: w.__setitem__("vars", ["r", "sin θ", "cos θ", "cos φ"]),
    "a coefficient that is not a number": lambda w: w["num"].__setitem__("constant", "one"),
    "the factors missing": lambda w: w["num"].pop("factors"),
    "a factorisation of another form (−n, consistent in itself)": lambda w: w["num"].update(
        form=terms({k: -v for k, v in NUM.items()}), constant="-1"),
    "the denominator's part missing": lambda w: w.pop("den"),
}


@pytest.mark.parametrize("name", list(TAMPERINGS))
def test_every_tampering_of_the_witness_is_rejected(name):
    """Rejected whichever sign the statement claims: the witness shows no sign at all."""
    assert decided(tampered(TAMPERINGS[name])) == NO_WITNESS
    assert decided(tampered(TAMPERINGS[name]), "< 0") == NO_WITNESS


def test_a_witness_of_another_atom_is_passed_over_and_a_good_one_used():
    other = tampered(TAMPERINGS["another expression (not the kernel's E)"])
    assert decided([other, "not a witness", {"num": 1}, witness()]) == "verified"


def test_a_factor_in_r_with_a_root_in_the_unit_interval_is_rejected():
    """(r − 1/2)(r − 1)·cos θ > 0 is false for r > 1/2; a witness calling (r − 1/2)(r − 1) a factor
    without root in ]0, 1[ (its root 1 is at the end) is refused."""
    quad = {mono(r=2): 1, mono(r=1): F(-3, 2), mono(): F(1, 2)}
    num = mul(quad, COS_T)
    w = {"vars": NAMES, "expr": {"num": terms(num), "den": terms({mono(): 1})},
         "num": {"form": terms(num), "constant": "1", "factors": [
             {"poly": terms(quad), "mult": 1, "how": "r"}, {"poly": terms(COS_T), "mult": 1, "how": "form",
                                                            "form": terms(COS_T)}]},
         "den": {"form": terms({mono(): 1}), "constant": "1", "factors": []}}
    assert decided(w, expr="(r^2 - 3*r/2 + 1/2)*cos(θ)") == NO_WITNESS
    quad_ok = {mono(r=2): 1, mono(r=1): -3, mono(): 2}                         # (r − 1)(r − 2): no root in ]0, 1[
    num_ok = mul(quad_ok, COS_T)
    w_ok = copy.deepcopy(w)
    w_ok["expr"]["num"] = w_ok["num"]["form"] = terms(num_ok)
    w_ok["num"]["factors"][0]["poly"] = terms(quad_ok)
    assert decided(w_ok, expr="(r^2 - 3*r + 2)*cos(θ)") == "verified"


@pytest.mark.parametrize("binders, says", [
    ("forall θ in [0, π/2[, φ in ]π/2, π[, r in ]0, 1[", "open interval"),       # sin 0 = 0
    ("forall θ in ]0, π/2], φ in ]π/2, π[, r in ]0, 1[", "open interval"),       # cos π/2 = 0
    ("forall θ in ]0, π/2[, φ in ]π/2, π[, r in [0, 1[", "open interval"),       # r = 0
    ("forall θ in ]0, π/2[, φ in ]π/2, π[, r in ]0, 1]", "open interval"),       # a factor in r may vanish at 1
    ("forall θ in ]0, π/2[, φ in ]π/2, π[, r in ]0, 2[", "inside [0, 1]"),       # r² − 3r + 3 checked on ]0, 1[ only
    ("forall θ in ]0, π/2[, φ in ]π/2, π[, r in ]-1, 1[", "inside [0, 1]"),
    ("forall θ in ]0, π/3[, φ in ]π/2, π[, r in ]0, 1[", "only the quadrants"),
])
def test_hypotheses_come_only_from_open_intervals_where_they_hold(binders, says):
    got = decided(witness(), binders=binders)
    assert got.startswith("failed: Z9.1 (test:1): ") and says in got, got


def test_over_several_variables_only_conjunctions_of_strict_signs_and_identities():
    assert outcome(f"{BINDERS}: cos(θ)^2 + sin(θ)^2 = 1 and r*cos(θ) > 0") == "verified"
    assert outcome(f"{BINDERS}: cos(θ)^2 = 1 and r*cos(θ) > 0").startswith("failed: Z9.1: the statement file says")
    for body, says in (("r*cos(θ) ≥ 0", "only strict signs"), ("r > 0 or cos(θ) > 0", "a conjunction")):
        got = outcome(f"{BINDERS}: {body}")
        assert got.startswith("failed: Z9.1 (test:1): ") and says in got, got
