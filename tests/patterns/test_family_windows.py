"""``certify family``: the per-n windows of (ab)^n(cb)^n and their checks."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

from certify.patterns import family_windows as FW

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def doc():
    return FW.windows(4)[0]


def test_windows_hold_for_small_n(doc):
    """One interval on the upper branch, above 7 − 4√3, hi_n a zero of q_2(0), decreasing; n = 2, 3
    are L5's printed windows ≈ [0.12754, 0.17157] and [0.09452, 0.10102]."""
    assert doc["all_hold"] and doc["first_failure"] is None
    w = {rec["n"]: rec for rec in doc["windows"]}
    assert sorted(w) == [2, 3, 4] and all(rec["branch"] == "upper" for rec in w.values())
    assert (w[2]["lo"]["digits"][:7], w[2]["hi"]["digits"][:7]) == ("0.12754", "0.17157")
    assert (w[3]["lo"]["digits"][:7], w[3]["hi"]["digits"][:7]) == ("0.09451", "0.10102")


def test_checks_fail_when_a_window_is_altered():
    """The checks turn false: windows out of order (hi_{n+1} ≥ lo_n), a set that is not one
    interval, a hi_n where q_2(0) does not vanish."""
    recs, ends = zip(*(FW.window(n) for n in (2, 3)))
    recs, ends = list(recs), list(ends)
    assert FW.check_windows(recs, ends)["all_hold"]
    swapped = FW.check_windows(recs[::-1], ends[::-1])
    assert swapped["first_failure"] == {"n": 2, "reason": "hi_2 ≥ lo_3"}
    for key in ("one_interval", "above_r_star", "hi_zero_of_u"):
        bad = [dict(recs[0], **{key: False}), recs[1]]
        assert FW.check_windows(bad, ends)["first_failure"]["n"] == 2, key


def test_hi_is_not_a_zero_of_u_elsewhere():
    """The zero test can fail: q_2(0) does not vanish at lo_2 on the upper branch."""
    from certify.algebra.poly import to_field
    from certify.dynamics.systems import candidate_in
    from certify.patterns.family import family_word
    from certify.patterns.feasibility import vanishes_on_branch
    _, (lo, _hi) = FW.window(2)
    cand = candidate_in("four", family_word(2))
    assert not vanishes_on_branch(cand.spectrum, to_field(cand.q0[1]).numer, lo, 0)


def test_command_writes_family_json(tmp_path):
    out = subprocess.run([sys.executable, "-m", "certify", "family", "--n-max", "3", "--out", str(tmp_path)],
                         cwd=ROOT, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    data = json.loads((tmp_path / "family.json").read_text(encoding="utf-8"))
    assert data["schema"] == "certify-family" and [w["n"] for w in data["windows"]] == [2, 3]
    from tests.cli.test_schemas import validate
    validate("family", data)                              # certify/schemas/family.schema.json
    bad = subprocess.run([sys.executable, "-m", "certify", "family", "--n-max", "1", "--out", str(tmp_path)],
                         cwd=ROOT, capture_output=True, text=True)
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "Traceback" not in bad.stderr


def test_worker_processes_give_the_same_document(doc):
    """`certify family --jobs 2`: the n analysed in worker processes (records as plain data, the ends
    read back from them) give the document of the serial run, byte for byte."""
    from certify.run.executors import process_pool
    with process_pool(2) as pool:
        parallel = FW.windows(4, pool=pool)[0]
    assert json.dumps(parallel, sort_keys=True) == json.dumps(doc, sort_keys=True)


def test_pattern_beyond_30_gives_the_theorem_s_window():
    """`certify pattern '(ab)^31(cb)^31' --json`: the theorem's route, valid against its schema, the
    window ]ℓ_31, r_31[ exact (its ends read back equal proved_window's), no undecided point."""
    from certify.cli.schemas import validate
    from certify.patterns import end_number
    out = subprocess.run([sys.executable, "-m", "certify", "pattern", "(ab)^31(cb)^31", "--json"],
                         cwd=ROOT, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert validate("family-window", out.stdout) == []
    rec = json.loads(out.stdout)
    assert rec["route"] == "theorem" and rec["proof_holds"] and rec["undecided"] == []
    piece = rec["stable"][0]["pieces"][0]
    assert (end_number(piece["lo"]), end_number(piece["hi"])) == FW.proved_window(31)
    md = FW.theorem_markdown(rec)
    assert "no undecided point" in md and "Not computed on this route" in md


def test_pattern_dispatch(monkeypatch, capsys):
    """The theorem's route only for the family beyond EXACT_N0 over the whole of ]0, 1[; the engine's
    otherwise (a word of the family at n ≤ 30, another word, or --r-range); a failing proof: exit 1."""
    import certify.patterns as P
    from certify.cli import main
    calls = []
    monkeypatch.setattr(P, "analyse", lambda word, lo=0, hi=1, progress=None: calls.append(word) or _Stub())
    monkeypatch.setattr(FW, "EXACT_N0", 8)
    assert main(["pattern", "(ab)^8(cb)^8"]) == 0 and calls == ["(ab)^8(cb)^8"]
    assert main(["pattern", "(ab)^9(cb)^9", "--r-range", "0.07", "0.08"]) == 0 and len(calls) == 2
    assert main(["pattern", "(ab)^9(cb)^9"]) == 0 and len(calls) == 2
    assert "]≈0.07" in capsys.readouterr().out
    monkeypatch.setattr(FW, "theorem", lambda n0=7: {"facts": {}, "failures": ["a margin"]})
    assert main(["pattern", "(ab)^9(cb)^9"]) == 1
    assert "NOT decided" in capsys.readouterr().out


class _Stub:
    def markdown(self):
        return "engine"

    def json_text(self):
        return "{}"
