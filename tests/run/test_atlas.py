"""`certify atlas`: the atlas on a tiny grid against `orbit`, `island` and `identify`
(certify/run/atlas.py): a wrong window, a dropped attractor, a mislabelled class each make
:func:`check_atlas` fail; the schema; resuming; bad input exits 2."""
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
PARAMS = {"r_range": ["7/50", "8/25"], "resolution": 3, "data": 0, "collisions": 5000, "word_max": 30,
          "word_seconds": 60, "command": "test"}


def _run(state=None, resume=False, ex=None):
    rs = atlas.r_values(Fraction("0.14"), Fraction("0.32"), 3)              # 0.17 (below 3−2√2), 0.23, 0.29
    return atlas.run_atlas(rs, atlas.data_grid(0), 5000, ex or Serial(), state, resume, word_seconds=60, word_max=30)


@pytest.fixture(scope="module")
def records(tmp_path_factory):
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
    assert atlas.check_atlas(doc) == []
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
    assert "## Cells" in text and "## Families" in text and "(ab)^n(cb)^n" in text
    assert json.loads((tmp_path / "atlas.json").read_text(encoding="utf-8")) == json.loads(atlas.to_json(doc))
    assert (tmp_path / "atlas.png").read_bytes()[:4] == b"\x89PNG"


def test_a_word_too_long_or_too_slow_gets_no_window():
    assert atlas.word_job("ababcbcb", word_max=4)["outcome"] == "too long"
    assert atlas.word_job("(ab)^3(cb)^3", seconds=0.001)["outcome"] == "time limit"


def test_families_and_rotation_numbers(doc):
    fam = {f["family"]: f for f in doc["families"]}
    assert fam["(ab)^n(cb)^n"]["repeated"] == ["ab", "cb"]
    his = {m["attractor"]: m["windows"][0]["rotation_at_hi"] for f in doc["families"] for m in f["members"]}
    assert his["(ab)^2(cb)^2 (lower)"]["resonance"] == [1, 2]                # ends at 3−2√2
    assert his["a(bac)^2bcb (upper)"]["resonance"] == [1, 3]                 # ends at 2−√3, ρ = 1/3
    assert his["abacba(bc)^2abcb (upper)"]["resonance"] == [1, 4]            # ends at r = 1
    ends = {(x["attractor"], x["p"], x["q"]) for x in doc["summary"]["resonant_upper_ends"]}
    assert ("a(bac)^2bcb (upper)", 1, 3) in ends and doc["summary"]["upper_ends_above"] >= len(ends)
    groups = {(g["p"], g["q"]): g["attractors"] for g in doc["by_resonance"]}
    assert groups[(1, 4)] == ["abacba(bc)^2abcb (upper)"] and list(groups)[0] == (1, 2)   # by increasing r


@pytest.mark.parametrize("argv", [["--r-range", "0.5", "0.2"], ["--r-range", "0", "2"], ["--r-range", "x", "1"],
                                  ["--resolution", "0"], ["--data", "-1"], ["--collisions", "0"]])
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
            "--out", str(tmp_path)]
    assert cli.main([*argv, "--jobs", "2"]) == 0
    first = (tmp_path / "atlas.json").read_bytes()
    assert "wrote" in capsys.readouterr().out and (tmp_path / "atlas-state.jsonl").exists()
    assert cli.main([*argv, "--jobs", "1", "--resume", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    jsonschema.validate(doc, SCHEMA)
    assert (tmp_path / "atlas.json").read_bytes() == first and doc["summary"]["orbits"] == 9


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
