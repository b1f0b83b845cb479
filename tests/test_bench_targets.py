"""benchmarks/bench_targets.py (``certify bench --targets``): one line per target with the
ratio to the plain script, and the section of BENCH.md saying which targets are met."""
import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _module():
    spec = importlib.util.spec_from_file_location("bench_targets", ROOT / "benchmarks" / "bench_targets.py")
    module = sys.modules[spec.name] = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_targets_are_timed_and_written(monkeypatch, tmp_path, capsys):
    import benchmarks.bench as bench
    M = _module()
    seconds = iter([2.0, 2.2, 1.0, 0.5])                 # script, engine for each target, in that order
    monkeypatch.setattr(M, "median_seconds", lambda f, repeat: next(seconds))
    monkeypatch.setattr(bench, "time_command", lambda repeat, args=None: [1.1] if args else [7.0])
    monkeypatch.setattr(bench, "BENCH", tmp_path / "BENCH.md")
    assert M.main(["--all", "--repeat", "1"]) == 0
    out = capsys.readouterr().out
    assert "ratio 1.10 to the script on " + M.TARGETS[0][1] in out           # orbit: 2.2 / 2.0
    text = (tmp_path / "BENCH.md").read_text()
    rows = [line for line in text.splitlines() if line.startswith("| `")]
    assert len(rows) == 5
    assert "| 1.10× | met (≤ 1.2×) |" in rows[0]
    assert "| 0.55× | met (≤ 0.6×) |" in rows[2]                                # pattern: 1.1 / 2.0
    assert "| 0.50× | met (≤ 0.6×, a stricter reading) |" in rows[1]              # in process / its own word's script
    assert "| 1.10× | **not met** (≤ 0.6×, a stricter reading) |" in rows[3]     # whole command / its own word's
    assert "| 3.50× | **not met** (≤ 3.0×) |" in rows[4]                          # all: 7.0 / 2.0


def test_census_speed_analyses_every_word_of_each_length_and_counts_words_per_second(monkeypatch, capsys):
    from certify.patterns import census
    M = _module()
    seen = []
    monkeypatch.setattr(census, "analyse_word", seen.append)
    monkeypatch.setattr(M, "median_seconds", lambda f, repeat: (f(), 2.0)[1])       # runs the job once
    rows = M.census_speed((4, 5), repeat=1)
    assert seen == census.words_of_length(4) + census.words_of_length(5) == ["abcb", "abacb", "abcab"]
    assert rows == ["| 4 | 1 | 2.00 | 0.50 |", "| 5 | 2 | 2.00 | 1.00 |"]


def test_bench_targets_with_census_writes_its_own_section(monkeypatch, tmp_path, capsys):
    import benchmarks.bench as bench
    M = _module()
    monkeypatch.setattr(M, "census_speed", lambda lengths, repeat: ["| 8 | 6 | 3.00 | 2.00 |"])
    monkeypatch.setattr(M, "median_seconds", lambda f, repeat: 1.0)
    monkeypatch.setattr(bench, "time_command", lambda repeat, args=None: [1.0])
    monkeypatch.setattr(bench, "BENCH", tmp_path / "BENCH.md")
    assert M.main(["--all", "--census", "--repeat", "1"]) == 0
    text = (tmp_path / "BENCH.md").read_text()
    assert "census speed (issue 35)" in text and "| 8 | 6 | 3.00 | 2.00 |" in text
    assert "targets (issue 26)" in text
