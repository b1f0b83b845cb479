"""``certify island``: text, JSON against its schema, bad input (one line, exit 2)."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import jsonschema
import pytest

from certify import cli
from certify.patterns import island_theorem

ROOT = Path(__file__).resolve().parents[2]
SCHEMA = json.loads(island_theorem.SCHEMA_PATH.read_text())


def run(capsys, *argv):
    code = cli.main(["island", *argv])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_text_shows_every_step_and_the_numbers(capsys):
    code, out, err = run(capsys, "--r", "0.3", "--depth", "6")
    assert code == 0 and err == ""
    assert "island theorem at r = 3/10: proved: an island of quasi-periodic orbits around [ac]b" in out
    assert out.count("✓") == 7 and "✗" not in out
    assert "c_max = 71/120" in out and "rotation number ρ = 0.3169449453512215" in out
    assert "quasi-periodic: yes" in out and "island fraction" in out


def test_not_elliptic_says_in_its_first_line_that_what_is_proved_is_no_island(capsys):
    """Issue 38 item 8: at r = 1/10 the theorem holds in its other case (A not elliptic); the
    first line no longer reads "proved" alone above "not elliptic: no island"."""
    code, out, _ = run(capsys, "--r", "1/10")
    first = out.splitlines()[0]
    assert code == 0 and first.startswith("island theorem at r = 1/10: proved")
    assert "not elliptic" in first and "no island" in first


def test_json_validates_and_says_what_the_issue_asks(capsys):
    code, out, _ = run(capsys, "--r", "3/10", "--json", "--depth", "6", "--resonances", "5")
    doc = json.loads(out)
    jsonschema.validate(doc, SCHEMA)
    assert doc["r"] == "3/10" and doc["elliptic"] and doc["quasi_periodic"] and doc["c_max"] == "71/120"
    assert doc["rotation_number"]["digits"] >= 15
    lo, hi = (doc["island_fraction"][k] for k in ("lo", "hi"))
    assert "/" in lo and "/" in hi
    assert [(x["p"], x["q"]) for x in doc["resonances"]] == [(2, 5), (1, 3)]
    assert doc["resonances"][1]["minimal_polynomial"] == "r^2 - 4r + 1"
    ends = {(x["word"], x["end"]): (x["p"], x["q"]) for x in doc["window_resonances"]}
    assert ends.get(("abacbacbcb", "hi")) == (1, 3)          # a(bac)^2bcb ends at 2 - √3 (the issue)


def test_range_json_with_the_symbolic_theorem_validates(capsys):
    code, out, _ = run(capsys, "--r-range", "0.1", "0.9", "3", "--json", "--depth", "4", "--symbolic")
    doc = json.loads(out)
    jsonschema.validate(doc, SCHEMA)
    assert [x["r"] for x in doc["islands"]] == ["1/10", "1/2", "9/10"]
    assert [x["elliptic"] for x in doc["islands"]] == [False, True, True]
    assert doc["islands"][0]["rotation_number"] is None and doc["islands"][0]["island_fraction"] is None
    assert doc["symbolic"]["holds"]


def test_the_schema_refuses_a_broken_document(capsys):
    _, out, _ = run(capsys, "--r", "1/2", "--json", "--depth", "3")
    doc = json.loads(out)
    doc["rotation_number"]["digits"] = 10
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(doc, SCHEMA)


@pytest.mark.parametrize("argv", [["--r", "2"], ["--r", "abc"], ["--r", "0"], ["--r-range", "0.5", "0.2"],
                                  ["--r-range", "0.2", "0.5", "x"], ["--r-range", "0.2"], [],
                                  ["--r", "0.3", "--resonances", "1000"], ["--r", "0.3", "--depth", "99"],
                                  ["--r", "0.3", "--r-range", "0.1", "0.2"]])
def test_bad_input_is_one_line_and_exit_2(capsys, argv):
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and err.startswith("certify: error:")


def test_exit_code_2_from_the_shell():
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    p = subprocess.run([sys.executable, "-m", "certify", "island", "--r", "1.5"], capture_output=True, text=True,
                       env=env, cwd=ROOT)
    assert p.returncode == 2 and "must lie in ]0,1[" in p.stderr and len(p.stderr.strip().splitlines()) == 1
