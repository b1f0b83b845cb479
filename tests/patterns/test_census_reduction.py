"""The census, both ways: each record's periodic orbits of the reduction beside its
self-similar analysis (certify/patterns/census.py, certify/run/census_report.py);
resume completes older records by the missing part only; the exact union of the
attracting windows; the families; the wording of CENSUS.md and README."""
import json
from pathlib import Path

import flint
import pytest

from certify.algebra.algebraic import Algebraic
from certify.patterns import census
from certify.run import census_report as run_census
from certify.run.executors import Serial

ROOT = Path(__file__).resolve().parents[2]
COMPLEX = "abacbabcbcabcb"           # the simulator's attractor at r = 0.3 (period 14)


def _exact(windows):
    """Sorted exact keys of (lo, hi) end-point pairs."""
    return sorted((census.end_number(a).key(), census.end_number(b).key()) for a, b in windows)


def _stable(record):
    return [(p["lo"], p["hi"]) for s in record["result"]["stable"] for p in s["pieces"] if p["kind"] == "interval"]


@pytest.fixture(scope="module")
def ab2cb2():
    return census.analyse_word("ababcbcb")


def test_ab2cb2_attracting_windows_of_the_reduction_are_its_stable_self_similar_windows(ab2cb2):
    """Two routes, one answer (L4-L5): the attracting windows of the reduction in the
    census record equal, end for end as algebraic numbers, its stable self-similar windows."""
    stable = _stable(ab2cb2)
    attracting = [(a, b) for a, b, _pair in census.attracting_windows(ab2cb2)]
    assert stable and ab2cb2["stable"]
    assert _exact(attracting) == _exact(stable)
    assert [p for *_ab, p in census.attracting_windows(ab2cb2)] == ["real"]
    assert ab2cb2[census.REDUCTION]["attracting"] is True


def test_the_self_similar_part_is_the_pattern_record_unchanged(ab2cb2):
    alone = census.self_similar_record("ababcbcb")
    for key in (census.SECONDS, census.REDUCTION_SECONDS):
        alone.pop(key, None)
    assert {k: v for k, v in ab2cb2.items() if k not in (census.REDUCTION, *census.TIMES)} == alone


def test_the_complex_pair_attractor_holds_three_tenths_and_has_no_stable_self_similar_window():
    rec = census.analyse_word(COMPLEX)
    assert not rec["stable"] and _stable(rec) == []
    r0 = Algebraic.rational(flint.fmpq(3, 10))
    hits = [(a, b, p) for a, b, p in census.attracting_windows(rec)
            if census.end_number(a) < r0 < census.end_number(b)]
    assert len(hits) == 1 and hits[0][2] == "complex"
    text = run_census.markdown(run_census.document([rec], 14))
    assert "complex pair" in text and "not a collapse" in text


def test_resume_computes_only_the_missing_reduction_part(tmp_path):
    """A state written by an older census (self-similar records only) is completed: no
    word is analysed again by pattern, each gets its reduction part, and the result is
    the census of a fresh run; a second resume computes nothing."""
    words = census.words(4)
    state = tmp_path / "state.jsonl"
    old = [census.self_similar_record(w) for w in words]
    state.write_text("".join(run_census.dumps(r) + "\n" for r in old))
    completed = []

    def complete(record):
        completed.append(record["word"])
        return census.add_reduction(record)

    def job(word):
        raise AssertionError(f"{word} analysed again")
    records = run_census.run_census(4, Serial(), state, resume=True, job=job, complete=complete)
    assert completed == words
    for rec, before in zip(records, old):
        assert {k: v for k, v in rec.items() if k != census.REDUCTION} == \
            {k: v for k, v in before.items() if k not in census.TIMES}
        assert rec[census.REDUCTION]["outcome"] in ("analysed", "three particles")
    fresh = run_census.run_census(4, Serial())
    assert run_census.to_json(run_census.document(records, 4)) == run_census.to_json(run_census.document(fresh, 4))
    completed.clear()
    again = run_census.run_census(4, Serial(), state, resume=True, job=job, complete=complete)
    assert completed == [] and again == records
    lines = [json.loads(x) for x in state.read_text().splitlines()]
    assert len(lines) == 2 * len(words) and all(census.REDUCTION_SECONDS in x for x in lines[len(words):])


