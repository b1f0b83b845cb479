"""tools/five_particle_search.py (observed, floats): its datum against certify pattern's exact sets for
four particles, and the five-particle word it finds."""
import importlib.util
from pathlib import Path

import pytest

from certify.patterns.pattern import analyse

ROOT = Path(__file__).resolve().parents[1]
spec = importlib.util.spec_from_file_location("five_particle_search", ROOT / "tools" / "five_particle_search.py")
search = importlib.util.module_from_spec(spec)
spec.loader.exec_module(search)


def inside(intervals, r: float, margin: float = 1e-3) -> bool | None:
    """True/False away from the ends (None within ``margin`` of one)."""
    for lo, hi in intervals:
        a, b = float(lo.digits(15)), float(hi.digits(15))
        if min(abs(r - a), abs(r - b)) < margin:
            return None
        if a < r < b:
            return True
    return False


@pytest.mark.parametrize("word", ["ababcbcb", "abcb", "ababcb"])
def test_the_datum_of_two_eigenvalues_is_the_pattern_for_four_particles(word):
    """Stable and feasible at r exactly where certify pattern's exact analysis says so (grid of 0.01)."""
    res = analyse(word)
    stable = [(lo, hi) for *_, lo, hi in res.intervals("stable")]
    feasible = [(lo, hi) for *_, lo, hi in res.intervals("feasible")]
    for k in range(1, 100):
        r = k / 100
        found = search.data(word, r, 4)
        for expected, seen in ((inside(stable, r), any(s for *_, s in found)), (inside(feasible, r), bool(found))):
            assert expected is None or expected == seen, (word, r)


def test_the_five_particle_word():
    """abadcbcabc: stable at 0.26, feasible but not stable at 0.2, neither at 0.27."""
    assert any(s for *_, s in search.data("abadcbcabc", 0.26, 5))
    assert search.data("abadcbcabc", 0.2, 5) and not any(s for *_, s in search.data("abadcbcabc", 0.2, 5))
    assert not search.data("abadcbcabc", 0.27, 5)
    assert search.canonical("abcbdcbdcd", "abcd") == "abadcbcabc"     # its mirror (a↔d, b↔c), rotated


def test_words_are_classes():
    ws = list(search.words(6, 5))
    assert len(ws) == len(set(ws)) and all(set(w) == set("abcd") for w in ws)
    assert all(search.canonical(w, "abcd") == w for w in ws)
