"""certify.run.figure_points: the certified points of Section 5's figures.

The intervals are checked against a second route (the ball engine's own states along the
whole orbit, exact products), a point moved off the certified set is not counted, and a
continuation refuses a state outside the island or the trap."""
import flint
import numpy as np
import pytest

from certify.algebra.balls import precision
from certify.dynamics.model import INDEX
from certify.numerics import engines, figures, rules
from certify.run import figure_points as fp

RS = [0.25, 0.5]
COLLISIONS, KEEP = 3000, 60


@pytest.fixture(scope="module")
def run():
    data = figures.compute("5.1", "paper", r=RS, collisions=COLLISIONS, keep=KEEP)
    return data, fp.certify_figure(data)


def test_small_figure_fully_certified(run):
    data, found = run
    s = fp.summary(found)
    assert s["orbits"] == len(RS) * 8 and s["r_values"] == len(RS)
    assert s["all"]["points"] == int(np.isfinite(data.phi).sum()) > 0
    assert s["classes"]["island"] > 0 and s["classes"]["trapped"] > 0
    assert s["all"]["certified"] == s["all"]["points"], s["not_certified"]


def _ball_phi(q, theta0, phi0, ks):
    """The true φ after the collisions ks, by the ball engine all along (a second route)."""
    out, want = {}, set(ks)
    for k, j, n, bits in engines.ball_states(q, theta0, phi0, max(ks)):
        if k in want:
            assert j == INDEX["b"]
            with precision(bits):
                out[k] = fp._phi(n)
    return out


def _ball(lo, hi):
    """The ball [lo, hi]."""
    return flint.arb((lo + hi) / 2, (hi - lo) / 2)


def test_island_intervals_against_the_ball_engine():
    q = rules.exact_r(0.5)
    theta0, phi0 = (float(x[1]) for x in figures.initial_data("grid"))      # orbit 1: an island orbit
    n0 = next(iter(engines.ball_states(q, theta0, phi0, 0)))[2]
    steps = [1, 2, 17, 333]
    got = fp.island_intervals(q, n0, steps)
    assert not isinstance(got, str)
    true = _ball_phi(q, theta0, phi0, [3 * m for m in steps])
    for m, (lo, hi) in zip(steps, got):
        assert hi - lo < flint.fmpq(1, 10 ** 9)
        b = true[3 * m]
        assert b.overlaps(_ball(lo, hi))


def test_trap_intervals_against_the_ball_engine():
    q = rules.exact_r(0.25)
    th, ph = figures.initial_data("grid")
    x = fp.OrbitPoints(0.25, float(th[0]), float(ph[0]))
    intervals = fp._trapped(x, q, float(th[0]), float(ph[0]), COLLISIONS, KEEP)
    assert x.kind == fp.TRAPPED and intervals
    window = fp.trap_window(x.word, x.entry, COLLISIONS, KEEP)
    true = _ball_phi(q, float(th[0]), float(ph[0]), [k for k, _, _ in window])
    for k, b in true.items():
        assert any(b.overlaps(_ball(lo, hi))
                   for lo, hi in intervals), k


def test_a_point_moved_off_the_set_is_not_certified(run):
    data, found = run
    th, ph = figures.initial_data("grid")
    phi = data.phi[0, 1].copy()
    base = fp.certify_orbit(RS[0], float(th[1]), float(ph[1]), phi, COLLISIONS, KEEP)
    assert base.certified == base.points
    grid = np.linspace(0.0, np.pi, 20001)
    far = grid[np.min(np.abs(grid[:, None] - phi[None, :]), axis=1) > 3 * fp.PIXEL]
    assert far.size
    moved = phi.copy()
    moved[-1] = far[0]
    x = fp.certify_orbit(RS[0], float(th[1]), float(ph[1]), moved, COLLISIONS, KEEP)
    assert x.points == base.points and x.certified == base.certified - 1
    assert "farther than a pixel" in x.why


def test_matched_is_exact_about_the_pixel():
    px = fp.pixel()
    lo = flint.fmpq(1)
    tight = [(lo, lo + flint.fmpq(1, 10 ** 12))]
    assert fp.matched(np.array([1.0 + 0.99 * fp.PIXEL]), tight).all()
    assert not fp.matched(np.array([1.0 + 1.01 * fp.PIXEL, 1.0 - 1.01 * fp.PIXEL]), tight).any()
    wide = [(lo, lo + 3 * px)]                 # φ inside, but a point of I lies more than a pixel away
    assert not fp.matched(np.array([1.0 + 1.5 * fp.PIXEL]), wide).any()
    assert float(px) <= fp.PIXEL


def test_a_state_outside_is_refused():
    q = flint.fmpq(3, 10)
    outside = tuple(flint.arb(z) for z in (-3, 1, 1))          # u = −1/2, v = 1/2: Q = 9/10 > c_max
    assert "not proved inside the island" in fp.island_intervals(q, outside, [1])
    inside = tuple(flint.arb(z) for z in (-1, 0, 1))
    assert not isinstance(fp.island_intervals(q, inside, [1]), str)
    assert "no island" in fp.island_intervals(flint.fmpq(1, 10), inside, [1])    # r < 3 − 2√2

    r = rules.exact_r(0.25)
    th, ph = figures.initial_data("grid")
    x = fp.OrbitPoints(0.25, float(th[0]), float(ph[0]))
    fp._trapped(x, r, float(th[0]), float(ph[0]), COLLISIONS, KEEP)
    U = fp._trap(x.word, r)
    t = U.chart
    far = [U.centre[k] + 4 * U.outer * (1 if k == (t + 1) % 3 else 0) for k in range(3)]
    state = tuple(flint.arb(z) for z in far)
    assert U.ball_sign(state) == -1
    assert "not proved inside the trapping ellipse" in fp.trap_intervals(U, state, {len(x.word): {1}})
    from certify.algebra.balls import precision
    with precision(256):                  # the centre as tight balls, whatever precision an earlier test left
        centre = tuple(flint.arb(z) for z in U.centre)
    assert not isinstance(fp.trap_intervals(U, centre, {len(x.word): {1}}), str)


def test_a_window_reaching_back_before_the_entry():
    """The window's b-collisions up to the entry are the ball engine's, the entry's own included."""
    th, ph = figures.initial_data("grid")
    data = figures.compute("5.1", "paper", r=[0.5], collisions=600, keep=200)
    x = fp.certify_orbit(0.5, float(th[0]), float(ph[0]), data.phi[0, 0], 600, 200)
    assert x.kind == fp.TRAPPED and x.entry > 600 - 3 * 200
    window = fp.trap_window(x.word, x.entry, 600, 200)
    assert len(window) < 200                     # the rest comes from before the entry
    assert x.points == 200 and x.certified == x.points, x.why


def test_a_ball_across_the_boundary_is_refused():
    """A state whose ball straddles the boundary ellipse is refused, although its midpoint lies
    in the island: its points would not be certified (tests/dynamics/test_island.py builds such
    balls in general; here u = 0.54 ± 0.01 on v = 0 at r = 3/10, the ellipse at u ≈ 0.5439)."""
    from certify.dynamics import island
    q = flint.fmpq(3, 10)
    across = island.normal(flint.arb("0.54 +/- 0.01"), flint.arb(0))
    assert "not proved inside the island" in fp.island_intervals(q, across, [1, 2])
    got = fp.island_intervals(q, tuple(z.mid() for z in across), [1, 2])
    assert not isinstance(got, str) and len(got) == 2
