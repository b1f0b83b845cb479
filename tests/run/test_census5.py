"""The five-particle census as files (certify/run/census5.py): the same bytes on a rerun and from a
resumed state, the schema, the check that recomputes and compares (and fails on an altered record or
summary), and the faster routes of five.FiveSpectrum (resultants, zero tests) against the engine's."""
import functools
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


def test_a_resume_analyses_again_the_records_another_engine_made_otherwise(written, tmp_path, monkeypatch):
    """Every state record carries the engine's mark (census5.json's do not).  On resume, a record of an
    older engine (a record without a mark is engine UNMARKED's) is analysed again when an engine since
    alters it (census5.CHANGED: engine 2 alters the records with a factor not analysed) and reused
    otherwise; engine 3 adds the part on the orbits of the reduction, so an engine-2 record without it is
    kept and completed (census5.complete: five.census_record not called again for it); a record of an
    unknown (newer) engine is analysed again."""
    from certify.patterns.census import REDUCTION
    lines = [json.loads(x) for x in (written / "state.jsonl").read_text(encoding="utf-8").splitlines()]
    assert len(lines) == 4 and all(rec[census5.MARK] == census5.ENGINE == 3 for rec in lines)
    assert all(census5.MARK not in rec for rec in json.loads((written / census5.JSON).read_text())["words"])
    mark = census5.MARK
    factor = [{"factor": "-r^2 + κ", "multiplicity": 2, "stable": "none (proved)"}]     # as engine 1 wrote it
    without = lambda rec: {k: v for k, v in rec.items() if k not in (REDUCTION, mark)}  # noqa: E731
    changed = dict(without(lines[0]), verdict="an older verdict", not_analysed=factor, **{mark: 1})
    unmarked = {**without(lines[1]), "verdict": "an older verdict", "not_analysed": factor}
    kept = dict(without(lines[2]), **{mark: 2})              # engine 2's record: completed, not analysed again
    newer = dict(lines[3], verdict="a newer verdict", **{mark: census5.ENGINE + 1})
    assert [census5.current(rec) for rec in (changed, unmarked, kept, newer)] == [False, False, True, False]
    state = tmp_path / "state.jsonl"
    state.write_text("".join(json.dumps(rec) + "\n" for rec in [changed, unmarked, kept, newer]), encoding="utf-8")
    said, calls, analysed = [], [], []
    with executor(1) as ex:
        fresh = census5.run(L, ex)
        record = five.census_record
        monkeypatch.setattr(five, "census_record", lambda w, shared=None: analysed.append(w) or record(w, shared))
        resumed = census5.run(L, ex, state, resume=True, progress=lambda k, n, w: calls.append(w), notice=said.append)
    assert resumed == fresh
    assert sorted(analysed) == sorted([changed["word"], unmarked["word"], newer["word"]])
    assert kept["word"] in calls and kept["word"] not in analysed
    assert said == [f"3 state record(s) made by another engine than {census5.ENGINE} (first {changed['word']}): "
                    "analysed again"]


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
    """FiveSpectrum.resultant (the Bézout determinant by Laplace's expansion) equals the engine's
    subresultant (Spectrum.resultant) on every polynomial a word's analysis asks for, as primitive
    polynomials."""
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


def _random_matrix(rng, n, degree):
    return [[flint.fmpz_poly([rng.randint(-9, 9) for _ in range(rng.randint(0, degree + 1))]) for _ in range(n)]
            for _ in range(n)]


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5, 6])
def test_laplace_is_the_determinant(n):
    """laplace_determinant against python-flint's integer determinant at more integer r than its degree
    (so the polynomials are equal), on random n×n matrices of integer polynomials with zero entries."""
    import random
    rng = random.Random(39 + n)
    A = _random_matrix(rng, n, 4)
    A[0][0] = flint.fmpz_poly(0)
    d = five.laplace_determinant(A)
    for r0 in range(-2 * n - 1, 2 * n + 2):           # 4n + 3 > 4n ≥ deg det points
        assert d(r0) == flint.fmpz_mat([[e(r0) for e in row] for row in A]).det()


def _mpoly(coeffs):
    """The polynomial Σ_j coeffs[j](r) λ^j in poly.MCTX (r, λ, s)."""
    from certify.algebra.poly import MCTX
    return MCTX.from_dict({(i, j, 0): int(c) for j, col in enumerate(coeffs) for i, c in enumerate(col.coeffs()) if c})


