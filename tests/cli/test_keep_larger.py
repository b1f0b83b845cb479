"""Issue 38, item 2: no command replaces a larger result already in its output (by default
the committed reports/) without --force; one helper, certify.run.files.keep_larger."""
from __future__ import annotations

import shutil
from fractions import Fraction

import pytest

from certify import cli
from certify.errors import UsageError
from certify.run.files import REPORTS, keep_larger

# (the command, smaller than the committed result, and the committed files it would replace)
SMALLER = {
    "atlas": (["atlas", "--resolution", "1", "--data", "0", "--collisions", "200", "--seeds", "none", "--refine", "0",
               "--jobs", "1"], ["atlas.json"]),
    "family": (["family", "--n-max", "2"], ["family.json"]),
    "figures --n4": (["figures", "--n4", "6", "--jobs", "1"], ["numerics-n4.json"]),
    "figures paper": (["figures", "--resolution", "paper", "--only", "5.2", "--jobs", "1"],
                      ["numerics-paper.json"]),
}


@pytest.mark.parametrize("name", SMALLER)
def test_a_smaller_run_does_not_replace_the_committed_result(name, tmp_path, capsys):
    argv, files = SMALLER[name]
    for f in files:
        shutil.copy(REPORTS / f, tmp_path / f)
    before = {f: (tmp_path / f).read_bytes() for f in files}
    assert cli.main([*argv, "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "holds a larger" in err and "--out DIR" in err and "--force" in err
    assert {f: (tmp_path / f).read_bytes() for f in files} == before
    assert not (tmp_path / "figures").exists() or not any((tmp_path / "figures").iterdir())


def test_stress_quick_does_not_replace_the_full_report(tmp_path, capsys):
    target = tmp_path / "STRESS.md"
    shutil.copy(REPORTS / "STRESS.md", target)
    before = target.read_bytes()
    assert cli.main(["stress", "--quick", "--jobs", "1", "--out", str(target)]) == 2
    err = capsys.readouterr().err
    assert "random orbits 1000" in err and "random orbits 40" in err and "--out FILE" in err
    assert target.read_bytes() == before


def test_force_replaces_it(tmp_path):
    shutil.copy(REPORTS / "family.json", tmp_path / "family.json")
    assert cli.main(["family", "--n-max", "2", "--out", str(tmp_path), "--force"]) == 0
    assert '"n_max": 2' in (tmp_path / "family.json").read_text()


def test_a_run_as_large_replaces_it_without_force(tmp_path):
    assert cli.main(["family", "--n-max", "2", "--out", str(tmp_path)]) == 0
    assert cli.main(["family", "--n-max", "3", "--out", str(tmp_path)]) == 0
    assert cli.main(["family", "--n-max", "3", "--out", str(tmp_path)]) == 0


def test_keep_larger_compares_every_measure_and_intervals_by_inclusion():
    old = {"r-range": (Fraction(9, 125), Fraction(1)), "r values": 200}
    keep_larger("x", "atlas", old, {"r-range": (Fraction(0), Fraction(1)), "r values": 200}, force=False)
    keep_larger("x", "atlas", None, {"r values": 1}, force=False)
    keep_larger("x", "atlas", old, {"r-range": (Fraction(1, 2), Fraction(1)), "r values": 1}, force=True)
    with pytest.raises(UsageError, match=r"r-range \]9/125, 1\[\) than this run's \(r-range \]1/2, 1\[\)"):
        keep_larger("x", "atlas", old, {"r-range": (Fraction(1, 2), Fraction(1)), "r values": 300}, force=False)
    with pytest.raises(UsageError, match="r values 200"):
        keep_larger("x", "atlas", old, {"r-range": (Fraction(0), Fraction(1)), "r values": 199}, force=False)
