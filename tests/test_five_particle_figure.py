"""tools/five_particle_figure.py: reports/five-windows.png is drawn from the committed results of
`certify pattern` (reports/five-patterns/), and its --check reproduces them or fails."""
import importlib.util
import json
import math
from pathlib import Path

import pytest

from certify.patterns import census
from certify.run import five_figure

ROOT = Path(__file__).resolve().parents[1]
spec = importlib.util.spec_from_file_location("five_particle_figure", ROOT / "tools" / "five_particle_figure.py")
tool = importlib.util.module_from_spec(spec)
spec.loader.exec_module(tool)


def committed() -> dict:
    return {p.stem: json.loads(p.read_text(encoding="utf-8")) for p in sorted(tool.COMMITTED.glob("*.json"))}


def test_the_committed_results_are_the_two_certified_stable_words():
    """Each committed file is a five-particle pattern result named by its word, and the figure's rows
    are their stable windows: abadcbcabc on ]≈0.25012, 2 − √3[ and the 19-letter word on
    ]≈0.22516, ≈0.25924[ (one window each)."""
    results = committed()
    assert sorted(results) == ["ababcbcdcdbcdbcbabc", "abadcbcabc"]
    for word, doc in results.items():
        assert doc["system"] == "five" and doc["input"] == word == doc["normal_form"]
    rows = dict(five_figure.five_particle_windows(results))
    assert [round(x, 6) for x in rows["abadcbcabc"][0]] == [0.250122, round(2 - math.sqrt(3), 6)]
    assert [round(x, 6) for x in rows["ababcbcdcdbcdbcbabc"][0]] == [0.225155, 0.259241]
    assert all(len(s) == 1 for s in rows.values())


def test_check_names_a_committed_file_that_is_not_reproduced(tmp_path):
    """differences() compares the bytes a fresh analysis prints with the committed file: an end of the
    window altered in a copy is named, the untouched copy is not (fresh output stubbed by the
    committed bytes: the real analysis is the slow test below)."""
    src = tool.COMMITTED / "abadcbcabc.json"
    good, bad = tmp_path / "good.json", tmp_path / "bad.json"
    good.write_bytes(src.read_bytes())
    bad.write_bytes(src.read_bytes().replace(b"0.2501215574", b"0.2501215575", 1))
    assert bad.read_bytes() != good.read_bytes()

    def fresh(word, r_range):
        assert (word, r_range) == ("abadcbcabc", ["0", "1"])
        return src.read_bytes()
    assert tool.differences([good, bad], fresh) == [
        "bad.json: certify pattern abadcbcabc --r-range 0 1 prints something else now"]


@pytest.mark.slow
def test_the_ten_letter_result_is_reproduced_by_certify_pattern():
    """`certify pattern abadcbcabc --json --r-range 0 1` prints the committed file's bytes (about 20 s);
    the 19-letter word's (13 min of CPU) is `python tools/five_particle_figure.py --check`."""
    assert tool.differences([tool.COMMITTED / "abadcbcabc.json"]) == []
    assert census.windows({"result": committed()["abadcbcabc"]})