@pytest.mark.parametrize("degree_g", [0, 2, 5, 9])
def test_the_bezout_resultant_is_the_resultant(degree_g):
    """bezout_resultant(g, cp) is python-flint's Res_κ(g, cp) made primitive, for cp of degree 6 in κ with
    leading coefficient 4 (not monic over Z), g of degree below 6 and above it (the pseudo-remainder), and
    with a content; a g sharing a factor with cp gives 0."""
    import random

    from certify.algebra.poly import mpoly_to_univariate, primitive
    rng = random.Random(degree_g)
    poly = lambda d: flint.fmpz_poly([rng.randint(-9, 9) for _ in range(d + 1)])  # noqa: E731
    cp = [poly(3) for _ in range(6)] + [flint.fmpz_poly([4])]
    g = [6 * poly(4) for _ in range(degree_g + 1)]
    expected = primitive(mpoly_to_univariate(_mpoly(g).resultant(_mpoly(cp), "lam")))
    assert five.bezout_resultant(g, cp) == expected and not expected.is_zero()
    # g = (κ - r)·h and cp = (κ - r)·m share the factor κ - r: the resultant is 0
    shift = [flint.fmpz_poly([0, -1]), flint.fmpz_poly([1])]
    times = lambda a, b: [sum((a[i] * b[k - i] for i in range(len(a)) if 0 <= k - i < len(b)),  # noqa: E731
                              flint.fmpz_poly(0)) for k in range(len(a) + len(b) - 1)]
    assert five.bezout_resultant(times(shift, [poly(2) for _ in range(3)]),
                                 times(shift, [poly(2) for _ in range(5)] + [flint.fmpz_poly([4])])).is_zero()


def test_the_high_precision_zero_test_gives_the_engines_answers(monkeypatch):
    """FiveSpectrum's zero test (:meth:`five.FiveSpectrum._attempts`): the engine's attempts (a gcd's roots
    as they come, then the monic gcd's, to 1024 bits), then the roots as they come to 2^16 bits.  Wherever
    a word's analysis asks about a gcd taken as it comes (abdbcd asks twice), its answer is Spectrum's (the
    engine's two routes, the monic gcd made afresh) where that one decides; where that one is undecided,
    the high precision is what decided."""
    from certify.algebra.branches import Spectrum
    from certify.errors import Undecided
    asked = []
    mine = five.FiveSpectrum._vanishes_on

    def spy(self, G, rc, branch, maxprec):
        answer = mine(self, G, rc, branch, maxprec)
        if getattr(G, "fallback", None) is not None:
            asked.append((self, G, rc, branch, maxprec, answer))
        return answer
    monkeypatch.setattr(five.FiveSpectrum, "_vanishes_on", spy)
    five.analyse_five("abdbcd")
    assert len(asked) >= 2
    for sp, G, rc, branch, maxprec, answer in asked:
        engine = functools.partial(G)         # the engine's two routes, its monic gcd made afresh
        engine.fallback = G.fallback  # type: ignore[attr-defined]
        try:
            assert Spectrum._vanishes_on(sp, engine, rc, branch, maxprec) == answer
        except Undecided:                     # then the high precision alone gives the answer
            sp._attempts = lambda G, maxprec: iter([(G, 2 * maxprec, five.AS_IT_COMES_PRECISION)])
            try:
                assert mine(sp, G, rc, branch, maxprec) == answer
            finally:
                del sp._attempts


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


def test_a_factor_not_analysed_is_named_in_the_verdict_and_the_markdown(written, tmp_path, monkeypatch):
    """The length-4 words all have a repeated factor of cp(Λ²M) (κ = r²), analysed on its planes
    (five.REPEATED_ROUTE): CENSUS5.md says every factor is analysed.  Where that route does not apply (here
    made to refuse), each record's verdict names the factor as not analysed on the whole range, and
    CENSUS5.md excepts the factors not analysed from its answers and qualifies its counts."""
    doc = json.loads((written / census5.JSON).read_text(encoding="utf-8"))
    assert len(doc["words"]) == 4 and not any(w["not_analysed"] for w in doc["words"])
    assert all("not analysed" not in w["verdict"] for w in doc["words"])
    md = (written / census5.MARKDOWN).read_text(encoding="utf-8")
    assert "Every factor of cp(Λ²M) is analysed" in md and "less the factors not analysed" not in md

    def refuse(*a, **k):
        raise ArithmeticError("refused")
    monkeypatch.setattr(five, "repeated_candidate", refuse)
    words = [dict(five.census_record(w["word"]), reduction=w["reduction"]) for w in doc["words"]]
    assert all(w["not_analysed"] for w in words)
    for w in words:
        assert "not analysed: the factor(s) " + w["not_analysed"][0]["factor"] in w["verdict"], w["verdict"]
    census5.write_outputs(words, L, tmp_path)
    md = (tmp_path / census5.MARKDOWN).read_text(encoding="utf-8")
    assert "and less the factors not analysed (below), on the whole range" in md
    assert "| exists (factors analysed) | feasible (factors analysed) |" in md
