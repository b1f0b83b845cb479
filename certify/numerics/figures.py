"""The data of Figures 5.1-5.8 (Section 5, l. 1053-1210) and what can be read off them.

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
from functools import lru_cache
import time
from dataclasses import dataclass, field

import numpy as np

GAP = 1e-3            # rad: two kept angles further apart than this are in different clusters
POINT = 1e-6          # rad: a cluster narrower than this is one accumulation point
PIXEL = math.pi / 1000  # rad: a cluster narrower than this is one point to the eye (1000 px for [0, π])
FEW = 100             # N5: at most this many clusters, each within a pixel: "finitely many points"
MAX_PIECES = 50       # more clusters than this: the orbit spreads over intervals ("apparent chaos")
BINS = 1000           # bins of [0, π] for the coverage
PIECE_GAP = 0.03      # rad: the coarse resolution at which an orbit's points form a few intervals (N7)
MAX_INTERVALS = 20    # at most this many intervals at PIECE_GAP: "a finite union of intervals"

# --- thresholds (CLAIMS L1, L3, L4), as floats for drawing and for choosing r -----------------

R_CRIT = 7 - 4 * math.sqrt(3)                              # three-particle collapse (L1)
N_LINES = (2, 3, 4, 5, 6)                                   # the thresholds drawn, as in L4


@lru_cache(maxsize=None)
def r_max(n: int) -> float:
    """The upper threshold of (ab)^n(cb)^n as a float, computed (:func:`upper_threshold`,
    20 digits), not typed in: for n = 2..6 it is the printed radical of L4 (a test)."""
    return float(upper_threshold(n, 20))


P_EXIST = (17, -138, 831, -3148, 831, -138, 17)             # l. 1101


def r_exist() -> float:
    """The root of P (l. 1101) in [0, 1], ≈ 0.19166 (L3): the last red line of 5.2, 5.3b, 5.5."""
    roots = np.roots(P_EXIST)
    return float(min(z.real for z in roots if abs(z.imag) < 1e-12 and 0 < z.real < 1))


def red_lines() -> dict[str, float]:
    """The vertical red lines: the CDKK thresholds (L4) and r_exist (L3)."""
    lines = {f"(ab)^{n}(cb)^{n}": r_max(n) for n in N_LINES}
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

# The number the compiled paper prints for each figure: figures are numbered through the paper
# (Figures 1-5 are in Sections 3 and 4), a subfigure is a letter of the figure whose caption
# follows it.  Derived from the LaTeX counters; tests/test_numbering.py re-derives it.
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

    def restrict(self, spec: Spec) -> "FigureData":
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
        orbits = numerics.iterate(rs, theta0, phi0, **kwargs)
        _MEMO[key] = (np.asarray(orbits.r, float), np.asarray(orbits.phi, float), np.asarray(orbits.breaks),
                      time.perf_counter() - t, np.asarray(orbits.certified))
    rr, phi, breaks, seconds, certified = _MEMO[key]
    return FigureData(spec, resolution, rr, phi, breaks, lengths["collisions"], lengths["keep"], engine, seconds,
                      certified=certified)


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


def windows_of() -> dict[int, tuple[float, float]]:
    """The r-ranges in which N3 counts the points of (ab)^n(cb)^n: from the next upper
    threshold to this one (L4), the two lower ends of L5 where they are printed."""
    lower = {2: 0.12754, 3: 0.09452}
    return {n: (lower.get(n, r_max(n + 1)), r_max(n)) for n in (2, 3, 4, 5)}


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
        "certified": None if data.certified is None or not data.certified.size else {
            "fraction": round(data.certified_fraction(), 6),
            "horizon": [int(data.certified.min()), int(np.median(data.certified)), int(data.certified.max())]},
    }


# --- N4: the windows of (ab)^n(cb)^n for large n ---------------------------------------------

def word_matrix_mp(word: str, r):
    """M_w = K_{c_n} ... K_{c_1} at an mpmath r (the printed A, B, C: ``model.collide``)."""
    import mpmath
    from certify.dynamics import collide
    M = mpmath.eye(3)
    for letter in word:
        cols = [collide(letter, tuple(M[i, j] for i in range(3)), r) for j in range(3)]
        M = mpmath.matrix([[cols[j][i] for j in range(3)] for i in range(3)])
    return M


def q2_of_dominant(n: int, r) -> float:
    """u = q_2(0)/(−q_1(0)) of the dominant eigenvector of M_w, w = (ab)^n(cb)^n, at r
    (mpmath, at the current precision); CDKK's upper threshold is where it vanishes (L6)."""
    import mpmath
    E, V = mpmath.eig(word_matrix_mp("ab" * n + "cb" * n, r))
    k = max(range(3), key=lambda i: abs(E[i]))
    return mpmath.re(V[1, k] / (-V[0, k]))


