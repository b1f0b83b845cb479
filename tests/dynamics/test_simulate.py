"""certify.dynamics.simulate: the four-particle dynamics, exact (fmpq) and in balls (arb)."""
import doctest

import flint
import pytest
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from certify.algebra.balls import precision
from certify.dynamics import simulate as sim
from certify.dynamics.model import collision_matrix

Q = flint.fmpq
rationals = st.fractions(min_value=-5, max_value=5, max_denominator=50).map(lambda f: Q(f.numerator, f.denominator))
positive = st.fractions(min_value=0, max_value=5, max_denominator=50).map(lambda f: Q(f.numerator, f.denominator))
restitution = st.fractions(min_value=0, max_value=1, max_denominator=40).filter(lambda f: 0 < f < 1).map(
    lambda f: Q(f.numerator, f.denominator))


def test_doctest():
    assert doctest.testmod(sim).failed == 0


@given(st.sampled_from("abc"), restitution, st.tuples(rationals, rationals, rationals))
def test_collide_is_the_collision_matrix(letter, r0, q):
    """The numerics of A, B, C agree exactly with the engine's matrices (l. 209-232)."""
    K = collision_matrix(letter, sp.Rational(int(r0.p), int(r0.q)))
    want = K * sp.Matrix([sp.Rational(int(z.p), int(z.q)) for z in q])
    got = sim.collide(letter, q, r0)
    assert [sp.Rational(int(z.p), int(z.q)) for z in got] == list(want)


@given(st.sampled_from("abc"), restitution, rationals)
def test_collision_separates_the_pair(letter, r0, qi):
    """M3: an approaching pair (q_i < 0) separates (q_i > 0) after its collision."""
    assume(qi < 0)
    q = [Q(1), Q(1), Q(1)]
    q[sim.INDEX[letter]] = qi
    assert sim.collide(letter, q, r0)[sim.INDEX[letter]] > 0


def test_next_collision_exact():
    p, q = sim.exact([1, 0, 2]), sim.exact([-1, "1/2", -1])
    assert sim.next_collision(p, q) == ("a", Q(1))
    assert sim.next_collision(sim.exact([1, 1, 1]), sim.exact([1, 2, 3])) is None


small = st.integers(-3, 3).map(Q) | st.fractions(min_value=-3, max_value=3, max_denominator=4).map(
    lambda f: Q(f.numerator, f.denominator))


@settings(max_examples=300)
@given(st.tuples(small.map(abs), small.map(abs), small.map(abs)), st.tuples(small, small, small))
def test_exact_first_collisions_is_the_generic_one(p, q):
    """The fmpq path (times compared by cross-multiplied integers, one division) gives
    the letters and time of collision_times + first_collisions, ties included (small
    entries make ties and non-approaching pairs frequent), and the same signs and order
    as python-flint's own comparisons."""
    times = sim.collision_times(p, q)
    want = sim.first_collisions(times) if times else None
    assert sim.first_collisions_exact(p, q) == want
    for z in p + q:
        assert sim.sign(z) == (z > 0) - (z < 0)
    for s, t in zip(p + q, q + p):
        assert sim.less(s, t) == (s < t)


@settings(max_examples=200)
@given(st.tuples(small.map(abs), small.map(abs), small.map(abs)), st.tuples(small, small, small), restitution)
def test_inlined_exact_run_is_the_generic_one(p, q, r0):
    """follow on fmpq data takes the inlined loop (_follow_exact); with ``until`` it steps
    through step() and next_collision: the same events, states and stop (ties, contacts and
    multiple collisions are frequent with small entries)."""
    fast = sim.follow(p, q, r0, 30)
    slow = sim.follow(p, q, r0, 30, until=lambda run: False)
    assert (fast.events, fast.states, fast.stop, fast.reason) == (slow.events, slow.states, slow.stop, slow.reason)


def positive_multiple(V, v) -> bool:
    """V = k v for some k > 0 (or both zero), exactly."""
    if all(z == 0 for z in v):
        return all(z == 0 for z in V)
    return all(a * w == b * z for a, z in zip(V, v) for b, w in zip(V, v)) and \
        sum(a * z for a, z in zip(V, v)) > 0


@settings(max_examples=200)
@given(st.tuples(small.map(abs), small.map(abs), small.map(abs)), st.tuples(small, small, small), restitution,
       st.tuples(positive, positive).filter(lambda s: s[0] > 0 and s[1] > 0))
def test_run_on_rays_is_the_exact_run(p, q, r0, scale):
    """follow_rays, on integer directions of p and q, has the events, stop and reason of
    the exact run, and at every collision positive multiples of its p and q (ties, contacts
    and multiple collisions are frequent with small entries; the data scaled by positive
    factors give the same rays)."""
    exact = sim.follow(p, q, r0, 30)
    for a, b in ((p, q), (tuple(scale[0] * z for z in p), tuple(scale[1] * z for z in q))):
        rays = sim.follow_rays(a, b, r0, 30)
        assert (rays.events, rays.stop, rays.reason, rays.word) == (exact.events, exact.stop, exact.reason, exact.word)
        assert len(rays.rays) == len(exact.states)
        for (P, Q_), s in zip(rays.rays, exact.states):
            assert positive_multiple(P, s.p) and positive_multiple(Q_, s.q)
    if exact.states[-1].p != (0, 0, 0):
        assert rays.rays[-1][0][0].gcd(rays.rays[-1][0][1]).gcd(rays.rays[-1][0][2]) == 1   # P primitive


