"""The ball states' proved leaps along a repelling block (certify.numerics.leaps): the state after
a leap is the state a scan of every collision reaches, a leap ends before the orbit leaves the
block (after the first spiral too, where the focus's slow turning proves the leap), and no leap is
taken along an attracting block or a block the orbit does not follow."""
import math
from fractions import Fraction

import flint
import pytest
from flint import fmpq
from hypothesis import given
from hypothesis import strategies as st

from certify.algebra.balls import precision
from certify.numerics import engines, leaps, rules
from certify.run import identify as ident

R = fmpq(93271, 100000)            # abcb repels with multipliers of modulus 1 + 5.6e-5
DATUM = (0.6872233929727672, 2.55981623625835)   # an orbit of reports/atlas.json at R that winds out along abcb


def _mats(r):
    return [flint.fmpz_mat([[int(z) for z in row] for row in K]) for K in rules.integer_rows(r)]


def _direction(n):
    norm = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt()
    return [z / norm for z in n]


def _last(collisions, leap, r=R, datum=DATUM):
    *_, last = engines.ball_states(r, *datum, collisions, every=False, leap=leap)
    return last


@pytest.fixture(scope="module")
def plain():
    """Every state of the orbit at R up to collision 150 000, no leap: (letters, last state)."""
    letters, last = [], None
    for k, j, n, bits in engines.ball_states(R, *DATUM, 150_000):
        letters.append("abc"[j])
        last = (k, j, n, bits)
    return "".join(letters), last


def test_the_state_after_a_leap_is_the_state_of_every_collision(plain):
    """At collision 150 000 the leaping scan's normal and the plain scan's are one plane (their
    unit directions overlap, the leap's ball no wider than 10⁻⁹), the leap of 33 989 periods of abcb included."""
    holder = {}
    k, j, n, _ = _last(150_000, holder)
    k0, j0, n0, _ = plain[1]
    assert holder["leaps"] and holder["leaps"][0][1:3] == (33989, 4)
    assert (k, j) == (k0, j0) == (150_000, j0)
    for a, b in zip(_direction(n), _direction(n0)):
        assert a.overlaps(b) and a.rad() < 1e-9


def test_a_leap_ends_before_the_orbit_leaves_the_block(plain):
    """The plain scan's letters repeat abcb from collision 1 to about 138 000, then leave it; the
    leap proved ends LEAP_MARGIN letters and more before that."""
    letters = plain[0]
    start, periods, length, _ = _leap_of(R, DATUM)
    block = letters[start - length + 1:start + 1]
    exit_ = start
    while letters[exit_ + 1] == block[(exit_ + 1 - start - 1) % length]:
        exit_ += 1
    assert start + periods * length + leaps.LEAP_MARGIN <= exit_ < 150_000


def _leap_of(r, datum):
    holder = {}
    _last(engines.LEAP_EVERY + 1, holder, r, datum)
    holder["until"] = 10 ** 9
    _last(200_000, holder, r, datum)
    return holder["leaps"][0]


def test_a_leap_forced_past_its_proof_lands_elsewhere(plain):
    """The comparison above can fail: twice the proved number of periods from the same state gives a
    normal that is not the plain scan's at the same collision (the orbit left abcb in between)."""
    states = {k: (j, n, bits) for k, j, n, bits in engines.ball_states(R, *DATUM, 2048)}
    j, n, bits = states[2048]
    proof = leaps.leap_along(_mats(R), j, n, "abcb", 10 ** 9, bits)
    assert proof is not None and proof.J == 33989
    forced = leaps.Leap(proof.N, 2 * proof.J + 7, proof.sign, 4, proof.rate)
    k = 2048 + 4 * forced.J
    m = forced.apply(n, bits)
    *_, (k1, j1, n1, _) = engines.ball_states(R, *DATUM, k, every=False)
    assert k1 == k and not all(a.overlaps(b) for a, b in zip(_direction(m), _direction(n1)))


def test_no_leap_along_a_block_the_orbit_does_not_follow():
    states = {k: (j, n, bits) for k, j, n, bits in engines.ball_states(R, *DATUM, 2048)}
    j, n, bits = states[2048]
    assert "abc"[j] == "b"
    assert leaps.leap_along(_mats(R), j, n, "cbab", 10 ** 9, bits) is None       # the phase of the other b
    assert leaps.leap_along(_mats(R), j, n, "abcb", 10, bits) is None            # fewer than LEAP_MIN periods
    assert leaps.leap_along(_mats(R), j, n, "abcb", 10 ** 9, bits) is not None


def test_no_leap_along_an_attracting_block_or_in_the_island():
    """(ab)^2(cb)^2 attracts at r = 7187/50000, and the island's orbits rotate (|λ_i| all equal): their
    scans repeat a block over the window, and no leap is proved."""
    for r, datum in ((fmpq(7187, 50000), (0.5235987755982988, 0.6283185307179586)),
                     (fmpq(50109, 100000), (0.5235987755982988, 1.2566370614359172))):
        holder = {}
        _last(20_000, holder, r, datum)
        assert not holder.get("leaps")


