"""The census's files as a reader meets them (issue 38, item 6): CENSUS.md leads with a summary
that fits a screen and has no line of 1000 characters; census.json is a few MB; the table
census-words.csv.gz has one row per word with the exact ends of census.json; the files written
again from a census.json (tools/census_render.py) are the bytes `certify census` writes."""
from __future__ import annotations

import csv
import gzip
import io
import json
import re
import subprocess
import sys
from pathlib import Path

import flint
import pytest

from certify import cli
from certify.algebra import Algebraic
from certify.patterns import census
from certify.run import census_report
from certify.run.files import REPORTS

ROOT = Path(__file__).resolve().parents[2]
SCREEN = 40                     # lines: the summary ends within them
LONGEST = 1000                  # characters: no line of CENSUS.md reaches it
MB = 1_000_000


def committed() -> dict:
    return json.loads((REPORTS / "census.json").read_text(encoding="utf-8"))


def rows_of(raw: bytes) -> list[dict]:
    """The rows of a census-words.csv.gz, read by the standard library."""
    return list(csv.DictReader(io.StringIO(gzip.decompress(raw).decode("utf-8"))))


# ----------------------------------------------------------------- CENSUS.md
def summary_of(text: str) -> list[str]:
    """The lines of the section "## Summary" of a CENSUS.md."""
    lines = text.splitlines()
    start = lines.index("## Summary")
    end = next(k for k in range(start + 1, len(lines)) if lines[k].startswith("## "))
    return lines[start:end]


def test_the_committed_census_md_leads_with_a_summary_that_fits_a_screen():
    """The summary comes first (after the title and one line), ends within a screen, and gives
    the counts of census.json with their first words: stable self-similar data, attracting
    periodic orbits of the reduction, undecided points; and the largest feasible r."""
    text = (REPORTS / "CENSUS.md").read_text(encoding="utf-8")
    lines = text.splitlines()
    assert lines.index("## Summary") <= 5
    summary = summary_of(text)
    assert lines.index("## Summary") + len(summary) <= SCREEN
    s = committed()["census"]
    by = {r["word"]: r for r in committed()["words"]}
    for what, words in (("stable self-similar (collapsing) data", s["stable"]),
                        ("an attracting periodic orbit of the reduction", s["reduction"]["attracting"]),
                        ("feasible self-similar data", s["feasible"])):
        row = next(line for line in summary if line.startswith(f"| {what} |"))
        assert row.split(" | ")[1] == str(len(words)), row
        assert f"`{by[words[0]]['compact']}`" in row.split(" | ")[2], row
    undecided = next(line for line in summary if line.startswith("| undecided self-similar points |"))
    assert undecided.split(" | ")[1].startswith(f"{len(s['undecided'])} (")
    r_exist = Algebraic.roots(flint.fmpz_poly([17, -138, 831, -3148, 831, -138, 17]), 0, 1)   # P(r), l. 1100-1102
    assert len(r_exist) == 1
    assert any(line.startswith(f"- the largest r with feasible self-similar data: ≈{r_exist[0].digits(10)}, "
                               "reached by `abcb`") for line in summary)


def test_the_committed_census_md_has_no_line_of_a_thousand_characters():
    lines = (REPORTS / "CENSUS.md").read_text(encoding="utf-8").splitlines()
    longest = max(lines, key=len)
    assert len(longest) < LONGEST, (len(longest), longest[:120])


def test_a_cell_too_long_is_cut_and_sent_to_the_table():
    text = "; ".join(f"branch {k}: ]0, ≈0.1{k}[" for k in range(100))
    cut = census_report._short(text)
    assert len(cut) <= census_report.CELL + 40 and cut.endswith(f"(all: {census_report.TABLE})")
    assert census_report._short("upper: ]0, 1[") == "upper: ]0, 1["


