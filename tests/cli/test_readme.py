"""The README a new user reads first: short, the two set-up commands exactly, links that
resolve, and an example that is what `certify all` prints for the committed report."""
from __future__ import annotations

import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text(encoding="utf-8")
PENDING: set = set()                 # pages linked before they are written (none now)


def test_the_first_screen_is_short_and_has_the_two_commands():
    assert len(README.encode()) < 6200
    assert "pip install -e . && python -m certify all" in README
    assert "pip install -e '.[test]' && python -m pytest -q -n auto" in README
    assert "this session" not in README


def test_every_link_of_the_readme_and_the_docs_resolves():
    pages = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
    for page in pages:
        for target in re.findall(r"\]\(([^)#:]+)(?:#[^)]*)?\)", page.read_text(encoding="utf-8")):
            path = (page.parent / target).resolve()
            if str(path.relative_to(ROOT)) in PENDING:
                continue
            assert path.exists(), (page.name, target)


def test_the_kernel_count_is_what_the_committed_kernel_json_gives():
    data = json.loads((ROOT / "reports" / "kernel.json").read_text(encoding="utf-8"))
    assert f"**{data['verified']}/{data['statements']} statements verified**" in README


def test_the_example_is_what_the_committed_report_gives():
    from certify.run import runner
    data = json.loads((ROOT / "reports" / "report.json").read_text(encoding="utf-8"))
    n = data["summary"]
    line = (f"{len(data['certificates'])} certificates: " + ", ".join(f"{n[s]} {s}" for s in runner.STATUSES)
            + f" ({len(data['disagree'])} of them disagree with the paper)")
    assert line in README
    errors = data["errors_of_the_paper"]
    assert f"{len(errors)} distinct errors of the paper, in {n[runner.ERRATUM]} certificates" in README
    for id_ in data["disagree"]:
        assert f"\n  {id_}: " in README
