"""`certify atlas`: the atlas on a tiny grid against `orbit`, `island` and `identify`
(certify/run/atlas.py): a wrong window, a dropped attractor, a dropped seed or family
member, a mislabelled class each make :func:`check_atlas` fail; seeds followed across r by
their windows, met by the grid or not; refinement; families; the schema; resuming; bad
input exits 2."""
import copy
import json
import math
from fractions import Fraction

import jsonschema
import pytest

from certify import cli
from certify.numerics import grid
from certify.run import atlas
from certify.run.executors import Serial

SCHEMA = json.loads(atlas.SCHEMA_PATH.read_text(encoding="utf-8"))
PARAMS = {"r_range": ["7/50", "8/25"], "resolution": 3, "data": 0, "collisions": 5000, "word_max": 44,
          "word_seconds": 60, "seeds": "given", "refine": 0, "command": "test"}
# a family of the atlas, cut short for speed: members k = 1, 2, 3 (16, 28, 40 letters), prediction k = 4 (52:
# longer than word_max 44 here, so it gets no window and the prediction stays uncertified)
RULE = atlas.Rule("(abacbc)^k a(bcabac)^k bcb", "(abacbc)^{k}a(bcabac)^{k}bcb", 1, 3, (2, 0, 4, 1))
SEEDS = {RULE.word(k): f"family {RULE.name}, k = {k}" for k in RULE.members()}
FAMILIES = atlas.FAMILIES                       # the atlas's own rules (the tiny atlas runs with RULE only)


def _run(state=None, resume=False, ex=None):
    rs = atlas.r_values(Fraction("0.14"), Fraction("0.32"), 3)              # 0.17 (below 3−2√2), 0.23, 0.29
    return atlas.run_atlas(rs, atlas.data_grid(0), 5000, ex or Serial(), state, resume, word_seconds=60, word_max=44,
                           seeds=SEEDS)


@pytest.fixture(scope="module", autouse=True)
def family_rules():
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(atlas, "FAMILIES", (RULE,))
        yield


@pytest.fixture(scope="module")
def records(tmp_path_factory, family_rules):
    state = tmp_path_factory.mktemp("atlas") / "state.jsonl"
    return (*_run(state), state)


@pytest.fixture(scope="module")
def doc(records):
    return atlas.document(records[0], records[1], PARAMS)


def _cell_with(doc, k):
    return next(c for c in doc["cells"] if len(c["attractors"]) >= k and c["sampled"])


def test_the_grids():
    rs = atlas.r_values(Fraction("0.14"), Fraction("0.32"), 3)
    assert [str(r) for r in rs] == ["17/100", "23/100", "29/100"]
    th, ph = grid(8)
    data = atlas.data_grid(5)
    assert len(data) == 13 and data[:8] == list(zip(th.tolist(), ph.tolist()))
    assert atlas.data_grid(9)[:13] == data                               # nested
    assert all(0 < t < math.pi / 2 and 0 < p < math.pi and p != math.pi / 2 for t, p in data[8:])


def test_the_tiny_atlas_checks_against_orbit_island_and_identify(doc):
    assert [p for p in atlas.check_atlas(doc) if "prediction not certified" not in p] == []


def test_the_check_command_reads_the_atlas_and_exits_1_on_a_problem(doc, tmp_path, capsys, monkeypatch):
    """`certify atlas --check --out DIR`: 0 and one line on a document that checks (the tiny atlas, its
    family's prediction aside), 1 and the problem on a copy with a class changed; nothing written."""
    good = copy.deepcopy(doc)
    # the tiny atlas's family lacks its prediction (word_max 44): that problem only is left out
    families = atlas.check_families
    monkeypatch.setattr(atlas, "check_families", lambda d: [p for p in families(d) if "not certified" not in p])
    (tmp_path / "atlas.json").write_text(json.dumps(good), encoding="utf-8")
    assert cli.main(["atlas", "--check", "--out", str(tmp_path), "--jobs", "1"]) == 0
    assert "checks" in capsys.readouterr().out
    o = next(o for o in good["r"][1]["orbits"] if o["class"] == "attracting periodic")
    o["class"] = "island"
    (tmp_path / "atlas.json").write_text(json.dumps(good), encoding="utf-8")
    assert cli.main(["atlas", "--check", "--out", str(tmp_path), "--jobs", "1", "--sample", "1"]) == 1
    out = capsys.readouterr().out
    assert "by identify" in out and "problem(s)" in out.splitlines()[-1]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["atlas.json"]


def test_check_committed_is_check_atlas_through_an_executor(doc):
    """`certify atlas --check`'s driver: the same problems as check_atlas with every row and word (a
    wrong class and a moved window end in a copy are both named); --sample 2 checks rows 1 and 3."""
    assert sorted(atlas.check_committed(doc, Serial(), 1, 44)) == sorted(atlas.check_atlas(doc, 44))
    bad = copy.deepcopy(doc)
    row = bad["r"][2]
    o = next(o for o in row["orbits"] if o["class"] == "attracting periodic")
    o["class"] = "island"
    a = next(a for a in bad["attractors"] if a["windows"] and len(bad["r"]) > 0)
    a["windows"][0]["hi"] = copy.deepcopy(a["windows"][0]["lo"])
    problems = atlas.check_committed(bad, Serial(), 1, 44)
    assert any("by identify" in p and f"r = {row['r']}" in p for p in problems)
    assert any(a["name"].split(" (")[0] in p and "by certify orbit" in p for p in problems)
    seen = []
    atlas.check_committed(bad, Serial(), 2, 0, progress=lambda k, n, label: seen.append((k, n, label)))
    assert [label for *_, label in seen] == ["r 1", "r 2"] and seen[-1][:2] == (2, 2)
    names = {a["name"] for a in doc["attractors"]}
    assert {"(ab)^2(cb)^2 (lower)", "a(bac)^2bcb (upper)", "abacba(bc)^2abcb (upper)"} <= names
    below = next(c for c in doc["cells"] if "17/100" in c["sampled"])
    assert not below["island"] and below["island_fraction"] is None
    assert _cell_with(doc, 2)["island"]                                   # coexistence above 3−2√2
    assert doc["summary"]["inconsistent"] == []


def test_a_wrong_window_is_caught(doc):
    bad = copy.deepcopy(doc)
    a = next(a for a in bad["attractors"] if a["name"] == "a(bac)^2bcb (upper)")
    other = next(x for x in bad["attractors"] if x["name"] == "abacba(bc)^2abcb (upper)")
    a["windows"][0]["hi"] = other["windows"][0]["hi"]                     # its upper end moved to r = 1
    assert any("a(bac)^2bcb (upper): window" in p for p in atlas.check_windows(bad, 30))
    assert any("stitched again" in p for p in atlas.check_cells(bad))


def test_a_dropped_attractor_is_caught(doc):
    bad = copy.deepcopy(doc)
    cell = _cell_with(bad, 2)
    dropped = cell["attractors"].pop()
    problems = atlas.check_cells(bad)
    assert any(dropped in p and "by orbit_at" in p for p in problems)
    # dropped everywhere, the cells stitched again consistently: orbit_at still finds it
    bad = copy.deepcopy(doc)
    bad["attractors"] = [a for a in bad["attractors"] if a["name"] != dropped]
    bad["cells"] = atlas.stitch(bad["attractors"])
    for c in bad["cells"]:
        c["sampled"] = [r["r"] for r in bad["r"] if atlas._in_cell(atlas.Fraction(r["r"]), c)]
    assert any(dropped in p for p in atlas.check_cells(bad))