def test_the_summary_names_the_highest_undecided_point():
    """The highest undecided self-similar point of the committed census, found here from the
    records, is the one the summary names."""
    doc = committed()
    points = [(census_report.undecided_r(p), r["compact"], p) for r in doc["words"]
              for p in (r.get("result") or {}).get("undecided", [])]
    summary = summary_of((REPORTS / "CENSUS.md").read_text(encoding="utf-8"))
    line = next(line for line in summary if line.startswith("- the highest undecided self-similar point: "))
    if not points:                                     # the census to 20 decides every point
        assert line == "- the highest undecided self-similar point: none"
        return
    top = max(r for r, _w, _p in points)
    at_top = [(w, p) for r, w, p in points if r == top]
    word, text = at_top[0]
    assert line.startswith(f"- the highest undecided self-similar point: `{word}`, {text}")
    assert f"(and {len(at_top) - 1} more points at that r, in {len({w for w, _p in at_top})} words" in line


# ----------------------------------------------------------------- census.json and the table
def test_the_committed_census_data_is_a_few_megabytes():
    """census.json was 93 MB (every existence set of both analyses); now a few MB, the table less."""
    size = (REPORTS / "census.json").stat().st_size
    assert size < 8 * MB
    assert (REPORTS / census_report.TABLE).stat().st_size < 1 * MB
    assert f"the census to {committed()['census']['max_length']} is {size / MB:.1f} MB" in " ".join(docs().split())


def test_the_committed_records_are_brief_and_their_summary_is_theirs():
    """Each record of census.json is its own brief form, and the summary computed from the
    records is the one the file holds (nothing the summary needs was dropped)."""
    doc = committed()
    assert all(census_report.brief(r) == r for r in doc["words"])
    assert census.summary(doc["words"], doc["census"]["max_length"]) == doc["census"]


def test_the_committed_table_has_one_row_per_word_of_the_census():
    doc = committed()
    rows = rows_of((REPORTS / census_report.TABLE).read_bytes())
    words = [row["word"] for row in rows]
    assert words == [r["word"] for r in doc["words"]] == census.words(doc["census"]["max_length"])
    assert len(rows) == doc["census"]["words"]
    assert list(rows[0]) == list(census_report.COLUMNS)
    assert [row["word"] for row in rows if row["stable"] == "True"] == doc["census"]["stable"]
    assert [row["word"] for row in rows if row["attracting"] == "True"] == doc["census"]["reduction"]["attracting"]


def test_the_table_round_trips_the_exact_ends():
    """The exact columns are census.json's sets (JSON, exact ends); each end read back is an
    algebraic number (its root recounted in its interval); the float columns are the certified
    digits of the least and largest ends, the largest found by exact comparison."""
    doc = committed()
    rows = rows_of((REPORTS / census_report.TABLE).read_bytes())
    for row, rec in zip(rows, doc["words"]):
        result = rec.get("result") or {}
        assert json.loads(row["feasible_exact"]) == result.get("feasible", [])
        assert json.loads(row["stable_exact"]) == result.get("stable", [])
        assert json.loads(row["attracting_exact"]) == ((rec["reduction"].get("result") or {}).get("attracting", []))
    for row in rows:
        if row["stable"] != "True":
            continue
        ends = [p[k] for s in json.loads(row["stable_exact"]) for p in s["pieces"]
                for k in (("lo", "hi") if p["kind"] == "interval" else ("at",))]
        numbers = [census.end_number(e) for e in ends]
        top = max(range(len(ends)), key=lambda k: numbers[k])
        low = min(range(len(ends)), key=lambda k: numbers[k])
        assert float(row["stable_hi"]) == float(ends[top]["digits"])
        assert float(row["stable_lo"]) == float(ends[low]["digits"])


def test_a_row_of_the_table_with_an_error():
    rec = {"word": "acb", "compact": "acb", "length": 3, "blocks": ["acb"], "contains_abcab": True,
           "outcome": "error", "feasible": None, "stable": None, "undecided": None, "verdict": "error",
           "error": "ArithmeticError: x", "result": None,
           census.REDUCTION: {"outcome": "error", "feasible": None, "attracting": None, "verdict": "error",
                              "error": "ValueError: y", "result": None}}
    row = census_report.table_row(rec)
    assert row["feasible"] == row["stable_lo"] == "" and row["error"] == "ArithmeticError: x; ValueError: y"
    assert row["feasible_exact"] == "[]" and row["attracting"] is False


