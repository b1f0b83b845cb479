"""benchmarks/bench_atlas.py: the sampled jobs of an atlas timed one by one, and the estimate of the
whole atlas's CPU (each kind's sample times its sampling step) and of its wall time on two cores."""
import importlib.util
import sys
from pathlib import Path

from certify.run import atlas

ROOT = Path(__file__).resolve().parents[1]


def _module():
    spec = importlib.util.spec_from_file_location("bench_atlas", ROOT / "benchmarks" / "bench_atlas.py")
    module = sys.modules[spec.name] = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_estimate_is_each_sample_times_its_step_and_two_cores_or_the_longest_job():
    M = _module()
    out = {"r": [("1/2", 3.0), ("3/4", 5.0)], "horseshoe": [("1/2", 1.0), ("3/4", 1.0)], "word": [("abcb", 20.0)]}
    text = M.table(out, {"r": 10, "horseshoe": 10, "word": 6})
    assert "| r | 2 | 8.0 | 4.00 | 5.0 | 80 |" in text and "| word | 1 | 20.0 | 20.00 | 20.0 | 120 |" in text
    assert "estimated CPU of the atlas: 220 s; on two cores at best 1.8 min" in text
    text = M.table({"r": [], "horseshoe": [], "word": [("abcb", 500.0)]}, {"r": 1, "horseshoe": 1, "word": 1})
    assert "at best 8.3 min" in text                   # one job longer than half the total: its own time


def test_the_sample_takes_every_kth_r_in_order_and_every_kth_word():
    M = _module()
    p = {"data": 0, "collisions": 2000, "word_seconds": 60, "word_max": 4}
    doc = {"parameters": p, "r": [{"r": r} for r in ("7/10", "3/10", "1/2")],
           "words": [{"word": w} for w in ("abcb", "ababcbcb", "abacbc")]}
    log: list = []
    out = M.sample(doc, 2, 2, log=log.append)
    assert [r for r, _s in out["r"]] == ["1/2"] == [r for r, _s in out["horseshoe"]]   # 3/10, 1/2, 7/10: the 2nd
    assert [w for w, _s in out["word"]] == ["ababcbcb"] and "too long" in log[-1]     # over word_max: no cost
    assert atlas.word_job("ababcbcb", 60, 4)["outcome"] == "too long"
