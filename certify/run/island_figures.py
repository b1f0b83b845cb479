"""The island's figures (floats: drawings only; the proofs are in
:mod:`certify.patterns.island_theorem`):

* :func:`section_axes`: the b-section (θ, φ) at r with the island's boundary ellipse
  Q = c_max drawn over the b-section points of the paper's orbits (float64 engine, the
  initial data of ``certify.numerics.grid(8)``);
* :func:`rotation_axes`: the rotation number ρ(r) on ]3−2√2, 1[ with the resonances p/q
  marked, over the attracting windows of the census (reports/census.json, read with
  :func:`certify.patterns.census.attracting_windows`);
* :func:`island_figure`: both, side by side, written to a path (``certify island --figure``).
"""
from __future__ import annotations

import math
from pathlib import Path

import flint
import numpy as np

from certify.dynamics import island
from certify.patterns import island_theorem as it

from . import census_report, saving

LOWER = 3 - 2 * math.sqrt(2)
FLOAT_WIDTH = flint.fmpq(1, 2 ** 72)   # a resonance's interval refined (Sturm) below this before float(): the
# same float (its 20 digits), without float()'s own refinement, a bisection and a decimal rounding a bit


def b_section_points(r: float, collisions: int = 3000, count: int = 8) -> list[tuple[np.ndarray, np.ndarray]]:
    """(θ, φ) at every b-collision of the float64 orbits of the paper's first ``count``
    initial data (an observation: float orbits past their certified horizon)."""
    from certify.numerics import engines, grid, rules
    theta0, phi0 = grid(count)
    out = []
    for t0, p0 in zip(theta0, phi0):
        res = engines.float64_orbit(r, float(t0), float(p0), collisions, checkpoints=range(1, collisions + 1))
        pts = [(rules.theta_of(1, n), rules.phi_of(1, n)) for c, (i, n) in sorted(res.checkpoints.items()) if i == 1]
        th, ph = (np.array(x) for x in zip(*pts)) if pts else (np.array([]), np.array([]))
        out.append((th, ph))
    return out


def island_share(theta: np.ndarray, phi: np.ndarray, r: float) -> np.ndarray:
    """c_max − Q at the b-states (θ, φ), floats (positive inside the island)."""
    n = np.array([-np.cos(theta) * np.sin(phi), np.cos(phi), np.sin(theta) * np.sin(phi)])
    d = n[2] - n[0]
    u, v = (n[0] + n[2]) / d, 2 * n[1] / d
    return float(island.c_max(r)) - island.quadratic_form(u, v, r)


def section_data(r, collisions: int = 3000) -> tuple[float, list, tuple | None]:
    """What :func:`section_axes` draws: r as a float, the b-section points of the orbits,
    and (θ, φ, c_max − Q) on a grid for the island's boundary (None below 3−2√2)."""
    rf = float(r)
    points = b_section_points(rf, collisions)
    grid = None
    if rf > LOWER:
        T, P = np.meshgrid(np.linspace(1e-3, math.pi / 2 - 1e-3, 400), np.linspace(1e-3, math.pi - 1e-3, 400))
        grid = (T, P, island_share(T, P, rf))
    return rf, points, grid


def draw_section(ax, r, data) -> None:
    _, points, grid = data
    for k, (th, ph) in enumerate(points):
        ax.plot(th, ph, ".", ms=1.2, alpha=0.6, label=f"orbit {k + 1}")
    if grid is not None:
        ax.contour(*grid, levels=[0], colors="k", linewidths=1.2)
    ax.set_xlim(0, math.pi / 2)
    ax.set_ylim(0, math.pi)
    ax.set_xlabel("θ")
    ax.set_ylabel("φ")
    ax.set_title(f"b-section at r = {r}: the island's boundary Q = c_max (black)")


def section_axes(ax, r, collisions: int = 3000) -> None:
    draw_section(ax, r, section_data(r, collisions))


