"""The committed findings of Section 5 (reports/section5-orbits.json, `certify identify
--section5`) and the explanations the certificates N2, N5, N6 draw from them
(certify/run/section5_orbits.py): each committed word re-decided exactly at its r."""
from functools import cache

import pytest

from certify.run import section5_orbits as s5
from certify.run.files import load_findings
from certify.run.runner import holds

FOUND = load_findings(s5.FINDINGS)


@cache
def explained(claim: str) -> tuple:
    """The explanations of ``claim`` from the committed findings, computed once for this module
    (each re-decides every word and re-checks every class: seconds)."""
    return tuple(s5.explanations(claim, s5.FINDINGS))


def _first_attracting():
    for claim, entries in FOUND["claims"].items():
        for e in entries:
            for w in e["words"]:
                if w["kind"] == "attracting" and w["window"]:
                    return claim, e, w
    raise AssertionError("no attracting word with a window in the findings")


def test_the_committed_findings_follow_the_format():
    assert FOUND["schema"] == s5.SCHEMA and FOUND["version"] == s5.VERSION
    assert set(FOUND["claims"]) == set(s5.PLAN)
    for claim, entries in FOUND["claims"].items():
        assert [e["r"] for e in entries] == [str(__import__("fractions").Fraction(r)) for r, _ in s5.PLAN[claim]]
        for e in entries:
            assert sum(w["count"] for w in e["words"]) + e["unsettled"] + e["breaks"] == e["orbits"]
            assert sum(e["classes"].values()) == e["orbits"] == len(e["classified"])
            for w in e["words"]:
                assert w["period"] == len(w["word"]) and w["kind"] in ("attracting", "saddle", "repelling", "")
                assert w["certified"] <= w["count"] and (w["certified"] == 0 or w["kind"] == "attracting")


def test_the_committed_findings_follow_their_schema_and_hold_no_timing():
    import json
    from pathlib import Path
    jsonschema = __import__("pytest").importorskip("jsonschema")
    schema = json.loads((Path(s5.__file__).parents[1] / "schemas" / "section5-orbits.schema.json").read_text())
    jsonschema.validate(FOUND, schema)
    assert "seconds" not in json.dumps(FOUND)
    bad = json.loads(json.dumps(FOUND))
    bad["seconds"] = 1.0
    with __import__("pytest").raises(jsonschema.ValidationError):
        jsonschema.validate(bad, schema)


def test_the_classes_of_the_committed_findings_say_what_is_proved():
    """r = 3/10: island and attracting abacbabcbcabcb orbits; r = 0.173: the 122-letter word
    certified for ever for all 8; near r = 1 the (acb)^2(cab)^2 orbits are island orbits
    and no explanation reads "unexplained"."""
    entries = {(c, e["r"], e["collisions"]): e for c, es in FOUND["claims"].items() for e in es}
    e = entries[("N2", "3/10", 10_000)]
    assert e["classes"]["island"] > 0 and e["classes"]["attracting periodic"] > 0
    assert {o["word"] for o in e["classified"] if o["word"]} == {"abacbabcbcabcb"}
    e = entries[("N5", "173/1000", 100_000)]
    assert e["classes"]["attracting periodic"] == 8 and {len(o["word"]) for o in e["classified"]} == {122}
    for claim in s5.PLAN:
        for c in explained(claim):
            assert "unexplained" not in c.statement
    near_one = [c.statement for c in explained("N2") if "r = 999/1000" in c.statement]
    assert any("(acb)^2(cab)^2" in t.replace("acbacbcabcab", "(acb)^2(cab)^2") and "island orbits" in t
               for t in near_one), near_one


def test_a_committed_class_that_does_not_hold_fails():
    import json
    e = next(e for e in FOUND["claims"]["N2"] if e["r"] == "3/10")
    checks = s5.classes_check(e)
    assert checks and all(holds(c) for c in checks)
    wrong = json.loads(json.dumps(e))
    for o in wrong["classified"]:                      # an attracting orbit called an island orbit
        if o["class"] == "attracting periodic":
            o["class"], o["word"], o["rotation"] = "island", None, None
            break
    assert not all(holds(c) for c in s5.classes_check(wrong))
    late = json.loads(json.dumps(e))
    for o in late["classified"]:                       # the proof claimed from collision 0, before it holds
        if o["class"] == "attracting periodic":
            o["certified_from"] = 0
            break
    assert not all(holds(c) for c in s5.classes_check(late))


def test_every_committed_explanation_holds_exactly():
    for claim in s5.PLAN:
        checks = explained(claim)
        assert checks and all(holds(c) for c in checks), [c.statement for c in checks if not holds(c)]
        assert all(not c.counts for c in checks)          # ours, not the paper's claim: never a disagreement


def test_an_altered_word_fails():
    """A committed word altered into a near miss (its last letter): the explanation fails.
    (The word abcb and the r 1/10 are the committed mutants of N2, tests/proofs/test_mutants.py;
    all three edits: the slow test below.)"""
    claim, e, w = _first_attracting()
    assert any("an attracting periodic orbit of the reduction" in c.statement for c in explained(claim))
    found = s5.load((s5.FINDINGS, {"word": "abacbabcbcabca"}), claim)
    entry = next(e for e in found["claims"][claim] if e["words"])
    assert entry["words"][0]["word"] == "abacbabcbcabca"
    holds_, text, _ = s5.decide(entry, entry["words"][0])
    assert not holds_ and "abacbabcbcabca" in text


@pytest.mark.slow
def test_an_altered_word_or_r_fails():
    claim, e, w = _first_attracting()
    found = s5.explanations(claim, s5.FINDINGS)
    assert any("an attracting periodic orbit of the reduction" in c.statement for c in found)
    for edits in ({"word": "abcb"}, {"r": "1/10"}, {"word": "abacbabcbcabca"}):
        checks = s5.explanations(claim, (s5.FINDINGS, edits))
        assert not all(holds(c) for c in checks), edits


def test_inside_is_exact_at_the_ends():
    import flint
    window = {"lo": {"exact": None, "interval": ["11/50", "221/1000"], "digits": "0.2200"},
              "hi": {"exact": "1", "interval": None, "digits": "1"}}
    assert s5._inside(flint.fmpq(3, 10), window)
    assert not s5._inside(flint.fmpq(1, 5), window)
    assert not s5._inside(flint.fmpq(2201, 10000), window)     # inside the isolating interval: undecided, not inside
    assert not s5._inside(flint.fmpq(1), window)


def test_missing_findings_fail():
    (c,) = s5.explanations("N2", "no-such-findings.json")
    assert not holds(c) and "identify --section5" in c.evidence[0]


def test_the_report_labels_an_explanation_as_ours_not_the_engines():
    from certify.run.report import _checks
    (c,) = [x for x in explained("N2") if "abacbabcbcabcb" in x.statement][:1]
    text = _checks("As printed", [c])
    assert "certified explanation, beside the observation" in text and "consistency check of the engine" not in text
