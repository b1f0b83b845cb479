"""The committed figures as a reader sees them, measured on the rendered figure (tests/figure_checks.py):
no two texts overprint, none is cut by the edge, every panel has its own x tick labels, no legend
covers data, every style of points is in a legend; the sign charts leave no empty band; the Section 5
captions name what each percentage counts."""
from __future__ import annotations

import json

import matplotlib.pyplot as plt
import pytest
from flint import fmpq

from certify.run import atlas, island_figures, plots
from certify.run.files import REPORTS, load_findings
from certify.run.runner import run_certificate
from tests import figure_checks as fc
from tests.shared import CONTEXT, registry


# ------------------------------------------------------------------ the checks can fail
def rendered(fig):
    fig.canvas.draw()
    return fig


def test_the_checks_find_overprinted_cut_and_hidden_texts():
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(4, 3))
    top.annotate("1/2", (0.5, 0.5), xycoords="axes fraction")
    top.annotate("1/3", (0.5, 0.5), xycoords="axes fraction", xytext=(3, 1), textcoords="offset points")
    bottom.annotate("cut at the edge", (0.99, 0.5), xycoords="figure fraction")
    rendered(fig)
    assert ("1/2", "1/3") in fc.overlapping_texts(fig)
    assert fc.clipped_texts(fig) == ["cut at the edge"]
    assert len(fc.panels_without_x_ticks(fig)) == 1          # sharex hides the top panel's labels
    plt.close(fig)


def test_the_checks_find_a_legend_over_data_and_series_without_one():
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(6, 3))
    ax.bar([0, 1, 2], [1, 1, 1], width=1, label="share")
    ax.legend(loc="upper right")
    for k in range(3):
        bx.plot(range(10), [k] * 10, ".", label=f"orbit {k}")
    rendered(fig)
    assert fc.legends_over_data(fig) == ["share"]
    assert fc.unlabelled_series(fig) == ["untitled"]
    bx.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1))
    rendered(fig)
    assert fc.unlabelled_series(fig) == []
    plt.close(fig)


def test_the_checks_find_an_empty_band_and_unnamed_percentages():
    fig, ax = plt.subplots()
    ax.plot([0, 1, 2], [0, 1, 2], ".")
    ax.set_ylim(-2, 2)
    rendered(fig)
    assert fc.empty_height(ax) == pytest.approx(0.5, abs=0.01)
    plt.close(fig)
    assert fc.unnamed_percentages("certified: 0.61% of the collisions\npoints: 94.99%, 100.00% for r > 1") \
        == ["94.99%", "100.00%"]
    assert fc.unnamed_percentages("1% of the collisions, 2% of the collisions") == ["1%", "2%"]
    assert fc.unnamed_percentages("1% of the collisions, 2% of the plotted points") == []


# ------------------------------------------------------------------ the report's figures
@pytest.mark.parametrize("id", ["T8", "T14", "T15"])
def test_the_spectrum_and_sign_charts_are_legible(id, monkeypatch, tmp_path):
    """The critical values' labels (5-2√6, r*, r2) above the axes, none on another or on a curve;
    the sign charts' symlog axis starts at the data (no empty band of negative λ)."""
    for fig in fc.drawn(monkeypatch, tmp_path, run_certificate, registry()[id], CONTEXT):
        assert fc.problems(fig) == {}, id
        assert fc.empty_height(fig.axes[0]) < 0.15, id


def test_the_island_figure_is_legible(monkeypatch, tmp_path):
    """island.png: a legend for the orbits, the resonance labels apart, the census windows on
    their own panel of r (nothing drawn at a height of the ρ axis but ρ(r) itself)."""
    fig, = fc.drawn(monkeypatch, tmp_path, island_figures.report_figure, fmpq(3, 10))
    assert fc.problems(fig) == {}
    rho = next(ax for ax in fig.axes if ax.get_ylabel() == "rotation number ρ")
    assert not rho.patches
    strip = next(ax for ax in fig.axes if ax.get_shared_x_axes().joined(ax, rho) and ax is not rho)
    words = {w for w, _, _ in island_figures.rotation_data()[1]}
    assert {t.get_text() for t in strip.get_yticklabels()} == words and len(strip.patches) >= len(words)


def test_the_atlas_figure_is_legible(monkeypatch, tmp_path):
    """atlas.png drawn from the committed reports/atlas.json."""
    doc = json.loads((REPORTS / "atlas.json").read_text())
    fig, = fc.drawn(monkeypatch, tmp_path, atlas.figure, doc, tmp_path / "atlas.png")
    assert fc.problems(fig) == {}


