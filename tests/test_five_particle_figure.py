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


# The stable window of each committed word, to 6 decimals, as the float datum of
# tools/five_particle_search.py puts it (observed, docs/particles.md): the certified ends must agree.
FLOAT_WINDOWS = {
    "abadcbcabc": (0.250122, round(2 - math.sqrt(3), 6)),
    "ababcbcdcdbcdbcbabc": (0.225155, 0.259241),
    "abacbacbdcbcdcdbcdbcabcb": (0.212310, 0.212936),
    "abacbacbcdcbcdcdbcdbcbabcb": (0.206064, 0.206808),
    "abacbacbcbdcbcdcdbcdbcbabcb": (0.201452, 0.201939),
    "abacbacbcbdcbcdcdbcdbcbcabcb": (0.201913, 0.206054),
    "ababcbcabacbacbdcbdcdcbcbdcdbcdbcabc": (0.187070, 0.187596),
    "ababcbcabacbacbcabacbcdcbdcdcbcbdcdbcdbcbdcdbcbabc": (0.181800, 0.181845),
    # upper end: the datum at 50 digits (docs/particles.md); the float datum says 0.178700 (rounding)
    "abacbacbcabacbcbabacbcdcdbcbdcdbcdbcbdcdbcbcdcdbcbabacbc": (0.178587, 0.178701),
    # the half route's words (certify pattern --half): the float datum from N = J·M_X (--half of the search)
    "abacbacbcabacbcabacbcbabacbcdcdbcbdcdbcbdcdbcdbcbdcdbcbdcdbcbcdcdbcbabacbcabacbc": (0.175108, 0.175113),
    "abacbacbcabacbcabacbcabacbcbabacbcdcdbcbdcdbcbdcdbcbdcdbcdbcbdcdbcbdcdbcbdcdbcbcdcdbcbabacbcabacbcabacbc":
        (0.173649, 0.173650),
    # 60 letters: the float datum is at its rounding limit (stable at 1131 of 1301 points of ]0.1793, 0.1806[, with
    # scattered gaps); the datum at 50 digits puts the ends at 0.17938467006 and 0.18053842746
    "ababcbcabacbacbcabacbcbdcbcdcbdcdcbcbdcdbcdbcbdcdbcbcabcbabc": (0.179385, 0.180538),
    # F₁(2)·A, 68 letters: the datum at 50 digits puts the ends at 0.17645855020 and 0.17647846889
    "abacbcabacbcabcabacbcabacbcbabacbcdcdbcbdcdbcbdcbdcdbcbdcdbcbcdcdbcb": (0.176459, 0.176478),
    # F₁(3)·A, 92 letters: the datum at 50 digits puts the ends at 0.17423689616 and 0.17423864553
    "abacbcabacbcabacbcabcabacbcabacbcabacbcbabacbcdcdbcbdcdbcbdcdbcbdcbdcdbcbdcdbcbdcdbcbcdcdbcb":
        (0.174237, 0.174239),
    # F₁(4)·A, 116 letters (on x₊): the datum at 50 digits puts the ends at 0.17323577081 and 0.17323607271
    "abacbcabacbcabacbcabacbcabcabacbcabacbcabacbcabacbcbabacbcdcdbcbdcdbcbdcdbcbdcdbcbdcbdcdbcbdcdbcbdcdbcbdcdbcbcdcdbcb":
        (0.173236, 0.173236),
    # 128 letters: the float datum from N is at its rounding limit (stable at scattered points of
    # ]≈0.17293420, ≈0.17293436[); to 6 decimals it agrees with the certified window
    "abacbacbcabacbcabacbcabacbcabacbcbabacbcdcdbcbdcdbcbdcdbcbdcdbcbdcdbcdbcbdcdbcbdcdbcbdcdbcbdcdbcbcdcdbcbabacbc"
    "abacbcabacbcabacbc": (0.172934, 0.172934),
}


def test_the_committed_results_are_the_certified_stable_words():
    """Each committed file is a five-particle pattern result named by its word, and the figure's rows
    are their stable windows, where the float datum puts them: abadcbcabc on ]≈0.25012, 2 − √3[, the
    19-letter word on ]≈0.22516, ≈0.25924[, and the longer words met by the five-particle reduction
    (docs/particles.md); each word's windows are one interval up to common end points (the 27-letter
    word is stable on x₊ then x₋, the point between them undecided)."""
    results = committed()
    assert sorted(results) == sorted(FLOAT_WINDOWS)
    for word, doc in results.items():
        assert doc["system"] == "five" and doc["input"] == word == doc["normal_form"]
    rows = dict(five_figure.five_particle_windows(results))
    assert sorted(rows) == sorted(FLOAT_WINDOWS)
    for word, (lo, hi) in FLOAT_WINDOWS.items():
        windows = rows[word]
        assert [round(windows[0][0], 6), round(windows[-1][1], 6)] == [lo, hi], word
        assert all(a[1] == b[0] for a, b in zip(windows, windows[1:])), word   # one window, up to end points


def one_digit_changed(text: bytes) -> bytes:
    """The file with the last digit of its first stable window's upper end changed (once)."""
    digits = json.loads(text)["stable"][0]["pieces"][0]["hi"]["digits"]
    other = digits[:-1] + ("1" if digits[-1] != "1" else "2")
    assert text.count(digits.encode()) >= 1
    return text.replace(digits.encode(), other.encode(), 1)


