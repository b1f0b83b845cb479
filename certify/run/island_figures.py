"""The island's figures (floats: drawings only; the proofs are in
:mod:`certify.patterns.island_theorem`):

* :func:`section_axes`: the b-section (θ, φ) at r with the island's boundary ellipse
  Q = c_max drawn over the b-section points of the paper's orbits (float64 engine, the
  initial data of ``certify.numerics.grid(8)``);
* :func:`rotation_axes`: the rotation number ρ(r) on ]3−2√2, 1[ with the resonances p/q
  marked and, on a strip below sharing its r axis, the attracting windows of the census
  (reports/census.json, read with :func:`.census_report.committed_windows`);
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
    """The b-section points of each orbit (one colour each) and the island's boundary (black), with a
    legend below the panel (it covers no point)."""
    from matplotlib.lines import Line2D
    _, points, grid = data
    for k, (th, ph) in enumerate(points):
        ax.plot(th, ph, ".", ms=1.2, alpha=0.6, label=f"orbit {k + 1}")
    handles, labels = ax.get_legend_handles_labels()
    if grid is not None:
        ax.contour(*grid, levels=[0], colors="k", linewidths=1.2)
        handles.append(Line2D([], [], color="k", lw=1.2))
        labels.append("the island's boundary Q = c_max")
    ax.set_xlim(0, math.pi / 2)
    ax.set_ylim(0, math.pi)
    ax.set_xlabel("θ")
    ax.set_ylabel("φ")
    ax.set_title(f"b-section at r = {r}: {len(points)} orbits of the paper's initial data (float64)", fontsize=9)
    ax.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=5, fontsize=7,
              markerscale=5, frameon=False, handlelength=1.2, columnspacing=1.0)


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


def draw_rotation(ax, strip, Q: int, data) -> None:
    """Top (``ax``): ρ(r) with the resonances p/q as vertical lines, labelled above the panel
    (:func:`.plots.label_lines`: no two labels overlap).  Below (``strip``, the same r axis): the
    census's attracting windows, one row per word, as bars (an r interval: no height on the ρ axis)."""
    from .plots import label_lines, label_pad
    marks, shown = data
    rs = np.linspace(LOWER + 1e-9, 1 - 1e-9, 600)
    rho = np.arccos(-(1 - rs) ** 2 / (4 * rs)) / (2 * math.pi)
    ax.plot(rs, rho, "k-", lw=1.2)
    for _, x, y in marks:
        ax.axvline(x, color="tab:blue", lw=0.5, alpha=0.6)
        ax.plot([x], [y], "o", color="tab:blue", ms=2.5)
    ax.set_xlim(LOWER - 0.01, 1)
    ax.set_ylim(0.24, 0.51)
    rows = label_lines(ax, {label: x for label, x, _ in marks}, color="tab:blue", fontsize=7)
    ax.set_ylabel("rotation number ρ")
    ax.set_title(f"ρ(r) and the resonances ρ = p/q, q ≤ {Q} (blue)", fontsize=9, pad=label_pad(rows, 7))
    words = list(dict.fromkeys(w for w, _, _ in shown))
    for w, lo, hi in shown:                        # clipped by the axes at 3−2√2 − 0.01
        strip.barh(words.index(w), hi - lo, left=lo, height=0.6, color="tab:orange")
    strip.set_yticks(range(len(words)), words, fontsize=7)
    strip.set_ylim(len(words) - 0.5, -0.5)
    strip.set_xlabel("r")
    strip.set_title("attracting periodic orbits of the reduction: their windows in the census", fontsize=9)


def rotation_axes(ax, strip, Q: int = 12, windows=None) -> None:
    """ρ(r) on ``ax``, the census's windows (or ``windows``) on ``strip`` (:func:`draw_rotation`)."""
    draw_rotation(ax, strip, Q, rotation_data(Q, windows))


def island_axes(plt, section: bool, windows: int) -> tuple:
    """The figure and its panels: the b-section on the left (when ``section``), ρ(r) at the right
    over a strip of ``windows`` rows sharing its r axis."""
    fig = plt.figure(figsize=(12 if section else 6, 5.2 + 0.2 * windows))
    grid = fig.add_gridspec(2, 2 if section else 1, height_ratios=[3, 0.6 + 0.3 * max(windows, 1)])
    left = fig.add_subplot(grid[:, 0]) if section else None
    top = fig.add_subplot(grid[0, -1])
    return fig, left, top, fig.add_subplot(grid[1, -1], sharex=top)


def island_figure(path, r=None, Q: int = 12) -> Path:
    """The b-section at r (when given) and the rotation number against r, into ``path``."""
    plt = saving.pyplot()
    data = rotation_data(Q)
    fig, left, top, strip = island_axes(plt, r is not None, len({w for w, _, _ in data[1]}))
    if left is not None:
        section_axes(left, r)
    draw_rotation(top, strip, Q, data)
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
        fig, left, top, strip = island_axes(plt, True, len({w for w, _, _ in rotation[1]}))
        draw_section(left, r, section)
        draw_rotation(top, strip, 12, rotation)
        fig.tight_layout()
        return saving.save_figure(fig, "island")
    _, points, grid = section
    key = saving.input_digest(str(r), *(a for pair in points for a in pair), *(grid or ()), rotation)
    return saving.cached("island", key, draw)