def test_simultaneous_a_and_c_exact():
    """a and c at exactly the same time: one event "ac" (A and C commute, l. 240)."""
    p, q = sim.exact([1, 1, 2]), sim.exact([-1, 1, -2])
    assert sim.next_collision(p, q) == ("ac", Q(1))
    letters, t, p1, q1 = sim.step(p, q, Q(1, 2))
    assert letters == "ac" and p1[0] == 0 and p1[2] == 0
    run = sim.follow(p, q, Q(1, 2), 3)
    assert run.events[0] == "ac" and run.word.startswith("[ac]")


def test_b_tied_with_a_is_a_multiple_collision():
    """Gaps a and b (1 each) both close at speed 1: particles 1, 2, 3 meet at t = 1."""
    p, q = sim.exact([1, 1, 5]), sim.exact([-1, -1, 1])
    with pytest.raises(sim.MultipleCollision, match="triple collision of particles 1, 2, 3") as exc:
        sim.next_collision(p, q)
    assert exc.value.particles == (1, 2, 3) and exc.value.t == 1
    run = sim.follow(p, q, Q(1, 2), 2)
    assert run.stop == "multiple" and run.reason == "triple collision of particles 1, 2, 3"


def test_collision_next_to_a_closed_gap_is_a_multiple_collision():
    """Particles 3, 4 in contact (p3 = 0, q3 = 0); b closes at t = 2: 2, 3, 4 meet.
    With q3 = 1 > 0 instead, 3 and 4 have separated by then: a binary b."""
    with pytest.raises(sim.MultipleCollision, match="triple collision of particles 2, 3, 4"):
        sim.next_collision(sim.exact([3, 2, 0]), sim.exact([1, -1, 0]))
    assert sim.next_collision(sim.exact([3, 2, 0]), sim.exact([1, -1, 1])) == ("b", Q(2))


def test_balls_undecided_when_times_overlap():
    """With balls a tie cannot be proven either way: Undecided, and run() stops."""
    p = sim.balls(sim.exact([1, 1, 2]))
    q = sim.balls(sim.exact([-1, 1, -2]))
    with pytest.raises(sim.Undecided):
        sim.next_collision(p, q)
    assert sim.follow(p, q, flint.arb(Q(1, 2)), 3).stop == "undecided"


def test_balls_undecided_sign():
    with pytest.raises(sim.Undecided):
        sim.sign(flint.arb(0, 1e-10))
    assert sim.sign(flint.arb(0)) == 0 and sim.sign(flint.arb(-1)) == -1


def test_run_certified_raises_the_precision():
    """Two collision times 2^-200 apart: decided only once the precision exceeds that."""
    eps = Q(1, 2 ** 200)

    def datum(prec):
        return (sim.balls(sim.exact([1, 1, 1 + eps])), sim.balls(sim.exact([-1, 1, -1])), flint.arb(Q(1, 3)))
    run, prec = sim.run_certified(datum, 2, prec=64)
    assert prec > 200 and run.events[0] == "a"


@settings(max_examples=40, deadline=None)
@given(st.tuples(positive, positive, positive), st.tuples(rationals, rationals, rationals), restitution)
def test_exact_run_keeps_gaps_nonnegative(p, q, r0):
    """Particles never cross (M3): every gap stays >= 0, the closed gap is exactly 0."""
    run = sim.follow(p, q, r0, 25)
    assert len(run.states) == len(run.events) + 1 and run.stop in ("n", "free", "multiple")
    if run.stop == "free":                   # it ends because no pair approaches any more
        assert all(z >= 0 for z in run.states[-1].q)
    for ev, s in zip(run.events, run.states[1:]):
        assert all(z >= 0 for z in s.p)
        assert all(s.p[sim.INDEX[L]] == 0 for L in ev)
        assert all(s.q[sim.INDEX[L]] > 0 for L in ev)


@settings(max_examples=25, deadline=None)
@given(st.tuples(positive, positive, positive), st.tuples(rationals, rationals, rationals), restitution)
def test_balls_agree_with_exact(p, q, r0):
    """The ball run is a certified prefix of the exact run, with enclosing states."""
    exact_run = sim.follow(p, q, r0, 15)
    ball_run = sim.follow(sim.balls(p, 256), sim.balls(q, 256), flint.arb(r0), 15, prec=256)
    n = len(ball_run.events)
    assert ball_run.events == exact_run.events[:n]
    if ball_run.stop == "n" or ball_run.stop == exact_run.stop:
        assert n == len(exact_run.events)
    with precision(1024):             # the exact values as (nearly) exact balls
        for se, sb in zip(exact_run.states[:n + 1], ball_run.states):
            assert all(b.contains(flint.arb(e)) for e, b in zip(se.p + se.q, sb.p + sb.q))


def test_scaling_keeps_the_word():
    """M4 on the simulator: scaling p or q by a positive factor keeps the collisions."""
    p, q, r0 = sim.exact([1, "1/3", 2]), sim.exact([-1, "1/2", "-3/4"]), Q(1, 4)
    w = sim.follow(p, q, r0, 12).word
    assert sim.follow(tuple(3 * z for z in p), q, r0, 12).word == w
    assert sim.follow(p, tuple(Q(2, 7) * z for z in q), r0, 12).word == w


def test_precision_context_restores():
    old = flint.ctx.prec
    with precision(300):
        assert flint.ctx.prec == 300
    assert flint.ctx.prec == old
