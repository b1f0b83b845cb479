"""The island's figures: drawn without error, the census windows read, the island's
boundary separates the orbits that stay on their ellipse."""
from __future__ import annotations

import math

import numpy as np

from certify.run import island_figures as F


def test_census_windows_are_read_from_the_committed_census(tmp_path):
    windows = F.census_windows()
    assert windows and all(lo < hi for _w, lo, hi in windows)
    assert F.census_windows(tmp_path / "none.json") == []


def test_the_figure_is_written(tmp_path):
    path = F.island_figure(tmp_path / "island.png", None, 6)
    assert path.read_bytes()[:4] == b"\x89PNG"


def test_b_section_points_of_an_orbit_in_the_island_stay_inside():
    """A float orbit that starts inside the island stays inside (an observation, floats)."""
    pts = F.b_section_points(0.3, collisions=300, count=8)
    inside = [np.all(F.island_share(th, ph, 0.3) > 0) for th, ph in pts if len(th)]
    assert any(inside)
    assert 0 < F.island_share(np.array([math.pi / 4]), np.array([math.pi / 2]), 0.3)[0]


def test_the_resonances_drawn_are_the_floats_of_their_20_digits():
    """rotation_data refines each resonance's interval before float(): the floats are those of
    the unrefined resonances (float() rounds their 20 digits), and each lies in its interval."""
    from certify.patterns import island_theorem as it
    it.resonances_of_q.cache_clear()
    plain = [float(s.r) for s in it.resonances(8)]
    it.resonances_of_q.cache_clear()
    marks, _ = F.rotation_data(8, windows=[])
    assert [x for _label, x, _rho in marks] == plain and len(plain) >= 5
    for s, (_label, x, _rho) in zip(it.resonances(8), marks):
        assert s.r.hi - s.r.lo <= F.FLOAT_WIDTH and abs(x - float(s.r.lo)) <= 2 * math.ulp(x)
    it.resonances_of_q.cache_clear()
