"""L5 and L6 for every n ≥ 2: n ≤ 7 by the engine's exact analysis, n ≥ 8 by family_limit's theorem
(prove(7), re-verified by check), its windows exact for n = 8..30 (the one root of F_n in ]r_(n+1), r_n[);
reports/family.json, the engine's route to n = 30, compared only while current.  What each part proves,
and that it turns false when its input is altered (a window moved onto the next, a margin of the proof,
the engine's route disagreeing)."""
import copy
import json
import shutil
from fractions import Fraction

import pytest

from certify.algebra import radical
from certify.patterns import family_windows as FW
from certify.run import saving
from certify.run.files import REPORTS
from proofs import section1_literature as T
from tests.shared import CONTEXT, as_printed, registry

ORDER = T.PRINTED_L5["order"]
LIMIT = radical(T.PRINTED_L5["limit"])


@pytest.fixture(scope="module")
def limit():
    registry()
    return CONTEXT.get("ab_cb_limit")


@pytest.fixture(scope="module")
def engine():
    """The engine's windows n = 2..7 as the certificates read them (the session's quantities)."""
    registry()
    return T.engine_windows(CONTEXT.get("ab_cb_patterns"), CONTEXT.get("ab_cb_seven"))


def test_the_proof_holds_and_gives_exact_windows(limit):
    assert limit["failures"] == [] and limit["facts"]["N0"] == T.PROVED_FROM - 1 == 7
    assert sorted(limit["windows"]) == list(range(8, T.N0 + 1))
    assert T.large_n_windows(limit, LIMIT, ORDER).holds
    assert all(c.holds for c in T.large_n_q2(limit))
    cover, R = T.stable_cover(limit)
    assert cover.holds and R == 1 and "exactly ]ℓ_n, r_n[" in cover.statement


def test_exact_windows_join_the_two_routes(engine, limit):
    check = T.exact_windows(engine, limit["windows"], LIMIT, "7-4√3", ORDER)
    assert check.holds, check.evidence
    assert sum("(engine)" in e for e in check.evidence) == 6 and sum("(proof)" in e for e in check.evidence) == 23
    # r_8 < lo_7: the two routes meet with a gap
    assert limit["windows"][8][1] < engine[7][0]


def test_proved_window_is_the_engine_s_at_n_8():
    """The second route on one n: `certify pattern`'s exact analysis of (ab)^8(cb)^8 (about 70 s is too slow
    here; n = 8's ends as the engine printed them, in reports/family.json, are read back exactly)."""
    doc = json.loads((REPORTS / T.FAMILY).read_text(encoding="utf-8"))
    rec = next(w for w in doc["windows"] if w["n"] == 8)
    lo, hi = FW.proved_window(8)
    assert (T.end_number(rec["lo"]), T.end_number(rec["hi"])) == (lo, hi)


def test_a_window_moved_onto_the_next_fails(engine, limit):
    """hi_13 moved up to hi_12 (W_13 then meets W_12); lo_7 below r*; n = 5 not one interval: each found."""
    proved = dict(limit["windows"])
    proved[13] = (proved[13][0], proved[12][1])
    check = T.exact_windows(engine, proved, LIMIT, "7-4√3", ORDER)
    assert not check.holds and "W_13 meets W_12: hi_13 ≥ lo_12" in check.evidence
    assert not T.exact_windows({**engine, 5: None}, limit["windows"], LIMIT, "7-4√3", ORDER).holds
    assert not T.exact_windows(engine, limit["windows"], radical("1/10"), "1/10", ORDER).holds


def test_printed_words_are_read(engine, limit):
    for order in ("overlapping, accumulating on 7-4√3 from above", "disjoint, accumulating on 7-4√3 from below"):
        assert not T.exact_windows(engine, limit["windows"], LIMIT, "7-4√3", order).holds
        assert not T.large_n_windows(limit, LIMIT, order).holds
    assert not T.large_n_windows(limit, radical("3-2√2"), ORDER).holds


@pytest.mark.parametrize("alter", ["margin", "C", "s_lo"])
def test_an_altered_margin_fails_for_large_n(limit, alter):
    """A margin of the proof altered: family_limit.check finds it, the n ≥ 8 checks of L5, L6 fail."""
    facts = copy.deepcopy(limit["facts"])
    box = facts["lower"]["boxes"][5]
    if alter == "margin":
        box["margin"] = box["margin"] * 100
    elif alter == "C":
        facts["C"] = Fraction(1, 3)
    else:
        box["s_lo"] = [box["s_lo"][0] + Fraction(1, 1000), box["s_lo"][1]]
    altered = dict(limit, facts=facts, failures=FW.family_limit.check(facts))
    assert altered["failures"]
    assert not T.large_n_windows(altered, LIMIT, ORDER).holds
    assert not any(c.holds for c in T.large_n_q2(altered))
    assert not T.stable_cover(altered)[0].holds


