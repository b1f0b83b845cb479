"""tools/five_float_census.py (observed, floats): its attracting orbits against the exact census's
(reports/census5.json) on every word of 9 and 10, and its numpy filter against the per-r check."""
import importlib.util
import json
import re
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
spec = importlib.util.spec_from_file_location("five_float_census", ROOT / "tools" / "five_float_census.py")
scan = importlib.util.module_from_spec(spec)
spec.loader.exec_module(scan)

POINTS = 200
NUMBER = re.compile(r"\d+\.\d+|(?<![\d.])[01](?![\d.])")


@pytest.fixture(scope="module")
def grid():
    scan._setup(POINTS)
    return scan._STATE


def census_windows(kind: str) -> dict[str, list[tuple[float, float]]]:
    """{word: [(lo, hi)]} of the committed census's attracting orbits of ``kind`` ('real' or 'complex')."""
    words = json.loads((ROOT / "reports" / "census5.json").read_text())["words"]
    out = {}
    for rec in words:
        spans = []
        for text in rec["reduction"][f"attracting_{kind}"]:
            ends = [float(x) for x in NUMBER.findall(text.split(":", 1)[1])]
            spans += list(zip(ends[::2], ends[1::2]))
        if spans:
            out[rec["word"]] = spans
    return out


@pytest.mark.parametrize("length", [9, 10])
def test_the_scan_finds_the_census_attractors_and_no_others(grid, length):
    """Every word of ``length``: attracting exactly at the grid points inside the census's certified sets
    (points within 10⁻³ of an end not compared)."""
    words = [w for w in scan.word_classes(length) if len(w) == length]
    exact = {kind: census_windows(kind) for kind in ("real", "complex")}
    seen_any = False
    for w in words:
        found = scan.attractors(w, grid["K"], grid["steps"])
        for kind in ("real", "complex"):
            spans = exact[kind].get(w, [])
            for i, r in enumerate(grid["rs"]):
                x = float(r)
                if any(min(abs(x - lo), abs(x - hi)) < 1e-3 for lo, hi in spans):
                    continue
                assert (i in found.get(kind, [])) == any(lo < x < hi for lo, hi in spans), (w, kind, x)
                seen_any = seen_any or i in found.get(kind, [])
    assert seen_any == (length == 10)                   # abadcbcabc is the only one up to 10


@pytest.mark.parametrize("word", ["abadcbcabc", "ababcbcdcdbcdbcbabc"])
def test_the_filter_keeps_every_attracting_point(grid, word):
    """The numpy filter drops no r where the per-r check alone finds an attracting orbit (both kinds for
    the 19-letter word, whose pair turns complex at ≈0.2592)."""
    full = {}
    for i in range(POINTS):
        M = grid["K"][word[0]][i]
        for c in word[1:]:
            M = grid["K"][c][i] @ M
        for *_, kind in scan.floats.orbits_of(word, M, grid["steps"][i]):
            if kind:
                full.setdefault(kind, []).append(i)
    assert scan.attractors(word, grid["K"], grid["steps"]) == full
    assert set(full) == ({"real"} if len(word) == 10 else {"real", "complex"})


def test_runs_and_bad_input(capsys):
    assert scan.runs([5, 3, 4, 9]) == [(3, 5), (9, 9)]
    assert scan.main(["--length", "3"]) == 2
    assert "at least 4" in capsys.readouterr().err
    assert np.isclose(float(scan.grid(4)[0]), 0.2)
