"""The report writer, on hand-built outcomes (no real certificate is run)."""
from __future__ import annotations

import json
import os
import re
from pathlib import Path

import pytest

from certify.run import report, runner
from certify.run.runner import ERRATUM, FAIL, OBSERVED, PASS, Certificate, Check, Outcome, conclude


def cert(cid, statement="a statement", line="l. 1"):
    """A certificate record with a do-nothing function."""
    def claim():
        """Docstring title."""
    return Certificate(cid, line, statement, claim, (), {}, "proofs.fake")


CODE = "```\nP0 = 1 + r\n    | indented |\n```"


WRONG = Check("Δ_cp = disc/1811939328", False, ["ratio is `-1/4`", CODE])


def sample_results():
    """One certificate per status, with evidence, a note and a figure."""
    return [
        (cert("M1", "AC = CA"), conclude([Check("AC = CA", True, ["`AC - CA = 0`"])],
                                         evidence=[CODE])),
        (cert("T4", "|q| > 1 on the upper branch", "l. 340-349"),
         conclude([WRONG, Check("degree 10", True)],
                  corrected=[Check("Δ_cp = -disc/(4·1811939328)", True, ["exact"], corrects=WRONG)],
                  note="The paper's normalisation differs by -4.")),
        (cert("T5", "P0 has one root in ]0,1[", "l. 350"),
         conclude([Check("one root", False, ["Sturm count 2"])])),
        (cert("N2", "Figure 5.1", "l. 1071"),
         Outcome(OBSERVED, [Check("windows of stability", True)], figures=["spectrum.png"])),
    ]


def unescaped_pipes(row: str) -> int:
    return len(re.findall(r"(?<!\\)\|", row))


def test_markdown_is_deterministic():
    assert report.render_markdown(sample_results()) == report.render_markdown(sample_results())
    assert report.render_json(sample_results()) == report.render_json(sample_results())


def test_markdown_has_no_date_or_timing():
    text = report.render_markdown(sample_results())
    assert not re.search(r"\b20\d\d-\d\d-\d\d\b|\bseconds\b", text)


def test_summary_counts_every_status():
    text = report.render_markdown(sample_results())
    for status, n in [(PASS, 1), (ERRATUM, 1), (FAIL, 1), (OBSERVED, 1)]:
        assert f"| {status} | {n} |" in text
    assert "| **Total** | **4** |" in text
    assert "Failing: [T5](#cert-t5)." in text
    assert report.summary_line(sample_results()) == \
        "4 certificates: 1 PASS, 1 ERRATUM, 1 FAIL, 1 OBSERVED"


def test_errata_table_shows_printed_next_to_corrected():
    text = report.render_markdown(sample_results())
    errata = text.split("## Errata", 1)[1].split("## All certificates", 1)[0]
    assert "| As printed (false) | Corrected (certified) | What changed |" in errata
    assert "| ✗ Δ_cp = disc/1811939328 | ✓ Δ_cp = -disc/(4·1811939328) | + `-`; + `(4·`; + `)` |" in errata
    assert "degree 10" not in errata          # only the failing printed checks
    assert "T5" not in errata                 # a FAIL is not an erratum


def test_no_errata():
    results = [r for r in sample_results() if r[1].status != ERRATUM]
    assert "None: no certificate has status ERRATUM." in report.render_markdown(results)


def test_table_rows_escape_pipes():
    text = report.render_markdown(sample_results())
    header = "| Id | Paper | Statement | Status | Kernel |"
    assert header in text
    table = text.split(header, 1)[1].split("\n\n", 1)[0].splitlines()[2:]
    assert len(table) == 4
    assert all(unescaped_pipes(row) == 6 for row in table)
    assert "\\|q\\| > 1 on the upper branch" in text


def test_section_keeps_evidence_and_code_blocks():
    text = report.render_markdown(sample_results())
    section = text.split('<a id="cert-t4"></a>', 1)[1].split("### ", 1)[0]
    assert "T4 — ERRATUM — as printed: |q| > 1 on the upper branch" in section.splitlines()[0]
    assert "Paper: l. 340-349 of the source · Status: **ERRATUM**" in section
    assert "`proofs/fake.py` (`claim`)" in section
    assert "- ✗ Δ_cp = disc/1811939328\n  - ratio is `-1/4`" in section
    assert "  - ```\n    P0 = 1 + r\n        | indented |\n    ```" in section   # nested, intact
    assert "**Corrected (certified)**\n\n- ✓ Δ_cp = -disc/(4·1811939328)" in section
    assert "**Note.** The paper's normalisation differs by -4." in section
    m1 = text.split('<a id="cert-m1"></a>', 1)[1].split("### ", 1)[0]
    assert "**Evidence**\n\n" + CODE in m1    # outcome evidence verbatim