def test_a_mislabelled_class_is_caught(doc):
    bad = copy.deepcopy(doc)
    row = next(r for r in bad["r"] if any(o["class"] == atlas.ISLAND for o in r["orbits"]))
    o = next(o for o in row["orbits"] if o["class"] == atlas.ISLAND)
    o["class"] = atlas.UNRESOLVED
    row["counts"] = atlas._counts(row["orbits"])                          # the counts made consistent
    assert any("island" in p and "by identify" in p for p in atlas.check_orbits(bad, [row]))
    bad = copy.deepcopy(doc)                                              # an attractor's branch mislabelled
    row = next(r for r in bad["r"] if any(o["class"] == atlas.ATTRACTING for o in r["orbits"]))
    o = next(o for o in row["orbits"] if o["class"] == atlas.ATTRACTING)
    o["branch"] = "middle"
    row["counts"] = atlas._counts(row["orbits"])
    assert any("orbit_at" in p for p in atlas.check_orbits(bad, [row]))


def test_a_wrong_island_share_is_caught(doc):
    bad = copy.deepcopy(doc)
    row = next(r for r in bad["r"] if r["island"])
    row["island"]["fraction"][1] = "1"
    assert any("island's share" in p for p in atlas.check_orbits(bad, [row]))


def test_the_document_follows_its_schema_and_has_no_timing(doc):
    jsonschema.validate(doc, SCHEMA)
    assert '"seconds"' not in atlas.to_json(doc)
    bad = copy.deepcopy(doc)
    bad["r"][0]["orbits"][0]["class"] = "chaotic"
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(bad, SCHEMA)


def test_resume_reuses_the_state_and_gives_the_same_atlas(records, doc):
    class Refuse(Serial):
        def submit(self, fn, /, *args, **kwargs):
            raise AssertionError("a job was run again")
    rr, ww = _run(records[2], resume=True, ex=Refuse())
    assert atlas.to_json(atlas.document(rr, ww, PARAMS)) == atlas.to_json(doc)


def test_the_outputs_are_written(doc, tmp_path):
    atlas.write_outputs(doc, tmp_path)
    text = (tmp_path / "ATLAS.md").read_text(encoding="utf-8")
    assert "## Cells" in text and "## Families" in text and RULE.name in text and "(2k)/(4k + 1)" in text
    assert json.loads((tmp_path / "atlas.json").read_text(encoding="utf-8")) == json.loads(atlas.to_json(doc))
    assert (tmp_path / "atlas.png").read_bytes()[:4] == b"\x89PNG"


def test_a_word_too_long_or_too_slow_gets_no_window():
    assert atlas.word_job("ababcbcb", word_max=4)["outcome"] == "too long"
    assert atlas.word_job("(ab)^3(cb)^3", seconds=0.001)["outcome"] == "time limit"


def test_the_time_limit_counts_cpu_time_and_a_wall_clock_record_is_analysed_again(tmp_path):
    """A word's time limit is CPU time (SIGPROF): a process asleep is not stopped; a "time limit"
    record without the CPU clock (made by the wall-clock alarm before) is analysed again by
    --resume, one with it is reused."""
    import time
    rec = atlas.word_job("(ab)^3(cb)^3", seconds=0.001)
    assert rec["outcome"] == "time limit" and rec["clock"] == "cpu" and rec["cpu_seconds"] < 5
    assert atlas.word_job("ababcbcb", seconds=10)["outcome"] == "analysed"
    class Slept:                                     # an analysis that waits 0.5 s and uses no CPU
        def attracting(self):
            return []
        attracting_points = attracting
        undecided = ()

    def asleep(word, self_similar):
        time.sleep(0.5)
        return Slept()
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(atlas, "analyse", asleep)
        assert atlas.word_job("ababcbcb", seconds=0.2)["outcome"] == "analysed"     # a wall clock would stop it
    word = "abacbacbcabc"
    for clock, reran in ((None, True), ("cpu", False)):
        state = tmp_path / f"{clock}.jsonl"
        stale = {"kind": "word", "word": word, "compact": word, "length": 12, "outcome": "time limit",
                 "attracting": [], "attracting_points": [], "undecided": [], "word_max": 44, "word_seconds": 60}
        if clock:
            stale["clock"] = clock
        state.write_text(json.dumps(stale) + "\n", encoding="utf-8")
        class Count(Serial):
            ran: list = []

            def submit(self, fn, /, *args, **kwargs):
                self.ran.append(args[0])
                return super().submit(fn, *args, **kwargs)
        count = Count()
        _, words = atlas.run_atlas([], atlas.data_grid(0), 5000, count, state, True, word_seconds=60,
                                   word_max=44, seeds={word: "given"}, r_range=(Fraction(0), Fraction(1)))
        assert (word in count.ran) == reran
        assert [w["outcome"] for w in words] == (["analysed"] if reran else ["time limit"])


def test_rotation_numbers_at_the_window_ends(doc):
    his = {a["name"]: a["windows"][0]["hi"] for a in doc["attractors"]}
    assert atlas.end_rotation(his["(ab)^2(cb)^2 (lower)"])["resonance"] == [1, 2]          # ends at 3−2√2
    assert atlas.end_rotation(his["a(bac)^2bcb (upper)"])["resonance"] == [1, 3]           # ends at 2−√3, ρ = 1/3
    assert atlas.end_rotation(his["abacba(bc)^2abcb (upper)"])["resonance"] == [1, 4]      # ends at r = 1
    ends = {(x["attractor"], x["p"], x["q"], x["island_end"]) for x in doc["summary"]["resonant_upper_ends"]}
    assert ("a(bac)^2bcb (upper)", 1, 3, False) in ends and ("(ab)^2(cb)^2 (lower)", 1, 2, True) in ends
    assert ("abacba(bc)^2abcb (upper)", 1, 4, True) in ends
    interior = doc["summary"]["interior_ends"]                 # the island's own ends counted apart
    assert interior["resonant_upper"] == sum(not x["island_end"] for x in doc["summary"]["resonant_upper_ends"])
    assert interior["upper"] == doc["summary"]["upper_ends_above"] - sum(x["island_end"] for x in
                                                                         doc["summary"]["resonant_upper_ends"])
    groups = {(g["p"], g["q"]): g["attractors"] for g in doc["by_resonance"]}
    assert groups[(1, 4)] == ["abacba(bc)^2abcb (upper)"] and list(groups)[0] == (1, 2)   # by increasing r


def test_the_seeds_are_the_known_attractors(monkeypatch):
    monkeypatch.setattr(atlas, "FAMILIES", FAMILIES)
    found = atlas.seeds()
    family = {atlas.read(f"(ab)^{n}(cb)^{n}")[0] for n in range(2, 13)}
    assert family <= set(found)
    windows = atlas.committed_windows()
    assert {atlas.read(w)[0] for w in windows[0]} <= set(found)           # the census's attracting words
    assert any(len(w) == 122 for w in found)                              # the attractor of r = 0.173 (section 5)
    for rule in atlas.FAMILIES:
        assert {rule.word(k) for k in rule.members()} <= set(found)


def test_a_seed_gets_its_window_whether_the_grid_meets_it_or_not(doc):
    a = next(a for a in doc["attractors"] if a["word"] == RULE.word(3))     # 40 letters, ]≈0.17449, ≈0.17517[
    assert a["seen_at"] == [] and a["source"] == f"family {RULE.name}, k = 3"
    assert atlas.check_windows(doc, 44) == []                            # every window, seeds included, by orbit
    inside = [c for c in doc["cells"] if a["name"] in c["attractors"]]
    assert inside and all(not c["sampled"] for c in inside)              # listed in its cells, met or not
    far = next(w for w in doc["words"] if w["word"] == RULE.word(4))
    assert far["outcome"] == "too long" and "52 letters" in atlas.why_no_window(far)
    assert any(x["word"] == RULE.word(4) and x["why"].startswith("too long") for x in doc["without_window"])


