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
metadata (which would carry the matplotlib version).  So a drawing is a function of
its inputs: :func:`cached` copies the PNG drawn before from the same inputs (and the
same drawing code and libraries) instead of drawing it again.
"""
from __future__ import annotations

import hashlib
import os
from collections.abc import Callable
from contextlib import contextmanager
from fnmatch import fnmatch
from functools import cache
from pathlib import Path

from certify.run.files import atomic_path, write_atomic

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
    name = figure_name(name)
    if _output_dir is not None:
        write_figure(fig, _output_dir / name, dpi)
    else:
        pyplot().close(fig)
    return name


def write_figure(fig, path, dpi: int | None = None) -> Path:
    """Write ``fig`` as a PNG at ``path`` atomically (no software stamp: the same bytes each run), close
    it, return the path."""
    plt = pyplot()
    path = Path(path)
    try:
        with atomic_path(path) as tmp:
            fig.savefig(tmp, format="png", dpi=dpi or DPI, metadata={"Software": None})
    finally:
        plt.close(fig)
    return path


CACHE_ENV = "CERTIFY_FIGURE_CACHE"     # the cache's directory; "off" (or empty) draws every figure
DRAWING_CODE = ("saving.py", "plots.py", "island_figures.py")   # the modules that draw (this directory)


def cache_dir() -> Path | None:
    """Where drawn figures are kept by their inputs: $CERTIFY_FIGURE_CACHE, else
    $XDG_CACHE_HOME/certify/figures (~/.cache/certify/figures); None when turned off."""
    value = os.environ.get(CACHE_ENV)
    if value is not None:
        return None if value.strip().lower() in ("", "off", "0", "no") else Path(value)
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "certify" / "figures"


@cache
def _drawing_version() -> str:
    """The drawing code and the libraries that turn inputs into pixels, as one digest."""
    from importlib.metadata import version
    h = hashlib.sha256()
    for name in DRAWING_CODE:
        h.update((Path(__file__).parent / name).read_bytes())
    for lib in ("matplotlib", "numpy"):
        h.update(f"{lib} {version(lib)};".encode())
    return h.hexdigest()


def input_digest(*parts) -> str:
    """A digest of a drawing's inputs: numpy arrays by dtype, shape and bytes, the rest by repr."""
    h = hashlib.sha256()
    for part in parts:
        if hasattr(part, "tobytes") and hasattr(part, "dtype"):
            h.update(f"array {part.dtype} {part.shape}:".encode() + part.tobytes())
        else:
            h.update(repr(part).encode())
        h.update(b"|")
    return h.hexdigest()


def cached(name: str, inputs: str, draw: Callable[[], str], dpi: int | None = None) -> str:
    """Figure ``name``, drawn by ``draw()`` (which saves it with :func:`save_figure` and
    returns its name) unless the cache holds the PNG drawn from the same ``inputs`` (a
    digest of everything the drawing reads: :func:`input_digest`) with the same drawing
    code, libraries and dpi; then the cached bytes are written.  With no output directory,
    nothing is drawn (``name`` returned).  The bytes are the same either way: the PNG is
    a function of its inputs (module docstring)."""
    name = figure_name(name)
    if _output_dir is None:
        return name
    where = cache_dir()
    if where is None:
        return draw()
    key = hashlib.sha256(f"{name}|{dpi or DPI}|{inputs}|{_drawing_version()}".encode()).hexdigest()
    hit = where / f"{key}.png"
    try:
        data = hit.read_bytes()
    except OSError:
        data = None
    if data is not None:
        write_atomic(_output_dir / name, data)
        return name
    drawn = draw()
    try:
        where.mkdir(parents=True, exist_ok=True)
        write_atomic(hit, (_output_dir / drawn).read_bytes())
    except OSError:                     # a read-only or full cache: the figure is written all the same
        pass
    return drawn


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
