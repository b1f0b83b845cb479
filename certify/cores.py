"""The cores this process may use: the default of ``--jobs`` (on the ground floor, so that
the command line reads it without loading the runner)."""
from __future__ import annotations

import os


def default_jobs() -> int:
    """The cores this process may use."""
    try:
        return max(len(os.sched_getaffinity(0)), 1)
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1
