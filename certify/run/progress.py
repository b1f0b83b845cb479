"""A one-line progress indicator for a terminal, silent everywhere else.

:func:`show` has the signature of the ``progress`` callback of
:func:`certify.run.runner.run`: it is called as ``show(k, n, id)`` before the
``k``-th certificate (counting from 0) and as ``show(n, n, "")`` at the end.
On a terminal it writes ``[k+1/n] ID`` on stderr, overwriting the previous
line with a carriage return; when stderr is a file or a pipe (CI, tests) it
writes nothing, so logs stay clean.
"""
from __future__ import annotations

import shutil
import sys

_CLEAR = "\r\x1b[K"  # back to the start of the line, then erase it


def _is_terminal(stream) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):  # no isatty, or a closed stream
        return False


def show(k: int, n: int, cid: str, stream=None) -> None:
    """Show ``[k+1/n] cid`` on a terminal; erase the line when ``k == n``."""
    stream = stream if stream is not None else sys.stderr
    if not _is_terminal(stream):
        return
    if k >= n:
        stream.write(_CLEAR)
    else:
        width = shutil.get_terminal_size((80, 20)).columns
        stream.write(_CLEAR + f"[{k + 1}/{n}] {cid}"[: max(width - 1, 1)])
    stream.flush()


def clear(stream=None) -> None:
    """Erase a progress line left on the terminal (after an interruption)."""
    stream = stream if stream is not None else sys.stderr
    if _is_terminal(stream):
        stream.write(_CLEAR)
        stream.flush()
