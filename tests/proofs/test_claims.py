"""Every certificate names a claim of ../shared/CLAIMS.md and a range of lines that a
reader finds in the paper's source (arXiv:2411.10324v1, the LaTeX file)."""
from __future__ import annotations

import re

import pytest

from certify.run import runner
from tests.paper import NO_SOURCE, PAPER, ROOT

CLAIMS = PAPER.parent.parent / "CLAIMS.md"          # ../shared/CLAIMS.md beside the paper's folder
LINES = re.compile(r"l\. (\d+)(?:-(\d+))?((?:, \d+(?:-\d+)?)*)")


def ranges(line: str) -> list[tuple[int, int]]:
    """``l. 617-630, 686-690`` as [(617, 630), (686, 690)]."""
    assert LINES.fullmatch(line), f"not a line range: {line!r}"
    out = []
    for part in line[3:].split(", "):
        lo, _, hi = part.partition("-")
        out.append((int(lo), int(hi or lo)))
    return out


def test_every_paper_line_is_a_range():
    for cert in runner.select():
        for lo, hi in ranges(cert.line):
            assert 1 <= lo <= hi, (cert.id, cert.line)


@pytest.mark.skipif(not PAPER.is_file(), reason=NO_SOURCE)
def test_every_range_lies_in_the_source():
    n = len(PAPER.read_text(encoding="utf-8").splitlines())
    for cert in runner.select():
        for _lo, hi in ranges(cert.line):
            assert hi <= n, (cert.id, cert.line, n)


@pytest.mark.skipif(not CLAIMS.is_file(), reason=f"the claims list is not beside this checkout ({CLAIMS})")
def test_every_certificate_names_a_listed_claim():
    """A certificate of the paper names a claim of CLAIMS.md; one of the part "Beyond the paper"
    (B: issue 39) names no claim and cites the closing questions it answers (l. 1219-1234)."""
    from certify.run.report import part_of
    ids = set(re.findall(r"^\| ([LMTSN]\d+) \|", CLAIMS.read_text(encoding="utf-8"), re.M))
    for cert in runner.select():
        if part_of(cert.id) == "Beyond the paper":
            assert cert.id.split(".")[0] not in ids and all(1219 <= lo <= hi <= 1234 for lo, hi in ranges(cert.line)), \
                (cert.id, cert.line)
        else:
            assert cert.id.split(".")[0] in ids, cert.id


def test_every_erratum_row_shows_what_was_printed_and_what_is_true():
    """In the real run, each false printed check of an ERRATUM has a certified correction
    that reads differently (the errata show the change without diffing)."""
    from certify.run import report
    errata = [c.id for c in runner.select() if c.id in {"T16", "T17", "T24", "S2", "S4", "S8.1", "S9.1"}]
    results, _ = runner.run_selected(errata, jobs=2)
    for cert, outcome in results:
        assert outcome.status == runner.ERRATUM, cert.id
        assert outcome.kind in runner.ERRATUM_KINDS and outcome.misprint, cert.id
        pairs = report.erratum_pairs(outcome)
        assert pairs, cert.id
        for wrong, fixes in pairs:
            assert fixes, (cert.id, wrong.statement)
            for fix in fixes:
                assert runner.holds(fix) and fix.statement != wrong.statement, (cert.id, fix.statement)
                assert report.changes(wrong.statement, fix.statement), (cert.id, fix.statement)


def test_the_committed_report_says_each_erratum_kind_and_each_disagreement_reason():
    import json
    data = json.loads((ROOT / "reports" / "report.json").read_text(encoding="utf-8"))
    for c in data["certificates"]:
        if c["status"] == runner.ERRATUM:
            assert c["erratum"]["kind"] in runner.ERRATUM_KINDS and c["erratum"]["misprint"], c["id"]
        if c["status"] == runner.OBSERVED and c["agrees"] is False:
            assert c["reason"] and "\n" not in c["reason"], c["id"]
    errors = data["errors_of_the_paper"]
    assert len({i for e in errors for i in e["certificates"]}) == data["summary"][runner.ERRATUM]


def test_the_committed_report_shows_no_python_values():
    """Evidence is written for a reader: no reprs of lists of booleans, numpy scalars or None."""
    text = (ROOT / "reports" / "REPORT.md").read_text(encoding="utf-8")
    for leak in ("np.float64", "[True", "[False", ": True", ": False", "None", "['"):
        assert leak not in text, leak
