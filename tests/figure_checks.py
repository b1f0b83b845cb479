"""What a reader of a figure stumbles on, measured on the rendered figure (matplotlib's Agg
renderer, at the dpi the figure is saved with): two texts overprinting each other, a text cut
by the figure's edge, a panel without its own x tick labels, a legend over plotted data, a
series of points without a legend entry; and, called by the tests that need them, most of a
panel's height left empty (:func:`empty_height`) and percentages not named apart
(:func:`unnamed_percentages`).

:func:`drawn` runs a drawing with the figures' cache off and returns the figures it saved;
:func:`problems` lists the first five kinds for one of them (empty when legible)."""
from __future__ import annotations

import re

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import PathCollection, PolyCollection
from matplotlib.text import Text

from certify.run import saving


def drawn(monkeypatch, tmp_path, draw, *args, **kwargs) -> list:
    """``draw(*args, **kwargs)`` with figures saved into ``tmp_path`` (cache off): the figures
    it wrote, each rendered at the dpi it was saved with."""
    monkeypatch.setenv(saving.CACHE_ENV, "off")
    figures = []
    write = saving.write_figure

    def keep(fig, path, dpi=None):
        written = write(fig, path, dpi)
        FigureCanvasAgg(fig)                # closed by the write: a canvas again, to measure on
        fig.set_dpi(dpi or saving.DPI)
        fig.canvas.draw()
        figures.append(fig)
        return written
    monkeypatch.setattr(saving, "write_figure", keep)
    with saving.output_dir(tmp_path):
        draw(*args, **kwargs)
    assert figures, "nothing was drawn"
    return figures


def _renderer(fig):
    return fig.canvas.get_renderer()


def _tick_labels(ax, axis) -> list[Text]:
    """The tick labels of ``axis`` drawn: non-empty, visible, at a tick inside the view."""
    lo, hi = sorted(axis.get_view_interval())
    out = []
    for tick in axis.get_major_ticks() + axis.get_minor_ticks():
        if lo - 1e-12 * abs(hi - lo) <= tick.get_loc() <= hi + 1e-12 * abs(hi - lo):
            out += [t for t in (tick.label1, tick.label2) if t.get_visible() and t.get_text().strip()]
    return out


def _panels(fig) -> list:
    return [ax for ax in fig.axes if ax.get_visible() and ax.axison]


def texts(fig) -> list[Text]:
    """Every text drawn: titles, axis and tick labels, annotations, legends, the figure's texts."""
    out = [t for t in fig.texts if t.get_visible() and t.get_text().strip()]
    for ax in _panels(fig):
        out += [t for t in (ax.title, ax._left_title, ax._right_title, ax.xaxis.label, ax.yaxis.label)
                if t.get_visible() and t.get_text().strip()]
        out += _tick_labels(ax, ax.xaxis) + _tick_labels(ax, ax.yaxis)
        out += [t for t in ax.texts if t.get_visible() and t.get_text().strip()]
        if ax.get_legend() is not None:
            out += [t for t in ax.get_legend().get_texts() if t.get_text().strip()]
    for legend in fig.legends:
        out += [t for t in legend.get_texts() if t.get_text().strip()]
    return out


def overlapping_texts(fig) -> list[tuple[str, str]]:
    """The pairs of texts whose boxes overlap (by more than half a pixel each way)."""
    renderer = _renderer(fig)
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in texts(fig)]
    out = []
    for i, (a, p) in enumerate(boxes):
        for b, q in boxes[i + 1:]:
            if min(p.x1, q.x1) - max(p.x0, q.x0) > 0.5 and min(p.y1, q.y1) - max(p.y0, q.y0) > 0.5:
                out.append((a, b))
    return out


def clipped_texts(fig) -> list[str]:
    """The texts that reach past the figure's edge."""
    renderer, edge = _renderer(fig), fig.bbox
    out = []
    for t in texts(fig):
        box = t.get_window_extent(renderer)
        if box.x0 < edge.x0 - 0.5 or box.y0 < edge.y0 - 0.5 or box.x1 > edge.x1 + 0.5 or box.y1 > edge.y1 + 0.5:
            out.append(t.get_text())
    return out


