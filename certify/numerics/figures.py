"""The data of Figures 5.1-5.8 (Section 5, l. 1053-1210) and what can be read off them.

A figure of Section 5 is a cloud of points (r, φ_n): for each restitution coefficient r
of a regular grid, the angles φ of the last kept b-collisions of a few orbits of the
reduction map (:func:`certify.numerics.simulate`); an orbit that stops early (a break of
the engine, ``BREAKS``) is drawn as a red dot at (r, π/2), and the CDKK thresholds
(CLAIMS L4, L3) as red vertical lines.  :data:`SPECS` holds the paper's parameters of
every figure, as printed in its caption, and the cheap preview that ``certify all``
draws instead; :func:`compute` runs the engine on one of them.

Figure numbers.  The paper's figures are, in order: ``fig:Simul_1`` (5.1),
``fig:Simul_2`` (5.2), the two magnifications ``fig:Simul_2_zoom_1``/``_zoom_2`` (5.3a,
5.3b), ``fig:Simul_3`` (5.4), ``fig:Simul_2_zoom_3`` (5.5) and the three panels of the
thin stripe ``fig:Simul_4``, ``_5``, ``_6`` (5.6, 5.7, 5.8).

What is read off a cloud (floats, an observation, never a proof):

- :func:`clusters`: the sorted values cut where two consecutive ones are more than
  ``gap`` apart; each cluster is (lo, hi, count).
- :func:`omega`: the kind of the ω-limit set the kept points suggest: ``points`` (every
  cluster narrower than :data:`POINT`: the orbit converged to a periodic cycle, the
  count is its number of accumulation points), ``pieces`` (at most :data:`MAX_PIECES`
  clusters, some wider: a finite union of small intervals), ``spread`` (more).
- :func:`accumulation_points`: per r, the number of accumulation points of the union
  of the orbits (None when the union is not a finite set of points).
- :func:`coverage`: the fraction of [0, π] the points hit, in :data:`BINS` bins.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

GAP = 1e-3            # rad: two kept angles further apart than this are in different clusters
POINT = 1e-6          # rad: a cluster narrower than this is one accumulation point
PIXEL = math.pi / 1000  # rad: a cluster narrower than this is one point to the eye (1000 px for [0, π])
MAX_PIECES = 50       # more clusters than this: the orbit spreads over intervals ("apparent chaos")
BINS = 1000           # bins of [0, π] for the coverage

# --- thresholds (CLAIMS L1, L3, L4), as floats for drawing and for choosing r -----------------

R_CRIT = 7 - 4 * math.sqrt(3)                              # three-particle collapse (L1)
R_MAX = {                                                   # upper thresholds of (ab)^n(cb)^n (L4)
    2: 3 - 2 * math.sqrt(2),
    3: 5 - 2 * math.sqrt(6),
    4: 3 + 2 * math.sqrt(2) - 2 * math.sqrt(4 + 3 * math.sqrt(2)),
    5: 4 + math.sqrt(5) - 2 * math.sqrt(5 + 2 * math.sqrt(5)),
    6: 3 + 2 * math.sqrt(3) - 2 * math.sqrt(5 + 3 * math.sqrt(3)),
}
P_EXIST = (17, -138, 831, -3148, 831, -138, 17)             # l. 1101


def r_exist() -> float:
    """The root of P (l. 1101) in [0, 1], ≈ 0.19166 (L3): the last red line of 5.2, 5.3b, 5.5."""
    roots = np.roots(P_EXIST)
    return float(min(z.real for z in roots if abs(z.imag) < 1e-12 and 0 < z.real < 1))


def red_lines() -> dict[str, float]:
    """The vertical red lines: the CDKK thresholds (L4) and r_exist (L3)."""
    lines = {f"(ab)^{n}(cb)^{n}": v for n, v in R_MAX.items()}
    lines["r_exist"] = r_exist()
    return lines


# --- the figures ---------------------------------------------------------------------------

@dataclass(frozen=True)
class Spec:
    """One figure of Section 5: its r-grid and orbits as printed, and its preview.

    ``source``: a magnification draws the points of another figure's run (same Δr).
    ``orbits``: "grid" (the 8 orbits of ``paper_grid``) or "random:SEED" (one orbit
    from a random (θ0, φ0) drawn once with that seed, the same for every r)."""

    id: str
    label: str
    lo: float
    hi: float
    count: int                     # number of r values at the paper's resolution
    line: str                      # where the caption is printed
    orbits: str = "grid"
    source: str | None = None
    boxes: tuple = ()              # red rectangles (r_lo, r_hi) drawn on the figure
    preview: int = 40              # number of r values of the preview

    @property
    def step(self) -> float:
        return (self.hi - self.lo) / (self.count - 1)

    @property
    def name(self) -> str:
        return "fig" + self.id


SPECS = {s.id: s for s in (
    Spec("5.1", "fig:Simul_1", 0.072, 0.999, 3709, "l. 1076-1081", preview=120),
    Spec("5.2", "fig:Simul_2", 0.075, 0.192, 4681, "l. 1106-1111", preview=120),
    Spec("5.3a", "fig:Simul_2_zoom_1", 0.075, 0.105, 1201, "l. 1131-1137", source="5.2", preview=40),
    Spec("5.3b", "fig:Simul_2_zoom_2", 0.165, 0.192, 1081, "l. 1139-1143", source="5.2", preview=40),
    Spec("5.4", "fig:Simul_3", 0.171, 0.176, 5001, "l. 1154-1159", preview=40),
    Spec("5.5", "fig:Simul_2_zoom_3", 0.181, 0.192, 441, "l. 1160-1165", source="5.2",
         boxes=((0.1844, 0.1847), (0.1894, 0.1898)), preview=40),
    Spec("5.6", "fig:Simul_4", 0.1845, 0.1846, 1001, "l. 1179-1184", preview=21),
    Spec("5.7", "fig:Simul_5", 0.1845, 0.1846, 1001, "l. 1186-1191", orbits="random:5", preview=21),
    Spec("5.8", "fig:Simul_6", 0.1845, 0.1846, 1001, "l. 1193-1198", orbits="random:6", preview=21),
)}

PAPER = dict(collisions=10_000, keep=500)      # l. 1062-1063: 10^4 collisions, the last 500 b-collisions
PREVIEW = dict(collisions=2_000, keep=200)     # what `certify all` draws: seconds, not minutes
RESOLUTIONS = ("preview", "paper")


def r_values(spec: Spec, resolution: str) -> np.ndarray:
    """The r-grid of ``spec``: lo + kΔr, k = 0..count-1 at the paper's resolution; a
    regular sub-grid of ``preview`` values (ends included) for the preview."""
    n = spec.count if resolution == "paper" else min(spec.preview, spec.count)
    return np.linspace(spec.lo, spec.hi, n)


def initial_data(orbits: str):
    """(θ0, φ0) arrays of the orbits: the paper's grid, or one random datum."""
    from certify import numerics
    if orbits == "grid":
        theta0, phi0 = numerics.paper_grid()
        return np.asarray(theta0, float), np.asarray(phi0, float)
    kind, _, seed = orbits.partition(":")
    if kind != "random":
        raise ValueError(f"unknown orbits {orbits!r}")
    rng = np.random.default_rng(int(seed))
    return np.array([rng.uniform(0.05, math.pi / 2 - 0.05)]), np.array([rng.uniform(0.05, math.pi - 0.05)])


