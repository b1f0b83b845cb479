"""Issue 38, item 5: the counts, limits and defaults the docs quote are the tool's: the sample
run of `certify all` (README.md, docs/commands.md, docs/report.md, docs/verify.md) against the
committed reports/report.json that `certify all` wrote; the word limits of `pattern` and `orbit`;
each command's defaults in its own page docs/COMMAND.md; every schema `certify schema` lists."""
from __future__ import annotations

import argparse
import json
import re
from pathlib import Path

import pytest

from certify import cli
from certify.cli import schemas
from certify.patterns import periodic
from certify.patterns.reduction_orbits import MAX_ORBIT_LENGTH
from certify.run.files import REPORTS

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
REPORT = json.loads((REPORTS / "report.json").read_text(encoding="utf-8"))
SUMMARY = re.compile(r"(\d+) certificates: (\d+) PASS, (\d+) ERRATUM, (\d+) FAIL, (\d+) OBSERVED "
                     r"\((\d+) of them disagree with the paper\)")


def committed() -> dict:
    """The counts of the committed run, from reports/report.json."""
    s = REPORT["summary"]
    figures = {f for c in REPORT["certificates"] for f in c.get("figures", [])}
    return {"certificates": len(REPORT["certificates"]), "PASS": s["PASS"], "ERRATUM": s["ERRATUM"],
            "FAIL": s["FAIL"], "OBSERVED": s["OBSERVED"], "disagree": len(REPORT["disagree"]), "figures": len(figures)}


@pytest.mark.parametrize("page", ["README.md", "docs/commands.md"])
def test_the_sample_run_shows_the_committed_counts(page):
    text = (ROOT / page).read_text(encoding="utf-8")
    found = SUMMARY.findall(text)
    n = committed()
    assert found, f"{page}: no summary line"
    for line in found:
        assert list(map(int, line)) == [n[k] for k in ("certificates", "PASS", "ERRATUM", "FAIL", "OBSERVED",
                                                          "disagree")], (page, line)


def test_the_sample_run_shows_the_committed_number_of_figures():
    text = (DOCS / "commands.md").read_text(encoding="utf-8")
    assert re.findall(r"figures/ \((\d+) files\)", text) == [str(committed()["figures"])]


def test_the_reports_and_the_kernels_pages_count_the_committed_certificates():
    n = committed()
    report = (DOCS / "report.md").read_text(encoding="utf-8")
    assert f"{n['certificates']} certificates: {n['PASS']} PASS, {n['ERRATUM']} ERRATUM" in report
    assert f"{n['OBSERVED']} OBSERVED ({n['disagree']} of them disagree with the paper)" in report
    assert f"`{n['certificates']} certificates, 0 failed" in (DOCS / "verify.md").read_text(encoding="utf-8")


def test_the_word_limits_are_the_tools():
    commands = " ".join((DOCS / "commands.md").read_text(encoding="utf-8").split())
    assert f"at most {periodic.MAX_LENGTH} letters" in commands
    assert f"`orbit` takes at most {MAX_ORBIT_LENGTH} letters" in commands
    assert f"a word longer than {periodic.MAX_LENGTH}, {MAX_ORBIT_LENGTH} for `orbit`" in commands
    orbit = " ".join((DOCS / "orbit.md").read_text(encoding="utf-8").split())
    assert f"`MAX_ORBIT_LENGTH` = {MAX_ORBIT_LENGTH} letters" in orbit


def commands() -> dict:
    parser = cli.build_parser()
    return next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction)).choices


@pytest.mark.parametrize("name", sorted(n for n in commands() if (DOCS / f"{n}.md").is_file()))
def test_a_commands_page_quotes_its_defaults(name):
    """docs/atlas.md said `--word-max` (default 60) while the parser's was 64."""
    text = (DOCS / f"{name}.md").read_text(encoding="utf-8")
    defaults = {flag: a.default for a in commands()[name]._actions for flag in a.option_strings}
    quoted = re.findall(r"`(--[a-z0-9-]+)[^`]*`[^`()]{0,60}?\(default (\d+)\)", text)
    for flag, value in quoted:
        if defaults.get(flag) is not None:          # island's --r-range COUNT: 5 in the code, not the parser
            assert str(defaults[flag]) == value, (name, flag, value, defaults[flag])


def test_commands_md_names_every_schema():
    text = (DOCS / "commands.md").read_text(encoding="utf-8")
    section = text.split("## JSON outputs and their schemas", 1)[1].split("\n## ", 1)[0]
    for name in schemas.schemas():
        assert f"`{name}`" in section, name


def findings(r: str, collisions: int) -> dict:
    """The committed record of identify --section5 at r (reports/section5-orbits.json)."""
    doc = json.loads((REPORTS / "section5-orbits.json").read_text(encoding="utf-8"))
    return next(x for runs in doc["claims"].values() for x in runs
                if isinstance(x, dict) and x.get("r") == r and x.get("collisions") == collisions)


def test_orbit_md_says_what_the_committed_findings_say():
    """docs/orbit.md read "at r = 0.173 no orbit shows a period ≤ 120" while the committed
    findings (and README) have all eight on a certified 122-letter word."""
    text = " ".join((DOCS / "orbit.md").read_text(encoding="utf-8").split())
    for collisions in (10_000, 100_000):
        at = findings("173/1000", collisions)
        assert at["classes"] == {"attracting periodic": 8, "island": 0, "unresolved": 0}
        assert {len(w["word"]) for w in at["words"]} == {122}
    assert "at r = 0.173 all eight follow the 122-letter word" in text and "no period ≤ 120" not in text
    for r in ("3/10", "4/5"):
        assert findings(r, 10_000)["classes"] == {"attracting periodic": 4, "island": 4, "unresolved": 0}
    assert "the other four are island orbits (quasi-periodic, proved)" in text


def test_orbit_md_states_identifys_limits_on_r(capsys):
    from certify.cli.options import R_MARGIN_TEXT
    text = " ".join((DOCS / "orbit.md").read_text(encoding="utf-8").split())
    assert f"An r within {R_MARGIN_TEXT} of 0 or 1 is refused" in text and "(above 1 − 2^-53)" in text
    assert cli.main(["identify", "--r", "0.99999999999999999"]) == 2 and "rounds to 1.0" in capsys.readouterr().err
    assert cli.main(["identify", "--r", "2^-61"]) == 2 and R_MARGIN_TEXT in capsys.readouterr().err
