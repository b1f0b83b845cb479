"""The docs against the tool (issue 25, item 10): docs/commands.md names every option of every
command with the parser's default (its section "Every option" is generated from the parsers),
the defaults typed in help texts are the parsers', the commands' table names no option that does
not exist, the example of `certify all` is the committed report's, and the README's reading
list links every page of docs/."""
from __future__ import annotations

import argparse
import json
import re
from fractions import Fraction
from pathlib import Path

import pytest

from certify import cli
from certify.cli import options, reference

ROOT = Path(__file__).resolve().parents[2]
COMMANDS_MD = (ROOT / "docs" / "commands.md").read_text(encoding="utf-8")


def subparsers() -> dict:
    parser = cli.build_parser()
    return next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction)).choices


def test_every_option_section_is_the_parsers():
    """Fails when an option, a help text or a default changes without the docs: run
    `python -m certify.cli.reference` to rewrite the section."""
    assert reference.section(COMMANDS_MD) == reference.markdown()


def test_every_option_of_every_command_is_in_the_docs():
    for name, parser in subparsers().items():
        block = COMMANDS_MD.split(f"### `{name}`", 1)[1].split("### `", 1)[0]
        for action in parser._actions:
            for flag in action.option_strings:
                if flag not in ("-h", "--help"):
                    assert f"`{flag}" in block or f", {flag}" in block, (name, flag)


def typed_default(help_text: str) -> str | None:
    m = re.search(r"\(default:? ([^;),]*)", help_text or "")
    return m.group(1).strip() if m else None


@pytest.mark.parametrize("name", sorted(subparsers()))
def test_the_defaults_typed_in_help_texts_are_the_parsers(name):
    for action in subparsers()[name]._actions:
        typed = typed_default(action.help)
        if typed is None or action.default is None or "%(default)" in (action.help or ""):
            continue
        if action.dest == "jobs":
            assert typed.startswith("all cores"), (name, typed)
        elif isinstance(action.default, int):
            assert options.exact(typed.split()[0]) == Fraction(action.default), (name, action.dest, typed)
        else:
            assert typed == str(action.default), (name, action.dest, typed)


def test_the_typed_default_check_can_fail():
    assert typed_default("number of runs (default: 3)") == "3" and options.exact("3") != 5
    assert options.exact("10^4") == 10000


def table_rows() -> dict[str, str]:
    """The commands' table of docs/commands.md: command name -> the text of its rows."""
    rows: dict[str, str] = {}
    for line in COMMANDS_MD.split("## Numbers", 1)[0].splitlines():
        m = re.match(r"\| `(\w+)[ `]", line)
        if m:
            rows[m.group(1)] = rows.get(m.group(1), "") + line
    return rows


def test_the_table_lists_every_command_and_only_existing_options():
    rows, parsers = table_rows(), subparsers()
    assert set(rows) == set(parsers)
    for name, text in rows.items():
        known = {flag for a in parsers[name]._actions for flag in a.option_strings}
        first_cell = text.split(" | ", 1)[0]
        for flag in re.findall(r"--[a-z0-9][a-z0-9-]*", first_cell):
            assert flag in known, (name, flag)


def test_the_example_of_all_is_the_committed_report():
    """The errata lines of the example are the committed report's (regenerate both together)."""
    data = json.loads((ROOT / "reports" / "report.json").read_text(encoding="utf-8"))
    example = COMMANDS_MD.split("$ python -m certify all\n", 1)[1].split("```", 1)[0]
    for error in data["errors_of_the_paper"]:
        line = f"  {', '.join(error['certificates'])}: {error['kind']}: {' '.join(error['misprint'].split())}"
        assert line + "\n" in example, line


def test_the_readme_reading_list_links_every_page_of_the_docs():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    read_on = readme.split("## Read on", 1)[1]
    for page in sorted((ROOT / "docs").glob("*.md")):
        assert f"(docs/{page.name})" in read_on, page.name


def test_timings_quoted_by_the_docs_come_from_the_benchmarks():
    """docs/orbit.md quotes no typed seconds: it points at the section of reports/BENCH.md that
    benchmarks/bench_patterns.py --orbit writes; BENCH.md's `certify all` counts the
    certificates there are (regenerate it with `certify bench` when certificates are added)."""
    from certify.run import runner
    orbit = (ROOT / "docs" / "orbit.md").read_text(encoding="utf-8")
    speed = orbit.split("**Speed**", 1)[1].split("\n\n", 1)[0]
    assert not re.search(r"\d+(\.\d+)? s\b", speed) and "bench_patterns.py --orbit" in speed
    bench = (ROOT / "reports" / "BENCH.md").read_text(encoding="utf-8")
    assert "## certify orbit" in bench
    measured = re.search(r"## certify all\n\n.*?; (\d+) certificates", bench, re.S)
    assert measured and int(measured.group(1)) == len(runner.select()), "BENCH.md is stale: run `certify bench`"
