"""benchmarks/bench_census.py: the seconds per length read from a state file, and the
extrapolation of the census's time (exact word counts times a fitted mean)."""
import importlib.util
import json
import math
import sys
from pathlib import Path

from certify.patterns import census

ROOT = Path(__file__).resolve().parents[1]


def _module():
    spec = importlib.util.spec_from_file_location("bench_census", ROOT / "benchmarks" / "bench_census.py")
    module = sys.modules[spec.name] = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_seconds_by_length_adds_both_parts_and_keeps_the_last_line_of_a_word(tmp_path):
    M = _module()
    state = tmp_path / "state.jsonl"
    lines = [{"word": "abcb", "length": 4, "feasible": True, "seconds": 1.0},
             {"word": "abcb", "length": 4, "feasible": True, "seconds": 1.0, "reduction_seconds": 0.5},
             {"word": "abacb", "length": 5, "feasible": False, "seconds": 2.0, "reduction_seconds": 1.0}]
    state.write_text("".join(json.dumps(x) + "\n" for x in lines) + '{"word": "cut')
    assert M.seconds_by_length(state) == {4: [(1.5, "abcb", True)], 5: [(3.0, "abacb", False)]}


def test_the_extrapolation_multiplies_exact_counts_by_the_fitted_growth():
    M = _module()
    means = {8: 1.0, 9: 2.0, 10: 4.0}                     # doubling per collision: the fit must find it
    rows = M.extrapolate(means, 12, cores=(2,))
    assert "2.000× per collision" in rows[0]
    counts = {n: len(census.words_of_length(n)) for n in range(8, 13)}
    expected = sum(counts[n] * 2.0 ** (n - 8) for n in range(8, 13)) / 3600
    last = rows[-1].strip("|").split("|")
    assert int(last[0]) == 12 and int(last[1]) == len(census.words(12)) and int(last[2]) == counts[12]
    assert math.isclose(float(last[3]), 16.0) and math.isclose(float(last[4]), round(expected, 1))
    assert math.isclose(float(last[5]), round(expected / 2, 2))


def test_an_anchored_extrapolation_costs_the_anchor_at_its_length_and_grows_by_the_fit():
    M = _module()
    rows = M.extrapolate({8: 1.0, 9: 2.0, 10: 4.0}, 12, cores=(1,), anchor=(10, 3600.0), rows_from=10)
    table = [r.strip("|").split("|") for r in rows[4:]]
    assert [int(t[0]) for t in table] == [10, 11, 12]
    assert math.isclose(float(table[0][4]), 1.0)                       # the census to 10: the anchor's hour
    counts = {n: len(census.words_of_length(n)) for n in range(1, 13)}
    level = 3600.0 / sum(counts[n] * 2.0 ** n for n in range(1, 11))
    assert math.isclose(float(table[2][3]), round(level * 2.0 ** 12, 2))
    assert math.isclose(float(table[2][4]), round(level * sum(counts[n] * 2.0 ** n for n in range(1, 13)) / 3600, 1))
