"""certify.dynamics.island.inside: the one membership test of the island U_r = {Q < c_max}
(identify and the certified points of Section 5's figures).  A ball of states that straddles
the boundary ellipse is not inside, although its midpoint is: proved on balls built around
exact points of the ellipse, with an exact state of the ball on each side."""
import flint
import pytest

from certify.dynamics import island

RS = [flint.fmpq(3, 10), flint.fmpq(1, 2), flint.fmpq(9, 10)]
DIRECTIONS = [(1, 0), (0, 1), (1, 1), (-1, 2), (3, -1)]


def _scales_across(r, a, b):
    """Rationals lo < mid < hi with the states s·(a, b) inside U_r for s = lo and mid and
    outside for s = hi (decided exactly): the ray (a, b) crosses the ellipse between mid and hi."""
    s = (float(island.c_max(r) / island.quadratic_form(flint.fmpq(a), flint.fmpq(b), r))) ** 0.5
    lo, hi = (flint.fmpq(*(s * f).as_integer_ratio()) for f in (1 - 1e-3, 1 + 5e-4))
    mid = (lo + hi) / 2

    def inside_exactly(t):
        return island.quadratic_form(t * a, t * b, r) < island.c_max(r)
    assert inside_exactly(lo) and inside_exactly(mid) and not inside_exactly(hi)
    return lo, mid, hi


@pytest.mark.parametrize("r", RS, ids=str)
@pytest.mark.parametrize("a, b", DIRECTIONS)
def test_a_ball_across_the_boundary_is_not_inside(r, a, b):
    lo, mid, hi = _scales_across(r, a, b)
    scale = flint.arb(mid, hi - mid)                       # holds lo and hi
    across = island.normal(scale * a, scale * b)
    assert not island.inside(across, r)
    assert island.inside(tuple(z.mid() for z in across), r)      # its midpoint is inside
    assert island.inside(island.normal(lo * a, lo * b), r)         # exact states of the ball on both sides
    assert not island.inside(island.normal(hi * a, hi * b), r)
    small = flint.arb(lo / 2, lo / 100)                   # a ball well inside
    assert island.inside(island.normal(small * a, small * b), r)


def test_exact_states_and_states_not_at_b():
    r = flint.fmpq(3, 10)
    assert island.inside((-1, 0, 1), r)                      # the centre, the symmetric state [ac]b
    assert not island.inside((-3, 1, 1), r)                  # Q = 9/10 > c_max
    assert not island.inside((1, 0, 1), r)                   # n_z − n_x = 0: not a state inside the face b
    assert not island.inside((flint.arb(0, 1), flint.arb(0), flint.arb(1)), r)    # n_z − n_x not decided


def test_c_max_of_exact_r_asked_in_turn_is_each_r_own():
    """c_max keeps the last exact r's value: asked of r, r', r again (and of a ball between),
    each answer is 1 − (1−r)²/(4r) of the r asked."""
    for r in RS + RS[::-1] + [flint.fmpq(3, 10)]:
        assert island.c_max(r) == 1 - (1 - r) ** 2 / (4 * r)
        assert island.c_max(flint.arb(r)).contains(1 - (1 - r) ** 2 / (4 * r))
