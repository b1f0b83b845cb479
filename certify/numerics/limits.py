"""What can be read off a cloud of kept angles φ (Section 5): clusters, the kind of ω-limit
set they suggest, coverage (floats, an observation, never a proof).

- :func:`clusters`: the sorted values cut where two consecutive ones are more than
  ``gap`` apart; each cluster is (lo, hi, count).
- :func:`omega`: the kind of the ω-limit set the kept points suggest: ``points`` (every
  cluster narrower than :data:`POINT`: the orbit converged to a periodic cycle, the
  count is its number of accumulation points), ``pieces`` (at most :data:`MAX_PIECES`
  clusters, some wider: a finite union of small intervals), ``spread`` (more).
- :func:`accumulation_points`: per r, the number of accumulation points of the union
  of the orbits (None when the union is not a finite set of points).
- :func:`coverage`: the fraction of [0, π] the points hit, in :data:`BINS` bins.
- per r and per orbit of a run (a :class:`~certify.numerics.figures.FigureData`):
  :func:`per_r`, :func:`per_orbit`, :func:`window_counts`, :func:`fraction`,
  :func:`stripe_scan`, :func:`widest_orbit`, :func:`orbit_widths`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from .figures import FigureData

GAP = 1e-3            # rad: two kept angles further apart than this are in different clusters
POINT = 1e-6          # rad: a cluster narrower than this is one accumulation point
PIXEL = math.pi / 1000  # rad: a cluster narrower than this is one point to the eye (1000 px for [0, π])
FEW = 100             # N5: at most this many clusters, each within a pixel: "finitely many points"
MAX_PIECES = 50       # more clusters than this: the orbit spreads over intervals ("apparent chaos")
BINS = 1000           # bins of [0, π] for the coverage
PIECE_GAP = 0.03      # rad: the coarse resolution at which an orbit's points form a few intervals (N7)
MAX_INTERVALS = 20    # at most this many intervals at PIECE_GAP: "a finite union of intervals"


def clusters(values, gap: float = GAP) -> list[tuple[float, float, int]]:
    """The finite values sorted and cut wherever two consecutive ones differ by more than
    ``gap``: [(lo, hi, count), ...] in increasing order."""
    v, starts, ends = _cuts(values, gap)
    return [(float(v[s]), float(v[e]), int(e - s + 1)) for s, e in zip(starts, ends)]


def _cuts(values, gap: float):
    """(the finite values sorted, the index of each cluster's first value, of its last)."""
    v = np.sort(np.asarray(values, float).ravel())
    v = v[np.isfinite(v)]
    if v.size == 0:
        return v, np.zeros(0, int), np.zeros(0, int)
    cut = np.flatnonzero(np.diff(v) > gap)
    return v, np.r_[0, cut + 1], np.r_[cut, v.size - 1]


@dataclass(frozen=True)
class Omega:
    """What the kept points of an orbit (or of several) suggest about its ω-limit set."""

    kind: str          # "points", "pieces", "spread" or "none" (no point kept)
    clusters: int
    width: float       # of the widest cluster
    coverage: float

    @property
    def discrete(self) -> bool:
        return self.kind == "points"

    @property
    def few_points(self) -> bool:
        """At most FEW clusters, each within one pixel: finitely many points to the eye (N5)."""
        return self.kind != "none" and self.clusters <= FEW and self.width < PIXEL

    @property
    def visually_discrete(self) -> bool:
        """At most MAX_PIECES clusters, each within one pixel of a 1000-px-high figure."""
        return self.kind != "none" and self.clusters <= MAX_PIECES and self.width < PIXEL


def coverage(values, bins: int = BINS) -> float:
    """The fraction of the bins of [0, π] that hold a value."""
    v = np.asarray(values, float).ravel()
    v = v[np.isfinite(v)]
    if v.size == 0:
        return 0.0
    k = np.clip((v / math.pi * bins).astype(int), 0, bins - 1)
    return float(np.unique(k).size / bins)


def omega(values, gap: float = GAP, point: float = POINT, max_pieces: int = MAX_PIECES) -> Omega:
    """The kind of ω-limit set the values suggest (module docstring)."""
    v, starts, ends = _cuts(values, gap)        # the clusters, as arrays (no list of them)
    if starts.size == 0:
        return Omega("none", 0, 0.0, 0.0)
    width = float(np.max(v[ends] - v[starts]))  # the same doubles as max(hi − lo) over clusters()
    count = int(starts.size)
    kind = "points" if width < point else "pieces" if count <= max_pieces else "spread"
    return Omega(kind, count, width, coverage(values))


def accumulation_points(data: FigureData, k: int, gap: float = GAP, point: float = POINT) -> int | None:
    """The number of accumulation points of the completed orbits at r[k] together (None
    when their union is not a finite set of points, or no orbit completed)."""
    ok = data.breaks[k] == 0
    if not ok.any():
        return None
    w = omega(data.phi[k][ok], gap, point)
    return w.clusters if w.discrete else None


def per_r(data: FigureData, gap: float = GAP, point: float = POINT) -> list[Omega]:
    """The ω-summary of the union of the completed orbits, for each r."""
    return [omega(data.phi[k][data.breaks[k] == 0], gap, point) for k in range(len(data.r))]


def per_orbit(data: FigureData, k: int, gap: float = GAP, point: float = POINT) -> list[Omega]:
    """The ω-summary of each orbit at r[k] (kind "none" for an orbit that broke before
    its first kept b-collision)."""
    return [omega(data.phi[k, m], gap, point) for m in range(data.phi.shape[1])]


def window_counts(data: FigureData, lo: float, hi: float) -> dict:
    """The accumulation-point counts over the r values of [lo, hi]: {count: how many r},
    with None for the r values whose orbits do not converge to finitely many points."""
    out: dict = {}
    for k in data.where(lo, hi):
        c = accumulation_points(data, k)
        out[c] = out.get(c, 0) + 1
    return out


def dominant_count(counts: dict) -> tuple[int | None, int, int]:
    """(the most frequent finite count, how many r show it, how many r in all)."""
    total = sum(counts.values())
    finite = {c: n for c, n in counts.items() if c is not None}
    if not finite:
        return None, 0, total
    best = max(finite, key=lambda c: (finite[c], -c))
    return best, finite[best], total


def fraction(data: FigureData, lo: float, hi: float, test) -> tuple[float, int]:
    """(the fraction of the r values of [lo, hi] whose union ω-summary passes ``test``, how many r)."""
    idx = data.where(lo, hi)
    if not len(idx):
        return 0.0, 0
    kinds = [omega(data.phi[k][data.breaks[k] == 0]) for k in idx]
    return float(np.mean([bool(test(w)) for w in kinds])), int(len(idx))


def stripe_scan(data: FigureData) -> list[tuple[float, float, str]]:
    """(r, coverage of the union, kind) at every r of ``data``, by increasing coverage."""
    rows = [(float(data.r[k]), coverage(data.phi[k][data.breaks[k] == 0]), omega(data.phi[k][data.breaks[k] == 0]).kind)
            for k in range(len(data.r))]
    return sorted(rows, key=lambda row: row[1])


def widest_orbit(data: FigureData) -> np.ndarray:
    """At each r, the width of the widest cluster over the orbits (inf for a broken orbit)."""
    out = np.full(len(data.r), np.inf)
    for k in range(len(data.r)):
        ws = [omega(data.phi[k, m]).width if data.breaks[k, m] == 0 else np.inf for m in range(data.phi.shape[1])]
        out[k] = max(ws)
    return out


def orbit_widths(data: FigureData, k: int) -> list[float]:
    return [omega(data.phi[k, m]).width for m in range(data.phi.shape[1]) if data.breaks[k, m] == 0]
