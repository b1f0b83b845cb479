"""The census of periodic block patterns (certify census, T28): enumeration, records,
executors (serial, local processes, an in-process Dask cluster), streaming and resume,
the command line, and the certificate T28 (its mutants: tests/proofs/test_mutants.py)."""
import json

import pytest

from certify import cli
from certify.patterns import census
from certify.run import census_report as run_census
from certify.run.executors import Serial, executor
from certify.run.runner import CERTIFICATES, ERRATUM, run_certificate
from proofs import section3_remarks as T28
from tests.shared import as_printed


# ----------------------------------------------------------------- enumeration
def mobius(n):
    out, m, p = 1, n, 2
    while p * p <= m:
        if m % p == 0:
            m //= p
            if m % p == 0:
                return 0
            out = -out
        p += 1
    return -out if m > 1 else out


@pytest.mark.parametrize("L", range(1, 13))
def test_words_are_the_brute_force_classes(L):
    words = census.words(L)
    assert len(words) == len(set(words))
    assert {T28.least_rotation(w) for w in words} == T28.brute_force_classes(L)
    assert words == sorted(words, key=lambda w: (len(w), w))


def test_lyndon_block_words_are_counted_by_the_necklace_formula():
    # Lyndon words of k blocks over 4 blocks: (1/k) Σ_{d|k} μ(d) 4^{k/d}; with lengths 2, 2, 3, 3 they are
    # counted by total length; here: every block sequence of 2-letter blocks only (length 2k).
    seqs = [s for s in census.lyndon_block_words(12) if all(census.BLOCKS[j] in ("ab", "cb") for j in s)]
    for k in range(1, 7):
        expected = sum(mobius(d) * 2 ** (k // d) for d in range(1, k + 1) if k % d == 0) // k
        assert sum(1 for s in seqs if len(s) == k) == expected


def test_known_counts_and_members():
    assert [len(census.words(L)) for L in (2, 3, 4, 5, 8, 12, 16)] == [1, 2, 3, 5, 17, 104, 734]
    assert census.words(5) == ["ab", "acb", "abcb", "abacb", "abcab"]
    assert "ababababcbcbcbcb" in census.words(16)          # (ab)^4(cb)^4
    with pytest.raises(ValueError):
        census.words(0)


def test_blocks_and_containment():
    assert census.blocks_of("abacbcab") == ["ab", "acb", "cab"]
    with pytest.raises(ValueError):
        census.blocks_of("abcba")
    assert census.contains("cab", "abcab")                  # …cabcab… contains abcab
    assert census.contains_abcab("acb")                     # …acbacb… contains cbacb, the mirror
    assert not census.contains_abcab("abcb") and not census.contains_abcab("ababcbcb")
    assert census.contains_abcab("abcabcb")


def test_an_analysis_error_is_a_record_not_an_exception(monkeypatch):
    def boom(word, lo, hi, **options):
        raise ArithmeticError("a factor vanishes\n on a whole branch")
    monkeypatch.setattr(census, "analyse", boom)
    rec = census.analyse_word("abcb")
    assert rec["outcome"] == "error" and rec["verdict"] == "error"
    assert rec["error"] == "ArithmeticError: a factor vanishes on a whole branch"
    assert rec["feasible"] is None and rec["contains_abcab"] is False


def test_a_census_word_leaves_no_memo_behind():
    """A worker analyses thousands of words: each word's memos (its candidate, its
    Spectrum and their sign tables) must not outlive it."""
    from certify.dynamics import words
    census.analyse_word("ababcbcb")
    assert words.candidate.cache_info().currsize == words.spectrum_of.cache_info().currsize == 0


# ----------------------------------------------------------------- running, executors, resume
L_SMALL = 4                                   # ab, acb, abcb: seconds


@pytest.fixture(scope="module")
def reference():
    with executor(1) as ex:
        records = run_census.run_census(L_SMALL, ex)
    return records


def as_json(records):
    return run_census.to_json(run_census.document(records, L_SMALL))


def test_census_json_is_the_document_with_a_record_a_line(reference):
    text = as_json(reference)
    assert json.loads(text) == run_census.document(reference, L_SMALL)
    lines = text.splitlines()
    start = lines.index('"words": [') + 1
    assert [json.loads(line.rstrip(",")) for line in lines[start:-1]] == [run_census.brief(r) for r in reference]
    assert lines[-1] == "]}"


def test_serial_census_lists_every_word(reference):
    assert [r["word"] for r in reference] == census.words(L_SMALL)
    assert all("seconds" not in r for r in reference)
    by = {r["word"]: r for r in reference}
    assert by["ab"]["stable"] and by["abcb"]["feasible"]
    assert all(r["outcome"] in ("analysed", "error") for r in reference)   # errors are listed, never dropped


def test_a_dask_cluster_gives_the_same_bytes(reference):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(processes=False, n_workers=1, threads_per_worker=1,
                                  dashboard_address=None) as cluster:
        with executor(scheduler=cluster.scheduler_address) as ex:
            on_cluster = run_census.run_census(L_SMALL, ex)
        with distributed.Client(cluster, set_as_default=False) as client:
            with client.get_executor() as ex:
                on_client = run_census.run_census(L_SMALL, ex)
    assert as_json(on_cluster) == as_json(reference)
    assert as_json(on_client) == as_json(reference)


def census_json_of(tmp_path, name, L, *options):
    """The bytes of census.json written by `certify census --max-length L OPTIONS`."""
    out = tmp_path / name
    assert cli.main(["census", "--max-length", str(L), "--out", str(out), *options]) == 0
    return (out / "census.json").read_bytes()


@pytest.mark.parametrize("L", [6, pytest.param(10, marks=pytest.mark.slow)])
def test_a_cluster_of_worker_processes_writes_the_same_census_json(tmp_path, capsys, L):
    """`certify census --scheduler` on a Dask LocalCluster of single-thread worker
    processes (as `dask worker --nthreads 1` runs them) writes census.json byte for byte as
    the local run does."""
    distributed = pytest.importorskip("distributed")
    local = census_json_of(tmp_path, "local", L, "--jobs", "1")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=40) as cluster:
        on_cluster = census_json_of(tmp_path, "cluster", L, "--scheduler", cluster.scheduler_address)
    assert json.loads(local)["census"]["words"] == len(census.words(L))
    assert on_cluster == local


def test_a_cluster_of_workers_with_several_threads_is_refused(tmp_path, capsys):
    """python-flint's precision is global to a process: two threads of one worker could
    leave each other's balls at another precision (not the same bytes)."""
    distributed = pytest.importorskip("distributed")
    from certify.errors import UsageError
    with distributed.LocalCluster(processes=False, n_workers=1, threads_per_worker=2, dashboard_address=None,
                                  silence_logs=40) as cluster:
        with pytest.raises(UsageError, match="--nthreads 1"):
            with executor(scheduler=cluster.scheduler_address, one_thread=True):
                pass                                                          # pragma: no cover
        argv = ["census", "--max-length", "3", "--out", str(tmp_path), "--scheduler", cluster.scheduler_address]
        assert cli.main(argv) == 2 and "--nthreads 1" in capsys.readouterr().err
        with executor(scheduler=cluster.scheduler_address):                   # other jobs may share a worker
            pass


def test_local_processes_give_the_same_bytes(reference):
    with executor(2) as ex:
        assert as_json(run_census.run_census(L_SMALL, ex)) == as_json(reference)


class Counting:
    """A job that replays the reference records, counting its calls; it is interrupted
    (Ctrl-C) at call ``stop``."""

    def __init__(self, reference, stop=None):
        self.by = {r["word"]: r for r in reference}
        self.calls, self.stop = [], stop

    def __call__(self, word):
        if self.stop is not None and len(self.calls) == self.stop:
            raise KeyboardInterrupt
        self.calls.append(word)
        return dict(self.by[word], seconds=0.5)


def test_an_interrupted_census_resumes_without_redoing_words(tmp_path):
    words = census.words(8)
    reference = [fake(w) for w in words]
    state = tmp_path / "state.jsonl"
    first = Counting(reference, stop=5)
    with pytest.raises(KeyboardInterrupt):
        run_census.run_census(8, Serial(), state, job=first, window=3)
    assert len(first.calls) == 5
    lines = state.read_text().splitlines()
    assert [json.loads(x)["word"] for x in lines] == first.calls
    assert all(json.loads(x)["seconds"] == 0.5 for x in lines)          # timings kept in the state only
    with state.open("a") as f:                                          # a line cut by the interruption
        f.write('{"word": "abab')
    second = Counting(reference)
    resumed = run_census.run_census(8, Serial(), state, resume=True, job=second)
    assert not set(second.calls) & set(first.calls)
    assert sorted(second.calls + first.calls) == sorted(words)
    whole = run_census.run_census(8, Serial(), job=Counting(reference))
    assert run_census.to_json(run_census.document(resumed, 8)) == run_census.to_json(run_census.document(whole, 8))
    assert len(state.read_text().splitlines()) == len(words)


def test_without_resume_the_state_starts_over(tmp_path):
    words = census.words(5)
    reference = [fake(w) for w in words]
    state = tmp_path / "state.jsonl"
    state.write_text(json.dumps(fake("ab")) + "\n")
    job = Counting(reference)
    run_census.run_census(5, Serial(), state, job=job)
    assert sorted(job.calls) == sorted(words)


def fake(word):
    """A record of the census's shape, without the analysis (for the resume tests)."""
    feasible = word in ("ab", "abcb")
    return {"word": word, "compact": word, "length": len(word), "blocks": census.blocks_of(word),
            "contains_abcab": census.contains_abcab(word), "outcome": "analysed", "feasible": feasible,
            "stable": word == "ab", "undecided": False, "verdict": f"{word}: fake", "error": None,
            "result": {"feasible": [], "stable": []}, census.REDUCTION: FAKE_REDUCTION}


FAKE_REDUCTION = {"outcome": "analysed", "feasible": False, "attracting": False, "verdict": "fake", "error": None,
                  "result": {"exists": [], "feasible": [], "attracting": [], "attracting_points": [], "saddle": [],
                             "repelling": [], "complex_pair": [], "undecided": []}}


def test_markdown_tables_the_notable_words_and_lists_the_feasible_ones(tmp_path):
    """The table of notable words: stable first, then in error (with its error); a word only
    feasible is not a row but is in the appendix's list (every word: the data table)."""
    recs = [fake(w) for w in census.words(5)]
    recs[1] = dict(recs[1], outcome="error", feasible=None, stable=None, verdict="error", error="ArithmeticError: x")
    doc = run_census.document(recs, 5)
    text = run_census.markdown(doc)
    rows = [line for line in text.splitlines() if line.startswith("| `")]
    assert [row.split(" | ")[0] for row in rows] == ["| `ab`", "| `acb`"]
    assert "ArithmeticError: x" in rows[1]
    assert "| an analysis error (either way) | 1 | `acb` |" in text
    appendix = text[text.index("## Appendix"):]
    feasible = appendix[appendix.index("### Words with feasible self-similar data (2)"):]
    assert feasible.splitlines()[2] == "`ab`, `abcb`"


# ----------------------------------------------------------------- the command line
def test_census_command_writes_the_report_and_figure(tmp_path, capsys):
    assert cli.main(["census", "--max-length", "3", "--out", str(tmp_path), "--jobs", "1", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["census"]["words"] == 2 and [r["word"] for r in doc["words"]] == ["ab", "acb"]
    assert (tmp_path / "CENSUS.md").is_file() and (tmp_path / "census.json").is_file()
    assert (tmp_path / run_census.FIGURE).is_file()                     # ab is stable: one window drawn
    assert json.loads((tmp_path / "census.json").read_text()) == doc
    state = tmp_path / "census-state.jsonl"
    assert len(state.read_text().splitlines()) == 2
    assert cli.main(["census", "--max-length", "3", "--out", str(tmp_path), "--jobs", "1", "--resume"]) == 0
    assert "2 words up to length 3" in capsys.readouterr().out


@pytest.mark.parametrize("argv, message", [
    (["--max-length", "0"], "positive integer"),
    (["--max-length", "-3"], "positive integer"),
    (["--max-length", "x"], "positive integer"),
    (["--max-length", "3", "--out", "/proc/no/such"], "cannot write"),
    (["--max-length", "3", "--state", "/proc/no/such/state.jsonl"], "cannot write"),
    (["--max-length", "3", "--scheduler", "tcp://127.0.0.1:9"], "cannot reach the scheduler"),
])
def test_bad_options_are_one_line_and_exit_2(argv, message, capsys, tmp_path, monkeypatch):
    from certify.run import executors
    monkeypatch.setattr(executors, "CONNECT_TIMEOUT", 1)
    out = [] if "--out" in argv else ["--out", str(tmp_path)]
    assert cli.main(["census"] + argv + out) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1


# ----------------------------------------------------------------- T28
@pytest.fixture(scope="module")
def t28():
    return as_printed("T28")


def test_t28_is_an_erratum_with_certified_counterexamples(t28):
    # the census found patterns containing abcab with feasible data: the remark is refuted
    assert t28.status == ERRATUM, [(c.statement, c.holds, c.evidence) for c in t28.printed + t28.corrected]
    assert f"at most {T28.LENGTH} collisions" in t28.printed[-1].statement          # the bound is stated
    assert t28.printed[0].holds                                                    # the census is complete
    fix = t28.corrected[0]
    assert "abacbcabcab = ab acb cab cab on upper x₊: ]0, ≈0.1197259230[" in fix.statement
    assert "abcab" in "abacbcabcab" and census.contains("abacbacbcb", "cbacb")
    assert all("the dynamics from the datum gives " + w * T28.PERIODS in e
               for w, e in zip(T28.FOUND, fix.evidence)), fix.evidence


def test_t28_mutation_another_pattern_is_not_passed():
    # ababcb has feasible data (Theorem 3.1): the remark read for it is false, the counterexample named
    o = run_certificate(CERTIFICATES["T28"], overrides={"pattern": "ababcb"})
    assert o.status == ERRATUM
    assert any("ababcb = ab ab cb on" in c.statement for c in o.corrected)


def test_t28_quotes_the_remark_word_for_word_and_is_a_refuted_remark(t28):
    from tests.paper import plain_line
    assert T28.QUOTE_T28 in plain_line(515)
    assert T28.QUOTE_T28 in CERTIFICATES["T28"].statement
    assert t28.kind == "refuted remark" and "Remark 3.3" in t28.misprint


def test_t28_counts_the_counterexamples_under_each_reading():
    """abacbacbcb contains abcab only in its mirror; ababcb (Theorem 3.1) contains it only
    as letters in order, not consecutive: under that reading the theorem's own pattern
    would refute the remark."""
    counts = {name.split(" ")[0]: (a, b) for name, a, b in T28.reading_counts(["abacbacbcb"], "abcab")}
    assert counts == {"consecutive": (1, 1), "letters": (1, 2)}
    theorem = {name.split(" ")[0]: (a, b) for name, a, b in T28.reading_counts(["ababcb"], "abcab")}
    assert theorem == {"consecutive": (0, 0), "letters": (1, 1)}
    assert T28.orientations("abcb") == ["abcb"] and T28.orientations("abacb") == ["abacb", "cbcab"]


def test_t28_shows_the_readings_table(t28):
    table = [e for e in t28.evidence if "Reading of" in e]
    assert table and "| consecutive letters of the periodic word (cyclically) |" in table[0]


def test_a_shorter_census_does_not_silently_replace_a_longer_one(tmp_path, capsys):
    assert cli.main(["census", "--max-length", "4", "--out", str(tmp_path), "--jobs", "1"]) == 0
    before = (tmp_path / "census.json").read_bytes()
    capsys.readouterr()
    assert cli.main(["census", "--max-length", "3", "--out", str(tmp_path), "--jobs", "1"]) == 2
    err = capsys.readouterr().err
    assert "holds a larger census (longest period 4)" in err and err.count("\n") == 1
    assert (tmp_path / "census.json").read_bytes() == before
    assert cli.main(["census", "--max-length", "3", "--out", str(tmp_path), "--jobs", "1", "--force"]) == 0
    assert json.loads((tmp_path / "census.json").read_text())["census"]["max_length"] == 3
