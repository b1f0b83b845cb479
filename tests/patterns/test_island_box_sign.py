"""island_theorem.box_sign with the work of a column pair shared (Sides.at_pair: the balls of u's
ends, 2u·u and (1+r)u; Q at the corners from them, operation for operation), against the
box_sign it replaced (kept here): the same sign on every box island_fraction visits, and
the same fractions."""
import flint
import pytest

from certify.dynamics import island
from certify.patterns import island_theorem as it


def _reference_box_sign(box, r, sides):
    s0, s1, t0, t1 = box
    if t0 == 0 or t1 == 1:
        return it.box_sign_balls(box, r)
    (ua, _, w0_lo, w0_hi), (_, ub, w1_lo, w1_hi) = sides.at_s(s0), sides.at_s(s1)
    w_hi = max(w0_hi, w1_hi)
    w_lo = sides.w_min if s0 <= flint.fmpq(1, 2) <= s1 else min(w0_lo, w1_lo)
    c_lo, c_hi = sides.at_t(t1)[0], sides.at_t(t0)[1]
    va, vb = 2 * min(c_lo * w_lo, c_lo * w_hi), 2 * max(c_hi * w_lo, c_hi * w_hi)
    ua, ub, va, vb = (flint.arb(x) for x in (ua, ub, va, vb))
    R, c = sides.R, sides.c
    corners = [island.quadratic_form(x, y, R) for x in (ua, ub) for y in (va, vb)]
    if all(c - q > 0 for q in corners):
        return 1
    if ua <= 0 <= ub and va <= 0 <= vb:
        return 0
    edges = [it._edge_min(R, -(1 + R) * x, 2 * x * x, va, vb) for x in (ua, ub)] + \
            [it._edge_min(flint.arb(2), -(1 + R) * y, R * y * y, ua, ub) for y in (va, vb)]
    return -1 if all(e - c > 0 for e in edges) else 0


@pytest.mark.parametrize("r", ["1/5", "1/2", "23/25"])
def test_box_sign_is_the_replaced_box_sign_on_the_boxes_of_a_run(r):
    r = flint.fmpq(*map(int, r.split("/")))
    seen = set()
    with it.precision(64):
        sides, fresh = it.Sides(r), it.Sides(r)
        boxes = [(flint.fmpq(0), flint.fmpq(1), flint.fmpq(0), flint.fmpq(1))]
        for _level in range(7):
            nxt = []
            for box in boxes:
                s = it.box_sign(box, r, sides)
                assert s == _reference_box_sign(box, r, fresh), box
                seen.add(s)
                if s == 0:
                    nxt.extend(it._split(box))
            boxes = nxt
    assert seen == {-1, 0, 1}


def test_island_fraction_is_the_fraction_of_the_replaced_box_sign(monkeypatch):
    r = flint.fmpq(4, 5)
    got = it.island_fraction(r, depth=6)
    monkeypatch.setattr(it, "box_sign", _reference_box_sign)
    assert it.island_fraction(r, depth=6) == got