def test_unclosed_code_fence_is_closed():
    results = [(cert("M1"), conclude([Check("x", True)], evidence=["```\nno end"]))]
    text = report.render_markdown(results)
    assert text.count("```") % 2 == 0


def test_figures_inline():
    text = report.render_markdown(sample_results())
    assert "![N2: spectrum](figures/spectrum.png)" in text
    data = json.loads(report.render_json(sample_results()))
    assert data["certificates"][3]["figures"] == ["figures/spectrum.png"]


def test_json_content():
    data = json.loads(report.render_json(sample_results()))
    assert data["summary"] == {PASS: 1, ERRATUM: 1, FAIL: 1, OBSERVED: 1}
    t4 = data["certificates"][1]
    assert (t4["id"], t4["line"], t4["status"]) == ("T4", "l. 340-349", ERRATUM)
    assert t4["printed"][0] == {"statement": "Δ_cp = disc/1811939328", "holds": False,
                                "evidence": ["ratio is `-1/4`", CODE]}
    assert t4["corrected"][0]["holds"] is True
    assert t4["corrected"][0]["corrects"] == "Δ_cp = disc/1811939328"
    assert t4["part"] == "Section 3: Theorem 3.1, the pattern ababcb"
    assert t4["note"] == "The paper's normalisation differs by -4."
    assert t4["proof"] == {"module": "proofs.fake", "function": "claim"}


def test_undecidable_holds_is_not_a_pass():
    class Undecided:
        def __bool__(self):
            raise TypeError("cannot determine truth value")
    assert runner.holds(Check("x", Undecided())) is False


def test_write_report_writes_three_files(tmp_path):
    timings = {"certificates": {"M1": {"seconds": 0.5, "of_which_shared": 0.25},
                                "T4": {"seconds": 1.0, "of_which_shared": 0.0}},
               "shared": {"M": 0.25}}
    text = report.write_report(sample_results(), timings, tmp_path)
    assert (tmp_path / "REPORT.md").read_text(encoding="utf-8") == text
    assert json.loads((tmp_path / "report.json").read_text())["summary"][PASS] == 1
    saved = json.loads((tmp_path / "timings.json").read_text())
    assert saved["total_seconds"] == 1.5 and saved["shared"] == {"M": 0.25}
    assert not [p for p in os.listdir(tmp_path) if p.endswith(".tmp")]


def test_crash_leaves_previous_report_intact(tmp_path, monkeypatch):
    for name in ("REPORT.md", "report.json", "timings.json"):
        (tmp_path / name).write_text("old " + name)

    def crash(src, dst):
        raise OSError("disk on fire")
    monkeypatch.setattr(os, "replace", crash)
    with pytest.raises(OSError, match="disk on fire"):
        report.write_report(sample_results(), {"certificates": {}, "shared": {}}, tmp_path)
    for name in ("REPORT.md", "report.json", "timings.json"):
        assert (tmp_path / name).read_text() == "old " + name
    assert sorted(os.listdir(tmp_path)) == ["REPORT.md", "report.json", "timings.json"]


def test_changed_parts_names_what_is_stale():
    old = report.render_markdown(sample_results())
    assert report.changed_parts(None, old) == ["missing"]
    assert report.changed_parts(old, old) == []
    results = sample_results()
    results[2] = (results[2][0], conclude([Check("one root", True)]))   # T5 now passes
    assert report.changed_parts(old, report.render_markdown(results)) == ["summary", "T5"]
    extra = sample_results() + [(cert("N3"), Outcome(OBSERVED, [Check("x", True)]))]
    assert report.changed_parts(old, report.render_markdown(extra)) == ["summary", "N3 (new)"]


def test_anchor():
    assert report.anchor("T10.1") == "cert-t10-1"


# --------------------------------------------------------------------------
# A report a reader can navigate (issues 8 and 11)

def test_headings_carry_the_status_and_mark_a_printed_claim():
    text = report.render_markdown(sample_results())
    assert '### <a id="cert-m1"></a>M1 — PASS — AC = CA' in text
    assert '### <a id="cert-t4"></a>T4 — ERRATUM — as printed: |q| > 1 on the upper branch' in text
    assert '### <a id="cert-t5"></a>T5 — FAIL — as printed: P0 has one root in ]0,1[' in text
    # a heading never shows a claim that is not certified without its status
    for line in text.splitlines():
        if line.startswith("### "):
            assert any(f" — {s} — " in line for s in (PASS, ERRATUM, FAIL, OBSERVED)), line


