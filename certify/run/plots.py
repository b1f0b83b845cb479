"""Figures regenerated from certified data (the paper's figures are placeholders).

Curves are drawn with floats (figures only); what they show — the number of real
branches, the sign of a condition on each branch, the critical values of r — comes
from the certified sign tables.  Nothing is drawn when figures are not being saved.
"""
from __future__ import annotations

import bisect

import numpy as np
import sympy as sp

from certify.algebra.branches import BRANCH_NAMES
from certify.algebra.poly import r

from . import saving

COLORS = ("tab:blue", "tab:orange", "tab:green", "tab:purple")


def branch_curves(spectrum, rs: np.ndarray) -> np.ndarray:
    """Real eigenvalues at each r (floats, largest first, NaN where fewer are real)."""
    coeffs = [sp.lambdify(r, c, "numpy") for c in spectrum.P.all_coeffs()]
    out = np.full((len(rs), spectrum.degree), np.nan)
    for i, t in enumerate(rs):
        roots = np.roots([float(np.broadcast_to(f(t), ())) for f in coeffs])
        real = np.sort(roots[np.abs(roots.imag) < 1e-9].real)[::-1]
        out[i, : len(real)] = real
    return out


def _cell_indices(table, rs: np.ndarray) -> list[int | None]:
    """For each r (float), the index of the certified cell holding it (None on a border)."""
    bounds = [(float(cell.lo), float(cell.hi)) for cell in table.cells]
    los = [lo for lo, _ in bounds]
    if any(b[1] > c[0] for b, c in zip(bounds, bounds[1:])):     # not consecutive cells: look through them all
        return [next((k for k, (lo, hi) in enumerate(bounds) if lo < t < hi), None) for t in rs]
    out = []
    for t in rs:                 # the last cell starting below t is the only one that can hold it
        k = bisect.bisect_left(los, t) - 1
        out.append(k if k >= 0 and bounds[k][0] < t < bounds[k][1] else None)
    return out


def _marks(marks: dict | None) -> list[tuple[str, float]]:
    return [(label, float(value)) for label, value in (marks or {}).items()]


def _draw_marks(ax, marks: list[tuple[str, float]]) -> int:
    """The critical values of r as dashed grey lines, labelled above the axes (:func:`label_lines`);
    returns the rows of labels."""
    for _, value in marks:
        ax.axvline(value, color="grey", lw=0.6, ls="--")
    return label_lines(ax, dict(marks), color="black", fontsize=7)


def _spectrum_key(spectrum) -> str:
    """The characteristic polynomial the curves are computed from (:func:`branch_curves`), and the legend's names."""
    return f"{spectrum.degree} {[str(c) for c in spectrum.P.all_coeffs()]} {BRANCH_NAMES}"


def spectrum_figures(spectrum, table, marks: dict) -> list[str]:
    """Figures 1-2 of the paper (fig:spectrum, fig:spectrum zoom): the real spectrum of M on ]0,1[
    and its zoom 0<r<0.13, 0<λ<0.05.
    Branches are taken from the certified table: a point is drawn on branch k only
    where the table proves k+1 real eigenvalues.  What the table says at each point is
    read first (the same reads, in the same order, whether the PNG is drawn or copied
    from :func:`saving.cached`)."""
    if not saving.enabled():
        return ["spectrum.png", "spectrum_zoom.png"]
    names = []
    for name, (r_lo, r_hi), ylim in (("spectrum.png", (1e-4, 0.9999), None),
                                     ("spectrum_zoom.png", (1e-4, 0.13), (0, 0.05))):
        rs = np.linspace(r_lo, r_hi, 1500)
        cells = _cell_indices(table, rs)
        count = {}               # real branches per cell, each cell read once, in the order the points meet them
        for c in cells:
            if c is not None and c not in count:
                count[c] = len(table.cells[c].branches)
        oks = [np.array([c is not None and k < count[c] for c in cells]) for k in range(spectrum.degree)]
        shown = _marks(marks)

        def draw(name=name, rs=rs, oks=oks, shown=shown, r_lo=r_lo, r_hi=r_hi, ylim=ylim):
            plt = saving.pyplot()
            curves = branch_curves(spectrum, rs)
            fig, ax = plt.subplots(figsize=(6.4, 4.2))
            for k, ok in enumerate(oks):
                ax.plot(rs[ok], np.where(ok, curves[:, k], np.nan)[ok], ".", ms=1.5, color=COLORS[k],
                        label=BRANCH_NAMES[k] + " branch" if k < 3 else f"branch {k}")
            ax.set_xlim(r_lo, r_hi)
            _draw_marks(ax, shown)
            if ylim:
                ax.set_ylim(*ylim)
            ax.set_xlabel("r")
            ax.set_ylabel("real eigenvalues λ of M")
            ax.legend(loc="best", fontsize=7, markerscale=6)
            return saving.save_figure(fig, name)
        key = saving.input_digest(_spectrum_key(spectrum), r_lo, r_hi, ylim, *oks, shown)
        names.append(saving.cached(name, key, draw))
    return names


