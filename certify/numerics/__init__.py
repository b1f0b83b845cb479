"""Layer 3 (beside :mod:`certify.patterns`): numerical iteration of the spherical
billiard reduction (Section 5 of the paper), from collision to collision, in float64
(numba), mpmath or certified balls.  It imports only :mod:`certify.dynamics`,
:mod:`certify.algebra` and the ground floor.

- :mod:`.rules`: the one definition of the map's step and of the break rules.
- :mod:`.kernel`: the float64 engine, a numba transcription of the rules.
- :mod:`.engines`: one orbit on any engine (float64, mp, ball).
- :mod:`.orbits`: :func:`iterate` over r and initial data, :class:`Orbits`.
- :mod:`.figures`: the data of Figures 5.1-5.8 and their observables (clusters, breaks).
- :mod:`.stress`: near-singular, long and random orbits against the ball engine.
"""
from . import figures, stress
from .engines import ENGINES, OrbitResult, run_orbit
from .orbits import Orbits, grid, iterate, paper_grid
from .rules import BREAKS, COMPLETED, CORNER, HORIZON, NONFINITE, SHORT_STEP, UNDECIDED

__all__ = ["figures", "stress", "iterate", "Orbits", "paper_grid", "grid", "BREAKS", "ENGINES", "OrbitResult", "run_orbit",
           "COMPLETED", "UNDECIDED", "SHORT_STEP", "CORNER", "NONFINITE", "HORIZON"]
