"""Observed rotation numbers of the loops of unresolved orbits (certify/numerics/curves.py):
the estimate, run on orbits that the island theorem proves quasi-periodic, gives the island's
certified rotation number; a loop hopping among q clusters reads p/q."""
from fractions import Fraction

import flint
import numpy as np
import pytest

from certify.numerics import curves, grid
from certify.patterns.island_theorem import rotation_number
from certify.run import identify


@pytest.mark.parametrize("r", ["3/10", "3/5"])
def test_the_estimate_gives_the_islands_certified_rotation_number(r):
    q = Fraction(r)
    fq = flint.fmpq(q.numerator, q.denominator)
    th, ph = grid(8)
    island = [(t, p) for t, p in zip(th.tolist(), ph.tolist())
              if identify.classify(q, t, p, 3000).cls == identify.ISLAND]
    assert island, "no island orbit among the tool's 8"
    rho = float(rotation_number(fq, 12))
    for t, p in island[:2]:
        est = curves.rotation_estimate(curves.b_states(fq, t, p, 6000), 1)
        assert est["returns"] == 1 and abs(float(est["rotation"]) - rho) < 1e-5
        assert abs(float(est["radius_drift"]) - 1) < 0.01                  # an invariant curve: no drift


def test_clusters_visited_in_turn_read_p_over_q_and_a_flat_loop_none():
    turn = np.array([[np.cos(2 * np.pi * k / 3), np.sin(2 * np.pi * k / 3)] for k in range(3)])
    pts = np.array([turn[(2 * n) % 3] * (1 + 0.01 * np.sin(n)) for n in range(600)])   # 2/3 of a turn a step
    assert curves.rotation_estimate(pts, 1)["rotation"] == "0.666667"
    flat = np.array([[n, 2.0 * n] for n in range(100)], dtype=float)
    assert curves.rotation_estimate(flat, 1) is None and curves.rotation_estimate(pts[:30], 1) is None