def test_a_dropped_seed_or_family_member_is_caught(doc):
    assert atlas.check_seeds(doc) == [] and atlas.check_families(doc) == [f"family {RULE.name}: 3 certified "
                                                                          "members, prediction not certified"]
    bad = copy.deepcopy(doc)                                             # a member dropped everywhere
    gone = RULE.word(2)
    bad["attractors"] = [a for a in bad["attractors"] if a["word"] != gone]
    bad["words"] = [w for w in bad["words"] if w["word"] != gone]
    assert any("no word record" in p and "k = 2" in p for p in atlas.check_seeds(bad))
    assert any("differs" in p or "no member" in p for p in atlas.check_families(bad))
    bad = copy.deepcopy(doc)                                             # its attractor dropped, its word kept
    bad["attractors"] = [a for a in bad["attractors"] if a["word"] != gone]
    assert any(RULE.name in p for p in atlas.check_families(bad))
    bad = copy.deepcopy(doc)                                             # a member said not to close at p_k/q_k
    bad["families"][0]["members"][0]["closes"] = False
    assert any("differs" in p for p in atlas.check_families(bad))


def test_a_family_reads_its_rule_and_closing_resonances(doc):
    (fam,) = doc["families"]
    assert fam["closing"] == "(2k)/(4k + 1)" and fam["certified_members"] == 3
    assert [(m["k"], m["closing"], m["closes"], m["certified"]) for m in fam["members"]] == [
        (1, [2, 5], True, True), (2, [4, 9], True, True), (3, [6, 13], True, True), (4, [8, 17], False, False)]
    member = atlas.family_of(doc["families"])
    assert member[RULE.word(2)] == RULE.name and "abcb" not in member
    assert next(a for a in doc["attractors"] if a["word"] == RULE.word(2))["family"] == RULE.name


def test_a_member_met_beyond_the_prediction_is_listed_apart_and_tested(doc):
    """A member k > last + 1 that the atlas analysed (met by its orbits) is listed after the
    prediction, marked beyond, its closing at p_k/q_k decided like the others, and not counted
    among the certified members; a window that does not close at p_k/q_k leaves it uncertified."""
    far = RULE.word(6)
    k3 = next(a for a in doc["attractors"] if a["word"] == RULE.word(3))
    attractors = [*doc["attractors"], {**k3, "word": far}]              # k = 3's window (closing at 6/13)
    words = [*doc["words"], {**next(w for w in doc["words"] if w["word"] == RULE.word(3)), "word": far}]
    (fam,) = atlas.families(attractors, words)
    assert [(m["k"], m.get("beyond", False)) for m in fam["members"]] == [(1, False), (2, False), (3, False),
                                                                           (4, False), (6, True)]
    assert fam["members"][-1]["closing"] == [12, 25] and fam["members"][-1]["closes"] is False
    assert fam["members"][-1]["certified"] is False and fam["certified_members"] == 3
    (same,) = atlas.families(attractors, words)
    assert same == fam
    jsonschema.validate({**doc, "families": [fam]}, SCHEMA)


def test_the_rules_spell_the_windows_closing_at_3_8_and_5_12_and_near_1():
    """The rules read off the atlas: member 1 of (4k−1)/(8k) is the word closing at 3/8, of
    (4k+1)/(8k+4) the one at 5/12 (a power ^0 dropped), and the family ending at r = 1 grows
    by 24 letters a member, its (abcb)^m blocks m = k + ⌈k/2⌉ + 1."""
    rules = {rule.closing: rule for rule in FAMILIES}
    three_eighths, five_twelfths, near_one = rules[(4, -1, 8, 0)], rules[(4, 1, 8, 4)], rules[(0, 1, 0, 4)]
    assert atlas.compact(three_eighths.word(1)) == "abac(bca)^2ba(bc)^2a(bac)^2bcb"
    assert three_eighths.resonance(1) == (3, 8)
    assert atlas.compact(five_twelfths.word(1)) == "abacbca(bac)^2bc(ab)^2cbcabac(bca)^2ba(cb)^2"
    assert [three_eighths.resonance(k) for k in (2, 3)] == [(7, 16), (11, 24)]
    assert [five_twelfths.resonance(k) for k in (2, 3)] == [(9, 20), (13, 28)]
    assert [len(near_one.word(k)) for k in range(1, 5)] == [24 * k + 14 for k in range(1, 5)]
    assert atlas.compact(near_one.word(1)) == "abcabacbc(abcb)^3acbcaba(cbab)^2cb"
    assert "(abcb)^6" in atlas.compact(near_one.word(3)) and "(cbab)^7" in atlas.compact(near_one.word(4))
    assert all(len(rule.word(rule.last + 1)) <= atlas.WORD_MAX for rule in FAMILIES)   # every prediction: orbit


@pytest.fixture(scope="module")
def chaos_doc():
    """A two-r atlas: r = 31/200, where `certify chaos` proves a horseshoe, and r = 12471/12500,
    where four of the tool's 8 orbits repeat abcb (repelling there) without converging."""
    rows, words = atlas.run_atlas([Fraction("31/200"), Fraction("12471/12500")], atlas.data_grid(0), 5000, Serial(),
                                  seeds={}, word_max=30)
    return atlas.document(rows, words, {**PARAMS, "r_range": ["3/20", "1"], "word_max": 30})


def test_the_horseshoes_and_loops_check(chaos_doc):
    assert atlas.check_chaos(chaos_doc) == [] and atlas.check_summaries(chaos_doc) == []
    jsonschema.validate(chaos_doc, SCHEMA)
    hs = chaos_doc["summary"]["horseshoes"]
    assert (hs["searched"], hs["proved"], hs["proved_below"], hs["r"]) == (2, 1, 1, ["31/200"])
    (curve,) = chaos_doc["curves"]
    assert curve["word"] == "abcb" and curve["returns"] == 2 and curve["orbits"] >= 1
    text = atlas.markdown(chaos_doc)
    assert "measure zero" in text and "## Unresolved orbits" in text and "entropy ≥ " + hs["entropy_lower"][0] in text


def test_a_dropped_horseshoe_is_caught(chaos_doc):
    bad = copy.deepcopy(chaos_doc)
    row = next(r for r in bad["r"] if r["horseshoe"]["certified"])
    row["horseshoe"] = {"certified": False, "tried": 0}
    bad["summary"]["horseshoes"] = atlas.horseshoes(bad["r"])              # the summary made consistent
    assert any("by certify chaos's search again" in p for p in atlas.check_chaos(bad, [row]))
    assert atlas.check_summaries(bad) == []


def test_an_altered_box_or_covering_is_refused(chaos_doc):
    bad = copy.deepcopy(chaos_doc)
    row = next(r for r in bad["r"] if r["horseshoe"]["certified"])
    box = row["horseshoe"]["boxes"][1]
    box["unstable"] = [str(Fraction(z) / 4) for z in box["unstable"]]       # too short to cross the next box
    assert any("do not prove" in p for p in atlas.check_chaos(bad, [row]))
    bad = copy.deepcopy(chaos_doc)
    row = next(r for r in bad["r"] if r["horseshoe"]["certified"])
    row["horseshoe"]["entropy_lower"] = "0.5"                               # a larger entropy bound printed
    assert any("do not prove" in p for p in atlas.check_chaos(bad, [row]))


def test_an_altered_rotation_number_is_caught(chaos_doc):
    bad = copy.deepcopy(chaos_doc)
    row, o = next((r, o) for r in bad["r"] for o in r["orbits"] if o.get("curve"))
    o["curve"]["near"] = [1, 3]                                             # another class of rotation number
    assert any("computed again" in p for p in atlas.check_chaos(bad, [row]))
    assert any("loops" in p for p in atlas.check_summaries(bad))
    bad = copy.deepcopy(chaos_doc)
    bad["curves"][0]["rotation"] = ["0.5", "0.5"]
    assert any("loops" in p for p in atlas.check_summaries(bad))