def sign_chart(spectrum, table, name: str, title: str, xlim=(1e-4, 0.2), ylim=None, marks=None) -> str:
    """Figures 3-4 of the paper (fig: sign changes a-d, fig: sign change b): each branch coloured
    by the certified sign of a condition (read first, as in :func:`spectrum_figures`)."""
    if not saving.enabled():
        return name
    rs = np.linspace(xlim[0], xlim[1], 1500)
    cells = _cell_indices(table, rs)
    oks = [(sign, color, k, np.array([c is not None and k < len(table.cells[c].signs)
                                      and table.cells[c].signs[k] == sign for c in cells]))
           for sign, color in ((1, "tab:red"), (-1, "tab:blue")) for k in range(spectrum.degree)]
    shown = _marks(marks)

    def draw():
        plt = saving.pyplot()
        curves = branch_curves(spectrum, rs)
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        labelled = set()
        for sign, color, k, ok in oks:
            if ok.any():
                ax.plot(rs[ok], curves[ok, k], ".", ms=1.5, color=color,
                        label=None if sign in labelled else ("> 0" if sign > 0 else "< 0"))
                labelled.add(sign)
        ax.set_xlim(*xlim)
        ax.set_yscale("symlog", linthresh=1e-4)
        ax.set_ylim(*(ylim or (min(0.0, float(np.nanmin(curves))), None)))   # no empty band below the data
        rows = _draw_marks(ax, shown)
        ax.set_xlabel("r")
        ax.set_ylabel("λ")
        ax.set_title(title, fontsize=9, pad=label_pad(rows, 7))
        ax.legend(loc="best", fontsize=7, markerscale=6)
        return saving.save_figure(fig, name)
    key = saving.input_digest(_spectrum_key(spectrum), title, xlim, ylim, *(ok for *_, ok in oks), shown)
    return saving.cached(name, key, draw)


# --------------------------------------------------------------------------
# Section 5: clouds of (r, φ) points (certify.numerics.figures)

LABEL_PAD = 2                           # points between the axes and the first row of labels, and between rows


def text_width_inches(text: str, fontsize: float) -> float:
    """The width of ``text`` set in the default font at ``fontsize`` points, in inches (measured,
    as the renderer sets it)."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextToPath
    width, _, _ = TextToPath().get_text_width_height_descent(text, FontProperties(size=fontsize), ismath=False)
    return width / 72


def label_rows(lines: dict, xlo: float, xhi: float, axes_inches: float, fontsize: float = 6) -> dict:
    """Where to write each line's label above the axes so that none overprints another
    or is cut at an edge: ``{label: (x as axes fraction, row, ha)}``, row 0 first, a label
    going to the first row where it does not overlap one already placed (labels measured
    with :func:`text_width_inches`, a space apart)."""
    placed: dict[int, list[tuple[float, float]]] = {}
    out = {}
    space = text_width_inches(" ", fontsize)
    for label, value in sorted(lines.items(), key=lambda kv: kv[1]):
        x = (value - xlo) / (xhi - xlo)
        w = (text_width_inches(label, fontsize) + space) / axes_inches
        left, ha = (x - w / 2, "center")
        if left < 0:
            left, ha = x, "left"
        elif left + w > 1:
            left, ha = x - w, "right"
        row = next(k for k in range(len(lines) + 1)
                   if all(left + w <= a or b <= left for a, b in placed.get(k, [])))
        placed.setdefault(row, []).append((left, left + w))
        out[label] = (x, row, ha)
    return out


def label_lines(ax, lines: dict, color: str = "red", fontsize: float = 6) -> int:
    """Label the vertical lines ``lines`` ({label: r}, those inside the x range of ``ax``) above
    the axes, in rows (:func:`label_rows`) so that no two labels overlap; the axes' x limits
    and its place in the figure set first.  Returns the number of rows (:func:`label_pad`)."""
    xlo, xhi = ax.get_xlim()
    shown = {label: value for label, value in lines.items() if xlo <= value <= xhi}
    fig = ax.get_figure()
    inches = ax.get_position().width * fig.get_figwidth() * 0.9    # tight_layout may narrow the axes a little
    rows = label_rows(shown, xlo, xhi, inches, fontsize)
    for label, (x, row, ha) in rows.items():
        ax.annotate(label, (x, 1.0), xycoords="axes fraction", xytext=(0, LABEL_PAD + (fontsize + LABEL_PAD) * row),
                    textcoords="offset points", fontsize=fontsize, va="bottom", ha=ha, color=color,
                    annotation_clip=False)
    return 1 + max((row for _, row, _ in rows.values()), default=-1)


def label_pad(rows: int, fontsize: float = 6) -> float:
    """The title's pad (points) above ``rows`` rows of :func:`label_lines`."""
    return 6 + (fontsize + LABEL_PAD) * rows + (LABEL_PAD if rows else 0)


