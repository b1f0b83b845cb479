"""The thresholds r_max(n) (certify/numerics/thresholds.py): the scan's screened signs are
mpmath's signs, and the screen leaves the points near the root to mpmath."""
from __future__ import annotations

import mpmath
import pytest

from certify.numerics import thresholds as th


def grid(n: int) -> list:
    """upper_threshold's scan points (at the current precision)."""
    rc = 7 - 4 * mpmath.sqrt(3)
    lo, hi = (0.12, 0.32) if n > 6 else (0.05, 0.8)
    return [rc + mpmath.mpf(lo + (hi - lo) * k / 40) / n ** 2 for k in range(41)]


@pytest.mark.parametrize("n, dps", [(2, 20), (6, 20), (11, 20), (9, None)])
def test_the_screened_signs_are_mpmaths_on_the_whole_scan(n, dps):
    """Every sign the screen gives on the 41 points of the scan is the sign of mpmath's q_2
    (at n = 11 and 20 digits mpmath's q_2 is itself off in its 8th digit); the screen
    decides all but a few points, those next to the root."""
    with mpmath.workdps(dps or th.digits_for(n)):
        decided = 0
        for x in grid(n):
            s = th.screened_sign(n, x)
            if s is not None:
                decided += 1
                assert s == int(mpmath.sign(th.q2_of_dominant(n, x)))
        assert decided >= 39


def test_the_screen_leaves_the_root_to_mpmath():
    """At the threshold itself (q_2 ≈ 0 to the working precision) the screen does not decide,
    and the scan's first cell of a sign change is the cell mpmath's signs give."""
    with mpmath.workdps(20):
        root = th.upper_threshold(6, 20)
        assert th.screened_sign(6, root) is None
        xs = grid(6)
        signs = [int(mpmath.sign(th.q2_of_dominant(6, x))) for x in xs]
        first = next(k for k in range(40) if signs[k] * signs[k + 1] < 0)
        assert xs[first] < root < xs[first + 1]
        assert [th.scan_sign(6, x) for x in xs[:first + 2]] == signs[:first + 2]