def test_an_altered_share_interval_is_caught(doc, chaos_doc):
    for d in (doc, chaos_doc):
        bad = copy.deepcopy(d)
        cell = next(c for c in bad["cells"] if c["orbits"])
        key = next(iter(cell["intervals"]))
        cell["intervals"][key] = ["0.0000", "1.0000"]
        assert any("95% intervals" in p for p in atlas.check_summaries(bad))
    bad = copy.deepcopy(doc)
    bad["summary"]["certified_share_above"]["interval"] = ["0.9900", "1.0000"]
    assert any("certified_share_above" in p for p in atlas.check_summaries(bad))


def test_wilson_intervals():
    """Wilson's 95% interval: it holds the share, it narrows as the data grow, and at 0 of n it
    is [0, 1 − (about 3.84/n)] (the rule of three's neighbour)."""
    for n, total in ((0, 10), (3, 10), (10, 10), (500, 1000)):
        lo, hi = (float(x) for x in atlas.wilson(n, total))
        assert lo <= n / total <= hi and 0 <= lo and hi <= 1
    assert float(atlas.wilson(50, 100)[1]) - float(atlas.wilson(50, 100)[0]) > \
        float(atlas.wilson(500, 1000)[1]) - float(atlas.wilson(500, 1000)[0])
    z2 = atlas.Z95 ** 2
    assert abs(float(atlas.wilson(0, 100)[1]) - z2 / (100 + z2)) < 1e-4
    assert atlas.wilson(0, 0) is None


def test_refinement_samples_every_cell_and_near_the_window_ends(records, doc):
    lo, hi = Fraction("0.14"), Fraction("0.32")
    more = atlas.refinement(records[0], records[1], lo, hi)
    assert all(lo < x < hi for x in more)
    have = [Fraction(r["r"]) for r in records[0]] + more
    for c in doc["cells"]:
        a, b = atlas._alg(c["lo"]), atlas._alg(c["hi"])
        if a < atlas.Algebraic.rational(atlas.flint.fmpq(8, 25)) and atlas.Algebraic.rational(
                atlas.flint.fmpq(7, 50)) < b:
            assert any(atlas._in_open(x, a, b) for x in have), c["lo"]["digits"]
    k3 = next(a for a in doc["attractors"] if a["word"] == RULE.word(3))["windows"][0]
    assert any(atlas._in_open(x, atlas._alg(k3["lo"]), atlas._alg(k3["hi"])) for x in more)


def test_a_refined_run_reaches_the_seeded_window():
    rs = [Fraction("0.19")]
    word = RULE.word(2)                                                  # ]≈0.177205, ≈0.179226[
    rows, words = atlas.run_atlas(rs, atlas.data_grid(0), 3000, Serial(), seeds={word: "test"}, refine=1,
                                  word_max=44, r_range=(Fraction("0.176"), Fraction("0.2")))
    assert len(rows) > 1 and [r["r"] for r in rows] == sorted((r["r"] for r in rows), key=Fraction)
    reached = {o["word"] for r in rows for o in r["orbits"] if o["class"] == atlas.ATTRACTING}
    assert word in reached


@pytest.mark.parametrize("argv", [["--r-range", "0.5", "0.2"], ["--r-range", "0", "2"], ["--r-range", "x", "1"],
                                  ["--resolution", "0"], ["--data", "-1"], ["--collisions", "0"], ["--sample", "2"],
                                  ["--check"], ["--check", "--sample", "0"]])