def omega_figure(data, name: str, lines: dict | None = None, boxes=(), title: str = "",
                 size=(9.0, 5.0), dpi: int | None = None) -> str:
    """A figure of Section 5: the kept angles φ of every orbit against r, drawn as the
    pixels they hit (black), each break as a red dot at (r, π/2), the thresholds
    ``lines`` ({label: r}) as red vertical lines, ``boxes`` ((r_lo, r_hi), ...) as red
    rectangles.  ``dpi``: the resolution of the saved PNG (default: saving.DPI)."""
    if not saving.enabled():
        return saving.figure_name(name)
    key = saving.input_digest(float(data.spec.lo), float(data.spec.hi), data.r, data.phi, data.break_r(),
                              list((lines or {}).items()), list(boxes), title, size, dpi)
    return saving.cached(name, key, lambda: _draw_omega(data, name, lines, boxes, title, size, dpi), dpi)


def _draw_omega(data, name: str, lines, boxes, title: str, size, dpi) -> str:
    plt = saving.pyplot()
    from matplotlib.patches import Rectangle
    lo, hi = float(data.spec.lo), float(data.spec.hi)
    dpi = dpi or saving.DPI
    fig, ax = plt.subplots(figsize=size)
    width = max(int(size[0] * dpi * 0.8), 10)
    height = max(int(size[1] * dpi * 0.8), 10)
    r = np.broadcast_to(data.r[:, None, None], data.phi.shape)
    ok = np.isfinite(data.phi)
    span = (hi - lo) or 1.0
    hits, _, _ = np.histogram2d(data.phi[ok], r[ok], bins=(height, width),
                                range=((0.0, np.pi), (lo - span / (2 * width), hi + span / (2 * width))))
    ax.imshow(hits > 0, origin="lower", aspect="auto", cmap="Greys", interpolation="nearest",
              extent=(lo - span / (2 * width), hi + span / (2 * width), 0.0, np.pi), vmin=0, vmax=1)
    broken = data.break_r()
    if broken.size:
        ax.plot(broken, np.full(broken.size, np.pi / 2), ".", color="red", ms=2.5, label=f"breaks ({broken.size})")
    xlo, xhi = lo - span / (2 * width), hi + span / (2 * width)
    shown = {label: value for label, value in (lines or {}).items() if lo <= value <= hi}
    for value in shown.values():
        ax.axvline(value, color="red", lw=0.8)
    for b_lo, b_hi in boxes:
        ax.add_patch(Rectangle((b_lo, 0.02), b_hi - b_lo, np.pi - 0.04, fill=False, edgecolor="red", lw=1.0))
    ax.set_xlim(xlo, xhi)
    ax.set_ylim(0, np.pi)
    rows = label_lines(ax, shown)
    ax.set_xlabel("r")
    ax.set_ylabel("φ")
    ax.set_title(title, fontsize=8, pad=label_pad(rows))
    if broken.size:
        ax.legend(loc="upper right", fontsize=7)
    fig.tight_layout()
    return saving.save_figure(fig, name, dpi=dpi)


def section5_name(fig: str, resolution: str) -> str:
    """The file of Figure ``fig`` at ``resolution``: ``fig5.2-preview.png``, ``fig5.2-paper.png``
    (the paper-resolution files are kept by ``certify all``: saving.KEPT)."""
    return f"fig{fig}-{resolution}.png"


