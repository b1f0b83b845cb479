"""A new user's first run, in a fresh clone of this repository: ``certify all`` leaves
``git status`` clean (the committed report is current, and nothing else is written into
version control), and the serial run writes the same report as the run on every core.

These tests clone the committed HEAD (not the working tree) and run the real
certificates twice: they are marked slow (``python -m pytest -m slow
tests/cli/test_fresh_clone.py``), and ``.ci/run`` runs them after the default suite.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(shutil.which("git") is None or not (ROOT / ".git").exists(),
                                 reason="needs git and a git checkout")]


def certify(clone: Path, *args: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(clone)}
    env.pop("CERTIFY_DEBUG", None)
    return subprocess.run([sys.executable, "-m", "certify", *args], cwd=clone, env=env,
                          capture_output=True, text=True, timeout=900)


@pytest.fixture(scope="module")
def clone(tmp_path_factory):
    """A fresh clone of HEAD in which ``certify all`` has run once (on every core)."""
    path = tmp_path_factory.mktemp("fresh") / "certify"
    subprocess.run(["git", "clone", "--quiet", "--no-hardlinks", str(ROOT), str(path)], check=True)
    done = certify(path, "all")
    assert done.returncode == 0, done.stdout + done.stderr
    return path


def test_a_first_run_leaves_the_clone_clean(clone):
    status = subprocess.run(["git", "status", "--porcelain", "--untracked-files=all"], cwd=clone,
                            capture_output=True, text=True, check=True).stdout
    assert status == "", f"certify all changed the clone:\n{status}"


def test_the_serial_run_writes_the_same_report(clone, tmp_path):
    done = certify(clone, "all", "--jobs", "1", "--out", str(tmp_path))
    assert done.returncode == 0, done.stdout + done.stderr
    for name in ("REPORT.md", "report.json"):
        assert (tmp_path / name).read_bytes() == (clone / "reports" / name).read_bytes(), name
