"""The five-particle census as files (certify/run/census5.py): the same bytes on a rerun and from a
resumed state, the schema, the check that recomputes and compares (and fails on an altered record or
summary), and the faster resultant of five.FiveSpectrum against the engine's."""
import json
import subprocess
import sys
from pathlib import Path

import flint
import pytest

from certify.patterns import five
from certify.run import census5
from certify.run.executors import executor

ROOT = Path(__file__).resolve().parents[2]
L = 4                  # 4 words, seconds (tests/patterns/test_five.py runs the census to 5 against floats)


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    out = tmp_path_factory.mktemp("census5")
    with executor(1) as ex:
        records = census5.run(L, ex, out / "state.jsonl")
    census5.write_outputs(records, L, out)
    return out


def _copy(src: Path, dst: Path) -> Path:
    dst.mkdir(exist_ok=True)
    for name in (census5.JSON, census5.MARKDOWN):
        (dst / name).write_bytes((src / name).read_bytes())
    return dst


def test_a_rerun_and_a_resumed_state_write_the_same_bytes(written, tmp_path):
    """A second run writes the same files byte for byte, and so does a run resumed from the first run's
    state (no word analysed again: the state holds them all)."""
    with executor(1) as ex:
        fresh = census5.run(L, ex)
        census5.write_outputs(fresh, L, tmp_path)
        for name in (census5.JSON, census5.MARKDOWN):
            assert (tmp_path / name).read_bytes() == (written / name).read_bytes()
        calls = []
        resumed = census5.run(L, ex, written / "state.jsonl", resume=True, progress=lambda k, n, w: calls.append(w))
    assert resumed == fresh and all(w == "" for w in calls)


def test_the_census_follows_its_schema(written):
    import jsonschema
    doc = json.loads((written / census5.JSON).read_text(encoding="utf-8"))
    schema = json.loads((ROOT / "certify" / "schemas" / "census5.schema.json").read_text(encoding="utf-8"))
    jsonschema.validate(doc, schema)
    assert doc["census"]["words"] == len(doc["words"]) == len(list(five.word_classes(L)))


def test_the_check_passes_on_the_written_census(written):
    with executor(1) as ex:
        assert census5.check(written, ex) == []


def test_an_altered_record_fails_the_check(written, tmp_path):
    """A record given a feasible set, or with an undecided point dropped, re-rendered so that the summary
    agrees with it (the lie is consistent), is still caught: the word is analysed again."""
    for key, change in (("feasible", lambda rec: ["]1/5, 1/4["]), ("undecided", lambda rec: rec["undecided"][1:])):
        out = _copy(written, tmp_path / key)
        doc = json.loads((out / census5.JSON).read_text(encoding="utf-8"))
        rec = next(r for r in doc["words"] if r["undecided"])
        rec[key] = change(rec)
        census5.write_outputs(doc["words"], L, out)
        with executor(1) as ex:
            problems = census5.check(out, ex)
        assert problems == [f"{rec['word']}: the record differs ({key})"]


def test_an_altered_summary_fails_the_check(written, tmp_path):
    """A changed largest undecided point (the records left alone) is caught."""
    out = _copy(written, tmp_path / "summary")
    doc = json.loads((out / census5.JSON).read_text(encoding="utf-8"))
    doc["census"]["largest_undecided"]["r"]["digits"] = "0.3"
    (out / census5.JSON).write_text(census5.to_json(doc), encoding="utf-8")
    with executor(1) as ex:
        problems = census5.check(out, ex, max_length=4)
    assert "the summary differs from the one recomputed from the records" in problems