def test_bad_input_exits_2(argv, tmp_path, capsys):
    assert cli.main(["atlas", *argv, "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("certify: error:") and len(err.strip().splitlines()) == 1


def test_an_unwritable_output_directory_exits_2(tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    assert cli.main(["atlas", "--resolution", "1", "--out", str(blocker / "sub")]) == 2


def test_the_command_on_two_processes_writes_the_atlas_and_resumes(tmp_path, capsys):
    argv = ["atlas", "--r-range", "0.2", "0.3", "--resolution", "1", "--data", "1", "--collisions", "2000",
            "--seeds", "none", "--refine", "0", "--out", str(tmp_path)]
    assert cli.main([*argv, "--jobs", "2"]) == 0
    first = (tmp_path / "atlas.json").read_bytes()
    assert "wrote" in capsys.readouterr().out and (tmp_path / "atlas-state.jsonl").exists()
    assert cli.main([*argv, "--jobs", "1", "--resume", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    jsonschema.validate(doc, SCHEMA)
    assert (tmp_path / "atlas.json").read_bytes() == first and doc["summary"]["orbits"] == 9
    stray = {"kind": "word", "word": "ab" * 130, "compact": "(ab)^130", "length": 260, "outcome": "too long",
             "attracting": [], "attracting_points": [], "undecided": [], "word_max": 240, "word_seconds": 600}
    with (tmp_path / "atlas-state.jsonl").open("a") as f:                 # a word met at an r no longer asked for
        f.write(json.dumps(stray) + "\n")
    assert cli.main([*argv, "--jobs", "1", "--resume"]) == 0
    assert (tmp_path / "atlas.json").read_bytes() == first               # kept in the state, not listed


def test_the_refinement_runs_until_a_round_asks_for_no_new_r(monkeypatch):
    asked = []

    def refinement(r_records, word_records, lo, hi):
        asked.append(len(r_records))
        return [Fraction(1, 5 + len(asked))] if len(asked) < 3 else []
    monkeypatch.setattr(atlas, "refinement", refinement)
    rows, _words = atlas.run_atlas([Fraction(1, 4)], atlas.data_grid(0), 500, Serial(), refine=8,
                                   r_range=(Fraction(1, 10), Fraction(1, 2)))
    assert asked == [1, 2, 3] and [r["r"] for r in rows] == ["1/7", "1/6", "1/4"]


def test_the_progress_bar_follows_a_total_that_grows():
    import io

    from certify.run import progress

    class Terminal(io.StringIO):
        def isatty(self):
            return True
    tty = Terminal()
    bar = progress.Bar("job", tty)
    bar(1, 3, "r = 1/5")
    bar(2, 4, "10-letter word")                    # a new word met: one more job
    assert "2/4" in tty.getvalue()
    bar(4, 4)
    assert progress._OPEN == []


def test_unresolved_orbits_say_what_they_show(doc):
    r = atlas.flint.fmpq(9, 10)
    assert atlas.unresolved_kind(None, r) == atlas.NOTHING
    assert atlas.unresolved_kind("abcb", r) == atlas.NOT_ATTRACTING               # repelling near r = 1
    assert atlas.unresolved_kind("abacbabcbcabcb", r) == atlas.TRANSIENT           # attracting at 9/10
    kinds = doc["summary"]["unresolved_by_kind"]
    assert sum(v for k, v in kinds.items() if k != "certified by a longer run") == doc["summary"]["classes"][
        atlas.UNRESOLVED]
    for row in doc["r"]:
        for o in row["orbits"]:
            assert (o["unresolved"] is None) == (o["class"] != atlas.UNRESOLVED)


def test_a_wrong_unresolved_kind_or_rerun_is_caught(doc, chaos_doc):
    bad = copy.deepcopy(doc)
    row = bad["r"][0]
    o = row["orbits"][0]
    o["rerun"] = 7
    assert any("run again" in p for p in atlas.check_orbits(bad, [row]))
    bad = copy.deepcopy(chaos_doc)                  # its r = 12471/12500 has unresolved orbits (abcb repeated)
    row = next(r for r in bad["r"] if any(o["class"] == atlas.UNRESOLVED for o in r["orbits"]))
    o = next(o for o in row["orbits"] if o["class"] == atlas.UNRESOLVED)
    o["unresolved"] = "no such kind"
    assert any("no such kind" in p for p in atlas.check_orbits(bad, [row]))


def _committed(version=4):
    """reports/atlas.json, or the test skipped when it is absent or older than ``version``."""
    from certify.run.files import load_findings
    doc = load_findings("atlas.json")
    if doc is None or doc["version"] < version:
        pytest.skip(f"the committed atlas predates version {version} (regenerate: docs/atlas.md)")
    return doc


def test_the_committed_atlas_misses_no_seed_nor_family_member(monkeypatch):
    """reports/atlas.json: every known attractor and family member has its record and every
    family its three certified members and certified prediction; dropping one is caught."""
    monkeypatch.setattr(atlas, "FAMILIES", FAMILIES)
    doc = _committed(atlas.VERSION)
    assert atlas.check_seeds(doc) == [] and atlas.check_families(doc) == []
    assert {f["family"] for f in doc["families"]} == {rule.name for rule in FAMILIES}
    member = doc["families"][-1]["members"][1]["word"]
    bad = copy.deepcopy(doc)
    bad["attractors"] = [a for a in bad["attractors"] if a["word"] != member]
    bad["words"] = [w for w in bad["words"] if w["word"] != member]
    assert atlas.check_seeds(bad) and atlas.check_families(bad)


def test_the_committed_atlas_horseshoes_intervals_and_loops_check():
    """reports/atlas.json: its summaries, intervals and loops derived again from its rows; the
    horseshoes of two sampled r proved again from their printed boxes and searched again;
    a horseshoe dropped, a loop's rotation number or a share's interval altered is caught."""
    doc = _committed(atlas.VERSION)
    assert atlas.check_summaries(doc) == []
    proved = [row for row in doc["r"] if (row["horseshoe"] or {}).get("certified")]
    assert proved and doc["summary"]["horseshoes"]["proved"] == len(proved)
    assert atlas.check_chaos(doc, [proved[0], proved[-1]]) == []
    bad = copy.deepcopy(doc)
    row = next(r for r in bad["r"] if r["r"] == proved[0]["r"])
    row["horseshoe"] = {"certified": False, "tried": 0}
    assert atlas.check_chaos(bad, [row]) and atlas.check_summaries(bad)
    bad = copy.deepcopy(doc)
    bad["curves"][0]["near"] = [[0, 1]]
    assert atlas.check_summaries(bad)
    bad = copy.deepcopy(doc)
    cell = next(c for c in bad["cells"] if c["orbits"])
    cell["intervals"][next(iter(cell["intervals"]))] = ["0.0000", "1.0000"]
    assert atlas.check_summaries(bad)


def test_a_window_end_is_found_a_resonance_with_a_large_denominator():
    """(abacbc)^9a(bcabac)^9bcb closes at ρ = 18/37 and the 122-letter word at 19/40: with
    resonances looked up to q ≤ 32 only, they read "near" (15 of 17 interior upper ends of a
    coarse atlas were resonances, 17 of 17 with q ≤ 120)."""
    from certify.patterns.island_theorem import resonances_of_q
    from certify.patterns.pattern import end_data
    s = next(x for x in resonances_of_q(37) if x.p == 18)
    assert atlas.end_rotation(end_data(s.r))["resonance"] == [18, 37]
    assert atlas.closes_at(end_data(s.r), 18, 37) and not atlas.closes_at(end_data(s.r), 17, 35)
    assert atlas.end_rotation(end_data(s.r), 36)["resonance"] is None                 # q = 37 > 36: "near"
    off = atlas.Algebraic.rational(atlas.flint.fmpq(1731, 10000))          # ρ there is not p/q with q ≤ 120
    rot = atlas.end_rotation(end_data(off))
    assert rot["resonance"] is None and rot["near"][1] <= atlas.NEAR_Q


def _no_period_rule_one(rec):
    """``rec`` as the rule before :data:`atlas.LATE_RULE` made it: orbits with no period left
    unresolved (not run again), no ``late`` mark."""
    old = copy.deepcopy(rec)
    del old["late"]
    q = Fraction(rec["r"])
    for i, o in enumerate(old["orbits"]):
        if o["rerun"] is not None and o["class"] != atlas.UNRESOLVED:
            x = atlas.ident.classify(q, o["theta0"], o["phi0"], rec["collisions"])
            fq = atlas._fq(rec["r"])
            kind = atlas.unresolved_kind(x.word, fq)
            old["orbits"][i] = atlas._orbit_record(x, None, kind, o["theta0"], o["phi0"], fq)
    return old


def test_a_run_with_no_period_is_run_again_4_times_longer_below_and_16_above_3_minus_2_sqrt2():
    """late_factor of a run with no period: LATE where horseshoes are proved (r < 3 − 2√2 ≈ 0.171573),
    LONGER on the island's interval; a long transient LATE and a word not attracting LONGER on both."""
    below, above = atlas._fq("17/100"), atlas._fq("43/250")
    assert atlas.late_factor(atlas.NOTHING, None, below) == atlas.LATE
    assert atlas.late_factor(atlas.NOTHING, None, above) == atlas.LONGER
    assert atlas.late_stages(atlas.NOTHING, None, below) == (atlas.LATE,)
    assert atlas.late_stages(atlas.NOTHING, None, above) == (atlas.LATE, atlas.LONGER)         # 4×, then 16×
    for r in (below, above):                  # abcb: a saddle at 17/100, repelling fast (ρ ≈ 5.75) at 43/250
        assert atlas.late_factor(atlas.TRANSIENT, "abcb", r) == atlas.LATE
        assert atlas.late_factor(atlas.NOT_ATTRACTING, "abcb", r) == atlas.LONGER
        assert atlas.late_factor(atlas.NOTHING, "x" * 1200, r) is None
    rule_3 = {"class": atlas.UNRESOLVED, "unresolved": atlas.NOTHING, "observed": None, "rerun": atlas.LATE * 20_000}
    assert atlas.rerun_due(rule_3, above, 20_000) and not atlas.rerun_due(rule_3, below, 20_000)
    assert not atlas.rerun_due({**rule_3, "rerun": atlas.LONGER * 20_000}, above, 20_000)
    assert atlas.rerun_due({**rule_3, "rerun": None}, below, 20_000)


def test_a_word_repelling_slowly_is_run_again_over_four_of_its_e_folds():
    """Rule 5: near r = 1 abcb repels with ρ − 1 from 5.6e-5 (r = 93271/100000) down to 2e-9
    (r = 12471/12500); its orbits are run again 16× longer, then over SPIRAL_EFOLDS e-folds L/ln ρ
    (a power of 2 times the first run) when the 16× run does not (at 93271/100000 it does: 4 e-folds
    are 284 000 collisions) and that is at most SPIRAL_MAX times; beyond, 16× only."""
    stages = {r: atlas.late_stages(atlas.NOT_ATTRACTING, "abcb", atlas._fq(r))
              for r in ("93271/100000", "19211/20000", "33/34", "12239/12500", "12471/12500")}
    assert stages == {"93271/100000": (16,), "19211/20000": (16, 128), "33/34": (16, 256),
                      "12239/12500": (16, 512), "12471/12500": (16,)}
    efolds = 4 * 4 / math.log(float(atlas.ident.decided("abcb", atlas._fq("19211/20000")).modulus.mid()))
    assert 64 * 20_000 < efolds <= 128 * 20_000
    o = {"class": atlas.UNRESOLVED, "unresolved": atlas.NOT_ATTRACTING, "observed": "abcb", "rerun": 16 * 20_000}
    assert atlas.rerun_due(o, atlas._fq("33/34"), 20_000) and not atlas.rerun_due(o, atlas._fq("12471/12500"), 20_000)
    assert not atlas.rerun_due({**o, "rerun": 256 * 20_000}, atlas._fq("33/34"), 20_000)


def test_a_run_with_no_period_is_run_again_longer_and_its_class_checked():
    """r = 28/33, 5000 collisions: two of the tool's 8 orbits show no period (the run settles
    on abacba(bc)^2abcb after its middle); run again 4× longer (rule 4's first stage above 3 − 2√2)
    they are proved attracting.  Marking one unresolved again, or not run again, or certified from a collision of
    the first run, makes the check fail."""
    data = atlas.data_grid(0)
    rec = atlas.r_job("28/33", data, 5000)
    again = [o for o in rec["orbits"] if o["rerun"] == atlas.LATE * 5000]     # the 4× stage proves them
    assert len(again) >= 2 and all(o["class"] == atlas.ATTRACTING and o["unresolved"] is None for o in again)
    for o in again:                                           # the first run alone leaves them unresolved, no period
        x = atlas.ident.classify(Fraction(28, 33), o["theta0"], o["phi0"], 5000)
        assert x.cls == atlas.UNRESOLVED and x.word is None
    doc = {"parameters": {"collisions": 5000}, "r": [{**rec, "counts": atlas._counts(rec["orbits"]),
                                                      "total": len(rec["orbits"])}]}
    assert atlas.check_orbits(doc) == []
    bad = copy.deepcopy(doc)
    i = next(i for i, o in enumerate(rec["orbits"]) if o["rerun"])
    bad["r"][0]["orbits"][i] = _no_period_rule_one(rec)["orbits"][i]
    bad["r"][0]["counts"] = atlas._counts(bad["r"][0]["orbits"])
    problems = atlas.check_orbits(bad)
    assert any("run again" in p for p in problems) and any("by identify" in p for p in problems)
    bad = copy.deepcopy(doc)                       # certified at a collision of the first run: not what proves it
    o = bad["r"][0]["orbits"][i]
    assert o["certified_from"] > 5000
    o["certified_from"] = 4000
    assert any("certified from 4000" in p for p in atlas.check_orbits(bad))


def test_an_older_record_is_upgraded_by_running_only_the_late_orbits(tmp_path):
    """An r record of the rule before LATE_RULE (resumed from an older state): r_job keeps its
    island and the orbits the rule does not run again (a mark left in one survives), and runs
    the others: the same record as a fresh job; run_atlas --resume does it."""
    data = atlas.data_grid(0)
    fresh = atlas.r_job("28/33", data, 5000)
    old = _no_period_rule_one(fresh)
    kept = next(i for i, o in enumerate(old["orbits"]) if o["class"] == atlas.ISLAND)
    old["orbits"][kept]["why"] = "kept from the older record"
    up = atlas.r_job("28/33", data, 5000, old)
    assert up["orbits"][kept]["why"] == "kept from the older record" and up["island"] == old["island"]
    up["orbits"][kept]["why"] = fresh["orbits"][kept]["why"]
    assert {**up, "seconds": 0} == {**fresh, "seconds": 0}
    state = tmp_path / "state.jsonl"
    state.write_text(json.dumps(old) + "\n", encoding="utf-8")
    rows, _ = atlas.run_atlas([Fraction(28, 33)], data, 5000, Serial(), state, True, seeds={}, word_max=4)
    assert rows[0]["late"] == atlas.LATE_RULE and [o["rerun"] for o in rows[0]["orbits"]] == [
        o["rerun"] for o in fresh["orbits"]]


def test_the_observed_words_are_one_per_cyclic_word(chaos_doc):
    """Rotations of one cyclic word (the same block read from another collision) are one entry
    of the observed words and of the loops; an entry split by rotation is caught."""
    assert atlas.least_rotation("cbab") == atlas.least_rotation("abcb") == "abcb"
    rows = [{"r": "1/2", "orbits": [{"class": atlas.UNRESOLVED, "observed": w, "curve": None}
                                    for w in ("abcb", "bcba", "cbab", "babc")]}]
    assert atlas.observed_words(rows) == {"abcb": 4}
    bad = copy.deepcopy(chaos_doc)
    row, o = next((r, o) for r in bad["r"] for o in r["orbits"] if o.get("curve"))
    o["observed"] = o["observed"][1:] + o["observed"][0]           # the same word read from the next collision
    assert atlas.check_summaries(bad) == []
    bad["observed_words"] = {o["observed"]: 1, **{w: n - (w == "abcb") for w, n in bad["observed_words"].items()}}
    assert any("observed words" in p for p in atlas.check_summaries(bad))


def test_a_window_end_resonance_is_decided_in_one_place(doc):
    """island_theorem.end_rotation decides every window end (the island's own ends 1/2 and 1/4;
    inside, ρ's ball once and the resonance); the atlas's rotation records and its counts of
    interior ends read it; an altered resonance or island-end mark, or count, is caught."""
    from certify.patterns import island_theorem as it
    e = it.end_rotation(it.LOWER_END, 120)
    assert e.island_end and e.resonance == (1, 2) and e.ball is None
    assert it.end_rotation(atlas.Algebraic.rational(atlas.flint.fmpq(1)), 120).resonance == (1, 4)
    assert it.end_rotation(atlas.Algebraic.rational(atlas.flint.fmpq(1, 10)), 120) is None
    x = atlas.Algebraic.surd(2, -1, 3)                                   # 2 − √3: ρ = 1/3
    e = it.end_rotation(x, 6)
    assert not e.island_end and e.resonance == (1, 3) and e.ball[0] <= atlas.flint.fmpq(1, 3) <= e.ball[1]
    assert it.resonance_of(x, 6) == (1, 3) and it.resonance_of(it.LOWER_END, 6) is None
    assert atlas.check_ends(doc) == []
    def inside(w):                                  # a resonant upper end strictly inside ]3 − 2√2, 1[
        return w["rotation"] and w["rotation"]["resonance"] and not w["rotation"]["island_end"]
    a = next(a for a in doc["attractors"] if any(inside(w) for w in a["windows"]))
    for key, value in (("resonance", [0, 1]), ("island_end", True)):
        bad = copy.deepcopy(doc)
        w = next(w for w in next(b for b in bad["attractors"] if b["name"] == a["name"])["windows"] if inside(w))
        w["rotation"][key] = value
        assert any("decided again" in p for p in atlas.check_ends(bad))
    bad = copy.deepcopy(doc)
    bad["summary"]["interior_ends"]["resonant_upper"] += 1
    assert any("interior_ends" in p for p in atlas.check_ends(bad))


def test_the_committed_atlas_orbits_proved_by_the_longer_run_check():
    """reports/atlas.json: the orbits of r = 28/33 that only the longer run proves (their first
    run shows no period) are proved again by identify; one marked unresolved is caught; the
    observed words are one per cyclic word."""
    doc = _committed()
    row = next(r for r in doc["r"] if r["r"] == "28/33")
    late = [o for o in row["orbits"] if o["rerun"] and o["class"] != atlas.UNRESOLVED]
    assert late and doc["summary"]["unresolved_by_kind"]["certified by a longer run"] >= len(late)
    late = late[:1]                                          # one orbit: 100 000 collisions with its rerun
    sub = {**row, "orbits": late, "counts": atlas._counts(late), "total": len(late)}
    assert atlas.check_orbits(doc, [sub]) == []
    o = late[0]
    x = atlas.ident.classify(Fraction(row["r"]), o["theta0"], o["phi0"], doc["parameters"]["collisions"])
    bad = copy.deepcopy(sub)
    fq = atlas._fq(row["r"])
    bad["orbits"][0] = atlas._orbit_record(x, None, atlas.unresolved_kind(x.word, fq), o["theta0"], o["phi0"], fq)
    bad["counts"] = atlas._counts(bad["orbits"])
    assert any("by identify" in p for p in atlas.check_orbits(doc, [bad]))
    assert all(w == atlas.least_rotation(w) for w in doc["observed_words"])
    assert [c["word"] for c in doc["curves"]] == [atlas.least_rotation(c["word"]) for c in doc["curves"]]


def test_the_committed_atlas_window_ends_are_decided_again():
    """reports/atlas.json: the rotation records of the windows closing at the first resonances
    above 3 − 2√2 decided again (island_theorem.end_rotation); a moved resonance is caught."""
    doc = _committed()
    atts = [a for a in doc["attractors"] if any((w["rotation"] or {}).get("resonance") for w in a["windows"])][:6]
    assert atlas.check_rotations(atts) == []
    bad = copy.deepcopy(atts)
    w = next(w for w in bad[-1]["windows"] if (w["rotation"] or {}).get("resonance"))
    w["rotation"]["resonance"] = [w["rotation"]["resonance"][0] + 1, w["rotation"]["resonance"][1]]
    assert any("decided again" in p for p in atlas.check_rotations(bad))


@pytest.mark.slow
def test_the_committed_atlas_interior_ends_are_decided_again():
    """reports/atlas.json: every window's rotation record and the summary's counts of interior
    ends (as committed) decided again from all its attractors (check_ends); a count moved is
    caught. About 25 s measured on 2 busy cores."""
    doc = _committed()
    assert atlas.check_ends(doc) == []
    bad = copy.deepcopy(doc)
    bad["summary"]["interior_ends"]["resonant_upper"] -= 1
    assert any("interior_ends" in p for p in atlas.check_ends(bad))


def _longer_run_sample(doc, step=10):
    """The committed rows cut to every ``step``-th orbit (in the atlas's order) that only the
    longer run proves (rerun set, class certified), each row with its counts recounted."""
    late = [(row, o) for row in doc["r"] for o in row["orbits"] if o["rerun"] and o["class"] != atlas.UNRESOLVED]
    rows: dict = {}
    for row, o in late[::step]:
        rows.setdefault(row["r"], (row, []))[1].append(o)
    return len(late), [{**row, "orbits": os, "counts": atlas._counts(os), "total": len(os)}
                       for row, os in rows.values()]


@pytest.mark.slow
def test_the_committed_atlas_longer_run_orbits_sampled_check():
    """reports/atlas.json: every 10th of the orbits only a longer run proves (44 of 436 in version
    5, over the r where they are) classified again by identify, run again 4× or 16× longer, with
    their class, word, branch and the collision they are certified from (check_orbits)."""
    doc = _committed()
    n, rows = _longer_run_sample(doc)
    assert n == doc["summary"]["unresolved_by_kind"]["certified by a longer run"]
    assert sum(row["total"] for row in rows) == len(range(0, n, 10))
    assert atlas.check_orbits(doc, rows) == []


def _one_row(rec):
    return {"parameters": {"collisions": rec["collisions"]},
            "r": [{**rec, "counts": atlas._counts(rec["orbits"]), "total": len(rec["orbits"])}]}


def test_a_block_longer_than_the_parser_reads_is_proved_at_its_r():
    """r = 40/233, the tool's first datum: the run repeats a 458-letter block (over the parser's
    400 letters); the atlas decides it at r up to LONG_WORD letters and proves it attracting.
    The word altered by one letter, or the row moved to r = 3/10 (outside where it is proved),
    or the orbit left unresolved as rule 2 left it, makes the check fail; an r record of rule 2
    is upgraded by running that orbit again."""
    rec = atlas.r_job("40/233", atlas.data_grid(0)[:1], 20_000)
    o = rec["orbits"][0]
    assert o["class"] == atlas.ATTRACTING and len(o["word"]) == 458 > atlas.MAX_LENGTH and o["rerun"] is None
    doc = _one_row(rec)
    assert atlas.check_orbits(doc) == []
    bad = copy.deepcopy(doc)
    w = bad["r"][0]["orbits"][0]["word"]
    bad["r"][0]["orbits"][0]["word"] = w.replace("bab", "bcb", 1)             # one letter: still a word
    assert bad["r"][0]["orbits"][0]["word"] != w
    problems = atlas.check_orbits(bad)
    assert any("by identify" in p for p in problems) and any("not attracting there" in p for p in problems)
    bad = copy.deepcopy(doc)
    bad["r"][0]["r"] = "3/10"
    assert any("not attracting there" in p for p in atlas.check_orbits(bad))
    old = copy.deepcopy(rec)                              # rule 2: the block not read, the orbit unresolved
    del old["late"]
    old["orbits"][0] = {**o, "class": atlas.UNRESOLVED, "certified_from": None, "word": None, "branch": None,
                        "observed": o["word"], "why": "observed: not a word of the reduction (over 400)",
                        "unresolved": atlas.NOTHING}
    assert atlas.unread(old["orbits"][0]) and not atlas.late(old["orbits"][0], atlas._fq("40/233"))
    assert any("by identify" in p for p in atlas.check_orbits(_one_row(old)))
    assert {**atlas.r_job("40/233", atlas.data_grid(0)[:1], 20_000, old), "seconds": 0} == {**rec, "seconds": 0}


def test_a_word_not_attracting_at_r_is_run_again_sixteen_times_longer():
    """r = 93271/100000 (near r = 1), the tool's first datum: the run repeats abcb, whose
    periodic orbit is not attracting there; run again LONGER = 16× longer it is proved to
    follow a 14-letter word from collision 128 472, past the 4× run.  Left unresolved (not run
    again), or certified from a collision of a shorter run, the check fails."""
    rec = atlas.r_job("93271/100000", atlas.data_grid(0)[:1], 20_000)
    o = rec["orbits"][0]
    assert o["class"] == atlas.ATTRACTING and o["rerun"] == atlas.LONGER * 20_000
    assert atlas.LATE * 20_000 < o["certified_from"] <= atlas.LONGER * 20_000
    x = atlas.ident.classify(Fraction(93271, 100000), o["theta0"], o["phi0"], 20_000, word_max=atlas.LONG_WORD)
    fq = atlas._fq(rec["r"])
    assert x.cls == atlas.UNRESOLVED and atlas.unresolved_kind(x.word, fq) == atlas.NOT_ATTRACTING
    doc = _one_row(rec)
    assert atlas.check_orbits(doc) == []
    bad = copy.deepcopy(doc)
    bad["r"][0]["orbits"][0] = atlas._orbit_record(x, None, atlas.NOT_ATTRACTING, o["theta0"], o["phi0"], fq)
    bad["r"][0]["counts"] = atlas._counts(bad["r"][0]["orbits"])
    problems = atlas.check_orbits(bad)
    assert any("run again" in p for p in problems) and any("by identify" in p for p in problems)
    bad = copy.deepcopy(doc)
    bad["r"][0]["orbits"][0]["certified_from"] = 60_000
    assert any("certified from 60000" in p for p in atlas.check_orbits(bad))


def test_the_committed_atlas_long_blocks_and_sixteen_times_longer_runs_check():
    """reports/atlas.json (rule 3): an orbit proved on a block longer than the parser reads (the
    shortest such word) and one proved only by the run 16× longer (the first at r ≤ 0.94) are
    proved again by identify (check_orbits on those two orbits); the long word altered by one
    letter, its row moved to r = 3/10, or the 16× orbit marked unresolved as its first run
    leaves it, makes the check fail."""
    doc = _committed(5)
    collisions = doc["parameters"]["collisions"]
    long = [(row, o) for row in doc["r"] for o in row["orbits"] if o["word"] and len(o["word"]) > atlas.MAX_LENGTH]
    assert long and all(len(o["word"]) <= atlas.LONG_WORD for _, o in long)
    row, o = min(long, key=lambda ro: (len(ro[1]["word"]), Fraction(ro[0]["r"])))
    sub = {**row, "orbits": [o], "counts": atlas._counts([o]), "total": 1}
    assert atlas.check_orbits(doc, [sub]) == []
    bad = copy.deepcopy(sub)
    bad["orbits"][0]["word"] = o["word"].replace("bab", "bcb", 1)             # one letter: still a word
    assert bad["orbits"][0]["word"] != o["word"]
    assert any("not attracting there" in p for p in atlas.check_orbits(doc, [bad]))
    bad = {**copy.deepcopy(sub), "r": "3/10"}
    assert any("not attracting there" in p for p in atlas.check_orbits(doc, [bad]))
    longer = [(row, o) for row in doc["r"] for o in row["orbits"]
              if o["rerun"] == atlas.LONGER * collisions and o["class"] != atlas.UNRESOLVED]
    assert longer and doc["summary"]["unresolved_by_kind"]["certified by a longer run"] >= len(longer)
    row, o = next((row, o) for row, o in longer if Fraction(row["r"]) <= Fraction(94, 100))
    assert o["certified_from"] > collisions
    sub = {**row, "orbits": [o], "counts": atlas._counts([o]), "total": 1}
    assert atlas.check_orbits(doc, [sub]) == []
    fq = atlas._fq(row["r"])
    x = atlas.ident.classify(Fraction(row["r"]), o["theta0"], o["phi0"], collisions, word_max=atlas.LONG_WORD)
    assert atlas.unresolved_kind(x.word, fq) == atlas.NOT_ATTRACTING
    bad = copy.deepcopy(sub)
    bad["orbits"][0] = atlas._orbit_record(x, None, atlas.NOT_ATTRACTING, o["theta0"], o["phi0"], fq)
    bad["counts"] = atlas._counts(bad["orbits"])
    assert any("by identify" in p for p in atlas.check_orbits(doc, [bad]))


def test_the_committed_atlas_spiral_runs_check():
    """reports/atlas.json (rule 5): the orbit of the least r that only the run over four e-folds of
    abcb's repulsion proves (32× the first run, past the 16× run) is proved again by identify from
    the same collision; marked unresolved as its 16× run leaves it, or certified from a collision of
    the 16× run, the check fails."""
    doc = _committed(8)
    collisions = doc["parameters"]["collisions"]
    spiral = [(row, o) for row in doc["r"] for o in row["orbits"]
              if (o["rerun"] or 0) > atlas.LONGER * collisions and o["class"] != atlas.UNRESOLVED]
    assert len(spiral) > 500
    row, o = min(spiral, key=lambda ro: (ro[1]["rerun"], Fraction(ro[0]["r"])))
    assert o["rerun"] == 2 * atlas.LONGER * collisions and o["certified_from"] > atlas.LONGER * collisions // 4
    sub = {**row, "orbits": [o], "counts": atlas._counts([o]), "total": 1}
    assert atlas.check_orbits(doc, [sub]) == []
    fq = atlas._fq(row["r"])
    x = atlas.ident.classify(Fraction(row["r"]), o["theta0"], o["phi0"], atlas.LONGER * collisions,
                             word_max=atlas.LONG_WORD)
    assert x.cls == atlas.UNRESOLVED
    bad = copy.deepcopy(sub)
    bad["orbits"][0] = atlas._orbit_record(x, None, atlas.NOT_ATTRACTING, o["theta0"], o["phi0"], fq)
    bad["counts"] = atlas._counts(bad["orbits"])
    assert any("by identify" in p for p in atlas.check_orbits(doc, [bad]))
    bad = copy.deepcopy(sub)
    bad["orbits"][0]["certified_from"] = atlas.LONGER * collisions // 2
    assert atlas.check_orbits(doc, [bad])


def _atlas_state_tool():
    import importlib.util
    from pathlib import Path
    path = Path(__file__).resolve().parents[2] / "tools" / "atlas_state.py"
    spec = importlib.util.spec_from_file_location("atlas_state", path)
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    return tool


def test_a_state_rebuilt_from_the_committed_atlas_is_reused_as_it_is():
    """tools/atlas_state.py on reports/atlas.json: every r record carries the ``late`` mark, so
    ``certify atlas --resume`` takes each as done (:func:`atlas.current`, what its resume asks) rather
    than submitting it again; a row with an orbit that :func:`atlas.r_job` would still run longer (a
    row of an older rule) is left unmarked, to be upgraded."""
    doc = _committed(atlas.VERSION)
    tool = _atlas_state_tool()
    rows = [rec for rec in tool.records(doc) if rec["kind"] == "r"]
    assert len(rows) == len(doc["r"]) and all(atlas.current(rec) for rec in rows)
    older = copy.deepcopy(doc)
    older["r"] = older["r"][:1]
    older["r"][0]["orbits"][0].update({"class": atlas.UNRESOLVED, "unresolved": atlas.NOTHING, "observed": None,
                                       "rerun": None})
    [row] = [rec for rec in tool.records(older) if rec["kind"] == "r"]
    assert atlas.rerun_due(row["orbits"][0], atlas._fq(row["r"]), row["collisions"]) and not atlas.current(row)


def test_a_rule_spells_a_member_past_the_parsers_400_letters():
    """Rule.word reads up to LONG_WORD letters: member k = 38 of the 12k + 10 rule (466 letters) is the
    block every orbit of reports/atlas.json at r = 29/169 was proved to follow, and so are the other long
    blocks of docs/atlas.md, "Long blocks" (868 letters: k = 72 of the 12k + 4 rule; 554 and 458: k = 23
    and 19 of the 24k + 2 rule); the 400-letter parser refused them."""
    doc = _committed(atlas.VERSION)
    rows = {row["r"]: row for row in doc["r"]}
    by = {rule.spelling: rule for rule in FAMILIES}
    for r, spelling, k, length in (
            ("29/169", "(abacbc)^{k}a(bac)^2(bcabac)^{k}bcb", 38, 466),
            ("8579/50000", "(abacbc)^{k}a(bcabac)^{k}bcb", 72, 868),
            ("23/134", "(abacbc)^{k}a(bcabac)^{j}bc(ab)^2(cbcaba)^{k}c(bacbca)^{j}ba(cb)^2", 23, 554),
            ("40/233", "(abacbc)^{k}a(bcabac)^{j}bc(ab)^2(cbcaba)^{k}c(bacbca)^{j}ba(cb)^2", 19, 458)):
        word = by[spelling].word(k)
        assert len(word) == length > atlas.MAX_LENGTH
        followed = [o for o in rows[r]["orbits"] if o["word"] == word]
        assert followed and all(o["class"] == atlas.ATTRACTING for o in followed)
    assert {o["word"] for o in rows["29/169"]["orbits"]} == {by["(abacbc)^{k}a(bac)^2(bcabac)^{k}bcb"].word(38)}


def test_the_committed_atlas_orbit_a_turning_leap_moved_checks():
    """reports/atlas.json: at r = 45707/50000 orbit 19 is proved from collision 28 069 by the scan with
    the turning leaps (28 131 by the scan before them: the balls after a leap are other balls); it is
    proved again from that collision, and with the earlier scan's collision the check fails."""
    doc = _committed(8)
    row = next(row for row in doc["r"] if row["r"] == "45707/50000")
    o = row["orbits"][19]
    assert o["class"] == atlas.ATTRACTING and o["certified_from"] == 28_069
    sub = {**row, "orbits": [o], "counts": atlas._counts([o]), "total": 1}
    assert atlas.check_orbits(doc, [sub]) == []
    bad = copy.deepcopy(sub)
    bad["orbits"][0]["certified_from"] = 28_131
    assert atlas.check_orbits(doc, [bad])
