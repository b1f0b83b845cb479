"""Saving figures: nothing written unless the CLI set a directory; same bytes twice."""
from __future__ import annotations

import matplotlib.pyplot as plt
import pytest

from certify.run import saving as figures


def draw():
    fig, ax = plt.subplots(figsize=(3, 2))
    ax.plot([0, 1, 2], [0, 1, 4])
    ax.set_title("r ↦ λ(r)")
    return fig


def test_nothing_written_without_output_dir(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert not figures.enabled()
    fig = draw()
    assert figures.save_figure(fig, "spectrum") == "spectrum.png"
    assert not plt.fignum_exists(fig.number)          # closed all the same
    assert list(tmp_path.rglob("*")) == []


def test_saved_bytes_are_reproducible(tmp_path):
    with figures.output_dir(tmp_path / "a"):
        assert figures.enabled()
        figures.save_figure(draw(), "f.png")
    with figures.output_dir(tmp_path / "b"):
        figures.save_figure(draw(), "f.png")
    assert not figures.enabled()                        # restored after the block
    first, second = (tmp_path / "a" / "f.png").read_bytes(), (tmp_path / "b" / "f.png").read_bytes()
    assert first.startswith(b"\x89PNG") and first == second
    assert b"Matplotlib" not in first                   # no Software metadata
    assert sorted(p.name for p in (tmp_path / "a").iterdir()) == ["f.png"]   # no temp file


@pytest.mark.parametrize("bad", ["", "../x.png", "sub/x.png", ".."])
def test_figure_name_must_be_plain(bad):
    with pytest.raises(ValueError):
        figures.figure_name(bad)


def test_prune_keeps_listed_figures(tmp_path):
    for name in ("keep.png", "old.png", "notes.txt"):
        (tmp_path / name).write_text("x")
    assert figures.prune(tmp_path, keep={"keep.png"}) == ["old.png"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["keep.png", "notes.txt"]


def test_a_cached_figure_is_the_drawn_one_and_drawn_again_when_an_input_changes(tmp_path, monkeypatch):
    monkeypatch.setenv(figures.CACHE_ENV, str(tmp_path / "cache"))
    drawn = []

    def drawing(title):
        def go():
            drawn.append(title)
            fig = draw()
            fig.axes[0].set_title(title)
            return figures.save_figure(fig, "f.png")
        return go
    key = figures.input_digest([0.5, 1.0], "a")
    with figures.output_dir(tmp_path / "a"):
        assert figures.cached("f", key, drawing("a")) == "f.png"
    with figures.output_dir(tmp_path / "b"):
        assert figures.cached("f", key, drawing("a")) == "f.png"            # copied, not drawn
        figures.cached("f", figures.input_digest([0.5, 1.0], "b"), drawing("b"))
    assert drawn == ["a", "b"]
    assert figures.cached("f", key, drawing("a")) == "f.png" and drawn == ["a", "b"]   # nothing saved: nothing drawn
    with figures.output_dir(tmp_path / "c"):
        figures.cached("f", key, drawing("a"))
    assert (tmp_path / "a" / "f.png").read_bytes() == (tmp_path / "c" / "f.png").read_bytes()
    assert (tmp_path / "b" / "f.png").read_bytes() != (tmp_path / "c" / "f.png").read_bytes()
    monkeypatch.setenv(figures.CACHE_ENV, "off")
    with figures.output_dir(tmp_path / "d"):
        figures.cached("f", key, drawing("a"))
    assert drawn == ["a", "b", "a"]
    assert (tmp_path / "d" / "f.png").read_bytes() == (tmp_path / "a" / "f.png").read_bytes()
