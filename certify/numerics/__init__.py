"""Layer 3 (beside :mod:`certify.patterns`): numerical iteration of the spherical
billiard reduction (Section 5 of the paper), from collision to collision, in float64
(numba), mpmath or certified balls.  It imports only :mod:`certify.dynamics`,
:mod:`certify.algebra` and the ground floor, and reads or writes no file.

- :mod:`.rules`: the one definition of the map's step and of the break rules.
- :mod:`.kernel`: the float64 engine, a numba transcription of the rules.
- :mod:`.engines`: one orbit on any engine (float64, mp, ball).
- :mod:`.leaps`: the ball engine's proved leaps along a repelling periodic block; ``period_of``.
- :mod:`.orbits`: :func:`iterate` over r and initial data, :class:`Orbits`.
- :mod:`.figures`: the figures 5.1-5.8 as printed (:data:`SPECS`) and their runs.
- :mod:`.limits`: what a cloud of kept angles suggests (clusters, ω-limit kinds, coverage).
- :mod:`.thresholds`: the red lines (CDKK thresholds, r_exist) and r_max(n) for any n (mpmath).
- :mod:`.experiments`: N3-N7 read off the runs, the N4 search, the findings' numbers.
- :mod:`.stress`: near-singular, long and random orbits against the ball engine.
- :mod:`.trapping`: certified trapping ellipses of attracting periodic orbits of the reduction.
- :mod:`.horseshoe`: horseshoes of the b-to-b map proved by covering relations (``certify chaos``).
"""
from . import experiments, figures, horseshoe, limits, stress, thresholds
from .engines import ENGINES, OrbitResult, run_orbit
from .experiments import (
                          N4_DEFAULT,
                          findings,
                          is_rotation,
                          n3_stats,
                          n3_window_probes,
                          n4_search,
                          n4_window,
                          summary,
                          windows_of,
)
from .figures import PAPER, PAPER_NUMBER, PREVIEW, RESOLUTIONS, SPECS, FigureData, Spec, cite, compute, forget, probe
from .limits import (
                          BINS,
                          FEW,
                          GAP,
                          MAX_INTERVALS,
                          MAX_PIECES,
                          PIECE_GAP,
                          PIXEL,
                          POINT,
                          Omega,
                          accumulation_points,
                          clusters,
                          coverage,
                          dominant_count,
                          fraction,
                          omega,
                          orbit_widths,
                          per_orbit,
                          per_r,
                          stripe_scan,
                          widest_orbit,
                          window_counts,
)
from .orbits import Orbits, grid, iterate, load_float64, paper_grid
from .rules import BREAKS, COMPLETED, CORNER, HORIZON, NONFINITE, SHORT_STEP, UNDECIDED, phi_at_b
from .thresholds import N_LINES, R_CRIT, digits_for, min_component, r_exist, r_max, red_lines, upper_threshold

__all__ = [
    "experiments", "figures", "horseshoe", "limits", "stress", "thresholds",
    "ENGINES", "OrbitResult", "run_orbit",
    "N4_DEFAULT", "findings", "is_rotation", "n3_stats", "n3_window_probes", "n4_search", "n4_window", "summary",
    "windows_of",
    "PAPER", "PAPER_NUMBER", "PREVIEW", "RESOLUTIONS", "SPECS", "FigureData", "Spec", "cite", "compute", "forget",
    "probe",
    "BINS", "FEW", "GAP", "MAX_INTERVALS", "MAX_PIECES", "PIECE_GAP", "PIXEL", "POINT", "Omega", "accumulation_points",
    "clusters", "coverage", "dominant_count", "fraction", "omega", "orbit_widths", "per_orbit", "per_r", "stripe_scan",
    "widest_orbit", "window_counts",
    "Orbits", "grid", "iterate", "load_float64", "paper_grid",
    "BREAKS", "COMPLETED", "UNDECIDED", "SHORT_STEP", "CORNER", "NONFINITE", "HORIZON", "phi_at_b",
    "N_LINES", "R_CRIT", "digits_for", "min_component", "r_exist", "r_max", "red_lines", "upper_threshold",
]