def census_windows(path: Path | None = None) -> list[tuple[str, float, float]]:
    """(word, lo, hi) of every attracting window of the committed census (floats of the
    certified ends, :func:`.census_report.committed_windows`), or [] without a census file."""
    committed = census_report.committed_windows(path)
    if committed is None:
        return []
    windows, compact = committed
    return [(compact.get(w, w), float(span["lo"]["digits"]), float(span["hi"]["digits"]))
            for w, spans in windows.items() for span in spans]


def rotation_data(Q: int = 12, windows=None) -> tuple[list, list]:
    """What :func:`rotation_axes` draws: the resonances (label, r as a float, p/q) with q ≤ Q,
    and the attracting windows (word, lo, hi) above 3−2√2 (the committed census by default)."""
    marks = [(f"{s.p}/{s.q}", float(s.r.refine(FLOAT_WIDTH)), s.p / s.q) for s in it.resonances(Q)]
    shown = [(w, lo, hi) for w, lo, hi in (windows if windows is not None else census_windows()) if hi > LOWER]
    return marks, shown


def draw_rotation(ax, Q: int, data) -> None:
    marks, shown = data
    rs = np.linspace(LOWER + 1e-9, 1 - 1e-9, 600)
    rho = np.arccos(-(1 - rs) ** 2 / (4 * rs)) / (2 * math.pi)
    ax.plot(rs, rho, "k-", lw=1.2, label="ρ(r)")
    for label, x, y in marks:
        ax.axvline(x, color="tab:blue", lw=0.5, alpha=0.6)
        ax.annotate(label, (x, y), fontsize=7, xytext=(2, 2), textcoords="offset points")
    for k, (w, lo, hi) in enumerate(shown):            # one thin row per window, at the bottom
        y = 0.02 + 0.04 * k
        ax.axvspan(max(lo, LOWER), hi, ymin=y, ymax=y + 0.03, color="tab:orange", alpha=0.8,
                   label="attracting windows (census)" if k == 0 else None)
        ax.annotate(w, (max(lo, LOWER), 0.24 + 0.27 * (y + 0.03)), fontsize=6, va="bottom")
    ax.set_xlim(LOWER - 0.01, 1)
    ax.set_ylim(0.24, 0.51)
    ax.set_xlabel("r")
    ax.set_ylabel("rotation number ρ")
    ax.set_title(f"ρ(r) and the resonances p/q, q ≤ {Q}")
    ax.legend(loc="upper right", fontsize=7)


def rotation_axes(ax, Q: int = 12, windows=None) -> None:
    draw_rotation(ax, Q, rotation_data(Q, windows))


def island_figure(path, r=None, Q: int = 12) -> Path:
    """The b-section at r (when given) and the rotation number against r, into ``path``."""
    plt = saving.pyplot()
    ncols = 2 if r is not None else 1
    fig, axes = plt.subplots(1, ncols, figsize=(6 * ncols, 4.5))
    axes = np.atleast_1d(axes)
    if r is not None:
        section_axes(axes[0], r)
    rotation_axes(axes[-1], Q)
    fig.tight_layout()
    return saving.write_figure(fig, path)


def report_figure(r) -> str:
    """The b-section at r and the rotation number, as one figure of the report (``island.png``
    in the output directory of the run, :func:`certify.run.saving.save_figure`; drawn only
    then, copied from :func:`certify.run.saving.cached` when drawn before from the same data)."""
    if not saving.enabled():
        return saving.figure_name("island")
    section, rotation = section_data(r), rotation_data()

    def draw() -> str:
        plt = saving.pyplot()
        fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
        draw_section(axes[0], r, section)
        draw_rotation(axes[1], 12, rotation)
        fig.tight_layout()
        return saving.save_figure(fig, "island")
    _, points, grid = section
    key = saving.input_digest(str(r), *(a for pair in points for a in pair), *(grid or ()), rotation)
    return saving.cached("island", key, draw)