def panels_without_x_ticks(fig) -> list[str]:
    """The panels (by title or y label) with fewer than two x tick labels of their own."""
    return [ax.get_title() or ax.get_ylabel() or "untitled" for ax in _panels(fig)
            if len(_tick_labels(ax, ax.xaxis)) < 2]


def _data_points(ax) -> np.ndarray:
    """The plotted data of ``ax`` in display coordinates: the vertices of its lines of more
    than two points and of its point clouds."""
    pts = [line.get_transform().transform(line.get_xydata()) for line in ax.lines if len(line.get_xydata()) > 2]
    pts += [c.get_offset_transform().transform(c.get_offsets()) for c in ax.collections
            if isinstance(c, PathCollection) and len(c.get_offsets())]
    return np.concatenate(pts) if pts else np.empty((0, 2))


def _filled(ax) -> list:
    """The filled shapes of ``ax`` (bars, spans, areas) as display paths."""
    out = [p.get_transform().transform_path(p.get_path()) for p in ax.patches if p.get_fill()]
    for c in ax.collections:
        if isinstance(c, PolyCollection):
            out += [c.get_transform().transform_path(path) for path in c.get_paths()]
    return out


def legends_over_data(fig) -> list[str]:
    """The legends (by their first entry) drawn over a plotted point or a filled shape of their panel."""
    renderer = _renderer(fig)
    out = []
    for ax in _panels(fig):
        legend = ax.get_legend()
        if legend is None:
            continue
        box = legend.get_window_extent(renderer)
        pts = _data_points(ax)
        inside = ((pts[:, 0] > box.x0) & (pts[:, 0] < box.x1) & (pts[:, 1] > box.y0) & (pts[:, 1] < box.y1))
        xs, ys = np.meshgrid(np.linspace(box.x0, box.x1, 12), np.linspace(box.y0, box.y1, 6))
        grid = np.column_stack([xs.ravel(), ys.ravel()])
        covered = any(path.contains_points(grid).any() for path in _filled(ax))
        if inside.any() or covered:
            out.append(legend.get_texts()[0].get_text() if legend.get_texts() else "legend")
    return out


def unlabelled_series(fig) -> list[str]:
    """The panels (by title) that plot series of points (lines with markers and no line) in two or
    more styles (colour, marker), a style no legend shows."""
    shown = {t.get_text() for ax in _panels(fig) if ax.get_legend() for t in ax.get_legend().get_texts()}
    shown |= {t.get_text() for legend in fig.legends for t in legend.get_texts()}
    out = []
    for ax in _panels(fig):
        series = [line for line in ax.lines if line.get_linestyle() in ("None", "") and len(line.get_xydata()) > 2]
        styles = {(str(line.get_color()), line.get_marker()) for line in series}
        named = {(str(line.get_color()), line.get_marker()) for line in series if line.get_label() in shown}
        if len(styles) > 1 and styles - named:
            out.append(ax.get_title() or "untitled")
    return out


def empty_height(ax) -> float:
    """The share of the panel's height that no plotted point reaches (above and below the data)."""
    pts = _data_points(ax)
    box = ax.get_window_extent(_renderer(ax.get_figure()))
    ys = pts[:, 1][np.isfinite(pts[:, 1])]
    ys = ys[(ys >= box.y0) & (ys <= box.y1)]
    return 1.0 if not ys.size else 1 - (ys.max() - ys.min()) / box.height


def unnamed_percentages(title: str) -> list[str]:
    """The percentages of ``title`` not followed by "of <what>", or naming the same what as another."""
    found = re.findall(r"(\d+(?:\.\d+)?%)(?: of ([^,;:()\n]+))?", title)
    whats = [what.strip() for _, what in found]
    return [p for (p, _), what in zip(found, whats) if not what or whats.count(what) > 1]


def problems(fig) -> dict:
    """Everything :mod:`figure_checks` finds wrong with ``fig`` (only the kinds found)."""
    found = {"overlapping texts": overlapping_texts(fig), "texts cut by the edge": clipped_texts(fig),
             "panels without x tick labels": panels_without_x_ticks(fig),
             "legends over data": legends_over_data(fig), "series without a legend": unlabelled_series(fig)}
    return {kind: what for kind, what in found.items() if what}