def test_the_check_command_exits_1_on_a_difference(written, tmp_path):
    out = _copy(written, tmp_path / "cli")
    doc = json.loads((out / census5.JSON).read_text(encoding="utf-8"))
    doc["words"][0]["verdict"] = "stable"
    census5.write_outputs(doc["words"], L, out)
    run = lambda d: subprocess.run([sys.executable, "-m", "certify", "census", "--particles", "5",  # noqa: E731
                                    "--max-length", "4", "--check", "--out", str(d), "--jobs", "1"],
                                   cwd=ROOT, capture_output=True, text=True)
    bad, good = run(out), run(written)
    assert bad.returncode == 1 and f"{doc['words'][0]['word']}: the record differs (verdict)" in bad.stdout
    assert good.returncode == 0, good.stdout + good.stderr


@pytest.mark.parametrize("word", ["abcbdcb", "ababcad"])
def test_the_resultants_are_the_engines(word, monkeypatch):
    """FiveSpectrum.resultant (the multiplication determinant, Bareiss) equals the engine's subresultant
    (Spectrum.resultant) on every polynomial a word's analysis asks for, as primitive polynomials."""
    from certify.algebra.branches import Spectrum
    asked = []
    mine = five.FiveSpectrum.resultant

    def spy(self, g):
        R = mine(self, g)
        asked.append((self, g, R))
        return R
    monkeypatch.setattr(five.FiveSpectrum, "resultant", spy)
    five.analyse_five(word)
    assert len(asked) >= 5
    for sp, g, R in asked[:12]:
        assert R == Spectrum.resultant(sp, g)


def test_bareiss_is_the_determinant():
    """bareiss_determinant against python-flint's integer determinant at r = 0..8, on a 5×5 matrix of
    random integer polynomials with zero pivots forced (rows swapped)."""
    import random
    rng = random.Random(39)
    A = [[flint.fmpz_poly([rng.randint(-9, 9) for _ in range(rng.randint(0, 4))]) for _ in range(5)] for _ in range(5)]
    A[0][0] = flint.fmpz_poly(0)
    d = five.bareiss_determinant(A)
    for r0 in range(9):
        assert d(r0) == flint.fmpz_mat([[e(r0) for e in row] for row in A]).det()


COMMITTED = ROOT / "reports"


def test_the_committed_census_stands_to_5():
    """reports/census5.json: its summary and CENSUS5.md recomputed from its records, and its words to 5
    analysed again, agree."""
    with executor(1) as ex:
        assert census5.check(COMMITTED, ex, max_length=5) == []


def test_an_altered_committed_record_fails_the_check(tmp_path):
    """A record of reports/census5.json given a stable window (the summary re-rendered to agree) fails the
    check, which names the word and the field."""
    out = _copy(COMMITTED, tmp_path)
    doc = json.loads((out / census5.JSON).read_text(encoding="utf-8"))
    rec = next(r for r in doc["words"] if r["length"] == 5 and not r["stable"])
    rec["stable"] = ["]1/4, 2/7["]
    census5.write_outputs(doc["words"], doc["census"]["max_length"], out)
    with executor(1) as ex:
        problems = census5.check(out, ex, max_length=5)
    assert problems == [f"{rec['word']}: the record differs (stable)"]


def test_a_factor_not_analysed_is_named_in_the_verdict_and_the_markdown(written):
    """The length-4 words all have a repeated factor of cp(Λ²M) (κ = ±r^k): each record's verdict names
    it as not analysed on the whole range (the verdict of the factors analysed alone said "no candidate"),
    and CENSUS5.md excepts the factors not analysed from its answers and qualifies its counts."""
    doc = json.loads((written / census5.JSON).read_text(encoding="utf-8"))
    words = [w for w in doc["words"] if w["not_analysed"]]
    assert words
    for w in words:
        assert "not analysed: the factor(s) " + w["not_analysed"][0]["factor"] in w["verdict"], w["verdict"]
    assert all("not analysed" not in w["verdict"] for w in doc["words"] if not w["not_analysed"])
    md = (written / census5.MARKDOWN).read_text(encoding="utf-8")
    assert "and less the factors not analysed (below), on the whole range" in md
    assert "| exists (factors analysed) | feasible (factors analysed) |" in md
