"""The numerical experiments N3-N7 of Section 5: what the certificates read off the runs
of the figures, the search for the windows of (ab)^n(cb)^n at large n (N4), and the
findings ``certify figures --resolution paper`` and ``--n4`` write (JSON-ready dicts;
the run layer writes and reads the files).
"""
from __future__ import annotations

import time

import numpy as np

from .engines import run_orbit
from .figures import FigureData
from .limits import (
    GAP,
    PIECE_GAP,
    POINT,
    dominant_count,
    fraction,
    omega,
    per_r,
    stripe_scan,
    widest_orbit,
    window_counts,
)
from .orbits import paper_grid
from .thresholds import digits_for, min_component, r_max, upper_threshold


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
    ``orbits`` orbits of the tool's grid of 8 initial data on ``engine`` and count the accumulation points of
    their kept φ (gap 1e-8, point 1e-10 for mp and ball; the float defaults for float64);
    check the last 8n letters of the first orbit against (ab)^n(cb)^n."""
    t0 = time.perf_counter()
    dps = dps or digits_for(n)
    hi, lo = thresholds or (upper_threshold(n), upper_threshold(n + 1))
    theta0, phi0 = paper_grid()
    collisions = collisions or max(10_000, 400 * n)
    keep = max(500, 6 * n)
    gap, point = (GAP, POINT) if engine == "float64" else (1e-8, 1e-10)
    rows = []
    for f in fractions:
        r = float(hi - f * (hi - lo))
        res = [run_orbit(engine, r, float(theta0[m]), float(phi0[m]), collisions, keep, dps,
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


def n3_window_probes(fractions=(0.05, 0.15, 0.3, 0.45)) -> list[float]:
    """r values inside each window of N3 (n = 2..5): r_max(n) − f (r_max(n) − lower end)."""
    out = []
    for lo, hi in windows_of().values():
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
        out["n6"] = {"stripes": [round(r, 6) for r, _, _ in scan[:4]],
                     "coverages": [round(c, 3) for _, c, _ in scan[:4]],
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