# ----------------------------------------------------------------- the union, the families
def _end(p, lo, hi):
    return {"exact": None, "minimal_polynomial": p, "interval": [lo, hi], "digits": lo}


SILVER = _end("r^2 - 6r + 1", "0.171572875253", "0.171572875254")       # 3-2√2
SIX = _end("r^2 - 10r + 1", "0.101020514433", "0.101020514434")        # 5-2√6
HALF = {"exact": "1/2", "minimal_polynomial": "r - 1/2", "interval": ["1/2", "1/2"], "digits": "0.5"}
ONE_TENTH = {"exact": "1/10", "minimal_polynomial": "10r - 1", "interval": ["1/10", "1/10"], "digits": "0.1"}


def test_union_merges_overlaps_exactly_and_lists_the_gaps():
    u = census.union([(SIX, HALF), (ONE_TENTH, SILVER), (SIX, SILVER)])
    assert [(i["lo"]["digits"], i["hi"]["digits"]) for i in u["intervals"]] == [("0.1", "0.5")]
    assert u["set"] == "]1/10, 1/2["
    assert census.show_gaps(u) == "]0, 1/10] ∪ [1/2, 1["
    apart = census.union([(ONE_TENTH, SIX), (SILVER, HALF)], [SIX])     # 1/10 < 5-2√6 < 3-2√2
    assert apart["set"] == "]1/10, ≈0.1010205144[ ∪ ]≈0.1715728753, 1/2[ ∪ {≈0.1010205144}"
    assert census.show_gaps(apart).count("∪") == 2


def test_integer_polynomials_read_back_as_written():
    from certify.algebra.poly import show
    for coeffs in ([1, -10, 10, -10, 1], [1, -6, 1], [-1, 1], [0, 1], [3, 0, -14, 0, 0, 2]):
        assert census._integer_poly(show(flint.fmpz_poly(coeffs))) == coeffs


def test_families_find_ab_n_cb_n_and_need_three_consecutive_members():
    ab = ["ababcbcb", "abababcbcbcb", "ababababcbcbcbcb"]
    fams = census.families(ab + ["abacbacbcb"])
    assert [f["members"] for f in fams] == [ab] and fams[0]["repeated"] == ["ab", "cb"]
    assert census.families([ab[0], ab[2], "abacbacbcb"]) == []           # n = 3 missing: no family
    grown = [census.normal_form("ab" + "acb" * n + "cb")[0] for n in (1, 2, 3)]
    assert [f["members"] for f in census.families(grown)] == [grown]


# ----------------------------------------------------------------- the two notions, named apart
def test_census_md_and_readme_name_the_two_notions_apart():
    for path in (ROOT / "reports" / "CENSUS.md", ROOT / "README.md"):
        text = path.read_text(encoding="utf-8")
        assert "stable self-similar (collapsing) data" in text, path
        assert "attracting periodic orbit of the reduction" in text, path
        assert "no stable pattern other than" not in text, path


def test_census_md_names_the_window_ends_that_are_resonances_of_the_island():
    """CENSUS.md's resonance lines are what island_theorem.window_resonances decides on the
    committed census.json (2 − √3 is ρ = 1/3: a(bac)^2bcb's upper end); a window moved off
    the resonance loses its line."""
    import json

    doc = json.loads((ROOT / "reports" / "census.json").read_text(encoding="utf-8"))
    by = {r["word"]: r for r in doc["words"]}
    windows = doc["census"]["reduction"]["attracting_windows"]
    lines = run_census.resonance_lines(windows, by)
    text = (ROOT / "reports" / "CENSUS.md").read_text(encoding="utf-8")
    assert all(line in text for line in lines if line)
    assert any("`a(bac)^2bcb`: its upper end" in line and "ρ = 1/3" in line for line in lines)
    word = next(w for w in windows if by[w]["compact"] == "a(bac)^2bcb")
    moved = {word: [dict(span, hi={"exact": "27/100", "digits": "0.27"}) for span in windows[word]]}
    assert run_census.resonance_lines(moved, by)[2:] == ["- none", ""]