@pytest.mark.parametrize("id", ["N3", "N6"])
def test_the_section5_previews_are_legible(id, monkeypatch, tmp_path):
    """Figure 7's lines r_max(4..6) lie within 0.01 of one another and r_exist at its right edge:
    each label in a row where it overlaps none, inside the figure."""
    for fig in fc.drawn(monkeypatch, tmp_path, run_certificate, registry()[id], CONTEXT):
        assert fc.problems(fig) == {}, fig.axes[0].get_title()


def test_the_section5_captions_name_what_each_percentage_counts(monkeypatch, tmp_path):
    """The paper figures' captions give the share of the collisions certified by the run and the share
    of the plotted points certified afterwards: each percentage says what it is a share of."""
    from certify import numerics
    data = numerics.compute("5.1", "preview")
    data.extra["points"] = load_findings("numerics-paper.json")["5.1"]["points"]
    fig, = fc.drawn(monkeypatch, tmp_path, plots.section5_figure, data)
    title = fig.axes[0].get_title()
    assert title.count("%") == 3 and fc.unnamed_percentages(title) == []
    assert fc.problems(fig) == {}


def test_the_numerics_benchmark_figure_is_legible(monkeypatch, tmp_path):
    """bench_numerics.png: three panels side by side whose titles overlapped; a table shaped as
    `certify bench --numerics` makes it (engines' times and errors spread as measured there)."""
    bench = pytest.importorskip("benchmarks.bench_numerics")
    marks = (100, 1000, 10_000)
    engines = {"float64": (0.03, 1e-15), "mp 16 digits": (150.0, 1e-15), "mp 30 digits": (160.0, 1e-28),
               "mp 60 digits": (165.0, 1e-63), "mp 120 digits": (175.0, 1e-123), "ball (64/128 bits)": (70.0, 1e-19)}
    table = [[name] + [x for _ in bench.ORBITS for x in (sec, err, err, err)] for name, (sec, err) in engines.items()]
    fig, = fc.drawn(monkeypatch, tmp_path, bench.plot, table, marks, tmp_path / "bench_numerics.png")
    assert fc.problems(fig) == {}


def test_the_five_particle_windows_figure_is_legible(monkeypatch, tmp_path):
    """five-windows.png (tools/five_particle_figure.py): abadcbcabc's certified stable window
    (certify pattern over ]1/4, 27/100[) above the committed census's four-particle windows, the
    thresholds labelled above the axes; the rows are exactly the certified windows."""
    from certify.patterns.five import analyse_five
    from certify.run import five_figure
    res = analyse_five("abadcbcabc", fmpq(1, 4), fmpq(27, 100))
    five = five_figure.five_particle_windows({res.normal: res.to_json()})
    from certify.patterns.pattern import end_data
    assert five == [(res.normal, [(float(end_data(w.lo)["digits"]), float(end_data(w.hi)["digits"]))
                                  for w in res.intervals("stable")])]
    doc = json.loads((REPORTS / "census.json").read_text())
    four = five_figure.four_particle_windows(doc)
    assert [w for w, _ in four] == [r["compact"] for r in doc["words"] if r["stable"]]
    fig, = fc.drawn(monkeypatch, tmp_path, five_figure.figure, four, five, tmp_path / "five-windows.png",
                    five_figure.marks(), doc["census"]["max_length"])
    assert fc.problems(fig) == {}
    top = fig.axes[0]
    assert [t.get_text() for t in top.get_yticklabels()] == ["abadcbcabc"] and len(top.patches) == 1
    bar = top.patches[0]
    (lo, hi), = five[0][1]
    assert bar.get_x() == pytest.approx(lo) and bar.get_x() + bar.get_width() == pytest.approx(hi)


def test_a_narrow_five_particle_window_is_marked(monkeypatch, tmp_path):
    """A five-particle window narrower than five_figure.NARROW of the axis (the 36-letter word's is
    about 0.0005 wide on an axis of 0.3) gets a diamond at its middle besides its bar, a wide one
    only its bar; the figure stays legible."""
    from certify.run import five_figure
    doc = json.loads((REPORTS / "census.json").read_text())
    five = [("wide", [(0.25, 0.2679)]), ("narrow", [(0.18707, 0.18760)])]
    fig, = fc.drawn(monkeypatch, tmp_path, five_figure.figure, five_figure.four_particle_windows(doc), five,
                    tmp_path / "five-windows.png", five_figure.marks(), doc["census"]["max_length"])
    assert fc.problems(fig) == {}
    top = fig.axes[0]
    assert [t.get_text() for t in top.get_yticklabels()] == ["wide", "narrow"] and len(top.patches) == 2
    marked = [(list(line.get_xdata()), list(line.get_ydata())) for line in top.lines if line.get_marker() == "D"]
    assert marked == [([pytest.approx((0.18707 + 0.18760) / 2)], [1])]
