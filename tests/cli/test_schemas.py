"""Every JSON output has a schema that validates as shipped, with plain jsonschema (no
reference outside its own file), listed by ``certify schema``; real outputs validate."""
from __future__ import annotations

import json
import re
from fnmatch import fnmatch
from pathlib import Path

import pytest

from certify import cli
from certify.cli import schemas
from certify.run import runner
from certify.run.files import REPORTS

jsonschema = pytest.importorskip("jsonschema")
ROOT = Path(__file__).resolve().parents[2]


def validate(name: str, doc) -> None:
    """Plain jsonschema, the schema file alone: no registry, no resolver."""
    schema = json.loads(schemas.schemas()[name].read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator(schema).validate(doc)


@pytest.mark.parametrize("name", sorted(schemas.schemas()))
def test_every_schema_is_valid_and_self_contained(name):
    path = schemas.schemas()[name]
    schema = json.loads(path.read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator.check_schema(schema)
    refs = re.findall(r'"\$ref": "([^"]*)"', path.read_text(encoding="utf-8"))
    assert all(ref.startswith("#") for ref in refs), [r for r in refs if not r.startswith("#")]
    assert name in schemas.WRITERS, f"say which command writes {name}"


def test_every_schema_is_package_data():
    tomllib = pytest.importorskip("tomllib")              # Python 3.11+
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    data = config["tool"]["setuptools"]["package-data"]
    for path in schemas.schemas().values():
        folders = [(ROOT / pkg.replace(".", "/"), globs) for pkg, globs in data.items()]
        assert any(path.is_relative_to(folder) and fnmatch(path.relative_to(folder).as_posix(), g)
                   for folder, globs in folders for g in globs), path


@pytest.mark.parametrize("name, file", [("report", "report.json"), ("census", "census.json"),
                                        ("numerics-paper", "numerics-paper.json"), ("numerics-n4", "numerics-n4.json"),
                                        ("certificates", "certificates.json"), ("family", "family.json")])
def test_the_committed_outputs_validate(name, file):
    validate(name, json.loads((REPORTS / file).read_text(encoding="utf-8")))


def test_a_fresh_census_and_timings_validate(tmp_path, capsys):
    assert cli.main(["census", "--max-length", "4", "--out", str(tmp_path), "--jobs", "1"]) == 0
    validate("census", json.loads((tmp_path / "census.json").read_text(encoding="utf-8")))
    results, timings = runner.run_selected(["M1"], jobs=1)
    from certify.run import report
    validate("timings", json.loads(report.render_timings(timings)))
    validate("report", json.loads(report.render_json(results)))


def test_a_broken_output_does_not_validate():
    doc = json.loads((REPORTS / "report.json").read_text(encoding="utf-8"))
    doc["certificates"][0]["status"] = "MAYBE"
    with pytest.raises(jsonschema.ValidationError):
        validate("report", doc)


@pytest.mark.parametrize("argv", [["orbit", "abacbabcbcabcb", "--trap", "3/10", "--json"],
                                  ["orbit", "abcb", "--trap", "1/10", "--json"]])
def test_trap_json_validates(argv, capsys):
    cli.main(argv)
    validate("trap", json.loads(capsys.readouterr().out))


def test_schema_command_lists_prints_and_validates(tmp_path, capsys):
    assert cli.main(["schema"]) == 0
    assert set(re.findall(r"^(\S+) ", capsys.readouterr().out, re.M)) == set(schemas.schemas())
    assert cli.main(["schema", "orbit"]) == 0
    assert capsys.readouterr().out.strip().endswith("orbit.schema.json")
    good, bad = tmp_path / "good.json", tmp_path / "bad.json"
    good.write_text((REPORTS / "report.json").read_text(encoding="utf-8"), encoding="utf-8")
    bad.write_text('{"paper": 1}', encoding="utf-8")
    assert cli.main(["schema", "report", "--validate", str(good)]) == 0
    assert "valid against report.schema.json" in capsys.readouterr().out
    assert cli.main(["schema", "report", "--validate", str(bad)]) == 1
    assert "not valid against report.schema.json" in capsys.readouterr().out
    assert cli.main(["schema", "nosuch"]) == 2


def test_the_docs_show_the_one_line_validation():
    commands = (ROOT / "docs" / "commands.md").read_text(encoding="utf-8")
    assert "certify schema orbit --validate -" in commands
