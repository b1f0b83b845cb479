"""Progress bars on a terminal (tqdm), silent everywhere else.

A :class:`Bar` is a callback ``bar(k, n, label)``: ``k`` of ``n`` steps are done,
the last one named ``label`` (a certificate id, "collisions", ...).  The runner and
the particle simulator call it.  On a terminal it draws a tqdm bar on stderr and
erases it when ``k == n``; when stderr is a file or a pipe (CI, tests, logs) it
draws nothing at all.
"""
from __future__ import annotations

import sys

from tqdm import tqdm

_OPEN: list[Bar] = []


def _is_terminal(stream) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):  # no isatty, or a closed stream
        return False


class Bar:
    """A progress bar for one piece of long work; see the module's docstring."""

    def __init__(self, unit: str = "step", stream=None):
        self.unit, self.stream = unit, stream if stream is not None else sys.stderr
        self.bar: tqdm | None = None

    def __call__(self, k: int, n: int, label: str = "") -> None:
        if not _is_terminal(self.stream):
            return
        if self.bar is None:
            self.bar = tqdm(total=n, file=self.stream, unit=self.unit, leave=False, dynamic_ncols=True)
            _OPEN.append(self)
        if self.bar.total != n:                # a total that grows (the atlas meets new words)
            self.bar.total = n
        self.bar.n = k
        if label:
            self.bar.set_postfix_str(label, refresh=False)
        self.bar.refresh()
        if k >= n:
            self.close()

    def close(self) -> None:
        """Erase the bar (at the end, or after an interruption)."""
        if self.bar is not None:
            self.bar.close()
            self.bar = None
        if self in _OPEN:
            _OPEN.remove(self)


def clear() -> None:
    """Erase every bar left on the terminal (after an interruption or an error)."""
    for bar in list(_OPEN):
        bar.close()
