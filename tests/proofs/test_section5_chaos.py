"""N2.7 (ours): the horseshoe at r = 11/100 as statements of statements/5_numerics.txt, decided by the
kernel from its own collision matrices.  The committed block is the one tools/chaos_statements.py
writes from the boxes the engine proves today; the kernel verifies it from a run of N2.7; a statement
file whose box is moved out of its branch, or whose target box is moved off the image, is refused."""
from __future__ import annotations

import importlib.util
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from certify.numerics import horseshoe as hs

ROOT = Path(__file__).resolve().parents[2]
STATEMENTS = ROOT / "statements"


def tool():
    spec = importlib.util.spec_from_file_location("chaos_statements", ROOT / "tools" / "chaos_statements.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def run_n8(tmp_path_factory):
    out = tmp_path_factory.mktemp("n8")
    done = subprocess.run([sys.executable, "-m", "certify", "run", "N2.7", "--out", str(out)], cwd=ROOT,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return out / "certificates.json"


def kernel(certificates: Path, statements: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "certify_kernel", str(certificates), "--statements", str(statements),
                           "--only", "N2.7", "--jobs", "1"], cwd=ROOT, capture_output=True, text=True)


def test_the_committed_statements_are_the_boxes_the_engine_proves():
    t = tool()
    H = hs.find(t.R)
    text = (STATEMENTS / "5_numerics.txt").read_text(encoding="utf-8")
    committed = text[text.index(t.BEGIN):text.index(t.END) + len(t.END)]
    assert committed == t.block(H.proof), "paste the block of tools/chaos_statements.py into statements/5_numerics.txt"


def test_the_kernel_verifies_every_formal_statement_of_n8(run_n8):
    done = kernel(run_n8, STATEMENTS)
    assert done.returncode == 0, done.stdout + done.stderr
    n = len(hs.facts(hs.find(tool().R).proof))
    assert f"{n}/{n + 1} statements verified" in done.stdout       # N2.7.1 (the theorem) is not formalised


def forged(tmp_path: Path, old: str, new: str) -> Path:
    copy = tmp_path / "statements"
    shutil.copytree(STATEMENTS, copy)
    f = copy / "5_numerics.txt"
    text = f.read_text(encoding="utf-8")
    assert text.count(old) == 1, old
    f.write_text(text.replace(old, new), encoding="utf-8")
    return copy


def test_a_box_vertex_moved_out_of_its_branch_is_refused_by_the_kernel(run_n8, tmp_path):
    text = (STATEMENTS / "5_numerics.txt").read_text(encoding="utf-8")
    line = re.search(r"^let ch_B2_1 = \(.*\)$", text, re.M).group(0)
    done = kernel(run_n8, forged(tmp_path, line, "let ch_B2_1 = (-0.5, 40, 1.5)"))
    assert done.returncode == 1 and "N2.7" in done.stdout and "FAILED" in done.stdout


def test_a_target_box_moved_off_the_image_is_refused_by_the_kernel(run_n8, tmp_path):
    """The centre of B1 in the covering B0 ⇒ B1 moved by its own stable half-side, times 3: |y| ≥ 1."""
    text = (STATEMENTS / "5_numerics.txt").read_text(encoding="utf-8")
    line = re.search(r"^let ch_B0B1_1v = .* - (-?[0-9.]+)$", text, re.M)
    old = line.group(0)
    shifted = old[: line.start(1) - line.start(0)] + str(float(line.group(1)) + 0.01)
    done = kernel(run_n8, forged(tmp_path, old, shifted))
    assert done.returncode == 1 and "FAILED" in done.stdout
