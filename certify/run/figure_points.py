"""Section 5's plotted points, certified where the dynamics allows.

A figure of Section 5 plots, for each r of its grid and each orbit, the φ of the last
``keep`` b-collisions among the first ``collisions`` collisions of the float64 run
(:func:`certify.numerics.compute`).  The float64 run is proved only up to its certified
horizon (31-176 collisions, :func:`certify.numerics.rules.carry_bound`); the plotted
points come after it, so the float run past its horizon is *not* the true orbit.  What is
certified here is a statement about the **true orbit** (the reduction at the double r, read
exactly, from the datum (θ0, φ0) read exactly), and whether each plotted point lies within
a pixel of it.

**The true window.**  The true orbit's last ``keep`` b-collisions with collision index
≤ ``collisions`` (the float run's own definition, applied to the true orbit).

**A certified point.**  The plotted point (r, φ) of orbit m is *certified* when a rational
interval I = [lo, hi] is proved to contain the true φ at some b-collision of the true window
and every point of I lies within one pixel of φ:  max(φ − lo, hi − φ) ≤ PIXEL = π/1000
(:data:`certify.numerics.limits.PIXEL`: 1000 pixels for [0, π]).  Then a true point of
the figure lies within a pixel of the plotted one.  The comparison is exact (φ, a double,
read as a rational; lo, hi rational bounds of arb balls; PIXEL a rational lower bound of
π/1000); floats only choose which interval to try.

**Where the intervals come from** (the orbit's class, as ``certify identify``):

* **island**: r in ]3−2√2, 1[ (r² − 6r + 1 < 0, exactly), the island theorem for the symbol
  r proved (:func:`certify.patterns.island_theorem.symbolic_theorem`), and the datum, a state
  at b, proved inside the island U_r = {Q < c_max} (arb, the whole ball: :func:`certify.dynamics.island.inside`).
  By the theorem every later b-to-b step is the linear map A(r) of the chart (u, v) (three
  collisions: b, then a and c in either order; a double collision [ac] on the tie v = 0 is
  counted as two, a and c commuting), so the state after m steps is, exactly,
  z_m = (sin(mθ) A z_0 − sin((m−1)θ) z_0)/sin θ (Cayley-Hamilton, det A = 1, cos θ = tr A/2):
  evaluated in arb for each m of the window, no wrapping along the orbit.  It stays on the
  ellipse Q = Q(z_0).  φ = atan2(√(2(u²+1)), v) at the normal (u − 1, v, u + 1).
* **trapped**: the float64 run (an observation) repeats a block; its rotation w ending at
  c_0 has a certified trapping ellipse U (:func:`certify.numerics.trapping.attempt`); the
  rigorous orbit (:func:`certify.numerics.engines.ball_states`, exact products, arb) is
  proved inside U at some collision k_0 at c_0 (:meth:`~certify.numerics.trapping.Trap.ball_sign`).
  By the trap's theorem the true orbit follows w for ever, and after i periods its state at
  c_0 is c + T u_i with |u_i| ≤ s_i, s_{i+1} = min(ρ, R(s_i)), R the trap's image bound
  (:func:`radii`: a Lohner-style scalar bound that follows the contraction).  The ball
  engine follows the orbit on while s_i > :data:`SMALL` (to k_1 = k_0 + E·L); from k_1 the
  state after the j-th letter of period i is a positive multiple of P_j (c + T u_i), its φ
  enclosed in arb on the box |u| ≤ s_i, one interval per (j, i) until s_i ≤ SMALL, then one
  for all later periods.  Up to k_1 the window's b-states are the ball run's.
* **ball**: neither, but the ball engine run to the end (every collision choice decided by
  arb balls, exact products, precision up to :data:`BALL_DPS` digits; about 0.2 s for 10^4
  collisions when 64 bits suffice) encloses the true φ at each b-collision of the window
  directly: its certified horizon covers the window.  This holds the orbits that follow a
  word without an attracting periodic orbit (r near 1: abcb, whose N_w has a complex pair
  of modulus slightly above its real eigenvalue) or without a period in 10^4 collisions.
* **unresolved**: none of these (no trap and the ball engine stops undecided before the
  end: a chaotic orbit): its points are not certified.  An orbit whose float64 run breaks is
  drawn as a red dot: its points are not counted as plotted.

A continuation refuses a state that is not proved inside the island or the trap
(:func:`island_intervals`, :func:`trap_intervals` return the reason instead of intervals).
"""
from __future__ import annotations

import re
import time
from dataclasses import dataclass
from functools import cache

