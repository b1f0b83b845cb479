"""L5 and L6 for every n ≥ 2: n ≤ 30 read back from reports/family.json only while it is current,
n > 30 from family_limit's proof; what each part proves, and that it turns false when its input is
altered (a stale document, a window moved onto the next, a margin of the proof)."""
import copy
import json
import shutil
from fractions import Fraction

import pytest

from certify.algebra import radical
from certify.patterns import family_limit
from certify.patterns import family_windows as FW
from certify.run import saving
from certify.run.files import REPORTS
from proofs import section1_literature as T
from tests.shared import as_printed

ORDER = T.PRINTED_L5["order"]
LIMIT = radical(T.PRINTED_L5["limit"])


@pytest.fixture(scope="module")
def committed():
    return json.loads((REPORTS / T.FAMILY).read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def current(committed):
    """The committed records as if computed by this source (the check's logic on real records,
    whether or not the committed document is current)."""
    return dict(committed, digest=FW.code_digest())


@pytest.fixture(scope="module")
def limit():
    return T.proved_for_large_n(family_limit.prove(T.N0))


def test_committed_family_json_is_current(committed):
    """The committed reports/family.json was computed by this source: else L5, L6 FAIL and CI with
    them (regenerate it with `python -m certify family --n-max 30`, about 26 min)."""
    assert FW.is_current(committed), f"reports/family.json is stale: run `{T.FAMILY_COMMAND}`"
    assert committed["n_max"] >= T.N0


def test_code_digest_follows_the_source(tmp_path):
    """The digest changes with a file the windows depend on, not with one they do not."""
    root = tmp_path / "certify"
    shutil.copytree(FW.CERTIFY, root, ignore=shutil.ignore_patterns("__pycache__"))
    before = FW.code_digest(root)
    (root / "patterns" / "census.py").write_text("# not read by the windows\n", encoding="utf-8")
    assert FW.code_digest(root) == before
    path = root / "patterns" / "feasibility.py"
    path.write_text(path.read_text(encoding="utf-8") + "\n# altered\n", encoding="utf-8")
    assert FW.code_digest(root) != before


def test_stale_document_is_not_used(current):
    """Another digest: no window is read, the n ≤ 30 checks of L5 and L6 fail and say why."""
    ws, problems = T.exact_windows(dict(current, digest="0" * 64))
    assert ws == {} and "stale" in problems[0] and T.FAMILY_COMMAND in problems[0]
    assert not T.small_n_windows(ws, problems, LIMIT, "7-4√3", ORDER).holds
    assert not T.small_n_q2(dict(current, digest="0" * 64)).holds
    assert "missing" in T.exact_windows(None)[1][0]


def test_small_n_windows_from_the_records(current):
    ws, problems = T.exact_windows(current)
    assert not problems and sorted(ws) == list(range(2, T.N0 + 1))
    assert T.small_n_windows(ws, problems, LIMIT, "7-4√3", ORDER).holds
    assert T.small_n_q2(current).holds
    assert T.joined(ws).holds


def test_a_window_moved_onto_the_next_fails(current):
    """hi_13 moved up to hi_12 (W_13 then meets W_12): the exact comparison finds it."""
    recs = {w["n"]: w for w in current["windows"]}
    moved = dict(current, windows=[dict(w, hi=recs[12]["hi"]) if w["n"] == 13 else w for w in current["windows"]])
    ws, problems = T.exact_windows(moved)
    check = T.small_n_windows(ws, problems, LIMIT, "7-4√3", ORDER)
    assert not check.holds and "W_13 meets W_12: hi_13 ≥ lo_12" in check.evidence
    lowered = dict(current, windows=[dict(w, one_interval=False) if w["n"] == 7 else w for w in current["windows"]])
    assert not T.small_n_windows(*T.exact_windows(lowered), LIMIT, "7-4√3", ORDER).holds
    no_zero = dict(current, windows=[dict(w, hi_zero_of_u=False) if w["n"] == 9 else w for w in current["windows"]])
    check = T.small_n_q2(no_zero)
    assert not check.holds and "fails first at n = 9" in check.evidence


def test_printed_words_are_read(current, limit):
    ws, problems = T.exact_windows(current)
    for order in ("overlapping, accumulating on 7-4√3 from above", "disjoint, accumulating on 7-4√3 from below"):
        assert not T.small_n_windows(ws, problems, LIMIT, "7-4√3", order).holds
        assert not T.large_n_windows(limit, LIMIT, order).holds
    assert not T.large_n_windows(limit, radical("3-2√2"), ORDER).holds


def test_large_n_from_family_limit(limit):
    assert limit["failures"] == []
    assert T.large_n_windows(limit, LIMIT, ORDER).holds
    assert all(c.holds for c in T.large_n_q2(limit))


@pytest.mark.parametrize("alter", ["margin", "C", "s_lo"])
def test_an_altered_margin_fails_for_large_n(limit, alter):
    """A margin of the proof altered: family_limit.check finds it, the n > 30 checks of L5, L6 fail."""
    facts = copy.deepcopy(limit["facts"])
    box = facts["lower"]["boxes"][5]
    if alter == "margin":
        box["margin"] = box["margin"] * 100
    elif alter == "C":
        facts["C"] = Fraction(1, 3)
    else:
        box["s_lo"] = [box["s_lo"][0] + Fraction(1, 1000), box["s_lo"][1]]
    altered = T.proved_for_large_n(facts)
    assert altered["failures"]
    assert not T.large_n_windows(altered, LIMIT, ORDER).holds
    assert not any(c.holds for c in T.large_n_q2(altered))


def test_the_stable_set_beyond_the_windows_is_said(limit):
    """Where family_limit's facts do not cover ]0, 1[, L5 says NOT certified and states no
    theorem on the whole stable sets for every n; L6 likewise without part 9."""
    o = as_printed("L5")
    _, R = T.stable_cover(limit)
    whole = R is not None and R >= 1
    assert ("NOT certified" in o.note) != whole
    assert any("the whole stable sets" in c.statement for c in o.printed) == whole
    assert [c.ref for c in o.printed].count("L5.3") == 1
    assert ("NOT certified" in as_printed("L6").note) != ("positions" in limit["facts"])
    cover, R = T.stable_cover({"facts": {"positions": {"boxes": []}, "below": {"far": [], "low": []},
                                         "arcs": {"r": [None, Fraction(5, 8)]}}, "failures": []})
    assert R == Fraction(5, 8) and cover.holds and "]0, 5/8]" in cover.statement
    assert not T.stable_cover({"facts": {"positions": {"boxes": []}, "below": {"far": [], "low": []},
                                         "arcs": {"r": [None, Fraction(5, 8)]}}, "failures": ["x"]})[0].holds


def test_figure_is_written(tmp_path, current, limit, monkeypatch):
    monkeypatch.setenv(saving.CACHE_ENV, "off")
    with saving.output_dir(tmp_path):
        name = T.figure(T.exact_windows(current)[0], limit)
    assert name == "L5-family-windows.png" and (tmp_path / name).stat().st_size > 0
