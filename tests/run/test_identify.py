"""`certify identify`: each orbit classified, island / attracting periodic / unresolved,
and each proof re-checked (certify/run/identify.py)."""
import json
import math
from fractions import Fraction
from pathlib import Path

import flint
import pytest
from hypothesis import given
from hypothesis import strategies as st

from certify import cli
from certify.algebra.algebraic import Algebraic
from certify.dynamics import island
from certify.dynamics.model import INDEX
from certify.numerics import grid
from certify.run import identify as ident

COMPLEX = "abacbabcbcabcb"
LONG = ("abacbcabacbcabacbcabacbcabacbcabcabacbcabacbcabacbcabacbcababcbcabacbcabacbcabacbcabacbcabacbacbcabacbcabacb"
        "cabacbcabacbcb")
SCHEMA = Path(ident.__file__).parents[1] / "schemas" / "identify.schema.json"


@pytest.fixture(scope="module")
def three_tenths():
    return ident.identify([Fraction(3, 10)], collisions=20_000)


def test_period_of_reads_the_shortest_period_after_a_transient():
    assert ident.period_of("cbcabacb" + "abcb" * 50) == "abcb"
    assert ident.period_of("ab" * 3 + COMPLEX * 20) == COMPLEX            # not a multiple of the period
    assert ident.period_of("abcb" * 5 + "acbc" * 5 + "abcb" * 3) is None      # the last half is not periodic
    assert ident.period_of(COMPLEX * 3) is None                                  # fewer than 4 periods in the last half
    assert ident.period_of("abcb" * 40, max_period=3) is None