import flint
import numpy as np

from certify.algebra.balls import precision
from certify.dynamics import island
from certify.dynamics.model import INDEX
from certify.numerics import engines, rules, trapping
from certify.numerics.limits import PIXEL
from certify.patterns import island_theorem, read

from . import identify

PREC = 128                  # bits of the continuations' balls
ISLAND, TRAPPED, BALL, UNRESOLVED, BROKEN = "island", "trapped", "ball", "unresolved", "break"
KINDS = (ISLAND, TRAPPED, BALL, UNRESOLVED, BROKEN)
SMALL = flint.fmpq(1, 10 ** 12)   # a trap radius below this: one interval for all later periods
BALL_DPS = 100              # the cap of the ball engine run to the end (digits): a chaotic orbit stops cheaply
R_ISLAND = 3 - 2 * 2 ** 0.5  # 3 − 2√2 (for splitting the counts only; the island is decided exactly)


@cache
def pixel() -> flint.fmpq:
    """An exact rational ≤ π/1000 (= PIXEL), proved by arb."""
    with precision(128):
        b = flint.arb.pi() / 1000
        return b.mid().fmpq() - b.rad().fmpq()


assert abs(float(pixel()) - PIXEL) < 1e-15


@cache
def island_theorem_holds() -> bool:
    """The island theorem for the symbol r on ]3−2√2, 1[, proved once per process."""
    return bool(island_theorem.symbolic_theorem().holds)


def in_island_range(r: flint.fmpq) -> bool:
    """r in ]3−2√2, 1[, exactly (r² − 6r + 1 < 0 and r < 1)."""
    return bool(r < 1 and island.elliptic_polynomial(r) < 0)


def _bounds(x: flint.arb) -> tuple:
    """(lo, hi): exact rationals enclosing the ball x; (−4, 4) ⊃ [0, π] when x is not finite
    (an interval no plotted point can use)."""
    if not x.is_finite():
        return flint.fmpq(-4), flint.fmpq(4)
    m, e = x.mid().fmpq(), x.rad().fmpq()
    return m - e, m + e


def _phi(n) -> flint.arb:
    """φ of a state at b (any positive multiple of an oriented normal), a ball."""
    return flint.arb.atan2((n[2] * n[2] + n[0] * n[0]).sqrt(), n[1])


# ------------------------------------------------------------------ the continuations
def island_intervals(r: flint.fmpq, z0_state, steps: list[int]) -> list | str:
    """Intervals (lo, hi) enclosing the true φ after ``steps`` b-to-b steps from the state
    z0_state at b (a ball normal), one per step; the reason when the state is not proved in
    the island or the theorem does not apply at r."""
    if not in_island_range(r):
        return f"no island at r = {r}: r² − 6r + 1 ≥ 0"
    if not island_theorem_holds():
        return "the island theorem for the symbol r is not proved"
    with precision(PREC):
        if not island.inside(z0_state, r):              # the whole ball, not its midpoint
            return "the state at b is not proved inside the island U_r = {Q < c_max}"
        u0, v0 = island.chart(z0_state)
        (a, b), (c, d) = island.matrix_A(r)
        Au, Av = a * u0 + b * v0, c * u0 + d * v0
        theta = flint.arb((a + d) / 2).acos()           # cos θ = tr A / 2
        s = theta.sin()
        out = []
        for m in steps:
            sm, sm1 = (m * theta).sin(), ((m - 1) * theta).sin()
            u = (sm * Au - sm1 * u0) / s
            v = (sm * Av - sm1 * v0) / s
            out.append(_bounds(flint.arb.atan2((2 * (u * u + 1)).sqrt(), v)))
        return out


def radii(U: trapping.Trap, state, periods: int) -> list[flint.fmpq]:
    """[s_0, …, s_periods]: rational bounds |u_i| ≤ s_i of the frame coordinates of the
    orbit that is at ``state`` (a ball normal proved in U), after i periods.  s_0 bounds the
    state's own coordinates (arb); then s_{i+1} = min(ρ, R(s_i)) with the trap's image bound
    R(s) = (|g_0| + ‖A‖ s)/(α − |β| s) (:mod:`certify.numerics.trapping`: |g(u)| ≤ R(|u|), R
    increasing): a bound that follows the contraction, about ‖A‖/α ≈ |ν| per period near the
    periodic orbit, where the certificate's κ is the worst rate over the whole of U."""
    with precision(trapping.PREC):               # the certificate's own precision (‖A‖ needs it)
        return _radii(U, state, periods)


