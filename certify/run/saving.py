"""Saving a certificate's figures, reproducibly.

A certificate draws a matplotlib figure and hands it to :func:`save_figure`,
then lists the returned name in its outcome::

    from certify.run.saving import save_figure

    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(rs, signs)
    return conclude([...], figures=[save_figure(fig, "sign-a-minus-d.png")])

Where the file goes is decided by the command line, not by the certificate:
``python -m certify all`` sets the output directory to ``reports/figures`` for the
duration of the run (:func:`output_dir`).  When no directory is set (a test
running a certificate, a benchmark), :func:`save_figure` writes nothing, closes
the figure and still returns the name, so the certificate behaves the same.
:func:`enabled` lets a certificate skip an expensive drawing in that case.

The PNG bytes are reproducible: Agg backend, a fixed dpi, and no "Software"
metadata (which would carry the matplotlib version).
"""
from __future__ import annotations

from contextlib import contextmanager
from fnmatch import fnmatch
from pathlib import Path

from certify.run.files import atomic_path

DPI = 110

_output_dir: Path | None = None


def pyplot():
    """matplotlib.pyplot on the Agg backend (no screen needed, and the same pixels
    everywhere), imported when a figure is first drawn: commands that draw nothing
    do not pay for importing matplotlib."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def set_output_dir(path) -> None:
    """Send figures to ``path`` (created if needed); ``None`` turns saving off."""
    global _output_dir
    _output_dir = None if path is None else Path(path)
    if _output_dir is not None:
        _output_dir.mkdir(parents=True, exist_ok=True)


def get_output_dir() -> Path | None:
    """The directory figures are written to, or None when saving is off."""
    return _output_dir


def enabled() -> bool:
    """True when :func:`save_figure` will actually write a file."""
    return _output_dir is not None


@contextmanager
def output_dir(path):
    """Within the ``with`` block, figures are written to ``path``."""
    previous = _output_dir
    set_output_dir(path)
    try:
        yield Path(path)
    finally:
        set_output_dir(previous)


def figure_name(name: str) -> str:
    """``name`` as a PNG file name: a plain name (no directory), ending in .png."""
    if not name or Path(name).name != name or name in {".", ".."}:
        raise ValueError(f"figure name must be a plain file name, got {name!r}")
    return name if name.endswith(".png") else name + ".png"


def save_figure(fig, name: str, dpi: int | None = None) -> str:
    """Write ``fig`` as ``NAME.png`` into the output directory, close it, return the name.

    The write is atomic (temporary file, then :func:`os.replace`).  With no
    output directory set, nothing is written.  ``dpi``: default :data:`DPI`.
    """
    plt = pyplot()
    name = figure_name(name)
    try:
        if _output_dir is not None:
            with atomic_path(_output_dir / name) as tmp:
                fig.savefig(tmp, format="png", dpi=dpi or DPI, metadata={"Software": None})
    finally:
        plt.close(fig)
    return name


KEPT = ("*-paper.png", "bench_*.png", "census-*.png")   # written by `certify figures --resolution paper`,
# `certify bench`, `certify census` (minutes), never by a run of the certificates


def prune(directory, keep, kept=KEPT) -> list[str]:
    """Delete the PNG files in ``directory`` whose names are not in ``keep`` and match
    none of the patterns ``kept`` (the paper-resolution figures of Section 5, which
    ``certify figures --resolution paper`` writes and the report only links to).

    Used after a complete run so that ``reports/figures`` holds exactly the
    figures the report shows.  Returns the deleted names.
    """
    directory = Path(directory)
    if not directory.is_dir():
        return []
    removed = []
    for path in sorted(directory.glob("*.png")):
        if path.name not in keep and not any(fnmatch(path.name, pattern) for pattern in kept):
            path.unlink()
            removed.append(path.name)
    return removed