def section5_figure(data, dpi: int | None = None) -> str:
    """Figure ``data.spec.id`` of Section 5 drawn from a run of certify.numerics.figures,
    with the paper's red lines (CDKK thresholds L4, r_exist L3) and red rectangles."""
    from certify.numerics import cite, red_lines
    spec = data.spec
    orbits = data.phi.shape[1]
    title = (f"{cite(spec.id)}, {data.resolution}: {spec.lo} ≤ r ≤ {spec.hi}, {len(data.r)} values of r, "
             f"{orbits} orbit{'s' if orbits != 1 else ''}, last {data.keep} b-collisions of {data.collisions}, "
             f"{data.engine}")
    fraction = data.certified_fraction()
    if fraction is not None:             # the run itself, proved collision by collision up to its horizon
        horizon = int(data.certified.max())
        title += (f"\ncertified: {fraction:.2%} of the collisions computed (at most the first {horizon} of each "
                  "orbit; the plotted ones, later, shadow true orbits)" if horizon < data.collisions - data.keep
                  else f"\ncertified: {fraction:.2%} of the collisions computed")
    points = data.extra.get("points")
    if points and points["all"]["points"]:  # the plotted points, proved afterwards through the dynamics
        a, b = points["all"], points["above_3-2sqrt2"]
        every = f"; every {points['every']}th r" if points["every"] > 1 else ""
        title += ("\ncertified within a pixel of the true orbit (island, trap or ball engine"
                  f"{every}): {a['fraction']:.2%} of the plotted points"
                  + (f", {b['fraction']:.2%} of those at r > 3−2√2" if b["points"] else ""))
    lines = red_lines() if saving.enabled() else None       # mpmath roots, for drawing only
    return omega_figure(data, section5_name(spec.id, data.resolution), lines=lines, boxes=spec.boxes,
                        title=title, dpi=dpi)


# --------------------------------------------------------------------------
# L5: the windows of (ab)^n(cb)^n, rescaled (certify.patterns.family_windows, family_limit)

def family_windows_figure(exact: list, band: list, name: str = "L5-family-windows") -> str:
    """n²(W_n − (7 − 4√3)) against 1/n: ``exact`` the windows of n ≤ N₀ as (n, s_lo, s_hi)
    (bars), ``band`` the proved enclosures for every n > N₀ as (ε₀, ε₁, [s_lo interval],
    [s_hi interval]) over ε = 1/n ∈ [ε₀, ε₁] (shaded: the window's lower end lies in the lower
    box, its upper end in the upper box); left all n, right n ≥ 10.  Floats: a drawing of
    certified numbers."""
    last = max(n for n, _lo, _hi in exact)        # the exact windows are listed to n = last, the boxes beyond

    def panel(ax, first: bool):
        for k, (e0, e1, lo, hi) in enumerate(band):
            label = first and k == 0
            ax.fill_between([e0, e1], [lo[0]] * 2, [lo[1]] * 2, color="tab:orange", lw=0,
                            label=f"n > {last}: the lower end (proved box)" if label else None)
            ax.fill_between([e0, e1], [hi[0]] * 2, [hi[1]] * 2, color="tab:green", lw=0,
                            label=f"n > {last}: the upper end (proved box)" if label else None)
            ax.fill_between([e0, e1], [lo[1]] * 2, [hi[0]] * 2, color="tab:blue", alpha=0.15, lw=0,
                            label=f"n > {last}: inside the window" if label else None)
        for k, (n, lo, hi) in enumerate(exact):
            ax.plot([1 / n, 1 / n], [lo, hi], color="tab:blue", lw=2,
                    label=f"n ≤ {last}: the exact window" if first and k == 0 else None)
        ax.set_xlabel("1/n")

    def draw():
        plt = saving.pyplot()
        fig, (ax, zoom) = plt.subplots(1, 2, figsize=(10, 4))
        panel(ax, True)
        panel(zoom, False)
        near = [v for n, lo, hi in exact if n >= 10 for v in (lo, hi)] + [v for b in band for v in b[2] + b[3]]
        if near:
            zoom.set_xlim(0, 0.1 + 0.005)
            zoom.set_ylim(min(near) - 0.001, max(near) + 0.001)
        ax.set_ylabel("n² (r − (7 − 4√3))")
        zoom.set_title("n ≥ 10", fontsize=8)
        fig.suptitle("The stability windows of (ab)^n(cb)^n, rescaled", fontsize=9)
        ax.legend(loc="best", fontsize=7)
        return saving.save_figure(fig, name)
    key = saving.input_digest(tuple(exact), tuple(tuple(map(tuple, b[2:])) + b[:2] for b in band))
    return saving.cached(name, key, draw)