def _radii(U, state, periods):
    norm_g, norm_a, alpha, norm_b = U.image_bound()
    u = U.ball_coordinates(state)
    s = [min(_bounds((u[0] * u[0] + u[1] * u[1]).sqrt())[1], U.radius)]
    for _ in range(periods):
        R = (norm_g + norm_a * s[-1]) / (alpha - norm_b * s[-1])
        s.append(min(_bounds(R)[1], U.radius))
    return s


def trap_intervals(U: trapping.Trap, state, offsets: dict) -> list | str:
    """Intervals (lo, hi) enclosing the true φ after the j-th letter of U.word (a b) in the
    periods i of the orbit that is at ``state`` (contact U.word[-1]), ``offsets`` = {j: the
    periods i wanted}: one interval per (j, i) while the radius s_i exceeds :data:`SMALL`,
    then one for every later period (s_i decreases); the reason when the state is not
    proved inside U."""
    with precision(PREC):
        if U.ball_sign(state) != 1:
            return "the state is not proved inside the trapping ellipse"
        P = trapping.products(U.word, U.r)
        s_of = radii(U, state, max((max(v) for v in offsets.values()), default=0))
        out = []
        for j, periods in offsets.items():
            Pq = [[flint.fmpq(P[j][a, b]) for b in range(3)] for a in range(3)]
            c = [sum((Pq[a][b] * U.centre[b] for b in range(3)), flint.fmpq(0)) for a in range(3)]
            T = [[sum((Pq[a][b] * U.frame[col][b] for b in range(3)), flint.fmpq(0)) for a in range(3)]
                 for col in range(2)]
            for i in sorted(periods):
                box = flint.arb(0, 1) * s_of[i]            # [−s, s]: the disc |u| ≤ s lies in the box
                n = tuple(flint.arb(c[a]) + T[0][a] * box + T[1][a] * box for a in range(3))
                out.append(_bounds(_phi(n)))
                if s_of[i] <= SMALL:
                    break
        return out


# ------------------------------------------------------------------ the true window
def island_window(k0: int, collisions: int, keep: int) -> list[tuple[int, int]]:
    """(collision, steps m) of the true window's b-collisions after the entry at b at k0."""
    last = (collisions - k0) // 3
    return [(k0 + 3 * m, m) for m in range(max(0, last - keep + 1), last + 1)]


def trap_window(word: str, k0: int, collisions: int, keep: int) -> list[tuple[int, int, int]]:
    """(collision, period i, offset j) of the true orbit's last ``keep`` b-collisions up to
    ``collisions`` after the entry at the contact word[-1] at k0 (it follows word for ever)."""
    L, bs = len(word), [j for j in range(1, len(word) + 1) if word[j - 1] == "b"]
    out, i = [], (collisions - k0) // L
    while i >= 0 and len(out) < keep:
        out += [(k0 + i * L + j, i, j) for j in reversed(bs) if k0 + i * L + j <= collisions]
        i -= 1
    return sorted(out[:keep])


def matched(phi: np.ndarray, intervals: list) -> np.ndarray:
    """For each plotted φ (finite doubles), whether some interval (lo, hi) has
    max(φ − lo, hi − φ) ≤ pixel(), decided exactly in Q (the floats only pick the
    interval whose midpoint is nearest)."""
    ok = np.zeros(len(phi), dtype=bool)
    if not intervals:
        return ok
    mids = np.array([float((lo + hi) / 2) for lo, hi in intervals])
    order = np.argsort(mids)
    px = pixel()
    for a, x in enumerate(phi):
        k = int(np.searchsorted(mids[order], x))
        for c in (k - 1, k, k + 1):
            if 0 <= c < len(order):
                lo, hi = intervals[order[c]]
                q = flint.fmpq(*float(x).as_integer_ratio())
                if q - lo <= px and hi - q <= px:
                    ok[a] = True
                    break
    return ok


# ------------------------------------------------------------------ one orbit
@dataclass
class OrbitPoints:
    """The plotted points of one orbit and how many are certified (module docstring)."""

    r: float
    theta0: float
    phi0: float
    kind: str = UNRESOLVED
    entry: int | None = None           # the collision from which the class is proved
    word: str | None = None            # trapped: the rotation followed (certified)
    points: int = 0                    # plotted points (finite φ of a completed run)
    certified: int = 0
    why: str = ""

    def to_json(self) -> dict:
        return {"r": self.r, "theta0": self.theta0, "phi0": self.phi0, "kind": self.kind, "entry": self.entry,
                "word": self.word, "points": self.points, "certified": self.certified, "why": self.why}


