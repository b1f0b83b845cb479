"""The ball engine's fast paths against what they replace.

* ``engines._ball_classify`` answers as ``rules.classify`` with ball signs does, on balls
  of every kind (decided, containing 0, exact 0, infinite, nan; every contact).
* ``engines.ball_states`` gives, state by state, what the loop it replaced gave (one
  ``rules.classify`` and one precision context a collision: :func:`_reference_states`,
  kept here), the precision doubled or not, stopped at the cap or not; with
  ``every=False`` it yields that loop's last state only (``identify._state``'s route
  beyond VERIFY_MAX).
"""
import random

import flint
import pytest

from certify.algebra.balls import precision
from certify.numerics import engines, rules


def _reference_states(r, theta0, phi0, collisions, dps=None, start_bits=engines.BALL_START, stop=None):
    """ball_states before its fast paths (the transcription of the replaced loop)."""
    letter = rules.START
    cap = int((dps or engines.BALL_CAP_DPS) * engines.BITS_PER_DIGIT) + 1
    prec = min(start_bits, cap)
    with precision(prec):
        prod = engines._Product(r, engines._initial_ball(theta0, phi0, letter, None))
        n = prod.evaluate(prod.P, prod.base, prec)
    i, code, done = rules.INDEX[letter], 0, 0

    def more(P):
        nonlocal prec
        prec = min(2 * prec, cap)
        with precision(prec):
            prod.rebase(engines._initial_ball(theta0, phi0, letter, None), prec)
            return prod.evaluate(P, prod.base, prec)

    yield 0, i, n, prec
    while done < collisions:
        with precision(prec):
            code, j = rules.classify(i, n, (0, 0, 0), rules.ball_sign, flint.arb.is_finite)
            if code in (rules.UNDECIDED, rules.SHORT_STEP) and prec < cap:
                n = more(prod.P)
                continue
            if code:
                break
            P = prod.times(j)
            m = prod.value(P)
            t = (j + 1) % 3
            while not (m[t] > 0 or m[t] < 0) and prec < cap:
                m = more(P)
            if m[t] < 0:
                P, m = -P, tuple(-z for z in m)
        prod.push(P, m)
        n = m
        i, done = j, done + 1
        yield done, j, n, prec
    if stop is not None:
        stop.update(code=code, bits=prec)


def _key(state):
    k, j, n, bits = state
    return k, j, bits, tuple((z.mid().str(radius=False, more=True), z.rad().str(more=True)) for z in n)


CASES = [  # r, theta0, phi0, collisions, dps, start_bits
    (flint.fmpq(9, 10), 1.0471975511965976, 0.6283185307179586, 1500, None, 64),   # the island at 9/10
    (flint.fmpq(43, 250), 0.5235987755982988, 2.5132741228718345, 700, None, 64),
    (flint.fmpq(3, 10), 0.7, 1.1, 500, None, 8),        # the precision doubled along the orbit
    (flint.fmpq(1, 3), 0.4, 2.0, 800, 20, 4),
    (flint.fmpq(9, 10), 0.7, 1.1, 600, 30, 2),
    (flint.fmpq(1, 3), 0.4, 2.0, 800, 1, 2),            # the cap (4 bits) stops it
    (flint.fmpq(1, 10), 0.0, 0.3, 30, None, 64),        # a vertex: stopped at the datum, at the cap
    (flint.fmpq(1, 2), 0.7, 1.1, 0, None, 64),          # no collision asked
]


@pytest.mark.parametrize("r,theta0,phi0,collisions,dps,start_bits", CASES)
def test_ball_states_are_the_replaced_loops_states(r, theta0, phi0, collisions, dps, start_bits):
    old, new, last = {}, {}, {}
    want = [_key(s) for s in _reference_states(r, theta0, phi0, collisions, dps, start_bits, old)]
    got = [_key(s) for s in engines.ball_states(r, theta0, phi0, collisions, dps, start_bits=start_bits, stop=new)]
    only = [_key(s) for s in engines.ball_states(r, theta0, phi0, collisions, dps, start_bits=start_bits, stop=last,
                                                 every=False)]
    assert got == want
    assert only == want[-1:]
    assert old == new == last


def test_the_cases_double_the_precision_and_stop():
    """The cases above exercise what they are there for: a doubling, a stop at the cap."""
    bits = {s[3] for s in engines.ball_states(*CASES[2][:4], start_bits=8)}
    assert len(bits) > 1
    stop = {}
    for _ in engines.ball_states(*CASES[5][:4], dps=1, start_bits=2, stop=stop):
        pass
    assert stop["code"] != rules.COMPLETED


def _balls():
    rng = random.Random(26)
    kinds = [lambda: flint.arb(rng.uniform(0.1, 2)), lambda: flint.arb(-rng.uniform(0.1, 2)),
             lambda: flint.arb(rng.uniform(-0.1, 0.1), 0.5), lambda: flint.arb(0),
             lambda: flint.arb(rng.uniform(0.1, 2), 1e-30), lambda: flint.arb("inf"), lambda: flint.arb("-inf"),
             lambda: flint.arb("nan"), lambda: flint.arb(1, "inf")]
    for _ in range(3000):
        yield rng.randrange(3), tuple(rng.choice(kinds)() for _ in range(3))


def test_ball_classify_is_classify_with_ball_signs():
    seen = set()
    with precision(64):
        for i, n in _balls():
            want = rules.classify(i, n, (0, 0, 0), rules.ball_sign, flint.arb.is_finite)
            assert engines._ball_classify(i, n) == want, (i, n)
            seen.add(want[0])
    assert seen >= {rules.COMPLETED, rules.UNDECIDED, rules.SHORT_STEP, rules.CORNER, rules.NONFINITE}