def test_identify_certifies_from_the_collision_of_a_scan_of_every_state(monkeypatch):
    """At R the orbit leaves abcb and is proved to follow a 14-letter attractor from collision 184 711,
    with and without the leap (no attempt: LEAP_EVERY beyond the run)."""
    x = ident.classify(Fraction(93271, 100000), *DATUM, 640_000, word_max=1000)
    assert x.cls == ident.ATTRACTING and x.certified_from == 184_711 and len(x.word) == 14
    assert x.leaps and "leapt over 33989 periods of 4 letters" in x.why
    monkeypatch.setattr(engines, "LEAP_EVERY", 10 ** 12)
    y = ident.classify(Fraction(93271, 100000), *DATUM, 640_000, word_max=1000)
    assert (y.cls, y.certified_from, y.word) == (x.cls, x.certified_from, x.word) and not y.leaps


def test_the_margin_covers_every_block_identify_decides():
    """A skipped state is in no trapping ellipse of a word identify decides (module docstring of leaps)."""
    assert ident.MAX_ANALYSED + 1 <= leaps.LEAP_MARGIN


def test_a_block_that_does_not_repel_is_refused_once_for_all():
    """At r = 3/10 the orbit is attracted by abacbabcbcabcb with a complex in-plane pair: the one real
    eigenvalue of its period matrix dominates, nothing repels, and leap_along refuses the block and
    records it (a second call returns at once).  Along (ab)^2(cb)^2 at r = 7187/50000 (three real
    eigenvalues) the least one repels, so the block is not refused: the state is near the attracting
    eigenvector, and no leap is proved from it."""
    for r, refuse in ((fmpq(3, 10), True), (fmpq(7187, 50000), False)):
        states = list(engines.ball_states(r, 0.5235987755982988, 0.6283185307179586, 4096))
        block = leaps.period_of("".join("abc"[j] for _, j, _, _ in states[1:]))
        k, j, n, bits = states[-1]
        assert block is not None and len(block) == (14 if refuse else 8)
        refused: set = set()
        assert leaps.leap_along(_mats(r), j, n, block, 10 ** 9, bits, refused) is None
        assert refused == ({block} if refuse else set())


def test_a_turning_leap_where_the_orbit_returns_to_the_block(plain):
    """After the first spiral the orbit returns to abcb for runs of a few thousand letters, far from its
    periodic orbit: no form's |c_a| exceeds the others' sum, so the bound of ``_periods`` proves nothing
    at collision 144 149.  abcb's focus turns by nearly 2π/3 a period (m = 3, |δ| ≈ 0.004), and the
    turning criterion proves 558 periods: the leap ends LEAP_MARGIN letters and a period before the run
    (142 766 to 147 410 of the plain scan's letters) does, and the state at 150 000 is the plain scan's
    (the first test)."""
    letters = plain[0]
    states = {k: (j, n, bits) for k, j, n, bits in engines.ball_states(R, *DATUM, 144_149) if k == 144_149}
    j, n, bits = states[144_149]
    block = letters[144_149 - 3:144_149 + 1]
    assert block == "abcb"
    jump = leaps.leap_along(_mats(R), j, n, block, 10 ** 9, bits)
    assert jump is not None and jump.J == 558
    end = 144_149 + 4 * jump.J
    run_end = end
    while letters[run_end] == letters[run_end - 4]:
        run_end += 1
    assert end + leaps.LEAP_MARGIN + 4 <= run_end - 1 < 150_000
    with precision(256):
        C = leaps._follows(_mats(R), j, n, block)
        E, Rm = flint.acb_mat(C[-1]).eig(right=True)
        a = next(i for i in range(3) if leaps._pair(E, i) is not None)
        assert leaps._periods(C[:-1], E, Rm, Rm.inv(), a, n, 10 ** 9)[0] < leaps.LEAP_MIN
        m, delta = leaps._drift((E[leaps._pair(E, a)] / E[a]).arg())
        assert m == 3 and abs(delta) < 1e-2
    holder = {}
    _last(150_000, holder)
    assert [x[:3] for x in holder["leaps"]] == [(2048, 33989, 4), (144_149, 558, 4)]


@given(st.floats(-20, 20), st.floats(0, 7), st.integers(0, 64))
def test_least_cos_is_below_cos_on_the_arc(start, length, k):
    """_least_cos bounds cos from below at every point of its arc (k/64 of the way along it)."""
    with precision(64):
        lo, hi = flint.arb(start), flint.arb(start) + flint.arb(length)
        bound = leaps._least_cos(lo, hi)
    assert bound.lower() <= math.cos(start + length * k / 64) + 1e-12
    if length < 0.5 and all(abs(math.cos(start + length * i / 64)) > 1e-3 for i in range(65)) \
            and not any(start <= (2 * i + 1) * math.pi <= start + length for i in range(-5, 5)):
        assert float(bound.mid()) == pytest.approx(min(math.cos(start), math.cos(start + length)), abs=1e-9)