@cache
def _trap(word: str, r: flint.fmpq) -> trapping.Trap | str:
    return trapping.attempt(word, r)


def _entry_trap(q, theta0, phi0, U, collisions):
    """(k0, k1, state at k1, bits, b-states up to k1): the ball state at U's contact proved in U at a
    first collision k0, then followed by the ball engine while the trap's radius bound
    (:func:`radii`) stays above :data:`SMALL` (the periods right after the entry, where the
    bound is coarse and the ball states are sharp), up to k1 = k0 + E·L; None when never in U."""
    c0, pre, k0, stop_at = INDEX[U.word[-1]], {}, None, None
    for k, j, n, bits in engines.ball_states(q, theta0, phi0, collisions):
        if j == INDEX["b"]:
            pre[k] = (n, bits)
        if k0 is None and j == c0:
            with precision(bits):
                if U.ball_sign(n) == 1:
                    k0 = k
                    s = radii(U, n, (collisions - k) // len(U.word))
                    E = next((i for i, x in enumerate(s) if x <= SMALL), len(s) - 1)
                    stop_at = k + E * len(U.word)
        if stop_at is not None and k == stop_at:
            return k0, k, n, bits, pre
    return None


def certify_orbit(r: float, theta0: float, phi0: float, phi, collisions: int, keep: int,
                  broken: bool = False) -> OrbitPoints:
    """The plotted points ``phi`` (the kept φ of the float64 run, NaN-padded) of one orbit,
    certified as the module docstring says."""
    x = OrbitPoints(float(r), float(theta0), float(phi0))
    phi = np.asarray(phi, float)
    phi = phi[np.isfinite(phi)]
    if broken:
        x.kind, x.why = BROKEN, "the float64 run breaks: drawn as a red dot, no point plotted"
        return x
    x.points = len(phi)
    q = rules.exact_r(float(r))
    n0 = next(iter(engines.ball_states(q, theta0, phi0, 0)))
    intervals = island_intervals(q, n0[2], [m for _, m in island_window(0, collisions, keep)]) \
        if in_island_range(q) else "r ≤ 3−2√2"
    if not isinstance(intervals, str):
        x.kind, x.entry = ISLAND, 0
    else:
        found = _trapped(x, q, theta0, phi0, collisions, keep)
        if found is None:
            found = _ball_all(x, q, theta0, phi0, collisions, keep)
        if found is None:
            return x
        intervals = found
    ok = matched(phi, intervals)
    x.certified = int(ok.sum())
    if x.certified < x.points:
        x.why += f"{x.points - x.certified} plotted point(s) farther than a pixel from the certified set"
    return x


def _ball_all(x: OrbitPoints, q, theta0, phi0, collisions, keep) -> list | None:
    """The window's true φ from the ball engine run to the end (every collision decided,
    :func:`certify.numerics.engines.ball_states`, precision up to BALL_DPS digits), or None
    (x.why completed) when it stops undecided before."""
    stop, states = {"code": 0, "bits": 0}, []
    done = 0
    for done, j, n, bits in engines.ball_states(q, theta0, phi0, collisions, dps=BALL_DPS, stop=stop):
        if done and j == INDEX["b"]:
            states.append((n, bits))
            if len(states) > 2 * keep:
                del states[:-keep]
    if done < collisions:
        x.why = (f"the ball engine stops undecided at collision {done + 1} ({stop['bits']} bits, "
                 f"cap {BALL_DPS} digits); {x.why}")
        return None
    out = []
    for n, bits in states[-keep:]:
        with precision(bits):
            out.append(_bounds(_phi(n)))
    x.kind, x.entry, x.why = BALL, collisions, ""
    return out


def _trapped(x: OrbitPoints, q, theta0, phi0, collisions, keep) -> list | None:
    """The intervals of a trapped orbit (x.kind, x.entry, x.word set), or None (x.why set)."""
    res = engines.float64_orbit(q, theta0, phi0, collisions, word=True)
    block = identify.period_of(res.word) if res.code == 0 else None
    if block is None or len(block) > identify.MAX_ANALYSED:
        x.why = "no period observed in the float64 run (no trap to try)"
        return None
    try:
        normal = read(block)[0]
    except Exception as exc:                      # not a word of the reduction
        x.why = f"the observed block is not a word of the reduction ({exc})"
        return None
    word = identify.followed(block, normal)
    U = _trap(word, q)
    if isinstance(U, str):
        x.why = f"no certified trapping ellipse for the observed word: {U}"
        return None
    got = _entry_trap(q, theta0, phi0, U, collisions)
    if got is None:
        x.why = f"the rigorous orbit is not proved inside the trap of {word} within {collisions} collisions"
        return None
    k0, k1, state, bits, pre = got
    window = trap_window(word, k1, collisions, keep)
    before = sorted(k for k in pre if k <= k1)[-keep:]
    allk = sorted([(k, None, None) for k in before] + window)[-keep:]      # k1 itself: the ball state
    offsets: dict = {}
    for _k, i, j in allk:
        if i is not None:
            offsets.setdefault(j, set()).add(i)
    with precision(bits):
        intervals = trap_intervals(U, state, offsets)
    if isinstance(intervals, str):
        x.why = intervals
        return None
    for k, i, _j in allk:
        if i is None:
            n, b = pre[k]
            with precision(b):
                intervals.append(_bounds(_phi(n)))
    x.kind, x.entry, x.word = TRAPPED, k0, word
    return intervals


# ------------------------------------------------------------------ a figure
def certify_rows(rs, theta0, phi0, phi, breaks, collisions: int, keep: int) -> list[list[dict]]:
    """A picklable unit of work: the orbits of a few r (rows of a figure's run), as JSON."""
    return [[certify_orbit(float(r), float(theta0[m]), float(phi0[m]), phi[a, m], collisions, keep,
                           bool(breaks[a, m])).to_json() for m in range(len(theta0))]
            for a, r in enumerate(rs)]


def rows_of(data, every: int = 1) -> np.ndarray:
    """The indices of the r values certified: every ``every``-th of the grid, both ends."""
    n = len(data.r)
    idx = list(range(0, n, every))
    if idx and idx[-1] != n - 1:
        idx.append(n - 1)
    return np.array(idx, dtype=int)


def certify_figure(data, every: int = 1, executor=None, progress=None, chunk: int = 8) -> dict:
    """Certify the plotted points of a figure's run (``FigureData``), on every ``every``-th
    r; returns {"orbits": [...], "seconds": ...} (the orbits as JSON, row by row)."""
    from certify.numerics import figures
    theta0, phi0 = figures.initial_data(data.spec.orbits)
    idx = rows_of(data, every)
    t = time.perf_counter()
    parts = [idx[a:a + chunk] for a in range(0, len(idx), chunk)]
    args = [(data.r[p], theta0, phi0, data.phi[p], data.breaks[p], data.collisions, data.keep) for p in parts]
    out: list = [None] * len(parts)
    if executor is None:
        for a, x in enumerate(args):
            out[a] = certify_rows(*x)
            if progress is not None:
                progress(a + 1, len(parts), f"r = {data.r[parts[a][-1]]:.6g}")
    else:
        from concurrent.futures import as_completed
        futures = {executor.submit(certify_rows, *x): a for a, x in enumerate(args)}
        for done, f in enumerate(as_completed(futures), 1):
            out[futures[f]] = f.result()
            if progress is not None:
                progress(done, len(parts), "rows")
    orbits = [o for part in out for row in part for o in row]
    return {"every": every, "rows": len(idx), "orbits": orbits, "seconds": round(time.perf_counter() - t, 1)}


def summary(found: dict, lo: float | None = None, hi: float | None = None) -> dict:
    """The certified fraction of the points (all, and for r > 3−2√2), the classes, and
    why the rest is not certified; restricted to lo ≤ r ≤ hi when given (a magnification)."""
    orbits = [o for o in found["orbits"]
              if (lo is None or o["r"] >= lo - 1e-12) and (hi is None or o["r"] <= hi + 1e-12)]

    def frac(sel):
        pts = sum(o["points"] for o in sel)
        cert = sum(o["certified"] for o in sel)
        return {"points": pts, "certified": cert, "fraction": round(cert / pts, 6) if pts else None}
    above = [o for o in orbits if o["r"] > R_ISLAND]
    why: dict = {}
    for o in orbits:
        if o["certified"] < o["points"]:
            key = re.sub(r"\d+", "N", o["why"].split(";")[0].split(" (")[0])
            why[key] = why.get(key, 0) + o["points"] - o["certified"]
    return {"every": found["every"], "r_values": len({o["r"] for o in orbits}), "orbits": len(orbits),
            "all": frac(orbits), "above_3-2sqrt2": frac(above),
            "classes": {k: sum(1 for o in orbits if o["kind"] == k) for k in KINDS},
            "not_certified": dict(sorted(why.items(), key=lambda kv: -kv[1])), "seconds": found["seconds"]}