def test_contents_by_part_of_the_paper_with_stable_anchors():
    text = report.render_markdown(sample_results())
    contents = text.split("## Contents", 1)[1].split("## Summary", 1)[0]
    assert "- [Section 2: the model](#part-section-2-the-model): [M1](#cert-m1) PASS" in contents
    assert ("- [Section 3: Theorem 3.1, the pattern ababcb](#part-section-3-theorem-3-1-the-pattern-ababcb): "
            "[T4](#cert-t4) ERRATUM, [T5](#cert-t5) FAIL") in contents
    assert "- [Section 5: the numerical simulations](#part-section-5-the-numerical-simulations)" in contents
    for part in ("section-2-the-model", "section-3-theorem-3-1-the-pattern-ababcb",
                 "section-5-the-numerical-simulations"):
        assert f'## <a id="part-{part}"></a>' in text
    # every link of the report points at an anchor that exists
    anchors = set(re.findall(r'<a id="([^"]+)"></a>', text)) | {"summary", "errata", "all-certificates"}
    assert set(re.findall(r"\]\(#([^)]+)\)", text)) <= anchors
    assert text.rstrip("\n").endswith(report.END)


def test_the_report_says_which_source_its_line_numbers_refer_to():
    text = report.render_markdown(sample_results())
    head = text.split("## Contents", 1)[0]
    assert "arXiv:2411.10324v1" in head and "https://arxiv.org/e-print/2411.10324v1" in head
    assert "inelastic-collapse-four-particles.tex" in head


def test_erratum_rows_show_what_changed_and_only_the_false_checks():
    wrong = Check("t_c is smaller than t_b", False)
    fine = Check("t_b solves p_2 = 0", True)
    results = [(cert("S2", "t_c < t_b", "l. 628"),
                conclude([fine, wrong], corrected=[Check("t_c is larger than t_b", True, corrects=wrong),
                                                   Check("a supporting fact", True)]))]
    errata = report.render_markdown(results).split("## Errata", 1)[1].split("## All certificates", 1)[0]
    assert "| ✗ t_c is smaller than t_b | ✓ t_c is larger than t_b | `smaller` → `larger` |" in errata
    assert "t_b solves" not in errata and "a supporting fact" not in errata


def test_changes_names_the_differing_words_and_formulas():
    assert report.changes("cos θ is positive", "cos φ is positive") == "`θ` → `φ`"
    assert report.changes("`cross(cross(u0, ey), C*q0)`", "`cross(cross(u0, ez), C*q0)`") == "`ey` → `ez`"
    assert report.changes("c > 0 for r > 1", "c > 0 for r > 1") == ""


def test_consistency_checks_are_shown_as_such():
    results = [(cert("T3"), conclude([Check("cp(0) = -det M", True, counts=False), Check("a real claim", True)]))]
    text = report.render_markdown(results)
    assert "✓ cp(0) = -det M *(consistency check of the engine, not evidence)*" in text
    data = json.loads(report.render_json(results))
    assert data["certificates"][0]["printed"][0]["consistency"] is True


def test_changed_parts_charges_a_line_to_the_part_that_holds_it():
    old = report.render_markdown(sample_results())
    assert report.changed_parts(old + "junk\n", old) == ["outside any certificate"]
    assert report.changed_parts(old, old + "junk\n") == ["outside any certificate"]
    inside = old.replace("**Note.** The paper's", "junk\n\n**Note.** The paper's")
    assert report.changed_parts(inside, old) == ["T4"]
    assert report.changed_parts(old.replace("## Summary", "## Summary\njunk"), old) == ["summary"]


def _erratum(statement, misprint, kind="misprint", evidence=("a sign table",)):
    wrong = Check(f"{statement} as printed", False, list(evidence))
    return conclude([wrong, Check("shared", True, ["the same sign table"])],
                    corrected=[Check(f"{statement} corrected", True, list(evidence), corrects=wrong),
                               Check("shared", True, ["the same sign table"])], kind=kind, misprint=misprint)


