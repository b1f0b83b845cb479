"""What a certificate cites is what the compiled paper prints: theorem-like numbers and
figure numbers from the LaTeX counters (tests/paper.py), figure labels beside, and the
numbers a certificate quotes found on the lines it cites."""
from __future__ import annotations

import re

import pytest

from certify.numerics import figures as F
from certify.run import report, runner
from tests.paper import NO_SOURCE, PAPER, numbering, plain_lines
from tests.proofs.test_claims import ranges
from tests.shared import strings

pytestmark = pytest.mark.skipif(not PAPER.is_file(), reason=NO_SOURCE)        # it reads the whole source

NAMED = re.compile(r"\b(Theorem|Proposition|Corollary|Remark|Lemma)s? (\d+\.\d+)")
FIGURE = re.compile(r"\bFigures? (\d+)([a-c]?)(?:-\d+([a-c]))? \(([^)]*)\)")


def texts():
    """What a reader sees of each certificate: its statement and its printed inputs."""
    for cert in runner.select():
        yield cert, [cert.statement, *strings(cert.printed)]


def test_the_counters_give_the_numbers_claims_md_lists():
    n = numbering()
    assert n[("Theorem", "4.1")] == 571 and n[("Proposition", "4.4")] == 997
    assert n[("Corollary", "4.5")] == 1037 and n[("Remark", "4.6")] == 1049
    assert n[("Remark", "3.3")] == 513 and n[("Theorem", "3.1")] == 286
    assert n[("Figure", "6")] == "fig:Simul_1" and n[("Figure", "11c")] == "fig:Simul_6"


def test_every_theorem_like_number_cited_is_printed_by_the_paper():
    printed = numbering()
    cited = [(cert.id, m.group(1), m.group(2)) for cert, ts in texts() for t in ts for m in NAMED.finditer(t)]
    cited += [("report", m.group(1), m.group(2)) for part in report.PARTS.values() for m in NAMED.finditer(part)]
    assert cited
    for where, kind, number in cited:
        assert (kind, number) in printed, (where, kind, number)


def test_the_figures_of_section_5_cite_the_compiled_number_with_their_label():
    printed = numbering()
    for fig, spec in F.SPECS.items():
        assert printed[("Figure", F.PAPER_NUMBER[fig])] == spec.label, fig
        assert F.cite(fig) == f"Figure {F.PAPER_NUMBER[fig]} ({spec.label})"


def test_every_figure_a_certificate_names_has_its_label_beside():
    printed = numbering()
    labels = {v: k[1] for k, v in printed.items() if k[0] == "Figure" and v}
    seen = 0
    for cert, ts in texts():
        for t in ts:
            assert not re.search(r"\bFigures? 5\.\d", t), (cert.id, t)        # the inventory's names, not the paper's
            for m in FIGURE.finditer(t):
                number, first, last = m.group(1, 2, 3)
                letters = [chr(c) for c in range(ord(first), ord(last or first) + 1)] if first else [""]
                named = [x.strip() for x in m.group(4).split(",")]
                assert [labels.get(x) for x in named] == [number + x for x in letters], (cert.id, t)
                seen += 1
    assert seen >= 4


def test_the_numbers_a_certificate_quotes_are_on_the_lines_it_cites():
    """Every decimal number in a certificate's statement or printed inputs (not a theorem
    or figure number) occurs on the lines it cites, read as plain text."""
    for cert, ts in texts():
        text = plain_lines(ranges(cert.line))
        for t in ts:
            t = NAMED.sub("", t)
            for number in re.findall(r"(?<![\w.])\d+\.\d+", t):
                assert number in text, (cert.id, cert.line, number)


def test_altering_a_cited_line_is_caught():
    text = plain_lines(ranges("l. 1103"))
    assert "0.07180" in text and "0.07180" not in plain_lines(ranges("l. 130"))
