"""reduction.ball_run (identify's second route) against the loop it replaced.

``_next_index_ball`` reads the next contact from the same ball products and comparisons
as :func:`next_letter` on a Plane (and stops where that raises); ball_run gives the same letters,
last contact and balls as :func:`_reference_run` (the replaced loop, kept here), on orbits
that run to the end and orbits that stop at an undecided sign (too few bits), at a
corner, or at an exact zero.
"""
import random

import flint
import pytest

from certify.algebra.balls import precision
from certify.dynamics import reduction as R
from certify.dynamics.simulate import Undecided
from certify.numerics import rules


def _reference_run(letter, n, r, count, prec):
    letters, rows = [], R.cofactors(r)
    with precision(prec):
        m = tuple(flint.arb(z) for z in n)
        L = letter
        try:
            for _ in range(count):
                L2 = R.next_letter(R.Plane(L, m))
                m2 = R.apply(rows[L2], m)
                top = max(abs(z).upper() for z in m2) * R.sign(m2[R.ORIENTATION[L2]])
                L, m = L2, tuple(z / top for z in m2)
                letters.append(L)
        except (Undecided, R.Corner):
            pass
    return "".join(letters), L, m


def _key(run):
    letters, L, m = run
    return letters, L, tuple((z.mid().str(radius=False, more=True), z.rad().str(more=True)) for z in m)


def _data():
    rng = random.Random(27)
    for r in (flint.fmpq(9, 10), flint.fmpq(43, 250), flint.fmpq(1, 5), flint.fmpq(3, 10), flint.fmpq(7, 10)):
        for prec in (8, 32, 128, 1024):
            theta0, phi0 = rng.uniform(0.05, 1.5), rng.uniform(0.05, 3.1)
            with precision(prec):
                n0 = rules.initial_normal(flint.arb(theta0), flint.arb(phi0), "b", flint.arb.cos, flint.arb.sin)
            yield r, n0, prec


@pytest.mark.parametrize("r,n0,prec", list(_data()))
def test_ball_run_is_the_replaced_loop(r, n0, prec):
    assert _key(R.ball_run("b", n0, r, 400, prec)) == _key(_reference_run("b", n0, r, 400, prec))


def test_the_runs_stop_early_and_run_through():
    """The data above hold runs that stop before 400 collisions and runs that do not."""
    stopped = [len(R.ball_run("b", n0, r, 400, prec)[0]) < 400 for r, n0, prec in _data()]
    assert any(stopped) and not all(stopped)


def _balls():
    rng = random.Random(26)
    kinds = [lambda: flint.arb(rng.uniform(0.1, 2)), lambda: flint.arb(-rng.uniform(0.1, 2)),
             lambda: flint.arb(rng.uniform(-0.1, 0.1), 0.5), lambda: flint.arb(0),
             lambda: flint.arb(rng.uniform(0.5, 2), 0.45), lambda: flint.arb(-rng.uniform(0.5, 2), 0.45)]
    for _ in range(4000):
        yield rng.choice("abc"), tuple(rng.choice(kinds)() for _ in range(3))


def test_next_index_ball_is_next_letter():
    """The same letter, or a stop (-1) exactly where next_letter raises."""
    seen = set()
    with precision(64):
        for letter, n in _balls():
            try:
                want = R.INDEX[R.next_letter(R.Plane(letter, n))]
            except (Undecided, R.Corner) as exc:
                want = -1
                seen.add(type(exc))
            assert R._next_index_ball(R.INDEX[letter], n) == want, (letter, n)
            seen.add(want >= 0)
    assert seen == {True, False, Undecided, R.Corner}
