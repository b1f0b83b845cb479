"""``certify chaos``: text, JSON against its schema, no claim without a proof (exit 1), bad input
(one line, exit 2)."""
from __future__ import annotations

import json

import jsonschema
import pytest

from certify import cli
from certify.cli import schemas


def run(capsys, *argv):
    code = cli.main(["chaos", *argv])
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.fixture(scope="module")
def schema():
    return json.loads(schemas.schemas()["chaos"].read_text(encoding="utf-8"))


def test_json_at_9_100_is_a_proved_horseshoe_and_validates(capsys, schema):
    code, out, err = run(capsys, "--r", "9/100", "--json")
    doc = json.loads(out)
    jsonschema.validate(doc, schema)
    assert code == 0 and err == "" and doc["certified"] and doc["r"] == "9/100"
    assert float(doc["entropy_lower"]) > 0 and len(doc["boxes"]) == len(doc["T"])
    assert all(sum(row) >= 1 for row in doc["T"])


def test_text_prints_words_boxes_T_and_the_entropy_bound(capsys):
    code, out, _ = run(capsys, "--r", "0.11")
    assert code == 0 and "chaos at r = 11/100: a horseshoe, proved" in out
    assert "T = " in out and "ρ(T) ≥ " in out and "log ρ(T)/k ≥ " in out and "measure zero" in out
    assert out.count("✓") >= 3 and "✗" not in out


def test_no_horseshoe_found_is_said_with_exit_1(capsys, schema):
    code, out, _ = run(capsys, "--r", "0.9", "--json")
    doc = json.loads(out)
    jsonschema.validate(doc, schema)
    assert code == 1 and doc["certified"] is False and "nothing is claimed" in doc["why"]
    code, out, _ = run(capsys, "--r", "0.9")
    assert code == 1 and "NOT certified" in out


def test_a_broken_record_does_not_validate(schema):
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate({"schema": "certify-chaos", "version": 1, "r": "1/10", "certified": "yes"}, schema)


@pytest.mark.parametrize("argv", [["--r", "2"], ["--r", "0"], ["--r", "abc"], ["--r", "1"], []])
def test_bad_input_is_one_line_and_exit_2(capsys, argv):
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1 and "Traceback" not in err


def test_figure_is_a_png_and_a_directory_is_refused(capsys, tmp_path):
    code, _, _ = run(capsys, "--r", "9/100", "--figure", str(tmp_path / "h.png"))
    assert code == 0 and (tmp_path / "h.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    code, out, err = run(capsys, "--r", "9/100", "--figure", str(tmp_path))
    assert code == 2 and "is a directory" in err and out == ""