# ----------------------------------------------------------------- docs/census.md
def docs() -> str:
    return (ROOT / "docs" / "census.md").read_text(encoding="utf-8")


def test_docs_name_every_column_of_the_table():
    text = docs()
    missing = [c for c in census_report.COLUMNS if f"`{c}`" not in text]
    assert not missing, missing


def test_the_pandas_example_of_the_docs_runs_on_the_committed_table(tmp_path):
    """The example of docs/census.md, run from the checkout: the stable words of census.json."""
    pytest.importorskip("pandas")
    code = re.search(r"```python\n(import pandas.*?)```", docs(), re.S).group(1)
    out = subprocess.run([sys.executable, "-c", code + "\nprint(','.join(stable['word']))"], cwd=ROOT,
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-1].split(",") == committed()["census"]["stable"]


# ----------------------------------------------------------------- written again: the same bytes
FILES = ("CENSUS.md", "census.json", census_report.TABLE, census_report.FIGURE)


def render(source: Path, out: Path) -> int:
    return subprocess.run([sys.executable, str(ROOT / "tools" / "census_render.py"), str(source), str(out)],
                          capture_output=True, text=True, timeout=300).returncode


@pytest.mark.parametrize("L", [8, pytest.param(10, marks=pytest.mark.slow)])
def test_the_files_written_again_from_a_census_json_are_those_of_a_fresh_census(tmp_path, capsys, L):
    """`certify census --max-length L` into A; tools/census_render.py from A/census.json (brief
    records) and from a census.json of the full records of A's state file (as the census to 20
    was committed); tools/census_redo.py and `--resume` from the brief records, one word
    analysed again: the same bytes, every file."""
    fresh = tmp_path / "fresh"
    assert cli.main(["census", "--max-length", str(L), "--out", str(fresh), "--jobs", "1"]) == 0
    full = [json.loads(line) for line in (fresh / "census-state.jsonl").read_text(encoding="utf-8").splitlines()]
    assert any("exists" in (r.get("result") or {}) for r in full)                 # the full records
    old = tmp_path / "old" / "census.json"
    old.parent.mkdir()
    old.write_text(json.dumps({"census": census.summary(full, L), "words": census.order(full)}), encoding="utf-8")
    for name, source in (("brief", fresh / "census.json"), ("full", old)):
        assert render(source, tmp_path / name) == 0
        for file in FILES:
            assert (tmp_path / name / file).read_bytes() == (fresh / file).read_bytes(), (name, file)
    # tools/census_redo.py: the brief records kept in a state, one word analysed again, the same bytes
    state = tmp_path / "redo" / "state.jsonl"
    state.parent.mkdir()
    assert subprocess.run([sys.executable, str(ROOT / "tools" / "census_redo.py"), str(fresh / "census.json"),
                           str(state), "--word", "abcb"], capture_output=True, timeout=120).returncode == 0
    assert len(state.read_text(encoding="utf-8").splitlines()) == len(census.words(L)) - 1
    assert cli.main(["census", "--max-length", str(L), "--out", str(state.parent), "--jobs", "1",
                     "--state", str(state), "--resume"]) == 0
    for file in FILES:
        assert (state.parent / file).read_bytes() == (fresh / file).read_bytes(), ("redo", file)


def test_render_refuses_a_census_whose_summary_is_not_its_records(tmp_path):
    doc = committed()
    small = {"census": dict(doc["census"], max_length=4, words=3), "words": doc["words"][:3]}
    (tmp_path / "census.json").write_text(json.dumps(small), encoding="utf-8")
    assert render(tmp_path / "census.json", tmp_path / "out") == 1
    assert render(tmp_path / "missing.json", tmp_path / "out") == 2