def digits_for(n: int) -> int:
    """Decimal digits enough for (ab)^n(cb)^n: 40 + 1.5 n (the dominant eigenvector has a
    component of relative size about 10^-1.13n, N4)."""
    return 40 + (3 * n) // 2


def upper_threshold(n: int, dps: int | None = None):
    """The upper threshold r_max(n) of (ab)^n(cb)^n, numerically (mpmath, ``dps`` digits):
    the root of q_2(0) = 0 (dominant eigenvector, CLAIMS L6) in ]R_CRIT + 0.12/n², R_CRIT + 0.32/n²[
    (r_max(n) − R_CRIT ≈ 0.2/n², found by a scan of 40 cells and the Illinois method).
    For n = 2..6 it gives the five thresholds printed in L4.  ``dps``: default
    :func:`digits_for` (the eigenvector's smallest component is about 10^-1.13n).  Returns
    an mpmath number."""
    import mpmath
    with mpmath.workdps(dps or digits_for(n)):
        rc = 7 - 4 * mpmath.sqrt(3)
        f = lambda x: q2_of_dominant(n, x)   # noqa: E731
        lo_c, hi_c = (0.12, 0.32) if n > 6 else (0.05, 0.8)
        xs = [rc + mpmath.mpf(lo_c + (hi_c - lo_c) * k / 40) / n ** 2 for k in range(41)]
        vals = [f(x) for x in xs]
        for a, b, fa, fb in zip(xs, xs[1:], vals, vals[1:]):
            if fa * fb < 0:
                return mpmath.findroot(f, (a, b), solver="illinois")
    raise ArithmeticError(f"no root of q_2(0) found for n = {n}")