def test_errata_count_distinct_errors_of_the_paper_and_their_kinds():
    """Two certificates false by one misprint count it once; kinds are told apart."""
    results = [(cert("S8.1"), _erratum("e_y", "l. 980: e_y for e_z")),
               (cert("S8.2"), _erratum("e_y again", "l. 980: e_y for e_z")),
               (cert("S10"), _erratum("every pattern", "Remark 4.6", kind=runner.FALSE_STATEMENT)),
               (cert("T28"), _erratum("does not seem", "Remark 3.3", kind=runner.REFUTED_REMARK))]
    line = report.errata_line(results)
    assert line == ("3 distinct errors of the paper, in 4 certificates: 1 misprint (in 2 certificates), "
                    "1 false statement (in 1 certificate), 1 refuted remark (in 1 certificate)")
    text = report.render_markdown(results)
    assert text.count("#### 1. l. 980: e_y for e_z") == 1
    assert "*Misprint*, in [S8.1](#cert-s8-1), [S8.2](#cert-s8-2)." in text
    assert "- ERRATUM, refuted remark: Remark 3.3 ([T28](#cert-t28))" in text
    data = json.loads(report.render_json(results))
    assert [e["certificates"] for e in data["errors_of_the_paper"]] == [["S8.1", "S8.2"], ["S10"], ["T28"]]
    assert report.misprints(results)[0][1] == "misprint"


def test_evidence_shown_under_as_printed_is_not_repeated_under_corrected():
    text = report.render_markdown([(cert("T17"), _erratum("Δ < 0", "l. 437"))])
    section = text.split('<a id="cert-t17"></a>')[1]
    assert section.count("the same sign table") == 1 and "✓ shared (as above)" in section


def test_the_first_screen_says_which_main_results_hold():
    """Computed from the outcomes (issue 25): a theorem holds when its certificates PASS, or
    are errata whose misprint says it holds (a false step of its proof); a FAIL is said."""
    step = Check("the printed step", False)
    results = [
        (cert("T25.1", "Theorem 3.1: self-similar data iff r < 5-2√6"), conclude([Check("iff", True)])),
        (cert("S9.1", "Proposition 4.4: no aca, by the printed argument"),
         conclude([step], corrected=[Check("the right step", True, corrects=step)], kind="false statement",
                  misprint="l. 1014: a step of the proof of Proposition 4.4; the proposition holds")),
        (cert("S6", "Theorem 4.1: the plane is determined"), conclude([Check("plane", False)])),
        (cert("M1", "AC = CA"), conclude([Check("AC = CA", True)])),
    ]
    head = report.render_markdown(results).split("## Contents", 1)[0]
    assert "**The main results**: Theorem 3.1 ([T25.1](#cert-t25-1)), Proposition 4.4 ([S9.1](#cert-s9-1)) hold; " \
           "Theorem 4.1 ([S6](#cert-s6)) not certified." in head
    assert head.index("The main results") < head.index("Every claim")
    assert "main results" not in report.render_markdown([results[-1]]).split("## Contents", 1)[0]


def test_no_committed_json_holds_a_timing():
    """Issue 25: a committed finding holds what was found, not how long it took (the writers
    drop TIMINGS: run.files.write_findings); timings.json is written but not committed."""
    import json
    import subprocess

    from certify.run import files
    root = Path(__file__).resolve().parents[2]
    committed = subprocess.run(["git", "ls-files", "reports/*.json"], cwd=root, capture_output=True, text=True).stdout
    names = [n for n in committed.split() if n]
    if not names:
        pytest.skip("not a git checkout")

    def keys(x):
        if isinstance(x, dict):
            for k, v in x.items():
                yield k
                yield from keys(v)
        elif isinstance(x, list):
            for v in x:
                yield from keys(v)
    for name in names:
        found = set(keys(json.loads((root / name).read_text(encoding="utf-8")))) & set(files.TIMINGS)
        assert not found, (name, found)
    assert files.timeless({"a": [{"seconds": 1, "b": 2}], "seconds": 3}) == {"a": [{"b": 2}]}


def test_the_first_screen_names_the_open_questions_settled_and_only_those():
    """The open questions of the paper a PASS certificate settles are named in the first line, each
    linked; one that fails (or is absent) is not named."""
    from tests.shared import registry
    theorem = conclude([Check("self-similar data iff r < 5-2√6", True)])
    settled = [(registry()[cid], conclude([Check("settled", True)])) for cid, _ in report.OPEN_PROBLEMS]
    line = report.main_results_line([(registry()["T25.1"], theorem)] + settled)
    assert "Questions the paper leaves open, settled here" in line
    for cid, what in report.OPEN_PROBLEMS:
        assert what in line and f"(#cert-{cid.lower().replace('.', '-')})" in line, cid
    failed = [(registry()["L5"], conclude([Check("settled", False)]))]
    line = report.main_results_line([(registry()["T25.1"], theorem)] + failed)
    assert "leaves open" not in line
