"""Every phrase the report quotes from the paper is printed on the line it cites.

A quotation is a phrase in quotes after a citation ``l. N`` (tests/paper.py:
``quotations``): the errata's one-line summaries ("l. 436: Δ < 0 'until r = 1' …"), the
certificates' statements (T28 quotes Remark 3.3 on its line, l. 515) and every string of
the committed reports/report.json and reports/CENSUS.md.  The phrase is looked up, white space ignored, in the
plain text of the cited lines: of the source beside the checkout, else of the lines the
repository carries (tests/data/paper-lines.json), which must then be the source's own."""
from __future__ import annotations

import json
import re

import pytest

from certify.run import report, runner
from certify.run.files import REPORTS
from tests import paper, shared
from tests.shared import strings


def certificate_quotations():
    """(where, ranges, phrase) of the certificates' statements and printed inputs, and of
    the errata's summaries and checks as the certificates conclude them (run as printed)."""
    for cert in runner.select():
        for text in [cert.statement, *strings(cert.printed)]:
            for ranges, phrase in paper.quotations(text, cert.line):
                yield cert.id, ranges, phrase
        if cert.expect == runner.ERRATUM:
            o = shared.as_printed(cert.id)
            checks = [c.statement for c in o.printed + o.corrected] + [str(e) for c in o.printed for e in c.evidence]
            for text in [*report.slips(o), *checks]:
                for ranges, phrase in paper.quotations(text):
                    yield cert.id, ranges, phrase


def report_quotations():
    """(where, ranges, phrase) of every string of the committed reports/report.json, and of
    every line of reports/CENSUS.md."""
    doc = json.loads((REPORTS / "report.json").read_text(encoding="utf-8"))
    census = (REPORTS / "CENSUS.md").read_text(encoding="utf-8").splitlines()
    for where, texts in (("report.json", strings(doc)), ("CENSUS.md", census)):
        for text in texts:
            for ranges, phrase in paper.quotations(text):
                yield where, ranges, phrase


def test_every_phrase_a_certificate_quotes_is_on_the_line_it_cites():
    found = list(certificate_quotations())
    assert len(found) >= 6            # T17, T28 (twice), S2, S10 at least
    wrong = [(where, ranges, phrase) for where, ranges, phrase in found if not paper.found_on(phrase, ranges)]
    assert not wrong, wrong


def test_every_phrase_the_committed_report_quotes_is_on_the_line_it_cites():
    """Fails on a report written before a citation was corrected: `certify all` rewrites it."""
    found = list(report_quotations())
    assert len(found) >= 6
    wrong = [(where, ranges, phrase) for where, ranges, phrase in found if not paper.found_on(phrase, ranges)]
    assert not wrong, wrong


def docs_quotations():
    """(where, ranges, phrase) of the README and docs/*.md, outside code blocks (an example
    of code is not a quotation)."""
    for page in [paper.ROOT / "README.md", *sorted((paper.ROOT / "docs").glob("*.md"))]:
        fenced = False
        for n, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
            fenced ^= line.lstrip().startswith("```")
            if not fenced:
                for ranges, phrase in paper.quotations(line):
                    yield f"{page.name}:{n}", ranges, phrase


def test_every_phrase_the_docs_quote_is_on_the_line_they_cite():
    found = list(docs_quotations())
    assert len(found) >= 4             # T28, T16, T17, S2, S10 in docs/report.md at least
    wrong = [(where, ranges, phrase) for where, ranges, phrase in found if not paper.found_on(phrase, ranges)]
    assert not wrong, wrong


def test_a_quotation_on_the_next_line_is_caught():
    # T17's erratum once cited l. 437 for "until r = 1", which the source prints on l. 436
    assert paper.found_on("until r = 1", [(436, 436)])
    assert not paper.found_on("until r = 1", [(437, 437)])
    assert [p for _, p in paper.quotations("l. 437: Δ < 0 'until r = 1' misses (7-2√10)/3")] == ["until r = 1"]
    # a phrase quoted after the paper's (its correction) and a prime are not quotations
    assert [p for _, p in paper.quotations("l. 628: 'smaller' printed for 'larger', f'(x) and p'(0)")] == ["smaller"]
    # an ellipsis: the parts in order
    assert paper.found_on("t_c … smaller than t_b", [(628, 628)])
    assert not paper.found_on("smaller than t_b … t_c is negative", [(628, 628)])


def cited_lines() -> set[int]:
    """The lines the quotations of the certificates and of the committed report cite, and
    the line of Remark 3.3 that T28's tests read (tests/patterns/test_census.py)."""
    out = {515}
    for _, ranges, _ in [*certificate_quotations(), *report_quotations(), *docs_quotations()]:
        out |= {k for lo, hi in ranges for k in range(lo, hi + 1)}
    return out


def test_the_carried_lines_are_every_line_cited():
    assert cited_lines() <= set(paper.carried()), sorted(cited_lines() - set(paper.carried()))


@pytest.mark.skipif(not paper.have_source(), reason=paper.NO_SOURCE)
def test_the_carried_lines_are_the_sources():
    lines = paper.source_lines()
    assert paper.carried()
    for n, text in paper.carried().items():
        assert lines[n - 1] == text, n


def test_the_engine_reads_nothing_beside_the_checkout():
    """`certify all` needs no ../shared: no module of certify/ or proofs/ names the paper's
    source or the claims list as a file (the report cites lines; only the tests read them)."""
    root = paper.ROOT
    for path in [*sorted((root / "certify").rglob("*.py")), *sorted((root / "proofs").glob("*.py"))]:
        text = path.read_text(encoding="utf-8")
        assert not re.search(r"""/\s*["']shared["']|["'][^"'\n]*\.\./shared|\.tex["']|CLAIMS\.md["']""", text), path
