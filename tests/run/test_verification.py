"""reports/kernel.json: the kernel's results read back when nothing they depend on changed, decided
again otherwise (certify/run/verification.py), and what the report says of them."""
from __future__ import annotations

import json

from certify.run import report, verification


def fake_results(text: str) -> dict:
    return {"digest": verification.digest(text), "verified": 1, "statements": 2,
            "certificates": {"T5": {"status": "PASS", "ok": True, "failure": "", "counted": 2, "verified": 1,
                                    "statements": {"T5.1": "", "T5.2": "undecided at r = 1/3"},
                                    "line": "T5: PASS, 1/2 statements verified"}}}


def test_the_results_are_read_back_when_the_digest_matches(tmp_path, monkeypatch):
    text = '{"format": "certify-certificates/2", "certificates": []}\n'
    calls = []
    monkeypatch.setattr(verification, "decide", lambda t, jobs=2: calls.append(t) or fake_results(t))
    first = verification.results_for(text, tmp_path)
    assert calls == [text] and json.loads((tmp_path / "kernel.json").read_text()) == first
    assert verification.results_for(text, tmp_path) == first and calls == [text]        # read back
    verification.results_for(text.replace("[]", "[ ]"), tmp_path)                      # another run: again
    assert len(calls) == 2
    verification.results_for(text, tmp_path, again=True)
    assert len(calls) == 3


def test_the_digest_follows_the_statements_and_the_kernel(tmp_path):
    (tmp_path / "1_x.txt").write_text("vars x\n", encoding="utf-8")
    a = verification.digest("{}", tmp_path)
    (tmp_path / "1_x.txt").write_text("vars y\n", encoding="utf-8")
    assert verification.digest("{}", tmp_path) != a
    assert verification.digest("{ }", tmp_path) != verification.digest("{}", tmp_path)


def test_what_the_report_says_of_the_kernel():
    data = fake_results("x")
    assert verification.cell(data, "T5") == "1/2 verified"
    assert verification.cell(data, "T6") == "—" and verification.cell(None, "T5") == "—"
    assert verification.why_not(data, "T5", "T5.1") == "" and "undecided" in verification.why_not(data, "T5", "T5.2")
    assert "**1/2 statements verified**" in report.kernel_line(data)
    assert "not run" in report.kernel_line(None)
    failed = {**data, "certificates": {"T5": {**data["certificates"]["T5"], "ok": False}}}
    assert verification.cell(failed, "T5") == "FAILED" and "The kernel rejects T5" in report.kernel_line(failed)