@pytest.mark.parametrize("name", sorted(p.name for p in tool.COMMITTED.glob("*.json")))
def test_check_names_a_committed_file_that_is_not_reproduced(tmp_path, name):
    """differences() compares the bytes a fresh analysis prints with the committed file: for every
    committed file, a copy with one digit of its stable window's end altered is named, the untouched
    copy is not (fresh output stubbed by the committed bytes: the real analysis is the slow test
    below and --check)."""
    src = tool.COMMITTED / name
    data = json.loads(src.read_text(encoding="utf-8"))
    good, bad = tmp_path / "good.json", tmp_path / "bad.json"
    good.write_bytes(src.read_bytes())
    bad.write_bytes(one_digit_changed(src.read_bytes()))
    assert bad.read_bytes() != good.read_bytes()

    flags = ("--half",) if "half route" in data["explanation"] else ()

    def fresh(word, r_range, *given):
        assert (word, r_range, given) == (data["input"], data["r_range"], flags)
        return src.read_bytes()
    assert tool.differences([good, bad], fresh) == [
        f"bad.json: certify pattern {data['input']} --r-range {' '.join(data['r_range'])}"
        f"{''.join(' ' + f for f in flags)} prints something else now"]


@pytest.mark.slow
def test_the_ten_letter_result_is_reproduced_by_certify_pattern():
    """`certify pattern abadcbcabc --json --r-range 0 1` prints the committed file's bytes (about 20 s);
    the longer words' (1-6 min of CPU each) are `python tools/five_particle_figure.py --check`."""
    assert tool.differences([tool.COMMITTED / "abadcbcabc.json"]) == []
    assert census.windows({"result": committed()["abadcbcabc"]})


def test_the_family_of_f2_is_certified_for_k_1_to_4():
    """X_k = A^k·abacbacbc·A^k·b·A (A = abacbc), W_k = X_k·m(X_k): the committed results of k = 1, 2, 3, 4
    (56, 80, 104, 128 letters) each have one certified stable window, each strictly below the one before
    (exact rationals of the isolating intervals); k = 5 (152 letters) is not committed."""
    from certify.patterns.five import FAMILY_CORES
    results = committed()
    core = FAMILY_CORES["F₂"]
    assert five_figure.family_problems(results, core, range(1, 5)) == []
    rows = five_figure.family_rows(results, core, range(1, 6))
    assert [len(w) for _k, w, _s in rows] == [24 * k + 32 for k in range(1, 6)] and rows[-1][2] is None
    assert all(windows for _k, _w, windows in rows[:4])


def test_the_family_of_f1_is_certified_for_k_2_to_4():
    """X_k = A^k·abc·A^k·b·A, W_k = X_k·m(X_k): the committed results of k = 2, 3, 4 (68, 92, 116 letters)
    each have one certified stable window, each strictly below the one before and in its rule interval;
    without member 3 the check names it."""
    from certify.patterns.five import FAMILY_CORES, family_word
    results, core = committed(), FAMILY_CORES["F₁"]
    assert five_figure.family_problems(results, core, range(2, 5)) == []
    # the ends to 10 decimals, as the datum at 50 digits puts them (6 decimals, FLOAT_WINDOWS, do not
    # separate F₁(4)·A's ends, 3·10⁻⁷ apart)
    rows = dict(five_figure.five_particle_windows(results))
    for k, ends in ((2, (0.17645855020, 0.17647846889)), (3, (0.17423689616, 0.17423864553)),
                    (4, (0.17323577081, 0.17323607271))):
        windows = rows[family_word(core, k)]
        assert [windows[0][0], windows[-1][1]] == pytest.approx(ends, abs=1e-10), k
    w3 = family_word(core, 3)
    assert five_figure.family_problems({w: d for w, d in results.items() if w != w3}, core, range(2, 5)) == [
        f"k = 3: {w3} has no certified stable window (one interval)"]


def test_a_family_member_dropped_or_out_of_order_is_named():
    """Without member k = 2, with the results of members 1 and 2 swapped (member 2's window then lies
    above member 1's, and each outside its rule interval), or with member 3's stable set emptied, the
    family check names the member."""
    from certify.patterns.five import FAMILY_CORES, family_word
    core = FAMILY_CORES["F₂"]
    results = committed()
    w1, w2, w3 = (family_word(core, k) for k in (1, 2, 3))
    dropped = {w: d for w, d in results.items() if w != w2}
    assert five_figure.family_problems(dropped, core, range(1, 4)) == [
        f"k = 2: {w2} has no certified stable window (one interval)"]
    swapped = dict(results, **{w2: results[w1], w1: results[w2]})
    assert five_figure.family_problems(swapped, core, range(1, 4)) == [    # and each crosses its resonances
        "k = 1: (1, 1): the window reaches below r_5/11 ≈ 0.176636779067",
        f"k = 2: the window of {w2} does not lie below member k - 1's",
        "k = 2: (2, 1): the window reaches above r_6/13 ≈ 0.175174520939"]
    empty = dict(results, **{w3: dict(results[w3], stable=[])})
    assert five_figure.family_problems(empty, core, range(1, 4)) == [
        f"k = 3: {w3} has no certified stable window (one interval)"]


def test_a_long_word_is_labelled_by_its_start_and_length():
    """The rows of words longer than LABEL letters show their first 24 letters and their length (the
    axes are not narrowed by 104-letter labels); shorter words show whole."""
    assert five_figure.label("abadcbcabc") == "abadcbcabc"
    long = max(committed(), key=len)
    assert five_figure.label(long) == f"{long[:24]}… ({len(long)} letters)" and len(long) > five_figure.LABEL