@dataclass
class FigureData:
    """The points of one figure: ``phi[k, m, :]`` the kept b-angles of orbit m at r[k]
    (NaN-padded at the front), ``breaks[k, m]`` its break code (0: completed)."""

    spec: Spec
    resolution: str
    r: np.ndarray
    phi: np.ndarray
    breaks: np.ndarray
    collisions: int
    keep: int
    engine: str
    seconds: float = 0.0
    extra: dict = field(default_factory=dict)

    def restrict(self, spec: Spec) -> "FigureData":
        """The magnification ``spec`` of this run: the r values inside [spec.lo, spec.hi]."""
        eps = 1e-12
        sel = (self.r >= spec.lo - eps) & (self.r <= spec.hi + eps)
        return FigureData(spec, self.resolution, self.r[sel], self.phi[sel], self.breaks[sel],
                          self.collisions, self.keep, self.engine, self.seconds)

    def where(self, lo: float, hi: float) -> np.ndarray:
        """The indices k with lo ≤ r[k] ≤ hi."""
        return np.flatnonzero((self.r >= lo - 1e-12) & (self.r <= hi + 1e-12))

    def break_r(self) -> np.ndarray:
        """One r per broken orbit (an r appears as often as it has breaks)."""
        return np.repeat(self.r, (self.breaks != 0).sum(axis=1))


_MEMO: dict = {}