def test_period_of_is_not_capped_at_120_and_agrees_with_a_brute_force_search():
    word = "ab" * 7 + LONG * 9
    assert len(LONG) == 122 and ident.period_of(word) == LONG
    half = word[len(word) - len(word) // 2:]
    brute = next(p for p in range(1, len(half)) if all(half[i] == half[i + p] for i in range(len(half) - p)))
    assert brute == 122 and ident.settled_from(word, 122) <= 14


def test_followed_is_the_rotation_ending_with_b():
    assert ident.followed(COMPLEX[5:] + COMPLEX[:5], COMPLEX) == COMPLEX
    word = "ababcbcbcb"                                # (ab)^2(cb)^3: its mirror is not a rotation of it
    mirror = word.translate(str.maketrans("ac", "ca"))
    rot = ident.followed(mirror, word)
    assert rot[-1] == "b" and rot in mirror + mirror and rot not in word + word


def _at(r):
    return Algebraic.rational(flint.fmpq(r.numerator, r.denominator))


def test_window_at_says_which_window_or_why_not():
    res = ident.orbit_analysis(COMPLEX)
    window, why = ident.window_at(res, _at(Fraction(3, 10)))
    assert window["pair"] == "complex" and window["branch"] == "upper" and "not a collapse" in why
    window, why = ident.window_at(res, _at(Fraction(1, 20)))         # middle branch: a saddle there
    assert window is None and "saddle" in why
    window, why = ident.window_at(res, _at(Fraction(1, 5)))          # outside every set
    assert window is None and "no periodic orbit" in why


def test_three_tenths_has_island_and_certified_attracting_orbits(three_tenths):
    classes = {x.cls for x in three_tenths}
    assert classes == {ident.ISLAND, ident.ATTRACTING}
    for x in three_tenths:
        if x.cls == ident.ATTRACTING:
            assert x.word == COMPLEX and x.word_status == "certified" and x.rotation[-1] == "b"
            assert x.certified_from is not None and "follows" in x.why
        else:
            assert x.word_status in (None, "observed") and "quasi-periodic" in x.why
        assert ident.verify(Fraction(3, 10), x.theta0, x.phi0, x.cls, x.certified_from, x.rotation) is None


def test_the_json_follows_its_schema(three_tenths):
    jsonschema = pytest.importorskip("jsonschema")
    doc = json.loads(ident.json_text(three_tenths))
    jsonschema.validate(doc, json.loads(SCHEMA.read_text()))
    assert {o["class"] for o in doc["orbits"]} == {"island", "attracting periodic"}
    bad = json.loads(json.dumps(doc))
    bad["orbits"][0]["word_status"] = "certified"
    bad["orbits"][0]["class"] = "unresolved"
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(bad, json.loads(SCHEMA.read_text()))


def test_a_mislabelled_class_a_wrong_word_or_a_state_outside_the_trap_is_refused(three_tenths):
    r = Fraction(3, 10)
    att = next(x for x in three_tenths if x.cls == ident.ATTRACTING)
    isl = next(x for x in three_tenths if x.cls == ident.ISLAND)
    k = att.certified_from
    assert ident.verify(r, att.theta0, att.phi0, ident.ISLAND, k) is not None          # not in the island
    assert ident.verify(r, isl.theta0, isl.phi0, ident.ATTRACTING, isl.certified_from + 14, COMPLEX) is not None
    assert ident.verify(r, att.theta0, att.phi0, ident.ATTRACTING, k, "abcb") is not None       # a wrong word
    rotated = att.rotation[1:] + att.rotation[0]
    assert ident.verify(r, att.theta0, att.phi0, ident.ATTRACTING, k, rotated) is not None    # the wrong phase
    assert ident.verify(r, att.theta0, att.phi0, ident.ATTRACTING, 0, att.rotation) is not None  # before it enters
    assert ident.verify(Fraction(1, 10), isl.theta0, isl.phi0, ident.ISLAND, 0) is not None      # no island at 1/10
    assert ident.verify(r, att.theta0, att.phi0, ident.UNRESOLVED, k) is not None


def test_a_lying_first_route_is_caught_by_the_second_route(monkeypatch):
    """The first route's states at b are replaced by the island's centre for 300 collisions:
    the scan proposes "island" for every orbit; the second route (its own ball run to the
    state, the island's membership decided on it) refuses it for the orbits that are
    attracted, which stay attracting periodic."""
    true_states = ident.engines.ball_states

    def lying(r, theta0, phi0, collisions, **kw):
        for k, j, n, bits in true_states(r, theta0, phi0, collisions, **kw):
            yield (k, j, tuple(flint.arb(z) for z in (-1, 0, 1)), bits) if k < 300 and j == INDEX["b"] \
                else (k, j, n, bits)
    monkeypatch.setattr(ident.engines, "ball_states", lying)
    theta0, phi0 = grid(8)
    x = ident.classify(Fraction(3, 10), float(theta0[0]), float(phi0[0]), 20_000)
    assert x.cls == ident.ATTRACTING and any("refused by the second route" in n for n in x.notes)


def test_a_ball_across_the_boundary_is_no_island_on_either_route(monkeypatch):
    """A state at b whose ball straddles the island's boundary ellipse (its midpoint inside:
    tests/dynamics/test_island.py) is proposed by neither route: the scan does not even ask
    the second route, and the second route refuses it."""
    r = flint.fmpq(3, 10)
    across = island.normal(flint.arb("0.54 +/- 0.01"), flint.arb(0))
    asked = []
    monkeypatch.setattr(ident.engines, "ball_states", lambda *a, **kw: iter([(1, INDEX["b"], across, 64)]))
    monkeypatch.setattr(ident, "verify", lambda *a: asked.append(a))
    x = ident.Identified("3/10", 0.5, 0.5, 1, 0)
    assert ident._scan(x, r, 0.5, 0.5, None, None, 1)[0] is None and asked == []
    monkeypatch.undo()
    monkeypatch.setattr(ident, "_state", lambda *a: ("b", across, 64))
    assert "not proved inside the island" in ident.verify(Fraction(3, 10), 0.5, 0.5, ident.ISLAND, 1)
    monkeypatch.setattr(ident, "_state", lambda *a: ("b", tuple(z.mid() for z in across), 64))
    assert ident.verify(Fraction(3, 10), 0.5, 0.5, ident.ISLAND, 1) is None       # its midpoint is inside


def test_without_the_island_or_the_trap_the_class_changes(monkeypatch):
    theta0, phi0 = grid(2)
    monkeypatch.setattr(island, "inside", lambda n, r: False)
    assert ident.classify(Fraction(3, 10), float(theta0[1]), float(phi0[1]), 5000).cls == ident.UNRESOLVED
    monkeypatch.setattr(ident.trapping.Trap, "ball_sign", lambda self, n: 0)
    assert ident.classify(Fraction(3, 10), float(theta0[0]), float(phi0[0]), 5000).cls == ident.UNRESOLVED


def test_r_outside_the_island_range_has_no_island_class():
    """At r = 1/10 < 3−2√2 the island does not exist (c_max < 0, Q indefinite): an orbit
    there is attracting periodic (the (ab)^3(cb)^3 window) or unresolved, never island."""
    theta0, phi0 = grid(1)
    x = ident.classify(Fraction(1, 10), float(theta0[0]), float(phi0[0]), 5000)
    assert x.cls == ident.ATTRACTING and x.compact == "(ab)^3(cb)^3"


def test_the_122_letter_word_of_0_173_is_certified():
    """Under a second: the float64 run, orbit_at, the trap and the scan."""
    theta0, phi0 = grid(8)
    x = ident.classify(Fraction(173, 1000), float(theta0[0]), float(phi0[0]), 100_000)
    assert x.cls == ident.ATTRACTING and x.word == LONG and len(x.rotation) == 122


def test_near_one_no_line_contradicts_itself():
    """Issue 25 item 8: r = 0.999 no longer reads "settles on (acb)^2(cab)^2; no periodic
    orbit with this word at r": the orbits repeating that word are island orbits."""
    theta0, phi0 = grid(2)
    x = ident.classify(Fraction(999, 1000), float(theta0[1]), float(phi0[1]), 20_000)
    assert x.cls == ident.ISLAND and "no periodic orbit with this word" not in x.line()
    y = ident.classify(Fraction(999, 1000), float(theta0[0]), float(phi0[0]), 5000)
    assert y.cls == ident.UNRESOLVED and y.line().count("observed") >= 1 and "certified:" not in y.line()


def test_a_repeated_word_whose_orbit_repels_says_what_is_proved_and_what_observed():
    """Issue 38 item 8: at r = 0.95 the run repeats abcb, whose periodic orbit is repelling;
    the line says both halves: proved (no attracting orbit of abcb at r), observed (the run
    repeats the word without converging to its orbit)."""
    theta0, phi0 = grid(1)
    x = ident.classify(Fraction(19, 20), float(theta0[0]), float(phi0[0]), 5000)
    line = x.line()
    assert x.cls == ident.UNRESOLVED and x.word == "abcb" and "periodic orbit at r is repelling" in line
    assert "proved, the word has no attracting periodic orbit at r" in line
    assert "observed, the run repeats it without converging to that orbit" in line


def test_the_grid_beyond_eight_is_a_superset_without_corners():
    t8, p8 = grid(8)
    t, p = grid(24)
    assert list(t[:8]) == list(t8) and list(p[:8]) == list(p8) and len(set(zip(t, p))) == 24
    assert all(abs(math.cos(x)) > 1e-3 for x in p)                   # never φ0 = π/2


@pytest.mark.parametrize("argv, says", [
    (["identify"], "--r R"),
    (["identify", "--r", "0.3", "--r-range", "0.1", "0.2", "3"], "--r R"),
    (["identify", "--r", "2"], "]0,1["),
    (["identify", "--r", "x"], "expected an exact number"),
    (["identify", "--r", "1e-400"], "within 2^-60 of 0"),
    (["identify", "--r-range", "0.2", "0.1", "3"], "LO < HI"),
    (["identify", "--r-range", "0.1", "0.2", "z"], "COUNT"),
    (["identify", "--r", "0.3", "--orbits", "0"], "positive"),
    (["identify", "--section5", "--r", "0.3"], "--section5"),
    (["identify", "--r", "0.3", "--out", "somewhere"], "--out"),
])
def test_bad_input_is_one_line_and_exit_2(argv, says, capsys):
    assert cli.main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and says in err, err


def test_the_command_prints_one_line_per_orbit_with_its_class(capsys):
    assert cli.main(["identify", "--r", "3/10", "--orbits", "2", "--collisions", "5000"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == 2 and lines[0].split(": ")[1] in ident.CLASSES


def test_windows_adds_the_attracting_window_of_short_words_only_when_asked():
    theta0, phi0 = grid(1)
    x = ident.classify(Fraction(3, 10), float(theta0[0]), float(phi0[0]), 5000, windows=True)
    assert x.cls == ident.ATTRACTING and x.window["pair"] == "complex" and x.window["hi"]["exact"] == "1"
    assert Fraction(x.window["lo"]["interval"][1]) < Fraction(3, 10)
    assert ident.classify(Fraction(3, 10), float(theta0[0]), float(phi0[0]), 5000).window is None


def _plain_ladder(r, theta0, phi0, k):
    """The second route's ladder without jumps: VERIFY_START doubled until all k collisions are decided."""
    from certify.algebra.balls import precision
    from certify.dynamics.reduction import ball_run
    prec = ident.VERIFY_START
    while True:
        with precision(prec):
            n0 = ident.rules.initial_normal(flint.arb(theta0), flint.arb(phi0), "b", flint.arb.cos, flint.arb.sin)
        letters, last, n = ball_run("b", n0, r, k, prec)
        if len(letters) == k:
            return last, n, prec
        prec *= 2


def test_the_ladder_jumps_to_the_rung_that_doubling_reaches():
    """At r = 4/5 the balls lose about a bit per collision: 2300 collisions need 2048 bits.
    The jumps of next_precision land on the rung the plain doubling ladder stops at, with
    the same contact and a state overlapping it (and on fewer runs)."""
    theta0, phi0 = grid(2)
    r = flint.fmpq(4, 5)
    t, p = float(theta0[0]), float(phi0[0])
    for k in (150, 700, 2300):
        got, want = ident._state(r, t, p, k), _plain_ladder(r, t, p, k)
        assert got[0] == want[0] and got[2] == want[2]
        assert all((got[1][i] / got[1][1]).overlaps(want[1][i] / want[1][1]) for i in (0, 2))   # one direction
    assert want[2] == 2048


def test_next_precision_doubles_at_least_once_and_never_passes_the_cap():
    assert ident.next_precision(128, 171, 4511) == 4096        # 171 collisions at 128 bits: 4511 need 4096
    assert ident.next_precision(128, 171, 2386) == 2048
    assert ident.next_precision(128, 171, 700) == 512           # 684 predicted at 512, and 1/16 more
    assert ident.next_precision(128, 127, 130) == 256           # at least one rung up
    assert ident.next_precision(256, 3, 5000) == 512             # stopped early: no rate, one rung
    assert ident.next_precision(128, 100, 10 ** 9) == ident.VERIFY_CAP


def test_a_block_longer_than_the_parser_reads_is_decided_up_to_word_max():
    """r = 40/233, the tool's first datum: the run repeats a block of 458 letters (member k = 19
    of the atlas's rule of 24k + 2 letters).  By default (word_max = the parser's 400) it is not analysed and
    said so; with word_max = 1000 it is read as plain letters and proved attracting (trap and
    second route as for a short word).  The second route refuses the claim with the word
    altered by one letter and at r = 3/10 (not attracting there, orbit_at); word_max beyond
    MAX_ANALYSED is a usage error."""
    r, (th, ph) = Fraction(40, 233), (float(grid(8)[0][0]), float(grid(8)[1][0]))
    x = ident.classify(r, th, ph, 20_000)
    assert x.cls == ident.UNRESOLVED and "a block of 458 letters (longer than 400: not analysed)" in x.why
    y = ident.classify(r, th, ph, 20_000, word_max=1000)
    assert y.cls == ident.ATTRACTING and len(y.word) == 458 and y.certified_from == 1680
    k = y.certified_from
    assert ident.verify(r, th, ph, ident.ATTRACTING, k, y.rotation) is None
    altered = y.rotation.replace("bab", "bcb", 1)                        # one letter: still a word
    assert altered != y.rotation
    assert "no attracting periodic orbit" in ident.verify(r, th, ph, ident.ATTRACTING, k, altered)
    assert "no attracting periodic orbit" in ident.verify(Fraction(3, 10), th, ph, ident.ATTRACTING, k, y.rotation)
    with pytest.raises(ident.UsageError, match="word_max"):
        ident.classify(r, th, ph, 1000, word_max=ident.MAX_ANALYSED + 1)


def _counted(monkeypatch) -> list:
    """The collisions k of every ball state the scan computes (engines.ball_states wrapped)."""
    true_states, made = ident.engines.ball_states, []

    def states(*a, **kw):
        for s in true_states(*a, **kw):
            made.append(s[0])
            yield s
    monkeypatch.setattr(ident.engines, "ball_states", states)
    return made


def test_a_longer_run_goes_on_from_the_shorter_runs_scan(monkeypatch):
    """r = 97447/100000 (the island's interval, near 1), an atlas datum left unresolved, its run
    repeating no attracting word (no trapping ellipse: the scan looks for the island only): with
    the datum's Scan, a run of 1200 collisions after one of 300 computes the ball states 0..1200
    once (not 0..300 again), and its class and why are those of a run of 1200 from the datum."""
    made = _counted(monkeypatch)
    r, (th, ph) = Fraction(97447, 100000), (0.19634954084936207, 1.3962634015954636)
    fresh = ident.classify(r, th, ph, 1200)
    assert fresh.cls == ident.UNRESOLVED and made == list(range(1201))
    assert "not proved inside the island within 1200 collisions" in fresh.why
    made.clear()
    scan = ident.Scan()
    ident.classify(r, th, ph, 300, scan=scan)
    longer = ident.classify(r, th, ph, 1200, scan=scan)
    assert made == list(range(1201))
    assert longer.to_json() == fresh.to_json() and longer.notes == fresh.notes


def test_a_scan_gone_on_proves_the_class_at_the_same_collision(monkeypatch):
    """r = 1/2, the tool's first datum enters the trapping ellipse of abacbabcbcabcb at collision
    180: a scan to 100 then, with the same Scan and ellipse, to 400 proves it at 180 having
    computed the states 0..180 once, as a scan from the datum does; without the ellipse (another
    key) the Scan starts again from the datum."""
    r, q = Fraction(1, 2), flint.fmpq(1, 2)
    th, ph = float(grid(8)[0][0]), float(grid(8)[1][0])
    rotation = ident.classify(r, th, ph, 4000).rotation
    U = ident.trap_of(rotation, q)
    made = _counted(monkeypatch)
    x = ident.Identified("1/2", th, ph, 400, 0)
    assert ident._scan(x, q, th, ph, U, rotation, 400) == (ident.ATTRACTING, 180) and made == list(range(181))
    made.clear()
    scan = ident.Scan()
    short = ident._scan(x, q, th, ph, U, rotation, 100, scan)
    assert short[0] is None and "within 100 collisions" in short[1]
    assert ident._scan(x, q, th, ph, U, rotation, 400, scan) == (ident.ATTRACTING, 180) and made == list(range(181))
    made.clear()
    assert ident._scan(x, q, th, ph, None, None, 50, scan)[0] is None and made == list(range(51))


def test_beyond_verify_max_the_second_route_takes_the_scans_state(monkeypatch):
    """With VERIFY_MAX = 100, the claim at collision 180 of r = 1/2 (the test above) is checked on
    the state the scan has (the first route's): no ball state computed again, the same answer as
    verify computing it from the datum (ball_states to 180)."""
    r, q = Fraction(1, 2), flint.fmpq(1, 2)
    th, ph = float(grid(8)[0][0]), float(grid(8)[1][0])
    rotation = ident.classify(r, th, ph, 4000).rotation
    U = ident.trap_of(rotation, q)
    monkeypatch.setattr(ident, "VERIFY_MAX", 100)
    made = _counted(monkeypatch)
    x = ident.Identified("1/2", th, ph, 400, 0)
    assert ident._scan(x, q, th, ph, U, rotation, 400) == (ident.ATTRACTING, 180) and made == list(range(181))
    made.clear()
    assert ident.verify(r, th, ph, ident.ATTRACTING, 180, rotation) is None and made[-1:] == [180]
    assert ident.verify(r, th, ph, ident.ATTRACTING, 179, rotation) is not None


def test_a_scan_stopped_at_the_precision_cap_is_not_run_again(monkeypatch):
    """With a precision cap of 1 digit the balls stop undecided after a few collisions: the
    longer run with the same Scan computes no state again and says the same (where a run
    from the datum would stop at the same collision)."""
    made = _counted(monkeypatch)
    monkeypatch.setattr(ident.engines, "BALL_CAP_DPS", 1)
    r, (th, ph) = Fraction(97447, 100000), (0.19634954084936207, 1.3962634015954636)
    fresh = ident.classify(r, th, ph, 1200)
    assert "stopped undecided at collision" in fresh.why and 0 < len(made) < 1200
    made.clear()
    scan = ident.Scan()
    short = ident.classify(r, th, ph, 600, scan=scan)
    first = len(made)
    longer = ident.classify(r, th, ph, 1200, scan=scan)
    assert len(made) == first and longer.to_json() == fresh.to_json()
    assert short.why.split("; ")[-1] == fresh.why.split("; ")[-1]


def _states_at(r, datum, collisions, contact):
    return [n for k, j, n, bits in ident.engines.ball_states(r, *datum, collisions) if j == INDEX[contact]]


def test_the_sieves_skip_only_states_the_proofs_refuse(monkeypatch):
    """At r = 3/10 the second datum of the grid is in the island, the first is caught by the trapping
    ellipse U of abacbabcbcabcb.  Over every state of both at b (and of the first at c_0 for U) up to
    collision 5000, the float64 sieves never skip a state the proof accepts (``island.inside``,
    ``U.ball_sign`` = +1), and skip most of the others; with the margin's sign turned they skip
    accepted states (the check can fail)."""
    r = flint.fmpq(3, 10)
    theta0, phi0 = grid(2)
    floats = (float(r), float(island.c_max(r)))
    first, second = (float(theta0[0]), float(phi0[0])), (float(theta0[1]), float(phi0[1]))
    states = _states_at(r, second, 5000, "b") + _states_at(r, first, 5000, "b")
    inside = [island.inside(n, r) for n in states]
    skipped = [ident.surely_outside_island(n, *floats) for n in states]
    assert any(inside) and not any(a and b for a, b in zip(inside, skipped))
    assert sum(skipped) >= 0.9 * (len(states) - sum(inside)) > 0
    x = ident.classify(Fraction(3, 10), *first, 5000)
    U = ident.trap_of(x.rotation, r)
    at_c0 = _states_at(r, first, 5000, x.rotation[-1])
    caught = [U.ball_sign(n) == 1 for n in at_c0]
    skipped = [U.surely_outside(n) for n in at_c0]
    assert any(caught) and not any(a and b for a, b in zip(caught, skipped))
    assert sum(skipped) >= 0.5 * (len(at_c0) - sum(caught)) > 0
    monkeypatch.setattr(ident.trapping, "SIEVE_MARGIN", -10.0)
    assert any(a and U.surely_outside(n) for a, n in zip(caught, at_c0))
    assert any(a and ident.surely_outside_island(n, *floats) for a, n in zip(inside, states))


def test_the_sieve_changes_no_class_nor_its_collision(monkeypatch):
    """identify's answers at r = 3/10 and near r = 1 (an orbit certified after leaving abcb) are those of
    the scan without the sieve, word for word."""
    first = [ident.classify(Fraction(r), th, ph, 40_000, word_max=1000).to_json()
             for r, th, ph in (("3/10", 0.5235987755982988, 0.6283185307179586),
                               ("3/10", 0.5235987755982988, 1.2566370614359172),
                               ("93271/100000", 0.6872233929727672, 2.55981623625835))]
    monkeypatch.setattr(ident, "SIEVE", False)
    again = [ident.classify(Fraction(r), th, ph, 40_000, word_max=1000).to_json()
             for r, th, ph in (("3/10", 0.5235987755982988, 0.6283185307179586),
                               ("3/10", 0.5235987755982988, 1.2566370614359172),
                               ("93271/100000", 0.6872233929727672, 2.55981623625835))]
    assert first == again and {x["class"] for x in first} == {ident.ISLAND, ident.ATTRACTING, ident.UNRESOLVED}


@given(st.text(alphabet="abc", min_size=1, max_size=60), st.integers(1, 60))
def test_settled_from_is_the_start_of_the_periodic_tail(word, p):
    """From settled_from(word, p) on, word[i] = word[i + p]; one letter earlier it is not (or it is 0)."""
    p = min(p, len(word))
    k = ident.settled_from(word, p)
    assert all(word[i] == word[i + p] for i in range(k, len(word) - p))
    assert k == 0 or word[k - 1] != word[k - 1 + p]
