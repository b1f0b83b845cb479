"""The figures of Section 5 (l. 1053-1210), 5.1-5.8: their parameters as printed and the runs behind them.

A figure of Section 5 is a cloud of points (r, φ_n): for each restitution coefficient r
of a regular grid, the angles φ of the last kept b-collisions of a few orbits of the
reduction map (:func:`certify.numerics.iterate`); an orbit that stops early (a break of
the engine, ``BREAKS``) is drawn as a red dot at (r, π/2), and the CDKK thresholds
(CLAIMS L4, L3) as red vertical lines.  :data:`SPECS` holds the paper's parameters of
every figure, as printed in its caption, and the cheap preview that ``certify all``
draws instead; :func:`compute` runs the engine on one of them.

Figure numbers.  The paper's figures are, in order: ``fig:Simul_1`` (5.1),
``fig:Simul_2`` (5.2), the two magnifications ``fig:Simul_2_zoom_1``/``_zoom_2`` (5.3a,
5.3b), ``fig:Simul_3`` (5.4), ``fig:Simul_2_zoom_3`` (5.5) and the three panels of the
thin stripe ``fig:Simul_4``, ``_5``, ``_6`` (5.6, 5.7, 5.8).

What is read off a cloud is in :mod:`certify.numerics.limits`; the thresholds drawn as red
lines in :mod:`certify.numerics.thresholds`; the experiments N3-N7 in
:mod:`certify.numerics.experiments`.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from .orbits import iterate, paper_grid


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

# The number the compiled paper prints for each figure: figures are numbered through the paper
# (Figures 1-5 are in Sections 3 and 4), a subfigure is a letter of the figure whose caption
# follows it.  Derived from the LaTeX counters; tests/proofs/test_numbering.py re-derives it.
PAPER_NUMBER = {"5.1": "6", "5.2": "7", "5.3a": "8a", "5.3b": "8b", "5.4": "9", "5.5": "10",
                "5.6": "11a", "5.7": "11b", "5.8": "11c"}


def cite(fig: str) -> str:
    """``Figure 6 (fig:Simul_1)``: the compiled number with the LaTeX label beside."""
    return f"Figure {PAPER_NUMBER[fig]} ({SPECS[fig].label})"


PAPER = dict(collisions=10_000, keep=500)      # l. 1062-1063: 10^4 collisions, the last 500 b-collisions
PREVIEW = dict(collisions=2_000, keep=200)     # what `certify all` draws: seconds, not minutes
RESOLUTIONS = ("preview", "paper")


def r_values(spec: Spec, resolution: str) -> np.ndarray:
    """The r-grid of ``spec``: lo + kΔr, k = 0..count-1 at the paper's resolution; a
    regular sub-grid of ``preview`` values (ends included) for the preview."""
    n = spec.count if resolution == "paper" else min(spec.preview, spec.count)
    return np.linspace(spec.lo, spec.hi, n)


def initial_data(orbits: str):
    """(θ0, φ0) arrays of the orbits: the tool's grid of 8 initial data (the paper does not print
    its own), or one random datum."""
    if orbits == "grid":
        theta0, phi0 = paper_grid()
        return np.asarray(theta0, float), np.asarray(phi0, float)
    kind, _, seed = orbits.partition(":")
    if kind != "random":
        raise ValueError(f"unknown orbits {orbits!r}")
    rng = np.random.default_rng(int(seed))
    return np.array([rng.uniform(0.05, math.pi / 2 - 0.05)]), np.array([rng.uniform(0.05, math.pi - 0.05)])


@dataclass
class FigureData:
    """The points of one figure: ``phi[k, m, :]`` the kept b-angles of orbit m at r[k]
    (NaN-padded at the front), ``breaks[k, m]`` its break code (0: completed),
    ``certified[k, m]`` its certified horizon (the collisions proven; the kept angles
    come after it when it is below collisions − kept: a shadowing orbit)."""

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
    certified: np.ndarray | None = None

    def certified_fraction(self) -> float | None:
        """The fraction of the collisions done that are certified (None when unknown)."""
        if self.certified is None or not self.certified.size:
            return None
        return float(self.certified.sum()) / max(1, int(self.collisions) * self.certified.size)

    def restrict(self, spec: Spec) -> FigureData:
        """The magnification ``spec`` of this run: the r values inside [spec.lo, spec.hi]."""
        eps = 1e-12
        sel = (self.r >= spec.lo - eps) & (self.r <= spec.hi + eps)
        return FigureData(spec, self.resolution, self.r[sel], self.phi[sel], self.breaks[sel],
                          self.collisions, self.keep, self.engine, self.seconds,
                          certified=None if self.certified is None else self.certified[sel])

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
        orbits = iterate(rs, theta0, phi0, **kwargs)
        _MEMO[key] = (np.asarray(orbits.r, float), np.asarray(orbits.phi, float), np.asarray(orbits.breaks),
                      time.perf_counter() - t, np.asarray(orbits.certified))
    rr, phi, breaks, seconds, certified = _MEMO[key]
    return FigureData(spec, resolution, rr, phi, breaks, lengths["collisions"], lengths["keep"], engine, seconds,
                      certified=certified)


def forget() -> None:
    """Drop the memoised runs."""
    _MEMO.clear()


def probe(rs, collisions: int = PAPER["collisions"], keep: int = PAPER["keep"], orbits: str = "grid",
          engine: str = "float64") -> FigureData:
    """A run at chosen r values (not a figure): the paper's orbits and lengths by default."""
    spec = Spec("probe", "", float(np.min(rs)), float(np.max(rs)), max(len(rs), 2), "", orbits=orbits)
    return compute("5.1", "paper", engine, r=np.sort(np.asarray(rs, float)), collisions=collisions,
                   keep=keep).restrict(spec) if orbits == "grid" else _probe_orbits(spec, rs, collisions, keep, engine)


def _probe_orbits(spec, rs, collisions, keep, engine):
    theta0, phi0 = initial_data(spec.orbits)
    o = iterate(np.sort(np.asarray(rs, float)), theta0, phi0, collisions=collisions, keep=keep, engine=engine)
    return FigureData(spec, "probe", np.asarray(o.r), np.asarray(o.phi), np.asarray(o.breaks), collisions, keep, engine,
                      certified=np.asarray(o.certified))