def test_proved_window_counts_the_zeros(monkeypatch):
    """ℓ_n is the one root of F_n in ]r_(n+1), r_n[: F_n times r − q, q a rational between ℓ_n and r_n (a
    second zero there), is refused; n ≤ 7 (outside the proof) too."""
    import flint

    from certify.algebra.branches import simple_rational_between
    lo, hi = FW.proved_window(9)
    q = flint.fmpq(simple_rational_between(lo, hi))
    assert lo < radical(str(q)) < hi
    real = FW.family_limit.lower_polynomial
    monkeypatch.setattr(FW.family_limit, "lower_polynomial", lambda n: real(n) * flint.fmpq_poly([-q, 1]))
    with pytest.raises(ArithmeticError, match="2 zeros"):
        FW.proved_window(9)
    with pytest.raises(ValueError):
        FW.proved_window(7)


def test_second_route_compared_only_when_current(limit):
    """family.json: stale (another digest) → not compared, said in the note; current and equal → holds;
    current with lo_12 moved → fails at n = 12."""
    doc = json.loads((REPORTS / T.FAMILY).read_text(encoding="utf-8"))
    assert T.second_route(dict(doc, digest="0" * 64), limit["windows"]) is None
    assert "not compared" in T._route_note(dict(doc, digest="0" * 64))
    current = dict(doc, digest=FW.code_digest())
    assert T.second_route(current, limit["windows"]).holds
    recs = {w["n"]: w for w in current["windows"]}
    moved = dict(current, windows=[dict(w, lo=recs[13]["lo"]) if w["n"] == 12 else w for w in current["windows"]])
    check = T.second_route(moved, limit["windows"])
    assert not check.holds and "n = 12" in check.evidence[0]


def test_code_digest_follows_the_source(tmp_path):
    """The digest changes with a file the windows depend on, not with one they do not."""
    root = tmp_path / "certify"
    shutil.copytree(FW.CERTIFY, root, ignore=shutil.ignore_patterns("__pycache__"))
    before = FW.code_digest(root)
    (root / "patterns" / "island_theorem.py").write_text("# not read by the windows\n", encoding="utf-8")
    assert FW.code_digest(root) == before
    path = root / "patterns" / "feasibility.py"
    path.write_text(path.read_text(encoding="utf-8") + "\n# altered\n", encoding="utf-8")
    assert FW.code_digest(root) != before


def test_the_theorem_is_printed():
    o = as_printed("L5")
    assert [c.ref for c in o.printed].count("L5.3") == 1
    assert "proved for every n ≥ 2" in o.note and "NOT certified" not in o.note
    assert "proved for every n ≥ 2" in as_printed("L6").note


def test_figure_is_written(tmp_path, engine, limit, monkeypatch):
    monkeypatch.setenv(saving.CACHE_ENV, "off")
    with saving.output_dir(tmp_path):
        name = T.figure({**engine, **limit["windows"]}, limit)
    assert name == "L5-family-windows.png" and (tmp_path / name).stat().st_size > 0


@pytest.mark.parametrize("n", [2, 3])
def test_without_the_eigenspace_route_the_stable_sets_are_the_same(n):
    """L4-L6 run `pattern` without the eigenspace route: the same stable sets as with it, and every
    point it leaves undecided is a multiple eigenvalue of its branch (where nothing is stable)."""
    from certify.dynamics.systems import candidate_in
    from certify.patterns import analyse
    from certify.patterns.feasibility import Analysis
    word = T.ab_cb(n)
    fast, full = T.stable_sets(word), analyse(word)
    assert fast.intervals("stable") == full.intervals("stable") and fast.points("stable") == full.points("stable")
    assert len(fast.undecided) > len(full.undecided)
    an = Analysis(candidate_in("four", fast.normal), 0, 1)
    left = [(R.branch, rc) for R in fast.regions["stable"] for rc, _why in R.undecided]
    assert len(left) == len(fast.undecided)
    assert all(an._eigenspace(rc, k) is not None for k, rc in left)