def is_rotation(tail: str, period: str) -> bool:
    """``tail`` is a stretch of the periodic word period·period·... (any phase)."""
    if not tail or not period:
        return False
    ext = period * (len(tail) // len(period) + 2)
    return any(ext[s:s + len(tail)] == tail for s in range(len(period)))


def n4_window(n: int, engine: str = "mp", dps: int | None = None, fractions=(0.05, 0.2), orbits: int = 2,
              collisions: int | None = None, thresholds: tuple | None = None) -> dict:
    """Look for the stability window of (ab)^n(cb)^n just below its upper threshold:
    at r = r_max(n) − f (r_max(n) − r_max(n+1)) for each f of ``fractions``, run the first
    ``orbits`` orbits of the paper's grid on ``engine`` and count the accumulation points of
    their kept φ (gap 1e-8, point 1e-10 for mp and ball; the float defaults for float64);
    check the last 8n letters of the first orbit against (ab)^n(cb)^n."""
    from certify import numerics
    t0 = time.perf_counter()
    dps = dps or digits_for(n)
    hi, lo = thresholds or (upper_threshold(n), upper_threshold(n + 1))
    theta0, phi0 = numerics.paper_grid()
    collisions = collisions or max(10_000, 400 * n)
    keep = max(500, 6 * n)
    gap, point = (GAP, POINT) if engine == "float64" else (1e-8, 1e-10)
    rows = []
    for f in fractions:
        r = float(hi - f * (hi - lo))
        res = [numerics.run_orbit(engine, r, float(theta0[m]), float(phi0[m]), collisions, keep, dps,
                                  **({"word": True} if m == 0 else {})) for m in range(orbits)]
        codes = [int(x.code) for x in res]
        phis = np.concatenate([x.phi for x in res if x.code == 0]) if any(c == 0 for c in codes) else np.array([])
        w = omega(phis, gap, point)
        tail = res[0].word[-8 * n:] if res[0].code == 0 else ""
        rows.append({"f": f, "r": r, "breaks": codes, "kind": w.kind, "points": w.clusters,
                     "word": is_rotation(tail, "ab" * n + "cb" * n)})
    found = any(x["kind"] == "points" and x["points"] == 2 * n and not any(x["breaks"]) and x["word"] for x in rows)
    return {"n": n, "r_max": float(hi), "r_max_next": float(lo), "engine": engine,
            "dps": dps if engine != "float64" else None, "collisions": collisions, "keep": keep,
            "orbits": orbits, "rows": rows, "found": found, "seconds": round(time.perf_counter() - t0, 2)}


def n4_one(n: int):
    """(n, the mp row, the float64 row) of :func:`n4_search` (top level: picklable)."""
    th = (upper_threshold(n), upper_threshold(n + 1))
    return n, n4_window(n, "mp", thresholds=th), n4_window(n, "float64", thresholds=th)


N4_DEFAULT = (6, 8, 10, 12, 13, 15, 20, 30, 40, 50, 60, 80, 100)


def n4_search(nmax: int, ns=None, progress=None, executor=None) -> dict:
    """:func:`n4_window` on mp for each n of ``ns`` up to ``nmax`` (default: N4_DEFAULT and
    nmax), and on float64 at the same r for comparison.  ``executor``: run the n in parallel."""
    ns = sorted({n for n in (ns or N4_DEFAULT) if n <= nmax} | {nmax})
    t0 = time.perf_counter()
    out = {}

    jobs = (executor.map(n4_one, ns) if executor is not None else map(n4_one, ns))
    for k, (n, mp_row, f_row) in enumerate(jobs, 1):
        out[n] = {"mp": mp_row, "float64": f_row, "min_component": min_component(n, mp_row["rows"][0]["r"])}
        if progress:
            progress(k, len(ns), f"n = {n}")
    reached = [n for n in ns if out[n]["mp"]["found"]]
    float_reached = [n for n in ns if out[n]["float64"]["found"]]
    return {"ns": ns, "windows": {str(n): v for n, v in out.items()},
            "largest_n_mp": max(reached) if reached else None,
            "largest_n_float64": max(float_reached) if float_reached else None,
            "seconds": round(time.perf_counter() - t0, 1)}


# --- what the certificates N2-N7 read off the runs ---------------------------------------------

def probe(rs, collisions: int = PAPER["collisions"], keep: int = PAPER["keep"], orbits: str = "grid",
          engine: str = "float64") -> FigureData:
    """A run at chosen r values (not a figure): the paper's orbits and lengths by default."""
    spec = Spec("probe", "", float(np.min(rs)), float(np.max(rs)), max(len(rs), 2), "", orbits=orbits)
    return compute("5.1", "paper", engine, r=np.sort(np.asarray(rs, float)), collisions=collisions,
                   keep=keep).restrict(spec) if orbits == "grid" else _probe_orbits(spec, rs, collisions, keep, engine)


def _probe_orbits(spec, rs, collisions, keep, engine):
    from certify import numerics
    theta0, phi0 = initial_data(spec.orbits)
    o = numerics.iterate(np.sort(np.asarray(rs, float)), theta0, phi0, collisions=collisions, keep=keep, engine=engine)
    return FigureData(spec, "probe", np.asarray(o.r), np.asarray(o.phi), np.asarray(o.breaks), collisions, keep, engine,
                      certified=np.asarray(o.certified))


def fraction(data: FigureData, lo: float, hi: float, test) -> tuple[float, int]:
    """(the fraction of the r values of [lo, hi] whose union ω-summary passes ``test``, how many r)."""
    idx = data.where(lo, hi)
    if not len(idx):
        return 0.0, 0
    kinds = [omega(data.phi[k][data.breaks[k] == 0]) for k in idx]
    return float(np.mean([bool(test(w)) for w in kinds])), int(len(idx))


def n3_window_probes(fractions=(0.05, 0.15, 0.3, 0.45)) -> list[float]:
    """r values inside each window of N3 (n = 2..5): r_max(n) − f (r_max(n) − lower end)."""
    out = []
    for n, (lo, hi) in windows_of().items():
        out += [hi - f * (hi - lo) for f in fractions]
    return out


def n3_stats(*datas: FigureData) -> dict:
    """For each window of N3, the counts of accumulation points over the r values of the runs."""
    out = {}
    for n, (lo, hi) in windows_of().items():
        counts: dict = {}
        for d in datas:
            for c, k in window_counts(d, lo, hi).items():
                counts[c] = counts.get(c, 0) + k
        best, shown, total = dominant_count(counts)
        out[str(n)] = {"window": [lo, hi], "count": best, "shown_by": shown, "of": total,
                       "counts": {("none" if c is None else str(c)): k for c, k in sorted(
                           counts.items(), key=lambda item: -1 if item[0] is None else item[0])}}
    return out


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


def phi_at_b(p, q) -> float:
    """The φ the engines keep for the state (p, q) right after a b-collision: that of the
    normal p ∧ q, oriented as the engines orient it (``rules.phi_of``)."""
    from certify.dynamics import reduction
    from . import rules
    n = reduction.cross(p, q)
    if n[2] < 0:
        n = tuple(-z for z in n)
    return rules.phi_of(1, n)


def min_component(n: int, r, dps: int | None = None) -> float:
    """min |e_i| / max |e_i| for the dominant eigenvector e of M_w, w = (ab)^n(cb)^n, at r (mpmath)."""
    import mpmath
    with mpmath.workdps(dps or digits_for(n)):
        E, V = mpmath.eig(word_matrix_mp("ab" * n + "cb" * n, mpmath.mpf(r)))
        k = max(range(3), key=lambda i: abs(E[i]))
        v = [abs(V[i, k]) for i in range(3)]
        return float(min(v) / max(v))


# --- committed findings --------------------------------------------------------------------

def findings_path(name: str):
    """Where `certify figures` writes its findings (``numerics-paper.json``, ``numerics-n4.json``):
    the reports/ folder of the source checkout."""
    from pathlib import Path
    return Path(__file__).resolve().parents[2] / "reports" / name


def load_findings(name: str) -> dict | None:
    """The committed findings ``name``, or None when they are absent or unreadable."""
    import json
    try:
        return json.loads(findings_path(name).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def findings(datas: dict) -> dict:
    """What the certificates quote from the runs ``datas`` ({figure id: FigureData}, the
    paper's resolution): a summary of every figure, and the numbers of N3, N5, N6, N7."""
    out = {fig: summary(d) for fig, d in datas.items()}
    if "5.2" in datas:
        out["n3"] = n3_stats(datas["5.2"])
    if "5.4" in datas:
        d = datas["5.4"]
        frac, of = fraction(d, 0.172, 0.176, lambda w: w.few_points)
        counts = sorted({w.clusters for k, w in enumerate(per_r(d)) if 0.172 <= d.r[k] <= 0.176 and w.few_points})
        out["n5"] = {"finite": frac, "of": of, "counts": counts}
    if "5.5" in datas and "5.6" in datas:
        scan = stripe_scan(datas["5.5"])
        widest = widest_orbit(datas["5.6"])
        k = int(np.argmin(widest))
        out["n6"] = {"stripes": [round(r, 6) for r, _, _ in scan[:4]], "coverages": [round(c, 3) for _, c, _ in scan[:4]],
                     "special_r": float(datas["5.6"].r[k]), "special_width": float(widest[k])}
    if "5.6" in datas and "5.1" in datas:
        def intervals(d, ks):
            got = [omega(d.phi[k, m], gap=PIECE_GAP).clusters for k in ks for m in range(d.phi.shape[1])
                   if d.breaks[k, m] == 0]
            return {str(c): got.count(c) for c in sorted(set(got))}
        s6 = datas["5.6"]
        out["n7"] = {"stripe_intervals": intervals(s6, range(len(s6.r))),
                     "chaos_intervals": intervals(datas["5.1"], datas["5.1"].where(0.2, 0.9))}
    return out