def compute(fig: str, resolution: str = "preview", engine: str = "float64", executor=None, progress=None,
            r=None, collisions: int | None = None, keep: int | None = None, dps: int | None = None) -> FigureData:
    """Run the engine for figure ``fig`` ("5.1" .. "5.8") at ``resolution``; a magnification
    reuses its source's run (one run per command and resolution, memoised).  ``r``,
    ``collisions``, ``keep`` override the grid and lengths (tests, quick looks)."""
    from certify import numerics
    spec = SPECS[fig]
    if resolution not in RESOLUTIONS:
        raise ValueError(f"resolution must be one of {RESOLUTIONS}, got {resolution!r}")
    if spec.source is not None and r is None:
        return compute(spec.source, resolution, engine, executor, progress, None, collisions, keep, dps).restrict(spec)
    lengths = dict(PAPER if resolution == "paper" else PREVIEW)
    if collisions is not None:
        lengths["collisions"] = collisions
    if keep is not None:
        lengths["keep"] = keep
    rs = r_values(spec, resolution) if r is None else np.asarray(r, float)
    key = (spec.orbits, resolution, engine, dps, lengths["collisions"], lengths["keep"], rs.tobytes())
    if key not in _MEMO:
        theta0, phi0 = initial_data(spec.orbits)
        t = time.perf_counter()
        kwargs = dict(collisions=lengths["collisions"], keep=lengths["keep"], engine=engine)
        if dps is not None:
            kwargs["dps"] = dps
        if executor is not None:
            kwargs["executor"] = executor
        if progress is not None:
            kwargs["progress"] = progress
        orbits = numerics.simulate(rs, theta0, phi0, **kwargs)
        _MEMO[key] = (np.asarray(orbits.r, float), np.asarray(orbits.phi, float), np.asarray(orbits.breaks),
                      time.perf_counter() - t)
    rr, phi, breaks, seconds = _MEMO[key]
    return FigureData(spec, resolution, rr, phi, breaks, lengths["collisions"], lengths["keep"], engine, seconds)


def forget() -> None:
    """Drop the memoised runs."""
    _MEMO.clear()


# --- observables -------------------------------------------------------------------------

def clusters(values, gap: float = GAP) -> list[tuple[float, float, int]]:
    """The finite values sorted and cut wherever two consecutive ones differ by more than
    ``gap``: [(lo, hi, count), ...] in increasing order."""
    v = np.sort(np.asarray(values, float).ravel())
    v = v[np.isfinite(v)]
    if v.size == 0:
        return []
    cut = np.flatnonzero(np.diff(v) > gap)
    starts, ends = np.r_[0, cut + 1], np.r_[cut, v.size - 1]
    return [(float(v[s]), float(v[e]), int(e - s + 1)) for s, e in zip(starts, ends)]


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
    cl = clusters(values, gap)
    if not cl:
        return Omega("none", 0, 0.0, 0.0)
    width = max(hi - lo for lo, hi, _ in cl)
    kind = "points" if width < point else "pieces" if len(cl) <= max_pieces else "spread"
    return Omega(kind, len(cl), float(width), coverage(values))


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


def windows_of(spec_lo: float = R_CRIT) -> dict[int, tuple[float, float]]:
    """The r-ranges in which N3 counts the points of (ab)^n(cb)^n: from the next upper
    threshold to this one (L4), the two lower ends of L5 where they are printed."""
    lower = {2: 0.12754, 3: 0.09452}
    return {n: (lower.get(n, R_MAX.get(n + 1, spec_lo)), R_MAX[n]) for n in (2, 3, 4, 5)}


def summary(data: FigureData) -> dict:
    """Numbers that describe a figure's run (JSON-ready)."""
    kinds = per_r(data)
    breaks = data.break_r()
    return {
        "figure": data.spec.id, "resolution": data.resolution, "engine": data.engine,
        "r": [float(data.r[0]), float(data.r[-1]), int(len(data.r))] if len(data.r) else [],
        "orbits": int(data.phi.shape[1]), "collisions": data.collisions, "keep": data.keep,
        "seconds": round(data.seconds, 2),
        "breaks": {"count": int(breaks.size),
                   "r_min": float(breaks.min()) if breaks.size else None,
                   "r_max": float(breaks.max()) if breaks.size else None,
                   "below_0.08": int((breaks < 0.08).sum())},
        "kinds": {kind: sum(1 for w in kinds if w.kind == kind) for kind in ("points", "pieces", "spread", "none")},
    }
